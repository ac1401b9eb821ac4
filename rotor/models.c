/* rotor/models.c — the rotor module's models for `whirl run` (model = sfd,
 * model = sfd-rotating, model = jeffcott), registered by whirl_rotor_register_models: the
 * same vector fields as the sfd commands use, Table 1's parameters as
 * defaults, the journal at rest in the centre as the start, and the
 * physical parameter ranges of whirl_sfd_check_params.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <string.h>

#include <whirl/rotor.h>

static const double sfd_u0[4] = {0.0, 0.0, 0.0, 0.0};
/* the clearance (displacements are in clearances), and a clearance per
 * 1/ω_n for the velocities */
static const double sfd_scale[4] = {1.0, 1.0, 1.0, 1.0};

static int sfd_stpnt(double tau, double *u, double *par, void *data) {
  (void)tau;
  (void)par;
  (void)data;
  memset(u, 0, 4 * sizeof *u); /* at rest in the centre */
  return 0;
}

static int sfd_check(const double *p, char *msg, size_t len) {
  return whirl_sfd_check_params(p, msg, len) != WHIRL_OK;
}

int whirl_rotor_register_models(whirl_model_registry *reg, char *msg, size_t len) {
  /* the registry copies the descriptions; the defaults live here */
  static double par0[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(par0);
  const whirl_model fixed = {
      .abi = WHIRL_MODEL_ABI, .problem = *whirl_sfd_fixed(), .par0 = par0,
      .u0 = sfd_u0, .stpnt = sfd_stpnt, .forcing_param = WHIRL_SFD_OMEGA, .scale = sfd_scale,
      .description = "rigid rotor on two short squeeze-film dampers, fixed "
                     "frame (unbalance forcing at Omega)",
      .check_params = sfd_check};
  const whirl_model rotating = {
      .abi = WHIRL_MODEL_ABI, .problem = *whirl_sfd_rotating(), .par0 = par0,
      .u0 = sfd_u0, .stpnt = sfd_stpnt, .forcing_param = -1, .scale = sfd_scale,
      .description = "rigid rotor on two short squeeze-film dampers, rotating "
                     "frame (circular orbits are equilibria)",
      .check_params = sfd_check};
  int rc = whirl_model_registry_add(reg, "sfd", &fixed, msg, len);
  if (rc == WHIRL_OK) rc = whirl_model_registry_add(reg, "sfd-rotating", &rotating, msg, len);
  if (rc == WHIRL_OK) rc = whirl_model_registry_add(reg, "jeffcott", whirl_rotor_jeffcott(), msg, len);
  return rc;
}

/* drivers/sfd_common.c — shared by the SFD commands: the names of the
 * classes of a steady state (whirl_steady_classify), the checks of the
 * parameters and tolerances, the parameters in a picture's title.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>

#include <whirl/rotor.h>

#include "cli.h"
#include "sfd_common.h"

const char *sfd_steady_name(whirl_steady_kind kind, double eps_spread) {
  switch (kind) {
    case WHIRL_STEADY_FIXED: return eps_spread < 1e-6 ? "circular" : "periodic";
    case WHIRL_STEADY_PERIODIC: return "periodic";
    case WHIRL_STEADY_QUASIPERIODIC: return "quasiperiodic";
    case WHIRL_STEADY_IRREGULAR: return "irregular";
    case WHIRL_STEADY_TRANSIENT:
    case WHIRL_STEADY_DIVERGENT: return "transient";
  }
  return "irregular";
}

const char *sfd_steady_class(const char *cmd, const double *P, size_t npts, double eps_spread,
                             size_t *period, double *dimension) {
  whirl_steady_kind kind;
  if (whirl_steady_classify(P, npts, 4, 1e-6, 16, &kind, period, dimension) != WHIRL_OK) {
    cli_error(cmd, "out of memory classifying the steady state");
    return NULL;
  }
  return sfd_steady_name(kind, eps_spread);
}

/* The options of the parameters, for the messages (whirl/rotor/sfd.h's order). */
static const char *const param_option[WHIRL_SFD_NPAR][2] = {
    {"--omega", "the dimensionless speed, e.g. --omega 8.7"},
    {"--lambda", "the SFD constant, e.g. --lambda 0.25"},
    {"--delta", "the unbalance, e.g. --delta 0.3"},
    {"--zeta", "the external damping ratio, e.g. --zeta 0"},
    {"--fe", "the static force, e.g. --fe 0"}};

int sfd_check(const char *cmd, const double *p, int omega_option) {
  for (int k = 0; k < WHIRL_SFD_NPAR; ++k)
    if (isnan(p[k])) {
      cli_error(cmd, "%s is required (%s)", param_option[k][0], param_option[k][1]);
      return -1;
    }
  if (omega_option && !(p[WHIRL_SFD_OMEGA] > 0)) {
    cli_error(cmd, "--omega must be > 0 (got %g)", p[WHIRL_SFD_OMEGA]);
    return -1;
  }
  char msg[256];
  if (whirl_sfd_check_params(p, msg, sizeof msg) != WHIRL_OK) {
    cli_error(cmd, "%s", msg);
    return -1;
  }
  return 0;
}

const char *sfd_gp_params(char *buf, size_t len, const double *p, unsigned mask) {
  static const char *const symbol[WHIRL_SFD_NPAR] = {"{/Symbol W}", "{/Symbol l}",
                                                     "{/Symbol d}", "{/Symbol z}", "F_E"};
  size_t used = 0;
  buf[0] = '\0';
  for (int k = 0; k < WHIRL_SFD_NPAR && used < len; ++k)
    if (mask & SFD_P(k)) {
      int n = snprintf(buf + used, len - used, "%s%s = %g", used ? ", " : "", symbol[k], p[k]);
      if (n < 0) break;
      used += (size_t)n;
    }
  return buf;
}

int sfd_check_tolerances(const char *cmd, double rtol, double atol) {
  char msg[128];
  if (whirl_basins_check_tolerances(rtol, atol, msg, sizeof msg) == WHIRL_OK)
    return 0;
  cli_error(cmd, "--%s", msg); /* "rtol must be in [...]" names the option */
  return -1;
}

/* drivers/rotor_time.c — the integrator and initial states of the time
 * commands of FE rotors (rotor_time.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rotor_time.h"

whirl_ode *rotor_time_ode(const char *cmd, whirl_fe_ode *m, const double *p,
                          int method, double rtol, double atol, int *exit_code) {
  *exit_code = 1;
  whirl_ode *ode = whirl_ode_alloc(whirl_fe_ode_problem(m), p);
  if (!ode) {
    cli_error(cmd, "out of memory");
    return NULL;
  }
  (void)whirl_ode_set_method(ode, method); /* known, no state yet */
  if (method == WHIRL_ODE_BDF && whirl_fe_ode_use_mass(m, ode) != WHIRL_OK) {
    cli_error(cmd, "%s", whirl_fe_ode_errmsg(m));
    whirl_ode_free(ode);
    return NULL;
  }
  if (whirl_ode_set_tolerances(ode, rtol, atol) != WHIRL_OK) {
    cli_error(cmd, "bad tolerances: --rtol %g (>= 100 machine epsilon), --atol %g (> 0)",
              rtol, atol);
    whirl_ode_free(ode);
    *exit_code = 2;
    return NULL;
  }
  return ode;
}

void rotor_time_start(const whirl_fe_rotor *r, double y0, double z0, double *z) {
  memset(z, 0, 2 * (size_t)r->ndof * sizeof *z);
  for (int n = 0; n < r->nnode; ++n) {
    z[whirl_fe_rotor_dof(r, n, 0)] = y0;
    z[whirl_fe_rotor_dof(r, n, 1)] = z0;
  }
}

int rotor_time_inside(const char *cmd, whirl_fe_ode *m, const double *p,
                      const double *z0) {
  const whirl_problem *P = whirl_fe_ode_problem(m);
  double *f = malloc(P->n * sizeof *f);
  int rc = f ? P->rhs(0.0, z0, p, f, P->data) : -1;
  free(f);
  if (rc > 0)
    cli_error(cmd, "the initial displacement puts a journal at or beyond the clearance of a "
              "film element");
  else if (rc < 0)
    cli_error(cmd, "out of memory");
  return rc > 0 ? 2 : rc < 0 ? 1 : 0;
}

int rotor_time_node(const char *cmd, const whirl_fe_rotor *r, int node) {
  if (node < 0) return r->nnl > 0 ? r->nl[0].node : 0;
  if (node >= r->nnode) {
    cli_error(cmd, "--node %d is not a node of the rotor (0..%d)", node, r->nnode - 1);
    return -1;
  }
  return node;
}

double rotor_time_clearance(const whirl_fe_rotor *r) {
  double c = 0.0;
  for (int e = 0; e < r->nnl; ++e) {
    const whirl_fe_nl *el = &r->nl[e];
    if (el->kind != WHIRL_FE_RUB && el->kind != WHIRL_FE_CUBIC &&
        (c == 0.0 || el->par.clearance < c))
      c = el->par.clearance;
  }
  return c;
}

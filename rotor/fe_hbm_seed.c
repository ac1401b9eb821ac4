/* rotor/fe_hbm_seed.c — a start for the condensed harmonic balance away
 * from rest: forward circular orbits of a given relative eccentricity at
 * every film element (SFDs, journal bearings), for branches that the
 * response from rest does not reach — an isola seeded from a rigid-rotor
 * or Jeffcott solution, or from a guess (whirl/rotor/fe_hbm.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <string.h>

#include "fe_hbm_impl.h"

static int is_film(whirl_fe_nl_kind k) {
  return k == WHIRL_FE_SFD_SHORT_PI || k == WHIRL_FE_SFD_SHORT_2PI ||
         k == WHIRL_FE_SFD_LONG || k == WHIRL_FE_SFD_INERTIA ||
         k == WHIRL_FE_JOURNAL_SHORT;
}

/* The position of rotor DOF d among the kept unknowns, or −1. */
static int unknown_of(const whirl_fe_hbm *h, int d) {
  int m;
  const int *dofs = whirl_fe_hbm_nl_dofs(h, &m);
  for (int j = 0; j < m; j++)
    if (dofs[j] == d) return j;
  return -1;
}

int whirl_fe_hbm_seed_circular(const whirl_fe_hbm *h, double eps,
                               double phase, double *X) {
  if (!h || !X || !(eps >= 0 && eps < 1) || !isfinite(phase) || h->o.nu != 1)
    return WHIRL_EINVAL;
  memset(X, 0, (size_t)h->n * sizeof *X);
  const whirl_fe_rotor *r = h->r;
  const int b = h->b;
  for (int e = 0; e < r->nnl; e++) {
    const whirl_fe_nl *el = &r->nl[e];
    if (!is_film(el->kind)) continue;
    const int jy = unknown_of(h, whirl_fe_rotor_dof(r, el->node, 0));
    const int jz = unknown_of(h, whirl_fe_rotor_dof(r, el->node, 1));
    if (jy < 0 || jz < 0) return WHIRL_EINVAL;
    /* y = a cos ωt + b sin ωt = ρ cos(ωt + φ), z = ρ sin(ωt + φ) */
    const double rho = eps * el->par.clearance / h->Ls;
    X[b + jy] = rho * cos(phase), X[2 * b + jy] = -rho * sin(phase);
    X[b + jz] = rho * sin(phase), X[2 * b + jz] = rho * cos(phase);
  }
  return WHIRL_OK;
}

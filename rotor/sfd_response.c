/* rotor/sfd_response.c — the complete synchronous response of the SFD
 * rotor: every branch of circular orbits in omega_min <= Ω <= omega_max.
 * A continuation started at small Ω cannot reach an isolated branch, so the
 * seeds come from an independent source: every real root Ω of the paper's
 * eq. 15 on a grid of orbit radii ε, and every root ε on the boundaries
 * Ω = omega_min and Ω = omega_max.  Each seed not already on a traced branch
 * starts whirl_trace_branch on the rotating-frame equilibria, so each branch
 * is traced once, by the generic core.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/branch.h>
#include <whirl/equilibrium.h>
#include <whirl/rotor/sfd.h>

void whirl_sfd_response_options_default(whirl_sfd_response_options *o) {
  o->omega_min = 0.01;
  o->omega_max = 20.0;
  o->ds = 0.02;
  o->ds_max = 0.2;
  o->neps = 400;
  o->linsol = WHIRL_LINSOL_DENSE;
}

void whirl_sfd_response_free(whirl_sfd_response *r) {
  if (!r) return;
  for (size_t i = 0; i < r->nbranch; ++i) whirl_branch_free(r->branch[i]);
  free(r->branch);
  memset(r, 0, sizeof *r);
}

typedef struct seed {
  double eps, Omega;
} seed;

typedef struct seed_list {
  seed *v;
  size_t len, cap;
} seed_list;

static int seed_add(seed_list *s, double eps, double Omega) {
  if (s->len == s->cap) {
    size_t cap = s->cap ? 2 * s->cap : 256;
    seed *nv = realloc(s->v, cap * sizeof *nv);
    if (!nv) return -1;
    s->v = nv;
    s->cap = cap;
  }
  s->v[s->len].eps = eps;
  s->v[s->len].Omega = Omega;
  ++s->len;
  return 0;
}

/* Roots ε of G(ε, Ω) = 0 at fixed Ω by sign changes on a geometric grid
 * (small ε resolved down to 1e-10) refined by bisection. */
static int boundary_seeds(seed_list *s, double Omega, const double *p,
                          size_t neps) {
  const double lam = p[WHIRL_SFD_LAMBDA], del = p[WHIRL_SFD_DELTA],
               zet = p[WHIRL_SFD_ZETA];
  double e0 = 1e-10, g0;
  whirl_sfd_circ_G(e0, Omega, lam, del, zet, &g0, NULL, NULL);
  const size_t m = 4 * neps;
  for (size_t i = 1; i <= m; ++i) {
    /* geometric up to 0.05, then uniform up to 0.9995 */
    double e1 = i <= m / 4 ? 1e-10 * pow(0.05 / 1e-10, (double)i / (double)(m / 4))
                           : 0.05 + (0.9995 - 0.05) * (double)(i - m / 4) / (double)(m - m / 4);
    double g1;
    whirl_sfd_circ_G(e1, Omega, lam, del, zet, &g1, NULL, NULL);
    if (isfinite(g0) && isfinite(g1) && g0 * g1 < 0) {
      double a = e0, b = e1, ga = g0;
      for (int it = 0; it < 200 && b - a > 1e-15 * b; ++it) {
        double mid = 0.5 * (a + b), gm;
        whirl_sfd_circ_G(mid, Omega, lam, del, zet, &gm, NULL, NULL);
        if (gm * ga > 0) {
          a = mid;
          ga = gm;
        } else {
          b = mid;
        }
      }
      if (seed_add(s, 0.5 * (a + b), Omega)) return -1;
    }
    e0 = e1;
    g0 = g1;
  }
  return 0;
}

int whirl_sfd_response_compute(const double *p0,
                               const whirl_sfd_response_options *o,
                               whirl_sfd_response *out, char *errbuf,
                               size_t errlen) {
  memset(out, 0, sizeof *out);
  double p[WHIRL_SFD_NPAR];
  memcpy(p, p0, sizeof p);
  p[WHIRL_SFD_OMEGA] = o->omega_min;
  int rc = whirl_sfd_check_params(p, errbuf, errlen);
  if (rc != WHIRL_OK) return rc;
  if (p[WHIRL_SFD_FE] != 0.0)
    return WHIRL_ERRMSG(
        errbuf, errlen, WHIRL_EINVAL,
        "circular orbits need F_E = 0 (got %g): gravity must be fully "
        "compensated for the rotating-frame formulation",
        p[WHIRL_SFD_FE]);
  if (!(o->omega_min > 0) || !(o->omega_max > o->omega_min) ||
      !isfinite(o->omega_max))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "need 0 < omega_min < omega_max (got %g, %g)",
                        o->omega_min, o->omega_max);
  if (o->neps < 10 || !(o->ds > 0) || !(o->ds_max >= o->ds))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "need neps >= 10 and 0 < ds <= ds_max");
  const double lam = p[WHIRL_SFD_LAMBDA], del = p[WHIRL_SFD_DELTA],
               zet = p[WHIRL_SFD_ZETA];

  whirl_equilibrium *eq = whirl_equilibrium_alloc(whirl_sfd_rotating());
  seed_list seeds = {0};
  rc = WHIRL_ENOMEM;
  if (!eq) goto done;
  const whirl_system *sys = whirl_equilibrium_system(eq);

  /* seeds: boundaries first (the ends of every branch that leaves the
   * window), then the interior roots of eq. 15 on the ε grid */
  if (boundary_seeds(&seeds, o->omega_min, p, o->neps) ||
      boundary_seeds(&seeds, o->omega_max, p, o->neps))
    goto done;
  for (size_t i = 1; i <= o->neps; ++i) {
    const double eps = 0.9995 * (double)i / (double)(o->neps + 1);
    double Om[4];
    int nr = 0;
    if (whirl_sfd_circ_roots(eps, lam, del, zet, Om, &nr) != WHIRL_OK) continue;
    for (int k = 0; k < nr; ++k)
      if (Om[k] >= o->omega_min && Om[k] <= o->omega_max)
        if (seed_add(&seeds, eps, Om[k])) goto done;
  }
  out->nseeds = seeds.len;

  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = WHIRL_SFD_OMEGA;
  co.ds = o->ds;
  co.ds_min = 1e-10;
  co.ds_max = o->ds_max;
  co.nmx = 100000;
  co.p_min = o->omega_min;
  co.p_max = o->omega_max;
  co.max_angle = 0.1;
  co.linsol = o->linsol;
  /* a journal touching the housing ends a branch (domain stop); keep the
   * corrector off ε >= 1 */
  const double tol_on = 0.02; /* seed-to-branch distance counted as "on it" */

  for (size_t i = 0; i < seeds.len; ++i) {
    double x[4];
    whirl_sfd_circ_state(seeds.v[i].eps, seeds.v[i].Omega, lam, del, zet, x);
    p[WHIRL_SFD_OMEGA] = seeds.v[i].Omega;
    int on = 0;
    for (size_t b = 0; b < out->nbranch && !on; ++b)
      on = whirl_branch_within(out->branch[b], x, p, 1.0, tol_on);
    if (on) continue;
    whirl_branch *br = NULL;
    whirl_cont_stats st = {0};
    char msg[512];
    int trc = whirl_trace_branch(sys, &co, x, p, &br, &st, msg, sizeof msg);
    out->steps += st.steps;
    out->newton_its += st.newton_its;
    out->f_evals += st.f_evals;
    out->jac_evals += st.jac_evals;
    if (trc != WHIRL_OK) {
      /* a seed exactly at a fold cannot start (F_x singular); the other
       * seeds of that branch will.  A fatal model error is reported. */
      if (trc == WHIRL_EUSER || trc == WHIRL_ENOMEM) {
        WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "%s", msg);
        rc = trc;
        goto done;
      }
      continue;
    }
    /* a branch whose every point lies on one already traced is a duplicate
     * (a seed that sat between two points of a coarse polyline) */
    int dup = out->nbranch > 0;
    for (size_t k = 0; k < br->len && dup; ++k) {
      int near = 0;
      for (size_t b = 0; b < out->nbranch && !near; ++b)
        near = whirl_branch_within(out->branch[b], br->pts[k].x, br->pts[k].p,
                                   1.0, tol_on);
      if (!near) dup = 0;
    }
    if (dup) {
      whirl_branch_free(br);
      continue;
    }
    whirl_branch **nb = realloc(out->branch, (out->nbranch + 1) * sizeof *nb);
    if (!nb) {
      whirl_branch_free(br);
      goto done;
    }
    out->branch = nb;
    br->id = (int)out->nbranch + 1;
    out->branch[out->nbranch++] = br;
  }
  rc = WHIRL_OK;
done:
  if (rc == WHIRL_ENOMEM) WHIRL_ERRMSG(errbuf, errlen, rc, "out of memory");
  if (rc != WHIRL_OK) whirl_sfd_response_free(out);
  free(seeds.v);
  whirl_equilibrium_free(eq);
  return rc;
}

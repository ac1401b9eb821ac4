/* test/unit/t_response.c — the complete SFD response (continuation of the
 * rotating-frame equilibria) against the circular-orbit polynomial, eq. 15,
 * solved independently: every point on G = 0, every LP on G = G_eps = 0 to
 * 1e-8, the branch count (isola found), stability consistent with the
 * multipliers, dense against sparse, analytic against finite-difference
 * Jacobians, and the isola of Fig. 6a approaching the peak.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "../tap.h"

static size_t count(const whirl_sfd_response *r, int type) {
  size_t k = 0;
  for (size_t b = 0; b < r->nbranch; ++b)
    for (size_t i = 0; i < r->branch[b]->len; ++i) k += r->branch[b]->pts[i].type == type;
  return k;
}

static double eps_of(const whirl_branch_point *q) { return hypot(q->x[0], q->x[1]); }

/* LP points sorted by Omega: Om[k], ep[k]; returns their number */
static int lps(const whirl_sfd_response *r, double *Om, double *ep, int max) {
  int k = 0;
  for (size_t b = 0; b < r->nbranch; ++b)
    for (size_t i = 0; i < r->branch[b]->len; ++i)
      if (r->branch[b]->pts[i].type == WHIRL_PT_LP && k < max) {
        Om[k] = r->branch[b]->pts[i].p[WHIRL_SFD_OMEGA];
        ep[k] = eps_of(&r->branch[b]->pts[i]);
        ++k;
      }
  for (int i = 1; i < k; ++i)
    for (int j = i; j > 0 && Om[j] < Om[j - 1]; --j) {
      double t = Om[j]; Om[j] = Om[j - 1]; Om[j - 1] = t;
      t = ep[j]; ep[j] = ep[j - 1]; ep[j - 1] = t;
    }
  return k;
}

static void table1(void) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  whirl_sfd_response_options o;
  whirl_sfd_response_options_default(&o);
  whirl_sfd_response r;
  char err[256];
  int rc = whirl_sfd_response_compute(p, &o, &r, err, sizeof err);
  ok(rc == WHIRL_OK, "Table 1 response computed (%s)", rc ? err : "ok");
  if (rc) return;
  ok(r.nbranch == 2, "two branches found (main and isola): %zu", r.nbranch);
  ok(count(&r, WHIRL_PT_LP) == 3, "exactly three LP");
  ok(count(&r, WHIRL_PT_BP) == 0, "no BP");
  const double lam = p[WHIRL_SFD_LAMBDA], del = p[WHIRL_SFD_DELTA], zet = p[WHIRL_SFD_ZETA];

  /* every point lies on eq. 15 and has the phase of eqs. 16-17 */
  double gmax = 0, phmax = 0;
  int stab_ok = 1;
  for (size_t b = 0; b < r.nbranch; ++b)
    for (size_t i = 0; i < r.branch[b]->len; ++i) {
      const whirl_branch_point *q = &r.branch[b]->pts[i];
      const double Om = q->p[WHIRL_SFD_OMEGA], e = eps_of(q);
      double G, Ge, Go;
      whirl_sfd_circ_G(e, Om, lam, del, zet, &G, &Ge, &Go);
      /* scale: the size of the terms of eq. 15 */
      double sc = e * e * (1 + Om * Om) * (1 + Om * Om) + fabs(Ge) * e + fabs(Go) * Om;
      gmax = fmax(gmax, fabs(G) / sc);
      double beta = whirl_sfd_circ_phase(e, Om, lam, del, zet);
      double dph = remainder(atan2(-q->x[1], q->x[0]) - beta, 2 * M_PI);
      phmax = fmax(phmax, fabs(dph));
      /* stable <=> all rotating-frame eigenvalues in the left half plane */
      double mre = q->spec_re[0];
      if (q->type == WHIRL_PT_REGULAR && (q->stable == 1) != (mre < 0)) stab_ok = 0;
      if (q->x[2] != 0.0 && fabs(q->x[2]) > 1e-10) stab_ok = 0; /* u' = 0 */
    }
  ok(gmax < 1e-12, "all points satisfy eq. 15 (max scaled |G| = %.2e)", gmax);
  ok(phmax < 1e-9, "all phases agree with eqs. 16-17 (max diff %.2e rad)", phmax);
  ok(stab_ok, "stability labels agree with the eigenvalues");

  /* LPs against G = G_eps = 0 solved by Newton from a perturbed guess */
  double Om[8], ep[8];
  int k = lps(&r, Om, ep, 8);
  for (int i = 0; i < k; ++i) {
    double e = ep[i] + 0.002, w = Om[i] * 1.001;
    int frc = whirl_sfd_circ_fold(&e, &w, lam, del, zet);
    ok(frc == WHIRL_OK, "eq. 15 fold solver converges near LP %d", i + 1);
    is_abs(Om[i], w, 1e-8, "LP %d Omega = %.12f agrees with eq. 15", i + 1, w);
    is_abs(ep[i], e, 1e-8, "LP %d eps = %.12f agrees with eq. 15", i + 1, e);
  }
  if (k == 3) {
    ok(Om[0] > 1.6 && Om[1] < 1.9 && Om[2] > 5 && Om[2] < 9,
       "region B = [%.4f, %.4f] near resonance, isola born at %.4f", Om[0], Om[1], Om[2]);
    /* the isola is the branch that does not reach omega_min */
    const whirl_branch *iso = NULL;
    for (size_t b = 0; b < r.nbranch; ++b) {
      double lo = INFINITY;
      for (size_t i = 0; i < r.branch[b]->len; ++i)
        lo = fmin(lo, r.branch[b]->pts[i].p[WHIRL_SFD_OMEGA]);
      if (lo > 1.0) iso = r.branch[b];
    }
    ok(iso != NULL, "one branch is isolated (never below Omega = 1)");
    if (iso) {
      /* Fig. 3b: at Omega = 15 the larger orbit is stable, the smaller not */
      double ehi = -1, elo = 2;
      int shi = -1, slo = -1;
      for (size_t i = 0; i + 1 < iso->len; ++i) {
        double a = iso->pts[i].p[0], c = iso->pts[i + 1].p[0];
        if ((a - 15) * (c - 15) <= 0) {
          double e = eps_of(&iso->pts[i]);
          if (e > ehi) { ehi = e; shi = iso->pts[i].stable; }
          if (e < elo) { elo = e; slo = iso->pts[i].stable; }
        }
      }
      ok(shi == 1 && slo == 0, "isola at Omega = 15: upper (eps %.4f) stable, lower (eps %.4f) unstable",
         ehi, elo);
    }
  }

  /* sparse (UMFPACK) path gives the same LPs */
  o.linsol = WHIRL_LINSOL_SPARSE;
  whirl_sfd_response rs;
  rc = whirl_sfd_response_compute(p, &o, &rs, err, sizeof err);
  double Os[8], es[8];
  int ks = rc == WHIRL_OK ? lps(&rs, Os, es, 8) : 0;
  ok(ks == k, "sparse solver finds the same number of LP");
  for (int i = 0; i < k && i < ks; ++i) is_abs(Os[i], Om[i], 1e-10, "LP %d: sparse = dense", i + 1);
  if (rc == WHIRL_OK) whirl_sfd_response_free(&rs);
  whirl_sfd_response_free(&r);
}

/* Fig. 6a: lambda = 0.25; the isola moves towards the peak as delta grows
 * and joins it near delta = 0.4173 (paper: 0.417315). */
static void fig6(void) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_LAMBDA] = 0.25;
  whirl_sfd_response_options o;
  whirl_sfd_response_options_default(&o);
  const double deltas[3] = {0.35, 0.40, 0.417};
  double birth[3] = {NAN, NAN, NAN};
  char err[256];
  for (int j = 0; j < 3; ++j) {
    p[WHIRL_SFD_DELTA] = deltas[j];
    whirl_sfd_response r;
    if (whirl_sfd_response_compute(p, &o, &r, err, sizeof err) != WHIRL_OK) continue;
    for (size_t b = 0; b < r.nbranch; ++b) {
      double lo = INFINITY;
      for (size_t i = 0; i < r.branch[b]->len; ++i)
        lo = fmin(lo, r.branch[b]->pts[i].p[WHIRL_SFD_OMEGA]);
      if (lo > 1.0) birth[j] = lo;
    }
    whirl_sfd_response_free(&r);
  }
  ok(birth[0] > birth[1] && birth[1] > birth[2],
     "lambda 0.25: isola born at Omega %.3f, %.3f, %.3f for delta 0.35, 0.40, 0.417",
     birth[0], birth[1], birth[2]);
  /* delta = 0.2: no isola below 20, but one further out (Fig. 6b) */
  p[WHIRL_SFD_DELTA] = 0.2;
  whirl_sfd_response r;
  int rc = whirl_sfd_response_compute(p, &o, &r, err, sizeof err);
  ok(rc == WHIRL_OK && r.nbranch == 1, "lambda 0.25, delta 0.2: one branch up to Omega 20");
  if (rc == WHIRL_OK) whirl_sfd_response_free(&r);
  /* eq. 15 has roots near eps 0.97 only for Omega > 200: look up to 400 */
  o.omega_max = 400;
  o.ds_max = 5.0;
  rc = whirl_sfd_response_compute(p, &o, &r, err, sizeof err);
  double lo = INFINITY;
  for (size_t b = 0; rc == WHIRL_OK && b < r.nbranch; ++b)
    for (size_t i = 0; i < r.branch[b]->len && r.branch[b]->pts[i].p[0] > 1.0; ++i)
      lo = fmin(lo, r.branch[b]->pts[i].p[0]);
  ok(rc == WHIRL_OK && r.nbranch == 2 && lo > 200 && lo < 400,
     "lambda 0.25, delta 0.2: the isola is far out, born at Omega %.2f", lo);
  if (rc == WHIRL_OK) whirl_sfd_response_free(&r);
}

/* The same response with the model's Jacobians replaced by differences. */
static const whirl_problem *fd_model(void) {
  static whirl_problem m;
  m = *whirl_sfd_rotating();
  m.jac_x = NULL;
  m.jac_p = NULL;
  return &m;
}

static void fd_vs_analytic(void) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  whirl_equilibrium *ea = whirl_equilibrium_alloc(whirl_sfd_rotating());
  whirl_equilibrium *ef = whirl_equilibrium_alloc(fd_model());
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.icp = WHIRL_SFD_OMEGA;
  o.p_min = 0.5;
  o.p_max = 3.0;
  o.ds_max = 0.1;
  double x[4];
  p[0] = 0.5;
  double e0 = 0.0, Om[4];
  int nr = 0;
  /* start on the main branch at Omega = 0.5: scan eps for the root */
  for (double e = 0.01; e < 0.5 && !e0; e += 0.001) {
    whirl_sfd_circ_roots(e, p[1], p[2], p[3], Om, &nr);
    for (int k = 0; k < nr; ++k)
      if (fabs(Om[k] - 0.5) < 0.01) e0 = e, p[0] = Om[k];
  }
  whirl_sfd_circ_state(e0, p[0], p[1], p[2], p[3], x);
  double lp[2][2] = {{NAN, NAN}, {NAN, NAN}};
  for (int v = 0; v < 2; ++v) {
    whirl_branch *b = NULL;
    char err[256];
    whirl_trace_branch(whirl_equilibrium_system(v ? ef : ea), &o, x, p, &b, NULL, err, sizeof err);
    int k = 0;
    for (size_t i = 0; b && i < b->len; ++i)
      if (b->pts[i].type == WHIRL_PT_LP && k < 2) lp[v][k++] = b->pts[i].p[0];
    whirl_branch_free(b);
  }
  is_rel(lp[1][0], lp[0][0], 1e-8, "first LP: finite-difference Jacobian = analytic");
  is_rel(lp[1][1], lp[0][1], 1e-8, "second LP: finite-difference Jacobian = analytic");
  whirl_equilibrium_free(ea);
  whirl_equilibrium_free(ef);
}

int main(void) {
  table1();
  fig6();
  fd_vs_analytic();
  return done_testing();
}

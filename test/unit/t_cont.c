/* test/unit/t_cont.c — the continuation core on problems with closed-form
 * answers: folds of the cusp normal form, branch points of the pitchfork and
 * transcritical normal forms (with branch switching), the Hopf point of the
 * Brusselator, a closed branch (circle), exact parameter bounds, UZ points,
 * finite-difference Jacobians, dense against sparse on the Bratu problem, and
 * two continuations interleaved in one process.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/whirl.h>

#include "../tap.h"

/* ---- cusp normal form  F = mu + lam x - x^3,  p = (mu, lam) */
static int cusp_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = p[0] + p[1] * x[0] - x[0] * x[0] * x[0];
  return 0;
}
static int cusp_Fx(const double *x, const double *p, double *J, void *d) {
  (void)d;
  J[0] = p[1] - 3 * x[0] * x[0];
  return 0;
}
static int cusp_Fp(const double *x, const double *p, size_t k, double *fk, void *d) {
  (void)d;
  (void)p;
  fk[0] = k == 0 ? 1.0 : x[0];
  return 0;
}

/* The cusp counting the parameter values F is evaluated at: each new
 * value is what a costly parameter (a condensation per speed) pays for. */
static double cc_last = NAN;
static size_t cc_changes;
static int cusp_counted_F(const double *x, const double *p, double *f, void *d) {
  if (p[0] != cc_last) ++cc_changes;
  cc_last = p[0];
  return cusp_F(x, p, f, d);
}

/* ---- pitchfork F = x (p - x^2) and transcritical F = x (p - x) */
static int pf_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * (p[0] - x[0] * x[0]);
  return 0;
}
static int tc_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * (p[0] - x[0]);
  return 0;
}

/* ---- circle  F = x^2 + p^2 - 1: a closed branch with folds at p = +-1 */
static int circ_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * x[0] + p[0] * p[0] - 1.0;
  return 0;
}

/* ---- Brusselator x' = a - (b+1)x + x^2 y, y' = b x - x^2 y, p = (b, a):
 * equilibrium (a, b/a), Hopf at b = 1 + a^2 with frequency a. */
static int bru_rhs(double t, const double *x, const double *p, double *f, void *d) {
  (void)t;
  (void)d;
  const double b = p[0], a = p[1];
  f[0] = a - (b + 1) * x[0] + x[0] * x[0] * x[1];
  f[1] = b * x[0] - x[0] * x[0] * x[1];
  return 0;
}

/* ---- Bratu  -u'' = mu exp(u), u(0) = u(1) = 0, centred differences on m
 * interior points; tridiagonal Jacobian given both dense and sparse. */
#define BRATU_M 60
static int bratu_F(const double *u, const double *p, double *f, void *d) {
  (void)d;
  const double h = 1.0 / (BRATU_M + 1), ih2 = 1.0 / (h * h);
  for (int i = 0; i < BRATU_M; ++i) {
    double ul = i > 0 ? u[i - 1] : 0.0, ur = i < BRATU_M - 1 ? u[i + 1] : 0.0;
    f[i] = (ul - 2 * u[i] + ur) * ih2 + p[0] * exp(u[i]);
  }
  return 0;
}
static int bratu_Fx(const double *u, const double *p, double *J, void *d) {
  (void)d;
  const double h = 1.0 / (BRATU_M + 1), ih2 = 1.0 / (h * h);
  memset(J, 0, sizeof(double) * BRATU_M * BRATU_M);
  for (int i = 0; i < BRATU_M; ++i) {
    J[i + BRATU_M * i] = -2 * ih2 + p[0] * exp(u[i]);
    if (i > 0) J[i + BRATU_M * (i - 1)] = ih2;
    if (i < BRATU_M - 1) J[i + BRATU_M * (i + 1)] = ih2;
  }
  return 0;
}
static int bratu_Jp[BRATU_M + 1], bratu_Ji[3 * BRATU_M];
static int bratu_Fxs(const double *u, const double *p, double *Jx, void *d) {
  (void)d;
  const double h = 1.0 / (BRATU_M + 1), ih2 = 1.0 / (h * h);
  for (int j = 0; j < BRATU_M; ++j)
    for (int q = bratu_Jp[j]; q < bratu_Jp[j + 1]; ++q)
      Jx[q] = bratu_Ji[q] == j ? -2 * ih2 + p[0] * exp(u[j]) : ih2;
  return 0;
}
static int bratu_Fp(const double *u, const double *p, size_t k, double *fk, void *d) {
  (void)d;
  (void)p;
  (void)k;
  for (int i = 0; i < BRATU_M; ++i) fk[i] = exp(u[i]);
  return 0;
}

/* run a continuation to its end into a fresh branch */
static whirl_branch *run(const whirl_system *sys, const whirl_cont_options *o,
                         const double *x0, const double *p0, int dir, int *reason) {
  char err[256];
  whirl_cont *c = whirl_cont_alloc(sys, o, err, sizeof err);
  if (!c) {
    printf("# alloc: %s\n", err);
    return NULL;
  }
  whirl_branch *b = whirl_branch_alloc(sys->n, sys->npar, sys->nspec, o->icp);
  int rc = whirl_cont_start(c, x0, p0, dir);
  if (rc == WHIRL_OK) rc = whirl_cont_run(c, b);
  if (rc < 0) printf("# run: %s\n", whirl_cont_errmsg(c));
  if (reason) *reason = whirl_cont_stop_reason(c);
  whirl_cont_free(c);
  return b;
}

static size_t count_type(const whirl_branch *b, int type) {
  size_t k = 0;
  for (size_t i = 0; i < b->len; ++i) k += b->pts[i].type == type;
  return k;
}
static const whirl_branch_point *nth_type(const whirl_branch *b, int type, size_t nth) {
  for (size_t i = 0; i < b->len; ++i)
    if (b->pts[i].type == type && nth-- == 0) return &b->pts[i];
  return NULL;
}

/* The cusp's run: from mu = -6 (lambda = 1) up to mu = 6.5. */
static void cusp_options(whirl_cont_options *o, double ds_max) {
  whirl_cont_options_default(o);
  o->ds = 0.05;
  o->ds_max = ds_max;
  o->p_min = -6.5;
  o->p_max = 6.5;
}

/* max |F| over the branch's points */
static double cusp_residual(const whirl_branch *b) {
  double res = 0;
  for (size_t i = 0; b && i < b->len; ++i) {
    double f;
    cusp_F(b->pts[i].x, b->pts[i].p, &f, NULL);
    res = fmax(res, fabs(f));
  }
  return res;
}

static void test_cusp(int analytic) {
  whirl_system s = {.name = "cusp", .n = 1, .npar = 2, .F = cusp_F};
  if (analytic) {
    s.Fx = cusp_Fx;
    s.Fp = cusp_Fp;
  }
  whirl_cont_options o;
  cusp_options(&o, 0.2);
  double x0 = -2.0, p0[2] = {-6.0, 1.0};
  int reason;
  whirl_branch *b = run(&s, &o, &x0, p0, +1, &reason);
  ok(b && count_type(b, WHIRL_PT_LP) == 2, "cusp (%s): two folds", analytic ? "analytic" : "FD");
  const double mu_f = 2.0 / (3.0 * sqrt(3.0)), x_f = 1.0 / sqrt(3.0);
  const whirl_branch_point *l1 = nth_type(b, WHIRL_PT_LP, 0), *l2 = nth_type(b, WHIRL_PT_LP, 1);
  if (l1 && l2) {
    is_abs(l1->p[0], mu_f, 1e-12, "cusp first fold mu = 2/(3 sqrt 3)");
    is_abs(l1->x[0], -x_f, 1e-9, "cusp first fold x = -1/sqrt 3");
    is_abs(l2->p[0], -mu_f, 1e-12, "cusp second fold mu = -2/(3 sqrt 3)");
    is_abs(l2->x[0], x_f, 1e-9, "cusp second fold x = 1/sqrt 3");
  }
  ok(reason == WHIRL_STOP_PMAX, "cusp ends at the upper parameter bound");
  const whirl_branch_point *e = &b->pts[b->len - 1];
  ok(e->type == WHIRL_PT_EP, "cusp last point is EP");
  is_abs(e->p[0], 6.5, 1e-12, "cusp end point exactly at RL1");
  /* every point satisfies F = 0 */
  const double res = cusp_residual(b);
  ok(res < 1e-10, "cusp: all %zu points solve F = 0 (max |F| = %.2e)", b->len, res);
  whirl_branch_free(b);
}

/* natural_corrector: Newton at the predicted parameter away from the
 * folds, the arclength hyperplane near them (and where the fixed-parameter
 * Newton fails or lands on another sheet): the same folds, the same points
 * on the curve, far fewer parameter values. */
static void test_natural_corrector(double xw) {
  whirl_system s = {.name = "cusp", .n = 1, .npar = 2, .F = cusp_counted_F,
                    .Fx = cusp_Fx, .Fp = cusp_Fp};
  const double mu_f = 2.0 / (3.0 * sqrt(3.0)), x_f = 1.0 / sqrt(3.0);
  size_t changes[2] = {0, 0}, npts[2] = {0, 0};
  for (int nat = 0; nat < 2; ++nat) {
    whirl_cont_options o;
    cusp_options(&o, 0.4);
    /* x weighed 0.2: the steps reach far in mu, and Newton at a mu
     * predicted past the first fold converges on the upper sheet (the
     * secant's turn tells: natural_jumped) */
    o.x_weight = &xw;
    o.natural_corrector = nat ? 1e-9 : 0.0;
    double x0 = -2.0, p0[2] = {-6.0, 1.0};
    int reason;
    cc_changes = 0;
    whirl_branch *b = run(&s, &o, &x0, p0, +1, &reason);
    changes[nat] = cc_changes;
    const whirl_branch_point *l1 = nth_type(b, WHIRL_PT_LP, 0), *l2 = nth_type(b, WHIRL_PT_LP, 1);
    ok(b && count_type(b, WHIRL_PT_LP) == 2 && l1 && l2 && fabs(l1->p[0] - mu_f) < 1e-12 &&
       fabs(l2->p[0] + mu_f) < 1e-12 && fabs(l1->x[0] + x_f) < 1e-9 &&
       fabs(l2->x[0] - x_f) < 1e-9 && reason == WHIRL_STOP_PMAX,
       "natural corrector %s, x weight %g: the cusp's two folds at -+2/(3 sqrt 3), "
       "to the end", nat ? "on" : "off", xw);
    const double res = cusp_residual(b);
    npts[nat] = b ? b->len : 0;
    ok(b && res < 1e-10, "natural corrector %s, x weight %g: all %zu points solve "
       "F = 0 (%.1e)", nat ? "on" : "off", xw, npts[nat], res);
    whirl_branch_free(b);
  }
  ok(10 * changes[1] < 8 * changes[0], "natural corrector, x weight %g: %zu parameter "
     "values F was evaluated at, against %zu on the arclength hyperplane", xw, changes[1],
     changes[0]);
}

/* pf2 with a chain of 248 more unknowns, x_i = x_{i-1} / 2: N = 251, so
 * the switch direction comes from inverse iteration with the bordered LU,
 * not the dense SVD; beside the branch point (p = 1e-7) it must be the
 * vector of the null plane orthogonal to the given tangent, here
 * (0, 0.01, 0, ..., 1), off the plane as in test_switch_in_null_plane. */
enum { CHAIN = 250 };
static int chain_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = p[0] * x[0] - x[0] * x[0] * x[0];
  f[1] = 4.0 * x[0] + 3.0 * x[1];
  for (int i = 2; i < CHAIN; ++i) f[i] = x[i] - 0.5 * x[i - 1];
  return 0;
}
static void test_switch_large(void) {
  whirl_system s = {.name = "chain", .n = CHAIN, .npar = 1, .F = chain_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  static double x[CHAIN], bt[CHAIN + 1], ph[CHAIN + 1], f0[CHAIN], f1[CHAIN];
  double p[1] = {1e-7};
  bt[1] = 0.01;
  bt[CHAIN] = 1.0;
  whirl_point q = {.n = CHAIN, .npar = 1, .x = x, .p = p, .t = bt};
  const int rc = c ? whirl_cont_switch_direction(c, &q, +1, ph) : -1;
  /* [F_x F_p] ph by a difference quotient of F (F is cubic in x0 only) */
  double xe[CHAIN], pe[1] = {p[0] + 1e-6 * ph[CHAIN]}, res = 0.0, along = 0.0;
  for (int i = 0; i < CHAIN; ++i) xe[i] = x[i] + 1e-6 * ph[i];
  chain_F(x, p, f0, NULL);
  chain_F(xe, pe, f1, NULL);
  for (int i = 0; i < CHAIN; ++i) res = fmax(res, fabs(f1[i] - f0[i]) / 1e-6);
  for (int i = 0; i <= CHAIN; ++i) along += ph[i] * bt[i];
  ok(rc == WHIRL_OK && res < 1e-5 && fabs(along) < 1e-9 && ph[0] > 0.5,
     "switch direction of %d unknowns (inverse iteration): in the null plane to %.1e, "
     "orthogonal to the tangent (%.1e), x0 %.4f", CHAIN + 1, res, fabs(along), ph[0]);
  whirl_cont_free(c);
}

/* newton_full (AUTO's NWTN): a new Jacobian at the first newton_full
 * iterations of a correction only, the last one kept after: the cusp's
 * folds as exact and every point on the curve, fewer Jacobians than
 * iterations (with 0, one at every iteration). */
static void test_newton_full(void) {
  whirl_system s = {.name = "cusp", .n = 1, .npar = 2, .F = cusp_F, .Fx = cusp_Fx,
                    .Fp = cusp_Fp};
  const double mu_f = 2.0 / (3.0 * sqrt(3.0));
  for (int full = 0; full <= 1; ++full) {
    whirl_cont_options o;
    cusp_options(&o, 0.4);
    o.newton_full = full;
    o.newton_tol = 1e-12;
    char err[256];
    whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
    whirl_branch *b = whirl_branch_alloc(1, 2, 0, 0);
    double x0 = -2.0, p0[2] = {-6.0, 1.0};
    int rc = c && b ? whirl_cont_start(c, &x0, p0, +1) : -1;
    if (rc == WHIRL_OK) rc = whirl_cont_run(c, b);
    const whirl_cont_stats *st = c ? whirl_cont_get_stats(c) : NULL;
    const whirl_branch_point *l1 = b ? nth_type(b, WHIRL_PT_LP, 0) : NULL;
    const double res = cusp_residual(b);
    ok(rc >= 0 && st && l1 && fabs(l1->p[0] - mu_f) < 1e-12 && res < 1e-10 &&
           (full ? st->jac_evals < st->newton_its : st->jac_evals >= st->newton_its),
       "newton_full %d: the fold at 2/(3 sqrt 3) (%.3g off), F = 0 (%.1e), %zu Jacobians "
       "for %zu iterations", full, l1 ? fabs(l1->p[0] - mu_f) : NAN, res,
       st ? st->jac_evals : 0, st ? st->newton_its : 0);
    whirl_branch_free(b);
    whirl_cont_free(c);
  }
}

static void test_bp(void) {
  whirl_system s = {.name = "pitchfork", .n = 1, .npar = 1, .F = pf_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.03;
  o.ds_max = 0.1;
  o.p_min = -1.0;
  o.p_max = 1.0;
  double x0 = 0.0, p0 = -1.0;
  whirl_branch *b = run(&s, &o, &x0, &p0, +1, NULL);
  ok(b && count_type(b, WHIRL_PT_BP) == 1, "pitchfork: one BP on the trivial branch");
  ok(count_type(b, WHIRL_PT_LP) == 0, "pitchfork: no spurious LP on the trivial branch");
  const whirl_branch_point *bp = nth_type(b, WHIRL_PT_BP, 0);
  if (bp) is_abs(bp->p[0], 0.0, 1e-10, "pitchfork BP at p = 0");

  /* transcritical: BP at 0, then switch onto x = p */
  whirl_system t = {.name = "transcritical", .n = 1, .npar = 1, .F = tc_F};
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&t, &o, err, sizeof err);
  whirl_cont_start(c, &x0, &p0, +1);
  whirl_point bpp;
  double bx = NAN, bpar = NAN, bt[2] = {0, 0};
  int found = 0;
  while (whirl_cont_step(c) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    if (pt->type == WHIRL_PT_BP && !found) {
      found = 1;
      bx = pt->x[0];
      bpar = pt->p[0];
      bt[0] = pt->t[0];
      bt[1] = pt->t[1];
    }
  }
  ok(found, "transcritical: BP found");
  is_abs(bpar, 0.0, 1e-10, "transcritical BP at p = 0");
  bpp = (whirl_point){.n = 1, .npar = 1, .x = &bx, .p = &bpar, .t = bt};
  whirl_branch *sw = whirl_branch_alloc(1, 1, 0, 0);
  int rc = whirl_cont_start_switch(c, &bpp, +1);
  ok(rc == WHIRL_OK, "transcritical: branch switching starts (%s)", whirl_cont_errmsg(c));
  if (rc == WHIRL_OK) whirl_cont_run(c, sw);
  double maxdev = 0.0, maxx = 0.0;
  for (size_t i = 1; i < sw->len; ++i) {
    maxdev = fmax(maxdev, fabs(sw->pts[i].x[0] - sw->pts[i].p[0]));
    maxx = fmax(maxx, fabs(sw->pts[i].x[0]));
  }
  ok(sw->len > 5 && maxx > 0.5, "switched branch leaves the trivial branch (max |x| = %g)", maxx);
  ok(maxdev < 1e-9, "switched branch is x = p (max |x - p| = %.2e)", maxdev);
  whirl_branch_free(sw);
  whirl_cont_free(c);
  whirl_branch_free(b);
}

/* ---- two curved branches crossing: F = (x - sin kp)(x + p)(1 + x^2),
 * followed along x = sin kp with AUTO-like few Newton iterations (ITNW 3)
 * and big steps.  A branch point is where sin kp = -p.  Near it the
 * bordered Jacobian is nearly singular and Newton's basin shrinks with the
 * distance, so a secant trial that lands close to it fails: the bracket's
 * midpoint is tried instead (before, the branch point was dropped). */
static double crv_k;
static int crv_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = (x[0] - sin(crv_k * p[0])) * (x[0] + p[0]) * (1.0 + x[0] * x[0]);
  return 0;
}

/* The roots of sin kp + p in [lo, hi] by bisection on a fine grid. */
static int crv_roots(double k, double lo, double hi, double *r, int max) {
  int n = 0;
  const int M = 20000;
  for (int i = 0; i < M && n < max; ++i) {
    double a = lo + (hi - lo) * i / M, b = lo + (hi - lo) * (i + 1) / M;
    double fa = sin(k * a) + a, fb = sin(k * b) + b;
    if (fa == 0) { r[n++] = a; continue; }
    if (fa * fb > 0) continue;
    for (int it = 0; it < 200; ++it) {
      double m = 0.5 * (a + b), fm = sin(k * m) + m;
      if (fa * fm <= 0) b = m; else { a = m; fa = fm; }
    }
    r[n++] = 0.5 * (a + b);
  }
  return n;
}

static void test_bp_curved(double k, double ds) {
  whirl_system s = {.name = "crossing", .n = 1, .npar = 1, .F = crv_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_max = ds;
  o.p_min = -0.7;
  o.p_max = 1.0;
  o.newton_maxit = 3;
  crv_k = k;
  double p0 = -0.7, x0 = sin(k * p0), r[8];
  int nr = crv_roots(k, -0.69, 1.0, r, 8);
  whirl_branch *b = run(&s, &o, &x0, &p0, +1, NULL);
  int nbp = b ? (int)count_type(b, WHIRL_PT_BP) : -1;
  ok(nbp == nr, "crossing k = %g, ds = %g: %d BPs, as the %d roots of sin kp = -p", k, ds, nbp, nr);
  double worst = 0.0;
  for (int i = 0; i < nr && i < nbp; ++i)
    worst = fmax(worst, fabs(nth_type(b, WHIRL_PT_BP, (size_t)i)->p[0] - r[i]));
  ok(nbp == nr && worst < 1e-8, "crossing k = %g: BPs at the roots (worst %.1e)", k, worst);
  whirl_branch_free(b);
}

static void test_hopf(void) {
  static const whirl_problem bru = {.name = "brusselator", .n = 2, .npar = 2,
                                    .rhs = bru_rhs, .autonomous = 1};
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&bru);
  const whirl_system *s = whirl_equilibrium_system(eq);
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.05;
  o.ds_max = 0.2;
  o.p_min = 0.0;
  o.p_max = 4.0;
  const double a = 1.5;
  double p0[2] = {1.0, a}, x0[2] = {a, 1.0 / a};
  whirl_branch *b = run(s, &o, x0, p0, +1, NULL);
  ok(b && count_type(b, WHIRL_PT_HB) == 1, "Brusselator: one HB");
  const whirl_branch_point *h = nth_type(b, WHIRL_PT_HB, 0);
  if (h) {
    is_abs(h->p[0], 1.0 + a * a, 1e-10, "Brusselator HB at b = 1 + a^2");
    double w = fabs(h->spec_im[0]);
    is_abs(w, a, 1e-8, "Brusselator HB frequency = a");
    is_abs(h->spec_re[0], 0.0, 1e-10, "Brusselator HB: critical real part 0");
  }
  /* stability flips at the Hopf point */
  int before = -2, after = -2;
  for (size_t i = 0; i < b->len; ++i) {
    if (b->pts[i].p[0] < 1.0 + a * a - 0.1) before = b->pts[i].stable;
    if (b->pts[i].p[0] > 1.0 + a * a + 0.1 && after == -2) after = b->pts[i].stable;
  }
  ok(before == 1 && after == 0, "Brusselator stable before and unstable after HB");
  whirl_branch_free(b);
  whirl_equilibrium_free(eq);
}

/* Fixed points of maps (whirl_map_fixed_points_alloc), against closed
 * forms.  The logistic map x ↦ μ x (1 − x): the fixed point 1 − 1/μ has the
 * multiplier 2 − μ, a flip (PD) at μ = 3, and crosses x = 0 at the
 * transcritical μ = 1 (BP).  The Hénon map (x, y) ↦ (1 − α x² + y, β x) at
 * α = 1: multipliers μ² + 2αx μ − β = 0, so a flip where x = (1 − β)/(2α)
 * is a fixed point, (1 − β)² = 4α/3, β = 1 − 2/√3, and a Neimark–Sacker
 * point (TR) at β = −1, where the complex pair has modulus √−β = 1. */
static int logistic_rhs(double t, const double *u, const double *p, double *f,
                        void *data) {
  (void)t, (void)data;
  f[0] = p[0] * u[0] * (1.0 - u[0]);
  return 0;
}
static int henon_rhs(double t, const double *u, const double *p, double *f,
                     void *data) {
  (void)t, (void)data;
  f[0] = 1.0 - p[0] * u[0] * u[0] + u[1];
  f[1] = p[1] * u[0];
  return 0;
}

/* The strong resonances on the Hénon map's Neimark–Sacker locus (β = −1,
 * κ = 2 √(1 + α)): κ = 2 (1:4, θ = π/2) at α = 0, κ = 3 (1:3) at
 * α = 5/4, κ = 4 (1:2) at α = 3 (closed forms; AUTO's hen demo labels
 * R4, R3, R2 there), each labelled once, both ways from the TR at α = 1. */
static void henon_resonances(whirl_hopf *h, const double *Z, const double *p) {
  static const int type[3] = {WHIRL_PT_R4, WHIRL_PT_R3, WHIRL_PT_R2};
  static const double alpha[3] = {0.0, 1.25, 3.0};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.icp = 0;
  o.ds = 0.02;
  o.ds_max = 0.1;
  o.p_min = -0.5;
  o.p_max = 3.5;
  whirl_branch *up = run(whirl_hopf_system(h), &o, Z, p, +1, NULL);
  whirl_branch *down = run(whirl_hopf_system(h), &o, Z, p, -1, NULL);
  for (int r = 0; r < 3; ++r) {
    size_t n = 0;
    double dev = INFINITY;
    for (int side = 0; side < 2; ++side) {
      const whirl_branch *b = side ? down : up;
      for (size_t i = 0; b && i < b->len; ++i)
        if (b->pts[i].type == type[r]) n++, dev = fabs(b->pts[i].p[0] - alpha[r]);
    }
    ok(n == 1 && dev < 1e-8, "Henon map: %s on the Neimark-Sacker locus at alpha = %g "
       "(%zu labelled, |dalpha| %.2g)", whirl_point_type_name(type[r]), alpha[r], n, dev);
  }
  whirl_branch_free(up);
  whirl_branch_free(down);
}

/* The Hénon map's Neimark–Sacker locus from its TR: β = −1 for every α
 * while the pair is complex, where αx = √(1 + α) − 1, so cos θ = −αx and
 * κ = 2 (1 − cos θ) = 2 √(1 + α) (closed forms). */
static void henon_ns_locus(const whirl_system *s, const whirl_branch_point *tr) {
  char err[256] = "";
  whirl_hopf *h = whirl_hopf_alloc_map(s, 1, err, sizeof err);
  double Z[4], p[2] = {tr->p[0], tr->p[1]};
  int rc = h ? whirl_hopf_init(h, tr->x, p, Z) : -1;
  ok(rc == WHIRL_OK && fabs(Z[3] - 2 * sqrt(2.0)) < 1e-8,
     "Henon map: Neimark-Sacker system started at the TR, kappa %.10g = 2 sqrt 2 %s",
     rc == WHIRL_OK ? Z[3] : NAN, h ? whirl_hopf_errmsg(h) : err);
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.icp = 0;
  o.ds = 0.02;
  o.ds_max = 0.1;
  o.p_min = 0.2;
  o.p_max = 2.0;
  whirl_branch *b = rc == WHIRL_OK ? run(whirl_hopf_system(h), &o, Z, p, +1, NULL) : NULL;
  double dev = 0;
  for (size_t i = 0; b && i < b->len; ++i) {
    const double a = b->pts[i].p[0], *z = b->pts[i].x;
    dev = fmax(dev, fabs(z[2] + 1.0));
    dev = fmax(dev, fabs(z[3] - 2 * sqrt(1 + a)));
    dev = fmax(dev, fabs(a * z[0] - (sqrt(1 + a) - 1)));
  }
  ok(b && b->len > 10 && dev < 1e-9,
     "Henon map: Neimark-Sacker locus in alpha on beta = -1, kappa = 2 sqrt(1 + alpha) "
     "(%zu points, max dev %.2g)", b ? b->len : 0, dev);
  whirl_branch_free(b);
  henon_resonances(h, Z, p);
  whirl_hopf_free(h);
}

/* The logistic map's period-2 points from its PD at μ = 3: the fixed
 * points of f² through the pitchfork of f² there (the period-1 branch
 * x = 1 − 1/μ, tangent (1/μ², 1), is a branch of f² too), switched onto
 * and followed to their own flip at μ = 1 + √6, where
 * x = ((μ + 1) ± √((μ + 1)(μ − 3))) / (2μ) (closed forms). */
static void logistic_period_two(const whirl_problem *lg, double x, double mu,
                                const whirl_cont_options *o) {
  whirl_equilibrium *eq = whirl_map_iterate_fixed_points_alloc(lg, 2);
  const whirl_system *s = whirl_equilibrium_system(eq);
  char err[256] = "";
  whirl_cont *c = eq ? whirl_cont_alloc(s, o, err, sizeof err) : NULL;
  double t[2] = {1.0 / (mu * mu), 1.0}, nt = hypot(t[0], t[1]), px = x, pp = mu;
  t[0] /= nt, t[1] /= nt;
  whirl_point bp = {.type = WHIRL_PT_BP, .n = 1, .npar = 1, .x = &px, .p = &pp, .t = t,
                    .stable = -1, .n_unstable = -1};
  int rc = c ? whirl_cont_start_switch(c, &bp, +1) : -1;
  double pd_mu = NAN, pd_x = NAN, x_mid = NAN;
  while (rc == WHIRL_OK && whirl_cont_step(c) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    if (pt->p[0] > 3.2 && pt->p[0] < 3.3 && isnan(x_mid)) x_mid = pt->x[0], pp = pt->p[0];
    if (pt->type == WHIRL_PT_PD && isnan(pd_mu)) pd_mu = pt->p[0], pd_x = pt->x[0];
  }
  const double m = 1 + sqrt(6.0), r = sqrt((m + 1) * (m - 3));
  const double xp = (m + 1 + r) / (2 * m), xm = (m + 1 - r) / (2 * m);
  const double rm = sqrt((pp + 1) * (pp - 3));
  ok(!isnan(x_mid) && fmin(fabs(x_mid - (pp + 1 + rm) / (2 * pp)),
                           fabs(x_mid - (pp + 1 - rm) / (2 * pp))) < 1e-10,
     "logistic map: switched at the PD onto the period-2 points (x %.10g at mu %.4g) %s",
     x_mid, pp, rc ? whirl_cont_errmsg(c) : "");
  ok(fabs(pd_mu - m) < 1e-9 && fmin(fabs(pd_x - xp), fabs(pd_x - xm)) < 1e-9,
     "logistic map: the period-2 points flip at mu = 1 + sqrt 6 (%.12g, x %.10g)", pd_mu, pd_x);
  whirl_cont_free(c);
  whirl_equilibrium_free(eq);
}

static void test_maps(void) {
  static const whirl_problem lg = {.name = "logistic", .n = 1, .npar = 1,
                                   .rhs = logistic_rhs, .autonomous = 1};
  whirl_equilibrium *eq = whirl_map_fixed_points_alloc(&lg);
  const whirl_system *s = whirl_equilibrium_system(eq);
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.02;
  o.ds_max = 0.1;
  o.p_min = 0.5;
  o.p_max = 3.5;
  double p0[1] = {1.5}, x0[1] = {1.0 / 3.0};
  /* the BP from both branches: along x = 0 (multiplier μ), and along
   * 1 − 1/μ, where Newton from the chord between the bracket's ends
   * landed on the crossing branch as often as not and the BP came out
   * 5e-4 off (the Hermite bend in the start fixes it: locate.c) */
  double z0[1] = {0.0}, m0[1] = {0.6};
  whirl_branch *down = run(s, &o, x0, p0, -1, NULL);
  const whirl_branch_point *bpd = down ? nth_type(down, WHIRL_PT_BP, 0) : NULL;
  ok(bpd && fabs(bpd->p[0] - 1.0) < 1e-10 && fabs(bpd->x[0]) < 1e-10,
     "logistic map, mu down along 1 - 1/mu: the BP at mu = 1, x = 0 (%.12g, %.3g)",
     bpd ? bpd->p[0] : NAN, bpd ? bpd->x[0] : NAN);
  whirl_branch_free(down);
  o.p_max = 1.5;
  whirl_branch *b = run(s, &o, z0, m0, +1, NULL);
  o.p_max = 3.5;
  whirl_branch *up = run(s, &o, x0, p0, +1, NULL);
  const whirl_branch_point *bp = b ? nth_type(b, WHIRL_PT_BP, 0) : NULL;
  ok(b && count_type(b, WHIRL_PT_BP) == 1 && count_type(b, WHIRL_PT_PD) == 0,
     "logistic map, x = 0 from mu = 0.6: one BP, no PD (%zu, %zu)",
     b ? count_type(b, WHIRL_PT_BP) : 0, b ? count_type(b, WHIRL_PT_PD) : 0);
  if (bp) is_abs(bp->p[0], 1.0, 1e-10, "logistic map: BP at mu = 1 (%.12g)", bp->p[0]);
  whirl_branch_free(b);
  b = up;
  const whirl_branch_point *pd = b ? nth_type(b, WHIRL_PT_PD, 0) : NULL;
  ok(s->spectrum_kind == WHIRL_SPEC_MULTIPLIERS && b &&
     count_type(b, WHIRL_PT_PD) == 1 && count_type(b, WHIRL_PT_BP) == 0,
     "logistic map, mu up from 1.5: one PD, no BP (%zu, %zu)",
     b ? count_type(b, WHIRL_PT_PD) : 0, b ? count_type(b, WHIRL_PT_BP) : 0);
  if (pd) {
    is_abs(pd->p[0], 3.0, 1e-10, "logistic map: PD at mu = 3");
    is_abs(pd->x[0], 2.0 / 3.0, 1e-10, "logistic map: PD at x = 2/3");
    is_abs(pd->spec_re[0], -1.0, 1e-9, "logistic map: multiplier -1 at the PD");
  }
  int mid = -2, past = -2;
  for (size_t i = 0; b && i < b->len; ++i) {
    if (fabs(b->pts[i].p[0] - 2.0) < 0.05) mid = b->pts[i].stable;
    if (b->pts[i].p[0] > 3.1) past = b->pts[i].stable;
  }
  ok(mid == 1 && past == 0, "logistic map: stable at mu = 2, unstable past 3");
  if (pd) logistic_period_two(&lg, pd->x[0], pd->p[0], &o);
  whirl_branch_free(b);
  whirl_equilibrium_free(eq);

  static const whirl_problem hn = {.name = "henon", .n = 2, .npar = 2,
                                   .rhs = henon_rhs, .autonomous = 1};
  eq = whirl_map_fixed_points_alloc(&hn);
  s = whirl_equilibrium_system(eq);
  whirl_cont_options_default(&o);
  o.icp = 1;
  o.ds = 0.02;
  o.ds_max = 0.1;
  o.p_min = -1.5;
  o.p_max = 0.31;
  const double beta0 = 0.3, xf = (-(1 - beta0) + sqrt((1 - beta0) * (1 - beta0) + 4)) / 2;
  double q0[2] = {1.0, beta0}, y0[2] = {xf, beta0 * xf};
  b = run(s, &o, y0, q0, -1, NULL);
  pd = b ? nth_type(b, WHIRL_PT_PD, 0) : NULL;
  const whirl_branch_point *tr = b ? nth_type(b, WHIRL_PT_TR, 0) : NULL;
  ok(b && count_type(b, WHIRL_PT_PD) == 1 && count_type(b, WHIRL_PT_TR) == 1,
     "Henon map: one PD and one TR (%zu, %zu)", b ? count_type(b, WHIRL_PT_PD) : 0,
     b ? count_type(b, WHIRL_PT_TR) : 0);
  if (pd) is_abs(pd->p[1], 1.0 - 2.0 / sqrt(3.0), 1e-10, "Henon map: PD at beta = 1 - 2/sqrt 3");
  if (tr) {
    is_abs(tr->p[1], -1.0, 1e-10, "Henon map: TR at beta = -1");
    is_abs(tr->x[0], sqrt(2.0) - 1.0, 1e-10, "Henon map: TR at x = sqrt 2 - 1");
    henon_ns_locus(s, tr);
  }
  whirl_branch_free(b);
  whirl_equilibrium_free(eq);
}

/* Two complex pairs, A with real part p - 1 (through the axis at p = 1),
 * B fixed at -0.15: with steps of 0.3 in p the points p = 0.9 (A nearest
 * the axis, -0.1) and 1.2 (A at +0.2, now B nearest, -0.15) bracket the
 * Hopf point while the test "real part of the pair nearest the axis"
 * keeps its sign: it was missed there (it happened on the Hill
 * multipliers of an FE rotor) and must be found, at p = 1. */
static int two_pairs_rhs(double t, const double *u, const double *p, double *f,
                         void *data) {
  (void)t, (void)data;
  const double a = p[0] - 1.0, b = -0.15;
  f[0] = a * u[0] + 2.0 * u[1];
  f[1] = -2.0 * u[0] + a * u[1];
  f[2] = b * u[2] + 5.0 * u[3];
  f[3] = -5.0 * u[2] + b * u[3];
  return 0;
}

static void test_hopf_nearest_switch(void) {
  static const whirl_problem pr = {.name = "two pairs", .n = 4, .npar = 1,
                                   .rhs = two_pairs_rhs, .autonomous = 1};
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&pr);
  const whirl_system *s = whirl_equilibrium_system(eq);
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_min = o.ds_max = 0.3;
  o.p_min = -1.0;
  o.p_max = 1.9;
  double p0[1] = {0.0}, x0[4] = {0, 0, 0, 0};
  whirl_branch *b = run(s, &o, x0, p0, +1, NULL);
  const whirl_branch_point *h = b ? nth_type(b, WHIRL_PT_HB, 0) : NULL;
  ok(b && count_type(b, WHIRL_PT_HB) == 1,
     "two pairs, the nearest one switching within a step: one HB (%zu)",
     b ? count_type(b, WHIRL_PT_HB) : 0);
  if (h) is_abs(h->p[0], 1.0, 1e-10, "two pairs: the HB at p = 1");
  whirl_branch_free(b);
  whirl_equilibrium_free(eq);
}

static void test_loop(void) {
  whirl_system s = {.name = "circle", .n = 1, .npar = 1, .F = circ_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.05;
  o.ds_max = 0.1;
  double x0 = 1.0, p0 = 0.0;
  whirl_branch *b = NULL;
  char err[256];
  whirl_cont_stats st = {0};
  int rc = whirl_trace_branch(&s, &o, &x0, &p0, &b, &st, err, sizeof err);
  ok(rc == WHIRL_OK && b, "circle traced");
  ok(b->stop_reason == WHIRL_STOP_LOOP, "circle: branch closed on itself");
  ok(count_type(b, WHIRL_PT_LP) == 2, "circle: two folds");
  const whirl_branch_point *l1 = nth_type(b, WHIRL_PT_LP, 0), *l2 = nth_type(b, WHIRL_PT_LP, 1);
  if (l1 && l2) {
    is_abs(fabs(l1->p[0]), 1.0, 1e-12, "circle fold at |p| = 1");
    is_abs(l1->p[0] + l2->p[0], 0.0, 1e-12, "circle folds at p = -1 and p = +1");
  }
  is_abs(b->pts[0].x[0], b->pts[b->len - 1].x[0], 1e-12, "circle: polyline closes");
  ok(st.steps > 10 && st.newton_its >= st.steps, "statistics counted (%zu steps, %zu its)",
     st.steps, st.newton_its);
  whirl_branch_free(b);
}

/* AUTO's algebraic corrector (arclength_sphere): each new point of the
 * circle x^2 + p^2 = 1 at the step's chord from the last, |dX| = ds, the
 * arc 2 asin(ds/2) (the hyperplane's point lies farther, its distance to
 * the last sqrt(ds^2 + h^2) past the tangent); and the stored directions
 * (point_dir): the step's own secant, or the one it was predicted along,
 * the secant of the step before. */
static void test_sphere(int point_dir) {
  whirl_system s = {.name = "circle", .n = 1, .npar = 1, .F = circ_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_max = 0.3;
  o.ds_min = 1e-3;
  o.newton_tol = 1e-12;
  o.max_angle = 3.0;
  o.detect_lp = o.detect_bp = o.detect_hb = 0;
  o.arclength_sphere = 1;
  o.point_dir = point_dir;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x0 = 1.0, p0 = 0.0, X[12][2], D[12][2];
  int rc = c ? whirl_cont_start(c, &x0, &p0, 1) : -1;
  size_t m = 0;
  while (rc == WHIRL_OK && m < 12 && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    if (pt->index == 0) continue;
    X[m][0] = pt->x[0], X[m][1] = pt->p[0];
    D[m][0] = pt->dir[0], D[m][1] = pt->dir[1];
    ++m;
  }
  ok(m == 12, "sphere, point_dir %d: 12 points (rc %d)", point_dir, rc);
  double worst = 0.0, wdir = 0.0;
  for (size_t k = 1; k < m; ++k) {
    const double dx = X[k][0] - X[k - 1][0], dp = X[k][1] - X[k - 1][1];
    const double h = hypot(dx, dp);
    worst = fmax(worst, fabs(h - 0.3));
    /* the direction the point stores: its step's secant, or the previous */
    if (k >= 2) {
      const size_t j = point_dir == WHIRL_DIR_SECANT ? k : k - 1;
      const double ex = (X[j][0] - X[j - 1][0]) / 0.3, ep = (X[j][1] - X[j - 1][1]) / 0.3;
      wdir = fmax(wdir, hypot(D[k][0] - ex, D[k][1] - ep));
    }
  }
  ok(m == 12 && worst < 1e-10, "sphere: every chord is ds = 0.3 (worst |chord - ds| %.1e)", worst);
  ok(m == 12 && wdir < 1e-9, "sphere, point_dir %s: whirl_point.dir is %s (worst %.1e)",
     point_dir == WHIRL_DIR_SECANT ? "SECANT" : "PREDICTOR",
     point_dir == WHIRL_DIR_SECANT ? "the step's own secant" : "the previous step's secant", wdir);
  whirl_cont_free(c);
}

static void test_uz(void) {
  whirl_system s = {.name = "cusp", .n = 1, .npar = 2, .F = cusp_F, .Fx = cusp_Fx};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  const double uz[2] = {-3.0, 1.25};
  o.uz = uz;
  o.nuz = 2;
  o.p_min = -6.5;
  o.p_max = 6.5;
  double x0 = -2.0, p0[2] = {-6.0, 1.0};
  whirl_branch *b = run(&s, &o, &x0, p0, +1, NULL);
  ok(count_type(b, WHIRL_PT_UZ) == 2, "UZ: both requested values output");
  const whirl_branch_point *u = nth_type(b, WHIRL_PT_UZ, 1);
  if (u) is_abs(u->p[0], 1.25, 1e-12, "UZ at mu = 1.25");
  whirl_branch_free(b);
}

/* A user value met exactly by a step: on the trivial branch x = 0 of
 * F = x the steps of 0.25 from p = 0 land on p = 1 exactly (binary
 * fractions), where the value minus 1 is 0.0, not a sign change; that
 * point is the UZ, once (the step after it, from the zero, is no
 * crossing).  Before 2026-12-07 it was missed (no UZ at all). */
static int zero_F(const double *x, const double *p, double *f, void *d) {
  (void)p, (void)d;
  f[0] = x[0];
  return 0;
}
static int zero_Fx(const double *x, const double *p, double *J, void *d) {
  (void)x, (void)p, (void)d;
  J[0] = 1.0;
  return 0;
}

static void test_uz_exact(void) {
  whirl_system s = {.name = "zero", .n = 1, .npar = 1, .F = zero_F, .Fx = zero_Fx};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  const double uz[1] = {1.0};
  o.uz = uz;
  o.nuz = 1;
  o.ds = o.ds_max = 0.25;
  o.p_max = 2.1;
  double x0 = 0.0, p0[1] = {0.0};
  whirl_branch *b = run(&s, &o, &x0, p0, +1, NULL);
  const whirl_branch_point *u = b ? nth_type(b, WHIRL_PT_UZ, 0) : NULL;
  int exact_steps = 1;
  for (size_t i = 0; b && i < b->len; ++i)
    if (b->pts[i].type == WHIRL_PT_REGULAR && fmod(b->pts[i].p[0], 0.25) != 0.0)
      exact_steps = 0;
  ok(b && count_type(b, WHIRL_PT_UZ) == 1 && u && u->p[0] == 1.0 && exact_steps,
     "UZ met exactly by a step (p = 1 after four steps of 0.25): labelled once, at p = %g "
     "(%zu UZ; steps exact: %d)", u ? u->p[0] : NAN, b ? count_type(b, WHIRL_PT_UZ) : 0,
     exact_steps);
  whirl_branch_free(b);
}

/* User values of a quantity other than the continuation parameter (the
 * state x on the circle x^2 + p^2 = 1): localised like every special point,
 * and a stop value ends the branch (AUTO's UZR/UZSTOP on any quantity). */
static double circle_x(size_t k, const double *x, const double *p, void *ctx) {
  (void)k;
  (void)p;
  ++*(int *)ctx;
  return x[0];
}

static void test_uz_fun(void) {
  whirl_system s = {.name = "circle", .n = 1, .npar = 1, .F = circ_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.05;
  o.ds_max = 0.1;
  const double uz[2] = {0.6, -0.8};
  const int stop[2] = {0, 1};
  int calls = 0;
  o.uz = uz;
  o.uz_stop = stop;
  o.nuz = 2;
  o.uz_fun = circle_x;
  o.uz_ctx = &calls;
  double x0 = 1.0, p0 = 0.0;
  int reason = 0;
  whirl_branch *b = run(&s, &o, &x0, &p0, +1, &reason);
  ok(calls > 0, "uz_fun: the quantity is evaluated (%d calls)", calls);
  ok(count_type(b, WHIRL_PT_UZ) == 2, "uz_fun: both user values of x output");
  const whirl_branch_point *u0 = nth_type(b, WHIRL_PT_UZ, 0), *u1 = nth_type(b, WHIRL_PT_UZ, 1);
  if (u0 && u1) {
    is_abs(u0->x[0], 0.6, 1e-12, "uz_fun: first UZ at x = 0.6");
    is_abs(u0->p[0], 0.8, 1e-10, "uz_fun: there p = 0.8 (on the circle)");
    is_abs(u1->x[0], -0.8, 1e-12, "uz_fun: stop at x = -0.8 past the fold");
    is_abs(u1->p[0], 0.6, 1e-10, "uz_fun: there p = 0.6");
  } else {
    ok(0, "uz_fun: UZ points missing");
  }
  ok(reason == WHIRL_STOP_UZ, "uz_fun: the stop value ends the branch (reason %d)", reason);
  ok(b && b->len && b->pts[b->len - 1].type == WHIRL_PT_UZ,
     "uz_fun: the branch ends on the UZ point");
  whirl_branch_free(b);
}

static void test_bratu(void) {
  int q = 0;
  for (int j = 0; j < BRATU_M; ++j) {
    bratu_Jp[j] = q;
    if (j > 0) bratu_Ji[q++] = j - 1;
    bratu_Ji[q++] = j;
    if (j < BRATU_M - 1) bratu_Ji[q++] = j + 1;
  }
  bratu_Jp[BRATU_M] = q;
  whirl_system s = {.name = "bratu", .n = BRATU_M, .npar = 1, .F = bratu_F,
                    .Fx = bratu_Fx, .Fp = bratu_Fp, .nnz = (size_t)q,
                    .Jp = bratu_Jp, .Ji = bratu_Ji, .Fx_sparse = bratu_Fxs};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.1;
  o.ds_max = 0.5;
  o.p_min = -0.5;
  o.p_max = 4.0;
  o.x_max = 6.0;
  double u0[BRATU_M] = {0}, p0 = 0.0;
  whirl_branch *bd = run(&s, &o, u0, &p0, +1, NULL);
  o.linsol = WHIRL_LINSOL_SPARSE;
  whirl_branch *bs = run(&s, &o, u0, &p0, +1, NULL);
  const whirl_branch_point *ld = nth_type(bd, WHIRL_PT_LP, 0), *ls = nth_type(bs, WHIRL_PT_LP, 0);
  ok(ld && ls, "Bratu: fold found by the dense and by the sparse solver");
  if (ld && ls) {
    is_rel(ls->p[0], ld->p[0], 1e-11, "Bratu fold: sparse = dense");
    double du = 0;
    for (int i = 0; i < BRATU_M; ++i) du = fmax(du, fabs(ls->x[i] - ld->x[i]));
    ok(du < 1e-8, "Bratu fold state: sparse = dense (max diff %.2e)", du);
    /* continuous problem: mu_c = 3.513830719125162 (Bratu, from the
     * transcendental equation); centred differences are O(h^2) below it */
    is_rel(ld->p[0], 3.513830719125162, 2e-3, "Bratu fold near the continuous value");
  }
  whirl_branch_free(bd);
  whirl_branch_free(bs);
}

/* The exact unit tangent of Bratu's branch at (u, p): v = du/dp from
 * F_u v = -F_p (dense Gaussian elimination on the tridiagonal F_u), t =
 * (v, 1)/|(v, 1)| oriented as ref.  Returns |t - ref|_inf. */
static double bratu_tangent_error(const double *u, double p, const double *ref) {
  double J[BRATU_M * BRATU_M], v[BRATU_M], t[BRATU_M + 1];
  bratu_Fx(u, &p, J, NULL);
  bratu_Fp(u, &p, 0, v, NULL);
  for (int i = 0; i < BRATU_M; ++i) v[i] = -v[i];
  for (int k = 0; k < BRATU_M; ++k) /* no pivoting: F_u is diagonally dominant here */
    for (int i = k + 1; i < BRATU_M; ++i) {
      const double m = J[i + BRATU_M * k] / J[k + BRATU_M * k];
      for (int j = k; j < BRATU_M; ++j) J[i + BRATU_M * j] -= m * J[k + BRATU_M * j];
      v[i] -= m * v[k];
    }
  for (int i = BRATU_M - 1; i >= 0; --i) {
    for (int j = i + 1; j < BRATU_M; ++j) v[i] -= J[i + BRATU_M * j] * v[j];
    v[i] /= J[i + BRATU_M * i];
  }
  double nn = 1.0, dot = 0.0, err = 0.0;
  for (int i = 0; i < BRATU_M; ++i) nn += v[i] * v[i];
  nn = sqrt(nn);
  for (int i = 0; i < BRATU_M; ++i) t[i] = v[i] / nn;
  t[BRATU_M] = 1.0 / nn;
  for (int i = 0; i <= BRATU_M; ++i) dot += t[i] * ref[i];
  for (int i = 0; i <= BRATU_M; ++i) err = fmax(err, fabs((dot < 0 ? -t[i] : t[i]) - ref[i]));
  return err;
}

/* tangent_from_newton: the tangents of the regular points from the
 * corrector's last factorisation (at the iterate before the last
 * correction, a loose EPSL apart) against the exact tangent, the fold
 * (located afresh) as with fresh Jacobians, and a Jacobian fewer a step;
 * refined (1) to far below EPSL, as it is (2, AUTO's direction vector)
 * within EPSL and with two evaluations of F fewer a step. */
static void test_tangent_from_newton(void) {
  whirl_system s = {.name = "bratu", .n = BRATU_M, .npar = 1, .F = bratu_F,
                    .Fx = bratu_Fx, .Fp = bratu_Fp};
  whirl_cont_options o;
  double lp[3] = {NAN, NAN, NAN}, worst[3] = {0.0, 0.0, 0.0};
  size_t jac[3] = {0}, steps[3] = {0}, fev[3] = {0};
  for (int reuse = 0; reuse < 3; ++reuse) {
    whirl_cont_options_default(&o);
    o.ds = 0.1;
    o.ds_max = 0.3;
    o.p_min = -0.5;
    o.p_max = 4.0;
    o.x_max = 6.0;
    o.newton_tol = 1e-6; /* the last iterate well apart from the point */
    o.tangent_from_newton = reuse;
    char err[256];
    whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
    double u0[BRATU_M] = {0}, p0 = 0.0;
    int rc = c ? whirl_cont_start(c, u0, &p0, +1) : -1;
    while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
      const whirl_point *pt = whirl_cont_point(c);
      if (pt->type == WHIRL_PT_LP) lp[reuse] = pt->p[0];
      if (reuse && pt->type == WHIRL_PT_REGULAR && fabs(pt->t[BRATU_M]) > 0.05)
        worst[reuse] = fmax(worst[reuse], bratu_tangent_error(pt->x, pt->p[0], pt->t));
    }
    if (c) {
      jac[reuse] = whirl_cont_get_stats(c)->jac_evals;
      steps[reuse] = whirl_cont_get_stats(c)->steps;
      fev[reuse] = whirl_cont_get_stats(c)->f_evals;
    }
    whirl_cont_free(c);
  }
  ok(worst[1] > 0 && worst[1] < 1e-9,
     "tangent_from_newton: regular tangents = the exact tangent (max diff %.2e)", worst[1]);
  is_rel(lp[1], lp[0], 1e-12, "tangent_from_newton: the fold as with fresh Jacobians");
  ok(steps[1] > 10 && jac[1] + steps[1] / 2 < jac[0],
     "tangent_from_newton: %zu Jacobians against %zu (%zu and %zu steps)", jac[1],
     jac[0], steps[1], steps[0]);
  /* unrefined: off by O(|X - X_k|) <= newton_tol, more than refined */
  ok(worst[2] > 10 * worst[1] && worst[2] < 1e-5,
     "tangent_from_newton = 2: tangents within EPSL of the exact one (%.2e, refined %.2e)",
     worst[2], worst[1]);
  is_rel(lp[2], lp[0], 1e-12, "tangent_from_newton = 2: the fold as with fresh Jacobians");
  ok(steps[2] == steps[1] && jac[2] == jac[1] && fev[2] + 2 * steps[2] <= fev[1],
     "tangent_from_newton = 2: %zu F evaluations against %zu, the same %zu Jacobians "
     "(%zu and %zu steps)", fev[2], fev[1], jac[2], steps[2], steps[1]);
}

/* AUTO-07p demo enz's equations (two coupled enzyme compartments, p =
 * (s0, mu, rho, kappa) = (s0, 0, 100, 1)), continued in s0 from 0 with
 * c.enz.1's constants: the symmetric branch has a pitchfork at s0 =
 * 22.18, where the asymmetric branch turns (a pitchfork by a fold).  A
 * secant iterate of the localisation landed within 3e-15 (relative
 * determinant) of it, the next one failed beside it and the point was
 * lost, with tangent_from_newton (the run files' setting). */
static int enz_F(const double *u, const double *p, double *f, void *d) {
  (void)d;
  const double k = p[3], r1 = u[0] / (1 + u[0] + k * u[0] * u[0]),
               r2 = u[1] / (1 + u[1] + k * u[1] * u[1]);
  f[0] = (p[0] - u[0]) + (u[1] - u[0]) - p[2] * r1;
  f[1] = (p[0] + p[1] - u[1]) + (u[0] - u[1]) - p[2] * r2;
  return 0;
}
static int enz_rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t;
  return enz_F(u, p, f, d);
}
static void test_bp_at_fold(void) {
  /* as whirl run builds it: an equilibrium system of the vector field,
   * its Jacobians by whirl's central differences */
  whirl_problem pr = {.name = "enz", .n = 2, .npar = 4, .rhs = enz_rhs, .autonomous = 1};
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&pr);
  const whirl_system *sp = eq ? whirl_equilibrium_system(eq) : NULL;
  if (!sp) {
    ok(0, "enz: equilibrium system");
    return;
  }
  const whirl_system s = *sp;
  for (int reuse = 0; reuse < 2; ++reuse) {
    whirl_cont_options o;
    whirl_cont_options_default(&o);
    o.ds = 0.1;
    o.ds_min = 0.01;
    o.ds_max = 0.25;
    o.nmx = 250;
    o.newton_tol = 1e-7;
    o.newton_maxit = 5;
    o.tangent_from_newton = reuse;
    double u0[2] = {0, 0}, p0[4] = {0, 0, 100, 1};
    whirl_branch *b = run(&s, &o, u0, p0, +1, NULL);
    size_t nbp = b ? count_type(b, WHIRL_PT_BP) : 0;
    const whirl_branch_point *bp = b ? nth_type(b, WHIRL_PT_BP, 1) : NULL;
    ok(nbp == 2 && bp && fabs(bp->p[0] - 22.1816) < 1e-3,
       "enz (tangent %s): the pitchfork at s0 = 22.18 found (%zu BPs; %.10g)",
       reuse ? "from Newton" : "fresh", nbp, bp ? bp->p[0] : NAN);
    whirl_branch_free(b);
  }
  whirl_equilibrium_free(eq);
}

static void test_two_at_once(void) {
  whirl_system s = {.name = "cusp", .n = 1, .npar = 2, .F = cusp_F, .Fx = cusp_Fx, .Fp = cusp_Fp};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.p_min = -6.5;
  o.p_max = 6.5;
  char err[128];
  whirl_cont *c1 = whirl_cont_alloc(&s, &o, err, sizeof err);
  whirl_cont *c2 = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x1 = -2.0, p1[2] = {-6.0, 1.0}, x2 = 2.0, p2[2] = {6.0, 1.0};
  whirl_cont_start(c1, &x1, p1, +1);
  whirl_cont_start(c2, &x2, p2, -1);
  int r1 = WHIRL_OK, r2 = WHIRL_OK;
  double lp1 = NAN, lp2 = NAN;
  while (r1 == WHIRL_OK || r2 == WHIRL_OK) {
    if (r1 == WHIRL_OK && (r1 = whirl_cont_step(c1)) == WHIRL_OK &&
        whirl_cont_point(c1)->type == WHIRL_PT_LP && isnan(lp1))
      lp1 = whirl_cont_point(c1)->p[0];
    if (r2 == WHIRL_OK && (r2 = whirl_cont_step(c2)) == WHIRL_OK &&
        whirl_cont_point(c2)->type == WHIRL_PT_LP && isnan(lp2))
      lp2 = whirl_cont_point(c2)->p[0];
  }
  is_abs(lp1, 2.0 / (3.0 * sqrt(3.0)), 1e-12, "interleaved run 1 fold");
  is_abs(lp2, -2.0 / (3.0 * sqrt(3.0)), 1e-12, "interleaved run 2 fold (other direction)");
  whirl_cont_free(c1);
  whirl_cont_free(c2);
}


/* ---- an outward spiral in the weighted norm: (x0, p) = r(th) (cos th,
 * sin th), r = 1 + 0.05 th / (2 pi), th = x1 / 120, with x1's weight
 * 1e-6 (out of the step, as AUTO's THU = 0, or a BVP's many node values
 * against their integral weights).  After one turn the branch passes
 * 0.05 from its start, 5 steps of 0.01 away: no loop.  The loop test
 * measured the step unweighted (1.2 per step in x1) against the weighted
 * distance and stopped there "closed on itself" (spb's c.spb.3, a BVP
 * whose node values outnumber the integral norm: 565 of AUTO's 1554
 * points). */
static int spiral_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  const double th = x[1] / 120.0, r = 1.0 + 0.05 * th / (2.0 * M_PI);
  f[0] = x[0] - r * cos(th);
  f[1] = p[0] - r * sin(th);
  return 0;
}

static void test_loop_weighted(void) {
  whirl_system s = {.name = "spiral", .n = 2, .npar = 1, .F = spiral_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_max = 0.01;
  o.nmx = 800;
  const double xw[2] = {1.0, 1e-6};
  o.x_weight = xw;
  double x0[2] = {1.0, 0.0}, p0 = 0.0;
  whirl_branch *b = NULL;
  char err[256];
  whirl_cont_stats st = {0};
  int rc = whirl_trace_branch(&s, &o, x0, &p0, &b, &st, err, sizeof err);
  ok(rc == WHIRL_OK && b, "spiral traced");
  const double th = b && b->len ? b->pts[b->len - 1].x[1] / 120.0 : 0.0;
  ok(b && b->stop_reason == WHIRL_STOP_NMX && th > 2.0 * M_PI,
     "spiral, weighted norm: not a loop where it passes 0.05 from its start "
     "(stop %d after %.3f turns)", b ? b->stop_reason : -1, th / (2.0 * M_PI));
  whirl_branch_free(b);
}

/* ---- a kink, not a fold: x2 = x1, p = |x1| - x1/4: through x1 = 0
 * dp/dx1 jumps from -5/4 to +3/4, the tangent's p component jumps sign and
 * is never zero (lcbp's BP locus where the orbit shrinks to u = 0 and the
 * equations take |u|: AUTO's Newton fails there).  Not a fold: no LP.
 * Smoothed, p = sqrt(x1^2 + eps^2) - x1/4 with eps = 0.01, the fold at
 * dp/dx1 = 0, x1 = eps/sqrt(15), is one. */
static int kink_F(const double *x, const double *p, double *f, void *d) {
  const double eps = d ? *(const double *)d : 0.0;
  f[0] = x[1] - x[0];
  f[1] = p[0] - (eps > 0 ? sqrt(x[0] * x[0] + eps * eps) : fabs(x[0])) + 0.25 * x[0];
  return 0;
}

/* its Jacobian, analytic: the kink sharp (central differences across it
 * round the corner off within their step, and there the tangent's p
 * component does pass zero) */
static int kink_Fx(const double *x, const double *p, double *J, void *d) {
  (void)p;
  const double eps = d ? *(const double *)d : 0.0;
  const double g = eps > 0 ? x[0] / sqrt(x[0] * x[0] + eps * eps) : x[0] < 0 ? -1.0 : 1.0;
  J[0] = -1.0, J[1] = -g + 0.25, J[2] = 1.0, J[3] = 0.0;
  return 0;
}

static void test_kink_no_fold(void) {
  for (int smooth = 0; smooth <= 1; ++smooth) {
    double eps = smooth ? 1e-2 : 0.0;
    whirl_system s = {.name = "kink", .n = 2, .npar = 1, .F = kink_F, .Fx = kink_Fx, .data = &eps};
    whirl_cont_options o;
    whirl_cont_options_default(&o);
    o.ds = o.ds_max = 0.07;
    o.nmx = 200;
    double x0[2] = {-1.0, -1.0}, p0;
    p0 = (smooth ? sqrt(1.0 + eps * eps) : 1.0) - 0.25;
    whirl_branch *b = NULL;
    char err[256];
    whirl_cont_stats st = {0};
    int rc = whirl_trace_branch(&s, &o, x0, &p0, &b, &st, err, sizeof err);
    const double xend = b && b->len ? b->pts[0].x[0] : -1.0; /* the p-decreasing end */
    const size_t nlp = b ? count_type(b, WHIRL_PT_LP) : 99;
    if (!smooth)
      ok(rc == WHIRL_OK && xend > 0.3 && nlp == 0,
         "a kink p = |x1| - x1/4: passed (x1 to %.3g), no LP (%zu)", xend, nlp);
    else {
      const whirl_branch_point *l = b ? nth_type(b, WHIRL_PT_LP, 0) : NULL;
      /* dp/dx1 = x1 / sqrt(x1^2 + eps^2) - 1/4 = 0: x1 = eps / sqrt(15) */
      ok(rc == WHIRL_OK && nlp == 1 && l && fabs(l->x[0] - eps / sqrt(15.0)) < 1e-8,
         "smoothed, p = sqrt(x1^2 + 1e-4) - x1/4: one LP at x1 = eps/sqrt(15) = %.6g (%zu, at "
         "%.10g)", eps / sqrt(15.0), nlp, l ? l->x[0] : NAN);
    }
    whirl_branch_free(b);
  }
}

/* ---- a determinant that changes sign through a pole, not a zero: x2 = 0,
 * mu / (x1 - 1) = 0, whose solutions mu = x2 = 0 form the line along x1
 * (demo r3b's circle of equilibria at mu = 0 meets the second primary
 * so, where its mu / r2^3 is singular).  det [F_x F_mu; t] = 1 / (x1 − 1)
 * up to its sign: it changes sign at x1 = 1 and grows without bound
 * there, and the line has no branch point.  AUTO's localisation finds no
 * zero and labels nothing; whirl labelled a BP at x1 = 1 until 2026-12-07. */
static int pole_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[1];
  f[1] = p[0] / (x[0] - 1.0);
  return 0;
}
static void test_pole_no_bp(void) {
  whirl_system s = {.name = "pole", .n = 2, .npar = 1, .F = pole_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_max = 0.07;
  o.nmx = 30;
  o.detect_lp = 0; /* the line is vertical in mu: its fold test is 0 */
  double x0[2] = {0.03, 0.0}, p0 = 0.0;
  whirl_branch *b = run(&s, &o, x0, &p0, +1, NULL);
  const double xend = b && b->len ? b->pts[b->len - 1].x[0] : NAN;
  const size_t nbp = b ? count_type(b, WHIRL_PT_BP) : 99;
  ok(b && nbp == 0 && fabs(xend) > 1.5,
     "a pole of det [F_x F_mu; t] (mu / (x1 - 1) = 0): passed (x1 to %.3g), no BP (%zu)",
     xend, nbp);
  whirl_branch_free(b);
}

/* ---- a straight line x = (p, 100 p): the arclength per unit p is
 * sqrt(1 + 1e4 + 1) with unit weights and sqrt(2) when the second
 * component's weight is 0 (AUTO's THU), sqrt(1 + 1e4 + 4) with p_weight 2
 * (THL).  With the step held at ds, n steps advance p by n ds / that. */
static int line_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] - p[0];
  f[1] = x[1] - 100.0 * p[0];
  return 0;
}

static double line_p_after(const double *xw, double pw, int nsteps, double *s_out) {
  whirl_system s = {.name = "line", .n = 2, .npar = 1, .F = line_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_max = 0.01;
  o.x_weight = xw;
  o.p_weight = pw;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x0[2] = {0, 0}, p0 = 0;
  double p = NAN;
  if (c && whirl_cont_start(c, x0, &p0, +1) == WHIRL_OK) {
    /* the first step returns the start point, index 0 */
    while (whirl_cont_step(c) == WHIRL_OK && whirl_cont_point(c)->index < (size_t)nsteps)
      ;
    if (whirl_cont_point(c)->index == (size_t)nsteps) {
      p = whirl_cont_point(c)->p[0];
      *s_out = whirl_cont_point(c)->s;
    }
  }
  whirl_cont_free(c);
  return p;
}

/* The system's own norm weights (whirl_system.norm_weights, collocation's
 * quadrature weights of its node values), which multiply x_weight² and
 * change when the system changes its representation (remap): on the line
 * x = (p, 100 p) with the factors q = (3, 0) a step of ds moves p by
 * ds/sqrt(3 + 1) = ds/2; from the remap before the 6th step, q = (8, 0):
 * ds/3.  10 steps of 0.01 then advance p by 5 (0.01/2 + 0.01/3). */
typedef struct nw_line {
  int steps; /* remap calls */
  double q0;
} nw_line;
static int nw_weights(double *q, void *d) {
  const nw_line *l = d;
  q[0] = l->q0;
  q[1] = 0.0;
  return 0;
}
static int nw_remap(double *const *v, size_t nv, const double *p, void *d) {
  (void)v, (void)nv, (void)p;
  nw_line *l = d;
  if (++l->steps != 6) return 0;
  l->q0 = 8.0; /* a new representation, measured anew */
  return 1;
}
static void test_system_weights(void) {
  nw_line l = {0, 3.0};
  whirl_system s = {.name = "line", .n = 2, .npar = 1, .F = line_F,
                    .norm_weights = nw_weights, .remap = nw_remap, .data = &l};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_min = o.ds_max = 0.01;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x0[2] = {0, 0}, p0 = 0, p5 = NAN, p10 = NAN;
  if (c && whirl_cont_start(c, x0, &p0, +1) == WHIRL_OK)
    while (whirl_cont_step(c) == WHIRL_OK && whirl_cont_point(c)->index <= 10) {
      if (whirl_cont_point(c)->index == 5) p5 = whirl_cont_point(c)->p[0];
      if (whirl_cont_point(c)->index == 10) p10 = whirl_cont_point(c)->p[0];
    }
  is_rel(p5, 5 * 0.01 / 2.0, 1e-10, "norm_weights (3, 0): 5 steps of 0.01 move p "
         "by 0.05/2 (%.12g)", p5);
  is_rel(p10 - p5, 5 * 0.01 / 3.0, 1e-10, "norm_weights (8, 0) after a remap: "
         "the next 5 by 0.05/3 (%.12g)", p10 - p5);
  whirl_cont_free(c);
  /* with every detection off the remapped point is not analysed anew
   * (its mapped tangent is the tangent): the remap costs no Jacobian;
   * with detection on it costs one (a factorisation at the point on the
   * new representation, for the tests) */
  size_t jac[2][2] = {{0, 0}, {0, 0}}; /* [detection][remap] */
  for (int det = 0; det < 2; ++det)
    for (int rm = 0; rm < 2; ++rm) {
      l.steps = rm ? 0 : -1000; /* the remap at the 6th step, or never */
      l.q0 = 3.0;
      o.detect_lp = o.detect_bp = o.detect_hb = o.detect_pd = det;
      c = whirl_cont_alloc(&s, &o, err, sizeof err);
      int rs = c ? whirl_cont_start(c, x0, &p0, +1) : -1;
      if (rs) printf("# start %d: %s\n", rs, c ? whirl_cont_errmsg(c) : err);
      if (rs == WHIRL_OK)
        while (whirl_cont_step(c) == WHIRL_OK && whirl_cont_point(c)->index <= 10) {
        }
      if (c) jac[det][rm] = whirl_cont_get_stats(c)->jac_evals;
      whirl_cont_free(c);
    }
  ok(jac[0][1] == jac[0][0] && jac[1][1] == jac[1][0] + 1,
     "a remap costs no Jacobian with no detection on (%zu, %zu without it), "
     "one with (%zu, %zu)", jac[0][1], jac[0][0], jac[1][1], jac[1][0]);
  o.detect_lp = o.detect_bp = o.detect_hb = o.detect_pd = 1;
  l.steps = 0;
  l.q0 = NAN;
  ok(!whirl_cont_alloc(&s, &o, err, sizeof err) && strstr(err, "norm weight"),
     "a NaN norm weight of the system is refused: %s", err);
}

static void test_weights(void) {
  double s = NAN;
  const double w_out[2] = {1.0, 0.0}, w_half[2] = {0.5, 0.5};
  is_rel(line_p_after(NULL, 1.0, 10, &s), 0.1 / sqrt(10002.0), 1e-10,
         "unit weights: 10 steps of 0.01 advance p by 0.1/sqrt(10002)");
  is_rel(s, 0.1, 1e-10, "unit weights: arclength 0.1");
  is_rel(line_p_after(w_out, 1.0, 10, &s), 0.1 / sqrt(2.0), 1e-10,
         "x_weight {1, 0}: the second component is out of the step (p by 0.1/sqrt 2)");
  is_rel(s, 0.1, 1e-10, "x_weight {1, 0}: arclength 0.1 in the weighted norm");
  is_rel(line_p_after(w_half, 2.0, 10, &s), 0.1 / sqrt(0.25 + 2500.0 + 4.0), 1e-10,
         "x_weight {0.5, 0.5}, p_weight 2: p by 0.1/sqrt(2504.25)");
  whirl_system sys = {.name = "line", .n = 2, .npar = 1, .F = line_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  char err[256] = "";
  const double w_zero[2] = {0, 0}, w_neg[2] = {1, -1}, w_nan[2] = {1, NAN};
  o.x_weight = w_neg;
  ok(!whirl_cont_alloc(&sys, &o, err, sizeof err) && strstr(err, "x_weight"),
     "a negative x_weight is refused: %s", err);
  o.x_weight = w_nan;
  ok(!whirl_cont_alloc(&sys, &o, err, sizeof err), "a NaN x_weight is refused");
  is_rel(line_p_after(w_zero, 1.0, 10, &s), 0.1, 1e-10,
         "x_weight all 0: the step is in p alone (natural parameter), p by 0.1");
  /* p_weight 0 (AUTO's THL = {ICP(1): 0}, demo um2): the step in x alone,
   * |dx| = sqrt(1 + 1e4) |dp|; the start's Newton at fixed p still has its
   * constraint row (before: a zero border row, "F_x is singular") */
  is_rel(line_p_after(NULL, 0.0, 10, &s), 0.1 / sqrt(10001.0), 1e-10,
         "p_weight 0: the start converges, p by 0.1/sqrt(10001) in 10 steps");
  o.x_weight = w_zero;
  o.p_weight = 0.0;
  ok(!whirl_cont_alloc(&sys, &o, err, sizeof err) && strstr(err, "p_weight"),
     "every weight 0 is refused: %s", err);
}

static void test_errors(void) {
  whirl_system s = {.name = "cusp", .n = 1, .npar = 2, .F = cusp_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  char err[256] = "";
  o.icp = 5;
  ok(whirl_cont_alloc(&s, &o, err, sizeof err) == NULL && strstr(err, "ICP"),
     "bad ICP rejected: %s", err);
  whirl_cont_options_default(&o);
  o.ds_min = 0;
  ok(whirl_cont_alloc(&s, &o, err, sizeof err) == NULL && strstr(err, "DSMIN"),
     "bad DSMIN rejected: %s", err);
  whirl_cont_options_default(&o);
  o.linsol = WHIRL_LINSOL_SPARSE;
  ok(whirl_cont_alloc(&s, &o, err, sizeof err) == NULL, "sparse without pattern rejected: %s", err);
  whirl_cont_options_default(&o);
  s.Fx = cusp_Fx; /* exact F_x = 0 at the fold (differences give O(h^2)) */
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x = NAN, p[2] = {0, 1};
  ok(whirl_cont_start(c, &x, p, 1) == WHIRL_EINVAL, "NaN start rejected: %s", whirl_cont_errmsg(c));
  ok(whirl_cont_step(c) == WHIRL_EINVAL, "step after a failed start is an error: %s", whirl_cont_errmsg(c));
  x = 1.0 / sqrt(3.0);
  p[0] = -2.0 / (3.0 * sqrt(3.0));
  /* exactly at a fold x0 is a solution where F_x is singular: the start
   * takes the null vector of [F_x F_p] (along x, the parameter stationary)
   * as AUTO does, and the branch goes on over the fold's side on the curve
   * mu = x^3 - lam x (before 2026-12-05 this start was refused) */
  int rc = whirl_cont_start(c, &x, p, 1);
  int rs = rc == WHIRL_OK ? whirl_cont_step(c) : rc;
  whirl_branch *fb = whirl_branch_alloc(1, 2, 0, 0);
  if (rs == WHIRL_OK && fb) whirl_cont_run(c, fb);
  double fdev = 0.0, xmin = x, xmax = x;
  for (size_t i = 0; fb && i < fb->len; ++i) {
    const double xi = fb->pts[i].x[0], mu = fb->pts[i].p[0];
    fdev = fmax(fdev, fabs(mu + 1.0 * xi - xi * xi * xi));
    xmin = fmin(xmin, xi), xmax = fmax(xmax, xi);
  }
  ok(rc == WHIRL_OK && rs == WHIRL_OK && fb && fb->len > 3 && fdev < 1e-9 && xmax - xmin > 0.1,
     "start exactly at a fold: along its null vector, on mu = x^3 - x (%zu points, dev %.2g) %s",
     fb ? fb->len : 0, fdev, rc ? whirl_cont_errmsg(c) : "");
  whirl_branch_free(fb);
  whirl_cont_free(c);
}

/* F = x^2 - p with an analytic F_x = 2x. */
static int sq_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * x[0] - p[0];
  return 0;
}
static int sq_Fx(const double *x, const double *p, double *J, void *d) {
  (void)p, (void)d;
  J[0] = 2.0 * x[0];
  return 0;
}

/* The start's message says which failure it is: at p = -1 (no solution)
 * Newton from x0 = 1 jumps to x = 0 where F_x = 0 — that is a Newton that
 * does not converge, not a singular start point (it was reported as "F_x is
 * singular at the start point"); from x0 = 0 at p = 1 the start point
 * itself is singular. */
static void test_start_messages(void) {
  whirl_system s = {.name = "square", .n = 1, .npar = 1, .F = sq_F, .Fx = sq_Fx};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x0 = 1.0, p0 = -1.0;
  int rc = whirl_cont_start(c, &x0, &p0, 1);
  ok(rc == WHIRL_ENOCONV && strstr(whirl_cont_errmsg(c), "did not converge") &&
         !strstr(whirl_cont_errmsg(c), "singular"),
     "Newton wandering onto F_x = 0 is a divergence (%d): %s", rc, whirl_cont_errmsg(c));
  x0 = 0.0, p0 = 1.0;
  rc = whirl_cont_start(c, &x0, &p0, 1);
  ok(rc == WHIRL_ESINGULAR && strstr(whirl_cont_errmsg(c), "singular at the start point"),
     "a singular start point is one (%d): %s", rc, whirl_cont_errmsg(c));
  whirl_cont_free(c);
}

/* start_switch's side, AUTO's rule (AUTO-07p ae.f90 STPRAE: the new
 * direction has PAR-dot >= 0): dir = +1 leaves the BP where p grows, -1
 * where it falls, on x = p of the transcritical x' = x (p - x); where the
 * new branch leaves at constant p (the pitchfork x' = x (p - x^2), x =
 * +-sqrt(p)), +1 is the side where x grows.  The second point of the
 * switched branch, against the closed forms. */
static void switch_side(const whirl_system *s, double tp, int dir, double *x, double *p) {
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.02;
  o.ds_max = 0.05;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(s, &o, err, sizeof err);
  double bx = 0.0, bp = 0.0, bt[2] = {0.0, 1.0};
  (void)tp;
  const whirl_point bpp = {.n = 1, .npar = 1, .x = &bx, .p = &bp, .t = bt};
  *x = *p = NAN;
  if (c && whirl_cont_start_switch(c, &bpp, dir) == WHIRL_OK) {
    for (int k = 0; k < 3 && whirl_cont_step(c) == WHIRL_OK; k++) {
      const whirl_point *pt = whirl_cont_point(c);
      if (pt->index >= 2) {
        *x = pt->x[0], *p = pt->p[0];
        break;
      }
    }
  }
  whirl_cont_free(c);
}

static void test_switch_side(void) {
  whirl_system t = {.name = "transcritical", .n = 1, .npar = 1, .F = tc_F};
  whirl_system f = {.name = "pitchfork", .n = 1, .npar = 1, .F = pf_F};
  double x, p;
  switch_side(&t, 0.0, +1, &x, &p);
  ok(p > 0 && fabs(x - p) < 1e-8, "switch at the transcritical BP, dir +1: p grows on x = p (x %g, p %g)", x, p);
  switch_side(&t, 0.0, -1, &x, &p);
  ok(p < 0 && fabs(x - p) < 1e-8, "dir -1: p falls on x = p (x %g, p %g)", x, p);
  switch_side(&f, 0.0, +1, &x, &p);
  ok(x > 0 && fabs(x * x - p) < 1e-8, "switch at the pitchfork, dir +1: x = +sqrt(p) (x %g, p %g)", x, p);
  switch_side(&f, 0.0, -1, &x, &p);
  ok(x < 0 && fabs(x * x - p) < 1e-8, "dir -1: x = -sqrt(p) (x %g, p %g)", x, p);
}

/* A start that solves F where F_x is singular and the family does not
 * move the parameter: F = (x1^2 + x2^2 - 1, p - 2), the unit circle at
 * p = 2 (an orbit's phase family at its fixed period, AUTO's ph1, is the
 * same).  Newton at the fixed parameter cannot correct it; the start takes
 * the null vector of [F_x F_p] = the circle's tangent (closed form). */
static int circle_at_p_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * x[0] + x[1] * x[1] - 1.0;
  f[1] = p[0] - 2.0;
  return 0;
}

/* A system of two unknowns and one parameter, and options continuing in
 * it (the starts on singular points below). */
static whirl_system two_by_one(const char *name,
                               int (*F)(const double *, const double *, double *, void *),
                               whirl_cont_options *o) {
  whirl_system s = {0};
  s.name = name;
  s.n = 2;
  s.npar = 1;
  s.F = F;
  whirl_cont_options_default(o);
  o->icp = 0;
  return s;
}

static void test_start_on_singular_solution(void) {
  whirl_cont_options o;
  const whirl_system s = two_by_one("circle at p = 2", circle_at_p_F, &o);
  o.ds = 0.05;
  o.ds_max = 0.1;
  o.nmx = 40;
  const double x0[2] = {1.0, 0.0}, p0[1] = {2.0};
  whirl_branch *b = run(&s, &o, x0, p0, +1, NULL);
  double dev = 0.0, ymax = 0.0;
  for (size_t i = 0; b && i < b->len; ++i) {
    const double *x = b->pts[i].x;
    dev = fmax(dev, fmax(fabs(hypot(x[0], x[1]) - 1.0), fabs(b->pts[i].p[0] - 2.0)));
    ymax = fmax(ymax, fabs(x[1]));
  }
  ok(b && b->len > 10 && dev < 1e-9 && ymax > 0.5,
     "start on a solution with F_x singular, the parameter fixed along the family: the "
     "unit circle at p = 2 (%zu points, max dev %.2g, |x2| up to %.2f)",
     b ? b->len : 0, dev, ymax);
  whirl_branch_free(b);
}

/* A start 1e-6 from the branch point of F = (x^2 - p^2, y): Newton at
 * fixed p halves x at each iteration (F_x = 2x), so the start is taken on
 * the point as it is (its residual 1e-12) with the null vector of
 * [F_x F_p] by a generic border, here (0, 0, 1): p alone, the bisector of
 * the two branches x = +-p.  From the predictor (1e-6, 0, s) Newton on
 * x^2 = s^2 needs log2(s / 1e-6) > newton_maxit iterations down to DSMIN:
 * before, the branch ended there; now the first step turns onto a
 * branch's tangent from the algebraic branching equation (bpstart.c). */
static int x_bp_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * x[0] - p[0] * p[0];
  f[1] = x[1];
  return 0;
}

static void test_start_at_branch_point(int dir) {
  whirl_cont_options o;
  const whirl_system s = two_by_one("x^2 = p^2", x_bp_F, &o);
  o.ds = 0.01;
  o.ds_min = 1e-3;
  o.ds_max = 0.05;
  o.nmx = 20;
  o.newton_maxit = 7;
  const double x0[2] = {1e-6, 0.0}, p0[1] = {0.0};
  int reason = -1;
  whirl_branch *b = run(&s, &o, x0, p0, dir, &reason);
  double dev = 0.0, pend = 0.0;
  for (size_t i = 1; b && i < b->len; ++i) { /* after the start, 1e-6 off */
    const double *x = b->pts[i].x, q = b->pts[i].p[0];
    dev = fmax(dev, fmax(fabs(fabs(x[0]) - fabs(q)), fabs(x[1])));
    pend = q;
  }
  ok(b && b->len == 21 && reason == WHIRL_STOP_NMX && dev < 1e-9 && pend * dir > 0.3,
     "a start at a branch point along the bisector of its branches (dir %+d): on a "
     "branch x = +-p (%zu points, stop %d, max dev %.2g, p ends at %.3f)", dir,
     b ? b->len : 0, reason, dev, pend);
  whirl_branch_free(b);
}

/* A remap that leaves the current point far from a solution of the new
 * representation (an interpolation onto a new mesh with a large error):
 * F = (x0 - p, sinh(x1 - p)), the line x0 = x1 = p; before the 5th step
 * the remap moves x1 of the current point by 2, from where Newton on
 * sinh needs 5 iterations (2 -> 1.04 -> 0.26 -> 6e-3 -> 7e-8 -> 0), more
 * than newton_maxit = 3 at any step length: the branch ended at DSMIN.
 * Now the remapped point is corrected on the new representation first
 * (with twice the iterations) and the branch goes on along the line. */
typedef struct bad_remap {
  int calls;
} bad_remap;
static int sinh_line_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] - p[0];
  f[1] = sinh(x[1] - p[0]);
  return 0;
}
static int bad_remap_fn(double *const *v, size_t nv, const double *p, void *d) {
  (void)nv, (void)p;
  bad_remap *r = d;
  if (++r->calls != 5) return 0;
  v[0][1] += 2.0;
  return 1;
}
static void test_recorrect_after_remap(void) {
  bad_remap r = {0};
  whirl_system s = {.name = "sinh line", .n = 2, .npar = 1, .F = sinh_line_F,
                    .remap = bad_remap_fn, .data = &r};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = o.ds_max = 0.05;
  o.ds_min = 1e-4;
  o.newton_maxit = 3;
  o.nmx = 10;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x0[2] = {0, 0}, p0 = 0, dev = 0.0;
  size_t last = 0;
  int rc = c ? whirl_cont_start(c, x0, &p0, +1) : -1;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    dev = fmax(dev, fmax(fabs(pt->x[0] - pt->p[0]), fabs(pt->x[1] - pt->p[0])));
    last = pt->index;
  }
  ok(c && rc == WHIRL_DONE && whirl_cont_stop_reason(c) == WHIRL_STOP_NMX && last >= 10 &&
         dev < 1e-9 && whirl_cont_get_stats(c)->recorrected == 1,
     "a remapped point 2 off the branch is corrected on its new representation before "
     "the next step (stop: %s after point %zu, %zu corrected, max dev %.2g)",
     c ? whirl_stop_reason_name(whirl_cont_stop_reason(c)) : err, last,
     c ? whirl_cont_get_stats(c)->recorrected : 0, dev);
  whirl_cont_free(c);
}

/* A zero of a test function at the start point itself is no special
 * point of the branch (AUTO labels none at its start): the transcritical
 * x (p - x) = 0 started on x = 0 at p = 1e-13 (or 1e-6, 2e-5 of the
 * first step), towards p < 0, crosses its branch point p = 0 that near
 * the start; further on (p = 0.3) the same crossing is a BP.  (Demo pcl's eigenvalue problem on its trivial
 * branch had such a zero at the start, and a BP there ended its run.) */
static int transcritical_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * (p[0] - x[0]);
  return 0;
}
static void test_zero_at_start(void) {
  whirl_system s = {.name = "transcritical", .n = 1, .npar = 1, .F = transcritical_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.05;
  o.ds_max = 0.1;
  o.nmx = 10;
  const double x0[1] = {0.0};
  size_t nbp[3];
  const double pstart[3] = {1e-13, 1e-6, 0.3};
  for (int k = 0; k < 3; ++k) {
    whirl_branch *b = run(&s, &o, x0, &pstart[k], -1, NULL);
    nbp[k] = b ? count_type(b, WHIRL_PT_BP) : 99;
    whirl_branch_free(b);
  }
  ok(nbp[0] == 0 && nbp[1] == 0 && nbp[2] == 1,
     "a test function's zero at the start point is not labelled (%zu BP from p = 1e-13; %zu "
     "from p = 1e-6, 2e-5 of the step: a restart at an earlier run's label, located to its "
     "tolerance), one further on is (%zu BP from p = 0.3)", nbp[0], nbp[1], nbp[2]);
}

/* The lead unknown of a locus (options.lead, AUTO's ICP(1)): the curve
 * (x, q, p) = (s, 1 - s^2, s) of F = (q - 1 + x^2, x - p), continued in p
 * with q the lead.  Its LPs are q's turning points, the vertex s = 0 (none
 * in p, which is monotone); a start at the vertex to newton_tol (q's rate
 * below it: demo int's fold curve, symmetric in PAR(2)) has none in its
 * first step, as AUTO's STPRAE starts there by the next coordinate. */
static int vertex_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[1] - 1.0 + x[0] * x[0];
  f[1] = x[0] - p[0];
  return 0;
}
static void test_lead(void) {
  whirl_system s = {.name = "vertex", .n = 2, .npar = 1, .F = vertex_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.01;
  o.ds_max = 0.05;
  o.nmx = 40;
  o.newton_tol = 1e-6;
  size_t nlp[3];
  const double p0[3] = {0.5, 0.5, 1e-7};
  const long lead[3] = {1, -1, 1};
  /* towards the vertex: q grows (q leads), p falls (p leads, or the start
   * is the vertex and p orients it) */
  const int dir[3] = {+1, -1, -1};
  for (int k = 0; k < 3; ++k) {
    o.lead = lead[k];
    const double x0[2] = {p0[k], 1.0 - p0[k] * p0[k]};
    whirl_branch *b = run(&s, &o, x0, &p0[k], dir[k], NULL);
    nlp[k] = b ? count_type(b, WHIRL_PT_LP) : 99;
    whirl_branch_free(b);
  }
  ok(nlp[0] == 1 && nlp[1] == 0 && nlp[2] == 0,
     "the lead unknown's turning point is the LP (%zu through the vertex, %zu when p "
     "leads), none when the start is the vertex to newton_tol (%zu)", nlp[0], nlp[1], nlp[2]);
}

/* AUTO's start of an orbit or a BVP from data (options.start_as_given):
 * the given point is point 0 as it is, off the branch, and the first step
 * leaves it along the null vector of [F_x F_p] there.  On the circle
 * x^2 + p^2 = 1 from (0.9, 0.3) (the circle's x there is 0.953939) the
 * raw tangent is (-p, x)/|(p, x)| = (-0.3, 0.9)/0.948683 with p growing,
 * and point 1 is on the circle at arclength ds along it; without the
 * option point 0 is Newton's at p = 0.3. */
static int circle_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * x[0] + p[0] * p[0] - 1.0;
  return 0;
}
static void test_start_as_given(void) {
  whirl_system s = {.name = "circle", .n = 1, .npar = 1, .F = circle_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.05;
  o.ds_max = 0.05;
  o.nmx = 2;
  o.newton_tol = 1e-12;
  const double x0[1] = {0.9}, p0[1] = {0.3};
  o.start_as_given = 1;
  whirl_branch *b = run(&s, &o, x0, p0, +1, NULL);
  if (!b || b->len < 2) {
    ok(0, "start_as_given: a branch of two points at least");
  } else {
    const double nt = hypot(0.3, 0.9), tx = -0.3 / nt, tp = 0.9 / nt;
    const double x1 = b->pts[1].x[0], p1 = b->pts[1].p[0];
    const double along = (x1 - 0.9) * tx + (p1 - 0.3) * tp;
    ok(b->pts[0].x[0] == 0.9 && b->pts[0].p[0] == 0.3 &&
           fabs(x1 * x1 + p1 * p1 - 1.0) < 1e-10 && fabs(along - 0.05) < 1e-10,
       "start_as_given: point 0 is the given (%.17g, %.17g); point 1 (%.9g, %.9g) on the "
       "circle, %.12g along the raw tangent (ds 0.05)", b->pts[0].x[0], b->pts[0].p[0], x1,
       p1, along);
  }
  whirl_branch_free(b);
  o.start_as_given = 0;
  b = run(&s, &o, x0, p0, +1, NULL);
  ok(b && b->len >= 1 && fabs(b->pts[0].x[0] - sqrt(1.0 - 0.09)) < 1e-10,
     "without it, point 0 is corrected onto the circle (%.9g)", b ? b->pts[0].x[0] : NAN);
  whirl_branch_free(b);
}

/* AUTO's step sequence (options.auto_steps, run files): a located special
 * point starts the next step, at the step length that passed it, and the
 * length follows AUTO's ADPTDS.  On the line x = p, where Newton converges
 * at its first iteration, each step doubles (ADPTDS after 1 iteration; the
 * library's own rule grows by 1.5); the UZ at p = 0.3 is followed by a
 * point twice the passing step beyond it (not the point past it), and
 * every step yields one point.  On the circle x^2 + p^2 = 1 the fold at
 * p = 1 starts the next step and is not found again from there. */
static int line1_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] - p[0];
  return 0;
}
static double pt_dist(const whirl_branch *b, size_t i, size_t j) {
  return hypot(b->pts[i].x[0] - b->pts[j].x[0], b->pts[i].p[0] - b->pts[j].p[0]);
}
static void test_auto_steps(void) {
  whirl_system s = {.name = "line", .n = 1, .npar = 1, .F = line1_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.01;
  o.ds_max = 10.0;
  o.nmx = 9;
  const double uz[1] = {0.3};
  o.uz = uz;
  o.nuz = 1;
  const double x0[1] = {0.0}, p0[1] = {0.0};
  for (int mode = 0; mode < 2; ++mode) {
    o.auto_steps = mode;
    whirl_branch *b = run(&s, &o, x0, p0, +1, NULL);
    size_t u = 0;
    while (b && u < b->len && b->pts[u].type != WHIRL_PT_UZ) ++u;
    if (!b || u < 3 || u + 1 >= b->len) {
      ok(0, "auto_steps = %d: a UZ inside the branch", mode);
      whirl_branch_free(b);
      continue;
    }
    const double h1 = pt_dist(b, u - 2, u - 1), h0 = pt_dist(b, u - 3, u - 2);
    const double pass = (mode ? 2.0 : 1.5) * h1; /* the step that passed 0.3 */
    if (mode)
      ok(fabs(h1 / h0 - 2.0) < 1e-9 && fabs(b->pts[u].p[0] - 0.3) < 1e-12 &&
             fabs(pt_dist(b, u, u + 1) - 2.0 * pass) < 1e-9 * pass && b->len == o.nmx + 1,
         "auto_steps: steps double after one Newton iteration (%.6g), the UZ at 0.3 starts "
         "the next step, twice the passing one (%.6g, %.6g), one point a step (%zu points, NMX %zu steps)",
         h1 / h0, pt_dist(b, u, u + 1), 2.0 * pass, b->len, o.nmx);
    else
      ok(fabs(h1 / h0 - 1.5) < 1e-9 && fabs(pt_dist(b, u - 1, u + 1) - pass) < 1e-9 * pass,
         "the library's steps: x1.5 (%.6g), the point after the UZ is the one past it", h1 / h0);
    whirl_branch_free(b);
  }
  whirl_system cs = {.name = "circle", .n = 1, .npar = 1, .F = circ_F};
  whirl_cont_options_default(&o);
  o.auto_steps = 1;
  o.ds = 0.05;
  o.ds_max = 0.1;
  o.nmx = 30; /* past p = 1, not round to p = -1 */
  const double xc[1] = {-0.8}, pc[1] = {0.6};
  whirl_branch *b = run(&cs, &o, xc, pc, +1, NULL);
  const whirl_branch_point *lp = b ? nth_type(b, WHIRL_PT_LP, 0) : NULL;
  ok(b && count_type(b, WHIRL_PT_LP) == 1 && lp && fabs(lp->p[0] - 1.0) < 1e-10 &&
         lp + 1 < b->pts + b->len && lp[1].p[0] < 1.0 && lp[1].x[0] > 0.0,
     "auto_steps: the fold at p = 1 once (%zu LP), the branch on from it", b ? count_type(b, WHIRL_PT_LP) : 0);
  whirl_branch_free(b);
}

/* The side of a pitchfork's new branch (whirl_cont_start_switch, dir = +1):
 * AUTO's STPRAE rule, the first state component that moves grows.  F =
 * (p x1 - x1^3, 4 x1 + 3 x2): the trivial branch x = 0, the new one x1 =
 * +-sqrt(p), x2 = -4/3 x1 (direction (3, -4)/5 at the BP, p = 0): +1 is the
 * side x1 > 0, where before x2, the largest component, grew (x1 < 0). */
static int pf2_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = p[0] * x[0] - x[0] * x[0] * x[0];
  f[1] = 4.0 * x[0] + 3.0 * x[1];
  return 0;
}
static void test_switch_orientation(void) {
  whirl_system s = {.name = "pitchfork2", .n = 2, .npar = 1, .F = pf2_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.ds = 0.03;
  o.ds_max = 0.1;
  o.p_min = -1.0;
  o.p_max = 1.0;
  const double x0[2] = {0.0, 0.0}, p0[1] = {-0.5};
  whirl_branch *b = run(&s, &o, x0, p0, +1, NULL);
  const whirl_branch_point *bp = b ? nth_type(b, WHIRL_PT_BP, 0) : NULL;
  double x1 = NAN, x2 = NAN;
  if (bp) {
    char err[256];
    whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
    double bt[3] = {0, 0, 1}; /* the trivial branch's tangent: p alone */
    whirl_point q = {.n = 2, .npar = 1, .x = bp->x, .p = bp->p, .t = bt};
    whirl_branch *sw = whirl_branch_alloc(2, 1, 0, 0);
    if (c && whirl_cont_start_switch(c, &q, +1) == WHIRL_OK && whirl_cont_run(c, sw) >= 0 &&
        sw->len > 3)
      x1 = sw->pts[3].x[0], x2 = sw->pts[3].x[1];
    whirl_branch_free(sw);
    whirl_cont_free(c);
  }
  ok(x1 > 0.0 && fabs(x2 + 4.0 / 3.0 * x1) < 1e-9,
     "pitchfork along (3, -4)/5: dir = +1 is AUTO's side, x1 grows (x1 %.4g, x2 %.4g)", x1, x2);
  whirl_branch_free(b);
}

/* The switch direction is the vector of the null plane of [F_x F_p] at
 * the branch point orthogonal to the given tangent (AUTO's STSDRBV), also
 * where that tangent is not quite in the plane (a restart whose phase
 * condition refers to another point): pf2's BP at 0 with the tangent
 * (0, 0.01, 1), off the plane spanned by (3, -4, 0)/5 and (0, 0, 1).  The
 * plane's vector orthogonal to it, (3, -4, 0.04)/5.00016, has
 * 4 ph0 + 3 ph1 = 0; the old projection of (3, -4, 0)/5 off the tangent,
 * 2.4e-4, is outside the plane (brc's pitchfork of cycles: a parameter
 * rate of 1e-4 where the new branch has none, and the mirror branch). */
static void test_switch_in_null_plane(void) {
  whirl_system s = {.name = "pitchfork2", .n = 2, .npar = 1, .F = pf2_F};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  char err[256];
  whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
  double x[2] = {0.0, 0.0}, p[1] = {0.0}, bt[3] = {0.0, 0.01, 1.0}, ph[3] = {NAN, NAN, NAN};
  whirl_point q = {.n = 2, .npar = 1, .x = x, .p = p, .t = bt};
  const int rc = c ? whirl_cont_switch_direction(c, &q, +1, ph) : -1;
  const double in_plane = fabs(4.0 * ph[0] + 3.0 * ph[1]);
  const double along_t = fabs(ph[1] * bt[1] + ph[2] * bt[2]);
  ok(rc == WHIRL_OK && in_plane < 1e-12 && along_t < 1e-12 && fabs(ph[0] - 0.6) < 1e-4,
     "switch direction in the null plane (|A ph| %.2g) and orthogonal to the tangent "
     "(%.2g): (%.6f, %.6f, %.6f)", in_plane, along_t, ph[0], ph[1], ph[2]);
  whirl_cont_free(c);
}

/* whirl_branch_distance against the plain definition (every segment's
 * nearest point, written out here): polylines that turn back and forth in
 * the parameter, single points, several weights; the distance and the
 * nearest segment exactly as from the definition (the pruning by the
 * parameter's gap must not change either). */
/* the distance from q to segment k of the polyline xy (a point if len 1) */
static double ref_segment(size_t len, double (*xy)[3], const double *q, double w,
                          size_t k) {
  const double *A = xy[k], *B = xy[len == 1 ? k : k + 1];
  /* coordinates: x0, x1, w p */
  double a[3] = {A[0], A[1], w * A[2]}, b[3] = {B[0], B[1], w * B[2]};
  double z[3] = {q[0], q[1], w * q[2]}, ab = 0, az = 0, d = 0;
  for (int i = 0; i < 3; ++i) {
    ab += (b[i] - a[i]) * (b[i] - a[i]);
    az += (z[i] - a[i]) * (b[i] - a[i]);
  }
  double u = ab > 0 ? fmin(1.0, fmax(0.0, az / ab)) : 0.0;
  for (int i = 0; i < 3; ++i) d += pow(z[i] - (a[i] + u * (b[i] - a[i])), 2);
  return sqrt(d);
}

static double ref_distance(size_t len, double (*xy)[3], const double *q, double w) {
  double best = INFINITY;
  for (size_t k = 0; k < (len == 1 ? 1 : len - 1); ++k)
    best = fmin(best, ref_segment(len, xy, q, w, k));
  return best;
}

static void test_branch_distance(void) {
  unsigned seed = 12345u;
  int bad = 0, bad_within = 0, cases = 0;
  for (int trial = 0; trial < 200; ++trial) {
    size_t len = 1 + (size_t)(trial % 37);
    double w = trial % 3 == 0 ? 1.0 : trial % 3 == 1 ? 0.1 : 7.0;
    whirl_branch *b = whirl_branch_alloc(2, 1, 0, 0);
    double xy[40][3];
    double pv = 0;
    for (size_t k = 0; k < len; ++k) {
      seed = seed * 1103515245u + 12345u;
      double r1 = (double)(seed >> 8) / 16777216.0;
      seed = seed * 1103515245u + 12345u;
      double r2 = (double)(seed >> 8) / 16777216.0;
      pv += (r1 - 0.35) * 0.5; /* turns back now and then */
      xy[k][0] = sin(3 * pv) + 0.1 * r2;
      xy[k][1] = cos(2 * pv) * r1;
      xy[k][2] = pv;
      whirl_point pt = {0};
      pt.n = 2;
      pt.npar = 1;
      pt.x = xy[k];
      pt.p = &xy[k][2];
      pt.stable = -1;
      pt.n_unstable = -1;
      whirl_branch_append(b, &pt);
    }
    for (int t = 0; t < 20; ++t) {
      double q[3] = {sin((double)t), cos(1.3 * t), -2.0 + 0.25 * t};
      size_t sgot = 99;
      double dref = ref_distance(len, xy, q, w);
      double dgot = whirl_branch_distance(b, q, &q[2], w, &sgot);
      ++cases;
      /* the segment named is a nearest one (at a shared vertex two are) */
      double dseg = sgot < len ? ref_segment(len, xy, q, w, sgot) : INFINITY;
      if (fabs(dgot - dref) > 1e-12 * (1 + dref) ||
          fabs(dseg - dref) > 1e-12 * (1 + dref))
        ++bad;
      /* within(tol) is distance < tol (no tol equal to it to rounding) */
      const double tols[3] = {0.05, 0.3, 1.0};
      for (int j = 0; j < 3; ++j)
        if (fabs(dref - tols[j]) > 1e-9 &&
            whirl_branch_within(b, q, &q[2], w, tols[j]) != (dref < tols[j]))
          ++bad_within;
    }
    whirl_branch_free(b);
  }
  ok(bad == 0, "branch distance: %d of %d points differ from the definition "
               "(distance or nearest segment)", bad, cases);
  ok(bad_within == 0, "branch within: %d of %d answers differ from the "
                      "definition's distance < tol", bad_within, 3 * cases);
}

/* The localisation's trials: on the branch x = p (F = x - p, linear, so
 * a trial's correction is one Newton iteration; the arclength p alone,
 * x_weight 0: points at p = 0, 0.2, 0.4), a system test tau = exp(40 (p -
 * p0)) - 1 whose zero p0 = 0.2371 lies in the second step, far from its
 * secant's first trial (p = 0.20023, the test being convex).  With
 * loc_zone, F fails (a recoverable domain error) on 0.2001 < p < 0.2010,
 * around that first trial: a correction that does not converge is tried
 * next at the bracket's midpoint, not twice more 2e-8 from where it
 * failed (those offsets are for a start exactly on a singular point; the
 * fold loci of demo abcb spent 3 x 7 Newton iterations so per trial
 * beside a branch point of cycles; 3 failed corrections here before).
 * Without the zone: the zero in 15 trials. */
static const double loc_p0 = 0.2371;
static int loc_zone, loc_fails;
static int diagonal_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  if (loc_zone && p[0] > 0.2001 && p[0] < 0.2010) return ++loc_fails, 1;
  f[0] = x[0] - p[0];
  return 0;
}
static int loc_test(const double *x, const double *p, double *tau, int *types, void *d) {
  (void)x, (void)d;
  tau[0] = expm1(40.0 * (p[0] - loc_p0));
  types[0] = WHIRL_PT_CP;
  return 0;
}
static void test_localisation_trials(int zone) {
  whirl_system s = {.name = "diagonal", .n = 1, .npar = 1, .F = diagonal_F, .ntest = 1,
                    .test = loc_test};
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  const double xw[1] = {0.0};
  o.x_weight = xw;
  o.ds = 0.2;
  o.ds_max = 0.2;
  o.nmx = 3;
  loc_zone = zone;
  size_t its[2] = {0, 0};
  double pcp = NAN;
  char err[256];
  for (int with = 0; with < 2; ++with) {
    o.detect_sys = with;
    loc_fails = 0;
    whirl_cont *c = whirl_cont_alloc(&s, &o, err, sizeof err);
    whirl_branch *b = whirl_branch_alloc(1, 1, 0, 0);
    const double x0[1] = {0.0}, p0[1] = {0.0};
    int rc = c && b ? whirl_cont_start(c, x0, p0, +1) : -1;
    if (rc == WHIRL_OK) rc = whirl_cont_run(c, b);
    if (rc < 0) printf("# %s\n", c ? whirl_cont_errmsg(c) : err);
    if (c) its[with] = whirl_cont_get_stats(c)->newton_its;
    const whirl_branch_point *q = b ? nth_type(b, WHIRL_PT_CP, 0) : NULL;
    if (with && q) pcp = q->p[0];
    whirl_cont_free(c);
    whirl_branch_free(b);
  }
  const size_t trials = its[1] - its[0];
  printf("# %s: %zu trials, %d failed corrections\n", zone ? "zone" : "smooth", trials,
         loc_fails);
  if (zone)
    ok(fabs(pcp - loc_p0) <= 1e-11 && loc_fails == 1,
       "a trial whose correction fails: the next at the bracket's midpoint (%d failed, 1 "
       "expected), the zero at %.14g (p0 %.4g)", loc_fails, pcp, loc_p0);
  else
    ok(fabs(pcp - loc_p0) <= 1e-11 && trials <= 15,
       "a convex test function: located at %.14g (p0 %.4g) in %zu trials (<= 15)", pcp,
       loc_p0, trials);
}

int main(void) {
  test_start_messages();
  test_cusp(1);
  test_cusp(0);
  test_natural_corrector(1.0);
  test_natural_corrector(0.2);
  test_bp();
  test_bp_curved(3.0, 0.1);
  test_bp_curved(5.0, 0.2);
  test_switch_side();
  test_hopf();
  test_maps();
  test_hopf_nearest_switch();
  test_loop();
  test_sphere(WHIRL_DIR_SECANT);
  test_sphere(WHIRL_DIR_PREDICTOR);
  test_loop_weighted();
  test_kink_no_fold();
  test_pole_no_bp();
  test_uz();
  test_uz_exact();
  test_uz_fun();
  test_bratu();
  test_tangent_from_newton();
  test_bp_at_fold();
  test_two_at_once();
  test_weights();
  test_system_weights();
  test_recorrect_after_remap();
  test_zero_at_start();
  test_lead();
  test_auto_steps();
  test_start_as_given();
  test_switch_orientation();
  test_switch_in_null_plane();
  test_newton_full();
  test_switch_large();
  test_errors();
  test_start_on_singular_solution();
  test_start_at_branch_point(+1);
  test_start_at_branch_point(-1);
  test_branch_distance();
  test_localisation_trials(0);
  test_localisation_trials(1);
  return done_testing();
}

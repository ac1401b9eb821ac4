/* test/unit/t_deflate.c — deflated Newton (lib/analysis/deflate.c) on
 * problems whose solutions are closed forms:
 *  (a) the circle x² + y² = 4 cut by the hyperbola xy = 1: four roots
 *      x² = 2 ± √3, y = 1/x, all found from ONE start, then no fifth;
 *  (b) one deflated step equals Newton's step for G = M F with G's
 *      Jacobian by central differences (Sherman–Morrison, independent);
 *  (c) a quartic with roots −1, 1, 2, 3: all four from x = 0;
 *  (d) 401 unknowns through the sparse path (UMFPACK): x0² = 1 and
 *      x_i = c_i, both roots, equal to the dense solve;
 *  (e) without deflation the same start returns the same root (so (a)
 *      and (c) can fail), a domain error is reported as such, bad options
 *      are refused;
 *  (f) the crossings of a traced branch: the unit circle x² + p² = 1
 *      sampled at 40 points is crossed twice at p = 0.5, at ±√0.75;
 *  (g) the random generator is splitmix64: seed 0 gives 0xe220a8397b1dcdaf
 *      first (the reference output of Vigna's splitmix64.c).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/whirl.h>

#include "../tap.h"

static int circle_F(const double *x, const double *p, double *f, void *data) {
  (void)p;
  (void)data;
  f[0] = x[0] * x[0] + x[1] * x[1] - 4.0;
  f[1] = x[0] * x[1] - 1.0;
  return 0;
}
static int circle_Fx(const double *x, const double *p, double *J, void *data) {
  (void)p;
  (void)data;
  J[0] = 2 * x[0]; J[1] = x[1];
  J[2] = 2 * x[1]; J[3] = x[0];
  return 0;
}

static void test_circle(void) {
  whirl_system s = {.name = "circle", .n = 2, .npar = 1, .F = circle_F, .Fx = circle_Fx};
  char err[256];
  whirl_deflate *d = whirl_deflate_alloc(&s, NULL, err, sizeof err);
  ok(d != NULL, "alloc: %s", d ? "ok" : err);
  const double p = 0.0;
  double want[4][2];
  const double a = sqrt(2 + sqrt(3.0)), b = sqrt(2 - sqrt(3.0));
  const double xs[4] = {a, -a, b, -b};
  for (int k = 0; k < 4; k++) {
    want[k][0] = xs[k];
    want[k][1] = 1.0 / xs[k];
  }
  int found[4] = {0}, nfound = 0;
  for (int k = 0; k < 4; k++) {
    double x[2] = {1.0, 0.3};
    int its = 0, rc = whirl_deflate_solve(d, x, &p, &its);
    if (rc != WHIRL_OK) continue;
    for (int j = 0; j < 4; j++)
      if (fabs(x[0] - want[j][0]) < 1e-12 && fabs(x[1] - want[j][1]) < 1e-12 && !found[j]) {
        found[j] = 1;
        nfound++;
      }
    whirl_deflate_add(d, x);
  }
  ok(nfound == 4, "circle and hyperbola: all 4 closed-form roots from one start (%d)", nfound);
  double x[2] = {1.0, 0.3};
  ok(whirl_deflate_solve(d, x, &p, NULL) == WHIRL_ENOCONV, "no fifth root");
  /* (e) without deflation: the first root again */
  double y[2] = {1.0, 0.3}, z[2] = {1.0, 0.3};
  whirl_deflate_polish(d, y, &p, NULL);
  whirl_deflate_clear(d);
  ok(whirl_deflate_solve(d, z, &p, NULL) == WHIRL_OK &&
         fabs(y[0] - z[0]) + fabs(y[1] - z[1]) < 1e-13,
     "undeflated: the same start finds the same root twice");
  whirl_deflate_free(d);
}

/* (b) G = M F, M = (|x - r|^-2 + 1), one step against finite differences */
static void G_of(const double *x, const double *r, double *g) {
  double f[2];
  circle_F(x, NULL, f, NULL);
  const double dd = (x[0] - r[0]) * (x[0] - r[0]) + (x[1] - r[1]) * (x[1] - r[1]);
  const double m = 1.0 / dd + 1.0;
  g[0] = m * f[0];
  g[1] = m * f[1];
}

static void test_step_formula(void) {
  whirl_system s = {.name = "circle", .n = 2, .npar = 1, .F = circle_F, .Fx = circle_Fx};
  whirl_deflate_options o;
  whirl_deflate_options_default(&o);
  o.maxit = 1;
  whirl_deflate *d = whirl_deflate_alloc(&s, &o, NULL, 0);
  const double r[2] = {1.9, 0.55}, p = 0.0, x0[2] = {1.2, 0.9};
  whirl_deflate_add(d, r);
  double x[2] = {x0[0], x0[1]};
  whirl_deflate_solve(d, x, &p, NULL);
  /* Newton for G with a central-difference Jacobian */
  double g[2], gp[2], gm[2], J[4], h = 1e-6;
  G_of(x0, r, g);
  for (int j = 0; j < 2; j++) {
    double xp[2] = {x0[0], x0[1]}, xm[2] = {x0[0], x0[1]};
    xp[j] += h;
    xm[j] -= h;
    G_of(xp, r, gp);
    G_of(xm, r, gm);
    J[2 * j] = (gp[0] - gm[0]) / (2 * h);
    J[2 * j + 1] = (gp[1] - gm[1]) / (2 * h);
  }
  const double det = J[0] * J[3] - J[2] * J[1];
  const double dx0 = -(J[3] * g[0] - J[2] * g[1]) / det;
  const double dx1 = -(-J[1] * g[0] + J[0] * g[1]) / det;
  is_abs(x[0], x0[0] + dx0, 1e-8, "deflated step = Newton step of G (x)");
  is_abs(x[1], x0[1] + dx1, 1e-8, "deflated step = Newton step of G (y)");
  whirl_deflate_free(d);
}

static int quartic_F(const double *x, const double *p, double *f, void *data) {
  (void)p;
  (void)data;
  f[0] = (x[0] + 1) * (x[0] - 1) * (x[0] - 2) * (x[0] - 3);
  return 0;
}

static void test_quartic(void) {
  whirl_system s = {.name = "quartic", .n = 1, .npar = 1, .F = quartic_F};
  whirl_deflate *d = whirl_deflate_alloc(&s, NULL, NULL, 0);
  const double p = 0.0;
  double sum = 0.0, prod = 1.0;
  int n = 0;
  for (int k = 0; k < 6; k++) {
    double x = 0.0;
    if (whirl_deflate_solve(d, &x, &p, NULL) != WHIRL_OK) continue;
    whirl_deflate_add(d, &x);
    sum += x;
    prod *= x;
    n++;
  }
  ok(n == 4, "quartic: 4 roots from x = 0 (finite-difference Jacobian), got %d", n);
  is_abs(sum, 5.0, 1e-10, "their sum is 5 (Vieta)");
  is_abs(prod, -6.0, 1e-10, "their product is -6 (Vieta)");
  whirl_deflate_free(d);
}

/* (d) 401 unknowns: x0^2 = 1, x_i = 0.01 i */
#define NBIG 401
static int big_F(const double *x, const double *p, double *f, void *data) {
  (void)p;
  (void)data;
  f[0] = x[0] * x[0] - 1.0;
  for (int i = 1; i < NBIG; i++) f[i] = x[i] - 0.01 * i + 0.1 * (x[0] - 1) * (x[0] + 1);
  return 0;
}
static int big_Jp[NBIG + 1], big_Ji[2 * NBIG - 1];
static int big_Fxs(const double *x, const double *p, double *Jx, void *data) {
  (void)p;
  (void)data;
  Jx[0] = 2 * x[0];
  for (int i = 1; i < NBIG; i++) Jx[i] = 0.2 * x[0];
  for (int i = 1; i < NBIG; i++) Jx[NBIG - 1 + i] = 1.0;
  return 0;
}

static void test_sparse(void) {
  big_Jp[0] = 0;
  big_Jp[1] = NBIG; /* column 0: every row */
  for (int i = 0; i < NBIG; i++) big_Ji[i] = i;
  for (int j = 1; j < NBIG; j++) {
    big_Ji[NBIG - 1 + j] = j;
    big_Jp[j + 1] = NBIG + j;
  }
  whirl_system s = {.name = "big", .n = NBIG, .npar = 1, .F = big_F,
                    .nnz = 2 * NBIG - 1, .Jp = big_Jp, .Ji = big_Ji, .Fx_sparse = big_Fxs};
  whirl_deflate *d = whirl_deflate_alloc(&s, NULL, NULL, 0);
  static double x[NBIG];
  const double p = 0.0;
  double got[2] = {0, 0};
  int n = 0;
  for (int k = 0; k < 3; k++) {
    for (int i = 0; i < NBIG; i++) x[i] = 0.5;
    if (whirl_deflate_solve(d, x, &p, NULL) != WHIRL_OK) continue;
    whirl_deflate_add(d, x);
    if (n < 2) got[n] = x[0];
    n++;
  }
  ok(n == 2 && fabs(fabs(got[0]) - 1) < 1e-12 && fabs(got[0] + got[1]) < 1e-12,
     "sparse (UMFPACK) path: both roots x0 = +-1 and no third (%d)", n);
  ok(fabs(x[NBIG - 1] - 0.01 * (NBIG - 1)) < 1e-12 || n != 2, "the other unknowns");
  ok(whirl_deflate_get_stats(d)->factorizations > 0, "factorisations counted");
  whirl_deflate_free(d);
}

static int domain_F(const double *x, const double *p, double *f, void *data) {
  (void)p;
  (void)data;
  if (x[0] <= 0) return 1; /* outside the domain */
  f[0] = log(x[0]) + 5.0;  /* root exp(-5) */
  return 0;
}

static void test_bad(void) {
  whirl_system s = {.name = "dom", .n = 1, .npar = 1, .F = domain_F};
  whirl_deflate *d = whirl_deflate_alloc(&s, NULL, NULL, 0);
  double x = 1.0, p = 0.0;
  int rc = whirl_deflate_solve(d, &x, &p, NULL);
  ok(rc == WHIRL_OK && fabs(x - exp(-5.0)) < 1e-14,
     "steps halved where F leaves its domain: root exp(-5)");
  whirl_deflate_add(d, &x);
  x = 1.0;
  rc = whirl_deflate_solve(d, &x, &p, NULL);
  ok(rc == WHIRL_ENOCONV || rc == WHIRL_EDOMAIN, "the only root deflated: none found (%d)", rc);
  whirl_deflate_free(d);
  whirl_deflate_options o;
  whirl_deflate_options_default(&o);
  o.tol = 0;
  char err[256] = "";
  ok(whirl_deflate_alloc(&s, &o, err, sizeof err) == NULL && strstr(err, "tol"),
     "tol = 0 refused: %s", err);
  const double w = -1;
  whirl_deflate_options_default(&o);
  o.weight = &w;
  ok(whirl_deflate_alloc(&s, &o, err, sizeof err) == NULL && strstr(err, "weight"),
     "a negative weight refused: %s", err);
}

static int circ_F(const double *x, const double *p, double *f, void *data) {
  (void)data;
  f[0] = x[0] * x[0] + p[0] * p[0] - 1.0;
  return 0;
}

static void test_crossings(void) {
  whirl_system s = {.name = "unit circle", .n = 1, .npar = 1, .F = circ_F};
  whirl_deflate *d = whirl_deflate_alloc(&s, NULL, NULL, 0);
  double q[40], x[40];
  for (int k = 0; k < 40; k++) { /* once round, from the top */
    const double t = 2 * WHIRL_PI * k / 39.0;
    q[k] = sin(t);
    x[k] = cos(t);
  }
  const double p = 0.5;
  ok(whirl_deflate_add_crossings(d, q, x, 40, 0.5, &p) == WHIRL_OK, "crossings added");
  const double *r0 = whirl_deflate_root(d, 0), *r1 = whirl_deflate_root(d, 1);
  ok(whirl_deflate_count(d) == 2 && r0 && r1 &&
         fabs(fabs(r0[0]) - sqrt(0.75)) < 1e-14 && fabs(r0[0] + r1[0]) < 1e-14,
     "the circle crosses p = 0.5 twice, at +-sqrt(0.75), polished (%zu)",
     whirl_deflate_count(d));
  whirl_deflate_add_crossings(d, q, x, 40, 0.5, &p);
  ok(whirl_deflate_count(d) == 2, "added again: no duplicates");
  whirl_deflate_free(d);
  uint64_t st = 0;
  const double u = whirl_random_uniform(&st);
  ok(u == (double)(0xe220a8397b1dcdafull >> 11) * 0x1.0p-53,
     "splitmix64's reference first output from seed 0");
}

int main(void) {
  test_crossings();
  test_circle();
  test_step_formula();
  test_quartic();
  test_sparse();
  test_bad();
  return done_testing();
}

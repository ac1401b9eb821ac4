/* test/bench/bench_fe_hbm.c — cost of the harmonic balance of a
 * finite-element rotor (rotor/fe_hbm*.c) against its size: a synthetic
 * chain rotor (test/fe_chain.h) of N DOF (100, 300, 1000, 3000) on two
 * short SFDs (first and last node, with centring springs), H = 5.
 *   cond   the condensation at a new speed: one complex sparse LU of the
 *          held rotor per harmonic and 2m solves (ms)
 *   step   one Newton step at that speed: F, the dense analytic Jacobian,
 *          LU and solve (ms)
 *   solve  the Newton solve from X = 0 (ms, iterations)
 *   hill   the stability of that orbit by the sparse Hill method (ARPACK,
 *          24 eigenvalues nearest 0; ms, exponents kept in the strip)
 * and the same solve on the uncondensed dense HBM (all DOF × harmonics as
 * unknowns) at about 330 DOF, with the speed-up.  One TSV row per case.
 * Not a test: run `make bench`.  Usage: bench_fe_hbm [max_dof]
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/cont.h>
#include <whirl/rotor/fe_hbm.h>

#include "../fe_chain.h"

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static whirl_fe_rotor *chain(int ndof) {
  fe_chain_opts co;
  int nn = ndof / 4;
  fe_chain_defaults(&co, nn);
  co.length = 1.0;
  co.ks = 2e6;
  co.gravity = 9.81;
  co.nnl = 2;
  co.nl[0] = fe_chain_sfd(0, -1);
  co.nl[1] = fe_chain_sfd(nn - 1, -1);
  return fe_chain_build(&co);
}

typedef struct result {
  size_t n;
  double t_cond, t_step, t_solve, t_hill;
  int its, rc;
  size_t nexp;
} result;

/* One Newton step by hand: F, Fx, LU, solve. */
static int newton_step(const whirl_system *s, double *X, const double *p) {
  double *J = malloc(s->n * s->n * sizeof *J), *b = malloc(s->n * sizeof *b);
  whirl_linsol *ls = whirl_linsol_alloc_dense(s->n);
  int rc = (J && b && ls) ? 0 : WHIRL_ENOMEM;
  if (!rc) rc = s->F(X, p, b, s->data);
  if (!rc) rc = s->Fx(X, p, J, s->data);
  if (!rc) rc = whirl_linsol_factor(ls, J);
  if (!rc) rc = whirl_linsol_solve(ls, b, 1, 0);
  for (size_t i = 0; !rc && i < s->n; ++i) X[i] -= b[i];
  whirl_linsol_free(ls);
  free(J);
  free(b);
  return rc;
}

static result run(const whirl_fe_rotor *r, int uncondensed, double Om) {
  result res = {0, 0, 0, 0, 0, 0, 0, 0};
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = 5;
  o.uncondensed = uncondensed;
  o.stability = 0;
  char err[256] = "";
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &o, err, sizeof err);
  if (!h) { fprintf(stderr, "bench_fe_hbm: %s\n", err); res.rc = -1; return res; }
  const whirl_system *s = whirl_fe_hbm_system(h);
  res.n = s->n;
  double *X = calloc(s->n, sizeof *X), *F = malloc(s->n * sizeof *F), p[4];
  whirl_fe_hbm_params(Om, p);
  double t0 = now();
  res.rc = s->F(X, p, F, s->data); /* the condensation at a new speed */
  double t1 = now();
  res.rc |= s->F(X, p, F, s->data);
  double t2 = now();
  res.t_cond = 1e3 * ((t1 - t0) - (t2 - t1));
  res.rc |= newton_step(s, X, p);
  double t3 = now();
  res.t_step = 1e3 * (t3 - t2);
  memset(X, 0, s->n * sizeof *X);
  p[0] = Om * (1 + 1e-9); /* a new speed: the solve includes a condensation */
  double t4 = now();
  res.rc |= whirl_newton(s, X, p, 1e-10, 30, &res.its);
  res.t_solve = 1e3 * (now() - t4);
  if (!uncondensed && !res.rc) { /* stability: the sparse Hill method */
    double re[64], im[64];
    size_t m = 64;
    whirl_fe_hbm_options_default(&o);
    o.harmonics = 5;
    o.stability = 2;
    whirl_fe_hbm *hs = whirl_fe_hbm_alloc(r, &o, NULL, 0);
    double t5 = now();
    int rc = hs ? whirl_fe_hbm_hill(hs, X, p, re, im, &m) : -1;
    res.t_hill = rc ? -1 : 1e3 * (now() - t5);
    res.nexp = rc ? 0 : m;
    whirl_fe_hbm_free(hs);
  }
  free(X);
  free(F);
  whirl_fe_hbm_free(h);
  return res;
}

int main(int argc, char **argv) {
  int maxdof = argc > 1 ? atoi(argv[1]) : 3000;
  const int sizes[] = {100, 300, 1000, 3000};
  double Om = 300.0;
  printf("# bench_fe_hbm: chain rotor, two short SFDs, H = 5, Omega = %g rad/s\n", Om);
  printf("case\tndof\tunknowns\tcond_ms\tstep_ms\tsolve_ms\tits\thill_ms\texponents\n");
  for (size_t i = 0; i < sizeof sizes / sizeof *sizes; ++i) {
    if (sizes[i] > maxdof) break;
    whirl_fe_rotor *r = chain(sizes[i]);
    result c = run(r, 0, Om);
    printf("condensed\t%d\t%zu\t%.2f\t%.2f\t%.2f\t%d\t%.1f\t%zu%s\n", r->ndof,
           c.n, c.t_cond, c.t_step, c.t_solve, c.its, c.t_hill, c.nexp,
           c.rc ? "\tFAILED" : "");
    fe_chain_free(r);
  }
  whirl_fe_rotor *r = chain(332);
  result c = run(r, 0, Om), f = run(r, 1, Om);
  printf("condensed\t%d\t%zu\t%.2f\t%.2f\t%.2f\t%d\t%.1f\t%zu%s\n", r->ndof,
         c.n, c.t_cond, c.t_step, c.t_solve, c.its, c.t_hill, c.nexp,
         c.rc ? "\tFAILED" : "");
  printf("uncondensed\t%d\t%zu\t-\t%.2f\t%.2f\t%d\t-\t-%s\n", r->ndof, f.n,
         f.t_step, f.t_solve, f.its, f.rc ? "\tFAILED" : "");
  printf("# speed-up of the Newton solve at %d DOF: %.0fx\n", r->ndof,
         f.t_solve / c.t_solve);
  fe_chain_free(r);
  return (c.rc || f.rc) ? 1 : 0;
}

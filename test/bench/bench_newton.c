/* test/bench/bench_newton.c — cost of one Newton step of the periodic-orbit
 * discretisations against their size, on the dense (LAPACK) and the sparse
 * (UMFPACK) path: Jacobian assembly + factorisation + solve of F_x dx = −F,
 * for the SFD rotor at Table 1.
 *   HBM (fixed frame, Ω = 1.78 circular orbit): N = 4 .. 128 harmonics,
 *       unknowns 4(2N + 1); the Jacobian is block-dense (10 of 16 blocks).
 *   collocation (rotating-frame nonsynchronous cycle shape, here the
 *       fixed-frame orbit at 1.78): NTST = 10 .. 640, NCOL 4, unknowns
 *       4(4 NTST + 1); the Jacobian is block-bidiagonal with borders.
 * Prints one TSV row per size: median wall time (ms) over repeats of the
 * three parts.  Not a test: run `make bench`, record in doc/benchmarks.md.
 * Usage: bench_newton [repeats]
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/rotor.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* One Newton step on sys at X (dense or sparse); times in ms. */
static int step(const whirl_system *sys, const double *X, const double *p,
                int sparse, int reps, double *t_jac, double *t_fac,
                double *t_sol) {
  const size_t S = sys->n;
  double *J = malloc((sparse ? sys->nnz : S * S) * sizeof *J);
  double *b = malloc(S * sizeof *b);
  whirl_linsol *ls = sparse ? whirl_linsol_alloc_sparse(S, sys->Jp, sys->Ji)
                            : whirl_linsol_alloc_dense(S);
  double *tj = malloc(3 * (size_t)reps * sizeof *tj), *tf = tj + reps, *ts = tf + reps;
  int rc = !J || !b || !ls || !tj;
  for (int r = 0; r < reps && !rc; ++r) {
    double t0 = now();
    rc = sparse ? sys->Fx_sparse(X, p, J, sys->data) : sys->Fx(X, p, J, sys->data);
    double t1 = now();
    if (!rc) rc = whirl_linsol_factor(ls, J);
    double t2 = now();
    if (!rc) rc = sys->F(X, p, b, sys->data);
    if (!rc) rc = whirl_linsol_solve(ls, b, 1, 0);
    double t3 = now();
    tj[r] = t1 - t0, tf[r] = t2 - t1, ts[r] = t3 - t2;
  }
  if (!rc) {
    qsort(tj, (size_t)reps, sizeof *tj, cmp);
    qsort(tf, (size_t)reps, sizeof *tf, cmp);
    qsort(ts, (size_t)reps, sizeof *ts, cmp);
    *t_jac = 1e3 * tj[reps / 2], *t_fac = 1e3 * tf[reps / 2], *t_sol = 1e3 * ts[reps / 2];
  }
  whirl_linsol_free(ls);
  free(J), free(b), free(tj);
  return rc;
}

int main(int argc, char **argv) {
  int reps = argc > 1 ? atoi(argv[1]) : 7;
  if (reps < 1) reps = 1;
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = 1.78;
  double eps[4], mre[4];
  int st[4];
  size_t no = 0;
  whirl_sfd_circular_orbits(p, eps, st, mre, 4, &no);
  enum { M = 512 };
  double xr[4], *xs = malloc(4 * M * sizeof *xs);
  whirl_sfd_circ_state(eps[0], 1.78, p[1], p[2], p[3], xr);
  for (size_t j = 0; j < M; ++j)
    whirl_sfd_to_fixed(1.78, 2 * M_PI * (double)j / (M * 1.78), xr, xs + 4 * j);
  printf("method\tsize_param\tunknowns\tnnz\tpath\tjacobian_ms\tfactor_ms\tsolve_ms\tstep_ms\n");
  char err[256];
  static const int mask[16] = {0, 0, 1, 1, 0, 0, 1, 1, 1, 0, 1, 1, 0, 1, 1, 1};
  for (size_t N = 4; N <= 128; N *= 2) {
    whirl_hbm_options o;
    whirl_hbm_options_default(&o);
    o.harmonics = N;
    o.forcing_param = WHIRL_SFD_OMEGA;
    o.fx_mask = mask;
    o.no_spectrum = 1;
    whirl_hbm *h = whirl_hbm_alloc(whirl_sfd_fixed(), &o, err, sizeof err);
    if (!h || 2 * N + 1 > M) break;
    const whirl_system *sys = whirl_hbm_system(h);
    double *X = malloc(sys->n * sizeof *X);
    whirl_hbm_from_samples(h, xs, M, 0, X);
    for (int sp = 0; sp < 2; ++sp) {
      double a, b, c;
      if (step(sys, X, p, sp, reps, &a, &b, &c) == 0)
        printf("hbm\tN=%zu\t%zu\t%zu\t%s\t%.4f\t%.4f\t%.4f\t%.4f\n", N, sys->n, sys->nnz,
               sp ? "sparse" : "dense", a, b, c, a + b + c);
    }
    free(X);
    whirl_hbm_free(h);
  }
  for (size_t ntst = 10; ntst <= 640; ntst *= 2) {
    whirl_colloc_options o;
    whirl_colloc_options_default(&o);
    o.ntst = ntst;
    o.ncol = 4;
    o.forcing_param = WHIRL_SFD_OMEGA;
    whirl_colloc *c = whirl_colloc_alloc(whirl_sfd_fixed(), &o, err, sizeof err);
    if (!c) break;
    const whirl_system *sys = whirl_colloc_system(c);
    double *X = malloc(sys->n * sizeof *X);
    whirl_colloc_from_samples(c, xs, M, 2 * M_PI / 1.78, X);
    for (int sp = 0; sp < 2; ++sp) {
      if (!sp && sys->n > 3000) continue; /* dense LU of > 3000 unknowns: seconds */
      double a, b, cc;
      if (step(sys, X, p, sp, reps, &a, &b, &cc) == 0)
        printf("colloc\tNTST=%zu\t%zu\t%zu\t%s\t%.4f\t%.4f\t%.4f\t%.4f\n", ntst, sys->n,
               sys->nnz, sp ? "sparse" : "dense", a, b, cc, a + b + cc);
    }
    free(X);
    whirl_colloc_free(c);
  }
  free(xs);
  return 0;
}

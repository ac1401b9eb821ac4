/* test/bench/bench_basins.c — cost of the time-domain analysis:
 *  1. steps and right-hand-side evaluations per forcing period of the
 *     Dormand–Prince integrator at the default tolerance (1e-12 / 1e-15),
 *     from rest at Omega = 1.78 and 8.7;
 *  2. the Omega = 1.78 basin (zero velocities, ~8000 points): early exit on
 *     1 and 2 threads, against the fixed 500-period horizon (on every k-th
 *     point, --stride k, default 10, and scaled to all points; --stride 1
 *     integrates all of them), with the classifications compared.
 * usage: bench_basins [--points N] [--stride K] [--repeat R]
 * Prints wall times (medians over R repeats) and the ratios.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/rotor.h>

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double median(double *v, int n) {
  qsort(v, (size_t)n, sizeof *v, cmp);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static void per_period(double Om) {
  double p[5];
  whirl_sfd_default_params(p);
  p[0] = Om;
  const double T = 2 * M_PI / Om, x0[4] = {0, 0, 0, 0};
  whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
  whirl_ode_reset(ode, 0, x0);
  double t0 = now();
  int rc = whirl_ode_evolve(ode, 200 * T);
  double s = now() - t0;
  whirl_ode_stats st;
  whirl_ode_get_stats(ode, &st);
  printf("integrator\tOmega=%g\t200 periods from rest\tstatus %d\t%.1f steps/period\t%.1f RHS/period\t"
         "%.1f rejected/period\t%.3f ms/period\n",
         Om, rc, st.steps / 200.0, st.rhs_evals / 200.0, st.rejected / 200.0, 1e3 * s / 200);
  whirl_ode_free(ode);
}

int main(int argc, char **argv) {
  size_t npts = 8000, stride = 10;
  int repeat = 1;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--points") && i + 1 < argc) npts = (size_t)atol(argv[++i]);
    else if (!strcmp(argv[i], "--stride") && i + 1 < argc) stride = (size_t)atol(argv[++i]);
    else if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else {
      fprintf(stderr, "usage: bench_basins [--points N] [--stride K] [--repeat R]\n");
      return 2;
    }
  }
  if (repeat < 1 || repeat > 50 || stride < 1 || npts < 1) return 2;
  per_period(1.78);
  per_period(8.7);

  double p[5];
  whirl_sfd_default_params(p);
  p[0] = 1.78;
  whirl_sfd_attractors_options ao;
  whirl_sfd_attractors_options_default(&ao);
  whirl_sfd_attractors *A = NULL;
  char msg[256];
  double ta = now();
  if (whirl_sfd_attractors_find(p, &ao, &A, msg, sizeof msg) != WHIRL_OK) {
    fprintf(stderr, "bench_basins: %s\n", msg);
    return 1;
  }
  ta = now() - ta;
  size_t n = whirl_sfd_disc_points(npts, 0.98, NULL, 0);
  double *yz = malloc(2 * n * sizeof *yz), *X = malloc(4 * n * sizeof *X);
  int *w1 = malloc(n * sizeof(int)), *w2 = malloc(n * sizeof(int));
  unsigned *per = malloc(n * sizeof(unsigned));
  whirl_sfd_disc_points(npts, 0.98, yz, n);
  for (size_t i = 0; i < n; ++i) {
    X[4 * i] = yz[2 * i];
    X[4 * i + 1] = yz[2 * i + 1];
    X[4 * i + 2] = X[4 * i + 3] = 0;
  }
  whirl_basins_options bo;
  whirl_basins_options_default(&bo);
  bo.period = 2 * M_PI / p[0];
  const whirl_attractor *att = whirl_sfd_attractors_list(A);
  const size_t na = whirl_sfd_attractors_count(A);
  double t1[50], t2[50], tf[50];
  whirl_basins_stats s1, sf;
  for (int r = 0; r < repeat; ++r) {
    bo.fixed_horizon = 0;
    bo.nthreads = 1;
    double t = now();
    whirl_basins_compute(whirl_sfd_fixed(), p, n, X, att, na, &bo, w1, per, &s1, msg, sizeof msg);
    t1[r] = now() - t;
    bo.nthreads = 2;
    t = now();
    whirl_basins_compute(whirl_sfd_fixed(), p, n, X, att, na, &bo, w2, NULL, NULL, msg, sizeof msg);
    t2[r] = now() - t;
    if (memcmp(w1, w2, n * sizeof(int))) printf("MISMATCH between 1 and 2 threads\n");
  }
  /* fixed horizon on every stride-th point, 2 threads */
  size_t m = (n + stride - 1) / stride;
  double *Xs = malloc(4 * m * sizeof *Xs);
  int *ws = malloc(m * sizeof(int));
  for (size_t i = 0; i < m; ++i) memcpy(Xs + 4 * i, X + 4 * i * stride, 4 * sizeof *Xs);
  bo.fixed_horizon = 1;
  bo.max_periods = 500;
  bo.nthreads = 2;
  int frep = stride == 1 ? 1 : repeat;
  for (int r = 0; r < frep; ++r) {
    double t = now();
    whirl_basins_compute(whirl_sfd_fixed(), p, m, Xs, att, na, &bo, ws, NULL, &sf, msg, sizeof msg);
    tf[r] = now() - t;
  }
  size_t same = 0;
  for (size_t i = 0; i < m; ++i) same += ws[i] == w1[i * stride];
  size_t cnt[8] = {0};
  for (size_t i = 0; i < n; ++i)
    if (w1[i] >= 0 && w1[i] < 8) ++cnt[w1[i]];
  double m1 = median(t1, repeat), m2 = median(t2, repeat), mf = median(tf, frep) * (double)n / (double)m;
  printf("basin\tOmega=1.78\t%zu points\tattractors %.2f s\t", n, ta);
  for (size_t j = 0; j < na; ++j)
    printf("%s %.2f%%  ", whirl_sfd_attractors_info(A, j)->name, 100.0 * cnt[j] / (double)n);
  printf("\n");
  printf("early exit, 1 thread \t%.2f s (median of %d)\t%.1f periods/point\t%.0f RHS/point\n", m1, repeat,
         (double)s1.periods / n, (double)s1.rhs_evals / n);
  printf("early exit, 2 threads\t%.2f s (median of %d)\tspeed-up %.2f\n", m2, repeat, m1 / m2);
  printf("fixed 500 periods, 2 threads\t%.2f s for all %zu points (measured on %zu points, every %zu-th)\t"
         "%.0f RHS/point\n", mf, n, m, stride, (double)sf.rhs_evals / m);
  printf("early exit vs fixed horizon (2 threads)\t%.1fx faster\tsame class on %zu of %zu points\n", mf / m2,
         same, m);
  free(yz);
  free(X);
  free(Xs);
  free(ws);
  free(w1);
  free(w2);
  free(per);
  whirl_sfd_attractors_free(A);
  return 0;
}

/* test/bench/bench_fe_reduced.c — Hill's stability on the Craig–Bampton
 * reduction (stability 3, rotor/fe_hbm_reduce.c) against the full sparse
 * Hill method (stability 2) along a rotor's unbalance response: at every
 * EVERY-th point of the branch from rest (stability off), the exponents of
 * both, for cutoffs κ = 1.5, 2, 3, 4, 6 ((H + ½) ω_max units):
 *   kappa  the cutoff factor; modes the held rotor's modes kept
 *   maxerr the largest distance from a full exponent to the nearest
 *          reduced one, over the full exponents with |λ| < 0.45 ω (those
 *          well inside the disk both compute), relative to ω
 *   rmost  the largest error of the rightmost exponent's real part,
 *          relative to ω
 *   flips  points where the two disagree on stability
 *   ms     mean milliseconds per spectrum (full, then reduced)
 * Not a test: figures go into doc/fe-hbm.md with the machine.
 *   bench_fe_reduced ROTOR [EVERY]
 * (VERBOSE=1 in the environment: the failures, and both lists of exponents
 * at the last point, on stderr.)
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/rotor/fe_hbm.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct pts {
  size_t n, cap, nx, every, seen;
  double *X, *Om;
} pts;

static int keep(const whirl_fe_hbm_response_point *pt, void *ctx) {
  pts *c = ctx;
  if (pt->Omega <= 0 || c->seen++ % c->every) return 0;
  if (c->n == c->cap) {
    c->cap = c->cap ? 2 * c->cap : 64;
    c->X = realloc(c->X, c->cap * pt->n * sizeof *c->X);
    c->Om = realloc(c->Om, c->cap * sizeof *c->Om);
    if (!c->X || !c->Om) return 1;
  }
  c->nx = pt->n;
  memcpy(c->X + c->n * pt->n, pt->X, pt->n * sizeof *c->X);
  c->Om[c->n++] = pt->Omega;
  return 0;
}

#define NEXP 64

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: bench_fe_reduced ROTOR [EVERY]\n");
    return 2;
  }
  char err[512];
  whirl_fe_rotor *r = whirl_fe_rotor_read(argv[1], err, sizeof err, NULL);
  if (!r) { fprintf(stderr, "%s\n", err); return 2; }
  pts c = {.every = argc > 2 ? (size_t)atoi(argv[2]) : 5};
  if (c.every < 1) c.every = 1;
  whirl_fe_hbm_response_options o;
  whirl_fe_hbm_response_options_default(&o);
  o.hbm.stability = 0;
  if (whirl_fe_hbm_response(r, &o, keep, &c, err, sizeof err)) {
    fprintf(stderr, "response: %s\n", err);
    return 1;
  }
  o.hbm.stability = 2;
  whirl_fe_hbm *hf = whirl_fe_hbm_alloc(r, &o.hbm, err, sizeof err);
  if (!hf) { fprintf(stderr, "%s\n", err); return 1; }
  double *fre = malloc(c.n * NEXP * sizeof *fre), *fim = malloc(c.n * NEXP * sizeof *fim);
  size_t *fm = malloc(c.n * sizeof *fm);
  double t0 = now();
  for (size_t k = 0; k < c.n; ++k) {
    double p[WHIRL_FE_NPAR];
    whirl_fe_hbm_params(c.Om[k], p);
    fm[k] = NEXP;
    if (whirl_fe_hbm_hill(hf, c.X + k * c.nx, p, fre + k * NEXP, fim + k * NEXP, fm + k))
      fm[k] = 0;
  }
  double tfull = (now() - t0) / (double)c.n;
  printf("# %s: %zu points (every %zu-th of %zu), full sparse Hill %.2f ms a spectrum\n",
         argv[1], c.n, c.every, c.seen, 1e3 * tfull);
  printf("kappa\tmaxerr\trmost\tflips\tms_full\tms_reduced\n");
  const double kappas[] = {1.5, 2, 3, 4, 6};
  for (size_t q = 0; q < sizeof kappas / sizeof *kappas; ++q) {
    o.hbm.stability = 3;
    o.hbm.hill_cutoff = kappas[q];
    whirl_fe_hbm *hr = whirl_fe_hbm_alloc(r, &o.hbm, err, sizeof err);
    if (!hr) { fprintf(stderr, "%s\n", err); return 1; }
    double maxerr = 0, rmost = 0, t1 = now();
    int flips = 0, fails = 0;
    for (size_t k = 0; k < c.n; ++k) {
      double p[WHIRL_FE_NPAR], re[NEXP], im[NEXP], w = c.Om[k];
      size_t m = NEXP;
      whirl_fe_hbm_params(w, p);
      if (whirl_fe_hbm_hill(hr, c.X + k * c.nx, p, re, im, &m) || !fm[k]) {
        if (getenv("VERBOSE")) fprintf(stderr, "fail at %g: %s (full %zu)\n", w, whirl_fe_hbm_errmsg(hr), fm[k]);
        ++fails;
        continue;
      }
      if (getenv("VERBOSE") && k == c.n - 1)
        for (size_t j = 0; j < (m > fm[k] ? m : fm[k]); ++j)
          fprintf(stderr, "%g  %12.6g %12.6g   %12.6g %12.6g\n", w, j < fm[k] ? fre[k * NEXP + j] : NAN,
                  j < fm[k] ? fim[k * NEXP + j] : NAN, j < m ? re[j] : NAN, j < m ? im[j] : NAN);
      const double *a = fre + k * NEXP, *b = fim + k * NEXP;
      for (size_t j = 0; j < fm[k]; ++j) {
        if (hypot(a[j], b[j]) > 0.45 * w) continue;
        double best = INFINITY;
        for (size_t i = 0; i < m; ++i) best = fmin(best, hypot(re[i] - a[j], im[i] - b[j]));
        maxerr = fmax(maxerr, best / w);
      }
      rmost = fmax(rmost, fabs(re[0] - a[0]) / w);
      flips += (re[0] > 1e-9 * w) != (a[0] > 1e-9 * w);
    }
    double tred = (now() - t1) / (double)c.n;
    printf("%g\t%.2e\t%.2e\t%d%s\t%.2f\t%.2f\n", kappas[q], maxerr, rmost, flips,
           fails ? " (fails)" : "", 1e3 * tfull, 1e3 * tred);
    whirl_fe_hbm_free(hr);
  }
  whirl_fe_hbm_free(hf);
  whirl_fe_rotor_free(r);
  free(fre); free(fim); free(fm); free(c.X); free(c.Om);
  return 0;
}

/* test/bench/bench_region.c — the whole of Fig. 18 (both boundaries, zeta = 0
 * and 0.05, lambda in [0.01, 1.5], W = 20) by two-parameter continuation,
 * against the brute-force alternative: a grid of one-parameter
 * continuations (the complete synchronous response at every (lambda, delta)
 * of a grid, classified as "isolated branch below W" or not).
 * Prints wall times (median of --reps runs), steps, Newton iterations, and
 * the accuracy of both against the merge value of eq. 15 at lambda = 0.25.
 * usage: bench_region [--reps R] [--nl L] [--nd D]
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/rotor.h>
#include <whirl/rotor/sfd_region.h>

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Largest eccentricity of branch b where it crosses Omega (-1 if never). */
static double eps_at(const whirl_branch *b, double W) {
  double e = -1.0;
  for (size_t i = 0; i + 1 < b->len; ++i) {
    const double w0 = b->pts[i].p[WHIRL_SFD_OMEGA], w1 = b->pts[i + 1].p[WHIRL_SFD_OMEGA];
    if ((w0 - W) * (w1 - W) > 0 || w0 == w1) continue;
    const double u = (W - w0) / (w1 - w0);
    const double e0 = hypot(b->pts[i].x[0], b->pts[i].x[1]);
    const double e1 = hypot(b->pts[i + 1].x[0], b->pts[i + 1].x[1]);
    e = fmax(e, e0 + u * (e1 - e0));
  }
  return e;
}

/* 1 if the response at (lambda, delta) has an isolated branch below W in
 * the paper's sense: a branch not connected (within [omega_min, W]) to the
 * main branch that starts at omega_min, with orbits larger than the main
 * branch's at the same speed (before the merge the large orbits are
 * isolated; after it the main branch climbs onto them and what is left
 * apart is the small-orbit part). */
static int has_isola(double lambda, double delta, double zeta, double W, size_t *steps) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_LAMBDA] = lambda;
  p[WHIRL_SFD_DELTA] = delta;
  p[WHIRL_SFD_ZETA] = zeta;
  whirl_sfd_response_options o;
  whirl_sfd_response_options_default(&o);
  o.omega_max = W;
  whirl_sfd_response r;
  if (whirl_sfd_response_compute(p, &o, &r, NULL, 0) != 0) return -1;
  const whirl_branch *main_br = NULL;
  for (size_t b = 0; b < r.nbranch && !main_br; ++b)
    for (size_t i = 0; i < r.branch[b]->len; ++i)
      if (r.branch[b]->pts[i].p[WHIRL_SFD_OMEGA] < 1.5 * o.omega_min) {
        main_br = r.branch[b];
        break;
      }
  int iso = 0;
  for (size_t b = 0; b < r.nbranch && main_br && !iso; ++b) {
    if (r.branch[b] == main_br) continue;
    for (size_t i = 0; i < r.branch[b]->len && !iso; ++i) {
      const double W_i = r.branch[b]->pts[i].p[WHIRL_SFD_OMEGA];
      const double e_i = hypot(r.branch[b]->pts[i].x[0], r.branch[b]->pts[i].x[1]);
      const double em = eps_at(main_br, W_i);
      iso = em >= 0 && e_i > em + 1e-6;
    }
  }
  *steps += r.steps;
  whirl_sfd_response_free(&r);
  return iso;
}

int main(int argc, char **argv) {
  int reps = 5;
  size_t nl = 12, nd = 46;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--reps")) reps = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--nl")) nl = (size_t)atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--nd")) nd = (size_t)atoi(argv[i + 1]);
  }
  if (reps < 1 || reps > 100 || nl < 2 || nd < 2) {
    fprintf(stderr, "bench_region: bad arguments\n");
    return 2;
  }
  printf("# Fig. 18 by continuation: both boundaries, zeta = 0 and 0.05, lambda in [0.01, 1.5]\n");
  double t[100];
  size_t steps = 0, its = 0, pts = 0;
  for (int k = 0; k < reps; ++k) {
    const double t0 = now();
    steps = its = pts = 0;
    for (int z = 0; z < 2; ++z) {
      whirl_sfd_region_options o;
      whirl_sfd_region_options_default(&o);
      o.zeta = z ? 0.05 : 0.0;
      whirl_sfd_region r;
      if (whirl_sfd_region_compute(&o, &r, NULL, 0) != 0) {
        fprintf(stderr, "bench_region: region failed\n");
        return 1;
      }
      steps += r.steps, its += r.newton_its, pts += r.upper.len + r.lower.len;
      whirl_sfd_region_free(&r);
    }
    t[k] = now() - t0;
  }
  qsort(t, (size_t)reps, sizeof *t, cmp);
  const double tc = t[reps / 2];
  printf("continuation\twall_s %.4f (median of %d, min %.4f max %.4f)\tsteps %zu\tnewton %zu\tpoints %zu\n",
         tc, reps, t[0], t[reps - 1], steps, its, pts);

  /* accuracy at lambda = 0.25 (zeta 0): the merge delta by eq. 15 */
  whirl_sfd_curve mp;
  whirl_sfd_merge_points(0.25, 0.0, &mp, NULL, 0);
  const double dstar = mp.len ? mp.delta[0] : NAN;
  whirl_sfd_curve_free(&mp);
  whirl_sfd_region_options o;
  whirl_sfd_region_options_default(&o);
  whirl_sfd_region r;
  whirl_sfd_region_compute(&o, &r, NULL, 0);
  double lo, hi;
  whirl_sfd_region_band(&r, 0.25, 20.0, &lo, &hi);
  printf("continuation at lambda 0.25: upper %.10f (merge by eq. 15 %.10f, interpolation error %.1e), lower %.10f\n",
         hi, dstar, hi - dstar, lo);

  /* brute force: one damping case on an nl x nd grid */
  printf("# brute force: complete response at each (lambda, delta) of a %zu x %zu grid (zeta 0)\n", nl, nd);
  size_t bsteps = 0, bs0 = 0;
  whirl_sfd_region_compute(&o, &r, NULL, 0);
  const double t0 = now();
  size_t inside = 0, mismatch = 0;
  for (size_t i = 0; i < nl; ++i) {
    const double lam = 0.01 * pow(150.0, (double)i / (nl - 1));
    for (size_t j = 0; j < nd; ++j) {
      const double del = 0.05 + 0.9 * (double)j / (nd - 1);
      const int in = has_isola(lam, del, 0.0, 20.0, &bsteps) == 1;
      inside += in;
      const int band = whirl_sfd_region_band(&r, lam, 20.0, &lo, &hi) && del > lo && del < hi;
      if (band != in) {
        ++mismatch;
        printf("  mismatch at lambda %.4f delta %.4f: brute force %d, continuation band (%.5f, %.5f)\n",
               lam, del, in, lo, hi);
      }
    }
  }
  const double tb = now() - t0;
  printf("brute force\twall_s %.3f\tresponses %zu\tsteps %zu\tgrid points inside %zu\tdelta resolution %.4f\tdisagreements with the continuation band %zu\n",
         tb, nl * nd, bsteps, inside, 0.9 / (nd - 1), mismatch);
  /* between the MG (merge speed = W) and the cusp of the Omega = W fold
   * locus: the continuation says the region has ended; a fine delta scan
   * across both folds at W (0.43 ... 0.445) by brute force */
  const double lm = 0.5 * (r.lambda_m + r.lambda_c);
  if (isfinite(lm)) {
    const int empty = !whirl_sfd_region_band(&r, lm, 20.0, &lo, &hi);
    size_t nin = 0;
    for (int j = 0; j <= 40; ++j) nin += has_isola(lm, 0.43 + 0.015 * j / 40.0, 0.0, 20.0, &bs0) == 1;
    printf("lambda %.4f (between MG %.4f and CP %.4f): continuation band %s; brute force on 41 deltas "
           "in [0.43, 0.445]: %zu with an isola\n", lm, r.lambda_m, r.lambda_c,
           empty ? "empty" : "NOT empty", nin);
  }
  whirl_sfd_region_free(&r);
  /* brute force at lambda = 0.25: the first delta of the grid without an
   * isola above the region's lower edge */
  size_t bs = 0;
  double last_in = NAN, first_out = NAN;
  for (size_t j = 0; j < nd; ++j) {
    const double del = 0.05 + 0.9 * (double)j / (nd - 1);
    const int in = has_isola(0.25, del, 0.0, 20.0, &bs);
    if (in == 1) last_in = del;
    else if (!isnan(last_in) && isnan(first_out)) first_out = del;
  }
  printf("brute force at lambda 0.25: isola up to delta %.4f, none at %.4f (merge %.10f)\n", last_in,
         first_out, dstar);
  printf("ratio brute force (one damping case, %zu x %zu) / continuation (both cases): %.0f\n", nl, nd,
         tb / tc);
  return 0;
}

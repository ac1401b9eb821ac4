/* test/bench/bench_response.c — benchmark of the complete Table 1 response
 * (all branches, stability, localised LPs): wall time per run (median and
 * minimum over repeats), continuation steps, Newton iterations, F and
 * Jacobian evaluations.  Not a test: run `make bench` and record the figure
 * in doc/benchmarks.md with the machine.
 * Usage: bench_response [repeats] [dense|sparse]
 * SPDX-License-Identifier: BSD-3-Clause */
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

int main(int argc, char **argv) {
  int reps = argc > 1 ? atoi(argv[1]) : 51;
  if (reps < 1) reps = 1;
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  whirl_sfd_response_options o;
  whirl_sfd_response_options_default(&o);
  if (argc > 2 && !strcmp(argv[2], "sparse")) o.linsol = WHIRL_LINSOL_SPARSE;
  double *t = malloc((size_t)reps * sizeof *t);
  whirl_sfd_response r;
  char err[256];
  size_t nlp = 0;
  for (int k = 0; k < reps; ++k) {
    double t0 = now();
    if (whirl_sfd_response_compute(p, &o, &r, err, sizeof err) != WHIRL_OK) {
      fprintf(stderr, "bench_response: %s\n", err);
      return 1;
    }
    t[k] = now() - t0;
    if (k + 1 < reps) whirl_sfd_response_free(&r);
  }
  for (size_t b = 0; b < r.nbranch; ++b)
    for (size_t i = 0; i < r.branch[b]->len; ++i) nlp += r.branch[b]->pts[i].type == WHIRL_PT_LP;
  qsort(t, (size_t)reps, sizeof *t, cmp);
  printf("benchmark\tsolver\trepeats\tmedian_ms\tmin_ms\tbranches\tLP\tseeds\tsteps\t"
         "newton_its\tf_evals\tjac_evals\n");
  printf("sfd_response_table1\t%s\t%d\t%.3f\t%.3f\t%zu\t%zu\t%zu\t%zu\t%zu\t%zu\t%zu\n",
         o.linsol == WHIRL_LINSOL_SPARSE ? "sparse" : "dense", reps, 1e3 * t[reps / 2],
         1e3 * t[0], r.nbranch, nlp, r.nseeds, r.steps, r.newton_its, r.f_evals, r.jac_evals);
  whirl_sfd_response_free(&r);
  free(t);
  return 0;
}

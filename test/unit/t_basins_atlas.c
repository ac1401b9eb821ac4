/* test/unit/t_basins_atlas.c — basins with the atlas of classified cells
 * (whirl/basins.h) against the slow route: the SFD rotor at Omega = 8.5327
 * with circular initial velocities (the paper's slowest case, Fig. 14b:
 * two attractors, most trajectories passing a long transient first), on a
 * coarse disc of start states.  Checked:
 *  - point by point equal to the fixed 500-period classification, computed
 *    here by integrating every point 500 periods (fixed_horizon), while the
 *    atlas classifies most of the points (so the comparison means something);
 *  - identical on 1 and 2 threads, and computed in three blocks sharing one
 *    atlas identical to one call (the order the points are computed in does
 *    not matter);
 *  - the atlas built in steps (rounds in parts, classified in any order,
 *    entered in order: what MPI ranks do) the same as one call;
 *  - an atlas of a single cell (every cell mixed) classifies no point and
 *    leaves the certified classification;
 *  - bad input.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "../tap.h"

typedef struct {
  double p[5];
  whirl_sfd_attractors *A;
  size_t n, na;
  double *X;
} paper_case;

static int setup(paper_case *c, double Om, size_t npts) {
  whirl_sfd_default_params(c->p);
  c->p[WHIRL_SFD_OMEGA] = Om;
  char msg[256];
  if (whirl_sfd_attractors_find(c->p, NULL, &c->A, msg, sizeof msg) != WHIRL_OK) {
    ok(0, "attractors at Omega = %g: %s", Om, msg);
    return -1;
  }
  c->na = whirl_sfd_attractors_count(c->A);
  c->n = whirl_sfd_disc_points(npts, 0.98, NULL, 0);
  c->X = malloc(4 * c->n * sizeof *c->X);
  double *yz = malloc(2 * c->n * sizeof *yz);
  whirl_sfd_disc_points(npts, 0.98, yz, c->n);
  for (size_t i = 0; i < c->n; ++i) {
    c->X[4 * i] = yz[2 * i];
    c->X[4 * i + 1] = yz[2 * i + 1];
    whirl_sfd_circular_velocity(Om, yz[2 * i], yz[2 * i + 1], &c->X[4 * i + 2], &c->X[4 * i + 3]);
  }
  free(yz);
  return 0;
}

static void options(whirl_basins_options *o, double Om, int threads) {
  whirl_basins_options_default(o);
  o->period = 2 * WHIRL_PI / Om;
  o->max_periods = 500;
  o->nthreads = threads;
  o->seed_stride = 2;
  o->atlas_levels = 3;
  o->cells = 32;
  o->cell_hits = 4;
  o->section_phases = 8; /* the defaults of whirl sfd basins but the strides */
}

static int run(const paper_case *c, const whirl_basins_options *o, int *w, unsigned *per,
               whirl_basins_stats *st) {
  char msg[256];
  int rc = whirl_basins_compute(whirl_sfd_fixed(), c->p, c->n, c->X, whirl_sfd_attractors_list(c->A),
                                c->na, o, w, per, st, msg, sizeof msg);
  if (rc != WHIRL_OK) printf("# basins: %s\n", msg);
  return rc;
}

int main(void) {
  paper_case c;
  const double Om = 8.5327;
  if (setup(&c, Om, 100)) return done_testing();
  const size_t n = c.n;
  int *w2 = malloc(n * sizeof *w2), *w1 = malloc(n * sizeof *w1), *wb = malloc(n * sizeof *wb);
  int *wf = malloc(n * sizeof *wf), *wm = malloc(n * sizeof *wm);
  unsigned *p2 = malloc(n * sizeof *p2), *p1 = malloc(n * sizeof *p1), *pb = malloc(n * sizeof *pb);
  whirl_basins_options o;
  whirl_basins_stats st;

  options(&o, Om, 2);
  int rc = run(&c, &o, w2, p2, &st);
  ok(rc == WHIRL_OK && c.na == 2, "Omega = 8.5327, %zu circular starts: basins with the atlas (%zu "
     "attractors)", n, c.na);
  const size_t free_pts = n - (n - 1) / o.seed_stride - 1; /* the points not in the atlas */
  ok(st.by_atlas >= free_pts / 2, "the atlas classifies %zu of the %zu points outside it",
     st.by_atlas, free_pts);

  /* the slow route: every point 500 periods, classified at the end */
  whirl_basins_options of = o;
  of.fixed_horizon = 1;
  of.seed_stride = 0;
  rc = run(&c, &of, wf, NULL, NULL);
  size_t diff = 0, big = 0;
  for (size_t i = 0; i < n; ++i) {
    diff += w2[i] != wf[i];
    big += wf[i] == 1;
  }
  ok(rc == WHIRL_OK && diff == 0, "equal to the fixed 500-period classification point by point "
     "(%zu of %zu differ)", diff, n);
  ok(big > 0 && big < n, "both orbits have points (large: %zu of %zu)", big, n);

  options(&o, Om, 1);
  rc = run(&c, &o, w1, p1, NULL);
  ok(rc == WHIRL_OK && !memcmp(w1, w2, n * sizeof *w1) && !memcmp(p1, p2, n * sizeof *p1),
     "identical classes and periods on 1 and 2 threads");

  /* three blocks, last first, sharing one atlas */
  whirl_basins_atlas *a = NULL;
  char msg[256];
  options(&o, Om, 2);
  rc = whirl_basins_atlas_build(whirl_sfd_fixed(), c.p, n, c.X, whirl_sfd_attractors_list(c.A), c.na,
                                &o, &a, msg, sizeof msg);
  ok(rc == WHIRL_OK && whirl_basins_atlas_seeds(a) == (n - 1) / 2 + 1 && whirl_basins_atlas_cells(a) > 0,
     "atlas built: %zu points, %zu cells (%s)", whirl_basins_atlas_seeds(a),
     whirl_basins_atlas_cells(a), msg);
  const size_t cut[4] = {0, n / 3, 2 * n / 3, n};
  o.atlas = a;
  for (int b = 2; b >= 0 && rc == WHIRL_OK; --b) {
    o.first = cut[b];
    rc = whirl_basins_compute(whirl_sfd_fixed(), c.p, cut[b + 1] - cut[b], c.X + 4 * cut[b],
                              whirl_sfd_attractors_list(c.A), c.na, &o, wb + cut[b], pb + cut[b],
                              NULL, msg, sizeof msg);
  }
  ok(rc == WHIRL_OK && !memcmp(wb, w2, n * sizeof *wb) && !memcmp(pb, p2, n * sizeof *pb),
     "three blocks with a shared atlas, computed last first: the same classes and periods");
  /* the same atlas built in steps, as processes build it (drivers/
   * blocks_mpi.c): each round's seeds in parts of 3, classified last part
   * first, entered in order; then a round out of order refused */
  whirl_basins_atlas *as = NULL;
  options(&o, Om, 1);
  rc = whirl_basins_atlas_begin(whirl_sfd_fixed(), c.p, n, c.X, whirl_sfd_attractors_list(c.A), c.na,
                                &o, &as, msg, sizeof msg);
  int steps_ok = rc == WHIRL_OK && whirl_basins_atlas_rounds(as) == 3;
  void *parts[256] = {NULL};
  size_t lens[256] = {0}, seeds = 0;
  for (size_t r = 0; steps_ok && r < whirl_basins_atlas_rounds(as); ++r) {
    const size_t m = whirl_basins_atlas_round_seeds(as, r), np = (m + 2) / 3;
    seeds += m;
    steps_ok = np <= 256 && whirl_basins_atlas_classify(as, r + 1, 0, 1, &parts[0], &lens[0]) == WHIRL_EINVAL;
    for (size_t q = np; steps_ok && q-- > 0;)
      steps_ok = whirl_basins_atlas_classify(as, r, 3 * q, 3 * q + 3 <= m ? 3 : m - 3 * q, &parts[q],
                                             &lens[q]) == WHIRL_OK;
    if (steps_ok) steps_ok = whirl_basins_atlas_enter(as, r, (const void *const *)parts, lens, np) == WHIRL_OK;
    for (size_t q = 0; q < np && q < 256; ++q) free(parts[q]), parts[q] = NULL;
  }
  ok(steps_ok && seeds == whirl_basins_atlas_seeds(a) && whirl_basins_atlas_cells(as) == whirl_basins_atlas_cells(a),
     "built in steps (parts of 3 seeds, last first): the seeds and the %zu cells of one call",
     whirl_basins_atlas_cells(as));
  o.atlas = as;
  o.first = 0;
  rc = steps_ok ? whirl_basins_compute(whirl_sfd_fixed(), c.p, n, c.X, whirl_sfd_attractors_list(c.A),
                                       c.na, &o, wb, pb, NULL, msg, sizeof msg) : WHIRL_EINVAL;
  ok(rc == WHIRL_OK && !memcmp(wb, w2, n * sizeof *wb) && !memcmp(pb, p2, n * sizeof *pb),
     "with the atlas built in steps: the same classes and periods");
  const void *none[1] = {NULL};
  ok(whirl_basins_atlas_enter(as, 0, none, lens, 0) == WHIRL_EINVAL,
     "a round entered twice refused");
  whirl_basins_atlas_free(as);
  o.atlas = a;

  o.first = n - 5;
  ok(whirl_basins_compute(whirl_sfd_fixed(), c.p, 10, c.X, whirl_sfd_attractors_list(c.A), c.na, &o, wb,
                          NULL, NULL, msg, sizeof msg) == WHIRL_EINVAL && strstr(msg, "atlas"),
     "points beyond the atlas's list refused: %s", msg);
  whirl_basins_atlas_free(a);

  /* one cell: every cell mixed, so nothing by the atlas */
  options(&o, Om, 2);
  o.cells = 1;
  rc = run(&c, &o, wm, NULL, &st);
  diff = 0;
  for (size_t i = 0; i < n; ++i) diff += wm[i] != wf[i];
  ok(rc == WHIRL_OK && st.by_atlas == 0 && diff == 0,
     "an atlas of one cell classifies none (%zu) and leaves the certified classes (%zu differ)",
     st.by_atlas, diff);

  options(&o, Om, 2);
  o.atlas_levels = 9;
  ok(whirl_basins_atlas_build(whirl_sfd_fixed(), c.p, n, c.X, whirl_sfd_attractors_list(c.A), c.na, &o,
                              &a, msg, sizeof msg) == WHIRL_EINVAL && a == NULL,
     "9 levels refused: %s", msg);
  o.seed_stride = 0;
  ok(whirl_basins_atlas_build(whirl_sfd_fixed(), c.p, n, c.X, whirl_sfd_attractors_list(c.A), c.na, &o,
                              &a, msg, sizeof msg) == WHIRL_EINVAL && a == NULL,
     "seed stride 0 refused: %s", msg);

  free(w1), free(w2), free(wb), free(wf), free(wm), free(p1), free(p2), free(pb);
  free(c.X);
  whirl_sfd_attractors_free(c.A);
  return done_testing();
}

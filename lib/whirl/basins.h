/* whirl/basins.h — basins of attraction by time integration with early exit.
 *
 * Each attractor of a periodically forced (or autonomous) model is described
 * by a membership test on the stroboscopic section t = t0 + kT: test() says
 * whether a state lies in a region the attractor provably (or, for the
 * weaker tests, demonstrably — see the model's documentation) keeps, e.g.
 * a Lyapunov sublevel set of a stable equilibrium of the rotating frame.
 * A trajectory is assigned to the first attractor whose test holds on
 * `confirm` consecutive section points, and integration of that trajectory
 * stops there.  Trajectories that leave the model's domain (a recoverable
 * right-hand-side failure that the step control cannot get around, such as
 * journal–housing contact) are WHIRL_BASIN_DOMAIN; those not assigned after
 * max_periods are WHIRL_BASIN_UNSETTLED.
 *
 * Points are integrated in parallel (OpenMP, dynamic schedule); every point
 * has its own integrator and its result depends on nothing else, so the
 * basins are identical for any number of threads.
 *
 * Reuse of classified trajectories (an atlas; cell recurrence after
 * Datseris & Wagemakers, "Effortless estimation of basins of attraction",
 * Chaos 32, 023104, 2022).  With seed_stride = s > 0 the points 0, s, 2s,
 * ... are held by the atlas: they are classified first, in atlas_levels = L
 * rounds (round 1: the multiples of s·4^(L−1), by the tests alone; round l:
 * the multiples of s·4^(L−l) not in an earlier round, with the atlas of the
 * rounds before), and the section states of each, up to its
 * classification, are put into cells (each coordinate cut into `cells`
 * intervals over the range of round 1's states; with section_phases = m,
 * the section points are m a period, each phase with cells of its own).  A cell has the class of
 * the trajectories that visited it, or none if two classes did.  Every
 * other point is integrated until the tests capture it, or until
 * `cell_hits` consecutive section points (from the first period on, never
 * the initial state) lie in cells whose class is one attractor and whose
 * 2n face neighbours carry no other class: it then takes that class.  The
 * atlas depends on the held points only, each classified on its own within
 * its round, so the result is the same for any number of threads, any
 * order of the points and any split into blocks sharing one atlas.  The
 * tests are certificates, the atlas is not: its guarantee is empirical
 * (see doc/sfd-time-domain.md), which is why it is off by default here.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_BASINS_H
#define WHIRL_BASINS_H

#include <stddef.h>
#include <whirl/ode.h>
#include <whirl/problem.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_attractor {
  const char *name;
  /* 1 if x at section time t lies in the attractor's trapping region, 0 if
   * not, < 0 on error.  Called concurrently from several threads. */
  int (*test)(double t, const double *x, void *data);
  void *data;
  size_t confirm; /* consecutive section points the test must hold (>= 1) */
} whirl_attractor;

enum {
  WHIRL_BASIN_UNSETTLED = -1, /* no attractor within max_periods */
  WHIRL_BASIN_DOMAIN = -2,    /* left the model's domain (contact) */
  WHIRL_BASIN_FAILED = -3     /* integration error (see the message) */
};

/* Limits on the options, checked by whirl_basins_compute. */
/* The most attractors one whirl_basins_compute call classifies into
 * (more: WHIRL_EINVAL with a message). */
#define WHIRL_BASINS_MAX_ATTRACTORS 32
#define WHIRL_BASINS_MAX_THREADS 1024
#define WHIRL_BASINS_RTOL_MIN 1e-13
#define WHIRL_BASINS_RTOL_MAX 1e-3
#define WHIRL_BASINS_ATOL_MAX 1e-3

typedef struct whirl_basins_options {
  double t0;            /* start time (section phase), default 0 */
  double period;        /* section period T > 0 (required) */
  size_t max_periods;   /* default 500 (the paper's horizon) */
  int fixed_horizon;    /* 1: integrate max_periods always; the class is
                           the attractor whose test holds on the last
                           `confirm` section points */
  double rtol, atol;    /* default 1e-12, 1e-15; WHIRL_BASINS_RTOL_MIN <=
                           rtol <= WHIRL_BASINS_RTOL_MAX, 0 < atol <=
                           WHIRL_BASINS_ATOL_MAX (looser tolerances do not
                           classify, they only make the steps crawl) */
  int nthreads;         /* 0: OpenMP's default; at most
                           WHIRL_BASINS_MAX_THREADS */
  /* Optional progress report, called (serialised) after each point. */
  void (*progress)(size_t done, size_t total, void *data);
  void *progress_data;
  /* Atlas (see above; ignored with fixed_horizon). */
  size_t seed_stride;   /* 0: no atlas (default); s: every s-th point a seed */
  size_t cells;         /* intervals per coordinate, 0: 64 */
  size_t cell_hits;     /* consecutive section points in cells, 0: 3 */
  size_t section_phases; /* m (0: 1): the atlas's section points are
                           t0 + kT/m, each phase k mod m with cells of its
                           own (the tests still at t0 + kT only) */
  size_t atlas_levels;  /* L (0: 1, at most 8): the seeds are classified in
                           L rounds, round l those of stride s·4^(L−l) not
                           in an earlier round, each with the atlas of the
                           rounds before it (round 1 by the tests alone) */
  const struct whirl_basins_atlas *atlas; /* built beforehand over the whole
                           list of points (whirl_basins_atlas_build); NULL:
                           whirl_basins_compute builds its own over the
                           points it is given when seed_stride > 0 */
  size_t first;         /* with atlas: index in the atlas's list of x0[0] */
  int method;           /* whirl_ode_method of the trajectories: default
                           WHIRL_ODE_DOPRI5 (0); WHIRL_ODE_DOP853 takes
                           3–6 times fewer evaluations at rtol 1e-12 */
} whirl_basins_options;

WHIRL_API void whirl_basins_options_default(whirl_basins_options *o);

/* Check integration tolerances against the limits above: WHIRL_OK, or
 * WHIRL_EINVAL with "rtol must be in [1e-13, 0.001] (got 1)" in msg[len]. */
WHIRL_API int whirl_basins_check_tolerances(double rtol, double atol,
                                            char *msg, size_t len);

typedef struct whirl_basins_stats {
  size_t periods;   /* section periods integrated, all points */
  size_t steps;     /* accepted steps, all points */
  size_t rhs_evals; /* right-hand-side evaluations, all points */
  size_t by_atlas;  /* points classified by the atlas (not the tests) */
} whirl_basins_stats;

typedef struct whirl_basins_atlas whirl_basins_atlas;

/* Classify the seeds among npoints initial states x0 (every
 * o->seed_stride-th, which must be > 0) and build the atlas from their
 * trajectories, for whirl_basins_compute calls on any parts of the same
 * list (options.atlas, options.first).  Threads as o->nthreads.  The
 * seeds' classes are kept: those calls copy them.  Returns WHIRL_OK or an
 * error with a message in errbuf. */
WHIRL_API int whirl_basins_atlas_build(const whirl_problem *prob,
                                       const double *p, size_t npoints,
                                       const double *x0,
                                       const whirl_attractor *att,
                                       size_t natt,
                                       const whirl_basins_options *o,
                                       whirl_basins_atlas **out,
                                       char *errbuf, size_t errlen);
WHIRL_API void whirl_basins_atlas_free(whirl_basins_atlas *a);

/* The same atlas built in steps, for a caller that hands its rounds' seeds
 * to other processes (MPI) and gives every process the whole atlas:
 *
 *     whirl_basins_atlas_begin(..., &a, ...);    (no seed classified yet)
 *     for r in 0 .. whirl_basins_atlas_rounds(a) − 1:
 *       any split of the round's seeds 0 .. whirl_basins_atlas_round_seeds(a, r) − 1
 *       into parts, each whirl_basins_atlas_classify(a, r, j0, count, &buf, &len)
 *       (anywhere: an identical atlas, with the rounds before r entered);
 *       whirl_basins_atlas_enter(a, r, parts, lens, nparts), the parts in
 *       seed order, on every atlas that is to be used.
 *
 * A part is bytes (the seeds' classes and section states, in the
 * machine's representation: for processes of one architecture), malloc'd
 * (the caller frees it).  The atlas is the one whirl_basins_atlas_build
 * makes (which is these steps in one process).  begin keeps prob, p, x0 and
 * att, borrowed until the last round is entered.  WHIRL_OK, or WHIRL_EINVAL
 * (a round out of order, parts that are not exactly the round's seeds),
 * WHIRL_ENOMEM, or the error of a classification. */
WHIRL_API int whirl_basins_atlas_begin(const whirl_problem *prob,
                                       const double *p, size_t npoints,
                                       const double *x0,
                                       const whirl_attractor *att,
                                       size_t natt,
                                       const whirl_basins_options *o,
                                       whirl_basins_atlas **out,
                                       char *errbuf, size_t errlen);
WHIRL_API size_t whirl_basins_atlas_rounds(const whirl_basins_atlas *a);
WHIRL_API size_t whirl_basins_atlas_round_seeds(const whirl_basins_atlas *a,
                                                size_t r);
WHIRL_API int whirl_basins_atlas_classify(const whirl_basins_atlas *a,
                                          size_t r, size_t j0, size_t count,
                                          void **part, size_t *len);
WHIRL_API int whirl_basins_atlas_enter(whirl_basins_atlas *a, size_t r,
                                       const void *const *parts,
                                       const size_t *lens, size_t nparts);
/* Seeds, and classified cells, of an atlas. */
WHIRL_API size_t whirl_basins_atlas_seeds(const whirl_basins_atlas *a);
WHIRL_API size_t whirl_basins_atlas_cells(const whirl_basins_atlas *a);

/* Classify npoints initial states x0[npoints * n] (row i = point i) at
 * parameters p.  which[i] = index into att[] or a WHIRL_BASIN_* code;
 * periods[i] (may be NULL) the section periods integrated for point i.
 * Returns WHIRL_OK, or an error (bad options, a failing test) with a
 * message in errbuf. */
WHIRL_API int whirl_basins_compute(const whirl_problem *prob,
                                   const double *p, size_t npoints,
                                   const double *x0,
                                   const whirl_attractor *att, size_t natt,
                                   const whirl_basins_options *o, int *which,
                                   unsigned *periods, whirl_basins_stats *st,
                                   char *errbuf, size_t errlen);

/* Classify a single trajectory from x0 (the kernel of the above). */
WHIRL_API int whirl_basins_classify(whirl_ode *ode, const double *x0,
                                    const whirl_attractor *att, size_t natt,
                                    const whirl_basins_options *o, int *which,
                                    unsigned *periods);

#ifdef __cplusplus
}
#endif
#endif

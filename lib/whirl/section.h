/* whirl/section.h — the character of a Poincaré section and of the steady
 * state it samples: a fixed point (period-1 motion), a period-k cycle, an
 * invariant curve (quasiperiodic motion), an irregular set (chaos), or
 * points still converging or moving away (not settled).  The points are
 * any sampling of a trajectory once per period of the forcing (the
 * stroboscopic map) or at a crossing of a surface; lib/analysis/section.c.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SECTION_H
#define WHIRL_SECTION_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Character of a Poincaré section. */
typedef enum whirl_section_kind {
  WHIRL_SECTION_FIXED = 0,     /* all points coincide: period-1 motion */
  WHIRL_SECTION_PERIODIC = 1,  /* k distinct points repeating: period-k */
  WHIRL_SECTION_CURVE = 2,     /* points fill a closed curve: quasiperiodic */
  WHIRL_SECTION_IRREGULAR = 3  /* points fill an area or a fractal: chaotic */
} whirl_section_kind;

/* Classify npts points pts[npts*dim] (row i = pts[i*dim .. i*dim+dim-1], in
 * time order).  Two points coincide when their distance is at most tol times
 * the size of the set (largest distance from the centroid) plus tol
 * (absolute).  Period k is the smallest k ≤ max_period (at least 1 is tried)
 * with every P_i coinciding with P_{i mod k} (hence |P_{i+k} − P_i| small
 * for all i, and no slow drift): k = 1 is FIXED, k > 1 PERIODIC.  A cycle
 * longer than max_period (some k ≤ npts/2) is PERIODIC with *period = 0.
 * Otherwise the correlation-type dimension d of the set is estimated from
 * how nearest-neighbour distances scale, r ∝ (k/n)^(1/d) for the k-th of n
 * points: d = log 4 / log(r_32 / r_8), r_k the median distance to the k-th
 * nearest neighbour (the 8th among a quarter of the points is on average
 * the 32nd among all; using several neighbours and all points averages out
 * the gap structure of quasi-periodic points and is blind to a 2- or 4-fold
 * interleaving, where the 1st neighbour of every 4th point fails — see
 * lib/analysis/section.c).  d < 1.5 is a curve, otherwise irregular;
 * reliable from a few hundred points.
 * Outputs: *kind, *period (k, or 0), *dimension (0 for fixed and periodic,
 * +inf if the distances do not shrink at all); period and dimension may be
 * NULL.  WHIRL_EINVAL for npts < 2, npts < 2*max_period, npts < 64 when
 * the dimension is needed, dim = 0, tol < 0 or non-finite coordinates. */
WHIRL_API int whirl_section_classify(const double *pts, size_t npts,
                                     size_t dim, double tol,
                                     size_t max_period,
                                     whirl_section_kind *kind, size_t *period,
                                     double *dimension);

/* Character of a steady state from its section points. */
typedef enum whirl_steady_kind {
  WHIRL_STEADY_FIXED = 0,         /* one point: period-1 motion */
  WHIRL_STEADY_PERIODIC = 1,      /* k points repeating: period-k */
  WHIRL_STEADY_QUASIPERIODIC = 2, /* points on a closed curve */
  WHIRL_STEADY_IRREGULAR = 3,     /* points filling an area or a fractal */
  WHIRL_STEADY_TRANSIENT = 4,     /* not settled: still converging, or too
                                     few points to tell */
  WHIRL_STEADY_DIVERGENT = 5      /* not settled: moving away */
} whirl_steady_kind;

/* Fewest points whirl_steady_classify tells a steady state from (as the
 * dimension of whirl_section_classify needs). */
#define WHIRL_STEADY_MIN_POINTS 64

/* Classify the steady state sampled by npts section points pts[npts*dim]
 * (time order).  A point that is not finite makes it DIVERGENT; fewer than
 * WHIRL_STEADY_MIN_POINTS points TRANSIENT.  Otherwise the points are
 * classified by whirl_section_classify (tol, max_period as there): a fixed
 * point or a cycle is FIXED or PERIODIC (*period as there).  A curve or an
 * irregular set is first compared with how the points move: with s_first,
 * s_last the mean distance between successive points over the first and
 * the last tenth of the record, s_last < 1e-3 s_first is TRANSIENT (still
 * converging, e.g. a slowly settling spiral, which looks like a curve) and
 * s_last > 1e3 s_first DIVERGENT (moving away, e.g. from an unstable
 * fixed point); otherwise a curve is QUASIPERIODIC, an irregular set
 * IRREGULAR.
 * Outputs: *kind; *period (k, 0 if not periodic or longer than
 * max_period); *dimension (that of whirl_section_classify, NaN where it
 * was not estimated: too few points, not finite); period and dimension may
 * be NULL.  WHIRL_EINVAL for pts or kind NULL, dim = 0, tol < 0 or not
 * finite, max_period > npts / 2 (with npts >= WHIRL_STEADY_MIN_POINTS);
 * WHIRL_ENOMEM. */
WHIRL_API int whirl_steady_classify(const double *pts, size_t npts, size_t dim,
                                    double tol, size_t max_period,
                                    whirl_steady_kind *kind, size_t *period,
                                    double *dimension);

/* "fixed", "periodic", "quasiperiodic", "irregular", "transient",
 * "divergent"; "?" for another value. */
WHIRL_API const char *whirl_steady_kind_name(whirl_steady_kind kind);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/branch.h — a stored branch: the sequence of points a continuation
 * produced, with types, labels and stability, plus the helpers that complete
 * diagrams need (is a seed already on a traced branch?) and a convenience
 * loop that runs a continuation into a branch.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_BRANCH_H
#define WHIRL_BRANCH_H

#include <stddef.h>
#include <whirl/cont.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_branch_point {
  int type, label, stable, n_unstable;
  size_t index;
  double s;
  double *x;       /* x[n], owned by the branch */
  double *p;       /* p[npar] */
  double *spec_re; /* spec[nspec] (may be NULL when nspec == 0) */
  double *spec_im;
} whirl_branch_point;

typedef struct whirl_branch {
  int id;          /* BR, set by the caller */
  size_t n, npar, nspec, icp;
  size_t len, cap;
  whirl_branch_point *pts;
  int stop_reason; /* whirl_stop_reason of the continuation(s) that made it */
} whirl_branch;

WHIRL_API whirl_branch *whirl_branch_alloc(size_t n, size_t npar,
                                           size_t nspec, size_t icp);
WHIRL_API void whirl_branch_free(whirl_branch *b); /* accepts NULL */

/* Append a copy of pt.  WHIRL_ENOMEM on failure. */
WHIRL_API int whirl_branch_append(whirl_branch *b, const whirl_point *pt);

/* Reverse the order of the points (to join two half-branches). */
WHIRL_API void whirl_branch_reverse(whirl_branch *b);

/* Append every point of src except its first (the shared start) to dst. */
WHIRL_API int whirl_branch_join(whirl_branch *dst, const whirl_branch *src);

/* Distance in (x, p_icp) from (x, p) to the polyline of the branch, with the
 * parameter weighted by p_weight.  Returns +inf for an empty branch; *seg (if
 * not NULL) receives the index of the nearest segment's first point. */
WHIRL_API double whirl_branch_distance(const whirl_branch *b, const double *x,
                                       const double *p, double p_weight,
                                       size_t *seg);

/* Is (x, p) nearer than tol to the polyline of the branch (the distance of
 * whirl_branch_distance < tol)?  Stops at the first segment that is; segments
 * farther than tol in the parameter alone are not computed. */
WHIRL_API int whirl_branch_within(const whirl_branch *b, const double *x,
                                  const double *p, double p_weight, double tol);

/* Run the continuation c (already started) to its end, appending every point
 * to b.  Returns WHIRL_DONE at a normal end or the error. */
WHIRL_API int whirl_cont_run(whirl_cont *c, whirl_branch *b);

/* Trace a whole branch through a solution (x0, p0): continue in both
 * directions of the free parameter and join the halves into one branch
 * ordered along the curve.  If the first half closes on itself (isola), the
 * second is not run.  Returns WHIRL_OK with *out a new branch, or an error
 * (message in the continuation object, copied to errbuf). */
WHIRL_API int whirl_trace_branch(const whirl_system *sys,
                                 const whirl_cont_options *opt,
                                 const double *x0, const double *p0,
                                 whirl_branch **out, whirl_cont_stats *stats,
                                 char *errbuf, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

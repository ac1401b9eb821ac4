/* whirl/deflate.h — deflated Newton: solutions of F(x, p) = 0 at fixed p
 * other than the ones already known (Farrell, Birkisson & Funke, "Deflation
 * techniques for finding distinct solutions of nonlinear partial
 * differential equations", SIAM J. Sci. Comput. 37 (2015) A2026–A2045).
 *
 * With known solutions r_1 … r_m, Newton's method is applied to
 *
 *     G(x) = M(x) F(x),   M(x) = Π_i ( ‖x − r_i‖_W^(−q) + σ ),
 *
 * which has the roots of F except the r_i (near r_i, G ~ F/‖x − r_i‖^q
 * does not vanish) and, for σ > 0, behaves like F far from them.  Its
 * Newton step is the undeflated step δ = −F_x⁻¹ F scaled (Sherman–Morrison
 * on F_x + F ∇log M^T, their Theorem 3.2 / eq. 3.4) by
 *
 *     τ = 1 / (1 − ∇(log M) · δ),
 *
 * so one factorisation of F_x per iteration suffices, dense (LAPACK) or
 * sparse (UMFPACK, when the system has a pattern and n > 400, or n > 64
 * with under a quarter of the entries nonzero).  The norm is
 * weighted, ‖v‖_W² = Σ (w_i v_i)², so that unknowns of different scales
 * (a displacement and a velocity, harmonic coefficients) count alike.
 *
 *     whirl_deflate *d = whirl_deflate_alloc(sys, NULL, err, sizeof err);
 *     whirl_deflate_add(d, r1);            // known solutions
 *     memcpy(x, start, n * sizeof *x);
 *     if (whirl_deflate_solve(d, x, p, &its) == WHIRL_OK)
 *       whirl_deflate_add(d, x);           // a new one
 *
 * The core of the discovery of unknown branches (doc/discovery.md).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DEFLATE_H
#define WHIRL_DEFLATE_H

#include <stddef.h>
#include <stdint.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_deflate_options {
  double power;        /* q of the deflation operator (default 2) */
  double shift;        /* σ (default 1) */
  double tol;          /* converged when ‖δ‖_∞ ≤ tol (1 + ‖x‖_∞) and
                          ‖F‖_∞ ≤ 1e3 tol (default 1e-10) */
  int maxit;           /* Newton iterations (default 50) */
  double max_step;     /* largest step in the weighted norm (default 0: none);
                          longer steps are shortened (damping) */
  double max_distance; /* abandon a start whose iterate is farther than this
                          (weighted) from it (default 1e3) */
  double min_distance; /* a solution closer than this (weighted) to a known
                          one is that one, not new (default 1e-6) */
  const double *weight; /* n weights w_i of the norm (copied), NULL: ones */
} whirl_deflate_options;

/* power 2, shift 1, tol 1e-10, maxit 50, no step limit, max_distance 1e3,
 * min_distance 1e-6, unit weights. */
WHIRL_API void whirl_deflate_options_default(whirl_deflate_options *o);

typedef struct whirl_deflate whirl_deflate;

/* sys is borrowed (it must outlive d), o copied (NULL: defaults).  NULL on
 * invalid options or out of memory, with the reason in err[len]. */
WHIRL_API whirl_deflate *whirl_deflate_alloc(const whirl_system *sys,
                                             const whirl_deflate_options *o,
                                             char *err, size_t len);
WHIRL_API void whirl_deflate_free(whirl_deflate *d); /* accepts NULL */

/* Add a known solution r[n] (copied): WHIRL_OK, WHIRL_ENOMEM. */
WHIRL_API int whirl_deflate_add(whirl_deflate *d, const double *r);
/* Forget all known solutions. */
WHIRL_API void whirl_deflate_clear(whirl_deflate *d);
WHIRL_API size_t whirl_deflate_count(const whirl_deflate *d);
WHIRL_API const double *whirl_deflate_root(const whirl_deflate *d, size_t i);

/* The weighted distance from x to the nearest known solution (INFINITY
 * when there is none); *which receives its index (may be NULL). */
WHIRL_API double whirl_deflate_nearest(const whirl_deflate *d, const double *x,
                                       size_t *which);

/* Add the solutions at the parameter value s through which a traced
 * branch passes: for every pair of consecutive points (q[k], x[k]),
 * (q[k+1], x[k+1]) of the branch (npts points, x[k * n + j] with n the
 * system's size) that brackets s, their linear interpolant polished by
 * Newton at p (p holding s), or kept as interpolated where Newton fails
 * (next to a fold); one within min_distance of a known solution is not
 * added again.  WHIRL_OK or WHIRL_ENOMEM. */
WHIRL_API int whirl_deflate_add_crossings(whirl_deflate *d, const double *q,
                                          const double *x, size_t npts,
                                          double s, const double *p);

/* Deflated Newton from x (in/out) at parameters p.  WHIRL_OK: x is a
 * solution at least min_distance from every known one (not added: the
 * caller decides); WHIRL_ENOCONV: no new solution from this start (no
 * convergence, divergence, or convergence onto a known solution);
 * WHIRL_EDOMAIN: the iterates left the model's domain; another code: a
 * fatal error of the callbacks or the solver (message in
 * whirl_deflate_errmsg).  *its (may be NULL) receives the iterations. */
WHIRL_API int whirl_deflate_solve(whirl_deflate *d, double *x, const double *p,
                                  int *its);

/* Plain Newton with the same solver, no deflation: polishing a point known
 * to be close to a solution.  Same returns (a known solution is accepted). */
WHIRL_API int whirl_deflate_polish(whirl_deflate *d, double *x, const double *p,
                                   int *its);

/* Totals since alloc: Newton iterations, factorisations, residuals. */
typedef struct whirl_deflate_stats {
  size_t solves, iterations, factorizations, f_evals;
} whirl_deflate_stats;
WHIRL_API const whirl_deflate_stats *whirl_deflate_get_stats(const whirl_deflate *d);

WHIRL_API const char *whirl_deflate_errmsg(const whirl_deflate *d);

/* A uniform number in [0, 1) from the generator state *s (splitmix64,
 * Steele, Lea & Flood 2014): the random starts of discovery, reproducible
 * from a seed (*s = seed) on every platform. */
WHIRL_API double whirl_random_uniform(uint64_t *s);

#ifdef __cplusplus
}
#endif
#endif

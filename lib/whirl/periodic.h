/* whirl/periodic.h — one interface to the discretisations of a periodic
 * orbit, harmonic balance (whirl/hbm.h) and orthogonal collocation
 * (whirl/colloc.h), so that a caller measuring or evaluating orbits does
 * not choose between them by hand: the unknowns, the period, the state at
 * scaled time τ ∈ [0, 1], the maximum of each component over the orbit and
 * AUTO's L2-NORM.  A whirl_periodic is a view: it borrows the object.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_PERIODIC_H
#define WHIRL_PERIODIC_H

#include <stddef.h>

#include <whirl/colloc.h>
#include <whirl/hbm.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_periodic_ops {
  const char *method; /* "hbm", "colloc" */
  size_t (*size)(const void *obj);
  double (*period)(const void *obj, const double *x, const double *p);
  int (*eval)(const void *obj, const double *x, double tau, double *u);
  int (*max)(const void *obj, const double *x, double *mx);
  double (*l2norm)(const void *obj, const double *x);
} whirl_periodic_ops;

typedef struct whirl_periodic {
  const whirl_periodic_ops *ops;
  const void *obj;
} whirl_periodic;

WHIRL_API whirl_periodic whirl_periodic_of_hbm(const whirl_hbm *h);
WHIRL_API whirl_periodic whirl_periodic_of_colloc(const whirl_colloc *c);

/* "hbm" or "colloc". */
WHIRL_API const char *whirl_periodic_method(const whirl_periodic *po);
/* The unknowns of the discretised orbit. */
WHIRL_API size_t whirl_periodic_size(const whirl_periodic *po);
/* The period of the orbit x at parameters p. */
WHIRL_API double whirl_periodic_period(const whirl_periodic *po, const double *x,
                                       const double *p);
/* The state u[n] at scaled time τ ∈ [0, 1] (τ = t / T). */
WHIRL_API int whirl_periodic_eval(const whirl_periodic *po, const double *x,
                                  double tau, double *u);
/* The maximum over the orbit of each component, mx[n]: the true maximum
 * of the discretised orbit (its polynomial or series), not of its nodes or
 * samples. */
WHIRL_API int whirl_periodic_max(const whirl_periodic *po, const double *x,
                                 double *mx);
/* AUTO's L2-NORM, sqrt(∫₀¹ |u(τ)|² dτ); NaN when out of memory. */
WHIRL_API double whirl_periodic_l2norm(const whirl_periodic *po, const double *x);

/* For collocation, the two measures on their own (also the ops above):
 * the maximum of each component of the collocation polynomial, sampled at
 * 8 points per node interval with every sample maximum refined by
 * golden-section search between its neighbours; the L2 norm by 5-point
 * Gauss-Legendre quadrature on each mesh interval. */
WHIRL_API int whirl_colloc_max(const whirl_colloc *c, const double *x, double *mx);
WHIRL_API double whirl_colloc_l2norm(const whirl_colloc *c, const double *x);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/periodic.h — one interface to the discretisations of a periodic
 * orbit, harmonic balance (whirl/hbm.h) and orthogonal collocation
 * (whirl/colloc.h), so that a caller measuring or evaluating orbits does
 * not choose between them by hand: the unknowns, the period, the state at
 * scaled time τ ∈ [0, 1], the orbit from samples, from harmonics or from
 * another discretisation, the discretisation saved and restored (a
 * collocation mesh), the Floquet multipliers, the maximum of each component
 * over the orbit and AUTO's L2-NORM.  A whirl_periodic is a view: it
 * borrows the object.
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
  size_t (*dim)(const void *obj); /* n, the model's state dimension */
  double (*period)(const void *obj, const double *x, const double *p);
  int (*eval)(const void *obj, const double *x, double tau, double *u);
  int (*from_samples)(void *obj, const double *u, size_t m, double T,
                      double *x);
  size_t (*naux)(const void *obj);
  int (*save)(const void *obj, double *aux);
  int (*restore)(void *obj, const double *aux, const double *x);
  int (*multipliers)(const void *obj, const double *x, const double *p,
                     double *re, double *im, size_t *m);
  int (*max)(const void *obj, const double *x, double *mx);
  double (*l2norm)(const void *obj, const double *x);
  const char *(*errmsg)(const void *obj);
} whirl_periodic_ops;

typedef struct whirl_periodic {
  const whirl_periodic_ops *ops;
  void *obj;
} whirl_periodic;

WHIRL_API whirl_periodic whirl_periodic_of_hbm(whirl_hbm *h);
WHIRL_API whirl_periodic whirl_periodic_of_colloc(whirl_colloc *c);

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
/* The model's state dimension n. */
WHIRL_API size_t whirl_periodic_dim(const whirl_periodic *po);
/* The orbit x[size] from m samples u[k*n + i] of one period T at
 * t_k = k T/m, k = 0..m−1 (no end point): harmonic balance by the
 * discrete Fourier transform, collocation by periodic interpolation onto
 * its mesh (whirl_hbm_from_samples, whirl_colloc_from_samples). */
WHIRL_API int whirl_periodic_from_samples(whirl_periodic *po, const double *u,
                                          size_t m, double T, double *x);
/* The orbit x[size] from nh harmonics of period T, c[n(2nh+1)]: the mean
 * c[i], then c[n(2k−1) + i] and c[n(2k) + i] the cosine and sine
 * coefficients of harmonic k, u_i(t) = c_i + Σ_k (a_ki cos kωt + b_ki sin
 * kωt), ω = 2π/T — sampled at 4 max(2nh + 1, size/n) points (the
 * finer of the series and the discretisation), then from_samples. */
WHIRL_API int whirl_periodic_from_harmonics(whirl_periodic *po, const double *c,
                                            size_t nh, double T, double *x);
/* The orbit xdst of dst from the orbit xsrc of src (any two
 * discretisations of the same model): src sampled at m points, then
 * from_samples into dst.  m = 0: 4 × the larger of the two sizes / n. */
WHIRL_API int whirl_periodic_convert(const whirl_periodic *src,
                                     const double *xsrc, const double *p,
                                     whirl_periodic *dst, size_t m,
                                     double *xdst);
/* What, beyond x, defines an orbit of this discretisation: naux values
 * (collocation: its mesh, NTST + 1 points; harmonic balance: none), saved
 * into aux[naux] with the object's current state; restore sets them back
 * before a restart from the stored x (collocation: the mesh, then the phase
 * reference from x).  Returns WHIRL_OK or WHIRL_EINVAL (a bad mesh). */
WHIRL_API size_t whirl_periodic_naux(const whirl_periodic *po);
WHIRL_API int whirl_periodic_save(const whirl_periodic *po, double *aux);
WHIRL_API int whirl_periodic_restore(whirl_periodic *po, const double *aux,
                                     const double *x);
/* The Floquet multipliers of the orbit x at p, re[*m], im[*m] (*m the
 * capacity on entry, at least n; the number written on return), computed
 * as the object's system computes its stability (its options). */
WHIRL_API int whirl_periodic_multipliers(const whirl_periodic *po,
                                         const double *x, const double *p,
                                         double *re, double *im, size_t *m);
/* The message of the last failure, with its origin; never NULL. */
WHIRL_API const char *whirl_periodic_errmsg(const whirl_periodic *po);
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
/* AUTO's measures of each component (its IPLT, its b-file's MAX): m1[i] =
 * ∫₀¹ u_i, m2[i] = ∫₀¹ u_i² (the quadrature of whirl_colloc_l2norm), mn[i]
 * and mx[i] the minimum and maximum over the NTST*NCOL+1 nodes.  WHIRL_OK
 * or WHIRL_ENOMEM. */
WHIRL_API int whirl_colloc_moments(const whirl_colloc *c, const double *x, double *m1,
                                   double *m2, double *mn, double *mx);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/rotor/sfd_region.h — where the SFD rotor has an isolated branch (paper §5.4,
 * Fig. 18), traced by two-parameter continuation of circular synchronous
 * orbits (rotating-frame equilibria, F_E = 0) with the fold system of
 * whirl/fold.h:
 *   - the merge curve: the isola-peak merge point (G = G_eps = G_Omega = 0
 *     of eq. 15; MG of the fold curve in (Omega, delta)) followed in lambda
 *     as a codimension-two curve (fold system with the MG condition);
 *   - the Omega = W fold locus: a fold of the response at Omega = W, followed
 *     in (lambda, delta) with Omega held fixed; its lower branch is the isola
 *     birth below the maximum speed, its upper branch the second fold there,
 *     and the two meet at a cusp (CP) at large lambda; the MG label on it
 *     marks the lambda where the merge point itself reaches Omega = W.
 * The isola exists below Omega = W for delta between the lower branch and
 * the merge curve, as long as the merge speed is <= W; where it reaches W
 * (MG on the lower curve) the two boundaries touch and the region ends
 * (doc/isola-region.md; checked against a brute-force grid in
 * test/bench/bench_region.c).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SFD_REGION_H
#define WHIRL_SFD_REGION_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A traced curve of circular orbits, one entry per continuation point. */
typedef struct whirl_sfd_curve {
  size_t len, cap;
  double *lambda, *delta, *Omega, *eps;
  double *res;  /* relative residual of the defining equations of eq. 15 */
  int *type;    /* whirl_point_type of the point (0 regular) */
} whirl_sfd_curve;

WHIRL_API void whirl_sfd_curve_free(whirl_sfd_curve *c); /* contents; NULL ok */

/* Relative residuals of eq. 15 at (eps, Omega) for (lambda, delta, zeta):
 * |G|, |G_eps| and |G_Omega| each divided by the sum of the magnitudes of
 * the terms they are made of (so 1e-16 is exact in double precision).  Any
 * output may be NULL. */
WHIRL_API int whirl_sfd_circ_residuals(double eps, double Omega, double lambda,
                                       double delta, double zeta, double *rG,
                                       double *rGe, double *rGO);

/* Every isola merge or isola-centre point at this lambda: solutions of
 * G = G_eps = G_Omega = 0, seeded from eq. 15 (delta eliminated: G_eps = 0,
 * Omega G_Omega = 4 G at delta = 0, on an (eps, Omega) grid) and converged
 * on the rotating-frame equations by Newton on the fold system with the MG
 * condition.  out receives them by increasing delta (type MG or IS). */
WHIRL_API int whirl_sfd_merge_points(double lambda, double zeta,
                                     whirl_sfd_curve *out, char *errbuf,
                                     size_t errlen);

typedef struct whirl_sfd_region_options {
  double zeta;                   /* default 0 */
  double omega_max;              /* W, default 20 */
  double lambda_min, lambda_max; /* default 0.01, 1.5 */
  double ds_max;                 /* default 0.05 (in the arclength norm) */
  size_t nmx;                    /* per curve and direction, default 5000 */
} whirl_sfd_region_options;

WHIRL_API void whirl_sfd_region_options_default(whirl_sfd_region_options *o);

typedef struct whirl_sfd_region {
  whirl_sfd_curve upper; /* merge curve (MG/IS followed in lambda) */
  whirl_sfd_curve lower; /* fold locus at Omega = W (both branches) */
  double max_res_upper, max_res_lower;
  size_t steps, newton_its;
  /* where the merge speed reaches W (MG on the lower curve) and where the
   * two branches of the Omega = W locus meet (CP); NaN if not reached */
  double lambda_m, delta_m, lambda_c, delta_c;
} whirl_sfd_region;

WHIRL_API int whirl_sfd_region_compute(const whirl_sfd_region_options *o,
                                       whirl_sfd_region *r, char *errbuf,
                                       size_t errlen);
WHIRL_API void whirl_sfd_region_free(whirl_sfd_region *r);

/* The delta interval (lo, hi) with an isolated branch below Omega = W at
 * this lambda, from the traced curves by linear interpolation; returns 1
 * if the interval is non-empty, else 0. */
WHIRL_API int whirl_sfd_region_band(const whirl_sfd_region *r, double lambda,
                                    double omega_max, double *lo, double *hi);

#ifdef __cplusplus
}
#endif
#endif

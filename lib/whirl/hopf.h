/* whirl/hopf.h — constructor: the Hopf curve of an equilibrium problem as a
 * new whirl_system, by minimal augmentation with the squared Jacobian
 * (Govaerts 2000, ch. 4.4; Govaerts, Guckenheimer & Khibnik 1997).
 *
 * At a Hopf point F_x has eigenvalues +-i omega, so A = F_x^2 + kappa I with
 * kappa = omega^2 has a two-dimensional null space.  With borders B, C (n x 2)
 *     [A B; C^T 0] [V; G] = [0; I_2]
 * defines the 2 x 2 matrix G(x, p, kappa), zero at a Hopf point; two of its
 * entries, chosen at the start for the best conditioning, are the extra
 * equations.  Unknowns (x, p[par], kappa); the core continues the curve in
 * its ICP.  kappa < 0 continues the curve through neutral saddles (real pair
 * +-sqrt(-kappa)).  Test functions (whirl_system.test):
 *   BT  kappa = 0: the pair meets at zero (Bogdanov-Takens);
 *   ZH  a real eigenvalue other than the pair crosses zero (zero-Hopf).
 * The Jacobian is left to the core's finite differences of the exactly
 * evaluated residual.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_HOPF_H
#define WHIRL_HOPF_H

#include <stddef.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Test functions: BT (kappa = omega^2 through 0), ZH (a real eigenvalue
 * through 0), GH (the first Lyapunov coefficient through 0); on a map's
 * Neimark-Sacker curve, kappa = 2 (1 - cos theta) through 0, 4, 3, 2: the
 * strong resonances R1, R2, R3, R4 (AUTO's, which its hen demo stops at). */
enum { WHIRL_HOPF_TEST_BT = 0, WHIRL_HOPF_TEST_ZH = 1, WHIRL_HOPF_TEST_GH = 2,
       WHIRL_HOPF_TEST_R1 = 3, WHIRL_HOPF_TEST_R2 = 4, WHIRL_HOPF_TEST_R3 = 5,
       WHIRL_HOPF_TEST_R4 = 6, WHIRL_HOPF_NTEST = 7 };

typedef struct whirl_hopf whirl_hopf;

/* par: the parameter freed as an unknown (the one in which the Hopf point was
 * found).  NULL on bad arguments or out of memory, message in errbuf. */
WHIRL_API whirl_hopf *whirl_hopf_alloc(const whirl_system *base, size_t par,
                                       char *errbuf, size_t errlen);
WHIRL_API void whirl_hopf_free(whirl_hopf *h); /* accepts NULL */

/* The Neimark–Sacker (torus, TR) points of a map's fixed points, base
 * from whirl_map_fixed_points_alloc (F = f − x): the same system on
 * F_x^2 + kappa (F_x + I), kappa = 2 (1 − cos θ) for the multipliers
 * e^{±iθ}; no codimension-two tests yet.  whirl_hopf_init starts it at a
 * TR point. */
WHIRL_API whirl_hopf *whirl_hopf_alloc_map(const whirl_system *base, size_t par,
                                           char *errbuf, size_t errlen);
WHIRL_API const whirl_system *whirl_hopf_system(const whirl_hopf *h);
WHIRL_API size_t whirl_hopf_size(const whirl_hopf *h); /* n + 2 */

/* Start from a (localised) Hopf point (x, p) of the base: omega from the
 * complex pair of F_x nearest the imaginary axis, borders from the null
 * space of F_x^2 + omega^2 I; fills Z[n + 2] = (x, p[par], omega^2). */
WHIRL_API int whirl_hopf_init(whirl_hopf *h, const double *x, const double *p,
                              double *Z);

/* Copy p with p[par] = Z[n]. */
WHIRL_API void whirl_hopf_params(const whirl_hopf *h, const double *Z,
                                 const double *p, double *pfull);
WHIRL_API const char *whirl_hopf_errmsg(const whirl_hopf *h);

#ifdef __cplusplus
}
#endif
#endif

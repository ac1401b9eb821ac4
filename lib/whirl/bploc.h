/* whirl/bploc.h — constructor: the locus of branch points of equilibria
 * F(x, p) = 0 in more parameters (AUTO's ISW = 2 at a BP of a non-generic,
 * symmetric system, ISW = 3 at a BP of a generic one).
 *
 * A branch point in the parameter q is a solution where [F_x F_q] loses
 * rank: a left null vector psi with psi^T F_x = 0 and psi^T F_q = 0.  The
 * locus solves, in the unknowns Z = (x, psi, p_q, s),
 *   F(x, p) + beta psi = 0,  F_x^T psi = 0,  psi^T F_q = 0,  psi^T psi = 1,
 * 2n + 2 equations, with the core's continuation parameter appended:
 *  - generic (ISW = 3): beta = 0 and s a further parameter; the branch
 *    points of a generic system form a curve in three parameters (q, the
 *    continued one and s);
 *  - non-generic (ISW = 2): s = beta, an unfolding unknown that the
 *    symmetry keeps at 0 and that makes the system regular where the
 *    symmetry puts F_q, for every q, in the range of F_x (Doedel, Keller &
 *    Kernevez, Int. J. Bifurcation and Chaos 1 (1991) 493; Govaerts,
 *    Numerical Methods for Bifurcations of Dynamical Equilibria, SIAM 2000,
 *    ch. 5): the curve is in two parameters.
 * Dense (F_x of the base, n small); no test functions.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_BPLOC_H
#define WHIRL_BPLOC_H

#include <stddef.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_bploc whirl_bploc;

/* q: the parameter in which the base branch has its BP; extra: the third
 * parameter of a generic locus (ignored when !generic).  base is copied
 * (its data stays borrowed).  NULL on bad arguments or out of memory, the
 * message in errbuf. */
WHIRL_API whirl_bploc *whirl_bploc_alloc(const whirl_system *base, size_t q, int generic,
                                         size_t extra, char *errbuf, size_t errlen);
WHIRL_API void whirl_bploc_free(whirl_bploc *b); /* accepts NULL */
WHIRL_API const whirl_system *whirl_bploc_system(const whirl_bploc *b);
WHIRL_API size_t whirl_bploc_size(const whirl_bploc *b); /* 2 n + 2 */
WHIRL_API const char *whirl_bploc_errmsg(const whirl_bploc *b);

/* Start at a (localised) branch point (x, p) of the base: psi the left
 * null vector of F_x (SVD), beta = 0; fills Z[2n + 2]. */
WHIRL_API int whirl_bploc_init(whirl_bploc *b, const double *x, const double *p, double *Z);

/* Copy p with p[q] (and a generic locus's p[extra]) taken from Z. */
WHIRL_API void whirl_bploc_params(const whirl_bploc *b, const double *Z, const double *p,
                                  double *pfull);

#ifdef __cplusplus
}
#endif
#endif

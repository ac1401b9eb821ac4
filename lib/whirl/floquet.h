/* whirl/floquet.h — Floquet multipliers of a periodic orbit from its
 * monodromy matrix (variational equations, paper eq. 24), shared by every
 * discretisation of periodic orbits (harmonic balance, collocation): the
 * stability of a cycle is judged by the same route whatever produced it.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_FLOQUET_H
#define WHIRL_FLOQUET_H

#include <stddef.h>
#include <whirl/problem.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Multipliers of the orbit through x0[n] at time t0 with period T of the
 * model prob at parameters p: the eigenvalues of M = Φ(t0 + T) (LAPACK
 * dgeev), sorted by decreasing modulus into re[], im[].  With drop_trivial
 * (autonomous orbits) the multiplier nearest to 1 is left out, so *m = n - 1,
 * otherwise *m = n.  On entry *m is the capacity.  M (may be NULL) receives
 * the monodromy matrix (n*n, column-major); *trivial (may be NULL) the
 * distance |mu - 1| of the dropped multiplier, a check on the accuracy of the
 * orbit: with drop_trivial, when no eigenvalue of M lies within 0.1 of 1, M
 * is too inaccurate for any of its multipliers (an orbit near a homoclinic
 * loop, whose M has entries like e^{λT}) and WHIRL_ESINGULAR is returned:
 * its stability is unknown.  rtol, atol: integrator tolerances (<= 0:
 * 1e-11, 1e-13).  Returns WHIRL_OK or an error with the message in errbuf. */
WHIRL_API int whirl_floquet_multipliers(const whirl_problem *prob,
                                        const double *p, double t0,
                                        const double *x0, double T,
                                        int drop_trivial, double rtol,
                                        double atol, double *re, double *im,
                                        size_t *m, double *M, double *trivial,
                                        char *errbuf, size_t errlen);

/* The same multipliers from a monodromy matrix M[n*n] (column-major)
 * obtained otherwise, e.g. from the condensed collocation equations
 * (AUTO-07p): x0 is the orbit at t0 and xT its end after one period (equal
 * to x0 for a closed orbit), used by the Poincaré map when drop_trivial.
 * *m on entry the capacity; *trivial (may be NULL) and WHIRL_ESINGULAR as
 * above. */
WHIRL_API int whirl_floquet_from_monodromy(const whirl_problem *prob,
                                           const double *p, double t0,
                                           const double *x0, const double *xT,
                                           const double *M, int drop_trivial,
                                           double *re, double *im, size_t *m,
                                           double *trivial);

/* Unit eigenvector v[n] of M[n*n] for a real eigenvalue mu (the direction of
 * branch switching at a period doubling, mu = -1): the right singular vector
 * of M - mu I with the smallest singular value. */
WHIRL_API int whirl_floquet_real_eigvec(size_t n, const double *M, double mu,
                                        double *v);

#ifdef __cplusplus
}
#endif
#endif

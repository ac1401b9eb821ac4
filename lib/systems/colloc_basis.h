/* lib/systems/colloc_basis.h — private to lib/systems: the piecewise
 * polynomial basis shared by the collocation constructors (periodic orbits,
 * colloc.c; boundary value problems, bvp.c): Gauss–Legendre points and
 * weights on [0, 1], the Lagrange basis on NCOL + 1 equally spaced nodes of
 * an interval, and the evaluation of a piecewise polynomial given by its
 * node values on a mesh.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_COLLOC_BASIS_H
#define WHIRL_COLLOC_BASIS_H

#include <stddef.h>

/* Largest NCOL of the basis (the fixed-size scratch below). */
#define COLLOC_BASIS_MAXCOL 7

/* The Legendre polynomial P_m(z) (into *pm, by the three-term recurrence);
 * returns its derivative P_m'(z) (z != ±1). */
double colloc_basis_legendre(size_t m, double z, double *pm);

/* Gauss–Legendre points s[m] (increasing) and weights w[m] on [0, 1]. */
void colloc_basis_gauss_legendre(size_t m, double *s, double *w);

/* Lagrange basis on the nodes k/m, k = 0..m, at σ: l[k] = l_k(σ) and, if
 * dl is not NULL, dl[k] = l_k'(σ).  m <= COLLOC_BASIS_MAXCOL. */
void colloc_basis_lagrange(size_t m, double sigma, double *l, double *dl);

/* The values alone of that basis at σ, in O(m). */
void colloc_basis_lagrange_values(size_t m, double sigma, double *l);

/* Interval of the mesh tau[0..ntst] containing t ∈ [0, 1] (bisection). */
size_t colloc_basis_find_interval(const double *tau, size_t ntst, double t);

/* The piecewise polynomial with mesh tau[ntst + 1], degree m and node
 * values Xn (node-major, n each, ntst*m + 1 nodes) at t, wrapped
 * periodically into [0, 1]: x[n]. */
void colloc_basis_eval_poly(size_t n, size_t ntst, size_t m,
                            const double *tau, const double *Xn, double t,
                            double *x);

#endif

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

/* The quadrature weights of the node values of a piecewise polynomial of
 * degree m on mesh[ntst + 1] (ntst m + 1 nodes, n components each,
 * node-major): q[n (ntst m + 1)] with sum_j q_j x_j^2 = int_0^1 |x|^2 dt
 * over the node values squared, h_i W_k on node k of interval i (the
 * shared mesh points summed), W_k = int_0^1 l_k the closed Newton-Cotes
 * weights of the nodes k/m: the norm of AUTO-07p's steps (mesh.f90,
 * WINT and RNRMSQ). */
void colloc_basis_node_weights(size_t n, size_t m, size_t ntst, const double *mesh,
                               double *q);
/* The same in two parts: W[m + 1] = int_0^1 l_k (once per NCOL), then
 * the weights of a mesh from them (the same arithmetic). */
void colloc_basis_lagrange_integrals(size_t m, double *W);
void colloc_basis_node_weights_from(size_t n, size_t m, size_t ntst,
                                    const double *mesh, const double *W,
                                    double *q);

/* The weights dm[m + 1] of the m-th derivative in σ of the interpolant on
 * the nodes k/m: m^m (−1)^{m−k} C(m, k) (the m-th forward difference). */
void colloc_basis_derivative_weights(size_t m, double *dm);

/* Mesh adaptation (AUTO's IAD; de Boor 1973): the new mesh[N + 1] that
 * equidistributes the error density sum_r |x_r^(m)|^{1/(m+1)} of the
 * piecewise polynomial with node values X (n components, node-major) on
 * old[N + 1], x^(m) piecewise constant from dm; scratch E[N], Q[N + 1].
 * 1: a new mesh; 0: a constant solution (mesh = old); -1 - i: interval i
 * is not finite; -1 - N - k: interval k of the new mesh degenerate. */
int colloc_basis_new_mesh(size_t n, size_t m, size_t N, const double *dm,
                          const double *X, const double *old, double *mesh,
                          double *E, double *Q);

/* AUTO-07p's IAD for boundary-value problems (its manual; Russell &
 * Christiansen 1978): the same with the density sum_r |x_r^(m+1)|^{1/(m+1)},
 * x^(m+1) on interval i estimated by the jump of the piecewise constant
 * x^(m) to interval i + 1 over the distance of their midpoints, on the last
 * interval by the jump from the one before over its own length (one-sided:
 * a symmetric solution gets AUTO's asymmetric mesh); periodic: the last
 * interval takes the jump to the first over their mean length instead
 * (AUTO's EQDF with IPER, for orbits).  When every |x^(m)| <= 1e-7 the
 * mesh is kept (0).  Scratch D[n N]. */
int colloc_basis_new_mesh_jumps(size_t n, size_t m, size_t N, int periodic,
                                const double *dm, const double *X, const double *old,
                                double *mesh, double *E, double *Q, double *D);

/* The same from the solution X on old (N intervals of degree m) to a mesh
 * of Nnew intervals (AUTO-07p's NEWMSH in ADAPT2, a restart on another
 * NTST or NCOL, or from data: m = 1): mesh[Nnew + 1]; when the density
 * vanishes the uniform mesh (0). */
int colloc_basis_mesh_from_jumps(size_t n, size_t m, size_t N, int periodic,
                                 const double *dm, const double *X, const double *old,
                                 size_t Nnew, double *mesh, double *E, double *Q,
                                 double *D);

/* AUTO's ADAPT2 mesh for a restart (colloc_basis_mesh_from_jumps) with the
 * checks and scratch of its own: mesh[Nnew + 1] from Xold, n components
 * on nold intervals of degree mold over old.  0, or WHIRL_EINVAL (bad
 * sizes, old not increasing from 0 to 1, Xold not finite) or WHIRL_ENOMEM
 * with what went wrong in why[len]. */
int colloc_basis_adapt_mesh(size_t n, size_t mold, size_t nold, int periodic, const double *old,
                            const double *Xold, size_t Nnew, double *mesh, char *why,
                            size_t len);

/* The node values of v (a solution or a direction: the map is linear)
 * from the piecewise polynomial on old to the nodes of mesh, in place;
 * scratch copy[(N m + 1) n].  Entries past the nodes are not touched. */
void colloc_basis_map_nodes(size_t n, size_t m, size_t N, const double *old,
                            const double *mesh, double *copy, double *v);

/* The same map as a plan for several vectors: for each of the N m + 1
 * nodes j of mesh its interval idx[j] on old and the Lagrange values
 * L[j (m + 1) + k] there (the arithmetic of colloc_basis_eval_poly), then
 * applied to one vector in place (scratch copy[(N m + 1) n]): the same
 * bytes as colloc_basis_map_nodes, the search and the basis once. */
void colloc_basis_map_plan(size_t m, size_t N, const double *old, const double *mesh,
                           size_t *idx, double *L);
void colloc_basis_map_apply(size_t n, size_t m, size_t N, const size_t *idx,
                            const double *L, double *copy, double *v);
/* colloc_basis_map_apply on each of the nv vectors v[k] and the nw
 * vectors w[k], on up to nth threads (OpenMP), thread t's scratch copies
 * + t (N m + 1) n: the same bytes as one after the other (a mesh
 * adaptation carries the point, its tangent, earlier points and the
 * references: seven vectors of fnc's 2 001 nodes, a serial 4 % of its
 * run on one thread). */
void colloc_basis_map_many(size_t n, size_t m, size_t N, const size_t *idx,
                           const double *L, double *copies, double *const *v,
                           size_t nv, double *const *w, size_t nw, int nth);

#endif

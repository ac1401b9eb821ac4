/* lib/systems/twist_elim.h — private to lib/systems: the structured
 * elimination of a collocation orbit's variational operator with the
 * twisted boundary condition,
 *     A(θ) v = 0:  collocation rows (real, interval by interval),
 *                  B0(θ) v(0) + BN v(1) = 0  (the boundary rows),
 * as AUTO-07p's condensation of parameters does its BVPs (Doedel, "Finite
 * difference collocation methods for nonlinear two point boundary value
 * problems", SIAM J. Numer. Anal. 16 (1979) 173; AUTO-07p's solvbv.f90,
 * CONPAR and REDUCE): each interval's interior nodes eliminated by its own
 * block (row pivoting), then the mesh nodes v(1) .. v(N−1) one after the
 * other over the pairs of rows that hold them (row pivoting again), which
 * leaves n rows in v(0) and v(N); those and the boundary rows, v(N)
 * eliminated, leave the n × n reduced matrix S(θ).  Every row operation is
 * real; only B0(θ) is complex, so S(θ) = P' + B0'(θ) costs nothing per
 * angle once the real part is factored.  Stable where the monodromy
 * matrix (shooting) is not: long periods multiply the multipliers'
 * spread, pivoted elimination over the mesh does not (Ascher, Mattheij &
 * Russell, "Numerical solution of boundary value problems for ODEs",
 * SIAM 1995, §7.3).
 *
 * With the row operations Q (real, invertible), Q A(θ) = [U11 U12; 0 S(θ)]
 * in the order (interior and mesh nodes, v(N) | v(0)):
 *   - A(θ) v = 0  ⇔  S(θ) v(0) = 0 and the rest by back substitution;
 *   - A(θ)^H w = 0 ⇔ w = Q^T (0; w0) with S(θ)^H w0 = 0.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_TWIST_ELIM_H
#define WHIRL_TWIST_ELIM_H

#include <stddef.h>

typedef struct twist_elim twist_elim;

/* n states, ntst >= 1 intervals of ncol >= 1 collocation points.  NULL
 * when out of memory. */
twist_elim *twist_alloc(size_t n, size_t ntst, size_t ncol);
void twist_free(twist_elim *e); /* accepts NULL */

/* Interval i's block to fill before twist_factor: n ncol rows (the
 * interval's collocation rows in order), column-major with leading
 * dimension n ncol, its columns the interval's nodes in order, u at node
 * i ncol + l in columns l n .. l n + n − 1 (l = 0 .. ncol). */
double *twist_block(twist_elim *e, size_t i);
/* BN, the boundary rows' n × n block in v(1), column-major, to fill. */
double *twist_bn(twist_elim *e);

/* The real row operations: the intervals, the mesh chain and the
 * elimination of v(N) by the boundary rows.  0, or -1 for a zero pivot
 * (the collocation rows are singular without the boundary rows). */
int twist_factor(twist_elim *e);

/* S(θ) (n × n, column-major, re and im) for the boundary rows' block in
 * v(0), B0 = b0r + i b0i (column-major n × n), after twist_factor. */
void twist_reduce(twist_elim *e, const double *b0r, const double *b0i, double *sr,
                  double *si);

/* v on every node (node-major, n (ntst ncol + 1) values, re and im) from
 * v(0) = (v0r, v0i), as the factored rows determine it (the b0 of the last
 * twist_reduce). */
void twist_right(twist_elim *e, const double *v0r, const double *v0i, double *vr, double *vi);

/* w on every row (the collocation rows in order, then the n boundary
 * rows; re and im) as Q^T (0; w0), w0 = (w0r, w0i) the left null vector
 * of S(θ): A(θ)^H w = 0 where S(θ)^H w0 = 0. */
void twist_left(twist_elim *e, const double *w0r, const double *w0i, double *wr, double *wi);

#endif

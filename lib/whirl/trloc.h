/* whirl/trloc.h — constructor: the torus (Neimark–Sacker) locus of periodic
 * orbits as a new whirl_system, by complex minimal augmentation (Doedel,
 * Govaerts & Kuznetsov, "Computation of periodic solution bifurcations in
 * ODEs using bordered systems", SIAM J. Numer. Anal. 41 (2003) 401, §5;
 * AUTO-07p's ISW = 2 at a TR of orbits).
 *
 * The base is an orbit's system (collocation) and A(θ) the operator of the
 * orbit's variational equation with the boundary condition v(1) = e^{iθ}
 * v(0) in place of periodicity: the leading na × na block of F_x (the node
 * values' rows and columns) whose entries (ei[k], ej[k]) — the −1 of v(0)
 * in the boundary rows — become −e^{iθ}.  A(θ) is singular exactly when
 * e^{iθ} is a Floquet multiplier of the orbit.  A(θ) is eliminated by the
 * orbit's structure, interval by interval and mesh node by mesh node with
 * row pivoting in real arithmetic (AUTO-07p's condensation of
 * parameters), to an n × n complex block S(θ) on u(0), singular exactly
 * where A(θ) is.  With complex n-vectors b, c the bordered matrix
 * K = [S(θ) b; c^H 0] is regular at a simple pair, and
 *     K [v0; g] = [0; 1],   K^H [w0; h] = [0; 1]
 * define g ∈ ℂ, zero exactly there; v and w, the null vectors of A(θ) and
 * A(θ)^H on the whole mesh, follow from v0 and w0 by back substitution and
 * the transposed row operations.  The torus system is
 *     F(x, p) = 0,  Re g = 0,  Im g = 0
 * in the unknowns (x, p[par], θ), continued by the core in a further
 * parameter; its Jacobian rows are g_z = −w^H A_z v (four base Jacobians
 * at x ± h Re v, x ± h Im v) and g_θ = −w^H A_θ v.  The borders follow
 * the null vectors at every accepted point.  The locus adapts the base's
 * mesh and measures steps by the base's norm weights.
 * θ = π is a period doubling: the same operator as the period-doubling
 * locus (whirl_colloc_pd_operator) at e^{iπ} = −1.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_TRLOC_H
#define WHIRL_TRLOC_H

#include <stddef.h>
#include <whirl/fold.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_trloc whirl_trloc;

/* base (copied; its data stays borrowed) must have a sparse Jacobian
 * (pattern and Fx_sparse).  op: the period-doubling operator of the base
 * (whirl_colloc_pd_operator): na, its collocation structure (nstate,
 * ntst, ncol), and the entries whose constant ev[k] turns −1 into +1 at
 * θ = π; here they carry (1 − e^{iθ}) ev[k]/2.
 * par: the parameter freed as an unknown (the label's own).  par2 = −1:
 * the angle θ is the last unknown; else θ stays at its start value and
 * the parameter par2 is the last unknown (AUTO's TR locus "fixing the
 * angle", a third free parameter).  NULL on bad arguments or out of
 * memory, with a message in errbuf. */
WHIRL_API whirl_trloc *whirl_trloc_alloc(const whirl_system *base,
                                         const whirl_fold_operator *op,
                                         size_t par, long par2, char *errbuf,
                                         size_t errlen);
WHIRL_API void whirl_trloc_free(whirl_trloc *t); /* accepts NULL */

/* The torus system: n + 2 unknowns (x, p[par], θ or p[par2]), the base's
 * parameters (p[par], p[par2] are read from the unknowns). */
WHIRL_API const whirl_system *whirl_trloc_system(const whirl_trloc *t);
WHIRL_API size_t whirl_trloc_size(const whirl_trloc *t);

/* Start at a torus point (x, p) of the base whose multipliers include
 * e^{±iθ} (θ in (0, π)): the borders from inverse iteration on A(θ) and
 * A(θ)^H, Z[n + 2] = (x, p[par], θ or p[par2]).  WHIRL_OK, or an error with the
 * message in whirl_trloc_errmsg. */
WHIRL_API int whirl_trloc_init(whirl_trloc *t, const double *x,
                               const double *p, double theta, double *Z);

/* The base's parameters at Z (p with p[par] from Z); pfull may be p. */
WHIRL_API void whirl_trloc_params(const whirl_trloc *t, const double *Z,
                                  const double *p, double *pfull);
/* g = (Re g, Im g) at Z (the residual of the torus condition). */
WHIRL_API int whirl_trloc_g(whirl_trloc *t, const double *Z, const double *p,
                            double *g);
WHIRL_API const char *whirl_trloc_errmsg(const whirl_trloc *t);

#ifdef __cplusplus
}
#endif
#endif

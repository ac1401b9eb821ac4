/* whirl/equilibrium.h — constructor: the equilibria f(x, p) = 0 of an
 * autonomous ODE model as an algebraic problem, with the eigenvalues of the
 * Jacobian as its stability spectrum (so the core detects Hopf points).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_EQUILIBRIUM_H
#define WHIRL_EQUILIBRIUM_H

#include <whirl/problem.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_equilibrium whirl_equilibrium;

/* prob is borrowed and must outlive the object; t is fixed at 0 for
 * non-autonomous models.  NULL on out of memory or a bad model. */
WHIRL_API whirl_equilibrium *whirl_equilibrium_alloc(const whirl_problem *prob);
WHIRL_API void whirl_equilibrium_free(whirl_equilibrium *eq); /* NULL ok */

/* The fixed points x = f(x, p) of the map whose image prob->rhs returns
 * (prob->jac_x its derivative, or differences): F = f − x, with the
 * eigenvalues of f_x as the spectrum, kind WHIRL_SPEC_MULTIPLIERS (the
 * core finds LP at a multiplier +1, PD at −1, TR at a complex pair on the
 * unit circle).  Freed by whirl_equilibrium_free. */
WHIRL_API whirl_equilibrium *whirl_map_fixed_points_alloc(const whirl_problem *prob);

/* The same for the k-th iterate f^k (k >= 1): the points of period k of
 * the map (F = f^k − x, F_x by the chain rule, F_p by differences), the
 * branch born at a PD of period k / 2.  NULL for k < 1. */
WHIRL_API whirl_equilibrium *whirl_map_iterate_fixed_points_alloc(const whirl_problem *prob,
                                                                  int k);

/* The algebraic problem; owned by eq. */
WHIRL_API const whirl_system *whirl_equilibrium_system(
    const whirl_equilibrium *eq);

/* The message of the system's last failure (the eigenvalues of its
 * spectrum), with its origin "(equilibrium.c:N)".  Never NULL. */
WHIRL_API const char *whirl_equilibrium_errmsg(const whirl_equilibrium *eq);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/rotor/fe_ode.h — a finite-element rotor (whirl/rotor/fe.h) in
 * first-order form for time integration (whirl/ode.h): the state
 * z = (q, q'), 2 ndof components, and
 *
 *   q'' = M_eff⁻¹ [ f0 + s Ω² (u_c cos Ωt + u_s sin Ωt) − (C + Ω G) q'
 *                   − K q + Σ_e P_eᵀ f_e(r_e, r_e', 0, Ω) ] ,
 *   M_eff = M − Σ_e P_eᵀ Ja_e P_e ,
 *
 * the parameters p[WHIRL_FE_NPAR] those of whirl/rotor/fe_hbm.h (Ω, the
 * unbalance scale s, the clearance and viscosity scales of the film
 * elements; whirl_fe_hbm_params sets the defaults).  Fluid inertia: the
 * force of a WHIRL_FE_SFD_INERTIA element is affine in the acceleration,
 * f_e(r, v, a) = f_e(r, v, 0) + Ja_e(r) a, so its added mass is moved to
 * the left-hand side at each evaluation, exactly.  M is factored once
 * (sparse LU, UMFPACK); M_eff⁻¹ by the Sherman–Morrison–Woodbury identity
 *   M_eff⁻¹ x = M⁻¹ x + W (I − Ja_S W_S)⁻¹ Ja_S (M⁻¹ x)_S ,
 * W = M⁻¹ E (E the columns of the m nonlinear DOFs S, W_S its rows S, Ja_S
 * the assembled Ja on S): one m×m dense solve per evaluation.
 *
 * The Jacobian is analytic (implicit differentiation of M_eff q'' = R):
 *   ∂q''/∂q  = M_eff⁻¹ (−K + E Jr_S Eᵀ),
 *   ∂q''/∂q' = M_eff⁻¹ (−(C + Ω G) + E Jv_S Eᵀ),
 * Jr, Jv of the elements at the actual acceleration; M⁻¹K, M⁻¹C, M⁻¹G are
 * computed once (dense, ndof² each) at the first Jacobian.  It is dense:
 * M⁻¹ of a consistent beam mass is a full matrix, so ∂q''/∂q is full
 * whatever the sparsity of K (see doc/rotor-time.md for the choice).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_ODE_H
#define WHIRL_ROTOR_FE_ODE_H

#include <stddef.h>
#include <whirl/ode.h>
#include <whirl/problem.h>
#include <whirl/rotor/fe.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_fe_ode whirl_fe_ode;

/* r is borrowed and must outlive the object.  NULL on a singular mass
 * matrix, bad elements or no memory (message in errbuf). */
WHIRL_API whirl_fe_ode *whirl_fe_ode_alloc(const whirl_fe_rotor *r,
                                           char *errbuf, size_t errlen);
WHIRL_API void whirl_fe_ode_free(whirl_fe_ode *m); /* accepts NULL */

/* The model: n = 2 ndof, npar = WHIRL_FE_NPAR, rhs and the dense jac_x
 * (jac_p by finite differences), non-autonomous.  Its rhs returns 1
 * (recoverable) when a journal reaches a film's clearance. */
WHIRL_API const whirl_problem *whirl_fe_ode_problem(const whirl_fe_ode *m);

/* The Jacobian's values in compressed columns for
 * whirl_ode_set_sparse_jacobian: the pattern of the structural non-zeros
 * (the identity block, the non-zeros of M⁻¹K, M⁻¹(C, G) and of the
 * element columns), fill = the analytic Jacobian above.  Sets it on ode.
 * Worth it only when M⁻¹ is sparse (a lumped, diagonal mass). */
WHIRL_API int whirl_fe_ode_use_sparse(whirl_fe_ode *m, whirl_ode *ode);

/* BDF with the mass matrix on the left (whirl_ode_set_mass_matrix): sets
 * on ode the sparse G = diag(I, M) f_x (the assembled K, C, G and the
 * element Jacobians, no M⁻¹) and B = diag(I, M); CVODE's Newton systems
 * (B − γ G) δ = B r are then banded and solved by KLU in O(ndof).  The way
 * to integrate fine meshes.  Exact Newton without fluid inertia; with it
 * the added mass is left out of B (a modified Newton iteration; the
 * solution is the same).  WHIRL_OK or an error with the message. */
WHIRL_API int whirl_fe_ode_use_mass(whirl_fe_ode *m, whirl_ode *ode);

/* The last failure's message ("" if none). */
WHIRL_API const char *whirl_fe_ode_errmsg(const whirl_fe_ode *m);

#ifdef __cplusplus
}
#endif
#endif

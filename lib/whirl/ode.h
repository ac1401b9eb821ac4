/* whirl/ode.h — time integration of a model x' = f(t, x, p): explicit
 * Dormand–Prince 5(4) (Dormand & Prince 1980; Hairer, Nørsett & Wanner,
 * Solving ODEs I, §II.5 and §II.6) with local extrapolation, first-same-as-
 * last, PI step-size control, 4th-order dense output, event location on the
 * dense output, and the variational equations (paper eq. 24) for monodromy
 * matrices.
 *
 * Error control as MATLAB's ode45 (the paper's tool): a step is accepted when
 *   max_i |e_i| / max(atol, rtol * max(|x_i(t)|, |x_i(t+h)|)) <= 1,
 * e the difference of the 5th- and 4th-order solutions.  Defaults rtol 1e-12,
 * atol 1e-15 (paper §4.3).
 *
 * Callbacks follow problem.h: > 0 (or a non-finite value) is recoverable —
 * the step is rejected and retried with h/4; < 0 is fatal (WHIRL_EUSER).
 * If h falls below h_min the integrator stops with WHIRL_ESTEP and
 * whirl_ode_last_rhs_status() tells what the right-hand side last said
 * (e.g. WHIRL_SFD_CONTACT; WHIRL_EBADFUNC if it returned 0 with a NaN or
 * Inf; 0 if it was the error test that failed).  A recoverable failure at
 * the current point itself (first evaluation after a reset) is WHIRL_ESTEP
 * at once.  After any error the integrator stays at its last accepted
 * point and can go on (e.g. with other settings or after a reset).
 * Implementation: lib/ode/dopri.c; variational equations:
 * lib/ode/variational.c.  No global state: integrators may run in parallel
 * threads (one object per thread).
 *
 * Stiff problems: whirl_ode_set_method(ode, WHIRL_ODE_BDF) switches the
 * object to the variable-order (1..5) BDF formulas of SUNDIALS CVODE with
 * Newton iteration (Hindmarsh et al., ACM TOMS 31 (2005) 363; CVODE user
 * guide), lib/ode/bdf.c.  Its linear systems (I − γ f_x) use CVODE's dense
 * LU with the model's jac_x (CVODE's difference quotients when NULL),
 * or KLU sparse LU with a Jacobian given by whirl_ode_set_sparse_jacobian
 * (with a mass matrix on the left, whirl_ode_set_mass_matrix, for models
 * whose f_x = B⁻¹ g_x is dense but g_x sparse).
 * Everything in this header works with both methods (whirl_ode_monodromy
 * always uses DOPRI5); the differences: the error test is CVODE's weighted
 * RMS norm of the local error with weights 1/(rtol |x_i| + atol), looser
 * than the max norm above (at the same rtol expect larger errors); the
 * dense output is CVODE's interpolating polynomial of the current order
 * (CVodeGetDky); the minimum step defaults to none; a failed step is
 * retried as CVODE decides (at most 7 error-test and 10 Newton failures a
 * step); new tolerances or a change of direction restart CVODE (at order
 * 1) from the current point; messages end with CVODE's own.  Callbacks
 * keep their meaning: > 0 or a non-finite value makes CVODE retry with a
 * smaller step, < 0 stops at once (WHIRL_EUSER; last_rhs_status says what
 * the model returned, e.g. WHIRL_EDOMAIN); repeated recoverable failures
 * end in WHIRL_ESTEP with whirl_ode_last_rhs_status() as above.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ODE_H
#define WHIRL_ODE_H

#include <stddef.h>
#include <whirl/problem.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_ode whirl_ode;

typedef struct whirl_ode_stats {
  size_t steps;     /* accepted steps */
  size_t rejected;  /* rejected steps (error test or recoverable failure) */
  size_t rhs_evals; /* right-hand-side evaluations */
} whirl_ode_stats;

/* An integrator for prob with parameters p[prob->npar] (copied).  NULL on
 * bad arguments or out of memory. */
WHIRL_API whirl_ode *whirl_ode_alloc(const whirl_problem *prob,
                                     const double *p);
WHIRL_API void whirl_ode_free(whirl_ode *ode); /* accepts NULL */

/* Integration methods.  DOPRI5 (the default) for non-stiff problems, BDF
 * (CVODE) for stiff ones: a journal near the housing, fine finite-element
 * meshes. */
typedef enum whirl_ode_method {
  WHIRL_ODE_DOPRI5 = 0, /* explicit Dormand–Prince 5(4) (lib/ode/dopri.c) */
  WHIRL_ODE_BDF = 1,    /* implicit BDF 1..5 by CVODE (lib/ode/bdf.c) */
  WHIRL_ODE_DOP853 = 2  /* explicit Dormand–Prince 8(5,3), dense output of
                           order 7 (lib/ode/dop853.c): 3–6 times fewer
                           evaluations than DOPRI5 at tight tolerances */
} whirl_ode_method;

/* Choose the method (whirl_ode_method).  Settings, parameters and
 * statistics are kept.  If the integrator has a state (after a reset) it
 * restarts from it at once, as whirl_ode_reset(ode, t, x) would (pending
 * parameters take effect).  WHIRL_EINVAL for an unknown method. */
WHIRL_API int whirl_ode_set_method(whirl_ode *ode, int method);
WHIRL_API int whirl_ode_get_method(const whirl_ode *ode); /* -1 for NULL */
/* "dopri5", "bdf", "dop853"; NULL for an unknown method. */
WHIRL_API const char *whirl_ode_method_name(int method);
/* The method named s ("dopri5", "bdf" or "dop853"): WHIRL_OK and *method, or
 * WHIRL_EINVAL. */
WHIRL_API int whirl_ode_method_parse(const char *s, int *method);

/* A sparse Jacobian f_x for BDF: the pattern in compressed columns, Jp[n+1]
 * (Jp[0] = 0, non-decreasing, Jp[n] = nnz), Ji[nnz] the row indices of
 * each column in increasing order, all in [0, n); copied.  fill(t, x, p,
 * J, data) writes J[nnz], the values in that order (J[k] = df_Ji[k] /
 * dx_j for Jp[j] <= k < Jp[j+1]), with the whirl_jac_fn statuses; data is
 * passed to it (e.g. prob->data).  With a pattern BDF solves its linear
 * systems by KLU; nnz = 0 with fill NULL goes back to dense LU.  Takes
 * effect at the next reset (or set_method); the DOPRI5 method ignores it.
 * WHIRL_EINVAL with a message for a bad pattern. */
WHIRL_API int whirl_ode_set_sparse_jacobian(whirl_ode *ode, size_t nnz,
                                            const int *Jp, const int *Ji,
                                            whirl_jac_fn fill, void *data);

/* A constant mass matrix B for BDF with a sparse Jacobian, for models
 * B x' = g(t, x) whose rhs returns x' = B⁻¹ g (e.g. structures with a
 * consistent mass, where f_x = B⁻¹ g_x is dense but g_x is sparse): the
 * pattern Mp[n+1], Mi[nnz] (inside the sparse Jacobian's pattern) and the
 * values Mx[nnz], copied; the sparse Jacobian's fill then returns
 * G = B f_x (= g_x), not f_x.  BDF solves its Newton systems as
 * (B − γ G) δ = B r by KLU, the same iterates as (I − γ f_x) δ = r.
 * nnz = 0 removes it.  Takes effect at the next reset; DOPRI5 ignores it.
 * WHIRL_EINVAL for a bad pattern (or, at the reset, one not inside the
 * Jacobian's). */
WHIRL_API int whirl_ode_set_mass_matrix(whirl_ode *ode, size_t nnz,
                                        const int *Mp, const int *Mi,
                                        const double *Mx);

/* rtol > 0 (and >= 100 DBL_EPSILON), atol > 0; WHIRL_EINVAL otherwise. */
WHIRL_API int whirl_ode_set_tolerances(whirl_ode *ode, double rtol,
                                       double atol);
/* Initial step (0: automatic, Hairer's algorithm), minimum step (0: 16 ulp
 * of t) and maximum step (0: unlimited).  All >= 0 and finite, h_min and
 * h_init <= h_max (if set), h_init >= h_min; WHIRL_EINVAL otherwise.  The
 * minimum in force is never below 16 ulp of t; a last step shortened to hit
 * t_end exactly may be shorter, and one stretched by up to 1% to hit it may
 * exceed h_max by that much.  h_init = h_max = h with loose tolerances
 * gives fixed steps h. */
WHIRL_API int whirl_ode_set_step_limits(whirl_ode *ode, double h_init,
                                        double h_min, double h_max);
/* Maximum accepted steps per whirl_ode_evolve call, and between two
 * consecutive samples of whirl_ode_sample (0: unlimited); beyond it those
 * return WHIRL_EMAXITER with a message. */
WHIRL_API int whirl_ode_set_max_steps(whirl_ode *ode, size_t max_steps);
/* Replace the parameters (takes effect at the next reset). */
WHIRL_API int whirl_ode_set_params(whirl_ode *ode, const double *p);

/* Start (or restart) at (t0, x0): clears the step history (the next step
 * starts from h_init or the automatic choice), keeps the statistics.
 * WHIRL_EINVAL for a non-finite t0 or x0. */
WHIRL_API int whirl_ode_reset(whirl_ode *ode, double t0, const double *x0);

/* Take one accepted step towards t_end, never beyond it (t_end may be below
 * t: integration backwards).  Returns WHIRL_OK, or WHIRL_DONE if t == t_end
 * already (no step taken), or an error. */
WHIRL_API int whirl_ode_step(whirl_ode *ode, double t_end);
/* Step until t == t_end exactly.  WHIRL_EMAXITER after max_steps steps. */
WHIRL_API int whirl_ode_evolve(whirl_ode *ode, double t_end);

WHIRL_API size_t whirl_ode_size(const whirl_ode *ode); /* n */
WHIRL_API double whirl_ode_t(const whirl_ode *ode);
WHIRL_API const double *whirl_ode_x(const whirl_ode *ode);
/* Start of the last accepted step and the state there.  The state
 * pointers stay valid (their contents change) until whirl_ode_free. */
WHIRL_API double whirl_ode_t_prev(const whirl_ode *ode);
WHIRL_API const double *whirl_ode_x_prev(const whirl_ode *ode);
/* |step size| proposed for the next step (0 before the first step when
 * the initial step is automatic). */
WHIRL_API double whirl_ode_h(const whirl_ode *ode);

/* Dense output: x(t) for t in the last accepted step [t_prev, t] (4th order,
 * continuous; exact at both ends).  WHIRL_EINVAL outside the step, or
 * before the first step after a reset. */
WHIRL_API int whirl_ode_dense(const whirl_ode *ode, double t, double *x);

/* An event function g(t, x); events are its zeros. */
typedef double (*whirl_event_fn)(double t, const double *x, void *data);

/* Look for a zero of g in the last accepted step: if g changes sign between
 * t_prev and t (direction > 0: only − to +, < 0: only + to −, 0: both),
 * locate it on the dense output by the Illinois method to |Δt| <= tol_t and
 * return 1 with *t_ev and x_ev[n]; 0 if there is none.  g(t_prev) == 0 is
 * not an event (it was reported with the previous step).  At most one event
 * per step is reported (the first one, when g is sampled at 8 interior
 * points).  *t_ev is the end of the final bracket on the far side of the
 * zero (g there has the new sign or is 0); tol_t <= 0 means to a few ulp.
 * x_ev is required (also used as scratch).  WHIRL_EINVAL for NULL
 * arguments or no accepted step, WHIRL_EBADFUNC if g returns NaN or Inf. */
WHIRL_API int whirl_ode_find_event(const whirl_ode *ode, whirl_event_fn g,
                                   void *data, int direction, double tol_t,
                                   double *t_ev, double *x_ev);

WHIRL_API void whirl_ode_get_stats(const whirl_ode *ode, whirl_ode_stats *s);
/* The work of an implicit method (all 0 for DOPRI5), summed over resets
 * as whirl_ode_stats.  A separate struct, so that whirl_ode_stats keeps its
 * size (ABI).  BDF: steps are CVODE's, rejected the error-test and Newton
 * failures, rhs_evals every call of the model's rhs (difference-quotient
 * Jacobians included). */
typedef struct whirl_ode_implicit_stats {
  size_t jac_evals;    /* Jacobian evaluations (analytic, sparse, or by
                          difference quotients) */
  size_t lu_factors;   /* LU factorisations of I − γ f_x (CVODE's linear
                          solver setups) */
  size_t newton_iters; /* Newton iterations */
  size_t newton_fails; /* Newton convergence failures */
  size_t error_fails;  /* local error test failures */
} whirl_ode_implicit_stats;
WHIRL_API void whirl_ode_get_implicit_stats(const whirl_ode *ode,
                                            whirl_ode_implicit_stats *s);
WHIRL_API int whirl_ode_last_rhs_status(const whirl_ode *ode);
WHIRL_API const char *whirl_ode_errmsg(const whirl_ode *ode);

/* Uniform sampling: advance from the current time t_s over nsamples
 * intervals of length dt (dt < 0: backwards), calling fn(k, t_s + k dt,
 * x, data) for k = 0 (the current state) .. nsamples, x from the dense
 * output (steps are not cut at sample times, so sampling does not change
 * the solution).  fn returns 0 to go on, > 0 to stop (that value is
 * returned), < 0 for an error (returned).  Returns WHIRL_OK when all
 * samples were delivered, or the integrator's error. */
typedef int (*whirl_sample_fn)(size_t k, double t, const double *x,
                               void *data);
WHIRL_API int whirl_ode_sample(whirl_ode *ode, double dt, size_t nsamples,
                               whirl_sample_fn fn, void *data);

/* Monodromy matrix by the variational equations (paper eq. 24):
 *   x' = f(t, x, p),  Φ' = f_x(t, x, p) Φ,  Φ(t0) = I,
 * integrated together over [t0, t0 + T] with the same error control on all
 * n + n² components.  f_x is prob->jac_x, or central differences when NULL.
 * Outputs: xT[n] = x(t0 + T) (may be NULL), M[n*n] column-major.  Optional
 * stats (of the combined system: each evaluation calls rhs and jac_x once,
 * or rhs 2n + 1 times with finite differences).  T may be negative; T = 0
 * gives M = I.  rtol, atol as in whirl_ode_set_tolerances.  On error a
 * message goes to errbuf (may be NULL, errlen may be 0). */
WHIRL_API int whirl_ode_monodromy(const whirl_problem *prob, const double *p,
                                  double t0, const double *x0, double T,
                                  double rtol, double atol, double *xT,
                                  double *M, whirl_ode_stats *stats,
                                  char *errbuf, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

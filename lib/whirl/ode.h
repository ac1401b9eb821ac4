/* whirl/ode.h — explicit Runge–Kutta integration of a model x' = f(t, x, p):
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

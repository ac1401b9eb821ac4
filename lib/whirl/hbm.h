/* whirl/hbm.h — constructor: periodic solutions of an ODE model by harmonic
 * balance with the alternating frequency–time scheme (HBM/AFT; Cameron &
 * Griffin 1989; Krack & Gross, Harmonic Balance for Nonlinear Vibration
 * Problems, 2019; paper §4.2 and eq. 18), as an algebraic problem
 * F(X, p) = 0 for the continuation core.
 *
 * Each state component is a truncated Fourier series in the phase
 * θ = w (t − t0), w the fundamental frequency:
 *   x_i(θ) = c_i + Σ_{k=1..N} a_ik cos kθ + b_ik sin kθ .
 * Unknowns X (component-major, L = 2N + 1 per component, divided by the
 * component's scale): X[i*L] = c_i, X[i*L + 2k − 1] = a_ik, X[i*L + 2k] = b_ik,
 * then, for an autonomous model, w.  Equations: the Galerkin projection of
 * x' − f(t, x, p) onto 1, cos kθ, sin kθ, computed by AFT on M = K·(2N + 1)
 * equally spaced phases (K the oversampling); for autonomous models the
 * phase condition b_{j,1} = 0 of one component j.
 *
 * Forced models: forcing_param >= 0 names the parameter that is the forcing
 * frequency ω; the fundamental is w = ω/ν with the subharmonic index ν
 * (paper eq. 18).  Autonomous models (forcing_param = −1): w is an unknown.
 *
 * The Jacobian is assembled by AFT from the model's force Jacobian f_x at
 * the M phases; its pattern (full, or by blocks from an optional structural
 * mask of f_x) is given to the core so both the dense and the sparse
 * (UMFPACK) paths can be used.  The system's spectrum is the Floquet
 * multipliers from the variational equations at θ = 0 (whirl/floquet.h), so
 * the core reports stability and detects LP, PD and TR unchanged.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_HBM_H
#define WHIRL_HBM_H

#include <stddef.h>
#include <whirl/problem.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_hbm_options {
  size_t harmonics;    /* N (default 8, as in the paper) */
  size_t oversampling; /* K: M = K (2N + 1) time samples (default 10) */
  unsigned nu;         /* subharmonic index ν (default 1) */
  int forcing_param;   /* >= 0: forced, ω = p[forcing_param]; −1 autonomous */
  size_t phase_component; /* autonomous: component with b_1 = 0 (default 0) */
  double t0;           /* forced: time at θ = 0 (default 0) */
  const double *scale; /* optional n scales of the unknowns (default 1) */
  const int *fx_mask;  /* optional n*n structural mask of f_x, column-major
                          (mask[i + n*j] != 0 if df_i/dx_j can be nonzero);
                          NULL: full */
  double floquet_rtol; /* integrator tolerance for the multipliers (1e-11) */
  int no_spectrum;     /* 1: no multipliers (no stability, no PD/TR) */
} whirl_hbm_options;

WHIRL_API void whirl_hbm_options_default(whirl_hbm_options *o);

typedef struct whirl_hbm whirl_hbm;

/* prob is borrowed and must outlive the object; NULL on bad options (message
 * in errbuf) or memory. */
WHIRL_API whirl_hbm *whirl_hbm_alloc(const whirl_problem *prob,
                                     const whirl_hbm_options *o, char *errbuf,
                                     size_t errlen);
WHIRL_API void whirl_hbm_free(whirl_hbm *h); /* accepts NULL */

WHIRL_API const whirl_system *whirl_hbm_system(const whirl_hbm *h);
WHIRL_API size_t whirl_hbm_size(const whirl_hbm *h); /* n(2N+1) [+1] */
WHIRL_API size_t whirl_hbm_dim(const whirl_hbm *h); /* n, the model's */

/* The message of the last failure of a function given h, with its origin
 * "(hbm.c:N)"; each evaluation of the system's spectrum (the multipliers)
 * replaces it, by "" when it succeeds.  Never NULL. */
WHIRL_API const char *whirl_hbm_errmsg(const whirl_hbm *h);

/* Fundamental frequency w and period 2π/w of the solution X at p. */
WHIRL_API double whirl_hbm_frequency(const whirl_hbm *h, const double *X,
                                     const double *p);
WHIRL_API double whirl_hbm_period(const whirl_hbm *h, const double *X,
                                  const double *p);

/* X[size] from m >= 2N + 1 uniform samples of one period, x[k*n + i] at
 * θ_k = 2πk/m (no end point), by the discrete Fourier transform (exact for
 * trigonometric polynomials of degree N < m/2); for autonomous models the
 * frequency 2π/T is stored and the phase is NOT adjusted (rotate with
 * whirl_hbm_set_phase before starting a continuation).  Linear in x for
 * fixed T, so it maps perturbations as well. */
WHIRL_API int whirl_hbm_from_samples(whirl_hbm *h, const double *x, size_t m,
                                     double T, double *X);

/* Shift the time origin so that the phase condition b_{j,1} = 0 holds with
 * a_{j,1} >= 0 (autonomous models); no-op for forced ones. */
WHIRL_API void whirl_hbm_set_phase(const whirl_hbm *h, double *X);

/* State x[n] at phase θ. */
WHIRL_API void whirl_hbm_eval(const whirl_hbm *h, const double *X,
                              double theta, double *x);

/* The maximum over the orbit of each component, mx[n]: the maximum of the
 * truncated series (Newton on its derivative from the largest of 8(2N+1)
 * samples), not of samples.  WHIRL_OK or WHIRL_EINVAL. */
WHIRL_API int whirl_hbm_max(const whirl_hbm *h, const double *X, double *mx);

/* AUTO's L2-NORM of the orbit, sqrt(∫₀¹ |x(τ)|² dτ) (exact for the series:
 * 8(2N+1) samples of a trigonometric polynomial of degree 2N); NaN when out
 * of memory. */
WHIRL_API double whirl_hbm_l2norm(const whirl_hbm *h, const double *X);

/* Largest |x' − f(t, x, p)| of the truncated series over K·M equally spaced
 * phases: the time-domain residual (it measures the truncation error; the
 * Galerkin residual F is what Newton drives to zero). */
WHIRL_API int whirl_hbm_time_residual(whirl_hbm *h, const double *X,
                                      const double *p, size_t K, double *res);

/* Floquet multipliers of X at p (as the system's spectrum), with the
 * monodromy matrix M[n*n] if not NULL. */
WHIRL_API int whirl_hbm_multipliers(const whirl_hbm *h, const double *X,
                                    const double *p, double *re, double *im,
                                    size_t *m, double *M, char *errbuf,
                                    size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

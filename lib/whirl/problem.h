/* whirl/problem.h — a model: the vector field x' = f(t, x, p) of an ODE.
 * A model is a struct of callbacks plus a borrowed void *data (GSL style).
 * Constructors in lib/systems turn it into an algebraic problem (whirl_system):
 * equilibria (whirl/equilibrium.h), periodic orbits by harmonic balance
 * (whirl/hbm.h) or collocation (whirl/colloc.h); fold and Hopf curves wrap
 * those systems (whirl/fold.h, whirl/hopf.h).
 *
 * Callback contract (SUNDIALS): return 0 on success, > 0 for a recoverable
 * failure (e.g. a state outside the model's domain such as journal-housing
 * contact: the caller shortens its step), < 0 for a fatal error (reported as
 * WHIRL_EUSER).  The library checks every output for NaN/Inf and treats a
 * non-finite value as recoverable.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_PROBLEM_H
#define WHIRL_PROBLEM_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/* π to double precision, for models and the library (ISO C has no M_PI). */
#define WHIRL_PI 3.14159265358979323846

/* f[n] = right-hand side at (t, x[n], p[npar]). */
typedef int (*whirl_rhs_fn)(double t, const double *x, const double *p,
                            double *f, void *data);
/* Jacobian, column-major: jac_x fills J[n*n] with J[i + n*j] = df_i/dx_j;
 * jac_p fills J[n*npar] with J[i + n*k] = df_i/dp_k. */
typedef int (*whirl_jac_fn)(double t, const double *x, const double *p,
                            double *J, void *data);

typedef struct whirl_problem {
  const char *name;            /* short name, used in messages and headers */
  size_t n;                    /* state dimension */
  size_t npar;                 /* number of parameters */
  whirl_rhs_fn rhs;            /* required */
  whirl_jac_fn jac_x;          /* optional: NULL -> finite differences */
  whirl_jac_fn jac_p;          /* optional: NULL -> finite differences */
  int autonomous;              /* 1 if rhs does not depend on t */
  const char *const *x_names;  /* optional, n names */
  const char *const *p_names;  /* optional, npar names */
  void *data;                  /* borrowed; the library never frees it */
} whirl_problem;

/* Finite-difference Jacobians of a model (central differences, step
 * h_j = cbrt(DBL_EPSILON) * max(1, |x_j|)).  J as above.  work[2n] scratch.
 * Returns the first non-zero callback status, or WHIRL_EBADFUNC. */
WHIRL_API int whirl_fd_jac_x(const whirl_problem *prob, double t,
                             const double *x, const double *p, double *J,
                             double *work);
WHIRL_API int whirl_fd_jac_p(const whirl_problem *prob, double t,
                             const double *x, const double *p, double *J,
                             double *work);

/* Compare the model's analytic jac_x and jac_p with finite differences at
 * (t, x, p).  *max_err receives max |J_a - J_fd| / (1 + |J_a|) over all
 * entries.  Returns WHIRL_EINVAL if the model has neither Jacobian. */
WHIRL_API int whirl_check_jacobian(const whirl_problem *prob, double t,
                                   const double *x, const double *p,
                                   double *max_err);

#ifdef __cplusplus
}
#endif
#endif

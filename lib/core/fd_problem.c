/* lib/core/fd_problem.c — finite-difference Jacobians of an ODE model
 * x' = f(t, x, p) (whirl/problem.h) and a checker that compares a model's
 * analytic jac_x, jac_p with them.  Central differences with step
 * h_j = cbrt(DBL_EPSILON) * max(1, |x_j|): error O(h²) ~ 1e-11 relative.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/problem.h>

#include "util/short_copy.h"

static int all_finite(const double *v, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

/* f = rhs(t, x, p); the callback status, else WHIRL_EBADFUNC if f is not
 * finite. */
static int eval_rhs(const whirl_problem *prob, double t, const double *x,
                    const double *p, double *f) {
  int rc = prob->rhs(t, x, p, f, prob->data);
  if (rc != 0) return rc;
  return all_finite(f, prob->n) ? WHIRL_OK : WHIRL_EBADFUNC;
}

/* Column j of J holds the perturbed copy of x while its two evaluations run
 * (f+ in work[0..n), f− in work[n..2n)), so no allocation is needed.  The
 * divisor is the step actually taken, (x_j + h) − (x_j − h).  The column,
 * not each evaluation, is checked: a value of f+ or f− that is not finite
 * leaves its entry not finite (checking all 2n values of a column was half
 * the differences' own time, the model's calls apart, in demo fnc). */
int whirl_fd_jac_x(const whirl_problem *prob, double t, const double *x,
                   const double *p, double *J, double *work) {
  if (prob == NULL || prob->rhs == NULL || x == NULL || J == NULL ||
      work == NULL)
    return WHIRL_EINVAL;
  const size_t n = prob->n;
  const double h0 = cbrt(DBL_EPSILON);
  double *fp = work, *fm = work + n;
  for (size_t j = 0; j < n; ++j) {
    double *xc = J + n * j;
    const double h = h0 * fmax(1.0, fabs(x[j]));
    const double xp = x[j] + h, xm = x[j] - h;
    int rc;
    whirl_copy_short(xc, x, n);
    xc[j] = xp;
    if ((rc = prob->rhs(t, xc, p, fp, prob->data)) != 0) return rc;
    xc[j] = xm;
    if ((rc = prob->rhs(t, xc, p, fm, prob->data)) != 0) return rc;
    const double inv = 1.0 / (xp - xm);
    for (size_t i = 0; i < n; ++i) xc[i] = (fp[i] - fm[i]) * inv;
    if (!all_finite(xc, n)) return WHIRL_EBADFUNC;
  }
  return WHIRL_OK;
}

int whirl_fd_jac_p(const whirl_problem *prob, double t, const double *x,
                   const double *p, double *J, double *work) {
  if (prob == NULL || prob->rhs == NULL || x == NULL || p == NULL ||
      J == NULL || work == NULL)
    return WHIRL_EINVAL;
  const size_t n = prob->n, npar = prob->npar;
  const double h0 = cbrt(DBL_EPSILON);
  double pbuf[32];
  double *pc = npar <= 32 ? pbuf : malloc(npar * sizeof *pc);
  double *fp = work, *fm = work + n;
  int rc = WHIRL_OK;
  if (pc == NULL) return WHIRL_ENOMEM;
  memcpy(pc, p, npar * sizeof *pc);
  for (size_t k = 0; k < npar; ++k) {
    const double h = h0 * fmax(1.0, fabs(p[k]));
    const double pp = p[k] + h, pm = p[k] - h;
    pc[k] = pp;
    if ((rc = eval_rhs(prob, t, x, pc, fp)) != 0) goto done;
    pc[k] = pm;
    if ((rc = eval_rhs(prob, t, x, pc, fm)) != 0) goto done;
    pc[k] = p[k];
    const double inv = 1.0 / (pp - pm);
    for (size_t i = 0; i < n; ++i) J[i + n * k] = (fp[i] - fm[i]) * inv;
  }
done:
  if (pc != pbuf) free(pc);
  return rc;
}

int whirl_check_jacobian(const whirl_problem *prob, double t, const double *x,
                         const double *p, double *max_err) {
  if (max_err != NULL) *max_err = NAN;
  if (prob == NULL || prob->rhs == NULL || x == NULL || p == NULL ||
      max_err == NULL)
    return WHIRL_EINVAL;
  if (prob->jac_x == NULL && prob->jac_p == NULL) return WHIRL_EINVAL;
  const size_t n = prob->n, npar = prob->npar;
  const size_t m = n * (n > npar ? n : npar); /* room for either matrix */
  double *Ja = malloc((m > 0 ? m : 1) * sizeof *Ja);
  double *Jf = malloc((m > 0 ? m : 1) * sizeof *Jf);
  double *work = malloc((n > 0 ? 2 * n : 1) * sizeof *work);
  double err = 0.0;
  int rc = WHIRL_ENOMEM;
  if (Ja == NULL || Jf == NULL || work == NULL) goto done;
  if (prob->jac_x != NULL) {
    if ((rc = prob->jac_x(t, x, p, Ja, prob->data)) != 0) goto done;
    if (!all_finite(Ja, n * n)) {
      rc = WHIRL_EBADFUNC;
      goto done;
    }
    if ((rc = whirl_fd_jac_x(prob, t, x, p, Jf, work)) != 0) goto done;
    for (size_t i = 0; i < n * n; ++i)
      err = fmax(err, fabs(Ja[i] - Jf[i]) / (1.0 + fabs(Ja[i])));
  }
  if (prob->jac_p != NULL) {
    if ((rc = prob->jac_p(t, x, p, Ja, prob->data)) != 0) goto done;
    if (!all_finite(Ja, n * npar)) {
      rc = WHIRL_EBADFUNC;
      goto done;
    }
    if ((rc = whirl_fd_jac_p(prob, t, x, p, Jf, work)) != 0) goto done;
    for (size_t i = 0; i < n * npar; ++i)
      err = fmax(err, fabs(Ja[i] - Jf[i]) / (1.0 + fabs(Ja[i])));
  }
  rc = WHIRL_OK;
  *max_err = err;
done:
  free(Ja);
  free(Jf);
  free(work);
  return rc;
}

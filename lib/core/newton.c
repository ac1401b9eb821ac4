/* lib/core/newton.c — Newton's method for F(x, p) = 0 at fixed parameters,
 * with the dense LU of whirl_linsol: the corrector used to polish seeds and
 * in tests.  Converged when |dx|_inf <= tol (1 + |x|_inf).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>

#include <whirl/cont.h>

int whirl_newton(const whirl_system *sys, double *x, const double *p,
                 double tol, int maxit, int *its) {
  const size_t n = sys->n;
  size_t wlen = 2 * n + sys->nnz;
  whirl_linsol *ls = whirl_linsol_alloc_dense(n);
  double *J = malloc(n * n * sizeof *J), *f = malloc(n * sizeof *f);
  double *work = malloc(wlen * sizeof *work);
  int rc = WHIRL_ENOMEM, it = 0, grow = 0;
  double prev = INFINITY;
  if (!ls || !J || !f || !work) goto done;
  rc = WHIRL_ENOCONV;
  for (it = 1; it <= maxit; ++it) {
    int r = whirl_system_eval(sys, x, p, f);
    if (r == 0) r = whirl_system_jacobian(sys, x, p, J, work);
    if (r != 0) {
      rc = r > 0 || r == WHIRL_EBADFUNC ? WHIRL_EDOMAIN : WHIRL_EUSER;
      break;
    }
    r = whirl_linsol_factor(ls, J);
    if (r != WHIRL_OK) {
      /* singular at the start is the caller's problem; later it means the
       * iterates ran off to where F is flat: divergence */
      rc = it > 1 && r == WHIRL_ESINGULAR ? WHIRL_ENOCONV : r;
      break;
    }
    whirl_linsol_solve(ls, f, 1, 0);
    double dmax = 0.0, xmax = 0.0;
    for (size_t i = 0; i < n; ++i) {
      x[i] -= f[i];
      dmax = fmax(dmax, fabs(f[i]));
      xmax = fmax(xmax, fabs(x[i]));
    }
    if (!isfinite(dmax)) break;
    if (dmax <= tol * (1.0 + xmax)) {
      rc = WHIRL_OK;
      break;
    }
    /* growing corrections three times running: diverging */
    grow = it > 1 && dmax > prev ? grow + 1 : 0;
    if (grow >= 3) break;
    prev = dmax;
  }
done:
  if (its) *its = it;
  whirl_linsol_free(ls);
  free(J);
  free(f);
  free(work);
  return rc;
}

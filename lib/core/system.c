/* lib/core/system.c — evaluation helpers for the algebraic problem
 * F(x, p) = 0: finiteness checks, analytic-or-finite-difference Jacobians and
 * parameter derivatives, and a Jacobian checker.  Central differences with
 * h = cbrt(eps) * max(1, |x_j|) (error O(h^2) ~ 1e-11 relative).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/system.h>

static int all_finite(const double *v, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

int whirl_system_eval(const whirl_system *sys, const double *x,
                      const double *p, double *f) {
  int rc = sys->F(x, p, f, sys->data);
  if (rc != 0) return rc;
  return all_finite(f, sys->n) ? WHIRL_OK : WHIRL_EBADFUNC;
}

int whirl_system_fd_jacobian(const whirl_system *sys, const double *x,
                             const double *p, double *J, double *work) {
  const size_t n = sys->n;
  const double h0 = cbrt(DBL_EPSILON);
  double *xp = work, *fm = work + n;
  memcpy(xp, x, n * sizeof *xp);
  for (size_t j = 0; j < n; ++j) {
    const double h = h0 * fmax(1.0, fabs(x[j]));
    int rc;
    xp[j] = x[j] + h;
    if ((rc = whirl_system_eval(sys, xp, p, J + n * j)) != 0) return rc;
    xp[j] = x[j] - h;
    if ((rc = whirl_system_eval(sys, xp, p, fm)) != 0) return rc;
    xp[j] = x[j];
    const double inv = 1.0 / (2.0 * h);
    for (size_t i = 0; i < n; ++i) J[i + n * j] = (J[i + n * j] - fm[i]) * inv;
  }
  return WHIRL_OK;
}

int whirl_system_fd_param(const whirl_system *sys, const double *x,
                          const double *p, size_t k, double *fk, double *work) {
  const size_t n = sys->n;
  double pk[64];
  double *pp = sys->npar <= 64 ? pk : NULL;
  if (pp == NULL || k >= sys->npar) return WHIRL_EINVAL;
  memcpy(pp, p, sys->npar * sizeof *pp);
  const double h = cbrt(DBL_EPSILON) * fmax(1.0, fabs(p[k]));
  int rc;
  pp[k] = p[k] + h;
  if ((rc = whirl_system_eval(sys, x, pp, fk)) != 0) return rc;
  pp[k] = p[k] - h;
  if ((rc = whirl_system_eval(sys, x, pp, work)) != 0) return rc;
  for (size_t i = 0; i < n; ++i) fk[i] = (fk[i] - work[i]) / (2.0 * h);
  return WHIRL_OK;
}

void whirl_system_scatter_dense(const whirl_system *sys, const double *Jx,
                                double *J) {
  const size_t n = sys->n;
  memset(J, 0, n * n * sizeof *J);
  for (size_t j = 0; j < n; ++j)
    for (int q = sys->Jp[j]; q < sys->Jp[j + 1]; ++q) J[(size_t)sys->Ji[q] + n * j] = Jx[q];
}

int whirl_system_jacobian(const whirl_system *sys, const double *x,
                          const double *p, double *J, double *work) {
  const size_t n = sys->n;
  int rc;
  if (sys->Fx) {
    rc = sys->Fx(x, p, J, sys->data);
  } else if (sys->Fx_sparse && sys->nnz > 0) {
    /* scatter the sparse values into the dense matrix; work must hold nnz
     * doubles here, which the callers guarantee by sizing work as
     * max(2n, nnz). */
    rc = sys->Fx_sparse(x, p, work, sys->data);
    if (rc == 0) whirl_system_scatter_dense(sys, work, J);
  } else {
    return whirl_system_fd_jacobian(sys, x, p, J, work);
  }
  if (rc != 0) return rc;
  return all_finite(J, n * n) ? WHIRL_OK : WHIRL_EBADFUNC;
}

int whirl_system_param(const whirl_system *sys, const double *x,
                       const double *p, size_t k, double *fk, double *work) {
  if (sys->Fp) {
    int rc = sys->Fp(x, p, k, fk, sys->data);
    if (rc != 0) return rc;
    return all_finite(fk, sys->n) ? WHIRL_OK : WHIRL_EBADFUNC;
  }
  return whirl_system_fd_param(sys, x, p, k, fk, work);
}

int whirl_system_check_jacobian(const whirl_system *sys, const double *x,
                                const double *p, double *max_err) {
  const size_t n = sys->n;
  if (!sys->Fx && !sys->Fx_sparse && !sys->Fp) return WHIRL_EINVAL;
  size_t wlen = 2 * n + (sys->nnz > 2 * n ? sys->nnz : 0);
  double *Ja = malloc(n * n * sizeof *Ja), *Jf = malloc(n * n * sizeof *Jf);
  double *work = malloc((wlen + 2 * n) * sizeof *work);
  int rc = WHIRL_ENOMEM;
  double err = 0.0;
  if (!Ja || !Jf || !work) goto done;
  if (sys->Fx || sys->Fx_sparse) {
    if ((rc = whirl_system_jacobian(sys, x, p, Ja, work)) != 0) goto done;
    if ((rc = whirl_system_fd_jacobian(sys, x, p, Jf, work)) != 0) goto done;
    for (size_t i = 0; i < n * n; ++i)
      err = fmax(err, fabs(Ja[i] - Jf[i]) / (1.0 + fabs(Ja[i])));
  }
  if (sys->Fp) {
    for (size_t k = 0; k < sys->npar; ++k) {
      if ((rc = sys->Fp(x, p, k, Ja, sys->data)) != 0) goto done;
      if ((rc = whirl_system_fd_param(sys, x, p, k, Jf, work)) != 0) goto done;
      for (size_t i = 0; i < n; ++i)
        err = fmax(err, fabs(Ja[i] - Jf[i]) / (1.0 + fabs(Ja[i])));
    }
  }
  rc = WHIRL_OK;
done:
  *max_err = rc == WHIRL_OK ? err : NAN;
  free(Ja);
  free(Jf);
  free(work);
  return rc;
}

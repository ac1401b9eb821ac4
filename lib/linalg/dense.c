/* linalg/dense.c — dense backend of whirl_linsol: LU with partial pivoting
 * P A = L U (LAPACK dgetrf), solves with A or A^T (dgetrs), and log|det A|
 * with its sign from the diagonal of U and the parity of the row
 * interchanges (Golub & Van Loan, Matrix Computations, 4th ed., §3.4).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>

#include "linsol_impl.h"

typedef struct dense_backend {
  int n;     /* order, as a LAPACK integer */
  int *ipiv; /* ipiv[n], 1-based row interchanges from dgetrf */
} dense_backend;

static void dense_free(void *backend) {
  dense_backend *d = backend;
  if (!d) return;
  free(d->ipiv);
  free(d);
}

static int dense_factor(whirl_linsol *ls) {
  dense_backend *d = ls->backend;
  int info = 0;
  char lmsg[96];
  whirl_lapack_clear();
  dgetrf_(&d->n, &d->n, ls->vals, &d->n, d->ipiv, &info);
  if (whirl_lapack_take(lmsg, sizeof lmsg))
    return WHIRL_FAIL(ls, WHIRL_ELAPACK, "dgetrf: %s", lmsg);
  if (info < 0)
    return WHIRL_FAIL(ls, WHIRL_ELAPACK, "dgetrf: argument %d had an illegal value",
                      -info);
  if (info > 0)
    return WHIRL_FAIL(ls, WHIRL_ESINGULAR,
                      "dgetrf: matrix is exactly singular, U(%d,%d) = 0 (n = %d)",
                      info, info, d->n);
  return WHIRL_OK;
}

static int dense_solve(whirl_linsol *ls, double *B, size_t nrhs, int trans) {
  dense_backend *d = ls->backend;
  const char tr = trans ? 'T' : 'N';
  const int nr = (int)nrhs; /* range checked by whirl_linsol_solve */
  int info = 0;
  char lmsg[96];
  whirl_lapack_clear();
  dgetrs_(&tr, &d->n, &nr, ls->vals, &d->n, d->ipiv, B, &d->n, &info, 1);
  if (whirl_lapack_take(lmsg, sizeof lmsg))
    return WHIRL_FAIL(ls, WHIRL_ELAPACK, "dgetrs: %s", lmsg);
  if (info != 0)
    return WHIRL_FAIL(ls, WHIRL_ELAPACK, "dgetrs: argument %d had an illegal value",
                      -info);
  return WHIRL_OK;
}

/* det A = det P^T det U = (-1)^(#interchanges) prod U(i,i).  Summing the
 * logarithms instead of multiplying cannot overflow or underflow. */
static int dense_logdet(const whirl_linsol *ls, double *logabs, int *sign) {
  const dense_backend *d = ls->backend;
  const size_t n = ls->n;
  double sum = 0.0;
  int s = 1;
  size_t i;
  for (i = 0; i < n; ++i) {
    const double u = ls->vals[i + n * i];
    if (u < 0.0) s = -s;
    if ((size_t)d->ipiv[i] != i + 1) s = -s;
    sum += log(fabs(u));
  }
  *logabs = sum;
  *sign = s;
  return WHIRL_OK;
}

static const whirl_linsol_ops dense_ops = {dense_factor, dense_solve,
                                           dense_logdet, dense_free};

whirl_linsol *whirl_linsol_alloc_dense(size_t n) {
  whirl_linsol *ls;
  dense_backend *d;
  if (!whirl_dim_ok(n)) return NULL;
  ls = whirl_linsol_new(WHIRL_LINSOL_DENSE, n, n * n);
  if (!ls) return NULL;
  ls->ops = &dense_ops;
  ls->backend = d = calloc(1, sizeof *d);
  if (!d) goto fail;
  d->n = (int)n;
  d->ipiv = calloc(n, sizeof *d->ipiv);
  if (!d->ipiv) goto fail;
  return ls;
fail:
  whirl_linsol_free(ls);
  return NULL;
}

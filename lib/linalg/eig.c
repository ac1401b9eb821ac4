/* linalg/eig.c — dense eigenvalues by the Hessenberg QR algorithm (LAPACK
 * dgeev, no eigenvectors) with workspace sized once at alloc, sorted for
 * stability tests; and whirl_null_vectors, the right singular vectors of
 * the smallest singular values (dgesvd), used for branch switching.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "linsol_impl.h"

struct whirl_eig {
  int n;        /* order */
  double *a;    /* a[n*n]: copy of the input, destroyed by dgeev */
  double *work; /* work[lwork], optimal size from the dgeev query */
  int lwork;
  char errmsg[WHIRL_ERRMSG_SIZE];
};

void whirl_eig_free(whirl_eig *e) {
  if (!e) return;
  free(e->a);
  free(e->work);
  free(e);
}

whirl_eig *whirl_eig_alloc(size_t n) {
  whirl_eig *e;
  double query = 0.0, dummy = 0.0;
  int info = 0, minus1 = -1, one = 1;
  if (!whirl_dim_ok(n) || n * n > SIZE_MAX / sizeof(double)) return NULL;
  e = calloc(1, sizeof *e);
  if (!e) return NULL;
  e->n = (int)n;
  e->a = malloc(n * n * sizeof *e->a);
  if (!e->a) goto fail;
  /* Workspace query (lwork = -1): only work[0] is written.  WR and WI are
   * not referenced; pass a valid pointer anyway. */
  whirl_lapack_clear();
  dgeev_("N", "N", &e->n, e->a, &e->n, &dummy, &dummy, &dummy, &one, &dummy,
         &one, &query, &minus1, &info, 1, 1);
  if (whirl_lapack_take(NULL, 0) || info != 0 || !(query >= 1.0) || query > (double)INT_MAX) goto fail;
  e->lwork = (int)query;
  if ((size_t)e->lwork < 3 * n) e->lwork = (int)(3 * n); /* documented min */
  e->work = malloc((size_t)e->lwork * sizeof *e->work);
  if (!e->work) goto fail;
  return e;
fail:
  whirl_eig_free(e);
  return NULL;
}

/* Order for whirl_eig_compute: decreasing real part; among equal real parts,
 * decreasing |imaginary part| so that each conjugate pair stays together,
 * then positive imaginary part first. */
static int eig_before(double re1, double im1, double re2, double im2) {
  if (re1 != re2) return re1 > re2;
  if (fabs(im1) != fabs(im2)) return fabs(im1) > fabs(im2);
  return im1 > im2;
}

const char *whirl_eig_errmsg(const whirl_eig *e) {
  return e ? e->errmsg : "no eigenvalue workspace";
}

int whirl_eig_compute(whirl_eig *e, const double *A, double *re, double *im) {
  const size_t n = e ? (size_t)e->n : 0;
  size_t i, j;
  int info = 0, one = 1;
  double dummy = 0.0;
  char lmsg[96];
  if (!e || !A || !re || !im) return WHIRL_EINVAL;
  e->errmsg[0] = '\0';
  for (i = 0; i < n * n; ++i) {
    if (!isfinite(A[i])) /* dgeev would return garbage */
      return WHIRL_FAIL(e, WHIRL_EINVAL, "eigenvalues: entry %zu of the "
                        "matrix is not finite", i);
    e->a[i] = A[i];
  }
  whirl_lapack_clear();
  dgeev_("N", "N", &e->n, e->a, &e->n, re, im, &dummy, &one, &dummy, &one,
         e->work, &e->lwork, &info, 1, 1);
  /* dgeev does not check what its helpers report: an overflowing matrix
   * makes dgebal's scaling NaN, dgebal complains and dgeev goes on */
  if (whirl_lapack_take(lmsg, sizeof lmsg))
    return WHIRL_FAIL(e, WHIRL_ELAPACK, "dgeev: %s", lmsg);
  if (info != 0) /* > 0: the QR algorithm did not converge */
    return WHIRL_FAIL(e, WHIRL_ELAPACK, "dgeev: the QR algorithm failed "
                      "(info = %d)", info);
  /* Stable insertion sort: dgeev already returns each conjugate pair with
   * bit-identical real parts, positive imaginary part first; O(n^2)
   * comparisons are negligible next to the O(n^3) QR algorithm and need
   * no workspace. */
  for (i = 1; i < n; ++i) {
    const double r = re[i], s = im[i];
    for (j = i; j > 0 && eig_before(r, s, re[j - 1], im[j - 1]); --j) {
      re[j] = re[j - 1];
      im[j] = im[j - 1];
    }
    re[j] = r;
    im[j] = s;
  }
  return WHIRL_OK;
}

/* A = U S V^T with singular values in decreasing order, so the wanted
 * vectors are the last nvec rows of V^T (Golub & Van Loan §2.4: they span
 * the numerical null space).  Column c of V is row k - nvec + c of V^T;
 * sv[] is therefore non-increasing and the last column belongs to the
 * smallest singular value.  When m < k only m singular values exist and
 * rows m .. k-1 of V^T span the exact null space: their sv is 0.
 * Workspace is allocated here: this is a one-off helper, not an object. */
int whirl_null_vectors(size_t m, size_t k, const double *A, size_t nvec,
                       double *V, double *sv) {
  const size_t mk = m < k ? m : k;
  double *a = NULL, *s = NULL, *vt = NULL, *work = NULL, query = 0.0;
  double dummy = 0.0;
  int im, ik, info = 0, lwork, minus1 = -1, one = 1;
  int rc = WHIRL_OK;
  size_t i, c;
  if (m == 0 || k == 0 || m > (size_t)INT_MAX || k > (size_t)INT_MAX ||
      nvec > k || !A || m > SIZE_MAX / sizeof(double) / k ||
      k > SIZE_MAX / sizeof(double) / k)
    return WHIRL_EINVAL;
  if (nvec == 0) return WHIRL_OK;
  if (!V || !sv) return WHIRL_EINVAL;
  for (i = 0; i < m * k; ++i)
    if (!isfinite(A[i])) return WHIRL_EINVAL;
  im = (int)m;
  ik = (int)k;
  a = malloc(m * k * sizeof *a);
  s = malloc(mk * sizeof *s);
  vt = malloc(k * k * sizeof *vt);
  if (!a || !s || !vt) {
    rc = WHIRL_ENOMEM;
    goto cleanup;
  }
  memcpy(a, A, m * k * sizeof *a);
  whirl_lapack_clear();
  dgesvd_("N", "A", &im, &ik, a, &im, s, &dummy, &one, vt, &ik, &query,
          &minus1, &info, 1, 1);
  if (whirl_lapack_take(NULL, 0) || info != 0 || !(query >= 1.0) || query > (double)INT_MAX) {
    rc = WHIRL_ELAPACK;
    goto cleanup;
  }
  lwork = (int)query;
  work = malloc((size_t)lwork * sizeof *work);
  if (!work) {
    rc = WHIRL_ENOMEM;
    goto cleanup;
  }
  whirl_lapack_clear();
  dgesvd_("N", "A", &im, &ik, a, &im, s, &dummy, &one, vt, &ik, work, &lwork,
          &info, 1, 1);
  if (whirl_lapack_take(NULL, 0) || info != 0) { /* < 0 bad argument, > 0 dbdsqr did not converge */
    rc = WHIRL_ELAPACK;
    goto cleanup;
  }
  for (c = 0; c < nvec; ++c) {
    const size_t r = k - nvec + c;
    for (i = 0; i < k; ++i) V[i + k * c] = vt[r + k * i];
    sv[c] = r < mk ? s[r] : 0.0;
  }
cleanup:
  free(work);
  free(vt);
  free(s);
  free(a);
  return rc;
}

/* Gaussian elimination with complete pivoting (Golub & Van Loan §3.4.8)
 * over the first n - k columns; the k unknowns left free are set to 1 and
 * the others found by back substitution, then the column exchanges undone.
 * The pivot is the first entry of largest modulus in a row-by-row scan, so
 * the vector is a fixed function of A (AUTO-07p's choice in its null
 * space, NLVC). */
int whirl_null_vector_pivoted(size_t m, size_t n, size_t k, double *A, double *u) {
  if (!A || !u || k == 0 || k > n || m + k < n) return WHIRL_EINVAL;
  for (size_t i = 0; i < m * n; ++i)
    if (!isfinite(A[i])) return WHIRL_EINVAL;
  size_t *cpiv = malloc(n * sizeof *cpiv);
  if (!cpiv) return WHIRL_ENOMEM;
#define AT(i, j) A[(i) + m * (j)]
  double amax = 0.0;
  for (size_t jj = 0; jj < n - k; ++jj) {
    size_t ip = jj, jp = jj;
    double piv = 0.0;
    for (size_t i = jj; i < m; ++i)
      for (size_t j = jj; j < n; ++j)
        if (fabs(AT(i, j)) > piv) piv = fabs(AT(i, j)), ip = i, jp = j;
    if (jj == 0) amax = piv;
    if (!(piv > amax / DBL_MAX)) { /* a null space of more than k: go on */
      piv = fmax(amax / DBL_MAX, DBL_MIN);
      AT(ip, jp) = piv;
    }
    for (size_t j = 0; j < n && ip != jj; ++j) {
      const double t = AT(jj, j);
      AT(jj, j) = AT(ip, j), AT(ip, j) = t;
    }
    cpiv[jj] = jp;
    for (size_t i = 0; i < m && jp != jj; ++i) {
      const double t = AT(i, jj);
      AT(i, jj) = AT(i, jp), AT(i, jp) = t;
    }
    for (size_t l = jj + 1; l < m; ++l) {
      const double r = AT(l, jj) / AT(jj, jj);
      if (r != 0.0)
        for (size_t j = jj + 1; j < n; ++j) AT(l, j) -= r * AT(jj, j);
    }
  }
  for (size_t i = n - k; i < n; ++i) u[i] = 1.0;
  for (size_t i = n - k; i-- > 0;) {
    double s = 0.0;
    for (size_t j = i + 1; j < n; ++j) s += AT(i, j) * u[j];
    u[i] = -s / AT(i, i);
  }
  for (size_t i = n - k; i-- > 0;)
    if (cpiv[i] != i) {
      const double t = u[i];
      u[i] = u[cpiv[i]], u[cpiv[i]] = t;
    }
#undef AT
  free(cpiv);
  return WHIRL_OK;
}

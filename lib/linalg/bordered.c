/* linalg/bordered.c — bordered systems M = [A B; C D], A n x n, borders of
 * width m, assembled into one dense or one sparse LU (A's pattern plus dense
 * border rows and columns, analysed once).  Unlike block elimination through
 * A this stays well conditioned at folds and branch points where A is
 * singular (Govaerts, Numerical Methods for Bifurcations..., SIAM 2000, ch. 3).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "linsol_impl.h"

struct whirl_bordered {
  whirl_linsol_kind kind;
  size_t n, m, N;   /* N = n + m, order of M */
  whirl_linsol *ls; /* factorisation of M, owned */
  /* Sparse kind: column pointers Mp[N+1] of M.  Column j < n holds A's
   * entries of column j (same order) followed by the m rows of C, so the
   * A entries of column j sit at Mp[j] .. Mp[j+1]-m-1 and A's values can be
   * scattered in order without an index map; column n + k holds all N rows
   * (B then D). */
  int *Mp;
  char errmsg[WHIRL_ERRMSG_SIZE];
};

/* Record a failure of the inner solver under the bordered object. */
static int bordered_inner_fail(whirl_bordered *b, int rc) {
  snprintf(b->errmsg, sizeof b->errmsg, "%s", whirl_linsol_errmsg(b->ls));
  return rc;
}

/* Build the pattern of M from A's (validated) pattern and allocate the
 * sparse solver; the symbolic analysis is done there, once. */
static int bordered_alloc_sparse(whirl_bordered *b, const int *Ap,
                                 const int *Ai) {
  const size_t n = b->n, m = b->m, N = b->N;
  size_t nnzM, nborder, j, i, q = 0;
  int *Mi;
  int p;
  /* nnz(M) = nnz(A) + n m (C) + m N (B and D) must be an int.  With
   * m N <= INT_MAX, nborder <= 2 INT_MAX cannot wrap even in 32 bits. */
  if (m > (size_t)INT_MAX / N) return 0;
  nborder = n * m + m * N;
  if (nborder > (size_t)INT_MAX - (size_t)Ap[n]) return 0;
  nnzM = (size_t)Ap[n] + nborder;
  b->Mp = malloc((N + 1) * sizeof *b->Mp);
  Mi = malloc((nnzM ? nnzM : 1) * sizeof *Mi);
  if (!b->Mp || !Mi) {
    free(Mi);
    return 0;
  }
  for (j = 0; j < N; ++j) {
    b->Mp[j] = (int)q;
    if (j < n) {
      for (p = Ap[j]; p < Ap[j + 1]; ++p) Mi[q++] = Ai[p];
      for (i = n; i < N; ++i) Mi[q++] = (int)i;
    } else {
      for (i = 0; i < N; ++i) Mi[q++] = (int)i;
    }
  }
  b->Mp[N] = (int)q;
  b->ls = whirl_linsol_alloc_sparse(N, b->Mp, Mi);
  free(Mi);
  return b->ls != NULL;
}

whirl_bordered *whirl_bordered_alloc(whirl_linsol_kind kind, size_t n,
                                     size_t m, const int *Ap, const int *Ai) {
  whirl_bordered *b;
  if (n == 0 || m > SIZE_MAX - n) return NULL;
  if (kind != WHIRL_LINSOL_DENSE && kind != WHIRL_LINSOL_SPARSE) return NULL;
  if (kind == WHIRL_LINSOL_SPARSE && !whirl_csc_check(n, Ap, Ai)) return NULL;
  b = calloc(1, sizeof *b);
  if (!b) return NULL;
  b->kind = kind;
  b->n = n;
  b->m = m;
  b->N = n + m;
  if (kind == WHIRL_LINSOL_DENSE) {
    b->ls = whirl_linsol_alloc_dense(b->N);
    if (!b->ls) goto fail;
  } else if (!bordered_alloc_sparse(b, Ap, Ai)) {
    goto fail;
  }
  return b;
fail:
  whirl_bordered_free(b);
  return NULL;
}

void whirl_bordered_free(whirl_bordered *b) {
  if (!b) return;
  whirl_linsol_free(b->ls);
  free(b->Mp);
  free(b);
}

/* Dense M[N*N] column-major. */
static void assemble_dense(const whirl_bordered *b, double *M, const double *A,
                           const double *B, const double *C, const double *D) {
  const size_t n = b->n, m = b->m, N = b->N;
  size_t i, j;
  for (j = 0; j < n; ++j) {
    memcpy(M + N * j, A + n * j, n * sizeof *A);
    for (i = 0; i < m; ++i) M[n + i + N * j] = C[i + m * j];
  }
  for (j = 0; j < m; ++j) {
    for (i = 0; i < n; ++i) M[i + N * (n + j)] = B[i + n * j];
    for (i = 0; i < m; ++i) M[n + i + N * (n + j)] = D[i + m * j];
  }
}

/* Sparse values Mx[nnz(M)] in the order of the pattern built at alloc. */
static void assemble_sparse(const whirl_bordered *b, double *Mx,
                            const double *Ax, const double *B, const double *C,
                            const double *D) {
  const size_t n = b->n, m = b->m;
  const int *Mp = b->Mp;
  size_t i, j, q = 0;
  int p;
  for (j = 0; j < n; ++j) {
    const int end = Mp[j + 1] - (int)m;
    for (p = Mp[j]; p < end; ++p) Mx[p] = Ax[q++];
    for (i = 0; i < m; ++i) Mx[(size_t)end + i] = C[i + m * j];
  }
  for (j = 0; j < m; ++j) {
    double *col = Mx + Mp[n + j];
    for (i = 0; i < n; ++i) col[i] = B[i + n * j];
    for (i = 0; i < m; ++i) col[n + i] = D[i + m * j];
  }
}

int whirl_bordered_factor(whirl_bordered *b, const double *A, const double *B,
                          const double *C, const double *D) {
  int rc;
  if (!b) return WHIRL_EINVAL;
  b->errmsg[0] = '\0';
  if (!A || (b->m > 0 && (!B || !C || !D)))
    return WHIRL_FAIL(b, WHIRL_EINVAL, "bordered factor: block %s is NULL",
                      !A ? "A" : !B ? "B" : !C ? "C" : "D");
  if (b->kind == WHIRL_LINSOL_DENSE)
    assemble_dense(b, whirl_linsol_values(b->ls), A, B, C, D);
  else
    assemble_sparse(b, whirl_linsol_values(b->ls), A, B, C, D);
  rc = whirl_linsol_factor_values(b->ls);
  return rc == WHIRL_OK ? rc : bordered_inner_fail(b, rc);
}

int whirl_bordered_solve(whirl_bordered *b, double *R, size_t nrhs,
                         int trans) {
  int rc;
  if (!b) return WHIRL_EINVAL;
  b->errmsg[0] = '\0';
  rc = whirl_linsol_solve(b->ls, R, nrhs, trans);
  return rc == WHIRL_OK ? rc : bordered_inner_fail(b, rc);
}

int whirl_bordered_logdet(const whirl_bordered *b, double *logabs, int *sign) {
  if (!b) return WHIRL_EINVAL;
  return whirl_linsol_logdet(b->ls, logabs, sign);
}

const char *whirl_bordered_errmsg(const whirl_bordered *b) {
  return b ? b->errmsg : "whirl_bordered: NULL object";
}

/* linalg/sparse.c — sparse backend of whirl_linsol on SuiteSparse UMFPACK
 * (Davis, ACM TOMS 30(2), 2004): the fill-reducing symbolic analysis is done
 * once at alloc from the compressed-column pattern alone, each factor is a
 * numeric factorisation of new values on that pattern, and solves use
 * umfpack_di_wsolve with workspace owned by the object.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(HAVE_UMFPACK_H) && !defined(HAVE_SUITESPARSE_UMFPACK_H)
#include <umfpack.h>
#else
#include <suitesparse/umfpack.h>
#endif

#ifdef HAVE_CONFIG_H
#include "config.h"
#endif
#include <whirl/dynlib.h>

#include "linsol_impl.h"

/* UMFPACK, opened at the first sparse matrix (whirl/dynlib.h) */
#define UMF_FUNCS(X)                                                           \
  X(umfpack_di_defaults) X(umfpack_di_symbolic) X(umfpack_di_numeric)           \
  X(umfpack_di_wsolve) X(umfpack_di_get_determinant) X(umfpack_di_free_numeric) \
  X(umfpack_di_free_symbolic)
WHIRL_DYNLIB_UMFPACK(umf, UMF_FUNCS)

typedef struct sparse_backend {
  int n, nnz;
  int *Ap, *Ai;    /* owned copy of the pattern: Ap[n+1], Ai[nnz] */
  void *symbolic;  /* UMFPACK symbolic object, from alloc */
  void *numeric;   /* UMFPACK numeric object of the last factor, or NULL */
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  int *Wi;         /* wsolve workspace Wi[n] */
  double *W;       /* wsolve workspace W[5n] (iterative refinement on) */
  double *x;       /* x[n]: wsolve needs distinct right-hand side and result */
  char unbound[200]; /* why UMFPACK could not be opened ("" when it was) */
} sparse_backend;

int whirl_csc_check(size_t n, const int *Ap, const int *Ai) {
  size_t j;
  int p;
  if (!Ap || n > (size_t)INT_MAX) return 0;
  if (Ap[0] != 0) return 0;
  for (j = 0; j < n; ++j)
    if (Ap[j + 1] < Ap[j]) return 0;
  if (Ap[n] > 0 && !Ai) return 0;
  for (j = 0; j < n; ++j) {
    for (p = Ap[j]; p < Ap[j + 1]; ++p) {
      if (Ai[p] < 0 || (size_t)Ai[p] >= n) return 0;
      /* Sorted and without duplicates, as UMFPACK requires. */
      if (p > Ap[j] && Ai[p] <= Ai[p - 1]) return 0;
    }
  }
  return 1;
}

static void sparse_free(void *backend) {
  sparse_backend *s = backend;
  if (!s) return;
  if (s->numeric) umf.umfpack_di_free_numeric(&s->numeric);
  if (s->symbolic) umf.umfpack_di_free_symbolic(&s->symbolic);
  free(s->Ap);
  free(s->Ai);
  free(s->Wi);
  free(s->W);
  free(s->x);
  free(s);
}

static int sparse_factor(whirl_linsol *ls) {
  sparse_backend *s = ls->backend;
  int status;
  if (s->unbound[0]) return WHIRL_FAIL(ls, WHIRL_ENOLIB, "UMFPACK: %s", s->unbound);
  if (s->numeric) umf.umfpack_di_free_numeric(&s->numeric);
  status = umf.umfpack_di_numeric(s->Ap, s->Ai, ls->vals, s->symbolic, &s->numeric,
                              s->control, s->info);
  if (status == UMFPACK_OK) return WHIRL_OK;
  if (status == UMFPACK_WARNING_singular_matrix)
    /* The numeric object is valid (determinant 0), solves are refused. */
    return WHIRL_FAIL(ls, WHIRL_ESINGULAR,
                      "umfpack_di_numeric: matrix is exactly singular "
                      "(n = %d, nnz = %d)", s->n, s->nnz);
  if (s->numeric) umf.umfpack_di_free_numeric(&s->numeric);
  if (status == UMFPACK_ERROR_out_of_memory)
    return WHIRL_FAIL(ls, WHIRL_ENOMEM,
                      "umfpack_di_numeric: out of memory (n = %d, nnz = %d)",
                      s->n, s->nnz);
  return WHIRL_FAIL(ls, WHIRL_ESPARSE, "umfpack_di_numeric failed, status %d",
                    status);
}

int whirl_linsol_set_refinement(whirl_linsol *ls, int steps) {
  if (!ls || steps < 0) return WHIRL_EINVAL;
  if (ls->kind != WHIRL_LINSOL_SPARSE) return WHIRL_OK;
  sparse_backend *s = ls->backend;
  s->control[UMFPACK_IRSTEP] = steps;
  return WHIRL_OK;
}

static int sparse_solve(whirl_linsol *ls, double *B, size_t nrhs, int trans) {
  sparse_backend *s = ls->backend;
  /* For a real matrix UMFPACK_At (conjugate transpose) is the transpose. */
  const int sys = trans ? UMFPACK_At : UMFPACK_A;
  const size_t n = ls->n;
  size_t k;
  if (s->unbound[0]) return WHIRL_FAIL(ls, WHIRL_ENOLIB, "UMFPACK: %s", s->unbound);
  for (k = 0; k < nrhs; ++k) {
    double *b = B + k * n;
    int status;
    memcpy(s->x, b, n * sizeof *b);
    status = umf.umfpack_di_wsolve(sys, s->Ap, s->Ai, ls->vals, b, s->x,
                               s->numeric, s->control, s->info, s->Wi, s->W);
    if (status == UMFPACK_WARNING_singular_matrix)
      return WHIRL_FAIL(ls, WHIRL_ESINGULAR,
                        "umfpack_di_wsolve: matrix is singular");
    if (status != UMFPACK_OK)
      return WHIRL_FAIL(ls, WHIRL_ESPARSE,
                        "umfpack_di_wsolve failed on column %zu, status %d", k,
                        status);
  }
  return WHIRL_OK;
}

/* UMFPACK returns det A = Mx * 10^Ex with 1 <= |Mx| < 10, including the
 * row scaling and the signs of both permutations, so nothing overflows. */
static int sparse_logdet(const whirl_linsol *ls, double *logabs, int *sign) {
  const sparse_backend *s = ls->backend;
  double mx = 0.0, ex = 0.0, info[UMFPACK_INFO];
  if (s->unbound[0]) { /* never factored */
    *logabs = 0.0;
    *sign = 0;
    return WHIRL_ENOLIB;
  }
  int status = umf.umfpack_di_get_determinant(&mx, &ex, s->numeric, info);
  if (status != UMFPACK_OK && status != UMFPACK_WARNING_singular_matrix) {
    *logabs = 0.0;
    *sign = 0;
    return WHIRL_ESPARSE;
  }
  *sign = (mx > 0.0) - (mx < 0.0);
  *logabs = *sign ? log(fabs(mx)) + ex * log(10.0) : -HUGE_VAL;
  return WHIRL_OK;
}

static const whirl_linsol_ops sparse_ops = {sparse_factor, sparse_solve,
                                            sparse_logdet, sparse_free};

whirl_linsol *whirl_linsol_alloc_sparse(size_t n, const int *Ap,
                                        const int *Ai) {
  whirl_linsol *ls;
  sparse_backend *s;
  size_t nnz;
  int status;
  /* whirl_csc_check bounds n and nnz by INT_MAX; W[5n] must be allocatable. */
  if (n == 0 || n > SIZE_MAX / (5 * sizeof(double)) ||
      !whirl_csc_check(n, Ap, Ai))
    return NULL;
  nnz = (size_t)Ap[n];
  ls = whirl_linsol_new(WHIRL_LINSOL_SPARSE, n, nnz);
  if (!ls) return NULL;
  ls->ops = &sparse_ops;
  ls->backend = s = calloc(1, sizeof *s);
  if (!s) goto fail;
  s->n = (int)n;
  s->nnz = (int)nnz;
  s->Ap = malloc((n + 1) * sizeof *s->Ap);
  s->Ai = malloc((nnz ? nnz : 1) * sizeof *s->Ai);
  s->Wi = malloc(n * sizeof *s->Wi);
  s->W = malloc(5 * n * sizeof *s->W);
  s->x = malloc(n * sizeof *s->x);
  if (!s->Ap || !s->Ai || !s->Wi || !s->W || !s->x) goto fail;
  memcpy(s->Ap, Ap, (n + 1) * sizeof *Ap);
  if (nnz) memcpy(s->Ai, Ai, nnz * sizeof *Ai);
  /* without UMFPACK the object is made, and its first factor says why */
  if (umf_bind(s->unbound, sizeof s->unbound) != WHIRL_OK) return ls;
  umf.umfpack_di_defaults(s->control);
  /* Symbolic analysis (column ordering, supernodes) depends on the pattern
   * only; Ax = NULL makes UMFPACK treat every stored entry as nonzero, so
   * the analysis stays valid for all later values on this pattern. */
  status = umf.umfpack_di_symbolic(s->n, s->n, s->Ap, s->Ai, NULL, &s->symbolic,
                               s->control, s->info);
  if (status != UMFPACK_OK) goto fail;
  return ls;
fail:
  whirl_linsol_free(ls);
  return NULL;
}

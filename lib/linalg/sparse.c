/* linalg/sparse.c — sparse backend of whirl_linsol on SuiteSparse's KLU
 * (Davis & Palamadai Natarajan, ACM TOMS 37(3), 2010: a block triangular
 * form, AMD on each block, left-looking Gilbert-Peierls LU with partial
 * pivoting) or UMFPACK (Davis, ACM TOMS 30(2), 2004: multifrontal, BLAS
 * on the fronts).  The fill-reducing analysis is done once at alloc from
 * the compressed-column pattern alone; each factor is a numeric
 * factorisation of new values on that pattern (KLU: in the last pivot
 * order while its pivots do not grow, klu_refactor).  KLU is the default: on
 * collocation and FE patterns of a few hundred to a few thousand unknowns
 * its factorisation is 3-4x UMFPACK's speed (doc/benchmarks.md, the
 * sparse LU); WHIRL_SPARSE_LU=umfpack in the environment takes UMFPACK
 * (with its iterative refinement, umfpack_di_wsolve), for comparisons.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(HAVE_UMFPACK_H) && !defined(HAVE_SUITESPARSE_UMFPACK_H)
#include <klu.h>
#include <umfpack.h>
#else
#include <suitesparse/klu.h>
#include <suitesparse/umfpack.h>
#endif

#ifdef HAVE_CONFIG_H
#include "config.h"
#endif
#include <whirl/dynlib.h>

#include "linsol_impl.h"

/* UMFPACK and KLU (configure puts both in UMFPACK's libraries), opened at
 * the first sparse matrix (whirl/dynlib.h) */
#define UMF_FUNCS(X)                                                           \
  X(umfpack_di_defaults) X(umfpack_di_symbolic) X(umfpack_di_numeric)           \
  X(umfpack_di_wsolve) X(umfpack_di_get_determinant) X(umfpack_di_free_numeric) \
  X(umfpack_di_free_symbolic) X(klu_defaults) X(klu_analyze) X(klu_factor)      \
  X(klu_solve) X(klu_tsolve) X(klu_free_symbolic) X(klu_free_numeric) X(klu_rgrowth) \
  X(klu_refactor)
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
  int klu;         /* KLU (1) or UMFPACK (0) */
  klu_common kc;
  klu_symbolic *ks; /* KLU's analysis, from alloc */
  klu_numeric *kn;  /* KLU's factors of the last factor, or NULL */
  int cur_umf;      /* the last factors are UMFPACK's (KLU's pivots grew) */
  double rgrowth0;  /* the reciprocal pivot growth of KLU's last klu_factor */
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
  if (s->kn) umf.klu_free_numeric(&s->kn, &s->kc);
  if (s->ks) umf.klu_free_symbolic(&s->ks, &s->kc);
  free(s->Ap);
  free(s->Ai);
  free(s->Wi);
  free(s->W);
  free(s->x);
  free(s);
}

/* KLU's factors are kept where their reciprocal pivot growth (klu_rgrowth:
 * min over columns of max |scaled A| / max |U|) is at least this: KLU's
 * pivoting prefers the diagonal (tol 0.001, which keeps its speed) and on
 * the complex bordered matrix of a torus locus grew its pivots by 1e28
 * (test/regress/torus_locus.sh) where LAPACK's largest pivot was 10; a
 * factorisation grown beyond is redone by UMFPACK. */
#define KLU_MIN_RGROWTH 1e-8

/* UMFPACK's factors of ls->vals (its analysis made at the first call). */
static int umf_factor_values(whirl_linsol *ls) {
  sparse_backend *s = ls->backend;
  if (!s->symbolic) {
    const int st = umf.umfpack_di_symbolic(s->n, s->n, s->Ap, s->Ai, NULL, &s->symbolic,
                                           s->control, s->info);
    if (st != UMFPACK_OK)
      return WHIRL_FAIL(ls, st == UMFPACK_ERROR_out_of_memory ? WHIRL_ENOMEM : WHIRL_ESPARSE,
                        "umfpack_di_symbolic failed, status %d", st);
  }
  if (s->numeric) umf.umfpack_di_free_numeric(&s->numeric);
  const int status = umf.umfpack_di_numeric(s->Ap, s->Ai, ls->vals, s->symbolic, &s->numeric,
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

/* KLU's factors of ls->vals, or UMFPACK's where KLU's pivots grew or met
 * a zero (s->cur_umf says whose factors solve and logdet use): a matrix
 * is singular when UMFPACK says so. */
/* KLU's factors usable: no zero pivot, the reciprocal pivot growth at
 * least min_rgrowth (klu_rgrowth into s->kc.rgrowth). */
static int klu_factors_good(sparse_backend *s, const double *vals, double min_rgrowth) {
  int good = s->kn && s->kc.status == KLU_OK;
  for (int k = 0; good && k < s->n; ++k) good = ((double *)s->kn->Udiag)[k] != 0.0;
  return good && umf.klu_rgrowth(s->Ap, s->Ai, (double *)vals, s->ks, s->kn, &s->kc) &&
         s->kc.rgrowth >= min_rgrowth;
}

static int klu_factor_values(whirl_linsol *ls) {
  sparse_backend *s = ls->backend;
  /* the last factorisation's pivot order for the new values (klu_refactor:
   * Newton's matrices change little from one iteration to the next), kept
   * while their pivots grow at most 100x more than that factorisation's */
  if (s->kn && !s->cur_umf &&
      umf.klu_refactor(s->Ap, s->Ai, ls->vals, s->ks, s->kn, &s->kc) &&
      klu_factors_good(s, ls->vals, fmax(KLU_MIN_RGROWTH, 1e-2 * s->rgrowth0)))
    return WHIRL_OK;
  if (s->kn) umf.klu_free_numeric(&s->kn, &s->kc);
  s->kn = umf.klu_factor(s->Ap, s->Ai, ls->vals, s->ks, &s->kc);
  if (!s->kn && s->kc.status == KLU_OUT_OF_MEMORY)
    return WHIRL_FAIL(ls, WHIRL_ENOMEM, "klu_factor: out of memory (n = %d, nnz = %d)",
                      s->n, s->nnz);
  /* a zero pivot: KLU_SINGULAR, or a zero on U's diagonal with the status
   * OK (KLU 1.3 after its pivots grew) */
  const int good = klu_factors_good(s, ls->vals, KLU_MIN_RGROWTH);
  s->rgrowth0 = s->kc.rgrowth;
  s->cur_umf = !good;
  if (good) return WHIRL_OK;
  if (s->kn) umf.klu_free_numeric(&s->kn, &s->kc);
  return umf_factor_values(ls);
}

static int sparse_factor(whirl_linsol *ls) {
  sparse_backend *s = ls->backend;
  if (s->unbound[0]) return WHIRL_FAIL(ls, WHIRL_ENOLIB, "UMFPACK: %s", s->unbound);
  return s->klu ? klu_factor_values(ls) : umf_factor_values(ls);
}

int whirl_linsol_set_refinement(whirl_linsol *ls, int steps) {
  if (!ls || steps < 0) return WHIRL_EINVAL;
  if (ls->kind != WHIRL_LINSOL_SPARSE) return WHIRL_OK;
  sparse_backend *s = ls->backend;
  s->control[UMFPACK_IRSTEP] = steps;
  return WHIRL_OK;
}

/* x = A^-1 b (A^-T b) in place by KLU's factors. */
static int klu_solve_once(whirl_linsol *ls, double *x, int trans) {
  sparse_backend *s = ls->backend;
  const int ok = trans ? umf.klu_tsolve(s->ks, s->kn, s->n, 1, x, &s->kc)
                       : umf.klu_solve(s->ks, s->kn, s->n, 1, x, &s->kc);
  return ok ? WHIRL_OK
            : WHIRL_FAIL(ls, WHIRL_ESPARSE, "klu_%ssolve failed, status %d", trans ? "t" : "",
                         s->kc.status);
}

/* The residual r = b - op(A) x and the componentwise backward error
 * max_i |r_i| / (|op(A)| |x| + |b|)_i (Oettli & Prager; r and den in W). */
static double backward_error(const whirl_linsol *ls, const double *b, const double *x,
                             int trans, double *r, double *den) {
  const sparse_backend *s = ls->backend;
  const double *A = ls->vals;
  const int n = s->n;
  const int *Ap = s->Ap, *Ai = s->Ai;
  for (int i = 0; i < n; ++i) r[i] = b[i], den[i] = fabs(b[i]);
  /* the two orientations apart, each entry's operations in the same order
   * as one loop with the row and column chosen per entry (the same bits),
   * without that choice in the inner loop (a refined solve's residuals
   * were as costly as its solves on the fold loci of orbits) */
  if (trans) {
    for (int j = 0; j < n; ++j) {
      double rj = r[j], dj = den[j];
      for (int q = Ap[j]; q < Ap[j + 1]; ++q) {
        const double t = A[q] * x[Ai[q]];
        rj -= t;
        dj += fabs(t);
      }
      r[j] = rj, den[j] = dj;
    }
  } else {
    for (int j = 0; j < n; ++j) {
      const double xj = x[j];
      for (int q = Ap[j]; q < Ap[j + 1]; ++q) {
        const double t = A[q] * xj;
        r[Ai[q]] -= t;
        den[Ai[q]] += fabs(t);
      }
    }
  }
  double berr = 0.0;
  for (int i = 0; i < n; ++i)
    if (den[i] > 0.0) berr = fmax(berr, fabs(r[i]) / den[i]);
    else if (r[i] != 0.0) return HUGE_VAL;
  return berr;
}

/* One right-hand side by KLU with iterative refinement, as UMFPACK's
 * (its IRSTEP steps at most, 2 by default): a step while the backward
 * error exceeds the rounding unit and the last step at least halved it.
 * KLU itself has none; without it a pivot 1e-3 of its column cost three
 * digits (t_linalg). */
static int klu_solve_refined(whirl_linsol *ls, double *x, int trans) {
  sparse_backend *s = ls->backend;
  const int n = s->n, steps = (int)s->control[UMFPACK_IRSTEP];
  double *b = s->W, *r = s->W + n, *den = s->W + 2 * n;
  memcpy(b, x, (size_t)n * sizeof *b);
  int rc = klu_solve_once(ls, x, trans);
  double last = HUGE_VAL;
  for (int step = 0; rc == WHIRL_OK && step < steps; ++step) {
    const double berr = backward_error(ls, b, x, trans, r, den);
    if (!(berr > DBL_EPSILON) || berr > 0.5 * last) break;
    last = berr;
    if ((rc = klu_solve_once(ls, r, trans)) == WHIRL_OK)
      for (int i = 0; i < n; ++i) x[i] += r[i];
  }
  return rc;
}

static int sparse_solve(whirl_linsol *ls, double *B, size_t nrhs, int trans) {
  sparse_backend *s = ls->backend;
  /* For a real matrix UMFPACK_At (conjugate transpose) is the transpose. */
  const int sys = trans ? UMFPACK_At : UMFPACK_A;
  const size_t n = ls->n;
  size_t k;
  if (s->unbound[0]) return WHIRL_FAIL(ls, WHIRL_ENOLIB, "UMFPACK: %s", s->unbound);
  if (s->klu && !s->cur_umf) {
    for (k = 0; k < nrhs; ++k) {
      int rc = klu_solve_refined(ls, B + k * n, trans);
      if (rc) return rc;
    }
    return WHIRL_OK;
  }
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

/* The sign of the permutation p[n]: (-1)^(n - its cycles); seen[n]
 * workspace. */
static int perm_parity(const int *p, int n, int *seen) {
  int sign = 1;
  memset(seen, 0, (size_t)n * sizeof *seen);
  for (int i = 0; i < n; ++i) {
    if (seen[i]) continue;
    int len = 0;
    for (int j = i; !seen[j]; j = p[j]) seen[j] = 1, ++len;
    if (len % 2 == 0) sign = -sign;
  }
  return sign;
}

/* KLU factors P (R \ A) Q = L U + F, F strictly above the block diagonal
 * and L unit lower triangular, so det A = prod Rs_i sign(P) sign(Q) prod
 * diag U (Rs: the row scaling, none when scale = 0), summed in logs. */
static int klu_logdet(const sparse_backend *s, double *logabs, int *sign) {
  const klu_numeric *N = s->kn;
  const double *ud = N->Udiag;
  /* Wi: UMFPACK's solve workspace, free while KLU's factors are used */
  int sg = perm_parity(N->Pnum, s->n, s->Wi) * perm_parity(s->ks->Q, s->n, s->Wi);
  double la = 0.0;
  for (int k = 0; k < s->n; ++k) {
    if (ud[k] == 0.0 || !isfinite(ud[k])) {
      *logabs = -HUGE_VAL;
      *sign = 0;
      return WHIRL_OK;
    }
    if (ud[k] < 0.0) sg = -sg;
    la += log(fabs(ud[k]));
    if (N->Rs) la += log(N->Rs[k]);
  }
  *logabs = la;
  *sign = sg;
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
  if (s->klu && !s->cur_umf) return klu_logdet(s, logabs, sign);
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
  const char *lu = getenv("WHIRL_SPARSE_LU");
  s->klu = !(lu && !strcmp(lu, "umfpack"));
  umf.umfpack_di_defaults(s->control); /* IRSTEP 2: both backends' refinement */
  if (s->klu) { /* UMFPACK's analysis when KLU first leaves it a matrix */
    umf.klu_defaults(&s->kc);
    s->kc.halt_if_singular = 0; /* a singular matrix's factors, for its det */
    s->ks = umf.klu_analyze(s->n, s->Ap, s->Ai, &s->kc);
    if (!s->ks) goto fail;
    return ls;
  }
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

/* test/unit/t_linalg.c — unit tests of lib/linalg against analytic anchors:
 * dense and sparse LU solves with a known solution, determinants of known
 * sign and size (beyond the range of a double), bordered systems around a
 * singular A, eigenvalues of matrices with known spectrum, null vectors of a
 * known null space, and every error path provoked on purpose.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <unistd.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/linsol.h>

#include "../tap.h"

/* uniform in [-1, 1) from the shared generator of tap.h */
static double urand(void) { return tap_urand(-1.0, 1.0); }

static void *xcalloc(size_t n, size_t size) {
  void *p = calloc(n ? n : 1, size);
  if (!p) {
    fprintf(stderr, "t_linalg: out of memory\n");
    exit(99); /* TAP hard error; test code, not library code */
  }
  return p;
}

/* y = A x (trans = 0) or A^T x (trans = 1), A n x n column-major. */
static void matvec(size_t n, const double *A, const double *x, double *y,
                   int trans) {
  size_t i, j;
  for (i = 0; i < n; ++i) y[i] = 0.0;
  for (j = 0; j < n; ++j)
    for (i = 0; i < n; ++i) {
      if (trans)
        y[j] += A[i + n * j] * x[i];
      else
        y[i] += A[i + n * j] * x[j];
    }
}

/* max_i |a_i - b_i| / max_i |b_i| */
static double relerr(size_t n, const double *a, const double *b) {
  double num = 0.0, den = 0.0;
  size_t i;
  for (i = 0; i < n; ++i) {
    if (!isfinite(a[i])) return HUGE_VAL;
    if (fabs(a[i] - b[i]) > num) num = fabs(a[i] - b[i]);
    if (fabs(b[i]) > den) den = fabs(b[i]);
  }
  return den > 0.0 ? num / den : num;
}

/* Compressed-column copy of the entries of dense A[n*n] flagged in mask;
 * Ap[n+1], Ai and Ax are allocated here. */
static void dense_to_csc(size_t n, const double *A, const unsigned char *mask,
                         int **Ap, int **Ai, double **Ax) {
  size_t i, j, nnz = 0, q = 0;
  for (i = 0; i < n * n; ++i) nnz += mask[i] != 0;
  *Ap = xcalloc(n + 1, sizeof **Ap);
  *Ai = xcalloc(nnz, sizeof **Ai);
  *Ax = xcalloc(nnz, sizeof **Ax);
  for (j = 0; j < n; ++j) {
    (*Ap)[j] = (int)q;
    for (i = 0; i < n; ++i)
      if (mask[i + n * j]) {
        (*Ai)[q] = (int)i;
        (*Ax)[q++] = A[i + n * j];
      }
  }
  (*Ap)[n] = (int)q;
}

/* ------------------------------------------------------------------------ */
static void test_dense_solve(void) {
  enum { N = 50, NRHS = 3 };
  whirl_linsol *ls = whirl_linsol_alloc_dense(N);
  double *A = xcalloc(N * N, sizeof *A), *X = xcalloc(N * NRHS, sizeof *X);
  double *B = xcalloc(N * NRHS, sizeof *B);
  size_t i, k;
  int rc, trans;
  ok(ls != NULL, "dense alloc n = %d", N);
  ok(whirl_linsol_get_kind(ls) == WHIRL_LINSOL_DENSE &&
         whirl_linsol_size(ls) == N, "dense kind and size");
  /* Random entries in [-1, 1) plus N on the diagonal: strictly diagonally
   * dominant, condition number O(1). */
  for (i = 0; i < N * N; ++i) A[i] = urand();
  for (i = 0; i < N; ++i) A[i + N * i] += N;
  for (i = 0; i < N * NRHS; ++i) X[i] = urand();
  rc = whirl_linsol_factor(ls, A);
  ok(rc == WHIRL_OK, "dense factor: rc %d '%s'", rc, whirl_linsol_errmsg(ls));
  ok(whirl_linsol_errmsg(ls)[0] == '\0', "errmsg empty after success");
  /* The matrix is copied: clobbering the caller's array must not matter. */
  {
    double *Acopy = xcalloc(N * N, sizeof *Acopy);
    memcpy(Acopy, A, N * N * sizeof *A);
    for (trans = 0; trans <= 1; ++trans) {
      for (k = 0; k < NRHS; ++k) matvec(N, Acopy, X + N * k, B + N * k, trans);
      for (i = 0; i < N * N; ++i) A[i] = 0.0;
      rc = whirl_linsol_solve(ls, B, NRHS, trans);
      ok(rc == WHIRL_OK, "dense solve trans=%d rc %d", trans, rc);
      ok(relerr(N * NRHS, B, X) < 1e-12, "dense solve trans=%d: rel err %.2e",
         trans, relerr(N * NRHS, B, X));
      memcpy(A, Acopy, N * N * sizeof *A);
    }
    free(Acopy);
  }
  whirl_linsol_free(ls);
  free(A);
  free(B);
  free(X);
}

/* A = P L U with known diag(U): det A = det(P) prod U(i,i).  n = 200 and
 * |U(i,i)| ~ e^5 make |det A| ~ e^1000, far beyond DBL_MAX. */
static void test_dense_logdet(void) {
  enum { N = 200 };
  whirl_linsol *ls = whirl_linsol_alloc_dense(N);
  double *L = xcalloc(N * N, sizeof *L), *U = xcalloc(N * N, sizeof *U);
  double *LU = xcalloc(N * N, sizeof *LU), *A = xcalloc(N * N, sizeof *A);
  /* P: swap rows 0 and 1 (odd) and cycle rows 2 -> 3 -> 4 -> 2 (even). */
  size_t perm[N];
  double want_log = 0.0, logabs = 0.0;
  int want_sign = -1, sign = 0, rc;
  size_t i, j, k;
  for (i = 0; i < N; ++i) perm[i] = i;
  perm[0] = 1, perm[1] = 0, perm[2] = 3, perm[3] = 4, perm[4] = 2;
  for (j = 0; j < N; ++j) {
    L[j + N * j] = 1.0;
    for (i = j + 1; i < N; ++i) L[i + N * j] = 0.1 * urand() / N;
    for (i = 0; i < j; ++i) U[i + N * j] = 0.1 * urand();
    {
      const double t = 5.0 + urand(), s = (j % 7 == 3) ? -1.0 : 1.0;
      U[j + N * j] = s * exp(t);
      want_log += t;
      if (s < 0) want_sign = -want_sign;
    }
  }
  for (j = 0; j < N; ++j)
    for (k = 0; k <= j; ++k)
      for (i = k; i < N; ++i) LU[i + N * j] += L[i + N * k] * U[k + N * j];
  for (j = 0; j < N; ++j)
    for (i = 0; i < N; ++i) A[perm[i] + N * j] = LU[i + N * j];
  rc = whirl_linsol_factor(ls, A);
  ok(rc == WHIRL_OK, "P L U factor rc %d", rc);
  rc = whirl_linsol_logdet(ls, &logabs, &sign);
  ok(rc == WHIRL_OK, "logdet rc %d", rc);
  ok(want_log > 709.8, "test matrix has |det| > DBL_MAX (log %g)", want_log);
  is_rel(logabs, want_log, 1e-12, "log|det(P L U)|, n = %d", N);
  ok(sign == want_sign, "sign det(P L U) = %d (want %d)", sign, want_sign);
  whirl_linsol_free(ls);
  free(L);
  free(U);
  free(LU);
  free(A);
}

/* Permutation times diagonal, 5 x 5, both backends: det = sign(P) prod d. */
static void test_perm_diag_logdet(void) {
  const size_t perm[5] = {1, 0, 3, 4, 2}; /* transposition + 3-cycle: odd */
  const double d[5] = {2.0, -3.0, 0.5, 4.0, -1.0}; /* prod = 12 */
  double A[25] = {0};
  unsigned char mask[25] = {0};
  int *Ap, *Ai, kind;
  double *Ax;
  size_t j;
  for (j = 0; j < 5; ++j) {
    A[perm[j] + 5 * j] = d[j];
    mask[perm[j] + 5 * j] = 1;
  }
  dense_to_csc(5, A, mask, &Ap, &Ai, &Ax);
  for (kind = 0; kind <= 1; ++kind) {
    whirl_linsol *ls = kind ? whirl_linsol_alloc_sparse(5, Ap, Ai)
                            : whirl_linsol_alloc_dense(5);
    double logabs = 0.0;
    int sign = 0, rc = whirl_linsol_factor(ls, kind ? Ax : A);
    ok(rc == WHIRL_OK, "%s P*D factor rc %d", kind ? "sparse" : "dense", rc);
    whirl_linsol_logdet(ls, &logabs, &sign);
    is_rel(logabs, log(12.0), 1e-14, "%s log|det(P D)| = log 12",
           kind ? "sparse" : "dense");
    ok(sign == -1, "%s sign det(P D) = %d (want -1)",
       kind ? "sparse" : "dense", sign);
    whirl_linsol_free(ls);
  }
  free(Ap);
  free(Ai);
  free(Ax);
}

/* Random sparse N x N: tridiagonal plus 3 random entries per column,
 * strictly diagonally dominant by rows with random diagonal signs. */
static void random_sparse(size_t n, double *A, const unsigned char *mask) {
  size_t i, j;
  for (i = 0; i < n * n; ++i) A[i] = mask[i] ? urand() : 0.0;
  for (i = 0; i < n; ++i) {
    double rowsum = 0.0;
    for (j = 0; j < n; ++j)
      if (j != i) rowsum += fabs(A[i + n * j]);
    A[i + n * i] = (urand() < 0 ? -1.0 : 1.0) * (rowsum + 1.0 + urand());
  }
}

static void test_dense_vs_sparse(void) {
  enum { N = 200, NRHS = 2 };
  double *A = xcalloc(N * N, sizeof *A), *X = xcalloc(N * NRHS, sizeof *X);
  double *Bd = xcalloc(N * NRHS, sizeof *Bd);
  double *Bs = xcalloc(N * NRHS, sizeof *Bs);
  unsigned char *mask = xcalloc(N * N, 1);
  whirl_linsol *ld = whirl_linsol_alloc_dense(N), *lsp;
  int *Ap, *Ai, round, trans;
  double *Ax;
  size_t i, j, k;
  for (j = 0; j < N; ++j) {
    for (i = (j ? j - 1 : 0); i <= j + 1 && i < N; ++i) mask[i + N * j] = 1;
    for (k = 0; k < 3; ++k)
      mask[(size_t)((urand() + 1.0) * 0.5 * N) % N + N * j] = 1;
  }
  random_sparse(N, A, mask);
  dense_to_csc(N, A, mask, &Ap, &Ai, &Ax);
  lsp = whirl_linsol_alloc_sparse(N, Ap, Ai);
  ok(lsp != NULL, "sparse alloc n = %d, nnz = %d", N, Ap[N]);
  ok(whirl_linsol_get_kind(lsp) == WHIRL_LINSOL_SPARSE &&
         whirl_linsol_size(lsp) == N, "sparse kind and size");
  /* Round 0: first values; round 1: new values on the same pattern, so the
   * symbolic analysis from alloc is reused by the second factorisation. */
  for (round = 0; round < 2; ++round) {
    double la = 0.0, ls_ = 0.0;
    int sa = 0, ss = 0, rc;
    if (round == 1) {
      /* and without iterative refinement: still the exact x to 1e-12 */
      ok(whirl_linsol_set_refinement(lsp, 0) == WHIRL_OK &&
             whirl_linsol_set_refinement(lsp, -1) == WHIRL_EINVAL &&
             whirl_linsol_set_refinement(ld, 0) == WHIRL_OK,
         "refinement steps: 0 accepted, -1 refused, dense unaffected");
      random_sparse(N, A, mask);
      for (j = 0, k = 0; j < N; ++j)
        for (i = 0; i < N; ++i)
          if (mask[i + N * j]) Ax[k++] = A[i + N * j];
    }
    rc = whirl_linsol_factor(ld, A);
    ok(rc == WHIRL_OK, "round %d: dense factor rc %d", round, rc);
    rc = whirl_linsol_factor(lsp, Ax);
    ok(rc == WHIRL_OK, "round %d: sparse factor rc %d '%s'", round, rc,
       whirl_linsol_errmsg(lsp));
    for (trans = 0; trans <= 1; ++trans) {
      for (i = 0; i < N * NRHS; ++i) X[i] = urand();
      for (k = 0; k < NRHS; ++k) matvec(N, A, X + N * k, Bd + N * k, trans);
      memcpy(Bs, Bd, sizeof(double) * N * NRHS);
      ok(whirl_linsol_solve(ld, Bd, NRHS, trans) == WHIRL_OK &&
             whirl_linsol_solve(lsp, Bs, NRHS, trans) == WHIRL_OK,
         "round %d trans %d: both solves succeed", round, trans);
      ok(relerr(N * NRHS, Bs, X) < 1e-12,
         "round %d trans %d: sparse vs exact x, rel err %.2e", round, trans,
         relerr(N * NRHS, Bs, X));
      ok(relerr(N * NRHS, Bs, Bd) < 1e-12,
         "round %d trans %d: sparse vs dense x, rel err %.2e", round, trans,
         relerr(N * NRHS, Bs, Bd));
    }
    whirl_linsol_logdet(ld, &la, &sa);
    whirl_linsol_logdet(lsp, &ls_, &ss);
    is_rel(ls_, la, 1e-12, "round %d: sparse log|det| = dense log|det|",
           round);
    ok(ss == sa && sa != 0, "round %d: same sign of det (%d, %d)", round, ss,
       sa);
  }
  whirl_linsol_free(ld);
  whirl_linsol_free(lsp);
  free(Ap);
  free(Ai);
  free(Ax);
  free(A);
  free(X);
  free(Bd);
  free(Bs);
  free(mask);
}

/* ------------------------------------------------------------------------
 * Bordered: A = 1-D Neumann Laplacian tridiag(-1, 2, -1) with corners 1,
 * symmetric with null vector (1, ..., 1), rank n - 1, and exactly singular
 * in floating point (all pivots are integers, the last is 0).  Borders of
 * width m = 1 (B = C^T = ones, D = 0: the classic fold extension) or m = 2
 * (random) make M nonsingular.  Reference: dense solve of M assembled here. */
static void neumann(size_t n, double *A, unsigned char *mask) {
  size_t i;
  memset(A, 0, n * n * sizeof *A);
  for (i = 0; i < n; ++i) {
    A[i + n * i] = (i == 0 || i == n - 1) ? 1.0 : 2.0;
    if (i + 1 < n) A[i + 1 + n * i] = A[i + n * (i + 1)] = -1.0;
  }
  for (i = 0; i < n * n; ++i) mask[i] = A[i] != 0.0;
}

static void test_bordered(void) {
  /* n = 16 keeps cond(M) ~ 1e2 (A's smallest nonzero eigenvalue is
   * 4 sin^2(pi/32) ~ 0.04), so two backward-stable solves agree to 1e-12. */
  enum { N = 16, MMAX = 2, NRHS = 2 };
  const size_t NM = N + MMAX;
  double *A = xcalloc(N * N, sizeof *A), *M = xcalloc(NM * NM, sizeof *M);
  double B[N * MMAX], C[MMAX * N], D[MMAX * MMAX];
  double *R = xcalloc(NM * NRHS, sizeof *R), *Rref = xcalloc(NM * NRHS, sizeof *Rref);
  unsigned char *mask = xcalloc(N * N, 1);
  int *Ap, *Ai, kind, rc;
  double *Ax;
  size_t m, i, j;
  neumann(N, A, mask);
  dense_to_csc(N, A, mask, &Ap, &Ai, &Ax);
  {
    whirl_linsol *la = whirl_linsol_alloc_dense(N);
    whirl_linsol *ls = whirl_linsol_alloc_sparse(N, Ap, Ai);
    ok(whirl_linsol_factor(la, A) == WHIRL_ESINGULAR,
       "Neumann Laplacian A alone: dense factor -> ESINGULAR");
    rc = whirl_linsol_factor(ls, Ax);
    ok(rc == WHIRL_OK || rc == WHIRL_ESINGULAR,
       "Neumann Laplacian A alone: sparse factor rc %d", rc);
    whirl_linsol_free(la);
    whirl_linsol_free(ls);
  }
  for (m = 1; m <= MMAX; ++m) {
    const size_t K = N + m;
    whirl_linsol *ref = whirl_linsol_alloc_dense(K);
    whirl_bordered *bb[2];
    double ref_log = 0.0;
    int ref_sign = 0, round;
    for (kind = 0; kind <= 1; ++kind) {
      bb[kind] = whirl_bordered_alloc(
          kind ? WHIRL_LINSOL_SPARSE : WHIRL_LINSOL_DENSE, N, m,
          kind ? Ap : NULL, kind ? Ai : NULL);
      ok(bb[kind] != NULL, "%s bordered alloc n=%d m=%zu",
         kind ? "sparse" : "dense", N, m);
    }
    /* Round 1 refactors the same objects with new border values. */
    for (round = 0; round < 2; ++round) {
      for (i = 0; i < N * m; ++i) {
        B[i] = (m == 1 && round == 0) ? 1.0 : urand();
        C[i] = (m == 1 && round == 0) ? 1.0 : urand();
      }
      for (i = 0; i < m * m; ++i) D[i] = (m == 1 && round == 0) ? 0.0 : urand();
      memset(M, 0, NM * NM * sizeof *M);
      for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) M[i + K * j] = A[i + N * j];
      for (j = 0; j < m; ++j)
        for (i = 0; i < N; ++i) M[i + K * (N + j)] = B[i + N * j];
      for (j = 0; j < N; ++j)
        for (i = 0; i < m; ++i) M[N + i + K * j] = C[i + m * j];
      for (j = 0; j < m; ++j)
        for (i = 0; i < m; ++i) M[N + i + K * (N + j)] = D[i + m * j];
      rc = whirl_linsol_factor(ref, M);
      ok(rc == WHIRL_OK, "m=%zu round %d: reference factor of assembled M", m,
         round);
      whirl_linsol_logdet(ref, &ref_log, &ref_sign);
      for (kind = 0; kind <= 1; ++kind) {
        const char *kn = kind ? "sparse" : "dense";
        whirl_bordered *b = bb[kind];
        double la = 0.0;
        int sa = 0, trans;
        rc = whirl_bordered_factor(b, kind ? Ax : A, B, C, D);
        ok(rc == WHIRL_OK, "%s m=%zu round %d: bordered factor rc %d '%s'", kn,
           m, round, rc, whirl_bordered_errmsg(b));
        for (trans = 0; trans <= 1; ++trans) {
          for (i = 0; i < K * NRHS; ++i) R[i] = Rref[i] = urand();
          whirl_linsol_solve(ref, Rref, NRHS, trans);
          rc = whirl_bordered_solve(b, R, NRHS, trans);
          ok(rc == WHIRL_OK && relerr(K * NRHS, R, Rref) < 1e-12,
             "%s m=%zu round %d trans %d: bordered vs assembled, rel err %.2e",
             kn, m, round, trans, relerr(K * NRHS, R, Rref));
        }
        whirl_bordered_logdet(b, &la, &sa);
        is_rel(la, ref_log, 1e-12, "%s m=%zu round %d: bordered log|det M|",
               kn, m, round);
        ok(sa == ref_sign && sa != 0, "%s m=%zu round %d: sign det M = %d", kn,
           m, round, sa);
      }
    }
    whirl_bordered_free(bb[0]);
    whirl_bordered_free(bb[1]);
    whirl_linsol_free(ref);
  }
  free(Ap);
  free(Ai);
  free(Ax);
  free(A);
  free(M);
  free(R);
  free(Rref);
  free(mask);
}

/* ------------------------------------------------------------------------
 * Eigenvalues. */
static void check_spectrum(size_t n, const double *A, const double *wre,
                           const double *wim, double tol, const char *what) {
  whirl_eig *e = whirl_eig_alloc(n);
  double *re = xcalloc(n, sizeof *re), *im = xcalloc(n, sizeof *im);
  double err = 0.0;
  size_t i;
  int rc, pairs_ok = 1;
  ok(e != NULL, "%s: eig alloc n = %zu", what, n);
  rc = whirl_eig_compute(e, A, re, im);
  ok(rc == WHIRL_OK, "%s: eig rc %d", what, rc);
  for (i = 0; i < n; ++i) {
    const double d = hypot(re[i] - wre[i], im[i] - wim[i]);
    if (!(d <= err)) err = isnan(d) ? HUGE_VAL : d; /* NaN never passes */
  }
  ok(err <= tol, "%s: sorted eigenvalues match, max err %.2e", what, err);
  for (i = 0; i < n; ++i) {
    if (im[i] > 0.0) {
      pairs_ok &= i + 1 < n && re[i + 1] == re[i] && im[i + 1] == -im[i];
      ++i;
    } else if (im[i] < 0.0) {
      pairs_ok = 0;
    }
  }
  ok(pairs_ok, "%s: conjugate pairs adjacent, +imag first", what);
  whirl_eig_free(e);
  free(re);
  free(im);
}

static void test_eig(void) {
  /* Known spectrum: block diagonal K with real entries and rotation blocks
   * [a -b; b a] (eigenvalues a +- ib), conjugated: A = S K S^-1. */
  enum { N = 9 };
  const double blk[][2] = {/* a, b (0: real 1x1 block) */
                           {3.0, 0.0},  {1.0, 2.0}, {-0.5, 0.0},
                           {-2.0, 1.0}, {0.25, 3.0}, {0.0, 0.0}};
  const double wre[N] = {3.0, 1.0, 1.0, 0.25, 0.25, 0.0, -0.5, -2.0, -2.0};
  const double wim[N] = {0.0, 2.0, -2.0, 3.0, -3.0, 0.0, 0.0, 1.0, -1.0};
  double K[N * N] = {0}, S[N * N], SK[N * N], Y[N * N], A[N * N];
  whirl_linsol *ls = whirl_linsol_alloc_dense(N);
  size_t i, j, k, p = 0;
  for (k = 0; k < sizeof blk / sizeof blk[0]; ++k) {
    K[p + N * p] = blk[k][0];
    if (blk[k][1] != 0.0) {
      K[p + 1 + N * (p + 1)] = blk[k][0];
      K[p + N * (p + 1)] = -blk[k][1];
      K[p + 1 + N * p] = blk[k][1];
      ++p;
    }
    ++p;
  }
  for (i = 0; i < N * N; ++i) S[i] = 0.3 * urand();
  for (i = 0; i < N; ++i) S[i + N * i] += 1.0 + 0.3 * N;
  for (j = 0; j < N; ++j)
    for (i = 0; i < N; ++i) {
      SK[i + N * j] = 0.0;
      for (k = 0; k < N; ++k) SK[i + N * j] += S[i + N * k] * K[k + N * j];
    }
  /* A^T = S^-T (S K)^T: one transposed solve with the factors of S. */
  for (j = 0; j < N; ++j)
    for (i = 0; i < N; ++i) Y[i + N * j] = SK[j + N * i];
  whirl_linsol_factor(ls, S);
  whirl_linsol_solve(ls, Y, N, 1);
  for (j = 0; j < N; ++j)
    for (i = 0; i < N; ++i) A[i + N * j] = Y[j + N * i];
  whirl_linsol_free(ls);
  check_spectrum(N, A, wre, wim, 1e-10, "S K S^-1");

  /* Equal real parts: the tie-break keeps pairs together, larger |imag|
   * first, real eigenvalue last.  Already in real Schur form: exact. */
  {
    const double T[25] = {1, 0.5, 0, 0, 0, -0.5, 1, 0, 0, 0, 0, 0, 1,
                          2, 0,   0, 0, -2, 1, 0, 0, 0, 0, 0, 1};
    const double tre[5] = {1, 1, 1, 1, 1}, tim[5] = {2, -2, 0.5, -0.5, 0};
    check_spectrum(5, T, tre, tim, 1e-14, "equal real parts");
  }
  /* Companion matrix of (x-1)(x-2)(x^2+1) = x^4 - 3x^3 + 3x^2 - 3x + 2. */
  {
    const double Cm[16] = {0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -2, 3, -3, 3};
    const double cre[4] = {2, 1, 0, 0}, cim[4] = {0, 0, 1, -1};
    check_spectrum(4, Cm, cre, cim, 1e-10, "companion (x-1)(x-2)(x^2+1)");
  }
}

/* Null vectors of 2 x 3 matrices with known null spaces. */
static void test_null_vectors(void) {
  const double A[6] = {1, 4, 2, 5, 3, 6}; /* [1 2 3; 4 5 6], null (1,-2,1) */
  const double R1[6] = {1, 2, 1, 2, 1, 2}; /* [1 1 1; 2 2 2], rank 1 */
  double V[9], sv[3], Av[2], dot;
  size_t c;
  int rc = whirl_null_vectors(2, 3, A, 1, V, sv);
  ok(rc == WHIRL_OK, "null_vectors 2x3 rc %d", rc);
  dot = (V[0] - 2.0 * V[1] + V[2]) / sqrt(6.0);
  is_rel(fabs(dot), 1.0, 1e-14, "null vector = +-(1,-2,1)/sqrt(6)");
  ok(sv[0] == 0.0, "m < k: missing singular value reported as 0 (%g)", sv[0]);
  rc = whirl_null_vectors(2, 3, A, 2, V, sv);
  /* Singular values of [1 2 3; 4 5 6]: sqrt of the eigenvalues of A A^T =
   * [14 32; 32 77], (91 -+ sqrt(91^2 - 4*54)) / 2. */
  is_rel(sv[0], sqrt((91.0 - sqrt(91.0 * 91.0 - 216.0)) / 2.0), 1e-13,
         "nvec=2: sv[0] = smaller nonzero singular value");
  ok(rc == WHIRL_OK && sv[1] == 0.0, "nvec=2: sv[1] = 0, sv non-increasing");
  Av[0] = V[0] + 2 * V[1] + 3 * V[2];
  Av[1] = 4 * V[0] + 5 * V[1] + 6 * V[2];
  is_rel(hypot(Av[0], Av[1]), sv[0], 1e-13, "nvec=2: |A v_0| = sv[0]");
  rc = whirl_null_vectors(2, 3, R1, 2, V, sv);
  ok(rc == WHIRL_OK, "rank-1 2x3: rc %d", rc);
  for (c = 0; c < 2; ++c) {
    const double *v = V + 3 * c;
    is_abs(v[0] + v[1] + v[2], 0.0, 1e-14, "rank 1: A v_%zu = 0", c);
    is_rel(v[0] * v[0] + v[1] * v[1] + v[2] * v[2], 1.0, 1e-14,
           "rank 1: |v_%zu| = 1", c);
  }
  is_abs(V[0] * V[3] + V[1] * V[4] + V[2] * V[5], 0.0, 1e-14,
         "rank 1: v_0 . v_1 = 0");
  ok(sv[0] < 1e-14 && sv[1] == 0.0, "rank 1: sv = (%g, %g) ~ 0", sv[0], sv[1]);
  ok(whirl_null_vectors(2, 3, A, 4, V, sv) == WHIRL_EINVAL,
     "null_vectors nvec > k -> EINVAL");
  ok(whirl_null_vectors(0, 3, A, 1, V, sv) == WHIRL_EINVAL,
     "null_vectors m = 0 -> EINVAL");
  /* The pivoted choice, by hand: [1 2 3; 2 4 6] (rank 1, k = 2): the
   * pivot 6 at (2, 3), columns 1 and 3 exchanged; the free unknowns (the
   * permuted 2 and 3) are 1, the first -(4 + 2)/6 = -1, and the exchange
   * undone: u = (1, 1, -1).  [1 2 3; 4 5 6] (k = 1): the pivot 6 at
   * (2, 3), rows and columns 1 and 3 exchanged, [6 5 4; 0 -1/2 -1]; then
   * -1 at (2, 3), columns 2 and 3 exchanged; the free unknown 1, the
   * others -1/2 and -(4 (-1/2) + 5)/6 = -1/2, the exchanges undone in
   * reverse: u = (-1/2, 1, -1/2) */
  double B[6] = {1, 2, 2, 4, 3, 6}, u[3];
  rc = whirl_null_vector_pivoted(2, 3, 2, B, u);
  ok(rc == WHIRL_OK && u[0] == 1.0 && u[1] == 1.0 && u[2] == -1.0,
     "pivoted null vector of [1 2 3; 2 4 6]: (1, 1, -1) by hand (%g, %g, %g)", u[0], u[1], u[2]);
  double C[6] = {1, 4, 2, 5, 3, 6};
  rc = whirl_null_vector_pivoted(2, 3, 1, C, u);
  ok(rc == WHIRL_OK && fabs(u[0] + 0.5) < 1e-15 && fabs(u[1] - 1.0) < 1e-15 &&
         fabs(u[2] + 0.5) < 1e-15,
     "pivoted null vector of [1 2 3; 4 5 6]: (-1/2, 1, -1/2) by hand (%g, %g, %g)",
     u[0], u[1], u[2]);
  double D[4] = {1, 0, 0, NAN};
  ok(whirl_null_vector_pivoted(2, 2, 1, D, u) == WHIRL_EINVAL &&
         whirl_null_vector_pivoted(2, 3, 0, C, u) == WHIRL_EINVAL &&
         whirl_null_vector_pivoted(1, 3, 1, C, u) == WHIRL_EINVAL,
     "pivoted null vector: NaN, k = 0, m + k < n -> EINVAL");
}

/* ------------------------------------------------------------------------
 * Error paths. */
static void test_errors(void) {
  const int Ap[4] = {0, 2, 3, 5};
  const int Ai_bad[5] = {0, 3, 1, 0, 2};      /* row 3 out of range, n = 3 */
  const int Ai_unsorted[5] = {1, 0, 1, 0, 2}; /* column 0 unsorted */
  const int Ap_bad[4] = {1, 2, 3, 5};         /* Ap[0] != 0 */
  const int Ai_ok[5] = {0, 1, 1, 0, 2};
  double A[16], logabs = 1.0, b[4] = {1, 2, 3, 4};
  int sign = 7, rc;
  size_t i;
  whirl_linsol *ls;

  ok(whirl_linsol_alloc_dense(0) == NULL, "dense alloc n = 0 -> NULL");
  ok(whirl_linsol_alloc_sparse(0, Ap, Ai_ok) == NULL,
     "sparse alloc n = 0 -> NULL");
  ok(whirl_linsol_alloc_sparse(3, Ap, Ai_bad) == NULL,
     "sparse alloc, row index out of range -> NULL");
  ok(whirl_linsol_alloc_sparse(3, Ap, Ai_unsorted) == NULL,
     "sparse alloc, unsorted column -> NULL");
  ok(whirl_linsol_alloc_sparse(3, Ap_bad, Ai_ok) == NULL,
     "sparse alloc, Ap[0] != 0 -> NULL");
  ok(whirl_linsol_alloc_sparse(3, NULL, Ai_ok) == NULL,
     "sparse alloc, Ap NULL -> NULL");
  ok(whirl_bordered_alloc(WHIRL_LINSOL_DENSE, 0, 1, NULL, NULL) == NULL,
     "bordered alloc n = 0 -> NULL");
  ok(whirl_bordered_alloc(WHIRL_LINSOL_SPARSE, 3, 1, Ap, Ai_bad) == NULL,
     "bordered alloc, bad pattern -> NULL");
  ok(whirl_bordered_alloc((whirl_linsol_kind)7, 3, 1, NULL, NULL) == NULL,
     "bordered alloc, bad kind -> NULL");
  ok(whirl_eig_alloc(0) == NULL, "eig alloc n = 0 -> NULL");
  whirl_linsol_free(NULL);
  whirl_bordered_free(NULL);
  whirl_eig_free(NULL);
  ok(1, "free functions accept NULL");

  /* Dense 4x4 Neumann Laplacian: exactly singular (integer pivots). */
  ls = whirl_linsol_alloc_dense(4);
  rc = whirl_linsol_solve(ls, b, 1, 0);
  ok(rc == WHIRL_EINVAL, "solve before any factor -> EINVAL (%d)", rc);
  rc = whirl_linsol_logdet(ls, &logabs, &sign);
  ok(rc == WHIRL_EINVAL && sign == 0, "logdet before any factor -> EINVAL");
  {
    unsigned char mask4[16];
    neumann(4, A, mask4);
  }
  rc = whirl_linsol_factor(ls, A);
  ok(rc == WHIRL_ESINGULAR, "singular dense matrix -> WHIRL_ESINGULAR (%d)",
     rc);
  ok(strstr(whirl_linsol_errmsg(ls), "dense.c:") != NULL,
     "errmsg names file:line: '%s'", whirl_linsol_errmsg(ls));
  rc = whirl_linsol_logdet(ls, &logabs, &sign);
  ok(rc == WHIRL_OK && sign == 0 && logabs == -HUGE_VAL,
     "singular: logdet sign 0, log|det| = -inf (%d, %g)", sign, logabs);
  rc = whirl_linsol_solve(ls, b, 1, 0);
  ok(rc == WHIRL_ESINGULAR, "solve after singular factor -> ESINGULAR");
  rc = whirl_linsol_solve(ls, b, 1, 2);
  ok(rc == WHIRL_EINVAL, "solve trans = 2 -> EINVAL");
  A[5] = NAN;
  rc = whirl_linsol_factor(ls, A);
  ok(rc == WHIRL_EINVAL && strstr(whirl_linsol_errmsg(ls), "(1,1)") != NULL,
     "NaN entry -> EINVAL naming it: '%s'", whirl_linsol_errmsg(ls));
  ok(whirl_linsol_factor(ls, NULL) == WHIRL_EINVAL, "factor NULL -> EINVAL");
  /* Recovery: a good matrix after failures factors and solves again. */
  for (i = 0; i < 16; ++i) A[i] = (i % 5 == 0) ? 2.0 : 0.0;
  rc = whirl_linsol_factor(ls, A);
  ok(rc == WHIRL_OK && whirl_linsol_solve(ls, b, 1, 0) == WHIRL_OK &&
         b[0] == 0.5 && b[3] == 2.0,
     "refactor after failures: 2 I x = b works");
  whirl_linsol_free(ls);

  /* Sparse: column 1's only value is 0 -> exactly singular. */
  {
    const double Ax[5] = {4.0, 1.0, 0.0, 1.0, 3.0};
    whirl_linsol *sp = whirl_linsol_alloc_sparse(3, Ap, Ai_ok);
    whirl_bordered *bd;
    ok(sp != NULL, "sparse 3x3 alloc");
    rc = whirl_linsol_factor(sp, Ax);
    ok(rc == WHIRL_ESINGULAR, "singular sparse matrix -> ESINGULAR (%d) '%s'",
       rc, whirl_linsol_errmsg(sp));
    sign = 7;
    rc = whirl_linsol_logdet(sp, &logabs, &sign);
    ok(rc == WHIRL_OK && sign == 0, "singular sparse: logdet sign 0");
    ok(whirl_linsol_solve(sp, b, 1, 1) == WHIRL_ESINGULAR,
       "singular sparse: solve -> ESINGULAR");
    whirl_linsol_free(sp);
    bd = whirl_bordered_alloc(WHIRL_LINSOL_DENSE, 3, 1, NULL, NULL);
    rc = whirl_bordered_factor(bd, A, NULL, NULL, NULL);
    ok(rc == WHIRL_EINVAL && whirl_bordered_errmsg(bd)[0] != '\0',
       "bordered factor with NULL border -> EINVAL '%s'",
       whirl_bordered_errmsg(bd));
    rc = whirl_bordered_solve(bd, b, 1, 0);
    ok(rc == WHIRL_EINVAL && strstr(whirl_bordered_errmsg(bd), "linsol.c:"),
       "bordered solve without factor -> EINVAL, inner message '%s'",
       whirl_bordered_errmsg(bd));
    whirl_bordered_free(bd);
  }
  {
    whirl_eig *e = whirl_eig_alloc(2);
    const double Anan[4] = {1.0, INFINITY, 0.0, 1.0};
    double re[2], im[2];
    ok(whirl_eig_compute(e, Anan, re, im) == WHIRL_EINVAL,
       "eig of a matrix with Inf -> EINVAL");
    ok(whirl_eig_compute(e, NULL, re, im) == WHIRL_EINVAL,
       "eig of NULL -> EINVAL");
    whirl_eig_free(e);
  }
}

/* LAPACK's error printer (xerbla) writes to stdout in the reference and
 * OpenBLAS builds (1200 lines of "On entry to DGEBAL parameter number 3 had
 * an illegal value" in the results table of `sfd response --lambda
 * 1e308`); libwhirl exports its own xerbla_, which records instead of
 * printing.  Whirl's own calls check their arguments, so make LAPACK
 * complain by calling it directly with n = -1: the complaint must resolve
 * to libwhirl's xerbla_ (not liblapack's) and print nothing.  stdout goes
 * to a file meanwhile.  Then whirl's next LAPACK call must not inherit the
 * recorded complaint. */
extern void dgetrf_(const int *m, const int *n, double *a, const int *lda,
                    int *ipiv, int *info);
static void test_lapack_silent(void) {
  char path[] = "/tmp/t_linalg_stdout.XXXXXX";
  int fd = mkstemp(path), saved = dup(1);
  fflush(stdout);
  dup2(fd, 1);
  int m = -1, n = 2, lda = 2, ipiv[2], info = 0;
  double a[4] = {1, 0, 0, 1};
  dgetrf_(&m, &n, a, &lda, ipiv, &info);
  fflush(stdout);
  dup2(saved, 1);
  close(saved);
  off_t size = lseek(fd, 0, SEEK_END);
  char text[200] = "";
  ssize_t got = pread(fd, text, sizeof text - 1, 0);
  if (got > 0) text[got] = '\0';
  close(fd);
  unlink(path);
  ok(info == -1, "dgetrf with m = -1 returns info = -1 (%d)", info);
  ok(size == 0, "LAPACK printed nothing on stdout (%ld bytes%s%s)", (long)size,
     size ? ": " : "", strtok(text, "\n") ? text : "");
  double A[16] = {2, 1, 0, 0, -3, 0, 1, 0, 1, 0, 0, 1, 0.5, 0, 0, 0}, re[4], im[4];
  whirl_eig *e = whirl_eig_alloc(4);
  int rc = whirl_eig_compute(e, A, re, im);
  ok(rc == WHIRL_OK && whirl_eig_errmsg(e)[0] == '\0',
     "whirl's next LAPACK call succeeds (%d '%s')", rc, whirl_eig_errmsg(e));
  A[5] = NAN;
  rc = whirl_eig_compute(e, A, re, im);
  ok(rc == WHIRL_EINVAL && strstr(whirl_eig_errmsg(e), "not finite"),
     "a NaN matrix is refused before LAPACK sees it: %s", whirl_eig_errmsg(e));
  whirl_eig_free(e);
}

/* Both sparse backends (KLU, the default; UMFPACK by WHIRL_SPARSE_LU =
 * umfpack) against the dense LU on a matrix whose partial pivoting swaps
 * rows (small diagonal, no dominance: the sign of det from the pivoting's
 * permutation, the BTF and ordering permutations and the pivots), and on
 * an exactly singular one (a zero pivot: WHIRL_ESINGULAR, sign 0, no
 * solve). */
static void test_sparse_backends(void) {
  enum { N = 60 };
  static const char *const names[2] = {"KLU", "UMFPACK"};
  double *A = xcalloc(N * N, sizeof *A), *x = xcalloc(N, sizeof *x),
         *bd = xcalloc(N, sizeof *bd), *bs = xcalloc(N, sizeof *bs);
  unsigned char *mask = xcalloc(N * N, 1);
  int *Ap, *Ai;
  double *Ax;
  for (size_t j = 0; j < N; ++j)
    for (size_t i = 0; i < N; ++i)
      if (i == j || (i + 2 * j) % 7 == 0 || (3 * i + j) % 11 == 0) {
        mask[i + N * j] = 1;
        A[i + N * j] = i == j ? 1e-3 * urand() : urand();
      }
  dense_to_csc(N, A, mask, &Ap, &Ai, &Ax);
  whirl_linsol *ld = whirl_linsol_alloc_dense(N);
  double lad = 0.0;
  int sd = 0;
  whirl_linsol_factor(ld, A); /* overwrites A: solves below use Ax */
  whirl_linsol_logdet(ld, &lad, &sd);
  for (int b = 0; b < 2; ++b) {
    if (b) setenv("WHIRL_SPARSE_LU", "umfpack", 1);
    else unsetenv("WHIRL_SPARSE_LU");
    whirl_linsol *ls = whirl_linsol_alloc_sparse(N, Ap, Ai);
    double la = 0.0;
    int sg = 0, rc = whirl_linsol_factor(ls, Ax);
    whirl_linsol_logdet(ls, &la, &sg);
    ok(rc == WHIRL_OK && sg == sd && sd != 0 && fabs(la - lad) < 1e-10 * fabs(lad),
       "%s: det of a matrix that pivots: sign %d, log|det| %.12g (dense %d, %.12g)",
       names[b], sg, la, sd, lad);
    for (size_t i = 0; i < N; ++i) x[i] = urand();
    for (int trans = 0; trans <= 1; ++trans) {
      memset(bs, 0, N * sizeof *bs);
      for (size_t j = 0; j < N; ++j) /* bs = A x or A^T x from the CSC */
        for (int q = Ap[j]; q < Ap[j + 1]; ++q) {
          if (trans) bs[j] += Ax[q] * x[Ai[q]];
          else bs[Ai[q]] += Ax[q] * x[j];
        }
      memcpy(bd, bs, N * sizeof *bd);
      rc = whirl_linsol_solve(ls, bs, 1, trans);
      ok(rc == WHIRL_OK && relerr(N, bs, x) < 1e-13, "%s: solve%s, rel err %.1e", names[b],
         trans ? " with A^T" : "", relerr(N, bs, x));
    }
    whirl_linsol_free(ls);
    /* [[1 2 0]; [2 4 0]; [0 0 1]]: row 2 is twice row 1 */
    const int sp[4] = {0, 2, 4, 5}, si[5] = {0, 1, 0, 1, 2};
    const double sx[5] = {1.0, 2.0, 2.0, 4.0, 1.0};
    ls = whirl_linsol_alloc_sparse(3, sp, si);
    rc = whirl_linsol_factor(ls, sx);
    whirl_linsol_logdet(ls, &la, &sg);
    double r[3] = {1.0, 1.0, 1.0};
    ok(rc == WHIRL_ESINGULAR && sg == 0 && whirl_linsol_solve(ls, r, 1, 0) != WHIRL_OK,
       "%s: an exactly singular matrix: rc %d, sign %d, no solve ('%s')", names[b], rc, sg,
       whirl_linsol_errmsg(ls));
    whirl_linsol_free(ls);
  }
  unsetenv("WHIRL_SPARSE_LU");
  /* KLU refactors new values in the last pivot order: [[1 .5]; [.5 1]]
   * pivots on the diagonal; on [[1e-12 1]; [1 1]] that order would pivot
   * on 1e-12 (growth 1e12) and is dropped for a new factorisation: the
   * solve exact without refinement, det = 1e-12 - 1 */
  {
    const int sp[3] = {0, 2, 4}, si[4] = {0, 1, 0, 1};
    const double v1[4] = {1.0, 0.5, 0.5, 1.0}, v2[4] = {1e-12, 1.0, 1.0, 1.0};
    whirl_linsol *ls = whirl_linsol_alloc_sparse(2, sp, si);
    whirl_linsol_set_refinement(ls, 0);
    int rc = whirl_linsol_factor(ls, v1);
    if (!rc) rc = whirl_linsol_factor(ls, v2);
    double r[2] = {1.0 + 1e-12, 2.0}, la = 0.0; /* x = (1, 1) */
    int sg = 0;
    if (!rc) rc = whirl_linsol_solve(ls, r, 1, 0);
    whirl_linsol_logdet(ls, &la, &sg);
    ok(rc == WHIRL_OK && fabs(r[0] - 1.0) < 1e-14 && fabs(r[1] - 1.0) < 1e-14 && sg == -1 &&
           fabs(la - log(1.0 - 1e-12)) < 1e-14,
       "new values whose last pivot order grows 1e12: factored anew, x = (%.17g, %.17g), "
       "det %d exp(%.3g)", r[0], r[1], sg, la);
    whirl_linsol_free(ls);
  }
  whirl_linsol_free(ld);
  free(A), free(x), free(bd), free(bs), free(mask), free(Ap), free(Ai), free(Ax);
}

int main(void) {
  test_lapack_silent();
  test_dense_solve();
  test_dense_logdet();
  test_perm_diag_logdet();
  test_dense_vs_sparse();
  test_sparse_backends();
  test_bordered();
  test_eig();
  test_null_vectors();
  test_errors();
  return done_testing();
}

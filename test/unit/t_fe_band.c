/* test/unit/t_fe_band.c — the banded LU of rotor/fe_band.c (the interior
 * block of the condensed harmonic balance) against LAPACK's dense complex
 * LU (zgesv) on random complex band matrices given in a shuffled DOF order:
 * the reverse Cuthill–McKee ordering must bring the band back, the solves
 * with A and with Aᵀ must agree with the dense ones, with and without row
 * swaps, on disconnected patterns, and a singular matrix must be refused.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"

#include "../tap.h"

extern void zgesv_(const int *n, const int *nrhs, double complex *a,
                   const int *lda, int *ipiv, double complex *b,
                   const int *ldb, int *info);

/* A random complex n×n matrix with A(i, j) ≠ 0 only for −ku ≤ i − j ≤ kl
 * in the hidden order, stored dense (column-major) in the shuffled order
 * sh[hidden] = shuffled; diag scales the diagonal (0: zero diagonal, so
 * that the LU must swap rows); comp > 1 cuts the band into that many
 * uncoupled blocks. */
static void make(int n, int kl, int ku, double diag, int comp, const int *sh,
                 double complex *A) {
  memset(A, 0, (size_t)n * n * sizeof *A);
  for (int j = 0; j < n; ++j)
    for (int i = j - ku; i <= j + kl; ++i) {
      if (i < 0 || i >= n) continue;
      if (comp > 1 && i * comp / n != j * comp / n) continue;
      double complex v = tap_urand(-1, 1) + I * tap_urand(-1, 1);
      if (i == j) v = diag * (4.0 + v);
      A[sh[i] + (size_t)n * sh[j]] = v;
    }
}

/* CSC pattern and values of the nonzeros of dense A. */
static int to_csc(int n, const double complex *A, int *Ap, int *Ai,
                  double complex *Ax) {
  int nz = 0;
  Ap[0] = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i)
      if (A[i + (size_t)n * j] != 0) { Ai[nz] = i; Ax[nz++] = A[i + (size_t)n * j]; }
    Ap[j + 1] = nz;
  }
  return nz;
}

/* Largest relative difference of the band solve (A or Aᵀ) from zgesv on
 * nrhs random right-hand sides. */
static double against_dense(fe_band *b, int n, const double complex *A,
                            int transpose, int nrhs) {
  double complex *D = malloc((size_t)n * n * sizeof *D);
  double complex *X = malloc((size_t)n * nrhs * sizeof *X);
  double complex *Y = malloc((size_t)n * nrhs * sizeof *Y);
  int *ipiv = malloc((size_t)n * sizeof *ipiv), info = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      D[i + (size_t)n * j] = transpose ? A[j + (size_t)n * i] : A[i + (size_t)n * j];
  for (int k = 0; k < n * nrhs; ++k) X[k] = Y[k] = tap_urand(-1, 1) + I * tap_urand(-1, 1);
  zgesv_(&n, &nrhs, D, &n, ipiv, Y, &n, &info);
  int rc = fe_band_solve(b, transpose, nrhs, X);
  double worst = info || rc ? INFINITY : 0, scale = 0;
  for (int k = 0; k < n * nrhs; ++k) scale = fmax(scale, cabs(Y[k]));
  for (int k = 0; k < n * nrhs; ++k) worst = fmax(worst, cabs(X[k] - Y[k]) / scale);
  free(D);
  free(X);
  free(Y);
  free(ipiv);
  return worst;
}

static void shuffle(int n, int *sh) {
  for (int i = 0; i < n; ++i) sh[i] = i;
  for (int i = n - 1; i > 0; --i) {
    int j = (int)tap_urand(0, i + 1);
    if (j > i) j = i;
    int t = sh[i]; sh[i] = sh[j]; sh[j] = t;
  }
}

static void one_case(const char *what, int n, int kl, int ku, double diag,
                     int comp) {
  int *sh = malloc((size_t)n * sizeof *sh), *Ap = malloc((size_t)(n + 1) * sizeof *Ap);
  int *Ai = malloc((size_t)n * n * sizeof *Ai);
  double complex *A = malloc((size_t)n * n * sizeof *A);
  double complex *Ax = malloc((size_t)n * n * sizeof *Ax);
  shuffle(n, sh);
  make(n, kl, ku, diag, comp, sh, A);
  to_csc(n, A, Ap, Ai, Ax);
  fe_band b;
  int rc = fe_band_init(&b, n, Ap, Ai);
  int w = kl > ku ? kl : ku;
  /* the symmetrised band has half-width w; Cuthill–McKee's level
   * structure keeps each half-bandwidth within 2w of it */
  ok(rc == 0 && b.kl <= 2 * w && b.ku <= 2 * w,
     "%s: RCM brings the shuffled band (n = %d, kl %d, ku %d) back to kl %d, "
     "ku %d", what, n, kl, ku, b.kl, b.ku);
  rc = rc ? rc : fe_band_factor(&b, Ap, Ax);
  ok(rc == 0, "%s: factorised (U's upper bandwidth %d)", what, b.kv);
  if (diag == 0)
    ok(b.kv > b.ku, "%s: zero diagonal: rows swapped, U wider than ku (%d > %d)",
       what, b.kv, b.ku);
  double eN = rc ? INFINITY : against_dense(&b, n, A, 0, 3);
  double eT = rc ? INFINITY : against_dense(&b, n, A, 1, 2);
  ok(eN < 1e-11, "%s: A x = b as zgesv (%.1e)", what, eN);
  ok(eT < 1e-11, "%s: A^T x = b as zgesv (%.1e)", what, eT);
  fe_band_free(&b);
  free(sh);
  free(Ap);
  free(Ai);
  free(A);
  free(Ax);
}

/* A zero column: singular, refused (no division by zero). */
static void singular(void) {
  int n = 12, sh[12];
  for (int i = 0; i < n; ++i) sh[i] = i;
  double complex A[144], Ax[144];
  int Ap[13], Ai[144];
  make(n, 2, 2, 1.0, 1, sh, A);
  for (int i = 0; i < n; ++i) A[i + n * 5] = 0;
  to_csc(n, A, Ap, Ai, Ax);
  fe_band b;
  int rc = fe_band_init(&b, n, Ap, Ai);
  rc = rc ? rc : fe_band_factor(&b, Ap, Ax);
  ok(rc == WHIRL_ESINGULAR, "a matrix with a zero column: WHIRL_ESINGULAR (%d)", rc);
  fe_band_free(&b);
}

int main(void) {
  one_case("diagonally dominant", 80, 7, 7, 1.0, 1);
  one_case("unsymmetric band", 61, 3, 6, 1.0, 1);
  one_case("zero diagonal", 50, 4, 2, 0.0, 1);
  one_case("three uncoupled blocks", 45, 3, 3, 1.0, 3);
  one_case("diagonal only", 9, 0, 0, 1.0, 1);
  singular();
  return done_testing();
}

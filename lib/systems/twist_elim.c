/* lib/systems/twist_elim.c — the structured elimination of a collocation
 * orbit's variational operator with a twisted boundary condition: see
 * twist_elim.h.  Dense blocks, column-major; every elimination is an LU
 * with partial row pivoting of some columns of a block, its row swaps and
 * multipliers kept LAPACK's way (whole rows swapped, multipliers too), so
 * a block's row operations Q = L^{-1} P apply to new columns as P first,
 * then L, and their transposes as L^T first, then P^T.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "twist_elim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct twist_elim {
  size_t n, N, m;  /* states, intervals, collocation points */
  size_t R, ci;    /* an interval's rows n m and interior columns n (m − 1) */
  double *G;       /* N interval blocks, R × n (m + 1) each */
  int *gpiv;       /* N × ci */
  double *H;       /* N − 1 chain blocks, 2n × 3n: [v_k | v(0) | v_k+1] */
  int *hpiv;       /* (N − 1) × n */
  double *acc;     /* n × 2n: the rows left in [v(0) | v_k] */
  double *F;       /* 2n × n: [acc's v(N) part; BN], factored */
  int *fpiv;       /* n */
  double *Y;       /* 2n × 2n: [acc's v(0) part, 0; B0r, B0i], transformed */
  double *bn;      /* n × n */
  double *t;       /* scratch: 8n */
};

twist_elim *twist_alloc(size_t n, size_t ntst, size_t ncol) {
  if (n < 1 || ntst < 1 || ncol < 1) return NULL;
  twist_elim *e = calloc(1, sizeof *e);
  if (!e) return NULL;
  e->n = n, e->N = ntst, e->m = ncol;
  e->R = n * ncol, e->ci = n * (ncol - 1);
  const size_t nH = ntst > 1 ? ntst - 1 : 1;
  e->G = malloc(ntst * e->R * n * (ncol + 1) * sizeof *e->G);
  e->gpiv = malloc((ntst * e->ci + 1) * sizeof *e->gpiv);
  e->H = malloc(nH * 6 * n * n * sizeof *e->H);
  e->hpiv = malloc(nH * n * sizeof *e->hpiv);
  e->acc = malloc(2 * n * n * sizeof *e->acc);
  e->F = malloc(2 * n * n * sizeof *e->F);
  e->Y = malloc(4 * n * n * sizeof *e->Y);
  e->bn = calloc(n * n, sizeof *e->bn);
  e->fpiv = malloc(n * sizeof *e->fpiv);
  e->t = malloc(8 * n * sizeof *e->t);
  if (!e->G || !e->gpiv || !e->H || !e->hpiv || !e->acc || !e->F || !e->Y || !e->bn || !e->t || !e->fpiv) {
    twist_free(e);
    return NULL;
  }
  return e;
}

void twist_free(twist_elim *e) {
  if (!e) return;
  free(e->G), free(e->gpiv), free(e->H), free(e->hpiv), free(e->acc), free(e->F);
  free(e->Y), free(e->bn), free(e->t), free(e->fpiv), free(e);
}

double *twist_block(twist_elim *e, size_t i) { return e->G + i * e->R * e->n * (e->m + 1); }
double *twist_bn(twist_elim *e) { return e->bn; }

/* ------------------------------------------------------------ kernels */

/* LU with partial pivoting of the r × c columns c0 .. c0 + c − 1 of the
 * r × ncols block A (leading dimension r), the row operations applied to
 * all its columns: rows 0 .. c − 1 then hold U and the pivot rows' other
 * entries, rows c .. r − 1 the rows left (zero in those columns), the
 * multipliers below U's diagonal.  -1 on a zero pivot. */
static int lu_cols(double *A, size_t r, size_t c0, size_t c, size_t ncols, int *piv) {
  for (size_t j = 0; j < c; ++j) {
    double *col = A + r * (c0 + j);
    size_t p = j;
    for (size_t i = j + 1; i < r; ++i)
      if (fabs(col[i]) > fabs(col[p])) p = i;
    piv[j] = (int)p;
    if (!(fabs(col[p]) > 0.0)) return -1;
    if (p != j)
      for (size_t k = 0; k < ncols; ++k) {
        double *a = A + r * k, s = a[j];
        a[j] = a[p], a[p] = s;
      }
    const double d = col[j];
    for (size_t i = j + 1; i < r; ++i) col[i] /= d;
    for (size_t k = 0; k < ncols; ++k) {
      if (k >= c0 && k <= c0 + j) continue; /* L's columns, and this one */
      double *a = A + r * k;
      const double s = a[j];
      if (s != 0.0)
        for (size_t i = j + 1; i < r; ++i) a[i] -= col[i] * s;
    }
  }
  return 0;
}

/* Q = L^{-1} P of lu_cols (its multipliers in columns c0 .. of A) on the
 * r × k columns Y (leading dimension r): the swaps first, then L. */
static void q_apply(const double *A, size_t r, size_t c0, size_t c, const int *piv, double *Y,
                    size_t k) {
  for (size_t j = 0; j < c; ++j)
    if ((size_t)piv[j] != j)
      for (size_t q = 0; q < k; ++q) {
        double *y = Y + r * q, s = y[j];
        y[j] = y[piv[j]], y[piv[j]] = s;
      }
  for (size_t j = 0; j < c; ++j) {
    const double *l = A + r * (c0 + j);
    for (size_t q = 0; q < k; ++q) {
      double *y = Y + r * q;
      for (size_t i = j + 1; i < r; ++i) y[i] -= l[i] * y[j];
    }
  }
}

/* y[r] = Q^T (0; y[c .. r − 1]) in place: L^T first, then P^T. */
static void qt_apply(const double *A, size_t r, size_t c0, size_t c, const int *piv, double *y) {
  for (size_t j = 0; j < c; ++j) y[j] = 0.0;
  for (size_t j = c; j-- > 0;) {
    const double *l = A + r * (c0 + j);
    double s = 0.0;
    for (size_t i = j + 1; i < r; ++i) s += l[i] * y[i];
    y[j] -= s;
  }
  for (size_t j = c; j-- > 0;)
    if ((size_t)piv[j] != j) {
      const double s = y[j];
      y[j] = y[piv[j]], y[piv[j]] = s;
    }
}

/* x[c] = −U^{-1} (b) in place, U the c × c upper triangle at column c0 of
 * the r-row block A. */
static void u_solve(const double *A, size_t r, size_t c0, size_t c, double *x) {
  for (size_t j = c; j-- > 0;) {
    x[j] /= A[j + r * (c0 + j)];
    for (size_t i = 0; i < j; ++i) x[i] -= A[i + r * (c0 + j)] * x[j];
  }
  for (size_t j = 0; j < c; ++j) x[j] = -x[j];
}

/* out[c] = the pivot rows' entries in columns k0 .. k0 + kn − 1 of the
 * r-row block A times x, added. */
static void pivot_rows_times(const double *A, size_t r, size_t c, size_t k0, size_t kn,
                             const double *x, double *out) {
  for (size_t k = 0; k < kn; ++k) {
    const double *a = A + r * (k0 + k);
    for (size_t i = 0; i < c; ++i) out[i] += a[i] * x[k];
  }
}

/* ------------------------------------------------------------- factor */

int twist_factor(twist_elim *e) {
  const size_t n = e->n, N = e->N, m = e->m, R = e->R, ci = e->ci, nc = n * (m + 1);
  for (size_t i = 0; i < N; ++i) /* the interiors, interval by interval */
    if (ci && lu_cols(twist_block(e, i), R, n, ci, nc, e->gpiv + i * ci)) return -1;
  /* the rows left of interval 0: [v(0) | v(1)] */
  const double *G0 = twist_block(e, 0);
  for (size_t k = 0; k < n; ++k)
    for (size_t i = 0; i < n; ++i) {
      e->acc[i + n * k] = G0[ci + i + R * k];
      e->acc[i + n * (n + k)] = G0[ci + i + R * (n * m + k)];
    }
  for (size_t k = 1; k < N; ++k) { /* v_k over acc and interval k's rows */
    double *H = e->H + (k - 1) * 6 * n * n;
    const double *Gk = twist_block(e, k);
    memset(H, 0, 6 * n * n * sizeof *H);
    for (size_t q = 0; q < n; ++q)
      for (size_t i = 0; i < n; ++i) {
        H[i + 2 * n * q] = e->acc[i + n * (n + q)];             /* v_k */
        H[i + 2 * n * (n + q)] = e->acc[i + n * q];             /* v(0) */
        H[n + i + 2 * n * q] = Gk[ci + i + R * q];              /* A_k */
        H[n + i + 2 * n * (2 * n + q)] = Gk[ci + i + R * (n * m + q)]; /* B_k */
      }
    if (lu_cols(H, 2 * n, 0, n, 3 * n, e->hpiv + (k - 1) * n)) return -1;
    for (size_t q = 0; q < n; ++q)
      for (size_t i = 0; i < n; ++i) {
        e->acc[i + n * q] = H[n + i + 2 * n * (n + q)];
        e->acc[i + n * (n + q)] = H[n + i + 2 * n * (2 * n + q)];
      }
  }
  /* v(N) over acc and the boundary rows */
  for (size_t q = 0; q < n; ++q)
    for (size_t i = 0; i < n; ++i) {
      e->F[i + 2 * n * q] = e->acc[i + n * (n + q)];
      e->F[n + i + 2 * n * q] = e->bn[i + n * q];
    }
  return lu_cols(e->F, 2 * n, 0, n, n, e->fpiv);
}

void twist_reduce(twist_elim *e, const double *b0r, const double *b0i, double *sr,
                  double *si) {
  const size_t n = e->n, r = 2 * n;
  double *Y = e->Y;
  for (size_t q = 0; q < n; ++q)
    for (size_t i = 0; i < n; ++i) {
      Y[i + r * q] = e->acc[i + n * q];
      Y[i + r * (n + q)] = 0.0;
      Y[n + i + r * q] = b0r[i + n * q];
      Y[n + i + r * (n + q)] = b0i[i + n * q];
    }
  q_apply(e->F, r, 0, n, e->fpiv, Y, 2 * n);
  for (size_t q = 0; q < n; ++q)
    for (size_t i = 0; i < n; ++i) {
      sr[i + n * q] = Y[n + i + r * q];
      si[i + n * q] = Y[n + i + r * (n + q)];
    }
}

/* ---------------------------------------------------------- solutions */

/* Node k's n values of the node-major vector x. */
static double *node(double *x, size_t n, size_t k) { return x + n * k; }

void twist_right(twist_elim *e, const double *v0r, const double *v0i, double *vr, double *vi) {
  const size_t n = e->n, N = e->N, m = e->m, R = e->R, ci = e->ci, r = 2 * n;
  double *part[2] = {vr, vi};
  memcpy(node(vr, n, 0), v0r, n * sizeof *vr);
  memcpy(node(vi, n, 0), v0i, n * sizeof *vi);
  /* v(N): U_F v(N) + (Yr + i Yi)_top v(0) = 0 */
  double *x = e->t;
  for (int c = 0; c < 2; ++c) {
    memset(x, 0, n * sizeof *x);
    const double sg = c ? 1.0 : -1.0; /* re: Yr v0r − Yi v0i; im: Yr v0i + Yi v0r */
    pivot_rows_times(e->Y, r, n, 0, n, c ? v0i : v0r, x);
    for (size_t k = 0; k < n; ++k) {
      const double *a = e->Y + r * (n + k);
      const double v = (c ? v0r : v0i)[k];
      for (size_t i = 0; i < n; ++i) x[i] += sg * a[i] * v;
    }
    u_solve(e->F, r, 0, n, x);
    memcpy(node(part[c], n, N * m), x, n * sizeof *x);
  }
  for (size_t k = N; k-- > 1;) { /* v_k from v(0) and v_k+1 */
    const double *H = e->H + (k - 1) * 6 * n * n;
    for (int c = 0; c < 2; ++c) {
      memset(x, 0, n * sizeof *x);
      pivot_rows_times(H, r, n, n, n, node(part[c], n, 0), x);
      pivot_rows_times(H, r, n, 2 * n, n, node(part[c], n, (k + 1) * m), x);
      u_solve(H, r, 0, n, x);
      memcpy(node(part[c], n, k * m), x, n * sizeof *x);
    }
  }
  for (size_t i = 0; i < N && ci; ++i) { /* the interiors */
    const double *G = twist_block(e, i);
    for (int c = 0; c < 2; ++c) {
      double *xi = node(part[c], n, i * m + 1);
      memset(xi, 0, ci * sizeof *xi);
      pivot_rows_times(G, R, ci, 0, n, node(part[c], n, i * m), xi);
      pivot_rows_times(G, R, ci, n * m, n, node(part[c], n, (i + 1) * m), xi);
      u_solve(G, R, n, ci, xi);
    }
  }
}

void twist_left(twist_elim *e, const double *w0r, const double *w0i, double *wr, double *wi) {
  const size_t n = e->n, N = e->N, R = e->R, ci = e->ci, r = 2 * n, rows = N * R;
  double *y = e->t; /* 2n: a chain block's rows */
  double *part[2] = {wr, wi};
  for (int c = 0; c < 2; ++c) {
    double *w = part[c];
    /* the last block: [acc; boundary rows], w0 on the rows left */
    memcpy(y + n, c ? w0i : w0r, n * sizeof *y);
    qt_apply(e->F, r, 0, n, e->fpiv, y);
    memcpy(w + rows, y + n, n * sizeof *w); /* the boundary rows */
    /* y[0 .. n) is acc's: the rows left by the chain's last block */
    for (size_t k = N; k-- > 1;) {
      const double *H = e->H + (k - 1) * 6 * n * n;
      memcpy(y + n, y, n * sizeof *y);
      qt_apply(H, r, 0, n, e->hpiv + (k - 1) * n, y);
      /* y[n .. 2n): interval k's rows left; y[0 .. n): acc before */
      double *wk = w + k * R;
      memcpy(wk + ci, y + n, n * sizeof *wk);
    }
    memcpy(w + ci, y, n * sizeof *w); /* interval 0's rows left */
    for (size_t i = 0; i < N; ++i)
      if (ci) qt_apply(twist_block(e, i), R, n, ci, e->gpiv + i * ci, w + i * R);
  }
}

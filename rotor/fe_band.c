/* rotor/fe_band.c — complex banded LU of a sparse matrix, for the interior
 * block of a finite-element rotor's dynamic stiffness (fe_hbm_lin.c).
 *
 * A beam rotor couples only neighbouring nodes, so in a good ordering its
 * matrices are banded with a half-bandwidth of about 2 nodes × 4 DOFs.  The
 * reverse Cuthill–McKee ordering (Cuthill & McKee, Proc. 24th ACM National
 * Conference (1969) 157; George & Liu, Computer Solution of Large Sparse
 * Positive Definite Systems, Prentice-Hall 1981, §4.3) finds such an
 * ordering for any input pattern (pedestal and bearing DOFs numbered last,
 * matrices of another FE code).  A banded LU with partial pivoting in
 * LAPACK's storage (kl extra rows for the fill) then factors and solves in
 * O(n kl (kl + ku)) without the symbolic bookkeeping of a general sparse
 * LU, which dominates at a few hundred DOFs.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"

/* The symmetrised adjacency (A + Aᵀ without the diagonal) in CSR arrays. */
static int adjacency(int n, const int *Ap, const int *Ai, int **xadj,
                     int **adj) {
  int nz = Ap[n];
  int *cnt = calloc((size_t)n + 1, sizeof *cnt);
  int *a = malloc((size_t)(2 * nz + 1) * sizeof *a);
  if (!cnt || !a) { free(cnt); free(a); return WHIRL_ENOMEM; }
  for (int c = 0; c < n; ++c)
    for (int q = Ap[c]; q < Ap[c + 1]; ++q)
      if (Ai[q] != c) { cnt[Ai[q] + 1]++; cnt[c + 1]++; }
  for (int i = 0; i < n; ++i) cnt[i + 1] += cnt[i];
  int *fill = malloc((size_t)(n ? n : 1) * sizeof *fill);
  if (!fill) { free(cnt); free(a); return WHIRL_ENOMEM; }
  memcpy(fill, cnt, (size_t)n * sizeof *fill);
  for (int c = 0; c < n; ++c)
    for (int q = Ap[c]; q < Ap[c + 1]; ++q)
      if (Ai[q] != c) { a[fill[Ai[q]]++] = c; a[fill[c]++] = Ai[q]; }
  free(fill);
  *xadj = cnt;
  *adj = a;
  return WHIRL_OK;
}

/* Breadth-first levels from s over unnumbered vertices (order[] gets the
 * visit order from position head); neighbours by increasing degree, as
 * Cuthill–McKee prescribes.  Returns the new head; *last is the vertex of
 * least degree in the last level, *depth the number of levels. */
static int bfs(int s, const int *xadj, const int *adj, char *seen, int *order,
               int head, int *last, int *depth) {
  int tail = head, lev_start = head, lev_end;
  order[tail++] = s;
  seen[s] = 1;
  *depth = 0;
  while (lev_start < tail) {
    lev_end = tail;
    ++*depth;
    for (int h = lev_start; h < lev_end; ++h) {
      int v = order[h], first = tail;
      for (int e = xadj[v]; e < xadj[v + 1]; ++e)
        if (!seen[adj[e]]) { seen[adj[e]] = 1; order[tail++] = adj[e]; }
      for (int i = first + 1; i < tail; ++i) { /* insertion by degree */
        int w = order[i], dw = xadj[w + 1] - xadj[w], j = i;
        while (j > first && xadj[order[j - 1] + 1] - xadj[order[j - 1]] > dw) {
          order[j] = order[j - 1];
          --j;
        }
        order[j] = w;
      }
    }
    *last = order[lev_start];
    for (int h = lev_start; h < lev_end; ++h) {
      int v = order[h];
      if (xadj[v + 1] - xadj[v] < xadj[*last + 1] - xadj[*last]) *last = v;
    }
    lev_start = lev_end;
  }
  return tail;
}

/* Reverse Cuthill–McKee: perm[new] = old, from a pseudo-peripheral start
 * of each connected component (George & Liu's heuristic: restart from the
 * far end while the level structure gets deeper). */
static int rcm(int n, const int *Ap, const int *Ai, int *perm) {
  int *xadj, *adj, rc = adjacency(n, Ap, Ai, &xadj, &adj);
  if (rc) return rc;
  char *seen = calloc((size_t)(n ? n : 1), 1);
  if (!seen) { free(xadj); free(adj); return WHIRL_ENOMEM; }
  int head = 0;
  for (int s0 = 0; s0 < n; ++s0) {
    if (seen[s0]) continue;
    int s = s0, last, depth, best = -1;
    for (int tries = 0; tries < 8; ++tries) {
      int end = bfs(s, xadj, adj, seen, perm, head, &last, &depth);
      for (int h = head; h < end; ++h) seen[perm[h]] = 0;
      if (depth <= best) break;
      best = depth;
      s = last;
    }
    head = bfs(s, xadj, adj, seen, perm, head, &last, &depth);
  }
  for (int i = 0, j = n - 1; i < j; ++i, --j) {
    int t = perm[i]; perm[i] = perm[j]; perm[j] = t;
  }
  free(seen);
  free(xadj);
  free(adj);
  return WHIRL_OK;
}

int fe_band_init(fe_band *b, int n, const int *Ap, const int *Ai) {
  memset(b, 0, sizeof *b);
  b->n = n;
  size_t nn = (size_t)(n ? n : 1), nz = (size_t)(Ap[n] ? Ap[n] : 1);
  b->perm = malloc(nn * sizeof *b->perm);
  b->pinv = malloc(nn * sizeof *b->pinv);
  b->pos = malloc(nz * sizeof *b->pos);
  b->ipiv = malloc(nn * sizeof *b->ipiv);
  b->scale = malloc(nn * sizeof *b->scale);
  if (!b->perm || !b->pinv || !b->pos || !b->ipiv || !b->scale)
    return WHIRL_ENOMEM;
  int rc = rcm(n, Ap, Ai, b->perm);
  if (rc) return rc;
  for (int i = 0; i < n; ++i) b->pinv[b->perm[i]] = i;
  for (int c = 0; c < n; ++c)
    for (int q = Ap[c]; q < Ap[c + 1]; ++q) {
      int d = b->pinv[Ai[q]] - b->pinv[c];
      if (d > b->kl) b->kl = d;
      if (-d > b->ku) b->ku = -d;
    }
  b->ldab = 2 * b->kl + b->ku + 1;
  for (int c = 0; c < n; ++c)
    for (int q = Ap[c]; q < Ap[c + 1]; ++q) {
      int i = b->pinv[Ai[q]], j = b->pinv[c];
      b->pos[q] = (size_t)(b->kl + b->ku + i - j) + (size_t)b->ldab * j;
    }
  b->ab = malloc((size_t)b->ldab * nn * sizeof *b->ab);
  return b->ab ? WHIRL_OK : WHIRL_ENOMEM;
}

void fe_band_free(fe_band *b) {
  free(b->perm);
  free(b->pinv);
  free(b->pos);
  free(b->ipiv);
  free(b->scale);
  free(b->ab);
  free(b->work);
  memset(b, 0, sizeof *b);
}

/* |re| + |im|, LAPACK's pivot measure (izamax). */
static double cabs1(double complex z) { return fabs(creal(z)) + fabs(cimag(z)); }

/* Entry (i, j) of the band array: A(i, j) = ab[kv + i − j + ldab j]. */
#define AB(b, i, j) ((b)->ab[(size_t)((b)->kl + (b)->ku + (i) - (j)) + \
                             (size_t)(b)->ldab * (size_t)(j)])

/* LU with partial pivoting in LAPACK's band layout, the algorithm of
 * zgbtf2 (Golub & Van Loan, Matrix Computations, 4th ed., §4.3.5): column
 * j's pivot among rows j..j+kl, the row swap within the band, multipliers
 * below the diagonal, and the rank-one update of the columns U reaches
 * (up to ju ≤ j + kl + ku).  The loops are written out: the vectors are
 * kl ≈ 10 long, where a BLAS call costs more than its arithmetic. */
/* Symmetric equilibration s_i = 1/√|a_ii| (1 where a_ii = 0), stored in
 * the new order: the LU factors S A S, whose diagonal has modulus 1.  A
 * rotor's DOFs mix metres and radians (stiffnesses in N/m and N·m/rad
 * many decades apart on a stiff shaft), and partial pivoting picks its
 * pivots by modulus, so it needs rows of comparable scale (the same reason
 * UMFPACK scales by default; Higham, Accuracy and Stability of Numerical
 * Algorithms, 2nd ed., §9.8). */
static void equilibrate(fe_band *b) {
  for (int j = 0; j < b->n; ++j) {
    double d = cabs(AB(b, j, j));
    b->scale[j] = d > 0 && isfinite(d) ? 1.0 / sqrt(d) : 1.0;
  }
  for (int j = 0; j < b->n; ++j) {
    int i0 = j - b->ku > 0 ? j - b->ku : 0;
    int i1 = j + b->kl < b->n - 1 ? j + b->kl : b->n - 1;
    for (int i = i0; i <= i1; ++i) AB(b, i, j) *= b->scale[i] * b->scale[j];
  }
}

int fe_band_factor(fe_band *b, const int *Ap, const double complex *x) {
  int n = b->n, kl = b->kl, ku = b->ku, ju = 0;
  b->kv = ku;
  memset(b->ab, 0, (size_t)b->ldab * n * sizeof *b->ab);
  for (int q = 0; q < Ap[n]; ++q) b->ab[b->pos[q]] += x[q];
  equilibrate(b);
  for (int j = 0; j < n; ++j) {
    int km = kl < n - 1 - j ? kl : n - 1 - j, p = 0;
    double big = cabs1(AB(b, j, j));
    for (int i = 1; i <= km; ++i)
      if (cabs1(AB(b, j + i, j)) > big) { big = cabs1(AB(b, j + i, j)); p = i; }
    b->ipiv[j] = j + p;
    if (big == 0) return WHIRL_ESINGULAR;
    int reach = j + ku + p < n - 1 ? j + ku + p : n - 1;
    if (reach > ju) ju = reach;
    if (ju - j > b->kv) b->kv = ju - j;
    if (p)
      for (int c = j; c <= ju; ++c) {
        double complex t = AB(b, j, c);
        AB(b, j, c) = AB(b, j + p, c);
        AB(b, j + p, c) = t;
      }
    double complex rpiv = 1.0 / AB(b, j, j);
    double complex *l = &AB(b, j, j) + 1;
    for (int i = 0; i < km; ++i) l[i] *= rpiv;
    for (int c = j + 1; c <= ju; ++c) {
      double complex u = AB(b, j, c), *col = &AB(b, j, c) + 1;
      if (u != 0)
        for (int i = 0; i < km; ++i) col[i] -= l[i] * u;
    }
  }
  return WHIRL_OK;
}

/* X := A⁻¹ X with PA = LU for r right-hand sides stored row by row
 * (X[i r + s]: the r values of row i side by side, so that each band entry
 * is loaded once for all of them): the eliminations (swap, then
 * multipliers) in order, then U backwards. */
static void solve_n(const fe_band *b, int r, double complex *X) {
  int n = b->n, kl = b->kl, kv = b->kv;
  for (int j = 0; j < n - 1; ++j) {
    int km = kl < n - 1 - j ? kl : n - 1 - j, p = b->ipiv[j];
    double complex *xj = X + (size_t)j * r, *xp = X + (size_t)p * r;
    for (int s = 0; s < r; ++s) {
      double complex t = xp[s];
      xp[s] = xj[s];
      xj[s] = t;
    }
    const double complex *l = &AB(b, j, j) + 1;
    for (int i = 0; i < km; ++i) {
      double complex li = l[i], *xi = X + (size_t)(j + 1 + i) * r;
      for (int s = 0; s < r; ++s) xi[s] -= li * xj[s];
    }
  }
  for (int j = n - 1; j >= 0; --j) {
    double complex d = 1.0 / AB(b, j, j), *xj = X + (size_t)j * r;
    for (int s = 0; s < r; ++s) xj[s] *= d;
    int i0 = j - kv > 0 ? j - kv : 0;
    for (int i = i0; i < j; ++i) {
      double complex u = AB(b, i, j), *xi = X + (size_t)i * r;
      for (int s = 0; s < r; ++s) xi[s] -= u * xj[s];
    }
  }
}

/* X := A⁻ᵀ X (plain transpose), same layout: Uᵀ forwards, then the
 * transposed eliminations in reverse order (multipliers, then the swap). */
static void solve_t(const fe_band *b, int r, double complex *X) {
  int n = b->n, kl = b->kl, kv = b->kv;
  for (int j = 0; j < n; ++j) {
    int i0 = j - kv > 0 ? j - kv : 0;
    double complex *xj = X + (size_t)j * r;
    for (int i = i0; i < j; ++i) {
      double complex u = AB(b, i, j), *xi = X + (size_t)i * r;
      for (int s = 0; s < r; ++s) xj[s] -= u * xi[s];
    }
    double complex d = 1.0 / AB(b, j, j);
    for (int s = 0; s < r; ++s) xj[s] *= d;
  }
  for (int j = n - 2; j >= 0; --j) {
    int km = kl < n - 1 - j ? kl : n - 1 - j, p = b->ipiv[j];
    const double complex *l = &AB(b, j, j) + 1;
    double complex *xj = X + (size_t)j * r, *xp = X + (size_t)p * r;
    for (int i = 0; i < km; ++i) {
      double complex li = l[i], *xi = X + (size_t)(j + 1 + i) * r;
      for (int s = 0; s < r; ++s) xj[s] -= li * xi[s];
    }
    for (int s = 0; s < r; ++s) {
      double complex t = xj[s];
      xj[s] = xp[s];
      xp[s] = t;
    }
  }
}

int fe_band_solve(fe_band *b, int transpose, int nrhs, double complex *B) {
  size_t n = (size_t)b->n, r = (size_t)nrhs;
  if (n * r > b->nwork) {
    double complex *w = realloc(b->work, n * r * sizeof *w);
    if (!w) return WHIRL_ENOMEM;
    b->work = w;
    b->nwork = n * r;
  }
  /* A = S⁻¹ Â S⁻¹: A x = b is Â (S⁻¹ x) = S b, and likewise with Aᵀ */
  for (size_t s = 0; s < r; ++s)
    for (size_t i = 0; i < n; ++i)
      b->work[i * r + s] = b->scale[i] * B[b->perm[i] + n * s];
  if (transpose) solve_t(b, nrhs, b->work);
  else solve_n(b, nrhs, b->work);
  for (size_t s = 0; s < r; ++s)
    for (size_t i = 0; i < n; ++i)
      B[b->perm[i] + n * s] = b->scale[i] * b->work[i * r + s];
  return WHIRL_OK;
}

/* lib/systems/fold_sparse.c — the sparse path of the fold system
 * (whirl/fold.h) for a base system with a sparse Jacobian pattern (a
 * collocation orbit: thousands of unknowns, a few dozen nonzeros a
 * column).  The same minimal augmentation as the dense path (Govaerts
 * 2000, ch. 4), with every matrix kept in compressed columns:
 *   - the bordered operator M = [A b; c^T 0] of order na + 1, A the leading
 *     na x na block of F_x plus the operator's constant entries E, factored
 *     by UMFPACK (whirl_linsol sparse);
 *   - the contractions w^T (F_x(x + hv) − F_x(x − hv)) (v, 0) over the
 *     nonzeros;
 *   - the fold system's own Jacobian [F_x F_free; g_x g_free]: the base
 *     pattern with one dense row (g_x; two with a branch-point curve's
 *     w^T F_q) and nfree dense columns, so that the core factors it by
 *     UMFPACK too.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#include "fold_sparse_impl.h"

void fold_sparse_free(fold_sparse *s) {
  free(s->Jp); free(s->Ji); free(s->col);
  free(s->Mp); free(s->Mi); free(s->kmap); free(s->emap); free(s->cpos);
  free(s->Mx); free(s->Sp); free(s->Si);
  memset(s, 0, sizeof *s);
}

static int cmp_int(const void *a, const void *b) {
  const int x = *(const int *)a, y = *(const int *)b;
  return (x > y) - (x < y);
}

/* Position of row i in column j of M, or -1. */
static long find_in(const fold_sparse *s, size_t j, int i) {
  for (int q = s->Mp[j]; q < s->Mp[j + 1]; ++q)
    if (s->Mi[q] == i) return q;
  return -1;
}

/* Pattern of M: per column j < na the rows < na of F_x's column and of E,
 * sorted without repeats, then row na (c); column na all rows (b, 0). */
static int m_pattern(fold_sparse *s, size_t ne, const size_t *er, const size_t *ec) {
  const size_t na = s->na;
  size_t cap = s->nnz + ne + 2 * na + 1;
  s->Mp = malloc((na + 2) * sizeof *s->Mp);
  s->Mi = malloc(cap * sizeof *s->Mi);
  if (!s->Mp || !s->Mi) return -1;
  size_t q = 0;
  for (size_t j = 0; j < na; ++j) {
    s->Mp[j] = (int)q;
    const size_t q0 = q;
    for (int k = s->Jp[j]; k < s->Jp[j + 1]; ++k)
      if ((size_t)s->Ji[k] < na) s->Mi[q++] = s->Ji[k];
    for (size_t e = 0; e < ne; ++e)
      if (ec[e] == j) s->Mi[q++] = (int)er[e];
    qsort(s->Mi + q0, q - q0, sizeof *s->Mi, cmp_int);
    size_t u = q0;
    for (size_t t = q0; t < q; ++t)
      if (t == q0 || s->Mi[t] != s->Mi[u - 1]) s->Mi[u++] = s->Mi[t];
    q = u;
    s->Mi[q++] = (int)na;
  }
  s->Mp[na] = (int)q;
  for (size_t i = 0; i <= na; ++i) s->Mi[q++] = (int)i;
  s->Mp[na + 1] = (int)q;
  s->mnz = q;
  return 0;
}

/* Where each base entry, E entry and c_j go in M's values. */
static int m_maps(fold_sparse *s, size_t ne, const size_t *er, const size_t *ec) {
  s->kmap = malloc((s->nnz ? s->nnz : 1) * sizeof *s->kmap);
  s->emap = malloc((ne ? ne : 1) * sizeof *s->emap);
  s->cpos = malloc(s->na * sizeof *s->cpos);
  s->Mx = malloc(s->mnz * sizeof *s->Mx);
  if (!s->kmap || !s->emap || !s->cpos || !s->Mx) return -1;
  for (size_t k = 0; k < s->nnz; ++k)
    s->kmap[k] = (size_t)s->col[k] < s->na && (size_t)s->Ji[k] < s->na
                     ? find_in(s, (size_t)s->col[k], s->Ji[k]) : -1;
  for (size_t e = 0; e < ne; ++e) s->emap[e] = find_in(s, ec[e], (int)er[e]);
  for (size_t j = 0; j < s->na; ++j) s->cpos[j] = s->Mp[j + 1] - 1;
  return 0;
}

/* The fold system's pattern: base columns with rows n .. n + nrow - 1
 * appended (g, and a condition's row), then nfree full columns of n + nrow
 * rows. */
static int sys_pattern(fold_sparse *s, size_t nfree, size_t nrow) {
  const size_t n = s->n, N = n + nfree;
  s->snz = s->nnz + nrow * n + nfree * (n + nrow);
  s->Sp = malloc((N + 1) * sizeof *s->Sp);
  s->Si = malloc(s->snz * sizeof *s->Si);
  if (!s->Sp || !s->Si) return -1;
  size_t q = 0;
  for (size_t j = 0; j < n; ++j) {
    s->Sp[j] = (int)q;
    for (int k = s->Jp[j]; k < s->Jp[j + 1]; ++k) s->Si[q++] = s->Ji[k];
    for (size_t r = 0; r < nrow; ++r) s->Si[q++] = (int)(n + r);
  }
  for (size_t f = 0; f < nfree; ++f) {
    s->Sp[n + f] = (int)q;
    for (size_t i = 0; i < n + nrow; ++i) s->Si[q++] = (int)i;
  }
  s->Sp[N] = (int)q;
  return 0;
}

int fold_sparse_alloc(fold_sparse *s, const whirl_system *base, size_t na, size_t ne,
                      const size_t *er, const size_t *ec, size_t nfree, size_t nrow) {
  memset(s, 0, sizeof *s);
  const size_t n = base->n;
  s->n = n, s->na = na, s->nnz = base->nnz;
  s->Jp = malloc((n + 1) * sizeof *s->Jp);
  s->Ji = malloc((s->nnz ? s->nnz : 1) * sizeof *s->Ji);
  s->col = malloc((s->nnz ? s->nnz : 1) * sizeof *s->col);
  if (!s->Jp || !s->Ji || !s->col) return -1;
  memcpy(s->Jp, base->Jp, (n + 1) * sizeof *s->Jp);
  memcpy(s->Ji, base->Ji, s->nnz * sizeof *s->Ji);
  for (size_t j = 0; j < n; ++j)
    for (int k = s->Jp[j]; k < s->Jp[j + 1]; ++k) s->col[k] = (int)j;
  if (m_pattern(s, ne, er, ec) || m_maps(s, ne, er, ec) || sys_pattern(s, nfree, nrow)) return -1;
  return 0;
}

void fold_sparse_fill_m(fold_sparse *s, const double *Jx, const double *b, const double *c,
                        size_t ne, const double *ev) {
  const size_t na = s->na;
  memset(s->Mx, 0, s->mnz * sizeof *s->Mx);
  for (size_t k = 0; k < s->nnz; ++k)
    if (s->kmap[k] >= 0) s->Mx[s->kmap[k]] += Jx[k];
  for (size_t e = 0; e < ne; ++e) s->Mx[s->emap[e]] += ev[e];
  for (size_t j = 0; j < na; ++j) s->Mx[s->cpos[j]] = c[j];
  const size_t b0 = (size_t)s->Mp[na];
  memcpy(s->Mx + b0, b, na * sizeof *s->Mx);
  s->Mx[b0 + na] = 0.0;
}

double fold_sparse_wdiffv(const fold_sparse *s, const double *w, const double *Ap,
                          const double *Am, const double *v) {
  double acc = 0.0;
  for (size_t k = 0; k < s->nnz; ++k)
    if ((size_t)s->Ji[k] < s->na && (size_t)s->col[k] < s->na)
      acc += w[s->Ji[k]] * (Ap[k] - Am[k]) * v[s->col[k]];
  return acc;
}

void fold_sparse_wdiff_cols(const fold_sparse *s, const double *w, const double *Ap,
                            const double *Am, double *out) {
  memset(out, 0, s->n * sizeof *out);
  for (size_t k = 0; k < s->nnz; ++k)
    if ((size_t)s->Ji[k] < s->na) out[s->col[k]] += w[s->Ji[k]] * (Ap[k] - Am[k]);
}

double fold_sparse_wju(const fold_sparse *s, const double *w, const double *J,
                       const double *u) {
  double acc = 0.0;
  for (size_t k = 0; k < s->nnz; ++k) acc += w[s->Ji[k]] * J[k] * u[s->col[k]];
  return acc;
}

/* rotor/fe_sparse.c — triplet lists summed into compressed columns (the
 * layout of whirl_fe_csc and whirl/linsol.h), and y += aAx: the few sparse
 * operations the finite-element rotor needs.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#include "fe_impl.h"

void fe_trip_init(fe_trip *t, int n) {
  memset(t, 0, sizeof *t);
  t->n = n;
}

static int grow(fe_trip *t) {
  size_t cap = t->cap ? 2 * t->cap : 256;
  int *i = realloc(t->i, cap * sizeof *i);
  if (i) t->i = i;
  int *j = realloc(t->j, cap * sizeof *j);
  if (j) t->j = j;
  double *x = realloc(t->x, cap * sizeof *x);
  if (x) t->x = x;
  if (!i || !j || !x) return -1;
  t->cap = cap;
  return 0;
}

void fe_trip_add(fe_trip *t, int i, int j, double x) {
  if (t->failed) return;
  if (t->nt == t->cap && grow(t)) {
    t->failed = 1;
    return;
  }
  t->i[t->nt] = i;
  t->j[t->nt] = j;
  t->x[t->nt] = x;
  t->nt++;
}

void fe_trip_add_csc(fe_trip *t, const whirl_fe_csc *A, double a, int r0, int c0) {
  for (int c = 0; c < A->n; ++c)
    for (int k = A->p[c]; k < A->p[c + 1]; ++k) fe_trip_add(t, r0 + A->i[k], c0 + c, a * A->x[k]);
}

static void trip_free(fe_trip *t) {
  free(t->i);
  free(t->j);
  free(t->x);
  memset(t, 0, sizeof *t);
}

/* Counting sort by column, then by row within each column (two passes of
 * a bucket sort keep it O(nnz + n)), then duplicates summed. */
int fe_trip_to_csc(fe_trip *t, whirl_fe_csc *A) {
  const int n = t->n;
  memset(A, 0, sizeof *A);
  int *cnt = calloc((size_t)n + 1, sizeof *cnt);
  size_t *ord = malloc((t->nt + 1) * sizeof *ord), *tmp = malloc((t->nt + 1) * sizeof *tmp);
  int *pos = malloc(((size_t)n + 1) * sizeof *pos);
  int rc = WHIRL_ENOMEM;
  if (t->failed || !cnt || !ord || !tmp || !pos) goto done;
  /* by row, then stably by column */
  for (int pass = 0; pass < 2; ++pass) {
    const int *key = pass == 0 ? t->i : t->j;
    memset(cnt, 0, ((size_t)n + 1) * sizeof *cnt);
    for (size_t k = 0; k < t->nt; ++k) cnt[key[k] + 1]++;
    for (int c = 0; c < n; ++c) cnt[c + 1] += cnt[c];
    memcpy(pos, cnt, ((size_t)n + 1) * sizeof *pos);
    for (size_t m = 0; m < t->nt; ++m) {
      size_t k = pass == 0 ? m : tmp[m];
      ord[pos[key[k]]++] = k;
    }
    if (pass == 0) memcpy(tmp, ord, t->nt * sizeof *ord);
  }
  A->n = n;
  A->p = calloc((size_t)n + 1, sizeof *A->p);
  A->i = malloc((t->nt + 1) * sizeof *A->i);
  A->x = malloc((t->nt + 1) * sizeof *A->x);
  if (!A->p || !A->i || !A->x) goto done;
  /* cnt: the column starts of ord (the last pass); rows sorted within */
  int nnz = 0;
  for (int c = 0; c < n; ++c) {
    A->p[c] = nnz;
    for (int m = cnt[c]; m < cnt[c + 1]; ++m) {
      size_t k = ord[m];
      if (nnz > A->p[c] && A->i[nnz - 1] == t->i[k]) {
        A->x[nnz - 1] += t->x[k];
        continue;
      }
      A->i[nnz] = t->i[k];
      A->x[nnz++] = t->x[k];
    }
  }
  A->p[n] = nnz;
  rc = WHIRL_OK;
done:
  if (rc != WHIRL_OK) fe_csc_free(A);
  free(cnt);
  free(ord);
  free(tmp);
  free(pos);
  trip_free(t);
  return rc;
}

void fe_csc_free(whirl_fe_csc *A) {
  if (!A) return;
  free(A->p);
  free(A->i);
  free(A->x);
  memset(A, 0, sizeof *A);
}

void fe_csc_gemv(const whirl_fe_csc *A, double a, const double *x, double *y) {
  for (int c = 0; c < A->n; ++c)
    for (int k = A->p[c]; k < A->p[c + 1]; ++k) y[A->i[k]] += a * A->x[k] * x[c];
}

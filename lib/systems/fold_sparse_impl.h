/* lib/systems/fold_sparse_impl.h — the sparse path of the fold system
 * (fold_sparse.c), used by fold.c for bases with a sparse pattern.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_FOLD_SPARSE_IMPL_H
#define WHIRL_FOLD_SPARSE_IMPL_H

#include <stddef.h>
#include <whirl/system.h>

typedef struct fold_sparse {
  size_t n, na, nnz;  /* base unknowns, order of A, base nonzeros */
  int *Jp, *Ji, *col; /* base pattern (copied) and each entry's column */
  int *Mp, *Mi;       /* pattern of M = [A b; c^T 0], order na + 1 */
  size_t mnz;
  long *kmap;         /* nnz: M's entry of a base entry, -1 outside A */
  long *emap;         /* ne: M's entry of each E entry */
  long *cpos;         /* na: M's entry (na, j) */
  double *Mx;         /* mnz values */
  int *Sp, *Si;       /* the fold system's pattern, n + nfree columns */
  size_t snz;
} fold_sparse;

/* nrow: the rows below the base's (g; g and a condition's).
 * 0, or -1 out of memory (s then holds what was allocated: free it). */
int fold_sparse_alloc(fold_sparse *s, const whirl_system *base, size_t na, size_t ne,
                      const size_t *er, const size_t *ec, size_t nfree, size_t nrow);
void fold_sparse_free(fold_sparse *s);

/* M's values into s->Mx from the base values Jx[nnz], borders b, c[na]
 * and the operator's constants ev[ne]. */
void fold_sparse_fill_m(fold_sparse *s, const double *Jx, const double *b, const double *c,
                        size_t ne, const double *ev);

/* sum over A's block of w_i (Ap − Am)_ij v_j. */
double fold_sparse_wdiffv(const fold_sparse *s, const double *w, const double *Ap,
                          const double *Am, const double *v);

/* out[j] = sum over rows i < na of w_i (Ap − Am)_ij, for every column j < n. */
void fold_sparse_wdiff_cols(const fold_sparse *s, const double *w, const double *Ap,
                            const double *Am, double *out);

/* w^T J u over every entry (w[n], u[n]). */
double fold_sparse_wju(const fold_sparse *s, const double *w, const double *J,
                       const double *u);

#endif

/* whirl/linsol.h — one factor/solve interface over two backends:
 * dense LU (LAPACK dgetrf/dgetrs) and sparse LU (SuiteSparse KLU, or
 * UMFPACK with WHIRL_SPARSE_LU=umfpack in the environment, with the
 * symbolic analysis done once for a fixed pattern and a numeric factorisation
 * per call), plus bordered systems [A B; C D] and dense eigenvalues (dgeev).
 * Objects own all their workspace: factor and solve never allocate (except
 * inside KLU's or UMFPACK's numeric factorisation).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_LINSOL_H
#define WHIRL_LINSOL_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum whirl_linsol_kind {
  WHIRL_LINSOL_DENSE = 0,
  WHIRL_LINSOL_SPARSE = 1
} whirl_linsol_kind;

typedef struct whirl_linsol whirl_linsol;

/* Dense n x n solver.  Returns NULL on n == 0 or out of memory. */
WHIRL_API whirl_linsol *whirl_linsol_alloc_dense(size_t n);

/* Sparse n x n solver for the compressed-column pattern Ap[n+1], Ai[nnz]
 * (copied).  Row indices must be in [0, n) and sorted within each column.
 * Returns NULL on bad pattern or out of memory. */
WHIRL_API whirl_linsol *whirl_linsol_alloc_sparse(size_t n, const int *Ap,
                                                  const int *Ai);

WHIRL_API void whirl_linsol_free(whirl_linsol *ls);  /* accepts NULL */

WHIRL_API whirl_linsol_kind whirl_linsol_get_kind(const whirl_linsol *ls);
WHIRL_API size_t whirl_linsol_size(const whirl_linsol *ls);

/* Factorise A: dense, A[n*n] column-major; sparse, Ax[nnz] values in the
 * pattern's order.  A is copied, not kept.  Returns WHIRL_OK, or
 * WHIRL_ESINGULAR for an exactly singular matrix (the factor is still usable
 * for logdet, which then reports sign 0), or WHIRL_ELAPACK / WHIRL_ESPARSE. */
WHIRL_API int whirl_linsol_factor(whirl_linsol *ls, const double *A);

/* Solve A X = B in place for nrhs right-hand sides B[n*nrhs] column-major
 * (trans = 0), or A^T X = B (trans = 1), with the last factorisation. */
WHIRL_API int whirl_linsol_solve(whirl_linsol *ls, double *B, size_t nrhs,
                                 int trans);

/* Steps of iterative refinement per sparse solve (UMFPACK's IRSTEP, and
 * whirl's own with KLU by the same rule; default 2, each costing a
 * residual and another solve, taken while the backward error exceeds the
 * rounding unit and halves).  0 is for
 * callers whose solves only feed an iteration that corrects itself, e.g.
 * shift-invert Arnoldi.  Dense LU: no refinement, WHIRL_OK.  WHIRL_EINVAL
 * for steps < 0. */
WHIRL_API int whirl_linsol_set_refinement(whirl_linsol *ls, int steps);

/* log|det A| and its sign (-1, 0, +1) from the last factorisation; no
 * overflow for large n. */
WHIRL_API int whirl_linsol_logdet(const whirl_linsol *ls, double *logabs,
                                  int *sign);

/* Message describing the last failure ("" if none); owned by ls. */
WHIRL_API const char *whirl_linsol_errmsg(const whirl_linsol *ls);

/* ------------------------------------------------------------------------
 * Bordered systems  M = [A  B]   A n x n (dense or sparse pattern),
 *                       [C  D]   B n x m, C m x n, D m x m, all dense.
 * The (n+m) matrix is assembled once per factorisation into one dense or one
 * sparse LU (pattern of A plus dense borders; symbolic analysis once), so it
 * stays well conditioned when A itself is singular (folds, branch points).
 */
typedef struct whirl_bordered whirl_bordered;

/* kind DENSE: Ap/Ai ignored (may be NULL).  kind SPARSE: pattern of A. */
WHIRL_API whirl_bordered *whirl_bordered_alloc(whirl_linsol_kind kind,
                                               size_t n, size_t m,
                                               const int *Ap, const int *Ai);
WHIRL_API void whirl_bordered_free(whirl_bordered *b);  /* accepts NULL */

/* A: dense A[n*n] column-major or sparse values Ax[nnz];
 * B[n*m] column-major; C[m*n] column-major (C[i + m*j]); D[m*m] col-major. */
WHIRL_API int whirl_bordered_factor(whirl_bordered *b, const double *A,
                                    const double *B, const double *C,
                                    const double *D);
/* Solve M X = R in place, R[(n+m)*nrhs] column-major; trans = 1 for M^T. */
WHIRL_API int whirl_bordered_solve(whirl_bordered *b, double *R, size_t nrhs,
                                   int trans);
WHIRL_API int whirl_bordered_logdet(const whirl_bordered *b, double *logabs,
                                    int *sign);
WHIRL_API const char *whirl_bordered_errmsg(const whirl_bordered *b);

/* ------------------------------------------------------------------------
 * Dense eigenvalues (LAPACK dgeev, no vectors), workspace owned. */
typedef struct whirl_eig whirl_eig;
WHIRL_API whirl_eig *whirl_eig_alloc(size_t n);
WHIRL_API void whirl_eig_free(whirl_eig *e);  /* accepts NULL */
/* The reason of the last failure of whirl_eig_compute ("" after success). */
WHIRL_API const char *whirl_eig_errmsg(const whirl_eig *e);
/* Eigenvalues of A[n*n] (column-major, not modified): re[n], im[n], sorted by
 * decreasing real part (conjugate pairs adjacent, positive imaginary first). */
WHIRL_API int whirl_eig_compute(whirl_eig *e, const double *A, double *re,
                                double *im);

/* Null space helper for branch switching: the right singular vectors of the
 * dense m x k matrix A[m*k] (column-major, m <= k) belonging to its `nvec`
 * smallest singular values, as V[k*nvec] column-major; sv[nvec] receives
 * those singular values.  LAPACK dgesvd. */
WHIRL_API int whirl_null_vectors(size_t m, size_t k, const double *A,
                                 size_t nvec, double *V, double *sv);

/* A vector u[n] of the null space of the m x n matrix A (column-major,
 * overwritten), whose dimension is k (m + k >= n), by Gaussian elimination
 * with complete pivoting: the k unknowns left free are 1 (not normalised).
 * A fixed choice in a null space of dimension k > 1, AUTO-07p's (NLVC): the
 * phase of the orbits started at a Hopf point.  WHIRL_EINVAL for bad sizes
 * or a non-finite A, WHIRL_ENOMEM. */
WHIRL_API int whirl_null_vector_pivoted(size_t m, size_t n, size_t k, double *A,
                                        double *u);

#ifdef __cplusplus
}
#endif
#endif

/* linalg/linsol_impl.h — private to lib/linalg: the whirl_linsol object and
 * its backend ops table (SUNDIALS SUNLinearSolver shape), the Fortran LAPACK
 * prototypes and the CSC pattern check shared by sparse.c and bordered.c.
 * Errors: WHIRL_FAIL (util/errmsg_impl.h) into each object's errmsg.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_LINSOL_IMPL_H
#define WHIRL_LINSOL_IMPL_H

#include <stddef.h>

#include <whirl/linsol.h>

#include "util/errmsg_impl.h"

/* ------------------------------------------------------------------------
 * LAPACK's complaints (xerbla.c): xerbla_ records the routine and argument
 * for the calling thread instead of printing.  Call whirl_lapack_clear
 * before a LAPACK call; whirl_lapack_take afterwards returns 1 (and
 * "LAPACK DGEBAL: argument 3 had an illegal value" in msg) if LAPACK
 * complained during the call, and clears the record. */
void whirl_lapack_clear(void);
int whirl_lapack_take(char *msg, size_t len);

/* ------------------------------------------------------------------------
 * LAPACK (Fortran 77 interface, reference or optimised).  Integers are
 * Fortran INTEGER = C int (LP64).  CHARACTER arguments carry a hidden length
 * appended after the last argument; gfortran >= 8 passes it as size_t.  We
 * declare and pass those lengths (always 1) explicitly: omitting them is
 * undefined and has broken callers when gfortran turned LAPACK's internal
 * calls into sibling calls (the R "FCONE" episode, GCC PR 90329). */
extern void dgetrf_(const int *m, const int *n, double *a, const int *lda,
                    int *ipiv, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs,
                    const double *a, const int *lda, const int *ipiv,
                    double *b, const int *ldb, int *info, size_t trans_len);
extern void dgeev_(const char *jobvl, const char *jobvr, const int *n,
                   double *a, const int *lda, double *wr, double *wi,
                   double *vl, const int *ldvl, double *vr, const int *ldvr,
                   double *work, const int *lwork, int *info, size_t jobvl_len,
                   size_t jobvr_len);
extern void dgesvd_(const char *jobu, const char *jobvt, const int *m,
                    const int *n, double *a, const int *lda, double *s,
                    double *u, const int *ldu, double *vt, const int *ldvt,
                    double *work, const int *lwork, int *info,
                    size_t jobu_len, size_t jobvt_len);

/* ------------------------------------------------------------------------
 * The solver object.  The generic part (linsol.c) owns the value buffer
 * `vals` that the public factor copies into; each backend factorises from
 * it.  Dense: vals[n*n] column-major, overwritten by the LU factors.
 * Sparse: vals[nnz] in pattern order, kept because UMFPACK's iterative
 * refinement in the solve needs A itself.  The bordered solver assembles
 * its matrix straight into vals (whirl_linsol_values) so M exists once. */
typedef enum whirl_linsol_state {
  WHIRL_LS_NONE = 0,     /* no usable factorisation */
  WHIRL_LS_OK = 1,       /* nonsingular factors */
  WHIRL_LS_SINGULAR = 2  /* exactly singular: logdet gives sign 0, no solve */
} whirl_linsol_state;

typedef struct whirl_linsol_ops {
  /* Factorise ls->vals (already checked finite).  WHIRL_OK, WHIRL_ESINGULAR
   * (factors still valid for logdet) or another error code. */
  int (*factor)(whirl_linsol *ls);
  /* Solve with valid nonsingular factors; B[n*nrhs], nrhs >= 1, trans 0/1. */
  int (*solve)(whirl_linsol *ls, double *B, size_t nrhs, int trans);
  /* log|det| and sign of nonsingular factors. */
  int (*logdet)(const whirl_linsol *ls, double *logabs, int *sign);
  /* Release ls->backend; must accept a half-built or NULL backend. */
  void (*free)(void *backend);
} whirl_linsol_ops;

struct whirl_linsol {
  whirl_linsol_kind kind;
  size_t n;                    /* order of the matrix */
  const whirl_linsol_ops *ops; /* backend functions */
  void *backend;               /* backend data, owned */
  double *vals;                /* nvals matrix values, owned (see above) */
  size_t nvals;
  whirl_linsol_state state;
  char errmsg[WHIRL_ERRMSG_SIZE];
};

/* linsol.c: allocate the generic part with a zeroed vals[nvals]; the caller
 * then sets ops and backend.  NULL on out of memory. */
whirl_linsol *whirl_linsol_new(whirl_linsol_kind kind, size_t n, size_t nvals);

/* linsol.c: the value buffer (n*n or nnz entries) and a factorisation of
 * whatever it currently holds, for callers that assemble in place. */
double *whirl_linsol_values(whirl_linsol *ls);
int whirl_linsol_factor_values(whirl_linsol *ls);

/* sparse.c: 1 if (n, Ap[n+1], Ai[Ap[n]]) is a valid compressed-column
 * pattern (Ap[0] = 0, Ap nondecreasing, rows in [0, n) strictly increasing
 * within each column, nnz representable as int), else 0. */
int whirl_csc_check(size_t n, const int *Ap, const int *Ai);

/* The largest n a LAPACK/UMFPACK int argument accepts, and an n*n that must
 * not overflow size_t either. */
int whirl_dim_ok(size_t n);

#endif

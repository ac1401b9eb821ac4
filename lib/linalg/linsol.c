/* linalg/linsol.c — the public whirl_linsol_* entry points.  They check
 * arguments, copy the matrix into the object's value buffer, keep track of
 * whether a usable factorisation exists, and dispatch to the dense
 * (dense.c) or sparse (sparse.c) backend through the ops table.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "linsol_impl.h"

int whirl_dim_ok(size_t n) {
  return n >= 1 && n <= (size_t)INT_MAX && n <= SIZE_MAX / n;
}

whirl_linsol *whirl_linsol_new(whirl_linsol_kind kind, size_t n, size_t nvals) {
  whirl_linsol *ls;
  if (nvals > SIZE_MAX / sizeof(double)) return NULL;
  ls = calloc(1, sizeof *ls);
  if (!ls) return NULL;
  ls->kind = kind;
  ls->n = n;
  ls->nvals = nvals;
  ls->state = WHIRL_LS_NONE;
  /* nvals can be 0 for an all-zero sparse pattern; keep vals non-NULL. */
  ls->vals = calloc(nvals ? nvals : 1, sizeof *ls->vals);
  if (!ls->vals) {
    free(ls);
    return NULL;
  }
  return ls;
}

void whirl_linsol_free(whirl_linsol *ls) {
  if (!ls) return;
  if (ls->ops && ls->ops->free) ls->ops->free(ls->backend);
  free(ls->vals);
  free(ls);
}

whirl_linsol_kind whirl_linsol_get_kind(const whirl_linsol *ls) {
  return ls ? ls->kind : WHIRL_LINSOL_DENSE;
}

size_t whirl_linsol_size(const whirl_linsol *ls) { return ls ? ls->n : 0; }

double *whirl_linsol_values(whirl_linsol *ls) { return ls->vals; }

int whirl_linsol_factor_values(whirl_linsol *ls) {
  int rc;
  size_t p;
  ls->errmsg[0] = '\0';
  ls->state = WHIRL_LS_NONE;
  /* LAPACK and UMFPACK do not promise anything on NaN/Inf input (dgetrf may
   * pivot on a NaN and report success); catch it here with a useful index. */
  for (p = 0; p < ls->nvals; ++p) {
    if (!isfinite(ls->vals[p])) {
      if (ls->kind == WHIRL_LINSOL_DENSE)
        return WHIRL_FAIL(ls, WHIRL_EINVAL,
                          "matrix entry (%zu,%zu) is not finite (%g)",
                          p % ls->n, p / ls->n, ls->vals[p]);
      return WHIRL_FAIL(ls, WHIRL_EINVAL,
                        "sparse matrix value Ax[%zu] is not finite (%g)", p,
                        ls->vals[p]);
    }
  }
  rc = ls->ops->factor(ls);
  if (rc == WHIRL_OK)
    ls->state = WHIRL_LS_OK;
  else if (rc == WHIRL_ESINGULAR)
    ls->state = WHIRL_LS_SINGULAR;
  return rc;
}

int whirl_linsol_factor(whirl_linsol *ls, const double *A) {
  if (!ls) return WHIRL_EINVAL;
  if (!A) {
    ls->state = WHIRL_LS_NONE;
    return WHIRL_FAIL(ls, WHIRL_EINVAL, "factor: matrix pointer is NULL");
  }
  memcpy(ls->vals, A, ls->nvals * sizeof *ls->vals);
  return whirl_linsol_factor_values(ls);
}

int whirl_linsol_solve(whirl_linsol *ls, double *B, size_t nrhs, int trans) {
  if (!ls) return WHIRL_EINVAL;
  ls->errmsg[0] = '\0';
  if (trans != 0 && trans != 1)
    return WHIRL_FAIL(ls, WHIRL_EINVAL, "solve: trans = %d, must be 0 or 1",
                      trans);
  if (nrhs == 0) return WHIRL_OK;
  if (!B) return WHIRL_FAIL(ls, WHIRL_EINVAL, "solve: B is NULL");
  if (nrhs > (size_t)INT_MAX || nrhs > SIZE_MAX / ls->n)
    return WHIRL_FAIL(ls, WHIRL_EINVAL, "solve: nrhs = %zu is too large",
                      nrhs);
  switch (ls->state) {
    case WHIRL_LS_OK:
      return ls->ops->solve(ls, B, nrhs, trans);
    case WHIRL_LS_SINGULAR:
      return WHIRL_FAIL(ls, WHIRL_ESINGULAR,
                        "solve: the last factorisation was singular");
    case WHIRL_LS_NONE:
    default:
      return WHIRL_FAIL(ls, WHIRL_EINVAL,
                        "solve: no successful factorisation to solve with");
  }
}

int whirl_linsol_logdet(const whirl_linsol *ls, double *logabs, int *sign) {
  if (!ls || !logabs || !sign) return WHIRL_EINVAL;
  switch (ls->state) {
    case WHIRL_LS_OK:
      return ls->ops->logdet(ls, logabs, sign);
    case WHIRL_LS_SINGULAR:
      /* det = 0 exactly: log|det| = -inf, sign 0. */
      *logabs = -HUGE_VAL;
      *sign = 0;
      return WHIRL_OK;
    case WHIRL_LS_NONE:
    default:
      /* ls is const, so no message can be stored; the code says it all. */
      *logabs = 0.0;
      *sign = 0;
      return WHIRL_EINVAL;
  }
}

const char *whirl_linsol_errmsg(const whirl_linsol *ls) {
  return ls ? ls->errmsg : "whirl_linsol: NULL object";
}

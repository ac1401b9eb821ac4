/* rotor/fe_matrix.c — the linear part of a rotor as Matrix Market files,
 * read and written with CHOLMOD (cholmod_read_sparse,
 * cholmod_write_sparse; SuiteSparse's CHOLMOD User Guide, "Check module"):
 * a user of another finite-element code brings M, C, G, K in whirl's DOF
 * order (4 a node: y, z, θy, θz, node by node) and adds the nonlinear
 * elements in the rotor file (`nodes` and `matrices` lines,
 * doc/rotor-file.md); `whirl rotor export` writes a rotor's matrices the
 * same way.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include <cholmod.h>

#ifdef HAVE_CONFIG_H
#include "config.h"
#endif
#include <whirl/dynlib.h>
#include <whirl/rotor/fe_linear.h>

#include "fe_impl.h"

/* CHOLMOD, opened at the first matrix read or written (whirl/dynlib.h) */
#define CHOLMOD_FUNCS(X)                                                       \
  X(cholmod_start) X(cholmod_finish) X(cholmod_read_sparse) X(cholmod_write_sparse) \
  X(cholmod_allocate_sparse) X(cholmod_free_sparse)
WHIRL_DYNLIB_CHOLMOD(chol, CHOLMOD_FUNCS)

/* CHOLMOD bound, or −1 with the reason in msg */
static int cholmod_here(char *msg, size_t len) {
  char why[256];
  if (chol_bind(why, sizeof why) == WHIRL_OK) return 0;
  snprintf(msg, len, "CHOLMOD (Matrix Market files): %s", why);
  return -1;
}

/* Read the real square matrix of PATH, n×n, into T (added to it): both
 * triangles of a symmetric (or skew-symmetric) file.  0, or −1 with the
 * reason in msg. */
int fe_matrix_read(const char *path, int n, fe_trip *T, char *msg, size_t len) {
  struct stat st;
  if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) { /* a device or FIFO never ends */
    snprintf(msg, len, "'%s' is not a regular file", path);
    return -1;
  }
  if (cholmod_here(msg, len)) return -1;
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, len, "cannot open '%s': %s", path, strerror(errno));
    return -1;
  }
  cholmod_common cc;
  chol.cholmod_start(&cc);
  cc.print = 0;
  cholmod_sparse *A = chol.cholmod_read_sparse(f, &cc);
  fclose(f);
  int rc = 0;
  if (!A) {
    snprintf(msg, len, "'%s' is not a Matrix Market sparse matrix (CHOLMOD status %d)", path,
             cc.status);
    rc = -1;
  } else if (A->xtype != CHOLMOD_REAL || A->nrow != (size_t)n || A->ncol != (size_t)n) {
    snprintf(msg, len, "'%s' is %zu x %zu%s: the rotor has %d DOFs (4 a node)", path,
             A->nrow, A->ncol, A->xtype != CHOLMOD_REAL ? ", not real" : "", n);
    rc = -1;
  } else {
    const int *Ap = A->p, *Ai = A->i;
    const double *Ax = A->x;
    for (size_t j = 0; j < A->ncol; j++)
      for (int q = Ap[j]; q < (A->packed ? Ap[j + 1] : Ap[j] + ((int *)A->nz)[j]); q++) {
        const int i = Ai[q];
        fe_trip_add(T, i, (int)j, Ax[q]);
        /* a symmetric file stores one triangle (stype: which); CHOLMOD reads
         * a skew-symmetric one as unsymmetric, both triangles */
        if (A->stype != 0 && i != (int)j) fe_trip_add(T, (int)j, i, Ax[q]);
      }
    if (T->failed) {
      snprintf(msg, len, "out of memory reading '%s'", path);
      rc = -1;
    }
  }
  chol.cholmod_free_sparse(&A, &cc);
  chol.cholmod_finish(&cc);
  return rc;
}

/* Write the n×n matrix A of the rotor to PATH in Matrix Market
 * coordinate form.  0, or −1 with the reason in msg. */
static int fe_matrix_write(const whirl_fe_csc *A, FILE *f, const char *name, char *msg,
                           size_t len) {
  if (cholmod_here(msg, len)) return -1;
  cholmod_common cc;
  chol.cholmod_start(&cc);
  cc.print = 0;
  const int nnz = A->p[A->n];
  cholmod_sparse *S = chol.cholmod_allocate_sparse((size_t)A->n, (size_t)A->n, (size_t)nnz, 1, 1, 0,
                                              CHOLMOD_REAL, &cc);
  int rc = 0;
  if (!S) {
    snprintf(msg, len, "%s: out of memory", name);
    rc = -1;
  } else {
    memcpy(S->p, A->p, (size_t)(A->n + 1) * sizeof *A->p);
    memcpy(S->i, A->i, (size_t)nnz * sizeof *A->i);
    memcpy(S->x, A->x, (size_t)nnz * sizeof *A->x);
    if (chol.cholmod_write_sparse(f, S, NULL, NULL, &cc) < 0) {
      snprintf(msg, len, "%s: cannot write (CHOLMOD status %d)", name, cc.status);
      rc = -1;
    }
  }
  chol.cholmod_free_sparse(&S, &cc);
  chol.cholmod_finish(&cc);
  return rc;
}

int whirl_fe_rotor_write_matrix(const whirl_fe_rotor *r, char which, FILE *f, char *msg,
                                size_t len) {
  const whirl_fe_csc *A = which == 'M'   ? &r->M
                          : which == 'C' ? &r->C
                          : which == 'G' ? &r->G
                          : which == 'K' ? &r->K
                                         : NULL;
  if (!r || !f || !A) {
    snprintf(msg, len, "write matrix: which is one of M, C, G, K");
    return WHIRL_EINVAL;
  }
  return fe_matrix_write(A, f, (char[2]){which, 0}, msg, len) ? WHIRL_EIO : WHIRL_OK;
}

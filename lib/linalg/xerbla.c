/* linalg/xerbla.c — LAPACK's error handler, replaced.  LAPACK calls
 * XERBLA(SRNAME, INFO) when a routine is given an illegal argument (also
 * from inside dgeev when overflowing input has turned a scaling factor into
 * NaN); the reference and OpenBLAS versions print "** On entry to DGEBAL
 * parameter number 3 had an illegal value" on stdout, which then ends up in
 * a results table.  LAPACK documents XERBLA as the routine to replace, and
 * the dynamic linker binds liblapack's calls to the first definition in
 * load order: libwhirl's, exported here, comes before its dependency
 * liblapack.  This one prints nothing: it records the routine and argument
 * for the calling thread, and the whirl function that called LAPACK turns
 * the record into WHIRL_ELAPACK with a message (whirl_lapack_take).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "linsol_impl.h"

static _Thread_local struct {
  int set;
  int arg;
  char name[16];
} lapack_err;

/* Fortran: SUBROUTINE XERBLA(SRNAME, INFO), CHARACTER*(*) SRNAME; the hidden
 * length comes last (size_t with gfortran >= 8). */
WHIRL_API void xerbla_(const char *srname, const int *info, size_t len);
void xerbla_(const char *srname, const int *info, size_t len) {
  if (lapack_err.set) return; /* keep the first complaint */
  size_t k = 0;
  if (srname)
    for (; k < len && k + 1 < sizeof lapack_err.name && srname[k] &&
           srname[k] != ' ';
         ++k)
      lapack_err.name[k] = srname[k];
  lapack_err.name[k] = '\0';
  lapack_err.arg = info ? *info : 0;
  lapack_err.set = 1;
}

void whirl_lapack_clear(void) { lapack_err.set = 0; }

int whirl_lapack_take(char *msg, size_t len) {
  if (!lapack_err.set) return 0;
  if (msg && len)
    snprintf(msg, len, "LAPACK %s: argument %d had an illegal value",
             lapack_err.name[0] ? lapack_err.name : "?", lapack_err.arg);
  lapack_err.set = 0;
  return 1;
}

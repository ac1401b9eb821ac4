/* rotor/fe_arpack_lib.h — ARPACK's implicitly restarted Arnoldi routines
 * for real nonsymmetric problems (dnaupd, dneupd: Lehoucq, Sorensen & Yang,
 * ARPACK Users' Guide, SIAM 1998), called through fe_dnaupd and fe_dneupd
 * once fe_arpack_open has opened the library (at the first use, not at
 * every start: whirl/dynlib.h).  Only with WHIRL_HAVE_ARPACK.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_ARPACK_LIB_H
#define WHIRL_ROTOR_FE_ARPACK_LIB_H

#include <stddef.h>

/* WHIRL_OK once ARPACK is open, else WHIRL_ENOLIB with the reason in msg */
int fe_arpack_open(char *msg, size_t len);

/* ARPACK's dnaupd_ and dneupd_ (Fortran: hidden string lengths last) */
void fe_dnaupd(int *ido, const char *bmat, const int *n, const char *which, const int *nev,
               const double *tol, double *resid, const int *ncv, double *v, const int *ldv,
               int *iparam, int *ipntr, double *workd, double *workl, const int *lworkl,
               int *info, size_t lbmat, size_t lwhich);
void fe_dneupd(const int *rvec, const char *howmny, int *select, double *dr, double *di,
               double *z, const int *ldz, const double *sigmar, const double *sigmai,
               double *workev, const char *bmat, const int *n, const char *which,
               const int *nev, const double *tol, double *resid, const int *ncv, double *v,
               const int *ldv, int *iparam, int *ipntr, double *workd, double *workl,
               const int *lworkl, int *info, size_t lhowmny, size_t lbmat, size_t lwhich);

#endif

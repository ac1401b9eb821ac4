/* rotor/fe_arpack_lib.c — ARPACK opened at its first use (fe_arpack_lib.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include "config.h"

#ifdef WHIRL_HAVE_ARPACK
#include <whirl/dynlib.h>

#include "fe_arpack_lib.h"

extern void dnaupd_(int *ido, const char *bmat, const int *n, const char *which, const int *nev,
                    const double *tol, double *resid, const int *ncv, double *v, const int *ldv,
                    int *iparam, int *ipntr, double *workd, double *workl, const int *lworkl,
                    int *info, size_t lbmat, size_t lwhich);
extern void dneupd_(const int *rvec, const char *howmny, int *select, double *dr, double *di,
                    double *z, const int *ldz, const double *sigmar, const double *sigmai,
                    double *workev, const char *bmat, const int *n, const char *which,
                    const int *nev, const double *tol, double *resid, const int *ncv, double *v,
                    const int *ldv, int *iparam, int *ipntr, double *workd, double *workl,
                    const int *lworkl, int *info, size_t lhowmny, size_t lbmat, size_t lwhich);

#define ARPACK_FUNCS(X) X(dnaupd_) X(dneupd_)
WHIRL_DYNLIB_ARPACK(arp, ARPACK_FUNCS)

int fe_arpack_open(char *msg, size_t len) {
  char why[256];
  if (arp_bind(why, sizeof why) == WHIRL_OK) return WHIRL_OK;
  return WHIRL_ERRMSG(msg, len, WHIRL_ENOLIB, "ARPACK: %s", why);
}

void fe_dnaupd(int *ido, const char *bmat, const int *n, const char *which, const int *nev,
               const double *tol, double *resid, const int *ncv, double *v, const int *ldv,
               int *iparam, int *ipntr, double *workd, double *workl, const int *lworkl,
               int *info, size_t lbmat, size_t lwhich) {
  arp.dnaupd_(ido, bmat, n, which, nev, tol, resid, ncv, v, ldv, iparam, ipntr, workd, workl,
              lworkl, info, lbmat, lwhich);
}

void fe_dneupd(const int *rvec, const char *howmny, int *select, double *dr, double *di,
               double *z, const int *ldz, const double *sigmar, const double *sigmai,
               double *workev, const char *bmat, const int *n, const char *which,
               const int *nev, const double *tol, double *resid, const int *ncv, double *v,
               const int *ldv, int *iparam, int *ipntr, double *workd, double *workl,
               const int *lworkl, int *info, size_t lhowmny, size_t lbmat, size_t lwhich) {
  arp.dneupd_(rvec, howmny, select, dr, di, z, ldz, sigmar, sigmai, workev, bmat, n, which, nev,
              tol, resid, ncv, v, ldv, iparam, ipntr, workd, workl, lworkl, info, lhowmny, lbmat,
              lwhich);
}
#endif

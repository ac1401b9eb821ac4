/* rotor/fe_arpack.c — the eigenvalues of a large finite-element rotor
 * nearest a real shift σ by ARPACK's implicitly restarted Arnoldi method
 * (dnaupd/dneupd, Lehoucq, Sorensen & Yang, ARPACK Users' Guide, 1998,
 * §3.2 and §4.3) applied to OP = (A − σB)⁻¹B of the first-order pencil
 * A = [0 I; −K −D], B = [I 0; 0 M], D = C + ΩG (regular mode 1 on OP,
 * which="LM": the largest |ν| of OP are the s = σ + 1/ν nearest σ).
 * (A − σB) y = b is one sparse solve with P = K + σD + σ²M:
 *   P y1 = −b2 − (D + σM) b1,   y2 = b1 + σ y1,
 * P factorised once per speed by the sparse LU (KLU; whirl/linsol.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/linsol.h>

#include "fe_impl.h"

#ifndef WHIRL_HAVE_ARPACK
int fe_eig_arpack(const whirl_fe_rotor *r, double Omega, double shift, double tol, size_t nev,
                  fe_eigs *e, char *msg, size_t len) {
  (void)r, (void)Omega, (void)shift, (void)tol, (void)nev, (void)e;
  if (msg && len) snprintf(msg, len, "whirl was built without ARPACK: use the dense method");
  return WHIRL_EINVAL;
}
#else

#include "fe_arpack_lib.h"

typedef struct op {
  const whirl_fe_rotor *r;
  whirl_fe_csc D;   /* C + ΩG */
  whirl_linsol *ls; /* P = K + σD + σ²M */
  double sigma;
  double *t;        /* ndof */
} op;

static int op_init(op *o, const whirl_fe_rotor *r, double Omega, double sigma, char *msg, size_t len) {
  memset(o, 0, sizeof *o);
  o->r = r;
  o->sigma = sigma;
  if (fe_damping(r, Omega, &o->D)) return WHIRL_ENOMEM;
  fe_trip t;
  fe_trip_init(&t, r->ndof);
  fe_trip_add_csc(&t, &r->K, 1, 0, 0);
  fe_trip_add_csc(&t, &o->D, sigma, 0, 0);
  fe_trip_add_csc(&t, &r->M, sigma * sigma, 0, 0);
  whirl_fe_csc P;
  if (fe_trip_to_csc(&t, &P)) return WHIRL_ENOMEM;
  o->t = malloc((size_t)r->ndof * sizeof *o->t);
  o->ls = whirl_linsol_alloc_sparse((size_t)r->ndof, P.p, P.i);
  int rc = o->t && o->ls ? whirl_linsol_factor(o->ls, P.x) : WHIRL_ENOMEM;
  fe_csc_free(&P);
  if (rc && msg && len)
    snprintf(msg, len, "K + sigma (C + Omega G) + sigma^2 M is singular at the shift %g (%s): choose "
             "another shift", sigma, o->ls ? whirl_linsol_errmsg(o->ls) : "out of memory");
  return rc;
}

static void op_free(op *o) {
  fe_csc_free(&o->D);
  whirl_linsol_free(o->ls);
  free(o->t);
}

/* y = (A − σB)⁻¹ B x, x and y of length 2 ndof */
static int op_apply(op *o, const double *x, double *y) {
  const int n = o->r->ndof;
  const double *x1 = x, *x2 = x + n;
  double *y1 = y, *y2 = y + n, *Mx2 = o->t;
  memset(Mx2, 0, (size_t)n * sizeof *Mx2);
  fe_csc_gemv(&o->r->M, 1, x2, Mx2); /* b2 = M x2, b1 = x1 */
  for (int k = 0; k < n; ++k) y1[k] = -Mx2[k];
  fe_csc_gemv(&o->D, -1, x1, y1);
  fe_csc_gemv(&o->r->M, -o->sigma, x1, y1);
  int rc = whirl_linsol_solve(o->ls, y1, 1, 0);
  for (int k = 0; k < n; ++k) y2[k] = x1[k] + o->sigma * y1[k];
  return rc;
}

typedef struct work {
  int N, nev, ncv, lworkl;
  double *resid, *v, *workd, *workl, *dr, *di, *z, *workev;
  int *select;
} work;

static int work_alloc(work *w, int N, int nev) {
  w->N = N;
  w->nev = nev;
  w->ncv = 2 * nev + 1 > 20 ? 2 * nev + 1 : 20;
  if (w->ncv > N) w->ncv = N;
  w->lworkl = 3 * w->ncv * w->ncv + 6 * w->ncv;
  w->resid = calloc((size_t)N, sizeof *w->resid);
  w->v = malloc((size_t)N * w->ncv * sizeof *w->v);
  w->workd = malloc(3 * (size_t)N * sizeof *w->workd);
  w->workl = malloc((size_t)w->lworkl * sizeof *w->workl);
  w->dr = malloc(((size_t)nev + 1) * sizeof *w->dr);
  w->di = malloc(((size_t)nev + 1) * sizeof *w->di);
  w->z = malloc((size_t)N * (nev + 1) * sizeof *w->z);
  w->workev = malloc(3 * (size_t)w->ncv * sizeof *w->workev);
  w->select = malloc((size_t)w->ncv * sizeof *w->select);
  return w->resid && w->v && w->workd && w->workl && w->dr && w->di && w->z && w->workev && w->select
             ? WHIRL_OK
             : WHIRL_ENOMEM;
}

static void work_free(work *w) {
  free(w->resid);
  free(w->v);
  free(w->workd);
  free(w->workl);
  free(w->dr);
  free(w->di);
  free(w->z);
  free(w->workev);
  free(w->select);
}

/* The reverse-communication loop of dnaupd, then dneupd with vectors. */
static int arnoldi(op *o, work *w, double tol, int *nconv, char *msg, size_t len) {
  int ido = 0, info = 0, iparam[11] = {0}, ipntr[14] = {0};
  iparam[0] = 1;    /* exact shifts */
  iparam[2] = 1000; /* restarts */
  iparam[6] = 1;    /* mode 1 on OP */
  for (;;) {
    fe_dnaupd(&ido, "I", &w->N, "LM", &w->nev, &tol, w->resid, &w->ncv, w->v, &w->N, iparam, ipntr,
            w->workd, w->workl, &w->lworkl, &info, 1, 2);
    if (ido != -1 && ido != 1) break;
    if (op_apply(o, w->workd + ipntr[0] - 1, w->workd + ipntr[1] - 1)) {
      if (msg && len) snprintf(msg, len, "ARPACK: the sparse solve failed");
      return WHIRL_ESPARSE;
    }
  }
  if (info < 0 || (info == 1 && iparam[4] == 0)) {
    if (msg && len) snprintf(msg, len, "ARPACK dnaupd failed (info %d)", info);
    return info == 1 ? WHIRL_EMAXITER : WHIRL_ELAPACK;
  }
  const int rvec = 1;
  const double sr = 0, si = 0;
  fe_dneupd(&rvec, "A", w->select, w->dr, w->di, w->z, &w->N, &sr, &si, w->workev, "I", &w->N, "LM",
          &w->nev, &tol, w->resid, &w->ncv, w->v, &w->N, iparam, ipntr, w->workd, w->workl,
          &w->lworkl, &info, 1, 1, 2);
  if (info != 0) {
    if (msg && len) snprintf(msg, len, "ARPACK dneupd failed (info %d)", info);
    return WHIRL_ELAPACK;
  }
  *nconv = iparam[4];
  return WHIRL_OK;
}

/* The Ritz pairs ν, z of OP as s = σ + 1/ν with Im s > 0 and their whirl. */
static int ritz(const whirl_fe_rotor *r, const work *w, double sigma, int nconv, fe_eigs *e) {
  const double szero = FE_SZERO * fe_omega0(r);
  double *vi = malloc((size_t)r->ndof * sizeof *vi);
  if (!vi) return WHIRL_ENOMEM;
  for (int j = 0; j < nconv; ++j) {
    if (!(w->di[j] > 0) || j + 1 > w->nev) continue; /* the first of a pair */
    const double a = w->dr[j], b = w->di[j], n2 = a * a + b * b;
    double re = sigma + a / n2, im = -b / n2, sg = 1; /* vector z_j + i z_j+1 */
    if (hypot(re, im) < szero) { /* a rigid-body mode */
      j++;
      continue;
    }
    if (im < 0) {
      im = -im;
      sg = -1;
    }
    const double *zr = w->z + (size_t)w->N * j, *zi = zr + w->N;
    for (int k = 0; k < r->ndof; ++k) vi[k] = sg * zi[k];
    e->re[e->n] = re;
    e->im[e->n] = im;
    e->whirl[e->n++] = fe_whirl_of(r, zr, vi);
    j++;
  }
  free(vi);
  return WHIRL_OK;
}

int fe_eig_arpack(const whirl_fe_rotor *r, double Omega, double shift, double tol, size_t nev,
                  fe_eigs *e, char *msg, size_t len) {
  const int N = 2 * r->ndof;
  if (nev + 2 > (size_t)N) nev = (size_t)N - 2;
  memset(e, 0, sizeof *e);
  if (N < 4) {
    if (msg && len) snprintf(msg, len, "ARPACK: the rotor is too small (use the dense method)");
    return WHIRL_EINVAL;
  }
  if (fe_arpack_open(msg, len) != WHIRL_OK) return WHIRL_ENOLIB;
  op o;
  work w;
  memset(&w, 0, sizeof w);
  /* shift 0: just left of 0, where K + σD + σ²M is regular also for a
   * free rotor (K singular, or nearly so by round-off, which would spoil
   * the LU) and the rigid-body modes come out clean, to be dropped */
  if (shift == 0) shift = -1e-4 * fe_omega0(r);
  int nconv = 0, rc = op_init(&o, r, Omega, shift, msg, len);
  if (rc == WHIRL_ESINGULAR) { /* K singular (a free rotor): just off 0 */
    op_free(&o);
    shift -= 1e-2 * fe_omega0(r);
    rc = op_init(&o, r, Omega, shift, msg, len);
  }
  if (!rc) rc = work_alloc(&w, N, (int)nev);
  if (!rc) rc = fe_eigs_alloc(e, nev + 1);
  if (rc == WHIRL_ENOMEM && msg && len) snprintf(msg, len, "out of memory");
  if (!rc) rc = arnoldi(&o, &w, tol, &nconv, msg, len);
  if (!rc) rc = ritz(r, &w, shift, nconv, e);
  if (rc) fe_eigs_free(e);
  op_free(&o);
  work_free(&w);
  return rc;
}
#endif

/* rotor/fe_modes.c — damped natural frequencies, log decrements and whirl
 * directions of a finite-element rotor at a speed (whirl/rotor/fe_linear.h):
 * the quadratic eigenproblem in first-order form, by dense QZ or by
 * ARPACK (fe_arpack.c).  QZ (LAPACK dggevx with balancing) runs on the
 * inverted pencil B z = λ A z, λ = 1/s: its errors are of the order of
 * ε max|λ| = ε/min|s|, so the slow modes wanted come out to ~1e-12
 * (on (A, B) they would carry errors of ε max|s|, the fastest FE mode,
 * ~1e-8 relative on a 48-element shaft); a singular M (massless DOFs)
 * gives λ = 0, a singular K (free rotor) infinite λ: both are dropped.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor/fe_linear.h>

#include "fe_impl.h"

/* LAPACK: generalized eigenvalues and right eigenvectors of (A, B), with
 * balancing (permutation and scaling of Ward 1981, BALANC = 'B'). */
extern void dggevx_(const char *balanc, const char *jobvl, const char *jobvr, const char *sense,
                    const int *n, double *a, const int *lda, double *b, const int *ldb,
                    double *alphar, double *alphai, double *beta, double *vl, const int *ldvl,
                    double *vr, const int *ldvr, int *ilo, int *ihi, double *lscale,
                    double *rscale, double *abnrm, double *bbnrm, double *rconde, double *rcondv,
                    double *work, const int *lwork, int *iwork, int *bwork, int *info, size_t l1,
                    size_t l2, size_t l3, size_t l4);

void whirl_fe_modes_options_default(whirl_fe_modes_options *o) {
  o->method = WHIRL_FE_EIG_AUTO;
  o->dense_max = 150;
  o->shift = 0;
  o->tol = 0;
}

int fe_eigs_alloc(fe_eigs *e, size_t n) {
  e->n = 0;
  e->re = malloc((n + 1) * sizeof *e->re);
  e->im = malloc((n + 1) * sizeof *e->im);
  e->whirl = malloc((n + 1) * sizeof *e->whirl);
  if (e->re && e->im && e->whirl) return WHIRL_OK;
  fe_eigs_free(e);
  return WHIRL_ENOMEM;
}

void fe_eigs_free(fe_eigs *e) {
  free(e->re);
  free(e->im);
  free(e->whirl);
  memset(e, 0, sizeof *e);
}

/* Σ Im(Y conj Z) over the nodes: > 0 when (y, z) turns from y to z, the
 * sense of the spin.  A mode without translation (a pure tilt) is judged by
 * the direction of the shaft axis, (θz, −θy). */
int fe_whirl_of(const whirl_fe_rotor *r, const double *vr, const double *vi) {
  double wt = 0, nt = 0, wr = 0, nr = 0;
  for (int n = 0; n < r->nnode; ++n) {
    const int j = 4 * n;
    wt += vi[j] * vr[j + 1] - vr[j] * vi[j + 1];
    nt += vr[j] * vr[j] + vi[j] * vi[j] + vr[j + 1] * vr[j + 1] + vi[j + 1] * vi[j + 1];
    /* Y = θz, Z = −θy */
    wr += -(vi[j + 3] * vr[j + 2] - vr[j + 3] * vi[j + 2]);
    nr += vr[j + 2] * vr[j + 2] + vi[j + 2] * vi[j + 2] + vr[j + 3] * vr[j + 3] + vi[j + 3] * vi[j + 3];
  }
  const double w = nt > 1e-16 * nr ? wt : wr;
  return w >= 0 ? 1 : -1;
}

int fe_damping(const whirl_fe_rotor *r, double Omega, whirl_fe_csc *D) {
  fe_trip t;
  fe_trip_init(&t, r->ndof);
  fe_trip_add_csc(&t, &r->C, 1, 0, 0);
  if (Omega != 0) fe_trip_add_csc(&t, &r->G, Omega, 0, 0);
  return fe_trip_to_csc(&t, D);
}

static double max_abs(const whirl_fe_csc *A) {
  double m = 0;
  for (int q = 0; q < A->p[A->n]; ++q) m = fmax(m, fabs(A->x[q]));
  return m;
}

double fe_omega0(const whirl_fe_rotor *r) {
  const double km = max_abs(&r->K), mm = max_abs(&r->M);
  return km > 0 && mm > 0 ? sqrt(km / mm) : 1;
}

/* A, B of the first-order form, dense N×N column-major, N = 2 ndof, with
 * the second block v = s x/ω0, ω0 = (max|K| / max|M|)^½, so that both
 * blocks of A are of one size:  A = [0 ω0 I; −K/ω0 −D],  B = [I 0; 0 M]. */
static int pencil(const whirl_fe_rotor *r, double Omega, double *A, double *B) {
  const int n = r->ndof, N = 2 * n;
  whirl_fe_csc D;
  if (fe_damping(r, Omega, &D)) return WHIRL_ENOMEM;
  const double w0 = fe_omega0(r);
  memset(A, 0, (size_t)N * N * sizeof *A);
  memset(B, 0, (size_t)N * N * sizeof *B);
  for (int k = 0; k < n; ++k) {
    A[k + (size_t)N * (n + k)] = w0;
    B[k + (size_t)N * k] = 1;
  }
  const whirl_fe_csc *S[3] = {&r->K, &D, &r->M};
  const double f[3] = {1 / w0, 1, 1};
  for (int m = 0; m < 3; ++m)
    for (int c = 0; c < n; ++c)
      for (int q = S[m]->p[c]; q < S[m]->p[c + 1]; ++q) {
        const size_t row = (size_t)(n + S[m]->i[q]);
        if (m == 2) B[row + (size_t)N * (n + c)] += S[m]->x[q];
        else A[row + (size_t)N * (c + (m == 1 ? n : 0))] -= f[m] * S[m]->x[q];
      }
  fe_csc_free(&D);
  return WHIRL_OK;
}

/* The finite eigenvalues with Im s > 0 of the pencil, with their whirl. */
static int collect(const whirl_fe_rotor *r, int N, const double *ar, const double *ai,
                   const double *be, const double *VR, fe_eigs *e) {
  /* |s| below szero is a rigid-body mode (s = 0, defective: its
   * round-off is of the order √ε ω0); lmax the largest |λ| = 1/|s| of the
   * others, and |λ| ≤ 1e-12 lmax an infinite s (a massless DOF) */
  const double szero = FE_SZERO * fe_omega0(r);
  double lmax = 0;
  for (int j = 0; j < N; ++j) {
    const double l = be[j] != 0 ? hypot(ar[j], ai[j]) / fabs(be[j]) : INFINITY;
    if (l * szero < 1) lmax = fmax(lmax, l);
  }
  for (int j = 0; j < N; ++j) {
    if (ai[j] == 0 || be[j] == 0) continue; /* real, or s = 0 */
    const int j0 = ai[j] > 0 ? j : j - 1;   /* the pair's real column */
    const double a2 = ar[j] * ar[j] + ai[j] * ai[j], l = sqrt(a2) / fabs(be[j]);
    if (!(l > 1e-12 * lmax) || !(l * szero < 1)) continue; /* s infinite or 0 */
    const double re = be[j] * ar[j] / a2, im = -be[j] * ai[j] / a2; /* s = 1/λ */
    if (!(im > 0) || !isfinite(re) || !isfinite(im)) continue;
    const double sg = j == j0 ? 1 : -1; /* λ_j's vector: VR_j0 + sg i VR_j0+1 */
    double *vr = malloc(2 * (size_t)r->ndof * sizeof *vr), *vi = vr + r->ndof;
    if (!vr) return WHIRL_ENOMEM;
    for (int k = 0; k < r->ndof; ++k) {
      vr[k] = VR[k + (size_t)N * j0];
      vi[k] = sg * VR[k + (size_t)N * (j0 + 1)];
    }
    e->re[e->n] = re;
    e->im[e->n] = im;
    e->whirl[e->n++] = fe_whirl_of(r, vr, vi);
    free(vr);
  }
  return WHIRL_OK;
}

int fe_eig_dense(const whirl_fe_rotor *r, double Omega, fe_eigs *e, char *msg, size_t len) {
  const int N = 2 * r->ndof, one = 1;
  const size_t NN = (size_t)N * N;
  double *A = malloc(NN * sizeof *A), *B = malloc(NN * sizeof *B), *VR = malloc(NN * sizeof *VR);
  double *ar = malloc((size_t)N * sizeof *ar), *ai = malloc((size_t)N * sizeof *ai);
  double *be = malloc((size_t)N * sizeof *be), *work = NULL, *ls = NULL;
  int *iw = NULL, bw = 0;
  int rc = WHIRL_ENOMEM, info = 0, lwork = -1;
  if (!A || !B || !VR || !ar || !ai || !be || fe_eigs_alloc(e, (size_t)N)) goto done;
  if ((rc = pencil(r, Omega, A, B))) goto done;
  double wq = 0, dummy = 0, abn, bbn;
  int ilo, ihi;
  rc = WHIRL_ENOMEM;
  if (!(ls = malloc(2 * (size_t)N * sizeof *ls)) || !(iw = malloc(((size_t)N + 6) * sizeof *iw)))
    goto done;
#define GGEVX(wk, lw)                                                                         \
  dggevx_("B", "N", "V", "N", &N, B, &N, A, &N, ar, ai, be, &dummy, &one, VR, &N, &ilo, &ihi,  \
          ls, ls + N, &abn, &bbn, &dummy, &dummy, wk, lw, iw, &bw, &info, 1, 1, 1, 1)
  GGEVX(&wq, &lwork);
  lwork = info == 0 && wq >= 6 * N ? (int)wq : 6 * N + 16;
  if (!(work = malloc((size_t)lwork * sizeof *work))) goto done;
  GGEVX(work, &lwork);
#undef GGEVX
  if (info != 0) {
    rc = WHIRL_ELAPACK;
    if (msg && len) snprintf(msg, len, "dggevx failed (info %d) at speed %g rad/s", info, Omega);
    goto done;
  }
  rc = collect(r, N, ar, ai, be, VR, e);
done:
  if (rc == WHIRL_ENOMEM && msg && len) snprintf(msg, len, "out of memory (%d DOFs dense)", r->ndof);
  if (rc) fe_eigs_free(e);
  free(A);
  free(B);
  free(VR);
  free(ar);
  free(ai);
  free(be);
  free(work);
  free(ls);
  free(iw);
  return rc;
}

/* ascending ω_d */
static int by_omega(const void *a, const void *b) {
  const whirl_fe_mode *x = a, *y = b;
  return (x->omega > y->omega) - (x->omega < y->omega);
}

/* All positive-frequency modes the method finds at Omega, sorted. */
static int solve(const whirl_fe_rotor *r, double Omega, const whirl_fe_modes_options *o,
                 size_t nmodes, whirl_fe_mode **out, size_t *nout, char *msg, size_t len) {
  fe_eigs e;
  int dense = o->method == WHIRL_FE_EIG_DENSE || (o->method == WHIRL_FE_EIG_AUTO && r->ndof <= o->dense_max);
  int rc = dense ? fe_eig_dense(r, Omega, &e, msg, len)
                 : fe_eig_arpack(r, Omega, o->shift, o->tol, 2 * nmodes + 14, &e, msg, len);
  if (rc) return rc;
  whirl_fe_mode *m = malloc((e.n + 1) * sizeof *m);
  if (!m) {
    fe_eigs_free(&e);
    if (msg && len) snprintf(msg, len, "out of memory");
    return WHIRL_ENOMEM;
  }
  for (size_t k = 0; k < e.n; ++k) {
    /* an undamped mode's real part is round-off (~1e-13 ω): shown as 0 */
    const double re = fabs(e.re[k]) <= 1e-10 * e.im[k] ? 0 : e.re[k];
    m[k] = (whirl_fe_mode){e.im[k], re, re == 0 ? 0 : -2 * WHIRL_PI * re / e.im[k], e.whirl[k]};
  }
  qsort(m, e.n, sizeof *m, by_omega);
  *out = m;
  *nout = e.n;
  fe_eigs_free(&e);
  return WHIRL_OK;
}

int whirl_fe_modes(const whirl_fe_rotor *r, double Omega, const whirl_fe_modes_options *o,
                   size_t nmodes, whirl_fe_mode *modes, size_t *nfound, char *msg, size_t len) {
  whirl_fe_modes_options def;
  if (!o) {
    whirl_fe_modes_options_default(&def);
    o = &def;
  }
  if (nfound) *nfound = 0;
  if (!r || !modes || nmodes == 0 || !isfinite(Omega)) {
    if (msg && len) snprintf(msg, len, "whirl_fe_modes: bad arguments");
    return WHIRL_EINVAL;
  }
  whirl_fe_mode *m = NULL, *m2 = NULL;
  size_t n = 0, n2 = 0;
  int rc = solve(r, Omega, o, nmodes, &m, &n, msg, len);
  if (rc) return rc;
  if (Omega == 0 && n > 0) { /* the whirl as the rotor starts turning */
    rc = solve(r, 1e-3 * m[0].omega, o, nmodes, &m2, &n2, msg, len);
    if (rc) {
      free(m);
      return rc;
    }
    for (size_t k = 0; k < n && k < n2; ++k) m[k].whirl = m2[k].whirl;
    free(m2);
  }
  const size_t nk = n < nmodes ? n : nmodes;
  memcpy(modes, m, nk * sizeof *m);
  if (nfound) *nfound = nk;
  free(m);
  return WHIRL_OK;
}

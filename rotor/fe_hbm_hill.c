/* rotor/fe_hbm_hill.c — stability of a harmonic-balance orbit of a
 * finite-element rotor by Hill's method on the full linearised system.
 *
 * A perturbation δq = e^{λt} p(t), p of period 2π/ω, of
 *   M(t) δq'' + C(t) δq' + K(t) δq = 0,
 *   M(t) = M − Pᵀ ∂f/∂a P,  C(t) = C + Ω G − Pᵀ ∂f/∂v P,  K(t) = K − Pᵀ ∂f/∂r P,
 * with p in the real Fourier basis of the orbit (the Galerkin operators
 * M_H, C_H, K_H of multiplication by M(t), C(t), K(t), by AFT of the element
 * Jacobians, and ∇ the derivative) gives the quadratic eigenproblem
 *   λ² A2 + λ A1 + A0 = 0,  A2 = M_H,  A1 = C_H + 2 M_H ∇,
 *   A0 = K_H + C_H ∇ + M_H ∇²  (the Jacobian of the uncondensed HBM),
 * solved as the first-order companion [0 I; −A2⁻¹A0 −A2⁻¹A1] by LAPACK
 * dgeev.  Each Floquet exponent appears 2H + 1 times, shifted by i k ω
 * (Lazarus & Thomas, C. R. Mécanique 338 (2010) 510; Peletan, Baguet,
 * Torkhani & Jacquet-Richardet, Nonlinear Dyn. 71 (2013) 315); the members
 * in the strip |Im λ| ≤ ω/2 are kept (select_exponents), and the
 * multipliers are exp(λ 2π/ω).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"

/* dense += blockdiag over the L harmonic blocks of the sparse A (s A) */
static void add_blockdiag(double *D, size_t NH, int ndof, int L,
                          const whirl_fe_csc *A, double s) {
  for (int blk = 0; blk < L; ++blk) {
    size_t o = (size_t)blk * ndof;
    for (int c = 0; c < ndof; ++c)
      for (int q = A->p[c]; q < A->p[c + 1]; ++q)
        D[o + A->i[q] + NH * (o + c)] += s * A->x[q];
  }
}

/* dense −= the nonlinear operator Jop (m L square) at the DOFs */
static void sub_nl(double *D, size_t NH, const whirl_fe_hbm *h,
                   const double *Jop) {
  int m = h->aft.m, nd = h->r->ndof;
  size_t ml = (size_t)m * h->L;
  for (size_t c = 0; c < ml; ++c)
    for (size_t r = 0; r < ml; ++r) {
      size_t R = (r / m) * nd + h->aft.dof[r % m];
      size_t C = (c / m) * nd + h->aft.dof[c % m];
      D[R + NH * C] -= Jop[r + ml * c];
    }
}

/* out += s · A ∇ (A NH square): (A∇)[:, a_k] = −kω A[:, b_k],
 * (A∇)[:, b_k] = kω A[:, a_k]. */
static void add_times_nabla(double *out, const double *A, size_t NH, int ndof,
                            int H, double w, double s) {
  for (int k = 1; k <= H; ++k)
    for (int d = 0; d < ndof; ++d) {
      size_t ca = (size_t)ndof * (2 * k - 1) + d, cb = (size_t)ndof * 2 * k + d;
      for (size_t i = 0; i < NH; ++i) {
        out[i + NH * ca] -= s * k * w * A[i + NH * cb];
        out[i + NH * cb] += s * k * w * A[i + NH * ca];
      }
    }
}

/* A2, C_H, K_H at the orbit q (all DOFs, SI) into A[3 NH²]. */
static int hill_operators(whirl_fe_hbm *h, const double *qfull,
                          const double *p, double *A) {
  int nd = h->r->ndof, m = h->aft.m, L = h->L;
  size_t NH = (size_t)nd * L, N2 = NH * NH;
  double Omega = p[WHIRL_FE_P_OMEGA];
  for (int blk = 0; blk < L; ++blk)
    for (int j = 0; j < m; ++j) h->q[blk * m + j] = qfull[blk * nd + h->aft.dof[j]];
  fe_aft_set_scales(&h->aft, p[WHIRL_FE_P_CLEARANCE], p[WHIRL_FE_P_VISCOSITY]);
  int rc = fe_aft_eval(&h->aft, h->q, Omega / h->o.nu, Omega, h->f, h->Jnl,
                       FE_AFT_HILL);
  if (rc) return rc;
  size_t ml2 = (size_t)m * L * (size_t)m * L;
  memset(A, 0, 3 * N2 * sizeof *A);
  add_blockdiag(A, NH, nd, L, &h->r->M, 1.0);
  sub_nl(A, NH, h, h->Jnl + 2 * ml2);
  add_blockdiag(A + N2, NH, nd, L, &h->r->C, 1.0);
  add_blockdiag(A + N2, NH, nd, L, &h->r->G, Omega);
  sub_nl(A + N2, NH, h, h->Jnl + ml2);
  add_blockdiag(A + 2 * N2, NH, nd, L, &h->r->K, 1.0);
  sub_nl(A + 2 * N2, NH, h, h->Jnl);
  return 0;
}

/* The companion matrix Q[(2NH)²] from A2, C_H, K_H. */
static int companion(const whirl_fe_hbm *h, const double *A, double *Q,
                     double w) {
  int nd = h->r->ndof, H = h->H;
  size_t NH = (size_t)nd * h->L, N2 = NH * NH, n2 = 2 * NH;
  const double *A2 = A, *CH = A + N2, *KH = A + 2 * N2;
  double *R = malloc(2 * N2 * sizeof *R); /* [A0 A1] */
  whirl_linsol *ls = whirl_linsol_alloc_dense(NH);
  int rc = (R && ls) ? WHIRL_OK : WHIRL_ENOMEM;
  if (!rc) {
    double *A0 = R, *A1 = R + N2;
    memcpy(A0, KH, N2 * sizeof *A0);
    add_times_nabla(A0, CH, NH, nd, H, w, 1.0);
    for (int k = 1; k <= H; ++k) /* A2 ∇² = −(kω)² A2 on harmonic k */
      for (size_t c = (size_t)nd * (2 * k - 1); c < (size_t)nd * (2 * k + 1); ++c)
        for (size_t i = 0; i < NH; ++i)
          A0[i + NH * c] -= (k * w) * (k * w) * A2[i + NH * c];
    memcpy(A1, CH, N2 * sizeof *A1);
    add_times_nabla(A1, A2, NH, nd, H, w, 2.0);
    rc = whirl_linsol_factor(ls, A2);
    if (!rc) rc = whirl_linsol_solve(ls, R, 2 * NH, 0);
  }
  if (!rc) {
    memset(Q, 0, n2 * n2 * sizeof *Q);
    for (size_t i = 0; i < NH; ++i) Q[i + n2 * (NH + i)] = 1.0;
    for (size_t c = 0; c < n2; ++c)
      for (size_t i = 0; i < NH; ++i) Q[NH + i + n2 * c] = -R[i + NH * c];
  }
  whirl_linsol_free(ls);
  free(R);
  return rc;
}

/* The Floquet exponents among the Hill eigenvalues: each family
 * λ + i k ω has one member in the strip |Im| ≤ ω/2, the one the truncated
 * series represents best; the others (|k| > 0) are aliases, accurate only
 * while |k| is well below H.  Keep the strip's members, at most `keep`,
 * by decreasing Re.  A mode far above H ω (a stiff shaft's bending) has no
 * member in the strip: it is not resolved by the truncation, and is
 * reported as a multiplier 0 (re = −∞), the fill that keeps the count at
 * `keep`.  (Taking the `keep` eigenvalues of smallest |Im| instead, as
 * Lazarus & Thomas 2010 do, fills the place of such modes with aliases of
 * the resolved ones at |k| ≈ H, whose real parts are wrong: spurious
 * TR points on a stiff rotor.) */
static void select_exponents(const double *wr, const double *wi, size_t n2,
                             size_t keep, double w, double *re, double *im) {
  size_t s = 0;
  for (size_t i = 0; i < n2 && s < keep; ++i)
    if (fabs(wi[i]) <= 0.5 * w * (1 + 1e-9)) re[s] = wr[i], im[s] = wi[i], s++;
  for (; s < keep; ++s) re[s] = -HUGE_VAL, im[s] = 0.0;
  for (size_t i = 1; i < keep; ++i) /* insertion sort by decreasing Re */
    for (size_t j = i; j > 0 && re[j] > re[j - 1]; --j) {
      double t = re[j]; re[j] = re[j - 1]; re[j - 1] = t;
      t = im[j]; im[j] = im[j - 1]; im[j - 1] = t;
    }
}

int fe_hill_exponents(whirl_fe_hbm *h, const double *qfull, const double *p,
                      double *re, double *im, size_t *m) {
  size_t nd = (size_t)h->r->ndof, NH = nd * h->L, n2 = 2 * NH, keep = 2 * nd;
  if (*m < keep) return WHIRL_EINVAL;
  double *A = malloc(3 * NH * NH * sizeof *A);
  double *Q = malloc(n2 * n2 * sizeof *Q);
  double *wr = malloc(2 * n2 * sizeof *wr);
  whirl_eig *e = whirl_eig_alloc(n2);
  int rc = (A && Q && wr && e) ? WHIRL_OK : WHIRL_ENOMEM;
  if (!rc) rc = hill_operators(h, qfull, p, A);
  if (!rc) rc = companion(h, A, Q, p[WHIRL_FE_P_OMEGA] / h->o.nu);
  if (!rc) rc = whirl_eig_compute(e, Q, wr, wr + n2);
  if (!rc) {
    select_exponents(wr, wr + n2, n2, keep, p[WHIRL_FE_P_OMEGA] / h->o.nu, re, im);
    *m = keep;
  }
  whirl_eig_free(e);
  free(wr);
  free(Q);
  free(A);
  return rc;
}

int whirl_fe_hbm_hill(whirl_fe_hbm *h, const double *X, const double *p,
                      double *re, double *im, size_t *m) {
  if (h->hill == 3) {
    int rc = fe_hill_reduced(h, X, p, re, im, m);
    /* stability chosen by whirl (auto): a reduction that cannot be built
     * (a part of the rotor free when its nonlinear DOFs are held, too few
     * DOFs) leaves the whole rotor's sparse method */
    if (!(rc && h->cb_unavailable && h->o.stability < 0)) return rc;
    h->hill = 2;
  }
  int rc = whirl_fe_hbm_recover(h, X, p, h->qfull);
  if (rc) return rc;
  if (h->hill == 2)
    return fe_hill_sparse(h, h->qfull, p, h->o.hill_nev, re, im, m);
  return fe_hill_exponents(h, h->qfull, p, re, im, m);
}

/* The system's spectrum: the multipliers exp(λ T), by decreasing modulus. */
int fe_hbm_spectrum(const double *X, const double *p, const double *J,
                    double *re, double *im, size_t *m, void *data) {
  (void)J;
  whirl_fe_hbm *h = data;
  if (!(p[WHIRL_FE_P_OMEGA] > 0)) return WHIRL_ESINGULAR; /* T infinite: unknown */
  int rc = whirl_fe_hbm_hill(h, X, p, re, im, m);
  if (rc) return rc;
  double T = 2.0 * WHIRL_PI * h->o.nu / p[WHIRL_FE_P_OMEGA];
  for (size_t i = 0; i < *m; ++i) {
    double r = exp(re[i] * T), a = im[i] * T;
    re[i] = r * cos(a);
    im[i] = r * sin(a);
  }
  for (size_t i = 1; i < *m; ++i)
    for (size_t j = i; j > 0 && hypot(re[j], im[j]) > hypot(re[j - 1], im[j - 1]); --j) {
      double t = re[j]; re[j] = re[j - 1]; re[j - 1] = t;
      t = im[j]; im[j] = im[j - 1]; im[j - 1] = t;
    }
  return 0;
}

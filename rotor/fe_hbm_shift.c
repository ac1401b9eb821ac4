/* rotor/fe_hbm_shift.c — the Hill matrix of a harmonic-balance orbit at a
 * real shift σ, P(σ) = H(σ), factorised by condensation onto the nonlinear
 * DOFs: the shift-invert solves of the sparse Hill method
 * (fe_hbm_hill_sparse.c) without a sparse LU of order ndof (2H + 1).
 *
 * In the real harmonic form (fe_hbm_impl.h's layout over all ndof DOFs) the
 * linear part of P acts per harmonic k on the complex amplitude
 * Q_k = a_k − i b_k as the dynamic stiffness at s_k = σ + i kω,
 *   D(s) = K + s (C + Ω G) + s² M,
 * since e^{σt} Re(Q e^{ikωt}) is mapped to e^{σt} Re(D(s_k) Q e^{ikωt});
 * the nonlinear elements couple all harmonics, but only on the m nonlinear
 * DOFs: −N(σ) = −[J_r + J_v (∇ + σ) + J_a (∇ + σ)²] with AFT's Galerkin
 * operators J_r, J_v, J_a (fe_hbm_aft.c).  The Schur complement onto the
 * nonlinear DOFs (the receptance condensation of fe_hbm_lin.c, at the
 * complex frequencies s_k) is then
 *   S = blockdiag_k [Re Z_k, Im Z_k; −Im Z_k, Re Z_k] − N(σ),
 *   Z_k = D_nn(s_k) − D_nl(s_k) X_k,  X_k = D_ll(s_k)⁻¹ D_ln(s_k),
 * a dense real matrix of order m (2H + 1), and P y = r is solved as
 *   t_k = D_ll⁻¹ R_l,k,  S y_n = R_n − D_nl t  (real form),
 *   y_l,k = t_k − X_k Y_n,k
 * (Golub & Van Loan, Matrix Computations, 4th ed., §3.2.11 on block
 * elimination): one interior solve per harmonic and a dense solve of order
 * m (2H + 1) per right-hand side, after H + 1 interior factorisations.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"

extern void dgetrf_(const int *m, const int *n, double *a, const int *lda,
                    int *ipiv, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs,
                    const double *a, const int *lda, const int *ipiv,
                    double *b, const int *ldb, int *info, size_t ltrans);

void fe_shift_free(fe_shift *s) {
  if (s->lu)
    for (int k = 0; k <= s->H; ++k) fe_ilu_free(&s->lu[k]);
  void *p[] = {s->lu, s->Dn, s->X, s->T, s->S, s->ipiv, s->Dv, s->g, s->Z};
  for (size_t i = 0; i < sizeof p / sizeof *p; ++i) free(p[i]);
  memset(s, 0, sizeof *s);
}

int fe_shift_init(fe_shift *s, const fe_lin *l) {
  memset(s, 0, sizeof *s);
  s->H = l->H;
  int K = l->H + 1, ml = l->m * (2 * l->H + 1);
  size_t ni = (size_t)(l->ni ? l->ni : 1), m = (size_t)l->m;
  s->lu = calloc((size_t)K, sizeof *s->lu);
  s->Dn = malloc((size_t)K * (size_t)(l->nnlq ? l->nnlq : 1) * sizeof *s->Dn);
  s->X = malloc((size_t)K * ni * m * sizeof *s->X);
  s->T = malloc((size_t)K * ni * sizeof *s->T);
  s->S = malloc((size_t)ml * ml * sizeof *s->S);
  s->ipiv = malloc((size_t)ml * sizeof *s->ipiv);
  s->Dv = malloc((size_t)(l->nnz ? l->nnz : 1) * sizeof *s->Dv);
  s->g = malloc((size_t)ml * sizeof *s->g);
  s->Z = malloc((m * m + 2 * m) * sizeof *s->Z);
  if (!s->lu || !s->Dn || !s->X || !s->T || !s->S || !s->ipiv || !s->Dv ||
      !s->g || !s->Z) {
    fe_shift_free(s);
    return WHIRL_ENOMEM;
  }
  for (int k = 0; k < K; ++k) {
    int rc = fe_ilu_init(l, &s->lu[k]);
    if (rc) { fe_shift_free(s); return rc; }
  }
  return WHIRL_OK;
}

/* D(s) on l's union pattern, into s->Dv. */
static void dynamic_stiffness(fe_shift *s, const fe_lin *l, double complex z,
                              double Omega) {
  for (int q = 0; q < l->nnz; ++q)
    s->Dv[q] = l->Kx[q] + z * (l->Cx[q] + Omega * l->Gx[q]) + z * z * l->Mx[q];
}

/* Harmonic k at s_k: the factorisation, X_k = D_ll⁻¹ D_ln, the entries of
 * the nonlinear rows, and Z_k into the real form of S (rows and columns
 * of harmonic k). */
static int harmonic(fe_shift *s, fe_lin *l, int k, double complex z,
                    double Omega) {
  int n = l->ndof, m = l->m, ni = l->ni, ml = m * (2 * l->H + 1);
  dynamic_stiffness(s, l, z, Omega);
  double complex *X = s->X + (size_t)k * ni * m, *Dn = s->Dn + (size_t)k * l->nnlq;
  if (ni) {
    int rc = fe_ilu_factor(l, &s->lu[k], s->Dv);
    if (rc) return rc;
    memset(X, 0, (size_t)ni * m * sizeof *X);
    for (int c = 0; c < n; ++c)
      if (l->inv[c] < 0)
        for (int q = l->Up[c]; q < l->Up[c + 1]; ++q)
          if (l->inv[l->Ui[q]] >= 0)
            X[l->inv[l->Ui[q]] + (size_t)ni * (-1 - l->inv[c])] = s->Dv[q];
    if ((rc = fe_ilu_solve(l, &s->lu[k], 0, m, X))) return rc;
  }
  double complex *Z = s->Z;
  memset(Z, 0, (size_t)m * m * sizeof *Z);
  for (int e = 0; e < l->nnlq; ++e) {
    int q = l->nlq[e], i = -1 - l->inv[l->Ui[q]], c = l->nlcol[e], sc = l->inv[c];
    Dn[e] = s->Dv[q];
    for (int j = 0; j < m; ++j)
      Z[i + m * j] += Dn[e] * (sc >= 0 ? -X[sc + (size_t)ni * j]
                                       : (-1 - sc == j ? 1.0 : 0.0));
  }
  int ra = k == 0 ? 0 : m * (2 * k - 1), rb = m * 2 * k;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      double complex v = Z[i + m * j];
      if (k == 0) { s->S[i + (size_t)ml * j] = creal(v); continue; }
      s->S[ra + i + (size_t)ml * (ra + j)] = creal(v);
      s->S[ra + i + (size_t)ml * (rb + j)] = cimag(v);
      s->S[rb + i + (size_t)ml * (ra + j)] = -cimag(v);
      s->S[rb + i + (size_t)ml * (rb + j)] = creal(v);
    }
  return WHIRL_OK;
}

/* S −= c · J ∇ (column a_k ← −kω column b_k, b_k ← kω a_k of J). */
static void sub_j_nabla(double *S, const double *J, int m, int ml, double w,
                        double c) {
  for (int col = m; col < ml; ++col) {
    int blk = col / m, k = (blk + 1) / 2;
    int from = (blk & 1) ? col + m : col - m;
    double f = (blk & 1) ? -k * w : k * w;
    for (int r = 0; r < ml; ++r)
      S[r + (size_t)ml * col] -= c * f * J[r + (size_t)ml * from];
  }
}

/* S −= N(σ) = J_r + J_v (∇ + σ) + J_a (∇² + 2σ∇ + σ²), ∇² = −(kω)². */
static void sub_nonlinear(double *S, const double *J3, int m, int ml,
                          double w, double sigma) {
  size_t ml2 = (size_t)ml * ml;
  const double *Jr = J3, *Jv = J3 + ml2, *Ja = J3 + 2 * ml2;
  for (int col = 0; col < ml; ++col) {
    int k = (col / m + 1) / 2;
    double a2 = sigma * sigma - (k * w) * (k * w);
    for (int r = 0; r < ml; ++r) {
      size_t e = r + (size_t)ml * col;
      S[e] -= Jr[e] + sigma * Jv[e] + a2 * Ja[e];
    }
  }
  sub_j_nabla(S, Jv, m, ml, w, 1.0);
  sub_j_nabla(S, Ja, m, ml, w, 2 * sigma);
}

int fe_shift_factor(fe_shift *s, fe_lin *l, double Omega, double w,
                    double sigma, const double *J3) {
  int m = l->m, ml = m * (2 * l->H + 1), info = 0;
  memset(s->S, 0, (size_t)ml * ml * sizeof *s->S);
  for (int k = 0; k <= l->H; ++k) {
    int rc = harmonic(s, l, k, sigma + I * k * w, Omega);
    if (rc) {
      snprintf(l->err, sizeof l->err, "Hill's shift %g: the rotor with its "
               "nonlinear DOFs held is singular at harmonic %d", sigma, k);
      return rc;
    }
  }
  sub_nonlinear(s->S, J3, m, ml, w, sigma);
  dgetrf_(&ml, &ml, s->S, &ml, s->ipiv, &info);
  if (info > 0) {
    snprintf(l->err, sizeof l->err, "Hill's shift %g is an exponent (the "
             "condensed Hill matrix is singular)", sigma);
    return WHIRL_ESINGULAR;
  }
  return info ? WHIRL_ELAPACK : WHIRL_OK;
}

/* The complex amplitude of DOF d in harmonic k of a real-form vector. */
static double complex amplitude(const double *y, int n, int k, int d) {
  return k == 0 ? y[d] : y[n * (2 * k - 1) + d] - I * y[n * 2 * k + d];
}

static void set_amplitude(double *y, int n, int k, int d, double complex v) {
  if (k == 0) { y[d] = creal(v); return; }
  y[n * (2 * k - 1) + d] = creal(v);
  y[n * 2 * k + d] = -cimag(v);
}

int fe_shift_solve(fe_shift *s, fe_lin *l, double *y) {
  int n = l->ndof, m = l->m, ni = l->ni, ml = m * (2 * l->H + 1), one = 1;
  int info = 0;
  for (int k = 0; k <= l->H; ++k) { /* t_k and the reduced right side */
    double complex *t = s->T + (size_t)k * ni, *gk = s->Z + (size_t)m * m;
    const double complex *Dn = s->Dn + (size_t)k * l->nnlq;
    for (int d = 0; d < n; ++d) {
      int sd = l->inv[d];
      if (sd >= 0) t[sd] = amplitude(y, n, k, d);
      else gk[-1 - sd] = amplitude(y, n, k, d);
    }
    if (ni) {
      int rc = fe_ilu_solve(l, &s->lu[k], 0, 1, t);
      if (rc) return rc;
    }
    for (int e = 0; e < l->nnlq; ++e) {
      int sc = l->inv[l->nlcol[e]];
      if (sc >= 0) gk[-1 - l->inv[l->Ui[l->nlq[e]]]] -= Dn[e] * t[sc];
    }
    for (int j = 0; j < m; ++j) set_amplitude(s->g, m, k, j, gk[j]);
  }
  dgetrs_("N", &ml, &one, s->S, &ml, s->ipiv, s->g, &ml, &info, 1);
  if (info) return WHIRL_ELAPACK;
  for (int k = 0; k <= l->H; ++k) { /* y_l = t − X Y_n, y_n */
    const double complex *t = s->T + (size_t)k * ni;
    const double complex *X = s->X + (size_t)k * ni * m;
    double complex *Yn = s->Z + (size_t)m * m + m;
    for (int j = 0; j < m; ++j) Yn[j] = amplitude(s->g, m, k, j);
    for (int d = 0; d < n; ++d) {
      int sd = l->inv[d];
      if (sd < 0) { set_amplitude(y, n, k, d, Yn[-1 - sd]); continue; }
      double complex v = t[sd];
      for (int j = 0; j < m; ++j) v -= X[sd + (size_t)ni * j] * Yn[j];
      set_amplitude(y, n, k, d, v);
    }
  }
  return WHIRL_OK;
}

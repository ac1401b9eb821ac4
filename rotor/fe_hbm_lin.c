/* rotor/fe_hbm_lin.c — the linear part of the harmonic balance of a
 * finite-element rotor, per harmonic k of ω = Ω/ν:
 *   D_k = K − (kω)² M + i kω (C + Ω G),
 * condensed exactly onto the nonlinear DOFs n by the Schur complement
 *   Z_k = D_nn − D_nl D_ll⁻¹ D_ln = Vᵀ D_k W,  g_k = F_n − D_nl D_ll⁻¹ F_l
 *       = Vᵀ F_k,   W = [−D_ll⁻¹ D_ln; I],  V = [−D_ll⁻ᵀ D_nlᵀ; I]
 * (one complex LU of the interior block D_ll per harmonic and speed —
 * banded in a reverse Cuthill–McKee ordering (fe_band.c) for beam rotors,
 * UMFPACK's zi interface (Davis, ACM TOMS 30 (2004) 196) for wider
 * patterns — then m solves with D_ll and m with its transpose), and the derivatives in Ω without another
 * factorisation: since Vᵀ D = [0 Z] and D W = [0; Z],
 *   ∂Z/∂Ω = Vᵀ (∂D/∂Ω) W,   ∂g/∂Ω = Vᵀ (∂F/∂Ω − (∂D/∂Ω) [D_ll⁻¹ F_l; 0]).
 * Uncondensed, Z_k = D_k and g_k = F_k themselves (dense).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <umfpack.h>

_Static_assert(UMFPACK_CONTROL == 20, "fe_lin.control has UMFPACK_CONTROL entries");

#ifdef HAVE_CONFIG_H
#include "config.h"
#endif
#include <whirl/dynlib.h>

#include "fe_hbm_impl.h"

/* UMFPACK, opened at the first interior block too wide for the banded LU
 * (whirl/dynlib.h) */
#define UMF_FUNCS(X)                                                           \
  X(umfpack_zi_defaults) X(umfpack_zi_symbolic) X(umfpack_zi_numeric)           \
  X(umfpack_zi_solve) X(umfpack_zi_free_numeric) X(umfpack_zi_free_symbolic)
WHIRL_DYNLIB_UMFPACK(umf, UMF_FUNCS)

/* ------------------------------------------------------------ patterns */

/* The union pattern of K, M, C, G and the four on it. */
static int union_pattern(fe_lin *l) {
  const whirl_fe_csc *A[4] = {&l->r->K, &l->r->M, &l->r->C, &l->r->G};
  int n = l->ndof, cap = 0;
  for (int s = 0; s < 4; ++s) cap += A[s]->p[n];
  l->Up = malloc((size_t)(n + 1) * sizeof *l->Up);
  l->Ui = malloc((size_t)(cap ? cap : 1) * sizeof *l->Ui);
  int *mark = malloc((size_t)n * sizeof *mark);
  if (!l->Up || !l->Ui || !mark) { free(mark); return WHIRL_ENOMEM; }
  for (int i = 0; i < n; ++i) mark[i] = -1;
  int nz = 0;
  l->Up[0] = 0;
  for (int c = 0; c < n; ++c) {
    int start = nz;
    for (int s = 0; s < 4; ++s)
      for (int q = A[s]->p[c]; q < A[s]->p[c + 1]; ++q)
        if (mark[A[s]->i[q]] != c) {
          mark[A[s]->i[q]] = c;
          int i = A[s]->i[q], t = nz++;
          while (t > start && l->Ui[t - 1] > i) { l->Ui[t] = l->Ui[t - 1]; --t; }
          l->Ui[t] = i;
        }
    l->Up[c + 1] = nz;
  }
  free(mark);
  l->nnz = nz;
  double **X[4] = {&l->Kx, &l->Mx, &l->Cx, &l->Gx};
  for (int s = 0; s < 4; ++s) {
    *X[s] = calloc((size_t)(nz ? nz : 1), sizeof **X[s]);
    if (!*X[s]) return WHIRL_ENOMEM;
    for (int c = 0; c < n; ++c) {
      int u = l->Up[c];
      for (int q = A[s]->p[c]; q < A[s]->p[c + 1]; ++q) {
        while (l->Ui[u] != A[s]->i[q]) ++u;
        (*X[s])[u] += A[s]->x[q];
      }
    }
  }
  return WHIRL_OK;
}

/* The interior pattern (nonlinear rows and columns removed), its map into
 * the union pattern, and the symbolic analysis. */
static int interior_pattern(fe_lin *l) {
  int n = l->ndof, ni = 0;
  l->inv = malloc((size_t)n * sizeof *l->inv);
  if (!l->inv) return WHIRL_ENOMEM;
  for (int d = 0, j = 0; d < n; ++d) {
    if (j < l->m && l->nldof[j] == d) l->inv[d] = -1 - j++;
    else l->inv[d] = ni++;
  }
  l->ni = ni;
  l->Lp = malloc((size_t)(ni + 1) * sizeof *l->Lp);
  l->Li = malloc((size_t)(l->nnz ? l->nnz : 1) * sizeof *l->Li);
  l->Lmap = malloc((size_t)(l->nnz ? l->nnz : 1) * sizeof *l->Lmap);
  l->Lx = malloc((size_t)(l->nnz ? l->nnz : 1) * sizeof *l->Lx);
  l->Lz = malloc((size_t)(l->nnz ? l->nnz : 1) * sizeof *l->Lz);
  if (!l->Lp || !l->Li || !l->Lmap || !l->Lx || !l->Lz) return WHIRL_ENOMEM;
  int nz = 0;
  l->Lp[0] = 0;
  for (int c = 0; c < n; ++c) {
    if (l->inv[c] < 0) continue;
    for (int q = l->Up[c]; q < l->Up[c + 1]; ++q)
      if (l->inv[l->Ui[q]] >= 0) {
        l->Li[nz] = l->inv[l->Ui[q]];
        l->Lmap[nz++] = q;
      }
    l->Lp[l->inv[c] + 1] = nz;
  }
  if (ni == 0) return WHIRL_OK;
  int rc = fe_band_init(&l->lu.band, ni, l->Lp, l->Li);
  if (rc) return rc;
  l->use_band = l->interior_lu == 1 ||
                (l->interior_lu == 0 && l->lu.band.kl + l->lu.band.ku <= FE_BAND_MAX);
  if (l->use_band) return WHIRL_OK;
  fe_band_free(&l->lu.band);
  char why[200];
  if (umf_bind(why, sizeof why) != WHIRL_OK) {
    snprintf(l->err, sizeof l->err, "UMFPACK (the interior block): %s", why);
    return WHIRL_ENOLIB;
  }
  /* UMFPACK's default two steps of iterative refinement per solve cost more
   * than the solve; the interior block is well conditioned away from the
   * held rotor's resonances, and condensed = uncondensed to 1e-14 without
   * them (t_fe_hbm) */
  umf.umfpack_zi_defaults(l->control);
  l->control[UMFPACK_IRSTEP] = 0;
  int st = umf.umfpack_zi_symbolic(ni, ni, l->Lp, l->Li, NULL, NULL, &l->symbolic,
                               l->control, NULL);
  if (st != UMFPACK_OK) {
    snprintf(l->err, sizeof l->err,
             "UMFPACK symbolic analysis of the interior block: status %d", st);
    return WHIRL_ESPARSE;
  }
  return WHIRL_OK;
}

int fe_lin_init(fe_lin *l, const whirl_fe_rotor *r, int condensed,
                int interior_lu, int H, int nu, const fe_aft *a) {
  memset(l, 0, sizeof *l);
  l->interior_lu = interior_lu;
  l->r = r;
  l->condensed = condensed;
  l->H = H;
  l->nu = nu;
  l->ndof = r->ndof;
  l->m = a->m;
  l->nldof = a->dof;
  l->b = condensed ? a->m : r->ndof;
  size_t b = (size_t)l->b, n = (size_t)r->ndof, m = (size_t)a->m;
  l->pos = malloc(m * sizeof *l->pos);
  l->Z = malloc((size_t)(H + 1) * b * b * sizeof *l->Z);
  l->dZ = malloc((size_t)(H + 1) * b * b * sizeof *l->dZ);
  l->gu = malloc(b * sizeof *l->gu);
  l->dgu = malloc(b * sizeof *l->dgu);
  l->g0 = malloc(b * sizeof *l->g0);
  if (!l->pos || !l->Z || !l->dZ || !l->gu || !l->dgu || !l->g0)
    return WHIRL_ENOMEM;
  for (int s = 0; s < FE_LIN_SLOTS; ++s) {
    fe_lin_slot *sl = &l->slot[s];
    sl->Z = malloc((size_t)(H + 1) * b * b * sizeof *sl->Z);
    sl->dZ = malloc((size_t)(H + 1) * b * b * sizeof *sl->dZ);
    sl->gu = malloc(b * sizeof *sl->gu);
    sl->dgu = malloc(b * sizeof *sl->dgu);
    sl->g0 = malloc(b * sizeof *sl->g0);
    if (!sl->Z || !sl->dZ || !sl->gu || !sl->dgu || !sl->g0) return WHIRL_ENOMEM;
  }
  for (int j = 0; j < a->m; ++j) l->pos[j] = condensed ? j : a->dof[j];
  int rc = union_pattern(l);
  if (rc || !condensed) return rc;
  if ((rc = interior_pattern(l))) return rc;
  size_t ni = (size_t)l->ni ? (size_t)l->ni : 1;
  size_t nz = (size_t)(l->nnz ? l->nnz : 1);
  l->nlq = malloc(nz * sizeof *l->nlq);
  l->nlcol = malloc(nz * sizeof *l->nlcol);
  if (!l->nlq || !l->nlcol) return WHIRL_ENOMEM;
  for (int c = 0; c < (int)n; ++c) /* the entries of the nonlinear rows */
    for (int q = l->Up[c]; q < l->Up[c + 1]; ++q)
      if (l->inv[l->Ui[q]] < 0) {
        l->nlq[l->nnlq] = q;
        l->nlcol[l->nnlq++] = c;
      }
  l->Dv = malloc(nz * sizeof *l->Dv);
  l->dDv = malloc(nz * sizeof *l->dDv);
  l->Lv = malloc(nz * sizeof *l->Lv);
  l->rhs = malloc(ni * (2 * m + 1) * sizeof *l->rhs);
  if (!l->Dv || !l->dDv || !l->Lv || !l->rhs) return WHIRL_ENOMEM;
  l->Xk = calloc((size_t)(H + 1) * ni * m, sizeof *l->Xk);
  l->yk = calloc((size_t)(H + 1) * ni, sizeof *l->yk);
  l->w1 = malloc(n * m * sizeof *l->w1);
  l->w2 = malloc(n * m * sizeof *l->w2);
  l->w3 = malloc(n * sizeof *l->w3);
  l->br = malloc(4 * ni * sizeof *l->br);
  if (!l->Xk || !l->yk || !l->w1 || !l->w2 || !l->w3 || !l->br)
    return WHIRL_ENOMEM;
  l->bz = l->br + ni;
  l->xr = l->bz + ni;
  l->xz = l->xr + ni;
  return WHIRL_OK;
}

void fe_lin_free(fe_lin *l) {
  fe_ilu_free(&l->lu);
  for (int s = 0; s < FE_LIN_SLOTS; ++s) {
    fe_lin_slot *sl = &l->slot[s];
    free(sl->Z), free(sl->dZ), free(sl->gu), free(sl->dgu), free(sl->g0);
  }
  if (l->symbolic) umf.umfpack_zi_free_symbolic(&l->symbolic);
  void *p[] = {l->nlq, l->nlcol, l->Dv, l->dDv, l->Lv, l->rhs, l->pos, l->Z, l->dZ, l->gu, l->dgu, l->g0, l->Up, l->Ui,
               l->Kx, l->Mx, l->Cx, l->Gx, l->inv, l->Lp, l->Li, l->Lmap,
               l->Lx, l->Lz, l->Xk, l->yk, l->w1, l->w2, l->w3, l->br};
  for (size_t i = 0; i < sizeof p / sizeof *p; ++i) free(p[i]);
  memset(l, 0, sizeof *l);
}

/* ------------------------------------------------------------- helpers */

/* Value of D_k (d = 0) or ∂D_k/∂Ω (d = 1) at union entry q. */
static double complex dval(const fe_lin *l, int q, int k, double Omega, int d) {
  double w = k * Omega / l->nu, dw = (double)k / l->nu;
  if (d == 0)
    return l->Kx[q] - w * w * l->Mx[q] + I * w * (l->Cx[q] + Omega * l->Gx[q]);
  return -2.0 * w * dw * l->Mx[q] +
         I * (dw * l->Cx[q] + (dw * Omega + w) * l->Gx[q]);
}

/* D_k and ∂D_k/∂Ω on the union pattern, once per harmonic and speed. */
static void values(fe_lin *l, int k, double Omega) {
  for (int q = 0; q < l->nnz; ++q) {
    l->Dv[q] = dval(l, q, k, Omega, 0);
    l->dDv[q] = dval(l, q, k, Omega, 1);
  }
}

/* y[ndof] = D x (d = 0) or ∂D/∂Ω x (d = 1), x[ndof], at the values of
 * values(). */
static void matvec(const fe_lin *l, int d, const double complex *x,
                   double complex *y) {
  const double complex *A = d ? l->dDv : l->Dv;
  memset(y, 0, (size_t)l->ndof * sizeof *y);
  for (int c = 0; c < l->ndof; ++c)
    if (x[c] != 0)
      for (int q = l->Up[c]; q < l->Up[c + 1]; ++q) y[l->Ui[q]] += A[q] * x[c];
}

static double complex vdot(const double complex *v, const double complex *x,
                           int n) {
  double complex s = 0;
  for (int i = 0; i < n; ++i) s += v[i] * x[i];
  return s;
}

/* ---------------------------------------------------- the interior block */

/* A factorisation of the interior block on the pattern of l: a banded LU
 * or UMFPACK's numeric object (the symbolic one is l's). */
int fe_ilu_init(const fe_lin *l, fe_ilu *f) {
  memset(f, 0, sizeof *f);
  if (!l->use_band || l->ni == 0) return WHIRL_OK;
  return fe_band_init(&f->band, l->ni, l->Lp, l->Li);
}

void fe_ilu_free(fe_ilu *f) {
  if (f->numeric) umf.umfpack_zi_free_numeric(&f->numeric);
  fe_band_free(&f->band);
  memset(f, 0, sizeof *f);
}

/* Factor D_ll from the values Dv on l's union pattern. */
int fe_ilu_factor(fe_lin *l, fe_ilu *f, const double complex *Dv) {
  int nzl = l->Lp[l->ni], st;
  if (l->use_band) {
    for (int q = 0; q < nzl; ++q) l->Lv[q] = Dv[l->Lmap[q]];
    return fe_band_factor(&f->band, l->Lp, l->Lv);
  }
  for (int q = 0; q < nzl; ++q) {
    l->Lx[q] = creal(Dv[l->Lmap[q]]);
    l->Lz[q] = cimag(Dv[l->Lmap[q]]);
  }
  if (f->numeric) umf.umfpack_zi_free_numeric(&f->numeric);
  st = umf.umfpack_zi_numeric(l->Lp, l->Li, l->Lx, l->Lz, l->symbolic,
                          &f->numeric, l->control, NULL);
  if (st == UMFPACK_OK) return WHIRL_OK;
  return st == UMFPACK_WARNING_singular_matrix ? WHIRL_ESINGULAR : WHIRL_ESPARSE;
}

/* B (ni × nrhs) := D_ll⁻¹ B, or D_ll⁻ᵀ B (the plain transpose). */
int fe_ilu_solve(fe_lin *l, fe_ilu *f, int transpose, int nrhs,
                 double complex *B) {
  if (l->use_band) return fe_band_solve(&f->band, transpose, nrhs, B);
  int ni = l->ni, sys = transpose ? UMFPACK_Aat : UMFPACK_A;
  for (int r = 0; r < nrhs; ++r) {
    double complex *x = B + (size_t)ni * r;
    for (int i = 0; i < ni; ++i) { l->br[i] = creal(x[i]); l->bz[i] = cimag(x[i]); }
    /* without iterative refinement (control) UMFPACK reads only the
     * numeric factors, not the values: other factorisations may reuse Lx */
    int st = umf.umfpack_zi_solve(sys, l->Lp, l->Li, l->Lx, l->Lz, l->xr, l->xz,
                              l->br, l->bz, f->numeric, l->control, NULL);
    if (st != UMFPACK_OK && st != UMFPACK_WARNING_singular_matrix) {
      snprintf(l->err, sizeof l->err, "UMFPACK solve: status %d", st);
      return WHIRL_ESPARSE;
    }
    for (int i = 0; i < ni; ++i) x[i] = l->xr[i] + I * l->xz[i];
  }
  return WHIRL_OK;
}

/* Factor D_ll of harmonic k at the values of values(). */
static int interior_factor(fe_lin *l, int k, double Omega) {
  int st = fe_ilu_factor(l, &l->lu, l->Dv);
  if (st == WHIRL_OK) return WHIRL_OK;
  snprintf(l->err, sizeof l->err,
           "the rotor with its nonlinear DOFs held is singular at harmonic "
           "%d, Omega = %g rad/s", k, Omega);
  return st;
}

static int interior_solve(fe_lin *l, int transpose, int nrhs,
                          double complex *B) {
  return fe_ilu_solve(l, &l->lu, transpose, nrhs, B);
}

/* Full-length column u[ndof] = [−x; e_j] from the interior solution x. */
static void basis_column(const fe_lin *l, int j, const double complex *x,
                         double complex *u) {
  for (int d = 0; d < l->ndof; ++d) {
    int s = l->inv[d];
    u[d] = s >= 0 ? -x[s] : ((-1 - s == j) ? 1.0 : 0.0);
  }
}

/* ------------------------------------------------------ condensed update */

/* W (w1) and V (w2) of harmonic k with D_ll factorised: the m right
 * columns D_ll x = D_l,dj and the m left ones D_llᵀ x = (D_dj,l)ᵀ in one
 * solve each; X_k keeps the right ones for the recovery. */
static int bases(fe_lin *l, int k) {
  int n = l->ndof, m = l->m, ni = l->ni, rc;
  double complex *R = l->rhs, *Lt = l->rhs + (size_t)ni * m;
  memset(R, 0, 2 * (size_t)ni * m * sizeof *R);
  for (int c = 0; c < n; ++c)
    for (int q = l->Up[c]; q < l->Up[c + 1]; ++q) {
      int row = l->inv[l->Ui[q]], col = l->inv[c];
      if (row >= 0 && col < 0) R[row + (size_t)ni * (-1 - col)] = l->Dv[q];
      if (row < 0 && col >= 0) Lt[col + (size_t)ni * (-1 - row)] = l->Dv[q];
    }
  if (ni && ((rc = interior_solve(l, 0, m, R)) ||
             (rc = interior_solve(l, 1, m, Lt))))
    return rc;
  memcpy(l->Xk + (size_t)k * ni * m, R, (size_t)ni * m * sizeof *R);
  for (int j = 0; j < m; ++j) {
    basis_column(l, j, R + (size_t)ni * j, l->w1 + (size_t)j * n);
    basis_column(l, j, Lt + (size_t)ni * j, l->w2 + (size_t)j * n);
  }
  return WHIRL_OK;
}

/* Z_k = (D W) on the nonlinear rows — from the few entries of those rows
 * (nlq) — and ∂Z_k = Vᵀ ∂D W. */
static void condensed_z(fe_lin *l, int k) {
  int n = l->ndof, m = l->m;
  double complex *Z = l->Z + (size_t)k * m * m, *dZ = l->dZ + (size_t)k * m * m;
  memset(Z, 0, (size_t)m * m * sizeof *Z);
  for (int e = 0; e < l->nnlq; ++e) {
    int q = l->nlq[e], i = -1 - l->inv[l->Ui[q]];
    const double complex *wc = l->w1 + l->nlcol[e];
    for (int j = 0; j < m; ++j) Z[i + m * j] += l->Dv[q] * wc[(size_t)j * n];
  }
  for (int j = 0; j < m; ++j) {
    matvec(l, 1, l->w1 + (size_t)j * n, l->w3);
    for (int i = 0; i < m; ++i)
      dZ[i + m * j] = vdot(l->w2 + (size_t)i * n, l->w3, n);
  }
}

/* The reduced load of harmonic k: F (static k = 0, unit unbalance k = ν),
 * its particular interior solution y_k and g = Vᵀ F, ∂g = Vᵀ(∂F − ∂D ỹ). */
static int condensed_load(fe_lin *l, int k, double Omega) {
  int n = l->ndof, m = l->m, ni = l->ni, rc;
  const whirl_fe_rotor *r = l->r;
  double complex *F = malloc((size_t)n * sizeof *F);
  if (!F) return WHIRL_ENOMEM;
  for (int d = 0; d < n; ++d)
    F[d] = k == 0 ? r->f0[d]
                  : Omega * Omega * (r->unb_c[d] - I * r->unb_s[d]);
  double complex *y = l->yk + (size_t)k * ni;
  for (int d = 0; d < n; ++d)
    if (l->inv[d] >= 0) y[l->inv[d]] = F[d];
  if (ni && (rc = interior_solve(l, 0, 1, y))) { free(F); return rc; }
  for (int d = 0; d < n; ++d) l->w3[d] = l->inv[d] >= 0 ? y[l->inv[d]] : 0.0;
  for (int i = 0; i < m; ++i) {
    double complex g = vdot(l->w2 + (size_t)i * n, F, n);
    if (k == 0) l->g0[i] = creal(g);
    else l->gu[i] = g;
  }
  if (k != 0) {
    matvec(l, 1, l->w3, F); /* F := ∂D ỹ */
    for (int d = 0; d < n; ++d)
      F[d] = 2.0 * Omega * (r->unb_c[d] - I * r->unb_s[d]) - F[d];
    for (int i = 0; i < m; ++i) l->dgu[i] = vdot(l->w2 + (size_t)i * n, F, n);
  }
  free(F);
  return WHIRL_OK;
}

/* Harmonic 0 (D_0 = K) does not depend on Ω: condensed once. */
static int condensed_update(fe_lin *l, double Omega) {
  for (int k = l->k0_done ? 1 : 0; k <= l->H; ++k) {
    values(l, k, Omega);
    int rc = l->ni ? interior_factor(l, k, Omega) : WHIRL_OK;
    if (!rc) rc = bases(l, k);
    if (!rc) condensed_z(l, k);
    if (!rc && (k == 0 || k == l->nu)) rc = condensed_load(l, k, Omega);
    if (rc) return rc;
    if (k == 0) l->k0_done = 1;
  }
  return WHIRL_OK;
}

/* ---------------------------------------------------- uncondensed update */

/* Z_k = D_k, ∂Z_k = ∂D_k dense; g_u = F per unit unbalance, g_0 = f0. */
static int full_update(fe_lin *l, double Omega) {
  int n = l->ndof;
  const whirl_fe_rotor *r = l->r;
  for (int k = 0; k <= l->H; ++k) {
    double complex *Z = l->Z + (size_t)k * n * n, *dZ = l->dZ + (size_t)k * n * n;
    memset(Z, 0, (size_t)n * n * sizeof *Z);
    memset(dZ, 0, (size_t)n * n * sizeof *dZ);
    for (int c = 0; c < n; ++c)
      for (int q = l->Up[c]; q < l->Up[c + 1]; ++q) {
        Z[l->Ui[q] + (size_t)n * c] = dval(l, q, k, Omega, 0);
        dZ[l->Ui[q] + (size_t)n * c] = dval(l, q, k, Omega, 1);
      }
  }
  for (int d = 0; d < n; ++d) {
    l->g0[d] = r->f0[d];
    l->gu[d] = Omega * Omega * (r->unb_c[d] - I * r->unb_s[d]);
    l->dgu[d] = 2.0 * Omega * (r->unb_c[d] - I * r->unb_s[d]);
  }
  return WHIRL_OK;
}

/* The current results and slot s exchanged (their buffers). */
static void swap_slot(fe_lin *l, int s) {
  fe_lin_slot *sl = &l->slot[s], cur = {l->Omega, l->valid, l->Z, l->dZ, l->gu, l->dgu, l->g0};
  l->Omega = sl->Omega, l->valid = sl->valid;
  l->Z = sl->Z, l->dZ = sl->dZ, l->gu = sl->gu, l->dgu = sl->dgu, l->g0 = sl->g0;
  *sl = cur;
}

/* An earlier speed's results made current (the slots' order kept: the
 * one that was current takes the slot); 1 if Omega was kept. */
static int recall(fe_lin *l, double Omega) {
  for (int s = 0; s < FE_LIN_SLOTS; ++s)
    if (l->slot[s].valid && l->slot[s].Omega == Omega) {
      swap_slot(l, s);
      return 1;
    }
  return 0;
}

/* The current results kept as the latest slot, the oldest slot's buffers
 * current, with the speed-independent harmonic 0 (condensed once, not
 * again: condensed_update) copied into them. */
static void stash(fe_lin *l) {
  const size_t b = (size_t)l->b, bb = b * b;
  fe_lin_slot *sl = l->slot;
  fe_lin_slot old = sl[FE_LIN_SLOTS - 1];
  for (int s = FE_LIN_SLOTS - 1; s > 0; --s) sl[s] = sl[s - 1];
  sl[0] = (fe_lin_slot){l->Omega, l->valid, l->Z, l->dZ, l->gu, l->dgu, l->g0};
  l->Z = old.Z, l->dZ = old.dZ, l->gu = old.gu, l->dgu = old.dgu, l->g0 = old.g0;
  memcpy(l->Z, sl[0].Z, bb * sizeof *l->Z);
  memcpy(l->dZ, sl[0].dZ, bb * sizeof *l->dZ);
  memcpy(l->g0, sl[0].g0, b * sizeof *l->g0);
}

static int compute(fe_lin *l, double Omega) {
  l->valid = 0;
  l->xk_valid = 0;
  l->err[0] = 0;
  int rc = l->condensed ? condensed_update(l, Omega) : full_update(l, Omega);
  if (rc) return rc;
  l->Omega = l->xk_Omega = Omega;
  l->valid = l->xk_valid = 1;
  return WHIRL_OK;
}

int fe_lin_update(fe_lin *l, double Omega) {
  if (l->valid && Omega == l->Omega) return WHIRL_OK;
  if (recall(l, Omega)) return WHIRL_OK;
  if (l->valid) stash(l);
  return compute(l, Omega);
}

/* q_l,k = s y_k − X_k q_n,k per harmonic, the load scale s = 1 for the
 * static part and `unb` for the unbalance; real form of the complex
 * amplitudes Q = a − i b. */
int fe_lin_recover(fe_lin *l, double Omega, double unb, const double *x,
                   double *q) {
  int rc = fe_lin_update(l, Omega);
  /* X_k, y_k are the last computed speed's: again at a recalled one */
  if (!rc && !(l->xk_valid && l->xk_Omega == Omega)) rc = compute(l, Omega);
  if (rc) return rc;
  int n = l->ndof, m = l->m, ni = l->ni, b = l->b, L = 2 * l->H + 1;
  if (!l->condensed) {
    memcpy(q, x, (size_t)n * L * sizeof *q);
    return WHIRL_OK;
  }
  for (int k = 0; k <= l->H; ++k) {
    const double complex *Xk = l->Xk + (size_t)k * ni * m;
    const double complex *y = l->yk + (size_t)k * ni;
    double sk = k == 0 ? 1.0 : (k == l->nu ? unb : 0.0);
    for (int d = 0; d < n; ++d) {
      int s = l->inv[d];
      double complex Q;
      if (s < 0) {
        int j = -1 - s;
        Q = k == 0 ? x[j] : x[b * (2 * k - 1) + j] - I * x[b * 2 * k + j];
      } else {
        Q = (k == 0 || k == l->nu) ? sk * y[s] : 0.0;
        for (int j = 0; j < m; ++j) {
          double complex qn = k == 0 ? x[j]
                                     : x[b * (2 * k - 1) + j] - I * x[b * 2 * k + j];
          Q -= Xk[s + (size_t)ni * j] * qn;
        }
      }
      if (k == 0) {
        q[d] = creal(Q);
      } else {
        q[n * (2 * k - 1) + d] = creal(Q);
        q[n * 2 * k + d] = -cimag(Q);
      }
    }
  }
  return WHIRL_OK;
}

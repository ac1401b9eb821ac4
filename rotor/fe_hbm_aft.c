/* rotor/fe_hbm_aft.c — the forces of a finite-element rotor's nonlinear
 * elements on its nonlinear DOFs as Fourier coefficients, by the
 * alternating frequency–time scheme (Cameron & Griffin, J. Appl. Mech. 56
 * (1989) 149; Krack & Gross, Harmonic Balance for Nonlinear Vibration
 * Problems, 2019, §3.3): coefficients → N time samples of displacement,
 * velocity and acceleration (FFTW c2r), the element forces and Jacobians
 * pointwise (whirl_fe_nl_force), samples → coefficients (FFTW r2c).
 *
 * The Jacobian of the coefficients of f(t) = J(t) x⁽ᵈ⁾(t) with respect to
 * those of x is built from the discrete Fourier coefficients Ĵ_n of the
 * sampled J(t): with x̂_l = (a_l − i b_l)/2 and μ(l) = (i l ω)ᵈ,
 *   ∂f̂_k/∂c = Ĵ_k μ(0),  ∂f̂_k/∂a_l = (E + E')/2,  ∂f̂_k/∂b_l = i (E' − E)/2,
 *   E = Ĵ_{k−l} μ(l),  E' = Ĵ_{k+l} μ(−l)   (indices mod N),
 * and f_c = Re f̂_0, f_a,k = 2 Re f̂_k, f_b,k = −2 Im f̂_k: the exact
 * derivative of the discrete AFT, at the cost of one FFT per entry of the
 * element Jacobians instead of one per unknown.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#ifdef HAVE_CONFIG_H
#include "config.h"
#endif
#include <whirl/dynlib.h>

#include "fe_hbm_impl.h"

/* FFTW, opened at the first harmonic balance of a rotor (whirl/dynlib.h) */
#define FFTW_FUNCS(X)                                                          \
  X(fftw_malloc) X(fftw_free) X(fftw_plan_many_dft_c2r) X(fftw_plan_many_dft_r2c) \
  X(fftw_execute) X(fftw_destroy_plan)
WHIRL_DYNLIB_FFTW3(fftw, FFTW_FUNCS)

static int is_film(whirl_fe_nl_kind k) {
  return k == WHIRL_FE_SFD_SHORT_PI || k == WHIRL_FE_SFD_SHORT_2PI ||
         k == WHIRL_FE_SFD_LONG || k == WHIRL_FE_SFD_INERTIA ||
         k == WHIRL_FE_JOURNAL_SHORT;
}

static int cmp_int(const void *x, const void *y) {
  int a = *(const int *)x, b = *(const int *)y;
  return (a > b) - (a < b);
}

/* The nonlinear DOFs, sorted and unique, and each element's positions. */
static int collect_dofs(fe_aft *a, const whirl_fe_rotor *r) {
  int *all = malloc(4 * (size_t)r->nnl * sizeof *all);
  if (!all) return WHIRL_ENOMEM;
  int na = 0;
  for (int e = 0; e < r->nnl; ++e) {
    const whirl_fe_nl *el = &r->nl[e];
    for (int k = 0; k < 2; ++k) all[na++] = 4 * el->node + k;
    if (el->pedestal >= 0)
      for (int k = 0; k < 2; ++k)
        all[na++] = 4 * r->nnode + 2 * el->pedestal + k;
  }
  qsort(all, (size_t)na, sizeof *all, cmp_int);
  a->m = 0;
  for (int i = 0; i < na; ++i)
    if (a->m == 0 || all[i] != all[a->m - 1]) all[a->m++] = all[i];
  a->dof = all;
  for (int e = 0; e < r->nnl; ++e) {
    const whirl_fe_nl *el = &r->nl[e];
    for (int k = 0; k < 4; ++k) {
      int d = k < 2 ? 4 * el->node + k
                    : (el->pedestal >= 0
                           ? 4 * r->nnode + 2 * el->pedestal + (k - 2) : -1);
      a->epos[e][k] = -1;
      for (int j = 0; d >= 0 && j < a->m; ++j)
        if (a->dof[j] == d) a->epos[e][k] = j;
    }
  }
  return WHIRL_OK;
}

static int make_plans(fe_aft *a) {
  int N = a->N, nc = N / 2 + 1, m = a->m, nj = 12 * a->nnl;
  a->cq = fftw.fftw_malloc(sizeof *a->cq * (size_t)(3 * m * nc));
  a->tq = fftw.fftw_malloc(sizeof *a->tq * (size_t)(3 * m * N));
  a->cf = fftw.fftw_malloc(sizeof *a->cf * (size_t)(m * nc));
  a->tf = fftw.fftw_malloc(sizeof *a->tf * (size_t)(m * N));
  a->cj = fftw.fftw_malloc(sizeof *a->cj * (size_t)(nj * nc));
  a->tj = fftw.fftw_malloc(sizeof *a->tj * (size_t)(nj * N));
  if (!a->cq || !a->tq || !a->cf || !a->tf || !a->cj || !a->tj)
    return WHIRL_ENOMEM;
  a->p_q = fftw.fftw_plan_many_dft_c2r(1, &N, 3 * m, a->cq, NULL, 1, nc, a->tq,
                                  NULL, 1, N, FFTW_ESTIMATE);
  a->p_f = fftw.fftw_plan_many_dft_r2c(1, &N, m, a->tf, NULL, 1, N, a->cf, NULL,
                                  1, nc, FFTW_ESTIMATE);
  a->p_j = fftw.fftw_plan_many_dft_r2c(1, &N, nj, a->tj, NULL, 1, N, a->cj, NULL,
                                  1, nc, FFTW_ESTIMATE);
  return a->p_q && a->p_f && a->p_j ? WHIRL_OK : WHIRL_ENOMEM;
}

int fe_aft_init(fe_aft *a, const whirl_fe_rotor *r, int H, int N, char *err,
                size_t errlen) {
  memset(a, 0, sizeof *a);
  if (fftw_bind(err, errlen) != WHIRL_OK) return WHIRL_ENOLIB;
  a->H = H;
  a->N = N;
  a->nnl = r->nnl;
  a->el = malloc((size_t)r->nnl * sizeof *a->el);
  a->clear0 = malloc((size_t)r->nnl * sizeof *a->clear0);
  a->visc0 = malloc((size_t)r->nnl * sizeof *a->visc0);
  a->epos = malloc((size_t)r->nnl * sizeof *a->epos);
  if (!a->el || !a->clear0 || !a->visc0 || !a->epos) goto nomem;
  memcpy(a->el, r->nl, (size_t)r->nnl * sizeof *a->el);
  for (int e = 0; e < r->nnl; ++e) {
    a->clear0[e] = r->nl[e].par.clearance;
    a->visc0[e] = r->nl[e].par.viscosity;
    if (r->nl[e].node < 0 || r->nl[e].node >= r->nnode ||
        r->nl[e].pedestal >= r->npedestal)
      return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                          "nonlinear element %d: node %d or pedestal %d "
                          "out of range", e, r->nl[e].node,
                          r->nl[e].pedestal);
  }
  if (collect_dofs(a, r) || make_plans(a)) goto nomem;
  return WHIRL_OK;
nomem:
  return WHIRL_ERRMSG(err, errlen, WHIRL_ENOMEM, "out of memory");
}

void fe_aft_free(fe_aft *a) {
  if (fftw_bind(NULL, 0) == WHIRL_OK) { /* else FFTW made nothing to free */
    if (a->p_q) fftw.fftw_destroy_plan(a->p_q);
    if (a->p_f) fftw.fftw_destroy_plan(a->p_f);
    if (a->p_j) fftw.fftw_destroy_plan(a->p_j);
    fftw.fftw_free(a->cq);
    fftw.fftw_free(a->tq);
    fftw.fftw_free(a->cf);
    fftw.fftw_free(a->tf);
    fftw.fftw_free(a->cj);
    fftw.fftw_free(a->tj);
  }
  free(a->dof);
  free(a->el);
  free(a->clear0);
  free(a->visc0);
  free(a->epos);
  memset(a, 0, sizeof *a);
}

void fe_aft_set_scales(fe_aft *a, double clearance, double viscosity) {
  for (int e = 0; e < a->nnl; ++e)
    if (is_film(a->el[e].kind)) {
      a->el[e].par.clearance = a->clear0[e] * clearance;
      a->el[e].par.viscosity = a->visc0[e] * viscosity;
    }
}

/* Coefficients → samples of displacement, velocity, acceleration. */
static void to_time(fe_aft *a, const double *q, double w) {
  int m = a->m, nc = a->N / 2 + 1;
  memset(a->cq, 0, sizeof *a->cq * (size_t)(3 * m * nc));
  for (int j = 0; j < m; ++j) {
    double complex *d = a->cq + (size_t)j * nc;
    double complex *v = a->cq + (size_t)(m + j) * nc;
    double complex *ac = a->cq + (size_t)(2 * m + j) * nc;
    d[0] = q[j];
    for (int k = 1; k <= a->H; ++k) {
      double complex x = 0.5 * (q[m * (2 * k - 1) + j] - I * q[m * 2 * k + j]);
      d[k] = x;
      v[k] = I * (k * w) * x;
      ac[k] = -(k * w) * (k * w) * x;
    }
  }
  fftw.fftw_execute(a->p_q);
}

/* The forces and Jacobians of every element at every sample. */
static int sample_forces(fe_aft *a, double Omega, int jac) {
  int N = a->N, m = a->m;
  memset(a->tf, 0, sizeof *a->tf * (size_t)(m * N));
  for (int t = 0; t < N; ++t)
    for (int e = 0; e < a->nnl; ++e) {
      const int *ps = a->epos[e];
      double r[2], v[2], ac[2], f[2];
      for (int k = 0; k < 2; ++k) {
        int jn = ps[k], jp = ps[2 + k];
        r[k] = a->tq[(size_t)jn * N + t] - a->el[e].offset[k];
        v[k] = a->tq[(size_t)(m + jn) * N + t];
        ac[k] = a->tq[(size_t)(2 * m + jn) * N + t];
        if (jp >= 0) {
          r[k] -= a->tq[(size_t)jp * N + t];
          v[k] -= a->tq[(size_t)(m + jp) * N + t];
          ac[k] -= a->tq[(size_t)(2 * m + jp) * N + t];
        }
      }
      double J[12];
      int rc = whirl_fe_nl_force(&a->el[e], r, v, ac, Omega, f,
                                 jac ? J : NULL, jac ? J + 4 : NULL,
                                 jac ? J + 8 : NULL);
      if (rc == WHIRL_EDOMAIN) return 1;
      if (rc != WHIRL_OK) return rc < 0 ? rc : 1;
      for (int k = 0; k < 2; ++k) {
        a->tf[(size_t)ps[k] * N + t] += f[k];
        if (ps[2 + k] >= 0) a->tf[(size_t)ps[2 + k] * N + t] -= f[k];
      }
      if (jac)
        for (int s = 0; s < 12; ++s)
          a->tj[(size_t)(12 * e + s) * N + t] = J[s];
    }
  return 0;
}

/* Ĵ_n, n any integer, of a series transformed by r2c (normalised by N). */
static double complex jhat(const double complex *c, int N, int n) {
  int i = ((n % N) + N) % N;
  return (i <= N / 2 ? c[i] : conj(c[N - i])) / N;
}

static double complex mu(int l, double w, int d) {
  if (d == 0) return 1.0;
  if (d == 1) return I * (l * w);
  return -(l * w) * (l * w);
}

/* J[ld] += sgn · ∂(coefficients of Ĵ(t) x⁽ᵈ⁾(t))/∂(coefficients of x)
 * for the scalar series c, rows of DOF position ri, columns cj (m a block). */
static void add_block(const double complex *c, const fe_aft *a, double w,
                      int d, double sgn, double *J, int ri, int cj) {
  int H = a->H, N = a->N, m = a->m, ld = m * (2 * H + 1);
  for (int k = 0; k <= H; ++k)
    for (int l = 0; l <= H; ++l) {
      double complex col[2];
      int ncol = l == 0 ? 1 : 2, c0 = l == 0 ? 0 : 2 * l - 1;
      if (l == 0) {
        col[0] = jhat(c, N, k) * mu(0, w, d);
      } else {
        double complex E = jhat(c, N, k - l) * mu(l, w, d);
        double complex Ep = jhat(c, N, k + l) * mu(-l, w, d);
        col[0] = 0.5 * (E + Ep);
        col[1] = 0.5 * I * (Ep - E);
      }
      for (int s = 0; s < ncol; ++s) {
        size_t jc = (size_t)ld * (size_t)(m * (c0 + s) + cj);
        if (k == 0) {
          J[ri + jc] += sgn * creal(col[s]);
        } else {
          J[m * (2 * k - 1) + ri + jc] += sgn * 2.0 * creal(col[s]);
          J[m * 2 * k + ri + jc] -= sgn * 2.0 * cimag(col[s]);
        }
      }
    }
}

/* Scatter the blocks of every element entry, with the signs of node and
 * pedestal, into J (mode JAC: one matrix; HILL: three). */
static void assemble_jac(fe_aft *a, double w, double *J, int mode) {
  int nc = a->N / 2 + 1;
  size_t ld = (size_t)a->m * (size_t)(2 * a->H + 1), n2 = ld * ld;
  memset(J, 0, sizeof *J * n2 * (mode == FE_AFT_HILL ? 3 : 1));
  for (int e = 0; e < a->nnl; ++e) {
    const int *ps = a->epos[e];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int s = 0; s < 4; ++s) { /* (node|ped) rows × (node|ped) cols */
          int ri = ps[i + 2 * (s & 1)], cj = ps[j + 2 * (s >> 1)];
          if (ri < 0 || cj < 0) continue;
          double sgn = ((s & 1) ^ (s >> 1)) ? -1.0 : 1.0;
          for (int t = 0; t < 3; ++t) {
            const double complex *c =
                a->cj + (size_t)(12 * e + 4 * t + i + 2 * j) * nc;
            if (mode == FE_AFT_JAC)
              add_block(c, a, w, t, sgn, J, ri, cj);
            else
              add_block(c, a, w, 0, sgn, J + n2 * t, ri, cj);
          }
        }
  }
}

int fe_aft_eval(fe_aft *a, const double *q, double w, double Omega, double *f,
                double *J, int mode) {
  int m = a->m, N = a->N, nc = N / 2 + 1;
  to_time(a, q, w);
  int rc = sample_forces(a, Omega, mode != FE_AFT_FORCE);
  if (rc) return rc;
  fftw.fftw_execute(a->p_f);
  for (int j = 0; j < m; ++j) {
    const double complex *c = a->cf + (size_t)j * nc;
    f[j] = creal(c[0]) / N;
    for (int k = 1; k <= a->H; ++k) {
      f[m * (2 * k - 1) + j] = 2.0 * creal(c[k]) / N;
      f[m * 2 * k + j] = -2.0 * cimag(c[k]) / N;
    }
  }
  if (mode == FE_AFT_FORCE) return 0;
  fftw.fftw_execute(a->p_j);
  assemble_jac(a, w, J, mode);
  return 0;
}

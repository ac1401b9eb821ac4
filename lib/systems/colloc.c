/* lib/systems/colloc.c — constructor: periodic orbits of an ODE model by
 * orthogonal collocation at Gauss–Legendre points (de Boor & Swartz, SIAM J.
 * Numer. Anal. 10 (1973) 582; Doedel, AUTO-07p manual ch. 10), as an
 * algebraic problem F(X, p) = 0 for the continuation core, with a sparse
 * analytic Jacobian, Floquet multipliers as its spectrum, and AUTO-style mesh
 * adaptation (Russell & Christiansen 1978).
 *
 * Scaling: each collocation row is multiplied by its interval length h_i,
 *   sum_k l_k'(σ_c) x_{i,k} − h_i T f(t0 + T τ_c, x(τ_c), p) = 0,
 * with σ the local variable on [0, 1] and l_k the Lagrange basis on NCOL + 1
 * equally spaced nodes, so the rows stay O(|x|) on every mesh.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/colloc.h>
#include <whirl/cont.h>
#include <whirl/floquet.h>
#include <whirl/ode.h>

#include "colloc_basis.h"
#include "colloc_impl.h"
#include "util/short_copy.h"
#include "util/threads_impl.h"
#include <whirl/linsol.h>

void whirl_colloc_options_default(whirl_colloc_options *o) {
  memset(o, 0, sizeof *o);
  o->ntst = 20;
  o->ncol = 4;
  o->forcing_param = -1;
  o->nu = 1;
  o->t0 = 0.0;
  o->floquet_rtol = 1e-11;
  o->floquet = WHIRL_COLLOC_FLOQUET_CONDENSED;
  o->free_param = -1;
  o->threads = 1;
}

/* ------------------------------------------------------------ basis */

/* Gauss–Legendre points, the Lagrange basis and the evaluation of the
 * piecewise polynomial live in colloc_basis.c (shared with bvp.c); the
 * names used below. */
#define gauss_legendre colloc_basis_gauss_legendre
#define lagrange colloc_basis_lagrange
#define eval_poly colloc_basis_eval_poly

/* ------------------------------------------------------------ helpers */

double colloc_period_of(const whirl_colloc *c, const double *X,
                        const double *p) {
  if (c->fq >= 0) return c->Tfix;
  if (c->aut) return X[c->nx - 1];
  return 2.0 * WHIRL_PI * (double)c->nu / p[c->fpar];
}

/* p with p[fq] = X's last entry in buf (npar), or p itself (T unknown). */
static const double *par_into(const whirl_colloc *c, const double *X,
                              const double *p, double *buf) {
  if (c->fq < 0 || !p) return p;
  if (p != buf) memcpy(buf, p, c->prob->npar * sizeof *buf);
  buf[c->fq] = X[c->nx - 1];
  return buf;
}

const double *colloc_par(whirl_colloc *c, const double *X, const double *p) {
  return par_into(c, X, p, c->pq);
}

void whirl_colloc_params(const whirl_colloc *c, const double *X,
                         const double *p, double *pfull) {
  if (!c || !p || !pfull) return;
  if (pfull != p) memcpy(pfull, p, c->prob->npar * sizeof *pfull);
  if (c->fq >= 0 && X) pfull[c->fq] = X[c->nx - 1];
}

int whirl_colloc_free_param(const whirl_colloc *c) { return c ? c->fq : -1; }

static double period_of(const whirl_colloc *c, const double *X,
                        const double *p) {
  return colloc_period_of(c, X, p);
}

/* x and dx/dσ of interval i at Gauss point g into s->xc, s->dx (sums in
 * registers: s->xc, s->dx might alias X as far as the compiler knows). */
static void at_gauss(const whirl_colloc *c, colloc_scratch *s, const double *X,
                     size_t i, size_t g) {
  const size_t n = c->n, m = c->ncol;
  const double *l = c->L + g * (m + 1), *dl = c->D + g * (m + 1);
  const double *xi = X + n * i * m;
  for (size_t r = 0; r < n; ++r) {
    double v0 = 0.0, d = 0.0;
    for (size_t k = 0; k <= m; ++k) {
      const double v = xi[n * k + r];
      v0 += l[k] * v;
      d += dl[k] * v;
    }
    s->xc[r] = v0;
    s->dx[r] = d;
  }
}

static int phase_at_nodes(whirl_colloc *c);

/* Phase reference from the node values Xn: x_ref' at the Gauss points and
 * the phase row phase[j] = sum over the intervals holding node j of
 * h_i sum_c w_c l_k(σ_c) x_ref'(τ_{i,c}), so that the quadrature of
 * ∫ <x, x_ref'> dτ is <phase, X>. */
static void set_reference(whirl_colloc *c, const double *Xn) {
  const size_t n = c->n, m = c->ncol;
  double *dx = c->scr[0].dx;
  if (Xn != c->ref) memcpy(c->ref, Xn, c->nnodes * n * sizeof *c->ref);
  if (c->phase_nodes && c->have_ref_par && c->fq < 0 && phase_at_nodes(c) == 0) {
    c->phase0 = 0.0; /* AUTO's ∫ <x − x_ref, x_ref'> */
    c->have_ref = 1;
    return;
  }
  memset(c->phase, 0, c->nnodes * n * sizeof *c->phase); /* whirl's rule */
  for (size_t i = 0; i < c->ntst; ++i) {
    for (size_t g = 0; g < m; ++g) {
      const double *dl = c->D + g * (m + 1), *l = c->L + g * (m + 1);
      /* h x_ref'(τ) = dx_ref/dσ, so h_i w_c x_ref' = w_c dx_ref/dσ */
      for (size_t r = 0; r < n; ++r) {
        double d = 0.0;
        for (size_t k = 0; k <= m; ++k)
          d += dl[k] * c->ref[n * (i * m + k) + r];
        dx[r] = c->gw[g] * d;
      }
      for (size_t k = 0; k <= m; ++k)
        for (size_t r = 0; r < n; ++r)
          c->phase[n * (i * m + k) + r] += l[k] * dx[r];
    }
  }
  double s = 0.0;
  for (size_t q = 0; q < c->nnodes * n; ++q) s += c->phase[q] * c->ref[q];
  c->phase0 = s;
  c->have_ref = 1;
}

/* The weights of the Lagrange integrals on [0, 1] at the NCOL + 1 equally
 * spaced nodes (AUTO's WI; Gauss's rule is exact for them). */
static void node_int_weights(const whirl_colloc *c, double *wi) {
  const size_t m = c->ncol;
  for (size_t k = 0; k <= m; ++k) {
    double w = 0.0;
    for (size_t g = 0; g < m; ++g) w += c->gw[g] * c->L[g * (m + 1) + k];
    wi[k] = w;
  }
}

/* AUTO-07p's phase condition (periodic.f90 ICPS with bvp.f90 STUPBV and
 * the integral rule of solvebv.f90): ∫ <x − x_ref, x_ref'> by the weights
 * of the Lagrange integrals at the NCOL + 1 nodes of each interval, with
 * x_ref' = T f(x_ref) at those nodes (the model's vector field, where
 * whirl's own rule takes the reference polynomial's derivative at the
 * Gauss points).  The two agree to the collocation error; AUTO's orbits
 * take their phase along a branch from AUTO's.  0, else the model failed
 * at a node (whirl's rule then). */
static int phase_at_nodes(whirl_colloc *c) {
  const size_t n = c->n, m = c->ncol, N = c->ntst;
  double wi[COLLOC_MAXCOL + 1];
  node_int_weights(c, wi);
  memset(c->phase, 0, c->nnodes * n * sizeof *c->phase);
  double *f = c->scr[0].f;
  const double T = c->ref_T;
  for (size_t i = 0; i < N; ++i) {
    const double h = c->mesh[i + 1] - c->mesh[i];
    for (size_t k = 0; k <= m; ++k) {
      const size_t q = i * m + k;
      const double tau = c->mesh[i] + h * (double)k / (double)m;
      if (c->prob->rhs(c->t0 + T * tau, c->ref + n * q, c->ref_par, f, c->prob->data) != 0)
        return 1;
      for (size_t r = 0; r < n; ++r) {
        if (!isfinite(f[r])) return 1;
        c->phase[n * q + r] += h * wi[k] * T * f[r];
      }
    }
  }
  return 0;
}

/* The model's f_x at (t, s->xc) into s->J: analytic or central
 * differences. */
static int model_jac(const whirl_colloc *c, colloc_scratch *s, double t,
                     const double *p) {
  const whirl_problem *pr = c->prob;
  if (pr->jac_x) return pr->jac_x(t, s->xc, p, s->J, pr->data);
  return whirl_fd_jac_x(pr, t, s->xc, p, s->J, s->work);
}

int colloc_threads(const whirl_colloc *c) {
  return c->nthreads > 1 && c->ntst * c->ncol * c->n >= COLLOC_PAR_MIN
             ? c->nthreads : 1;
}

void colloc_residual_rows(const whirl_colloc *c, const colloc_scratch *s, size_t i,
                          size_t g, double h, double T, const double *f, double *F) {
  const size_t n = c->n;
  double *Fr = F + n * (i * c->ncol + g);
  for (size_t r = 0; r < n; ++r) Fr[r] = s->dx[r] - h * T * f[r];
}

/* The residual rows of interval i at (X, p), T, with scratch s. */
static int interval_F(whirl_colloc *c, colloc_scratch *s, const double *X,
                      const double *p, double T, size_t i, double *F) {
  const whirl_problem *pr = c->prob;
  const size_t m = c->ncol;
  const double h = c->mesh[i + 1] - c->mesh[i];
  for (size_t g = 0; g < m; ++g) {
    at_gauss(c, s, X, i, g);
    const double tau = c->mesh[i] + h * c->gs[g];
    int rc = pr->rhs(c->t0 + T * tau, s->xc, p, s->f, pr->data);
    if (rc != 0) return rc;
    colloc_residual_rows(c, s, i, g, h, T, s->f, F);
  }
  return 0;
}

/* ------------------------------------------------------------ system */

static int colloc_F(const double *X, const double *p, double *F, void *data) {
  whirl_colloc *c = data;
  const size_t N = c->ntst;
  /* its own copy: F is what differences of F_p call, from inside the
   * entry points that hold c->pq (colloc_cond.c's factorisation) */
  p = par_into(c, X, p, c->pF);
  const double T = period_of(c, X, p);
  /* a non-positive period (a step past ω = 0): recoverable, the core
   * shortens the step */
  if (!(T > 0) || !isfinite(T)) return 1;
  /* the intervals in parallel (the model is called from several threads
   * at once, as AUTO-07p's OpenMP build does): the first failure in
   * interval order is the one reported, whatever the threads */
  const int nth = colloc_threads(c) > 1 ? whirl_gov_begin(&c->gov_F) : 1;
  size_t bad = N;
  int bad_rc = 0;
#pragma omp parallel for num_threads(nth) schedule(dynamic, 8) if (nth > 1)
  for (size_t i = 0; i < N; ++i) {
    int rc = interval_F(c, &c->scr[whirl_thread_num()], X, p, T, i, F);
    if (rc != 0) {
#pragma omp critical(whirl_colloc_F)
      if (i < bad) bad = i, bad_rc = rc;
    }
  }
  if (colloc_threads(c) > 1) whirl_gov_end(&c->gov_F);
  if (bad < N) return bad_rc;
  colloc_end_rows(c, X, F);
  return 0;
}

void colloc_end_rows(const whirl_colloc *c, const double *X, double *F) {
  const size_t n = c->n, m = c->ncol, N = c->ntst;
  /* periodicity x(1) − x(0) = 0, or 2π k for a rotation */
  const double *x0 = X, *x1 = X + n * N * m;
  for (size_t r = 0; r < n; ++r) F[n * N * m + r] = x1[r] - x0[r] - c->rot[r];
  if (c->aut) {
    /* <phase, X> summed as <phase, X − ref> + <phase, ref>: the terms are
     * small near the reference, so the residual has little rounding */
    double s = 0.0;
    for (size_t q = 0; q < c->nnodes * n; ++q)
      s += c->phase[q] * (X[q] - c->ref[q]);
    /* ∫ <x, x_ref'> for orbits (<x_ref, x_ref'> integrates to 0); with a
     * rotation it does not, and AUTO's ∫ <x − x_ref, x_ref'> is the one */
    int rotating = 0;
    for (size_t r = 0; r < n; ++r) rotating |= c->rot[r] != 0.0;
    F[c->nx - 1] = s + (rotating ? 0.0 : c->phase0);
  }
}

/* At a fixed period the last unknown is the parameter q = c->fq: its
 * column of the collocation rows at (t, s->xc) is −h T ∂f/∂p_q, from the
 * model's jac_p or a central difference in p_q (p is colloc_par's). */
static int free_param_column(const whirl_colloc *c, colloc_scratch *s,
                             double t, double h, double T, const double *p,
                             double *dT) {
  const whirl_problem *pr = c->prob;
  const size_t n = c->n, q = (size_t)c->fq;
  int rc;
  if (pr->jac_p) {
    if ((rc = pr->jac_p(t, s->xc, p, s->Jpar, pr->data)) != 0) return rc;
    for (size_t r = 0; r < n; ++r) dT[r] = -h * T * s->Jpar[r + n * q];
    return 0;
  }
  whirl_copy_short(s->pw, p, pr->npar);
  const double hp = cbrt(DBL_EPSILON) * fmax(1.0, fabs(p[q]));
  s->pw[q] = p[q] + hp;
  const double up = s->pw[q];
  if ((rc = pr->rhs(t, s->xc, s->pw, s->f, pr->data)) != 0) return rc;
  s->pw[q] = p[q] - hp;
  const double dn = s->pw[q];
  if ((rc = pr->rhs(t, s->xc, s->pw, s->f2, pr->data)) != 0) return rc;
  for (size_t r = 0; r < n; ++r) dT[r] = -h * T * (s->f[r] - s->f2[r]) / (up - dn);
  return 0;
}

int colloc_gauss_jac(whirl_colloc *c, colloc_scratch *s, const double *X,
                     const double *p, double T, size_t i, size_t g,
                     double *dT) {
  const whirl_problem *pr = c->prob;
  const size_t n = c->n;
  const double h = c->mesh[i + 1] - c->mesh[i];
  at_gauss(c, s, X, i, g);
  const double tau = c->mesh[i] + h * c->gs[g];
  const double t = c->t0 + T * tau;
  int rc = model_jac(c, s, t, p);
  if (rc != 0 || !dT) return rc;
  if (c->fq >= 0) return free_param_column(c, s, t, h, T, p, dT);
  /* dF/dT = −h (f + T τ ∂f/∂t); the time term only for a model not
   * flagged autonomous (central difference in t) */
  if ((rc = pr->rhs(t, s->xc, p, s->f, pr->data)) != 0) return rc;
  for (size_t r = 0; r < n; ++r) dT[r] = -h * s->f[r];
  if (!pr->autonomous) {
    const double ht = cbrt(DBL_EPSILON) * fmax(1.0, fabs(t));
    if ((rc = pr->rhs(t + ht, s->xc, p, s->f, pr->data)) != 0) return rc;
    if ((rc = pr->rhs(t - ht, s->xc, p, s->f2, pr->data)) != 0) return rc;
    const double sc = -h * T * tau / (2.0 * ht);
    for (size_t r = 0; r < n; ++r) dT[r] += sc * (s->f[r] - s->f2[r]);
  }
  return 0;
}

/* Sparse values in pattern order.  Entry (row R, column col) of a node
 * column lies at Jp[col] + R − Ji[Jp[col]]: its collocation rows are one
 * contiguous block. */
static int colloc_Fx_sparse(const double *X, const double *p, double *Jx,
                            void *data) {
  whirl_colloc *c = data;
  const size_t n = c->n, m = c->ncol, N = c->ntst;
  p = colloc_par(c, X, p);
  const double T = period_of(c, X, p);
  const size_t colT = n * c->nnodes;
  for (size_t i = 0; i < N; ++i) {
    const double h = c->mesh[i + 1] - c->mesh[i];
    for (size_t g = 0; g < m; ++g) {
      const size_t R0 = n * (i * m + g);
      double *vT = c->aut ? Jx + (size_t)c->Jp[colT] + R0 : NULL;
      int rc = colloc_gauss_jac(c, &c->scr[0], X, p, T, i, g, vT);
      if (rc != 0) return rc;
      const double *l = c->L + g * (m + 1), *dl = c->D + g * (m + 1);
      for (size_t k = 0; k <= m; ++k) {
        const size_t j = i * m + k;
        for (size_t q = 0; q < n; ++q) {
          const size_t col = n * j + q;
          double *v = Jx + (size_t)c->Jp[col] + R0 - (size_t)c->Ji[c->Jp[col]];
          for (size_t r = 0; r < n; ++r)
            v[r] = (r == q ? dl[k] : 0.0) - h * T * l[k] * c->scr[0].J[r + n * q];
        }
      }
    }
  }
  /* periodicity: −1 in the columns of node 0, +1 in those of the last node;
   * these entries follow the n*ncol collocation rows of the column */
  for (size_t q = 0; q < n; ++q) {
    Jx[(size_t)c->Jp[q] + n * m] = -1.0;
    Jx[(size_t)c->Jp[n * N * m + q] + n * m] = 1.0;
  }
  if (c->aut)
    for (size_t col = 0; col < colT; ++col)
      Jx[c->Jp[col + 1] - 1] = c->phase[col];
  return 0;
}

static int colloc_Fx(const double *X, const double *p, double *J, void *data) {
  whirl_colloc *c = data;
  int rc = colloc_Fx_sparse(X, p, c->Jx, data);
  if (rc == 0) whirl_system_scatter_dense(&c->sys, c->Jx, J);
  return rc;
}

/* See colloc_impl.h.  The difference's step is that of
 * whirl_system_fd_param; the residual's other terms do not depend on p_k,
 * so a difference of f alone is the difference of the whole residual
 * without its cancellation of x'. */
int colloc_fk_rows(const whirl_colloc *c, colloc_scratch *s, const double *X,
                   const double *p, size_t k, double t, double hT, double *fr) {
  const whirl_problem *pr = c->prob;
  const size_t n = c->n;
  int rc;
  if (pr->jac_p) {
    if ((rc = pr->jac_p(t, s->xc, p, s->Jpar, pr->data)) != 0) return rc;
    for (size_t rr = 0; rr < n; ++rr) fr[rr] = -hT * s->Jpar[rr + n * k];
    return 0;
  }
  whirl_copy_short(s->pw, p, pr->npar);
  if (c->fq >= 0) s->pw[c->fq] = X[c->nx - 1];
  const double pk = s->pw[k], hp = cbrt(DBL_EPSILON) * fmax(1.0, fabs(pk));
  s->pw[k] = pk + hp;
  const double up = s->pw[k];
  if ((rc = pr->rhs(t, s->xc, s->pw, s->f, pr->data)) != 0) return rc;
  s->pw[k] = pk - hp;
  const double dn = s->pw[k];
  if ((rc = pr->rhs(t, s->xc, s->pw, s->f2, pr->data)) != 0) return rc;
  for (size_t rr = 0; rr < n; ++rr) {
    fr[rr] = -hT * (s->f[rr] - s->f2[rr]) / (up - dn);
    if (!isfinite(fr[rr])) return WHIRL_EBADFUNC;
  }
  return 0;
}

/* dF/dp_k.  The forcing frequency also sets T = 2π nu/ω and the time
 * argument t0 + Tτ, so its column is a central difference of the whole
 * residual; any other parameter enters through f only: −h T f_p
 * (colloc_fk_rows: the model's jac_p, or a central difference of f). */
static int colloc_Fp(const double *X, const double *p, size_t k, double *fk,
                     void *data) {
  whirl_colloc *c = data;
  const whirl_problem *pr = c->prob;
  const size_t n = c->n, m = c->ncol, N = c->ntst, np = pr->npar;
  if (k >= np) return WHIRL_EINVAL;
  p = colloc_par(c, X, p);
  if ((int)k == c->fq) { /* its value is X's: F does not depend on p[k] */
    memset(fk, 0, c->nx * sizeof *fk);
    return 0;
  }
  if (!c->aut && (int)k == c->fpar) {
    const double hp = cbrt(DBL_EPSILON) * fmax(1.0, fabs(p[k]));
    int rc;
    double *pw = c->scr[0].pw;
    memcpy(pw, p, np * sizeof *pw);
    pw[k] = p[k] + hp;
    const double up = pw[k];
    if ((rc = colloc_F(X, pw, c->r1, c)) != 0) return rc;
    pw[k] = p[k] - hp;
    const double dn = pw[k];
    if ((rc = colloc_F(X, pw, c->r2, c)) != 0) return rc;
    for (size_t q = 0; q < c->nx; ++q)
      fk[q] = (c->r1[q] - c->r2[q]) / (up - dn);
    return 0;
  }
  const double T = period_of(c, X, p);
  for (size_t i = 0; i < N; ++i) {
    const double h = c->mesh[i + 1] - c->mesh[i];
    for (size_t g = 0; g < m; ++g) {
      colloc_scratch *s = &c->scr[0];
      at_gauss(c, s, X, i, g);
      const double tau = c->mesh[i] + h * c->gs[g];
      int rc = colloc_fk_rows(c, s, X, p, k, c->t0 + T * tau, h * T, fk + n * (i * m + g));
      if (rc != 0) return rc;
    }
  }
  for (size_t q = n * N * m; q < c->nx; ++q) fk[q] = 0.0;
  return 0;
}

/* The model as the integrator sees it for the multipliers: records a
 * recoverable failure (status > 0 or a non-finite value) so the spectrum
 * can hand it on as recoverable instead of the integrator's WHIRL_ESTEP. */
static int colloc_shim_rhs(double t, const double *x, const double *p,
                           double *f, void *data) {
  whirl_colloc *c = data;
  int rc = c->prob->rhs(t, x, p, f, c->prob->data);
  if (rc > 0) c->rhs_fail = rc;
  if (rc == 0)
    for (size_t r = 0; r < c->n; ++r)
      if (!isfinite(f[r])) c->rhs_fail = WHIRL_EBADFUNC;
  return rc;
}

static int colloc_shim_jac(double t, const double *x, const double *p,
                           double *J, void *data) {
  whirl_colloc *c = data;
  int rc = c->prob->jac_x(t, x, p, J, c->prob->data);
  if (rc > 0) c->rhs_fail = rc;
  return rc;
}

/* Floquet multipliers of the orbit through node 0 (whirl/floquet.h): from
 * the monodromy matrix of the condensed collocation equations
 * (colloc_cond.c), or from the variational equations. */
static int colloc_spectrum(const double *X, const double *p, const double *J,
                           double *re, double *im, size_t *mcap, void *data) {
  whirl_colloc *c = data;
  (void)J;
  p = colloc_par(c, X, p);
  const double T = period_of(c, X, p);
  if (!(T > 0) || !isfinite(T)) return 1; /* recoverable, as in F */
  c->rhs_fail = 0;
  int rc;
  if (c->floquet == WHIRL_COLLOC_FLOQUET_CONDENSED) {
    double Mbuf[64], *M = c->n <= 8 ? Mbuf : malloc(c->n * c->n * sizeof *M);
    if (!M) return WHIRL_ENOMEM;
    rc = colloc_cond_monodromy(c, X, p, M);
    if (rc == WHIRL_OK)
      rc = whirl_floquet_from_monodromy(&c->shim, p, c->t0, X,
                                        X + c->n * (c->nnodes - 1), M, c->aut,
                                        re, im, mcap, NULL);
    if (M != Mbuf) free(M);
    if (rc != WHIRL_OK)
      WHIRL_FAIL(c, rc, "Floquet multipliers (condensed collocation): %s",
                 whirl_strerror(rc));
  } else {
    rc = whirl_floquet_multipliers(&c->shim, p, c->t0, X, T, c->aut,
                                   c->floquet_rtol, 0.0, re, im, mcap, NULL,
                                   NULL, c->errmsg, sizeof c->errmsg);
  }
  if (rc != WHIRL_OK && c->rhs_fail != 0) return c->rhs_fail;
  return rc;
}

/* A constant orbit (the start of a branch at a Hopf point) cannot be a
 * phase reference: its derivative vanishes and the phase row with it, so the
 * reference set by whirl_colloc_hopf_start is kept until the orbit has an
 * amplitude. */
static int colloc_accept(const double *X, const double *p, void *data) {
  (void)p;
  whirl_colloc *c = data;
  const size_t n = c->n, nn = c->nnodes * n;
  double spread = 0.0, size = 0.0;
  for (size_t q = 0; q < nn; ++q) {
    spread = fmax(spread, fabs(X[q] - X[q % n]));
    size = fmax(size, fabs(X[q]));
  }
  if (c->aut && c->have_ref && spread <= 1e-12 * (1.0 + size)) return 0;
  if (c->phase_nodes && p) {
    memcpy(c->ref_par, p, c->prob->npar * sizeof *c->ref_par);
    c->ref_T = period_of(c, X, p);
    c->have_ref_par = isfinite(c->ref_T) && c->ref_T > 0.0;
  }
  set_reference(c, X);
  return 0;
}

static int colloc_remap(double *const *v, size_t nv, const double *p,
                        void *data);

/* The system's norm weights: the quadrature weights of the node values
 * on the current mesh (the state's part of a step's norm is its integral,
 * as AUTO-07p's), 1 for the unknowns after them (the period, or the free
 * parameter at a fixed period). */
static int colloc_norm_weights(double *q, void *data) {
  const whirl_colloc *c = data;
  colloc_basis_node_weights_from(c->n, c->ncol, c->ntst, c->mesh, c->wint, q);
  for (size_t i = c->nnodes * c->n; i < c->nx; ++i) q[i] = 1.0;
  return 0;
}

/* ------------------------------------------------------------ alloc */

/* The message of a failed whirl_colloc_alloc in errbuf; evaluates to NULL. */
#define ALLOC_FAIL(...)                              \
  (WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,        \
                "whirl_colloc_alloc: " __VA_ARGS__), \
   NULL)

/* The options' rules: "" when they hold, else why not. */
static void check_options(const whirl_problem *prob, const whirl_colloc_options *o,
                          char *why, size_t len) {
  why[0] = '\0';
  if (o->ntst < 2 || o->ntst > WHIRL_COLLOC_MAX_NTST)
    snprintf(why, len, "need 2 <= NTST <= %d (got %zu)",
             WHIRL_COLLOC_MAX_NTST, o->ntst);
  else if (o->ncol < 2 || o->ncol > COLLOC_MAXCOL)
    snprintf(why, len, "need 2 <= NCOL <= %d (got %zu)", COLLOC_MAXCOL,
             o->ncol);
  else if (o->forcing_param < -1 ||
           (o->forcing_param >= 0 && (size_t)o->forcing_param >= prob->npar))
    snprintf(why, len,
             "forcing_param %d is neither -1 nor a parameter index (npar %zu)",
             o->forcing_param, prob->npar);
  else if (o->forcing_param >= 0 && o->nu < 1)
    snprintf(why, len, "need nu >= 1 for a forced orbit");
  else if (o->forcing_param >= 0 && prob->autonomous)
    /* an autonomous model at an imposed period with no phase condition has a
     * singular Jacobian (every time shift is a solution) */
    snprintf(why, len,
             "forcing_param %d given but model '%s' is autonomous; use -1",
             o->forcing_param, prob->name ? prob->name : "?");
  else if (o->forcing_param < 0 && prob->n < 2)
    snprintf(why, len, "an autonomous model needs n >= 2 for a cycle");
  else if (o->free_param >= 0 &&
           (o->forcing_param >= 0 || (size_t)o->free_param >= prob->npar ||
            !(o->period > 0) || !isfinite(o->period)))
    snprintf(why, len, "a fixed period needs an autonomous orbit, free_param "
             "a parameter index (got %d of npar %zu) and period > 0 (got %g)",
             o->free_param, prob->npar, o->period);
  else if (!isfinite(o->t0) || !(o->floquet_rtol >= 0.0))
    snprintf(why, len, "t0 must be finite and floquet_rtol >= 0");
  else if (o->floquet != WHIRL_COLLOC_FLOQUET_CONDENSED &&
           o->floquet != WHIRL_COLLOC_FLOQUET_VARIATIONAL)
    snprintf(why, len, "floquet must be CONDENSED or VARIATIONAL (got %d)",
             o->floquet);
}

/* The nonzeros of F_x: n*ncol collocation rows per interval holding the
 * node (two at inner mesh points), periodicity at the end nodes, the phase
 * row, and the T column over all collocation rows. */
static size_t count_nonzeros(size_t n, size_t m, size_t N, size_t nnodes, int aut) {
  size_t nnz = n * (size_t)aut * N * m;
  for (size_t j = 0; j < nnodes; ++j) {
    size_t rows = (j % m == 0 && j != 0 && j != nnodes - 1) ? 2 * n * m : n * m;
    if (j == 0 || j == nnodes - 1) ++rows;
    rows += (size_t)aut;
    nnz += n * rows;
  }
  return nnz;
}

/* The work arrays; 0, or -1 out of memory. */
static int alloc_arrays(whirl_colloc *c) {
  const whirl_problem *prob = c->prob;
  const size_t n = c->n, N = c->ntst, nnodes = c->nnodes, nx = c->nx, nnz = c->nnz;
  const size_t np = prob->npar ? prob->npar : 1;
  c->mesh = malloc((N + 1) * sizeof *c->mesh);
  c->rot = calloc(n, sizeof *c->rot);
  c->old_mesh = malloc((N + 1) * sizeof *c->old_mesh);
  c->Jp = malloc((nx + 1) * sizeof *c->Jp);
  c->Ji = malloc(nnz * sizeof *c->Ji);
  c->Jx = malloc(nnz * sizeof *c->Jx);
  c->ref = calloc(nnodes * n, sizeof *c->ref);
  c->phase = calloc(nnodes * n, sizeof *c->phase);
  c->ref_par = calloc(prob->npar ? prob->npar : 1, sizeof *c->ref_par);
  /* one copy a thread: the remap's vectors on the threads */
  c->old_X = malloc(nnodes * n * (size_t)c->nthreads * sizeof *c->old_X);
  c->map_idx = malloc(nnodes * sizeof *c->map_idx);
  c->map_L = malloc(nnodes * (c->ncol + 1) * sizeof *c->map_L);
  c->ref_new = malloc(nnodes * n * sizeof *c->ref_new);
  c->scr = calloc((size_t)c->nthreads, sizeof *c->scr);
  if (!c->scr) return -1;
  for (int t = 0; t < c->nthreads; ++t) {
    colloc_scratch *s = &c->scr[t];
    double **ptrs[] = {&s->xc, &s->dx, &s->f, &s->f2, &s->J, &s->Jpar, &s->work, &s->pw, &s->dT};
    const size_t sizes[] = {n, n, n, n, n * n, n * np, 2 * n, np, n};
    size_t tot = 0;
    for (size_t q = 0; q < sizeof sizes / sizeof *sizes; ++q) tot += sizes[q];
    /* one block a thread, on lines of its own (the threads write it at
     * every Gauss point) */
    s->block = whirl_thread_alloc(1, whirl_thread_stride(tot, sizeof *s->block),
                                  sizeof *s->block);
    if (!s->block) return -1;
    double *q = s->block;
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; ++k) {
      *ptrs[k] = q;
      q += sizes[k];
    }
  }
  c->pq = malloc(np * sizeof *c->pq);
  c->pF = malloc(np * sizeof *c->pF);
  c->r1 = malloc(nx * sizeof *c->r1);
  c->r2 = malloc(nx * sizeof *c->r2);
  if (!c->mesh || !c->old_mesh || !c->Jp || !c->Ji || !c->Jx || !c->ref ||
      !c->phase || !c->ref_par || !c->old_X || !c->ref_new || !c->pq || !c->pF || !c->r1 ||
      !c->r2 || !c->map_idx || !c->map_L) {
    return -1;
  }
  return 0;
}

/* The uniform mesh, Gauss points and weights, the Lagrange basis and its
 * derivatives there, and the m-th derivative of the interpolant. */
static void init_quadrature(whirl_colloc *c) {
  const size_t m = c->ncol, N = c->ntst;
  for (size_t i = 0; i <= N; ++i) c->mesh[i] = (double)i / (double)N;
  c->mesh[N] = 1.0;

  gauss_legendre(m, c->gs, c->gw);
  for (size_t g = 0; g < m; ++g)
    lagrange(m, c->gs[g], c->L + g * (m + 1), c->D + g * (m + 1));
  /* m-th derivative of the interpolant on nodes k/m, in σ */
  colloc_basis_derivative_weights(m, c->dm);
  colloc_basis_lagrange_integrals(m, c->wint);

}

/* The sparsity pattern of F_x, rows sorted within each column. */
static void build_pattern(whirl_colloc *c) {
  const size_t n = c->n, m = c->ncol, N = c->ntst, nnodes = c->nnodes, nx = c->nx;
  const int aut = c->aut;
  size_t pos = 0;
  for (size_t j = 0; j < nnodes; ++j) {
    const size_t i0 = (j % m == 0 && j != 0) ? j / m - 1 : j / m;
    const size_t i1 = j == nnodes - 1 ? N - 1 : j / m;
    for (size_t q = 0; q < n; ++q) {
      c->Jp[n * j + q] = (int)pos;
      for (size_t R = n * i0 * m; R < n * (i1 + 1) * m; ++R)
        c->Ji[pos++] = (int)R;
      if (j == 0 || j == nnodes - 1) c->Ji[pos++] = (int)(n * N * m + q);
      if (aut) c->Ji[pos++] = (int)(nx - 1);
    }
  }
  if (aut) {
    c->Jp[n * nnodes] = (int)pos;
    for (size_t R = 0; R < n * N * m; ++R) c->Ji[pos++] = (int)R;
  }
  c->Jp[nx] = (int)pos;

}

/* The model seen at a node (shim) and the continuation system. */
static void init_system(whirl_colloc *c) {
  const whirl_problem *prob = c->prob;
  const size_t n = c->n;
  const int aut = c->aut;
  c->shim = *prob;
  c->shim.rhs = colloc_shim_rhs;
  c->shim.jac_x = prob->jac_x ? colloc_shim_jac : NULL;
  c->shim.jac_p = NULL;
  c->shim.data = c;

  whirl_system *s = &c->sys;
  s->name = prob->name;
  s->n = c->nx;
  s->npar = prob->npar;
  s->F = colloc_F;
  s->Fx = colloc_Fx;
  s->Fp = colloc_Fp;
  s->nnz = c->nnz;
  s->Jp = c->Jp;
  s->Ji = c->Ji;
  s->Fx_sparse = colloc_Fx_sparse;
  s->nspec = aut ? n - 1 : n;
  s->spectrum = s->nspec ? colloc_spectrum : NULL;
  s->spectrum_kind = WHIRL_SPEC_MULTIPLIERS;
  s->accept = aut ? colloc_accept : NULL;
  s->remap = colloc_remap;
  s->norm_weights = colloc_norm_weights;
  s->bsolver = &colloc_bsolver;
  s->x_names = NULL; /* node-major unknowns have no model names */
  s->p_names = prob->p_names;
  s->data = c;
}

whirl_colloc *whirl_colloc_alloc(const whirl_problem *prob,
                                 const whirl_colloc_options *o, char *errbuf,
                                 size_t errlen) {
  char why[200];
  if (errbuf && errlen) errbuf[0] = '\0';
  if (!prob || !prob->rhs || prob->n == 0)
    return ALLOC_FAIL("model is NULL, has no rhs or n = 0");
  if (!o) return ALLOC_FAIL("no options");
  check_options(prob, o, why, sizeof why);
  if (why[0]) return ALLOC_FAIL("%s", why);

  const size_t n = prob->n, m = o->ncol, N = o->ntst;
  const int aut = o->forcing_param < 0;
  const size_t nnodes = N * m + 1; /* N, m bounded above: no overflow */
  /* sizes first, in floating point so that nothing overflows: at most
   * 2 n m + 2 nonzeros in each of the n nnodes + 1 columns */
  if ((double)n * (double)nnodes + 1.0 >= (double)INT_MAX ||
      (double)n * (double)nnodes * (2.0 * (double)n * (double)m + 3.0) >=
          (double)INT_MAX)
    return ALLOC_FAIL(
        "problem too large for int indices "
        "(reduce NTST, NCOL or the model's dimension)");
  const size_t nx = n * nnodes + (size_t)aut;
  const size_t nnz = count_nonzeros(n, m, N, nnodes, aut);
  if (nx >= (size_t)INT_MAX || nnz >= (size_t)INT_MAX || nx > SIZE_MAX / nx)
    return ALLOC_FAIL("problem too large for int indices");

  whirl_colloc *c = calloc(1, sizeof *c);
  if (!c) return ALLOC_FAIL("out of memory");
  c->prob = prob;
  c->n = n;
  c->ntst = N;
  c->ncol = m;
  c->nnodes = nnodes;
  c->nx = nx;
  c->nnz = nnz;
  c->aut = aut;
  c->fpar = o->forcing_param;
  c->nu = o->nu ? o->nu : 1;
  c->t0 = o->t0;
  c->floquet_rtol = o->floquet_rtol > 0 ? o->floquet_rtol : 1e-11;
  c->floquet = o->floquet;
  c->adapt_every = o->adapt_every;
  c->mesh_jumps = o->mesh_jumps;
  c->phase_nodes = o->phase_nodes;
  c->fq = o->free_param >= 0 ? o->free_param : -1;
  c->Tfix = o->period;
  c->nthreads = whirl_threads_resolve(o->threads);
  whirl_gov_init(&c->gov_F, c->nthreads);
  if (alloc_arrays(c)) {
    whirl_colloc_free(c);
    return ALLOC_FAIL("out of memory");
  }
  init_quadrature(c);
  build_pattern(c);
  init_system(c);
  return c;
}

void whirl_colloc_free(whirl_colloc *c) {
  if (!c) return;
  colloc_bsolver.free(c->spec_ws);
  free(c->mesh);
  free(c->rot);
  free(c->old_mesh);
  free(c->Jp);
  free(c->Ji);
  free(c->Jx);
  free(c->ref);
  free(c->phase);
  free(c->ref_par);
  free(c->old_X);
  free(c->map_idx);
  free(c->map_L);
  free(c->ref_new);
  for (int t = 0; c->scr && t < c->nthreads; ++t) free(c->scr[t].block);
  free(c->scr);
  free(c->pq);
  free(c->pF);
  free(c->r1);
  free(c->r2);
  free(c);
}

const whirl_system *whirl_colloc_system(const whirl_colloc *c) {
  return c ? &c->sys : NULL;
}

size_t whirl_colloc_size(const whirl_colloc *c) { return c ? c->nx : 0; }

void whirl_colloc_pd_operator(const whirl_colloc *c, whirl_fold_operator *op,
                              size_t *ei, size_t *ej, double *ev) {
  const size_t n = c->n, rows = n * c->ntst * c->ncol; /* the periodicity rows follow */
  for (size_t r = 0; r < n; ++r) { /* -1 at x(0) in x(1) - x(0) becomes +1 */
    ei[r] = rows + r;
    ej[r] = r;
    ev[r] = 2.0;
  }
  memset(op, 0, sizeof *op);
  op->na = n * c->nnodes;
  op->ne = n;
  op->ei = ei;
  op->ej = ej;
  op->ev = ev;
  op->point_type = WHIRL_PT_PD;
  op->name = "period-doubling curve";
  op->nstate = n;
  op->ntst = c->ntst;
  op->ncol = c->ncol;
}

const double *whirl_colloc_mesh(const whirl_colloc *c) {
  return c ? c->mesh : NULL;
}

double whirl_colloc_period(const whirl_colloc *c, const double *X,
                           const double *p) {
  if (!c || (c->aut && !X) || (!c->aut && !p)) return NAN;
  return period_of(c, X, p);
}

/* ------------------------------------------------------------ samples */

/* Local cubic interpolation through the four samples around each node time
 * (periodic indices): exact for cubics, O(dt^4), linear in the samples and
 * needs no workspace whatever m is.  Sample k sits at τ = k/m (for a forced
 * model, time t0 + kT/m); T itself only enters X for autonomous models. */
int whirl_colloc_from_samples(whirl_colloc *c, const double *x, size_t m,
                              double T, double *X) {
  if (!c) return WHIRL_EINVAL;
  if (!x || !X || m < 4 || !(T > 0) || !isfinite(T))
    return WHIRL_FAIL(c, WHIRL_EINVAL,
                      "from_samples: need samples, m >= 4 (got %zu) and a "
                      "finite period T > 0 (got %g)",
                      m, T);
  const size_t n = c->n, M = c->ncol, N = c->ntst;
  for (size_t i = 0; i < N; ++i) {
    const double h = c->mesh[i + 1] - c->mesh[i];
    for (size_t k = 0; k <= M; ++k) {
      if (k == M && i + 1 < N) continue; /* shared with the next interval */
      const size_t j = i * M + k;
      double u = (c->mesh[i] + h * (double)k / (double)M) * (double)m;
      if (j == c->nnodes - 1) u = (double)m; /* τ = 1 is sample 0 again */
      double fl = floor(u);
      double s = u - fl;
      size_t k0 = (size_t)fl % m;
      const size_t im1 = (k0 + m - 1) % m, ip1 = (k0 + 1) % m,
                   ip2 = (k0 + 2) % m;
      const double wm1 = -s * (s - 1.0) * (s - 2.0) / 6.0;
      const double w0 = (s + 1.0) * (s - 1.0) * (s - 2.0) / 2.0;
      const double w1 = -(s + 1.0) * s * (s - 2.0) / 2.0;
      const double w2 = (s + 1.0) * s * (s - 1.0) / 6.0;
      /* a rotation: the samples less the ramp rot·τ are periodic (sample
       * k at τ = k/m; the indices wrap by a whole period) */
      const double tj = u / (double)m, ts[4] = {(double)im1 / (double)m, (double)k0 / (double)m,
                                                (double)ip1 / (double)m, (double)ip2 / (double)m};
      for (size_t r = 0; r < n; ++r)
        X[n * j + r] = wm1 * (x[n * im1 + r] - c->rot[r] * ts[0]) +
                       w0 * (x[n * k0 + r] - c->rot[r] * ts[1]) +
                       w1 * (x[n * ip1 + r] - c->rot[r] * ts[2]) +
                       w2 * (x[n * ip2 + r] - c->rot[r] * ts[3]) + c->rot[r] * tj;
    }
  }
  if (c->aut) {
    X[c->nx - 1] = T;
    set_reference(c, X);
  }
  return WHIRL_OK;
}

int whirl_colloc_eval(const whirl_colloc *c, const double *X, double tau,
                      double *x) {
  if (!c || !X || !x || !isfinite(tau)) return WHIRL_EINVAL;
  eval_poly(c->n, c->ntst, c->ncol, c->mesh, X, tau, x);
  return WHIRL_OK;
}

/* ------------------------------------------------------------ adaptation */

/* Equidistribute the piecewise constant density E_i = sum_r |x_r^(NCOL)|^
 * {1/(NCOL+1)} on interval i (x^(NCOL) of the collocation polynomial, a
 * constant per interval): the new mesh points are where the monotone,
 * piecewise linear integral Q(τ) reaches Q(1) k/NTST.  (AUTO's IAD differences
 * these constants once more to estimate x^(NCOL+1); the density here is the
 * one the header documents.)  X (and the phase reference) are then the old
 * piecewise polynomials at the new nodes. */
/* A new mesh equidistributing |x^(NCOL)|^{1/(NCOL+1)} over the orbit X
 * (Russell & Christiansen 1978, as AUTO's IAD); the old mesh is kept in
 * old_mesh for map_nodes.  Returns 1 when the mesh changed, 0 when it is
 * kept (a constant orbit), WHIRL_EINVAL for a non-finite X. */
static int new_mesh(whirl_colloc *c, const double *X) {
  const size_t N = c->ntst;
  memcpy(c->old_mesh, c->mesh, (N + 1) * sizeof *c->mesh);
  /* E, Q: N, N + 1 <= nx; the jumps' scratch D (n N) is old_X, which
   * map_nodes fills only after the mesh is made */
  const int rc = c->mesh_jumps
                     ? colloc_basis_new_mesh_jumps(c->n, c->ncol, N, 1, c->dm, X,
                                                   c->old_mesh, c->mesh, c->r1, c->r2,
                                                   c->old_X)
                     : colloc_basis_new_mesh(c->n, c->ncol, N, c->dm, X, c->old_mesh,
                                             c->mesh, c->r1, c->r2);
  if (rc <= -1 - (int)N)
    return WHIRL_FAIL(c, WHIRL_EINVAL, "mesh adaptation: interval %d degenerate",
                      -1 - (int)N - rc);
  if (rc < 0)
    return WHIRL_FAIL(c, WHIRL_EINVAL,
                      "mesh adaptation: the orbit is not finite in interval %d", -1 - rc);
  if (rc == 1) c->last_ws = NULL; /* factorisations on the old mesh are not reused */
  return rc;
}

/* The node values of v (a solution or a direction: the map is linear)
 * from the piecewise polynomial on old_mesh to the nodes of mesh, in place;
 * entries past the nodes (the period) are left as they are. */
static void map_nodes(whirl_colloc *c, double *v) {
  colloc_basis_map_nodes(c->n, c->ncol, c->ntst, c->old_mesh, c->mesh, c->old_X, v);
}

/* The phase reference onto the new mesh. */
static void map_reference(whirl_colloc *c) {
  if (!(c->aut && c->have_ref)) return;
  map_nodes(c, c->ref);
  set_reference(c, c->ref);
}

const char *whirl_colloc_errmsg(const whirl_colloc *c) {
  return c ? c->errmsg : "whirl_colloc: NULL object";
}

size_t whirl_colloc_adaptations(const whirl_colloc *c) {
  return c ? c->adaptations : 0;
}

int whirl_colloc_adapt(whirl_colloc *c, double *X) {
  if (!c || !X) return WHIRL_EINVAL;
  int rc = new_mesh(c, X);
  if (rc <= 0) return rc;
  map_nodes(c, X);
  map_reference(c);
  return WHIRL_OK;
}

/* The system's remap hook: a new mesh every adapt_every accepted points,
 * with the current point, tangent and previous points carried over. */
static int colloc_remap(double *const *v, size_t nv, const double *p,
                        void *data) {
  (void)p;
  whirl_colloc *c = data;
  if (c->adapt_every <= 0 || ++c->since_adapt < c->adapt_every) return 0;
  c->since_adapt = 0;
  int rc = new_mesh(c, v[0]);
  if (rc <= 0) return rc;
  /* one plan (each new node's old interval and basis) for every vector:
   * the same values as map_nodes, without a search and a basis a node
   * and vector (a fiftieth of demo pla's run) */
  const size_t N = c->ntst, m = c->ncol;
  colloc_basis_map_plan(m, N, c->old_mesh, c->mesh, c->map_idx, c->map_L);
  const int with_ref = c->aut && c->have_ref;
  double *const own[1] = {c->ref};
  colloc_basis_map_many(c->n, m, N, c->map_idx, c->map_L, c->old_X, v, nv, own,
                        (size_t)with_ref,
                        colloc_threads(c) > 1 ? whirl_gov_current(&c->gov_F) : 1);
  if (with_ref) set_reference(c, c->ref);
  ++c->adaptations;
  return 1;
}

/* ------------------------------------------------------------ PD switch */

/* The model and its variational equations y = (x, φ):
 * x' = f(t, x, p), φ' = f_x(t, x, p) φ. */
typedef struct pd_aug {
  const whirl_problem *prob;
  double *J, *work; /* n*n, 2n */
} pd_aug;

static int pd_aug_rhs(double t, const double *y, const double *p, double *f,
                      void *data) {
  const pd_aug *a = data;
  const whirl_problem *pr = a->prob;
  const size_t n = pr->n;
  int rc = pr->rhs(t, y, p, f, pr->data);
  if (rc != 0) return rc;
  rc = pr->jac_x ? pr->jac_x(t, y, p, a->J, pr->data)
                 : whirl_fd_jac_x(pr, t, y, p, a->J, a->work);
  if (rc != 0) return rc;
  for (size_t r = 0; r < n; ++r) {
    double s = 0.0;
    for (size_t q = 0; q < n; ++q) s += a->J[r + n * q] * y[n + q];
    f[n + r] = s;
  }
  return 0;
}

/* φ at the increasing times t0 + s[k], s[k] ∈ [0, T], integrating from
 * (t0, y0): out[n*k ...] = sign φ(t0 + s[k]); y scratch[2n]. */
static int pd_sample_phi(whirl_ode *ode, size_t n, const double *y0,
                         double t0, double T, const double *s, size_t cnt,
                         double sign, double *out, double *y) {
  int rc = whirl_ode_reset(ode, t0, y0);
  if (rc != WHIRL_OK) return rc;
  for (size_t k = 0; k < cnt; ++k) {
    const double t = t0 + s[k];
    if (s[k] <= 0.0) {
      memcpy(y, y0, 2 * n * sizeof *y);
    } else {
      while (whirl_ode_t(ode) < t)
        if ((rc = whirl_ode_step(ode, t0 + T)) != WHIRL_OK) return rc;
      if ((rc = whirl_ode_dense(ode, t, y)) != WHIRL_OK) return rc;
    }
    for (size_t r = 0; r < n; ++r) out[n * k + r] = sign * y[n + r];
  }
  return WHIRL_OK;
}

int whirl_colloc_pd_switch(const whirl_colloc *c, const double *X,
                           const double *p, whirl_colloc *c2, double *X2,
                           double *D2) {
  if (!c2 || c2 == c) return WHIRL_EINVAL;
  if (!c || !X || !p || !X2 || !D2)
    return WHIRL_FAIL(c2, WHIRL_EINVAL, "PD switch: NULL argument");
  const whirl_problem *pr = c->prob;
  const size_t n = c->n;
  if (c2->n != n || c2->prob->npar != pr->npar || c2->aut != c->aut ||
      c2->fpar != c->fpar || c2->t0 != c->t0 ||
      (!c->aut && c2->nu != 2 * c->nu))
    return WHIRL_FAIL(c2, WHIRL_EINVAL,
                      "PD switch: the doubled orbit's object does not match "
                      "(model, forcing or nu = 2 nu)");
  const double T = period_of(c, X, p);
  if (!(T > 0) || !isfinite(T))
    return WHIRL_FAIL(c2, WHIRL_EINVAL, "PD switch: period %g", T);
  for (size_t q = 0; q < c->nx; ++q)
    if (!isfinite(X[q]))
      return WHIRL_FAIL(c2, WHIRL_EINVAL, "PD switch: X[%zu] not finite", q);

  const size_t N = c->ntst, m = c->ncol, N2 = c2->ntst, m2 = c2->ncol;
  const size_t nn2 = c2->nnodes, nx2 = c2->nx;
  double *buf = malloc((2 * n * n + 9 * n + 2 * nn2) * sizeof *buf);
  if (!buf) return WHIRL_FAIL(c2, WHIRL_ENOMEM, "PD switch: out of memory");
  double *M = buf, *Ja = M + n * n, *v = Ja + n * n, *xT = v + n,
         *y0 = xT + n, *y = y0 + 2 * n, *wk = y + 2 * n, *tau2 = wk + 2 * n,
         *sq = tau2 + nn2;
  whirl_ode *ode = NULL;
  pd_aug aug = {pr, Ja, wk};
  whirl_problem ap = *pr;
  size_t half = 0; /* c2's nodes with t = 2T τ2 <= T */
  double nrm = 0.0;
  int rc;

  /* the doubled orbit on c2's nodes */
  c2->last_ws = NULL; /* c2's mesh changes */
  if (N2 == 2 * N && m2 == m) {
    for (size_t i = 0; i <= N; ++i) {
      c2->mesh[i] = 0.5 * c->mesh[i];
      c2->mesh[N + i] = 0.5 + 0.5 * c->mesh[i];
    }
    c2->mesh[N] = 0.5;
    c2->mesh[N2] = 1.0;
    for (size_t j2 = 0; j2 < nn2; ++j2) {
      const size_t j = j2 <= N * m ? j2 : j2 - N * m;
      memcpy(X2 + n * j2, X + n * j, n * sizeof *X2);
      if (j2 > N * m) /* a rotation turns on over the second period */
        for (size_t r = 0; r < n; ++r) X2[n * j2 + r] += c->rot[r];
    }
  }
  for (size_t r = 0; r < n; ++r) c2->rot[r] = 2.0 * c->rot[r];
  for (size_t i = 0; i < N2; ++i) {
    const double h = c2->mesh[i + 1] - c2->mesh[i];
    for (size_t k = 0; k < m2; ++k)
      tau2[i * m2 + k] = c2->mesh[i] + h * (double)k / (double)m2;
  }
  tau2[nn2 - 1] = 1.0;
  if (!(N2 == 2 * N && m2 == m))
    for (size_t j2 = 0; j2 < nn2; ++j2) {
      double t = 2.0 * tau2[j2];
      const int second = t > 1.0;
      if (second) t -= 1.0;
      eval_poly(n, N, m, c->mesh, X, t, X2 + n * j2);
      for (size_t r = 0; second && r < n; ++r) X2[n * j2 + r] += c->rot[r];
    }
  if (c2->aut) X2[nx2 - 1] = 2.0 * T;

  /* the Floquet eigenvector of the multiplier −1 at τ = 0 */
  rc = whirl_ode_monodromy(pr, p, c->t0, X, T, c->floquet_rtol, 1e-13, xT, M,
                           NULL, NULL, 0);
  if (rc == WHIRL_OK) rc = whirl_floquet_real_eigvec(n, M, -1.0, v);
  if (rc != WHIRL_OK) goto done;

  /* φ at c2's node times t = 2T τ2: φ(t) on [0, T], −φ(t − T) beyond */
  ap.name = "pd-variational";
  ap.n = 2 * n;
  ap.rhs = pd_aug_rhs;
  ap.jac_x = NULL;
  ap.jac_p = NULL;
  ap.x_names = NULL;
  ap.data = &aug;
  ode = whirl_ode_alloc(&ap, p);
  if (!ode) {
    rc = WHIRL_ENOMEM;
    goto done;
  }
  rc = whirl_ode_set_tolerances(ode, c->floquet_rtol, 1e-13);
  if (rc != WHIRL_OK) goto done;
  memcpy(y0, X, n * sizeof *y0);
  memcpy(y0 + n, v, n * sizeof *y0);
  while (half < nn2 && 2.0 * tau2[half] <= 1.0) {
    sq[half] = fmin(2.0 * T * tau2[half], T);
    ++half;
  }
  for (size_t j2 = half; j2 < nn2; ++j2)
    sq[j2] = fmin(fmax(2.0 * T * tau2[j2] - T, 0.0), T);
  rc = pd_sample_phi(ode, n, y0, c->t0, T, sq, half, 1.0, D2, y);
  if (rc == WHIRL_OK && half < nn2)
    rc = pd_sample_phi(ode, n, y0, c->t0, T, sq + half, nn2 - half, -1.0,
                       D2 + n * half, y);
  if (rc != WHIRL_OK) goto done;
  for (size_t q = n * nn2; q <= nx2; ++q) D2[q] = 0.0; /* T, parameter */
  for (size_t q = 0; q < n * nn2; ++q) nrm += D2[q] * D2[q];
  nrm = sqrt(nrm);
  if (!(nrm > 0) || !isfinite(nrm)) {
    rc = WHIRL_EBADFUNC;
    goto done;
  }
  for (size_t q = 0; q < n * nn2; ++q) D2[q] /= nrm;
  if (c2->aut) set_reference(c2, X2);
  rc = WHIRL_OK;
done:
  if (rc != WHIRL_OK) WHIRL_FAIL(c2, rc, "PD switch: %s", whirl_strerror(rc));
  whirl_ode_free(ode);
  free(buf);
  return rc;
}

/* ------------------------------------------------------------ restart */

int whirl_colloc_set_mesh(whirl_colloc *c, const double *tau) {
  if (!c) return WHIRL_EINVAL;
  if (!tau) return WHIRL_FAIL(c, WHIRL_EINVAL, "set_mesh: no mesh");
  const size_t N = c->ntst;
  if (tau[0] != 0.0 || tau[N] != 1.0)
    return WHIRL_FAIL(c, WHIRL_EINVAL,
                      "the mesh must run from 0 to 1 (got %g .. %g)", tau[0],
                      tau[N]);
  for (size_t k = 1; k <= N; ++k)
    if (!(tau[k] > tau[k - 1]) || !isfinite(tau[k]))
      return WHIRL_FAIL(c, WHIRL_EINVAL,
                        "the mesh is not increasing at point %zu", k);
  memcpy(c->mesh, tau, (N + 1) * sizeof *tau);
  c->last_ws = NULL;
  return WHIRL_OK;
}

/* The node part of V: the piecewise polynomial Vold (nold intervals of
 * degree mold over old_mesh) at c's nodes (AUTO's INTERP). */
static void interp_nodes(const whirl_colloc *c, size_t nold, size_t mold,
                         const double *old_mesh, const double *Vold, double *V) {
  const size_t n = c->n, M = c->ncol;
  const double *mesh = c->mesh;
  for (size_t j = 0; j < c->nnodes; ++j) {
    const size_t i = j / M, k = j % M;
    const double tau = j == c->nnodes - 1 ? 1.0
                                          : mesh[i] + (mesh[i + 1] - mesh[i]) * (double)k /
                                                          (double)M;
    colloc_basis_eval_poly(n, nold, mold, old_mesh, Vold, tau, V + n * j);
  }
}

int whirl_colloc_adapt_from(whirl_colloc *c, size_t nold, size_t mold,
                            const double *old_mesh, const double *Xold, double *X) {
  if (!c) return WHIRL_EINVAL;
  char why[160];
  double *mesh = malloc((c->ntst + 1) * sizeof *mesh);
  int rc = colloc_basis_adapt_mesh(c->n, mold, nold, 1, old_mesh, Xold, c->ntst, mesh, why,
                                   sizeof why);
  rc = rc ? WHIRL_FAIL(c, rc, "adapt_from: %s", why) : whirl_colloc_set_mesh(c, mesh);
  free(mesh);
  if (rc == WHIRL_OK) interp_nodes(c, nold, mold, old_mesh, Xold, X);
  return rc;
}

int whirl_colloc_interp_from(whirl_colloc *c, size_t nold, size_t mold,
                             const double *old_mesh, const double *Vold, double *V) {
  if (!c) return WHIRL_EINVAL;
  if (!old_mesh || !Vold || !V || nold < 1 || mold < 1 || mold > COLLOC_BASIS_MAXCOL ||
      old_mesh[0] != 0.0 || old_mesh[nold] != 1.0)
    return WHIRL_FAIL(c, WHIRL_EINVAL, "interp_from: need a function on %zu intervals "
                      "of degree %zu (1 to %d) over a mesh from 0 to 1", nold, mold,
                      COLLOC_BASIS_MAXCOL);
  interp_nodes(c, nold, mold, old_mesh, Vold, V);
  return WHIRL_OK;
}

int whirl_colloc_set_reference(whirl_colloc *c, const double *X) {
  if (!c) return WHIRL_EINVAL;
  if (!X) return WHIRL_FAIL(c, WHIRL_EINVAL, "set_reference: no orbit");
  if (c->aut) set_reference(c, X);
  return WHIRL_OK;
}

/* ------------------------------------------------------------ Hopf start */

/* AUTO's first phase condition from a Hopf point (STHOPF, PHASE = nodes):
 * ∫ <x − x0, u'> by the nodes' weights, u' = −(a sin 2πτ + b cos 2πτ) the
 * eigenfunction's derivative, exact.  The reference stays x0 + D (set by
 * whirl's rule before), so phase0 = <phase, D> makes <phase, X − ref> +
 * phase0 = <phase, X − x0>; and until the first accepted orbit sets the
 * reference's parameters, a new mesh takes whirl's rule on x0 + D. */
static void hopf_phase_at_nodes(whirl_colloc *c, const double *D, const double *a,
                                const double *b) {
  const size_t n = c->n, m = c->ncol;
  double wi[COLLOC_MAXCOL + 1];
  node_int_weights(c, wi);
  memset(c->phase, 0, c->nnodes * n * sizeof *c->phase);
  for (size_t i = 0; i < c->ntst; ++i) {
    const double h = c->mesh[i + 1] - c->mesh[i];
    for (size_t k = 0; k <= m; ++k) {
      const double tau = c->mesh[i] + h * (double)k / (double)m;
      const double cs = cos(2.0 * WHIRL_PI * tau), sn = sin(2.0 * WHIRL_PI * tau);
      for (size_t r = 0; r < n; ++r)
        c->phase[n * (i * m + k) + r] -= h * wi[k] * (a[r] * sn + b[r] * cs);
    }
  }
  double s = 0.0;
  for (size_t q = 0; q < c->nnodes * n; ++q) s += c->phase[q] * D[q];
  c->phase0 = s;
  c->have_ref_par = 0;
}

/* At a Hopf point x0 of the model (J = f_x(x0) has eigenvalues ±iω), the
 * periodic orbits are x0 + s Re(φ e^{2πiτ}) + O(s²) with period 2π/ω + O(s)
 * (Hopf's theorem; AUTO-07p starts IPS = 2 from an HB label the same way).
 * φ = a + ib solves (J − iωI)φ = 0, i.e. the real 2n system
 *     [ J   ωI ] [a]   [0]
 *     [−ωI  J  ] [b] = [0],
 * whose null vectors come from the SVD.  X is the constant orbit x0 with
 * T = 2π/ω, D the unit direction a cos 2πτ − b sin 2πτ at the nodes (zero
 * period and parameter entries), and the phase reference is x0 + D, so the
 * phase condition fixes the rotation of φ.  ω: the eigenvalue pair of J
 * closest to the imaginary axis. */
int whirl_colloc_hopf_start(whirl_colloc *c, const double *x0,
                            const double *p, double *X, double *D,
                            double *omega) {
  return whirl_colloc_hopf_start_at(c, x0, p, 0.0, X, D, omega);
}

int whirl_colloc_hopf_start_at(whirl_colloc *c, const double *x0,
                               const double *p, double omega_want, double *X,
                               double *D, double *omega) {
  if (!c) return WHIRL_EINVAL;
  if (!x0 || !p || !X || !D)
    return WHIRL_FAIL(c, WHIRL_EINVAL, "Hopf start: NULL argument");
  if (!c->aut)
    return WHIRL_FAIL(c, WHIRL_EINVAL,
                      "Hopf start: the model is forced, not autonomous");
  const size_t n = c->n, nn = 2 * n;
  const whirl_problem *pr = c->prob;
  double *buf = malloc((n * n + 2 * n + nn * nn + 2 * nn + 2) * sizeof *buf);
  whirl_eig *e = whirl_eig_alloc(n);
  int rc = WHIRL_OK;
  if (!buf || !e) {
    rc = WHIRL_ENOMEM;
    goto done;
  }
  double *J = buf, *re = J + n * n, *im = re + n, *A = im + n, *V = A + nn * nn,
         *sv = V + nn * 2;
  rc = pr->jac_x ? pr->jac_x(c->t0, x0, p, J, pr->data)
                 : whirl_fd_jac_x(pr, c->t0, x0, p, J, A);
  if (rc != 0) {
    rc = rc < 0 ? WHIRL_EUSER : WHIRL_EDOMAIN;
    goto done;
  }
  rc = whirl_eig_compute(e, J, re, im);
  if (rc != WHIRL_OK) goto done;
  /* the pair nearest the imaginary axis, or nearest i omega_want */
  double w = 0.0, best = HUGE_VAL;
  for (size_t k = 0; k < n; ++k) {
    const double dist = omega_want > 0 ? hypot(re[k], im[k] - omega_want) : fabs(re[k]);
    if (im[k] > 0 && dist < best) best = dist, w = im[k];
  }
  if (!(w > 0)) {
    rc = WHIRL_FAIL(c, WHIRL_EINVAL,
                    "Hopf start: f_x has no complex pair (not a Hopf point)");
    goto done;
  }
  /* u(τ) = sin(2πτ) v1 + cos(2πτ) v2 solves u' = f_x u / ω when
   * [-ωI f_x; f_x ωI] (v1; v2) = 0: a null space of dimension two (the
   * phase), from which the pivoted elimination takes AUTO-07p's vector
   * (STHOPF), so orbits start in AUTO's phase and meet AUTO's meshes */
  memset(A, 0, nn * nn * sizeof *A);
  for (size_t j = 0; j < n; ++j)
    for (size_t i = 0; i < n; ++i) {
      A[i + nn * (n + j)] = J[i + n * j];
      A[(n + i) + nn * j] = J[i + n * j];
    }
  for (size_t i = 0; i < n; ++i) {
    A[i + nn * i] = -w;
    A[(n + i) + nn * (n + i)] = w;
  }
  (void)sv;
  rc = whirl_null_vector_pivoted(nn, nn, 2, A, V);
  if (rc != WHIRL_OK) goto done;
  for (size_t i = 0; i < n; ++i) { /* D = a cos - b sin: a = v2, b = -v1 */
    const double v1 = V[i];
    V[i] = V[n + i];
    V[n + i] = -v1;
  }
  const double *a = V, *b = V + n;
  double nrm = 0.0;
  for (size_t j = 0; j < c->nnodes; ++j) {
    size_t i = j / c->ncol, k = j % c->ncol;
    double tau = j == c->nnodes - 1
                     ? 1.0
                     : c->mesh[i] + (c->mesh[i + 1] - c->mesh[i]) *
                                        (double)k / (double)c->ncol;
    double cs = cos(2.0 * WHIRL_PI * tau), sn = sin(2.0 * WHIRL_PI * tau);
    for (size_t r = 0; r < n; ++r) {
      X[n * j + r] = x0[r];
      D[n * j + r] = a[r] * cs - b[r] * sn;
      nrm += D[n * j + r] * D[n * j + r];
    }
  }
  nrm = sqrt(nrm);
  if (!(nrm > 0) || !isfinite(nrm)) {
    rc = WHIRL_EBADFUNC;
    goto done;
  }
  const size_t nd = n * c->nnodes;
  for (size_t q = 0; q < nd; ++q) D[q] /= nrm;
  X[c->nx - 1] = 2.0 * WHIRL_PI / w;
  D[c->nx - 1] = 0.0;
  D[c->nx] = 0.0;
  for (size_t q = 0; q < nd; ++q) c->ref_new[q] = X[q] + D[q];
  set_reference(c, c->ref_new); /* whirl's rule on x0 + D */
  if (c->phase_nodes) hopf_phase_at_nodes(c, D, a, b);
  if (omega) *omega = w;
done:
  if (rc != WHIRL_OK && rc != WHIRL_EINVAL)
    WHIRL_FAIL(c, rc, "Hopf start: %s", whirl_strerror(rc));
  whirl_eig_free(e);
  free(buf);
  return rc;
}

/* Rotations (AUTO-07p bvp.f90, SETRTN; periodic.f90, BCPS): a component
 * whose jump over one period is 2 pi k, k = nint(jump / 2 pi) != 0, is an
 * angle that turns k times; the periodicity condition becomes
 * x(1) - x(0) = 2 pi k for it.  From the jumps jump[n]; the number of
 * rotating components. */
size_t whirl_colloc_set_rotations(whirl_colloc *c, const double *jump) {
  size_t k = 0;
  for (size_t i = 0; c && jump && i < c->n; ++i) {
    const double t = nearbyint(jump[i] / (2.0 * WHIRL_PI));
    c->rot[i] = isfinite(t) ? 2.0 * WHIRL_PI * t : 0.0;
    k += c->rot[i] != 0.0;
  }
  return k;
}

const double *whirl_colloc_rotations(const whirl_colloc *c) { return c ? c->rot : NULL; }

size_t whirl_colloc_rotations_of(whirl_colloc *c, const double *X) {
  if (!c || !X) return 0;
  double jump[64] = {0};
  double *j = c->n <= 64 ? jump : malloc(c->n * sizeof *j);
  if (!j) return 0;
  for (size_t i = 0; i < c->n; ++i) j[i] = X[c->n * (c->nnodes - 1) + i] - X[i];
  const size_t k = whirl_colloc_set_rotations(c, j);
  if (j != jump) free(j);
  return k;
}

/* lib/systems/colloc_cond.c — the structured linear solver of periodic
 * collocation (whirl_system bsolver): the condensation of parameters of
 * cond_elim.c with the rows of an orbit — the collocation rows in the node
 * values, the period T (autonomous orbits) and p_k; the periodicity rows
 * x_N − x_0 as the end rows; the phase condition (autonomous) and the
 * core's r as the border rows — and the monodromy matrix of the condensed
 * collocation equations (AUTO-07p's Floquet multipliers).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/status.h>
#include <whirl/system.h>

#include "colloc_impl.h"
#include "cond_elim.h"

/* F's collocation rows at Gauss point g of interval i into F, after
 * colloc_gauss_jac there: from the f its dF/dT evaluated (s->f: an
 * autonomous model at a free period), else from an evaluation of its own
 * (the residual's, colloc.c). */
static int fill_F_rows(whirl_colloc *c, colloc_scratch *s, const double *p, double T,
                       size_t i, size_t g, int shared, double *F) {
  const double h = c->mesh[i + 1] - c->mesh[i];
  if (!shared) {
    const double tau = c->mesh[i] + h * c->gs[g];
    const int rc = c->prob->rhs(c->t0 + T * tau, s->xc, p, s->f2, c->prob->data);
    if (rc != 0) return rc;
  }
  colloc_residual_rows(c, s, i, g, h, T, shared ? s->f : s->f2, F);
  return 0;
}

/* One interval's collocation rows at (X, p): rows g n + rr of block Wi,
 * columns [interior | x_i | x_{i+1} | T? | p_k]; dF/dp_k from the model's
 * f_p into fk when fk_loop; F's rows into cond_F(w) when it is set. */
static int fill_interval(whirl_colloc *c, colloc_scratch *s, cond_ws *w,
                         const double *X, const double *p, double T, size_t i,
                         int mode, int fk_loop, size_t k) {
  const int mono = mode == COND_FILL_MONO;
  const size_t n = c->n, m = c->ncol, ni = n * (m - 1), wc = cond_block_ld(w);
  const size_t ng = c->aut ? 2 : 1;
  double *Wi = cond_block(w, i), *fk = cond_fk(w);
  const double h = c->mesh[i + 1] - c->mesh[i], hT = h * T;
  double *dT = s->dT, *F = cond_F(w);
  /* colloc_gauss_jac's dF/dT leaves f at the point in s->f */
  const int shared = c->aut && !mono && c->fq < 0 && c->prob->autonomous;
  for (size_t g = 0; g < m; ++g) {
    int rc = colloc_gauss_jac(c, s, X, p, T, i, g, c->aut && !mono ? dT : NULL);
    if (rc != 0) return rc;
    if (F && (rc = fill_F_rows(c, s, p, T, i, g, shared, F)) != 0) return rc;
    if (fk_loop) {
      const double t = c->t0 + T * (c->mesh[i] + h * c->gs[g]);
      if ((rc = colloc_fk_rows(c, s, X, p, k, t, h * T, fk + n * (i * m + g))) != 0) return rc;
    }
    const double *l = c->L + g * (m + 1), *dl = c->D + g * (m + 1);
    for (size_t rr = 0; rr < n; ++rr) {
      double *a = Wi + (g * n + rr) * wc;
      for (size_t kk = 0; kk <= m; ++kk) {
        double *ak = a + (kk == 0 ? ni : kk == m ? ni + n : (kk - 1) * n);
        const double lk = l[kk];
        for (size_t q = 0; q < n; ++q) ak[q] = -lk * (hT * s->J[rr + n * q]);
        ak[rr] += dl[kk];
      }
      double *ag = a + ni + 2 * n;
      if (mono) {
        for (size_t e = 0; e < ng; ++e) ag[e] = 0.0;
      } else {
        if (c->aut) ag[0] = dT[rr];
        ag[ng - 1] = fk[n * (i * m + g) + rr];
      }
    }
  }
  return 0;
}

/* Before the intervals: the period, and dF/dp_k — in each interval's fill
 * (colloc_fk_rows) when the parameter enters through f only, else by the system
 * (forcing frequency: T and the time argument depend on it too; a fixed
 * period's free parameter, from X: its column 0). */
static int colloc_fill_begin(cond_ws *w, const double *X, const double *p,
                             size_t k, int mode) {
  whirl_colloc *c = cond_sys(w);
  const int full = mode == COND_FILL_FULL;
  const size_t n = c->n, N = c->ntst, m = c->ncol;
  double *fk = cond_fk(w);
  c->fill_T = colloc_period_of(c, X, p);
  c->fill_X = X;
  if (!(c->fill_T > 0) || !isfinite(c->fill_T)) return 1; /* recoverable, as F */
  c->fill_fk_loop = full && !(!c->aut && (int)k == c->fpar) && (int)k != c->fq;
  if (full && !c->fill_fk_loop) {
    int rc = whirl_system_param(&c->sys, X, p, k, fk, cond_work(w));
    if (rc != 0) return rc;
  }
  if (c->fill_fk_loop) memset(fk + n * N * m, 0, (c->nx - n * N * m) * sizeof *fk);
  return 0;
}

/* Interval i, on thread t's scratch (cond_elim.c's parallel loop). */
static int colloc_fill_one(cond_ws *w, const double *X, const double *p,
                           size_t k, int mode, size_t i, int t) {
  whirl_colloc *c = cond_sys(w);
  return fill_interval(c, &c->scr[t], w, X, p, c->fill_T, i, mode,
                       c->fill_fk_loop, k);
}

/* After the intervals: the first failure, or F's end rows when the fill
 * makes F (cond_factor_F). */
static int colloc_fill_end(cond_ws *w, size_t bad, int status) {
  whirl_colloc *c = cond_sys(w);
  if (bad < c->ntst) return status;
  if (cond_F(w)) colloc_end_rows(c, c->fill_X, cond_F(w));
  return 0;
}

/* The phase condition (autonomous, t = 0) with the current reference, or
 * the core's r. */
static const double *colloc_border(cond_ws *w, size_t t, const double *r,
                                   double *g) {
  whirl_colloc *c = cond_sys(w);
  const size_t nx = c->nx;
  if (c->aut && t == 0) {
    g[0] = 0.0;                  /* T */
    g[1] = cond_fk(w)[nx - 1];   /* p_k */
    return c->phase;
  }
  if (c->aut) g[0] = r[nx - 1];
  g[c->aut ? 1 : 0] = r[nx];
  return r;
}

/* The phase condition's node entries, fixed by the reference between
 * factorisations: eliminated in the loop over the intervals. */
static const double *colloc_border_early(cond_ws *w, size_t t) {
  const whirl_colloc *c = cond_sys(w);
  return c->aut && t == 0 ? c->phase : NULL;
}

/* Periodicity x_N − x_0 (the rotations are constants). */
static void colloc_end_row(cond_ws *w, size_t e, double *a) {
  const whirl_colloc *c = cond_sys(w);
  const size_t n = c->n, ng = c->aut ? 2 : 1;
  memset(a, 0, (2 * n + ng) * sizeof *a);
  a[e] = -1.0;
  a[n + e] = 1.0;
  a[2 * n + ng - 1] = cond_fk(w)[n * c->ntst * c->ncol + e];
}

static const cond_ops colloc_ops = {NULL,           colloc_border,   colloc_end_row,
                                    colloc_fill_begin, colloc_fill_one, colloc_fill_end,
                                    colloc_border_early};

static void *bs_alloc(void *data) {
  whirl_colloc *c = data;
  const size_t gcol[2] = {c->aut ? c->nx - 1 : c->nx, c->nx};
  const int blab[2] = {c->aut ? (int)c->nx - 1 : (int)c->nx, (int)c->nx};
  const cond_shape s = {c->n, c->ncol, c->ntst, c->nx, c->aut ? 2 : 1,
                        c->aut ? 2 : 1, c->prob->npar,
                        c->aut ? gcol : gcol + 1, c->aut ? blab : blab + 1,
                        colloc_threads(c)};
  return cond_alloc(&s, &colloc_ops, c);
}

static void bs_free(void *ws) {
  cond_ws *w = ws;
  if (!w) return;
  whirl_colloc *c = cond_sys(w);
  if (c->last_ws == w) c->last_ws = NULL;
  cond_free(w);
}

static int bs_factor(void *ws, const double *X, const double *p, size_t k,
                     const double *r) {
  whirl_colloc *c = cond_sys(ws);
  p = colloc_par(c, X, p); /* a fixed period: its free parameter from X */
  const int rc = cond_factor(ws, X, p, k, r);
  /* the collocation rows may be factored even when the border is not:
   * the multipliers at the same point reuse them */
  if (cond_factored_at(ws, X, p)) c->last_ws = ws;
  return rc;
}

/* As bs_factor, and F(X, p) from the same evaluations (cond_factor_F). */
static int bs_factor_F(void *ws, const double *X, const double *p, size_t k,
                       const double *r, double *f) {
  whirl_colloc *c = cond_sys(ws);
  p = colloc_par(c, X, p);
  const int rc = cond_factor_F(ws, X, p, k, r, f);
  if (cond_factored_at(ws, X, p)) c->last_ws = ws;
  return rc;
}

static int bs_factor_col(void *ws, const double *X, const double *p,
                         const double *col, const double *r) {
  return cond_factor_col(ws, X, colloc_par(cond_sys(ws), X, p), col, r);
}

const whirl_bsolver colloc_bsolver = {bs_alloc,   bs_free,     bs_factor,
                                      cond_solve, cond_logdet, cond_reborder,
                                      bs_factor_col, cond_solve_t, bs_factor_F};

int colloc_cond_monodromy(whirl_colloc *c, const double *X, const double *p,
                          double *M) {
  /* the collocation rows of the last factorisation of the bordered matrix
   * at this very point (the core factors at every point it analyses, then
   * asks for the spectrum), else a condensation of F_x of our own */
  cond_ws *w = c->last_ws;
  p = colloc_par(c, X, p);
  if (w && cond_factored_at(w, X, p)) return cond_monodromy(w, M);
  if (!c->spec_ws && !(c->spec_ws = bs_alloc(c))) return WHIRL_ENOMEM;
  w = c->spec_ws;
  int rc = cond_factor_rows(w, X, p);
  return rc != 0 ? rc : cond_monodromy(w, M);
}

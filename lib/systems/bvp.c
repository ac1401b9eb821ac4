/* lib/systems/bvp.c — constructor: boundary value problems u' = f(t, u, p)
 * on [0, 1] with boundary conditions b(u(0), u(1), p) = 0 and integral
 * conditions ∫ g(u, p) dt = 0 by orthogonal collocation at Gauss–Legendre
 * points (AUTO-07p's IPS = 4; whirl/bvp.h), the sibling of colloc.c with
 * T = 1, no phase condition and no periodicity; the basis is colloc_basis.c.
 *
 * Rows: n·NTST·NCOL collocation rows (scaled by the interval length h_i,
 *   sum_k l_k'(σ_c) u_{i,k} − h_i f(τ_{i,c}, u(τ_{i,c}), p~) = 0),
 * then NBC boundary rows, then NINT integral rows (Gauss quadrature).
 * Columns: the node values, then the nfree free parameters.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/bvp.h>
#include <whirl/colloc.h>

#include "bvp_impl.h"
#include "util/short_copy.h"
#include "util/threads_impl.h"

void whirl_bvp_options_default(whirl_bvp_options *o) {
  memset(o, 0, sizeof *o);
  o->ntst = 20;
  o->ncol = 4;
  o->threads = 1;
}

/* ------------------------------------------------------------ helpers */

void whirl_bvp_params(const whirl_bvp *b, const double *X, const double *p,
                      double *pfull) {
  if (!b || !X || !p || !pfull) return;
  if (pfull != p) memcpy(pfull, p, b->npar * sizeof *pfull);
  const double *xf = X + b->n * b->nnodes;
  for (size_t j = 0; j < b->nfree; ++j) pfull[b->free[j]] = xf[j];
}

/* u and du/dσ at Gauss point g of interval i into s->u, s->du, node by
 * node: u = sum_k l_k(σ_g) u_{i,k}. */
static void gauss_state(const whirl_bvp *b, bvp_scratch *s, const double *X, size_t i,
                        size_t g) {
  const size_t n = b->n, m = b->ncol;
  const double *lv = b->L + g * (m + 1), *dv = b->D + g * (m + 1);
  const double *node = X + n * (i * m);
  double *restrict u = s->u, *restrict du = s->du;
  for (size_t r = 0; r < n; ++r) { /* the first node's terms: no memset */
    u[r] = lv[0] * node[r];
    du[r] = dv[0] * node[r];
  }
  for (size_t k = 1; k <= m; ++k) {
    node += n;
    const double a = lv[k], d = dv[k];
    for (size_t r = 0; r < n; ++r) {
      u[r] += a * node[r];
      du[r] += d * node[r];
    }
  }
}

/* For the integral conditions at Gauss point g of interval i (after
 * gauss_state): u' = (du/dσ)/h into ud, or with udot_direction the
 * direction of the correction there (AUTO's UDOT: its direction vector's
 * state part, interpolated as u), and the reference and its derivative
 * into uo, upo. */
static void gauss_reference(const whirl_bvp *b, bvp_scratch *s, size_t i, size_t g) {
  const size_t n = b->n, m = b->ncol;
  const double h = b->mesh[i + 1] - b->mesh[i];
  const double *lv = b->L + g * (m + 1), *dv = b->D + g * (m + 1);
  double *restrict ud = s->ud, *restrict uo = s->uo, *restrict upo = s->upo;
  if (b->udot_direction) {
    const double *node = b->dref + n * (i * m);
    for (size_t r = 0; r < n; ++r) ud[r] = lv[0] * node[r]; /* = 0 + its term */
    for (size_t k = 1; k <= m; ++k) {
      node += n;
      const double a = lv[k];
      for (size_t r = 0; r < n; ++r) ud[r] += a * node[r];
    }
  } else {
    for (size_t r = 0; r < n; ++r) ud[r] = s->du[r] / h;
  }
  /* the same sums, term by term, as from zero: the first node's terms
   * start them (0 + x is x), dv[k] / h once a node */
  const double *node = b->ref + n * (i * m);
  const double d0 = dv[0] / h;
  for (size_t r = 0; r < n; ++r) {
    uo[r] = lv[0] * node[r];
    upo[r] = d0 * node[r];
  }
  for (size_t k = 1; k <= m; ++k) {
    node += n;
    const double a = lv[k], d = dv[k] / h;
    for (size_t r = 0; r < n; ++r) {
      uo[r] += a * node[r];
      upo[r] += d * node[r];
    }
  }
}

/* Central-difference step for a value v (as whirl_fd_jac_x). */
static double fd_step(double v) { return cbrt(DBL_EPSILON) * fmax(1.0, fabs(v)); }

/* The model's f_x at (t, s->u) into s->J: analytic or differences. */
static int model_fx(const whirl_bvp *b, bvp_scratch *s, double t, const double *p) {
  const whirl_problem *pr = b->prob;
  if (pr->jac_x) return pr->jac_x(t, s->u, p, s->J, pr->data);
  return whirl_fd_jac_x(pr, t, s->u, p, s->J, s->work);
}

/* df/dp_k at (t, s->u, p) into out[n]: the model's jac_p, or a central
 * difference of f in p_k (s->pq, s->f, s->fm are used). */
static int model_fp(const whirl_bvp *b, bvp_scratch *s, double t, const double *p,
                    size_t k, double *out) {
  const whirl_problem *pr = b->prob;
  const size_t n = b->n;
  int rc;
  if (pr->jac_p) {
    if ((rc = pr->jac_p(t, s->u, p, s->Jpar, pr->data)) != 0) return rc;
    whirl_copy_short(out, s->Jpar + n * k, n);
    return 0;
  }
  whirl_copy_short(s->pq, p, b->npar);
  const double hp = fd_step(p[k]);
  s->pq[k] = p[k] + hp;
  const double up = s->pq[k];
  if ((rc = pr->rhs(t, s->u, s->pq, s->f, pr->data)) != 0) return rc;
  s->pq[k] = p[k] - hp;
  const double dn = s->pq[k];
  if ((rc = pr->rhs(t, s->u, s->pq, s->fm, pr->data)) != 0) return rc;
  for (size_t r = 0; r < n; ++r) out[r] = (s->f[r] - s->fm[r]) / (up - dn);
  return 0;
}

/* AUTO-07p's step of a forward difference in a parameter v (FUNI and
 * ICNI with JAC = 0: HMACH (1 + |v|), HMACH = 1e-7). */
static double auto_step(double v) { return 1e-7 * (1.0 + fabs(v)); }

/* df/dp_k as AUTO's FUNI: a forward difference of f in p_k from f0, f at
 * (t, s->u, p) (s->pq, s->f are used); the model's jac_p when it has one. */
static int model_fp_forward(const whirl_bvp *b, bvp_scratch *s, double t, const double *p,
                            size_t k, const double *f0, double *out) {
  const whirl_problem *pr = b->prob;
  if (pr->jac_p) return model_fp(b, s, t, p, k, out);
  whirl_copy_short(s->pq, p, b->npar);
  s->pq[k] = p[k] + auto_step(p[k]);
  const double dp = s->pq[k] - p[k];
  const int rc = pr->rhs(t, s->u, s->pq, s->f, pr->data);
  if (rc != 0) return rc;
  for (size_t r = 0; r < b->n; ++r) out[r] = (s->f[r] - f0[r]) / dp;
  return 0;
}

/* A user callback's status: a fatal one gets a message. */
static int user_status(whirl_bvp *b, int rc, const char *what) {
  if (rc < 0) WHIRL_FAIL(b, WHIRL_EUSER, "%s returned %d (fatal)", what, rc);
  return rc;
}

/* The integral rows' terms h w_g g at the Gauss points, terms (b->icterm
 * or F's b->icF), added up into I[nint] in interval and Gauss-point
 * order: the same sum, to the bit, as one loop making and adding them
 * (the loops that make them run on several threads). */
static void sum_integral_terms(const whirl_bvp *b, const double *terms, double *I) {
  const size_t nint = b->nint, npts = b->ntst * b->ncol;
  for (size_t q = 0; q < npts; ++q)
    for (size_t s = 0; s < nint; ++s) I[s] += terms[q * nint + s];
}

/* The threads of the loops over the intervals: several only where there is
 * work enough to share (as colloc_threads). */
int bvp_threads(const whirl_bvp *b) {
  return b->nthreads > 1 && b->ntst * b->ncol * b->n >= 512 ? b->nthreads : 1;
}

/* A loop over the intervals, fn(b, scratch, X, i, k, out, &what) on the
 * threads the governor g allows: 0, or the first failure in interval
 * order with the message of the callback *what names. */
typedef int (*interval_fn)(const whirl_bvp *b, bvp_scratch *s, const double *X, size_t i,
                           size_t k, double *out, const char **what);
static int for_intervals(whirl_bvp *b, whirl_gov *g, interval_fn fn, const double *X,
                         size_t k, double *out) {
  const size_t N = b->ntst;
  const int par = bvp_threads(b) > 1;
  const int nth = par ? whirl_gov_begin(g) : 1;
  size_t bad = N;
  int bad_rc = 0;
  const char *bad_what = NULL;
#pragma omp parallel for num_threads(nth) schedule(static) if (nth > 1)
  for (size_t i = 0; i < N; ++i) {
    const char *what = NULL;
    const int rc = fn(b, &b->scr[whirl_thread_num()], X, i, k, out, &what);
    if (rc != 0) {
#pragma omp critical(whirl_bvp_intervals)
      if (i < bad) bad = i, bad_rc = rc, bad_what = what;
    }
  }
  if (par) whirl_gov_end(g);
  return bad < N ? user_status(b, bad_rc, bad_what) : 0;
}

/* ∂g/∂u into s->gu[k + nint q] and ∂g/∂u' into s->gd, by central
 * differences at the current Gauss point (after gauss_state and
 * gauss_reference), parameters pt.  With auto_differences or
 * udot_direction ∂g/∂u' is 0: AUTO's ICNI takes no derivative in UDOT,
 * data to ICND, and the direction is no function of the unknowns. */
static int ic_partials(const whirl_bvp *b, bvp_scratch *s, const double *pt) {
  const size_t n = b->n, nint = b->nint;
  double *gpart[2] = {s->gu, s->gd};
  const int nw = b->auto_differences || b->udot_direction ? 1 : 2;
  if (nw == 1) memset(s->gd, 0, n * nint * sizeof *s->gd);
  for (int w = 0; w < nw; ++w) {
    const double *v0 = w ? s->ud : s->u;
    memcpy(s->uq, s->u, n * sizeof *s->uq);
    memcpy(s->udq, s->ud, n * sizeof *s->udq);
    double *vq = w ? s->udq : s->uq;
    for (size_t q = 0; q < n; ++q) {
      const double hq = fd_step(v0[q]);
      int rc;
      vq[q] = v0[q] + hq;
      const double up = vq[q];
      if ((rc = b->ic(s->uq, s->uo, s->udq, s->upo, pt, s->gi, b->data)) != 0) return rc;
      vq[q] = v0[q] - hq;
      const double dn = vq[q];
      if ((rc = b->ic(s->uq, s->uo, s->udq, s->upo, pt, s->gim, b->data)) != 0) return rc;
      vq[q] = v0[q];
      for (size_t k = 0; k < nint; ++k)
        gpart[w][k + nint * q] = (s->gi[k] - s->gim[k]) / (up - dn);
    }
  }
  return 0;
}

/* ∂g/∂p_k at the current Gauss point (after gauss_state and
 * gauss_reference), by central differences, into s->gi. */
static int ic_dp_at(const whirl_bvp *b, bvp_scratch *s, const double *pt, size_t k) {
  double *pp = s->pq;
  int rc;
  memcpy(pp, pt, b->npar * sizeof *pp);
  const double hp = fd_step(pt[k]);
  pp[k] = pt[k] + hp;
  const double up = pp[k];
  if ((rc = b->ic(s->u, s->uo, s->ud, s->upo, pp, s->gi, b->data)) != 0) return rc;
  pp[k] = pt[k] - hp;
  const double dn = pp[k];
  if ((rc = b->ic(s->u, s->uo, s->ud, s->upo, pp, s->gim, b->data)) != 0) return rc;
  for (size_t q = 0; q < b->nint; ++q) s->gi[q] = (s->gi[q] - s->gim[q]) / (up - dn);
  return 0;
}

/* ∂g/∂p_k as AUTO's ICNI: a forward difference from g0, g at the current
 * Gauss point with parameters pt, into s->gi (s->pq is used). */
static int ic_dp_forward(const whirl_bvp *b, bvp_scratch *s, const double *pt, size_t k,
                         const double *g0) {
  double *pp = s->pq;
  memcpy(pp, pt, b->npar * sizeof *pp);
  pp[k] = pt[k] + auto_step(pt[k]);
  const double dp = pp[k] - pt[k];
  const int rc = b->ic(s->u, s->uo, s->ud, s->upo, pp, s->gi, b->data);
  if (rc != 0) return rc;
  for (size_t q = 0; q < b->nint; ++q) s->gi[q] = (s->gi[q] - g0[q]) / dp;
  return 0;
}

/* ------------------------------------------------------------ system */

/* F's collocation rows at Gauss point g of interval i (width h), u' − h f
 * from f there, and its integral terms h w_g g from g there (b->icF):
 * written so by the residual and by the Jacobian's fill alike, the same
 * bytes from the same evaluations. */
static void residual_rows(const whirl_bvp *b, const bvp_scratch *s, size_t i, size_t g,
                          double h, const double *f, double *F) {
  const size_t n = b->n;
  double *row = F + n * (i * b->ncol + g);
  for (size_t r = 0; r < n; ++r) row[r] = s->du[r] - h * f[r];
}
static void residual_terms(const whirl_bvp *b, size_t i, size_t g, double h,
                           const double *gi) {
  double *t = b->icF + b->nint * (i * b->ncol + g);
  for (size_t c = 0; c < b->nint; ++c) t[c] = h * b->gw[g] * gi[c];
}

/* Interval i's collocation rows of F (u' - h f at its Gauss points) and
 * its integral terms (b->icF). */
static int residual_interval(const whirl_bvp *b, bvp_scratch *s, const double *X, size_t i,
                             size_t k, double *F, const char **what) {
  (void)k;
  const whirl_problem *pr = b->prob;
  const size_t m = b->ncol;
  const double h = b->mesh[i + 1] - b->mesh[i];
  int rc;
  for (size_t g = 0; g < m; ++g) {
    gauss_state(b, s, X, i, g);
    *what = "the model's rhs";
    if ((rc = pr->rhs(b->mesh[i] + h * b->gs[g], s->u, b->pt, s->f, pr->data)) != 0) return rc;
    residual_rows(b, s, i, g, h, s->f, F);
    if (!b->nint) continue;
    gauss_reference(b, s, i, g);
    *what = "integral conditions";
    if ((rc = b->ic(s->u, s->uo, s->ud, s->upo, b->pt, s->gi, b->data)) != 0) return rc;
    residual_terms(b, i, g, h, s->gi);
  }
  return 0;
}

int bvp_F_boundary(whirl_bvp *b, const double *X, double *F) {
  double *c = F + b->ncoll;
  const int rc = b->nbc ? b->bc(X, X + b->n * (b->nnodes - 1), b->pt, c, b->data) : 0;
  return rc ? user_status(b, rc, "boundary conditions") : 0;
}

void bvp_F_integrals(whirl_bvp *b, double *F) {
  double *c = F + b->ncoll + b->nbc;
  memset(c, 0, b->nint * sizeof *c);
  sum_integral_terms(b, b->icF, c);
}

static int bvp_F(const double *X, const double *p, double *F, void *data) {
  whirl_bvp *b = data;
  whirl_bvp_params(b, X, p, b->pt);
  int rc = for_intervals(b, &b->gov_F, residual_interval, X, 0, F);
  if (rc != 0 || (rc = bvp_F_boundary(b, X, F)) != 0) return rc;
  bvp_F_integrals(b, F);
  return 0;
}

/* Where the entries of the boundary and integral rows of column col sit:
 * they are the last nbc + nint (or nint) entries of the column. */
static double *ic_entries(const whirl_bvp *b, double *Jx, size_t col) {
  return Jx + (size_t)b->Jp[col + 1] - b->nint;
}
static double *bc_entries(const whirl_bvp *b, double *Jx, size_t col) {
  return Jx + (size_t)b->Jp[col + 1] - b->nint - b->nbc;
}

/* The integral rows' terms of one Gauss point in b->icacc: (NCOL + 1) n
 * node columns, then the nfree free columns, nint each. */
static size_t icacc_size(const whirl_bvp *b) {
  return ((b->ncol + 1) * b->n + b->nfree) * b->nint;
}

/* Where fill_interval puts interval i's collocation rows: the sparse
 * Jacobian's values Jx (each column's rows of a Gauss point contiguous),
 * or the interval's dense row-major block B of cond_elim.c (rows g n + r,
 * columns [interior | x_i | x_{i+1} | free | p_k], row length wc), with
 * p_k's column too when fk is set (those rows of dF/dp_k also into fk). */
typedef struct fill_target {
  double *Jx;
  double *B;
  size_t wc;
  int globals;  /* the free columns (0: F_x alone, the monodromy's) */
  double *fk;   /* dF/dp_k's entries (indexed as F's rows), or NULL */
  size_t k;
  double *F;    /* F's collocation rows and integral terms (b->icF) from
                   the same evaluations, or NULL */
} fill_target;

/* The first of the n collocation rows of Gauss point g of interval i in
 * the column of node k's component q (k <= NCOL), and the step between
 * them in *stride. */
static double *target_node_rows(const whirl_bvp *b, const fill_target *T, size_t i,
                                size_t g, size_t k, size_t q, size_t *stride) {
  const size_t n = b->n, m = b->ncol;
  if (!T->B) {
    *stride = 1;
    const size_t col = n * (i * m + k) + q;
    /* the column's collocation rows start at row Ji[Jp[col]] */
    return T->Jx + (size_t)b->Jp[col] + n * (i * m + g) - (size_t)b->Ji[b->Jp[col]];
  }
  *stride = T->wc;
  const size_t pos = k == 0 ? (m - 1) * n + q : k == m ? m * n + q : (k - 1) * n + q;
  return T->B + g * n * T->wc + pos;
}

/* The same for global column j: free parameter j < NFREE, p_k's NFREE. */
static double *target_global_rows(const whirl_bvp *b, const fill_target *T, size_t i,
                                  size_t g, size_t j, size_t *stride) {
  const size_t n = b->n, m = b->ncol;
  if (!T->B) {
    *stride = 1;
    return T->Jx + (size_t)b->Jp[n * b->nnodes + j] + n * (i * m + g);
  }
  *stride = T->wc;
  return T->B + g * n * T->wc + (m + 1) * n + j;
}

/* A Gauss point's n collocation rows of the node columns in a dense block
 * (rows R of wc entries, target_node_rows's columns: nodes 1..NCOL-1,
 * then node 0, then node NCOL): entry (r, node k, q) is −h l_k J[r][q]
 * plus l_k' where q = r, J column-major.  Row by row, so the writes are
 * contiguous; the same products as the sparse fill's. */
static void node_rows_dense(const whirl_bvp *b, const double *J, const double *lv,
                            const double *dv, double h, double *R, size_t wc) {
  const size_t n = b->n, m = b->ncol;
  for (size_t r = 0; r < n; ++r, R += wc)
    for (size_t k = 0; k <= m; ++k) {
      double *v = R + (k == 0 ? (m - 1) * n : k == m ? m * n : (k - 1) * n);
      const double a = -h * lv[k];
      for (size_t q = 0; q < n; ++q) v[q] = a * J[n * q + r];
      v[r] += dv[k];
    }
}

/* −h df/dp_k at the current Gauss point into T's p_k column and T->fk
 * (central differences, or the model's jac_p: bvp_Fp's numbers). */
static int fill_fk(const whirl_bvp *b, bvp_scratch *s, const fill_target *T, size_t i,
                   size_t g, double t, double h) {
  const size_t n = b->n;
  double *v = T->fk + n * (i * b->ncol + g);
  const int rc = model_fp(b, s, t, b->pt, T->k, v);
  if (rc != 0) return rc;
  size_t st;
  double *e = target_global_rows(b, T, i, g, b->nfree, &st);
  for (size_t r = 0; r < n; ++r) {
    v[r] *= -h;
    if (!isfinite(v[r])) return WHIRL_EBADFUNC;
    e[r * st] = v[r];
  }
  return 0;
}

/* Interval i's part of the Jacobian: its collocation rows of the node
 * columns (analytic) and of the free columns (df/dp), in place (no other
 * interval has them), and the integral rows' terms of its Gauss points
 * (∂g/∂u by central differences, times the quadrature weight and the
 * basis; h w ∂g/∂p) into its slice of b->icacc, which the caller adds up;
 * with T->fk, dF/dp_k's rows and its integral terms (b->icterm) too.  0,
 * or the status of the callback *what names. */
static int fill_interval(const whirl_bvp *b, bvp_scratch *s, const double *X,
                         const fill_target *T, size_t i, const char **what) {
  const size_t n = b->n, m = b->ncol, nint = b->nint;
  const size_t na = icacc_size(b), nfree = T->globals ? b->nfree : 0;
  const double h = b->mesh[i + 1] - b->mesh[i];
  double *tmp = s->uq; /* a column's n rows, before their stride */
  size_t st;
  int rc;
  for (size_t g = 0; g < m; ++g) {
    const double t = b->mesh[i] + h * b->gs[g];
    gauss_state(b, s, X, i, g);
    *what = "the model's Jacobian";
    if ((rc = model_fx(b, s, t, b->pt)) != 0) return rc;
    const double *lv = b->L + g * (m + 1), *dv = b->D + g * (m + 1);
    if (T->B)
      node_rows_dense(b, s->J, lv, dv, h, T->B + g * n * T->wc, T->wc);
    else
      for (size_t k = 0; k <= m; ++k)
        for (size_t q = 0; q < n; ++q) {
          double *v = target_node_rows(b, T, i, g, k, q, &st);
          const double *Jq = s->J + n * q;
          for (size_t r = 0; r < n; ++r) v[r * st] = -h * lv[k] * Jq[r];
          v[q * st] += dv[k];
        }
    *what = "the model's parameter derivative";
    /* AUTO's forward differences share f at the point (s->fm), and so
     * does F's row (the residual's evaluation, AUTO's SETUBV) */
    const int fwd = b->auto_differences && nfree > 0;
    if (((fwd && !b->prob->jac_p) || T->F) &&
        (rc = b->prob->rhs(t, s->u, b->pt, s->fm, b->prob->data)) != 0) {
      if (T->F) *what = "the model's rhs";
      return rc;
    }
    if (T->F) residual_rows(b, s, i, g, h, s->fm, T->F);
    for (size_t j = 0; j < nfree; ++j) {
      rc = fwd ? model_fp_forward(b, s, t, b->pt, b->free[j], s->fm, tmp)
               : model_fp(b, s, t, b->pt, b->free[j], tmp);
      if (rc != 0) return rc;
      double *v = target_global_rows(b, T, i, g, j, &st);
      for (size_t r = 0; r < n; ++r) v[r * st] = tmp[r] * -h;
    }
    if (T->fk && (rc = fill_fk(b, s, T, i, g, t, h)) != 0) return rc;
    if (!nint) continue;
    gauss_reference(b, s, i, g);
    *what = "integral conditions";
    if ((rc = ic_partials(b, s, b->pt)) != 0) return rc;
    /* u = sum l_k x_k, u' = sum l_k' x_k / h: node k's term is
     * h w_g (l_k ∂g/∂u + l_k'/h ∂g/∂u') */
    double *acc = b->icacc + na * (i * m + g);
    for (size_t k = 0; k <= m; ++k) {
      const double wk = h * b->gw[g] * lv[k], wd = b->gw[g] * dv[k];
      for (size_t q = 0; q < n; ++q)
        for (size_t c = 0; c < nint; ++c)
          acc[(k * n + q) * nint + c] = wk * s->gu[c + nint * q] + wd * s->gd[c + nint * q];
    }
    /* the free parameters' terms: h w_g ∂g/∂p (AUTO's forward differences
     * from g at the point, in s->gim) */
    acc += (m + 1) * n * nint;
    if ((fwd || T->F) && (rc = b->ic(s->u, s->uo, s->ud, s->upo, b->pt, s->gim, b->data)) != 0)
      return rc;
    if (T->F) residual_terms(b, i, g, h, s->gim);
    for (size_t j = 0; j < nfree; ++j) {
      rc = fwd ? ic_dp_forward(b, s, b->pt, b->free[j], s->gim)
               : ic_dp_at(b, s, b->pt, b->free[j]);
      if (rc != 0) return rc;
      for (size_t c = 0; c < nint; ++c) acc[j * nint + c] = h * b->gw[g] * s->gi[c];
    }
    if (!T->fk) continue;
    /* dF/dp_k's integral terms, as fp_interval's */
    if ((rc = ic_dp_at(b, s, b->pt, T->k)) != 0) return rc;
    double *tk = b->icterm + nint * (i * m + g);
    for (size_t c = 0; c < nint; ++c) tk[c] = h * b->gw[g] * s->gi[c];
  }
  return 0;
}

/* The integral rows' terms of every Gauss point (b->icacc) added into
 * their entries in interval and Gauss-point order, so the Jacobian is the
 * same bytes on any number of threads: into the sparse values Jx, or (Jx
 * NULL) into the dense rows ic (row c at ic + c ldic, F_x's columns; the
 * free columns when globals). */
static void sum_integral_entries(const whirl_bvp *b, double *Jx, double *ic,
                                 size_t ldic, int globals) {
  const size_t n = b->n, m = b->ncol, N = b->ntst, nint = b->nint;
  const size_t colF = n * b->nnodes, na = icacc_size(b);
  const size_t st = Jx ? 1 : ldic;
  for (size_t i = 0; nint && i < N; ++i)
    for (size_t g = 0; g < m; ++g) {
      const double *acc = b->icacc + na * (i * m + g);
      for (size_t k = 0; k <= m; ++k)
        for (size_t q = 0; q < n; ++q) {
          const size_t col = n * (i * m + k) + q;
          double *v = Jx ? ic_entries(b, Jx, col) : ic + col;
          for (size_t c = 0; c < nint; ++c) v[c * st] += acc[(k * n + q) * nint + c];
        }
      acc += (m + 1) * n * nint;
      for (size_t j = 0; globals && j < b->nfree; ++j) {
        double *v = Jx ? ic_entries(b, Jx, colF + j) : ic + colF + j;
        for (size_t c = 0; c < nint; ++c) v[c * st] += acc[j * nint + c];
      }
    }
}

/* The collocation rows of every column and the integral rows' node and
 * free entries: the intervals in parallel (fill_interval), then the
 * integral terms summed into the entries (sum_integral_entries).  The
 * first failure in interval order is the one reported. */
static int fill_collocation(whirl_bvp *b, const double *X, double *Jx) {
  const size_t N = b->ntst;
  const fill_target T = {Jx, NULL, 0, 1, NULL, 0, NULL};
  const int nth = bvp_threads(b) > 1 ? whirl_gov_begin(&b->gov) : 1;
  size_t bad = N;
  int bad_rc = 0;
  const char *bad_what = NULL;
#pragma omp parallel for num_threads(nth) schedule(dynamic, 4) if (nth > 1)
  for (size_t i = 0; i < N; ++i) {
    const char *what = NULL;
    const int rc = fill_interval(b, &b->scr[whirl_thread_num()], X, &T, i, &what);
    if (rc != 0) {
#pragma omp critical(whirl_bvp_fill)
      if (i < bad) bad = i, bad_rc = rc, bad_what = what;
    }
  }
  if (bvp_threads(b) > 1) whirl_gov_end(&b->gov);
  if (bad < N) return user_status(b, bad_rc, bad_what);
  sum_integral_entries(b, Jx, NULL, 0, 1);
  return 0;
}

/* ------------------------------------------------------------ blocks */

int bvp_fill_block(whirl_bvp *b, int thread, const double *X, size_t i, double *B,
                   size_t wc, int globals, double *fk, size_t k, double *F,
                   const char **what) {
  const fill_target T = {NULL, B, wc, globals, fk, k, F};
  *what = NULL;
  memset(B, 0, b->n * b->ncol * wc * sizeof *B);
  return fill_interval(b, &b->scr[thread], X, &T, i, what);
}

void bvp_block_sums(whirl_bvp *b, double *ic, size_t ldic, int globals, double *fk_ic) {
  sum_integral_entries(b, NULL, ic, ldic, globals);
  if (fk_ic) sum_integral_terms(b, b->icterm, fk_ic);
}

int bvp_block_status(whirl_bvp *b, int rc, const char *what) {
  return what ? user_status(b, rc, what) : rc;
}

/* The boundary rows' entries in the columns of u(0) and u(1), by central
 * differences of bc: into the sparse values Jx, or (Jx NULL) into the
 * dense rows bcr (row s at bcr + s nf, u(0)'s columns first, then u(1)'s). */
static int fill_boundary(whirl_bvp *b, const double *X, double *Jx, double *bcr,
                         size_t nf) {
  const size_t n = b->n, nbc = b->nbc, last = b->nnodes - 1;
  double *w0 = b->scr[0].work, *w1 = b->scr[0].work + n; /* copies of u(0), u(1) */
  memcpy(w0, X, n * sizeof *w0);
  memcpy(w1, X + n * last, n * sizeof *w1);
  for (int end = 0; end < 2; ++end) {
    double *w = end ? w1 : w0;
    for (size_t q = 0; q < n; ++q) {
      const double v0 = w[q], hq = fd_step(v0);
      int rc;
      w[q] = v0 + hq;
      const double up = w[q];
      if ((rc = b->bc(w0, w1, b->pt, b->fb, b->data)) != 0)
        return user_status(b, rc, "boundary conditions");
      w[q] = v0 - hq;
      const double dn = w[q];
      if ((rc = b->bc(w0, w1, b->pt, b->fbm, b->data)) != 0)
        return user_status(b, rc, "boundary conditions");
      w[q] = v0;
      double *v = Jx ? bc_entries(b, Jx, n * (end ? last : 0) + q) : b->cp;
      for (size_t s = 0; s < nbc; ++s) v[s] = (b->fb[s] - b->fbm[s]) / (up - dn);
      for (size_t s = 0; !Jx && s < nbc; ++s) bcr[s * nf + (end ? n : 0) + q] = v[s];
    }
  }
  return 0;
}

/* d(boundary rows)/dp_k by central differences of bc alone, out[nbc]. */
static int bc_dp(whirl_bvp *b, const double *X, size_t k, double *out) {
  const size_t last = b->nnodes - 1;
  double *pp = b->scr[0].pq;
  int rc;
  memcpy(pp, b->pt, b->npar * sizeof *pp);
  const double hp = fd_step(b->pt[k]);
  pp[k] = b->pt[k] + hp;
  const double up = pp[k];
  if ((rc = b->bc(X, X + b->n * last, pp, b->fb, b->data)) != 0)
    return user_status(b, rc, "boundary conditions");
  pp[k] = b->pt[k] - hp;
  const double dn = pp[k];
  if ((rc = b->bc(X, X + b->n * last, pp, b->fbm, b->data)) != 0)
    return user_status(b, rc, "boundary conditions");
  for (size_t s = 0; s < b->nbc; ++s) out[s] = (b->fb[s] - b->fbm[s]) / (up - dn);
  return 0;
}

int bvp_Fx_sparse(const double *X, const double *p, double *Jx, void *data) {
  whirl_bvp *b = data;
  const size_t colF = b->n * b->nnodes;
  int rc;
  whirl_bvp_params(b, X, p, b->pt);
  /* the integral rows accumulate over the intervals holding a node, and
   * (free columns) over all, in fill_collocation */
  for (size_t col = 0; col < b->nx; ++col)
    memset(ic_entries(b, Jx, col), 0, b->nint * sizeof *Jx);
  if ((rc = fill_collocation(b, X, Jx)) != 0) return rc;
  if (b->nbc && (rc = fill_boundary(b, X, Jx, NULL, 0)) != 0) return rc;
  for (size_t j = 0; j < b->nfree && b->nbc; ++j)
    if ((rc = bc_dp(b, X, b->free[j], bc_entries(b, Jx, colF + j))) != 0) return rc;
  return 0;
}

int bvp_fill_bc_rows(whirl_bvp *b, const double *X, double *bcr, size_t nf, int globals,
                     double *fk_bc, size_t k) {
  const size_t n = b->n, nbc = b->nbc;
  int rc;
  if (!nbc) return 0;
  if ((rc = fill_boundary(b, X, NULL, bcr, nf)) != 0) return rc;
  for (size_t j = 0; globals && j < b->nfree; ++j) {
    if ((rc = bc_dp(b, X, b->free[j], b->cp)) != 0) return rc;
    for (size_t s = 0; s < nbc; ++s) bcr[s * nf + 2 * n + j] = b->cp[s];
  }
  if (!fk_bc) return 0;
  if ((rc = bc_dp(b, X, k, fk_bc)) != 0) return rc;
  for (size_t s = 0; s < nbc; ++s)
    if (!isfinite(fk_bc[s])) return WHIRL_EBADFUNC;
  return 0;
}

static int bvp_Fx(const double *X, const double *p, double *J, void *data) {
  whirl_bvp *b = data;
  int rc = bvp_Fx_sparse(X, p, b->Jx, data);
  if (rc == 0) whirl_system_scatter_dense(&b->sys, b->Jx, J);
  return rc;
}

/* Interval i's collocation rows of dF/dp_k (−h df/dp_k at its Gauss
 * points) and its integral terms h w_g ∂g/∂p_k (b->icterm). */
static int fp_interval(const whirl_bvp *b, bvp_scratch *s, const double *X, size_t i,
                       size_t k, double *fk, const char **what) {
  const size_t n = b->n, m = b->ncol;
  const double h = b->mesh[i + 1] - b->mesh[i];
  int rc;
  for (size_t g = 0; g < m; ++g) {
    gauss_state(b, s, X, i, g);
    double *v = fk + n * (i * m + g);
    *what = "the model's parameter derivative";
    if ((rc = model_fp(b, s, b->mesh[i] + h * b->gs[g], b->pt, k, v)) != 0) return rc;
    for (size_t r = 0; r < n; ++r) v[r] *= -h;
    if (!b->nint) continue;
    gauss_reference(b, s, i, g); /* the integral rows at this point */
    *what = "integral conditions";
    if ((rc = ic_dp_at(b, s, b->pt, k)) != 0) return rc;
    double *t = b->icterm + b->nint * (i * m + g);
    for (size_t c = 0; c < b->nint; ++c) t[c] = h * b->gw[g] * s->gi[c];
  }
  return 0;
}

/* dF/dp_k: −h df/dp_k in the collocation rows, differences of the
 * conditions.  A free parameter's entry of p is not read (p~ takes it from
 * X): its column is 0. */
static int bvp_Fp(const double *X, const double *p, size_t k, double *fk,
                  void *data) {
  whirl_bvp *b = data;
  if (k >= b->npar) return WHIRL_EINVAL;
  memset(fk, 0, b->nx * sizeof *fk);
  for (size_t j = 0; j < b->nfree; ++j)
    if (b->free[j] == k) return 0;
  whirl_bvp_params(b, X, p, b->pt);
  int rc = for_intervals(b, &b->gov_Fp, fp_interval, X, k, fk);
  if (rc != 0) return rc;
  sum_integral_terms(b, b->icterm, fk + b->ncoll + b->nbc);
  return b->nbc ? bc_dp(b, X, k, fk + b->ncoll) : 0;
}

/* ------------------------------------------------------------ alloc */

/* The message of a failed whirl_bvp_alloc in errbuf; evaluates to NULL. */
#define ALLOC_FAIL(...)                           \
  (WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,     \
                "whirl_bvp_alloc: " __VA_ARGS__), \
   NULL)

/* The options' rules: "" when they hold, else why not. */
static void check_options(const whirl_problem *prob, const whirl_bvp_options *o,
                          char *why, size_t len) {
  why[0] = '\0';
  const size_t n = prob->n;
  if (o->ntst < 1 || o->ntst > WHIRL_COLLOC_MAX_NTST)
    snprintf(why, len, "need 1 <= NTST <= %d (got %zu)", WHIRL_COLLOC_MAX_NTST,
             o->ntst);
  else if (o->ncol < 2 || o->ncol > COLLOC_BASIS_MAXCOL)
    snprintf(why, len, "need 2 <= NCOL <= %d (got %zu)", COLLOC_BASIS_MAXCOL,
             o->ncol);
  else if (o->nbc > 0 && !o->bc)
    snprintf(why, len, "NBC = %zu boundary conditions but bc is NULL", o->nbc);
  else if (o->nint > 0 && !o->ic)
    snprintf(why, len, "NINT = %zu integral conditions but ic is NULL",
             o->nint);
  else if (o->nbc + o->nint < n || o->nbc + o->nint - n != o->nfree)
    snprintf(why, len,
             "the counts do not match: NBC + NINT = %zu + %zu conditions on "
             "n = %zu components need nfree = NBC + NINT - n = %ld free "
             "parameters besides the continuation parameter (AUTO's NFPR - "
             "1), got nfree = %zu",
             o->nbc, o->nint, n, (long)o->nbc + (long)o->nint - (long)n,
             o->nfree);
  else if (o->nfree > 0 && !o->free)
    snprintf(why, len, "nfree = %zu but the list free is NULL", o->nfree);
  else if (o->adapt_every < 0)
    snprintf(why, len, "adapt_every = %d: need >= 0 (0: a fixed mesh)", o->adapt_every);
  if (why[0]) return;
  for (size_t j = 0; j < o->nfree; ++j) {
    if (o->free[j] >= prob->npar) {
      snprintf(why, len, "free[%zu] = %zu is not a parameter index (npar %zu)",
               j, o->free[j], prob->npar);
      return;
    }
    for (size_t q = 0; q < j; ++q)
      if (o->free[q] == o->free[j]) {
        snprintf(why, len, "free parameter %zu listed twice", o->free[j]);
        return;
      }
  }
}

/* The sparsity pattern, rows sorted within each column: a node's
 * collocation rows (one or two intervals), the boundary rows for u(0) and
 * u(1), the integral rows; a free parameter's column is full. */
static size_t build_pattern(whirl_bvp *b, int count_only) {
  const size_t n = b->n, m = b->ncol, N = b->ntst, nnodes = b->nnodes;
  size_t pos = 0;
  for (size_t j = 0; j < nnodes; ++j) {
    const size_t i0 = (j % m == 0 && j != 0) ? j / m - 1 : j / m;
    const size_t i1 = j == nnodes - 1 ? N - 1 : j / m;
    const int end = j == 0 || j == nnodes - 1;
    for (size_t q = 0; q < n; ++q) {
      if (count_only) {
        pos += n * (i1 + 1 - i0) * m + (end ? b->nbc : 0) + b->nint;
        continue;
      }
      b->Jp[n * j + q] = (int)pos;
      for (size_t R = n * i0 * m; R < n * (i1 + 1) * m; ++R)
        b->Ji[pos++] = (int)R;
      for (size_t s = 0; end && s < b->nbc; ++s)
        b->Ji[pos++] = (int)(b->ncoll + s);
      for (size_t s = 0; s < b->nint; ++s)
        b->Ji[pos++] = (int)(b->ncoll + b->nbc + s);
    }
  }
  for (size_t j = 0; j < b->nfree; ++j) {
    if (count_only) {
      pos += b->nx;
      continue;
    }
    b->Jp[n * nnodes + j] = (int)pos;
    for (size_t R = 0; R < b->nx; ++R) b->Ji[pos++] = (int)R;
  }
  if (!count_only) b->Jp[b->nx] = (int)pos;
  return pos;
}

/* One thread's scratch (bvp_scratch's sizes); 0, or -1 out of memory. */
static int alloc_scratch(const whirl_bvp *b, bvp_scratch *s) {
  const size_t n = b->n, np = b->npar ? b->npar : 1, ni = b->nint;
  const size_t sizes[] = {n, n, n, n, n, n * n, n * np, 2 * n, np, ni, ni, ni * n, ni * n,
                          n, n, n, n};
  double **ptrs[] = {&s->u, &s->du, &s->f, &s->fm, &s->uq, &s->J, &s->Jpar, &s->work,
                     &s->pq, &s->gi, &s->gim, &s->gu, &s->gd, &s->uo, &s->upo, &s->ud,
                     &s->udq};
  const size_t nptr = sizeof sizes / sizeof sizes[0];
  size_t tot = 0;
  for (size_t k = 0; k < nptr; ++k) tot += sizes[k] + 1;
  /* lines of its own: the threads write their scratch at every Gauss point */
  if (!(s->block = whirl_thread_alloc(1, whirl_thread_stride(tot, sizeof *s->block),
                                      sizeof *s->block)))
    return -1;
  double *q = s->block;
  for (size_t k = 0; k < nptr; ++k) {
    *ptrs[k] = q;
    q += sizes[k] + 1;
  }
  return 0;
}

/* The work arrays; 0, or -1 out of memory. */
static int alloc_arrays(whirl_bvp *b) {
  const size_t n = b->n, np = b->npar ? b->npar : 1, nc = b->nbc + b->nint;
  b->mesh = malloc((b->ntst + 1) * sizeof *b->mesh);
  b->free = malloc((b->nfree ? b->nfree : 1) * sizeof *b->free);
  b->Jp = malloc((b->nx + 1) * sizeof *b->Jp);
  b->Ji = malloc(b->nnz * sizeof *b->Ji);
  b->Jx = malloc(b->nnz * sizeof *b->Jx);
  b->map_idx = malloc(b->nnodes * sizeof *b->map_idx);
  const size_t sizes[] = {np, b->nbc, b->nbc, nc, nc, n * b->nnodes,
                          icacc_size(b) * b->ntst * b->ncol,
                          b->ntst + 1, n * b->nnodes * (size_t)b->nthreads, b->ntst,
                          b->ntst + 1,
                          n * b->ntst, b->nnodes * (b->ncol + 1),
                          b->ntst * b->ncol * b->nint, b->ntst * b->ncol * b->nint,
                          n * b->nnodes, n * b->nnodes, b->ntst + 1};
  double **ptrs[] = {&b->pt, &b->fb, &b->fbm, &b->cp, &b->cm, &b->ref, &b->icacc,
                     &b->old_mesh, &b->mapscr, &b->E, &b->Q, &b->Dm, &b->map_L,
                     &b->icterm, &b->icF, &b->dref, &b->nwq, &b->nwmesh};
  const size_t nptr = sizeof sizes / sizeof sizes[0];
  size_t tot = 0;
  for (size_t k = 0; k < nptr; ++k) tot += sizes[k] + 1;
  b->buf = calloc(tot, sizeof *b->buf);
  b->scr = calloc((size_t)b->nthreads, sizeof *b->scr);
  if (!b->mesh || !b->free || !b->Jp || !b->Ji || !b->Jx || !b->map_idx || !b->buf ||
      !b->scr)
    return -1;
  double *q = b->buf;
  for (size_t k = 0; k < nptr; ++k) {
    *ptrs[k] = q;
    q += sizes[k] + 1;
  }
  for (int t = 0; t < b->nthreads; ++t)
    if (alloc_scratch(b, &b->scr[t])) return -1;
  return 0;
}

/* The system's norm weights: the quadrature weights of the node values
 * on the current mesh (the state's part of a step's norm is its integral,
 * as AUTO-07p's), 1 for the unknowns after them (the free parameters). */
static int bvp_norm_weights(double *q, void *data) {
  whirl_bvp *b = data;
  const size_t nw = b->nnodes * b->n, nm = (b->ntst + 1) * sizeof *b->mesh;
  /* the weights depend on the mesh alone: kept until it changes */
  if (!b->nw_ok || memcmp(b->nwmesh, b->mesh, nm) != 0) {
    colloc_basis_node_weights_from(b->n, b->ncol, b->ntst, b->mesh, b->wint, b->nwq);
    memcpy(b->nwmesh, b->mesh, nm);
    b->nw_ok = 1;
  }
  memcpy(q, b->nwq, nw * sizeof *q);
  for (size_t i = nw; i < b->nx; ++i) q[i] = 1.0;
  return 0;
}

/* The system's remap hook: a new mesh every adapt_every accepted points
 * (AUTO's IAD), equidistributing AUTO's estimate of the (NCOL+1)-th
 * derivative (colloc_basis_new_mesh_jumps), with the current point, the
 * tangent, the previous points and the integral conditions' reference
 * carried over (their node values; the free parameters stay). */
static int bvp_remap(double *const *v, size_t nv, const double *p, void *data) {
  (void)p;
  whirl_bvp *b = data;
  if (b->adapt_every <= 0 || ++b->since_adapt < b->adapt_every) return 0;
  b->since_adapt = 0;
  const size_t N = b->ntst;
  memcpy(b->old_mesh, b->mesh, (N + 1) * sizeof *b->mesh);
  const int rc = colloc_basis_new_mesh_jumps(b->n, b->ncol, N, 0, b->dm, v[0], b->old_mesh,
                                             b->mesh, b->E, b->Q, b->Dm);
  if (rc < 0)
    return WHIRL_FAIL(b, WHIRL_EINVAL, "mesh adaptation: the solution is not finite "
                      "or an interval degenerate (%d)", rc);
  if (rc == 0) return 0;
  /* one plan (intervals and basis at the new nodes) for every vector */
  colloc_basis_map_plan(b->ncol, N, b->old_mesh, b->mesh, b->map_idx, b->map_L);
  double *const own[2] = {b->ref, b->dref};
  colloc_basis_map_many(b->n, b->ncol, N, b->map_idx, b->map_L, b->mapscr, v, nv, own, 2,
                        bvp_threads(b) > 1 ? whirl_gov_current(&b->gov) : 1);
  ++b->adaptations;
  return 1;
}

size_t whirl_bvp_adaptations(const whirl_bvp *b) { return b ? b->adaptations : 0; }

static int bvp_accept(const double *X, const double *p, void *data) {
  (void)p;
  return whirl_bvp_set_reference(data, X);
}

/* The system's direction hook (udot_direction): the node values of the
 * correction's direction, AUTO's UDOT of the integral conditions. */
static int bvp_direction(const double *dir, void *data) {
  whirl_bvp *b = data;
  memcpy(b->dref, dir, b->n * b->nnodes * sizeof *b->dref);
  return 0;
}

whirl_bvp *whirl_bvp_alloc(const whirl_problem *prob,
                           const whirl_bvp_options *o, char *errbuf,
                           size_t errlen) {
  char why[320];
  if (errbuf && errlen) errbuf[0] = '\0';
  if (!prob || !prob->rhs || prob->n == 0)
    return ALLOC_FAIL("model is NULL, has no rhs or n = 0");
  if (!o) return ALLOC_FAIL("no options");
  check_options(prob, o, why, sizeof why);
  if (why[0]) return ALLOC_FAIL("%s", why);

  const size_t n = prob->n, m = o->ncol, N = o->ntst;
  const size_t nnodes = N * m + 1; /* N, m bounded above */
  /* sizes in floating point first: nothing overflows on the way */
  const double dnx = (double)n * (double)nnodes + (double)o->nfree;
  const double dnnz =
      (double)n * (double)nnodes *
          (2.0 * (double)n * (double)m + (double)o->nbc + (double)o->nint) +
      (double)o->nfree * dnx;
  if (dnx + 1.0 >= (double)INT_MAX || dnnz >= (double)INT_MAX)
    return ALLOC_FAIL(
        "problem too large for int indices "
        "(reduce NTST, NCOL, the model's dimension or the conditions)");

  whirl_bvp *b = calloc(1, sizeof *b);
  if (!b) return ALLOC_FAIL("out of memory");
  b->prob = prob;
  b->n = n;
  b->npar = prob->npar;
  b->ntst = N;
  b->ncol = m;
  b->nnodes = nnodes;
  b->ncoll = n * N * m;
  b->nbc = o->nbc;
  b->nint = o->nint;
  b->nfree = o->nfree;
  b->nx = n * nnodes + o->nfree;
  b->bc = o->bc;
  b->ic = o->ic;
  b->data = o->data;
  b->nnz = build_pattern(b, 1);
  b->nthreads = whirl_threads_resolve(o->threads);
  whirl_gov_init(&b->gov, b->nthreads);
  whirl_gov_init(&b->gov_F, b->nthreads);
  whirl_gov_init(&b->gov_Fp, b->nthreads);
  if (alloc_arrays(b)) {
    whirl_bvp_free(b);
    return ALLOC_FAIL("out of memory");
  }
  if (b->nfree) memcpy(b->free, o->free, b->nfree * sizeof *b->free);
  build_pattern(b, 0);

  for (size_t i = 0; i <= N; ++i) b->mesh[i] = (double)i / (double)N;
  b->mesh[N] = 1.0;
  colloc_basis_gauss_legendre(m, b->gs, b->gw);
  colloc_basis_lagrange_integrals(m, b->wint);
  colloc_basis_derivative_weights(m, b->dm);
  b->adapt_every = o->adapt_every;
  b->auto_differences = o->auto_differences != 0;
  b->udot_direction = o->udot_direction != 0;
  for (size_t g = 0; g < m; ++g)
    colloc_basis_lagrange(m, b->gs[g], b->L + g * (m + 1), b->D + g * (m + 1));

  whirl_system *s = &b->sys;
  s->name = prob->name;
  s->n = b->nx;
  s->npar = prob->npar;
  s->F = bvp_F;
  s->Fx = bvp_Fx;
  s->Fp = bvp_Fp;
  s->nnz = b->nnz;
  s->Jp = b->Jp;
  s->Ji = b->Ji;
  s->Fx_sparse = bvp_Fx_sparse;
  /* condensation of parameters (bvp_cond.c) wants two intervals or more */
  s->bsolver = N >= 2 ? &bvp_bsolver : NULL;
  s->accept = b->nint ? bvp_accept : NULL; /* the reference of ICND */
  s->direction = b->nint && b->udot_direction ? bvp_direction : NULL; /* ICND's UDOT */
  s->remap = bvp_remap;
  s->norm_weights = bvp_norm_weights;
  s->x_names = NULL; /* node-major unknowns have no model names */
  s->p_names = prob->p_names;
  s->data = b;
  return b;
}

void whirl_bvp_free(whirl_bvp *b) {
  if (!b) return;
  free(b->mesh);
  free(b->free);
  free(b->Jp);
  free(b->Ji);
  free(b->Jx);
  free(b->map_idx);
  free(b->buf);
  for (int t = 0; b->scr && t < b->nthreads; ++t) free(b->scr[t].block);
  free(b->scr);
  free(b);
}

const whirl_system *whirl_bvp_system(const whirl_bvp *b) {
  return b ? &b->sys : NULL;
}

size_t whirl_bvp_size(const whirl_bvp *b) { return b ? b->nx : 0; }

/* ------------------------------------------------------------ solutions */

/* Time of node j on the current mesh. */
static double node_time(const whirl_bvp *b, size_t j) {
  if (j == b->nnodes - 1) return 1.0;
  const size_t i = j / b->ncol, k = j % b->ncol;
  return b->mesh[i] + (b->mesh[i + 1] - b->mesh[i]) * (double)k / (double)b->ncol;
}

int whirl_bvp_from_function(whirl_bvp *b,
                            int (*u)(double t, double *u, double *p, void *d),
                            void *d, double *X, double *p) {
  if (!b) return WHIRL_EINVAL;
  if (!u || !X || (!p && b->npar))
    return WHIRL_FAIL(b, WHIRL_EINVAL, "from_function: NULL argument");
  for (size_t j = 0; j < b->nnodes; ++j) {
    const double t = node_time(b, j);
    int rc = u(t, X + b->n * j, p, d);
    if (rc != 0)
      return WHIRL_FAIL(b, rc, "from_function: the start function returned "
                               "%d at t = %g", rc, t);
  }
  for (size_t j = 0; j < b->nfree; ++j) X[b->n * b->nnodes + j] = p[b->free[j]];
  return whirl_bvp_set_reference(b, X); /* AUTO: UOLD is the start at first */
}

int whirl_bvp_eval(const whirl_bvp *b, const double *X, double t, double *u) {
  if (!b || !X || !u || !(t >= 0.0 && t <= 1.0)) return WHIRL_EINVAL;
  colloc_basis_eval_poly(b->n, b->ntst, b->ncol, b->mesh, X, t, u);
  return WHIRL_OK;
}

double whirl_bvp_l2norm(const whirl_bvp *b, const double *X) {
  if (!b || !X) return NAN;
  const size_t n = b->n, m = b->ncol;
  /* AUTO's RNRMV: each interval's node values squared by the closed
   * Newton-Cotes weights of its NCOL + 1 equally spaced nodes (WINT), not
   * a Gauss rule of the polynomial: the two part by 1 % on a coarse mesh
   * with a boundary layer (demo kar's first points, uniform NTST 40) */
  const double *W = b->wint;
  double s = 0.0;
  for (size_t i = 0; i < b->ntst; ++i) {
    const double h = b->mesh[i + 1] - b->mesh[i];
    for (size_t k = 0; k <= m; ++k) {
      double sq = 0.0;
      for (size_t r = 0; r < n; ++r) {
        const double v = X[n * (i * m + k) + r];
        sq += v * v;
      }
      s += h * W[k] * sq;
    }
  }
  return sqrt(s);
}

/* fmax and fmin (a number over a NaN) by comparisons: at -O2 each is a
 * library call, once an entry of every point's maxima */
static inline double max_num(double a, double b) { return b > a || a != a ? b : a; }
static inline double min_num(double a, double b) { return b < a || a != a ? b : a; }

int whirl_bvp_max(const whirl_bvp *b, const double *X, double *mx) {
  if (!b || !X || !mx) return WHIRL_EINVAL;
  for (size_t r = 0; r < b->n; ++r) mx[r] = X[r];
  for (size_t j = 1; j < b->nnodes; ++j)
    for (size_t r = 0; r < b->n; ++r) mx[r] = max_num(mx[r], X[b->n * j + r]);
  return WHIRL_OK;
}

int whirl_bvp_set_reference(whirl_bvp *b, const double *X) {
  if (!b || !X) return WHIRL_EINVAL;
  memcpy(b->ref, X, b->n * b->nnodes * sizeof *b->ref);
  return WHIRL_OK;
}

int whirl_bvp_moments(const whirl_bvp *b, const double *X, double *m1, double *m2,
                      double *mn, double *mx) {
  if (!b || !X || !m1 || !m2 || !mn || !mx) return WHIRL_EINVAL;
  const size_t n = b->n;
  double gx[5], gw[5], u[64], *v = n <= 64 ? u : malloc(n * sizeof *v);
  if (!v) return WHIRL_ENOMEM;
  colloc_basis_gauss_legendre(5, gx, gw); /* on [0, 1] */
  /* the basis at the five points of an interval, the same on every one */
  const size_t m = b->ncol;
  double lg[5][COLLOC_BASIS_MAXCOL + 1];
  for (int g = 0; g < 5; ++g) colloc_basis_lagrange_values(m, gx[g], lg[g]);
  for (size_t r = 0; r < n; ++r) m1[r] = m2[r] = 0.0;
  for (size_t i = 0; i < b->ntst; ++i) {
    const double h = b->mesh[i + 1] - b->mesh[i];
    for (int g = 0; g < 5; ++g) {
      for (size_t r = 0; r < n; ++r) v[r] = 0.0;
      for (size_t k = 0; k <= m; ++k) {
        const double *xk = X + n * (i * m + k);
        for (size_t r = 0; r < n; ++r) v[r] += lg[g][k] * xk[r];
      }
      for (size_t r = 0; r < n; ++r) m1[r] += h * gw[g] * v[r], m2[r] += h * gw[g] * v[r] * v[r];
    }
  }
  for (size_t r = 0; r < n; ++r) mn[r] = mx[r] = X[r];
  for (size_t j = 1; j < b->nnodes; ++j)
    for (size_t r = 0; r < n; ++r) {
      mn[r] = min_num(mn[r], X[n * j + r]);
      mx[r] = max_num(mx[r], X[n * j + r]);
    }
  if (v != u) free(v);
  return WHIRL_OK;
}

const double *whirl_bvp_mesh(const whirl_bvp *b) { return b ? b->mesh : NULL; }

int whirl_bvp_set_mesh(whirl_bvp *b, const double *tau) {
  if (!b) return WHIRL_EINVAL;
  if (!tau) return WHIRL_FAIL(b, WHIRL_EINVAL, "set_mesh: no mesh");
  const size_t N = b->ntst;
  if (tau[0] != 0.0 || tau[N] != 1.0)
    return WHIRL_FAIL(b, WHIRL_EINVAL,
                      "set_mesh: the mesh must run from 0 to 1 (got %g .. %g)",
                      tau[0], tau[N]);
  for (size_t k = 1; k <= N; ++k)
    if (!(tau[k] > tau[k - 1]) || !isfinite(tau[k]))
      return WHIRL_FAIL(b, WHIRL_EINVAL,
                        "set_mesh: the mesh is not increasing at point %zu", k);
  memcpy(b->mesh, tau, (N + 1) * sizeof *tau);
  return WHIRL_OK;
}

int whirl_bvp_mesh_from(whirl_bvp *b, size_t nold, size_t mold, const double *old_mesh,
                        const double *Xold) {
  if (!b) return WHIRL_EINVAL;
  char why[160];
  double *mesh = malloc((b->ntst + 1) * sizeof *mesh);
  int rc = colloc_basis_adapt_mesh(b->n, mold, nold, 0, old_mesh, Xold, b->ntst, mesh, why,
                                   sizeof why);
  rc = rc ? WHIRL_FAIL(b, rc, "mesh_from: %s", why) : whirl_bvp_set_mesh(b, mesh);
  free(mesh);
  return rc;
}

const char *whirl_bvp_errmsg(const whirl_bvp *b) {
  return b ? b->errmsg : "whirl_bvp: NULL object";
}

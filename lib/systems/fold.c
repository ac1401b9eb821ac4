/* lib/systems/fold.c — constructor: the minimally augmented fold system of a
 * whirl_system (Govaerts 2000, ch. 4.2; Govaerts, Kuznetsov & Dhooge 2005,
 * MatCont), its codimension-two test functions, and the codimension-two
 * curves obtained by imposing one of them.  See whirl/fold.h.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/cont.h>
#include <whirl/fold.h>
#include <whirl/linsol.h>

#include "util/errmsg_impl.h"
#include "fold_sparse_impl.h"

struct whirl_fold {
  whirl_system base; /* copy; data borrowed */
  whirl_system sys;
  whirl_fold_options o;
  size_t n, N;       /* base size, fold-system size n + nfree + (cond) */
  size_t na;         /* order of the singular operator A (n for F_x) */
  size_t ne;         /* its constant entries (an operator's E) */
  size_t *e_row, *e_col;
  double *e_val;
  int point_type;    /* WHIRL_PT_LP, or the operator's */
  int sparse;        /* base with a sparse pattern: every matrix sparse */
  fold_sparse sp;
  double *b, *c;     /* borders [na]: left and right null vector estimates */
  whirl_linsol *ls;  /* dense LU of M = [A b; c^T 0], order na + 1 (or NULL:) */
  void *bws;         /* the base's structured solver of M (whirl_bsolver
                        factor_col, solve_t: condensed collocation), or NULL */
  double *rc;        /* n + 1: M's last row (c, 0) for bws */
  whirl_eig *eig;    /* eigenvalues of F_x for the zero-Hopf test */
  double *M;         /* (n+1)^2 */
  double *A;         /* F_x at the current point, n*n (sparse: nnz values) */
  double *Ap, *Am;   /* F_x at shifted points, likewise */
  double *v, *w;     /* na + 1: null vectors and g (v, w of A) */
  double *phi;       /* n + 1: F_x phi = -F_q (bordered) */
  double *pf, *pq;   /* npar: full parameter vectors */
  double *xs;        /* n: shifted state */
  double *fq, *fqp;  /* n: F_q at the point and at a shifted point */
  double *work;      /* 2n: scratch of whirl_system_jacobian / _param */
  double *Zs, *tmp;  /* N: scratch for finite differences of the cond row */
  double *gx;        /* n: the row g_x */
  double *hx;        /* n: the row of w^T F_q (a branch-point curve) */
  double *xc, *pc;   /* the point of the last null_solve (n, npar) */
  int cached;        /* 1: f->A (unless bws), the factorisation, v and w are
                        at (xc, pc) */
  double *er, *ei;   /* n: eigenvalues */
  char errmsg[WHIRL_ERRMSG_SIZE];
};

void whirl_fold_options_default(whirl_fold_options *o, size_t par) {
  memset(o, 0, sizeof *o);
  o->par = par;
  o->nfree = 1;
  o->free[0] = par;
  o->free[1] = par;
  o->cond = WHIRL_FOLD_COND_NONE;
}

void whirl_fold_params(const whirl_fold *f, const double *Z, const double *p,
                       double *pfull) {
  if (pfull != p) memcpy(pfull, p, f->base.npar * sizeof *pfull);
  for (size_t k = 0; k < f->o.nfree; ++k)
    if (!(f->o.unfold && k == 1)) pfull[f->o.free[k]] = Z[f->n + k]; /* beta: no parameter */
}

static double norm2(const double *a, size_t n) {
  double s = 0.0;
  for (size_t i = 0; i < n; ++i) s += a[i] * a[i];
  return sqrt(s);
}

static double dot(const double *a, const double *b, size_t n) {
  double s = 0.0;
  for (size_t i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

static double amax(const double *a, size_t n) {
  double s = 0.0;
  for (size_t i = 0; i < n; ++i) s = fmax(s, fabs(a[i]));
  return s;
}

/* Difference step for directional derivatives of the Jacobian: about
 * cbrt(eps) relative, which balances truncation (h^2) and rounding (eps/h)
 * for a central difference of an analytic Jacobian, each unknown on its
 * own scale (the largest relative change h |dir_i| / (1 + |x_i|) is
 * 6e-6): a long period or a large parameter beside node values of 1e-3
 * would otherwise move them by far more, and g's derivative lose its
 * digits (AUTO's tor.6 at PERIOD 400, trloc.c). */
static double hstep(const double *x, size_t n, const double *dir) {
  double r = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double q = fabs(dir[i]) / (1.0 + fabs(x[i]));
    if (q > r) r = q;
  }
  /* a direction of denormal size (a branch point's phi where F_q vanishes
   * on an invariant subspace, tfc's) moves nothing: not 1/r, which
   * overflows and makes the row NaN */
  return r > 1e-200 ? 6e-6 / r : 6e-6;
}

static int jac(whirl_fold *f, const double *x, const double *p, double *J) {
  if (f->sparse) return f->base.Fx_sparse(x, p, J, f->base.data);
  return whirl_system_jacobian(&f->base, x, p, J, f->work);
}

/* The bordered matrix [A b; c^T 0] at (x, p) factored: by the base's
 * structured solver (which evaluates F_x itself), else from the Jacobian
 * in f->A. */
static int factor_bordered(whirl_fold *f, const double *x, const double *p) {
  const size_t n = f->n, na = f->na, m = na + 1;
  if (f->bws) {
    memcpy(f->rc, f->c, n * sizeof *f->rc);
    f->rc[n] = 0.0;
    return f->base.bsolver->factor_col(f->bws, x, p, f->b, f->rc);
  }
  if (f->sparse) {
    fold_sparse_fill_m(&f->sp, f->A, f->b, f->c, f->ne, f->e_val);
    return whirl_linsol_factor(f->ls, f->sp.Mx);
  }
  for (size_t j = 0; j < na; ++j) {
    memcpy(f->M + m * j, f->A + n * j, na * sizeof *f->M);
    f->M[na + m * j] = f->c[j];
  }
  for (size_t k = 0; k < f->ne; ++k) f->M[f->e_row[k] + m * f->e_col[k]] += f->e_val[k];
  memcpy(f->M + m * na, f->b, na * sizeof *f->M);
  f->M[na + m * na] = 0.0;
  return whirl_linsol_factor(f->ls, f->M);
}

/* M u = vec (trans: M^T u = vec) in place, with the last factor_bordered. */
static int m_solve(whirl_fold *f, double *vec, int trans) {
  if (!f->bws) return whirl_linsol_solve(f->ls, vec, 1, trans);
  return trans ? f->base.bsolver->solve_t(f->bws, vec, 1)
               : f->base.bsolver->solve(f->bws, vec, 1);
}

/* F_x at (x, p) into f->A, the bordered LU of [A b; c^T 0] with A its
 * leading na x na block plus E, and the null vectors: f->v = (v, g) and
 * f->w = (w, g). */
static int null_solve(whirl_fold *f, const double *x, const double *p) {
  const size_t na = f->na, m = na + 1;
  /* the same point as the last call (F, then its Jacobian and dF/dp, at
   * every Newton iterate): F_x, the factorisation and v, w are current */
  if (f->cached && !memcmp(x, f->xc, f->n * sizeof *x) &&
      !memcmp(p, f->pc, f->base.npar * sizeof *p))
    return 0;
  f->cached = 0;
  /* (the base's structured solver evaluates F_x itself; f->A only for
   * the assembled Jacobian, fold_Fx_sparse) */
  int rc = f->bws ? 0 : jac(f, x, p, f->A);
  if (rc != 0) return rc;
  rc = factor_bordered(f, x, p);
  if (rc != WHIRL_OK)
    return WHIRL_FAIL(f, rc == WHIRL_ESINGULAR ? 1 : rc,
                      "fold system: bordered matrix [F_x b; c^T 0] is singular "
                      "(the fold is not simple here)");
  memset(f->v, 0, m * sizeof *f->v);
  f->v[na] = 1.0;
  memset(f->w, 0, m * sizeof *f->w);
  f->w[na] = 1.0;
  if ((rc = m_solve(f, f->v, 0)) != WHIRL_OK || (rc = m_solve(f, f->w, 1)) != WHIRL_OK)
    return WHIRL_FAIL(f, rc, "fold system: bordered solve failed");
  memcpy(f->xc, x, f->n * sizeof *x);
  memcpy(f->pc, p, f->base.npar * sizeof *p);
  f->cached = 1;
  return 0;
}

/* F_q(x, p) with q = o.par, into out[n]. */
static int fq_at(whirl_fold *f, const double *x, const double *p, double *out) {
  return whirl_system_param(&f->base, x, p, f->o.par, out, f->work);
}

/* w^T (Ap - Am) u: the difference of two shifted Jacobians contracted
 * with the left null vector w and u (A's block; E is constant). */
static double wdiff_dot(const whirl_fold *f, const double *u) {
  const size_t n = f->n, na = f->na;
  if (f->sparse) return fold_sparse_wdiffv(&f->sp, f->w, f->Ap, f->Am, u);
  double s = 0.0;
  for (size_t j = 0; j < na; ++j) {
    double col = 0.0;
    for (size_t i = 0; i < na; ++i)
      col += f->w[i] * (f->Ap[i + n * j] - f->Am[i + n * j]);
    s += col * u[j];
  }
  return s;
}

/* ... with the right null vector v */
static double wdiffv(const whirl_fold *f) { return wdiff_dot(f, f->v); }

/* out[j] = w^T (Ap - Am) e_j for every column j < n (rows of A's block). */
static void wdiff_cols(const whirl_fold *f, double *out) {
  const size_t n = f->n, na = f->na;
  if (f->sparse) {
    fold_sparse_wdiff_cols(&f->sp, f->w, f->Ap, f->Am, out);
    return;
  }
  for (size_t j = 0; j < n; ++j) {
    double s = 0.0;
    for (size_t i = 0; i < na; ++i) s += f->w[i] * (f->Ap[i + n * j] - f->Am[i + n * j]);
    out[j] = s;
  }
}

/* w^T F_xx[v, v] / (|w| |v|^2) from F_x at x +- h v (uses f->Ap, f->Am). */
static int cusp_value(whirl_fold *f, const double *x, const double *p,
                      double *val) {
  const size_t n = f->n;
  const double *v = f->v, *w = f->w;
  const double h = hstep(x, n, v);
  int rc;
  for (size_t i = 0; i < n; ++i) f->xs[i] = x[i] + h * v[i];
  if ((rc = jac(f, f->xs, p, f->Ap)) != 0) return rc;
  for (size_t i = 0; i < n; ++i) f->xs[i] = x[i] - h * v[i];
  if ((rc = jac(f, f->xs, p, f->Am)) != 0) return rc;
  const double s = wdiffv(f);
  const double nv = norm2(v, n), nw = norm2(w, n);
  *val = s / (2.0 * h) / (nw * nv * nv);
  return 0;
}

static double bt_value(const whirl_fold *f) {
  const size_t n = f->n;
  return dot(f->w, f->v, n) / (norm2(f->w, n) * norm2(f->v, n));
}

/* w^T F_q / (|w| |F_q|), F_q left in f->fq. */
static int mg_value(whirl_fold *f, const double *x, const double *p,
                    double *val) {
  const size_t n = f->n;
  int rc = fq_at(f, x, p, f->fq);
  if (rc != 0) return rc;
  const double nq = norm2(f->fq, n), nw = norm2(f->w, n);
  *val = dot(f->w, f->fq, n) / (nw * (nq > 0 ? nq : 1.0));
  return 0;
}

/* The value of the imposed codimension-two condition at (x, p); needs
 * null_solve done at (x, p). */
static int cond_value(whirl_fold *f, const double *x, const double *p,
                      double *val) {
  switch (f->o.cond) {
  case WHIRL_FOLD_COND_CP: return cusp_value(f, x, p, val);
  case WHIRL_FOLD_COND_BT: *val = bt_value(f); return 0;
  case WHIRL_FOLD_COND_MG: return mg_value(f, x, p, val);
  case WHIRL_FOLD_COND_BP: { /* w^T F_q itself: its row is worked out (bp_row) */
    int rc = fq_at(f, x, p, f->fq);
    *val = rc ? 0.0 : dot(f->w, f->fq, f->n);
    return rc;
  }
  default: *val = 0.0; return 0;
  }
}

static int fold_F(const double *Z, const double *p, double *out, void *data) {
  whirl_fold *f = data;
  const size_t n = f->n;
  whirl_fold_params(f, Z, p, f->pf);
  int rc = f->base.F(Z, f->pf, out, f->base.data);
  if (rc != 0) return rc;
  if ((rc = null_solve(f, Z, f->pf)) != 0) return rc;
  if (f->o.unfold) /* F + beta b */
    for (size_t i = 0; i < n; ++i) out[i] += Z[n + 1] * f->b[i];
  out[n] = f->v[f->na];
  if (f->o.cond) return cond_value(f, Z, f->pf, &out[n + 1]);
  return 0;
}

/* w^T (F_x)_r u, by the symmetry of the second derivatives (F_x)_r u =
 * (F_r)_x u: w^T (F_r(x + h u) - F_r(x - h u)) / 2h over A's rows, two
 * parameter derivatives of the base where differences of F_x in r take
 * two Jacobians; at (Z, f->pf) (uses f->xs, f->fqp, f->tmp). */
static int w_fxr_dir(whirl_fold *f, const double *Z, size_t r, const double *u, double *out) {
  const size_t n = f->n, na = f->na;
  const double h = hstep(Z, na, u);
  int rc;
  for (size_t i = 0; i < n; ++i) f->xs[i] = Z[i] + (i < na ? h * u[i] : 0.0);
  if ((rc = whirl_system_param(&f->base, f->xs, f->pf, r, f->fqp, f->work)) != 0) return rc;
  for (size_t i = 0; i < n; ++i) f->xs[i] = Z[i] - (i < na ? h * u[i] : 0.0);
  if ((rc = whirl_system_param(&f->base, f->xs, f->pf, r, f->tmp, f->work)) != 0) return rc;
  double s = 0.0;
  for (size_t i = 0; i < na; ++i) s += f->w[i] * (f->fqp[i] - f->tmp[i]);
  *out = s / (2.0 * h);
  return 0;
}

/* g_q = -w^T (F_x)_q v (Govaerts 2000, eq. 4.13), at (Z, f->pf) with
 * null_solve done there. */
static int g_param(whirl_fold *f, const double *Z, size_t q, double *gq) {
  double wv;
  int rc = w_fxr_dir(f, Z, q, f->v, &wv);
  if (rc == 0) *gq = -wv;
  return rc;
}

/* The row of g: g_x[n] into gx and g_q of the freed parameters into
 * gq[nfree], g_z = -w^T (F_x)_z v: g_x from two base Jacobians at
 * x +- h v, g_q from two parameter derivatives there (g_param; Govaerts
 * 2000, eq. 4.13), v and w padded with zeros beyond A's block;
 * null_solve done at (Z, f->pf). */
static int g_derivs(whirl_fold *f, const double *Z, double *gx, double *gq, int with_free) {
  const size_t n = f->n, na = f->na, nf = f->o.nfree;
  const double *v = f->v;
  const double h = hstep(Z, na, v);
  int rc;
  for (size_t i = 0; i < n; ++i) f->xs[i] = Z[i] + (i < na ? h * v[i] : 0.0);
  if ((rc = jac(f, f->xs, f->pf, f->Ap)) != 0) return rc;
  for (size_t i = 0; i < n; ++i) f->xs[i] = Z[i] - (i < na ? h * v[i] : 0.0);
  if ((rc = jac(f, f->xs, f->pf, f->Am)) != 0) return rc;
  wdiff_cols(f, gx);
  for (size_t j = 0; j < n; ++j) gx[j] /= -2.0 * h;
  for (size_t k = 0; with_free && k < nf; ++k) {
    gq[k] = 0.0; /* beta: F_x does not depend on it */
    if (!(f->o.unfold && k == 1) && (rc = g_param(f, Z, f->o.free[k], &gq[k])) != 0) return rc;
  }
  return 0;
}

/* phi = the x part of M^{-1} [F_q; 0] at (Z, f->pf) (b, c fixed), into
 * f->phi; null_solve done there. */
static int bp_phi(whirl_fold *f, const double *Z) {
  double *phi = f->phi;
  int rc;
  if ((rc = fq_at(f, Z, f->pf, phi)) != 0) return rc;
  phi[f->n] = 0.0;
  if ((rc = m_solve(f, phi, 0)) != WHIRL_OK)
    return WHIRL_FAIL(f, rc, "branch-point curve: the solve for F_q failed");
  return 0;
}

/* The derivatives in the parameter r of h = w^T F_q and of g, at (Z,
 * f->pf) with null_solve and bp_phi done there: with w_r^T F_q = -w^T
 * (F_x)_r phi (b, c fixed),
 *     h_r = w^T F_qr - w^T (F_x)_r phi,   g_r = -w^T (F_x)_r v,
 * from F_x and F_q at r +- hr (leaves those Jacobians in f->Ap, f->Am).
 * (w_fxr_dir's parameter derivatives at x +- h phi and x +- h v in place
 * of the two Jacobians: abcb's branch-point loci 3-4 % slower, medians
 * of 9: four evaluations of F_r cost more than two of F_x here.) */
static int bp_param(whirl_fold *f, const double *Z, size_t r, double *hr_out, double *gr_out) {
  const size_t n = f->n, np = f->base.npar;
  const double *w = f->w;
  double *fqm = f->tmp;
  const double hr = 6e-6 * (1.0 + fabs(f->pf[r]));
  int rc;
  memcpy(f->pq, f->pf, np * sizeof *f->pq);
  f->pq[r] = f->pf[r] + hr;
  if ((rc = jac(f, Z, f->pq, f->Ap)) != 0 || (rc = fq_at(f, Z, f->pq, f->fqp)) != 0) return rc;
  f->pq[r] = f->pf[r] - hr;
  if ((rc = jac(f, Z, f->pq, f->Am)) != 0 || (rc = fq_at(f, Z, f->pq, fqm)) != 0) return rc;
  double wfqr = 0.0;
  for (size_t i = 0; i < n; ++i) wfqr += w[i] * (f->fqp[i] - fqm[i]);
  *hr_out = (wfqr - wdiff_dot(f, f->phi)) / (2.0 * hr);
  *gr_out = -wdiffv(f) / (2.0 * hr);
  return 0;
}

/* The row of h = w^T F_q of a branch-point curve, at (Z, f->pf) with
 * null_solve done there: with [phi; gamma] = M^{-1} [F_q; 0] (b, c fixed,
 * so w_z^T F_q = -w^T (F_x)_z phi),
 *     h_z = w^T F_qz - w^T (F_x)_z phi,
 * h_x from base Jacobians at q +- hq (w^T F_xq, by symmetry of the second
 * derivatives) and at x +- h phi; h_q and a freed r from F_q and F_x at
 * q +- hq, r +- hr (bp_param); h_beta = 0.  hx[n], hfree[nfree]; from the
 * same Jacobians g's derivatives in the freed parameters, gfree[nfree] (as
 * g_param's), which g_derivs then leaves out. */
static int bp_row(whirl_fold *f, const double *Z, double *hx, double *hfree, double *gfree) {
  const size_t n = f->n;
  double *phi = f->phi, *fqm = f->tmp;
  int rc;
  if ((rc = bp_phi(f, Z)) != 0) return rc;
  for (size_t k = 0; k < f->o.nfree; ++k) {
    hfree[k] = gfree[k] = 0.0;
    if (f->o.unfold && k == 1) continue;
    const size_t r = f->o.free[k];
    if ((rc = bp_param(f, Z, r, &hfree[k], &gfree[k])) != 0) return rc;
    if (k == 0) { /* w^T F_xq, the first part of h_x */
      const double hr = 6e-6 * (1.0 + fabs(f->pf[r]));
      wdiff_cols(f, hx);
      for (size_t j = 0; j < n; ++j) hx[j] /= 2.0 * hr;
    }
  }
  const double h = hstep(Z, n, phi);
  for (size_t i = 0; i < n; ++i) f->xs[i] = Z[i] + h * phi[i];
  if ((rc = jac(f, f->xs, f->pf, f->Ap)) != 0) return rc;
  for (size_t i = 0; i < n; ++i) f->xs[i] = Z[i] - h * phi[i];
  if ((rc = jac(f, f->xs, f->pf, f->Am)) != 0) return rc;
  wdiff_cols(f, fqm);
  for (size_t j = 0; j < n; ++j) hx[j] -= fqm[j] / (2.0 * h);
  return 0;
}

/* dF/dp_k of the fold system into out[N] (phi_ready: bp_phi done at
 * (Z, p)): the base's F_pk and g_pk = -w^T (F_x)_pk v
 * (g_param), and on a branch-point curve h_pk (bp_param),
 * instead of differences of the whole system (each of which factors the
 * bordered operator: on abcb's branch-point curve of orbits two of the
 * three factorisations of a Newton iteration). */
static int fp_column(whirl_fold *f, const double *Z, const double *p, size_t k,
                     double *out, int phi_ready) {
  const size_t n = f->n;
  const int bp = f->o.cond == WHIRL_FOLD_COND_BP;
  for (size_t j = 0; j < f->o.nfree; ++j)
    if (f->o.free[j] == k && !(f->o.unfold && j == 1)) {
      /* an unknown of the fold system: p[k] is not read */
      memset(out, 0, f->N * sizeof *out);
      return 0;
    }
  whirl_fold_params(f, Z, p, f->pf);
  int rc = null_solve(f, Z, f->pf);
  if (rc != 0) return rc;
  if ((rc = whirl_system_param(&f->base, Z, f->pf, k, out, f->work)) != 0) return rc;
  if (!bp) return g_param(f, Z, k, &out[n]);
  if (!phi_ready && (rc = bp_phi(f, Z)) != 0) return rc;
  return bp_param(f, Z, k, &out[n + 1], &out[n]);
}

static int fold_Fp(const double *Z, const double *p, size_t k, double *out, void *data) {
  return fp_column(data, Z, p, k, out, 0);
}

/* The sparse Jacobian of the fold system in its pattern (fold_sparse.c):
 * each base column with g_x below it, then F_q and g_q. */
static int fold_Fx_sparse(const double *Z, const double *p, double *Jx, void *data) {
  whirl_fold *f = data;
  const size_t n = f->n, nf = f->o.nfree;
  const int bp = f->o.cond == WHIRL_FOLD_COND_BP;
  double gq[2], hq[2] = {0.0, 0.0};
  int rc;
  whirl_fold_params(f, Z, p, f->pf);
  if ((rc = null_solve(f, Z, f->pf)) != 0) return rc;
  if ((rc = g_derivs(f, Z, f->gx, gq, !bp)) != 0) return rc;
  if (bp && (rc = bp_row(f, Z, f->hx, hq, gq)) != 0) return rc;
  if (f->bws && (rc = jac(f, Z, f->pf, f->A)) != 0) return rc;
  size_t q = 0;
  for (size_t j = 0; j < n; ++j) {
    for (int k = f->sp.Jp[j]; k < f->sp.Jp[j + 1]; ++k) Jx[q++] = f->A[k];
    Jx[q++] = f->gx[j];
    if (bp) Jx[q++] = f->hx[j];
  }
  for (size_t k = 0; k < nf; ++k) { /* F_free (beta: b), g_free, h_free */
    if (f->o.unfold && k == 1) memcpy(Jx + q, f->b, n * sizeof *Jx);
    else if ((rc = whirl_system_param(&f->base, Z, f->pf, f->o.free[k], Jx + q, f->work)) != 0)
      return rc;
    q += n;
    Jx[q++] = gq[k];
    if (bp) Jx[q++] = hq[k];
  }
  return 0;
}

/* Jacobian of the fold system, N x N column-major: [F_x F_free; g_x g_free]
 * (g_derivs), and the cond row by central differences of its value. */
static int fold_Fx(const double *Z, const double *p, double *J, void *data) {
  whirl_fold *f = data;
  const size_t n = f->n, N = f->N, nf = f->o.nfree;
  int rc;
  whirl_fold_params(f, Z, p, f->pf);
  if ((rc = null_solve(f, Z, f->pf)) != 0) return rc;
  memset(J, 0, N * N * sizeof *J);
  for (size_t j = 0; j < n; ++j)
    memcpy(J + N * j, f->A + n * j, n * sizeof *J);
  for (size_t k = 0; k < nf; ++k) {
    if (f->o.unfold && k == 1) { /* beta's column: b */
      memcpy(J + N * (n + k), f->b, n * sizeof *J);
      continue;
    }
    rc = whirl_system_param(&f->base, Z, f->pf, f->o.free[k], f->fq, f->work);
    if (rc != 0) return rc;
    memcpy(J + N * (n + k), f->fq, n * sizeof *J);
  }
  double gq[2];
  if ((rc = g_derivs(f, Z, f->gx, gq, 1)) != 0) return rc;
  for (size_t j = 0; j < n; ++j) J[n + N * j] = f->gx[j];
  for (size_t k = 0; k < nf; ++k) J[n + N * (n + k)] = gq[k];
  if (f->o.cond) {
    /* the imposed condition: central differences of its value */
    for (size_t j = 0; j < N; ++j) {
      const double hz = 1e-6 * (1.0 + fabs(Z[j]));
      double vp, vm;
      memcpy(f->Zs, Z, N * sizeof *f->Zs);
      f->Zs[j] = Z[j] + hz;
      whirl_fold_params(f, f->Zs, p, f->pq);
      if ((rc = null_solve(f, f->Zs, f->pq)) != 0) return rc;
      if ((rc = cond_value(f, f->Zs, f->pq, &vp)) != 0) return rc;
      f->Zs[j] = Z[j] - hz;
      whirl_fold_params(f, f->Zs, p, f->pq);
      if ((rc = null_solve(f, f->Zs, f->pq)) != 0) return rc;
      if ((rc = cond_value(f, f->Zs, f->pq, &vm)) != 0) return rc;
      J[n + 1 + N * j] = (vp - vm) / (2.0 * hz);
    }
  }
  return 0;
}

/* Zero-Hopf test: the bialternate product prod_{i<j} (l_i + l_j) over the
 * eigenvalues of F_x without the one nearest 0 (Govaerts 2000, ch. 4.4).
 * It vanishes when a complex pair crosses the imaginary axis (ZH) and at
 * neutral saddles (a real pair l, -l), which are not reported. */
static int zh_value(whirl_fold *f, double *val, int *type) {
  const size_t n = f->n;
  *val = 1.0;
  *type = 0;
  if (n < 3 || !f->eig || f->sparse) return 0; /* (sparse: no dense eigenvalues) */
  int rc = whirl_eig_compute(f->eig, f->A, f->er, f->ei);
  if (rc != WHIRL_OK) return 0;
  size_t k0 = 0;
  for (size_t i = 1; i < n; ++i)
    if (hypot(f->er[i], f->ei[i]) < hypot(f->er[k0], f->ei[k0])) k0 = i;
  double complex prod = 1.0;
  double best = INFINITY;
  int best_pair = 0;
  for (size_t i = 0; i < n; ++i) {
    if (i == k0) continue;
    for (size_t j = i + 1; j < n; ++j) {
      if (j == k0) continue;
      const double complex li = f->er[i] + I * f->ei[i];
      const double complex lj = f->er[j] + I * f->ei[j];
      const double sc = 1.0 + cabs(li) + cabs(lj);
      prod *= (li + lj) / sc;
      const double r = cabs(li + lj) / sc;
      if (r < best) {
        best = r;
        best_pair = f->ei[i] != 0.0 &&
                    fabs(f->ei[i] + f->ei[j]) <= 1e-8 * (1.0 + fabs(f->ei[i]));
      }
    }
  }
  *val = creal(prod);
  *type = best_pair ? WHIRL_PT_ZH : 0;
  return 0;
}

/* Second directional derivative along u of the map (x, q) -> [F_x F_q] u2,
 * contracted with w: w^T D^2F[u, u2] by a central difference. */
static int hess_wd(whirl_fold *f, const double *x, const double *p,
                   const double *u, const double *u2, double *val) {
  const size_t n = f->n;
  const size_t q = f->o.par;
  const double h = 6e-6 * (1.0 + amax(x, n) + fabs(p[q])) /
                   fmax(fmax(amax(u, n), fabs(u[n])), 1e-300);
  double s[2];
  for (int side = 0; side < 2; ++side) {
    const double sg = side ? -1.0 : 1.0;
    for (size_t i = 0; i < n; ++i) f->xs[i] = x[i] + sg * h * u[i];
    memcpy(f->pq, p, f->base.npar * sizeof *f->pq);
    f->pq[q] = p[q] + sg * h * u[n];
    int rc = jac(f, f->xs, f->pq, f->Ap);
    if (rc != 0) return rc;
    if ((rc = fq_at(f, f->xs, f->pq, f->fqp)) != 0) return rc;
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) acc += f->w[i] * f->fqp[i] * u2[n];
    if (f->sparse) acc += fold_sparse_wju(&f->sp, f->w, f->Ap, u2);
    else
      for (size_t i = 0; i < n; ++i) {
        double r = 0.0;
        for (size_t j = 0; j < n; ++j) r += f->Ap[i + n * j] * u2[j];
        acc += f->w[i] * r;
      }
    s[side] = acc;
  }
  *val = (s[0] - s[1]) / (2.0 * h);
  return 0;
}

/* Isola centre or merge: the sign of the reduced Hessian of the base
 * problem in (x, q) restricted to span{(v, 0), (phi, 1)}, F_x phi = -F_q.
 * Definite: the solution set is locally a point that grows into an isola
 * (IS); indefinite: two branches cross and separate (MG). */
static int classify_mg(whirl_fold *f, const double *x, const double *p,
                       int *type) {
  const size_t n = f->n;
  double *u1 = f->tmp; /* N >= n + 1 entries */
  memcpy(u1, f->v, n * sizeof *u1);
  u1[n] = 0.0;
  for (size_t i = 0; i < n; ++i) f->phi[i] = -f->fq[i];
  f->phi[n] = 0.0;
  int rc = m_solve(f, f->phi, 0);
  if (rc != WHIRL_OK)
    return WHIRL_FAIL(f, rc, "fold system: solve for F_q failed");
  f->phi[n] = 1.0;
  double q11, q12, q22;
  if ((rc = hess_wd(f, x, p, u1, u1, &q11)) != 0) return rc;
  if ((rc = hess_wd(f, x, p, u1, f->phi, &q12)) != 0) return rc;
  if ((rc = hess_wd(f, x, p, f->phi, f->phi, &q22)) != 0) return rc;
  *type = q11 * q22 - q12 * q12 > 0 ? WHIRL_PT_IS : WHIRL_PT_MG;
  return 0;
}

static int fold_test(const double *Z, const double *p, double *tau, int *types,
                     void *data) {
  whirl_fold *f = data;
  int rc;
  whirl_fold_params(f, Z, p, f->pf);
  if ((rc = null_solve(f, Z, f->pf)) != 0) return rc;
  const int eig = f->base.spectrum && f->base.spectrum_kind == WHIRL_SPEC_EIGENVALUES;
  tau[WHIRL_FOLD_TEST_BT] = bt_value(f);
  types[WHIRL_FOLD_TEST_BT] = eig ? WHIRL_PT_BT : 0;
  if ((rc = mg_value(f, Z, f->pf, &tau[WHIRL_FOLD_TEST_MG])) != 0) return rc;
  /* IS or MG (six Jacobians): the type counts only where the core has
   * localised a zero of the value, so it is worked out only near one */
  types[WHIRL_FOLD_TEST_MG] = WHIRL_PT_MG;
  if (fabs(tau[WHIRL_FOLD_TEST_MG]) < 1e-6 &&
      (rc = classify_mg(f, Z, f->pf, &types[WHIRL_FOLD_TEST_MG])) != 0)
    return rc;
  /* zero-Hopf: eigenvalues of F_x, a question about equilibria only (of
   * an orbit's collocation Jacobian they mean nothing: not computed) */
  tau[WHIRL_FOLD_TEST_ZH] = 1.0;
  types[WHIRL_FOLD_TEST_ZH] = 0;
  if (eig && (rc = zh_value(f, &tau[WHIRL_FOLD_TEST_ZH], &types[WHIRL_FOLD_TEST_ZH])) != 0)
    return rc;
  if ((rc = cusp_value(f, Z, f->pf, &tau[WHIRL_FOLD_TEST_CP])) != 0) return rc;
  types[WHIRL_FOLD_TEST_CP] = WHIRL_PT_CP;
  return 0;
}

/* New borders from the null vectors at every accepted point, so M stays
 * well conditioned along the curve; signs follow continuously. */
static int fold_accept(const double *Z, const double *p, void *data) {
  whirl_fold *f = data;
  whirl_fold_params(f, Z, p, f->pf);
  int rc = null_solve(f, Z, f->pf);
  if (rc != 0) return rc < 0 ? rc : 0; /* keep the old borders */
  const size_t na = f->na;
  const double nv = norm2(f->v, na), nw = norm2(f->w, na);
  if (nv > 0 && nw > 0 && isfinite(nv) && isfinite(nw))
    for (size_t i = 0; i < na; ++i) {
      f->c[i] = f->v[i] / nv;
      f->b[i] = f->w[i] / nw;
    }
  f->cached = 0; /* new borders; the base's accept may change F_x (phase) */
  if (f->base.accept) return f->base.accept(Z, f->pf, f->base.data);
  return 0;
}

/* A new mesh of the base (AUTO's IAD on a locus of orbits or of a BVP):
 * the core's vectors and the right border c (a vector of the base's
 * unknowns) mapped by the base, the locus's own unknowns as they are.  The
 * left border b is a vector of the equations, which a new mesh orders as
 * the old one: kept, since any b with w^T b != 0 serves and the next
 * accepted point sets b = w. */
enum { FOLD_REMAP_MAX = 15 };
static int fold_remap(double *const *v, size_t nv, const double *p, void *data) {
  whirl_fold *f = data;
  double *vv[FOLD_REMAP_MAX + 1];
  if (nv > FOLD_REMAP_MAX) return WHIRL_EINVAL;
  for (size_t i = 0; i < nv; ++i) vv[i] = v[i];
  vv[nv] = f->c;
  const int rc = f->base.remap(vv, nv + 1, p, f->base.data);
  if (rc != 0) f->cached = 0;
  return rc;
}

/* The base's norm weights on its unknowns (a collocation's or a BVP's
 * node values by the quadrature: AUTO's integral norm), 1 on the
 * locus's own. */
static int fold_norm_weights(double *q, void *data) {
  whirl_fold *f = data;
  const int rc = f->base.norm_weights(q, f->base.data);
  for (size_t i = f->n; i < f->N; ++i) q[i] = 1.0;
  return rc;
}

/* ------------------------------------------------------------------------
 * The fold system's structured solver (whirl_system bsolver), on the
 * sparse path.  The core's Newton matrix of the fold system is
 *     K = [F_x U; W^T D],   U = [F_free F_pk] (n x m, m = nfree + 1),
 *     W^T = [g_x; (h_x;) r_x],  D = [g_free g_pk; (h_free h_pk;) r_free r_pk],
 * whose leading block is singular at the fold.  It is solved with the
 * factors of M = [F_x b; c^T 0], which the fold system has anyway for its
 * null vectors, where the core factored K by a sparse LU once more: with
 * [Z; S] = M^{-1} [U; 0] and [v; g] = M^{-1} [0; 1], the solution of
 * K (z, y) = (f, h) is z = z1 - Z y + gamma v, [z1; s1] = M^{-1} [f; 0],
 * where
 *     [D - W^T Z   W^T v] [y    ]   [h - W^T z1]
 *     [   -S         g  ] [gamma] = [   -s1    ],
 * and det K = det M times the determinant of that (m + 1)-matrix (K
 * extended by s = c^T z - gamma and gamma, then block elimination by M:
 * Govaerts 2000, ch. 3, bordered systems with a singular block). */
typedef struct fold_bem {
  whirl_fold *f;
  size_t m;           /* K's border: nfree + 1 */
  double *Zc;         /* (n + 1) x m: [U; 0], then M^{-1} [U; 0] */
  double *Wt;         /* m x n: the rows g_x, (h_x,) r_x */
  double *D;          /* m x m, row-major */
  double S[16];       /* the (m + 1)-matrix, row-major, factored in place */
  int piv[4];
  double logabs;      /* log|det K| and its sign */
  int sign, state;    /* state: 0 none, 1 factored, 2 singular */
  double *t;          /* N + 1 scratch */
} fold_bem;

static void *bem_alloc(void *data) {
  whirl_fold *f = data;
  const size_t n = f->n, m = f->o.nfree + 1;
  fold_bem *e = calloc(1, sizeof *e);
  if (!e) return NULL;
  e->f = f;
  e->m = m;
  e->Zc = calloc((n + 1) * m, sizeof *e->Zc);
  e->Wt = calloc(m * n, sizeof *e->Wt);
  e->D = calloc(m * m, sizeof *e->D);
  e->t = calloc(f->N + 2, sizeof *e->t);
  if (!e->Zc || !e->Wt || !e->D || !e->t) {
    free(e->Zc), free(e->Wt), free(e->D), free(e->t), free(e);
    return NULL;
  }
  return e;
}

static void bem_free(void *ws) {
  fold_bem *e = ws;
  if (!e) return;
  free(e->Zc), free(e->Wt), free(e->D), free(e->t), free(e);
}

/* The (m + 1)-matrix from Zc, Wt, D and the null vector, LU with partial
 * pivoting; det K with M's determinant. */
static int bem_schur(fold_bem *e) {
  whirl_fold *f = e->f;
  const size_t n = f->n, m = e->m, q = m + 1;
  double *S = e->S;
  for (size_t i = 0; i < m; ++i) {
    const double *wi = e->Wt + n * i;
    for (size_t j = 0; j < m; ++j) S[q * i + j] = e->D[m * i + j] - dot(wi, e->Zc + (n + 1) * j, n);
    S[q * i + m] = dot(wi, f->v, n);
  }
  for (size_t j = 0; j < m; ++j) S[q * m + j] = -e->Zc[(n + 1) * j + n];
  S[q * m + m] = f->v[n];
  double la;
  int sg, rc = f->bws ? f->base.bsolver->logdet(f->bws, &la, &sg)
                      : whirl_linsol_logdet(f->ls, &la, &sg);
  if (rc != WHIRL_OK) return rc;
  for (size_t c = 0; c < q; ++c) {
    size_t pr = c;
    for (size_t r = c + 1; r < q; ++r)
      if (fabs(S[q * r + c]) > fabs(S[q * pr + c])) pr = r;
    e->piv[c] = (int)pr;
    if (!(fabs(S[q * pr + c]) > 0.0)) {
      e->state = 2;
      return WHIRL_ESINGULAR;
    }
    if (pr != c) {
      sg = -sg;
      for (size_t k = 0; k < q; ++k) {
        const double tmp = S[q * c + k];
        S[q * c + k] = S[q * pr + k], S[q * pr + k] = tmp;
      }
    }
    const double d = S[q * c + c];
    la += log(fabs(d));
    if (d < 0.0) sg = -sg;
    for (size_t r = c + 1; r < q; ++r) {
      const double l = S[q * r + c] / d;
      S[q * r + c] = l;
      for (size_t k = c + 1; k < q; ++k) S[q * r + k] -= l * S[q * c + k];
    }
  }
  if (!isfinite(la)) return WHIRL_EBADFUNC;
  e->logabs = la, e->sign = sg, e->state = 1;
  return WHIRL_OK;
}

/* The core's border r: the last row of W^T and of D. */
static void bem_border(fold_bem *e, const double *r) {
  const size_t n = e->f->n, m = e->m;
  memcpy(e->Wt + n * (m - 1), r, n * sizeof *e->Wt);
  memcpy(e->D + m * (m - 1), r + n, m * sizeof *e->D);
}

static int bem_factor(void *ws, const double *Z, const double *p, size_t k, const double *r) {
  fold_bem *e = ws;
  whirl_fold *f = e->f;
  const size_t n = f->n, nf = f->o.nfree, m = e->m;
  const int bp = f->o.cond == WHIRL_FOLD_COND_BP;
  double gq[2] = {0.0, 0.0}, hq[2] = {0.0, 0.0};
  e->state = 0;
  whirl_fold_params(f, Z, p, f->pf);
  int rc = null_solve(f, Z, f->pf);
  if (rc == 0) rc = g_derivs(f, Z, f->gx, gq, !bp);
  if (rc == 0 && bp) rc = bp_row(f, Z, f->hx, hq, gq);
  /* [F_pk; g_pk; (h_pk)], phi of bp_row still current at (Z, f->pf) */
  if (rc == 0) rc = fp_column(f, Z, p, k, e->t, bp);
  if (rc != 0) return rc;
  memcpy(e->Wt, f->gx, n * sizeof *e->Wt);
  if (bp) memcpy(e->Wt + n, f->hx, n * sizeof *e->Wt);
  for (size_t j = 0; j < nf; ++j) {
    double *u = e->Zc + (n + 1) * j;
    if (f->o.unfold && j == 1) memcpy(u, f->b, n * sizeof *u); /* beta's column */
    else if ((rc = whirl_system_param(&f->base, Z, f->pf, f->o.free[j], u, f->work)) != 0)
      return rc;
    e->D[j] = gq[j];
    if (bp) e->D[m + j] = hq[j];
  }
  double *u = e->Zc + (n + 1) * nf;
  memcpy(u, e->t, n * sizeof *u);
  e->D[nf] = e->t[n];
  if (bp) e->D[m + nf] = e->t[n + 1];
  bem_border(e, r);
  for (size_t j = 0; j < m; ++j) {
    e->Zc[(n + 1) * j + n] = 0.0;
    if ((rc = m_solve(f, e->Zc + (n + 1) * j, 0)) != WHIRL_OK) return rc;
  }
  return bem_schur(e);
}

static int bem_reborder(void *ws, const double *r) {
  fold_bem *e = ws;
  if (e->state == 0) return WHIRL_EINVAL;
  bem_border(e, r);
  return bem_schur(e);
}

static int bem_solve(void *ws, double *b, size_t nrhs) {
  fold_bem *e = ws;
  whirl_fold *f = e->f;
  const size_t n = f->n, m = e->m, q = m + 1, N1 = f->N + 1;
  if (e->state != 1) return WHIRL_ESINGULAR;
  double *t = e->t, y[4];
  for (size_t k = 0; k < nrhs; ++k) {
    double *bk = b + N1 * k;
    memcpy(t, bk, n * sizeof *t);
    t[n] = 0.0;
    int rc = m_solve(f, t, 0);
    if (rc != WHIRL_OK) return rc;
    for (size_t i = 0; i < m; ++i) y[i] = bk[n + i] - dot(e->Wt + n * i, t, n);
    y[m] = -t[n];
    /* the (m + 1)-matrix's LU, whole rows swapped: the swaps first */
    for (size_t c = 0; c < q; ++c) {
      const size_t pr = (size_t)e->piv[c];
      const double tmp = y[c];
      y[c] = y[pr], y[pr] = tmp;
    }
    for (size_t c = 0; c < q; ++c)
      for (size_t r = c + 1; r < q; ++r) y[r] -= e->S[q * r + c] * y[c];
    for (size_t c = q; c-- > 0;) {
      for (size_t kk = c + 1; kk < q; ++kk) y[c] -= e->S[q * c + kk] * y[kk];
      y[c] /= e->S[q * c + c];
    }
    for (size_t i = 0; i < n; ++i) {
      double z = t[i] + y[m] * f->v[i];
      for (size_t j = 0; j < m; ++j) z -= e->Zc[(n + 1) * j + i] * y[j];
      bk[i] = z;
    }
    memcpy(bk + n, y, m * sizeof *bk);
  }
  return WHIRL_OK;
}

static int bem_logdet(void *ws, double *logabs, int *sign) {
  const fold_bem *e = ws;
  if (e->state == 0) return WHIRL_EINVAL;
  *logabs = e->state == 2 ? -INFINITY : e->logabs;
  *sign = e->state == 2 ? 0 : e->sign;
  return WHIRL_OK;
}

static const whirl_bsolver fold_bem_solver = {bem_alloc, bem_free, bem_factor, bem_solve,
                                              bem_logdet, bem_reborder, NULL, NULL, NULL};

/* The sparse path: a base with a sparse pattern, large enough that dense
 * LUs of order n dominate (collocation orbits), and no imposed condition
 * but the branch points' (the others' rows are differenced densely). */
static int use_sparse(const whirl_system *base, const whirl_fold_options *o) {
  return base->Fx_sparse && base->Jp && base->Ji && base->nnz > 0 && base->n > 100 &&
         ((o->cond == WHIRL_FOLD_COND_NONE && o->nfree == 1) ||
          (o->cond == WHIRL_FOLD_COND_BP && o->nfree == 2));
}

static int operator_valid(const whirl_fold_operator *op, size_t n) {
  if (op->na < 1 || op->na > n || (op->ne && (!op->ei || !op->ej || !op->ev))) return 0;
  for (size_t k = 0; k < op->ne; ++k)
    if (op->ei[k] >= op->na || op->ej[k] >= op->na || !isfinite(op->ev[k])) return 0;
  return 1;
}

/* The operator's constant entries, copied. */
static int copy_operator(whirl_fold *f, const whirl_fold_operator *op) {
  f->na = op ? op->na : f->n;
  f->point_type = op ? op->point_type : WHIRL_PT_LP;
  f->ne = op ? op->ne : 0;
  if (!f->ne) return 0;
  f->e_row = malloc(f->ne * sizeof *f->e_row);
  f->e_col = malloc(f->ne * sizeof *f->e_col);
  f->e_val = malloc(f->ne * sizeof *f->e_val);
  if (!f->e_row || !f->e_col || !f->e_val) return -1;
  memcpy(f->e_row, op->ei, f->ne * sizeof *f->e_row);
  memcpy(f->e_col, op->ej, f->ne * sizeof *f->e_col);
  memcpy(f->e_val, op->ev, f->ne * sizeof *f->e_val);
  return 0;
}

whirl_fold *whirl_fold_alloc(const whirl_system *base,
                             const whirl_fold_options *o, char *errbuf,
                             size_t errlen) {
  const char *why = NULL;
  if (!base || !base->F || base->n == 0) why = "base system has no F";
  else if (!o) why = "no options";
  else if (o->par >= base->npar) why = "fold parameter is not a parameter of the base system";
  else if (o->nfree < 1 || o->nfree > 2) why = "nfree must be 1 or 2";
  else if (o->unfold && o->cond != WHIRL_FOLD_COND_BP)
    why = "unfold (beta) belongs to a branch-point curve (cond BP)";
  else if (o->free[0] >= base->npar ||
           (o->nfree == 2 && !o->unfold && o->free[1] >= base->npar))
    why = "a freed parameter is not a parameter of the base system";
  else if (o->nfree == 2 && !o->unfold && o->free[0] == o->free[1])
    why = "the two freed parameters are the same";
  else if (o->cond < WHIRL_FOLD_COND_NONE || o->cond > WHIRL_FOLD_COND_BP)
    why = "unknown codimension-two condition";
  else if ((o->cond != WHIRL_FOLD_COND_NONE) != (o->nfree == 2))
    why = "a codimension-two condition needs exactly two freed parameters "
          "(and two freed parameters need a condition)";
  else if (o->op && o->cond != WHIRL_FOLD_COND_NONE)
    why = "an operator's curve has no codimension-two conditions";
  else if (o->op && !operator_valid(o->op, base->n))
    why = "the operator needs 1 <= na <= n and its entries within na";
  if (why) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_fold_alloc: %s", why);
    return NULL;
  }
  whirl_fold *f = calloc(1, sizeof *f);
  if (!f) goto nomem;
  const size_t n = base->n;
  f->base = *base;
  f->o = *o;
  f->n = n;
  f->N = n + o->nfree;
  f->o.op = NULL; /* copied below */
  if (copy_operator(f, o->op) != 0) goto nomem;
  if (o->cond == WHIRL_FOLD_COND_BP) f->point_type = WHIRL_PT_BP;
  const size_t na = f->na;
  f->sparse = use_sparse(base, o);
  if (f->sparse && fold_sparse_alloc(&f->sp, base, na, f->ne, f->e_row, f->e_col, o->nfree,
                                     o->cond ? 2 : 1))
    goto nomem;
  const size_t nj = f->sparse ? (base->nnz ? base->nnz : 1) : n * n;
  f->b = calloc(n, sizeof *f->b);
  f->c = calloc(n, sizeof *f->c);
  /* M by the base's structured solver where it has one that takes b and
   * solves transposed (condensed collocation: AUTO's cost per iteration
   * where KLU on M cost 4x, doc/benchmarks.md), F_x's own singularity */
  const whirl_bsolver *bs = base->bsolver;
  if (f->sparse && bs && bs->factor_col && bs->solve_t && na == n && f->ne == 0 &&
      !getenv("WHIRL_FOLD_KLU"))
    f->bws = bs->alloc(base->data);
  f->rc = calloc(n + 1, sizeof *f->rc);
  f->ls = f->bws ? NULL
          : f->sparse ? whirl_linsol_alloc_sparse(na + 1, f->sp.Mp, f->sp.Mi)
                      : whirl_linsol_alloc_dense(na + 1);
  f->eig = n >= 3 && !o->op && !f->sparse ? whirl_eig_alloc(n) : NULL;
  f->M = f->sparse ? calloc(1, sizeof *f->M) : calloc((na + 1) * (na + 1), sizeof *f->M);
  f->A = calloc(nj, sizeof *f->A);
  f->Ap = calloc(nj, sizeof *f->Ap);
  f->Am = calloc(nj, sizeof *f->Am);
  f->gx = calloc(n, sizeof *f->gx);
  f->hx = calloc(n, sizeof *f->hx);
  f->xc = calloc(n, sizeof *f->xc);
  f->pc = calloc(base->npar, sizeof *f->pc);
  f->v = calloc(n + 1, sizeof *f->v);
  f->w = calloc(n + 1, sizeof *f->w);
  f->phi = calloc(n + 1, sizeof *f->phi);
  f->pf = calloc(base->npar, sizeof *f->pf);
  f->pq = calloc(base->npar, sizeof *f->pq);
  f->xs = calloc(n, sizeof *f->xs);
  f->fq = calloc(n, sizeof *f->fq);
  f->fqp = calloc(n, sizeof *f->fqp);
  /* whirl_system_jacobian's scratch: max(2n, nnz) (the sparse values) */
  f->work = calloc(2 * n + 2 + base->nnz, sizeof *f->work);
  f->Zs = calloc(f->N, sizeof *f->Zs);
  f->tmp = calloc(f->N, sizeof *f->tmp);
  f->er = calloc(n, sizeof *f->er);
  f->ei = calloc(n, sizeof *f->ei);
  if (!f->b || !f->c || !f->rc || (!f->ls && !f->bws) || (n >= 3 && !o->op && !f->sparse && !f->eig) || !f->M ||
      !f->A || !f->gx || !f->hx || !f->xc || !f->pc ||
      !f->Ap || !f->Am || !f->v || !f->w || !f->phi || !f->pf || !f->pq ||
      !f->xs || !f->fq || !f->fqp || !f->work || !f->Zs ||
      !f->tmp || !f->er || !f->ei)
    goto nomem;
  f->b[0] = f->c[0] = 1.0;
  whirl_system *s = &f->sys;
  memset(s, 0, sizeof *s);
  s->name = o->op && o->op->name ? o->op->name
            : o->op                         ? "singular-operator curve"
            : o->cond == WHIRL_FOLD_COND_CP ? "cusp curve"
            : o->cond == WHIRL_FOLD_COND_BT ? "Bogdanov-Takens curve"
            : o->cond == WHIRL_FOLD_COND_MG ? "isola/merge curve"
            : o->cond == WHIRL_FOLD_COND_BP ? (o->unfold ? "branch-point curve (symmetric)"
                                                         : "branch-point curve (generic)")
                                            : "fold curve";
  s->n = f->N;
  s->npar = base->npar;
  s->F = fold_F;
  s->Fx = f->sparse ? NULL : fold_Fx;
  if (f->sparse) {
    s->nnz = f->sp.snz;
    s->Jp = f->sp.Sp;
    s->Ji = f->sp.Si;
    s->Fx_sparse = fold_Fx_sparse;
    /* (an operator's A is not F_x's block: K's general LU) */
    if (na == n && f->ne == 0 && !getenv("WHIRL_FOLD_KLU")) s->bsolver = &fold_bem_solver;
  }
  s->Fp = o->cond == WHIRL_FOLD_COND_NONE || o->cond == WHIRL_FOLD_COND_BP ? fold_Fp : NULL;
  s->accept = fold_accept;
  s->remap = base->remap ? fold_remap : NULL;
  s->norm_weights = base->norm_weights ? fold_norm_weights : NULL;
  s->ntest = o->cond || o->op ? 0 : WHIRL_FOLD_NTEST;
  s->test = o->cond || o->op ? NULL : fold_test;
  s->p_names = base->p_names;
  s->data = f;
  return f;
nomem:
  whirl_fold_free(f);
  WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "whirl_fold_alloc: out of memory");
  return NULL;
}

void whirl_fold_free(whirl_fold *f) {
  if (!f) return;
  whirl_linsol_free(f->ls);
  if (f->bws) f->base.bsolver->free(f->bws);
  free(f->rc);
  whirl_eig_free(f->eig);
  free(f->b); free(f->c); free(f->M); free(f->A); free(f->Ap); free(f->Am);
  free(f->v); free(f->w); free(f->phi); free(f->pf); free(f->pq);
  free(f->xs); free(f->fq); free(f->fqp); free(f->work);
  free(f->Zs); free(f->tmp); free(f->er); free(f->ei);
  free(f->e_row); free(f->e_col); free(f->e_val); free(f->gx); free(f->hx); free(f->xc); free(f->pc);
  fold_sparse_free(&f->sp);
  free(f);
}

const whirl_system *whirl_fold_system(const whirl_fold *f) { return &f->sys; }
size_t whirl_fold_size(const whirl_fold *f) { return f->N; }
const char *whirl_fold_errmsg(const whirl_fold *f) { return f->errmsg; }

/* The operator A at the last jac(): the leading na x na block of f->A
 * plus E, column-major with leading dimension na, into out. */
static void operator_matrix(const whirl_fold *f, double *out) {
  const size_t n = f->n, na = f->na;
  for (size_t j = 0; j < na; ++j) memcpy(out + na * j, f->A + n * j, na * sizeof *out);
  for (size_t k = 0; k < f->ne; ++k) out[f->e_row[k] + na * f->e_col[k]] += f->e_val[k];
}

/* Sparse start: borders from a fixed pseudo-random pair, then twice the
 * null vectors of [A b; c^T 0] as the new borders — at a singular A the
 * bordered solves give its null vectors exactly (inverse iteration
 * without an SVD of order na). */
static int sparse_borders(whirl_fold *f, const double *x, const double *p) {
  const size_t na = f->na, m = na + 1;
  unsigned long long r = 88172645463325252ULL;
  for (size_t i = 0; i < na; ++i) { /* xorshift64 */
    r ^= r << 13, r ^= r >> 7, r ^= r << 17;
    f->c[i] = (double)(r >> 11) / 9007199254740992.0 - 0.5;
    r ^= r << 13, r ^= r >> 7, r ^= r << 17;
    f->b[i] = (double)(r >> 11) / 9007199254740992.0 - 0.5;
  }
  f->cached = 0;
  for (int pass = 0; pass < 2; ++pass) {
    int rc = factor_bordered(f, x, p);
    if (rc != WHIRL_OK) return rc;
    memset(f->v, 0, m * sizeof *f->v);
    memset(f->w, 0, m * sizeof *f->w);
    f->v[na] = f->w[na] = 1.0;
    if ((rc = m_solve(f, f->v, 0)) != WHIRL_OK || (rc = m_solve(f, f->w, 1)) != WHIRL_OK)
      return rc;
    const double nv = norm2(f->v, na), nw = norm2(f->w, na);
    if (!(nv > 0) || !(nw > 0) || !isfinite(nv) || !isfinite(nw)) return WHIRL_ESINGULAR;
    for (size_t i = 0; i < na; ++i) f->c[i] = f->v[i] / nv, f->b[i] = f->w[i] / nw;
  }
  return WHIRL_OK;
}

int whirl_fold_init(whirl_fold *f, const double *x, const double *p, double *Z) {
  const size_t n = f->n, na = f->na;
  for (size_t i = 0; i < n; ++i)
    if (!isfinite(x[i]))
      return WHIRL_FAIL(f, WHIRL_EINVAL, "fold start: x[%zu] is not finite", i);
  f->cached = 0;
  int rc = jac(f, x, p, f->A);
  if (rc != 0)
    return WHIRL_FAIL(f, rc < 0 ? rc : WHIRL_EDOMAIN,
                      "fold start: the Jacobian failed (%d)", rc);
  if (f->sparse) {
    if ((rc = sparse_borders(f, x, p)) != WHIRL_OK)
      return WHIRL_FAIL(f, rc, "fold start: the bordered operator [A b; c^T 0] is "
                        "singular (the point is not a simple fold or PD)");
    memcpy(Z, x, n * sizeof *Z);
    for (size_t k = 0; k < f->o.nfree; ++k)
      Z[n + k] = f->o.unfold && k == 1 ? 0.0 : p[f->o.free[k]];
    f->errmsg[0] = 0;
    return WHIRL_OK;
  }
  double sv;
  operator_matrix(f, f->Am);
  rc = whirl_null_vectors(na, na, f->Am, 1, f->c, &sv);
  if (rc != WHIRL_OK) return WHIRL_FAIL(f, rc, "fold start: SVD of F_x failed");
  operator_matrix(f, f->Am);
  for (size_t i = 0; i < na; ++i)
    for (size_t j = 0; j < na; ++j) f->Ap[j + na * i] = f->Am[i + na * j];
  rc = whirl_null_vectors(na, na, f->Ap, 1, f->b, &sv);
  if (rc != WHIRL_OK)
    return WHIRL_FAIL(f, rc, "fold start: SVD of F_x^T failed");
  memcpy(Z, x, n * sizeof *Z);
  for (size_t k = 0; k < f->o.nfree; ++k)
    Z[n + k] = f->o.unfold && k == 1 ? 0.0 : p[f->o.free[k]];
  f->errmsg[0] = 0;
  return WHIRL_OK;
}

int whirl_fold_point_type(const whirl_fold *f) { return f->point_type; }

int whirl_fold_vectors(whirl_fold *f, const double *Z, const double *p,
                       double *v, double *w, double *g, double *tau) {
  const size_t na = f->na;
  whirl_fold_params(f, Z, p, f->pf);
  int rc = null_solve(f, Z, f->pf);
  if (rc != 0) return rc;
  const double gv = f->v[na];
  if (v) memcpy(v, f->v, na * sizeof *v);
  if (w) memcpy(w, f->w, na * sizeof *w);
  if (g) *g = gv;
  if (tau && !f->o.op) {
    int types[WHIRL_FOLD_NTEST];
    memcpy(f->Zs, Z, f->N * sizeof *f->Zs);
    rc = fold_test(f->Zs, p, tau, types, f);
  }
  return rc;
}

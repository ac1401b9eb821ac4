/* lib/systems/trloc.c — constructor: the torus (Neimark–Sacker) locus of
 * periodic orbits by complex minimal augmentation (Doedel, Govaerts &
 * Kuznetsov, SIAM J. Numer. Anal. 41 (2003) 401, §5).  See whirl/trloc.h.
 *
 * A(θ) is eliminated by the orbit's structure (twist_elim.h: each
 * interval's interior, then the mesh nodes, row pivoting as AUTO-07p's
 * condensation), all in real arithmetic but for its last n × n block
 * S(θ), whose bordered matrix K = [S b; c^H 0] gives g, v(0) and the
 * adjoint's w0; v and w on the whole mesh follow by back substitution
 * and the transposed row operations.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/trloc.h>

#include "twist_elim.h"
#include "util/errmsg_impl.h"

/* Where a base Jacobian entry goes: an interval's block, the boundary
 * rows' block in v(0) or in v(1), or nowhere (outside A's block). */
enum { TO_NONE, TO_BLOCK, TO_B0, TO_BN };

struct whirl_trloc {
  whirl_system base, sys;
  size_t par, n, N, na, ne, nnz;
  long par2;               /* −1: θ is the last unknown; else that
                              parameter, θ fixed at theta */
  double theta;
  size_t *ei, *ej;
  double *es;              /* ev/2: E(θ) = (1 − e^{iθ}) es at (ei, ej) */
  size_t ns, ntst, ncol;   /* the orbit's states, intervals, points */
  size_t rows;             /* its collocation rows: the boundary rows follow */
  twist_elim *te;
  unsigned char *to;       /* per base entry: TO_* */
  size_t *at;              /* and its place there */
  double *b0, *b0r, *b0i;  /* the boundary rows in v(0): base, and + E(θ) */
  double *sr, *si;         /* S(θ) */
  double complex *K, *KH;  /* the reduced bordered matrix and its adjoint */
  double complex *kx;      /* (ns + 1) x 2: [v0; g], [w0; h] */
  size_t *kp;
  double *b, *c;           /* borders on the boundary block: 2 ns (re, im) */
  double *v, *w;           /* null vectors of A(θ), A(θ)^H: 2 na */
  double g[2];
  double *Jx, *Jp, *Jm;    /* base values at x, x + h d, x − h d */
  double *xs, *pf, *ps, *fp, *work;
  double *Zc, *pc;         /* the point of the last factorisation */
  int cached;
  int *Sp, *Si;            /* the torus system's pattern, N columns */
  size_t snz;
  char errmsg[WHIRL_ERRMSG_SIZE];
};

void whirl_trloc_params(const whirl_trloc *t, const double *Z, const double *p,
                        double *pfull) {
  if (pfull != p) memcpy(pfull, p, t->base.npar * sizeof *pfull);
  pfull[t->par] = Z[t->n];
  if (t->par2 >= 0) pfull[t->par2] = Z[t->n + 1];
}

/* The angle at Z: the last unknown, or the fixed one. */
static double angle(const whirl_trloc *t, const double *Z) {
  return t->par2 >= 0 ? t->theta : Z[t->n + 1];
}

/* ------------------------------------------------------------ structure */

/* Each base entry of A's block sorted into the interval blocks and the
 * boundary rows' two blocks.  0, or -1 where the pattern is not a
 * collocation orbit's (an entry outside its interval, a boundary row
 * entry at another node than u(0) and u(1)). */
static int sort_entries(whirl_trloc *t) {
  const size_t n = t->ns, m = t->ncol, R = n * m, bs = R * n * (m + 1), last = t->ntst * m;
  for (size_t j = 0; j < t->n; ++j)
    for (int q = t->base.Jp[j]; q < t->base.Jp[j + 1]; ++q) {
      const size_t i = (size_t)t->base.Ji[q], nd = j / n, s = j % n;
      t->to[q] = TO_NONE;
      if (i >= t->na || j >= t->na) continue;
      if (i >= t->rows) {
        const size_t rb = i - t->rows;
        if (nd != 0 && nd != last) return -1;
        t->to[q] = nd == 0 ? TO_B0 : TO_BN;
        t->at[q] = rb + n * s;
        continue;
      }
      const size_t it = i / R, lr = i % R;
      if (nd < it * m || nd > it * m + m) return -1;
      t->to[q] = TO_BLOCK;
      t->at[q] = it * bs + lr + R * ((nd - it * m) * n + s);
    }
  return 0;
}

/* The operator's entries: E in the boundary rows at u(0), one per state. */
static int operator_fits(const whirl_fold_operator *op) {
  const size_t n = op->nstate;
  if (!n || !op->ntst || !op->ncol || op->na != n * (op->ntst * op->ncol + 1)) return 0;
  for (size_t e = 0; e < op->ne; ++e)
    if (op->ei[e] < n * op->ntst * op->ncol || op->ej[e] >= n) return 0;
  return 1;
}

/* ----------------------------------------------------- the reduced solve */

/* x = K^{-1} e_last for the complex (m × m) K, column-major, by Gaussian
 * elimination with partial pivoting in place. */
static int small_solve(double complex *A, size_t m, size_t *piv, double complex *x) {
  for (size_t k = 0; k < m; ++k) {
    size_t pr = k;
    for (size_t r = k + 1; r < m; ++r)
      if (cabs(A[r + m * k]) > cabs(A[pr + m * k])) pr = r;
    piv[k] = pr;
    if (!(cabs(A[pr + m * k]) > 0.0)) return WHIRL_ESINGULAR;
    if (pr != k)
      for (size_t j = 0; j < m; ++j) {
        const double complex s = A[k + m * j];
        A[k + m * j] = A[pr + m * j], A[pr + m * j] = s;
      }
    for (size_t r = k + 1; r < m; ++r) {
      const double complex l = A[r + m * k] / A[k + m * k];
      A[r + m * k] = l;
      for (size_t j = k + 1; j < m; ++j) A[r + m * j] -= l * A[k + m * j];
    }
  }
  /* whole rows were swapped, multipliers too: P first, then L and U */
  for (size_t i = 0; i < m; ++i) x[i] = i + 1 == m ? 1.0 : 0.0;
  for (size_t k = 0; k < m; ++k) {
    const double complex s = x[k];
    x[k] = x[piv[k]], x[piv[k]] = s;
  }
  for (size_t k = 0; k < m; ++k)
    for (size_t r = k + 1; r < m; ++r) x[r] -= A[r + m * k] * x[k];
  for (size_t k = m; k-- > 0;) {
    for (size_t j = k + 1; j < m; ++j) x[k] -= A[k + m * j] * x[j];
    x[k] /= A[k + m * k];
  }
  for (size_t i = 0; i < m; ++i)
    if (!isfinite(creal(x[i])) || !isfinite(cimag(x[i]))) return WHIRL_ESINGULAR;
  return 0;
}

/* K = [S(θ) b; c^H 0] and KH = K^H. */
static void reduced_matrix(whirl_trloc *t) {
  const size_t n = t->ns, m = n + 1;
  for (size_t j = 0; j < n; ++j)
    for (size_t i = 0; i < n; ++i) t->K[i + m * j] = t->sr[i + n * j] + I * t->si[i + n * j];
  for (size_t i = 0; i < n; ++i) {
    t->K[i + m * n] = t->b[i] + I * t->b[n + i];
    t->K[n + m * i] = t->c[i] - I * t->c[n + i]; /* conj(c) */
  }
  t->K[n + m * n] = 0.0;
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) t->KH[j + m * i] = conj(t->K[i + m * j]);
}

/* -------------------------------------------------------------- solves */

static int base_jx(whirl_trloc *t, const double *x, const double *p, double *Jx) {
  int rc = t->base.Fx_sparse(x, p, Jx, t->base.data);
  for (size_t q = 0; rc == 0 && q < t->nnz; ++q)
    if (!isfinite(Jx[q])) rc = WHIRL_EBADFUNC;
  return rc;
}

/* The base's values into the interval blocks and the boundary rows'
 * blocks; b0r, b0i: the block in v(0) with E(θ). */
static void fill_blocks(whirl_trloc *t, double theta) {
  const size_t n = t->ns, m = t->ncol;
  memset(twist_block(t->te, 0), 0, t->ntst * n * m * n * (m + 1) * sizeof(double));
  double *bn = twist_bn(t->te), *blocks = twist_block(t->te, 0);
  memset(bn, 0, n * n * sizeof *bn);
  memset(t->b0, 0, n * n * sizeof *t->b0);
  for (size_t q = 0; q < t->nnz; ++q) switch (t->to[q]) {
    case TO_BLOCK: blocks[t->at[q]] = t->Jx[q]; break;
    case TO_B0: t->b0[t->at[q]] = t->Jx[q]; break;
    case TO_BN: bn[t->at[q]] = t->Jx[q]; break;
    default: break;
    }
  const double zr = 1.0 - cos(theta), zi = -sin(theta); /* 1 − e^{iθ} */
  memcpy(t->b0r, t->b0, n * n * sizeof *t->b0r);
  memset(t->b0i, 0, n * n * sizeof *t->b0i);
  for (size_t e = 0; e < t->ne; ++e) {
    const size_t k = (t->ei[e] - t->rows) + n * t->ej[e];
    t->b0r[k] += zr * t->es[e];
    t->b0i[k] += zi * t->es[e];
  }
}

/* At Z: the base Jacobian, A(θ) eliminated to S(θ), v0 and g from
 * K [v0; g] = [0; 1], w0 from K^H [w0; h] = [0; 1], and the null vectors
 * v, w of A(θ) and A(θ)^H on the whole mesh.  g vanishes exactly where
 * A(θ) is singular, and g's derivative is −w^H A_z v with these v, w
 * there (Q A(θ) = [U11 U12; 0 S(θ)], Q real: w = Q^T (0; w0)).  Cached
 * for the same Z and p. */
static int null_solve(whirl_trloc *t, const double *Z, const double *p) {
  const size_t n = t->ns, m = n + 1, na = t->na;
  if (t->cached && !memcmp(t->Zc, Z, t->N * sizeof *Z) &&
      !memcmp(t->pc, p, t->base.npar * sizeof *p))
    return 0;
  t->cached = 0;
  whirl_trloc_params(t, Z, p, t->pf);
  int rc = base_jx(t, Z, t->pf, t->Jx);
  if (rc) return rc;
  fill_blocks(t, angle(t, Z));
  if (twist_factor(t->te)) return WHIRL_ESINGULAR;
  twist_reduce(t->te, t->b0r, t->b0i, t->sr, t->si);
  reduced_matrix(t);
  double complex *v0 = t->kx, *w0 = t->kx + m;
  if ((rc = small_solve(t->K, m, t->kp, v0)) || (rc = small_solve(t->KH, m, t->kp, w0)))
    return rc;
  t->g[0] = creal(v0[n]);
  t->g[1] = cimag(v0[n]);
  double *re = t->work, *im = t->work + n;
  for (size_t i = 0; i < n; ++i) re[i] = creal(v0[i]), im[i] = cimag(v0[i]);
  twist_right(t->te, re, im, t->v, t->v + na);
  for (size_t i = 0; i < n; ++i) re[i] = creal(w0[i]), im[i] = cimag(w0[i]);
  twist_left(t->te, re, im, t->w, t->w + na);
  memcpy(t->Zc, Z, t->N * sizeof *Z);
  memcpy(t->pc, p, t->base.npar * sizeof *p);
  t->cached = 1;
  return 0;
}

/* New borders c = v0, b = w0 (normalised), the reduced null vectors of
 * the last null_solve. */
static int new_borders(whirl_trloc *t) {
  const size_t n = t->ns, m = n + 1;
  const double complex *v0 = t->kx, *w0 = t->kx + m;
  double nv = 0.0, nw = 0.0;
  for (size_t i = 0; i < n; ++i) nv += creal(v0[i] * conj(v0[i])), nw += creal(w0[i] * conj(w0[i]));
  nv = sqrt(nv), nw = sqrt(nw);
  if (!(nv > 0) || !(nw > 0) || !isfinite(nv) || !isfinite(nw)) return WHIRL_ESINGULAR;
  for (size_t i = 0; i < n; ++i) {
    t->c[i] = creal(v0[i]) / nv, t->c[n + i] = cimag(v0[i]) / nv;
    t->b[i] = creal(w0[i]) / nw, t->b[n + i] = cimag(w0[i]) / nw;
  }
  t->cached = 0;
  return 0;
}

/* ------------------------------------------------------ the torus system */

static int tr_F(const double *Z, const double *p, double *out, void *data) {
  whirl_trloc *t = data;
  whirl_trloc_params(t, Z, p, t->ps);
  int rc = t->base.F(Z, t->ps, out, t->base.data);
  if (rc) return rc;
  if ((rc = null_solve(t, Z, p))) return rc < 0 && rc != WHIRL_ESINGULAR ? rc : 1;
  out[t->n] = t->g[0];
  out[t->n + 1] = t->g[1];
  return 0;
}

/* The difference step along d (nd node values): the largest relative
 * change h |d_i| / (1 + |x_i|) of a node value 1e-6, each on its own
 * scale, not the period's or a parameter's after them (an orbit of period
 * 400 would shift node values of 1e-3 by 4e-4 and g_x by the third
 * derivative's error, and Newton on the locus converge linearly: AUTO's
 * tor.6). */
static double hstep(const double *x, const double *d, size_t nd) {
  double r = 0.0;
  for (size_t i = 0; i < nd; ++i) {
    const double q = fabs(d[i]) / (1.0 + fabs(x[i]));
    if (q > r) r = q;
  }
  return r > 1e-200 ? 1e-6 / r : 1e-6;
}

/* out[k] += s Σ_{i<na} u_i (Jp − Jm)_ik / (2h) for every base column k. */
static void contract_rows(const whirl_trloc *t, const double *u, double s, double h,
                          double *out) {
  for (size_t k = 0; k < t->n; ++k) {
    double acc = 0.0;
    for (int q = t->base.Jp[k]; q < t->base.Jp[k + 1]; ++q) {
      const size_t i = (size_t)t->base.Ji[q];
      if (i < t->na) acc += u[i] * (t->Jp[q] - t->Jm[q]);
    }
    out[k] += s * acc / (2.0 * h);
  }
}

/* Re and Im of −w^H A_z v over the base unknowns z (gr, gi[n]): A_z v
 * along z by the symmetry of F's second derivatives, the directional
 * difference of F_x along Re v and along Im v (Doedel et al. 2003). */
static int g_x(whirl_trloc *t, const double *Z, double *gr, double *gi) {
  const size_t n = t->n, na = t->na;
  const double *wr = t->w, *wi = t->w + na;
  memset(gr, 0, n * sizeof *gr);
  memset(gi, 0, n * sizeof *gi);
  for (int part = 0; part < 2; ++part) {
    const double *d = t->v + part * na; /* Re v, Im v */
    const double h = hstep(Z, d, na);
    for (int sgn = 0; sgn < 2; ++sgn) {
      memcpy(t->xs, Z, n * sizeof *t->xs);
      for (size_t i = 0; i < na; ++i) t->xs[i] += (sgn ? -h : h) * d[i];
      int rc = base_jx(t, t->xs, t->pf, sgn ? t->Jm : t->Jp);
      if (rc) return rc;
    }
    /* w^H D[v] = wr D_r + wi D_i + i (wr D_i − wi D_r), g = −that */
    contract_rows(t, wr, -1.0, h, part ? gi : gr);
    contract_rows(t, wi, part ? -1.0 : 1.0, h, part ? gr : gi);
  }
  return 0;
}

/* −w^H A_{p_k} v (re, im) by differences of F_x in p_k. */
static int g_param(whirl_trloc *t, size_t k, double *re, double *im) {
  const size_t na = t->na;
  memcpy(t->ps, t->pf, t->base.npar * sizeof *t->ps);
  const double h = 1e-6 * (1.0 + fabs(t->pf[k]));
  t->ps[k] = t->pf[k] + h;
  int rc = base_jx(t, t->Zc, t->ps, t->Jp);
  t->ps[k] = t->pf[k] - h;
  if (!rc) rc = base_jx(t, t->Zc, t->ps, t->Jm);
  if (rc) return rc;
  const double *vr = t->v, *vi = t->v + na, *wr = t->w, *wi = t->w + na;
  double a = 0, b = 0, c = 0, d = 0; /* wr D vr, wi D vi, wr D vi, wi D vr */
  for (size_t j = 0; j < na; ++j)
    for (int q = t->base.Jp[j]; q < t->base.Jp[j + 1]; ++q) {
      const size_t i = (size_t)t->base.Ji[q];
      if (i >= na) continue;
      const double D = (t->Jp[q] - t->Jm[q]) / (2.0 * h);
      a += wr[i] * D * vr[j];
      b += wi[i] * D * vi[j];
      c += wr[i] * D * vi[j];
      d += wi[i] * D * vr[j];
    }
  *re = -(a + b);
  *im = -(c - d);
  return 0;
}

/* −w^H A_θ v, A_θ = −i e^{iθ} es at (ei, ej). */
static void g_theta(const whirl_trloc *t, double theta, double *re, double *im) {
  const size_t na = t->na;
  double sr = 0.0, si = 0.0; /* S = Σ es conj(w_ei) v_ej */
  for (size_t e = 0; e < t->ne; ++e) {
    const double wr = t->w[t->ei[e]], wi = t->w[na + t->ei[e]];
    const double vr = t->v[t->ej[e]], vi = t->v[na + t->ej[e]];
    sr += t->es[e] * (wr * vr + wi * vi);
    si += t->es[e] * (wr * vi - wi * vr);
  }
  /* i e^{iθ} S */
  *re = -sin(theta) * sr - cos(theta) * si;
  *im = cos(theta) * sr - sin(theta) * si;
}

static int base_fp(whirl_trloc *t, const double *x, const double *p, size_t k, double *fk) {
  if (t->base.Fp) return t->base.Fp(x, p, k, fk, t->base.data);
  return whirl_system_fd_param(&t->base, x, p, k, fk, t->work);
}

/* The torus system's Jacobian in its pattern: per base column the base
 * values then g's two rows; column n (p[par]) dense; column n + 1 (θ) g's. */
static int tr_Fx_sparse(const double *Z, const double *p, double *Jx, void *data) {
  whirl_trloc *t = data;
  const size_t n = t->n;
  int rc = null_solve(t, Z, p);
  if (rc) return rc < 0 && rc != WHIRL_ESINGULAR ? rc : 1;
  double *gr = t->work, *gi = t->work + n;
  if ((rc = g_x(t, Z, gr, gi))) return rc;
  size_t q = 0;
  for (size_t j = 0; j < n; ++j) {
    for (int k = t->base.Jp[j]; k < t->base.Jp[j + 1]; ++k) Jx[q++] = t->Jx[k];
    Jx[q++] = gr[j];
    Jx[q++] = gi[j];
  }
  if ((rc = base_fp(t, Z, t->pf, t->par, t->fp))) return rc;
  memcpy(Jx + q, t->fp, n * sizeof *Jx);
  q += n;
  if ((rc = g_param(t, t->par, Jx + q, Jx + q + 1))) return rc;
  q += 2;
  if (t->par2 < 0) { /* θ: F does not depend on it */
    g_theta(t, Z[n + 1], Jx + q, Jx + q + 1);
    return 0;
  }
  if ((rc = base_fp(t, Z, t->pf, (size_t)t->par2, t->fp))) return rc;
  memcpy(Jx + q, t->fp, n * sizeof *Jx);
  q += n;
  return g_param(t, (size_t)t->par2, Jx + q, Jx + q + 1);
}

static int tr_Fx(const double *Z, const double *p, double *J, void *data) {
  whirl_trloc *t = data;
  double *Jx = malloc((t->snz ? t->snz : 1) * sizeof *Jx);
  if (!Jx) return WHIRL_ENOMEM;
  int rc = tr_Fx_sparse(Z, p, Jx, data);
  if (!rc) whirl_system_scatter_dense(&t->sys, Jx, J);
  free(Jx);
  return rc;
}

static int tr_Fp(const double *Z, const double *p, size_t k, double *out, void *data) {
  whirl_trloc *t = data;
  if (k == t->par || (long)k == t->par2) { /* unknowns here: not read from p */
    memset(out, 0, t->N * sizeof *out);
    return 0;
  }
  int rc = null_solve(t, Z, p);
  if (rc) return rc < 0 && rc != WHIRL_ESINGULAR ? rc : 1;
  if ((rc = base_fp(t, Z, t->pf, k, out))) return rc;
  return g_param(t, k, out + t->n, out + t->n + 1);
}

/* New borders from the null vectors at every accepted point, so K stays
 * well conditioned along the locus; then the base's own (collocation's
 * phase reference). */
static int tr_accept(const double *Z, const double *p, void *data) {
  whirl_trloc *t = data;
  int rc = null_solve(t, Z, p);
  if (rc) return rc < 0 ? rc : WHIRL_ESINGULAR;
  if ((rc = new_borders(t))) return rc;
  whirl_trloc_params(t, Z, p, t->pf);
  if (t->base.accept) return t->base.accept(Z, t->pf, t->base.data);
  return 0;
}

/* A new mesh of the base (AUTO's IAD on a locus of orbits): its node
 * values mapped by the base, the locus's own unknowns (p[par], θ or
 * p[par2]) as they are.  The borders live on the boundary block, v(0)
 * and the periodicity rows, which a mesh does not move. */
static int tr_remap(double *const *v, size_t nv, const double *p, void *data) {
  whirl_trloc *t = data;
  const int rc = t->base.remap(v, nv, p, t->base.data);
  if (rc != 0) t->cached = 0;
  return rc;
}

/* The base's norm weights on its unknowns (the quadrature of its node
 * values: AUTO's integral norm), 1 on the locus's own. */
static int tr_norm_weights(double *q, void *data) {
  whirl_trloc *t = data;
  const int rc = t->base.norm_weights(q, t->base.data);
  q[t->n] = q[t->n + 1] = 1.0;
  return rc;
}

/* ---------------------------------------------------------------- public */

static int sys_pattern(whirl_trloc *t) {
  const size_t n = t->n;
  t->snz = t->nnz + 2 * n + (n + 2) + (n + 2);
  t->Sp = malloc((t->N + 1) * sizeof *t->Sp);
  t->Si = malloc(t->snz * sizeof *t->Si);
  if (!t->Sp || !t->Si) return -1;
  size_t q = 0;
  for (size_t j = 0; j < n; ++j) {
    t->Sp[j] = (int)q;
    for (int k = t->base.Jp[j]; k < t->base.Jp[j + 1]; ++k) t->Si[q++] = t->base.Ji[k];
    t->Si[q++] = (int)n;
    t->Si[q++] = (int)n + 1;
  }
  t->Sp[n] = (int)q;
  for (size_t i = 0; i < n + 2; ++i) t->Si[q++] = (int)i;
  t->Sp[n + 1] = (int)q;
  if (t->par2 >= 0) /* a parameter: F's column too */
    for (size_t i = 0; i < n; ++i) t->Si[q++] = (int)i;
  t->Si[q++] = (int)n;
  t->Si[q++] = (int)n + 1;
  t->Sp[n + 2] = (int)q;
  t->snz = q;
  return 0;
}

whirl_trloc *whirl_trloc_alloc(const whirl_system *base, const whirl_fold_operator *op,
                               size_t par, long par2, char *errbuf, size_t errlen) {
  if (!base || !op || !base->F || !base->Fx_sparse || !base->Jp || !base->Ji ||
      op->na < 1 || op->na > base->n || op->ne < 1 || !op->ei || !op->ej || !op->ev ||
      par >= base->npar || par2 >= (long)base->npar || par2 == (long)par || par2 < -1) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                 "whirl_trloc_alloc: need a base with a sparse Jacobian, its "
                 "period-doubling operator and parameter indices below npar "
                 "(a second one other than the first, or -1)");
    return NULL;
  }
  if (!operator_fits(op)) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_trloc_alloc: the operator is no "
                 "collocation orbit's (nstate, ntst, ncol and its entries in the boundary "
                 "rows at u(0): whirl_colloc_pd_operator)");
    return NULL;
  }
  whirl_trloc *t = calloc(1, sizeof *t);
  if (!t) goto nomem;
  t->base = *base;
  t->par = par;
  t->par2 = par2;
  t->n = base->n;
  t->N = base->n + 2;
  t->na = op->na;
  t->ne = op->ne;
  t->nnz = base->nnz;
  t->ns = op->nstate, t->ntst = op->ntst, t->ncol = op->ncol;
  t->rows = op->nstate * op->ntst * op->ncol;
  const size_t n = t->n, na = t->na, ns = t->ns, m = ns + 1;
  t->ei = malloc(t->ne * sizeof *t->ei);
  t->ej = malloc(t->ne * sizeof *t->ej);
  t->es = malloc(t->ne * sizeof *t->es);
  t->to = malloc(t->nnz ? t->nnz : 1);
  t->at = malloc((t->nnz ? t->nnz : 1) * sizeof *t->at);
  if (!t->ei || !t->ej || !t->es || !t->to || !t->at) goto nomem;
  for (size_t e = 0; e < t->ne; ++e)
    t->ei[e] = op->ei[e], t->ej[e] = op->ej[e], t->es[e] = 0.5 * op->ev[e];
  if (sort_entries(t)) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_trloc_alloc: the base's Jacobian "
                 "pattern is no collocation orbit's of %zu states on %zu intervals of %zu "
                 "points", ns, t->ntst, t->ncol);
    whirl_trloc_free(t);
    return NULL;
  }
  if (sys_pattern(t)) goto nomem;
  t->te = twist_alloc(ns, t->ntst, t->ncol);
  t->b0 = malloc(ns * ns * sizeof *t->b0);
  t->b0r = malloc(ns * ns * sizeof *t->b0r);
  t->b0i = malloc(ns * ns * sizeof *t->b0i);
  t->sr = malloc(ns * ns * sizeof *t->sr);
  t->si = malloc(ns * ns * sizeof *t->si);
  t->K = malloc(m * m * sizeof *t->K);
  t->KH = malloc(m * m * sizeof *t->KH);
  t->kx = malloc(2 * m * sizeof *t->kx);
  t->kp = malloc(m * sizeof *t->kp);
  t->b = calloc(2 * ns, sizeof *t->b);
  t->c = calloc(2 * ns, sizeof *t->c);
  t->v = calloc(2 * na, sizeof *t->v);
  t->w = calloc(2 * na, sizeof *t->w);
  t->Jx = calloc(t->nnz ? t->nnz : 1, sizeof *t->Jx);
  t->Jp = calloc(t->nnz ? t->nnz : 1, sizeof *t->Jp);
  t->Jm = calloc(t->nnz ? t->nnz : 1, sizeof *t->Jm);
  t->xs = calloc(n, sizeof *t->xs);
  t->pf = calloc(base->npar, sizeof *t->pf);
  t->ps = calloc(base->npar, sizeof *t->ps);
  t->pc = calloc(base->npar, sizeof *t->pc);
  t->fp = calloc(n, sizeof *t->fp);
  t->work = calloc(2 * n + 2, sizeof *t->work);
  t->Zc = calloc(t->N, sizeof *t->Zc);
  if (!t->te || !t->b0 || !t->b0r || !t->b0i || !t->sr || !t->si || !t->K || !t->KH ||
      !t->kx || !t->kp || !t->b || !t->c || !t->v || !t->w || !t->Jx || !t->Jp || !t->Jm ||
      !t->xs || !t->pf || !t->ps || !t->pc || !t->fp || !t->work || !t->Zc)
    goto nomem;
  t->b[0] = t->c[0] = 1.0;
  whirl_system *s = &t->sys;
  s->name = par2 >= 0 ? "torus curve at a fixed angle" : "torus curve";
  s->n = t->N;
  s->npar = base->npar;
  s->F = tr_F;
  s->Fx = tr_Fx;
  s->nnz = t->snz;
  s->Jp = t->Sp;
  s->Ji = t->Si;
  s->Fx_sparse = tr_Fx_sparse;
  s->Fp = tr_Fp;
  s->accept = tr_accept;
  s->remap = base->remap ? tr_remap : NULL;
  s->norm_weights = base->norm_weights ? tr_norm_weights : NULL;
  s->p_names = base->p_names;
  s->data = t;
  return t;
nomem:
  whirl_trloc_free(t);
  WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "whirl_trloc_alloc: out of memory");
  return NULL;
}

void whirl_trloc_free(whirl_trloc *t) {
  if (!t) return;
  twist_free(t->te);
  void *p[] = {t->ei, t->ej, t->es, t->to, t->at, t->b0, t->b0r, t->b0i, t->sr, t->si,
               t->K, t->KH, t->kx, t->kp, t->b, t->c, t->v, t->w, t->Jx, t->Jp, t->Jm,
               t->xs, t->pf, t->ps, t->fp, t->work, t->Zc, t->pc, t->Sp, t->Si};
  for (size_t i = 0; i < sizeof p / sizeof *p; ++i) free(p[i]);
  free(t);
}

const whirl_system *whirl_trloc_system(const whirl_trloc *t) { return &t->sys; }
size_t whirl_trloc_size(const whirl_trloc *t) { return t->N; }
const char *whirl_trloc_errmsg(const whirl_trloc *t) { return t->errmsg; }

int whirl_trloc_g(whirl_trloc *t, const double *Z, const double *p, double *g) {
  int rc = null_solve(t, Z, p);
  if (rc) return rc;
  g[0] = t->g[0];
  g[1] = t->g[1];
  return WHIRL_OK;
}

/* Inverse iteration for the borders: with b = c fixed, K [v0; g] = [0; 1]
 * gives v0 ∝ S^{-1} b, which three rounds turn into the null vector of a
 * nearly singular S(θ) (and the adjoint solve into w0). */
int whirl_trloc_init(whirl_trloc *t, const double *x, const double *p, double theta,
                     double *Z) {
  if (!x || !p || !Z || !(theta > 0.0 && theta < 3.14159265358979323846 + 1e-12))
    return WHIRL_FAIL(t, WHIRL_EINVAL, "trloc_init: need x, p and an angle in (0, pi], "
                      "not %g", theta);
  const size_t n = t->n, nb = t->ns;
  memcpy(Z, x, n * sizeof *Z);
  Z[n] = p[t->par];
  t->theta = theta;
  Z[n + 1] = t->par2 >= 0 ? p[t->par2] : theta;
  for (size_t i = 0; i < 2 * nb; ++i) /* generic, no symmetry with v */
    t->b[i] = t->c[i] = 1.0 + 0.5 * sin(1.0 + 2.7 * (double)i);
  for (int round = 0; round < 3; ++round) {
    t->cached = 0;
    int rc = null_solve(t, Z, p);
    if (rc)
      return WHIRL_FAIL(t, rc < 0 ? rc : WHIRL_ESINGULAR, "trloc_init: the bordered "
                        "operator at theta = %g is singular (%d)", theta, rc);
    if (new_borders(t))
      return WHIRL_FAIL(t, WHIRL_ESINGULAR, "trloc_init: no null vector at theta = %g",
                        theta);
  }
  t->cached = 0;
  return WHIRL_OK;
}

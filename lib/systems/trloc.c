/* lib/systems/trloc.c — constructor: the torus (Neimark–Sacker) locus of
 * periodic orbits by complex minimal augmentation (Doedel, Govaerts &
 * Kuznetsov, SIAM J. Numer. Anal. 41 (2003) 401, §5).  See whirl/trloc.h.
 *
 * The complex bordered matrix M = [A(θ) b; c^H 0] of order m = na + 1 is
 * factored as the real matrix R(M) = [[Re M, −Im M]; [Im M, Re M]] of
 * order 2m (R(M)^T = R(M^H): the adjoint solve is the transposed one), on
 * a pattern built once from the base's: per column the rows of A's block,
 * the operator's entries and the border rows.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/linsol.h>
#include <whirl/trloc.h>

#include "util/errmsg_impl.h"

/* What an entry of R(M) holds: a base Jacobian value (idx into Jx), the
 * real or imaginary part of an operator entry E_k, or a border's part. */
enum { S_J, S_ER, S_EI, S_EIN, S_BR, S_BI, S_BIN, S_CR, S_CI, S_CIN };

struct whirl_trloc {
  whirl_system base, sys;
  size_t par, n, N, na, m, ne, nnz;
  long par2;               /* −1: θ is the last unknown; else that
                              parameter, θ fixed at theta */
  double theta;
  size_t *ei, *ej, *eord;
  double *es;              /* ev/2: E(θ) = (1 − e^{iθ}) es at (ei, ej) */
  int *Mp, *Mi;            /* R(M)'s pattern, order 2m */
  unsigned char *skind;    /* per entry: S_* */
  long *sidx;              /* per entry: the Jx entry, E entry or row */
  long *eon;               /* per S_J entry: the E entry on it, or -1 */
  size_t mnz;
  double *Mx;
  whirl_linsol *ls;
  double *b, *c;           /* borders: 2 na (re, then im) */
  double *v, *w;           /* null vectors: 2 na */
  double g[2];
  double *Jx, *Jp, *Jm;    /* base values at x, x + h d, x − h d */
  double *xs, *pf, *ps, *rhs, *fp, *work;
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

/* ---------------------------------------------------------- R(M) pattern */

/* Rows of column j of the base pattern that lie in A's block, sorted. */
static size_t a_rows(const whirl_trloc *t, size_t j, int *out) {
  size_t k = 0;
  for (int q = t->base.Jp[j]; q < t->base.Jp[j + 1]; ++q)
    if ((size_t)t->base.Ji[q] < t->na) out[k++] = t->base.Ji[q];
  return k;
}

static void put(whirl_trloc *t, size_t *q, int row, int kind, long idx) {
  if (t->Mi) {
    t->Mi[*q] = row;
    t->skind[*q] = (unsigned char)kind;
    t->sidx[*q] = idx;
  }
  ++*q;
}

/* The base entry (i, j) of A's block: its index in Jx, or -1. */
static long base_entry(const whirl_trloc *t, size_t i, size_t j) {
  for (int q = t->base.Jp[j]; q < t->base.Jp[j + 1]; ++q)
    if ((size_t)t->base.Ji[q] == i) return q;
  return -1;
}

/* A diagonal block's column j at row offset off: A's rows[k] and the E
 * entries of column j that are no base entry, merged in row order. */
static void diagonal_block(whirl_trloc *t, size_t *q, size_t j, const int *rows, size_t k,
                           size_t off) {
  size_t ne = 0, a = 0, b = 0;
  for (size_t e = 0; e < t->ne; ++e) /* t->eord: scratch of ne entries */
    if (t->ej[e] == j && base_entry(t, t->ei[e], j) < 0) {
      size_t r = ne++;
      while (r > 0 && t->ei[t->eord[r - 1]] > t->ei[e]) t->eord[r] = t->eord[r - 1], --r;
      t->eord[r] = e;
    }
  while (a < k || b < ne) {
    if (b < ne && (a >= k || t->ei[t->eord[b]] < (size_t)rows[a])) {
      put(t, q, (int)(off + t->ei[t->eord[b]]), S_ER, (long)t->eord[b]);
      ++b;
    } else {
      put(t, q, (int)(off + (size_t)rows[a]), S_J, base_entry(t, (size_t)rows[a], j));
      ++a;
    }
  }
}

/* One pass over R(M)'s columns: counts (Mi NULL) or fills.  Column j < na
 * (Re part of v_j): A's rows and the E rows with ej = j (merged), row na
 * (c^H), the E rows + m (Im E), row na + m; column na: rows < na (Re b),
 * rows m.. (Im b); column m + j: the E rows (−Im E), row na, A's rows + m,
 * row na + m; column m + na: rows < na (−Im b), rows m.. (Re b).  An E
 * entry on a base entry is not listed again: the base entry holds the sum
 * (eon, build_pattern). */
static size_t pattern_pass(whirl_trloc *t, int *rows) {
  const size_t na = t->na, m = t->m;
  size_t q = 0;
  for (size_t half = 0; half < 2; ++half)
    for (size_t j = 0; j < m; ++j) {
      const size_t col = half * m + j;
      if (t->Mp) t->Mp[col] = (int)q;
      if (j == na) { /* the border column b */
        for (size_t i = 0; i < na; ++i) put(t, &q, (int)i, half ? S_BIN : S_BR, (long)i);
        for (size_t i = 0; i < na; ++i) put(t, &q, (int)(m + i), half ? S_BR : S_BI, (long)i);
        continue;
      }
      const size_t k = a_rows(t, j, rows);
      if (half) /* upper right: −Im E */
        for (size_t e = 0; e < t->ne; ++e)
          if (t->ej[e] == j) put(t, &q, (int)t->ei[e], S_EIN, (long)e);
      if (!half) diagonal_block(t, &q, j, rows, k, 0); /* upper left */
      put(t, &q, (int)na, half ? S_CI : S_CR, (long)j); /* c^H: Re c, +Im c */
      if (!half) /* lower left: Im E */
        for (size_t e = 0; e < t->ne; ++e)
          if (t->ej[e] == j) put(t, &q, (int)(m + t->ei[e]), S_EI, (long)e);
      if (half) diagonal_block(t, &q, j, rows, k, m); /* lower right */
      put(t, &q, (int)(na + m), half ? S_CR : S_CIN, (long)j);
    }
  if (t->Mp) t->Mp[2 * m] = (int)q;
  return q;
}

static int build_pattern(whirl_trloc *t) {
  int *rows = malloc((t->na + 1) * sizeof *rows);
  if (!rows) return -1;
  t->mnz = pattern_pass(t, rows);
  t->Mp = malloc((2 * t->m + 1) * sizeof *t->Mp);
  t->Mi = malloc(t->mnz * sizeof *t->Mi);
  t->skind = malloc(t->mnz);
  t->sidx = malloc(t->mnz * sizeof *t->sidx);
  t->Mx = malloc(t->mnz * sizeof *t->Mx);
  t->eon = malloc(t->mnz * sizeof *t->eon);
  if (!t->Mp || !t->Mi || !t->skind || !t->sidx || !t->Mx || !t->eon) {
    free(rows);
    return -1;
  }
  pattern_pass(t, rows);
  free(rows);
  /* an E entry on a base entry adds there: found once, not per factor */
  for (size_t col = 0; col < 2 * t->m; ++col)
    for (int q = t->Mp[col]; q < t->Mp[col + 1]; ++q) {
      t->eon[q] = -1;
      if (t->skind[q] != S_J) continue;
      const size_t i = (size_t)t->Mi[q] % t->m, j = col % t->m;
      for (size_t e = 0; e < t->ne; ++e)
        if (t->ei[e] == i && t->ej[e] == j) t->eon[q] = (long)e;
    }
  return 0;
}

/* R(M)'s values at the base values Jx, angle θ and the borders.  An E
 * entry on a base entry adds its real part there. */
static void fill_m(whirl_trloc *t, double theta) {
  const double er = 1.0 - cos(theta), ei = -sin(theta); /* 1 − e^{iθ} */
  const size_t na = t->na;
  for (size_t q = 0; q < t->mnz; ++q) {
    const long k = t->sidx[q];
    double val = 0.0;
    switch (t->skind[q]) {
    case S_J:
      val = t->Jx[k] + (t->eon[q] >= 0 ? er * t->es[t->eon[q]] : 0.0);
      break;
    case S_ER: val = er * t->es[k]; break;
    case S_EI: val = ei * t->es[k]; break;
    case S_EIN: val = -ei * t->es[k]; break;
    case S_BR: val = t->b[k]; break;
    case S_BI: val = t->b[na + k]; break;
    case S_BIN: val = -t->b[na + k]; break;
    case S_CR: val = t->c[k]; break;
    case S_CI: val = t->c[na + k]; break;   /* row na, column m + j: +Im c */
    case S_CIN: val = -t->c[na + k]; break; /* row na + m, column j */
    }
    t->Mx[q] = val;
  }
}

/* -------------------------------------------------------------- solves */

static int base_jx(whirl_trloc *t, const double *x, const double *p, double *Jx) {
  int rc = t->base.Fx_sparse(x, p, Jx, t->base.data);
  for (size_t q = 0; rc == 0 && q < t->nnz; ++q)
    if (!isfinite(Jx[q])) rc = WHIRL_EBADFUNC;
  return rc;
}

/* At Z: the base Jacobian, R(M) factored, v and g from M [v; g] = [0; 1],
 * w from M^H [w; h] = [0; 1].  Cached for the same Z and p. */
static int null_solve(whirl_trloc *t, const double *Z, const double *p) {
  const size_t na = t->na, m = t->m;
  if (t->cached && !memcmp(t->Zc, Z, t->N * sizeof *Z) &&
      !memcmp(t->pc, p, t->base.npar * sizeof *p))
    return 0;
  t->cached = 0;
  whirl_trloc_params(t, Z, p, t->pf);
  int rc = base_jx(t, Z, t->pf, t->Jx);
  if (rc) return rc;
  fill_m(t, angle(t, Z));
  rc = whirl_linsol_factor(t->ls, t->Mx);
  if (rc && rc != WHIRL_ESINGULAR) return rc;
  if (rc == WHIRL_ESINGULAR) return WHIRL_ESINGULAR;
  for (int adj = 0; adj < 2; ++adj) {
    memset(t->rhs, 0, 2 * m * sizeof *t->rhs);
    t->rhs[na] = 1.0;
    if ((rc = whirl_linsol_solve(t->ls, t->rhs, 1, adj))) return rc;
    double *u = adj ? t->w : t->v;
    for (size_t i = 0; i < na; ++i) {
      u[i] = t->rhs[i];
      u[na + i] = t->rhs[m + i];
    }
    if (!adj) {
      t->g[0] = t->rhs[na];
      t->g[1] = t->rhs[m + na];
    }
  }
  memcpy(t->Zc, Z, t->N * sizeof *Z);
  memcpy(t->pc, p, t->base.npar * sizeof *p);
  t->cached = 1;
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

static double hstep(const double *x, size_t n, const double *d, size_t nd) {
  double xm = 0.0, dm = 0.0;
  for (size_t i = 0; i < n; ++i) xm = fmax(xm, fabs(x[i]));
  for (size_t i = 0; i < nd; ++i) dm = fmax(dm, fabs(d[i]));
  return dm > 0 ? 1e-6 * (1.0 + xm) / dm : 1e-6;
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
    const double h = hstep(Z, n, d, na);
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

/* New borders from the null vectors at every accepted point (b = w, c = v,
 * normalised), so M stays well conditioned along the locus; then the
 * base's own (collocation's phase reference). */
static int tr_accept(const double *Z, const double *p, void *data) {
  whirl_trloc *t = data;
  const size_t na = t->na;
  int rc = null_solve(t, Z, p);
  if (rc) return rc < 0 ? rc : WHIRL_ESINGULAR;
  double nv = 0.0, nw = 0.0;
  for (size_t i = 0; i < 2 * na; ++i) nv += t->v[i] * t->v[i], nw += t->w[i] * t->w[i];
  nv = sqrt(nv), nw = sqrt(nw);
  if (!(nv > 0) || !(nw > 0)) return WHIRL_ESINGULAR;
  for (size_t i = 0; i < 2 * na; ++i) t->c[i] = t->v[i] / nv, t->b[i] = t->w[i] / nw;
  t->cached = 0;
  whirl_trloc_params(t, Z, p, t->pf);
  if (t->base.accept) return t->base.accept(Z, t->pf, t->base.data);
  return 0;
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
  for (size_t e = 0; e < op->ne; ++e)
    if (op->ei[e] >= op->na || op->ej[e] >= op->na) {
      WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_trloc_alloc: operator entry %zu "
                   "outside its %zu x %zu block", e, op->na, op->na);
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
  t->m = op->na + 1;
  t->ne = op->ne;
  t->nnz = base->nnz;
  const size_t n = t->n, na = t->na;
  t->ei = malloc(t->ne * sizeof *t->ei);
  t->ej = malloc(t->ne * sizeof *t->ej);
  t->es = malloc(t->ne * sizeof *t->es);
  t->eord = malloc(t->ne * sizeof *t->eord);
  if (!t->ei || !t->ej || !t->es || !t->eord) goto nomem;
  for (size_t e = 0; e < t->ne; ++e)
    t->ei[e] = op->ei[e], t->ej[e] = op->ej[e], t->es[e] = 0.5 * op->ev[e];
  if (build_pattern(t) || sys_pattern(t)) goto nomem;
  t->ls = whirl_linsol_alloc_sparse(2 * t->m, t->Mp, t->Mi);
  t->b = calloc(2 * na, sizeof *t->b);
  t->c = calloc(2 * na, sizeof *t->c);
  t->v = calloc(2 * na, sizeof *t->v);
  t->w = calloc(2 * na, sizeof *t->w);
  t->Jx = calloc(t->nnz ? t->nnz : 1, sizeof *t->Jx);
  t->Jp = calloc(t->nnz ? t->nnz : 1, sizeof *t->Jp);
  t->Jm = calloc(t->nnz ? t->nnz : 1, sizeof *t->Jm);
  t->xs = calloc(n, sizeof *t->xs);
  t->pf = calloc(base->npar, sizeof *t->pf);
  t->ps = calloc(base->npar, sizeof *t->ps);
  t->pc = calloc(base->npar, sizeof *t->pc);
  t->rhs = calloc(2 * t->m, sizeof *t->rhs);
  t->fp = calloc(n, sizeof *t->fp);
  t->work = calloc(2 * n + 2, sizeof *t->work);
  t->Zc = calloc(t->N, sizeof *t->Zc);
  if (!t->ls || !t->b || !t->c || !t->v || !t->w || !t->Jx || !t->Jp || !t->Jm || !t->xs ||
      !t->pf || !t->ps || !t->pc || !t->rhs || !t->fp || !t->work || !t->Zc)
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
  whirl_linsol_free(t->ls);
  void *p[] = {t->ei, t->ej, t->eord, t->es, t->Mp, t->Mi, t->skind, t->sidx, t->eon, t->Mx, t->b, t->c,
               t->v, t->w, t->Jx, t->Jp, t->Jm, t->xs, t->pf, t->ps, t->rhs, t->fp,
               t->work, t->Zc, t->pc, t->Sp, t->Si};
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

/* Inverse iteration for the borders: with b = c fixed, M [v; g] = [0; 1]
 * gives v ∝ A^{-1} b, which three rounds turn into the null vector of a
 * nearly singular A(θ) (and the adjoint solve into w). */
int whirl_trloc_init(whirl_trloc *t, const double *x, const double *p, double theta,
                     double *Z) {
  if (!x || !p || !Z || !(theta > 0.0 && theta < 3.14159265358979323846 + 1e-12))
    return WHIRL_FAIL(t, WHIRL_EINVAL, "trloc_init: need x, p and an angle in (0, pi], "
                      "not %g", theta);
  const size_t n = t->n, na = t->na;
  memcpy(Z, x, n * sizeof *Z);
  Z[n] = p[t->par];
  t->theta = theta;
  Z[n + 1] = t->par2 >= 0 ? p[t->par2] : theta;
  for (size_t i = 0; i < 2 * na; ++i) /* generic, no symmetry with v */
    t->b[i] = t->c[i] = 1.0 + 0.5 * sin(1.0 + 2.7 * (double)i);
  for (int round = 0; round < 3; ++round) {
    t->cached = 0;
    int rc = null_solve(t, Z, p);
    if (rc)
      return WHIRL_FAIL(t, rc < 0 ? rc : WHIRL_ESINGULAR, "trloc_init: the bordered "
                        "operator at theta = %g is singular (%d)", theta, rc);
    double nv = 0.0, nw = 0.0;
    for (size_t i = 0; i < 2 * na; ++i) nv += t->v[i] * t->v[i], nw += t->w[i] * t->w[i];
    nv = sqrt(nv), nw = sqrt(nw);
    if (!(nv > 0) || !(nw > 0) || !isfinite(nv) || !isfinite(nw))
      return WHIRL_FAIL(t, WHIRL_ESINGULAR, "trloc_init: no null vector at theta = %g",
                        theta);
    for (size_t i = 0; i < 2 * na; ++i) t->c[i] = t->v[i] / nv, t->b[i] = t->w[i] / nw;
  }
  t->cached = 0;
  return WHIRL_OK;
}

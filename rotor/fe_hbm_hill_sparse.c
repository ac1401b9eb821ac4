/* rotor/fe_hbm_hill_sparse.c — Hill's method for large finite-element
 * rotors: the Floquet exponents nearest a small real shift σ of the sparse
 * Hill pencil, by ARPACK's shift-invert Arnoldi (Lehoucq, Sorensen & Yang,
 * ARPACK Users' Guide, 1998, §3.2, §4.3), instead of the dense QR of
 * fe_hbm_hill.c.
 *
 * The quadratic problem (λ² A2 + λ A1 + A0) u = 0 of fe_hbm_hill.c is the
 * pencil L y = λ B y, L = [0 I; −A0 −A1], B = [I 0; 0 A2], y = (u, λu).
 * OP = (L − σB)⁻¹ B (mode 1, which = "LM") has the eigenvalues
 * θ = 1/(λ − σ), and (L − σB) y = b is one sparse solve of order ndof·L:
 *   P y1 = −b2 − (A1 + σ A2) b1,  y2 = b1 + σ y1,  P = A0 + σ A1 + σ² A2
 * (once per orbit: condensed onto the nonlinear DOFs by fe_hbm_shift.c
 * when the harmonic balance is condensed, else the sparse LU (KLU) of
 * whirl/linsol.h).  A0, A1, A2 keep the
 * sparsity of K, C + ΩG, M per harmonic, the derivative ∇ coupling a_k with
 * b_k, and a dense (m L)² block of the nonlinear elements.
 *
 * All eigenvalues within R = 1.05 ω/2 of σ are computed (nev grows until
 * the farthest of the nev nearest σ lies beyond R, up to hill_nev; past
 * that the stability is unknown, WHIRL_EMAXITER).  Those in the strip
 * |Im λ| ≤ ω/2 are one copy each of the exponents of the modes nearest the
 * imaginary axis around 0 (the copies λ + i k ω, k ≠ 0, lie outside the
 * strip): every exponent with |λ| ≤ ω/2, the lightly damped modes that
 * decide stability.  Strongly damped exponents, far from σ, are not
 * computed; nor is an unstable one farther than R (Re λ ≳ ω/2 or, at the
 * strip's edge, Re λ ≳ 0.3 ω/2), which a branch from a stable start
 * reaches only by crossing the disk.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"
#include "fe_impl.h"

#ifndef WHIRL_HAVE_ARPACK
int fe_hill_sparse(whirl_fe_hbm *h, const double *qfull, const double *p,
                   size_t nev, double *re, double *im, size_t *m) {
  (void)qfull, (void)p, (void)nev, (void)re, (void)im, (void)m;
  WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, WHIRL_EINVAL,
               "whirl was built without ARPACK: no sparse Hill method");
  return WHIRL_EINVAL;
}
#else

#include "fe_arpack_lib.h"

typedef struct hill_op {
  whirl_fe_hbm *h;       /* its ARPACK workspace */
  int NH;
  double sigma;
  whirl_fe_csc A2, CH;   /* M_H and C_H (with the nonlinear blocks) */
  int nd;                /* DOFs of a harmonic block */
  double w;              /* the orbit's angular frequency */
  whirl_linsol *ls;      /* P = A0 + σ A1 + σ² A2 (uncondensed) */
  fe_lin *lin;           /* condensed: P solved by fe_shift */
  fe_shift sh;
  double *t;             /* NH */
} hill_op;

/* t += s · A ∇ (column a_k ← −kω b_k, b_k ← kω a_k) */
static void add_nabla(fe_trip *t, const whirl_fe_csc *A, double s, int nd,
                      double w) {
  for (int c = 0; c < A->n; ++c) {
    int blk = c / nd;
    if (blk == 0) continue;
    int k = (blk + 1) / 2, to = (blk & 1) ? c + nd : c - nd;
    double f = (blk & 1) ? k * w : -k * w;
    for (int q = A->p[c]; q < A->p[c + 1]; ++q)
      fe_trip_add(t, A->i[q], to, s * f * A->x[q]);
  }
}

/* t += s · A ∇² (column of harmonic k times −(kω)²) */
static void add_nabla2(fe_trip *t, const whirl_fe_csc *A, double s, int nd,
                       double w) {
  for (int c = 0; c < A->n; ++c) {
    int k = (c / nd + 1) / 2;
    for (int q = A->p[c]; q < A->p[c + 1]; ++q)
      fe_trip_add(t, A->i[q], c, -s * (k * w) * (k * w) * A->x[q]);
  }
}

/* M_H, C_H, K_H (which = 0, 1, 2) as compressed columns. */
static int operator_csc(const whirl_fe_hbm *h, int which, double Omega,
                        whirl_fe_csc *A) {
  int nd = h->r->ndof, m = h->aft.m, L = h->L;
  size_t ml = (size_t)m * L, ml2 = ml * ml;
  const double *J = h->Jnl + ml2 * (which == 0 ? 2 : which == 1 ? 1 : 0);
  fe_trip t;
  fe_trip_init(&t, nd * L);
  for (int blk = 0; blk < L; ++blk) {
    int o = blk * nd;
    if (which == 0) fe_trip_add_csc(&t, &h->r->M, 1.0, o, o);
    if (which == 1) {
      fe_trip_add_csc(&t, &h->r->C, 1.0, o, o);
      fe_trip_add_csc(&t, &h->r->G, Omega, o, o);
    }
    if (which == 2) fe_trip_add_csc(&t, &h->r->K, 1.0, o, o);
  }
  for (size_t c = 0; c < ml; ++c)
    for (size_t r = 0; r < ml; ++r)
      if (J[r + ml * c] != 0)
        fe_trip_add(&t, (int)(r / m) * nd + h->aft.dof[r % m],
                    (int)(c / m) * nd + h->aft.dof[c % m], -J[r + ml * c]);
  return fe_trip_to_csc(&t, A);
}

static void op_free(hill_op *o) {
  fe_csc_free(&o->A2);
  fe_csc_free(&o->CH);
  whirl_linsol_free(o->ls);
  if (o->lin) fe_shift_free(&o->sh);
  free(o->t);
}

/* P = A0 + σ A1 + σ² A2 assembled and factorised by the sparse LU. */
static int op_factor_sparse(hill_op *o, const whirl_fe_csc *CH,
                            const whirl_fe_csc *KH, int nd, double w) {
  double sigma = o->sigma;
  fe_trip t;
  fe_trip_init(&t, o->NH);
  /* P = K_H + C_H∇ + M_H∇² + σ(C_H + 2 M_H∇) + σ² M_H */
  fe_trip_add_csc(&t, KH, 1.0, 0, 0);
  add_nabla(&t, CH, 1.0, nd, w);
  add_nabla2(&t, &o->A2, 1.0, nd, w);
  fe_trip_add_csc(&t, CH, sigma, 0, 0);
  add_nabla(&t, &o->A2, 2 * sigma, nd, w);
  fe_trip_add_csc(&t, &o->A2, sigma * sigma, 0, 0);
  whirl_fe_csc P;
  memset(&P, 0, sizeof P);
  int rc = fe_trip_to_csc(&t, &P);
  if (!rc) o->ls = whirl_linsol_alloc_sparse((size_t)o->NH, P.p, P.i);
  /* Arnoldi corrects its own basis: refinement halved the whole response's
   * time on compressor.rotor and changed no digit of branches.tsv */
  if (o->ls) whirl_linsol_set_refinement(o->ls, 0);
  if (!rc) rc = o->ls ? whirl_linsol_factor(o->ls, P.x) : WHIRL_ENOMEM;
  fe_csc_free(&P);
  return rc;
}

/* The operator at shift σ: M_H and C_H for the products, P's
 * factorisation condensed onto the nonlinear DOFs (fe_hbm_shift.c) when
 * the harmonic balance is condensed, else a sparse LU of P. */
static int op_init(hill_op *o, whirl_fe_hbm *h, double Omega, double sigma) {
  int nd = h->r->ndof;
  double w = Omega / h->o.nu;
  whirl_fe_csc KH;
  memset(o, 0, sizeof *o);
  o->h = h;
  memset(&KH, 0, sizeof KH);
  o->NH = nd * h->L;
  o->nd = nd;
  o->w = w;
  o->sigma = sigma;
  int rc = operator_csc(h, 0, Omega, &o->A2);
  if (!rc) rc = operator_csc(h, 1, Omega, &o->CH);
  if (!rc && !h->lin.condensed) rc = operator_csc(h, 2, Omega, &KH);
  o->t = malloc((size_t)o->NH * sizeof *o->t);
  if (!rc && !o->t) rc = WHIRL_ENOMEM;
  if (!rc && h->lin.condensed) {
    o->lin = &h->lin;
    rc = fe_shift_init(&o->sh, &h->lin);
    if (rc) o->lin = NULL;
    else rc = fe_shift_factor(&o->sh, &h->lin, Omega, w, sigma, h->Jnl);
  } else if (!rc) {
    rc = op_factor_sparse(o, &o->CH, &KH, nd, w);
  }
  fe_csc_free(&KH);
  return rc;
}

/* t = x2 + σ x1 + 2 ∇x1, with (∇x)(a_k) = kω x(b_k), (∇x)(b_k) = −kω x(a_k)
 * per DOF (A ∇ x = A (∇x), add_nabla's matrix applied to a vector) */
static void shifted_velocity(const hill_op *o, const double *x1, const double *x2,
                             double *t) {
  const int nd = o->nd, L = o->NH / nd;
  for (int k = 0; k < o->NH; ++k) t[k] = x2[k] + o->sigma * x1[k];
  for (int blk = 1; blk + 1 < L; blk += 2) {
    const double kw = 2.0 * (double)((blk + 1) / 2) * o->w;
    const double *a = x1 + (size_t)blk * nd, *b = a + nd;
    double *ta = t + (size_t)blk * nd, *tb = ta + nd;
    for (int j = 0; j < nd; ++j) {
      ta[j] += kw * b[j];
      tb[j] -= kw * a[j];
    }
  }
}

/* y = (L − σB)⁻¹ B x: the right-hand side −(A2 x2 + (A1 + σ A2) x1) with
 * A1 = C_H + 2 M_H ∇ is −M_H (x2 + σ x1 + 2 ∇x1) − C_H x1, two sparse
 * products instead of three of the assembled A1 + σ A2 */
static int op_apply(hill_op *o, const double *x, double *y) {
  int n = o->NH;
  const double *x1 = x, *x2 = x + n;
  double *y1 = y, *y2 = y + n;
  shifted_velocity(o, x1, x2, o->t);
  memset(y1, 0, (size_t)n * sizeof *y1);
  fe_csc_gemv(&o->A2, -1.0, o->t, y1);
  fe_csc_gemv(&o->CH, -1.0, x1, y1);
  int rc = o->lin ? fe_shift_solve(&o->sh, o->lin, y1)
                  : whirl_linsol_solve(o->ls, y1, 1, 0);
  for (int k = 0; k < n; ++k) y2[k] = x1[k] + o->sigma * y1[k];
  return rc;
}

/* The next start: the sum of the Ritz vectors z[N × nconv] (the wanted
 * invariant subspace of this orbit), normalised. */
static void next_start(double *start, const double *z, int N, int nconv) {
  double s = 0;
  memset(start, 0, (size_t)N * sizeof *start);
  for (int j = 0; j < nconv; ++j)
    for (int i = 0; i < N; ++i) start[i] += z[i + (size_t)N * j];
  for (int i = 0; i < N; ++i) s += start[i] * start[i];
  s = sqrt(s);
  for (int i = 0; s > 0 && i < N; ++i) start[i] /= s;
}

/* ARPACK's work arrays, kept from orbit to orbit in h (a fresh
 * allocation of megabytes per orbit is fresh pages: 6 % of a run in page
 * faults): `need` doubles, `nsel` ints. */
static int hill_workspace(whirl_fe_hbm *h, size_t need, size_t nsel) {
  if (need > h->hill_ws_len) {
    free(h->hill_ws);
    h->hill_ws_len = 0;
    if (!(h->hill_ws = malloc(need * sizeof *h->hill_ws))) return WHIRL_ENOMEM;
    h->hill_ws_len = need;
  }
  if (nsel > h->hill_sel_len) {
    free(h->hill_sel);
    h->hill_sel_len = 0;
    if (!(h->hill_sel = malloc(nsel * sizeof *h->hill_sel))) return WHIRL_ENOMEM;
    h->hill_sel_len = nsel;
  }
  return WHIRL_OK;
}

/* dnaupd's reverse communication from start (when *warm; ARPACK's random
 * start else), then the Ritz values and, for the next orbit's start, the
 * sum of the Ritz vectors.  Along a branch the wanted invariant subspace
 * moves little from point to point: a Krylov space grown from a vector in
 * it is nearly invariant after nev steps, so the warm start saves most of
 * the restarts (Saad, Numerical Methods for Large Eigenvalue Problems,
 * 2nd ed., SIAM 2011, §4.3, §7.1).  A poor start costs only restarts. */
static int arnoldi(hill_op *o, int nev, double *start, int *warm, double *dr,
                   double *di, int *nconv) {
  int N = 2 * o->NH, ncv = 2 * nev + 1 > 20 ? 2 * nev + 1 : 20;
  if (ncv > N) ncv = N;
  int lworkl = 3 * ncv * ncv + 6 * ncv, ido = 0, info = *warm ? 1 : 0;
  int iparam[11] = {0}, ipntr[14] = {0};
  double tol = o->h->hill_tol > 0 ? o->h->hill_tol : 1e-12;
  size_t need = (size_t)N * (4 + ncv + nev + 1) + lworkl + 3 * (size_t)ncv;
  int rc = hill_workspace(o->h, need, (size_t)ncv);
  if (rc) return rc;
  double *resid = o->h->hill_ws, *v = resid + N, *workd = v + (size_t)N * ncv;
  double *workl = workd + 3 * (size_t)N, *workev = workl + lworkl;
  double *z = workev + 3 * (size_t)ncv;
  int *select = o->h->hill_sel;
  if (*warm) memcpy(resid, start, (size_t)N * sizeof *resid);
  iparam[0] = 1;    /* exact shifts */
  iparam[2] = 1000; /* restarts */
  iparam[6] = 1;    /* mode 1 on OP */
  while (!rc) {
    fe_dnaupd(&ido, "I", &N, "LM", &nev, &tol, resid, &ncv, v, &N, iparam,
            ipntr, workd, workl, &lworkl, &info, 1, 2);
    if (ido != -1 && ido != 1) break;
    rc = op_apply(o, workd + ipntr[0] - 1, workd + ipntr[1] - 1);
  }
  if (!rc && (info < 0 || (info == 1 && iparam[4] == 0)))
    rc = info == 1 ? WHIRL_EMAXITER : WHIRL_ELAPACK;
  if (!rc) {
    const int rvec = 1;
    const double sr = 0, si = 0;
    fe_dneupd(&rvec, "A", select, dr, di, z, &N, &sr, &si, workev, "I", &N,
            "LM", &nev, &tol, resid, &ncv, v, &N, iparam, ipntr, workd, workl,
            &lworkl, &info, 1, 1, 2);
    if (info != 0) rc = WHIRL_ELAPACK;
    *nconv = iparam[4];
  }
  *warm = 0;
  if (!rc && *nconv > 0) {
    next_start(start, z, N, *nconv < nev ? *nconv : nev);
    *warm = 1;
  }
  return rc;
}

/* 1/|θ| = |λ − σ| of the farthest Ritz value, and the count of those
 * within R of σ. */
static double farthest(const double *dr, const double *di, int nconv, double R,
                       int *inside) {
  double far = 0;
  *inside = 0;
  for (int j = 0; j < nconv; ++j) {
    double d = 1 / hypot(dr[j], di[j]);
    if (d > far) far = d;
    if (d <= R) ++*inside;
  }
  return far;
}

/* The exponents within R = 1.05 ω/2 of σ, by Arnoldi runs with nev grown
 * until the farthest of the nev nearest σ lies beyond R (or nev reaches
 * nev_max).  The disk holds one copy of every exponent with |λ| ≤ ω/2 —
 * every lightly damped one of the strip, whatever its frequency — and
 * hardly any copy from outside the strip, so nev follows the count of
 * such modes, which grows with the speed: the next orbit starts from that
 * count and a margin (h->hill_nev_cur). */
static int disk_exponents(whirl_fe_hbm *h, hill_op *o, double w, int nev_max,
                          double *dr, int *nev_used, int *nconv) {
  const double R = 1.05 * 0.5 * w;
  const int margin = 6;
  int nev = h->hill_nev_cur > 0 ? h->hill_nev_cur : 8, inside = 0, rc;
  if (nev > nev_max) nev = nev_max;
  for (;;) {
    double *di = dr + nev_max + 1;
    rc = arnoldi(o, nev, h->hill_start, &h->hill_warm, dr, di, nconv);
    if (rc) {
      WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, rc, "sparse Hill (ARPACK, nev "
                   "%d): %s", nev, whirl_strerror(rc));
      return rc;
    }
    double far = farthest(dr, di, *nconv, R, &inside);
    if (*nconv >= nev && far >= R) break;
    if (nev >= nev_max) {
      WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, WHIRL_EMAXITER,
                   "sparse Hill: the %d exponents nearest %.4g lie within "
                   "1.05 omega/2 = %.4g of it, and more may: stability "
                   "unknown here (raise hill_nev, --hill-nev)",
                   nev, o->sigma, R);
      return WHIRL_EMAXITER;
    }
    nev += nev / 2 > 4 ? nev / 2 : 4;
    if (nev > nev_max) nev = nev_max;
  }
  *nev_used = nev;
  h->hill_nev_cur = inside + margin < nev_max ? inside + margin : nev_max;
  if (h->hill_nev_cur < margin) h->hill_nev_cur = margin;
  return WHIRL_OK;
}

int fe_hill_sparse(whirl_fe_hbm *h, const double *qfull, const double *p,
                   size_t nev, double *re, double *im, size_t *m) {
  int nd = h->r->ndof, nm = h->aft.m, L = h->L;
  double Omega = p[WHIRL_FE_P_OMEGA], w = Omega / h->o.nu;
  if ((size_t)(2 * nd * L) < nev + 4 || *m < nev) return WHIRL_EINVAL;
  if (fe_arpack_open(h->errmsg, sizeof h->errmsg) != WHIRL_OK) return WHIRL_ENOLIB;
  for (int blk = 0; blk < L; ++blk)
    for (int j = 0; j < nm; ++j) h->q[blk * nm + j] = qfull[blk * nd + h->aft.dof[j]];
  fe_aft_set_scales(&h->aft, p[WHIRL_FE_P_CLEARANCE], p[WHIRL_FE_P_VISCOSITY]);
  int rc = fe_aft_eval(&h->aft, h->q, w, Omega, h->f, h->Jnl, FE_AFT_HILL);
  if (rc) return rc;
  hill_op o;
  double sigma = 1e-3 * w; /* just right of 0: P is singular at a fold */
  double *dr = malloc(2 * (nev + 1) * sizeof *dr);
  if (!dr) return WHIRL_ENOMEM;
  int nconv = 0, used = 0;
  rc = op_init(&o, h, Omega, sigma);
  if (!rc && !h->hill_start) {
    h->hill_start = malloc((size_t)o.NH * 2 * sizeof *h->hill_start);
    h->hill_warm = 0;
    if (!h->hill_start) rc = WHIRL_ENOMEM;
  }
  if (rc)
    WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, rc, "sparse Hill: shift-invert "
                 "operator: %s", whirl_strerror(rc));
  else
    rc = disk_exponents(h, &o, w, (int)nev, dr, &used, &nconv);
  op_free(&o);
  size_t k = 0;
  for (int j = 0; !rc && j < nconv && j < used; ++j) {
    double a = dr[j], b = dr[nev + 1 + j], n2 = a * a + b * b;
    double lr = sigma + a / n2, li = -b / n2;
    if (fabs(li) > 0.5 * w * (1 + 1e-9)) continue; /* a copy off the strip */
    re[k] = lr;
    im[k++] = li;
  }
  free(dr);
  if (rc) return rc;
  for (size_t i = 1; i < k; ++i) /* by decreasing real part */
    for (size_t j = i; j > 0 && re[j] > re[j - 1]; --j) {
      double t = re[j]; re[j] = re[j - 1]; re[j - 1] = t;
      t = im[j]; im[j] = im[j - 1]; im[j - 1] = t;
    }
  *m = k;
  return WHIRL_OK;
}
#endif

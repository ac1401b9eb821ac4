/* rotor/sfd_region.c — the isola region of the SFD rotor (paper §5.4,
 * Fig. 18) by two-parameter continuation: the merge curve (fold system of
 * the rotating-frame equilibria with the MG condition, continued in lambda)
 * and the fold locus at Omega = W (fold system with delta freed and Omega
 * fixed, continued in lambda).  See whirl/rotor/sfd_region.h and
 * doc/isola-region.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/cont.h>
#include <whirl/equilibrium.h>
#include <whirl/fold.h>
#include <whirl/rotor/sfd.h>
#include <whirl/rotor/sfd_region.h>

/* ------------------------------------------------------------ curves */

void whirl_sfd_curve_free(whirl_sfd_curve *c) {
  if (!c) return;
  free(c->lambda); free(c->delta); free(c->Omega); free(c->eps);
  free(c->res); free(c->type);
  memset(c, 0, sizeof *c);
}

static int curve_push(whirl_sfd_curve *c, double lambda, double delta,
                      double Omega, double eps, double res, int type) {
  if (c->len == c->cap) {
    size_t cap = c->cap ? 2 * c->cap : 256;
    double *a[5] = {c->lambda, c->delta, c->Omega, c->eps, c->res};
    for (int k = 0; k < 5; ++k) {
      double *q = realloc(a[k], cap * sizeof *q);
      if (!q) return WHIRL_ENOMEM;
      a[k] = q;
    }
    c->lambda = a[0], c->delta = a[1], c->Omega = a[2], c->eps = a[3], c->res = a[4];
    int *t = realloc(c->type, cap * sizeof *t);
    if (!t) return WHIRL_ENOMEM;
    c->type = t;
    c->cap = cap;
  }
  c->lambda[c->len] = lambda;
  c->delta[c->len] = delta;
  c->Omega[c->len] = Omega;
  c->eps[c->len] = eps;
  c->res[c->len] = res;
  c->type[c->len] = type;
  ++c->len;
  return 0;
}

/* Append src reversed (without its first point, the shared start) in front
 * of dst's points: dst = reverse(src[1:]) + dst. */
static int curve_prepend_reversed(whirl_sfd_curve *dst, const whirl_sfd_curve *src) {
  whirl_sfd_curve t = {0};
  for (size_t i = src->len; i-- > 1;)
    if (curve_push(&t, src->lambda[i], src->delta[i], src->Omega[i], src->eps[i],
                   src->res[i], src->type[i]))
      goto nomem;
  for (size_t i = 0; i < dst->len; ++i)
    if (curve_push(&t, dst->lambda[i], dst->delta[i], dst->Omega[i], dst->eps[i],
                   dst->res[i], dst->type[i]))
      goto nomem;
  whirl_sfd_curve_free(dst);
  *dst = t;
  return 0;
nomem:
  whirl_sfd_curve_free(&t);
  return WHIRL_ENOMEM;
}

/* ------------------------------------------------------------ residuals */

int whirl_sfd_circ_residuals(double eps, double Omega, double lambda,
                             double delta, double zeta, double *rG,
                             double *rGe, double *rGO) {
  double G, Ge, GO, c[5], cp[5], cm[5];
  int rc = whirl_sfd_circ_G(eps, Omega, lambda, delta, zeta, &G, &Ge, &GO);
  if (rc != 0) return rc;
  if ((rc = whirl_sfd_circ_coeffs(eps, lambda, delta, zeta, c)) != 0) return rc;
  /* scales: sums of |terms|; dc/deps by a difference (scale only) */
  const double h = 1e-6 * fmin(eps, 1.0 - eps);
  whirl_sfd_circ_coeffs(eps + h, lambda, delta, zeta, cp);
  whirl_sfd_circ_coeffs(eps - h, lambda, delta, zeta, cm);
  double sG = 0.0, sGe = 0.0, sGO = 0.0, Wk = 1.0;
  for (int k = 0; k < 5; ++k) {
    sG += fabs(c[k]) * Wk;
    sGe += fabs((cp[k] - cm[k]) / (2.0 * h)) * Wk;
    if (k > 0) sGO += k * fabs(c[k]) * Wk / Omega;
    Wk *= Omega;
  }
  if (rG) *rG = fabs(G) / sG;
  if (rGe) *rGe = fabs(Ge) / sGe;
  if (rGO) *rGO = fabs(GO) / sGO;
  return 0;
}

/* ------------------------------------------------------------ systems */

typedef struct ctx {
  whirl_equilibrium *eq;
  const whirl_system *base;
  double p[WHIRL_SFD_NPAR];
} ctx;

static int ctx_init(ctx *c, double lambda, double zeta) {
  c->eq = whirl_equilibrium_alloc(whirl_sfd_rotating());
  if (!c->eq) return WHIRL_ENOMEM;
  c->base = whirl_equilibrium_system(c->eq);
  whirl_sfd_default_params(c->p);
  c->p[WHIRL_SFD_LAMBDA] = lambda;
  c->p[WHIRL_SFD_ZETA] = zeta;
  c->p[WHIRL_SFD_FE] = 0.0;
  return 0;
}

static whirl_fold *merge_system(const ctx *c) {
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, WHIRL_SFD_OMEGA);
  fo.nfree = 2;
  fo.free[0] = WHIRL_SFD_OMEGA;
  fo.free[1] = WHIRL_SFD_DELTA;
  fo.cond = WHIRL_FOLD_COND_MG;
  return whirl_fold_alloc(c->base, &fo, NULL, 0);
}

/* Reduced eq. 15 without delta: E1 = G_eps, E2 = Omega G_Omega - 4 G, both
 * at delta = 0 (delta enters G only as -delta^2 Omega^4). */
static int reduced(double e, double W, double lambda, double zeta, double *E) {
  double G, Ge, GO;
  int rc = whirl_sfd_circ_G(e, W, lambda, 0.0, zeta, &G, &Ge, &GO);
  if (rc != 0) return rc;
  E[0] = Ge;
  E[1] = W * GO - 4.0 * G;
  return 0;
}

static int reduced_newton(double *e, double *W, double lambda, double zeta) {
  for (int it = 0; it < 40; ++it) {
    double E[2], Ee[2], EW[2];
    const double he = 1e-7, hW = 1e-7 * (1.0 + *W);
    if (reduced(*e, *W, lambda, zeta, E) || reduced(*e + he, *W, lambda, zeta, Ee) ||
        reduced(*e, *W + hW, lambda, zeta, EW))
      return -1;
    const double a = (Ee[0] - E[0]) / he, b = (EW[0] - E[0]) / hW;
    const double c = (Ee[1] - E[1]) / he, d = (EW[1] - E[1]) / hW;
    const double det = a * d - b * c;
    if (!(fabs(det) > 0)) return -1;
    double de = (-E[0] * d + b * E[1]) / det, dW = (-a * E[1] + c * E[0]) / det;
    double s = 1.0;
    while (s > 1e-3 && !(*e + s * de > 0.0 && *e + s * de < 0.999 && *W + s * dW > 0.05)) s *= 0.5;
    if (s <= 1e-3) return -1;
    *e += s * de;
    *W += s * dW;
    if (fabs(de) < 1e-12 && fabs(dW) < 1e-10 * (1.0 + *W)) return 0;
  }
  return -1;
}

/* Converge a merge point on the rotating-frame equations: Newton on the MG
 * system from the eq. 15 estimate.  Z[6] = (u, v, u', v', Omega, delta). */
static int refine_merge(const ctx *c, whirl_fold *f, double e, double W,
                        double d, double *Z, int *type) {
  double p[WHIRL_SFD_NPAR], x[4];
  memcpy(p, c->p, sizeof p);
  p[WHIRL_SFD_OMEGA] = W;
  p[WHIRL_SFD_DELTA] = d;
  whirl_sfd_circ_state(e, W, p[WHIRL_SFD_LAMBDA], d, p[WHIRL_SFD_ZETA], x);
  if (whirl_fold_init(f, x, p, Z) != WHIRL_OK) return -1;
  int its = 0;
  if (whirl_newton(whirl_fold_system(f), Z, p, 1e-13, 30, &its) != 0) return -1;
  /* classify with the plain fold system's test functions */
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, WHIRL_SFD_OMEGA);
  whirl_fold *g = whirl_fold_alloc(c->base, &fo, NULL, 0);
  if (!g) return WHIRL_ENOMEM;
  double Zg[5], pz[WHIRL_SFD_NPAR], tau[WHIRL_FOLD_NTEST];
  int ty[WHIRL_FOLD_NTEST];
  whirl_fold_params(f, Z, p, pz);
  whirl_fold_init(g, Z, pz, Zg);
  const whirl_system *gs = whirl_fold_system(g);
  *type = WHIRL_PT_MG;
  if (gs->test(Zg, pz, tau, ty, gs->data) == 0) *type = ty[WHIRL_FOLD_TEST_MG];
  whirl_fold_free(g);
  return 0;
}

int whirl_sfd_merge_points(double lambda, double zeta, whirl_sfd_curve *out,
                           char *errbuf, size_t errlen) {
  memset(out, 0, sizeof *out);
  if (!(isfinite(lambda) && lambda > 0) || !(isfinite(zeta) && zeta >= 0)) {
    if (errbuf && errlen)
      WHIRL_ERRMSG(
          errbuf, errlen, WHIRL_EINVAL,
          "merge: need lambda > 0 and zeta >= 0 (got lambda %g, zeta %g)",
          lambda, zeta);
    return WHIRL_EINVAL;
  }
  ctx c;
  if (ctx_init(&c, lambda, zeta)) return WHIRL_ENOMEM;
  whirl_fold *f = merge_system(&c);
  if (!f) {
    whirl_equilibrium_free(c.eq);
    return WHIRL_ENOMEM;
  }
  int rc = 0;
  for (int i = 1; i < 50 && rc == 0; ++i) {
    for (int j = 0; j < 64 && rc == 0; ++j) {
      double e = i / 50.0, W = 0.3 * pow(1.1, j);
      if (reduced_newton(&e, &W, lambda, zeta) != 0 || e < 1e-3) continue;
      double P;
      whirl_sfd_circ_G(e, W, lambda, 0.0, zeta, &P, NULL, NULL);
      if (!(P > 0)) continue;
      const double d = sqrt(P) / (W * W);
      int dup = 0;
      for (size_t k = 0; k < out->len; ++k)
        dup |= fabs(out->Omega[k] - W) < 1e-6 * (1.0 + W) && fabs(out->eps[k] - e) < 1e-6;
      if (dup) continue;
      double Z[6];
      int type;
      if (refine_merge(&c, f, e, W, d, Z, &type) != 0) continue;
      const double eps = hypot(Z[0], Z[1]), Om = Z[4], dl = Z[5];
      dup = 0;
      for (size_t k = 0; k < out->len; ++k)
        dup |= fabs(out->Omega[k] - Om) < 1e-6 * (1.0 + Om) && fabs(out->eps[k] - eps) < 1e-6;
      if (dup || !(eps > 1e-3 && eps < 1.0)) continue;
      double r1, r2, r3;
      whirl_sfd_circ_residuals(eps, Om, lambda, dl, zeta, &r1, &r2, &r3);
      rc = curve_push(out, lambda, dl, Om, eps, fmax(r1, fmax(r2, r3)), type);
    }
  }
  /* by increasing delta */
  for (size_t i = 1; i < out->len; ++i)
    for (size_t j = i; j > 0 && out->delta[j] < out->delta[j - 1]; --j) {
      double *a[5] = {out->lambda, out->delta, out->Omega, out->eps, out->res};
      for (int k = 0; k < 5; ++k) {
        double t = a[k][j];
        a[k][j] = a[k][j - 1];
        a[k][j - 1] = t;
      }
      int t = out->type[j];
      out->type[j] = out->type[j - 1];
      out->type[j - 1] = t;
    }
  whirl_fold_free(f);
  whirl_equilibrium_free(c.eq);
  if (rc != 0 && errbuf && errlen)
    WHIRL_ERRMSG(errbuf, errlen, rc, "merge: out of memory");
  return rc;
}

/* ------------------------------------------------------------ tracing */

void whirl_sfd_region_options_default(whirl_sfd_region_options *o) {
  o->zeta = 0.0;
  o->omega_max = 20.0;
  o->lambda_min = 0.01;
  o->lambda_max = 1.5;
  o->ds_max = 0.05;
  o->nmx = 5000;
}

typedef struct trace_job {
  const whirl_system *sys;
  whirl_fold *f;
  int upper;    /* 1: merge curve (Z = x, Omega, delta); 0: Omega = W locus
                   (Z = x, delta) */
  double W, zeta;
} trace_job;

static int trace_dir(const trace_job *job, const whirl_sfd_region_options *o,
                     const double *Z0, const double *p0, int dir,
                     whirl_sfd_curve *out, whirl_sfd_region *r, char *errbuf,
                     size_t errlen) {
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = WHIRL_SFD_LAMBDA;
  co.ds = fmin(1e-3, o->ds_max);
  co.ds_min = fmin(1e-10, co.ds);
  co.ds_max = o->ds_max;
  co.nmx = o->nmx;
  co.p_min = o->lambda_min;
  co.p_max = o->lambda_max;
  co.newton_tol = 1e-12;
  co.detect_bp = 0;
  co.detect_hb = 0;
  co.detect_loop = 1;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(job->sys, &co, err, sizeof err);
  if (!c) return WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "region: %s", err);
  const size_t n = 4;
  int rc = whirl_cont_start(c, Z0, p0, dir);
  while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    const double lam = pt->p[WHIRL_SFD_LAMBDA];
    const double Om = job->upper ? pt->x[n] : job->W;
    const double dl = job->upper ? pt->x[n + 1] : pt->x[n];
    const double eps = hypot(pt->x[0], pt->x[1]);
    double r1 = NAN, r2 = NAN, r3 = 0.0;
    whirl_sfd_circ_residuals(eps, Om, lam, dl, job->zeta, &r1, &r2, job->upper ? &r3 : NULL);
    const double res = fmax(r1, fmax(r2, r3));
    int type = pt->type == WHIRL_PT_REGULAR || pt->type == WHIRL_PT_EP ? 0 : pt->type;
    if ((rc = curve_push(out, lam, dl, Om, eps, res, type)) != 0) break;
    if (job->upper) r->max_res_upper = fmax(r->max_res_upper, res);
    else r->max_res_lower = fmax(r->max_res_lower, res);
  }
  const whirl_cont_stats *st = whirl_cont_get_stats(c);
  r->steps += st->steps;
  r->newton_its += st->newton_its;
  if (rc == WHIRL_DONE && whirl_cont_stop_reason(c) == WHIRL_STOP_NMX) {
    /* the curve would be cut short without a word (5001 points) */
    rc = WHIRL_EMAXITER;
    if (errbuf && errlen)
      WHIRL_ERRMSG(
          errbuf, errlen, WHIRL_EMAXITER,
          "region: the %s curve took %zu steps (nmx) before "
          "reaching the lambda range's ends at %s lambda = %.6g: raise nmx "
          "or ds-max",
          job->upper ? "upper" : "lower", co.nmx,
          dir < 0 ? "decreasing" : "increasing",
          whirl_cont_point(c)->p[WHIRL_SFD_LAMBDA]);
  } else if (rc < 0 && errbuf && errlen)
    WHIRL_ERRMSG(errbuf, errlen, rc, "region: continuation failed: %s",
                 whirl_cont_errmsg(c));
  whirl_cont_free(c);
  return rc < 0 ? rc : 0;
}

/* Both directions from Z0, joined into one curve ordered along the
 * arclength. */
static int trace_both(const trace_job *job, const whirl_sfd_region_options *o,
                      const double *Z0, const double *p0, whirl_sfd_curve *out,
                      whirl_sfd_region *r, char *errbuf, size_t errlen) {
  whirl_sfd_curve back = {0};
  const size_t N = job->sys->n;
  double Z[8];
  memcpy(Z, Z0, N * sizeof *Z);
  double x4[4];
  memcpy(x4, Z0, sizeof x4);
  double pz[WHIRL_SFD_NPAR];
  whirl_fold_params(job->f, Z0, p0, pz);
  whirl_fold_init(job->f, x4, pz, Z);
  int rc = trace_dir(job, o, Z, p0, -1, &back, r, errbuf, errlen);
  if (rc == 0) {
    whirl_fold_init(job->f, x4, pz, Z);
    rc = trace_dir(job, o, Z, p0, +1, out, r, errbuf, errlen);
  }
  if (rc == 0) rc = curve_prepend_reversed(out, &back);
  whirl_sfd_curve_free(&back);
  return rc;
}

/* The LPs in delta of the circular orbits at Omega = W, lambda fixed,
 * continued from the centred rotor at delta = 0: x[k*4..], delta[k]. */
static int omega_w_folds(const ctx *c, double W, double *xs, double *ds,
                         size_t cap, size_t *nf) {
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = WHIRL_SFD_DELTA;
  co.ds = 1e-3;
  co.ds_max = 0.02;
  co.nmx = 5000;
  co.p_min = -1e-9;
  co.p_max = 1.0;
  co.newton_tol = 1e-12;
  co.detect_bp = co.detect_hb = 0;
  *nf = 0;
  whirl_cont *cc = whirl_cont_alloc(c->base, &co, NULL, 0);
  if (!cc) return WHIRL_ENOMEM;
  double p[WHIRL_SFD_NPAR], x[4] = {0, 0, 0, 0};
  memcpy(p, c->p, sizeof p);
  p[WHIRL_SFD_OMEGA] = W;
  p[WHIRL_SFD_DELTA] = 0.0;
  int rc = whirl_cont_start(cc, x, p, +1);
  while (rc == WHIRL_OK && (rc = whirl_cont_step(cc)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(cc);
    if (pt->type == WHIRL_PT_LP && *nf < cap) {
      memcpy(xs + 4 * *nf, pt->x, 4 * sizeof *xs);
      ds[*nf] = pt->p[WHIRL_SFD_DELTA];
      ++*nf;
    }
  }
  whirl_cont_free(cc);
  return 0; /* the branch ends at contact or delta = 1: both are normal */
}

static int on_curve(const whirl_sfd_curve *c, double lambda, double delta) {
  for (size_t i = 0; i < c->len; ++i)
    if (fabs(c->lambda[i] - lambda) < 1e-6 && fabs(c->delta[i] - delta) < 1e-6) return 1;
  return 0;
}

int whirl_sfd_region_compute(const whirl_sfd_region_options *o,
                             whirl_sfd_region *r, char *errbuf, size_t errlen) {
  memset(r, 0, sizeof *r);
  if (errbuf && errlen) errbuf[0] = '\0';
  r->lambda_m = r->delta_m = r->lambda_c = r->delta_c = NAN;
  const char *why = NULL;
  if (!(isfinite(o->zeta) && o->zeta >= 0)) why = "zeta must be >= 0";
  else if (!(isfinite(o->omega_max) && o->omega_max > 0)) why = "omega-max must be > 0";
  else if (!(isfinite(o->lambda_min) && o->lambda_min > 0)) why = "lambda-min must be > 0";
  else if (!(isfinite(o->lambda_max) && o->lambda_max > o->lambda_min))
    why = "lambda-max must be > lambda-min";
  else if (!(o->ds_max > 0) || o->nmx < 1) why = "ds-max must be > 0 and nmx >= 1";
  if (why) return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "region: %s", why);
  int rc = 0;
  /* seeds at a lambda inside the range (log-centre), then the ends */
  const double seeds[3] = {sqrt(o->lambda_min * o->lambda_max), o->lambda_min,
                           o->lambda_max};
  /* ---- upper: the merge curve */
  for (int s = 0; s < 3 && r->upper.len == 0 && rc == 0; ++s) {
    whirl_sfd_curve mp;
    rc = whirl_sfd_merge_points(seeds[s], o->zeta, &mp, errbuf, errlen);
    if (rc != 0) break;
    ctx c;
    if (ctx_init(&c, seeds[s], o->zeta)) {
      whirl_sfd_curve_free(&mp);
      return WHIRL_ENOMEM;
    }
    whirl_fold *f = merge_system(&c);
    for (size_t k = 0; k < mp.len && rc == 0 && f; ++k) {
      if (mp.type[k] != WHIRL_PT_MG || on_curve(&r->upper, mp.lambda[k], mp.delta[k])) continue;
      double Z[6], p[WHIRL_SFD_NPAR];
      int type;
      memcpy(p, c.p, sizeof p);
      if (refine_merge(&c, f, mp.eps[k], mp.Omega[k], mp.delta[k], Z, &type) != 0) continue;
      trace_job job = {whirl_fold_system(f), f, 1, o->omega_max, o->zeta};
      whirl_sfd_curve part = {0};
      rc = trace_both(&job, o, Z, p, &part, r, errbuf, errlen);
      if (rc == 0 && r->upper.len == 0) {
        r->upper = part;
      } else {
        whirl_sfd_curve_free(&part);
      }
    }
    whirl_fold_free(f);
    whirl_equilibrium_free(c.eq);
    whirl_sfd_curve_free(&mp);
  }
  /* ---- lower: the fold locus at Omega = W, delta freed */
  for (int s = 0; s < 3 && r->lower.len == 0 && rc == 0; ++s) {
    ctx c;
    if (ctx_init(&c, seeds[s], o->zeta)) return WHIRL_ENOMEM;
    double xs[4 * 8], dls[8];
    size_t nf = 0;
    omega_w_folds(&c, o->omega_max, xs, dls, 8, &nf);
    whirl_fold_options fo;
    whirl_fold_options_default(&fo, WHIRL_SFD_OMEGA);
    fo.free[0] = WHIRL_SFD_DELTA;
    whirl_fold *f = whirl_fold_alloc(c.base, &fo, NULL, 0);
    for (size_t k = 0; k < nf && rc == 0 && f; ++k) {
      if (on_curve(&r->lower, seeds[s], dls[k])) continue;
      double p[WHIRL_SFD_NPAR], Z[5];
      memcpy(p, c.p, sizeof p);
      p[WHIRL_SFD_OMEGA] = o->omega_max;
      p[WHIRL_SFD_DELTA] = dls[k];
      if (whirl_fold_init(f, xs + 4 * k, p, Z) != WHIRL_OK) continue;
      trace_job job = {whirl_fold_system(f), f, 0, o->omega_max, o->zeta};
      whirl_sfd_curve part = {0};
      rc = trace_both(&job, o, Z, p, &part, r, errbuf, errlen);
      if (rc == 0 && r->lower.len == 0) r->lower = part;
      else whirl_sfd_curve_free(&part);
    }
    whirl_fold_free(f);
    whirl_equilibrium_free(c.eq);
  }
  for (size_t i = 0; i < r->lower.len; ++i) {
    if (r->lower.type[i] == WHIRL_PT_MG && isnan(r->lambda_m))
      r->lambda_m = r->lower.lambda[i], r->delta_m = r->lower.delta[i];
    if (r->lower.type[i] == WHIRL_PT_CP && isnan(r->lambda_c))
      r->lambda_c = r->lower.lambda[i], r->delta_c = r->lower.delta[i];
  }
  if (rc == 0 && (r->upper.len == 0 || r->lower.len == 0)) {
    if (errbuf && errlen)
      WHIRL_ERRMSG(
          errbuf, errlen, WHIRL_ENOCONV,
          "region: no %s found for lambda in [%g, %g] (zeta %g, W %g)",
          r->upper.len == 0 ? "isola merge point" : "fold at Omega = W",
          o->lambda_min, o->lambda_max, o->zeta, o->omega_max);
    rc = WHIRL_ENOCONV;
  }
  return rc;
}

void whirl_sfd_region_free(whirl_sfd_region *r) {
  if (!r) return;
  whirl_sfd_curve_free(&r->upper);
  whirl_sfd_curve_free(&r->lower);
}

/* delta values of a curve's segments that cross lambda; Omega too. */
static size_t crossings(const whirl_sfd_curve *c, double lambda, double *dl,
                        double *Om, size_t cap) {
  size_t k = 0;
  const double tol = 1e-12 * (1.0 + fabs(lambda));
  for (size_t i = 0; i + 1 < c->len && k < cap; ++i) {
    const double a = c->lambda[i], b = c->lambda[i + 1];
    const int at_a = fabs(a - lambda) <= tol, at_b = fabs(b - lambda) <= tol;
    if (!at_a && !at_b && (a - lambda) * (b - lambda) > 0) continue;
    if (a == b) continue;
    if (at_b && !at_a && i + 2 < c->len) continue; /* counted on the next one */
    double u = at_a ? 0.0 : at_b ? 1.0 : (lambda - a) / (b - a);
    dl[k] = c->delta[i] + u * (c->delta[i + 1] - c->delta[i]);
    Om[k] = c->Omega[i] + u * (c->Omega[i + 1] - c->Omega[i]);
    ++k;
  }
  return k;
}

int whirl_sfd_region_band(const whirl_sfd_region *r, double lambda,
                          double omega_max, double *lo, double *hi) {
  double dl[16], Om[16], du[16], Ou[16];
  const size_t nl = crossings(&r->lower, lambda, dl, Om, 16);
  const size_t nu = crossings(&r->upper, lambda, du, Ou, 16);
  if (nl == 0) return 0;
  double dmin = dl[0];
  for (size_t i = 1; i < nl; ++i) dmin = fmin(dmin, dl[i]);
  double top = NAN;
  /* the merge point bounds the region from above while it lies below W;
   * where the merge speed passes W the two boundaries meet (tangentially)
   * and the region ends */
  for (size_t i = 0; i < nu; ++i)
    if (Ou[i] <= omega_max && du[i] > dmin && (isnan(top) || du[i] < top)) top = du[i];
  if (isnan(top) || !(top > dmin)) return 0;
  *lo = dmin;
  *hi = top;
  return 1;
}

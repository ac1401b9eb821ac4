/* rotor/fe_hbm_loci.c — fold loci of the periodic response of a
 * finite-element rotor in two parameters: the speed Ω and a scale of the
 * unbalance, of the film clearances or of their viscosity
 * (whirl/rotor/fe_hbm.h).  The generic fold system (whirl/fold.h, minimal
 * augmentation) is built on the condensed harmonic balance with the speed
 * in units of omega_scale, so that the fold system's unknown Ω is O(1)
 * like the others in the arclength; the core follows it in the second
 * parameter and reports its codimension-two points (cusps CP, isola
 * births IS and merges MG).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/fold.h>

#include "fe_hbm_impl.h"

void whirl_fe_locus_options_default(whirl_fe_locus_options *o) {
  memset(o, 0, sizeof *o);
  whirl_fe_hbm_options_default(&o->hbm);
  o->hbm.stability = 0;
  o->param = WHIRL_FE_P_UNBALANCE;
  o->pmin = 0.0;
  o->pmax = 10.0;
  o->nmx = 500;
  o->pmin2 = 0.0;
  o->pmax2 = 10.0;
}

/* The base system with p[0] the speed over omega_scale. */
typedef struct scaled {
  const whirl_system *base;
  double ws;
  double p[WHIRL_FE_NPAR];
} scaled;

static const double *unscale(scaled *s, const double *p) {
  memcpy(s->p, p, sizeof s->p);
  s->p[WHIRL_FE_P_OMEGA] = p[WHIRL_FE_P_OMEGA] * s->ws;
  return s->p;
}
static int sc_F(const double *x, const double *p, double *f, void *d) {
  scaled *s = d;
  return s->base->F(x, unscale(s, p), f, s->base->data);
}
static int sc_Fx(const double *x, const double *p, double *J, void *d) {
  scaled *s = d;
  return s->base->Fx(x, unscale(s, p), J, s->base->data);
}
static int sc_Fp(const double *x, const double *p, size_t k, double *fk, void *d) {
  scaled *s = d;
  const int rc = s->base->Fp(x, unscale(s, p), k, fk, s->base->data);
  if (!rc && k == WHIRL_FE_P_OMEGA)
    for (size_t i = 0; i < s->base->n; i++) fk[i] *= s->ws;
  return rc;
}

static whirl_system scaled_system(scaled *s) {
  whirl_system S;
  memset(&S, 0, sizeof S);
  S.name = "fe-hbm (scaled speed)";
  S.n = s->base->n;
  S.npar = s->base->npar;
  S.F = sc_F;
  S.Fx = s->base->Fx ? sc_Fx : NULL;
  S.Fp = s->base->Fp ? sc_Fp : NULL;
  S.p_names = s->base->p_names;
  S.data = s;
  return S;
}

static void locus_cont_options(whirl_cont_options *co, const whirl_fe_locus_options *o,
                               int icp) {
  whirl_cont_options_default(co);
  co->icp = (size_t)icp;
  co->p_min = o->pmin;
  co->p_max = o->pmax;
  co->ds = o->ds > 0 ? o->ds : 0.01;
  co->ds_max = o->ds_max > 0 ? o->ds_max : 0.05;
  co->ds_min = co->ds * 1e-6;
  co->nmx = o->nmx;
  co->newton_tol = 1e-9;
  co->detect_lp = 1;
  co->detect_bp = 0;
  co->detect_loop = 1;
}

typedef struct locus_run {
  whirl_fold *f;
  scaled *s;
  whirl_cont *c;
  double *Z, *pf;
} locus_run;

static void run_free(locus_run *L) {
  whirl_cont_free(L->c);
  whirl_fold_free(L->f);
  free(L->Z);
  free(L->pf);
}

/* The fold system fo on the scaled base, started at the fold (X, p),
 * followed in the parameter icp. */
static int run_start(locus_run *L, const whirl_fe_locus_options *o,
                     const whirl_fold_options *fo, int icp, const double *X,
                     const double *p, int direction, char *err, size_t errlen) {
  const whirl_system S = scaled_system(L->s);
  L->f = whirl_fold_alloc(&S, fo, err, errlen);
  if (!L->f) return WHIRL_EINVAL;
  const size_t nz = whirl_fold_size(L->f);
  L->Z = malloc(nz * sizeof *L->Z);
  L->pf = malloc(WHIRL_FE_NPAR * sizeof *L->pf);
  if (!L->Z || !L->pf) return WHIRL_ENOMEM;
  double ps[WHIRL_FE_NPAR];
  memcpy(ps, p, sizeof ps);
  ps[WHIRL_FE_P_OMEGA] = p[WHIRL_FE_P_OMEGA] / L->s->ws;
  int rc = whirl_fold_init(L->f, X, ps, L->Z);
  if (!rc && fo->cond) { /* the codimension-two point itself first */
    /* to 1e-9, the corrector's tolerance: the augmented system's second
     * derivatives are differences of Jacobians, whose rounding on a stiff
     * shaft (the Schur complement of a large K onto small film forces)
     * leaves Newton's corrections at a floor of 2e-10 to 6e-10 on
     * examples/rotor/rigid-limit.rotor; 1e-11 was met only by chance */
    int its = 0;
    rc = whirl_newton(whirl_fold_system(L->f), L->Z, ps, 1e-9, 30, &its);
  }
  if (rc)
    return WHIRL_ERRMSG(err, errlen, rc, "fold locus: start at Omega = %g rad/s: %s",
                        p[WHIRL_FE_P_OMEGA], whirl_fold_errmsg(L->f));
  whirl_cont_options co;
  locus_cont_options(&co, o, icp);
  L->c = whirl_cont_alloc(whirl_fold_system(L->f), &co, err, errlen);
  if (!L->c) return WHIRL_ENOMEM;
  rc = whirl_cont_start(L->c, L->Z, ps, direction < 0 ? -1 : +1);
  if (rc)
    WHIRL_ERRMSG(err, errlen, rc, "fold locus: start at Omega = %g rad/s: %s",
                 p[WHIRL_FE_P_OMEGA], whirl_cont_errmsg(L->c));
  return rc;
}

/* One point of the locus to the caller: Ω back in rad/s. */
static int run_report(locus_run *L, int icp, int second, double wlo, double whi,
                      whirl_fe_locus_fn fn, void *ctx) {
  const whirl_point *pt = whirl_cont_point(L->c);
  whirl_fold_params(L->f, pt->x, pt->p, L->pf);
  whirl_fe_locus_point lp = {pt->index, pt->type, L->pf[WHIRL_FE_P_OMEGA] * L->s->ws,
                             L->pf[icp], second > 0 ? L->pf[second] : NAN, pt->x,
                             L->s->base->n};
  if (!(lp.Omega >= wlo && lp.Omega <= whi)) return WHIRL_DONE; /* left the range */
  return fn ? fn(&lp, ctx) : 0;
}

/* Follow the fold system fo of the scaled condensed HBM from (X, p) in
 * the parameter icp (o's range), reporting `second` as value2 (−1: none);
 * what names the curve in messages.  The body of both public functions. */
static int follow_fold(const whirl_fe_rotor *r, const whirl_fe_locus_options *o,
                       const whirl_fold_options *fo, int icp, int second, const double *X,
                       const double *p, int direction, whirl_fe_locus_fn fn, void *ctx,
                       const char *what, char *err, size_t errlen) {
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &o->hbm, err, errlen);
  if (!h) return WHIRL_EINVAL;
  double wlo = r->speed_min, whi = r->speed_max;
  if (!(whi > wlo)) wlo = 0, whi = HUGE_VAL;
  scaled s = {whirl_fe_hbm_system(h), o->omega_scale > 0 ? o->omega_scale : p[WHIRL_FE_P_OMEGA],
              {0}};
  locus_run L = {NULL, &s, NULL, NULL, NULL};
  int rc = run_start(&L, o, fo, icp, X, p, direction, err, errlen);
  while (!rc && (rc = whirl_cont_step(L.c)) == WHIRL_OK)
    rc = run_report(&L, icp, second, wlo, whi, fn, ctx);
  if (rc == WHIRL_DONE) rc = WHIRL_OK;
  else if (rc < 0 && L.c && whirl_cont_errmsg(L.c)[0])
    WHIRL_ERRMSG(err, errlen, rc, "%s: %s", what, whirl_cont_errmsg(L.c));
  run_free(&L);
  whirl_fe_hbm_free(h);
  return rc;
}

int whirl_fe_hbm_fold_locus(const whirl_fe_rotor *r, const whirl_fe_locus_options *o,
                            const double *X, const double *p, int direction,
                            whirl_fe_locus_fn fn, void *ctx, char *err, size_t errlen) {
  if (!r || !o || !X || !p || o->param < 1 || o->param >= WHIRL_FE_NPAR ||
      !(o->pmax > o->pmin) || !(p[WHIRL_FE_P_OMEGA] > 0))
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "fold locus: need a second parameter (unbalance, clearance or "
                        "viscosity), pmin < pmax and a fold at a speed > 0");
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, WHIRL_FE_P_OMEGA);
  return follow_fold(r, o, &fo, o->param, -1, X, p, direction, fn, ctx, "fold locus", err,
                     errlen);
}

int whirl_fe_hbm_merge_curve(const whirl_fe_rotor *r, const whirl_fe_locus_options *o,
                             int along, const double *X, const double *p,
                             int direction, whirl_fe_locus_fn fn, void *ctx,
                             char *err, size_t errlen) {
  if (!r || !o || !X || !p || o->param < 1 || o->param >= WHIRL_FE_NPAR || along < 1 ||
      along >= WHIRL_FE_NPAR || along == o->param || !(p[WHIRL_FE_P_OMEGA] > 0))
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "merge curve: need two different parameters among unbalance, "
                        "clearance and viscosity, and a merge point at a speed > 0");
  /* the merge (isola-centre) condition w^T F_q = 0 as an extra equation,
   * the speed and o->param free, followed in `along` (whirl/fold.h) */
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, WHIRL_FE_P_OMEGA);
  fo.nfree = 2;
  fo.free[0] = WHIRL_FE_P_OMEGA;
  fo.free[1] = (size_t)o->param;
  fo.cond = WHIRL_FOLD_COND_MG;
  whirl_fe_locus_options oa = *o;
  oa.pmin = o->pmin2, oa.pmax = o->pmax2;
  return follow_fold(r, &oa, &fo, along, o->param, X, p, direction, fn, ctx, "merge curve",
                     err, errlen);
}

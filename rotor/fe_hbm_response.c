/* rotor/fe_hbm_response.c — the periodic speed response of a finite-element
 * rotor: the condensed harmonic-balance system (fe_hbm.c) followed in Ω by
 * the generic continuation core (whirl/cont.h), with its folds LP, branch
 * points BP and, from Hill's multipliers, period doublings PD and tori TR;
 * each point's amplitude at a node from the recovered full orbit.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"

void whirl_fe_hbm_response_options_default(whirl_fe_hbm_response_options *o) {
  memset(o, 0, sizeof *o);
  whirl_fe_hbm_options_default(&o->hbm);
  o->unbalance = o->clearance = o->viscosity = 1.0;
  o->nmx = 2000;
  o->seed_phase = NAN;
  o->direction = +1;
}

static int speed_range(const whirl_fe_rotor *r,
                       const whirl_fe_hbm_response_options *o, double *lo,
                       double *hi, char *err, size_t errlen) {
  *lo = o->speed_min;
  *hi = o->speed_max;
  if (*lo == 0 && *hi == 0) { *lo = r->speed_min; *hi = r->speed_max; }
  if (!(*hi > *lo) || *lo < 0)
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "speed range [%g, %g] rad/s: need 0 <= min < max",
                        *lo, *hi);
  if (o->node < 0 || o->node >= r->nnode)
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "node %d: the rotor has nodes 0..%d", o->node,
                        r->nnode - 1);
  return WHIRL_OK;
}

static void cont_options(whirl_cont_options *co, double lo, double hi,
                         const whirl_fe_hbm_response_options *o) {
  whirl_cont_options_default(co);
  co->icp = WHIRL_FE_P_OMEGA;
  co->p_min = lo;
  co->p_max = hi;
  /* arclength in units of the speed range: Ω enters with the weight
   * 1/(hi − lo), the unknowns (displacements over the length scale) with 1 */
  double w = 1.0 / (hi - lo);
  co->p_weight = w;
  co->ds = w * (o->ds > 0 ? o->ds : (hi - lo) / 200);
  /* a tenth of the range: the step is at ds_max nearly everywhere (the
   * unknowns' arclength dominates), and /10 against /50 takes 138 steps
   * instead of 546 on examples/rotor/compressor.rotor, the same folds */
  co->ds_max = w * (o->ds_max > 0 ? o->ds_max : (hi - lo) / 10);
  if (co->ds > co->ds_max) co->ds = co->ds_max;
  co->ds_min = co->ds * 1e-6;
  co->nmx = o->nmx;
  co->newton_tol = 1e-9;
  /* a new speed is a new condensation (H + 1 banded LUs and their
   * solves): Newton at the predicted speed away from folds, one speed a
   * step instead of one per iteration (0.62 → 0.24 s on compressor.rotor,
   * the same folds to 1e-11) */
  co->natural_corrector = 1e-4;
  co->detect_hb = 1;
  co->detect_pd = 1;
  co->detect_loop = o->seed_eps > 0 || o->seed_x; /* an isola closes on itself */
}

/* Report one point of the branch. */
static int report(whirl_fe_hbm *h, const whirl_point *pt, int node,
                  double *q, whirl_fe_hbm_response_fn fn, void *ctx) {
  whirl_fe_hbm_response_point rp;
  memset(&rp, 0, sizeof rp);
  int rc = whirl_fe_hbm_recover(h, pt->x, pt->p, q);
  if (rc) return rc;
  rp.index = pt->index;
  rp.type = pt->type;
  rp.label = pt->label;
  rp.Omega = pt->p[WHIRL_FE_P_OMEGA];
  rp.amplitude = whirl_fe_hbm_amplitude(h, q, node);
  rp.stable = pt->stable;
  rp.X = pt->x;
  rp.n = pt->n;
  return fn ? fn(&rp, ctx) : 0;
}

/* |F|² of the seed of phase ph at p. */
static double seed_residual(whirl_fe_hbm *h, double eps, double ph,
                            const double *p, double *x, double *f) {
  const whirl_system *S = whirl_fe_hbm_system(h);
  if (whirl_fe_hbm_seed_circular(h, eps, ph, x) || S->F(x, p, f, S->data))
    return HUGE_VAL;
  double s = 0;
  for (size_t i = 0; i < S->n; i++) s += f[i] * f[i];
  return isfinite(s) ? s : HUGE_VAL;
}

/* The start x0: rest, or the seed of the options (its phase the best of
 * 16 when not given). */
static int start_point(whirl_fe_hbm *h, const whirl_fe_hbm_response_options *o,
                       const double *p, double *x0, char *err,
                       size_t errlen) {
  const size_t n = whirl_fe_hbm_size(h);
  if (o->seed_x) {
    memcpy(x0, o->seed_x, n * sizeof *x0);
    return WHIRL_OK;
  }
  if (!(o->seed_eps > 0)) return WHIRL_OK;
  double ph = o->seed_phase;
  if (isnan(ph)) {
    double *f = malloc(n * sizeof *f), best = HUGE_VAL;
    if (!f) return WHIRL_ENOMEM;
    for (int k = 0; k < 16; k++) {
      const double t = 2 * WHIRL_PI * k / 16, v = seed_residual(h, o->seed_eps, t, p, x0, f);
      if (v < best) best = v, ph = t;
    }
    free(f);
    if (isnan(ph))
      return WHIRL_ERRMSG(err, errlen, WHIRL_EDOMAIN,
                          "seed eps = %g at Omega = %g rad/s: no phase with "
                          "a finite residual", o->seed_eps, o->seed_omega);
  }
  return whirl_fe_hbm_seed_circular(h, o->seed_eps, ph, x0);
}

static double norm2(const double *f, size_t n) {
  double s = 0;
  for (size_t i = 0; i < n; i++) s += f[i] * f[i];
  return isfinite(s) ? s : HUGE_VAL;
}

/* Damped Newton on F(x, p) = 0 from x (in place): the full step is halved
 * while the trial leaves the model's domain (a journal at its clearance)
 * or does not reduce |F|, so that a start far from the solution — a
 * journal bearing's static equilibrium at low speed, ε → 1, from the
 * centred journal — stays inside the clearances (Deuflhard, Newton
 * Methods for Nonlinear Problems, 2004, §3.1: the residual-based damping).
 * WHIRL_OK when |F| ≤ tol; the corrector of the continuation then polishes
 * it. */
static int settle(const whirl_system *S, double *x, const double *p) {
  const size_t n = S->n;
  double *f = malloc((3 * n + n * n) * sizeof *f), *xt = f + n, *ft = xt + n, *J = ft + n;
  whirl_linsol *ls = whirl_linsol_alloc_dense(n);
  int rc = f && ls ? S->F(x, p, f, S->data) : WHIRL_ENOMEM;
  double r = rc ? HUGE_VAL : norm2(f, n);
  for (int it = 0; !rc && it < 200 && r > 1e-20; it++) {
    rc = S->Fx(x, p, J, S->data);
    if (!rc) rc = whirl_linsol_factor(ls, J);
    if (!rc) rc = whirl_linsol_solve(ls, f, 1, 0);
    double t = 1.0, rt = HUGE_VAL;
    for (; !rc && t > 1e-8; t *= 0.5) {
      for (size_t i = 0; i < n; i++) xt[i] = x[i] - t * f[i];
      if (S->F(xt, p, ft, S->data) == 0 && (rt = norm2(ft, n)) < r) break;
    }
    if (rc || !(t > 1e-8)) { rc = rc ? rc : WHIRL_ENOCONV; break; }
    memcpy(x, xt, n * sizeof *x), memcpy(f, ft, n * sizeof *f), r = rt;
  }
  whirl_linsol_free(ls);
  free(f);
  return rc ? rc : (r <= 1e-20 ? WHIRL_OK : WHIRL_ENOCONV);
}

/* The counts of one branch added to the report. */
static void add_report(whirl_fe_hbm_response_report *r, const whirl_cont_stats *s,
                       size_t unknowns) {
  whirl_cont_stats *t = &r->cont;
  t->steps += s->steps;
  t->rejected += s->rejected;
  t->recorrected += s->recorrected;
  t->newton_its += s->newton_its;
  t->f_evals += s->f_evals;
  t->jac_evals += s->jac_evals;
  t->factorizations += s->factorizations;
  t->eig_evals += s->eig_evals;
  t->spectrum_failed += s->spectrum_failed;
  t->special += s->special;
  r->unknowns = unknowns;
}

static int follow(whirl_fe_hbm *h, const whirl_cont_options *co,
                  const whirl_fe_hbm_response_options *o, double lo,
                  whirl_fe_hbm_response_fn fn, void *ctx, char *err,
                  size_t errlen) {
  size_t n = whirl_fe_hbm_size(h);
  double *x0 = calloc(n, sizeof *x0);
  double *q = malloc((size_t)h->r->ndof * h->L * sizeof *q);
  double p[WHIRL_FE_NPAR];
  const double om0 = o->seed_eps > 0 || o->seed_x ? o->seed_omega : lo;
  whirl_fe_hbm_params(om0, p);
  p[WHIRL_FE_P_UNBALANCE] = o->unbalance;
  p[WHIRL_FE_P_CLEARANCE] = o->clearance;
  p[WHIRL_FE_P_VISCOSITY] = o->viscosity;
  int rc = x0 && q ? start_point(h, o, p, x0, err, errlen) : WHIRL_ENOMEM;
  whirl_cont *c = !rc ? whirl_cont_alloc(whirl_fe_hbm_system(h), co, err, errlen) : NULL;
  /* the first step returns the corrected start point (EP) */
  /* a damped Newton first when the plain one of the start would fail */
  if (!rc && c) settle(whirl_fe_hbm_system(h), x0, p); /* failure: the core's Newton tells */
  if (!rc) rc = c ? whirl_cont_start(c, x0, p, o->direction < 0 ? -1 : +1) : WHIRL_ENOMEM;
  if (rc && c)
    WHIRL_ERRMSG(err, errlen, rc, "start at Omega = %g rad/s: %s", om0,
                 whirl_cont_errmsg(c));
  while (!rc && (rc = whirl_cont_step(c)) == WHIRL_OK)
    rc = report(h, whirl_cont_point(c), o->node, q, fn, ctx);
  if (rc == WHIRL_DONE) rc = WHIRL_OK;
  else if (rc < 0 && c && whirl_cont_errmsg(c)[0]) {
    /* the core knows only the callback's status: the stability's own
     * message says what failed (a reduction too small, say) */
    const char *why = strstr(whirl_cont_errmsg(c), "spectrum") ? whirl_fe_hbm_errmsg(h) : "";
    WHIRL_ERRMSG(err, errlen, rc, "%s%s%s", whirl_cont_errmsg(c), why[0] ? ": " : "", why);
  }
  if (c && o->report) add_report(o->report, whirl_cont_get_stats(c), n);
  whirl_cont_free(c);
  free(q);
  free(x0);
  return rc;
}

int whirl_fe_hbm_response(const whirl_fe_rotor *r,
                      const whirl_fe_hbm_response_options *o,
                      whirl_fe_hbm_response_fn fn, void *ctx, char *errbuf,
                      size_t errlen) {
  whirl_fe_hbm_response_options def;
  if (!o) { whirl_fe_hbm_response_options_default(&def); o = &def; }
  double lo, hi;
  int rc = speed_range(r, o, &lo, &hi, errbuf, errlen);
  if (rc) return rc;
  if (o->seed_eps > 0 && !(o->seed_eps < 1 && o->seed_omega >= lo && o->seed_omega <= hi))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "seed: need 0 < eps = %g < 1 and Omega = %g rad/s in "
                        "the speed range [%g, %g]", o->seed_eps,
                        o->seed_omega, lo, hi);
  if (o->seed_x && !(o->seed_omega >= lo && o->seed_omega <= hi))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "seed: Omega = %g rad/s "
                        "outside the speed range [%g, %g]", o->seed_omega, lo, hi);
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &o->hbm, errbuf, errlen);
  if (!h) return WHIRL_EINVAL;
  whirl_cont_options co;
  cont_options(&co, lo, hi, o);
  rc = follow(h, &co, o, lo, fn, ctx, errbuf, errlen);
  whirl_fe_hbm_free(h);
  return rc;
}

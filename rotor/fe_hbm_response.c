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

void whirl_fe_hbm_response_options_default(
    whirl_fe_hbm_response_options *o) {
  memset(o, 0, sizeof *o);
  whirl_fe_hbm_options_default(&o->hbm);
  o->unbalance = o->clearance = o->viscosity = 1.0;
  o->nmx = 2000;
}

static int speed_range(const whirl_fe_rotor *r,
                       const whirl_fe_hbm_response_options *o,
                       double *lo, double *hi, char *err, size_t errlen) {
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
  co->ds_max = w * (o->ds_max > 0 ? o->ds_max : (hi - lo) / 50);
  co->ds_min = co->ds * 1e-6;
  co->nmx = o->nmx;
  co->newton_tol = 1e-9;
  co->detect_hb = 1;
  co->detect_pd = 1;
  co->detect_loop = 0;
}

/* Report one point of the branch. */
static int report(whirl_fe_hbm *h, const whirl_point *pt, int node,
                  double *q, whirl_fe_hbm_response_fn fn, void *ctx) {
  whirl_fe_hbm_response_point rp;
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

static int follow(whirl_fe_hbm *h, const whirl_cont_options *co,
                  const whirl_fe_hbm_response_options *o, double lo,
                  whirl_fe_hbm_response_fn fn, void *ctx, char *err,
                  size_t errlen) {
  size_t n = whirl_fe_hbm_size(h);
  double *x0 = calloc(n, sizeof *x0);
  double *q = malloc((size_t)h->r->ndof * h->L * sizeof *q);
  double p[WHIRL_FE_NPAR];
  whirl_fe_hbm_params(lo, p);
  p[WHIRL_FE_P_UNBALANCE] = o->unbalance;
  p[WHIRL_FE_P_CLEARANCE] = o->clearance;
  p[WHIRL_FE_P_VISCOSITY] = o->viscosity;
  whirl_cont *c = (x0 && q) ? whirl_cont_alloc(whirl_fe_hbm_system(h), co, err,
                                               errlen) : NULL;
  /* the first step returns the corrected start point (EP) */
  int rc = c ? whirl_cont_start(c, x0, p, +1) : WHIRL_ENOMEM;
  if (rc && c)
    WHIRL_ERRMSG(err, errlen, rc, "start at Omega = %g rad/s: %s", lo,
                 whirl_cont_errmsg(c));
  while (!rc && (rc = whirl_cont_step(c)) == WHIRL_OK)
    rc = report(h, whirl_cont_point(c), o->node, q, fn, ctx);
  if (rc == WHIRL_DONE) rc = WHIRL_OK;
  else if (rc < 0 && c && whirl_cont_errmsg(c)[0])
    WHIRL_ERRMSG(err, errlen, rc, "%s", whirl_cont_errmsg(c));
  whirl_cont_free(c);
  free(q);
  free(x0);
  return rc;
}

int whirl_fe_hbm_response(const whirl_fe_rotor *r,
                          const whirl_fe_hbm_response_options *o,
                          whirl_fe_hbm_response_fn fn, void *ctx,
                          char *errbuf, size_t errlen) {
  whirl_fe_hbm_response_options def;
  if (!o) { whirl_fe_hbm_response_options_default(&def); o = &def; }
  double lo, hi;
  int rc = speed_range(r, o, &lo, &hi, errbuf, errlen);
  if (rc) return rc;
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &o->hbm, errbuf, errlen);
  if (!h) return WHIRL_EINVAL;
  whirl_cont_options co;
  cont_options(&co, lo, hi, o);
  rc = follow(h, &co, o, lo, fn, ctx, errbuf, errlen);
  whirl_fe_hbm_free(h);
  return rc;
}

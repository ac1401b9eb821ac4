/* rotor/fe_hbm_discover.c — isolas of a finite-element rotor's response
 * found without a start on them (whirl_fe_hbm_discover, doc/discovery.md):
 * the branch from rest, then at each sample speed deflated Newton
 * (whirl/deflate.h; Farrell, Birkisson & Funke 2015) on the condensed
 * harmonic-balance system, deflated against every crossing of that speed by
 * every branch traced so far, and a branch from each new solution.  The same
 * method as `whirl run`'s DISCOVER (lib/run/run_discover.c); its starts use
 * the rotor's own scale, the film clearance (the unknowns are displacements
 * over it): circular orbits of eccentricity in (0.05, 0.95) at every film
 * element, and known orbits at a random phase and amplitude.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/deflate.h>

#include "fe_hbm_impl.h"

void whirl_fe_discover_options_default(whirl_fe_discover_options *d) {
  memset(d, 0, sizeof *d);
  d->starts = 40;
  d->seed = 1;
}

typedef struct fe_trace {
  size_t npts, cap;
  double *om, *x; /* npts, npts × n */
} fe_trace;

typedef struct fe_disc {
  const whirl_fe_rotor *r;
  whirl_fe_hbm *h;
  const whirl_system *S;
  size_t n;
  whirl_deflate *d;
  fe_trace *tr;
  size_t ntr, captr;
  int branch, half;     /* of the points being reported */
  whirl_fe_hbm_response_fn fn;
  void *ctx;
  uint64_t rng;
  double p[WHIRL_FE_NPAR];
} fe_disc;

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double urand(fe_disc *D) { return whirl_random_uniform(&D->rng); }

/* Every point reported: kept in the current trace, then passed on. */
static int keep(const whirl_fe_hbm_response_point *pt, void *ctx) {
  fe_disc *D = ctx;
  fe_trace *t = &D->tr[D->ntr - 1];
  if (t->npts == t->cap) {
    size_t cap = t->cap ? 2 * t->cap : 256;
    double *no = realloc(t->om, cap * sizeof *no);
    if (!no) return WHIRL_ENOMEM;
    t->om = no;
    double *nx = realloc(t->x, cap * D->n * sizeof *nx);
    if (!nx) return WHIRL_ENOMEM;
    t->x = nx;
    t->cap = cap;
  }
  t->om[t->npts] = pt->Omega;
  memcpy(t->x + t->npts++ * D->n, pt->X, D->n * sizeof *pt->X);
  whirl_fe_hbm_response_point q = *pt;
  q.branch = D->branch;
  q.half = D->half;
  return D->fn ? D->fn(&q, D->ctx) : 0;
}

static int new_trace(fe_disc *D) {
  if (D->ntr == D->captr) {
    size_t cap = D->captr ? 2 * D->captr : 8;
    fe_trace *nt = realloc(D->tr, cap * sizeof *nt);
    if (!nt) return WHIRL_ENOMEM;
    D->tr = nt;
    D->captr = cap;
  }
  memset(&D->tr[D->ntr++], 0, sizeof *D->tr);
  return WHIRL_OK;
}

/* The solutions known at speed s: the crossings of s by every trace. */
static int known_at(fe_disc *D, double s) {
  whirl_deflate_clear(D->d);
  for (size_t t = 0; t < D->ntr; t++) {
    int rc = whirl_deflate_add_crossings(D->d, D->tr[t].om, D->tr[t].x, D->tr[t].npts, s, D->p);
    if (rc) return rc;
  }
  return WHIRL_OK;
}

/* A known orbit (harmonic-major blocks of b) at phase φ, scaled by a. */
static void shifted(const fe_disc *D, const double *r, double a, double phi, double *x) {
  const int b = D->h->b, H = D->h->H;
  for (int j = 0; j < b; j++) x[j] = a * r[j];
  for (int k = 1; k <= H; k++) {
    const double c = cos(k * phi), s = sin(k * phi);
    for (int j = 0; j < b; j++) {
      const double ak = r[(2 * k - 1) * b + j], bk = r[2 * k * b + j];
      x[(2 * k - 1) * b + j] = a * (ak * c + bk * s);
      x[2 * k * b + j] = a * (bk * c - ak * s);
    }
  }
}

/* The k-th start: X = 0, three scaled copies of each known solution, then
 * random circular orbits and (four in five once solutions are known) known
 * orbits at a random phase and amplitude in [1/4, 4]. */
static int start_k(fe_disc *D, size_t k, size_t nknown, double *x) {
  static const double scale[3] = {0.5, 1.5, -1.0};
  if (k == 0) {
    memset(x, 0, D->n * sizeof *x);
    return 0;
  }
  k--;
  if (k < 3 * nknown) {
    const double *r = whirl_deflate_root(D->d, k / 3);
    for (size_t j = 0; j < D->n; j++) x[j] = scale[k % 3] * r[j];
    return 0;
  }
  if (nknown && urand(D) < 0.8) {
    size_t pick = (size_t)(urand(D) * (double)nknown);
    if (pick >= nknown) pick = nknown - 1;
    const double a = exp(log(4.0) * (2 * urand(D) - 1)), phi = 2 * WHIRL_PI * urand(D);
    shifted(D, whirl_deflate_root(D->d, pick), a, phi, x);
    return 0;
  }
  const double eps = 0.05 + 0.9 * urand(D), phase = 2 * WHIRL_PI * urand(D);
  return whirl_fe_hbm_seed_circular(D->h, eps, phase, x) ? 1 : 0;
}

/* A branch from the solution x at speed s: towards smaller speeds, then
 * larger (two traces). */
static int trace_from(fe_disc *D, const whirl_fe_hbm_response_options *o, double s,
                      const double *x, char *err, size_t len) {
  whirl_fe_hbm_response_options o2 = *o;
  o2.seed_x = x;
  o2.seed_omega = s;
  o2.seed_eps = 0;
  D->branch++;
  int rc = WHIRL_OK;
  for (int dir = -1; !rc && dir <= 1; dir += 2) {
    o2.direction = dir;
    D->half = dir;
    rc = new_trace(D);
    if (!rc) rc = whirl_fe_hbm_response(D->r, &o2, keep, D, err, len);
  }
  return rc;
}

/* Deflated Newton at speed s from d->starts starts; each new solution's
 * branch traced at once (and deflated from then on). */
static int search_speed(fe_disc *D, const whirl_fe_hbm_response_options *o,
                        const whirl_fe_discover_options *d, size_t si, double *x,
                        whirl_fe_discover_report *rep, char *err, size_t len) {
  const double s = d->speeds[si];
  whirl_fe_hbm_params(s, D->p);
  D->p[WHIRL_FE_P_UNBALANCE] = o->unbalance;
  D->p[WHIRL_FE_P_CLEARANCE] = o->clearance;
  D->p[WHIRL_FE_P_VISCOSITY] = o->viscosity;
  D->rng = (uint64_t)d->seed * 0x9E3779B97F4A7C15ull + si + 1;
  int rc = known_at(D, s);
  const size_t nknown = whirl_deflate_count(D->d);
  for (size_t k = 0; !rc && k < d->starts; k++) {
    if (start_k(D, k, nknown, x)) continue;
    rep->starts++;
    double t0 = now();
    int r = whirl_deflate_solve(D->d, x, D->p, NULL);
    rep->search_seconds += now() - t0;
    if (r == WHIRL_ENOCONV || r == WHIRL_EDOMAIN) continue;
    if (r != WHIRL_OK)
      return WHIRL_ERRMSG(err, len, r, "discovery at Omega = %g rad/s: %s", s,
                          whirl_deflate_errmsg(D->d));
    rc = trace_from(D, o, s, x, err, len);
    if (!rc) rc = known_at(D, s);
  }
  return rc;
}

static int check(const whirl_fe_rotor *r, const whirl_fe_hbm_response_options *o,
                 const whirl_fe_discover_options *d, char *err, size_t len) {
  double lo = o->speed_min, hi = o->speed_max;
  if (lo == 0 && hi == 0) lo = r->speed_min, hi = r->speed_max;
  if (!d || !d->speeds || d->nspeeds == 0 || d->starts == 0)
    return WHIRL_ERRMSG(err, len, WHIRL_EINVAL, "discovery needs speeds and a "
                        "budget of starts >= 1");
  if (o->seed_eps > 0 || o->seed_x)
    return WHIRL_ERRMSG(err, len, WHIRL_EINVAL, "discovery starts from rest: "
                        "no seed with it");
  for (size_t i = 0; i < d->nspeeds; i++)
    if (!(d->speeds[i] >= lo && d->speeds[i] <= hi))
      return WHIRL_ERRMSG(err, len, WHIRL_EINVAL, "discovery speed %g rad/s is "
                          "outside the speed range [%g, %g]", d->speeds[i], lo, hi);
  return WHIRL_OK;
}

int whirl_fe_hbm_discover(const whirl_fe_rotor *r, const whirl_fe_hbm_response_options *o,
                          const whirl_fe_discover_options *d, whirl_fe_hbm_response_fn fn,
                          void *ctx, whirl_fe_discover_report *report, char *err,
                          size_t len) {
  whirl_fe_discover_report rep;
  memset(&rep, 0, sizeof rep);
  int rc = check(r, o, d, err, len);
  if (rc) return rc;
  fe_disc D;
  memset(&D, 0, sizeof D);
  D.r = r, D.fn = fn, D.ctx = ctx, D.branch = 1;
  whirl_fe_hbm_options ho = o->hbm;
  ho.stability = 0; /* the search needs no multipliers */
  D.h = whirl_fe_hbm_alloc(r, &ho, err, len);
  if (!D.h) return WHIRL_EINVAL;
  D.S = whirl_fe_hbm_system(D.h);
  D.n = D.S->n;
  whirl_deflate_options dop;
  whirl_deflate_options_default(&dop);
  dop.tol = 1e-11;
  dop.max_step = 1.0; /* a clearance per step */
  dop.max_distance = 20.0;
  D.d = whirl_deflate_alloc(D.S, &dop, err, len);
  double *x = malloc(D.n * sizeof *x);
  rc = D.d && x ? new_trace(&D) : WHIRL_ENOMEM;
  if (!rc) rc = whirl_fe_hbm_response(r, o, keep, &D, err, len);
  for (size_t si = 0; !rc && si < d->nspeeds; si++)
    rc = search_speed(&D, o, d, si, x, &rep, err, len);
  rep.branches = (size_t)D.branch;
  rep.isolated = (size_t)D.branch - 1;
  rep.iterations = D.d ? whirl_deflate_get_stats(D.d)->iterations : 0;
  if (report) *report = rep;
  for (size_t t = 0; t < D.ntr; t++) {
    free(D.tr[t].om);
    free(D.tr[t].x);
  }
  free(D.tr);
  free(x);
  whirl_deflate_free(D.d);
  whirl_fe_hbm_free(D.h);
  return rc;
}

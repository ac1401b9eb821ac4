/* lib/analysis/basins.c — basins of attraction by time integration with
 * early exit on certified capture (see whirl/basins.h).  One Dormand–Prince
 * integrator per thread; each point is classified independently, so the
 * result does not depend on the number of threads or on scheduling.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "basins_impl.h"

#define MAX_ATTRACTORS WHIRL_BASINS_MAX_ATTRACTORS

void whirl_basins_options_default(whirl_basins_options *o) {
  if (!o) return;
  memset(o, 0, sizeof *o);
  o->max_periods = 500;
  o->rtol = 1e-12;
  o->atol = 1e-15;
}

int whirl_basins_check_tolerances(double rtol, double atol, char *msg,
                                  size_t len) {
  char dummy[1];
  if (!msg || len == 0) msg = dummy, len = sizeof dummy;
  msg[0] = '\0';
  /* the message is the check's answer, for the user: no source location */
  if (!(rtol >= WHIRL_BASINS_RTOL_MIN && rtol <= WHIRL_BASINS_RTOL_MAX)) {
    snprintf(msg, len, "rtol must be in [%g, %g] (got %g)",
             WHIRL_BASINS_RTOL_MIN, WHIRL_BASINS_RTOL_MAX, rtol);
    return WHIRL_EINVAL;
  }
  if (!(atol > 0 && atol <= WHIRL_BASINS_ATOL_MAX)) {
    snprintf(msg, len, "atol must be in (0, %g] (got %g)",
             WHIRL_BASINS_ATOL_MAX, atol);
    return WHIRL_EINVAL;
  }
  return WHIRL_OK;
}

typedef struct {
  const whirl_attractor *att;
  size_t natt;
  int fixed;
  size_t count[MAX_ATTRACTORS];
  int which;
  size_t last_k;
  int error;
  const whirl_basins_atlas *atlas;
  size_t phases;            /* section points a period (atlas, record) */
  size_t need_hits, hits;
  int cell_class, by_atlas;
  basins_record *rec;
} classify_ctx;

static void record(basins_record *r, const double *x, size_t phase) {
  if (r->oom) return;
  if (r->m == r->cap) {
    size_t cap = r->cap ? 2 * r->cap : 64;
    double *nx = realloc(r->x, cap * r->n * sizeof *nx);
    if (!nx) {
      r->oom = 1;
      return;
    }
    r->x = nx;
    r->cap = cap;
  }
  memcpy(r->x + r->m * r->n, x, (r->n - 1) * sizeof *x);
  r->x[r->m * r->n + r->n - 1] = (double)phase;
  ++r->m;
}

/* The atlas's word on section point k (of `phases` a period): 1 once
 * cell_hits consecutive points (k >= 1) lie in cells of one class. */
static int atlas_says(classify_ctx *c, size_t k, const double *x) {
  if (!c->atlas || k == 0) return 0;
  int cls = basins_atlas_lookup(c->atlas, x, k % c->phases);
  if (cls < 0 || (size_t)cls >= c->natt) {
    c->hits = 0;
    return 0;
  }
  c->hits = cls == c->cell_class ? c->hits + 1 : 1;
  c->cell_class = cls;
  if (c->hits < c->need_hits) return 0;
  c->which = cls;
  c->by_atlas = 1;
  return 1;
}

static int on_section(size_t k, double t, const double *x, void *data) {
  classify_ctx *c = data;
  c->last_k = (k + c->phases - 1) / c->phases; /* periods begun */
  if (c->rec) record(c->rec, x, k % c->phases);
  for (size_t j = 0; k % c->phases == 0 && j < c->natt; ++j) {
    int r = c->att[j].test(t, x, c->att[j].data);
    if (r < 0) {
      c->error = r;
      return r;
    }
    c->count[j] = r ? c->count[j] + 1 : 0;
    size_t need = c->att[j].confirm ? c->att[j].confirm : 1;
    if (!c->fixed && c->count[j] >= need) {
      c->which = (int)j;
      return 1; /* settled: stop integrating this point */
    }
  }
  return atlas_says(c, k, x);
}

int basins_classify_ex(whirl_ode *ode, const double *x0,
                       const whirl_attractor *att, size_t natt,
                       const whirl_basins_options *o,
                       const whirl_basins_atlas *atlas, basins_record *rec,
                       int *which, unsigned *periods, int *by_atlas) {
  if (!ode || !x0 || (!att && natt) || natt > MAX_ATTRACTORS || !o ||
      !which || !(o->period > 0) || !isfinite(o->period))
    return WHIRL_EINVAL;
  classify_ctx c;
  memset(&c, 0, sizeof c);
  c.att = att;
  c.natt = natt;
  c.fixed = o->fixed_horizon;
  c.which = WHIRL_BASIN_UNSETTLED;
  c.atlas = o->fixed_horizon ? NULL : atlas;
  c.need_hits = o->cell_hits ? o->cell_hits : 3;
  c.cell_class = -1;
  c.rec = rec;
  c.phases = (c.atlas || rec) && o->section_phases ? o->section_phases : 1;
  if (by_atlas) *by_atlas = 0;
  int rc = whirl_ode_reset(ode, o->t0, x0);
  if (rc != WHIRL_OK) {
    *which = WHIRL_BASIN_FAILED;
    if (periods) *periods = 0;
    return WHIRL_OK;
  }
  rc = whirl_ode_sample(ode, o->period / (double)c.phases,
                        o->max_periods * c.phases, on_section, &c);
  if (periods) *periods = (unsigned)c.last_k;
  if (c.error) return c.error;
  if (rc == 1) {
    *which = c.which;
    if (by_atlas) *by_atlas = c.by_atlas;
    return WHIRL_OK;
  }
  if (rc == WHIRL_OK) {
    *which = WHIRL_BASIN_UNSETTLED;
    if (c.fixed)
      for (size_t j = 0; j < natt; ++j) {
        size_t need = att[j].confirm ? att[j].confirm : 1;
        if (c.count[j] >= need) {
          *which = (int)j;
          break;
        }
      }
    return WHIRL_OK;
  }
  if (rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(ode) > 0)
    *which = WHIRL_BASIN_DOMAIN;
  else
    *which = WHIRL_BASIN_FAILED;
  return WHIRL_OK;
}

int whirl_basins_classify(whirl_ode *ode, const double *x0,
                          const whirl_attractor *att, size_t natt,
                          const whirl_basins_options *o, int *which,
                          unsigned *periods) {
  return basins_classify_ex(ode, x0, att, natt, o, NULL, NULL, which, periods,
                            NULL);
}

int basins_check(const whirl_problem *prob, const double *p, size_t npoints,
                 const double *x0, const whirl_attractor *att, size_t natt,
                 const whirl_basins_options *o, char *errbuf, size_t errlen) {
  errbuf[0] = '\0';
  if (!prob || !p || (!x0 && npoints) || !o)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "basins: missing argument");
  if (!(o->period > 0) || !isfinite(o->period))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "basins: section period must be > 0 (got %g)",
                        o->period);
  if (o->max_periods == 0)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "basins: max_periods must be >= 1");
  if (natt > MAX_ATTRACTORS)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "basins: at most %d attractors (got %zu)",
                        MAX_ATTRACTORS, natt);
  if (o->nthreads < 0 || o->nthreads > WHIRL_BASINS_MAX_THREADS)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "basins: nthreads must be in 0..%d (got %d)",
                        WHIRL_BASINS_MAX_THREADS, o->nthreads);
  char tmsg[128];
  if (whirl_basins_check_tolerances(o->rtol, o->atol, tmsg, sizeof tmsg))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "basins: %s", tmsg);
  for (size_t j = 0; j < natt; ++j)
    if (!att[j].test)
      return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                          "basins: attractor %zu has no test", j);
  return WHIRL_OK;
}

/* The atlas of this call: the caller's (checked against the points), one
 * built here (*own), or none. */
static int call_atlas(const whirl_problem *prob, const double *p,
                      size_t npoints, const double *x0,
                      const whirl_attractor *att, size_t natt,
                      const whirl_basins_options *o,
                      const whirl_basins_atlas **use, whirl_basins_atlas **own,
                      char *errbuf, size_t errlen) {
  *use = NULL;
  *own = NULL;
  if (o->fixed_horizon) return WHIRL_OK;
  if (o->atlas) {
    if (basins_atlas_dim(o->atlas) != prob->n ||
        o->first > basins_atlas_points(o->atlas) ||
        npoints > basins_atlas_points(o->atlas) - o->first)
      return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                          "basins: points %zu..%zu are not in the atlas's "
                          "list of %zu", o->first, o->first + npoints,
                          basins_atlas_points(o->atlas));
    *use = o->atlas;
    return WHIRL_OK;
  }
  if (o->seed_stride == 0 || npoints == 0) return WHIRL_OK;
  whirl_basins_options so = *o;
  so.progress = NULL;
  int rc = whirl_basins_atlas_build(prob, p, npoints, x0, att, natt, &so, own,
                                    errbuf, errlen);
  *use = *own;
  return rc;
}

int whirl_basins_compute(const whirl_problem *prob, const double *p,
                         size_t npoints, const double *x0,
                         const whirl_attractor *att, size_t natt,
                         const whirl_basins_options *o, int *which,
                         unsigned *periods, whirl_basins_stats *st,
                         char *errbuf, size_t errlen) {
  char dummy[1];
  if (!errbuf || errlen == 0) {
    errbuf = dummy;
    errlen = sizeof dummy;
  }
  int status = basins_check(prob, p, npoints, x0, att, natt, o, errbuf, errlen);
  if (status != WHIRL_OK) return status;
  if (!which && npoints)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "basins: missing argument");
  const whirl_basins_atlas *atlas;
  whirl_basins_atlas *own;
  status = call_atlas(prob, p, npoints, x0, att, natt, o, &atlas, &own,
                      errbuf, errlen);
  if (status != WHIRL_OK) return status;
  const size_t first = own ? 0 : o->first;

  size_t done = 0, tot_periods = 0, tot_steps = 0, tot_rhs = 0, tot_atlas = 0;
  const size_t n = prob->n;
#ifdef _OPENMP
  int nth = o->nthreads > 0 ? o->nthreads : omp_get_max_threads();
#endif

#ifdef _OPENMP
#pragma omp parallel num_threads(nth) reduction(+ : tot_periods, tot_steps, tot_rhs, tot_atlas)
#endif
  {
    whirl_ode *ode = whirl_ode_alloc(prob, p);
    int my_status = ode ? WHIRL_OK : WHIRL_ENOMEM;
    if (ode) my_status = whirl_ode_set_tolerances(ode, o->rtol, o->atol);
    if (ode && my_status == WHIRL_OK && o->method != WHIRL_ODE_DOPRI5)
      my_status = whirl_ode_set_method(ode, o->method);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
    for (size_t i = 0; i < npoints; ++i) {
      unsigned per = 0;
      int w = WHIRL_BASIN_FAILED, by = 0;
      if (basins_atlas_seed(atlas, first + i, &w, &per)) {
        /* a seed: classified by the tests when the atlas was built */
      } else if (my_status == WHIRL_OK) {
        int rc = basins_classify_ex(ode, x0 + i * n, att, natt, o, atlas,
                                    NULL, &w, &per, &by);
        if (rc != WHIRL_OK) my_status = rc;
      }
      which[i] = w;
      if (periods) periods[i] = per;
      tot_periods += per;
      tot_atlas += (size_t)by;
#ifdef _OPENMP
#pragma omp critical(whirl_basins_progress)
#endif
      {
        ++done;
        if (o->progress) o->progress(done, npoints, o->progress_data);
      }
    }
    if (ode) {
      whirl_ode_stats s;
      whirl_ode_get_stats(ode, &s);
      tot_steps += s.steps;
      tot_rhs += s.rhs_evals;
    }
    whirl_ode_free(ode);
#ifdef _OPENMP
#pragma omp critical(whirl_basins_status)
#endif
    if (my_status != WHIRL_OK && status == WHIRL_OK) status = my_status;
  }
  whirl_basins_atlas_free(own);
  if (st) {
    st->periods = tot_periods;
    st->steps = tot_steps;
    st->rhs_evals = tot_rhs;
    st->by_atlas = tot_atlas;
  }
  if (status != WHIRL_OK)
    WHIRL_ERRMSG(errbuf, errlen, status, "basins: %s", whirl_strerror(status));
  return status;
}

/* lib/run/run_discover.c — branches nobody gave a start for (DISCOVER,
 * doc/discovery.md): the start branch is traced, then
 *
 *  1. at every sample value s of the continuation parameter, deflated
 *     Newton (whirl/deflate.h; Farrell, Birkisson & Funke 2015) from a
 *     budget of starts (run_discover_starts.c), deflated against every
 *     solution of every traced branch at s (the branch's crossings of s,
 *     polished by Newton);
 *  2. through a second parameter (ICP's second entry): from every fold of a
 *     traced branch, the fold locus is continued in it, through isola
 *     births and merges, back to its value; a fold found there that lies on
 *     no traced branch seeds one;
 *  3. every new solution seeds a branch traced in both directions (once:
 *     a branch that closes on itself is traced whole by the first), whose
 *     crossings are deflated from then on; the report counts the branches
 *     and the isolated ones (every branch found here is disconnected from
 *     the start branch, else its solutions would have been deflated).
 *
 * Random starts come from one generator seeded by DISCOVER_SEED and the
 * sample's index, so a run is reproducible and independent of threads.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run_discover_impl.h"

static const char *const from_name[NFROM] = {
    "the model's start", "a scaled known solution", "a settled time integration",
    "a random start", "a fold locus through the second parameter"};

/* ---- traces ---------------------------------------------------------------- */

int run_trace_add(run_trace *t, const double *x, const double *p, int icp, int type, int br) {
  if (t->npts == 0) t->br = br;
  if (t->npts == t->cap) {
    size_t cap = t->cap ? 2 * t->cap : 256;
    double *nx = realloc(t->x, cap * t->n * sizeof *nx);
    if (!nx) return -1;
    t->x = nx;
    double *nq = realloc(t->q, cap * sizeof *nq);
    if (!nq) return -1;
    t->q = nq;
    int *nt = realloc(t->type, cap * sizeof *nt);
    if (!nt) return -1;
    t->type = nt;
    t->cap = cap;
  }
  double *dst = t->x + t->npts * t->n;
  if (t->convert) {
    if (t->convert(x, p, dst, t->convert_ctx)) return -1;
  } else {
    memcpy(dst, x, t->n * sizeof *x);
  }
  t->q[t->npts] = p[icp];
  t->type[t->npts++] = type;
  return 0;
}

void run_trace_free(run_trace *t) {
  free(t->x);
  free(t->q);
  free(t->type);
  memset(t, 0, sizeof *t);
}

/* ---- the search ------------------------------------------------------------- */

/* Collocation: a point of the branch (its current mesh) onto the search
 * mesh, and back. */
static int to_search(const double *x, const double *p, double *out, void *ctx) {
  disc *D = ctx;
  whirl_periodic src = whirl_periodic_of_colloc(D->b0->colloc);
  return whirl_periodic_convert(&src, x, p, &D->po, 0, out) ? -1 : 0;
}
static int to_branch(disc *D, const double *x, double *out) {
  whirl_periodic dst = whirl_periodic_of_colloc(D->b0->colloc);
  return whirl_periodic_convert(&D->po, x, D->p, &dst, 0, out) ? -1 : 0;
}

/* The box of random starts: DISCOVER_BOX, else ±the model's scale of the
 * component, else ±1.5 × its largest value on the start branch (±1 where
 * it is 0). */
static int set_box(disc *D, const run_trace *t0) {
  run_ctx *R = D->R;
  for (size_t i = 0; i < D->n; i++) D->hi[i] = 0.0;
  for (size_t k = 0; k < t0->npts; k++)
    for (size_t j = 0; j < D->nb; j++) {
      const size_t i = disc_component(D, j);
      D->hi[i] = fmax(D->hi[i], fabs(t0->x[k * t0->n + j]));
    }
  const double *scale = R->model->scale;
  for (size_t i = 0; i < D->n; i++) {
    const double a = scale ? scale[i] : D->hi[i] > 0 ? 1.5 * D->hi[i] : 1.0;
    D->lo[i] = -a;
    D->hi[i] = a;
  }
  for (size_t g = 0; g < R->s->nbox; g++) {
    const int i = run_state_index(R, &R->s->box[g].ref);
    if (i < 0) {
      run_fail(R, WHIRL_RK_DISCOVER_BOX, "DISCOVER_BOX: '%s' is not a state "
               "component of model '%s'", R->s->box[g].ref.index ? "(index)"
               : R->s->box[g].ref.name, R->prob.name);
      return -2;
    }
    D->lo[i] = R->s->box[g].lo;
    D->hi[i] = R->s->box[g].hi;
  }
  return 0;
}

/* The search system: the branch's own, or for collocation a fixed
 * uniform mesh of the same size. */
static int search_system(disc *D) {
  run_ctx *R = D->R;
  const branch_spec *b0 = D->b0;
  D->periodic = b0->kind != WHIRL_SOL_EQ;
  if (b0->kind == WHIRL_SOL_HBM) {
    D->S = b0->sys;
    D->po = whirl_periodic_of_hbm(b0->hbm);
    D->m = 8 * (2 * (size_t)R->s->nhb + 1);
  } else if (b0->kind == WHIRL_SOL_COLLOC) {
    whirl_colloc_options co;
    whirl_colloc_options_default(&co);
    co.ntst = (size_t)R->s->ntst;
    co.ncol = (size_t)R->s->ncol;
    co.forcing_param = R->model->forcing_param;
    char err[512];
    D->sc = whirl_colloc_alloc(&R->prob, &co, err, sizeof err);
    if (!D->sc) {
      run_say(R, "discovery: collocation: %s", err);
      return -1;
    }
    D->S = whirl_colloc_system(D->sc);
    D->po = whirl_periodic_of_colloc(D->sc);
    D->m = 4 * (co.ntst * co.ncol + 1);
  } else {
    D->S = b0->sys;
    D->m = 1;
  }
  D->nb = D->S->n;
  return 0;
}

static int disc_init(disc *D, run_ctx *R, const branch_spec *b0) {
  memset(D, 0, sizeof *D);
  D->R = R;
  D->b0 = b0;
  D->n = R->n;
  if (search_system(D)) return -1; /* (autonomous orbits: refused by run.c) */
  D->lo = malloc(D->n * sizeof *D->lo);
  D->hi = malloc(D->n * sizeof *D->hi);
  D->w = malloc(D->nb * sizeof *D->w);
  D->p = malloc(R->npar * sizeof *D->p);
  D->x = malloc((D->nb + 1) * sizeof *D->x);
  D->cv = malloc((b0->nb + 1) * sizeof *D->cv);
  D->cv2 = malloc((b0->nb + 1) * sizeof *D->cv2);
  D->xs = malloc((D->m * D->n > D->nb ? D->m * D->n : D->nb) * sizeof *D->xs);
  D->c = calloc(3 * D->n, sizeof *D->c);
  D->cap = 16;
  D->traces = calloc(D->cap, sizeof *D->traces);
  D->curve = calloc(D->cap, sizeof *D->curve);
  if (!D->lo || !D->hi || !D->w || !D->p || !D->x || !D->xs || !D->c || !D->cv ||
      !D->cv2 || !D->traces || !D->curve)
    return -1;
  return 0;
}

/* A new trace, in the search's unknowns. */
static run_trace *new_trace(disc *D) {
  if (D->ntraces == D->cap) {
    const size_t cap = 2 * D->cap;
    run_trace *nt = realloc(D->traces, cap * sizeof *nt);
    if (!nt) return NULL;
    D->traces = nt;
    int *nc = realloc(D->curve, cap * sizeof *nc);
    if (!nc) return NULL;
    D->curve = nc;
    D->cap = cap;
  }
  run_trace *t = &D->traces[D->ntraces];
  memset(t, 0, sizeof *t);
  t->n = D->nb;
  if (D->sc) {
    t->convert = to_search;
    t->convert_ctx = D;
  }
  D->curve[D->ntraces++] = (int)D->ncurves + 1;
  return t;
}

/* After the start branch: the box, the weights and the deflation. */
static int setup_search(disc *D) {
  run_ctx *R = D->R;
  int rc = set_box(D, &D->traces[0]);
  if (rc) return rc;
  /* collocation: node values, so an orbit's norm grows like the root of
   * the number of nodes; scaled back to one node's */
  const double per = D->sc ? 1.0 / sqrt((double)(R->s->ntst * R->s->ncol + 1)) : 1.0;
  for (size_t j = 0; j < D->nb; j++) {
    const size_t i = disc_component(D, j);
    D->w[j] = per * 2.0 / (D->hi[i] - D->lo[i]);
  }
  whirl_deflate_options o;
  whirl_deflate_options_default(&o);
  o.weight = D->w;
  o.tol = fmin(R->s->epsl, R->s->epsu) * 1e-3;
  o.max_step = 1.0;         /* at most a box half-width per step */
  o.max_distance = 20.0;
  o.min_distance = 1e-6;
  char err[512];
  D->d = whirl_deflate_alloc(D->S, &o, err, sizeof err);
  if (!D->d) {
    run_say(R, "discovery: %s", err);
    return -1;
  }
  return 0;
}

static void disc_free(disc *D) {
  for (size_t t = 0; t < D->ntraces; t++) run_trace_free(&D->traces[t]);
  free(D->traces);
  free(D->curve);
  whirl_deflate_free(D->d);
  whirl_colloc_free(D->sc);
  free(D->lo);
  free(D->hi);
  free(D->w);
  free(D->p);
  free(D->x);
  free(D->xs);
  free(D->c);
  free(D->cv);
  free(D->cv2);
}

static void params_at(disc *D, double s) {
  memcpy(D->p, D->R->par, D->R->npar * sizeof *D->p);
  D->p[D->b0->icp] = s;
}

/* The known solutions at s: every crossing of s by a traced branch. */
static int known_at(disc *D, double s) {
  whirl_deflate_clear(D->d);
  for (size_t t = 0; t < D->ntraces; t++) {
    const run_trace *T = &D->traces[t];
    if (whirl_deflate_add_crossings(D->d, T->q, T->x, T->npts, s, D->p)) return -1;
  }
  return 0;
}

/* A new branch from the solution seed at D->p: both directions (one when
 * it closes), from Newton at seed, or along ±dir[nb + 1] from it exactly
 * (a fold).  0, or the failure of run_branch. */
static int trace_curve(disc *D, const double *seed, const double *dir, int from) {
  run_ctx *R = D->R;
  branch_spec b = *D->b0;
  const size_t nb = b.nb;
  double *neg = NULL;
  if (D->sc) { /* onto the branch's mesh: the seed, and a direction (linear) */
    if (to_branch(D, seed, D->cv)) return -1;
    seed = D->cv;
    if (dir) {
      if (to_branch(D, dir, D->cv2)) return -1;
      D->cv2[nb] = dir[D->nb];
      dir = D->cv2;
    }
  }
  if (dir && !(neg = malloc((nb + 1) * sizeof *neg))) return -1;
  for (size_t j = 0; dir && j <= nb; j++) neg[j] = -dir[j];
  b.x0 = seed;
  b.p0 = D->p;
  b.bp = NULL;
  const int first = R->branch + 1;
  const double t0 = run_now();
  int rc = 0, closed = 0;
  fprintf(R->log, "discovery: a new solution at %s = %.10g from %s\n",
          R->pnames[b.icp], D->p[b.icp], from_name[from]);
  for (int sign = 1; sign >= -1 && !closed && !rc; sign -= 2) {
    run_trace *t = new_trace(D);
    if (!t) {
      rc = -1;
      break;
    }
    b.trace = t;
    b.dir_sign = sign;
    b.dir = dir ? (sign > 0 ? dir : neg) : NULL;
    rc = run_branch(R, &b);
    closed = D->traces[D->ntraces - 1].closed;
  }
  free(neg);
  D->t_trace += run_now() - t0;
  if (rc) return rc;
  D->ncurves++;
  D->nclosed += closed != 0;
  D->found[from]++;
  if (closed)
    run_summary(R, "  branch %d is isolated: a closed branch (an isola), found at "
                "%s = %.8g from %s", first, R->pnames[b.icp], D->p[b.icp], from_name[from]);
  else
    run_summary(R, "  branches %d and %d are one isolated branch (not connected to "
                "the start), found at %s = %.8g from %s", first, R->branch,
                R->pnames[b.icp], D->p[b.icp], from_name[from]);
  return 0;
}

/* Route 1: deflated Newton at sample value number si. */
static int search_sample(disc *D, size_t si, double *x) {
  run_ctx *R = D->R;
  const double s = R->s->discover[si];
  params_at(D, s);
  D->rng = (uint64_t)R->s->discover_seed * 0x9E3779B97F4A7C15ull + si + 1;
  if (known_at(D, s)) return -1;
  const size_t nknown = whirl_deflate_count(D->d);
  const size_t budget = (size_t)R->s->discover_starts;
  size_t before = D->ncurves, failed[3] = {0, 0, 0}; /* unusable, no convergence, domain */
  for (size_t k = 0; k < budget; k++) {
    int from = FROM_RANDOM;
    if (R->io.progress) R->io.progress(si * budget + k, R->s->ndiscover * budget, R->io.ctx);
    if (disc_start(D, k, nknown, x, &from)) {
      failed[0]++;
      continue;
    }
    D->starts++;
    int rc = whirl_deflate_solve(D->d, x, D->p, NULL);
    if (rc == WHIRL_ENOCONV || rc == WHIRL_EDOMAIN) {
      failed[rc == WHIRL_ENOCONV ? 1 : 2]++;
      continue;
    }
    if (rc != WHIRL_OK) {
      run_say(R, "discovery at %s = %g: %s", R->pnames[D->b0->icp], s,
              whirl_deflate_errmsg(D->d));
      return -1;
    }
    rc = trace_curve(D, x, NULL, from);
    if (rc) return rc;
    params_at(D, s); /* run_branch leaves it alone; the sample stays */
    if (known_at(D, s)) return -1;
  }
  fprintf(R->log, "discovery at %s = %.10g: %zu solutions known before, %zu "
          "new branches; of %zu starts %zu unusable (integration failed), %zu "
          "without a new solution, %zu left the domain\n", R->pnames[D->b0->icp], s,
          nknown, D->ncurves - before, budget, failed[0], failed[1], failed[2]);
  return 0;
}

/* Is the fold (x, q) one of the LPs already on a traced branch? */
static int known_fold(const disc *D, const double *x, double q) {
  for (size_t t = 0; t < D->ntraces; t++) {
    const run_trace *T = &D->traces[t];
    for (size_t k = 0; k < T->npts; k++) {
      if (T->type[k] != WHIRL_PT_LP || fabs(T->q[k] - q) > 1e-6 * (1 + fabs(q))) continue;
      double e = 0.0;
      for (size_t j = 0; j < D->nb; j++) e = fmax(e, D->w[j] * fabs(T->x[k * T->n + j] - x[j]));
      if (e < 1e-4) return 1;
    }
  }
  return 0;
}

/* One direction of the fold locus of the LP (x, p) in the second
 * parameter: every return to its value (a UZ point) that is a fold on no
 * traced branch seeds one.  0, -1. */
static int fold_pass(disc *D, whirl_fold *f, const double *Z0, const double *p0,
                     int sign, double *v, double *dir) {
  run_ctx *R = D->R;
  const int p2 = R->icp[1], q = D->b0->icp;
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.icp = (size_t)p2;
  o.ds = fmin(fmax(fabs(R->s->ds), R->s->dsmin), R->s->dsmax);
  o.ds_min = R->s->dsmin;
  o.ds_max = R->s->dsmax;
  o.nmx = (size_t)R->s->nmx;
  o.newton_tol = fmin(R->s->epsl, R->s->epsu);
  o.newton_maxit = R->s->itnw;
  o.detect_bp = o.detect_hb = o.detect_pd = 0;
  const double uz = R->par[p2];
  o.uz = &uz;
  o.nuz = 1;
  char err[512];
  whirl_cont *c = whirl_cont_alloc(whirl_fold_system(f), &o, err, sizeof err);
  if (!c) return -1;
  int rc = whirl_cont_start(c, Z0, p0, sign), returns = 0;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    if (pt->type != WHIRL_PT_UZ) continue;
    returns++;
    whirl_fold_params(f, pt->x, pt->p, D->p);
    D->p[p2] = uz;
    if (known_fold(D, pt->x, D->p[q])) continue;
    fprintf(R->log, "discovery: the fold locus in %s returns to %s = %.10g at "
            "a new fold, %s = %.10g\n", R->pnames[p2], R->pnames[p2], uz,
            R->pnames[q], D->p[q]);
    if (whirl_fold_vectors(f, pt->x, pt->p, v, NULL, NULL, NULL) != WHIRL_OK) continue;
    memcpy(dir, v, D->nb * sizeof *dir);
    dir[D->nb] = 0.0;
    memcpy(D->x, pt->x, D->nb * sizeof *D->x);
    int r = trace_curve(D, D->x, dir, FROM_FOLD);
    if (r) {
      whirl_cont_free(c);
      return r;
    }
  }
  fprintf(R->log, "  fold locus (%s): %zu points, %d returns to %s = %g, %s\n",
          sign > 0 ? "up" : "down", whirl_cont_get_stats(c)->steps, returns,
          R->pnames[p2], uz, rc == WHIRL_DONE ? whirl_stop_reason_name(whirl_cont_stop_reason(c))
                                              : whirl_cont_errmsg(c));
  whirl_cont_free(c);
  return 0;
}

/* Route 2: the fold loci of every LP of every traced branch (those of
 * branches found on the way too), in ICP's second parameter. */
static int fold_route(disc *D) {
  run_ctx *R = D->R;
  if (R->nicp < 2 || R->icp[1] < 0 || R->icp[1] == D->b0->icp) return 0;
  if (D->sc) { /* the fold system of collocation is dense: far too slow */
    fprintf(R->log, "discovery: fold loci of collocation orbits are not followed "
            "(METHOD = hbm follows them)\n");
    return 0;
  }
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, (size_t)D->b0->icp);
  char err[512];
  whirl_fold *f = whirl_fold_alloc(D->S, &fo, err, sizeof err);
  const size_t nz = D->nb + 1;
  double *Z = malloc((nz + 1) * sizeof *Z), *pz = malloc(R->npar * sizeof *pz);
  double *v = malloc(D->nb * sizeof *v), *dir = malloc(nz * sizeof *dir);
  int rc = f && Z && pz && v && dir ? 0 : -1;
  for (size_t t = 0; !rc && t < D->ntraces; t++)
    for (size_t k = 0; !rc && k < D->traces[t].npts; k++) {
      const run_trace *T = &D->traces[t];
      if (T->type[k] != WHIRL_PT_LP) continue;
      memcpy(pz, R->par, R->npar * sizeof *pz);
      pz[D->b0->icp] = T->q[k];
      memcpy(D->x, T->x + k * T->n, D->nb * sizeof *D->x);
      if (whirl_fold_init(f, D->x, pz, Z) != WHIRL_OK) continue;
      fprintf(R->log, "discovery: fold locus in %s from the LP at %s = %.10g "
              "(BR %d)\n", R->pnames[R->icp[1]], R->pnames[D->b0->icp], T->q[k], T->br);
      double *Zs = malloc((nz + 1) * sizeof *Zs);
      if (!Zs) rc = -1;
      for (int sign = 1; !rc && sign >= -1; sign -= 2) {
        memcpy(Zs, Z, nz * sizeof *Zs);
        rc = fold_pass(D, f, Zs, pz, sign, v, dir);
      }
      free(Zs);
    }
  whirl_fold_free(f);
  free(Z);
  free(pz);
  free(v);
  free(dir);
  return rc;
}

int run_discover(run_ctx *R, const branch_spec *b0) {
  disc D;
  int rc = disc_init(&D, R, b0);
  branch_spec b = *b0;
  if (!rc && !(b.trace = new_trace(&D))) rc = -1;
  if (!rc) rc = run_branch(R, &b); /* the start branch */
  const double t_start = run_now();
  if (!rc) rc = setup_search(&D);
  double *x = rc ? NULL : malloc((D.nb + 1) * sizeof *x);
  if (!rc && !x) rc = -1;
  for (size_t si = 0; !rc && si < R->s->ndiscover; si++) rc = search_sample(&D, si, x);
  const double t_loci = run_now(), traced = D.t_trace;
  if (!rc) rc = fold_route(&D);
  D.t_loci = run_now() - t_loci - (D.t_trace - traced);
  if (!rc) {
    R->curves = D.ncurves + 1;
    R->isolated = D.ncurves;
    R->closed = D.nclosed;
    const whirl_deflate_stats *st = whirl_deflate_get_stats(D.d);
    run_summary(R, "discovery: %zu branch%s, %zu of them isolated (closed or not "
                "connected to the start), %zu closed", D.ncurves + 1,
                D.ncurves ? "es" : "", D.ncurves, D.nclosed);
    fprintf(R->log, "discovery: %zu branches, %zu isolated, %zu closed; %zu starts "
            "at %zu sample values, %zu deflated Newton iterations, %zu "
            "factorisations, %.3f s: %.3f s searching, %.3f s on fold loci, "
            "%.3f s tracing the new branches\n", D.ncurves + 1, D.ncurves, D.nclosed,
            D.starts, R->s->ndiscover, st->iterations, st->factorizations,
            run_now() - t_start, run_now() - t_start - D.t_loci - D.t_trace, D.t_loci,
            D.t_trace);
  }
  free(x);
  disc_free(&D);
  return rc;
}

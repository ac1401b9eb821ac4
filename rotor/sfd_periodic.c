/* rotor/sfd_periodic.c — periodic responses of the SFD rotor by the
 * generic periodic-orbit constructors (lib/systems/hbm.c, colloc.c) and the
 * generic continuation core: synchronous orbits in the fixed frame (F_E = 0
 * as a check of eq. 15, F_E != 0 for non-circular orbits) and the
 * nonsynchronous response as a cycle of the rotating frame.  Nothing here is
 * specific to a discretisation except the thin `pdisc` wrapper; the seeds
 * come from independent routes (eq. 15 for the synchronous branches, a long
 * time integration for the nonsynchronous one).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/branch.h>
#include <whirl/colloc.h>
#include <whirl/hbm.h>
#include <whirl/ode.h>
#include <whirl/rotor/sfd_dynamics.h>
#include <whirl/rotor/sfd_periodic.h>

const char *whirl_sfd_method_name(int method) {
  switch (method) {
  case WHIRL_SFD_METHOD_CIRCULAR: return "circular";
  case WHIRL_SFD_METHOD_HBM: return "hbm";
  case WHIRL_SFD_METHOD_COLLOC: return "colloc";
  default: return "?";
  }
}

void whirl_sfd_periodic_options_default(whirl_sfd_periodic_options *o) {
  memset(o, 0, sizeof *o);
  o->method = WHIRL_SFD_METHOD_HBM;
  o->harmonics = 8;
  o->oversampling = 10;
  o->ntst = 40;
  o->ncol = 4;
  o->omega_min = 0.05;
  o->omega_max = 20.0;
  o->ds = 1e-2;
  o->ds_max = 0.2;
  o->nmx = 20000;
  o->linsol = WHIRL_LINSOL_DENSE;
}

void whirl_sfd_periodic_free(whirl_sfd_periodic *r) {
  if (!r) return;
  for (size_t b = 0; b < r->nbranch; ++b) free(r->br[b].pts);
  free(r->br);
  memset(r, 0, sizeof *r);
}

/* ------------------------------------------------ discretisation wrapper */
typedef struct pdisc {
  int method;
  whirl_hbm *h;
  whirl_colloc *c;
  const whirl_system *sys;
  size_t size;
  double *xw; /* collocation of an autonomous orbit: the arclength weights,
                 0 on the period (AUTO's default THL = {11: 0}) */
} pdisc;

static int pd_alloc(pdisc *d, const whirl_problem *prob, int forcing_param,
                    const whirl_sfd_periodic_options *o, char *errbuf,
                    size_t errlen) {
  memset(d, 0, sizeof *d);
  d->method = o->method;
  if (o->method == WHIRL_SFD_METHOD_HBM) {
    whirl_hbm_options ho;
    whirl_hbm_options_default(&ho);
    ho.harmonics = o->harmonics;
    ho.oversampling = o->oversampling;
    ho.forcing_param = forcing_param;
    ho.phase_component = 0;
    /* f_x of both SFD frames: position rows depend on velocities only */
    static const int mask[16] = {0, 0, 1, 1, 0, 0, 1, 1,
                                 1, 0, 1, 1, 0, 1, 1, 1};
    ho.fx_mask = mask;
    d->h = whirl_hbm_alloc(prob, &ho, errbuf, errlen);
    if (!d->h) return WHIRL_EINVAL;
    d->sys = whirl_hbm_system(d->h);
    d->size = whirl_hbm_size(d->h);
  } else if (o->method == WHIRL_SFD_METHOD_COLLOC) {
    whirl_colloc_options co;
    whirl_colloc_options_default(&co);
    co.ntst = o->ntst;
    co.ncol = o->ncol;
    co.forcing_param = forcing_param;
    d->c = whirl_colloc_alloc(prob, &co, errbuf, errlen);
    if (!d->c) return WHIRL_EINVAL;
    d->sys = whirl_colloc_system(d->c);
    d->size = whirl_colloc_size(d->c);
    if (forcing_param < 0) { /* the period is the last unknown */
      if (!(d->xw = malloc(d->size * sizeof *d->xw))) return WHIRL_ENOMEM;
      for (size_t i = 0; i + 1 < d->size; ++i) d->xw[i] = 1.0;
      d->xw[d->size - 1] = 0.0;
    }
  } else {
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "periodic orbits need method hbm or colloc (got %d)",
                        o->method);
  }
  return WHIRL_OK;
}

static void pd_free(pdisc *d) {
  whirl_hbm_free(d->h);
  whirl_colloc_free(d->c);
  free(d->xw);
  memset(d, 0, sizeof *d);
}

static int pd_from_samples(pdisc *d, const double *x, size_t m, double T,
                           double *X) {
  if (d->h) {
    int rc = whirl_hbm_from_samples(d->h, x, m, T, X);
    if (rc == WHIRL_OK) whirl_hbm_set_phase(d->h, X);
    return rc;
  }
  return whirl_colloc_from_samples(d->c, x, m, T, X);
}

/* State at scaled time τ ∈ [0, 1). */
static void pd_eval(const pdisc *d, const double *X, double tau, double *x) {
  if (d->h) whirl_hbm_eval(d->h, X, 2.0 * WHIRL_PI * tau, x);
  else whirl_colloc_eval(d->c, X, tau, x);
}

static double pd_period(const pdisc *d, const double *X, const double *p) {
  return d->h ? whirl_hbm_period(d->h, X, p) : whirl_colloc_period(d->c, X, p);
}

/* ------------------------------------------------------ orbit summaries */
static double radius_at(const pdisc *d, const double *X, double tau) {
  double x[4];
  pd_eval(d, X, tau, x);
  return hypot(x[0], x[1]);
}

/* Golden-section refinement of an extremum of the radius in
 * [tau - h, tau + h]; sgn = +1 for a maximum, −1 for a minimum. */
static double refine_extremum(const pdisc *d, const double *X, double tau,
                              double h, double sgn) {
  const double g = 0.5 * (sqrt(5.0) - 1.0);
  double a = tau - h, b = tau + h;
  double c1 = b - g * (b - a), c2 = a + g * (b - a);
  double f1 = sgn * radius_at(d, X, c1), f2 = sgn * radius_at(d, X, c2);
  /* to 1e-10 in τ: the extremum's value is then exact to ~1e-20 */
  for (int it = 0; it < 80 && b - a > 1e-10; ++it) {
    if (f1 > f2) {
      b = c2, c2 = c1, f2 = f1;
      c1 = b - g * (b - a);
      f1 = sgn * radius_at(d, X, c1);
    } else {
      a = c1, c1 = c2, f1 = f2;
      c2 = a + g * (b - a);
      f2 = sgn * radius_at(d, X, c2);
    }
  }
  return sgn * fmax(f1, f2);
}

enum { NSUM = 256 };

static void orbit_fill(const pdisc *d, const whirl_branch *b, size_t i,
                       int synchronous, whirl_sfd_orbit *o) {
  const whirl_branch_point *q = &b->pts[i];
  const double *X = q->x, *p = q->p;
  memset(o, 0, sizeof *o);
  o->type = q->type;
  o->label = q->label;
  o->stable = q->stable;
  o->n_unstable = q->n_unstable;
  o->Omega = p[WHIRL_SFD_OMEGA];
  double rmax = -1, rmin = INFINITY, a1 = 0, b1 = 0;
  size_t kmax = 0, kmin = 0;
  for (size_t k = 0; k < NSUM; ++k) {
    const double tau = (double)k / NSUM;
    double x[4];
    pd_eval(d, X, tau, x);
    const double r = hypot(x[0], x[1]);
    if (r > rmax) rmax = r, kmax = k;
    if (r < rmin) rmin = r, kmin = k;
    a1 += 2.0 * x[0] * cos(2.0 * WHIRL_PI * tau) / NSUM;
    b1 += 2.0 * x[0] * sin(2.0 * WHIRL_PI * tau) / NSUM;
  }
  const double h = 1.0 / NSUM;
  o->eps_max = fmax(rmax, refine_extremum(d, X, (double)kmax / NSUM, h, 1.0));
  o->eps_min = fmin(rmin, refine_extremum(d, X, (double)kmin / NSUM, h, -1.0));
  o->a1 = a1;
  o->b1 = b1;
  o->phase = synchronous ? atan2(b1, a1) : NAN;
  o->period = pd_period(d, X, p);
  o->f2 = synchronous ? NAN
                      : fabs(o->Omega - 2.0 * WHIRL_PI / o->period) / o->Omega;
  o->max_mult = NAN;
  o->mult_re = o->mult_im = NAN;
  for (size_t k = 0; k < b->nspec; ++k) {
    const double m = hypot(q->spec_re[k], q->spec_im[k]);
    if (!(m <= o->max_mult)) {
      o->max_mult = m;
      o->mult_re = q->spec_re[k];
      o->mult_im = q->spec_im[k];
    }
  }
  double *F = malloc(d->size * sizeof *F);
  o->residual = NAN;
  if (F && whirl_system_eval(d->sys, X, p, F) == 0) {
    double r = 0;
    /* collocation's integral phase condition refers to the last accepted
     * point, so for the others its row is not a residual: left out */
    const size_t nres = d->c && !synchronous ? d->size - 1 : d->size;
    for (size_t k = 0; k < nres; ++k) r = fmax(r, fabs(F[k]));
    o->residual = r;
  }
  free(F);
}

static int add_branch(whirl_sfd_periodic *out, const pdisc *d,
                      const whirl_branch *b, int synchronous, int isola) {
  whirl_sfd_periodic_branch *nb =
      realloc(out->br, (out->nbranch + 1) * sizeof *nb);
  if (!nb) return WHIRL_ENOMEM;
  out->br = nb;
  whirl_sfd_periodic_branch *B = &out->br[out->nbranch];
  memset(B, 0, sizeof *B);
  B->pts = malloc((b->len ? b->len : 1) * sizeof *B->pts);
  if (!B->pts) return WHIRL_ENOMEM;
  B->id = (int)out->nbranch + 1;
  B->isola = isola;
  B->stop_reason = b->stop_reason;
  B->len = b->len;
  for (size_t i = 0; i < b->len; ++i) {
    orbit_fill(d, b, i, synchronous, &B->pts[i]);
    if (B->pts[i].residual > out->max_residual) out->max_residual = B->pts[i].residual;
  }
  ++out->nbranch;
  return WHIRL_OK;
}

static void cont_defaults(whirl_cont_options *co, const pdisc *d,
                          const whirl_sfd_periodic_options *o) {
  /* Collocation measures a step by the orbit's integral over the period
   * (its norm weights, as AUTO), harmonic balance by its coefficients: ds
   * means the same for every discretisation of collocation, with no scale
   * by the node count. */
  whirl_cont_options_default(co);
  co->icp = WHIRL_SFD_OMEGA;
  co->ds = o->ds;
  co->ds_min = 1e-9;
  co->ds_max = o->ds_max;
  co->x_weight = d->xw;
  co->nmx = o->nmx;
  co->p_min = o->omega_min;
  co->p_max = o->omega_max;
  co->uz = o->nuz ? o->uz : NULL;
  co->nuz = o->nuz < 8 ? o->nuz : 8;
  co->detect_bp = 0; /* cycles of a forced system: no symmetry-breaking
                        branches are sought here */
  co->linsol = o->linsol;
  co->progress = o->progress;
  co->progress_ctx = o->progress_data;
  /* collocation Jacobians are sparse (block bidiagonal plus borders) */
  if (o->method == WHIRL_SFD_METHOD_COLLOC) co->linsol = WHIRL_LINSOL_SPARSE;
  co->newton_tol = 1e-12; /* the paper: residual below 7e-14 */
  if (o->method == WHIRL_SFD_METHOD_COLLOC) {
    /* chord Newton on collocation's structured solver: one factorisation
     * per point (the one the tangent and the multipliers need), cheap
     * iterations (F and one solve) that contract by about 0.03-0.2 each,
     * from a second-order predictor; the step grows after at most 8 of
     * them and shrinks after more than 12 */
    co->newton_chord = 1;
    co->newton_fast = 8;
    co->newton_maxit = 24;
    co->curved_predictor = 1;
  }
}

/* Trace a whole branch through X0 and append it; *skipped = 1 if X0 lies on
 * an already traced branch of `seen`. */
static int trace_add(whirl_sfd_periodic *out, const pdisc *d,
                     const whirl_cont_options *co, const double *X0,
                     const double *p, int synchronous, int isola,
                     whirl_branch **seen, size_t *nseen, char *errbuf,
                     size_t errlen) {
  whirl_branch *br = NULL;
  whirl_cont_stats st = {0};
  int rc = whirl_trace_branch(d->sys, co, X0, p, &br, &st, errbuf, errlen);
  if (rc != WHIRL_OK) return rc;
  out->steps += st.steps;
  out->newton_its += st.newton_its;
  rc = add_branch(out, d, br, synchronous, isola);
  seen[(*nseen)++] = br;
  return rc;
}

/* Fixed-frame samples of the circular orbit (ε, Ω) of eq. 15. */
static void circle_samples(const double *p, double eps, double Om, size_t m,
                           double *xs) {
  double xr[4];
  whirl_sfd_circ_state(eps, Om, p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA],
                       p[WHIRL_SFD_ZETA], xr);
  for (size_t j = 0; j < m; ++j)
    whirl_sfd_to_fixed(Om, 2.0 * WHIRL_PI * (double)j / ((double)m * Om), xr,
                       xs + 4 * j);
}

static int check_options(const double *p, const whirl_sfd_periodic_options *o,
                         char *errbuf, size_t errlen) {
  char msg[256];
  if (whirl_sfd_check_params(p, msg, sizeof msg) != WHIRL_OK)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "%s", msg);
  if (!(o->omega_min > 0) || !(o->omega_max > o->omega_min))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "need 0 < omega_min < omega_max (got %g, %g)",
                        o->omega_min, o->omega_max);
  if (!(o->ds > 0) || !(o->ds_max >= o->ds))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "need 0 < ds <= ds_max (got %g, %g)", o->ds, o->ds_max);
  return WHIRL_OK;
}

/* Samples of one period for a seed orbit: 256, or for harmonic balance
 * twice the 2N + 1 coefficients per component, since the projection onto N
 * harmonics needs at least 2N + 1 samples (256 made 128..200 harmonics
 * fail with "invalid argument"). */
static size_t seed_samples(const whirl_sfd_periodic_options *o) {
  const size_t hb = o->method == WHIRL_SFD_METHOD_HBM ? 2 * (2 * o->harmonics + 1) : 0;
  return hb > 256 ? hb : 256;
}

int whirl_sfd_periodic_response(const double *p0,
                                const whirl_sfd_periodic_options *o,
                                whirl_sfd_periodic *out, char *errbuf,
                                size_t errlen) {
  memset(out, 0, sizeof *out);
  double p[WHIRL_SFD_NPAR];
  memcpy(p, p0, sizeof p);
  p[WHIRL_SFD_OMEGA] = o->omega_max;
  int rc = check_options(p, o, errbuf, errlen);
  if (rc) return rc;
  const size_t msamp = seed_samples(o);
  out->method = o->method;
  pdisc d;
  if ((rc = pd_alloc(&d, whirl_sfd_fixed(), WHIRL_SFD_OMEGA, o, errbuf, errlen)))
    return rc;
  out->unknowns = d.size;
  /* the circular response at F_E = 0 gives every branch (isolas included) */
  double p_circ[WHIRL_SFD_NPAR];
  memcpy(p_circ, p, sizeof p_circ);
  p_circ[WHIRL_SFD_FE] = 0.0;
  whirl_sfd_response_options ro;
  whirl_sfd_response_options_default(&ro);
  ro.omega_min = o->omega_min;
  ro.omega_max = o->omega_max;
  whirl_sfd_response circ;
  rc = whirl_sfd_response_compute(p_circ, &ro, &circ, errbuf, errlen);
  if (rc != WHIRL_OK) {
    pd_free(&d);
    return rc;
  }
  const size_t maxb = circ.nbranch + 2;
  whirl_branch **seen = calloc(maxb, sizeof *seen);
  double *X = malloc(d.size * sizeof *X), *xs = malloc(4 * msamp * sizeof *xs);
  size_t nseen = 0;
  if (!seen || !X || !xs) rc = WHIRL_ENOMEM;
  whirl_cont_options co;
  cont_defaults(&co, &d, o);
  const double FE = p[WHIRL_SFD_FE];
  if (rc == WHIRL_OK && FE == 0.0) {
    snprintf(out->note, sizeof out->note,
             "seeded from the %zu branches of eq. 15 (circular orbits)", circ.nbranch);
    for (size_t b = 0; b < circ.nbranch && rc == WHIRL_OK; ++b) {
      const whirl_branch *cb = circ.branch[b];
      const whirl_branch_point *q = &cb->pts[cb->len / 2];
      double lo = INFINITY;
      for (size_t i = 0; i < cb->len; ++i) lo = fmin(lo, cb->pts[i].p[WHIRL_SFD_OMEGA]);
      const double Om = q->p[WHIRL_SFD_OMEGA];
      circle_samples(p, hypot(q->x[0], q->x[1]), Om, msamp, xs);
      p[WHIRL_SFD_OMEGA] = Om;
      rc = pd_from_samples(&d, xs, msamp, 2.0 * WHIRL_PI / Om, X);
      if (rc == WHIRL_OK)
        rc = trace_add(out, &d, &co, X, p, 1, lo > o->omega_min * (1 + 1e-9), seen,
                       &nseen, errbuf, errlen);
    }
  } else if (rc == WHIRL_OK) {
    /* main branch: the static deflection z = F_E plus the undamped linear
     * unbalance response at omega_min */
    const double Om = o->omega_min, A = p[WHIRL_SFD_DELTA] * Om * Om / (1.0 - Om * Om);
    for (size_t j = 0; j < msamp; ++j) {
      const double th = 2.0 * WHIRL_PI * (double)j / msamp;
      xs[4 * j] = A * cos(th);
      xs[4 * j + 1] = FE + A * sin(th);
      xs[4 * j + 2] = -Om * A * sin(th);
      xs[4 * j + 3] = Om * A * cos(th);
    }
    p[WHIRL_SFD_OMEGA] = Om;
    rc = pd_from_samples(&d, xs, msamp, 2.0 * WHIRL_PI / Om, X);
    if (rc == WHIRL_OK)
      rc = trace_add(out, &d, &co, X, p, 1, 0, seen, &nseen, errbuf, errlen);
    size_t carried = 0, nisola = 0;
    /* isolas of F_E = 0 carried to F_E by continuation in F_E at fixed Ω */
    for (size_t b = 0; b < circ.nbranch && rc == WHIRL_OK; ++b) {
      const whirl_branch *cb = circ.branch[b];
      double lo = INFINITY;
      for (size_t i = 0; i < cb->len; ++i) lo = fmin(lo, cb->pts[i].p[WHIRL_SFD_OMEGA]);
      if (lo <= o->omega_min * (1 + 1e-9)) continue;
      ++nisola;
      const whirl_branch_point *q = &cb->pts[cb->len / 2];
      const double Oi = q->p[WHIRL_SFD_OMEGA];
      circle_samples(p, hypot(q->x[0], q->x[1]), Oi, msamp, xs);
      double pf[WHIRL_SFD_NPAR];
      memcpy(pf, p, sizeof pf);
      pf[WHIRL_SFD_OMEGA] = Oi;
      pf[WHIRL_SFD_FE] = 0.0;
      if ((rc = pd_from_samples(&d, xs, msamp, 2.0 * WHIRL_PI / Oi, X))) break;
      whirl_cont_options cf = co;
      cf.icp = WHIRL_SFD_FE;
      cf.p_min = FE < 0 ? FE : 0.0;
      cf.p_max = FE < 0 ? 0.0 : FE;
      cf.nmx = 2000;
      char e2[256];
      whirl_cont *c = whirl_cont_alloc(d.sys, &cf, e2, sizeof e2);
      int found = 0;
      if (c && whirl_cont_start(c, X, pf, FE > 0 ? 1 : -1) == WHIRL_OK) {
        while (whirl_cont_step(c) == WHIRL_OK) {
          const whirl_point *pt = whirl_cont_point(c);
          if (fabs(pt->p[WHIRL_SFD_FE] - FE) < 1e-12 * (1 + fabs(FE))) {
            memcpy(X, pt->x, d.size * sizeof *X);
            memcpy(pf, pt->p, sizeof pf);
            found = 1;
            break;
          }
        }
      }
      whirl_cont_free(c);
      if (!found) continue; /* the isola does not survive to this F_E */
      int on = 0;
      for (size_t k = 0; k < nseen && !on; ++k)
        on = whirl_branch_within(seen[k], X, pf, 1.0, 1e-6);
      if (on) continue;
      ++carried;
      rc = trace_add(out, &d, &co, X, pf, 1, 1, seen, &nseen, errbuf, errlen);
    }
    snprintf(out->note, sizeof out->note,
             "main branch from the static deflection at Omega = %g; %zu of %zu "
             "isolas of F_E = 0 carried to F_E = %g by continuation in F_E",
             o->omega_min, carried, nisola, FE);
  }
  for (size_t k = 0; k < nseen; ++k) whirl_branch_free(seen[k]);
  free(seen);
  free(X);
  free(xs);
  whirl_sfd_response_free(&circ);
  pd_free(&d);
  if (rc != WHIRL_OK) {
    if (errbuf && !errbuf[0])
      WHIRL_ERRMSG(errbuf, errlen, rc, "%s", whirl_strerror(rc));
    whirl_sfd_periodic_free(out);
  }
  return rc;
}

/* ------------------------------------------------- nonsynchronous cycle */
typedef struct sample_ctx {
  double *xs;
  size_t m;
} sample_ctx;

static int take_sample(size_t k, double t, const double *x, void *data) {
  (void)t;
  sample_ctx *s = data;
  if (k < s->m) memcpy(s->xs + 4 * k, x, 4 * sizeof *x);
  return 0;
}

static double g_du(double t, const double *x, void *data) {
  (void)t, (void)data;
  return x[2]; /* u' = 0 going down: a maximum of u */
}

/* Settle on the attractor reached from rest (rotating frame), find its
 * period by returns to the section u' = 0 (u at a maximum), and take m
 * uniform samples over one period.  Returns WHIRL_ENOCONV if the motion is
 * not a cycle (a circular orbit is an equilibrium here).
 *
 * The transient only has to bring the state near the cycle, which
 * collocation's Newton iteration then corrects, so it is integrated at
 * rtol 1e-7 and stops at the first return of a section point to a previous
 * one within 1e-4 of the orbit's size (after at least 10 forcing periods,
 * at most 1500): the state is then within about 1e-4 / (1 − |μ|) of the
 * cycle, μ its largest multiplier.  The cycle is then sampled at rtol
 * 1e-12. */
enum { NCROSS = 40 };
static int cycle_from_integration(const double *p, size_t m, double *xs,
                                  double *T, char *errbuf, size_t errlen) {
  const whirl_problem *rot = whirl_sfd_rotating();
  whirl_ode *ode = whirl_ode_alloc(rot, p);
  if (!ode) return WHIRL_ENOMEM;
  whirl_ode_set_tolerances(ode, 1e-7, 1e-10);
  const double Om = p[WHIRL_SFD_OMEGA], Tf = 2.0 * WHIRL_PI / Om;
  const double x0[4] = {0, 0, 0, 0};
  whirl_ode_reset(ode, 0.0, x0);
  int rc = whirl_ode_evolve(ode, 10.0 * Tf);
  /* the last NCROSS section points (ring buffer), and the closing pair */
  double tc[NCROSS], xc[NCROSS][4], xe[4], te, scale = 0.0, Tr = 0.0;
  double xstart[4];
  size_t nc = 0, found = 0;
  const double t_end = 1500.0 * Tf;
  while (rc == WHIRL_OK && !found && whirl_ode_t(ode) < t_end) {
    if ((rc = whirl_ode_step(ode, t_end)) < 0) break;
    rc = WHIRL_OK;
    if (whirl_ode_find_event(ode, g_du, NULL, -1, 0.0, &te, xe) != 1) continue;
    const size_t slot = nc % NCROSS;
    tc[slot] = te;
    memcpy(xc[slot], xe, sizeof xe);
    ++nc;
    scale = fmax(scale, hypot(xe[0], xe[1]));
    /* the nearest earlier section point that this one returns to */
    for (size_t k = 1; k < NCROSS && k < nc && !found; ++k) {
      const size_t q = (nc - 1 - k) % NCROSS;
      double dist = 0.0;
      for (int i = 0; i < 4; ++i) dist = fmax(dist, fabs(xe[i] - xc[q][i]));
      if (dist < 1e-4 * fmax(scale, 1e-3)) {
        found = 1;
        Tr = te - tc[q];
        memcpy(xstart, xe, sizeof xe);
      }
    }
  }
  if (rc != WHIRL_OK) {
    rc = WHIRL_ERRMSG(errbuf, errlen, rc,
                      "nonsync: integration from rest at Omega = %g "
                      "failed: %s",
                      Om, whirl_ode_errmsg(ode));
    whirl_ode_free(ode);
    return rc;
  }
  if (nc < 2 || !found || scale < 1e-9) {
    whirl_ode_free(ode);
    return WHIRL_ERRMSG(
        errbuf, errlen, WHIRL_ENOCONV,
        "nonsync: from rest at Omega = %g the rotor settles on %s, not "
        "on a nonsynchronous cycle; start at another speed "
        "(--omega-start)",
        Om,
        nc < 2 ? "a circular orbit"
               : "no periodic cycle of the rotating frame");
  }
  *T = Tr;
  whirl_ode_set_tolerances(ode, 1e-12, 1e-15);
  whirl_ode_reset(ode, 0.0, xstart);
  sample_ctx sc = {xs, m};
  rc = whirl_ode_sample(ode, *T / (double)m, m - 1, take_sample, &sc);
  whirl_ode_free(ode);
  if (rc != WHIRL_OK)
    return WHIRL_ERRMSG(errbuf, errlen, rc,
                        "nonsync: sampling the cycle failed");
  /* a circular orbit is an equilibrium of the rotating frame: its decaying
   * oscillation also returns to the section, but with (almost) no
   * amplitude left */
  double spread = 0.0;
  for (size_t k = 1; k < m; ++k)
    for (int i = 0; i < 2; ++i) spread = fmax(spread, fabs(xs[4 * k + i] - xs[i]));
  if (spread < 1e-2 * fmax(scale, 1e-3))
    return WHIRL_ERRMSG(
        errbuf, errlen, WHIRL_ENOCONV,
        "nonsync: from rest at Omega = %g the rotor settles on a circular "
        "orbit (an equilibrium of the rotating frame), not on a "
        "nonsynchronous cycle; start at another speed (--omega-start)",
        p[WHIRL_SFD_OMEGA]);
  return WHIRL_OK;
}

int whirl_sfd_nonsync(const double *p0, double omega_start,
                      const whirl_sfd_periodic_options *o,
                      whirl_sfd_periodic *out, char *errbuf, size_t errlen) {
  memset(out, 0, sizeof *out);
  double p[WHIRL_SFD_NPAR];
  memcpy(p, p0, sizeof p);
  p[WHIRL_SFD_OMEGA] = omega_start;
  int rc = check_options(p, o, errbuf, errlen);
  if (rc) return rc;
  if (p[WHIRL_SFD_FE] != 0.0)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "nonsync: the rotating frame needs F_E = 0 (got %g)",
                        p[WHIRL_SFD_FE]);
  if (!(omega_start >= o->omega_min && omega_start <= o->omega_max))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "nonsync: start speed %g outside [%g, %g]", omega_start,
                        o->omega_min, o->omega_max);
  out->method = o->method;
  const size_t msamp = seed_samples(o);
  double *xs = malloc(4 * msamp * sizeof *xs), T = 0;
  if (!xs) return WHIRL_ENOMEM;
  rc = cycle_from_integration(p, msamp, xs, &T, errbuf, errlen);
  pdisc d;
  if (rc == WHIRL_OK) rc = pd_alloc(&d, whirl_sfd_rotating(), -1, o, errbuf, errlen);
  if (rc != WHIRL_OK) {
    free(xs);
    return rc;
  }
  out->unknowns = d.size;
  double *X = malloc(d.size * sizeof *X);
  whirl_branch *br = NULL;
  if (!X) rc = WHIRL_ENOMEM;
  if (rc == WHIRL_OK) rc = pd_from_samples(&d, xs, msamp, T, X);
  if (rc == WHIRL_OK && d.c) {
    /* collocation: correct once, adapt the mesh to the orbit, go on */
    whirl_cont_options co;
    cont_defaults(&co, &d, o);
    whirl_cont *c = whirl_cont_alloc(d.sys, &co, errbuf, errlen);
    if (c && whirl_cont_start(c, X, p, 1) == WHIRL_OK &&
        whirl_cont_step(c) == WHIRL_OK) {
      memcpy(X, whirl_cont_point(c)->x, d.size * sizeof *X);
      whirl_colloc_adapt(d.c, X);
    }
    whirl_cont_free(c);
  }
  if (rc == WHIRL_OK) {
    whirl_cont_options co;
    cont_defaults(&co, &d, o);
    co.detect_loop = 0;
    whirl_cont_stats st = {0};
    rc = whirl_trace_branch(d.sys, &co, X, p, &br, &st, errbuf, errlen);
    if (rc == WHIRL_OK) {
      out->steps = st.steps;
      out->newton_its = st.newton_its;
      rc = add_branch(out, &d, br, 0, 0);
    }
  }
  snprintf(out->note, sizeof out->note,
           "cycle of the rotating frame from a time integration from rest at "
           "Omega = %g (period %.10g)",
           omega_start, T);
  whirl_branch_free(br);
  free(X);
  free(xs);
  pd_free(&d);
  if (rc != WHIRL_OK) whirl_sfd_periodic_free(out);
  return rc;
}

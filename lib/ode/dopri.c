/* lib/ode/dopri.c — the explicit Runge–Kutta pair of Dormand & Prince,
 * "A family of embedded Runge–Kutta formulae", J. Comput. Appl. Math. 6
 * (1980) 19–26, as in Hairer's DOPRI5 (Hairer, Nørsett & Wanner, Solving
 * Ordinary Differential Equations I, 2nd ed., §II.4–II.6): 5th-order
 * solution with local extrapolation, first-same-as-last, the max-norm error
 * test of MATLAB's ode45 (whirl/ode.h), Hairer's PI step-size controller
 * (β = 0.04, safety 0.9, factor in [0.2, 10], no increase right after a
 * rejection), his starting-step algorithm (HNW I p. 169), the 4th-order
 * continuous extension of DOPRI5 (subroutine CONTD5, HNW I §II.6) and event
 * location on it by the Illinois method.  No global state: one integrator
 * per thread.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>

#include "ode_impl.h"

/* ------------------------------------------------------------------------
 * Butcher tableau (Dormand & Prince 1980, Table 2; HNW I Table II.5.2) */
static const double C2 = 1.0 / 5.0, C3 = 3.0 / 10.0, C4 = 4.0 / 5.0,
                    C5 = 8.0 / 9.0;
static const double A21 = 1.0 / 5.0;
static const double A31 = 3.0 / 40.0, A32 = 9.0 / 40.0;
static const double A41 = 44.0 / 45.0, A42 = -56.0 / 15.0, A43 = 32.0 / 9.0;
static const double A51 = 19372.0 / 6561.0, A52 = -25360.0 / 2187.0,
                    A53 = 64448.0 / 6561.0, A54 = -212.0 / 729.0;
static const double A61 = 9017.0 / 3168.0, A62 = -355.0 / 33.0,
                    A63 = 46732.0 / 5247.0, A64 = 49.0 / 176.0,
                    A65 = -5103.0 / 18656.0;
/* 5th-order weights (= row 7: FSAL) */
static const double A71 = 35.0 / 384.0, A73 = 500.0 / 1113.0,
                    A74 = 125.0 / 192.0, A75 = -2187.0 / 6784.0,
                    A76 = 11.0 / 84.0;
/* b - b̂: 5th minus 4th order weights */
static const double E1 = 71.0 / 57600.0, E3 = -71.0 / 16695.0,
                    E4 = 71.0 / 1920.0, E5 = -17253.0 / 339200.0,
                    E6 = 22.0 / 525.0, E7 = -1.0 / 40.0;
/* dense output (Hairer's DOPRI5, coefficients D1..D7) */
static const double D1 = -12715105075.0 / 11282082432.0,
                    D3 = 87487479700.0 / 32700410799.0,
                    D4 = -10690763975.0 / 1880347072.0,
                    D5 = 701980252875.0 / 199316789632.0,
                    D6 = -1453857185.0 / 822651844.0,
                    D7 = 69997945.0 / 29380423.0;

/* step-size control (DOPRI5 defaults) */
static const double SAFE = 0.9, BETA = 0.04, FACMIN = 0.2, FACMAX = 10.0;

/* struct whirl_ode: ode_impl.h (shared with the BDF back end, bdf.c) */

/* ------------------------------------------------------------------------ */

static int all_finite(const double *v, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

/* f = f(t, y).  Returns 0, > 0 recoverable (callback > 0 or a non-finite
 * output), < 0 fatal.  last_rhs is the callback's status, or WHIRL_EBADFUNC
 * when it returned 0 with a non-finite value. */
static int eval(whirl_ode *o, double t, const double *y, double *f) {
  ++o->st.rhs_evals;
  int r = o->prob.rhs(t, y, o->p, f, o->prob.data);
  if (r == 0 && !all_finite(f, o->n)) {
    o->last_rhs = WHIRL_EBADFUNC;
    return 1;
  }
  o->last_rhs = r;
  return r;
}

int whirl_ode_eval_(whirl_ode *o, double t, const double *y, double *f) {
  return eval(o, t, y, f);
}

/* what the right-hand side said last, for messages */
void whirl_ode_rhs_said_(const whirl_ode *o, char *buf, size_t len) {
  if (o->last_rhs == WHIRL_EBADFUNC)
    snprintf(buf, len, "right-hand side returned NaN or Inf");
  else
    snprintf(buf, len, "right-hand side returned %d", o->last_rhs);
}

/* the default minimum step: 16 units in the last place of t */
double whirl_ode_ulp16_(double t) {
  const double a = fabs(t);
  return 16.0 * (nextafter(a, INFINITY) - a);
}

/* ------------------------------------------------------------------------
 * Allocation and settings */

whirl_ode *whirl_ode_alloc(const whirl_problem *prob, const double *p) {
  if (prob == NULL || prob->rhs == NULL || prob->n == 0) return NULL;
  if (prob->npar > 0 && p == NULL) return NULL;
  const size_t n = prob->n, npar = prob->npar;
  if (n > SIZE_MAX / sizeof(double) / 20) return NULL;
  whirl_ode *o = calloc(1, sizeof *o);
  if (o == NULL) return NULL;
  /* x, x_prev, xs, xnew, k1..k7, 4n dense coefficients */
  double *mem = malloc(15 * n * sizeof *mem);
  double *pm = malloc((2 * npar + 1) * sizeof *pm);
  if (mem == NULL || pm == NULL) {
    free(mem);
    free(pm);
    free(o);
    return NULL;
  }
  o->prob = *prob;
  o->n = n;
  o->npar = npar;
  o->p = pm;
  o->p_new = pm + npar;
  if (npar > 0) memcpy(o->p, p, npar * sizeof *p);
  o->x = mem;
  o->x_prev = mem + n;
  o->xs = mem + 2 * n;
  o->xnew = mem + 3 * n;
  for (int i = 0; i < 7; ++i) o->k[i] = mem + (4 + (size_t)i) * n;
  o->rc = mem + 11 * n;
  o->rtol = 1e-12;
  o->atol = 1e-15;
  o->t = o->t_prev = NAN;
  o->errmsg[0] = '\0';
  return o;
}

void whirl_ode_free(whirl_ode *o) {
  if (o == NULL) return;
  whirl_bdf_free_(o->bdf);
  whirl_dop853_free_(o->d8);
  free(o->x); /* start of the state block */
  free(o->p);
  free(o);
}

int whirl_ode_set_tolerances(whirl_ode *o, double rtol, double atol) {
  if (o == NULL) return WHIRL_EINVAL;
  if (!(rtol >= 100.0 * DBL_EPSILON) || !isfinite(rtol))
    return WHIRL_FAIL(o, WHIRL_EINVAL,
                      "rtol must be finite and >= %.3g (got %g)",
                      100.0 * DBL_EPSILON, rtol);
  if (!(atol > 0.0) || !isfinite(atol))
    return WHIRL_FAIL(o, WHIRL_EINVAL, "atol must be finite and > 0 (got %g)",
                      atol);
  o->rtol = rtol;
  o->atol = atol;
  return WHIRL_OK;
}

int whirl_ode_set_step_limits(whirl_ode *o, double h_init, double h_min,
                              double h_max) {
  if (o == NULL) return WHIRL_EINVAL;
  if (!(h_init >= 0.0) || !(h_min >= 0.0) || !(h_max >= 0.0) ||
      !isfinite(h_init) || !isfinite(h_min) || !isfinite(h_max))
    return WHIRL_FAIL(
        o, WHIRL_EINVAL,
        "step limits must be finite and >= 0 (got h_init %g, h_min "
        "%g, h_max %g)",
        h_init, h_min, h_max);
  if (h_max > 0.0 && (h_min > h_max || h_init > h_max))
    return WHIRL_FAIL(o, WHIRL_EINVAL,
                      "need h_min <= h_max and h_init <= h_max (got h_init %g, "
                      "h_min %g, h_max %g)",
                      h_init, h_min, h_max);
  if (h_init > 0.0 && h_init < h_min)
    return WHIRL_FAIL(o, WHIRL_EINVAL, "h_init %g below h_min %g", h_init,
                      h_min);
  o->h_init = h_init;
  o->h_min = h_min;
  o->h_max = h_max;
  return WHIRL_OK;
}

int whirl_ode_set_max_steps(whirl_ode *o, size_t max_steps) {
  if (o == NULL) return WHIRL_EINVAL;
  o->max_steps = max_steps;
  return WHIRL_OK;
}

size_t whirl_ode_max_steps_(const whirl_ode *o) { return o->max_steps; }

char *whirl_ode_errbuf_(whirl_ode *o) { return o->errmsg; }

int whirl_ode_set_params(whirl_ode *o, const double *p) {
  if (o == NULL) return WHIRL_EINVAL;
  if (o->npar == 0) return WHIRL_OK;
  if (p == NULL) return WHIRL_FAIL(o, WHIRL_EINVAL, "parameter vector is NULL");
  if (!all_finite(p, o->npar))
    return WHIRL_FAIL(o, WHIRL_EINVAL, "parameters must be finite");
  memcpy(o->p_new, p, o->npar * sizeof *p);
  o->p_pending = 1;
  return WHIRL_OK;
}

int whirl_ode_reset(whirl_ode *o, double t0, const double *x0) {
  if (o == NULL) return WHIRL_EINVAL;
  if (x0 == NULL) return WHIRL_FAIL(o, WHIRL_EINVAL, "initial state is NULL");
  if (!isfinite(t0))
    return WHIRL_FAIL(o, WHIRL_EINVAL, "initial time %g is not finite", t0);
  for (size_t i = 0; i < o->n; ++i)
    if (!isfinite(x0[i]))
      return WHIRL_FAIL(o, WHIRL_EINVAL,
                        "initial state x[%zu] = %g is not finite", i, x0[i]);
  if (o->p_pending) {
    memcpy(o->p, o->p_new, o->npar * sizeof *o->p);
    o->p_pending = 0;
  }
  memcpy(o->x, x0, o->n * sizeof *x0);
  memcpy(o->x_prev, x0, o->n * sizeof *x0);
  o->t = o->t_prev = t0;
  o->h = o->h_init;
  o->facold = 1e-4;
  o->started = 1;
  o->have_step = 0;
  o->have_f = 0;
  o->reject_last = 0;
  o->last_rhs = 0;
  o->errmsg[0] = '\0';
  if (o->method == WHIRL_ODE_BDF) {
    const int r = whirl_bdf_reset_(o);
    if (r != WHIRL_OK) o->started = 0;
    return r;
  }
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Starting step (HNW I p. 169, HINIT of DOPRI5 and DOP853) for a method of
 * the given order, with the max norm of the error test.  f0 = f(t, x);
 * uses xs and f1 (n doubles).  Returns the step magnitude in *h, or a
 * fatal callback status. */
int whirl_ode_initial_step_(whirl_ode *o, const double *f0, double *f1,
                            int order, double posneg, double span,
                            double hmax, double *hout) {
  const size_t n = o->n;
  const double *x = o->x;
  double dnf = 0.0, dny = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double sk = fmax(o->atol, o->rtol * fabs(x[i]));
    dnf = fmax(dnf, fabs(f0[i]) / sk);
    dny = fmax(dny, fabs(x[i]) / sk);
  }
  double h = (dnf <= 1e-5 || dny <= 1e-5) ? 1e-6 : 0.01 * dny / dnf;
  h = fmin(fmin(h, hmax), span);
  /* an explicit Euler step, to estimate the second derivative */
  for (size_t i = 0; i < n; ++i) o->xs[i] = x[i] + posneg * h * f0[i];
  const int r = eval(o, o->t + posneg * h, o->xs, f1);
  if (r < 0) return r;
  double h1;
  if (r > 0) {
    h1 = 0.1 * h; /* f undefined there: start well inside */
  } else {
    double der2 = 0.0;
    for (size_t i = 0; i < n; ++i) {
      const double sk = fmax(o->atol, o->rtol * fabs(x[i]));
      der2 = fmax(der2, fabs(f1[i] - f0[i]) / sk);
    }
    der2 /= h;
    const double der12 = fmax(der2, dnf);
    h1 = der12 <= 1e-15 ? fmax(1e-6, h * 1e-3) : pow(0.01 / der12, 1.0 / order);
    h1 = fmin(100.0 * h, h1);
  }
  *hout = fmin(h1, hmax);
  return 0;
}

/* ------------------------------------------------------------------------
 * One step */

/* The right-hand side at the start of the first step into f (later steps
 * reuse the last stage: first same as last). */
int whirl_ode_first_rhs_(whirl_ode *o, double *f) {
  int r = eval(o, o->t, o->x, f);
  if (r < 0)
    return WHIRL_FAIL(o, WHIRL_EUSER,
                      "right-hand side returned %d at t = %.17g", r, o->t);
  if (r > 0) {
    char what[64];
    whirl_ode_rhs_said_(o, what, sizeof what);
    return WHIRL_FAIL(o, WHIRL_ESTEP,
                      "no step possible from t = %.17g: %s there", o->t, what);
  }
  o->have_f = 1;
  return WHIRL_OK;
}

/* The six stages of a step of hh from (t, x) to tn (Dormand & Prince 1980,
 * Butcher table above): k[1..6] and the 5th-order solution in xnew.  The
 * rhs status: 0, or the first nonzero one. */
static int stages(whirl_ode *o, double t, double hh, double tn) {
  const size_t n = o->n;
  const double *const x = o->x;
  double *const xs = o->xs, *const xn = o->xnew;
  double **k = o->k;
  size_t i;
  int r;
  for (i = 0; i < n; ++i) xs[i] = x[i] + hh * A21 * k[0][i];
  if ((r = eval(o, t + C2 * hh, xs, k[1])) != 0) return r;
  for (i = 0; i < n; ++i)
    xs[i] = x[i] + hh * (A31 * k[0][i] + A32 * k[1][i]);
  if ((r = eval(o, t + C3 * hh, xs, k[2])) != 0) return r;
  for (i = 0; i < n; ++i)
    xs[i] = x[i] + hh * (A41 * k[0][i] + A42 * k[1][i] + A43 * k[2][i]);
  if ((r = eval(o, t + C4 * hh, xs, k[3])) != 0) return r;
  for (i = 0; i < n; ++i)
    xs[i] = x[i] + hh * (A51 * k[0][i] + A52 * k[1][i] + A53 * k[2][i] +
                         A54 * k[3][i]);
  if ((r = eval(o, t + C5 * hh, xs, k[4])) != 0) return r;
  for (i = 0; i < n; ++i)
    xs[i] = x[i] + hh * (A61 * k[0][i] + A62 * k[1][i] + A63 * k[2][i] +
                         A64 * k[3][i] + A65 * k[4][i]);
  if ((r = eval(o, tn, xs, k[5])) != 0) return r;
  for (i = 0; i < n; ++i)
    xn[i] = x[i] + hh * (A71 * k[0][i] + A73 * k[2][i] + A74 * k[3][i] +
                         A75 * k[4][i] + A76 * k[5][i]);
  return eval(o, tn, xn, k[6]);
}

/* ode45's error test: max_i |e_i| / max(atol, rtol max(|x|, |x_new|)). */
static double error_norm(const whirl_ode *o, double hh) {
  const double *const x = o->x, *const xn = o->xnew;
  double *const *k = o->k;
  double err = 0.0;
  for (size_t i = 0; i < o->n; ++i) {
    const double e =
        hh * (E1 * k[0][i] + E3 * k[2][i] + E4 * k[3][i] + E5 * k[4][i] +
              E6 * k[5][i] + E7 * k[6][i]);
    const double sk = fmax(o->atol, o->rtol * fmax(fabs(x[i]), fabs(xn[i])));
    err = fmax(err, fabs(e) / sk);
  }
  return err;
}

/* Accept the step from t to tn: the dense output (CONTD5), then advance;
 * the next step is hnew. */
static void accept_step(whirl_ode *o, double t, double tn, double hh, double err,
                        double hnew) {
  const size_t n = o->n;
  double *const x = o->x, *const xn = o->xnew;
  double **k = o->k;
  double *rc = o->rc;
  for (size_t i = 0; i < n; ++i) {
    const double ydiff = xn[i] - x[i];
    const double bspl = hh * k[0][i] - ydiff;
    rc[i] = ydiff;
    rc[n + i] = bspl;
    rc[2 * n + i] = ydiff - hh * k[6][i] - bspl;
    rc[3 * n + i] = hh * (D1 * k[0][i] + D3 * k[2][i] + D4 * k[3][i] +
                          D5 * k[4][i] + D6 * k[5][i] + D7 * k[6][i]);
  }
  memcpy(o->x_prev, x, n * sizeof *x);
  memcpy(x, xn, n * sizeof *x);
  double *tmp = k[0]; /* first same as last */
  k[0] = k[6];
  k[6] = tmp;
  o->t_prev = t;
  o->t = tn;
  o->facold = fmax(err, 1e-4);
  o->h = hnew;
  o->reject_last = 0;
  o->have_step = 1;
  ++o->st.steps;
}

/* DOPRI5 as an explicit method of the shared step (below) */
static double *dopri_f0(whirl_ode *o) { return o->k[0]; }
static double *dopri_scratch(whirl_ode *o) { return o->k[1]; }
static const ode_explicit_method dopri5 = {
    5, 0.2 - 0.75 * BETA, BETA, SAFE, FACMIN, FACMAX,
    dopri_f0, dopri_scratch, stages, error_norm, accept_step};

/* One step of an explicit embedded pair m towards t_end (o->t != t_end):
 * the starting step (HNW I p. 169) if none is proposed, then steps of the
 * proposed size until one passes the error test, with Hairer's PI
 * controller (fac = err^expo / facold^beta, the new step's factor within
 * [facmin, facmax] with safety safe, no increase right after a rejection);
 * a recoverable failure (the model's domain, a non-finite error) retries
 * with h/4. */
int whirl_ode_explicit_step_(whirl_ode *o, const ode_explicit_method *m,
                             double t_end) {
  const double posneg = t_end > o->t ? 1.0 : -1.0;
  const double hmax = o->h_max > 0.0 ? o->h_max : INFINITY;
  int r;
  if (!o->have_f && (r = whirl_ode_first_rhs_(o, m->f0(o))) != WHIRL_OK)
    return r;
  double h = o->h;
  if (!(h > 0.0)) {
    r = whirl_ode_initial_step_(o, m->f0(o), m->scratch(o), m->order, posneg,
                                fabs(t_end - o->t), hmax, &h);
    if (r < 0)
      return WHIRL_FAIL(o, WHIRL_EUSER,
                        "right-hand side returned %d at t = %.17g", r, o->t);
  }
  h = fmin(h, hmax);

  for (;;) {
    const double t = o->t, span = fabs(t_end - t);
    const double hmin = fmax(o->h_min, whirl_ode_ulp16_(t));
    h = fmax(h, fmin(hmin, span));
    /* reach t_end exactly; stretch the step by up to 1% to get there */
    const int last = 1.01 * h >= span;
    const double hs = last ? span : h, hh = posneg * hs;
    const double tn = last ? t_end : t + hh;
    const char *why = NULL;

    r = m->stages(o, t, hh, tn);
    if (r < 0)
      return WHIRL_FAIL(o, WHIRL_EUSER,
                        "right-hand side returned %d in a step from t = %.17g",
                        r, t);
    const double err = r ? NAN : m->error(o, hh);
    if (!r && !isfinite(err)) why = "non-finite error estimate";
    if (!r && !why) {
      const double fac11 = pow(err, m->expo);
      double fac = fac11 / pow(o->facold, m->beta);
      fac = fmax(1.0 / m->facmax, fmin(1.0 / m->facmin, fac / m->safe));
      double hnew = hs / fac;
      if (err <= 1.0) {
        hnew = fmin(hnew, hmax);
        if (o->reject_last) hnew = fmin(hnew, hs);
        /* a step shortened to hit t_end says little about the next one */
        if (last && hs < h) hnew = fmin(fmax(hnew, h), hmax);
        m->accept(o, t, tn, hh, err, hnew);
        return WHIRL_OK;
      }
      hnew = hs / fmin(1.0 / m->facmin, fac11 / m->safe);
      ++o->st.rejected;
      o->reject_last = 1;
      if (hnew < hmin)
        return WHIRL_FAIL(
            o, WHIRL_ESTEP,
            "step size %.3g below minimum %.3g at t = %.17g: error "
            "test failed (error %.3g)",
            hnew, hmin, t, err);
      h = hnew;
      continue;
    }
    /* recoverable failure: reject, retry with h/4 */
    ++o->st.rejected;
    o->reject_last = 1;
    h = hs / 4.0;
    if (h < hmin) {
      char what[64];
      if (why == NULL) whirl_ode_rhs_said_(o, what, sizeof what);
      return WHIRL_FAIL(o, WHIRL_ESTEP,
                        "step size %.3g below minimum %.3g at t = %.17g: %s", h,
                        hmin, t, why != NULL ? why : what);
    }
  }
}

int whirl_ode_step(whirl_ode *o, double t_end) {
  if (o == NULL) return WHIRL_EINVAL;
  if (!o->started)
    return WHIRL_FAIL(o, WHIRL_EINVAL,
                      "no initial state: call whirl_ode_reset");
  if (!isfinite(t_end))
    return WHIRL_FAIL(o, WHIRL_EINVAL, "t_end %g is not finite", t_end);
  if (t_end == o->t) return WHIRL_DONE;
  if (o->method == WHIRL_ODE_BDF) return whirl_bdf_step_(o, t_end);
  if (o->method == WHIRL_ODE_DOP853) return whirl_dop853_step_(o, t_end);
  return whirl_ode_explicit_step_(o, &dopri5, t_end);
}

int whirl_ode_evolve(whirl_ode *o, double t_end) {
  if (o == NULL) return WHIRL_EINVAL;
  if (!o->started)
    return WHIRL_FAIL(o, WHIRL_EINVAL,
                      "no initial state: call whirl_ode_reset");
  if (!isfinite(t_end))
    return WHIRL_FAIL(o, WHIRL_EINVAL, "t_end %g is not finite", t_end);
  size_t count = 0;
  while (o->t != t_end) {
    if (o->max_steps > 0 && count >= o->max_steps)
      return WHIRL_FAIL(
          o, WHIRL_EMAXITER,
          "%zu steps taken, t = %.17g has not reached t_end = %.17g", count,
          o->t, t_end);
    const int rc = whirl_ode_step(o, t_end);
    if (rc != WHIRL_OK) return rc;
    ++count;
  }
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Access */

size_t whirl_ode_size(const whirl_ode *o) { return o ? o->n : 0; }
double whirl_ode_t(const whirl_ode *o) { return o ? o->t : NAN; }
const double *whirl_ode_x(const whirl_ode *o) { return o ? o->x : NULL; }
double whirl_ode_t_prev(const whirl_ode *o) { return o ? o->t_prev : NAN; }
const double *whirl_ode_x_prev(const whirl_ode *o) {
  return o ? o->x_prev : NULL;
}
double whirl_ode_h(const whirl_ode *o) {
  if (o == NULL) return NAN;
  return o->method == WHIRL_ODE_BDF && o->started ? whirl_bdf_h_(o) : o->h;
}

void whirl_ode_get_stats(const whirl_ode *o, whirl_ode_stats *s) {
  if (s == NULL) return;
  if (o == NULL) {
    memset(s, 0, sizeof *s);
    return;
  }
  *s = o->st;
}

void whirl_ode_get_implicit_stats(const whirl_ode *o,
                                  whirl_ode_implicit_stats *s) {
  if (s == NULL) return;
  if (o == NULL) {
    memset(s, 0, sizeof *s);
    return;
  }
  *s = o->ist;
}

int whirl_ode_last_rhs_status(const whirl_ode *o) {
  return o ? o->last_rhs : WHIRL_EINVAL;
}

const char *whirl_ode_errmsg(const whirl_ode *o) {
  return o ? o->errmsg : "integrator is NULL";
}

/* ------------------------------------------------------------------------
 * Dense output and events */

/* x(t_prev + θ h) by CONTD5 (or CVODE's polynomial for BDF), no checks:
 * t is in the last step */
static void dense_eval(const whirl_ode *o, double t, double *out) {
  const size_t n = o->n;
  if (t == o->t) {
    memcpy(out, o->x, n * sizeof *out);
    return;
  }
  if (t == o->t_prev) {
    memcpy(out, o->x_prev, n * sizeof *out);
    return;
  }
  if (o->method == WHIRL_ODE_BDF) {
    (void)whirl_bdf_dense_(o, t, out); /* inside the step: cannot fail */
    return;
  }
  if (o->method == WHIRL_ODE_DOP853) { /* prepared by the caller */
    whirl_dop853_dense_(o, t, out);
    return;
  }
  const double th = (t - o->t_prev) / (o->t - o->t_prev), th1 = 1.0 - th;
  const double *rc = o->rc;
  for (size_t i = 0; i < n; ++i)
    out[i] = o->x_prev[i] +
             th * (rc[i] +
                   th1 * (rc[n + i] +
                          th * (rc[2 * n + i] + th1 * rc[3 * n + i])));
}

/* DOP853 computes its dense output's stages on the first request after a
 * step.  The object is the caller's own (whirl_ode_alloc), so writing to
 * it through a pointer to const is defined; the state x(t) it describes
 * does not change, only the work counters and the cached coefficients. */
static int prepare_dense(const whirl_ode *o) {
  if (o->method != WHIRL_ODE_DOP853) return WHIRL_OK;
  return whirl_dop853_prepare_dense_((whirl_ode *)o);
}

static int in_step(const whirl_ode *o, double t) {
  return t >= fmin(o->t_prev, o->t) && t <= fmax(o->t_prev, o->t);
}

int whirl_ode_dense(const whirl_ode *o, double t, double *x) {
  if (o == NULL || x == NULL || !o->started || !o->have_step ||
      !in_step(o, t))
    return WHIRL_EINVAL;
  const int r = prepare_dense(o);
  if (r != WHIRL_OK) return r;
  dense_eval(o, t, x);
  return WHIRL_OK;
}

/* s = sign of a sample: -1, 0, +1 */
static int sgn(double v) { return (v > 0.0) - (v < 0.0); }

int whirl_ode_find_event(const whirl_ode *o, whirl_event_fn g, void *data,
                         int direction, double tol_t, double *t_ev,
                         double *x_ev) {
  if (o == NULL || g == NULL || t_ev == NULL || x_ev == NULL ||
      !o->started || !o->have_step || isnan(tol_t))
    return WHIRL_EINVAL;
  const int prep = prepare_dense(o);
  if (prep != WHIRL_OK) return prep;
  double *const y = x_ev; /* the state at the sample points */
  const double t0 = o->t_prev, h = o->t - o->t_prev;
  enum { NS = 9 };

  double tl = t0, gl = g(t0, o->x_prev, data);
  if (!isfinite(gl)) return WHIRL_EBADFUNC;
  for (int s = 1; s <= NS; ++s) {
    const double ts = s == NS ? o->t : t0 + h * s / NS;
    dense_eval(o, ts, y);
    const double gs = g(ts, y, data);
    if (!isfinite(gs)) return WHIRL_EBADFUNC;
    const int a = sgn(gl), b = sgn(gs);
    /* a sign change (into zero counts) from the last non-zero sample */
    const int rising = a < 0 && b >= 0, falling = a > 0 && b <= 0;
    if ((rising && direction >= 0) || (falling && direction <= 0)) {
      if (gs == 0.0) {
        *t_ev = ts;
        return 1;
      }
      /* Illinois on [tl, ts]: lo keeps the old sign, hi the new one;
       * the answer is hi, on the far side of the zero */
      double lo = tl, glo = gl, hi = ts, ghi = gs;
      int side = 0;
      for (int it = 0; it < 200; ++it) {
        const double tol = fmax(tol_t, 0.25 * whirl_ode_ulp16_(fmax(fabs(lo), fabs(hi))));
        if (fabs(hi - lo) <= tol) break;
        double tc = hi - ghi * (hi - lo) / (ghi - glo);
        if (!(tc > fmin(lo, hi) && tc < fmax(lo, hi)))
          tc = 0.5 * (lo + hi);
        if (tc == lo || tc == hi) break;
        dense_eval(o, tc, y);
        const double gc = g(tc, y, data);
        if (!isfinite(gc)) return WHIRL_EBADFUNC;
        if (gc == 0.0) {
          hi = tc;
          break;
        }
        if (sgn(gc) == sgn(glo)) {
          lo = tc;
          glo = gc;
          if (side == -1) ghi *= 0.5;
          side = -1;
        } else {
          hi = tc;
          ghi = gc;
          if (side == 1) glo *= 0.5;
          side = 1;
        }
      }
      *t_ev = hi;
      dense_eval(o, hi, x_ev);
      return 1;
    }
    if (b != 0) {
      tl = ts;
      gl = gs;
    }
  }
  return 0;
}

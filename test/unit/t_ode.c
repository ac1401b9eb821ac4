/* test/unit/t_ode.c — the Dormand–Prince integrator (lib/ode/dopri.c) and
 * the variational equations (lib/ode/variational.c) against closed forms:
 * convergence order 5 of the steps and of the dense output (fixed steps,
 * error ratio 2^5 on halving), accuracy at the default tolerances over 100
 * periods of the harmonic oscillator, zeros of cos t and of a large-amplitude
 * pendulum (period 4 K(sin θ0/2), K by the AGM), the state transition matrix
 * of a damped oscillator, the Floquet multipliers 1 and exp(-4π) of the
 * limit cycle x' = -y + x(1 - r²), y' = x + y(1 - r²), and argument and
 * callback errors.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>

#include "../tap.h"
#include "ode_models.h"

/* ------------------------------------------------------------------------
 * Models (and those of ode_models.h) */

/* damped oscillator x'' + 2 ζ x' + x = 0, ζ = p[0] */
static int damp_rhs(double t, const double *x, const double *p, double *f,
                    void *data) {
  (void)t;
  (void)data;
  f[0] = x[1];
  f[1] = -x[0] - 2.0 * p[0] * x[1];
  return 0;
}
static int damp_jac(double t, const double *x, const double *p, double *J,
                    void *data) {
  (void)t;
  (void)x;
  (void)data;
  J[0] = 0.0;
  J[1] = -1.0;
  J[2] = 1.0;
  J[3] = -2.0 * p[0];
  return 0;
}

/* limit cycle: the unit circle, period 2π */
static int cyc_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t;
  (void)p;
  (void)data;
  const double s = 1.0 - x[0] * x[0] - x[1] * x[1];
  f[0] = -x[1] + x[0] * s;
  f[1] = x[0] + x[1] * s;
  return 0;
}
static int cyc_jac(double t, const double *x, const double *p, double *J,
                   void *data) {
  (void)t;
  (void)p;
  (void)data;
  const double s = 1.0 - x[0] * x[0] - x[1] * x[1];
  J[0] = s - 2.0 * x[0] * x[0];
  J[1] = 1.0 - 2.0 * x[0] * x[1];
  J[2] = -1.0 - 2.0 * x[0] * x[1];
  J[3] = s - 2.0 * x[1] * x[1];
  return 0;
}

/* x' = p x (set_params) */
static int lin1_rhs(double t, const double *x, const double *p, double *f,
                    void *data) {
  (void)t;
  (void)data;
  f[0] = p[0] * x[0];
  return 0;
}

/* x' = 2t - 4: x = (t - 1)(t - 3) from x(0) = 3 */
static int par_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)x;
  (void)p;
  (void)data;
  f[0] = 2.0 * t - 4.0;
  return 0;
}

/* misbehaving right-hand sides */
static int fatal_rhs(double t, const double *x, const double *p, double *f,
                     void *data) {
  (void)p;
  (void)data;
  f[0] = -x[0];
  return t > 0.5 ? -3 : 0;
}
static int nan_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t;
  (void)x;
  (void)p;
  (void)data;
  f[0] = NAN;
  return 0;
}
static int blowup_rhs(double t, const double *x, const double *p, double *f,
                      void *data) {
  (void)t;
  (void)p;
  (void)data;
  f[0] = x[0] * x[0];
  return 0;
}
/* oscillator whose evaluations 20–22 fail recoverably (a transient fault) */
static int flaky_rhs(double t, const double *x, const double *p, double *f,
                     void *data) {
  int *calls = data;
  ++*calls;
  osc_rhs(t, x, p, f, NULL);
  if (*calls == 20) return 2;
  if (*calls == 21) f[1] = INFINITY;
  if (*calls == 22) f[0] = NAN;
  return 0;
}

/* ------------------------------------------------------------------------
 * Helpers */

/* integrate prob from (t0, x0) to t1 with fixed steps h (h_init = h_max = h,
 * tolerances so loose that no step is rejected) */
static int fixed_run(const whirl_problem *prob, double t0, const double *x0,
                     double t1, double h, double *x1, whirl_ode_stats *st) {
  whirl_ode *o = whirl_ode_alloc(prob, NULL);
  int rc = whirl_ode_set_tolerances(o, 0.1, 0.1);
  if (rc == 0) rc = whirl_ode_set_step_limits(o, h, 0.0, h);
  if (rc == 0) rc = whirl_ode_reset(o, t0, x0);
  if (rc == 0) rc = whirl_ode_evolve(o, t1);
  memcpy(x1, whirl_ode_x(o), prob->n * sizeof *x1);
  whirl_ode_get_stats(o, st);
  whirl_ode_free(o);
  return rc;
}

static double g_x1(double t, const double *x, void *data) {
  (void)t;
  (void)data;
  return x[1];
}
static double g_nan(double t, const double *x, void *data) {
  (void)x;
  (void)data;
  return t > 0.0 ? NAN : 1.0;
}

/* ------------------------------------------------------------------------ */

static void test_order(void) {
  /* y' = -2ty on [0, 2] (h = 0.05, 0.025, 0.0125) and the oscillator on
   * [0, 10] (h = 0.2, 0.1, 0.05): fixed steps */
  double eg[3], eo[3];
  int good = 1;
  for (int k = 0; k < 3; ++k) {
    whirl_ode_stats st;
    const double hg = 0.05 / (1 << k), ho = 0.2 / (1 << k);
    double y0 = 1.0, y1, x0[2] = {1.0, 0.0}, x1[2];
    int rc = fixed_run(&gauss, 0.0, &y0, 2.0, hg, &y1, &st);
    const size_t want = (size_t)lround(2.0 / hg);
    good = good && rc == 0 && st.steps == want && st.rejected == 0 &&
           st.rhs_evals == 6 * want + 1;
    eg[k] = fabs(y1 - exp(-4.0));
    rc = fixed_run(&osc, 0.0, x0, 10.0, ho, x1, &st);
    good = good && rc == 0 && st.steps == (size_t)lround(10.0 / ho) &&
           st.rejected == 0;
    eo[k] = fmax(fabs(x1[0] - cos(10.0)), fabs(x1[1] + sin(10.0)));
    printf("# fixed steps: y'=-2ty h %-6g error %.3e; oscillator h %-4g "
           "error %.3e\n",
           hg, eg[k], ho, eo[k]);
  }
  ok(good, "fixed steps: h_init = h_max = h gives T/h steps, no rejection, "
           "6 rhs evaluations per step + 1");
  for (int k = 0; k < 2; ++k) {
    const double rg = eg[k] / eg[k + 1], ro = eo[k] / eo[k + 1];
    ok(rg > 25.0 && rg < 40.0,
       "order 5, y' = -2ty: error ratio on halving h = %g is %.2f (32)",
       0.05 / (1 << k), rg);
    ok(ro > 25.0 && ro < 40.0,
       "order 5, oscillator: error ratio on halving h = %g is %.2f (32)",
       0.2 / (1 << k), ro);
  }

  /* tolerance proportionality: error ~ rtol over 1e-4 .. 1e-10 */
  double lt[4], le[4], ls[4];
  for (int k = 0; k < 4; ++k) {
    const double tol = pow(10.0, -4.0 - 2.0 * k);
    whirl_ode *o = whirl_ode_alloc(&osc, NULL);
    const double x0[2] = {1.0, 0.0};
    whirl_ode_set_tolerances(o, tol, tol);
    whirl_ode_reset(o, 0.0, x0);
    whirl_ode_evolve(o, 20.0);
    const double *x = whirl_ode_x(o);
    whirl_ode_stats st;
    whirl_ode_get_stats(o, &st);
    lt[k] = log(tol);
    le[k] = log(fmax(fabs(x[0] - cos(20.0)), fabs(x[1] + sin(20.0))));
    ls[k] = log((double)st.steps);
    whirl_ode_free(o);
  }
  /* least-squares slope of log error against log steps */
  double ms = 0, me = 0, sxy = 0, sxx = 0;
  for (int k = 0; k < 4; ++k) {
    ms += ls[k] / 4;
    me += le[k] / 4;
  }
  for (int k = 0; k < 4; ++k) {
    sxy += (ls[k] - ms) * (le[k] - me);
    sxx += (ls[k] - ms) * (ls[k] - ms);
  }
  const double slope = sxy / sxx;
  ok(slope < -4.5 && slope > -5.5,
     "error against number of steps over rtol 1e-4..1e-10: slope %.2f (-5)",
     slope);
  ok(le[3] - lt[3] < log(100.0) && le[0] - lt[0] < log(100.0),
     "global error within 100 rtol over 3 periods (%.2g at 1e-4, %.2g at "
     "1e-10)",
     exp(le[0]), exp(le[3]));
}

static void test_accuracy(void) {
  whirl_ode *o = whirl_ode_alloc(&osc, NULL);
  const double x0[2] = {1.0, 0.0}, T = 200.0 * PI;
  int rc = whirl_ode_reset(o, 0.0, x0);
  rc = rc ? rc : whirl_ode_evolve(o, T);
  const double *x = whirl_ode_x(o);
  const double err = fmax(fabs(x[0] - 1.0), fabs(x[1]));
  whirl_ode_stats st;
  whirl_ode_get_stats(o, &st);
  printf("# oscillator, 100 periods at rtol 1e-12, atol 1e-15: %zu steps "
         "(%.1f per period), %zu rejected, %zu rhs evaluations, error %.2e\n",
         st.steps, st.steps / 100.0, st.rejected, st.rhs_evals, err);
  ok(rc == 0 && whirl_ode_t(o) == T && err < 1e-9,
     "oscillator over 100 periods at default tolerances: t = T exactly, "
     "error %.2e < 1e-9",
     err);
  ok(st.rhs_evals == 6 * (st.steps + st.rejected) + 2,
     "rhs evaluations = 6 (accepted + rejected) + 2 (start, initial step)");
  ok(whirl_ode_step(o, T) == WHIRL_DONE, "whirl_ode_step at t_end: DONE");
  whirl_ode_free(o);

  /* backward integration */
  o = whirl_ode_alloc(&osc, NULL);
  whirl_ode_reset(o, 0.0, x0);
  rc = whirl_ode_evolve(o, -10.0);
  x = whirl_ode_x(o);
  ok(rc == 0 && whirl_ode_t(o) == -10.0 &&
         fabs(x[0] - cos(10.0)) < 1e-11 && fabs(x[1] - sin(10.0)) < 1e-11,
     "backward integration of the oscillator to t = -10 (error %.1e)",
     fmax(fabs(x[0] - cos(10.0)), fabs(x[1] - sin(10.0))));
  ok(whirl_ode_t_prev(o) > -10.0 && whirl_ode_h(o) > 0.0,
     "backward: t_prev > t, proposed |h| > 0");
  /* and forward again from there, past the start */
  rc = whirl_ode_evolve(o, 5.0);
  x = whirl_ode_x(o);
  ok(rc == 0 && fabs(x[0] - cos(5.0)) < 1e-11 &&
         fabs(x[1] + sin(5.0)) < 1e-11,
     "direction reversal: back to t = 5 (error %.1e)",
     fmax(fabs(x[0] - cos(5.0)), fabs(x[1] + sin(5.0))));
  whirl_ode_free(o);

  o = whirl_ode_alloc(&gauss, NULL);
  const double y2 = exp(-4.0);
  whirl_ode_set_tolerances(o, 1e-10, 1e-14);
  whirl_ode_reset(o, 2.0, &y2);
  rc = whirl_ode_evolve(o, 0.0);
  ok(rc == 0 && fabs(whirl_ode_x(o)[0] - 1.0) < 1e-8,
     "backward y' = -2ty from t = 2 to 0: y(0) = 1 (error %.1e)",
     fabs(whirl_ode_x(o)[0] - 1.0));
  whirl_ode_free(o);
}

/* max dense error over 20 interior points per step, against the global
 * (exact) solution and against the local solution through (t_prev, x_prev) */
static void dense_errors(whirl_ode *o, const whirl_problem *prob, double *glob,
                         double *loc) {
  const double t0 = whirl_ode_t_prev(o), t1 = whirl_ode_t(o);
  const double *xp = whirl_ode_x_prev(o);
  for (int j = 1; j < 20; ++j) {
    const double t = t0 + (t1 - t0) * j / 20.0;
    double x[2], ex[2], lx[2];
    whirl_ode_dense(o, t, x);
    if (prob == &osc) {
      ex[0] = cos(t);
      ex[1] = -sin(t);
      const double c = cos(t - t0), s = sin(t - t0);
      lx[0] = c * xp[0] + s * xp[1];
      lx[1] = -s * xp[0] + c * xp[1];
      *glob = fmax(*glob, fmax(fabs(x[0] - ex[0]), fabs(x[1] - ex[1])));
      *loc = fmax(*loc, fmax(fabs(x[0] - lx[0]), fabs(x[1] - lx[1])));
    } else {
      ex[0] = exp(-t * t);
      lx[0] = xp[0] * exp(t0 * t0 - t * t);
      *glob = fmax(*glob, fabs(x[0] - ex[0]));
      *loc = fmax(*loc, fabs(x[0] - lx[0]));
    }
  }
}

static void test_dense(void) {
  /* adaptive: dense error comparable with the error at the step ends */
  const double tols[2] = {1e-6, 1e-10};
  for (int k = 0; k < 2; ++k) {
    whirl_ode *o = whirl_ode_alloc(&osc, NULL);
    const double x0[2] = {1.0, 0.0};
    whirl_ode_set_tolerances(o, tols[k], tols[k]);
    whirl_ode_reset(o, 0.0, x0);
    double end_err = 0.0, dglob = 0.0, dloc = 0.0;
    int ends = 1, rc = 0;
    while (rc == 0 && whirl_ode_t(o) < 20.0) {
      rc = whirl_ode_step(o, 20.0);
      const double t = whirl_ode_t(o), *x = whirl_ode_x(o);
      end_err = fmax(end_err, fmax(fabs(x[0] - cos(t)), fabs(x[1] + sin(t))));
      dense_errors(o, &osc, &dglob, &dloc);
      double y[2];
      whirl_ode_dense(o, t, y);
      ends = ends && y[0] == x[0] && y[1] == x[1];
      whirl_ode_dense(o, whirl_ode_t_prev(o), y);
      ends = ends && y[0] == whirl_ode_x_prev(o)[0] &&
             y[1] == whirl_ode_x_prev(o)[1];
    }
    printf("# dense output, rtol = atol = %g: step-end error %.2e, dense "
           "error %.2e (local %.2e)\n",
           tols[k], end_err, dglob, dloc);
    ok(rc == 0 && dglob < 3.0 * end_err,
       "dense output at tol %g: max interior error %.2e within 3x the "
       "step-end error %.2e",
       tols[k], dglob, end_err);
    ok(ends, "dense output at tol %g is exact at both ends of every step",
       tols[k]);
    double y[2];
    const double t0 = whirl_ode_t_prev(o), t1 = whirl_ode_t(o);
    ok(whirl_ode_dense(o, t0 - 1e-3 * (t1 - t0), y) == WHIRL_EINVAL &&
           whirl_ode_dense(o, t1 + 1e-3 * (t1 - t0), y) == WHIRL_EINVAL &&
           whirl_ode_dense(o, NAN, y) == WHIRL_EINVAL &&
           whirl_ode_dense(o, t1, NULL) == WHIRL_EINVAL,
       "dense output outside the last step (or NaN, NULL): EINVAL");
    whirl_ode_free(o);
  }

  /* fixed steps: interpolation error (against the local solution) falls
   * like h^5 (continuous extension of order 4) */
  for (int q = 0; q < 2; ++q) {
    const whirl_problem *prob = q == 0 ? &gauss : &osc;
    const double hs[3] = {q == 0 ? 0.05 : 0.2, q == 0 ? 0.025 : 0.1,
                          q == 0 ? 0.0125 : 0.05};
    double el[3], eg[3];
    for (int k = 0; k < 3; ++k) {
      whirl_ode *o = whirl_ode_alloc(prob, NULL);
      const double x0[2] = {1.0, 0.0};
      whirl_ode_set_tolerances(o, 0.1, 0.1);
      whirl_ode_set_step_limits(o, hs[k], 0.0, hs[k]);
      whirl_ode_reset(o, 0.0, x0);
      el[k] = eg[k] = 0.0;
      while (whirl_ode_t(o) < 2.0 && whirl_ode_step(o, 2.0) == 0)
        dense_errors(o, prob, &eg[k], &el[k]);
      whirl_ode_free(o);
    }
    printf("# fixed-step dense error, %s: local %.2e %.2e %.2e, global %.2e "
           "%.2e %.2e\n",
           prob->name, el[0], el[1], el[2], eg[0], eg[1], eg[2]);
    for (int k = 0; k < 2; ++k) {
      const double r = el[k] / el[k + 1];
      ok(r > 25.0 && r < 40.0,
         "dense output, %s: local interior error ratio on halving h = %g "
         "is %.2f (32)",
         prob->name, hs[k], r);
      const double rg = eg[k] / eg[k + 1];
      ok(rg > 16.0 && rg < 40.0,
         "dense output, %s: global interior error ratio on halving h = %g "
         "is %.2f (16..32)",
         prob->name, hs[k], rg);
    }
  }

  whirl_ode *o = whirl_ode_alloc(&osc, NULL);
  double y[2];
  const double x0[2] = {1.0, 0.0};
  whirl_ode_reset(o, 0.0, x0);
  ok(whirl_ode_dense(o, 0.0, y) == WHIRL_EINVAL,
     "dense output before the first step: EINVAL");
  whirl_ode_free(o);
}

/* all events of g over [t0, t1] into tev[] (up to max) */
static int collect_events(const whirl_problem *prob, const double *x0,
                          double t1, whirl_event_fn g, int dir, double *tev,
                          double *xev, int max) {
  whirl_ode *o = whirl_ode_alloc(prob, NULL);
  whirl_ode_reset(o, 0.0, x0);
  int ne = 0;
  while (whirl_ode_t(o) != t1) {
    if (whirl_ode_step(o, t1) != 0) {
      ne = -1;
      break;
    }
    double t, x[2];
    int r = whirl_ode_find_event(o, g, NULL, dir, 1e-14, &t, x);
    if (r < 0) {
      ne = -1;
      break;
    }
    if (r == 1 && ne < max) {
      tev[ne] = t;
      xev[2 * ne] = x[0];
      xev[2 * ne + 1] = x[1];
      ++ne;
    }
  }
  whirl_ode_free(o);
  return ne;
}

static void test_events(void) {
  const double x0[2] = {1.0, 0.0};
  double tev[16], xev[32];
  /* zeros of x = cos t at π/2 + kπ; x' = -sin t = ∓1 there */
  int ne = collect_events(&osc, x0, 20.0, g_x0, 0, tev, xev, 16);
  double terr = 0.0, xerr = 0.0;
  for (int k = 0; k < ne; ++k) {
    terr = fmax(terr, fabs(tev[k] - (PI / 2 + k * PI)));
    xerr = fmax(xerr, fmax(fabs(xev[2 * k]),
                           fabs(xev[2 * k + 1] - (k % 2 ? 1.0 : -1.0))));
  }
  ok(ne == 6 && terr < 1e-12 && xerr < 1e-11,
     "oscillator: %d zeros of x in (0, 20] at pi/2 + k pi (max error %.1e, "
     "state %.1e)",
     ne, terr, xerr);
  ne = collect_events(&osc, x0, 20.0, g_x0, 1, tev, xev, 16);
  terr = 0.0;
  for (int k = 0; k < ne; ++k)
    terr = fmax(terr, fabs(tev[k] - (1.5 * PI + 2 * k * PI)));
  ok(ne == 3 && terr < 1e-12,
     "direction +1: only the 3 rising zeros 3pi/2 + 2k pi (error %.1e)", terr);
  ne = collect_events(&osc, x0, 20.0, g_x0, -1, tev, xev, 16);
  terr = 0.0;
  for (int k = 0; k < ne; ++k)
    terr = fmax(terr, fabs(tev[k] - (0.5 * PI + 2 * k * PI)));
  ok(ne == 3 && terr < 1e-12,
     "direction -1: only the 3 falling zeros pi/2 + 2k pi (error %.1e)", terr);
  /* v = -sin t vanishes at t = 0: not an event; then at kπ */
  ne = collect_events(&osc, x0, 20.0, g_x1, 0, tev, xev, 16);
  terr = 0.0;
  for (int k = 0; k < ne; ++k) terr = fmax(terr, fabs(tev[k] - (k + 1) * PI));
  ok(ne == 6 && terr < 1e-12,
     "g(t_prev) = 0 at the start is not an event: zeros of v at k pi, k = "
     "1..6 (error %.1e)",
     terr);

  /* pendulum from θ0 = 2 at rest: θ = 0 at T/4 and 3T/4, θ' = 0 at T/2,
   * T = 4 K(sin(θ0/2)) */
  const double th0 = 2.0, P = 4.0 * ellipk(sin(th0 / 2.0));
  const double p0[2] = {th0, 0.0};
  ne = collect_events(&pend, p0, 1.2 * P, g_x0, 0, tev, xev, 16);
  const double vmax = 2.0 * sin(th0 / 2.0); /* energy: θ'² = 2(cosθ - cosθ0) */
  ok(ne == 2 && fabs(tev[0] - 0.25 * P) < 1e-11 &&
         fabs(tev[1] - 0.75 * P) < 1e-11 && fabs(xev[1] + vmax) < 1e-11 &&
         fabs(xev[3] - vmax) < 1e-11,
     "pendulum, theta0 = 2: zeros at T/4, 3T/4 of T = 4K(sin 1) = %.15g "
     "(errors %.1e, %.1e)",
     P, ne > 0 ? tev[0] - 0.25 * P : NAN, ne > 1 ? tev[1] - 0.75 * P : NAN);
  ne = collect_events(&pend, p0, 1.2 * P, g_x1, 1, tev, xev, 16);
  ok(ne == 1 && fabs(tev[0] - 0.5 * P) < 1e-11 &&
         fabs(xev[0] + th0) < 1e-11,
     "pendulum: theta' rises through 0 once, at T/2 with theta = -theta0 "
     "(error %.1e)",
     ne > 0 ? tev[0] - 0.5 * P : NAN);

  /* x' = 2t - 4, x(0) = 3: x = (t - 1)(t - 3), integrated exactly (also by
   * the dense output); one step of 4 holds both zeros */
  {
    whirl_problem par = {.name = "parabola", .n = 1, .rhs = par_rhs};
    whirl_ode *o = whirl_ode_alloc(&par, NULL);
    const double three = 3.0;
    whirl_ode_set_step_limits(o, 4.0, 0.0, 0.0);
    whirl_ode_reset(o, 0.0, &three);
    int rc = whirl_ode_step(o, 4.0);
    double t0 = NAN, t1 = NAN, tm = NAN, x[1], x1 = NAN;
    int r0 = whirl_ode_find_event(o, g_x0, NULL, 0, 1e-14, &t0, x);
    int r1 = whirl_ode_find_event(o, g_x0, NULL, 1, 1e-14, &t1, x);
    x1 = x[0];
    int rm = whirl_ode_find_event(o, g_x0, NULL, -1, 1e-14, &tm, x);
    ok(rc == 0 && whirl_ode_t_prev(o) == 0.0 && whirl_ode_t(o) == 4.0 &&
           fabs(whirl_ode_x(o)[0] - 3.0) < 1e-14,
       "x = (t-1)(t-3): one step from 0 to 4, exact");
    ok(r0 == 1 && fabs(t0 - 1.0) < 1e-14,
       "two zeros in one step: the first (t = 1) is reported (%.1e)",
       t0 - 1.0);
    ok(r1 == 1 && fabs(t1 - 3.0) < 1e-14 && fabs(x1) < 1e-13 && rm == 1 &&
           fabs(tm - 1.0) < 1e-14,
       "direction +1 finds the rising zero t = 3 (%.1e), -1 the falling "
       "t = 1 (%.1e)",
       t1 - 3.0, tm - 1.0);
    ok(whirl_ode_find_event(o, g_nan, NULL, 0, 1e-12, &t0, x) ==
               WHIRL_EBADFUNC &&
           whirl_ode_find_event(o, NULL, NULL, 0, 1e-12, &t0, x) ==
               WHIRL_EINVAL &&
           whirl_ode_find_event(o, g_x0, NULL, 0, 1e-12, NULL, x) ==
               WHIRL_EINVAL,
       "find_event: non-finite g gives EBADFUNC, NULL g or t_ev EINVAL");
    whirl_ode_free(o);
  }
}

static void test_monodromy(void) {
  /* damped oscillator: Φ(T) = e^{-ζT} (cos ω T I + sin ω T / ω (A + ζ I)) */
  const double zeta = 0.1, T = 2.0 * PI, w = sqrt(1.0 - zeta * zeta);
  const double e = exp(-zeta * T), c = cos(w * T), s = sin(w * T);
  const double Mx[4] = {e * (c + zeta * s / w), -e * s / w, e * s / w,
                        e * (c - zeta * s / w)};
  const double x0[2] = {0.3, -0.7};
  for (int fd = 0; fd < 2; ++fd) {
    whirl_problem damp = {.name = "damped",
                          .n = 2,
                          .npar = 1,
                          .rhs = damp_rhs,
                          .jac_x = fd ? NULL : damp_jac,
                          .autonomous = 1};
    double M[4], xT[2], err = 0.0;
    char buf[200];
    whirl_ode_stats st;
    int rc = whirl_ode_monodromy(&damp, &zeta, 0.0, x0, T, 1e-12, 1e-15, xT,
                                 M, &st, buf, sizeof buf);
    for (int i = 0; i < 4; ++i) err = fmax(err, fabs(M[i] - Mx[i]));
    const double xerr =
        fmax(fabs(xT[0] - (Mx[0] * x0[0] + Mx[2] * x0[1])),
             fabs(xT[1] - (Mx[1] * x0[0] + Mx[3] * x0[1])));
    ok(rc == 0 && err < 1e-10 && xerr < 1e-10 && st.steps > 0,
       "damped oscillator, %s Jacobian: M = exact transition matrix "
       "(error %.1e, x(T) %.1e, %zu steps)",
       fd ? "finite-difference" : "analytic", err, xerr, st.steps);
  }

  /* limit cycle on the unit circle: multipliers 1 and exp(-4π) */
  const double c0[2] = {1.0, 0.0}, mu2 = exp(-4.0 * PI);
  for (int fd = 0; fd < 2; ++fd) {
    whirl_problem cyc = {.name = "cycle",
                         .n = 2,
                         .rhs = cyc_rhs,
                         .jac_x = fd ? NULL : cyc_jac,
                         .autonomous = 1};
    double M[4], xT[2];
    char buf[200];
    int rc = whirl_ode_monodromy(&cyc, NULL, 0.0, c0, 2.0 * PI, 1e-12, 1e-15,
                                 xT, M, NULL, buf, sizeof buf);
    const double tr = M[0] + M[3], det = M[0] * M[3] - M[1] * M[2];
    const double disc = tr * tr - 4.0 * det;
    const double l1 = 0.5 * (tr + sqrt(fmax(disc, 0.0)));
    const double l2 = det / l1;
    printf("# limit cycle (%s): multipliers %.15g, %.6e (exact 1, %.6e)\n",
           fd ? "fd" : "analytic", l1, l2, mu2);
    ok(rc == 0 && disc > 0.0 && fabs(l1 - 1.0) < 1e-8 &&
           fabs(l2 - mu2) < 1e-8 && fabs(l2 - mu2) < 1e-3 * mu2,
       "limit cycle, %s Jacobian: Floquet multipliers 1 (%.1e) and "
       "exp(-4pi) (rel %.1e)",
       fd ? "finite-difference" : "analytic", l1 - 1.0, l2 / mu2 - 1.0);
    ok(fabs(xT[0] - 1.0) < 1e-10 && fabs(xT[1]) < 1e-10,
       "limit cycle: x(2pi) = x(0) (%.1e)",
       fmax(fabs(xT[0] - 1.0), fabs(xT[1])));
  }

  /* T = 0: the identity */
  {
    whirl_problem cyc = {.name = "cycle", .n = 2, .rhs = cyc_rhs};
    double M[4];
    ok(whirl_ode_monodromy(&cyc, NULL, 0.0, c0, 0.0, 1e-10, 1e-12, NULL, M,
                           NULL, NULL, 0) == 0 &&
           M[0] == 1.0 && M[1] == 0.0 && M[2] == 0.0 && M[3] == 1.0,
       "monodromy over T = 0 is the identity");
  }

  /* errors */
  {
    whirl_problem fat = {.name = "fatal", .n = 1, .rhs = fatal_rhs};
    whirl_problem cyc = {.name = "cycle", .n = 2, .rhs = cyc_rhs};
    double M[4], one = 1.0;
    char buf[200];
    int rc = whirl_ode_monodromy(&fat, NULL, 0.0, &one, 1.0, 1e-10, 1e-12,
                                 NULL, M, NULL, buf, sizeof buf);
    printf("# monodromy error message: %s\n", buf);
    ok(rc == WHIRL_EUSER && strstr(buf, "returned -3") != NULL,
       "monodromy: fatal rhs gives EUSER and a message");
    rc = whirl_ode_monodromy(&cyc, NULL, 0.0, c0, 1.0, 0.0, 1e-12, NULL, M,
                             NULL, buf, sizeof buf);
    ok(rc == WHIRL_EINVAL && strstr(buf, "rtol") != NULL,
       "monodromy: rtol = 0 gives EINVAL (\"%s\")", buf);
    ok(whirl_ode_monodromy(NULL, NULL, 0.0, c0, 1.0, 1e-10, 1e-12, NULL, M,
                           NULL, buf, sizeof buf) == WHIRL_EINVAL &&
           buf[0] != '\0' &&
           whirl_ode_monodromy(&cyc, NULL, 0.0, c0, 1.0, 1e-10, 1e-12, NULL,
                               NULL, NULL, NULL, 0) == WHIRL_EINVAL &&
           whirl_ode_monodromy(&cyc, NULL, 0.0, c0, NAN, 1e-10, 1e-12, NULL,
                               M, NULL, NULL, 0) == WHIRL_EINVAL,
       "monodromy: NULL problem, NULL M, NaN T give EINVAL");
  }
}

static void test_errors(void) {
  const double x0[2] = {1.0, 0.0};
  double one = 1.0, p = 1.0;
  whirl_problem bad = osc;
  ok(whirl_ode_alloc(NULL, NULL) == NULL, "alloc: NULL problem");
  bad.rhs = NULL;
  ok(whirl_ode_alloc(&bad, NULL) == NULL, "alloc: no rhs");
  bad = osc;
  bad.n = 0;
  ok(whirl_ode_alloc(&bad, NULL) == NULL, "alloc: n = 0");
  whirl_problem lin1 = {.name = "lin1", .n = 1, .npar = 1, .rhs = lin1_rhs};
  ok(whirl_ode_alloc(&lin1, NULL) == NULL, "alloc: npar > 0 with NULL p");
  whirl_ode_free(NULL);

  whirl_ode *o = whirl_ode_alloc(&osc, NULL);
  ok(whirl_ode_step(o, 1.0) == WHIRL_EINVAL &&
         whirl_ode_evolve(o, 1.0) == WHIRL_EINVAL,
     "step/evolve before reset: EINVAL (\"%s\")", whirl_ode_errmsg(o));
  ok(whirl_ode_set_tolerances(o, 0.0, 1e-12) == WHIRL_EINVAL &&
         whirl_ode_set_tolerances(o, -1e-6, 1e-12) == WHIRL_EINVAL &&
         whirl_ode_set_tolerances(o, 1e-15, 1e-12) == WHIRL_EINVAL &&
         whirl_ode_set_tolerances(o, NAN, 1e-12) == WHIRL_EINVAL &&
         whirl_ode_set_tolerances(o, 1e-6, 0.0) == WHIRL_EINVAL &&
         whirl_ode_set_tolerances(o, 1e-6, INFINITY) == WHIRL_EINVAL &&
         whirl_ode_set_tolerances(o, 1e-6, 1e-9) == WHIRL_OK,
     "tolerances: rtol <= 0, < 100 eps, NaN, atol <= 0 or Inf rejected");
  ok(whirl_ode_set_step_limits(o, -1.0, 0.0, 0.0) == WHIRL_EINVAL &&
         whirl_ode_set_step_limits(o, 0.0, 1.0, 0.5) == WHIRL_EINVAL &&
         whirl_ode_set_step_limits(o, 0.0, NAN, 0.0) == WHIRL_EINVAL &&
         whirl_ode_set_step_limits(o, 0.0, 0.0, 0.0) == WHIRL_OK,
     "step limits: negative, NaN, h_min > h_max rejected");
  const double xnan[2] = {NAN, 0.0};
  ok(whirl_ode_reset(o, 0.0, xnan) == WHIRL_EINVAL &&
         whirl_ode_reset(o, INFINITY, x0) == WHIRL_EINVAL &&
         whirl_ode_reset(o, 0.0, NULL) == WHIRL_EINVAL,
     "reset: NaN state, infinite t0, NULL state rejected (\"%s\")",
     whirl_ode_errmsg(o));
  whirl_ode_reset(o, 0.0, x0);
  ok(whirl_ode_evolve(o, NAN) == WHIRL_EINVAL, "evolve to NaN: EINVAL");

  /* max_steps */
  whirl_ode_set_tolerances(o, 1e-12, 1e-15);
  whirl_ode_set_max_steps(o, 10);
  whirl_ode_stats st0, st1;
  whirl_ode_get_stats(o, &st0);
  int rc = whirl_ode_evolve(o, 200.0 * PI);
  whirl_ode_get_stats(o, &st1);
  ok(rc == WHIRL_EMAXITER && st1.steps - st0.steps == 10 &&
         whirl_ode_t(o) > 0.0,
     "max_steps 10 exceeded: EMAXITER after 10 steps (\"%s\")",
     whirl_ode_errmsg(o));
  rc = whirl_ode_evolve(o, 200.0 * PI);
  ok(rc == WHIRL_EMAXITER, "  the limit is per evolve call");
  whirl_ode_set_max_steps(o, 0);
  ok(whirl_ode_evolve(o, 2.0 * PI) == 0 &&
         fabs(whirl_ode_x(o)[0] - 1.0) < 1e-10,
     "  after EMAXITER the integration can go on");
  whirl_ode_free(o);

  /* fatal callback */
  whirl_problem fat = {.name = "fatal", .n = 1, .rhs = fatal_rhs};
  o = whirl_ode_alloc(&fat, NULL);
  whirl_ode_reset(o, 0.0, &one);
  rc = whirl_ode_evolve(o, 1.0);
  ok(rc == WHIRL_EUSER && whirl_ode_last_rhs_status(o) == -3 &&
         strstr(whirl_ode_errmsg(o), "-3") != NULL && whirl_ode_t(o) <= 0.5,
     "fatal rhs status -3: EUSER at t = %g <= 0.5 (\"%s\")", whirl_ode_t(o),
     whirl_ode_errmsg(o));
  whirl_ode_free(o);

  /* NaN everywhere: ESTEP at once */
  whirl_problem nanp = {.name = "nan", .n = 1, .rhs = nan_rhs};
  o = whirl_ode_alloc(&nanp, NULL);
  whirl_ode_reset(o, 0.0, &one);
  rc = whirl_ode_evolve(o, 1.0);
  ok(rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(o) == WHIRL_EBADFUNC &&
         whirl_ode_t(o) == 0.0,
     "rhs NaN everywhere: ESTEP, last status EBADFUNC (\"%s\")",
     whirl_ode_errmsg(o));
  whirl_ode_free(o);

  /* recoverable failure beyond t = 1.5: ESTEP just before the wall */
  whirl_problem wall = {.name = "wall", .n = 1, .rhs = wall_rhs};
  double zero = 0.0;
  o = whirl_ode_alloc(&wall, NULL);
  whirl_ode_reset(o, 0.0, &zero);
  rc = whirl_ode_evolve(o, 3.0);
  ok(rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(o) == 7 &&
         whirl_ode_t(o) <= 1.5 && whirl_ode_t(o) > 1.5 - 1e-12 &&
         fabs(whirl_ode_x(o)[0] - whirl_ode_t(o)) < 1e-12,
     "rhs status 7 beyond t = 1.5: ESTEP at t = 1.5 - %.1e, last status 7 "
     "(\"%s\")",
     1.5 - whirl_ode_t(o), whirl_ode_errmsg(o));
  whirl_ode_reset(o, 0.0, &zero);
  rc = whirl_ode_evolve(o, 1.5);
  ok(rc == 0 && whirl_ode_t(o) == 1.5 &&
         fabs(whirl_ode_x(o)[0] - 1.5) < 1e-14,
     "  while t_end = 1.5 is reached exactly");
  whirl_ode_free(o);

  /* transient recoverable failures: rejected and retried */
  int calls = 0;
  whirl_problem flaky = {
      .name = "flaky", .n = 2, .rhs = flaky_rhs, .data = &calls};
  o = whirl_ode_alloc(&flaky, NULL);
  whirl_ode_reset(o, 0.0, x0);
  rc = whirl_ode_evolve(o, 10.0);
  whirl_ode_get_stats(o, &st1);
  ok(rc == 0 && st1.rejected >= 3 &&
         fabs(whirl_ode_x(o)[0] - cos(10.0)) < 1e-10 &&
         st1.rhs_evals == (size_t)calls,
     "transient status 2, Inf, NaN: %zu steps rejected, result still "
     "accurate, rhs_evals = %d calls",
     st1.rejected, calls);
  whirl_ode_free(o);

  /* blow-up of x' = x² at t = 1 */
  whirl_problem blow = {.name = "blowup", .n = 1, .rhs = blowup_rhs};
  o = whirl_ode_alloc(&blow, NULL);
  whirl_ode_reset(o, 0.0, &one);
  rc = whirl_ode_evolve(o, 2.0);
  whirl_ode_get_stats(o, &st1);
  printf("# blow-up: stopped at t = %.17g, x = %.3g after %zu steps: %s\n",
         whirl_ode_t(o), whirl_ode_x(o)[0], st1.steps, whirl_ode_errmsg(o));
  ok((rc == WHIRL_ESTEP || rc == WHIRL_EBADFUNC) && whirl_ode_t(o) < 1.0 &&
         whirl_ode_t(o) > 1.0 - 1e-6,
     "x' = x^2 from x(0) = 1 towards t = 2: %s near the blow-up at t = 1",
     whirl_strerror(rc));
  whirl_ode_free(o);

  /* set_params takes effect at the next reset */
  o = whirl_ode_alloc(&lin1, &p);
  whirl_ode_reset(o, 0.0, &one);
  whirl_ode_evolve(o, 0.5);
  p = -1.0;
  whirl_ode_set_params(o, &p); /* not yet */
  whirl_ode_evolve(o, 1.0);
  const double x1 = whirl_ode_x(o)[0];
  whirl_ode_reset(o, 0.0, &one);
  whirl_ode_evolve(o, 1.0);
  ok(fabs(x1 - exp(1.0)) < 1e-10 && fabs(whirl_ode_x(o)[0] - exp(-1.0)) < 1e-10,
     "set_params: old parameters until the reset, new ones after");
  ok(whirl_ode_set_params(o, NULL) == WHIRL_EINVAL,
     "set_params: NULL rejected");
  whirl_ode_free(o);

  ok(whirl_ode_last_rhs_status(NULL) == WHIRL_EINVAL &&
         whirl_ode_errmsg(NULL) != NULL && isnan(whirl_ode_t(NULL)) &&
         whirl_ode_x(NULL) == NULL && whirl_ode_set_max_steps(NULL, 1) ==
         WHIRL_EINVAL,
     "accessors accept NULL");
}

/* Several integrators stepped alternately give the same results as one at a
 * time: no shared state. */
static void test_independent(void) {
  const double x0[2] = {1.0, 0.0}, q0[2] = {2.0, 0.0};
  whirl_ode *a = whirl_ode_alloc(&osc, NULL), *b = whirl_ode_alloc(&pend, NULL);
  whirl_ode_set_tolerances(b, 1e-8, 1e-10);
  whirl_ode_reset(a, 0.0, x0);
  whirl_ode_reset(b, 0.0, q0);
  while (whirl_ode_t(a) < 30.0 || whirl_ode_t(b) < 30.0) {
    whirl_ode_step(a, 30.0);
    whirl_ode_step(b, 30.0);
  }
  whirl_ode *c = whirl_ode_alloc(&osc, NULL), *d = whirl_ode_alloc(&pend, NULL);
  whirl_ode_set_tolerances(d, 1e-8, 1e-10);
  whirl_ode_reset(c, 0.0, x0);
  whirl_ode_reset(d, 0.0, q0);
  whirl_ode_evolve(c, 30.0);
  whirl_ode_evolve(d, 30.0);
  ok(memcmp(whirl_ode_x(a), whirl_ode_x(c), 2 * sizeof(double)) == 0 &&
         memcmp(whirl_ode_x(b), whirl_ode_x(d), 2 * sizeof(double)) == 0,
     "interleaved integrators give bit-identical results");
  whirl_ode_free(a);
  whirl_ode_free(b);
  whirl_ode_free(c);
  whirl_ode_free(d);

#ifdef _OPENMP
  int bad = 0;
#pragma omp parallel for reduction(+ : bad)
  for (int i = 0; i < 16; ++i) {
    double M[4];
    const double zeta = 0.01 * i, T = 2.0 * PI;
    whirl_problem damp = {.name = "damped",
                          .n = 2,
                          .npar = 1,
                          .rhs = damp_rhs,
                          .jac_x = damp_jac,
                          .autonomous = 1};
    int rc = whirl_ode_monodromy(&damp, &zeta, 0.0, x0, T, 1e-12, 1e-15,
                                 NULL, M, NULL, NULL, 0);
    const double w = sqrt(1.0 - zeta * zeta);
    if (rc != 0 ||
        fabs(M[2] - exp(-zeta * T) * sin(w * T) / w) > 1e-10)
      ++bad;
  }
  ok(bad == 0, "16 monodromy computations in OpenMP threads");
#endif
}

/* whirl_ode_sample honours max_steps between two samples: a stiff stretch
 * (the SFD journal pressed to the housing) made `sfd simulate --y0
 * 0.999999` run for over 15 minutes inside one call.  Here the harmonic
 * oscillator sampled once per period needs a few hundred steps per sample
 * at tight tolerances: a budget of 50 must stop it with a message. */
static int count_samples(size_t k, double t, const double *x, void *data) {
  (void)t, (void)x;
  *(size_t *)data = k;
  return 0;
}

static void test_sample_budget(void) {
  const double p[1] = {1.0}, x0[2] = {1.0, 0.0};
  whirl_ode *o = whirl_ode_alloc(&osc, p);
  size_t last = 0;
  whirl_ode_set_tolerances(o, 1e-12, 1e-14);
  whirl_ode_reset(o, 0.0, x0);
  whirl_ode_set_max_steps(o, 50);
  int rc = whirl_ode_sample(o, 2 * M_PI, 3, count_samples, &last);
  ok(rc == WHIRL_EMAXITER && strstr(whirl_ode_errmsg(o), "50 steps between two samples") && last == 0,
     "sample: budget of 50 steps per sample exceeded (%d): %s", rc, whirl_ode_errmsg(o));
  whirl_ode_reset(o, 0.0, x0);
  whirl_ode_set_max_steps(o, 100000);
  rc = whirl_ode_sample(o, 2 * M_PI, 3, count_samples, &last);
  ok(rc == WHIRL_OK && last == 3, "sample: a sufficient budget changes nothing (%d, %zu samples)", rc, last);
  whirl_ode_reset(o, 0.0, x0);
  whirl_ode_set_max_steps(o, 50);
  rc = whirl_ode_sample(o, 2 * M_PI / 1000, 3000, count_samples, &last);
  ok(rc == WHIRL_OK && last == 3000, "sample: the budget is per sample, not per call (%d)", rc);
  whirl_ode_free(o);
}

int main(void) {
  test_sample_budget();
  test_order();
  test_accuracy();
  test_dense();
  test_events();
  test_monodromy();
  test_errors();
  test_independent();
  return done_testing();
}

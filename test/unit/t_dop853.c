/* test/unit/t_dop853.c — the Dormand–Prince 8(5,3) integrator
 * (lib/ode/dop853.c) against closed forms: convergence order 8 of the
 * steps (fixed steps, error ratio 2^8 on halving) and order 7 of the dense
 * output (local interior error ratio 2^8), the error falling like steps^-8
 * over rtol 1e-5..1e-11, accuracy over 100 periods of the oscillator and of
 * the large-amplitude pendulum (period 4 K(sin θ0/2), K by the AGM) at the
 * default tolerances, with far fewer evaluations than DOPRI5, events (the
 * zeros of cos t), the dense output's three stages computed once a step
 * and only on request, a failing right-hand side, and the method's name.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>

#include "../tap.h"
#include "ode_models.h"

static whirl_ode *dop853(const whirl_problem *prob) {
  whirl_ode *o = whirl_ode_alloc(prob, NULL);
  if (o != NULL && whirl_ode_set_method(o, WHIRL_ODE_DOP853) != WHIRL_OK) {
    whirl_ode_free(o);
    return NULL;
  }
  return o;
}

/* fixed steps h from (t0, x0) to t1 (tolerances so loose that no step is
 * rejected) */
static int fixed_run(const whirl_problem *prob, double t0, const double *x0,
                     double t1, double h, double *x1, whirl_ode_stats *st) {
  whirl_ode *o = dop853(prob);
  int rc = whirl_ode_set_tolerances(o, 0.1, 0.1);
  if (rc == 0) rc = whirl_ode_set_step_limits(o, h, 0.0, h);
  if (rc == 0) rc = whirl_ode_reset(o, t0, x0);
  if (rc == 0) rc = whirl_ode_evolve(o, t1);
  memcpy(x1, whirl_ode_x(o), prob->n * sizeof *x1);
  whirl_ode_get_stats(o, st);
  whirl_ode_free(o);
  return rc;
}

/* ------------------------------------------------------------------------ */

static void test_method(void) {
  int m = -1;
  ok(whirl_ode_method_parse("dop853", &m) == WHIRL_OK &&
         m == WHIRL_ODE_DOP853 &&
         strcmp(whirl_ode_method_name(WHIRL_ODE_DOP853), "dop853") == 0,
     "method name dop853 <-> WHIRL_ODE_DOP853");
  whirl_ode *o = dop853(&osc);
  ok(o != NULL && whirl_ode_get_method(o) == WHIRL_ODE_DOP853,
     "set_method(DOP853)");
  whirl_ode_free(o);
}

static void test_order(void) {
  /* y' = -2ty on [0, 2] (h = 0.2, 0.1, 0.05) and the oscillator on [0, 10]
   * (h = 1, 0.5, 0.25) */
  double eg[3], eo[3];
  int good = 1;
  for (int k = 0; k < 3; ++k) {
    whirl_ode_stats st;
    const double hg = 0.2 / (1 << k), ho = 1.0 / (1 << k);
    double y0 = 1.0, y1, x0[2] = {1.0, 0.0}, x1[2];
    int rc = fixed_run(&gauss, 0.0, &y0, 2.0, hg, &y1, &st);
    const size_t want = (size_t)lround(2.0 / hg);
    good = good && rc == 0 && st.steps == want && st.rejected == 0 &&
           st.rhs_evals == 12 * want + 1;
    eg[k] = fabs(y1 - exp(-4.0));
    rc = fixed_run(&osc, 0.0, x0, 10.0, ho, x1, &st);
    good = good && rc == 0 && st.steps == (size_t)lround(10.0 / ho) &&
           st.rejected == 0;
    eo[k] = fmax(fabs(x1[0] - cos(10.0)), fabs(x1[1] + sin(10.0)));
    printf("# fixed steps: y'=-2ty h %-6g error %.3e; oscillator h %-4g "
           "error %.3e\n",
           hg, eg[k], ho, eo[k]);
  }
  ok(good, "fixed steps: T/h steps, no rejection, 12 rhs evaluations per "
           "step + 1 (no dense output asked for)");
  for (int k = 0; k < 2; ++k) {
    const double rg = eg[k] / eg[k + 1], ro = eo[k] / eo[k + 1];
    ok(rg > 160.0 && rg < 400.0,
       "order 8, y' = -2ty: error ratio on halving h = %g is %.1f (256)",
       0.2 / (1 << k), rg);
    ok(ro > 160.0 && ro < 400.0,
       "order 8, oscillator: error ratio on halving h = %g is %.1f (256)",
       1.0 / (1 << k), ro);
  }

  /* the error against the number of steps over rtol 1e-5 .. 1e-11 */
  double le[4], ls[4];
  for (int k = 0; k < 4; ++k) {
    const double tol = pow(10.0, -5.0 - 2.0 * k);
    whirl_ode *o = dop853(&osc);
    const double x0[2] = {1.0, 0.0};
    whirl_ode_set_tolerances(o, tol, tol);
    whirl_ode_reset(o, 0.0, x0);
    whirl_ode_evolve(o, 40.0);
    const double *x = whirl_ode_x(o);
    whirl_ode_stats st;
    whirl_ode_get_stats(o, &st);
    le[k] = log(fmax(fabs(x[0] - cos(40.0)), fabs(x[1] + sin(40.0))));
    ls[k] = log((double)st.steps);
    ok(le[k] < log(100.0 * tol), "oscillator to t = 40 at rtol %g: error "
       "%.2e within 100 rtol", tol, exp(le[k]));
    whirl_ode_free(o);
  }
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
  ok(slope < -6.5 && slope > -9.5,
     "error against number of steps over rtol 1e-5..1e-11: slope %.2f (-8)",
     slope);
}

/* max local interior dense error over 19 points a step (against the exact
 * solution through (t_prev, x_prev)) */
static double dense_local(whirl_ode *o, const whirl_problem *prob) {
  const double t0 = whirl_ode_t_prev(o), t1 = whirl_ode_t(o);
  const double *xp = whirl_ode_x_prev(o);
  double e = 0.0;
  for (int j = 1; j < 20; ++j) {
    const double t = t0 + (t1 - t0) * j / 20.0;
    double x[2];
    if (whirl_ode_dense(o, t, x) != WHIRL_OK) return INFINITY;
    if (prob == &osc) {
      const double c = cos(t - t0), s = sin(t - t0);
      e = fmax(e, fmax(fabs(x[0] - (c * xp[0] + s * xp[1])),
                       fabs(x[1] - (-s * xp[0] + c * xp[1]))));
    } else {
      e = fmax(e, fabs(x[0] - xp[0] * exp(t0 * t0 - t * t)));
    }
  }
  return e;
}

static void test_dense(void) {
  /* fixed steps: the continuous extension of order 7 has a local error
   * O(h^8) */
  for (int q = 0; q < 2; ++q) {
    const whirl_problem *prob = q == 0 ? &gauss : &osc;
    const double h0 = q == 0 ? 0.2 : 1.0;
    double el[3];
    int ends = 1;
    size_t evals = 0, steps = 0;
    for (int k = 0; k < 3; ++k) {
      const double h = h0 / (1 << k);
      whirl_ode *o = dop853(prob);
      const double x0[2] = {1.0, 0.0};
      whirl_ode_set_tolerances(o, 0.1, 0.1);
      whirl_ode_set_step_limits(o, h, 0.0, h);
      whirl_ode_reset(o, 0.0, x0);
      el[k] = 0.0;
      while (whirl_ode_t(o) < 2.0 && whirl_ode_step(o, 2.0) == 0) {
        el[k] = fmax(el[k], dense_local(o, prob));
        double y[2];
        whirl_ode_dense(o, whirl_ode_t(o), y);
        ends = ends && y[0] == whirl_ode_x(o)[0];
        whirl_ode_dense(o, whirl_ode_t_prev(o), y);
        ends = ends && y[0] == whirl_ode_x_prev(o)[0];
      }
      whirl_ode_stats st;
      whirl_ode_get_stats(o, &st);
      evals = st.rhs_evals;
      steps = st.steps;
      whirl_ode_free(o);
    }
    printf("# fixed-step dense error, %s: local %.2e %.2e %.2e\n",
           prob->name, el[0], el[1], el[2]);
    for (int k = 0; k < 2; ++k) {
      const double r = el[k] / el[k + 1];
      ok(r > 160.0 && r < 400.0,
         "dense output, %s: local interior error ratio on halving h = %g "
         "is %.1f (256: order 7)",
         prob->name, h0 / (1 << k), r);
    }
    ok(ends, "dense output, %s: exact at both ends of every step",
       prob->name);
    ok(evals == 15 * steps + 1,
       "dense output, %s: its 3 stages once a step however many points "
       "(%zu evaluations for %zu steps)",
       prob->name, evals, steps);
  }

  /* adaptive, default tolerances: dense error within a few tolerances */
  whirl_ode *o = dop853(&osc);
  const double x0[2] = {1.0, 0.0};
  whirl_ode_reset(o, 0.0, x0);
  double dg = 0.0;
  while (whirl_ode_t(o) < 20.0 && whirl_ode_step(o, 20.0) == 0)
    for (int j = 1; j < 10; ++j) {
      const double t = whirl_ode_t_prev(o) +
                       (whirl_ode_t(o) - whirl_ode_t_prev(o)) * j / 10.0;
      double y[2];
      whirl_ode_dense(o, t, y);
      dg = fmax(dg, fmax(fabs(y[0] - cos(t)), fabs(y[1] + sin(t))));
    }
  ok(whirl_ode_t(o) == 20.0 && dg < 1e-10,
     "adaptive dense output at the default tolerances: error %.2e < 1e-10",
     dg);
  double y[2];
  const double t0 = whirl_ode_t_prev(o), t1 = whirl_ode_t(o);
  ok(whirl_ode_dense(o, t1 + 1e-3 * (t1 - t0), y) == WHIRL_EINVAL &&
         whirl_ode_dense(o, NAN, y) == WHIRL_EINVAL,
     "dense output outside the last step: EINVAL");
  whirl_ode_free(o);
}

static void test_accuracy(void) {
  /* oscillator, 100 periods at the default tolerances; the same with
   * DOPRI5 for the evaluations */
  whirl_ode_stats st[2];
  double err[2];
  for (int m = 0; m < 2; ++m) {
    whirl_ode *o = m == 0 ? dop853(&osc) : whirl_ode_alloc(&osc, NULL);
    const double x0[2] = {1.0, 0.0}, T = 200.0 * PI;
    int rc = whirl_ode_reset(o, 0.0, x0);
    rc = rc ? rc : whirl_ode_evolve(o, T);
    err[m] = fmax(fabs(whirl_ode_x(o)[0] - 1.0), fabs(whirl_ode_x(o)[1]));
    whirl_ode_get_stats(o, &st[m]);
    ok(rc == 0 && whirl_ode_t(o) == T, "%s: 100 periods, t = T exactly",
       m == 0 ? "DOP853" : "DOPRI5");
    whirl_ode_free(o);
  }
  printf("# oscillator, 100 periods, rtol 1e-12: DOP853 %zu steps %zu evals "
         "error %.2e; DOPRI5 %zu steps %zu evals error %.2e\n",
         st[0].steps, st[0].rhs_evals, err[0], st[1].steps, st[1].rhs_evals,
         err[1]);
  ok(err[0] < 1e-9, "DOP853 oscillator error %.2e < 1e-9", err[0]);
  ok(st[0].rhs_evals == 12 * (st[0].steps + st[0].rejected) + 2,
     "rhs evaluations = 12 (accepted + rejected) + 2 (start, initial step)");
  ok(3 * st[0].rhs_evals < st[1].rhs_evals,
     "DOP853 needs under a third of DOPRI5's evaluations at rtol 1e-12 "
     "(%zu against %zu)",
     st[0].rhs_evals, st[1].rhs_evals);

  /* pendulum from θ0 = 3 at rest: period 4 K(sin(θ0/2)), 20 periods */
  const double th0 = 3.0, T = 4.0 * ellipk(sin(0.5 * th0));
  whirl_ode *o = dop853(&pend);
  const double x0[2] = {th0, 0.0};
  whirl_ode_reset(o, 0.0, x0);
  int rc = whirl_ode_evolve(o, 20.0 * T);
  const double *x = whirl_ode_x(o);
  const double e = fmax(fabs(x[0] - th0), fabs(x[1]));
  ok(rc == 0 && e < 1e-8,
     "pendulum θ0 = 3, 20 periods (T = %.12f): back to the start to %.2e",
     T, e);
  /* backward to 0 again */
  rc = whirl_ode_evolve(o, 0.0);
  x = whirl_ode_x(o);
  ok(rc == 0 && fabs(x[0] - th0) < 1e-8 && fabs(x[1]) < 1e-8,
     "pendulum backward to t = 0 (error %.2e)",
     fmax(fabs(x[0] - th0), fabs(x[1])));
  whirl_ode_free(o);
}

static void test_events(void) {
  /* zeros of x = cos t: π/2 + kπ */
  whirl_ode *o = dop853(&osc);
  const double x0[2] = {1.0, 0.0};
  whirl_ode_reset(o, 0.0, x0);
  int n = 0;
  double worst = 0.0;
  while (whirl_ode_t(o) < 20.0 && whirl_ode_step(o, 20.0) == 0) {
    double tev, xev[2];
    if (whirl_ode_find_event(o, g_x0, NULL, 0, 1e-14, &tev, xev) == 1) {
      const double want = PI / 2 + n * PI;
      worst = fmax(worst, fabs(tev - want));
      ++n;
    }
  }
  ok(n == 6 && worst < 1e-11,
     "events: the %d zeros of cos t in [0, 20] to %.1e", n, worst);
  whirl_ode_free(o);
}

static void test_failure(void) {
  /* a right-hand side undefined beyond t = 1.5: ESTEP just before it */
  whirl_problem wall = {.name = "wall", .n = 1, .rhs = wall_rhs};
  whirl_ode *o = dop853(&wall);
  const double y0 = 0.0;
  whirl_ode_reset(o, 0.0, &y0);
  const int rc = whirl_ode_evolve(o, 3.0);
  ok(rc == WHIRL_ESTEP && whirl_ode_t(o) <= 1.5 && whirl_ode_t(o) > 1.49 &&
         strstr(whirl_ode_errmsg(o), "returned 7") != NULL,
     "rhs failing beyond t = 1.5: ESTEP at t = %.6f, message \"%s\"",
     whirl_ode_t(o), whirl_ode_errmsg(o));
  whirl_ode_free(o);
}

int main(void) {
  test_method();
  test_order();
  test_dense();
  test_accuracy();
  test_events();
  test_failure();
  return done_testing();
}

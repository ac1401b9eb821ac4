/* test/unit/ode_models.h — closed-form test problems shared by the
 * integrator tests (t_ode.c: DOPRI5, t_dop853.c: DOP853): the harmonic
 * oscillator x'' = -x, y' = -2ty (y = y0 exp(t0² - t²)), the pendulum
 * θ'' = -sin θ (period 4 K(sin θ0/2)), x' = 1 undefined (status 7) beyond
 * t = 1.5, the event x[0] and the complete elliptic integral K by the AGM.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_TEST_ODE_MODELS_H
#define WHIRL_TEST_ODE_MODELS_H
#include <math.h>

#include <whirl/ode.h>

#define PI 3.14159265358979323846

static inline int osc_rhs(double t, const double *x, const double *p, double *f,
                          void *data) {
  (void)t;
  (void)p;
  (void)data;
  f[0] = x[1];
  f[1] = -x[0];
  return 0;
}
static const whirl_problem osc = {
    .name = "oscillator", .n = 2, .rhs = osc_rhs, .autonomous = 1};

static inline int gauss_rhs(double t, const double *x, const double *p, double *f,
                            void *data) {
  (void)p;
  (void)data;
  f[0] = -2.0 * t * x[0];
  return 0;
}
static const whirl_problem gauss = {.name = "gauss", .n = 1, .rhs = gauss_rhs};

static inline int pend_rhs(double t, const double *x, const double *p, double *f,
                           void *data) {
  (void)t;
  (void)p;
  (void)data;
  f[0] = x[1];
  f[1] = -sin(x[0]);
  return 0;
}
static const whirl_problem pend = {
    .name = "pendulum", .n = 2, .rhs = pend_rhs, .autonomous = 1};

static inline int wall_rhs(double t, const double *x, const double *p, double *f,
                           void *data) {
  (void)x;
  (void)p;
  (void)data;
  f[0] = 1.0;
  return t > 1.5 ? 7 : 0;
}

/* complete elliptic integral K(k) = π / (2 AGM(1, sqrt(1 - k²))) */
static inline double ellipk(double k) {
  double a = 1.0, b = sqrt(1.0 - k * k);
  for (int i = 0; i < 40 && fabs(a - b) > 1e-16 * a; ++i) {
    const double m = 0.5 * (a + b);
    b = sqrt(a * b);
    a = m;
  }
  return PI / (a + b);
}

static inline double g_x0(double t, const double *x, void *data) {
  (void)t;
  (void)data;
  return x[0];
}
#endif

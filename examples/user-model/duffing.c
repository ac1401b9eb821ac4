/* examples/user-model/duffing.c — a model of your own as a whirl plug-in:
 * the forced Duffing oscillator (a one-mass rotor-like resonance with a
 * hardening spring)
 *
 *     x'' + 2 zeta x' + x + gamma x^3 = F cos(Omega t)
 *
 * as the first-order system u = (x, v):  x' = v,
 *                                        v' = F cos(Omega t) - 2 zeta v - x - gamma x^3.
 * Parameters p = (Omega, zeta, gamma, F); Omega is the forcing frequency.
 *
 * Build:  make            (two-line Makefile: pkg-config --cflags --libs whirl)
 * Run:    whirl run duffing.whirl
 * Tutorial: doc/user-models.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>

#include <whirl/whirl.h>

static int rhs(double t, const double *u, const double *p, double *f, void *data) {
  (void)data;
  const double x = u[0], v = u[1];
  f[0] = v;
  f[1] = p[3] * cos(p[0] * t) - 2.0 * p[1] * v - x - p[2] * x * x * x;
  return 0;
}

/* Jacobians are optional (NULL: finite differences), column-major:
 * J[i + n*j] = d f_i / d u_j. */
static int jac_x(double t, const double *u, const double *p, double *J, void *data) {
  (void)t;
  (void)data;
  J[0] = 0.0;                                  /* d f0 / dx */
  J[1] = -1.0 - 3.0 * p[2] * u[0] * u[0];      /* d f1 / dx */
  J[2] = 1.0;                                  /* d f0 / dv */
  J[3] = -2.0 * p[1];                          /* d f1 / dv */
  return 0;
}

static int jac_p(double t, const double *u, const double *p, double *J, void *data) {
  (void)data;
  J[0] = 0.0; J[1] = -p[3] * t * sin(p[0] * t);   /* d/dOmega */
  J[2] = 0.0; J[3] = -2.0 * u[1];                 /* d/dzeta */
  J[4] = 0.0; J[5] = -u[0] * u[0] * u[0];         /* d/dgamma */
  J[6] = 0.0; J[7] = cos(p[0] * t);               /* d/dF */
  return 0;
}

static const char *const x_names[] = {"x", "v"};
static const char *const p_names[] = {"Omega", "zeta", "gamma", "F"};
static const double par0[] = {0.5, 0.05, 0.1, 0.3};
static const double u0[] = {0.0, 0.0};

/* The one symbol whirl looks for. */
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "duffing", .n = 2, .npar = 4, .rhs = rhs,
                .jac_x = jac_x, .jac_p = jac_p, .autonomous = 0,
                .x_names = x_names, .p_names = p_names},
    .par0 = par0,
    .u0 = u0,
    .forcing_param = 0, /* p[0] = Omega is the forcing frequency */
    .description = "forced Duffing oscillator"};

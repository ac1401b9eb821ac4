/* examples/auto/enz.c — AUTO-07p demo 'enz' as a whirl plug-in model: two
 * identical cells, each with a substrate-inhibited enzyme reaction,
 * coupled by exchange of the substrate ("a two-cell, one-substrate enzyme
 * model", AUTO-07p demos/enz/enz.f90).
 *
 *   R(s)  = s / (1 + s + kappa s^2)
 *   s1' = (s0      - s1) + (s2 - s1) - rho R(s1)
 *   s2' = (s0 + mu - s2) + (s1 - s2) - rho R(s2)
 *
 * Parameters in AUTO's order, PAR(k) = p[k-1]:  PAR(1) = s0 (substrate
 * supply), PAR(2) = mu (supply asymmetry), PAR(3) = rho (reaction rate),
 * PAR(4) = kappa (inhibition constant).  AUTO's start point (STPNT):
 * s0 = 0, mu = 0, rho = 100, kappa = 1, (s1, s2) = (0, 0).
 * For mu = 0 the model is symmetric under s1 <-> s2: on the symmetric
 * branch s1 = s2 = s, s0 = s + rho R(s); folds where rho R'(s) = -1,
 * pitchforks (branch points) where rho R'(s) = -3.
 *
 * Written for whirl from the equations above (no AUTO code).  Run files:
 * examples/auto/enz-*.whirl; reference values: enz.ref,
 * doc/auto-reference.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <whirl/model.h>

/* R(s) and R'(s) */
static double enz_rate(double s, double kappa, double *dr) {
  const double d = 1.0 + s + kappa * s * s;
  if (dr) *dr = (1.0 - kappa * s * s) / (d * d);
  return s / d;
}

static int enz_rhs(double t, const double *u, const double *p, double *f,
                   void *data) {
  (void)t;
  (void)data;
  const double s1 = u[0], s2 = u[1];
  const double s0 = p[0], mu = p[1], rho = p[2], kappa = p[3];
  f[0] = (s0 - s1) + (s2 - s1) - rho * enz_rate(s1, kappa, NULL);
  f[1] = (s0 + mu - s2) + (s1 - s2) - rho * enz_rate(s2, kappa, NULL);
  return 0;
}

static int enz_jac_x(double t, const double *u, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)data;
  double d1, d2;
  enz_rate(u[0], p[3], &d1);
  enz_rate(u[1], p[3], &d2);
  J[0] = -2.0 - p[2] * d1; /* df1/ds1 */
  J[1] = 1.0;              /* df2/ds1 */
  J[2] = 1.0;              /* df1/ds2 */
  J[3] = -2.0 - p[2] * d2; /* df2/ds2 */
  return 0;
}

static int enz_jac_p(double t, const double *u, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)data;
  const double kappa = p[3];
  const double r1 = enz_rate(u[0], kappa, NULL);
  const double r2 = enz_rate(u[1], kappa, NULL);
  const double d1 = 1.0 + u[0] + kappa * u[0] * u[0];
  const double d2 = 1.0 + u[1] + kappa * u[1] * u[1];
  J[0] = 1.0; /* d/ds0 */
  J[1] = 1.0;
  J[2] = 0.0; /* d/dmu */
  J[3] = 1.0;
  J[4] = -r1; /* d/drho */
  J[5] = -r2;
  /* dR/dkappa = -s^3 / d^2 = -R s^2 / d */
  J[6] = p[2] * r1 * u[0] * u[0] / d1; /* d/dkappa */
  J[7] = p[2] * r2 * u[1] * u[1] / d2;
  return 0;
}

static const char *const enz_x_names[] = {"s1", "s2"};
static const char *const enz_p_names[] = {"s0", "mu", "rho", "kappa"};
static const double enz_par0[] = {0.0, 0.0, 100.0, 1.0};
static const double enz_u0[] = {0.0, 0.0};

const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "enz",
                .n = 2,
                .npar = 4,
                .rhs = enz_rhs,
                .jac_x = enz_jac_x,
                .jac_p = enz_jac_p,
                .autonomous = 1,
                .x_names = enz_x_names,
                .p_names = enz_p_names},
    .par0 = enz_par0,
    .u0 = enz_u0,
    .forcing_param = -1,
    .description = "AUTO demo enz: two coupled cells with substrate-inhibited "
                   "enzyme kinetics"};

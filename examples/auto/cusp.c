/* examples/auto/cusp.c — AUTO-07p demo 'cusp' as a whirl plug-in model: the
 * normal form of the cusp bifurcation (AUTO-07p demo cusp).
 *
 *   x' = mu + lambda x - x^3
 *
 * Parameters in AUTO's order, PAR(k) = p[k-1]:  PAR(1) = lambda,
 * PAR(2) = mu.  AUTO's start point (STPNT): lambda = 1, mu = 0, x = 0.
 * Folds: mu = -lambda x + x^3 with lambda = 3 x^2, i.e.
 * 27 mu^2 = 4 lambda^3; the cusp point is (mu, lambda, x) = (0, 0, 0).
 *
 * Written for whirl from the equation above (no AUTO code).  Run files:
 * examples/auto/cusp-*.whirl; reference values: cusp.ref,
 * doc/auto-reference.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <whirl/model.h>

static int cusp_rhs(double t, const double *u, const double *p, double *f,
                    void *data) {
  (void)t;
  (void)data;
  const double x = u[0];
  f[0] = p[1] + p[0] * x - x * x * x;
  return 0;
}

static int cusp_jac_x(double t, const double *u, const double *p, double *J,
                      void *data) {
  (void)t;
  (void)data;
  J[0] = p[0] - 3.0 * u[0] * u[0];
  return 0;
}

static int cusp_jac_p(double t, const double *u, const double *p, double *J,
                      void *data) {
  (void)t;
  (void)p;
  (void)data;
  J[0] = u[0]; /* d/dlambda */
  J[1] = 1.0;  /* d/dmu */
  return 0;
}

static const char *const cusp_x_names[] = {"x"};
static const char *const cusp_p_names[] = {"lambda", "mu"};
static const double cusp_par0[] = {1.0, 0.0};
static const double cusp_u0[] = {0.0};

const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "cusp",
                .n = 1,
                .npar = 2,
                .rhs = cusp_rhs,
                .jac_x = cusp_jac_x,
                .jac_p = cusp_jac_p,
                .autonomous = 1,
                .x_names = cusp_x_names,
                .p_names = cusp_p_names},
    .par0 = cusp_par0,
    .u0 = cusp_u0,
    .forcing_param = -1,
    .description = "AUTO demo cusp: x' = mu + lambda x - x^3"};

/* examples/auto/pp2.c — AUTO-07p demo 'pp2' as a whirl plug-in model: a
 * predator-prey system with harvesting of the prey ("basic computations
 * for continuous dynamical systems", AUTO-07p demos/pp2/pp2.f90).
 *
 *   fish'   = r fish (1 - fish) - fish sharks - quota (1 - exp(-k fish))
 *   sharks' = -sharks + c fish sharks
 *
 * Parameters in AUTO's order, PAR(k) = p[k-1]:  PAR(1) = quota (harvest
 * rate), PAR(2) = r = 3 (prey growth), PAR(3) = k = 5 (saturation of the
 * harvest), PAR(4) = c = 3 (predator conversion).  AUTO names only PAR(1)
 * ('quota') and the states ('fish', 'sharks'); r, k, c are ours.  AUTO's
 * PVLS copies fish into PAR(9) for the stop at fish = -0.25; whirl's run
 * files name the state directly (UZSTOP = {fish: -0.25}).
 * AUTO's start point (STPNT): quota = 0, r = 3, k = 5, c = 3,
 * (fish, sharks) = (0, 0).
 * Closed forms: on sharks = 0, quota = r fish (1 - fish) / (1 - exp(-k fish))
 * (branch point from fish = 0 at quota = r/k = 0.6); the coexistence branch
 * has fish = 1/c, sharks = r (1 - 1/c) - c quota (1 - exp(-k/c)), and its
 * Hopf point is at quota = 1 / (3 - 8 exp(-5/3)) for r = 3, k = 5, c = 3.
 *
 * Written for whirl from the equations above (no AUTO code).  Run files:
 * examples/auto/pp2-*.whirl; reference values: pp2.ref,
 * doc/auto-reference.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>

#include <whirl/model.h>

static int pp2_rhs(double t, const double *u, const double *p, double *f,
                   void *data) {
  (void)t;
  (void)data;
  const double x = u[0], y = u[1];
  f[0] = p[1] * x * (1.0 - x) - x * y - p[0] * (1.0 - exp(-p[2] * x));
  f[1] = -y + p[3] * x * y;
  return 0;
}

static int pp2_jac_x(double t, const double *u, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)data;
  const double x = u[0], y = u[1];
  const double e = exp(-p[2] * x);
  J[0] = p[1] * (1.0 - 2.0 * x) - y - p[0] * p[2] * e; /* df1/dfish */
  J[1] = p[3] * y;                                     /* df2/dfish */
  J[2] = -x;                                           /* df1/dsharks */
  J[3] = -1.0 + p[3] * x;                              /* df2/dsharks */
  return 0;
}

static int pp2_jac_p(double t, const double *u, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)data;
  const double x = u[0], y = u[1];
  const double e = exp(-p[2] * x);
  J[0] = -(1.0 - e);        /* d/dquota */
  J[1] = 0.0;
  J[2] = x * (1.0 - x);     /* d/dr */
  J[3] = 0.0;
  J[4] = -p[0] * x * e;     /* d/dk */
  J[5] = 0.0;
  J[6] = 0.0;               /* d/dc */
  J[7] = x * y;
  return 0;
}

static const char *const pp2_x_names[] = {"fish", "sharks"};
static const char *const pp2_p_names[] = {"quota", "r", "k", "c"};
static const double pp2_par0[] = {0.0, 3.0, 5.0, 3.0};
static const double pp2_u0[] = {0.0, 0.0};

const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "pp2",
                .n = 2,
                .npar = 4,
                .rhs = pp2_rhs,
                .jac_x = pp2_jac_x,
                .jac_p = pp2_jac_p,
                .autonomous = 1,
                .x_names = pp2_x_names,
                .p_names = pp2_p_names},
    .par0 = pp2_par0,
    .u0 = pp2_u0,
    .forcing_param = -1,
    .description = "AUTO demo pp2: predator-prey model with harvesting of "
                   "the prey"};

/* examples/auto/lrz.c — AUTO-07p demo 'lrz' as a whirl plug-in model: the
 * Lorenz equations (E. N. Lorenz, J. Atmos. Sci. 20 (1963) 130-141;
 * AUTO-07p demo lrz).
 *
 *   x' = sigma (y - x)
 *   y' = rho x - y - x z
 *   z' = x y - beta z
 *
 * Parameters in AUTO's order, PAR(k) = p[k-1]:  PAR(1) = rho, PAR(2) =
 * beta, PAR(3) = sigma.  AUTO's start point (STPNT): rho = 0,
 * beta = 8/3, sigma = 10, (x, y, z) = (0, 0, 0).
 * Closed forms: pitchfork (branch point) of the origin at rho = 1; the
 * equilibria C+- = (+-sqrt(beta (rho - 1)), +-sqrt(beta (rho - 1)),
 * rho - 1) lose stability at the Hopf point
 * rho_H = sigma (sigma + beta + 3) / (sigma - beta - 1) = 470/19 for
 * sigma = 10, beta = 8/3.  The periodic orbits born there end in a
 * homoclinic orbit of the origin at rho = 13.9266 (AUTO demo lrz run 2).
 *
 * Written for whirl from the equations above (no AUTO code).  Run files:
 * examples/auto/lrz-*.whirl; reference values: lrz.ref,
 * doc/auto-reference.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <whirl/model.h>

static int lrz_rhs(double t, const double *u, const double *p, double *f,
                   void *data) {
  (void)t;
  (void)data;
  const double x = u[0], y = u[1], z = u[2];
  const double rho = p[0], beta = p[1], sigma = p[2];
  f[0] = sigma * (y - x);
  f[1] = rho * x - y - x * z;
  f[2] = x * y - beta * z;
  return 0;
}

/* J[i + 3 j] = d f_i / d u_j */
static int lrz_jac_x(double t, const double *u, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)data;
  const double x = u[0], y = u[1], z = u[2];
  const double rho = p[0], beta = p[1], sigma = p[2];
  J[0] = -sigma;  /* d/dx */
  J[1] = rho - z;
  J[2] = y;
  J[3] = sigma;   /* d/dy */
  J[4] = -1.0;
  J[5] = x;
  J[6] = 0.0;     /* d/dz */
  J[7] = -x;
  J[8] = -beta;
  return 0;
}

/* J[i + 3 k] = d f_i / d p_k */
static int lrz_jac_p(double t, const double *u, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)p;
  (void)data;
  const double x = u[0], y = u[1], z = u[2];
  J[0] = 0.0;     /* d/drho */
  J[1] = x;
  J[2] = 0.0;
  J[3] = 0.0;     /* d/dbeta */
  J[4] = 0.0;
  J[5] = -z;
  J[6] = y - x;   /* d/dsigma */
  J[7] = 0.0;
  J[8] = 0.0;
  return 0;
}

static const char *const lrz_x_names[] = {"x", "y", "z"};
static const char *const lrz_p_names[] = {"rho", "beta", "sigma"};
static const double lrz_par0[] = {0.0, 8.0 / 3.0, 10.0};
static const double lrz_u0[] = {0.0, 0.0, 0.0};

const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "lrz",
                .n = 3,
                .npar = 3,
                .rhs = lrz_rhs,
                .jac_x = lrz_jac_x,
                .jac_p = lrz_jac_p,
                .autonomous = 1,
                .x_names = lrz_x_names,
                .p_names = lrz_p_names},
    .par0 = lrz_par0,
    .u0 = lrz_u0,
    .forcing_param = -1,
    .description = "AUTO demo lrz: the Lorenz equations"};

/* test/regress/twist.c — the Hopf normal form with a twist, a plug-in model
 * for fixed_period.sh and arclength.sh: r' = r (mu - r^2),
 * theta' = 1 + b r^2 in Cartesian form, whose orbits r^2 = mu have the
 * period 2 pi / (1 + b mu).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  const double x = u[0], y = u[1], s = x * x + y * y, w = 1 + p[1] * s;
  f[0] = (p[0] - s) * x - w * y;
  f[1] = (p[0] - s) * y + w * x;
  return 0;
}
static const char *const xn[] = {"x", "y"};
static const char *const pn[] = {"mu", "b"};
static const double par0[] = {-0.5, 0.5};
static const double u0[] = {0.0, 0.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "twist", .n = 2, .npar = 2, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .u0 = u0, .forcing_param = -1,
    .description = "Hopf normal form, frequency 1 + b r^2"};

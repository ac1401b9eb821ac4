/* examples/auto/ab.c — AUTO-07p demo 'ab' as a whirl plug-in model: the
 * first-order exothermic reaction A -> B in a continuous stirred tank
 * reactor (Uppal, Ray & Poore 1974; AUTO-07p manual, demo ab).
 *
 *   u1' = -u1 + Da (1 - u1) exp(u2)
 *   u2' = -u2 + B Da (1 - u1) exp(u2) - beta u2
 *
 * u1: conversion, u2: temperature (both scaled).  Parameters in AUTO's
 * order, PAR(k) = p[k-1]:  PAR(1) = Da (Damkoehler number), PAR(2) = B
 * (heat of reaction), PAR(3) = beta (heat transfer coefficient).
 * AUTO's start point (STPNT): Da = 0, B = 8, beta = 3, U = (0, 0), an
 * equilibrium for every B (the trivial branch of run 1).
 *
 * Written for whirl from the equations above (no AUTO code).  Run files:
 * examples/auto/ab-*.whirl; reference values: ab.ref, doc/auto-reference.md.
 * Build: gcc -std=c11 -shared -fPIC -I<whirl headers> -o ab.so ab.c -lm
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>

#include <whirl/model.h>

static int ab_rhs(double t, const double *u, const double *p, double *f,
                  void *data) {
  (void)t;
  (void)data;
  const double r = p[0] * (1.0 - u[0]) * exp(u[1]); /* reaction rate */
  f[0] = -u[0] + r;
  f[1] = -u[1] + p[1] * r - p[2] * u[1];
  return 0;
}

/* J[i + 2 j] = d f_i / d u_j */
static int ab_jac_x(double t, const double *u, const double *p, double *J,
                    void *data) {
  (void)t;
  (void)data;
  const double e = exp(u[1]);
  const double r = p[0] * (1.0 - u[0]) * e;
  J[0] = -1.0 - p[0] * e;        /* df1/du1 */
  J[1] = -p[1] * p[0] * e;       /* df2/du1 */
  J[2] = r;                      /* df1/du2 */
  J[3] = -1.0 + p[1] * r - p[2]; /* df2/du2 */
  return 0;
}

/* J[i + 2 k] = d f_i / d p_k */
static int ab_jac_p(double t, const double *u, const double *p, double *J,
                    void *data) {
  (void)t;
  (void)data;
  const double g = (1.0 - u[0]) * exp(u[1]);
  J[0] = g;            /* d/dDa */
  J[1] = p[1] * g;
  J[2] = 0.0;          /* d/dB */
  J[3] = p[0] * g;
  J[4] = 0.0;          /* d/dbeta */
  J[5] = -u[1];
  return 0;
}

static const char *const ab_x_names[] = {"u1", "u2"};
static const char *const ab_p_names[] = {"Da", "B", "beta"};
static const double ab_par0[] = {0.0, 8.0, 3.0};
static const double ab_u0[] = {0.0, 0.0};

const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "ab",
                .n = 2,
                .npar = 3,
                .rhs = ab_rhs,
                .jac_x = ab_jac_x,
                .jac_p = ab_jac_p,
                .autonomous = 1,
                .x_names = ab_x_names,
                .p_names = ab_p_names},
    .par0 = ab_par0,
    .u0 = ab_u0,
    .forcing_param = -1,
    .description = "AUTO demo ab: A -> B reaction in a CSTR (Uppal, Ray & "
                   "Poore 1974)"};

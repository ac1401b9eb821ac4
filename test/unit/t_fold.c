/* test/unit/t_fold.c — fold and Hopf systems (two-parameter continuation)
 * and their codimension-two points, against closed forms:
 *  (a) the cusp normal form x' = mu + lambda x - x^3 (AUTO-07p demo 'cusp'):
 *      the fold at lambda = 1 is mu = 2/(3 sqrt 3); along the fold curve
 *      mu = -+2 (lambda/3)^{3/2}; the cusp CP at the origin;
 *  (b) AUTO-07p demo 'ab' (beta = 3): the fold locus in (D, B) is
 *      B u1 (1 - u1) = 1 + beta, the Hopf locus B u1 (1 - u1) = 2 + beta -
 *      (1 + beta) u1 (doc/auto-reference.md), with D = u1 e^{-u2}/(1 - u1),
 *      u2 = B u1/(1 + beta); the cusp at B = 4(1 + beta) = 16, u1 = 1/2,
 *      D = e^{-2}; the Bogdanov-Takens point where both loci meet:
 *      u1 = 1/(1 + beta), B = 64/3, D = e^{-4/3}/3, on both curves;
 *  (c) the Bogdanov-Takens normal form x' = y, y' = b1 + b2 x + x^2 - x y
 *      (Kuznetsov, Elements of Applied Bifurcation Theory, 3rd ed., §8.4):
 *      fold curve b1 = b2^2/4, Hopf curve b1 = 0 (b2 < 0), BT at the origin;
 *  (d) a zero-Hopf point: x' = b1 + x^2 - a(y^2 + z^2)... see zh_* below;
 *  (e) the fold system's Jacobian against finite differences;
 *  (f) SFD circular orbits: the fold curve of the rotating-frame equilibria
 *      in (Omega, delta) at lambda = 0.25 passes the isola merge MG, which
 *      agrees with G = G_eps = G_Omega = 0 of eq. 15 solved independently;
 *  (g) bad options.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>
#include <whirl/rotor/sfd_region.h>

#include "../tap.h"

/* ------------------------------------------------------------------------
 * Models */

/* cusp: p = (lambda, mu) */
static int cusp_rhs(double t, const double *x, const double *p, double *f,
                    void *d) {
  (void)t, (void)d;
  f[0] = p[1] + p[0] * x[0] - x[0] * x[0] * x[0];
  return 0;
}
static int cusp_jac(double t, const double *x, const double *p, double *J,
                    void *d) {
  (void)t, (void)d;
  J[0] = p[0] - 3.0 * x[0] * x[0];
  return 0;
}
static const whirl_problem cusp = {
    .name = "cusp", .n = 1, .npar = 2, .rhs = cusp_rhs, .jac_x = cusp_jac,
    .autonomous = 1};

/* ab: p = (D, B, beta) */
static int ab_rhs(double t, const double *u, const double *p, double *f,
                  void *d) {
  (void)t, (void)d;
  const double E = p[0] * exp(u[1]);
  f[0] = -u[0] + (1.0 - u[0]) * E;
  f[1] = -u[1] + p[1] * (1.0 - u[0]) * E - p[2] * u[1];
  return 0;
}
static int ab_jac(double t, const double *u, const double *p, double *J,
                  void *d) {
  (void)t, (void)d;
  const double E = p[0] * exp(u[1]);
  J[0] = -1.0 - E;
  J[1] = -p[1] * E;
  J[2] = (1.0 - u[0]) * E;
  J[3] = -1.0 + p[1] * (1.0 - u[0]) * E - p[2];
  return 0;
}
static const whirl_problem ab = {
    .name = "ab", .n = 2, .npar = 3, .rhs = ab_rhs, .jac_x = ab_jac,
    .autonomous = 1};

/* Bogdanov-Takens normal form: p = (b1, b2) */
static int bt_rhs(double t, const double *x, const double *p, double *f,
                  void *d) {
  (void)t, (void)d;
  f[0] = x[1];
  f[1] = p[0] + p[1] * x[0] + x[0] * x[0] - x[0] * x[1];
  return 0;
}
static const whirl_problem btnf = {
    .name = "bt", .n = 2, .npar = 2, .rhs = bt_rhs, .autonomous = 1};

/* Fold-Hopf (zero-Hopf) truncated normal form in cylindrical form made
 * Cartesian (Kuznetsov §8.5): x' = b1 + x^2 + (y^2 + z^2),
 *   y' = b2 y - w z + x y,  z' = w y + b2 z + x z   (w = 1).
 * Equilibria y = z = 0, x = +-sqrt(-b1); the eigenvalues there are 2x and
 * b2 + x +- i.  Fold curve b1 = 0 (x = 0), on which the pair has real part
 * b2: ZH at (b1, b2) = (0, 0). */
static int zh_rhs(double t, const double *x, const double *p, double *f,
                  void *d) {
  (void)t, (void)d;
  f[0] = p[0] + x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  f[1] = p[1] * x[1] - x[2] + x[0] * x[1];
  f[2] = x[1] + p[1] * x[2] + x[0] * x[2];
  return 0;
}
static const whirl_problem zhnf = {
    .name = "zh", .n = 3, .npar = 2, .rhs = zh_rhs, .autonomous = 1};

/* ------------------------------------------------------------------------
 * Helpers */

typedef struct run {
  size_t npts;
  double maxdev;       /* largest deviation from a closed form */
  int ntype[16];       /* special points by type */
  double sp[16][8];    /* first special point of each type: Z then p */
  size_t nZ;
  int stop;
} run;

typedef double (*dev_fn)(const double *Z, const double *p);

static int trace(const whirl_system *s, const double *Z0, const double *p0,
                 size_t icp, int dir, double ds, double pmin, double pmax,
                 size_t nmx, dev_fn dev, run *r) {
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = icp;
  co.ds = ds;
  co.ds_max = 0.05;
  co.nmx = nmx;
  co.p_min = pmin;
  co.p_max = pmax;
  co.newton_tol = 1e-11;
  co.detect_hb = 0;
  co.detect_bp = 0;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(s, &co, err, sizeof err);
  if (!c) {
    printf("# %s\n", err);
    return -1;
  }
  memset(r, 0, sizeof *r);
  r->nZ = s->n;
  int rc = whirl_cont_start(c, Z0, p0, dir);
  while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    ++r->npts;
    if (dev) r->maxdev = fmax(r->maxdev, dev(pt->x, pt->p));
    if (pt->type > 0 && pt->type < 16) {
      if (r->ntype[pt->type]++ == 0) {
        for (size_t i = 0; i < s->n && i < 6; ++i) r->sp[pt->type][i] = pt->x[i];
        r->sp[pt->type][6] = pt->p[0];
        r->sp[pt->type][7] = pt->p[1];
      }
    }
  }
  r->stop = whirl_cont_stop_reason(c);
  if (rc < 0) printf("# continuation error: %s\n", whirl_cont_errmsg(c));
  whirl_cont_free(c);
  return rc < 0 ? rc : 0;
}

/* Localise the first LP (or HB) of an equilibrium branch. */
static int first_special(const whirl_system *s, const double *x0,
                         const double *p0, size_t icp, int dir, int type,
                         double *x, double *p) {
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = icp;
  co.ds = 0.01;
  co.ds_max = 0.05;
  co.nmx = 2000;
  co.newton_tol = 1e-12;
  whirl_cont *c = whirl_cont_alloc(s, &co, NULL, 0);
  int rc = whirl_cont_start(c, x0, p0, dir), found = 0;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    if (pt->type == type) {
      memcpy(x, pt->x, s->n * sizeof *x);
      memcpy(p, pt->p, s->npar * sizeof *p);
      found = 1;
      break;
    }
  }
  whirl_cont_free(c);
  return found ? 0 : -1;
}

/* ------------------------------------------------------------------------
 * (a) cusp */

static double cusp_dev(const double *Z, const double *p) {
  /* fold curve: lambda = 3 x^2, mu = -2 x^3 (from f = f_x = 0) */
  const double x = Z[0], mu = Z[1], lam = p[0];
  return fmax(fabs(lam - 3.0 * x * x), fabs(mu + 2.0 * x * x * x));
}

static void test_cusp(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&cusp);
  const whirl_system *s = whirl_equilibrium_system(eq);
  double x0 = 0.0, p0[2] = {1.0, 0.0}, x, p[2];
  int rc = first_special(s, &x0, p0, 1, +1, WHIRL_PT_LP, &x, p);
  ok(rc == 0, "cusp: an LP in mu at lambda = 1");
  is_abs(p[1], 2.0 / (3.0 * sqrt(3.0)), 1e-11, "cusp: LP at mu = 2/(3 sqrt 3)");
  is_abs(x, -1.0 / sqrt(3.0), 1e-7, "cusp: LP at x = -1/sqrt 3");

  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 1);
  char err[256];
  whirl_fold *f = whirl_fold_alloc(s, &fo, err, sizeof err);
  ok(f != NULL, "cusp: fold system allocated");
  double Z[2];
  ok(whirl_fold_init(f, &x, p, Z) == WHIRL_OK, "cusp: fold system started");
  run r;
  rc = trace(whirl_fold_system(f), Z, p, 0, -1, 0.01, -1.0, 2.0, 500, cusp_dev, &r);
  ok(rc == 0 && r.npts > 20, "cusp: fold curve traced in lambda (%zu points)", r.npts);
  ok(r.maxdev < 1e-10, "cusp: every point on lambda = 3x^2, mu = -2x^3 (max dev %.2g)", r.maxdev);
  ok(r.ntype[WHIRL_PT_CP] == 1, "cusp: one CP on the fold curve (%d)", r.ntype[WHIRL_PT_CP]);
  ok(r.ntype[WHIRL_PT_LP] == 0, "cusp: the turning point is reported as CP, not LP");
  const double *cp = r.sp[WHIRL_PT_CP];
  ok(fabs(cp[0]) < 1e-8 && fabs(cp[1]) < 1e-12 && fabs(cp[6]) < 1e-12,
     "cusp: CP at the origin (x %.2g, mu %.2g, lambda %.2g)", cp[0], cp[1], cp[6]);
  ok(r.ntype[WHIRL_PT_BT] == 0 && r.ntype[WHIRL_PT_MG] == 0 && r.ntype[WHIRL_PT_IS] == 0,
     "cusp: no BT, IS or MG");
  whirl_fold_free(f);
  whirl_equilibrium_free(eq);
}

/* ------------------------------------------------------------------------
 * (b) ab */

static const double AB_BETA = 3.0;

static double ab_fold_dev(const double *Z, const double *p) {
  /* Z = (u1, u2, D), p[1] = B */
  const double u1 = Z[0], u2 = Z[1], D = Z[2], B = p[1], b = AB_BETA;
  const double e1 = B * u1 * (1.0 - u1) - (1.0 + b);
  const double e2 = u2 - B * u1 / (1.0 + b);
  const double e3 = D - u1 * exp(-u2) / (1.0 - u1);
  return fmax(fabs(e1) / B, fmax(fabs(e2), fabs(e3)));
}

static double ab_hopf_dev(const double *Z, const double *p) {
  const double u1 = Z[0], u2 = Z[1], D = Z[2], kappa = Z[3], B = p[1], b = AB_BETA;
  const double e1 = B * u1 * (1.0 - u1) - (2.0 + b - (1.0 + b) * u1);
  const double e2 = u2 - B * u1 / (1.0 + b);
  const double e3 = D - u1 * exp(-u2) / (1.0 - u1);
  /* omega^2 = det J on the Hopf curve: det = (1+beta)/(1-u1) - B u1 */
  const double e4 = kappa - ((1.0 + b) / (1.0 - u1) - B * u1);
  return fmax(fmax(fabs(e1) / B, fabs(e2)), fmax(fabs(e3), fabs(e4)));
}

static void test_ab(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&ab);
  const whirl_system *s = whirl_equilibrium_system(eq);
  double u0[2] = {0.0, 0.0}, p0[3] = {0.0, 17.0, AB_BETA}, u[2], p[3];
  int rc = first_special(s, u0, p0, 0, +1, WHIRL_PT_LP, u, p);
  ok(rc == 0, "ab: an LP in D at B = 17");
  is_abs(p[0], 0.121901160811, 1e-11, "ab: LP at D = 0.121901160811 (closed form)");

  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 0);
  whirl_fold *f = whirl_fold_alloc(s, &fo, NULL, 0);
  double Z[3];
  ok(f && whirl_fold_init(f, u, p, Z) == WHIRL_OK, "ab: fold system started at the LP");
  run r, r2;
  /* B down through the cusp at 16 and up the u1 > 1/2 side to 30 ... */
  rc = trace(whirl_fold_system(f), Z, p, 1, -1, 0.05, 10.0, 30.0, 2000, ab_fold_dev, &r);
  ok(rc == 0 && r.npts > 20, "ab: fold locus traced in (D, B) (%zu points)", r.npts);
  ok(r.maxdev < 1e-10, "ab: fold locus on the closed form (max dev %.2g)", r.maxdev);
  ok(r.ntype[WHIRL_PT_CP] == 1, "ab: one cusp (%d)", r.ntype[WHIRL_PT_CP]);
  ok(r.ntype[WHIRL_PT_BT] == 0, "ab: no BT on the u1 > 1/2 side");
  is_abs(r.sp[WHIRL_PT_CP][7], 16.0, 1e-7, "ab: CP at B = 4(1 + beta) = 16");
  is_abs(r.sp[WHIRL_PT_CP][2], exp(-2.0), 1e-8, "ab: CP at D = e^-2");
  is_abs(r.sp[WHIRL_PT_CP][0], 0.5, 1e-5, "ab: CP at u1 = 1/2");
  /* ... and B up along u1 < 1/2 through the BT point */
  whirl_fold_init(f, u, p, Z);
  rc = trace(whirl_fold_system(f), Z, p, 1, +1, 0.05, 10.0, 30.0, 2000, ab_fold_dev, &r2);
  ok(rc == 0 && r2.maxdev < 1e-10, "ab: fold locus, other direction, on the closed form (%.2g)",
     r2.maxdev);
  ok(r2.ntype[WHIRL_PT_BT] == 1, "ab: one Bogdanov-Takens point on the fold locus (%d)",
     r2.ntype[WHIRL_PT_BT]);
  is_abs(r2.sp[WHIRL_PT_BT][7], 64.0 / 3.0, 1e-8, "ab: BT at B = 64/3");
  is_abs(r2.sp[WHIRL_PT_BT][2], exp(-4.0 / 3.0) / 3.0, 1e-10, "ab: BT at D = e^{-4/3}/3");
  is_abs(r2.sp[WHIRL_PT_BT][0], 0.25, 1e-9, "ab: BT at u1 = 1/(1 + beta)");
  ok(r2.ntype[WHIRL_PT_CP] == 0, "ab: no cusp on the u1 < 1/2 side");
  whirl_fold_free(f);

  /* Hopf locus from the first HB at B = 17 */
  rc = first_special(s, u0, p0, 0, +1, WHIRL_PT_HB, u, p);
  ok(rc == 0, "ab: an HB in D at B = 17");
  is_abs(p[0], 0.120865719509, 1e-10, "ab: HB at D = 0.120865719509 (closed form)");
  whirl_hopf *h = whirl_hopf_alloc(s, 0, NULL, 0);
  double ZH[4];
  ok(h && whirl_hopf_init(h, u, p, ZH) == WHIRL_OK, "ab: Hopf system started at the HB");
  rc = trace(whirl_hopf_system(h), ZH, p, 1, +1, 0.05, 10.0, 21.0, 2000, ab_hopf_dev, &r);
  ok(rc == 0 && r.npts > 20, "ab: Hopf locus traced up to B = 21 (%zu points)", r.npts);
  ok(r.maxdev < 1e-9, "ab: Hopf locus on the closed form, kappa = det J (max dev %.2g)",
     r.maxdev);
  /* on to the BT point, where kappa = omega^2 passes 0 */
  rc = whirl_hopf_init(h, u, p, ZH);
  rc = trace(whirl_hopf_system(h), ZH, p, 1, +1, 0.05, 10.0, 30.0, 2000, NULL, &r);
  ok(r.ntype[WHIRL_PT_BT] >= 1, "ab: BT on the Hopf locus (%d)", r.ntype[WHIRL_PT_BT]);
  is_abs(r.sp[WHIRL_PT_BT][7], 64.0 / 3.0, 1e-8, "ab: BT on the Hopf locus at B = 64/3");
  is_abs(r.sp[WHIRL_PT_BT][2], exp(-4.0 / 3.0) / 3.0, 1e-10,
         "ab: BT on the Hopf locus at D = e^{-4/3}/3");
  whirl_hopf_free(h);
  whirl_equilibrium_free(eq);
}

/* ------------------------------------------------------------------------
 * (c) Bogdanov-Takens normal form */

static void test_bt(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&btnf);
  const whirl_system *s = whirl_equilibrium_system(eq);
  /* fold at b2 = 1: x = -1/2, b1 = 1/4 (exact) */
  double x[2] = {-0.5, 0.0}, p[2] = {0.25, 1.0};
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 0);
  whirl_fold *f = whirl_fold_alloc(s, &fo, NULL, 0);
  double Z[3];
  ok(f && whirl_fold_init(f, x, p, Z) == WHIRL_OK, "BT normal form: fold system started");
  run r;
  int rc = trace(whirl_fold_system(f), Z, p, 1, -1, 0.05, -1.0, 2.0, 500, NULL, &r);
  ok(rc == 0 && r.ntype[WHIRL_PT_BT] == 1, "BT normal form: one BT on the fold curve (%d)",
     r.ntype[WHIRL_PT_BT]);
  const double *bt = r.sp[WHIRL_PT_BT];
  ok(fabs(bt[0]) < 1e-9 && fabs(bt[2]) < 1e-12 && fabs(bt[7]) < 1e-9,
     "BT normal form: BT at the origin (x %.2g, b1 %.2g, b2 %.2g)", bt[0], bt[2], bt[7]);
  ok(r.ntype[WHIRL_PT_CP] == 0, "BT normal form: no cusp on the fold curve");
  whirl_fold_free(f);

  /* Hopf curve from b2 = -1, b1 = 0, x = 0: eigenvalues +-i */
  double xh[2] = {0.0, 0.0}, ph[2] = {0.0, -1.0}, ZH[4];
  whirl_hopf *h = whirl_hopf_alloc(s, 0, NULL, 0);
  ok(h && whirl_hopf_init(h, xh, ph, ZH) == WHIRL_OK, "BT normal form: Hopf system started");
  is_abs(ZH[3], 1.0, 1e-12, "BT normal form: omega^2 = -b2 = 1 at the start");
  rc = trace(whirl_hopf_system(h), ZH, ph, 1, +1, 0.05, -2.0, 1.0, 500, NULL, &r);
  ok(rc == 0 && r.ntype[WHIRL_PT_BT] == 1, "BT normal form: BT on the Hopf curve (%d)",
     r.ntype[WHIRL_PT_BT]);
  bt = r.sp[WHIRL_PT_BT];
  ok(fabs(bt[2]) < 1e-10 && fabs(bt[7]) < 1e-10 && fabs(bt[3]) < 1e-10,
     "BT normal form: Hopf curve reaches BT at the origin with omega -> 0 (b1 %.2g, b2 %.2g, kappa %.2g)",
     bt[2], bt[7], bt[3]);
  whirl_hopf_free(h);
  whirl_equilibrium_free(eq);
}

/* ------------------------------------------------------------------------
 * (d) zero-Hopf */

static void test_zh(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&zhnf);
  const whirl_system *s = whirl_equilibrium_system(eq);
  /* fold at b1 = 0, x = 0, for b2 = -0.5; continue the fold curve in b2 */
  double x[3] = {0.0, 0.0, 0.0}, p[2] = {0.0, -0.5};
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 0);
  whirl_fold *f = whirl_fold_alloc(s, &fo, NULL, 0);
  double Z[4];
  ok(f && whirl_fold_init(f, x, p, Z) == WHIRL_OK, "zero-Hopf: fold system started");
  run r;
  int rc = trace(whirl_fold_system(f), Z, p, 1, +1, 0.05, -1.0, 0.7, 500, NULL, &r);
  ok(rc == 0 && r.ntype[WHIRL_PT_ZH] == 1, "zero-Hopf: one ZH on the fold curve (%d)",
     r.ntype[WHIRL_PT_ZH]);
  ok(fabs(r.sp[WHIRL_PT_ZH][7]) < 1e-10, "zero-Hopf: ZH at b2 = 0 (%.2g)", r.sp[WHIRL_PT_ZH][7]);
  ok(r.ntype[WHIRL_PT_BT] == 0, "zero-Hopf: no BT");
  whirl_fold_free(f);
  whirl_equilibrium_free(eq);
}

/* ------------------------------------------------------------------------
 * (e) Jacobian of the fold system against central differences */

static void test_jacobian(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&ab);
  const whirl_system *s = whirl_equilibrium_system(eq);
  double u[2] = {0.4, 0.0}, p[3] = {0.0, 17.0, AB_BETA};
  u[1] = p[1] * u[0] / (1.0 + AB_BETA);
  p[0] = u[0] * exp(-u[1]) / (1.0 - u[0]);
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 0);
  whirl_fold *f = whirl_fold_alloc(s, &fo, NULL, 0);
  double Z[3];
  whirl_fold_init(f, u, p, Z);
  double err = 1.0;
  int crc = whirl_system_check_jacobian(whirl_fold_system(f), Z, p, &err);
  ok(crc == 0 && err < 1e-7,
     "fold system: Jacobian (two-Jacobian difference for g) against finite differences (%.2g)",
     err);
  whirl_fold_free(f);
  /* merge (cond) system: 2 freed parameters */
  whirl_fold_options_default(&fo, 0);
  fo.nfree = 2;
  fo.free[1] = 1;
  fo.cond = WHIRL_FOLD_COND_BT;
  f = whirl_fold_alloc(s, &fo, NULL, 0);
  double Z2[4];
  ok(f && whirl_fold_init(f, u, p, Z2) == WHIRL_OK && whirl_fold_size(f) == 4,
     "BT-curve system: 4 unknowns (u1, u2, D, B)");
  crc = whirl_system_check_jacobian(whirl_fold_system(f), Z2, p, &err);
  ok(crc == 0 && err < 1e-6,
     "BT-curve system: Jacobian against finite differences (%.2g)", err);
  /* Newton on the BT system lands on the closed-form BT point */
  double Zb[4] = {0.3, 1.5, 0.1, 20.0};
  int its = 0;
  whirl_fold_init(f, Zb, (double[]){0.1, 20.0, AB_BETA}, Zb);
  int rc = whirl_newton(whirl_fold_system(f), Zb, (double[]){0.1, 20.0, AB_BETA}, 1e-13,
                        30, &its);
  ok(rc == 0, "BT-curve system: Newton converges (%d iterations)", its);
  is_abs(Zb[3], 64.0 / 3.0, 1e-9, "BT-curve system: B = 64/3");
  is_abs(Zb[0], 0.25, 1e-10, "BT-curve system: u1 = 1/4");
  whirl_fold_free(f);
  whirl_equilibrium_free(eq);
}

/* ------------------------------------------------------------------------
 * (f) SFD: the isola merge on the fold curve in (Omega, delta) */

/* Independent: G = G_eps = G_Omega = 0 of eq. 15 by Newton in (eps, Omega,
 * delta) with a finite-difference Jacobian of whirl_sfd_circ_G. */
static int eq15_merge(double lambda, double zeta, double *e, double *W,
                      double *d) {
  for (int it = 0; it < 60; ++it) {
    double F[3], J[9], x[3] = {*e, *W, *d};
    for (int k = -1; k < 3; ++k) {
      double y[3] = {x[0], x[1], x[2]}, h = 0.0;
      if (k >= 0) h = 1e-7 * (1.0 + fabs(x[k])), y[k] += h;
      double G, Ge, GW;
      whirl_sfd_circ_G(y[0], y[1], lambda, y[2], zeta, &G, &Ge, &GW);
      const double v[3] = {G, Ge, GW};
      for (int i = 0; i < 3; ++i) {
        if (k < 0) F[i] = v[i];
        else J[i + 3 * k] = (v[i] - F[i]) / h;
      }
    }
    /* Cramer */
    const double det = J[0] * (J[4] * J[8] - J[7] * J[5]) - J[3] * (J[1] * J[8] - J[7] * J[2]) +
                       J[6] * (J[1] * J[5] - J[4] * J[2]);
    double dx[3];
    for (int c = 0; c < 3; ++c) {
      double M[9];
      memcpy(M, J, sizeof M);
      for (int i = 0; i < 3; ++i) M[i + 3 * c] = -F[i];
      dx[c] = (M[0] * (M[4] * M[8] - M[7] * M[5]) - M[3] * (M[1] * M[8] - M[7] * M[2]) +
               M[6] * (M[1] * M[5] - M[4] * M[2])) / det;
    }
    *e += dx[0], *W += dx[1], *d += dx[2];
    if (fabs(dx[0]) + fabs(dx[1]) + fabs(dx[2]) < 1e-14) return 0;
  }
  return -1;
}

static void test_sfd_merge(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(whirl_sfd_rotating());
  const whirl_system *s = whirl_equilibrium_system(eq);
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_LAMBDA] = 0.25;
  p[WHIRL_SFD_DELTA] = 0.40;
  /* the isola's fold at delta = 0.40 from the complete response */
  whirl_sfd_response_options ro;
  whirl_sfd_response_options_default(&ro);
  whirl_sfd_response resp;
  char err[256];
  int rc = whirl_sfd_response_compute(p, &ro, &resp, err, sizeof err);
  ok(rc == 0, "SFD merge: response at lambda 0.25, delta 0.40");
  /* every LP of the response seeds a fold curve in delta; collect MG */
  int nmg = 0;
  double mg[8] = {0};
  for (size_t b = 0; b < resp.nbranch; ++b) {
    const whirl_branch *br = resp.branch[b];
    for (size_t i = 0; i < br->len; ++i) {
      if (br->pts[i].type != WHIRL_PT_LP) continue;
      double x[4], pp[WHIRL_SFD_NPAR];
      memcpy(x, br->pts[i].x, sizeof x);
      memcpy(pp, br->pts[i].p, sizeof pp);
      whirl_fold_options fo;
      whirl_fold_options_default(&fo, WHIRL_SFD_OMEGA);
      whirl_fold *f = whirl_fold_alloc(s, &fo, NULL, 0);
      double Z[5];
      whirl_fold_init(f, x, pp, Z);
      for (int dir = -1; dir <= 1; dir += 2) {
        whirl_cont_options co;
        whirl_cont_options_default(&co);
        co.icp = WHIRL_SFD_DELTA;
        co.ds = 0.01;
        co.ds_max = 0.05;
        co.nmx = 400;
        co.p_min = 0.3;
        co.p_max = 0.6;
        co.newton_tol = 1e-12;
        co.detect_bp = co.detect_hb = 0;
        whirl_cont *c = whirl_cont_alloc(whirl_fold_system(f), &co, NULL, 0);
        whirl_fold_init(f, x, pp, Z);
        rc = whirl_cont_start(c, Z, pp, dir);
        while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
          const whirl_point *pt = whirl_cont_point(c);
          if (pt->type == WHIRL_PT_MG && nmg++ == 0) {
            mg[0] = hypot(pt->x[0], pt->x[1]);
            mg[1] = pt->x[4];
            mg[2] = pt->p[WHIRL_SFD_DELTA];
          }
          if (pt->type == WHIRL_PT_MG || pt->type == WHIRL_PT_IS)
            printf("# %s on the fold curve from LP at Omega %.6f: delta %.12f Omega %.10f\n",
                   whirl_point_type_name(pt->type), pp[0], pt->p[WHIRL_SFD_DELTA], pt->x[4]);
        }
        whirl_cont_free(c);
      }
      whirl_fold_free(f);
    }
  }
  whirl_sfd_response_free(&resp);
  ok(nmg >= 1, "SFD merge: MG found on a fold curve in (Omega, delta) (%d)", nmg);
  double e = 0.7, W = 5.0, d = 0.4;
  rc = eq15_merge(0.25, 0.0, &e, &W, &d);
  ok(rc == 0, "SFD merge: eq. 15 merge by Newton in (eps, Omega, delta)");
  printf("# eq. 15: eps %.12f Omega %.12f delta %.12f\n", e, W, d);
  is_abs(mg[2], d, 1e-8, "SFD merge: delta* by continuation = eq. 15");
  is_abs(mg[1], W, 1e-6, "SFD merge: Omega* by continuation = eq. 15");
  is_abs(mg[0], e, 1e-6, "SFD merge: eps* by continuation = eq. 15");
  whirl_equilibrium_free(eq);
}

/* whirl_sfd_merge_points against eq. 15 at several (lambda, zeta): the eq.
 * 15 Newton starts 1 % away from whirl's point and must come back to it. */
static void test_merge_points(void) {
  const double lams[] = {0.02, 0.05, 0.25, 1.0};
  for (int z = 0; z < 2; ++z)
    for (size_t i = 0; i < sizeof lams / sizeof *lams; ++i) {
      const double zeta = z ? 0.05 : 0.0;
      whirl_sfd_curve mp;
      char err[256];
      int rc = whirl_sfd_merge_points(lams[i], zeta, &mp, err, sizeof err);
      ok(rc == 0 && mp.len >= 1, "merge points at lambda %g, zeta %g: %zu", lams[i], zeta, mp.len);
      if (mp.len < 1) continue;
      double e = mp.eps[0] * 1.01, W = mp.Omega[0] * 0.99, d = mp.delta[0] * 1.01;
      rc = eq15_merge(lams[i], zeta, &e, &W, &d);
      ok(rc == 0 && fabs(d - mp.delta[0]) < 1e-9 && fabs(W - mp.Omega[0]) < 1e-7 &&
             fabs(e - mp.eps[0]) < 1e-7 && mp.type[0] == WHIRL_PT_MG,
         "merge at lambda %g, zeta %g: delta %.10f Omega %.8f eps %.8f (%s) = eq. 15 "
         "(%.1e, %.1e, %.1e)",
         lams[i], zeta, mp.delta[0], mp.Omega[0], mp.eps[0], whirl_point_type_name(mp.type[0]),
         d - mp.delta[0], W - mp.Omega[0], e - mp.eps[0]);
      whirl_sfd_curve_free(&mp);
    }
}

/* ------------------------------------------------------------------------
 * (h) nesting: the fold system of a harmonic-balance system (fixed-frame
 * periodic orbits, F_E != 0 possible).  At F_E = 0 the HBM fold curve in
 * (Omega, delta) passes the same merge as eq. 15; then the fold is carried
 * to F_E = -0.1 along the fold curve in (Omega, F_E) and the merge is found
 * again, converged in the number of harmonics. */

static whirl_hbm *sfd_hbm(size_t N) {
  whirl_hbm_options ho;
  whirl_hbm_options_default(&ho);
  ho.harmonics = N;
  ho.forcing_param = WHIRL_SFD_OMEGA;
  ho.no_spectrum = 1;
  return whirl_hbm_alloc(whirl_sfd_fixed(), &ho, NULL, 0);
}

/* HBM coefficients of the circular orbit (eps, Omega) of eq. 15. */
static void circular_X(whirl_hbm *h, double eps, const double *p, double *X) {
  const double W = p[WHIRL_SFD_OMEGA];
  double r[4];
  whirl_sfd_circ_state(eps, W, p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA], r);
  enum { M = 64 };
  double x[4 * M];
  for (int k = 0; k < M; ++k) {
    const double th = 2.0 * 3.14159265358979323846 * k / M, c = cos(th), s = sin(th);
    const double y = r[0] * c - r[1] * s, z = r[0] * s + r[1] * c;
    x[4 * k] = y, x[4 * k + 1] = z, x[4 * k + 2] = -W * z, x[4 * k + 3] = W * y;
  }
  whirl_hbm_from_samples(h, x, M, 2.0 * 3.14159265358979323846 / W, X);
}

/* Trace the fold system of sys from Z in parameter icp until the first
 * point of type `type`; its delta, Omega (Z[nx]) and F_E in out[3]. */
static int fold_event(whirl_fold *f, double *Z, double *p, size_t icp, int dir, double pmin,
                      double pmax, int type, double *out, double *Zend) {
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = icp;
  co.ds = 0.005;
  co.ds_max = 0.15;
  co.nmx = 600;
  co.p_min = pmin;
  co.p_max = pmax;
  co.newton_tol = 1e-11;
  co.detect_bp = co.detect_hb = 0;
  const whirl_system *s = whirl_fold_system(f);
  whirl_cont *c = whirl_cont_alloc(s, &co, NULL, 0);
  int rc = whirl_cont_start(c, Z, p, dir), found = 0;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    if ((type && pt->type == type) || (!type && whirl_cont_stop_reason(c) != 0)) found = 1;
    if (!type || found) {
      out[0] = pt->p[WHIRL_SFD_DELTA];
      out[1] = pt->x[s->n - 1];
      out[2] = pt->p[WHIRL_SFD_FE];
      if (Zend) memcpy(Zend, pt->x, s->n * sizeof *Zend);
      if (Zend) memcpy(p, pt->p, s->npar * sizeof *p);
    }
    if (found) break;
  }
  if (!type && rc == WHIRL_DONE) found = 1;
  if (getenv("T_FOLD_DEBUG"))
    printf("# fold_event icp %zu: %zu steps, stop %s, rc %d (%s), last p %.10g\n", icp,
           whirl_cont_get_stats(c)->steps, whirl_stop_reason_name(whirl_cont_stop_reason(c)), rc,
           whirl_cont_errmsg(c), whirl_cont_point(c)->p[icp]);
  whirl_cont_free(c);
  return found ? 0 : -1;
}

static void test_hbm_fold(void) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p); /* Table 1: lambda 0.0503, delta 0.3 */
  whirl_sfd_curve mp;
  whirl_sfd_merge_points(p[WHIRL_SFD_LAMBDA], 0.0, &mp, NULL, 0);
  const double dstar = mp.len ? mp.delta[0] : NAN;
  whirl_sfd_curve_free(&mp);
  double e = 0.91, W = 7.09, mg8[3] = {0}, mg12[3] = {0};
  const int frc = whirl_sfd_circ_fold(&e, &W, p[1], p[2], p[3]);
  ok(frc == 0 && fabs(W - 7.0881196) < 1e-6,
     "HBM fold: the isola fold of Table 1 from eq. 15 (Omega %.10f)", W);
  for (int pass = 0; pass < 2; ++pass) {
    const size_t N = pass ? 12 : 8;
    whirl_hbm *h = sfd_hbm(N);
    const whirl_system *hs = whirl_hbm_system(h);
    const size_t nx = whirl_hbm_size(h);
    double *X = calloc(nx, sizeof *X), *Z = calloc(nx + 1, sizeof *Z);
    double pp[WHIRL_SFD_NPAR];
    memcpy(pp, p, sizeof pp);
    pp[WHIRL_SFD_OMEGA] = W;
    circular_X(h, e, pp, X);
    whirl_fold_options fo;
    whirl_fold_options_default(&fo, WHIRL_SFD_OMEGA);
    whirl_fold *f = whirl_fold_alloc(hs, &fo, NULL, 0);
    ok(f && whirl_fold_init(f, X, pp, Z) == WHIRL_OK, "HBM fold (N = %zu): fold system of the "
       "HBM system started (%zu unknowns)", N, nx + 1);
    double out[3];
    if (pass == 0) {
      int rc = fold_event(f, Z, pp, WHIRL_SFD_DELTA, +1, 0.0, 0.5, WHIRL_PT_MG, out, NULL);
      ok(rc == 0, "HBM fold, F_E = 0: MG on the fold curve in (Omega, delta)");
      is_abs(out[0], dstar, 1e-9, "HBM fold, F_E = 0: merge delta = eq. 15 (%.10f)", out[0]);
      whirl_fold_init(f, X, pp, Z);
    }
    /* carry the fold to F_E = -0.1 (fold curve in (Omega, F_E)) */
    int rc = fold_event(f, Z, pp, WHIRL_SFD_FE, -1, -0.1, 0.1, 0, out, Z);
    ok(rc == 0 && fabs(pp[WHIRL_SFD_FE] + 0.1) < 1e-12,
       "HBM fold (N = %zu): fold carried to F_E = -0.1, Omega %.10f", N, Z[nx]);
    rc = fold_event(f, Z, pp, WHIRL_SFD_DELTA, +1, 0.0, 0.5, WHIRL_PT_MG, pass ? mg12 : mg8, NULL);
    ok(rc == 0, "HBM fold (N = %zu), F_E = -0.1: MG at delta %.10f, Omega %.8f", N,
       (pass ? mg12 : mg8)[0], (pass ? mg12 : mg8)[1]);
    whirl_fold_free(f);
    free(X);
    free(Z);
    whirl_hbm_free(h);
  }
  ok(mg8[0] > 0.2 && fabs(mg8[0] - mg12[0]) < 1e-8 && fabs(mg8[1] - mg12[1]) < 1e-6,
     "HBM fold, F_E = -0.1: the merge is converged in the harmonics (8 vs 12: %.1e in delta)",
     fabs(mg8[0] - mg12[0]));
  ok(mg8[0] > 0.2 && fabs(mg8[0] - dstar) > 1e-6, "HBM fold: F_E = -0.1 moves the merge (by %.2e)",
     mg8[0] - dstar);
}

/* ------------------------------------------------------------------------
 * (g) bad options */

static void test_errors(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&ab);
  const whirl_system *s = whirl_equilibrium_system(eq);
  whirl_fold_options fo;
  char err[256] = "";
  whirl_fold_options_default(&fo, 7);
  ok(whirl_fold_alloc(s, &fo, err, sizeof err) == NULL && strstr(err, "parameter"),
     "fold: a parameter index out of range is refused (%s)", err);
  whirl_fold_options_default(&fo, 0);
  fo.cond = WHIRL_FOLD_COND_MG;
  ok(whirl_fold_alloc(s, &fo, err, sizeof err) == NULL && strstr(err, "two freed"),
     "fold: a condition without a second freed parameter is refused (%s)", err);
  ok(whirl_hopf_alloc(s, 5, err, sizeof err) == NULL, "hopf: bad parameter refused (%s)", err);
  whirl_hopf *h = whirl_hopf_alloc(s, 0, NULL, 0);
  double u[2] = {0.0, 0.0}, p[3] = {0.01, 17.0, AB_BETA}, Z[4];
  ok(whirl_hopf_init(h, u, p, Z) != WHIRL_OK && strlen(whirl_hopf_errmsg(h)) > 0,
     "hopf: start at a point without a complex pair is refused (%s)", whirl_hopf_errmsg(h));
  whirl_hopf_free(h);
  whirl_equilibrium_free(eq);
}

/* A region curve that needs more steps than nmx is a failure with a
 * message, not a curve cut short without a word (the upper curve stopped
 * at 5001 points); a ds_max below the first step (1e-3) works. */
static void test_region_limits(void) {
  whirl_sfd_region_options o;
  whirl_sfd_region_options_default(&o);
  o.nmx = 20;
  whirl_sfd_region r;
  char msg[512] = "";
  int rc = whirl_sfd_region_compute(&o, &r, msg, sizeof msg);
  ok(rc == WHIRL_EMAXITER && strstr(msg, "took 20 steps (nmx)"), "nmx = 20: the cut is a failure (%d): %s",
     rc, msg);
  whirl_sfd_region_free(&r);
  whirl_sfd_region_options_default(&o);
  o.ds_max = 1e-4;
  o.nmx = 100000;
  o.lambda_min = 0.01;
  o.lambda_max = 0.012;
  rc = whirl_sfd_region_compute(&o, &r, msg, sizeof msg);
  ok(rc == WHIRL_OK && !msg[0], "ds_max = 1e-4 works (%d) '%s'", rc, msg);
  whirl_sfd_region_free(&r);
}

/* ------------------------------------------------------------------------
 * The generalised Hopf (Bautin) point: the normal form
 *   z' = (b1 + i) z + b2 z |z|^2 - z |z|^4
 * in x, y has its Hopf curve at b1 = 0 with the first Lyapunov coefficient
 * (Kuznetsov 2004, eq. 3.20, with |q| = 1: the complex coordinate along q
 * is (x + iy)/sqrt 2, so its cubic coefficient is 2 b2) l1 = 2 b2, and the
 * GH at b2 = 0. */
static int bautin_rhs(double t, const double *x, const double *p, double *f, void *d) {
  (void)t, (void)d;
  const double r2 = x[0] * x[0] + x[1] * x[1], g = p[0] + p[1] * r2 - r2 * r2;
  f[0] = g * x[0] - x[1];
  f[1] = x[0] + g * x[1];
  return 0;
}
static const whirl_problem bautin = {
    .name = "bautin", .n = 2, .npar = 2, .rhs = bautin_rhs, .autonomous = 1};

static void test_gh(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&bautin);
  const whirl_system *s = whirl_equilibrium_system(eq);
  whirl_hopf *h = whirl_hopf_alloc(s, 0, NULL, 0);
  double x[2] = {0, 0}, p[2] = {0.0, -0.5}, Z[4], tau[WHIRL_HOPF_NTEST];
  int types[WHIRL_HOPF_NTEST];
  ok(h && whirl_hopf_init(h, x, p, Z) == WHIRL_OK, "Bautin normal form: Hopf system started");
  const whirl_system *hs = whirl_hopf_system(h);
  int rc = hs->test(Z, p, tau, types, hs->data);
  ok(rc == 0 && types[WHIRL_HOPF_TEST_GH] == WHIRL_PT_GH &&
         fabs(tau[WHIRL_HOPF_TEST_GH] + 1.0) < 1e-6,
     "Bautin normal form: first Lyapunov coefficient %.9f = 2 b2 = -1",
     tau[WHIRL_HOPF_TEST_GH]);
  p[1] = -1.0;
  Z[3] = 1.0;
  run r;
  rc = trace(hs, Z, p, 1, +1, 0.05, -1.0, 1.0, 500, NULL, &r);
  ok(rc == 0 && r.ntype[WHIRL_PT_GH] == 1, "Bautin normal form: one GH on the Hopf curve (%d)",
     r.ntype[WHIRL_PT_GH]);
  ok(fabs(r.sp[WHIRL_PT_GH][7]) < 1e-6 && fabs(r.sp[WHIRL_PT_GH][2]) < 1e-9,
     "Bautin normal form: GH at b2 = 0, b1 = 0 (%.2g, %.2g)", r.sp[WHIRL_PT_GH][7],
     r.sp[WHIRL_PT_GH][2]);
  whirl_hopf_free(h);
  whirl_equilibrium_free(eq);
}

/* FitzHugh-Nagumo as AUTO's fhn demo (x' = c (x - x^3/3 + y),
 * y' = -(x - a + b y)/c, b = 0.8): on its Hopf curve x^2 = 1 - b/c^2, and
 * the first Lyapunov coefficient changes sign at x = 1/2 (a = 2/15,
 * c = sqrt(16/15)), where the planar formula of Guckenheimer & Holmes
 * (1983, eq. 3.4.11) in the eigenbasis changes sign too (computed
 * independently with numpy: -1.3e-3 at x = 0.49, +1.3e-3 at 0.51); AUTO's
 * hyper.all reports no GH on this curve (doc/auto-reference.md). */
static int fhn_rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  const double b = 0.8;
  f[0] = p[2] * (u[0] - u[0] * u[0] * u[0] / 3 + u[1]);
  f[1] = -(u[0] - p[0] + b * u[1]) / p[2];
  return 0;
}
static const whirl_problem fhn = {.name = "fhn", .n = 2, .npar = 3, .rhs = fhn_rhs,
                                  .autonomous = 1};

static void test_fhn_gh(void) {
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&fhn);
  const whirl_system *s = whirl_equilibrium_system(eq);
  whirl_hopf *h = whirl_hopf_alloc(s, 0, NULL, 0);
  /* the Hopf point at c = 3: x^2 = 1 - 0.8/9, y = x^3/3 - x, a = x + b y */
  const double c = 3, x0 = sqrt(1 - 0.8 / 9), y0 = x0 * x0 * x0 / 3 - x0;
  double x[2] = {x0, y0}, p[3] = {x0 + 0.8 * y0, 0.8, c}, Z[4];
  ok(h && whirl_hopf_init(h, x, p, Z) == WHIRL_OK, "FHN: Hopf system started at c = 3");
  run r;
  int rc = trace(whirl_hopf_system(h), Z, p, 2, -1, 0.05, 0.95, 3.5, 500, NULL, &r);
  ok(rc == 0 && r.ntype[WHIRL_PT_GH] == 1, "FHN: one GH on the Hopf curve (%d)",
     r.ntype[WHIRL_PT_GH]);
  /* trace()'s sp[.][7] is p[1] (b); the GH's c is its p[2], not kept: check
   * x, y and a */
  ok(fabs(r.sp[WHIRL_PT_GH][0] - 0.5) < 1e-7 && fabs(r.sp[WHIRL_PT_GH][2] - 2.0 / 15.0) < 1e-7,
     "FHN: GH at x = 1/2, a = 2/15 (%.10f, %.10f)", r.sp[WHIRL_PT_GH][0],
     r.sp[WHIRL_PT_GH][2]);
  whirl_hopf_free(h);
  whirl_equilibrium_free(eq);
}

/* A base with only a sparse Jacobian (Fx_sparse, no Fx) and few unknowns
 * takes whirl_fold's dense path, through whirl_system_jacobian, whose
 * scratch must hold the nnz sparse values: the fold's held 2n + 2 (8 for
 * n = 3, nnz 9: a heap overflow, ASan in CI's sanitize stage).  The cusp
 * x^3 - a x - b padded with two linear unknowns, its fold at a = 3 x^2. */
static int cusp3_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * x[0] * x[0] - p[0] * x[0] - p[1] + 0.1 * x[1] * x[2];
  f[1] = x[1] - x[0] - x[2];
  f[2] = x[2] + x[1] - 2.0 * x[0];
  return 0;
}
static int cusp3_Fxs(const double *x, const double *p, double *J, void *d) {
  (void)d;
  /* dense 3 x 3 pattern, column-major */
  J[0] = 3.0 * x[0] * x[0] - p[0], J[1] = -1.0, J[2] = -2.0;
  J[3] = 0.1 * x[2], J[4] = 1.0, J[5] = 1.0;
  J[6] = 0.1 * x[1], J[7] = -1.0, J[8] = 1.0;
  return 0;
}
static void test_sparse_only_base(void) {
  static const int Jp[4] = {0, 3, 6, 9}, Ji[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};
  whirl_system s = {.name = "cusp3", .n = 3, .npar = 2, .F = cusp3_F, .nnz = 9, .Jp = Jp,
                    .Ji = Ji, .Fx_sparse = cusp3_Fxs};
  char err[256];
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 1);
  whirl_fold *f = whirl_fold_alloc(&s, &fo, err, sizeof err);
  /* x2 = 1.5 x0, x1 = 0.5 x0 solve the linear rows; at x0 = 1 the cubic's
   * d/dx0 with the coupling: 3 - a + 0.1 (1.5 * 0.5 + 0.5 * 1.5) = 0 */
  const double x0[3] = {1.0, 1.5, 0.5};
  double p[2] = {3.15, 0.0}, Z[4], F[4];
  p[1] = 1.0 - p[0] + 0.1 * 1.5 * 0.5;
  int rc = f ? whirl_fold_init(f, x0, p, Z) : -1;
  const whirl_system *fs = f ? whirl_fold_system(f) : NULL;
  if (rc == WHIRL_OK) rc = fs->F(Z, p, F, fs->data);
  ok(rc == WHIRL_OK && isfinite(F[3]),
     "fold system of a base with only a sparse Jacobian (n 3, nnz 9) starts and evaluates: %s",
     f ? whirl_fold_errmsg(f) : err);
  whirl_fold_free(f);
}

int main(void) {
  test_region_limits();
  test_cusp();
  test_ab();
  test_bt();
  test_zh();
  test_gh();
  test_fhn_gh();
  test_jacobian();
  test_sfd_merge();
  test_merge_points();
  test_hbm_fold();
  test_errors();
  test_sparse_only_base();
  return done_testing();
}

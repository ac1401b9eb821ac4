/* test/unit/t_sfd.c — the SFD rotor model (rotor/sfd.c) and the
 * circular-orbit solver (rotor/sfd_circular.c): force against the polar
 * form of eq. 8, analytic against finite-difference Jacobians, frame
 * equivalence, contact and argument errors, roots of eq. 15 as equilibria of
 * both frames, the degree drop at ε = δ, and the Ω-folds of Table 1.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/model.h>
#include <whirl/rotor.h>

#include "../tap.h"

#define PI 3.14159265358979323846


static double maxabs(const double *v, size_t n) {
  double m = 0.0;
  for (size_t i = 0; i < n; ++i) m = fmax(m, fabs(v[i]));
  return m;
}

static void random_params(double *p, int with_fe) {
  p[WHIRL_SFD_OMEGA] = tap_urand(0.1, 10.0);
  p[WHIRL_SFD_LAMBDA] = tap_urand(0.01, 1.5);
  p[WHIRL_SFD_DELTA] = tap_urand(0.0, 0.95);
  p[WHIRL_SFD_ZETA] = tap_urand(0.0, 0.1);
  p[WHIRL_SFD_FE] = with_fe ? tap_urand(-0.5, 0.5) : 0.0;
}

/* position of radius eps at a random angle, velocity random in [-2, 2]² */
static void random_state(double eps, double *x) {
  const double th = tap_urand(0.0, 2.0 * PI);
  x[0] = eps * cos(th);
  x[1] = eps * sin(th);
  x[2] = tap_urand(-2.0, 2.0);
  x[3] = tap_urand(-2.0, 2.0);
}

/* ------------------------------------------------------------------------
 * The rotating model with F_E (its last parameter) hidden: it rejects
 * F_E != 0, so finite differences must not perturb it.  The F_E column of
 * jac_p is tested separately (test_frames). */
static int rot4_rhs(double t, const double *x, const double *p, double *f,
                    void *data) {
  (void)data;
  double q[WHIRL_SFD_NPAR];
  memcpy(q, p, 4 * sizeof *q);
  q[WHIRL_SFD_FE] = 0.0;
  return whirl_sfd_rotating()->rhs(t, x, q, f, NULL);
}
static int rot4_jac_x(double t, const double *x, const double *p, double *J,
                      void *data) {
  (void)data;
  double q[WHIRL_SFD_NPAR];
  memcpy(q, p, 4 * sizeof *q);
  q[WHIRL_SFD_FE] = 0.0;
  return whirl_sfd_rotating()->jac_x(t, x, q, J, NULL);
}
static int rot4_jac_p(double t, const double *x, const double *p, double *J,
                      void *data) {
  (void)data;
  double q[WHIRL_SFD_NPAR], Jp[4 * WHIRL_SFD_NPAR];
  memcpy(q, p, 4 * sizeof *q);
  q[WHIRL_SFD_FE] = 0.0;
  int rc = whirl_sfd_rotating()->jac_p(t, x, q, Jp, NULL);
  memcpy(J, Jp, 16 * sizeof *J);
  return rc;
}
static const whirl_problem rot4 = {.name = "rot4",
                                   .n = 4,
                                   .npar = 4,
                                   .rhs = rot4_rhs,
                                   .jac_x = rot4_jac_x,
                                   .jac_p = rot4_jac_p,
                                   .autonomous = 1};

/* ------------------------------------------------------------------------ */

static void test_params(void) {
  double p[WHIRL_SFD_NPAR];
  char msg[128];
  whirl_sfd_default_params(p);
  ok(p[0] == 1.0 && p[1] == 0.0503 && p[2] == 0.3 && p[3] == 0.0 && p[4] == 0.0,
     "default parameters are Table 1 (Omega 1, lambda 0.0503, delta 0.3)");
  ok(whirl_sfd_check_params(p, msg, sizeof msg) == WHIRL_OK && msg[0] == '\0',
     "defaults pass check_params");

  struct {
    int k;
    double v;
    const char *want;
  } bad[] = {
      {WHIRL_SFD_LAMBDA, -1.0, "lambda must be in (0, 100] (got -1)"},
      {WHIRL_SFD_LAMBDA, 0.0, "lambda must be in (0, 100] (got 0)"},
      {WHIRL_SFD_DELTA, -0.25, "delta must be in [0, 10] (got -0.25)"},
      {WHIRL_SFD_ZETA, -0.01, "zeta must be in [0, 10] (got -0.01)"},
      {WHIRL_SFD_OMEGA, -2.0, "Omega must be in [0, 1000] (got -2)"},
      /* out of the physical range (1e308 overflowed every force) */
      {WHIRL_SFD_LAMBDA, 1e308, "lambda must be in (0, 100] (got 1e+308)"},
      {WHIRL_SFD_DELTA, 1e308, "delta must be in [0, 10] (got 1e+308)"},
      {WHIRL_SFD_ZETA, 10.5, "zeta must be in [0, 10] (got 10.5)"},
      {WHIRL_SFD_OMEGA, 1e4, "Omega must be in [0, 1000] (got 10000)"},
      {WHIRL_SFD_FE, 1.0, "FE must be in (-1, 1): a static force |FE| >= 1 puts the journal on the housing (got 1)"},
      {WHIRL_SFD_FE, -1.5, "FE must be in (-1, 1): a static force |FE| >= 1 puts the journal on the housing (got -1.5)"},
      {WHIRL_SFD_LAMBDA, NAN, "lambda must be finite (got nan)"},
      {WHIRL_SFD_FE, INFINITY, "FE must be finite (got inf)"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    whirl_sfd_default_params(p);
    p[bad[i].k] = bad[i].v;
    int rc = whirl_sfd_check_params(p, msg, sizeof msg);
    ok(rc == WHIRL_EINVAL && strcmp(msg, bad[i].want) == 0,
       "check_params: \"%s\" (got rc %d, \"%s\")", bad[i].want, rc, msg);
  }
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_LAMBDA] = -1.0;
  char small[8];
  memset(small, 'x', sizeof small);
  ok(whirl_sfd_check_params(p, small, sizeof small) == WHIRL_EINVAL &&
         small[7] == '\0' && strcmp(small, "lambda ") == 0,
     "check_params truncates to the buffer");
  ok(whirl_sfd_check_params(p, NULL, 0) == WHIRL_EINVAL &&
         whirl_sfd_check_params(NULL, NULL, 0) == WHIRL_EINVAL,
     "check_params accepts NULL msg and rejects NULL p");
  ok(strcmp(whirl_sfd_fixed()->x_names[2], "dy") == 0 &&
         strcmp(whirl_sfd_rotating()->x_names[0], "u") == 0 &&
         strcmp(whirl_sfd_fixed()->p_names[WHIRL_SFD_FE], "FE") == 0 &&
         whirl_sfd_fixed()->n == 4 && whirl_sfd_rotating()->npar == 5 &&
         whirl_sfd_rotating()->autonomous && !whirl_sfd_fixed()->autonomous,
     "model descriptions (names, sizes, autonomy)");
}

/* The force of DESIGN.md in its polar form, for comparison. */
static void polar_force(double y, double z, double vy, double vz, double lam,
                        double *f) {
  const double e = hypot(y, z), s = 1.0 - e * e;
  const double ry = y / e, rz = z / e, ty = -rz, tz = ry;
  const double ed = ry * vy + rz * vz, eg = ty * vy + tz * vz;
  const double fr = -2.0 * lam *
                    (0.5 * PI * (1.0 + 2.0 * e * e) / pow(s, 2.5) * ed +
                     2.0 * e / (s * s) * eg);
  const double ft =
      -2.0 * lam * (2.0 * e / (s * s) * ed + 0.5 * PI / pow(s, 1.5) * eg);
  f[0] = fr * ry + ft * ty;
  f[1] = fr * rz + ft * tz;
}

static void test_force(void) {
  double f[2], J[8], dl[2], g[2];
  const double lam = 0.37, vy = 0.8, vz = -1.3;

  /* ε = 0: f = −πλv exactly, velocity Jacobian −πλ I, position 0 */
  int rc = whirl_sfd_force(0.0, 0.0, vy, vz, lam, f, J, dl);
  ok(rc == 0 && f[0] == -PI * lam * vy && f[1] == -PI * lam * vz,
     "force at eps = 0 is -pi lambda v exactly");
  ok(J[0] == 0 && J[1] == 0 && J[2] == 0 && J[3] == 0 && J[4] == -PI * lam &&
         J[5] == 0 && J[6] == 0 && J[7] == -PI * lam && dl[0] == -PI * vy &&
         dl[1] == -PI * vz,
     "Jacobian at eps = 0: [0 | -pi lambda I], d/dlambda = -pi v");
  rc = whirl_sfd_force(1e-300, 0.0, vy, vz, lam, f, J, NULL);
  ok(rc == 0 && f[0] == -PI * lam * vy && isfinite(J[0]),
     "force at eps = 1e-300 is finite and -pi lambda v");

  /* Cartesian form against the polar form of eq. 8 at random states */
  double err = 0.0, lerr = 0.0;
  for (int i = 0; i < 500; ++i) {
    double x[4];
    const double l = tap_urand(0.01, 1.5);
    random_state(tap_urand(1e-3, 0.97), x);
    whirl_sfd_force(x[0], x[1], x[2], x[3], l, f, NULL, dl);
    polar_force(x[0], x[1], x[2], x[3], l, g);
    const double sc = maxabs(g, 2) + l * maxabs(x + 2, 2);
    err = fmax(err, maxabs((double[]){f[0] - g[0], f[1] - g[1]}, 2) / sc);
    lerr =
        fmax(lerr, fmax(fabs(dl[0] * l - f[0]), fabs(dl[1] * l - f[1])) / sc);
  }
  ok(err < 1e-12, "force equals the polar form of eq. 8 (max rel err %.2e)",
     err);
  ok(lerr < 1e-15, "d f / d lambda = f / lambda (max rel err %.2e)", lerr);

  /* circular orbit: ε' = 0, εγ' = εΩ gives F_r = aΩ, F_t = bΩ (eq. 15) */
  double cerr = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double l = tap_urand(0.01, 1.5), e = tap_urand(0.01, 0.98);
    const double Om = tap_urand(0.05, 20.0), th = tap_urand(0.0, 2.0 * PI);
    const double s = 1.0 - e * e;
    const double a = -4.0 * l * e * e / (s * s), b = -PI * l * e / pow(s, 1.5);
    const double ry = cos(th), rz = sin(th);
    whirl_sfd_force(e * ry, e * rz, -e * Om * rz, e * Om * ry, l, f, NULL,
                    NULL);
    const double Fr = f[0] * ry + f[1] * rz, Ft = -f[0] * rz + f[1] * ry;
    cerr = fmax(cerr, fmax(fabs(Fr - a * Om) / fabs(a * Om),
                           fabs(Ft - b * Om) / fabs(b * Om)));
  }
  ok(cerr < 1e-12,
     "circular orbit: (F_r, F_t) = (a Omega, b Omega) of eq. 15 (max rel err "
     "%.2e)",
     cerr);

  /* rotation equivariance f(Rr, Rv) = R f(r, v) */
  double qerr = 0.0;
  for (int i = 0; i < 100; ++i) {
    double x[4], h[2];
    random_state(tap_urand(0.0, 0.9), x);
    const double c = cos(1.1), sn = sin(1.1);
    whirl_sfd_force(x[0], x[1], x[2], x[3], lam, f, NULL, NULL);
    whirl_sfd_force(c * x[0] - sn * x[1], sn * x[0] + c * x[1],
                    c * x[2] - sn * x[3], sn * x[2] + c * x[3], lam, h, NULL,
                    NULL);
    qerr = fmax(qerr, fmax(fabs(h[0] - (c * f[0] - sn * f[1])),
                           fabs(h[1] - (sn * f[0] + c * f[1]))) /
                          (1.0 + maxabs(f, 2)));
  }
  ok(qerr < 1e-13, "force is rotation-equivariant (max err %.2e)", qerr);
}

static void test_contact_nan(void) {
  double f[4], J[4 * WHIRL_SFD_NPAR], p[WHIRL_SFD_NPAR];
  const whirl_problem *fx = whirl_sfd_fixed(), *rot = whirl_sfd_rotating();
  whirl_sfd_default_params(p);
  const double pos[2][2] = {{1.0, 0.0}, {0.72, 0.96}}; /* ε = 1, 1.2 */
  for (int i = 0; i < 2; ++i) {
    const double x[4] = {pos[i][0], pos[i][1], 0.1, 0.2};
    const double e = hypot(x[0], x[1]);
    ok(whirl_sfd_force(x[0], x[1], x[2], x[3], 0.1, f, NULL, NULL) ==
           WHIRL_SFD_CONTACT,
       "force: contact at eps = %g", e);
    ok(fx->rhs(0.3, x, p, f, NULL) == WHIRL_SFD_CONTACT &&
           fx->jac_x(0.3, x, p, J, NULL) == WHIRL_SFD_CONTACT &&
           fx->jac_p(0.3, x, p, J, NULL) == WHIRL_SFD_CONTACT,
       "fixed frame: contact at eps = %g (rhs, jac_x, jac_p)", e);
    ok(rot->rhs(0.0, x, p, f, NULL) == WHIRL_SFD_CONTACT &&
           rot->jac_x(0.0, x, p, J, NULL) == WHIRL_SFD_CONTACT &&
           rot->jac_p(0.0, x, p, J, NULL) == WHIRL_SFD_CONTACT,
       "rotating frame: contact at eps = %g (rhs, jac_x, jac_p)", e);
  }
  ok(WHIRL_SFD_CONTACT > 0, "WHIRL_SFD_CONTACT is recoverable (> 0)");
  ok(whirl_sfd_force(NAN, 0.0, 0.0, 0.0, 0.1, f, NULL, NULL) == WHIRL_EINVAL &&
         whirl_sfd_force(0.1, 0.0, 0.0, INFINITY, 0.1, f, NULL, NULL) ==
             WHIRL_EINVAL &&
         whirl_sfd_force(0.1, 0.0, 0.0, 0.0, NAN, f, NULL, NULL) ==
             WHIRL_EINVAL &&
         whirl_sfd_force(0.1, 0.0, 0.0, 0.0, 0.1, NULL, NULL, NULL) ==
             WHIRL_EINVAL,
     "force rejects NaN/Inf input and NULL output with WHIRL_EINVAL");
  const double xn[4] = {0.1, NAN, 0.0, 0.0}, x0[4] = {0.1, 0.2, 0.0, 0.0};
  ok(fx->rhs(0.0, xn, p, f, NULL) < 0 && rot->rhs(0.0, xn, p, f, NULL) < 0,
     "NaN state is a fatal error (< 0) in both frames");
  p[WHIRL_SFD_DELTA] = NAN;
  ok(fx->rhs(0.0, x0, p, f, NULL) < 0 && rot->rhs(0.0, x0, p, f, NULL) < 0,
     "NaN parameter is a fatal error (< 0) in both frames");
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_FE] = 0.1;
  ok(rot->rhs(0.0, x0, p, f, NULL) < 0 && rot->jac_x(0.0, x0, p, J, NULL) < 0 &&
         rot->jac_p(0.0, x0, p, J, NULL) < 0,
     "rotating frame rejects F_E != 0 as fatal (< 0)");
  ok(fx->rhs(0.0, x0, p, f, NULL) == 0 && f[3] != 0.0,
     "fixed frame accepts F_E != 0");
}

/* central differences of the force in position with a step h relative to
 * ε (the force has curvature ~ 1/ε near the centre) */
static double small_eps_fd_err(double eps, double lam) {
  double x[4], J[8], fp[2], fm[2];
  double err = 0.0;
  random_state(eps, x);
  whirl_sfd_force(x[0], x[1], x[2], x[3], lam, fp, J, NULL);
  const double h = 1e-2 * eps;
  for (int j = 0; j < 2; ++j) {
    double xp[4], xm[4];
    memcpy(xp, x, sizeof xp);
    memcpy(xm, x, sizeof xm);
    xp[j] += h;
    xm[j] -= h;
    whirl_sfd_force(xp[0], xp[1], xp[2], xp[3], lam, fp, NULL, NULL);
    whirl_sfd_force(xm[0], xm[1], xm[2], xm[3], lam, fm, NULL, NULL);
    for (int i = 0; i < 2; ++i) {
      const double d = (fp[i] - fm[i]) / (xp[j] - xm[j]);
      err = fmax(err, fabs(d - J[i + 2 * j]) / (1.0 + fabs(J[i + 2 * j])));
    }
  }
  return err;
}

/* central differences of a model's jac_x with explicit steps h[4] */
static int fd_jac_h(const whirl_problem *prob, double t, const double *x,
                    const double *p, const double *h, double *J) {
  for (int j = 0; j < 4; ++j) {
    double xp[4], xm[4], fp[4], fm[4];
    memcpy(xp, x, sizeof xp);
    memcpy(xm, x, sizeof xm);
    xp[j] += h[j];
    xm[j] -= h[j];
    int rc = prob->rhs(t, xp, p, fp, NULL);
    if (rc == 0) rc = prob->rhs(t, xm, p, fm, NULL);
    if (rc != 0) return rc;
    for (int i = 0; i < 4; ++i)
      J[i + 4 * j] = (fp[i] - fm[i]) / (xp[j] - xm[j]);
  }
  return 0;
}

/* max |J_a − J_fd| / (1 + |J_a|) of jac_x against fd_jac_h with all steps h */
static double jac_err_h(const whirl_problem *prob, double t, const double *x,
                        const double *p, double h) {
  double Ja[16], Jf[16];
  const double hs[4] = {h, h, h, h};
  if (prob->jac_x(t, x, p, Ja, NULL) != 0 ||
      fd_jac_h(prob, t, x, p, hs, Jf) != 0)
    return INFINITY;
  double err = 0.0;
  for (int i = 0; i < 16; ++i)
    err = fmax(err, fabs(Ja[i] - Jf[i]) / (1.0 + fabs(Ja[i])));
  return err;
}

static void test_jacobians(void) {
  double p[WHIRL_SFD_NPAR], x[4], err, worst;
  int bad;
  const whirl_problem *fx = whirl_sfd_fixed();

  /* Away from the centre: whirl_check_jacobian (h = cbrt(eps) max(1, |x|)).
   * Its O(h²) error grows like (h/ε)² near ε = 0, where the force has
   * curvature ~ 1/ε (see below), so this sweep keeps ε >= 0.02. */
  for (int pass = 0; pass < 2; ++pass) {
    const whirl_problem *prob = pass == 0 ? fx : &rot4;
    const char *name = pass == 0 ? "fixed" : "rotating";
    worst = 0.0;
    bad = 0;
    for (int i = 0; i < 400; ++i) {
      random_params(p, pass == 0);
      random_state(tap_urand(0.02, 0.95), x);
      if (pass == 1) { /* keep the fixed-frame speed V = w' + iΩw moderate */
        x[2] += p[0] * x[1];
        x[3] -= p[0] * x[0];
      }
      const double t = tap_urand(0.0, 10.0);
      if (whirl_check_jacobian(prob, t, x, p, &err) != 0) ++bad;
      worst = fmax(worst, err);
    }
    ok(bad == 0 && worst < 1e-6,
       "%s frame: jac_x, jac_p = finite differences at 400 random states, "
       "0.02 <= eps < 0.95 (max err %.2e)",
       name, worst);
  }

  /* ε = 0 exactly with a moving journal.  Fixed frame: whirl_check_jacobian.
   * Both frames: steps h = 1e-8 as well, because in the rotating frame the
   * velocity V = w' + iΩw moves with the position and the cross term
   * ~ ε·V becomes ~ u|u|, whose central difference has an O(h) error. */
  random_params(p, 1);
  x[0] = x[1] = 0.0;
  x[2] = 0.7;
  x[3] = -0.4;
  int rc = whirl_check_jacobian(fx, 1.3, x, p, &err);
  ok(rc == 0 && err < 1e-6,
     "fixed frame: whirl_check_jacobian at eps = 0 "
     "exactly (err %.2e)",
     err);
  err = jac_err_h(fx, 1.3, x, p, 1e-8);
  ok(err < 1e-6,
     "fixed frame: jac_x at eps = 0 = differences, h = 1e-8 (err %.2e)", err);
  p[WHIRL_SFD_FE] = 0.0;
  err = jac_err_h(&rot4, 1.3, x, p, 1e-8);
  ok(err < 1e-6,
     "rotating frame: jac_x at eps = 0 = differences, h = 1e-8 "
     "(err %.2e)",
     err);
  rc = whirl_check_jacobian(&rot4, 1.3, x, p, &err);
  ok(rc == 0 && err < 1e-4,
     "rotating frame: whirl_check_jacobian at eps = 0 "
     "within its O(h) error (err %.2e)",
     err);

  /* ε = 1e-9 with the journal at rest (zero initial conditions) */
  random_params(p, 1);
  x[0] = 0.6e-9;
  x[1] = -0.8e-9;
  x[2] = x[3] = 0.0;
  rc = whirl_check_jacobian(fx, 0.4, x, p, &err);
  ok(rc == 0 && err < 1e-6,
     "fixed frame: whirl_check_jacobian at eps = 1e-9, journal at rest "
     "(err %.2e)",
     err);
  p[WHIRL_SFD_FE] = 0.0;
  err = jac_err_h(&rot4, 0.4, x, p, 1e-11);
  ok(err < 1e-4,
     "rotating frame: jac_x at eps = 1e-9 = differences, h = 1e-11 "
     "(err %.2e)",
     err);

  /* Near the centre, with the journal moving, the π-film cross term
   * (size 4λε|v|, direction-dependent through 2γ) makes f Lipschitz but not
   * differentiable at ε = 0.  Steps h = cbrt(eps) ≫ ε straddle that kink, so
   * the check uses steps proportional to ε instead (error ~ 1e-4 from the
   * step, ~ 1e-5 from rounding; a wrong Jacobian is off by ~ λ|v|). */
  const double es[4] = {1e-9, 1e-6, 1e-3, 1e-2};
  for (int k = 0; k < 4; ++k) {
    worst = 0.0;
    for (int i = 0; i < 20; ++i)
      worst = fmax(worst, small_eps_fd_err(es[k], tap_urand(0.2, 1.5)));
    ok(worst < 1e-3,
       "force position Jacobian at eps = %g = differences with h = eps/100 "
       "(max err %.2e)",
       es[k], worst);
  }
  {
    /* the kink itself: one-sided slopes of f_y along r = (y, 0), v = (0, 1)
     * are ∓4λ; the value returned at ε = 0 is their mean, 0 */
    double fp[2], fm[2], f0[2], J[8];
    const double lam = 0.5, h = 1e-7;
    whirl_sfd_force(h, 0.0, 0.0, 1.0, lam, fp, NULL, NULL);
    whirl_sfd_force(-h, 0.0, 0.0, 1.0, lam, fm, NULL, NULL);
    whirl_sfd_force(0.0, 0.0, 0.0, 1.0, lam, f0, J, NULL);
    const double right = (fp[0] - f0[0]) / h, left = (f0[0] - fm[0]) / h;
    ok(fabs(right + 4.0 * lam) < 1e-6 && fabs(left - 4.0 * lam) < 1e-6 &&
           J[0] == 0.0 && fabs(0.5 * (left + right)) < 1e-6,
       "non-differentiable at eps = 0: one-sided slopes %.6f, %.6f; J_yy = %g",
       right, left, J[0]);
  }
}

/* The rotating frame is the fixed frame seen from y + iz = w e^{iΩτ}:
 * with W = w e^{iΩτ}, W' = (w' + iΩw) e^{iΩτ},
 * W'' = (w'' + 2iΩw' − Ω²w) e^{iΩτ}. */
static void test_frames(void) {
  const whirl_problem *fx = whirl_sfd_fixed(), *rot = whirl_sfd_rotating();
  double err = 0.0, ferr = 0.0;
  for (int i = 0; i < 200; ++i) {
    double p[WHIRL_SFD_NPAR], x[4], X[4], fr[4], ff[4];
    double Jr[4 * WHIRL_SFD_NPAR], Jf[4 * WHIRL_SFD_NPAR];
    random_params(p, 0);
    random_state(tap_urand(0.0, 0.9), x);
    const double Om = p[0], t = tap_urand(0.0, 20.0), c = cos(Om * t),
                 s = sin(Om * t);
    const double Vu = x[2] - Om * x[1], Vv = x[3] + Om * x[0];
    X[0] = c * x[0] - s * x[1];
    X[1] = s * x[0] + c * x[1];
    X[2] = c * Vu - s * Vv;
    X[3] = s * Vu + c * Vv;
    if (rot->rhs(0.0, x, p, fr, NULL) != 0 || fx->rhs(t, X, p, ff, NULL) != 0) {
      err = INFINITY;
      continue;
    }
    const double au = fr[2] - 2.0 * Om * x[3] - Om * Om * x[0];
    const double av = fr[3] + 2.0 * Om * x[2] - Om * Om * x[1];
    const double Au = c * au - s * av, Av = s * au + c * av;
    const double sc = 1.0 + maxabs(ff, 4) + p[2] * Om * Om;
    err = fmax(err, fmax(fabs(Au - ff[2]), fabs(Av - ff[3])) / sc);
    err = fmax(err, fmax(fabs(X[2] - ff[0]), fabs(X[3] - ff[1])) / sc);
    /* d/dF_E: fixed frame (0, 1) in the z equation, i.e. i e^{−iΩτ} in the
     * rotating frame */
    rot->jac_p(t, x, p, Jr, NULL);
    fx->jac_p(t, X, p, Jf, NULL);
    const double gu = Jr[2 + 4 * WHIRL_SFD_FE], gv = Jr[3 + 4 * WHIRL_SFD_FE];
    ferr = fmax(ferr, fmax(fabs(c * gu - s * gv - Jf[2 + 4 * WHIRL_SFD_FE]),
                           fabs(s * gu + c * gv - Jf[3 + 4 * WHIRL_SFD_FE])));
  }
  ok(err < 1e-13,
     "rotating-frame rhs = fixed-frame rhs in rotating coordinates "
     "(max rel err %.2e)",
     err);
  ok(ferr < 1e-14,
     "rotating jac_p F_E column = fixed-frame one rotated "
     "(max err %.2e)",
     ferr);
}

/* ------------------------------------------------------------------------
 * Circular orbits (eqs. 15–17) */

/* Eq. 15 as printed, with F_r, F_t taken from whirl_sfd_force. */
static double eq15_direct(double e, double Om, double lam, double de,
                          double ze) {
  double f[2];
  whirl_sfd_force(e, 0.0, 0.0, e * Om, lam, f, NULL, NULL);
  const double Fr = f[0], Ft = f[1];
  return (e * e - de * de) * pow(Om, 4) +
         (4.0 * ze * ze * e * e - 2.0 * e * e + 2.0 * e * Fr) * Om * Om -
         4.0 * ze * e * Ft * Om + e * e - 2.0 * e * Fr + Fr * Fr + Ft * Ft;
}

static double G_scale(double e, double Om, double lam, double de, double ze) {
  double c[5], s = 0.0;
  whirl_sfd_circ_coeffs(e, lam, de, ze, c);
  for (int k = 4; k >= 0; --k) s = s * fabs(Om) + fabs(c[k]);
  return s;
}

/* residual of the circular orbit (ε, Ω) as an equilibrium of the rotating
 * frame and as a solution x' = f(τ, x) of the fixed frame at a few τ */
static void orbit_residuals(double e, double Om, const double *p, double *rrot,
                            double *rfix) {
  double x[4], f[4], fd[2];
  whirl_sfd_circ_state(e, Om, p[1], p[2], p[3], x);
  whirl_sfd_force(e, 0.0, 0.0, e * Om, p[1], fd, NULL, NULL);
  const double sc = 1.0 + p[2] * Om * Om + (1.0 + Om * Om) * e + maxabs(fd, 2);
  *rrot = *rfix = INFINITY;
  if (whirl_sfd_rotating()->rhs(0.0, x, p, f, NULL) != 0) return;
  *rrot = maxabs(f, 4) / sc;
  *rfix = 0.0;
  const double taus[3] = {0.0, 0.77, 5.3};
  for (int k = 0; k < 3; ++k) {
    const double c = cos(Om * taus[k]), s = sin(Om * taus[k]);
    const double Y = c * x[0] - s * x[1], Z = s * x[0] + c * x[1];
    const double X[4] = {Y, Z, -Om * Z, Om * Y};
    const double want[4] = {-Om * Z, Om * Y, -Om * Om * Y, -Om * Om * Z};
    if (whirl_sfd_fixed()->rhs(taus[k], X, p, f, NULL) != 0) {
      *rfix = INFINITY;
      return;
    }
    for (int i = 0; i < 4; ++i) *rfix = fmax(*rfix, fabs(f[i] - want[i]) / sc);
  }
}

static void test_circular(void) {
  double c[5], G, Ge, GO;

  /* coefficients and G against eq. 15 as printed; derivatives against
   * central differences */
  double cerr = 0.0, derr = 0.0;
  for (int i = 0; i < 300; ++i) {
    const double lam = tap_urand(0.01, 1.5), de = tap_urand(0.05, 0.95);
    const double ze = tap_urand(0.0, 0.1), e = tap_urand(0.01, 0.95),
                 Om = tap_urand(0.1, 20.0);
    whirl_sfd_circ_G(e, Om, lam, de, ze, &G, &Ge, &GO);
    const double sc = G_scale(e, Om, lam, de, ze);
    cerr = fmax(cerr, fabs(G - eq15_direct(e, Om, lam, de, ze)) / sc);
    /* fourth-order central differences; G has (1 − ε²)^{-4} in it, so the
     * ε step is scaled by the distance to the wall too */
    const double he = 1e-4 * fmin(e, 1.0 - e), hO = 1e-4 * Om;
    double g[4];
    for (int k = 0; k < 4; ++k) {
      const double m = k < 2 ? k + 1.0 : -(k - 1.0); /* 1, 2, -1, -2 */
      whirl_sfd_circ_G(e + m * he, Om, lam, de, ze, &g[k], NULL, NULL);
    }
    derr =
        fmax(derr, fabs((8 * (g[0] - g[2]) - (g[1] - g[3])) / (12 * he) - Ge) /
                       (sc / e));
    for (int k = 0; k < 4; ++k) {
      const double m = k < 2 ? k + 1.0 : -(k - 1.0);
      whirl_sfd_circ_G(e, Om + m * hO, lam, de, ze, &g[k], NULL, NULL);
    }
    derr =
        fmax(derr, fabs((8 * (g[0] - g[2]) - (g[1] - g[3])) / (12 * hO) - GO) /
                       (sc / Om));
  }
  ok(cerr < 1e-13,
     "circ_G = eq. 15 with the force of whirl_sfd_force "
     "(max rel err %.2e)",
     cerr);
  ok(derr < 1e-8, "G_eps, G_Omega = central differences (max rel err %.2e)",
     derr);

  /* random parameters: every root solves eq. 15, is an equilibrium of the
   * rotating frame and a solution of the fixed frame; no root is missed */
  double gmax = 0.0, rmax = 0.0, fmaxr = 0.0;
  int missed = 0, bad = 0, nroot_total = 0, ncase = 0;
  for (int i = 0; i < 300; ++i) {
    double p[WHIRL_SFD_NPAR], Om[4];
    int nr;
    p[1] = tap_urand(0.01, 1.5);
    p[2] = tap_urand(0.05, 0.95);
    p[3] = tap_urand(0.0, 0.1);
    p[4] = 0.0;
    const double e = tap_urand(0.01, 0.98);
    if (whirl_sfd_circ_roots(e, p[1], p[2], p[3], Om, &nr) != 0) {
      ++bad;
      continue;
    }
    ++ncase;
    nroot_total += nr;
    for (int k = 0; k < nr; ++k) {
      if (k > 0 && !(Om[k] > Om[k - 1])) ++bad;
      whirl_sfd_circ_G(e, Om[k], p[1], p[2], p[3], &G, NULL, NULL);
      gmax = fmax(gmax, fabs(G) / G_scale(e, Om[k], p[1], p[2], p[3]));
      p[0] = Om[k];
      double rr, rf;
      orbit_residuals(e, Om[k], p, &rr, &rf);
      rmax = fmax(rmax, rr);
      fmaxr = fmax(fmaxr, rf);
    }
    /* sign changes of G on a log grid must each bracket a returned root */
    const double top = fmax(1e4, nr > 0 ? 4.0 * Om[nr - 1] : 0.0);
    double prev = 0.0, wprev = 0.0;
    for (int k = 0; k <= 4000; ++k) {
      const double w = 1e-3 * pow(top / 1e-3, k / 4000.0);
      whirl_sfd_circ_G(e, w, p[1], p[2], p[3], &G, NULL, NULL);
      if (k > 0 && ((G > 0) != (prev > 0)) && G != 0.0) {
        int found = 0;
        for (int q = 0; q < nr; ++q) found |= Om[q] >= wprev && Om[q] <= w;
        if (!found) ++missed;
      }
      prev = G;
      wprev = w;
    }
  }
  ok(bad == 0, "circ_roots succeeds and sorts ascending (%d cases, %d roots)",
     ncase, nroot_total);
  ok(gmax < 1e-12, "every root gives G = 0 (max |G|/scale %.2e)", gmax);
  ok(rmax < 1e-10,
     "circ_state is an equilibrium of the rotating frame "
     "(max scaled |rhs| %.2e)",
     rmax);
  ok(fmaxr < 1e-10,
     "the circular orbit solves the fixed-frame model "
     "(max scaled residual %.2e)",
     fmaxr);
  ok(missed == 0, "no sign change of G on a log grid is missed (%d)", missed);

  /* the phase of eqs. 16–17 */
  {
    const double lam = 0.0503, de = 0.3, ze = 0.05, e = 0.2;
    double Om[4];
    int nr;
    whirl_sfd_circ_roots(e, lam, de, ze, Om, &nr);
    const double b = whirl_sfd_circ_phase(e, Om[0], lam, de, ze);
    double f[2];
    whirl_sfd_force(e, 0.0, 0.0, e * Om[0], lam, f, NULL, NULL);
    const double d2 = de * Om[0] * Om[0];
    ok(nr >= 1 &&
           fabs(d2 * cos(b) - (e - e * Om[0] * Om[0] - f[0])) <
               1e-12 * (1 + d2) &&
           fabs(d2 * sin(b) - (2 * ze * e * Om[0] - f[1])) < 1e-12 * (1 + d2),
       "phase satisfies eqs. 16-17 (beta = %.6f at Omega = %.6f)", b, Om[0]);
  }

  /* degree drop: ε = δ makes c4 = 0 exactly; the largest root of the
   * neighbouring quartics goes to +∞ for ε > δ and −∞ for ε < δ */
  {
    const double lam = 0.25, de = 0.3, ze = 0.02;
    double R0[4], Rp[4], Rm[4];
    int n0, np, nm;
    whirl_sfd_circ_coeffs(de, lam, de, ze, c);
    int rc = whirl_sfd_circ_roots(de, lam, de, ze, R0, &n0);
    whirl_sfd_circ_roots(de * (1 + 1e-7), lam, de, ze, Rp, &np);
    whirl_sfd_circ_roots(de * (1 - 1e-7), lam, de, ze, Rm, &nm);
    int same = rc == 0 && c[4] == 0.0 && np == n0 + 1 && nm == n0;
    for (int k = 0; same && k < n0; ++k)
      same = fabs(Rp[k] - R0[k]) < 1e-5 * R0[k] &&
             fabs(Rm[k] - R0[k]) < 1e-5 * R0[k];
    double gm = 0.0;
    for (int k = 0; k < n0; ++k) {
      whirl_sfd_circ_G(de, R0[k], lam, de, ze, &G, NULL, NULL);
      gm = fmax(gm, fabs(G) / G_scale(de, R0[k], lam, de, ze));
    }
    ok(same && gm<1e-13,
                  "eps = delta: cubic with %d positive roots, limits of the "
                  "quartic from "
                  "both sides (+1 huge root %.3g above), |G| %.1e",
                  n0, np>
                   n0
           ? Rp[np - 1]
           : 0.0,
       gm);
  }

  /* argument errors */
  double R[4];
  int nr;
  ok(whirl_sfd_circ_roots(1.0, 0.1, 0.3, 0.0, R, &nr) == WHIRL_EDOMAIN &&
         whirl_sfd_circ_roots(NAN, 0.1, 0.3, 0.0, R, &nr) == WHIRL_EINVAL &&
         whirl_sfd_circ_roots(0.5, -0.1, 0.3, 0.0, R, &nr) == WHIRL_EINVAL &&
         whirl_sfd_circ_roots(0.5, 0.1, 0.3, 0.0, NULL, &nr) == WHIRL_EINVAL &&
         whirl_sfd_circ_G(0.5, NAN, 0.1, 0.3, 0.0, &G, NULL, NULL) ==
             WHIRL_EINVAL &&
         whirl_sfd_circ_coeffs(1.5, 0.1, 0.3, 0.0, c) == WHIRL_EDOMAIN &&
         isnan(whirl_sfd_circ_phase(1.0, 1.0, 0.1, 0.3, 0.0)),
     "circular solver rejects eps >= 1 (EDOMAIN), NaN and negative arguments");
}

/* Ω-folds of eq. 15 (G = G_ε = 0).  Along the solution curve of eq. 15
 * parametrised by ε, Ω(ε) has dΩ/dε = −G_ε/G_Ω, and an Ω-fold is an extremum
 * of Ω(ε).  (Where the number of roots in Ω changes with ε instead, G_Ω = 0:
 * an extremum of ε, e.g. the top of the resonance peak, not an Ω-fold.)  So
 * scan ε, follow each root while the root count stays the same, and refine
 * every sign change of dΩ/dε with whirl_sfd_circ_fold.  Returns the number
 * of folds with 0 < Ω <= omax, written to fe[], fo[] (up to 16), or -1. */
static int find_folds(double lam, double de, double ze, double omax, double *fe,
                      double *fo, double *worst_res) {
  const int N = 20000;
  double prevs[4] = {0};
  int prevn = -1, nf = 0;
  *worst_res = 0.0;
  for (int i = 1; i < N; ++i) {
    const double e = (double)i / N;
    double R[4], sg[4];
    int n;
    if (whirl_sfd_circ_roots(e, lam, de, ze, R, &n) != 0) return -1;
    for (int k = 0; k < n; ++k) {
      double Ge, GO;
      whirl_sfd_circ_G(e, R[k], lam, de, ze, NULL, &Ge, &GO);
      sg[k] = -Ge / GO;
    }
    for (int k = 0; n == prevn && k < n; ++k) {
      if ((sg[k] > 0.0) == (prevs[k] > 0.0)) continue;
      double e1 = e, w1 = R[k];
      if (whirl_sfd_circ_fold(&e1, &w1, lam, de, ze) != WHIRL_OK) return -1;
      if (!(w1 > 0.0 && w1 <= omax) || nf >= 16) continue;
      double G, Ge;
      whirl_sfd_circ_G(e1, w1, lam, de, ze, &G, &Ge, NULL);
      const double sc = G_scale(e1, w1, lam, de, ze);
      *worst_res = fmax(*worst_res, fmax(fabs(G) / sc, fabs(Ge) * e1 / sc));
      fe[nf] = e1;
      fo[nf] = w1;
      ++nf;
    }
    memcpy(prevs, sg, sizeof sg);
    prevn = n;
  }
  return nf;
}

static void test_folds(void) {
  double fe[16], fo[16], res;
  int nf = find_folds(0.0503, 0.3, 0.0, 20.0, fe, fo, &res);
  for (int k = 0; k < nf; ++k)
    printf("# Table 1 fold %d: Omega = %.12g  eps = %.12g\n", k + 1, fo[k],
           fe[k]);
  /* reference: the same system solved by mpmath at 40 digits */
  const double ref[3] = {1.66619771686312, 1.88557959956546, 7.08811962886324};
  int match = nf == 3;
  for (int k = 0; match && k < 3; ++k)
    match = fabs(fo[k] - ref[k]) < 1e-12 * ref[k];
  ok(match && res<1e-12,
                  "Table 1: three Omega-folds below 20 (B: %.6f, %.6f; isola: "
                  "%.6f), "
                  "G = G_eps = 0 (max scaled residual %.1e)",
                  nf> 0
         ? fo[0]
         : 0.0,
     nf > 1 ? fo[1] : 0.0, nf > 2 ? fo[2] : 0.0, res);
  if (nf >= 1) {
    double e = fe[nf - 1], w = fo[nf - 1];
    double e2 = e * (1 + 1e-3), w2 = w * (1 - 1e-3);
    int rc = whirl_sfd_circ_fold(&e2, &w2, 0.0503, 0.3, 0.0);
    ok(rc == 0 && fabs(e2 - e) <= 1e-13 * e && fabs(w2 - w) <= 1e-13 * w,
       "fold solver converges to the same fold from a perturbed guess");
  }

  /* λ = 0.25 (paper Fig. 6): the isola is born at ever lower Ω as δ grows
   * and has merged with the resonance peak by δ = 0.417315 */
  const double deltas[5] = {0.2, 0.3, 0.4, 0.417315, 0.45};
  const int want[5] = {0, 0, 1, 1, 1};
  for (int k = 0; k < 5; ++k) {
    nf = find_folds(0.25, deltas[k], 0.0, 20.0, fe, fo, &res);
    for (int q = 0; q < nf; ++q)
      printf("# lambda 0.25 delta %g fold: Omega = %.12g  eps = %.12g\n",
             deltas[k], fo[q], fe[q]);
    ok(nf == want[k] && res < 1e-12,
       "lambda 0.25, delta %g: %d Omega-fold(s) below 20", deltas[k], nf);
  }

  double e = 1.5, w = 2.0;
  int rc1 = whirl_sfd_circ_fold(&e, &w, 0.0503, 0.3, 0.0);
  e = -0.5;
  int rc2 = whirl_sfd_circ_fold(&e, &w, 0.0503, 0.3, 0.0);
  e = NAN;
  int rc3 = whirl_sfd_circ_fold(&e, &w, 0.0503, 0.3, 0.0);
  e = 0.5;
  ok(rc1 == WHIRL_ENOCONV && rc2 == WHIRL_ENOCONV && rc3 == WHIRL_EINVAL &&
         whirl_sfd_circ_fold(NULL, &w, 0.0503, 0.3, 0.0) == WHIRL_EINVAL &&
         whirl_sfd_circ_fold(&e, &w, -1.0, 0.3, 0.0) == WHIRL_EINVAL,
     "fold solver: ENOCONV outside 0 < eps < 1, EINVAL for NULL/NaN/bad "
     "lambda");
}

/* ------------------------------------------------------------------------
 * Finite-difference helpers on a problem with a known Jacobian and on
 * misbehaving callbacks. */
static int lin_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)data;
  f[0] = p[0] * x[0] * x[1] + sin(t);
  f[1] = x[0] * x[0] * x[0] - p[1] * x[1];
  return 0;
}
static int lin_jac_x(double t, const double *x, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)data;
  J[0] = p[0] * x[1];
  J[1] = 3.0 * x[0] * x[0];
  J[2] = p[0] * x[0];
  J[3] = -p[1];
  return 0;
}
static int nan_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t;
  (void)p;
  (void)data;
  f[0] = x[0] > 1.0 ? NAN : 0.0;
  f[1] = 0.0;
  return 0;
}
static int three_rhs(double t, const double *x, const double *p, double *f,
                     void *data) {
  (void)t;
  (void)x;
  (void)p;
  (void)data;
  f[0] = f[1] = 0.0;
  return 3;
}

static void test_fd_helpers(void) {
  whirl_problem lin = {
      .name = "lin", .n = 2, .npar = 2, .rhs = lin_rhs, .jac_x = lin_jac_x};
  const double x[2] = {1.5, -0.5}, p[2] = {2.0, 0.3};
  double J[4], Jp[4], work[4], err;
  int rc = whirl_fd_jac_x(&lin, 0.2, x, p, J, work);
  ok(rc == 0 && fabs(J[0] - p[0] * x[1]) < 1e-9 &&
         fabs(J[1] - 3 * x[0] * x[0]) < 1e-9 &&
         fabs(J[2] - p[0] * x[0]) < 1e-9 && fabs(J[3] + p[1]) < 1e-9,
     "whirl_fd_jac_x on a polynomial field");
  rc = whirl_fd_jac_p(&lin, 0.2, x, p, Jp, work);
  ok(rc == 0 && fabs(Jp[0] - x[0] * x[1]) < 1e-9 && fabs(Jp[1]) < 1e-12 &&
         fabs(Jp[2]) < 1e-12 && fabs(Jp[3] + x[1]) < 1e-9,
     "whirl_fd_jac_p on a polynomial field");
  rc = whirl_check_jacobian(&lin, 0.2, x, p, &err);
  ok(rc == 0 && err < 1e-9, "whirl_check_jacobian: correct jac_x (err %.1e)",
     err);
  lin.jac_x = NULL;
  ok(whirl_check_jacobian(&lin, 0.2, x, p, &err) == WHIRL_EINVAL && isnan(err),
     "whirl_check_jacobian: EINVAL without Jacobians");
  whirl_problem nanp = {.name = "nan", .n = 2, .npar = 2, .rhs = nan_rhs};
  const double xa[2] = {1.0, 0.0};
  ok(whirl_fd_jac_x(&nanp, 0.0, xa, p, J, work) == WHIRL_EBADFUNC,
     "whirl_fd_jac_x: non-finite rhs gives WHIRL_EBADFUNC");
  whirl_problem thr = {.name = "three", .n = 2, .npar = 2, .rhs = three_rhs};
  ok(whirl_fd_jac_x(&thr, 0.0, xa, p, J, work) == 3 &&
         whirl_fd_jac_p(&thr, 0.0, xa, p, J, work) == 3,
     "whirl_fd_jac_x/_p pass the callback status on");
}

/* |F_E| >= 1 presses the journal onto the housing: the fixed-frame model
 * reports contact (recoverable) for every state, so that `whirl run` with
 * FE = 1.5 stops at once instead of integrating along the housing for
 * minutes; the built-in model's parameter check refuses it up front. */
static void test_fe_domain(void) {
  const whirl_problem *fx = whirl_sfd_fixed();
  double p[WHIRL_SFD_NPAR], x[4] = {0.1, 0.0, 0.0, 0.0}, f[4], J[4 * WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_FE] = 1.5;
  ok(fx->rhs(0.0, x, p, f, NULL) == WHIRL_SFD_CONTACT, "rhs with FE = 1.5: contact");
  ok(fx->jac_x(0.0, x, p, J, NULL) == WHIRL_SFD_CONTACT &&
         fx->jac_p(0.0, x, p, J, NULL) == WHIRL_SFD_CONTACT,
     "jac_x, jac_p with FE = 1.5: contact");
  p[WHIRL_SFD_FE] = -1.0;
  ok(fx->rhs(0.0, x, p, f, NULL) == WHIRL_SFD_CONTACT, "rhs with FE = -1: contact");
  p[WHIRL_SFD_FE] = 0.999;
  ok(fx->rhs(0.0, x, p, f, NULL) == WHIRL_OK, "rhs with FE = 0.999: fine");
  char msg[256];
  p[WHIRL_SFD_FE] = 1.5;
  whirl_model_registry *reg = whirl_model_registry_alloc();
  const int rc = reg ? whirl_rotor_register_models(reg, msg, sizeof msg) : WHIRL_ENOMEM;
  ok(rc == WHIRL_OK && whirl_model_registry_count(reg) == 3 &&
         !strcmp(whirl_model_registry_name(reg, 1), "sfd-rotating") &&
         whirl_model_registry_find(reg, "jeffcott") &&
         whirl_model_registry_find(reg, "jeffcott")->problem.n == 8,
     "the rotor module registers its models (%zu: %s, %s, %s)",
     whirl_model_registry_count(reg), whirl_model_registry_name(reg, 0),
     whirl_model_registry_name(reg, 1), whirl_model_registry_name(reg, 2));
  const whirl_model *sfd = whirl_model_registry_find(reg, "sfd");
  ok(whirl_model_check_params(sfd, p, msg, sizeof msg) == WHIRL_EINVAL &&
         strstr(msg, "FE must be in (-1, 1)"),
     "registered model 'sfd' refuses FE = 1.5: %s", msg);
  p[WHIRL_SFD_FE] = 0.5;
  ok(whirl_model_check_params(sfd, p, msg, sizeof msg) == WHIRL_OK,
     "and accepts FE = 0.5");
  ok(whirl_rotor_register_models(reg, msg, sizeof msg) == WHIRL_EINVAL &&
         strstr(msg, "registered already"),
     "a name is registered once: %s", msg);
  /* the state's scales (ABI 3): the clearance for the rotor models, and a
   * scale that is not positive is refused */
  ok(sfd->scale && sfd->scale[0] == 1.0 && whirl_model_check(sfd, msg, sizeof msg) == WHIRL_OK,
     "model 'sfd' has its scales (the clearance)");
  whirl_model bad = *sfd;
  const double zero[4] = {1.0, 0.0, 1.0, 1.0};
  bad.scale = zero;
  ok(whirl_model_check(&bad, msg, sizeof msg) == WHIRL_EINVAL && strstr(msg, "scale[1]"),
     "a zero scale is refused: %s", msg);
  whirl_model_registry_free(reg);
}

int main(void) {
  test_fe_domain();
  test_params();
  test_force();
  test_contact_nan();
  test_jacobians();
  test_frames();
  test_circular();
  test_folds();
  test_fd_helpers();
  return done_testing();
}

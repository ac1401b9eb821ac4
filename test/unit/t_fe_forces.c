/* test/unit/t_fe_forces.c — the nonlinear element forces of FE rotors
 * (rotor/fe_forces*.c, whirl_fe_nl_force) against independent references:
 * the textbook closed forms on circular centred orbits (Vance 1988, San
 * Andrés), the paper's nondimensional force (rotor/sfd.c) times its
 * scaling, the short-bearing static eccentricity and attitude angle and
 * its classical stiffness and damping coefficients, a brute-force
 * quadrature of the short-bearing pressure, a finite-difference solution of
 * the long-bearing Reynolds equation, hand computations
 * for the rub and the cubic spring, and central finite differences for
 * every analytic Jacobian.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <whirl/rotor.h>
#include <whirl/rotor/fe.h>

#include "../tap.h"

#define PI 3.14159265358979323846

/* A typical damper (any values do): R = 50 mm, L = 20 mm, c = 100 µm,
 * μ = 0.03 Pa·s (the paper's oil), ρ = 860 kg/m³. */
static whirl_fe_nl film(whirl_fe_nl_kind kind) {
  whirl_fe_nl e;
  memset(&e, 0, sizeof e);
  e.kind = kind;
  e.pedestal = -1;
  e.par.radius = 0.05;
  e.par.length = 0.02;
  e.par.clearance = 1e-4;
  e.par.viscosity = 0.03;
  e.par.density = 860.0;
  return e;
}

static double force_scale(const whirl_fe_nl *e) { /* μ R L³ / c² */
  const whirl_fe_nl_params *p = &e->par;
  return p->viscosity * p->radius * pow(p->length, 3) /
         (p->clearance * p->clearance);
}

/* radial and tangential components of f at r (t̂ = ẑ × r̂) */
static void polar(const double r[2], const double f[2], double *fr,
                  double *ft) {
  const double e = hypot(r[0], r[1]), ry = r[0] / e, rz = r[1] / e;
  *fr = f[0] * ry + f[1] * rz;
  *ft = -f[0] * rz + f[1] * ry;
}

/* circular centred orbit at phase psi: r = e(cos ψ, sin ψ), v = eω t̂ */
static void orbit(double e, double w, double psi, double r[2], double v[2]) {
  r[0] = e * cos(psi);
  r[1] = e * sin(psi);
  v[0] = -e * w * sin(psi);
  v[1] = e * w * cos(psi);
}

/* ------------------------------------------------------------------------
 * Brute-force quadrature of the short-bearing film force:
 *   f = −μRL³ ∫ P(φ) n dφ,  P = (w·n)/h³,  h = c − r·n,
 * mode 0: over all φ; mode 1: only where w·n > 0 (both by the trapezoidal
 * rule on N points of the periodic integrand: spectral for mode 0, O(N⁻²)
 * at the kinks of mode 1); mode 2: over θ = φ − γ ∈ (0, π) by Simpson's
 * rule (the integrand jumps at the ends). */
static void film_quad(const whirl_fe_nl *e, const double r[2],
                      const double w[2], int mode, double f[2]) {
  const int N = 400000;
  const double gam = atan2(r[1], r[0]);
  double sy = 0.0, sz = 0.0;
  for (int k = 0; k <= N; ++k) {
    double ph = 2.0 * PI * k / N, wt = k < N ? 1.0 : 0.0;
    if (mode == 2) {
      ph = gam + PI * k / N;
      wt = (k == 0 || k == N) ? 1.0 / 3.0 : (k % 2 ? 4.0 / 3.0 : 2.0 / 3.0);
    }
    const double ny = cos(ph), nz = sin(ph);
    const double G = w[0] * ny + w[1] * nz;
    const double h = e->par.clearance - r[0] * ny - r[1] * nz;
    if (mode == 1 && G <= 0.0) continue;
    sy += wt * G / (h * h * h) * ny;
    sz += wt * G / (h * h * h) * nz;
  }
  const whirl_fe_nl_params *p = &e->par;
  const double dph = (mode == 2 ? PI : 2.0 * PI) / N;
  const double k = -p->viscosity * p->radius * pow(p->length, 3) * dph;
  f[0] = k * sy;
  f[1] = k * sz;
}

/* ------------------------------------------------------------------------
 * Central finite differences of f against Jr, Jv, Ja at one state; returns
 * the largest error relative to the largest Jacobian entry of each. */
static double fd_check(const whirl_fe_nl *e, const double r[2],
                       const double v[2], const double a[2], double Om,
                       double hr, double hv, double ha, double err[3]) {
  double f[2], J[3][4];
  if (whirl_fe_nl_force(e, r, v, a, Om, f, J[0], J[1], J[2]) != WHIRL_OK)
    return INFINITY;
  const double h[3] = {hr, hv, ha};
  double worst = 0.0;
  for (int m = 0; m < 3; ++m) {
    double x[3][2] = {{r[0], r[1]}, {v[0], v[1]}, {a[0], a[1]}};
    double scale = 0.0, e_max = 0.0;
    for (int i = 0; i < 4; ++i) scale = fmax(scale, fabs(J[m][i]));
    for (int j = 0; j < 2; ++j) {
      double fp[2], fm[2];
      const double x0 = x[m][j];
      x[m][j] = x0 + h[m];
      int rc1 = whirl_fe_nl_force(e, x[0], x[1], x[2], Om, fp, NULL, NULL, NULL);
      x[m][j] = x0 - h[m];
      int rc2 = whirl_fe_nl_force(e, x[0], x[1], x[2], Om, fm, NULL, NULL, NULL);
      x[m][j] = x0;
      if (rc1 != WHIRL_OK || rc2 != WHIRL_OK) return INFINITY;
      for (int i = 0; i < 2; ++i) {
        const double d = (fp[i] - fm[i]) / (2.0 * h[m]);
        e_max = fmax(e_max, fabs(d - J[m][i + 2 * j]));
      }
    }
    err[m] = scale > 0.0 ? e_max / scale : e_max;
    worst = fmax(worst, err[m]);
  }
  return worst;
}

/* Jacobians at n random states with ε ≤ emax, velocities up to vmax m/s,
 * accelerations up to amax m/s², speed Om. */
static void jac_random(whirl_fe_nl e, const char *name, int n, double emax,
                       double vmax, double amax, double Om, double tol) {
  const double c = e.par.clearance > 0.0 ? e.par.clearance : 1e-4;
  double worst = 0.0;
  for (int k = 0; k < n; ++k) {
    const double eps = emax * sqrt(tap_urand(0.0, 1.0)), g = tap_urand(0, 2 * PI);
    const double r[2] = {c * eps * cos(g), c * eps * sin(g)};
    const double v[2] = {tap_urand(-vmax, vmax), tap_urand(-vmax, vmax)};
    const double a[2] = {tap_urand(-amax, amax), tap_urand(-amax, amax)};
    double err[3];
    double w = fd_check(&e, r, v, a, Om, 1e-6 * c, 1e-6 * fmax(vmax, 1e-3),
                        1e-6 * fmax(amax, 1.0), err);
    worst = fmax(worst, w);
  }
  ok(worst < tol, "%s: Jr, Jv, Ja = central differences at %d random states "
     "(worst rel err %.2g)", name, n, worst);
}

/* ------------------------------------------------------------------------
 * Cubic spring. */
static void test_cubic(void) {
  whirl_fe_nl e;
  memset(&e, 0, sizeof e);
  e.kind = WHIRL_FE_CUBIC;
  e.par.k1 = 2e6;
  e.par.k3 = 5e12;
  const double r[2] = {3e-4, -4e-4}, v[2] = {1.0, 2.0}, a[2] = {0, 0};
  double f[2], Jr[4], Jv[4], Ja[4];
  int rc = whirl_fe_nl_force(&e, r, v, a, 100.0, f, Jr, Jv, Ja);
  /* |r|² = 25e-8, k1 + k3|r|² = 2e6 + 1.25e6 = 3.25e6 */
  ok(rc == WHIRL_OK && fabs(f[0] + 975.0) < 1e-9 && fabs(f[1] - 1300.0) < 1e-9,
     "cubic: f = -(k1 + k3|r|^2) r = (-975, 1300) N (got %.12g, %.12g)", f[0], f[1]);
  /* Jr = -3.25e6 I - 2 k3 r r^T: rr^T = [9 -12; -12 16] 1e-8 */
  ok(fabs(Jr[0] + 3.25e6 + 0.9e6) < 1e-6 && fabs(Jr[1] - 1.2e6) < 1e-6 &&
         fabs(Jr[2] - 1.2e6) < 1e-6 && fabs(Jr[3] + 3.25e6 + 1.6e6) < 1e-6,
     "cubic: Jr by hand");
  ok(Jv[0] == 0 && Jv[1] == 0 && Jv[2] == 0 && Jv[3] == 0 && Ja[0] == 0 &&
         Ja[3] == 0, "cubic: Jv = Ja = 0");
  jac_random(e, "cubic", 50, 5.0, 1.0, 0.0, 0.0, 1e-8);
}

/* ------------------------------------------------------------------------
 * Short SFD, π film. */
static void test_short_pi(void) {
  whirl_fe_nl e = film(WHIRL_FE_SFD_SHORT_PI);
  const double c = e.par.clearance, K = force_scale(&e);
  /* circular centred orbit: Vance (1988) eq. 4.? / San Andrés Notes 13:
   *   F_r = −(μRL³/c²) 2ε²ω/(1−ε²)², F_t = −(μRL³/c²) πεω/(2(1−ε²)^{3/2}) */
  const double eps[] = {0.1, 0.5, 0.8, 0.95};
  int good = 1;
  for (size_t i = 0; i < sizeof eps / sizeof eps[0]; ++i) {
    const double w = 150.0, s = 1.0 - eps[i] * eps[i];
    for (int k = 0; k < 4; ++k) {
      double r[2], v[2], f[2], fr, ft;
      orbit(eps[i] * c, w, 0.3 + 1.7 * k, r, v);
      if (whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL)) good = 0;
      polar(r, f, &fr, &ft);
      const double wr = -K * 2.0 * eps[i] * eps[i] * w / (s * s);
      const double wt = -K * PI * eps[i] * w / (2.0 * s * sqrt(s));
      if (fabs(fr - wr) > 1e-12 * fabs(wr) || fabs(ft - wt) > 1e-12 * fabs(wt)) {
        good = 0;
        printf("# eps %g: fr %.15g want %.15g, ft %.15g want %.15g\n", eps[i],
               fr, wr, ft, wt);
      }
    }
  }
  ok(good, "sfd-short-pi: circular centred orbit = Vance's closed forms (1e-12)");

  /* = the paper's nondimensional force (rotor/sfd.c, both dampers) times
   * m c ω_n²/2, λ = μR(L/c)³/√(2km) (eqs. 11–14), at random states */
  const double m = 285.0, kk = 25e6, wn = sqrt(2.0 * kk / m);
  const double lam = e.par.viscosity * e.par.radius *
                     pow(e.par.length / c, 3) / sqrt(2.0 * kk * m);
  double worst = 0.0;
  for (int k = 0; k < 40; ++k) {
    const double y = tap_urand(-0.65, 0.65), z = tap_urand(-0.65, 0.65);
    const double yp = tap_urand(-2, 2), zp = tap_urand(-2, 2);
    double fn[2], f[2];
    whirl_sfd_force(y, z, yp, zp, lam, fn, NULL, NULL);
    const double r[2] = {c * y, c * z}, v[2] = {c * wn * yp, c * wn * zp};
    whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL);
    const double sc = m * c * wn * wn / 2.0;
    worst = fmax(worst, hypot(f[0] - sc * fn[0], f[1] - sc * fn[1]) /
                            (sc * hypot(fn[0], fn[1])));
  }
  ok(worst < 1e-12, "sfd-short-pi: = paper eq. 8 nondimensional (sfd.c) x "
     "m c wn^2/2 with lambda of eq. 14 at 40 states (%.2g)", worst);

  /* = quadrature of the short-bearing pressure over θ ∈ (0, π) */
  worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double g = tap_urand(0, 2 * PI), ep = tap_urand(0.05, 0.85);
    const double r[2] = {c * ep * cos(g), c * ep * sin(g)};
    const double v[2] = {tap_urand(-0.05, 0.05), tap_urand(-0.05, 0.05)};
    double f[2], q[2];
    whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL);
    film_quad(&e, r, v, 2, q);
    worst = fmax(worst, hypot(f[0] - q[0], f[1] - q[1]) / hypot(q[0], q[1]));
  }
  ok(worst < 1e-10, "sfd-short-pi: = quadrature of the short-bearing pressure "
     "over the half film ahead of the line of centres (%.2g)", worst);

  jac_random(e, "sfd-short-pi", 200, 0.9, 0.05, 0.0, 0.0, 1e-6);
}

/* ------------------------------------------------------------------------
 * Short SFD, 2π film. */
static void test_short_2pi(void) {
  whirl_fe_nl e = film(WHIRL_FE_SFD_SHORT_2PI);
  const double c = e.par.clearance, K = force_scale(&e);
  /* circular centred orbit (Vance 1988; San Andrés): F_r = 0,
   * F_t = −(μRL³/c²) πεω/(1−ε²)^{3/2} */
  int good = 1;
  const double eps[] = {0.1, 0.5, 0.8, 0.95};
  for (size_t i = 0; i < 4; ++i) {
    const double w = -80.0, s = 1.0 - eps[i] * eps[i];
    double r[2], v[2], f[2], fr, ft;
    orbit(eps[i] * c, w, 2.0 + i, r, v);
    whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL);
    polar(r, f, &fr, &ft);
    const double wt = -K * PI * eps[i] * w / (s * sqrt(s));
    if (fabs(fr) > 1e-12 * fabs(wt) || fabs(ft - wt) > 1e-12 * fabs(wt)) good = 0;
  }
  ok(good, "sfd-short-2pi: circular orbit F_r = 0, F_t = Vance's (1e-12)");
  /* pure squeeze: F_r = −(μRL³/c³) π(1+2ε²)/(1−ε²)^{5/2} ė */
  {
    const double ep = 0.6, s = 1 - ep * ep, g = 0.7, ed = 0.03;
    const double r[2] = {c * ep * cos(g), c * ep * sin(g)};
    const double v[2] = {ed * cos(g), ed * sin(g)};
    double f[2], fr, ft;
    whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL);
    polar(r, f, &fr, &ft);
    const double want = -K / c * PI * (1 + 2 * ep * ep) / pow(s, 2.5) * ed;
    ok(fabs(fr - want) < 1e-12 * fabs(want) && fabs(ft) < 1e-12 * fabs(want),
       "sfd-short-2pi: pure squeeze F_r = -(muRL^3/c^3) pi(1+2e^2)/s^{5/2} de");
  }
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double g = tap_urand(0, 2 * PI), ep = tap_urand(0.05, 0.85);
    const double r[2] = {c * ep * cos(g), c * ep * sin(g)};
    const double v[2] = {tap_urand(-0.05, 0.05), tap_urand(-0.05, 0.05)};
    double f[2], q[2];
    whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL);
    film_quad(&e, r, v, 0, q);
    worst = fmax(worst, hypot(f[0] - q[0], f[1] - q[1]) / hypot(q[0], q[1]));
  }
  ok(worst < 1e-9, "sfd-short-2pi: = quadrature of the full film (%.2g)", worst);
  jac_random(e, "sfd-short-2pi", 200, 0.9, 0.05, 0.0, 0.0, 1e-6);
}

/* ------------------------------------------------------------------------
 * Short journal bearing. */

/* the Ocvirk relation: W c²/(μ Ω R L³) = ε √(16ε² + π²(1−ε²)) / (4(1−ε²)²),
 * solved for ε by bisection (it increases with ε) */
static double ocvirk_eps(double S) {
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (lo + hi), s = 1 - m * m;
    const double g = m * sqrt(16 * m * m + PI * PI * s) / (4 * s * s);
    if (g < S) lo = m; else hi = m;
  }
  return 0.5 * (lo + hi);
}

/* Newton on f(r) + W = 0 for the static journal (v = 0) with the analytic
 * Jr; W along −z (gravity), the journal rotating at +Ω. */
static int journal_static(const whirl_fe_nl *e, double W, double Om,
                          double r[2]) {
  r[0] = 0.0;
  r[1] = -0.3 * e->par.clearance;
  const double v[2] = {0, 0};
  for (int it = 0; it < 100; ++it) {
    double f[2], J[4];
    if (whirl_fe_nl_force(e, r, v, NULL, Om, f, J, NULL, NULL)) return -1;
    const double g0 = f[0], g1 = f[1] - W; /* f + (0, −W) */
    const double det = J[0] * J[3] - J[2] * J[1];
    double d0 = (J[3] * g0 - J[2] * g1) / det, d1 = (-J[1] * g0 + J[0] * g1) / det;
    /* damp to stay inside the clearance */
    double t = 1.0;
    while (hypot(r[0] - t * d0, r[1] - t * d1) >= 0.999 * e->par.clearance) t *= 0.5;
    r[0] -= t * d0;
    r[1] -= t * d1;
    if (hypot(d0, d1) < 1e-15 * e->par.clearance) return it;
  }
  return -1;
}

static void test_journal(void) {
  whirl_fe_nl e = film(WHIRL_FE_JOURNAL_SHORT);
  const double c = e.par.clearance, Om = 300.0;
  const double U = e.par.viscosity * Om * e.par.radius * pow(e.par.length, 3) / (c * c);
  const double S[] = {0.05, 0.3, 1.0, 3.0, 20.0};
  int good = 1;
  for (int i = 0; i < 5; ++i) {
    double r[2];
    const double W = S[i] * U;
    int it = journal_static(&e, W, Om, r);
    const double ep = hypot(r[0], r[1]) / c, want = ocvirk_eps(S[i]);
    /* attitude: the angle from the load line (−z) to the journal centre,
     * in the direction of rotation (+Ω: from y to z) */
    const double phi = atan2(r[0], -r[1]);
    const double wphi = atan(PI * sqrt(1 - want * want) / (4 * want));
    printf("# W/U %g: eps %.15g (Ocvirk %.15g), attitude %.12g deg (%.12g)\n",
           S[i], ep, want, phi * 180 / PI, wphi * 180 / PI);
    if (it < 0 || fabs(ep - want) > 1e-10 || fabs(phi - wphi) > 1e-9) good = 0;
  }
  ok(good, "journal-short: static equilibrium under a load along -z: "
     "eccentricity = Ocvirk relation, attitude tan(phi) = pi sqrt(1-e^2)/(4e), "
     "journal ahead of the load in the direction of rotation");
  /* the linearised stiffness and damping at equilibrium = the classical
   * short-bearing (half-Sommerfeld) coefficients, f = −K x − C ẋ (San
   * Andrés, Modern Lubrication Theory notes; Childs 1993; the closed forms
   * of ROSS's fluid_flow module), in the frame X = y horizontal, Y = z up,
   * the load W along −Y and the rotation from X to Y, so K = −Jr, C = −Jv */
  good = 1;
  for (int i = 0; i < 5; ++i) {
    double r[2], f[2], Jr[4], Jv[4];
    const double W = S[i] * U, v[2] = {0, 0};
    journal_static(&e, W, Om, r);
    whirl_fe_nl_force(&e, r, v, NULL, Om, f, Jr, Jv, NULL);
    const double ep = hypot(r[0], r[1]) / c, e2 = ep * ep, s = 1 - e2;
    const double h0 = 1.0 / pow(PI * PI * s + 16 * e2, 1.5);
    const double a = W / c * h0, b = W / (c * Om) * h0, q = ep * sqrt(s);
    const double K[4] = {/* XX, YX, XY, YY (column-major) */
                         a * 4 * (PI * PI * (2 - e2) + 16 * e2),
                         -a * PI * (PI * PI * s * (1 + 2 * e2) + 32 * e2 * (1 + e2)) / q,
                         a * PI * (PI * PI * s * s - 16 * e2 * e2) / q,
                         a * 4 * (PI * PI * (1 + 2 * e2) + 32 * e2 * (1 + e2) / s)};
    const double C[4] = {b * 2 * PI * sqrt(s) * (PI * PI * (1 + 2 * e2) - 16 * e2) / ep,
                         -b * 8 * (PI * PI * (1 + 2 * e2) - 16 * e2),
                         -b * 8 * (PI * PI * (1 + 2 * e2) - 16 * e2),
                         b * 2 * PI * (PI * PI * s * s + 48 * e2) / q};
    for (int k = 0; k < 4; ++k)
      if (fabs(-Jr[k] - K[k]) > 1e-9 * fabs(K[0]) ||
          fabs(-Jv[k] - C[k]) > 1e-9 * fabs(C[0])) {
        good = 0;
        printf("# eps %.3f: K[%d] %.12g (%.12g), C[%d] %.12g (%.12g)\n", ep, k,
               -Jr[k], K[k], k, -Jv[k], C[k]);
      }
  }
  ok(good, "journal-short: Jr, Jv at equilibrium = the classical short-bearing "
     "stiffness and damping coefficients (1e-9)");


  /* the Couette equivalence: with v = 0 the force is the π film of the
   * squeeze velocity ε(γ̇ − Ω/2): against the quadrature of w·n > 0 */
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double g = tap_urand(0, 2 * PI), ep = tap_urand(0.05, 0.85);
    const double r[2] = {c * ep * cos(g), c * ep * sin(g)};
    const double v[2] = {tap_urand(-0.05, 0.05), tap_urand(-0.05, 0.05)};
    const double w[2] = {v[0] + 0.5 * Om * r[1], v[1] - 0.5 * Om * r[0]};
    double f[2], q[2];
    whirl_fe_nl_force(&e, r, v, NULL, Om, f, NULL, NULL, NULL);
    film_quad(&e, r, w, 1, q);
    worst = fmax(worst, hypot(f[0] - q[0], f[1] - q[1]) / hypot(q[0], q[1]));
  }
  ok(worst < 1e-6, "journal-short: = quadrature of the half-Sommerfeld film "
     "(positive pressure only) at random states (%.2g)", worst);
  jac_random(e, "journal-short", 200, 0.9, 0.05, 0.0, Om, 1e-6);
  jac_random(e, "journal-short (Omega < 0)", 100, 0.9, 0.05, 0.0, -Om, 1e-6);
}

/* ------------------------------------------------------------------------
 * Rub. */
static void test_rub(void) {
  whirl_fe_nl e;
  memset(&e, 0, sizeof e);
  e.kind = WHIRL_FE_RUB;
  e.par.clearance = 2e-4;
  e.par.k_contact = 1e8;
  e.par.friction = 0.2;
  e.par.radius = 0.05;
  double f[2], Jr[4], Jv[4];
  const double a[2] = {0, 0};
  {
    const double r[2] = {1e-4, 1e-4}, v[2] = {1, 1};
    int rc = whirl_fe_nl_force(&e, r, v, a, 100, f, Jr, Jv, NULL);
    ok(rc == WHIRL_OK && f[0] == 0 && f[1] == 0 && Jr[0] == 0 && Jr[3] == 0,
       "rub: no force inside the clearance");
  }
  {
    /* r = (0, 3e-4): penetration 1e-4, N = 1e4 N along −z; t̂ = (−1, 0);
     * u = t̂·v + RΩ = −0.5 + 5 > 0: friction −μN t̂ = (+2000, 0) */
    const double r[2] = {0.0, 3e-4}, v[2] = {0.5, 0.0};
    int rc = whirl_fe_nl_force(&e, r, v, a, 100, f, Jr, Jv, NULL);
    ok(rc == WHIRL_OK && fabs(f[0] - 2000.0) < 1e-9 && fabs(f[1] + 1e4) < 1e-9,
       "rub: f = (2000, -10000) N by hand (got %.12g, %.12g)", f[0], f[1]);
    /* Jr by hand: r̂ = (0,1), t̂ = (−1,0), w = δ/ρ = 1/3;
     * −k[r̂r̂ᵀ + w t̂t̂ᵀ + μ(t̂r̂ᵀ − w r̂t̂ᵀ)] = −1e8 [[1/3, −0.2], [0.2/3, 1]] */
    ok(fabs(Jr[0] + 1e8 / 3) < 1e-3 && fabs(Jr[1] + 0.2e8 / 3) < 1e-3 &&
           fabs(Jr[2] - 0.2e8) < 1e-3 && fabs(Jr[3] + 1e8) < 1e-3,
       "rub: Jr by hand");
    /* the shaft spinning backwards faster than the whirl: friction flips */
    rc = whirl_fe_nl_force(&e, r, v, a, -100, f, NULL, NULL, NULL);
    ok(rc == WHIRL_OK && fabs(f[0] + 2000.0) < 1e-9 && fabs(f[1] + 1e4) < 1e-9,
       "rub: Omega < 0 reverses the friction");
  }
  /* Jacobians away from contact onset and from u = 0: states with
   * ρ ∈ (1.05 c, 2 c) */
  double worst = 0.0;
  for (int k = 0; k < 100; ++k) {
    const double rho = e.par.clearance * tap_urand(1.05, 2.0), g = tap_urand(0, 2 * PI);
    const double r[2] = {rho * cos(g), rho * sin(g)};
    const double v[2] = {tap_urand(-1, 1), tap_urand(-1, 1)};
    double err[3];
    worst = fmax(worst, fd_check(&e, r, v, a, 100.0, 1e-10, 1e-6, 1e-6, err));
  }
  ok(worst < 1e-6, "rub: Jr, Jv = central differences at 100 states in "
     "contact (%.2g)", worst);
}

/* ------------------------------------------------------------------------
 * Domain and argument errors. */
static void test_errors(void) {
  const whirl_fe_nl_kind kinds[] = {WHIRL_FE_SFD_SHORT_PI, WHIRL_FE_SFD_SHORT_2PI,
                                    WHIRL_FE_SFD_LONG, WHIRL_FE_SFD_INERTIA,
                                    WHIRL_FE_JOURNAL_SHORT};
  const double a[2] = {0, 0};
  for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; ++i) {
    whirl_fe_nl e = film(kinds[i]);
    const double r[2] = {0.6e-4, 0.8e-4}, v[2] = {0.01, 0.0};
    double f[2] = {7, 7}, J[4] = {7, 7, 7, 7};
    int rc = whirl_fe_nl_force(&e, r, v, a, 10, f, J, J, J);
    ok(rc == WHIRL_EDOMAIN && f[0] == 7 && J[0] == 7,
       "kind %d: |r| = c is WHIRL_EDOMAIN, nothing written", (int)kinds[i]);
    e.par.clearance = 0.0;
    ok(whirl_fe_nl_force(&e, r, v, a, 10, f, NULL, NULL, NULL) == WHIRL_EINVAL,
       "kind %d: zero clearance is WHIRL_EINVAL", (int)kinds[i]);
    e = film(kinds[i]);
    e.par.viscosity = -1;
    ok(whirl_fe_nl_force(&e, r, v, a, 10, f, NULL, NULL, NULL) == WHIRL_EINVAL,
       "kind %d: negative viscosity is WHIRL_EINVAL", (int)kinds[i]);
    e = film(kinds[i]);
    const double rn[2] = {NAN, 0};
    ok(whirl_fe_nl_force(&e, rn, v, a, 10, f, NULL, NULL, NULL) == WHIRL_EINVAL &&
           whirl_fe_nl_force(NULL, r, v, a, 10, f, NULL, NULL, NULL) == WHIRL_EINVAL &&
           whirl_fe_nl_force(&e, r, v, a, 10, NULL, NULL, NULL, NULL) == WHIRL_EINVAL,
       "kind %d: NaN state, NULL element or f are WHIRL_EINVAL", (int)kinds[i]);
  }
  whirl_fe_nl e = film(WHIRL_FE_RUB);
  e.par.k_contact = 0;
  const double r[2] = {0, 0}, v[2] = {0, 0};
  double f[2];
  ok(whirl_fe_nl_force(&e, r, v, a, 0, f, NULL, NULL, NULL) == WHIRL_EINVAL,
     "rub: zero contact stiffness is WHIRL_EINVAL");
  e.kind = (whirl_fe_nl_kind)99;
  ok(whirl_fe_nl_force(&e, r, v, a, 0, f, NULL, NULL, NULL) == WHIRL_EINVAL,
     "unknown kind is WHIRL_EINVAL");
}

/* ------------------------------------------------------------------------
 * Long SFD, sealed ends, π film. */

/* the long-bearing Reynolds equation ∂θ(D³ ∂θ p̃) = −(w_r cos θ + w_t sin θ)
 * on θ ∈ (0, π), p̃(0) = p̃(π) = 0, by second-order finite differences
 * (Thomas algorithm), and its force f = −RL ∫ p n with p = (12μR²/c³) p̃,
 * in the local basis (r̂, t̂) */
static void long_fd(const whirl_fe_nl *e, double eps, double wr, double wt,
                    double F[2]) {
  enum { N = 20000 };
  static double lo[N], di[N], up[N], rhs[N], p[N + 1];
  const double h = PI / N;
  for (int i = 1; i < N; ++i) {
    const double th = i * h, Dm = 1 - eps * cos(th - 0.5 * h),
                 Dp = 1 - eps * cos(th + 0.5 * h);
    lo[i] = Dm * Dm * Dm;
    up[i] = Dp * Dp * Dp;
    di[i] = -(lo[i] + up[i]);
    rhs[i] = -(wr * cos(th) + wt * sin(th)) * h * h;
  }
  for (int i = 2; i < N; ++i) { /* forward elimination */
    const double m = lo[i] / di[i - 1];
    di[i] -= m * up[i - 1];
    rhs[i] -= m * rhs[i - 1];
  }
  p[0] = p[N] = 0.0;
  for (int i = N - 1; i >= 1; --i) p[i] = (rhs[i] - up[i] * p[i + 1]) / di[i];
  double sc = 0, ss = 0;
  for (int i = 1; i < N; ++i) {
    sc += p[i] * cos(i * h) * h;
    ss += p[i] * sin(i * h) * h;
  }
  const whirl_fe_nl_params *q = &e->par;
  const double k = -q->radius * q->length * 12.0 * q->viscosity * q->radius *
                   q->radius / pow(q->clearance, 3);
  F[0] = k * sc;
  F[1] = k * ss;
}

static void test_long(void) {
  whirl_fe_nl e = film(WHIRL_FE_SFD_LONG);
  const double c = e.par.clearance;
  const double KL = e.par.viscosity * pow(e.par.radius, 3) * e.par.length / (c * c);
  /* circular centred orbit (Vance 1988; San Andrés, Notes 13):
   *   F_r = −24 μR³L ε²ω/(c²(2+ε²)(1−ε²)), F_t = −12π μR³L εω/(c²(2+ε²)√(1−ε²)) */
  int good = 1;
  const double eps[] = {0.1, 0.5, 0.8, 0.95};
  for (size_t i = 0; i < 4; ++i) {
    const double w = 120.0, s = 1.0 - eps[i] * eps[i], q = 2 + eps[i] * eps[i];
    double r[2], v[2], f[2], fr, ft;
    orbit(eps[i] * c, w, 1.0 + i, r, v);
    whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL);
    polar(r, f, &fr, &ft);
    const double wr = -24 * KL * eps[i] * eps[i] * w / (q * s);
    const double wt = -12 * PI * KL * eps[i] * w / (q * sqrt(s));
    if (fabs(fr - wr) > 1e-12 * fabs(wr) || fabs(ft - wt) > 1e-12 * fabs(wt)) good = 0;
  }
  ok(good, "sfd-long: circular centred orbit = Vance's pi-film closed forms (1e-12)");
  /* = finite differences of the long-bearing Reynolds equation, with
   * squeeze (ė ≠ 0) */
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double g = tap_urand(0, 2 * PI), ep = tap_urand(0.05, 0.8);
    const double r[2] = {c * ep * cos(g), c * ep * sin(g)};
    const double v[2] = {tap_urand(-0.05, 0.05), tap_urand(-0.05, 0.05)};
    double f[2], fr, ft, F[2];
    whirl_fe_nl_force(&e, r, v, NULL, 0.0, f, NULL, NULL, NULL);
    polar(r, f, &fr, &ft);
    const double ry = cos(g), rz = sin(g);
    long_fd(&e, ep, ry * v[0] + rz * v[1], -rz * v[0] + ry * v[1], F);
    worst = fmax(worst, hypot(fr - F[0], ft - F[1]) / hypot(F[0], F[1]));
  }
  ok(worst < 1e-6, "sfd-long: = finite-difference solution of the long-bearing "
     "Reynolds equation on the pi film at random states (%.2g)", worst);
  jac_random(e, "sfd-long", 200, 0.9, 0.05, 0.0, 0.0, 1e-6);
}

/* ------------------------------------------------------------------------
 * Short SFD, π film, fluid inertia. */
static void test_inertia(void) {
  whirl_fe_nl e = film(WHIRL_FE_SFD_INERTIA), e0 = film(WHIRL_FE_SFD_SHORT_PI);
  const double c = e.par.clearance;
  const double kI = e.par.density * e.par.radius * pow(e.par.length, 3) / 12.0;
  /* ρ = 0: the short π film */
  {
    whirl_fe_nl z = e;
    z.par.density = 0.0;
    double worst = 0.0;
    for (int k = 0; k < 20; ++k) {
      const double r[2] = {tap_urand(-0.6, 0.6) * c, tap_urand(-0.6, 0.6) * c};
      const double v[2] = {tap_urand(-0.05, 0.05), tap_urand(-0.05, 0.05)};
      const double a[2] = {tap_urand(-50, 50), tap_urand(-50, 50)};
      double f[2], f0[2];
      whirl_fe_nl_force(&z, r, v, a, 0, f, NULL, NULL, NULL);
      whirl_fe_nl_force(&e0, r, v, a, 0, f0, NULL, NULL, NULL);
      worst = fmax(worst, hypot(f[0] - f0[0], f[1] - f0[1]) / hypot(f0[0], f0[1]));
    }
    ok(worst == 0.0, "sfd-inertia: density 0 is the short pi film (%.2g)", worst);
  }
  /* at the centre: the added mass of half the film, πρRL³/(24c) */
  {
    const double r[2] = {0, 0}, v[2] = {0.02, -0.01}, a[2] = {30, -70};
    double f[2], f0[2], Ja[4];
    whirl_fe_nl_force(&e, r, v, a, 0, f, NULL, NULL, Ja);
    whirl_fe_nl_force(&e0, r, v, a, 0, f0, NULL, NULL, NULL);
    const double M = PI * e.par.density * e.par.radius * pow(e.par.length, 3) / (24 * c);
    ok(fabs(f[0] - f0[0] + M * a[0]) < 1e-12 * M * 70 &&
           fabs(f[1] - f0[1] + M * a[1]) < 1e-12 * M * 70 &&
           fabs(Ja[0] + M) < 1e-12 * M && fabs(Ja[3] + M) < 1e-12 * M &&
           fabs(Ja[1]) < 1e-12 * M,
       "sfd-inertia: at the centre f - f_visc = -pi rho R L^3/(24c) a, Ja = -M I");
  }
  /* circular centred orbit r = e r̂(ωt): a = −ω² r, v = eω t̂; the inertia
   * forces by hand (doc/rotor-forces.md §4), β = (1 − √s)/ε:
   *   F_r = −kI ω² ε (π/√s) [2β² − 1/(1+√s)],
   *   F_t = −6 kI ω² (atanh ε − ε)/ε,  kI = ρRL³/12 */
  int good = 1;
  const double eps[] = {0.1, 0.4, 0.7, 0.9, 0.97};
  for (size_t i = 0; i < 5; ++i) {
    const double w = 400.0, ep = eps[i], s = 1 - ep * ep, rs = sqrt(s);
    const double be = (1 - rs) / ep;
    double r[2], v[2], f[2], f0[2], fr, ft;
    orbit(ep * c, w, 0.5 + i, r, v);
    const double a[2] = {-w * w * r[0], -w * w * r[1]};
    whirl_fe_nl_force(&e, r, v, a, 0, f, NULL, NULL, NULL);
    whirl_fe_nl_force(&e0, r, v, a, 0, f0, NULL, NULL, NULL);
    const double d[2] = {f[0] - f0[0], f[1] - f0[1]};
    polar(r, d, &fr, &ft);
    const double wr = -kI * w * w * ep * PI / rs * (2 * be * be - 1 / (1 + rs));
    const double wt = -6 * kI * w * w * (atanh(ep) - ep) / ep;
    printf("# eps %g: inertia F_r %.15g (%.15g), F_t %.15g (%.15g)\n", ep, fr,
           wr, ft, wt);
    if (fabs(fr - wr) > 1e-11 * fabs(wr) || fabs(ft - wt) > 1e-11 * fabs(wt)) good = 0;
  }
  ok(good, "sfd-inertia: circular centred orbit inertia forces = closed forms (1e-11)");
  /* random states against a brute-force quadrature of the inertia term */
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double g = tap_urand(0, 2 * PI), ep = tap_urand(0.05, 0.9);
    const double r[2] = {c * ep * cos(g), c * ep * sin(g)};
    const double v[2] = {tap_urand(-0.05, 0.05), tap_urand(-0.05, 0.05)};
    const double a[2] = {tap_urand(-50, 50), tap_urand(-50, 50)};
    double f[2], f0[2], sy = 0, sz = 0;
    whirl_fe_nl_force(&e, r, v, a, 0, f, NULL, NULL, NULL);
    whirl_fe_nl_force(&e0, r, v, a, 0, f0, NULL, NULL, NULL);
    const int N = 200000;
    for (int j = 0; j <= N; ++j) { /* Simpson over φ ∈ (γ, γ + π) */
      const double ph = g + PI * j / N, ny = cos(ph), nz = sin(ph);
      const double h = c - r[0] * ny - r[1] * nz, G = v[0] * ny + v[1] * nz;
      const double wq = (j == 0 || j == N) ? 1.0 / 3 : (j % 2 ? 4.0 / 3 : 2.0 / 3);
      const double P = (a[0] * ny + a[1] * nz) / h + 2 * G * G / (h * h);
      sy += wq * P * ny;
      sz += wq * P * nz;
    }
    const double qy = -kI * sy * PI / N, qz = -kI * sz * PI / N;
    worst = fmax(worst, hypot(f[0] - f0[0] - qy, f[1] - f0[1] - qz) / hypot(qy, qz));
  }
  ok(worst < 1e-10, "sfd-inertia: inertia part = Simpson quadrature at random "
     "states (%.2g)", worst);
  jac_random(e, "sfd-inertia", 200, 0.9, 0.05, 200.0, 0.0, 1e-6);
}

/* ------------------------------------------------------------------------
 * At the centre the films are linear dampers: f = −C0 v with
 * C0 = (π/2) μRL³/c³ (π film, short and journal), π μRL³/c³ (2π film),
 * (π/2 − 2/π) 12μR³L/c³ (the long π film's direction average). */
static void test_centre(void) {
  const struct {
    whirl_fe_nl_kind kind;
    double c0;
  } k[] = {{WHIRL_FE_SFD_SHORT_PI, PI / 2}, {WHIRL_FE_SFD_SHORT_2PI, PI},
           {WHIRL_FE_JOURNAL_SHORT, PI / 2}, {WHIRL_FE_SFD_LONG, -1}};
  int good = 1;
  for (int i = 0; i < 4; ++i) {
    whirl_fe_nl e = film(k[i].kind);
    const whirl_fe_nl_params *p = &e.par;
    double C0 = k[i].c0 * p->viscosity * p->radius * pow(p->length, 3) / pow(p->clearance, 3);
    if (k[i].c0 < 0)
      C0 = (PI / 2 - 2 / PI) * 12 * p->viscosity * pow(p->radius, 3) * p->length /
           pow(p->clearance, 3);
    const double r[2] = {0, 0}, v[2] = {0.03, -0.02};
    double f[2], Jv[4];
    whirl_fe_nl_force(&e, r, v, NULL, 250.0, f, NULL, Jv, NULL);
    if (fabs(f[0] + C0 * v[0]) > 1e-13 * C0 * 0.03 ||
        fabs(f[1] + C0 * v[1]) > 1e-13 * C0 * 0.03 || fabs(Jv[0] + C0) > 1e-13 * C0 ||
        fabs(Jv[3] + C0) > 1e-13 * C0 || fabs(Jv[1]) > 1e-13 * C0)
      good = 0;
  }
  ok(good, "films at the centre: f = -C0 v, Jv = -C0 I (pi film, 2pi film, "
     "journal, long-film average)");
}

int main(void) {
  test_cubic();
  test_short_pi();
  test_short_2pi();
  test_long();
  test_inertia();
  test_journal();
  test_centre();
  test_rub();
  test_errors();
  return done_testing();
}

/* test/unit/t_fe.c — the finite-element rotor (whirl/rotor/fe.h,
 * fe_linear.h) through the public API, against independent results:
 *  (a) Friswell et al. (2010) Examples 5.9.1, 5.9.5 (damped bearings) and
 *      5.9.9 (overhung): the natural frequencies at 0 and 4000 rev/min as
 *      ROSS prints and tests them (doc/rotor-validation.md), and the whirl
 *      (the lower of each split pair backward);
 *  (b) a massless shaft with one rigid disk at mid-span (Jeffcott): the
 *      translation √(k/m) with k = 1/(L³/48EI + L/(4κGA) + 1/(2kb)) and
 *      the gyroscopic tilt ω = (±IpΩ + √(Ip²Ω² + 4 It kθ))/(2 It), kθ =
 *      1/(L/(12EI) + 1/(κGAL) + 2/(L² kb)) (unit-load method), to 1e-8;
 *      its critical speeds √(k/m) and √(kθ/(It ± Ip)); its unbalance
 *      response meΩ²/(k_eff − mΩ²), circular forward, with damped bearings
 *      (complex k_eff);
 *  (c) a uniform simply supported Timoshenko shaft: the FE frequencies
 *      converge to the closed form (the quadratic in ω² of Timoshenko's
 *      equation for sin(nπx/L)) at the rate h⁴ as the elements double;
 *  (d) structure: M, K symmetric, G skew, rigid translation of M = mass,
 *      f0 of gravity sums to the weight; dense QZ and ARPACK agree on a
 *      48-element damped, cross-coupled rotor; a free rotor (K singular):
 *      no rigid-body modes, the Euler-Bernoulli free-free frequency;
 *  (e) the nonlinear kinds' names round trip; a file's errors name the line.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */
#include "config.h"                /* WHIRL_HAVE_ARPACK */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <whirl/rotor.h>

#include "../tap.h"

#define PI 3.14159265358979323846
#define RPM (PI / 30)

static char path_buf[64];

/* the rotor of TEXT, through a temporary file */
static whirl_fe_rotor *rotor_of(const char *text, char *msg, size_t len) {
  snprintf(path_buf, sizeof path_buf, "t_fe.XXXXXX");
  int fd = mkstemp(path_buf);
  if (fd < 0) return NULL;
  FILE *f = fdopen(fd, "w");
  fputs(text, f);
  fclose(f);
  whirl_fe_rotor *r = whirl_fe_rotor_read(path_buf, msg, len, NULL);
  unlink(path_buf);
  return r;
}

static whirl_fe_rotor *example(const char *name) {
  char p[1024], msg[512];
  const char *top = getenv("top_srcdir");
  snprintf(p, sizeof p, "%s/examples/rotor/%s", top ? top : ".", name);
  whirl_fe_rotor *r = whirl_fe_rotor_read(p, msg, sizeof msg, NULL);
  if (!r) printf("# %s\n", msg);
  return r;
}

static size_t modes_at(const whirl_fe_rotor *r, double Om, int method, size_t n, whirl_fe_mode *m) {
  whirl_fe_modes_options o;
  whirl_fe_modes_options_default(&o);
  o.method = (whirl_fe_eig_method)method;
  size_t nf = 0;
  char msg[512];
  if (whirl_fe_modes(r, Om, &o, n, m, &nf, msg, sizeof msg)) printf("# %s\n", msg);
  return nf;
}

/* ---- (a) Friswell's examples ---------------------------------------------- */

static void check_table(const char *what, const whirl_fe_rotor *r, double rpm, const double *want,
                        double tol, int hz_damped) {
  whirl_fe_mode m[6];
  size_t nf = modes_at(r, rpm * RPM, WHIRL_FE_EIG_DENSE, 6, m);
  ok(nf == 6, "%s at %g rpm: six modes", what, rpm);
  for (size_t k = 0; k < 6 && k < nf; ++k)
    is_rel(hz_damped ? m[k].omega / (2 * PI) : m[k].omega, want[k], tol, "%s at %g rpm: mode %zu", what,
           rpm, k + 1);
  if (rpm > 0 && nf == 6)
    ok(m[0].whirl < 0 && m[1].whirl > 0 && m[2].whirl < 0 && m[3].whirl > 0,
       "%s at %g rpm: backward below forward", what, rpm);
}

static void test_friswell(void) {
  /* ROSS docs/examples/example_05_09_01.rst prints (rad/s, 6 elements) */
  const double w0[6] = {86.65811435, 86.65811435, 274.31285391, 274.31285391, 716.78631221, 716.78631221};
  const double w4[6] = {85.389467, 87.7958637, 251.78460413, 294.71333087, 600.17936195, 827.07536193};
  whirl_fe_rotor *r = example("friswell-5.9.1.rotor");
  ok(r != NULL, "examples/rotor/friswell-5.9.1.rotor reads");
  if (!r) return;
  ok(r->nnode == 7 && r->ndof == 28, "5.9.1: 7 nodes, 28 DOFs");
  check_table("5.9.1", r, 0, w0, 2e-9, 0);
  check_table("5.9.1", r, 4000, w4, 2e-8, 0);
  /* ROSS ross/tests (test_friswell): the same to 2 decimals */
  const double t0[6] = {86.66, 86.66, 274.31, 274.31, 716.78, 716.78};
  check_table("5.9.1 (2 decimals)", r, 0, t0, 6e-5, 0);
  whirl_fe_rotor_free(r);

  r = example("friswell-5.9.9.rotor");
  ok(r != NULL, "examples/rotor/friswell-5.9.9.rotor reads");
  if (r) {
    const double o0[6] = {90.14, 90.14, 630.73, 630.73, 830.43, 830.43};
    const double o4[6] = {76.19, 103.91, 565.99, 634.23, 647.75, 1174.2};
    check_table("5.9.9", r, 0, o0, 1e-4, 0);
    check_table("5.9.9", r, 4000, o4, 1e-4, 0);
    whirl_fe_rotor_free(r);
  }
}

static const char *f595 =
    "material steel E=211e9 G=81.2e9 rho=7810\n"
    "shaft from=0 to=6 length=1.5 od=0.05 material=steel\n"
    "disk node=2 width=0.07 od=0.28 id=0.05 material=steel\n"
    "disk node=4 width=0.07 od=0.35 id=0.05 material=steel\n"
    "bearing node=0 kyy=1e6 kzz=1e6 cyy=3e3 czz=3e3\n"
    "bearing node=6 kyy=1e6 kzz=1e6 cyy=3e3 czz=3e3\n";

static void test_friswell_damped(void) {
  char msg[512];
  whirl_fe_rotor *r = rotor_of(f595, msg, sizeof msg);
  ok(r != NULL, "5.9.5 reads");
  if (!r) return;
  /* damped natural frequencies, Hz, ROSS test_friswell (wd) */
  const double d0[6] = {13.89, 13.89, 46.54, 46.54, 103.22, 103.22};
  const double d4[6] = {13.68, 14.07, 41.98, 50.65, 104.25, 105.66};
  check_table("5.9.5 damped", r, 0, d0, 6e-4, 1);
  check_table("5.9.5 damped", r, 4000, d4, 6e-4, 1);
  whirl_fe_mode m[2];
  modes_at(r, 0, WHIRL_FE_EIG_DENSE, 2, m);
  ok(m[0].log_dec > 0.1 && m[0].log_dec < 1, "5.9.5: the first mode is damped (log dec %g)", m[0].log_dec);
  whirl_fe_rotor_free(r);
}

/* ---- (b) Jeffcott ----------------------------------------------------------- */

#define JEFF_TEXT \
    "material massless E=2e11 G=8e10 rho=0\n" \
    "shaft from=0 to=%d length=0.8 od=0.03 id=0.01 material=massless\n" \
    "disk node=%d mass=12 ip=0.2 it=0.5\n" \
    "bearing node=0 kyy=%g kzz=%g cyy=%g czz=%g\n" \
    "bearing node=%d kyy=%g kzz=%g cyy=%g czz=%g\n" \
    "unbalance node=%d me=1e-4 phase-deg=0\n"

typedef struct jeff {
  double k, kt, m, ip, it;
} jeff;

/* the closed forms of the rotor above (kb: each bearing) */
static jeff jeff_closed(double kb) {
  const double E = 2e11, G = 8e10, L = 0.8, od = 0.03, id = 0.01, nu = E / (2 * G) - 1;
  const double A = PI * (od * od - id * id) / 4, I = PI * (pow(od, 4) - pow(id, 4)) / 64;
  const double a2 = (id / od) * (id / od), b = (1 + a2) * (1 + a2);
  const double kap = 6 * (1 + nu) * b / ((7 + 6 * nu) * b + (20 + 12 * nu) * a2); /* Cowper */
  jeff j = {0, 0, 12, 0.2, 0.5};
  j.k = 1 / (L * L * L / (48 * E * I) + L / (4 * kap * G * A) + 1 / (2 * kb));
  j.kt = 1 / (L / (12 * E * I) + 1 / (kap * G * A * L) + 2 / (L * L * kb));
  return j;
}

static whirl_fe_rotor *jeff_rotor(int nel, double kb, double cb) {
  char text[1024], msg[512];
  snprintf(text, sizeof text, JEFF_TEXT, nel, nel / 2, kb, kb, cb, cb, nel, kb, kb, cb, cb, nel / 2);
  whirl_fe_rotor *r = rotor_of(text, msg, sizeof msg);
  if (!r) printf("# %s\n", msg);
  return r;
}

static void test_jeffcott_modes(void) {
  const double kb = 5e7;
  const jeff j = jeff_closed(kb);
  for (int nel = 2; nel <= 8; nel *= 2) {
    whirl_fe_rotor *r = jeff_rotor(nel, kb, 0);
    if (!ok(r != NULL, "Jeffcott with %d elements reads", nel)) continue;
    const double Oms[2] = {0, 3000 * RPM};
    for (int s = 0; s < 2; ++s) {
      const double Om = Oms[s], q = sqrt(j.ip * j.ip * Om * Om + 4 * j.it * j.kt);
      const double wb = (-j.ip * Om + q) / (2 * j.it), wf = (j.ip * Om + q) / (2 * j.it);
      const double wt = sqrt(j.k / j.m);
      whirl_fe_mode m[4];
      size_t nf = modes_at(r, Om, WHIRL_FE_EIG_DENSE, 4, m);
      if (!ok(nf == 4, "Jeffcott %d el., %g rad/s: 4 finite modes (massless shaft)", nel, Om)) continue;
      /* ascending: the translation pair (√(k/m) ≈ 290) below the tilt */
      is_rel(m[0].omega, wt, 1e-8, "Jeffcott %d el., %g rad/s: translation = sqrt(k/m) (1)", nel, Om);
      is_rel(m[1].omega, wt, 1e-8, "Jeffcott %d el., %g rad/s: translation = sqrt(k/m) (2)", nel, Om);
      is_rel(m[2].omega, wb, 1e-8, "Jeffcott %d el., %g rad/s: backward tilt", nel, Om);
      is_rel(m[3].omega, wf, 1e-8, "Jeffcott %d el., %g rad/s: forward tilt", nel, Om);
      if (Om > 0) ok(m[2].whirl < 0 && m[3].whirl > 0, "Jeffcott at speed: tilt whirl backward, forward");
    }
    whirl_fe_rotor_free(r);
  }
}

static void test_jeffcott_critical(void) {
  const double kb = 5e7;
  const jeff j = jeff_closed(kb);
  whirl_fe_rotor *r = jeff_rotor(4, kb, 0);
  if (!r) return;
  const size_t ns = 41, nm = 4;
  double sp[41];
  for (size_t k = 0; k < ns; ++k) sp[k] = 2000.0 * (double)k / (double)(ns - 1);
  whirl_fe_mode cd[41 * 4];
  whirl_fe_critical c[16];
  size_t nc = 0;
  char msg[512];
  whirl_fe_modes_options o;
  whirl_fe_modes_options_default(&o);
  int rc = whirl_fe_campbell(r, sp, ns, &o, nm, cd, msg, sizeof msg);
  if (!rc) rc = whirl_fe_critical_speeds(r, sp, ns, &o, nm, cd, c, 16, &nc, msg, sizeof msg);
  ok(rc == 0, "Jeffcott Campbell and critical speeds: %s", rc ? msg : "ok");
  /* translation twice, tilt backward √(kθ/(It+Ip)), forward √(kθ/(It−Ip)) */
  const double wt = sqrt(j.k / j.m), wb = sqrt(j.kt / (j.it + j.ip)), wf = sqrt(j.kt / (j.it - j.ip));
  ok(nc == 4, "Jeffcott: 4 critical speeds below 2000 rad/s (got %zu)", nc);
  if (nc == 4) {
    is_rel(c[0].speed, wt, 1e-9, "critical speed 1 = sqrt(k/m)");
    is_rel(c[1].speed, wt, 1e-9, "critical speed 2 = sqrt(k/m)");
    is_rel(c[2].speed, wb, 1e-9, "critical speed: backward tilt sqrt(kt/(It+Ip))");
    is_rel(c[3].speed, wf, 1e-9, "critical speed: forward tilt sqrt(kt/(It-Ip))");
    ok(c[2].whirl < 0 && c[3].whirl > 0, "critical speeds: tilt backward, then forward");
  }
  whirl_fe_rotor_free(r);
}

static void test_jeffcott_unbalance(void) {
  const double kb = 5e7, cb = 2e3, me = 1e-4;
  const jeff j = jeff_closed(kb);
  /* the shaft's flexibility at mid-span: k with rigid bearings */
  const double fs = 1 / jeff_closed(1e300).k;
  whirl_fe_rotor *r = jeff_rotor(4, kb, cb);
  if (!r) return;
  const double Oms[3] = {150, 290, 600};
  for (int s = 0; s < 3; ++s) {
    const double Om = Oms[s];
    /* series: shaft, then the two bearings (kb + iΩcb) in parallel */
    /* 1/(2(kb + iΩc)) = (kb − iΩc)/(2|kb + iΩc|²) */
    const double ki = Om * cb, br = kb / (2 * (kb * kb + ki * ki)), bi = -ki / (2 * (kb * kb + ki * ki));
    const double fr = fs + br, fi = bi, fn = fr * fr + fi * fi;
    const double er = fr / fn - j.m * Om * Om, ei = -fi / fn; /* k_eff − mΩ² */
    const double en = er * er + ei * ei, F = me * Om * Om;
    const double Yr = F * er / en, Yi = -F * ei / en;
    double qr[20], qi[20];
    char msg[512];
    int rc = whirl_fe_unbalance_response(r, Om, qr, qi, msg, sizeof msg);
    ok(rc == 0, "unbalance response at %g rad/s: %s", Om, rc ? msg : "ok");
    const int y = whirl_fe_rotor_dof(r, 2, 0), z = whirl_fe_rotor_dof(r, 2, 1);
    is_rel(hypot(qr[y], qi[y]), hypot(Yr, Yi), 1e-8, "|Y| at %g rad/s = meΩ²/|k_eff - mΩ²|", Om);
    is_abs(qr[y], Yr, 1e-8 * hypot(Yr, Yi), "Re Y at %g rad/s", Om);
    is_abs(qi[y], Yi, 1e-8 * hypot(Yr, Yi), "Im Y at %g rad/s", Om);
    /* forward circular: Z = −i Y */
    is_abs(qr[z], Yi, 1e-8 * hypot(Yr, Yi), "Re Z = Im Y at %g rad/s", Om);
    is_abs(qi[z], -Yr, 1e-8 * hypot(Yr, Yi), "Im Z = -Re Y at %g rad/s", Om);
  }
  whirl_fe_rotor_free(r);
}

/* ---- (c) simply supported Timoshenko shaft -------------------------------------- */

/* ω_n of Timoshenko's equation for w = sin(nπx/L) e^{iωt}:
 * (ρ²I/κG) ω⁴ − (ρA + ρI k²(1 + E/κG)) ω² + EI k⁴ = 0, lower root. */
static double ss_timoshenko(int n, double L, double E, double G, double rho, double od, double id) {
  const double nu = E / (2 * G) - 1, a2 = (id / od) * (id / od), b = (1 + a2) * (1 + a2);
  const double kap = 6 * (1 + nu) * b / ((7 + 6 * nu) * b + (20 + 12 * nu) * a2);
  const double A = PI * (od * od - id * id) / 4, I = PI * (pow(od, 4) - pow(id, 4)) / 64;
  const double k = n * PI / L, qa = rho * rho * I / (kap * G);
  const double qb = -(rho * A + rho * I * k * k * (1 + E / (kap * G))), qc = E * I * pow(k, 4);
  const double w2 = (-qb - sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  return sqrt(w2);
}

/* The FE frequencies of a pinned shaft with nel = 4..32 elements against
 * the closed form: each doubling divides the error by at least `rate`
 * (h⁴: 16 for slender elements, φ = 12EI/(κGAh²) small; the Timoshenko
 * element's shape functions lose an order as φ grows, h²: 4, for elements
 * short against the diameter), and at 32 elements mode 1 is within tol1. */
static double check_ss(const char *what, double L, double od, double id, double rate, double tol1) {
  const double E = 211e9, G = 81.2e9, rho = 7810;
  double err_prev[3] = {0, 0, 0}, w16 = 0, w32 = 0;
  for (int nel = 4; nel <= 32; nel *= 2) {
    char text[1024], msg[512];
    /* pinned ends: bearings of 1e14 N/m, ~1e-9 of the frequencies */
    snprintf(text, sizeof text,
             "material steel E=%g G=%g rho=%g\nshaft from=0 to=%d length=%g od=%g id=%g material=steel\n"
             "bearing node=0 kyy=1e14 kzz=1e14\nbearing node=%d kyy=1e14 kzz=1e14\n",
             E, G, rho, nel, L, od, id, nel);
    whirl_fe_rotor *r = rotor_of(text, msg, sizeof msg);
    if (!ok(r != NULL, "%s, %d elements: reads", what, nel)) continue;
    whirl_fe_mode m[6];
    size_t nf = modes_at(r, 0, WHIRL_FE_EIG_DENSE, 6, m);
    ok(nf == 6, "%s, %d elements: 6 modes", what, nel);
    for (int n = 1; n <= 3 && nf == 6; ++n) {
      const double w = ss_timoshenko(n, L, E, G, rho, od, id), e = fabs(m[2 * n - 1].omega - w) / w;
      printf("# %s %d elements mode %d: FE %.10g closed form %.10g rel err %.3g\n", what, nel, n,
             m[2 * n - 1].omega, w, e);
      if (nel == 32 && n == 1) ok(e < tol1, "%s, 32 elements: mode 1 within %g (%.2g)", what, tol1, e);
      if (nel > 4 && err_prev[n - 1] > 1e-9)
        ok(e < err_prev[n - 1] / rate, "%s mode %d: error / %.1f from %d to %d elements (>= %g)", what,
           n, err_prev[n - 1] / e, nel / 2, nel, rate);
      err_prev[n - 1] = e;
      if (n == 1 && nel == 16) w16 = m[1].omega;
      if (n == 1 && nel == 32) w32 = m[1].omega;
    }
    whirl_fe_rotor_free(r);
  }
  return w32 + (w32 - w16) / 3;
}

static void test_simply_supported(void) {
  check_ss("slender SS shaft", 2.0, 0.02, 0, 9, 2e-7);
  const double w = check_ss("thick hollow SS shaft", 0.6, 0.08, 0.03, 3.8, 2e-5);
  /* h² asymptotically: Richardson ω32 + (ω32 − ω16)/3 is the closed form */
  is_rel(w, ss_timoshenko(1, 0.6, 211e9, 81.2e9, 7810, 0.08, 0.03), 2e-6,
         "thick SS shaft: Richardson-extrapolated (h^2) mode 1 = closed form (shear and Cowper's kappa)");
}

/* ---- (d) structure, dense vs ARPACK ------------------------------------------------ */

static double entry(const whirl_fe_csc *A, int i, int j) {
  for (int k = A->p[j]; k < A->p[j + 1]; ++k)
    if (A->i[k] == i) return A->x[k];
  return 0;
}

static void test_structure(void) {
  char msg[512];
  const char *text =
      "material steel E=211e9 G=81.2e9 rho=7810\n"
      "shaft from=0 to=3 length=0.9 od=0.06 id=0.02 material=steel\n"
      "shaft from=3 to=5 length=0.4 od=0.04 material=steel\n"
      "disk node=2 mass=10 ip=0.1 it=0.06\n"
      "pedestal P mass=20 kyy=1e7 kzz=2e7 cyy=100 czz=100\n"
      "bearing node=0 kyy=1e6 kzz=2e6 kyz=3e5 kzy=-3e5 cyy=1e2\n"
      "bearing node=5 kyy=1e6 kzz=1e6 pedestal=P\n"
      "gravity g=9.81 direction=-z\n"
      "load node=1 fy=5\n";
  whirl_fe_rotor *r = rotor_of(text, msg, sizeof msg);
  if (!ok(r != NULL, "structure rotor reads: %s", r ? "" : msg)) return;
  ok(r->ndof == 6 * 4 + 2, "6 nodes and one pedestal: 26 DOFs");
  double asym = 0, gsym = 0, mass = 0;
  for (int i = 0; i < r->ndof; ++i)
    for (int j = 0; j < r->ndof; ++j) {
      asym = fmax(asym, fabs(entry(&r->M, i, j) - entry(&r->M, j, i)));
      gsym = fmax(gsym, fabs(entry(&r->G, i, j) + entry(&r->G, j, i)));
    }
  ok(asym == 0, "M symmetric");
  ok(gsym == 0, "G skew-symmetric");
  double kasym = 0;
  for (int i = 0; i < r->ndof; ++i)
    for (int j = 0; j < r->ndof; ++j)
      if (i + j != 1) kasym = fmax(kasym, fabs(entry(&r->K, i, j) - entry(&r->K, j, i)));
  ok(kasym == 0, "K symmetric but for the cross-coupling kyz = -kzy of bearing 0");
  is_rel(entry(&r->K, 0, 1), 3e5, 1e-15, "K(y0, z0) = kyz");
  is_rel(entry(&r->K, 1, 0), -3e5, 1e-15, "K(z0, y0) = kzy");
  for (int i = 0; i < r->ndof; ++i)
    for (int j = 0; j < r->ndof; ++j)
      if ((i < 24 && i % 4 == 1) || i == 25)
        if ((j < 24 && j % 4 == 1) || j == 25) mass += entry(&r->M, i, j);
  const double ms = 7810 * PI * ((0.06 * 0.06 - 0.02 * 0.02) / 4 * 0.9 + 0.04 * 0.04 / 4 * 0.4);
  is_rel(mass, ms + 10 + 20, 1e-13, "rigid z translation: 1ᵀM1 = shaft + disk + pedestal mass");
  double fz = 0, fy = 0;
  for (int n = 0; n < r->nnode; ++n) fz += r->f0[4 * n + 1], fy += r->f0[4 * n];
  fz += r->f0[25];
  is_rel(fz, -9.81 * (ms + 30), 1e-13, "f0: gravity sums to the weight");
  is_rel(fy, 5, 1e-15, "f0: the static load fy");
  whirl_fe_rotor_free(r);
}

#ifdef WHIRL_HAVE_ARPACK
static void test_arpack(void) {
  char text[1024], msg[512];
  snprintf(text, sizeof text,
           "material steel E=211e9 G=81.2e9 rho=7810\n"
           "shaft from=0 to=48 length=1.5 od=0.05 material=steel\n"
           "disk node=16 width=0.07 od=0.28 id=0.05 material=steel\n"
           "disk node=32 width=0.07 od=0.35 id=0.05 material=steel\n"
           "bearing node=0 kyy=1e6 kzz=0.8e6 kyz=2e5 kzy=-2e5 cyy=3e3 czz=2e3\n"
           "bearing node=48 kyy=1e6 kzz=0.8e6 cyy=3e3 czz=3e3\n");
  whirl_fe_rotor *r = rotor_of(text, msg, sizeof msg);
  if (!ok(r != NULL, "48-element rotor reads")) return;
  ok(r->ndof == 196, "196 DOFs");
  whirl_fe_mode d[8], a[8];
  size_t nd = modes_at(r, 4000 * RPM, WHIRL_FE_EIG_DENSE, 8, d);
  size_t na = modes_at(r, 4000 * RPM, WHIRL_FE_EIG_ARPACK, 8, a);
  ok(nd == 8 && na == 8, "dense and ARPACK: 8 modes each");
  for (size_t k = 0; k < 8 && k < nd && k < na; ++k) {
    is_rel(a[k].omega, d[k].omega, 1e-9, "ARPACK = dense: omega of mode %zu", k + 1);
    is_abs(a[k].log_dec, d[k].log_dec, 1e-8, "ARPACK = dense: log dec of mode %zu", k + 1);
    ok(a[k].whirl == d[k].whirl, "ARPACK = dense: whirl of mode %zu", k + 1);
  }
  whirl_fe_rotor_free(r);
}

/* A free rotor (no supports: K singular, four rigid-body modes at s = 0):
 * both methods drop the zero eigenvalues and find the first free-free
 * bending mode, (4.730040745/L)² √(EI/ρA) for a slender shaft (Euler-
 * Bernoulli; shear and rotary inertia lower it by ~(r/L)², here 1e-4). */
static void test_free(void) {
  char msg[512];
  whirl_fe_rotor *r = rotor_of("material steel E=211e9 G=81.2e9 rho=7810\n"
                               "shaft from=0 to=40 length=2 od=0.02 material=steel\n",
                               msg, sizeof msg);
  if (!ok(r != NULL, "free rotor reads")) return;
  const double A = PI * 1e-4, I = PI * 1.6e-7 / 64, b = 4.730040745 / 2;
  const double w1 = b * b * sqrt(211e9 * I / (7810 * A));
  whirl_fe_mode d[4], a[4];
  size_t nd = modes_at(r, 0, WHIRL_FE_EIG_DENSE, 4, d), na = modes_at(r, 0, WHIRL_FE_EIG_ARPACK, 4, a);
  ok(nd == 4 && na == 4, "free rotor: 4 modes by each method (rigid-body modes dropped)");
  if (nd == 4 && na == 4) {
    is_rel(d[0].omega, w1, 1e-3, "free rotor: first bending mode (dense) = Euler-Bernoulli free-free");
    is_rel(d[1].omega, w1, 1e-3, "free rotor: its pair");
    /* K is singular (the rigid-body modes), so shift-invert's P = K +
     * sigma D + sigma^2 M is ill conditioned and its solves limit the
     * eigenvalues to ~1e-9 with any LU: UMFPACK's 8.1e-10, 2.8e-10,
     * 1.2e-10, 3.3e-10, KLU's 2.5e-10, 1.5e-9, 2.3e-10, 8.9e-11 (each
     * backward stable to 2e-16); a supported rotor's agree to 1e-9 above */
    for (int k = 0; k < 4; ++k) is_rel(a[k].omega, d[k].omega, 5e-9, "free rotor: ARPACK = dense, mode %d", k + 1);
  }
  whirl_fe_rotor_free(r);
}
#endif

/* ---- (e) names, errors ---------------------------------------------------------------- */

static void test_names(void) {
  const char *names[] = {"sfd-short-pi", "sfd-short-2pi", "sfd-long", "sfd-inertia",
                         "journal-short", "rub", "cubic"};
  for (int k = 0; k < 7; ++k) {
    ok(!strcmp(whirl_fe_nl_kind_name((whirl_fe_nl_kind)k), names[k]), "kind %d is '%s'", k, names[k]);
    ok(whirl_fe_nl_kind_from_name(names[k]) == k, "'%s' is kind %d", names[k], k);
  }
  ok(whirl_fe_nl_kind_from_name("sfd") == -1, "'sfd' is no kind");
  char msg[512];
  whirl_fe_rotor *r = rotor_of(
      "material s E=2e11 G=8e10 rho=7800\nshaft from=0 to=2 length=1 od=0.05 material=s\n"
      "pedestal H mass=5 kyy=1e7 kzz=1e7\n"
      "sfd-short-pi node=1 radius=0.05 length=0.02 clearance=1e-4 viscosity=0.01 offset-z=-2e-5\n"
      "rub node=2 clearance=2e-4 k-contact=1e8 friction=0.1 pedestal=H\n"
      "cubic node=0 k1=1e6 k3=1e12\n",
      msg, sizeof msg);
  if (ok(r != NULL, "a rotor with nonlinear elements reads: %s", r ? "" : msg)) {
    ok(r->nnl == 3, "three nonlinear elements");
    ok(r->nl[0].kind == WHIRL_FE_SFD_SHORT_PI && r->nl[0].node == 1 && r->nl[0].pedestal == -1 &&
           r->nl[0].par.clearance == 1e-4 && r->nl[0].offset[1] == -2e-5 && r->nl[0].line == 4,
       "the SFD: kind, node, ground, clearance, offset, line");
    ok(r->nl[1].kind == WHIRL_FE_RUB && r->nl[1].pedestal == 0 && r->nl[1].par.k_contact == 1e8 &&
           r->nl[1].par.friction == 0.1,
       "the rub: on pedestal H, contact stiffness, friction");
    ok(r->nl[2].par.k1 == 1e6 && r->nl[2].par.k3 == 1e12, "the cubic spring's k1, k3");
    ok(whirl_fe_rotor_dof(r, -1, 1) == 13 && whirl_fe_rotor_dof(r, 2, 3) == 11 &&
           whirl_fe_rotor_dof(r, 3, 0) == -1 && whirl_fe_rotor_dof(r, -2, 0) == -1,
       "whirl_fe_rotor_dof: pedestal and node DOFs, out of range -1");
    whirl_fe_rotor_free(r);
  }
  r = rotor_of("material s E=2e11 G=8e10 rho=7800\nshaft from=0 to=2 length=1 od=0.05 material=s\n"
               "disk node=3 mass=1\n",
               msg, sizeof msg);
  ok(r == NULL && strstr(msg, ":3: disk: node 3 is not on the shaft") != NULL, "error names the line: %s", msg);
}

int main(void) {
  test_friswell();
  test_friswell_damped();
  test_jeffcott_modes();
  test_jeffcott_critical();
  test_jeffcott_unbalance();
  test_simply_supported();
  test_structure();
#ifdef WHIRL_HAVE_ARPACK
  test_arpack();
  test_free();
#else
  ok(1, "# SKIP built without ARPACK: no dense-ARPACK comparison, no free rotor");
#endif
  test_names();
  return done_testing();
}

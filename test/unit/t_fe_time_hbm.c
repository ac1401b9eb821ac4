/* test/unit/t_fe_time_hbm.c — the harmonic balance of an FE rotor
 * (whirl/rotor/fe_hbm.h) against its time integration (BDF, CVODE, on
 * whirl/rotor/fe_ode.h): examples/rotor/sfd-rigid.rotor, a stiff shaft with
 * a disk on two short π-film SFDs (the paper's Table 1), has two stable
 * synchronous orbits between its folds (≈ 664 and ≈ 743 rad/s).  Each branch
 * is reached by natural-parameter Newton steps of the HBM in speed (from
 * 600 rad/s up for the upper one, from 900 rad/s down for the lower one),
 * checked stable by Hill's exponents (the speeds lie between the folds the
 * continuation whirl_fe_response finds, 663.8 and 742.7 rad/s); the integration starts from the HBM
 * orbit at t = 0 displaced by 5 % and runs until the state repeats over a
 * period, then the last period's Fourier coefficients (64 samples) and
 * amplitude at the journal node are compared with the HBM's.  The two
 * routes share only the rotor and the element forces.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/cont.h>
#include <whirl/ode.h>
#include <whirl/rotor/fe_hbm.h>
#include <whirl/rotor/fe_ode.h>

#include "../tap.h"

#define H 3
#define L (2 * H + 1)
#define NS 64

static whirl_fe_rotor *rotor;
static whirl_fe_hbm *hbm;

/* Newton at speeds from → to in steps, X in/out */
static int follow(double *X, double from, double to, double step) {
  const whirl_system *s = whirl_fe_hbm_system(hbm);
  double p[WHIRL_FE_NPAR];
  int its, rc = 0, n = (int)ceil(fabs(to - from) / step - 1e-9);
  for (int k = 0; k <= n && !rc; ++k) {
    whirl_fe_hbm_params(from + (to - from) * k / (n ? n : 1), p);
    rc = whirl_newton(s, X, p, 1e-13, 30, &its);
  }
  return rc;
}

static int stable(const double *X, double Om) {
  double p[WHIRL_FE_NPAR], re[512], im[512];
  size_t m = 512;
  whirl_fe_hbm_params(Om, p);
  if (whirl_fe_hbm_hill(hbm, X, p, re, im, &m) || m == 0) return -1;
  return re[0] < 0;
}

typedef struct samples { double *q; int nd; } samples;

static int take(size_t k, double t, const double *x, void *data) {
  samples *s = data;
  (void)t;
  if (k < NS) memcpy(s->q + (size_t)s->nd * k, x, (size_t)s->nd * sizeof *x);
  return 0;
}

/* BDF from z0 until q repeats over a period to 1e-9 of the amplitude, then
 * the last period's Fourier coefficients into c[nd L] (HBM layout). */
static int integrate(double Om, const double *z0, double amp, double *c,
                     int *periods) {
  whirl_fe_ode *m = whirl_fe_ode_alloc(rotor, NULL, 0);
  const whirl_problem *P = whirl_fe_ode_problem(m);
  const int nd = rotor->ndof;
  double p[WHIRL_FE_NPAR], T = 2 * WHIRL_PI / Om;
  double *prev = malloc((size_t)nd * sizeof *prev);
  whirl_fe_hbm_params(Om, p);
  whirl_ode *ode = whirl_ode_alloc(P, p);
  int rc = whirl_ode_set_method(ode, WHIRL_ODE_BDF);
  rc |= whirl_ode_set_tolerances(ode, 1e-9, 1e-13);
  rc |= whirl_ode_reset(ode, 0.0, z0);
  double d = INFINITY;
  for (*periods = 0; !rc && d > 1e-9 * amp && *periods < 400; ++*periods) {
    memcpy(prev, whirl_ode_x(ode), (size_t)nd * sizeof *prev);
    rc = whirl_ode_evolve(ode, T * (*periods + 1));
    d = 0.0;
    for (int i = 0; i < nd; ++i) d = fmax(d, fabs(whirl_ode_x(ode)[i] - prev[i]));
  }
  samples s = {malloc((size_t)nd * NS * sizeof(double)), nd};
  if (!rc) rc = whirl_ode_sample(ode, T / NS, NS, take, &s);
  memset(c, 0, (size_t)nd * L * sizeof *c);
  for (int j = 0; j < NS && !rc; ++j)
    for (int i = 0; i < nd; ++i) {
      const double y = s.q[(size_t)nd * j + i] / NS;
      c[i] += y;
      for (int k = 1; k <= H; ++k) {
        c[nd * (2 * k - 1) + i] += 2 * y * cos(2 * WHIRL_PI * k * j / NS);
        c[nd * 2 * k + i] += 2 * y * sin(2 * WHIRL_PI * k * j / NS);
      }
    }
  free(s.q); free(prev);
  whirl_ode_free(ode);
  whirl_fe_ode_free(m);
  return rc || d > 1e-9 * amp;
}

/* the state at t = 0 of the HBM orbit q (all DOFs), displaced by a factor */
static void start_state(const double *q, double Om, double f, double *z) {
  const int nd = rotor->ndof;
  for (int i = 0; i < nd; ++i) {
    double y = q[i], v = 0.0;
    for (int k = 1; k <= H; ++k) {
      y += q[nd * (2 * k - 1) + i];
      v += k * Om * q[nd * 2 * k + i];
    }
    z[i] = f * y;
    z[nd + i] = f * v;
  }
}

static double radius(const double *c, int nd, int node) {
  return hypot(c[nd + 4 * node], c[2 * nd + 4 * node]);
}

static double branch_amplitude(const double *X, double Om) {
  double p[WHIRL_FE_NPAR], *q = malloc((size_t)rotor->ndof * L * sizeof *q);
  whirl_fe_hbm_params(Om, p);
  double a = whirl_fe_hbm_recover(hbm, X, p, q) ? NAN : whirl_fe_hbm_amplitude(hbm, q, 0);
  free(q);
  return a;
}

static void compare(const char *branch, const double *X, double Om) {
  const int nd = rotor->ndof;
  double p[WHIRL_FE_NPAR], *q = malloc((size_t)nd * L * sizeof *q);
  double *c = malloc((size_t)nd * L * sizeof *c), *z = malloc(2 * (size_t)nd * sizeof *z);
  whirl_fe_hbm_params(Om, p);
  int rc = whirl_fe_hbm_recover(hbm, X, p, q), periods = 0;
  const double amp = whirl_fe_hbm_amplitude(hbm, q, 0);
  start_state(q, Om, 1.05, z);
  rc |= integrate(Om, z, amp, c, &periods);
  double dc = 0.0;
  for (int k = 0; k < L; ++k) /* the journal node's and the disk's coefficients */
    for (int i = 0; i < 2; ++i)
      for (int node = 0; node <= 2; node += 2)
        dc = fmax(dc, fabs(c[nd * k + 4 * node + i] - q[nd * k + 4 * node + i]));
  /* the time orbit's amplitude at the journal: the radius of its first
   * harmonic (the orbit is a circle: an isotropic rotor, no gravity) */
  const double rmax = radius(c, nd, 0);
  ok(rc == 0 && dc < 1e-6 * amp && fabs(rmax - amp) < 1e-6 * amp,
     "%s branch, %.0f rad/s: BDF steady state after %d periods = HBM (H = %d): "
     "coefficients %.2e, amplitude %.9e m vs %.9e m (%.1e)",
     branch, Om, periods, H, dc / amp, rmax, amp, fabs(rmax - amp) / amp);
  free(q); free(c); free(z);
}

int main(void) {
  char msg[512] = "";
  const char *src = getenv("top_srcdir");
  char path[1024];
  snprintf(path, sizeof path, "%s/examples/rotor/sfd-rigid.rotor", src ? src : ".");
  rotor = whirl_fe_rotor_read(path, msg, sizeof msg, NULL);
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = H;
  hbm = rotor ? whirl_fe_hbm_alloc(rotor, &o, msg, sizeof msg) : NULL;
  if (!ok(hbm != NULL, "read %s and set up the HBM %s", path, msg)) return done_testing();
  const size_t n = whirl_fe_hbm_size(hbm);
  double *Xu = calloc(n, sizeof *Xu), *Xl = calloc(n, sizeof *Xl);
  const double speeds[2] = {690.0, 725.0};
  /* the upper branch from below, the lower from above */
  int rc = follow(Xu, 300.0, speeds[0], 10.0) | follow(Xl, 900.0, speeds[0], 10.0);
  for (int k = 0; k < 2; ++k) {
    const double Om = speeds[k];
    if (k) rc |= follow(Xu, speeds[0], Om, 5.0) | follow(Xl, speeds[0], Om, 5.0);
    double au = branch_amplitude(Xu, Om), al = branch_amplitude(Xl, Om);
    ok(rc == 0 && stable(Xu, Om) == 1 && stable(Xl, Om) == 1 && au > 1.2 * al,
       "%.0f rad/s: two HBM orbits, stable by Hill, journal amplitudes %.4g "
       "and %.4g of the clearance", Om, au / 1e-4, al / 1e-4);
    compare("upper", Xu, Om);
    compare("lower", Xl, Om);
  }
  free(Xu); free(Xl);
  whirl_fe_hbm_free(hbm);
  whirl_fe_rotor_free(rotor);
  return done_testing();
}

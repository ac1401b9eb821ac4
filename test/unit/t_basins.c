/* test/unit/t_basins.c — time-domain analysis of the SFD rotor: frames,
 * circular orbits at one speed (eq. 15) against integration, Floquet
 * multipliers by the variational equations against the rotating-frame
 * eigenvalues, the Lyapunov certificates checked by integration, basins
 * identical for 1 and 2 threads and equal to the fixed-horizon result, and
 * bad input.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "../tap.h"

static void table1(double *p, double Om) {
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = Om;
}

static void test_frames(void) {
  const double Om = 2.3, t = 0.77, x[4] = {0.3, -0.2, 0.5, 0.9};
  double xr[4], xb[4];
  whirl_sfd_to_rotating(Om, t, x, xr);
  whirl_sfd_to_fixed(Om, t, xr, xb);
  double err = 0;
  for (int i = 0; i < 4; ++i) err = fmax(err, fabs(xb[i] - x[i]));
  ok(err < 1e-15, "rotating -> fixed frame round trip (err %.1e)", err);
  /* a rotating-frame equilibrium (u, v, 0, 0) is a circle travelled with
   * velocity Omega (-z, y) */
  const double w[4] = {0.4, 0.1, 0, 0};
  whirl_sfd_to_fixed(Om, t, w, xb);
  double vy, vz;
  whirl_sfd_circular_velocity(Om, xb[0], xb[1], &vy, &vz);
  is_abs(xb[2], vy, 1e-15, "circular velocity y' = -Omega z");
  is_abs(xb[3], vz, 1e-15, "circular velocity z' = Omega y");
  is_rel(hypot(xb[0], xb[1]), hypot(0.4, 0.1), 1e-15, "radius kept by the frame change");
}

static void test_circular_orbits(void) {
  double p[5], eps[16], mr[16];
  int st[16];
  size_t n = 0;
  table1(p, 1.78);
  int rc = whirl_sfd_circular_orbits(p, eps, st, mr, 16, &n);
  ok(rc == WHIRL_OK && n == 3, "Omega = 1.78 (region B): three circular orbits (got %zu)", n);
  if (n == 3) {
    ok(st[0] == 1 && st[1] == 0 && st[2] == 1, "stable, unstable, stable (got %d %d %d)", st[0], st[1], st[2]);
    for (int i = 0; i < 3; ++i) {
      /* independent: eq. 15 solved for Omega at this radius contains 1.78 */
      double Oms[4];
      int nr = 0;
      whirl_sfd_circ_roots(eps[i], p[1], p[2], p[3], Oms, &nr);
      double best = INFINITY;
      for (int k = 0; k < nr; ++k) best = fmin(best, fabs(Oms[k] - 1.78));
      ok(best < 1e-9, "eps = %.10f is a root of eq. 15 at Omega = 1.78 (|dOmega| = %.1e)", eps[i], best);
    }
  }
  table1(p, 1.0);
  whirl_sfd_circular_orbits(p, eps, st, mr, 16, &n);
  ok(n == 1 && st[0] == 1, "Omega = 1 (region A): one stable orbit (got %zu)", n);
  table1(p, 8.5327);
  whirl_sfd_circular_orbits(p, eps, st, mr, 16, &n);
  ok(n == 3 && st[0] == 1 && st[1] == 0 && st[2] == 1,
     "Omega = 8.5327 (region D): main branch stable, isola lower unstable, upper stable (n = %zu)", n);
  table1(p, 1.0);
  p[WHIRL_SFD_FE] = 0.1;
  ok(whirl_sfd_circular_orbits(p, eps, st, mr, 16, &n) == WHIRL_EINVAL, "FE != 0 rejected");
}

/* The circular orbit integrated in the fixed frame stays on its circle, and
 * its monodromy eigenvalues are exp(mu T) of the rotating frame. */
static void test_integrate_circle(void) {
  double p[5], eps[16], mr[16];
  int st[16];
  size_t n = 0;
  table1(p, 1.78);
  whirl_sfd_circular_orbits(p, eps, st, mr, 16, &n);
  for (size_t i = 0; i < n && i < 3; ++i) {
    double xr[4], x[4];
    whirl_sfd_circ_state(eps[i], p[0], p[1], p[2], p[3], xr);
    whirl_sfd_to_fixed(p[0], 0.0, xr, x);
    const double T = 2 * M_PI / p[0];
    whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
    whirl_ode_reset(ode, 0.0, x);
    int rc = whirl_ode_evolve(ode, 3 * T);
    const double *xe = whirl_ode_x(ode);
    ok(rc == WHIRL_OK && fabs(hypot(xe[0], xe[1]) - eps[i]) < 1e-9,
       "orbit %zu: integrated 3 periods stays at eps = %.10f (err %.1e)", i, eps[i],
       fabs(hypot(xe[0], xe[1]) - eps[i]));
    whirl_ode_free(ode);

    /* Floquet multipliers: variational equations vs exp(mu T) */
    double M[16], xT[4], J[16], re[4], im[4], mre[4], mim[4];
    char msg[256];
    rc = whirl_ode_monodromy(whirl_sfd_fixed(), p, 0.0, x, T, 1e-12, 1e-15, xT, M, NULL, msg, sizeof msg);
    whirl_sfd_rotating()->jac_x(0, xr, p, J, NULL);
    whirl_eig *e = whirl_eig_alloc(4);
    whirl_eig_compute(e, J, re, im);
    whirl_eig_compute(e, M, mre, mim);
    whirl_eig_free(e);
    double a[4], b[4];
    for (int k = 0; k < 4; ++k) {
      a[k] = exp(re[k] * T);
      b[k] = hypot(mre[k], mim[k]);
    }
    /* compare the sorted moduli */
    for (int s = 0; s < 4; ++s)
      for (int k = 0; k + 1 < 4; ++k) {
        if (a[k] < a[k + 1]) { double t = a[k]; a[k] = a[k + 1]; a[k + 1] = t; }
        if (b[k] < b[k + 1]) { double t = b[k]; b[k] = b[k + 1]; b[k + 1] = t; }
      }
    double err = 0;
    for (int k = 0; k < 4; ++k) err = fmax(err, fabs(a[k] - b[k]) / fmax(1.0, a[k]));
    ok(rc == WHIRL_OK && err < 1e-8,
       "orbit %zu: |Floquet multipliers| by eq. 24 = exp(Re mu T) of the rotating frame (err %.1e)", i, err);
  }
}

/* The certified level: states on the boundary V = rho, integrated in the
 * fixed frame, converge to the orbit (an independent route). */
static void test_certificate(void) {
  double p[5];
  table1(p, 1.78);
  whirl_sfd_attractors_options o;
  whirl_sfd_attractors_options_default(&o);
  o.find_cycle = 0;
  whirl_sfd_attractors *A = NULL;
  char msg[256];
  int rc = whirl_sfd_attractors_find(p, &o, &A, msg, sizeof msg);
  ok(rc == WHIRL_OK && whirl_sfd_attractors_count(A) == 2, "Omega = 1.78: two attractors (%s)", msg);
  if (rc != WHIRL_OK) return;
  const whirl_sfd_attractor_info *s = whirl_sfd_attractors_info(A, 0), *l = whirl_sfd_attractors_info(A, 1);
  ok(s && l && !strcmp(s->name, "small") && !strcmp(l->name, "large") && s->eps < l->eps,
     "named small (eps %.4f) and large (eps %.4f)", s ? s->eps : NAN, l ? l->eps : NAN);
  ok(s && l && s->level > 0 && l->level > 0, "positive certified levels (%.3g, %.3g)", s ? s->level : NAN,
     l ? l->level : NAN);
  const whirl_attractor *att = whirl_sfd_attractors_list(A);
  /* points just inside the certified set of each attractor: search along
   * rays for the boundary with the test itself, then integrate */
  int conv_all = 1, stay_all = 1;
  for (size_t j = 0; j < 2; ++j) {
    const whirl_sfd_attractor_info *in = whirl_sfd_attractors_info(A, j);
    double xs[4];
    whirl_sfd_circ_state(in->eps, p[0], p[1], p[2], p[3], xs);
    for (int k = 0; k < 8; ++k) {
      double d[4] = {cos(k * 0.9), sin(k * 1.7), cos(k * 2.3 + 1), sin(k * 0.4 + 2)};
      double lo = 0, hi = 1;
      for (int it = 0; it < 50; ++it) {
        double m = 0.5 * (lo + hi), xr[4], x[4];
        for (int i = 0; i < 4; ++i) xr[i] = xs[i] + m * d[i];
        whirl_sfd_to_fixed(p[0], 0.0, xr, x);
        if (hypot(x[0], x[1]) < 1 && att[j].test(0.0, x, att[j].data) == 1) lo = m;
        else hi = m;
      }
      double xr[4], x[4];
      for (int i = 0; i < 4; ++i) xr[i] = xs[i] + 0.999 * lo * d[i];
      whirl_sfd_to_fixed(p[0], 0.0, xr, x);
      whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
      whirl_ode_reset(ode, 0.0, x);
      const double T = 2 * M_PI / p[0];
      for (int per = 1; per <= 60; ++per) {
        if (whirl_ode_evolve(ode, per * T) != WHIRL_OK) { stay_all = 0; break; }
        if (att[j].test(per * T, whirl_ode_x(ode), att[j].data) != 1) stay_all = 0;
      }
      double xe[4];
      whirl_sfd_to_rotating(p[0], 60 * T, whirl_ode_x(ode), xe);
      double dist = 0;
      for (int i = 0; i < 4; ++i) dist = fmax(dist, fabs(xe[i] - xs[i]));
      if (!(dist < 0.1 * lo)) conv_all = 0;
      whirl_ode_free(ode);
    }
  }
  ok(stay_all, "trajectories from the certified boundary stay in the set for 60 periods");
  ok(conv_all, "and approach their orbit");
  whirl_sfd_attractors_free(A);
}

static void test_basins_threads(void) {
  double p[5];
  table1(p, 1.78);
  whirl_sfd_attractors_options o;
  whirl_sfd_attractors_options_default(&o);
  o.find_cycle = 0;
  whirl_sfd_attractors *A = NULL;
  char msg[256];
  if (whirl_sfd_attractors_find(p, &o, &A, msg, sizeof msg) != WHIRL_OK) {
    ok(0, "attractors: %s", msg);
    return;
  }
  size_t n = whirl_sfd_disc_points(60, 0.98, NULL, 0);
  double *yz = malloc(2 * n * sizeof *yz), *X = malloc(4 * n * sizeof *X);
  whirl_sfd_disc_points(60, 0.98, yz, n);
  for (size_t i = 0; i < n; ++i) {
    X[4 * i] = yz[2 * i];
    X[4 * i + 1] = yz[2 * i + 1];
    X[4 * i + 2] = X[4 * i + 3] = 0;
  }
  int *w1 = malloc(n * sizeof(int)), *w2 = malloc(n * sizeof(int)), *w3 = malloc(n * sizeof(int));
  unsigned *p1 = malloc(n * sizeof(unsigned)), *p2 = malloc(n * sizeof(unsigned));
  whirl_basins_options bo;
  whirl_basins_options_default(&bo);
  bo.period = 2 * M_PI / p[0];
  bo.max_periods = 400;
  bo.rtol = 1e-10;
  bo.atol = 1e-13;
  bo.nthreads = 1;
  int rc1 = whirl_basins_compute(whirl_sfd_fixed(), p, n, X, whirl_sfd_attractors_list(A), 2, &bo, w1, p1,
                                 NULL, msg, sizeof msg);
  bo.nthreads = 2;
  int rc2 = whirl_basins_compute(whirl_sfd_fixed(), p, n, X, whirl_sfd_attractors_list(A), 2, &bo, w2, p2,
                                 NULL, msg, sizeof msg);
  ok(rc1 == WHIRL_OK && rc2 == WHIRL_OK, "basins on 1 and 2 threads run (%zu points)", n);
  ok(!memcmp(w1, w2, n * sizeof(int)) && !memcmp(p1, p2, n * sizeof(unsigned)),
     "identical classification and periods on 1 and 2 threads");
  size_t settled = 0, both = 0, maxper = 0;
  for (size_t i = 0; i < n; ++i) {
    settled += w1[i] >= 0;
    if (p1[i] > maxper) maxper = p1[i];
  }
  for (size_t i = 0; i < n; ++i) both += w1[i] == 1;
  ok(settled == n, "every point settles within 400 periods (%zu of %zu; slowest %zu periods)", settled, n, maxper);
  ok(both > 0 && both < n, "both orbits attract some points (large: %zu of %zu)", both, n);
  bo.fixed_horizon = 1;
  bo.max_periods = maxper + 50;
  bo.nthreads = 2;
  int rc3 = whirl_basins_compute(whirl_sfd_fixed(), p, n, X, whirl_sfd_attractors_list(A), 2, &bo, w3, NULL,
                                 NULL, msg, sizeof msg);
  ok(rc3 == WHIRL_OK && !memcmp(w1, w3, n * sizeof(int)),
     "fixed horizon of %zu periods gives the same classification as the early exit", maxper + 50);

  /* a state touching the housing is classified as contact, not integrated */
  {
    const double xc[4] = {1.01, 0, 0, 0};
    int wc = 99;
    unsigned pc = 99;
    bo.period = 2 * M_PI / p[0];
    bo.fixed_horizon = 0;
    int rcc = whirl_basins_compute(whirl_sfd_fixed(), p, 1, xc, whirl_sfd_attractors_list(A), 2, &bo, &wc,
                                   &pc, NULL, msg, sizeof msg);
    ok(rcc == WHIRL_OK && wc == WHIRL_BASIN_DOMAIN, "initial state with eps = 1.01 is contact (got %d)", wc);
  }
  /* bad input */
  bo.period = 0;
  ok(whirl_basins_compute(whirl_sfd_fixed(), p, n, X, whirl_sfd_attractors_list(A), 2, &bo, w3, NULL, NULL,
                          msg, sizeof msg) == WHIRL_EINVAL && strstr(msg, "period"),
     "period 0 rejected: %s", msg);
  free(yz);
  free(X);
  free(w1);
  free(w2);
  free(w3);
  free(p1);
  free(p2);
  whirl_sfd_attractors_free(A);
}

static void test_inputs(void) {
  size_t n = whirl_sfd_disc_points(8000, 0.98, NULL, 0);
  ok(fabs((double)n - 8000) < 0.02 * 8000, "disc lattice: %zu points for 8000 asked", n);
  double *yz = malloc(2 * n * sizeof *yz);
  whirl_sfd_disc_points(8000, 0.98, yz, n);
  double rmax = 0;
  for (size_t i = 0; i < n; ++i) rmax = fmax(rmax, hypot(yz[2 * i], yz[2 * i + 1]));
  ok(rmax <= 0.98 && rmax > 0.96, "all inside 98 %% of the clearance (max %.4f)", rmax);
  free(yz);
  ok(whirl_sfd_disc_points(0, 0.98, NULL, 0) == 0, "no points for n = 0");

  double p[5];
  table1(p, 1.78);
  p[WHIRL_SFD_FE] = 0.2;
  whirl_sfd_attractors *A = NULL;
  char msg[256];
  ok(whirl_sfd_attractors_find(p, NULL, &A, msg, sizeof msg) == WHIRL_EINVAL && A == NULL && strstr(msg, "FE"),
     "attractors with FE != 0 rejected: %s", msg);
  table1(p, -1);
  ok(whirl_sfd_attractors_find(p, NULL, &A, msg, sizeof msg) == WHIRL_EINVAL, "Omega < 0 rejected: %s", msg);
  table1(p, 2.0);
  p[WHIRL_SFD_LAMBDA] = NAN;
  ok(whirl_sfd_attractors_find(p, NULL, &A, msg, sizeof msg) == WHIRL_EINVAL, "NaN lambda rejected: %s", msg);
  table1(p, 2.0);
  double out[8];
  ok(whirl_sfd_trajectory_samples(p, NULL, 1, 0, 2, 1e-9, 1e-12, out, msg, sizeof msg) == WHIRL_EINVAL,
     "trajectory samples with an empty span rejected");
}

/* Absurd options are refused with a message, before any thread starts
 * (100000 threads crashed libgomp; rtol = 1 or atol = 16 made the steps
 * crawl for minutes). */
static void test_option_limits(void) {
  double p[5], x0[4] = {0.1, 0, 0, 0}, t = 2 * M_PI / 1.78;
  table1(p, 1.78);
  whirl_basins_options bo;
  whirl_basins_options_default(&bo);
  bo.period = t;
  bo.max_periods = 1;
  int which = 99;
  char msg[256];
  const struct { int nthreads; double rtol, atol; const char *word; } bad[] = {
      {100000, 1e-12, 1e-15, "nthreads"}, {-1, 1e-12, 1e-15, "nthreads"},
      {1, 1.0, 1e-15, "rtol"},            {1, 1e-16, 1e-15, "rtol"},
      {1, 1e-12, 16.0, "atol"},           {1, 1e-12, 0.0, "atol"}};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    bo.nthreads = bad[k].nthreads;
    bo.rtol = bad[k].rtol;
    bo.atol = bad[k].atol;
    int rc = whirl_basins_compute(whirl_sfd_fixed(), p, 1, x0, NULL, 0, &bo, &which, NULL, NULL, msg,
                                  sizeof msg);
    ok(rc == WHIRL_EINVAL && strstr(msg, bad[k].word) && which == 99,
       "basins refuse nthreads %d, rtol %g, atol %g: %s", bad[k].nthreads, bad[k].rtol, bad[k].atol, msg);
  }
  whirl_sfd_attractors_options ao;
  whirl_sfd_attractors_options_default(&ao);
  ao.atol = 16;
  whirl_sfd_attractors *A = NULL;
  ok(whirl_sfd_attractors_find(p, &ao, &A, msg, sizeof msg) == WHIRL_EINVAL && A == NULL && strstr(msg, "atol"),
     "attractors refuse atol 16: %s", msg);
}

int main(void) {
  test_option_limits();
  test_frames();
  test_circular_orbits();
  test_integrate_circle();
  test_certificate();
  test_basins_threads();
  test_inputs();
  return done_testing();
}

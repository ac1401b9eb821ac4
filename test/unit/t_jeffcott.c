/* test/unit/t_jeffcott.c — the Jeffcott rotor of the rotor module
 * (rotor/jeffcott.c, doc/jeffcott-model.md), through the public
 * API only:
 *  (a) analytic jac_x, jac_p against central differences at random states
 *      and parameters (and a deliberately broken Jacobian must fail);
 *  (b) rigid limit: with y_d = y_j the mass-weighted sum of the equations is
 *      whirl_sfd_fixed() exactly; the HBM synchronous orbits for kappa = 1e4
 *      ... 1e8 converge to those of whirl_sfd_fixed (paper Table 1, the three
 *      orbits at Omega = 1.78) at the rate 1/kappa, with the disc-journal
 *      offset of the first-order expansion; long time integration at
 *      kappa = 1e4 lands on the rigid rotor's orbit to O(1/kappa);
 *  (c) circular orbits: an independent closed form (journal radius eps on
 *      eps |D_j D_d - kappa^2/4| = (kappa/2) delta Omega^2, doc §5) against
 *      HBM (all roots, folds included) and against time integration; the
 *      linear limit (force -pi lambda v) against HBM to O(delta^2);
 *  (d) contact (eps >= 1) is WHIRL_SFD_CONTACT in every callback.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "../../rotor/jeffcott.c"

#include <complex.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "../tap.h"

#define PI 3.14159265358979323846

static const whirl_problem *jeff = &jeffcott_model.problem;

/* ------------------------------------------------------------------------
 * Closed form of the synchronous circular orbits (doc/jeffcott-model.md §5).
 * Journal w_j = W_j e^{iΩτ}, |W_j| = ε; disc w_d = W_d e^{iΩτ}.  The π-film
 * force on a circular orbit is (a + ib) Ω W_j / ε with a = −4λε²/s²,
 * b = −πλε/s^{3/2}, s = 1 − ε² (whirl/rotor/sfd.h); `linear` replaces it by the
 * ε → 0 value −iπλΩ W_j (force −πλ v). */
static double complex circ_Dd(const double *p) {
  return 0.5 * p[J_KAPPA] - p[J_ALPHA] * p[J_OMEGA] * p[J_OMEGA] +
         2.0 * I * p[J_ZETA] * p[J_OMEGA];
}
static double complex circ_Dj(double eps, const double *p, int linear) {
  const double Om = p[J_OMEGA], la = p[J_LAMBDA], s = 1.0 - eps * eps;
  const double a_e = linear ? 0.0 : -4.0 * la * eps / (s * s);
  const double b_e = linear ? -PI * la : -PI * la / (s * sqrt(s));
  return 1.0 + 0.5 * p[J_KAPPA] - (1.0 - p[J_ALPHA]) * Om * Om -
         (a_e + I * b_e) * Om;
}
static double circ_G(double eps, const double *p) {
  const double hk = 0.5 * p[J_KAPPA], Om = p[J_OMEGA];
  return eps * cabs(circ_Dj(eps, p, 0) * circ_Dd(p) - hk * hk) -
         hk * p[J_DELTA] * Om * Om;
}
static void circ_amps(double eps, const double *p, int linear,
                      double complex *Wd, double complex *Wj) {
  const double hk = 0.5 * p[J_KAPPA], u = p[J_DELTA] * p[J_OMEGA] * p[J_OMEGA];
  const double complex Dd = circ_Dd(p);
  *Wj = hk * u / (circ_Dj(eps, p, linear) * Dd - hk * hk);
  *Wd = (u + hk * *Wj) / Dd;
}
/* All roots ε in (0, 1) of circ_G: sign changes on a grid, then bisection. */
static size_t circ_roots(const double *p, double *eps, size_t maxn) {
  size_t n = 0;
  const int M = 4000;
  double e0 = 0.0, g0 = circ_G(0.0, p);
  for (int i = 1; i < M; ++i) {
    const double q = (double)i / M, e1 = 1.0 - (1.0 - q) * (1.0 - q);
    const double g1 = circ_G(e1, p);
    if ((g0 < 0) != (g1 < 0) && n < maxn) {
      double lo = e0, hi = e1, glo = g0;
      for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
        const double m = 0.5 * (lo + hi), gm = circ_G(m, p);
        if ((gm < 0) == (glo < 0)) lo = m, glo = gm;
        else hi = m;
      }
      eps[n++] = 0.5 * (lo + hi);
    }
    e0 = e1, g0 = g1;
  }
  return n;
}

/* ------------------------------------------------------------------------
 * HBM coefficients of synchronous circular orbits.  A body b (of nb) has
 * position components (2b, 2b+1) and velocities (2nb + 2b, 2nb + 2b + 1);
 * y + iz = W e^{iΩτ} gives y: a1 = Re W, b1 = −Im W; z: a1 = Im W,
 * b1 = Re W; y': a1 = −Ω Im W, b1 = −Ω Re W; z': a1 = Ω Re W, b1 = −Ω Im W. */
static void set_circ(double *X, size_t L, size_t nb, size_t b, double Om,
                     double complex W) {
  const double R = creal(W), M = cimag(W);
  const size_t iy = 2 * b, iz = iy + 1, ivy = 2 * nb + 2 * b, ivz = ivy + 1;
  X[iy * L + 1] = R, X[iy * L + 2] = -M;
  X[iz * L + 1] = M, X[iz * L + 2] = R;
  X[ivy * L + 1] = -Om * M, X[ivy * L + 2] = -Om * R;
  X[ivz * L + 1] = Om * R, X[ivz * L + 2] = -Om * M;
}
/* W of component pair (iy, iy+1) from its first harmonic (y alone). */
static double complex get_W(const double *X, size_t L, size_t iy) {
  return X[iy * L + 1] - I * X[iy * L + 2];
}
/* Largest |coefficient| of harmonics 2..N over all components. */
static double higher_harmonics(const double *X, size_t n, size_t L) {
  double m = 0.0;
  for (size_t i = 0; i < n; ++i) {
    m = fmax(m, fabs(X[i * L]));
    for (size_t q = 3; q < L; ++q) m = fmax(m, fabs(X[i * L + q]));
  }
  return m;
}

static whirl_hbm *hbm_of(const whirl_problem *prob, size_t N) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o);
  o.harmonics = N;
  o.oversampling = 4;
  o.forcing_param = 0;
  o.no_spectrum = 1;
  char err[256] = "";
  whirl_hbm *h = whirl_hbm_alloc(prob, &o, err, sizeof err);
  if (h == NULL) printf("# hbm_alloc(%s): %s\n", prob->name, err);
  return h;
}

/* Table 1 with the defaults of the model for alpha, kappa. */
static void table1(double *p, double Om, double zeta, double alpha,
                   double kappa) {
  p[J_OMEGA] = Om, p[J_LAMBDA] = 0.0503, p[J_DELTA] = 0.3, p[J_ZETA] = zeta;
  p[J_ALPHA] = alpha, p[J_KAPPA] = kappa;
}

/* ------------------------------------------------------------------------
 * The model description itself. */
static void test_model(void) {
  const whirl_model *m = whirl_rotor_jeffcott();
  ok(m->abi == WHIRL_MODEL_ABI && jeff->n == 8 && jeff->npar == 6 &&
         m->forcing_param == 0 && jeff->autonomous == 0,
     "model: abi %d, n 8, npar 6, forced at p[0]", m->abi);
  static const char *const want[6] = {"Omega", "lambda", "delta",
                                      "zeta",  "alpha",  "kappa"};
  int names = 1;
  for (int k = 0; k < 6; ++k) names &= strcmp(jeff->p_names[k], want[k]) == 0;
  ok(names, "parameter names Omega lambda delta zeta alpha kappa");
  double f[8];
  int rc = jeff->rhs(0.0, m->u0, m->par0, f, NULL);
  ok(rc == 0 && m->par0[J_ALPHA] > 0 && m->par0[J_ALPHA] < 1 &&
         m->par0[J_KAPPA] > 0,
     "defaults par0 = (%g, %g, %g, %g, %g, %g) are in the domain",
     m->par0[0], m->par0[1], m->par0[2], m->par0[3], m->par0[4], m->par0[5]);
}

/* ------------------------------------------------------------------------
 * (a) Jacobians */
static int bad_jac_x(double t, const double *x, const double *p, double *J,
                     void *data) {
  int rc = jeffcott_jac_x(t, x, p, J, data);
  J[6 + 8 * 3] += 1e-4; /* d f_yj'' / d z_j slightly wrong */
  return rc;
}

static void random_state(double *x, double eps_j) {
  const double th = tap_urand(0.0, 2.0 * PI);
  x[0] = tap_urand(-2.0, 2.0), x[1] = tap_urand(-2.0, 2.0);
  x[2] = eps_j * cos(th), x[3] = eps_j * sin(th);
  for (int i = 4; i < 8; ++i) x[i] = tap_urand(-2.0, 2.0);
}

static void test_jacobians(void) {
  double worst = 0.0;
  int fails = 0;
  for (int k = 0; k < 16; ++k) {
    double p[6], x[8];
    p[J_OMEGA] = tap_urand(0.2, 8.0);
    p[J_LAMBDA] = tap_urand(0.01, 1.5);
    p[J_DELTA] = tap_urand(0.0, 0.9);
    p[J_ZETA] = tap_urand(0.0, 0.1);
    p[J_ALPHA] = tap_urand(0.05, 0.95);
    p[J_KAPPA] = tap_urand(0.5, 100.0);
    random_state(x, k == 0 ? 0.0 : tap_urand(0.05, 0.8));
    const double t = tap_urand(0.0, 10.0);
    double e = INFINITY;
    if (whirl_check_jacobian(jeff, t, x, p, &e) != 0) ++fails;
    worst = fmax(worst, e);
  }
  ok(fails == 0 && worst < 1e-6,
     "jac_x, jac_p = central differences at 16 random points, eps_j = 0 "
     "included (max rel err %.1e < 1e-6)", worst);
  /* the check can fail: an error of 1e-4 in one entry is seen */
  whirl_problem bad = *jeff;
  bad.jac_x = bad_jac_x;
  double p[6], x[8], e = 0.0;
  table1(p, 1.7, 0.02, 0.4, 12.0);
  random_state(x, 0.5);
  whirl_check_jacobian(&bad, 0.3, x, p, &e);
  ok(e > 1e-6, "a Jacobian entry off by 1e-4 is caught (%.1e)", e);
}

/* ------------------------------------------------------------------------
 * (b) rigid limit */
static void test_rigid_identity(void) {
  /* y_d = y_j, v_d = v_j: α f_d + (1 − α) f_j is the rigid rotor's y'',
   * for any kappa (the shaft force cancels) */
  double worst = 0.0;
  for (int k = 0; k < 10; ++k) {
    double p[6], x[8], q[WHIRL_SFD_NPAR], xs[4], f[8], fs[4];
    table1(p, tap_urand(0.2, 8.0), tap_urand(0, 0.1), tap_urand(0.05, 0.95),
           tap_urand(0.5, 1e3));
    p[J_LAMBDA] = tap_urand(0.01, 1.5), p[J_DELTA] = tap_urand(0, 0.9);
    random_state(x, tap_urand(0.0, 0.9));
    x[0] = x[2], x[1] = x[3], x[4] = x[6], x[5] = x[7];
    q[WHIRL_SFD_OMEGA] = p[J_OMEGA], q[WHIRL_SFD_LAMBDA] = p[J_LAMBDA];
    q[WHIRL_SFD_DELTA] = p[J_DELTA], q[WHIRL_SFD_ZETA] = p[J_ZETA];
    q[WHIRL_SFD_FE] = 0.0;
    xs[0] = x[2], xs[1] = x[3], xs[2] = x[6], xs[3] = x[7];
    const double t = tap_urand(0, 10), al = p[J_ALPHA];
    jeff->rhs(t, x, p, f, NULL);
    whirl_sfd_fixed()->rhs(t, xs, q, fs, NULL);
    for (int c = 0; c < 2; ++c) {
      const double sum = al * f[4 + c] + (1 - al) * f[6 + c];
      worst = fmax(worst, fabs(sum - fs[2 + c]) / (1 + fabs(fs[2 + c])));
    }
  }
  ok(worst < 1e-13,
     "y_d = y_j: alpha y_d'' + (1 - alpha) y_j'' = whirl_sfd_fixed y'' (%.1e)",
     worst);
}

/* Solve the rigid rotor's synchronous orbits by HBM and the Jeffcott rotor's
 * from them for growing kappa. */
static void test_rigid_hbm(void) {
  const size_t N = 3, L = 2 * N + 1;
  whirl_hbm *hs = hbm_of(whirl_sfd_fixed(), N), *hj = hbm_of(jeff, N);
  if (!hs || !hj) {
    ok(0, "HBM objects");
    whirl_hbm_free(hs), whirl_hbm_free(hj);
    return;
  }
  const whirl_system *ss = whirl_hbm_system(hs), *sj = whirl_hbm_system(hj);
  const double Om = 1.78, al = 0.4;
  double q[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(q); /* Table 1, ζ = 0, F_E = 0 */
  q[WHIRL_SFD_OMEGA] = Om;
  double eps[4], mre[4];
  int st[4];
  size_t no = 0;
  whirl_sfd_circular_orbits(q, eps, st, mre, 4, &no);
  ok(no == 3, "Table 1, Omega = 1.78: three rigid-rotor orbits (%zu)", no);
  const double kap[4] = {1e4, 1e5, 1e6, 1e8};
  for (size_t k = 0; k < no; ++k) {
    /* rigid rotor: HBM Newton from eq. 15's orbit */
    double xr[4], Xs[4 * 7], Xj[8 * 7];
    whirl_sfd_circ_state(eps[k], Om, q[1], q[2], q[3], xr);
    const double complex Ws = xr[0] + I * xr[1];
    memset(Xs, 0, sizeof Xs);
    set_circ(Xs, L, 1, 0, Om, Ws * (1 + 1e-4));
    int its, rc = whirl_newton(ss, Xs, q, 1e-12, 20, &its);
    ok(rc == 0 && fabs(cabs(get_W(Xs, L, 0)) - eps[k]) < 1e-10,
       "rigid orbit %zu: HBM eps %.10f = eq. 15", k, eps[k]);
    const double complex Wr = get_W(Xs, L, 0);
    double dev[4] = {0}, off[4] = {0};
    for (int m = 0; m < 4; ++m) {
      double p[6];
      table1(p, Om, 0.0, al, kap[m]);
      memset(Xj, 0, sizeof Xj);
      set_circ(Xj, L, 2, 0, Om, Wr);
      set_circ(Xj, L, 2, 1, Om, Wr);
      /* kappa = 1e8: the residual carries kappa * rounding of y_d − y_j */
      rc = whirl_newton(sj, Xj, p, kap[m] > 1e7 ? 1e-7 : 1e-10, 20, &its);
      if (rc != 0) {
        ok(0, "orbit %zu kappa %g: Newton rc %d", k, kap[m], rc);
        dev[m] = NAN;
        continue;
      }
      for (size_t c = 0; c < 4; ++c)
        for (size_t h = 0; h < L; ++h) {
          const size_t cd = c < 2 ? c : c + 2, cj = cd + 2; /* y,z,y',z' */
          dev[m] = fmax(dev[m], fabs(Xj[cd * L + h] - Xs[c * L + h]));
          dev[m] = fmax(dev[m], fabs(Xj[cj * L + h] - Xs[c * L + h]));
        }
      /* first order: (κ/2)(W_d − W_j) = δΩ² + (αΩ² − 2iζΩ) W_rigid */
      const double complex D = get_W(Xj, L, 0) - get_W(Xj, L, 2);
      const double complex want = q[2] * Om * Om + al * Om * Om * Wr;
      off[m] = cabs(0.5 * kap[m] * D - want) / cabs(want);
    }
    printf("# orbit %zu (eps %.4f): max|X_jeffcott - X_rigid| = %.2e %.2e "
           "%.2e %.2e for kappa 1e4 1e5 1e6 1e8\n",
           k, eps[k], dev[0], dev[1], dev[2], dev[3]);
    ok(dev[3] < 1e-6, "orbit %zu, kappa = 1e8: disc and journal on the rigid "
       "orbit, max coefficient difference %.1e < 1e-6", k, dev[3]);
    const double r1 = dev[0] * 1e4, r2 = dev[1] * 1e5, r3 = dev[2] * 1e6;
    ok(fabs(r2 / r1 - 1) < 0.15 && fabs(r3 / r2 - 1) < 0.02,
       "orbit %zu: difference falls as 1/kappa (kappa*dev %.4f %.4f %.4f)", k,
       r1, r2, r3);
    ok(off[1] < 1e-3 && off[2] < 1e-4,
       "orbit %zu: (kappa/2)(W_d - W_j) -> delta Om^2 + alpha Om^2 W "
       "(rel err %.1e at 1e5, %.1e at 1e6)", k, off[1], off[2]);
  }
  whirl_hbm_free(hs);
  whirl_hbm_free(hj);
}

/* Stroboscopic state after nper forcing periods from rest. */
static int strobe(const whirl_problem *prob, const double *p, size_t n,
                  double Om, int nper, double *x) {
  whirl_ode *o = whirl_ode_alloc(prob, p);
  if (!o) return -1;
  whirl_ode_set_tolerances(o, 1e-11, 1e-13);
  for (size_t i = 0; i < n; ++i) x[i] = 0.0;
  int rc = whirl_ode_reset(o, 0.0, x);
  if (rc == 0) rc = whirl_ode_evolve(o, nper * 2 * PI / Om);
  if (rc == 0) memcpy(x, whirl_ode_x(o), n * sizeof *x);
  whirl_ode_free(o);
  return rc;
}

static void test_rigid_time(void) {
  /* Table 1, Omega = 1 (one orbit), from rest, 150 periods (the transient
   * decays like exp(−πλτ/2): e^{-37}); kappa = 1e4: the shaft mode has
   * frequency ~ 140, about 2e5 steps of the explicit integrator — kappa =
   * 1e8 would need 100 times more, so the 1/kappa rate is checked at 1e3 */
  double q[WHIRL_SFD_NPAR], p[6], xs[4], xj[8];
  whirl_sfd_default_params(q);
  q[WHIRL_SFD_OMEGA] = 1.0;
  int rc = strobe(whirl_sfd_fixed(), q, 4, 1.0, 150, xs);
  double dev[2] = {NAN, NAN};
  const double kap[2] = {1e3, 1e4};
  for (int m = 0; m < 2 && rc == 0; ++m) {
    table1(p, 1.0, 0.0, 0.5, kap[m]);
    rc = strobe(jeff, p, 8, 1.0, 150, xj);
    if (rc) break;
    dev[m] = 0.0;
    for (int c = 0; c < 4; ++c) {
      const int cd = c < 2 ? c : c + 2;
      dev[m] = fmax(dev[m], fmax(fabs(xj[cd] - xs[c]), fabs(xj[cd + 2] - xs[c])));
    }
  }
  ok(rc == 0 && dev[1] < 1e-3,
     "time integration, kappa = 1e4: disc and journal on the rigid rotor's "
     "orbit at tau = 300 pi (max diff %.2e < 1e-3)", dev[1]);
  ok(rc == 0 && dev[0] / dev[1] > 8 && dev[0] / dev[1] < 12,
     "... and the difference falls as 1/kappa (%.2e at 1e3, ratio %.2f)",
     dev[0], dev[0] / dev[1]);
}

/* ------------------------------------------------------------------------
 * (c) circular orbits and the linear limit */
static void test_circular_hbm(void) {
  const size_t N = 4, L = 2 * N + 1;
  whirl_hbm *h = hbm_of(jeff, N);
  if (!h) {
    ok(0, "HBM object");
    return;
  }
  const whirl_system *sys = whirl_hbm_system(h);
  /* ζ = 0.05 at the disc, α = 0.5, κ = 10: three orbits at 1.59 (rigid-body
   * fold pair), 2.58 (isolated lock-up branch), 5.9 (bending-mode folds) */
  const double speeds[5] = {1.0, 1.59, 2.58, 4.5, 5.9};
  const size_t nwant[5] = {1, 3, 3, 1, 3};
  double worst_e = 0, worst_d = 0, worst_h = 0;
  int fails = 0, counts = 1;
  for (int s = 0; s < 5; ++s) {
    double p[6], eps[4];
    table1(p, speeds[s], 0.05, 0.5, 10.0);
    const size_t nr = circ_roots(p, eps, 4);
    counts &= nr == nwant[s];
    for (size_t k = 0; k < nr; ++k) {
      double complex Wd, Wj;
      circ_amps(eps[k], p, 0, &Wd, &Wj);
      double X[8 * 9] = {0};
      set_circ(X, L, 2, 0, speeds[s], Wd * (1 + 2e-4 * tap_urand(-1, 1)));
      set_circ(X, L, 2, 1, speeds[s], Wj * (1 + 2e-4 * tap_urand(-1, 1)));
      int its;
      if (whirl_newton(sys, X, p, 1e-12, 20, &its) != 0) {
        ++fails;
        continue;
      }
      worst_e = fmax(worst_e, fabs(cabs(get_W(X, L, 2)) - eps[k]));
      worst_e = fmax(worst_e, fabs(cabs(get_W(X, L, 3) * -I) - eps[k]));
      worst_d = fmax(worst_d, cabs(get_W(X, L, 0) - Wd) / (1 + cabs(Wd)));
      worst_h = fmax(worst_h, higher_harmonics(X, 8, L));
    }
  }
  ok(counts, "closed form: 1, 3, 3, 1, 3 orbits at Omega = 1, 1.59, 2.58, "
     "4.5, 5.9 (kappa 10, alpha 0.5, zeta 0.05)");
  ok(fails == 0, "HBM Newton converged from every closed-form orbit");
  ok(worst_e < 1e-10 && worst_d < 1e-10,
     "HBM = closed form: journal radius (%.1e), disc amplitude (%.1e)",
     worst_e, worst_d);
  ok(worst_h < 1e-12, "circular orbits: mean and harmonics 2..4 vanish (%.1e)",
     worst_h);

  /* linear limit: force −πλv; the neglected radial force a = −4λε² makes
   * the error O(ε²) = O(δ²) */
  const double lin_speeds[3] = {0.8, 2.0, 4.5};
  for (int s = 0; s < 3; ++s) {
    double err[2] = {0, 0}, amp = 0, ampd = 0;
    for (int m = 0; m < 2; ++m) {
      double p[6];
      table1(p, lin_speeds[s], 0.05, 0.5, 10.0);
      p[J_DELTA] = m == 0 ? 2e-3 : 1e-3;
      double complex Wd, Wj;
      circ_amps(0.0, p, 1, &Wd, &Wj);
      double X[8 * 9] = {0};
      set_circ(X, L, 2, 0, p[0], Wd);
      set_circ(X, L, 2, 1, p[0], Wj);
      int its;
      if (whirl_newton(sys, X, p, 1e-13, 20, &its) != 0) err[m] = NAN;
      else err[m] = fmax(cabs(get_W(X, L, 0) - Wd), cabs(get_W(X, L, 2) - Wj));
      if (m == 0) amp = cabs(Wj), ampd = cabs(Wd);
    }
    /* relative error of the order of the journal eccentricity (the radial
     * force over the linear one is 4 eps / pi (1 - eps^2)^{-1/2}), and it
     * shrinks four times when delta halves */
    ok(err[0] < amp * fmax(amp, ampd) && err[0] / err[1] > 3.6 &&
           err[0] / err[1] < 4.4,
       "Omega %.1f: |HBM - linear closed form| = %.2e at delta 2e-3 "
       "(eps_j %.2e, |W_d| %.2e), %.2e at 1e-3: ratio %.3f = O(delta^2)",
       lin_speeds[s], err[0], amp, ampd, err[1], err[0] / err[1]);
  }
  whirl_hbm_free(h);
}

static void test_circular_time(void) {
  /* κ = 10, ζ = 0.05, Ω = 1: one orbit; from rest for 120 periods the
   * slowest mode decays below 1e-9 */
  double p[6], x[8], eps[4];
  table1(p, 1.0, 0.05, 0.5, 10.0);
  const size_t nr = circ_roots(p, eps, 4);
  int rc = strobe(jeff, p, 8, 1.0, 120, x);
  double complex Wd, Wj;
  circ_amps(eps[0], p, 0, &Wd, &Wj);
  /* at τ = kT: y + iz = W, y' + iz' = iΩW */
  const double want[8] = {creal(Wd), cimag(Wd), creal(Wj), cimag(Wj),
                          -cimag(Wd), creal(Wd), -cimag(Wj), creal(Wj)};
  double d = 0;
  for (int i = 0; i < 8; ++i) d = fmax(d, fabs(x[i] - want[i]));
  ok(nr == 1 && rc == 0 && d < 1e-8,
     "time integration from rest (120 periods) = closed-form orbit, eps_j "
     "%.6f (max diff %.1e < 1e-8)", eps[0], d);
}

/* ------------------------------------------------------------------------
 * (d) contact and the parameter domain */
static void test_contact(void) {
  double p[6], f[8], J[64], Jp[48];
  table1(p, 1.5, 0.01, 0.5, 10.0);
  double x[8] = {0.2, 0.1, 0.6, 0.8, 0.1, 0.2, 0.3, 0.4}; /* ε_j = 1 */
  ok(jeff->rhs(0.1, x, p, f, NULL) == WHIRL_SFD_CONTACT &&
         jeff->jac_x(0.1, x, p, J, NULL) == WHIRL_SFD_CONTACT &&
         jeff->jac_p(0.1, x, p, Jp, NULL) == WHIRL_SFD_CONTACT,
     "eps_j = 1: rhs, jac_x, jac_p return WHIRL_SFD_CONTACT");
  x[2] = 1.5, x[3] = -0.3;
  ok(jeff->rhs(0.1, x, p, f, NULL) == WHIRL_SFD_CONTACT,
     "eps_j = 1.53: WHIRL_SFD_CONTACT");
  x[0] = 3.0, x[1] = -2.0, x[2] = 0.6, x[3] = 0.79;
  ok(jeff->rhs(0.1, x, p, f, NULL) == 0,
     "the disc may leave the clearance circle (|r_d| = 3.6, eps_j 0.99): ok");
  x[3] = 0.3;
  p[J_ALPHA] = 1.0;
  int r1 = jeff->rhs(0, x, p, f, NULL);
  p[J_ALPHA] = 0.5, p[J_KAPPA] = 0.0;
  int r2 = jeff->rhs(0, x, p, f, NULL);
  p[J_KAPPA] = 10.0, p[J_LAMBDA] = NAN;
  int r3 = jeff->rhs(0, x, p, f, NULL);
  ok(r1 == JEFFCOTT_PARAM_DOMAIN && r2 == JEFFCOTT_PARAM_DOMAIN && r3 < 0,
     "alpha = 1, kappa = 0: recoverable %d %d; lambda NaN: fatal %d", r1, r2,
     r3);
}

int main(void) {
  test_model();
  test_jacobians();
  test_rigid_identity();
  test_rigid_hbm();
  test_rigid_time();
  test_circular_hbm();
  test_circular_time();
  test_contact();
  return done_testing();
}

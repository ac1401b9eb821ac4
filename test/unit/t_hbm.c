/* test/unit/t_hbm.c — harmonic balance (lib/systems/hbm.c):
 *  - the AFT Jacobian against finite differences (SFD fixed frame, Duffing,
 *    an autonomous van der Pol oscillator);
 *  - SFD circular orbits (F_E = 0): HBM in the fixed frame against the
 *    circular-orbit polynomial eq. 15 (independent closed form), Galerkin
 *    and time-domain residuals, and the monodromy multipliers against
 *    exp(2π μ/Ω) of the rotating-frame eigenvalues;
 *  - Duffing x'' + 2ζx' + x + γx³ = F cos ωt: with one harmonic HBM IS the
 *    one-term harmonic balance, whose amplitude equation
 *    [(1 − ω² + ¾γA²)² + (2ζω)²] A² = F² is solved here independently
 *    (Newton on the closed form), folds included; with 8 harmonics the weak
 *    case stays within the O(γ²) neglected terms;
 *  - the van der Pol limit cycle (autonomous, phase condition): period
 *    against the two-timing expansion 2π(1 + μ²/16) for small μ and
 *    amplitude 2;
 *  - bad options.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "../tap.h"

/* ---------------------------------------------------------------- models */
/* Duffing: x = (x, x'), p = (omega, zeta, gamma, F). */
static int duff_rhs(double t, const double *x, const double *p, double *f,
                    void *d) {
  (void)d;
  f[0] = x[1];
  f[1] = -2 * p[1] * x[1] - x[0] - p[2] * x[0] * x[0] * x[0] +
         p[3] * cos(p[0] * t);
  return 0;
}
static int duff_jac(double t, const double *x, const double *p, double *J,
                    void *d) {
  (void)t, (void)d;
  J[0] = 0, J[1] = -1 - 3 * p[2] * x[0] * x[0];
  J[2] = 1, J[3] = -2 * p[1];
  return 0;
}
static const char *const duff_pn[] = {"omega", "zeta", "gamma", "F"};
static const whirl_problem duffing = {"duffing", 2, 4, duff_rhs, duff_jac, NULL,
                                      0, NULL, duff_pn, NULL};

/* van der Pol: x'' − μ(1 − x²)x' + x = 0, p = (mu). */
static int vdp_rhs(double t, const double *x, const double *p, double *f,
                   void *d) {
  (void)t, (void)d;
  f[0] = x[1];
  f[1] = p[0] * (1 - x[0] * x[0]) * x[1] - x[0];
  return 0;
}
static const whirl_problem vdp = {"vdp", 2, 1, vdp_rhs, NULL, NULL, 1,
                                  NULL, NULL, NULL};

/* One-term harmonic balance of Duffing: G(A, ω) = 0 and its fold
 * G = G_A = 0 in (A, ω), solved by Newton with analytic derivatives. */
static double duff_G(double A, double w, double z, double g, double F,
                     double *GA, double *Gw) {
  const double r = 1 - w * w + 0.75 * g * A * A, c = 2 * z * w;
  if (GA) *GA = 2 * A * (r * r + c * c) + A * A * 2 * r * 1.5 * g * A;
  if (Gw) *Gw = A * A * (2 * r * (-2 * w) + 2 * c * 2 * z);
  return (r * r + c * c) * A * A - F * F;
}
static int duff_fold(double *A, double *w, double z, double g, double F) {
  for (int it = 0; it < 100; ++it) {
    /* unknowns (A, w): G = 0, H = G_A = 0; derivatives of H by differences
     * of the analytic G_A (smooth polynomial, step 1e-7) */
    double GA, Gw;
    const double G = duff_G(*A, *w, z, g, F, &GA, &Gw);
    const double h = 1e-7;
    double GAa, GAw, t1, t2;
    duff_G(*A + h, *w, z, g, F, &t1, NULL);
    duff_G(*A - h, *w, z, g, F, &t2, NULL);
    GAa = (t1 - t2) / (2 * h);
    duff_G(*A, *w + h, z, g, F, &t1, NULL);
    duff_G(*A, *w - h, z, g, F, &t2, NULL);
    GAw = (t1 - t2) / (2 * h);
    const double det = GA * GAw - Gw * GAa;
    const double dA = (G * GAw - Gw * GA) / det, dw = (GA * GA - GAa * G) / det;
    *A -= dA, *w -= dw;
    if (fabs(dA) < 1e-15 && fabs(dw) < 1e-15) return 0;
  }
  return 1;
}

/* Amplitude sqrt(a1² + b1²) of the first harmonic of component 0. */
static double amp1(const double *X) { return hypot(X[1], X[2]); }

/* ------------------------------------------------------------- Jacobians */
static void test_jacobians(void) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o);
  o.harmonics = 5;
  o.oversampling = 4;
  o.forcing_param = WHIRL_SFD_OMEGA;
  char err[256];
  whirl_hbm *h = whirl_hbm_alloc(whirl_sfd_fixed(), &o, err, sizeof err);
  ok(h != NULL, "hbm of the SFD fixed frame allocated %s", err);
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = 2.1;
  p[WHIRL_SFD_FE] = -0.1;
  const size_t S = whirl_hbm_size(h);
  double *X = calloc(S, sizeof *X);
  for (size_t q = 0; q < S; ++q) X[q] = 0.05 * tap_urand(-1, 1);
  X[11 * 1] += 0.3; /* a non-circular orbit well inside the clearance */
  double e;
  int rc = whirl_system_check_jacobian(whirl_hbm_system(h), X, p, &e);
  ok(rc == 0 && e < 1e-7, "SFD HBM: AFT Jacobian vs differences (%.1e)", e);
  free(X);
  whirl_hbm_free(h);

  o.forcing_param = 0;
  h = whirl_hbm_alloc(&duffing, &o, err, sizeof err);
  double pd[4] = {1.3, 0.05, 0.8, 0.5};
  double Xd[22];
  for (size_t q = 0; q < 22; ++q) Xd[q] = tap_urand(-1, 1);
  rc = whirl_system_check_jacobian(whirl_hbm_system(h), Xd, pd, &e);
  ok(rc == 0 && e < 1e-7, "Duffing HBM: AFT Jacobian vs differences (%.1e)", e);
  whirl_hbm_free(h);

  o.forcing_param = -1;
  h = whirl_hbm_alloc(&vdp, &o, err, sizeof err);
  ok(h && whirl_hbm_size(h) == 23, "autonomous HBM has 2(2N+1)+1 unknowns");
  double Xv[23], pv[1] = {0.7};
  for (size_t q = 0; q < 22; ++q) Xv[q] = tap_urand(-1, 1);
  Xv[22] = 0.9;
  rc = whirl_system_check_jacobian(whirl_hbm_system(h), Xv, pv, &e);
  ok(rc == 0 && e < 1e-7, "van der Pol HBM (frequency unknown): Jacobian (%.1e)", e);
  whirl_hbm_free(h);
}

/* --------------------------------------------------- SFD circular orbits */
static void test_sfd_circular(void) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o); /* the paper's 8 harmonics, K = 10 */
  o.forcing_param = WHIRL_SFD_OMEGA;
  char err[256];
  whirl_hbm *h = whirl_hbm_alloc(whirl_sfd_fixed(), &o, err, sizeof err);
  const whirl_system *sys = whirl_hbm_system(h);
  const size_t S = whirl_hbm_size(h), L = 17;
  const double speeds[] = {0.8, 1.78, 3.0, 7.5};
  for (size_t s = 0; s < 4; ++s) {
    double p[WHIRL_SFD_NPAR];
    whirl_sfd_default_params(p);
    p[WHIRL_SFD_OMEGA] = speeds[s];
    double eps[4], mre[4];
    int st[4];
    size_t no = 0;
    whirl_sfd_circular_orbits(p, eps, st, mre, 4, &no);
    for (size_t k = 0; k < no; ++k) {
      /* start: the circular orbit sampled in the fixed frame, perturbed */
      double xr[4], xs[64 * 4];
      whirl_sfd_circ_state(eps[k], speeds[s], p[1], p[2], p[3], xr);
      for (size_t j = 0; j < 64; ++j) {
        const double t = 2 * M_PI * j / (64 * speeds[s]);
        whirl_sfd_to_fixed(speeds[s], t, xr, xs + 4 * j);
      }
      double *X = malloc(S * sizeof *X), *F = malloc(S * sizeof *F);
      whirl_hbm_from_samples(h, xs, 64, 0, X);
      for (size_t q = 0; q < S; ++q) X[q] *= 1.0 + 1e-3 * tap_urand(-1, 1);
      whirl_cont_options co;
      whirl_cont_options_default(&co);
      co.icp = WHIRL_SFD_OMEGA;
      whirl_cont *c = whirl_cont_alloc(sys, &co, err, sizeof err);
      int rc = whirl_cont_start(c, X, p, 1);
      const whirl_point *pt = rc == 0 ? (whirl_cont_step(c), whirl_cont_point(c)) : NULL;
      /* the start point is the first point emitted */
      if (!pt) {
        ok(0, "Omega %g orbit %zu: start failed: %s", speeds[s], k, whirl_cont_errmsg(c));
        whirl_cont_free(c);
        free(X), free(F);
        continue;
      }
      const double ey = hypot(pt->x[1], pt->x[2]);
      const double ez = hypot(pt->x[L + 1], pt->x[L + 2]);
      is_abs(ey, eps[k], 1e-10, "Omega %g: HBM eps(y) = eq. 15 eps %.10f", speeds[s], eps[k]);
      is_abs(ez, eps[k], 1e-10, "Omega %g: HBM eps(z) = eq. 15 eps", speeds[s]);
      whirl_system_eval(sys, pt->x, pt->p, F);
      double fres = 0, hmax = 0;
      for (size_t q = 0; q < S; ++q) fres = fmax(fres, fabs(F[q]));
      for (size_t i = 0; i < 4; ++i)
        for (size_t q = 3; q < L; ++q) hmax = fmax(hmax, fabs(pt->x[i * L + q]));
      ok(fres < 1e-12, "Omega %g: Galerkin residual %.1e < 1e-12", speeds[s], fres);
      ok(hmax < 1e-12, "Omega %g: higher harmonics of a circle vanish (%.1e)", speeds[s], hmax);
      double tres;
      whirl_hbm_time_residual(h, pt->x, pt->p, 3, &tres);
      ok(tres < 1e-11, "Omega %g: time-domain residual %.1e", speeds[s], tres);
      /* multipliers against exp(2π μ / Ω) of the rotating-frame equilibrium */
      double J[16], er[4], ei[4];
      whirl_sfd_rotating()->jac_x(0, xr, p, J, NULL);
      whirl_eig *eg = whirl_eig_alloc(4);
      whirl_eig_compute(eg, J, er, ei);
      whirl_eig_free(eg);
      double worst = 0;
      for (size_t a = 0; a < pt->nspec; ++a) {
        double best = INFINITY;
        for (size_t b = 0; b < 4; ++b) {
          const double m = exp(2 * M_PI * er[b] / speeds[s]);
          const double ph = 2 * M_PI * ei[b] / speeds[s];
          best = fmin(best, hypot(pt->spec_re[a] - m * cos(ph), pt->spec_im[a] - m * sin(ph)));
        }
        worst = fmax(worst, best);
      }
      ok(pt->nspec == 4 && worst < 1e-8,
         "Omega %g: multipliers = exp(2 pi mu/Omega) (%.1e)", speeds[s], worst);
      ok(pt->stable == st[k], "Omega %g eps %.3f: stability %d as eq. 15 says", speeds[s],
         eps[k], pt->stable);
      whirl_cont_free(c);
      free(X), free(F);
    }
  }
  whirl_hbm_free(h);
}

/* -------------------------------------------------------------- Duffing */
/* Trace the Duffing response in ω with N harmonics; return the LP values. */
static size_t duff_trace(size_t N, const double *p0, double wmax, double *lp_w,
                         double *lp_A, size_t maxlp, double *worst_G) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o);
  o.harmonics = N;
  o.oversampling = 8;
  o.forcing_param = 0;
  o.no_spectrum = 1;
  char err[256];
  whirl_hbm *h = whirl_hbm_alloc(&duffing, &o, err, sizeof err);
  const size_t S = whirl_hbm_size(h);
  double *X = calloc(S, sizeof *X);
  double p[4];
  memcpy(p, p0, sizeof p);
  /* start at low frequency: the linear response is a fine guess */
  const double A0 = p[3] / (1 - p[0] * p[0]);
  X[1] = A0;                          /* x = A0 cos ωt */
  X[(2 * N + 1) + 2] = -p[0] * A0;    /* x' = −ω A0 sin ωt */








  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 0;
  co.ds = 0.01;
  co.ds_max = 0.05;
  co.p_min = 0.05;
  co.p_max = wmax;
  co.nmx = 5000;
  whirl_cont *c = whirl_cont_alloc(whirl_hbm_system(h), &co, err, sizeof err);
  size_t nlp = 0;
  *worst_G = 0;
  if (whirl_cont_start(c, X, p, 1) == 0) {
    while (whirl_cont_step(c) == WHIRL_OK) {
      const whirl_point *pt = whirl_cont_point(c);
      if (N == 1) {
        const double G = duff_G(amp1(pt->x), pt->p[0], p[1], p[2], p[3], NULL, NULL);
        *worst_G = fmax(*worst_G, fabs(G));
      }
      if (pt->type == WHIRL_PT_LP && nlp < maxlp) {
        lp_w[nlp] = pt->p[0];
        lp_A[nlp] = amp1(pt->x);
        ++nlp;
      }
    }
  }
  whirl_cont_free(c);
  whirl_hbm_free(h);
  free(X);
  return nlp;
}

static void test_duffing(void) {
  /* weakly nonlinear: ζ = 0.01, γ = 0.05, F = 0.02 (hardening, two folds) */
  const double p[4] = {0.3, 0.01, 0.05, 0.02};
  double w1[4], a1[4], w8[4], a8[4], G1, G8;
  size_t n1 = duff_trace(1, p, 2.0, w1, a1, 4, &G1);
  size_t n8 = duff_trace(8, p, 2.0, w8, a8, 4, &G8);
  ok(n1 == 2, "Duffing N = 1: two folds (%zu)", n1);
  ok(G1 < 1e-12, "Duffing N = 1: every point on the one-term curve (|G| %.1e)", G1);
  if (n1 == 2) {
    for (int k = 0; k < 2; ++k) {
      double A = a1[k], w = w1[k];
      int rc = duff_fold(&A, &w, p[1], p[2], p[3]);
      ok(rc == 0, "closed-form fold %d converged", k);
      is_abs(w1[k], w, 1e-8, "Duffing N = 1 fold %d at omega = %.10f", k, w);
      is_abs(a1[k], A, 1e-7, "Duffing N = 1 fold %d amplitude %.8f", k, A);
    }
  }
  ok(n8 == 2, "Duffing N = 8: two folds (%zu)", n8);
  if (n1 == 2 && n8 == 2)
    for (int k = 0; k < 2; ++k)
      ok(fabs(w8[k] - w1[k]) < 1e-4 * w1[k],
         "weak Duffing: 8 harmonics move fold %d by %.2e (higher harmonics "
         "are O(gamma A^3/32) here)", k, fabs(w8[k] - w1[k]));
}

/* ---------------------------------------------------------- van der Pol */
static void test_vdp(void) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o);
  o.harmonics = 12;
  char err[256];
  whirl_hbm *h = whirl_hbm_alloc(&vdp, &o, err, sizeof err);
  const size_t S = whirl_hbm_size(h);
  double *X = calloc(S, sizeof *X);
  X[1] = 2.0;               /* x = 2 cos t */
  X[25 + 2] = -2.0 * 1.0;   /* x' = −2 sin t */
  X[S - 1] = 1.0;
  double p[1] = {0.1};
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 0;
  whirl_cont *c = whirl_cont_alloc(whirl_hbm_system(h), &co, err, sizeof err);
  int rc = whirl_cont_start(c, X, p, 1);
  ok(rc == 0, "van der Pol mu = 0.1: HBM converged %s", rc ? whirl_cont_errmsg(c) : "");
  if (rc == 0) {
    whirl_cont_step(c);
    const whirl_point *pt = whirl_cont_point(c);
    const double T = 2 * M_PI / pt->x[S - 1];
    /* two-timing: T = 2π (1 + μ²/16 + O(μ⁴)); amplitude 2 + O(μ²) */
    is_abs(T, 2 * M_PI * (1 + 0.01 / 16), 2e-5, "van der Pol period %.8f", T);
    is_abs(amp1(pt->x), 2.0, 2e-3, "van der Pol first-harmonic amplitude");
    ok(pt->nspec == 1 && pt->stable == 1 &&
           fabs(pt->spec_re[0] - exp(-2 * M_PI * 0.1)) < 5e-3,
       "van der Pol: nontrivial multiplier %.5f ~ exp(-2 pi mu) (averaging)",
       pt->spec_re[0]);
  }
  whirl_cont_free(c);
  whirl_hbm_free(h);
  free(X);
}

/* ------------------------------------------------- torus point (closed form)
 * Forced Hopf normal form z' = (a + i) z − |z|² z + F e^{iωt}, z = x + iy.
 * In the frame rotating with ω, w = z e^{−iωt} obeys
 * w' = (a + iσ) w − |w|² w + F, σ = 1 − ω, so the synchronous orbits are
 * equilibria of w, with r = |w| on r²[(a − r²)² + σ²] = F², and a torus
 * (Neimark–Sacker) point of the orbit is a Hopf point of the equilibrium:
 * trace 2a − 4r² = 0, i.e. r² = a/2 and σ² = 2F²/a − a²/4, with the
 * rotating-frame frequency β = sqrt(det) = sqrt(σ² − a²/4), so the critical
 * multipliers are exp(±2πiβ/ω).  a = 1, F = 0.6: σ² = 0.47, β² = 0.22. */
static int nf_rhs(double t, const double *x, const double *p, double *f,
                  void *d) {
  (void)d;
  const double r2 = x[0] * x[0] + x[1] * x[1];
  f[0] = p[1] * x[0] - x[1] - r2 * x[0] + p[2] * cos(p[0] * t);
  f[1] = x[0] + p[1] * x[1] - r2 * x[1] + p[2] * sin(p[0] * t);
  return 0;
}
static const whirl_problem forced_nf = {"forced-hopf", 2, 3, nf_rhs, NULL, NULL,
                                        0, NULL, NULL, NULL};

static void test_torus(void) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o);
  o.harmonics = 4;
  o.forcing_param = 0;
  char err[256];
  whirl_hbm *h = whirl_hbm_alloc(&forced_nf, &o, err, sizeof err);
  const size_t S = whirl_hbm_size(h), L = 9;
  double *X = calloc(S, sizeof *X);
  /* ω = 1 (σ = 0): r²(1 − r²)² = 0.36 has the root r = 1.2181..., found here
   * by bisection on the closed form; the orbit z = r e^{i(t + φ)} with
   * (1 − r²) r e^{iφ} = −F fixes the phase: e^{iφ} = 1 (r > 1) */
  double lo = 1.0, hi = 2.0;
  for (int it = 0; it < 200; ++it) {
    double m = 0.5 * (lo + hi), g = m * m * (1 - m * m) * (1 - m * m) - 0.36;
    if (g < 0) lo = m; else hi = m;
  }
  const double r = 0.5 * (lo + hi);
  X[1] = r;     /* x = r cos t */
  X[L + 2] = r; /* y = r sin t */
  double p[3] = {1.0, 1.0, 0.6};
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 0;
  co.ds = 0.02;
  co.ds_max = 0.05;
  co.p_min = 0.1;
  co.p_max = 1.9;
  const double sig = sqrt(0.47), beta = sqrt(0.22);
  const double want[2] = {1 - sig, 1 + sig};
  for (int dir = -1; dir <= 1; dir += 2) {
    whirl_cont *c = whirl_cont_alloc(whirl_hbm_system(h), &co, err, sizeof err);
    int ntr = 0;
    if (whirl_cont_start(c, X, p, dir) == 0) {
      while (whirl_cont_step(c) == WHIRL_OK) {
        const whirl_point *pt = whirl_cont_point(c);
        if (pt->type != WHIRL_PT_TR) continue;
        ++ntr;
        const double w = pt->p[0], wt = want[dir > 0];
        is_abs(w, wt, 1e-8, "torus point TR at omega = 1 %c sqrt(0.47) = %.10f",
               dir > 0 ? '+' : '-', wt);
        is_abs(hypot(pt->x[1], pt->x[2]) * hypot(pt->x[1], pt->x[2]), 0.5, 1e-8,
               "TR on the circle r^2 = a/2");
        double ang = INFINITY;
        for (size_t k = 0; k < pt->nspec; ++k)
          if (pt->spec_im[k] > 0) ang = atan2(pt->spec_im[k], pt->spec_re[k]);
        const double wa = fmod(2 * M_PI * beta / w, 2 * M_PI);
        const double wrap = fmin(fabs(ang - wa), fabs(fabs(ang - wa) - 2 * M_PI));
        ok(wrap < 1e-6 || fabs(ang + wa - 2 * M_PI) < 1e-6,
           "TR multipliers exp(+-2 pi i beta/omega): angle %.8f vs %.8f", ang, wa);
      }
    }
    ok(ntr == 1, "exactly one TR going %s (%d)", dir > 0 ? "up" : "down", ntr);
    whirl_cont_free(c);
  }
  whirl_hbm_free(h);
  free(X);
}

static void test_bad(void) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o);
  char err[256] = "";
  o.forcing_param = -1;
  ok(whirl_hbm_alloc(&duffing, &o, err, sizeof err) == NULL && strstr(err, "not autonomous"),
     "forced model without forcing parameter rejected: %s", err);
  o.forcing_param = 7;
  ok(whirl_hbm_alloc(&duffing, &o, err, sizeof err) == NULL && strstr(err, "out of range"),
     "forcing parameter out of range rejected: %s", err);
  o.forcing_param = 0;
  o.harmonics = 0;
  ok(whirl_hbm_alloc(&duffing, &o, err, sizeof err) == NULL && strstr(err, "harmonics"),
     "zero harmonics rejected: %s", err);
}


/* The maximum over the orbit is the series' maximum (whirl_hbm_max), not
 * that of its samples: an orbit whose first component is the trigonometric
 * polynomial u(θ) = 0.3 + cos(θ − 0.05) + 0.4 sin(3θ + 0.7), its second
 * u'(θ).  Reference: the maximum over 10^6 phases refined by golden-section
 * search (independent of the library's Newton refinement). */
static double poly_u(double th) { return 0.3 + cos(th - 0.05) + 0.4 * sin(3.0 * th + 0.7); }
static double poly_du(double th) { return -sin(th - 0.05) + 1.2 * cos(3.0 * th + 0.7); }
static double dense_max(double (*f)(double)) {
  const size_t m = 1000000;
  double best = -HUGE_VAL, arg = 0.0;
  for (size_t k = 0; k < m; ++k) {
    const double th = 2.0 * WHIRL_PI * (double)k / (double)m, v = f(th);
    if (v > best) best = v, arg = th;
  }
  const double g = 0.5 * (sqrt(5.0) - 1.0), h = 2.0 * WHIRL_PI / (double)m;
  double a = arg - h, b = arg + h;
  for (int it = 0; it < 200 && b - a > 1e-15; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (f(x1) < f(x2)) a = x1; else b = x2;
  }
  return fmax(best, f(0.5 * (a + b)));
}

static void test_true_max(void) {
  whirl_hbm_options o;
  whirl_hbm_options_default(&o);
  o.harmonics = 3;
  o.forcing_param = 0;
  char err[256];
  whirl_hbm *h = whirl_hbm_alloc(&duffing, &o, err, sizeof err);
  ok(h != NULL, "hbm for the maximum test: %s", h ? "allocated" : err);
  if (!h) return;
  const size_t m = 64;
  double xs[2 * 64], *X = calloc(whirl_hbm_size(h), sizeof *X), mx[2];
  for (size_t k = 0; k < m; ++k) {
    const double th = 2.0 * WHIRL_PI * (double)k / (double)m;
    xs[2 * k] = poly_u(th), xs[2 * k + 1] = poly_du(th);
  }
  const int rc = whirl_hbm_from_samples(h, xs, m, 2.0 * WHIRL_PI, X);
  const double ref0 = dense_max(poly_u), ref1 = dense_max(poly_du);
  /* the samples the maximum starts from: 8 (2N + 1) phases */
  double s0 = -HUGE_VAL, v[2];
  for (size_t k = 0; k < 56; ++k) {
    whirl_hbm_eval(h, X, 2.0 * WHIRL_PI * (double)k / 56.0, v);
    s0 = fmax(s0, v[0]);
  }
  const int rcm = whirl_hbm_max(h, X, mx);
  ok(rc == WHIRL_OK && rcm == WHIRL_OK &&
         fabs(mx[0] - ref0) < 1e-12 && fabs(mx[1] - ref1) < 1e-12,
     "whirl_hbm_max is the series' maximum: %.15f, %.15f (reference %.15f, %.15f)",
     mx[0], mx[1], ref0, ref1);
  ok(ref0 - s0 > 1e-4, "... where the 56 samples fall short by %.2e", ref0 - s0);
  const whirl_periodic po = whirl_periodic_of_hbm(h);
  double pmx[2];
  const double l2 = whirl_periodic_l2norm(&po, X);
  const int rcp = whirl_periodic_max(&po, X, pmx);
  /* ∫ u² over a period / 2π: 0.09 + 1/2 + 0.08; ∫ u'² / 2π: 1/2 + 0.72 */
  const double l2_ref = sqrt(0.09 + 0.5 + 0.08 + 0.5 + 0.72);
  ok(!strcmp(whirl_periodic_method(&po), "hbm") &&
         whirl_periodic_size(&po) == whirl_hbm_size(h) &&
         rcp == WHIRL_OK && pmx[0] == mx[0] &&
         fabs(l2 - l2_ref) < 1e-13,
     "the periodic interface over hbm: max, L2-NORM %.15f (closed form %.15f)", l2,
     l2_ref);
  free(X);
  whirl_hbm_free(h);
}

int main(void) {
  test_true_max();
  test_jacobians();
  test_sfd_circular();
  test_duffing();
  test_vdp();
  test_torus();
  test_bad();
  return done_testing();
}

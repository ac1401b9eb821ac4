/* test/unit/t_fe_hbm.c — harmonic balance of finite-element rotors
 * (rotor/fe_hbm*.c, whirl/rotor/fe_hbm.h) against independent references:
 * the AFT coefficients of a cubic spring against cos³θ = (3 cos θ +
 * cos 3θ)/4 and of an SFD on a circular orbit against its rotational
 * symmetry; a linear rotor (k3 = 0) against a dense complex solve of
 * (D_k + k1 PPᵀ) q = F written here; the condensed HBM against the
 * uncondensed HBM on all DOFs (the acceptance, 1e-10); every
 * analytic Jacobian and dF/dp against central differences; Hill's
 * stability against the monodromy matrix of the full time-domain system
 * (variational equations integrated by whirl/floquet.h, the model written
 * here); the folds of a continuation against Hill's multiplier +1.
 * The rotor is built by hand (test/fe_chain.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <whirl/cont.h>
#include <whirl/floquet.h>
#include <whirl/fold.h>
#include <whirl/rotor/fe_hbm.h>
#include <whirl/rotor/fe_linear.h>

#include "../fe_chain.h"
#include "../tap.h"

#define PI 3.14159265358979323846

/* The harmonic balance of r (H harmonics, condensed unless uncondensed,
 * scales Ls, Fs, options.stability), nev the sparse Hill method's cap
 * hill_nev (0: the default); make() with the default cap. */
static whirl_fe_hbm *make_capped(const whirl_fe_rotor *r, int H, int uncondensed,
                                 double Ls, double Fs, int stability, size_t nev) {
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = (size_t)H;
  o.uncondensed = uncondensed;
  o.length_scale = Ls;
  o.force_scale = Fs;
  o.stability = stability;
  if (nev) o.hill_nev = nev;
  char err[256] = "";
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &o, err, sizeof err);
  if (!h) printf("# alloc: %s\n", err);
  return h;
}

static whirl_fe_hbm *make(const whirl_fe_rotor *r, int H, int uncondensed,
                          double Ls, double Fs, int stability) {
  return make_capped(r, H, uncondensed, Ls, Fs, stability, 0);
}

/* ---------------------------------------------------------------- AFT */

/* With K = 0 and Ω = 0 the uncondensed residual is −f_nl exactly. */
static void test_aft_cubic(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 2);
  co.kb = co.ks = co.EI = 0;
  co.nnl = 1;
  co.nl[0] = fe_chain_cubic(1, 2e5, 3e11);
  whirl_fe_rotor *r = fe_chain_build(&co);
  whirl_fe_hbm *h = make(r, 3, 1, 1.0, 1.0, 0);
  size_t n = whirl_fe_hbm_size(h);
  double *X = calloc(n, sizeof *X), *F = calloc(n, sizeof *F), p[4];
  whirl_fe_hbm_params(0.0, p);
  int nd = r->ndof, y = 4;            /* y of node 1 */
  double A = 1e-3;
  X[nd * 1 + y] = A;                   /* a_1 */
  int rc = whirl_system_eval(whirl_fe_hbm_system(h), X, p, F);
  ok(rc == 0, "AFT cubic: evaluated (%d)", rc);
  double k1 = 2e5, k3 = 3e11;
  is_rel(-F[nd * 1 + y], -(k1 * A + 0.75 * k3 * A * A * A), 1e-12,
         "cubic: a_1 of the force = -(k1 A + 3/4 k3 A^3)");
  is_rel(-F[nd * 5 + y], -0.25 * k3 * A * A * A, 1e-12,
         "cubic: a_3 of the force = -k3 A^3 / 4");
  double rest = 0;
  for (size_t i = 0; i < n; ++i)
    if (i != (size_t)(nd + y) && i != (size_t)(5 * nd + y)) rest = fmax(rest, fabs(F[i]));
  ok(rest < 1e-12 * k3 * A * A * A, "cubic: every other coefficient 0 (%g)", rest);
  free(X); free(F);
  whirl_fe_hbm_free(h);
  fe_chain_free(r);
}

/* A circular centred orbit y = e cos θ, z = e sin θ at ω: the force turns
 * with the journal, f(θ) = R(θ) f(0), so its first harmonic is
 * a_y = b_z = f_r, b_y = −a_z = −f_t with (f_r, f_t) the force at θ = 0,
 * r = (e, 0), v = (0, e ω); nothing in the other harmonics. */
static void test_aft_sfd_circular(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 2);
  co.kb = co.ks = co.EI = 0;
  co.beta = co.cb = 0;
  co.disk_node = -1;
  co.nnl = 1;
  co.nl[0] = fe_chain_sfd(1, -1);
  whirl_fe_rotor *r = fe_chain_build(&co);
  for (int c = 0; c < r->M.p[r->ndof]; ++c) r->M.x[c] = 0; /* D_k = 0 */
  whirl_fe_hbm *h = make(r, 4, 1, 1.0, 1.0, 0);
  size_t n = whirl_fe_hbm_size(h);
  double *X = calloc(n, sizeof *X), *F = calloc(n, sizeof *F), p[4];
  double Om = 300.0, e = 0.4 * co.nl[0].par.clearance;
  whirl_fe_hbm_params(Om, p);
  int nd = r->ndof, y = 4, z = 5;
  X[nd * 1 + y] = e;
  X[nd * 2 + z] = e;
  int rc = whirl_system_eval(whirl_fe_hbm_system(h), X, p, F);
  double rr[2] = {e, 0}, vv[2] = {0, e * Om}, aa[2] = {0, 0}, f[2];
  rc |= whirl_fe_nl_force(&r->nl[0], rr, vv, aa, Om, f, NULL, NULL, NULL);
  ok(rc == 0, "SFD circular: evaluated");
  double sc = fabs(f[0]) + fabs(f[1]);
  is_rel(-F[nd + y], f[0], 1e-9, "SFD circular: a_y = f_r");
  is_rel(-F[2 * nd + z], f[0], 1e-9, "SFD circular: b_z = f_r");
  is_rel(-F[2 * nd + y], -f[1], 1e-9, "SFD circular: b_y = -f_t");
  is_rel(-F[nd + z], f[1], 1e-9, "SFD circular: a_z = f_t");
  double rest = 0;
  for (int k = 0; k < 9; ++k)
    if (k != 1 && k != 2) rest = fmax(rest, fmax(fabs(F[k * nd + y]), fabs(F[k * nd + z])));
  ok(rest < 1e-9 * sc, "SFD circular: no other harmonic (%g of %g)", rest, sc);
  free(X); free(F);
  whirl_fe_hbm_free(h);
  fe_chain_free(r);
}

/* ------------------------------------------------------------- models */

/* 5 nodes (20 DOF, 22 with the pedestal): a cubic spring at node 0 and an
 * SFD at node 4 (to ground or on the pedestal), gravity. */
static whirl_fe_rotor *model5(int pedestal, double k3) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 5);
  co.pedestal = pedestal;
  co.gravity = 9.81;
  co.ks = 3e6;
  co.nnl = 2;
  co.nl[0] = fe_chain_cubic(0, 0.0, k3);
  co.nl[1] = fe_chain_sfd(4, pedestal ? 0 : -1);
  return fe_chain_build(&co);
}

static const char *kname(whirl_fe_nl_kind k) {
  switch (k) {
  case WHIRL_FE_SFD_SHORT_PI: return "short pi SFD";
  case WHIRL_FE_SFD_SHORT_2PI: return "short 2pi SFD";
  case WHIRL_FE_SFD_LONG: return "long SFD";
  case WHIRL_FE_SFD_INERTIA: return "SFD with fluid inertia";
  default: return "?";
  }
}

/* the same with the SFD of another kind (fluid inertia: ρ = 860 kg/m³) */
static whirl_fe_rotor *model5_kind(int pedestal, whirl_fe_nl_kind kind) {
  whirl_fe_rotor *r = model5(pedestal, 1e13);
  r->nl[1].kind = kind;
  r->nl[1].par.density = 860.0;
  return r;
}

static double maxabs(const double *x, size_t n) {
  double m = 0;
  for (size_t i = 0; i < n; ++i) m = fmax(m, fabs(x[i]));
  return m;
}

static void test_jacobians(int pedestal, int uncondensed,
                           whirl_fe_nl_kind kind) {
  whirl_fe_rotor *r = model5_kind(pedestal, kind);
  whirl_fe_hbm *h = make(r, 3, uncondensed, 0, 0, 0);
  const whirl_system *s = whirl_fe_hbm_system(h);
  double *X = calloc(s->n, sizeof *X), p[4], err = 1;
  whirl_fe_hbm_params(250.0, p);
  p[1] = 1.3; p[2] = 1.1; p[3] = 0.9;
  for (size_t i = 0; i < s->n; ++i) X[i] = tap_urand(-0.08, 0.08);
  int rc = whirl_system_check_jacobian(s, X, p, &err);
  ok(rc == 0 && err < 2e-6, "%s%s, %s: Jacobian and dF/dp against "
     "differences (%.2e)", uncondensed ? "uncondensed" : "condensed",
     pedestal ? ", pedestal" : "", kname(kind), err);
  free(X);
  whirl_fe_hbm_free(h);
  fe_chain_free(r);
}

/* The linear part's speed cache (fe_lin_update: the current speed and
 * FE_LIN_SLOTS earlier ones): F, its Jacobian and the recovered DOFs at a
 * speed left and come back to (three speeds between) are those of a
 * fresh object at that speed, to the bit; the recovery needs X_k, y_k of
 * that speed, which the cache does not keep (with the last computed
 * speed's the recovered DOFs differ: the test fails so). */
static void test_speed_cache(void) {
  whirl_fe_rotor *r = model5_kind(1, WHIRL_FE_SFD_SHORT_PI);
  const int H = 3, L = 2 * H + 1, nd = r->ndof;
  whirl_fe_hbm *h = make(r, H, 0, 0, 0, 0), *g = make(r, H, 0, 0, 0, 0);
  const whirl_system *s = whirl_fe_hbm_system(h), *sg = whirl_fe_hbm_system(g);
  const size_t n = s->n;
  double *X = calloc(n, sizeof *X), *F1 = calloc(n, sizeof *F1), *F2 = calloc(n, sizeof *F2);
  double *J1 = calloc(n * n, sizeof *J1), *J2 = calloc(n * n, sizeof *J2);
  double *w = calloc(2 * n + 8, sizeof *w), p[4];
  double *q1 = calloc((size_t)nd * L, sizeof *q1), *q2 = calloc((size_t)nd * L, sizeof *q2);
  for (size_t i = 0; i < n; ++i) X[i] = tap_urand(-0.05, 0.05);
  const double Om[6] = {250.0, 250.0 + 1e-3, 250.0 - 1e-3, 251.0, 250.0, 251.0};
  int rc = 0, same = 1;
  for (int k = 0; k < 6 && !rc; ++k) {
    whirl_fe_hbm_params(Om[k], p);
    rc |= whirl_system_eval(s, X, p, F1);
    rc |= whirl_system_jacobian(s, X, p, J1, w);
    if (k < 4) continue;
    /* 250 again after three others (recalled), then 251 (kept) */
    rc |= whirl_fe_hbm_recover(h, X, p, q1);
    rc |= whirl_system_eval(sg, X, p, F2);
    rc |= whirl_system_jacobian(sg, X, p, J2, w);
    rc |= whirl_fe_hbm_recover(g, X, p, q2);
    same &= !memcmp(F1, F2, n * sizeof *F1) && !memcmp(J1, J2, n * n * sizeof *J1) &&
            !memcmp(q1, q2, (size_t)nd * L * sizeof *q1);
  }
  ok(rc == 0 && same, "the speed cache: F, Jacobian and recovered DOFs at a speed come back "
     "to are a fresh object's, to the bit (rc %d)", rc);
  free(X), free(F1), free(F2), free(J1), free(J2), free(w), free(q1), free(q2);
  whirl_fe_hbm_free(h);
  whirl_fe_hbm_free(g);
  fe_chain_free(r);
}

/* ---------------------------------------------- linear: a dense solve */

/* x = A⁻¹ b, A n×n complex column-major (destroyed), partial pivoting. */
static void csolve(int n, double complex *A, double complex *b) {
  for (int k = 0; k < n; ++k) {
    int piv = k;
    for (int i = k + 1; i < n; ++i)
      if (cabs(A[i + n * k]) > cabs(A[piv + n * k])) piv = i;
    for (int j = 0; j < n; ++j) {
      double complex t = A[k + n * j]; A[k + n * j] = A[piv + n * j]; A[piv + n * j] = t;
    }
    double complex t = b[k]; b[k] = b[piv]; b[piv] = t;
    for (int i = k + 1; i < n; ++i) {
      double complex l = A[i + n * k] / A[k + n * k];
      for (int j = k; j < n; ++j) A[i + n * j] -= l * A[k + n * j];
      b[i] -= l * b[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    for (int j = k + 1; j < n; ++j) b[k] -= A[k + n * j] * b[j];
    b[k] /= A[k + n * k];
  }
}

static void dense_add(double complex *D, int n, const whirl_fe_csc *A,
                      double complex s) {
  for (int c = 0; c < n; ++c)
    for (int q = A->p[c]; q < A->p[c + 1]; ++q) D[A->i[q] + n * c] += s * A->x[q];
}

/* The SFD replaced by a linear cubic spring (k3 = 0) at node 4 too. */
static void test_linear(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 5);
  co.gravity = 9.81;
  co.nnl = 2;
  double k1 = 3e6;
  co.nl[0] = fe_chain_cubic(0, k1, 0.0);
  co.nl[1] = fe_chain_cubic(4, k1, 0.0);
  whirl_fe_rotor *r = fe_chain_build(&co);
  whirl_fe_hbm *h = make(r, 2, 0, 1e-4, 0, 0);
  const whirl_system *s = whirl_fe_hbm_system(h);
  double *X = calloc(s->n, sizeof *X), p[4], Om = 180.0;
  whirl_fe_hbm_params(Om, p);
  int its = 0, rc = whirl_newton(s, X, p, 1e-13, 10, &its);
  int n = r->ndof, L = 5;
  double *q = calloc((size_t)n * L, sizeof *q);
  rc |= whirl_fe_hbm_recover(h, X, p, q);
  ok(rc == 0 && its <= 3, "linear: Newton converged in %d iterations", its);
  double complex *D = calloc((size_t)n * n, sizeof *D), *b = calloc((size_t)n, sizeof *b);
  double err = 0, sc = 0;
  for (int k = 0; k <= 1; ++k) {
    memset(D, 0, (size_t)n * n * sizeof *D);
    double w = k * Om;
    dense_add(D, n, &r->K, 1.0);
    dense_add(D, n, &r->M, -w * w);
    dense_add(D, n, &r->C, I * w);
    dense_add(D, n, &r->G, I * w * Om);
    for (int c = 0; c < 2; ++c) { D[c + n * c] += k1; D[16 + c + n * (16 + c)] += k1; }
    for (int d = 0; d < n; ++d)
      b[d] = k == 0 ? r->f0[d] : Om * Om * (r->unb_c[d] - I * r->unb_s[d]);
    csolve(n, D, b);
    for (int d = 0; d < n; ++d) {
      double complex Q = k == 0 ? q[d] : q[n + d] - I * q[2 * n + d];
      err = fmax(err, cabs(Q - b[d]));
      sc = fmax(sc, cabs(b[d]));
    }
  }
  ok(err < 1e-10 * sc, "linear: condensed HBM and recovery = (D_k + k1 PP^T)^-1 F "
     "(%.2e of %.2e)", err, sc);
  ok(maxabs(q + 3 * n, 2 * (size_t)n) < 1e-14 * sc, "linear: harmonic 2 is 0");
  free(D); free(b); free(q); free(X);
  whirl_fe_hbm_free(h);
  fe_chain_free(r);
}

/* ------------------------------- condensed = uncondensed (acceptance) */

static void test_condensed_vs_full(int pedestal, double Om, double unb,
                                   whirl_fe_nl_kind kind) {
  whirl_fe_rotor *r = model5_kind(pedestal, kind);
  int H = 5, n = r->ndof, L = 2 * H + 1;
  whirl_fe_hbm *hc = make(r, H, 0, 0, 0, 0), *hf = make(r, H, 1, 0, 0, 0);
  const whirl_system *sc = whirl_fe_hbm_system(hc), *sf = whirl_fe_hbm_system(hf);
  double *Xc = calloc(sc->n, sizeof *Xc), *Xf = calloc(sf->n, sizeof *Xf), p[4];
  whirl_fe_hbm_params(Om, p);
  p[WHIRL_FE_P_UNBALANCE] = unb;
  int ic = 0, jf = 0;
  int rc = whirl_newton(sc, Xc, p, 1e-13, 40, &ic);
  rc |= whirl_newton(sf, Xf, p, 1e-13, 40, &jf);
  double *qc = calloc((size_t)n * L, sizeof *qc), *qf = calloc((size_t)n * L, sizeof *qf);
  rc |= whirl_fe_hbm_recover(hc, Xc, p, qc);
  rc |= whirl_fe_hbm_recover(hf, Xf, p, qf);
  double d = 0, s = maxabs(qf, (size_t)n * L);
  for (int i = 0; i < n * L; ++i) d = fmax(d, fabs(qc[i] - qf[i]));
  ok(rc == 0, "%s: condensed (%zu unknowns, %d its) and uncondensed (%zu, "
     "%d its) converged at %g rad/s%s", kname(kind), sc->n,
     ic, sf->n, jf, Om, pedestal ? ", pedestal" : "");
  ok(d <= 1e-10 * s, "condensed = uncondensed on all %d DOF x %d coefficients: "
     "%.2e of %.2e", n, L, d, s);
  /* the interior LU by UMFPACK instead of the banded one */
  whirl_fe_hbm_options ou;
  whirl_fe_hbm_options_default(&ou);
  ou.harmonics = (size_t)H;
  ou.stability = 0;
  ou.interior_lu = 2;
  char eu[256] = "";
  whirl_fe_hbm *hu = whirl_fe_hbm_alloc(r, &ou, eu, sizeof eu);
  double *Xu = calloc(sc->n, sizeof *Xu), *qu = calloc((size_t)n * L, sizeof *qu);
  int iu = 0, ru = hu ? whirl_newton(whirl_fe_hbm_system(hu), Xu, p, 1e-13, 40, &iu) : -1;
  ru |= hu ? whirl_fe_hbm_recover(hu, Xu, p, qu) : -1;
  double du = 0;
  for (int i = 0; i < n * L; ++i) du = fmax(du, fabs(qu[i] - qf[i]));
  ok(ru == 0 && du <= 1e-10 * s, "condensed with UMFPACK's LU = uncondensed: "
     "%.2e of %.2e %s", du, s, eu);
  free(Xu); free(qu);
  whirl_fe_hbm_free(hu);
  double a1 = whirl_fe_hbm_amplitude(hc, qc, 4), c = r->nl[1].par.clearance;
  ok(a1 > 0.3 * c && a1 < c, "SFD journal amplitude %.3g of the clearance: "
     "nonlinear", a1 / c);
  free(qc); free(qf); free(Xc); free(Xf);
  whirl_fe_hbm_free(hc);
  whirl_fe_hbm_free(hf);
  fe_chain_free(r);
}

/* ν = 2 (response frequency Ω/2, H = 10) holds the synchronous orbit in
 * its even harmonics: harmonic 2k must equal harmonic k of ν = 1, H = 5
 * (the same 32 samples per shaft period), the odd ones 0. */
static void test_subharmonic_index(void) {
  whirl_fe_rotor *r = model5(0, 1e13);
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = 5;
  whirl_fe_hbm *h1 = whirl_fe_hbm_alloc(r, &o, NULL, 0);
  o.harmonics = 10;
  o.nu = 2;
  whirl_fe_hbm *h2 = whirl_fe_hbm_alloc(r, &o, NULL, 0);
  const whirl_system *s1 = whirl_fe_hbm_system(h1), *s2 = whirl_fe_hbm_system(h2);
  double *X1 = calloc(s1->n, sizeof *X1), *X2 = calloc(s2->n, sizeof *X2), p[4];
  whirl_fe_hbm_params(150.0, p);
  p[WHIRL_FE_P_UNBALANCE] = 12.0;
  int i1 = 0, i2 = 0, m = 0;
  int rc = whirl_newton(s1, X1, p, 1e-13, 40, &i1) | whirl_newton(s2, X2, p, 1e-13, 40, &i2);
  whirl_fe_hbm_nl_dofs(h1, &m);
  double d = 0, odd = 0, sc = maxabs(X1, s1->n);
  for (int j = 0; j < m; ++j) {
    d = fmax(d, fabs(X1[j] - X2[j]));
    for (int k = 1; k <= 5; ++k)
      for (int c = 0; c < 2; ++c)
        d = fmax(d, fabs(X1[m * (2 * k - 1 + c) + j] - X2[m * (4 * k - 1 + c) + j]));
    for (int k = 1; k <= 10; k += 2)
      odd = fmax(odd, fmax(fabs(X2[m * (2 * k - 1) + j]), fabs(X2[m * 2 * k + j])));
  }
  ok(rc == 0, "nu = 2: both converged (%d, %d iterations)", i1, i2);
  ok(d < 1e-11 * sc && odd < 1e-11 * sc, "nu = 2: even harmonics = nu = 1 "
     "(%.1e), odd harmonics 0 (%.1e), of %.2e", d, odd, sc);
  free(X1); free(X2);
  whirl_fe_hbm_free(h1);
  whirl_fe_hbm_free(h2);
  fe_chain_free(r);
}

/* ------------------------------------ the time-domain model (reference) */

/* x = (q, v): q' = v, M v' = f0 + s Ω² (u_c cos Ωt + u_s sin Ωt) + Σ Pᵀ f_e
 * − (C + Ω G) v − K q, with M⁻¹ dense. */
typedef struct tmodel {
  const whirl_fe_rotor *r;
  double *Minv; /* n×n */
  double *w;    /* 3n work */
} tmodel;

static void spmv_add(const whirl_fe_csc *A, const double *x, double s,
                     double *y) {
  for (int c = 0; c < A->n; ++c)
    for (int q = A->p[c]; q < A->p[c + 1]; ++q) y[A->i[q]] += s * A->x[q] * x[c];
}

static int elem(const whirl_fe_rotor *r, int e, const double *x, double Om,
                double f[2], double Jr[4], double Jv[4], int d[4]) {
  const whirl_fe_nl *el = &r->nl[e];
  int n = r->ndof;
  double rr[2], vv[2], aa[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    d[k] = 4 * el->node + k;
    d[2 + k] = el->pedestal >= 0 ? 4 * r->nnode + 2 * el->pedestal + k : -1;
    rr[k] = x[d[k]] - el->offset[k] - (d[2 + k] >= 0 ? x[d[2 + k]] : 0);
    vv[k] = x[n + d[k]] - (d[2 + k] >= 0 ? x[n + d[2 + k]] : 0);
  }
  return whirl_fe_nl_force(el, rr, vv, aa, Om, f, Jr, Jv, NULL) ? 1 : 0;
}

static int t_rhs(double t, const double *x, const double *p, double *f,
                 void *data) {
  tmodel *tm = data;
  const whirl_fe_rotor *r = tm->r;
  int n = r->ndof;
  double Om = p[0], *b = tm->w;
  for (int d = 0; d < n; ++d)
    b[d] = r->f0[d] + p[1] * Om * Om * (r->unb_c[d] * cos(Om * t) +
                                         r->unb_s[d] * sin(Om * t));
  spmv_add(&r->K, x, -1.0, b);
  spmv_add(&r->C, x + n, -1.0, b);
  spmv_add(&r->G, x + n, -Om, b);
  for (int e = 0; e < r->nnl; ++e) {
    double fe[2];
    int d[4];
    if (elem(r, e, x, Om, fe, NULL, NULL, d)) return 1;
    for (int k = 0; k < 2; ++k) {
      b[d[k]] += fe[k];
      if (d[2 + k] >= 0) b[d[2 + k]] -= fe[k];
    }
  }
  for (int i = 0; i < n; ++i) {
    f[i] = x[n + i];
    double s = 0;
    for (int j = 0; j < n; ++j) s += tm->Minv[i + n * j] * b[j];
    f[n + i] = s;
  }
  return 0;
}

/* J = [0 I; M⁻¹(−K + Pᵀ Jr P)  M⁻¹(−(C + ΩG) + Pᵀ Jv P)] */
static int t_jac(double t, const double *x, const double *p, double *J,
                 void *data) {
  (void)t;
  tmodel *tm = data;
  const whirl_fe_rotor *r = tm->r;
  int n = r->ndof, n2 = 2 * n;
  double *B = calloc((size_t)n * n2, sizeof *B); /* the force's Jacobian */
  const whirl_fe_csc *A[3] = {&r->K, &r->C, &r->G};
  double s[3] = {-1.0, -1.0, -p[0]};
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < n; ++c)
      for (int q = A[a]->p[c]; q < A[a]->p[c + 1]; ++q)
        B[A[a]->i[q] + n * (c + (a ? n : 0))] += s[a] * A[a]->x[q];
  for (int e = 0; e < r->nnl; ++e) {
    double fe[2], Jr[4], Jv[4];
    int d[4];
    if (elem(r, e, x, p[0], fe, Jr, Jv, d)) { free(B); return 1; }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        if (d[i] < 0 || d[j] < 0) continue;
        double sg = ((i < 2) == (j < 2)) ? 1.0 : -1.0;
        B[d[i] + n * d[j]] += sg * Jr[(i & 1) + 2 * (j & 1)];
        B[d[i] + n * (n + d[j])] += sg * Jv[(i & 1) + 2 * (j & 1)];
      }
  }
  memset(J, 0, (size_t)n2 * n2 * sizeof *J);
  for (int i = 0; i < n; ++i) J[i + n2 * (n + i)] = 1.0;
  for (int c = 0; c < n2; ++c)
    for (int i = 0; i < n; ++i) {
      double v = 0;
      for (int k = 0; k < n; ++k) v += tm->Minv[i + n * k] * B[k + n * c];
      J[n + i + n2 * c] = v;
    }
  free(B);
  return 0;
}

static void minv(const whirl_fe_rotor *r, double *Mi) {
  int n = r->ndof;
  double complex *A = malloc((size_t)n * n * sizeof *A), *b = malloc((size_t)n * sizeof *b);
  for (int j = 0; j < n; ++j) {
    memset(A, 0, (size_t)n * n * sizeof *A);
    dense_add(A, n, &r->M, 1.0);
    for (int i = 0; i < n; ++i) b[i] = i == j;
    csolve(n, A, b);
    for (int i = 0; i < n; ++i) Mi[i + n * j] = creal(b[i]);
  }
  free(A); free(b);
}

/* The monodromy multipliers of the orbit q (coefficients of every DOF) by
 * the variational equations over one period. */
static int monodromy(const whirl_fe_rotor *r, const double *q, int H,
                     const double *p, double *re, double *im) {
  int n = r->ndof;
  tmodel tm = {r, malloc((size_t)n * n * sizeof(double)), malloc(3 * (size_t)n * sizeof(double))};
  minv(r, tm.Minv);
  whirl_problem prob = {"fe-time", 2 * (size_t)n, 4, t_rhs, t_jac, NULL, 0,
                        NULL, NULL, &tm};
  double *x0 = calloc(2 * (size_t)n, sizeof *x0), Om = p[0];
  for (int d = 0; d < n; ++d) {
    x0[d] = q[d];
    for (int k = 1; k <= H; ++k) {
      x0[d] += q[n * (2 * k - 1) + d];
      x0[n + d] += k * Om * q[n * 2 * k + d];
    }
  }
  size_t m = 2 * (size_t)n;
  char err[256] = "";
  int rc = whirl_floquet_multipliers(&prob, p, 0.0, x0, 2 * PI / Om, 0, 1e-11,
                                     1e-14, re, im, &m, NULL, NULL, err,
                                     sizeof err);
  if (rc) printf("# floquet: %s\n", err);
  free(x0); free(tm.Minv); free(tm.w);
  return rc;
}

/* ------------------------------------ continuation, Hill and monodromy */

/* 3 nodes (12 DOF), a hardening cubic spring at node 0: a Duffing-like
 * resonance with two folds. */
static whirl_fe_rotor *duffing3(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 3);
  co.kb = 1e6;
  co.ks = 1e6;
  co.cb = 150;
  co.beta = 1e-5;
  co.me = 1e-3;
  co.nnl = 1;
  co.nl[0] = fe_chain_cubic(0, 0.0, 1e14);
  return fe_chain_build(&co);
}

typedef struct collect {
  int n, nlp, ntr, changes, last_stable;
  double lp[4];
  double *Xlp[4];
  double *Xs, *Xu;   /* a stable and an unstable point */
  double Os, Ou;
  double *Xt, Ot;    /* an unstable point of small amplitude */
  size_t nx;
} collect;

static int on_point(const whirl_fe_hbm_response_point *pt, void *ctx) {
  collect *c = ctx;
  ++c->n;
  if (c->n > 1 && pt->stable >= 0 && c->last_stable >= 0 &&
      pt->stable != c->last_stable)
    ++c->changes;
  if (pt->stable >= 0) c->last_stable = pt->stable;
  if (pt->type == WHIRL_PT_TR) ++c->ntr;
  if (pt->type == WHIRL_PT_LP && c->nlp < 4) {
    c->lp[c->nlp] = pt->Omega;
    c->Xlp[c->nlp] = malloc(pt->n * sizeof(double));
    memcpy(c->Xlp[c->nlp++], pt->X, pt->n * sizeof(double));
  }
  double **dst = pt->stable == 1 ? &c->Xs : (pt->stable == 0 ? &c->Xu : NULL);
  if (dst && !*dst && pt->amplitude > 2.5e-4 && pt->amplitude < 3.5e-4 &&
      pt->type == WHIRL_PT_REGULAR) {
    *dst = malloc(pt->n * sizeof(double));
    memcpy(*dst, pt->X, pt->n * sizeof(double));
    *(pt->stable ? &c->Os : &c->Ou) = pt->Omega;
  }
  if (pt->stable == 0 && !c->Xt && pt->amplitude < 1e-4 &&
      pt->type == WHIRL_PT_REGULAR) {
    c->Xt = malloc(pt->n * sizeof(double));
    memcpy(c->Xt, pt->X, pt->n * sizeof(double));
    c->Ot = pt->Omega;
  }
  c->nx = pt->n;
  return 0;
}

static void hill_vs_monodromy(whirl_fe_hbm *h, const whirl_fe_rotor *r,
                              const double *X, double Om, int H,
                              const char *what) {
  int n = r->ndof;
  double p[4], *q = calloc((size_t)n * (2 * H + 1), sizeof *q);
  double re[64], im[64], mr[64], mi[64];
  size_t m = 64;
  whirl_fe_hbm_params(Om, p);
  int rc = whirl_fe_hbm_hill(h, X, p, re, im, &m);
  rc |= whirl_fe_hbm_recover(h, X, p, q);
  rc |= monodromy(r, q, H, p, mr, mi);
  double T = 2 * PI / Om, hmax = exp(re[0] * T), mmax = hypot(mr[0], mi[0]);
  ok(rc == 0 && m == 2 * (size_t)n, "%s: Hill kept %zu exponents", what, m);
  is_abs(hmax, mmax, 2e-4 * fmax(1.0, mmax),
         "%s at %.2f rad/s: largest multiplier, Hill %.6f vs monodromy %.6f",
         what, Om, hmax, mmax);
  ok((hmax < 1) == (mmax < 1), "%s: Hill and monodromy agree on stability", what);
  free(q);
}

/* A fold locus through the fold system: from the first LP (Ω1, p at the
 * LP) in the parameter icp (direction dir), round the cusp where the two
 * folds meet, and back to the start's value, where it must arrive at the
 * second LP Ω2 of the speed continuation. */
static void test_fold_locus(const whirl_fe_rotor *r, int H, const double *X,
                            const double *p0, double Om2, size_t icp, int dir,
                            const char *name) {
  whirl_fe_hbm *h = make(r, H, 0, 0, 0, 0);
  const whirl_system *s = whirl_fe_hbm_system(h);
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, WHIRL_FE_P_OMEGA);
  char err[256] = "";
  whirl_fold *f = whirl_fold_alloc(s, &fo, err, sizeof err);
  double p[4], *Z = calloc(s->n + 1, sizeof *Z);
  memcpy(p, p0, sizeof p);
  int rc = f ? whirl_fold_init(f, X, p, Z) : -1;
  ok(rc == 0, "fold locus in speed x %s: started at the first LP %s", name, err);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = icp;
  co.ds = 0.01 * p0[icp];
  co.ds_max = 1.0;
  co.nmx = 400;
  co.p_min = 0.001 * p0[icp];
  co.p_max = 100 * p0[icp];
  co.newton_tol = 1e-9;
  double uz = p0[icp];
  int uz_stop = 1;
  co.uz = &uz;
  co.nuz = 1;
  co.uz_stop = &uz_stop;
  whirl_cont *c = rc ? NULL : whirl_cont_alloc(whirl_fold_system(f), &co, err, sizeof err);
  rc = c ? whirl_cont_start(c, Z, p, dir) : -1;
  double ext = p0[icp], Om_end = 0, v_end = 0;
  int steps = 0;
  while (!rc && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    double v = pt->p[icp];
    ext = dir < 0 ? fmin(ext, v) : fmax(ext, v);
    Om_end = pt->x[s->n];
    v_end = v;
    ++steps;
  }
  ok(rc == WHIRL_DONE && c && whirl_cont_stop_reason(c) == WHIRL_STOP_UZ,
     "fold locus in speed x %s: round the cusp (%s to %.4g) and back in %d "
     "steps", name, name, ext, steps);
  ok(fabs(ext / p0[icp] - 1) > 1e-3, "fold locus: the folds meet at %s %.4g",
     name, ext);
  is_rel(v_end, p0[icp], 1e-9, "fold locus: ends at the start's %s", name);
  is_rel(Om_end, Om2, 1e-6, "fold locus: at the second LP of the speed "
         "continuation, %.6f vs %.6f rad/s", Om_end, Om2);
  whirl_cont_free(c);
  whirl_fold_free(f);
  free(Z);
  whirl_fe_hbm_free(h);
}

/* Folds of an SFD-supported mode at 10× the unbalance: the speed response
 * and its fold locus in speed × clearance. */
static int on_lp(const whirl_fe_hbm_response_point *pt, void *ctx) {
  collect *c = ctx;
  if (pt->type == WHIRL_PT_LP && c->nlp < 4) {
    c->lp[c->nlp] = pt->Omega;
    c->Xlp[c->nlp] = malloc(pt->n * sizeof(double));
    memcpy(c->Xlp[c->nlp++], pt->X, pt->n * sizeof(double));
  }
  return 0;
}

static void test_sfd_clearance_locus(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 5);
  co.nnl = 1;
  co.nl[0] = fe_chain_sfd(4, -1);
  whirl_fe_rotor *r = fe_chain_build(&co);
  whirl_fe_hbm_response_options o;
  whirl_fe_hbm_response_options_default(&o);
  o.hbm.harmonics = 5;
  o.hbm.stability = 0;
  o.speed_min = 150;
  o.speed_max = 350;
  o.node = 4;
  o.unbalance = 10;
  collect c;
  memset(&c, 0, sizeof c);
  char err[256] = "";
  int rc = whirl_fe_hbm_response(r, &o, on_lp, &c, err, sizeof err);
  ok(rc == 0 && c.nlp == 2, "SFD rotor at 10x unbalance: two folds at %.3f, "
     "%.3f rad/s %s", c.lp[0], c.lp[1], err);
  if (c.nlp == 2) {
    double p[4];
    whirl_fe_hbm_params(c.lp[0], p);
    p[WHIRL_FE_P_UNBALANCE] = 10;
    test_fold_locus(r, 5, c.Xlp[0], p, c.lp[1], WHIRL_FE_P_CLEARANCE, +1,
                    "clearance");
  }
  for (int k = 0; k < c.nlp; ++k) free(c.Xlp[k]);
  fe_chain_free(r);
}

/* The sparse Hill method (ARPACK) against the dense one: every exponent
 * it returns is one of the dense exponents, and the rightmost agree. */
static void hill_sparse_vs_dense(const whirl_fe_rotor *r, const double *X,
                                 double Om, const char *what) {
  whirl_fe_hbm *hd = make(r, 5, 0, 0, 0, 1), *hs = make(r, 5, 0, 0, 0, 2);
  double p[4], dre[64], dim[64], sre[64], sim[64], w = Om, worst = 0;
  size_t md = 64, ms = 64;
  whirl_fe_hbm_params(Om, p);
  int rc = whirl_fe_hbm_hill(hd, X, p, dre, dim, &md);
  int rs = whirl_fe_hbm_hill(hs, X, p, sre, sim, &ms);
  if (rs == WHIRL_EINVAL && strstr(whirl_fe_hbm_errmsg(hs), "without ARPACK")) {
    ok(1, "# SKIP %s: built without ARPACK", what);
  } else {
    for (size_t i = 0; i < ms; ++i) {
      double best = INFINITY;
      for (size_t j = 0; j < md; ++j)
        best = fmin(best, hypot(sre[i] - dre[j], sim[i] - dim[j]));
      worst = fmax(worst, best);
    }
    ok(rc == 0 && rs == 0 && ms >= 4 && worst < 1e-8 * w,
       "%s: the %zu sparse Hill exponents (ARPACK) are dense ones (%.1e)",
       what, ms, worst / w);
    is_abs(sre[0], dre[0], 1e-8 * w, "%s: rightmost exponent, sparse %.6g vs "
           "dense %.6g", what, sre[0], dre[0]);
  }
  whirl_fe_hbm_free(hd);
  whirl_fe_hbm_free(hs);
}

/* The sparse Hill method's shift-invert solves condensed onto the nonlinear
 * DOFs (fe_hbm_shift.c: interior DOFs, gyroscopic terms, a pedestal, an SFD
 * whose Jacobian has displacement, velocity and — with fluid inertia —
 * acceleration parts) against the dense Hill method and the uncondensed
 * sparse route (UMFPACK on the whole Hill matrix), at a state that is not
 * an orbit (Hill's matrix is defined at any coefficients). */
static void hill_condensed_shift(whirl_fe_nl_kind kind) {
  whirl_fe_rotor *r = model5_kind(1, kind);
  const double ls = 2e-4; /* the SFD's clearance, the same for all three */
  whirl_fe_hbm *hd = make(r, 3, 0, ls, 0, 1), *hs = make(r, 3, 0, ls, 0, 2);
  whirl_fe_hbm *hu = make(r, 3, 1, ls, 0, 2);
  const whirl_system *sd = whirl_fe_hbm_system(hd), *su = whirl_fe_hbm_system(hu);
  double *X = calloc(sd->n, sizeof *X), *XU = calloc(su->n, sizeof *XU), p[4];
  double dre[400], dim[400], sre[64], sim[64], ure[64], uim[64], worst = 0;
  size_t md = 400, ms = 64, mu = 64;
  whirl_fe_hbm_params(250.0, p);
  p[1] = 1.3;
  for (size_t i = 0; i < sd->n; ++i) X[i] = tap_urand(-0.08, 0.08);
  /* the same state uncondensed: the nonlinear DOFs' coefficients as given,
   * the others recovered as the condensed system defines them */
  int rc = whirl_fe_hbm_recover(hd, X, p, XU);
  for (size_t i = 0; i < su->n; ++i) XU[i] /= ls;
  rc |= whirl_fe_hbm_hill(hd, X, p, dre, dim, &md);
  int rs = whirl_fe_hbm_hill(hs, X, p, sre, sim, &ms);
  int ru = whirl_fe_hbm_hill(hu, XU, p, ure, uim, &mu);
  if (rs == WHIRL_EINVAL && strstr(whirl_fe_hbm_errmsg(hs), "without ARPACK")) {
    ok(1, "# SKIP %s: built without ARPACK", kname(kind));
  } else {
    double w = 250.0, wu = 0;
    for (size_t i = 0; i < ms; ++i) {
      double best = INFINITY, bu = INFINITY;
      for (size_t j = 0; j < md; ++j)
        best = fmin(best, hypot(sre[i] - dre[j], sim[i] - dim[j]));
      for (size_t j = 0; j < mu; ++j)
        bu = fmin(bu, hypot(sre[i] - ure[j], sim[i] - uim[j]));
      worst = fmax(worst, best);
      wu = fmax(wu, bu);
    }
    ok(rc == 0 && rs == 0 && ru == 0 && ms >= 4 && worst < 1e-8 * w,
       "%s: the %zu condensed shift-invert exponents are dense Hill ones "
       "(%.1e)", kname(kind), ms, worst / w);
    ok(ms == mu && wu < 1e-8 * w, "%s: and the uncondensed sparse route's "
       "(%zu of %zu, %.1e)", kname(kind), ms, mu, wu / w);
  }
  free(X); free(XU);
  whirl_fe_hbm_free(hd); whirl_fe_hbm_free(hs); whirl_fe_hbm_free(hu);
  fe_chain_free(r);
}

/* The sparse Hill method returns every exponent within 1.05 ω/2 of its
 * shift, however many (nev grows to reach the disk's edge), and says
 * stability is unknown rather than return part of them when hill_nev
 * cannot hold them all: a 9-node chain at a speed where the disk holds
 * many of the dense method's exponents, at a state that is not an orbit. */
static void hill_sparse_complete(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 9);
  co.nnl = 1;
  co.nl[0] = fe_chain_sfd(8, -1);
  whirl_fe_rotor *r = fe_chain_build(&co);
  const double Om = 1500.0, w = Om, sigma = 1e-3 * w, R = 1.05 * 0.5 * w;
  whirl_fe_hbm *hd = make(r, 3, 0, 2e-4, 0, 1), *hs = make_capped(r, 3, 0, 2e-4, 0, 2, 0);
  whirl_fe_hbm *hf = make_capped(r, 3, 0, 2e-4, 0, 2, 4);
  const whirl_system *sd = whirl_fe_hbm_system(hd);
  double *X = calloc(sd->n, sizeof *X), p[4], dre[256], dim[256];
  double sre[64], sim[64], fre[64], fim[64], worst = 0;
  size_t md = 256, ms = 64, mf = 64, inside = 0;
  whirl_fe_hbm_params(Om, p);
  for (size_t i = 0; i < sd->n; ++i) X[i] = tap_urand(-0.3, 0.3);
  int rd = whirl_fe_hbm_hill(hd, X, p, dre, dim, &md);
  int rs = whirl_fe_hbm_hill(hs, X, p, sre, sim, &ms);
  if (rs == WHIRL_EINVAL && strstr(whirl_fe_hbm_errmsg(hs), "without ARPACK")) {
    ok(1, "# SKIP sparse Hill completeness: built without ARPACK");
  } else {
    for (size_t j = 0; j < md; ++j) {
      if (!(hypot(dre[j] - sigma, dim[j]) < 0.98 * R)) continue;
      double best = INFINITY;
      for (size_t i = 0; i < ms; ++i)
        best = fmin(best, hypot(sre[i] - dre[j], sim[i] - dim[j]));
      worst = fmax(worst, best);
      ++inside;
    }
    ok(rd == 0 && rs == 0 && inside >= 8 && worst < 1e-8 * w,
       "sparse Hill: all %zu dense exponents within 1.05 omega/2 of the shift "
       "are found (%zu returned, worst %.1e) %s", inside, ms, worst / w,
       rs ? whirl_fe_hbm_errmsg(hs) : "");
    int rf = whirl_fe_hbm_hill(hf, X, p, fre, fim, &mf);
    ok(rf == WHIRL_EMAXITER && strstr(whirl_fe_hbm_errmsg(hf), "stability unknown"),
       "sparse Hill with hill_nev 4 < %zu: stability unknown, not %zu of them "
       "(rc %d: %s)", inside, rf ? (size_t)0 : mf, rf, whirl_fe_hbm_errmsg(hf));
  }
  free(X);
  whirl_fe_hbm_free(hd); whirl_fe_hbm_free(hs); whirl_fe_hbm_free(hf);
  fe_chain_free(r);
}

/* The largest distance from an exponent of (re, im)[m] to the nearest of
 * (rr, ri)[mr], over those with |λ| < 0.45 ω (well inside the disk both
 * methods compute). */
static double exponent_distance(const double *re, const double *im, size_t m,
                                const double *rr, const double *ri, size_t mr,
                                double w) {
  double worst = 0;
  for (size_t j = 0; j < m; ++j) {
    if (hypot(re[j], im[j]) > 0.45 * w) continue;
    double best = INFINITY;
    for (size_t i = 0; i < mr; ++i) best = fmin(best, hypot(rr[i] - re[j], ri[i] - im[j]));
    worst = fmax(worst, best);
  }
  return worst;
}

/* Hill's method on the Craig–Bampton reduction (stability 3) against the
 * sparse method on the whole rotor: a 9-node shaft on a cubic spring
 * (node 0) and an SFD on a pedestal (node 8: the pedestal's constraint
 * mode does not reach the interior), at a state that is not an orbit.
 * With every interior mode kept the reduction is a change of basis: the
 * same exponents to rounding; with the default cutoff close, and closer
 * with a higher one (the modes' and the inertia relief's truncation). */
static void hill_reduced(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 9);
  co.pedestal = 1;
  co.nnl = 2;
  co.nl[0] = fe_chain_cubic(0, 1e6, 1e13);
  co.nl[1] = fe_chain_sfd(8, 0);
  whirl_fe_rotor *r = fe_chain_build(&co);
  const double Om = 600.0, w = Om;
  whirl_fe_hbm *hs = make(r, 3, 0, 2e-4, 0, 2);
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = 3;
  o.length_scale = 2e-4;
  o.stability = 3;
  const double cut[3] = {100, 2, 6};
  whirl_fe_hbm *hr[3];
  char err[256];
  for (int k = 0; k < 3; ++k) {
    o.hill_cutoff = cut[k];
    hr[k] = whirl_fe_hbm_alloc(r, &o, err, sizeof err);
  }
  const whirl_system *ss = whirl_fe_hbm_system(hs);
  double *X = calloc(ss->n, sizeof *X), p[4], sre[64], sim[64], rre[3][64], rim[3][64];
  size_t ms = 64, mr[3] = {64, 64, 64};
  whirl_fe_hbm_params(Om, p);
  for (size_t i = 0; i < ss->n; ++i) X[i] = tap_urand(-0.05, 0.05);
  int rs = whirl_fe_hbm_hill(hs, X, p, sre, sim, &ms), rr = 0;
  for (int k = 0; k < 3; ++k) rr |= hr[k] ? whirl_fe_hbm_hill(hr[k], X, p, rre[k], rim[k], &mr[k]) : -1;
  if (rs == WHIRL_EINVAL && strstr(whirl_fe_hbm_errmsg(hs), "without ARPACK")) {
    ok(1, "# SKIP reduced Hill: built without ARPACK");
  } else {
    double e[3];
    for (int k = 0; k < 3; ++k)
      e[k] = fmax(exponent_distance(sre, sim, ms, rre[k], rim[k], mr[k], w),
                  exponent_distance(rre[k], rim[k], mr[k], sre, sim, ms, w)) / w;
    if (rs || rr) printf("# %d %s / %d %s %s %s\n", rs, whirl_fe_hbm_errmsg(hs), rr, whirl_fe_hbm_errmsg(hr[0]), whirl_fe_hbm_errmsg(hr[1]), whirl_fe_hbm_errmsg(hr[2]));
    ok(rs == 0 && rr == 0 && ms >= 4 && mr[0] == ms && e[0] < 1e-9,
       "reduced Hill, every interior mode kept: the %zu sparse exponents (%zu, %.1e) %s",
       ms, mr[0], e[0], rr ? whirl_fe_hbm_errmsg(hr[0]) : "");
    ok(rr == 0 && e[1] < 1e-2 && fabs(rre[1][0] - sre[0]) < 1e-3 * w,
       "reduced Hill, cutoff 2 (H + 1/2) omega: exponents within %.1e omega, the "
       "rightmost %.6g against %.6g", e[1], rre[1][0], sre[0]);
    ok(rr == 0 && e[2] < 0.5 * e[1] && fabs(rre[2][0] - sre[0]) < 1e-5 * w,
       "reduced Hill, cutoff 6 (H + 1/2) omega: closer (%.1e omega), the rightmost "
       "%.8g against %.8g", e[2], rre[2][0], sre[0]);
  }
  free(X);
  whirl_fe_hbm_free(hs);
  for (int k = 0; k < 3; ++k) whirl_fe_hbm_free(hr[k]);
  fe_chain_free(r);
}

/* stability −1 (auto) on a rotor too large for the dense method is the
 * reduction; where that cannot be built (here: too small a reduction for
 * the sparse method with hill_nev 400) whirl takes the whole rotor's
 * sparse method instead — an explicit stability 3 says why it cannot. */
static void hill_auto_fallback(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 40);
  co.nnl = 1;
  co.nl[0] = fe_chain_sfd(39, -1);
  whirl_fe_rotor *r = fe_chain_build(&co);
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = 3;
  o.length_scale = 2e-4;
  o.hill_nev = 400;
  whirl_fe_hbm *h[3];
  char err[256];
  for (int k = 0; k < 3; ++k) {
    o.stability = k == 0 ? -1 : k == 1 ? 2 : 3;
    h[k] = whirl_fe_hbm_alloc(r, &o, err, sizeof err);
  }
  const whirl_system *s = whirl_fe_hbm_system(h[1]);
  double *X = calloc(s->n, sizeof *X), p[4], re[3][400], im[3][400], worst = 0;
  size_t m[3] = {400, 400, 400};
  whirl_fe_hbm_params(900.0, p);
  for (size_t i = 0; i < s->n; ++i) X[i] = tap_urand(-0.05, 0.05);
  int rc[3];
  for (int k = 0; k < 3; ++k) rc[k] = whirl_fe_hbm_hill(h[k], X, p, re[k], im[k], &m[k]);
  if (rc[1] == WHIRL_EINVAL && strstr(whirl_fe_hbm_errmsg(h[1]), "without ARPACK")) {
    ok(1, "# SKIP auto fallback: built without ARPACK");
  } else {
    for (size_t j = 0; j < m[0] && j < m[1]; ++j)
      worst = fmax(worst, hypot(re[0][j] - re[1][j], im[0][j] - im[1][j]));
    ok(rc[0] == 0 && rc[1] == 0 && m[0] == m[1] && m[0] >= 4 && worst < 1e-8 * 900.0,
       "auto on a reduction too small for hill_nev 400: the whole rotor's sparse "
       "exponents (%zu of %zu, %.1e)", m[0], m[1], worst);
    ok(rc[2] != 0 && strstr(whirl_fe_hbm_errmsg(h[2]), "too small"),
       "explicit reduced Hill there: an error that says why (%s)",
       whirl_fe_hbm_errmsg(h[2]));
  }
  free(X);
  for (int k = 0; k < 3; ++k) whirl_fe_hbm_free(h[k]);
  fe_chain_free(r);
}

static void test_response(void) {
  whirl_fe_rotor *r = duffing3();
  whirl_fe_hbm_response_options o;
  whirl_fe_hbm_response_options_default(&o);
  o.hbm.harmonics = 5;
  o.speed_min = 150;
  o.speed_max = 400;
  /* steps of at most 8 rad/s: the window of unstable tori (about 329 to
   * 341 rad/s) is wider than a step, so a point lands in it whatever the
   * corrector (the default range/10 = 25 rad/s may step over it) */
  o.ds_max = 8;
  o.node = 0;
  whirl_fe_hbm_response_report rep;
  memset(&rep, 0, sizeof rep);
  o.report = &rep;
  collect c;
  memset(&c, 0, sizeof c);
  c.last_stable = -1;
  char err[256] = "";
  int rc = whirl_fe_hbm_response(r, &o, on_point, &c, err, sizeof err);
  ok(rc == 0, "response: continuation 150..400 rad/s (%d points) %s", c.n, err);
  ok(c.nlp == 2, "response: two folds (LP) of the hardening resonance: %d at "
     "%.1f, %.1f rad/s", c.nlp, c.lp[0], c.lp[1]);
  /* the core labels a TR where the complex multiplier nearest the unit
   * circle crosses it; on the way back another pair is nearer, so only the
   * first crossing is certain to be labelled */
  ok(c.ntr >= 1, "response: a torus point (TR) past the resonance, %d",
     c.ntr);
  ok(c.changes == 4, "response: stability changes at the two LP and the two "
     "TR (%d)", c.changes);
  if (c.nlp == 2) {
    double p[4];
    whirl_fe_hbm_params(c.lp[0], p);
    test_fold_locus(r, 5, c.Xlp[0], p, c.lp[1], WHIRL_FE_P_UNBALANCE, -1,
                    "unbalance");
  }
  whirl_fe_hbm *h = make(r, 5, 0, 0, 0, 1);
  /* the report: a step per point but the start and the located ones */
  ok(rep.unknowns == whirl_fe_hbm_size(h) && rep.cont.steps + 1 + rep.cont.special >=
         (size_t)c.n && rep.cont.steps < (size_t)c.n && rep.cont.newton_its > rep.cont.steps &&
         rep.cont.eig_evals >= rep.cont.steps,
     "response report: %zu unknowns (%zu), %zu steps and %zu special for %d points, "
     "%zu Newton iterations, %zu spectra", rep.unknowns, whirl_fe_hbm_size(h),
     rep.cont.steps, rep.cont.special, c.n, rep.cont.newton_its, rep.cont.eig_evals);
  for (int k = 0; k < c.nlp; ++k) { /* a fold: a Floquet multiplier +1 */
    double p[4], re[64], im[64], best = INFINITY;
    size_t m = 64;
    whirl_fe_hbm_params(c.lp[k], p);
    const whirl_system *s = whirl_fe_hbm_system(h);
    rc = s->spectrum(c.Xlp[k], p, NULL, re, im, &m, s->data);
    for (size_t i = 0; i < m; ++i) best = fmin(best, hypot(re[i] - 1, im[i]));
    ok(rc == 0 && best < 1e-3, "fold %d: Hill multiplier at +1 (|mu - 1| = %.1e)",
       k + 1, best);
    free(c.Xlp[k]);
  }
  if (c.Xs) hill_vs_monodromy(h, r, c.Xs, c.Os, 5, "stable orbit");
  else ok(0, "a stable orbit was found");
  if (c.Xu) hill_vs_monodromy(h, r, c.Xu, c.Ou, 5, "unstable orbit");
  else ok(0, "an unstable orbit was found");
  if (c.Xt) hill_vs_monodromy(h, r, c.Xt, c.Ot, 5, "small unstable orbit");
  if (c.Xs) hill_sparse_vs_dense(r, c.Xs, c.Os, "stable orbit");
  if (c.Xu) hill_sparse_vs_dense(r, c.Xu, c.Ou, "unstable orbit");
  if (c.Xt) hill_sparse_vs_dense(r, c.Xt, c.Ot, "small unstable orbit");
  free(c.Xs); free(c.Xu); free(c.Xt);
  whirl_fe_hbm_free(h);
  fe_chain_free(r);
}

/* --------------------------------------- a rotor file (reader, Timoshenko) */

static const char rotor_text[] =
    "title two-disk rotor on a squeeze-film damper and a pedestal\n"
    "material steel E=211e9 G=81.2e9 rho=7810\n"
    "shaft from=0 to=4 length=0.8 od=0.06 id=0.02 material=steel\n"
    "shaft from=4 to=6 length=0.3 od=0.04 material=steel\n"
    "disk node=2 mass=12.5 ip=0.12 it=0.07\n"
    "disk node=5 width=0.05 od=0.25 id=0.04 material=steel\n"
    "pedestal housing mass=30 kyy=5e7 kzz=5e7 cyy=2e3 czz=2e3\n"
    "bearing node=0 kyy=2e7 kzz=1.8e7 kyz=1e5 kzy=-1e5 cyy=500 czz=500\n"
    "bearing node=6 kyy=1e7 kzz=1e7 pedestal=housing\n"
    "%s\n"
    "unbalance node=2 me=2e-4 phase-deg=0\n"
    "unbalance node=5 me=1e-4 phase-deg=90\n"
    "%s\n"
    "speed from=0 to=12000 unit=rpm\n";

static whirl_fe_rotor *rotor_file(const char *nl, const char *gravity) {
  char text[2048], path[64], msg[512] = "";
  snprintf(text, sizeof text, rotor_text, nl, gravity);
  snprintf(path, sizeof path, "t_fe_hbm.XXXXXX");
  int fd = mkstemp(path);
  if (fd < 0) return NULL;
  FILE *f = fdopen(fd, "w");
  fputs(text, f);
  fclose(f);
  whirl_fe_rotor *r = whirl_fe_rotor_read(path, msg, sizeof msg, NULL);
  unlink(path);
  if (!r) printf("# %s\n", msg);
  return r;
}

/* A null element (cubic, k1 = k3 = 0): the condensed HBM's harmonic 1 of
 * every DOF = the linear unbalance response (fe-model's direct sparse
 * solve of the real 2 ndof form, whirl_fe_unbalance_response). */
static void test_file_linear(void) {
  whirl_fe_rotor *r = rotor_file("cubic node=6 k1=0 k3=0 pedestal=housing", "");
  ok(r != NULL, "rotor file read (%d DOF)", r ? r->ndof : 0);
  if (!r) return;
  whirl_fe_hbm *h = make(r, 3, 0, 1e-4, 0, 0);
  const whirl_system *s = whirl_fe_hbm_system(h);
  int n = r->ndof, its = 0;
  double *X = calloc(s->n, sizeof *X), *q = calloc((size_t)n * 7, sizeof *q);
  double *qr = malloc((size_t)n * sizeof *qr), *qi = malloc((size_t)n * sizeof *qi);
  double p[4], Om = 700.0, d = 0, sc = 0;
  whirl_fe_hbm_params(Om, p);
  int rc = whirl_newton(s, X, p, 1e-13, 10, &its);
  rc |= whirl_fe_hbm_recover(h, X, p, q);
  rc |= whirl_fe_unbalance_response(r, Om, qr, qi, NULL, 0);
  for (int i = 0; i < n; ++i) {
    d = fmax(d, hypot(q[n + i] - qr[i], -q[2 * n + i] - qi[i]));
    sc = fmax(sc, hypot(qr[i], qi[i]));
  }
  ok(rc == 0 && d < 1e-10 * sc, "file rotor, null element: HBM = linear "
     "unbalance response on all %d DOF (%.1e of %.1e)", n, d, sc);
  free(X); free(q); free(qr); free(qi);
  whirl_fe_hbm_free(h);
  whirl_fe_rotor_free(r);
}

/* The file's SFD on the pedestal, with gravity: condensed = uncondensed. */
static void test_file_sfd(void) {
  whirl_fe_rotor *r = rotor_file(
      "sfd-short-pi node=6 radius=0.04 length=0.012 clearance=1.5e-4 "
      "viscosity=0.02 pedestal=housing offset-z=-3e-5",
      "gravity g=9.81 direction=-z");
  if (!r) { ok(0, "rotor file with an SFD read"); return; }
  int H = 4, n = r->ndof, L = 2 * H + 1;
  whirl_fe_hbm *hc = make(r, H, 0, 0, 0, 0), *hf = make(r, H, 1, 0, 0, 0);
  const whirl_system *sc = whirl_fe_hbm_system(hc), *sf = whirl_fe_hbm_system(hf);
  double *Xc = calloc(sc->n, sizeof *Xc), *Xf = calloc(sf->n, sizeof *Xf), p[4];
  double *qc = calloc((size_t)n * L, sizeof *qc), *qf = calloc((size_t)n * L, sizeof *qf);
  whirl_fe_hbm_params(600.0, p);
  p[WHIRL_FE_P_UNBALANCE] = 5.0;
  int i1 = 0, i2 = 0;
  int rc = whirl_newton(sc, Xc, p, 1e-13, 40, &i1) | whirl_newton(sf, Xf, p, 1e-13, 40, &i2);
  rc |= whirl_fe_hbm_recover(hc, Xc, p, qc) | whirl_fe_hbm_recover(hf, Xf, p, qf);
  double d = 0, s = maxabs(qf, (size_t)n * L);
  for (int i = 0; i < n * L; ++i) d = fmax(d, fabs(qc[i] - qf[i]));
  double e = whirl_fe_hbm_amplitude(hc, qc, 6);
  if (rc) printf("# rc %d its %d %d\n", rc, i1, i2);
  ok(rc == 0 && i1 >= 3 && d <= 1e-10 * s, "file rotor, SFD on the pedestal: "
     "condensed (%zu, %d its) = uncondensed (%zu) to %.1e of %.1e (journal "
     "at %.3g m)", sc->n, i1, sf->n, d, s, e);
  free(Xc); free(Xf); free(qc); free(qf);
  whirl_fe_hbm_free(hc);
  whirl_fe_hbm_free(hf);
  whirl_fe_rotor_free(r);
}

/* Bad options are refused with a message; contact is recoverable. */
static void test_errors(void) {
  whirl_fe_rotor *r = model5(0, 1e13);
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  char err[256] = "";
  o.nu = 6;
  ok(!whirl_fe_hbm_alloc(r, &o, err, sizeof err) && strstr(err, "nu"),
     "nu > harmonics refused: %s", err);
  whirl_fe_hbm_options_default(&o);
  o.nsamples = 10;
  ok(!whirl_fe_hbm_alloc(r, &o, err, sizeof err) && strstr(err, "nsamples"),
     "nsamples <= 2H refused: %s", err);
  for (int st = -1; st <= 3; st += 4) { /* auto may take the reduction too */
    whirl_fe_hbm_options_default(&o);
    o.stability = st;
    o.hill_cutoff = 0;
    ok(!whirl_fe_hbm_alloc(r, &o, err, sizeof err) && strstr(err, "hill_cutoff"),
       "stability %d with hill_cutoff 0 refused: %s", st, err);
  }
  whirl_fe_hbm_options_default(&o);
  int nnl = r->nnl;
  r->nnl = 0;
  ok(!whirl_fe_hbm_alloc(r, &o, err, sizeof err), "no nonlinear element "
     "refused: %s", err);
  r->nnl = nnl;
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &o, NULL, 0);
  const whirl_system *s = whirl_fe_hbm_system(h);
  double *X = calloc(s->n, sizeof *X), *F = calloc(s->n, sizeof *F), p[4];
  int m = 0;
  const int *dof = whirl_fe_hbm_nl_dofs(h, &m);
  ok(m == 4 && dof[0] == 0 && dof[1] == 1 && dof[2] == 16 && dof[3] == 17,
     "nonlinear DOFs: y, z of nodes 0 and 4");
  whirl_fe_hbm_params(100.0, p);
  X[2 * m + 2] = 1.2; /* the SFD journal's y beyond its clearance (Ls = c) */
  int rc = s->F(X, p, F, s->data);
  ok(rc > 0, "journal beyond the clearance: recoverable (%d)", rc);
  free(X); free(F);
  whirl_fe_hbm_free(h);
  fe_chain_free(r);
}

int main(void) {
  test_aft_cubic();
  test_aft_sfd_circular();
  test_jacobians(0, 0, WHIRL_FE_SFD_SHORT_PI);
  test_jacobians(1, 0, WHIRL_FE_SFD_SHORT_PI);
  test_jacobians(1, 1, WHIRL_FE_SFD_SHORT_PI);
  test_jacobians(1, 0, WHIRL_FE_SFD_INERTIA);
  test_jacobians(0, 1, WHIRL_FE_SFD_INERTIA);
  test_jacobians(0, 0, WHIRL_FE_SFD_LONG);
  test_jacobians(0, 0, WHIRL_FE_SFD_SHORT_2PI);
  hill_condensed_shift(WHIRL_FE_SFD_SHORT_PI);
  hill_condensed_shift(WHIRL_FE_SFD_INERTIA);
  hill_sparse_complete();
  hill_reduced();
  hill_auto_fallback();
  test_linear();
  test_speed_cache();
  test_condensed_vs_full(0, 150.0, 12.0, WHIRL_FE_SFD_SHORT_PI);
  test_condensed_vs_full(1, 320.0, 4.0, WHIRL_FE_SFD_SHORT_PI);
  test_condensed_vs_full(1, 320.0, 4.0, WHIRL_FE_SFD_INERTIA);
  test_condensed_vs_full(0, 150.0, 12.0, WHIRL_FE_SFD_SHORT_2PI);
  test_subharmonic_index();
  test_errors();
  test_file_linear();
  test_file_sfd();
  test_response();
  test_sfd_clearance_locus();
  return done_testing();
}

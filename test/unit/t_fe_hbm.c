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
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/cont.h>
#include <whirl/floquet.h>
#include <whirl/rotor/fe_hbm.h>

#include "../fe_chain.h"
#include "../tap.h"

#define PI 3.14159265358979323846

static whirl_fe_hbm *make(const whirl_fe_rotor *r, int H, int uncondensed,
                          double Ls, double Fs, int stability) {
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = (size_t)H;
  o.uncondensed = uncondensed;
  o.length_scale = Ls;
  o.force_scale = Fs;
  o.stability = stability;
  char err[256] = "";
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &o, err, sizeof err);
  if (!h) printf("# alloc: %s\n", err);
  return h;
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

static double maxabs(const double *x, size_t n) {
  double m = 0;
  for (size_t i = 0; i < n; ++i) m = fmax(m, fabs(x[i]));
  return m;
}

static void test_jacobians(int pedestal, int uncondensed) {
  whirl_fe_rotor *r = model5(pedestal, 1e13);
  whirl_fe_hbm *h = make(r, 3, uncondensed, 0, 0, 0);
  const whirl_system *s = whirl_fe_hbm_system(h);
  double *X = calloc(s->n, sizeof *X), p[4], err = 1;
  whirl_fe_hbm_params(250.0, p);
  p[1] = 1.3; p[2] = 1.1; p[3] = 0.9;
  for (size_t i = 0; i < s->n; ++i) X[i] = tap_urand(-0.08, 0.08);
  int rc = whirl_system_check_jacobian(s, X, p, &err);
  ok(rc == 0 && err < 2e-6, "%s%s: Jacobian and dF/dp against differences "
     "(%.2e)", uncondensed ? "uncondensed" : "condensed",
     pedestal ? ", pedestal" : "", err);
  free(X);
  whirl_fe_hbm_free(h);
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

static void test_condensed_vs_full(int pedestal, double Om) {
  whirl_fe_rotor *r = model5(pedestal, 1e13);
  int H = 5, n = r->ndof, L = 2 * H + 1;
  whirl_fe_hbm *hc = make(r, H, 0, 0, 0, 0), *hf = make(r, H, 1, 0, 0, 0);
  const whirl_system *sc = whirl_fe_hbm_system(hc), *sf = whirl_fe_hbm_system(hf);
  double *Xc = calloc(sc->n, sizeof *Xc), *Xf = calloc(sf->n, sizeof *Xf), p[4];
  whirl_fe_hbm_params(Om, p);
  int ic = 0, jf = 0;
  int rc = whirl_newton(sc, Xc, p, 1e-13, 40, &ic);
  rc |= whirl_newton(sf, Xf, p, 1e-13, 40, &jf);
  double *qc = calloc((size_t)n * L, sizeof *qc), *qf = calloc((size_t)n * L, sizeof *qf);
  rc |= whirl_fe_hbm_recover(hc, Xc, p, qc);
  rc |= whirl_fe_hbm_recover(hf, Xf, p, qf);
  double d = 0, s = maxabs(qf, (size_t)n * L);
  for (int i = 0; i < n * L; ++i) d = fmax(d, fabs(qc[i] - qf[i]));
  ok(rc == 0, "condensed (%zu unknowns, %d its) and uncondensed (%zu, %d its) "
     "converged at %g rad/s%s", sc->n, ic, sf->n, jf, Om,
     pedestal ? ", pedestal" : "");
  ok(d <= 1e-10 * s, "condensed = uncondensed on all %d DOF x %d coefficients: "
     "%.2e of %.2e", n, L, d, s);
  double a1 = whirl_fe_hbm_amplitude(hc, qc, 4), c = r->nl[1].par.clearance;
  ok(a1 > 1e-3 * c && a1 < c, "SFD journal amplitude %.3g m inside the clearance",
     a1);
  free(qc); free(qf); free(Xc); free(Xf);
  whirl_fe_hbm_free(hc);
  whirl_fe_hbm_free(hf);
  fe_chain_free(r);
}

int main(void) {
  test_aft_cubic();
  test_aft_sfd_circular();
  test_jacobians(0, 0);
  test_jacobians(1, 0);
  test_jacobians(1, 1);
  test_linear();
  test_condensed_vs_full(0, 150.0);
  test_condensed_vs_full(1, 320.0);
  return done_testing();
}

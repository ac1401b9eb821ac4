/* test/unit/t_colloc.c — periodic orbits by orthogonal collocation
 * (lib/systems/colloc.c) against closed forms and independent computations:
 * the sparse Jacobian against finite differences (Lorenz, forced Duffing),
 * the limit cycle of the λ-ω system (radius sqrt(a), period 2π, multiplier
 * exp(-4πa)), the steady state of a forced linear oscillator (amplitude and
 * multipliers in closed form), a continuation of the λ-ω cycle with the
 * dense and the sparse solver, the stable periodic orbit of the Lorenz
 * system at ρ = 250 against direct time integration, mesh adaptation, and
 * rejected options.
 * Run with the argument "quick" to skip the Lorenz orbit and shorten the
 * continuation (for valgrind).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/branch.h>
#include <whirl/colloc.h>
#include <whirl/periodic.h>
#include <whirl/cont.h>
#include <whirl/linsol.h>
#include <whirl/ode.h>
#include <whirl/rotor/sfd.h>
#include <whirl/rotor/sfd_dynamics.h>

#include "../tap.h"
#include "bsolver_check.h"
#ifdef _OPENMP
#include <omp.h>
#endif

#define PI 3.14159265358979323846

/* ------------------------------------------------------------------------
 * Models */

/* Lorenz, p = (σ, ρ, b) */
static int lor_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t;
  (void)data;
  f[0] = p[0] * (x[1] - x[0]);
  f[1] = x[0] * (p[1] - x[2]) - x[1];
  f[2] = x[0] * x[1] - p[2] * x[2];
  return 0;
}
static int lor_jac(double t, const double *x, const double *p, double *J,
                   void *data) {
  (void)t;
  (void)data;
  J[0] = -p[0], J[1] = p[1] - x[2], J[2] = x[1];
  J[3] = p[0], J[4] = -1.0, J[5] = x[0];
  J[6] = 0.0, J[7] = -x[0], J[8] = -p[2];
  return 0;
}
static int lor_jacp(double t, const double *x, const double *p, double *J,
                    void *data) {
  (void)t;
  (void)p;
  (void)data;
  J[0] = x[1] - x[0], J[1] = 0.0, J[2] = 0.0;
  J[3] = 0.0, J[4] = x[0], J[5] = 0.0;
  J[6] = 0.0, J[7] = 0.0, J[8] = -x[2];
  return 0;
}
static const whirl_problem lorenz = {.name = "lorenz",
                                     .n = 3,
                                     .npar = 3,
                                     .rhs = lor_rhs,
                                     .jac_x = lor_jac,
                                     .jac_p = lor_jacp,
                                     .autonomous = 1};
/* the same without Jacobians: the constructor differences f itself */
static const whirl_problem lorenz_fd = {
    .name = "lorenz-fd", .n = 3, .npar = 3, .rhs = lor_rhs, .autonomous = 1};

/* λ-ω system x' = a x - y - x r², y' = x + a y - y r², p = (a): in polar
 * coordinates r' = r (a - r²), θ' = 1, so the cycle is the circle of radius
 * sqrt(a), period 2π; the radial linearisation a - 3r² = -2a gives the
 * nontrivial multiplier exp(-2a · 2π). */
static int lw_rhs(double t, const double *x, const double *p, double *f,
                  void *data) {
  (void)t;
  (void)data;
  const double r2 = x[0] * x[0] + x[1] * x[1];
  f[0] = p[0] * x[0] - x[1] - x[0] * r2;
  f[1] = x[0] + p[0] * x[1] - x[1] * r2;
  return 0;
}
static int lw_jac(double t, const double *x, const double *p, double *J,
                  void *data) {
  (void)t;
  (void)data;
  const double r2 = x[0] * x[0] + x[1] * x[1];
  J[0] = p[0] - r2 - 2.0 * x[0] * x[0];
  J[1] = 1.0 - 2.0 * x[0] * x[1];
  J[2] = -1.0 - 2.0 * x[0] * x[1];
  J[3] = p[0] - r2 - 2.0 * x[1] * x[1];
  return 0;
}
static int lw_jacp(double t, const double *x, const double *p, double *J,
                   void *data) {
  (void)t;
  (void)p;
  (void)data;
  J[0] = x[0];
  J[1] = x[1];
  return 0;
}
static const whirl_problem lamom = {.name = "lambda-omega",
                                    .n = 2,
                                    .npar = 1,
                                    .rhs = lw_rhs,
                                    .jac_x = lw_jac,
                                    .jac_p = lw_jacp,
                                    .autonomous = 1};

/* forced Duffing x'' + 2ζ x' + x + β x³ = cos(ω t), p = (ω, ζ, β); linear
 * for β = 0 */
static int duf_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)data;
  f[0] = x[1];
  f[1] = -x[0] - 2.0 * p[1] * x[1] - p[2] * x[0] * x[0] * x[0] + cos(p[0] * t);
  return 0;
}
static int duf_jac(double t, const double *x, const double *p, double *J,
                   void *data) {
  (void)t;
  (void)data;
  J[0] = 0.0, J[1] = -1.0 - 3.0 * p[2] * x[0] * x[0];
  J[2] = 1.0, J[3] = -2.0 * p[1];
  return 0;
}
static int duf_jacp(double t, const double *x, const double *p, double *J,
                    void *data) {
  (void)data;
  J[0] = 0.0, J[1] = -t * sin(p[0] * t);
  J[2] = 0.0, J[3] = -2.0 * x[1];
  J[4] = 0.0, J[5] = -x[0] * x[0] * x[0];
  return 0;
}
static const whirl_problem duffing = {.name = "duffing",
                                      .n = 2,
                                      .npar = 3,
                                      .rhs = duf_rhs,
                                      .jac_x = duf_jac,
                                      .jac_p = duf_jacp,
                                      .autonomous = 0};

/* ------------------------------------------------------------------------
 * Helpers */

/* The compressed-column pattern is well formed: Jp non-decreasing from 0 to
 * nnz, rows in range and strictly increasing within each column. */
static int pattern_ok(const whirl_system *s) {
  if (!s->Jp || !s->Ji || s->Jp[0] != 0 || (size_t)s->Jp[s->n] != s->nnz)
    return 0;
  for (size_t j = 0; j < s->n; ++j) {
    if (s->Jp[j + 1] < s->Jp[j]) return 0;
    for (int q = s->Jp[j]; q < s->Jp[j + 1]; ++q) {
      if (s->Ji[q] < 0 || (size_t)s->Ji[q] >= s->n) return 0;
      if (q > s->Jp[j] && s->Ji[q] <= s->Ji[q - 1]) return 0;
    }
  }
  return 1;
}

/* max over the mesh points τ_i of | |x(τ_i)| - r | (2-D orbits); the
 * collocation solution is superconvergent there (de Boor & Swartz). */
static double radius_err_mesh(const double *X, size_t ntst, size_t ncol,
                              double r) {
  double e = 0.0;
  for (size_t i = 0; i <= ntst; ++i) {
    const double *x = X + 2 * (i * ncol);
    e = fmax(e, fabs(hypot(x[0], x[1]) - r));
  }
  return e;
}

/* same at every node */
static double radius_err_nodes(const double *X, size_t nnodes, double r) {
  double e = 0.0;
  for (size_t j = 0; j < nnodes; ++j)
    e = fmax(e, fabs(hypot(X[2 * j], X[2 * j + 1]) - r));
  return e;
}

/* samples of the circle of radius R, counter-clockwise from (R, 0) */
static void circle_samples(double R, size_t m, double *x) {
  for (size_t k = 0; k < m; ++k) {
    x[2 * k] = R * cos(2.0 * PI * (double)k / (double)m);
    x[2 * k + 1] = R * sin(2.0 * PI * (double)k / (double)m);
  }
}

/* distance from (re, im) to the nearest of the pair (a ± i b) */
static double pair_dist(double re, double im, double a, double b) {
  return fmin(hypot(re - a, im - b), hypot(re - a, im + b));
}

/* Newton correction at fixed parameters by the continuation core: start,
 * then the first step delivers the corrected start point (EP) from the
 * core's queue without taking a continuation step. */
static int correct(whirl_cont *ct, const double *X, const double *p) {
  int rc = whirl_cont_start(ct, X, p, 1);
  if (rc == WHIRL_OK) rc = whirl_cont_step(ct);
  return rc;
}

/* Lorenz without f_x (differences), recording the size of the OpenMP teams
 * that call it (which threads of a team take the intervals is the
 * schedule's choice: a team of 3 may leave all of them to one), and failing
 * (status 3 + ⌊10 t / T⌋) at t > fail_from·T when fail_from < 1: the
 * threads test below. */
static int seen_team[64];
static double fail_from = 2.0, fail_T = 1.0;
static int lor_seen_rhs(double t, const double *x, const double *p, double *f,
                        void *data) {
#ifdef _OPENMP
  const int tid = omp_get_thread_num(), team = omp_get_num_threads();
  if (tid >= 0 && tid < 64 && team < 64) seen_team[tid] |= 1 << (team < 30 ? team : 30);
#endif
  if (t > fail_from * fail_T) return 3 + (int)(10.0 * t / fail_T);
  return lor_rhs(t, x, p, f, data);
}
static const whirl_problem lorenz_seen = {
    .name = "lorenz-threads", .n = 3, .npar = 3, .rhs = lor_seen_rhs,
    .jac_p = lor_jacp}; /* f_p: the factorisation fills without F */

/* ------------------------------------------------------------------------
 * 1. Jacobians */

/* A closed curve of the Lorenz model, not a solution, plus a random
 * perturbation of every node: X[nx] (period 0.7) for Jacobian checks. */
static void lorenz_curve(whirl_colloc *c, size_t nx, double *X) {
  double smp[3 * 32];
  for (size_t k = 0; k < 32; ++k) {
    const double th = 2.0 * PI * (double)k / 32.0;
    smp[3 * k] = 10.0 * cos(th) + 3.0;
    smp[3 * k + 1] = 15.0 * sin(th);
    smp[3 * k + 2] = 200.0 + 30.0 * cos(2.0 * th);
  }
  whirl_colloc_from_samples(c, smp, 32, 0.7, X);
  for (size_t q = 0; q + 1 < nx; ++q) X[q] += tap_urand(-1.0, 1.0);
}

static void test_jacobians(void) {
  char err[256];
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = 10;
  o.ncol = 4;
  const whirl_problem *lp[2] = {&lorenz, &lorenz_fd};
  for (int v = 0; v < 2; ++v) {
    whirl_colloc *c = whirl_colloc_alloc(lp[v], &o, err, sizeof err);
    ok(c != NULL, "alloc Lorenz (%s) NTST 10 NCOL 4: %s", lp[v]->name, err);
    if (!c) continue;
    const whirl_system *s = whirl_colloc_system(c);
    const size_t nx = whirl_colloc_size(c);
    ok(nx == 3 * 41 + 1 && s->n == nx,
       "size n (NTST NCOL + 1) + 1 = 124 (got %zu)", nx);
    ok(pattern_ok(s), "sparse pattern well formed, sorted rows (nnz %zu)",
       s->nnz);
    ok(s->spectrum_kind == WHIRL_SPEC_MULTIPLIERS && s->nspec == 2 &&
           s->accept != NULL,
       "autonomous: multipliers, nspec n-1 = 2, accept hook");
    double *X = malloc(nx * sizeof *X);
    lorenz_curve(c, nx, X);
    const double p[3] = {10.0, 250.0, 8.0 / 3.0};
    double e_dense = NAN, e_sparse = NAN;
    int rc1 = whirl_system_check_jacobian(s, X, p, &e_dense);
    whirl_system sp = *s;
    sp.Fx = NULL; /* the checker then scatters Fx_sparse */
    int rc2 = whirl_system_check_jacobian(&sp, X, p, &e_sparse);
    printf("# Lorenz (%s): Jacobian error dense %.2e sparse %.2e\n",
           lp[v]->name, e_dense, e_sparse);
    ok(rc1 == 0 && e_dense < 1e-6,
       "Lorenz (%s): dense Jacobian and F_p vs differences %.2e < 1e-6",
       lp[v]->name, e_dense);
    ok(rc2 == 0 && e_sparse < 1e-6,
       "Lorenz (%s): sparse Jacobian vs differences %.2e < 1e-6", lp[v]->name,
       e_sparse);
    /* F_p from the model's jac_p, or from differences of f at the Gauss
     * points (checked against the whole residual's differences above) */
    ok(s->Fp != NULL, "Lorenz (%s): F_p present", lp[v]->name);
    free(X);
    whirl_colloc_free(c);
  }

  /* forced Duffing (nonlinear, explicit time): forced mode, t0 != 0, and
   * autonomous mode on a time-dependent model (T column carries ∂f/∂t) */
  for (int mode = 0; mode < 2; ++mode) {
    whirl_colloc_options_default(&o);
    o.ntst = 8;
    o.ncol = 3;
    o.t0 = 0.4;
    o.forcing_param = mode == 0 ? 0 : -1;
    whirl_colloc *c = whirl_colloc_alloc(&duffing, &o, err, sizeof err);
    ok(c != NULL, "alloc Duffing, forcing_param %d: %s", o.forcing_param, err);
    if (!c) continue;
    const whirl_system *s = whirl_colloc_system(c);
    const size_t nx = whirl_colloc_size(c);
    ok(nx == 2 * 25 + (size_t)(mode == 1), "size %zu", nx);
    ok(pattern_ok(s), "Duffing: sparse pattern well formed");
    double smp[2 * 16], *X = malloc(nx * sizeof *X);
    for (size_t k = 0; k < 16; ++k) {
      smp[2 * k] = cos(2.0 * PI * (double)k / 16.0);
      smp[2 * k + 1] = -sin(2.0 * PI * (double)k / 16.0);
    }
    whirl_colloc_from_samples(c, smp, 16, 2.0 * PI / 1.3, X);
    for (size_t q = 0; q < 2 * 25; ++q) X[q] += tap_urand(-0.3, 0.3);
    const double p[3] = {1.3, 0.1, 0.7};
    double e_dense = NAN, e_sparse = NAN;
    int rc1 = whirl_system_check_jacobian(s, X, p, &e_dense);
    whirl_system sp = *s;
    sp.Fx = NULL;
    int rc2 = whirl_system_check_jacobian(&sp, X, p, &e_sparse);
    printf("# Duffing (%s): Jacobian error dense %.2e sparse %.2e\n",
           mode == 0 ? "forced" : "T unknown", e_dense, e_sparse);
    ok(rc1 == 0 && e_dense < 1e-6,
       "Duffing (%s): dense Jacobian and F_p (all 3 parameters) vs "
       "differences %.2e < 1e-6",
       mode == 0 ? "forced" : "T unknown", e_dense);
    ok(rc2 == 0 && e_sparse < 1e-6,
       "Duffing (%s): sparse Jacobian vs differences %.2e < 1e-6",
       mode == 0 ? "forced" : "T unknown", e_sparse);
    if (mode == 0) {
      ok(s->nspec == 2 && s->accept == NULL,
         "forced: nspec n = 2, no phase reference");
      is_rel(whirl_colloc_period(c, X, p), 2.0 * PI / 1.3, 1e-15,
             "forced period 2π/ω");
    }
    free(X);
    whirl_colloc_free(c);
  }
}

/* ------------------------------------------------------------------------
 * 1b. The structured bordered solver (condensation of parameters) against
 * UMFPACK: test/unit/bsolver_check.h. */

static void bsolver_vs_umfpack(const char *name, whirl_colloc *c,
                               const double *X, const double *p, size_t k) {
  bsolver_check(name, whirl_colloc_system(c), X, p, k, 1);
}

/* ------------------------------------------------------------------------
 * 1c. A fixed period (free_param): X's last unknown is the parameter rho
 * in T's place.  The Jacobian (its last column dF/drho from jac_p, or a
 * difference in rho without it) and F_p against differences of F, the
 * structured solver against UMFPACK, and the parameters and period the
 * object reports. */
static void test_fixed_period(void) {
  char err[256];
  const whirl_problem *lp[2] = {&lorenz, &lorenz_fd};
  for (int v = 0; v < 2; ++v) {
    whirl_colloc_options o;
    whirl_colloc_options_default(&o);
    o.ntst = 10;
    o.ncol = 4;
    o.free_param = 1;
    o.period = 0.7;
    whirl_colloc *c = whirl_colloc_alloc(lp[v], &o, err, sizeof err);
    ok(c != NULL, "fixed period: alloc Lorenz (%s): %s", lp[v]->name, err);
    if (!c) continue;
    const whirl_system *s = whirl_colloc_system(c);
    const size_t nx = whirl_colloc_size(c);
    double *X = malloc(nx * sizeof *X);
    lorenz_curve(c, nx, X);
    X[nx - 1] = 250.0; /* rho */
    const double p[3] = {10.0, -77.0, 8.0 / 3.0}; /* p[1] is X's */
    double pf[3];
    whirl_colloc_params(c, X, p, pf);
    ok(whirl_colloc_free_param(c) == 1 && pf[1] == 250.0 && pf[0] == 10.0 &&
           whirl_colloc_period(c, X, p) == 0.7,
       "fixed period: rho from X (%g), T = 0.7 (%g)", pf[1],
       whirl_colloc_period(c, X, p));
    double e_dense = NAN, e_sparse = NAN;
    int rc1 = whirl_system_check_jacobian(s, X, p, &e_dense);
    whirl_system sp = *s;
    sp.Fx = NULL;
    int rc2 = whirl_system_check_jacobian(&sp, X, p, &e_sparse);
    ok(rc1 == 0 && e_dense < 1e-6,
       "fixed period, Lorenz (%s): dense Jacobian (the rho column) and F_p vs "
       "differences %.2e < 1e-6", lp[v]->name, e_dense);
    ok(rc2 == 0 && e_sparse < 1e-6,
       "fixed period, Lorenz (%s): sparse Jacobian vs differences %.2e < 1e-6",
       lp[v]->name, e_sparse);
    bsolver_vs_umfpack(v == 0 ? "fixed period, Lorenz" : "fixed period, Lorenz (F_p by differences)", c, X, p, 0);
    free(X);
    whirl_colloc_free(c);
  }
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.free_param = 1;
  o.period = 0.0;
  ok(whirl_colloc_alloc(&lorenz, &o, err, sizeof err) == NULL &&
         strstr(err, "fixed period"),
     "fixed period 0 refused: %s", err);
}

/* Sizes are checked before anything is counted or allocated: NTST =
 * 99999999999 busy-looped over the mesh nodes counting nonzeros before the
 * int-index check; a large model at the largest NTST must be refused by
 * its size too, without overflowing size_t on the way. */
static void test_size_limits(void) {
  char err[256];
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = 99999999999u;
  const clock_t t0 = clock();
  whirl_colloc *c = whirl_colloc_alloc(&lorenz, &o, err, sizeof err);
  const double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
  ok(!c && strstr(err, "NTST") && secs < 0.5, "NTST = 99999999999 refused at once (%.3f s CPU): %s",
     secs, err);
  whirl_colloc_free(c);
  o.ntst = WHIRL_COLLOC_MAX_NTST;
  o.ncol = 7;
  whirl_problem big = lorenz;
  big.n = (size_t)1 << 40;
  c = whirl_colloc_alloc(&big, &o, err, sizeof err);
  ok(!c && strstr(err, "too large"), "n = 2^40 at NTST %d refused: %s", WHIRL_COLLOC_MAX_NTST, err);
  whirl_colloc_free(c);
}

/* The fold system of orbits (whirl_fold on the collocation system, its
 * sparse path): its [F_x b; c^T 0] factored by the condensed solver with b
 * as the given column and its left null vector by the transposed solve,
 * its Newton matrix by block elimination with those factors (its own
 * bsolver).  Checked: the system's Jacobian and dF/dp against differences
 * of its F (g_x = -w^T (F_x)_x v needs the right w), and its structured
 * solves and determinant against UMFPACK on the assembled matrix. */
static void fold_of_orbits_check(whirl_colloc *c, const double *X, const double *p) {
  char err[256];
  const size_t nx = whirl_colloc_size(c);
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 1); /* rho freed, sigma the core's */
  whirl_fold *f = whirl_fold_alloc(whirl_colloc_system(c), &fo, err, sizeof err);
  double *Z = malloc((nx + 1) * sizeof *Z), jerr = 1.0, pf[3] = {p[0], p[1], p[2]};
  int rc = f && Z ? whirl_fold_init(f, X, pf, Z) : WHIRL_ENOMEM;
  const whirl_system *s = f ? whirl_fold_system(f) : NULL;
  if (rc == WHIRL_OK) rc = whirl_system_check_jacobian(s, Z, pf, &jerr);
  ok(rc == WHIRL_OK && jerr < 1e-5, "fold of orbits (Lorenz NTST 12): Jacobian and dF/dp "
     "against differences of its F (%.1e; %s)", jerr, f ? whirl_fold_errmsg(f) : err);
  if (rc == WHIRL_OK) bsolver_check("fold of orbits (Lorenz NTST 12), k = sigma", s, Z, pf, 0, 0);
  free(Z);
  whirl_fold_free(f);
}

static void test_structured(void) {
  char err[256];
  whirl_colloc_options o;
  /* Lorenz, T unknown, phase condition: a closed curve, not a solution */
  whirl_colloc_options_default(&o);
  o.ntst = 12;
  o.ncol = 4;
  whirl_colloc *c = whirl_colloc_alloc(&lorenz, &o, err, sizeof err);
  if (c) {
    const size_t nx = whirl_colloc_size(c);
    double *X = malloc(nx * sizeof *X);
    lorenz_curve(c, nx, X);
    const double p[3] = {10.0, 250.0, 8.0 / 3.0};
    bsolver_vs_umfpack("Lorenz NTST 12 NCOL 4, k = rho", c, X, p, 1);
    fold_of_orbits_check(c, X, p);
    free(X);
  }
  whirl_colloc_free(c);
  /* forced Duffing: no phase row, the forcing frequency as parameter (its
   * column by differences of the whole residual) and another one */
  whirl_colloc_options_default(&o);
  o.ntst = 7;
  o.ncol = 3;
  o.t0 = 0.4;
  o.forcing_param = 0;
  c = whirl_colloc_alloc(&duffing, &o, err, sizeof err);
  if (c) {
    const size_t nx = whirl_colloc_size(c);
    double smp[2 * 16], *X = malloc(nx * sizeof *X);
    for (size_t k = 0; k < 16; ++k) {
      smp[2 * k] = cos(2.0 * PI * (double)k / 16.0);
      smp[2 * k + 1] = -sin(2.0 * PI * (double)k / 16.0);
    }
    whirl_colloc_from_samples(c, smp, 16, 2.0 * PI / 1.3, X);
    for (size_t q = 0; q < nx; ++q) X[q] += tap_urand(-0.3, 0.3);
    const double p[3] = {1.3, 0.1, 0.7};
    bsolver_vs_umfpack("forced Duffing NTST 7 NCOL 3, k = omega", c, X, p, 0);
    bsolver_vs_umfpack("forced Duffing NTST 7 NCOL 3, k = 1", c, X, p, 1);
    free(X);
  }
  whirl_colloc_free(c);
  /* the SFD rotating frame (nonsynchronous cycle), NTST 20 NCOL 6 */
  whirl_colloc_options_default(&o);
  o.ntst = 20;
  o.ncol = 6;
  c = whirl_colloc_alloc(whirl_sfd_rotating(), &o, err, sizeof err);
  if (c) {
    const size_t nx = whirl_colloc_size(c);
    double smp[4 * 64], *X = malloc(nx * sizeof *X), p[WHIRL_SFD_NPAR];
    whirl_sfd_default_params(p);
    p[WHIRL_SFD_OMEGA] = 8.7;
    for (size_t k = 0; k < 64; ++k) {
      const double th = 2.0 * PI * (double)k / 64.0;
      smp[4 * k] = 0.5 * cos(th) + 0.2 * cos(2.0 * th);
      smp[4 * k + 1] = 0.5 * sin(th);
      smp[4 * k + 2] = -0.5 * sin(th);
      smp[4 * k + 3] = 0.5 * cos(th) + 0.1;
    }
    whirl_colloc_from_samples(c, smp, 64, 1.03, X);
    bsolver_vs_umfpack("SFD rotating frame NTST 20 NCOL 6, k = Omega", c, X, p,
                       WHIRL_SFD_OMEGA);
    free(X);
  }
  whirl_colloc_free(c);
}

/* ------------------------------------------------------------------------
 * 2. λ-ω cycle from a wrong circle */

static void test_lambda_omega(void) {
  const double a = 0.25, r = sqrt(a);
  const size_t ntst = 20, ncol = 4, m = 64;
  char err[256];
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = ntst;
  o.ncol = ncol;
  whirl_colloc *c = whirl_colloc_alloc(&lamom, &o, err, sizeof err);
  ok(c != NULL, "alloc λ-ω: %s", err);
  if (!c) return;
  const whirl_system *s = whirl_colloc_system(c);
  const size_t nx = whirl_colloc_size(c);
  double smp[2 * 64], *X = malloc(nx * sizeof *X);
  circle_samples(1.1 * r, m, smp);
  ok(whirl_colloc_from_samples(c, smp, m, 6.0, X) == WHIRL_OK &&
         X[nx - 1] == 6.0,
     "from_samples stores T = 6");
  /* the interpolated circle: 4-point cubic interpolation of 64 samples is
   * accurate to ~ (2π/64)^4 / 24 ~ 4e-6 relative */
  ok(radius_err_nodes(X, ntst * ncol + 1, 1.1 * r) < 1e-5 * r,
     "interpolated samples lie on the radius-1.1 r circle (%.1e)",
     radius_err_nodes(X, ntst * ncol + 1, 1.1 * r));
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 0;
  co.linsol = WHIRL_LINSOL_SPARSE;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  const double p[1] = {a};
  int rc = ct ? correct(ct, X, p) : -1;
  ok(rc == WHIRL_OK, "Newton from the wrong circle converges: %s",
     ct ? whirl_cont_errmsg(ct) : err);
  if (rc == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    memcpy(X, pt->x, nx * sizeof *X);
    const double er = radius_err_mesh(X, ntst, ncol, r);
    const double en = radius_err_nodes(X, ntst * ncol + 1, r);
    printf("# λ-ω a = %g: radius error %.2e at mesh points, %.2e at all "
           "nodes; period error %.2e\n",
           a, er, en, X[nx - 1] - 2.0 * PI);
    ok(er < 1e-9, "radius sqrt(a) at the mesh points to 1e-9 (%.2e)", er);
    ok(en < 1e-7, "radius sqrt(a) at all nodes to 1e-7 (%.2e)", en);
    is_rel(X[nx - 1], 2.0 * PI, 1e-9, "period 2π");
    is_rel(whirl_colloc_period(c, X, p), 2.0 * PI, 1e-9, "whirl_colloc_period");
    /* the nontrivial multiplier from the variational equations */
    const double mu = exp(-2.0 * a * 2.0 * PI);
    ok(pt->nspec == 1, "one nontrivial multiplier (nspec %zu)", pt->nspec);
    printf("# multiplier %.15g, closed form %.15g, rel err %.2e\n",
           pt->spec_re[0], mu, fabs(pt->spec_re[0] / mu - 1.0));
    is_rel(pt->spec_re[0], mu, 1e-8, "multiplier exp(-4πa) = %.6g", mu);
    is_abs(pt->spec_im[0], 0.0, 1e-12, "multiplier is real");
    /* evaluation between nodes: a point of the circle, and periodic wrap */
    double xe[2], xw[2];
    whirl_colloc_eval(c, X, 0.337, xe);
    whirl_colloc_eval(c, X, 1.337, xw);
    is_abs(hypot(xe[0], xe[1]), r, 1e-7, "eval at τ = 0.337 lies on the cycle");
    ok(fabs(xe[0] - xw[0]) < 1e-14 && fabs(xe[1] - xw[1]) < 1e-14,
       "eval wraps τ periodically");
    /* the one periodic-orbit interface: on the circle of radius r the
     * maximum of each component is r, the L2-NORM r, the period 2π */
    const whirl_periodic po = whirl_periodic_of_colloc(c);
    double pmx[2];
    const int rcm = whirl_periodic_max(&po, X, pmx);
    ok(rcm == WHIRL_OK && !strcmp(whirl_periodic_method(&po), "colloc") &&
           fabs(pmx[0] - r) < 1e-7 && fabs(pmx[1] - r) < 1e-7 &&
           fabs(whirl_periodic_l2norm(&po, X) - r) < 1e-7 &&
           fabs(whirl_periodic_period(&po, X, p) - 2.0 * PI) < 1e-9,
       "periodic interface over collocation: MAX %.10f, %.10f, L2 %.10f (r = %.10f)",
       pmx[0], pmx[1], whirl_periodic_l2norm(&po, X), r);
    /* the phase: x(τ) = r (cos 2π(τ + φ), sin ...) with φ from the phase
     * condition against the reference circle starting at (1.1 r, 0): φ = 0 */
    is_abs(atan2(X[1], X[0]), 0.0, 1e-9,
           "phase condition fixes the phase of the reference (x(0) on the +x "
           "axis)");
  }
  whirl_cont_free(ct);
  free(X);
  whirl_colloc_free(c);
}

/* ------------------------------------------------------------------------
 * 3. forced linear oscillator */

/* The λ-ω system on ntst x ncol, adapted every adapt_every steps, with
 * AUTO's phase condition when phase_nodes. */
static whirl_colloc *lw_alloc(size_t ntst, size_t ncol, int adapt_every,
                              int phase_nodes, char *err, size_t errlen) {
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = ntst;
  o.ncol = ncol;
  o.adapt_every = adapt_every;
  o.phase_nodes = phase_nodes;
  return whirl_colloc_alloc(&lamom, &o, err, errlen);
}

/* AUTO's phase condition (phase_nodes): ∫ <x − x_ref, T f(x_ref)> at the
 * nodes.  On the λ-ω cycle (r² = a, T = 2π, f = (−y, x) there) with the
 * reference at phase 0 and x the same circle at phase φ, the integrand at
 * every node is 2π a sin φ exactly (sin(θ + φ) cos θ − cos(θ + φ) sin θ),
 * so any rule whose weights sum to 1 gives 2π a sin φ to rounding; whirl's
 * Gauss rule with the reference polynomial's derivative is off by its
 * interpolation error (the row is ∫ <x, x_ref'>, the same value for the
 * exact circle). */
static void test_phase_nodes(void) {
  const double a = 0.25, r = sqrt(a), phi = 0.3, T = 2.0 * WHIRL_PI;
  const size_t ntst = 8, ncol = 4;
  char err[256];
  double dev[2] = {0.0, 0.0};
  for (int nodes = 0; nodes <= 1; ++nodes) {
    whirl_colloc *c = lw_alloc(ntst, ncol, 0, nodes, err, sizeof err);
    ok(c != NULL, "alloc λ-ω (phase_nodes %d): %s", nodes, err);
    if (!c) return;
    const whirl_system *s = whirl_colloc_system(c);
    const size_t nx = whirl_colloc_size(c), nn = ntst * ncol + 1;
    double *X = malloc(nx * sizeof *X), *R = malloc(nx * sizeof *R),
           *F = malloc(nx * sizeof *F);
    const double p[1] = {a};
    for (size_t j = 0; j < nn; ++j) { /* the initial mesh is uniform */
      const double th = 2.0 * WHIRL_PI * (double)j / (double)(nn - 1);
      R[2 * j] = r * cos(th);
      R[2 * j + 1] = r * sin(th);
      X[2 * j] = r * cos(th + phi);
      X[2 * j + 1] = r * sin(th + phi);
    }
    R[nx - 1] = X[nx - 1] = T;
    int rc = s->accept(R, p, s->data);
    if (rc == 0) rc = s->F(X, p, F, s->data);
    dev[nodes] = rc == 0 ? fabs(F[nx - 1] - T * a * sin(phi)) : INFINITY;
    free(X);
    free(R);
    free(F);
    whirl_colloc_free(c);
  }
  ok(dev[1] < 1e-13, "AUTO's phase condition at the nodes on the λ-ω cycle "
     "shifted by 0.3: 2π a sin 0.3 to %.1e", dev[1]);
  ok(dev[0] > 1e3 * dev[1] && dev[0] < 1e-3,
     "whirl's Gauss rule: the same integral to its interpolation error %.1e", dev[0]);
}

static void test_forced(void) {
  const double w = 1.3, z = 0.1;
  const size_t ntst = 20, ncol = 4;
  char err[256];
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = ntst;
  o.ncol = ncol;
  o.forcing_param = 0;
  whirl_colloc *c = whirl_colloc_alloc(&duffing, &o, err, sizeof err);
  ok(c != NULL, "alloc forced oscillator: %s", err);
  if (!c) return;
  const whirl_system *s = whirl_colloc_system(c);
  const size_t nx = whirl_colloc_size(c);
  double smp[2 * 8] = {0}, *X = malloc(nx * sizeof *X);
  whirl_colloc_from_samples(c, smp, 8, 2.0 * PI / w, X); /* x = 0 */
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 1; /* ζ; the forcing frequency stays fixed */
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  const double p[3] = {w, z, 0.0};
  int rc = ct ? correct(ct, X, p) : -1;
  ok(rc == WHIRL_OK, "forced oscillator: Newton converges: %s",
     ct ? whirl_cont_errmsg(ct) : err);
  if (rc == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    memcpy(X, pt->x, nx * sizeof *X);
    /* steady state x = A cos(ωt - φ), A = 1/sqrt((1-ω²)² + (2ζω)²) */
    const double A = 1.0 / sqrt((1 - w * w) * (1 - w * w) + 4 * z * z * w * w);
    const double phi = atan2(2.0 * z * w, 1.0 - w * w);
    const double Tp = 2.0 * PI / w;
    const double amp = hypot(X[0], X[1] / w); /* at t = 0 */
    double emax = 0.0;
    const double *mesh = whirl_colloc_mesh(c);
    for (size_t i = 0; i <= ntst; ++i) {
      const double t = Tp * mesh[i];
      const double *x = X + 2 * i * ncol;
      emax = fmax(emax, fabs(x[0] - A * cos(w * t - phi)));
      emax = fmax(emax, fabs(x[1] + A * w * sin(w * t - phi)));
    }
    printf("# forced: amplitude %.15g closed form %.15g; max error at mesh "
           "points %.2e\n",
           amp, A, emax);
    is_rel(amp, A, 1e-9, "amplitude 1/sqrt((1-ω²)² + (2ζω)²) = %.6f", A);
    ok(emax < 1e-9, "x(t) = A cos(ωt - φ) at the mesh points (%.2e)", emax);
    /* multipliers exp((-ζ ± i sqrt(1-ζ²)) T) */
    const double mr = exp(-z * Tp) * cos(sqrt(1 - z * z) * Tp);
    const double mi = exp(-z * Tp) * sin(sqrt(1 - z * z) * Tp);
    ok(pt->nspec == 2, "two multipliers (nspec %zu)", pt->nspec);
    double d0 = pair_dist(pt->spec_re[0], pt->spec_im[0], mr, mi);
    double d1 = pair_dist(pt->spec_re[1], pt->spec_im[1], mr, mi);
    printf("# forced multipliers %.12g%+.12gi, %.12g%+.12gi; closed form "
           "%.12g±%.12gi; errors %.1e %.1e\n",
           pt->spec_re[0], pt->spec_im[0], pt->spec_re[1], pt->spec_im[1], mr,
           fabs(mi), d0, d1);
    ok(d0 < 1e-8 && d1 < 1e-8 && pt->spec_im[0] * pt->spec_im[1] < 0,
       "multipliers exp((-ζ ± i sqrt(1-ζ²)) 2π/ω) to 1e-8 (%.1e, %.1e)", d0,
       d1);
  }
  whirl_cont_free(ct);
  free(X);
  whirl_colloc_free(c);
}

/* the subharmonic setting nu = 2 at t0 = 0.9 finds the same (unique)
 * response over two forcing periods, with the same multipliers squared */
static void test_forced_nu2(void) {
  const double w = 1.3, z = 0.1;
  char err[256];
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.forcing_param = 0;
  o.nu = 2;
  o.ntst = 40; /* two forcing periods at the resolution of test 3 */
  o.t0 = 0.9;
  whirl_colloc *c = whirl_colloc_alloc(&duffing, &o, err, sizeof err);
  ok(c != NULL, "alloc nu = 2: %s", err);
  if (!c) return;
  const whirl_system *s = whirl_colloc_system(c);
  double smp[2 * 8] = {0}, *X = malloc(whirl_colloc_size(c) * sizeof *X);
  whirl_colloc_from_samples(c, smp, 8, 4.0 * PI / w, X);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 1;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  const double p[3] = {w, z, 0.0};
  int rc = correct(ct, X, p);
  if (rc == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    const double A = 1.0 / sqrt((1 - w * w) * (1 - w * w) + 4 * z * z * w * w);
    const double phi = atan2(2.0 * z * w, 1.0 - w * w);
    double xe[2];
    whirl_colloc_eval(c, pt->x, 0.0, xe);
    is_abs(xe[0], A * cos(w * 0.9 - phi), 1e-9,
           "nu = 2, t0 = 0.9: x(t0) = A cos(ω t0 - φ)");
    is_rel(whirl_colloc_period(c, pt->x, pt->p), 4.0 * PI / w, 1e-15,
           "nu = 2: period 4π/ω");
    is_rel(hypot(pt->spec_re[0], pt->spec_im[0]), exp(-z * 4.0 * PI / w), 1e-8,
           "nu = 2: |multiplier| = exp(-2ζ 2π/ω)");
  } else {
    ok(0, "nu = 2: Newton failed: %s", whirl_cont_errmsg(ct));
  }
  whirl_cont_free(ct);
  free(X);
  whirl_colloc_free(c);
}

/* ------------------------------------------------------------------------
 * 4. continuation of the λ-ω cycle in a */

typedef struct lw_run {
  size_t npts;
  double *p;   /* a of each point */
  double *X;   /* nx per point */
  double rmax; /* max radius error at mesh points over the branch */
  double Tmax; /* max |T - 2π| */
  int stop;
} lw_run;

static int run_lw(whirl_linsol_kind kind, int structured, int chord,
                  double a_min, lw_run *out) {
  const size_t ntst = 20, ncol = 4, m = 64;
  char err[256];
  memset(out, 0, sizeof *out);
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = ntst;
  o.ncol = ncol;
  whirl_colloc *c = whirl_colloc_alloc(&lamom, &o, err, sizeof err);
  if (!c) return -1;
  const whirl_system *s = whirl_colloc_system(c);
  const size_t nx = whirl_colloc_size(c);
  double smp[2 * 64], *X = malloc(nx * sizeof *X);
  circle_samples(1.1, m, smp);
  whirl_colloc_from_samples(c, smp, m, 6.0, X);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 0;
  co.ds = 0.05;
  co.ds_max = 0.1;
  co.p_min = a_min;
  co.p_max = 2.0;
  co.nmx = 200;
  co.linsol = kind;
  co.structured = structured;
  co.newton_chord = chord;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  const double p0[1] = {1.0};
  int rc = ct ? whirl_cont_start(ct, X, p0, -1) : -1;
  size_t cap = 256;
  out->p = malloc(cap * sizeof *out->p);
  out->X = malloc(cap * nx * sizeof *out->X);
  while (rc == WHIRL_OK && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    /* the core does not call the accept hook yet: update the phase
     * reference to the accepted point here */
    s->accept(pt->x, pt->p, s->data);
    if (out->npts < cap) {
      out->p[out->npts] = pt->p[0];
      memcpy(out->X + nx * out->npts, pt->x, nx * sizeof *X);
      ++out->npts;
    }
    out->rmax =
        fmax(out->rmax, radius_err_mesh(pt->x, ntst, ncol, sqrt(pt->p[0])));
    out->Tmax = fmax(out->Tmax, fabs(pt->x[nx - 1] - 2.0 * PI));
  }
  out->stop = ct ? whirl_cont_stop_reason(ct) : -1;
  if (rc != WHIRL_DONE)
    printf("# continuation: %s\n", ct ? whirl_cont_errmsg(ct) : err);
  whirl_cont_free(ct);
  free(X);
  whirl_colloc_free(c);
  return rc;
}

/* tangent_from_newton along the λ-ω branch a: 1 -> 0.3 (EPSL 1e-7): the
 * multiplier of every regular point, taken from the corrector's last
 * factorisation (the condensed blocks at its last iterate, as AUTO), is
 * the closed form exp(-4πa): to 1e-5 relative, since the iterate's a is up
 * to EPSL (1 + |X|) off and d log mu / da = -4π (2.4e-6 measured; a
 * stale or foreign factorisation is off by orders more), and the branch
 * needs a Jacobian fewer a step than with a fresh analysis at every
 * point. */
static void test_lw_from_newton(void) {
  size_t jac[2] = {0, 0}, steps[2] = {0, 0}, pts = 0;
  double worst = 0.0;
  for (int reuse = 0; reuse < 2; ++reuse) {
    char err[256];
    whirl_colloc_options o;
    whirl_colloc_options_default(&o);
    o.ntst = 20;
    o.ncol = 4;
    whirl_colloc *c = whirl_colloc_alloc(&lamom, &o, err, sizeof err);
    if (!c) continue;
    const whirl_system *s = whirl_colloc_system(c);
    const size_t nx = whirl_colloc_size(c);
    double smp[2 * 64], *X = malloc(nx * sizeof *X);
    circle_samples(1.0, 64, smp);
    whirl_colloc_from_samples(c, smp, 64, 2.0 * PI, X);
    whirl_cont_options co;
    whirl_cont_options_default(&co);
    co.ds = 0.05;
    co.ds_max = 0.1;
    co.p_min = 0.3;
    co.p_max = 2.0;
    co.newton_tol = 1e-7;
    co.tangent_from_newton = reuse;
    whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
    const double p0[1] = {1.0};
    int rc = ct ? whirl_cont_start(ct, X, p0, -1) : -1;
    while (rc == WHIRL_OK && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
      const whirl_point *pt = whirl_cont_point(ct);
      s->accept(pt->x, pt->p, s->data);
      if (!reuse || pt->type != WHIRL_PT_REGULAR || pt->nspec != 1) continue;
      const double mu = exp(-4.0 * PI * pt->p[0]);
      worst = fmax(worst, fabs(pt->spec_re[0] / mu - 1.0));
      ++pts;
    }
    if (ct) {
      jac[reuse] = whirl_cont_get_stats(ct)->jac_evals;
      steps[reuse] = whirl_cont_get_stats(ct)->steps;
    }
    whirl_cont_free(ct);
    free(X);
    whirl_colloc_free(c);
  }
  ok(pts > 5 && worst < 1e-5,
     "λ-ω, tangent from Newton: %zu multipliers = exp(-4πa) to %.1e", pts, worst);
  ok(steps[1] > 5 && jac[1] + steps[1] / 2 < jac[0],
     "λ-ω, tangent from Newton: %zu Jacobians against %zu (%zu, %zu steps)",
     jac[1], jac[0], steps[1], steps[0]);
}

/* Mesh adaptation along a branch (adapt_every, the system's remap hook):
 * the λ-ω branch a: 1 -> 0.3 from a badly clustered mesh (τ_k = (k/N)^3,
 * intervals from 1e-4 to 0.14), once with that mesh fixed and once adapted
 * every step.  The adapted run must carry the continuation across every new
 * mesh (the core's point, tangent and previous points remapped) to the end,
 * with the mesh spread out and the orbit closer to the exact circle of
 * radius sqrt(a) and period 2π than on the fixed clustered mesh. */
static int run_lw_mesh(int adapt_every, int clustered, double *rmax,
                       double *Tmax, double *hmin, size_t *nad) {
  const size_t ntst = 8, ncol = 3, m = 64;
  char err[256];
  whirl_colloc *c = lw_alloc(ntst, ncol, adapt_every, 0, err, sizeof err);
  if (!c) return -1;
  double tau[9];
  for (size_t k = 0; k <= ntst; ++k)
    tau[k] = pow((double)k / (double)ntst, clustered ? 3.0 : 1.0);
  whirl_colloc_set_mesh(c, tau);
  const whirl_system *s = whirl_colloc_system(c);
  const size_t nx = whirl_colloc_size(c);
  double smp[2 * 64], *X = malloc(nx * sizeof *X);
  circle_samples(1.0, m, smp);
  whirl_colloc_from_samples(c, smp, m, 2.0 * PI, X);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.ds = 0.02;
  co.ds_max = 0.05;
  co.p_min = 0.3;
  co.p_max = 2.0;
  co.nmx = 200;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  const double p0[1] = {1.0};
  int rc = ct ? whirl_cont_start(ct, X, p0, -1) : -1;
  *rmax = *Tmax = 0.0;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    if (pt->index < 10) continue; /* judge the orbits once the mesh moved */
    *rmax = fmax(*rmax, radius_err_nodes(pt->x, ntst * ncol + 1, sqrt(pt->p[0])));
    *Tmax = fmax(*Tmax, fabs(pt->x[nx - 1] - 2.0 * PI));
  }
  if (rc == WHIRL_DONE && whirl_cont_stop_reason(ct) != WHIRL_STOP_PMIN) rc = -1;
  const double *mesh = whirl_colloc_mesh(c);
  *hmin = 1.0;
  for (size_t k = 0; k < ntst; ++k) *hmin = fmin(*hmin, mesh[k + 1] - mesh[k]);
  *nad = whirl_colloc_adaptations(c);
  if (rc != WHIRL_DONE) printf("# continuation: %s\n", ct ? whirl_cont_errmsg(ct) : err);
  whirl_cont_free(ct);
  free(X);
  whirl_colloc_free(c);
  return rc;
}

static void test_adapt_along_branch(void) {
  double r0, T0, h0, r1, T1, h1, ru, Tu, hu;
  size_t n0, n1, nu;
  int rc0 = run_lw_mesh(0, 1, &r0, &T0, &h0, &n0);
  int rc1 = run_lw_mesh(1, 1, &r1, &T1, &h1, &n1);
  int rcu = run_lw_mesh(0, 0, &ru, &Tu, &hu, &nu);
  printf("# λ-ω on a clustered mesh: fixed: radius error %.2e, period error "
         "%.2e, smallest interval %.1e; adapted every step (%zu meshes): "
         "%.2e, %.2e, %.1e; uniform fixed mesh: %.2e, %.2e\n", r0, T0, h0,
         n1, r1, T1, h1, ru, Tu);
  ok(rc0 == WHIRL_DONE && rc1 == WHIRL_DONE,
     "both runs reach a = 0.3 (the adapted one across every new mesh)");
  ok(n0 == 0 && n1 > 10, "adapt_every = 1 adapts at every step (%zu), 0 never (%zu)", n1, n0);
  ok(h1 > 10.0 * h0, "the adapted mesh spreads out (smallest interval %.1e from %.1e)", h1, h0);
  ok(r1 < 0.5 * r0, "adapted orbits are closer to the circle (%.2e < %.2e / 2)", r1, r0);
  /* for the circle the equidistributed mesh is nearly uniform: the adapted
   * run recovers the accuracy of the uniform mesh */
  ok(rcu == WHIRL_DONE && r1 < 2.0 * ru && T1 < 2.0 * Tu + 1e-12,
     "adapted run as accurate as on a uniform mesh (radius %.2e vs %.2e, "
     "period %.2e vs %.2e)", r1, ru, T1, Tu);
}

static double lw_diff(const lw_run *a, const lw_run *b) {
  if (a->npts != b->npts || a->npts == 0) return INFINITY;
  const size_t nx = 2 * (20 * 4 + 1) + 1;
  double diff = 0.0;
  for (size_t k = 0; k < a->npts; ++k) {
    diff = fmax(diff, fabs(a->p[k] - b->p[k]));
    for (size_t q = 0; q < nx; ++q)
      diff = fmax(diff, fabs(a->X[nx * k + q] - b->X[nx * k + q]));
  }
  return diff;
}

static void test_continuation(int quick) {
  const double a_min = quick ? 0.6 : 0.05;
  /* the general LUs (dense, UMFPACK), the structured solver of the system
   * (the default), and the structured solver with chord Newton */
  lw_run d, sp, st, ch;
  int rcd = run_lw(WHIRL_LINSOL_DENSE, 0, 0, a_min, &d);
  int rcs = run_lw(WHIRL_LINSOL_SPARSE, 0, 0, a_min, &sp);
  int rct = run_lw(WHIRL_LINSOL_SPARSE, 1, 0, a_min, &st);
  int rcc = run_lw(WHIRL_LINSOL_SPARSE, 1, 1, a_min, &ch);
  printf("# λ-ω branch a: 1 -> %g: %zu points (dense), %zu (sparse), %zu "
         "(structured), %zu (chord); max radius error %.2e, max period error "
         "%.2e\n",
         a_min, d.npts, sp.npts, st.npts, ch.npts, fmax(d.rmax, sp.rmax),
         fmax(d.Tmax, sp.Tmax));
  ok(rcd == WHIRL_DONE && d.stop == WHIRL_STOP_PMIN && d.npts > 3,
     "dense: branch ends at a = %g (%zu points)", a_min, d.npts);
  ok(rcs == WHIRL_DONE && sp.stop == WHIRL_STOP_PMIN && sp.npts > 3,
     "sparse: branch ends at a = %g (%zu points)", a_min, sp.npts);
  ok(rct == WHIRL_DONE && st.stop == WHIRL_STOP_PMIN && st.npts > 3,
     "structured: branch ends at a = %g (%zu points)", a_min, st.npts);
  ok(rcc == WHIRL_DONE && ch.stop == WHIRL_STOP_PMIN && ch.npts > 3,
     "structured, chord Newton: branch ends at a = %g (%zu points)", a_min,
     ch.npts);
  if (d.npts)
    is_abs(d.p[d.npts - 1], a_min, 1e-10, "last point at a = %g", a_min);
  ok(d.rmax < 1e-8 && sp.rmax < 1e-8 && st.rmax < 1e-8 && ch.rmax < 1e-8,
     "radius sqrt(a) on every point to 1e-8 (%.2e, %.2e, %.2e, %.2e)", d.rmax,
     sp.rmax, st.rmax, ch.rmax);
  ok(d.Tmax < 1e-8 && sp.Tmax < 1e-8 && st.Tmax < 1e-8 && ch.Tmax < 1e-8,
     "period 2π on every point (%.2e, %.2e, %.2e, %.2e)", d.Tmax, sp.Tmax,
     st.Tmax, ch.Tmax);
  const double diff = lw_diff(&d, &sp), dst = lw_diff(&d, &st);
  ok(diff < 1e-9,
     "dense and sparse solvers give the same branch (max "
     "difference %.1e)",
     diff);
  ok(dst < 1e-9,
     "dense and structured solvers give the same branch (max difference "
     "%.1e)",
     dst);
  free(d.p), free(d.X), free(sp.p), free(sp.X), free(st.p), free(st.X);
  free(ch.p), free(ch.X);
}

/* ------------------------------------------------------------------------
 * 5. Lorenz at ρ = 250 */

static double z_event(double t, const double *x, void *data) {
  (void)t;
  return x[2] - *(const double *)data;
}

typedef struct sample_buf {
  double *x;
  size_t n;
} sample_buf;

static int store_sample(size_t k, double t, const double *x, void *data) {
  (void)t;
  sample_buf *b = data;
  memcpy(b->x + b->n * k, x, b->n * sizeof *x);
  return 0;
}

/* The condensed multipliers of a collocation solution X (re, im from the
 * core's point, m of them) against the variational equations: a second
 * object with WHIRL_COLLOC_FLOQUET_VARIATIONAL on the same (uniform) mesh,
 * to 1e-8. */
static void floquet_routes(const char *name, const whirl_problem *prob,
                           const whirl_colloc_options *o, const double *X,
                           const double *p, const double *re,
                           const double *im, size_t m) {
  whirl_colloc_options ov = *o;
  ov.floquet = WHIRL_COLLOC_FLOQUET_VARIATIONAL;
  ov.floquet_rtol = 1e-12;
  char err[256];
  whirl_colloc *cv = whirl_colloc_alloc(prob, &ov, err, sizeof err);
  const whirl_system *sv = whirl_colloc_system(cv);
  double vre[8], vim[8];
  size_t mv = 8;
  int rc = cv ? sv->spectrum(X, p, NULL, vre, vim, &mv, sv->data) : -1;
  double d = rc == 0 && mv == m ? 0.0 : INFINITY;
  for (size_t k = 0; k < m && k < mv; ++k) {
    printf("# %s: multiplier %zu condensed %.12f%+.12fi, variational "
           "%.12f%+.12fi\n",
           name, k, re[k], im[k], vre[k], vim[k]);
    /* conjugate pairs may come in either order */
    d = fmax(d, fmin(hypot(re[k] - vre[k], im[k] - vim[k]),
                     hypot(re[k] - vre[k], im[k] + vim[k])));
  }
  ok(d < 1e-8,
     "%s: condensed and variational multipliers agree to %.1e (< 1e-8)", name,
     d);
  whirl_colloc_free(cv);
}

/* The nonsynchronous cycle of the SFD rotor (rotating frame, Table 1) at
 * Omega = 8.7 from a time integration from rest, corrected by collocation
 * (NTST 40, NCOL 6, mesh adapted): condensed against variational
 * multipliers. */
static double du_event(double t, const double *x, void *data) {
  (void)t, (void)data;
  return x[2];
}

static void test_sfd_floquet(void) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = 8.7;
  const whirl_problem *rot = whirl_sfd_rotating();
  whirl_ode *ode = whirl_ode_alloc(rot, p);
  const double x0[4] = {0, 0, 0, 0};
  whirl_ode_set_tolerances(ode, 1e-10, 1e-13);
  int rc = whirl_ode_reset(ode, 0.0, x0);
  const double Tf = 2.0 * PI / 8.7;
  if (rc == 0) rc = whirl_ode_evolve(ode, 200.0 * Tf);
  double tev[2], xev[2][4], xe[4], te;
  size_t nev = 0;
  while (rc == 0 && nev < 2 && whirl_ode_t(ode) < 220.0 * Tf) {
    rc = whirl_ode_step(ode, 220.0 * Tf);
    if (rc == 0 && whirl_ode_find_event(ode, du_event, NULL, -1, 0.0, &te, xe) == 1) {
      tev[nev] = te;
      memcpy(xev[nev], xe, sizeof xe);
      ++nev;
    }
  }
  ok(rc == 0 && nev == 2, "SFD 8.7: two returns to u' = 0 after settling");
  if (nev < 2) {
    whirl_ode_free(ode);
    return;
  }
  const double Tr = tev[1] - tev[0];
  const size_t m = 256;
  double *smp = malloc(4 * m * sizeof *smp);
  sample_buf sb = {smp, 4};
  whirl_ode_set_tolerances(ode, 1e-12, 1e-15);
  whirl_ode_reset(ode, 0.0, xev[1]);
  rc = whirl_ode_sample(ode, Tr / (double)m, m - 1, store_sample, &sb);
  whirl_ode_free(ode);
  char err[256];
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = 40;
  o.ncol = 6;
  whirl_colloc *c = whirl_colloc_alloc(rot, &o, err, sizeof err);
  const whirl_system *s = whirl_colloc_system(c);
  const size_t nx = whirl_colloc_size(c);
  double *X = malloc(nx * sizeof *X);
  whirl_colloc_from_samples(c, smp, m, Tr, X);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = WHIRL_SFD_OMEGA;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  rc = correct(ct, X, p);
  if (rc == WHIRL_OK) {
    /* on a mesh adapted to the orbit (the variational route only uses
     * x(0) and T, not the mesh) */
    memcpy(X, whirl_cont_point(ct)->x, nx * sizeof *X);
    rc = whirl_colloc_adapt(c, X);
    if (rc == WHIRL_OK) rc = correct(ct, X, p);
  }
  ok(rc == WHIRL_OK, "SFD 8.7: collocation Newton converges, mesh adapted: %s",
     whirl_cont_errmsg(ct));
  if (rc == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    printf("# SFD 8.7: period %.12f (integration %.12f)\n", pt->x[nx - 1], Tr);
    ok(pt->nspec == 3 && pt->stable == 1,
       "SFD 8.7: three nontrivial multipliers, stable");
    floquet_routes("SFD rotating frame, Omega = 8.7, NTST 40 NCOL 6", rot, &o,
                   pt->x, pt->p, pt->spec_re, pt->spec_im, pt->nspec);
  }
  whirl_cont_free(ct);
  free(X);
  free(smp);
  whirl_colloc_free(c);
}

static void test_lorenz(void) {
  const double p[3] = {10.0, 250.0, 8.0 / 3.0};
  double level = p[1] - 1.0;
  const double x0[3] = {1.0, 1.0, 200.0};
  whirl_ode *ode = whirl_ode_alloc(&lorenz, p);
  int rc = whirl_ode_reset(ode, 0.0, x0);
  if (rc == 0) rc = whirl_ode_evolve(ode, 50.0);
  /* successive upward crossings of z = ρ - 1 with x > 0 */
  double tev[8], xev[8][3], xe[3], te;
  size_t nev = 0;
  while (rc == 0 && nev < 8 && whirl_ode_t(ode) < 100.0) {
    rc = whirl_ode_step(ode, 100.0);
    if (rc == 0 &&
        whirl_ode_find_event(ode, z_event, &level, 1, 0.0, &te, xe) == 1 &&
        xe[0] > 0) {
      tev[nev] = te;
      memcpy(xev[nev], xe, sizeof xe);
      ++nev;
    }
  }
  ok(rc == 0 && nev == 8, "Lorenz: 8 returns to z = ρ-1 after t = 50 (rc %d)",
     rc);
  if (nev < 8) {
    whirl_ode_free(ode);
    return;
  }
  const double Tint = tev[7] - tev[6];
  double spread = 0.0;
  for (size_t k = 1; k < 8; ++k)
    spread = fmax(spread, fabs(tev[k] - tev[k - 1] - Tint));
  printf("# Lorenz: period from integration %.12f (spread over 7 returns "
         "%.1e)\n",
         Tint, spread);
  ok(spread < 1e-9, "settled on a periodic orbit: return times agree (%.1e)",
     spread);

  /* m uniform samples over one period from the last return */
  const size_t m = 400;
  double *smp = malloc(3 * m * sizeof *smp);
  sample_buf sb = {smp, 3};
  whirl_ode_reset(ode, tev[7], xev[7]);
  rc = whirl_ode_sample(ode, Tint / (double)m, m - 1, store_sample, &sb);
  ok(rc == 0, "samples of one period");
  whirl_ode_free(ode);

  char err[256];
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = 50;
  o.ncol = 4;
  whirl_colloc *c = whirl_colloc_alloc(&lorenz, &o, err, sizeof err);
  const whirl_system *s = whirl_colloc_system(c);
  const size_t nx = whirl_colloc_size(c);
  double *X = malloc(nx * sizeof *X);
  whirl_colloc_from_samples(c, smp, m, Tint, X);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 1;
  co.linsol = WHIRL_LINSOL_SPARSE;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  rc = correct(ct, X, p);
  ok(rc == WHIRL_OK, "Lorenz: collocation Newton converges: %s",
     whirl_cont_errmsg(ct));
  if (rc == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    memcpy(X, pt->x, nx * sizeof *X);
    s->accept(pt->x, pt->p, s->data); /* not yet done by the core */
    const double Tc = X[nx - 1];
    printf("# Lorenz: period by collocation %.12f, integration %.12f, rel "
           "diff %.2e\n",
           Tc, Tint, fabs(Tc / Tint - 1.0));
    is_rel(Tc, Tint, 1e-6, "collocation period agrees with integration");
    double mx = 0.0;
    for (size_t k = 0; k < pt->nspec; ++k)
      mx = fmax(mx, hypot(pt->spec_re[k], pt->spec_im[k]));
    printf("# Lorenz multipliers: %.6g%+.6gi, %.6g%+.6gi\n", pt->spec_re[0],
           pt->spec_im[0], pt->spec_re[1], pt->spec_im[1]);
    ok(pt->nspec == 2 && mx < 1.0,
       "stable: both nontrivial |mu| < 1 (max %.3g)", mx);
    floquet_routes("Lorenz rho = 250, NTST 50 NCOL 4", &lorenz, &o, X, p,
                   pt->spec_re, pt->spec_im, pt->nspec);
    /* integrating from node 0 over T returns to node 0 */
    double xT[3], M[9];
    whirl_ode_monodromy(&lorenz, p, 0.0, X, Tc, 1e-12, 1e-12, xT, M, NULL, NULL,
                        0);
    double ret =
        fmax(fmax(fabs(xT[0] - X[0]), fabs(xT[1] - X[1])), fabs(xT[2] - X[2]));
    printf("# Lorenz: |x(T) - x(0)| integrating the collocation start %.2e\n",
           ret);
    ok(ret < 1e-6, "the orbit closes under time integration (%.1e)", ret);

    /* mesh adaptation, then re-correction: the period stays */
    double *Xa = malloc(nx * sizeof *Xa);
    memcpy(Xa, X, nx * sizeof *Xa);
    rc = whirl_colloc_adapt(c, Xa);
    const double *mesh = whirl_colloc_mesh(c);
    int mono = mesh[0] == 0.0 && mesh[50] == 1.0;
    double hmin = 1.0, hmax = 0.0;
    for (size_t i = 0; i < 50; ++i) {
      mono = mono && mesh[i + 1] > mesh[i];
      hmin = fmin(hmin, mesh[i + 1] - mesh[i]);
      hmax = fmax(hmax, mesh[i + 1] - mesh[i]);
    }
    printf("# adapted mesh: h from %.4f to %.4f\n", hmin, hmax);
    ok(rc == 0 && mono && hmax > 1.5 * hmin,
       "adapt: monotone, non-uniform mesh (h %.4f..%.4f)", hmin, hmax);
    is_rel(Xa[nx - 1], Tc, 0.0, "adapt keeps T");
    double xo[3], xn[3];
    /* remapped values are the old polynomial: node 0 unchanged */
    whirl_colloc_eval(c, Xa, 0.0, xn);
    memcpy(xo, X, sizeof xo);
    ok(fabs(xn[0] - xo[0]) + fabs(xn[1] - xo[1]) + fabs(xn[2] - xo[2]) < 1e-12,
       "adapt: x(0) unchanged");
    rc = correct(ct, Xa, p);
    ok(rc == WHIRL_OK, "re-correction on the adapted mesh: %s",
       whirl_cont_errmsg(ct));
    if (rc == WHIRL_OK) {
      const double Ta = whirl_cont_point(ct)->x[nx - 1];
      printf("# Lorenz: period after adaptation %.12f (rel change %.2e)\n", Ta,
             fabs(Ta / Tc - 1.0));
      is_rel(Ta, Tc, 1e-8, "adapted mesh keeps the period to 1e-8");
      /* the adapted orbit closes under time integration at least as well
       * as the one on the uniform mesh */
      const double *xa = whirl_cont_point(ct)->x;
      whirl_ode_monodromy(&lorenz, p, 0.0, xa, Ta, 1e-12, 1e-12, xT, M, NULL,
                          NULL, 0);
      double reta = fmax(fmax(fabs(xT[0] - xa[0]), fabs(xT[1] - xa[1])),
                         fabs(xT[2] - xa[2]));
      ok(reta < ret,
         "adapted orbit closes better under integration: |x(T) - "
         "x(0)| %.1e < %.1e (uniform)",
         reta, ret);
    }
    free(Xa);
  }
  whirl_cont_free(ct);
  free(X);
  free(smp);
  whirl_colloc_free(c);
}

/* ------------------------------------------------------------------------
 * 6. bad input */

static void test_errors(void) {
  char err[256];
  whirl_colloc_options o;
  struct {
    size_t ntst, ncol;
    int fp;
    unsigned nu;
    const whirl_problem *prob;
    const char *what;
  } bad[] = {
      {20, 1, -1, 1, &lamom, "NCOL = 1"},
      {0, 4, -1, 1, &lamom, "NTST = 0"},
      {1, 4, -1, 1, &lamom, "NTST = 1"},
      {20, 8, -1, 1, &lamom, "NCOL = 8"},
      {20, 4, 3, 1, &duffing, "forcing_param = npar"},
      {20, 4, 0, 0, &duffing, "nu = 0"},
      {20, 4, 0, 1, &lamom, "forcing an autonomous model"},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    whirl_colloc_options_default(&o);
    o.ntst = bad[k].ntst;
    o.ncol = bad[k].ncol;
    o.forcing_param = bad[k].fp;
    o.nu = bad[k].nu;
    err[0] = '\0';
    whirl_colloc *c = whirl_colloc_alloc(bad[k].prob, &o, err, sizeof err);
    ok(c == NULL && strlen(err) > 0, "%s rejected: \"%s\"", bad[k].what, err);
    whirl_colloc_free(c);
  }
  ok(whirl_colloc_alloc(NULL, NULL, err, sizeof err) == NULL && err[0],
     "NULL model rejected: \"%s\"", err);
  whirl_colloc_free(NULL);
  whirl_colloc_options_default(&o);
  whirl_colloc *c = whirl_colloc_alloc(&lamom, &o, err, sizeof err);
  double smp[8] = {0}, X[2 * 81 + 1], x[2];
  ok(whirl_colloc_from_samples(c, smp, 3, 1.0, X) == WHIRL_EINVAL &&
         whirl_colloc_from_samples(c, smp, 4, 0.0, X) == WHIRL_EINVAL &&
         whirl_colloc_eval(c, X, NAN, x) == WHIRL_EINVAL,
     "from_samples: m < 4 or T <= 0, eval at NaN: EINVAL");
  whirl_colloc_free(c);
}

/* AUTO's ADAPT2 from data (whirl_colloc_adapt_from, mold = 1): rows of a
 * hat u1 = (0, 0, 1, 0, 0) on t = 0, 1/4, ..., 1 (u2 = 0).  By hand, AUTO's
 * EQDF: slopes 0, 4, -4, 0; the densities |2 jump / (h + h)|^(1/2) of the
 * first three intervals 4, sqrt(32), 4 and, periodic, |(0 - 0) / h|^(1/2)
 * = 0 of the last; their integral 1, 2.414, 3.414, 3.414; half of it,
 * 1.707, is in the second interval at 1/4 + 0.707 / sqrt(32) = 3/8: the
 * mesh of NTST = 2 is (0, 3/8, 1), and the nodes of NCOL = 2 (0, 3/16,
 * 3/8, 11/16, 1) take the hat's values (0, 0, 1/2, 1/4, 0). */
static void test_adapt_from_data(void) {
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = 2;
  o.ncol = 2;
  char err[256];
  whirl_colloc *c = whirl_colloc_alloc(&lamom, &o, err, sizeof err);
  const double t[5] = {0, 0.25, 0.5, 0.75, 1}, u[10] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
  double X[11] = {0};
  const int rc = c ? whirl_colloc_adapt_from(c, 4, 1, t, u, X) : -1;
  const double *m = c ? whirl_colloc_mesh(c) : NULL;
  const double want[5] = {0, 0, 0.5, 0.25, 0};
  double err_nodes = 0.0;
  for (int j = 0; j < 5; ++j) err_nodes = fmax(err_nodes, fabs(X[2 * j] - want[j]) + fabs(X[2 * j + 1]));
  ok(rc == WHIRL_OK && m && fabs(m[1] - 0.375) < 1e-15 && m[2] == 1.0 && err_nodes < 1e-15,
     "adapt_from data: AUTO's mesh (0, %.15g, 1) = (0, 3/8, 1) by hand, the hat at its nodes "
     "(error %.2g)", m ? m[1] : -1.0, err_nodes);
  /* ADAPT2's second function (the direction): rows t and 1 - t, linear,
   * so exact at the new nodes 0, 3/16, 3/8, 11/16, 1; the period's entry
   * left as it was */
  const double v[10] = {0, 1, 0.25, 0.75, 0.5, 0.5, 0.75, 0.25, 1, 0};
  const double tau[5] = {0, 0.1875, 0.375, 0.6875, 1};
  double V[11] = {0};
  V[10] = 42.0;
  const int rv = c ? whirl_colloc_interp_from(c, 4, 1, t, v, V) : -1;
  double err_v = 0.0;
  for (int j = 0; j < 5; ++j)
    err_v = fmax(err_v, fabs(V[2 * j] - tau[j]) + fabs(V[2 * j + 1] - (1.0 - tau[j])));
  ok(rv == WHIRL_OK && err_v < 1e-15 && V[10] == 42.0,
     "interp_from: t and 1 - t at the nodes of that mesh by hand (error %.2g), the last "
     "entry left", err_v);
  ok(c && whirl_colloc_interp_from(c, 4, 0, t, v, V) == WHIRL_EINVAL &&
         whirl_colloc_interp_from(c, 0, 1, t, v, V) == WHIRL_EINVAL,
     "interp_from: degree 0, no intervals: WHIRL_EINVAL (%s)", c ? whirl_colloc_errmsg(c) : "");
  const double bad[5] = {0, 0.5, 0.25, 0.75, 1};
  ok(c && whirl_colloc_adapt_from(c, 4, 1, bad, u, X) == WHIRL_EINVAL &&
         whirl_colloc_adapt_from(c, 4, 0, t, u, X) == WHIRL_EINVAL,
     "adapt_from: a mesh not increasing, degree 0: WHIRL_EINVAL (%s)",
     c ? whirl_colloc_errmsg(c) : "");
  whirl_colloc_free(c);
}


/* ------------------------------------------------------------------------
 * Threads (whirl_colloc_options.threads): the residual, the bordered
 * factorisation and solves, and log|det| with its sign are the same bytes
 * on 1, 2 and 3 threads (each interval by the same arithmetic, the
 * determinant's factors in interval order); the model is called from more
 * than one thread; a failing model reports the failure of the first
 * interval in order, whatever the threads. */
static void test_threads(void) {
  char err[256];
  double *ref[4] = {NULL}, la[3] = {0};
  int sg[3] = {0};
  size_t nx = 0;
  const double p[3] = {10.0, 250.0, 8.0 / 3.0};
  for (int v = 0; v < 3; ++v) {
    whirl_colloc_options o;
    whirl_colloc_options_default(&o);
    o.ntst = 96; /* 96 · 4 · 3 = 1152 values at Gauss points: parallel */
    o.ncol = 4;
    o.threads = v + 1;
    memset(seen_team, 0, sizeof seen_team);
    fail_from = 2.0;
    whirl_colloc *c = whirl_colloc_alloc(&lorenz_seen, &o, err, sizeof err);
    ok(c != NULL, "threads %d: alloc Lorenz NTST 96: %s", v + 1, err);
    if (!c) return;
    nx = whirl_colloc_size(c);
    const whirl_system *s = whirl_colloc_system(c);
    double *X = malloc(nx * sizeof *X), *F = malloc(nx * sizeof *F);
    double *r = malloc((nx + 1) * sizeof *r), *b = malloc((nx + 1) * sizeof *b);
    tap_rng = 77; /* the same curve, border and right-hand side each time */
    lorenz_curve(c, nx, X);
    for (size_t q = 0; q <= nx; ++q) {
      r[q] = 0.3 * tap_urand(-1.0, 1.0) / sqrt((double)nx) + (q == nx);
      b[q] = tap_urand(-1.0, 1.0);
    }
    void *ws = s->bsolver->alloc(s->data);
    int rc = s->F(X, p, F, s->data);
    if (rc == 0) rc = s->bsolver->factor(ws, X, p, 1, r);
    if (rc == 0) rc = s->bsolver->solve(ws, b, 1);
    if (rc == 0) rc = s->bsolver->logdet(ws, &la[v], &sg[v]);
    ok(rc == 0, "threads %d: F, factor, solve, log|det| (%d)", v + 1, rc);
    int teams = 0; /* the team sizes seen, as bits */
    for (int t = 0; t < 64; ++t) teams |= seen_team[t];
#ifdef _OPENMP
    ok((teams & 1 << (v + 1)) != 0,
       "threads %d: the model was called from teams of %d thread(s) "
       "(sizes seen 0x%x)", v + 1, v + 1, (unsigned)teams);
#endif
    if (v == 0) {
      ref[0] = F, ref[1] = b;
      F = b = NULL;
    } else {
      ok(memcmp(F, ref[0], nx * sizeof *F) == 0 &&
             memcmp(b, ref[1], (nx + 1) * sizeof *b) == 0 && la[v] == la[0] &&
             sg[v] == sg[0],
         "threads %d: F, the solution and log|det| %.17g (sign %d) the same "
         "bytes as on one thread",
         v + 1, la[v], sg[v]);
    }
    /* failures at t > 0.3 T: every thread meets some; the first interval's
     * in order is the one reported, status 3 + 3 */
    fail_T = whirl_colloc_period(c, X, p);
    fail_from = 0.3;
    const int frc = s->F(X, p, F ? F : X, s->data) ;
    const int jrc = s->bsolver->factor(ws, X, p, 1, r);
    fail_from = 2.0;
    ok(frc == 6 && jrc == 6,
       "threads %d: a model failing from t = 0.3 T: F and the factorisation "
       "report the first interval's status 6 (got %d, %d)", v + 1, frc, jrc);
    s->bsolver->free(ws);
    whirl_colloc_free(c);
    free(X), free(F), free(r), free(b);
  }
  free(ref[0]), free(ref[1]);
}

int main(int argc, char **argv) {
  const int quick = argc > 1 && strcmp(argv[1], "quick") == 0;
  test_size_limits();
  test_jacobians();
  test_structured();
  test_threads();
  test_fixed_period();
  test_lambda_omega();
  test_phase_nodes();
  test_forced();
  test_forced_nu2();
  test_continuation(quick);
  test_adapt_along_branch();
  test_adapt_from_data();
  test_lw_from_newton();
  if (!quick) test_lorenz();
  if (!quick) test_sfd_floquet();
  test_errors();
  return done_testing();
}

/* test/unit/t_bvp.c — boundary value problems by orthogonal collocation
 * (lib/systems/bvp.c, AUTO-07p's IPS = 4) against closed forms:
 *  1. Bratu's problem (AUTO's demo exp): u'' = -λ e^u, u(0) = u(1) = 0,
 *     continued in λ from (0, 0): the solutions at λ = 1 and 3 against
 *     u(x) = -2 ln[cosh((x - 1/2) θ/2) / cosh(θ/4)], θ = sqrt(2λ) cosh(θ/4)
 *     (the smaller root), and the fold at λ* = 3.513830719125162;
 *  2. the analytic Jacobian against finite differences of F, the sparse
 *     against the dense, with and without the model's Jacobians;
 *  3. an integral condition with a free parameter: u' = a u, u(0) = 1,
 *     ∫ (u - c) dt = 0, continued in c with a free: (e^a - 1)/a = c; and a
 *     model that depends on t with a free parameter in the boundary
 *     conditions, u' = a u + sin 3t, u(0) = q, u(1) = B;
 *  4. rejected options.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <whirl/bvp.h>
#include <whirl/cont.h>
#include <whirl/fold.h>

#include "../tap.h"
#include "bsolver_check.h"

/* ------------------------------------------------------------------------
 * Bratu: u1' = u2, u2' = -λ e^{u1}, p = (λ) */

static int bratu_rhs(double t, const double *u, const double *p, double *f,
                     void *data) {
  (void)t;
  (void)data;
  f[0] = u[1];
  f[1] = -p[0] * exp(u[0]);
  return 0;
}
static int bratu_jac(double t, const double *u, const double *p, double *J,
                     void *data) {
  (void)t;
  (void)data;
  J[0] = 0.0, J[1] = -p[0] * exp(u[0]);
  J[2] = 1.0, J[3] = 0.0;
  return 0;
}
static int bratu_jacp(double t, const double *u, const double *p, double *J,
                      void *data) {
  (void)t;
  (void)p;
  (void)data;
  J[0] = 0.0, J[1] = -exp(u[0]);
  return 0;
}
static const whirl_problem bratu = {.name = "bratu",
                                    .n = 2,
                                    .npar = 1,
                                    .rhs = bratu_rhs,
                                    .jac_x = bratu_jac,
                                    .jac_p = bratu_jacp,
                                    .autonomous = 1};
static const whirl_problem bratu_fd = {
    .name = "bratu-fd", .n = 2, .npar = 1, .rhs = bratu_rhs, .autonomous = 1};

static int bratu_bc(const double *u0, const double *u1, const double *p,
                    double *fb, void *data) {
  (void)p;
  (void)data;
  fb[0] = u0[0];
  fb[1] = u1[0];
  return 0;
}

/* θ = sqrt(2λ) cosh(θ/4), the smaller root, by bisection on [0, θ_*]:
 * θ - sqrt(2λ) cosh(θ/4) is negative at 0 and >= 0 at the fold's
 * θ_* = 4.798714560 for λ <= λ_* (positive between the two roots). */
static double bratu_theta(double lam) {
  const double s = sqrt(2.0 * lam);
  double lo = 0.0, hi = 4.798714560;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid - s * cosh(mid / 4.0) < 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}
static double bratu_u(double lam, double x) {
  const double th = bratu_theta(lam);
  return -2.0 * log(cosh((x - 0.5) * th / 2.0) / cosh(th / 4.0));
}
static double bratu_du(double lam, double x) {
  const double th = bratu_theta(lam);
  return -th * tanh((x - 0.5) * th / 2.0);
}

/* AUTO's STPNT of exp: λ = 0, u = 0 */
static int bratu_start(double t, double *u, double *p, void *d) {
  (void)t;
  (void)d;
  u[0] = u[1] = 0.0;
  p[0] = 0.0;
  return 0;
}

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

/* max over the mesh points (superconvergent) and over all nodes of the
 * error of u1 and u2 against the closed form */
static void bratu_errors(const whirl_bvp *b, const double *X, double lam,
                         size_t ntst, size_t ncol, double *emesh,
                         double *enode) {
  const double *tau = whirl_bvp_mesh(b);
  *emesh = *enode = 0.0;
  for (size_t j = 0; j <= ntst * ncol; ++j) {
    const size_t i = j / ncol, k = j % ncol;
    const double x = j == ntst * ncol ? 1.0
                                      : tau[i] + (tau[i + 1] - tau[i]) *
                                                     (double)k / (double)ncol;
    const double e = fmax(fabs(X[2 * j] - bratu_u(lam, x)),
                          fabs(X[2 * j + 1] - bratu_du(lam, x)));
    *enode = fmax(*enode, e);
    if (k == 0) *emesh = fmax(*emesh, e);
  }
}

/* ------------------------------------------------------------------------
 * 1. Bratu by the continuation core */

/* Bratu's BVP options: NTST, NCOL, its two boundary conditions. */
static void bratu_options(whirl_bvp_options *o, size_t ntst, size_t ncol) {
  whirl_bvp_options_default(o);
  o->ntst = ntst;
  o->ncol = ncol;
  o->nbc = 2;
  o->bc = bratu_bc;
}

/* kind: the core's LU of the bordered matrix (structured = 0), or with
 * structured = 1 the system's condensation of parameters (bvp_cond.c) */
static void test_bratu(whirl_linsol_kind kind, int structured) {
  const char *kn = structured ? "condensed"
                   : kind == WHIRL_LINSOL_SPARSE ? "sparse" : "dense";
  const size_t ntst = 10, ncol = 4;
  char err[256];
  whirl_bvp_options o;
  bratu_options(&o, ntst, ncol);
  whirl_bvp *b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(b != NULL, "Bratu (%s): alloc NTST 10 NCOL 4: %s", kn, err);
  if (!b) return;
  const whirl_system *s = whirl_bvp_system(b);
  const size_t nx = whirl_bvp_size(b);
  ok(nx == 2 * 41 && s->n == nx, "size n (NTST NCOL + 1) = 82 (got %zu)", nx);
  double *X = malloc(nx * sizeof *X), p[1] = {7.0};
  int rc = whirl_bvp_from_function(b, bratu_start, NULL, X, p);
  ok(rc == WHIRL_OK && p[0] == 0.0, "from_function: STPNT sets λ = 0");

  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 0;
  co.linsol = kind;
  co.structured = structured;
  co.ds = 0.1;
  co.ds_max = 0.25;
  co.nmx = 200;
  co.p_min = -0.5;
  const double uz[2] = {1.0, 3.0};
  co.uz = uz;
  co.nuz = 2;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  ok(ct != NULL, "Bratu (%s): continuation alloc: %s", kn, err);
  rc = ct ? whirl_cont_start(ct, X, p, +1) : -1;
  ok(rc == WHIRL_OK, "Bratu (%s): start at λ = 0, u = 0: %s", kn,
     ct ? whirl_cont_errmsg(ct) : err);
  int seen_uz[2] = {0, 0}, seen_lp = 0;
  double lam_lp = NAN, mx_lp[2] = {NAN, NAN}, l2_lp = NAN;
  while (rc == WHIRL_OK && !seen_lp && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    if (pt->type == WHIRL_PT_UZ && pt->uz >= 0 && pt->uz < 2 &&
        !seen_uz[pt->uz]) {
      const double lam = pt->p[0];
      double em, en;
      bratu_errors(b, pt->x, lam, ntst, ncol, &em, &en);
      printf("# Bratu (%s) UZ λ = %.12g (θ = %.12f): error %.2e at mesh "
             "points, %.2e at all nodes; L2 %.10f\n",
             kn, lam, bratu_theta(lam), em, en, whirl_bvp_l2norm(b, pt->x));
      is_abs(lam, uz[pt->uz], 1e-10, "Bratu (%s): UZ at λ = %g", kn, uz[pt->uz]);
      ok(em < 1e-9, "Bratu (%s) λ = %g: closed form at the mesh points to "
                    "1e-9 (%.2e)", kn, lam, em);
      ok(en < 1e-6, "Bratu (%s) λ = %g: closed form at all nodes to 1e-6 "
                    "(%.2e)", kn, lam, en);
      /* between the nodes: the polynomial at t = 0.3137 */
      double ue[2] = {NAN, NAN};
      whirl_bvp_eval(b, pt->x, 0.3137, ue);
      is_abs(ue[0], bratu_u(lam, 0.3137), 1e-6,
             "Bratu (%s) λ = %g: eval at t = 0.3137 (%.10f)", kn, lam, ue[0]);
      seen_uz[pt->uz] = 1;
    }
    if (pt->type == WHIRL_PT_LP) {
      seen_lp = 1;
      lam_lp = pt->p[0];
      whirl_bvp_max(b, pt->x, mx_lp);
      l2_lp = whirl_bvp_l2norm(b, pt->x);
    }
  }
  ok(seen_uz[0] && seen_uz[1], "Bratu (%s): UZ points at λ = 1 and 3 on the "
                               "lower branch", kn);
  printf("# Bratu (%s): LP at λ = %.15f (closed form 3.513830719125162), "
         "MAX U1 %.10f, L2 %.10f\n", kn, lam_lp, mx_lp[0], l2_lp);
  ok(seen_lp, "Bratu (%s): a fold (LP) on the branch: %s", kn,
     ct ? whirl_cont_errmsg(ct) : "");
  is_abs(lam_lp, 3.513830719125162, 1e-6, "Bratu (%s): LP at λ* = 3.5138307 "
                                          "(1e-6)", kn);
  /* at the fold θ_* = 4.798714560: max u1 = u(1/2) = 2 ln cosh(θ_* / 4) */
  is_abs(mx_lp[0], 2.0 * log(cosh(4.798714560 / 4.0)), 1e-5,
         "Bratu (%s): MAX U1 at the fold = 2 ln cosh(θ*/4)", kn);
  whirl_cont_free(ct);
  free(X);
  whirl_bvp_free(b);
}

/* The corrector with F made by the Jacobian's fill (the bsolver's
 * factor_F) against the same continuation with F evaluated apart (a copy
 * of the system whose bsolver lacks factor_F): the same points to the bit
 * through the fold, one F evaluation fewer per Newton iteration with a
 * new Jacobian (every iteration here). */
static void test_factor_F_branch(void) {
  char err[256];
  whirl_bvp_options o;
  bratu_options(&o, 10, 4);
  whirl_bvp *b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(b && whirl_bvp_system(b)->bsolver && whirl_bvp_system(b)->bsolver->factor_F,
     "Bratu NTST 10: the condensed solver makes F with the Jacobian (factor_F)");
  if (!b) return;
  const size_t nx = whirl_bvp_size(b);
  whirl_system plain = *whirl_bvp_system(b);
  whirl_bsolver bs = *plain.bsolver;
  bs.factor_F = NULL;
  plain.bsolver = &bs;
  double *pts[2] = {malloc(60 * (nx + 1) * sizeof(double)), malloc(60 * (nx + 1) * sizeof(double))};
  size_t np[2] = {0, 0}, fev[2] = {0, 0}, its[2] = {0, 0}, jac[2] = {0, 0}, fus[2] = {0, 0};
  for (int fused = 0; fused < 2; ++fused) {
    double *X = malloc(nx * sizeof *X), p[1] = {0.0};
    whirl_bvp_from_function(b, bratu_start, NULL, X, p);
    whirl_cont_options co;
    whirl_cont_options_default(&co);
    co.structured = 1;
    co.ds = 0.1;
    co.ds_max = 0.25;
    co.nmx = 60;
    co.p_min = -0.5;
    co.tangent_from_newton = 2;
    whirl_cont *ct = whirl_cont_alloc(fused ? whirl_bvp_system(b) : &plain, &co, err,
                                      sizeof err);
    int rc = ct && X ? whirl_cont_start(ct, X, p, +1) : -1;
    while (rc == WHIRL_OK && np[fused] < 60 && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
      const whirl_point *pt = whirl_cont_point(ct);
      memcpy(pts[fused] + np[fused] * (nx + 1), pt->x, nx * sizeof *pt->x);
      pts[fused][np[fused]++ * (nx + 1) + nx] = pt->p[0];
    }
    if (ct) {
      fev[fused] = whirl_cont_get_stats(ct)->f_evals;
      its[fused] = whirl_cont_get_stats(ct)->newton_its;
      jac[fused] = whirl_cont_get_stats(ct)->jac_evals;
      fus[fused] = whirl_cont_get_stats(ct)->f_fused;
    }
    whirl_cont_free(ct);
    free(X);
  }
  ok(np[0] > 20 && np[0] == np[1] &&
         memcmp(pts[0], pts[1], np[0] * (nx + 1) * sizeof(double)) == 0,
     "factor_F: the branch's %zu points the bytes of F evaluated apart (%zu)", np[1], np[0]);
  ok(its[0] == its[1] && jac[0] == jac[1] && fev[0] == fev[1],
     "factor_F: the same %zu Newton iterations, %zu Jacobians and %zu F (%zu, %zu, %zu)",
     its[1], jac[1], fev[1], its[0], jac[0], fev[0]);
  /* every corrector iteration takes a new Jacobian (NWTN unset): each F
   * of the corrector from its Jacobian; the others (the localisation's
   * differences) evaluated apart */
  ok(fus[0] == 0 && fus[1] > 0 && fus[1] + 20 >= its[1] && fus[1] <= its[1],
     "factor_F: %zu of the %zu Newton iterations' F made with their Jacobians (apart: %zu)",
     fus[1], its[1], fus[0]);
  free(pts[0]), free(pts[1]);
  whirl_bvp_free(b);
}

/* The larger root of θ = sqrt(2λ) cosh(θ/4) (Bratu's upper branch), by
 * bisection on [θ_*, 40]. */
static double bratu_theta_upper(double lam) {
  const double s = sqrt(2.0 * lam);
  double lo = 4.798714560, hi = 40.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid - s * cosh(mid / 4.0) > 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

/* The largest error of u on Bratu's upper branch at the UZ λ = 0.2 (a
 * peak of height 2 ln cosh(θ/4), θ ≈ 17) on NTST 8, NCOL 4, over 1001
 * points, with a fixed mesh and adapted every 2 steps (AUTO's IAD): the
 * mesh follows the peak, so the error of the adapted run is smaller. */
static double bratu_upper_error(int adapt_every, size_t *nadapt) {
  char err[256];
  whirl_bvp_options o;
  bratu_options(&o, 8, 4);
  o.adapt_every = adapt_every;
  whirl_bvp *b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  if (!b) return NAN;
  const size_t nx = whirl_bvp_size(b);
  double *X = malloc(nx * sizeof *X), p[1] = {0.0}, e = NAN;
  whirl_bvp_from_function(b, bratu_start, NULL, X, p);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.ds = 0.1;
  co.ds_max = 0.5;
  co.nmx = 400;
  const double uz[1] = {0.2};
  co.uz = uz;
  co.nuz = 1;
  whirl_cont *ct = whirl_cont_alloc(whirl_bvp_system(b), &co, err, sizeof err);
  int rc = ct ? whirl_cont_start(ct, X, p, +1) : -1, folded = 0;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    folded |= pt->type == WHIRL_PT_LP;
    if (folded && pt->type == WHIRL_PT_UZ) {
      const double th = bratu_theta_upper(0.2);
      e = 0.0;
      for (int k = 0; k <= 1000; ++k) { /* the polynomial against the closed form */
        const double x = k / 1000.0;
        double u[2];
        whirl_bvp_eval(b, pt->x, x, u);
        e = fmax(e, fabs(u[0] + 2.0 * log(cosh((x - 0.5) * th / 2.0) / cosh(th / 4.0))));
      }
      break;
    }
  }
  *nadapt = whirl_bvp_adaptations(b);
  whirl_cont_free(ct);
  free(X);
  whirl_bvp_free(b);
  return e;
}

static void test_bratu_adapt(void) {
  size_t n0 = 9, n2 = 0;
  const double e0 = bratu_upper_error(0, &n0), e2 = bratu_upper_error(2, &n2);
  printf("# Bratu upper branch, λ = 0.2, NTST 8: error of u %.2e (fixed mesh), "
         "%.2e (adapted, %zu meshes)\n", e0, e2, n2);
  ok(n0 == 0 && n2 > 0, "adapt_every 2: meshes adapted along the branch (%zu), none "
                        "with 0", n2);
  ok(e2 < e0 / 3.0 && e2 < 1e-4, "the adapted mesh is 3x nearer the closed form "
                                 "than the uniform one (%.1e vs %.1e)", e2, e0);
}

/* Newton at fixed λ = 1 from u = 0 on a non-uniform mesh (set_mesh), the
 * core's dense corrector on the system's F and F_x. */
static void test_bratu_newton(void) {
  const size_t ntst = 8, ncol = 5;
  char err[256];
  whirl_bvp_options o;
  bratu_options(&o, ntst, ncol);
  whirl_bvp *b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(b != NULL, "Bratu NTST 8 NCOL 5: %s", err);
  if (!b) return;
  double tau[9];
  for (size_t i = 0; i <= ntst; ++i) {
    const double x = (double)i / (double)ntst;
    tau[i] = x * x * (3.0 - 2.0 * x); /* denser at both ends */
  }
  tau[0] = 0.0, tau[ntst] = 1.0;
  ok(whirl_bvp_set_mesh(b, tau) == WHIRL_OK && whirl_bvp_mesh(b)[3] == tau[3],
     "set_mesh: a non-uniform mesh");
  const double bad[9] = {0, 0.1, 0.3, 0.2, 0.5, 0.6, 0.7, 0.8, 1};
  ok(whirl_bvp_set_mesh(b, bad) == WHIRL_EINVAL &&
         strstr(whirl_bvp_errmsg(b), "increasing"),
     "set_mesh refuses a decreasing mesh: %s", whirl_bvp_errmsg(b));
  const size_t nx = whirl_bvp_size(b);
  double *X = calloc(nx, sizeof *X);
  const double p[1] = {1.0};
  int its = 0;
  int rc = whirl_newton(whirl_bvp_system(b), X, p, 1e-12, 20, &its);
  double em, en;
  bratu_errors(b, X, 1.0, ntst, ncol, &em, &en);
  printf("# Bratu λ = 1, Newton from 0 (%d iterations): error %.2e at mesh "
         "points, %.2e at nodes\n", its, em, en);
  ok(rc == WHIRL_OK && em < 1e-10 && en < 1e-7,
     "Bratu λ = 1 by Newton on a non-uniform mesh: mesh points %.2e < 1e-10, "
     "nodes %.2e < 1e-7", em, en);
  /* L2-NORM: the quadrature of |u|² of the closed form by Simpson */
  double q = 0.0;
  const int M = 2000;
  for (int k = 0; k <= M; ++k) {
    const double x = (double)k / M, w = (k == 0 || k == M) ? 1 : (k % 2 ? 4 : 2);
    const double a = bratu_u(1.0, x), d = bratu_du(1.0, x);
    q += w * (a * a + d * d);
  }
  q = sqrt(q / (3.0 * M));
  is_abs(whirl_bvp_l2norm(b, X), q, 1e-8, "L2-NORM = sqrt(∫ u1² + u2²) of the "
                                          "closed form (%.10f)", q);
  /* the system's norm weights: the quadrature of the node values on this
   * mesh, exact for f² of degree 4 <= NCOL on every interval (AUTO's
   * RNRMSQ): f = 1 + 2t + 3t² in u1 and 1 - t in u2 on the non-uniform
   * mesh: f² = 1 + 4t + 10t² + 12t³ + 9t⁴, int_0^1 f² = 1 + 2 + 10/3 + 3 +
   * 9/5, and int_0^1 (1 - t)² = 1/3 */
  const whirl_system *sys = whirl_bvp_system(b);
  double *qw = malloc(nx * sizeof *qw);
  int qrc = sys->norm_weights ? sys->norm_weights(qw, sys->data) : -1;
  double sq = 0.0, tot = 0.0;
  for (size_t i = 0; qrc == 0 && i < ntst; ++i)
    for (size_t k = 0; k <= ncol; ++k) {
      const size_t j = i * ncol + k;
      if (k == ncol && i + 1 < ntst) continue; /* the next interval's first */
      const double t = tau[i] + (tau[i + 1] - tau[i]) * (double)k / (double)ncol;
      const double f = 1 + 2 * t + 3 * t * t, g = 1 - t;
      sq += qw[2 * j] * f * f + qw[2 * j + 1] * g * g;
      tot += qw[2 * j];
    }
  ok(qrc == 0, "the BVP system has norm weights");
  is_abs(tot, 1.0, 1e-14, "norm weights: sum 1 over the nodes of a component (%.15g)", tot);
  is_abs(sq, 1.0 + 2.0 + 10.0 / 3.0 + 3.0 + 9.0 / 5.0 + 1.0 / 3.0, 1e-13,
         "norm weights on a non-uniform mesh integrate (1 + 2t + 3t²)² + (1 - t)² "
         "exactly (%.15g)", sq);
  /* asked again: the same; then on another mesh (the weights are kept
   * while the mesh stays): that mesh's */
  double *qa = malloc(nx * sizeof *qa), *tu = malloc((ntst + 1) * sizeof *tu);
  int same = qa && sys->norm_weights(qa, sys->data) == 0 && memcmp(qa, qw, nx * sizeof *qa) == 0;
  ok(same, "norm weights asked twice on one mesh: the same");
  for (size_t i = 0; i <= ntst; ++i) tu[i] = (double)i / (double)ntst;
  qrc = whirl_bvp_set_mesh(b, tu) == 0 ? sys->norm_weights(qw, sys->data) : -1;
  sq = 0.0;
  for (size_t i = 0; qrc == 0 && i < ntst; ++i)
    for (size_t k = 0; k <= ncol; ++k) {
      const size_t j = i * ncol + k;
      if (k == ncol && i + 1 < ntst) continue;
      const double t = tu[i] + (tu[i + 1] - tu[i]) * (double)k / (double)ncol;
      const double f = 1 + 2 * t + 3 * t * t, g = 1 - t;
      sq += qw[2 * j] * f * f + qw[2 * j + 1] * g * g;
    }
  is_abs(sq, 1.0 + 2.0 + 10.0 / 3.0 + 3.0 + 9.0 / 5.0 + 1.0 / 3.0, 1e-13,
         "norm weights after a new mesh are the new mesh's (%.15g)", sq);
  free(qa);
  free(tu);
  free(qw);
  free(X);
  whirl_bvp_free(b);
}

/* ------------------------------------------------------------------------
 * 3. u' = a u, u(0) = 1, ∫ (u - c) dt = 0; p = (a, c), a free, c the
 *    continuation parameter: u = e^{a t}, (e^a - 1)/a = c */

static int ex_rhs(double t, const double *u, const double *p, double *f,
                  void *data) {
  (void)t;
  (void)data;
  f[0] = p[0] * u[0];
  return 0;
}
static int ex_jac(double t, const double *u, const double *p, double *J,
                  void *data) {
  (void)t;
  (void)u;
  (void)data;
  J[0] = p[0];
  return 0;
}
static int ex_jacp(double t, const double *u, const double *p, double *J,
                   void *data) {
  (void)t;
  (void)p;
  (void)data;
  J[0] = u[0];
  J[1] = 0.0;
  return 0;
}
static const whirl_problem expo = {.name = "expo",
                                   .n = 1,
                                   .npar = 2,
                                   .rhs = ex_rhs,
                                   .jac_x = ex_jac,
                                   .jac_p = ex_jacp,
                                   .autonomous = 1};
static const whirl_problem expo_fd = {
    .name = "expo-fd", .n = 1, .npar = 2, .rhs = ex_rhs, .autonomous = 1};
static int ex_bc(const double *u0, const double *u1, const double *p,
                 double *fb, void *data) {
  (void)u1;
  (void)p;
  (void)data;
  fb[0] = u0[0] - 1.0;
  return 0;
}
static int ex_ic(const double *u, const double *uo, const double *ud,
                 const double *upo, const double *p, double *fi, void *data) {
  (void)data, (void)uo, (void)ud, (void)upo;
  fi[0] = u[0] - p[1];
  return 0;
}
/* ∫ (u' − c) dt = u(1) − u(0) − c: with u' = a u, u(0) = 1, e^a = 1 + c */
static int ex_ic_dot(const double *u, const double *uo, const double *ud,
                     const double *upo, const double *p, double *fi, void *data) {
  (void)data, (void)u, (void)uo, (void)upo;
  fi[0] = ud[0] - p[1];
  return 0;
}
/* every argument of AUTO's ICND, nonlinearly, for the Jacobian check */
static int ex_ic_all(const double *u, const double *uo, const double *ud,
                     const double *upo, const double *p, double *fi, void *data) {
  (void)data;
  fi[0] = u[0] * ud[0] + (u[0] - uo[0]) * upo[0] * (1.0 + ud[0] * ud[0]) - p[1];
  return 0;
}
/* a start that is not a solution: u = 1 + t, a = 0.5, c = 2 */
static int ex_start(double t, double *u, double *p, void *d) {
  (void)d;
  u[0] = 1.0 + t;
  p[0] = 0.5;
  p[1] = 2.0;
  return 0;
}
/* a with (e^a - 1)/a = c (c > 1: a > 0), by Newton on the closed form */
static double ex_a_of_c(double c) {
  double a = 1.0;
  for (int it = 0; it < 100; ++it) {
    const double g = expm1(a) / a - c;
    const double dg = (a * exp(a) - expm1(a)) / (a * a);
    const double da = g / dg;
    a -= da;
    if (fabs(da) < 1e-16 * fabs(a)) break;
  }
  return a;
}

static void test_integral(void) {
  const size_t ntst = 10, ncol = 4;
  char err[256];
  const size_t fr[1] = {0};
  whirl_bvp_options o;
  whirl_bvp_options_default(&o);
  o.ntst = ntst;
  o.ncol = ncol;
  o.nbc = 1;
  o.nint = 1;
  o.bc = ex_bc;
  o.ic = ex_ic;
  o.nfree = 1;
  o.free = fr;
  whirl_bvp *b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
  ok(b != NULL, "u' = a u with ∫ u = c, a free: alloc: %s", err);
  if (!b) return;
  const whirl_system *s = whirl_bvp_system(b);
  const size_t nx = whirl_bvp_size(b);
  ok(nx == 41 + 1, "size n (NTST NCOL + 1) + nfree = 42 (got %zu)", nx);
  double *X = malloc(nx * sizeof *X), p[2] = {9.0, 9.0};
  whirl_bvp_from_function(b, ex_start, NULL, X, p);
  ok(X[nx - 1] == 0.5 && X[40] == 2.0 && p[1] == 2.0,
     "from_function: the free a = 0.5 into X, u(1) = 2");
  double pf[2];
  p[0] = -7.0; /* ignored: a comes from X */
  whirl_bvp_params(b, X, p, pf);
  ok(pf[0] == 0.5 && pf[1] == 2.0, "whirl_bvp_params: a from X, c from p");

  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 1;
  co.linsol = WHIRL_LINSOL_SPARSE;
  co.ds = 0.05;
  co.ds_max = 0.2;
  co.p_max = 4.0;
  co.nmx = 200;
  const double uz[2] = {2.5, 3.5};
  co.uz = uz;
  co.nuz = 2;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  int rc = ct ? whirl_cont_start(ct, X, p, +1) : -1;
  ok(rc == WHIRL_OK, "start from u = 1 + t, a = 0.5 at c = 2 (Newton): %s",
     ct ? whirl_cont_errmsg(ct) : err);
  if (rc == WHIRL_OK) rc = whirl_cont_step(ct); /* the corrected start */
  if (rc == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    const double a = pt->x[nx - 1];
    printf("# c = 2: a = %.15f, closed form %.15f\n", a, ex_a_of_c(2.0));
    is_abs(a, ex_a_of_c(2.0), 1e-10, "c = 2: the free a solves (e^a - 1)/a = 2");
    double mx = NAN;
    whirl_bvp_max(b, pt->x, &mx);
    is_abs(mx, exp(a), 1e-10, "MAX U = u(1) = e^a");
    /* AUTO's rule (Newton-Cotes of the node values, RNRMV) integrates e^{2at}
     * to about 1e-10 on this mesh; a Gauss rule of the polynomial, 1e-11 */
    is_abs(whirl_bvp_l2norm(b, pt->x), sqrt(expm1(2.0 * a) / (2.0 * a)), 1e-9,
           "L2-NORM = sqrt((e^{2a} - 1)/(2a))");
    double m1 = NAN, m2 = NAN, mn = NAN, mxm = NAN;
    whirl_bvp_moments(b, pt->x, &m1, &m2, &mn, &mxm);
    is_abs(m1, 2.0, 1e-10, "moments: ∫ u = c = 2 (the integral condition)");
    is_abs(m2, expm1(2.0 * a) / (2.0 * a), 1e-10, "moments: ∫ u² = (e^{2a} - 1)/(2a)");
    ok(mn == 1.0 && mxm == mx, "moments: min u = u(0) = 1, max = MAX U");
    double ue = NAN;
    whirl_bvp_eval(b, pt->x, 0.77, &ue);
    is_abs(ue, exp(0.77 * a), 1e-8, "u(0.77) = e^{0.77 a}");
  }
  int nuz = 0;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    if (pt->type != WHIRL_PT_UZ) continue;
    ++nuz;
    const double c = pt->p[1], a = pt->x[nx - 1];
    printf("# UZ c = %.12g: a = %.15f, closed form %.15f\n", c, a,
           ex_a_of_c(c));
    is_abs(a, ex_a_of_c(c), 1e-10, "UZ c = %g: a solves (e^a - 1)/a = c", c);
  }
  ok(nuz == 2, "two UZ points, c = 2.5 and 3.5 (got %d); stop: %s", nuz,
     whirl_stop_reason_name(whirl_cont_stop_reason(ct)));
  whirl_cont_free(ct);
  free(X);
  whirl_bvp_free(b);
}

/* ------------------------------------------------------------------------
 * 2. Jacobians */

static void check_jac(const char *name, const whirl_bvp *b, const double *X,
                      const double *p) {
  const whirl_system *s = whirl_bvp_system(b);
  const size_t nx = s->n;
  ok(pattern_ok(s), "%s: sparse pattern well formed, sorted rows (nnz %zu)",
     name, s->nnz);
  double e_dense = NAN, e_sparse = NAN;
  int rc1 = whirl_system_check_jacobian(s, X, p, &e_dense);
  whirl_system sp = *s;
  sp.Fx = NULL; /* the checker then scatters Fx_sparse */
  int rc2 = whirl_system_check_jacobian(&sp, X, p, &e_sparse);
  printf("# %s: Jacobian error dense %.2e sparse %.2e\n", name, e_dense,
         e_sparse);
  ok(rc1 == 0 && e_dense < 1e-6,
     "%s: dense F_x and F_p vs differences of F: %.2e < 1e-6", name, e_dense);
  ok(rc2 == 0 && e_sparse < 1e-6,
     "%s: sparse F_x vs differences of F: %.2e < 1e-6", name, e_sparse);
  /* the sparse values scattered are the dense matrix, entry for entry, and
   * the dense matrix has nothing outside the pattern */
  double *J = malloc(nx * nx * sizeof *J), *Jx = malloc(s->nnz * sizeof *Jx);
  int rc = s->Fx(X, p, J, s->data);
  if (rc == 0) rc = s->Fx_sparse(X, p, Jx, s->data);
  double diff = 0.0;
  for (size_t col = 0; rc == 0 && col < nx; ++col)
    for (int q = s->Jp[col]; q < s->Jp[col + 1]; ++q) {
      diff = fmax(diff, fabs(J[(size_t)s->Ji[q] + nx * col] - Jx[q]));
      J[(size_t)s->Ji[q] + nx * col] = 0.0;
    }
  double outside = 0.0;
  for (size_t q = 0; rc == 0 && q < nx * nx; ++q) outside = fmax(outside, fabs(J[q]));
  ok(rc == 0 && diff == 0.0 && outside == 0.0,
     "%s: sparse = dense on the pattern (%.1e), dense 0 off it (%.1e)", name,
     diff, outside);
  free(J);
  free(Jx);
}

/* AUTO's ICND arguments: u' (UDOT) and the reference and its derivative
 * (UOLD, UPOLD).  ∫ (u' − c) = u(1) − u(0) − c with u' = a u, u(0) = 1:
 * a = ln(1 + c) (closed form); an integrand using all four, with a
 * reference set, has its Jacobian checked against differences of F; and
 * the accept hook takes the core's accepted point as the reference. */
static void test_icnd_arguments(void) {
  char err[256];
  const size_t fr[1] = {0};
  whirl_bvp_options o;
  whirl_bvp_options_default(&o);
  o.ntst = 10;
  o.ncol = 4;
  o.nbc = 1;
  o.nint = 1;
  o.bc = ex_bc;
  o.ic = ex_ic_dot;
  o.nfree = 1;
  o.free = fr;
  whirl_bvp *b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
  ok(b != NULL, "∫ (u' - c) = 0: alloc: %s", err);
  if (!b) return;
  const whirl_system *s = whirl_bvp_system(b);
  const size_t nx = whirl_bvp_size(b);
  double *X = malloc(nx * sizeof *X), p[2] = {9.0, 9.0};
  whirl_bvp_from_function(b, ex_start, NULL, X, p);
  p[1] = 1.5;
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 1;
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  int rc = ct ? whirl_cont_start(ct, X, p, +1) : -1;
  if (rc == WHIRL_OK) rc = whirl_cont_step(ct);
  ok(rc == WHIRL_OK, "∫ (u' - c) = 0 at c = 1.5: Newton converges (%s)",
     ct ? whirl_cont_errmsg(ct) : err);
  if (rc == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    is_abs(pt->x[nx - 1], log(2.5), 1e-10, "UDOT: the free a = ln(1 + c) = ln 2.5");
    ok(s->accept != NULL, "an accept hook keeps the reference (UOLD)");
  }
  whirl_cont_free(ct);
  whirl_bvp_free(b);

  o.ic = ex_ic_all;
  b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
  ok(b != NULL, "an integrand of u, UOLD, UDOT, UPOLD: alloc: %s", err);
  if (!b) return;
  s = whirl_bvp_system(b);
  double *R = malloc(nx * sizeof *R);
  for (size_t j = 0; j < 41; ++j) {
    const double t = (double)j / 40.0;
    X[j] = 1.0 + t + 0.3 * sin(5.0 * t);
    R[j] = cos(2.0 * t);
  }
  X[nx - 1] = 0.7;
  p[0] = 0.7, p[1] = 0.4;
  double e0 = NAN, e1 = NAN, f0 = NAN, f1 = NAN, *F = malloc(nx * sizeof *F);
  int r0 = whirl_system_check_jacobian(s, X, p, &e0);
  s->F(X, p, F, s->data);
  f0 = F[nx - 1];
  whirl_bvp_set_reference(b, R);
  int r1 = whirl_system_check_jacobian(s, X, p, &e1);
  s->F(X, p, F, s->data);
  f1 = F[nx - 1];
  printf("# ICND of u, UOLD, UDOT, UPOLD: Jacobian error %.2e (the start as reference), %.2e (another)\n",
         e0, e1);
  ok(r0 == 0 && r1 == 0 && e0 < 1e-6 && e1 < 1e-6,
     "ICND of u, UOLD, UDOT, UPOLD: Jacobian vs differences %.1e, %.1e < 1e-6", e0, e1);
  ok(f0 != f1, "the reference enters the integral row (%.6g before, %.6g after)", f0, f1);
  free(R), free(F), free(X);
  whirl_bvp_free(b);
}

/* options.udot_direction (AUTO's UDOT: the direction vector, not u'):
 * the system gives the core a direction hook, and the integral row of
 * fi = udot - c is then the integral of the direction's state part: with
 * the node values of cos 2t it is sin 2 / 2 - c, where with u' it is
 * u(1) - u(0) - c; the Jacobian stays the differences' of F (udot is data,
 * no function of the unknowns). */
static void test_udot_direction(void) {
  char err[256];
  const size_t fr[1] = {0};
  whirl_bvp_options o;
  whirl_bvp_options_default(&o);
  o.ntst = 10, o.ncol = 4, o.nbc = 1, o.nint = 1;
  o.bc = ex_bc, o.ic = ex_ic_dot;
  o.nfree = 1, o.free = fr;
  double p[2] = {0.7, 0.4};
  for (int dir = 0; dir <= 1; ++dir) {
    o.udot_direction = dir;
    whirl_bvp *b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
    ok(b != NULL, "udot_direction = %d: alloc: %s", dir, err);
    if (!b) return;
    const whirl_system *s = whirl_bvp_system(b);
    const size_t nx = whirl_bvp_size(b);
    ok((s->direction != NULL) == dir, "udot_direction = %d: %s direction hook", dir,
       dir ? "a" : "no");
    double *X = malloc(nx * sizeof *X), *D = malloc((nx + 1) * sizeof *D),
           *F = malloc(nx * sizeof *F);
    const double *tau = whirl_bvp_mesh(b);
    for (size_t i = 0; i < 10; ++i) /* the nodes: 4 a mesh interval, equidistant */
      for (size_t k = 0; k <= 4; ++k) {
        const double t = tau[i] + 0.25 * (double)k * (tau[i + 1] - tau[i]);
        X[4 * i + k] = 1.0 + t + 0.3 * sin(5.0 * t);
        D[4 * i + k] = cos(2.0 * t);
      }
    X[nx - 1] = 0.7, D[nx - 1] = 0.5, D[nx] = 0.25;
    if (dir) s->direction(D, s->data);
    int rc = s->F(X, p, F, s->data);
    const double want = dir ? sin(2.0) / 2.0 - p[1] : X[40] - X[0] - p[1];
    is_abs(F[nx - 1], want, 1e-8, "udot_direction = %d: the integral row %s", dir,
           dir ? "sin 2 / 2 - c (the direction cos 2t)" : "u(1) - u(0) - c (u')");
    double e = NAN;
    rc = rc ? rc : whirl_system_check_jacobian(s, X, p, &e);
    ok(rc == 0 && e < 1e-6, "udot_direction = %d: Jacobian vs differences of F %.1e", dir, e);
    free(X), free(D), free(F);
    whirl_bvp_free(b);
  }
}

static void test_jacobians(void) {
  char err[256];
  whirl_bvp_options o;
  const whirl_problem *bp[2] = {&bratu, &bratu_fd};
  for (int v = 0; v < 2; ++v) {
    whirl_bvp_options_default(&o);
    o.ntst = 6;
    o.ncol = 3;
    o.nbc = 2;
    o.bc = bratu_bc;
    whirl_bvp *b = whirl_bvp_alloc(bp[v], &o, err, sizeof err);
    ok(b != NULL, "alloc %s NTST 6 NCOL 3: %s", bp[v]->name, err);
    if (!b) continue;
    const size_t nx = whirl_bvp_size(b);
    double *X = malloc(nx * sizeof *X);
    for (size_t q = 0; q < nx; ++q) X[q] = tap_urand(-1.0, 1.0);
    const double p[1] = {2.3};
    check_jac(bp[v]->name, b, X, p);
    free(X);
    whirl_bvp_free(b);
  }
  /* the integral condition, the free parameter's column */
  const whirl_problem *ep[2] = {&expo, &expo_fd};
  const size_t fr[1] = {0};
  for (int v = 0; v < 2; ++v) {
    whirl_bvp_options_default(&o);
    o.ntst = 5;
    o.ncol = 4;
    o.nbc = 1;
    o.nint = 1;
    o.bc = ex_bc;
    o.ic = ex_ic;
    o.nfree = 1;
    o.free = fr;
    whirl_bvp *b = whirl_bvp_alloc(ep[v], &o, err, sizeof err);
    ok(b != NULL, "alloc %s with NINT 1, a free: %s", ep[v]->name, err);
    if (!b) continue;
    const size_t nx = whirl_bvp_size(b);
    double *X = malloc(nx * sizeof *X);
    for (size_t q = 0; q < nx; ++q) X[q] = tap_urand(-1.0, 1.0);
    const double p[2] = {0.0 /* ignored */, 1.7};
    check_jac(ep[v]->name, b, X, p);
    free(X);
    whirl_bvp_free(b);
  }
}

/* ------------------------------------------------------------------------
 * 3b. A model that depends on t, a free parameter in the boundary
 *     conditions: u' = a u + sin 3t, u(0) = q, u(1) = B; p = (a, q, B),
 *     q free: u = q e^{at} + s(t), s(t) = (3 e^{at} - 3 cos 3t - a sin 3t)
 *     / (a² + 9), so q = (B - s(1)) e^{-a} */

static int na_rhs(double t, const double *u, const double *p, double *f,
                  void *data) {
  (void)data;
  f[0] = p[0] * u[0] + sin(3.0 * t);
  return 0;
}
static const whirl_problem nonaut = {
    .name = "nonaut", .n = 1, .npar = 3, .rhs = na_rhs, .autonomous = 0};
static int na_bc(const double *u0, const double *u1, const double *p,
                 double *fb, void *data) {
  (void)data;
  fb[0] = u0[0] - p[1];
  fb[1] = u1[0] - p[2];
  return 0;
}
static double na_s(double a, double t) {
  return (3.0 * exp(a * t) - 3.0 * cos(3.0 * t) - a * sin(3.0 * t)) /
         (a * a + 9.0);
}

static void test_nonautonomous(void) {
  char err[256];
  const size_t fr[1] = {1};
  whirl_bvp_options o;
  whirl_bvp_options_default(&o);
  o.ntst = 12;
  o.ncol = 3;
  o.nbc = 2;
  o.bc = na_bc;
  o.nfree = 1;
  o.free = fr;
  whirl_bvp *b = whirl_bvp_alloc(&nonaut, &o, err, sizeof err);
  ok(b != NULL, "u' = a u + sin 3t, u(0) = q free, u(1) = B: alloc: %s", err);
  if (!b) return;
  const size_t nx = whirl_bvp_size(b);
  double *X = malloc(nx * sizeof *X);
  for (size_t q = 0; q < nx; ++q) X[q] = tap_urand(-1.0, 1.0);
  const double p[3] = {-0.8, 0.0 /* ignored */, 1.5};
  check_jac("nonaut", b, X, p);
  for (size_t q = 0; q < nx; ++q) X[q] = 0.0;
  int its = 0;
  int rc = whirl_newton(whirl_bvp_system(b), X, p, 1e-13, 20, &its);
  const double a = p[0], qx = (p[2] - na_s(a, 1.0)) * exp(-a);
  double e = 0.0;
  for (size_t i = 0; i <= o.ntst; ++i) {
    const double t = (double)i / (double)o.ntst;
    e = fmax(e, fabs(X[i * o.ncol] - (qx * exp(a * t) + na_s(a, t))));
  }
  printf("# nonaut: q = %.15f, closed form %.15f; error at the mesh points "
         "%.2e (%d Newton iterations)\n", X[nx - 1], qx, e, its);
  ok(rc == WHIRL_OK, "nonaut: Newton from 0 converges");
  is_abs(X[nx - 1], qx, 1e-9, "nonaut: the free q = (B - s(1)) e^{-a}");
  ok(e < 1e-9, "nonaut: u at the mesh points to 1e-9 (%.2e)", e);
  free(X);
  whirl_bvp_free(b);
}

/* ------------------------------------------------------------------------
 * 3b. The condensation of parameters (bvp_cond.c) against UMFPACK on the
 * assembled bordered matrix (bsolver_check.h), at random states: boundary
 * rows alone (Bratu: no free parameter, NBC = n), with an
 * integral condition and a free parameter (expo), with a free parameter in
 * the boundary rows (nonaut); NTST 1 has no structured solver. */
static void bsolver_case(const char *name, const whirl_problem *prob,
                         whirl_bvp_options *o, const double *p, size_t k) {
  char err[256];
  whirl_bvp *b = whirl_bvp_alloc(prob, o, err, sizeof err);
  ok(b != NULL, "%s: alloc: %s", name, err);
  if (!b) return;
  const size_t nx = whirl_bvp_size(b);
  double *X = malloc(nx * sizeof *X);
  for (size_t q = 0; q < nx; ++q) X[q] = tap_urand(-1.0, 1.0);
  if (X) bsolver_check(name, whirl_bvp_system(b), X, p, k, 1);
  free(X);
  whirl_bvp_free(b);
}

/* The fold system of a BVP (whirl_fold on it, sparse path): [F_x b;
 * c^T 0] by the condensed solver with b given and w by its transposed
 * solve, the fold system's Newton matrix by block elimination; its
 * Jacobian and dF/dp against differences of its F, its solves and
 * determinant against UMFPACK on the assembled matrix.  nonaut with B
 * freed, a the core's, at a random state (NTST 30 NCOL 4: over 100
 * unknowns, the fold's sparse path). */
static void fold_of_bvp_check(whirl_bvp_options *o, const double *p) {
  char err[256];
  whirl_bvp *b = whirl_bvp_alloc(&nonaut, o, err, sizeof err);
  const size_t nx = b ? whirl_bvp_size(b) : 0;
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 2);
  whirl_fold *f = b ? whirl_fold_alloc(whirl_bvp_system(b), &fo, err, sizeof err) : NULL;
  double *X = malloc((nx + 1) * sizeof *X), *Z = malloc((nx + 2) * sizeof *Z), jerr = 1.0;
  double pf[3] = {p[0], p[1], p[2]};
  for (size_t q = 0; X && q < nx; ++q) X[q] = tap_urand(-1.0, 1.0);
  int rc = f && X && Z ? whirl_fold_init(f, X, pf, Z) : WHIRL_ENOMEM;
  const whirl_system *s = f ? whirl_fold_system(f) : NULL;
  if (rc == WHIRL_OK) rc = whirl_system_check_jacobian(s, Z, pf, &jerr);
  ok(rc == WHIRL_OK && nx > 100 && jerr < 1e-5, "fold of a BVP (nonaut NTST 30 NCOL 4, %zu unknowns): "
     "Jacobian and dF/dp against differences of its F (%.1e; %s)", nx, jerr,
     f ? whirl_fold_errmsg(f) : err);
  if (rc == WHIRL_OK) bsolver_check("fold of a BVP (nonaut NTST 30 NCOL 4), k = a", s, Z, pf, 0, 0);
  free(X), free(Z);
  whirl_fold_free(f);
  whirl_bvp_free(b);
}

static void test_bsolver(void) {
  whirl_bvp_options o;
  bratu_options(&o, 9, 4);
  const double pb[1] = {2.0};
  bsolver_case("Bratu NTST 9 NCOL 4, k = lambda", &bratu, &o, pb, 0);
  bsolver_case("Bratu by differences NTST 9 NCOL 4, k = lambda", &bratu_fd, &o, pb, 0);
  o.ntst = 1;
  char err[256];
  whirl_bvp *b1 = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(b1 && !whirl_bvp_system(b1)->bsolver,
     "Bratu NTST 1: no structured solver (the core's LU)");
  whirl_bvp_free(b1);

  const size_t fa[1] = {0};
  whirl_bvp_options_default(&o);
  o.ntst = 6;
  o.ncol = 3;
  o.nbc = 1;
  o.nint = 1;
  o.bc = ex_bc;
  o.ic = ex_ic;
  o.nfree = 1;
  o.free = fa;
  const double pe[2] = {0.0 /* a from X */, 2.5};
  bsolver_case("expo NTST 6 NCOL 3 (NINT 1, a free), k = c", &expo, &o, pe, 1);
  /* differences (dF/dp_k's rows made in the intervals' loop, its integral
   * row summed after it) and p_k a free parameter (its column 0) */
  bsolver_case("expo by differences (NINT 1, a free), k = c", &expo_fd, &o, pe, 1);
  bsolver_case("expo by differences (NINT 1, a free), k = a (free)", &expo_fd, &o, pe, 0);
  /* AUTO's differences: F's rows share f and g at the Gauss points with
   * the forward differences (factor_F) */
  o.auto_differences = 1;
  bsolver_case("expo by AUTO's differences (NINT 1, a free), k = c", &expo_fd, &o, pe, 1);
  o.auto_differences = 0;

  const size_t fq[1] = {1};
  whirl_bvp_options_default(&o);
  o.ntst = 5;
  o.ncol = 2;
  o.nbc = 2;
  o.bc = na_bc;
  o.nfree = 1;
  o.free = fq;
  const double pn[3] = {-0.8, 0.0 /* q from X */, 1.5};
  bsolver_case("nonaut NTST 5 NCOL 2 (q free in the BCs), k = B", &nonaut, &o, pn, 2);
  bsolver_case("nonaut NTST 5 NCOL 2 (q free in the BCs), k = a", &nonaut, &o, pn, 0);
  o.ntst = 30;
  o.ncol = 4;
  fold_of_bvp_check(&o, pn);
}

/* ------------------------------------------------------------------------
 * 4. Rejected options */

static void test_bad_options(void) {
  char err[256];
  whirl_bvp_options o;
  whirl_bvp *b;
  const size_t fr[2] = {0, 0}, fr_out[1] = {5};

  whirl_bvp_options_default(&o);
  o.nbc = 2;
  o.bc = bratu_bc;
  o.nfree = 1;
  o.free = fr;
  b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(!b && strstr(err, "nfree"), "Bratu with nfree = 1 refused: %s", err);
  whirl_bvp_free(b);

  o.nfree = 0;
  o.nbc = 1;
  b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(!b && strstr(err, "NBC + NINT"), "NBC = 1 < n = 2 refused: %s", err);
  whirl_bvp_free(b);

  whirl_bvp_options_default(&o);
  o.nbc = 2;
  o.bc = bratu_bc;
  o.ncol = 8;
  b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(!b && strstr(err, "NCOL"), "NCOL = 8 refused: %s", err);
  o.ncol = 1;
  b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(!b && strstr(err, "NCOL"), "NCOL = 1 refused: %s", err);
  o.ncol = 4;
  o.ntst = 0;
  b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(!b && strstr(err, "NTST"), "NTST = 0 refused: %s", err);

  whirl_bvp_options_default(&o);
  o.nbc = 2;
  o.bc = NULL;
  b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(!b && strstr(err, "bc is NULL"), "NBC = 2 with bc NULL refused: %s", err);

  whirl_bvp_options_default(&o);
  o.nbc = 1;
  o.nint = 1;
  o.bc = ex_bc;
  o.nfree = 1;
  o.free = fr;
  b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
  ok(!b && strstr(err, "ic is NULL"), "NINT = 1 with ic NULL refused: %s", err);
  o.ic = ex_ic;
  o.free = fr_out;
  b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
  ok(!b && strstr(err, "free[0] = 5"), "free index out of range refused: %s",
     err);
  o.free = NULL;
  b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
  ok(!b && strstr(err, "NULL"), "nfree = 1 without a list refused: %s", err);
  /* two free parameters of the same index (n = 1, NBC 1, NINT 2) */
  o.nint = 2;
  o.nfree = 2;
  o.free = fr;
  b = whirl_bvp_alloc(&expo, &o, err, sizeof err);
  ok(!b && strstr(err, "twice"), "a free parameter listed twice refused: %s",
     err);

  whirl_bvp_options_default(&o);
  o.nbc = 2;
  o.bc = bratu_bc;
  o.adapt_every = -1;
  b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(!b && strstr(err, "adapt_every"), "adapt_every < 0 refused: %s", err);
  b = whirl_bvp_alloc(NULL, &o, err, sizeof err);
  ok(!b && err[0], "NULL model refused: %s", err);
  ok(whirl_bvp_size(NULL) == 0 && whirl_bvp_system(NULL) == NULL &&
         whirl_bvp_errmsg(NULL) != NULL,
     "NULL object: size 0, no system, a message");
  whirl_bvp_free(NULL);
}

/* AUTO's ADAPT2 of a restart onto another NTST (whirl_bvp_mesh_from): a
 * boundary layer u = (exp(-(1 - t)/eps), 0), eps = 0.01, sampled on a
 * uniform NTST 100 (NCOL 4), moved onto NTST 40: the mesh equidistributes
 * |u^(5)|^(1/5) ~ exp(-(1 - t)/(5 eps)) / eps, so the share of intervals
 * in t > 1 - 5 eps ln 2 is the share of the density's integral there,
 * 1/2 (a uniform mesh: 0.7 %); sampled at the new nodes the layer is
 * resolved (largest step in u 1/8 of the uniform one's).  A mesh that is
 * not increasing is refused with a message. */
static int layer_start(double t, double *u, double *p, void *d) {
  (void)p, (void)d;
  u[0] = exp(-(1.0 - t) / 0.01);
  u[1] = 0.0;
  return 0;
}

static void test_mesh_from(void) {
  char err[256];
  whirl_bvp_options o;
  whirl_bvp_options_default(&o);
  o.ntst = 100, o.ncol = 4, o.nbc = 2, o.bc = bratu_bc;
  whirl_bvp *src = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  o.ntst = 40;
  whirl_bvp *b = whirl_bvp_alloc(&bratu, &o, err, sizeof err);
  ok(src && b, "mesh_from: NTST 100 and 40 allocated: %s", err);
  if (!src || !b) return;
  double *Xs = malloc(whirl_bvp_size(src) * sizeof *Xs), p[1] = {0.0};
  double *X = malloc(whirl_bvp_size(b) * sizeof *X);
  whirl_bvp_from_function(src, layer_start, NULL, Xs, p);
  double old[101];
  memcpy(old, whirl_bvp_mesh(src), sizeof old);
  ok(whirl_bvp_mesh_from(b, 100, 4, old, Xs) == WHIRL_OK, "mesh_from: NTST 100 -> 40: %s",
     whirl_bvp_errmsg(b));
  const double *m = whirl_bvp_mesh(b), t_half = 1.0 - 5.0 * 0.01 * log(2.0);
  size_t in = 0;
  for (size_t i = 0; i < 40; ++i) in += m[i] >= t_half;
  ok(in >= 18 && in <= 22 && m[0] == 0.0 && m[40] == 1.0,
     "mesh_from: %zu of 40 intervals beyond t = %.4f (the density's half: 20)", in, t_half);
  whirl_bvp_from_function(b, layer_start, NULL, X, p);
  double jump = 0.0;
  for (size_t j = 0; j + 1 < 161; ++j) jump = fmax(jump, fabs(X[2 * (j + 1)] - X[2 * j]));
  const double uniform = 1.0 - exp(-1.0 / (40 * 4 * 0.01)); /* the last node gap */
  ok(jump < 0.125 * uniform,
     "mesh_from: the largest step in u between nodes %.3g (uniform NTST 40: %.3g)", jump,
     uniform);
  old[50] = old[49];
  ok(whirl_bvp_mesh_from(b, 100, 4, old, Xs) == WHIRL_EINVAL &&
         strstr(whirl_bvp_errmsg(b), "not increasing"),
     "mesh_from: a mesh not increasing is refused: %s", whirl_bvp_errmsg(b));
  free(Xs), free(X);
  whirl_bvp_free(src), whirl_bvp_free(b);
}

/* ------------------------------------------------------------------------
 * 6. The Jacobian's intervals on several threads (whirl_bvp_options.
 *    threads): the same bytes as on one (each interval's terms by the same
 *    arithmetic, the integral rows summed in interval order after the
 *    loop), right against differences, and the first failure in interval
 *    order reported whichever thread meets which. */

/* ex_ic_all, failing where u is large: -1 for u in [100, 200), -2 from
 * 1000 */
static int ex_ic_fail(const double *u, const double *uo, const double *ud,
                      const double *upo, const double *p, double *fi, void *data) {
  if (u[0] >= 1000.0) return -2;
  if (u[0] >= 100.0) return -1;
  return ex_ic_all(u, uo, ud, upo, p, fi, data);
}

static whirl_bvp *threads_bvp(size_t ntst, int threads, whirl_bvp_ic_fn ic, char *err,
                              size_t len) {
  static const size_t fr[1] = {0};
  whirl_bvp_options o;
  whirl_bvp_options_default(&o);
  o.ntst = ntst;
  o.ncol = 4;
  o.nbc = 1;
  o.nint = 1;
  o.bc = ex_bc;
  o.ic = ic;
  o.nfree = 1;
  o.free = fr;
  o.threads = threads;
  return whirl_bvp_alloc(&expo_fd, &o, err, len);
}

static void test_threads(void) {
  char err[256];
  const size_t ntst = 600; /* 2400 Gauss values: the loop goes parallel */
  whirl_bvp *b1 = threads_bvp(ntst, 1, ex_ic_all, err, sizeof err),
            *b3 = threads_bvp(ntst, 3, ex_ic_all, err, sizeof err);
  ok(b1 && b3, "u' = a u, an ICND of all its arguments on NTST 600: 1 and 3 threads: %s", err);
  if (!b1 || !b3) return;
  const whirl_system *s1 = whirl_bvp_system(b1), *s3 = whirl_bvp_system(b3);
  const size_t nx = s1->n, nnz = s1->nnz;
  double *X = malloc(nx * sizeof *X), *R = malloc(nx * sizeof *R),
         *J1 = malloc(nnz * sizeof *J1), *J3 = malloc(nnz * sizeof *J3);
  /* smooth node values (random ones make u' ~ NTST, beyond differences) */
  for (size_t q = 0; q < nx; ++q) {
    const double t = (double)q / (double)nx;
    X[q] = 1.0 + 0.3 * sin(3.0 * t) + 0.01 * tap_urand(-1.0, 1.0);
    R[q] = 1.0 + 0.2 * cos(2.0 * t);
  }
  whirl_bvp_set_reference(b1, R);
  whirl_bvp_set_reference(b3, R);
  const double p[2] = {0.0, 1.7};
  const int r1 = s1->Fx_sparse(X, p, J1, s1->data), r3 = s3->Fx_sparse(X, p, J3, s3->data);
  ok(r1 == 0 && r3 == 0 && memcmp(J1, J3, nnz * sizeof *J1) == 0,
     "the sparse Jacobian on 3 threads is the same bytes as on 1 (%zu values)", nnz);
  whirl_system sp = *s3;
  sp.Fx = NULL; /* the checker scatters Fx_sparse */
  double e = NAN;
  const int rc = whirl_system_check_jacobian(&sp, X, p, &e);
  ok(rc == 0 && e < 1e-6, "on 3 threads against differences of F: %.1e < 1e-6", e);
  /* the residual and F_p (the integral row's terms summed in order after
   * the parallel loop) the same bytes too */
  double *F1 = malloc(2 * nx * sizeof *F1), *F3 = malloc(2 * nx * sizeof *F3);
  int f1 = s1->F(X, p, F1, s1->data), f3 = s3->F(X, p, F3, s3->data);
  f1 = f1 ? f1 : s1->Fp(X, p, 1, F1 + nx, s1->data);
  f3 = f3 ? f3 : s3->Fp(X, p, 1, F3 + nx, s3->data);
  ok(f1 == 0 && f3 == 0 && memcmp(F1, F3, 2 * nx * sizeof *F1) == 0 && F1[nx - 1] != 0.0 &&
         F1[2 * nx - 1] != 0.0,
     "F and F_p on 3 threads are the same bytes as on 1 (integral rows %.6g, %.6g)",
     F1[nx - 1], F1[2 * nx - 1]);
  free(F1), free(F3);
  /* the structured solver's condensation on 3 threads (cond_elim.c's
   * parallel loop over the intervals): the same factors, solution and
   * determinant bytes as on 1 */
  {
    const whirl_bsolver *bs1 = s1->bsolver, *bs3 = s3->bsolver;
    void *w1 = bs1 ? bs1->alloc(s1->data) : NULL, *w3 = bs3 ? bs3->alloc(s3->data) : NULL;
    double *r = malloc((nx + 1) * sizeof *r), *z1 = malloc((nx + 1) * sizeof *z1),
           *z3 = malloc((nx + 1) * sizeof *z3), la1 = NAN, la3 = NAN;
    int sg1 = 0, sg3 = 0, rc1 = -1, rc3 = -1;
    for (size_t q = 0; q <= nx; ++q) r[q] = 1.0 / (double)(nx + 1), z1[q] = z3[q] = sin(0.1 * q);
    if (w1 && w3) {
      rc1 = bs1->factor(w1, X, p, 1, r), rc3 = bs3->factor(w3, X, p, 1, r);
      rc1 = rc1 ? rc1 : bs1->solve(w1, z1, 1), rc3 = rc3 ? rc3 : bs3->solve(w3, z3, 1);
      bs1->logdet(w1, &la1, &sg1), bs3->logdet(w3, &la3, &sg3);
    }
    ok(rc1 == 0 && rc3 == 0 && memcmp(z1, z3, (nx + 1) * sizeof *z1) == 0 && la1 == la3 &&
           sg1 == sg3 && sg1 != 0,
       "the structured solve on 3 threads: the same bytes as on 1 (log|det| %.6g, sign %d)",
       la1, sg1);
#ifdef _OPENMP
    /* called from inside another parallel region (the solver's regions
     * then get one thread: nesting is off): every interval is still done,
     * the same bytes (a solver that shared the intervals among the threads
     * it asked for waited for ever for the missing threads' part) */
    void *wn = bs3 ? bs3->alloc(s3->data) : NULL;
    double *zn = malloc((nx + 1) * sizeof *zn), lan = NAN;
    int sgn = 0, rcn = -1;
    for (size_t q = 0; q <= nx; ++q) zn[q] = sin(0.1 * q);
    omp_set_max_active_levels(1);
#pragma omp parallel num_threads(2)
#pragma omp single
    if (wn) {
      rcn = bs3->factor(wn, X, p, 1, r);
      rcn = rcn ? rcn : bs3->solve(wn, zn, 1);
      bs3->logdet(wn, &lan, &sgn);
    }
    ok(rcn == 0 && memcmp(z1, zn, (nx + 1) * sizeof *z1) == 0 && la1 == lan && sg1 == sgn,
       "the structured solve asking for 3 threads inside another parallel region (one "
       "thread): the same bytes as on 1");
    if (bs3) bs3->free(wn);
    free(zn);
#endif
    if (bs1) bs1->free(w1);
    if (bs3) bs3->free(w3);
    free(r), free(z1), free(z3);
  }
  whirl_bvp_free(b1), whirl_bvp_free(b3);
  /* u = 150 on the nodes of intervals 10-19 (ic -1 there, at most -1 in
   * their neighbours), u = 5000 on those of 500-599 (-2): the first failure
   * in interval order, -1, is the one reported, on 1 thread and on 3 (the
   * last one, or the one met last, would be -2) */
  int got[2] = {0, 0};
  for (int v = 0; v < 2; ++v) {
    whirl_bvp *b = threads_bvp(ntst, v ? 3 : 1, ex_ic_fail, err, sizeof err);
    const whirl_system *s = whirl_bvp_system(b);
    for (size_t q = 0; q < nx; ++q) X[q] = 0.5;
    for (size_t k = 10 * 4; k <= 20 * 4; ++k) X[k] = 150.0;
    for (size_t k = 500 * 4; k <= 600 * 4; ++k) X[k] = 5000.0;
    whirl_bvp_set_reference(b, X);
    got[v] = s->Fx_sparse(X, p, J1, s->data);
    ok(got[v] == -1 && strstr(whirl_bvp_errmsg(b), "integral conditions returned -1"),
       "%d thread(s): the first failing interval's status: %d, '%s'", v ? 3 : 1, got[v],
       whirl_bvp_errmsg(b));
    double *F = malloc(nx * sizeof *F);
    const int gf = s->F(X, p, F, s->data);
    ok(gf == -1 && strstr(whirl_bvp_errmsg(b), "integral conditions returned -1"),
       "%d thread(s): F's first failing interval's status: %d, '%s'", v ? 3 : 1, gf,
       whirl_bvp_errmsg(b));
    free(F);
    whirl_bvp_free(b);
  }
  free(X), free(R), free(J1), free(J3);
}


/* ------------------------------------------------------------------------
 * AUTO's difference quotients (options.auto_differences; AUTO-07p's FUNI
 * and ICNI with JAC = 0): forward in the free parameter from one shared
 * evaluation, central in u, none in u' (AUTO's UDOT is data to ICND).
 * Counted calls a Gauss point and the Jacobian against differences of F. */

static long n_rhs_calls, n_ic_calls;
static int counted_rhs(double t, const double *u, const double *p, double *f, void *d) {
  ++n_rhs_calls;
  return ex_rhs(t, u, p, f, d);
}
static int counted_ic(const double *u, const double *uo, const double *ud,
                      const double *upo, const double *p, double *fi, void *d) {
  ++n_ic_calls;
  return ex_ic(u, uo, ud, upo, p, fi, d);
}
static const whirl_problem expo_counted = {
    .name = "expo-counted", .n = 1, .npar = 2, .rhs = counted_rhs, .autonomous = 1};

/* the Jacobian of u' = a u, u(0) = 1, ∫ g = 0 (ic) on NTST 5, NCOL 4 at
 * random X, with or without AUTO's rule, into J (sparse values); the
 * calls of rhs and ic it made */
static int expo_jacobian(int auto_rule, whirl_bvp_ic_fn ic, const whirl_problem *prob,
                         double *J, size_t *nnz, long *rhs_calls, long *ic_calls,
                         double *err) {
  char msg[256];
  const size_t fr[1] = {0};
  whirl_bvp_options o;
  whirl_bvp_options_default(&o);
  o.ntst = 5, o.ncol = 4, o.nbc = 1, o.nint = 1, o.bc = ex_bc, o.ic = ic;
  o.nfree = 1, o.free = fr, o.auto_differences = auto_rule;
  whirl_bvp *b = whirl_bvp_alloc(prob, &o, msg, sizeof msg);
  if (!b) return -1;
  const whirl_system *s = whirl_bvp_system(b);
  double X[21 + 1];
  tap_rng = 0x2545F4914F6CDD1DULL; /* the same X for every call */
  *nnz = s->nnz;
  for (size_t q = 0; q < 21; ++q) X[q] = 1.0 + 0.5 * tap_urand(-1.0, 1.0);
  X[21] = 0.8;
  const double p[2] = {0.0 /* free: from X */, 1.7};
  n_rhs_calls = n_ic_calls = 0;
  int rc = s->nnz <= 512 ? s->Fx_sparse(X, p, J, s->data) : -1;
  *rhs_calls = n_rhs_calls, *ic_calls = n_ic_calls;
  if (rc == 0 && err) rc = whirl_system_check_jacobian(s, X, p, err);
  whirl_bvp_free(b);
  return rc;
}

static void test_auto_differences(void) {
  double Jc[512], Ja[512], e_c = NAN, e_a = NAN;
  long rc_c, ic_c, rc_a, ic_a;
  size_t nnz = 0;
  const size_t gauss = 5 * 4;
  int r1 = expo_jacobian(0, counted_ic, &expo_counted, Jc, &nnz, &rc_c, &ic_c, &e_c);
  int r2 = expo_jacobian(1, counted_ic, &expo_counted, Ja, &nnz, &rc_a, &ic_a, &e_a);
  ok(r1 == 0 && r2 == 0, "AUTO's differences: both Jacobians made (%d, %d)", r1, r2);
  /* central: ic in u (2), u' (2), a (2); AUTO: ic in u (2), at the point
   * and a forward (2); rhs: f_x (2) and f_a (2) either way (n = 1) */
  ok(ic_c == 6 * (long)gauss && ic_a == 4 * (long)gauss,
     "ic calls a Gauss point: central 6 (got %ld), AUTO's 4 (got %ld; none in u')",
     ic_c / (long)gauss, ic_a / (long)gauss);
  ok(rc_c == 4 * (long)gauss && rc_a == 4 * (long)gauss,
     "rhs calls a Gauss point: 4 either way for n = 1 (got %ld, %ld)", rc_c / (long)gauss,
     rc_a / (long)gauss);
  printf("# Jacobian vs differences of F: central %.2e, AUTO's %.2e\n", e_c, e_a);
  ok(e_a < 1e-6 && e_c < 1e-6,
     "an ic without u': AUTO's rule is the Jacobian to %.1e (central %.1e) < 1e-6", e_a, e_c);
  double d = 0.0;
  for (size_t q = 0; q < nnz; ++q) d = fmax(d, fabs(Ja[q] - Jc[q]));
  ok(d > 0.0 && d < 1e-6, "the two rules' entries differ by rounding alone: %.1e", d);
  /* an ic that reads u': AUTO's rule leaves out its u' terms (data) */
  double e_u = NAN;
  long a, b;
  expo_jacobian(1, ex_ic_all, &expo_fd, Ja, &nnz, &a, &b, &e_u);
  expo_jacobian(0, ex_ic_all, &expo_fd, Jc, &nnz, &a, &b, &e_c);
  ok(e_c < 1e-6 && e_u > 1e-3,
     "an ic reading u': central has its terms (%.1e), AUTO's rule not (%.1e: UDOT is data)",
     e_c, e_u);
}

/* ------------------------------------------------------------------------
 * 3c. Failures inside the structured factorisation (bvp_cond.c fills each
 * interval's block in the loop that condenses it, on three threads here):
 * a fatal status of the model's rhs in the Jacobian is reported for the
 * first interval in order (-6: the rhs returns -floor(10 t) past t = 0.6),
 * with the message the sparse Jacobian gives; a dF/dp_k that is not
 * finite (sqrt(p1 - 2) at p1 = 2: NaN at p1 - h) is WHIRL_EBADFUNC,
 * recoverable, as the system's F_p says. */
static int nan_rhs(double t, const double *u, const double *p, double *f, void *data) {
  (void)t, (void)data;
  f[0] = u[1];
  f[1] = -p[0] * exp(u[0]) + u[0] * sqrt(p[1] - 2.0);
  return 0;
}
static const whirl_problem nan_model = {
    .name = "nanp", .n = 2, .npar = 2, .rhs = nan_rhs, .autonomous = 1};
static int fail_rhs(double t, const double *u, const double *p, double *f, void *data) {
  /* fatal past t = 0.6: -6 first, then -7 ... */
  return t > 0.6 ? -(int)(10.0 * t) : nan_rhs(t, u, p, f, data);
}
static const whirl_problem fail_model = {
    .name = "fail", .n = 2, .npar = 2, .rhs = fail_rhs, .autonomous = 0};

static void test_structured_failures(void) {
  whirl_bvp_options o;
  bratu_options(&o, 100, 3);
  o.threads = 3;
  const double p[2] = {1.0, 2.0};
  for (int pass = 0; pass < 2; ++pass) {
    char err[256];
    whirl_bvp *b = whirl_bvp_alloc(pass ? &nan_model : &fail_model, &o, err, sizeof err);
    ok(b != NULL, "failure model %d: alloc: %s", pass, b ? "" : err);
    if (!b) continue;
    const whirl_system *s = whirl_bvp_system(b);
    const size_t nx = whirl_bvp_size(b);
    double *X = calloc(nx, sizeof *X), *r = calloc(nx + 1, sizeof *r);
    double *Jx = malloc(s->nnz * sizeof *Jx), *fk = malloc(nx * sizeof *fk);
    double *wk = malloc((nx + 16) * sizeof *wk);
    void *ws = s->bsolver ? s->bsolver->alloc(s->data) : NULL;
    ok(ws && X && r && Jx && fk && wk, "failure model %d: structured solver", pass);
    if (ws && X && r && Jx && fk && wk) {
      r[nx] = 1.0;
      if (!pass) {
        int rs = s->Fx_sparse(X, p, Jx, s->data);
        char sparse_msg[512];
        snprintf(sparse_msg, sizeof sparse_msg, "%s", whirl_bvp_errmsg(b));
        int rc = s->bsolver->factor(ws, X, p, 0, r);
        printf("# sparse: %d '%s'; structured: %d '%s'\n", rs, sparse_msg, rc,
               whirl_bvp_errmsg(b));
        ok(rc == -6 && rs == -6 &&
               strstr(whirl_bvp_errmsg(b), "the model's Jacobian returned -6 (fatal)") &&
               strcmp(sparse_msg, whirl_bvp_errmsg(b)) == 0,
           "a fatal rhs in the structured Jacobian: the first interval's status (-6), the "
           "sparse Jacobian's message '%s'", whirl_bvp_errmsg(b));
      } else {
        int rp = whirl_system_param(s, X, p, 1, fk, wk);
        int rc = s->bsolver->factor(ws, X, p, 1, r);
        ok(rc == WHIRL_EBADFUNC && rp == WHIRL_EBADFUNC,
           "dF/dp_k not finite: the structured factor %d, F_p %d (WHIRL_EBADFUNC %d)", rc,
           rp, WHIRL_EBADFUNC);
        rc = s->bsolver->factor(ws, X, p, 0, r);
        ok(rc == 0, "the same model, k = 0 (finite): factored (%d)", rc);
      }
    }
    if (ws) s->bsolver->free(ws);
    free(X), free(r), free(Jx), free(fk), free(wk);
    whirl_bvp_free(b);
  }
}

int main(void) {
  test_bratu(WHIRL_LINSOL_DENSE, 0);
  test_bratu(WHIRL_LINSOL_SPARSE, 0);
  test_bratu(WHIRL_LINSOL_DENSE, 1);
  test_bsolver();
  test_factor_F_branch();
  test_structured_failures();
  test_bratu_newton();
  test_bratu_adapt();
  test_jacobians();
  test_integral();
  test_icnd_arguments();
  test_nonautonomous();
  test_bad_options();
  test_mesh_from();
  test_threads();
  test_auto_differences();
  test_udot_direction();
  return done_testing();
}

/* test/unit/t_trloc.c — the torus (Neimark–Sacker) locus of periodic orbits
 * (whirl/trloc.h) against a closed form, written here:
 *   x' = μ x − y − x r²,  y' = x + μ y − y r²,  r² = x² + y²,
 *   z' = s z − ν w,  w' = ν z + s w,  s = a + k r²,
 * p = (μ, a, ν, k).  Its orbit x² + y² = μ, z = w = 0 has the period 2π
 * and the multipliers 1, e^{−4πμ} and e^{2π s} e^{±2πiν}, s = a + kμ: a
 * torus bifurcation where a = −kμ, at the angle θ = 2πν.  The locus is
 * continued in μ (a = −kμ along it, θ = 2πν fixed) and in ν (a fixed, θ =
 * 2πν), and at its end the orbit's multipliers, from the variational
 * equations integrated along it (whirl_floquet_multipliers), have a pair
 * on the unit circle at that angle.  The torus system's sparse Jacobian is
 * checked against finite differences of the whole system.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/colloc.h>
#include <whirl/cont.h>
#include <whirl/floquet.h>
#include <whirl/trloc.h>

#include "../tap.h"

#define PI 3.14159265358979323846

static int tor_rhs(double t, const double *u, const double *p, double *f, void *data) {
  (void)t, (void)data;
  const double r2 = u[0] * u[0] + u[1] * u[1], s = p[1] + p[3] * r2;
  f[0] = p[0] * u[0] - u[1] - u[0] * r2;
  f[1] = u[0] + p[0] * u[1] - u[1] * r2;
  f[2] = s * u[2] - p[2] * u[3];
  f[3] = p[2] * u[2] + s * u[3];
  return 0;
}
static const char *const tor_pn[] = {"mu", "a", "nu", "k"};
static const whirl_problem tor4 = {.name = "tor4", .n = 4, .npar = 4, .rhs = tor_rhs,
                                   .autonomous = 1, .p_names = tor_pn};

/* The orbit at μ on the collocation mesh, corrected by Newton (a start of
 * the base continuation at fixed μ). */
static int orbit(whirl_colloc *c, const double *p, double *X) {
  const size_t m = 400, nx = whirl_colloc_size(c);
  double *u = malloc(4 * m * sizeof *u);
  if (!u) return WHIRL_ENOMEM;
  const double r = sqrt(p[0]);
  for (size_t k = 0; k < m; ++k) {
    const double t = 2.0 * PI * (double)k / (double)m;
    u[4 * k] = r * cos(t), u[4 * k + 1] = r * sin(t), u[4 * k + 2] = u[4 * k + 3] = 0.0;
  }
  int rc = whirl_colloc_from_samples(c, u, m, 2.0 * PI, X);
  free(u);
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = 0;
  co.nmx = 1;
  char err[256];
  whirl_cont *ct = rc ? NULL : whirl_cont_alloc(whirl_colloc_system(c), &co, err, sizeof err);
  if (!rc) rc = ct ? whirl_cont_start(ct, X, p, 1) : WHIRL_ENOMEM;
  if (!rc) rc = whirl_cont_step(ct); /* the start, corrected */
  if (!rc) memcpy(X, whirl_cont_point(ct)->x, nx * sizeof *X);
  whirl_cont_free(ct);
  return rc;
}

/* The locus from Z in parameter icp to p_max; the last point in Zend,
 * pend.  Every point's a and θ against a = −kμ, θ = 2πν: the worst
 * deviations in *da, *dth. */
static int follow(const whirl_system *s, size_t icp, const double *Z, const double *p,
                  double pmax, size_t nx, double *Zend, double *pend, double *da,
                  double *dth, size_t *npts) {
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  co.icp = icp;
  co.ds = 0.05;
  co.ds_max = 0.1;
  co.p_max = pmax;
  co.p_min = -10.0;
  co.nmx = 200;
  co.linsol = WHIRL_LINSOL_SPARSE;
  char err[256];
  whirl_cont *ct = whirl_cont_alloc(s, &co, err, sizeof err);
  int rc = ct ? whirl_cont_start(ct, Z, p, 1) : WHIRL_ENOMEM;
  *da = *dth = 0.0;
  *npts = 0;
  while (rc == WHIRL_OK && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(ct);
    const double mu = icp == 0 ? pt->p[0] : p[0], nu = icp == 2 ? pt->p[2] : p[2];
    *da = fmax(*da, fabs(pt->x[nx] + p[3] * mu));
    *dth = fmax(*dth, fabs(pt->x[nx + 1] - 2.0 * PI * nu));
    memcpy(Zend, pt->x, (nx + 2) * sizeof *Zend);
    memcpy(pend, pt->p, 4 * sizeof *pend);
    ++*npts;
  }
  if (rc != WHIRL_DONE) printf("# %s\n", ct ? whirl_cont_errmsg(ct) : err);
  rc = rc == WHIRL_DONE && whirl_cont_stop_reason(ct) == WHIRL_STOP_PMAX ? WHIRL_OK : rc;
  whirl_cont_free(ct);
  return rc;
}

/* The pair of |μ| nearest 1 with Im > 0: its modulus and angle. */
static void unit_pair(const double *re, const double *im, size_t m, double *mod,
                      double *ang) {
  double best = INFINITY;
  for (size_t k = 0; k < m; ++k) {
    const double r = hypot(re[k], im[k]);
    if (im[k] > 1e-9 && fabs(r - 1.0) < best) best = fabs(r - 1.0), *mod = r, *ang = atan2(im[k], re[k]);
  }
}

int main(void) {
  whirl_colloc_options o;
  whirl_colloc_options_default(&o);
  o.ntst = 20;
  o.ncol = 4;
  char err[256];
  whirl_colloc *c = whirl_colloc_alloc(&tor4, &o, err, sizeof err);
  ok(c != NULL, "collocation of tor4 (%s)", c ? "" : err);
  if (!c) return done_testing();
  const size_t nx = whirl_colloc_size(c);
  double p[4] = {1.0, -0.5, 0.15, 0.5}; /* a = −kμ: a torus point, θ = 0.3π */
  double *X = malloc(nx * sizeof *X), *Z = malloc((nx + 2) * sizeof *Z);
  double *Ze = malloc((nx + 2) * sizeof *Ze);
  int rc = X && Z && Ze ? orbit(c, p, X) : WHIRL_ENOMEM;
  ok(rc == WHIRL_OK && fabs(X[nx - 1] - 2.0 * PI) < 1e-8, "the orbit at mu = 1, period %.10f",
     rc ? NAN : X[nx - 1]);

  whirl_fold_operator op;
  size_t ei[4], ej[4];
  double ev[4];
  whirl_colloc_pd_operator(c, &op, ei, ej, ev);
  whirl_trloc *t = whirl_trloc_alloc(whirl_colloc_system(c), &op, 1, -1, err, sizeof err);
  ok(t != NULL && whirl_trloc_size(t) == nx + 2, "torus system of %zu unknowns (%s)",
     t ? whirl_trloc_size(t) : 0, t ? "" : err);
  if (!t || rc) return done_testing();
  double g[2] = {NAN, NAN};
  rc = whirl_trloc_init(t, X, p, 0.3 * PI, Z);
  if (!rc) rc = whirl_trloc_g(t, Z, p, g);
  ok(rc == WHIRL_OK && hypot(g[0], g[1]) < 1e-6,
     "at the torus point A(theta) is singular: |g| = %.1e (%s)", hypot(g[0], g[1]),
     rc ? whirl_trloc_errmsg(t) : "");
  double jerr = 1.0;
  rc = whirl_system_check_jacobian(whirl_trloc_system(t), Z, p, &jerr);
  ok(rc == 0 && jerr < 1e-5, "torus system: sparse Jacobian and dF/dp against finite "
     "differences of the whole system (%.1e)", jerr);
  p[0] = 0.9; /* off the locus: g is not zero there */
  {
    double *Xo = malloc(nx * sizeof *Xo), *Zo = malloc((nx + 2) * sizeof *Zo), go[2];
    int ro = Xo && Zo ? orbit(c, p, Xo) : WHIRL_ENOMEM;
    memcpy(Zo, Xo ? Xo : Z, nx * sizeof *Zo);
    Zo[nx] = -0.5, Zo[nx + 1] = 0.3 * PI; /* s = a + kμ = -0.05 */
    if (!ro) ro = whirl_trloc_g(t, Zo, p, go);
    ok(ro == WHIRL_OK && hypot(go[0], go[1]) > 1e-3, "off the locus (mu 0.9) |g| = %.2e", 
       hypot(go[0], go[1]));
    free(Xo), free(Zo);
  }
  p[0] = 1.0;

  double pe[4], da, dth;
  size_t npts;
  rc = follow(whirl_trloc_system(t), 0, Z, p, 1.5, nx, Ze, pe, &da, &dth, &npts);
  ok(rc == WHIRL_OK && npts > 3 && da < 1e-7 && dth < 1e-7,
     "the locus in mu from 1 to 1.5 (%zu points): a = -k mu to %.1e, theta = 2 pi nu to %.1e",
     npts, da, dth);
  if (rc == WHIRL_OK) {
    double pf[4], re[4], im[4], mod = NAN, ang = NAN;
    size_t m = 4;
    whirl_trloc_params(t, Ze, pe, pf);
    rc = whirl_floquet_multipliers(&tor4, pf, 0.0, Ze, Ze[nx - 1], 1, 1e-11, 1e-13, re, im, &m,
                                   NULL, NULL, err, sizeof err);
    if (!rc) unit_pair(re, im, m, &mod, &ang);
    ok(rc == WHIRL_OK && fabs(mod - 1.0) < 1e-6 && fabs(ang - 0.3 * PI) < 1e-6,
       "at its end (mu %.4f, a %.6f) the integrated multipliers have |mu| = %.9f at angle "
       "%.9f (0.3 pi = %.9f)", pf[0], pf[1], mod, ang, 0.3 * PI);
  }
  rc = follow(whirl_trloc_system(t), 2, Z, p, 0.35, nx, Ze, pe, &da, &dth, &npts);
  ok(rc == WHIRL_OK && npts > 3 && da < 1e-7 && dth < 1e-7 && fabs(Ze[nx + 1] - 0.7 * PI) < 1e-7,
     "the locus in nu from 0.15 to 0.35 (%zu points): a = -k mu to %.1e, theta = 2 pi nu to "
     "%.1e, %.9f at the end", npts, da, dth, Ze[nx + 1]);

  /* the angle fixed, nu free (AUTO's locus "fixing the angle", a third
   * parameter): along mu, a = -k mu and nu = theta / 2 pi = 0.15 */
  whirl_trloc *tf = whirl_trloc_alloc(whirl_colloc_system(c), &op, 1, 2, err, sizeof err);
  rc = tf ? whirl_trloc_init(tf, X, p, 0.3 * PI, Z) : WHIRL_ENOMEM;
  jerr = 1.0;
  if (!rc) rc = whirl_system_check_jacobian(whirl_trloc_system(tf), Z, p, &jerr);
  ok(rc == WHIRL_OK && jerr < 1e-5, "angle fixed, nu free: Jacobian and dF/dp against finite "
     "differences (%.1e)", jerr);
  double nu_dev = INFINITY;
  if (!rc) {
    whirl_cont_options co;
    whirl_cont_options_default(&co);
    co.icp = 0, co.ds = 0.05, co.ds_max = 0.1, co.p_max = 1.5, co.nmx = 200;
    co.linsol = WHIRL_LINSOL_SPARSE;
    whirl_cont *ct = whirl_cont_alloc(whirl_trloc_system(tf), &co, err, sizeof err);
    rc = ct ? whirl_cont_start(ct, Z, p, 1) : WHIRL_ENOMEM;
    size_t k = 0;
    nu_dev = 0.0, da = 0.0;
    while (rc == WHIRL_OK && (rc = whirl_cont_step(ct)) == WHIRL_OK) {
      const whirl_point *pt = whirl_cont_point(ct);
      da = fmax(da, fabs(pt->x[nx] + p[3] * pt->p[0]));
      nu_dev = fmax(nu_dev, fabs(pt->x[nx + 1] - 0.15));
      ++k;
    }
    ok(rc == WHIRL_DONE && whirl_cont_stop_reason(ct) == WHIRL_STOP_PMAX && k > 3 &&
           da < 1e-7 && nu_dev < 1e-7,
       "angle fixed: the locus in mu to 1.5 (%zu points), a = -k mu to %.1e, nu = 0.15 to %.1e",
       k, da, nu_dev);
    whirl_cont_free(ct);
  }
  whirl_trloc_free(tf);

  whirl_fold_operator bad = op;
  bad.na = nx + 5;
  ok(whirl_trloc_alloc(whirl_colloc_system(c), &bad, 1, -1, err, sizeof err) == NULL &&
         strstr(err, "trloc"),
     "an operator larger than the system: NULL, %s", err);
  whirl_fold_operator flat = op; /* no collocation structure to eliminate by */
  flat.nstate = 0;
  ok(whirl_trloc_alloc(whirl_colloc_system(c), &flat, 1, -1, err, sizeof err) == NULL &&
         strstr(err, "collocation"),
     "an operator without the orbit's collocation structure: NULL, %s", err);
  ok(whirl_trloc_alloc(whirl_colloc_system(c), &op, 1, 1, err, sizeof err) == NULL &&
         whirl_trloc_alloc(whirl_colloc_system(c), &op, 1, 4, err, sizeof err) == NULL,
     "the second parameter the first, or beyond npar: NULL");
  whirl_trloc_free(t);
  whirl_colloc_free(c);
  free(X), free(Z), free(Ze);
  return done_testing();
}

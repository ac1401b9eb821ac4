/* lib/core/bpstart.c — a branch started at a branch point.
 *
 * A start x0 that solves F but where F_x is singular is a fold or a branch
 * point (cont.c, start_on_solution).  At a fold the null vector of
 * [F_x F_p] is the tangent.  At a simple branch point that null space is
 * two-dimensional, spanned by t and z, and a vector of it is in general
 * no branch's tangent: the hyperplane normal to it meets both branches at
 * the same distance, and Newton from the predictor wanders between them
 * (abcb's run 4 of AUTO-07p restarts at the turning point of a fold locus
 * of orbits, which is such a point; whether the first step converged
 * depended on the rounding of the BLAS kernels).  The branches' tangents
 * alpha t + beta z solve the algebraic branching equation
 *
 *     a11 alpha^2 + 2 a12 alpha beta + a22 beta^2 = 0,
 *     a_ij = psi^T F_XX[u_i, u_j],   psi^T [F_x F_p] = 0
 *
 * (Keller 1977, "Numerical solution of bifurcation and nonlinear
 * eigenvalue problems"; Govaerts 2000, ch. 5; Seydel 2010, sec. 5.5).
 * z and psi come by inverse iteration with the factors of the extended
 * matrix [F_x F_p; t^T], the second derivatives by second differences of
 * F along t, z and t + z.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

/* F at X0 + h u (x and the continuation parameter), into f[n]. */
static int f_along(whirl_cont *c, const double *X0, const double *p0, const double *u,
                   double h, double *Xs, double *ps, double *f) {
  const size_t n = c->n;
  for (size_t i = 0; i <= n; ++i) Xs[i] = X0[i] + h * u[i];
  memcpy(ps, p0, c->npar * sizeof *ps);
  ps[c->opt.icp] = Xs[n];
  return whirl_system_eval(&c->sys, Xs, ps, f);
}

static double amax(const double *a, size_t n) {
  double m = 0.0;
  for (size_t i = 0; i < n; ++i)
    if (fabs(a[i]) > m) m = fabs(a[i]);
  return m;
}

static double norm2(const double *a, size_t n) {
  double s = 0.0;
  for (size_t i = 0; i < n; ++i) s += a[i] * a[i];
  return sqrt(s);
}

/* A difference step along u for X0's scale. */
static double step_along(const double *X0, size_t N, const double *u, double rel) {
  const double d = amax(u, N);
  return rel * (1.0 + amax(X0, N)) / (d > 0 ? d : 1.0);
}

/* Two steps of inverse iteration with the last factorisation (trans: its
 * transpose) from a fixed vector with no structure, into v[N], unit in
 * the Euclidean norm. */
static int inverse_iteration(whirl_cont *c, int trans, double *v) {
  const size_t N = c->N;
  for (size_t i = 0; i < N; ++i) v[i] = 1.0 + 0.5 * sin(1.7 * (double)i + (trans ? 1.1 : 0.3));
  for (int k = 0; k < 2; ++k) {
    const int rc = cont_solve_ext(c, v, trans);
    if (rc != 0) return rc;
    const double nv = norm2(v, N);
    if (!(nv > 0) || !isfinite(nv)) return 1;
    for (size_t i = 0; i < N; ++i) v[i] /= nv;
  }
  return 0;
}

/* F at X0 + h u and X0 - h u into w's fp and fm (w: Xs[N], ps[npar],
 * fp[n], fm[n]), h a step of rel for X0's scale along u. */
static int f_pair(whirl_cont *c, const double *X0, const double *p0, const double *u,
                  double rel, double *w, double *h) {
  double *Xs = w, *ps = w + c->N, *fp = ps + c->npar, *fm = fp + c->n;
  *h = step_along(X0, c->N, u, rel);
  const int rc = f_along(c, X0, p0, u, *h, Xs, ps, fp);
  return rc ? rc : f_along(c, X0, p0, u, -*h, Xs, ps, fm);
}

/* |[F_x F_p] u| / |u| by central differences of F. */
static int jac_times(whirl_cont *c, const double *X0, const double *p0, const double *u,
                     double *w, double *out) {
  const size_t n = c->n;
  double *fp = w + c->N + c->npar, *fm = fp + n, h;
  const int rc = f_pair(c, X0, p0, u, 1e-6, w, &h);
  if (rc != 0) return rc;
  for (size_t i = 0; i < n; ++i) fp[i] = (fp[i] - fm[i]) / (2.0 * h);
  *out = norm2(fp, n) / norm2(u, c->N);
  return 0;
}

/* psi^T F_XX[u, u], by the second difference F(X0 + hu) + F(X0 - hu) -
 * 2 F(X0) over h^2 (f0 = F(X0)). */
static int second_derivative(whirl_cont *c, const double *X0, const double *p0,
                             const double *u, const double *psi, const double *f0,
                             double *w, double *out) {
  const size_t n = c->n;
  const double *fp = w + c->N + c->npar, *fm = fp + n;
  double h;
  const int rc = f_pair(c, X0, p0, u, 1e-4, w, &h);
  if (rc != 0) return rc;
  double s = 0.0;
  for (size_t i = 0; i < n; ++i) s += psi[i] * (fp[i] + fm[i] - 2.0 * f0[i]);
  *out = s / (h * h);
  return 0;
}

/* The roots (alpha, beta) of the branching equation, scaled so that the
 * larger of the two is 1: 0, or 1 when they are not real and distinct. */
static int branching_roots(double a11, double a12, double a22, double r[2][2]) {
  const double D = a12 * a12 - a11 * a22;
  if (!(D > 1e-12 * (a12 * a12 + fabs(a11 * a22)))) return 1;
  const double sq = sqrt(D);
  for (int k = 0; k < 2; ++k) {
    const double s = k ? -sq : sq;
    if (fabs(a11) >= fabs(a22)) /* beta = 1: a11 alpha^2 + 2 a12 alpha + a22 */
      r[k][0] = (-a12 + s) / a11, r[k][1] = 1.0;
    else /* alpha = 1: a22 beta^2 + 2 a12 beta + a11 */
      r[k][0] = 1.0, r[k][1] = (-a12 + s) / a22;
  }
  return 0;
}

int cont_bp_start_tangent(whirl_cont *c, const double *X0, const double *p0, const double *t,
                          double *u) {
  const size_t n = c->n, N = c->N;
  double *mem = malloc((5 * N + 3 * n + c->npar) * sizeof *mem);
  if (!mem) return WHIRL_ENOMEM;
  double *z = mem, *y = z + N, *g = y + N, *v = g + N, *f0 = v + N, *w = f0 + n;
  int rc = cont_factor_at(c, X0, p0, t);
  if (rc == 0) rc = inverse_iteration(c, 0, z);
  if (rc != 0) goto done;
  /* z orthogonal to t in the steps' norm, then: is it a null vector too?
   * (at a fold [F_x F_p; t^T] is regular and z is nothing in particular) */
  const double zt = cont_dot(c, z, t) / cont_dot(c, t, t);
  for (size_t i = 0; i < N; ++i) z[i] -= zt * t[i];
  for (size_t i = 0; i < N; ++i) g[i] = 1.0 + 0.5 * cos(0.9 * (double)i + 0.2);
  double jz, jg;
  if ((rc = jac_times(c, X0, p0, z, w, &jz)) != 0 || (rc = jac_times(c, X0, p0, g, w, &jg)) != 0)
    goto done;
  if (!(jz <= 1e-4 * jg)) {
    rc = 1;
    goto done;
  }
  /* psi: the left null vector of [F_x F_p; t^T] is (psi, 0) */
  if ((rc = inverse_iteration(c, 1, y)) != 0) goto done;
  double *Xs = w, *ps = w + N;
  memcpy(Xs, X0, N * sizeof *Xs);
  memcpy(ps, p0, c->npar * sizeof *ps);
  ps[c->opt.icp] = X0[n];
  if ((rc = whirl_system_eval(&c->sys, Xs, ps, f0)) != 0) goto done;
  double a11, a22, a33; /* psi^T F_XX at t, z and t + z */
  for (size_t i = 0; i < N; ++i) v[i] = t[i] + z[i];
  if ((rc = second_derivative(c, X0, p0, t, y, f0, w, &a11)) != 0 ||
      (rc = second_derivative(c, X0, p0, z, y, f0, w, &a22)) != 0 ||
      (rc = second_derivative(c, X0, p0, v, y, f0, w, &a33)) != 0)
    goto done;
  /* a12 from F_XX[t + z, t + z] = a11 + 2 a12 + a22 */
  double r[2][2];
  if (branching_roots(a11, 0.5 * (a33 - a11 - a22), a22, r)) {
    rc = 1;
    goto done;
  }
  /* the branch nearest t, on t's side: where the start would have
   * stepped (as AUTO's first step from its null vector lands on the branch
   * nearest its predictor) */
  double best = -1.0;
  for (int k = 0; k < 2; ++k) {
    for (size_t i = 0; i < N; ++i) v[i] = r[k][0] * t[i] + r[k][1] * z[i];
    const double nv = sqrt(cont_dot(c, v, v)), dv = cont_dot(c, v, t) / (nv > 0 ? nv : 1.0);
    if (nv > 0 && fabs(dv) > best) {
      best = fabs(dv);
      for (size_t i = 0; i < N; ++i) u[i] = (dv < 0 ? -v[i] : v[i]) / nv;
    }
  }
  rc = best >= 0.0 ? 0 : 1;
done:
  free(mem);
  return rc;
}

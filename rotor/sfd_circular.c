/* rotor/sfd_circular.c — synchronous circular centred orbits of the SFD
 * rotor (paper §4.1): the quartic in Ω of eq. 15, its real roots (companion
 * matrix eigenvalues by LAPACK dgeev, polished by Newton), the phase of
 * eqs. 16–17, the rotating-frame state, and Ω-folds (G = ∂G/∂ε = 0).
 * Independent of the continuation code: it checks it.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stddef.h>

#include <whirl/linsol.h>
#include <whirl/rotor/sfd.h>

static int check_args(double eps, double lambda, double delta, double zeta) {
  if (!isfinite(eps) || !isfinite(lambda) || !isfinite(delta) ||
      !isfinite(zeta) || eps < 0.0 || lambda < 0.0 || delta < 0.0 ||
      zeta < 0.0)
    return WHIRL_EINVAL;
  if (eps >= 1.0) return WHIRL_EDOMAIN; /* contact: a, b are singular */
  return WHIRL_OK;
}

/* Force coefficients of a circular orbit (F_r = aΩ, F_t = bΩ: DESIGN.md
 * force with ε' = 0, εγ' = εΩ) and their ε-derivatives, s = 1 − ε²:
 *   a   = −4λε² s^{-2}            b   = −πλε s^{-3/2}
 *   a'  = −8λε(1+ε²) s^{-3}       b'  = −πλ(1+2ε²) s^{-5/2}
 *   a'' = −8λ(1+8ε²+3ε⁴) s^{-4}   b'' = −3πλε(3+2ε²) s^{-7/2}          */
static void circ_ab(double eps, double lambda, double a[3], double b[3]) {
  const double e2 = eps * eps, s = (1.0 - eps) * (1.0 + eps);
  const double s1 = 1.0 / s, rs = 1.0 / sqrt(s);
  a[0] = -4.0 * lambda * e2 * s1 * s1;
  a[1] = -8.0 * lambda * eps * (1.0 + e2) * s1 * s1 * s1;
  a[2] = -8.0 * lambda * (1.0 + 8.0 * e2 + 3.0 * e2 * e2) * s1 * s1 * s1 * s1;
  b[0] = -WHIRL_PI * lambda * eps * s1 * rs;
  b[1] = -WHIRL_PI * lambda * (1.0 + 2.0 * e2) * s1 * s1 * rs;
  b[2] = -3.0 * WHIRL_PI * lambda * eps * (3.0 + 2.0 * e2) * s1 * s1 * s1 * rs;
}

/* c[k] multiplies Ω^k in eq. 15; d1, d2 (may be NULL) get dc/dε, d²c/dε².
 * Expanding eq. 15 with F_r = aΩ, F_t = bΩ:
 *   c4 = ε² − δ², c3 = 2εa, c2 = ε²(4ζ² − 2) + a² + b² − 4ζεb,
 *   c1 = −2εa, c0 = ε². */
static void circ_coeffs(double eps, double lambda, double delta, double zeta,
                        double c[5], double d1[5], double d2[5]) {
  double a[3], b[3];
  circ_ab(eps, lambda, a, b);
  const double z2 = 4.0 * zeta * zeta - 2.0;
  c[4] = eps * eps - delta * delta;
  c[3] = 2.0 * eps * a[0];
  c[2] = eps * eps * z2 + a[0] * a[0] + b[0] * b[0] - 4.0 * zeta * eps * b[0];
  c[1] = -c[3];
  c[0] = eps * eps;
  if (d1 != NULL) {
    d1[4] = 2.0 * eps;
    d1[3] = 2.0 * a[0] + 2.0 * eps * a[1];
    d1[2] = 2.0 * eps * z2 + 2.0 * a[0] * a[1] + 2.0 * b[0] * b[1] -
            4.0 * zeta * (b[0] + eps * b[1]);
    d1[1] = -d1[3];
    d1[0] = 2.0 * eps;
  }
  if (d2 != NULL) {
    d2[4] = 2.0;
    d2[3] = 4.0 * a[1] + 2.0 * eps * a[2];
    d2[2] = 2.0 * z2 + 2.0 * (a[1] * a[1] + a[0] * a[2]) +
            2.0 * (b[1] * b[1] + b[0] * b[2]) -
            4.0 * zeta * (2.0 * b[1] + eps * b[2]);
    d2[1] = -d2[3];
    d2[0] = 2.0;
  }
}

/* p(x) = Σ c[k] x^k for k <= deg (Horner), p'(x) in *dp, and the rounding
 * scale Σ |c[k]| |x|^k in *scale (either may be NULL). */
static double poly(const double *c, int deg, double x, double *dp,
                   double *scale) {
  double p = c[deg], d = 0.0, sc = fabs(c[deg]);
  const double ax = fabs(x);
  for (int k = deg - 1; k >= 0; --k) {
    d = d * x + p;
    p = p * x + c[k];
    sc = sc * ax + fabs(c[k]);
  }
  if (dp != NULL) *dp = d;
  if (scale != NULL) *scale = sc;
  return p;
}

int whirl_sfd_circ_coeffs(double eps, double lambda, double delta,
                          double zeta, double c[5]) {
  if (c == NULL) return WHIRL_EINVAL;
  int rc = check_args(eps, lambda, delta, zeta);
  if (rc != 0) return rc;
  circ_coeffs(eps, lambda, delta, zeta, c, NULL, NULL);
  return WHIRL_OK;
}

int whirl_sfd_circ_G(double eps, double Omega, double lambda, double delta,
                     double zeta, double *G, double *G_eps, double *G_Omega) {
  int rc = check_args(eps, lambda, delta, zeta);
  if (rc != 0) return rc;
  if (!isfinite(Omega)) return WHIRL_EINVAL;
  double c[5], d1[5], dO;
  circ_coeffs(eps, lambda, delta, zeta, c, d1, NULL);
  const double g = poly(c, 4, Omega, &dO, NULL);
  if (G != NULL) *G = g;
  if (G_eps != NULL) *G_eps = poly(d1, 4, Omega, NULL, NULL);
  if (G_Omega != NULL) *G_Omega = dO;
  return WHIRL_OK;
}

/* Newton polish of a real root estimate of p (degree deg), safeguarded: an
 * iterate is kept only while |p| decreases, so a start at the real part of a
 * close complex pair cannot run away.  Returns the best iterate; *res and
 * *scale are |p| and Σ|c_k||x|^k there. */
static double polish(const double *c, int deg, double x, double *res,
                     double *scale) {
  double dp, sc, px = poly(c, deg, x, &dp, &sc);
  for (int it = 0; it < 100 && px != 0.0 && dp != 0.0; ++it) {
    const double dx = px / dp, xn = x - dx;
    double dpn, scn, pn = poly(c, deg, xn, &dpn, &scn);
    if (!(fabs(pn) < fabs(px))) break;
    x = xn;
    px = pn;
    dp = dpn;
    sc = scn;
    if (fabs(dx) <= 2.0 * DBL_EPSILON * fabs(x)) break;
  }
  *res = fabs(px);
  *scale = sc;
  return x;
}

/* The root of p in [a, b], where p(a) and p(b) differ in sign: Newton
 * steps kept inside the bracket, which each step halves at least (a
 * bisection where Newton would leave it or gain too little; Press et al.,
 * Numerical Recipes, 3rd ed., 2007, §9.4, rtsafe). */
static double bracketed_root(const double *c, int deg, double a, double b) {
  double pa = poly(c, deg, a, NULL, NULL);
  double x = 0.5 * (a + b), dp, px = poly(c, deg, x, &dp, NULL);
  for (int it = 0; it < 200 && px != 0.0; ++it) {
    if ((px < 0.0) == (pa < 0.0)) {
      a = x;
      pa = px;
    } else {
      b = x;
    }
    if (b - a <= 2.0 * DBL_EPSILON * fmax(fabs(a), fabs(b))) break;
    const double xn = dp != 0.0 ? x - px / dp : a;
    if (dp != 0.0 && fabs(xn - x) <= 2.0 * DBL_EPSILON * fabs(x)) return xn; /* converged */
    const double width = b - a;
    const int newton = xn > a && xn < b && fabs(xn - x) < 0.5 * width;
    x = newton ? xn : a + 0.5 * width;
    px = poly(c, deg, x, &dp, NULL);
  }
  return x;
}

/* The real roots of p (degree deg <= 4, c[deg] != 0) in ascending order,
 * *m of them.  Between neighbouring real roots of p' (and the Cauchy bound
 * 1 + max |c_k / c_deg| beyond them) p is monotone: at most one root
 * there, found from a change of sign; a root of p' where |p| is at the
 * level of rounding (a double root: a fold of eq. 15) is one too.  p' is
 * solved the same way, down to the quadratic formula. */
static void real_roots(const double *c, int deg, double *r, int *m) {
  *m = 0;
  if (deg == 1) {
    r[(*m)++] = -c[0] / c[1];
    return;
  }
  if (deg == 2) { /* the quadratic formula without cancellation */
    const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (disc < 0.0) { /* complex, or a double root lost to rounding */
      const double v = -c[1] / (2.0 * c[2]);
      double sc;
      if (fabs(poly(c, 2, v, NULL, &sc)) <= 1e-10 * sc) r[(*m)++] = v;
      return;
    }
    const double q = -0.5 * (c[1] + copysign(sqrt(disc), c[1]));
    const double x1 = q / c[2], x2 = q != 0.0 ? c[0] / q : x1;
    r[(*m)++] = fmin(x1, x2);
    if (x2 != x1) r[(*m)++] = fmax(x1, x2);
    return;
  }
  double d[4] = {0}, crit[4], bound = 0.0;
  int nc;
  for (int k = 0; k < deg; ++k) d[k] = (double)(k + 1) * c[k + 1];
  real_roots(d, deg - 1, crit, &nc);
  for (int k = 0; k < deg; ++k) bound = fmax(bound, fabs(c[k] / c[deg]));
  bound += 1.0;
  double x[6];
  int nx = 0;
  x[nx++] = -bound;
  for (int i = 0; i < nc; ++i)
    if (crit[i] > -bound && crit[i] < bound) x[nx++] = crit[i];
  x[nx++] = bound;
  for (int i = 0; i + 1 < nx; ++i) {
    double sc;
    const double pa = poly(c, deg, x[i], NULL, &sc), pb = poly(c, deg, x[i + 1], NULL, NULL);
    if (i > 0 && fabs(pa) <= 1e-10 * sc) /* at a root of p' */
      r[(*m)++] = x[i];
    else if ((pa < 0.0) != (pb < 0.0) && pb != 0.0)
      r[(*m)++] = bracketed_root(c, deg, x[i], x[i + 1]);
  }
}

int whirl_sfd_circ_roots(double eps, double lambda, double delta, double zeta,
                         double *Omega, int *nroots) {
  if (Omega == NULL || nroots == NULL) return WHIRL_EINVAL;
  *nroots = 0;
  int rc = check_args(eps, lambda, delta, zeta);
  if (rc != 0) return rc;
  double c[5];
  circ_coeffs(eps, lambda, delta, zeta, c, NULL, NULL);

  /* Drop exact zero leading coefficients (c4 = ε² − δ² vanishes when ε = δ:
   * the quartic becomes a cubic, its largest root having gone to infinity)
   * and exact zero trailing ones (roots Ω = 0, not wanted). */
  int hi = 4, lo = 0;
  while (hi >= 0 && c[hi] == 0.0) --hi;
  if (hi < 0) return WHIRL_EINVAL; /* G ≡ 0: only for ε = δ = 0 */
  while (lo < hi && c[lo] == 0.0) ++lo;
  const double *q = c + lo; /* q(Ω) = G(Ω) / Ω^lo, degree deg */
  const int deg = hi - lo;
  if (deg == 0) return WHIRL_OK;

  double root[4], r[4];
  int nr = 0, m = 0;
  real_roots(q, deg, root, &nr);
  for (int k = 0; k < nr; ++k) {
    double res, sc;
    const double x = polish(q, deg, root[k], &res, &sc);
    if (!(x > 0.0) || !isfinite(x)) continue;
    if (!(res <= 1e-10 * sc)) continue;
    r[m++] = x;
  }
  /* ascending; merge roots that polished onto the same value */
  for (int i = 1; i < m; ++i)
    for (int j = i; j > 0 && r[j] < r[j - 1]; --j) {
      const double t = r[j];
      r[j] = r[j - 1];
      r[j - 1] = t;
    }
  int out = 0;
  for (int i = 0; i < m; ++i) {
    if (out > 0 && r[i] - Omega[out - 1] <= 1e-12 * r[i]) continue;
    Omega[out++] = r[i];
  }
  *nroots = out;
  return WHIRL_OK;
}

/* Eqs. 16–17: δΩ² (cos β, sin β) = (ε − εΩ² − F_r, 2ζεΩ − F_t); β is the
 * angle by which the unbalance leads the journal (eq. 5: unbalance at γ + β).
 * NaN for invalid arguments. */
double whirl_sfd_circ_phase(double eps, double Omega, double lambda,
                            double delta, double zeta) {
  if (check_args(eps, lambda, delta, zeta) != 0 || !isfinite(Omega))
    return NAN;
  double a[3], b[3];
  circ_ab(eps, lambda, a, b);
  const double cr = eps - eps * Omega * Omega - a[0] * Omega;
  const double ct = 2.0 * zeta * eps * Omega - b[0] * Omega;
  return atan2(ct, cr);
}

/* The journal is at angle γ = Ωτ − β while the unbalance is at Ωτ (DESIGN.md
 * forcing δΩ²e^{iΩτ}), so in the frame y + iz = w e^{iΩτ} it sits at
 * w = ε e^{−iβ}: verified to be an equilibrium of whirl_sfd_rotating. */
void whirl_sfd_circ_state(double eps, double Omega, double lambda,
                          double delta, double zeta, double *x) {
  if (x == NULL) return;
  const double beta = whirl_sfd_circ_phase(eps, Omega, lambda, delta, zeta);
  x[0] = eps * cos(beta);
  x[1] = -eps * sin(beta);
  x[2] = 0.0;
  x[3] = 0.0;
  if (isnan(beta)) x[2] = x[3] = NAN;
}

/* Newton on (G, G_ε) = 0 in (ε, Ω) with the exact Jacobian
 * [[G_ε, G_Ω], [G_εε, G_εΩ]] (analytic second derivatives of eq. 15 from
 * circ_coeffs).  At a quadratic fold G_ε = 0, G_Ω ≠ 0, G_εε ≠ 0, so the
 * Jacobian is regular and convergence quadratic. */
int whirl_sfd_circ_fold(double *eps, double *Omega, double lambda,
                        double delta, double zeta) {
  if (eps == NULL || Omega == NULL) return WHIRL_EINVAL;
  double e = *eps, w = *Omega;
  if (!isfinite(w) || !isfinite(e) || check_args(0.5, lambda, delta, zeta) != 0)
    return WHIRL_EINVAL;
  if (!(e > 0.0 && e < 1.0)) return WHIRL_ENOCONV; /* as if it had left */
  for (int it = 0; it < 50; ++it) {
    double c[5], d1[5], d2[5], dO, d1O;
    circ_coeffs(e, lambda, delta, zeta, c, d1, d2);
    const double G = poly(c, 4, w, &dO, NULL);
    const double Ge = poly(d1, 4, w, &d1O, NULL);
    const double Gee = poly(d2, 4, w, NULL, NULL);
    /* [Ge dO; Gee d1O] (de, dw) = −(G, Ge) by Cramer's rule */
    const double det = Ge * d1O - dO * Gee;
    if (!(det != 0.0) || !isfinite(det)) return WHIRL_ENOCONV;
    const double de = (-G * d1O + dO * Ge) / det;
    const double dw = (-Ge * Ge + G * Gee) / det;
    if (!isfinite(de) || !isfinite(dw)) return WHIRL_ENOCONV;
    e += de;
    w += dw;
    if (!(e > 0.0 && e < 1.0)) return WHIRL_ENOCONV;
    if (fabs(de) < 1e-14 * e && fabs(dw) < 1e-14 * fabs(w)) {
      *eps = e;
      *Omega = w;
      return WHIRL_OK;
    }
  }
  return WHIRL_ENOCONV;
}

/* rotor/fe_forces_film.c — short-bearing film forces in closed form: the
 * 2π-film SFD and the plain journal bearing (Ocvirk short bearing,
 * half-Sommerfeld cavitation with the film boundary where the pressure
 * changes sign), with exact Jacobians.  doc/rotor-forces.md §2, §5.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>

#include <whirl/problem.h>
#include <whirl/rotor/fe.h>

#include "fe_forces_impl.h"

/* ------------------------------------------------------------------------
 * The short-bearing (Ocvirk) film.  With ρ = r/c, n(φ) = (cos φ, sin φ),
 * the film h = c (1 − ρ·n) and w the "squeeze velocity" (w = v for a
 * damper; w = v − (Ω/2) ẑ×r for a journal spinning at Ω), the short-bearing
 * Reynolds equation ∂_Z(h³ ∂_Z p) = −12 μ w·n with p(±L/2) = 0 gives
 *   p = 6 μ (w·n)/h³ (L²/4 − Z²),  ∫p dZ = μ L³ (w·n)/h³,
 * and the force on the journal
 *   f = −(μRL³/c³) ∫_H (w·n) n (1 − ρ·n)^{-3} dφ,
 * H the full circle (2π film) or the half where w·n > 0 (half-Sommerfeld:
 * the negative pressures dropped).  Both ends of that half have w·n = 0,
 * so its motion adds nothing to the derivatives (Leibniz rule):
 *   ∂f/∂w = −K ∫_H n nᵀ D^{-3},  ∂f/∂ρ = −3K ∫_H (w·n) n nᵀ D^{-4},
 * D = 1 − ρ·n, K = μRL³/c³.  In the basis r̂ = ρ/ε, t̂ ⊥ r̂ (θ = φ − γ,
 * D = 1 − ε cos θ) Sommerfeld's substitution
 *   cos θ = (cos ψ + ε)/(1 + ε cos ψ),  sin θ = √s sin ψ/(1 + ε cos ψ),
 *   dθ = √s dψ/(1 + ε cos ψ),  s = 1 − ε²,
 * turns every integrand into a trigonometric polynomial in ψ (below), so
 * the integrals are closed forms over any arc, exact up to ε → 1. */

typedef struct film_int {
  double cc, cs, ss;          /* ∫ {cos², sin cos, sin²} θ D^{-3} dθ */
  double ccc, ccs, css, sss;  /* ∫ {cos³, cos² sin, cos sin², sin³} D^{-4} */
} film_int;

/* The antiderivatives in ψ of the seven polynomials, at ψ. */
static void film_prims(double ps, double e, double P[7]) {
  const double c = cos(ps), sn = sin(ps), s2 = sin(2.0 * ps);
  const double ce = c + e, sn3 = sn * sn * sn;
  P[0] = 0.5 * ps + 0.25 * s2 + 2.0 * e * sn + e * e * ps;  /* (c+ε)² */
  P[1] = 0.5 * sn * sn - e * c;                             /* s (c+ε) */
  P[2] = 0.5 * ps - 0.25 * s2;                              /* s² */
  P[3] = sn - sn3 / 3.0 + 3.0 * e * (0.5 * ps + 0.25 * s2) + /* (c+ε)³ */
         3.0 * e * e * sn + e * e * e * ps;
  P[4] = -ce * ce * ce / 3.0;                               /* (c+ε)² s */
  P[5] = sn3 / 3.0 + e * (0.5 * ps - 0.25 * s2);            /* (c+ε) s² */
  P[6] = -c + c * c * c / 3.0;                              /* s³ */
}

/* The integrals over θ ∈ (t1, t1 + π), or over the full circle when full. */
static void film_integrals(double e, double t1, int full, film_int *I) {
  const double s = (1.0 - e) * (1.0 + e), rs = sqrt(s);
  double p1 = -WHIRL_PI, p2 = WHIRL_PI;
  if (!full) {
    const double t2 = t1 + WHIRL_PI;
    p1 = atan2(rs * sin(t1), cos(t1) - e);
    double dp = atan2(rs * sin(t2), cos(t2) - e) - p1;
    if (dp <= 0.0) dp += 2.0 * WHIRL_PI;
    p2 = p1 + dp;
  }
  double A[7], B[7];
  film_prims(p1, e, A);
  film_prims(p2, e, B);
  const double s1 = 1.0 / s;
  I->cc = (B[0] - A[0]) * s1 * s1 / rs;      /* s^{-5/2} */
  I->cs = (B[1] - A[1]) * s1 * s1;           /* s^{-2} */
  I->ss = (B[2] - A[2]) * s1 / rs;           /* s^{-3/2} */
  I->ccc = (B[3] - A[3]) * s1 * s1 * s1 / rs; /* s^{-7/2} */
  I->ccs = (B[4] - A[4]) * s1 * s1 * s1;     /* s^{-3} */
  I->css = (B[5] - A[5]) * s1 * s1 / rs;     /* s^{-5/2} */
  I->sss = (B[6] - A[6]) * s1 * s1;          /* s^{-2} */
}

/* Q M Qᵀ for a symmetric local M (fe_forces_impl.h). */
void whirl_fe_to_fixed(double ry, double rz, double a, double b, double d,
                       double sc, double J[4]) {
  const double ty = -rz, tz = ry;
  J[0] = sc * (a * ry * ry + 2.0 * b * ry * ty + d * ty * ty);
  J[1] = sc * (a * ry * rz + b * (ry * tz + ty * rz) + d * ty * tz);
  J[2] = J[1];
  J[3] = sc * (a * rz * rz + 2.0 * b * rz * tz + d * tz * tz);
}

/* The short-bearing film force at r with squeeze velocity w: f, ∂f/∂r (Jr)
 * and ∂f/∂w (Jw), on H = the full circle (full) or the half w·n > 0.  At
 * w = 0 the half-film force is not differentiable in w (it is positively
 * homogeneous); Jw is then its symmetric derivative, half the full film's. */
static int short_film(const whirl_fe_nl_params *p, const double r[2],
                      const double w[2], int full, double f[2], double Jr[4],
                      double Jw[4]) {
  const double c = p->clearance;
  const double y = r[0] / c, z = r[1] / c, e = sqrt(y * y + z * z);
  if (!(e < 1.0)) return WHIRL_EDOMAIN;
  const double ry = e > 0.0 ? y / e : 1.0, rz = e > 0.0 ? z / e : 0.0;
  const double wr = ry * w[0] + rz * w[1], wt = -rz * w[0] + ry * w[1];
  const int half_zero = !full && wr == 0.0 && wt == 0.0;
  film_int I;
  /* H = {θ: wr cos θ + wt sin θ > 0} = (β − π/2, β + π/2), β = arg w */
  film_integrals(e, atan2(wt, wr) - 0.5 * WHIRL_PI, full || half_zero, &I);
  const double K = p->viscosity * p->radius * pow(p->length, 3) / (c * c * c);
  const double fr = -K * (I.cc * wr + I.cs * wt);
  const double ft = -K * (I.cs * wr + I.ss * wt);
  f[0] = fr * ry - ft * rz;
  f[1] = fr * rz + ft * ry;
  if (Jw != NULL)
    whirl_fe_to_fixed(ry, rz, I.cc, I.cs, I.ss, half_zero ? -0.5 * K : -K, Jw);
  if (Jr != NULL) {
    const double a = wr * I.ccc + wt * I.ccs, b = wr * I.ccs + wt * I.css;
    const double d = wr * I.css + wt * I.sss;
    whirl_fe_to_fixed(ry, rz, a, b, d, -3.0 * K / c, Jr);
  }
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Short SFD, 2π film: H the full circle, w = v (Vance 1988; San
 * Andrés, Notes 13: F_r = 0, F_t = −πμRL³ ω ε/(c² s^{3/2}) on a circular
 * centred orbit). */
int whirl_fe_sfd_short_2pi(const whirl_fe_nl_params *p, const double r[2],
                           const double v[2], double f[2], double Jr[4],
                           double Jv[4]) {
  return short_film(p, r, v, 1, f, Jr, Jv);
}

/* ------------------------------------------------------------------------
 * Short plain journal bearing (Ocvirk 1952; Childs 1993; Vance 1988):
 * the journal spins at Ω, the housing is fixed.  The Couette term
 * (U/2) ∂h/∂x with U = ΩR adds −(Ω/2) r·t̂(φ) to −∂h/∂t = v·n, so the
 * squeeze velocity is w = v − (Ω/2) ẑ×r = (v_y + Ω r_z/2, v_z − Ω r_y/2)
 * (the familiar "ε̇, ε(γ̇ − Ω/2)"), with half-Sommerfeld cavitation: the
 * film where w·n > 0, boundaries that depend on r, v and Ω.  The static
 * solution (v = 0) is the classical short bearing, tan φ = π√s/(4ε).
 *   ∂f/∂r = ∂f/∂r|_w + ∂f/∂w ∂w/∂r,  ∂w/∂r = (Ω/2) [[0, 1], [−1, 0]]. */
int whirl_fe_journal_short(const whirl_fe_nl_params *p, const double r[2],
                           const double v[2], double Omega, double f[2],
                           double Jr[4], double Jv[4]) {
  const double h = 0.5 * Omega;
  const double w[2] = {v[0] + h * r[1], v[1] - h * r[0]};
  double Jw[4], Jx[4];
  int rc = short_film(p, r, w, 0, f, Jr != NULL ? Jx : NULL, Jw);
  if (rc != WHIRL_OK) return rc;
  if (Jr != NULL) {
    /* column y: Jw · (0, −h); column z: Jw · (h, 0) */
    Jr[0] = Jx[0] - h * Jw[2];
    Jr[1] = Jx[1] - h * Jw[3];
    Jr[2] = Jx[2] + h * Jw[0];
    Jr[3] = Jx[3] + h * Jw[1];
  }
  if (Jv != NULL)
    for (int i = 0; i < 4; ++i) Jv[i] = Jw[i];
  return WHIRL_OK;
}

/* rotor/fe_forces_sfd.c — the squeeze-film dampers with the conventional
 * π film (the film over the half θ ∈ (0, π) ahead of the line of centres,
 * as in paper eq. 8 and rotor/sfd.c): the long SFD with sealed ends and the
 * short SFD with fluid inertia, with exact Jacobians.  doc/rotor-forces.md
 * §3, §4.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>

#include <whirl/problem.h>
#include <whirl/rotor/fe.h>

#include "fe_forces_impl.h"

/* ------------------------------------------------------------------------
 * Long SFD, sealed ends, π film.  The long-bearing Reynolds equation
 * ∂_θ(h³ ∂_θ p) = −12 μ R² w·n (no axial flow) solved on θ ∈ (0, π) with
 * p = 0 at both ends (the π film of Vance 1988 and San Andrés, Notes
 * 13, whose circular-orbit forces it reproduces) gives, after an
 * integration by parts (f = RL ∫ ∂_θp (sin θ, −cos θ) dθ in (r̂, t̂)),
 * with K_L = 12 μ R³ L / c³, w_r = r̂·v = ė and w_t = t̂·v = eγ̇:
 *   F_r = −K_L (A w_r + B w_t),  F_t = −K_L (B w_r + C w_t),
 *   A = (π/2 − 8/(π(2+ε²))) s^{-3/2},  B = 2ε/(s(2+ε²)),
 *   C = π/(√s (2+ε²)),  s = 1 − ε².
 * In the fixed frame, with r̂r̂ᵀ = (I + R₂)/2, t̂t̂ᵀ = (I − R₂)/2 and
 * r̂t̂ᵀ + t̂r̂ᵀ = S₂ (R₂, S₂ the reflections by 2γ; dR₂/dγ = 2S₂,
 * dS₂/dγ = −2R₂, ∂γ/∂ρ = t̂/ε):
 *   f = −K_L [ (A+C)/2 w + (A−C)/2 R₂ w + B S₂ w ].
 * A − C → −4/π as ε → 0: the fixed π film is not isotropic at the centre
 * and f is discontinuous there (its direction average is returned at
 * ε = 0 exactly, with Jr = 0, as rotor/sfd.c does for its cross term). */

static void long_coeffs(double e, double k[6]) {
  const double e2 = e * e, s = (1.0 - e) * (1.0 + e), rs = sqrt(s);
  const double q2 = 2.0 + e2, g = 0.5 * WHIRL_PI - 8.0 / (WHIRL_PI * q2);
  const double q = s * q2, dq = -2.0 * e - 4.0 * e * e2, m = rs * q2;
  k[0] = g / (s * rs);                                     /* A */
  k[1] = 2.0 * e / q;                                      /* B */
  k[2] = WHIRL_PI / m;                                     /* C */
  k[3] = 3.0 * e * g / (s * s * rs) +                      /* dA/dε */
         16.0 * e / (WHIRL_PI * q2 * q2) / (s * rs);
  k[4] = (2.0 * q - 2.0 * e * dq) / (q * q);               /* dB/dε */
  k[5] = 3.0 * WHIRL_PI * e * e2 / (rs * m * m);           /* dC/dε */
}

int whirl_fe_sfd_long(const whirl_fe_nl_params *p, const double r[2],
                      const double v[2], double f[2], double Jr[4],
                      double Jv[4]) {
  const double c = p->clearance;
  const double y = r[0] / c, z = r[1] / c, e = sqrt(y * y + z * z);
  if (!(e < 1.0)) return WHIRL_EDOMAIN;
  const double K = 12.0 * p->viscosity * pow(p->radius, 3) * p->length /
                   (c * c * c);
  double k[6];
  long_coeffs(e, k);
  const double h = 0.5 * (k[0] + k[2]);
  if (e == 0.0) {
    f[0] = -K * h * v[0];
    f[1] = -K * h * v[1];
    whirl_fe_j2_zero(Jr);
    if (Jv != NULL) Jv[0] = Jv[3] = -K * h, Jv[1] = Jv[2] = 0.0;
    return WHIRL_OK;
  }
  const double ry = y / e, rz = z / e, ty = -rz, tz = ry;
  const double c2 = (ry - rz) * (ry + rz), s2 = 2.0 * ry * rz;
  const double Rw[2] = {c2 * v[0] + s2 * v[1], s2 * v[0] - c2 * v[1]};
  const double Sw[2] = {-s2 * v[0] + c2 * v[1], c2 * v[0] + s2 * v[1]};
  const double d = 0.5 * (k[0] - k[2]);
  f[0] = -K * (h * v[0] + d * Rw[0] + k[1] * Sw[0]);
  f[1] = -K * (h * v[1] + d * Rw[1] + k[1] * Sw[1]);
  if (Jv != NULL) {
    Jv[0] = -K * (h + d * c2 - k[1] * s2);
    Jv[1] = Jv[2] = -K * (d * s2 + k[1] * c2);
    Jv[3] = -K * (h - d * c2 + k[1] * s2);
  }
  if (Jr != NULL) {
    const double dh = 0.5 * (k[3] + k[5]), dd = 0.5 * (k[3] - k[5]);
    for (int i = 0; i < 2; ++i) {
      const double gr = dh * v[i] + dd * Rw[i] + k[4] * Sw[i]; /* along r̂ */
      const double gt = (2.0 * d * Sw[i] - 2.0 * k[1] * Rw[i]) / e; /* t̂ */
      Jr[i] = -K * (gr * ry + gt * ty) / c;
      Jr[i + 2] = -K * (gr * rz + gt * tz) / c;
    }
  }
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Short SFD, π film, with fluid inertia: the momentum-averaged (bulk-flow)
 * short film of San Andrés & Vance (1986, 1987) and San Andrés (Notes 13),
 * with the axial flow per unit width q = Z (v·n) (continuity) and
 *   −h ∂_Z p = 12 μ q/h + ρ (∂_t q + ∂_Z(q²/h)),
 * whose axial integral is
 *   ∫p dZ = μ L³ (v·n)/h³ + (ρ L³/12) [ (a·n)/h + 2 (v·n)²/h² ]
 * (a·n = −∂²h/∂t², the temporal term; 2(v·n)²/h², the convective term).
 * The viscous part is the short π film (rotor/sfd.c); the inertia part
 *   f_I = −(ρ R L³/12) ∫_γ^{γ+π} [ (a·n)/h + 2(v·n)²/h² ] n dφ
 * is integrated by Gauss–Legendre over panels graded towards θ = 0, where
 * the integrand's poles ±i acosh(1/ε) approach the real axis.  Its
 * Jacobians: Ja and Jv and the interior part of Jr differentiate under the
 * integral; the π-film ends move with γ (∂γ/∂r = t̂/|r|) and add
 * (F(γ+π) − F(γ)) t̂ᵀ/|r| to Jr.  At ρ = 0, f_I = −(πρRL³/(24c)) a (half
 * the 2π film's added mass πρRL³/(12c)).  The convective term of the fixed
 * π film is discontinuous at the centre (O(ρ_f |v|²/c²), direction
 * dependent): at ε = 0 exactly its direction average, zero, is returned. */

static const double gl16[8][2] = {
    {0.0950125098376374401, 0.1894506104550684962},
    {0.2816035507792589132, 0.1826034150449235888},
    {0.4580167776572273863, 0.1691565193950025381},
    {0.6178762444026437484, 0.1495959888165767320},
    {0.7554044083550030339, 0.1246289712555338720},
    {0.8656312023878317438, 0.0951585116824927848},
    {0.9445750230732325760, 0.0622535239386478928},
    {0.9894009349916499326, 0.0271524594117540948}};

/* ∫_0^π of the inertia integrands in the local basis: m = ∫ n nᵀ/D,
 * g = ∫ G² n/D², jv = ∫ G n nᵀ/D², jr = ∫ [A/(c²D²) + 4G²/(c³D³)] n nᵀ,
 * G = v_loc·n, A = a_loc·n, D = 1 − ε cos θ (sym. matrices as cc, cs, ss). */
typedef struct inertia_int {
  double m[3], g[2], jv[3], jr[3];
} inertia_int;

static void inertia_node(double th, double wq, double e, double c,
                         const double vl[2], const double al[2],
                         inertia_int *I) {
  const double ct = cos(th), st = sin(th), iD = 1.0 / (1.0 - e * ct);
  const double G = vl[0] * ct + vl[1] * st, A = al[0] * ct + al[1] * st;
  const double n[3] = {ct * ct, ct * st, st * st};
  const double g2 = G * G * iD * iD;
  const double wr = wq * (A * iD * iD / (c * c) + 4.0 * g2 * iD / (c * c * c));
  for (int k = 0; k < 3; ++k) {
    I->m[k] += wq * iD * n[k];
    I->jv[k] += wq * G * iD * iD * n[k];
    I->jr[k] += wr * n[k];
  }
  I->g[0] += wq * g2 * ct;
  I->g[1] += wq * g2 * st;
}

static void inertia_integrals(double e, double c, const double vl[2],
                              const double al[2], inertia_int *I) {
  *I = (inertia_int){{0, 0, 0}, {0, 0}, {0, 0, 0}, {0, 0, 0}};
  const double d = e > 0.0 ? acosh(1.0 / e) : INFINITY; /* pole distance */
  double lo = 0.0, hi = fmin(2.0 * d, WHIRL_PI);
  for (;;) {
    const double m = 0.5 * (lo + hi), hl = 0.5 * (hi - lo);
    for (int k = 0; k < 8; ++k) {
      inertia_node(m - hl * gl16[k][0], hl * gl16[k][1], e, c, vl, al, I);
      inertia_node(m + hl * gl16[k][0], hl * gl16[k][1], e, c, vl, al, I);
    }
    if (hi >= WHIRL_PI) break;
    lo = hi;
    hi = fmin(2.0 * hi, WHIRL_PI);
  }
}

int whirl_fe_sfd_inertia(const whirl_fe_nl_params *p, const double r[2],
                         const double v[2], const double a[2], double f[2],
                         double Jr[4], double Jv[4], double Ja[4]) {
  double fv[2], Jrv[4], Jvv[4];
  int rc = whirl_fe_sfd_short_pi(p, r, v, fv, Jrv, Jvv);
  if (rc != WHIRL_OK) return rc;
  const double c = p->clearance, e = sqrt(r[0] * r[0] + r[1] * r[1]) / c;
  const double ry = e > 0.0 ? r[0] / (c * e) : 1.0;
  const double rz = e > 0.0 ? r[1] / (c * e) : 0.0;
  const double vl[2] = {ry * v[0] + rz * v[1], -rz * v[0] + ry * v[1]};
  const double al[2] = {ry * a[0] + rz * a[1], -rz * a[0] + ry * a[1]};
  inertia_int I;
  inertia_integrals(e, c, vl, al, &I);
  if (e == 0.0) /* the direction averages at the centre */
    I.g[0] = I.g[1] = I.jv[0] = I.jv[1] = I.jv[2] = I.jr[0] = I.jr[1] =
        I.jr[2] = 0.0;
  const double kI = p->density * p->radius * pow(p->length, 3) / 12.0;
  const double Fr = -kI * ((I.m[0] * al[0] + I.m[1] * al[1]) / c + 2.0 * I.g[0] / (c * c));
  const double Ft = -kI * ((I.m[1] * al[0] + I.m[2] * al[1]) / c + 2.0 * I.g[1] / (c * c));
  f[0] = fv[0] + Fr * ry - Ft * rz;
  f[1] = fv[1] + Fr * rz + Ft * ry;
  if (Ja != NULL) whirl_fe_to_fixed(ry, rz, I.m[0], I.m[1], I.m[2], -kI / c, Ja);
  if (Jv != NULL) {
    whirl_fe_to_fixed(ry, rz, I.jv[0], I.jv[1], I.jv[2], -4.0 * kI / (c * c), Jv);
    for (int i = 0; i < 4; ++i) Jv[i] += Jvv[i];
  }
  if (Jr != NULL) {
    whirl_fe_to_fixed(ry, rz, I.jr[0], I.jr[1], I.jr[2], -kI, Jr);
    for (int i = 0; i < 4; ++i) Jr[i] += Jrv[i];
    if (e > 0.0) { /* the moving ends: (F(γ+π) − F(γ)) t̂ᵀ/|r|, along r̂ */
      const double s = (1.0 - e) * (1.0 + e);
      const double dF = kI * (al[0] * 2.0 * e / (c * s) +
                              4.0 * (1.0 + e * e) * vl[0] * vl[0] / (c * c * s * s));
      const double q = dF / (c * e), ty = -rz, tz = ry;
      Jr[0] += q * ry * ty;
      Jr[1] += q * rz * ty;
      Jr[2] += q * ry * tz;
      Jr[3] += q * rz * tz;
    }
  }
  return WHIRL_OK;
}

/* rotor/fe_forces.c — the forces of the nonlinear elements of
 * finite-element rotors (whirl/rotor/fe.h): argument and parameter checks,
 * the dispatch by kind, the short π-film SFD (paper eq. 8, through
 * rotor/sfd.c), the cubic spring and the radial rub.  The other film
 * elements are in rotor/fe_forces_film.c; doc/rotor-forces.md gives every
 * formula with its reference.  SI units, dimensional forces on the journal.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>

#include <whirl/problem.h>
#include <whirl/rotor/fe.h>
#include <whirl/rotor/sfd.h>

#include "fe_forces_impl.h"

/* ------------------------------------------------------------------------
 * Small 2×2 helpers (column-major, J[i + 2j]). */

void whirl_fe_j2_zero(double J[4]) {
  if (J != NULL) J[0] = J[1] = J[2] = J[3] = 0.0;
}

/* ------------------------------------------------------------------------
 * Parameters.  Film elements need R, L, c, μ > 0 (and ρ ≥ 0 with fluid
 * inertia); the rub a gap c ≥ 0, k_contact > 0, friction ≥ 0, radius ≥ 0;
 * the cubic spring finite k1, k3 (softening springs are allowed). */

static int pos(double x) { return isfinite(x) && x > 0.0; }
static int nonneg(double x) { return isfinite(x) && x >= 0.0; }

static int film_params_ok(const whirl_fe_nl_params *p) {
  return pos(p->radius) && pos(p->length) && pos(p->clearance) &&
         pos(p->viscosity);
}

static int params_ok(const whirl_fe_nl *e) {
  const whirl_fe_nl_params *p = &e->par;
  switch (e->kind) {
  case WHIRL_FE_SFD_SHORT_PI:
  case WHIRL_FE_SFD_SHORT_2PI:
  case WHIRL_FE_SFD_LONG:
  case WHIRL_FE_JOURNAL_SHORT:
    return film_params_ok(p);
  case WHIRL_FE_SFD_INERTIA:
    return film_params_ok(p) && nonneg(p->density);
  case WHIRL_FE_RUB:
    return nonneg(p->clearance) && pos(p->k_contact) && nonneg(p->friction) &&
           nonneg(p->radius);
  case WHIRL_FE_CUBIC:
    return isfinite(p->k1) && isfinite(p->k3);
  }
  return 0;
}

/* ------------------------------------------------------------------------
 * Short SFD, π film: paper eq. 8 (Vance 1988; San Andrés, Notes 13),
 *   F_r = −(μRL³/c²) [A ε̇ + B εγ̇],  F_t = −(μRL³/c²) [B ε̇ + C εγ̇],
 * the film taken over the half θ ∈ (0, π) ahead of the line of centres.
 * rotor/sfd.c computes −2λ[...] in ε, ε' units; with λ = 1/2 and the rates
 * ε̇ = ė/c in 1/s its result times μRL³/c² is the force in N, and
 * d/dr = (1/c) d/dε. */

int whirl_fe_sfd_short_pi(const whirl_fe_nl_params *p, const double r[2],
                          const double v[2], double f[2], double Jr[4],
                          double Jv[4]) {
  const double c = p->clearance;
  const double k = p->viscosity * p->radius * pow(p->length, 3) / (c * c);
  double fn[2], Jn[8];
  int rc = whirl_sfd_force(r[0] / c, r[1] / c, v[0] / c, v[1] / c, 0.5, fn,
                           (Jr != NULL || Jv != NULL) ? Jn : NULL, NULL);
  if (rc == WHIRL_SFD_CONTACT) return WHIRL_EDOMAIN;
  if (rc != WHIRL_OK) return WHIRL_EINVAL;
  f[0] = k * fn[0];
  f[1] = k * fn[1];
  for (int i = 0; i < 4; ++i) {
    if (Jr != NULL) Jr[i] = k * Jn[i] / c;
    if (Jv != NULL) Jv[i] = k * Jn[4 + i] / c;
  }
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Cubic spring f = −(k1 + k3 |r|²) r, Jr = −(k1 + k3|r|²) I − 2 k3 r rᵀ. */

static void cubic(const whirl_fe_nl_params *p, const double r[2], double f[2],
                  double Jr[4]) {
  const double s = p->k1 + p->k3 * (r[0] * r[0] + r[1] * r[1]);
  f[0] = -s * r[0];
  f[1] = -s * r[1];
  if (Jr == NULL) return;
  Jr[0] = -s - 2.0 * p->k3 * r[0] * r[0];
  Jr[1] = -2.0 * p->k3 * r[1] * r[0];
  Jr[2] = Jr[1];
  Jr[3] = -s - 2.0 * p->k3 * r[1] * r[1];
}

/* ------------------------------------------------------------------------
 * Radial rub (Childs 1993; Muszynska 2005), not smoothed.  With
 * ρ = |r|, r̂ = r/ρ, t̂ = (−r̂_z, r̂_y) (the direction of +Ω rotation) and
 * the penetration δ = ρ − c > 0, the normal force N = k_contact δ and the
 * Coulomb friction μ_f N oppose the penetration and the sliding of the
 * shaft surface on the stator:
 *   f = −N r̂ − μ_f N sgn(u) t̂,   u = t̂·v + R Ω,
 * u the tangential velocity of the shaft's surface point at the contact
 * (whirl plus spin; R the radius, Ω > 0 counter-clockwise from y to z).
 * sgn(0) = 0.  f is continuous in r (its Jacobian jumps at ρ = c) and
 * jumps in v where u changes sign; Jv = 0 and Jr is the derivative at
 * fixed sgn(u), exact away from ρ = c and u = 0. */

static void rub(const whirl_fe_nl_params *p, const double r[2],
                const double v[2], double Omega, double f[2], double Jr[4]) {
  const double rho = sqrt(r[0] * r[0] + r[1] * r[1]);
  const double d = rho - p->clearance;
  f[0] = f[1] = 0.0;
  whirl_fe_j2_zero(Jr);
  if (!(d > 0.0)) return;
  const double ry = r[0] / rho, rz = r[1] / rho, ty = -rz, tz = ry;
  const double u = ty * v[0] + tz * v[1] + p->radius * Omega;
  const double sg = (u > 0.0) - (u < 0.0);
  const double k = p->k_contact, m = p->friction * sg;
  f[0] = -k * d * (ry + m * ty);
  f[1] = -k * d * (rz + m * tz);
  if (Jr == NULL) return;
  /* d(δ r̂)/dr = r̂r̂ᵀ + w t̂t̂ᵀ, d(δ t̂)/dr = t̂r̂ᵀ − w r̂t̂ᵀ, w = δ/ρ */
  const double w = d / rho;
  const double Pa[4] = {ry * ry + w * ty * ty, rz * ry + w * tz * ty,
                        ry * rz + w * ty * tz, rz * rz + w * tz * tz};
  const double Pb[4] = {ty * ry - w * ry * ty, tz * ry - w * rz * ty,
                        ty * rz - w * ry * tz, tz * rz - w * rz * tz};
  for (int i = 0; i < 4; ++i) Jr[i] = -k * (Pa[i] + m * Pb[i]);
}

/* ------------------------------------------------------------------------
 * The dispatch. */

static int args_ok(const whirl_fe_nl *e, const double r[2], const double v[2],
                   const double a[2], double Omega, const double f[2]) {
  if (e == NULL || r == NULL || v == NULL || f == NULL) return 0;
  if (!isfinite(r[0]) || !isfinite(r[1]) || !isfinite(v[0]) ||
      !isfinite(v[1]) || !isfinite(Omega))
    return 0;
  if (e->kind == WHIRL_FE_SFD_INERTIA &&
      (a == NULL || !isfinite(a[0]) || !isfinite(a[1])))
    return 0;
  return 1;
}

/* The force of each kind; Ja is written by the fluid-inertia SFD only. */
static int nl_force(const whirl_fe_nl *e, const double r[2], const double v[2],
                    const double a[2], double Omega, double f[2], double Jr[4],
                    double Jv[4], double Ja[4]) {
  const whirl_fe_nl_params *p = &e->par;
  switch (e->kind) {
  case WHIRL_FE_SFD_SHORT_PI:
    return whirl_fe_sfd_short_pi(p, r, v, f, Jr, Jv);
  case WHIRL_FE_SFD_SHORT_2PI:
    return whirl_fe_sfd_short_2pi(p, r, v, f, Jr, Jv);
  case WHIRL_FE_SFD_LONG:
    return whirl_fe_sfd_long(p, r, v, f, Jr, Jv);
  case WHIRL_FE_SFD_INERTIA:
    return whirl_fe_sfd_inertia(p, r, v, a, f, Jr, Jv, Ja);
  case WHIRL_FE_JOURNAL_SHORT:
    return whirl_fe_journal_short(p, r, v, Omega, f, Jr, Jv);
  case WHIRL_FE_RUB:
    rub(p, r, v, Omega, f, Jr);
    whirl_fe_j2_zero(Jv);
    return WHIRL_OK;
  case WHIRL_FE_CUBIC:
    cubic(p, r, f, Jr);
    whirl_fe_j2_zero(Jv);
    return WHIRL_OK;
  }
  return WHIRL_EINVAL;
}

int whirl_fe_nl_force(const whirl_fe_nl *e, const double r[2],
                      const double v[2], const double a[2], double Omega,
                      double f[2], double Jr[4], double Jv[4], double Ja[4]) {
  if (!args_ok(e, r, v, a, Omega, f) || !params_ok(e)) return WHIRL_EINVAL;
  int rc = nl_force(e, r, v, a, Omega, f, Jr, Jv, Ja);
  if (rc == WHIRL_OK && e->kind != WHIRL_FE_SFD_INERTIA) whirl_fe_j2_zero(Ja);
  return rc;
}

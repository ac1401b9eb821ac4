/* sfd.c — AUTO-07p equation file for whirl's speed comparison: synchronous
 * circular orbits of the rigid rotor on two short π-film squeeze-film
 * dampers (shared/DESIGN.md, "The SFD rotor model"), as equilibria of the
 * rotating-frame ODE, w = u + iv, state U = (u, v, u', v'):
 *   w'' + 2iΩw' − Ω²w + 2ζ(w' + iΩw) + w = δΩ² + f(w, w' + iΩw).
 * PAR(1) = Ω, PAR(2) = λ, PAR(3) = δ, PAR(4) = ζ; PAR(5) = ε = |w| is an
 * output measure set in PVLS (never a continuation parameter).
 * The start point comes from the constants (U, PAR) written by
 * run_sfd.py from eq. 15 of the paper; STPNT only sets Table 1.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "auto_f2c.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* π-film force of both dampers at position (x, y), velocity (vx, vy).
 * ε >= 1 is contact with the housing: the force is set to NaN, so AUTO's
 * Newton fails there instead of continuing a meaningless solution. */
static void sfd_force(double x, double y, double vx, double vy, double lam,
                      double *fx, double *fy)
{
  const double e = hypot(x, y);
  double rx, ry, er, et, s, fr, ft;
  if (e >= 1.0) {
    *fx = *fy = NAN;
    return;
  }
  if (e == 0.0) { /* limit ε -> 0: f = −πλ v */
    *fx = -M_PI * lam * vx;
    *fy = -M_PI * lam * vy;
    return;
  }
  rx = x / e; /* r̂ = (rx, ry), t̂ = (−ry, rx) */
  ry = y / e;
  er = rx * vx + ry * vy;  /* ε'  */
  et = -ry * vx + rx * vy; /* εγ' */
  s = 1.0 - e * e;
  fr = -2.0 * lam * (0.5 * M_PI * (1.0 + 2.0 * e * e) / pow(s, 2.5) * er
                     + 2.0 * e / (s * s) * et);
  ft = -2.0 * lam * (2.0 * e / (s * s) * er + 0.5 * M_PI / pow(s, 1.5) * et);
  *fx = fr * rx - ft * ry;
  *fy = fr * ry + ft * rx;
}

int func(integer ndim, const doublereal *u, const integer *icp,
         const doublereal *par, integer ijac, doublereal *f,
         doublereal *dfdu, doublereal *dfdp)
{
  const double om = par[0], lam = par[1], dl = par[2], z = par[3];
  const double x = u[0], y = u[1], p = u[2], q = u[3];
  double fx, fy;
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp;
  /* fixed-frame velocity seen in the rotating frame: w' + iΩw */
  sfd_force(x, y, p - om * y, q + om * x, lam, &fx, &fy);
  f[0] = p;
  f[1] = q;
  f[2] = 2.0 * om * q + om * om * x - 2.0 * z * (p - om * y) - x
         + dl * om * om + fx;
  f[3] = -2.0 * om * p + om * om * y - 2.0 * z * (q + om * x) - y + fy;
  return 0;
}

int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
  const double om = 0.01, lam = 0.0503, dl = 0.3;
  /* linear approximation w = δΩ² / (1 − Ω² + iπλΩ); exact start point
   * from the constants U, PAR (run_sfd.py) overrides it */
  const double re = 1.0 - om * om, im = M_PI * lam * om;
  const double d = re * re + im * im;
  (void)ndim; (void)t;
  par[0] = om;  /* Ω */
  par[1] = lam; /* λ (Table 1) */
  par[2] = dl;  /* δ (Table 1) */
  par[3] = 0.0; /* ζ */
  par[4] = 0.0; /* ε, output only */
  u[0] = dl * om * om * re / d;
  u[1] = -dl * om * om * im / d;
  u[2] = 0.0;
  u[3] = 0.0;
  return 0;
}

/* Not used for equilibria; AUTO links them anyway. */
int bcnd(integer ndim, const doublereal *par, const integer *icp,
         integer nbc, const doublereal *u0, const doublereal *u1,
         integer ijac, doublereal *f, doublereal *dbc)
{
  (void)ndim; (void)par; (void)icp; (void)nbc; (void)u0; (void)u1;
  (void)ijac; (void)f; (void)dbc;
  return 0;
}

int icnd(integer ndim, const doublereal *par, const integer *icp,
         integer nint, const doublereal *u, const doublereal *uold,
         const doublereal *udot, const doublereal *upold, integer ijac,
         doublereal *fi, doublereal *dint)
{
  (void)ndim; (void)par; (void)icp; (void)nint; (void)u; (void)uold;
  (void)udot; (void)upold; (void)ijac; (void)fi; (void)dint;
  return 0;
}

int fopt(integer ndim, const doublereal *u, const integer *icp,
         const doublereal *par, integer ijac, doublereal *fs,
         doublereal *dfdu, doublereal *dfdp)
{
  (void)ndim; (void)u; (void)icp; (void)par; (void)ijac; (void)fs;
  (void)dfdu; (void)dfdp;
  return 0;
}

/* Output measure: PAR(5) = ε = |w|, the orbit radius / clearance. */
int pvls(integer ndim, const doublereal *u, doublereal *par)
{
  (void)ndim;
  par[4] = hypot(u[0], u[1]);
  return 0;
}

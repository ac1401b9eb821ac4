/* nonsync.c — AUTO-07p equation file for whirl's speed comparison: the
 * nonsynchronous response of the rigid rotor on two short π-film
 * squeeze-film dampers (shared/DESIGN.md, "The SFD rotor model"; paper
 * §5.2) as a periodic orbit (IPS = 2) of the autonomous rotating-frame ODE,
 * w = u + iv, state U = (u, v, u', v'):
 *   w'' + 2iΩw' − Ω²w + 2ζ(w' + iΩw) + w = δΩ² + f(w, w' + iΩw).
 * The right-hand side is the one of ../sfd/sfd.c (equilibria benchmark).
 * PAR(1) = Ω, PAR(2) = λ, PAR(3) = δ, PAR(4) = ζ; PAR(11) = T, the period
 * in the rotating frame (AUTO's convention for IPS = 2).  PAR(5) = Ω − 8.59
 * is an output measure set in PVLS (never a continuation parameter): AUTO
 * prints 11 significant digits, so Ω itself only to ~1e-10, Ω − 8.59 near
 * the fold (≈ 6.7e-5) to ~1e-15.
 * The start orbit comes from the data file nonsync.dat (constant dat,
 * written by start_orbit.c); AUTO sets PAR(11) from its time column before
 * calling STPNT, so STPNT sets only Table 1 and leaves PAR(11) alone.
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

/* Called once, after AUTO has read nonsync.dat and set PAR(11) = T; the
 * state u is not used (the orbit comes from the data file).  PAR(1) = Ω is
 * also set in the constants (PAR = {1: 8.7}), which take precedence. */
int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
  (void)ndim; (void)t; (void)u;
  par[0] = 8.7;    /* Ω of the start orbit */
  par[1] = 0.0503; /* λ (Table 1) */
  par[2] = 0.3;    /* δ (Table 1) */
  par[3] = 0.0;    /* ζ */
  par[4] = 0.0;    /* Ω − 8.59, output only */
  return 0;
}

/* Periodic boundary conditions and the phase condition are AUTO's own
 * (IPS = 2, NBC = NINT = 0); AUTO links these anyway. */
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

/* Output measure: PAR(5) = Ω − 8.59, to read the fold of cycles with more
 * digits than AUTO prints for Ω (the b-file's E format). */
int pvls(integer ndim, const doublereal *u, doublereal *par)
{
  (void)ndim; (void)u;
  par[4] = par[0] - 8.59;
  return 0;
}

/* ab.c — equation file for AUTO-07p: the A -> B reaction in a CSTR
 * (AUTO-07p demo 'ab', written for whirl's reference tests).
 *   u1' = -u1 + D (1 - u1) exp(u2)
 *   u2' = -u2 + B D (1 - u1) exp(u2) - beta u2
 * PAR(1) = D (Damkoehler number), PAR(2) = B, PAR(3) = beta.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "auto_f2c.h"

int func(integer ndim, const doublereal *u, const integer *icp,
         const doublereal *par, integer ijac, doublereal *f,
         doublereal *dfdu, doublereal *dfdp)
{
  const double x = u[0], y = u[1];
  const double d = par[0], b = par[1], beta = par[2];
  const double r = d * (1.0 - x) * exp(y); /* reaction rate */
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp;
  f[0] = -x + r;
  f[1] = -y + b * r - beta * y;
  return 0;
}

int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
  (void)ndim; (void)t;
  par[0] = 0.0; /* D */
  par[1] = 8.0; /* B */
  par[2] = 3.0; /* beta */
  u[0] = 0.0;
  u[1] = 0.0;
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

int pvls(integer ndim, const doublereal *u, doublereal *par)
{
  (void)ndim; (void)u; (void)par;
  return 0;
}

/* cusp.c — equation file for AUTO-07p: the cusp normal form
 * (AUTO-07p demo 'cusp', written for whirl's reference tests).
 *   x' = mu + lambda x - x^3,   PAR(1) = lambda, PAR(2) = mu.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "auto_f2c.h"

int func(integer ndim, const doublereal *u, const integer *icp,
         const doublereal *par, integer ijac, doublereal *f,
         doublereal *dfdu, doublereal *dfdp)
{
  const double x = u[0], lambda = par[0], mu = par[1];
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp;
  f[0] = mu + lambda * x - x * x * x;
  return 0;
}

int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
  (void)ndim; (void)t;
  par[0] = 1.0; /* lambda */
  par[1] = 0.0; /* mu */
  u[0] = 0.0;
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

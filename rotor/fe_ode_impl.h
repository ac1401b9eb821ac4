/* rotor/fe_ode_impl.h — inside the first-order model of an FE rotor
 * (whirl/rotor/fe_ode.h; not installed): the object, shared by the
 * right-hand side (fe_ode.c) and the Jacobians (fe_ode_jac.c).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_ODE_IMPL_H
#define WHIRL_ROTOR_FE_ODE_IMPL_H

#include <whirl/linsol.h>
#include <whirl/rotor/fe_ode.h>

struct whirl_fe_ode {
  const whirl_fe_rotor *r;
  whirl_problem prob;
  int nd, m;          /* ndof; nonlinear DOFs S (sorted, unique) */
  int *dof;           /* S, m */
  int (*epos)[4];     /* element e's (y, z, ped y, ped z) positions in S, −1 */
  whirl_fe_nl *el;    /* the elements with the parameters' scales */
  int inertia;        /* some element has fluid inertia */
  whirl_linsol *lsM;  /* LU of M */
  whirl_linsol *lsX;  /* LU of I − Ja_S W_S (dense m×m) */
  double *W;          /* M⁻¹ E, nd×m */
  double *R, *a;      /* the forces and the acceleration, nd */
  double *JaS, *JrS, *JvS, *X, *y; /* m×m; y: m×nd scratch */
  double *MiK, *MiC, *MiG; /* M⁻¹K, M⁻¹C, M⁻¹G, nd×nd, at the first jac */
  double *Jd;         /* sparse fill: the dense Jacobian, n×n */
  int *Jp, *Ji;       /* sparse pattern */
  size_t nnz;
  int *Gp, *Gi;       /* the mass-matrix form's G pattern (fe_ode_mass.c) */
  size_t gnnz;
  double *Gw;         /* its column work vector, 2nd */
  char err[256];
};

/* The acceleration of state z at (t, p) into m->a, the assembled element
 * Jacobians Ja_S (with_jac: also Jr_S, Jv_S at that acceleration) and the
 * factor of I − Ja_S W_S.  0, or 1 when a journal reaches a clearance,
 * < 0 on a failed factorisation. */
int fe_ode_accel(whirl_fe_ode *m, double t, const double *z, const double *p,
                 int with_jac);
/* Y[nd×ncol] (leading dimension ld) ← M_eff⁻¹ M Y, i.e. apply the
 * Woodbury correction to columns already multiplied by M⁻¹. */
int fe_ode_woodbury(whirl_fe_ode *m, double *Y, size_t ld, int ncol);
int fe_ode_jac_dense(double t, const double *z, const double *p, double *J,
                     void *data);

#endif

/* rotor/fe_forces_impl.h — internal: the film forces of rotor/fe_forces.c,
 * rotor/fe_forces_film.c and rotor/fe_forces_sfd.c, called by the dispatch
 * of rotor/fe_forces.c (whirl_fe_nl_force).  Each writes f[2] and the
 * Jacobians that are not NULL (column-major 2×2), or returns WHIRL_EDOMAIN
 * for |r| ≥ c with nothing written.  The parameters are checked by the
 * caller.  Not installed.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_FORCES_IMPL_H
#define WHIRL_ROTOR_FE_FORCES_IMPL_H

#include <whirl/rotor/fe.h>

void whirl_fe_j2_zero(double J[4]); /* J = 0 (J may be NULL) */

/* Q M Qᵀ times sc for a symmetric M = [[a, b], [b, d]] in the basis
 * Q = [r̂ t̂], r̂ = (ry, rz), t̂ = (−rz, ry): J column-major. */
void whirl_fe_to_fixed(double ry, double rz, double a, double b, double d,
                       double sc, double J[4]);

int whirl_fe_sfd_short_pi(const whirl_fe_nl_params *p, const double r[2],
                          const double v[2], double f[2], double Jr[4],
                          double Jv[4]);
int whirl_fe_sfd_short_2pi(const whirl_fe_nl_params *p, const double r[2],
                           const double v[2], double f[2], double Jr[4],
                           double Jv[4]);
int whirl_fe_sfd_long(const whirl_fe_nl_params *p, const double r[2],
                      const double v[2], double f[2], double Jr[4],
                      double Jv[4]);
int whirl_fe_sfd_inertia(const whirl_fe_nl_params *p, const double r[2],
                         const double v[2], const double a[2], double f[2],
                         double Jr[4], double Jv[4], double Ja[4]);
int whirl_fe_journal_short(const whirl_fe_nl_params *p, const double r[2],
                           const double v[2], double Omega, double f[2],
                           double Jr[4], double Jv[4]);

#endif

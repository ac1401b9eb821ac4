/* drivers/rotor_time.h — what `whirl rotor simulate` and `whirl rotor
 * basins` share: the integrator of an FE rotor (whirl/rotor/fe_ode.h) at a
 * speed, and the initial state of a displaced shaft.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_TIME_H
#define WHIRL_ROTOR_TIME_H

#include <whirl/rotor/fe_ode.h>

#include "rotor_cli.h"

/* An integrator of m at p (whirl_fe_hbm_params layout) with the method
 * (WHIRL_ODE_BDF: the mass matrix on the left, KLU; whirl_fe_ode_use_mass)
 * and tolerances; NULL with a message and *exit_code 2 when the
 * tolerances are bad, 1 when out of memory or the BDF cannot be set up
 * (SUNDIALS not loaded). */
whirl_ode *rotor_time_ode(const char *cmd, whirl_fe_ode *m, const double *p,
                          int method, double rtol, double atol, int *exit_code);

/* The state z[2 ndof] of the shaft translated rigidly by (y0, z0) (every
 * node's y, z; pedestals and rotations 0), at rest. */
void rotor_time_start(const whirl_fe_rotor *r, double y0, double z0, double *z);

/* 0 when the start z0 lies inside every film's clearance, else 2 with
 * "the initial displacement is outside the clearance ..." printed. */
int rotor_time_inside(const char *cmd, whirl_fe_ode *m, const double *p,
                      const double *z0);

/* --node: K when given (K ≥ 0), else the node of the first nonlinear
 * element (0 without any); −1 with a message when K is not a node. */
int rotor_time_node(const char *cmd, const whirl_fe_rotor *r, int node);

/* The smallest clearance of the film elements, or 0. */
double rotor_time_clearance(const whirl_fe_rotor *r);

#endif

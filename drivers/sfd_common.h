/* drivers/sfd_common.h — pieces shared by the SFD time-domain commands
 * (simulate, sweep, basins, onset): the character of a steady state from
 * its Poincaré points, and the SFD parameter options.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SFD_COMMON_H
#define WHIRL_SFD_COMMON_H

#include <stddef.h>

/* Character of a steady state from npts stroboscopic points P[npts*4] (time
 * order) and the spread of ε over the last period (max − min):
 * "circular" (one point, constant ε), "periodic" (k points; *period = k),
 * "quasiperiodic" (points on a closed curve), "irregular" (area-filling),
 * or "transient" (points still converging: successive distances shrink by
 * more than 1e3 over the record). */
const char *sfd_steady_class(const double *P, size_t npts, double eps_spread,
                             size_t *period, double *dimension);

/* Check the SFD parameter vector and print a message naming the option. */
int sfd_check(const char *cmd, const double *p);

/* Check --rtol/--atol against the library's limits (whirl/basins.h) and
 * print a message naming the option; 0 if they are usable, -1 if not. */
int sfd_check_tolerances(const char *cmd, double rtol, double atol);

#endif

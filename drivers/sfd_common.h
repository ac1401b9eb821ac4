/* drivers/sfd_common.h — pieces shared by the SFD commands: the model's
 * parameters as options, their checks and their text in titles, and the
 * names of the classes of a steady state (simulate, sweep).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SFD_COMMON_H
#define WHIRL_SFD_COMMON_H

#include <stddef.h>

#include <whirl/section.h>
#include <whirl/rotor.h>

#include "cli.h"

/* The SFD model's parameters as entries of a command's option table
 * (cli_opt initialisers, in the order the command's --help lists them).  P
 * is the command's parameter vector, filled by whirl_sfd_default_params:
 * its values are the defaults --help shows.  The ranges are those of
 * whirl_sfd_check_params (whirl/rotor/sfd.h), which sfd_check applies. */
#define SFD_OPT_PARAM(p, k, name, arg, help)                                  \
  { name, CLI_DOUBLE, &(p)[k], arg, help, NULL }
#define SFD_OPT_OMEGA(p)                                                      \
  SFD_OPT_PARAM(p, WHIRL_SFD_OMEGA, "--omega", "W",                           \
                "dimensionless speed Omega, 0 < W <= 1000")
#define SFD_OPT_LAMBDA(p)                                                     \
  SFD_OPT_PARAM(p, WHIRL_SFD_LAMBDA, "--lambda", "L",                         \
                "SFD constant lambda, 0 < L <= 100")
#define SFD_OPT_DELTA(p)                                                      \
  SFD_OPT_PARAM(p, WHIRL_SFD_DELTA, "--delta", "D",                           \
                "unbalance delta = e_G/c, 0 <= D <= 10")
#define SFD_OPT_ZETA(p)                                                       \
  SFD_OPT_PARAM(p, WHIRL_SFD_ZETA, "--zeta", "Z",                             \
                "external damping ratio zeta, 0 <= Z <= 10")
#define SFD_OPT_FE(p)                                                         \
  SFD_OPT_PARAM(p, WHIRL_SFD_FE, "--fe", "F",                                 \
                "static force F_E (gravity not fully compensated by the "     \
                "centring springs; static deflection F_E), |F| < 1")
/* lambda, delta, zeta: the model of Table 1 */
#define SFD_OPTS_MODEL(p) SFD_OPT_LAMBDA(p), SFD_OPT_DELTA(p), SFD_OPT_ZETA(p)

/* --y0 --z0 --vy0 --vz0: the initial state x0[4] of a time integration */
#define SFD_OPTS_STATE(x0)                                                    \
  {"--y0", CLI_DOUBLE, &(x0)[0], "A", "initial displacement y / clearance",   \
   NULL},                                                                     \
  {"--z0", CLI_DOUBLE, &(x0)[1], "B", "initial displacement z / clearance",   \
   NULL},                                                                     \
  {"--vy0", CLI_DOUBLE, &(x0)[2], "C", "initial velocity y'", NULL},          \
  {"--vz0", CLI_DOUBLE, &(x0)[3], "D", "initial velocity z'", NULL}

/* --rtol, --atol of the time integrations (limits: whirl/basins.h, checked
 * by sfd_check_tolerances). */
#define SFD_OPTS_TOL(rtol, atol)                                              \
  {"--rtol", CLI_DOUBLE, &(rtol), "R",                                        \
   "relative integration tolerance, 1e-13 <= R <= 1e-3", NULL},               \
  {"--atol", CLI_DOUBLE, &(atol), "A",                                        \
   "absolute integration tolerance, 0 < A <= 1e-3", NULL}

/* The class of a steady state as the SFD commands name it: a fixed point
 * of the stroboscopic map is "circular" when the eccentricity is constant
 * over a period (its spread max - min below 1e-6), else "periodic";
 * "quasiperiodic", "irregular"; "transient" for points still converging or
 * moving away (not settled yet). */
const char *sfd_steady_name(whirl_steady_kind kind, double eps_spread);

/* The class (sfd_steady_name) of the steady state sampled by npts
 * stroboscopic points P[npts*4] (time order; whirl_steady_classify with
 * tolerance 1e-6 and periods up to 16), eps_spread the spread of the
 * eccentricity over the last period; *period (1 for a fixed point),
 * *dimension as there.  NULL, with the message printed, when the points
 * cannot be classified (out of memory). */
const char *sfd_steady_class(const char *cmd, const double *P, size_t npts,
                             double eps_spread, size_t *period,
                             double *dimension);

/* Check a command's SFD parameters p[WHIRL_SFD_NPAR] (the options above)
 * and print a message naming the parameter; 0 if they are usable, -1 if
 * not.  A NaN is an option that is required and was not given.  With
 * OMEGA_OPTION, p[WHIRL_SFD_OMEGA] is the option --omega and must be > 0;
 * otherwise the command puts there the largest speed it reaches (response
 * --omega-max, the top of a sweep), checked against the model's range
 * only.  Then the model's ranges: whirl_sfd_check_params. */
int sfd_check(const char *cmd, const double *p, int omega_option);

/* The parameters p[k] of the bits SFD_P(k) of MASK, in whirl/rotor/sfd.h's order,
 * as text for a gnuplot title: "{/Symbol l} = 0.0503, {/Symbol d} = 0.3,
 * {/Symbol z} = 0" for SFD_P_MODEL.  Returns buf. */
#define SFD_P(k) (1u << (k))
#define SFD_P_MODEL                                                           \
  (SFD_P(WHIRL_SFD_LAMBDA) | SFD_P(WHIRL_SFD_DELTA) | SFD_P(WHIRL_SFD_ZETA))
const char *sfd_gp_params(char *buf, size_t len, const double *p, unsigned mask);

/* Check --rtol/--atol against the library's limits (whirl/basins.h) and
 * print a message naming the option; 0 if they are usable, -1 if not. */
int sfd_check_tolerances(const char *cmd, double rtol, double atol);

#endif

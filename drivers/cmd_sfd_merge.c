/* drivers/cmd_sfd_merge.c — `whirl sfd merge`: the points where the isolated
 * branch of circular orbits merges with the resonance peak (or is born as a
 * point), G = G_eps = G_Omega = 0 of eq. 15, converged on the rotating-frame
 * equations by the fold system with the MG condition (whirl/fold.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>
#include <whirl/rotor/sfd_region.h>

#include "cli.h"
#include "sfd_common.h"

#define CMD "sfd merge"

static const cli_doc doc = {
"usage: whirl sfd merge --lambda L [--zeta Z] [--quiet]\n"
"\n"
"The isola-peak merge point of the circular synchronous orbits (F_E = 0):\n"
"the unbalance delta at which the isolated branch joins the resonance peak,\n"
"with the speed and eccentricity where it happens.  It is the point where\n"
"the fold curve in (Omega, delta) has an extremum of delta (G = dG/deps =\n"
"dG/dOmega = 0 in eq. 15), converged on the rotating-frame equilibrium\n"
"equations (fold system with the merge condition).\n"
"\n"
"options:\n",
"stdout: TSV 'lambda zeta delta Omega eps type residual', one row per point\n"
"(type MG: an isola merges with another branch; IS: an isola is born as a\n"
"point); residual = largest relative residual of G, G_eps, G_Omega.\n"};

int cmd_sfd_merge(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_LAMBDA] = NAN; /* required */
  int quiet = 0;
  const cli_opt opts[] = {SFD_OPT_LAMBDA(p), SFD_OPT_ZETA(p), CLI_OPT_QUIET(quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 0 : 2;
  const double lambda = p[WHIRL_SFD_LAMBDA], zeta = p[WHIRL_SFD_ZETA];
  if (sfd_check(CMD, p, 0)) return 2;
  char msg[512] = "";
  whirl_sfd_curve mp;
  const double t0 = cli_now();
  int rc = whirl_sfd_merge_points(lambda, zeta, &mp, msg, sizeof msg);
  const double secs = cli_now() - t0;
  if (rc != 0) {
    cli_error(CMD, "%s", msg);
    return 1;
  }
  if (mp.len == 0) {
    cli_error(CMD, "no isola merge point for lambda = %g, zeta = %g (eccentricity in (0, 1))",
              lambda, zeta);
    whirl_sfd_curve_free(&mp);
    return 1;
  }
  printf("lambda\tzeta\tdelta\tOmega\teps\ttype\tresidual\n");
  for (size_t i = 0; i < mp.len; ++i)
    printf("%.10g\t%.10g\t%.12f\t%.12f\t%.12f\t%s\t%.1e\n", mp.lambda[i], zeta, mp.delta[i],
           mp.Omega[i], mp.eps[i], whirl_point_type_name(mp.type[i]), mp.res[i]);
  if (!quiet)
    fprintf(stderr, "whirl sfd merge: %zu point%s for lambda = %g, zeta = %g (%.3f s); below "
                    "delta = %.9f the isolated branch is separate from the resonance peak\n",
            mp.len, mp.len == 1 ? "" : "s", lambda, zeta, secs, mp.delta[0]);
  whirl_sfd_curve_free(&mp);
  return 0;
}

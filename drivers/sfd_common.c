/* drivers/sfd_common.c — shared by the SFD time-domain commands: the class
 * of a steady state (whirl_section_classify plus a check that the points are
 * not still converging to a fixed point, which would otherwise look like a
 * curve: a slowly settling spiral).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>

#include <whirl/whirl.h>

#include "cli.h"
#include "sfd_common.h"

static double step_len(const double *P, size_t k) {
  double s = 0;
  for (int i = 0; i < 4; ++i) {
    double d = P[4 * (k + 1) + i] - P[4 * k + i];
    s += d * d;
  }
  return sqrt(s);
}

const char *sfd_steady_class(const double *P, size_t npts, double eps_spread,
                             size_t *period, double *dimension) {
  *period = 0;
  *dimension = NAN;
  if (npts < 64) return "transient";
  /* still converging?  mean step over the first and the last tenth */
  size_t m = npts / 10;
  double a = 0, b = 0;
  for (size_t k = 0; k < m; ++k) {
    a += step_len(P, k);
    b += step_len(P, npts - 2 - k);
  }
  whirl_section_kind kind;
  size_t per = 0;
  double dim = NAN;
  int rc = whirl_section_classify(P, npts, 4, 1e-6, 16, &kind, &per, &dim);
  if (rc != WHIRL_OK) return "irregular";
  *dimension = dim;
  if (kind == WHIRL_SECTION_FIXED) {
    *period = 1;
    return eps_spread < 1e-6 ? "circular" : "periodic";
  }
  if (kind == WHIRL_SECTION_PERIODIC) {
    *period = per;
    return "periodic";
  }
  if (b < 1e-3 * a) return "transient";
  return kind == WHIRL_SECTION_CURVE ? "quasiperiodic" : "irregular";
}

/* The options of the parameters, for the messages (whirl/sfd.h's order). */
static const char *const param_option[WHIRL_SFD_NPAR][2] = {
    {"--omega", "the dimensionless speed, e.g. --omega 8.7"},
    {"--lambda", "the SFD constant, e.g. --lambda 0.25"},
    {"--delta", "the unbalance, e.g. --delta 0.3"},
    {"--zeta", "the external damping ratio, e.g. --zeta 0"},
    {"--fe", "the static force, e.g. --fe 0"}};

int sfd_check(const char *cmd, const double *p, int omega_option) {
  for (int k = 0; k < WHIRL_SFD_NPAR; ++k)
    if (isnan(p[k])) {
      cli_error(cmd, "%s is required (%s)", param_option[k][0], param_option[k][1]);
      return -1;
    }
  if (omega_option && !(p[WHIRL_SFD_OMEGA] > 0)) {
    cli_error(cmd, "--omega must be > 0 (got %g)", p[WHIRL_SFD_OMEGA]);
    return -1;
  }
  char msg[256];
  if (whirl_sfd_check_params(p, msg, sizeof msg) != WHIRL_OK) {
    cli_error(cmd, "%s", msg);
    return -1;
  }
  return 0;
}

const char *sfd_gp_params(char *buf, size_t len, const double *p, unsigned mask) {
  static const char *const symbol[WHIRL_SFD_NPAR] = {"{/Symbol W}", "{/Symbol l}",
                                                     "{/Symbol d}", "{/Symbol z}", "F_E"};
  size_t used = 0;
  buf[0] = '\0';
  for (int k = 0; k < WHIRL_SFD_NPAR && used < len; ++k)
    if (mask & SFD_P(k)) {
      int n = snprintf(buf + used, len - used, "%s%s = %g", used ? ", " : "", symbol[k], p[k]);
      if (n < 0) break;
      used += (size_t)n;
    }
  return buf;
}

int sfd_check_tolerances(const char *cmd, double rtol, double atol) {
  char msg[128];
  if (whirl_basins_check_tolerances(rtol, atol, msg, sizeof msg) == WHIRL_OK)
    return 0;
  cli_error(cmd, "--%s", msg); /* "rtol must be in [...]" names the option */
  return -1;
}

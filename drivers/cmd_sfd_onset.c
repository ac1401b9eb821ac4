/* drivers/cmd_sfd_onset.c — `whirl sfd onset`: the speed at which the
 * response from rest stops settling on a circular orbit (the onset of the
 * nonsynchronous response from zero initial conditions, paper §5.2:
 * 8.5322–8.5327), bracketed by bisection in Ω.  At each speed the trajectory
 * from rest is integrated until it enters the certified neighbourhood of a
 * stable circular orbit (class circular, as sfd sweep names it) or
 * --periods pass (nonsynchronous).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "cli.h"
#include "sfd_common.h"

#define CMD "sfd onset"

static const cli_doc doc = {
"usage: whirl sfd onset --from A --to B [options]\n"
"\n"
"Bisection in Omega for the onset of the nonsynchronous response from rest\n"
"(zero initial conditions).  At A the response from rest must settle on a\n"
"circular orbit and at B it must not (or the other way round).\n"
"\n"
"options (defaults: Table 1 of the paper):\n",
"stdout: TSV 'Omega class periods' for every speed tried, then a line\n"
"'onset<TAB>lo<TAB>hi'.\n"};

/* 1 circular (captured by a circular orbit: the class `sfd sweep` calls
 * circular), 0 nonsynchronous (not captured), -1 contact, < -1
 * error.  *per: periods integrated. */
static int from_rest(double *p, size_t periods, double rtol, double atol, unsigned *per,
                     char *msg, size_t len) {
  whirl_sfd_attractors_options ao;
  whirl_sfd_attractors_options_default(&ao);
  ao.find_cycle = 0;
  ao.rtol = rtol;
  ao.atol = atol;
  whirl_sfd_attractors *A = NULL;
  int rc = whirl_sfd_attractors_find(p, &ao, &A, msg, len);
  if (rc != WHIRL_OK) return -2;
  whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
  if (!ode || whirl_ode_set_tolerances(ode, rtol, atol) != WHIRL_OK) {
    snprintf(msg, len, "cannot set up the integrator");
    whirl_ode_free(ode);
    whirl_sfd_attractors_free(A);
    return -2;
  }
  whirl_basins_options bo;
  whirl_basins_options_default(&bo);
  bo.period = 2 * WHIRL_PI / p[WHIRL_SFD_OMEGA];
  bo.max_periods = periods;
  bo.rtol = rtol;
  bo.atol = atol;
  const double x0[4] = {0, 0, 0, 0};
  int which = WHIRL_BASIN_FAILED;
  rc = whirl_basins_classify(ode, x0, whirl_sfd_attractors_list(A), whirl_sfd_attractors_count(A), &bo,
                             &which, per);
  whirl_ode_free(ode);
  whirl_sfd_attractors_free(A);
  if (rc != WHIRL_OK || which == WHIRL_BASIN_FAILED) {
    snprintf(msg, len, "integration failed at Omega = %g", p[WHIRL_SFD_OMEGA]);
    return -2;
  }
  if (which == WHIRL_BASIN_DOMAIN) return -1;
  return which >= 0 ? 1 : 0;
}

static const char *cls_name(int c) {
  return c == 1 ? "circular" : c == 0 ? "nonsynchronous" : "contact";
}

/* The response from rest at Omega = om (from_rest), its row printed on
 * stdout: its class, or < -1 after the message (PROG, unless NULL, cleared
 * first). */
static int try_speed(double *p, double om, size_t periods, double rtol, double atol,
                     cli_progress *prog) {
  char msg[512];
  unsigned per = 0;
  p[WHIRL_SFD_OMEGA] = om;
  const int c = from_rest(p, periods, rtol, atol, &per, msg, sizeof msg);
  if (c < -1) {
    if (prog) cli_progress_end(prog);
    cli_error(CMD, "%s", msg);
    return c;
  }
  printf("%.10f\t%s\t%u\n", om, cls_name(c), per);
  fflush(stdout);
  return c;
}

int cmd_sfd_onset(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  double from = NAN, to = NAN, tol = 1e-5, rtol = 1e-12, atol = 1e-15;
  size_t periods = 3000;
  int quiet = 0;
  const cli_opt opts[] = {
      {"--from", CLI_DOUBLE, &from, "A", "one end of the bracket, A > 0", NULL},
      {"--to", CLI_DOUBLE, &to, "B", "the other end, B > 0", NULL},
      {"--tol", CLI_DOUBLE, &tol, "T", "width of the final bracket", NULL},
      {"--periods", CLI_SIZE, &periods, "P",
       "periods before a response counts as nonsynchronous", NULL},
      SFD_OPTS_MODEL(p),
      SFD_OPTS_TOL(rtol, atol),
      CLI_OPT_QUIET(quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 0 : 2;
  if (isnan(from) || isnan(to)) {
    cli_error(CMD, "--from and --to are required (e.g. --from 8.5 --to 8.6)");
    return 2;
  }
  if (!(from > 0) || !(to > 0) || from == to || !(tol > 0) || periods < 1) {
    cli_error(CMD, "need --from, --to > 0 and different, --tol > 0, --periods >= 1");
    return 2;
  }
  if (sfd_check_tolerances(CMD, rtol, atol)) return 2;
  p[WHIRL_SFD_OMEGA] = fmax(from, to);
  if (sfd_check(CMD, p, 0)) return 2;
  printf("Omega\tclass\tperiods\n");
  double a = from, b = to;
  const int ca = try_speed(p, a, periods, rtol, atol, NULL);
  if (ca < -1) return 1;
  const int cb = try_speed(p, b, periods, rtol, atol, NULL);
  if (cb < -1) return 1;
  if (ca == cb) {
    cli_error(CMD, "no change of the response from rest between %g and %g (both %s): widen the bracket",
              a, b, cls_name(ca));
    return 1;
  }
  cli_progress prog;
  cli_progress_init(&prog, "whirl sfd onset", quiet);
  size_t total = (size_t)ceil(log2(fabs(b - a) / tol)), k = 0;
  while (fabs(b - a) > tol) {
    cli_progress_show(&prog, k++, total);
    const double m = 0.5 * (a + b);
    const int cm = try_speed(p, m, periods, rtol, atol, &prog);
    if (cm < -1) return 1;
    if (cm == ca) a = m;
    else b = m;
  }
  cli_progress_end(&prog);
  printf("onset\t%.10f\t%.10f\n", fmin(a, b), fmax(a, b));
  if (!quiet)
    fprintf(stderr, "whirl sfd onset: the response from rest changes from %s to %s between Omega = %.8f "
                    "and %.8f\n", cls_name(ca), cls_name(ca == 1 ? 0 : 1), fmin(a, b), fmax(a, b));
  return 0;
}

/* test/unit/t_errors.c — bad input to the library ends in a status code and
 * a message, never a crash: SFD parameters out of range or NaN, F_E != 0 for
 * circular orbits, contact with the housing (eps >= 1), a Newton that
 * diverges, a model that fails fatally, a branch that runs into a domain
 * error, and numbers as run files write them (whirl_run_number).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <whirl/rotor.h>

#include "../tap.h"

static int atan_F(const double *x, const double *p, double *f, void *d) {
  (void)p;
  (void)d;
  f[0] = atan(x[0]);
  return 0;
}
static int fatal_F(const double *x, const double *p, double *f, void *d) {
  (void)x;
  (void)p;
  (void)d;
  f[0] = 0;
  return -7;
}
/* F = x - p, defined only for p < 1 (a "contact" beyond) */
static int wall_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  if (p[0] >= 1.0) return 1;
  f[0] = x[0] - p[0];
  return 0;
}

int main(void) {
  double p[WHIRL_SFD_NPAR];
  char msg[256];
  struct {
    int k;
    double v;
    const char *name;
  } bad[] = {{WHIRL_SFD_LAMBDA, 0.0, "lambda"},   {WHIRL_SFD_LAMBDA, -1.0, "lambda"},
             {WHIRL_SFD_DELTA, -0.1, "delta"},    {WHIRL_SFD_ZETA, -0.01, "zeta"},
             {WHIRL_SFD_LAMBDA, NAN, "lambda"},   {WHIRL_SFD_DELTA, INFINITY, "delta"},
             {WHIRL_SFD_OMEGA, -1.0, "Omega"}};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    whirl_sfd_default_params(p);
    p[bad[i].k] = bad[i].v;
    msg[0] = '\0';
    int rc = whirl_sfd_check_params(p, msg, sizeof msg);
    ok(rc == WHIRL_EINVAL && strstr(msg, bad[i].name), "%s = %g rejected: %s", bad[i].name,
       bad[i].v, msg);
  }
  whirl_sfd_default_params(p);
  ok(whirl_sfd_check_params(p, msg, sizeof msg) == WHIRL_OK, "Table 1 parameters accepted");

  /* the response refuses bad parameters before computing anything */
  whirl_sfd_response_options o;
  whirl_sfd_response_options_default(&o);
  whirl_sfd_response r;
  p[WHIRL_SFD_LAMBDA] = -0.1;
  ok(whirl_sfd_response_compute(p, &o, &r, msg, sizeof msg) == WHIRL_EINVAL &&
         strstr(msg, "lambda"), "response: lambda < 0 rejected: %s", msg);
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_FE] = 0.5;
  ok(whirl_sfd_response_compute(p, &o, &r, msg, sizeof msg) == WHIRL_EINVAL &&
         strstr(msg, "F_E"), "response: F_E != 0 rejected: %s", msg);
  whirl_sfd_default_params(p);
  o.omega_max = 0.001;
  ok(whirl_sfd_response_compute(p, &o, &r, msg, sizeof msg) == WHIRL_EINVAL,
     "response: omega_max < omega_min rejected: %s", msg);

  /* contact with the housing is a recoverable status, not a number */
  double f[2], x[4] = {0.8, 0.6, 0.0, 0.0}, fx[4];
  ok(whirl_sfd_force(1.0, 0.0, 0.1, 0.0, 0.05, f, NULL, NULL) == WHIRL_SFD_CONTACT,
     "force at eps = 1 reports contact");
  ok(whirl_sfd_force(0.9, 0.9, 0.0, 0.0, 0.05, f, NULL, NULL) == WHIRL_SFD_CONTACT,
     "force at eps = 1.27 reports contact");
  ok(whirl_sfd_force(NAN, 0.0, 0.0, 0.0, 0.05, f, NULL, NULL) < 0, "force rejects NaN");
  whirl_sfd_default_params(p);
  ok(whirl_sfd_rotating()->rhs(0.0, x, p, fx, NULL) == WHIRL_SFD_CONTACT,
     "rotating model reports contact at eps = 1");
  ok(whirl_sfd_fixed()->rhs(0.0, x, p, fx, NULL) == WHIRL_SFD_CONTACT,
     "fixed-frame model reports contact at eps = 1");

  /* a Newton iteration that diverges (atan from x = 10) */
  whirl_system s = {.name = "atan", .n = 1, .npar = 1, .F = atan_F};
  double xx = 10.0, pp = 0.0;
  int its = 0;
  int rc = whirl_newton(&s, &xx, &pp, 1e-12, 20, &its);
  ok(rc == WHIRL_ENOCONV, "diverging Newton reported as no convergence (%s)", whirl_strerror(rc));

  /* a fatal callback comes back as WHIRL_EUSER with a message */
  whirl_system sf = {.name = "fatal", .n = 1, .npar = 1, .F = fatal_F};
  whirl_cont_options co;
  whirl_cont_options_default(&co);
  whirl_cont *c = whirl_cont_alloc(&sf, &co, msg, sizeof msg);
  rc = whirl_cont_start(c, &xx, &pp, 1);
  ok(rc == WHIRL_EUSER && strstr(whirl_cont_errmsg(c), "fatal"), "fatal callback: %s",
     whirl_cont_errmsg(c));
  whirl_cont_free(c);

  /* a branch running into a domain error ends cleanly at the last good point */
  whirl_system sw = {.name = "wall", .n = 1, .npar = 1, .F = wall_F};
  co.ds = 0.1;
  co.ds_max = 0.1;
  co.ds_min = 1e-6;
  c = whirl_cont_alloc(&sw, &co, msg, sizeof msg);
  xx = 0.0;
  pp = 0.0;
  whirl_cont_start(c, &xx, &pp, 1);
  double last = NAN;
  while ((rc = whirl_cont_step(c)) == WHIRL_OK) last = whirl_cont_point(c)->p[0];
  ok(rc == WHIRL_DONE && whirl_cont_stop_reason(c) == WHIRL_STOP_DOMAIN,
     "domain error ends the branch: %s", whirl_cont_errmsg(c));
  ok(last < 1.0 && last > 1.0 - 1e-5, "last point just before the wall (p = %.8f)", last);
  whirl_cont_free(c);

  /* numbers as run files (and the commands' options) write them */
  static const struct {
    const char *text;
    int rc;
    double x;
  } nums[] = {
      {"0.1", WHIRL_OK, 0.1},          {"-2", WHIRL_OK, -2.0},
      {"+.5", WHIRL_OK, 0.5},          {"5.", WHIRL_OK, 5.0},
      {"2.0E+1", WHIRL_OK, 20.0},      {"1e-400", WHIRL_OK, 0.0},
      {"1e-310", WHIRL_OK, 1e-310},    {"1e999", WHIRL_EDOMAIN, 0},
      {"nan", WHIRL_EDOMAIN, 0},       {"-Infinity", WHIRL_EDOMAIN, 0},
      {"0x10", WHIRL_EINVAL, 0},       {"0x1p-3", WHIRL_EINVAL, 0},
      {" 1", WHIRL_EINVAL, 0},         {"1 ", WHIRL_EINVAL, 0},
      {"1e", WHIRL_EINVAL, 0},         {"e5", WHIRL_EINVAL, 0},
      {".", WHIRL_EINVAL, 0},          {"-", WHIRL_EINVAL, 0},
      {"", WHIRL_EINVAL, 0},           {"1,5", WHIRL_EINVAL, 0},
      {"1d-3", WHIRL_EINVAL, 0},       {"--1", WHIRL_EINVAL, 0}};
  for (size_t i = 0; i < sizeof nums / sizeof nums[0]; i++) {
    double got = -7.0;
    rc = whirl_run_number(nums[i].text, &got);
    ok(rc == nums[i].rc && (rc != WHIRL_OK ? got == -7.0 : got == nums[i].x),
       "whirl_run_number('%s') = %d (want %d), x = %g", nums[i].text, rc,
       nums[i].rc, got);
  }
  double tiny = 1.0;
  rc = whirl_run_number("4.9406564584124654e-324", &tiny);
  ok(rc == WHIRL_OK && tiny > 0 && tiny < 1e-320, "the smallest denormal is read (%g)",
     tiny);

  ok(strcmp(whirl_strerror(WHIRL_ENOCONV), "Newton iteration did not converge") == 0,
     "status messages");
  return done_testing();
}

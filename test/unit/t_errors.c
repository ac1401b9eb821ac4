/* test/unit/t_errors.c — bad input to the library ends in a status code and
 * a message, never a crash: SFD parameters out of range or NaN, F_E != 0 for
 * circular orbits, contact with the housing (eps >= 1), a Newton that
 * diverges, a model that fails fatally, a branch that runs into a domain
 * error, numbers as run files write them (whirl_run_number), the one
 * message formatter (whirl_errmsg_set) and the last message of the hbm,
 * collocation and equilibrium objects (whirl_X_errmsg).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <whirl/rotor.h>

#include "../tap.h"

/* a forced linear oscillator x'' + x = cos(p0 t), for the HBM and
 * collocation objects */
static int osc_rhs(double t, const double *x, const double *p, double *f,
                   void *d) {
  (void)d;
  f[0] = x[1];
  f[1] = -x[0] + cos(p[0] * t);
  return 0;
}
static const whirl_problem osc = {.name = "osc", .n = 2, .npar = 1,
                                  .rhs = osc_rhs};

/* whirl_errmsg_set: message, origin, truncation, NULL buffer */
static void formatter(void) {
  char buf[64];
  int rc = whirl_errmsg_set(buf, sizeof buf, WHIRL_EINVAL, "/a/b/thing.c", 42,
                            "n = %d", 7);
  ok(rc == WHIRL_EINVAL && strcmp(buf, "n = 7 (thing.c:42)") == 0,
     "errmsg_set: message and base name of the origin: '%s'", buf);
  rc = WHIRL_ERRMSG(buf, sizeof buf, WHIRL_ENOMEM, "at %s", "here");
  ok(rc == WHIRL_ENOMEM && strncmp(buf, "at here (t_errors.c:", 20) == 0,
     "WHIRL_ERRMSG records this file and line: '%s'", buf);
  char small[8];
  whirl_errmsg_set(small, sizeof small, 0, "x.c", 1, "%s", "0123456789");
  ok(strcmp(small, "0123456") == 0, "a message that fills the buffer is "
     "truncated, without origin: '%s'", small);
  ok(whirl_errmsg_set(NULL, 0, WHIRL_EIO, "x.c", 1, "nothing") == WHIRL_EIO,
     "NULL buffer: only the code");
}

/* hbm, collocation and equilibrium objects keep their last message */
static void object_messages(void) {
  whirl_hbm_options ho;
  whirl_hbm_options_default(&ho);
  ho.forcing_param = 0;
  whirl_hbm *h = whirl_hbm_alloc(&osc, &ho, NULL, 0);
  double X[64], x[8] = {0};
  ok(h && whirl_hbm_from_samples(h, x, 4, 1.0, X) == WHIRL_EINVAL &&
         strstr(whirl_hbm_errmsg(h), "2N + 1 = 17") &&
         strstr(whirl_hbm_errmsg(h), "(hbm.c:"),
     "hbm: too few samples, message kept: %s", h ? whirl_hbm_errmsg(h) : "");
  whirl_hbm_free(h);
  whirl_colloc_options co;
  whirl_colloc_options_default(&co);
  co.forcing_param = 0;
  whirl_colloc *c = whirl_colloc_alloc(&osc, &co, NULL, 0);
  const double bad[3] = {0.0, 0.7, 0.5};
  co.ntst = 2;
  whirl_colloc *c2 = whirl_colloc_alloc(&osc, &co, NULL, 0);
  ok(c2 && whirl_colloc_set_mesh(c2, bad) == WHIRL_EINVAL &&
         strstr(whirl_colloc_errmsg(c2), "0 to 1"),
     "colloc: a mesh that does not end at 1 is refused: %s",
     c2 ? whirl_colloc_errmsg(c2) : "");
  ok(c && whirl_colloc_hopf_start(c, x, x, X, X, NULL) == WHIRL_EINVAL &&
         strstr(whirl_colloc_errmsg(c), "forced"),
     "colloc: a Hopf start of a forced model is refused: %s",
     c ? whirl_colloc_errmsg(c) : "");
  whirl_colloc_free(c2);
  whirl_colloc_free(c);
  /* the equilibrium system's spectrum with no room for the eigenvalues */
  whirl_equilibrium *eq = whirl_equilibrium_alloc(&osc);
  const whirl_system *es = eq ? whirl_equilibrium_system(eq) : NULL;
  double re[2], im[2], p0 = 1.0;
  size_t m = 1;
  ok(es && es->spectrum(x, &p0, NULL, re, im, &m, es->data) == WHIRL_EINVAL &&
         strstr(whirl_equilibrium_errmsg(eq), "room for 1 of 2"),
     "equilibrium: the spectrum's failure is kept: %s",
     eq ? whirl_equilibrium_errmsg(eq) : "");
  whirl_equilibrium_free(eq);
}

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
  formatter();
  object_messages();
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

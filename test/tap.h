/* test/tap.h — minimal TAP producer for whirl's unit tests (gsl_test_rel in
 * TAP form).  ok(), is_rel(), is_abs(), then return done_testing().
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_TAP_H
#define WHIRL_TAP_H
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>

static int tap_n = 0, tap_fail = 0;

static int tap_report(int cond, const char *fmt, va_list ap) {
  ++tap_n;
  if (!cond) ++tap_fail;
  printf("%s %d - ", cond ? "ok" : "not ok", tap_n);
  vprintf(fmt, ap);
  printf("\n");
  fflush(stdout);
  return cond;
}

static int ok(int cond, const char *fmt, ...) __attribute__((format(printf, 2, 3), unused));
static int ok(int cond, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  int r = tap_report(cond, fmt, ap);
  va_end(ap);
  return r;
}

/* |got - want| <= tol * max(1e-300, |want|); NaN never passes. */
static int is_rel(double got, double want, double tol, const char *fmt, ...)
    __attribute__((format(printf, 4, 5), unused));
static int is_rel(double got, double want, double tol, const char *fmt, ...) {
  double err = fabs(got - want), scale = fabs(want) > 1e-300 ? fabs(want) : 1e-300;
  int cond = isfinite(got) && err <= tol * scale;
  va_list ap;
  va_start(ap, fmt);
  int r = tap_report(cond, fmt, ap);
  va_end(ap);
  if (!cond) printf("#   got %.17g want %.17g rel err %.3g > %.3g\n", got, want, err / scale, tol);
  return r;
}

/* |got - want| <= tol; NaN never passes. */
static int is_abs(double got, double want, double tol, const char *fmt, ...)
    __attribute__((format(printf, 4, 5), unused));
static int is_abs(double got, double want, double tol, const char *fmt, ...) {
  double err = fabs(got - want);
  int cond = isfinite(got) && err <= tol;
  va_list ap;
  va_start(ap, fmt);
  int r = tap_report(cond, fmt, ap);
  va_end(ap);
  if (!cond) printf("#   got %.17g want %.17g abs err %.3g > %.3g\n", got, want, err, tol);
  return r;
}

/* Deterministic xorshift64* generator (Vigna 2016), uniform in [lo, hi):
 * fixed seed, so a failure reproduces. */
static uint64_t tap_rng = 0x2545F4914F6CDD1DULL;
static double tap_urand(double lo, double hi) __attribute__((unused));
static double tap_urand(double lo, double hi) {
  tap_rng ^= tap_rng >> 12;
  tap_rng ^= tap_rng << 25;
  tap_rng ^= tap_rng >> 27;
  const uint64_t r = tap_rng * 0x2545F4914F6CDD1DULL;
  return lo + (hi - lo) * ((double)(r >> 11) * 0x1.0p-53);
}

static int done_testing(void) __attribute__((unused));
static int done_testing(void) {
  printf("1..%d\n", tap_n);
  if (tap_fail) printf("# %d of %d tests failed\n", tap_fail, tap_n);
  return tap_fail ? 1 : 0;
}
#endif

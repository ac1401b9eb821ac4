/* test/unit/t_dynlib.c — functions of a library bound at their first use
 * (whirl/dynlib.h): a table bound from libm and called, from several
 * threads at once; a library that is not there and a function that is not
 * in it end in WHIRL_ENOLIB with a message naming them, never a crash; a
 * malformed list of libraries is refused.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <pthread.h>
#include <string.h>

#include <whirl/dynlib.h>

#include "../tap.h"

#define MATH_FUNCS(X) X(cos) X(atan2)
WHIRL_DYNLIB(m, MATH_FUNCS, "libwhirl-no-such-library.so.0:libm.so.6")

#define NONE_FUNCS(X) X(sin)
WHIRL_DYNLIB(none, NONE_FUNCS, "libwhirl-no-such-library.so.0")

/* the first library of a list that cannot be opened fails the list: a
 * table is bound from all of its libraries or not at all */
static void missing_library(void) {
  char err[300] = "";
  int rc = none_bind(err, sizeof err);
  ok(rc == WHIRL_ENOLIB && strstr(err, "libwhirl-no-such-library.so.0") != NULL,
     "a library that is not there: WHIRL_ENOLIB, named: '%s'", err);
  char again[300] = "";
  ok(none_bind(again, sizeof again) == WHIRL_ENOLIB && strcmp(err, again) == 0,
     "asked again: the same answer, the same reason");
  char tiny[8];
  ok(none_bind(tiny, sizeof tiny) == WHIRL_ENOLIB && strlen(tiny) == 7,
     "the reason cut to the caller's buffer: '%s'", tiny);
  ok(m_bind(err, sizeof err) == WHIRL_ENOLIB,
     "a list with a library that is not there is not bound either");
}

static void missing_function(void) {
  const char *names[] = {"cos", "whirl_no_such_function"};
  whirl_dynfn fns[2] = {0, 0};
  char err[300] = "";
  int rc = whirl_dynlib_bind("libm.so.6", names, 2, fns, err, sizeof err);
  ok(rc == WHIRL_ENOLIB && strstr(err, "whirl_no_such_function") && strstr(err, "libm.so.6"),
     "a function the library lacks: WHIRL_ENOLIB, named: '%s'", err);
  const char *one[] = {"cos"};
  rc = whirl_dynlib_bind("libm.so.6", one, 1, fns, err, sizeof err);
  double (*c)(double);
  memcpy(&c, &fns[0], sizeof c);
  ok(rc == WHIRL_OK && c && c(0.25) == cos(0.25), "cos bound from libm.so.6 is cos");
}

static void bad_lists(void) {
  const char *one[] = {"cos"};
  whirl_dynfn fns[1];
  char err[300];
  ok(whirl_dynlib_bind("libm.so.6::libc.so.6", one, 1, fns, err, sizeof err) == WHIRL_EINVAL,
     "an empty name in the list: WHIRL_EINVAL (%s)", err);
  ok(whirl_dynlib_bind(NULL, one, 1, fns, err, sizeof err) == WHIRL_EINVAL,
     "no list: WHIRL_EINVAL");
  ok(whirl_dynlib_bind("", one, 1, fns, err, sizeof err) == WHIRL_EINVAL,
     "an empty list: WHIRL_EINVAL (%s)", err);
}

/* a table bound from libm: the first list fails, so bind libm on its own */
#define LIBM_FUNCS(X) X(cos) X(atan2) X(hypot)
WHIRL_DYNLIB(lm, LIBM_FUNCS, "libm.so.6")

static void *use_libm(void *arg) {
  double *out = arg;
  *out = lm_bind(NULL, 0) == WHIRL_OK ? lm.hypot(3.0, 4.0) + lm.atan2(0.0, -1.0) : -1.0;
  return NULL;
}

static void bound_in_threads(void) {
  enum { NT = 4 };
  pthread_t t[NT];
  double out[NT];
  int started = 1;
  for (int i = 0; i < NT; i++) started &= pthread_create(&t[i], NULL, use_libm, &out[i]) == 0;
  for (int i = 0; i < NT && started; i++) pthread_join(t[i], NULL);
  int all = started;
  for (int i = 0; i < NT && started; i++) all &= out[i] == 5.0 + atan2(0.0, -1.0);
  ok(all, "bound from %d threads at once, each calls hypot and atan2 of libm", NT);
  ok(lm.cos(1.0) == cos(1.0), "the table's cos is libm's");
}

int main(void) {
  missing_library();
  missing_function();
  bad_lists();
  bound_in_threads();
  return done_testing();
}

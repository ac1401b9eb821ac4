/* test/unit/t_fmt_num.c — fmt_e and fmt_g (lib/util/fmt_num.h) write what
 * snprintf's "%.*e" and "%.*g" write, byte for byte, for precisions 0..17
 * (e to 16; 14 to 17 digits by the long double path where it has one):
 * on random doubles of every exponent, on numbers at and next to ties of
 * the last digit (where the fast path must hand over to snprintf), on the
 * special values, and where rounding carries into a new exponent.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "util/fmt_num.h"
#include "tap.h"

static uint64_t state = 0x9e3779b97f4a7c15ull;
static uint64_t next(void) { /* xorshift64 */
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return state;
}

static long mismatches, compared;
static char first_bad[160];

static void compare(double x) {
  char a[64], b[64];
  for (int p = 0; p <= 17; p++) {
    for (int g = 0; g < 2; g++) {
      if (!g && p > 16) continue;
      const int la = g ? fmt_g(a, sizeof a, x, p) : fmt_e(a, sizeof a, x, p);
      const int lb = snprintf(b, sizeof b, g ? "%.*g" : "%.*e", p, x);
      compared++;
      if (la != lb || strcmp(a, b)) {
        if (!mismatches++)
          snprintf(first_bad, sizeof first_bad, "%s p=%d: %s, snprintf %s", g ? "g" : "e",
                   p, a, b);
      }
    }
  }
}

static double random_double(int mode) {
  const uint64_t r = next();
  double x;
  switch (mode) {
  case 0: /* any bit pattern: every exponent, NaNs and infinities */
    memcpy(&x, &r, sizeof x);
    return x;
  case 1: /* uniform mantissas over forty decades */
    return ldexp((double)(r >> 11), -53) * pow(10.0, (int)(next() % 40) - 20);
  case 2: /* a digit string ending in 5: a tie at some precision */
    return ((double)(r % 100000000000ull) + 0.5) * pow(10.0, (int)(next() % 30) - 25);
  case 3: /* dyadic numbers with short decimal expansions: exact ties */
    return ((double)(int64_t)(r % 2000001) - 1e6) / ldexp(1.0, (int)(next() % 30));
  default: /* 31-bit fractions times a power of ten, another spread of
            * mantissas for the long double path's 14 to 17 digits */
    return ((double)(r % 2147483648ull) / 2147483648.0 - 0.5) * pow(10.0, (int)(next() % 30) - 15);
  }
}

int main(void) {
  static const double special[] = {0.0,      -0.0,    INFINITY, -INFINITY, NAN,
                                   DBL_MIN,  DBL_MAX, DBL_TRUE_MIN, 1.0,   -1.0,
                                   9.99999999995e5, 9.9999999999949e5, 0.5, 2.5,
                                   1.52587890625e-05, 1e22, 1e23, 1e-5, 1e-4, 123456.5,
                                   1e100, 1.5e-300, 99999.5, 0.000099999995};
  for (size_t i = 0; i < sizeof special / sizeof *special; i++) compare(special[i]);
  ok(mismatches == 0, "special values, carries and ties as snprintf (%ld compared)%s%s",
     compared, mismatches ? ": " : "", first_bad);
  for (int mode = 0; mode < 5; mode++) {
    mismatches = compared = 0;
    for (int i = 0; i < 15000; i++) {
      const double x = random_double(mode);
      compare(x);
      compare(-x);
      compare(nextafter(x, INFINITY));
    }
    ok(mismatches == 0, "random doubles of kind %d as snprintf (%ld of %ld differ)%s%s", mode,
       mismatches, compared, mismatches ? ": " : "", first_bad);
  }
  long dbad = 0;
  char da[32], db[32];
  static const long edge[] = {0, 1, -1, 9, 10, -10, 99, 100, LONG_MAX, LONG_MIN, LONG_MIN + 1};
  for (size_t i = 0; i < sizeof edge / sizeof *edge + 100000; i++) {
    const long v = i < sizeof edge / sizeof *edge ? edge[i] : (long)next();
    const int la = fmt_d(da, v), lb = snprintf(db, sizeof db, "%ld", v);
    dbad += la != lb || strcmp(da, db);
  }
  ok(dbad == 0, "fmt_d as %%ld: 0, +-1, 9/10, 99/100, LONG_MIN/MAX and 100000 random (%ld differ)",
     dbad);
  char small[8];
  const int n = fmt_e(small, sizeof small, 1.25, 3);
  ok(n == 9 && !strcmp(small, "1.250e+"), "a buffer too small: snprintf's truncation and length");
  return done_testing();
}

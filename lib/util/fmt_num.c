/* lib/util/fmt_num.c — doubles written as printf's "%.Pe" and "%.Pg" write
 * them, byte for byte, without glibc's multiple-precision conversion for
 * the numbers where that is provably unneeded (fmt_num.h).
 *
 * The D = P + 1 (e) or P (g) significant digits of x are the integer
 * nearest y = x 10^(D-1-k), k the decimal exponent of x.  For |D-1-k| <= 22
 * the power of ten is an exact double, so y is x 10^(D-1-k) rounded once:
 * its relative error is at most 2^-53, and for D <= 13 its absolute error
 * below 1e-3.  The nearest integer is then certain unless y's fraction
 * lies within that error of 1/2 (where printf's exact, round-half-even
 * conversion decides): those numbers, and infinities, NaNs, zeros,
 * subnormals and exponents beyond the table go to snprintf.  The same
 * scheme as the fast paths of Grisu (Loitsch, PLDI 2010) and Ryu printf
 * (Adams, PLDI 2019): a cheap approximation where it is provably right, the
 * exact algorithm elsewhere.
 *
 * For D = 14 to 17 digits (the round trip's "%.17g" of solution files) the
 * same in long double where its significand has 64 bits (x86-64): 10^p is
 * exact there for |p| <= 27 and y < 10^17 < 2^57 is rounded once.  Since
 * whole + 1/2 is then representable and rounding is monotonic, y's side of
 * it is the exact product's unless y lands on it: only a computed fraction
 * of exactly 1/2 is undecided (0.2 to 0.7 % of the tests' random doubles
 * at 17 digits).  A fraction within 0.01 of 1/2 goes to snprintf, a margin
 * beyond that.
 * Where long double is no wider than double, or its arithmetic is not
 * (an x87 precision control set to 53 bits, checked at each call), those
 * precisions go to snprintf.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "util/fmt_num.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double pow10_exact[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

enum { MAX_DIGITS = 13, MAX_DIGITS_LD = 17 };

/* The D significant digits of |x| > 0 as an integer in *n (10^(D-1) <=
 * *n < 10^D) and its decimal exponent *k, rounded to nearest; 0 when that
 * cannot be decided here. */
static int digits_of(double x, int D, long long *n, int *k) {
  const double a = fabs(x);
  if (!(a >= 1e-290 && a <= 1e290) || D < 1 || D > MAX_DIGITS) return 0;
  const double lo = pow10_exact[D - 1], hi = pow10_exact[D];
  /* the exponent from the binary one (log10 2 = 0.30103): at most one off,
   * which the loop mends */
  int e = (int)floor(ilogb(a) * 0.30102999566398120);
  for (int tries = 0; tries < 3; tries++) {
    const int p = D - 1 - e;
    if (p > 22 || p < -22) return 0;
    const double y = p >= 0 ? a * pow10_exact[p] : a / pow10_exact[-p];
    if (y < lo) {
      e--;
      continue;
    }
    if (y >= hi) {
      e++;
      continue;
    }
    const double whole = floor(y), frac = y - whole;
    if (fabs(frac - 0.5) <= 2e-3) return 0; /* too near a tie to tell */
    long long m = (long long)whole + (frac > 0.5);
    if (m >= (long long)hi) { /* 9.99...9 rounded up to 10.0...0 */
      m /= 10;
      e++;
    }
    *n = m;
    *k = e;
    return 1;
  }
  return 0;
}

#if LDBL_MANT_DIG >= 64
static const long double pow10_exact_ld[28] = {
    1e0L,  1e1L,  1e2L,  1e3L,  1e4L,  1e5L,  1e6L,  1e7L,  1e8L,  1e9L,
    1e10L, 1e11L, 1e12L, 1e13L, 1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L,
    1e20L, 1e21L, 1e22L, 1e23L, 1e24L, 1e25L, 1e26L, 1e27L};

/* 1 when long double arithmetic carries 64 bits here (1 + 2^-63 != 1):
 * asked at each call (an addition; no static, so no race between
 * threads that format numbers) */
static int ld_is_wide(void) {
  volatile long double one = 1.0L, tiny = 0x1p-63L;
  return one + tiny != one;
}

/* digits_of for 13 < D <= 17, in long double (see the head of the file) */
static int digits_of_ld(double x, int D, long long *n, int *k) {
  const long double a = fabs(x);
  if (!(a >= 1e-290L && a <= 1e290L) || D <= MAX_DIGITS || D > MAX_DIGITS_LD || !ld_is_wide())
    return 0;
  const long double lo = pow10_exact_ld[D - 1], hi = pow10_exact_ld[D];
  int e = (int)floor(ilogb(x) * 0.30102999566398120);
  for (int tries = 0; tries < 3; tries++) {
    const int p = D - 1 - e;
    if (p > 27 || p < -27) return 0;
    const long double y = p >= 0 ? a * pow10_exact_ld[p] : a / pow10_exact_ld[-p];
    if (y < lo) {
      e--;
      continue;
    }
    if (y >= hi) {
      e++;
      continue;
    }
    const long double whole = floorl(y), frac = y - whole;
    if (fabsl(frac - 0.5L) <= 0.01L) return 0; /* too near a tie to tell */
    long long m = (long long)whole + (frac > 0.5L);
    if (m >= (long long)hi) {
      m /= 10;
      e++;
    }
    *n = m;
    *k = e;
    return 1;
  }
  return 0;
}
#else
static int digits_of_ld(double x, int D, long long *n, int *k) {
  (void)x, (void)D, (void)n, (void)k;
  return 0;
}
#endif

/* D significant digits of x by whichever of the two applies */
static int digits_any(double x, int D, long long *n, int *k) {
  return D <= MAX_DIGITS ? digits_of(x, D, n, k) : digits_of_ld(x, D, n, k);
}

/* the D digits of n, most significant first */
static void put_digits(char *out, long long n, int D) {
  for (int i = D - 1; i >= 0; i--) {
    out[i] = (char)('0' + n % 10);
    n /= 10;
  }
}

/* "e+05", "e-22", "e+100": the sign and at least two digits */
static int put_exponent(char *out, int k) {
  int len = 0;
  out[len++] = 'e';
  out[len++] = k < 0 ? '-' : '+';
  const int a = k < 0 ? -k : k;
  if (a >= 100) out[len++] = (char)('0' + a / 100);
  out[len++] = (char)('0' + a / 10 % 10);
  out[len++] = (char)('0' + a % 10);
  return len;
}

/* printf's own conversion where the fast one cannot tell the digits: a
 * literal precision for the common ones, as glibc's "%.*g" takes its slow
 * positional path (twice the time of "%.17g"; the same bytes) */
static int slow_g(char *out, size_t size, double x, int prec) {
  switch (prec) {
  case 17: return snprintf(out, size, "%.17g", x);
  case 12: return snprintf(out, size, "%.12g", x);
  case 10: return snprintf(out, size, "%.10g", x);
  default: return snprintf(out, size, "%.*g", prec, x);
  }
}
static int slow_e(char *out, size_t size, double x, int prec) {
  switch (prec) {
  case 16: return snprintf(out, size, "%.16e", x);
  case 10: return snprintf(out, size, "%.10e", x);
  default: return snprintf(out, size, "%.*e", prec, x);
  }
}

int fmt_e(char *out, size_t size, double x, int prec) {
  long long n;
  int k, len = 0;
  char d[MAX_DIGITS_LD];
  if (size < FMT_NUM_SIZE || prec < 0 || !digits_any(x, prec + 1, &n, &k))
    return slow_e(out, size, x, prec);
  put_digits(d, n, prec + 1);
  if (signbit(x)) out[len++] = '-';
  out[len++] = d[0];
  if (prec > 0) {
    out[len++] = '.';
    memcpy(out + len, d + 1, (size_t)prec);
    len += prec;
  }
  len += put_exponent(out + len, k);
  out[len] = '\0';
  return len;
}

int fmt_g(char *out, size_t size, double x, int prec) {
  long long n;
  int k, len = 0;
  char d[MAX_DIGITS_LD];
  const int P = prec == 0 ? 1 : prec;
  if (size < FMT_NUM_SIZE || prec < 0 || !digits_any(x, P, &n, &k))
    return slow_g(out, size, x, prec);
  put_digits(d, n, P);
  int used = P; /* the digits left once trailing zeros go */
  while (used > 1 && d[used - 1] == '0') used--;
  if (signbit(x)) out[len++] = '-';
  if (k < -4 || k >= P) { /* the style of %e */
    out[len++] = d[0];
    if (used > 1) {
      out[len++] = '.';
      memcpy(out + len, d + 1, (size_t)(used - 1));
      len += used - 1;
    }
    len += put_exponent(out + len, k);
  } else if (k < 0) { /* 0.000ddd */
    out[len++] = '0';
    out[len++] = '.';
    for (int i = 0; i < -k - 1; i++) out[len++] = '0';
    memcpy(out + len, d, (size_t)used);
    len += used;
  } else { /* ddd.ddd */
    memcpy(out + len, d, (size_t)(k + 1)); /* k < P: all digits of d */
    len += k + 1;
    if (used > k + 1) {
      out[len++] = '.';
      memcpy(out + len, d + k + 1, (size_t)(used - k - 1));
      len += used - k - 1;
    }
  }
  out[len] = '\0';
  return len;
}

int fmt_d(char *out, long v) {
  char d[24];
  int n = 0, len = 0;
  unsigned long u = v < 0 ? 0ul - (unsigned long)v : (unsigned long)v;
  do {
    d[n++] = (char)('0' + u % 10);
    u /= 10;
  } while (u);
  if (v < 0) out[len++] = '-';
  while (n) out[len++] = d[--n];
  out[len] = '\0';
  return len;
}

void fmt_put_e(FILE *f, double x, int prec) {
  char buf[FMT_NUM_SIZE + 16];
  fmt_e(buf, sizeof buf, x, prec);
  fputs(buf, f);
}

void fmt_put_g(FILE *f, double x, int prec) {
  char buf[FMT_NUM_SIZE + 16];
  fmt_g(buf, sizeof buf, x, prec);
  fputs(buf, f);
}

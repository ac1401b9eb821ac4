/* lib/util/fmt_num.h — a double as printf's "%.Pe" or "%.Pg" writes it,
 * the same bytes, in a fraction of the time for most numbers (fmt_num.c):
 * the tables of a response hold thousands of them (doc/benchmarks.md).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_UTIL_FMT_NUM_H
#define WHIRL_UTIL_FMT_NUM_H

#include <stddef.h>
#include <stdio.h>

/* room enough for any number of either form with prec <= 17 */
#define FMT_NUM_SIZE 32

/* Write x to out[size] as snprintf(out, size, "%.*e", prec, x) would, and
 * return the same length; size >= FMT_NUM_SIZE for the fast path. */
int fmt_e(char *out, size_t size, double x, int prec);
/* ... as snprintf(out, size, "%.*g", prec, x) would */
int fmt_g(char *out, size_t size, double x, int prec);

/* Write v to out (room for 21 bytes) as "%ld" would; the length. */
int fmt_d(char *out, long v);

/* fprintf(f, "%.*e", prec, x) and fprintf(f, "%.*g", prec, x) by the above */
void fmt_put_e(FILE *f, double x, int prec);
void fmt_put_g(FILE *f, double x, int prec);

#endif

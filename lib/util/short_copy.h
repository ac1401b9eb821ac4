/* lib/util/short_copy.h — private to libwhirl and the AUTO adapter: copies
 * and clears of a few to a few dozen doubles, inline.  The library's
 * innermost loops copy short vectors (a Gauss point's n states, a model's
 * parameters before each perturbed call, a row's n entries) millions of
 * times a run; a call of memcpy or memset, through the PLT into libc's
 * size dispatch, costs more than such a copy itself (demo fnc: 8 % of
 * its last run on one thread in memcpy, 88 bytes at a time).  Written in
 * pairs, which compilers do not turn back into those calls
 * (-ftree-loop-distribute-patterns turns a plain element loop into one).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SHORT_COPY_H
#define WHIRL_SHORT_COPY_H

#include <stddef.h>

/* d[k] = s[k], k < len (d and s do not overlap) */
static inline void whirl_copy_short(double *restrict d, const double *restrict s,
                                    size_t len) {
  size_t k = 0;
  for (; k + 2 <= len; k += 2) {
    d[k] = s[k];
    d[k + 1] = s[k + 1];
  }
  if (k < len) d[k] = s[k];
}

/* d[k] = 0, k < len */
static inline void whirl_zero_short(double *d, size_t len) {
  size_t k = 0;
  for (; k + 2 <= len; k += 2) {
    d[k] = 0.0;
    d[k + 1] = 0.0;
  }
  if (k < len) d[k] = 0.0;
}

#endif

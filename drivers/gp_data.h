/* drivers/gp_data.h — the points a figure's plot items draw (gp_data.c):
 * from its datablocks, or from the tables beside the script (read once
 * each, fields split at tabs or blanks, '#' lines skipped, a blank line a
 * break in the curve) through their `using` columns or expressions.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_GP_DATA_H
#define WHIRL_DRIVERS_GP_DATA_H

#include <stddef.h>

#include "gp_figure.h"

typedef struct gp_points {
  double *x, *y;      /* NaN where a value is undefined (a break, as gnuplot) */
  unsigned char *brk; /* brk[i]: a blank line before point i */
  size_t n;
} gp_points;

/* The points of every plot item of F, (*pts)[s] for s < f->nseries; the
 * data files are in DIR.  0; 1 when a file cannot be read (gnuplot is to
 * draw it, and say so; why in err); -1 out of memory. */
int gp_series_points(const gp_figure *f, const char *dir, gp_points **pts, char *err,
                     size_t len);
void gp_points_free(gp_points *pts, size_t n); /* accepts NULL */

/* The whole of the file PATH, NUL-terminated (*n bytes, if N); NULL if it
 * cannot be read. */
char *gp_slurp(const char *path, size_t *n);

#endif

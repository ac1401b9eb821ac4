/* drivers/gp_axis.h — an axis of the pictures whirl draws itself: its
 * range (as set, or from the data and extended to a tick, as gnuplot's),
 * its ticks and their labels, and the map from values to pixels
 * (gp_axis.c).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_GP_AXIS_H
#define WHIRL_DRIVERS_GP_AXIS_H

#include <stddef.h>

#include "gp_data.h"
#include "gp_figure.h"

enum { MAX_TICKS = 64 };

typedef struct axis_map {
  double lo, hi;     /* data range (log10 of it on a log axis) */
  double step;       /* between major ticks (decades on a log axis) */
  double p0, p1;     /* pixels of lo and hi */
  int log;
  double tick[MAX_TICKS], minor[4 * MAX_TICKS];
  int ntick, nminor;
} axis_map;

/* The range of axis A (AX 0: x, 1: y) of F, its points PTS: as set, or
 * from the data and extended to a tick; its ticks.  -1 for a range that
 * cannot be drawn (a log axis at or below 0). */
int gp_axis_range(const gp_figure *f, const gp_points *pts, const gp_axis *a, int ax,
                  axis_map *m);

/* The pixel of value V (NaN: undefined, or at or below 0 on a log axis). */
double gp_axis_px(const axis_map *m, double v);
/* The pixel of tick position T, on a pixel's centre. */
double gp_axis_tick_px(const axis_map *m, double t);
/* The pixel of a position in first (data) or graph (0..1) coordinates. */
double gp_axis_coord_px(const axis_map *m, gp_coord c);
/* The label of tick position T (enhanced text: 1x10^{-6}). */
void gp_axis_tick_label(const axis_map *m, double t, char *buf, size_t len);

#endif

/* drivers/gp_axis.c — the axes of gp_axis.h.  Tick steps follow gnuplot's
 * rule (a step of 1, 2 or 5 times a power of ten, about 20 / mantissa a
 * decade, from the length of the range before it is extended); automatic
 * ranges end on a tick (a decade on a log axis), and tick labels are in
 * gnuplot's default format "% h".
 * SPDX-License-Identifier: BSD-3-Clause */
#include "gp_axis.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The tick step of a range of length ARG: 1, 2, 5 (or 0.5, 0.2 ...) times
 * a power of ten, about 20 / (ARG / 10^floor(log10 ARG)) ticks a decade
 * (gnuplot's "quantize_normal_tics" rule, guide 20). */
static double tick_step(double arg) {
  const double power = pow(10.0, floor(log10(arg)));
  const double xnorm = arg / power, posns = 20.0 / xnorm;
  double t;
  if (posns > 40) t = 0.05;
  else if (posns > 20) t = 0.1;
  else if (posns > 10) t = 0.2;
  else if (posns > 4) t = 0.5;
  else if (posns > 2) t = 1;
  else if (posns > 0.5) t = 2;
  else t = ceil(xnorm);
  return t * power;
}

/* The data's range on one axis (the points of every series), positive
 * values only on a log axis.  0 when there are none. */
static int data_range(const gp_figure *f, const gp_points *pts, int ax, int log,
                      double *lo, double *hi) {
  *lo = INFINITY;
  *hi = -INFINITY;
  for (size_t s = 0; s < f->nseries; s++)
    for (size_t i = 0; i < pts[s].n; i++) {
      const double v = ax ? pts[s].y[i] : pts[s].x[i];
      if (!isfinite(v) || (log && v <= 0)) continue;
      *lo = fmin(*lo, v);
      *hi = fmax(*hi, v);
    }
  return *lo <= *hi;
}

/* The axis's range: as set, or from the data and extended to a tick;
 * -1 for a range that cannot be drawn (a log axis at or below 0). */
/* The ticks of M's range: major every step, minor on a log axis. */
static void axis_ticks(axis_map *m) {
  const double lo = fmin(m->lo, m->hi), hi = fmax(m->lo, m->hi);
  /* a log axis: every decade, or whole numbers of decades on a long one */
  const double step = m->step;
  const double tol = 1e-9 * step;
  m->ntick = m->nminor = 0;
  for (double k = ceil((lo - tol) / step); k * step <= hi + tol && m->ntick < MAX_TICKS; k++) {
    double v = k * step;
    if (fabs(v) < tol) v = 0;
    m->tick[m->ntick++] = v;
  }
  if (!m->log) return;
  for (double d = floor(lo); d <= hi; d++) {
    if (step > 1) { /* ticks every few decades: the decades between */
      if (d > lo + tol && d < hi - tol && fmod(d, step) != 0 && m->nminor < 4 * MAX_TICKS)
        m->minor[m->nminor++] = d;
      continue;
    }
    for (int j = 2; j <= 9 && m->nminor < 4 * MAX_TICKS; j++) { /* 2..9 times each */
      const double v = d + log10((double)j);
      if (v > lo + tol && v < hi - tol) m->minor[m->nminor++] = v;
    }
  }
}

int gp_axis_range(const gp_figure *f, const gp_points *pts, const gp_axis *a, int ax,
                      axis_map *m) {
  double dlo, dhi;
  int have = data_range(f, pts, ax, a->log, &dlo, &dhi);
  double lo = a->auto_lo ? (have ? dlo : a->log ? 1 : -10) : a->lo;
  double hi = a->auto_hi ? (have ? dhi : a->log ? 10 : 10) : a->hi;
  if (a->log && (lo <= 0 || hi <= 0)) return -1;
  if (a->log) lo = log10(lo), hi = log10(hi);
  if (lo > hi && a->auto_lo != a->auto_hi) { /* one end set past the data */
    if (a->auto_lo) lo = hi - 1;
    else hi = lo + 1;
  }
  if (lo == hi) {
    const double d = a->log ? 1 : fabs(lo) > 0 ? 0.01 * fabs(lo) : 1;
    lo -= d;
    hi += d;
  }
  /* the step from the range before it is extended to ticks, as gnuplot's
   * (the data's 0.01..20 gives a step of 2, the set [0:20] one of 5) */
  const double span = fabs(hi - lo);
  const double step = a->log ? fmax(1.0, ceil(tick_step(span))) : tick_step(span);
  const int rev = lo > hi;
  if (a->auto_lo) lo = (rev ? ceil(lo / step - 1e-9) : floor(lo / step + 1e-9)) * step;
  if (a->auto_hi) hi = (rev ? floor(hi / step + 1e-9) : ceil(hi / step - 1e-9)) * step;
  m->lo = lo;
  m->hi = hi;
  m->log = a->log;
  m->step = step;
  axis_ticks(m);
  return 0;
}

double gp_axis_px(const axis_map *m, double v) {
  if (m->log) v = v > 0 ? log10(v) : NAN;
  return m->p0 + (v - m->lo) / (m->hi - m->lo) * (m->p1 - m->p0);
}

/* The pixel of tick position T (log10 of the value on a log axis), on a
 * pixel's centre so that one-pixel lines there are sharp. */
double gp_axis_tick_px(const axis_map *m, double t) {
  return round(m->p0 + (t - m->lo) / (m->hi - m->lo) * (m->p1 - m->p0) - 0.5) + 0.5;
}

/* a position in the figure's coordinates: first (data) or graph (0..1) */
double gp_axis_coord_px(const axis_map *m, gp_coord c) {
  return c.sys == GP_GRAPH ? m->p0 + c.v * (m->p1 - m->p0) : gp_axis_px(m, c.v);
}

/* The label of tick T in gnuplot's default format "% h": %g, its
 * exponent written 1x10^{-6} (enhanced text) rather than 1e-06. */
void gp_axis_tick_label(const axis_map *m, double t, char *buf, size_t len) {
  double v = m->log ? pow(10.0, t) : t;
  char g[24]; /* %g of a double: at most 13 characters */
  snprintf(g, sizeof g, "%g", v);
  char *e = strchr(g, 'e');
  if (!e) {
    snprintf(buf, len, "%s", g);
    return;
  }
  *e = '\0';
  snprintf(buf, len, "%sx10^{%d}", g, atoi(e + 1));
}


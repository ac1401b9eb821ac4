/* drivers/run_plot_labels.c — the names of whirl run's special points on
 * its diagram: "LP 3" (AUTO's type and LAB), each placed apart from the
 * others, the points and the curves (label_place.c).  gnuplot's 'with
 * labels' put every name at the same offset, so an LP next to an HB (or a
 * UZ) wrote one name over the other, and a point at the axes' end lost
 * its name to the frame.  The axes' ranges are written out (the data's,
 * 4 % wider each way) because the placement works in fractions of them.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "label_place.h"
#include "overlay.h"
#include "run_plot_impl.h"

/* One character of 'Sans,11' on the 900 x 650 diagram, as fractions of
 * its axes (about 810 x 540 pixels): 9.5 and 17 pixels, a little more than
 * an upper-case glyph and a line, so that close labels keep a gap. */
#define CHAR_U (9.5 / 810.0)
#define CHAR_V (17.0 / 540.0)
#define SAMPLES 8 /* curve samples between two points of a branch */

/* Field K (0-based) of the tab-separated ROW as a number, NaN if absent. */
static double field(const char *row, int k) {
  const char *s = row;
  for (int i = 0; i < k && s; i++) {
    s = strchr(s, '\t');
    if (s) s++;
  }
  return s ? strtod(s, NULL) : NAN;
}

/* The data's range RANGE = {x0, x1, y0, y1}, widened by 4 % each way. */
static void ranges(const ov_run *t, const double *px, const double *py, size_t n,
                   double range[4]) {
  range[0] = range[2] = INFINITY, range[1] = range[3] = -INFINITY;
  for (size_t i = 0; i < t->n + n; i++) {
    const double x = i < t->n ? t->pt[i].x : px[i - t->n];
    const double y = i < t->n ? t->pt[i].y : py[i - t->n];
    if (!isfinite(x) || !isfinite(y)) continue;
    range[0] = fmin(range[0], x), range[1] = fmax(range[1], x);
    range[2] = fmin(range[2], y), range[3] = fmax(range[3], y);
  }
  for (int a = 0; a < 4; a += 2) {
    double w = range[a + 1] - range[a];
    if (!(w > 0)) w = fabs(range[a]) > 0 ? fabs(range[a]) : 1;
    range[a] -= 0.04 * w, range[a + 1] += 0.04 * w;
  }
}

/* The curves as fractions of the axes, SAMPLES a step; *nc samples. */
static void curve_samples(const ov_run *t, const double range[4], double *u, double *v,
                          size_t *nc) {
  const double wx = range[1] - range[0], wy = range[3] - range[2];
  *nc = 0;
  for (size_t i = 1; i < t->n; i++) {
    const ov_point *a = &t->pt[i - 1], *b = &t->pt[i];
    if (a->seg != b->seg) continue;
    for (int s = 0; s < SAMPLES; s++) {
      const double q = (double)s / SAMPLES;
      u[*nc] = (a->x + q * (b->x - a->x) - range[0]) / wx;
      v[*nc] = (a->y + q * (b->y - a->y) - range[2]) / wy;
      if (isfinite(u[*nc]) && isfinite(v[*nc])) ++*nc;
    }
  }
}

/* The labels' lines; their texts "TY LAB" in TEXT. */
static void write_set_labels(FILE *f, const lp_label *l, char (*text)[16], const double *px,
                             const double *py, size_t n) {
  for (size_t i = 0; i < n; i++)
    fprintf(f, "set label '%s' at %.10g, %.10g offset %g,%g %s front noenhanced\n", text[i],
            px[i], py[i], l[i].dx, l[i].dy, l[i].right ? "right" : "left");
}

void run_plot_labels(FILE *f, const cli_outdir *od, const whirl_run *r,
                     const whirl_run_plot *pl) {
  ov_run t;
  char msg[300];
  const size_t ns = whirl_run_nspecial(r);
  if (ov_read_columns(&t, od->stage, pl->x - 1, pl->y - 1, msg, sizeof msg)) return;
  double *px = malloc((ns + 1) * sizeof *px), *py = malloc((ns + 1) * sizeof *py);
  double *cu = malloc((SAMPLES * t.n + 1) * sizeof *cu), *cv = malloc((SAMPLES * t.n + 1) * sizeof *cv);
  lp_label *l = calloc(ns + 1, sizeof *l);
  char(*text)[16] = calloc(ns + 1, sizeof *text);
  size_t n = 0, nc = 0;
  for (size_t i = 0; px && py && l && text && i < ns; i++) {
    const whirl_run_special *s = whirl_run_special_point(r, i);
    if (!strcmp(s->ty, "EP")) continue;
    px[n] = field(s->row, pl->x - 1), py[n] = field(s->row, pl->y - 1);
    snprintf(text[n], sizeof text[n], s->lab > 0 ? "%.2s %d" : "%.2s", s->ty, s->lab);
    if (isfinite(px[n]) && isfinite(py[n])) n++;
  }
  if (px && py && cu && cv && l && text) {
    double range[4];
    ranges(&t, px, py, n, range);
    curve_samples(&t, range, cu, cv, &nc);
    for (size_t i = 0; i < n; i++) {
      l[i].u = (px[i] - range[0]) / (range[1] - range[0]);
      l[i].v = (py[i] - range[2]) / (range[3] - range[2]);
      l[i].chars = strlen(text[i]);
    }
    lp_place(l, n, CHAR_U, CHAR_V, cu, cv, nc);
    fprintf(f, "set xrange [%.10g:%.10g]\nset yrange [%.10g:%.10g]\n", range[0], range[1],
            range[2], range[3]);
    write_set_labels(f, l, text, px, py, n);
  }
  free(px), free(py), free(cu), free(cv), free(l), free(text);
  ov_free(&t);
}

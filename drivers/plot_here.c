/* drivers/plot_here.c — the PNG pictures whirl draws itself (gp_draw.h)
 * rather than by gnuplot: which ones (PNG, not WHIRL_DRAW=gnuplot, a
 * script of the subset gp_parse.c reads, a font), and the painter that
 * draws them, one for the whole run.  (Two pictures on two processors, a
 * painter each, were measured slower: the second painter's font and
 * canvas, and the two threads faulting pages into one address space, cost
 * more than the picture; doc/benchmarks.md.)
 * SPDX-License-Identifier: BSD-3-Clause */
#include "plot_here.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "gp_draw.h"

/* The painter: made at the first picture, kept for the
 * rest of the run (its glyphs cached, its canvas mapped), freed at exit. */
static gp_painter *painter;
static int painter_tried;

static void painter_free(void) { gp_painter_free(painter); }

/* Is a PNG drawn here at all (format, WHIRL_DRAW, a font)? */
static int here_at_all(void) {
  const char *how = getenv("WHIRL_DRAW");
  char err[300];
  if (strcmp(cli_picture_format, "png") || (how && !strcmp(how, "gnuplot"))) return 0;
  if (!painter_tried) {
    painter_tried = 1;
    painter = gp_painter_new(err, sizeof err);
    if (painter) atexit(painter_free);
  }
  return painter != NULL;
}

int cli_draw_here(cli_outdir *d, const char *name) {
  char err[300], png[300], shown[4400];
  if (!here_at_all()) return 1;
  const int rc = gp_draw_script(painter, d->stage, name, err, sizeof err);
  if (rc == 1) return 1;
  snprintf(png, sizeof png, "%s.png", name);
  if (rc == 0) return cli_outdir_record(d, png) == 0 ? 0 : -1;
  cli_outdir_shown(d, png, shown, sizeof shown);
  cli_error(d->cmd, "the picture %s could not be written: %s", shown, err);
  return -1;
}

size_t cli_draw_here_all(cli_outdir *d, const char *const *pics, const char **rest,
                         int *failed) {
  size_t nrest = 0;
  *failed = 0;
  for (size_t i = 0; pics && pics[i] && !*failed; i++) {
    const int r = cli_draw_here(d, pics[i]);
    if (r == 1) rest[nrest++] = pics[i];
    if (r < 0) *failed = 1;
  }
  return nrest;
}

/* drivers/gp_draw.h — PNG pictures drawn in-process from whirl's gnuplot
 * scripts (gp_figure.h reads them, gp_draw.c draws them), so that a
 * picture costs a millisecond, not a gnuplot start (doc/benchmarks.md).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_GP_DRAW_H
#define WHIRL_DRIVERS_GP_DRAW_H

#include <stddef.h>

#include "gp_figure.h"
#include "raster_text.h"

/* What the pictures of a run share: the font (its glyphs cached) and the
 * canvas (its memory mapped once, for pictures of one size). */
typedef struct gp_painter gp_painter;

/* NULL, with the reason in err, when there is no font (gnuplot draws). */
gp_painter *gp_painter_new(char *err, size_t len);
void gp_painter_free(gp_painter *p); /* accepts NULL */

/* Draw the figure F (its data files in DIR) as a PNG at PATH.  0: written;
 * 1: F holds something not drawn here, or a data file cannot be read
 * (nothing written); -1: the file could not be written (removed; the
 * reason in err). */
int gp_draw_png(gp_painter *p, const gp_figure *f, const char *dir, const char *path,
                char *err, size_t len);

/* Draw the picture of the script DIR/NAME.gp where the script says (its
 * `set output`, a file name in DIR).  0: drawn; 1: the script is not one
 * drawn here (gnuplot draws it; why in err); -1: the picture could not be
 * written (err says why, nothing is left). */
int gp_draw_script(gp_painter *p, const char *dir, const char *name, char *err,
                   size_t len);

#endif

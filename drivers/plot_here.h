/* drivers/plot_here.h — the PNG pictures whirl draws itself instead of
 * gnuplot (plot_here.c; the drawing: gp_draw.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_PLOT_HERE_H
#define WHIRL_DRIVERS_PLOT_HERE_H

#include <stddef.h>

#include "outdir.h"

/* Draw the picture NAME here.  0: drawn and recorded; 1: gnuplot's to
 * draw (another format, WHIRL_DRAW=gnuplot, no font, a script outside the
 * subset); -1: it could not be written (reported). */
int cli_draw_here(cli_outdir *d, const char *name);

/* Draw the pictures PICS (NULL-terminated) here; REST (room for all of
 * them) receives those gnuplot is to draw, in order, and their count is
 * returned.  *failed: one could not be written (reported; the pictures
 * after it are not drawn). */
size_t cli_draw_here_all(cli_outdir *d, const char *const *pics, const char **rest,
                         int *failed);

#endif

/* drivers/raster_text.h — text on the canvas of raster.h: glyphs rendered
 * by FreeType from one TrueType font (DejaVu Sans unless WHIRL_FONT names
 * another), with the part of gnuplot's enhanced text mode whirl's pictures
 * use: {/Symbol x} (Greek letters), subscripts _x or _{...}, superscripts
 * ^x or ^{...}, {/=S ...} (size S points) and \x (a literal x).  Strings are
 * UTF-8.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_RASTER_TEXT_H
#define WHIRL_DRIVERS_RASTER_TEXT_H

#include <stddef.h>
#include <stdint.h>

#include "raster.h"

typedef struct raster_font raster_font;

/* The font at PATH (NULL: $WHIRL_FONT, else the one configure found).
 * NULL, with the reason in err, when there is no font or no FreeType. */
raster_font *raster_font_open(const char *path, char *err, size_t len);
void raster_font_close(raster_font *f); /* accepts NULL */

typedef struct raster_extent {
  double width;   /* advance of the whole string, pixels */
  double ascent;  /* above the baseline (> 0) */
  double descent; /* below it (> 0) */
} raster_extent;

/* The extent of S at SIZE pixels per em (ENHANCED: gnuplot's enhanced
 * syntax above, else the characters as they are).  -1 for a string the
 * renderer does not draw (an enhanced construct outside the subset, bad
 * UTF-8), 0 otherwise. */
int raster_text_extent(raster_font *f, const char *s, double size, int enhanced,
                       raster_extent *e);

/* Draw S with its baseline's left end at (x, y); ROTATED: turned 90 degrees
 * counter-clockwise about that point (reading upwards). */
int raster_text_draw(raster *r, raster_font *f, const char *s, double size,
                     int enhanced, double x, double y, int rotated, uint32_t rgb);

#endif

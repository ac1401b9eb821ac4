/* drivers/gp_figure.h — a 2-d picture as whirl's gnuplot scripts describe
 * it, for drawing PNGs in-process (gp_draw.c) instead of starting gnuplot.
 * gp_parse.c reads the part of gnuplot's language whirl writes for line
 * and point plots (doc/output-directories.md lists it); a script with
 * anything else is left to gnuplot.  The script stays the one description
 * of the picture: `gnuplot NAME.gp` redraws it.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_GP_FIGURE_H
#define WHIRL_DRIVERS_GP_FIGURE_H

#include <stddef.h>
#include <stdint.h>

#include "gp_expr.h"

enum { GP_FIRST = 0, GP_GRAPH = 1 };             /* coordinate systems */
enum { GP_LEFT = -1, GP_CENTRE = 0, GP_RIGHT = 1 }; /* text alignment */
enum { GP_LINES = 0, GP_POINTS = 1 };

typedef struct gp_text {
  char *s;      /* NULL: none */
  int enhanced; /* gnuplot's enhanced syntax ({/Symbol l}, F_E) */
} gp_text;

typedef struct gp_coord {
  double v;
  int sys; /* GP_FIRST or GP_GRAPH */
} gp_coord;

typedef struct gp_arrow {
  gp_coord x0, y0, x1, y1;
  double lw;
  int dt; /* 1 solid, 2 dashed, 3 dotted, ... */
  uint32_t rgb;
} gp_arrow;

typedef struct gp_label {
  gp_text text;
  gp_coord x, y;
  int align;
  double font_pt; /* 0: the terminal's */
  uint32_t rgb;
  double off_x, off_y; /* offset in characters */
} gp_label;

typedef struct gp_block { /* a datablock $NAME << EOD */
  char name[64];
  double *v;     /* nrow rows of ncol numbers (NaN: missing) */
  size_t nrow, ncol;
  unsigned char *brk; /* brk[i]: a blank line before row i (a new curve) */
} gp_block;

typedef struct gp_series { /* one item of the plot command */
  size_t block;  /* a datablock; SIZE_MAX: a file, or no data (NaN, 1/0:
                    a key entry alone, file NULL) */
  char *file;    /* a table in the script's directory ('branches.tsv') */
  int cx, cy;    /* columns, 1-based, where ux, uy are NULL */
  gp_expr *ux, *uy; /* using (expression): x and y from a file's rows */
  int style;   /* GP_LINES, GP_POINTS */
  double lw, ps;
  int dt, pt;
  int has_rgb;
  uint32_t rgb;
  gp_text title; /* s NULL: notitle */
} gp_series;

typedef struct gp_axis {
  double lo, hi;
  int auto_lo, auto_hi;
  int log;
  gp_text label;
} gp_axis;

typedef struct gp_figure {
  int w, h;
  double font_pt;
  int enhanced; /* the terminal's default for text */
  char output[256];
  gp_axis x, y;
  gp_text title;
  double title_off_x, title_off_y;
  int grid, key, key_box; /* key: outside right top, or (key_bottom) under
                             the axes, its entries side by side */
  int key_bottom;
  uint32_t grid_rgb;
  int key_left;           /* its text left-justified (Left), else right */
  int key_reverse;        /* the sample before the text (reverse) */
  double key_width;       /* extra width, in characters (width N) */
  double margin[4]; /* t, b, l, r in characters; < 0: automatic */
  gp_arrow *arrow;
  size_t narrow;
  gp_label *label;
  size_t nlabel;
  gp_block *block;
  size_t nblock;
  gp_series *series;
  size_t nseries;
  char sep;           /* the data files' separator: '\t', or 0 (blanks) */
  gp_var var[16];     /* NAME = value */
  size_t nvar;
} gp_figure;

/* Parse the script TEXT into *fig.  0: parsed; 1: it uses something not
 * drawn here (why in err, for a debugging note: the caller runs gnuplot);
 * -1: out of memory. */
int gp_parse(const char *text, gp_figure *fig, char *err, size_t len);
void gp_figure_free(gp_figure *fig);

#endif

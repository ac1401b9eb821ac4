/* drivers/raster.h — an RGB canvas with anti-aliased drawing, for the
 * pictures whirl draws itself (gp_draw.c): thick polylines with round joins
 * and dash patterns, discs, rectangles, and coverage masks (glyphs).  Every
 * shape is drawn as a coverage per pixel, the largest coverage of its parts,
 * then blended once: a polyline's segments do not darken where they meet.
 * Pixels are indices into a palette of the colours in use (at most 256: a
 * picture of a few inks and their anti-aliased shades; past that a blend
 * takes the nearest colour there is), a quarter of the memory of RGB to
 * fill and to write, and the PNG needs no colour count.
 *
 * The shapes are recorded as they come and drawn by raster_render in
 * bands of rows, each band handed on (to the PNG encoder) before the next
 * is drawn over it: a picture needs the memory of a band, 140 kB for
 * 1100-pixel rows, not of the whole canvas (1.65 MB, whose fresh pages
 * cost more than drawing it; doc/benchmarks.md).  raster_pixels draws the
 * whole picture at once, for tests.
 *
 * Coordinates are pixels with (0, 0) the top-left corner of the top-left
 * pixel; a pixel's centre is at (i + 0.5, j + 0.5).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_RASTER_H
#define WHIRL_DRIVERS_RASTER_H

#include <stddef.h>
#include <stdint.h>

typedef struct raster_op raster_op;

typedef struct raster {
  int w, h;
  uint32_t pal[256]; /* the colours in use, 0x00RRGGBB; pal[0] the background */
  int npal;
  /* drawing: the band of rows row0 .. row0 + rows - 1 */
  int row0, rows;
  uint8_t *px;        /* rows * w palette indices of the band, row-major */
  uint8_t *cov;       /* rows * w coverage of the shape being drawn (0 outside) */
  size_t band_cap;    /* bytes of px (and of cov) */
  int16_t slot[1024]; /* colour -> palette index: open addressing, -1 empty */
  uint32_t *touch;    /* band indices of the pixels the shape covers */
  size_t ntouch, cap;
  double clip[4];     /* x0, y0, x1, y1: shapes are cut to this rectangle */
  uint32_t bg;
  /* the shapes recorded since raster_new or raster_clear */
  raster_op *ops;
  size_t nops, opcap;
  double *nums; /* their coordinates and dash lengths */
  size_t nnums, numcap;
  uint8_t *bytes; /* their masks */
  size_t nbytes, bytecap;
  int failed;   /* out of memory while recording */
  uint8_t *all; /* raster_pixels' whole picture */
} raster;

/* A W x H canvas of colour BG, the clip the whole canvas.  NULL when out
 * of memory or W, H out of 1..16384. */
raster *raster_new(int w, int h, uint32_t bg);
void raster_free(raster *r); /* accepts NULL */
/* The canvas as new, of the same size and colour BG (its memory kept). */
void raster_clear(raster *r, uint32_t bg);

void raster_set_clip(raster *r, double x0, double y0, double x1, double y1);
void raster_clip_all(raster *r);

/* A polyline through (x[i], y[i]), i < n, WIDTH pixels wide, round joins
 * and caps; DASH (NDASH on/off lengths in pixels, 0 for solid) runs along
 * its length.  Non-finite points break the line. */
void raster_polyline(raster *r, const double *x, const double *y, size_t n,
                     double width, const double *dash, int ndash, uint32_t rgb);
/* one segment */
void raster_line(raster *r, double x0, double y0, double x1, double y1,
                 double width, const double *dash, int ndash, uint32_t rgb);
void raster_disc(raster *r, double cx, double cy, double radius, uint32_t rgb);
/* a circle of RADIUS, its line WIDTH wide */
void raster_ring(raster *r, double cx, double cy, double radius, double width,
                 uint32_t rgb);
void raster_fill_rect(raster *r, double x0, double y0, double x1, double y1,
                      uint32_t rgb);
/* the outline of a rectangle, WIDTH wide, centred on its edges */
void raster_stroke_rect(raster *r, double x0, double y0, double x1, double y1,
                        double width, uint32_t rgb);
/* a coverage mask (0..255, W x H, row stride STRIDE) with its top-left
 * pixel at (x, y), in RGB */
void raster_mask(raster *r, const uint8_t *mask, int w, int h, int stride,
                 int x, int y, uint32_t rgb);

/* Draw the shapes recorded, in order, in bands of BAND rows from the top;
 * after each band SINK(CTX, rows, y0, n) receives its n rows from row y0
 * (palette indices into r->pal, as far as drawn).  0; -1 out of memory
 * (now or while recording); else what SINK returned when not 0. */
int raster_render(raster *r, int band,
                  int (*sink)(void *ctx, const uint8_t *rows, int y0, int n), void *ctx);

/* The whole picture, w * h palette indices (row-major, into r->pal), drawn
 * from the shapes recorded; NULL when out of memory.  Valid until the next
 * call on r. */
const uint8_t *raster_pixels(raster *r);

#endif

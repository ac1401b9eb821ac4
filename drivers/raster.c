/* drivers/raster.c — the canvas of raster.h: each shape is recorded with
 * the clip it was given and the rows it can reach; raster_render then
 * draws the record band by band (raster_draw.c), each band only the
 * shapes that reach it, cut to the band, and hands the band's rows on.
 * The palette is built as the bands are drawn, so it is complete only
 * when the last band is (the PNG writes it after the image's data).
 * SPDX-License-Identifier: BSD-3-Clause */
#include "raster.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "raster_impl.h"

typedef enum op_kind { OP_POLYLINE, OP_DISC, OP_RING, OP_RECT, OP_MASK } op_kind;

/* A recorded shape: its kind and colour, the clip it was drawn with, the
 * rows it can reach (j0..j1: none when j0 > j1), its numbers (a polyline's
 * x[n], y[n] and dash[ndash] at nums + at; a mask's bytes at bytes + at)
 * and its scalars v[] (polyline: width; disc: cx, cy, radius; ring: cx,
 * cy, radius, width; rectangle: x0, y0, x1, y1; mask: x, y, w, h). */
struct raster_op {
  op_kind kind;
  uint32_t rgb;
  double clip[4];
  int j0, j1;
  size_t at, n;
  int ndash;
  double v[4];
};

raster *raster_new(int w, int h, uint32_t bg) {
  if (w < 1 || h < 1 || w > 16384 || h > 16384) return NULL;
  raster *r = calloc(1, sizeof *r);
  if (!r) return NULL;
  r->w = w;
  r->h = h;
  r->cap = 4096;
  r->touch = malloc(r->cap * sizeof *r->touch);
  if (!r->touch) {
    free(r);
    return NULL;
  }
  raster_clear(r, bg);
  return r;
}

void raster_clear(raster *r, uint32_t bg) {
  r->bg = bg;
  r->nops = r->nnums = r->nbytes = 0;
  r->failed = 0;
  raster_clip_all(r);
}

void raster_free(raster *r) {
  if (!r) return;
  free(r->px);
  free(r->cov);
  free(r->touch);
  free(r->ops);
  free(r->nums);
  free(r->bytes);
  free(r->all);
  free(r);
}

void raster_set_clip(raster *r, double x0, double y0, double x1, double y1) {
  r->clip[0] = fmax(0.0, fmin(x0, x1));
  r->clip[1] = fmax(0.0, fmin(y0, y1));
  r->clip[2] = fmin((double)r->w, fmax(x0, x1));
  r->clip[3] = fmin((double)r->h, fmax(y0, y1));
}

void raster_clip_all(raster *r) { raster_set_clip(r, 0, 0, r->w, r->h); }

/* ---- the record ---------------------------------------------------------- */

/* Room for N more items of SIZE bytes in *P (*len used, *cap allocated). */
static int grow(void **p, size_t *cap, size_t len, size_t n, size_t size) {
  if (len + n <= *cap) return 0;
  size_t c = *cap ? 2 * *cap : 256;
  while (c < len + n) c *= 2;
  void *q = realloc(*p, c * size);
  if (!q) return -1;
  *p = q;
  *cap = c;
  return 0;
}

/* A new shape of KIND and colour RGB reaching rows ylo..yhi (pixels, any
 * order of magnitude), with the current clip; NULL when out of memory or
 * when it reaches no row of the clip. */
static raster_op *add_op(raster *r, op_kind kind, uint32_t rgb, double ylo, double yhi) {
  const double lo = fmax(ylo, r->clip[1]), hi = fmin(yhi, r->clip[3]);
  if (!(lo <= hi)) return NULL;
  if (grow((void **)&r->ops, &r->opcap, r->nops, 1, sizeof *r->ops)) {
    r->failed = 1;
    return NULL;
  }
  raster_op *op = &r->ops[r->nops++];
  memset(op, 0, sizeof *op);
  op->kind = kind;
  op->rgb = rgb;
  memcpy(op->clip, r->clip, sizeof op->clip);
  op->j0 = (int)floor(lo) - 1;
  op->j1 = (int)ceil(hi) + 1;
  return op;
}

void raster_polyline(raster *r, const double *x, const double *y, size_t n,
                     double width, const double *dash, int ndash, uint32_t rgb) {
  double ylo = INFINITY, yhi = -INFINITY;
  for (size_t i = 0; i < n; i++)
    if (isfinite(x[i]) && isfinite(y[i])) {
      ylo = fmin(ylo, y[i]);
      yhi = fmax(yhi, y[i]);
    }
  const double reach = fabs(0.5 * width) + 1.0;
  if (ndash < 0) ndash = 0;
  if (grow((void **)&r->nums, &r->numcap, r->nnums, 2 * n + (size_t)ndash, sizeof *r->nums)) {
    r->failed = 1;
    return;
  }
  raster_op *op = add_op(r, OP_POLYLINE, rgb, ylo - reach, yhi + reach);
  if (!op) return;
  op->at = r->nnums;
  op->n = n;
  op->ndash = ndash;
  op->v[0] = width;
  if (n) {
    memcpy(r->nums + r->nnums, x, n * sizeof *x);
    memcpy(r->nums + r->nnums + n, y, n * sizeof *y);
  }
  if (ndash) memcpy(r->nums + r->nnums + 2 * n, dash, (size_t)ndash * sizeof *dash);
  r->nnums += 2 * n + (size_t)ndash;
}

void raster_line(raster *r, double x0, double y0, double x1, double y1,
                 double width, const double *dash, int ndash, uint32_t rgb) {
  const double x[2] = {x0, x1}, y[2] = {y0, y1};
  raster_polyline(r, x, y, 2, width, dash, ndash, rgb);
}

void raster_disc(raster *r, double cx, double cy, double radius, uint32_t rgb) {
  const double reach = fabs(radius) + 1.0;
  raster_op *op = add_op(r, OP_DISC, rgb, cy - reach, cy + reach);
  if (!op) return;
  op->v[0] = cx;
  op->v[1] = cy;
  op->v[2] = radius;
}

void raster_ring(raster *r, double cx, double cy, double radius, double width,
                 uint32_t rgb) {
  const double reach = fabs(radius) + fabs(0.5 * width) + 1.0;
  raster_op *op = add_op(r, OP_RING, rgb, cy - reach, cy + reach);
  if (!op) return;
  op->v[0] = cx;
  op->v[1] = cy;
  op->v[2] = radius;
  op->v[3] = width;
}

void raster_fill_rect(raster *r, double x0, double y0, double x1, double y1,
                      uint32_t rgb) {
  raster_op *op = add_op(r, OP_RECT, rgb, fmin(y0, y1), fmax(y0, y1));
  if (!op) return;
  op->v[0] = x0;
  op->v[1] = y0;
  op->v[2] = x1;
  op->v[3] = y1;
}

void raster_stroke_rect(raster *r, double x0, double y0, double x1, double y1,
                        double width, uint32_t rgb) {
  const double hw = 0.5 * width;
  raster_fill_rect(r, x0 - hw, y0 - hw, x1 + hw, y0 + hw, rgb);
  raster_fill_rect(r, x0 - hw, y1 - hw, x1 + hw, y1 + hw, rgb);
  raster_fill_rect(r, x0 - hw, y0 + hw, x0 + hw, y1 - hw, rgb);
  raster_fill_rect(r, x1 - hw, y0 + hw, x1 + hw, y1 - hw, rgb);
}

void raster_mask(raster *r, const uint8_t *mask, int w, int h, int stride,
                 int x, int y, uint32_t rgb) {
  if (w < 1 || h < 1) return;
  const size_t size = (size_t)w * (size_t)h;
  if (grow((void **)&r->bytes, &r->bytecap, r->nbytes, size, 1)) {
    r->failed = 1;
    return;
  }
  raster_op *op = add_op(r, OP_MASK, rgb, y, (double)y + h);
  if (!op) return;
  op->at = r->nbytes;
  op->v[0] = x;
  op->v[1] = y;
  op->v[2] = w;
  op->v[3] = h;
  for (int j = 0; j < h; j++)
    memcpy(r->bytes + r->nbytes + (size_t)j * (size_t)w, mask + (size_t)j * (size_t)stride,
           (size_t)w);
  r->nbytes += size;
}

/* ---- drawing the record ---------------------------------------------------- */

static void draw_op(raster *r, const raster_op *op) {
  const double *v = op->v;
  switch (op->kind) {
  case OP_POLYLINE: {
    const double *x = r->nums + op->at, *y = x + op->n;
    band_polyline(r, x, y, op->n, v[0], op->ndash ? y + op->n : NULL, op->ndash, op->rgb);
    break;
  }
  case OP_DISC: band_disc(r, v[0], v[1], v[2], op->rgb); break;
  case OP_RING: band_ring(r, v[0], v[1], v[2], v[3], op->rgb); break;
  case OP_RECT: band_fill_rect(r, v[0], v[1], v[2], v[3], op->rgb); break;
  case OP_MASK:
    band_mask(r, r->bytes + op->at, (int)v[2], (int)v[3], (int)v[2], (int)v[0], (int)v[1],
              op->rgb);
    break;
  }
}

/* Draw the record on the band of rows row0 .. row0 + rows - 1. */
static void draw_band(raster *r, int row0, int rows) {
  r->row0 = row0;
  r->rows = rows;
  memset(r->px, 0, (size_t)rows * (size_t)r->w); /* palette index 0: background */
  for (size_t k = 0; k < r->nops; k++) {
    const raster_op *op = &r->ops[k];
    if (op->j1 < row0 || op->j0 >= row0 + rows) continue;
    r->clip[0] = op->clip[0];
    r->clip[1] = fmax(op->clip[1], (double)row0);
    r->clip[2] = op->clip[2];
    r->clip[3] = fmin(op->clip[3], (double)(row0 + rows));
    draw_op(r, op);
  }
}

/* Band buffers of ROWS rows; -1 when out of memory. */
static int band_memory(raster *r, int rows) {
  const size_t need = (size_t)rows * (size_t)r->w;
  if (need <= r->band_cap) return 0;
  uint8_t *px = malloc(need), *cov = calloc(need, 1);
  if (!px || !cov) {
    free(px);
    free(cov);
    return -1;
  }
  free(r->px);
  free(r->cov);
  r->px = px;
  r->cov = cov;
  r->band_cap = need;
  return 0;
}

int raster_render(raster *r, int band,
                  int (*sink)(void *ctx, const uint8_t *rows, int y0, int n), void *ctx) {
  if (band < 1) band = 1;
  if (band > r->h) band = r->h;
  if (r->failed || band_memory(r, band)) return -1;
  const double clip[4] = {r->clip[0], r->clip[1], r->clip[2], r->clip[3]};
  memset(r->slot, 0xff, sizeof r->slot);
  r->npal = 0;
  r->ntouch = 0;
  (void)band_colour_index(r, r->bg); /* index 0: the cleared band is background */
  int rc = 0;
  for (int y = 0; y < r->h && !rc; y += band) {
    const int rows = r->h - y < band ? r->h - y : band;
    draw_band(r, y, rows);
    rc = sink(ctx, r->px, y, rows);
  }
  memcpy(r->clip, clip, sizeof clip); /* the recording's clip, for shapes to come */
  return rc;
}

static int into_all(void *ctx, const uint8_t *rows, int y0, int n) {
  raster *r = ctx;
  memcpy(r->all + (size_t)y0 * (size_t)r->w, rows, (size_t)n * (size_t)r->w);
  return 0;
}

const uint8_t *raster_pixels(raster *r) {
  if (!r->all && !(r->all = malloc((size_t)r->w * (size_t)r->h))) return NULL;
  return raster_render(r, r->h, into_all, r) ? NULL : r->all;
}

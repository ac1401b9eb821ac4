/* drivers/raster_impl.h — inside the canvas of raster.h: the recorded
 * shapes (raster.c) and their drawing on one band of rows
 * (raster_draw.c).  The band_ functions draw on r->px and r->cov, rows
 * r->row0 .. r->row0 + r->rows - 1, cut to r->clip (which must lie within
 * those rows), and blend each shape into the band once.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_RASTER_IMPL_H
#define WHIRL_DRIVERS_RASTER_IMPL_H

#include "raster.h"

/* The palette index of colour C: found, added, or (the palette full) the
 * nearest colour's. */
int band_colour_index(raster *r, uint32_t c);

void band_polyline(raster *r, const double *x, const double *y, size_t n, double width,
                   const double *dash, int ndash, uint32_t rgb);
void band_disc(raster *r, double cx, double cy, double radius, uint32_t rgb);
void band_ring(raster *r, double cx, double cy, double radius, double width, uint32_t rgb);
void band_fill_rect(raster *r, double x0, double y0, double x1, double y1, uint32_t rgb);
void band_mask(raster *r, const uint8_t *mask, int w, int h, int stride, int x, int y,
               uint32_t rgb);

#endif

/* drivers/png_write.h — a small, fast PNG encoder for the in-process
 * picture renderer, without dependencies.  Pictures are mostly one
 * background colour with anti-aliased lines and text, so the encoder codes
 * runs of equal pixels only (fixed-Huffman DEFLATE, no match search): an
 * 8-bit palette image when there are at most 256 colours, else 8-bit RGB.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_PNG_WRITE_H
#define WHIRL_PNG_WRITE_H

#include <stdint.h>
#include <stdio.h>

/* Write W x H pixels PIX (row-major, top row first, each 0x00RRGGBB; the
 * top byte is ignored) to F as a PNG, and flush F.
 * Returns 0, or -1 with errno set (a write error; EINVAL for W or H out of
 * range 1..65535 or a null F or PIX; ENOMEM). */
int png_write_rgb(FILE *f, const uint32_t *pix, int w, int h);

/* Write W x H palette indices IDX (row-major, top row first) with the
 * NPAL colours PAL (0x00RRGGBB; every index < NPAL) to F as an 8-bit
 * palette PNG, and flush F.  Returns as png_write_rgb (EINVAL also for
 * NPAL out of 1..256). */
int png_write_indexed(FILE *f, const uint8_t *idx, int w, int h, const uint32_t *pal,
                      int npal);

/* The same, coded as the rows come (raster.h draws a picture in bands)
 * and written with the palette, which is complete only at the end: NEW
 * (NULL with errno EINVAL or ENOMEM), ADD N more rows of W palette
 * indices, WRITE once all H rows are in (then the palette: every index
 * < NPAL), FREE.  ADD and WRITE return 0, or -1 with errno set. */
typedef struct png_rows png_rows;
png_rows *png_rows_new(int w, int h);
int png_rows_add(png_rows *s, const uint8_t *idx, int n);
int png_rows_write(png_rows *s, FILE *f, const uint32_t *pal, int npal);
void png_rows_free(png_rows *s); /* accepts NULL */

#endif

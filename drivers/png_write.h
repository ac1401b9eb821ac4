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

#endif

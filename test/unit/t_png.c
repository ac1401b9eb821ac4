/* test/unit/t_png.c — the PNG encoder (drivers/png_write.c) against an
 * independent decoder: this file parses each PNG itself (signature, chunk
 * order, lengths, CRCs by zlib's crc32(), IHDR fields), inflates the IDATs
 * with zlib (which checks the Adler-32), undoes filter 0 and the palette
 * and compares every pixel with the input.  The images: 1 x 1; a white
 * 1100 x 750 with anti-aliased diagonal lines in 5 colours (palette); noise
 * with more than 256 colours (RGB); widths 1, 2, 3, 257, 1000 and 65535;
 * runs of 1, 2, 3, 4, 258..262 and 517 pixels in both modes; exactly 256
 * and 257 colours; several IDAT chunks; the longest runs of the largest
 * bytes (the largest Adler-32 terms).  The Adler-32 in the stream is also
 * compared with a plain byte-by-byte sum, and write errors and bad sizes
 * must be refused.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "../tap.h"
#include "png_write.h"

/* ---- an independent reader */

typedef struct png_img {
  uint32_t w, h;
  int ctype;         /* 2 RGB, 3 palette */
  unsigned npal;     /* palette entries */
  unsigned nidat;    /* IDAT chunks */
  uint32_t *pix;     /* decoded, 0x00RRGGBB */
} png_img;

static uint32_t be32(const uint8_t *p) {
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Plain byte-by-byte Adler-32 (RFC 1950). */
static uint32_t adler_plain(const uint8_t *p, size_t n) {
  uint32_t s1 = 1, s2 = 0;
  for (size_t i = 0; i < n; ++i) {
    s1 = (s1 + p[i]) % 65521;
    s2 = (s2 + s1) % 65521;
  }
  return s2 << 16 | s1;
}

/* Inflate Z (N bytes) into exactly RAW_N bytes, the zlib stream ending
 * exactly at Z's end (zlib checks the Adler-32); then the stream's trailer
 * against adler_plain.  *MSG: zlib's message, if any. */
static const char *inflate_all(const uint8_t *z, size_t n, uint8_t *raw, size_t raw_n,
                               char msg[128]) {
  if (n < 7 || z[0] != 0x78 || (z[0] * 256 + z[1]) % 31) return "bad zlib header";
  if (((z[2] >> 1) & 3) != 1) return "first block not fixed Huffman";
  z_stream s;
  memset(&s, 0, sizeof s);
  if (inflateInit(&s) != Z_OK) return "inflateInit failed";
  s.next_in = (Bytef *)(uintptr_t)z; /* zlib's API is not const */
  s.avail_in = (uInt)n;
  s.next_out = raw;
  s.avail_out = (uInt)raw_n;
  const int rc = inflate(&s, Z_FINISH);
  const size_t got = raw_n - s.avail_out, left = s.avail_in;
  snprintf(msg, 128, "inflate: %s", s.msg ? s.msg : "stream incomplete or too long");
  inflateEnd(&s);
  if (rc != Z_STREAM_END) return msg;
  if (got != raw_n) return "inflated size differs";
  if (left) return "bytes after the zlib stream";
  if (be32(z + n - 4) != adler_plain(raw, raw_n)) return "Adler-32 differs from the plain sum";
  return NULL;
}

/* Chunks one by one: CRC, order, IHDR, PLTE, IDATs gathered in *Z. */
static const char *read_chunks(const uint8_t *s, size_t n, png_img *im, uint32_t *pal,
                               uint8_t **z, size_t *zn) {
  static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (n < 8 || memcmp(s, sig, 8)) return "bad signature";
  int seen_iend = 0, idat_done = 0;
  for (size_t at = 8; at < n;) {
    if (seen_iend) return "data after IEND";
    if (n - at < 12) return "truncated chunk";
    const uint32_t len = be32(s + at);
    if (len > n - at - 12) return "chunk length past the end";
    const uint8_t *type = s + at + 4, *data = s + at + 8;
    if (be32(data + len) != (uint32_t)crc32(0, type, len + 4)) return "bad CRC";
    if (at == 8 && memcmp(type, "IHDR", 4)) return "IHDR not first";
    if (!memcmp(type, "IHDR", 4)) {
      if (at != 8 || len != 13) return "bad IHDR";
      im->w = be32(data);
      im->h = be32(data + 4);
      im->ctype = data[9];
      if (data[8] != 8 || (data[9] != 2 && data[9] != 3) || data[10] || data[11] || data[12])
        return "bad IHDR fields";
    } else if (!memcmp(type, "PLTE", 4)) {
      if (len % 3 || len == 0 || len > 768 || im->nidat) return "bad PLTE";
      im->npal = len / 3;
      for (unsigned i = 0; i < im->npal; ++i)
        pal[i] = (uint32_t)data[3 * i] << 16 | (uint32_t)data[3 * i + 1] << 8 | data[3 * i + 2];
    } else if (!memcmp(type, "IDAT", 4)) {
      if (idat_done) return "IDAT chunks not consecutive";
      uint8_t *t = realloc(*z, *zn + len + 1);
      if (!t) return "out of memory";
      *z = t;
      memcpy(*z + *zn, data, len);
      *zn += len;
      im->nidat++;
    } else if (!memcmp(type, "IEND", 4)) {
      if (len) return "IEND not empty";
      seen_iend = 1;
    } else {
      return "unexpected chunk";
    }
    if (im->nidat && memcmp(type, "IDAT", 4)) idat_done = 1;
    at += 12 + (size_t)len;
  }
  if (!seen_iend || !im->nidat) return "IEND or IDAT missing";
  if (im->ctype == 3 && !im->npal) return "palette image without PLTE";
  return NULL;
}

/* Undo filter 0 and the palette of the inflated rows RAW into IM->pix. */
static const char *unfilter(const uint8_t *raw, png_img *im, const uint32_t *pal) {
  const size_t bpp = im->ctype == 3 ? 1 : 3, row = 1 + bpp * im->w;
  for (size_t y = 0; y < im->h; ++y) {
    const uint8_t *r = raw + y * row;
    if (r[0] != 0) return "filter type not 0";
    for (size_t x = 0; x < im->w; ++x) {
      const uint8_t *q = r + 1 + bpp * x;
      if (bpp == 1 && q[0] >= im->npal) return "palette index out of range";
      im->pix[y * im->w + x] =
          bpp == 1 ? pal[q[0]] : (uint32_t)q[0] << 16 | (uint32_t)q[1] << 8 | q[2];
    }
  }
  return NULL;
}

/* Decode the PNG S (N bytes) into IM; NULL, or what is wrong. */
static const char *png_read(const uint8_t *s, size_t n, png_img *im) {
  static char msg[128];
  uint32_t pal[256];
  uint8_t *z = NULL, *raw = NULL;
  size_t zn = 0;
  memset(im, 0, sizeof *im);
  const char *err = read_chunks(s, n, im, pal, &z, &zn);
  if (!err && (im->w == 0 || im->h == 0)) err = "zero size";
  const size_t raw_n = err ? 0 : im->h * (1 + (im->ctype == 3 ? 1 : 3) * (size_t)im->w);
  if (!err && !(raw = malloc(raw_n)) ) err = "out of memory";
  if (!err) err = inflate_all(z, zn, raw, raw_n, msg);
  if (!err && !(im->pix = malloc(sizeof(uint32_t) * im->w * im->h))) err = "out of memory";
  if (!err) err = unfilter(raw, im, pal);
  free(z);
  free(raw);
  return err;
}

/* ---- helpers */

/* Encode into memory; the bytes in *OUT (free them), their count in *N. */
static int encode(const uint32_t *pix, int w, int h, uint8_t **out, size_t *n) {
  char *buf = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&buf, &len);
  if (!f) return -1;
  const int rc = png_write_rgb(f, pix, w, h);
  fclose(f);
  *out = (uint8_t *)buf;
  *n = len;
  return rc;
}

/* The number of distinct colours (top byte ignored), by sorting a copy. */
static int cmp_u32(const void *a, const void *b) {
  const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
  return (x > y) - (x < y);
}
static size_t distinct(const uint32_t *pix, size_t n) {
  uint32_t *c = malloc(n * sizeof *c);
  if (!c) return 0;
  for (size_t i = 0; i < n; ++i) c[i] = pix[i] & 0xFFFFFF;
  qsort(c, n, sizeof *c, cmp_u32);
  size_t d = 1;
  for (size_t i = 1; i < n; ++i) d += c[i] != c[i - 1];
  free(c);
  return d;
}

/* Encode, decode and compare: one TAP line.  The colour type must be
 * palette iff there are <= 256 colours, with a palette of exactly those;
 * *NIDAT (if not NULL) gets the IDAT count, *BYTES the PNG's size. */
static int roundtrip(const char *name, const uint32_t *pix, int w, int h, unsigned *nidat,
                     size_t *bytes) {
  uint8_t *s = NULL;
  size_t n = 0;
  png_img im = {0};
  const size_t npix = (size_t)w * (size_t)h, ncol = distinct(pix, npix);
  const char *err = encode(pix, w, h, &s, &n) ? "png_write_rgb failed" : png_read(s, n, &im);
  if (!err && (im.w != (uint32_t)w || im.h != (uint32_t)h)) err = "IHDR size differs";
  if (!err && im.ctype != (ncol <= 256 ? 3 : 2)) err = "wrong colour type";
  if (!err && im.ctype == 3 && im.npal != ncol) err = "palette size is not the colour count";
  for (size_t i = 0; !err && i < npix; ++i)
    if (im.pix[i] != (pix[i] & 0xFFFFFF)) err = "a pixel differs";
  if (!err && nidat) *nidat = im.nidat;
  if (!err && bytes) *bytes = n;
  ok(!err, "%s (%dx%d, %zu colours, %zu bytes)", name, w, h, ncol, n);
  if (err) printf("#   %s\n", err);
  free(im.pix);
  free(s);
  return !err;
}

static uint32_t rnd32(void) { return (uint32_t)tap_urand(0, 4294967296.0); }

/* C blended with white at coverage A in [0, 1]. */
static uint32_t blend(uint32_t c, double a) {
  uint32_t out = 0;
  for (int sh = 0; sh < 24; sh += 8) {
    const double v = ((c >> sh) & 0xFF) * a + 255 * (1 - a);
    out |= (uint32_t)(v + 0.5) << sh;
  }
  return out;
}

/* ---- the tests */

static void test_small(void) {
  const uint32_t one = 0x123456;
  roundtrip("1x1", &one, 1, 1, NULL, NULL);
  const uint32_t two[2] = {0xFFFFFF, 0xFFFFFF};
  roundtrip("2x1 one colour", two, 2, 1, NULL, NULL);
  roundtrip("1x2 one colour", two, 1, 2, NULL, NULL);
}

/* White 1100 x 750 with diagonal lines in 5 colours, each pixel at 4
 * levels of coverage by its distance from the line (no libm: a rough
 * normal distance will do). */
static void test_lines(void) {
  const int w = 1100, h = 750;
  static const uint32_t col[5] = {0xFF0000, 0x0000FF, 0x008000, 0x000000, 0xFF8C00};
  uint32_t *pix = malloc(sizeof *pix * w * h);
  for (int i = 0; i < w * h; ++i) pix[i] = 0xFFFFFF;
  for (int l = 0; l < 40; ++l) {
    const double slope = 0.2 + 0.13 * l, off = -400 + 37 * l;
    for (int x = 0; x < w; ++x) {
      const double yc = off + slope * x;
      for (int y = (int)yc - 2; y <= (int)yc + 2; ++y) {
        if (y < 0 || y >= h) continue;
        const double d = fabs(y - yc) / (1 + 0.7 * slope); /* ~ the normal distance */
        const double a = d < 0.4 ? 1 : d < 0.8 ? 0.66 : d < 1.2 ? 0.4 : 0.15;
        if (d < 1.5) pix[y * w + x] = blend(col[l % 5], a);
      }
    }
  }
  size_t bytes = 0;
  roundtrip("white with anti-aliased lines, palette", pix, w, h, NULL, &bytes);
  ok(bytes > 0 && bytes < (size_t)w * h / 8, "lines picture: %zu bytes < 1/8 of the pixel bytes",
     bytes);
  for (int i = 0; i < w * h; ++i) pix[i] = 0xFFFFFF;
  roundtrip("all white 1100x750", pix, w, h, NULL, &bytes);
  ok(bytes < 12000, "all white 1100x750 is small: %zu bytes", bytes);
  size_t bytes_ff = 0;
  for (int i = 0; i < w * h; ++i) pix[i] = 0xFFFFFFFF;
  roundtrip("all white with top byte 0xFF", pix, w, h, NULL, &bytes_ff);
  ok(bytes_ff == bytes, "a constant top byte changes nothing (%zu bytes)", bytes_ff);
  for (int i = 0; i < w * h; ++i) pix[i] = 0xFFFFFF | (uint32_t)(i & 0xFF) << 24;
  roundtrip("all white with varying garbage in the top byte", pix, w, h, NULL, NULL);
  free(pix);
}

/* Random noise, more than 256 colours (RGB), and with 4 colours. */
static void test_noise(void) {
  uint32_t pix[64 * 48];
  for (int i = 0; i < 64 * 48; ++i) pix[i] = rnd32() & 0xFFFFFF;
  roundtrip("random noise, RGB", pix, 64, 48, NULL, NULL);
  for (int i = 0; i < 64 * 48; ++i) pix[i] = (rnd32() & 3) * 0x3F3F3F;
  roundtrip("random 4-colour noise, palette", pix, 64, 48, NULL, NULL);
}

/* Widths 1, 2, 3, 257, 1000: short random runs, in both modes. */
static void test_widths(void) {
  static const int ws[] = {1, 2, 3, 257, 1000};
  for (size_t k = 0; k < sizeof ws / sizeof ws[0]; ++k) {
    const int w = ws[k], h = w < 100 ? 300 : 7;
    uint32_t *pix = malloc(sizeof *pix * w * h);
    for (int mode = 0; mode < 2; ++mode) {
      uint32_t c = 0;
      for (int i = 0; i < w * h; ++i) {
        if (rnd32() % 3 == 0) c = mode ? rnd32() & 0xFFFFFF : rnd32() % 7 * 0x010203;
        pix[i] = c;
      }
      char name[64];
      snprintf(name, sizeof name, "width %d, %s", w, mode ? "random colours" : "7 colours");
      roundtrip(name, pix, w, h, NULL, NULL);
    }
    free(pix);
  }
}

/* Rows of runs of the given lengths (each run a new colour), as palette
 * image and, with a noise row added, as RGB image. */
static void test_runs(void) {
  static const int len[] = {1, 2, 3, 4, 5, 6, 258, 259, 260, 261, 262, 517, 516, 777};
  const int w = 4000, h = 3;
  uint32_t *pix = malloc(sizeof *pix * w * (h + 1));
  for (int mode = 0; mode < 2; ++mode) {
    for (int y = 0; y < h; ++y) {
      int x = 0, k = y;
      uint32_t c = 0;
      while (x < w) {
        const int n = len[k++ % (sizeof len / sizeof len[0])];
        c = mode ? (c + 0x10305) & 0xFFFFFF : (c + 1) % 5 * 0x333333;
        for (int i = 0; i < n && x < w; ++i) pix[y * w + x++] = c;
      }
    }
    for (int x = 0; x < w; ++x) pix[h * w + x] = mode ? rnd32() & 0xFFFFFF : 0xFFFFFF;
    roundtrip(mode ? "runs 1..777 of RGB pixels" : "runs 1..777 of palette pixels", pix, w, h + 1,
              NULL, NULL);
  }
  free(pix);
}

/* Single runs of each length as whole rows: width = run length. */
static void test_row_runs(void) {
  static const int len[] = {1, 2, 3, 258, 259, 260, 517};
  for (size_t k = 0; k < sizeof len / sizeof len[0]; ++k) {
    const int w = len[k];
    uint32_t *pix = malloc(sizeof *pix * w * 2);
    for (int i = 0; i < w * 2; ++i) pix[i] = i < w ? 0x00FF00 : 0x0000FF;
    char name[64];
    snprintf(name, sizeof name, "rows that are one run of %d", w);
    roundtrip(name, pix, w, 2, NULL, NULL);
    free(pix);
  }
}

/* Exactly 256 colours: palette; one more: RGB. */
static void test_256(void) {
  uint32_t pix[257 * 3];
  for (int i = 0; i < 257 * 3; ++i) pix[i] = (uint32_t)(i % 256) * 0x010101;
  roundtrip("exactly 256 colours", pix, 257, 3, NULL, NULL);
  pix[257 * 3 - 1] = 0x123456;
  roundtrip("257 colours", pix, 257, 3, NULL, NULL);
}

/* The widest rows, worst case for the buffer (every byte a 9-bit literal),
 * and images whose stream spans several IDAT chunks. */
static void test_big(void) {
  const int w = 65535;
  uint32_t *pix = malloc(sizeof *pix * w * 3);
  unsigned nidat = 0;
  for (int i = 0; i < w * 3; ++i) pix[i] = rnd32() & 0xFFFFFF;
  roundtrip("width 65535, noise, RGB", pix, w, 3, &nidat, NULL);
  ok(nidat == 3, "RGB noise 65535x3: %u IDAT chunks (one a row: rows > 64 KiB)", nidat);
  roundtrip("400x300 noise, RGB", pix, 400, 300, &nidat, NULL);
  ok(nidat >= 6, "RGB noise 400x300 spans %u IDAT chunks", nidat);
  for (int i = 0; i < w * 3; ++i) pix[i] = (144 + rnd32() % 112) * 0x010101;
  for (int i = 0; i < 144; ++i) pix[i] = (uint32_t)i * 0x010101;
  roundtrip("width 65535, 256-colour noise, palette", pix, w, 3, &nidat, NULL);
  ok(nidat == 3, "palette noise 65535x3 spans %u IDAT chunks", nidat);
  for (int i = 0; i < w * 3; ++i) pix[i] = 0xABCDEF;
  roundtrip("width 65535, one colour", pix, w, 3, NULL, NULL);
  /* the largest Adler-32 terms of a row: the longest runs of the largest
   * byte values, index 255 (palette) and white (RGB) */
  for (int i = 0; i < w * 2; ++i) pix[i] = i < 255 ? (uint32_t)i : 0xFFFFFF;
  roundtrip("width 65535, runs of palette index 255", pix, w, 2, NULL, NULL);
  for (int i = 0; i < w * 2; ++i) pix[i] = i < 300 ? (uint32_t)i : 0xFFFFFF;
  roundtrip("width 65535, runs of RGB white", pix, w, 2, NULL, NULL);
  free(pix);
}

/* Bad sizes are refused; write errors are reported. */
static void test_errors(void) {
  const uint32_t pix[4] = {0};
  FILE *f = fopen("/dev/null", "w");
  errno = 0;
  ok(png_write_rgb(f, pix, 0, 1) == -1 && errno == EINVAL, "w = 0 refused (EINVAL)");
  errno = 0;
  ok(png_write_rgb(f, pix, 1, 0) == -1 && errno == EINVAL, "h = 0 refused (EINVAL)");
  ok(png_write_rgb(f, pix, 65536, 1) == -1 && png_write_rgb(f, pix, 1, 65536) == -1 &&
         png_write_rgb(f, pix, -1, 1) == -1,
     "w or h out of 1..65535 refused");
  ok(png_write_rgb(f, NULL, 1, 1) == -1 && png_write_rgb(NULL, pix, 1, 1) == -1,
     "null pixels or file refused");
  ok(png_write_rgb(f, pix, 2, 2) == 0, "a 2x2 picture to /dev/null");
  if (f) fclose(f);
  f = fopen("/dev/full", "w");
  if (f) setvbuf(f, NULL, _IONBF, 0);
  errno = 0;
  ok(f && png_write_rgb(f, pix, 2, 2) == -1 && errno == ENOSPC, "unbuffered /dev/full: -1, ENOSPC");
  if (f) fclose(f);
  f = fopen("/dev/full", "w");
  errno = 0;
  ok(f && png_write_rgb(f, pix, 2, 2) == -1 && errno == ENOSPC,
     "buffered /dev/full: -1, ENOSPC (at the flush)");
  if (f) fclose(f);
  f = fopen("/dev/null", "r");
  errno = 0;
  const int rc = f ? png_write_rgb(f, pix, 2, 2) : 0, e = errno;
  ok(rc == -1 && e != 0, "a read-only FILE: -1, errno %d", e);
  if (f) fclose(f);
}

/* png_write_indexed: indices and a palette of the caller's (the pictures
 * whirl draws itself), decoded here: every pixel is its palette colour,
 * the palette the caller's in its order; with runs of every length, widths
 * around the 8-index scan, all 256 entries, and the refusals. */
static void test_indexed(void) {
  static const int widths[] = {1, 7, 8, 9, 17, 1100};
  uint32_t pal[256];
  for (int i = 0; i < 256; ++i) pal[i] = rnd32() & 0xFFFFFF;
  for (size_t k = 0; k < sizeof widths / sizeof *widths; ++k) {
    const int w = widths[k], h = 37;
    uint8_t *idx = malloc((size_t)w * h);
    size_t i = 0;
    while (i < (size_t)w * h) { /* runs of 1..300 of one index */
      size_t run = 1 + (size_t)tap_urand(0, 300), v = (size_t)tap_urand(0, 256);
      for (; run-- && i < (size_t)w * h; ++i) idx[i] = (uint8_t)v;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    const int rc = f ? png_write_indexed(f, idx, w, h, pal, 256) : -1;
    if (f) fclose(f);
    png_img im = {0};
    const char *err = rc ? "png_write_indexed failed" : png_read((uint8_t *)buf, len, &im);
    if (!err && (im.ctype != 3 || im.npal != 256)) err = "not a palette of 256";
    for (size_t j = 0; !err && j < (size_t)w * h; ++j)
      if (im.pix[j] != pal[idx[j]]) err = "a pixel differs";
    ok(!err, "indexed %dx%d, runs of 1..300, 256 entries (%zu bytes)", w, h, len);
    if (err) printf("#   %s\n", err);
    free(im.pix);
    free(buf);
    free(idx);
  }
  const uint8_t idx[4] = {0, 1, 1, 0};
  FILE *f = fopen("/dev/null", "w");
  errno = 0;
  ok(f && png_write_indexed(f, idx, 2, 2, pal, 0) == -1 && errno == EINVAL &&
         png_write_indexed(f, idx, 2, 2, pal, 257) == -1 &&
         png_write_indexed(f, idx, 0, 2, pal, 2) == -1 &&
         png_write_indexed(f, NULL, 2, 2, pal, 2) == -1,
     "indexed: a palette of 0 or 257, w = 0, no indices refused (EINVAL)");
  if (f) fclose(f);
  f = fopen("/dev/full", "w");
  errno = 0;
  ok(f && png_write_indexed(f, idx, 2, 2, pal, 2) == -1 && errno == ENOSPC,
     "indexed to /dev/full: -1, ENOSPC");
  if (f) fclose(f);
}

/* png_rows: rows added in bands of uneven height give the very bytes of
 * png_write_indexed in one go, also past 64 KiB of code (several IDAT
 * chunks); writing before the last row, or adding past it, is refused. */
static void test_rows(void) {
  uint32_t pal[256];
  for (int i = 0; i < 256; ++i) pal[i] = rnd32() & 0xFFFFFF;
  const int w = 300, h = 400; /* noise: ~120 kB of code */
  uint8_t *idx = malloc((size_t)w * h);
  for (size_t i = 0; i < (size_t)w * h; ++i) idx[i] = (uint8_t)tap_urand(0, 256);
  char *one = NULL, *bands = NULL;
  size_t n1 = 0, n2 = 0;
  FILE *f = open_memstream(&one, &n1);
  const int r1 = png_write_indexed(f, idx, w, h, pal, 256);
  fclose(f);
  f = open_memstream(&bands, &n2);
  png_rows *s = png_rows_new(w, h);
  int r2 = s ? 0 : -1;
  for (int y = 0, band = 1; !r2 && y < h; y += band, band = band % 7 + 3)
    r2 = png_rows_add(s, idx + (size_t)y * w, y + band <= h ? band : h - y);
  r2 = r2 || png_rows_write(s, f, pal, 256);
  png_rows_free(s);
  fclose(f);
  ok(!r1 && !r2 && n1 == n2 && n1 > 65536 && !memcmp(one, bands, n1),
     "rows in bands of 1..9: the same %zu bytes as in one go", n1);
  free(one);
  free(bands);
  s = png_rows_new(w, h);
  f = fopen("/dev/null", "w");
  errno = 0;
  int early = s && png_rows_add(s, idx, h - 1) == 0 && png_rows_write(s, f, pal, 256) == -1 &&
              errno == EINVAL;
  errno = 0;
  int past = s && png_rows_add(s, idx, 2) == -1 && errno == EINVAL;
  ok(early && past, "png_rows: writing before the last row and adding past it refused (EINVAL)");
  ok(png_rows_new(0, 5) == NULL && errno == EINVAL, "png_rows_new(0, 5): NULL, EINVAL");
  png_rows_free(s);
  if (f) fclose(f);
  free(idx);
}

int main(void) {
  test_small();
  test_lines();
  test_noise();
  test_widths();
  test_runs();
  test_row_runs();
  test_256();
  test_big();
  test_errors();
  test_indexed();
  test_rows();
  return done_testing();
}

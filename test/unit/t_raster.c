/* test/unit/t_raster.c — the canvas of the pictures whirl draws itself
 * (drivers/raster.c) against geometry: the ink a shape leaves (the sum over
 * pixels of how far each went from white to black) is its area — a disc's
 * pi r^2, a thick segment's length times width plus its round caps — and
 * where it is; a polyline's joints are not inked twice; dashes leave their
 * share of the ink; a dashed line running 10^12 pixels off the canvas ends
 * at once (it walked every dash before: the fuzz target's slowest input).
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include "../tap.h"
#include "raster.h"

/* The ink of the canvas (black on white), in pixels: the sum of 1 - grey. */
static double ink(raster *r) {
  const uint8_t *px = raster_pixels(r);
  double s = 0;
  for (size_t k = 0; px && k < (size_t)r->w * (size_t)r->h; k++)
    s += 1.0 - (double)(r->pal[px[k]] & 0xff) / 255.0;
  return px ? s : -1;
}

/* the ink's centre */
static void centre(raster *r, double *cx, double *cy) {
  const uint8_t *px = raster_pixels(r);
  double s = 0, sx = 0, sy = 0;
  for (int j = 0; px && j < r->h; j++)
    for (int i = 0; i < r->w; i++) {
      const double a = 1.0 - (double)(r->pal[px[(size_t)j * (size_t)r->w + (size_t)i]] & 0xff) / 255.0;
      s += a;
      sx += a * (i + 0.5);
      sy += a * (j + 0.5);
    }
  *cx = sx / s;
  *cy = sy / s;
}

/* raster_render's sink: the band's colours into the picture CTX */
typedef struct picture {
  raster *r;
  uint32_t *rgb;
} picture;

static int into_rgb(void *ctx, const uint8_t *rows, int y0, int n) {
  picture *p = ctx;
  for (size_t k = 0; k < (size_t)n * (size_t)p->r->w; k++)
    p->rgb[(size_t)y0 * (size_t)p->r->w + k] = p->r->pal[rows[k]];
  return 0;
}

/* Drawn in bands of BAND rows and drawn whole: the same colour in every
 * pixel (the palettes' orders may differ). */
static int same_in_bands(raster *r, int band) {
  const size_t n = (size_t)r->w * (size_t)r->h;
  uint32_t *banded = malloc(n * sizeof *banded), *whole = malloc(n * sizeof *whole);
  picture p = {r, banded};
  int same = banded && whole && raster_render(r, band, into_rgb, &p) == 0;
  const uint8_t *px = same ? raster_pixels(r) : NULL;
  for (size_t k = 0; px && k < n; k++) whole[k] = r->pal[px[k]];
  for (size_t k = 0; px && k < n && same; k++) same = banded[k] == whole[k];
  free(banded);
  free(whole);
  return same && px;
}

static void on_alarm(int sig) {
  (void)sig;
  static const char msg[] = "not ok - a dashed line far off the canvas did not end in 5 s\n";
  if (write(1, msg, sizeof msg - 1) < 0) _exit(2);
  _exit(1);
}

int main(void) {
  raster *r = raster_new(200, 200, 0xffffff);
  const double pi = 3.14159265358979;

  raster_disc(r, 100.3, 80.6, 20, 0);
  double a = ink(r), cx, cy;
  centre(r, &cx, &cy);
  ok(fabs(a - pi * 400) < 0.01 * pi * 400 && fabs(cx - 100.3) < 0.05 && fabs(cy - 80.6) < 0.05,
     "a disc of radius 20: ink %.1f (pi r^2 = %.1f), centre (%.2f, %.2f)", a, pi * 400, cx, cy);

  raster_clear(r, 0xffffff);
  raster_line(r, 30, 40, 150, 130, 3, NULL, 0, 0); /* length 150 */
  a = ink(r);
  const double want = 150 * 3 + pi * 1.5 * 1.5;
  ok(fabs(a - want) < 0.02 * want, "a segment 150 long, 3 wide, round caps: ink %.1f (%.1f)", a, want);

  raster_clear(r, 0xffffff);
  const double x[5] = {20, 60, 100, 140, 180}, y[5] = {100, 60, 100, 60, 100};
  raster_polyline(r, x, y, 5, 4, NULL, 0, 0);
  a = ink(r);
  const double len = 4 * sqrt(2.0) * 40;
  ok(a < len * 4 + pi * 4 + 0.03 * len * 4 && a > 0.95 * len * 4,
     "a zigzag of 4 segments, 4 wide: ink %.1f, not inked twice at its joints (%.1f)", a,
     len * 4 + pi * 4);

  raster_clear(r, 0xffffff);
  const double dash[2] = {6, 6};
  raster_line(r, 10, 50.5, 190, 50.5, 1, dash, 2, 0);
  a = ink(r);
  ok(fabs(a - 90) < 6, "a dashed line 180 long, dashes 6 on 6 off: ink %.1f (90)", a);

  raster_clear(r, 0xffffff);
  signal(SIGALRM, on_alarm);
  alarm(5);
  raster_line(r, -1e12, -1e12, 1e12, 1e12, 2, dash, 2, 0);
  alarm(0);
  a = ink(r);
  /* half the diagonal's length, 2 wide, and a round cap of radius 1 at
   * either end of each dash of 6 (one disc each) */
  const double diag = 200 * sqrt(2.0), dashed = diag + diag / 12 * pi;
  ok(fabs(a - dashed) < 0.05 * dashed, "a dashed line from -1e12 to 1e12: ended, ink %.1f "
     "on the canvas's diagonal (%.1f)", a, dashed);

  raster_clear(r, 0xffffff);
  raster_set_clip(r, 50, 50, 150, 150);
  raster_disc(r, 50, 50, 20, 0);
  a = ink(r);
  ok(fabs(a - pi * 100) < 0.05 * pi * 100, "a disc on the clip's corner: a quarter inked (%.1f, %.1f)",
     a, pi * 100);

  /* every kind of shape, across bands, clipped and not */
  raster_clear(r, 0xffffff);
  raster_disc(r, 100, 100, 33.3, 0xd62728);
  raster_ring(r, 60, 140, 25, 2, 0x1f4e9c);
  raster_stroke_rect(r, 10.5, 10.5, 189.5, 189.5, 1, 0);
  raster_line(r, 10, 50.5, 190, 50.5, 1, dash, 2, 0x808080);
  raster_set_clip(r, 20, 20, 180, 180);
  raster_polyline(r, x, y, 5, 2.5, NULL, 0, 0x2ca02c);
  raster_fill_rect(r, 30.3, 150.7, 170.2, 175.1, 0x9400d3);
  uint8_t mask[9 * 13];
  for (int k = 0; k < 9 * 13; k++) mask[k] = (uint8_t)(k * 37);
  raster_mask(r, mask, 9, 13, 9, 150, 27, 0x000000);
  raster_clip_all(r);
  int bands_ok = 1;
  static const int bands[] = {1, 7, 64, 200};
  for (size_t b = 0; b < sizeof bands / sizeof *bands; b++) bands_ok &= same_in_bands(r, bands[b]);
  ok(bands_ok, "discs, rings, rectangles, dashes, polylines and masks, clipped: drawn in bands "
     "of 1, 7, 64 and 200 rows, every pixel as drawn whole");
  raster_free(r);
  return done_testing();
}

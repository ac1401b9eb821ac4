/* drivers/raster_draw.c — the shapes of raster.h drawn on the band of rows
 * a canvas holds (raster.c replays them band by band).  A shape's coverage
 * of each pixel is the box filter of its distance: a pixel whose centre
 * lies d from a stroke of half-width hw is covered
 * min(1, max(0, hw + 0.5 - d)) (the usual one-pixel ramp of distance-based
 * anti-aliasing).  Coverage is kept per shape as the maximum over its
 * parts, in cov[], with the pixels it touched listed, and blended into the
 * picture once (flush).  Every shape is cut to r->clip, which raster.c
 * keeps within the band.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "raster_impl.h"

/* fmin and fmax of numbers known not to be NaN, inline */
static inline double lesser(double a, double b) { return a < b ? a : b; }
static inline double greater(double a, double b) { return a > b ? a : b; }

static uint32_t blend(uint32_t old, uint32_t ink, unsigned a) {
  uint32_t out = 0;
  for (int s = 0; s <= 16; s += 8) {
    unsigned o = (old >> s) & 255u, k = (ink >> s) & 255u;
    out |= ((k * a + o * (255u - a) + 127u) / 255u) << s;
  }
  return out;
}

/* The palette index of colour C: found, added, or (the palette full) the
 * nearest colour's. */
int band_colour_index(raster *r, uint32_t c) {
  const size_t mask = sizeof r->slot / sizeof *r->slot - 1;
  size_t h = (c * 2654435761u) >> 22 & mask;
  for (; r->slot[h] >= 0; h = (h + 1) & mask)
    if (r->pal[r->slot[h]] == c) return r->slot[h];
  if (r->npal < 256) {
    r->pal[r->npal] = c;
    r->slot[h] = (int16_t)r->npal;
    return r->npal++;
  }
  int best = 0;
  long bd = -1;
  for (int i = 0; i < r->npal; i++) {
    long d = 0;
    for (int s = 0; s <= 16; s += 8) {
      long e = (long)((c >> s) & 255u) - (long)((r->pal[i] >> s) & 255u);
      d += e * e;
    }
    if (bd < 0 || d < bd) bd = d, best = i;
  }
  return best;
}

/* Keep coverage C (0..1) of pixel (i, j), inside the canvas and the clip,
 * if it exceeds what the shape has there already. */
static inline void cover_in(raster *r, int i, int j, double c) {
  if (!(c > 0)) return; /* none (a negative width covers nothing) */
  const size_t k = (size_t)(j - r->row0) * (size_t)r->w + (size_t)i;
  /* 16 levels of coverage (17 with none): shades enough for the eye, and a
   * picture's inks, their shades and where two meet stay within the
   * palette's 256 colours */
  const unsigned v = c >= 1 ? 255u : 17u * (unsigned)(c * 15.0 + 0.5);
  if (v <= r->cov[k]) return;
  if (r->cov[k] == 0) {
    if (r->ntouch == r->cap) {
      uint32_t *t = realloc(r->touch, 2 * r->cap * sizeof *t);
      if (!t) return; /* out of memory: the pixel stays as it was */
      r->touch = t;
      r->cap *= 2;
    }
    r->touch[r->ntouch++] = (uint32_t)k;
  }
  r->cov[k] = (uint8_t)v;
}

/* The pixels whose centres lie in the clip: columns i0..i1, rows j0..j1. */
static void clip_pixels(const raster *r, int *i0, int *i1, int *j0, int *j1) {
  *i0 = (int)ceil(r->clip[0] - 0.5);
  *i1 = (int)floor(r->clip[2] - 0.5);
  *j0 = (int)ceil(r->clip[1] - 0.5);
  *j1 = (int)floor(r->clip[3] - 0.5);
}

/* Blend the shape's coverage in RGB and clear it.  Neighbouring pixels
 * mostly share their colour and coverage: the last blend is reused. */
static void flush(raster *r, uint32_t rgb) {
  int last_old = -1, last_new = 0;
  unsigned last_a = 0;
  for (size_t t = 0; t < r->ntouch; t++) {
    const uint32_t k = r->touch[t];
    const unsigned a = r->cov[k];
    if (r->px[k] != last_old || a != last_a) {
      last_old = r->px[k];
      last_a = a;
      last_new = band_colour_index(r, blend(r->pal[last_old], rgb, a));
    }
    r->px[k] = (uint8_t)last_new;
    r->cov[k] = 0;
  }
  r->ntouch = 0;
}

static int clampi(double v, int lo, int hi) {
  if (!(v > lo)) return lo;
  if (v > hi) return hi;
  return (int)v;
}

/* A line one pixel wide along a row or column of pixel centres (the
 * frame, ticks, the grid's dots) covers the pixels it runs through by the
 * length it runs in each: done here without the distance of each pixel.
 * 0 for any other segment. */
static int cover_crisp(raster *r, double x0, double y0, double x1, double y1,
                       double hw) {
  const int vertical = x0 == x1, horizontal = y0 == y1;
  const double fixed = vertical ? x0 : y0;
  if (hw != 0.5 || vertical == horizontal || fixed - floor(fixed) != 0.5) return 0;
  int i0, i1, j0, j1;
  clip_pixels(r, &i0, &i1, &j0, &j1);
  const int k = (int)floor(fixed);
  const double lo = vertical ? fmin(y0, y1) : fmin(x0, x1);
  const double hi = vertical ? fmax(y0, y1) : fmax(x0, x1);
  if (vertical ? (k < i0 || k > i1) : (k < j0 || k > j1)) return 1;
  const int m0 = vertical ? j0 : i0, m1 = vertical ? j1 : i1;
  for (int m = clampi(floor(lo), m0, m1); m <= clampi(ceil(hi), m0, m1); m++) {
    const double c = fmin(m + 1.0, hi) - fmax((double)m, lo);
    if (c > 0) cover_in(r, vertical ? k : m, vertical ? m : k, c);
  }
  return 1;
}

/* The coverage of a round-capped segment of half-width hw: a pixel whose
 * centre lies d from it is covered R - d, R = hw + 0.5.  Rows (steep
 * segments) or columns (shallow ones) are scanned over the band where the
 * segment crosses them, not over its whole bounding box. */
static void cover_segment(raster *r, double x0, double y0, double x1, double y1,
                          double hw) {
  const double R = hw + 0.5, R2 = R * R, dx = x1 - x0, dy = y1 - y0;
  /* nothing to do beside the clip (most bands of a picture) */
  if (greater(y0, y1) + R < r->clip[1] || lesser(y0, y1) - R > r->clip[3] ||
      greater(x0, x1) + R < r->clip[0] || lesser(x0, x1) - R > r->clip[2])
    return;
  if (cover_crisp(r, x0, y0, x1, y1, hw)) return;
  const double l2 = dx * dx + dy * dy, il2 = l2 > 0 ? 1.0 / l2 : 0.0;
  const int steep = fabs(dy) >= fabs(dx);
  int ci0, ci1, cj0, cj1;
  clip_pixels(r, &ci0, &ci1, &cj0, &cj1);
  /* scan along the major axis a; the minor axis b spans a band */
  const double a0 = steep ? lesser(y0, y1) : lesser(x0, x1);
  const double a1 = steep ? greater(y0, y1) : greater(x0, x1);
  const double b0 = steep ? lesser(x0, x1) : lesser(y0, y1);
  const double b1 = steep ? greater(x0, x1) : greater(y0, y1);
  const double da = steep ? dy : dx, db = steep ? dx : dy;
  const double as = steep ? y0 : x0, bs = steep ? x0 : y0;
  const double slope = fabs(da) > 0 ? db / da : 0.0;
  const double half = fabs(da) > 0 ? R * sqrt(l2) / fabs(da) : R;
  const int alo = steep ? cj0 : ci0, ahi = steep ? cj1 : ci1;
  const int blo = steep ? ci0 : cj0, bhi = steep ? ci1 : cj1;
  if (alo > ahi || blo > bhi) return;
  for (int a = clampi(floor(a0 - R), alo, ahi); a <= clampi(ceil(a1 + R), alo, ahi); a++) {
    const double ac = a + 0.5, bc = bs + (ac - as) * slope;
    const double lo = greater(b0 - R, bc - half - 1), hi = lesser(b1 + R, bc + half + 1);
    for (int b = clampi(floor(lo), blo, bhi); b <= clampi(ceil(hi), blo, bhi); b++) {
      const int i = steep ? b : a, j = steep ? a : b;
      const double px = i + 0.5 - x0, py = j + 0.5 - y0;
      double u = (px * dx + py * dy) * il2;
      u = u < 0 ? 0 : u > 1 ? 1 : u;
      const double ex = px - u * dx, ey = py - u * dy, d2 = ex * ex + ey * ey;
      if (d2 < R2) cover_in(r, i, j, R - sqrt(d2));
    }
  }
}

/* The "on" pieces of a dashed segment from (x0, y0) to (x1, y1); *phase is
 * the position in the pattern (of total length period) where it starts. */
/* The part [*t0, *t1] (of [0, 1]) of the segment (x0, y0)-(x1, y1) that
 * lies within M pixels of the clip (Liang and Barsky's clipping); 0 when
 * none does. */
static int clip_segment(const raster *r, double x0, double y0, double x1, double y1,
                        double m, double *t0, double *t1) {
  const double dx = x1 - x0, dy = y1 - y0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x0 - (r->clip[0] - m), r->clip[2] + m - x0, y0 - (r->clip[1] - m),
                       r->clip[3] + m - y0};
  *t0 = 0;
  *t1 = 1;
  for (int k = 0; k < 4; k++) {
    if (p[k] == 0) {
      if (q[k] < 0) return 0;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0 && t > *t0) *t0 = t;
    if (p[k] > 0 && t < *t1) *t1 = t;
  }
  return *t0 < *t1;
}

/* The "on" pieces of a dashed segment from (x0, y0) to (x1, y1); *phase is
 * the position in the pattern (of total length period) where it starts.
 * Only its part near the clip is walked (a segment of a curve running far
 * out of the frame would take as many pieces as its length). */
static void cover_dashed(raster *r, double x0, double y0, double x1, double y1,
                         double hw, const double *dash, int ndash, double period,
                         double *phase) {
  const double L = hypot(x1 - x0, y1 - y0);
  double t0, t1;
  if (!isfinite(L) || !clip_segment(r, x0, y0, x1, y1, hw + 1, &t0, &t1)) {
    *phase = isfinite(L) ? fmod(*phase + L, period) : 0;
    return;
  }
  double s = t0 * L;
  const double end = t1 * L;
  *phase = fmod(*phase + s, period);
  while (s < end) {
    double p = fmod(*phase, period), acc = 0;
    int k = 0;
    while (k < ndash - 1 && p >= acc + dash[k]) acc += dash[k++];
    const double left = acc + dash[k] - p, step = fmin(left, end - s);
    if (k % 2 == 0 && step > 0) {
      const double u0 = s / L, u1 = (s + step) / L;
      cover_segment(r, x0 + u0 * (x1 - x0), y0 + u0 * (y1 - y0),
                    x0 + u1 * (x1 - x0), y0 + u1 * (y1 - y0), hw);
    }
    s += step;
    *phase = p + step;
    if (step <= 0) break;
  }
  *phase = fmod(*phase + (L - end), period);
}

void band_polyline(raster *r, const double *x, const double *y, size_t n,
                     double width, const double *dash, int ndash, uint32_t rgb) {
  double period = 0, phase = 0;
  for (int k = 0; k < ndash; k++) period += dash[k];
  const int dashed = ndash >= 2 && period > 0;
  const double hw = 0.5 * width;
  for (size_t i = 0; i + 1 < n; i++) {
    if (!isfinite(x[i]) || !isfinite(y[i]) || !isfinite(x[i + 1]) ||
        !isfinite(y[i + 1]))
      continue;
    if (dashed)
      cover_dashed(r, x[i], y[i], x[i + 1], y[i + 1], hw, dash, ndash, period, &phase);
    else
      cover_segment(r, x[i], y[i], x[i + 1], y[i + 1], hw);
  }
  if (n == 1 && isfinite(x[0]) && isfinite(y[0]))
    cover_segment(r, x[0], y[0], x[0], y[0], hw);
  flush(r, rgb);
}

void band_disc(raster *r, double cx, double cy, double radius, uint32_t rgb) {
  cover_segment(r, cx, cy, cx, cy, radius); /* the ramp centred on the edge */
  flush(r, rgb);
}

void band_ring(raster *r, double cx, double cy, double radius, double width,
                 uint32_t rgb) {
  const double R = radius + 0.5 * width + 0.5, hw = 0.5 * width;
  int i0, i1, j0, j1;
  clip_pixels(r, &i0, &i1, &j0, &j1);
  for (int j = clampi(floor(cy - R), j0, j1); j <= clampi(ceil(cy + R), j0, j1); j++)
    for (int i = clampi(floor(cx - R), i0, i1); i <= clampi(ceil(cx + R), i0, i1); i++) {
      const double d = hypot(i + 0.5 - cx, j + 0.5 - cy);
      const double c = hw + 0.5 - fabs(d - radius);
      if (c > 0) cover_in(r, i, j, c);
    }
  flush(r, rgb);
}

/* the length of [a, a + 1] inside [lo, hi] */
static double overlap(double a, double lo, double hi) {
  return greater(0.0, lesser(a + 1, hi) - greater(a, lo));
}

void band_fill_rect(raster *r, double x0, double y0, double x1, double y1,
                      uint32_t rgb) {
  const double xl = fmin(x0, x1), xh = fmax(x0, x1);
  const double yl = fmin(y0, y1), yh = fmax(y0, y1);
  int i0, i1, j0, j1;
  clip_pixels(r, &i0, &i1, &j0, &j1);
  for (int j = clampi(floor(yl), j0, j1); j <= clampi(ceil(yh), j0, j1); j++) {
    const double cy = overlap(j, yl, yh);
    for (int i = clampi(floor(xl), i0, i1); i <= clampi(ceil(xh), i0, i1); i++) {
      const double c = cy * overlap(i, xl, xh);
      if (c > 0) cover_in(r, i, j, c);
    }
  }
  flush(r, rgb);
}

void band_mask(raster *r, const uint8_t *mask, int w, int h, int stride,
               int x, int y, uint32_t rgb) {
  int i0, i1, j0, j1;
  clip_pixels(r, &i0, &i1, &j0, &j1);
  const int ja = j0 - y > 0 ? j0 - y : 0, jb = j1 - y + 1 < h ? j1 - y + 1 : h;
  const int ia = i0 - x > 0 ? i0 - x : 0, ib = i1 - x + 1 < w ? i1 - x + 1 : w;
  for (int j = ja; j < jb; j++)
    for (int i = ia; i < ib; i++) {
      const uint8_t m = mask[(size_t)j * (size_t)stride + (size_t)i];
      if (m) cover_in(r, x + i, y + j, m / 255.0);
    }
  flush(r, rgb);
}

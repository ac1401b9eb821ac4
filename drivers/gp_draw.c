/* drivers/gp_draw.c — a gp_figure (gp_figure.h) drawn on a raster canvas
 * and written as PNG, laid out as gnuplot's pngcairo terminal lays out the
 * same script (measured on its pictures): the frame inside margins made of
 * the tick labels, axis labels and title, the key outside on the right in a
 * box, ticks inside the frame on all four sides, the grid dotted behind
 * the data, the data cut at the frame; the axes' ranges and ticks are
 * gp_axis.c's.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "gp_draw.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gp_axis.h"
#include "gp_data.h"
#include "png_write.h"
#include "raster.h"
#include "raster_text.h"

typedef struct frame {
  double em, vchar, hchar; /* font size in pixels; a line; a character */
  double L, R, T, B;       /* the frame, pixels */
  axis_map x, y;
} frame;

/* gnuplot's default line colours (linetypes 1..8) */
static const uint32_t default_rgb[8] = {0x9400d3, 0x009e73, 0x56b4e9, 0xe69f00,
                                        0xf0e442, 0x0072b2, 0xe51e10, 0x000000};

/* ---- text --------------------------------------------------------------- */

typedef struct pen {
  raster *r;
  raster_font *font;
  const gp_points *pts; /* each series' points */
  int failed;           /* a string outside the subset was met */
} pen;

static double text_width(pen *P, const gp_text *t, double size) {
  raster_extent e;
  if (!t->s) return 0;
  if (raster_text_extent(P->font, t->s, size, t->enhanced, &e)) P->failed = 1;
  return e.width;
}

/* Draw T aligned (GP_LEFT, GP_CENTRE, GP_RIGHT) on (x, baseline y). */
static void text_at(pen *P, const gp_text *t, double size, double x, double y,
                    int align, uint32_t rgb) {
  if (!t->s || !t->s[0]) return;
  const double w = text_width(P, t, size);
  x -= align == GP_CENTRE ? 0.5 * w : align == GP_RIGHT ? w : 0;
  if (raster_text_draw(P->r, P->font, t->s, size, t->enhanced, x, y, 0, rgb))
    P->failed = 1;
}

/* ---- layout ------------------------------------------------------------- */

static double widest_tick_label(pen *P, const axis_map *m, double em) {
  double w = 0;
  char buf[64];
  for (int k = 0; k < m->ntick; k++) {
    gp_axis_tick_label(m, m->tick[k], buf, sizeof buf);
    gp_text t = {buf, 1};
    w = fmax(w, text_width(P, &t, em));
  }
  return w;
}

/* The key's widest entry text. */
static double key_text_width(pen *P, const gp_figure *f, double em) {
  double w = 0;
  for (size_t s = 0; s < f->nseries; s++)
    if (f->series[s].title.s) w = fmax(w, text_width(P, &f->series[s].title, em));
  return w;
}

/* The key box: a margin, the text, a gap, the sample (4.67 characters),
 * a margin, and `width N` characters more. */
static double key_width(pen *P, const gp_figure *f, double em) {
  return key_text_width(P, f, em) + (1.6 + 2.8 + 0.6 + 0.6 * f->key_width) * em;
}

static size_t key_rows(const gp_figure *f) {
  size_t n = 0;
  for (size_t s = 0; s < f->nseries; s++) n += f->series[s].title.s != NULL;
  return n;
}

/* The frame within the margins (gnuplot's, measured at 'Sans,12': a line
 * is 1.1625 em, the tick labels' tops 0.875 em under the frame, the x
 * label's 2.56 em, the left margin 0.7 em + the y label + 1.1 em + the
 * widest tick label + 0.75 em, the key 0.7 em from the right edge and
 * 1.25 em from the frame). */
static int lay_out(pen *P, const gp_figure *f, frame *F) {
  F->em = f->font_pt * 4.0 / 3.0;
  F->vchar = 1.1625 * F->em;
  F->hchar = 0.6 * F->em;
  if (gp_axis_range(f, P->pts, &f->x, 0, &F->x) || gp_axis_range(f, P->pts, &f->y, 1, &F->y))
    return -1;
  const double em = F->em;
  raster_extent e;
  double ylab = 0;
  if (f->y.label.s && f->y.label.s[0]) {
    if (raster_text_extent(P->font, f->y.label.s, em, f->y.label.enhanced, &e)) return -1;
    ylab = e.ascent + e.descent + 1.1 * em;
  }
  const double m[4] = {f->margin[0], f->margin[1], f->margin[2], f->margin[3]};
  F->T = m[0] >= 0 ? m[0] * F->vchar : (f->title.s && f->title.s[0] ? 3 : 1) * F->vchar;
  F->B = f->h - (m[1] >= 0 ? m[1] * F->vchar
                           : (f->x.label.s && f->x.label.s[0] ? 3.8 : 2.3) * em +
                                 (f->key_bottom ? F->vchar : 0));
  F->L = m[2] >= 0 ? m[2] * F->hchar
                   : 0.7 * em + ylab + widest_tick_label(P, &F->y, em) + 0.75 * em;
  double right = 2.0 * em;
  if (f->key && !f->key_bottom && key_rows(f))
    right = key_width(P, f, em) + 0.7 * em + 1.25 * em;
  F->R = f->w - (m[3] >= 0 ? m[3] * F->hchar : right);
  F->L = round(F->L);
  F->R = round(F->R);
  F->T = round(F->T);
  F->B = round(F->B);
  if (F->R - F->L < 20 || F->B - F->T < 20) return -1;
  F->x.p0 = F->L + 0.5;
  F->x.p1 = F->R + 0.5;
  F->y.p0 = F->B + 0.5;
  F->y.p1 = F->T + 0.5;
  return 0;
}

/* ---- drawing ------------------------------------------------------------ */

/* gnuplot's dash types: 1 solid, 2 dashed, 3 dotted, 4 dash-dot, 5
 * dash-dot-dot, in units of the line width */
static int dash_pattern(int dt, double lw, double *d) {
  const double u = fmax(lw, 1.0);
  switch (dt) {
  case 2: d[0] = 4 * u; d[1] = 4 * u; return 2;
  case 3: d[0] = 1 * u; d[1] = 3 * u; return 2;
  case 4: d[0] = 5.5 * u; d[1] = 3 * u; d[2] = 1 * u; d[3] = 3 * u; return 4;
  case 5: d[0] = 5.5 * u; d[1] = 3 * u; d[2] = 1 * u; d[3] = 3 * u;
          d[4] = 1 * u; d[5] = 3 * u; return 6;
  default: return 0;
  }
}

/* gnuplot's grid: dotted light grey lines at the major ticks */
static void draw_grid(raster *r, const frame *F, uint32_t rgb) {
  const double dots[2] = {1.0, 3.0};
  for (int k = 0; k < F->x.ntick; k++) {
    const double x = gp_axis_tick_px(&F->x, F->x.tick[k]);
    if (x > F->L + 1 && x < F->R) raster_line(r, x, F->T, x, F->B, 1.0, dots, 2, rgb);
  }
  for (int k = 0; k < F->y.ntick; k++) {
    const double y = gp_axis_tick_px(&F->y, F->y.tick[k]);
    if (y > F->T + 1 && y < F->B) raster_line(r, F->L, y, F->R, y, 1.0, dots, 2, rgb);
  }
}

/* ticks on all four sides, inwards, and the labels left and under */
static void draw_ticks(pen *P, const frame *F) {
  raster *r = P->r;
  const double major = round(0.4 * F->em), minor = round(0.2 * F->em);
  char buf[64];
  for (int k = 0; k < F->x.ntick; k++) {
    const double x = gp_axis_tick_px(&F->x, F->x.tick[k]);
    raster_line(r, x, F->B + 0.5, x, F->B + 0.5 - major, 1.0, NULL, 0, 0);
    raster_line(r, x, F->T + 0.5, x, F->T + 0.5 + major, 1.0, NULL, 0, 0);
    gp_axis_tick_label(&F->x, F->x.tick[k], buf, sizeof buf);
    gp_text t = {buf, 1};
    text_at(P, &t, F->em, x, F->B + 0.875 * F->em + 0.73 * F->em, GP_CENTRE, 0);
  }
  for (int k = 0; k < F->y.ntick; k++) {
    const double y = gp_axis_tick_px(&F->y, F->y.tick[k]);
    raster_line(r, F->L + 0.5, y, F->L + 0.5 + major, y, 1.0, NULL, 0, 0);
    raster_line(r, F->R + 0.5, y, F->R + 0.5 - major, y, 1.0, NULL, 0, 0);
    gp_axis_tick_label(&F->y, F->y.tick[k], buf, sizeof buf);
    gp_text t = {buf, 1};
    text_at(P, &t, F->em, F->L - 0.75 * F->em, y + 0.36 * F->em, GP_RIGHT, 0);
  }
  for (int k = 0; k < F->y.nminor; k++) {
    const double y = gp_axis_tick_px(&F->y, F->y.minor[k]);
    raster_line(r, F->L + 0.5, y, F->L + 0.5 + minor, y, 1.0, NULL, 0, 0);
    raster_line(r, F->R + 0.5, y, F->R + 0.5 - minor, y, 1.0, NULL, 0, 0);
  }
  for (int k = 0; k < F->x.nminor; k++) {
    const double x = gp_axis_tick_px(&F->x, F->x.minor[k]);
    raster_line(r, x, F->B + 0.5, x, F->B + 0.5 - minor, 1.0, NULL, 0, 0);
    raster_line(r, x, F->T + 0.5, x, F->T + 0.5 + minor, 1.0, NULL, 0, 0);
  }
}

static uint32_t series_rgb(const gp_series *S, size_t index) {
  return S->has_rgb ? S->rgb : default_rgb[index % 8];
}

/* a point of type PT (7: a disc, 6: a circle) at (x, y), inside the frame */
static void draw_point(raster *r, const frame *F, double x, double y, int pt, double ps,
                       uint32_t rgb) {
  if (!(x >= F->L && x <= F->R + 1 && y >= F->T && y <= F->B + 1)) return;
  if (pt == 6) raster_ring(r, x, y, 3.4 * ps, 1.0, rgb);
  else raster_disc(r, x, y, 3.4 * ps, rgb);
}

/* the series' curves (a blank line in the data breaks them, as does an
 * undefined point) or points */
static int draw_series(raster *r, const frame *F, const gp_figure *f, const gp_points *p,
                       size_t s) {
  const gp_series *S = &f->series[s];
  const uint32_t rgb = series_rgb(S, s);
  double *x = malloc((p->n + 1) * sizeof *x), *y = malloc((p->n + 1) * sizeof *y);
  if (!x || !y) {
    free(x);
    free(y);
    return -1;
  }
  double dash[6];
  const int nd = dash_pattern(S->dt, S->lw, dash);
  size_t n = 0;
  for (size_t i = 0; i <= p->n; i++) {
    if (S->style == GP_LINES && n > 0 && (i == p->n || p->brk[i])) {
      raster_polyline(r, x, y, n, S->lw, dash, nd, rgb);
      n = 0;
    }
    if (i == p->n) break;
    x[n] = gp_axis_px(&F->x, p->x[i]);
    y[n] = gp_axis_px(&F->y, p->y[i]);
    if (S->style == GP_POINTS) draw_point(r, F, x[n], y[n], S->pt, S->ps, rgb);
    else n++;
  }
  free(x);
  free(y);
  return 0;
}

/* A key entry's sample, from s0 to s1 on the line yc */
static void key_sample(pen *P, const gp_series *S, size_t s, double s0, double s1,
                       double yc) {
  const uint32_t rgb = series_rgb(S, s);
  if (S->style == GP_POINTS) {
    const frame all = {.L = 0, .R = P->r->w, .T = 0, .B = P->r->h};
    draw_point(P->r, &all, 0.5 * (s0 + s1), yc, S->pt, S->ps, rgb);
  } else {
    double dash[6];
    const int nd = dash_pattern(S->dt, S->lw, dash);
    raster_line(P->r, s0, yc, s1, yc, S->lw, dash, nd, rgb);
  }
}

/* The key under the axes, its entries side by side (text, then sample),
 * centred under the frame. */
static void draw_key_bottom(pen *P, const frame *F, const gp_figure *f) {
  const double em = F->em, gap = 1.5 * em, sample = 2.8 * em, pad = 0.6 * em;
  double total = 0;
  for (size_t s = 0; s < f->nseries; s++)
    if (f->series[s].title.s)
      total += text_width(P, &f->series[s].title, em) + pad + sample + gap;
  double x = 0.5 * (F->L + F->R) - 0.5 * (total - gap);
  const double yc = f->h - 0.95 * F->vchar;
  for (size_t s = 0; s < f->nseries; s++) {
    const gp_series *S = &f->series[s];
    if (!S->title.s) continue;
    const double w = text_width(P, &S->title, em);
    text_at(P, &S->title, em, x, yc + 0.36 * em, GP_LEFT, 0);
    key_sample(P, S, s, x + w + pad, x + w + pad + sample, yc);
    x += w + pad + sample + gap;
  }
}

static void draw_key(pen *P, const frame *F, const gp_figure *f) {
  const size_t rows = key_rows(f);
  if (!f->key || !rows) return;
  if (f->key_bottom) {
    draw_key_bottom(P, F, f);
    return;
  }
  const double em = F->em, kw = key_width(P, f, em);
  const double right = f->w - 0.7 * em, left = right - kw;
  const double top = F->T, bottom = top + (double)rows * F->vchar + 0.4 * em;
  if (f->key_box)
    raster_stroke_rect(P->r, round(left) + 0.5, top + 0.5, round(right) + 0.5,
                       round(bottom) + 0.5, 1.0, 0);
  /* text then sample, or (reverse) sample then text; the text flush
   * right against the sample, or (Left) flush left */
  const double tw = key_text_width(P, f, em); /* `width N` adds to the far end */
  double s0, s1, tx;
  int align;
  if (f->key_reverse) {
    s0 = left + 0.6 * em, s1 = s0 + 2.8 * em;
    tx = s1 + 0.6 * em + (f->key_left ? 0 : tw), align = f->key_left ? GP_LEFT : GP_RIGHT;
  } else {
    s1 = right - 0.6 * em, s0 = s1 - 2.8 * em;
    tx = s0 - 0.6 * em - (f->key_left ? tw : 0), align = f->key_left ? GP_LEFT : GP_RIGHT;
  }
  size_t row = 0;
  for (size_t s = 0; s < f->nseries; s++) {
    const gp_series *S = &f->series[s];
    if (!S->title.s) continue;
    const double yc = top + 0.2 * em + ((double)row + 0.5) * F->vchar;
    text_at(P, &S->title, em, tx, yc + 0.36 * em, align, 0);
    key_sample(P, S, s, s0, s1, yc);
    row++;
  }
}

static void draw_labels(pen *P, const frame *F, const gp_figure *f) {
  for (size_t k = 0; k < f->nlabel; k++) {
    const gp_label *l = &f->label[k];
    const double size = l->font_pt > 0 ? l->font_pt * 4.0 / 3.0 : F->em;
    const double x = gp_axis_coord_px(&F->x, l->x) + l->off_x * F->hchar;
    const double y = gp_axis_coord_px(&F->y, l->y) - l->off_y * F->vchar;
    text_at(P, &l->text, size, x, y + 0.36 * size, l->align, l->rgb);
  }
}

static void draw_arrows(raster *r, const frame *F, const gp_figure *f) {
  for (size_t k = 0; k < f->narrow; k++) {
    const gp_arrow *a = &f->arrow[k];
    double dash[6];
    const int nd = dash_pattern(a->dt, a->lw, dash);
    raster_line(r, gp_axis_coord_px(&F->x, a->x0), gp_axis_coord_px(&F->y, a->y0),
                gp_axis_coord_px(&F->x, a->x1), gp_axis_coord_px(&F->y, a->y1), a->lw, dash, nd,
                a->rgb);
  }
}

static int draw(pen *P, const gp_figure *f) {
  frame F;
  if (lay_out(P, f, &F)) return 1;
  raster *r = P->r;
  if (f->grid) draw_grid(r, &F, f->grid_rgb);
  raster_set_clip(r, F.L, F.T, F.R + 1, F.B + 1);
  draw_arrows(r, &F, f);
  for (size_t s = 0; s < f->nseries; s++)
    if (draw_series(r, &F, f, &P->pts[s], s)) return -1;
  raster_clip_all(r);
  raster_stroke_rect(r, F.L + 0.5, F.T + 0.5, F.R + 0.5, F.B + 0.5, 1.0, 0);
  draw_ticks(P, &F);
  const double mid = 0.5 * (F.L + F.R);
  text_at(P, &f->x.label, F.em, mid, F.B + 2.56 * F.em + 0.75 * F.em, GP_CENTRE, 0);
  if (f->y.label.s && f->y.label.s[0]) {
    raster_extent e;
    const double w = text_width(P, &f->y.label, F.em);
    if (raster_text_extent(P->font, f->y.label.s, F.em, f->y.label.enhanced, &e) ||
        raster_text_draw(r, P->font, f->y.label.s, F.em, f->y.label.enhanced,
                         0.7 * F.em + e.ascent, 0.5 * (F.T + F.B) + 0.5 * w, 1, 0))
      P->failed = 1;
  }
  text_at(P, &f->title, F.em, mid + f->title_off_x * F.hchar,
          F.T - 1.18 * F.vchar - f->title_off_y * F.vchar, GP_CENTRE, 0);
  draw_labels(P, &F, f);
  draw_key(P, &F, f);
  return P->failed ? 1 : 0;
}

struct gp_painter {
  raster_font *font;
  raster *canvas; /* NULL until the first picture */
};

gp_painter *gp_painter_new(char *err, size_t len) {
  gp_painter *p = calloc(1, sizeof *p);
  if (!p) {
    snprintf(err, len, "out of memory");
    return NULL;
  }
  p->font = raster_font_open(NULL, err, len);
  if (!p->font) {
    free(p);
    return NULL;
  }
  return p;
}

void gp_painter_free(gp_painter *p) {
  if (!p) return;
  raster_font_close(p->font);
  raster_free(p->canvas);
  free(p);
}

/* The painter's canvas, white, of the figure's size. */
static raster *canvas_for(gp_painter *p, const gp_figure *f) {
  if (p->canvas && (p->canvas->w != f->w || p->canvas->h != f->h)) {
    raster_free(p->canvas);
    p->canvas = NULL;
  }
  if (p->canvas) raster_clear(p->canvas, 0xffffff);
  else p->canvas = raster_new(f->w, f->h, 0xffffff);
  return p->canvas;
}

/* rows of pixels into the PNG's code */
static int to_png(void *ctx, const uint8_t *rows, int y0, int n) {
  (void)y0;
  return png_rows_add(ctx, rows, n);
}

/* The picture drawn on R, in bands of rows as they are coded, written to
 * OUT as a PNG: 0, or -1 with errno set. */
static int write_png(raster *r, FILE *out) {
  enum { BAND = 64 }; /* rows: 140 kB of band for 1100-pixel rows */
  png_rows *s = png_rows_new(r->w, r->h);
  if (!s) return -1;
  const int rc = raster_render(r, BAND, to_png, s);
  if (rc == -1 && !errno) errno = ENOMEM;
  const int bad = rc != 0 || png_rows_write(s, out, r->pal, r->npal) != 0;
  png_rows_free(s);
  return bad ? -1 : 0;
}

int gp_draw_png(gp_painter *p, const gp_figure *f, const char *dir, const char *path,
                char *err, size_t len) {
  gp_points *pts = NULL;
  int rc = gp_series_points(f, dir, &pts, err, len);
  if (rc) return rc;
  raster *r = canvas_for(p, f);
  if (!r) {
    gp_points_free(pts, f->nseries);
    snprintf(err, len, "out of memory");
    return -1;
  }
  pen P = {r, p->font, pts, 0};
  rc = draw(&P, f);
  gp_points_free(pts, f->nseries);
  if (rc == 1) snprintf(err, len, "a text or range not drawn here");
  if (rc == -1) snprintf(err, len, "out of memory");
  if (rc != 0) return rc;
  FILE *out = fopen(path, "wb");
  int werr = 0;
  if (!out || write_png(r, out) != 0) werr = errno ? errno : EIO;
  if (out && fclose(out) != 0 && !werr) werr = errno ? errno : EIO;
  if (werr) {
    snprintf(err, len, "%s", strerror(werr));
    if (out) remove(path);
    return -1;
  }
  return 0;
}

int gp_draw_script(gp_painter *p, const char *dir, const char *name, char *err,
                   size_t len) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s.gp", dir, name);
  char *text = gp_slurp(path, NULL);
  if (!text) {
    snprintf(err, len, "cannot read %s.gp", name);
    return 1;
  }
  gp_figure fig;
  int rc = gp_parse(text, &fig, err, len);
  free(text);
  if (rc == 0 && (strchr(fig.output, '/') || fig.output[0] == '.')) {
    snprintf(err, len, "output outside the directory");
    rc = 1;
  }
  if (rc == 0) {
    snprintf(path, sizeof path, "%s/%s", dir, fig.output);
    rc = gp_draw_png(p, &fig, dir, path, err, len);
  }
  if (rc < 0 && !err[0]) snprintf(err, len, "out of memory");
  gp_figure_free(&fig);
  return rc;
}

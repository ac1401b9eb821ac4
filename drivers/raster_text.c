/* drivers/raster_text.c — text of raster_text.h.  A string is first laid
 * out as glyph items (code point, size, baseline shift) by a small parser of
 * gnuplot's enhanced syntax, then each glyph is rendered by FreeType
 * (anti-aliased, light hinting, as cairo draws gnuplot's text), kept in a
 * cache, and placed in a coverage mask that is blended once; rotated text
 * turns that mask by 90 degrees.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "config.h"
#include "raster_text.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef WHIRL_HAVE_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#endif

#ifndef WHIRL_FONT
#define WHIRL_FONT ""
#endif

enum { MAX_ITEMS = 512, CACHE = 256 };

typedef struct glyph {
  uint32_t cp;
  int size64;          /* size in 1/64 pixel */
  int left, top, w, h; /* bitmap placement from the pen, FreeType's */
  double advance;      /* pixels */
  uint8_t *bits;       /* w * h coverage */
} glyph;

typedef struct item {
  uint32_t cp;
  double size, dy; /* pixels per em; baseline shift, down positive */
} item;

typedef struct layout {
  item v[MAX_ITEMS];
  int n;
} layout;

struct raster_font {
#ifdef WHIRL_HAVE_FREETYPE
  FT_Library lib;
  FT_Face face;
#endif
  int size64; /* the size the face is set to */
  glyph cache[CACHE];
  int ncache;
  layout lay; /* the string being measured or drawn */
};

raster_font *raster_font_open(const char *path, char *err, size_t len) {
#ifdef WHIRL_HAVE_FREETYPE
  if (!path || !*path) path = getenv("WHIRL_FONT");
  if (!path || !*path) path = WHIRL_FONT;
  if (!*path) {
    snprintf(err, len, "no font (configure found none; set WHIRL_FONT to a .ttf)");
    return NULL;
  }
  raster_font *f = calloc(1, sizeof *f);
  if (!f) {
    snprintf(err, len, "out of memory");
    return NULL;
  }
  if (FT_Init_FreeType(&f->lib)) {
    snprintf(err, len, "FreeType could not start");
    free(f);
    return NULL;
  }
  if (FT_New_Face(f->lib, path, 0, &f->face)) {
    snprintf(err, len, "cannot read the font %s", path);
    FT_Done_FreeType(f->lib);
    free(f);
    return NULL;
  }
  return f;
#else
  (void)path;
  snprintf(err, len, "whirl was built without FreeType");
  return NULL;
#endif
}

void raster_font_close(raster_font *f) {
  if (!f) return;
  for (int i = 0; i < f->ncache; i++) free(f->cache[i].bits);
#ifdef WHIRL_HAVE_FREETYPE
  FT_Done_Face(f->face);
  FT_Done_FreeType(f->lib);
#endif
  free(f);
}

/* ---- glyphs ------------------------------------------------------------ */

/* The glyph of CP at SIZE pixels per em, from the cache or rendered; NULL
 * when FreeType fails (the character is then skipped). */
static const glyph *glyph_get(raster_font *f, uint32_t cp, double size) {
  const int s64 = (int)lround(size * 64.0);
  for (int i = 0; i < f->ncache; i++)
    if (f->cache[i].cp == cp && f->cache[i].size64 == s64) return &f->cache[i];
#ifdef WHIRL_HAVE_FREETYPE
  if (f->size64 != s64) {
    if (FT_Set_Char_Size(f->face, 0, s64, 72, 72)) return NULL;
    f->size64 = s64;
  }
  if (FT_Load_Char(f->face, cp, FT_LOAD_RENDER | FT_LOAD_NO_HINTING)) return NULL;
  const FT_GlyphSlot g = f->face->glyph;
  glyph G = {cp, s64, g->bitmap_left, g->bitmap_top, (int)g->bitmap.width,
             (int)g->bitmap.rows, g->advance.x / 64.0, NULL};
  if (G.w > 0 && G.h > 0) {
    G.bits = malloc((size_t)G.w * (size_t)G.h);
    if (!G.bits) return NULL;
    for (int j = 0; j < G.h; j++)
      memcpy(G.bits + (size_t)j * (size_t)G.w,
             g->bitmap.buffer + (ptrdiff_t)j * g->bitmap.pitch, (size_t)G.w);
  }
  if (f->ncache == CACHE) { /* full: the oldest half goes */
    for (int i = 0; i < CACHE / 2; i++) free(f->cache[i].bits);
    memmove(f->cache, f->cache + CACHE / 2, (CACHE / 2) * sizeof *f->cache);
    f->ncache = CACHE / 2;
  }
  f->cache[f->ncache] = G;
  return &f->cache[f->ncache++];
#else
  (void)cp;
  return NULL;
#endif
}

/* ---- enhanced text ----------------------------------------------------- */

/* gnuplot's Symbol font: Latin letters stand for Greek ones (Adobe Symbol
 * encoding). */
static uint32_t symbol_cp(uint32_t c) {
  static const uint16_t lower[26] = {
      0x3b1, 0x3b2, 0x3c7, 0x3b4, 0x3b5, 0x3c6, 0x3b3, 0x3b7, 0x3b9,
      0x3d5, 0x3ba, 0x3bb, 0x3bc, 0x3bd, 0x3bf, 0x3c0, 0x3b8, 0x3c1,
      0x3c3, 0x3c4, 0x3c5, 0x3d6, 0x3c9, 0x3be, 0x3c8, 0x3b6};
  static const uint16_t upper[26] = {
      0x391, 0x392, 0x3a7, 0x394, 0x395, 0x3a6, 0x393, 0x397, 0x399,
      0x3d1, 0x39a, 0x39b, 0x39c, 0x39d, 0x39f, 0x3a0, 0x398, 0x3a1,
      0x3a3, 0x3a4, 0x3a5, 0x3c2, 0x3a9, 0x39e, 0x3a8, 0x396};
  if (c >= 'a' && c <= 'z') return lower[c - 'a'];
  if (c >= 'A' && c <= 'Z') return upper[c - 'A'];
  return c;
}

/* One UTF-8 character at *s (advanced past it); 0 with *s unchanged at the
 * end, (uint32_t)-1 for bad UTF-8. */
static uint32_t utf8_next(const char **s) {
  const unsigned char *p = (const unsigned char *)*s;
  uint32_t c = p[0];
  int n = c < 0x80 ? 0 : (c & 0xe0) == 0xc0 ? 1 : (c & 0xf0) == 0xe0 ? 2
        : (c & 0xf8) == 0xf0 ? 3 : -1;
  if (c == 0) return 0;
  if (n < 0) return (uint32_t)-1;
  c &= n == 0 ? 0x7f : (0x3f >> n);
  for (int k = 1; k <= n; k++) {
    if ((p[k] & 0xc0) != 0x80) return (uint32_t)-1;
    c = (c << 6) | (p[k] & 0x3f);
  }
  *s += n + 1;
  return c;
}

typedef struct style {
  double size, dy;
  int symbol;
} style;

static int add_item(layout *L, uint32_t cp, const style *st) {
  if (L->n == MAX_ITEMS) return -1;
  L->v[L->n++] = (item){st->symbol ? symbol_cp(cp) : cp, st->size, st->dy};
  return 0;
}

static int parse_group(const char **s, style st, layout *L, int nested);

/* After _ or ^: a {group} or one character, smaller and shifted. */
static int parse_script(const char **s, style st, layout *L, double shift) {
  style in = {0.8 * st.size, st.dy + shift * st.size, st.symbol};
  if (**s == '{') {
    ++*s;
    return parse_group(s, in, L, 1);
  }
  if (**s == '\\' && (*s)[1]) ++*s;
  uint32_t c = utf8_next(s);
  if (c == 0 || c == (uint32_t)-1) return -1;
  return add_item(L, c, &in);
}

/* {/Font=size text}: the font part (Symbol, or a size) then the text. */
static int parse_font_group(const char **s, style st, layout *L, double pt2px) {
  const char *p = *s;
  size_t n = strcspn(p, " }");
  style in = st;
  if (n >= 6 && !strncmp(p, "Symbol", 6)) in.symbol = 1, p += 6, n -= 6;
  else if (n && *p != '=' && *p != ':') return -1; /* another font family */
  if (n && *p == '=') {
    char *end;
    double pt = strtod(p + 1, &end);
    if (end != p + n || !(pt > 0 && pt < 200)) return -1;
    in.size = pt * pt2px;
  } else if (n && *p == ':') {
    return -1; /* :Bold, :Italic: not drawn here */
  }
  *s = p + n;
  if (**s == ' ') ++*s;
  return parse_group(s, in, L, 1);
}

/* The text up to the end (or the closing brace of a nested group). */
static int parse_group(const char **s, style st, layout *L, int nested) {
  const double pt2px = 4.0 / 3.0; /* a point is 4/3 pixel (96 per inch) */
  while (**s) {
    char c = **s;
    int rc = 0;
    if (c == '}') {
      if (!nested) return -1;
      ++*s;
      return 0;
    }
    if (c == '@' || c == '&' || c == '~') return -1; /* not drawn here */
    if (c == '{') {
      ++*s;
      if (**s == '/') {
        ++*s;
        rc = parse_font_group(s, st, L, pt2px);
      } else {
        rc = parse_group(s, st, L, 1);
      }
    } else if (c == '_' || c == '^') {
      ++*s;
      rc = parse_script(s, st, L, c == '_' ? 0.3 : -0.45);
    } else {
      if (c == '\\' && (*s)[1]) ++*s;
      uint32_t cp = utf8_next(s);
      if (cp == (uint32_t)-1) return -1;
      rc = add_item(L, cp, &st);
    }
    if (rc) return rc;
  }
  return nested ? -1 : 0;
}

static int lay_out(const char *s, double size, int enhanced, layout *L) {
  style st = {size, 0.0, 0};
  L->n = 0;
  if (enhanced) return parse_group(&s, st, L, 0);
  for (;;) {
    uint32_t c = utf8_next(&s);
    if (c == 0) return 0;
    if (c == (uint32_t)-1 || add_item(L, c, &st)) return -1;
  }
}

/* ---- measuring and drawing -------------------------------------------- */

int raster_text_extent(raster_font *f, const char *s, double size, int enhanced,
                       raster_extent *e) {
  layout *L = &f->lay;
  e->width = 0;
  e->ascent = 0.75 * size; /* DejaVu's digits and capitals, for empty text */
  e->descent = 0.24 * size;
  if (lay_out(s, size, enhanced, L)) return -1;
  for (int i = 0; i < L->n; i++) {
    const glyph *g = glyph_get(f, L->v[i].cp, L->v[i].size);
    if (!g) continue;
    e->width += g->advance;
    e->ascent = fmax(e->ascent, 0.75 * L->v[i].size - L->v[i].dy);
    e->descent = fmax(e->descent, 0.24 * L->v[i].size + L->v[i].dy);
  }
  return 0;
}

/* The string's coverage in a mask with the baseline's left end at (ox, oy)
 * of the mask; *mw x *mh. */
static uint8_t *text_mask(raster_font *f, const layout *L, int *mw, int *mh,
                          int *ox, int *oy) {
  double width = 0, top = 0, bottom = 0;
  for (int i = 0; i < L->n; i++) {
    const glyph *g = glyph_get(f, L->v[i].cp, L->v[i].size);
    if (!g) continue;
    width += g->advance;
    top = fmax(top, g->top - L->v[i].dy);
    bottom = fmax(bottom, g->h - g->top + L->v[i].dy);
  }
  *ox = 2;
  *oy = (int)ceil(top) + 2;
  *mw = (int)ceil(width) + 6;
  *mh = *oy + (int)ceil(bottom) + 3;
  uint8_t *m = calloc((size_t)*mw * (size_t)*mh, 1);
  if (!m) return NULL;
  double pen = *ox;
  for (int i = 0; i < L->n; i++) {
    const glyph *g = glyph_get(f, L->v[i].cp, L->v[i].size);
    if (!g) continue;
    const int gx = (int)lround(pen) + g->left;
    const int gy = *oy + (int)lround(L->v[i].dy) - g->top;
    for (int j = 0; j < g->h; j++)
      for (int k = 0; k < g->w; k++) {
        const int X = gx + k, Y = gy + j;
        if (X < 0 || Y < 0 || X >= *mw || Y >= *mh) continue;
        uint8_t *d = &m[(size_t)Y * (size_t)*mw + (size_t)X];
        const uint8_t v = g->bits[(size_t)j * (size_t)g->w + (size_t)k];
        if (v > *d) *d = v;
      }
    pen += g->advance;
  }
  return m;
}

int raster_text_draw(raster *r, raster_font *f, const char *s, double size,
                     int enhanced, double x, double y, int rotated, uint32_t rgb) {
  layout *L = &f->lay;
  if (lay_out(s, size, enhanced, L)) return -1;
  int mw, mh, ox, oy;
  uint8_t *m = text_mask(f, L, &mw, &mh, &ox, &oy);
  if (!m) return -1;
  const int X = (int)lround(x), Y = (int)lround(y);
  if (!rotated) {
    raster_mask(r, m, mw, mh, mw, X - ox, Y - oy, rgb);
    free(m);
    return 0;
  }
  /* turned counter-clockwise: mask column i becomes row mw - 1 - i */
  uint8_t *t = malloc((size_t)mw * (size_t)mh);
  if (!t) {
    free(m);
    return -1;
  }
  for (int j = 0; j < mh; j++)
    for (int i = 0; i < mw; i++)
      t[(size_t)(mw - 1 - i) * (size_t)mh + (size_t)j] = m[(size_t)j * (size_t)mw + (size_t)i];
  raster_mask(r, t, mh, mw, mh, X - oy, Y - (mw - 1 - ox), rgb);
  free(t);
  free(m);
  return 0;
}

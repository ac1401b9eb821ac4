/* drivers/gp_parse.c — the part of gnuplot's language whirl's line and
 * point pictures use, read into a gp_figure (gp_figure.h):
 *   set terminal pngcairo size W,H [enhanced] font 'Sans,S'; set output
 *   $NAME << EOD ... EOD (datablocks of numbers)
 *   set title|xlabel|ylabel 'T' [offset X,Y] [noenhanced]
 *   set xrange|yrange [A:B] (A, B numbers or *); set logscale x|y|xy
 *   set grid; set key outside right top [box] [vertical] [Left|Right]
 *             [reverse] [width N]
 *   set tmargin|bmargin|lmargin|rmargin N
 *   set arrow from P to P nohead [dt N] [lw N] [lc rgb '#rrggbb'] [front|back]
 *   set label 'T' at P [left|center|right] [font 'Sans,S'] [tc rgb 'C']
 *             [offset X,Y] [front|back] [noenhanced]
 *   plot $NAME using I:J with lines|points [dt N] [lw N] [lc rgb 'C']
 *             [pt 7|6] [ps N] [title 'T' [noenhanced]|notitle], ...
 *   (NaN or 1/0 in place of $NAME using I:J: a key entry alone; 'FILE'
 *   using X:Y, X and Y a column or a (gp_expr.h expression), a table in
 *   the script's directory)
 *   set datafile separator '\t'; NAME = expression; set grid lc rgb C;
 *   set key outside bottom center horizontal
 * with P = [first|graph] X, [first|graph] Y, and C '#rrggbb' or one of
 * gnuplot's names black, white, red, green, blue, gray, grey.  Anything else makes the
 * script gnuplot's to draw (gp_parse returns 1).
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include "gp_figure.h"

#include <math.h>
#include <stdint.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { TOK_WORD, TOK_STR, TOK_PUNCT };
enum { MAX_TOK = 256 };

typedef struct token {
  int kind;
  size_t pos; /* where it starts in the line */
  char text[512];
} token;

typedef struct stmt {
  token t[MAX_TOK];
  int n, i; /* tokens, the next one */
} stmt;

/* ---- tokens ------------------------------------------------------------- */

static int is_punct(char c) { return c == ',' || c == ':' || c == '[' || c == ']'; }

/* Split LINE into tokens: quoted strings ('' is a quote inside single
 * quotes, \" inside double ones), the punctuation , : [ ], and words.
 * -1 for a line the renderer does not read (too long, an open quote). */
static int tokenize(const char *line, stmt *S) {
  S->n = S->i = 0;
  const char *p = line;
  while (*p) {
    if (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') {
      p++;
      continue;
    }
    if (*p == '#') break;
    if (S->n == MAX_TOK) return -1;
    token *t = &S->t[S->n++];
    size_t k = 0;
    t->pos = (size_t)(p - line);
    if (*p == '\'' || *p == '"') {
      const char q = *p++;
      t->kind = TOK_STR;
      for (;;) {
        if (!*p) return -1;
        if (*p == q && q == '\'' && p[1] == '\'') p++;
        else if (*p == q) break;
        else if (q == '"' && *p == '\\' && p[1]) {
          p++;
          if (*p == 'n') return -1; /* a line break: not drawn here */
          if (*p == 't') { /* "\t": a tab */
            if (k + 1 >= sizeof t->text) return -1;
            t->text[k++] = '\t';
            p++;
            continue;
          }
        }
        if (k + 1 >= sizeof t->text) return -1;
        t->text[k++] = *p++;
      }
      p++;
    } else if (is_punct(*p)) {
      t->kind = TOK_PUNCT;
      t->text[k++] = *p++;
    } else {
      t->kind = TOK_WORD;
      while (*p && !strchr(" \t\r\n'\"#", *p) && !is_punct(*p)) {
        if (k + 1 >= sizeof t->text) return -1;
        t->text[k++] = *p++;
      }
    }
    t->text[k] = '\0';
  }
  return 0;
}

static const token *peek(const stmt *S) { return S->i < S->n ? &S->t[S->i] : NULL; }

/* Is the next token the word W (or punctuation)?  Taken if so. */
static int take(stmt *S, const char *w) {
  const token *t = peek(S);
  if (t && t->kind != TOK_STR && !strcmp(t->text, w)) {
    S->i++;
    return 1;
  }
  return 0;
}

static int take_number(stmt *S, double *v) {
  const token *t = peek(S);
  if (!t || t->kind != TOK_WORD) return 0;
  char *end;
  double x = strtod(t->text, &end);
  if (end == t->text || *end || !isfinite(x)) return 0;
  *v = x;
  S->i++;
  return 1;
}

static int take_string(stmt *S, char **out) {
  const token *t = peek(S);
  if (!t || t->kind != TOK_STR) return 0;
  char *s = strdup(t->text);
  if (!s) return 0;
  free(*out);
  *out = s;
  S->i++;
  return 1;
}

/* gnuplot's colour names that whirl's scripts use, and their values */
static int named_rgb(const char *name, uint32_t *rgb) {
  static const struct {
    const char *name;
    uint32_t rgb;
  } names[] = {{"black", 0x000000}, {"white", 0xffffff}, {"red", 0xff0000},
               {"green", 0x00ff00}, {"blue", 0x0000ff}, {"gray", 0xc0c0c0},
               {"grey", 0xc0c0c0}};
  for (size_t i = 0; i < sizeof names / sizeof *names; i++)
    if (!strcmp(name, names[i].name)) {
      *rgb = names[i].rgb;
      return 1;
    }
  return 0;
}

/* rgb '#rrggbb' or rgb 'NAME' */
static int take_rgb(stmt *S, uint32_t *rgb) {
  if (!take(S, "rgb")) return 0;
  const token *t = peek(S);
  if (t && t->kind == TOK_STR && named_rgb(t->text, rgb)) {
    S->i++;
    return 1;
  }
  if (!t || t->kind != TOK_STR || t->text[0] != '#' || strlen(t->text) != 7) return 0;
  char *end;
  unsigned long v = strtoul(t->text + 1, &end, 16);
  if (*end) return 0;
  *rgb = (uint32_t)v;
  S->i++;
  return 1;
}

/* X,Y: an offset in characters */
static int take_pair(stmt *S, double *x, double *y) {
  return take_number(S, x) && take(S, ",") && take_number(S, y);
}

/* [first|graph] V */
static int take_coord(stmt *S, gp_coord *c) {
  c->sys = take(S, "graph") ? GP_GRAPH : (take(S, "first"), GP_FIRST);
  return take_number(S, &c->v);
}

/* 'Sans,S' or 'Sans': the size S in points (0 when not given) */
static int font_size(const char *spec, double *pt) {
  const char *comma = strchr(spec, ',');
  size_t fam = comma ? (size_t)(comma - spec) : strlen(spec);
  if (fam && strncmp(spec, "Sans", fam)) return 0; /* another family */
  *pt = 0;
  if (!comma) return 1;
  char *end;
  *pt = strtod(comma + 1, &end);
  return !*end && *pt > 0 && *pt < 200;
}

/* ---- statements --------------------------------------------------------- */

typedef struct parser {
  gp_figure *fig;
  char *err;
  size_t len;
  stmt S;              /* the statement being read (130 KB: not on the stack) */
  char line[1 << 16];  /* its text, continuation lines joined */
} parser;

static int unsupported(parser *P, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(P->err, P->len, fmt, ap);
  va_end(ap);
  return 1;
}

static int grow(void **v, size_t n, size_t size) {
  void *p = realloc(*v, (n + 1) * size);
  if (!p) return -1;
  *v = p;
  memset((char *)p + n * size, 0, size);
  return 0;
}

static int set_terminal(parser *P, stmt *S) {
  gp_figure *f = P->fig;
  double w, h;
  char *font = NULL;
  if (!take(S, "pngcairo")) return unsupported(P, "terminal other than pngcairo");
  while (peek(S)) {
    if (take(S, "size") && take_pair(S, &w, &h)) {
      if (!(w >= 16 && w <= 4096 && h >= 16 && h <= 4096)) /* larger: gnuplot */
        return unsupported(P, "picture size");
      f->w = (int)w;
      f->h = (int)h;
    } else if (take(S, "enhanced")) {
      f->enhanced = 1;
    } else if (take(S, "noenhanced")) {
      f->enhanced = 0;
    } else if (take(S, "font") && take_string(S, &font)) {
      int good = font_size(font, &f->font_pt);
      free(font);
      font = NULL;
      if (!good || f->font_pt <= 0) return unsupported(P, "terminal font");
    } else {
      return unsupported(P, "terminal option");
    }
  }
  return 0;
}

/* set title|xlabel|ylabel 'T' [offset X,Y] [noenhanced] */
static int set_text(parser *P, stmt *S, gp_text *t, double *ox, double *oy) {
  if (!take_string(S, &t->s)) return unsupported(P, "text without a string");
  t->enhanced = P->fig->enhanced;
  while (peek(S)) {
    double x, y;
    if (take(S, "noenhanced")) t->enhanced = 0;
    else if (take(S, "enhanced")) t->enhanced = 1;
    else if (ox && take(S, "offset") && take_pair(S, &x, &y)) *ox = x, *oy = y;
    else return unsupported(P, "text option");
  }
  return 0;
}

/* [A:B] with * for automatic ends */
static int set_range(parser *P, stmt *S, gp_axis *a) {
  if (!take(S, "[")) return unsupported(P, "range");
  a->auto_lo = take(S, "*") || (peek(S) && !strcmp(peek(S)->text, ":"));
  if (!a->auto_lo && !take_number(S, &a->lo)) return unsupported(P, "range");
  if (!take(S, ":")) return unsupported(P, "range");
  a->auto_hi = take(S, "*") || (peek(S) && !strcmp(peek(S)->text, "]"));
  if (!a->auto_hi && !take_number(S, &a->hi)) return unsupported(P, "range");
  if (!take(S, "]") || peek(S)) return unsupported(P, "range");
  return 0;
}

static int set_key(parser *P, stmt *S) {
  P->fig->key = 1;
  int outside = 0, right = 0, top = 0, bottom = 0, center = 0, horizontal = 0;
  while (peek(S)) {
    if (take(S, "outside")) outside = 1;
    else if (take(S, "right")) right = 1;
    else if (take(S, "top")) top = 1;
    else if (take(S, "bottom")) bottom = 1;
    else if (take(S, "center") || take(S, "centre")) center = 1;
    else if (take(S, "horizontal")) horizontal = 1;
    else if (take(S, "box")) P->fig->key_box = 1;
    else if (take(S, "vertical")) continue;
    else if (take(S, "Left")) P->fig->key_left = 1;
    else if (take(S, "Right")) P->fig->key_left = 0;
    else if (take(S, "reverse")) P->fig->key_reverse = 1;
    else if (take(S, "noreverse")) P->fig->key_reverse = 0;
    else if (take(S, "width") && take_number(S, &P->fig->key_width)) continue;
    else return unsupported(P, "key option");
  }
  P->fig->key_bottom = outside && bottom && center && horizontal && !right && !top;
  return outside && ((right && top && !bottom && !horizontal) || P->fig->key_bottom)
             ? 0
             : unsupported(P, "key placement");
}

/* gnuplot's dash types drawn here as gnuplot draws them (gp_draw.c's
 * dash_pattern): 1 solid to 5 dash-dot-dot; and the point types: 6 a
 * circle, 7 a disc.  Any other value (gnuplot's other patterns and
 * symbols, or a number no int holds) is gnuplot's to draw. */
static int dash_type(parser *P, double v, int *dt) {
  if (!(v >= 1 && v <= 5 && v == floor(v))) return unsupported(P, "a dash type");
  *dt = (int)v;
  return 0;
}
static int point_type(parser *P, double v, int *pt) {
  if (!(v == 6 || v == 7)) return unsupported(P, "a point type");
  *pt = (int)v;
  return 0;
}

static int set_arrow(parser *P, stmt *S) {
  gp_figure *f = P->fig;
  if (grow((void **)&f->arrow, f->narrow, sizeof *f->arrow)) return -1;
  gp_arrow *a = &f->arrow[f->narrow];
  a->lw = 1;
  a->dt = 1;
  if (!take(S, "from") || !take_coord(S, &a->x0) || !take(S, ",") ||
      !take_coord(S, &a->y0) || !take(S, "to") || !take_coord(S, &a->x1) ||
      !take(S, ",") || !take_coord(S, &a->y1))
    return unsupported(P, "arrow position");
  int nohead = 0;
  while (peek(S)) {
    double v;
    if (take(S, "nohead")) nohead = 1;
    else if (take(S, "front") || take(S, "back")) continue;
    else if (take(S, "dt") && take_number(S, &v)) {
      if (dash_type(P, v, &a->dt)) return 1;
    } else if (take(S, "lw") && take_number(S, &v)) a->lw = v;
    else if (take(S, "lc") && take_rgb(S, &a->rgb)) continue;
    else return unsupported(P, "arrow option");
  }
  if (!nohead) return unsupported(P, "arrow with a head");
  if (!(a->lw >= 0 && a->lw <= 100)) return unsupported(P, "an arrow's width");
  f->narrow++;
  return 0;
}

static int set_label(parser *P, stmt *S) {
  gp_figure *f = P->fig;
  if (grow((void **)&f->label, f->nlabel, sizeof *f->label)) return -1;
  gp_label *l = &f->label[f->nlabel++]; /* counted now: freed with the rest */
  l->align = GP_LEFT;
  l->text.enhanced = f->enhanced;
  if (!take_string(S, &l->text.s) || !take(S, "at") || !take_coord(S, &l->x) ||
      !take(S, ",") || !take_coord(S, &l->y))
    return unsupported(P, "label position");
  char *font = NULL;
  while (peek(S)) {
    double x, y;
    if (take(S, "left")) l->align = GP_LEFT;
    else if (take(S, "center") || take(S, "centre")) l->align = GP_CENTRE;
    else if (take(S, "right")) l->align = GP_RIGHT;
    else if (take(S, "front") || take(S, "back")) continue;
    else if (take(S, "noenhanced")) l->text.enhanced = 0;
    else if (take(S, "tc") && take_rgb(S, &l->rgb)) continue;
    else if (take(S, "offset") && take_pair(S, &x, &y)) l->off_x = x, l->off_y = y;
    else if (take(S, "font") && take_string(S, &font)) {
      int good = font_size(font, &l->font_pt);
      free(font);
      font = NULL;
      if (!good) return unsupported(P, "label font");
    } else {
      return unsupported(P, "label option");
    }
  }
  return 0;
}

static int set_margin(parser *P, stmt *S, int side) {
  double v;
  if (!take_number(S, &v) || peek(S) || v < 0 || v > 100)
    return unsupported(P, "margin");
  P->fig->margin[side] = v;
  return 0;
}

static int set_stmt(parser *P, stmt *S) {
  gp_figure *f = P->fig;
  static const char *const margins[4] = {"tmargin", "bmargin", "lmargin", "rmargin"};
  for (int k = 0; k < 4; k++)
    if (take(S, margins[k])) return set_margin(P, S, k);
  if (take(S, "terminal")) return set_terminal(P, S);
  if (take(S, "output")) {
    const token *t = peek(S);
    if (!t || t->kind != TOK_STR || strlen(t->text) >= sizeof f->output)
      return unsupported(P, "output");
    strcpy(f->output, t->text);
    return 0;
  }
  if (take(S, "title"))
    return set_text(P, S, &f->title, &f->title_off_x, &f->title_off_y);
  if (take(S, "xlabel")) return set_text(P, S, &f->x.label, NULL, NULL);
  if (take(S, "ylabel")) return set_text(P, S, &f->y.label, NULL, NULL);
  if (take(S, "xrange")) return set_range(P, S, &f->x);
  if (take(S, "yrange")) return set_range(P, S, &f->y);
  if (take(S, "logscale")) {
    if (take(S, "x")) f->x.log = 1;
    else if (take(S, "y")) f->y.log = 1;
    else if (take(S, "xy")) f->x.log = f->y.log = 1;
    else return unsupported(P, "logscale axes");
    return peek(S) ? unsupported(P, "logscale base") : 0;
  }
  if (take(S, "grid")) {
    f->grid = 1;
    if (peek(S) && !(take(S, "lc") && take_rgb(S, &f->grid_rgb) && !peek(S)))
      return unsupported(P, "grid options");
    return 0;
  }
  if (take(S, "datafile")) {
    const token *t = peek(S);
    if (!take(S, "separator") || !(t = peek(S))) return unsupported(P, "datafile");
    if (t->kind == TOK_STR && (!strcmp(t->text, "\\t") || !strcmp(t->text, "\t")))
      f->sep = '\t';
    else if (t->kind == TOK_WORD && !strcmp(t->text, "tab")) f->sep = '\t';
    else if (t->kind == TOK_WORD && !strcmp(t->text, "whitespace")) f->sep = 0;
    else return unsupported(P, "datafile separator");
    S->i++;
    return peek(S) ? unsupported(P, "datafile") : 0;
  }
  if (take(S, "key")) return set_key(P, S);
  if (take(S, "arrow")) return set_arrow(P, S);
  if (take(S, "label")) return set_label(P, S);
  return unsupported(P, "set %s", peek(S) ? peek(S)->text : "");
}

/* One side of `using X:Y` (TEXT, trimmed): a column number, or an
 * expression. */
static int using_part(parser *P, const char *text, int *col, gp_expr **e) {
  char *end;
  const long c = strtol(text, &end, 10);
  if (end != text && !*end) {
    if (c < 1 || c > 1000) return unsupported(P, "a using column");
    *col = (int)c;
    return 0;
  }
  char why[128];
  *e = gp_expr_parse(text, P->fig->var, P->fig->nvar, why, sizeof why);
  return *e ? 0 : unsupported(P, "using: %s", why);
}

/* The first ':' of S at depth 0 outside quotes that is not a ?: one; NULL
 * if none. */
static char *top_colon(char *s) {
  int depth = 0, tern = 0;
  char q = 0;
  for (char *c = s; *c; c++) {
    if (q) q = *c == q ? 0 : q;
    else if (*c == '\'' || *c == '"') q = *c;
    else if (*c == '(') depth++;
    else if (*c == ')') depth--;
    else if (*c == '?' && depth == 0) tern++;
    else if (*c == ':' && depth == 0 && tern) tern--;
    else if (*c == ':' && depth == 0) return c;
  }
  return NULL;
}

/* S without the blanks at its ends */
static char *trim(char *s) {
  while (*s == ' ' || *s == '\t') s++;
  for (char *e = s + strlen(s); e > s && (e[-1] == ' ' || e[-1] == '\t');) *--e = '\0';
  return s;
}

/* 'FILE' using X:Y: the file's name, and X and Y from the raw text of the
 * line up to `with`. */
static int file_source(parser *P, stmt *S, gp_series *s) {
  const token *t = peek(S);
  if (!t->text[0] || strchr(t->text, '/') || t->text[0] == '.' || !strcmp(t->text, "-"))
    return unsupported(P, "a data file outside the directory");
  if (!(s->file = strdup(t->text))) return -1;
  s->block = SIZE_MAX;
  S->i++;
  if (!take(S, "using") || !peek(S)) return unsupported(P, "a file without using");
  int w = S->i;
  while (w < S->n && !(S->t[w].kind == TOK_WORD && !strcmp(S->t[w].text, "with"))) w++;
  const size_t from = S->t[S->i].pos, to = w < S->n ? S->t[w].pos : strlen(P->line);
  char spec[1024];
  if (to - from >= sizeof spec) return unsupported(P, "a long using");
  memcpy(spec, P->line + from, to - from);
  spec[to - from] = '\0';
  S->i = w;
  char *colon = top_colon(spec);
  if (!colon) return unsupported(P, "using without X:Y");
  *colon = '\0';
  char *x = trim(spec), *y = trim(colon + 1);
  if (top_colon(y)) return unsupported(P, "using X:Y:Z");
  const int rc = using_part(P, x, &s->cx, &s->ux);
  return rc ? rc : using_part(P, y, &s->cy, &s->uy);
}

/* The source of a plot item: a datablock and its columns (using I:J), or
 * NaN or 1/0, no data (the item is there for its key entry). */
static int plot_source(parser *P, stmt *S, gp_series *s) {
  gp_figure *f = P->fig;
  const token *t = peek(S);
  if (take(S, "NaN") || take(S, "1/0")) {
    s->block = SIZE_MAX;
    s->cx = s->cy = 1;
    return 0;
  }
  if (t && t->kind == TOK_STR) return file_source(P, S, s);
  if (!t || t->kind != TOK_WORD || t->text[0] != '$') return unsupported(P, "plot source");
  size_t b = 0;
  while (b < f->nblock && strcmp(f->block[b].name, t->text)) b++;
  if (b == f->nblock) return unsupported(P, "unknown datablock");
  S->i++;
  s->block = b;
  double cx, cy;
  if (!take(S, "using") || !take_number(S, &cx) || !take(S, ":") ||
      !take_number(S, &cy) || cx < 1 || cy < 1 || cx > 64 || cy > 64)
    return unsupported(P, "plot columns");
  s->cx = (int)cx;
  s->cy = (int)cy;
  return 0;
}

/* one item of the plot command: $NAME using I:J with lines|points [options] */
static int plot_item(parser *P, stmt *S) {
  gp_figure *f = P->fig;
  if (grow((void **)&f->series, f->nseries, sizeof *f->series)) return -1;
  gp_series *s = &f->series[f->nseries++];
  s->lw = s->ps = 1;
  s->dt = 1;
  s->pt = 7;
  s->title.enhanced = f->enhanced;
  double v;
  const int src = plot_source(P, S, s);
  if (src) return src;
  if (!take(S, "with")) return unsupported(P, "plot style");
  if (take(S, "lines")) s->style = GP_LINES;
  else if (take(S, "points")) s->style = GP_POINTS;
  else return unsupported(P, "plot style");
  int titled = 0;
  while (peek(S) && strcmp(peek(S)->text, ",")) {
    if (take(S, "dt") && take_number(S, &v)) {
      if (dash_type(P, v, &s->dt)) return 1;
    } else if (take(S, "lw") && take_number(S, &v)) s->lw = v;
    else if (take(S, "ps") && take_number(S, &v)) s->ps = v;
    else if (take(S, "pt") && take_number(S, &v)) {
      if (point_type(P, v, &s->pt)) return 1;
    }
    else if (take(S, "lc") && take_rgb(S, &s->rgb)) s->has_rgb = 1;
    else if (take(S, "notitle")) titled = 1;
    else if (take(S, "title") && take_string(S, &s->title.s)) titled = 1;
    else if (titled && take(S, "noenhanced")) s->title.enhanced = 0;
    else if (titled && take(S, "enhanced")) s->title.enhanced = 1;
    else return unsupported(P, "plot option");
  }
  if (!titled) return unsupported(P, "a plot item without its title");
  if (s->style == GP_POINTS && s->pt != 7 && s->pt != 6) return unsupported(P, "point type");
  if (!(s->lw >= 0 && s->lw <= 100 && s->ps >= 0 && s->ps <= 100))
    return unsupported(P, "a line width or point size");
  return 0;
}

static int plot_stmt(parser *P, stmt *S) {
  for (;;) {
    int rc = plot_item(P, S);
    if (rc) return rc;
    if (!take(S, ",")) break;
  }
  return peek(S) ? unsupported(P, "plot") : 0;
}

/* ---- datablocks --------------------------------------------------------- */

/* The rows of numbers from *p up to the line TERM; *p moves past it. */
static int read_block(parser *P, const char **p, const char *name, const char *term) {
  gp_figure *f = P->fig;
  if (grow((void **)&f->block, f->nblock, sizeof *f->block)) return -1;
  gp_block *B = &f->block[f->nblock++];
  snprintf(B->name, sizeof B->name, "%s", name);
  size_t cap = 0, blank = 0;
  while (**p) {
    const char *eol = strchr(*p, '\n');
    size_t n = eol ? (size_t)(eol - *p) : strlen(*p);
    if (n == strlen(term) && !strncmp(*p, term, n)) {
      *p += n + (eol != NULL);
      return 0;
    }
    double row[64];
    size_t k = 0;
    const char *q = *p, *end = *p + n;
    while (q < end) {
      while (q < end && (*q == ' ' || *q == '\t' || *q == '\r')) q++;
      if (q >= end) break;
      char *e;
      double v = strtod(q, &e);
      if (e == q || (e < end && *e != ' ' && *e != '\t' && *e != '\r')) {
        v = NAN; /* a word: no number there */
        while (q < end && *q != ' ' && *q != '\t') q++;
      } else {
        q = e;
      }
      if (k == 64) return unsupported(P, "a datablock row of more than 64 columns");
      row[k++] = v;
    }
    *p += n + (eol != NULL);
    if (k == 0) {
      blank = 1;
      continue;
    }
    if (B->nrow == 0) B->ncol = k;
    if (k != B->ncol) return unsupported(P, "datablock rows of different lengths");
    if (B->nrow == cap) {
      cap = cap ? 2 * cap : 256;
      double *v = realloc(B->v, cap * B->ncol * sizeof *v);
      unsigned char *br = realloc(B->brk, cap);
      if (v) B->v = v;
      if (br) B->brk = br;
      if (!v || !br) return -1;
    }
    memcpy(B->v + B->nrow * B->ncol, row, k * sizeof *row);
    B->brk[B->nrow++] = (unsigned char)blank;
    blank = 0;
  }
  return unsupported(P, "datablock without its end");
}

/* ---- the script --------------------------------------------------------- */

/* The next statement: a line, with lines ending in \ joined to it. */
static int next_line(const char **p, char *buf, size_t len) {
  size_t k = 0;
  while (**p) {
    const char *eol = strchr(*p, '\n');
    size_t n = eol ? (size_t)(eol - *p) : strlen(*p);
    const int cont = n > 0 && (*p)[n - 1] == '\\';
    const size_t take_n = cont ? n - 1 : n;
    if (k + take_n + 1 >= len) return -1;
    memcpy(buf + k, *p, take_n);
    k += take_n;
    *p += n + (eol != NULL);
    if (!cont) break;
  }
  buf[k] = '\0';
  return 0;
}

/* NAME = expression: a variable for the expressions after it */
static int assignment(parser *P, stmt *S) {
  gp_figure *f = P->fig;
  const char *name = S->t[0].text;
  char why[128];
  if (strlen(name) >= sizeof f->var[0].name || strspn(name, "abcdefghijklmnopqrstuvwxyz"
      "ABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789") != strlen(name) || f->nvar == 16)
    return unsupported(P, "a variable");
  gp_expr *e = gp_expr_parse(P->line + S->t[2].pos, f->var, f->nvar, why, sizeof why);
  if (!e) return unsupported(P, "%s = : %s", name, why);
  gp_var *v = &f->var[f->nvar++];
  memcpy(v->name, name, strlen(name) + 1); /* it fits: checked above */
  const gp_row none = {NULL, NULL, 0};
  v->value = gp_expr_value(e, &none, &v->is_int);
  gp_expr_free(e);
  return 0;
}

static int statement(parser *P, const char **p, const char *line) {
  stmt *const S = &P->S;
  char name[64], term[16];
  int used = 0;
  if (sscanf(line, " %63[$A-Za-z0-9_] << %15s %n", name, term, &used) == 2 &&
      name[0] == '$' && line[used] == '\0')
    return read_block(P, p, name, term);
  if (tokenize(line, S)) return unsupported(P, "a line not read here");
  if (S->n == 0) return 0;
  if (S->n >= 3 && S->t[0].kind == TOK_WORD && S->t[1].kind == TOK_WORD &&
      !strcmp(S->t[1].text, "="))
    return assignment(P, S);
  if (take(S, "set")) return set_stmt(P, S);
  if (take(S, "plot")) return plot_stmt(P, S);
  return unsupported(P, "statement %s", S->t[0].text);
}

int gp_parse(const char *text, gp_figure *fig, char *err, size_t len) {
  memset(fig, 0, sizeof *fig);
  fig->w = 640;
  fig->h = 480;
  fig->font_pt = 12;
  fig->enhanced = 1;
  fig->grid_rgb = 0xd0d0d0;
  fig->x.auto_lo = fig->x.auto_hi = fig->y.auto_lo = fig->y.auto_hi = 1;
  for (int k = 0; k < 4; k++) fig->margin[k] = -1;
  parser *P = malloc(sizeof *P);
  if (!P) return -1;
  P->fig = fig;
  P->err = err;
  P->len = len;
  err[0] = '\0';
  const char *p = text;
  int plotted = 0, rc = 0;
  while (*p && rc == 0) {
    if (next_line(&p, P->line, sizeof P->line)) rc = unsupported(P, "a line too long");
    else if (plotted && P->line[strspn(P->line, " \t\r")]) rc = unsupported(P, "after plot");
    else rc = statement(P, &p, P->line);
    plotted = fig->nseries > 0;
  }
  if (rc == 0 && !fig->nseries) rc = unsupported(P, "no plot");
  if (rc == 0 && !fig->output[0]) rc = unsupported(P, "no output");
  free(P);
  return rc;
}

void gp_figure_free(gp_figure *fig) {
  free(fig->title.s);
  free(fig->x.label.s);
  free(fig->y.label.s);
  free(fig->arrow);
  for (size_t i = 0; i < fig->nlabel; i++) free(fig->label[i].text.s);
  free(fig->label);
  for (size_t i = 0; i < fig->nblock; i++) {
    free(fig->block[i].v);
    free(fig->block[i].brk);
  }
  free(fig->block);
  for (size_t i = 0; i < fig->nseries; i++) {
    free(fig->series[i].title.s);
    free(fig->series[i].file);
    gp_expr_free(fig->series[i].ux);
    gp_expr_free(fig->series[i].uy);
  }
  free(fig->series);
  memset(fig, 0, sizeof *fig);
}

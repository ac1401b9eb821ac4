/* drivers/gp_data.c — the points of a figure's plot items (gp_data.h).
 * A table is read whole and cut in place into fields; a field that is a
 * number whole (blanks aside) has that value, any other NaN, and its text
 * stays for strcol().  gnuplot's reading: lines starting with '#' are
 * comments, a blank line breaks the curve, and a point with an undefined
 * coordinate is not drawn (the line breaks there too).
 * SPDX-License-Identifier: BSD-3-Clause */
#include "gp_data.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *gp_slurp(const char *path, size_t *nread) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  size_t cap = 1 << 16, n = 0, got;
  char *buf = malloc(cap);
  while (buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
    n += got;
    if (n + 1 == cap) {
      char *b = realloc(buf, 2 * cap);
      if (!b) {
        free(buf);
        buf = NULL;
        break;
      }
      buf = b;
      cap *= 2;
    }
  }
  if (buf && ferror(f)) {
    free(buf);
    buf = NULL;
  }
  fclose(f);
  if (buf) buf[n] = '\0';
  if (nread) *nread = n;
  return buf;
}

typedef struct table {
  const char *name;
  char *buf;           /* the file, its fields cut in place */
  char **text;         /* every field, row after row */
  double *num;         /* its number, NaN if it is not one */
  size_t *first, *nf;  /* a row's first field and count */
  unsigned char *brk;  /* a blank line before the row */
  size_t nrow, nfield;
} table;

static void table_free(table *t) {
  free(t->buf);
  free(t->text);
  free(t->num);
  free(t->first);
  free(t->nf);
  free(t->brk);
}

/* The value of field S: a number whole (blanks around it allowed), or NaN. */
static double field_number(const char *s) {
  char *end;
  const double v = strtod(s, &end);
  if (end == s) return NAN;
  end += strspn(end, " \t\r");
  return *end ? NAN : v;
}

/* Cut the line L (NUL-terminated) into fields at SEP (0: runs of blanks),
 * appending them to T.  -1 out of memory. */
static int add_row(table *t, char *l, char sep, unsigned char brk, size_t *cap, size_t *rcap) {
  if (t->nrow == *rcap) {
    *rcap = *rcap ? 2 * *rcap : 256;
    size_t *a = realloc(t->first, *rcap * sizeof *a);
    if (a) t->first = a;
    size_t *b = realloc(t->nf, *rcap * sizeof *b);
    if (b) t->nf = b;
    unsigned char *c = realloc(t->brk, *rcap);
    if (c) t->brk = c;
    if (!a || !b || !c) return -1;
  }
  t->first[t->nrow] = t->nfield;
  t->brk[t->nrow] = brk;
  for (char *p = l;;) {
    if (!sep) p += strspn(p, " \t");
    if (!sep && !*p) break;
    if (t->nfield == *cap) {
      *cap = *cap ? 2 * *cap : 1024;
      char **a = realloc(t->text, *cap * sizeof *a);
      if (a) t->text = a;
      double *b = realloc(t->num, *cap * sizeof *b);
      if (b) t->num = b;
      if (!a || !b) return -1;
    }
    const size_t n = sep ? strcspn(p, (char[]){sep, '\0'}) : strcspn(p, " \t");
    const int last = !p[n];
    p[n] = '\0';
    t->text[t->nfield] = p;
    t->num[t->nfield++] = field_number(p);
    if (last) break;
    p += n + 1;
  }
  t->nf[t->nrow] = t->nfield - t->first[t->nrow];
  t->nrow++;
  return 0;
}

/* Read the table DIR/NAME into T.  0, 1 (cannot be read), -1 (memory). */
static int table_read(table *t, const char *dir, const char *name, char sep) {
  char path[4096];
  memset(t, 0, sizeof *t);
  t->name = name;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  if (!(t->buf = gp_slurp(path, NULL))) return 1;
  size_t cap = 0, rcap = 0;
  unsigned char brk = 0;
  for (char *l = t->buf; *l;) {
    char *eol = strchr(l, '\n');
    if (eol) *eol = '\0';
    const size_t n = strlen(l);
    if (n && l[n - 1] == '\r') l[n - 1] = '\0';
    const char *first = l + strspn(l, " \t");
    if (!*first) brk = 1; /* a blank line: the curve breaks */
    else if (*first != '#' && add_row(t, l, sep, brk, &cap, &rcap)) return -1;
    else if (*first != '#') brk = 0;
    if (!eol) break;
    l = eol + 1;
  }
  return 0;
}

/* X or Y of row I of T: column COL, or expression E */
static double row_value(const table *t, size_t i, int col, const gp_expr *e) {
  const gp_row row = {(const char *const *)t->text + t->first[i], t->num + t->first[i],
                      t->nf[i]};
  if (e) return gp_expr_eval(e, &row);
  return col >= 1 && (size_t)col <= row.n ? row.num[col - 1] : NAN;
}

static int points_alloc(gp_points *p, size_t n) {
  p->x = malloc((n + 1) * sizeof *p->x);
  p->y = malloc((n + 1) * sizeof *p->y);
  p->brk = malloc(n + 1);
  p->n = n;
  return p->x && p->y && p->brk ? 0 : -1;
}

static void from_block(const gp_block *B, const gp_series *S, gp_points *p) {
  const size_t cx = (size_t)S->cx - 1, cy = (size_t)S->cy - 1;
  for (size_t i = 0; i < B->nrow; i++) {
    p->x[i] = cx < B->ncol ? B->v[i * B->ncol + cx] : NAN;
    p->y[i] = cy < B->ncol ? B->v[i * B->ncol + cy] : NAN;
    p->brk[i] = B->brk[i];
  }
}

static void from_table(const table *t, const gp_series *S, gp_points *p) {
  for (size_t i = 0; i < t->nrow; i++) {
    p->x[i] = row_value(t, i, S->cx, S->ux);
    p->y[i] = row_value(t, i, S->cy, S->uy);
    p->brk[i] = t->brk[i];
  }
}

/* The table NAME among those read (read now if it is not). */
static const table *table_of(table *tab, size_t *ntab, const char *dir, const char *name,
                             char sep, int *rc) {
  for (size_t k = 0; k < *ntab; k++)
    if (!strcmp(tab[k].name, name)) return &tab[k];
  *rc = table_read(&tab[*ntab], dir, name, sep);
  return *rc ? NULL : &tab[(*ntab)++];
}

int gp_series_points(const gp_figure *f, const char *dir, gp_points **pts, char *err,
                     size_t len) {
  gp_points *P = calloc(f->nseries + 1, sizeof *P);
  table *tab = calloc(f->nseries + 1, sizeof *tab); /* at most one a series */
  size_t ntab = 0;
  int rc = P && tab ? 0 : -1;
  for (size_t s = 0; s < f->nseries && rc == 0; s++) {
    const gp_series *S = &f->series[s];
    if (S->block != SIZE_MAX) {
      const gp_block *B = &f->block[S->block];
      if ((rc = points_alloc(&P[s], B->nrow)) == 0) from_block(B, S, &P[s]);
    } else if (S->file) {
      const table *t = table_of(tab, &ntab, dir, S->file, f->sep, &rc);
      if (rc == 1) snprintf(err, len, "cannot read %s", S->file);
      if (t && (rc = points_alloc(&P[s], t->nrow)) == 0) from_table(t, S, &P[s]);
    }
  }
  /* those read, and what a failed read left in the next one (zeros else) */
  for (size_t k = 0; tab && k <= ntab && k <= f->nseries; k++) table_free(&tab[k]);
  free(tab);
  if (rc) {
    if (rc < 0) snprintf(err, len, "out of memory");
    gp_points_free(P, f->nseries);
    P = NULL;
  }
  *pts = P;
  return rc;
}

void gp_points_free(gp_points *pts, size_t n) {
  if (!pts) return;
  for (size_t s = 0; s < n; s++) {
    free(pts[s].x);
    free(pts[s].y);
    free(pts[s].brk);
  }
  free(pts);
}

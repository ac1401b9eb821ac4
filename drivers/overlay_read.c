/* drivers/overlay_read.c — a run's branches.tsv for `whirl plot overlay`:
 * the header first, '#' comments, blank lines between blocks, one
 * tab-separated row a point (doc/tables.md).  Read strictly, so a table
 * that is not a branch table is refused with its file and line rather than
 * drawn wrong.  Nothing is printed: messages go to the caller's buffer.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "overlay.h"

#define OV_MAX_COLS 4096

/* The columns a branch table is read by: -1 where absent. */
typedef struct cols {
  int x, y, stab, type, branch;
  size_t n;
} cols;

/* Split LINE (its newline removed) at tabs into W (at most OV_MAX_COLS). */
static size_t split(char *line, char **w) {
  size_t n = 0;
  line[strcspn(line, "\r\n")] = '\0';
  for (char *s = line;; ++n) {
    if (n == OV_MAX_COLS) return n + 1;
    w[n] = s;
    char *t = strchr(s, '\t');
    if (!t) return n + 1;
    *t = '\0';
    s = t + 1;
  }
}

static int find(char **w, size_t n, const char *name) {
  for (size_t i = 0; i < n; i++)
    if (!strcmp(w[i], name)) return (int)i;
  return -1;
}

/* The header's columns: X and Y as asked (NULL: the defaults). */
static int header(char **w, size_t n, const char *x, const char *y, const int xy[2],
                  cols *c, ov_run *r, const char *path, char *msg, size_t len) {
  static const char *const ys[] = {"eps", "eps_max", "amplitude_m", "l2_norm"};
  c->n = n;
  c->stab = find(w, n, "stable");
  c->type = find(w, n, "type");
  c->branch = find(w, n, "branch");
  c->x = x ? find(w, n, x) : find(w, n, "Omega");
  if (!x && c->x < 0 && c->type == 2 && n > 4) c->x = 4; /* whirl run: PAR(1) */
  c->y = -1;
  for (size_t k = 0; !y && k < sizeof ys / sizeof *ys && c->y < 0; k++) c->y = find(w, n, ys[k]);
  if (y) c->y = find(w, n, y);
  if (xy) /* by position (whirl run's picture knows its columns so) */
    c->x = xy[0] < (int)n ? xy[0] : -1, c->y = xy[1] < (int)n ? xy[1] : -1;
  const char *miss = c->stab < 0 ? "stable"
                     : c->x < 0   ? (x ? x : "Omega")
                     : c->y < 0   ? (y ? y : "eps (nor eps_max, amplitude_m, l2_norm)")
                                  : NULL;
  if (miss) {
    snprintf(msg, len, "%s: its header (line 1) has no column %s%s", path, miss,
             c->stab < 0 ? ": not a branch table" : " (name one with --x or --y)");
    return -1;
  }
  snprintf(r->xname, sizeof r->xname, "%s", w[c->x]);
  snprintf(r->yname, sizeof r->yname, "%s", w[c->y]);
  return 0;
}

/* A number of the table: all of the field, finite or nan. */
static int number(const char *s, double *v) {
  char *end;
  errno = 0;
  *v = strtod(s, &end);
  return end != s && *end == '\0' && errno != ERANGE ? 0 : -1;
}

/* The "k=v" words of a comment line, as "k=v k=v" (commas dropped). */
static void params_of(const char *line, char *out, size_t len) {
  char buf[1024];
  size_t used = 0;
  snprintf(buf, sizeof buf, "%s", line);
  out[0] = '\0';
  for (char *save = NULL, *t = strtok_r(buf, " \t\r\n", &save); t;
       t = strtok_r(NULL, " \t\r\n", &save)) {
    size_t l = strlen(t);
    while (l && (t[l - 1] == ',' || t[l - 1] == ';')) t[--l] = '\0';
    if (!strchr(t, '=') || t[0] == '=' || used + l + 2 > len) continue;
    used += (size_t)snprintf(out + used, len - used, "%s%s", used ? " " : "", t);
  }
}

static int add_point(ov_run *r, size_t *cap, const ov_point *p) {
  if (r->n == *cap) {
    size_t c = *cap ? 2 * *cap : 256;
    ov_point *g = realloc(r->pt, c * sizeof *g);
    if (!g) return -1;
    r->pt = g;
    *cap = c;
  }
  r->pt[r->n++] = *p;
  return 0;
}

/* One data row W (N fields) as a point; its segment from SEG. */
static int row(char **w, size_t n, const cols *c, size_t seg, ov_point *p,
               const char *path, int lineno, char *msg, size_t len) {
  double s;
  if (n != c->n) {
    snprintf(msg, len, "%s:%d: %zu fields where the header has %zu", path, lineno, n, c->n);
    return -1;
  }
  if (number(w[c->x], &p->x) || number(w[c->y], &p->y) || number(w[c->stab], &s) ||
      (s != 1 && s != 0 && s != -1)) {
    snprintf(msg, len, "%s:%d: not a row of numbers ('%.40s' '%.40s', stable '%.10s')", path,
             lineno, w[c->x], w[c->y], w[c->stab]);
    return -1;
  }
  p->stab = (int)s;
  p->lp = c->type >= 0 && !strcmp(w[c->type], "LP");
  p->seg = seg;
  return 0;
}

/* The rows of F after its header. */
static int rows(FILE *f, const cols *c, ov_run *r, const char *path, char *msg,
                size_t len) {
  char *line = NULL, **w = malloc((OV_MAX_COLS + 1) * sizeof *w), last[64] = "";
  size_t n = 0, cap = 0, seg = 0;
  int lineno = 1, rc = w ? 0 : -1;
  while (rc == 0 && getline(&line, &n, f) > 0) {
    lineno++;
    if (line[0] == '#') {
      if (!r->params[0]) params_of(line + 1, r->params, sizeof r->params);
      continue;
    }
    if (line[strspn(line, " \t\r\n")] == '\0') { /* a blank line: a new block */
      seg++;
      continue;
    }
    size_t nw = split(line, w);
    ov_point p;
    if ((rc = row(w, nw, c, seg, &p, path, lineno, msg, len)) != 0) break;
    if (c->branch >= 0 && strcmp(w[c->branch], last)) { /* a new branch */
      if (last[0]) p.seg = ++seg;
      snprintf(last, sizeof last, "%s", w[c->branch]);
    }
    if (add_point(r, &cap, &p)) rc = -1, snprintf(msg, len, "%s: out of memory", path);
  }
  if (rc == 0 && ferror(f)) rc = -1, snprintf(msg, len, "%s: read error", path);
  if (rc == 0 && r->n == 0) rc = -1, snprintf(msg, len, "%s: no rows after the header", path);
  free(line);
  free(w);
  return rc;
}

static int read_table(ov_run *r, const char *dir, const char *x, const char *y,
                      const int xy[2], char *msg, size_t len) {
  char path[4200], *line = NULL, **w = NULL;
  size_t n = 0;
  memset(r, 0, sizeof *r);
  snprintf(r->dir, sizeof r->dir, "%s", dir);
  for (size_t l = strlen(r->dir); l > 1 && r->dir[l - 1] == '/';) r->dir[--l] = '\0';
  snprintf(path, sizeof path, "%s/branches.tsv", r->dir);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, len, "%s: no branches.tsv in it (%s): give the output directories of "
             "whirl sfd response, sfd nonsync, rotor response or run", r->dir, strerror(errno));
    return -1;
  }
  cols c;
  int rc = -1;
  if (getline(&line, &n, f) <= 0 || line[0] == '#')
    snprintf(msg, len, "%s: no header line first (doc/tables.md)", path);
  else if (!(w = malloc((OV_MAX_COLS + 1) * sizeof *w)))
    snprintf(msg, len, "%s: out of memory", path);
  else if (header(w, split(line, w), x, y, xy, &c, r, path, msg, len) == 0)
    rc = rows(f, &c, r, path, msg, len);
  free(w);
  free(line);
  fclose(f);
  if (rc) ov_free(r);
  return rc;
}

int ov_read(ov_run *r, const char *dir, const char *x, const char *y, char *msg,
            size_t len) {
  return read_table(r, dir, x, y, NULL, msg, len);
}

int ov_read_columns(ov_run *r, const char *dir, int x, int y, char *msg, size_t len) {
  const int xy[2] = {x, y};
  return read_table(r, dir, NULL, NULL, xy, msg, len);
}

void ov_free(ov_run *r) {
  free(r->pt);
  r->pt = NULL;
  r->n = 0;
}

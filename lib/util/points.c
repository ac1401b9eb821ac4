/* lib/util/points.c — a list of parameter sets from a TSV file (see
 * whirl/points.h).  Messages are the user's: "FILE:LINE: what", no source
 * location.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* getline */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/points.h>

/* The fields of a line (tabs between them, blanks around them trimmed):
 * the count, or max + 1 when there are more than max. */
static size_t split(char *line, char **f, size_t max) {
  size_t n = 0;
  line[strcspn(line, "\r\n")] = '\0';
  for (char *c = line;;) {
    char *t = strchr(c, '\t');
    if (t) *t = '\0';
    while (*c == ' ') c++;
    for (size_t e = strlen(c); e && c[e - 1] == ' ';) c[--e] = '\0';
    if (n == max) return max + 1;
    f[n++] = c;
    if (!t) return n;
    c = t + 1;
  }
}

static int header(const char *path, size_t ln, char **f, size_t n, size_t maxcols,
                  whirl_points_name_check check, void *ctx, whirl_points *P, char *msg,
                  size_t len) {
  if (n > maxcols) {
    snprintf(msg, len, "%s:%zu: more than %zu columns", path, ln, maxcols);
    return WHIRL_EINVAL;
  }
  if (!(P->names = calloc(n, sizeof *P->names))) return WHIRL_ENOMEM;
  char why[512];
  for (size_t a = 0; a < n; a++) {
    if (!f[a][0] || strlen(f[a]) >= WHIRL_POINTS_MAXNAME)
      snprintf(why, sizeof why, "%s", f[a][0] ? "is too long a name" : "is an empty name");
    else if (!check || !check(f[a], a, why, sizeof why, ctx)) {
      snprintf(P->names[a], WHIRL_POINTS_MAXNAME, "%s", f[a]);
      continue;
    }
    snprintf(msg, len, "%s:%zu: column %zu, '%.80s' %s", path, ln, a + 1, f[a], why);
    return WHIRL_EINVAL;
  }
  P->ncols = n;
  P->header_line = ln;
  return WHIRL_OK;
}

static int row(const char *path, size_t ln, char **f, size_t n, size_t *cap, whirl_points *P,
               char *msg, size_t len) {
  const size_t m = P->ncols;
  if (n != m) {
    snprintf(msg, len, "%s:%zu: %s%zu value%s where the header names %zu column%s", path, ln,
             n > m ? "more than " : "", n > m ? m : n, n == 1 && n <= m ? "" : "s", m,
             m == 1 ? "" : "s");
    return WHIRL_EINVAL;
  }
  if (P->nrows == *cap) {
    const size_t c = *cap ? 2 * *cap : 16;
    double *v = realloc(P->v, c * m * sizeof *v);
    if (!v) return WHIRL_ENOMEM;
    P->v = v, *cap = c;
  }
  double *v = P->v + P->nrows * m;
  for (size_t a = 0; a < m; a++) {
    char *end;
    errno = 0;
    v[a] = strtod(f[a], &end);
    if (end == f[a] || *end || errno == ERANGE || !isfinite(v[a])) {
      snprintf(msg, len, "%s:%zu: column %zu (%s): '%.80s' is not a finite number", path, ln,
               a + 1, P->names[a], f[a]);
      return WHIRL_EINVAL;
    }
  }
  P->nrows++;
  return WHIRL_OK;
}

int whirl_points_read(const char *path, size_t maxcols, whirl_points_name_check check,
                      void *ctx, whirl_points *out, char *msg, size_t len) {
  char dummy[1];
  if (!msg || !len) msg = dummy, len = sizeof dummy;
  msg[0] = '\0';
  if (!path || !out || maxcols == 0) return WHIRL_EINVAL;
  memset(out, 0, sizeof *out);
  FILE *fp = fopen(path, "r");
  if (!fp) {
    snprintf(msg, len, "cannot read '%s': %s", path, strerror(errno));
    return WHIRL_EIO;
  }
  char *line = NULL, **f = malloc((maxcols + 1) * sizeof *f);
  size_t cap = 0, rcap = 0, ln = 0;
  int rc = f ? WHIRL_OK : WHIRL_ENOMEM, have = 0;
  while (rc == WHIRL_OK && getline(&line, &cap, fp) > 0) {
    ln++;
    if (line[strspn(line, " \t\r\n")] == '\0' || line[0] == '#') continue;
    const size_t n = split(line, f, maxcols);
    rc = have ? row(path, ln, f, n, &rcap, out, msg, len)
              : header(path, ln, f, n, maxcols, check, ctx, out, msg, len);
    have = 1;
  }
  if (rc == WHIRL_OK && ferror(fp)) {
    snprintf(msg, len, "%s: %s", path, strerror(errno));
    rc = WHIRL_EIO;
  }
  free(line);
  free(f);
  fclose(fp);
  if (rc == WHIRL_OK && !out->nrows) {
    snprintf(msg, len, "%s:%zu: no points (%s)", path, ln ? ln : 1,
             have ? "a header and no rows of values" : "not even a header of names");
    rc = WHIRL_EINVAL;
  }
  if (rc == WHIRL_ENOMEM) snprintf(msg, len, "%s: out of memory", path);
  if (rc != WHIRL_OK) whirl_points_free(out);
  return rc;
}

void whirl_points_free(whirl_points *p) {
  if (!p) return;
  free(p->names);
  free(p->v);
  memset(p, 0, sizeof *p);
}

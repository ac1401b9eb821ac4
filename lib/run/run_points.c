/* lib/run/run_points.c — the points of a parameter study from a TSV file
 * (POINTS = file.tsv, doc/parameter-studies.md): a header line of
 * parameter names, then a row of values a point, separated by tabs; blank
 * lines and lines starting with '#' are skipped.  Every name must be a
 * parameter of the model (not the continuation parameter, not twice),
 * every row must have a finite number under each name, and there must be
 * a point: otherwise "FILE:LINE: what", and the run is bad input.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* getline */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_impl.h"

/* The fields of a line (tabs between them, blanks around them trimmed), at
 * most max: the count, or max + 1 when there are more. */
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

/* The header's names into the study's axes: 0, or -1 (said). */
static int header(run_ctx *R, const char *path, size_t ln, char **f, size_t n) {
  if (n > WHIRL_RUN_MAXITEMS) {
    run_say(R, "%s:%zu: more than %d columns", path, ln, WHIRL_RUN_MAXITEMS);
    return -1;
  }
  for (size_t a = 0; a < n; a++) {
    whirl_run_ref ref = {0, ""};
    snprintf(ref.name, sizeof ref.name, "%s", f[a]);
    const int k = f[a][0] ? run_par_index(R, &ref) : -1;
    const char *why = k < 0 ? "is not a parameter of model" : k == R->icp[0]
                      ? "is the continuation parameter (ICP) of model" : NULL;
    for (size_t b = 0; !why && b < a; b++)
      if (R->study_par[b] == k) why = "is named twice for model";
    if (why) {
      run_say(R, "%s:%zu: column %zu, '%s' %s '%s' (the header names parameters that "
              "a study varies)", path, ln, a + 1, f[a], why, R->prob.name);
      return -1;
    }
    R->study_par[a] = k;
  }
  R->study_naxes = n;
  return 0;
}

/* One row of values appended: 0, or -1 (said). */
static int row(run_ctx *R, const char *path, size_t ln, char **f, size_t n) {
  const size_t m = R->study_naxes;
  if (n != m) {
    run_say(R, "%s:%zu: %s%zu value%s where the header names %zu parameter%s", path, ln,
            n > m ? "more than " : "", n > m ? m : n, n == 1 && n <= m ? "" : "s", m, m == 1 ? "" : "s");
    return -1;
  }
  double *v = realloc(R->points, (R->study_npoints + 1) * m * sizeof *v);
  if (!v) {
    run_say(R, "%s: out of memory", path);
    return -1;
  }
  R->points = v;
  v += R->study_npoints * m;
  for (size_t a = 0; a < m; a++) {
    char *end;
    errno = 0;
    v[a] = strtod(f[a], &end);
    if (end == f[a] || *end || errno == ERANGE || !isfinite(v[a])) {
      run_say(R, "%s:%zu: column %zu (%s): '%s' is not a finite number", path, ln, a + 1,
              R->pnames[R->study_par[a]], f[a]);
      return -1;
    }
  }
  R->study_npoints++;
  return 0;
}

int run_points_load(run_ctx *R, const char *path) {
  FILE *fp = fopen(path, "r");
  if (!fp) {
    run_fail(R, WHIRL_RK_POINTS, "POINTS: cannot read '%s': %s", path, strerror(errno));
    return -1;
  }
  char *line = NULL, *f[WHIRL_RUN_MAXITEMS + 1];
  size_t cap = 0, ln = 0;
  int rc = 0, have_header = 0;
  R->study_npoints = 0;
  while (!rc && getline(&line, &cap, fp) > 0) {
    ln++;
    if (line[strspn(line, " \t\r\n")] == '\0' || line[0] == '#') continue;
    const size_t n = split(line, f, WHIRL_RUN_MAXITEMS);
    rc = have_header ? row(R, path, ln, f, n) : header(R, path, ln, f, n);
    have_header = 1;
  }
  free(line);
  fclose(fp);
  if (!rc && !R->study_npoints) {
    run_say(R, "%s:%zu: no points (%s)", path, ln,
            have_header ? "a header and no rows of values" : "not even a header of parameter names");
    rc = -1;
  }
  return rc;
}

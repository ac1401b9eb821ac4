/* test/unit/t_gp_parse.c — drivers/gp_parse.c, the reader of the gnuplot
 * scripts whirl draws itself: a script of `whirl sfd response`
 * (test/fuzz/corpus-picture/response.gp) is parsed; the dash types and
 * point types it draws as gnuplot does are taken, any other value (another
 * pattern or symbol, a fraction, a number no int holds: the fuzzer's
 * `dt 1111...112`, undefined behaviour before) is left to gnuplot (1,
 * naming it).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gp_figure.h"
#include "tap.h"

#ifndef SRCDIR
#define SRCDIR "."
#endif

static char *slurp(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  char *s = malloc(1 << 16);
  size_t n = s ? fread(s, 1, (1 << 16) - 1, f) : 0;
  fclose(f);
  if (s) s[n] = '\0';
  return s;
}

/* TEXT with the first FROM replaced by TO (a new string). */
static char *replaced(const char *text, const char *from, const char *to) {
  const char *at = strstr(text, from);
  if (!at) return NULL;
  size_t a = (size_t)(at - text), lf = strlen(from), lt = strlen(to);
  char *s = malloc(strlen(text) - lf + lt + 1);
  if (!s) return NULL;
  memcpy(s, text, a);
  memcpy(s + a, to, lt);
  strcpy(s + a + lt, at + lf);
  return s;
}

static int parse(const char *text, char *err, size_t len) {
  gp_figure fig;
  memset(&fig, 0, sizeof fig);
  err[0] = '\0';
  const int rc = gp_parse(text, &fig, err, len);
  gp_figure_free(&fig);
  return rc;
}

int main(void) {
  char err[256];
  char *base = slurp(SRCDIR "/test/fuzz/corpus-picture/response.gp");
  ok(base != NULL, "read response.gp");
  if (!base) return done_testing();
  int rc = parse(base, err, sizeof err);
  ok(rc == 0, "response.gp as written is drawn here (%d %s)", rc, err);
  static const struct {
    const char *from, *to;
    int want;
    const char *why;
  } cases[] = {
      {"nohead dt 2", "nohead dt 1111111111111111111111111111111111111112", 1, "dash type"},
      {"nohead dt 2", "nohead dt 1e300", 1, "dash type"},
      {"nohead dt 2", "nohead dt -3", 1, "dash type"},
      {"nohead dt 2", "nohead dt 2.5", 1, "dash type"},
      {"nohead dt 2", "nohead dt 6", 1, "dash type"},
      {"nohead dt 2", "nohead dt 5", 0, NULL},
      {"with lines dt 2", "with lines dt 1e300", 1, "dash type"},
      {"with lines dt 2", "with lines dt 3", 0, NULL},
      {"with points pt 7", "with points pt 1", 1, "point type"},
      {"with points pt 7", "with points pt 7e300", 1, "point type"},
      {"with points pt 7", "with points pt 6", 0, NULL},
  };
  for (size_t k = 0; k < sizeof cases / sizeof *cases; ++k) {
    char *s = replaced(base, cases[k].from, cases[k].to);
    rc = s ? parse(s, err, sizeof err) : -9;
    ok(rc == cases[k].want && (!cases[k].why || strstr(err, cases[k].why)),
       "'%s': %s (%d, %s)", cases[k].to,
       cases[k].want ? "left to gnuplot" : "drawn here", rc, err);
    free(s);
  }
  free(base);
  return done_testing();
}

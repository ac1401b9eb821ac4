/* drivers/cli.c — option parsing with messages that say what and where,
 * for every whirl subcommand.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <whirl/runfile.h>

#include "cli.h"

/* Length of a source location " (name.c:123)" at s, or 0. */
static size_t location_len(const char *s) {
  if (s[0] != ' ' || s[1] != '(') return 0;
  size_t k = 2;
  while (s[k] && (isalnum((unsigned char)s[k]) || s[k] == '_' || s[k] == '-' ||
                  s[k] == '/'))
    ++k;
  if (k == 2 || s[k] != '.' || (s[k + 1] != 'c' && s[k + 1] != 'h') || s[k + 2] != ':')
    return 0;
  k += 3;
  const size_t digits = k;
  while (isdigit((unsigned char)s[k])) ++k;
  return k > digits && s[k] == ')' ? k + 1 : 0;
}

void cli_strip_locations(char *s) {
  char *w = s;
  for (const char *r = s; *r;) {
    const size_t skip = location_len(r);
    if (skip) r += skip;
    else *w++ = *r++;
  }
  *w = '\0';
}

void cli_error(const char *cmd, const char *fmt, ...) {
  char msg[4096];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  cli_strip_locations(msg);
  fprintf(stderr, "whirl %s: %s\n", cmd, msg);
}

/* Numbers as run files write them (whirl_run_number): no blanks, no
 * hexadecimal; an underflow such as 1e-310 is the nearest double. */
int cli_double(const char *cmd, const char *opt, const char *text, double *v) {
  int rc = whirl_run_number(text, v);
  if (rc == WHIRL_EDOMAIN)
    cli_error(cmd, "%s must be a finite number, got '%s'", opt, text);
  else if (rc)
    cli_error(cmd, "%s expects a number, got '%s'", opt, text);
  return rc ? -1 : 0;
}

const char *cli_value(int argc, char **argv, int *i, const char *name,
                      int *missing) {
  const char *a = argv[*i];
  size_t len = strlen(name);
  *missing = 0;
  if (strncmp(a, name, len) != 0) return NULL;
  if (a[len] == '=') return a + len + 1;
  if (a[len] != '\0') return NULL;
  if (*i + 1 >= argc) {
    *missing = 1;
    return NULL;
  }
  return argv[++*i];
}

int cli_is_tty(void) { return isatty(fileno(stderr)); }

int cli_parse(const char *cmd, int argc, char **argv, const cli_opt *opts,
              size_t nopts, void (*help)(FILE *)) {
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      help(stdout);
      return 1;
    }
    int matched = 0;
    for (size_t k = 0; k < nopts && !matched; ++k) {
      const cli_opt *o = &opts[k];
      if (o->kind == CLI_FLAG) {
        if (!strcmp(argv[i], o->name)) {
          *(int *)o->dst = 1;
          matched = 1;
        }
        continue;
      }
      int missing = 0;
      const char *v = cli_value(argc, argv, &i, o->name, &missing);
      if (missing) {
        cli_error(cmd, "option %s needs a value", o->name);
        return 2;
      }
      if (!v) continue;
      matched = 1;
      char *end = NULL;
      switch (o->kind) {
        case CLI_DOUBLE:
          if (cli_double(cmd, o->name, v, (double *)o->dst)) return 2;
          break;
        case CLI_SIZE:
        case CLI_INT: {
          errno = 0;
          long long n = strtoll(v, &end, 10);
          if (end == v || *end || errno == ERANGE || isspace((unsigned char)v[0]) ||
              (o->kind == CLI_SIZE && n < 0) ||
              (o->kind == CLI_INT && (n < -2147483647LL || n > 2147483647LL))) {
            cli_error(cmd, "%s expects %s integer, got '%s'", o->name,
                      o->kind == CLI_SIZE ? "a non-negative" : "an", v);
            return 2;
          }
          if (o->kind == CLI_SIZE)
            *(size_t *)o->dst = (size_t)n;
          else
            *(int *)o->dst = (int)n;
          break;
        }
        case CLI_STRING:
          if (!*v) {
            cli_error(cmd, "%s needs a non-empty value", o->name);
            return 2;
          }
          *(const char **)o->dst = v;
          break;
        case CLI_FLAG:
          break;
      }
    }
    if (!matched) {
      cli_error(cmd, "unknown option '%s' (see whirl %s --help)", argv[i], cmd);
      return 2;
    }
  }
  return 0;
}

double cli_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cli_progress_init(cli_progress *p, const char *what, int quiet) {
  p->on = !quiet && cli_is_tty();
  p->last = -1;
  p->what = what;
}

void cli_progress_show(cli_progress *p, size_t done, size_t total) {
  if (!p->on) return;
  double now = cli_now();
  if (done < total && p->last >= 0 && now - p->last < 0.2) return;
  p->last = now;
  fprintf(stderr, "\r%s: %zu/%zu (%.0f%%)  ", p->what, done, total,
          total ? 100.0 * (double)done / (double)total : 100.0);
  fflush(stderr);
}

void cli_progress_end(cli_progress *p) {
  if (!p->on) return;
  fprintf(stderr, "\r\033[K");
  fflush(stderr);
}

/* drivers/cli.c — option parsing with messages that say what and where,
 * for every whirl subcommand.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"

void cli_error(const char *cmd, const char *fmt, ...) {
  va_list ap;
  fprintf(stderr, "whirl %s: ", cmd);
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
}

int cli_double(const char *cmd, const char *opt, const char *text, double *v) {
  char *end = NULL;
  errno = 0;
  double d = strtod(text, &end);
  if (end == text || *end != '\0' || errno == ERANGE) {
    cli_error(cmd, "%s expects a number, got '%s'", opt, text);
    return -1;
  }
  if (!isfinite(d)) {
    cli_error(cmd, "%s must be a finite number, got '%s'", opt, text);
    return -1;
  }
  *v = d;
  return 0;
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

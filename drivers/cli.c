/* drivers/cli.c — option parsing with messages that say what and where,
 * for every whirl subcommand.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, fileno */
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

/* ------------------------------------------------------------------------
 * --help from the option table */

#define HELP_WIDTH 79   /* columns of --help */
#define HELP_COL_MAX 22 /* where the help starts at most; a longer option
                           puts its help on the next line */
#define DEFAULT_LEN 48  /* a default as shown */

/* "1e-05" -> "1e-5", "1e+06" -> "1e6": exponents as the texts write them. */
static void tidy_exponent(char *s) {
  char *e = strchr(s, 'e');
  if (!e) return;
  char *r = e + 1, *w = e + 1;
  if (*r == '+') ++r;
  else if (*r == '-') *w++ = *r++;
  while (*r == '0' && r[1]) ++r;
  memmove(w, r, strlen(r) + 1);
}

/* The default of o as --help shows it: o->dflt, or *o->dst now (before
 * parsing), "required" for a NaN (a value that must be given); "" for
 * none (flags, a NULL string). */
static void format_default(const cli_opt *o, char *buf, size_t len) {
  buf[0] = '\0';
  if (o->dflt) {
    snprintf(buf, len, "%s", o->dflt);
    return;
  }
  switch (o->kind) {
    case CLI_DOUBLE: {
      const double v = *(const double *)o->dst;
      if (isnan(v)) {
        snprintf(buf, len, "required");
      } else {
        snprintf(buf, len, "%g", v);
        tidy_exponent(buf);
      }
      break;
    }
    case CLI_SIZE:
      snprintf(buf, len, "%zu", *(const size_t *)o->dst);
      break;
    case CLI_INT:
      snprintf(buf, len, "%d", *(const int *)o->dst);
      break;
    case CLI_STRING: {
      const char *v = *(const char *const *)o->dst;
      if (v) snprintf(buf, len, "%s", v);
      break;
    }
    case CLI_FLAG:
      break;
  }
}

/* TEXT from column COL (where the cursor is), its words wrapped to
 * HELP_WIDTH, every line starting at COL; '\n' in TEXT breaks the line. */
static void print_wrapped(FILE *f, const char *text, size_t col) {
  size_t pos = col;
  for (const char *s = text; *s;) {
    if (*s == '\n' || *s == ' ') {
      if (*s++ == '\n') pos = HELP_WIDTH + 1; /* the next word starts a line */
      continue;
    }
    const size_t w = strcspn(s, " \n");
    if (pos > col && pos + 1 + w > HELP_WIDTH) {
      fprintf(f, "\n%*s", (int)col, "");
      pos = col;
    } else if (pos > col) {
      fputc(' ', f);
      ++pos;
    }
    fwrite(s, 1, w, f);
    pos += w;
    s += w;
  }
  fputc('\n', f);
}

/* "--name ARG" of o. */
static void option_label(const cli_opt *o, char *buf, size_t len) {
  snprintf(buf, len, "%s%s%s", o->name, o->arg ? " " : "", o->arg ? o->arg : "");
}

/* One option: its label, then its help with the default DEF appended to the
 * help's first line. */
static void print_option(FILE *f, const char *label, const char *help,
                         const char *def, size_t col) {
  char text[2048];
  const size_t first = strcspn(help, "\n");
  if (*def)
    snprintf(text, sizeof text, "%.*s%s(%s)%s", (int)first, help, first ? " " : "", def,
             help + first);
  else
    snprintf(text, sizeof text, "%s", help);
  fprintf(f, "  %s", label);
  const size_t used = 2 + strlen(label);
  if (!*text) {
    fputc('\n', f);
    return;
  }
  if (used + 2 > col)
    fprintf(f, "\n%*s", (int)col, "");
  else
    fprintf(f, "%*s", (int)(col - used), "");
  print_wrapped(f, text, col);
}

void cli_help_item(FILE *f, const char *label, const char *text, size_t col) {
  print_option(f, label, text, "", col);
}

/* The help of a command: doc->head, the options with the defaults
 * shown[k], --help itself, doc->tail. */
static void print_help(FILE *f, const cli_opt *opts, size_t nopts,
                       const char (*shown)[DEFAULT_LEN], const cli_doc *doc) {
  char label[128];
  size_t col = strlen("--help") + 6; /* 2 before, at least 2 after */
  for (size_t k = 0; k < nopts; ++k) {
    option_label(&opts[k], label, sizeof label);
    const size_t want = strlen(label) + 6;
    if (want <= HELP_COL_MAX && want > col) col = want;
  }
  fputs(doc->head, f);
  for (size_t k = 0; k < nopts; ++k) {
    option_label(&opts[k], label, sizeof label);
    print_option(f, label, opts[k].help ? opts[k].help : "", shown[k], col);
  }
  print_option(f, "--help", "this text", "", col);
  if (doc->tail) fprintf(f, "\n%s", doc->tail);
}

/* ------------------------------------------------------------------------
 * Parsing */

/* Store the value text V of option o; 0, or 2 with the message printed. */
static int store_value(const char *cmd, const cli_opt *o, const char *v) {
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
  return 0;
}

/* Parse argv[*i] (and its value); 0, -1 if no option matches, 2 on a bad
 * value (message printed). */
static int parse_one(const char *cmd, int argc, char **argv, int *i,
                     const cli_opt *opts, size_t nopts) {
  for (size_t k = 0; k < nopts; ++k) {
    const cli_opt *o = &opts[k];
    if (o->kind == CLI_FLAG) {
      if (strcmp(argv[*i], o->name)) continue;
      *(int *)o->dst = 1;
      return 0;
    }
    int missing = 0;
    const char *v = cli_value(argc, argv, i, o->name, &missing);
    if (missing) {
      cli_error(cmd, "option %s needs a value", o->name);
      return 2;
    }
    if (v) return store_value(cmd, o, v);
  }
  return -1;
}

int cli_parse(const char *cmd, int argc, char **argv, const cli_opt *opts,
              size_t nopts, const cli_doc *doc) {
  /* the defaults as they are before any option changes them */
  char (*shown)[DEFAULT_LEN] = calloc(nopts + 1, sizeof *shown);
  if (!shown) {
    cli_error(cmd, "out of memory");
    return 2;
  }
  for (size_t k = 0; k < nopts; ++k) format_default(&opts[k], shown[k], DEFAULT_LEN);
  int rc = 0;
  for (int i = 1; i < argc && !rc; ++i) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      print_help(stdout, opts, nopts, (const char(*)[DEFAULT_LEN])shown, doc);
      rc = 1;
    } else if ((rc = parse_one(cmd, argc, argv, &i, opts, nopts)) < 0) {
      cli_error(cmd, "unknown option '%s' (see whirl %s --help)", argv[i], cmd);
      rc = 2;
    }
  }
  free(shown);
  return rc;
}

double cli_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cli_progress_init(cli_progress *p, const char *what, int quiet) {
  p->on = !quiet && cli_is_tty();
  p->shown = 0;
  p->last = -1;
  p->start = cli_now();
  p->what = what;
}

void cli_duration(double s, char *buf, size_t len) {
  if (!(s >= 0) || s > 1e8) snprintf(buf, len, "?");
  else if (s >= 3600) snprintf(buf, len, "%dh%02dm", (int)(s / 3600), (int)fmod(s, 3600) / 60);
  else if (s >= 60) snprintf(buf, len, "%dm%02ds", (int)(s / 60), (int)fmod(s, 60));
  else snprintf(buf, len, "%ds", (int)ceil(s));
}

void cli_progress_show(cli_progress *p, size_t done, size_t total) {
  if (!p->on) return;
  double now = cli_now();
  if (done == 0 && !p->shown) p->start = now; /* a new piece of work */
  if (done < total && (now - p->start < 0.5 || (p->last >= 0 && now - p->last < 0.2))) return;
  p->last = now;
  if (done > total) done = total;
  /* the mean rate so far: (elapsed / done) per unit for the rest */
  char eta[32];
  cli_duration(done ? (now - p->start) * (double)(total - done) / (double)done : -1, eta,
               sizeof eta);
  fprintf(stderr, "\r\033[K%s: %zu/%zu (%.0f%%), ETA %s", p->what, done, total,
          total ? 100.0 * (double)done / (double)total : 100.0, eta);
  fflush(stderr);
  p->shown = 1;
}

void cli_progress_clear(cli_progress *p) {
  if (!p->on || !p->shown) return;
  fprintf(stderr, "\r\033[K");
  fflush(stderr);
  p->shown = 0;
  p->last = -1; /* drawn again at the next show */
}

void cli_progress_end(cli_progress *p) {
  if (!p->on) return;
  fprintf(stderr, "\r\033[K");
  fflush(stderr);
  p->shown = 0;
}

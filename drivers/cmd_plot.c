/* drivers/cmd_plot.c — `whirl plot overlay DIR...`: the branch tables of
 * several runs (sfd response, sfd nonsync, rotor response, whirl run) on
 * one picture, as the paper's Fig. 6a draws the response for six δ.  The
 * inputs are read and checked before anything is written; the picture is
 * drawn as every command's (drivers/plot.c: --format, one output directory
 * swapped in whole, the script left beside it, the same behaviour without
 * gnuplot).
 * SPDX-License-Identifier: BSD-3-Clause */
#define _XOPEN_SOURCE 700 /* realpath */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "overlay.h"

#define CMD "plot overlay"
#define OV_MAX_RUNS 64

static const cli_doc doc = {
"usage: whirl plot overlay DIR1 DIR2 ... [options]\n"
"\n"
"Draw the branches of several runs on one picture: the branches.tsv of\n"
"output directories of whirl sfd response, sfd nonsync, rotor response or\n"
"whirl run, each run in its own colour (stable solid, unstable dashed,\n"
"folds LP marked) with a legend entry a run.  The directories come first.\n"
"\n"
"options:\n",
"Legend: --labels, else the parameters that differ between the runs (from\n"
"each table's first comment line, e.g. delta=0.1), else the directories.\n"
"Axes: Omega against the first of eps, eps_max, amplitude_m, l2_norm\n"
"(whirl run without Omega: its first parameter), or --x, --y.\n"
"DIR/NAME.png (.pdf, .svg) and DIR/NAME.gp, the script that redraws it.\n"
"Exit status: 0; 2 bad input (nothing written); 1 a file could not be\n"
"written or drawn."};

/* LIST "a,b,c" into N labels, or -1 when it does not hold N. */
static int split_labels(const char *list, size_t n, char (*out)[256]) {
  size_t k = 0;
  for (const char *s = list;; k++) {
    size_t l = strcspn(s, ",");
    if (k < n) snprintf(out[k], 256, "%.*s", (int)(l < 255 ? l : 255), s);
    if (!s[l]) break;
    s += l + 1;
  }
  return k + 1 == n ? 0 : -1;
}

static size_t count_labels(const char *list) {
  size_t k = 1;
  for (; *list; list++) k += *list == ',';
  return k;
}

/* Is OUT one of the inputs (the same directory, however named)? */
static int is_input(const char *out, const ov_run *runs, size_t n) {
  char a[PATH_MAX], b[PATH_MAX];
  if (!realpath(out, a)) return 0; /* not there yet: no input */
  for (size_t k = 0; k < n; k++)
    if (realpath(runs[k].dir, b) && !strcmp(a, b)) return 1;
  return 0;
}

/* A picture's stem: a file name, no directory. */
static int plain_name(const char *s) {
  return s[0] && s[0] != '.' && strspn(s, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-.") == strlen(s);
}

/* Read every run; 0, or 2 after the message. */
static int read_runs(char **dirs, size_t n, const char *x, const char *y, ov_run *runs) {
  char msg[4600];
  for (size_t k = 0; k < n; k++)
    if (ov_read(&runs[k], dirs[k], x, y, msg, sizeof msg)) {
      cli_error(CMD, "%s", msg);
      return 2;
    }
  for (size_t k = 1; k < n; k++)
    if (strcmp(runs[k].xname, runs[0].xname) || strcmp(runs[k].yname, runs[0].yname)) {
      cli_error(CMD, "%s plots %s against %s, %s %s against %s: name the columns with --x and --y",
                runs[k].dir, runs[k].yname, runs[k].xname, runs[0].dir, runs[0].yname,
                runs[0].xname);
      return 2;
    }
  return 0;
}

/* Write NAME.gp into OUT and draw it; the command's exit status. */
static int draw(const char *out, const char *name, const ov_run *runs, size_t n,
                const char (*labels)[256], const char *title) {
  cli_outdir od;
  char gp[300];
  int rc = cli_outdir_begin(&od, CMD, NULL, out);
  if (rc) return rc;
  snprintf(gp, sizeof gp, "%s.gp", name);
  out_file o;
  int bad = out_open(&o, &od, gp);
  if (!bad) {
    if (ov_write_gp(o.fp, runs, n, labels, title, name)) out_abort(&o), bad = 1;
    else bad = out_commit(&o) != 0;
  }
  const char *pics[] = {name, NULL};
  return cli_outdir_finish(&od, bad, pics);
}

/* The options after the directories, checked; 0 to go on, else the status. */
typedef struct ov_opts {
  const char *out, *name, *title, *labels, *x, *y;
  int quiet;
} ov_opts;
static int parse(int argc, char **argv, ov_opts *o) {
  const cli_opt opts[] = {
      {"--title", CLI_STRING, &o->title, "T", "the picture's title",
       "the parameters the runs share"},
      {"--labels", CLI_STRING, &o->labels, "L",
       "the legend: one title a run, comma-separated, in the order of the directories", ""},
      {"--x", CLI_STRING, &o->x, "NAME", "the column along x", "Omega"},
      {"--y", CLI_STRING, &o->y, "NAME", "the column along y",
       "eps, eps_max, amplitude_m or l2_norm"},
      {"--name", CLI_STRING, &o->name, "NAME", "the picture's file name, without extension", NULL},
      /* CLI_OPTS_OUT without --no-plot: the picture is all this command makes */
      {"--out", CLI_STRING, &o->out, "DIR", "output directory", NULL},
      {"--format", CLI_STRING, &cli_picture_format, "F",
       "the picture as png, pdf (vector, pdfcairo) or svg", NULL},
      CLI_OPT_QUIET(o->quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 1 : 2;
  if (cli_picture_format_check(CMD)) return 2;
  if (!plain_name(o->name)) {
    cli_error(CMD, "--name '%s': a file name (letters, digits, _ - .), not a path", o->name);
    return 2;
  }
  return 0;
}

/* The legend (the defaults, or --labels) and the title (--title, else
 * what the runs share); 0, or 2 after the message. */
static int legend(ov_opts *o, const ov_run *runs, size_t n, char (*labels)[256],
                  char *common, size_t clen) {
  ov_default_labels(runs, n, labels, common, clen);
  if (!o->title) o->title = common[0] ? common : "whirl plot overlay";
  if (o->labels && split_labels(o->labels, n, labels)) {
    cli_error(CMD, "--labels '%s': %zu titles for %zu runs", o->labels,
              count_labels(o->labels), n);
    return 2;
  }
  return 0;
}

/* What was drawn, on stderr; no picture claimed when none was drawn. */
static void summary(const ov_opts *o, const ov_run *runs, size_t n) {
  const int skipped = cli_pictures_skipped();
  fprintf(stderr, "whirl %s: %zu run%s, %s against %s%s%s/%s.%s\n", CMD, n,
          n == 1 ? "" : "s", runs[0].yname, runs[0].xname,
          skipped ? "; the script " : ", in ", o->out, o->name,
          skipped ? "gp" : cli_picture_format);
}

static int overlay(int argc, char **argv) {
  ov_opts o = {"overlay", "overlay", NULL, NULL, NULL, NULL, 0};
  int nd = 1; /* the directories: the words before the first option */
  while (nd < argc && argv[nd][0] != '-') nd++;
  char **dirs = argv + 1;
  const size_t n = (size_t)(nd - 1);
  char **av = malloc((size_t)(argc - nd + 2) * sizeof *av);
  if (!av) return 1;
  av[0] = argv[0];
  memcpy(av + 1, argv + nd, (size_t)(argc - nd) * sizeof *av);
  av[argc - nd + 1] = NULL;
  int rc = parse(argc - nd + 1, av, &o);
  free(av);
  if (rc) return rc == 1 ? 0 : rc;
  if (n == 0 || n > OV_MAX_RUNS) {
    cli_error(CMD, n ? "at most %d runs on one picture" : "no runs given: whirl plot overlay "
              "DIR1 DIR2 ... (output directories of sfd response, sfd nonsync, rotor response, run)",
              OV_MAX_RUNS);
    return 2;
  }
  ov_run *runs = calloc(n, sizeof *runs);
  char (*labels)[256] = calloc(n, sizeof *labels), common[600] = "";
  if (!runs || !labels) cli_error(CMD, "out of memory"), rc = 1;
  if (rc == 0) rc = read_runs(dirs, n, o.x, o.y, runs);
  if (rc == 0) rc = legend(&o, runs, n, labels, common, sizeof common);
  if (rc == 0 && is_input(o.out, runs, n))
    cli_error(CMD, "--out %s is one of the runs drawn: it would be replaced", o.out), rc = 2;
  if (rc == 0) rc = cli_outdir_check(CMD, NULL, o.out);
  if (rc == 0) rc = draw(o.out, o.name, runs, n, (const char(*)[256])labels, o.title);
  if (rc == 0 && !o.quiet) summary(&o, runs, n);
  for (size_t k = 0; runs && k < n; k++) ov_free(&runs[k]);
  free(runs);
  free(labels);
  return rc;
}

static const struct {
  const char *name;
  int (*run)(int argc, char **argv);
  const char *what;
} plot_commands[] = {
    {"overlay", overlay,
     "several runs' branches on one picture (Fig. 6a): the output directories of sfd "
     "response, sfd nonsync, rotor response or run"}};
#define NPLOT (sizeof plot_commands / sizeof plot_commands[0])

void cli_plot_help(FILE *f, const char *prefix, size_t col) {
  char label[64];
  for (size_t k = 0; k < NPLOT; ++k) {
    snprintf(label, sizeof label, "%s%s DIR...", prefix, plot_commands[k].name);
    cli_help_item(f, label, plot_commands[k].what, col);
  }
}

int cmd_plot(int argc, char **argv) {
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    FILE *f = argc < 2 ? stderr : stdout;
    fprintf(f, "usage: whirl plot <command> [options]\n\nPictures of earlier runs.\n"
               "commands:\n");
    cli_plot_help(f, "", 20);
    fprintf(f, "\n  whirl plot <command> --help   options of a command\n");
    return argc < 2 ? 2 : 0;
  }
  for (size_t k = 0; k < NPLOT; ++k)
    if (!strcmp(argv[1], plot_commands[k].name)) return plot_commands[k].run(argc - 1, argv + 1);
  fprintf(stderr, "whirl plot: unknown command '%s' (see whirl plot --help)\n", argv[1]);
  return 2;
}

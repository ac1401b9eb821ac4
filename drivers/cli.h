/* drivers/cli.h — shared helpers of the whirl command: option parsing with
 * clear messages and progress lines; output directories in outdir.h.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_CLI_H
#define WHIRL_CLI_H

#include <stddef.h>
#include <stdio.h>

/* Print "whirl <cmd>: <message>" to stderr, without the source locations
 * (" (cont.c:683)") that library messages carry for developers: the user
 * reads what went wrong, run.log keeps the full text. */
void cli_error(const char *cmd, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Remove every " (name.c:123)" / " (name.h:12)" from s, in place. */
void cli_strip_locations(char *s);

/* Parse a finite double option value; on failure prints a message naming the
 * option and returns -1. */
int cli_double(const char *cmd, const char *opt, const char *text, double *v);

/* Parse "--name=value" or "--name value": returns the value (advancing *i in
 * the second form) if argv[*i] is the option `name`, NULL otherwise; sets
 * *missing when the option is present without a value. */
const char *cli_value(int argc, char **argv, int *i, const char *name,
                      int *missing);

/* Output directories, their files and pictures: outdir.h. */
#include "outdir.h"

/* A table of options for cli_parse, which prints --help from it too: one
 * line an option, "  --name ARG   help (default)", in the table's order. */
typedef enum {
  CLI_DOUBLE, /* double *              --name X */
  CLI_SIZE,   /* size_t *, >= 0 integer */
  CLI_INT,    /* int *, any integer */
  CLI_STRING, /* const char **, non-empty */
  CLI_FLAG    /* int *, set to 1 when present */
} cli_kind;
typedef struct cli_opt {
  const char *name; /* "--periods" */
  cli_kind kind;
  void *dst;        /* the value; its value before parsing is the default */
  const char *arg;  /* the value's placeholder in --help ("N"); NULL: flags */
  const char *help; /* what it means, for --help (wrapped; '\n' breaks) */
  const char *dflt; /* the default as --help shows it where *dst does not
                       hold it ("N/2", one computed later); NULL: *dst as
                       parsing found it, "required" for a NaN; "": none */
} cli_opt;

/* Options most commands share: the output directory DIR, --no-plot (the
 * data only) and --quiet (no summary or progress line on stderr). */
#define CLI_OPT_QUIET(quiet)                                                  \
  {"--quiet", CLI_FLAG, &(quiet), NULL, "no summary or progress line on stderr", NULL}
#define CLI_OPTS_OUT(dir, noplot, quiet)                                      \
  {"--out", CLI_STRING, &(dir), "DIR", "output directory", NULL},             \
  {"--no-plot", CLI_FLAG, &(noplot), NULL, "write the data only, no pictures", \
   NULL},                                                                     \
  {"--format", CLI_STRING, &cli_picture_format, "F",                          \
   "the pictures as png, pdf (vector, pdfcairo) or svg", NULL},               \
  CLI_OPT_QUIET(quiet)

/* A command's --help around its options: HEAD (usage line, description,
 * the heading of the options), the options, then TAIL (outputs, exit
 * status; NULL for none) after an empty line. */
typedef struct cli_doc {
  const char *head;
  const char *tail;
} cli_doc;

/* Parse argv[1..argc-1] against opts; --help/-h prints doc and the options
 * (with their defaults, whatever came before --help) to stdout.  Returns 0
 * to go on, 1 when help was shown (exit 0), 2 on a bad option (message
 * printed; exit 2). */
int cli_parse(const char *cmd, int argc, char **argv, const cli_opt *opts,
              size_t nopts, const cli_doc *doc);

/* One item of a help text: "  LABEL", then TEXT from column COL, wrapped
 * to 79 columns ('\n' breaks a line); LABEL wider than COL - 4 puts TEXT
 * on the next line. */
void cli_help_item(FILE *f, const char *label, const char *text, size_t col);

/* Progress line on stderr (only on a terminal and when not quiet; never on
 * stdout): "WHAT: DONE/TOTAL (P%), ETA 1m05s", one line rewritten in place
 * (carriage return, the rest of the line cleared), at most five updates a
 * second, the first after half a second (short work draws none); the ETA
 * extrapolates the mean rate since cli_progress_init (or the last show of
 * DONE = 0 while no line was up: a new piece of work).
 * cli_progress_clear takes the line off (before a line on stdout, which
 * may be the same terminal; the next show draws it again);
 * cli_progress_end clears it for good. */
typedef struct cli_progress {
  int on, shown;
  double last, start;
  const char *what;
} cli_progress;
void cli_progress_init(cli_progress *p, const char *what, int quiet);
void cli_progress_show(cli_progress *p, size_t done, size_t total);
void cli_progress_clear(cli_progress *p);
void cli_progress_end(cli_progress *p);
/* "1h02m", "3m05s", "12s" or "?" (negative or not finite) into buf */
void cli_duration(double seconds, char *buf, size_t len);
double cli_now(void); /* monotonic seconds */

/* 1 when stderr is a terminal (progress lines are shown only then). */
int cli_is_tty(void);

int cmd_run(int argc, char **argv);
int cmd_auto(int argc, char **argv); /* cmd_auto.c: AUTO-07p files */
int cmd_sfd_response(int argc, char **argv);
int cmd_sfd_simulate(int argc, char **argv);
int cmd_sfd_nonsync(int argc, char **argv);
int cmd_sfd_sweep(int argc, char **argv);
int cmd_sfd_basins(int argc, char **argv);
int cmd_sfd_onset(int argc, char **argv);
int cmd_sfd_merge(int argc, char **argv);
int cmd_sfd_region(int argc, char **argv);
/* whirl rotor modes|campbell (cmd_rotor.c); the help items of its commands */
int cmd_rotor(int argc, char **argv);
int cmd_rotor_response(int argc, char **argv); /* cmd_rotor_response.c */
int cmd_rotor_loci(int argc, char **argv);     /* cmd_rotor_loci.c */
int cmd_rotor_export(int argc, char **argv);   /* cmd_rotor_export.c */
int cmd_rotor_simulate(int argc, char **argv); /* cmd_rotor_simulate.c */
int cmd_rotor_basins(int argc, char **argv);   /* cmd_rotor_basins.c */
void cli_rotor_help(FILE *f, const char *prefix, size_t col);
/* whirl plot overlay (cmd_plot.c); the help items of its commands */
int cmd_plot(int argc, char **argv);
void cli_plot_help(FILE *f, const char *prefix, size_t col);

#endif

/* drivers/cli.h — shared helpers of the whirl command: option parsing with
 * clear messages, output directories with atomic file writes, and gnuplot.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_CLI_H
#define WHIRL_CLI_H

#include <stddef.h>
#include <stdio.h>

/* Print "whirl <cmd>: <message>" to stderr. */
void cli_error(const char *cmd, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Parse a finite double option value; on failure prints a message naming the
 * option and returns -1. */
int cli_double(const char *cmd, const char *opt, const char *text, double *v);

/* Parse "--name=value" or "--name value": returns the value (advancing *i in
 * the second form) if argv[*i] is the option `name`, NULL otherwise; sets
 * *missing when the option is present without a value. */
const char *cli_value(int argc, char **argv, int *i, const char *name,
                      int *missing);

/* Create a directory and its parents (mkdir -p).  0 or -1 with errno. */
int cli_mkdirs(const char *path);

/* An output file written atomically: data go to DIR/.NAME.tmp, and
 * out_commit renames it to DIR/NAME; out_abort removes it. */
typedef struct out_file {
  FILE *fp;
  char tmp[4096], final[4096];
} out_file;
int out_open(out_file *o, const char *dir, const char *name);
int out_commit(out_file *o); /* closes; 0 on success */
void out_abort(out_file *o);

/* Run gnuplot on a script file in dir (cwd = dir); 0 on success, else a
 * message in msg. */
int cli_gnuplot(const char *dir, const char *script, char *msg, size_t len);

/* 1 when stderr is a terminal (progress lines are shown only then). */
int cli_is_tty(void);

int cmd_sfd_response(int argc, char **argv);

#endif

/* drivers/overlay.h — `whirl plot overlay`: several runs' branch tables on
 * one picture.  overlay_read.c reads a run's branches.tsv (the table
 * convention of doc/tables.md) into points; overlay_gp.c writes the gnuplot
 * script that draws them together.  Neither prints: a failure is a message
 * in the caller's buffer, and the command (cmd_plot.c) says it.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_OVERLAY_H
#define WHIRL_OVERLAY_H

#include <stddef.h>
#include <stdio.h>

/* One row of a branch table: the two plotted columns, its stability (1, 0,
 * -1 unknown), whether it is a fold (type LP), and the piece of curve it
 * belongs to (a new one at every branch and every blank line). */
typedef struct ov_point {
  double x, y;
  int stab, lp;
  size_t seg;
} ov_point;

/* A run: the directory as given, the columns plotted, the parameters of
 * its first comment line ("lambda=0.0503 delta=0.3 ..."), its points. */
typedef struct ov_run {
  char dir[4096];
  char xname[64], yname[64];
  char params[512];
  ov_point *pt; /* n, owned */
  size_t n;
} ov_run;

/* Read DIR/branches.tsv into R (zeroed first).  X and Y name the columns
 * plotted, or are NULL for the defaults: x Omega (else the fifth column,
 * whirl run's first parameter), y the first of eps, eps_max, amplitude_m,
 * l2_norm.  Returns 0, or -1 with a one-line message in MSG (no file, a
 * missing column, a row that is not the header's, no rows). */
int ov_read(ov_run *r, const char *dir, const char *x, const char *y, char *msg,
            size_t len);
/* The same with the columns X, Y by their 0-based positions. */
int ov_read_columns(ov_run *r, const char *dir, int x, int y, char *msg, size_t len);
void ov_free(ov_run *r);

/* The legend titles when the user gave none: the parameters whose values
 * differ between the runs ("delta=0.1"), when every run names the same
 * ones; else each run's directory.  OUT[k] for each of N runs; COMMON
 * (CLEN bytes) the parameters they share ("lambda=0.0503, zeta=0"), or "". */
void ov_default_labels(const ov_run *runs, size_t n, char (*out)[256], char *common,
                       size_t clen);

/* The script of the picture NAME (cli_gp_preamble's NAME.FMT): every run's
 * curves in its own colour, stable solid, unstable dashed, unknown thin,
 * folds marked, one legend entry a run (LABELS[k]) and one for each line
 * style, the legend outside the axes.  0, or -1 when writing failed. */
int ov_write_gp(FILE *f, const ov_run *runs, size_t n, const char (*labels)[256],
                const char *title, const char *name);

#endif

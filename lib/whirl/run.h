/* whirl/run.h — run a run file: everything `whirl run FILE` decides, as a
 * library (the command is parse, call, print).  The run builds the problem
 * IPS, ISW and METHOD ask for (equilibria, periodic orbits by collocation
 * or harmonic balance, fold and Hopf loci, branch switching at BP and PD,
 * basins of attraction), starts it from the model's start, a settled forced
 * response or a labelled solution (S, IRS), continues it with the user
 * points and stops (UZR, UZSTOP), and writes its branch table, labelled
 * solutions and log (doc/run-files.md).
 *
 *     whirl_run *r = whirl_run_alloc(models, &io);
 *     int rc = whirl_run_load(r, "ab-1.whirl", NULL, 0);
 *     if (rc == 0) rc = whirl_run_execute(r);
 *     for (size_t i = 0; i < whirl_run_nspecial(r); i++)
 *       puts(whirl_run_special_point(r, i)->row);
 *     whirl_run_free(r);
 *
 * The library prints nothing: messages go to io.message (one line each,
 * without a "whirl run:" prefix), the summary lines the command prints on
 * stdout to io.summary, progress to io.progress.  Files are opened and
 * closed through io.open and io.close (the command stages them, see
 * doc/output-directories.md); without io.open they are written straight
 * into the output directory, created if missing.
 *
 * Status codes: 0 done; 2 bad input (the run file, the model, a label to
 * restart from); 1 a failed computation or a file that could not be
 * written.  A branch that ended in failure (DSMIN without convergence)
 * keeps its points: whirl_run_execute returns 0 and whirl_run_failed 1.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_RUN_H
#define WHIRL_RUN_H

#include <stddef.h>
#include <stdio.h>

#include <whirl/model.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_run whirl_run;

typedef struct whirl_run_io {
  void (*message)(const char *line, void *ctx); /* errors, warnings */
  void (*summary)(const char *line, void *ctx); /* the run's summary */
  FILE *(*open)(const char *name, void *ctx);   /* a file of the output */
  int (*close)(FILE *f, const char *name, void *ctx); /* 0 when complete */
  void (*progress)(size_t done, size_t total, void *ctx);
  void *ctx;
} whirl_run_io;

/* A labelled point of the run: its row of branches.tsv (without the
 * newline), and the numbers in it. */
typedef struct whirl_run_special {
  int br, lab;
  size_t pt;
  char ty[3];
  const double *par; /* npar */
  double period;     /* 0 for equilibria */
  double l2norm;
  const double *state; /* n: the state, or its MAX over the orbit */
  const char *row;
} whirl_run_special;

/* What the run's picture shows (for the caller that draws it). */
typedef struct whirl_run_plot {
  int basins;                 /* 1: basins.tsv, else branches.tsv */
  int x, y;                   /* 1-based columns of branches.tsv */
  size_t stab_col;            /* the STAB column */
  const char *x_name, *y_name; /* axis names */
  int seen_stab[3];           /* rows with STAB -1, 0, 1 exist */
  int seen_special;           /* labelled points exist */
  const int *branches;        /* the BR column's values, each once, in order */
  const int *branch_stab;     /* for each: bit k set when it has rows of STAB k - 1 */
  size_t nbranches;
  const int *attractors;      /* basins: the attractors' labels */
  size_t nattractors;
} whirl_run_plot;

/* MODELS: the registered models `model = NAME` may name (NULL: plug-ins
 * only), borrowed.  IO is copied; NULL: no messages, files in the output
 * directory. */
WHIRL_API whirl_run *whirl_run_alloc(const whirl_model_registry *models,
                                     const whirl_run_io *io);
WHIRL_API void whirl_run_free(whirl_run *r); /* accepts NULL */

/* Read the run file, apply the overrides ("--KEY=value"), load and check
 * the model and resolve names.  0, 2 or 1 (a run file that cannot be read). */
WHIRL_API int whirl_run_load(whirl_run *r, const char *file,
                             const char *const *overrides, size_t noverrides);

/* The output directory (OUT, or the run file's name with .out), and where
 * OUT was given ("FILE:LINE", or "" for the default). */
WHIRL_API const char *whirl_run_output(const whirl_run *r);
WHIRL_API const char *whirl_run_output_where(const whirl_run *r);

/* Run it: restart solution, files, branches or basins. */
WHIRL_API int whirl_run_execute(whirl_run *r);

/* 1 when a branch ended in failure (its points are kept). */
WHIRL_API int whirl_run_failed(const whirl_run *r);

WHIRL_API size_t whirl_run_nspecial(const whirl_run *r);
WHIRL_API const whirl_run_special *whirl_run_special_point(const whirl_run *r, size_t i);
WHIRL_API const whirl_run_plot *whirl_run_plot_info(const whirl_run *r);
/* The model's name, the run file's name. */
WHIRL_API const char *whirl_run_model_name(const whirl_run *r);
WHIRL_API const char *whirl_run_file_name(const whirl_run *r);

/* ---- tables computed in blocks: parameter studies and basins ----
 * A parameter study (STUDY = {name: [values], ...}, doc/parameter-studies.md)
 * runs its analysis at every point of a grid; whirl_run_execute writes
 * study.tsv (a header, then a row a point) and run.log.  Basins (IPS =
 * basins) write basins.tsv, a row a start state.  A caller that
 * distributes the work itself (processes, a checkpoint) computes the rows
 * by blocks: each block depends on its index alone, so blocks computed
 * anywhere give the same bytes. */
/* The rows of the table (0: neither a study nor basins). */
WHIRL_API size_t whirl_run_rows(const whirl_run *r);
/* Rows computed together: 1 for a study, a grid line for basins (the table
 * has a blank line after each block of more than one row). */
WHIRL_API size_t whirl_run_rows_block(const whirl_run *r);
/* The file of the study's points (POINTS), "" for a grid or none: its
 * bytes are an input of the run as much as the run file's. */
WHIRL_API const char *whirl_run_points_file(const whirl_run *r);
/* "study.tsv" or "basins.tsv". */
WHIRL_API const char *whirl_run_rows_file(const whirl_run *r);
/* Before the first block (basins: the attractors from S): 0, 2 bad input,
 * 1 failure (said through io.message). */
WHIRL_API int whirl_run_rows_prepare(whirl_run *r);
/* Stages before the blocks (basins with BASIN_SEEDS: the rounds of the
 * atlas, whirl/basins.h), each of whirl_run_rows_stage_blocks blocks: a
 * block computed anywhere (bytes, malloc'd), and once a stage's blocks are
 * all there, entered in order by every whirl_run that computes blocks
 * after it.  0 stages: none (a study, basins without an atlas). */
WHIRL_API size_t whirl_run_rows_stages(const whirl_run *r);
WHIRL_API size_t whirl_run_rows_stage_blocks(const whirl_run *r, size_t s);
WHIRL_API int whirl_run_rows_stage_compute(whirl_run *r, size_t s, size_t b, char **out,
                                           size_t *len);
WHIRL_API int whirl_run_rows_stage_enter(whirl_run *r, size_t s, char *const *parts,
                                         const size_t *lens, size_t n);
/* The table's header line (no newline) into buf[len]. */
WHIRL_API int whirl_run_rows_header(const whirl_run *r, char *buf, size_t len);
/* Block `block`'s rows, joined by newlines (no final one), in *out
 * (malloc'd, the caller frees): WHIRL_OK also when a study point's run
 * failed (its status column says so). */
WHIRL_API int whirl_run_rows_compute(whirl_run *r, size_t block, char **out);
/* After the last block, all of them in order: the summary (basins: the
 * attractors' shares) through io.summary, and what the picture shows. */
WHIRL_API int whirl_run_rows_finish(whirl_run *r, const char *const *blocks,
                                    size_t nblocks);

/* The first error message (a run file's FILE:LINE: ...), "" if none. */
WHIRL_API const char *whirl_run_errmsg(const whirl_run *r);

#ifdef __cplusplus
}
#endif
#endif

/* drivers/run_study.h — `whirl run` of a parameter study (run_study.c):
 * and of basins: checkpoint and resume, chunks for job arrays, MPI.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVER_RUN_STUDY_H
#define WHIRL_DRIVER_RUN_STUDY_H

#include <stddef.h>

#include <whirl/run.h>

typedef struct study_opts {
  const char *file;          /* the run file */
  const char *const *ov;     /* its overrides */
  size_t nov;
  size_t chunk, chunks;      /* --chunk=I/N (chunks 0: the whole study) */
  int quiet, no_plot;         /* --quiet, --no-plot */
} study_opts;

/* The table of r (whirl_run_rows > 0: a study or basins), this process being rank of
 * nranks (1: alone).  The exit status (0, 1, 2), said on failure; ranks
 * other than 0 return 0. */
int run_study_command(whirl_run *r, const study_opts *o, int rank, int nranks);

/* --merge-chunks=N: the chunks' tables joined into the output directory. */
int run_study_merge(whirl_run *r, const study_opts *o);

#endif

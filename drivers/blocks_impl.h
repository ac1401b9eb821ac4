/* drivers/blocks_impl.h — what blocks.c and blocks_mpi.c share: the state
 * of a table computed in blocks on this process.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVER_BLOCKS_IMPL_H
#define WHIRL_DRIVER_BLOCKS_IMPL_H

#include <stdio.h>

#include "blocks.h"
#include "cli.h"

#define RS '\x1e' /* a table block's newline in the checkpoint */

typedef struct blocks {
  const blocks_def *d;
  size_t nt, lo, hi;        /* table blocks; this run's [lo, hi) */
  size_t off[BLOCKS_MAX_STAGES + 2]; /* entry index of stage s's block 0 */
  char **data;              /* entries: every stage's blocks, then lo .. hi */
  size_t *len;
  unsigned char *have;      /* 1: computed (its data freed once absorbed) */
  char out[4200], ckpt[4300];
  uint64_t id;
  FILE *ck;
  size_t resumed, computed, done, total;
  double synced;
  cli_progress prog;
  FILE *times;              /* WHIRL_BLOCK_TIMES: a line a block computed */
} blocks;

/* When a block was computed, and where (for WHIRL_BLOCK_TIMES). */
typedef struct blocks_when {
  double t0, t1; /* CLOCK_MONOTONIC seconds */
  int rank;
  double cpu;    /* the computing thread's CPU seconds (a run's: its share) */
} blocks_when;

double blocks_seconds(void);
double blocks_cpu_seconds(void); /* this thread's CPU time */

/* The entry of block b of stage s (the table's: b in [lo, hi)), and a
 * stage's blocks on this run [first, end). */
size_t blocks_entry(const blocks *K, size_t s, size_t b);
size_t blocks_stage_first(const blocks *K, size_t s);
size_t blocks_stage_end(const blocks *K, size_t s);
/* Keep a finished block (data taken over): memory, checkpoint, progress. */
int blocks_keep(blocks *K, size_t s, size_t b, char *data, size_t n, const blocks_when *w);
/* Compute block b of stage s here and keep it: 0 or 1. */
int blocks_compute_one(blocks *K, size_t s, size_t b);
/* Stage s's blocks to the command (every process), then freed: 0 or 1. */
int blocks_absorb(blocks *K, size_t s);

/* MPI (blocks_mpi.c): rank 0 and the others; 0 or 1. */
int blocks_master(blocks *K, int nranks);
int blocks_worker(blocks *K);

#endif

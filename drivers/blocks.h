/* drivers/blocks.h — a table computed in blocks, resumable, in chunks and
 * on MPI (blocks.c): the machinery of `whirl run` studies and basins and of
 * `whirl sfd basins`, each of them a user of this one interface.
 *
 * A command describes its table (rows, rows a block, header) and, before
 * it, optional stages whose blocks every process needs (the rounds of a
 * basins atlas): each stage's blocks are computed anywhere, then given,
 * in order, to every process (absorb) before the next stage starts.  A
 * block is bytes: a table block is its rows joined by '\n' (no final one),
 * optionally followed by '\0' and bytes for the command alone (its
 * statistics).  Every block depends on its index and the stages before
 * it alone, so the table is the same bytes however the blocks are spread.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVER_BLOCKS_H
#define WHIRL_DRIVER_BLOCKS_H

#include <stddef.h>
#include <stdint.h>

#include "outdir.h"

#define BLOCKS_MAX_STAGES 8
#define BLOCKS_RUN 16 /* blocks a run of compute_run at most */

/* What the table's last step is given (rank 0). */
typedef struct blocks_result {
  char *const *blk;       /* the table's blocks lo .. hi − 1 (blk[b − lo]) */
  const size_t *len;      /* their bytes (the rows and any trailer) */
  size_t lo, hi, nblocks; /* this run's blocks of all nblocks */
  int whole;              /* 1: all blocks, not a chunk */
  size_t chunks;          /* merged from this many chunks (0: computed) */
  size_t computed, resumed; /* table blocks computed now, from the checkpoint */
  int nranks;
  const char *out;        /* the output directory written */
} blocks_result;

typedef struct blocks_def {
  const char *cmd;        /* "run", "sfd basins": the messages' prefix */
  const char *progress;   /* the progress line's name */
  const char *file;       /* the table's file in the output directory */
  const char *out;        /* the output directory (its chunks: OUT.chunk-I-of-N) */
  const char *where;      /* where OUT was given (FILE:LINE), or NULL */
  size_t rows, block;     /* rows, rows a block (the last block may have fewer) */
  int blank;              /* a blank line after each block */
  const char *header;     /* the table's header lines, each with its '\n' */
  size_t nstages;         /* stages before the table */
  size_t stage_blocks[BLOCKS_MAX_STAGES];
  uint64_t id;            /* the run's identity (blocks_hash of its inputs) */
  void *ctx;
  /* Block b of stage s (s == nstages: the table), malloc'd: 0, or 1
   * (said). */
  int (*compute)(void *ctx, size_t s, size_t b, char **data, size_t *len);
  /* Optional, for one process: blocks b0 .. b0 + nb − 1 of stage s in one
   * call (nb <= BLOCKS_RUN; threads then share one pass over them instead
   * of waiting for each other at the end of every block), data[k] and
   * len[k] block b0 + k's.  A stage's blocks may take their bytes together
   * (all in data[0], the others empty): a stage is only ever taken in
   * whole, in order.  0, or 1 (said). */
  int (*compute_run)(void *ctx, size_t s, size_t b0, size_t nb, char **data, size_t *len);
  /* Every process, stage s < nstages once all its blocks are in: 0 or 1. */
  int (*absorb)(void *ctx, size_t s, char *const *data, const size_t *len, size_t nb);
  /* Rank 0, the table written into od: the other files, then
   * cli_outdir_finish / commit / abort (od is the callback's); the exit
   * status. */
  int (*finish)(void *ctx, cli_outdir *od, const blocks_result *res);
} blocks_def;

/* FNV-1a, 64 bits, over bytes; start with BLOCKS_HASH0. */
#define BLOCKS_HASH0 0xcbf29ce484222325ull
uint64_t blocks_hash(uint64_t h, const void *p, size_t n);

/* Compute and write the table: all of it (chunks 0) or the chunk-th of
 * `chunks` contiguous parts of its blocks (every stage in full) into
 * OUT.chunk-I-of-N; resumed from OUT[.chunk-I-of-N].checkpoint, which every
 * finished block is appended to.  This process is `rank` of `nranks`
 * (MPI when nranks > 1).  The exit status on rank 0 (0, 1, 2; said),
 * 0 on the others. */
int blocks_run(const blocks_def *d, size_t chunk, size_t chunks, int quiet, int rank,
               int nranks);

/* The tables of OUT.chunk-I-of-N for I = 1 .. chunks joined into OUT: the
 * exit status. */
int blocks_merge(const blocks_def *d, size_t chunks);

/* The rank and number of processes: MPI's (initialised here) when built
 * with it, else 0 of 1; blocks_processes_end after the work. */
void blocks_processes(int *argc, char ***argv, int *rank, int *nranks);
void blocks_processes_end(void);

#endif

/* drivers/run_study.c — `whirl run` of a table computed in blocks: a
 * parameter study (STUDY, doc/parameter-studies.md, a block a point) or
 * basins of attraction (IPS = basins, a block a grid line), the blocks
 * computed by the library (whirl_run_rows_compute) and distributed,
 * checkpointed and chunked by blocks.c, of which this is one user.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "blocks.h"
#include "cli.h"
#include "run_cmd.h"
#include "run_study.h"

typedef struct study {
  whirl_run *r;
  const study_opts *o;
  char header[4100];
  blocks_def d;
} study;

/* The bytes of file `path` into the hash: 0, or -1. */
static int hash_file(const char *path, uint64_t *h) {
  FILE *f = fopen(path, "rb");
  if (!f) return -1;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) *h = blocks_hash(*h, buf, n);
  fclose(f);
  return 0;
}

/* The run's identity: the run file's bytes, the overrides and the bytes
 * of the study's points file. */
static int identity(const whirl_run *r, const study_opts *o, uint64_t *id) {
  uint64_t h = BLOCKS_HASH0;
  if (hash_file(o->file, &h)) return -1;
  for (size_t i = 0; i < o->nov; i++) h = blocks_hash(h, o->ov[i], strlen(o->ov[i]) + 1);
  const char *pts = whirl_run_points_file(r);
  if (pts[0] && hash_file(pts, &h)) return -1;
  *id = h;
  return 0;
}

static int compute(void *ctx, size_t s, size_t b, char **data, size_t *len) {
  study *S = ctx;
  if (s < S->d.nstages) return whirl_run_rows_stage_compute(S->r, s, b, data, len) ? 1 : 0;
  if (whirl_run_rows_compute(S->r, b, data)) return 1;
  *len = strlen(*data);
  return 0;
}

static int absorb(void *ctx, size_t s, char *const *data, const size_t *len, size_t nb) {
  study *S = ctx;
  return whirl_run_rows_stage_enter(S->r, s, data, len, nb) ? 1 : 0;
}

/* run.log and, for basins of the whole grid, the shares and the picture;
 * then the output swapped in and the line that says so. */
static int finish(void *ctx, cli_outdir *od, const blocks_result *res) {
  study *S = ctx;
  const size_t B = S->d.block;
  const char *name = S->d.file, *pic = NULL;
  FILE *g = cli_outdir_fopen(od, "run.log");
  int bad = !g;
  if (g) {
    fprintf(g, "whirl %s run %s: blocks %zu to %zu of %zu (%zu rows each) of %s\n",
            whirl_version(), S->o->file, res->lo, res->hi - 1, res->nblocks, B, name);
    fprintf(g, "%zu computed now, %zu from the checkpoint; %d process%s\n", res->computed,
            res->resumed, res->nranks, res->nranks == 1 ? "" : "es");
    bad = cli_outdir_fclose(od, g, "run.log") != 0;
  }
  if (!bad && B > 1 && res->whole) { /* basins, whole */
    whirl_run_rows_finish(S->r, (const char *const *)res->blk, res->nblocks);
    if (!S->o->no_plot && run_write_plot(od, S->r, &pic)) bad = 1;
  }
  if (bad) {
    cli_outdir_abort(od);
    return 1;
  }
  const int pic_failed = pic && cli_outdir_plot(od, pic) != 0;
  if (cli_outdir_commit(od)) return 1;
  const char *what = B > 1 ? "grid lines" : "points";
  const int shown = B > 1 && res->whole && pic && !cli_pictures_skipped();
  if (S->o->quiet) return pic_failed;
  if (res->chunks)
    printf("%zu %s from %zu chunks; wrote %s/ (%s, run.log)\n", res->nblocks, what, res->chunks,
           res->out, name);
  else
    printf("%zu %s (%zu computed, %zu from the checkpoint); wrote %s/ (%s, run.log%s%s)\n",
           res->hi - res->lo, what, res->computed, res->resumed, res->out, name,
           shown ? ", basins." : "", shown ? cli_picture_format : "");
  return pic_failed;
}

static int setup(study *S, whirl_run *r, const study_opts *o) {
  memset(S, 0, sizeof *S);
  S->r = r;
  S->o = o;
  int rc = whirl_run_rows_prepare(r);
  if (rc) return rc;
  if (whirl_run_rows_header(r, S->header, sizeof S->header - 1)) return 1;
  strcat(S->header, "\n");
  blocks_def *d = &S->d;
  d->cmd = "run";
  d->file = whirl_run_rows_file(r);
  d->out = whirl_run_output(r);
  d->where = whirl_run_output_where(r);
  d->rows = whirl_run_rows(r);
  d->block = whirl_run_rows_block(r);
  d->progress = d->block > 1 ? "basins" : "study";
  d->blank = d->block > 1;
  d->header = S->header;
  d->ctx = S;
  d->compute = compute;
  d->absorb = absorb;
  d->finish = finish;
  d->nstages = whirl_run_rows_stages(r);
  if (d->nstages > BLOCKS_MAX_STAGES) return 1;
  for (size_t s = 0; s < d->nstages; s++) d->stage_blocks[s] = whirl_run_rows_stage_blocks(r, s);
  return identity(r, o, &d->id) ? 1 : 0;
}

int run_study_command(whirl_run *r, const study_opts *o, int rank, int nranks) {
  study S;
  int rc = setup(&S, r, o);
  if (rc) return rank == 0 ? rc : 0;
  return blocks_run(&S.d, o->chunk, o->chunks, o->quiet, rank, nranks);
}

int run_study_merge(whirl_run *r, const study_opts *o) {
  study S;
  int rc = setup(&S, r, o);
  return rc ? rc : blocks_merge(&S.d, o->chunks);
}

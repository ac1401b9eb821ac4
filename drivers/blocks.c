/* drivers/blocks.c — a table computed in blocks (blocks.h), and around
 * the blocks
 *
 *  - a checkpoint, OUT.checkpoint: every finished block (of the stages and
 *    of the table) is appended and flushed at once (a killed process loses
 *    nothing), synced to the disk at most once a second; a run killed and
 *    started again with the same command (the same identity) takes the
 *    blocks from it and computes only the others.  The output directory is
 *    written at the end, as one transaction, and the checkpoint removed: a
 *    partial state is never an output;
 *  - chunks for job arrays without MPI: the I-th of N contiguous parts of
 *    the table's blocks into OUT.chunk-I-of-N/, and the merge of the N
 *    tables into OUT, the bytes one run writes;
 *  - MPI (built with --with-mpi, run under mpirun): stage by stage, rank 0
 *    hands the blocks out as ranks finish them (dynamic load balancing: a
 *    block's cost varies a hundredfold), computes blocks itself between
 *    their messages, broadcasts a finished stage to every rank, and writes
 *    the table's blocks in order, so the file is the same for any number
 *    of ranks and threads.
 *
 * The checkpoint: a line "# whirl checkpoint ID (what)", then an entry a
 * block, "S\tB\tLEN\t", LEN bytes and '\n' (a table block's newlines
 * written as RS, so that it is one line); an entry cut short by a kill is
 * dropped when it is read.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* fsync, fileno, clock_gettime */
#include <errno.h>
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "config.h"
#ifdef WHIRL_HAVE_MPI
#include <mpi.h>
#endif

#include "cli.h"

#include "blocks_impl.h"

uint64_t blocks_hash(uint64_t h, const void *p, size_t n) {
  const unsigned char *c = p;
  for (size_t i = 0; i < n; i++) h = (h ^ c[i]) * 0x100000001b3ull;
  return h;
}

double blocks_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double blocks_cpu_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Entry index of block b of stage s (the table's: b in [lo, hi)). */
size_t blocks_entry(const blocks *K, size_t s, size_t b) {
  return K->off[s] + (s == K->d->nstages ? b - K->lo : b);
}
size_t blocks_stage_first(const blocks *K, size_t s) { return s == K->d->nstages ? K->lo : 0; }
size_t blocks_stage_end(const blocks *K, size_t s) {
  return s == K->d->nstages ? K->hi : K->d->stage_blocks[s];
}

/* ---- the checkpoint ---------------------------------------------------- */

/* One entry "S\tB\tLEN\t" of f: 1 read, 0 at the end (or cut short). */
static int entry_head(FILE *f, size_t v[3]) {
  char buf[96];
  size_t k = 0, tabs = 0;
  int c;
  while (tabs < 3 && k + 1 < sizeof buf && (c = getc(f)) != EOF) {
    buf[k++] = (char)c;
    if (c == '\t') tabs++;
    else if (c < '0' || c > '9') return 0;
  }
  buf[k] = '\0';
  return tabs == 3 && sscanf(buf, "%zu\t%zu\t%zu\t", &v[0], &v[1], &v[2]) == 3;
}

/* The entries of an earlier attempt's checkpoint (after its first line). */
static void take_entries(blocks *K, FILE *f) {
  size_t v[3];
  while (entry_head(f, v)) {
    const size_t s = v[0], b = v[1], n = v[2];
    if (s > K->d->nstages || b < blocks_stage_first(K, s) || b >= blocks_stage_end(K, s)) return;
    char *buf = malloc(n + 1);
    if (!buf) return;
    if (fread(buf, 1, n, f) != n || getc(f) != '\n') { /* cut short by the kill */
      free(buf);
      return;
    }
    buf[n] = '\0';
    const size_t e = blocks_entry(K, s, b);
    for (size_t i = 0; s == K->d->nstages && i < n; i++)
      if (buf[i] == RS) buf[i] = '\n';
    if (K->have[e]) {
      free(buf);
      continue;
    }
    K->data[e] = buf, K->len[e] = n, K->have[e] = 1;
    if (s == K->d->nstages) K->resumed++;
    K->done++;
  }
}

/* Read the checkpoint of an earlier attempt: 0 (none, or its blocks
 * taken), 2 (it belongs to another run: said). */
static int resume(blocks *K) {
  FILE *f = fopen(K->ckpt, "rb");
  if (!f) return 0;
  char line[512];
  uint64_t id = 0;
  int ok = fgets(line, sizeof line, f) && sscanf(line, "# whirl checkpoint %" SCNx64, &id) == 1;
  if (!ok || id != K->id) {
    fclose(f);
    cli_error(K->d->cmd, "%s is the checkpoint of another run (other inputs, options or "
              "chunk): remove it, or give another output directory", K->ckpt);
    return 2;
  }
  take_entries(K, f);
  fclose(f);
  return 0;
}

static int put_entry(const blocks *K, FILE *f, size_t s, size_t b, const char *data, size_t n) {
  if (fprintf(f, "%zu\t%zu\t%zu\t", s, b, n) < 0) return -1;
  if (s < K->d->nstages) {
    if (fwrite(data, 1, n, f) != n) return -1;
  } else {
    for (size_t i = 0; i < n; i++)
      if (fputc(data[i] == '\n' ? RS : data[i], f) == EOF) return -1;
  }
  return fputc('\n', f) == EOF ? -1 : 0;
}

/* Start the checkpoint again with the blocks kept (an entry cut short by a
 * kill is dropped), through a new file of its own renamed over it. */
static int checkpoint_open(blocks *K) {
  char tmp[4400];
  snprintf(tmp, sizeof tmp, "%s.tmp.%ld", K->ckpt, (long)getpid());
  FILE *f = fopen(tmp, "wbx"); /* never over a file that is there */
  if (!f) {
    cli_error(K->d->cmd, "cannot write %s: %s", tmp, strerror(errno));
    return 1;
  }
  int bad = fprintf(f, "# whirl checkpoint %016" PRIx64 " (%s %s)\n", K->id, K->d->cmd,
                    K->out) < 0;
  for (size_t s = 0; s <= K->d->nstages; s++)
    for (size_t b = blocks_stage_first(K, s); !bad && b < blocks_stage_end(K, s); b++) {
      const size_t e = blocks_entry(K, s, b);
      if (K->have[e]) bad = put_entry(K, f, s, b, K->data[e], K->len[e]);
    }
  if (bad || fflush(f) || fsync(fileno(f)) || fclose(f) || rename(tmp, K->ckpt)) {
    cli_error(K->d->cmd, "cannot write %s: %s", K->ckpt, strerror(errno));
    remove(tmp);
    return 1;
  }
  K->synced = blocks_seconds();
  K->ck = fopen(K->ckpt, "ab");
  return K->ck ? 0 : 1;
}

/* Keep block b of stage s (data taken over): in memory and in the
 * checkpoint, flushed at once and synced at most once a second (one fsync
 * a block would bound rank 0 at a few hundred blocks a second). */
int blocks_keep(blocks *K, size_t s, size_t b, char *data, size_t n, const blocks_when *w) {
  const size_t e = blocks_entry(K, s, b);
  if (K->times)
    fprintf(K->times, "%zu\t%zu\t%d\t%.6f\t%.6f\t%zu\t%.6f\n", s, b, w->rank, w->t0, w->t1, n,
            w->cpu);
  K->data[e] = data, K->len[e] = n, K->have[e] = 1;
  if (s == K->d->nstages) K->computed++;
  cli_progress_show(&K->prog, ++K->done, K->total);
  int bad = put_entry(K, K->ck, s, b, data, n) || fflush(K->ck);
  if (!bad && blocks_seconds() - K->synced >= 1.0) {
    bad = fsync(fileno(K->ck)) != 0;
    K->synced = blocks_seconds();
  }
  if (bad) cli_error(K->d->cmd, "writing %s failed: %s", K->ckpt, strerror(errno));
  return bad;
}

/* Every process, after stage s: its blocks to the command, then freed. */
int blocks_absorb(blocks *K, size_t s) {
  const size_t e = K->off[s], nb = K->d->stage_blocks[s];
  int rc = K->d->absorb(K->d->ctx, s, K->data + e, K->len + e, nb);
  for (size_t b = 0; b < nb; b++) {
    free(K->data[e + b]);
    K->data[e + b] = NULL;
  }
  return rc;
}

int blocks_compute_one(blocks *K, size_t s, size_t b) {
  char *data = NULL;
  size_t n = 0;
  const double c0 = blocks_cpu_seconds();
  blocks_when w = {blocks_seconds(), 0, 0, 0};
  if (K->d->compute(K->d->ctx, s, b, &data, &n)) return 1;
  w.t1 = blocks_seconds();
  w.cpu = blocks_cpu_seconds() - c0;
  return blocks_keep(K, s, b, data, n, &w);
}

/* The missing blocks b .. b + nb − 1 of stage s in one call, kept. */
static int compute_run(blocks *K, size_t s, size_t b, size_t nb) {
  char *data[BLOCKS_RUN] = {NULL};
  size_t len[BLOCKS_RUN] = {0};
  const double c0 = blocks_cpu_seconds();
  blocks_when w = {blocks_seconds(), 0, 0, 0};
  if (K->d->compute_run(K->d->ctx, s, b, nb, data, len)) return 1;
  w.t1 = blocks_seconds();
  w.cpu = (blocks_cpu_seconds() - c0) / (double)nb;
  int bad = 0;
  for (size_t k = 0; k < nb; k++) {
    if (!bad) bad = blocks_keep(K, s, b + k, data[k], len[k], &w);
    else free(data[k]);
  }
  return bad;
}

/* One process: the stages' blocks in order, each stage taken in, then the
 * table's; runs of up to BLOCKS_RUN missing blocks at once when the
 * command computes runs. */
static int compute_serial(blocks *K) {
  for (size_t s = 0; s <= K->d->nstages; s++) {
    const size_t end = blocks_stage_end(K, s);
    for (size_t b = blocks_stage_first(K, s); b < end;) {
      size_t nb = 0;
      while (b + nb < end && nb < BLOCKS_RUN && !K->have[blocks_entry(K, s, b + nb)]) nb++;
      if (nb == 0) {
        b++;
        continue;
      }
      if (K->d->compute_run && nb > 1 ? compute_run(K, s, b, nb) : blocks_compute_one(K, s, b))
        return 1;
      b += K->d->compute_run ? nb : 1;
    }
    if (s < K->d->nstages && blocks_absorb(K, s)) return 1;
  }
  return 0;
}

/* ---- the output -------------------------------------------------------- */

/* The table (the header, the blocks' rows in order, a blank line after
 * each block when asked), then the command's files. */
static int write_output(blocks *K, size_t chunks, int nranks) {
  cli_outdir od;
  int rc = cli_outdir_begin(&od, K->d->cmd, K->d->where, K->out);
  if (rc) return rc;
  const size_t nb = K->hi - K->lo, e0 = K->off[K->d->nstages];
  FILE *f = cli_outdir_fopen(&od, K->d->file);
  if (f) {
    fputs(K->d->header, f);
    for (size_t b = 0; b < nb; b++)
      fprintf(f, "%s\n%s", K->data[e0 + b], K->d->blank ? "\n" : "");
  }
  if (!f || cli_outdir_fclose(&od, f, K->d->file)) {
    cli_outdir_abort(&od);
    return 1;
  }
  const blocks_result res = {K->data + e0, K->len + e0, K->lo, K->hi, K->nt,
                             K->lo == 0 && K->hi == K->nt, chunks, K->computed, K->resumed,
                             nranks, K->out};
  return K->d->finish(K->d->ctx, &od, &res);
}

static int setup(blocks *K, const blocks_def *d, size_t chunk, size_t chunks) {
  memset(K, 0, sizeof *K);
  K->d = d;
  K->nt = d->block ? (d->rows + d->block - 1) / d->block : 0;
  K->hi = K->nt;
  if (chunks) {
    if (chunk < 1 || chunk > chunks || chunks > K->nt) {
      cli_error(d->cmd, "chunk %zu/%zu: need 1 <= I <= N <= %zu (the %s)", chunk, chunks,
                K->nt, d->block > 1 ? "blocks of rows" : "points");
      return 2;
    }
    K->lo = (chunk - 1) * K->nt / chunks;
    K->hi = chunk * K->nt / chunks;
    snprintf(K->out, sizeof K->out, "%s.chunk-%zu-of-%zu", d->out, chunk, chunks);
  } else {
    snprintf(K->out, sizeof K->out, "%s", d->out);
  }
  snprintf(K->ckpt, sizeof K->ckpt, "%s.checkpoint", K->out);
  size_t n = 0;
  for (size_t s = 0; s < d->nstages; s++) K->off[s] = n, n += d->stage_blocks[s];
  K->off[d->nstages] = n;
  n += K->hi - K->lo;
  K->total = n;
  K->data = calloc(n + 1, sizeof *K->data);
  K->len = calloc(n + 1, sizeof *K->len);
  K->have = calloc(n + 1, 1);
  if (!K->data || !K->len || !K->have) return 1;
  const size_t v[5] = {d->rows, d->block, d->nstages, K->lo, K->hi};
  K->id = blocks_hash(blocks_hash(d->id, v, sizeof v), d->stage_blocks, sizeof d->stage_blocks);
  return 0;
}

static void release(blocks *K) {
  if (K->ck) fclose(K->ck);
  if (K->times) fclose(K->times);
  for (size_t i = 0; K->data && i < K->total; i++) free(K->data[i]);
  free(K->data);
  free(K->len);
  free(K->have);
}

int blocks_run(const blocks_def *d, size_t chunk, size_t chunks, int quiet, int rank,
               int nranks) {
  blocks K;
  int rc = setup(&K, d, chunk, chunks);
  if (!rc && rank == 0) rc = cli_outdir_check(d->cmd, d->where, K.out);
  if (!rc && rank == 0) rc = resume(&K);
  if (!rc && rank == 0) rc = checkpoint_open(&K);
  const char *tf = getenv("WHIRL_BLOCK_TIMES"); /* a benchmark's record */
  if (!rc && rank == 0 && tf && *tf && (K.times = fopen(tf, "w")))
    fprintf(K.times, "stage\tblock\trank\tstart\tend\tbytes\tcpu\n");
  cli_progress_init(&K.prog, d->progress, quiet || rank != 0);
#ifdef WHIRL_HAVE_MPI
  if (nranks > 1) {
    int go = rc, all;
    MPI_Allreduce(&go, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (all) rc = rc ? rc : 1;
    else rc = rank == 0 ? blocks_master(&K, nranks) : blocks_worker(&K);
  } else
#endif
  if (!rc) rc = compute_serial(&K);
  (void)nranks;
  cli_progress_end(&K.prog);
  if (K.ck) {
    fsync(fileno(K.ck));
    fclose(K.ck);
    K.ck = NULL;
  }
  if (!rc && rank == 0) rc = write_output(&K, 0, nranks);
  if (!rc && rank == 0) remove(K.ckpt);
  release(&K);
  return rank == 0 ? rc : 0;
}

/* ---- chunks joined ------------------------------------------------------ */

/* A line of f into *line; 1 read (with its '\n'), 0 at the end. */
static int line_of(FILE *f, char **line, size_t *cap, ssize_t *m) {
  *m = getline(line, cap, f);
  return *m > 0;
}

/* The rows of one chunk's table into their blocks: 0, or 2 (said). */
static int read_chunk(blocks *K, size_t c, size_t chunks) {
  const blocks_def *d = K->d;
  char path[4400];
  const size_t lo = (c - 1) * K->nt / chunks, hi = c * K->nt / chunks;
  snprintf(path, sizeof path, "%s.chunk-%zu-of-%zu/%s", d->out, c, chunks, d->file);
  FILE *f = fopen(path, "r");
  size_t cap = 0, b = lo, k = 0, len = 0, hl = strlen(d->header), got = 0;
  char *line = NULL, *acc = NULL;
  ssize_t m;
  int rc = f ? 0 : 2;
  while (!rc && got < hl && line_of(f, &line, &cap, &m)) { /* the header, exactly */
    if ((size_t)m > hl - got || memcmp(line, d->header + got, (size_t)m)) rc = 2;
    got += (size_t)m;
  }
  if (got != hl) rc = 2;
  while (!rc && line_of(f, &line, &cap, &m)) {
    if (d->blank && !strcmp(line, "\n")) continue; /* the blank line after a block */
    if (b >= hi || line[m - 1] != '\n') { rc = 2; break; }
    char *na = realloc(acc, len + (size_t)m + 1);
    if (!na) { rc = 1; break; }
    acc = na;
    memcpy(acc + len, line, (size_t)m + 1);
    len += (size_t)m;
    const size_t want = b + 1 < K->nt ? d->block : d->rows - b * d->block;
    if (++k == want) {
      acc[--len] = '\0';
      K->data[blocks_entry(K, d->nstages, b)] = acc, K->len[blocks_entry(K, d->nstages, b)] = len;
      b++;
      acc = NULL, len = 0, k = 0;
    }
  }
  if (!rc && (b != hi || k != 0)) rc = 2;
  if (rc) cli_error(d->cmd, "%s: %s", path, f ? "not the table of this chunk" : strerror(errno));
  free(acc);
  free(line);
  if (f) fclose(f);
  return rc;
}

int blocks_merge(const blocks_def *d, size_t chunks) {
  blocks K;
  int rc = setup(&K, d, 0, 0);
  if (!rc && !(chunks >= 1 && chunks <= K.nt)) {
    cli_error(d->cmd, "merging %zu chunks: need 1 <= N <= %zu", chunks, K.nt);
    rc = 2;
  }
  for (size_t c = 1; !rc && c <= chunks; c++) rc = read_chunk(&K, c, chunks);
  K.resumed = K.nt;
  if (!rc) rc = cli_outdir_check(d->cmd, d->where, K.out);
  if (!rc) rc = write_output(&K, chunks, 1);
  release(&K);
  return rc;
}

/* ---- processes ---------------------------------------------------------- */

/* MPI is finalized once, at exit: a process may run several commands (whirl
 * auto runs its run files one after another), and MPI cannot be initialized
 * again once finalized. */
#ifdef WHIRL_HAVE_MPI
static void finalize_at_exit(void) {
  int fin = 0;
  MPI_Finalized(&fin);
  if (!fin) MPI_Finalize();
}
#endif

#ifdef WHIRL_HAVE_MPI
/* Started by an MPI launcher (mpirun/mpiexec of Open MPI or MPICH, srun):
 * the variables their process managers give each rank.  Without one the
 * process is alone and MPI is not initialized at all: a singleton MPI_Init
 * costs 0.2-0.45 s (Open MPI probing its transports), more than a small
 * run's whole computation. */
static int launched_by_mpi(void) {
  static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK",
                                     "PMI_SIZE", "MPI_LOCALNRANKS"};
  for (size_t i = 0; i < sizeof vars / sizeof vars[0]; i++)
    if (getenv(vars[i]) != NULL) return 1;
  return 0;
}
#endif

void blocks_processes(int *argc, char ***argv, int *rank, int *nranks) {
  *rank = 0;
  *nranks = 1;
#ifdef WHIRL_HAVE_MPI
  int init = 0;
  MPI_Initialized(&init);
  if (!init && !launched_by_mpi()) return;
  if (!init) {
    MPI_Init(argc, argv);
    atexit(finalize_at_exit);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, nranks);
#else
  (void)argc;
  (void)argv;
#endif
}

void blocks_processes_end(void) {
#ifdef WHIRL_HAVE_MPI
  /* the ranks part here (a rank that returns first must not exit while
   * others still call it in) and MPI is finalized at exit */
  int init = 0, fin = 0;
  MPI_Initialized(&init);
  MPI_Finalized(&fin);
  if (init && !fin) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

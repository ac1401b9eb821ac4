/* drivers/run_study.c — `whirl run` of a table computed in blocks: a
 * parameter study (STUDY, doc/parameter-studies.md, a block a point) or
 * basins of attraction (IPS = basins, a block a grid line), the blocks
 * computed by the library (whirl_run_rows_compute), and around them
 *
 *  - a checkpoint, OUT.checkpoint: every finished block is appended and
 *    flushed at once (a killed process loses nothing), synced to the disk
 *    at most once a second; a run killed and started again with the same
 *    command (the same run file bytes, overrides and chunk) takes the blocks
 *    from it and computes only the others.  The output directory is written
 *    at the end, as one transaction, and the checkpoint removed: a partial
 *    state is never an output;
 *  - chunks for job arrays without MPI: --chunk=I/N computes the I-th of N
 *    contiguous parts into OUT.chunk-I-of-N/, and --merge-chunks=N joins
 *    them into OUT, the bytes one run writes;
 *  - MPI (built with --with-mpi, run under mpirun): rank 0 hands the blocks
 *    out to the other ranks as they finish (dynamic load balancing: a
 *    block's cost varies a hundredfold), computes blocks itself between
 *    their messages, and writes them in order, so the file is the same for
 *    any number of ranks and threads.
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
#include "run_cmd.h"
#include "run_study.h"

#define RS '\x1e' /* separates a block's rows on one checkpoint line */

typedef struct study {
  whirl_run *r;
  const study_opts *o;
  size_t B, nblocks, lo, hi; /* rows a block, blocks; this run's [lo, hi) */
  char **blk;                /* blk[b - lo]: the block's rows, or NULL */
  char out[4200], ckpt[4300];
  uint64_t id;               /* identity of the run, for the checkpoint */
  FILE *ck;
  size_t resumed, computed;
  double synced;             /* when the checkpoint was last synced */
  cli_progress prog;
} study;

static double seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* FNV-1a, 64 bits, over bytes. */
static uint64_t fnv(uint64_t h, const void *p, size_t n) {
  const unsigned char *c = p;
  for (size_t i = 0; i < n; i++) h = (h ^ c[i]) * 0x100000001b3ull;
  return h;
}

/* The run's identity: the run file's bytes, the overrides, the chunk and
 * the blocks. */
static int identity(study *S) {
  FILE *f = fopen(S->o->file, "rb");
  if (!f) return -1;
  uint64_t h = 0xcbf29ce484222325ull;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) h = fnv(h, buf, n);
  fclose(f);
  for (size_t i = 0; i < S->o->nov; i++) h = fnv(h, S->o->ov[i], strlen(S->o->ov[i]) + 1);
  const size_t v[4] = {S->nblocks, S->B, S->lo, S->hi};
  S->id = fnv(h, v, sizeof v);
  return 0;
}

/* A checkpoint line "B\trows" (rows separated by RS) into its block. */
static void take_line(study *S, char *line) {
  size_t len = strlen(line), b;
  char *end;
  if (len == 0 || line[len - 1] != '\n') return; /* cut short by the kill */
  line[len - 1] = '\0';
  b = (size_t)strtoull(line, &end, 10);
  if (end == line || *end != '\t' || b < S->lo || b >= S->hi || S->blk[b - S->lo]) return;
  for (char *c = end + 1; *c; c++)
    if (*c == RS) *c = '\n';
  if ((S->blk[b - S->lo] = strdup(end + 1))) S->resumed++;
}

/* Read the checkpoint of an earlier attempt: 0 (none, or its blocks
 * taken), 2 (it belongs to another run: said). */
static int resume(study *S) {
  FILE *f = fopen(S->ckpt, "r");
  if (!f) return 0;
  size_t cap = 0;
  char *line = NULL;
  uint64_t id = 0;
  int ok = getline(&line, &cap, f) > 0 &&
           sscanf(line, "# whirl study checkpoint %" SCNx64, &id) == 1;
  if (!ok || id != S->id) {
    free(line);
    fclose(f);
    cli_error("run", "%s is the checkpoint of another run (another run file, "
              "overrides or chunk): remove it, or give another OUT", S->ckpt);
    return 2;
  }
  while (getline(&line, &cap, f) > 0) take_line(S, line);
  free(line);
  fclose(f);
  return 0;
}

/* One checkpoint line of block b. */
static int put_block(FILE *f, size_t b, const char *rows) {
  if (fprintf(f, "%zu\t", b) < 0) return -1;
  for (const char *c = rows; *c; c++)
    if (fputc(*c == '\n' ? RS : *c, f) == EOF) return -1;
  return fputc('\n', f) == EOF ? -1 : 0;
}

/* Start the checkpoint again with the blocks kept (a line cut short by a
 * kill is dropped), through a new file of its own renamed over it. */
static int checkpoint_open(study *S) {
  char tmp[4400];
  snprintf(tmp, sizeof tmp, "%s.tmp.%ld", S->ckpt, (long)getpid());
  FILE *f = fopen(tmp, "wx"); /* never over a file that is there */
  if (!f) {
    cli_error("run", "cannot write %s: %s", tmp, strerror(errno));
    return 1;
  }
  int bad = fprintf(f, "# whirl study checkpoint %016" PRIx64 " (%s)\n", S->id, S->o->file) < 0;
  for (size_t b = S->lo; !bad && b < S->hi; b++)
    if (S->blk[b - S->lo]) bad = put_block(f, b, S->blk[b - S->lo]);
  if (bad || fflush(f) || fsync(fileno(f)) || fclose(f) || rename(tmp, S->ckpt)) {
    cli_error("run", "cannot write %s: %s", S->ckpt, strerror(errno));
    remove(tmp);
    return 1;
  }
  S->synced = seconds();
  S->ck = fopen(S->ckpt, "a");
  return S->ck ? 0 : 1;
}

/* Keep block b (rows taken over): in memory and in the checkpoint, flushed
 * at once and synced at most once a second (one fsync a block would bound
 * rank 0 at a few hundred blocks a second). */
static int keep(study *S, size_t b, char *rows) {
  S->blk[b - S->lo] = rows;
  S->computed++;
  int bad = put_block(S->ck, b, rows) || fflush(S->ck);
  if (!bad && seconds() - S->synced >= 1.0) {
    bad = fsync(fileno(S->ck)) != 0;
    S->synced = seconds();
  }
  if (bad) cli_error("run", "writing %s failed: %s", S->ckpt, strerror(errno));
  return bad;
}

static int compute_serial(study *S) {
  for (size_t b = S->lo; b < S->hi; b++) {
    cli_progress_show(&S->prog, b - S->lo, S->hi - S->lo);
    if (S->blk[b - S->lo]) continue;
    char *rows;
    if (whirl_run_rows_compute(S->r, b, &rows)) return 1;
    if (keep(S, b, rows)) return 1;
  }
  return 0;
}

#ifdef WHIRL_HAVE_MPI
enum { TAG_WORK = 1, TAG_ROWS = 2, TAG_STOP = 3 };
/* Blocks in the hands of a rank: one computing, the others queued so that
 * it does not wait while rank 0 computes one of its own (a study point
 * costs 10 to 500 ms here, bench_study.sh). */
enum { QUEUE = 4 };
#define NONE ((unsigned long long)-1)

static unsigned long long next_block(const study *S, size_t *next) {
  while (*next < S->hi && S->blk[*next - S->lo]) (*next)++;
  return *next < S->hi ? (unsigned long long)(*next)++ : NONE;
}

/* Rank rk's next message: block w, or — when there is none and it holds no
 * other — the stop.  held[rk] counts its blocks in hand (-1: stopped). */
static void hand_out(unsigned long long w, int rk, int *held, size_t *busy) {
  if (w != NONE) {
    MPI_Send(&w, 1, MPI_UNSIGNED_LONG_LONG, rk, TAG_WORK, MPI_COMM_WORLD);
    held[rk]++;
    (*busy)++;
  } else if (held[rk] == 0) {
    MPI_Send(&w, 1, MPI_UNSIGNED_LONG_LONG, rk, TAG_STOP, MPI_COMM_WORLD);
    held[rk] = -1;
  }
}

/* A finished block from any rank: "B\trows", or "!" for a failure. */
static int receive(study *S, int *from) {
  MPI_Status st;
  int len;
  MPI_Probe(MPI_ANY_SOURCE, TAG_ROWS, MPI_COMM_WORLD, &st);
  MPI_Get_count(&st, MPI_CHAR, &len);
  char *msg = malloc((size_t)len + 1);
  if (!msg) return 1;
  MPI_Recv(msg, len, MPI_CHAR, st.MPI_SOURCE, TAG_ROWS, MPI_COMM_WORLD, &st);
  msg[len] = '\0';
  *from = st.MPI_SOURCE;
  char *end;
  size_t b = (size_t)strtoull(msg, &end, 10);
  int bad = msg[0] == '!' || end == msg || *end != '\t' || b < S->lo || b >= S->hi;
  char *rows = bad ? NULL : strdup(end + 1);
  free(msg);
  return bad || !rows || keep(S, b, rows);
}

/* Rank 0: QUEUE blocks in every other rank's hands; each finished block
 * brings its rank the next unfinished one, or the stop once it holds none
 * and none is left.  Between messages rank 0 computes blocks itself. */
static int master(study *S, int nranks) {
  size_t next = S->lo, done = S->resumed, busy = 0;
  int bad = 0, *held = calloc((size_t)nranks, sizeof *held);
  if (!held) return 1;
  for (int k = 0; k < QUEUE; k++)
    for (int rk = 1; rk < nranks; rk++)
      if (held[rk] >= 0) hand_out(next_block(S, &next), rk, held, &busy);
  for (;;) {
    int pending = 0, from;
    if (busy) MPI_Iprobe(MPI_ANY_SOURCE, TAG_ROWS, MPI_COMM_WORLD, &pending, MPI_STATUS_IGNORE);
    if (pending || (busy && (bad || next >= S->hi))) {
      bad |= receive(S, &from);
      busy--;
      held[from]--;
      cli_progress_show(&S->prog, ++done, S->hi - S->lo);
      hand_out(bad ? NONE : next_block(S, &next), from, held, &busy);
      continue;
    }
    if (bad || next >= S->hi) break;
    unsigned long long w = next_block(S, &next);
    char *rows;
    if (w == NONE) continue;
    if (whirl_run_rows_compute(S->r, (size_t)w, &rows) || keep(S, (size_t)w, rows)) bad = 1;
    cli_progress_show(&S->prog, ++done, S->hi - S->lo);
  }
  for (int rk = 1; rk < nranks; rk++) /* those that never had work */
    if (held[rk] == 0) hand_out(NONE, rk, held, &busy);
  free(held);
  return bad;
}

/* Other ranks: compute the blocks rank 0 sends and return them, until told
 * to stop (the stop comes after the last block a rank holds). */
static void worker(study *S) {
  for (;;) {
    unsigned long long w;
    MPI_Status st;
    MPI_Recv(&w, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    if (st.MPI_TAG == TAG_STOP) return;
    char *rows = NULL, *msg = NULL;
    if (!whirl_run_rows_compute(S->r, (size_t)w, &rows) &&
        (msg = malloc(strlen(rows) + 32)))
      sprintf(msg, "%llu\t%s", w, rows);
    const char *send = msg ? msg : "!";
    MPI_Send(send, (int)strlen(send), MPI_CHAR, 0, TAG_ROWS, MPI_COMM_WORLD);
    free(rows);
    free(msg);
  }
}
#endif

/* The table (the header, the blocks in order, a blank line after each
 * block of more than one row), run.log and, for basins, the picture. */
static int write_output(study *S, int nranks) {
  cli_outdir od;
  int rc = cli_outdir_begin(&od, "run", whirl_run_output_where(S->r), S->out);
  if (rc) return rc;
  char head[4096];
  const char *name = whirl_run_rows_file(S->r);
  FILE *f = cli_outdir_fopen(&od, name);
  int bad = !f || whirl_run_rows_header(S->r, head, sizeof head);
  if (!bad) {
    fprintf(f, "%s\n", head);
    for (size_t b = S->lo; b < S->hi; b++)
      fprintf(f, "%s\n%s", S->blk[b - S->lo], S->B > 1 ? "\n" : "");
  }
  if (f) bad |= cli_outdir_fclose(&od, f, name) != 0;
  FILE *g = bad ? NULL : cli_outdir_fopen(&od, "run.log");
  if (g) {
    fprintf(g, "whirl %s run %s: blocks %zu to %zu of %zu (%zu rows each) of %s\n",
            whirl_version(), S->o->file, S->lo, S->hi - 1, S->nblocks, S->B, name);
    fprintf(g, "%zu computed now, %zu from the checkpoint; %d process%s\n", S->computed,
            S->resumed, nranks, nranks == 1 ? "" : "es");
    bad |= cli_outdir_fclose(&od, g, "run.log") != 0;
  } else {
    bad = 1;
  }
  const char *pic = NULL;
  if (!bad && S->B > 1 && S->lo == 0 && S->hi == S->nblocks) { /* basins, whole */
    whirl_run_rows_finish(S->r, (const char *const *)S->blk, S->nblocks);
    if (run_write_plot(&od, S->r, &pic)) bad = 1;
  }
  if (bad) {
    cli_outdir_abort(&od);
    return 1;
  }
  const int pic_failed = pic && cli_outdir_plot(&od, pic) != 0;
  return cli_outdir_commit(&od) || pic_failed ? 1 : 0;
}

static int setup(study *S, whirl_run *r, const study_opts *o) {
  memset(S, 0, sizeof *S);
  S->r = r;
  S->o = o;
  S->B = whirl_run_rows_block(r);
  S->nblocks = whirl_run_rows(r) / S->B;
  S->lo = 0;
  S->hi = S->nblocks;
  if (o->chunks) {
    if (o->chunk < 1 || o->chunk > o->chunks || o->chunks > S->nblocks) {
      cli_error("run", "--chunk=%zu/%zu: need 1 <= I <= N <= %zu (the %s)", o->chunk,
                o->chunks, S->nblocks, S->B > 1 ? "grid lines" : "points");
      return 2;
    }
    S->lo = (o->chunk - 1) * S->nblocks / o->chunks;
    S->hi = o->chunk * S->nblocks / o->chunks;
    snprintf(S->out, sizeof S->out, "%s.chunk-%zu-of-%zu", whirl_run_output(r), o->chunk,
             o->chunks);
  } else {
    snprintf(S->out, sizeof S->out, "%s", whirl_run_output(r));
  }
  snprintf(S->ckpt, sizeof S->ckpt, "%s.checkpoint", S->out);
  S->blk = calloc(S->hi - S->lo + 1, sizeof *S->blk);
  if (!S->blk || identity(S)) return 1;
  return 0;
}

static void release(study *S) {
  if (S->ck) fclose(S->ck);
  for (size_t i = 0; S->blk && i < S->hi - S->lo; i++) free(S->blk[i]);
  free(S->blk);
}

int run_study_command(whirl_run *r, const study_opts *o, int rank, int nranks) {
  study S;
  int rc = whirl_run_rows_prepare(r);
  if (!rc) rc = setup(&S, r, o);
  else memset(&S, 0, sizeof S);
  if (!rc && rank == 0) rc = cli_outdir_check("run", whirl_run_output_where(r), S.out);
  if (!rc && rank == 0) rc = resume(&S);
  if (!rc && rank == 0) rc = checkpoint_open(&S);
  cli_progress_init(&S.prog, S.B > 1 ? "basins" : "study", o->quiet || rank != 0);
#ifdef WHIRL_HAVE_MPI
  if (nranks > 1) {
    int go = rc, all;
    MPI_Allreduce(&go, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (all) rc = rc ? rc : 1;
    else if (rank == 0) rc = master(&S, nranks);
    else worker(&S);
  } else
#endif
  if (!rc) rc = compute_serial(&S);
  cli_progress_end(&S.prog);
  if (S.ck) {
    fsync(fileno(S.ck));
    fclose(S.ck);
    S.ck = NULL;
  }
  if (!rc && rank == 0) rc = write_output(&S, nranks);
  if (!rc && rank == 0) {
    remove(S.ckpt);
    if (!o->quiet)
      printf("%zu %s (%zu computed, %zu from the checkpoint); wrote %s/ (%s, run.log%s%s)\n",
             S.hi - S.lo, S.B > 1 ? "grid lines" : "points", S.computed, S.resumed, S.out,
             whirl_run_rows_file(r), S.B > 1 && !o->chunks && !cli_pictures_skipped()
             ? ", basins." : "",
             S.B > 1 && !o->chunks && !cli_pictures_skipped() ? cli_picture_format : "");
  }
  release(&S);
  return rank == 0 ? rc : 0;
}

/* The rows of one chunk's table into their blocks: 0, or 2 (said). */
static int read_chunk(study *S, size_t c, size_t chunks, const char *head) {
  char path[4400];
  const size_t lo = (c - 1) * S->nblocks / chunks, hi = c * S->nblocks / chunks;
  snprintf(path, sizeof path, "%s.chunk-%zu-of-%zu/%s", whirl_run_output(S->r), c, chunks,
           whirl_run_rows_file(S->r));
  FILE *f = fopen(path, "r");
  size_t cap = 0, b = lo, k = 0, len = 0;
  char *line = NULL, *acc = NULL;
  ssize_t m = f ? getline(&line, &cap, f) : -1;
  int rc = m > 0 && (size_t)m == strlen(head) + 1 && !strncmp(line, head, strlen(head)) ? 0 : 2;
  while (!rc && (m = getline(&line, &cap, f)) > 0) {
    if (!strcmp(line, "\n")) continue; /* the blank line after a block */
    if (b >= hi || line[m - 1] != '\n') { rc = 2; break; }
    char *na = realloc(acc, len + (size_t)m + 1);
    if (!na) { rc = 1; break; }
    acc = na;
    memcpy(acc + len, line, (size_t)m + 1);
    len += (size_t)m;
    if (++k == S->B) {
      acc[len - 1] = '\0';
      S->blk[b++] = acc;
      acc = NULL, len = 0, k = 0;
    }
  }
  if (!rc && (b != hi || k != 0)) rc = 2;
  if (rc) cli_error("run", "%s: %s", path, f ? "not the table of this chunk of the run" : strerror(errno));
  free(acc);
  free(line);
  if (f) fclose(f);
  return rc;
}

/* --merge-chunks=N: OUT.chunk-I-of-N's tables for I = 1..N, each with its
 * blocks exactly, joined into OUT. */
int run_study_merge(whirl_run *r, const study_opts *o) {
  study S;
  study_opts whole = *o;
  whole.chunks = 0;
  int rc = whirl_run_rows_prepare(r);
  if (!rc) rc = setup(&S, r, &whole);
  else memset(&S, 0, sizeof S);
  if (!rc && !(o->chunks >= 1 && o->chunks <= S.nblocks)) {
    cli_error("run", "--merge-chunks=%zu: need 1 <= N <= %zu", o->chunks, S.nblocks);
    rc = 2;
  }
  char head[4096];
  if (!rc && whirl_run_rows_header(r, head, sizeof head)) rc = 1;
  for (size_t c = 1; !rc && c <= o->chunks; c++) rc = read_chunk(&S, c, o->chunks, head);
  S.resumed = S.nblocks;
  if (!rc) rc = cli_outdir_check("run", whirl_run_output_where(r), S.out);
  if (!rc) rc = write_output(&S, 1);
  if (!rc && !o->quiet)
    printf("%zu %s from %zu chunks; wrote %s/ (%s, run.log)\n", S.nblocks,
           S.B > 1 ? "grid lines" : "points", o->chunks, S.out, whirl_run_rows_file(r));
  release(&S);
  return rc;
}

/* drivers/run_study.c — `whirl run` of a parameter study (STUDY,
 * doc/parameter-studies.md): the points of the grid computed by the
 * library one row at a time (whirl_run_study_row), and around them
 *
 *  - a checkpoint, OUT.checkpoint: every finished row is appended and
 *    flushed to disk at once; a run killed and started again with the same
 *    command (the same run file bytes, overrides and chunk) takes the rows
 *    from it and computes only the others.  The output directory is
 *    written at the end, as one transaction, and the checkpoint removed:
 *    a partial state is never an output;
 *  - chunks for job arrays without MPI: --chunk=I/N computes the I-th of N
 *    contiguous parts into OUT.chunk-I-of-N/, and --merge-chunks=N joins
 *    them into OUT/study.tsv, the bytes one run writes;
 *  - MPI (built with --with-mpi, run under mpirun): rank 0 hands the points
 *    out to the other ranks as they finish (dynamic load balancing: a
 *    point's cost varies a hundredfold), computes points itself between
 *    their messages, and writes the rows in the order of the points, so the
 *    file is the same for any number of ranks and threads.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* fsync, fileno */
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
#include "run_study.h"

#define ROWLEN 4096

typedef struct study {
  whirl_run *r;
  const study_opts *o;
  size_t npoints, lo, hi;  /* the points of this run (its chunk): [lo, hi) */
  char **rows;             /* rows[i - lo], NULL until computed */
  char out[4200], ckpt[4300];
  uint64_t id;             /* identity of the run, for the checkpoint */
  FILE *ck;
  size_t resumed, computed;
  double synced;           /* when the checkpoint was last synced */
  cli_progress prog;
} study;

/* FNV-1a, 64 bits, over bytes. */
static uint64_t fnv(uint64_t h, const void *p, size_t n) {
  const unsigned char *c = p;
  for (size_t i = 0; i < n; i++) h = (h ^ c[i]) * 0x100000001b3ull;
  return h;
}

/* The run's identity: the run file's bytes, the overrides, the chunk and
 * the number of points. */
static int identity(study *S) {
  FILE *f = fopen(S->o->file, "rb");
  if (!f) return -1;
  uint64_t h = 0xcbf29ce484222325ull;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) h = fnv(h, buf, n);
  fclose(f);
  for (size_t i = 0; i < S->o->nov; i++) h = fnv(h, S->o->ov[i], strlen(S->o->ov[i]) + 1);
  const size_t v[3] = {S->npoints, S->lo, S->hi};
  S->id = fnv(h, v, sizeof v);
  return 0;
}

/* Read the checkpoint of an earlier attempt: 0 (none, or its rows taken),
 * 2 (it belongs to another run: said). */
static int resume(study *S) {
  FILE *f = fopen(S->ckpt, "r");
  if (!f) return 0;
  char line[ROWLEN + 2];
  uint64_t id = 0;
  int ok = fgets(line, sizeof line, f) &&
           sscanf(line, "# whirl study checkpoint %" SCNx64, &id) == 1;
  if (!ok || id != S->id) {
    fclose(f);
    cli_error("run", "%s is the checkpoint of another run (another run file, "
              "overrides or chunk): remove it, or give another OUT", S->ckpt);
    return 2;
  }
  while (fgets(line, sizeof line, f)) {
    size_t len = strlen(line), i;
    char *end;
    if (len == 0 || line[len - 1] != '\n') break; /* cut short by the kill */
    i = (size_t)strtoull(line, &end, 10);
    if (end == line || *end != '\t' || i < S->lo || i >= S->hi || S->rows[i - S->lo]) continue;
    line[len - 1] = '\0';
    if (!(S->rows[i - S->lo] = strdup(line))) break;
    S->resumed++;
  }
  fclose(f);
  return 0;
}

/* Start the checkpoint again with the rows kept (a line cut short by a
 * kill is dropped), written beside and renamed over it.  0 or 1. */
static int checkpoint_open(study *S) {
  char tmp[4400];
  snprintf(tmp, sizeof tmp, "%s.tmp.%ld", S->ckpt, (long)getpid());
  FILE *f = fopen(tmp, "wx"); /* never over a file that is there */
  if (!f) {
    cli_error("run", "cannot write %s: %s", tmp, strerror(errno));
    return 1;
  }
  fprintf(f, "# whirl study checkpoint %016" PRIx64 " (%s)\n", S->id, S->o->file);
  for (size_t i = S->lo; i < S->hi; i++)
    if (S->rows[i - S->lo]) fprintf(f, "%s\n", S->rows[i - S->lo]);
  if (fflush(f) || fsync(fileno(f)) || fclose(f) || rename(tmp, S->ckpt)) {
    cli_error("run", "cannot write %s: %s", S->ckpt, strerror(errno));
    return 1;
  }
  S->ck = fopen(S->ckpt, "a");
  return S->ck ? 0 : 1;
}

static double seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Keep row i: in memory and in the checkpoint, flushed at once (a killed
 * process loses nothing the kernel holds) and synced to the disk at most
 * once a second (a lost node loses at most that second; one fsync a row
 * would bound rank 0 at a few hundred rows a second). */
static int keep(study *S, size_t i, const char *row) {
  if (!(S->rows[i - S->lo] = strdup(row))) return 1;
  S->computed++;
  int bad = fprintf(S->ck, "%s\n", row) < 0 || fflush(S->ck);
  if (!bad && seconds() - S->synced >= 1.0) {
    bad = fsync(fileno(S->ck)) != 0;
    S->synced = seconds();
  }
  if (bad) {
    cli_error("run", "writing %s failed: %s", S->ckpt, strerror(errno));
    return 1;
  }
  return 0;
}

static int compute_serial(study *S) {
  char row[ROWLEN];
  for (size_t i = S->lo; i < S->hi; i++) {
    cli_progress_show(&S->prog, i - S->lo, S->hi - S->lo);
    if (S->rows[i - S->lo]) continue;
    if (whirl_run_study_row(S->r, i, row, sizeof row) || keep(S, i, row)) return 1;
  }
  return 0;
}

#ifdef WHIRL_HAVE_MPI
enum { TAG_WORK = 1, TAG_ROW = 2, TAG_STOP = 3 };
/* Points in the hands of a rank: one computing, the others queued so that
 * it does not wait while rank 0 computes a point of its own (a point costs
 * 10 to 500 ms here, bench_study.sh). */
enum { QUEUE = 4 };

/* The next unfinished point of the study from *next, or -1. */
static unsigned long long next_point(const study *S, size_t *next) {
  while (*next < S->hi && S->rows[*next - S->lo]) (*next)++;
  return *next < S->hi ? (unsigned long long)(*next)++ : (unsigned long long)-1;
}

/* Rank rk's next message: the point w, or — when there is none and it
 * holds no other — the stop.  held[rk] counts its points in hand. */
static void hand_out(unsigned long long w, int rk, int *held, size_t *busy) {
  if (w != (unsigned long long)-1) {
    MPI_Send(&w, 1, MPI_UNSIGNED_LONG_LONG, rk, TAG_WORK, MPI_COMM_WORLD);
    held[rk]++;
    (*busy)++;
  } else if (held[rk] == 0) {
    MPI_Send(&w, 1, MPI_UNSIGNED_LONG_LONG, rk, TAG_STOP, MPI_COMM_WORLD);
    held[rk] = -1; /* stopped */
  }
}

/* Rank 0: every other rank holds QUEUE points at a time (one computing,
 * the others queued, so that it does not wait for rank 0); a finished row brings it the
 * next unfinished point, and the stop once it holds none and none is left.
 * Between messages rank 0 computes points itself.  Rows go into the
 * checkpoint as they come; the file is written in the points' order
 * afterwards. */
static int master(study *S, int nranks) {
  size_t next = S->lo, done = S->resumed, busy = 0;
  char row[ROWLEN + 32];
  int bad = 0, *held = calloc((size_t)nranks, sizeof *held);
  if (!held) return 1;
  for (int k = 0; k < QUEUE; k++)
    for (int rk = 1; rk < nranks; rk++)
      if (held[rk] >= 0) hand_out(next_point(S, &next), rk, held, &busy);
  for (;;) {
    int pending = 0;
    MPI_Status st;
    if (busy) MPI_Iprobe(MPI_ANY_SOURCE, TAG_ROW, MPI_COMM_WORLD, &pending, &st);
    if (pending || (busy && (bad || next >= S->hi))) {
      MPI_Recv(row, (int)sizeof row, MPI_CHAR, MPI_ANY_SOURCE, TAG_ROW, MPI_COMM_WORLD, &st);
      busy--;
      held[st.MPI_SOURCE]--;
      size_t i = (size_t)strtoull(row, NULL, 10);
      if (row[0] == '!') bad = 1;
      else if (!bad && i >= S->lo && i < S->hi) bad = keep(S, i, row);
      cli_progress_show(&S->prog, ++done, S->hi - S->lo);
      hand_out(bad ? (unsigned long long)-1 : next_point(S, &next), st.MPI_SOURCE, held, &busy);
      continue;
    }
    if (bad || next >= S->hi) break;
    unsigned long long w = next_point(S, &next);
    if (w == (unsigned long long)-1) continue;
    if (whirl_run_study_row(S->r, (size_t)w, row, sizeof row) || keep(S, (size_t)w, row)) bad = 1;
    cli_progress_show(&S->prog, ++done, S->hi - S->lo);
  }
  for (int rk = 1; rk < nranks; rk++) /* those never stopped (no work at all) */
    if (held[rk] == 0) hand_out((unsigned long long)-1, rk, held, &busy);
  free(held);
  return bad;
}

/* Other ranks: compute the points rank 0 sends, return their rows, until
 * told to stop (a rank holds up to QUEUE points; the stop comes after
 * them). */
static void worker(study *S) {
  char row[ROWLEN];
  for (;;) {
    unsigned long long w;
    MPI_Status st;
    MPI_Recv(&w, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    if (st.MPI_TAG == TAG_STOP) return;
    if (whirl_run_study_row(S->r, (size_t)w, row, sizeof row)) snprintf(row, sizeof row, "!");
    MPI_Send(row, (int)strlen(row) + 1, MPI_CHAR, 0, TAG_ROW, MPI_COMM_WORLD);
  }
}
#endif

/* study.tsv (the header and the rows in order) and run.log into OUT. */
static int write_output(study *S, const char *out, int nranks) {
  cli_outdir od;
  int rc = cli_outdir_begin(&od, "run", whirl_run_output_where(S->r), out);
  if (rc) return rc;
  char head[ROWLEN];
  FILE *f = cli_outdir_fopen(&od, "study.tsv");
  int bad = !f || whirl_run_study_header(S->r, head, sizeof head);
  if (!bad) {
    fprintf(f, "%s\n", head);
    for (size_t i = S->lo; i < S->hi; i++) fprintf(f, "%s\n", S->rows[i - S->lo]);
  }
  if (f) bad |= cli_outdir_fclose(&od, f, "study.tsv") != 0;
  FILE *g = bad ? NULL : cli_outdir_fopen(&od, "run.log");
  if (g) {
    fprintf(g, "whirl %s run %s: parameter study, points %zu to %zu of %zu\n",
            whirl_version(), S->o->file, S->lo, S->hi - 1, S->npoints);
    fprintf(g, "%zu computed now, %zu from the checkpoint; %d process%s\n",
            S->computed, S->resumed, nranks, nranks == 1 ? "" : "es");
    bad |= cli_outdir_fclose(&od, g, "run.log") != 0;
  } else {
    bad = 1;
  }
  return cli_outdir_finish(&od, bad, NULL);
}

static int setup(study *S, whirl_run *r, const study_opts *o) {
  memset(S, 0, sizeof *S);
  S->r = r;
  S->o = o;
  S->npoints = whirl_run_study_size(r);
  S->lo = 0;
  S->hi = S->npoints;
  if (o->chunks) {
    if (o->chunk < 1 || o->chunk > o->chunks || o->chunks > S->npoints) {
      cli_error("run", "--chunk=%zu/%zu: need 1 <= I <= N <= %zu (the points)", o->chunk,
                o->chunks, S->npoints);
      return 2;
    }
    S->lo = (o->chunk - 1) * S->npoints / o->chunks;
    S->hi = o->chunk * S->npoints / o->chunks;
    snprintf(S->out, sizeof S->out, "%s.chunk-%zu-of-%zu", whirl_run_output(r), o->chunk,
             o->chunks);
  } else {
    snprintf(S->out, sizeof S->out, "%s", whirl_run_output(r));
  }
  snprintf(S->ckpt, sizeof S->ckpt, "%s.checkpoint", S->out);
  S->rows = calloc(S->hi - S->lo + 1, sizeof *S->rows);
  if (!S->rows || identity(S)) return 1;
  return 0;
}

static void release(study *S) {
  if (S->ck) fclose(S->ck);
  for (size_t i = 0; S->rows && i < S->hi - S->lo; i++) free(S->rows[i]);
  free(S->rows);
}

int run_study_command(whirl_run *r, const study_opts *o, int rank, int nranks) {
  study S;
  int rc = setup(&S, r, o);
  if (!rc && rank == 0) rc = cli_outdir_check("run", whirl_run_output_where(r), S.out);
  if (!rc && rank == 0) rc = resume(&S);
  if (!rc && rank == 0) rc = checkpoint_open(&S);
  cli_progress_init(&S.prog, "study", o->quiet || rank != 0);
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
  if (!rc && rank == 0) rc = write_output(&S, S.out, nranks);
  if (!rc && rank == 0) {
    remove(S.ckpt);
    if (!o->quiet)
      printf("study: %zu points (%zu computed, %zu from the checkpoint); wrote %s/ "
             "(study.tsv, run.log)\n", S.hi - S.lo, S.computed, S.resumed, S.out);
  }
  release(&S);
  return rank == 0 ? rc : 0;
}

/* --merge-chunks=N: OUT.chunk-I-of-N/study.tsv for I = 1..N, their rows
 * checked to be the points 0..P-1 once each, joined into OUT/study.tsv. */
int run_study_merge(whirl_run *r, const study_opts *o) {
  study S;
  study_opts whole = *o;
  whole.chunks = 0;
  int rc = setup(&S, r, &whole);
  if (!rc) rc = o->chunks >= 1 && o->chunks <= S.npoints ? 0 : 2;
  if (rc == 2) cli_error("run", "--merge-chunks=%zu: need 1 <= N <= %zu", o->chunks, S.npoints);
  char head[ROWLEN], line[ROWLEN + 2], path[4400];
  if (!rc && whirl_run_study_header(r, head, sizeof head)) rc = 1;
  for (size_t c = 1; !rc && c <= o->chunks; c++) {
    snprintf(path, sizeof path, "%s.chunk-%zu-of-%zu/study.tsv", whirl_run_output(r), c, o->chunks);
    FILE *f = fopen(path, "r");
    if (!f || !fgets(line, sizeof line, f) || strncmp(line, head, strlen(head)) ||
        line[strlen(head)] != '\n') {
      cli_error("run", "%s: %s", path, f ? "not a study.tsv of this run" : strerror(errno));
      rc = 2;
    }
    while (!rc && fgets(line, sizeof line, f)) {
      char *end;
      size_t i = (size_t)strtoull(line, &end, 10), len = strlen(line);
      if (end == line || *end != '\t' || i >= S.npoints || S.rows[i] || line[len - 1] != '\n') {
        cli_error("run", "%s: row '%.40s' is not a new point of this study", path, line);
        rc = 2;
        break;
      }
      line[len - 1] = '\0';
      if (!(S.rows[i] = strdup(line))) rc = 1;
    }
    if (f) fclose(f);
  }
  for (size_t i = 0; !rc && i < S.npoints; i++)
    if (!S.rows[i]) {
      cli_error("run", "point %zu is in none of the %zu chunks", i, o->chunks);
      rc = 2;
    }
  S.resumed = S.npoints;
  if (!rc) rc = cli_outdir_check("run", whirl_run_output_where(r), S.out);
  if (!rc) rc = write_output(&S, S.out, 1);
  if (!rc && !o->quiet) printf("study: %zu points from %zu chunks; wrote %s/ (study.tsv, run.log)\n",
                               S.npoints, o->chunks, S.out);
  release(&S);
  return rc;
}

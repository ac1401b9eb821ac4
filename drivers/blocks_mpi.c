/* drivers/blocks_mpi.c — the blocks of a table (blocks.h) on MPI ranks.
 * Stage by stage, rank 0 keeps up to QUEUE blocks in the hands of every
 * other rank (one computing, the others queued, so that a rank does not
 * wait while rank 0 computes one of its own) and sends the next unfinished
 * block with each finished one it receives: dynamic load balancing, since
 * a block's cost varies a hundredfold.  Between messages rank 0 computes
 * blocks itself.  A finished stage (an atlas round) is broadcast to every
 * rank, which takes it in before the next stage's blocks; the table's
 * blocks stay on rank 0, which keeps the checkpoint and writes them.
 *
 * Messages: work {stage, block} (TAG_WORK), the end of a stage (TAG_STAGE,
 * then the stage's broadcast) or of the run (TAG_STOP), to the ranks; a
 * finished block {stage, block, when it was computed} and its bytes
 * (TAG_DATA; stage UINT64_MAX: it failed, said by that rank), to rank 0.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "config.h"
#ifdef WHIRL_HAVE_MPI
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <mpi.h>

#include "blocks_impl.h"

enum { TAG_WORK = 1, TAG_DATA = 2, TAG_STOP = 3, TAG_STAGE = 4 };
enum { QUEUE = 4 };
#define NONE UINT64_MAX
#define PIECE (1 << 30) /* bytes a broadcast at most (MPI counts are int) */

/* A finished block's message starts with this. */
typedef struct head {
  uint64_t stage, block;
  double t0, t1, cpu; /* when it was computed, its CPU seconds */
} head;

/* The order blocks are handed out in: every STRIDE-th first, then the
 * ones after them, and so on (0, 8, 16, ..., 1, 9, ...), so that the last
 * blocks handed out are spread over the stage rather than its end, where
 * costly blocks may crowd (the rim of a basin's disc: the tail of a stage
 * is then an average block; bench_basins_mpi.sh, 0.93 -> 0.96 at 2 ranks
 * in the replayed schedule).  The file does not depend on the order. */
enum { STRIDE = 8 };
typedef struct order {
  size_t first, count, per, k; /* the k-th of STRIDE * per positions next */
} order;

static void order_init(order *o, const blocks *K, size_t s) {
  o->first = blocks_stage_first(K, s);
  o->count = blocks_stage_end(K, s) - o->first;
  o->per = (o->count + STRIDE - 1) / STRIDE;
  o->k = 0;
}
static int order_done(const order *o) { return o->k >= STRIDE * o->per; }

static uint64_t next_block(const blocks *K, size_t s, order *o) {
  while (!order_done(o)) {
    const size_t i = (o->k % o->per) * STRIDE + o->k / o->per;
    o->k++;
    if (i < o->count && !K->have[blocks_entry(K, s, o->first + i)]) return o->first + i;
  }
  return NONE;
}

static void send_work(size_t s, uint64_t b, int rk, int tag) {
  const uint64_t w[2] = {s, b};
  MPI_Send(w, 2, MPI_UINT64_T, rk, tag, MPI_COMM_WORLD);
}

/* A finished block from any rank: 0, or 1 (it failed there, or here). */
static int receive(blocks *K, size_t s, int *from) {
  MPI_Status st;
  int len;
  MPI_Probe(MPI_ANY_SOURCE, TAG_DATA, MPI_COMM_WORLD, &st);
  MPI_Get_count(&st, MPI_BYTE, &len);
  char *msg = malloc((size_t)len + 1);
  if (!msg) return 1; /* the message is left: the run ends in failure */
  MPI_Recv(msg, len, MPI_BYTE, st.MPI_SOURCE, TAG_DATA, MPI_COMM_WORLD, &st);
  *from = st.MPI_SOURCE;
  head h = {NONE, 0, 0, 0, 0};
  if ((size_t)len >= sizeof h) memcpy(&h, msg, sizeof h);
  if (h.stage != s || h.block < blocks_stage_first(K, s) || h.block >= blocks_stage_end(K, s)) {
    free(msg);
    return 1;
  }
  const size_t n = (size_t)len - sizeof h;
  memmove(msg, msg + sizeof h, n);
  msg[n] = '\0';
  const blocks_when w = {h.t0, h.t1, *from, h.cpu};
  return blocks_keep(K, s, (size_t)h.block, msg, n, &w);
}

/* The blocks of stage s: handed out, computed here between messages,
 * every one sent out received back (also after a failure). */
static int master_stage(blocks *K, size_t s, int nranks, int *held) {
  size_t busy = 0, missing = 0;
  order next;
  order_init(&next, K, s);
  for (size_t b = next.first; b < blocks_stage_end(K, s); b++)
    missing += !K->have[blocks_entry(K, s, b)];
  /* at first no more than a share of the stage each: rank 0 computes too */
  size_t q = missing / (2 * (size_t)nranks);
  q = q < 1 ? 1 : q > QUEUE ? QUEUE : q;
  int bad = 0;
  for (size_t k = 0; k < q; k++)
    for (int rk = 1; rk < nranks; rk++) {
      const uint64_t w = next_block(K, s, &next);
      if (w != NONE) send_work(s, w, rk, TAG_WORK), held[rk]++, busy++;
    }
  for (;;) {
    int pending = 0, from = 0;
    if (busy) MPI_Iprobe(MPI_ANY_SOURCE, TAG_DATA, MPI_COMM_WORLD, &pending, MPI_STATUS_IGNORE);
    if (pending || (busy && (bad || order_done(&next)))) {
      bad |= receive(K, s, &from);
      busy--, held[from]--;
      const uint64_t w = bad ? NONE : next_block(K, s, &next);
      if (w != NONE) send_work(s, w, from, TAG_WORK), held[from]++, busy++;
      continue;
    }
    if (bad || order_done(&next)) break;
    const uint64_t w = next_block(K, s, &next);
    if (w != NONE && blocks_compute_one(K, s, (size_t)w)) bad = 1;
  }
  return bad;
}

/* A rank without the memory for a broadcast: the whole job ends. */
static void out_of_memory(const blocks *K) {
  cli_error(K->d->cmd, "out of memory for a stage's blocks (a broadcast): the job is ended");
  MPI_Abort(MPI_COMM_WORLD, 1);
}

/* Stage s's blocks from rank 0 to every rank (collective). */
static int broadcast(blocks *K, size_t s, int rank) {
  const size_t nb = K->d->stage_blocks[s], e0 = K->off[s];
  uint64_t *len = malloc((nb + 1) * sizeof *len);
  int bad = !len;
  if (bad && rank != 0) out_of_memory(K);
  for (size_t b = 0; !bad && rank == 0 && b < nb; b++) len[b] = K->len[e0 + b];
  MPI_Bcast(&bad, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (bad) {
    free(len);
    return 1;
  }
  MPI_Bcast(len, (int)nb, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  for (size_t b = 0; b < nb; b++) {
    if (rank != 0) {
      K->len[e0 + b] = (size_t)len[b];
      K->data[e0 + b] = malloc((size_t)len[b] + 1);
      if (!K->data[e0 + b]) out_of_memory(K); /* the others wait in it */
      K->have[e0 + b] = 1;
    }
    for (size_t at = 0; at < len[b]; at += PIECE) {
      const size_t m = len[b] - at < PIECE ? len[b] - at : PIECE;
      MPI_Bcast(K->data[e0 + b] + at, (int)m, MPI_BYTE, 0, MPI_COMM_WORLD);
    }
    if (rank != 0) K->data[e0 + b][len[b]] = '\0';
  }
  free(len);
  return 0;
}

int blocks_master(blocks *K, int nranks) {
  int *held = calloc((size_t)nranks, sizeof *held), bad = !held;
  for (size_t s = 0; !bad && s <= K->d->nstages; s++) {
    bad = master_stage(K, s, nranks, held);
    if (bad || s == K->d->nstages) break;
    for (int rk = 1; rk < nranks; rk++) send_work(s, 0, rk, TAG_STAGE);
    bad = broadcast(K, s, 0) || blocks_absorb(K, s);
  }
  for (int rk = 1; rk < nranks; rk++) send_work(0, 0, rk, TAG_STOP);
  free(held);
  return bad;
}

/* The finished blocks on their way to rank 0: sent without waiting (a
 * block's rows are more than the few kB a message is sent eagerly with;
 * a blocking send would wait until rank 0 is done with a block of its
 * own, and the rank with it), freed once rank 0 has them. */
typedef struct outbox {
  MPI_Request rq[2 * QUEUE];
  char *msg[2 * QUEUE];
  int n;
} outbox;

static void outbox_reap(outbox *o, int all) {
  for (int i = 0; i < o->n;) {
    int done = 0;
    if (all) MPI_Wait(&o->rq[i], MPI_STATUS_IGNORE), done = 1;
    else MPI_Test(&o->rq[i], &done, MPI_STATUS_IGNORE);
    if (!done) {
      i++;
      continue;
    }
    free(o->msg[i]);
    o->n--;
    o->rq[i] = o->rq[o->n], o->msg[i] = o->msg[o->n];
  }
}

static void outbox_send(outbox *o, char *msg, size_t n) {
  outbox_reap(o, 0);
  if (o->n == 2 * QUEUE) {
    int i;
    MPI_Waitany(o->n, o->rq, &i, MPI_STATUS_IGNORE);
    free(o->msg[i]);
    o->n--;
    o->rq[i] = o->rq[o->n], o->msg[i] = o->msg[o->n];
  }
  MPI_Isend(msg, (int)n, MPI_BYTE, 0, TAG_DATA, MPI_COMM_WORLD, &o->rq[o->n]);
  o->msg[o->n++] = msg;
}

/* Compute the blocks rank 0 sends and return them, take each finished
 * stage in, until told to stop. */
int blocks_worker(blocks *K) {
  int failed = 0;
  outbox ob = {.n = 0};
  for (;;) {
    uint64_t w[2];
    MPI_Status st;
    MPI_Recv(w, 2, MPI_UINT64_T, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    if (st.MPI_TAG == TAG_STOP) break;
    if (st.MPI_TAG == TAG_STAGE) {
      failed |= broadcast(K, (size_t)w[0], 1) || blocks_absorb(K, (size_t)w[0]);
      continue;
    }
    char *data = NULL, *msg = NULL;
    size_t n = 0;
    const double c0 = blocks_cpu_seconds();
    head h = {w[0], w[1], blocks_seconds(), 0, 0};
    if (failed || K->d->compute(K->d->ctx, (size_t)w[0], (size_t)w[1], &data, &n) ||
        n > INT_MAX - sizeof h || !(msg = malloc(n + sizeof h)))
      h.stage = NONE, n = 0;
    h.t1 = blocks_seconds();
    h.cpu = blocks_cpu_seconds() - c0;
    if (!msg && !(msg = malloc(sizeof h))) { /* a failure: the header alone */
      cli_error(K->d->cmd, "out of memory for a message: the job is ended");
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    memcpy(msg, &h, sizeof h);
    if (n) memcpy(msg + sizeof h, data, n);
    free(data);
    outbox_send(&ob, msg, n + sizeof h);
  }
  outbox_reap(&ob, 1);
  return 0;
}
#else
typedef int blocks_mpi_unused; /* ISO C: no empty translation unit */
#endif

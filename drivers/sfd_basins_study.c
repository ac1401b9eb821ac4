/* drivers/sfd_basins_study.c — `whirl sfd basins --study FILE`: basin
 * fractions as the analysis of a parameter study.  FILE lists points
 * (whirl/points.h: a header of names among omega, lambda, delta, zeta, a
 * row of values a point); at each, the parameters of the command line with
 * the row's values, the attractors are found and the initial states
 * classified exactly as `whirl sfd basins` at that point alone does with
 * the same options (its own atlas), and study.tsv gets a row
 *
 *   point  <the names>  status  states  circular small middle large
 *   quasiperiodic  contact unsettled failed
 *
 * (the count of states of each class; status ok, invalid — the parameters
 * are outside the model's domain, said on stderr —, or error).  A block of
 * blocks.c is a point, so the study is resumable, in chunks and on MPI
 * like every table; a row depends on its point alone.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <whirl/points.h>

#include "cli.h"
#include "sfd_basins.h"

static const char *const pname[] = {"omega", "lambda", "delta", "zeta"};
#define NNAMES (sizeof pname / sizeof pname[0])
static const char *const klass[] = {"circular", "small", "middle", "large", "quasiperiodic",
                                    "contact", "unsettled", "failed"};
#define NCLASS (sizeof klass / sizeof klass[0])

typedef struct study {
  const sb *base;
  whirl_points P;
  int par[NNAMES];           /* column a: parameter index */
  char header[1024];
  blocks_def d;
} study;

static int check_name(const char *name, size_t col, char *why, size_t len, void *ctx) {
  study *T = ctx;
  size_t k = 0;
  while (k < NNAMES && strcasecmp(name, pname[k])) k++;
  for (size_t b = 0; k < NNAMES && b < col; b++)
    if (T->par[b] == (int)k) {
      snprintf(why, len, "is named twice");
      return 1;
    }
  if (k == NNAMES || col >= NNAMES) {
    snprintf(why, len, "is not a parameter of whirl sfd basins (omega, lambda, delta, zeta)");
    return 1;
  }
  T->par[col] = (int)k;
  return 0;
}

/* Point i's classes counted: 0 ok, 1 invalid, 2 error (said). */
static int classify_point(const study *T, size_t i, sb *P, size_t *cnt) {
  char msg[512];
  for (size_t a = 0; a < T->P.ncols; a++) P->p[T->par[a]] = T->P.v[i * T->P.ncols + a];
  if (!(P->p[WHIRL_SFD_OMEGA] > 0) || whirl_sfd_check_params(P->p, msg, sizeof msg) != WHIRL_OK) {
    cli_error(CMD, "study point %zu: %s", i, P->p[WHIRL_SFD_OMEGA] > 0 ? msg : "omega must be > 0");
    return 1;
  }
  whirl_sfd_attractors_options ao;
  whirl_sfd_attractors_options_default(&ao);
  ao.rtol = P->rtol, ao.atol = P->atol, ao.method = P->method;
  if (whirl_sfd_attractors_find(P->p, &ao, &P->A, msg, sizeof msg) != WHIRL_OK) {
    cli_error(CMD, "study point %zu: %s", i, msg);
    return 2;
  }
  P->na = whirl_sfd_attractors_count(P->A);
  sfd_basins_options(P);
  if (sfd_basins_states(P, 0)) return 2;
  int *which = malloc((P->n + 1) * sizeof *which);
  int rc = which ? whirl_basins_compute(whirl_sfd_fixed(), P->p, P->n, P->X,
                                        whirl_sfd_attractors_list(P->A), P->na, &P->bo, which,
                                        NULL, NULL, msg, sizeof msg)
                 : WHIRL_ENOMEM;
  if (rc != WHIRL_OK) cli_error(CMD, "study point %zu: %s", i, which ? msg : "out of memory");
  for (size_t q = 0; rc == WHIRL_OK && q < P->n; q++) {
    const char *name = sfd_basins_class(P, which[q]);
    size_t k = 0;
    while (k + 1 < NCLASS && strcmp(name, klass[k])) k++;
    cnt[k]++;
  }
  free(which);
  return rc == WHIRL_OK ? 0 : 2;
}

static int compute(void *ctx, size_t s, size_t i, char **data, size_t *len) {
  const study *T = ctx;
  (void)s;
  sb P = *T->base;
  P.A = NULL, P.X = NULL, P.atlas = NULL;
  size_t cnt[NCLASS] = {0};
  const int st = classify_point(T, i, &P, cnt);
  char *row = malloc(64 * (T->P.ncols + NCLASS) + 64);
  if (row) {
    size_t pos = (size_t)sprintf(row, "%zu", i);
    for (size_t a = 0; a < T->P.ncols; a++)
      pos += (size_t)sprintf(row + pos, "\t%.10g", T->P.v[i * T->P.ncols + a]);
    pos += (size_t)sprintf(row + pos, "\t%s\t%zu", st == 0 ? "ok" : st == 1 ? "invalid" : "error",
                           st == 0 ? P.n : 0);
    for (size_t k = 0; k < NCLASS; k++) pos += (size_t)sprintf(row + pos, "\t%zu", cnt[k]);
    *data = row;
    *len = pos;
  }
  free(P.X);
  whirl_sfd_attractors_free(P.A);
  if (!row) cli_error(CMD, "out of memory");
  return row ? 0 : 1;
}

static int finish(void *ctx, cli_outdir *od, const blocks_result *res) {
  const study *T = ctx;
  if (cli_outdir_commit(od)) return 1;
  if (!T->base->quiet)
    fprintf(stderr, "whirl sfd basins: %zu of %zu study points (%zu computed, %zu from the "
            "checkpoint%s); wrote %s/study.tsv\n", res->hi - res->lo, res->nblocks, res->computed,
            res->chunks ? 0 : res->resumed, res->chunks ? ", chunks joined" : "", res->out);
  return 0;
}

/* The identity: the options' and the points file's bytes. */
static int identity(const sb *S, const char *file, uint64_t *id) {
  FILE *f = fopen(file, "rb");
  if (!f) return -1;
  uint64_t h = sfd_basins_id(S);
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) h = blocks_hash(h, buf, n);
  fclose(f);
  *id = blocks_hash(h, "study", 5);
  return 0;
}

static void describe(study *T, const char *dir) {
  size_t pos = (size_t)snprintf(T->header, sizeof T->header, "point");
  for (size_t a = 0; a < T->P.ncols; a++)
    pos += (size_t)snprintf(T->header + pos, sizeof T->header - pos, "\t%s", pname[T->par[a]]);
  pos += (size_t)snprintf(T->header + pos, sizeof T->header - pos, "\tstatus\tstates");
  for (size_t k = 0; k < NCLASS; k++)
    pos += (size_t)snprintf(T->header + pos, sizeof T->header - pos, "\t%s", klass[k]);
  snprintf(T->header + pos, sizeof T->header - pos, "\n");
  blocks_def *d = &T->d;
  d->cmd = CMD, d->progress = "whirl sfd basins study", d->file = "study.tsv", d->out = dir;
  d->rows = T->P.nrows, d->block = 1, d->header = T->header, d->ctx = T;
  d->compute = compute, d->finish = finish;
}

int sfd_basins_study(const sb *S, const char *file, const char *dir, size_t ci, size_t cn,
                     size_t merge, int rank, int nranks) {
  study T;
  memset(&T, 0, sizeof T);
  T.base = S;
  char msg[1200];
  const int rc = whirl_points_read(file, NNAMES, check_name, &T, &T.P, msg, sizeof msg);
  if (rc != WHIRL_OK) {
    cli_error(CMD, "--study %s", msg);
    return rc == WHIRL_ENOMEM ? 1 : 2;
  }
  int has_omega = 0;
  for (size_t a = 0; a < T.P.ncols; a++) has_omega |= T.par[a] == WHIRL_SFD_OMEGA;
  int status = 0;
  if (!has_omega && isnan(S->p[WHIRL_SFD_OMEGA])) {
    cli_error(CMD, "--study %s: no omega column, and no --omega", file);
    status = 2;
  }
  describe(&T, dir);
  if (!status && identity(S, file, &T.d.id)) status = 1;
  if (!status) status = merge ? (rank == 0 ? blocks_merge(&T.d, merge) : 0)
                              : blocks_run(&T.d, ci, cn, S->quiet, rank, nranks);
  whirl_points_free(&T.P);
  return status;
}

/* lib/run/run_study.c — a parameter study (STUDY = {name: [values], ...},
 * doc/parameter-studies.md): the run file's analysis — its continuation,
 * special points and discovery — at every point of a grid of parameter
 * values (the first name varies slowest), one row of study.tsv a point:
 *
 *   point  <the grid's parameters>  status  branches  isolated  closed
 *   LP  BP  HB  PD  TR  UZ
 *
 * status: ok; failed (a branch ended in failure, its points kept); error
 * (the computation failed); invalid (the parameters are outside the
 * model's domain).  Each point is an independent run of the same run file
 * in memory (its files go nowhere), so a row depends on its point alone:
 * rows computed in any order, by any number of processes, are the same
 * bytes (the command distributes them: drivers/run_study.c).
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_impl.h"

/* The grid's axes: runs of equal references in STUDY. */
int run_study_resolve(run_ctx *R) {
  const whirl_run_settings *s = R->s;
  if (s->points[0]) return R->in_study ? 0 : run_points_load(R, s->points);
  R->study_naxes = 0;
  R->study_npoints = s->nstudy ? 1 : 0;
  for (size_t i = 0; i < s->nstudy; i++) {
    const int k = run_par_index(R, &s->study[i].ref);
    if (k < 0) {
      run_fail(R, WHIRL_RK_STUDY, "STUDY: '%s' is not a parameter of model '%s'",
               s->study[i].ref.index ? "(index)" : s->study[i].ref.name, R->prob.name);
      return -1;
    }
    if (k == R->icp[0]) {
      run_fail(R, WHIRL_RK_STUDY, "STUDY: '%s' is the continuation parameter (ICP); "
               "a study varies the others", R->pnames[k]);
      return -1;
    }
    size_t a = R->study_naxes;
    if (a == 0 || R->study_par[a - 1] != k) {
      for (size_t b = 0; b < a; b++)
        if (R->study_par[b] == k) {
          run_fail(R, WHIRL_RK_STUDY, "STUDY: '%s' given twice", R->pnames[k]);
          return -1;
        }
      R->study_par[a] = k;
      R->study_first[a] = i;
      R->study_nval[a] = 0;
      R->study_naxes = ++a;
    }
    R->study_nval[a - 1]++;
  }
  for (size_t a = 0; a < R->study_naxes; a++) R->study_npoints *= R->study_nval[a];
  return 0;
}

static int is_study(const whirl_run *r) {
  return r && r->s && !r->in_study && r->study_npoints > 0;
}
static int is_basins(const whirl_run *r) {
  return r && r->s && !r->in_study && r->s->ips == WHIRL_IPS_BASINS;
}

/* Append to buf[len] at *pos; -1 when it does not fit. */
static int put(char *buf, size_t len, size_t *pos, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  int m = vsnprintf(buf + *pos, len - *pos, fmt, ap);
  va_end(ap);
  if (m < 0 || (size_t)m >= len - *pos) return -1;
  *pos += (size_t)m;
  return 0;
}

static int study_header(const whirl_run *R, char *buf, size_t len) {
  size_t pos = 0;
  if (put(buf, len, &pos, "point")) return WHIRL_EINVAL;
  for (size_t a = 0; a < R->study_naxes; a++)
    if (put(buf, len, &pos, "\t%s", R->pnames[R->study_par[a]])) return WHIRL_EINVAL;
  return put(buf, len, &pos, "\tstatus\tbranches\tisolated\tclosed\tLP\tBP\tHB\tPD\tTR\tUZ")
             ? WHIRL_EINVAL : WHIRL_OK;
}

/* The point's child run: messages go to the parent's, prefixed; files to
 * /dev/null. */
typedef struct point_ctx {
  run_ctx *R;
  size_t i;
} point_ctx;

static void point_message(const char *line, void *ctx) {
  point_ctx *pc = ctx;
  char msg[4600];
  snprintf(msg, sizeof msg, "study point %zu: %s", pc->i, line);
  if (pc->R->io.message) pc->R->io.message(msg, pc->R->io.ctx);
}
static FILE *point_open(const char *name, void *ctx) {
  (void)name;
  (void)ctx;
  return fopen("/dev/null", "w");
}
static int point_close(FILE *f, const char *name, void *ctx) {
  (void)name;
  (void)ctx;
  return fclose(f) ? -1 : 0;
}

/* The point's values: its row of POINTS, or index i in mixed radix, the
 * last axis fastest. */
static void point_values(const run_ctx *R, size_t i, double *v) {
  if (R->points) {
    memcpy(v, R->points + i * R->study_naxes, R->study_naxes * sizeof *v);
    return;
  }
  for (size_t a = R->study_naxes; a-- > 0;) {
    const size_t m = R->study_nval[a];
    v[a] = R->s->study[R->study_first[a] + i % m].value;
    i /= m;
  }
}

/* Run point i: 0 ok, 1 failed branch, 2 invalid parameters, 3 error. */
static int run_point(run_ctx *R, size_t i, const double *v, whirl_run **out) {
  point_ctx pc = {R, i};
  const whirl_run_io io = {point_message, NULL, point_open, point_close, NULL, &pc};
  whirl_run *c = whirl_run_alloc(R->registry, &io);
  *out = c;
  if (!c) return 3;
  c->in_study = 1;
  if (whirl_run_load(c, R->file, (const char *const *)R->overrides, R->noverrides)) return 3;
  for (size_t a = 0; a < R->study_naxes; a++) c->par[R->study_par[a]] = v[a];
  char why[256];
  if (whirl_model_check_params(c->model, c->par, why, sizeof why) != WHIRL_OK) {
    point_message(why, &pc);
    return 2;
  }
  const int rc = whirl_run_execute(c);
  return rc == 2 ? 2 : rc ? 3 : whirl_run_failed(c) ? 1 : 0;
}

static int study_row(whirl_run *R, size_t i, char *buf, size_t len) {
  double v[WHIRL_RUN_MAXITEMS];
  point_values(R, i, v);
  whirl_run *c = NULL;
  static const char *const status[] = {"ok", "failed", "invalid", "error"};
  const int st = run_point(R, i, v, &c);
  size_t counts[6] = {0};
  static const char *const ty[6] = {"LP", "BP", "HB", "PD", "TR", "UZ"};
  for (size_t k = 0; c && st < 2 && k < c->nspecial; k++)
    for (int t = 0; t < 6; t++)
      if (!strcmp(c->special[k].ty, ty[t])) counts[t]++;
  size_t pos = 0;
  int bad = put(buf, len, &pos, "%zu", i);
  for (size_t a = 0; !bad && a < R->study_naxes; a++) bad = put(buf, len, &pos, "\t%.10g", v[a]);
  if (!bad)
    bad = put(buf, len, &pos, "\t%s\t%zu\t%zu\t%zu", status[st], st < 2 ? c->curves : 0,
              st < 2 ? c->isolated : 0, st < 2 ? c->closed : 0);
  for (int t = 0; !bad && t < 6; t++) bad = put(buf, len, &pos, "\t%zu", counts[t]);
  whirl_run_free(c);
  return bad ? WHIRL_EINVAL : WHIRL_OK;
}

/* whirl_run_execute of a study, one process: study.tsv and run.log. */
int run_study(run_ctx *R) {
  char line[4096];
  FILE *f = run_open(R, "study.tsv");
  if (!f) return -1;
  int rc = study_header(R, line, sizeof line);
  if (!rc) fprintf(f, "%s\n", line);
  for (size_t i = 0; !rc && i < R->study_npoints; i++) {
    if (R->io.progress) R->io.progress(i, R->study_npoints, R->io.ctx);
    rc = study_row(R, i, line, sizeof line);
    if (!rc) fprintf(f, "%s\n", line);
  }
  fprintf(R->log, "parameter study: %zu points\n", R->study_npoints);
  return run_close(R, f, "study.tsv") || rc ? -1 : 0;
}

/* ---- the rows of a table computed in blocks (whirl/run.h) ----------------- */

size_t whirl_run_rows(const whirl_run *r) {
  if (is_study(r)) return r->study_npoints;
  if (is_basins(r)) return (size_t)r->s->grid[0] * (size_t)r->s->grid[1];
  return 0;
}

size_t whirl_run_rows_block(const whirl_run *r) {
  return is_basins(r) ? (size_t)r->s->grid[0] : is_study(r) ? 1 : 0;
}

const char *whirl_run_points_file(const whirl_run *r) {
  return r && r->s ? r->s->points : "";
}

const char *whirl_run_rows_file(const whirl_run *r) {
  return is_basins(r) ? "basins.tsv" : is_study(r) ? "study.tsv" : NULL;
}

int whirl_run_rows_prepare(whirl_run *r) {
  if (!whirl_run_rows(r)) return WHIRL_EINVAL;
  if (!is_basins(r)) return 0;
  int rc = run_basins_setup(r);
  if (!rc) rc = run_basins_atlas_begin(r);
  return rc == -2 ? 2 : rc ? 1 : 0;
}

size_t whirl_run_rows_stages(const whirl_run *r) { return is_basins(r) ? run_basins_rounds(r) : 0; }

size_t whirl_run_rows_stage_blocks(const whirl_run *r, size_t s) {
  return is_basins(r) ? run_basins_round_blocks(r, s) : 0;
}

int whirl_run_rows_stage_compute(whirl_run *r, size_t s, size_t b, char **out, size_t *len) {
  void *part = NULL;
  *out = NULL;
  if (!is_basins(r) || run_basins_round_compute(r, s, b, &part, len)) return WHIRL_EINVAL;
  *out = part;
  return WHIRL_OK;
}

int whirl_run_rows_stage_enter(whirl_run *r, size_t s, char *const *parts, const size_t *lens,
                               size_t n) {
  return is_basins(r) && !run_basins_round_enter(r, s, (const void *const *)parts, lens, n)
             ? WHIRL_OK : WHIRL_EINVAL;
}

int whirl_run_rows_header(const whirl_run *r, char *buf, size_t len) {
  if (is_study(r)) return study_header(r, buf, len);
  if (is_basins(r) && r->bjob) return run_basins_header(r, buf, len) ? WHIRL_EINVAL : WHIRL_OK;
  return WHIRL_EINVAL;
}

/* A basins block: one grid line, classified together (OpenMP inside). */
static int basins_block(whirl_run *R, size_t b, char **out) {
  const size_t B = run_basins_line(R), first = b * B;
  int *which = malloc(B * sizeof *which);
  unsigned *periods = malloc(B * sizeof *periods);
  char *text = malloc(B * 96 + 1);
  whirl_basins_stats st;
  int rc = which && periods && text ? run_basins_classify(R, first, B, which, periods, &st) : -1;
  size_t pos = 0;
  for (size_t q = 0; !rc && q < B; q++) {
    if (q) text[pos++] = '\n';
    rc = run_basins_row(R, first + q, which[q], periods[q], text + pos, 96);
    pos += strlen(text + pos);
  }
  free(which);
  free(periods);
  if (rc) {
    free(text);
    return WHIRL_EINVAL;
  }
  *out = text;
  return WHIRL_OK;
}

int whirl_run_rows_compute(whirl_run *r, size_t block, char **out) {
  *out = NULL;
  const size_t B = whirl_run_rows_block(r);
  if (!B || block >= whirl_run_rows(r) / B) return WHIRL_EINVAL;
  if (is_basins(r)) return r->bjob ? basins_block(r, block, out) : WHIRL_EINVAL;
  char row[4096];
  int rc = study_row(r, block, row, sizeof row);
  if (!rc && !(*out = strdup(row))) rc = WHIRL_ENOMEM;
  return rc;
}

int whirl_run_rows_finish(whirl_run *r, const char *const *blocks, size_t nblocks) {
  if (!is_basins(r)) return is_study(r) ? WHIRL_OK : WHIRL_EINVAL;
  const size_t np = whirl_run_rows(r);
  int *cls = malloc(np * sizeof *cls);
  if (!cls) return WHIRL_ENOMEM;
  size_t q = 0;
  for (size_t b = 0; b < nblocks; b++)
    for (const char *c = blocks[b]; c && *c && q < np;) {
      const char *t = strchr(c, '\t');
      t = t ? strchr(t + 1, '\t') : NULL;
      cls[q++] = t ? atoi(t + 1) : -3;
      c = strchr(c, '\n');
      c = c ? c + 1 : NULL;
    }
  if (q == np) run_basins_summary(r, cls, np);
  free(cls);
  return q == np ? WHIRL_OK : WHIRL_EINVAL;
}

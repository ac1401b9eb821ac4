/* drivers/cmd_sfd_basins.c — `whirl sfd basins`: basins of attraction of the
 * SFD rotor at one speed (paper §5.3, Figs. 12–17).  Initial displacements
 * evenly spread in 98 % of the clearance with zero or circular-orbit
 * velocities, or taken from a quasiperiodic trajectory; each trajectory is
 * integrated until it provably settles on one of the attractors found at
 * that speed (whirl/rotor/sfd_dynamics.h), in parallel (OpenMP threads,
 * and MPI processes under mpirun): a table in blocks (blocks.h), so also
 * resumable and in chunks for job arrays.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "blocks.h"
#include "cli.h"
#include "sfd_basins.h"
#include "sfd_common.h"

static const cli_doc doc = {
"usage: whirl sfd basins --omega W [options]\n"
"\n"
"Basins of attraction at speed W.  The attractors are found first: the\n"
"stable circular orbits of eq. 15 (named small/large, or circular when\n"
"there is one), each with a certified Lyapunov neighbourhood in the\n"
"rotating frame, and the nonsynchronous (quasiperiodic) response if a\n"
"trajectory settles on one.  Every initial state is then integrated until\n"
"it enters one of those neighbourhoods (or --periods have passed), or --\n"
"an atlas of classified cells (--seeds) -- until it has passed --cell-hits\n"
"consecutive periods in cells that trajectories of one attractor alone\n"
"went through.\n"
"\n"
"options (defaults: Table 1 of the paper):\n",
"stdout: TSV 'attractor count percent'.  DIR/basins.tsv: y0 z0 vy0 vz0\n"
"attractor periods; DIR/attractors.tsv; DIR/basins.png (red small orbit,\n"
"green large, blue quasiperiodic, black contact, grey unsettled).\n"};

static const char *colour_of(const char *name) {
  if (!strcmp(name, "small") || !strcmp(name, "circular")) return "#d62728";
  if (!strcmp(name, "large")) return "#2ca02c";
  if (!strcmp(name, "quasiperiodic")) return "#1f3fbf";
  if (!strcmp(name, "contact")) return "#000000";
  if (!strcmp(name, "middle")) return "#ff7f0e";
  return "#999999";
}

/* basins.gp: the initial states coloured by the class they end in, only
 * the classes that occur (so the key says what is drawn). */
static int write_script(cli_outdir *od, const whirl_sfd_attractors *A, size_t na,
                        const size_t *cnt, size_t ncontact, size_t nunset, size_t nfail,
                        size_t n, double Om, const char *vel) {
  out_file g;
  if (out_open(&g, od, "basins.gp")) return -1;
  FILE *f = g.fp;
  cli_gp_preamble(f, CMD, "basins", 900, 900, "Sans,12");
  fprintf(f, "set title 'basins of attraction, {/Symbol W} = %g, %s initial velocities'\n"
             "set size ratio -1\nset xrange [-1.05:1.05]\nset yrange [-1.05:1.05]\n"
             "set xlabel 'y_0'\nset ylabel 'z_0'\nset key outside right top box opaque\n"
             "set object 1 circle at 0,0 size 1 fs empty border lc rgb 'black' lw 2\n",
          Om, vel);
  const char *names[WHIRL_BASINS_MAX_ATTRACTORS + 3]; /* and the 3 outcomes */
  size_t nn = 0;
  /* only the classes that occur, so the key says what is drawn */
  for (size_t j = 0; j < na; ++j)
    if (cnt[j]) names[nn++] = whirl_sfd_attractors_info(A, j)->name;
  if (ncontact) names[nn++] = "contact";
  if (nunset) names[nn++] = "unsettled";
  if (nfail) names[nn++] = "failed";
  double ps = n > 20000 ? 0.25 : n > 4000 ? 0.45 : 0.8;
  fprintf(f, "plot ");
  for (size_t j = 0; j < nn; ++j)
    fprintf(f, "%s'basins.tsv' using ((strcol(5) eq '%s') ? $1 : 1/0):2 with points pt 7 ps %g "
               "lc rgb '%s' title '%s'", j ? ", \\\n  " : "", names[j], ps, colour_of(names[j]), names[j]);
  fprintf(f, "\n");
  return out_commit(&g);
}

/* ---- the basins as a table in blocks (blocks.h) -------------------------
 * Stages: the atlas's rounds (a block: a few of a round's seeds, classified
 * and recorded), taken in by every process; then the table, a block a run
 * of consecutive initial states classified with the whole atlas.  A table
 * block is its rows, then '\0' and "steps rhs_evals by_atlas" of it. */

enum { TABLE_BLOCKS = 128, TABLE_BLOCK_MAX = 128, ROUND_BLOCKS = 128 };

const char *sfd_basins_class(const sb *S, int w) {
  return w >= 0 ? whirl_sfd_attractors_info(S->A, (size_t)w)->name
         : w == WHIRL_BASIN_DOMAIN ? "contact" : w == WHIRL_BASIN_UNSETTLED ? "unsettled" : "failed";
}

/* Table blocks b0 .. b0 + nb − 1: their states classified together, each
 * block its rows, then the trailer (the statistics: all on the first). */
static int table_run(sb *S, size_t b0, size_t nb, char **data, size_t *len) {
  const size_t B = S->d.block, first = b0 * B;
  const size_t m = S->n - first < nb * B ? S->n - first : nb * B;
  int *which = malloc((m + 1) * sizeof *which);
  unsigned *per = malloc((m + 1) * sizeof *per);
  char msg[512];
  whirl_basins_options o = S->bo;
  o.atlas = S->atlas;
  o.first = first;
  whirl_basins_stats st;
  int rc = which && per ? WHIRL_OK : WHIRL_ENOMEM;
  if (rc == WHIRL_OK)
    rc = whirl_basins_compute(whirl_sfd_fixed(), S->p, m, S->X + 4 * first,
                              whirl_sfd_attractors_list(S->A), S->na, &o, which, per, &st, msg,
                              sizeof msg);
  for (size_t k = 0; rc == WHIRL_OK && k < nb; ++k) {
    const size_t i0 = k * B, i1 = (k + 1) * B < m ? (k + 1) * B : m;
    char *text = malloc((i1 - i0) * 128 + 96);
    if (!(data[k] = text)) {
      rc = WHIRL_ENOMEM;
      break;
    }
    size_t pos = 0;
    for (size_t i = i0; i < i1; ++i) {
      const double *x = S->X + 4 * (first + i);
      pos += (size_t)sprintf(text + pos, "%s%.10g\t%.10g\t%.10g\t%.10g\t%s\t%u", i > i0 ? "\n" : "",
                             x[0], x[1], x[2], x[3], sfd_basins_class(S, which[i]), per[i]);
    }
    text[pos++] = '\0';
    pos += (size_t)sprintf(text + pos, "%zu %zu %zu", k ? 0 : st.steps, k ? 0 : st.rhs_evals,
                           k ? 0 : st.by_atlas);
    len[k] = pos;
  }
  free(which);
  free(per);
  if (rc != WHIRL_OK) {
    for (size_t k = 0; k < nb; ++k) free(data[k]), data[k] = NULL;
    cli_error(CMD, "%s", rc == WHIRL_ENOMEM ? "out of memory" : msg);
    return 1;
  }
  return 0;
}

/* Blocks b0 .. b0 + nb − 1 of atlas round s: their seeds classified
 * together, the bytes all in data[0] (the round is taken in whole). */
static int round_run(sb *S, size_t s, size_t b0, size_t nb, char **data, size_t *len) {
  const size_t m = whirl_basins_atlas_round_seeds(S->atlas, s), j0 = b0 * S->per[s];
  const size_t count = m - j0 < nb * S->per[s] ? m - j0 : nb * S->per[s];
  void *part = NULL;
  int rc = whirl_basins_atlas_classify(S->atlas, s, j0, count, &part, &len[0]);
  data[0] = part;
  for (size_t k = 1; rc == WHIRL_OK && k < nb; ++k)
    if ((data[k] = malloc(1))) len[k] = 0;
    else rc = WHIRL_ENOMEM;
  if (rc != WHIRL_OK) {
    for (size_t k = 0; k < nb; ++k) free(data[k]), data[k] = NULL;
    cli_error(CMD, "basins atlas, round %zu: %s", s + 1, whirl_strerror(rc));
    return 1;
  }
  return 0;
}

static int compute_run(void *ctx, size_t s, size_t b0, size_t nb, char **data, size_t *len) {
  sb *S = ctx;
  return s == S->d.nstages ? table_run(S, b0, nb, data, len) : round_run(S, s, b0, nb, data, len);
}

static int compute(void *ctx, size_t s, size_t b, char **data, size_t *len) {
  return compute_run(ctx, s, b, 1, data, len);
}

static int absorb(void *ctx, size_t s, char *const *data, const size_t *len, size_t nb) {
  sb *S = ctx;
  int rc = whirl_basins_atlas_enter(S->atlas, s, (const void *const *)data, len, nb);
  if (rc != WHIRL_OK) cli_error(CMD, "basins atlas, round %zu: %s", s + 1, whirl_strerror(rc));
  return rc != WHIRL_OK;
}

typedef struct tally {
  size_t cnt[WHIRL_BASINS_MAX_ATTRACTORS], ncontact, nunset, nfail;
  size_t periods, steps, rhs, by_atlas;
  int stats;  /* steps, RHS and atlas counts known (every block's trailer) */
} tally;

/* One row "y z vy vz NAME PERIODS" counted. */
static void count_row(const sb *S, const char *row, tally *T) {
  const char *c = row;
  for (int k = 0; k < 4 && c; ++k) c = strchr(c, '\t'), c = c ? c + 1 : NULL;
  if (!c) return;
  const char *e = strchr(c, '\t');
  const size_t L = e ? (size_t)(e - c) : strlen(c);
  size_t j = 0;
  while (j < S->na && !(strlen(sfd_basins_class(S, (int)j)) == L && !strncmp(sfd_basins_class(S, (int)j), c, L))) ++j;
  if (j < S->na) ++T->cnt[j];
  else if (!strncmp(c, "contact", L)) ++T->ncontact;
  else if (!strncmp(c, "unsettled", L)) ++T->nunset;
  else ++T->nfail;
  if (e) T->periods += strtoull(e + 1, NULL, 10);
}

static void count_all(const sb *S, const blocks_result *res, tally *T) {
  memset(T, 0, sizeof *T);
  T->stats = 1;
  for (size_t b = 0; b < res->hi - res->lo; ++b) {
    const char *blk = res->blk[b];
    for (const char *c = blk; c && *c;) {
      count_row(S, c, T);
      c = strchr(c, '\n');
      c = c ? c + 1 : NULL;
    }
    const size_t rl = strlen(blk);
    size_t st[3];
    if (rl < res->len[b] && sscanf(blk + rl + 1, "%zu %zu %zu", &st[0], &st[1], &st[2]) == 3)
      T->steps += st[0], T->rhs += st[1], T->by_atlas += st[2];
    else
      T->stats = 0;
  }
}

static int write_attractors(cli_outdir *od, const sb *S) {
  out_file fa;
  if (out_open(&fa, od, "attractors.tsv")) return 1;
  fprintf(fa.fp, "attractor\tclass\teps_max\teps_min\trate\tlevel\n");
  for (size_t j = 0; j < S->na; ++j) {
    const whirl_sfd_attractor_info *in = whirl_sfd_attractors_info(S->A, j);
    fprintf(fa.fp, "%s\t%s\t%.12g\t%.12g\t%.6g\t%.6g\n", in->name,
            in->kind == WHIRL_SFD_CIRCULAR ? "circular" : "quasiperiodic", in->eps, in->eps_min,
            in->rate, in->level);
  }
  return out_commit(&fa) != 0;
}

static void print_shares(const sb *S, const tally *T) {
  const double n = (double)S->n;
  printf("attractor\tcount\tpercent\n");
  for (size_t j = 0; j < S->na; ++j)
    printf("%s\t%zu\t%.2f\n", sfd_basins_class(S, (int)j), T->cnt[j], 100.0 * (double)T->cnt[j] / n);
  if (T->ncontact) printf("contact\t%zu\t%.2f\n", T->ncontact, 100.0 * (double)T->ncontact / n);
  if (T->nunset) printf("unsettled\t%zu\t%.2f\n", T->nunset, 100.0 * (double)T->nunset / n);
  if (T->nfail) printf("failed\t%zu\t%.2f\n", T->nfail, 100.0 * (double)T->nfail / n);
}

/* The summary on stderr: the attractors, the times and the work. */
static void report(const sb *S, const tally *T, const blocks_result *res) {
  fprintf(stderr, "whirl sfd basins: Omega = %g, %zu initial states (%s velocities), %zu attractor%s:\n",
          S->p[WHIRL_SFD_OMEGA], S->n, S->vel, S->na, S->na == 1 ? "" : "s");
  for (size_t j = 0; j < S->na; ++j) {
    const whirl_sfd_attractor_info *in = whirl_sfd_attractors_info(S->A, j);
    if (in->kind == WHIRL_SFD_CIRCULAR)
      fprintf(stderr, "  %-13s circular orbit eps = %.10g, Re mu = %.4g, certified level %.3g\n",
              in->name, in->eps, in->rate, in->level);
    else
      fprintf(stderr, "  %-13s limit cycle of the rotating frame, eps in [%.4g, %.4g], tolerance %.3g\n",
              in->name, in->eps_min, in->eps, in->level);
  }
  if (res->chunks) {
    fprintf(stderr, "  joined from %zu chunks; %zu periods (%.1f per point)\n", res->chunks,
            T->periods, (double)T->periods / (double)S->n);
    return;
  }
  char thr[64];
  if (S->threads > 0) snprintf(thr, sizeof thr, "%d thread%s", S->threads, S->threads == 1 ? "" : "s");
  else snprintf(thr, sizeof thr, "all threads");
  if (res->nranks > 1) {
    const size_t l = strlen(thr);
    snprintf(thr + l, sizeof thr - l, " on each of %d processes", res->nranks);
  }
  fprintf(stderr, "  attractors %.2f s; basins %.2f s on %s; %zu periods (%.1f per point)", S->t_att,
          cli_now() - S->t_start - S->t_att, thr, T->periods, (double)T->periods / (double)S->n);
  if (T->stats)
    fprintf(stderr, ", %zu steps, %zu RHS evaluations; %zu points by the atlas", T->steps, T->rhs,
            T->by_atlas);
  if (res->resumed) fprintf(stderr, "; %zu of %zu blocks from the checkpoint", res->resumed, res->hi - res->lo);
  fputc('\n', stderr);
}

static int finish(void *ctx, cli_outdir *od, const blocks_result *res) {
  sb *S = ctx;
  tally T;
  count_all(S, res, &T);
  if (!res->whole) { /* a chunk: its rows only */
    int rc = cli_outdir_commit(od);
    if (!rc && !S->quiet)
      fprintf(stderr, "whirl sfd basins: blocks %zu to %zu of %zu (%zu computed, %zu from the "
              "checkpoint); wrote %s/basins.tsv\n", res->lo + 1, res->hi, res->nblocks,
              res->computed, res->resumed, res->out);
    return rc;
  }
  int bad = write_attractors(od, S);
  print_shares(S, &T);
  if (!bad && !S->noplot)
    bad = write_script(od, S->A, S->na, T.cnt, T.ncontact, T.nunset, T.nfail, S->n,
                       S->p[WHIRL_SFD_OMEGA], S->vel);
  static const char *const pics[] = {"basins", NULL};
  const int status = cli_outdir_finish(od, bad, S->noplot ? NULL : pics);
  if (!S->quiet) report(S, &T, res);
  return status;
}

/* ---- the command --------------------------------------------------------- */

/* The options into S, checked: 0, 1 (help shown) or 2 (said). */
static int parse(sb *S, int argc, char **argv, const char **dir, const char **chunk, size_t *merge,
                 const char **study) {
  whirl_sfd_default_params(S->p);
  S->p[WHIRL_SFD_OMEGA] = NAN;
  S->npoints = 8000, S->periods = 500, S->seeds = 4, S->levels = 4, S->cells = 32, S->hits = 4;
  S->phases = 8, S->radius = 0.98, S->rtol = 1e-12, S->atol = 1e-15, S->vel = "zero";
  S->method_name = "dop853";
  double *p = S->p;
  const cli_opt opts[] = {
      SFD_OPT_OMEGA(p),
      {"--velocities", CLI_STRING, &S->vel, "V",
       "initial velocities\n"
       "zero: y' = z' = 0 (Figs. 12, 13a, 14a);\n"
       "circular: (y', z') = Omega (-z, y), the velocity of a circular orbit through (y, z) "
       "(Figs. 13b, 14b, 15b);\n"
       "trajectory: displacements sampled from the trajectory from rest over periods "
       "600..1200, zero velocities (Figs. 15a-17)", NULL},
      {"--points", CLI_SIZE, &S->npoints, "N", "about N initial states", NULL},
      {"--radius", CLI_DOUBLE, &S->radius, "R", "displacements within R of the clearance", NULL},
      {"--periods", CLI_SIZE, &S->periods, "P", "most forcing periods per trajectory", NULL},
      {"--fixed-horizon", CLI_FLAG, &S->fixed, NULL,
       "always integrate P periods, classify at the end", NULL},
      {"--seeds", CLI_SIZE, &S->seeds, "K",
       "atlas of classified cells: every K-th initial state is classified first and its "
       "trajectory's cells keep its class; 0: no atlas, every state integrated until a "
       "certified capture (doc/sfd-time-domain.md)", NULL},
      {"--levels", CLI_SIZE, &S->levels, "L",
       "those states in L rounds (1..8) of strides K*4^(L-1), ..., 4K, K, each round "
       "using the cells of the rounds before", NULL},
      {"--cells", CLI_SIZE, &S->cells, "N", "atlas cells: N intervals per coordinate", NULL},
      {"--cell-hits", CLI_SIZE, &S->hits, "H",
       "consecutive section points in cells of one attractor that classify a state", NULL},
      {"--phases", CLI_SIZE, &S->phases, "M", "atlas section points a forcing period (1..64)", NULL},
      {"--threads", CLI_INT, &S->threads, "T", "OpenMP threads, 0..1024; 0: as many as OpenMP offers", NULL},
      {"--chunk", CLI_STRING, chunk, "PART",
       "PART = I/N: the I-th of N parts of the states (each with the whole atlas) into DIR.chunk-I-of-N/, "
       "for job arrays (doc/parameter-studies.md)", ""},
      {"--merge-chunks", CLI_SIZE, merge, "N", "join DIR.chunk-1-of-N ... DIR.chunk-N-of-N into DIR", ""},
      {"--study", CLI_STRING, study, "FILE",
       "basin fractions at each point of FILE, a TSV: a header of parameter names (omega, "
       "lambda, delta, zeta), a row of values a point; the options give the rest: "
       "DIR/study.tsv, a row a point (doc/parameter-studies.md)", ""},
      SFD_OPTS_MODEL(p),
      SFD_OPTS_TOL(S->rtol, S->atol),
      {"--method", CLI_STRING, &S->method_name, "M",
       "integration method: dop853 (explicit, order 8: 3-6 times fewer evaluations at "
       "rtol 1e-12) or dopri5 (explicit, order 5)", NULL},
      CLI_OPTS_OUT(*dir, S->noplot, S->quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 1 : 2;
  double q[WHIRL_SFD_NPAR];
  memcpy(q, p, sizeof q);
  if (*study && isnan(q[WHIRL_SFD_OMEGA])) q[WHIRL_SFD_OMEGA] = 1; /* may be the file's */
  if (sfd_check(CMD, q, 1)) return 2;
  const char *vel = S->vel;
  S->vmode = !strcmp(vel, "zero") ? 0 : !strcmp(vel, "circular") ? 1 : !strcmp(vel, "trajectory") ? 2 : -1;
  if (S->vmode < 0) {
    cli_error(CMD, "--velocities must be zero, circular or trajectory (got '%s')", vel);
    return 2;
  }
  if (S->npoints < 1 || S->npoints > 10000000) {
    cli_error(CMD, "--points must be in [1, 1e7] (got %zu)", S->npoints);
    return 2;
  }
  if (!(S->radius > 0 && S->radius < 1)) {
    cli_error(CMD, "--radius must be in (0, 1): a fraction of the clearance (got %g)", S->radius);
    return 2;
  }
  if (S->periods < 1) {
    cli_error(CMD, "--periods must be >= 1");
    return 2;
  }
  if (S->phases < 1 || S->phases > 64) {
    cli_error(CMD, "--phases must be in 1..64 (got %zu)", S->phases);
    return 2;
  }
  if (S->levels < 1 || S->levels > 8 || S->cells < 1 || S->cells > 1000000 || S->hits < 1 ||
      S->hits > S->periods) {
    cli_error(CMD, "need 1 <= --levels <= 8, 1 <= --cells <= 1e6, 1 <= --cell-hits <= --periods "
              "(got %zu, %zu, %zu)", S->levels, S->cells, S->hits);
    return 2;
  }
  if (S->threads < 0 || S->threads > WHIRL_BASINS_MAX_THREADS) {
    cli_error(CMD, "--threads must be in 0..%d (got %d)", WHIRL_BASINS_MAX_THREADS, S->threads);
    return 2;
  }
  if (strcmp(S->method_name, "dopri5") != 0 && strcmp(S->method_name, "dop853") != 0) {
    cli_error(CMD, "--method must be dop853 or dopri5 (got '%s')", S->method_name);
    return 2;
  }
  (void)whirl_ode_method_parse(S->method_name, &S->method);
  return sfd_check_tolerances(CMD, S->rtol, S->atol) ? 2 : 0;
}

/* The initial states (S->n of them into S->X): 0, or 1 (said). */
int sfd_basins_states(sb *S, int rows_only) {
  const double Om = S->p[WHIRL_SFD_OMEGA];
  char msg[512];
  if (S->vmode == 2) {
    S->n = S->npoints;
    if (rows_only) return 0;
    if (!(S->X = malloc(4 * S->n * sizeof *S->X))) return cli_error(CMD, "out of memory"), 1;
    if (whirl_sfd_trajectory_samples(S->p, NULL, 600, 600, S->n, S->rtol, S->atol, S->X, msg,
                                     sizeof msg) != WHIRL_OK) {
      cli_error(CMD, "--velocities trajectory: %s", msg);
      return 1;
    }
    for (size_t i = 0; i < S->n; ++i) S->X[4 * i + 2] = S->X[4 * i + 3] = 0;
    return 0;
  }
  const size_t n = S->n = whirl_sfd_disc_points(S->npoints, S->radius, NULL, 0);
  if (rows_only) return 0;
  S->X = malloc(4 * (n ? n : 1) * sizeof *S->X);
  double *yz = malloc(2 * (n ? n : 1) * sizeof *yz);
  if (!S->X || !yz) {
    free(yz);
    cli_error(CMD, "out of memory");
    return 1;
  }
  whirl_sfd_disc_points(S->npoints, S->radius, yz, n);
  for (size_t i = 0; i < n; ++i) {
    double *x = S->X + 4 * i;
    x[0] = yz[2 * i], x[1] = yz[2 * i + 1], x[2] = x[3] = 0;
    if (S->vmode == 1) whirl_sfd_circular_velocity(Om, x[0], x[1], &x[2], &x[3]);
  }
  free(yz);
  return 0;
}

void sfd_basins_options(sb *S) {
  whirl_basins_options *bo = &S->bo;
  whirl_basins_options_default(bo);
  bo->period = 2 * WHIRL_PI / S->p[WHIRL_SFD_OMEGA];
  bo->max_periods = S->periods;
  bo->fixed_horizon = S->fixed;
  bo->rtol = S->rtol;
  bo->atol = S->atol;
  bo->nthreads = S->threads;
  bo->seed_stride = S->seeds;
  bo->cells = S->cells;
  bo->atlas_levels = S->levels;
  bo->section_phases = S->phases;
  bo->cell_hits = S->hits;
  bo->method = S->method;
}

/* The identity of a run: every option that changes a row (not --threads,
 * --quiet, the output directory). */
uint64_t sfd_basins_id(const sb *S) {
  char id[1024];
  int len = snprintf(id, sizeof id, "sfd basins %s %zu %a %zu %d %zu %zu %zu %zu %zu %a %a %s",
                     S->vel, S->npoints, S->radius, S->periods, S->fixed, S->seeds, S->levels,
                     S->cells, S->hits, S->phases, S->rtol, S->atol, S->method_name);
  for (size_t k = 0; k < WHIRL_SFD_NPAR && len > 0 && (size_t)len < sizeof id; ++k)
    len += snprintf(id + len, sizeof id - (size_t)len, " %a", S->p[k]);
  return blocks_hash(BLOCKS_HASH0, id, strlen(id));
}

/* The table and its stages (the atlas's rounds), and the run's identity: */
static int describe(sb *S, const char *dir, int merging) {
  blocks_def *d = &S->d;
  char msg[512];
  if (!merging && S->seeds && !S->fixed) {
    if (whirl_basins_atlas_begin(whirl_sfd_fixed(), S->p, S->n, S->X, whirl_sfd_attractors_list(S->A),
                                 S->na, &S->bo, &S->atlas, msg, sizeof msg) != WHIRL_OK)
      return cli_error(CMD, "%s", msg), 1;
    d->nstages = whirl_basins_atlas_rounds(S->atlas);
    for (size_t s = 0; s < d->nstages; ++s) {
      const size_t m = whirl_basins_atlas_round_seeds(S->atlas, s), q = (m + ROUND_BLOCKS - 1) / ROUND_BLOCKS;
      S->per[s] = q < 1 ? 1 : q;
      d->stage_blocks[s] = (m + S->per[s] - 1) / S->per[s];
    }
  }
  const size_t q = (S->n + TABLE_BLOCKS - 1) / TABLE_BLOCKS;
  d->block = q < 1 ? 1 : q > TABLE_BLOCK_MAX ? TABLE_BLOCK_MAX : q;
  d->rows = S->n;
  d->cmd = CMD, d->progress = "whirl sfd basins", d->file = "basins.tsv", d->out = dir;
  d->header = S->header, d->ctx = S, d->compute = compute, d->absorb = absorb, d->finish = finish;
  d->compute_run = compute_run;
  const double *p = S->p;
  snprintf(S->header, sizeof S->header,
           "y0\tz0\tvy0\tvz0\tattractor\tperiods\n"
           "# whirl sfd basins: Omega=%.10g lambda=%.10g delta=%.10g zeta=%.10g velocities=%s "
           "periods=%zu%s rtol=%g atol=%g method=%s\n",
           p[WHIRL_SFD_OMEGA], p[1], p[2], p[3], S->vel, S->periods,
           S->fixed ? " (fixed horizon)" : "", S->rtol, S->atol, S->method_name);
  d->id = sfd_basins_id(S);
  return 0;
}

static int basins_ranked(int argc, char **argv, int rank, int nranks) {
  sb S;
  memset(&S, 0, sizeof S);
  const char *dir = "sfd-basins", *chunk = NULL, *study = NULL;
  size_t merge = 0, ci = 0, cn = 0;
  int rc = parse(&S, argc, argv, &dir, &chunk, &merge, &study);
  if (rc) return rc == 1 ? 0 : 2;
  char tail;
  if (chunk && (sscanf(chunk, "%zu/%zu%c", &ci, &cn, &tail) != 2 || cn == 0)) {
    cli_error(CMD, "--chunk %s: write --chunk I/N, the I-th of N parts (1 <= I <= N)", chunk);
    return 2;
  }
  if (chunk && merge) {
    cli_error(CMD, "--chunk and --merge-chunks: one or the other");
    return 2;
  }
  if (rank != 0) S.quiet = 1;
  if (study) return sfd_basins_study(&S, study, dir, ci, cn, merge, rank, nranks);
  if (rank == 0 && !chunk && !merge && (rc = cli_outdir_check(CMD, NULL, dir))) return rc;
  S.t_start = cli_now();
  whirl_sfd_attractors_options ao;
  whirl_sfd_attractors_options_default(&ao);
  ao.rtol = S.rtol;
  ao.atol = S.atol;
  ao.method = S.method;
  char msg[512];
  if (!S.quiet && cli_is_tty())
    fprintf(stderr, "whirl sfd basins: finding the attractors at Omega = %g ...\r", S.p[WHIRL_SFD_OMEGA]);
  if (whirl_sfd_attractors_find(S.p, &ao, &S.A, msg, sizeof msg) != WHIRL_OK) {
    cli_error(CMD, "%s", msg);
    return 1;
  }
  S.t_att = cli_now() - S.t_start;
  S.na = whirl_sfd_attractors_count(S.A);
  sfd_basins_options(&S);
  rc = sfd_basins_states(&S, merge > 0);
  if (!rc) rc = describe(&S, dir, merge > 0);
  if (!rc && merge) rc = rank == 0 ? blocks_merge(&S.d, merge) : 0;
  else if (!rc) rc = blocks_run(&S.d, ci, cn, S.quiet, rank, nranks);
  whirl_basins_atlas_free(S.atlas);
  free(S.X);
  whirl_sfd_attractors_free(S.A);
  return rc;
}

int cmd_sfd_basins(int argc, char **argv) {
  int rank, nranks;
  blocks_processes(&argc, &argv, &rank, &nranks);
  const int status = basins_ranked(argc, argv, rank, nranks);
  blocks_processes_end();
  return status;
}

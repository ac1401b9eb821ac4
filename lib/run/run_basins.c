/* lib/run/run_basins.c — `whirl run` with IPS = basins: basins of
 * attraction of labelled stable solutions of any model, on a grid of start
 * states in two components (BASIN_AXES, BASIN_GRID; the others from U).
 * Each attractor is a labelled solution of an earlier run (S,
 * BASIN_ATTRACTORS): a periodic orbit (collocation or harmonic balance) of a
 * forced model, whose state at the section t = 0 (mod 2π/ω) is the target,
 * or an equilibrium.  A trajectory belongs to an attractor once its section
 * points stay within BASIN_TOL·(1 + |x*|) of the target (max norm) for 3
 * consecutive periods; whirl_basins_compute integrates the grid in parallel
 * and stops each trajectory there (BASIN_PERIODS at most).
 * Writes basins.tsv (axis values, attractor: its label, -1 unsettled,
 * -2 left the domain, -3 failed; periods integrated) and basins.png.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_impl.h"

typedef struct target {
  size_t n;
  double tol;
  double *x;
} target;

static int near_target(double t, const double *x, void *data) {
  (void)t;
  const target *g = data;
  double d = 0.0, s = 0.0;
  for (size_t i = 0; i < g->n; i++) {
    d = fmax(d, fabs(x[i] - g->x[i]));
    s = fmax(s, fabs(g->x[i]));
  }
  return d <= g->tol * (1.0 + s);
}

static void progress(size_t done, size_t total, void *data) {
  const run_ctx *R = data;
  if (R->io.progress) R->io.progress(done, total, R->io.ctx);
}

/* The state at the section t = 0 of a stored solution. */
static int section_state(run_ctx *R, const whirl_solution *so, double *x) {
  char err[256];
  if (so->kind == WHIRL_SOL_EQ) {
    memcpy(x, so->x, R->n * sizeof *x);
    return 0;
  }
  if (so->kind == WHIRL_SOL_COLLOC) {
    whirl_colloc_options co;
    whirl_colloc_options_default(&co);
    co.ntst = (size_t)so->ntst;
    co.ncol = (size_t)so->ncol;
    co.forcing_param = R->model->forcing_param;
    whirl_colloc *c = whirl_colloc_alloc(&R->prob, &co, err, sizeof err);
    if (!c || whirl_colloc_size(c) != so->nx) {
      whirl_colloc_free(c);
      return -1;
    }
    whirl_colloc_set_mesh(c, so->mesh);
    whirl_colloc_eval(c, so->x, 0.0, x);
    whirl_colloc_free(c);
    return 0;
  }
  whirl_hbm_options ho;
  whirl_hbm_options_default(&ho);
  ho.harmonics = (size_t)so->nhb;
  ho.forcing_param = R->model->forcing_param;
  ho.no_spectrum = 1;
  whirl_hbm *h = whirl_hbm_alloc(&R->prob, &ho, err, sizeof err);
  if (!h || whirl_hbm_size(h) != so->nx) {
    whirl_hbm_free(h);
    return -1;
  }
  whirl_hbm_eval(h, so->x, 0.0, x);
  whirl_hbm_free(h);
  return 0;
}

/* Everything the classification of grid points needs, made once. */
struct run_basins_job {
  size_t na, np, g0, g1;
  int ax[2];
  target *tg;
  whirl_attractor *att;
  char (*names)[32];
  double *x0;              /* np start states */
  whirl_basins_options o;
  whirl_basins_atlas *atlas; /* BASIN_SEEDS, built in rounds (the rows' stages) */
  size_t per[8];           /* seeds a block, each round */
  int atlas_ready;         /* its last round entered */
};

void run_basins_job_free(run_basins_job *J) {
  if (!J) return;
  for (size_t a = 0; J->tg && a < J->na; a++) free(J->tg[a].x);
  free(J->tg);
  free(J->att);
  free(J->names);
  free(J->x0);
  whirl_basins_atlas_free(J->atlas);
  free(J);
}

/* The attractors (labelled stable solutions of S, all at one parameter
 * set), the run's parameters taken from them, the grid of start states and
 * the options.  0, -1, -2 (bad input, said). */
static int attractors(run_ctx *R, run_basins_job *J) {
  const whirl_run_settings *s = R->s;
  const size_t n = R->n;
  for (size_t a = 0; a < J->na; a++) {
    whirl_solution so;
    char msg[1024];
    if (run_solution_find(R, R->spath, s->attractors[a], "", &so, msg, sizeof msg)) {
      run_fail(R, WHIRL_RK_BASIN_ATTRACTORS, "BASIN_ATTRACTORS: %s", msg);
      return -2;
    }
    int rc = so.stable != 1 ? -2 : 0;
    if (rc)
      run_fail(R, WHIRL_RK_BASIN_ATTRACTORS, "BASIN_ATTRACTORS: label %d is "
               "not a stable solution (STAB = %d)", so.label, so.stable);
    if (!rc && a == 0) {
      memcpy(R->par, so.par, R->npar * sizeof *R->par);
      for (size_t i = 0; i < s->npar; i++)
        R->par[run_par_index(R, &s->par[i].ref)] = s->par[i].value;
    }
    for (size_t k = 0; !rc && k < R->npar; k++)
      if (fabs(so.par[k] - R->par[k]) > 1e-8 * (1.0 + fabs(R->par[k]))) {
        run_fail(R, WHIRL_RK_BASIN_ATTRACTORS, "BASIN_ATTRACTORS: label %d "
                 "has %s = %.10g, the basins are computed at %.10g (all "
                 "attractors must be at the same parameters: use UZR in the "
                 "continuation run)", so.label, R->pnames[k], so.par[k], R->par[k]);
        rc = -2;
      }
    target *g = &J->tg[a];
    g->n = n;
    g->tol = s->basin_tol;
    if (!rc && (!(g->x = malloc(n * sizeof *g->x)) || section_state(R, &so, g->x))) {
      run_say(R, "label %d: cannot evaluate the solution", so.label);
      rc = -1;
    }
    if (!rc) {
      snprintf(J->names[a], sizeof J->names[a], "LAB %d", so.label);
      J->att[a] = (whirl_attractor){.name = J->names[a], .test = near_target, .data = g, .confirm = 3};
      if (R->log) {
        fprintf(R->log, "attractor %zu: label %d (%s, %s), section state", a + 1, so.label,
                so.ty, so.kind == WHIRL_SOL_EQ ? "equilibrium" : "periodic orbit");
        for (size_t i = 0; i < n; i++) fprintf(R->log, " %.10g", g->x[i]);
        fputc('\n', R->log);
      }
    }
    whirl_solution_free(&so);
    if (rc) return rc;
  }
  return 0;
}

static void grid_states(const run_ctx *R, run_basins_job *J) {
  const whirl_run_settings *s = R->s;
  for (size_t j = 0; j < J->g1; j++)
    for (size_t i = 0; i < J->g0; i++) {
      double *x = J->x0 + (j * J->g0 + i) * R->n;
      memcpy(x, R->u, R->n * sizeof *x);
      x[J->ax[0]] = s->axes[0].lo + (s->axes[0].hi - s->axes[0].lo) * (double)i / (double)(J->g0 - 1);
      x[J->ax[1]] = s->axes[1].lo + (s->axes[1].hi - s->axes[1].lo) * (double)j / (double)(J->g1 - 1);
    }
}

int run_basins_setup(run_ctx *R) {
  if (R->bjob) return 0;
  const whirl_run_settings *s = R->s;
  int ax0 = run_state_index(R, &s->axes[0].ref), ax1 = run_state_index(R, &s->axes[1].ref);
  if (ax0 == ax1) {
    run_fail(R, WHIRL_RK_BASIN_AXES, "BASIN_AXES: the two axes are the same "
             "component '%s'", R->xnames[ax0]);
    return -2;
  }
  run_basins_job *J = calloc(1, sizeof *J);
  if (!J) return -1;
  J->na = s->nattractors;
  J->g0 = (size_t)s->grid[0];
  J->g1 = (size_t)s->grid[1];
  J->np = J->g0 * J->g1;
  J->ax[0] = ax0;
  J->ax[1] = ax1;
  J->tg = calloc(J->na, sizeof *J->tg);
  J->att = calloc(J->na, sizeof *J->att);
  J->names = calloc(J->na, sizeof *J->names);
  J->x0 = malloc(J->np * R->n * sizeof *J->x0);
  int rc = J->tg && J->att && J->names && J->x0 ? attractors(R, J) : -1;
  if (rc) {
    run_basins_job_free(J);
    return rc;
  }
  grid_states(R, J);
  const int fp = R->model->forcing_param;
  whirl_basins_options_default(&J->o);
  J->o.period = fp >= 0 ? 2.0 * WHIRL_PI / R->par[fp] : 1.0;
  J->o.max_periods = (size_t)s->basin_periods;
  J->o.rtol = 1e-9;
  J->o.atol = 1e-12;
  J->o.method = s->basin_method;
  if (s->basin_seeds > 0) { /* the atlas, as whirl sfd basins has it */
    J->o.seed_stride = (size_t)s->basin_seeds;
    J->o.atlas_levels = 4;
    J->o.cells = 32;
    J->o.cell_hits = 4;
    J->o.section_phases = 8;
  }
  R->plot.basins = 1;
  R->plot.x_name = R->xnames[ax0];
  R->plot.y_name = R->xnames[ax1];
  R->plot.attractors = s->attractors;
  R->plot.nattractors = J->na;
  R->bjob = J;
  return 0;
}

size_t run_basins_points(const run_ctx *R) { return R->bjob ? R->bjob->np : 0; }
size_t run_basins_line(const run_ctx *R) { return R->bjob ? R->bjob->g0 : 0; }

/* Classify the points first .. first + count − 1 of the grid: which[],
 * periods[] for them.  0 or -1 (said). */
int run_basins_classify(run_ctx *R, size_t first, size_t count, int *which,
                        unsigned *periods, whirl_basins_stats *st) {
  run_basins_job *J = R->bjob;
  char err[512];
  whirl_basins_options o = J->o;
  if (J->atlas_ready) { /* built in rounds: for any block of the grid */
    o.atlas = J->atlas;
    o.first = first;
  }
  if (count == J->np) {
    o.progress = progress;
    o.progress_data = R;
  }
  int brc = whirl_basins_compute(&R->prob, R->par, count, J->x0 + first * R->n, J->att, J->na,
                                 &o, which, periods, st, err, sizeof err);
  if (brc != WHIRL_OK) {
    run_say(R, "basins: %s", err);
    return -1;
  }
  return 0;
}

/* ---- the atlas in rounds: the stages of the rows (whirl/run.h) ---------- */

int run_basins_atlas_begin(run_ctx *R) {
  run_basins_job *J = R->bjob;
  if (!J || J->atlas || !J->o.seed_stride) return 0;
  char err[512];
  if (whirl_basins_atlas_begin(&R->prob, R->par, J->np, J->x0, J->att, J->na, &J->o, &J->atlas,
                               err, sizeof err) != WHIRL_OK) {
    run_say(R, "basins: %s", err);
    return -1;
  }
  for (size_t s = 0; s < whirl_basins_atlas_rounds(J->atlas); s++) {
    const size_t m = whirl_basins_atlas_round_seeds(J->atlas, s), q = (m + 127) / 128;
    J->per[s] = q < 4 ? 4 : q;
  }
  return 0;
}

size_t run_basins_rounds(const run_ctx *R) {
  return R->bjob ? whirl_basins_atlas_rounds(R->bjob->atlas) : 0;
}

size_t run_basins_round_blocks(const run_ctx *R, size_t s) {
  const run_basins_job *J = R->bjob;
  if (s >= run_basins_rounds(R)) return 0;
  return (whirl_basins_atlas_round_seeds(J->atlas, s) + J->per[s] - 1) / J->per[s];
}

int run_basins_round_compute(run_ctx *R, size_t s, size_t b, void **part, size_t *len) {
  const run_basins_job *J = R->bjob;
  if (b >= run_basins_round_blocks(R, s)) return -1;
  const size_t m = whirl_basins_atlas_round_seeds(J->atlas, s), j0 = b * J->per[s];
  const int rc = whirl_basins_atlas_classify(J->atlas, s, j0, m - j0 < J->per[s] ? m - j0 : J->per[s],
                                             part, len);
  if (rc != WHIRL_OK) run_say(R, "basins atlas, round %zu: %s", s + 1, whirl_strerror(rc));
  return rc == WHIRL_OK ? 0 : -1;
}

int run_basins_round_enter(run_ctx *R, size_t s, const void *const *parts, const size_t *lens,
                           size_t n) {
  const int rc = R->bjob ? whirl_basins_atlas_enter(R->bjob->atlas, s, parts, lens, n) : WHIRL_EINVAL;
  if (rc == WHIRL_OK && s + 1 == run_basins_rounds(R)) R->bjob->atlas_ready = 1;
  if (rc != WHIRL_OK) run_say(R, "basins atlas, round %zu: %s", s + 1, whirl_strerror(rc));
  return rc == WHIRL_OK ? 0 : -1;
}

/* Point q's row of basins.tsv (no newline): its two axis values, its class
 * (an attractor's label, or -1 unsettled, -2 left the domain, -3 failed)
 * and the periods integrated. */
int run_basins_row(const run_ctx *R, size_t q, int which, unsigned periods, char *buf,
                   size_t len) {
  const run_basins_job *J = R->bjob;
  const int cls = which >= 0 ? R->s->attractors[which] : which;
  int m = snprintf(buf, len, "%.10g\t%.10g\t%d\t%u", J->x0[q * R->n + J->ax[0]],
                   J->x0[q * R->n + J->ax[1]], cls, periods);
  return m < 0 || (size_t)m >= len ? -1 : 0;
}

/* The header of basins.tsv. */
int run_basins_header(const run_ctx *R, char *buf, size_t len) {
  const run_basins_job *J = R->bjob;
  int m = snprintf(buf, len, "%s\t%s\tattractor\tperiods", R->xnames[J->ax[0]], R->xnames[J->ax[1]]);
  return m < 0 || (size_t)m >= len ? -1 : 0;
}

/* The summary lines (and the log's) from the classes of all points. */
void run_basins_summary(run_ctx *R, const int *cls, size_t np) {
  const run_basins_job *J = R->bjob;
  size_t count[WHIRL_RUN_MAXITEMS + 3] = {0};
  for (size_t q = 0; q < np; q++) {
    size_t k = 0;
    if (cls[q] < 0) k = (size_t)(-cls[q] - 1);
    for (size_t a = 0; cls[q] >= 0 && a < J->na; a++)
      if (R->s->attractors[a] == cls[q]) k = a + 3;
    count[k]++;
  }
  char line[1024];
  int len = snprintf(line, sizeof line, "basins: %zu x %zu grid at", J->g0, J->g1);
  for (size_t k = 0; k < R->npar && len > 0 && (size_t)len < sizeof line; k++)
    len += snprintf(line + len, sizeof line - (size_t)len, " %s = %g", R->pnames[k], R->par[k]);
  run_summary(R, "%s", line);
  for (size_t a = 0; a < J->na; a++) {
    if (R->log)
      fprintf(R->log, "  LAB %d: %zu points (%.1f%%)\n", R->s->attractors[a], count[a + 3],
              100.0 * (double)count[a + 3] / (double)np);
    run_summary(R, "  attractor LAB %d: %.1f%% of the grid", R->s->attractors[a],
                100.0 * (double)count[a + 3] / (double)np);
  }
  if (R->log)
    fprintf(R->log, "  unsettled: %zu, left the domain: %zu, failed: %zu\n", count[0],
            count[1], count[2]);
  run_summary(R, "  unsettled %zu, left the domain %zu, failed %zu", count[0], count[1],
              count[2]);
}

int run_basins(run_ctx *R) {
  int rc = run_basins_setup(R);
  if (rc) return rc;
  run_basins_job *J = R->bjob;
  fprintf(R->log, "basins at");
  for (size_t k = 0; k < R->npar; k++) fprintf(R->log, " %s = %.10g", R->pnames[k], R->par[k]);
  fputc('\n', R->log);
  int *which = malloc(J->np * sizeof *which), *cls = malloc(J->np * sizeof *cls);
  unsigned *periods = malloc(J->np * sizeof *periods);
  whirl_basins_stats st;
  rc = which && cls && periods ? run_basins_classify(R, 0, J->np, which, periods, &st) : -1;
  FILE *f = rc ? NULL : run_open(R, "basins.tsv");
  char line[256];
  if (!rc && (!f || run_basins_header(R, line, sizeof line))) rc = -1;
  if (!rc) fprintf(f, "%s\n", line);
  for (size_t q = 0; !rc && q < J->np; q++) {
    if (run_basins_row(R, q, which[q], periods[q], line, sizeof line)) rc = -1;
    else fprintf(f, "%s\n%s", line, (q + 1) % J->g0 == 0 ? "\n" : "");
    cls[q] = which[q] >= 0 ? R->s->attractors[which[q]] : which[q];
  }
  if (f && run_close(R, f, "basins.tsv")) rc = -1;
  if (!rc) {
    fprintf(R->log, "grid %zu x %zu, %zu periods, %zu steps, %zu RHS evaluations\n",
            J->g0, J->g1, st.periods, st.steps, st.rhs_evals);
    run_basins_summary(R, cls, J->np);
  }
  free(which);
  free(cls);
  free(periods);
  return rc;
}

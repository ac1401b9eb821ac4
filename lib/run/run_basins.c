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
 * Writes basins.tsv (axis values, class: attractor label, -1 unsettled,
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

int run_basins(run_ctx *R) {
  const whirl_run_settings *s = R->s;
  const size_t n = R->n, na = s->nattractors;
  const int fp = R->model->forcing_param;
  int rc = -1;
  int ax[2] = {run_state_index(R, &s->axes[0].ref), run_state_index(R, &s->axes[1].ref)};
  if (ax[0] == ax[1]) {
    run_fail(R, WHIRL_RK_BASIN_AXES, "BASIN_AXES: the two axes are the same "
             "component '%s'", R->xnames[ax[0]]);
    return -2;
  }
  const size_t g0 = (size_t)s->grid[0], g1 = (size_t)s->grid[1], np = g0 * g1;
  target *tg = calloc(na, sizeof *tg);
  whirl_attractor *att = calloc(na, sizeof *att);
  double *x0 = malloc(np * n * sizeof *x0);
  int *which = malloc(np * sizeof *which);
  unsigned *periods = malloc(np * sizeof *periods);
  char (*names)[32] = calloc(na, sizeof *names);
  if (!tg || !att || !x0 || !which || !periods || !names) goto done;
  for (size_t a = 0; a < na; a++) {
    whirl_solution so;
    char msg[1024];
    if (run_solution_find(R, s->s, s->attractors[a], "", &so, msg, sizeof msg)) {
      run_fail(R, WHIRL_RK_BASIN_ATTRACTORS, "BASIN_ATTRACTORS: %s", msg);
      rc = -2;
      goto done;
    }
    if (so.stable != 1) {
      run_fail(R, WHIRL_RK_BASIN_ATTRACTORS, "BASIN_ATTRACTORS: label %d is "
               "not a stable solution (STAB = %d)", so.label, so.stable);
      whirl_solution_free(&so);
      rc = -2;
      goto done;
    }
    if (a == 0) {
      memcpy(R->par, so.par, R->npar * sizeof *R->par);
      for (size_t i = 0; i < s->npar; i++)
        R->par[run_par_index(R, &s->par[i].ref)] = s->par[i].value;
    }
    for (size_t k = 0; k < R->npar; k++)
      if (fabs(so.par[k] - R->par[k]) > 1e-8 * (1.0 + fabs(R->par[k]))) {
        run_fail(R, WHIRL_RK_BASIN_ATTRACTORS, "BASIN_ATTRACTORS: label %d "
                 "has %s = %.10g, the basins are computed at %.10g (all "
                 "attractors must be at the same parameters: use UZR in the "
                 "continuation run)", so.label, R->pnames[k], so.par[k], R->par[k]);
        whirl_solution_free(&so);
        rc = -2;
        goto done;
      }
    tg[a].n = n;
    tg[a].tol = s->basin_tol;
    tg[a].x = malloc(n * sizeof *tg[a].x);
    if (!tg[a].x || section_state(R, &so, tg[a].x)) {
      whirl_solution_free(&so);
      run_say(R, "label %d: cannot evaluate the solution", so.label);
      goto done;
    }
    snprintf(names[a], sizeof names[a], "LAB %d", so.label);
    att[a].name = names[a];
    att[a].test = near_target;
    att[a].data = &tg[a];
    att[a].confirm = 3;
    fprintf(R->log, "attractor %zu: label %d (%s, %s), section state", a + 1,
            so.label, so.ty, so.kind == WHIRL_SOL_EQ ? "equilibrium" : "periodic orbit");
    for (size_t i = 0; i < n; i++) fprintf(R->log, " %.10g", tg[a].x[i]);
    fputc('\n', R->log);
    whirl_solution_free(&so);
  }
  fprintf(R->log, "basins at");
  for (size_t k = 0; k < R->npar; k++) fprintf(R->log, " %s = %.10g", R->pnames[k], R->par[k]);
  fputc('\n', R->log);
  for (size_t j = 0; j < g1; j++)
    for (size_t i = 0; i < g0; i++) {
      double *x = x0 + (j * g0 + i) * n;
      memcpy(x, R->u, n * sizeof *x);
      x[ax[0]] = s->axes[0].lo + (s->axes[0].hi - s->axes[0].lo) * (double)i / (double)(g0 - 1);
      x[ax[1]] = s->axes[1].lo + (s->axes[1].hi - s->axes[1].lo) * (double)j / (double)(g1 - 1);
    }
  whirl_basins_options o;
  whirl_basins_options_default(&o);
  o.period = fp >= 0 ? 2.0 * WHIRL_PI / R->par[fp] : 1.0;
  o.max_periods = (size_t)s->basin_periods;
  o.rtol = 1e-9;
  o.atol = 1e-12;
  o.progress = progress;
  o.progress_data = R;
  whirl_basins_stats st;
  char err[512];
  int brc = whirl_basins_compute(&R->prob, R->par, np, x0, att, na, &o, which,
                                 periods, &st, err, sizeof err);
  if (brc != WHIRL_OK) {
    run_say(R, "basins: %s", err);
    goto done;
  }
  FILE *f = run_open(R, "basins.tsv");
  if (!f) goto done;
  fprintf(f, "# %s\t%s\tclass\tperiods\n", R->xnames[ax[0]], R->xnames[ax[1]]);
  size_t count[WHIRL_RUN_MAXITEMS + 3] = {0};
  for (size_t j = 0; j < g1; j++) {
    for (size_t i = 0; i < g0; i++) {
      size_t q = j * g0 + i;
      int cls = which[q] >= 0 ? s->attractors[which[q]] : which[q];
      count[which[q] >= 0 ? (size_t)which[q] + 3 : (size_t)(-which[q] - 1)]++;
      fprintf(f, "%.10g\t%.10g\t%d\t%u\n", x0[q * n + ax[0]], x0[q * n + ax[1]],
              cls, periods[q]);
    }
    fputc('\n', f);
  }
  if (run_close(R, f, "basins.tsv")) goto done;
  fprintf(R->log, "grid %zu x %zu, %zu periods, %zu steps, %zu RHS evaluations\n",
          g0, g1, st.periods, st.steps, st.rhs_evals);
  char line[1024];
  int len = snprintf(line, sizeof line, "basins: %zu x %zu grid at", g0, g1);
  for (size_t k = 0; k < R->npar && len > 0 && (size_t)len < sizeof line; k++)
    len += snprintf(line + len, sizeof line - (size_t)len, " %s = %g", R->pnames[k], R->par[k]);
  run_summary(R, "%s", line);
  for (size_t a = 0; a < na; a++) {
    fprintf(R->log, "  LAB %d: %zu points (%.1f%%)\n", s->attractors[a], count[a + 3],
            100.0 * (double)count[a + 3] / (double)np);
    run_summary(R, "  attractor LAB %d: %.1f%% of the grid", s->attractors[a],
                100.0 * (double)count[a + 3] / (double)np);
  }
  fprintf(R->log, "  unsettled: %zu, left the domain: %zu, failed: %zu\n",
          count[0], count[1], count[2]);
  run_summary(R, "  unsettled %zu, left the domain %zu, failed %zu", count[0], count[1],
              count[2]);
  /* what the picture shows */
  R->plot.x_name = R->xnames[ax[0]];
  R->plot.y_name = R->xnames[ax[1]];
  R->plot.attractors = s->attractors;
  R->plot.nattractors = na;
  rc = 0;
done:
  if (tg)
    for (size_t a = 0; a < na; a++) free(tg[a].x);
  free(tg);
  free(att);
  free(x0);
  free(which);
  free(periods);
  free(names);
  return rc;
}

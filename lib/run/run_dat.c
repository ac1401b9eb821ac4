/* lib/run/run_dat.c — a start orbit from a data file (DAT, AUTO-07p's
 * `dat`): rows "t u(1) ... u(n)", t increasing, more numbers on a row
 * ignored, Fortran's D exponents read.  As AUTO-07p does it (toolboxbv.f90,
 * STPNUB): the period is t_last - t_first unless the model's start sets
 * it (STPNT's PAR(11), whirl's period0), time is rescaled to [0, 1] and
 * the orbit is the piecewise-linear interpolant of the rows (its ADAPT2 of
 * data with NCOL = 1), sampled here at m equally spaced times for the
 * collocation's start (whirl_colloc_from_samples), or with MESH_RULE =
 * jumps evaluated at the nodes of the mesh AUTO's ADAPT2 makes from the
 * rows (whirl_colloc_adapt_from); the first point is then corrected by
 * Newton with the phase condition against this orbit.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_impl.h"

/* The numbers of one line, at most max, D exponents as E.  Their count. */
static size_t numbers(char *line, double *v, size_t max) {
  for (char *q = line; *q; q++)
    if (*q == 'D' || *q == 'd') *q = 'E';
  size_t k = 0;
  for (char *q = line, *end; k < max; q = end) {
    v[k] = strtod(q, &end);
    if (end == q) break;
    k++;
  }
  return k;
}

static int all_finite(const double *v, size_t k) {
  for (size_t i = 0; i < k; i++)
    if (!isfinite(v[i])) return 0;
  return 1;
}

/* The rows of PATH: t[*nr] and u[*nr * n] (allocated).  0, or -1 said. */
static int read_rows(run_ctx *R, const char *path, double **t, double **u, size_t *nr) {
  const size_t n = R->n;
  FILE *f = fopen(path, "r");
  if (!f) {
    run_fail(R, WHIRL_RK_DAT, "%s: cannot open", path);
    return -1;
  }
  char line[8192];
  double *v = malloc((n + 1) * sizeof *v);
  size_t cap = 0, lineno = 0;
  int rc = v ? 0 : -1;
  *t = *u = NULL, *nr = 0;
  while (!rc && fgets(line, sizeof line, f)) {
    lineno++;
    const size_t k = numbers(line, v, n + 1);
    if (k == 0 && strspn(line, " \t\r\n") == strlen(line)) continue;
    if (k < n + 1) {
      run_fail(R, WHIRL_RK_DAT, "%s:%zu: %zu numbers, a row is t and the %zu state components",
               path, lineno, k, n);
      rc = -1;
    } else if (!all_finite(v, n + 1)) {
      run_fail(R, WHIRL_RK_DAT, "%s:%zu: a number is not finite", path, lineno);
      rc = -1;
    } else if (*nr && !(v[0] > (*t)[*nr - 1])) {
      run_fail(R, WHIRL_RK_DAT, "%s:%zu: t = %g does not increase", path, lineno, v[0]);
      rc = -1;
    } else {
      if (*nr == cap) {
        cap = cap ? 2 * cap : 64;
        double *nt = realloc(*t, cap * sizeof *nt), *nu = nt ? realloc(*u, cap * n * sizeof *nu) : NULL;
        if (nt) *t = nt;
        if (nu) *u = nu;
        if (!nt || !nu) rc = -1;
      }
      if (!rc) (*t)[*nr] = v[0], memcpy(*u + *nr * n, v + 1, n * sizeof *v), ++*nr;
    }
  }
  fclose(f);
  free(v);
  if (!rc && *nr < 2) {
    run_fail(R, WHIRL_RK_DAT, "%s: %zu rows, an orbit needs at least 2", path, *nr);
    rc = -1;
  }
  return rc;
}

/* The rows of the data file, the period and the jumps over it. */
static int dat_rows(run_ctx *R, double **tp, double **up, size_t *nrp, double *T,
                    double *jump) {
  const size_t n = R->n;
  double *t = NULL, *u = NULL;
  size_t nr;
  char path[4096];
  /* relative to the run file's directory, as model, S and OUT (run_path) */
  if (run_path(R, WHIRL_RK_DAT, R->s->dat, path, sizeof path)) {
    run_fail(R, WHIRL_RK_DAT, "DAT: the path is too long");
    return -1;
  }
  if (read_rows(R, path, &t, &u, &nr)) {
    free(t), free(u);
    return -1;
  }
  *T = t[nr - 1] - t[0];
  /* AUTO sets PAR(11) to it and then calls STPNT, which may set the
   * period itself (demo pen: its data are in scaled time): the model's
   * period0, where it has one, is that value */
  const double tdat = *T;
  if (R->model->period0 > 0) *T = R->model->period0;
  for (size_t i = 0; jump && i < n; i++) jump[i] = u[(nr - 1) * n + i] - u[i];
  fprintf(R->log, "start orbit from %s: %zu rows over %.10g, period %.10g\n", path, nr,
          tdat, *T);
  *tp = t, *up = u, *nrp = nr;
  return 0;
}

int run_dat_samples(run_ctx *R, size_t m, double *xs, double *T, double *jump) {
  const size_t n = R->n;
  double *t, *u;
  size_t nr;
  if (dat_rows(R, &t, &u, &nr, T, jump)) return -1;
  for (size_t k = 0, j = 0; k < m; k++) { /* the interpolant at k/m */
    const double tk = t[0] + *T * (double)k / (double)m;
    while (j + 2 < nr && t[j + 1] <= tk) j++;
    const double w = (tk - t[j]) / (t[j + 1] - t[j]);
    for (size_t i = 0; i < n; i++)
      xs[k * n + i] = (1.0 - w) * u[j * n + i] + w * u[(j + 1) * n + i];
  }
  free(t), free(u);
  return 0;
}

int run_dat_adapt(run_ctx *R, whirl_colloc *colloc, double *X, double *T, double *jump) {
  double *t, *u;
  size_t nr;
  if (dat_rows(R, &t, &u, &nr, T, jump)) return -1;
  /* AUTO's time of the rows on [0, 1], their mesh of nr - 1 linear pieces */
  const double t0 = t[0], span = t[nr - 1] - t[0];
  for (size_t k = 0; k < nr; k++) t[k] = (t[k] - t0) / span;
  t[nr - 1] = 1.0;
  const int rc = whirl_colloc_adapt_from(colloc, nr - 1, 1, t, u, X);
  if (rc != WHIRL_OK) run_say(R, "DAT: %s", whirl_colloc_errmsg(colloc));
  free(t), free(u);
  return rc == WHIRL_OK ? 0 : -1;
}

/* The piecewise-linear interpolant of the rows (time on [0, 1]) at t. */
typedef struct dat_rows_lin {
  const double *t, *u;
  size_t nr, n;
} dat_rows_lin;

static int rows_at(double t, double *u, double *p, void *d) {
  const dat_rows_lin *L = d;
  size_t j = 0;
  (void)p;
  while (j + 2 < L->nr && L->t[j + 1] <= t) j++;
  const double w = (t - L->t[j]) / (L->t[j + 1] - L->t[j]);
  for (size_t i = 0; i < L->n; i++)
    u[i] = (1.0 - w) * L->u[j * L->n + i] + w * L->u[(j + 1) * L->n + i];
  return 0;
}

int run_dat_bvp(run_ctx *R, whirl_bvp *bvp, double *X) {
  const size_t n = R->n;
  double *t = NULL, *u = NULL, *us = malloc(n * sizeof *us);
  size_t nr;
  char path[4096];
  int rc = us ? 0 : -1;
  if (!rc && run_path(R, WHIRL_RK_DAT, R->s->dat, path, sizeof path)) {
    run_fail(R, WHIRL_RK_DAT, "DAT: the path is too long");
    rc = -1;
  }
  if (!rc) rc = read_rows(R, path, &t, &u, &nr);
  if (!rc) {
    const double t0 = t[0], span = t[nr - 1] - t[0];
    for (size_t k = 0; k < nr; k++) t[k] = (t[k] - t0) / span;
    t[nr - 1] = 1.0;
    if (R->npar > 10) R->par[10] = span; /* AUTO's PAR(11) = PERIOD */
    fprintf(R->log, "start solution from %s: %zu rows over %.10g\n", path, nr, span);
    memcpy(us, u, n * sizeof *us); /* STPNT(NDIM, U, PAR, 0) may set PAR */
    if (R->model->stpnt && R->model->stpnt(0.0, us, R->par, R->prob.data) != 0) {
      run_fail(R, WHIRL_RK_MODEL, "model '%s': stpnt failed", R->prob.name);
      rc = -1;
    }
  }
  if (!rc && whirl_bvp_mesh_from(bvp, nr - 1, 1, t, u) != WHIRL_OK) {
    run_say(R, "DAT: %s", whirl_bvp_errmsg(bvp));
    rc = -1;
  }
  if (!rc) {
    dat_rows_lin L = {t, u, nr, n};
    if (whirl_bvp_from_function(bvp, rows_at, &L, X, R->par) != WHIRL_OK) {
      run_say(R, "DAT: %s", whirl_bvp_errmsg(bvp));
      rc = -1;
    }
  }
  free(t), free(u), free(us);
  return rc;
}

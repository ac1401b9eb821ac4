/* lib/run/run_table.c — the branch table of a run, branches.tsv (AUTO's
 * b-file as TSV, the column names of doc/tables.md: branch pt type label
 * (AUTO's BR PT TY LAB), then all parameters, period for periodic orbits,
 * l2_norm (AUTO's L2-NORM), the state (max_NAME, the MAX of each component
 * over the orbit, for periodic orbits) and stable (AUTO's STAB: 1 stable,
 * 0 unstable, -1 unknown)), and the labelled points kept with their rows
 * (whirl_run_special).
 *
 * L2-NORM follows AUTO: |x| for an equilibrium, sqrt(∫_0^1 |x(τ)|² dτ) for
 * a periodic orbit; MAX and L2-NORM of orbits come from the periodic-orbit
 * interface (whirl/periodic.h), so the table does not choose between
 * collocation and harmonic balance.
 *
 * IPLT (AUTO-07p manual, "IPLT"; io.f90 HEADNG, ae.f90 STPLAE) replaces
 * that column as AUTO does: for equilibria U(i) where |IPLT| = i <= NDIM,
 * U(IPLT - NDIM) for NDIM < IPLT <= 2 NDIM ("INTEGRAL U(i)") and
 * U(IPLT - 2 NDIM) up to 3 NDIM ("L2-NORM U(i)"); for orbits MAX U(i),
 * MIN U(-IPLT) (over the nodes, as AUTO), ∫₀¹ u_i and sqrt(∫₀¹ u_i²); any
 * other IPLT is the L2-NORM.  The limits A0, A1 bound the same measure.
 * The column keeps its name l2_norm (doc/tables.md); the picture's axis
 * and AUTO's b-file (auto_files.c) name the measure as AUTO does.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* open_memstream */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "run_impl.h"

/* IPLT's component (0-based) and kind: 0 L2-NORM, 1 U(i) or MAX U(i),
 * 2 MIN U(i), 3 INTEGRAL U(i), 4 L2-NORM U(i). */
static int iplt_kind(const run_ctx *R, size_t *comp) {
  const long n = (long)R->n, ip = R->s->iplt;
  if (ip == 0 || ip < -n || ip > 3 * n) return 0;
  *comp = (size_t)((ip < 0 ? -ip : ip > 2 * n ? ip - 2 * n : ip > n ? ip - n : ip) - 1);
  return ip < 0 ? 2 : ip > 2 * n ? 4 : ip > n ? 3 : 1;
}

/* The name of the L2-NORM column (AUTO's HEADNG names). */
static void measure_name(const run_ctx *R, whirl_solution_kind kind, char *buf, size_t len) {
  size_t i = 0;
  const int k = iplt_kind(R, &i);
  static const char *const pre[2][5] = {{"L2-NORM", "", "", "INTEGRAL ", "L2-NORM "},
                                        {"L2-NORM", "MAX ", "MIN ", "INTEGRAL ", "L2-NORM "}};
  const int orbit = kind != WHIRL_SOL_EQ;
  if (!k) snprintf(buf, len, "L2-NORM");
  else snprintf(buf, len, "%s%s", pre[orbit][k], R->xnames[i]);
}

/* Does a solution of this kind have a period (a column of its own)? */
static int has_period(whirl_solution_kind kind) {
  return kind == WHIRL_SOL_COLLOC || kind == WHIRL_SOL_HBM;
}

int run_table_header(run_ctx *R, whirl_solution_kind kind, int icp, int q) {
  FILE *f = R->table;
  const int per = has_period(kind);
  /* the diagram of a locus has ICP(1) across, as AUTO's: when the label's
   * own parameter q is ICP(1) (an unknown of the locus, continued in
   * icp), q is the x axis and icp the y axis */
  if (q >= 0 && R->nicp > 0 && R->icp[0] == q) {
    const int t = icp;
    icp = q;
    q = t;
  }
  size_t col = 4;
  fprintf(f, "branch\tpt\ttype\tlabel");
  int ycol = 0;
  for (size_t k = 0; k < R->npar; k++) {
    fprintf(f, "\t%s", R->pnames[k]);
    col++;
    if ((int)k == icp) R->plot_x = (int)col;
    if ((int)k == q && R->plot_kind == RUN_PLOT_DEFAULT) ycol = (int)col;
    if (R->plot_kind == RUN_PLOT_PAR && (int)k == R->plot_index) ycol = (int)col;
  }
  if (per) {
    fprintf(f, "\tperiod");
    col++;
    if (R->plot_kind == RUN_PLOT_PERIOD) ycol = (int)col;
  }
  /* the column keeps its name under IPLT; the picture's axis says AUTO's */
  char mname[WHIRL_RUN_MAXNAME + 16];
  measure_name(R, kind, mname, sizeof mname);
  fprintf(f, "\tl2_norm");
  col++;
  if (!ycol || R->plot_kind == RUN_PLOT_L2) ycol = (int)col;
  for (size_t i = 0; i < R->n; i++) {
    fprintf(f, kind == WHIRL_SOL_EQ ? "\t%s" : "\tmax_%s", R->xnames[i]);
    col++;
    if (R->plot_kind == RUN_PLOT_STATE && (int)i == R->plot_index) ycol = (int)col;
  }
  fprintf(f, "\tstable\n");
  col++;
  R->ncols = col;
  R->plot_y = ycol;
  /* axis names: AUTO's names of the header's columns (1-based, branch is
   * column 1) */
  snprintf(R->plot_x_name, sizeof R->plot_x_name, "%s", R->pnames[R->plot_x - 5]);
  if (ycol >= 5 && ycol < 5 + (int)R->npar)
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "%s", R->pnames[ycol - 5]);
  else if (per && ycol == 5 + (int)R->npar)
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "PERIOD");
  else if (ycol == 5 + (int)R->npar + per)
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "%.*s", (int)sizeof R->plot_y_name - 1, mname);
  else
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "%s%s", kind == WHIRL_SOL_EQ ? "" : "MAX ",
             R->xnames[ycol - 6 - (int)R->npar - per]);
  return ferror(f) ? -1 : 0;
}

/* A read-only view: the table measures orbits, it changes no object. */
whirl_periodic run_periodic(whirl_solution_kind kind, const void *obj) {
  void *o = (void *)(uintptr_t)obj;
  return kind == WHIRL_SOL_COLLOC ? whirl_periodic_of_colloc(o) : whirl_periodic_of_hbm(o);
}

/* ∫u_i, ∫u_i² and the minimum of an orbit's component i: collocation by
 * its mesh, harmonic balance by 512 equally spaced samples (the trapezoid
 * rule is exact for its trigonometric polynomials of lower degree). */
static int orbit_moments(const run_ctx *R, whirl_solution_kind kind, const void *obj,
                         const whirl_periodic *po, const double *xb, size_t i, double m[3]) {
  const size_t n = R->n, ns = 512;
  double *v = malloc(4 * n * sizeof *v);
  int rc = v ? WHIRL_OK : WHIRL_ENOMEM;
  if (!rc && kind == WHIRL_SOL_COLLOC)
    rc = whirl_colloc_moments(obj, xb, v, v + n, v + 2 * n, v + 3 * n);
  else if (!rc && kind == WHIRL_SOL_BVP)
    rc = whirl_bvp_moments(obj, xb, v, v + n, v + 2 * n, v + 3 * n);
  else if (!rc) {
    v[i] = v[n + i] = 0.0, v[2 * n + i] = HUGE_VAL;
    double *u = malloc(n * sizeof *u);
    for (size_t k = 0; u && !rc && k < ns; k++) {
      rc = whirl_periodic_eval(po, xb, (double)k / (double)ns, u);
      v[i] += u[i] / (double)ns, v[n + i] += u[i] * u[i] / (double)ns;
      v[2 * n + i] = fmin(v[2 * n + i], u[i]);
    }
    if (!u) rc = WHIRL_ENOMEM;
    free(u);
  }
  if (!rc) m[0] = v[i], m[1] = v[n + i], m[2] = v[2 * n + i];
  free(v);
  return rc;
}

/* The L2-NORM column's value under IPLT (above). */
static int iplt_measure(const run_ctx *R, whirl_solution_kind kind, const void *obj,
                        const whirl_periodic *po, const double *xb, const double *mx,
                        double *out) {
  size_t i = 0;
  const int k = iplt_kind(R, &i);
  if (!k) return 0;
  if (kind == WHIRL_SOL_EQ || k == 1) {
    *out = kind == WHIRL_SOL_EQ ? xb[i] : mx[i];
    return 0;
  }
  double m[3];
  if (orbit_moments(R, kind, obj, po, xb, i, m)) return -1;
  *out = k == 2 ? m[2] : k == 3 ? m[0] : sqrt(m[1]);
  return 0;
}

int run_point_measures(const run_ctx *R, whirl_solution_kind kind, const void *obj,
                       const double *xb, const double *p, double *l2out,
                       double *period_out, double *mx) {
  if (kind == WHIRL_SOL_EQ) {
    double l2 = 0.0;
    for (size_t i = 0; i < R->n; i++) l2 += xb[i] * xb[i], mx[i] = xb[i];
    *l2out = sqrt(l2);
    *period_out = 0.0;
    return iplt_measure(R, kind, obj, NULL, xb, mx, l2out);
  }
  if (kind == WHIRL_SOL_BVP) { /* AUTO's MAX over the nodes, no period */
    *period_out = 0.0;
    *l2out = whirl_bvp_l2norm(obj, xb);
    if (whirl_bvp_max(obj, xb, mx) != WHIRL_OK || isnan(*l2out)) return -1;
    return iplt_measure(R, kind, obj, NULL, xb, mx, l2out);
  }
  const whirl_periodic po = run_periodic(kind, obj);
  *period_out = whirl_periodic_period(&po, xb, p);
  *l2out = whirl_periodic_l2norm(&po, xb);
  if (isnan(*l2out)) return -1;
  if (kind == WHIRL_SOL_COLLOC && R->s->orbit_max_nodes) { /* AUTO's, as BVPs' */
    /* the node values, then the period (or the free parameter in its place) */
    const size_t n = R->n, nnodes = (whirl_colloc_size(obj) - (R->prob.autonomous ? 1 : 0)) / n;
    for (size_t i = 0; i < n; i++) mx[i] = xb[i];
    for (size_t j = 1; j < nnodes; j++)
      for (size_t i = 0; i < n; i++) mx[i] = fmax(mx[i], xb[n * j + i]);
  } else if (whirl_periodic_max(&po, xb, mx) != WHIRL_OK) {
    return -1;
  }
  return iplt_measure(R, kind, obj, &po, xb, mx, l2out);
}

/* One row of the branch table. */
static void write_row(FILE *f, const run_ctx *R, int br, size_t pt, const char *ty,
                      int lab, const double *p, int periodic, double period, double l2,
                      const double *mx, int stable) {
  /* a regular point's type is '-', as in every whirl table (doc/tables.md);
   * RG stays the run's own name for it (IRS, the solutions file, AUTO's files) */
  fprintf(f, "%d\t%zu\t%s\t%d", br, pt, strcmp(ty, "RG") ? ty : "-", lab);
  for (size_t k = 0; k < R->npar; k++) fprintf(f, "\t%.12g", p[k]);
  if (periodic) fprintf(f, "\t%.12g", period);
  fprintf(f, "\t%.12g", l2);
  for (size_t i = 0; i < R->n; i++) fprintf(f, "\t%.12g", mx[i]);
  fprintf(f, "\t%d", stable);
}

int run_keep_special(run_ctx *R, int br, size_t pt, const char *ty, int lab,
                     const double *p, double period, double l2, const double *state,
                     const char *row) {
  if (R->nspecial == R->capspecial) {
    const size_t cap = R->capspecial ? 2 * R->capspecial : 16;
    whirl_run_special *g = realloc(R->special, cap * sizeof *g);
    if (!g) return -1;
    R->special = g;
    R->capspecial = cap;
  }
  double *v = malloc((R->npar + R->n) * sizeof *v);
  char *copy = malloc(strlen(row) + 1);
  if (!v || !copy) {
    free(v);
    free(copy);
    return -1;
  }
  memcpy(v, p, R->npar * sizeof *v);
  memcpy(v + R->npar, state, R->n * sizeof *v);
  strcpy(copy, row);
  whirl_run_special *s = &R->special[R->nspecial++];
  memset(s, 0, sizeof *s);
  s->br = br;
  s->pt = pt;
  s->lab = lab;
  snprintf(s->ty, sizeof s->ty, "%s", ty);
  s->par = v;
  s->state = v + R->npar;
  s->period = period;
  s->l2norm = l2;
  s->row = copy;
  return 0;
}

/* Keep BR among the branches of the table (in order of their first row),
 * with the stabilities of its rows: the picture draws each branch on its
 * own, so that no line joins the end of one to the start of the next.
 * -1 when out of memory. */
static int note_branch(run_ctx *R, int br, int stable) {
  const int bit = stable >= -1 && stable <= 1 ? 1 << (stable + 1) : 0;
  for (size_t i = R->nbranch_ids; i-- > 0;)
    if (R->branch_ids[i] == br) {
      R->branch_stab[i] |= bit;
      return 0;
    }
  if (R->nbranch_ids == R->capbranch_ids) {
    const size_t cap = R->capbranch_ids ? 2 * R->capbranch_ids : 8;
    int *v = realloc(R->branch_ids, cap * sizeof *v);
    if (!v) return -1;
    R->branch_ids = v;
    int *m = realloc(R->branch_stab, cap * sizeof *m);
    if (!m) return -1;
    R->branch_stab = m;
    R->capbranch_ids = cap;
  }
  R->branch_stab[R->nbranch_ids] = bit;
  R->branch_ids[R->nbranch_ids++] = br;
  return 0;
}

int run_table_row(run_ctx *R, whirl_solution_kind kind, const void *obj, int br,
                  size_t pt, const char *ty, int lab, const double *xb,
                  const double *p, int stable, double *l2out, double *period_out,
                  double *state) {
  FILE *f = R->table;
  const size_t n = R->n;
  double *mx = calloc(n, sizeof *mx);
  if (!mx) return -1;
  double l2, period;
  if (run_point_measures(R, kind, obj, xb, p, &l2, &period, mx)) {
    free(mx);
    return -1;
  }
  const int periodic = has_period(kind);
  write_row(f, R, br, pt, ty, lab, p, periodic, period, l2, mx, stable);
  fputc('\n', f);
  int rc = 0;
  if (strcmp(ty, "RG")) { /* a labelled point: kept, with its row */
    char *row = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&row, &len);
    if (m) write_row(m, R, br, pt, ty, lab, p, periodic, period, l2, mx, stable);
    if (!m || fclose(m) != 0 || run_keep_special(R, br, pt, ty, lab, p, period, l2, mx, row))
      rc = -1;
    free(row);
  }
  if (stable >= -1 && stable <= 1) R->seen_stab[stable + 1] = 1;
  if (strcmp(ty, "RG") && strcmp(ty, "EP")) R->seen_special = 1;
  if (note_branch(R, br, stable)) rc = -1;
  *l2out = l2;
  *period_out = period;
  memcpy(state, mx, n * sizeof *state);
  free(mx);
  return rc || ferror(f) ? -1 : 0;
}

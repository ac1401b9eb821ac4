/* drivers/run_table.c — `whirl run` output: the branch table branches.tsv
 * (AUTO's b-file as TSV: BR PT TY LAB, then all parameters, PERIOD for
 * periodic orbits, L2-NORM, the state (MAX of each component for periodic
 * orbits: the maximum over the orbit, see colloc_max), and STAB: 1 stable, 0 unstable, -1 unknown) and
 * the picture diagram.png drawn from it by gnuplot.
 *
 * L2-NORM follows AUTO: |x| for an equilibrium, sqrt(∫_0^1 |x(τ)|² dτ) for a
 * periodic orbit (Gauss–Legendre on every mesh interval for collocation,
 * 5 points: exact for the degree-2·NCOL integrand up to NCOL = 4, and to
 * the accuracy of the orbit beyond; a uniform trapezoidal rule, exact for
 * trigonometric polynomials, for harmonic balance).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli.h"
#include "run.h"

int run_table_header(run_ctx *R, whirl_solution_kind kind, int icp, int q) {
  FILE *f = R->table;
  size_t col = 4;
  fprintf(f, "# BR\tPT\tTY\tLAB");
  int ycol = 0;
  for (size_t k = 0; k < R->npar; k++) {
    fprintf(f, "\t%s", R->pnames[k]);
    col++;
    if ((int)k == icp) R->plot_x = (int)col;
    if ((int)k == q && R->plot_kind == RUN_PLOT_DEFAULT) ycol = (int)col;
    if (R->plot_kind == RUN_PLOT_PAR && (int)k == R->plot_index) ycol = (int)col;
  }
  if (kind != WHIRL_SOL_EQ) {
    fprintf(f, "\tPERIOD");
    col++;
    if (R->plot_kind == RUN_PLOT_PERIOD) ycol = (int)col;
  }
  fprintf(f, "\tL2-NORM");
  col++;
  if (!ycol || R->plot_kind == RUN_PLOT_L2) ycol = (int)col;
  for (size_t i = 0; i < R->n; i++) {
    fprintf(f, kind == WHIRL_SOL_EQ ? "\t%s" : "\tMAX %s", R->xnames[i]);
    col++;
    if (R->plot_kind == RUN_PLOT_STATE && (int)i == R->plot_index) ycol = (int)col;
  }
  fprintf(f, "\tSTAB\n");
  col++;
  R->ncols = col;
  R->plot_y = ycol;
  /* axis names: the header's columns (1-based, "# BR" is column 1) */
  snprintf(R->plot_x_name, sizeof R->plot_x_name, "%s", R->pnames[R->plot_x - 5]);
  if (ycol >= 5 && ycol < 5 + (int)R->npar)
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "%s", R->pnames[ycol - 5]);
  else if (kind != WHIRL_SOL_EQ && ycol == 5 + (int)R->npar)
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "PERIOD");
  else if (ycol == 5 + (int)R->npar + (kind != WHIRL_SOL_EQ))
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "L2-NORM");
  else
    snprintf(R->plot_y_name, sizeof R->plot_y_name, "%s%s", kind == WHIRL_SOL_EQ ? "" : "MAX ",
             R->xnames[ycol - 6 - (int)R->npar - (kind != WHIRL_SOL_EQ)]);
  return ferror(f) ? -1 : 0;
}

whirl_periodic run_periodic(whirl_solution_kind kind, const void *obj) {
  return kind == WHIRL_SOL_COLLOC ? whirl_periodic_of_colloc(obj) : whirl_periodic_of_hbm(obj);
}

int run_point_measures(const run_ctx *R, whirl_solution_kind kind, const void *obj,
                       const double *xb, const double *p, double *l2out,
                       double *period_out, double *mx) {
  if (kind == WHIRL_SOL_EQ) {
    double l2 = 0.0;
    for (size_t i = 0; i < R->n; i++) l2 += xb[i] * xb[i], mx[i] = xb[i];
    *l2out = sqrt(l2);
    *period_out = 0.0;
    return 0;
  }
  const whirl_periodic po = run_periodic(kind, obj);
  *period_out = whirl_periodic_period(&po, xb, p);
  *l2out = whirl_periodic_l2norm(&po, xb);
  return whirl_periodic_max(&po, xb, mx) != WHIRL_OK || isnan(*l2out) ? -1 : 0;
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
  fprintf(f, "%d\t%zu\t%s\t%d", br, pt, ty, lab);
  for (size_t k = 0; k < R->npar; k++) fprintf(f, "\t%.12g", p[k]);
  if (kind != WHIRL_SOL_EQ) fprintf(f, "\t%.12g", period);
  fprintf(f, "\t%.12g", l2);
  for (size_t i = 0; i < n; i++) fprintf(f, "\t%.12g", mx[i]);
  fprintf(f, "\t%d\n", stable);
  if (stable >= -1 && stable <= 1) R->seen_stab[stable + 1] = 1;
  if (strcmp(ty, "RG") && strcmp(ty, "EP")) R->seen_special = 1;
  *l2out = l2;
  *period_out = period;
  memcpy(state, mx, n * sizeof *state);
  free(mx);
  return ferror(f) ? -1 : 0;
}

/* gnuplot: stable parts solid, unstable dashed, unknown thin; labelled
 * special points marked and named.  Each series is NaN where the STAB
 * column differs: gnuplot breaks a line at an undefined point, so a stable
 * stretch is not joined across an unstable one (no 'set datafile missing',
 * which would make it skip those points and join them). */
int run_write_plot(run_ctx *R, const char **name) {
  *name = R->s->ips == WHIRL_IPS_BASINS ? "basins" : "diagram";
  if (R->s->ips == WHIRL_IPS_BASINS) return 0;
  FILE *f = cli_outdir_fopen(&R->od, "diagram.gp");
  if (!f) return -1;
  /* names of the user's files, model and parameters, quoted for gnuplot */
  char title[1024], qtitle[2100], qx[200], qy[200];
  snprintf(title, sizeof title, "whirl run: %s (model %s)", whirl_runfile_name(R->rf),
           R->prob.name);
  int x = R->plot_x, y = R->plot_y;
  cli_gp_preamble(f, "run", "diagram", 900, 650, "Sans,11");
  fprintf(f,
          "set datafile separator '\\t'\n"
          "set key top left\n"
          "set grid lc rgb '#dddddd'\n"
          "set title %s noenhanced\n"
          "set xlabel %s noenhanced\n"
          "set ylabel %s noenhanced\n"
          "S = %zu\n"
          "plot ",
          cli_gp_quote(title, qtitle, sizeof qtitle), cli_gp_quote(R->plot_x_name, qx, sizeof qx),
          cli_gp_quote(R->plot_y_name, qy, sizeof qy), R->ncols);
  /* only the series that have points (gnuplot warns about empty ones) */
  int first = 1;
  for (int k = 2; k >= 0; k--) {
    if (!R->seen_stab[k]) continue;
    fprintf(f, "%s'branches.tsv' using %d:", first ? "" : ", \\\n     ", x);
    if (k == 2)
      fprintf(f, "(column(S) == 1 ? column(%d) : NaN) with lines lw 2 lc rgb "
              "'#1f4e9c' title 'stable'", y);
    else if (k == 1)
      fprintf(f, "(column(S) == 0 ? column(%d) : NaN) with lines lw 2 dt 2 lc "
              "rgb '#c0392b' title 'unstable'", y);
    else
      fprintf(f, "(column(S) < 0 ? column(%d) : NaN) with lines lw 1 lc rgb "
              "'#777777' title 'stability unknown'", y);
    first = 0;
  }
  if (R->seen_special)
    fprintf(f, ", \\\n     'branches.tsv' using %d:(strcol(3) ne 'RG' && "
            "strcol(3) ne 'EP' ? column(%d) : NaN) with points pt 7 ps 1 lc "
            "rgb 'black' notitle, \\\n     'branches.tsv' using %d:(strcol(3) "
            "ne 'RG' && strcol(3) ne 'EP' ? column(%d) : NaN):3 with labels "
            "offset 1,0.7 notitle", x, y, x, y);
  fputc('\n', f);
  return cli_outdir_fclose(&R->od, f, "diagram.gp");
}

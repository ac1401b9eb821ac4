/* drivers/run_plot.c — the picture of `whirl run`: the gnuplot script of
 * the bifurcation diagram (diagram.gp over branches.tsv) or of the basins
 * (basins.gp over basins.tsv), from what the run says it drew
 * (whirl_run_plot_info).  Every name the user chose is quoted for gnuplot.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>

#include <whirl/whirl.h>

#include "cli.h"
#include "run_cmd.h"
#include "run_plot_impl.h"

/* One series of the diagram: the rows of branch BR whose STAB column
 * (gnuplot variable S) is K, NaN elsewhere: gnuplot breaks a line at an
 * undefined point, so a stable stretch is not joined across an unstable
 * one (no 'set datafile missing', which would make it skip those points
 * and join them), and, each branch its own series, the end of one branch
 * is not joined to the start of the next.  TITLED: the key's entry. */
static void diagram_series(FILE *f, int x, int y, int br, int k, int titled) {
  static const char *const cond[3] = {"< 0", "== 0", "== 1"};
  static const char *const style[3] = {
      "lw 1 lc rgb '#777777'", "lw 2 dt 2 lc rgb '#c0392b'", "lw 2 lc rgb '#1f4e9c'"};
  static const char *const name[3] = {"stability unknown", "unstable", "stable"};
  fprintf(f, "'branches.tsv' using %d:(column(1) == %d && column(S) %s ? column(%d) : NaN) "
          "with lines %s ", x, br, cond[k], y, style[k]);
  if (titled) fprintf(f, "title '%s'", name[k]);
  else fprintf(f, "notitle");
}

/* Stable parts solid, unstable dashed, unknown thin, each branch on its
 * own; labelled special points marked and named. */
static int write_diagram(cli_outdir *od, const whirl_run *r, const whirl_run_plot *pl) {
  FILE *f = cli_outdir_fopen(od, "diagram.gp");
  if (!f) return -1;
  char title[1024], qtitle[2100], qx[200], qy[200];
  snprintf(title, sizeof title, "whirl run: %s (model %s)", whirl_run_file_name(r),
           whirl_run_model_name(r));
  const int x = pl->x, y = pl->y;
  cli_gp_preamble(f, "run", "diagram", 900, 650, "Sans,11");
  if (pl->seen_special) run_plot_labels(f, od, r, pl);
  fprintf(f,
          "set datafile separator '\t'\n"
          "set key outside bottom center horizontal\nset bmargin 5\n" /* off the curves, under the x label */
          "set grid lc rgb '#dddddd'\n"
          "set title %s noenhanced\n"
          "set xlabel %s noenhanced\n"
          "set ylabel %s noenhanced\n"
          "S = %zu\n"
          "plot ",
          cli_gp_quote(title, qtitle, sizeof qtitle), cli_gp_quote(pl->x_name, qx, sizeof qx),
          cli_gp_quote(pl->y_name, qy, sizeof qy), pl->stab_col);
  /* only the series that have points (gnuplot warns about empty ones) */
  int first = 1;
  for (int k = 2; k >= 0; k--) {
    int titled = 0;
    for (size_t b = 0; b < pl->nbranches; b++) {
      if (!(pl->branch_stab[b] & 1 << k)) continue;
      fprintf(f, "%s", first ? "" : ", \\\n     ");
      diagram_series(f, x, y, pl->branches[b], k, !titled);
      first = 0;
      titled = 1;
    }
  }
  if (pl->seen_special)
    fprintf(f, ", \\\n     'branches.tsv' using %d:(strcol(3) ne '-' && "
            "strcol(3) ne 'EP' ? column(%d) : NaN) with points pt 7 ps 1 lc "
            "rgb 'black' notitle", x, y);
  fputc('\n', f);
  return cli_outdir_fclose(od, f, "diagram.gp");
}

/* The initial states coloured by the attractor they end on. */
static int write_basins(cli_outdir *od, const whirl_run *r, const whirl_run_plot *pl) {
  FILE *f = cli_outdir_fopen(od, "basins.gp");
  if (!f) return -1;
  char title[400], qt[900], qx[200], qy[200];
  snprintf(title, sizeof title, "whirl run: basins of attraction (model %s)",
           whirl_run_model_name(r));
  cli_gp_preamble(f, "run", "basins", 800, 700, "Sans,11");
  fprintf(f,
          "set datafile separator '\\t'\n"
          "set title %s noenhanced\n"
          "set xlabel %s noenhanced\nset ylabel %s noenhanced\n"
          "set size ratio -1\nset tics out\nunset colorbox\n"
          "set palette defined (-3 'black', -2 '#555555', -1 'white', 0 '#1f4e9c', "
          "1 '#e67e22', 2 '#27ae60', 3 '#8e44ad')\n"
          "set cbrange [-3:3]\n",
          cli_gp_quote(title, qt, sizeof qt), cli_gp_quote(pl->x_name, qx, sizeof qx),
          cli_gp_quote(pl->y_name, qy, sizeof qy));
  fprintf(f, "map(c) = c < 0 ? c : (");
  for (size_t a = 0; a < pl->nattractors; a++)
    fprintf(f, "c == %d ? %zu : ", pl->attractors[a], a % 4);
  fprintf(f, "0)\nplot 'basins.tsv' using 1:2:(map($3)) with image notitle");
  for (size_t a = 0; a < pl->nattractors; a++)
    fprintf(f, ", \\\n     NaN with boxes fs solid lc palette cb %zu title 'LAB %d'",
            a % 4, pl->attractors[a]);
  fputc('\n', f);
  return cli_outdir_fclose(od, f, "basins.gp");
}

int run_write_plot(cli_outdir *od, const whirl_run *r, const char **name) {
  const whirl_run_plot *pl = whirl_run_plot_info(r);
  *name = pl->basins ? "basins" : "diagram";
  return pl->basins ? write_basins(od, r, pl) : write_diagram(od, r, pl);
}

/* drivers/overlay_gp.c — the gnuplot script of `whirl plot overlay`: the
 * runs' points in datablocks (the script redraws the picture on its own,
 * wherever the runs went since), one colour a run, the line styles of the
 * single-run pictures (stable solid, unstable dashed, folds marked), and
 * the legend outside the axes so that it never covers a curve.  Every
 * string the user chose is quoted for gnuplot (cli_gp_quote).
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "overlay.h"

/* One colour a run (Tableau 10, distinguishable in print), repeated after 8. */
static const char *const colour[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                     "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
#define NCOLOUR (sizeof colour / sizeof *colour)

/* The "k=v" words of PARAMS as keys and values (at most OV_PAIRS). */
#define OV_PAIRS 16
typedef struct pairs {
  char k[OV_PAIRS][32], v[OV_PAIRS][64];
  size_t n;
} pairs;
static void pairs_of(const char *params, pairs *p) {
  char buf[512];
  snprintf(buf, sizeof buf, "%s", params);
  p->n = 0;
  for (char *save = NULL, *t = strtok_r(buf, " ", &save); t && p->n < OV_PAIRS;
       t = strtok_r(NULL, " ", &save)) {
    char *eq = strchr(t, '=');
    *eq = '\0';
    snprintf(p->k[p->n], sizeof p->k[0], "%s", t);
    snprintf(p->v[p->n++], sizeof p->v[0], "%s", eq + 1);
  }
}

void ov_default_labels(const ov_run *runs, size_t n, char (*out)[256], char *common,
                       size_t clen) {
  pairs *p = n >= 2 ? calloc(n, sizeof *p) : NULL;
  int same = p != NULL;
  for (size_t k = 0; k < n && same; k++) {
    pairs_of(runs[k].params, &p[k]);
    same = p[k].n > 0 && p[k].n == p[0].n;
    for (size_t i = 0; same && i < p[k].n; i++) same = !strcmp(p[k].k[i], p[0].k[i]);
  }
  int differ[OV_PAIRS] = {0}, some = 0;
  for (size_t i = 0; same && i < p[0].n; i++)
    for (size_t k = 1; k < n; k++)
      if (strcmp(p[k].v[i], p[0].v[i])) some = differ[i] = 1;
  common[0] = '\0';
  for (size_t i = 0, used = 0; same && i < p[0].n; i++) /* what the runs share */
    if (!differ[i] && used + 2 < clen)
      used += (size_t)snprintf(common + used, clen - used, "%s%s=%s", used ? ", " : "",
                               p[0].k[i], p[0].v[i]);
  for (size_t k = 0; k < n; k++) {
    out[k][0] = '\0';
    if (!same || !some) { /* nothing to tell them apart by: their directories */
      snprintf(out[k], 256, "%.255s", runs[k].dir);
      continue;
    }
    for (size_t i = 0, used = 0; i < p[k].n; i++)
      if (differ[i] && used < 250)
        used += (size_t)snprintf(out[k] + used, 256 - used, "%s%s=%s", used ? ", " : "",
                                 p[k].k[i], p[k].v[i]);
  }
  free(p);
}

/* The points of R of stability STAB as pieces of curve, each begun at the
 * point before it on its segment so that the curve stays joined where the
 * stability changes (as the sfd response picture does).  Returns the
 * number of points written. */
static size_t block(FILE *f, const ov_run *r, int stab) {
  size_t w = 0;
  int open = 0;
  for (size_t i = 0; i < r->n; i++) {
    const ov_point *p = &r->pt[i];
    const int same_seg = i > 0 && r->pt[i - 1].seg == p->seg;
    if (open && !same_seg) fputc('\n', f), open = 0;
    if (p->stab != stab) {
      if (open) fputc('\n', f), open = 0;
      continue;
    }
    if (!open && same_seg) fprintf(f, "%.10g\t%.10g\n", r->pt[i - 1].x, r->pt[i - 1].y);
    fprintf(f, "%.10g\t%.10g\n", p->x, p->y);
    open = 1;
    w++;
  }
  return w;
}

static size_t folds(FILE *f, const ov_run *r) {
  size_t w = 0;
  for (size_t i = 0; i < r->n; i++)
    if (r->pt[i].lp) fprintf(f, "%.10g\t%.10g\n", r->pt[i].x, r->pt[i].y), w++;
  return w;
}

/* The axis label of a column: what it is, for the names of doc/tables.md. */
static void axis(FILE *f, const char *which, const char *name) {
  static const struct { const char *name, *label; } known[] = {
      {"Omega", "dimensionless speed {/Symbol W}"},
      {"eps", "orbit radius / clearance {/Symbol e}"},
      {"eps_max", "largest eccentricity {/Symbol e}_{max}"},
      {"eps_min", "smallest eccentricity {/Symbol e}_{min}"},
      {"amplitude_m", "amplitude (m)"},
      {"speed_rpm", "shaft speed (rpm)"},
      {"speed_rad_s", "shaft speed (rad/s)"},
      {"l2_norm", "L2-NORM"},
      {"f2", "second frequency f_2 / {/Symbol W}"}};
  char q[200];
  for (size_t k = 0; k < sizeof known / sizeof *known; k++)
    if (!strcmp(name, known[k].name)) {
      fprintf(f, "set %s '%s'\n", which, known[k].label);
      return;
    }
  fprintf(f, "set %s %s noenhanced\n", which, cli_gp_quote(name, q, sizeof q));
}

/* "plot" before the first series, ", \" before the others. */
static void sep(FILE *f, int *first) {
  fputs(*first ? "plot " : ", \\\n     ", f);
  *first = 0;
}

/* The series of run K (1-based) whose datablocks have points. */
static void series(FILE *f, size_t k, const size_t have[4], const char *c, int *first) {
  static const char *const style[3] = {"lw 2", "lw 2 dt 2", "lw 1"};
  static const char *const name[3] = {"s", "u", "n"};
  for (int s = 0; s < 3; s++)
    if (have[s]) {
      sep(f, first);
      fprintf(f, "$%s%zu using 1:2 with lines %s lc rgb '%s' notitle", name[s], k, style[s], c);
    }
  if (have[3]) {
    sep(f, first);
    fprintf(f, "$lp%zu using 1:2 with points pt 7 ps 1.3 lc rgb '%s' notitle", k, c);
  }
}

int ov_write_gp(FILE *f, const ov_run *runs, size_t n, const char (*labels)[256],
                const char *title, const char *name) {
  char q[1200];
  size_t have[64][4] = {{0}}, any[4] = {0};
  double ymin = 0;
  cli_gp_preamble(f, "plot overlay", name, 1100, 700, "Sans,12");
  for (size_t k = 0; k < n && k < 64; k++) {
    static const int stab[3] = {1, 0, -1};
    static const char *const bn[3] = {"s", "u", "n"};
    for (int s = 0; s < 3; s++) {
      fprintf(f, "$%s%zu << EOD\n", bn[s], k + 1);
      any[s] += have[k][s] = block(f, &runs[k], stab[s]);
      fputs("EOD\n", f);
    }
    fprintf(f, "$lp%zu << EOD\n", k + 1);
    any[3] += have[k][3] = folds(f, &runs[k]);
    fputs("EOD\n", f);
    for (size_t i = 0; i < runs[k].n; i++)
      if (runs[k].pt[i].y < ymin) ymin = runs[k].pt[i].y;
  }
  fprintf(f, "set title %s noenhanced\n", cli_gp_quote(title, q, sizeof q));
  axis(f, "xlabel", runs[0].xname);
  axis(f, "ylabel", runs[0].yname);
  /* the legend beside the axes, never on a curve */
  fputs("set key outside right top vertical Left reverse box width 1\nset grid\n", f);
  if (ymin >= 0) fputs("set yrange [0:*]\n", f);
  int first = 1;
  for (size_t k = 0; k < n && k < 64; k++)
    series(f, k + 1, have[k], colour[k % NCOLOUR], &first);
  for (size_t k = 0; k < n && k < 64; k++) { /* the legend: one entry a run */
    sep(f, &first);
    fprintf(f, "NaN with lines lw 2 lc rgb '%s' title %s noenhanced", colour[k % NCOLOUR],
            cli_gp_quote(labels[k], q, sizeof q));
  }
  if (any[0]) sep(f, &first), fputs("NaN with lines lw 2 lc rgb 'black' title 'stable'", f);
  if (any[1]) sep(f, &first), fputs("NaN with lines lw 2 dt 2 lc rgb 'black' title 'unstable'", f);
  if (any[2]) sep(f, &first), fputs("NaN with lines lw 1 lc rgb 'black' title 'stability not computed'", f);
  if (any[3]) sep(f, &first), fputs("NaN with points pt 7 ps 1.3 lc rgb 'black' title 'LP (fold)'", f);
  fputc('\n', f);
  return ferror(f) ? -1 : 0;
}

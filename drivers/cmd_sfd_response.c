/* drivers/cmd_sfd_response.c — `whirl sfd response`: every branch of
 * synchronous circular orbits of the SFD rotor for Ω in (0, W], with
 * stability, Floquet multipliers and special points, as TSV and PNG.
 * Outputs: DIR/branches.tsv, DIR/special.tsv, DIR/response.png (ε vs Ω, as
 * the paper's Fig. 3), DIR/multipliers.png (largest multiplier modulus, as
 * Figs. 4–5), and the gnuplot scripts that drew them.  Special points also go
 * to stdout as TSV.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, fileno */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/rotor.h>

#include "cli.h"
#include "util/fmt_num.h"
#include "sfd_common.h"

#define CMD "sfd response"

static const cli_doc doc = {
"usage: whirl sfd response [options]\n"
"\n"
"All branches of synchronous orbits of the rigid rotor on two short\n"
"squeeze-film dampers (pi-film), for omega-min <= Omega <= omega-max: the\n"
"main resonance branch and any isolated branch (isola), found by seeding the\n"
"continuation from every real root of the circular-orbit polynomial (paper\n"
"eq. 15).  Stability from the rotating-frame eigenvalues mu, reported as\n"
"fixed-frame Floquet multipliers exp(2 pi mu / Omega).\n"
"\n"
"options (defaults: Table 1 of the paper):\n",
"outputs: DIR/branches.tsv (branch pt type label Omega eps phase u v stable\n"
"n_unstable max_multiplier mu_re mu_im), DIR/special.tsv, DIR/response.png,\n"
"DIR/multipliers.png.  stdout: the special points as TSV.  phase is beta of\n"
"eqs. 16-17 (radians): the journal lags the unbalance by beta.  With\n"
"hbm/colloc, eps is the LARGEST eccentricity of the orbit (eps_min the\n"
"smallest), stability comes from the monodromy matrix (variational\n"
"equations), and branches.tsv adds eps_min, period and residual columns.\n"
"\n"
"exit status: 0; 2 for bad options (nothing computed); 1 when the run\n"
"failed: no branch found, or a branch ended at DSMIN without convergence\n"
"or with a persisting domain error (one line per branch on stderr; the\n"
"tables are still written).\n"};

typedef struct row {
  int branch, pt, label, stable, nu, itype;
  const char *type;
  double Om, eps, phase, u, v, maxmult, mure, muim;
  double eps_min, period, residual; /* periodic methods only */
} row;

/* The response as rows, whatever method produced it. */
typedef struct tab {
  size_t nbranch;
  size_t *len;
  row **rows;
  int *isola;
  int *stop;
} tab;

static void tab_free(tab *t) {
  for (size_t b = 0; b < t->nbranch; ++b) free(t->rows[b]);
  free(t->rows);
  free(t->len);
  free(t->isola);
  free(t->stop);
  memset(t, 0, sizeof *t);
}

static int tab_alloc(tab *t, size_t nbranch) {
  memset(t, 0, sizeof *t);
  t->nbranch = nbranch;
  t->len = calloc(nbranch + 1, sizeof *t->len);
  t->rows = calloc(nbranch + 1, sizeof *t->rows);
  t->isola = calloc(nbranch + 1, sizeof *t->isola);
  t->stop = calloc(nbranch + 1, sizeof *t->stop);
  return t->len && t->rows && t->isola && t->stop ? 0 : -1;
}

/* Branches that ended in failure (DSMIN reached without convergence, a
 * domain error persisting to DSMIN): one line each on stderr naming the
 * branch, its last point and the reason; returns their number.  No branch
 * at all is a failure too: with delta > 0 the main resonance branch exists
 * for every speed. */
static size_t report_failures(const tab *t) {
  if (t->nbranch == 0) {
    cli_error(CMD, "no branch of orbits found (at least the main resonance branch "
                   "should exist): the computation failed");
    return 1;
  }
  size_t nfail = 0;
  for (size_t b = 0; b < t->nbranch; ++b) {
    if (t->stop[b] != WHIRL_STOP_NOCONV && t->stop[b] != WHIRL_STOP_DOMAIN) continue;
    const row *last = t->len[b] ? &t->rows[b][t->len[b] - 1] : NULL;
    cli_error(CMD, "branch %zu failed after point %zu (Omega = %.10g, eps = %.6g): %s",
              b + 1, t->len[b], last ? last->Om : NAN, last ? last->eps : NAN,
              whirl_stop_reason_name(t->stop[b]));
    ++nfail;
  }
  return nfail;
}

static row make_row(const whirl_branch *b, size_t i) {
  const whirl_branch_point *q = &b->pts[i];
  row r;
  r.branch = b->id;
  r.pt = (int)i;
  r.label = q->label;
  r.type = whirl_point_type_name(q->type);
  r.stable = q->stable;
  r.nu = q->n_unstable;
  r.Om = q->p[WHIRL_SFD_OMEGA];
  r.u = q->x[0];
  r.v = q->x[1];
  r.eps = hypot(r.u, r.v);
  r.phase = atan2(-r.v, r.u);
  r.mure = b->nspec ? q->spec_re[0] : NAN;
  r.muim = b->nspec ? fabs(q->spec_im[0]) : NAN;
  r.maxmult = exp(2.0 * WHIRL_PI * r.mure / r.Om);
  r.itype = q->type;
  r.eps_min = r.eps;
  r.period = 2.0 * WHIRL_PI / r.Om;
  r.residual = NAN;
  return r;
}

static int tab_from_circular(tab *t, const whirl_sfd_response *res,
                             double omega_min) {
  if (tab_alloc(t, res->nbranch)) return -1;
  for (size_t b = 0; b < res->nbranch; ++b) {
    const whirl_branch *br = res->branch[b];
    t->rows[b] = malloc((br->len + 1) * sizeof *t->rows[b]);
    if (!t->rows[b]) return -1;
    t->len[b] = br->len;
    double lo = INFINITY;
    for (size_t i = 0; i < br->len; ++i) {
      t->rows[b][i] = make_row(br, i);
      lo = fmin(lo, t->rows[b][i].Om);
    }
    t->isola[b] = !(lo <= omega_min * (1 + 1e-12));
    t->stop[b] = br->stop_reason;
  }
  return 0;
}

static int tab_from_periodic(tab *t, const whirl_sfd_periodic *res) {
  if (tab_alloc(t, res->nbranch)) return -1;
  for (size_t b = 0; b < res->nbranch; ++b) {
    const whirl_sfd_periodic_branch *br = &res->br[b];
    t->rows[b] = malloc((br->len + 1) * sizeof *t->rows[b]);
    if (!t->rows[b]) return -1;
    t->len[b] = br->len;
    t->isola[b] = br->isola;
    t->stop[b] = br->stop_reason;
    for (size_t i = 0; i < br->len; ++i) {
      const whirl_sfd_orbit *q = &br->pts[i];
      row *r = &t->rows[b][i];
      r->branch = br->id;
      r->pt = (int)i;
      r->label = q->label;
      r->itype = q->type;
      r->type = whirl_point_type_name(q->type);
      r->stable = q->stable;
      r->nu = q->n_unstable;
      r->Om = q->Omega;
      r->eps = q->eps_max;
      r->eps_min = q->eps_min;
      r->phase = q->phase;
      r->u = q->a1;
      r->v = -q->b1;
      r->maxmult = q->max_mult;
      r->mure = q->mult_re;
      r->muim = q->mult_im;
      r->period = q->period;
      r->residual = q->residual;
    }
  }
  return 0;
}

static int is_special(int type) { return type != WHIRL_PT_REGULAR; }

static void print_special_header(FILE *f) {
  fprintf(f, "type\tbranch\tlabel\tOmega\teps\tphase\tstable\tmax_multiplier\tmeaning\n");
}

static void print_special(FILE *f, const row *r, int type) {
  const char *ff = type == WHIRL_PT_LP   ? "saddle-node of the synchronous orbit"
                   : type == WHIRL_PT_HB ? "Neimark-Sacker (torus, TR) of the orbit"
                   : type == WHIRL_PT_TR ? "Neimark-Sacker (torus, TR) of the orbit"
                   : type == WHIRL_PT_PD ? "period doubling of the orbit"
                   : type == WHIRL_PT_BP ? "branch point"
                   : type == WHIRL_PT_UZ ? "orbit at the requested speed"
                                         : "end of the branch";
  fprintf(f, "%s\t%d\t%d\t%.15g\t%.15g\t%.15g\t%d\t%.10g\t%s\n", r->type, r->branch,
          r->label, r->Om, r->eps, r->phase, r->stable, r->maxmult, ff);
}

/* The letters A-D of the regions between the three LP speeds LP (sorted)
 * on [0, WMAX] (Fig. 3), above the frame: inside it they sat on the
 * upper branch (D) and between B's two red lines, 0.22 apart.  Each is at
 * its region's middle, pushed apart to 4 % of the axis so that a narrow
 * region's letter does not run into its neighbour's. */
static void region_letters(FILE *f, const double *lp, double wmax) {
  const double gap = 0.04 * wmax;
  double xs[4] = {0.5 * lp[0], 0.5 * (lp[0] + lp[1]), 0.5 * (lp[1] + lp[2]),
                  0.5 * (lp[2] + wmax)};
  for (int i = 1; i < 4; ++i)
    if (xs[i] < xs[i - 1] + gap) xs[i] = xs[i - 1] + gap;
  for (int i = 2; i >= 0 && xs[3] > wmax; --i) /* the last past the end: back */
    if (xs[i] > xs[i + 1] - gap) xs[i] = xs[i + 1] - gap;
  if (xs[3] > wmax) xs[3] = wmax;
  fprintf(f, "set tmargin 5\n"); /* the title moved up above them */
  for (int i = 0; i < 4; ++i)
    fprintf(f, "set label '%c' at %.10g, graph 1.035 center font 'Sans,14' tc rgb '#d62728'\n",
            'A' + i, xs[i]);
}

/* Row R of branches.tsv in LINE (room for 512 bytes), its length: as
 * "%d\t%d\t%s\t%d" then "\t%.10e" five times, "\t%d\t%d", "\t%.10e" three
 * times (and the periodic methods' three more) and "\n" would print it, by
 * fmt_num.h: the same text in a fifth of printf's time. */
static size_t table_row(char *line, const row *r, int periodic) {
  const double state[] = {r->Om, r->eps, r->phase, r->u, r->v};
  const double mult[] = {r->maxmult, r->mure, r->muim};
  const char *type = r->itype ? r->type : "-";
  size_t n = 0;
  n += (size_t)fmt_d(line + n, r->branch);
  line[n++] = '\t';
  n += (size_t)fmt_d(line + n, r->pt);
  line[n++] = '\t';
  n += (size_t)snprintf(line + n, 16, "%.8s", type);
  line[n++] = '\t';
  n += (size_t)fmt_d(line + n, r->label);
  for (size_t k = 0; k < 5; ++k) line[n++] = '\t', n += (size_t)fmt_e(line + n, FMT_NUM_SIZE, state[k], 10);
  line[n++] = '\t';
  n += (size_t)fmt_d(line + n, r->stable);
  line[n++] = '\t';
  n += (size_t)fmt_d(line + n, r->nu);
  for (size_t k = 0; k < 3; ++k) line[n++] = '\t', n += (size_t)fmt_e(line + n, FMT_NUM_SIZE, mult[k], 10);
  if (periodic)
    n += (size_t)snprintf(line + n, 128, "\t%.10e\t%.10e\t%.3e", r->eps_min, r->period, r->residual);
  line[n++] = '\n';
  return n;
}

/* a data line of a script: "%.8g %.8g\n" (fmt_num.h) */
static void put_pair(FILE *f, double x, double y) {
  fmt_put_g(f, x, 8);
  fputc(' ', f);
  fmt_put_g(f, y, 8);
  fputc('\n', f);
}

/* Gnuplot script for ε against Ω: stable solid, unstable dashed, LP marked,
 * red dashed region borders at the LPs (Fig. 3). */
static int write_response_gp(cli_outdir *od, const tab *res,
                             const double *p, double wmax, const char *ylab) {
  out_file o;
  if (out_open(&o, od, "response.gp")) return -1;
  FILE *f = o.fp;
  double lp[64];
  int nlp = 0;
  cli_gp_preamble(f, CMD, "response", 1100, 750, "Sans,12");
  for (int pass = 0; pass < 2; ++pass) {
    fprintf(f, "$%s << EOD\n", pass == 0 ? "stable" : "unstable");
    for (size_t b = 0; b < res->nbranch; ++b) {
      const row *br = res->rows[b];
      int open = 0;
      for (size_t i = 0; i < res->len[b]; ++i) {
        int st = br[i].stable == 1;
        int want = pass == 0;
        if (st == want) {
          if (!open && i > 0) put_pair(f, br[i - 1].Om, br[i - 1].eps);
          put_pair(f, br[i].Om, br[i].eps);
          open = 1;
        } else if (open) {
          fprintf(f, "\n");
          open = 0;
        }
      }
      fprintf(f, "\n");
    }
    fprintf(f, "EOD\n");
  }
  fprintf(f, "$special << EOD\n0 -1\n");
  for (size_t b = 0; b < res->nbranch; ++b)
    for (size_t i = 0; i < res->len[b]; ++i)
      if (res->rows[b][i].itype == WHIRL_PT_LP) {
        const row *r = &res->rows[b][i];
        fprintf(f, "%.10g %.10g\n", r->Om, r->eps);
        if (nlp < 64) lp[nlp++] = r->Om;
      }
  fprintf(f, "EOD\n");
  /* sort LP speeds for the region borders */
  for (int i = 1; i < nlp; ++i)
    for (int j = i; j > 0 && lp[j] < lp[j - 1]; --j) {
      double t = lp[j];
      lp[j] = lp[j - 1];
      lp[j - 1] = t;
    }
  for (int i = 0; i < nlp; ++i)
    fprintf(f, "set arrow from %.10g, graph 0 to %.10g, graph 1 nohead dt 2 lw 1.5 lc rgb '#d62728'\n",
            lp[i], lp[i]);
  if (nlp == 3) region_letters(f, lp, wmax);
  char title[256];
  fprintf(f,
          "set title 'SFD rigid rotor, %s: %s'%s\n"
          "set xlabel 'dimensionless speed {/Symbol W}'\n"
          "set ylabel '%s'\n"
          "set xrange [0:%g]\nset yrange [0:1]\nset grid\nset key outside right top box\n"
          "plot $stable using 1:2 with lines lw 2.5 lc rgb '#1f4e9c' title 'stable', \\\n"
          "     $unstable using 1:2 with lines dt 2 lw 2.5 lc rgb '#1f4e9c' title 'unstable', \\\n"
          "     $special using 1:2 with points pt 7 ps 1.6 lc rgb '#2ca02c' title 'LP (saddle-node)'\n",
          p[WHIRL_SFD_FE] == 0.0 ? "circular orbits" : "synchronous orbits",
          sfd_gp_params(title, sizeof title, p, SFD_P_MODEL | SFD_P(WHIRL_SFD_FE)),
          nlp == 3 ? " offset 0,1.2" : "", ylab, wmax);
  return out_commit(&o);
}

/* The lower end of the multipliers' axis (see write_multipliers_gp). */
#define SFD_MULT_FLOOR 1e-3

/* Gnuplot script for the largest Floquet multiplier modulus (Figs. 4-5). */
static int write_multipliers_gp(cli_outdir *od, const tab *res,
                                double wmax) {
  out_file o;
  if (out_open(&o, od, "multipliers.gp")) return -1;
  FILE *f = o.fp;
  cli_gp_preamble(f, CMD, "multipliers", 1100, 750, "Sans,12");
  for (size_t b = 0; b < res->nbranch; ++b) {
    fprintf(f, "$b%zu << EOD\n", b + 1);
    for (size_t i = 0; i < res->len[b]; ++i)
      put_pair(f, res->rows[b][i].Om, res->rows[b][i].maxmult);
    fprintf(f, "EOD\n");
  }
  fprintf(f,
          "set title 'largest Floquet multiplier modulus of the synchronous orbits'\n"
          "set xlabel 'dimensionless speed {/Symbol W}'\nset ylabel 'max |{/Symbol r}|'\n"
          /* from 1e-3: slow orbits' multipliers reach 1e-22, which squeezed
           * the part that matters, around 1, into a tenth of the axis; the
           * legend beside the axes, off the curves near 1 */
          "set xrange [0:%g]\nset logscale y\nset yrange [%g:*]\nset grid\n"
          "set key outside right top box\n"
          "set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2 lw 1.5 lc rgb '#d62728'\n"
          "plot ",
          wmax, SFD_MULT_FLOOR);
  for (size_t b = 0; b < res->nbranch; ++b)
    fprintf(f, "%s$b%zu using 1:2 with lines lw 2 title 'branch %zu'", b ? ", " : "", b + 1, b + 1);
  fprintf(f, "\n");
  return out_commit(&o);
}

/* Is the ds option given explicitly?  (Its default differs by method.) */
static int has_option(int argc, char **argv, const char *name) {
  const size_t n = strlen(name);
  for (int i = 1; i < argc; ++i)
    if (!strncmp(argv[i], name, n) && (argv[i][n] == '\0' || argv[i][n] == '='))
      return 1;
  return 0;
}

int cmd_sfd_response(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  whirl_sfd_response_options o;
  whirl_sfd_response_options_default(&o);
  whirl_sfd_periodic_options po;
  whirl_sfd_periodic_options_default(&po);
  const char *dir = "sfd-response", *method_name = NULL;
  int plot = 1, quiet = 0, sparse = 0, noplot = 0;
  double omega_min = NAN, uz = NAN;
  /* defaults that depend on the method */
  char omega_min_shown[64], ds_shown[64];
  snprintf(omega_min_shown, sizeof omega_min_shown, "%g; hbm/colloc %g", o.omega_min,
           po.omega_min);
  snprintf(ds_shown, sizeof ds_shown, "%g; hbm/colloc %g, the paper's", o.ds, po.ds);
  const cli_opt opts[] = {
      SFD_OPT_LAMBDA(p),
      SFD_OPT_PARAM(p, WHIRL_SFD_DELTA, "--delta", "D",
                    "unbalance delta = e_G/c, 0 < D <= 10"),
      SFD_OPT_ZETA(p),
      {"--omega-max", CLI_DOUBLE, &o.omega_max, "W", "largest speed, W <= 1000", NULL},
      {"--omega-min", CLI_DOUBLE, &omega_min, "M", "smallest speed, 0 < M < W", omega_min_shown},
      SFD_OPT_FE(p),
      {"--method", CLI_STRING, &method_name, "M",
       "circular | hbm | colloc: circular orbits from the rotating-frame equilibria (F_E = 0 "
       "only; the default then), or fixed-frame periodic orbits by harmonic balance (default "
       "when F_E != 0) or by collocation", ""},
      {"--harmonics", CLI_SIZE, &po.harmonics, "N", "HBM harmonics as in the paper", NULL},
      {"--oversampling", CLI_SIZE, &po.oversampling, "K",
       "HBM: K (2N+1) time samples (AFT) as in the paper", NULL},
      {"--ntst", CLI_SIZE, &po.ntst, "N", "collocation mesh intervals", NULL},
      {"--ncol", CLI_SIZE, &po.ncol, "C", "collocation points per interval", NULL},
      {"--uz", CLI_DOUBLE, &uz, "W", "hbm/colloc: also report the orbits at Omega = W (UZ)", ""},
      {"--ds", CLI_DOUBLE, &o.ds, "S", "first continuation step", ds_shown},
      {"--ds-max", CLI_DOUBLE, &o.ds_max, "S", "largest continuation step (DSMAX)", NULL},
      {"--sparse", CLI_FLAG, &sparse, NULL, "use the sparse (UMFPACK) linear solver", NULL},
      CLI_OPTS_OUT(dir, noplot, quiet)};
  int prc = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (prc) return prc == 1 ? 0 : 2;
  plot = !noplot;
  int method = p[WHIRL_SFD_FE] != 0.0 ? WHIRL_SFD_METHOD_HBM : WHIRL_SFD_METHOD_CIRCULAR;
  if (method_name) {
    if (!strcmp(method_name, "circular")) method = WHIRL_SFD_METHOD_CIRCULAR;
    else if (!strcmp(method_name, "hbm")) method = WHIRL_SFD_METHOD_HBM;
    else if (!strcmp(method_name, "colloc")) method = WHIRL_SFD_METHOD_COLLOC;
    else {
      cli_error(CMD, "--method must be circular, hbm or colloc (got '%s')", method_name);
      return 2;
    }
  }
  const int periodic = method != WHIRL_SFD_METHOD_CIRCULAR;
  if (!periodic && p[WHIRL_SFD_FE] != 0.0) {
    cli_error(CMD, "--method circular needs --fe 0: with F_E = %g the orbits are not "
                   "circular (use --method hbm or colloc)", p[WHIRL_SFD_FE]);
    return 2;
  }
  if (!has_option(argc, argv, "--ds") && periodic) o.ds = po.ds;
  if (!(omega_min == omega_min)) omega_min = periodic ? po.omega_min : o.omega_min;
  o.omega_min = omega_min;
  if (periodic && (po.harmonics < 1 || po.harmonics > 200)) {
    cli_error(CMD, "--harmonics must be in 1..200 (got %zu)", po.harmonics);
    return 2;
  }
  if (periodic && (po.oversampling < 1 || po.oversampling > 100)) {
    cli_error(CMD, "--oversampling must be in 1..100 (got %zu)", po.oversampling);
    return 2;
  }
  if (periodic && (po.ntst < 2 || po.ntst > WHIRL_COLLOC_MAX_NTST || po.ncol < 2 || po.ncol > 7)) {
    cli_error(CMD, "need 2 <= --ntst <= %d and 2 <= --ncol <= 7 (got %zu, %zu)",
              WHIRL_COLLOC_MAX_NTST, po.ntst, po.ncol);
    return 2;
  }
  if (sparse) o.linsol = WHIRL_LINSOL_SPARSE;
  /* parameters are checked before anything is computed or written */
  char msg[512];
  if (!(o.omega_max <= WHIRL_SFD_OMEGA_MAX)) {
    cli_error(CMD, "--omega-max must be <= %g (got %g)", WHIRL_SFD_OMEGA_MAX, o.omega_max);
    return 2;
  }
  p[WHIRL_SFD_OMEGA] = o.omega_max;
  if (sfd_check(CMD, p, 0)) return 2;
  if (!(p[WHIRL_SFD_DELTA] > 0)) {
    cli_error(CMD, "--delta must be > 0: without unbalance the rotor stays in the "
                   "centre and there is no orbit to trace");
    return 2;
  }
  if (!(o.omega_min > 0) || !(o.omega_max > o.omega_min)) {
    cli_error(CMD, "need 0 < --omega-min < --omega-max (got %g and %g)", o.omega_min,
              o.omega_max);
    return 2;
  }
  if (!(o.ds > 0) || !(o.ds_max >= o.ds)) {
    cli_error(CMD, "need 0 < --ds <= --ds-max (got %g and %g)", o.ds, o.ds_max);
    return 2;
  }
  if (uz == uz) {
    if (!periodic || !(uz > o.omega_min && uz < o.omega_max)) {
      cli_error(CMD, "--uz needs --method hbm or colloc and omega-min < W < omega-max "
                     "(got %g)", uz);
      return 2;
    }
    po.uz[0] = uz;
    po.nuz = 1;
  }
  po.method = method;
  po.omega_min = o.omega_min;
  po.omega_max = o.omega_max;
  po.ds = o.ds;
  po.ds_max = o.ds_max;
  po.linsol = o.linsol;

  int orc = cli_outdir_check(CMD, NULL, dir); /* before the work, not after */
  if (orc) return orc;
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  whirl_sfd_response res;
  whirl_sfd_periodic pres;
  memset(&res, 0, sizeof res);
  memset(&pres, 0, sizeof pres);
  int rc = periodic ? whirl_sfd_periodic_response(p, &po, &pres, msg, sizeof msg)
                    : whirl_sfd_response_compute(p, &o, &res, msg, sizeof msg);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  if (rc != WHIRL_OK) {
    cli_error(CMD, "%s", msg);
    return 1;
  }
  const double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
  tab T;
  if (periodic ? tab_from_periodic(&T, &pres) : tab_from_circular(&T, &res, o.omega_min)) {
    cli_error(CMD, "out of memory");
    tab_free(&T);
    whirl_sfd_response_free(&res);
    whirl_sfd_periodic_free(&pres);
    return 1;
  }
  /* a failed branch is reported (and the exit status is 1), but the points
   * computed are written: they show where it failed */
  const int failed = report_failures(&T);
  if (T.nbranch == 0) {
    tab_free(&T);
    whirl_sfd_response_free(&res);
    whirl_sfd_periodic_free(&pres);
    return 1;
  }
  const size_t steps = periodic ? pres.steps : res.steps;
  const size_t newton_its = periodic ? pres.newton_its : res.newton_its;
  whirl_sfd_response_free(&res);
  whirl_sfd_periodic_free(&pres);

  cli_outdir od;
  out_file fb, fs;
  if (cli_outdir_begin(&od, CMD, NULL, dir) || out_open(&fb, &od, "branches.tsv") || out_open(&fs, &od, "special.tsv")) {
    cli_outdir_abort(&od);
    tab_free(&T);
    return 1;
  }
  /* the header first, then the comments (doc/tables.md) */
  fprintf(fb.fp, "branch\tpt\ttype\tlabel\tOmega\teps\tphase\tu\tv\tstable\tn_unstable\t"
                 "max_multiplier\t%s\n",
          periodic ? "mult_re\tmult_im\teps_min\tperiod\tresidual" : "mu_re\tmu_im");
  fprintf(fb.fp, "# whirl %s sfd response: lambda=%.10g delta=%.10g zeta=%.10g FE=%.10g "
                 "Omega in [%g, %g], method %s",
          whirl_version(), p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA],
          p[WHIRL_SFD_FE], o.omega_min, o.omega_max, whirl_sfd_method_name(method));
  if (method == WHIRL_SFD_METHOD_HBM)
    fprintf(fb.fp, " (%zu harmonics, oversampling %zu, %zu unknowns)", po.harmonics,
            po.oversampling, pres.unknowns ? pres.unknowns : 4 * (2 * po.harmonics + 1));
  else if (method == WHIRL_SFD_METHOD_COLLOC)
    fprintf(fb.fp, " (NTST %zu, NCOL %zu)", po.ntst, po.ncol);
  fprintf(fb.fp, "\n");
  if (periodic)
    fprintf(fb.fp, "# fixed-frame periodic orbits: eps = LARGEST eccentricity |(y, z)| on the "
                   "orbit / clearance, eps_min the smallest; phase = angle by which the first "
                   "harmonic of y lags the unbalance (rad); u, v = first harmonic of y "
                   "(y1 = u cos Omega t - v sin Omega t); multipliers from the monodromy matrix "
                   "(variational equations); mult = the multiplier of largest modulus; "
                   "residual = max |F| of the discretised equations\n");
  else
    fprintf(fb.fp, "# eps = orbit radius / clearance; phase = beta of eqs. 16-17 (rad); "
                   "max_multiplier = max |exp(2 pi mu / Omega)|; mu = rotating-frame eigenvalue "
                   "of largest real part\n");
  print_special_header(fs.fp);
  print_special_header(stdout);
  size_t counts[8] = {0};
  for (size_t b = 0; b < T.nbranch; ++b) {
    for (size_t i = 0; i < T.len[b]; ++i) {
      const row *r = &T.rows[b][i];
      char line[512];
      const size_t len = table_row(line, r, periodic);
      fwrite(line, 1, len, fb.fp);
      if (is_special(r->itype)) {
        print_special(fs.fp, r, r->itype);
        print_special(stdout, r, r->itype);
        if (r->itype >= 0 && r->itype < 8) ++counts[r->itype];
      }
    }
    if (b + 1 < T.nbranch) fprintf(fb.fp, "\n\n");
  }
  int bad = out_commit(&fb) | out_commit(&fs);
  if (!bad && plot) {
    const char *ylab = periodic ? "largest eccentricity {/Symbol e}_{max}"
                                : "relative eccentricity {/Symbol e}";
    bad = write_response_gp(&od, &T, p, o.omega_max, ylab) ||
          write_multipliers_gp(&od, &T, o.omega_max);
  }
  static const char *const pics[] = {"response", "multipliers", NULL};
  const int status = cli_outdir_finish(&od, bad, plot ? pics : NULL);
  if (bad) {
    tab_free(&T);
    return 1;
  }
  if (!quiet) {
    fprintf(stderr, "whirl sfd response: %zu branch%s of %s orbits for %g <= Omega <= %g "
                    "(lambda=%g delta=%g zeta=%g FE=%g), method %s\n",
            T.nbranch, T.nbranch == 1 ? "" : "es", periodic ? "synchronous" : "circular",
            o.omega_min, o.omega_max, p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA],
            p[WHIRL_SFD_ZETA], p[WHIRL_SFD_FE], whirl_sfd_method_name(method));
    for (size_t b = 0; b < T.nbranch; ++b) {
      double lo = INFINITY, hi = -INFINITY, res_max = 0;
      for (size_t i = 0; i < T.len[b]; ++i) {
        lo = fmin(lo, T.rows[b][i].Om);
        hi = fmax(hi, T.rows[b][i].Om);
        if (periodic) res_max = fmax(res_max, T.rows[b][i].residual);
      }
      fprintf(stderr, "  branch %d: %zu points, Omega in [%.6g, %.6g], %s; ended: %s", (int)(b + 1),
              T.len[b], lo, hi, !T.isola[b] ? "reaches omega-min (main resonance branch)" :
              "isolated branch (isola)", whirl_stop_reason_name(T.stop[b]));
      if (periodic) fprintf(stderr, "; max residual %.1e", res_max);
      fprintf(stderr, "\n");
    }
    fprintf(stderr, "  special points: %zu LP, %zu BP, %zu %s, %zu PD; "
                    "%zu steps, %zu Newton iterations; %.2f ms\n",
            counts[WHIRL_PT_LP], counts[WHIRL_PT_BP],
            counts[WHIRL_PT_HB] + counts[WHIRL_PT_TR], periodic ? "TR" : "HB",
            counts[WHIRL_PT_PD], steps, newton_its, 1e3 * secs);
    if (plot && !status && !cli_pictures_skipped())
      fprintf(stderr, "  wrote %s/branches.tsv, %s/special.tsv, response.%s, "
              "multipliers.%s\n", dir, dir, cli_picture_format, cli_picture_format);
    else
      fprintf(stderr, "  wrote %s/branches.tsv, %s/special.tsv\n", dir, dir);
  }
  tab_free(&T);
  return status || failed;
}

/* drivers/cmd_sfd_response.c — `whirl sfd response`: every branch of
 * synchronous circular orbits of the SFD rotor for Ω in (0, W], with
 * stability, Floquet multipliers and special points, as TSV and PNG.
 * Outputs: DIR/branches.tsv, DIR/special.tsv, DIR/response.png (ε vs Ω, as
 * the paper's Fig. 3), DIR/multipliers.png (largest multiplier modulus, as
 * Figs. 4–5), and the gnuplot scripts that drew them.  Special points also go
 * to stdout as TSV.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/whirl.h>

#include "cli.h"

#define CMD "sfd response"

static void help(FILE *f) {
  fprintf(f,
"usage: whirl sfd response [options]\n"
"\n"
"All branches of synchronous circular orbits of the rigid rotor on two short\n"
"squeeze-film dampers (pi-film), for omega-min <= Omega <= omega-max: the\n"
"main resonance branch and any isolated branch (isola), found by seeding the\n"
"continuation from every real root of the circular-orbit polynomial (paper\n"
"eq. 15).  Stability from the rotating-frame eigenvalues mu, reported as\n"
"fixed-frame Floquet multipliers exp(2 pi mu / Omega).\n"
"\n"
"options (defaults: Table 1 of the paper):\n"
"  --lambda L      SFD constant lambda > 0             (0.0503)\n"
"  --delta D       unbalance delta = e_G/c >= 0        (0.3)\n"
"  --zeta Z        external damping ratio zeta >= 0    (0)\n"
"  --omega-max W   largest speed                       (20)\n"
"  --omega-min M   smallest speed, 0 < M < W           (0.01)\n"
"  --ds S          first continuation step             (0.02)\n"
"  --ds-max S      largest continuation step (DSMAX)   (0.2)\n"
"  --sparse        use the sparse (UMFPACK) linear solver\n"
"  --out DIR       output directory                    (sfd-response)\n"
"  --no-plot       write the data only, no PNG\n"
"  --quiet         no summary on stderr\n"
"  --help          this text\n"
"\n"
"outputs: DIR/branches.tsv (branch pt type label Omega eps phase u v stable\n"
"n_unstable max_multiplier mu_re mu_im), DIR/special.tsv, DIR/response.png,\n"
"DIR/multipliers.png.  stdout: the special points as TSV.  phase is beta of\n"
"eqs. 16-17 (radians): the journal lags the unbalance by beta.\n");
}

typedef struct row {
  int branch, pt, label, stable, nu;
  const char *type;
  double Om, eps, phase, u, v, maxmult, mure, muim;
} row;

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
  r.maxmult = exp(2.0 * M_PI * r.mure / r.Om);
  return r;
}

static int is_special(int type) { return type != WHIRL_PT_REGULAR; }

static void print_special_header(FILE *f) {
  fprintf(f, "type\tbranch\tlabel\tOmega\teps\tphase\tstable\tmax_multiplier\tfixed_frame\n");
}

static void print_special(FILE *f, const row *r, int type) {
  const char *ff = type == WHIRL_PT_LP   ? "saddle-node of the synchronous orbit"
                   : type == WHIRL_PT_HB ? "Neimark-Sacker (torus, TR) of the orbit"
                   : type == WHIRL_PT_BP ? "branch point"
                                         : "end of the branch";
  fprintf(f, "%s\t%d\t%d\t%.15g\t%.15g\t%.15g\t%d\t%.10g\t%s\n", r->type, r->branch,
          r->label, r->Om, r->eps, r->phase, r->stable, r->maxmult, ff);
}

/* Gnuplot script for ε against Ω: stable solid, unstable dashed, LP marked,
 * red dashed region borders at the LPs (Fig. 3). */
static int write_response_gp(const char *dir, const whirl_sfd_response *res,
                             const double *p, double wmax) {
  out_file o;
  if (out_open(&o, dir, "response.gp")) return -1;
  FILE *f = o.fp;
  double lp[64];
  int nlp = 0;
  fprintf(f, "# gnuplot script written by whirl sfd response; run: gnuplot response.gp\n");
  fprintf(f, "set terminal pngcairo size 1100,750 enhanced font 'Sans,12'\n");
  fprintf(f, "set output '.response.png.tmp'\n");
  for (int pass = 0; pass < 2; ++pass) {
    fprintf(f, "$%s << EOD\n", pass == 0 ? "stable" : "unstable");
    for (size_t b = 0; b < res->nbranch; ++b) {
      const whirl_branch *br = res->branch[b];
      int open = 0;
      for (size_t i = 0; i < br->len; ++i) {
        int st = br->pts[i].stable == 1;
        int want = pass == 0;
        if (st == want) {
          if (!open && i > 0) {
            row r = make_row(br, i - 1);
            fprintf(f, "%.8g %.8g\n", r.Om, r.eps);
          }
          row r = make_row(br, i);
          fprintf(f, "%.8g %.8g\n", r.Om, r.eps);
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
    for (size_t i = 0; i < res->branch[b]->len; ++i)
      if (res->branch[b]->pts[i].type == WHIRL_PT_LP) {
        row r = make_row(res->branch[b], i);
        fprintf(f, "%.10g %.10g\n", r.Om, r.eps);
        if (nlp < 64) lp[nlp++] = r.Om;
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
  if (nlp == 3) {
    const double xs[4] = {0.5 * lp[0], 0.5 * (lp[0] + lp[1]), 0.5 * (lp[1] + lp[2]),
                          0.5 * (lp[2] + wmax)};
    for (int i = 0; i < 4; ++i)
      fprintf(f, "set label '%c' at %.10g, graph 0.95 center font 'Sans,14' tc rgb '#d62728'\n",
              'A' + i, xs[i]);
  }
  fprintf(f,
          "set title 'SFD rigid rotor, circular orbits: {/Symbol l} = %g, {/Symbol d} = %g, {/Symbol z} = %g'\n"
          "set xlabel 'dimensionless speed {/Symbol W}'\n"
          "set ylabel 'relative eccentricity {/Symbol e}'\n"
          "set xrange [0:%g]\nset yrange [0:1]\nset grid\nset key bottom right box opaque\n"
          "plot $stable using 1:2 with lines lw 2.5 lc rgb '#1f4e9c' title 'stable', \\\n"
          "     $unstable using 1:2 with lines dt 2 lw 2.5 lc rgb '#1f4e9c' title 'unstable', \\\n"
          "     $special using 1:2 with points pt 7 ps 1.6 lc rgb '#2ca02c' title 'LP (saddle-node)'\n",
          p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA], wmax);
  return out_commit(&o);
}

/* Gnuplot script for the largest Floquet multiplier modulus (Figs. 4-5). */
static int write_multipliers_gp(const char *dir, const whirl_sfd_response *res,
                                double wmax) {
  out_file o;
  if (out_open(&o, dir, "multipliers.gp")) return -1;
  FILE *f = o.fp;
  fprintf(f, "# gnuplot script written by whirl sfd response; run: gnuplot multipliers.gp\n");
  fprintf(f, "set terminal pngcairo size 1100,750 enhanced font 'Sans,12'\n");
  fprintf(f, "set output '.multipliers.png.tmp'\n");
  for (size_t b = 0; b < res->nbranch; ++b) {
    fprintf(f, "$b%zu << EOD\n", b + 1);
    for (size_t i = 0; i < res->branch[b]->len; ++i) {
      row r = make_row(res->branch[b], i);
      fprintf(f, "%.8g %.8g\n", r.Om, r.maxmult);
    }
    fprintf(f, "EOD\n");
  }
  fprintf(f,
          "set title 'largest Floquet multiplier modulus of the circular orbits'\n"
          "set xlabel 'dimensionless speed {/Symbol W}'\nset ylabel 'max |{/Symbol r}|'\n"
          "set xrange [0:%g]\nset logscale y\nset grid\nset key top right box opaque\n"
          "set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2 lw 1.5 lc rgb '#d62728'\n"
          "plot ",
          wmax);
  for (size_t b = 0; b < res->nbranch; ++b)
    fprintf(f, "%s$b%zu using 1:2 with lines lw 2 title 'branch %zu'", b ? ", " : "", b + 1, b + 1);
  fprintf(f, "\n");
  return out_commit(&o);
}

int cmd_sfd_response(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  whirl_sfd_response_options o;
  whirl_sfd_response_options_default(&o);
  const char *dir = "sfd-response";
  int plot = 1, quiet = 0;

  for (int i = 1; i < argc; ++i) {
    int missing = 0;
    const char *v;
    struct { const char *name; double *dst; } dopts[] = {
        {"--lambda", &p[WHIRL_SFD_LAMBDA]}, {"--delta", &p[WHIRL_SFD_DELTA]},
        {"--zeta", &p[WHIRL_SFD_ZETA]},     {"--omega-max", &o.omega_max},
        {"--omega-min", &o.omega_min},      {"--ds-max", &o.ds_max},
        {"--ds", &o.ds}};
    int matched = 0;
    for (size_t k = 0; k < sizeof dopts / sizeof dopts[0] && !matched; ++k) {
      v = cli_value(argc, argv, &i, dopts[k].name, &missing);
      if (missing) {
        cli_error(CMD, "option %s needs a value", dopts[k].name);
        return 2;
      }
      if (v) {
        if (cli_double(CMD, dopts[k].name, v, dopts[k].dst)) return 2;
        matched = 1;
      }
    }
    if (matched) continue;
    v = cli_value(argc, argv, &i, "--out", &missing);
    if (missing) {
      cli_error(CMD, "option --out needs a value");
      return 2;
    }
    if (v) {
      if (!*v) {
        cli_error(CMD, "--out needs a non-empty directory name");
        return 2;
      }
      dir = v;
      continue;
    }
    if (!strcmp(argv[i], "--sparse")) o.linsol = WHIRL_LINSOL_SPARSE;
    else if (!strcmp(argv[i], "--no-plot")) plot = 0;
    else if (!strcmp(argv[i], "--quiet")) quiet = 1;
    else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      help(stdout);
      return 0;
    } else {
      cli_error(CMD, "unknown option '%s' (see whirl sfd response --help)", argv[i]);
      return 2;
    }
  }
  /* parameters are checked before anything is computed or written */
  char msg[512];
  p[WHIRL_SFD_OMEGA] = o.omega_max;
  if (whirl_sfd_check_params(p, msg, sizeof msg) != WHIRL_OK) {
    cli_error(CMD, "%s", msg);
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

  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  whirl_sfd_response res;
  int rc = whirl_sfd_response_compute(p, &o, &res, msg, sizeof msg);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  if (rc != WHIRL_OK) {
    cli_error(CMD, "%s", msg);
    return 1;
  }
  const double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);

  if (cli_mkdirs(dir)) {
    cli_error(CMD, "cannot create output directory '%s': %s", dir, strerror(errno));
    whirl_sfd_response_free(&res);
    return 1;
  }
  out_file fb, fs;
  if (out_open(&fb, dir, "branches.tsv")) {
    cli_error(CMD, "cannot write %s/branches.tsv: %s", dir, strerror(errno));
    whirl_sfd_response_free(&res);
    return 1;
  }
  if (out_open(&fs, dir, "special.tsv")) {
    cli_error(CMD, "cannot write %s/special.tsv: %s", dir, strerror(errno));
    out_abort(&fb);
    whirl_sfd_response_free(&res);
    return 1;
  }
  fprintf(fb.fp, "# whirl %s sfd response: lambda=%.10g delta=%.10g zeta=%.10g Omega in [%g, %g]\n",
          whirl_version(), p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA],
          o.omega_min, o.omega_max);
  fprintf(fb.fp, "# eps = orbit radius / clearance; phase = beta of eqs. 16-17 (rad); "
                 "max_multiplier = max |exp(2 pi mu / Omega)|; mu = rotating-frame eigenvalue "
                 "of largest real part\n");
  fprintf(fb.fp, "branch\tpt\ttype\tlabel\tOmega\teps\tphase\tu\tv\tstable\tn_unstable\t"
                 "max_multiplier\tmu_re\tmu_im\n");
  print_special_header(fs.fp);
  print_special_header(stdout);
  size_t counts[6] = {0};
  for (size_t b = 0; b < res.nbranch; ++b) {
    const whirl_branch *br = res.branch[b];
    for (size_t i = 0; i < br->len; ++i) {
      row r = make_row(br, i);
      fprintf(fb.fp, "%d\t%d\t%s\t%d\t%.10e\t%.10e\t%.10e\t%.10e\t%.10e\t%d\t%d\t%.10e\t%.10e\t%.10e\n",
              r.branch, r.pt, br->pts[i].type ? r.type : "-", r.label, r.Om, r.eps, r.phase, r.u,
              r.v, r.stable, r.nu, r.maxmult, r.mure, r.muim);
      int type = br->pts[i].type;
      if (is_special(type)) {
        print_special(fs.fp, &r, type);
        print_special(stdout, &r, type);
        if (type >= 0 && type < 6) ++counts[type];
      }
    }
    if (b + 1 < res.nbranch) fprintf(fb.fp, "\n\n");
  }
  if (out_commit(&fb) || out_commit(&fs)) {
    cli_error(CMD, "writing the tables in '%s' failed: %s", dir, strerror(errno));
    whirl_sfd_response_free(&res);
    return 1;
  }
  int status = 0;
  if (plot) {
    if (write_response_gp(dir, &res, p, o.omega_max) ||
        write_multipliers_gp(dir, &res, o.omega_max)) {
      cli_error(CMD, "cannot write the gnuplot scripts in '%s': %s", dir, strerror(errno));
      status = 1;
    } else if (cli_plot(dir, "response", msg, sizeof msg) ||
               cli_plot(dir, "multipliers", msg, sizeof msg)) {
      cli_error(CMD, "plot: %s", msg);
      status = 1;
    }
  }
  if (!quiet) {
    fprintf(stderr, "whirl sfd response: %zu branch%s of circular orbits for %g <= Omega <= %g "
                    "(lambda=%g delta=%g zeta=%g)\n",
            res.nbranch, res.nbranch == 1 ? "" : "es", o.omega_min, o.omega_max,
            p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA]);
    for (size_t b = 0; b < res.nbranch; ++b) {
      const whirl_branch *br = res.branch[b];
      double lo = INFINITY, hi = -INFINITY;
      for (size_t i = 0; i < br->len; ++i) {
        lo = fmin(lo, br->pts[i].p[WHIRL_SFD_OMEGA]);
        hi = fmax(hi, br->pts[i].p[WHIRL_SFD_OMEGA]);
      }
      int main_branch = lo <= o.omega_min * (1 + 1e-12);
      fprintf(stderr, "  branch %d: %zu points, Omega in [%.6g, %.6g], %s; ended: %s\n", br->id,
              br->len, lo, hi, main_branch ? "reaches omega-min (main resonance branch)" :
              "isolated branch (isola)", whirl_stop_reason_name(br->stop_reason));
    }
    fprintf(stderr, "  special points: %zu LP, %zu BP, %zu HB; %zu seeds from eq. 15; "
                    "%zu steps, %zu Newton iterations; %.2f ms\n",
            counts[WHIRL_PT_LP], counts[WHIRL_PT_BP], counts[WHIRL_PT_HB], res.nseeds, res.steps,
            res.newton_its, 1e3 * secs);
    fprintf(stderr, "  wrote %s/branches.tsv, %s/special.tsv%s\n", dir, dir,
            plot && !status ? ", response.png, multipliers.png" : "");
  }
  whirl_sfd_response_free(&res);
  return status;
}

/* drivers/cmd_sfd_region.c — `whirl sfd region`: the region of (lambda,
 * delta) in which the rotor has an isolated branch below Omega = W (paper
 * Fig. 18), its two boundaries traced by two-parameter continuation
 * (whirl/rotor/sfd_region.h), written as TSV and drawn like the paper's figure.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>
#include <whirl/rotor/sfd_region.h>

#include "cli.h"
#include "sfd_common.h"

#define CMD "sfd region"

static const cli_doc doc = {
"usage: whirl sfd region [options]\n"
"\n"
"Where the response of circular orbits (F_E = 0) has an isolated branch\n"
"below the maximum speed W (paper Fig. 18), by continuation:\n"
"  upper boundary: the isola-peak merge point followed in lambda\n"
"  lower boundary: a fold of the response at Omega = W followed in\n"
"                  (lambda, delta), through the cusp where it meets the\n"
"                  other fold at W.  The boundaries touch where the merge\n"
"                  speed reaches W (label MG on the lower curve).\n"
"\n"
"options:\n",
"files: DIR/upper.tsv and DIR/lower.tsv ('lambda delta Omega eps type\n"
"residual'; type CP, MG, LP or '-'), DIR/band.tsv (lambda, lower and upper\n"
"delta of the region on a log grid), DIR/region.png and region.gp.\n"
"stdout: the special points as TSV 'curve type lambda delta Omega eps'.\n"};

static int write_curve(cli_outdir *od, const char *name, const whirl_sfd_curve *c,
                       const char *what, double zeta, double W) {
  out_file o;
  if (out_open(&o, od, name)) return -1;
  fprintf(o.fp, "lambda\tdelta\tOmega\teps\ttype\tresidual\n");
  fprintf(o.fp, "# whirl %s sfd region: %s; zeta = %.10g, W = %.10g; residual = largest "
                "relative residual of the defining equations of eq. 15\n",
          whirl_version(), what, zeta, W);
  for (size_t i = 0; i < c->len; ++i)
    fprintf(o.fp, "%.12e\t%.12e\t%.12e\t%.12e\t%s\t%.1e\n", c->lambda[i], c->delta[i],
            c->Omega[i], c->eps[i], c->type[i] ? whirl_point_type_name(c->type[i]) : "-",
            c->res[i]);
  return out_commit(&o);
}

static int write_band(cli_outdir *od, const whirl_sfd_region *r, double a, double b, double W) {
  out_file o;
  if (out_open(&o, od, "band.tsv")) return -1;
  fprintf(o.fp, "lambda\tdelta_lower\tdelta_upper\n");
  const size_t K = 600;
  for (size_t k = 0; k <= K; ++k) {
    const double lam = a * pow(b / a, (double)k / K);
    double lo, hi;
    if (whirl_sfd_region_band(r, lam, W, &lo, &hi)) fprintf(o.fp, "%.10e\t%.10e\t%.10e\n", lam, lo, hi);
    else fprintf(o.fp, "\n");
  }
  return out_commit(&o);
}

static int write_plot(cli_outdir *od, const whirl_sfd_region *r, double zeta, double W,
                      double a, double b) {
  out_file o;
  if (out_open(&o, od, "region.gp")) return -1;
  FILE *f = o.fp;
  cli_gp_preamble(f, CMD, "region", 1000, 750, "Sans,12");
  fprintf(f,
          "set title 'isolated branch below {/Symbol W} = %g: {/Symbol z} = %g (cf. paper Fig. 18)'\n"
          "set xlabel 'SFD constant {/Symbol l}'\nset ylabel 'unbalance {/Symbol d}'\n"
          "set logscale x\nset xrange [%g:%g]\nset yrange [0:1]\nset grid\n"
          "set key outside bottom center vertical box\nset bmargin 9\n" /* long entries: under the x label */
          "set datafile separator '\\t'\n"
          "",
          W, zeta, a, b);
  /* special points: MG labelled to the left, the others to the right */
  for (int side = 0; side < 2; ++side) {
    fprintf(f, "$sp%d << EOD\n", side);
    for (int c = 0; c < 2; ++c) {
      const whirl_sfd_curve *cv = c ? &r->lower : &r->upper;
      for (size_t i = 0; i < cv->len; ++i)
        if (cv->type[i] && (cv->type[i] == WHIRL_PT_MG) == (side == 0))
          fprintf(f, "%.10g\t%.10g\t%s\n", cv->lambda[i], cv->delta[i],
                  whirl_point_type_name(cv->type[i]));
    }
    fprintf(f, "0.001\t-1\t-\nEOD\n");
  }
  fprintf(f, ""
             "plot 'band.tsv' using 1:2:3 with filledcurves fc rgb '#9ecae1' fs solid 0.8 "
             "title 'isolated branch below {/Symbol W}_{max}', \\\n"
             "     'upper.tsv' using 1:2 every ::0 with lines lw 2.5 lc rgb '#d62728' "
             "title 'u: isola-peak merge (continued in {/Symbol l})', \\\n"
             "     'lower.tsv' using 1:2 with lines lw 2.5 lc rgb '#1f4e9c' "
             "title 'l: fold at {/Symbol W} = %g (continued in {/Symbol l}, {/Symbol d})', \\\n"
             "     $sp0 using 1:2 with points pt 7 ps 1.5 lc rgb 'black' notitle, \\\n"
             "     $sp1 using 1:2 with points pt 7 ps 1.5 lc rgb 'black' notitle, \\\n"
             "     $sp0 using 1:2:3 with labels right offset -0.6,0.9 notitle, \\\n"
             "     $sp1 using 1:2:3 with labels left offset 0.6,0.9 notitle\n",
          W);
  if (out_commit(&o)) return -1;
  return 0;
}

int cmd_sfd_region(int argc, char **argv) {
  whirl_sfd_region_options o;
  whirl_sfd_region_options_default(&o);
  const char *dir = "sfd-region";
  int quiet = 0, noplot = 0;
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_ZETA] = o.zeta;
  const cli_opt opts[] = {
      SFD_OPT_ZETA(p),
      {"--omega-max", CLI_DOUBLE, &o.omega_max, "W", "maximum speed, 1 < W <= 1000", NULL},
      {"--lambda-min", CLI_DOUBLE, &o.lambda_min, "A", "smallest lambda", NULL},
      {"--lambda-max", CLI_DOUBLE, &o.lambda_max, "B", "largest lambda, B <= 100", NULL},
      {"--ds-max", CLI_DOUBLE, &o.ds_max, "S", "largest continuation step, 1e-4 <= S <= 1", NULL},
      CLI_OPTS_OUT(dir, noplot, quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 0 : 2;
  o.zeta = p[WHIRL_SFD_ZETA];
  if (sfd_check(CMD, p, 0)) return 2;
  if (!(o.omega_max > 1) || o.omega_max > 1000) {
    cli_error(CMD, "--omega-max must be in (1, 1000] (got %g)", o.omega_max);
    return 2;
  }
  if (!(o.lambda_min > 0) || !(o.lambda_max > o.lambda_min) ||
      o.lambda_max > WHIRL_SFD_LAMBDA_MAX) {
    cli_error(CMD, "need 0 < --lambda-min < --lambda-max <= %g (got %g, %g)",
              WHIRL_SFD_LAMBDA_MAX, o.lambda_min, o.lambda_max);
    return 2;
  }
  if (!(o.ds_max >= 1e-4) || o.ds_max > 1) {
    cli_error(CMD, "--ds-max must be in [1e-4, 1] (got %g)", o.ds_max);
    return 2;
  }
  /* steps enough for the same arclength (about 10 per curve and direction
   * in (lambda, delta, Omega) at the defaults) at a smaller --ds-max */
  o.nmx = (size_t)fmax((double)o.nmx, ceil(20.0 / o.ds_max));
  char msg[512] = "";
  int orc = cli_outdir_check(CMD, NULL, dir); /* before the work, not after */
  if (orc) return orc;
  whirl_sfd_region reg;
  const double t0 = cli_now();
  int rc = whirl_sfd_region_compute(&o, &reg, msg, sizeof msg);
  const double secs = cli_now() - t0;
  if (rc != 0) {
    cli_error(CMD, "%s", msg);
    whirl_sfd_region_free(&reg);
    return 1;
  }
  cli_outdir od;
  int bad = cli_outdir_begin(&od, CMD, NULL, dir) != 0;
  if (bad) {
    whirl_sfd_region_free(&reg);
    return 1;
  }
  if (write_curve(&od, "upper.tsv", &reg.upper,
                  "upper boundary: isola-peak merge point (G = G_eps = G_Omega = 0) continued "
                  "in lambda", o.zeta, o.omega_max) ||
      write_curve(&od, "lower.tsv", &reg.lower,
                  "lower boundary: fold at Omega = W (G = G_eps = 0) continued in (lambda, "
                  "delta), both branches", o.zeta, o.omega_max) ||
      write_band(&od, &reg, o.lambda_min, o.lambda_max, o.omega_max))
    bad = 1;
  if (!bad && !noplot)
    bad = write_plot(&od, &reg, o.zeta, o.omega_max, o.lambda_min, o.lambda_max);
  static const char *const pics[] = {"region", NULL};
  const int status = cli_outdir_finish(&od, bad, noplot ? NULL : pics);
  printf("curve\ttype\tlambda\tdelta\tOmega\teps\n");
  for (int c = 0; c < 2; ++c) {
    const whirl_sfd_curve *cv = c ? &reg.lower : &reg.upper;
    for (size_t i = 0; i < cv->len; ++i)
      if (cv->type[i])
        printf("%s\t%s\t%.10f\t%.10f\t%.10f\t%.10f\n", c ? "lower" : "upper",
               whirl_point_type_name(cv->type[i]), cv->lambda[i], cv->delta[i], cv->Omega[i],
               cv->eps[i]);
  }
  if (!quiet) {
    fprintf(stderr, "whirl sfd region: zeta = %g, W = %g, lambda in [%g, %g]: %zu + %zu points, "
                    "%zu steps, %zu Newton iterations, %.3f s\n",
            o.zeta, o.omega_max, o.lambda_min, o.lambda_max, reg.upper.len, reg.lower.len,
            reg.steps, reg.newton_its, secs);
    fprintf(stderr, "  max relative residual of eq. 15: upper %.1e, lower %.1e\n",
            reg.max_res_upper, reg.max_res_lower);
    if (!isnan(reg.lambda_m))
      fprintf(stderr, "  the merge point reaches Omega = W at lambda = %.8f, delta = %.8f "
                      "(MG on the lower curve): the two boundaries touch and the region "
                      "ends\n", reg.lambda_m, reg.delta_m);
    if (!isnan(reg.lambda_c))
      fprintf(stderr, "  the two folds at Omega = W meet in a cusp (CP) at lambda = %.8f, "
                      "delta = %.8f (not a boundary of the region)\n", reg.lambda_c, reg.delta_c);
    if (!status)
      fprintf(stderr, "  wrote %s/upper.tsv, lower.tsv, band.tsv%s%s\n", dir,
              noplot || cli_pictures_skipped() ? "" : ", region.",
              noplot || cli_pictures_skipped() ? "" : cli_picture_format);
  }
  whirl_sfd_region_free(&reg);
  return status;
}

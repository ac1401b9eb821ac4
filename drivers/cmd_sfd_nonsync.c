/* drivers/cmd_sfd_nonsync.c — `whirl sfd nonsync`: the nonsynchronous
 * response of the SFD rotor (F_E = 0) as a periodic orbit of the rotating
 * frame, found from a long time integration from rest and continued in Ω
 * with its Floquet multipliers, folds of cycles (LP), period doublings (PD)
 * and torus points (TR).  In the fixed frame the orbit is quasiperiodic with
 * frequencies Ω + k ω_r; the paper's second frequency is
 * f2 = |Ω − ω_r| / Ω.  Outputs DIR/branches.tsv, DIR/special.tsv,
 * DIR/nonsync.png (eccentricity range over the synchronous response) and
 * DIR/f2.png; special points as TSV on stdout.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "cli.h"
#include "sfd_common.h"

#define CMD "sfd nonsync"

static const cli_doc doc = {
"usage: whirl sfd nonsync [options]\n"
"\n"
"The nonsynchronous response of the rigid rotor on two short SFDs (F_E = 0):\n"
"in the frame rotating with the shaft it is a periodic orbit (period T_r,\n"
"frequency w_r = 2 pi / T_r), so the fixed-frame motion is quasiperiodic with\n"
"frequencies Omega + k w_r and second frequency f2 = |Omega - w_r| / Omega\n"
"(normalised by Omega, as in the paper).  The orbit is found by integrating\n"
"from rest at --omega-start until it settles, then continued in Omega in both\n"
"directions by collocation (default) or harmonic balance, with stability\n"
"from the monodromy matrix, folds of cycles (LP, where the branch is born),\n"
"period doublings (PD) and torus points (TR).\n"
"\n"
"options (defaults: Table 1 of the paper):\n",
"outputs: DIR/branches.tsv (branch pt type label Omega f2 period eps_max\n"
"eps_min stable n_unstable max_multiplier mult_re mult_im residual),\n"
"DIR/special.tsv, DIR/nonsync.png, DIR/f2.png.  stdout: the special points\n"
"(type branch label Omega f2 period eps_max eps_min stable max_multiplier\n"
"meaning), including UZ at --omega-start on the unstable side and the start\n"
"point itself (type ST).  Exit 1 if the rotor does not settle on a\n"
"nonsynchronous cycle at --omega-start.\n"};

static const char *meaning(int type) {
  switch (type) {
  case WHIRL_PT_LP: return "fold of cycles (saddle-node of the nonsynchronous orbit)";
  case WHIRL_PT_PD: return "period doubling";
  case WHIRL_PT_TR: return "torus (Neimark-Sacker) of the rotating-frame cycle";
  case WHIRL_PT_BP: return "branch point";
  case WHIRL_PT_UZ: return "user speed";
  default: return "end of the branch";
  }
}

static void print_special(FILE *f, const whirl_sfd_periodic_branch *b,
                          const whirl_sfd_orbit *q, const char *type,
                          const char *what) {
  fprintf(f, "%s\t%d\t%d\t%.12g\t%.10g\t%.10g\t%.10g\t%.10g\t%d\t%.10g\t%s\n", type, b->id,
          q->label, q->Omega, q->f2, q->period, q->eps_max, q->eps_min, q->stable,
          q->max_mult, what);
}

/* eps range of the cycle (stable solid, unstable dashed) over the circular
 * orbits of the synchronous response, and f2 against Omega. */
static int write_plots(cli_outdir *od, const whirl_sfd_periodic *ns,
                       const whirl_sfd_response *sync, const double *p, double wmin,
                       double wmax) {
  out_file o;
  if (out_open(&o, od, "nonsync.gp")) return -1;
  FILE *f = o.fp;
  cli_gp_preamble(f, CMD, "nonsync", 1100, 750, "Sans,12");
  for (int pass = 0; pass < 2; ++pass) {
    fprintf(f, "$sync%d << EOD\n", pass);
    for (size_t b = 0; sync && b < sync->nbranch; ++b) {
      const whirl_branch *br = sync->branch[b];
      for (size_t i = 0; i < br->len; ++i) {
        if ((br->pts[i].stable == 1) != (pass == 0)) {
          fprintf(f, "\n");
          continue;
        }
        fprintf(f, "%.8g %.8g\n", br->pts[i].p[WHIRL_SFD_OMEGA],
                hypot(br->pts[i].x[0], br->pts[i].x[1]));
      }
      fprintf(f, "\n");
    }
    fprintf(f, "EOD\n$ns%d << EOD\n", pass);
    for (size_t b = 0; b < ns->nbranch; ++b) {
      const whirl_sfd_periodic_branch *br = &ns->br[b];
      for (size_t i = 0; i < br->len; ++i) {
        const whirl_sfd_orbit *q = &br->pts[i];
        if ((q->stable == 1) != (pass == 0)) {
          fprintf(f, "\n");
          continue;
        }
        fprintf(f, "%.8g %.8g %.8g %.8g\n", q->Omega, q->eps_max, q->eps_min, q->f2);
      }
      fprintf(f, "\n");
    }
    fprintf(f, "EOD\n");
  }
  fprintf(f, "$lp << EOD\n0 -1 -1 -1\n");
  for (size_t b = 0; b < ns->nbranch; ++b)
    for (size_t i = 0; i < ns->br[b].len; ++i)
      if (ns->br[b].pts[i].type == WHIRL_PT_LP)
        fprintf(f, "%.10g %.10g %.10g %.10g\n", ns->br[b].pts[i].Omega,
                ns->br[b].pts[i].eps_max, ns->br[b].pts[i].eps_min, ns->br[b].pts[i].f2);
  fprintf(f, "EOD\n");
  char title[256];
  fprintf(f,
          "set title 'nonsynchronous response (rotating-frame cycle): %s'\n"
          "set xlabel 'dimensionless speed {/Symbol W}'\n"
          "set ylabel 'eccentricity {/Symbol e}'\n"
          "set xrange [%g:%g]\nset yrange [0:1]\nset grid\nset key outside right top box\n"
          "plot $sync0 using 1:2 with lines lw 2 lc rgb '#1f4e9c' title 'circular orbits, stable', \\\n"
          "     $sync1 using 1:2 with lines dt 2 lw 2 lc rgb '#1f4e9c' title 'circular orbits, unstable', \\\n"
          "     $ns0 using 1:2 with lines lw 2.5 lc rgb '#d62728' title 'nonsync {/Symbol e}_{max}, stable', \\\n"
          "     $ns0 using 1:3 with lines lw 2.5 lc rgb '#ff7f0e' title 'nonsync {/Symbol e}_{min}, stable', \\\n"
          "     $ns1 using 1:2 with lines dt 2 lw 2 lc rgb '#d62728' title 'nonsync {/Symbol e}_{max}, unstable', \\\n"
          "     $ns1 using 1:3 with lines dt 2 lw 2 lc rgb '#ff7f0e' title 'nonsync {/Symbol e}_{min}, unstable', \\\n"
          "     $lp using 1:2 with points pt 7 ps 1.6 lc rgb '#2ca02c' title 'LP of cycles (birth)', \\\n"
          "     $lp using 1:3 with points pt 7 ps 1.6 lc rgb '#2ca02c' notitle\n",
          sfd_gp_params(title, sizeof title, p, SFD_P_MODEL), wmin, wmax);
  if (out_commit(&o)) return -1;

  if (out_open(&o, od, "f2.gp")) return -1;
  f = o.fp;
  cli_gp_preamble(f, CMD, "f2", 1100, 750, "Sans,12");
  for (int pass = 0; pass < 2; ++pass) {
    fprintf(f, "$ns%d << EOD\n", pass);
    for (size_t b = 0; b < ns->nbranch; ++b)
      for (size_t i = 0; i < ns->br[b].len; ++i) {
        const whirl_sfd_orbit *q = &ns->br[b].pts[i];
        if ((q->stable == 1) != (pass == 0)) fprintf(f, "\n");
        else fprintf(f, "%.8g %.8g\n", q->Omega, q->f2);
      }
    fprintf(f, "EOD\n");
  }
  fprintf(f,
          "set title 'second frequency of the nonsynchronous response, f_2 = |{/Symbol W} - "
          "{/Symbol w}_r| / {/Symbol W}'\n"
          "set xlabel 'dimensionless speed {/Symbol W}'\nset ylabel 'second frequency f_2 (in units of {/Symbol W})'\n"
          "set grid\nset key outside right top box\n"
          "plot $ns0 using 1:2 with lines lw 2.5 lc rgb '#d62728' title 'stable', \\\n"
          "     $ns1 using 1:2 with lines dt 2 lw 2 lc rgb '#d62728' title 'unstable', \\\n"
          "     '-' using 1:2 with points pt 9 ps 2 lc rgb 'black' title 'paper (time integration): 0.2974 at 8.7'\n"
          "8.7 0.2974\ne\n");
  return out_commit(&o);
}

/* Progress of the continuation: the part of [omega_min, omega_max] the
 * branch has covered (both halves from the start speed together). */
typedef struct {
  cli_progress prog;
  double lo, hi, a, b;
} branch_progress;

static void on_point(size_t points, double omega, void *data) {
  branch_progress *bp = data;
  if (points == 1) bp->lo = bp->hi = omega;
  bp->lo = fmin(bp->lo, omega), bp->hi = fmax(bp->hi, omega);
  cli_progress_show(&bp->prog, (size_t)(1000.0 * (bp->hi - bp->lo) / (bp->b - bp->a)), 1000);
}

int cmd_sfd_nonsync(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  whirl_sfd_periodic_options o;
  whirl_sfd_periodic_options_default(&o);
  o.method = WHIRL_SFD_METHOD_COLLOC;
  /* NTST 35, NCOL 6: the fold of cycles to ~1e-12 (NTST 60, NCOL 4 gave
   * 1e-9), and the rest of the branch at least as accurately */
  o.ntst = 35;
  o.ncol = 6;
  o.harmonics = 40;
  o.omega_min = 1.0;
  double w0 = 8.7;
  const char *dir = "sfd-nonsync", *method_name = NULL;
  int noplot = 0, quiet = 0;
  const char *method_shown = whirl_sfd_method_name(o.method);
  const cli_opt opts[] = {
      SFD_OPTS_MODEL(p),
      {"--omega-start", CLI_DOUBLE, &w0, "S", "speed of the time integration", NULL},
      {"--omega-max", CLI_DOUBLE, &o.omega_max, "W", "largest speed", NULL},
      {"--omega-min", CLI_DOUBLE, &o.omega_min, "M", "smallest speed", NULL},
      {"--method", CLI_STRING, &method_name, "M", "colloc | hbm", method_shown},
      {"--ntst", CLI_SIZE, &o.ntst, "N", "collocation mesh intervals", NULL},
      {"--ncol", CLI_SIZE, &o.ncol, "C", "collocation points per interval", NULL},
      {"--harmonics", CLI_SIZE, &o.harmonics, "N", "HBM harmonics", NULL},
      {"--oversampling", CLI_SIZE, &o.oversampling, "K", "HBM: K (2N+1) time samples", NULL},
      {"--ds", CLI_DOUBLE, &o.ds, "S", "first arclength step", NULL},
      {"--ds-max", CLI_DOUBLE, &o.ds_max, "S", "largest arclength step", NULL},
      CLI_OPTS_OUT(dir, noplot, quiet)};
  int prc = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (prc) return prc == 1 ? 0 : 2;
  if (method_name) {
    if (!strcmp(method_name, "colloc")) o.method = WHIRL_SFD_METHOD_COLLOC;
    else if (!strcmp(method_name, "hbm")) o.method = WHIRL_SFD_METHOD_HBM;
    else {
      cli_error(CMD, "--method must be colloc or hbm (got '%s')", method_name);
      return 2;
    }
  }
  char msg[512];
  p[WHIRL_SFD_OMEGA] = w0;
  if (sfd_check(CMD, p, 0)) return 2;
  if (!(o.omega_min > 0) || !(o.omega_max > o.omega_min) || !(w0 >= o.omega_min) ||
      !(w0 <= o.omega_max)) {
    cli_error(CMD, "need 0 < --omega-min <= --omega-start <= --omega-max (got %g, %g, %g)",
              o.omega_min, w0, o.omega_max);
    return 2;
  }
  if (!(o.ds > 0) || !(o.ds_max >= o.ds)) {
    cli_error(CMD, "need 0 < --ds <= --ds-max (got %g and %g)", o.ds, o.ds_max);
    return 2;
  }
  if (o.ntst < 2 || o.ntst > WHIRL_COLLOC_MAX_NTST || o.ncol < 2 || o.ncol > 7 ||
      o.harmonics < 1 || o.harmonics > 200 || o.oversampling < 1 || o.oversampling > 100) {
    cli_error(CMD, "need 2 <= --ntst <= %d, 2 <= --ncol <= 7, 1 <= --harmonics <= 200, "
                   "1 <= --oversampling <= 100 (got %zu, %zu, %zu, %zu)", WHIRL_COLLOC_MAX_NTST,
              o.ntst, o.ncol, o.harmonics, o.oversampling);
    return 2;
  }
  o.uz[0] = w0;
  o.nuz = 1;

  int orc = cli_outdir_check(CMD, NULL, dir); /* before the work, not after */
  if (orc) return orc;
  const double t0 = cli_now();
  whirl_sfd_periodic ns;
  branch_progress bp = {.a = o.omega_min, .b = o.omega_max};
  cli_progress_init(&bp.prog, "whirl sfd nonsync", quiet);
  o.progress = on_point, o.progress_data = &bp;
  int rc = whirl_sfd_nonsync(p, w0, &o, &ns, msg, sizeof msg);
  cli_progress_end(&bp.prog);
  if (rc != WHIRL_OK) {
    cli_error(CMD, "%s", msg);
    return 1;
  }
  const double secs = cli_now() - t0;
  /* the synchronous response for the picture (cheap: rotating-frame
   * equilibria) */
  whirl_sfd_response sync;
  whirl_sfd_response_options ro;
  whirl_sfd_response_options_default(&ro);
  ro.omega_max = o.omega_max;
  int have_sync = !noplot && whirl_sfd_response_compute(p, &ro, &sync, msg, sizeof msg) == 0;

  cli_outdir od;
  out_file fb, fs;
  if (cli_outdir_begin(&od, CMD, NULL, dir) || out_open(&fb, &od, "branches.tsv") ||
      out_open(&fs, &od, "special.tsv")) {
    cli_outdir_abort(&od);
    whirl_sfd_periodic_free(&ns);
    if (have_sync) whirl_sfd_response_free(&sync);
    return 1;
  }
  fprintf(fb.fp, "branch\tpt\ttype\tlabel\tOmega\tf2\tperiod\teps_max\teps_min\tstable\tn_unstable\t"
                 "max_multiplier\tmult_re\tmult_im\tresidual\n");
  fprintf(fb.fp, "# whirl %s sfd nonsync: lambda=%.10g delta=%.10g zeta=%.10g, method %s", whirl_version(),
          p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA],
          whirl_sfd_method_name(o.method));
  if (o.method == WHIRL_SFD_METHOD_COLLOC) fprintf(fb.fp, " (NTST %zu, NCOL %zu", o.ntst, o.ncol);
  else fprintf(fb.fp, " (%zu harmonics, oversampling %zu", o.harmonics, o.oversampling);
  fprintf(fb.fp, ", %zu unknowns); %s\n", ns.unknowns, ns.note);
  fprintf(fb.fp, "# rotating-frame cycle; period = T_r; f2 = |Omega - 2 pi / T_r| / Omega "
                 "(second fixed-frame frequency over Omega); eps_max, eps_min = largest and "
                 "smallest eccentricity on the orbit; multipliers from the monodromy matrix "
                 "(trivial one removed); residual = max |F| of the discretised equations\n");
  const char *hdr = "type\tbranch\tlabel\tOmega\tf2\tperiod\teps_max\teps_min\tstable\t"
                    "max_multiplier\tmeaning\n";
  fputs(hdr, fs.fp);
  fputs(hdr, stdout);
  double lo = INFINITY, hi = -INFINITY, st_lo = INFINITY, st_hi = -INFINITY;
  const whirl_sfd_orbit *lp = NULL, *start = NULL;
  size_t nlp = 0, npd = 0, ntr = 0;
  for (size_t b = 0; b < ns.nbranch; ++b) {
    const whirl_sfd_periodic_branch *br = &ns.br[b];
    for (size_t i = 0; i < br->len; ++i) {
      const whirl_sfd_orbit *q = &br->pts[i];
      fprintf(fb.fp, "%d\t%zu\t%s\t%d\t%.12e\t%.12e\t%.12e\t%.10e\t%.10e\t%d\t%d\t%.10e\t%.10e\t%.10e\t%.2e\n",
              br->id, i, q->type ? whirl_point_type_name(q->type) : "-", q->label, q->Omega, q->f2,
              q->period, q->eps_max, q->eps_min, q->stable, q->n_unstable, q->max_mult,
              q->mult_re, q->mult_im, q->residual);
      lo = fmin(lo, q->Omega);
      hi = fmax(hi, q->Omega);
      if (q->stable == 1) st_lo = fmin(st_lo, q->Omega), st_hi = fmax(st_hi, q->Omega);
      if (q->type == WHIRL_PT_LP && (!lp || q->Omega < lp->Omega)) lp = q;
      nlp += q->type == WHIRL_PT_LP;
      npd += q->type == WHIRL_PT_PD;
      ntr += q->type == WHIRL_PT_TR;
      if (q->type == WHIRL_PT_REGULAR && fabs(q->Omega - w0) < 1e-12 * w0 && !start) start = q;
      if (q->type != WHIRL_PT_REGULAR) {
        print_special(fs.fp, br, q, whirl_point_type_name(q->type), meaning(q->type));
        print_special(stdout, br, q, whirl_point_type_name(q->type), meaning(q->type));
      }
      if (q == start) {
        print_special(fs.fp, br, q, "ST", "start point (from the time integration)");
        print_special(stdout, br, q, "ST", "start point (from the time integration)");
      }
    }
  }
  int failed = 0;
  /* a branch of cycles that ended at DSMIN failed there: said, exit 1,
   * the tables are kept */
  for (size_t b = 0; b < ns.nbranch; ++b) {
    const whirl_sfd_periodic_branch *br = &ns.br[b];
    if (br->stop_reason != WHIRL_STOP_NOCONV && br->stop_reason != WHIRL_STOP_DOMAIN) continue;
    cli_error(CMD, "branch %d failed after point %zu (Omega = %.10g): %s", br->id, br->len,
              br->len ? br->pts[br->len - 1].Omega : NAN, whirl_stop_reason_name(br->stop_reason));
    failed = 1;
  }
  int bad = out_commit(&fb) | out_commit(&fs);
  if (!noplot && !bad)
    bad = write_plots(&od, &ns, have_sync ? &sync : NULL, p, fmax(0.0, lo - 0.5), o.omega_max);
  static const char *const pics[] = {"nonsync", "f2", NULL};
  const int status = cli_outdir_finish(&od, bad, noplot ? NULL : pics);
  if (!quiet) {
    fprintf(stderr, "whirl sfd nonsync: %s\n", ns.note);
    fprintf(stderr, "  %s with %zu unknowns; Omega in [%.10g, %.10g]; stable for Omega in "
                    "[%.10g, %.10g]\n",
            whirl_sfd_method_name(o.method), ns.unknowns, lo, hi, st_lo, st_hi);
    if (lp)
      fprintf(stderr, "  born at a fold of cycles (LP) at Omega = %.10f (f2 = %.6f)\n", lp->Omega,
              lp->f2);
    if (start)
      fprintf(stderr, "  at Omega = %g: f2 = %.8f, T_r = %.10f, stable = %d\n", w0, start->f2,
              start->period, start->stable);
    fprintf(stderr, "  special points: %zu LP, %zu PD, %zu TR; %zu steps, %zu Newton "
                    "iterations; max residual %.1e; %.2f s\n",
            nlp, npd, ntr, ns.steps, ns.newton_its, ns.max_residual, secs);
    if (!noplot && !status && !cli_pictures_skipped())
      fprintf(stderr, "  wrote %s/branches.tsv, special.tsv, nonsync.%s, f2.%s\n", dir,
              cli_picture_format, cli_picture_format);
  }
  whirl_sfd_periodic_free(&ns);
  if (have_sync) whirl_sfd_response_free(&sync);
  return status || failed;
}

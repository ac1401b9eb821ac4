/* drivers/cmd_sfd_basins.c — `whirl sfd basins`: basins of attraction of the
 * SFD rotor at one speed (paper §5.3, Figs. 12–17).  Initial displacements
 * evenly spread in 98 % of the clearance with zero or circular-orbit
 * velocities, or taken from a quasiperiodic trajectory; each trajectory is
 * integrated until it provably settles on one of the attractors found at
 * that speed (whirl/rotor/sfd_dynamics.h), in parallel (OpenMP).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "cli.h"
#include "sfd_common.h"

#define CMD "sfd basins"

static const cli_doc doc = {
"usage: whirl sfd basins --omega W [options]\n"
"\n"
"Basins of attraction at speed W.  The attractors are found first: the\n"
"stable circular orbits of eq. 15 (named small/large, or circular when\n"
"there is one), each with a certified Lyapunov neighbourhood in the\n"
"rotating frame, and the nonsynchronous (quasiperiodic) response if a\n"
"trajectory settles on one.  Every initial state is then integrated until\n"
"it enters one of those neighbourhoods (or --periods have passed), or --\n"
"an atlas of classified cells (--seeds) -- until it has passed --cell-hits\n"
"consecutive periods in cells that trajectories of one attractor alone\n"
"went through.\n"
"\n"
"options (defaults: Table 1 of the paper):\n",
"stdout: TSV 'attractor count percent'.  DIR/basins.tsv: y0 z0 vy0 vz0\n"
"attractor periods; DIR/attractors.tsv; DIR/basins.png (red small orbit,\n"
"green large, blue quasiperiodic, black contact, grey unsettled).\n"};

static void progress_cb(size_t done, size_t total, void *data) {
  cli_progress_show(data, done, total);
}

static const char *colour_of(const char *name) {
  if (!strcmp(name, "small") || !strcmp(name, "circular")) return "#d62728";
  if (!strcmp(name, "large")) return "#2ca02c";
  if (!strcmp(name, "quasiperiodic")) return "#1f3fbf";
  if (!strcmp(name, "contact")) return "#000000";
  if (!strcmp(name, "middle")) return "#ff7f0e";
  return "#999999";
}

/* basins.gp: the initial states coloured by the class they end in, only
 * the classes that occur (so the key says what is drawn). */
static int write_script(cli_outdir *od, const whirl_sfd_attractors *A, size_t na,
                        const size_t *cnt, size_t ncontact, size_t nunset, size_t nfail,
                        size_t n, double Om, const char *vel) {
  out_file g;
  if (out_open(&g, od, "basins.gp")) return -1;
  FILE *f = g.fp;
  cli_gp_preamble(f, CMD, "basins", 900, 900, "Sans,12");
  fprintf(f, "set title 'basins of attraction, {/Symbol W} = %g, %s initial velocities'\n"
             "set size ratio -1\nset xrange [-1.05:1.05]\nset yrange [-1.05:1.05]\n"
             "set xlabel 'y_0'\nset ylabel 'z_0'\nset key outside right top box opaque\n"
             "set object 1 circle at 0,0 size 1 fs empty border lc rgb 'black' lw 2\n",
          Om, vel);
  const char *names[WHIRL_BASINS_MAX_ATTRACTORS + 3]; /* and the 3 outcomes */
  size_t nn = 0;
  /* only the classes that occur, so the key says what is drawn */
  for (size_t j = 0; j < na; ++j)
    if (cnt[j]) names[nn++] = whirl_sfd_attractors_info(A, j)->name;
  if (ncontact) names[nn++] = "contact";
  if (nunset) names[nn++] = "unsettled";
  if (nfail) names[nn++] = "failed";
  double ps = n > 20000 ? 0.25 : n > 4000 ? 0.45 : 0.8;
  fprintf(f, "plot ");
  for (size_t j = 0; j < nn; ++j)
    fprintf(f, "%s'basins.tsv' using ((strcol(5) eq '%s') ? $1 : 1/0):2 with points pt 7 ps %g "
               "lc rgb '%s' title '%s'", j ? ", \\\n  " : "", names[j], ps, colour_of(names[j]), names[j]);
  fprintf(f, "\n");
  return out_commit(&g);
}

int cmd_sfd_basins(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = NAN;
  size_t npoints = 8000, periods = 500, seeds = 4, levels = 4, cells = 32, hits = 4, phases = 8;
  double radius = 0.98, rtol = 1e-12, atol = 1e-15;
  int threads = 0, fixed = 0, noplot = 0, quiet = 0;
  const char *vel = "zero", *dir = "sfd-basins";
  const cli_opt opts[] = {
      SFD_OPT_OMEGA(p),
      {"--velocities", CLI_STRING, &vel, "V",
       "initial velocities\n"
       "zero: y' = z' = 0 (Figs. 12, 13a, 14a);\n"
       "circular: (y', z') = Omega (-z, y), the velocity of a circular orbit through (y, z) "
       "(Figs. 13b, 14b, 15b);\n"
       "trajectory: displacements sampled from the trajectory from rest over periods "
       "600..1200, zero velocities (Figs. 15a-17)", NULL},
      {"--points", CLI_SIZE, &npoints, "N", "about N initial states", NULL},
      {"--radius", CLI_DOUBLE, &radius, "R", "displacements within R of the clearance", NULL},
      {"--periods", CLI_SIZE, &periods, "P", "most forcing periods per trajectory", NULL},
      {"--fixed-horizon", CLI_FLAG, &fixed, NULL,
       "always integrate P periods, classify at the end", NULL},
      {"--seeds", CLI_SIZE, &seeds, "K",
       "atlas of classified cells: every K-th initial state is classified first and its "
       "trajectory's cells keep its class; 0: no atlas, every state integrated until a "
       "certified capture (doc/sfd-time-domain.md)", NULL},
      {"--levels", CLI_SIZE, &levels, "L",
       "those states in L rounds (1..8) of strides K*4^(L-1), ..., 4K, K, each round "
       "using the cells of the rounds before", NULL},
      {"--cells", CLI_SIZE, &cells, "N", "atlas cells: N intervals per coordinate", NULL},
      {"--cell-hits", CLI_SIZE, &hits, "H",
       "consecutive section points in cells of one attractor that classify a state", NULL},
      {"--phases", CLI_SIZE, &phases, "M", "atlas section points a forcing period (1..64)", NULL},
      {"--threads", CLI_INT, &threads, "T", "OpenMP threads, 0..1024; 0: as many as OpenMP offers", NULL},
      SFD_OPTS_MODEL(p),
      SFD_OPTS_TOL(rtol, atol),
      CLI_OPTS_OUT(dir, noplot, quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 0 : 2;
  if (sfd_check(CMD, p, 1)) return 2;
  int vmode = !strcmp(vel, "zero") ? 0 : !strcmp(vel, "circular") ? 1 : !strcmp(vel, "trajectory") ? 2 : -1;
  if (vmode < 0) {
    cli_error(CMD, "--velocities must be zero, circular or trajectory (got '%s')", vel);
    return 2;
  }
  if (npoints < 1 || npoints > 10000000) {
    cli_error(CMD, "--points must be in [1, 1e7] (got %zu)", npoints);
    return 2;
  }
  if (!(radius > 0 && radius < 1)) {
    cli_error(CMD, "--radius must be in (0, 1): a fraction of the clearance (got %g)", radius);
    return 2;
  }
  if (periods < 1) {
    cli_error(CMD, "--periods must be >= 1");
    return 2;
  }
  if (phases < 1 || phases > 64) {
    cli_error(CMD, "--phases must be in 1..64 (got %zu)", phases);
    return 2;
  }
  if (levels < 1 || levels > 8 || cells < 1 || cells > 1000000 || hits < 1 || hits > periods) {
    cli_error(CMD, "need 1 <= --levels <= 8, 1 <= --cells <= 1e6, 1 <= --cell-hits <= --periods "
              "(got %zu, %zu, %zu)", levels, cells, hits);
    return 2;
  }
  if (threads < 0 || threads > WHIRL_BASINS_MAX_THREADS) {
    cli_error(CMD, "--threads must be in 0..%d (got %d)", WHIRL_BASINS_MAX_THREADS, threads);
    return 2;
  }
  if (sfd_check_tolerances(CMD, rtol, atol)) return 2;
  int orc = cli_outdir_check(CMD, NULL, dir); /* before the work, not after */
  if (orc) return orc;
  const double Om = p[WHIRL_SFD_OMEGA], T = 2 * WHIRL_PI / Om;
  char msg[512];
  double t_start = cli_now();

  /* 1. attractors */
  whirl_sfd_attractors_options ao;
  whirl_sfd_attractors_options_default(&ao);
  ao.rtol = rtol;
  ao.atol = atol;
  if (!quiet && cli_is_tty()) fprintf(stderr, "whirl sfd basins: finding the attractors at Omega = %g ...\r", Om);
  whirl_sfd_attractors *A = NULL;
  int rc = whirl_sfd_attractors_find(p, &ao, &A, msg, sizeof msg);
  if (rc != WHIRL_OK) {
    cli_error(CMD, "%s", msg);
    return 1;
  }
  double t_att = cli_now() - t_start;
  const size_t na = whirl_sfd_attractors_count(A);

  /* 2. initial states */
  size_t n = 0;
  double *X = NULL;
  if (vmode < 2) {
    n = whirl_sfd_disc_points(npoints, radius, NULL, 0);
    X = malloc(4 * (n ? n : 1) * sizeof *X);
    double *yz = malloc(2 * (n ? n : 1) * sizeof *yz);
    if (!X || !yz) {
      free(X);
      free(yz);
      whirl_sfd_attractors_free(A);
      cli_error(CMD, "out of memory");
      return 1;
    }
    whirl_sfd_disc_points(npoints, radius, yz, n);
    for (size_t i = 0; i < n; ++i) {
      X[4 * i] = yz[2 * i];
      X[4 * i + 1] = yz[2 * i + 1];
      X[4 * i + 2] = X[4 * i + 3] = 0;
      if (vmode == 1) whirl_sfd_circular_velocity(Om, yz[2 * i], yz[2 * i + 1], &X[4 * i + 2], &X[4 * i + 3]);
    }
    free(yz);
  } else {
    n = npoints;
    X = malloc(4 * n * sizeof *X);
    if (!X) {
      whirl_sfd_attractors_free(A);
      cli_error(CMD, "out of memory");
      return 1;
    }
    rc = whirl_sfd_trajectory_samples(p, NULL, 600, 600, n, rtol, atol, X, msg, sizeof msg);
    if (rc != WHIRL_OK) {
      cli_error(CMD, "--velocities trajectory: %s", msg);
      free(X);
      whirl_sfd_attractors_free(A);
      return 1;
    }
    for (size_t i = 0; i < n; ++i) X[4 * i + 2] = X[4 * i + 3] = 0;
  }

  /* 3. classify */
  whirl_basins_options bo;
  whirl_basins_options_default(&bo);
  bo.period = T;
  bo.max_periods = periods;
  bo.fixed_horizon = fixed;
  bo.rtol = rtol;
  bo.atol = atol;
  bo.nthreads = threads;
  bo.seed_stride = seeds;
  bo.cells = cells;
  bo.atlas_levels = levels;
  bo.section_phases = phases;
  bo.cell_hits = hits;
  cli_progress prog;
  cli_progress_init(&prog, "whirl sfd basins", quiet);
  bo.progress = progress_cb;
  bo.progress_data = &prog;
  int *which = malloc(n * sizeof *which);
  unsigned *per = malloc(n * sizeof *per);
  if (!which || !per) {
    cli_error(CMD, "out of memory");
    free(which);
    free(per);
    free(X);
    whirl_sfd_attractors_free(A);
    return 1;
  }
  whirl_basins_stats bst;
  double t1 = cli_now();
  rc = whirl_basins_compute(whirl_sfd_fixed(), p, n, X, whirl_sfd_attractors_list(A), na, &bo, which,
                            per, &bst, msg, sizeof msg);
  double t_cls = cli_now() - t1;
  cli_progress_end(&prog);
  if (rc != WHIRL_OK) {
    cli_error(CMD, "%s", msg);
    free(which);
    free(per);
    free(X);
    whirl_sfd_attractors_free(A);
    return 1;
  }

  /* 4. tally and write */
  size_t cnt[WHIRL_BASINS_MAX_ATTRACTORS] = {0}, ncontact = 0, nunset = 0, nfail = 0;
  for (size_t i = 0; i < n; ++i) {
    if (which[i] >= 0) ++cnt[which[i]];
    else if (which[i] == WHIRL_BASIN_DOMAIN) ++ncontact;
    else if (which[i] == WHIRL_BASIN_UNSETTLED) ++nunset;
    else ++nfail;
  }
  cli_outdir od;
  out_file fb, fa;
  int bad = cli_outdir_begin(&od, CMD, NULL, dir) != 0;
  if (!bad && !(bad = out_open(&fb, &od, "basins.tsv"))) {
    fprintf(fb.fp, "y0\tz0\tvy0\tvz0\tattractor\tperiods\n");
    fprintf(fb.fp, "# whirl sfd basins: Omega=%.10g lambda=%.10g delta=%.10g zeta=%.10g velocities=%s "
                   "periods=%zu%s rtol=%g atol=%g\n",
            Om, p[1], p[2], p[3], vel, periods, fixed ? " (fixed horizon)" : "", rtol, atol);
    for (size_t i = 0; i < n; ++i) {
      const char *name = which[i] >= 0 ? whirl_sfd_attractors_info(A, (size_t)which[i])->name
                         : which[i] == WHIRL_BASIN_DOMAIN ? "contact"
                         : which[i] == WHIRL_BASIN_UNSETTLED ? "unsettled" : "failed";
      fprintf(fb.fp, "%.10g\t%.10g\t%.10g\t%.10g\t%s\t%u\n", X[4 * i], X[4 * i + 1], X[4 * i + 2],
              X[4 * i + 3], name, per[i]);
    }
    bad = out_commit(&fb);
  }
  if (!bad && !(bad = out_open(&fa, &od, "attractors.tsv"))) {
    fprintf(fa.fp, "attractor\tclass\teps_max\teps_min\trate\tlevel\n");
    for (size_t j = 0; j < na; ++j) {
      const whirl_sfd_attractor_info *in = whirl_sfd_attractors_info(A, j);
      fprintf(fa.fp, "%s\t%s\t%.12g\t%.12g\t%.6g\t%.6g\n", in->name,
              in->kind == WHIRL_SFD_CIRCULAR ? "circular" : "quasiperiodic", in->eps, in->eps_min,
              in->rate, in->level);
    }
    bad = out_commit(&fa);
  }

  printf("attractor\tcount\tpercent\n");
  for (size_t j = 0; j < na; ++j)
    printf("%s\t%zu\t%.2f\n", whirl_sfd_attractors_info(A, j)->name, cnt[j], 100.0 * (double)cnt[j] / (double)n);
  if (ncontact) printf("contact\t%zu\t%.2f\n", ncontact, 100.0 * (double)ncontact / (double)n);
  if (nunset) printf("unsettled\t%zu\t%.2f\n", nunset, 100.0 * (double)nunset / (double)n);
  if (nfail) printf("failed\t%zu\t%.2f\n", nfail, 100.0 * (double)nfail / (double)n);

  if (!bad && !noplot) bad = write_script(&od, A, na, cnt, ncontact, nunset, nfail, n, Om, vel);
  static const char *const pics[] = {"basins", NULL};
  int status = cli_outdir_finish(&od, bad, noplot ? NULL : pics);
  if (!quiet) {
    fprintf(stderr, "whirl sfd basins: Omega = %g, %zu initial states (%s velocities), %zu attractor%s:\n",
            Om, n, vel, na, na == 1 ? "" : "s");
    for (size_t j = 0; j < na; ++j) {
      const whirl_sfd_attractor_info *in = whirl_sfd_attractors_info(A, j);
      if (in->kind == WHIRL_SFD_CIRCULAR)
        fprintf(stderr, "  %-13s circular orbit eps = %.10g, Re mu = %.4g, certified level %.3g\n",
                in->name, in->eps, in->rate, in->level);
      else
        fprintf(stderr, "  %-13s limit cycle of the rotating frame, eps in [%.4g, %.4g], tolerance %.3g\n",
                in->name, in->eps_min, in->eps, in->level);
    }
    char thr[32];
    if (threads > 0) snprintf(thr, sizeof thr, "%d thread%s", threads, threads == 1 ? "" : "s");
    else snprintf(thr, sizeof thr, "all threads");
    fprintf(stderr, "  attractors %.2f s; basins %.2f s on %s; %zu periods (%.1f per point), "
                    "%zu steps, %zu RHS evaluations; %zu points by the atlas\n",
            t_att, t_cls, thr, bst.periods,
            (double)bst.periods / (double)n, bst.steps, bst.rhs_evals, bst.by_atlas);
  }
  free(which);
  free(per);
  free(X);
  whirl_sfd_attractors_free(A);
  return status;
}

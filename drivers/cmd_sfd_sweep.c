/* drivers/cmd_sfd_sweep.c — `whirl sfd sweep`: the paper's speed sweep by
 * time integration (§5.1, Fig. 3 markers; Fig. 11): each speed starts from
 * the end state of the previous one; a speed is done when the stroboscopic
 * map has converged (periodic response) or after --periods.  Writes the
 * steady amplitude and the Poincaré points against Ω, and draws them over
 * the continuation curve of circular orbits.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "cli.h"
#include "sfd_common.h"

#define CMD "sfd sweep"

static const cli_doc doc = {
"usage: whirl sfd sweep --from A --to B --step S [options]\n"
"\n"
"Up and/or down sweep of the speed by time integration, each speed started\n"
"from the end state of the previous one (the first of each direction from\n"
"rest, or from --y0 --z0 --vy0 --vz0).\n"
"A speed is finished when successive Poincare points (once per forcing\n"
"period) differ by less than --settle (relative) for 3 periods, else after\n"
"--periods periods; then --record periods are kept as the steady state.\n"
"\n"
"options (defaults: Table 1 of the paper):\n",
"stdout and DIR/sweep.tsv: direction Omega class eps_max eps_min periods\n"
"eps_eq15 diff (eps_eq15: the radius of eq. 15 nearest to the settled\n"
"circular orbit, diff = eps_max - eps_eq15).  DIR/poincare.tsv: the\n"
"section points against Omega.  DIR/sweep.png: amplitudes over the\n"
"continuation curve (Fig. 3); DIR/bifurcation.png: y of the section\n"
"points against Omega (Fig. 11).\n"};

typedef struct {
  double P[4]; /* last section point */
  int n;       /* consecutive small changes */
  double tol;
  int settled;
  double t; /* time of the last section point */
} settle_ctx;

static int on_period(size_t k, double t, const double *x, void *data) {
  settle_ctx *c = data;
  c->t = t;
  if (k == 0) {
    memcpy(c->P, x, 4 * sizeof *x);
    c->n = 0;
    return 0;
  }
  double d = 0, s = 0;
  for (int i = 0; i < 4; ++i) {
    d += (x[i] - c->P[i]) * (x[i] - c->P[i]);
    s += x[i] * x[i];
  }
  memcpy(c->P, x, 4 * sizeof *x);
  c->n = sqrt(d) <= c->tol * (1 + sqrt(s)) ? c->n + 1 : 0;
  if (c->n >= 3) {
    c->settled = 1;
    return 1;
  }
  return 0;
}

typedef struct {
  double *P; /* record x 4 */
  size_t spp, np;
  double emin, emax;
} rec_ctx;

static int on_sample(size_t k, double t, const double *x, void *data) {
  (void)t;
  rec_ctx *c = data;
  double e = hypot(x[0], x[1]);
  if (e < c->emin) c->emin = e;
  if (e > c->emax) c->emax = e;
  if (k % c->spp == 0) {
    memcpy(c->P + 4 * c->np, x, 4 * sizeof *x);
    ++c->np;
  }
  return 0;
}

/* Radius of eq. 15 nearest to e at this speed (independent check). */
static double eq15_radius(const double *p, double e) {
  double eps[16];
  int st[16];
  size_t n = 0;
  if (whirl_sfd_circular_orbits(p, eps, st, NULL, 16, &n) != WHIRL_OK || n == 0) return NAN;
  double best = NAN;
  for (size_t i = 0; i < n && i < 16; ++i)
    if (isnan(best) || fabs(eps[i] - e) < fabs(best - e)) best = eps[i];
  return best;
}

/* sweep.gp (the markers over the continuation curve of circular orbits)
 * and bifurcation.gp (the Poincare points against Omega). */
static int write_scripts(cli_outdir *od, const double *p, double lo, double hi, int up) {
  /* the continuation curve of circular orbits under the markers */
  whirl_sfd_response_options ro;
  whirl_sfd_response_options_default(&ro);
  ro.omega_max = hi * 1.02;
  ro.omega_min = fmin(0.01, lo);
  whirl_sfd_response res;
  char msg[512];
  int rc = whirl_sfd_response_compute(p, &ro, &res, msg, sizeof msg);
  out_file g;
  int bad = out_open(&g, od, "sweep.gp");
  if (!bad) {
    FILE *f = g.fp;
    cli_gp_preamble(f, CMD, "sweep", 1100, 750, "Sans,12");
    for (int pass = 0; pass < 2; ++pass) {
      fprintf(f, "$%s << EOD\n", pass ? "unstable" : "stable");
      if (rc == WHIRL_OK)
        for (size_t b = 0; b < res.nbranch; ++b) {
          const whirl_branch *br = res.branch[b];
          for (size_t i = 0; i < br->len; ++i) {
            int st = br->pts[i].stable == 1;
            if (st == !pass)
              fprintf(f, "%.8g %.8g\n", br->pts[i].p[0], hypot(br->pts[i].x[0], br->pts[i].x[1]));
            else
              fprintf(f, "\n");
          }
          fprintf(f, "\n");
        }
      fprintf(f, "EOD\n");
    }
    char title[256];
    fprintf(f,
            "set title 'speed sweep by time integration over the circular orbits: %s'\n"
            "set xlabel 'dimensionless speed {/Symbol W}'\nset ylabel 'max relative eccentricity {/Symbol e}'\n"
            "set xrange [%g:%g]\nset yrange [0:1]\nset grid\nset key outside right top box\n"
            "plot $stable using 1:2 with lines lw 2 lc rgb '#1f4e9c' title 'stable (continuation)', \\\n"
            "  $unstable using 1:2 with lines dt 2 lw 2 lc rgb '#1f4e9c' title 'unstable', \\\n"
            "  'sweep.tsv' index 0 using 2:4 with points pt 1 ps 1.2 lc rgb 'black' title '%s sweep', \\\n"
            "  'sweep.tsv' index 1 using 2:4 with points pt 1 ps 1.2 lc rgb '#2ca02c' title 'down sweep'\n",
            sfd_gp_params(title, sizeof title, p, SFD_P_MODEL), fmax(0, lo - 0.02 * (hi - lo)),
            hi + 0.02 * (hi - lo),
            up ? "up" : "down");
    bad = out_commit(&g);
  }
  if (rc == WHIRL_OK) whirl_sfd_response_free(&res);
  out_file b;
  if (!bad && !(bad = out_open(&b, od, "bifurcation.gp"))) {
    cli_gp_preamble(b.fp, CMD, "bifurcation", 1100, 750, "Sans,12");
    fprintf(b.fp, "set title 'bifurcation diagram: Poincare points (once per period) of the sweep'\n"
                  "set xlabel 'dimensionless speed {/Symbol W}'\nset ylabel 'y at {/Symbol t} = k 2{/Symbol p}/{/Symbol W}'\n"
                  "set grid\nset key outside right top box\n"
                  "plot 'poincare.tsv' index 0 using 2:3 with points pt 7 ps 0.3 lc rgb 'black' title '%s', \\\n"
                  "  'poincare.tsv' index 1 using 2:3 with points pt 7 ps 0.3 lc rgb '#2ca02c' title 'down'\n",
            up ? "up" : "down");
    bad = out_commit(&b);
  }
  return bad;
}

int cmd_sfd_sweep(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR], x0[4] = {0, 0, 0, 0};
  whirl_sfd_default_params(p);
  double from = NAN, to = NAN, step = NAN, rtol = 1e-12, atol = 1e-15, settle = 1e-11;
  size_t periods = 600, record = 400;
  const char *dir = "sfd-sweep", *direction = "both";
  int noplot = 0, quiet = 0;
  const cli_opt opts[] = {
      {"--from", CLI_DOUBLE, &from, "A", "one end of the speed range, A > 0", NULL},
      {"--to", CLI_DOUBLE, &to, "B", "the other end, B > 0", NULL},
      {"--step", CLI_DOUBLE, &step, "S", "speed step, S > 0", NULL},
      {"--direction", CLI_STRING, &direction, "D", "up, down or both", NULL},
      {"--periods", CLI_SIZE, &periods, "N", "most periods per speed", NULL},
      {"--record", CLI_SIZE, &record, "R", "periods kept as steady state", NULL},
      {"--settle", CLI_DOUBLE, &settle, "TOL", "convergence of the section", NULL},
      SFD_OPTS_STATE(x0),
      SFD_OPTS_MODEL(p),
      SFD_OPTS_TOL(rtol, atol),
      CLI_OPTS_OUT(dir, noplot, quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 0 : 2;
  if (isnan(from) || isnan(to) || isnan(step)) {
    cli_error(CMD, "--from, --to and --step are required (e.g. --from 1 --to 10 --step 0.05)");
    return 2;
  }
  if (!(from > 0) || !(to > 0) || from == to) {
    cli_error(CMD, "need --from > 0, --to > 0 and --from != --to (got %g, %g)", from, to);
    return 2;
  }
  if (!(step > 0)) {
    cli_error(CMD, "--step must be > 0 (got %g)", step);
    return 2;
  }
  double lo = fmin(from, to), hi = fmax(from, to);
  double nsp = floor((hi - lo) / step + 1e-9) + 1;
  if (nsp > 1e5) {
    cli_error(CMD, "%g speeds is too many (max 100000): increase --step", nsp);
    return 2;
  }
  int up = 0, down = 0;
  if (!strcmp(direction, "up")) up = 1;
  else if (!strcmp(direction, "down")) down = 1;
  else if (!strcmp(direction, "both")) up = down = 1;
  else {
    cli_error(CMD, "--direction must be up, down or both (got '%s')", direction);
    return 2;
  }
  if (record < 1 || periods < 1 || record > 100000) {
    cli_error(CMD, "need --periods >= 1 and 1 <= --record <= 100000");
    return 2;
  }
  if (sfd_check_tolerances(CMD, rtol, atol)) return 2;
  if (!(settle > 0)) {
    cli_error(CMD, "--settle must be > 0");
    return 2;
  }
  p[WHIRL_SFD_OMEGA] = hi;
  if (sfd_check(CMD, p, 0)) return 2;
  if (hypot(x0[0], x0[1]) >= 1) {
    cli_error(CMD, "the initial displacement is outside the clearance (|(y0, z0)| must be < 1)");
    return 2;
  }
  /* the tables are written as the sweep goes, into the staged directory */
  cli_outdir od;
  out_file fs, fp;
  int orc = cli_outdir_begin(&od, CMD, NULL, dir);
  if (orc) return orc;
  if (out_open(&fs, &od, "sweep.tsv") || out_open(&fp, &od, "poincare.tsv")) {
    cli_outdir_abort(&od);
    return 1;
  }
  const char *hdr = "direction\tOmega\tclass\teps_max\teps_min\tperiods\teps_eq15\tdiff\n";
  fputs(hdr, fs.fp);
  fprintf(fs.fp, "# whirl sfd sweep: lambda=%.10g delta=%.10g zeta=%.10g, step %g, at most %zu periods "
                 "per speed, settle %g, rtol %g atol %g\n", p[1], p[2], p[3], step, periods, settle, rtol, atol);
  fputs(hdr, stdout);
  fprintf(fp.fp, "direction\tOmega\ty\tz\tvy\tvz\n");
  const size_t SPP = 64;
  double *P = malloc(4 * (record + 1) * sizeof *P);
  if (!P) {
    cli_error(CMD, "out of memory");
    out_abort(&fs);
    out_abort(&fp);
    cli_outdir_abort(&od);
    return 1;
  }
  cli_progress prog;
  cli_progress_init(&prog, "whirl sfd sweep", quiet);
  size_t total = (size_t)nsp * (size_t)(up + down), done = 0, ncirc = 0, nfail = 0;
  double maxdiff = 0;
  whirl_ode_stats tot = {0, 0, 0};
  double t0 = cli_now();
  int status = 0;
  for (int pass = 0; pass < 2 && !status; ++pass) {
    if ((pass == 0 && !up) || (pass == 1 && !down)) continue;
    const char *dname = pass == 0 ? "up" : "down";
    double x[4];
    memcpy(x, x0, sizeof x);
    for (size_t j = 0; j < (size_t)nsp; ++j, ++done) {
      cli_progress_show(&prog, done, total);
      double Om = pass == 0 ? lo + step * (double)j : hi - step * (double)j;
      p[WHIRL_SFD_OMEGA] = Om;
      const double T = 2 * WHIRL_PI / Om;
      whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
      if (!ode || whirl_ode_set_tolerances(ode, rtol, atol) != WHIRL_OK) {
        cli_error(CMD, "cannot set up the integrator (out of memory or bad tolerances)");
        whirl_ode_free(ode);
        status = 1;
        break;
      }
      settle_ctx sc = {{0}, 0, settle, 0, 0};
      int rc = whirl_ode_reset(ode, 0.0, x);
      if (rc == WHIRL_OK) rc = whirl_ode_sample(ode, T, periods, on_period, &sc);
      size_t used = periods;
      if (rc == 1) {
        /* settled at a section point: continue from that state (the
         * integrator itself has stepped past it) */
        rc = WHIRL_OK;
        used = (size_t)llround(sc.t / T);
      }
      rec_ctx rcx = {P, SPP, 0, INFINITY, 0};
      size_t nrec = sc.settled ? 1 : record;
      if (rc == WHIRL_OK) {
        /* restart the sampling at a multiple of T: the section phase */
        double xs[4];
        memcpy(xs, sc.settled ? sc.P : whirl_ode_x(ode), sizeof xs);
        rc = whirl_ode_reset(ode, 0.0, xs);
        if (rc == WHIRL_OK) rc = whirl_ode_sample(ode, T / (double)SPP, SPP * nrec, on_sample, &rcx);
      }
      const char *cls;
      double e15 = NAN, diff = NAN;
      if (rc != WHIRL_OK) {
        int contact = rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(ode) == WHIRL_SFD_CONTACT;
        if (!contact) {
          cli_progress_end(&prog);
          cli_error(CMD, "integration failed at Omega = %g, tau = %g: %s", Om, whirl_ode_t(ode),
                    whirl_ode_errmsg(ode));
          whirl_ode_free(ode);
          status = 1;
          break;
        }
        cls = "contact";
        ++nfail;
        memset(x, 0, sizeof x); /* the next speed starts from rest */
      } else {
        memcpy(x, whirl_ode_x(ode), sizeof x);
        size_t per = 0;
        double dim;
        cls = sc.settled ? sfd_steady_name(WHIRL_STEADY_FIXED, rcx.emax - rcx.emin)
                         : sfd_steady_class(CMD, P, rcx.np, rcx.emax - rcx.emin, &per, &dim);
        if (!cls) {
          cli_progress_end(&prog);
          whirl_ode_free(ode);
          status = 1;
          break;
        }
        if (!strcmp(cls, "circular")) {
          e15 = eq15_radius(p, rcx.emax);
          diff = rcx.emax - e15;
          if (fabs(diff) > maxdiff) maxdiff = fabs(diff);
          ++ncirc;
        }
      }
      used += nrec;
      whirl_ode_stats s;
      whirl_ode_get_stats(ode, &s);
      tot.steps += s.steps;
      tot.rhs_evals += s.rhs_evals;
      whirl_ode_free(ode);
#define ROW_FMT "%s\t%.10g\t%s\t%.12g\t%.12g\t%zu\t%.12g\t%.3e\n"
      double emax = strcmp(cls, "contact") ? rcx.emax : 1.0, emin = strcmp(cls, "contact") ? rcx.emin : NAN;
      fprintf(fs.fp, ROW_FMT, dname, Om, cls, emax, emin, used, e15, diff);
      cli_progress_clear(&prog); /* stdout may be the same terminal */
      printf(ROW_FMT, dname, Om, cls, emax, emin, used, e15, diff);
      fflush(stdout);
      for (size_t k = 0; k < rcx.np && strcmp(cls, "contact"); ++k)
        fprintf(fp.fp, "%s\t%.10g\t%.12g\t%.12g\t%.12g\t%.12g\n", dname, Om, P[4 * k],
                P[4 * k + 1], P[4 * k + 2], P[4 * k + 3]);
    }
    fprintf(fs.fp, "\n\n");
    fprintf(fp.fp, "\n\n");
  }
  cli_progress_end(&prog);
  free(P);
  if (status) {
    out_abort(&fs);
    out_abort(&fp);
    cli_outdir_abort(&od);
    return status;
  }
  int bad = out_commit(&fs) | out_commit(&fp);
  double secs = cli_now() - t0;
  if (!bad && !noplot) bad = write_scripts(&od, p, lo, hi, up);
  static const char *const pics[] = {"sweep", "bifurcation", NULL};
  status = cli_outdir_finish(&od, bad, noplot ? NULL : pics);
  if (!quiet && !bad)
    fprintf(stderr, "whirl sfd sweep: %zu speeds, %zu settled on circular orbits (max |eps - eq. 15| = %.2e), "
                    "%zu contact; %zu steps, %zu RHS evaluations, %.2f s\n",
            done, ncirc, maxdiff, nfail, tot.steps, tot.rhs_evals, secs);
  return status;
}


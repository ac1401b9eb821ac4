/* drivers/cmd_sfd_simulate.c — `whirl sfd simulate`: one response of the SFD
 * rotor by time integration (Dormand–Prince 5(4), RelTol 1e-12, AbsTol 1e-15
 * as the paper's ode45 runs; or BDF by CVODE, --method bdf, for a journal
 * near the housing, where the film makes the equations stiff), with the time history, the orbit in the
 * clearance circle, the stroboscopic Poincaré section (once per forcing
 * period) and the spectrum (paper Figs. 7–10).  Prints the class of the
 * steady state and its dominant frequencies as TSV.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "cli.h"
#include "sfd_common.h"

#define CMD "sfd simulate"

static const cli_doc doc = {
"usage: whirl sfd simulate --omega W [options]\n"
"\n"
"Transient and steady-state response of the rigid rotor on two short SFDs\n"
"by time integration (Dormand-Prince 5(4) with dense output, or BDF by\n"
"SUNDIALS CVODE with --method bdf) from a given initial state, in the fixed\n"
"frame.  BDF pays off when the journal runs close to the housing (large\n"
"unbalance, eccentricity near 1), where the film force makes the equations\n"
"stiff; use it with a looser --rtol (e.g. 1e-8).  The steady state is the\n"
"second half of the run (or from --steady-from); its Poincare section is the\n"
"state once per forcing period (tau = k 2 pi / Omega).\n"
"\n"
"options (defaults: Table 1 of the paper):\n",
"stdout: a line 'class<TAB>K' with K one of circular, periodic,\n"
"quasiperiodic, irregular, transient (not settled yet), contact; then the\n"
"dominant frequencies of y in the steady state as TSV 'rank frequency\n"
"amplitude', frequency in units of the rotation frequency (Hann-windowed\n"
"DFT with Gaussian peak interpolation).\n"
"files: history.tsv (t y z vy vz eps), poincare.tsv, spectrum.tsv,\n"
"peaks.tsv, and history.png, orbit.png, spectrum.png, phase.png.\n"
"exit status: 0 ok, 1 runtime error, 2 bad option, 3 the journal touched\n"
"the housing (eps >= 1; data up to the contact are written).\n"};

typedef struct {
  double *buf; /* (nsamp+1) x 4 */
  size_t cap;
  size_t got;
  /* the step budget per forcing period, checked once a period */
  whirl_ode *ode;
  size_t samples, max_steps, steps0;
  cli_progress *prog;
} hist;

#define OVER_BUDGET 2 /* keep's "stop" status: too many steps in a period */

static int keep(size_t k, double t, const double *x, void *data) {
  (void)t;
  hist *h = data;
  if (k < h->cap) {
    memcpy(h->buf + 4 * k, x, 4 * sizeof *x);
    h->got = k + 1;
  }
  if (k % h->samples == 0) {
    whirl_ode_stats st;
    whirl_ode_get_stats(h->ode, &st);
    if (k > 0 && st.steps - h->steps0 > h->max_steps) return OVER_BUDGET;
    h->steps0 = st.steps;
    cli_progress_show(h->prog, k, h->cap - 1);
  }
  return 0;
}

/* NAME.gp: the common preamble and title, then BODY. */
static int write_gp(cli_outdir *od, const char *name, const char *body,
                    const double *p) {
  out_file o;
  char file[64];
  snprintf(file, sizeof file, "%s.gp", name);
  if (out_open(&o, od, file)) return -1;
  cli_gp_preamble(o.fp, CMD, name, 1000, 800, "Sans,12");
  char title[256];
  fprintf(o.fp, "set grid\nset title 'SFD rotor, %s'\n%s",
          sfd_gp_params(title, sizeof title, p, ~0u), body);
  return out_commit(&o);
}

/* The forcing periods history.png shows in full at its foot. */
#define HISTORY_WINDOW 10

/* The pictures' scripts: the time history, the orbit in the clearance
 * circle with the Poincare section, the phase plane and (without contact)
 * the spectrum.  K0 is the first steady sample. */
static int write_scripts(cli_outdir *od, const double *p, size_t k0, int contact) {
  char body[4096];
  /* A thousand periods of y and z are a solid band: the whole run is shown
   * once a forcing period (the Poincare samples' eps: a transient settling
   * on a line, a band for a quasiperiodic motion), and the motion itself
   * in a window of the last HISTORY_WINDOW periods. */
  snprintf(body, sizeof body,
           "T = 2 * pi / %.17g\n"
           "stats 'history.tsv' using 1 nooutput\n"
           "t1 = STATS_max\nt0 = t1 - %d * T > STATS_min ? t1 - %d * T : STATS_min\n"
           "set multiplot layout 2,1\nset lmargin 10\nset rmargin 10\n"
           "set xlabel '{/Symbol t}'\nset ylabel '{/Symbol e} once a period'\n"
           "set xrange [STATS_min:t1]\nset yrange [0:*]\n"
           "plot 'poincare.tsv' using 2:(sqrt($3**2 + $4**2)) with points pt 7 ps 0.3 "
           "lc rgb '#1f4e9c' notitle\n"
           "set title sprintf('the last %%g periods', (t1 - t0) / T)\n"
           "set xrange [t0:t1]\nset yrange [*:*]\nset ylabel 'y, z'\n"
           "set key outside right top\n"
           "plot 'history.tsv' using 1:2 with lines lw 1.5 lc rgb '#1f4e9c' title 'y', \\\n"
           "     '' using 1:3 with lines lw 1.5 lc rgb '#d62728' title 'z'\n"
           "unset multiplot\n",
           p[WHIRL_SFD_OMEGA], HISTORY_WINDOW, HISTORY_WINDOW);
  int bad = write_gp(od, "history", body, p);
  snprintf(body, sizeof body,
           "set size ratio -1\nset xrange [-1.05:1.05]\nset yrange [-1.05:1.05]\n"
           "set xlabel 'y'\nset ylabel 'z'\nset parametric\nset trange [0:2*pi]\n"
           "plot cos(t), sin(t) with lines lw 2 lc rgb 'black' title 'clearance', \\\n"
           "  'history.tsv' every ::%zu using 2:3 with lines lw 0.5 lc rgb '#1f77b4' title 'orbit', \\\n"
           "  'poincare.tsv' using ($7 == 1 ? $3 : 1/0):4 with points pt 7 ps 0.4 lc rgb '#2ca02c' title 'Poincare section'\n",
           k0 + 1);
  bad = bad || write_gp(od, "orbit", body, p);
  if (!contact) {
    snprintf(body, sizeof body,
             "set logscale y\nset xlabel 'frequency / rotation frequency'\nset ylabel 'amplitude of y'\n"
             "set xrange [0:4]\n"
             "plot 'spectrum.tsv' using 1:2 with lines lw 1.5 lc rgb '#1f4e9c' notitle\n");
    bad = bad || write_gp(od, "spectrum", body, p);
  }
  snprintf(body, sizeof body,
           "set xlabel 'y'\nset ylabel 'dy/d{/Symbol t}'\n"
           "plot 'history.tsv' every ::%zu using 2:4 with lines lw 0.5 lc rgb '#1f77b4' title 'trajectory', \\\n"
           "  'poincare.tsv' using ($7 == 1 ? $3 : 1/0):5 with points pt 7 ps 0.4 lc rgb '#2ca02c' title 'Poincare section'\n",
           k0 + 1);
  bad = bad || write_gp(od, "phase", body, p);
  return bad;
}

int cmd_sfd_simulate(int argc, char **argv) {
  double p[WHIRL_SFD_NPAR], x0[4] = {0, 0, 0, 0};
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = NAN;
  size_t periods = 1000, samples = 64, steady_from = (size_t)-1, max_steps = 1000000;
  double rtol = 1e-12, atol = 1e-15;
  const char *dir = "sfd-simulate", *method_name = "dopri5";
  int noplot = 0, quiet = 0, method = WHIRL_ODE_DOPRI5;
  const cli_opt opts[] = {
      SFD_OPT_OMEGA(p),
      SFD_OPTS_STATE(x0),
      {"--periods", CLI_SIZE, &periods, "N", "forcing periods to integrate", NULL},
      {"--steady-from", CLI_SIZE, &steady_from, "K", "first period of the steady state", "N/2"},
      {"--samples", CLI_SIZE, &samples, "S", "samples per period in the outputs", NULL},
      {"--max-steps", CLI_SIZE, &max_steps, "M",
       "most integration steps in one forcing period; more means the journal crawls along "
       "the housing", NULL},
      SFD_OPTS_MODEL(p),
      SFD_OPT_FE(p),
      SFD_OPTS_TOL(rtol, atol),
      {"--method", CLI_STRING, &method_name, "M",
       "integration method: dopri5 (explicit, order 5), dop853 (explicit, order 8: fewer "
       "steps at tight tolerances) or bdf (implicit, for stiff runs near the housing)", NULL},
      CLI_OPTS_OUT(dir, noplot, quiet)};
  int r = cli_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc);
  if (r) return r == 1 ? 0 : 2;
  if (sfd_check(CMD, p, 1)) return 2;
  if (hypot(x0[0], x0[1]) >= 1) {
    cli_error(CMD, "the initial displacement (%g, %g) is outside the clearance "
              "(|(y0, z0)| = %g must be < 1)", x0[0], x0[1], hypot(x0[0], x0[1]));
    return 2;
  }
  if (periods < 4) {
    cli_error(CMD, "--periods must be >= 4 (got %zu)", periods);
    return 2;
  }
  if (samples < 8 || samples > 4096) {
    cli_error(CMD, "--samples must be in [8, 4096] (got %zu)", samples);
    return 2;
  }
  if (steady_from == (size_t)-1) steady_from = periods / 2;
  if (steady_from >= periods) {
    cli_error(CMD, "--steady-from must be < --periods (got %zu >= %zu)", steady_from, periods);
    return 2;
  }
  if (sfd_check_tolerances(CMD, rtol, atol)) return 2;
  if (whirl_ode_method_parse(method_name, &method) != WHIRL_OK) {
    cli_error(CMD, "--method must be dopri5, dop853 or bdf (got '%s')", method_name);
    return 2;
  }
  if (max_steps < 100) {
    cli_error(CMD, "--max-steps must be >= 100 (got %zu)", max_steps);
    return 2;
  }
  if ((double)periods * (double)samples > 1e7) {
    cli_error(CMD, "--periods x --samples = %g samples is too many to keep (max 1e7: "
              "lower --samples)",
              (double)periods * (double)samples);
    return 2;
  }

  int orc = cli_outdir_check(CMD, NULL, dir); /* before the work, not after */
  if (orc) return orc;

  const double Om = p[WHIRL_SFD_OMEGA], T = 2 * WHIRL_PI / Om;
  const size_t nsamp = periods * samples;
  whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
  cli_progress prog;
  cli_progress_init(&prog, "whirl sfd simulate", quiet);
  hist h = {malloc(4 * (nsamp + 1) * sizeof(double)), nsamp + 1, 0, ode, samples, max_steps,
            0, &prog};
  if (!h.buf || !ode) {
    cli_error(CMD, "out of memory");
    free(h.buf);
    whirl_ode_free(ode);
    return 1;
  }
  (void)whirl_ode_set_method(ode, method); /* a known method, no state yet */
  if (whirl_ode_set_tolerances(ode, rtol, atol) != WHIRL_OK) {
    cli_error(CMD, "bad tolerances: rtol %g (>= 100 machine epsilon), atol %g", rtol, atol);
    free(h.buf);
    whirl_ode_free(ode);
    return 2;
  }
  double t0 = cli_now();
  int rc = whirl_ode_reset(ode, 0.0, x0);
  /* the same budget between two samples: keep is not called while one
   * sample interval takes forever */
  if (rc == WHIRL_OK) rc = whirl_ode_set_max_steps(ode, max_steps);
  if (rc == WHIRL_OK) rc = whirl_ode_sample(ode, T / (double)samples, nsamp, keep, &h);
  cli_progress_end(&prog);
  double secs = cli_now() - t0;
  int contact = 0;
  if (rc == OVER_BUDGET || rc == WHIRL_EMAXITER) {
    const double *x = whirl_ode_x(ode);
    cli_error(CMD, "the integration needed more than %zu steps in one forcing period "
              "(period %.0f, tau = %.6g): the journal is at the housing (eps = %.8f); "
              "start farther from it or raise --max-steps", max_steps,
              floor(whirl_ode_t(ode) / T) + 1, whirl_ode_t(ode), hypot(x[0], x[1]));
    free(h.buf);
    whirl_ode_free(ode);
    return 1;
  }
  if (rc != WHIRL_OK) {
    if (rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(ode) == WHIRL_SFD_CONTACT) {
      contact = 1;
    } else {
      cli_error(CMD, "integration failed at tau = %g: %s", whirl_ode_t(ode),
                whirl_ode_errmsg(ode));
      free(h.buf);
      whirl_ode_free(ode);
      return 1;
    }
  }
  whirl_ode_stats st;
  whirl_ode_implicit_stats ist;
  whirl_ode_get_stats(ode, &st);
  whirl_ode_get_implicit_stats(ode, &ist);
  const double t_contact = whirl_ode_t(ode);
  whirl_ode_free(ode);

  /* steady state: Poincaré points and the spectrum of y */
  const size_t k0 = steady_from * samples;
  const char *cls = "contact";
  size_t period = 0;
  double dim = NAN, eps_spread = 0;
  whirl_peak peaks[16];
  size_t npk = 0;
  size_t npoin = 0;
  double *P = NULL;
  if (!contact) {
    npoin = periods - steady_from + 1;
    P = malloc(4 * npoin * sizeof *P);
    double *y = malloc((nsamp + 1 - k0) * sizeof *y);
    if (!P || !y) {
      cli_error(CMD, "out of memory");
      free(P);
      free(y);
      free(h.buf);
      return 1;
    }
    for (size_t k = 0; k < npoin; ++k)
      memcpy(P + 4 * k, h.buf + 4 * (k0 + k * samples), 4 * sizeof *P);
    double emin = INFINITY, emax = 0;
    for (size_t k = nsamp - samples; k <= nsamp; ++k) {
      double e = hypot(h.buf[4 * k], h.buf[4 * k + 1]);
      emin = fmin(emin, e);
      emax = fmax(emax, e);
    }
    eps_spread = emax - emin;
    cls = sfd_steady_class(CMD, P, npoin, eps_spread, &period, &dim);
    if (!cls) {
      free(P);
      free(y);
      free(h.buf);
      return 1;
    }
    for (size_t k = k0; k <= nsamp; ++k) y[k - k0] = h.buf[4 * k];
    /* dt = T/samples; frequency in units of the rotation frequency = f T */
    rc = whirl_spectrum_peaks(y, nsamp + 1 - k0, 1.0 / (double)samples, 1e-3, peaks, 12, &npk);
    if (rc != WHIRL_OK) npk = 0;
    free(y);
  }

  /* ---- files ---- */
  cli_outdir od;
  out_file fh, fp, fs, fk;
  int bad = cli_outdir_begin(&od, CMD, NULL, dir) != 0;
  if (bad) {
    free(P);
    free(h.buf);
    return 1;
  }
  bad = out_open(&fh, &od, "history.tsv");
  if (!bad) {
    fprintf(fh.fp, "t\ty\tz\tvy\tvz\teps\n");
    fprintf(fh.fp, "# whirl sfd simulate: Omega=%.10g lambda=%.10g delta=%.10g zeta=%.10g FE=%.10g "
                   "x0=(%g, %g, %g, %g) rtol=%g atol=%g method=%s\n",
            p[0], p[1], p[2], p[3], p[4], x0[0], x0[1], x0[2], x0[3], rtol, atol, method_name);
    for (size_t k = 0; k < h.got; ++k) {
      const double *x = h.buf + 4 * k;
      fprintf(fh.fp, "%.10g\t%.12g\t%.12g\t%.12g\t%.12g\t%.12g\n", (double)k * T / (double)samples,
              x[0], x[1], x[2], x[3], hypot(x[0], x[1]));
    }
    bad = out_commit(&fh);
  }
  if (!bad && !(bad = out_open(&fp, &od, "poincare.tsv"))) {
    fprintf(fp.fp, "k\tt\ty\tz\tvy\tvz\tsteady\n");
    fprintf(fp.fp, "# stroboscopic section tau = k 2 pi / Omega; steady = 1 from period %zu\n", steady_from);
    for (size_t k = 0; k * samples < h.got; ++k) {
      const double *x = h.buf + 4 * k * samples;
      fprintf(fp.fp, "%zu\t%.10g\t%.12g\t%.12g\t%.12g\t%.12g\t%d\n", k, (double)k * T, x[0], x[1],
              x[2], x[3], k >= steady_from);
    }
    bad = out_commit(&fp);
  }
  if (!bad && !contact && !(bad = out_open(&fs, &od, "spectrum.tsv"))) {
    size_t m = nsamp + 1 - k0, nf = 0;
    double *y = malloc(m * sizeof *y);
    double *fr = NULL, *am = NULL;
    if (y) {
      for (size_t k = k0; k <= nsamp; ++k) y[k - k0] = h.buf[4 * k];
      whirl_spectrum(y, m, 1.0 / (double)samples, NULL, NULL, 0, &nf);
      fr = malloc(nf * sizeof *fr);
      am = malloc(nf * sizeof *am);
    }
    fprintf(fs.fp, "frequency\tamplitude\n# amplitude spectrum of y over periods %zu..%zu (Hann "
                   "window); frequency in units of the rotation frequency\n", steady_from, periods);
    if (fr && am && whirl_spectrum(y, m, 1.0 / (double)samples, fr, am, nf, &nf) == WHIRL_OK)
      for (size_t k = 0; k < nf && fr[k] <= 4.0; ++k)
        fprintf(fs.fp, "%.8g\t%.8g\n", fr[k], am[k]);
    free(y);
    free(fr);
    free(am);
    bad = out_commit(&fs);
  }
  if (!bad && !(bad = out_open(&fk, &od, "peaks.tsv"))) {
    fprintf(fk.fp, "rank\tfrequency\tamplitude\n");
    for (size_t k = 0; k < npk; ++k)
      fprintf(fk.fp, "%zu\t%.6f\t%.6g\n", k + 1, peaks[k].freq, peaks[k].amp);
    bad = out_commit(&fk);
  }
  if (!bad && !noplot) bad = write_scripts(&od, p, k0, contact);
  const char *pics[] = {"history", "orbit", "phase", contact ? NULL : "spectrum", NULL};
  int status = cli_outdir_finish(&od, bad, noplot ? NULL : pics);
  if (bad) {
    free(P);
    free(h.buf);
    return 1;
  }

  /* ---- stdout ---- */
  printf("class\t%s\n", cls);
  printf("rank\tfrequency\tamplitude\n");
  for (size_t k = 0; k < npk; ++k) printf("%zu\t%.6f\t%.6g\n", k + 1, peaks[k].freq, peaks[k].amp);

  if (contact && !status) status = 3;
  if (contact)
    cli_error(CMD, "the journal touches the housing (eps >= 1) at tau = %.10g (period %.2f) at "
              "Omega = %g; history up to the contact written to %s", t_contact, t_contact / T, Om, dir);
  if (!quiet) {
    fprintf(stderr, "whirl sfd simulate: Omega = %g, %zu periods from (%g, %g, %g, %g): class %s",
            Om, periods, x0[0], x0[1], x0[2], x0[3], cls);
    if (period > 1) fprintf(stderr, " (period %zu)", period);
    if (isfinite(dim)) fprintf(stderr, " (section dimension %.2f)", dim);
    fprintf(stderr, "\n  %s: %zu steps (%zu rejected), %zu RHS evaluations, %.1f RHS/period, %.3f s\n",
            method_name, st.steps, st.rejected, st.rhs_evals,
            (double)st.rhs_evals / (contact ? fmax(t_contact / T, 1e-300) : (double)periods), secs);
    if (method == WHIRL_ODE_BDF)
      fprintf(stderr, "  %zu Jacobians, %zu LU factorisations, %zu Newton iterations\n",
              ist.jac_evals, ist.lu_factors, ist.newton_iters);
    fprintf(stderr, "  wrote %s/history.tsv poincare.tsv%s peaks.tsv%s\n", dir,
            contact ? "" : " spectrum.tsv",
            noplot || status || cli_pictures_skipped() ? "" : " and the pictures");
  }
  free(P);
  free(h.buf);
  return status;
}

/* drivers/cmd_rotor_simulate.c — `whirl rotor simulate FILE --speed S`: the
 * time response of a finite-element rotor with its nonlinear elements
 * (whirl/rotor/fe_ode.h) from a displaced shaft at rest, by BDF (CVODE,
 * the default: FE rotors are stiff) or DOPRI5.  Writes time.tsv (the
 * node's y, z, velocities and radius at every sample), time.png and
 * orbit.png (the last half of the run) into an output directory as one
 * transaction; prints the steady amplitude (the largest radius over the
 * last period) on stdout.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rotor_time.h"

#define CMD "rotor simulate"

static const cli_doc doc = {
"usage: whirl rotor simulate FILE --speed S [options]\n"
"\n"
"Time response of the rotor of FILE (doc/rotor-file.md) at the shaft speed S\n"
"with its unbalance, static loads and nonlinear elements: the equations of\n"
"whirl/rotor/fe.h in first-order form, integrated by BDF (SUNDIALS CVODE with\n"
"the mass matrix on the left and sparse KLU; the default) or Dormand-Prince\n"
"5(4) (--method dopri5, for coarse meshes: the shaft's high modes limit its\n"
"step).  Undamped high modes of the shaft cost both methods many steps.\n"
"The start: the shaft translated by (--y0, --z0) (every node), at rest, t = 0.\n"
"\n"
"options:\n",
"stdout: 'amplitude<TAB>A' (metres), the largest radius sqrt(y^2 + z^2) at\n"
"the node over the last period, and 'change<TAB>D', how much the state at\n"
"the node moved over that period (m; small: a synchronous steady state).\n"
"files: time.tsv (t, y, z, vy, vz, r at the node), time.png, orbit.png.\n"
"exit status: 0 ok, 1 the integration failed, 2 bad input, 3 a journal\n"
"reached a film's clearance (the samples up to there are written).\n"};

typedef struct sim_args {
  const char *file, *unit, *method, *dir;
  double speed, unb, y0, z0, rtol, atol;
  size_t periods, samples;
  int node, noplot, quiet;
} sim_args;

typedef struct hist {
  const whirl_fe_rotor *r;
  int node;
  double *buf; /* 5 per sample: t, y, z, vy, vz */
  size_t cap, got;
  cli_progress *prog;
} hist;

static int keep(size_t k, double t, const double *x, void *data) {
  hist *h = data;
  const int nd = h->r->ndof, dy = whirl_fe_rotor_dof(h->r, h->node, 0);
  if (k < h->cap) {
    double *o = h->buf + 5 * k;
    o[0] = t, o[1] = x[dy], o[2] = x[dy + 1], o[3] = x[nd + dy], o[4] = x[nd + dy + 1];
    h->got = k + 1;
  }
  cli_progress_show(h->prog, k, h->cap - 1);
  return 0;
}

static int parse_args(int argc, char **argv, sim_args *a) {
  const cli_opt opts[] = {
      {"--speed", CLI_DOUBLE, &a->speed, "S", "shaft speed, in --unit", NULL},
      {"--unit", CLI_STRING, &a->unit, "U", "unit of --speed: rpm, rad/s or hz", NULL},
      {"--periods", CLI_SIZE, &a->periods, "N", "revolutions to integrate", NULL},
      {"--samples", CLI_SIZE, &a->samples, "K", "samples per revolution in time.tsv", NULL},
      {"--node", CLI_INT, &a->node, "N", "the node written and plotted",
       "that of the first nonlinear element"},
      {"--y0", CLI_DOUBLE, &a->y0, "Y", "initial displacement of the shaft in y (m)", NULL},
      {"--z0", CLI_DOUBLE, &a->z0, "Z", "initial displacement of the shaft in z (m)", NULL},
      {"--unbalance", CLI_DOUBLE, &a->unb, "F", "multiplies the rotor's unbalance", NULL},
      {"--method", CLI_STRING, &a->method, "M", "bdf (implicit) or dopri5 (explicit)", NULL},
      {"--rtol", CLI_DOUBLE, &a->rtol, "R", "relative tolerance", NULL},
      {"--atol", CLI_DOUBLE, &a->atol, "A", "absolute tolerance (m, m/s)", NULL},
      {"-o", CLI_STRING, &a->dir, "DIR", "output directory (also --out)", NULL},
      CLI_OPTS_OUT(a->dir, a->noplot, a->quiet)};
  return rotor_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc, &a->file);
}

static int check_args(const sim_args *a, int *method) {
  if (!(a->speed > 0)) {
    cli_error(CMD, isnan(a->speed) ? "--speed is required" : "--speed must be > 0 (got %g)",
              a->speed);
    return 2;
  }
  if (a->periods < 1 || a->periods > 1000000 || a->samples < 8 || a->samples > 4096) {
    cli_error(CMD, "need 1 <= --periods <= 1e6 and 8 <= --samples <= 4096");
    return 2;
  }
  if ((double)a->periods * (double)a->samples > 2e7) {
    cli_error(CMD, "--periods x --samples = %g samples is too many (max 2e7)",
              (double)a->periods * (double)a->samples);
    return 2;
  }
  if (!(a->unb >= 0)) {
    cli_error(CMD, "--unbalance must be >= 0 (got %g)", a->unb);
    return 2;
  }
  if (whirl_ode_method_parse(a->method, method) != WHIRL_OK) {
    cli_error(CMD, "--method must be bdf or dopri5 (got '%s')", a->method);
    return 2;
  }
  return 0;
}

static int write_gp(cli_outdir *od, const char *name, const whirl_fe_rotor *r,
                    const sim_args *a, double Om, const char *body) {
  out_file o;
  char file[64], t[600], q[640];
  snprintf(file, sizeof file, "%s.gp", name);
  if (out_open(&o, od, file)) return -1;
  cli_gp_preamble(o.fp, CMD, name, 1000, 800, "Sans,12");
  snprintf(t, sizeof t, "%s, %.6g rad/s, node %d", r->title && *r->title ? r->title : a->file,
           Om, a->node);
  fprintf(o.fp, "set grid\nset title %s noenhanced\nset datafile separator '\\t'\n%s",
          cli_gp_quote(t, q, sizeof q), body);
  return out_commit(&o);
}

static int write_out(const sim_args *a, const whirl_fe_rotor *r, double Om, const hist *h) {
  cli_outdir od;
  int rc = cli_outdir_begin(&od, CMD, NULL, a->dir);
  if (rc) return rc;
  out_file f;
  int bad = out_open(&f, &od, "time.tsv");
  if (!bad) {
    fprintf(f.fp, "t_s\ty_m\tz_m\tvy_m_s\tvz_m_s\tr_m\n");
    for (size_t k = 0; k < h->got; ++k) {
      const double *o = h->buf + 5 * k;
      fprintf(f.fp, "%.12g\t%.10g\t%.10g\t%.10g\t%.10g\t%.10g\n", o[0], o[1], o[2], o[3], o[4],
              hypot(o[1], o[2]));
    }
    bad = out_commit(&f);
  }
  char body[2048];
  const double c = rotor_time_clearance(r);
  snprintf(body, sizeof body,
           "set multiplot layout 2,1\nset xlabel 't (s)'\nset ylabel 'y (mm)'\n"
           "plot 'time.tsv' using 1:(1e3*$2) with lines lw 1 lc rgb '#1f4e9c' notitle\n"
           "set ylabel 'z (mm)'\nunset title\n"
           "plot 'time.tsv' using 1:(1e3*$3) with lines lw 1 lc rgb '#1f4e9c' notitle\n"
           "unset multiplot\n");
  if (!bad && !a->noplot) bad = write_gp(&od, "time", r, a, Om, body);
  char circ[160] = ""; /* the clearance circle of the smallest film */
  if (c > 0)
    snprintf(circ, sizeof circ, "%g*cos(t), %g*sin(t) with lines lw 2 lc rgb 'black' "
             "title 'clearance', \\\n  ", 1e3 * c, 1e3 * c);
  snprintf(body, sizeof body,
           "set size ratio -1\nset key outside right top box\nset xlabel 'y (mm)'\nset ylabel 'z (mm)'\n"
           "set parametric\nset trange [0:2*pi]\n"
           "plot %s'time.tsv' every ::%zu using (1e3*$2):(1e3*$3) with lines lw 1 "
           "lc rgb '#1f77b4' title 'orbit, last half'\n",
           circ, h->got / 2 + 1);
  if (!bad && !a->noplot) bad = write_gp(&od, "orbit", r, a, Om, body);
  static const char *const pics[] = {"time", "orbit", NULL};
  return cli_outdir_finish(&od, bad, a->noplot ? NULL : pics);
}

/* Integrate and sample; 0, 3 (contact) or 1, message printed. */
static int run(const sim_args *a, const whirl_fe_rotor *r, int method, double Om, hist *h) {
  char msg[512] = "";
  whirl_fe_ode *m = whirl_fe_ode_alloc(r, msg, sizeof msg);
  if (!m) {
    cli_error(CMD, "%s", msg);
    return 1;
  }
  double p[WHIRL_FE_NPAR], *z0 = malloc(2 * (size_t)r->ndof * sizeof *z0);
  whirl_fe_hbm_params(Om, p);
  p[WHIRL_FE_P_UNBALANCE] = a->unb;
  int rc = 1; /* out of memory */
  whirl_ode *ode = z0 ? rotor_time_ode(CMD, m, p, method, a->rtol, a->atol, &rc) : NULL;
  if (ode) rc = 0;
  if (ode) {
    rotor_time_start(r, a->y0, a->z0, z0);
    rc = rotor_time_inside(CMD, m, p, z0);
  }
  if (ode && !rc) {
    const double T = 2 * WHIRL_PI / Om, t0 = cli_now();
    rc = whirl_ode_reset(ode, 0.0, z0);
    if (rc == WHIRL_OK) rc = whirl_ode_sample(ode, T / (double)a->samples, h->cap - 1, keep, h);
    cli_progress_end(h->prog);
    whirl_ode_stats st;
    whirl_ode_implicit_stats is;
    whirl_ode_get_stats(ode, &st);
    whirl_ode_get_implicit_stats(ode, &is);
    if (rc != WHIRL_OK) {
      const int contact = rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(ode) > 0;
      cli_error(CMD, contact ? "a journal reached the clearance of a film element at t = %g s"
                             : "the integration failed at t = %g s: %s",
                whirl_ode_t(ode), whirl_ode_errmsg(ode));
      rc = contact ? 3 : 1;
    } else if (!a->quiet)
      fprintf(stderr, "whirl rotor simulate: %zu revolutions, %zu steps, %zu rhs, %zu Jacobians, "
              "%zu LU, %zu error-test and %zu Newton failures, %.3g s\n", a->periods, st.steps,
              st.rhs_evals, is.jac_evals, is.lu_factors, is.error_fails, is.newton_fails,
              cli_now() - t0);
  }
  whirl_ode_free(ode);
  free(z0);
  whirl_fe_ode_free(m);
  return rc;
}

/* the largest radius over the last period, and the state's change over it */
static void summary(const hist *h, size_t samples) {
  double amp = 0.0, d = 0.0;
  const size_t k1 = h->got - 1, k0 = k1 >= samples ? k1 - samples : 0;
  for (size_t k = k0; k <= k1; ++k) amp = fmax(amp, hypot(h->buf[5 * k + 1], h->buf[5 * k + 2]));
  for (int i = 1; i < 3; ++i) d = fmax(d, fabs(h->buf[5 * k1 + i] - h->buf[5 * k0 + i]));
  printf("amplitude\t%.10g\nchange\t%.3g\n", amp, d);
}

int cmd_rotor_simulate(int argc, char **argv) {
  sim_args a = {.unit = "rpm", .method = "bdf", .dir = "rotor-simulate", .speed = NAN,
                .unb = 1, .rtol = 1e-8, .atol = 1e-12, .periods = 200, .samples = 64,
                .node = -1};
  int method, rc = parse_args(argc, argv, &a);
  if (rc) return rc == 1 ? 0 : 2;
  const double f = rotor_unit_factor(CMD, a.unit);
  if (f < 0 || check_args(&a, &method)) return 2;
  whirl_fe_rotor *r = rotor_load(a.file);
  if (!r) return 2;
  a.node = rotor_time_node(CMD, r, a.node);
  rc = a.node < 0 ? 2 : cli_outdir_check(CMD, NULL, a.dir);
  const double Om = a.speed * f;
  cli_progress prog;
  cli_progress_init(&prog, "whirl rotor simulate", a.quiet);
  const size_t cap = a.periods * a.samples + 1;
  hist h = {r, a.node, rc ? NULL : malloc(5 * cap * sizeof(double)), cap, 0, &prog};
  if (!rc && !h.buf) {
    cli_error(CMD, "out of memory");
    rc = 1;
  }
  if (!rc) rc = run(&a, r, method, Om, &h);
  if ((rc == 0 || rc == 3) && h.got > 1) {
    int wrc = write_out(&a, r, Om, &h);
    if (rc == 0 && wrc == 0) summary(&h, a.samples);
    if (wrc) rc = wrc;
  }
  free(h.buf);
  whirl_fe_rotor_free(r);
  return rc;
}

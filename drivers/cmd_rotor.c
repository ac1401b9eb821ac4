/* drivers/cmd_rotor.c — `whirl rotor modes|campbell|response FILE`: the
 * linear analyses of a finite-element rotor file (doc/rotor-file.md,
 * whirl/rotor/fe_linear.h).  modes and response print a TSV on stdout;
 * campbell writes campbell.tsv, critical.tsv and campbell.png into an
 * output directory, as one transaction (outdir.h).  A bad rotor file is
 * "whirl rotor: FILE:LINE: ...", exit 2, before anything is written.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/runfile.h>
#include <whirl/rotor.h>

#include "rotor_cli.h"

#define RPM ROTOR_RPM

static int method_of(const char *cmd, const char *m, whirl_fe_modes_options *o) {
  whirl_fe_modes_options_default(o);
  if (!strcmp(m, "auto")) o->method = WHIRL_FE_EIG_AUTO;
  else if (!strcmp(m, "dense")) o->method = WHIRL_FE_EIG_DENSE;
  else if (!strcmp(m, "arpack")) o->method = WHIRL_FE_EIG_ARPACK;
  else {
    cli_error(cmd, "--method must be auto, dense or arpack (got '%s')", m);
    return -1;
  }
  return 0;
}

#define OPT_METHOD(m)                                                          \
  {"--method", CLI_STRING, &(m), "M",                                          \
   "eigensolver: auto (dense QZ up to 150 DOFs, else ARPACK), dense, arpack",  \
   NULL}

/* ------------------------------------------------------------- modes */

static const cli_doc modes_doc = {
"usage: whirl rotor modes FILE [options]\n"
"\n"
"The damped natural frequencies of the rotor at one speed, lowest first\n"
"(positive frequencies only), with their log decrements and whirl.\n"
"\n"
"options:\n",
"stdout: TSV 'mode omega_rad_s freq_hz log_dec whirl' (forward/backward).\n"
"exit status: 0, 1 a failed eigensolution, 2 bad options or rotor file.\n"};

int cmd_rotor_modes(int argc, char **argv);
int cmd_rotor_modes(int argc, char **argv) {
  const char *CMD = "rotor modes", *file, *unit = "rpm", *method = "auto";
  double speed = 0;
  size_t nmodes = 6;
  const cli_opt opts[] = {
      {"--speed", CLI_DOUBLE, &speed, "S", "shaft speed, in --unit", NULL},
      {"--unit", CLI_STRING, &unit, "U", "unit of --speed: rpm, rad/s or hz", NULL},
      {"--modes", CLI_SIZE, &nmodes, "N", "how many modes", NULL},
      OPT_METHOD(method)};
  int rc = rotor_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &modes_doc, &file);
  if (rc) return rc == 1 ? 0 : 2;
  whirl_fe_modes_options mo;
  const double f = rotor_unit_factor(CMD, unit);
  if (f < 0 || method_of(CMD, method, &mo)) return 2;
  if (nmodes < 1 || nmodes > 100000 || !(speed >= 0)) {
    cli_error(CMD, "need --modes >= 1 and --speed >= 0");
    return 2;
  }
  whirl_fe_rotor *r = rotor_load(file);
  if (!r) return 2;
  whirl_fe_mode *m = malloc(nmodes * sizeof *m);
  size_t nf = 0;
  char msg[512];
  rc = m ? whirl_fe_modes(r, speed * f, &mo, nmodes, m, &nf, msg, sizeof msg) : WHIRL_ENOMEM;
  if (rc) cli_error(CMD, "%s", m ? msg : "out of memory");
  else {
    printf("mode\tomega_rad_s\tfreq_hz\tlog_dec\twhirl\n");
    for (size_t k = 0; k < nf; ++k)
      printf("%zu\t%.10g\t%.10g\t%.6g\t%s\n", k + 1, m[k].omega, m[k].omega / (2 * WHIRL_PI),
             m[k].log_dec, m[k].whirl > 0 ? "forward" : "backward");
  }
  free(m);
  whirl_fe_rotor_free(r);
  return rc ? 1 : 0;
}

/* ---------------------------------------------------------- campbell */

static const cli_doc campbell_doc = {
"usage: whirl rotor campbell FILE [options]\n"
"\n"
"The Campbell diagram of the rotor: the lowest damped natural frequencies\n"
"against speed, with the 1x line and the critical speeds where a mode's\n"
"frequency equals the speed (refined by regula falsi).\n"
"\n"
"options:\n",
"files in DIR: campbell.tsv (speed_rpm speed_rad_s mode omega_rad_s freq_hz\n"
"log_dec whirl), critical.tsv (mode speed_rpm speed_rad_s freq_hz whirl),\n"
"campbell.png (gnuplot).\n"
"exit status: 0, 1 a failed eigensolution or output, 2 bad options or rotor file.\n"};

/* --speeds A:B:N in rad/s into sp[N] (malloc'ed); NULL spec: the file's. */
static double *speed_grid(const char *cmd, const char *spec, double f, const whirl_fe_rotor *r,
                          size_t *n) {
  double a = r->speed_min, b = r->speed_max, nn = 101;
  if (spec) {
    char buf[200], *p[3] = {buf, NULL, NULL};
    snprintf(buf, sizeof buf, "%s", spec);
    for (int k = 1; k < 3; ++k)
      if ((p[k] = strchr(p[k - 1], ':'))) *p[k]++ = '\0';
      else break;
    if (!p[2] || whirl_run_number(p[0], &a) || whirl_run_number(p[1], &b) ||
        whirl_run_number(p[2], &nn)) {
      cli_error(cmd, "--speeds must be A:B:N (got '%s')", spec);
      return NULL;
    }
    a *= f;
    b *= f;
  } else if (!(b > a)) {
    cli_error(cmd, "the rotor file has no speed range: give --speeds A:B:N");
    return NULL;
  }
  if (!(a >= 0) || !(b > a) || nn < 2 || nn > 100000 || nn != floor(nn)) {
    cli_error(cmd, "--speeds A:B:N needs 0 <= A < B and 2 <= N <= 100000 integer");
    return NULL;
  }
  *n = (size_t)nn;
  double *sp = malloc(*n * sizeof *sp);
  for (size_t k = 0; sp && k < *n; ++k) sp[k] = a + (b - a) * (double)k / (double)(*n - 1);
  if (!sp) cli_error(cmd, "out of memory");
  return sp;
}

static void write_campbell(FILE *f, const double *sp, size_t ns, const whirl_fe_mode *cd, size_t nm) {
  fprintf(f, "speed_rpm\tspeed_rad_s\tmode\tomega_rad_s\tfreq_hz\tlog_dec\twhirl\n");
  for (size_t j = 0; j < nm; ++j)
    for (size_t k = 0; k < ns; ++k) {
      const whirl_fe_mode *m = &cd[k * nm + j];
      if (!isfinite(m->omega)) continue;
      fprintf(f, "%.10g\t%.10g\t%zu\t%.10g\t%.10g\t%.6g\t%s\n", sp[k] / RPM, sp[k], j + 1, m->omega,
              m->omega / (2 * WHIRL_PI), m->log_dec, m->whirl > 0 ? "forward" : "backward");
    }
}

static void write_critical(FILE *f, const whirl_fe_critical *c, size_t nc) {
  fprintf(f, "mode\tspeed_rpm\tspeed_rad_s\tfreq_hz\twhirl\n");
  for (size_t k = 0; k < nc; ++k)
    fprintf(f, "%d\t%.10g\t%.10g\t%.10g\t%s\n", c[k].mode + 1, c[k].speed / RPM, c[k].speed,
            c[k].speed / (2 * WHIRL_PI), c[k].whirl > 0 ? "forward" : "backward");
}

static void write_gp(FILE *f, const whirl_fe_rotor *r, const char *file, size_t nm, double top_rpm) {
  char t[600];
  cli_gp_preamble(f, "rotor campbell", "campbell", 1100, 750, "Sans,12");
  snprintf(t, sizeof t, "Campbell diagram: %s", r->title && *r->title ? r->title : file);
  fprintf(f,
          "set title %s noenhanced\nset xlabel 'speed (rev/min)'\nset ylabel 'damped natural "
          "frequency (Hz)'\nset grid\nset key outside right top box\nset datafile separator '\\t'\n"
          "set xrange [*:%g]\nset yrange [0:*]\n",
          cli_gp_quote(t, (char[640]){0}, 640), top_rpm);
  fprintf(f,
          "plot for [j=1:%zu] 'campbell.tsv' using 1:(column(3)==j && strcol(7) eq 'forward' ? "
          "$5 : 1/0) with lines lw 2 lc rgb '#1f4e9c' notitle, \\\n"
          "  for [j=1:%zu] 'campbell.tsv' using 1:(column(3)==j && strcol(7) eq 'backward' ? "
          "$5 : 1/0) with lines lw 2 dt 2 lc rgb '#c0392b' notitle, \\\n"
          "  1/0 with lines lw 2 lc rgb '#1f4e9c' title 'forward', \\\n"
          "  1/0 with lines lw 2 dt 2 lc rgb '#c0392b' title 'backward', \\\n"
          "  x/60 with lines lc rgb 'black' title '1x', \\\n"
          "  'critical.tsv' using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'critical "
          "speeds'\n",
          nm, nm);
}

/* The tables and the picture into DIR, as one transaction. */
static int campbell_out(const char *dir, int noplot, const whirl_fe_rotor *r, const char *file,
                        const double *sp, size_t ns, const whirl_fe_mode *cd, size_t nm,
                        const whirl_fe_critical *c, size_t nc) {
  cli_outdir od;
  int rc = cli_outdir_begin(&od, "rotor campbell", NULL, dir);
  if (rc) return rc;
  out_file a, b, g;
  int bad = out_open(&a, &od, "campbell.tsv");
  if (!bad) write_campbell(a.fp, sp, ns, cd, nm), bad = out_commit(&a);
  if (!bad && !(bad = out_open(&b, &od, "critical.tsv"))) write_critical(b.fp, c, nc), bad = out_commit(&b);
  if (!bad && !noplot && !(bad = out_open(&g, &od, "campbell.gp")))
    write_gp(g.fp, r, file, nm, sp[ns - 1] / RPM), bad = out_commit(&g);
  static const char *const pics[] = {"campbell", NULL};
  return cli_outdir_finish(&od, bad, noplot ? NULL : pics);
}

int cmd_rotor_campbell(int argc, char **argv);
int cmd_rotor_campbell(int argc, char **argv) {
  const char *CMD = "rotor campbell", *file, *unit = "rpm", *method = "auto", *spec = NULL;
  const char *dir = "rotor-campbell";
  size_t nmodes = 6;
  int noplot = 0, quiet = 0;
  const cli_opt opts[] = {
      {"--speeds", CLI_STRING, &spec, "A:B:N", "N speeds from A to B, in --unit",
       "the file's speed range, 101 speeds"},
      {"--unit", CLI_STRING, &unit, "U", "unit of --speeds: rpm, rad/s or hz", NULL},
      {"--modes", CLI_SIZE, &nmodes, "N", "how many modes", NULL},
      OPT_METHOD(method),
      {"-o", CLI_STRING, &dir, "DIR", "output directory (also --out)", NULL},
      CLI_OPTS_OUT(dir, noplot, quiet)};
  int rc = rotor_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &campbell_doc, &file);
  if (rc) return rc == 1 ? 0 : 2;
  whirl_fe_modes_options mo;
  const double f = rotor_unit_factor(CMD, unit);
  if (f < 0 || method_of(CMD, method, &mo)) return 2;
  if (nmodes < 1 || nmodes > 1000) {
    cli_error(CMD, "need 1 <= --modes <= 1000");
    return 2;
  }
  whirl_fe_rotor *r = rotor_load(file);
  if (!r) return 2;
  size_t ns = 0, nc = 0;
  double *sp = speed_grid(CMD, spec, f, r, &ns);
  if (!sp || (rc = cli_outdir_check(CMD, NULL, dir))) {
    free(sp);
    whirl_fe_rotor_free(r);
    return sp ? rc : 2;
  }
  whirl_fe_mode *cd = malloc(ns * nmodes * sizeof *cd);
  whirl_fe_critical *c = malloc(ns * nmodes * sizeof *c);
  char msg[512] = "out of memory";
  rc = cd && c ? whirl_fe_campbell(r, sp, ns, &mo, nmodes, cd, msg, sizeof msg) : WHIRL_ENOMEM;
  if (!rc) rc = whirl_fe_critical_speeds(r, sp, ns, &mo, nmodes, cd, c, ns * nmodes, &nc, msg, sizeof msg);
  if (rc) {
    cli_error(CMD, "%s", msg);
    rc = 1;
  } else {
    rc = campbell_out(dir, noplot, r, file, sp, ns, cd, nmodes, c, nc);
    if (!rc && !quiet)
      fprintf(stderr, "whirl rotor campbell: %zu speeds, %zu modes, %zu critical speeds in %s\n", ns,
              nmodes, nc, dir);
  }
  free(cd);
  free(c);
  free(sp);
  whirl_fe_rotor_free(r);
  return rc;
}

/* --------------------------------------------------------- unbalance */

static const cli_doc unbalance_doc = {
"usage: whirl rotor unbalance FILE --node K [options]\n"
"\n"
"The linear steady response of node K to the rotor's unbalances over a\n"
"speed range (the nonlinear elements left out): y(t) = y_amp_m cos(Wt +\n"
"y_phase), likewise z; the orbit's semi-axes and its whirl.\n"
"\n"
"options:\n",
"stdout: TSV 'speed_rpm speed_rad_s y_amp_m y_phase_deg z_amp_m z_phase_deg\n"
"major_m minor_m whirl' (amplitudes in m).\n"
"exit status: 0, 1 a failed solve (an undamped resonance), 2 bad options or\n"
"rotor file.\n"};

/* One row: Q = (Y, Z) at the node; y + iz = r+ e^{iΩt} + r− e^{−iΩt} with
 * r+ = |Y + iZ|/2, r− = |Y − iZ|/2: major r+ + r−, minor |r+ − r−|. */
static void unbalance_row(double Om, double yr, double yi, double zr, double zi) {
  const double rp = hypot(yr - zi, yi + zr) / 2, rm = hypot(yr + zi, yi - zr) / 2;
  printf("%.10g\t%.10g\t%.10g\t%.8g\t%.10g\t%.8g\t%.10g\t%.10g\t%s\n", Om / RPM, Om, hypot(yr, yi),
         atan2(yi, yr) * 180 / WHIRL_PI, hypot(zr, zi), atan2(zi, zr) * 180 / WHIRL_PI, rp + rm,
         fabs(rp - rm), rp >= rm ? "forward" : "backward");
}

static int has_unbalance(const whirl_fe_rotor *r) {
  for (int k = 0; k < r->ndof; ++k)
    if (r->unb_c[k] != 0 || r->unb_s[k] != 0) return 1;
  return 0;
}

int cmd_rotor_unbalance(int argc, char **argv);
int cmd_rotor_unbalance(int argc, char **argv) {
  const char *CMD = "rotor unbalance", *file, *unit = "rpm", *spec = NULL;
  int node = -1;
  const cli_opt opts[] = {
      {"--node", CLI_INT, &node, "K", "the node whose response is shown", "required"},
      {"--speeds", CLI_STRING, &spec, "A:B:N", "N speeds from A to B, in --unit",
       "the file's speed range, 101 speeds"},
      {"--unit", CLI_STRING, &unit, "U", "unit of --speeds: rpm, rad/s or hz", NULL}};
  int rc = rotor_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &unbalance_doc, &file);
  if (rc) return rc == 1 ? 0 : 2;
  const double f = rotor_unit_factor(CMD, unit);
  if (f < 0) return 2;
  whirl_fe_rotor *r = rotor_load(file);
  if (!r) return 2;
  size_t ns = 0;
  double *sp = NULL, *q = NULL;
  rc = 2;
  if (node < 0 || node >= r->nnode) cli_error(CMD, "--node must be a shaft node, 0..%d", r->nnode - 1);
  else if (!has_unbalance(r)) cli_error("rotor", "%s: the rotor has no unbalance", file);
  else if ((sp = speed_grid(CMD, spec, f, r, &ns)) && !(q = malloc(2 * (size_t)r->ndof * sizeof *q)))
    cli_error(CMD, "out of memory");
  if (q) {
    rc = 0;
    printf("speed_rpm\tspeed_rad_s\ty_amp_m\ty_phase_deg\tz_amp_m\tz_phase_deg\tmajor_m\tminor_m\twhirl\n");
    char msg[512];
    for (size_t k = 0; k < ns && !rc; ++k) {
      double *qr = q, *qi = q + r->ndof;
      if (whirl_fe_unbalance_response(r, sp[k], qr, qi, msg, sizeof msg)) {
        cli_error(CMD, "%s", msg);
        rc = 1;
      } else
        unbalance_row(sp[k], qr[4 * node], qi[4 * node], qr[4 * node + 1], qi[4 * node + 1]);
    }
  }
  free(q);
  free(sp);
  whirl_fe_rotor_free(r);
  return rc;
}

/* ---------------------------------------------------------- dispatch */

static const struct {
  const char *name;
  int (*run)(int argc, char **argv);
  const char *what;
} rotor_commands[] = {
    {"modes", cmd_rotor_modes,
     "damped natural frequencies, log decrements and whirl at one speed"},
    {"campbell", cmd_rotor_campbell,
     "Campbell diagram and critical speeds over a speed range (TSV, PNG)"},
    {"unbalance", cmd_rotor_unbalance,
     "linear unbalance response of a node over a speed range (the nonlinear elements "
     "left out)"},
    {"export", cmd_rotor_export,
     "the assembled M, C, G, K as Matrix Market files (for matrices lines)"},
    {"loci", cmd_rotor_loci,
     "fold loci in the speed and the unbalance, clearance or viscosity (TSV, PNG)"},
    {"simulate", cmd_rotor_simulate,
     "time response at one speed by BDF or DOPRI5: time history and orbit (TSV, PNG)"},
    {"basins", cmd_rotor_basins,
     "basins of attraction at one speed over initial displacements (TSV, PNG)"},
    {"response", cmd_rotor_response,
     "periodic unbalance response with the nonlinear elements: harmonic balance "
     "in speed, folds, stability (TSV, PNG)"}};
#define NROTOR (sizeof rotor_commands / sizeof rotor_commands[0])

void cli_rotor_help(FILE *f, const char *prefix, size_t col) {
  char label[64];
  for (size_t k = 0; k < NROTOR; ++k) {
    snprintf(label, sizeof label, "%s%s FILE", prefix, rotor_commands[k].name);
    cli_help_item(f, label, rotor_commands[k].what, col);
  }
}

int cmd_rotor(int argc, char **argv) {
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    FILE *f = argc < 2 ? stderr : stdout;
    fprintf(f, "usage: whirl rotor <command> FILE [options]\n\n"
               "Analyses of a finite-element rotor file (doc/rotor-file.md).\n"
               "commands:\n");
    cli_rotor_help(f, "", 20);
    fprintf(f, "\n  whirl rotor <command> --help   options of a command\n");
    return argc < 2 ? 2 : 0;
  }
  for (size_t k = 0; k < NROTOR; ++k)
    if (!strcmp(argv[1], rotor_commands[k].name)) return rotor_commands[k].run(argc - 1, argv + 1);
  fprintf(stderr, "whirl rotor: unknown command '%s' (see whirl rotor --help)\n", argv[1]);
  return 2;
}

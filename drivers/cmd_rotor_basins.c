/* drivers/cmd_rotor_basins.c — `whirl rotor basins FILE --speed S`: basins
 * of attraction of a finite-element rotor at one speed over a grid of
 * initial displacements (y0, z0) of the shaft (rotor_time_start: the shaft
 * translated, at rest).  The attractors are the stable synchronous orbits
 * the harmonic balance finds at S: the response followed from rest over the
 * rotor's speed range (whirl_fe_hbm_response), each of its crossings of S
 * corrected by Newton there and kept when Hill's exponents say stable
 * (isolas the response from rest does not reach are not found).  Each grid
 * point is integrated by BDF (whirl/rotor/fe_ode.h, the mass matrix on the
 * left) and assigned, by whirl_basins_classify, to the first orbit whose
 * state once a revolution (t = kT) stays within --tol of the orbit's
 * (q and q' each relative to their largest entry) for 3 revolutions.
 * Writes attractors.tsv, basins.tsv and basins.png as one transaction.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/basins.h>
#include <whirl/cont.h>

#include "rotor_time.h"

#define CMD "rotor basins"
#define MAXATT 8 /* ≤ the colours of write_gp */
#define H 5

static const cli_doc doc = {
"usage: whirl rotor basins FILE --speed S [options]\n"
"\n"
"Basins of attraction at the shaft speed S of the rotor of FILE over a grid of\n"
"initial displacements (y0, z0) of the shaft (every node translated, at rest).\n"
"The attractors are the stable synchronous orbits of the harmonic balance at S\n"
"(the response from rest over the file's speed range, its crossings of S\n"
"corrected by Newton, stability by Hill); each point is integrated by BDF and\n"
"assigned to the orbit its state once a revolution approaches.\n"
"\n"
"options:\n",
"stdout: TSV 'attractor count', a row per class of points.\n"
"files: attractors.tsv 'attractor amplitude_m node' (index, amplitude at\n"
"--node), basins.tsv 'y0_m z0_m attractor periods' (attractor: 1.. an\n"
"orbit, 0 unsettled, -1 outside or reaching a clearance, -2 failed;\n"
"periods: revolutions integrated), basins.png.\n"
"exit status: 0 ok, 1 failed, 2 bad input.\n"};

typedef struct bas_args {
  const char *file, *unit, *dir;
  double speed, range, tol, rtol, atol;
  size_t grid, periods;
  int node, noplot, quiet;
} bas_args;

typedef struct orbit {
  double *z;   /* the state at t = 0 (mod T), 2 ndof */
  double qs, vs, tol, amp;
  int nd;
} orbit;

static int near_orbit(double t, const double *x, void *data) {
  (void)t;
  const orbit *o = data;
  double dq = 0.0, dv = 0.0;
  for (int i = 0; i < o->nd; ++i) {
    dq = fmax(dq, fabs(x[i] - o->z[i]));
    dv = fmax(dv, fabs(x[o->nd + i] - o->z[o->nd + i]));
  }
  return dq < o->tol * o->qs && dv < o->tol * o->vs;
}

/* the response's points: speed and unknowns */
typedef struct trace { double *om, *X; size_t n, cap, nx; } trace;

static int collect(const whirl_fe_hbm_response_point *pt, void *ctx) {
  trace *t = ctx;
  if (t->n == t->cap) {
    size_t cap = t->cap ? 2 * t->cap : 256;
    double *om = realloc(t->om, cap * sizeof *om), *X = realloc(t->X, cap * t->nx * sizeof *X);
    if (om) t->om = om;
    if (X) t->X = X;
    if (!om || !X) return WHIRL_ENOMEM;
    t->cap = cap;
  }
  t->om[t->n] = pt->Omega;
  memcpy(t->X + t->n++ * t->nx, pt->X, t->nx * sizeof *t->X);
  return 0;
}

/* orbit o from the HBM solution X at Ω: its state at t = 0 */
static int make_orbit(whirl_fe_hbm *h, const whirl_fe_rotor *r, const double *X, double Om,
                      int node, double tol, orbit *o) {
  const int nd = r->ndof;
  double p[WHIRL_FE_NPAR], *q = malloc((size_t)nd * (2 * H + 1) * sizeof *q);
  o->z = calloc(2 * (size_t)nd, sizeof *o->z);
  whirl_fe_hbm_params(Om, p);
  if (!q || !o->z || whirl_fe_hbm_recover(h, X, p, q)) { free(q); return -1; }
  o->nd = nd, o->tol = tol, o->qs = o->vs = 0.0;
  o->amp = whirl_fe_hbm_amplitude(h, q, node);
  for (int i = 0; i < nd; ++i) {
    o->z[i] = q[i];
    for (int k = 1; k <= H; ++k) {
      o->z[i] += q[nd * (2 * k - 1) + i];
      o->z[nd + i] += k * Om * q[nd * 2 * k + i];
    }
    o->qs = fmax(o->qs, fabs(o->z[i]));
    o->vs = fmax(o->vs, fabs(o->z[nd + i]));
  }
  free(q);
  return 0;
}

static int stable_at(whirl_fe_hbm *h, const double *X, const double *p) {
  static double re[4096], im[4096];
  size_t m = sizeof re / sizeof re[0];
  return whirl_fe_hbm_hill(h, X, p, re, im, &m) == WHIRL_OK && m > 0 && re[0] < 0;
}

/* The stable orbits at Ω from the response's crossings of Ω. */
static int find_orbits(const char *cmd, whirl_fe_hbm *h, const whirl_fe_rotor *r,
                       const trace *t, double Om, int node, double tol, orbit *o, int *no) {
  const whirl_system *s = whirl_fe_hbm_system(h);
  double p[WHIRL_FE_NPAR], *X = malloc(t->nx * sizeof *X);
  whirl_fe_hbm_params(Om, p);
  *no = 0;
  for (size_t i = 0; X && i + 1 < t->n && *no < MAXATT; ++i) {
    if ((t->om[i] - Om) * (t->om[i + 1] - Om) > 0 || t->om[i] == t->om[i + 1]) continue;
    const size_t j = fabs(t->om[i] - Om) < fabs(t->om[i + 1] - Om) ? i : i + 1;
    memcpy(X, t->X + j * t->nx, t->nx * sizeof *X);
    int its;
    if (whirl_newton(s, X, p, 1e-10, 30, &its) != WHIRL_OK || !stable_at(h, X, p)) continue;
    orbit c;
    if (make_orbit(h, r, X, Om, node, tol, &c)) break;
    int dup = 0;
    for (int k = 0; k < *no; ++k) dup |= fabs(o[k].amp - c.amp) < 1e-6 * c.amp;
    if (dup) free(c.z);
    else o[(*no)++] = c;
  }
  free(X);
  if (*no == 0) cli_error(cmd, "no stable synchronous orbit at this speed");
  return *no > 0 ? 0 : 1;
}

static int attractors(const bas_args *a, const whirl_fe_rotor *r, double Om, orbit *o,
                      int *no) {
  char msg[512] = "";
  whirl_fe_hbm_response_options ro;
  whirl_fe_hbm_response_options_default(&ro);
  ro.hbm.harmonics = H;
  ro.hbm.stability = 0;
  ro.node = a->node;
  ro.speed_min = fmin(r->speed_min, 0.5 * Om);
  ro.speed_max = fmax(r->speed_max, 1.5 * Om);
  whirl_fe_hbm *h = whirl_fe_hbm_alloc(r, &ro.hbm, msg, sizeof msg);
  trace t = {NULL, NULL, 0, 0, h ? whirl_fe_hbm_size(h) : 0};
  int rc = h ? whirl_fe_hbm_response(r, &ro, collect, &t, msg, sizeof msg) : WHIRL_EINVAL;
  if (rc != WHIRL_OK) cli_error(CMD, "harmonic balance: %s", msg);
  else rc = find_orbits(CMD, h, r, &t, Om, a->node, a->tol, o, no);
  free(t.om), free(t.X);
  whirl_fe_hbm_free(h);
  return rc ? 1 : 0;
}

typedef struct grid {
  double *y0, *z0;
  int *cls;
  unsigned *revs;
  size_t n;
} grid;

/* every grid point classified; class k + 1 for orbit k, 0 unsettled, −1
 * outside or a clearance reached, −2 failed */
static int classify(const bas_args *a, const whirl_fe_rotor *r, double Om, orbit *o, int no,
                    grid *g) {
  char msg[512] = "";
  whirl_fe_ode *m = whirl_fe_ode_alloc(r, msg, sizeof msg);
  double p[WHIRL_FE_NPAR], *z0 = malloc(4 * (size_t)r->ndof * sizeof *z0);
  double *f = z0 ? z0 + 2 * r->ndof : NULL; /* scratch: the rhs at the start */
  whirl_fe_hbm_params(Om, p);
  int code = 1;
  whirl_ode *ode = m && z0 ? rotor_time_ode(CMD, m, p, WHIRL_ODE_BDF, a->rtol, a->atol, &code) : NULL;
  whirl_attractor att[MAXATT];
  for (int k = 0; k < no; ++k)
    att[k] = (whirl_attractor){"orbit", near_orbit, &o[k], 3};
  whirl_basins_options bo;
  whirl_basins_options_default(&bo);
  bo.period = 2 * WHIRL_PI / Om;
  bo.max_periods = a->periods;
  cli_progress prog;
  cli_progress_init(&prog, "whirl rotor basins", a->quiet);
  int rc = ode ? 0 : code;
  for (size_t i = 0; !rc && i < g->n; ++i) {
    rotor_time_start(r, g->y0[i], g->z0[i], z0);
    int w = WHIRL_BASIN_DOMAIN;
    unsigned per = 0;
    const whirl_problem *P = whirl_fe_ode_problem(m);
    if (P->rhs(0.0, z0, p, f, P->data) == 0 && /* inside every clearance */
        whirl_basins_classify(ode, z0, att, (size_t)no, &bo, &w, &per) != WHIRL_OK)
      rc = 1;
    g->cls[i] = w >= 0 ? w + 1 : w == WHIRL_BASIN_UNSETTLED ? 0 : w == WHIRL_BASIN_DOMAIN ? -1 : -2;
    g->revs[i] = per;
    cli_progress_show(&prog, i + 1, g->n);
  }
  cli_progress_end(&prog);
  if (rc && ode) cli_error(CMD, "%s", whirl_ode_errmsg(ode));
  whirl_ode_free(ode);
  whirl_fe_ode_free(m);
  free(z0);
  return rc;
}

static void write_tables(FILE *fa, FILE *fb, const orbit *o, int no, const grid *g, int node) {
  fprintf(fa, "attractor\tamplitude_m\tnode\n");
  for (int k = 0; k < no; ++k) fprintf(fa, "%d\t%.10g\t%d\n", k + 1, o[k].amp, node);
  fprintf(fb, "y0_m\tz0_m\tattractor\tperiods\n");
  for (size_t i = 0; i < g->n; ++i) {
    if (i > 0 && g->y0[i] != g->y0[i - 1]) fputc('\n', fb); /* gnuplot's scans */
    fprintf(fb, "%.10g\t%.10g\t%d\t%u\n", g->y0[i], g->z0[i], g->cls[i], g->revs[i]);
  }
}

/* colours of the classes −2 .. 8 (failed, outside, unsettled, orbits) */
static const unsigned colour[11] = {0x000000, 0xb0b0b0, 0xffffff, 0x1f4e9c, 0xc0392b, 0x2d8f3c,
                                    0xe08e0b, 0x8e44ad, 0x16a085, 0x7f8c8d, 0xd35400};

static void write_gp(FILE *f, const whirl_fe_rotor *r, const bas_args *a, double Om,
                     const orbit *o, int no) {
  char t[600], q[640];
  cli_gp_preamble(f, CMD, "basins", 900, 800, "Sans,12");
  snprintf(t, sizeof t, "basins at %.6g rad/s: %s", Om, r->title && *r->title ? r->title : a->file);
  fprintf(f, "set title %s noenhanced\nset size ratio -1\nset datafile separator '\\t'\n"
             "set xlabel 'y0 (mm)'\nset ylabel 'z0 (mm)'\nset key outside right top vertical\nset autoscale fix\n",
          cli_gp_quote(t, q, sizeof q));
  /* a palette of steps: class c is the band [c − 1/2, c + 1/2] */
  fprintf(f, "set cbrange [-2.5:%g]\nunset colorbox\nset palette defined (", no + 0.5);
  for (int c = -2; c <= no; ++c)
    fprintf(f, "%s%g '#%06x', %g '#%06x'", c > -2 ? ", " : "", c - 0.5, colour[c + 2], c + 0.5,
            colour[c + 2]);
  fprintf(f, ")\nplot 'basins.tsv' using (1e3*$1):(1e3*$2):3 with image notitle");
  for (int k = 0; k < no; ++k)
    fprintf(f, ", \\\n  1/0 with boxes fs solid lc rgb '#%06x' title 'orbit %d, %.3g mm'",
            colour[k + 3], k + 1, 1e3 * o[k].amp);
  fprintf(f, ", \\\n  1/0 with boxes fs solid lc rgb '#%06x' title 'outside', \\\n"
             "  1/0 with boxes fs solid border lc rgb '#000000' fc rgb '#ffffff' title 'unsettled'\n",
          colour[1]);
}

static int write_out(const bas_args *a, const whirl_fe_rotor *r, double Om, const orbit *o,
                     int no, const grid *g) {
  cli_outdir od;
  int rc = cli_outdir_begin(&od, CMD, NULL, a->dir);
  if (rc) return rc;
  out_file fa, fb, fg;
  int bad = out_open(&fa, &od, "attractors.tsv");
  if (!bad && (bad = out_open(&fb, &od, "basins.tsv"))) out_abort(&fa);
  if (!bad) {
    write_tables(fa.fp, fb.fp, o, no, g, a->node);
    bad = out_commit(&fa);
    bad = out_commit(&fb) || bad;
  }
  if (!bad && !a->noplot && !(bad = out_open(&fg, &od, "basins.gp")))
    write_gp(fg.fp, r, a, Om, o, no), bad = out_commit(&fg);
  static const char *const pics[] = {"basins", NULL};
  return cli_outdir_finish(&od, bad, a->noplot ? NULL : pics);
}

static int parse_args(int argc, char **argv, bas_args *a) {
  const cli_opt opts[] = {
      {"--speed", CLI_DOUBLE, &a->speed, "S", "shaft speed, in --unit", NULL},
      {"--unit", CLI_STRING, &a->unit, "U", "unit of --speed: rpm, rad/s or hz", NULL},
      {"--grid", CLI_SIZE, &a->grid, "N", "N x N initial displacements", NULL},
      {"--range", CLI_DOUBLE, &a->range, "R", "y0, z0 in [-R, R] (m)",
       "0.95 x the smallest film clearance"},
      {"--node", CLI_INT, &a->node, "N", "the node of the amplitudes",
       "that of the first nonlinear element"},
      {"--periods", CLI_SIZE, &a->periods, "N", "most revolutions per point", NULL},
      {"--tol", CLI_DOUBLE, &a->tol, "T", "distance to an orbit's state that assigns a point "
       "(relative)", NULL},
      {"--rtol", CLI_DOUBLE, &a->rtol, "R", "relative tolerance of BDF", NULL},
      {"--atol", CLI_DOUBLE, &a->atol, "A", "absolute tolerance of BDF (m, m/s)", NULL},
      {"-o", CLI_STRING, &a->dir, "DIR", "output directory (also --out)", NULL},
      CLI_OPTS_OUT(a->dir, a->noplot, a->quiet)};
  return rotor_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &doc, &a->file);
}

static int check_args(const bas_args *a) {
  const char *why = !(a->speed > 0) ? "--speed is required and must be > 0"
                    : a->grid < 3 || a->grid > 1000 ? "need 3 <= --grid <= 1000"
                    : a->periods < 4 ? "need --periods >= 4"
                    : !(a->tol > 0 && a->tol < 1) ? "need 0 < --tol < 1"
                    : !(isnan(a->range) || a->range > 0) ? "need --range > 0" : NULL;
  if (why) cli_error(CMD, "%s", why);
  return why ? 2 : 0;
}

static int make_grid(grid *g, size_t N, double R) {
  g->n = N * N;
  g->y0 = malloc(g->n * sizeof *g->y0);
  g->z0 = malloc(g->n * sizeof *g->z0);
  g->cls = malloc(g->n * sizeof *g->cls);
  g->revs = malloc(g->n * sizeof *g->revs);
  if (!g->y0 || !g->z0 || !g->cls || !g->revs) return 1;
  for (size_t i = 0; i < N; ++i)
    for (size_t j = 0; j < N; ++j) {
      g->y0[i * N + j] = -R + 2 * R * (double)i / (double)(N - 1);
      g->z0[i * N + j] = -R + 2 * R * (double)j / (double)(N - 1);
    }
  return 0;
}

int cmd_rotor_basins(int argc, char **argv) {
  bas_args a = {.unit = "rpm", .dir = "rotor-basins", .speed = NAN, .range = NAN, .tol = 0.01,
                .rtol = 1e-8, .atol = 1e-12, .grid = 11, .periods = 300, .node = -1};
  int rc = parse_args(argc, argv, &a);
  if (rc) return rc == 1 ? 0 : 2;
  const double f = rotor_unit_factor(CMD, a.unit);
  if (f < 0 || check_args(&a)) return 2;
  whirl_fe_rotor *r = rotor_load(a.file);
  if (!r) return 2;
  a.node = rotor_time_node(CMD, r, a.node);
  rc = a.node < 0 ? 2 : 0;
  if (!rc && r->nnl == 0) {
    cli_error(CMD, "the rotor has no nonlinear element: one orbit, no basins");
    rc = 2;
  }
  if (!rc && isnan(a.range)) a.range = 0.95 * rotor_time_clearance(r);
  if (!rc && !(a.range > 0)) {
    cli_error(CMD, "--range is required for a rotor without film elements");
    rc = 2;
  }
  if (!rc) rc = cli_outdir_check(CMD, NULL, a.dir);
  const double Om = a.speed * f;
  orbit o[MAXATT];
  int no = 0;
  grid g = {0};
  if (!rc) rc = attractors(&a, r, Om, o, &no);
  if (!rc && make_grid(&g, a.grid, a.range)) cli_error(CMD, "out of memory"), rc = 1;
  if (!rc) rc = classify(&a, r, Om, o, no, &g);
  if (!rc) rc = write_out(&a, r, Om, o, no, &g);
  if (!rc) printf("attractor\tcount\n");
  if (!rc)
    for (int k = -2; k <= no; ++k) {
      size_t c = 0;
      for (size_t i = 0; i < g.n; ++i) c += g.cls[i] == k;
      if (c) printf("%d\t%zu\n", k, c);
    }
  for (int k = 0; k < no; ++k) free(o[k].z);
  free(g.y0), free(g.z0), free(g.cls), free(g.revs);
  whirl_fe_rotor_free(r);
  return rc;
}

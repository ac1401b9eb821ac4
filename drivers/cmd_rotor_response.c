/* drivers/cmd_rotor_response.c — `whirl rotor response FILE`: the periodic
 * unbalance response of a finite-element rotor with its nonlinear
 * elements, by harmonic balance condensed onto their DOFs and followed in
 * speed (whirl_fe_hbm_response, doc/fe-hbm.md): from rest across the speed
 * range, and from each --seed (an isola the response from rest does not
 * reach) in both directions.  stdout: the special points (LP, BP, PD, TR)
 * as TSV; the output directory: branches.tsv, special.tsv and
 * response.png (amplitude at a node against speed, stable solid, unstable
 * dashed, folds marked), as one transaction.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rotor_cli.h"

/* One point of a branch as the tables print it. */
typedef struct resp_point {
  int branch, type, stable;
  double Omega, amplitude;
} resp_point;

typedef struct resp_table {
  resp_point *pt;
  size_t n, cap;
  int branch, half;
  size_t reverse_from; /* points of the current half-branch start here */
  cli_progress prog;
  double lo, hi;
} resp_table;

static void reverse_half(resp_table *t, size_t from);

static int collect(const whirl_fe_hbm_response_point *p, void *ctx) {
  resp_table *t = ctx;
  if (p->branch > 0 && (p->branch != t->branch || p->half != t->half)) {
    /* discovery: a found branch's half towards smaller speeds is turned
     * round before its other half follows */
    if (t->half == -1 && p->half == +1 && p->branch == t->branch) reverse_half(t, t->reverse_from);
    if (p->half == -1) t->reverse_from = t->n;
    t->branch = p->branch, t->half = p->half;
  }
  if (t->n == t->cap) {
    size_t cap = t->cap ? 2 * t->cap : 256;
    resp_point *np = realloc(t->pt, cap * sizeof *np);
    if (!np) return WHIRL_ENOMEM;
    t->pt = np, t->cap = cap;
  }
  t->pt[t->n++] = (resp_point){t->branch, p->type, p->stable, p->Omega, p->amplitude};
  cli_progress_show(&t->prog, (size_t)(1000 * (p->Omega - t->lo) / (t->hi - t->lo)), 1000);
  return 0;
}

/* The half-branch from the seed towards smaller speeds, reversed so that
 * the branch reads from its low end, its seed point dropped (the +1 half
 * repeats it). */
static void reverse_half(resp_table *t, size_t from) {
  for (size_t i = from, j = t->n - 1; i < j; i++, j--) {
    resp_point s = t->pt[i];
    t->pt[i] = t->pt[j], t->pt[j] = s;
  }
  if (t->n > from) t->n--;
}

static int is_special(int type) {
  return type == WHIRL_PT_LP || type == WHIRL_PT_BP || type == WHIRL_PT_PD ||
         type == WHIRL_PT_TR || type == WHIRL_PT_HB;
}

static void print_header(FILE *f) {
  fprintf(f, "type\tbranch\tspeed_rad_s\tspeed_rpm\tOmega_nd\tamplitude_m\tstable\n");
}

static void print_point(FILE *f, const resp_point *p, double wref) {
  const char *ty = p->type ? whirl_point_type_name(p->type) : "-";
  fprintf(f, "%s\t%d\t%.12g\t%.12g\t%.12g\t%.12g\t%d\n", ty, p->branch, p->Omega,
          p->Omega / ROTOR_RPM, wref > 0 ? p->Omega / wref : NAN, p->amplitude, p->stable);
}

static void write_table(FILE *f, const resp_table *t, double wref, int special_only) {
  print_header(f);
  for (size_t i = 0; i < t->n; i++)
    if (!special_only || is_special(t->pt[i].type)) print_point(f, &t->pt[i], wref);
}

/* Stable stretches solid, unstable ones dashed, and (--stability off, or
 * where it could not be judged) stability unknown thin grey: each series
 * only when the table has its points. */
static void write_gp(FILE *f, const whirl_fe_rotor *r, const char *file, int node,
                     const resp_table *tb) {
  static const char *const series[3] = {
      "'branches.tsv' using 4:($7<0 ? 1e3*$6 : 1/0) with lines lw 1 lc rgb '#777777' "
      "title 'stability not computed'",
      "'branches.tsv' using 4:($7==0 ? 1e3*$6 : 1/0) with lines lw 2 dt 2 lc rgb '#c0392b' "
      "title 'unstable'",
      "'branches.tsv' using 4:($7==1 ? 1e3*$6 : 1/0) with lines lw 2 lc rgb '#1f4e9c' "
      "title 'stable'"};
  int seen[3] = {0, 0, 0}, lp = 0, other = 0;
  for (size_t i = 0; i < tb->n; i++) {
    seen[tb->pt[i].stable < 0 ? 0 : tb->pt[i].stable ? 2 : 1] = 1;
    lp |= tb->pt[i].type == WHIRL_PT_LP;
    other |= is_special(tb->pt[i].type) && tb->pt[i].type != WHIRL_PT_LP;
  }
  char t[600], q[640];
  cli_gp_preamble(f, "rotor response", "response", 1100, 750, "Sans,12");
  snprintf(t, sizeof t, "unbalance response at node %d: %s", node,
           r->title && *r->title ? r->title : file);
  fprintf(f,
          "set title %s noenhanced\nset xlabel 'speed (rev/min)'\n"
          "set ylabel 'amplitude at node %d (mm)'\nset grid\nset key outside right top box\n"
          "set datafile separator '\\t'\nplot ",
          cli_gp_quote(t, q, sizeof q), node);
  const char *sep = "";
  for (int k = 2; k >= 0; k--)
    if (seen[k]) fprintf(f, "%s%s", sep, series[k]), sep = ", \\\n  ";
  if (lp)
    fprintf(f, "%s'special.tsv' using 4:(strcol(1) eq 'LP' ? 1e3*$6 : 1/0) with points "
            "pt 7 ps 1.4 lc rgb 'black' title 'LP'", sep), sep = ", \\\n  ";
  if (other)
    fprintf(f, "%s'special.tsv' using 4:(strcol(1) ne 'LP' ? 1e3*$6 : 1/0) with points "
            "pt 6 ps 1.6 lc rgb '#2d8f3c' title 'BP, PD, TR'", sep);
  fputc('\n', f);
}

/* Breaks between branches (and between the stable and unstable parts)
 * are blank lines in branches.tsv so that gnuplot does not join them. */
static void write_branches(FILE *f, const resp_table *t, double wref) {
  print_header(f);
  for (size_t i = 0; i < t->n; i++) {
    if (i > 0 && t->pt[i].branch != t->pt[i - 1].branch) fputc('\n', f);
    print_point(f, &t->pt[i], wref);
  }
}

static int response_out(const char *dir, int noplot, const whirl_fe_rotor *r,
                        const char *file, int node, const resp_table *t) {
  cli_outdir od;
  int rc = cli_outdir_begin(&od, "rotor response", NULL, dir);
  if (rc) return rc;
  out_file a, b, g;
  int bad = out_open(&a, &od, "branches.tsv");
  if (!bad) write_branches(a.fp, t, r->omega_ref), bad = out_commit(&a);
  if (!bad && !(bad = out_open(&b, &od, "special.tsv")))
    write_table(b.fp, t, r->omega_ref, 1), bad = out_commit(&b);
  if (!bad && !noplot && !(bad = out_open(&g, &od, "response.gp")))
    write_gp(g.fp, r, file, node, t), bad = out_commit(&g);
  static const char *const pics[] = {"response", NULL};
  return cli_outdir_finish(&od, bad, noplot ? NULL : pics);
}

/* --seed W:E — a seeded branch at speed W (in --unit) of relative
 * eccentricity E at the film elements. */
static int parse_seed(const char *cmd, const char *s, double f, double *w, double *e) {
  const char *colon = s ? strchr(s, ':') : NULL;
  char a[64];
  if (!colon || (size_t)(colon - s) >= sizeof a) goto bad;
  memcpy(a, s, (size_t)(colon - s)), a[colon - s] = '\0';
  if (whirl_run_number(a, w) || whirl_run_number(colon + 1, e)) goto bad;
  *w *= f;
  if (*w >= 0 && *e > 0 && *e < 1) return 0;
bad:
  cli_error(cmd, "--seed wants SPEED:EPS with SPEED >= 0 and 0 < EPS < 1 (got '%s')",
            s ? s : "");
  return -1;
}

static const cli_doc response_doc = {
"usage: whirl rotor response FILE [options]\n"
"\n"
"The periodic unbalance response of the rotor with its nonlinear elements\n"
"(squeeze-film dampers, journal bearings, rub, cubic springs): harmonic\n"
"balance condensed onto their degrees of freedom, followed in speed from\n"
"rest with its folds (LP), branch points (BP) and, from Hill's multipliers,\n"
"stability, period doublings (PD) and tori (TR).  --seed adds a branch\n"
"started from forward circular orbits at the film elements (an isola that\n"
"the response from rest does not reach), followed both ways.\n"
"\n"
"options:\n",
"stdout: TSV 'type branch speed_rad_s speed_rpm Omega_nd amplitude_m stable' of\n"
"the special points (Omega: speed over the file's reference frequency).\n"
"files in DIR: branches.tsv (every point), special.tsv, response.png.\n"
"exit status: 0, 1 a failed continuation or output, 2 bad options or rotor file.\n"};

typedef struct resp_args {
  const char *file, *unit, *dir, *seed[8], *stability, *discover;
  double from, to, unb, clr, visc, ds_max;
  size_t harmonics, nmx, nseed, starts, hill_nev;
  int dseed;
  int node, noplot, quiet;
} resp_args;

/* Points in motion whose stability could not be computed (the sparse Hill
 * method's hill_nev too small for the exponents near 0, or a failed
 * eigensolver): said once, since the picture shows them grey. */
static void note_unknown_stability(const resp_table *t, size_t hill_nev) {
  size_t unknown = 0;
  for (size_t i = 0; i < t->n; ++i)
    if (t->pt[i].stable < 0 && t->pt[i].Omega > 0) ++unknown;
  if (unknown)
    fprintf(stderr, "whirl rotor response: stability unknown at %zu of %zu points "
            "(with the sparse Hill method: more than --hill-nev %zu exponents near 0)\n",
            unknown, t->n, hill_nev);
}

static int parse_args(int argc, char **argv, resp_args *a) {
  const char *seed = NULL;
  /* the defaults --help shows are the library's (0 and the sentinels in
   * resp_args mean "not given") */
  whirl_fe_hbm_response_options ro;
  whirl_fe_discover_options dd;
  whirl_fe_hbm_response_options_default(&ro);
  whirl_fe_discover_options_default(&dd);
  char d_h[24], d_nmx[24], d_starts[24], d_seed[24], d_nev[24];
  snprintf(d_h, sizeof d_h, "%zu", ro.hbm.harmonics);
  snprintf(d_nev, sizeof d_nev, "%zu", ro.hbm.hill_nev);
  snprintf(d_nmx, sizeof d_nmx, "%zu", ro.nmx);
  snprintf(d_starts, sizeof d_starts, "%zu", dd.starts);
  snprintf(d_seed, sizeof d_seed, "%lu", (unsigned long)dd.seed);
  const cli_opt opts[] = {
      {"--from", CLI_DOUBLE, &a->from, "S", "lowest speed, in --unit", "the file's"},
      {"--to", CLI_DOUBLE, &a->to, "S", "highest speed, in --unit", "the file's"},
      {"--ds-max", CLI_DOUBLE, &a->ds_max, "S",
       "the longest continuation step in speed, in --unit (a window of unstable "
       "orbits between two torus or period-doubling points narrower than it may be "
       "stepped over)", "a tenth of the range"},
      {"--unit", CLI_STRING, &a->unit, "U", "unit of the speeds: rpm, rad/s or hz", NULL},
      {"--node", CLI_INT, &a->node, "K", "amplitude at node K",
       "the first nonlinear element's node"},
      {"--harmonics", CLI_SIZE, &a->harmonics, "H", "harmonics of the balance", d_h},
      {"--unbalance", CLI_DOUBLE, &a->unb, "S", "scale of the file's unbalances", NULL},
      {"--clearance", CLI_DOUBLE, &a->clr, "S", "scale of the film clearances", NULL},
      {"--viscosity", CLI_DOUBLE, &a->visc, "S", "scale of the film viscosities", NULL},
      {"--seed", CLI_STRING, &seed, "W:E",
       "also the branch through the circular orbits of relative eccentricity E at the "
       "film elements at speed W (in --unit); may be repeated",
       ""},
      {"--discover", CLI_STRING, &a->discover, "W1,W2,...",
       "also every branch found at these speeds (in --unit) by deflated Newton, "
       "deflated against the branches traced (doc/discovery.md)",
       ""},
      {"--discover-starts", CLI_SIZE, &a->starts, "N", "starts per discovery speed",
       d_starts},
      {"--discover-seed", CLI_INT, &a->dseed, "S", "seed of the random starts", d_seed},
      {"--stability", CLI_STRING, &a->stability, "S",
       "Hill's stability: auto (dense up to 1200 unknowns of the Hill matrix, else "
       "reduced), dense, sparse (ARPACK on the whole rotor), reduced (sparse on a "
       "Craig-Bampton reduction: the nonlinear DOFs, the held rotor's modes up to "
       "3 (H + 1/2) omega and inertia-relief vectors), or off",
       NULL},
      {"--hill-nev", CLI_SIZE, &a->hill_nev, "N",
       "the most Floquet exponents the sparse Hill method computes at one orbit (all "
       "within 1.05 omega/2 of 0 are needed; where more lie there, stability is unknown)",
       d_nev},
      {"--nmx", CLI_SIZE, &a->nmx, "N", "continuation steps per branch", d_nmx},
      {"-o", CLI_STRING, &a->dir, "DIR", "output directory (also --out)", NULL},
      CLI_OPTS_OUT(a->dir, a->noplot, a->quiet)};
  /* --seed may be given several times: collect them before cli_parse,
   * which keeps the last */
  for (int i = 1; i < argc; i++)
    if (!strncmp(argv[i], "--seed", 6) && a->nseed < 8) {
      if (argv[i][6] == '=') a->seed[a->nseed++] = argv[i] + 7;
      else if (!argv[i][6] && i + 1 < argc) a->seed[a->nseed++] = argv[i + 1];
    }
  return rotor_parse("rotor response", argc, argv, opts, sizeof opts / sizeof opts[0],
                     &response_doc, &a->file);
}

static int check_args(const char *CMD, resp_args *a, const whirl_fe_rotor *r, double f,
                      whirl_fe_hbm_response_options *o) {
  whirl_fe_hbm_response_options_default(o);
  if (a->harmonics) o->hbm.harmonics = a->harmonics;
  static const char *const stab[] = {"off", "dense", "sparse", "reduced", "auto"};
  int k = 0;
  while (k < 5 && strcmp(a->stability, stab[k])) k++;
  if (k == 5) {
    cli_error(CMD, "--stability must be auto, dense, sparse, reduced or off (got '%s')",
              a->stability);
    return 2;
  }
  o->hbm.stability = k == 4 ? -1 : k;
  if (a->nmx) o->nmx = a->nmx;
  if (a->hill_nev) o->hbm.hill_nev = a->hill_nev;
  if (a->ds_max > 0) o->ds_max = a->ds_max * f;
  o->speed_min = isnan(a->from) ? r->speed_min : a->from * f;
  o->speed_max = isnan(a->to) ? r->speed_max : a->to * f;
  o->unbalance = a->unb, o->clearance = a->clr, o->viscosity = a->visc;
  if (a->node < 0) a->node = r->nnl > 0 ? r->nl[0].node : 0;
  o->node = a->node;
  if (r->nnl == 0) {
    cli_error(CMD, "%s has no nonlinear element: its response is linear (whirl rotor "
              "campbell, or add a damper or bearing)", a->file);
    return 2;
  }
  if (!(o->speed_max > o->speed_min) || o->speed_min < 0) {
    cli_error(CMD, "need 0 <= --from < --to (or a speed line in %s)", a->file);
    return 2;
  }
  if (a->node >= r->nnode) {
    cli_error(CMD, "--node %d: the rotor has nodes 0..%d", a->node, r->nnode - 1);
    return 2;
  }
  if (!(a->ds_max >= 0) || !isfinite(a->ds_max)) {
    cli_error(CMD, "--ds-max must be a speed > 0 (got %g)", a->ds_max);
    return 2;
  }
  if (!(a->unb >= 0) || !(a->clr > 0) || !(a->visc > 0) || o->hbm.harmonics > 200) {
    cli_error(CMD, "need --unbalance >= 0, --clearance > 0, --viscosity > 0, "
              "--harmonics <= 200");
    return 2;
  }
  return 0;
}

/* --discover W1,W2,...: at most 64 speeds, converted to rad/s. */
static int parse_speeds(const char *cmd, const char *s, double f, double *w, size_t *n) {
  char buf[2048];
  *n = 0;
  if (strlen(s) >= sizeof buf) goto bad;
  memcpy(buf, s, strlen(s) + 1);
  for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
    if (*n == 64 || whirl_run_number(tok, &w[*n]) || !(w[*n] >= 0)) goto bad;
    w[(*n)++] *= f;
  }
  if (*n) return 0;
bad:
  cli_error(cmd, "--discover wants up to 64 speeds >= 0 separated by commas, in "
            "--unit (got '%s')", s);
  return -1;
}

/* The branch from rest and the branches discovery finds (--discover). */
static int discover(const char *CMD, const resp_args *a, double f, const whirl_fe_rotor *r,
                    whirl_fe_hbm_response_options *o, resp_table *t, char *msg, size_t len) {
  double speeds[64];
  whirl_fe_discover_options d;
  whirl_fe_discover_report rep;
  whirl_fe_discover_options_default(&d);
  if (parse_speeds(CMD, a->discover, f, speeds, &d.nspeeds)) return WHIRL_EINVAL;
  d.speeds = speeds;
  if (a->starts != SIZE_MAX) d.starts = a->starts;
  if (a->dseed != INT_MIN) d.seed = (unsigned long)a->dseed;
  int rc = whirl_fe_hbm_discover(r, o, &d, collect, t, &rep, msg, len);
  if (!rc && !a->quiet)
    fprintf(stderr, "whirl rotor response: discovery: %zu branch%s, %zu of them isolated "
            "(not connected to the branch from rest); %zu starts, %zu deflated Newton "
            "iterations, %.3f s searching\n", rep.branches, rep.branches == 1 ? "" : "es",
            rep.isolated, rep.starts, rep.iterations, rep.search_seconds);
  return rc;
}

/* The branch from rest, then each seeded branch in both directions. */
static int compute(const char *CMD, const resp_args *a, double f, const whirl_fe_rotor *r,
                   whirl_fe_hbm_response_options *o, resp_table *t) {
  char msg[600] = "";
  t->lo = o->speed_min, t->hi = o->speed_max, t->branch = 1;
  cli_progress_init(&t->prog, "rotor response", a->quiet);
  int rc = a->discover ? discover(CMD, a, f, r, o, t, msg, sizeof msg)
                       : whirl_fe_hbm_response(r, o, collect, t, msg, sizeof msg);
  if (rc == WHIRL_EINVAL && a->discover && !msg[0]) return 2;
  for (size_t s = 0; !rc && s < a->nseed; s++) {
    if (parse_seed(CMD, a->seed[s], f, &o->seed_omega, &o->seed_eps)) return 2;
    t->branch = 2 + (int)s;
    const size_t from = t->n;
    o->direction = -1;
    rc = whirl_fe_hbm_response(r, o, collect, t, msg, sizeof msg);
    reverse_half(t, from);
    o->direction = +1;
    if (!rc) rc = whirl_fe_hbm_response(r, o, collect, t, msg, sizeof msg);
  }
  cli_progress_end(&t->prog);
  if (rc) {
    cli_strip_locations(msg);
    cli_error(CMD, "%s", msg[0] ? msg : whirl_strerror(rc));
    return rc == WHIRL_EINVAL ? 2 : 1;
  }
  return 0;
}

int cmd_rotor_response(int argc, char **argv) {
  const char *CMD = "rotor response";
  resp_args a = {.unit = "rpm", .dir = "rotor-response", .stability = "auto", .from = NAN, .to = NAN,
                 .unb = 1, .clr = 1, .visc = 1, .node = -1, .dseed = INT_MIN, .starts = SIZE_MAX};
  int rc = parse_args(argc, argv, &a);
  if (rc) return rc == 1 ? 0 : 2;
  const double f = rotor_unit_factor(CMD, a.unit);
  if (f < 0) return 2;
  for (size_t s = 0; s < a.nseed; s++) {
    double w, e;
    if (parse_seed(CMD, a.seed[s], f, &w, &e)) return 2;
  }
  if (a.discover) {
    double w[64];
    size_t nw;
    if (parse_speeds(CMD, a.discover, f, w, &nw)) return 2;
    if (a.nseed) {
      cli_error(CMD, "--discover starts from rest and finds the isolas itself: give it "
                "without --seed");
      return 2;
    }
  }
  if ((a.starts != SIZE_MAX || a.dseed != INT_MIN) && !a.discover) {
    cli_error(CMD, "--discover-starts and --discover-seed need --discover SPEEDS");
    return 2;
  }
  if (a.starts == 0 || (a.dseed != INT_MIN && a.dseed < 0)) {
    cli_error(CMD, "--discover-starts must be >= 1 and --discover-seed >= 0");
    return 2;
  }
  whirl_fe_rotor *r = rotor_load(a.file);
  if (!r) return 2;
  whirl_fe_hbm_response_options o;
  whirl_fe_hbm_response_report rep;
  memset(&rep, 0, sizeof rep);
  resp_table t = {0};
  rc = check_args(CMD, &a, r, f, &o);
  o.report = &rep;
  if (!rc) rc = cli_outdir_check(CMD, NULL, a.dir);
  if (!rc) rc = compute(CMD, &a, f, r, &o, &t);
  if (!rc) rc = response_out(a.dir, a.noplot, r, a.file, a.node, &t);
  if (!rc) {
    write_table(stdout, &t, r->omega_ref, 1);
    if (!a.quiet)
      fprintf(stderr, "whirl rotor response: %zu points on %d branches in %s: %zu "
              "steps (%zu rejected), %zu Newton iterations, %zu unknowns, %zu spectra\n",
              t.n, t.branch, a.dir, rep.cont.steps, rep.cont.rejected,
              rep.cont.newton_its, rep.unknowns, rep.cont.eig_evals);
    if (!a.quiet && o.hbm.stability != 0) note_unknown_stability(&t, o.hbm.hill_nev);
  }
  free(t.pt);
  whirl_fe_rotor_free(r);
  return rc;
}

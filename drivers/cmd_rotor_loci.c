/* drivers/cmd_rotor_loci.c — `whirl rotor loci FILE --param P`: the fold
 * loci of a finite-element rotor's periodic response in the speed and a
 * second parameter P (a scale of the unbalance, of the film clearances or
 * of their viscosity): the response is followed in speed (from rest and
 * from each --seed) to find its folds, and from each fold its locus is
 * followed both ways by the generic fold system (whirl_fe_hbm_fold_locus).
 * stdout: the loci's special points (cusps CP, isola births IS and merges
 * MG, folds of the locus LP); DIR: loci.tsv, loci.png.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rotor_cli.h"

/* The folds of the speed response: their unknowns and parameters. */
typedef struct fold_list {
  double *X; /* nfold × n */
  double p[64][WHIRL_FE_NPAR];
  size_t n, nfold;
} fold_list;

static int keep_fold(const whirl_fe_hbm_response_point *pt, void *ctx) {
  fold_list *f = ctx;
  if (pt->type != WHIRL_PT_LP || f->nfold == 64) return 0;
  double *X = realloc(f->X, (f->nfold + 1) * pt->n * sizeof *X);
  if (!X) return WHIRL_ENOMEM;
  f->X = X, f->n = pt->n;
  memcpy(X + f->nfold * pt->n, pt->X, pt->n * sizeof *X);
  whirl_fe_hbm_params(pt->Omega, f->p[f->nfold]);
  f->nfold++;
  return 0;
}

/* The merge points MG found on the loci: the base unknowns, the speed and
 * the locus parameter there. */
typedef struct merge_list {
  double *X;
  double Omega[16], value[16];
  size_t n, count;
} merge_list;

typedef struct locus_out {
  FILE *all;      /* loci.tsv or merge.tsv, being written */
  merge_list mg;
  char *special;  /* the special rows, for stdout */
  size_t len, cap;
  int locus;
  double wref;
} locus_out;

static int add_special(locus_out *o, const char *row) {
  const size_t k = strlen(row);
  if (o->len + k + 1 > o->cap) {
    size_t cap = 2 * (o->cap + k + 256);
    char *s = realloc(o->special, cap);
    if (!s) return WHIRL_ENOMEM;
    o->special = s, o->cap = cap;
  }
  memcpy(o->special + o->len, row, k + 1);
  o->len += k;
  return 0;
}

static int keep_merge(merge_list *m, const whirl_fe_locus_point *pt) {
  if (m->count == 16) return 0;
  double *X = realloc(m->X, (m->count + 1) * pt->n * sizeof *X);
  if (!X) return WHIRL_ENOMEM;
  m->X = X, m->n = pt->n;
  memcpy(X + m->count * pt->n, pt->X, pt->n * sizeof *X);
  m->Omega[m->count] = pt->Omega, m->value[m->count] = pt->value;
  m->count++;
  return 0;
}

static int on_point(const whirl_fe_locus_point *pt, void *ctx) {
  locus_out *o = ctx;
  char row[256];
  int k = snprintf(row, sizeof row, "%s\t%d\t%.12g\t%.12g\t%.12g\t%.12g",
                   pt->type ? whirl_point_type_name(pt->type) : "-", o->locus, pt->Omega,
                   pt->Omega / ROTOR_RPM, o->wref > 0 ? pt->Omega / o->wref : NAN, pt->value);
  if (!isnan(pt->value2)) snprintf(row + k, sizeof row - (size_t)k, "\t%.12g\n", pt->value2);
  else snprintf(row + k, sizeof row - (size_t)k, "\n");
  fputs(row, o->all);
  if (pt->type == WHIRL_PT_MG && isnan(pt->value2) && keep_merge(&o->mg, pt)) return WHIRL_ENOMEM;
  return pt->type && pt->type != WHIRL_PT_EP ? add_special(o, row) : 0;
}

static const char *const param_names[] = {NULL, "unbalance", "clearance", "viscosity"};

static const cli_doc loci_doc = {
"usage: whirl rotor loci FILE --param P [options]\n"
"\n"
"Fold loci of the periodic unbalance response in the speed and a second\n"
"parameter P: unbalance (a scale of the file's unbalances), clearance (of\n"
"the film elements' clearances) or viscosity.  The folds of the response\n"
"in speed (from rest, and from each --seed) start the loci; each is\n"
"followed both ways by the fold system (minimal augmentation), with its\n"
"cusps (CP) and the points where an isolated branch is born (IS) or merges\n"
"(MG).\n"
"\n"
"options:\n",
"stdout: TSV 'type locus speed_rad_s speed_rpm Omega_nd P' of the loci's\n"
"special points.  files in DIR: loci.tsv (every point, a blank line between\n"
"loci), loci.png; with --merge-along Q, merge.tsv 'type curve speed_rad_s\n"
"speed_rpm Omega_nd Q P': the merge curves.\n"
"exit status: 0, 1 a failed continuation or output, 2 bad options or rotor file.\n"};

typedef struct loci_args {
  const char *file, *unit, *dir, *param, *range, *seed, *along, *range2;
  size_t harmonics;
  int noplot, quiet;
} loci_args;

static void write_gp(FILE *f, const whirl_fe_rotor *r, const char *file, const char *param) {
  char t[600], q[640];
  cli_gp_preamble(f, "rotor loci", "loci", 1100, 750, "Sans,12");
  snprintf(t, sizeof t, "fold loci: %s", r->title && *r->title ? r->title : file);
  fprintf(f,
          "set title %s noenhanced\nset xlabel 'speed (rev/min)'\nset ylabel '%s scale'\n"
          "set grid\nset key outside right top box\nset datafile separator '\\t'\n"
          "plot 'loci.tsv' using 4:6 with lines lw 2 lc rgb '#1f4e9c' title 'folds', \\\n"
          "  'loci.tsv' using 4:(strcol(1) eq 'CP' || strcol(1) eq 'IS' || strcol(1) eq 'MG' ? "
          "$6 : 1/0) with points pt 7 ps 1.5 lc rgb '#c0392b' title 'CP, IS, MG'\n",
          cli_gp_quote(t, q, sizeof q), param);
}

/* The speed response's folds, then their loci into the staged loci.tsv. */
static int compute(const char *CMD, const loci_args *a, const whirl_fe_rotor *r, int param,
                   double lo, double hi, double f, FILE *tsv, locus_out *out) {
  whirl_fe_hbm_response_options ro;
  whirl_fe_hbm_response_options_default(&ro);
  if (a->harmonics) ro.hbm.harmonics = a->harmonics;
  ro.hbm.stability = 0;
  fold_list folds = {0};
  char msg[600] = "";
  int rc = whirl_fe_hbm_response(r, &ro, keep_fold, &folds, msg, sizeof msg);
  if (!rc && a->seed) {
    const char *c = strchr(a->seed, ':');
    double w, e;
    char s[64];
    if (!c || (size_t)(c - a->seed) >= sizeof s) goto bad_seed;
    memcpy(s, a->seed, (size_t)(c - a->seed)), s[c - a->seed] = '\0';
    if (whirl_run_number(s, &w) || whirl_run_number(c + 1, &e) || !(e > 0 && e < 1)) goto bad_seed;
    ro.seed_omega = w * f, ro.seed_eps = e;
    for (int d = -1; !rc && d <= 1; d += 2)
      ro.direction = d, rc = whirl_fe_hbm_response(r, &ro, keep_fold, &folds, msg, sizeof msg);
  }
  whirl_fe_locus_options lo_opt;
  whirl_fe_locus_options_default(&lo_opt);
  lo_opt.hbm = ro.hbm;
  lo_opt.param = param, lo_opt.pmin = lo, lo_opt.pmax = hi;
  fprintf(tsv, "type\tlocus\tspeed_rad_s\tspeed_rpm\tOmega_nd\t%s\n", param_names[param]);
  for (size_t k = 0; !rc && k < folds.nfold; k++)
    for (int d = -1; !rc && d <= 1; d += 2) {
      out->locus = (int)(2 * k + (d > 0)) + 1;
      if (out->locus > 1) fputc('\n', tsv);
      rc = whirl_fe_hbm_fold_locus(r, &lo_opt, folds.X + k * folds.n, folds.p[k], d, on_point,
                                   out, msg, sizeof msg);
    }
  free(folds.X);
  if (rc) {
    cli_strip_locations(msg);
    cli_error(CMD, "%s", msg[0] ? msg : whirl_strerror(rc));
    return 1;
  }
  if (folds.nfold == 0) {
    cli_error(CMD, "the response has no fold in the speed range: no locus to follow");
    return 1;
  }
  return 0;
bad_seed:
  free(folds.X);
  cli_error(CMD, "--seed wants SPEED:EPS with 0 < EPS < 1 (got '%s')", a->seed);
  return 2;
}

/* The merge curves through the loci's MG points, both ways, into f. */
static int merge_curves(const char *CMD, const loci_args *a, const whirl_fe_rotor *r, int param,
                        int along, double lo2, double hi2, FILE *f, locus_out *out) {
  whirl_fe_locus_options o;
  whirl_fe_locus_options_default(&o);
  if (a->harmonics) o.hbm.harmonics = a->harmonics;
  o.param = param, o.pmin2 = lo2, o.pmax2 = hi2;
  char msg[600] = "";
  int rc = 0;
  fprintf(f, "type\tcurve\tspeed_rad_s\tspeed_rpm\tOmega_nd\t%s\t%s\n", param_names[along],
          param_names[param]);
  for (size_t k = 0; !rc && k < out->mg.count; k++)
    for (int d = -1; !rc && d <= 1; d += 2) {
      double p[WHIRL_FE_NPAR];
      whirl_fe_hbm_params(out->mg.Omega[k], p);
      p[param] = out->mg.value[k];
      out->locus = (int)(2 * k + (d > 0)) + 1;
      if (out->locus > 1) fputc('\n', f);
      rc = whirl_fe_hbm_merge_curve(r, &o, along, out->mg.X + k * out->mg.n, p, d, on_point,
                                    out, msg, sizeof msg);
    }
  if (rc) {
    cli_strip_locations(msg);
    cli_error(CMD, "%s", msg[0] ? msg : whirl_strerror(rc));
    return 1;
  }
  if (!a->quiet)
    fprintf(stderr, "whirl rotor loci: %zu merge point%s followed in %s\n", out->mg.count,
            out->mg.count == 1 ? "" : "s", param_names[along]);
  return 0;
}

static int parse_range(const char *CMD, const char *s, double *lo, double *hi) {
  const char *c = s ? strchr(s, ':') : NULL;
  char a[64];
  if (c && (size_t)(c - s) < sizeof a) {
    memcpy(a, s, (size_t)(c - s)), a[c - s] = '\0';
    if (!whirl_run_number(a, lo) && !whirl_run_number(c + 1, hi) && *lo >= 0 && *hi > *lo)
      return 0;
  }
  cli_error(CMD, "--range wants A:B with 0 <= A < B (got '%s')", s ? s : "");
  return -1;
}

int cmd_rotor_loci(int argc, char **argv) {
  const char *CMD = "rotor loci";
  loci_args a = {.unit = "rpm", .dir = "rotor-loci", .param = NULL, .range = "0:10",
                 .range2 = "0.2:5"};
  const cli_opt opts[] = {
      {"--param", CLI_STRING, &a.param, "P", "second parameter: unbalance, clearance or viscosity",
       "required"},
      {"--range", CLI_STRING, &a.range, "A:B", "range of the second parameter (a scale)", NULL},
      {"--harmonics", CLI_SIZE, &a.harmonics, "H", "harmonics of the balance", "5"},
      {"--seed", CLI_STRING, &a.seed, "W:E", "also the folds of the branch seeded as in "
       "whirl rotor response", ""},
      {"--merge-along", CLI_STRING, &a.along, "Q",
       "also the merge curves through the loci's merge points MG, followed in Q "
       "(unbalance, clearance or viscosity): where isolas exist in the (Q, P) plane",
       ""},
      {"--range2", CLI_STRING, &a.range2, "A:B", "range of Q", NULL},
      {"--unit", CLI_STRING, &a.unit, "U", "unit of --seed's speed: rpm, rad/s or hz", NULL},
      {"-o", CLI_STRING, &a.dir, "DIR", "output directory (also --out)", NULL},
      CLI_OPTS_OUT(a.dir, a.noplot, a.quiet)};
  int rc = rotor_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &loci_doc, &a.file);
  if (rc) return rc == 1 ? 0 : 2;
  int param = 0;
  for (int k = 1; k < WHIRL_FE_NPAR; k++)
    if (a.param && !strcmp(a.param, param_names[k])) param = k;
  double lo, hi;
  const double f = rotor_unit_factor(CMD, a.unit);
  if (!param) {
    cli_error(CMD, "--param must be unbalance, clearance or viscosity (got '%s')",
              a.param ? a.param : "nothing");
    return 2;
  }
  if (f < 0 || parse_range(CMD, a.range, &lo, &hi)) return 2;
  int along = 0;
  double lo2 = 0, hi2 = 0;
  for (int k = 1; a.along && k < WHIRL_FE_NPAR; k++)
    if (!strcmp(a.along, param_names[k])) along = k;
  if (a.along && (!along || along == param)) {
    cli_error(CMD, "--merge-along must be unbalance, clearance or viscosity, not --param "
              "(got '%s')", a.along);
    return 2;
  }
  if (along && parse_range(CMD, a.range2, &lo2, &hi2)) return 2;
  whirl_fe_rotor *r = rotor_load(a.file);
  if (!r) return 2;
  locus_out out = {.wref = r->omega_ref};
  cli_outdir od;
  out_file t, g;
  rc = r->nnl ? cli_outdir_check(CMD, NULL, a.dir) : 2;
  if (!r->nnl) cli_error(CMD, "%s has no nonlinear element: no folds", a.file);
  if (!rc) rc = cli_outdir_begin(&od, CMD, NULL, a.dir);
  if (!rc) {
    int bad = out_open(&t, &od, "loci.tsv");
    if (!bad) {
      out.all = t.fp;
      rc = compute(CMD, &a, r, param, lo, hi, f, t.fp, &out);
      if (rc) out_abort(&t);
      bad = rc ? rc : out_commit(&t);
    }
    out_file m;
    if (!bad && along && !(bad = out_open(&m, &od, "merge.tsv"))) {
      out.all = m.fp;
      rc = merge_curves(CMD, &a, r, param, along, lo2, hi2, m.fp, &out);
      if (rc) out_abort(&m);
      bad = rc ? rc : out_commit(&m);
    }
    if (!bad && !a.noplot && !(bad = out_open(&g, &od, "loci.gp")))
      write_gp(g.fp, r, a.file, param_names[param]), bad = out_commit(&g);
    static const char *const pics[] = {"loci", NULL};
    const int rc2 = cli_outdir_finish(&od, bad, a.noplot ? NULL : pics);
    rc = rc ? rc : rc2;
  }
  if (!rc) {
    printf("type\tlocus\tspeed_rad_s\tspeed_rpm\tOmega_nd\t%s\n", param_names[param]);
    if (out.special) fputs(out.special, stdout);
  }
  free(out.special);
  free(out.mg.X);
  whirl_fe_rotor_free(r);
  return rc;
}

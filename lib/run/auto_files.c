/* lib/run/auto_files.c — AUTO-07p's b., s. and d. files from a whirl run's
 * output (whirl/auto_files.h).  The layout is AUTO-07p 0.9.2's as its own
 * output shows it (fort.7, fort.8, fort.9 of the demos; the AUTO-07p
 * manual, ch. "Output files") and as its Python reader parseB/parseS takes
 * it: fixed-width integers, ES19.10E3 reals, column names at 19 characters.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* strtok_r, getline */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/auto_files.h>
#include <whirl/solution.h>
#include "util/fmt_num.h"

/* ---- numbers as Fortran writes them ------------------------------------ */

/* x as ES(w).(d)E3: d.ddd...E+eee, right-justified in w. */
static const char *es(double x, int w, int d, char *buf, size_t len) {
  char m[64], t[40];
  if (x == 0) x = 0; /* no -0 */
  /* "%.*E" as fmt_e writes "%.*e" (util/fmt_num.h: the same digits, a
   * fifth of printf's time): the letter is read either way */
  const int n = fmt_e(m, sizeof m, x, d);
  const char *e = strpbrk(m, "eE");
  size_t tl = 0;
  if (e) { /* the mantissa (at most 24 characters), E, the sign, 3 digits */
    size_t ml = (size_t)(e - m);
    if (ml > 24) ml = 24;
    int ex = atoi(e + 1);
    memcpy(t, m, ml);
    tl = ml;
    t[tl++] = 'E';
    t[tl++] = ex < 0 ? '-' : '+';
    ex = (ex < 0 ? -ex : ex) % 1000;
    t[tl++] = (char)('0' + ex / 100);
    t[tl++] = (char)('0' + ex / 10 % 10);
    t[tl++] = (char)('0' + ex % 10);
  } else { /* inf, nan: in capitals, as %E */
    tl = n > 0 ? (size_t)n : 0;
    if (tl > 32) tl = 32;
    for (size_t i = 0; i < tl; i++) t[i] = (char)toupper((unsigned char)m[i]);
  }
  const size_t pad = w > 0 && (size_t)w > tl ? (size_t)w - tl : 0;
  if (pad + tl + 1 > len) { /* cannot happen with the callers' buffers */
    buf[0] = '\0';
    return buf;
  }
  memset(buf, ' ', pad);
  memcpy(buf + pad, t, tl);
  buf[pad + tl] = '\0';
  return buf;
}

static void put_reals(FILE *f, const double *v, size_t n) {
  char b[40];
  for (size_t i = 0; i < n; i++) {
    if (i % 7 == 0) fputs(i ? "\n    " : "    ", f);
    fputs(es(v[i], 19, 10, b, sizeof b), f);
  }
  fputc('\n', f);
}

/* ---- the run: its constants and its table ------------------------------ */

typedef struct row {
  int br, pt, lab, stab;
  int alab; /* AUTO's label (0: none): label_offset + its rank */
  char ty[3];
  double *v; /* npar, [period], l2, state */
} row;

typedef struct table {
  row *r;
  size_t n;
  size_t nv; /* values a row */
} table;

typedef struct run {
  const whirl_auto_output *o;
  int ips, isw, orbit; /* orbit: IPS 2, a period */
  int mesh;             /* IPS 2 or 4: solutions on a mesh (MAX U(i), AUTO's
                           type codes of orbits and boundary-value problems) */
  int icp[16]; /* 1-based; 11 of orbits: the period */
  size_t nicp;
  table t;
  char mname[64]; /* AUTO's name of the L2-NORM column (IPLT) */
} run;

static int named(const whirl_auto_constants *ac, const char *name) {
  whirl_auto_item it;
  for (size_t i = 0; i < whirl_auto_constants_count(ac, "parnames"); i++)
    if (whirl_auto_constants_item(ac, "parnames", i, &it) == WHIRL_OK && !strcmp(it.text, name))
      return it.index;
  return !strcmp(name, "PERIOD") || !strcmp(name, "Period") ? 11 : 0;
}

/* AUTO's name of the second column (io.f90, HEADNG) under IPLT: L2-NORM,
 * or U(i), MAX U(i), MIN U(i), INTEGRAL U(i), L2-NORM U(i) with the state's
 * names (unames). */
static void measure_name(run *R) {
  int ip = 0;
  const long n = R->o->ndim;
  whirl_auto_constants_int(R->o->ac, "IPLT", &ip);
  snprintf(R->mname, sizeof R->mname, "L2-NORM");
  if (ip == 0 || ip < -n || ip > 3 * n) return;
  const long i = (ip < 0 ? -ip : ip > 2 * n ? ip - 2 * n : ip > n ? ip - n : ip) - 1;
  char x[40];
  if (R->o->x_names) snprintf(x, sizeof x, "%.39s", R->o->x_names[i]);
  else snprintf(x, sizeof x, "U(%ld)", i + 1);
  const char *pre = ip > 2 * n ? "L2-NORM " : ip > n ? "INTEGRAL " : !R->mesh ? "" : ip > 0 ? "MAX " : "MIN ";
  snprintf(R->mname, sizeof R->mname, "%s%s", pre, x);
}

static void read_icp(run *R) {
  const whirl_auto_constants *ac = R->o->ac;
  R->ips = 1, R->isw = 1;
  whirl_auto_constants_int(ac, "IPS", &R->ips);
  whirl_auto_constants_int(ac, "ISW", &R->isw);
  R->orbit = R->ips == 2;
  R->mesh = R->ips == 2 || R->ips == 4;
  for (size_t i = 0; i < whirl_auto_constants_count(ac, "ICP") && R->nicp < 16; i++) {
    whirl_auto_item it;
    whirl_auto_constants_item(ac, "ICP", i, &it);
    int k = it.name ? named(ac, it.name) : it.index;
    if (k > 0) R->icp[R->nicp++] = k;
  }
  if (!R->nicp) R->icp[R->nicp++] = 1;
  measure_name(R);
}

static void table_free(table *t) {
  for (size_t i = 0; i < t->n; i++) free(t->r[i].v);
  free(t->r);
}

/* One row of branches.tsv. 0, or -1 (malformed). */
static int parse_row(char *line, size_t nv, row *r) {
  char *save = NULL, *w[4];
  for (int i = 0; i < 4; i++)
    if (!(w[i] = strtok_r(i ? NULL : line, "\t\n", &save))) return -1;
  r->br = atoi(w[0]), r->pt = atoi(w[1]), r->lab = atoi(w[3]);
  /* branches.tsv writes a regular point as '-' (doc/tables.md): AUTO's RG */
  snprintf(r->ty, sizeof r->ty, "%s", strcmp(w[2], "-") ? w[2] : "RG");
  if (!(r->v = malloc((nv ? nv : 1) * sizeof *r->v))) return -1;
  for (size_t i = 0; i < nv; i++) {
    char *s = strtok_r(NULL, "\t\n", &save), *end;
    if (!s) return -1;
    r->v[i] = strtod(s, &end);
  }
  char *s = strtok_r(NULL, "\t\n", &save);
  if (!s) return -1;
  r->stab = atoi(s);
  return 0;
}

static int read_table(run *R, char *msg, size_t len) {
  char path[4200], line[65536];
  snprintf(path, sizeof path, "%s/branches.tsv", R->o->rundir);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, len, "%s: cannot open", path);
    return WHIRL_EIO;
  }
  R->t.nv = R->o->npar + (size_t)R->orbit + 1 + (size_t)R->o->ndim;
  int rc = WHIRL_OK, lineno = 0;
  while (rc == WHIRL_OK && fgets(line, sizeof line, f)) {
    lineno++;
    /* the header (the first line), comments, blank lines */
    if (line[0] == '#' || line[0] == '\n' || (lineno == 1 && !strncmp(line, "branch\t", 7)))
      continue;
    row *r = realloc(R->t.r, (R->t.n + 1) * sizeof *r);
    if (!r) rc = WHIRL_ENOMEM;
    else {
      R->t.r = r;
      memset(&r[R->t.n], 0, sizeof *r);
      if (parse_row(line, R->t.nv, &r[R->t.n++])) {
        snprintf(msg, len, "%s:%d: not a row of %zu values", path, lineno, R->t.nv + 5);
        rc = WHIRL_EINVAL;
      }
    }
  }
  fclose(f);
  return rc;
}

/* AUTO's labels: the labelled rows numbered on from label_offset.  A run
 * restarted from a label does not label its first point (AUTO-07p's
 * CNRLAE/CNRLBV give it type 0 when IRS is not 0), so whirl's EP there
 * loses its label and type, unless NPR = 1: AUTO labels every NPR-th
 * point it counts, the first one included (type 4; r3b's L1 family from
 * a libration point labels PT 1, and its c.r3b.H1's IRS = 5 is the BP at
 * PT 5).  The number of labels. */
static int number_labels(run *R) {
  int k = 0, npr = 0;
  if (R->o->ac) whirl_auto_constants_int(R->o->ac, "NPR", &npr);
  for (size_t i = 0; i < R->t.n; i++) {
    row *r = &R->t.r[i];
    if (R->o->restarted && i == 0 && r->lab > 0 && !strcmp(r->ty, "EP")) {
      if (npr != 1) r->lab = 0;
      snprintf(r->ty, sizeof r->ty, "RG");
    }
    r->alab = r->lab > 0 ? R->o->label_offset + ++k : 0;
  }
  return k;
}

/* AUTO's branch number of a row: whirl's, or o->br on from the run's first. */
static int branch_of(const run *R, const row *r) {
  return R->o->br > 0 ? R->o->br + r->br - 1 : r->br;
}

/* ---- b. ---------------------------------------------------------------- */

/* AUTO's type code of whirl's TY (parseB.type_translation's table). */
static int type_base(const char *ty, int lab, int orbit) {
  static const struct {
    const char *ty;
    int eq, po;
  } map[] = {{"BP", 1, 6}, {"LP", 2, 5}, {"HB", 3, 3}, {"UZ", -4, -4}, {"PD", 7, 7},
             {"TR", 8, 8}, {"EP", 9, 9}, {"MX", -9, -9}, {"BT", -1, -1}, {"CP", -2, -2},
             {"ZH", -3, -3}, {"GH", -32, -32}, {"R1", -5, -5}, {"R2", -6, -6},
             {"R3", -7, -7}, {"R4", -8, -8}};
  for (size_t i = 0; i < sizeof map / sizeof *map; i++)
    if (!strcmp(map[i].ty, ty)) return orbit ? map[i].po : map[i].eq;
  return lab > 0 ? 4 : 0; /* RG; a labelled one every NPR steps */
}

/* The code as AUTO writes it on a locus started from a point of type
 * itpst (o->itpst): 10 itpst + the type, with the type's sign (AUTO-07p
 * ae.f90 and bvp.f90: ITP + SIGN(10, ITP) ITPST at a special point,
 * 4 + 10 ITPST every NPR steps, +-9 + 10 ITPST at the ends); a row
 * without a label keeps 0.  GH, AUTO's CP code -2 on a Hopf locus, is -32
 * (whirl labels it on Hopf loci alone). */
static int type_code(const char *ty, int lab, int orbit, int itpst) {
  const int t = type_base(ty, lab, orbit);
  if (itpst <= 0 || itpst > 9 || t == 0 || t == -32) return t;
  return t > 0 ? t + 10 * itpst : t - 10 * itpst;
}

/* The b-file's columns: PAR(ICP(1)), L2-NORM, U(i) (MAX U(i) of orbits),
 * then the other ICP (PERIOD for PAR(11) of orbits): index into a row's
 * values, and the name. */
typedef struct cols {
  size_t at[64];
  char name[64][32];
  size_t n;
} cols;

static size_t par_at(const run *R, int k) {
  if (R->orbit && k == 11) return R->o->npar;  /* PERIOD */
  return k >= 1 && (size_t)k <= R->o->npar ? (size_t)k - 1 : (size_t)-1;
}

static void add_col(cols *c, size_t at, const char *name) {
  if (at == (size_t)-1 || c->n == 64) return;
  c->at[c->n] = at;
  snprintf(c->name[c->n++], sizeof c->name[0], "%.31s", name);
}

static void par_name(const run *R, int k, char *buf, size_t len) {
  if (R->orbit && k == 11) snprintf(buf, len, "PERIOD");
  else if (R->o->p_names && k >= 1 && (size_t)k <= R->o->npar)
    snprintf(buf, len, "%s", R->o->p_names[k - 1]);
  else snprintf(buf, len, "PAR(%d)", k);
}

static void columns(const run *R, cols *c) {
  /* AUTO's b-file names IPLT's measure: "L2-NORM U(1)", "MAX U(2)", ... */
  char nm[80];
  const size_t l2 = R->o->npar + (size_t)R->orbit;
  c->n = 0;
  par_name(R, R->icp[0], nm, sizeof nm);
  add_col(c, par_at(R, R->icp[0]), nm);
  add_col(c, l2, R->mname);
  /* AUTO-07p io.f90, WRLINE: with NICP parameters, U(1..N2) with
   * N2 = NDIM, 7 - NICP where both exceed 7 columns, 0 past 7 parameters */
  const int nicp = (int)R->nicp, n2 = nicp > 7 ? 0 : nicp + R->o->ndim > 7 ? 7 - nicp
                                                                       : R->o->ndim;
  for (int i = 0; i < n2; i++) {
    char x[64];
    if (R->o->x_names) snprintf(x, sizeof x, "%s", R->o->x_names[i]);
    else snprintf(x, sizeof x, "U(%d)", i + 1);
    snprintf(nm, sizeof nm, "%s%s", R->mesh ? "MAX " : "", x);
    add_col(c, l2 + 1 + (size_t)i, nm);
  }
  for (size_t j = 1; j < R->nicp; j++) {
    par_name(R, R->icp[j], nm, sizeof nm);
    add_col(c, par_at(R, R->icp[j]), nm);
  }
}

static void header_ints(FILE *f, const whirl_auto_constants *ac, const char *const *keys,
                        int n) {
  int any = 0, v;
  for (int i = 0; i < n; i++)
    if (whirl_auto_constants_int(ac, keys[i], &v) == WHIRL_OK) {
      if (!any) fputs("   0", f);
      fprintf(f, "   %-4s=%4d", keys[i], v);
      any = 1;
    }
  if (any) fputc('\n', f);
}

static void header_reals(FILE *f, const whirl_auto_constants *ac, const char *const *keys,
                         int n) {
  int any = 0;
  double x;
  char b[40];
  for (int i = 0; i < n; i++)
    if (whirl_auto_constants_real(ac, keys[i], &x) == WHIRL_OK) {
      if (!any) fputs("   0", f);
      fprintf(f, "   %-5s=%s", keys[i], es(x, 11, 4, b, sizeof b));
      any = 1;
    }
  if (any) fputc('\n', f);
}

/* The header of a branch: AUTO's lines starting "   0". */
static void b_header(FILE *f, const run *R, const cols *c) {
  const whirl_auto_constants *ac = R->o->ac;
  static const char *const k1[] = {"NDIM", "IPS", "IRS", "ILP"},
                           *const k2[] = {"NTST", "NCOL", "IAD", "ISP"},
                           *const k3[] = {"ISW", "IPLT", "NBC", "NINT"},
                           *const k4[] = {"NMX", "NPR", "MXBF", "IID", "IADS"},
                           *const k5[] = {"ITMX", "ITNW", "NWTN", "JAC", "NPAR"},
                           *const r1[] = {"EPSL", "EPSU", "EPSS"}, *const r2[] = {"DS", "DSMIN", "DSMAX"};
  double lim[4] = {-HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL};
  static const char *const lk[] = {"RL0", "RL1", "A0", "A1"};
  char b[40];
  fputs("   0", f);
  for (int i = 0; i < 4; i++) {
    whirl_auto_constants_real(ac, lk[i], &lim[i]);
    fprintf(f, " %s", es(isinf(lim[i]) ? copysign(1.7976e308, lim[i]) : lim[i], 12, 4, b, sizeof b));
  }
  fputc('\n', f);
  header_reals(f, ac, r1, 3);
  header_reals(f, ac, r2, 3);
  header_ints(f, ac, k1, 4);
  header_ints(f, ac, k2, 4);
  header_ints(f, ac, k3, 4);
  header_ints(f, ac, k4, 5);
  header_ints(f, ac, k5, 5);
  const char *e = whirl_auto_constants_text(ac, "e");
  if (e) fprintf(f, "   0   e = '%s'\n", e);
  fputs("   0   User-specified parameter", f);
  fputs(R->nicp > 1 ? "s:" : ": ", f);
  for (size_t j = 0; j < R->nicp; j++) fprintf(f, " %4d", R->icp[j]);
  fputs("\n   0   Active continuation parameter", f);
  fputs(R->nicp > 1 ? "s:" : ": ", f);
  for (size_t j = 0; j < R->nicp; j++) fprintf(f, " %4d", R->icp[j]);
  fputc('\n', f);
  if (R->o->itpst > 0 && R->o->itpst <= 9) { /* a locus: AUTO's line (io.f90) */
    static const char *const lb[] = {"", "BP", "LP", "HB", "RG", "LP", "BP", "PD", "TR", "EP"};
    fprintf(f, "   0   Branch type: %2d    TY = '%-3s'\n", R->o->itpst, lb[R->o->itpst]);
  }
  fputs("   0\n   0    PT  TY  LAB", f);
  for (size_t j = 0; j < c->n; j++) fprintf(f, "    %-15.15s", c->name[j]);
  fputc('\n', f);
}

static void b_row(FILE *f, const run *R, const cols *c, const row *r) {
  char b[40];
  const int br = R->orbit ? -branch_of(R, r) : branch_of(R, r),
            pt = r->stab == 1 ? -(r->pt + 1) : r->pt + 1;
  fprintf(f, "%4d%6d%4d%5d", br, pt, type_code(r->ty, r->lab, R->mesh, R->o->itpst), r->alab);
  for (size_t j = 0; j < c->n; j++) fputs(es(r->v[c->at[j]], 19, 10, b, sizeof b), f);
  fputc('\n', f);
}

static void write_b(FILE *f, const run *R) {
  cols c;
  columns(R, &c);
  for (size_t i = 0; i < R->t.n; i++) {
    if (i == 0 || R->t.r[i].br != R->t.r[i - 1].br) b_header(f, R, &c);
    b_row(f, R, &c, &R->t.r[i]);
  }
}

/* ---- d. ---------------------------------------------------------------- */

static void write_d(FILE *f, const run *R) {
  cols c;
  char b[40];
  columns(R, &c);
  for (size_t i = 0; i < R->t.n; i++) {
    const row *r = &R->t.r[i];
    if (r->lab <= 0) continue;
    fputs("\n  BR    PT  TY  LAB", f);
    for (size_t j = 0; j < c.n; j++) fprintf(f, " %13.13s", c.name[j]);
    fprintf(f, "\n%4d%6d  %-2s%5d", branch_of(R, r), r->stab == 1 ? -(r->pt + 1) : r->pt + 1,
            strcmp(r->ty, "RG") ? r->ty : "  ", r->alab);
    for (size_t j = 0; j < c.n; j++) fputs(es(r->v[c.at[j]], 14, 5, b, sizeof b), f);
    fputs("\n===============================================\n", f);
  }
}

/* ---- s. ---------------------------------------------------------------- */

static size_t lines_of(size_t n, size_t per) { return n ? (n + per - 1) / per : 0; }

/* One labelled solution S of table row R as an s-file block. */
static int write_s_block(FILE *f, const run *R, const whirl_solution *S, const row *r) {
  const size_t n = (size_t)R->o->ndim, nparw = R->o->npar > 11 ? R->o->npar : 11;
  const int orbit = S->kind == WHIRL_SOL_COLLOC, bvp = S->kind == WHIRL_SOL_BVP;
  const int mesh = orbit || bvp;
  const size_t ntpl = mesh ? (size_t)S->ntst * (size_t)S->ncol + 1 : 1;
  int fp[3 + WHIRL_SOL_MAXFREE];
  size_t nfpr = 0;
  fp[nfpr++] = S->icp + 1;
  if (S->icp2 >= 0) fp[nfpr++] = S->icp2 + 1;
  if (orbit) fp[nfpr++] = 11;
  for (int j = 0; bvp && j < S->nfree && j < WHIRL_SOL_MAXFREE; j++) fp[nfpr++] = S->free_par[j] + 1;
  double *par = calloc(nparw, sizeof *par), *v = malloc((n + 1) * sizeof *v);
  if (!par || !v) {
    free(par), free(v);
    return WHIRL_ENOMEM;
  }
  memcpy(par, S->par, S->npar * sizeof *par);
  if (orbit) par[10] = S->x[S->nx - 1];
  const size_t nrow = ntpl * lines_of(n + 1, 7) + lines_of(nfpr, 20) + lines_of(nfpr, 7) +
                      ntpl * lines_of(n, 7) + lines_of(nparw, 7);
  fprintf(f, "%6d%6d%6d%6d%6zu%6d%8zu%6zu%8zu%5d%5d%5zu%5d%5zu%5d%5d\n", branch_of(R, r),
          r->pt + 1, type_code(r->ty, r->lab, mesh, R->o->itpst), r->alab, nfpr, R->isw, ntpl,
          n + 1, nrow,
          mesh ? S->ntst : 1, mesh ? S->ncol : 0, nparw, 0, n, R->ips, 0);
  for (size_t j = 0; j < ntpl; j++) { /* t and the state at node j */
    const size_t iv = mesh ? j / (size_t)S->ncol : 0, k = mesh ? j % (size_t)S->ncol : 0;
    v[0] = 0;
    if (mesh)
      v[0] = iv < (size_t)S->ntst
                 ? S->mesh[iv] + (S->mesh[iv + 1] - S->mesh[iv]) * (double)k / S->ncol
                 : S->mesh[S->ntst];
    memcpy(v + 1, S->x + n * j, n * sizeof *v);
    put_reals(f, v, n + 1);
  }
  for (size_t j = 0; j < nfpr; j++) fprintf(f, "%5d", fp[j]);
  fputc('\n', f);
  double rl[3 + WHIRL_SOL_MAXFREE] = {0}; /* the tangent's parameter part, in fp's order */
  if (S->tan) {
    rl[0] = S->tan[S->nx];
    if (orbit) rl[nfpr - 1] = S->tan[S->nx - 1];
    for (int j = 0; bvp && j < S->nfree && j < WHIRL_SOL_MAXFREE; j++)
      rl[1 + j] = S->tan[S->nx - (size_t)S->nfree + (size_t)j];
  }
  put_reals(f, rl, nfpr);
  for (size_t j = 0; j < ntpl; j++) {
    for (size_t i = 0; i < n; i++) v[i] = S->tan ? S->tan[n * j + i] : 0;
    put_reals(f, v, n);
  }
  put_reals(f, par, nparw);
  free(par), free(v);
  return ferror(f) ? WHIRL_EIO : WHIRL_OK;
}

/* The s-file in one pass over the solutions file (whirl_solution_each):
 * its labels are those of the table's labelled rows in the same order (a
 * run writes both as it goes; a block of no row, of a smaller label than
 * the next row's, is skipped), checked first on the LAB lines alone
 * (s_order); otherwise each label is looked up on its own
 * (write_s_by_label), a pass over the file each. */
typedef struct s_pass {
  const run *R;
  FILE *f;
  size_t next; /* the table row to match */
  int rc;
} s_pass;

static int s_pass_block(const whirl_solution *S, void *data) {
  s_pass *P = data;
  const run *R = P->R;
  while (P->next < R->t.n && R->t.r[P->next].lab <= 0) P->next++;
  /* a block before the next labelled row's has no row (the start of a
   * restart, whose label AUTO does not repeat): skipped */
  if (P->next < R->t.n && S->label < R->t.r[P->next].lab) return 0;
  if (P->next >= R->t.n || R->t.r[P->next].lab != S->label) return 1; /* another order */
  const row *r = &R->t.r[P->next++];
  if (S->kind != WHIRL_SOL_HBM && (P->rc = write_s_block(P->f, R, S, r))) return 2;
  return 0;
}

/* The labels of the LAB lines of path, in order, against the table's
 * labelled rows (blocks of smaller labels than the next row's skipped):
 * 0 the same order, 1 not, -1 with the message when path cannot be read.
 * Only the LAB lines are looked at; the write pass checks the blocks. */
static int s_order(const run *R, const char *path, char *msg, size_t len) {
  FILE *in = fopen(path, "r");
  if (!in) {
    snprintf(msg, len, "%s: cannot open", path);
    return -1;
  }
  char *line = NULL;
  size_t cap = 0, next = 0;
  int rc = 0;
  while (!rc && getline(&line, &cap, in) >= 0) {
    if (strncmp(line, "LAB ", 4)) continue;
    const long lab = strtol(line + 4, NULL, 10);
    while (next < R->t.n && R->t.r[next].lab <= 0) next++;
    if (next < R->t.n && lab < R->t.r[next].lab) continue;
    if (next >= R->t.n || R->t.r[next].lab != lab) rc = 1;
    else next++;
  }
  while (!rc && next < R->t.n && R->t.r[next].lab <= 0) next++;
  if (!rc && next < R->t.n) rc = 1;
  free(line);
  fclose(in);
  return rc;
}

static int write_s_by_label(FILE *f, const run *R, const char *path, char *msg, size_t len) {
  for (size_t i = 0; i < R->t.n; i++) {
    const row *r = &R->t.r[i];
    if (r->lab <= 0) continue;
    FILE *in = fopen(path, "r");
    if (!in) {
      snprintf(msg, len, "%s: cannot open", path);
      return WHIRL_EIO;
    }
    whirl_solution S;
    const whirl_solution_shape any = {NULL, 0, 0, -1, 0};
    int rc = whirl_solution_read(in, path, &any, r->lab, NULL, &S, msg, len);
    fclose(in);
    if (rc) return WHIRL_EINVAL;
    rc = S.kind == WHIRL_SOL_HBM ? WHIRL_OK : write_s_block(f, R, &S, r);
    whirl_solution_free(&S);
    if (rc) return rc;
  }
  return WHIRL_OK;
}

static int write_s(FILE *f, const run *R, char *msg, size_t len) {
  char path[4200];
  snprintf(path, sizeof path, "%s/solutions", R->o->rundir);
  int rc = s_order(R, path, msg, len);
  if (rc < 0) return WHIRL_EIO;
  if (rc > 0) return write_s_by_label(f, R, path, msg, len);
  FILE *in = fopen(path, "r");
  if (!in) {
    snprintf(msg, len, "%s: cannot open", path);
    return WHIRL_EIO;
  }
  s_pass P = {R, f, 0, WHIRL_OK};
  rc = whirl_solution_each(in, path, s_pass_block, &P, msg, len);
  fclose(in);
  if (rc < 0) return WHIRL_EINVAL;
  if (rc == 1) { /* cannot happen after s_order */
    snprintf(msg, len, "%s: the labels are not those of the table", path);
    return WHIRL_EINVAL;
  }
  return rc == 2 ? P.rc : WHIRL_OK;
}

int whirl_auto_write_files(const whirl_auto_output *o, FILE *b, FILE *s, FILE *d,
                           int *nlabels, char *msg, size_t len) {
  if (!o || !o->rundir || !o->ac || o->ndim < 1) return WHIRL_EINVAL;
  run R;
  memset(&R, 0, sizeof R);
  R.o = o;
  read_icp(&R);
  int rc = read_table(&R, msg, len);
  const int nlab = rc ? 0 : number_labels(&R);
  if (!rc && b) write_b(b, &R);
  if (!rc && s) rc = write_s(s, &R, msg, len);
  if (!rc && d) write_d(d, &R);
  if (!rc && nlabels) *nlabels = nlab;
  if (!rc && ((b && ferror(b)) || (s && ferror(s)) || (d && ferror(d)))) {
    snprintf(msg, len, "write error");
    rc = WHIRL_EIO;
  }
  table_free(&R.t);
  return rc;
}

int whirl_auto_labels(const whirl_auto_output *o, whirl_auto_label *lab, size_t max,
                      size_t *n, char *msg, size_t len) {
  if (!o || !o->rundir || !o->ac || o->ndim < 1 || !n) return WHIRL_EINVAL;
  run R;
  memset(&R, 0, sizeof R);
  R.o = o;
  read_icp(&R);
  int rc = read_table(&R, msg, len);
  *n = 0;
  if (!rc) number_labels(&R);
  for (size_t i = 0; !rc && i < R.t.n; i++) {
    const row *r = &R.t.r[i];
    if (!r->alab) continue;
    if (*n < max) {
      lab[*n].label = r->alab, lab[*n].whirl = r->lab, lab[*n].br = branch_of(&R, r);
      lab[*n].type = type_code(r->ty, r->lab, R.mesh, o->itpst);
      snprintf(lab[*n].ty, sizeof lab[*n].ty, "%s", r->ty);
    }
    ++*n;
  }
  table_free(&R.t);
  return rc;
}

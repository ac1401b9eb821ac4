/* drivers/cmd_auto.c — `whirl auto DIR [NAME]`: an AUTO-07p demo (or any
 * AUTO problem directory) run from its own files, unchanged: the constants
 * files c.NAME.1, c.NAME.2, ... (whirl/auto_constants.h) each translated
 * into a whirl run file, the equations NAME.f90 compiled into a plug-in
 * (auto_model.c), and the runs executed in order by `whirl run`, each into
 * its own output directory, so that no run replaces the output another
 * restarts from.  doc/auto-files.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _XOPEN_SOURCE 700 /* realpath */
#include "config.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <whirl/whirl.h>

#include "auto_model.h"
#include "cli.h"

#define MAXRUNS 64
#define MAXALL 512 /* with the branches MXBF switches to */
#define MARKER ".whirl-auto"

typedef struct auto_run {
  char c[256];    /* the constants file's suffix: ab.1 (c.ab.1) */
  char label[64]; /* "@LABEL": the restart label, or "" */
  char from[320]; /* "@ID:LABEL": the run to restart from, or "" */
  char id[256 + 64 + 24]; /* the run's name in OUT: ab.1, ab.2@3 (c, label, a count) */
  whirl_auto_constants *ac;
  char *text;     /* the whirl run file */
  char irs[64];   /* the whirl label IRS resolves to ("": r->label or IRS) */
  long src;       /* the run it restarts from (-1: none) */
  int fresh;      /* IRS = 0 and no @LABEL: AUTO numbers labels from 1 */
  /* AUTO's numbering of the run's labels (after it ran) */
  whirl_auto_label *labs;
  size_t nlabs;
  int offset;     /* labels before its first: the largest of its group */
  int sub;        /* a branch MXBF switches to (no IRS of its own) */
  int no_switch;  /* ISW < 0 at a label that is no BP or PD: AUTO goes on
                   * along the branch (its run file says ISW = 1) */
  int br_fixed;   /* its AUTO branch number (0: NEWLAB's) */
  int br_auto;    /* the AUTO branch number its first branch got */
  int ndim;       /* its NDIM (a plug-in of its own when not the first run's) */
  char **x_names; /* its ndim state names */
} auto_run;

typedef struct auto_job {
  const char *dir, *name, *out;
  int quiet, plot; /* --quiet; --plot: each run's diagram */
  const char *script; /* --script[=FILE]: AUTO's script of runs ("" = NAME.auto) */
  auto_run run[MAXALL];
  size_t nrun;
  size_t npar;
  int ndim;
  char **p_names, **x_names;
  char absdir[4096]; /* DIR as an absolute path ("" if unknown) */
} auto_job;

static void usage(FILE *f) {
  fprintf(f,
          "usage: whirl auto DIR [NAME] [--runs=C1,C2@LABEL,...|--script[=FILE]] [--out=OUT]\n"
          "                  [--plot] [--quiet]\n"
          "\n"
          "Run an AUTO-07p problem from its own files: the constants files\n"
          "DIR/c.NAME.1, c.NAME.2, ... (or DIR/c.NAME alone) in order, the equations\n"
          "DIR/NAME.f90 compiled (gfortran, or $FC) into a plug-in.  NAME defaults to\n"
          "DIR's last component.  --runs names the constants files (c.C1, ...) to run,\n"
          "in order; C@LABEL restarts from LABEL (a number or HB1) of the run before.\n"
          "A run whose IRS is not 0 restarts from the run before it.\n"
          "Output (default NAME.out): NAME.so, and for each run C its run file\n"
          "C.whirl and output directory C.out (branches.tsv, solutions, run.log).\n"
          "Like AUTO, no pictures unless --plot (then C.out/diagram.png).\n"
          "--script runs AUTO's script of runs instead (DIR/NAME.auto, or FILE) with\n"
          "AUTO's commands (run, load, save, relabel, merge; Python 3): each run into\n"
          "OUT/runs, save(bd, 'x') into OUT/b.x, s.x, d.x, every run's points in\n"
          "OUT/b.runs.\n"
          "doc/auto-files.md.\n");
}

/* "--runs=a,b@3": the runs. 0 or 2. */
static int parse_runs(auto_job *J, const char *list) {
  char buf[4096];
  snprintf(buf, sizeof buf, "%s", list);
  for (char *save = NULL, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
    if (J->nrun == MAXRUNS) {
      cli_error("auto", "--runs: more than %d runs", MAXRUNS);
      return 2;
    }
    auto_run *r = &J->run[J->nrun++];
    char *at = strchr(t, '@'), *colon = at ? strrchr(at, ':') : NULL;
    if (colon) *colon = 0, snprintf(r->label, sizeof r->label, "%s", colon + 1);
    if (at) {
      *at = 0;
      snprintf(colon ? r->from : r->label, colon ? sizeof r->from : sizeof r->label, "%s", at + 1);
    }
    snprintf(r->c, sizeof r->c, "%s", t);
    if (!r->c[0] || (at && !r->label[0]) || (colon && !r->from[0]) || strchr(r->c, '/')) {
      cli_error("auto", "--runs: '%s' is not C, C@LABEL or C@RUN:LABEL (c.C in DIR)", t);
      return 2;
    }
  }
  return 0;
}

static int by_suffix(const void *a, const void *b) {
  const char *x = *(char *const *)a, *y = *(char *const *)b;
  const char *dx = strrchr(x, '.'), *dy = strrchr(y, '.');
  long nx = dx ? strtol(dx + 1, NULL, 10) : 0, ny = dy ? strtol(dy + 1, NULL, 10) : 0;
  return nx != ny ? (nx < ny ? -1 : 1) : strcmp(x, y);
}

/* The default runs: c.NAME.<k> by k, else c.NAME.  0 or 2. */
static int default_runs(auto_job *J) {
  DIR *d = opendir(J->dir);
  if (!d) {
    cli_error("auto", "%s: %s", J->dir, strerror(errno));
    return 2;
  }
  char *names[MAXRUNS];
  size_t n = 0, len = strlen(J->name);
  int plain = 0;
  for (struct dirent *e; (e = readdir(d));) {
    const char *s = e->d_name;
    if (strncmp(s, "c.", 2) || strncmp(s + 2, J->name, len)) continue;
    if (!s[2 + len]) plain = 1;
    else if (s[2 + len] == '.' && isdigit((unsigned char)s[3 + len]) && n < MAXRUNS)
      names[n++] = strdup(s + 2);
  }
  closedir(d);
  if (!n && plain) names[n++] = strdup(J->name);
  if (!n) {
    cli_error("auto", "%s: no constants file c.%s or c.%s.1", J->dir, J->name, J->name);
    return 2;
  }
  qsort(names, n, sizeof *names, by_suffix);
  for (size_t i = 0; i < n; i++) {
    snprintf(J->run[i].c, sizeof J->run[i].c, "%s", names[i] ? names[i] : "");
    free(names[i]);
  }
  J->nrun = n;
  return 0;
}

/* The names (unames, parnames) a constants file without them takes from
 * the nearest earlier one of the demo that has them, as the demos' later
 * c-files assume (c.exp.2 names ICP = ['lambda'] of c.exp.1's parnames;
 * AUTO's scripts carry them from run to run): run i's constants again with
 * those dictionaries after its own text (its lines keep their numbers in
 * messages).  0, 1 (memory) or 2 (said). */
static int inherit_names(auto_job *J, size_t i, const char *path) {
  static const char *const keys[] = {"unames", "parnames"};
  char *names = NULL, *text = NULL;
  size_t nlen = 0, len = 0;
  FILE *m = open_memstream(&names, &nlen);
  int added = 0;
  for (size_t k = 0; m && k < 2; k++) {
    if (whirl_auto_constants_count(J->run[i].ac, keys[k])) continue;
    for (size_t j = i; j-- > 0;) {
      const whirl_auto_constants *e = J->run[j].ac;
      const size_t n = whirl_auto_constants_count(e, keys[k]);
      if (!n) continue;
      fprintf(m, "%s = {", keys[k]);
      for (size_t q = 0; q < n; q++) {
        whirl_auto_item it;
        whirl_auto_constants_item(e, keys[k], q, &it);
        fprintf(m, "%s%d: '%s'", q ? ", " : "", it.index, it.text);
      }
      fputs("}\n", m);
      added = 1;
      break;
    }
  }
  if (!m || fclose(m)) {
    free(names);
    return 1;
  }
  if (!added) {
    free(names);
    return 0;
  }
  /* the file's own lines first, so that messages name their lines; the
   * names after them (the file has none of these keys) */
  FILE *t = open_memstream(&text, &len), *f = fopen(path, "r");
  int last = '\n';
  for (int ch; t && f && (ch = fgetc(f)) != EOF; last = ch) fputc(ch, t);
  if (f) fclose(f);
  if (t && last != '\n') fputc('\n', t);
  if (t) fputs(names, t);
  free(names);
  if (!t || fclose(t)) {
    free(text);
    return 1;
  }
  whirl_auto_constants_free(J->run[i].ac);
  int rc = (J->run[i].ac = whirl_auto_constants_alloc()) ? 0 : 1;
  if (!rc && whirl_auto_constants_parse(J->run[i].ac, path, text, len) != WHIRL_OK) {
    cli_error("auto", "%s", whirl_auto_constants_errmsg(J->run[i].ac));
    rc = 2;
  }
  free(text);
  return rc;
}

/* The parameters stored by the earlier run a run restarts from (@RUN:,
 * RUN of an earlier invocation into OUT: a script's runs), from its
 * solutions' header; 0 when there is none.  AUTO's NPAR is at least the
 * restart's (main.f90: NPAR = MAX(NPARR, NPAR)): tfc's run 5 (NPAR 6)
 * restarts from run 3's label, whose ICP printed PAR(7), PAR(8). */
static size_t stored_npar(const auto_job *J, const auto_run *r) {
  if (!r->from[0] || strchr(r->from, '/')) return 0;
  char path[4400], line[512];
  snprintf(path, sizeof path, "%s/%s.out/solutions", J->out, r->from);
  FILE *f = fopen(path, "r");
  size_t np = 0;
  if (!f) return 0;
  if (!fgets(line, sizeof line, f) ||
      sscanf(line, "# whirl solutions: model %*[^,], npar %zu", &np) != 1 || np > 36)
    np = 0;
  fclose(f);
  return np;
}

/* Read every constants file.  0 or 2 (the message printed). */
static int read_constants(auto_job *J) {
  for (size_t i = 0; i < J->nrun; i++) {
    auto_run *r = &J->run[i];
    char path[4400];
    snprintf(path, sizeof path, "%s/c.%s", J->dir, r->c);
    r->ac = whirl_auto_constants_alloc();
    if (!r->ac) return 1;
    if (whirl_auto_constants_read(r->ac, path) != WHIRL_OK) {
      cli_error("auto", "%s", whirl_auto_constants_errmsg(r->ac));
      return 2;
    }
    int irc = inherit_names(J, i, path);
    if (irc) return irc;
    int n = 0;
    whirl_auto_constants_int(r->ac, "NPAR", &n);
    if (n > 0 && (size_t)n > J->npar) J->npar = (size_t)n;
    /* AUTO's NPAR is at least the largest ICP (main.f90: NPAR =
     * MAX(MAXVAL(ABS(ICU)), NPAR)); PAR(11) of orbits is whirl's PERIOD */
    for (size_t k = 0; k < whirl_auto_constants_count(r->ac, "ICP"); k++) {
      whirl_auto_item it;
      if (whirl_auto_constants_item(r->ac, "ICP", k, &it) || it.name) continue;
      const int a = abs(it.index);
      if (a != 11 && a <= 36 && (size_t)a > J->npar) J->npar = (size_t)a;
    }
    whirl_auto_constants_int(r->ac, "NDIM", &r->ndim);
    if (whirl_auto_constants_line(r->ac, "NDIM") > 0 && r->ndim < 1) {
      /* before any run: a later c-file's bad NDIM writes nothing */
      cli_error("auto", "%s:%d: NDIM = %d: must be >= 1", path,
                whirl_auto_constants_line(r->ac, "NDIM"), r->ndim);
      return 2;
    }
    if (!J->ndim) J->ndim = r->ndim;
  }
  if (J->ndim < 1) {
    cli_error("auto", "%s/c.%s: NDIM missing", J->dir, J->run[0].c);
    return 2;
  }
  for (size_t i = 0; i < J->nrun; i++) {
    if (J->run[i].ndim < 1) J->run[i].ndim = J->ndim;
    const size_t np = stored_npar(J, &J->run[i]);
    if (np > J->npar) J->npar = np;
  }
  if (!J->npar) J->npar = 36; /* AUTO's NPARX */
  return 0;
}

/* Whirl's run-file names: letters, digits, _ . ( ) - + ^ /, not a digit
 * first (whirl_model_check). */
static int name_ok(const char *s) {
  if (!s || !*s || strlen(s) >= 64 || isdigit((unsigned char)*s)) return 0;
  for (; *s; s++)
    if (!isalnum((unsigned char)*s) && !strchr("_.()-+^/", *s)) return 0;
  return 1;
}

/* The names of the model's parameters or state components: AUTO's
 * parnames / unames where given and usable, else PAR(k) / U(k). */
static char **make_names(const auto_job *J, const char *key, const char *stem, size_t n) {
  char **v = calloc(n, sizeof *v);
  for (size_t k = 0; v && k < n; k++) {
    const char *given = NULL;
    for (size_t i = 0; i < J->nrun && !given; i++)
      for (size_t j = 0; j < whirl_auto_constants_count(J->run[i].ac, key); j++) {
        whirl_auto_item it;
        whirl_auto_constants_item(J->run[i].ac, key, j, &it);
        if ((size_t)it.index == k + 1) given = it.text;
      }
    for (size_t m = 0; given && m < k; m++)
      if (!strcmp(v[m], given)) given = NULL;
    char buf[80];
    snprintf(buf, sizeof buf, "%s(%zu)", stem, k + 1);
    v[k] = strdup(name_ok(given) ? given : buf);
  }
  return v;
}

static void free_names(char **v, size_t n) {
  for (size_t i = 0; v && i < n; i++) free(v[i]);
  free(v);
}

/* restart_from's answer for @RUN:LABEL when RUN ran in an earlier
 * invocation of whirl auto into the same OUT (OUT/RUN.out): a script of
 * runs (--script) calls whirl auto once a run. */
#define EXTERNAL (-3L)

/* The run that run i restarts from: @RUN:LABEL's RUN; for @LABEL the
 * nearest earlier run of another constants file; else the run before.
 * -1: none (the first run), -2: RUN unknown (said), EXTERNAL. */
static long restart_from(const auto_job *J, size_t i) {
  const auto_run *r = &J->run[i];
  for (size_t k = i; r->from[0] && k-- > 0;)
    if (!strcmp(J->run[k].id, r->from)) return (long)k;
  if (r->from[0]) { /* a run of an earlier invocation into the same OUT */
    char sol[4400];
    snprintf(sol, sizeof sol, "%s/%s.out/solutions", J->out, r->from);
    if (!strchr(r->from, '/') && access(sol, R_OK) == 0) return EXTERNAL;
    cli_error("auto", "--runs: %s@%s:%s: no earlier run %s (here or in %s)", r->c, r->from,
              r->label, r->from, J->out);
    return -2;
  }
  for (size_t k = i; r->label[0] && k-- > 0;)
    if (strcmp(J->run[k].c, r->c)) return (long)k;
  return (long)i - 1;
}

/* The plug-in file stem of NDIM (not the first run's): NAME.ndimK. */
static void ndim_file(const auto_job *J, int ndim, char *buf, size_t len) {
  snprintf(buf, len, "%s.ndim%d", J->name, ndim);
}

/* Run i's run file, restarting from run FROM (-1: none).  0 or 2. */
static int translate_run(auto_job *J, size_t i, long from) {
  auto_run *r = &J->run[i];
  char model[700], restart[4400], out[4400], file[600];
  ndim_file(J, r->ndim, file, sizeof file);
  snprintf(model, sizeof model, "%s.so", r->ndim == J->ndim ? J->name : file);
  /* beside the run file in J->out, as a run file's paths are (run_path) */
  if (from >= 0 || from == EXTERNAL)
    snprintf(restart, sizeof restart, "%s.out", from >= 0 ? J->run[from].id : r->from);
  snprintf(out, sizeof out, "%s.out", r->id);
  const char *lab = r->irs[0] ? r->irs : r->label[0] ? r->label : NULL;
  /* dat files by an absolute path: the run file is in OUT, DIR relative
   * to the working directory */
  const whirl_auto_runfile_opts o = {model, from >= 0 || from == EXTERNAL ? restart : NULL,
                                     lab, out, J->npar,
                                     J->absdir[0] ? J->absdir : J->dir};
  r->src = from >= 0 ? from : -1;
  free(r->text);
  r->text = NULL;
  if (whirl_auto_constants_runfile(r->ac, &o, &r->text) != WHIRL_OK) {
    cli_error("auto", "%s", whirl_auto_constants_errmsg(r->ac));
    return 2;
  }
  /* ISW < 0 where AUTO goes on along the branch (continues_at): the run
   * file's line (auto_runfile.c writes "ISW    = %d") as ISW = 1, the
   * same length */
  char *isw = r->no_switch ? strstr(r->text, "\nISW    = -") : NULL;
  if (isw) memcpy(isw + 10, " 1", 2);
  return 0;
}

/* Each run's id (unique in OUT) and run file.  0 or 2. */
static int translate(auto_job *J) {
  for (size_t i = 0; i < J->nrun; i++) {
    auto_run *r = &J->run[i];
    /* built in a buffer of its own: c and label are fields of the same run
     * (GCC's -Wrestrict), and c + label + a count fit id */
    char id[sizeof r->c + sizeof r->label + 24];
    snprintf(id, sizeof id, "%s%s%s", r->c, r->label[0] ? "@" : "", r->label);
    for (size_t k = 0, dup = 1; k < i; k++)
      if (!strcmp(J->run[k].id, id))
        snprintf(id, sizeof id, "%s%s%s-%zu", r->c, r->label[0] ? "@" : "", r->label, ++dup);
    _Static_assert(sizeof id == sizeof r->id, "id holds c, label and a count");
    memcpy(r->id, id, sizeof id);
    int irs = 0;
    whirl_auto_constants_int(r->ac, "IRS", &irs);
    r->fresh = !r->label[0] && !r->from[0] && !irs && !whirl_auto_constants_text(r->ac, "IRS");
    const long from = restart_from(J, i);
    if (from == -2 || translate_run(J, i, from)) return 2;
  }
  return 0;
}

/* Can run i (its IPS, ISW) start from solution S? */
static int fits_isw(const auto_run *r, const whirl_solution *S, int isw) {
  int ips = 1;
  whirl_auto_constants_int(r->ac, "IPS", &ips);
  /* a point of a locus restarts that locus (ISW = 2) */
  const char *t = (abs(isw) == 2 || isw == 3) && S->icp2 >= 0 && S->locus[0] ? S->locus : S->ty;
  if (ips == 1)
    return S->kind == WHIRL_SOL_EQ && (isw == 2 ? !strcmp(t, "LP") || !strcmp(t, "HB") ||
                                                      !strcmp(t, "BP")
                                       : isw == 3 ? !strcmp(t, "BP")
                                       : isw == -1 ? !strcmp(t, "BP") : 1);
  if (ips == -1) /* fixed points of a map: its loci; switching at a BP or a PD */
    return S->kind == WHIRL_SOL_EQ && (isw == 2 ? !strcmp(t, "LP") || !strcmp(t, "PD") ||
                                                      !strcmp(t, "TR")
                                       : isw == -1 ? !strcmp(t, "BP") || !strcmp(t, "PD") : 1);
  if (S->kind == WHIRL_SOL_EQ) return !strcmp(t, "HB");
  if (isw == -1) return !strcmp(t, "BP") || !strcmp(t, "PD");
  if (isw == 2) return !strcmp(t, "LP") || !strcmp(t, "PD") || !strcmp(t, "TR") || !strcmp(t, "BP");
  if (isw == 3) return !strcmp(t, "BP");
  return 1;
}

static int fits(const auto_run *r, const whirl_solution *S) {
  int isw = 1;
  whirl_auto_constants_int(r->ac, "ISW", &isw);
  return fits_isw(r, S, isw);
}

/* AUTO's label numbering across runs (AUTO-07p io.f90, FINDLB and NEWLAB):
 * a run restarting from an s-file numbers its labels on from the largest
 * label in that file, a run with IRS = 0 from 1; IRS = k is the first
 * solution labelled k in the file, IRS = 'HB2' its second HB.  The c-files
 * of a demo are AUTO's legacy script (`@r NAME; @sv NAME` for a fresh start,
 * `@r NAME k NAME; @ap NAME` for a restart), so the s-file a run restarts
 * from holds the runs since the last fresh start: its group. */
static size_t group_start(const auto_job *J, size_t i) {
  size_t g = i;
  while (g > 0 && !J->run[g].fresh) g--;
  return g;
}

/* The label of run i's group (runs before i) that AUTO's IRS (TY, K)
 * names: its run in *j and its entry.  NULL: none. */
static const whirl_auto_label *group_label(const auto_job *J, size_t i, const char *ty, int k,
                                           size_t *j) {
  int count = 0;
  for (size_t g = group_start(J, i > 0 ? i - 1 : 0); g < i; g++)
    for (size_t m = 0; m < J->run[g].nlabs; m++) {
      const whirl_auto_label *L = &J->run[g].labs[m];
      if (ty[0] ? !strcmp(L->ty, ty) && ++count == k : L->label == k) {
        *j = g;
        return L;
      }
    }
  return NULL;
}

/* Can run i start from label LAB of run j?  1 or 0. */
static int fits_label(const auto_job *J, size_t i, size_t j, int lab) {
  char dir[4400], msg[512];
  whirl_solution S;
  const whirl_solution_shape any = {NULL, 0, 0, -1, 0};
  snprintf(dir, sizeof dir, "%s/%s.out", J->out, J->run[j].id);
  if (whirl_solution_find(dir, &any, lab, "", &S, msg, sizeof msg)) return 0;
  const int good = fits(&J->run[i], &S);
  whirl_solution_free(&S);
  return good;
}

/* ISW < 0 at label L (run j) that is no BP or PD, nor an HB that starts
 * orbits, and no TY given: AUTO switches at those alone, and elsewhere
 * continues the branch as with ISW = 1 (ae.f90, periodic.f90; numbered
 * as a switch: first_branch).  1 when run i can go on from L so. */
static int continues_at(const auto_job *J, size_t i, size_t j, const whirl_auto_label *L) {
  const auto_run *r = &J->run[i];
  int isw = 1, ips = 1;
  whirl_auto_constants_int(r->ac, "ISW", &isw);
  whirl_auto_constants_int(r->ac, "IPS", &ips);
  if (isw >= 0 || whirl_auto_constants_text(r->ac, "TY") || !strcmp(L->ty, "BP") ||
      !strcmp(L->ty, "PD") || (!strcmp(L->ty, "HB") && ips == 2))
    return 0;
  char dir[4400], msg[512];
  whirl_solution S;
  const whirl_solution_shape any = {NULL, 0, 0, -1, 0};
  snprintf(dir, sizeof dir, "%s/%s.out", J->out, J->run[j].id);
  if (whirl_solution_find(dir, &any, L->whirl, "", &S, msg, sizeof msg)) return 0;
  const int good = fits_isw(r, &S, 1);
  whirl_solution_free(&S);
  return good;
}

/* Run i restarts by the default rule (IRS, no @RUN): the label AUTO's
 * numbering gives IRS in run i's group (above); where that is no label
 * run i can start from (whirl labels a point AUTO does not, or misses
 * one), the nearest earlier run whose own label IRS (or k-th point of type
 * TY) is one run i can start from; else the run before.  Re-translates
 * run i when that changes its source.  0 or 2. */
static int pick_source(auto_job *J, size_t i) {
  auto_run *r = &J->run[i];
  int irs = 0;
  const char *t = whirl_auto_constants_text(r->ac, "IRS");
  char lab[64] = "";
  if (r->from[0] || r->sub || i == 0) return 0;
  if (r->label[0]) snprintf(lab, sizeof lab, "%s", r->label);
  else if (t) snprintf(lab, sizeof lab, "%s", t);
  else if (whirl_auto_constants_int(r->ac, "IRS", &irs) == WHIRL_OK && irs) snprintf(lab, sizeof lab, "%d", irs);
  if (!lab[0]) return 0;
  char ty[8] = "";
  size_t nty = 0;
  while (nty < 7 && isalpha((unsigned char)lab[nty])) ty[nty] = lab[nty], nty++;
  ty[nty] = 0;
  const int k = atoi(lab + nty);
  size_t g;
  const whirl_auto_label *L = r->label[0] ? NULL : group_label(J, i, ty, k, &g);
  if (L && fits_label(J, i, g, L->whirl)) {
    snprintf(r->irs, sizeof r->irs, "%d", L->whirl);
    return translate_run(J, i, (long)g);
  }
  const long def = restart_from(J, i);
  for (long j = (long)i - 1; j >= 0; j--) {
    char dir[4400], msg[512];
    whirl_solution S;
    const whirl_solution_shape any = {NULL, 0, 0, -1, 0};
    snprintf(dir, sizeof dir, "%s/%s.out", J->out, J->run[j].id);
    if (whirl_solution_find(dir, &any, k, ty, &S, msg, sizeof msg)) continue;
    const int good = fits(r, &S);
    whirl_solution_free(&S);
    if (good) return j == def ? 0 : translate_run(J, i, j);
  }
  if (L && continues_at(J, i, g, L)) {
    r->no_switch = 1;
    snprintf(r->irs, sizeof r->irs, "%d", L->whirl);
    return translate_run(J, i, (long)g);
  }
  return 0;
}

/* ---- the output directory ---------------------------------------------- */

/* OUT may be missing, empty, or an earlier output of whirl auto (MARKER).
 * 0 or 2. */
static int check_out(const char *out) {
  struct stat st;
  if (stat(out, &st) != 0) return 0;
  if (!S_ISDIR(st.st_mode)) {
    cli_error("auto", "%s exists and is not a directory", out);
    return 2;
  }
  char m[4400];
  snprintf(m, sizeof m, "%s/%s", out, MARKER);
  if (access(m, F_OK) == 0) return 0;
  DIR *d = opendir(out);
  int empty = 1;
  for (struct dirent *e; d && (e = readdir(d));)
    if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) empty = 0;
  if (d) closedir(d);
  if (empty) return 0;
  cli_error("auto", "%s holds files whirl auto did not write (no %s): choose another "
            "--out", out, MARKER);
  return 2;
}

static void remove_files(const char *dir) {
  DIR *d = opendir(dir);
  char p[4800];
  for (struct dirent *e; d && (e = readdir(d));) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
    unlink(p);
  }
  if (d) closedir(d);
  rmdir(dir);
}

/* Move the stage's files into OUT (made when missing) and mark it.  0 or 1. */
static int install_stage(const char *stage, const char *out) {
  if (mkdir(out, 0777) != 0 && errno != EEXIST) {
    cli_error("auto", "%s: %s", out, strerror(errno));
    return 1;
  }
  DIR *d = opendir(stage);
  char a[4800], b[4800];
  int rc = d ? 0 : 1;
  for (struct dirent *e; d && (e = readdir(d));) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    snprintf(a, sizeof a, "%s/%s", stage, e->d_name);
    snprintf(b, sizeof b, "%s/%s", out, e->d_name);
    if (rename(a, b) != 0) rc = 1;
  }
  if (d) closedir(d);
  rmdir(stage);
  snprintf(a, sizeof a, "%s/%s", out, MARKER);
  FILE *f = fopen(a, "w");
  if (!f || fprintf(f, "written by whirl auto\n") < 0) rc = 1;
  if (f && fclose(f)) rc = 1;
  if (rc) cli_error("auto", "%s: cannot move the plug-in into it", out);
  return rc;
}

/* Compile the plug-ins in OUT.tmp.PID, then into OUT: NAME.so for the
 * first run's NDIM, NAME.ndimK.so for each other NDIM of the c-files (an
 * extended system in the same equations file, as demo pcl's), the model's
 * name NAME in all (a run restarts from another NDIM's label as AUTO's
 * READBV does).  Each run's state names in r->x_names.  0, 1 or 2. */
static int build_model(auto_job *J) {
  char src[4400], stage[4400], file[600];
  int rc = auto_model_source(J->dir, J->name, src, sizeof src);
  if (rc) return rc;
  J->p_names = make_names(J, "parnames", "PAR", J->npar);
  J->x_names = make_names(J, "unames", "U", (size_t)J->ndim);
  if (!J->p_names || !J->x_names) return 1;
  for (size_t i = 0; i < J->nrun; i++) {
    auto_run *r = &J->run[i];
    r->x_names = r->ndim == J->ndim ? J->x_names : make_names(J, "unames", "U", (size_t)r->ndim);
    if (!r->x_names) return 1;
  }
  snprintf(stage, sizeof stage, "%s.tmp.%ld", J->out, (long)getpid());
  if (mkdir(stage, 0777) != 0) {
    cli_error("auto", "%s: %s", stage, strerror(errno));
    return 1;
  }
  int built = 0;
  for (size_t i = 0; i < J->nrun && !rc; i++) {
    const auto_run *r = &J->run[i];
    size_t first = 0; /* one plug-in an NDIM: the first run with it builds */
    while (J->run[first].ndim != r->ndim) first++;
    if (first != i) continue;
    ndim_file(J, r->ndim, file, sizeof file);
    const auto_model_info m = {J->name, r->ndim, J->npar, (const char *const *)J->p_names,
                               (const char *const *)r->x_names,
                               r->ndim == J->ndim ? NULL : file};
    if (auto_model_current(J->out, src, &m)) continue;
    rc = auto_model_build(J->out, stage, src, &m);
    built = 1;
  }
  if (rc) {
    remove_files(stage);
    return rc;
  }
  if (!built) {
    rmdir(stage);
    return 0;
  }
  return install_stage(stage, J->out);
}

/* Open OUT/b.STEM, s.STEM, d.STEM for writing (MODE "w" or "a"). */
static int open_auto(const auto_job *J, const char *stem, const char *mode, FILE *f[3],
                     char path[3][4400]) {
  static const char kind[3] = {'b', 's', 'd'};
  int rc = 0;
  for (int k = 0; k < 3; k++) {
    snprintf(path[k], sizeof path[k], "%s/%c.%s", J->out, kind[k], stem);
    if (!(f[k] = fopen(path[k], mode))) rc = 1;
  }
  return rc;
}

static int close_auto(FILE *f[3], char path[3][4400], int rc) {
  for (int k = 0; k < 3; k++)
    if (f[k] && fclose(f[k])) rc = 1;
  if (rc) { /* no half-written AUTO files */
    cli_error("auto", "%s: cannot write", path[0]);
    for (int k = 0; k < 3; k++) unlink(path[k]);
  }
  return rc;
}

/* The bytes of the file src appended to dst: 0, or 1 when src cannot be
 * read or dst written. */
static int append_file(FILE *dst, const char *src) {
  FILE *in = fopen(src, "rb");
  if (!in) return 1;
  char buf[65536];
  size_t got;
  int rc = 0;
  while (!rc && (got = fread(buf, 1, sizeof buf, in)) > 0)
    if (fwrite(buf, 1, got, dst) != got) rc = 1;
  if (ferror(in)) rc = 1;
  fclose(in);
  return rc;
}

/* The label of an earlier run that run i restarts from, or NULL. */
static const whirl_auto_label *restart_label(const auto_job *J, size_t i) {
  const auto_run *r = &J->run[i];
  const int want = r->src >= 0 ? atoi(r->irs[0] ? r->irs : r->label) : 0;
  for (size_t m = 0; r->src >= 0 && m < J->run[r->src].nlabs; m++)
    if (J->run[r->src].labs[m].whirl == want) return &J->run[r->src].labs[m];
  return NULL;
}

/* The row (from 0) of whirl label lab in OUT/ID.out/branches.tsv, or -1. */
static long table_row_of(const auto_job *J, const char *id, int lab) {
  char path[4400], *line = NULL;
  size_t cap = 0;
  snprintf(path, sizeof path, "%s/%s.out/branches.tsv", J->out, id);
  FILE *f = fopen(path, "r");
  long row = -1, found = -1;
  int col = -1;
  while (f && found < 0 && getline(&line, &cap, f) > 0) {
    if (line[0] == '#') continue;
    char *save = NULL, *t = strtok_r(line, "\t\n", &save);
    for (int c = 0; t; c++, t = strtok_r(NULL, "\t\n", &save)) {
      if (row < 0 && !strcmp(t, "label")) col = c;
      if (row >= 0 && c == col && atoi(t) == lab) found = row;
    }
    if (col < 0) break; /* no label column: not whirl's table */
    row++;
  }
  free(line);
  if (f) fclose(f);
  return found;
}

/* AUTO's type code of whirl label lab of the run ID of an earlier
 * invocation (a script's earlier run): its row of OUT/b.ID, the one of
 * branches.tsv's rows that lab is on (the same points in the same
 * order).  0 when not found. */
static int external_type(const auto_job *J, const char *id, int lab) {
  const long k = table_row_of(J, id, lab);
  char path[4400], *line = NULL;
  size_t cap = 0;
  snprintf(path, sizeof path, "%s/b.%s", J->out, id);
  FILE *f = k < 0 ? NULL : fopen(path, "r");
  long row = 0;
  int type = 0;
  for (ssize_t len; f && (len = getline(&line, &cap, f)) > 0;) {
    char br[5] = {0}, ty[5] = {0};
    if (len < 15 || atoi(memcpy(br, line, 4)) == 0) continue; /* a header line */
    if (row++ == k) {
      memcpy(ty, line + 10, 4);
      type = atoi(ty);
      break;
    }
  }
  free(line);
  if (f) fclose(f);
  return type;
}

/* AUTO's ITPST of run i (AUTO-07p io.f90, READLB): with |ISW| >= 2 the
 * type of the label it restarts from, its code or the code / 10 where
 * that is a point of a locus itself; else 0. */
static int start_type(const auto_job *J, size_t i) {
  const auto_run *r = &J->run[i];
  int isw = 1;
  whirl_auto_constants_int(r->ac, "ISW", &isw);
  if (abs(isw) < 2 || r->fresh) return 0;
  const whirl_auto_label *L = restart_label(J, i);
  const int t = L ? L->type
                  : r->from[0] && r->src < 0 ? external_type(J, r->from, atoi(r->label)) : 0;
  const int k = abs(t) < 10 ? abs(t) : abs(t / 10);
  return k <= 9 ? k : 0; /* a code of 100 or more is none of AUTO's */
}

/* AUTO's number of run i's first branch (AUTO-07p io.f90, NEWLAB): the
 * constants' IBR when given; else one more than the largest of its group
 * for a fresh start or a branch switch (ISW < 0); the restart label itself
 * for a locus (|ISW| = 2) or orbits from a Hopf point; else the branch of
 * the restart point.  (A script's runs get IBR and LAB from its runner,
 * python/whirl_auto.py, which knows the solutions a run starts from.) */
static int first_branch(const auto_job *J, size_t i) {
  const auto_run *r = &J->run[i];
  int ips = 1, isw = 1, mbr = 0;
  whirl_auto_constants_int(r->ac, "IPS", &ips);
  whirl_auto_constants_int(r->ac, "ISW", &isw);
  for (size_t g = group_start(J, i > 0 ? i - 1 : 0); !r->fresh && g < i; g++)
    for (size_t m = 0; m < J->run[g].nlabs; m++)
      if (J->run[g].labs[m].br > mbr) mbr = J->run[g].labs[m].br;
  if (r->br_fixed > 0) return r->br_fixed;
  int ibr = 0; /* AUTO's IBR: the branch number given */
  whirl_auto_constants_int(r->ac, "IBR", &ibr);
  if (ibr > 0) return ibr;
  const whirl_auto_label *L = restart_label(J, i);
  if (isw < 0 || r->fresh || !L) return mbr + 1;
  if (((abs(isw) == 2 || isw == 3) && abs(L->type) < 10) || (ips == 2 && L->type == 3))
    return L->label;
  return L->br;
}

/* OUT/b.ID, s.ID, d.ID of run i from its output directory, and the run
 * appended to OUT/b.NAME, s.NAME, d.NAME (emptied before the runs), its
 * labels and branches numbered as AUTO numbers them (above), which both
 * files show.  0 or 1. */
static int write_auto_files(auto_job *J, size_t i) {
  auto_run *r = &J->run[i];
  char dir[4400], path[3][4400], msg[1024];
  snprintf(dir, sizeof dir, "%s/%s.out", J->out, r->id);
  r->offset = 0;
  for (size_t g = group_start(J, i > 0 ? i - 1 : 0); !r->fresh && g < i; g++)
    for (size_t m = 0; m < J->run[g].nlabs; m++)
      if (J->run[g].labs[m].label > r->offset) r->offset = J->run[g].labs[m].label;
  int lab = 0; /* AUTO's LAB: the first label given (NEWLAB) */
  whirl_auto_constants_int(r->ac, "LAB", &lab);
  if (lab > 0 && !r->sub) r->offset = lab - 1;
  r->br_auto = first_branch(J, i);
  whirl_auto_output o = {dir, r->ac, r->ndim, J->npar, (const char *const *)J->p_names,
                         (const char *const *)r->x_names, r->offset, !r->fresh, r->br_auto,
                         start_type(J, i)};
  size_t n = 0;
  if (whirl_auto_labels(&o, NULL, 0, &n, msg, sizeof msg) != WHIRL_OK ||
      !(r->labs = calloc(n ? n : 1, sizeof *r->labs)) ||
      whirl_auto_labels(&o, r->labs, n, &r->nlabs, msg, sizeof msg) != WHIRL_OK) {
    cli_error("auto", "%s: %s", dir, r->labs ? msg : "out of memory");
    return 1;
  }
  FILE *f[3];
  /* a run named NAME (c.NAME) has the merged files as its own; another
   * run's files are written once and appended to them as they are (the
   * same bytes: formatting the run's solutions twice was a tenth of demo
   * man's time) */
  const int own = !strcmp(r->id, J->name);
  int rc = open_auto(J, own ? J->name : r->id, own ? "a" : "w", f, path);
  if (!rc && whirl_auto_write_files(&o, f[0], f[1], f[2], NULL, msg, sizeof msg) != WHIRL_OK) {
    cli_error("auto", "%s: %s", dir, msg);
    rc = 1;
  }
  if (close_auto(f, path, rc)) return 1;
  if (own) return 0;
  char run_path[3][4400];
  memcpy(run_path, path, sizeof run_path);
  rc = open_auto(J, J->name, "a", f, path);
  for (int k = 0; k < 3 && !rc; k++) rc = append_file(f[k], run_path[k]);
  return close_auto(f, path, rc);
}

/* Run i: its run file written (its restart chosen) and run, its AUTO
 * files written.  Its exit status (0, 1, 2), or -1 (cannot write), -2
 * (bad input: stop). */
static int run_one(auto_job *J, size_t i) {
  char path[4400], dir[4400];
  /* an earlier invocation's output of this run must not pass for this one's */
  snprintf(dir, sizeof dir, "%s/%s.out", J->out, J->run[i].id);
  remove_files(dir);
  for (const char *k = "bsd"; *k; k++) {
    snprintf(path, sizeof path, "%s/%c.%s", J->out, *k, J->run[i].id);
    unlink(path);
  }
  if (pick_source(J, i)) return -2;
  snprintf(path, sizeof path, "%s/%s.whirl", J->out, J->run[i].id);
  FILE *rf = fopen(path, "w");
  if (!rf || fputs(J->run[i].text, rf) < 0 || fclose(rf)) {
    cli_error("auto", "%s: cannot write", path);
    return -1;
  }
  if (!J->quiet) printf("== %s (c.%s)\n", J->run[i].id, J->run[i].c);
  fflush(stdout);
  char *argv[5] = {"run", path, NULL, NULL, NULL};
  int argc = 2;
  if (!J->plot) argv[argc++] = "--no-plot";
  if (J->quiet) argv[argc++] = "--quiet";
  int st = cmd_run(argc, argv);
  char tsv[4400];
  snprintf(tsv, sizeof tsv, "%s/%s.out/branches.tsv", J->out, J->run[i].id);
  if (st != 2 && access(tsv, R_OK) == 0 && write_auto_files(J, i) && !st) st = 1;
  if (st) cli_error("auto", "run %s (c.%s) failed (exit %d)", J->run[i].id, J->run[i].c, st);
  return st;
}

/* ---- MXBF: AUTO's automatic branch switching ------------------------- */

/* AUTO-07p ae.f90 (CNRLAE, STBIF, SWPNT): on a branch of equilibria
 * (IPS = 1, |ISW| <= 1) AUTO stores the first |MXBF| branch points it meets,
 * in order, on that branch and on the branches it then switches to (a BP
 * met while |MXBF| are stored is not stored); after a branch ends it
 * switches at the first stored BP (ISW = -1): with MXBF > 0 first with DS
 * and then with -DS (the direction in which the parameter grows is +), the
 * two halves one branch number, with MXBF < 0 once, with DS; at most
 * 2|MXBF| (|MXBF|) branches follow the first.  Labels number on.  whirl
 * auto does the same with a run a branch, inserted after run i. */
/* AUTO's MXBF where a constants file has none (AUTO-07p main.f90's
 * defaults): branch switching is on unless a file turns it off (demo
 * pp2's c.pp2 has MXBF in a comment only: AUTO switches at its BPs). */
#define AUTO_MXBF 10

typedef struct bp_queue {
  size_t run[64];
  int lab[64];
  size_t n, cap;
} bp_queue;

static void queue_bps(const auto_job *J, size_t i, bp_queue *q) {
  for (size_t m = 0; m < J->run[i].nlabs; m++)
    if (!strcmp(J->run[i].labs[m].ty, "BP") && q->n < q->cap)
      q->run[q->n] = i, q->lab[q->n++] = J->run[i].labs[m].whirl;
}

/* Insert after run AT a run switching at BP (run j, whirl label lab) of
 * run i's constants with DS times SIGN and AUTO branch BR.  0, 1 or 2. */
static int insert_switch(auto_job *J, size_t i, size_t at, size_t j, int lab, int sign,
                         int br, int k) {
  if (J->nrun == MAXALL) {
    cli_error("auto", "%s: more than %d runs with MXBF's branches", J->run[i].c, MAXALL);
    return 1;
  }
  memmove(&J->run[at + 1], &J->run[at], (J->nrun - at) * sizeof J->run[0]);
  J->nrun++;
  for (size_t m = at + 1; m < J->nrun; m++)
    if (J->run[m].src >= (long)at) J->run[m].src++;
  auto_run *r = &J->run[at], *p = &J->run[i]; /* i < at: p did not move */
  char c[sizeof r->c]; /* r and p are elements of one array (-Wrestrict) */
  memcpy(c, p->c, sizeof c);
  memset(r, 0, sizeof *r);
  memcpy(r->c, c, sizeof c);
  char id[sizeof r->id];
  snprintf(id, sizeof id, "%.300s.bif%d", p->id, k);
  memcpy(r->id, id, sizeof id);
  snprintf(r->irs, sizeof r->irs, "%d", lab);
  r->sub = 1, r->br_fixed = br;
  r->ndim = p->ndim, r->x_names = p->x_names; /* p's (freed with the runs of its NDIM) */
  /* the constants file again with ISW = -1 and the signed DS last (a later
   * key replaces an earlier one) */
  char path[4400], *text = NULL;
  size_t len = 0;
  snprintf(path, sizeof path, "%s/c.%s", J->dir, p->c);
  FILE *f = fopen(path, "r"), *m = open_memstream(&text, &len);
  double ds = 0.01;
  whirl_auto_constants_real(p->ac, "DS", &ds);
  for (int ch; f && m && (ch = fgetc(f)) != EOF;) fputc(ch, m);
  if (m) fprintf(m, "\nISW = -1, DS = %.17g\n", sign * ds);
  if (f) fclose(f);
  if (!f || !m || fclose(m) || !(r->ac = whirl_auto_constants_alloc()) ||
      whirl_auto_constants_parse(r->ac, path, text, len) != WHIRL_OK) {
    cli_error("auto", "%s: cannot set up MXBF's switch", path);
    free(text);
    return 1;
  }
  free(text);
  return translate_run(J, at, (long)j);
}

/* After run i (and its branches so far) ran: the next switch MXBF asks
 * for, inserted after run at (its BP queue and counts in *q, *nbfc, *br,
 * *pos).  1 when one was inserted, 0 when none is left, -1 on error. */
static int next_switch(auto_job *J, size_t i, size_t at, bp_queue *q, int *nbfc, int *br,
                       int *pos) {
  int mxbf = AUTO_MXBF;
  whirl_auto_constants_int(J->run[i].ac, "MXBF", &mxbf);
  const int nbfcs = mxbf > 0 ? 2 * mxbf : -mxbf;
  queue_bps(J, at, q);
  if (!q->n || *nbfc >= nbfcs) return 0;
  if (*pos || mxbf < 0) ++*br; /* a new branch; its second half keeps it */
  const int sign = *pos ? 1 : -1;
  const size_t j = q->run[0];
  const int lab = q->lab[0];
  if (mxbf > 0) *pos = !*pos;
  if (*pos) { /* both halves done (or the one of MXBF < 0): the next BP */
    memmove(q->run, q->run + 1, (q->n - 1) * sizeof *q->run);
    memmove(q->lab, q->lab + 1, (q->n - 1) * sizeof *q->lab);
    q->n--;
  }
  ++*nbfc;
  return insert_switch(J, i, at + 1, j, lab, sign, *br, *nbfc) ? -1 : 1;
}

/* MXBF's queue of run i: set up when run i has ran (IPS = 1 or -1 (AUTO
 * switches at BPs of maps' fixed points alike), |ISW| <= 1, MXBF not 0).
 * 0 when MXBF does not apply. */
static int mxbf_begin(const auto_job *J, size_t i, bp_queue *q) {
  int ips = 1, isw = 1, mxbf = AUTO_MXBF;
  const auto_run *r = &J->run[i];
  whirl_auto_constants_int(r->ac, "IPS", &ips);
  whirl_auto_constants_int(r->ac, "ISW", &isw);
  whirl_auto_constants_int(r->ac, "MXBF", &mxbf);
  memset(q, 0, sizeof *q);
  q->cap = (size_t)abs(mxbf) < 64 ? (size_t)abs(mxbf) : 64;
  return (ips == 1 || ips == -1) && abs(isw) <= 1 && mxbf != 0 && !r->sub;
}

/* Write the run files and run them all in order (a run after a failed one
 * may still work, as in AUTO).  The first failing status. */
static int run_all(auto_job *J) {
  int status = 0;
  for (size_t i = 0; i < J->nrun; i++) {
    char path[4400];
    snprintf(path, sizeof path, "%s/%s.whirl", J->out, J->run[i].id);
    FILE *f = fopen(path, "w");
    if (!f || fputs(J->run[i].text, f) < 0 || fclose(f)) {
      cli_error("auto", "%s: cannot write", path);
      return 1;
    }
  }
  FILE *f[3];
  char merged[3][4400];
  if (close_auto(f, merged, open_auto(J, J->name, "w", f, merged))) return 1;
  for (size_t i = 0; i < J->nrun; i++) {
    int st = run_one(J, i);
    if (st == -2) return 2;
    if (st < 0) return 1;
    if (st && !status) status = st;
    bp_queue q;
    if (!mxbf_begin(J, i, &q)) continue;
    int nbfc = 0, br = J->run[i].br_auto, pos = 1, k;
    size_t at = i;
    while ((k = next_switch(J, i, at, &q, &nbfc, &br, &pos)) == 1) {
      st = run_one(J, ++at);
      if (st < 0) return st == -2 ? 2 : 1;
      if (st && !status) status = st;
    }
    if (k < 0) return 1;
    i = at;
  }
  return status;
}

/* ---- AUTO's scripts: python/whirl_auto.py ------------------------------ */

/* The script runner: the source tree's, else the installed one. */
static const char *script_module(void) {
  const char *e = getenv("WHIRL_AUTO_SCRIPT_RUNNER");
  if (e && *e) return e;
#ifdef WHIRL_SRC_PYTHONDIR
  if (access(WHIRL_SRC_PYTHONDIR "/whirl_auto.py", R_OK) == 0)
    return WHIRL_SRC_PYTHONDIR "/whirl_auto.py";
#endif
#ifdef WHIRL_PKGDATADIR
  return WHIRL_PKGDATADIR "/python/whirl_auto.py";
#else
  return "/usr/local/share/whirl/python/whirl_auto.py";
#endif
}

/* --script: AUTO's script of runs (NAME.auto) executed by whirl_auto.py
 * with AUTO's commands, each run one `whirl auto` of this executable into
 * OUT/runs.  Its exit status: 0, 1 (a run failed) or 2 (bad input). */
static int run_script(auto_job *J) {
  char script[4400], self[4096];
  if (J->script[0]) snprintf(script, sizeof script, "%s", J->script);
  else snprintf(script, sizeof script, "%s/%s.auto", J->dir, J->name);
  if (access(script, R_OK) != 0) {
    cli_error("auto", "%s: %s (the script --script runs)", script, strerror(errno));
    return 2;
  }
  if (check_out(J->out)) return 2;
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) {
    cli_error("auto", "--script: cannot find this executable (/proc/self/exe)");
    return 1;
  }
  self[n] = 0;
  /* OUT and its mark are made by the runner once the script compiles: a
   * script with a syntax error writes nothing */
  const char *py = getenv("WHIRL_PYTHON");
  if (!(py && *py) && access(WHIRL_PYTHON3, X_OK) == 0) py = WHIRL_PYTHON3;
  char whirl_arg[4200], dir_arg[4200], out_arg[4200];
  snprintf(whirl_arg, sizeof whirl_arg, "--whirl=%s", self);
  snprintf(dir_arg, sizeof dir_arg, "--dir=%s", J->dir);
  snprintf(out_arg, sizeof out_arg, "--out=%s", J->out);
  char *argv[] = {(char *)(py && *py ? py : "python3"), (char *)script_module(), whirl_arg,
                  dir_arg, out_arg, J->quiet ? "--quiet" : script, J->quiet ? script : NULL,
                  NULL};
  fflush(stdout);
  pid_t pid = fork();
  if (pid < 0) {
    cli_error("auto", "--script: cannot start Python: %s", strerror(errno));
    return 1;
  }
  if (pid == 0) {
    execvp(argv[0], argv);
    fprintf(stderr, "whirl auto: --script needs Python 3 ('%s': %s; set WHIRL_PYTHON)\n",
            argv[0], strerror(errno));
    _exit(2);
  }
  int st;
  while (waitpid(pid, &st, 0) < 0)
    if (errno != EINTR) return 1;
  return WIFEXITED(st) ? WEXITSTATUS(st) : 1;
}

/* ---- the command ------------------------------------------------------- */

/* The default order of the constants files could not be made (none of
 * them numbered, or a restart from a label no earlier run in that order
 * has): where DIR/NAME.auto exists, its script orders AUTO's runs (ph1's
 * c.ph1 restarts from runs of c.ph1.ss and c.ph1.ps; plp has c.plp.ss,
 * c.plp.hb, ...), so say how to run it. */
static void script_hint(const auto_job *J) {
  char script[4400];
  snprintf(script, sizeof script, "%s/%s.auto", J->dir, J->name);
  if (access(script, R_OK) == 0)
    fprintf(stderr, "whirl auto: %s orders the runs of these constants files: "
                    "`whirl auto %s %s --script` runs it\n", script, J->dir, J->name);
}

static int parse_args(auto_job *J, int argc, char **argv, const char **runs) {
  const char *pos[2] = {NULL, NULL};
  size_t npos = 0;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return -1;
    }
    if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) J->quiet = 1;
    else if (!strcmp(a, "--plot")) J->plot = 1;
    else if (!strncmp(a, "--out=", 6) && a[6]) J->out = a + 6;
    else if (!strncmp(a, "--runs=", 7) && a[7]) *runs = a + 7;
    else if (!strcmp(a, "--script")) J->script = "";
    else if (!strncmp(a, "--script=", 9) && a[9]) J->script = a + 9;
    else if (a[0] == '-' || npos == 2) {
      cli_error("auto", "unexpected argument '%s' (see whirl auto --help)", a);
      return 2;
    } else pos[npos++] = a;
  }
  if (!npos) {
    usage(stderr);
    return 2;
  }
  static char dir[4096];
  snprintf(dir, sizeof dir, "%s", pos[0]);
  for (size_t n = strlen(dir); n > 1 && dir[n - 1] == '/';) dir[--n] = 0;
  J->dir = dir;
  if (!realpath(dir, J->absdir)) J->absdir[0] = '\0';
  if (pos[1]) J->name = pos[1];
  else { /* DIR's last component, of its real path (".", "..", "demo/.") */
    static char base[256];
    const char *d = J->absdir[0] ? J->absdir : J->dir;
    size_t n = strlen(d);
    while (n > 1 && d[n - 1] == '/') n--;
    size_t b = n;
    while (b > 0 && d[b - 1] != '/') b--;
    snprintf(base, sizeof base, "%.*s", (int)(n - b), d + b);
    J->name = base;
  }
  if (!name_ok(J->name) || strchr(J->name, '/')) {
    cli_error("auto", "'%s' is not a usable problem name (give NAME)", J->name);
    return 2;
  }
  return 0;
}

int cmd_auto(int argc, char **argv) {
  static auto_job J;
  const char *runs = NULL;
  char out[300];
  memset(&J, 0, sizeof J);
  int rc = parse_args(&J, argc, argv, &runs);
  if (rc) return rc < 0 ? 0 : rc;
  if (!J.out) {
    snprintf(out, sizeof out, "%s.out", J.name);
    J.out = out;
  }
  if (J.script) {
    if (runs) {
      cli_error("auto", "--script and --runs exclude each other (the script names the runs)");
      return 2;
    }
    return run_script(&J);
  }
  rc = runs ? parse_runs(&J, runs) : default_runs(&J);
  if (!rc) rc = read_constants(&J);
  if (!rc) rc = translate(&J);
  if (rc && !runs) script_hint(&J);
  if (!rc) rc = check_out(J.out);
  if (!rc) rc = build_model(&J);
  if (!rc) rc = run_all(&J);
  for (size_t i = 0; i < J.nrun; i++) {
    if (J.run[i].x_names != J.x_names && !J.run[i].sub)
      free_names(J.run[i].x_names, (size_t)J.run[i].ndim);
    whirl_auto_constants_free(J.run[i].ac);
    free(J.run[i].text);
    free(J.run[i].labs);
  }
  free_names(J.p_names, J.npar);
  free_names(J.x_names, (size_t)J.ndim);
  return rc;
}

/* test/unit/t_auto_constants.c — AUTO-07p constants files read as AUTO
 * reads them (whirl/auto_constants.h).
 *
 * 1. Texts written here: several keys a line, Python literals in both
 *    quotes, dictionaries over several lines, negative UZR indices,
 *    Fortran numbers, AUTO's `*` shorthand, comments, and bad input with
 *    its FILE:LINE message.
 * 2. The demos' own files (AUTO_07P_DIR, else ../shared/auto-07p next to
 *    the source tree; SKIP where absent): every c.* of every demo parses,
 *    and four of them (ab/c.ab.1, pla/c.pla.3, pcl/c.pcl.5, pp2/c.pp2)
 *    give the values their text shows, copied here by hand.
 * `t_auto_constants --dump FILE...` prints what it read, one key a line,
 * for test/regress/auto_constants.sh to compare with AUTO's own parser.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/whirl.h>

#include "../tap.h"

static whirl_auto_constants *parse(const char *text, int *rc) {
  whirl_auto_constants *ac = whirl_auto_constants_alloc();
  *rc = whirl_auto_constants_parse(ac, "c.t", text, strlen(text));
  return ac;
}

static int int_is(const whirl_auto_constants *ac, const char *k, int want) {
  int v = want + 1;
  return whirl_auto_constants_int(ac, k, &v) == WHIRL_OK && v == want;
}
static int real_is(const whirl_auto_constants *ac, const char *k, double want) {
  double v = want + 1;
  return whirl_auto_constants_real(ac, k, &v) == WHIRL_OK && v == want;
}
static int text_is(const whirl_auto_constants *ac, const char *k, const char *want) {
  const char *t = whirl_auto_constants_text(ac, k);
  return t && !strcmp(t, want);
}
/* Item i of an indexed key: its index (or name) and values. */
static int indexed_is(const whirl_auto_constants *ac, const char *k, size_t i, int index,
                      const char *name, const double *v, size_t nv) {
  whirl_auto_item it;
  if (whirl_auto_constants_item(ac, k, i, &it) != WHIRL_OK) return 0;
  if (name ? !it.name || strcmp(it.name, name) : it.name || it.index != index) return 0;
  if (it.nvalues != nv) return 0;
  for (size_t j = 0; j < nv; j++)
    if (it.values[j] != v[j]) return 0;
  return 1;
}
static int ref_is(const whirl_auto_constants *ac, const char *k, size_t i, int index,
                  const char *name) {
  return indexed_is(ac, k, i, index, name, NULL, 0);
}
static int name_is(const whirl_auto_constants *ac, const char *k, size_t i, int index,
                   const char *text) {
  whirl_auto_item it;
  return whirl_auto_constants_item(ac, k, i, &it) == WHIRL_OK && it.index == index &&
         it.text && !strcmp(it.text, text);
}

static void syntax(void) {
  int rc;
  whirl_auto_constants *ac = parse(
      "# a comment\n"
      "NDIM=   2, IPS =   1, IRS =   0, ILP =   1\n"
      "ICP =  [2, 'PERIOD']  NMX = ***\n"
      "DS  =   -0.1, DSMIN= 1.0D-03, DSMAX=2.5-1 ! rest ignored\n"
      "UZR = {2: [14.0, 15], -1: 0.25, 'lambda': 3}, UZSTOP = {2: 18}\n"
      "THL = {11: 0}, THU = {}\n"
      "unames = {1: \"u1\",\n"
      "          2: 'u 2'}\n"
      "e = 'ab', s = \"ab\", dat='ab.dat', sv = ''\n"
      "IRS = HB2, UZR = {2: 1, 2: [3, 4]}\n"
      "STOP = ['HB1', 'LP2']\n", &rc);
  ok(rc == WHIRL_OK, "several keys a line, lists, dicts: parses (%s)",
     whirl_auto_constants_errmsg(ac));
  ok(int_is(ac, "NDIM", 2) && int_is(ac, "IPS", 1) && int_is(ac, "ILP", 1),
     "NDIM, IPS, ILP on one line");
  ok(int_is(ac, "NMX", 1000), "NMX = ***: AUTO's 10^3");
  ok(whirl_auto_constants_count(ac, "ICP") == 2 && ref_is(ac, "ICP", 0, 2, NULL) &&
         ref_is(ac, "ICP", 1, 0, "PERIOD"),
     "ICP = [2, 'PERIOD']: an index and a name");
  ok(real_is(ac, "DS", -0.1) && real_is(ac, "DSMIN", 1e-3) && real_is(ac, "DSMAX", 2.5e-1),
     "reals, Fortran D exponent and 2.5-1");
  ok(whirl_auto_constants_line(ac, "DSMAX") == 4 && whirl_auto_constants_line(ac, "e") == 9,
     "lines of the keys (after a dictionary over two lines)");
  ok(whirl_auto_constants_count(ac, "UZR") == 1 &&
         indexed_is(ac, "UZR", 0, 2, NULL, (double[]){1, 3, 4}, 3),
     "UZR given again replaces; {2: 1, 2: [3, 4]} collects into 2: [1, 3, 4]");
  ok(whirl_auto_constants_count(ac, "THU") == 0 && whirl_auto_constants_line(ac, "THU") == 6 &&
         indexed_is(ac, "THL", 0, 11, NULL, (double[]){0}, 1),
     "THL = {11: 0}; THU = {} given and empty");
  ok(name_is(ac, "unames", 0, 1, "u1") && name_is(ac, "unames", 1, 2, "u 2"),
     "unames over two lines, both quotes, a blank inside quotes");
  ok(text_is(ac, "e", "ab") && text_is(ac, "s", "ab") && text_is(ac, "dat", "ab.dat") &&
         text_is(ac, "sv", ""),
     "e, s, dat, sv");
  ok(text_is(ac, "IRS", "HB2") && whirl_auto_constants_kind(ac, "IRS") == WHIRL_AC_TEXT,
     "IRS = HB2: a label name");
  ok(ref_is(ac, "STOP", 0, 0, "HB1") && ref_is(ac, "STOP", 1, 0, "LP2"), "STOP names");
  whirl_auto_constants_free(ac);

  ac = parse("UZSTOP = {-1: 0.25, 2: [-3, 4.5e1]}\n", &rc);
  ok(rc == WHIRL_OK && indexed_is(ac, "UZSTOP", 0, -1, NULL, (double[]){0.25}, 1) &&
         indexed_is(ac, "UZSTOP", 1, 2, NULL, (double[]){-3, 45}, 2),
     "negative UZSTOP index (a stop)");
  whirl_auto_constants_free(ac);
}

static void errors(void) {
  static const struct {
    const char *text, *msg;
  } cases[] = {
      {"NDIM = 2\nDSMX = 0.1\n", "c.t:2: unknown AUTO constant 'DSMX'"},
      {"NDIM = 2, ndim = 3\n", "c.t:1: unknown AUTO constant 'ndim'"},
      {"NDIM = 2.0\n", "c.t:1: NDIM: '2.0' is not an integer"},
      {"DS = abc\n", "c.t:1: DS: 'abc' is not a number"},
      {"DS = 1e999\n", "c.t:1: DS: '1e999' is not a finite number"},
      {"ICP = [1,\n 2\n", "c.t:1: unterminated '[' or '{' (end of file)"},
      {"e = 'ab\n", "c.t:1: unterminated quoted string"},
      {"\n\nUZR = {2: }\n", "c.t:3: UZR: '2' has no value"},
      {"UZR = {2: [1, 2}}\n", "c.t:1: UZR: ']' missing"},
      {"UZR = 5\n", "c.t:1: UZR: expected a dictionary {index: value, ...}, got '5'"},
      {"NMX = [5]\n", "c.t:1: NMX: expected one value, got a list"},
      {"ICP = [1]x\n", "c.t:1: text after the closing bracket"},
      {"unames = {a: 'x'}\n", "c.t:1: unames: 'a' is not an integer index"},
      {"2 1 0 1\n", "c.t:1: an old-style (numeric) constants file: whirl reads AUTO-07p's "
                    "KEY = value files only"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    int rc;
    whirl_auto_constants *ac = parse(cases[i].text, &rc);
    const char *m = whirl_auto_constants_errmsg(ac);
    ok(rc == WHIRL_EINVAL && !strcmp(m, cases[i].msg), "error: %s (got '%s')", cases[i].msg, m);
    whirl_auto_constants_free(ac);
  }
  whirl_auto_constants *ac = whirl_auto_constants_alloc();
  ok(whirl_auto_constants_read(ac, "/nonexistent/c.x") == WHIRL_EIO &&
         strstr(whirl_auto_constants_errmsg(ac), "/nonexistent/c.x: cannot open"),
     "a missing file: WHIRL_EIO naming it");
  whirl_auto_constants_free(ac);
}

/* ---- as a whirl run file ---------------------------------------------- */

static void runfile(void) {
  int rc;
  whirl_auto_constants *ac = parse(
      "NDIM=2, IPS=2, IRS=3, ISW=1\n"
      "ICP=['Da', 'PERIOD']\n"
      "UZR={-1: 0.25, 'Da': [0.1, 0.2], 22: 0.0, 11: 5}\n"
      "parnames={1: 'Da'}, unames={1: 'x'}\n"
      "NPAR=3, DS=0.01\n"
      "THL={11: 0, 2: 3, 5: 1}, THU={'x': 0.5}\n"
      "U={'x': 1.5}\n", &rc);
  const whirl_auto_runfile_opts o = {"m.so", "prev.out", NULL, "o.out", 3, NULL};
  char *t = NULL;
  ok(rc == WHIRL_OK && whirl_auto_constants_runfile(ac, &o, &t) == WHIRL_OK && t,
     "translates (%s)", whirl_auto_constants_errmsg(ac));
  static const char *const want[] = {
      "\nmodel  = 'm.so'\n", "\nOUT    = 'o.out'\n", "\nIPS    = 2\n", "\nISW    = 1\n",
      "\nJAC    = 0\n", "\nICP    = [1, PERIOD]\n", "\nS      = 'prev.out'\n",
      "\nIRS    = 3\n", "\nNDIM   = 2\n", "\nDS     = 0.01\n", "\nU      = {1: 1.5}\n",
      "\n# note: UZR on PAR(22): not a parameter of the model (a PVLS quantity?), ignored\n",
      "\nUZR    = {1: [0.1, 0.2], PERIOD: [5]}\n", "\nUZSTOP = {1: [0.25]}\n",
      "\nTHL    = {PERIOD: 0, 2: 3}\n", "\nTHU    = {1: 0.5}\n",
      "\n# note: THL on PAR(5): not a parameter of the model, ignored\n"};
  for (size_t i = 0; i < sizeof want / sizeof *want; i++)
    ok(t && strstr(t, want[i]), "run file has '%.*s'", (int)strlen(want[i]) - 2, want[i] + 1);
  whirl_runfile *rf = whirl_runfile_alloc();
  ok(t && whirl_runfile_parse(rf, "t.whirl", t, strlen(t)) == WHIRL_OK,
     "whirl's run-file parser reads it (%s)", whirl_runfile_errmsg(rf));
  whirl_runfile_free(rf);
  free(t);
  whirl_auto_constants_free(ac);

  static const struct {
    const char *text, *msg;
    const char *restart;
  } bad[] = {
      {"NDIM=1\nIPS = 9\nICP=[1]\n", "c.t:2: IPS = 9: whirl runs AUTO's equilibria (1), "
                                      "periodic orbits (2), boundary-value problems (4) and "
                                      "fixed points of maps (-1) only", NULL},
      {"NDIM=1, ICP=[1]\ndat = 'x'\n",
       "c.t:2: dat = 'x': a data file starts periodic orbits (IPS = 2) or a boundary-value "
       "problem (IPS = 4), not IPS = 1", NULL},
      {"NDIM=1, IPS=2, ICP=[1]\ndat = 'nothere'\n",
       "c.t:2: dat = 'nothere': no data file nothere or nothere.dat", NULL},
      {"NDIM=1, ICP=[1]\n\nIRS = 3\n", "c.t:3: IRS = 3: no earlier run to restart from", NULL},
      {"NDIM=1\nICP=['foo']\n", "c.t:2: ICP: 'foo' is neither in parnames nor PERIOD", NULL},
      {"NDIM=1\nICP=[7]\n", "c.t:2: ICP: PAR(7) beyond NPAR = 3", NULL},
      {"NDIM=1\nICP=[1], ISW = 4\n", "c.t:2: ISW = 4: whirl has ISW = 1, -1, 2 and 3 only", NULL},
      {"NDIM=1, ICP=[1]\nU = {2: 0}\n", "c.t:2: U: U(2) beyond NDIM = 1", NULL},
  };
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    ac = parse(bad[i].text, &rc);
    const whirl_auto_runfile_opts ob = {"m.so", bad[i].restart, NULL, NULL, 3, NULL};
    t = NULL;
    rc = rc ? rc : whirl_auto_constants_runfile(ac, &ob, &t);
    ok(rc == WHIRL_EINVAL && !t && !strcmp(whirl_auto_constants_errmsg(ac), bad[i].msg),
       "refused: %s (got '%s')", bad[i].msg, whirl_auto_constants_errmsg(ac));
    whirl_auto_constants_free(ac);
  }
}

/* ---- the demos' own files ---------------------------------------------- */

static char demos[1200];

/* AUTO_07P_DIR/demos, else $top_srcdir/../shared/auto-07p/demos; 0 if absent. */
static int find_demos(void) {
  const char *d = getenv("AUTO_07P_DIR"), *top = getenv("top_srcdir");
  if (d && *d) snprintf(demos, sizeof demos, "%s/demos", d);
  else snprintf(demos, sizeof demos, "%s/../shared/auto-07p/demos", top && *top ? top : ".");
  DIR *dir = opendir(demos);
  if (!dir) return 0;
  closedir(dir);
  return 1;
}

static whirl_auto_constants *demo_file(const char *rel) {
  char path[1400];
  snprintf(path, sizeof path, "%s/%s", demos, rel);
  whirl_auto_constants *ac = whirl_auto_constants_alloc();
  if (whirl_auto_constants_read(ac, path) != WHIRL_OK)
    printf("# %s\n", whirl_auto_constants_errmsg(ac));
  return ac;
}

static size_t ntranslated, nrunfile_bad;

/* A demo file of IPS 1 or 2 without dat, as a run file: whirl's parser
 * must read it. */
static void translate_demo(whirl_auto_constants *ac) {
  int ips = 1, npar = 36;
  whirl_auto_constants_int(ac, "IPS", &ips);
  whirl_auto_constants_int(ac, "NPAR", &npar);
  if ((ips != 1 && ips != 2) || whirl_auto_constants_line(ac, "dat")) return;
  const whirl_auto_runfile_opts o = {"m.so", "r.out", NULL, "o.out", (size_t)npar, NULL};
  char *t = NULL;
  if (whirl_auto_constants_runfile(ac, &o, &t) != WHIRL_OK) {
    printf("# %s\n", whirl_auto_constants_errmsg(ac));
    return; /* refused with a message: not counted */
  }
  whirl_runfile *rf = whirl_runfile_alloc();
  ntranslated++;
  if (whirl_runfile_parse(rf, whirl_auto_constants_name(ac), t, strlen(t)) != WHIRL_OK) {
    printf("# %s\n", whirl_runfile_errmsg(rf));
    nrunfile_bad++;
  }
  whirl_runfile_free(rf);
  free(t);
}

/* Every c.* of one demo directory; the number of files, *bad those that fail. */
static size_t parse_demo(const char *name, size_t *bad) {
  char dirpath[1400];
  snprintf(dirpath, sizeof dirpath, "%s/%s", demos, name);
  DIR *dir = opendir(dirpath);
  size_t n = 0;
  for (struct dirent *e; dir && (e = readdir(dir));) {
    if (strncmp(e->d_name, "c.", 2)) continue;
    char rel[1400];
    snprintf(rel, sizeof rel, "%s/%s", name, e->d_name);
    whirl_auto_constants *ac = demo_file(rel);
    if (*whirl_auto_constants_errmsg(ac)) (*bad)++;
    else translate_demo(ac);
    whirl_auto_constants_free(ac);
    n++;
  }
  if (dir) closedir(dir);
  return n;
}

static void every_demo(void) {
  DIR *dir = opendir(demos);
  size_t files = 0, bad = 0, ndemos = 0;
  for (struct dirent *e; dir && (e = readdir(dir));) {
    if (e->d_name[0] == '.') continue;
    size_t b = 0, n = parse_demo(e->d_name, &b);
    if (n) ndemos++;
    files += n, bad += b;
  }
  if (dir) closedir(dir);
  ok(files >= 300 && bad == 0, "every c.* of the %zu demos parses: %zu files, %zu failed",
     ndemos, files, bad);
  ok(ntranslated >= 80 && nrunfile_bad == 0,
     "the %zu of IPS 1 or 2 translate into run files whirl's parser reads (%zu fail)",
     ntranslated, nrunfile_bad);
}

/* ab/c.ab.1: its text, copied by hand. */
static void demo_ab(void) {
  whirl_auto_constants *ac = demo_file("ab/c.ab.1");
  ok(int_is(ac, "NDIM", 2) && int_is(ac, "IPS", 1) && int_is(ac, "IRS", 0) &&
         int_is(ac, "ILP", 1) && int_is(ac, "NTST", 50) && int_is(ac, "NCOL", 4) &&
         int_is(ac, "IAD", 3) && int_is(ac, "ISP", 1) && int_is(ac, "ISW", 1) &&
         int_is(ac, "IPLT", 0) && int_is(ac, "NBC", 0) && int_is(ac, "NINT", 0),
     "ab/c.ab.1 lines 1, 3");
  ok(int_is(ac, "NMX", 200) && int_is(ac, "NPR", 200) && int_is(ac, "MXBF", 10) &&
         int_is(ac, "IID", 2) && int_is(ac, "ITMX", 8) && int_is(ac, "ITNW", 5) &&
         int_is(ac, "NWTN", 3) && int_is(ac, "JAC", 0) && int_is(ac, "NPAR", 3) &&
         int_is(ac, "IADS", 1),
     "ab/c.ab.1 lines 4, 7");
  ok(real_is(ac, "EPSL", 1e-7) && real_is(ac, "EPSU", 1e-7) && real_is(ac, "EPSS", 1e-5) &&
         real_is(ac, "DS", 0.1) && real_is(ac, "DSMIN", 0.001) && real_is(ac, "DSMAX", 0.2),
     "ab/c.ab.1 lines 5, 6");
  ok(whirl_auto_constants_count(ac, "ICP") == 1 && ref_is(ac, "ICP", 0, 2, NULL) &&
         indexed_is(ac, "THL", 0, 11, NULL, (double[]){0}, 1) &&
         whirl_auto_constants_count(ac, "THU") == 0 &&
         indexed_is(ac, "UZR", 0, 2, NULL, (double[]){14, 15, 16, 17}, 4) &&
         indexed_is(ac, "UZSTOP", 0, 2, NULL, (double[]){18}, 1) &&
         whirl_auto_constants_line(ac, "UZSTOP") == 9 && whirl_auto_constants_nkeys(ac) == 33,
     "ab/c.ab.1 ICP, THL, THU, UZR, UZSTOP; 33 keys");
  whirl_auto_constants_free(ac);
}

/* pla/c.pla.3 (IRS = HB2), pcl/c.pcl.5 (names over two lines), pp2/c.pp2
 * (comments, blank lines, names as UZSTOP indices). */
static void demo_others(void) {
  whirl_auto_constants *ac = demo_file("pla/c.pla.3");
  ok(text_is(ac, "IRS", "HB2") && real_is(ac, "EPSS", 1e-4) && real_is(ac, "DS", -0.1) &&
         indexed_is(ac, "UZR", 0, 1, NULL, (double[]){1.25, 1.5, 1.75, 2.1, 2.62}, 5) &&
         indexed_is(ac, "UZSTOP", 0, 11, NULL, (double[]){50000}, 1) && int_is(ac, "ITMX", 12),
     "pla/c.pla.3: IRS = HB2, EPSS =0.0001, UZR, UZSTOP");
  whirl_auto_constants_free(ac);
  ac = demo_file("pcl/c.pcl.5");
  ok(whirl_auto_constants_count(ac, "unames") == 9 && name_is(ac, "unames", 6, 7, "x+") &&
         name_is(ac, "parnames", 7, 21, "sigma+") && text_is(ac, "IRS", "UZ1") &&
         ref_is(ac, "ICP", 0, 0, "T+") && ref_is(ac, "ICP", 3, 0, "sigma+") &&
         indexed_is(ac, "UZSTOP", 0, 0, "sigma+", (double[]){0}, 1) &&
         int_is(ac, "NMX", 99999) && real_is(ac, "DSMAX", 100) &&
         whirl_auto_constants_line(ac, "NDIM") == 5,
     "pcl/c.pcl.5: unames and parnames over two lines, names in ICP and UZSTOP");
  whirl_auto_constants_free(ac);
  ac = demo_file("pp2/c.pp2");
  ok(int_is(ac, "NDIM", 2) && name_is(ac, "parnames", 1, 9, "fish") &&
         indexed_is(ac, "UZSTOP", 0, 0, "quota", (double[]){0, 1}, 2) &&
         indexed_is(ac, "UZSTOP", 1, 0, "fish", (double[]){-0.25}, 1) &&
         int_is(ac, "NMX", 100) && whirl_auto_constants_line(ac, "NMX") == 17 &&
         real_is(ac, "DSMIN", 0.01),
     "pp2/c.pp2: comments, blank lines, UZSTOP by names");
  whirl_auto_constants_free(ac);
}

/* ---- --dump: what was read, one key a line ------------------------------
 * KEY<TAB>value: integers %d, reals %.17g, texts 'quoted', lists
 * [1, 'name'], indexed {1: 0.5, 'name': [1, 2]}, names {1: 'x'}. */
static void dump_ref(const whirl_auto_item *it) {
  if (it->name) printf("'%s'", it->name);
  else printf("%d", it->index);
}

static void dump_item(whirl_auto_kind kind, const whirl_auto_item *it) {
  dump_ref(it);
  if (kind == WHIRL_AC_NAMES) printf(": '%s'", it->text);
  if (kind != WHIRL_AC_INDEXED) return;
  printf(": %s", it->is_list ? "[" : "");
  for (size_t j = 0; j < it->nvalues; j++) printf("%s%.17g", j ? ", " : "", it->values[j]);
  printf("%s", it->is_list ? "]" : "");
}

static void dump_key(const whirl_auto_constants *ac, const char *k) {
  const whirl_auto_kind kind = whirl_auto_constants_kind(ac, k);
  int i;
  double x;
  printf("%s\t", k);
  if (whirl_auto_constants_int(ac, k, &i) == WHIRL_OK) printf("%d", i);
  else if (whirl_auto_constants_real(ac, k, &x) == WHIRL_OK) printf("%.17g", x);
  else if (kind == WHIRL_AC_TEXT) printf("'%s'", whirl_auto_constants_text(ac, k));
  else {
    const int list = kind == WHIRL_AC_LIST;
    printf("%c", list ? '[' : '{');
    for (size_t j = 0; j < whirl_auto_constants_count(ac, k); j++) {
      whirl_auto_item it;
      whirl_auto_constants_item(ac, k, j, &it);
      printf("%s", j ? ", " : "");
      dump_item(kind, &it);
    }
    printf("%c", list ? ']' : '}');
  }
  printf("\n");
}

static int dump(int argc, char **argv) {
  int status = 0;
  for (int a = 2; a < argc; a++) {
    whirl_auto_constants *ac = whirl_auto_constants_alloc();
    printf("== %s\n", argv[a]);
    if (whirl_auto_constants_read(ac, argv[a]) != WHIRL_OK) {
      printf("error\t%s\n", whirl_auto_constants_errmsg(ac));
      status = 1;
    }
    for (size_t i = 0; i < whirl_auto_constants_nkeys(ac); i++)
      dump_key(ac, whirl_auto_constants_key(ac, i));
    whirl_auto_constants_free(ac);
  }
  return status;
}

int main(int argc, char **argv) {
  if (argc > 1 && !strcmp(argv[1], "--dump")) return dump(argc, argv);
  syntax();
  errors();
  runfile();
  if (!find_demos()) {
    printf("# SKIP the demos: %s not found (set AUTO_07P_DIR)\n", demos);
  } else {
    every_demo();
    demo_ab();
    demo_others();
  }
  return done_testing();
}

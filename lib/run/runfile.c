/* lib/run/runfile.c — parser of run files (whirl/runfile.h): `key = value`
 * lines with AUTO-07p's constant names (AUTO-07p manual, ch. 10 "Description
 * of AUTO-constants") and readable aliases, typed and range-checked per key,
 * every error with the file and line.  Pure text processing: no model, no
 * allocation after whirl_runfile_alloc, no output; safe on any input (the
 * fuzz target test/fuzz/fuzz_runfile.c feeds it arbitrary bytes).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <whirl/ode.h>

#include "runfile_impl.h"

/* ---- the key table ----------------------------------------------------- */

typedef enum {
  K_STRING, K_INT, K_REAL, K_IPS, K_METHOD, K_REFLIST, K_VALDICT, K_UZDICT,
  K_IRS, K_RANGES, K_GRID, K_INTLIST, K_REALLIST, K_STOPLIST, K_IGNORED
} key_kind;

typedef struct key_def {
  whirl_run_key key;
  const char *name;  /* AUTO's name (or whirl's, upper case) */
  const char *alias; /* readable long name */
  const char *alias2;
  key_kind kind;
} key_def;

static const key_def keys[] = {
    {WHIRL_RK_MODEL, "MODEL", "e", NULL, K_STRING},
    {WHIRL_RK_NDIM, "NDIM", "dimension", NULL, K_INT},
    {WHIRL_RK_IPS, "IPS", "problem", NULL, K_IPS},
    {WHIRL_RK_METHOD, "METHOD", "periodic_method", NULL, K_METHOD},
    {WHIRL_RK_ICP, "ICP", "continuation_parameters", NULL, K_REFLIST},
    {WHIRL_RK_PAR, "PAR", "parameters", NULL, K_VALDICT},
    {WHIRL_RK_U, "U", "start", NULL, K_VALDICT},
    {WHIRL_RK_ILP, "ILP", "detect_folds", NULL, K_INT},
    {WHIRL_RK_ISP, "ISP", "detect_bifurcations", NULL, K_INT},
    {WHIRL_RK_ISW, "ISW", "switch", NULL, K_INT},
    {WHIRL_RK_IRS, "IRS", "restart_label", NULL, K_IRS},
    {WHIRL_RK_S, "S", "restart_from", NULL, K_STRING},
    {WHIRL_RK_NTST, "NTST", "mesh_intervals", NULL, K_INT},
    {WHIRL_RK_NCOL, "NCOL", "collocation_points", NULL, K_INT},
    {WHIRL_RK_IAD, "IAD", "adapt_mesh", NULL, K_INT},
    {WHIRL_RK_NHB, "NHB", "harmonics", NULL, K_INT},
    {WHIRL_RK_OVERSAMPLING, "OVERSAMPLING", "hbm_oversampling", NULL, K_INT},
    {WHIRL_RK_DS, "DS", "step", NULL, K_REAL},
    {WHIRL_RK_DSMIN, "DSMIN", "step_min", NULL, K_REAL},
    {WHIRL_RK_DSMAX, "DSMAX", "step_max", NULL, K_REAL},
    {WHIRL_RK_NMX, "NMX", "max_steps", NULL, K_INT},
    {WHIRL_RK_NPR, "NPR", "label_every", NULL, K_INT},
    {WHIRL_RK_RL0, "RL0", "par_min", NULL, K_REAL},
    {WHIRL_RK_RL1, "RL1", "par_max", NULL, K_REAL},
    {WHIRL_RK_A0, "A0", "norm_min", NULL, K_REAL},
    {WHIRL_RK_A1, "A1", "norm_max", NULL, K_REAL},
    {WHIRL_RK_EPSL, "EPSL", "tol_par", NULL, K_REAL},
    {WHIRL_RK_EPSU, "EPSU", "tol_state", NULL, K_REAL},
    {WHIRL_RK_EPSS, "EPSS", "tol_special", NULL, K_REAL},
    {WHIRL_RK_ITNW, "ITNW", "newton_max_iterations", NULL, K_INT},
    {WHIRL_RK_JAC, "JAC", "analytic_jacobian", NULL, K_INT},
    {WHIRL_RK_UZR, "UZR", "user_points", NULL, K_UZDICT},
    {WHIRL_RK_UZSTOP, "UZSTOP", "stop_at", NULL, K_UZDICT},
    {WHIRL_RK_OUT, "OUT", "output", "sv", K_STRING},
    {WHIRL_RK_PLOT, "PLOT", "plot_y", NULL, K_STRING},
    {WHIRL_RK_BASIN_AXES, "BASIN_AXES", "basin_axes", NULL, K_RANGES},
    {WHIRL_RK_BASIN_GRID, "BASIN_GRID", "basin_grid", NULL, K_GRID},
    {WHIRL_RK_BASIN_PERIODS, "BASIN_PERIODS", "basin_periods", NULL, K_INT},
    {WHIRL_RK_BASIN_ATTRACTORS, "BASIN_ATTRACTORS", "attractors", NULL,
     K_INTLIST},
    {WHIRL_RK_BASIN_TOL, "BASIN_TOL", "basin_tol", NULL, K_REAL},
    {WHIRL_RK_DISCOVER, "DISCOVER", "discover_at", NULL, K_REALLIST},
    {WHIRL_RK_DISCOVER_BOX, "DISCOVER_BOX", "discover_box", NULL, K_RANGES},
    {WHIRL_RK_DISCOVER_STARTS, "DISCOVER_STARTS", "discover_starts", NULL, K_INT},
    {WHIRL_RK_DISCOVER_SEED, "DISCOVER_SEED", "discover_seed", NULL, K_INT},
    {WHIRL_RK_DISCOVER_SETTLE, "DISCOVER_SETTLE", "discover_settle", NULL, K_REAL},
    {WHIRL_RK_STUDY, "STUDY", "parameter_study", NULL, K_UZDICT},
    {WHIRL_RK_IPLT, "IPLT", "plot_measure", NULL, K_INT},
    {WHIRL_RK_DAT, "DAT", "start_data", NULL, K_STRING},
    {WHIRL_RK_POINTS, "POINTS", "study_points", NULL, K_STRING},
    {WHIRL_RK_BASIN_SEEDS, "BASIN_SEEDS", "basin_seeds", NULL, K_INT},
    {WHIRL_RK_BASIN_METHOD, "BASIN_METHOD", "basin_method", NULL, K_METHOD},
    {WHIRL_RK_THL, "THL", "parameter_weights", NULL, K_VALDICT},
    {WHIRL_RK_THU, "THU", "state_weights", NULL, K_VALDICT},
    {WHIRL_RK_STOP, "STOP", "stop_at_points", NULL, K_STOPLIST},
    {WHIRL_RK_NBC, "NBC", "boundary_conditions", NULL, K_INT},
    {WHIRL_RK_NINT, "NINT", "integral_conditions", NULL, K_INT},
    {WHIRL_RK_ORBIT_MAX, "ORBIT_MAX", "orbit_max", NULL, K_METHOD},
    {WHIRL_RK_MESH_RULE, "MESH_RULE", "mesh_rule", NULL, K_METHOD},
    {WHIRL_RK_EQ_STEP, "EQ_STEP", "eq_step", NULL, K_METHOD},
    {WHIRL_RK_DIFFERENCES, "DIFFERENCES", "differences", NULL, K_METHOD},
    {WHIRL_RK_UDOT, "UDOT", "udot", NULL, K_METHOD},
    {WHIRL_RK_TANGENT, "TANGENT", "tangent", NULL, K_METHOD},
    {WHIRL_RK_MX, "MX", "no_convergence", NULL, K_METHOD},
    {WHIRL_RK_THREADS, "THREADS", "threads", NULL, K_INT},
    {WHIRL_RK_NWTN, "NWTN", "newton_full_iterations", NULL, K_INT},
    {WHIRL_RK_HB_PERIOD, "HB_PERIOD", "hopf_period", NULL, K_STRING},
    {WHIRL_RK_LOCATE, "LOCATE", "locate", NULL, K_METHOD},
    {WHIRL_RK_ITMX, "ITMX", "locate_iterations", NULL, K_INT},
    {WHIRL_RK_PHASE, "PHASE", "phase_condition", NULL, K_METHOD},
};
#define NKEYS (sizeof keys / sizeof keys[0])

/* AUTO constants that whirl accepts for compatibility and ignores (each
 * noted in the run's log): they control output, AUTO's own iteration
 * details. */
static const char *const ignored_keys[] = {
    "IID", "MXBF", "IADS",
    "NTHL", "NTHU", "NUZR", "NPAR", "SP", "UNAMES",
    "PARNAMES", "NUNSTAB", "NSTAB", "IIS", "IBR", "LAB", "TY", "EFILE",
    "SFILE", "NPRM", "DATFILE"};
#define NIGNORED (sizeof ignored_keys / sizeof ignored_keys[0])

/* ---- the object --------------------------------------------------------- */

#define MAXITEMS 256
#define ITEMLEN 160

typedef struct item {
  char text[ITEMLEN];
  int quoted;
  int group; /* dictionary entry (0-based), -1 outside dictionaries */
  char key[ITEMLEN];
} item;

typedef enum { V_SCALAR, V_LIST, V_DICT } vkind;

typedef struct pvalue {
  vkind kind;
  size_t n, ngroups;
  item it[MAXITEMS];
} pvalue;

struct whirl_runfile {
  char name[WHIRL_RUN_MAXPATH];
  whirl_run_settings s;
  int line[WHIRL_RK_COUNT];           /* > 0 file line, -1 command line */
  char cmd[WHIRL_RK_COUNT][96];       /* the override text, truncated */
  int nlines;
  int parsed;
  char ignored[256];
  char err[1536];
  pvalue v;                           /* scratch */
  char raw[WHIRL_RUN_MAXPATH + 64];   /* scratch: a string value */
};

static void set_defaults(whirl_run_settings *s) {
  memset(s, 0, sizeof *s);
  s->ips = WHIRL_IPS_EQUILIBRIA;
  s->method = WHIRL_METHOD_COLLOC;
  s->ilp = 1;
  s->isp = 2;
  s->isw = 1;
  s->ntst = 20;
  s->ncol = 4;
  s->iad = 3;
  s->nhb = 8;
  s->oversampling = 4;
  s->ds = 0.01;
  s->dsmin = 1e-5;
  s->dsmax = 0.1;
  s->nmx = 200;
  s->npr = 0;
  s->rl0 = -1e30;
  s->rl1 = 1e30;
  s->a0 = 0.0;
  s->a1 = 1e30;
  s->epsl = 1e-7;
  s->epsu = 1e-7;
  s->epss = 1e-5;
  s->itnw = 8;
  s->itmx = 8;
  s->jac = 1;
  s->grid[0] = s->grid[1] = 41;
  s->basin_periods = 500;
  s->basin_method = WHIRL_ODE_DOP853;
  s->basin_tol = 1e-3;
  s->discover_starts = 40;
  s->discover_seed = 1;
  s->discover_settle = 100.0;
}

whirl_runfile *whirl_runfile_alloc(void) {
  whirl_runfile *rf = calloc(1, sizeof *rf);
  if (!rf) return NULL;
  set_defaults(&rf->s);
  return rf;
}

void whirl_runfile_free(whirl_runfile *rf) { free(rf); }

const whirl_run_settings *whirl_runfile_settings(const whirl_runfile *rf) {
  return &rf->s;
}
const char *whirl_runfile_errmsg(const whirl_runfile *rf) { return rf->err; }
const char *whirl_runfile_name(const whirl_runfile *rf) { return rf->name; }
const char *whirl_runfile_ignored(const whirl_runfile *rf) {
  return rf->ignored;
}
int whirl_runfile_given(const whirl_runfile *rf, whirl_run_key k) {
  return k >= 0 && k < WHIRL_RK_COUNT && rf->line[k] != 0;
}
int whirl_runfile_on_command_line(const whirl_runfile *rf, whirl_run_key k) {
  return k >= 0 && k < WHIRL_RK_COUNT && rf->line[k] < 0;
}

const char *whirl_run_key_name(whirl_run_key k) {
  for (size_t i = 0; i < NKEYS; i++)
    if (keys[i].key == k) return keys[i].name;
  return "?";
}

const char *whirl_runfile_where(const whirl_runfile *rf, whirl_run_key k,
                                char *buf, size_t len) {
  if (k < 0 || k >= WHIRL_RK_COUNT || rf->line[k] == 0)
    snprintf(buf, len, "%s", rf->name);
  else if (rf->line[k] < 0)
    snprintf(buf, len, "command line (%s)", rf->cmd[k]);
  else
    snprintf(buf, len, "%s:%d", rf->name, rf->line[k]);
  return buf;
}

/* ---- messages ----------------------------------------------------------- */

/* where: "FILE:LINE" or "command line (...)"; the message follows. */
static int fail(whirl_runfile *rf, const char *where, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int fail(whirl_runfile *rf, const char *where, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  whirl_errmsg_vat(rf->err, sizeof rf->err, WHIRL_EINVAL, where, fmt, ap);
  va_end(ap);
  return WHIRL_EINVAL;
}

/* A short printable rendering of untrusted text for messages: control and
 * non-ASCII bytes become '?', long text is cut with "...". */
static const char *show(const char *s, size_t n, char *buf, size_t len) {
  size_t j = 0;
  for (size_t i = 0; i < n && s[i] && j + 4 < len; i++) {
    unsigned char c = (unsigned char)s[i];
    buf[j++] = (c >= 32 && c < 127) ? (char)c : '?';
    if (j >= 48 && i + 1 < n && s[i + 1]) {
      memcpy(buf + j, "...", 3);
      j += 3;
      break;
    }
  }
  buf[j] = '\0';
  return buf;
}

/* ---- lexing a value ----------------------------------------------------- */

typedef enum { T_WORD, T_LBRACK, T_RBRACK, T_LBRACE, T_RBRACE, T_COLON,
               T_COMMA, T_END } tok_kind;

typedef struct lexer {
  const char *p, *end;
} lexer;

static int is_delim(char c) {
  return c == ' ' || c == '\t' || c == ',' || c == '[' || c == ']' ||
         c == '{' || c == '}' || c == ':' || c == '\'' || c == '"';
}

/* Next token; a word is copied into w[ITEMLEN] with *quoted set.  Returns
 * the kind, or -1 with msg set on an unterminated quote or a long word. */
static int lex(lexer *L, char *w, int *quoted, const char **msg) {
  while (L->p < L->end && (*L->p == ' ' || *L->p == '\t')) L->p++;
  if (L->p >= L->end) return T_END;
  char c = *L->p;
  switch (c) {
    case '[': L->p++; return T_LBRACK;
    case ']': L->p++; return T_RBRACK;
    case '{': L->p++; return T_LBRACE;
    case '}': L->p++; return T_RBRACE;
    case ':': L->p++; return T_COLON;
    case ',': L->p++; return T_COMMA;
    default: break;
  }
  size_t n = 0;
  *quoted = 0;
  if (c == '\'' || c == '"') {
    const char *q = L->p + 1;
    while (q < L->end && *q != c) q++;
    if (q >= L->end) {
      *msg = "unterminated quoted string";
      return -1;
    }
    n = (size_t)(q - (L->p + 1));
    if (n >= ITEMLEN) {
      *msg = "quoted string too long";
      return -1;
    }
    memcpy(w, L->p + 1, n);
    L->p = q + 1;
    *quoted = 1;
  } else {
    const char *q = L->p;
    while (q < L->end && !is_delim(*q)) q++;
    n = (size_t)(q - L->p);
    if (n >= ITEMLEN) {
      *msg = "value too long";
      return -1;
    }
    memcpy(w, L->p, n);
    L->p = q;
  }
  w[n] = '\0';
  return T_WORD;
}

static int push(pvalue *v, const char *w, int quoted, int group,
                const char *key, const char **msg) {
  if (v->n >= MAXITEMS) {
    *msg = "too many items (at most 256)";
    return -1;
  }
  item *it = &v->it[v->n++];
  snprintf(it->text, sizeof it->text, "%s", w);
  it->quoted = quoted;
  it->group = group;
  snprintf(it->key, sizeof it->key, "%s", key ? key : "");
  return 0;
}

/* Items of a bracketed list after '[' up to ']' (commas or blanks between
 * items), or of a bare list up to the end (closing = T_END). */
static int parse_items(lexer *L, pvalue *v, int closing, int group,
                       const char *key, const char **msg) {
  char w[ITEMLEN];
  int quoted = 0, need_item = 0;
  for (;;) {
    int t = lex(L, w, &quoted, msg);
    if (t < 0) return -1;
    if (t == closing) {
      if (need_item) {
        *msg = "a value is missing after ','";
        return -1;
      }
      return 0;
    }
    if (t == T_WORD) {
      if (push(v, w, quoted, group, key, msg)) return -1;
      need_item = 0;
    } else if (t == T_COMMA) {
      if (need_item || v->n == 0) {
        *msg = "',' without a value before it";
        return -1;
      }
      need_item = 1;
    } else if (t == T_END) {
      *msg = "']' missing";
      return -1;
    } else {
      *msg = closing == T_RBRACK ? "unexpected character in a list"
                                 : "unexpected bracket or ':' (a list is "
                                   "written [a, b], a dictionary {k: v})";
      return -1;
    }
  }
}

static int parse_value(const char *s, size_t n, pvalue *v, const char **msg) {
  lexer L = {s, s + n};
  char w[ITEMLEN];
  int quoted = 0;
  v->n = v->ngroups = 0;
  const char *save = L.p;
  int t = lex(&L, w, &quoted, msg);
  if (t < 0) return -1;
  if (t == T_END) {
    *msg = "no value after '='";
    return -1;
  }
  if (t == T_LBRACE) {
    v->kind = V_DICT;
    for (;;) {
      t = lex(&L, w, &quoted, msg);
      if (t < 0) return -1;
      if (t == T_RBRACE && v->ngroups == 0) break; /* {} */
      if (t != T_WORD) {
        *msg = t == T_END ? "'}' missing" : "a dictionary key is missing";
        return -1;
      }
      char key[ITEMLEN];
      memcpy(key, w, sizeof key);
      t = lex(&L, w, &quoted, msg);
      if (t < 0) return -1;
      if (t != T_COLON) {
        *msg = "':' missing after a dictionary key";
        return -1;
      }
      int g = (int)v->ngroups++;
      size_t before = v->n;
      t = lex(&L, w, &quoted, msg);
      if (t < 0) return -1;
      if (t == T_WORD) {
        if (push(v, w, quoted, g, key, msg)) return -1;
      } else if (t == T_LBRACK) {
        if (parse_items(&L, v, T_RBRACK, g, key, msg)) return -1;
        if (v->n == before) {
          *msg = "empty list as a dictionary value";
          return -1;
        }
      } else {
        *msg = "a dictionary value is missing";
        return -1;
      }
      t = lex(&L, w, &quoted, msg);
      if (t < 0) return -1;
      if (t == T_RBRACE) break;
      if (t != T_COMMA) {
        *msg = t == T_END ? "'}' missing" : "',' or '}' expected";
        return -1;
      }
    }
  } else if (t == T_LBRACK) {
    v->kind = V_LIST;
    if (parse_items(&L, v, T_RBRACK, -1, NULL, msg)) return -1;
  } else if (t == T_WORD) {
    L.p = save;
    if (parse_items(&L, v, T_END, -1, NULL, msg)) return -1;
    v->kind = v->n == 1 ? V_SCALAR : V_LIST;
    return 0;
  } else {
    *msg = "a value cannot start with ']', '}', ':' or ','";
    return -1;
  }
  t = lex(&L, w, &quoted, msg);
  if (t < 0) return -1;
  if (t != T_END) {
    *msg = "unexpected text after the closing bracket";
    return -1;
  }
  return 0;
}

/* The first dictionary key written twice ({B: 1, B: 2}), or NULL. */
static const char *dup_key(const pvalue *v) {
  if (v->kind != V_DICT) return NULL;
  for (size_t i = 1; i < v->n; i++)
    for (size_t j = 0; j < i; j++)
      if (v->it[j].group != v->it[i].group && !strcmp(v->it[j].key, v->it[i].key))
        return v->it[i].key;
  return NULL;
}

/* parse_value for key kn, and no key twice in a dictionary; WHIRL_OK or the
 * error. */
static int parse_checked(whirl_runfile *rf, const char *where, const char *kn,
                         const char *text, size_t n) {
  const char *msg, *dup;
  char shown[64];
  if (parse_value(text, n, &rf->v, &msg)) return fail(rf, where, "%s: %s", kn, msg);
  if ((dup = dup_key(&rf->v)))
    return fail(rf, where, "%s: key '%s' given twice", kn,
                show(dup, ITEMLEN, shown, sizeof shown));
  return WHIRL_OK;
}

/* ---- typed conversion --------------------------------------------------- */

/* Length of the decimal number at s as AUTO reads one: an optional sign,
 * digits with an optional point (at least one digit), an optional exponent
 * (e or E, optional sign, digits); 0 if there is none. */
static size_t decimal_len(const char *s) {
  size_t i = 0, digits = 0;
  if (s[i] == '+' || s[i] == '-') i++;
  while (isdigit((unsigned char)s[i])) i++, digits++;
  if (s[i] == '.') {
    i++;
    while (isdigit((unsigned char)s[i])) i++, digits++;
  }
  if (!digits) return 0;
  if (s[i] == 'e' || s[i] == 'E') {
    size_t j = i + 1;
    if (s[j] == '+' || s[j] == '-') j++;
    if (!isdigit((unsigned char)s[j])) return 0;
    while (isdigit((unsigned char)s[j])) j++;
    i = j;
  }
  return i;
}

int whirl_run_number(const char *s, double *x) {
  if (!s || !x) return WHIRL_EINVAL;
  if (!strcasecmp(s, "nan") || !strcasecmp(s, "inf") ||
      !strcasecmp(s, "infinity") || ((s[0] == '+' || s[0] == '-') &&
                                     (!strcasecmp(s + 1, "inf") ||
                                      !strcasecmp(s + 1, "infinity"))))
    return WHIRL_EDOMAIN;
  const size_t n = decimal_len(s);
  if (!n || s[n]) return WHIRL_EINVAL;
  double v = strtod(s, NULL); /* an underflow gives a denormal or 0: fine */
  if (!isfinite(v)) return WHIRL_EDOMAIN;
  *x = v;
  return WHIRL_OK;
}

static int to_double(const char *s, double *x) {
  return whirl_run_number(s, x) == WHIRL_OK ? 0 : -1;
}

/* An integer: digits with an optional sign, or an exact integral decimal
 * ("1e3", "2.0"), within +-INT_MAX / 2. */
static int to_int(const char *s, int *x) {
  double d;
  if (to_double(s, &d) || d != floor(d) || fabs(d) > INT_MAX / 2) return -1;
  *x = (int)d;
  return 0;
}

/* A parameter/state reference: a positive index or a name (letters,
 * digits, '_', '.', '(', ')', '-' and '+', not starting with a digit). */
static int to_ref(const item *it, whirl_run_ref *r, const char **msg) {
  const char *s = it->text;
  int k;
  memset(r, 0, sizeof *r);
  if (!it->quoted && isdigit((unsigned char)s[0])) {
    if (to_int(s, &k) || k < 1) {
      *msg = "is not a positive index or a name";
      return -1;
    }
    r->index = k;
    return 0;
  }
  if (!*s) {
    *msg = "is an empty name";
    return -1;
  }
  if (strlen(s) >= WHIRL_RUN_MAXNAME) {
    *msg = "is too long for a name";
    return -1;
  }
  for (const char *q = s; *q; q++) {
    unsigned char c = (unsigned char)*q;
    if (!(isalnum(c) || c == '_' || c == '.' || c == '(' || c == ')' ||
          c == '-' || c == '+' || c == '^' || c == '/')) {
      *msg = "is not a valid name";
      return -1;
    }
  }
  memcpy(r->name, s, strlen(s) + 1); /* shorter than the buffer: checked above */
  return 0;
}

/* Range checks of numeric keys: NULL if fine, else the reason. */
static const char *check_real(whirl_run_key k, double x) {
  switch (k) {
    case WHIRL_RK_DS: return x == 0.0 ? "must not be 0" : NULL;
    case WHIRL_RK_DSMIN:
    case WHIRL_RK_DSMAX:
    case WHIRL_RK_EPSL:
    case WHIRL_RK_EPSU:
    case WHIRL_RK_EPSS:
    case WHIRL_RK_BASIN_TOL: return x <= 0.0 ? "must be > 0" : NULL;
    case WHIRL_RK_DISCOVER_SETTLE: return x < 0.0 ? "must be >= 0 (0: no time integration)" : NULL;
    case WHIRL_RK_A0: return NULL; /* any (under IPLT the measure may be negative) */
    case WHIRL_RK_A1: return NULL; /* any above A0 (checked with it) */
    default: return NULL;
  }
}

static const char *check_int(whirl_run_key k, int x) {
  switch (k) {
    case WHIRL_RK_NDIM: return x < 1 ? "must be >= 1" : NULL;
    case WHIRL_RK_ILP: return x != 0 && x != 1 ? "must be 0 or 1" : NULL;
    case WHIRL_RK_ISP:
      return x < 0 || x > 4 ? "must be 0, 1, 2, 3 or 4 (AUTO-07p's ISP)" : NULL;
    case WHIRL_RK_ISW:
      return x != 1 && x != -1 && x != 2 && x != 3
                 ? "must be 1 (same branch), -1 (switch at BP/PD), 2 "
                   "(two-parameter continuation from LP/HB/PD/TR, or a symmetric BP) "
                   "or 3 (a generic BP's locus in three parameters)"
                 : NULL;
    case WHIRL_RK_NTST: return x < 2 || x > 100000 ? "must be in [2, 100000]" : NULL;
    case WHIRL_RK_NCOL: return x < 2 || x > 7 ? "must be in [2, 7]" : NULL;
    case WHIRL_RK_IAD: return x < 0 ? "must be >= 0" : NULL;
    case WHIRL_RK_NHB: return x < 1 || x > 1000 ? "must be in [1, 1000]" : NULL;
    case WHIRL_RK_OVERSAMPLING: return x < 2 || x > 64 ? "must be in [2, 64]" : NULL;
    case WHIRL_RK_NMX: return x < 1 ? "must be >= 1" : NULL;
    case WHIRL_RK_THREADS:
      return x < 0 || x > 256 ? "must be in [0, 256] (0: as many as OpenMP offers)" : NULL;
    case WHIRL_RK_NPR: return x < 0 ? "must be >= 0" : NULL;
    case WHIRL_RK_ITNW: return x < 1 || x > 1000 ? "must be in [1, 1000]" : NULL;
    case WHIRL_RK_ITMX: return x < 0 || x > 1000 ? "must be in [0, 1000]" : NULL;
    case WHIRL_RK_NWTN: return x < 0 || x > 1000 ? "must be in [0, 1000] (0: a new Jacobian at every iteration)" : NULL;
    case WHIRL_RK_JAC:
      /* AUTO-07p documents 0 and 1 only */
      return x != 0 && x != 1 ? "must be 0 (finite differences) or 1 (the "
                                "model's Jacobian)"
                              : NULL;
    case WHIRL_RK_BASIN_PERIODS: return x < 1 ? "must be >= 1" : NULL;
    case WHIRL_RK_BASIN_SEEDS: return x < 0 ? "must be >= 0 (0: no atlas)" : NULL;
    case WHIRL_RK_DISCOVER_STARTS:
      return x < 1 || x > 1000000 ? "must be in [1, 1000000] (the starts tried at each sample value)" : NULL;
    case WHIRL_RK_DISCOVER_SEED: return x < 0 ? "must be >= 0" : NULL;
    case WHIRL_RK_NBC:
    case WHIRL_RK_NINT: return x < 0 || x > 1000 ? "must be in [0, 1000]" : NULL;
    default: return NULL;
  }
}

static int *int_field(whirl_run_settings *s, whirl_run_key k) {
  switch (k) {
    case WHIRL_RK_NDIM: return &s->ndim;
    case WHIRL_RK_ILP: return &s->ilp;
    case WHIRL_RK_ISP: return &s->isp;
    case WHIRL_RK_ISW: return &s->isw;
    case WHIRL_RK_NTST: return &s->ntst;
    case WHIRL_RK_NCOL: return &s->ncol;
    case WHIRL_RK_IAD: return &s->iad;
    case WHIRL_RK_NHB: return &s->nhb;
    case WHIRL_RK_OVERSAMPLING: return &s->oversampling;
    case WHIRL_RK_NMX: return &s->nmx;
    case WHIRL_RK_NPR: return &s->npr;
    case WHIRL_RK_IPLT: return &s->iplt;
    case WHIRL_RK_NBC: return &s->nbc;
    case WHIRL_RK_NINT: return &s->nint;
    case WHIRL_RK_ITNW: return &s->itnw;
    case WHIRL_RK_JAC: return &s->jac;
    case WHIRL_RK_BASIN_PERIODS: return &s->basin_periods;
    case WHIRL_RK_BASIN_SEEDS: return &s->basin_seeds;
    case WHIRL_RK_BASIN_METHOD: return &s->basin_method;
    case WHIRL_RK_ORBIT_MAX: return &s->orbit_max_nodes;
    case WHIRL_RK_MESH_RULE: return &s->mesh_jumps;
    case WHIRL_RK_EQ_STEP: return &s->eq_sphere;
    case WHIRL_RK_DIFFERENCES: return &s->auto_differences;
    case WHIRL_RK_UDOT: return &s->udot_direction;
    case WHIRL_RK_TANGENT: return &s->tangent_iterate;
    case WHIRL_RK_MX: return &s->mx_label;
    case WHIRL_RK_THREADS: return &s->threads;
    case WHIRL_RK_NWTN: return &s->nwtn;
    case WHIRL_RK_ITMX: return &s->itmx;
    case WHIRL_RK_LOCATE: return &s->locate_auto;
    case WHIRL_RK_PHASE: return &s->phase_nodes;
    case WHIRL_RK_DISCOVER_STARTS: return &s->discover_starts;
    case WHIRL_RK_DISCOVER_SEED: return &s->discover_seed;
    default: return NULL;
  }
}

static double *real_field(whirl_run_settings *s, whirl_run_key k) {
  switch (k) {
    case WHIRL_RK_DS: return &s->ds;
    case WHIRL_RK_DSMIN: return &s->dsmin;
    case WHIRL_RK_DSMAX: return &s->dsmax;
    case WHIRL_RK_RL0: return &s->rl0;
    case WHIRL_RK_RL1: return &s->rl1;
    case WHIRL_RK_A0: return &s->a0;
    case WHIRL_RK_A1: return &s->a1;
    case WHIRL_RK_EPSL: return &s->epsl;
    case WHIRL_RK_EPSU: return &s->epsu;
    case WHIRL_RK_EPSS: return &s->epss;
    case WHIRL_RK_BASIN_TOL: return &s->basin_tol;
    case WHIRL_RK_DISCOVER_SETTLE: return &s->discover_settle;
    default: return NULL;
  }
}

static char *string_field(whirl_run_settings *s, whirl_run_key k, size_t *len) {
  switch (k) {
    case WHIRL_RK_MODEL: *len = sizeof s->model; return s->model;
    case WHIRL_RK_OUT: *len = sizeof s->out; return s->out;
    case WHIRL_RK_S: *len = sizeof s->s; return s->s;
    case WHIRL_RK_DAT: *len = sizeof s->dat; return s->dat;
    case WHIRL_RK_HB_PERIOD: *len = sizeof s->hb_period; return s->hb_period;
    case WHIRL_RK_PLOT: *len = sizeof s->plot; return s->plot;
    case WHIRL_RK_POINTS: *len = sizeof s->points; return s->points;
    default: *len = 0; return NULL;
  }
}

/* INT and REAL keys: one number, checked against the key's range. */
static int set_number(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name;
  char shown[64];
  if (v->kind != V_SCALAR)
    return fail(rf, where, "%s: expected one number, got a %s", kn,
                v->kind == V_DICT ? "dictionary" : "list");
  const char *t = v->it[0].text;
  if (d->kind == K_INT) {
    int x;
    if (v->it[0].quoted || to_int(t, &x))
      return fail(rf, where, "%s: '%s' is not an integer", kn,
                  show(t, ITEMLEN, shown, sizeof shown));
    const char *why = check_int(d->key, x);
    if (why) return fail(rf, where, "%s = %d: %s", kn, x, why);
    *int_field(s, d->key) = x;
  } else {
    double x;
    if (v->it[0].quoted || to_double(t, &x))
      return fail(rf, where, "%s: '%s' is not a finite number", kn,
                  show(t, ITEMLEN, shown, sizeof shown));
    const char *why = check_real(d->key, x);
    if (why) return fail(rf, where, "%s = %s: %s", kn, t, why);
    *real_field(s, d->key) = x;
  }
  return WHIRL_OK;
}

/* IPS: 1 or equilibria, 2 or periodic, -1 or map, basins. */
static int set_ips(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name;
  char shown[64];
  if (v->kind != V_SCALAR)
    return fail(rf, where, "%s: expected one value", kn);
  const char *t = v->it[0].text;
  int x;
  if (!strcasecmp(t, "equilibria") || !strcasecmp(t, "EQ"))
    x = WHIRL_IPS_EQUILIBRIA;
  else if (!strcasecmp(t, "periodic") || !strcasecmp(t, "PO"))
    x = WHIRL_IPS_PERIODIC;
  else if (!strcasecmp(t, "basins"))
    x = WHIRL_IPS_BASINS;
  else if (!strcasecmp(t, "map") || !strcasecmp(t, "maps"))
    x = WHIRL_IPS_MAP;
  else if (!strcasecmp(t, "bvp"))
    x = WHIRL_IPS_BVP;
  else if (to_int(t, &x))
    return fail(rf, where,
                "%s: '%s' is not a problem type (1 or equilibria, 2 or "
                "periodic, 4 or bvp, -1 or map, basins)",
                kn, show(t, ITEMLEN, shown, sizeof shown));
  else if (x != 1 && x != 2 && x != 4 && x != -1)
    return fail(rf, where,
                "%s = %d is not supported (1 equilibria, 2 periodic "
                "orbits, 4 boundary-value problems, -1 fixed points of a map, "
                "basins)",
                kn, x);
  s->ips = x;
  return WHIRL_OK;
}

/* The keys that choose between two words (whirl's default first), each a
 * flag of the settings (int_field): MESH_RULE the density of orbits' meshes,
 * EQ_STEP the step of algebraic branches, DIFFERENCES BVPs' difference
 * quotients, UDOT what the integral conditions' udot is, TANGENT a new
 * point's tangent, LOCATE where a branch goes on after a special point,
 * MX a branch whose Newton fails at DSMIN, ORBIT_MAX what MAX U(i) of an
 * orbit is, PHASE the phase condition of orbits (doc/run-files.md) */
typedef struct two_words {
  whirl_run_key key;
  const char *no, *yes;
} two_words;
static const two_words two_word_keys[] = {
    {WHIRL_RK_MESH_RULE, "derivative", "jumps"},  {WHIRL_RK_EQ_STEP, "tangent", "sphere"},
    {WHIRL_RK_DIFFERENCES, "central", "auto"},    {WHIRL_RK_UDOT, "derivative", "direction"},
    {WHIRL_RK_TANGENT, "refined", "iterate"},     {WHIRL_RK_LOCATE, "converged", "auto"},
    {WHIRL_RK_MX, "fail", "label"},               {WHIRL_RK_ORBIT_MAX, "curve", "nodes"},
    {WHIRL_RK_PHASE, "gauss", "nodes"}};

static const two_words *two_words_of(whirl_run_key key) {
  for (size_t i = 0; i < sizeof two_word_keys / sizeof *two_word_keys; i++)
    if (two_word_keys[i].key == key) return &two_word_keys[i];
  return NULL;
}

/* METHOD: colloc or hbm. */
static int set_method(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name;
  char shown[64];
  if (v->kind != V_SCALAR)
    return fail(rf, where, "%s: expected one word", kn);
  const char *t = v->it[0].text;
  const two_words *w = two_words_of(d->key);
  if (w) { /* a choice of two: the second one sets the flag */
    if (strcasecmp(t, w->no) && strcasecmp(t, w->yes))
      return fail(rf, where, "%s: '%s' is neither %s nor %s", kn,
                  show(t, ITEMLEN, shown, sizeof shown), w->no, w->yes);
    *int_field(s, d->key) = !strcasecmp(t, w->yes);
    return WHIRL_OK;
  }
  if (d->key == WHIRL_RK_BASIN_METHOD) { /* the explicit integrators */
    if (strcasecmp(t, "dop853") && strcasecmp(t, "dopri5"))
      return fail(rf, where, "%s: '%s' is not an integrator (dop853 or dopri5)",
                  kn, show(t, ITEMLEN, shown, sizeof shown));
    s->basin_method = !strcasecmp(t, "dop853") ? WHIRL_ODE_DOP853 : WHIRL_ODE_DOPRI5;
    return WHIRL_OK;
  }
  if (!strcasecmp(t, "colloc") || !strcasecmp(t, "collocation"))
    s->method = WHIRL_METHOD_COLLOC;
  else if (!strcasecmp(t, "hbm") || !strcasecmp(t, "harmonic_balance"))
    s->method = WHIRL_METHOD_HBM;
  else
    return fail(rf, where, "%s: '%s' is not a method (colloc or hbm)", kn,
                show(t, ITEMLEN, shown, sizeof shown));
  return WHIRL_OK;
}

/* ICP: a list of at most WHIRL_RUN_MAXICP parameters. */
static int set_reflist(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name, *msg = NULL;
  char shown[64];
  if (v->kind == V_DICT)
    return fail(rf, where, "%s: expected a list of parameters, got a "
                "dictionary", kn);
  if (v->n == 0) return fail(rf, where, "%s: empty list", kn);
  if (v->n > WHIRL_RUN_MAXICP)
    return fail(rf, where, "%s: at most %d parameters", kn, WHIRL_RUN_MAXICP);
  for (size_t i = 0; i < v->n; i++)
    if (to_ref(&v->it[i], &s->icp[i], &msg))
      return fail(rf, where, "%s: '%s' %s", kn,
                  show(v->it[i].text, ITEMLEN, shown, sizeof shown), msg);
  s->nicp = v->n;
  return WHIRL_OK;
}

/* PAR, U, THL, THU (a dictionary or a positional list), UZR, UZSTOP
 * (dictionaries). */
static int set_values(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name, *msg = NULL;
  char shown[64];
  whirl_run_value *dst = d->key == WHIRL_RK_PAR ? s->par
                         : d->key == WHIRL_RK_U ? s->u
                         : d->key == WHIRL_RK_UZR ? s->uzr
                         : d->key == WHIRL_RK_STUDY ? s->study
                         : d->key == WHIRL_RK_THL ? s->thl
                         : d->key == WHIRL_RK_THU ? s->thu
                                                  : s->uzstop;
  size_t *cnt = d->key == WHIRL_RK_PAR ? &s->npar
                : d->key == WHIRL_RK_U ? &s->nu
                : d->key == WHIRL_RK_UZR ? &s->nuzr
                : d->key == WHIRL_RK_STUDY ? &s->nstudy
                : d->key == WHIRL_RK_THL ? &s->nthl
                : d->key == WHIRL_RK_THU ? &s->nthu
                                         : &s->nuzstop;
  if (v->kind != V_DICT && d->kind == K_UZDICT)
    return fail(rf, where, "%s: expected a dictionary {parameter: "
                "value or [values]}", kn);
  if (v->n > WHIRL_RUN_MAXITEMS)
    return fail(rf, where, "%s: too many values (at most %d)", kn,
                WHIRL_RUN_MAXITEMS);
  for (size_t i = 0; i < v->n; i++) {
    whirl_run_value *e = &dst[i];
    if (v->kind == V_DICT) {
      item key = v->it[i];
      snprintf(key.text, sizeof key.text, "%s", v->it[i].key);
      key.quoted = 0;
      if (to_ref(&key, &e->ref, &msg))
        return fail(rf, where, "%s: key '%s' %s", kn,
                    show(key.text, ITEMLEN, shown, sizeof shown), msg);
      if (d->kind == K_VALDICT && i > 0 && v->it[i].group == v->it[i - 1].group)
        return fail(rf, where, "%s: '%s' has a list where one value is "
                    "expected", kn, show(key.text, ITEMLEN, shown, sizeof shown));
    } else {
      memset(&e->ref, 0, sizeof e->ref);
      e->ref.index = (int)i + 1; /* positional: PAR = [a, b, c] */
    }
    if (v->it[i].quoted || to_double(v->it[i].text, &e->value))
      return fail(rf, where, "%s: '%s' is not a finite number", kn,
                  show(v->it[i].text, ITEMLEN, shown, sizeof shown));
    if ((d->key == WHIRL_RK_THL || d->key == WHIRL_RK_THU) && e->value < 0)
      return fail(rf, where, "%s: weight %s is negative (a weight of the "
                  "arclength norm is >= 0)", kn,
                  show(v->it[i].text, ITEMLEN, shown, sizeof shown));
  }
  *cnt = v->n;
  return WHIRL_OK;
}

/* IRS: a label, or a type and count (HB1). */
static int set_irs(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name;
  char shown[64];
  if (v->kind != V_SCALAR) return fail(rf, where, "%s: expected a label", kn);
  const char *t = v->it[0].text;
  int x;
  s->irs_type[0] = '\0';
  if (!to_int(t, &x)) {
    if (x < 0) return fail(rf, where, "%s = %d: must be >= 0", kn, x);
    s->irs = x;
    return WHIRL_OK;
  }
  /* TY[k]: the k-th point of type TY (AUTO: IRS = 'HB1') */
  static const char *const types[] = {"EP", "LP", "BP", "HB", "UZ", "PD",
                                      "TR", "CP", "BT", "ZH", "IS", "MG", "GH", "RG",
                                      "R1", "R2", "R3", "R4"};
  for (size_t i = 0; i < sizeof types / sizeof types[0]; i++) {
    if (strncasecmp(t, types[i], 2)) continue;
    int k = 1;
    if (t[2] && (to_int(t + 2, &k) || k < 1)) break;
    memcpy(s->irs_type, types[i], 3);
    s->irs = k;
    return WHIRL_OK;
  }
  return fail(rf, where, "%s: '%s' is not a label (a number, or a type "
              "and count such as HB1)", kn, show(t, ITEMLEN, shown, sizeof shown));
}

/* BASIN_AXES: one or two {component: [min, max]}; DISCOVER_BOX: any
 * number of them. */
static int set_ranges(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name, *msg = NULL;
  char shown[64];
  const int box = d->key == WHIRL_RK_DISCOVER_BOX;
  const size_t maxg = box ? WHIRL_RUN_MAXITEMS : 2;
  whirl_run_range *out = box ? s->box : s->axes;
  if (v->kind != V_DICT || v->ngroups < 1 || v->ngroups > maxg)
    return fail(rf, where, box ? "%s: expected {component: [min, max], ...}"
                               : "%s: expected {component: [min, max], "
                                 "component: [min, max]}", kn);
  for (size_t g = 0; g < v->ngroups; g++) {
    size_t first = MAXITEMS, count = 0;
    for (size_t i = 0; i < v->n; i++)
      if (v->it[i].group == (int)g) {
        if (first == MAXITEMS) first = i;
        count++;
      }
    if (count != 2)
      return fail(rf, where, "%s: each %s needs [min, max]", kn, box ? "component" : "axis");
    whirl_run_range *r = &out[g];
    item key = v->it[first];
    snprintf(key.text, sizeof key.text, "%s", v->it[first].key);
    key.quoted = 0;
    if (to_ref(&key, &r->ref, &msg))
      return fail(rf, where, "%s: key '%s' %s", kn,
                  show(key.text, ITEMLEN, shown, sizeof shown), msg);
    if (to_double(v->it[first].text, &r->lo) ||
        to_double(v->it[first + 1].text, &r->hi))
      return fail(rf, where, "%s: a range bound is not a finite number", kn);
    if (!(r->lo < r->hi))
      return fail(rf, where, "%s: range [%g, %g] of '%s' is empty or inverted "
                  "(min must be below max)", kn, r->lo, r->hi,
                  show(key.text, ITEMLEN, shown, sizeof shown));
  }
  if (box)
    s->nbox = v->ngroups;
  else
    s->naxes = v->ngroups;
  return WHIRL_OK;
}

/* DISCOVER: a list of finite numbers (sample values). */
static int set_reallist(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  char shown[64];
  if (v->kind == V_DICT || v->n == 0)
    return fail(rf, where, "%s: expected a list of values [a, b, ...]", d->name);
  if (v->n > WHIRL_RUN_MAXITEMS)
    return fail(rf, where, "%s: more than %d values", d->name, WHIRL_RUN_MAXITEMS);
  for (size_t i = 0; i < v->n; i++)
    if (v->it[i].quoted || to_double(v->it[i].text, &s->discover[i]))
      return fail(rf, where, "%s: '%s' is not a finite number", d->name,
                  show(v->it[i].text, ITEMLEN, shown, sizeof shown));
  s->ndiscover = v->n;
  return WHIRL_OK;
}

/* BASIN_GRID: N or [N1, N2]. */
static int set_grid(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name;
  char shown[64];
  if (v->kind == V_DICT || v->n > 2 || v->n == 0)
    return fail(rf, where, "%s: expected N or [N1, N2]", kn);
  for (size_t i = 0; i < 2; i++) {
    int x;
    const item *it = &v->it[i < v->n ? i : 0];
    if (it->quoted || to_int(it->text, &x))
      return fail(rf, where, "%s: '%s' is not an integer", kn,
                  show(it->text, ITEMLEN, shown, sizeof shown));
    if (x < 2 || x > 4096)
      return fail(rf, where, "%s = %d: must be in [2, 4096]", kn, x);
    s->grid[i] = x;
  }
  return WHIRL_OK;
}

/* BASIN_ATTRACTORS: a list of labels. */
static int set_intlist(whirl_runfile *rf, const key_def *d, const char *where) {
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  const char *kn = d->name;
  char shown[64];
  if (v->kind == V_DICT) return fail(rf, where, "%s: expected a list of labels", kn);
  if (v->n > WHIRL_RUN_MAXITEMS)
    return fail(rf, where, "%s: too many labels", kn);
  for (size_t i = 0; i < v->n; i++) {
    int x;
    if (v->it[i].quoted || to_int(v->it[i].text, &x) || x < 1)
      return fail(rf, where, "%s: '%s' is not a label (a positive integer)",
                  kn, show(v->it[i].text, ITEMLEN, shown, sizeof shown));
    s->attractors[i] = x;
  }
  s->nattractors = v->n;
  return WHIRL_OK;
}

/* STOP: point types with a count, AUTO's ['TR1', 'LP2'] (a type alone
 * counts 1): the branch ends at the count-th point of that type. */
static int set_stoplist(whirl_runfile *rf, const key_def *d, const char *where) {
  static const char *const types[] = {"BP", "LP", "HB", "UZ", "PD", "TR", "EP", "MX",
                                      "R1", "R2", "R3", "R4"};
  whirl_run_settings *s = &rf->s;
  const pvalue *v = &rf->v;
  char shown[64];
  if (v->kind == V_DICT) return fail(rf, where, "%s: expected a list like [TR1, LP2]", d->name);
  if (v->n > WHIRL_RUN_MAXITEMS) return fail(rf, where, "%s: too many points", d->name);
  for (size_t i = 0; i < v->n; i++) {
    const char *t = v->it[i].text;
    size_t k = 0;
    while (k < sizeof types / sizeof *types && strncasecmp(t, types[k], 2)) k++;
    int n = 1;
    if (k == sizeof types / sizeof *types || (t[2] && (to_int(t + 2, &n) || n < 1)))
      return fail(rf, where, "%s: '%s' is not a point type with a count (BP, LP, HB, UZ, "
                  "PD, TR, EP, MX or R1-R4, then 1, 2, ...: TR1)", d->name,
                  show(t, ITEMLEN, shown, sizeof shown));
    memset(&s->stop[i], 0, sizeof s->stop[i]);
    snprintf(s->stop[i].ref.name, sizeof s->stop[i].ref.name, "%s", types[k]);
    s->stop[i].value = n;
  }
  s->nstop = v->n;
  return WHIRL_OK;
}

/* Convert the value text (already comment-stripped) for key d.  where:
 * "FILE:LINE" for messages. */
static int set_value(whirl_runfile *rf, const key_def *d, const char *where,
                     const char *text, size_t n) {
  whirl_run_settings *s = &rf->s;
  const char *kn = d->name;

  /* strings take the whole value (quotes removed), so paths may contain
   * blanks, commas and brackets */
  if (d->kind == K_STRING) {
    while (n && (*text == ' ' || *text == '\t')) text++, n--;
    while (n && (text[n - 1] == ' ' || text[n - 1] == '\t')) n--;
    if (n >= 2 && (text[0] == '\'' || text[0] == '"') && text[n - 1] == text[0])
      text++, n -= 2;
    else if (n && (text[0] == '\'' || text[0] == '"'))
      return fail(rf, where, "%s: unterminated quoted string", kn);
    if (!n) return fail(rf, where, "%s: no value after '='", kn);
    for (size_t i = 0; i < n; i++)
      if ((unsigned char)text[i] < 32)
        return fail(rf, where, "%s: control character in the value", kn);
    size_t cap;
    char *dst = string_field(s, d->key, &cap);
    if (n >= cap)
      return fail(rf, where, "%s: value too long (at most %zu characters)",
                  kn, cap - 1);
    memcpy(dst, text, n);
    dst[n] = '\0';
    if (d->key == WHIRL_RK_PLOT && strlen(dst) >= WHIRL_RUN_MAXNAME)
      return fail(rf, where, "%s: name too long", kn);
    return WHIRL_OK;
  }

  int rc = parse_checked(rf, where, kn, text, n);
  if (rc) return rc;

  switch (d->kind) {
    case K_INT: return set_number(rf, d, where);
    case K_REAL: return set_number(rf, d, where);
    case K_IPS: return set_ips(rf, d, where);
    case K_METHOD: return set_method(rf, d, where);
    case K_REFLIST: return set_reflist(rf, d, where);
    case K_VALDICT: return set_values(rf, d, where);
    case K_UZDICT: return set_values(rf, d, where);
    case K_IRS: return set_irs(rf, d, where);
    case K_RANGES: return set_ranges(rf, d, where);
    case K_GRID: return set_grid(rf, d, where);
    case K_INTLIST: return set_intlist(rf, d, where);
    case K_STOPLIST: return set_stoplist(rf, d, where);
    case K_REALLIST: return set_reallist(rf, d, where);
    case K_IGNORED:
    case K_STRING:
      return WHIRL_OK;
  }
  return WHIRL_OK;
}

/* ---- keys --------------------------------------------------------------- */

static const key_def *find_key(const char *k, size_t n) {
  for (size_t i = 0; i < NKEYS; i++) {
    const char *names[3] = {keys[i].name, keys[i].alias, keys[i].alias2};
    for (int j = 0; j < 3; j++)
      if (names[j] && strlen(names[j]) == n && !strncasecmp(names[j], k, n))
        return &keys[i];
  }
  return NULL;
}

static int is_ignored_key(const char *k, size_t n) {
  for (size_t i = 0; i < NIGNORED; i++)
    if (strlen(ignored_keys[i]) == n && !strncasecmp(ignored_keys[i], k, n))
      return 1;
  return 0;
}

/* Edit distance, for "did you mean" (keys are short). */
static size_t distance(const char *a, size_t na, const char *b) {
  size_t nb = strlen(b), prev[48], cur[48];
  if (na >= 47 || nb >= 47) return 99;
  for (size_t j = 0; j <= nb; j++) prev[j] = j;
  for (size_t i = 1; i <= na; i++) {
    cur[0] = i;
    for (size_t j = 1; j <= nb; j++) {
      size_t c = prev[j - 1] + (toupper((unsigned char)a[i - 1]) !=
                                toupper((unsigned char)b[j - 1]));
      if (prev[j] + 1 < c) c = prev[j] + 1;
      if (cur[j - 1] + 1 < c) c = cur[j - 1] + 1;
      cur[j] = c;
    }
    memcpy(prev, cur, (nb + 1) * sizeof *prev);
  }
  return prev[nb];
}

static int unknown_key(whirl_runfile *rf, const char *where, const char *k,
                       size_t n) {
  char shown[64];
  const char *best = NULL;
  size_t bd = 3;
  for (size_t i = 0; i < NKEYS; i++) {
    const char *names[3] = {keys[i].name, keys[i].alias, keys[i].alias2};
    for (int j = 0; j < 3; j++) {
      if (!names[j]) continue;
      size_t d = distance(k, n, names[j]);
      if (d < bd || (d == bd && d == 1)) bd = d, best = names[j];
    }
  }
  show(k, n, shown, sizeof shown);
  if (best && bd <= (n > 3 ? 2u : 1u))
    return fail(rf, where, "unknown key '%s' (did you mean %s?)", shown, best);
  return fail(rf, where, "unknown key '%s' (see doc/run-files.md)", shown);
}

static void note_ignored(whirl_runfile *rf, const char *k, size_t n) {
  size_t len = strlen(rf->ignored);
  if (len + n + 3 >= sizeof rf->ignored) return;
  if (len) {
    memcpy(rf->ignored + len, ", ", 2);
    len += 2;
  }
  for (size_t i = 0; i < n; i++)
    rf->ignored[len + i] = (char)toupper((unsigned char)k[i]);
  rf->ignored[len + n] = '\0';
}

/* One "key = value" (comment already removed).  line > 0: file line;
 * line < 0: command line, text is the argument. */
static int assign(whirl_runfile *rf, int line, const char *where,
                  const char *k, size_t kn, const char *val, size_t vn,
                  const char *arg) {
  char shown[64];
  if (kn == 0) return fail(rf, where, "a key is missing before '='");
  for (size_t i = 0; i < kn; i++) {
    unsigned char c = (unsigned char)k[i];
    if (!(isalnum(c) || c == '_'))
      return fail(rf, where, "'%s' is not a key name (letters, digits, '_')",
                  show(k, kn, shown, sizeof shown));
  }
  const key_def *d = find_key(k, kn);
  if (!d) {
    if (is_ignored_key(k, kn)) {
      int rc = parse_checked(rf, where, show(k, kn, shown, sizeof shown), val, vn);
      if (rc) return rc;
      note_ignored(rf, k, kn);
      return WHIRL_OK;
    }
    return unknown_key(rf, where, k, kn);
  }
  if (line > 0 && rf->line[d->key] > 0)
    return fail(rf, where, "%s given twice (first at line %d)", d->name,
                rf->line[d->key]);
  int rc = set_value(rf, d, where, val, vn);
  if (rc) return rc;
  rf->line[d->key] = line;
  if (line < 0) snprintf(rf->cmd[d->key], sizeof rf->cmd[d->key], "%s", arg);
  return WHIRL_OK;
}

/* Split one line at '=' and strip the comment ('#' outside quotes). */
static int parse_line(whirl_runfile *rf, int line, const char *s, size_t n) {
  char where[WHIRL_RUN_MAXPATH + 32];
  snprintf(where, sizeof where, "%s:%d", rf->name, line);
  /* comment */
  char q = 0;
  size_t end = n;
  for (size_t i = 0; i < n; i++) {
    char c = s[i];
    if (q) {
      if (c == q) q = 0;
    } else if (c == '\'' || c == '"') {
      q = c;
    } else if (c == '#') {
      end = i;
      break;
    }
  }
  n = end;
  while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r')) n--;
  size_t i = 0;
  while (i < n && (s[i] == ' ' || s[i] == '\t')) i++;
  if (i == n) return WHIRL_OK; /* blank or comment */
  for (size_t j = i; j < n; j++)
    if (s[j] == '\r' || s[j] == '\f' || s[j] == '\v')
      return fail(rf, where, "control character in the line");
  const char *eq = memchr(s + i, '=', n - i);
  if (!eq) {
    char shown[64];
    return fail(rf, where, "expected 'key = value', got '%s'",
                show(s + i, n - i, shown, sizeof shown));
  }
  size_t kn = (size_t)(eq - (s + i));
  while (kn && (s[i + kn - 1] == ' ' || s[i + kn - 1] == '\t')) kn--;
  const char *val = eq + 1;
  size_t vn = (size_t)(s + n - val);
  return assign(rf, line, where, s + i, kn, val, vn, NULL);
}

int whirl_runfile_parse(whirl_runfile *rf, const char *name, const char *text,
                        size_t len) {
  if (!rf || !text) return WHIRL_EINVAL;
  snprintf(rf->name, sizeof rf->name, "%s", name ? name : "<run file>");
  if (rf->parsed) return fail(rf, rf->name, "already parsed");
  rf->parsed = 1;
  size_t start = 0;
  int line = 0;
  while (start < len) {
    size_t stop = start;
    while (stop < len && text[stop] != '\n') stop++;
    line++;
    if (line == INT_MAX / 2) {
      char where[WHIRL_RUN_MAXPATH + 32];
      snprintf(where, sizeof where, "%s:%d", rf->name, line);
      return fail(rf, where, "too many lines");
    }
    if (memchr(text + start, '\0', stop - start)) {
      char where[WHIRL_RUN_MAXPATH + 32];
      snprintf(where, sizeof where, "%s:%d", rf->name, line);
      return fail(rf, where, "NUL byte in the line (not a text file?)");
    }
    int rc = parse_line(rf, line, text + start, stop - start);
    if (rc) return rc;
    start = stop + 1;
  }
  rf->nlines = line;
  return WHIRL_OK;
}

int whirl_runfile_read(whirl_runfile *rf, const char *path) {
  if (!rf || !path) return WHIRL_EINVAL;
  snprintf(rf->name, sizeof rf->name, "%s", path);
  FILE *f = fopen(path, "rb");
  if (!f) {
    snprintf(rf->err, sizeof rf->err, "%s: cannot open: %s", path,
             strerror(errno));
    return WHIRL_EIO;
  }
  size_t cap = 4096, n = 0;
  char *buf = malloc(cap);
  int rc = WHIRL_OK;
  while (buf) {
    size_t got = fread(buf + n, 1, cap - n, f);
    n += got;
    if (n < cap) break;
    if (cap >= (size_t)16 << 20) { /* a run file is a few hundred bytes */
      rc = fail(rf, path, "file larger than 16 MB: not a run file?");
      break;
    }
    char *nb = realloc(buf, cap *= 2);
    if (!nb) {
      free(buf);
      buf = NULL;
    } else {
      buf = nb;
    }
  }
  if (!buf) {
    fclose(f);
    snprintf(rf->err, sizeof rf->err, "%s: out of memory", path);
    return WHIRL_ENOMEM;
  }
  if (rc == WHIRL_OK && ferror(f)) {
    snprintf(rf->err, sizeof rf->err, "%s: read error: %s", path,
             strerror(errno));
    rc = WHIRL_EIO;
  }
  fclose(f);
  if (rc == WHIRL_OK) rc = whirl_runfile_parse(rf, path, buf, n);
  free(buf);
  return rc;
}

int whirl_runfile_override(whirl_runfile *rf, const char *arg) {
  if (!rf || !arg) return WHIRL_EINVAL;
  char where[160], shown[64];
  snprintf(where, sizeof where, "command line (%s)", show(arg, strlen(arg), shown, sizeof shown));
  const char *a = arg;
  if (a[0] == '-' && a[1] == '-') a += 2;
  const char *eq = strchr(a, '=');
  if (!eq)
    return fail(rf, where, "expected --KEY=value");
  if (strchr(a, '\n')) return fail(rf, where, "newline in the argument");
  return assign(rf, -1, where, a, (size_t)(eq - a), eq + 1, strlen(eq + 1), arg);
}

/* Where to blame a check on: the key's line, or the end of the file when
 * the key was not given (a missing key has no line of its own). */
static const char *where_of(const whirl_runfile *rf, whirl_run_key k, char *buf,
                            size_t len) {
  if (rf->line[k] == 0) {
    snprintf(buf, len, "%s:%d", rf->name, rf->nlines > 0 ? rf->nlines : 1);
    return buf;
  }
  return whirl_runfile_where(rf, k, buf, len);
}

int whirl_runfile_check(whirl_runfile *rf) {
  whirl_run_settings *s = &rf->s;
  char w[WHIRL_RUN_MAXPATH + 64];
  if (!rf->line[WHIRL_RK_MODEL]) {
    snprintf(w, sizeof w, "%s:%d", rf->name, rf->nlines > 0 ? rf->nlines : 1);
    return fail(rf, w, "end of file without the required key 'model' (a "
                "built-in model name or a plug-in .so)");
  }
  if (s->ips != WHIRL_IPS_BASINS && s->nicp == 0) {
    snprintf(w, sizeof w, "%s:%d", rf->name, rf->nlines > 0 ? rf->nlines : 1);
    return fail(rf, w, "end of file without the required key 'ICP' (the "
                "continuation parameter)");
  }
  if (s->dsmin > s->dsmax)
    return fail(rf, where_of(rf, rf->line[WHIRL_RK_DSMAX] ? WHIRL_RK_DSMAX : WHIRL_RK_DSMIN,
                             w, sizeof w),
                "DSMIN = %g exceeds DSMAX = %g", s->dsmin, s->dsmax);
  if (!(s->rl0 < s->rl1))
    return fail(rf, where_of(rf, rf->line[WHIRL_RK_RL1] ? WHIRL_RK_RL1 : WHIRL_RK_RL0, w, sizeof w),
                "RL0 = %g must be below RL1 = %g", s->rl0, s->rl1);
  if (!(s->a0 < s->a1))
    return fail(rf, where_of(rf, WHIRL_RK_A1, w, sizeof w),
                "A0 = %g must be below A1 = %g", s->a0, s->a1);
  if ((s->irs > 0 || s->irs_type[0]) && !s->s[0])
    return fail(rf, where_of(rf, WHIRL_RK_IRS, w, sizeof w),
                "IRS names a label but S (the previous run's output "
                "directory) is not given");
  if (s->isw != 1 && s->irs == 0 && !s->irs_type[0])
    return fail(rf, where_of(rf, WHIRL_RK_ISW, w, sizeof w),
                "ISW = %d needs a labelled start point (IRS)", s->isw);
  if (s->isw == 2 && s->nicp < 2)
    return fail(rf, where_of(rf, WHIRL_RK_ICP, w, sizeof w),
                "ISW = 2 (two-parameter continuation) needs two parameters "
                "in ICP");
  if (s->isw == 3 && s->nicp < 3)
    return fail(rf, where_of(rf, WHIRL_RK_ICP, w, sizeof w),
                "ISW = 3 (a generic branch point's locus) needs three parameters "
                "in ICP");
  if (s->ndiscover || s->nbox || rf->line[WHIRL_RK_DISCOVER_STARTS] ||
      rf->line[WHIRL_RK_DISCOVER_SEED] || rf->line[WHIRL_RK_DISCOVER_SETTLE]) {
    const whirl_run_key k = rf->line[WHIRL_RK_DISCOVER] ? WHIRL_RK_DISCOVER
                            : rf->line[WHIRL_RK_DISCOVER_BOX] ? WHIRL_RK_DISCOVER_BOX
                            : rf->line[WHIRL_RK_DISCOVER_STARTS] ? WHIRL_RK_DISCOVER_STARTS
                            : rf->line[WHIRL_RK_DISCOVER_SEED] ? WHIRL_RK_DISCOVER_SEED
                                                                : WHIRL_RK_DISCOVER_SETTLE;
    if (!s->ndiscover)
      return fail(rf, where_of(rf, k, w, sizeof w), "discovery needs DISCOVER = "
                  "[values of the continuation parameter to search at]");
    if (s->ips == WHIRL_IPS_BASINS || s->isw != 1)
      return fail(rf, where_of(rf, k, w, sizeof w), "DISCOVER searches for "
                  "branches of equilibria (IPS = 1) or periodic orbits (IPS = 2) "
                  "with ISW = 1");
    for (size_t i = 0; i < s->ndiscover; i++)
      if (!(s->discover[i] >= s->rl0 && s->discover[i] <= s->rl1))
        return fail(rf, where_of(rf, WHIRL_RK_DISCOVER, w, sizeof w),
                    "DISCOVER: %g is outside [RL0, RL1] = [%g, %g]",
                    s->discover[i], s->rl0, s->rl1);
  }
  if (s->nstudy && s->points[0])
    return fail(rf, where_of(rf, WHIRL_RK_POINTS, w, sizeof w), "POINTS and STUDY: "
                "a study is a grid (STUDY) or a list of points (POINTS), not both");
  if (s->points[0] && s->ips == WHIRL_IPS_BASINS)
    return fail(rf, where_of(rf, WHIRL_RK_POINTS, w, sizeof w), "POINTS of basins "
                "is not available yet: a study runs continuations (IPS = 1, 2) "
                "and their discovery");
  if (s->nstudy && s->ips == WHIRL_IPS_BASINS)
    return fail(rf, where_of(rf, WHIRL_RK_STUDY, w, sizeof w), "STUDY of basins "
                "is not available yet: a study runs continuations (IPS = 1, 2) "
                "and their discovery");
  if (s->ips == WHIRL_IPS_BASINS) {
    if (s->naxes != 2)
      return fail(rf, where_of(rf, rf->line[WHIRL_RK_BASIN_AXES] ? WHIRL_RK_BASIN_AXES : WHIRL_RK_IPS, w, sizeof w),
                  "IPS = basins needs BASIN_AXES = {a: [min, max], b: [min, max]}");
    if (!s->nattractors || !s->s[0])
      return fail(rf, where_of(rf, rf->line[WHIRL_RK_BASIN_ATTRACTORS] ? WHIRL_RK_BASIN_ATTRACTORS : WHIRL_RK_IPS, w, sizeof w),
                  "IPS = basins needs BASIN_ATTRACTORS (labels of stable "
                  "solutions) and S (the run that computed them)");
  }
  return WHIRL_OK;
}

/* ---- the accessors (whirl/runfile.h) ------------------------------------ */

int whirl_runfile_int(const whirl_runfile *rf, whirl_run_key k, int *v) {
  whirl_run_settings *s = (whirl_run_settings *)&rf->s; /* read only */
  const int *f = k == WHIRL_RK_IPS      ? &s->ips
                 : k == WHIRL_RK_METHOD ? &s->method
                 : k == WHIRL_RK_IRS    ? &s->irs
                                        : int_field(s, k);
  if (f == NULL) return WHIRL_EINVAL;
  *v = *f;
  return WHIRL_OK;
}

int whirl_runfile_real(const whirl_runfile *rf, whirl_run_key k, double *v) {
  const double *f = real_field((whirl_run_settings *)&rf->s, k);
  if (f == NULL) return WHIRL_EINVAL;
  *v = *f;
  return WHIRL_OK;
}

const char *whirl_runfile_string(const whirl_runfile *rf, whirl_run_key k) {
  size_t len;
  if (k == WHIRL_RK_IRS) return rf->s.irs_type;
  return string_field((whirl_run_settings *)&rf->s, k, &len);
}

size_t whirl_runfile_count(const whirl_runfile *rf, whirl_run_key k) {
  const whirl_run_settings *s = &rf->s;
  switch (k) {
    case WHIRL_RK_ICP: return s->nicp;
    case WHIRL_RK_PAR: return s->npar;
    case WHIRL_RK_U: return s->nu;
    case WHIRL_RK_UZR: return s->nuzr;
    case WHIRL_RK_UZSTOP: return s->nuzstop;
    case WHIRL_RK_BASIN_AXES: return s->naxes;
    case WHIRL_RK_BASIN_GRID: return 2;
    case WHIRL_RK_BASIN_ATTRACTORS: return s->nattractors;
    case WHIRL_RK_DISCOVER: return s->ndiscover;
    case WHIRL_RK_STUDY: return s->nstudy;
    case WHIRL_RK_THL: return s->nthl;
    case WHIRL_RK_THU: return s->nthu;
    case WHIRL_RK_STOP: return s->nstop;
    case WHIRL_RK_DISCOVER_BOX: return s->nbox;
    default: return 0;
  }
}

/* The value items of PAR, U, UZR and UZSTOP; NULL for other keys. */
static const whirl_run_value *value_list(const whirl_run_settings *s,
                                         whirl_run_key k) {
  switch (k) {
    case WHIRL_RK_PAR: return s->par;
    case WHIRL_RK_U: return s->u;
    case WHIRL_RK_UZR: return s->uzr;
    case WHIRL_RK_UZSTOP: return s->uzstop;
    case WHIRL_RK_STUDY: return s->study;
    case WHIRL_RK_THL: return s->thl;
    case WHIRL_RK_THU: return s->thu;
    case WHIRL_RK_STOP: return s->stop;
    default: return NULL;
  }
}

int whirl_runfile_item(const whirl_runfile *rf, whirl_run_key k, size_t i,
                       whirl_run_value *out) {
  const whirl_run_settings *s = &rf->s;
  if (i >= whirl_runfile_count(rf, k) || k == WHIRL_RK_BASIN_AXES ||
      k == WHIRL_RK_DISCOVER_BOX)
    return WHIRL_EINVAL;
  const whirl_run_value *list = value_list(s, k);
  memset(out, 0, sizeof *out);
  if (list != NULL)
    *out = list[i];
  else if (k == WHIRL_RK_ICP)
    out->ref = s->icp[i];
  else if (k == WHIRL_RK_BASIN_GRID)
    out->value = s->grid[i];
  else if (k == WHIRL_RK_DISCOVER)
    out->value = s->discover[i];
  else /* BASIN_ATTRACTORS */
    out->value = s->attractors[i];
  return WHIRL_OK;
}

int whirl_runfile_axis(const whirl_runfile *rf, size_t i,
                       whirl_run_range *axis) {
  if (i >= rf->s.naxes) return WHIRL_EINVAL;
  *axis = rf->s.axes[i];
  return WHIRL_OK;
}

int whirl_runfile_box(const whirl_runfile *rf, size_t i, whirl_run_range *range) {
  if (i >= rf->s.nbox) return WHIRL_EINVAL;
  *range = rf->s.box[i];
  return WHIRL_OK;
}

/* lib/run/auto_constants.c — AUTO-07p constants files as AUTO-07p 0.9.2
 * reads them (whirl/auto_constants.h).  The scanner follows the rules of
 * AUTO's python/auto/parseC.py (scanvalue, parseline): a value is a blank-
 * or comma-delimited word, a quoted string, or a bracketed list/dictionary
 * flattened into words (a list inside a dictionary kept as '[' ... ']'
 * marks), continued over lines while a bracket is open; each key then types
 * its value (integers for I..N, reals else, lists, indexed lists).  Written
 * afresh from that description; no AUTO code.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/auto_constants.h>
#include <whirl/runfile.h>

#include "auto_impl.h"

/* ---- the keys AUTO knows (parseC's table) ----------------------------- */

typedef struct key_def {
  const char *name;
  whirl_auto_kind kind;
} key_def;

static const key_def keys[] = {
    {"NDIM", WHIRL_AC_INT},   {"IPS", WHIRL_AC_INT},     {"IRS", WHIRL_AC_INT},
    {"ILP", WHIRL_AC_INT},    {"NTST", WHIRL_AC_INT},    {"NCOL", WHIRL_AC_INT},
    {"IAD", WHIRL_AC_INT},    {"ISP", WHIRL_AC_INT},     {"ISW", WHIRL_AC_INT},
    {"IPLT", WHIRL_AC_INT},   {"NBC", WHIRL_AC_INT},     {"NINT", WHIRL_AC_INT},
    {"NMX", WHIRL_AC_INT},    {"NPR", WHIRL_AC_INT},     {"MXBF", WHIRL_AC_INT},
    {"IID", WHIRL_AC_INT},    {"ITMX", WHIRL_AC_INT},    {"ITNW", WHIRL_AC_INT},
    {"NWTN", WHIRL_AC_INT},   {"JAC", WHIRL_AC_INT},     {"IADS", WHIRL_AC_INT},
    {"IIS", WHIRL_AC_INT},    {"NPAR", WHIRL_AC_INT},    {"IBR", WHIRL_AC_INT},
    {"LAB", WHIRL_AC_INT},    {"NUNSTAB", WHIRL_AC_INT}, {"NSTAB", WHIRL_AC_INT},
    {"IEQUIB", WHIRL_AC_INT}, {"ITWIST", WHIRL_AC_INT},  {"ISTART", WHIRL_AC_INT},
    {"EPSL", WHIRL_AC_REAL},  {"EPSU", WHIRL_AC_REAL},   {"EPSS", WHIRL_AC_REAL},
    {"DS", WHIRL_AC_REAL},    {"DSMIN", WHIRL_AC_REAL},  {"DSMAX", WHIRL_AC_REAL},
    {"RL0", WHIRL_AC_REAL},   {"RL1", WHIRL_AC_REAL},    {"A0", WHIRL_AC_REAL},
    {"A1", WHIRL_AC_REAL},    {"e", WHIRL_AC_TEXT},      {"s", WHIRL_AC_TEXT},
    {"dat", WHIRL_AC_TEXT},   {"sv", WHIRL_AC_TEXT},     {"TY", WHIRL_AC_TEXT},
    {"ICP", WHIRL_AC_LIST},   {"IREV", WHIRL_AC_LIST},   {"IFIXED", WHIRL_AC_LIST},
    {"IPSI", WHIRL_AC_LIST},  {"SP", WHIRL_AC_LIST},     {"STOP", WHIRL_AC_LIST},
    {"THL", WHIRL_AC_INDEXED}, {"THU", WHIRL_AC_INDEXED}, {"UZR", WHIRL_AC_INDEXED},
    {"UZSTOP", WHIRL_AC_INDEXED}, {"U", WHIRL_AC_INDEXED}, {"PAR", WHIRL_AC_INDEXED},
    {"unames", WHIRL_AC_NAMES}, {"parnames", WHIRL_AC_NAMES},
};
#define NKEYS (sizeof keys / sizeof keys[0])

whirl_auto_kind whirl_auto_key_kind(const char *key) {
  for (size_t i = 0; key && i < NKEYS; i++)
    if (!strcmp(keys[i].name, key)) return keys[i].kind;
  return WHIRL_AC_NONE;
}

/* ---- the object ------------------------------------------------------- */

typedef struct ac_item {
  int index;
  char *name;
  double *values;
  size_t nvalues;
  int is_list;
  char *text;
} ac_item;

typedef struct ac_entry {
  const char *key; /* keys[].name */
  whirl_auto_kind kind;
  int line;
  int ival;
  double rval;
  char *text;
  ac_item *items;
  size_t nitems;
} ac_entry;

struct whirl_auto_constants {
  char name[1024];
  char err[1400];
  ac_entry *e;
  size_t ne, cap;
  int parsed;
};

static void item_clear(ac_item *it) {
  free(it->name);
  free(it->values);
  free(it->text);
}

static void entry_clear(ac_entry *en) {
  free(en->text);
  for (size_t i = 0; i < en->nitems; i++) item_clear(&en->items[i]);
  free(en->items);
  en->text = NULL, en->items = NULL, en->nitems = 0;
}

whirl_auto_constants *whirl_auto_constants_alloc(void) {
  return calloc(1, sizeof(whirl_auto_constants));
}

void whirl_auto_constants_free(whirl_auto_constants *ac) {
  if (!ac) return;
  for (size_t i = 0; i < ac->ne; i++) entry_clear(&ac->e[i]);
  free(ac->e);
  free(ac);
}

const char *whirl_auto_constants_errmsg(const whirl_auto_constants *ac) {
  return ac ? ac->err : "";
}
const char *whirl_auto_constants_name(const whirl_auto_constants *ac) {
  return ac ? ac->name : "";
}

/* ---- lines and the scanner -------------------------------------------- */

typedef struct span {
  const char *s;
  size_t n;
} span;

/* A word of a value; mark '[' or ']' for the bounds of a list inside a
 * dictionary (AUTO's '[' and ']' words, kept apart from quoted brackets). */
typedef struct word {
  char *s;
  int mark;
} word;

typedef struct scanval {
  int is_list; /* bracketed */
  char *scalar; /* else the word */
  word *w;
  size_t n, cap;
} scanval;

typedef struct scanner {
  whirl_auto_constants *ac;
  span *lines;
  size_t nlines, li, i;
} scanner;

/* Control bytes of the user's text shown in a message as '?': one line
 * of printable text. */
static void printable(char *s) {
  for (; *s; s++)
    if ((unsigned char)*s < 0x20 || *s == 0x7f) *s = '?';
}

static int fail(whirl_auto_constants *ac, size_t line, const char *fmt, ...)
    WHIRL_PRINTF_LIKE(3, 4);
static int fail(whirl_auto_constants *ac, size_t line, const char *fmt, ...) {
  char where[1100];
  va_list ap;
  snprintf(where, sizeof where, "%s:%zu", ac->name, line);
  va_start(ap, fmt);
  whirl_errmsg_vat(ac->err, sizeof ac->err, WHIRL_EINVAL, where, fmt, ap);
  va_end(ap);
  printable(ac->err);
  return WHIRL_EINVAL;
}

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

static void scanval_free(scanval *v) {
  free(v->scalar);
  for (size_t i = 0; i < v->n; i++) free(v->w[i].s);
  free(v->w);
  memset(v, 0, sizeof *v);
}

static int push_word(scanval *v, const char *s, size_t n, int mark) {
  if (v->n == v->cap) {
    size_t cap = v->cap ? 2 * v->cap : 16;
    word *w = realloc(v->w, cap * sizeof *w);
    if (!w) return WHIRL_ENOMEM;
    v->w = w, v->cap = cap;
  }
  char *c = malloc(n + 1);
  if (!c) return WHIRL_ENOMEM;
  memcpy(c, s, n);
  c[n] = 0;
  v->w[v->n].s = c, v->w[v->n].mark = mark;
  v->n++;
  return WHIRL_OK;
}

/* The word being built. */
typedef struct wbuf {
  char b[512];
  size_t n;
} wbuf;

static int wbuf_add(wbuf *b, char c) {
  if (b->n + 1 >= sizeof b->b) return -1;
  b->b[b->n++] = c;
  return 0;
}

/* Flush the word into the list (if any). */
static int flush(scanval *v, wbuf *b) {
  int rc = b->n ? push_word(v, b->b, b->n, 0) : WHIRL_OK;
  b->n = 0;
  return rc;
}

typedef struct scanstate {
  int level, isdict, quoteesc;
  char quote, prev;
  size_t start_line; /* where the value began, for messages */
} scanstate;

/* One character outside quotes (parseC.scanvalue's rules).  1: the value
 * ended at it; 0: go on; <0: an error (set). */
static int scan_plain(scanner *S, scanstate *q, scanval *v, wbuf *b, char c) {
  if (c == ',' || is_blank(c)) return q->level == 0;
  if (c == ':') return 0;
  if (c == ']' || c == '}') {
    if (q->level == 0)
      return fail(S->ac, S->li + 1, "'%c' without an opening bracket", c);
    if (c == '}') q->isdict = 0;
    q->level--;
    if (flush(v, b)) return WHIRL_ENOMEM;
    if (c == ']' && q->isdict && push_word(v, "]", 1, ']')) return WHIRL_ENOMEM;
    return 0;
  }
  if ((q->prev == ',' || is_blank(q->prev) || q->prev == ':') && q->level > 0 &&
      flush(v, b))
    return WHIRL_ENOMEM;
  if (c == '[' || c == '{') {
    if (q->level == 0) {
      if (v->is_list || b->n)
        return fail(S->ac, S->li + 1, "'%c' after the value", c);
      v->is_list = 1;
    }
    q->level++;
    if (c == '{') q->isdict = 1;
    else if (q->isdict && push_word(v, "[", 1, '[')) return WHIRL_ENOMEM;
    return 0;
  }
  if (c == '"' || c == '\'') {
    q->quote = c;
    return 0;
  }
  if (q->level == 0 && v->is_list)
    return fail(S->ac, S->li + 1, "text after the closing bracket");
  if (wbuf_add(b, c)) return fail(S->ac, S->li + 1, "a word longer than 500 characters");
  return 0;
}

/* Scan the value that starts at S->i of the current line, continuing on
 * the following lines while a bracket is open.  On return S->li, S->i are
 * just past it. */
static int scan_value(scanner *S, scanval *v) {
  scanstate q = {0, 0, 0, 0, ' ', S->li + 1};
  wbuf b = {{0}, 0};
  memset(v, 0, sizeof *v);
  for (;;) {
    const span *L = &S->lines[S->li];
    if (S->i == L->n) {
      if (q.quote)
        return fail(S->ac, S->li + 1, "unterminated quoted string");
      if (q.level == 0) break;
      if (S->li + 1 == S->nlines)
        return fail(S->ac, q.start_line, "unterminated '[' or '{' (end of file)");
      S->li++, S->i = 0;
      continue;
    }
    const char c = L->s[S->i];
    if (!q.quote) {
      int r = scan_plain(S, &q, v, &b, c);
      if (r < 0) return r;
      if (r) break;
    } else if (c == q.quote) {
      /* AUTO drops a doubled quote inside quotes ('' and "") */
      if ((S->i + 1 < L->n && L->s[S->i + 1] == c) || q.quoteesc) q.quoteesc = !q.quoteesc;
      else q.quote = 0;
    } else if (wbuf_add(&b, c)) {
      return fail(S->ac, S->li + 1, "a word longer than 500 characters");
    }
    q.prev = c;
    S->i++;
  }
  if (v->is_list) return WHIRL_OK;
  v->scalar = malloc(b.n + 1);
  if (!v->scalar) return WHIRL_ENOMEM;
  memcpy(v->scalar, b.b, b.n);
  v->scalar[b.n] = 0;
  return WHIRL_OK;
}

/* ---- numbers as AUTO reads them --------------------------------------- */

/* A real as parseB.AUTOatof reads one: Python's float, else the Fortran
 * forms 1.0E (no exponent), 1.0D-03 and 1.0-100 (exponent without E).
 * 0, or -1 (not a number), -2 (not finite).  AUTO prints a warning and
 * takes 0 for what it cannot read; whirl refuses it. */
static int ac_real(const char *s, double *x) {
  char b[128];
  size_t n = strlen(s);
  while (n && is_blank(*s)) s++, n--;
  while (n && is_blank(s[n - 1])) n--;
  if (n == 0 || n + 2 >= sizeof b) return -1;
  memcpy(b, s, n);
  b[n] = 0;
  int rc = whirl_run_number(b, x);
  if (rc == WHIRL_EDOMAIN) return -2;
  if (rc == WHIRL_OK) return 0;
  if (b[n - 1] == 'E') {
    b[n - 1] = 0;
    rc = whirl_run_number(b, x);
    b[n - 1] = 'E';
    if (rc == WHIRL_OK) return 0;
  }
  for (size_t i = 0; i < n; i++) {
    if (b[i] == 'D') b[i] = 'E';
    else if (b[i] == 'd') b[i] = 'e';
  }
  rc = whirl_run_number(b, x);
  if (rc != WHIRL_EINVAL) return rc == WHIRL_OK ? 0 : -2;
  for (size_t i = 1; i < n; i++)
    if ((b[i] == '-' || b[i] == '+') && b[i - 1] != 'e' && b[i - 1] != 'E') {
      memmove(b + i + 1, b + i, n - i + 1);
      b[i] = 'E';
      rc = whirl_run_number(b, x);
      return rc == WHIRL_OK ? 0 : rc == WHIRL_EDOMAIN ? -2 : -1;
    }
  return -1;
}

/* An integer as Python's int() reads one (sign, digits, blanks around,
 * '_' between digits), or AUTO's `*...`: 10 to the number of characters.
 * 0 or -1. */
static int ac_int(const char *s, int *x) {
  size_t n = strlen(s);
  if (n && s[0] == '*') {
    if (n > 9) return -1;
    long p = 1;
    for (size_t i = 0; i < n; i++) p *= 10;
    *x = (int)p;
    return 0;
  }
  while (n && is_blank(*s)) s++, n--;
  while (n && is_blank(s[n - 1])) n--;
  size_t i = 0;
  int neg = 0, digits = 0;
  if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
  long long v = 0;
  for (; i < n; i++) {
    if (s[i] == '_' && digits && i + 1 < n && isdigit((unsigned char)s[i + 1])) continue;
    if (!isdigit((unsigned char)s[i])) return -1;
    v = 10 * v + (s[i] - '0'), digits++;
    if (v > INT_MAX) return -1;
  }
  if (!digits) return -1;
  *x = (int)(neg ? -v : v);
  return 0;
}

static char *dup_str(const char *s) {
  size_t n = strlen(s) + 1;
  char *c = malloc(n);
  if (c) memcpy(c, s, n);
  return c;
}

/* ---- typing a value by its key ---------------------------------------- */

/* The entry of key d (created, or cleared for a new assignment). */
static ac_entry *entry_for(whirl_auto_constants *ac, const key_def *d) {
  for (size_t i = 0; i < ac->ne; i++)
    if (ac->e[i].key == d->name) {
      entry_clear(&ac->e[i]);
      return &ac->e[i];
    }
  if (ac->ne == ac->cap) {
    size_t cap = ac->cap ? 2 * ac->cap : 32;
    ac_entry *e = realloc(ac->e, cap * sizeof *e);
    if (!e) return NULL;
    ac->e = e, ac->cap = cap;
  }
  ac_entry *en = &ac->e[ac->ne++];
  memset(en, 0, sizeof *en);
  en->key = d->name;
  return en;
}

static ac_item *new_item(ac_entry *en) {
  ac_item *it = realloc(en->items, (en->nitems + 1) * sizeof *it);
  if (!it) return NULL;
  en->items = it;
  it = &en->items[en->nitems++];
  memset(it, 0, sizeof *it);
  return it;
}

/* An index or a name (an integer word is an index, as AUTO's int()). */
static int set_ref(ac_item *it, const char *w, int names_only) {
  if (!names_only && ac_int(w, &it->index) == 0) return WHIRL_OK;
  it->index = 0;
  it->name = dup_str(w);
  return it->name ? WHIRL_OK : WHIRL_ENOMEM;
}

static int set_scalar(scanner *S, ac_entry *en, const key_def *d, const scanval *v,
                      size_t line) {
  if (v->is_list)
    return fail(S->ac, line, "%s: expected one value, got a list", d->name);
  en->kind = d->kind;
  if (d->kind == WHIRL_AC_TEXT) {
    en->text = dup_str(v->scalar);
    return en->text ? WHIRL_OK : WHIRL_ENOMEM;
  }
  if (d->kind == WHIRL_AC_REAL) {
    int rc = ac_real(v->scalar, &en->rval);
    if (rc == -2) return fail(S->ac, line, "%s: '%s' is not a finite number", d->name, v->scalar);
    if (rc) return fail(S->ac, line, "%s: '%s' is not a number", d->name, v->scalar);
    return WHIRL_OK;
  }
  if (ac_int(v->scalar, &en->ival) == 0) return WHIRL_OK;
  if (!strcmp(d->name, "IRS")) { /* a label name: HB2, UZ1 */
    en->kind = WHIRL_AC_TEXT;
    en->text = dup_str(v->scalar);
    return en->text ? WHIRL_OK : WHIRL_ENOMEM;
  }
  return fail(S->ac, line, "%s: '%s' is not an integer", d->name, v->scalar);
}

/* ICP, IREV, IFIXED, IPSI: integers or names; SP, STOP: names.  A single
 * word is a list of one. */
static int set_list(scanner *S, ac_entry *en, const key_def *d, const scanval *v,
                    size_t line) {
  const int names = !strcmp(d->name, "SP") || !strcmp(d->name, "STOP");
  en->kind = WHIRL_AC_LIST;
  if (!v->is_list) {
    ac_item *it = new_item(en);
    return !it ? WHIRL_ENOMEM : set_ref(it, v->scalar, names);
  }
  for (size_t i = 0; i < v->n; i++) {
    if (v->w[i].mark) return fail(S->ac, line, "%s: a list inside the list", d->name);
    ac_item *it = new_item(en);
    if (!it || set_ref(it, v->w[i].s, names)) return WHIRL_ENOMEM;
  }
  return WHIRL_OK;
}

static int add_value(ac_item *it, double x) {
  double *v = realloc(it->values, (it->nvalues + 1) * sizeof *v);
  if (!v) return WHIRL_ENOMEM;
  it->values = v;
  v[it->nvalues++] = x;
  return WHIRL_OK;
}

/* The earlier item of the same index or name, else a new one. */
static ac_item *item_of(ac_entry *en, const char *w, int *merged) {
  ac_item probe = {0};
  *merged = 0;
  if (set_ref(&probe, w, 0)) return NULL;
  for (size_t i = 0; i < en->nitems; i++) {
    ac_item *it = &en->items[i];
    if ((probe.name && it->name && !strcmp(probe.name, it->name)) ||
        (!probe.name && !it->name && probe.index == it->index)) {
      item_clear(&probe);
      *merged = 1;
      it->is_list = 1; /* AUTO turns both into one list */
      return it;
    }
  }
  ac_item *it = new_item(en);
  if (!it) {
    item_clear(&probe);
    return NULL;
  }
  *it = probe;
  return it;
}

static int number_word(scanner *S, const key_def *d, const word *w, size_t line,
                       double *x) {
  if (w->mark) return fail(S->ac, line, "%s: a number expected, got '%c'", d->name, w->mark);
  int rc = ac_real(w->s, x);
  if (rc == -2) return fail(S->ac, line, "%s: '%s' is not a finite number", d->name, w->s);
  if (rc) return fail(S->ac, line, "%s: '%s' is not a number", d->name, w->s);
  return WHIRL_OK;
}

/* THL, THU, UZR, UZSTOP, U, PAR: index -> number or [numbers]. */
static int set_indexed(scanner *S, ac_entry *en, const key_def *d, const scanval *v,
                       size_t line) {
  en->kind = WHIRL_AC_INDEXED;
  if (!v->is_list)
    return fail(S->ac, line, "%s: expected a dictionary {index: value, ...}, got '%s'",
                d->name, v->scalar);
  for (size_t i = 0; i < v->n;) {
    int merged, rc;
    if (v->w[i].mark) return fail(S->ac, line, "%s: an index expected, got '%c'", d->name, v->w[i].mark);
    if (i + 1 == v->n) return fail(S->ac, line, "%s: '%s' has no value", d->name, v->w[i].s);
    ac_item *it = item_of(en, v->w[i].s, &merged);
    if (!it) return WHIRL_ENOMEM;
    i++;
    if (v->w[i].mark == '[') {
      it->is_list = 1;
      for (i++; i < v->n && v->w[i].mark != ']'; i++) {
        double x;
        if ((rc = number_word(S, d, &v->w[i], line, &x)) || (rc = add_value(it, x))) return rc;
      }
      if (i == v->n) return fail(S->ac, line, "%s: ']' missing", d->name);
      i++;
    } else {
      double x;
      if ((rc = number_word(S, d, &v->w[i], line, &x)) || (rc = add_value(it, x))) return rc;
      i++;
    }
  }
  return WHIRL_OK;
}

/* unames, parnames: integer index -> name. */
static int set_names(scanner *S, ac_entry *en, const key_def *d, const scanval *v,
                     size_t line) {
  en->kind = WHIRL_AC_NAMES;
  if (!v->is_list)
    return fail(S->ac, line, "%s: expected a dictionary {index: 'name', ...}", d->name);
  if (v->n % 2)
    return fail(S->ac, line, "%s: '%s' has no name", d->name, v->w[v->n - 1].s);
  for (size_t i = 0; i < v->n; i += 2) {
    if (v->w[i].mark || v->w[i + 1].mark)
      return fail(S->ac, line, "%s: a list where an index or a name goes", d->name);
    ac_item *it = new_item(en);
    if (!it) return WHIRL_ENOMEM;
    if (ac_int(v->w[i].s, &it->index))
      return fail(S->ac, line, "%s: '%s' is not an integer index", d->name, v->w[i].s);
    if (!(it->text = dup_str(v->w[i + 1].s))) return WHIRL_ENOMEM;
  }
  return WHIRL_OK;
}

/* ---- lines ------------------------------------------------------------ */

static const key_def *find_def(const char *k) {
  for (size_t i = 0; i < NKEYS; i++)
    if (!strcmp(keys[i].name, k)) return &keys[i];
  return NULL;
}

/* KEY = value at S->i: scan the value and type it. */
static int assign(scanner *S, const char *key, size_t line) {
  const key_def *d = find_def(key);
  if (!d) return fail(S->ac, line, "unknown AUTO constant '%s'", key);
  scanval v;
  int rc = scan_value(S, &v);
  ac_entry *en = rc ? NULL : entry_for(S->ac, d);
  if (!rc && !en) rc = WHIRL_ENOMEM;
  if (!rc) {
    en->line = (int)line;
    switch (d->kind) {
    case WHIRL_AC_LIST: rc = set_list(S, en, d, &v, line); break;
    case WHIRL_AC_INDEXED: rc = set_indexed(S, en, d, &v, line); break;
    case WHIRL_AC_NAMES: rc = set_names(S, en, d, &v, line); break;
    default: rc = set_scalar(S, en, d, &v, line); break;
    }
  }
  scanval_free(&v);
  return rc;
}

/* The assignments of one line (parseC.parseline): until the line ends, a
 * comment starts ('#', '!', '_' where a key would), or text without '='
 * (which AUTO ignores). */
static int parse_line(scanner *S) {
  for (;;) {
    const span *L = &S->lines[S->li];
    while (S->i < L->n && (is_blank(L->s[S->i]) || L->s[S->i] == ',')) S->i++;
    if (S->i == L->n) return WHIRL_OK;
    const char *p = L->s + S->i, c = *p;
    if (c == '#' || c == '!' || c == '_') return WHIRL_OK;
    const char *eq = memchr(p, '=', L->n - S->i);
    if (!eq) return WHIRL_OK;
    size_t a = 0, b = (size_t)(eq - p);
    while (b > a && is_blank(p[b - 1])) b--;
    char key[64];
    if (b == 0) return fail(S->ac, S->li + 1, "'=' without a key");
    if (b >= sizeof key) return fail(S->ac, S->li + 1, "unknown AUTO constant '%.40s...'", p);
    memcpy(key, p, b);
    key[b] = 0;
    const size_t line = S->li + 1;
    S->i += (size_t)(eq - p) + 1;
    while (S->i < L->n && is_blank(L->s[S->i])) S->i++;
    int rc = assign(S, key, line);
    if (rc) return rc;
  }
}

/* Split text into lines, each without its end of line. */
static int split_lines(whirl_auto_constants *ac, const char *text, size_t len,
                       span **out, size_t *nout) {
  size_t n = 1;
  for (size_t i = 0; i < len; i++) n += text[i] == '\n';
  span *L = malloc(n * sizeof *L);
  if (!L) return WHIRL_ENOMEM;
  size_t k = 0, start = 0;
  for (size_t i = 0; i <= len; i++) {
    if (i < len && text[i] == 0) {
      free(L);
      return fail(ac, k + 1, "NUL byte in the line (not a text file?)");
    }
    if (i == len || text[i] == '\n') {
      L[k].s = text + start, L[k].n = i - start;
      while (L[k].n && is_blank(L[k].s[L[k].n - 1])) L[k].n--;
      k++, start = i + 1;
    }
  }
  *out = L, *nout = k;
  return WHIRL_OK;
}

int whirl_auto_constants_parse(whirl_auto_constants *ac, const char *name,
                               const char *text, size_t len) {
  if (!ac || (!text && len) || ac->parsed) return WHIRL_EINVAL;
  ac->parsed = 1;
  snprintf(ac->name, sizeof ac->name, "%s", name ? name : "constants");
  scanner S = {ac, NULL, 0, 0, 0};
  int rc = split_lines(ac, text ? text : "", len, &S.lines, &S.nlines);
  for (S.li = 0; rc == WHIRL_OK && S.li < S.nlines; S.li++) {
    const span *L = &S.lines[S.li];
    size_t i = 0;
    while (i < L->n && is_blank(L->s[i])) i++;
    if (i < L->n && isdigit((unsigned char)L->s[i]))
      rc = fail(ac, S.li + 1, "an old-style (numeric) constants file: whirl reads "
                "AUTO-07p's KEY = value files only");
    else {
      S.i = i;
      rc = parse_line(&S);
    }
  }
  free(S.lines);
  if (rc == WHIRL_ENOMEM) snprintf(ac->err, sizeof ac->err, "%s: out of memory", ac->name);
  return rc;
}

int whirl_auto_constants_read(whirl_auto_constants *ac, const char *path) {
  if (!ac || !path) return WHIRL_EINVAL;
  FILE *f = fopen(path, "rb");
  if (!f) {
    snprintf(ac->err, sizeof ac->err, "%s: cannot open: %s", path, strerror(errno));
    return WHIRL_EIO;
  }
  size_t cap = 4096, n = 0;
  char *buf = malloc(cap);
  while (buf) {
    n += fread(buf + n, 1, cap - n, f);
    if (n < cap) break;
    char *b = cap < (1u << 24) ? realloc(buf, 2 * cap) : NULL;
    if (!b) free(buf);
    buf = b, cap *= 2;
  }
  const int err = ferror(f);
  fclose(f);
  if (!buf || err) {
    const int rc = buf ? WHIRL_EIO : WHIRL_ENOMEM;
    snprintf(ac->err, sizeof ac->err, "%s: %s", path,
             buf ? "read error" : "too large or out of memory");
    free(buf);
    return rc;
  }
  int rc = whirl_auto_constants_parse(ac, path, buf, n);
  free(buf);
  return rc;
}

/* ---- accessors -------------------------------------------------------- */

static const ac_entry *entry(const whirl_auto_constants *ac, const char *key) {
  for (size_t i = 0; ac && key && i < ac->ne; i++)
    if (!strcmp(ac->e[i].key, key)) return &ac->e[i];
  return NULL;
}

whirl_auto_kind whirl_auto_constants_kind(const whirl_auto_constants *ac, const char *key) {
  const ac_entry *en = entry(ac, key);
  return en ? en->kind : WHIRL_AC_NONE;
}

int whirl_auto_constants_line(const whirl_auto_constants *ac, const char *key) {
  const ac_entry *en = entry(ac, key);
  return en ? en->line : 0;
}

size_t whirl_auto_constants_nkeys(const whirl_auto_constants *ac) { return ac ? ac->ne : 0; }

const char *whirl_auto_constants_key(const whirl_auto_constants *ac, size_t i) {
  return ac && i < ac->ne ? ac->e[i].key : NULL;
}

int whirl_auto_constants_int(const whirl_auto_constants *ac, const char *key, int *v) {
  const ac_entry *en = entry(ac, key);
  if (!en || en->kind != WHIRL_AC_INT || !v) return WHIRL_EINVAL;
  *v = en->ival;
  return WHIRL_OK;
}

int whirl_auto_constants_real(const whirl_auto_constants *ac, const char *key, double *v) {
  const ac_entry *en = entry(ac, key);
  if (!en || en->kind != WHIRL_AC_REAL || !v) return WHIRL_EINVAL;
  *v = en->rval;
  return WHIRL_OK;
}

const char *whirl_auto_constants_text(const whirl_auto_constants *ac, const char *key) {
  const ac_entry *en = entry(ac, key);
  return en && en->kind == WHIRL_AC_TEXT ? en->text : NULL;
}

size_t whirl_auto_constants_count(const whirl_auto_constants *ac, const char *key) {
  const ac_entry *en = entry(ac, key);
  return en ? en->nitems : 0;
}

int whirl_auto_constants_item(const whirl_auto_constants *ac, const char *key, size_t i,
                              whirl_auto_item *item) {
  const ac_entry *en = entry(ac, key);
  if (!en || i >= en->nitems || !item) return WHIRL_EINVAL;
  const ac_item *it = &en->items[i];
  item->index = it->index;
  item->name = it->name;
  item->values = it->values;
  item->nvalues = it->nvalues;
  item->is_list = it->is_list;
  item->text = it->text;
  return WHIRL_OK;
}

int whirl_auto_constants_fail(whirl_auto_constants *ac, int line, const char *fmt, ...) {
  char where[1100];
  va_list ap;
  snprintf(where, sizeof where, "%s:%d", ac->name, line);
  va_start(ap, fmt);
  whirl_errmsg_vat(ac->err, sizeof ac->err, WHIRL_EINVAL, where, fmt, ap);
  va_end(ap);
  printable(ac->err);
  return WHIRL_EINVAL;
}

/* drivers/gp_expr.c — gnuplot's `using` expressions (gp_expr.h): a
 * recursive-descent parser into a tree, C's precedence (gnuplot's):
 *   c ? a : b  <  ||  <  &&  <  == != eq ne  <  < > <= >=  <  + -
 *   <  * / %  <  unary - + !  <  ** (right-associative)  <  primaries
 * and an evaluator on a row.  Values are numbers (integers kept as such,
 * as gnuplot divides them: 1/0 is undefined, 7/2 is 3) or strings (eq, ne
 * and strcol); anything undefined is NaN.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* strndup */
#include "gp_expr.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { E_NUM, E_STR, E_COL, E_STRCOL, E_FUN, E_UN, E_BIN, E_TERN };
enum { F_SQRT, F_ABS, F_LOG, F_LOG10, F_EXP };

struct gp_expr {
  int kind, op;  /* op: the operator ("==" as 'E', "**" as 'P', ...) */
  double num;
  int is_int;
  char *str;
  gp_expr *a, *b, *c;
};

typedef struct value {
  double num;
  int is_int;
  const char *str; /* a string value, else NULL */
} value;

/* ---- parsing ------------------------------------------------------------ */

typedef struct lexer {
  const char *p;
  const gp_var *vars;
  size_t nvars;
  char *err;
  size_t len;
  int failed;
} lexer;

static gp_expr *fail(lexer *L, const char *fmt, ...) {
  if (!L->failed) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(L->err, L->len, fmt, ap);
    va_end(ap);
  }
  L->failed = 1;
  return NULL;
}

static void skip(lexer *L) {
  while (*L->p == ' ' || *L->p == '\t') L->p++;
}

/* Is the next token OP?  Taken if so.  Words (eq, ne) must end there. */
static int accept(lexer *L, const char *op) {
  skip(L);
  const size_t n = strlen(op);
  if (strncmp(L->p, op, n)) return 0;
  if (isalpha((unsigned char)op[0]) && (isalnum((unsigned char)L->p[n]) || L->p[n] == '_'))
    return 0;
  /* not the first character of a longer operator */
  if ((!strcmp(op, "*") && L->p[1] == '*') || (!strcmp(op, "<") && L->p[1] == '=') ||
      (!strcmp(op, ">") && L->p[1] == '=') || (!strcmp(op, "!") && L->p[1] == '='))
    return 0;
  L->p += n;
  return 1;
}

static gp_expr *node(lexer *L, int kind, int op, gp_expr *a, gp_expr *b, gp_expr *c) {
  gp_expr *e = calloc(1, sizeof *e);
  if (!e || L->failed) {
    free(e);
    gp_expr_free(a);
    gp_expr_free(b);
    gp_expr_free(c);
    return e ? fail(L, "a bad expression") : fail(L, "out of memory");
  }
  e->kind = kind;
  e->op = op;
  e->a = a;
  e->b = b;
  e->c = c;
  return e;
}

static gp_expr *number(lexer *L, double v, int is_int) {
  gp_expr *e = node(L, E_NUM, 0, NULL, NULL, NULL);
  if (e) e->num = v, e->is_int = is_int;
  return e;
}

static gp_expr *ternary(lexer *L);

/* 'text' or "text" */
static gp_expr *string(lexer *L) {
  const char q = *L->p++;
  char buf[256];
  size_t k = 0;
  for (;;) {
    if (!*L->p) return fail(L, "an open string");
    if (*L->p == q && q == '\'' && L->p[1] == '\'') L->p++;
    else if (*L->p == q) break;
    else if (q == '"' && *L->p == '\\') return fail(L, "an escape in a string");
    if (k + 1 >= sizeof buf) return fail(L, "a long string");
    buf[k++] = *L->p++;
  }
  L->p++;
  gp_expr *e = node(L, E_STR, 0, NULL, NULL, NULL);
  if (e && !(e->str = strndup(buf, k))) {
    gp_expr_free(e);
    return fail(L, "out of memory");
  }
  return e;
}

/* NAME(e) for the functions read here */
static gp_expr *call(lexer *L, const char *name) {
  static const char *const fun[] = {"sqrt", "abs", "log", "log10", "exp"};
  int kind = -1, op = 0;
  if (!strcmp(name, "column")) kind = E_COL;
  else if (!strcmp(name, "strcol")) kind = E_STRCOL;
  for (int f = 0; f < 5; f++)
    if (!strcmp(name, fun[f])) kind = E_FUN, op = f;
  if (kind < 0) return fail(L, "the function %s", name);
  gp_expr *a = ternary(L);
  if (!accept(L, ")")) {
    gp_expr_free(a);
    return fail(L, "a call without its )");
  }
  return node(L, kind, op, a, NULL, NULL);
}

static gp_expr *primary(lexer *L) {
  skip(L);
  const char *p = L->p;
  if (*p == '(') {
    L->p++;
    gp_expr *e = ternary(L);
    if (!accept(L, ")")) {
      gp_expr_free(e);
      return fail(L, "a ( without its )");
    }
    return e;
  }
  if (*p == '\'' || *p == '"') return string(L);
  if (*p == '$') {
    char *end;
    const long c = strtol(p + 1, &end, 10);
    if (end == p + 1 || c < 0 || c > 1000) return fail(L, "a bad $N");
    L->p = end;
    return node(L, E_COL, 0, number(L, (double)c, 1), NULL, NULL);
  }
  if (isdigit((unsigned char)*p) || (*p == '.' && isdigit((unsigned char)p[1]))) {
    char *end;
    const double v = strtod(p, &end);
    const int is_int = strspn(p, "0123456789") == (size_t)(end - p);
    L->p = end;
    return number(L, v, is_int);
  }
  if (isalpha((unsigned char)*p) || *p == '_') {
    char name[32];
    size_t k = 0;
    while ((isalnum((unsigned char)*L->p) || *L->p == '_') && k + 1 < sizeof name)
      name[k++] = *L->p++;
    name[k] = '\0';
    if (accept(L, "(")) return call(L, name);
    if (!strcmp(name, "NaN")) return number(L, NAN, 0);
    if (!strcmp(name, "pi")) return number(L, 3.14159265358979323846, 0);
    for (size_t i = 0; i < L->nvars; i++)
      if (!strcmp(name, L->vars[i].name)) return number(L, L->vars[i].value, L->vars[i].is_int);
    return fail(L, "the name %s", name);
  }
  return fail(L, "'%.20s' where a value belongs", p);
}

/* unary - + ! and ** (binding tighter, right-associative) */
static gp_expr *unary(lexer *L) {
  if (accept(L, "-")) return node(L, E_UN, '-', unary(L), NULL, NULL);
  if (accept(L, "+")) return unary(L);
  if (accept(L, "!")) return node(L, E_UN, '!', unary(L), NULL, NULL);
  gp_expr *a = primary(L);
  if (a && accept(L, "**")) return node(L, E_BIN, 'P', a, unary(L), NULL);
  return a;
}

/* One level of left-associative binary operators OPS[i] (coded CODE[i]),
 * its operands of the next level NEXT. */
static gp_expr *binary(lexer *L, gp_expr *(*next)(lexer *), const char *const *ops,
                       const char *code) {
  gp_expr *a = next(L);
  for (int again = 1; a && again;) {
    again = 0;
    for (int i = 0; ops[i]; i++)
      if (accept(L, ops[i])) {
        a = node(L, E_BIN, code[i], a, next(L), NULL);
        again = 1;
        break;
      }
  }
  return a;
}

static gp_expr *mul(lexer *L) {
  static const char *const ops[] = {"*", "/", "%", NULL};
  return binary(L, unary, ops, "*/%");
}
static gp_expr *add(lexer *L) {
  static const char *const ops[] = {"+", "-", NULL};
  return binary(L, mul, ops, "+-");
}
static gp_expr *rel(lexer *L) {
  static const char *const ops[] = {"<=", ">=", "<", ">", NULL};
  return binary(L, add, ops, "LG<>");
}
static gp_expr *equality(lexer *L) {
  static const char *const ops[] = {"==", "!=", "eq", "ne", NULL};
  return binary(L, rel, ops, "ENen");
}
static gp_expr *and_(lexer *L) {
  static const char *const ops[] = {"&&", NULL};
  return binary(L, equality, ops, "&");
}
static gp_expr *or_(lexer *L) {
  static const char *const ops[] = {"||", NULL};
  return binary(L, and_, ops, "|");
}

static gp_expr *ternary(lexer *L) {
  gp_expr *c = or_(L);
  if (!c || !accept(L, "?")) return c;
  gp_expr *a = ternary(L);
  if (!accept(L, ":")) {
    gp_expr_free(c);
    gp_expr_free(a);
    return fail(L, "a ? without its :");
  }
  return node(L, E_TERN, 0, c, a, ternary(L));
}

gp_expr *gp_expr_parse(const char *text, const gp_var *vars, size_t nvars, char *err,
                       size_t len) {
  lexer L = {text, vars, nvars, err, len, 0};
  gp_expr *e = ternary(&L);
  skip(&L);
  if (e && *L.p) {
    gp_expr_free(e);
    e = fail(&L, "'%.20s' after the expression", L.p);
  }
  if (!e && !L.failed) snprintf(err, len, "a bad expression");
  return e;
}

void gp_expr_free(gp_expr *e) {
  if (!e) return;
  gp_expr_free(e->a);
  gp_expr_free(e->b);
  gp_expr_free(e->c);
  free(e->str);
  free(e);
}

/* ---- evaluation --------------------------------------------------------- */

static value eval(const gp_expr *e, const gp_row *row);

static value num(double v, int is_int) { return (value){v, is_int, NULL}; }

/* column K (1-based) of the row: its number, or its text */
static value column(const gp_expr *e, const gp_row *row, int text) {
  const value k = eval(e->a, row);
  const double c = k.num;
  if (!(c >= 1 && c <= (double)row->n) || c != floor(c)) return num(NAN, 0);
  const size_t i = (size_t)c - 1;
  if (text) return (value){NAN, 0, row->text[i]};
  return num(row->num[i], 0);
}

static value arith(int op, value a, value b) {
  const int ints = a.is_int && b.is_int;
  const double x = a.num, y = b.num;
  switch (op) {
  case '+': return num(x + y, ints);
  case '-': return num(x - y, ints);
  case '*': return num(x * y, ints);
  case '/':
    if (y == 0) return num(NAN, 0); /* gnuplot: undefined */
    return ints ? num(trunc(x / y), 1) : num(x / y, 0);
  case '%':
    if (!ints || y == 0) return num(NAN, 0);
    return num(fmod(x, y), 1);
  default: return num(pow(x, y), ints && y >= 0);
  }
}

static value compare(int op, value a, value b) {
  if (op == 'e' || op == 'n') { /* eq, ne: strings */
    if (!a.str || !b.str) return num(NAN, 0);
    const int same = !strcmp(a.str, b.str);
    return num(op == 'e' ? same : !same, 1);
  }
  const double x = a.num, y = b.num;
  if (isnan(x) || isnan(y)) return num(NAN, 0); /* undefined stays so */
  int r = 0;
  switch (op) {
  case 'E': r = x == y; break;
  case 'N': r = x != y; break;
  case '<': r = x < y; break;
  case '>': r = x > y; break;
  case 'L': r = x <= y; break;
  default: r = x >= y; break;
  }
  return num(r, 1);
}

static value fun(int f, value a) {
  switch (f) {
  case F_SQRT: return num(sqrt(a.num), 0);
  case F_ABS: return num(fabs(a.num), a.is_int);
  case F_LOG: return num(log(a.num), 0);
  case F_LOG10: return num(log10(a.num), 0);
  default: return num(exp(a.num), 0);
  }
}

static value eval(const gp_expr *e, const gp_row *row) {
  switch (e->kind) {
  case E_NUM: return num(e->num, e->is_int);
  case E_STR: return (value){NAN, 0, e->str};
  case E_COL: return column(e, row, 0);
  case E_STRCOL: return column(e, row, 1);
  case E_FUN: return fun(e->op, eval(e->a, row));
  case E_UN: {
    const value a = eval(e->a, row);
    if (e->op == '-') return num(-a.num, a.is_int);
    return isnan(a.num) ? a : num(a.num == 0, 1);
  }
  case E_TERN: {
    const value c = eval(e->a, row);
    if (isnan(c.num)) return num(NAN, 0);
    return eval(c.num != 0 ? e->b : e->c, row);
  }
  default: break;
  }
  if (e->op == '&' || e->op == '|') { /* short-circuit, as C and gnuplot */
    const value a = eval(e->a, row);
    if (isnan(a.num)) return a;
    if ((e->op == '&') == (a.num == 0)) return num(e->op == '|', 1);
    const value b = eval(e->b, row);
    return isnan(b.num) ? b : num(b.num != 0, 1);
  }
  const value a = eval(e->a, row), b = eval(e->b, row);
  if (strchr("ENenLG<>", e->op)) return compare(e->op, a, b);
  return arith(e->op, a, b);
}

double gp_expr_value(const gp_expr *e, const gp_row *row, int *is_int) {
  const value v = eval(e, row);
  if (is_int) *is_int = !v.str && v.is_int;
  return v.str ? NAN : v.num;
}

double gp_expr_eval(const gp_expr *e, const gp_row *row) {
  return gp_expr_value(e, row, NULL);
}

/* test/unit/t_gp_expr.c — gnuplot's `using` expressions (drivers/gp_expr.c)
 * against the same formulas written in C here, row by row of a table like
 * whirl's (a header, numbers, type names), and gnuplot's own rules where C
 * differs: integers divide as integers (7/2 is 3, 1/0 undefined), ** binds
 * tighter than unary minus and to the right, a column that is not a number
 * or an undefined comparison leaves the value undefined (NaN); what is not
 * read here (a function, an open parenthesis, a string where a number is
 * wanted at the end) is refused with a reason.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../tap.h"
#include "gp_expr.h"

enum { NCOL = 4, NROW = 5 };

/* branch, type, Omega, stable: the header, then four points */
static const char *const text[NROW][NCOL] = {
    {"branch", "type", "Omega", "stable"}, {"1", "EP", "0.5", "1"}, {"1", "LP", "1.75", "0"},
    {"2", "-", "3.25", "1"},               {"2", "BP", "-2", "-1"}};

static double num(const char *s) {
  char *end;
  const double v = strtod(s, &end);
  return end != s && !*end ? v : NAN;
}

/* the row I of the table as the evaluator sees it */
static gp_row row_of(int i, double *nums) {
  for (int c = 0; c < NCOL; c++) nums[c] = num(text[i][c]);
  return (gp_row){text[i], nums, NCOL};
}

static int same(double a, double b) { return (isnan(a) && isnan(b)) || a == b; }

/* EXPR on every row against WANT(row's numbers, row's texts) */
static void check(const char *expr, double (*want)(const double *, const char *const *)) {
  const gp_var vars[] = {{"S", 4, 1}, {"B", 2, 1}};
  char err[128] = "";
  gp_expr *e = gp_expr_parse(expr, vars, 2, err, sizeof err);
  int bad = e == NULL;
  for (int i = 0; e && i < NROW; i++) {
    double nums[NCOL];
    const gp_row r = row_of(i, nums);
    const double got = gp_expr_eval(e, &r), w = want(nums, text[i]);
    if (!same(got, w)) {
      bad = 1;
      printf("#   row %d: %g, C says %g\n", i, got, w);
    }
  }
  ok(!bad, "%s on every row as C computes it%s%s", expr, e ? "" : ": ", e ? "" : err);
  gp_expr_free(e);
}

static double w_branch(const double *n, const char *const *t) {
  (void)t;
  /* NaN == 2 is false in C, but gnuplot leaves it undefined: so does C's
   * NaN through the ternary's condition here */
  if (isnan(n[0]) || isnan(n[3])) return NAN;
  return n[0] == 2 && n[3] == 1 ? n[2] : NAN;
}
static double w_scaled(const double *n, const char *const *t) {
  (void)t;
  if (isnan(n[3])) return NAN;
  return n[3] != 1 ? 1e3 * n[2] : NAN;
}
static double w_types(const double *n, const char *const *t) {
  return strcmp(t[1], "-") && strcmp(t[1], "EP") ? n[2] : NAN;
}
static double w_lp(const double *n, const char *const *t) {
  return !strcmp(t[1], "LP") || !strcmp(t[1], "BP") ? sqrt(n[2] * n[2]) : NAN;
}
static double w_arith(const double *n, const char *const *t) {
  (void)t;
  return -n[2] * 2 + n[0] / 4.0 - (n[2] - 1) * (n[2] + 1);
}

static double value(const char *expr, int *is_int) {
  char err[128];
  gp_expr *e = gp_expr_parse(expr, NULL, 0, err, sizeof err);
  const gp_row none = {NULL, NULL, 0};
  const double v = e ? gp_expr_value(e, &none, is_int) : -12345;
  gp_expr_free(e);
  return v;
}

static void test_gnuplot_rules(void) {
  int is_int = 0;
  ok(value("7/2", &is_int) == 3 && is_int, "7/2 is 3, an integer (gnuplot divides integers)");
  ok(value("7/2.0", &is_int) == 3.5 && !is_int, "7/2.0 is 3.5");
  ok(isnan(value("1/0", &is_int)), "1/0 is undefined (NaN)");
  ok(value("2**3**2", &is_int) == 512, "** to the right: 2**3**2 is 512");
  ok(value("-2**2", NULL) == -4, "** before unary minus: -2**2 is -4");
  ok(value("1 + 2 * 3 == 7 && !(4 < 3)", NULL) == 1, "C's precedence of + * == && !");
  ok(value("0 ? 1 : 2 ? 3 : 4", NULL) == 3, "?: to the right");
  ok(value("'a' eq 'a' && 'a' ne 'b'", NULL) == 1, "eq and ne on strings");
  ok(isnan(value("'a'", NULL)), "a string as a number: undefined");
  ok(fabs(value("sqrt(2)*sqrt(2) - 2", NULL)) < 1e-15 && value("abs(-3)", NULL) == 3,
     "sqrt and abs");
  ok(fabs(value("pi", NULL) - 3.14159265358979) < 1e-13, "pi");
}

static void test_refusals(void) {
  static const char *const bad[] = {"foo(1)", "(1 +", "column(1", "1 ? 2", "$", "x",
                                    "1 2", "'open", "\"a\\tb\""};
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    char err[128] = "";
    gp_expr *e = gp_expr_parse(bad[i], NULL, 0, err, sizeof err);
    ok(e == NULL && err[0], "%s refused: %s", bad[i], err);
    gp_expr_free(e);
  }
}

int main(void) {
  check("(column(1) == B && column(S) == 1 ? column(3) : NaN)", w_branch);
  check("($4!=1 ? 1e3*$3 : 1/0)", w_scaled);
  check("(strcol(2) ne '-' && strcol(2) ne 'EP' ? column(3) : NaN)", w_types);
  check("(strcol(2) eq 'LP' || strcol(2) eq 'BP' ? sqrt($3*$3) : 1/0)", w_lp);
  check("-$3*2 + $1/4.0 - ($3 - 1)*($3 + 1)", w_arith);
  test_gnuplot_rules();
  test_refusals();
  return done_testing();
}

/* drivers/gp_expr.h — the expressions of gnuplot's `using` that whirl's
 * scripts write, e.g. (column(1) == 2 && column(S) == 1 ? column(10) : NaN)
 * or ($7 != 1 ? 1e3*$6 : 1/0): numbers, NaN, pi, the script's variables,
 * $N, column(e), strcol(e), strings; + - * / ** (unary - and !); == != < >
 * <= >=, eq and ne on strings; && ||; c ? a : b.  An expression is parsed
 * once and evaluated for each row of a table; what gnuplot leaves
 * undefined (a division by zero, a column that is not a number) is NaN,
 * and a NaN point is not drawn (a line breaks there).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVERS_GP_EXPR_H
#define WHIRL_DRIVERS_GP_EXPR_H

#include <stddef.h>

typedef struct gp_expr gp_expr;

/* The script's variables (name = number), for the parse. */
typedef struct gp_var {
  char name[32];
  double value;
  int is_int; /* gnuplot's integers divide as integers (7 / 2 is 3) */
} gp_var;

/* A row of a table: its fields as text and as numbers (NaN: not one). */
typedef struct gp_row {
  const char *const *text;
  const double *num;
  size_t n;
} gp_row;

/* Parse TEXT (the whole of it must be one expression).  NULL, with why in
 * err, for what is not read here (the picture is then gnuplot's) or no
 * memory. */
gp_expr *gp_expr_parse(const char *text, const gp_var *vars, size_t nvars, char *err,
                       size_t len);

/* Its value on ROW (NaN: undefined; a string's value is NaN). */
double gp_expr_eval(const gp_expr *e, const gp_row *row);
/* The same, and *is_int: the value is one of gnuplot's integers. */
double gp_expr_value(const gp_expr *e, const gp_row *row, int *is_int);

void gp_expr_free(gp_expr *e); /* accepts NULL */

#endif

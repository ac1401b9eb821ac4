/* test/unit/bsolver_check.h — a system's structured bordered solver
 * (whirl_system bsolver: the condensation of parameters of periodic
 * collocation and of BVPs) against UMFPACK on the assembled bordered
 * matrix [F_x F_p; r^T] at (X, p): solutions to 1e-12 relative, log|det|
 * and its sign (the branch-point test) equal, for a border r, for -r and
 * for a new r by reborder; the transposed solve (solve_t) of that
 * matrix; then [F_x col; r^T] with a random column (factor_col: a fold
 * system's [F_x b; c^T 0]) and its transposed solve against UMFPACK's of
 * the same matrix; where the solver makes F with the factorisation
 * (factor_F), that F byte for byte the system's F and the factorisation
 * the bytes of factor's.  Included by t_colloc.c and t_bvp.c.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_TEST_BSOLVER_CHECK_H
#define WHIRL_TEST_BSOLVER_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/linsol.h>
#include <whirl/system.h>

#include "../tap.h"

/* given_col: the solver must also take a given column and solve
 * transposed (condensed collocation; a fold system's has neither). */
static void bsolver_check(const char *name, const whirl_system *s,
                          const double *X, const double *p, size_t k, int given_col) {
  const size_t nx = s->n, N1 = nx + 1;
  ok(s->bsolver && s->bsolver->factor && s->bsolver->solve &&
         s->bsolver->logdet && s->bsolver->reborder,
     "%s: the system has a structured solver", name);
  if (!s->bsolver) return;
  double *Jx = malloc(s->nnz * sizeof *Jx), *fk = malloc(nx * sizeof *fk);
  double *wk = malloc((nx + 16) * sizeof *wk), *r = malloc(N1 * sizeof *r);
  double *b1 = malloc(2 * N1 * sizeof *b1), *b2 = malloc(2 * N1 * sizeof *b2);
  void *ws = s->bsolver->alloc(s->data);
  whirl_bordered *bd = whirl_bordered_alloc(WHIRL_LINSOL_SPARSE, nx, 1, s->Jp, s->Ji);
  ok(ws && bd && Jx && fk && wk && r && b1 && b2, "%s: allocations", name);
  if (!ws || !bd || !Jx || !fk || !wk || !r || !b1 || !b2) goto done;
  int rc = s->Fx_sparse(X, p, Jx, s->data);
  if (rc == 0) rc = whirl_system_param(s, X, p, k, fk, wk);
  ok(rc == 0, "%s: Jacobian and F_p", name);
  for (int pass = 0; pass < 3; ++pass) {
    /* a border near the parameter direction (well conditioned away from
     * folds, as the core's tangent rows), then its negative (the
     * determinant changes sign), then a new border by reborder */
    for (size_t q = 0; q < N1; ++q)
      r[q] = pass == 1 ? -r[q]
                       : 0.3 * tap_urand(-1.0, 1.0) / sqrt((double)N1) +
                             (q == nx ? 1.0 : 0.0);
    for (size_t q = 0; q < 2 * N1; ++q) b1[q] = b2[q] = tap_urand(-1.0, 1.0);
    int r1 = pass == 2 ? s->bsolver->reborder(ws, r)
                       : s->bsolver->factor(ws, X, p, k, r);
    int r2 = whirl_bordered_factor(bd, Jx, fk, r, r + nx);
    if (r1 == 0) r1 = s->bsolver->solve(ws, b1, 2);
    if (r2 == 0) r2 = whirl_bordered_solve(bd, b2, 2, 0);
    double la1 = NAN, la2 = NAN, e = 0.0, sc = 0.0;
    int s1 = 9, s2 = 8;
    s->bsolver->logdet(ws, &la1, &s1);
    whirl_bordered_logdet(bd, &la2, &s2);
    for (size_t q = 0; q < 2 * N1; ++q) {
      e = fmax(e, fabs(b1[q] - b2[q]));
      sc = fmax(sc, fabs(b2[q]));
    }
    printf("# %s (%s): |z - z_umfpack| / |z| = %.2e, log|det| %.12g vs %.12g, "
           "sign %d vs %d\n",
           name, pass == 0 ? "factor" : pass == 1 ? "-r" : "reborder", e / sc,
           la1, la2, s1, s2);
    ok(r1 == 0 && r2 == 0 && e <= 1e-12 * sc,
       "%s (%s): structured solve = UMFPACK solve to %.1e relative (<= 1e-12)",
       name, pass == 0 ? "factor" : pass == 1 ? "border -r" : "reborder",
       e / sc);
    ok(s1 == s2 && s1 != 0 && fabs(la1 - la2) <= 1e-10 * fmax(1.0, fabs(la2)),
       "%s (%s): determinant sign %d = %d, log|det| %.10g = %.10g", name,
       pass == 0 ? "factor" : pass == 1 ? "border -r" : "reborder", s1, s2,
       la1, la2);
  }
  if (s->bsolver->factor_F) { /* F with the Jacobian's evaluations */
    double *f1 = malloc(nx * sizeof *f1), *f2 = malloc(nx * sizeof *f2);
    for (size_t q = 0; q < 2 * N1; ++q) b1[q] = b2[q] = tap_urand(-1.0, 1.0);
    int r1 = f1 && f2 ? s->bsolver->factor_F(ws, X, p, k, r, f1) : WHIRL_ENOMEM;
    double la1 = NAN, la2 = NAN;
    int s1 = 9, s2 = 8;
    if (r1 == 0) r1 = s->bsolver->solve(ws, b1, 2);
    s->bsolver->logdet(ws, &la1, &s1);
    int r2 = f1 && f2 ? s->F(X, p, f2, s->data) : WHIRL_ENOMEM;
    if (r2 == 0) r2 = s->bsolver->factor(ws, X, p, k, r);
    if (r2 == 0) r2 = s->bsolver->solve(ws, b2, 2);
    s->bsolver->logdet(ws, &la2, &s2);
    ok(r1 == 0 && r2 == 0 && memcmp(f1, f2, nx * sizeof *f1) == 0,
       "%s (factor_F): F the bytes of the system's F", name);
    ok(r1 == 0 && r2 == 0 && memcmp(b1, b2, 2 * N1 * sizeof *b1) == 0 && la1 == la2 &&
           s1 == s2,
       "%s (factor_F): solutions and determinant the bytes of factor's", name);
    free(f1), free(f2);
  }
  /* a given column and the transposed solve */
  if (!given_col) goto done;
  ok(s->bsolver->factor_col && s->bsolver->solve_t,
     "%s: the structured solver takes a given column and solves transposed", name);
  if (!s->bsolver->factor_col || !s->bsolver->solve_t) goto done;
  { /* the transposed solve after factor: the core's [F_x F_p; r^T] (the
     * left null vector at a branch point, bpstart.c) */
    for (size_t q = 0; q < 2 * N1; ++q) b1[q] = b2[q] = tap_urand(-1.0, 1.0);
    int r1 = s->bsolver->factor(ws, X, p, k, r);
    int r2 = whirl_bordered_factor(bd, Jx, fk, r, r + nx);
    if (r1 == 0) r1 = s->bsolver->solve_t(ws, b1, 2);
    if (r2 == 0) r2 = whirl_bordered_solve(bd, b2, 2, 1);
    double e = 0.0, sc = 0.0;
    for (size_t q = 0; q < 2 * N1; ++q) {
      e = fmax(e, fabs(b1[q] - b2[q]));
      sc = fmax(sc, fabs(b2[q]));
    }
    ok(r1 == 0 && r2 == 0 && e <= 1e-11 * sc,
       "%s ([F_x F_p; r^T], transposed): structured solve = UMFPACK solve to %.1e "
       "relative (<= 1e-11)", name, e / sc);
  }
  for (size_t q = 0; q < nx; ++q) fk[q] = tap_urand(-1.0, 1.0) / sqrt((double)nx);
  for (size_t q = 0; q < N1; ++q) r[q] = tap_urand(-1.0, 1.0) / sqrt((double)N1);
  r[nx] = 0.0;
  for (int trans = 0; trans <= 1; ++trans) {
    for (size_t q = 0; q < 2 * N1; ++q) b1[q] = b2[q] = tap_urand(-1.0, 1.0);
    int r1 = s->bsolver->factor_col(ws, X, p, fk, r);
    int r2 = whirl_bordered_factor(bd, Jx, fk, r, r + nx);
    if (r1 == 0) r1 = trans ? s->bsolver->solve_t(ws, b1, 2) : s->bsolver->solve(ws, b1, 2);
    if (r2 == 0) r2 = whirl_bordered_solve(bd, b2, 2, trans);
    double e = 0.0, sc = 0.0;
    for (size_t q = 0; q < 2 * N1; ++q) {
      e = fmax(e, fabs(b1[q] - b2[q]));
      sc = fmax(sc, fabs(b2[q]));
    }
    ok(r1 == 0 && r2 == 0 && e <= 1e-11 * sc,
       "%s ([F_x col; r^T 0]%s): structured solve = UMFPACK solve to %.1e relative (<= 1e-11)",
       name, trans ? ", transposed" : "", e / sc);
  }
done:
  if (ws) s->bsolver->free(ws);
  whirl_bordered_free(bd);
  free(Jx), free(fk), free(wk), free(r), free(b1), free(b2);
}

#endif

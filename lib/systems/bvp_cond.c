/* lib/systems/bvp_cond.c — the structured linear solver of boundary-value
 * problems (whirl_system bsolver; AUTO-07p's IPS = 4 is solved so): the
 * condensation of parameters of cond_elim.c with a BVP's rows — the
 * collocation rows in the node values, the free parameters and p_k; the
 * NBC boundary conditions (in u(0), u(1) and the globals) as the end rows;
 * the NINT integral conditions and the core's r as the border rows.
 * NFREE = NBC + NINT − n makes the final system square, as AUTO's
 * NFPR = NBC + NINT − NDIM + 1 with the continuation parameter.
 *
 * The entries are made where they go (bvp.c's bvp_fill_block, the same
 * code and numbers as the sparse Jacobian and Fp that the sparse LU
 * factors, so the two solvers agree to rounding; t_bvp checks solutions
 * and determinants): the boundary rows before the intervals, each
 * interval's block and dF/dp_k's rows in the loop that condenses it
 * (cond_elim.c's fill_one, on the intervals' threads: one parallel loop
 * for the Jacobian and its condensation), the integral rows summed over
 * the intervals after it (fill_end).  cond_factor_F makes F as well,
 * from the same evaluations (bvp.c's residual rows and sums).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/status.h>

#include "bvp_impl.h"
#include "cond_elim.h"

/* A workspace's own rows (the integral and boundary rows of the point it
 * factored: two workspaces of one BVP may be factored at two points), and
 * what its last fill does. */
typedef struct bvp_rows {
  whirl_bvp *b;
  size_t nf;    /* 2n + nfree + 1: [x_0 | x_N | free | p_k] */
  double *ic;   /* nint x (nx + 1): the integral rows over M's columns */
  double *bcr;  /* nbc x nf: the boundary rows */
  const char **what; /* NTST: the callback a failed interval's fill names */
  int mode;     /* the fill's COND_FILL_* */
  int fk_here;  /* dF/dp_k made by the fill (COND_FILL_FULL, p_k not free) */
  size_t k;
} bvp_rows;

/* Before the intervals: the parameters, the boundary rows and dF/dp_k's
 * (bvp.c's bvp_fill_bc_rows); the intervals fill their own blocks. */
static int bvp_fill_begin(cond_ws *w, const double *X, const double *p, size_t k,
                          int mode) {
  bvp_rows *R = cond_sys(w);
  whirl_bvp *b = R->b;
  const size_t nx = b->nx, pk = 2 * b->n + b->nfree, fb = b->ncoll;
  double *fk = cond_fk(w);
  R->mode = mode;
  R->k = k;
  R->fk_here = mode == COND_FILL_FULL;
  for (size_t j = 0; j < b->nfree; ++j)
    if (b->free[j] == k) R->fk_here = 0; /* its column is 0 (bvp_Fp) */
  whirl_bvp_params(b, X, p, b->pt);
  if (mode == COND_FILL_FULL) memset(fk, 0, nx * sizeof *fk);
  memset(R->ic, 0, b->nint * (nx + 1) * sizeof *R->ic);
  memset(R->bcr, 0, b->nbc * R->nf * sizeof *R->bcr);
  int rc = bvp_fill_bc_rows(b, X, R->bcr, R->nf, mode != COND_FILL_MONO,
                            R->fk_here ? fk + fb : NULL, k);
  if (rc != 0) return rc; /* with its message (bvp.c) */
  if (cond_F(w) && (rc = bvp_F_boundary(b, X, cond_F(w))) != 0) return rc;
  if (mode == COND_FILL_MONO) return 0;
  for (size_t e = 0; e < b->nbc; ++e) R->bcr[e * R->nf + pk] = fk[fb + e];
  for (size_t t = 0; t < b->nint; ++t)
    R->ic[t * (nx + 1) + nx] = fk[fb + b->nbc + t];
  return 0;
}

/* Interval i's block, on thread t (cond_elim.c's parallel loop): its
 * collocation rows made there (bvp.c), dF/dp_k's column given
 * (COND_FILL_GIVEN) copied in. */
static int bvp_fill_one(cond_ws *w, const double *X, const double *p, size_t k,
                        int mode, size_t i, int thread) {
  (void)p, (void)k;
  bvp_rows *R = cond_sys(w);
  whirl_bvp *b = R->b;
  const size_t n = b->n, m = b->ncol, nm = n * m, ni = n * (m - 1), wc = cond_block_ld(w),
               r0 = i * nm;
  double *B = cond_block(w, i);
  const int rc = bvp_fill_block(b, thread, X, i, B, wc, mode != COND_FILL_MONO,
                                R->fk_here ? cond_fk(w) : NULL, R->k, cond_F(w),
                                &R->what[i]);
  if (rc != 0 || mode != COND_FILL_GIVEN) return rc;
  const double *fk = cond_fk(w) + r0;
  const size_t pk = ni + 2 * n + b->nfree;
  for (size_t rr = 0; rr < nm; ++rr) B[rr * wc + pk] = fk[rr];
  return 0;
}

/* After the intervals: the first failure's message, or the integral rows'
 * sums over the intervals (and dF/dp_k's). */
static int bvp_fill_end(cond_ws *w, size_t bad, int status) {
  bvp_rows *R = cond_sys(w);
  whirl_bvp *b = R->b;
  const size_t nx = b->nx, fi = b->ncoll + b->nbc;
  if (bad < b->ntst) return bvp_block_status(b, status, R->what[bad]);
  if (cond_F(w)) bvp_F_integrals(b, cond_F(w));
  double *fk = cond_fk(w);
  bvp_block_sums(b, R->ic, nx + 1, R->mode != COND_FILL_MONO, R->fk_here ? fk + fi : NULL);
  if (!R->fk_here) return 0;
  for (size_t t = 0; t < b->nint; ++t) {
    if (!isfinite(fk[fi + t])) return WHIRL_EBADFUNC;
    R->ic[t * (nx + 1) + nx] = fk[fi + t];
  }
  return 0;
}

/* Integral condition t < NINT, or the core's r. */
static const double *bvp_border(cond_ws *w, size_t t, const double *r,
                                double *g) {
  const bvp_rows *R = cond_sys(w);
  const whirl_bvp *b = R->b;
  const size_t nn = b->n * b->nnodes, nx = b->nx;
  const double *row = t < b->nint ? R->ic + t * (nx + 1) : r;
  for (size_t e = 0; e < b->nfree; ++e) g[e] = row[nn + e];
  g[b->nfree] = row[nx];
  return row;
}

static void bvp_end_row(cond_ws *w, size_t e, double *a) {
  const bvp_rows *R = cond_sys(w);
  memcpy(a, R->bcr + e * R->nf, R->nf * sizeof *a);
}

static const cond_ops bvp_ops = {NULL,           bvp_border,   bvp_end_row,
                                 bvp_fill_begin, bvp_fill_one, bvp_fill_end,
                                 NULL}; /* the integral rows: filled with
                                         * the intervals, summed after */

static void bs_free(void *ws) {
  if (!ws) return;
  bvp_rows *R = cond_sys(ws);
  cond_free(ws);
  free(R->ic);
  free(R->bcr);
  free(R->what);
  free(R);
}

static void *bs_alloc(void *data) {
  whirl_bvp *b = data;
  const size_t ng = b->nfree + 1, nb = b->nint + 1;
  bvp_rows *R = calloc(1, sizeof *R);
  size_t *gcol = malloc(ng * sizeof *gcol);
  int *blab = malloc(nb * sizeof *blab);
  cond_ws *w = NULL;
  if (R && gcol && blab) {
    R->b = b;
    R->nf = 2 * b->n + ng;
    R->ic = malloc((b->nint * (b->nx + 1) + 1) * sizeof *R->ic);
    R->bcr = malloc((b->nbc * R->nf + 1) * sizeof *R->bcr);
    R->what = calloc(b->ntst, sizeof *R->what);
    for (size_t e = 0; e < b->nfree; ++e) gcol[e] = b->n * b->nnodes + e;
    gcol[b->nfree] = b->nx;
    for (size_t t = 0; t < b->nint; ++t) blab[t] = (int)(b->ncoll + b->nbc + t);
    blab[b->nint] = (int)b->nx;
    /* the intervals condensed on the Jacobian's threads (cond_elim.c's
     * parallel loop; the same bytes on any number) */
    const cond_shape s = {b->n,   b->ncol, b->ntst, b->nx,         ng,
                          nb,     b->npar, gcol,    blab, bvp_threads(b)};
    if (R->ic && R->bcr && R->what) w = cond_alloc(&s, &bvp_ops, R);
  }
  free(gcol);
  free(blab);
  if (!w && R) {
    free(R->ic);
    free(R->bcr);
    free(R->what);
    free(R);
  }
  return w;
}

const whirl_bsolver bvp_bsolver = {bs_alloc,   bs_free,     cond_factor,
                                   cond_solve, cond_logdet, cond_reborder,
                                   cond_factor_col, cond_solve_t, cond_factor_F};

/* lib/systems/bvp_cond.c — the structured linear solver of boundary-value
 * problems (whirl_system bsolver; AUTO-07p's IPS = 4 is solved so): the
 * condensation of parameters of cond_elim.c with a BVP's rows — the
 * collocation rows in the node values, the free parameters and p_k; the
 * NBC boundary conditions (in u(0), u(1) and the globals) as the end rows;
 * the NINT integral conditions and the core's r as the border rows.
 * NFREE = NBC + NINT − n makes the final system square, as AUTO's
 * NFPR = NBC + NINT − NDIM + 1 with the continuation parameter.
 *
 * The entries come from the system's own sparse Jacobian (bvp.c): the
 * boundary rows and dense integral rows before the intervals, each
 * interval's block in the loop that condenses it (cond_elim.c's
 * fill_one, on the intervals' threads), and dF/dp_k from its Fp: the same
 * numbers the sparse LU factors, so the two solvers agree to rounding
 * (t_bvp checks solutions and determinants).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#include <whirl/status.h>

#include "bvp_impl.h"
#include "cond_elim.h"

/* A workspace's own rows (the integral and boundary rows of the point it
 * factored: two workspaces of one BVP may be factored at two points). */
typedef struct bvp_rows {
  whirl_bvp *b;
  size_t nf;    /* 2n + nfree + 1: [x_0 | x_N | free | p_k] */
  double *ic;   /* nint x (nx + 1): the integral rows over M's columns */
  double *bcr;  /* nbc x nf: the boundary rows */
} bvp_rows;

/* The boundary and integral rows' entries of the Jacobian (the last
 * entries of each column, its rows sorted) into R->bcr and R->ic. */
static void scatter_conditions(bvp_rows *R, int mono) {
  const whirl_bvp *b = R->b;
  const size_t n = b->n, nn = n * b->nnodes, nx = b->nx, last = b->nnodes - 1,
               ncoll = b->ncoll;
  for (size_t col = 0; col < nx; ++col) {
    if (mono && col >= nn) break; /* F_x alone: the globals' columns 0 */
    const size_t node = col / n, q = col % n;
    const size_t bpos = col >= nn ? 2 * n + (col - nn)
                        : node == 0 ? q : node == last ? n + q : R->nf;
    for (int e = b->Jp[col + 1]; e-- > b->Jp[col];) {
      const size_t row = (size_t)b->Ji[e];
      if (row < ncoll) break;
      const double v = b->Jx[e];
      if (row < ncoll + b->nbc) {
        if (bpos < R->nf) R->bcr[(row - ncoll) * R->nf + bpos] = v;
      } else {
        R->ic[(row - ncoll - b->nbc) * (nx + 1) + col] = v;
      }
    }
  }
}

/* Before the intervals: the sparse Jacobian and dF/dp_k at (X, p) (each
 * by its own parallel loop), and the boundary and integral rows. */
static int bvp_fill_begin(cond_ws *w, const double *X, const double *p, size_t k,
                          int mode) {
  const int mono = mode == COND_FILL_MONO;
  bvp_rows *R = cond_sys(w);
  whirl_bvp *b = R->b;
  const size_t nx = b->nx, pk = 2 * b->n + b->nfree;
  int rc = bvp_Fx_sparse(X, p, b->Jx, b);
  if (rc != 0) return rc;
  double *fk = cond_fk(w);
  if (mode == COND_FILL_FULL &&
      (rc = whirl_system_param(&b->sys, X, p, k, fk, cond_work(w))) != 0)
    return rc;
  memset(R->ic, 0, b->nint * (nx + 1) * sizeof *R->ic);
  memset(R->bcr, 0, b->nbc * R->nf * sizeof *R->bcr);
  scatter_conditions(R, mono);
  if (mono) return 0;
  for (size_t e = 0; e < b->nbc; ++e) R->bcr[e * R->nf + pk] = fk[b->ncoll + e];
  for (size_t t = 0; t < b->nint; ++t)
    R->ic[t * (nx + 1) + nx] = fk[b->ncoll + b->nbc + t];
  return 0;
}

/* Interval i's block from the sparse Jacobian (cond_elim.c's parallel loop
 * over the intervals): the collocation rows of its m + 1 nodes' columns
 * (each column's rows sorted: those of interval i follow one another),
 * of the free parameters' dense columns, and dF/dp_k. */
static int bvp_fill_one(cond_ws *w, const double *X, const double *p, size_t k,
                        int mode, size_t i, int thread) {
  (void)X, (void)p, (void)k, (void)thread;
  const int mono = mode == COND_FILL_MONO;
  const bvp_rows *R = cond_sys(w);
  const whirl_bvp *b = R->b;
  const size_t n = b->n, m = b->ncol, nm = n * m, nn = n * b->nnodes, nx = b->nx,
               ni = n * (m - 1), wc = cond_block_ld(w), r0 = i * nm;
  double *B = cond_block(w, i);
  memset(B, 0, nm * wc * sizeof *B);
  for (size_t col = n * (i * m); col < n * (i * m + m + 1); ++col) {
    const size_t kk = col / n - i * m, q = col % n;
    const size_t pos = kk == 0 ? ni + q : kk == m ? ni + n + q : (kk - 1) * n + q;
    for (int e = b->Jp[col]; e < b->Jp[col + 1]; ++e) {
      const size_t row = (size_t)b->Ji[e];
      if (row < r0) continue;
      if (row >= r0 + nm) break;
      B[(row - r0) * wc + pos] = b->Jx[e];
    }
  }
  if (mono) return 0;
  for (size_t col = nn; col < nx; ++col) { /* dense: entry Jp[col] + row */
    const double *v = b->Jx + b->Jp[col] + r0;
    const size_t pos = ni + 2 * n + (col - nn);
    for (size_t rr = 0; rr < nm; ++rr) B[rr * wc + pos] = v[rr];
  }
  const double *fk = cond_fk(w) + r0;
  const size_t pk = ni + 2 * n + b->nfree;
  for (size_t rr = 0; rr < nm; ++rr) B[rr * wc + pk] = fk[rr];
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

static const cond_ops bvp_ops = {NULL, bvp_border, bvp_end_row, bvp_fill_begin, bvp_fill_one};

static void bs_free(void *ws) {
  if (!ws) return;
  bvp_rows *R = cond_sys(ws);
  cond_free(ws);
  free(R->ic);
  free(R->bcr);
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
    for (size_t e = 0; e < b->nfree; ++e) gcol[e] = b->n * b->nnodes + e;
    gcol[b->nfree] = b->nx;
    for (size_t t = 0; t < b->nint; ++t) blab[t] = (int)(b->ncoll + b->nbc + t);
    blab[b->nint] = (int)b->nx;
    /* the intervals condensed on the Jacobian's threads (cond_elim.c's
     * parallel loop; the same bytes on any number) */
    const cond_shape s = {b->n,   b->ncol, b->ntst, b->nx,         ng,
                          nb,     b->npar, gcol,    blab, bvp_threads(b)};
    if (R->ic && R->bcr) w = cond_alloc(&s, &bvp_ops, R);
  }
  free(gcol);
  free(blab);
  if (!w && R) {
    free(R->ic);
    free(R->bcr);
    free(R);
  }
  return w;
}

const whirl_bsolver bvp_bsolver = {bs_alloc,   bs_free,     cond_factor,
                                   cond_solve, cond_logdet, cond_reborder,
                                   cond_factor_col, cond_solve_t};

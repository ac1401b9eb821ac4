/* lib/systems/cond_elim.h — private to lib/systems: the structured
 * elimination of a collocation system's bordered Newton matrix (the
 * condensation of parameters of AUTO-07p), shared by the periodic orbits
 * (colloc_cond.c) and the boundary-value problems (bvp_cond.c).
 *
 * The matrix M = [F_x  dF/dp_k; rᵀ] of a collocation system on NTST
 * intervals of NCOL Gauss points, n states, node-major unknowns
 * x = (u_{0,0} .. u_{N,0}, globals), has
 *   - n NCOL collocation rows per interval i, M's rows n (i NCOL) ..,
 *     in the interval's nodes and the ng global unknowns g (the last is
 *     the continuation parameter p_k, M's column nx);
 *   - ne end rows, M's rows n NTST NCOL + e, in u(0), u(1) and g
 *     (periodicity x_N − x_0; or a BVP's boundary conditions);
 *   - nb border rows over all unknowns, eliminated with the pivots of the
 *     collocation rows but never pivots before the last step (a phase
 *     condition, integral conditions, the core's r).
 * ne + nb = n + ng, so the final dense system in [x_0 | x_N | g] is square.
 * cond_elim.c does the three steps (its header comment); the system says
 * where its rows come from through cond_ops.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_COND_ELIM_H
#define WHIRL_COND_ELIM_H

#include <stddef.h>

/* The product of the pivots as mantissa * 2^exponent: no overflow, and no
 * logarithm per pivot. */
typedef struct cond_det {
  double mant; /* sign included */
  long expo;
} cond_det;

typedef struct cond_ws cond_ws;

/* What a fill puts in the global columns (its `mode`): */
enum {
  COND_FILL_FULL = 0,  /* the globals' and dF/dp_k into cond_fk(w) */
  COND_FILL_MONO = 1,  /* F_x alone: every global column 0 (monodromy) */
  COND_FILL_GIVEN = 2  /* the globals', and in p_k's column the entries
                          already in cond_fk(w) (cond_factor_col): no
                          dF/dp_k computed */
};

typedef struct cond_ops {
  /* (Or NULL, with fill_begin and fill_one below.)  Fill the collocation
   * rows of every interval block (cond_block: rows
   * 0 .. n NCOL − 1, columns [interior | x_i | x_{i+1} | g]) and the
   * system's own data for border() and end_row(), at (X, p), the global
   * columns as `mode` says (COND_FILL_*; p_k's column always from
   * cond_fk(w)).  Returns 0, or the model's status. */
  int (*fill)(cond_ws *w, const double *X, const double *p, size_t k,
              int mode);
  /* Border row t: its entries on the node values (node-major as X; the
   * core's r when the system passes it through) returned, its ng global
   * entries into g.  The last border row (t = nb − 1) is the core's r and
   * is returned as r itself: cond_factor eliminates its interior entries
   * in the loop that condenses the intervals, before border() is called. */
  const double *(*border)(cond_ws *w, size_t t, const double *r, double *g);
  /* End row e into a[2n + ng] ([x_0 | x_N | g]), after fill. */
  void (*end_row)(cond_ws *w, size_t e, double *a);
  /* Optional, in place of fill: the system's data before the intervals
   * (fill_begin), then interval i's collocation rows alone (fill_one,
   * called from the loop over the intervals on thread `thread` of
   * cond_shape.nthreads, each block condensed right after it is filled:
   * one parallel loop for both).  Return 0 or the model's status. */
  int (*fill_begin)(cond_ws *w, const double *X, const double *p, size_t k,
                    int mode);
  int (*fill_one)(cond_ws *w, const double *X, const double *p, size_t k,
                  int mode, size_t i, int thread);
  /* Optional, with fill_one: after the loop over the intervals, on one
   * thread: bad = NTST and status 0 when every fill_one succeeded (the
   * system's sums over the intervals, in interval order), else the first
   * interval whose fill_one failed and its status (the system's message).
   * Returns 0 or the status to report. */
  int (*fill_end)(cond_ws *w, size_t bad, int status);
  /* Optional: border row t < nb − 1's node entries (as border() returns
   * them) when they are the system's own and known before the fill (the
   * phase condition of orbits, from its reference), else NULL.  Such rows
   * are eliminated by each interval in the loop that condenses it, as the
   * core's r is; border() must then return the same entries. */
  const double *(*border_early)(cond_ws *w, size_t t);
} cond_ops;

typedef struct cond_shape {
  size_t n, ncol, ntst; /* ntst >= 2 */
  size_t nx;            /* unknowns of F (M has nx + 1) */
  size_t ng, nb, npar;
  const size_t *gcol; /* ng: M's column of each global (the last: nx) */
  const int *blab;    /* nb: M's row of each border row (r: nx) */
  int nthreads;       /* threads of the loops over the intervals (0, 1:
                         serial); fill is the system's own */
} cond_shape;

cond_ws *cond_alloc(const cond_shape *s, const cond_ops *ops, void *sys);
void cond_free(cond_ws *w);
void *cond_sys(const cond_ws *w);
double *cond_block(cond_ws *w, size_t i); /* interval i's block, rows of */
size_t cond_block_ld(const cond_ws *w);   /* this many entries */
double *cond_fk(cond_ws *w);              /* dF/dp_k, nx */
double *cond_work(cond_ws *w);            /* nx + npar scratch for fill */
/* Where the fill also puts F(X, p) (nx), during cond_factor_F; else NULL.
 * A system whose fill honours it offers cond_factor_F in its bsolver. */
double *cond_F(const cond_ws *w);

/* The entry points take the workspace as void * so that a system's
 * whirl_bsolver table holds them as they are. */

/* M at (X, p, k, r) factored: fill, the condensation and the final LU.
 * 0, the model's status, WHIRL_ESINGULAR, WHIRL_EBADFUNC. */
int cond_factor(void *ws, const double *X, const double *p, size_t k,
                const double *r);
/* As cond_factor, and F(X, p) into f[nx] by the system's fill from the
 * evaluations the Jacobian makes (AUTO's SETUBV: the residual with the
 * Jacobian), the bytes its F gives.  f is complete when it returns 0. */
int cond_factor_F(void *ws, const double *X, const double *p, size_t k,
                  const double *r, double *f);
/* M with the column col[nx] (M's rows) in place of dF/dp_k, factored:
 * [F_x col; r^T], e.g. the fold system's [F_x b; c^T 0].  As cond_factor. */
int cond_factor_col(void *ws, const double *X, const double *p,
                    const double *col, const double *r);
/* The same collocation rows with a new border row r (chord Newton). */
int cond_reborder(void *ws, const double *r);
/* M z = b in place, b[(nx + 1) nrhs]. */
int cond_solve(void *ws, double *b, size_t nrhs);
/* M^T y = c in place, c[(nx + 1) nrhs] (the adjoint of cond_solve's
 * steps in reverse order: no second factorisation). */
int cond_solve_t(void *ws, double *b, size_t nrhs);
int cond_logdet(void *ws, double *logabs, int *sign);

/* Were the collocation rows last factored at (X, p)? */
int cond_factored_at(const cond_ws *w, const double *X, const double *p);
/* The collocation rows alone at (X, p) (mono fill). */
int cond_factor_rows(cond_ws *w, const double *X, const double *p);
/* M[n n] = −S_N⁻¹ S_0 from the rows left after step 2 (monodromy of a
 * periodic orbit), after cond_factor or cond_factor_rows. */
int cond_monodromy(cond_ws *w, double *M);

#endif

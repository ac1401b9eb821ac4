/* lib/systems/cond_elim.c — the structured solver of collocation systems
 * (cond_elim.h): the bordered Newton matrix of the continuation core
 *     M = [F_x  dF/dp_k; r^T]
 * factored without assembling it, as AUTO-07p does (Doedel, Keller &
 * Kernévez, Int. J. Bif. Chaos 1 (1991) 745, §6; AUTO-07p manual ch. 10;
 * the block elimination of Ascher, Mattheij & Russell, Numerical Solution of
 * BVPs for ODEs, §7.3):
 *
 *  1. Condensation of parameters.  The NCOL·n collocation equations of mesh
 *     interval i involve its (NCOL − 1)·n interior unknowns, its two mesh
 *     points and the global unknowns g (the period T of an autonomous orbit,
 *     a BVP's free parameters, and the continuation parameter).  Gaussian
 *     elimination with partial pivoting (within the interval's rows) of the
 *     interior unknowns leaves n equations  A_i x_i + C_i x_{i+1} + G_i g =
 *     r_i  per interval.  The border rows (phase condition, integral
 *     conditions, pseudo-arclength) are eliminated with the same pivot rows
 *     but are never pivots themselves, so they are done after the
 *     collocation rows and a new border row (chord Newton, the next step's
 *     arclength row) only redoes them and step 3.
 *  2. The mesh points x_1 .. x_{NTST−1} are eliminated in turn: x_j from the
 *     2n rows (the n rows left over so far, in x_0, x_j and g, and the n
 *     rows of interval j), with partial pivoting among them.  What is left
 *     are n rows  S_0 x_0 + S_N x_N + S_g g = s.
 *  3. Those n rows, the system's end rows (periodicity x_N − x_0 = 0, or the
 *     boundary conditions) and the border rows form a dense system of order
 *     2n + (number of globals), solved by LU.
 *
 * Every step is Gaussian elimination of M with rows and columns taken in a
 * particular order, so P M Q = L U and det M = sgn(P) sgn(Q) prod U_kk:
 * the determinant (branch-point test) is that of M, with the sign of the
 * row and column orders counted from the order in which they were used.
 *
 * The n rows of step 2 also give the monodromy matrix of a discretised
 * orbit, the transfer x_N = −S_N^{-1} S_0 x_0 of the linearised collocation
 * equations at fixed globals, whose eigenvalues are AUTO's Floquet
 * multipliers (Fairgrieve & Jepson, SIAM J. Numer. Anal. 28 (1991) 1446,
 * discuss its accuracy; fine for moderate multipliers).
 *
 * Threads: the intervals of step 1 (and of a solve's forward and back
 * substitutions) are shared by the threads of a governed loop, each
 * taking its part in order: the main thread the first intervals, which
 * it follows with the chain of step 2, link j once interval j is done,
 * and then the chain behind the other threads' intervals; its share moves
 * after each factorisation towards the balance (cond_balance: the chain
 * is its extra work), and the solves take the same shares, so each thread
 * reads the blocks it wrote from its own cache (taking intervals as they
 * come, a few at a time, balanced the work but moved the blocks between
 * the caches: demo fnc's run 20 was slower than with static halves).
 * AUTO-07p instead runs each thread's part of the mesh, then a coarse
 * system: other arithmetic on other thread counts.  Here each link and
 * each interval does the same operations in the same order on any
 * number of threads, so the results are the same bytes.
 *
 * Blocks are row-major: the eliminations work on rows.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/status.h>

#include "cond_elim.h"
#include "util/short_copy.h"
#include "util/threads_impl.h"

typedef cond_det det_acc;

struct cond_ws {
  const cond_ops *ops;
  void *sys;
  size_t n, m, N, nx;
  size_t ni;  /* interior unknowns per interval, n (NCOL − 1) */
  size_t nm;  /* collocation rows per interval, n NCOL */
  size_t ng;  /* global unknowns (the last: p_k) */
  size_t nb;  /* border rows */
  size_t ne;  /* end rows: 2n + ng − n − nb */
  size_t wr, wc; /* interval block: nm + nb rows, ni + 2n + ng columns */
  size_t pr, pc; /* mesh-point block: 2n + nb rows, 3n + ng columns */
  size_t nf;     /* final dense system: 2n + ng */
  size_t bc;     /* reduced border rows: n (NTST + 1) + ng columns */
  size_t *gcol;  /* ng: M's column of each global */
  int *blab;     /* nb: M's row of each border row */
  double *W;     /* NTST interval blocks */
  int *wpiv;     /* NTST * ni pivot rows */
  int *wlab;     /* NTST * n: M's row of each condensed row */
  double *P;     /* NTST − 1 mesh-point blocks (for x_1 .. x_{NTST−1}) */
  int *ppiv;     /* (NTST − 1) * n */
  double *B;     /* nb x bc: border rows on the mesh points and globals */
  double *F;     /* nf x nf */
  int *fpiv;     /* nf */
  int nth;       /* threads of the loops over the intervals */
  whirl_gov gov; /* condense_and_chain's threads of those (threads_impl.h) */
  int nth_last;  /* the threads of the last condensation, which the solves'
                  * loops take too */
  double *ysc;   /* each thread's back values in the solve (2n + ng), a
                    slice of ystride a thread (whirl_thread_alloc) */
  size_t ystride;
  size_t nlab;   /* max(nm, 2n, nf), rounded up to whole cache lines */
  int *lab;      /* scratch labels, nlab per thread (thread 0's first;
                    whirl_thread_alloc: no line shared between threads) */
  det_acc *idet; /* NTST: the product of each interval's pivots */
  unsigned char *done; /* NTST: interval i condensed (step 1's loop on
                        * several threads, read by the chain of step 2
                        * that follows it on the main thread) */
  size_t split;  /* intervals [0, split) are the main thread's in those
                  * loops, the rest the other threads' in equal parts (the
                  * same for the solves: each thread reads the blocks it
                  * wrote); moved by cond_balance */
  size_t low;    /* the solve's back substitution: the lowest mesh point
                  * known so far (NTST: none) */
  double *cpv;   /* (NTST − 1) n: the pivots of step 2, multiplied into
                  * det_c after the intervals' (the serial order) */
  int *clab;     /* 2n: the labels step 2 carries from block to block */
  int *irc;      /* NTST: each interval's gepp status */
  int *frc;      /* NTST: each interval's fill status (fill_one) */
  int *prow, *pcol; /* nx + 1: M's rows and columns in elimination order */
  int *mark;     /* nx + 1: scratch for the permutation signs */
  double *fk;    /* nx: dF/dp_k */
  double *Fout;  /* nx: F, during cond_factor_F (cond_F), else NULL */
  double *work;  /* nx + npar: the system's scratch in fill */
  double *loc;   /* NTST * wr: transformed right-hand sides of the intervals */
  double *ploc;  /* (NTST − 1) * pr: those of the mesh-point blocks */
  double *xs;    /* n (NTST + 1) + ng: mesh-point values and globals */
  double *bb;    /* nb */
  double *tmp;   /* 3 nf: the final right-hand side, solution, back values */
  det_acc det_c; /* product of the pivots of the collocation rows */
  size_t npiv_c; /* their number */
  int sign_c;    /* sign of the row and column orders (see factor_rows),
                  * 0 until cond_logdet asks for it */
  int sign_col;  /* the column order's alone (fixed by the shape), 0 until known */
  int jac_ok;    /* the collocation rows are factored (at Xf, pf) */
  double *Xf, *pf;
  size_t npar;
  int *slab;     /* n: M's rows of the n rows left after step 2 */
  double *mblk;  /* 2n^2 + 2n: the monodromy matrix */
  int *mpiv, *mlab; /* n each */
  const double **bsrc; /* nb: the border rows whose interior entries each
                        * interval eliminates in the loop that condenses it
                        * (cond_factor: the core's r, the last, and the
                        * system's border_early rows), else NULL */
  unsigned char *bdone; /* nb: the row's intervals' part done by that loop */
  det_acc det;   /* product of all the pivots */
  double logabs; /* log|det M| and its sign, when factored: */
  int sign_f;    /* the sign of the pivots' product and of the final
                  * system's swaps; det M's is sign_f sign_c */
  int state; /* 0 none, 1 factored, 2 singular */
};

void cond_free(cond_ws *w) {
  if (!w) return;
  void *p[] = {w->gcol, w->blab, w->W,    w->wpiv, w->wlab, w->P,   w->ppiv,
               w->B,    w->F,    w->fpiv, w->lab,  w->prow, w->pcol, w->mark,
               w->fk,   w->work, w->loc,  w->ploc, w->xs,   w->bb,   w->tmp,
               w->Xf,   w->pf,   w->slab, w->mblk, w->mpiv, w->mlab,
               w->idet, w->irc,  w->frc,  w->ysc,  w->bsrc, w->bdone,
               w->done, w->cpv,  w->clab};
  for (size_t i = 0; i < sizeof p / sizeof *p; ++i) free(p[i]);
  free(w);
}

cond_ws *cond_alloc(const cond_shape *s, const cond_ops *ops, void *sys) {
  if (s->ntst < 2 || s->nb + s->n > 2 * s->n + s->ng || s->ng < 1) return NULL;
  cond_ws *w = calloc(1, sizeof *w);
  if (!w) return NULL;
  const size_t n = s->n, m = s->ncol, N = s->ntst;
  w->ops = ops;
  w->sys = sys;
  w->n = n;
  w->m = m;
  w->N = N;
  w->nx = s->nx;
  w->ni = n * (m - 1);
  w->nm = n * m;
  w->ng = s->ng;
  w->nb = s->nb;
  w->ne = n + s->ng - s->nb;
  w->wr = w->nm + w->nb;
  w->wc = w->ni + 2 * n + w->ng;
  w->pr = 2 * n + w->nb;
  w->pc = 3 * n + w->ng;
  w->nf = 2 * n + w->ng;
  w->bc = n * (N + 1) + w->ng;
  size_t nlab = w->nm > w->nf ? w->nm : w->nf;
  if (2 * n > nlab) nlab = 2 * n;
  w->nlab = whirl_thread_stride(nlab, sizeof *w->lab);
  w->ystride = whirl_thread_stride(w->nf, sizeof *w->ysc);
  w->nth = s->nthreads > 1 ? s->nthreads : 1;
  whirl_gov_init(&w->gov, w->nth);
  const size_t nth = (size_t)w->nth;
  const size_t np = s->npar ? s->npar : 1;
  w->npar = np;
  w->gcol = malloc(w->ng * sizeof *w->gcol);
  w->blab = malloc(w->nb * sizeof *w->blab);
  w->W = malloc(N * w->wr * w->wc * sizeof *w->W);
  w->wpiv = malloc((N * w->ni + 1) * sizeof *w->wpiv);
  w->wlab = malloc(N * n * sizeof *w->wlab);
  w->P = malloc((N - 1) * w->pr * w->pc * sizeof *w->P);
  w->ppiv = malloc((N - 1) * n * sizeof *w->ppiv);
  w->B = malloc(w->nb * w->bc * sizeof *w->B);
  w->F = malloc(w->nf * w->nf * sizeof *w->F);
  w->fpiv = malloc(w->nf * sizeof *w->fpiv);
  w->lab = whirl_thread_alloc(nth, w->nlab, sizeof *w->lab);
  w->idet = malloc(N * sizeof *w->idet);
  w->irc = malloc(N * sizeof *w->irc);
  w->frc = malloc(N * sizeof *w->frc);
  w->prow = malloc((w->nx + 1) * sizeof *w->prow);
  w->pcol = malloc((w->nx + 1) * sizeof *w->pcol);
  w->mark = malloc((w->nx + 1) * sizeof *w->mark);
  w->fk = malloc(w->nx * sizeof *w->fk);
  w->work = malloc((w->nx + np) * sizeof *w->work);
  w->loc = malloc(N * w->wr * sizeof *w->loc);
  w->ploc = malloc((N - 1) * w->pr * sizeof *w->ploc);
  w->xs = malloc((n * (N + 1) + w->ng) * sizeof *w->xs);
  w->bb = malloc(w->nb * sizeof *w->bb);
  w->tmp = malloc(3 * w->nf * sizeof *w->tmp);
  w->Xf = malloc(w->nx * sizeof *w->Xf);
  w->pf = malloc(np * sizeof *w->pf);
  w->slab = malloc(n * sizeof *w->slab);
  w->mblk = malloc((2 * n * n + 2 * n) * sizeof *w->mblk);
  w->mpiv = malloc(n * sizeof *w->mpiv);
  w->mlab = malloc(n * sizeof *w->mlab);
  w->ysc = whirl_thread_alloc(nth, w->ystride, sizeof *w->ysc);
  w->bsrc = calloc(w->nb, sizeof *w->bsrc);
  w->bdone = calloc(w->nb, sizeof *w->bdone);
  w->done = malloc(N * sizeof *w->done);
  w->split = N / 2;
  w->cpv = malloc((N * n + 1) * sizeof *w->cpv);
  w->clab = malloc(2 * n * sizeof *w->clab);
  w->nth_last = 1;
  if (!w->gcol || !w->blab || !w->W || !w->wpiv || !w->wlab || !w->P ||
      !w->ppiv || !w->B || !w->F || !w->fpiv || !w->lab || !w->prow ||
      !w->pcol || !w->mark || !w->fk || !w->work || !w->loc || !w->ploc ||
      !w->xs || !w->bb || !w->tmp || !w->Xf || !w->pf || !w->slab ||
      !w->mblk || !w->mpiv || !w->mlab || !w->idet || !w->irc ||
      !w->frc || !w->ysc || !w->bsrc || !w->bdone || !w->done || !w->cpv ||
      !w->clab) {
    cond_free(w);
    return NULL;
  }
  memcpy(w->gcol, s->gcol, w->ng * sizeof *w->gcol);
  memcpy(w->blab, s->blab, w->nb * sizeof *w->blab);
  return w;
}

void *cond_sys(const cond_ws *w) { return w->sys; }
double *cond_block(cond_ws *w, size_t i) { return w->W + i * w->wr * w->wc; }
size_t cond_block_ld(const cond_ws *w) { return w->wc; }
double *cond_fk(cond_ws *w) { return w->fk; }
double *cond_work(cond_ws *w) { return w->work; }
double *cond_F(const cond_ws *w) { return w->Fout; }

/* ------------------------------------------------------------ kernels */

/* a[k] -= l u[k], k < len: the update of every elimination, unrolled by
 * four so that it runs at full speed without auto-vectorisation (-O2). */
static inline void row_update(double *restrict a, const double *restrict u,
                              double l, size_t len) {
  size_t k = 0;
  for (; k + 4 <= len; k += 4) {
    a[k] -= l * u[k];
    a[k + 1] -= l * u[k + 1];
    a[k + 2] -= l * u[k + 2];
    a[k + 3] -= l * u[k + 3];
  }
  for (; k < len; ++k) a[k] -= l * u[k];
}

static void det_mul(det_acc *d, double v) {
  int e;
  d->mant = frexp(d->mant * v, &e);
  d->expo += e;
}

/* d *= a (a product of pivots of its own) */
static void det_times(det_acc *d, const det_acc *a) {
  det_mul(d, a->mant);
  d->expo += a->expo;
}

/* Gaussian elimination with partial pivoting of the first ne columns of the
 * row-major block A (rows of ld entries): pivots are sought among the first
 * np rows; the next nextra rows (borders) are eliminated but never pivot.
 * Whole rows are swapped (LAPACK's convention: P A = L U, apply all the
 * swaps first when solving); lab[np] follows the swaps.  The diagonal of U
 * is stored as its reciprocal (the solves multiply).  Multiplies the
 * pivots into *det, or with pv stores them in pv[ne] (the caller
 * multiplies them in later, in its order); *nswaps (may be NULL) the
 * number of row swaps.  Returns 0, or 1 at a zero pivot column (exactly
 * singular), or 2 at a non-finite pivot. */
static int gepp(double *A, size_t ld, size_t np, size_t nextra, size_t ne,
                int *piv, int *lab, det_acc *det, double *pv, int *nswaps) {
  int swaps = 0;
  for (size_t c = 0; c < ne; ++c) {
    size_t pr = c;
    double best = fabs(A[c * ld + c]);
    for (size_t r = c + 1; r < np; ++r) {
      const double v = fabs(A[r * ld + c]);
      if (v > best) best = v, pr = r;
    }
    piv[c] = (int)pr;
    if (!isfinite(best)) return 2;
    if (!(best > 0.0)) return 1;
    if (pr != c) {
      double *a = A + c * ld, *b = A + pr * ld;
      for (size_t k = 0; k < ld; ++k) {
        const double t = a[k];
        a[k] = b[k];
        b[k] = t;
      }
      const int t = lab[c];
      lab[c] = lab[pr];
      lab[pr] = t;
      ++swaps;
    }
    double *u = A + c * ld;
    const double d = u[c], dinv = 1.0 / d;
    if (pv)
      pv[c] = d;
    else
      det_mul(det, d);
    u[c] = dinv; /* U is kept with reciprocal diagonal */
    for (size_t r = c + 1; r < np + nextra; ++r) {
      double *a = A + r * ld;
      const double l = a[c] * dinv;
      a[c] = l;
      if (l != 0.0) row_update(a + c + 1, u + c + 1, l, ld - c - 1);
    }
  }
  if (nswaps) *nswaps = swaps;
  return 0;
}

/* Dot product of a[k] and b[k], k < len, with four partial sums (the
 * dependency chain of one sum, not the arithmetic, limits a scalar loop). */
static inline double dot4(const double *restrict a, const double *restrict b,
                          size_t len) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  size_t k = 0;
  for (; k + 4 <= len; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
  for (; k < len; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

/* The forward part of a solve with a gepp block: the swaps, then L, row by
 * row (contiguous dot products). */
static void gepp_forward(const double *A, size_t ld, size_t np, size_t nextra,
                         size_t ne, const int *piv, double *b) {
  for (size_t c = 0; c < ne; ++c)
    if ((size_t)piv[c] != c) {
      const double t = b[c];
      b[c] = b[piv[c]];
      b[piv[c]] = t;
    }
  for (size_t r = 1; r < np + nextra; ++r)
    b[r] -= dot4(A + r * ld, b, r < ne ? r : ne);
}

/* The backward part: the eliminated unknowns x[ne] from the transformed
 * right-hand side b[ne] and the values y[ny] of the next ny columns. */
static void gepp_back(const double *A, size_t ld, size_t ne, size_t ny,
                      const double *b, const double *y, double *x) {
  for (size_t c = ne; c-- > 0;) {
    const double *a = A + c * ld;
    const double s = b[c] - dot4(a + c + 1, x + c + 1, ne - c - 1) -
                     dot4(a + ne, y, ny);
    x[c] = s * a[c];
  }
}

/* The adjoint of gepp_forward (b <- L^{-1} P b): b <- P^T L^{-T} b, L's
 * rows taken last to first (each an update of the contiguous row), then
 * the swaps in reverse order. */
static void gepp_forward_t(const double *A, size_t ld, size_t np, size_t nextra,
                           size_t ne, const int *piv, double *b) {
  for (size_t r = np + nextra; r-- > 1;)
    if (b[r] != 0.0) row_update(b, A + r * ld, b[r], r < ne ? r : ne);
  for (size_t c = ne; c-- > 0;)
    if ((size_t)piv[c] != c) {
      const double t = b[c];
      b[c] = b[piv[c]];
      b[piv[c]] = t;
    }
}

/* The adjoint of gepp_back (x = U^{-1} (b - Y y)): given xbar[ne], turned
 * in place into s = U^{-T} xbar, bbar[ne] += s and ybar[ny] -= Y^T s. */
static void gepp_back_t(const double *A, size_t ld, size_t ne, size_t ny,
                        double *s, double *bbar, double *ybar) {
  for (size_t c = 0; c < ne; ++c) {
    const double *a = A + c * ld;
    const double sc = s[c] * a[c]; /* reciprocal diagonal */
    s[c] = sc;
    bbar[c] += sc;
    if (sc == 0.0) continue;
    row_update(s + c + 1, a + c + 1, sc, ne - c - 1);
    if (ny) row_update(ybar, a + ne, sc, ny);
  }
}

/* Sign of a permutation perm[len] of 0..len−1 (cycle count); mark[len]. */
static int perm_sign(const int *perm, size_t len, int *mark) {
  int s = 1;
  memset(mark, 0, len * sizeof *mark);
  for (size_t i = 0; i < len; ++i) {
    if (mark[i]) continue;
    size_t j = i, cyc = 0;
    while (!mark[j]) {
      mark[j] = 1;
      j = (size_t)perm[j];
      ++cyc;
    }
    if (cyc % 2 == 0) s = -s;
  }
  return s;
}

/* ------------------------------------------------------------ factor */

/* The n rows left after condensing interval i: its block's rows ni..nm−1,
 * columns ni.. = [x_i | x_{i+1} | g]. */
static const double *cond_rows(const cond_ws *w, size_t i) {
  return w->W + i * w->wr * w->wc + w->ni * w->wc + w->ni;
}

/* A border row b (ld entries) eliminated by the ne pivot rows of a gepp
 * block A: its multipliers replace b[0..ne−1], and the rest of b is
 * updated.  The same arithmetic as gepp applies to its extra rows, so
 * borders may be (re)done after the collocation rows. */
static void border_eliminate(const double *A, size_t ld, size_t ne,
                             double *b) {
  for (size_t c = 0; c < ne; ++c) {
    const double *u = A + c * ld;
    const double l = b[c] * u[c]; /* reciprocal diagonal */
    b[c] = l;
    if (l != 0.0) row_update(b + c + 1, u + c + 1, l, ld - c - 1);
  }
}

static int singular(cond_ws *w) {
  w->state = 2;
  return WHIRL_ESINGULAR;
}

/* Border row t's interior entries src on interval i eliminated by the
 * interval's pivot rows (row nm + t of its block: its multipliers, then
 * its entries on [x_i | x_{i+1} | g] for reduce_border_intervals). */
static void border_interval(cond_ws *w, size_t t, const double *src, size_t i) {
  const size_t n = w->n, m = w->m, ni = w->ni, wc = w->wc;
  double *Wi = w->W + i * w->wr * wc;
  double *a = Wi + (w->nm + t) * wc;
  whirl_copy_short(a, src + n * (i * m + 1), ni);
  whirl_zero_short(a + ni, 2 * n + w->ng);
  border_eliminate(Wi, wc, ni, a);
}

/* Step 1 on interval i's block, with labels lab[nm]: its pivots' product
 * into idet[i], its pivot rows and columns in elimination order (all of
 * interval i's after those of the intervals before it).  gepp's status. */
static int condense_interval(cond_ws *w, size_t i, int *lab) {
  const size_t n = w->n, m = w->m, ni = w->ni, nm = w->nm;
  double *Wi = w->W + i * w->wr * w->wc;
  for (size_t q = 0; q < nm; ++q) lab[q] = (int)(n * i * m + q);
  w->idet[i].mant = 1.0;
  w->idet[i].expo = 0;
  int rc = gepp(Wi, w->wc, nm, 0, ni, w->wpiv + i * ni, lab, &w->idet[i], NULL, NULL);
  if (rc != 0) return rc;
  for (size_t q = 0; q < ni; ++q) {
    w->prow[i * ni + q] = lab[q];
    w->pcol[i * ni + q] = (int)(n * (i * m + 1 + q / n) + q % n);
  }
  for (size_t q = 0; q < n; ++q) w->wlab[i * n + q] = lab[ni + q];
  return 0;
}

/* Step 1 on interval i, on thread t's scratch: its block filled
 * (fill_one, when the system has it) and condensed, the border rows of
 * bsrc eliminated by it; then done[i] set, after all of that (release:
 * step 2, on the main thread, reads the block once it sees the flag). */
static void condense_one(cond_ws *w, const double *X, const double *p, size_t k,
                         int mode, size_t i, int t) {
  const cond_ops *ops = w->ops;
  w->frc[i] = ops->fill_one ? ops->fill_one(w, X, p, k, mode, i, t) : 0;
  w->irc[i] = w->frc[i] ? 0 : condense_interval(w, i, w->lab + w->nlab * (size_t)t);
  if (!w->frc[i] && !w->irc[i])
    for (size_t b = 0; b < w->nb; ++b)
      if (w->bsrc[b]) border_interval(w, b, w->bsrc[b], i);
  __atomic_store_n(&w->done[i], 1, __ATOMIC_RELEASE);
}

/* Step 2's link j (1 <= j < NTST): the mesh point x_j eliminated from
 * the n rows left over from the links before (interval 0's at j = 1) and
 * interval j's; block columns [x_j | x_0 | x_{j+1} | g].  Its pivots into
 * cpv (multiplied into det_c after the intervals', in link order), its
 * rows and columns at their place in the elimination order.  0, or
 * WHIRL_EBADFUNC, or WHIRL_ESINGULAR. */
static int chain_link(cond_ws *w, size_t j) {
  const size_t n = w->n, m = w->m, ng = w->ng, wc = w->wc, pc = w->pc;
  double *Pj = w->P + (j - 1) * w->pr * pc;
  for (size_t q = 0; q < n; ++q) {
    double *a = Pj + q * pc;
    if (j == 1) {
      const double *s = cond_rows(w, 0) + q * wc; /* [x_0 | x_1 | g] */
      whirl_copy_short(a, s + n, n);
      whirl_copy_short(a + n, s, n);
      whirl_copy_short(a + 3 * n, s + 2 * n, ng);
    } else {
      const double *s = w->P + (j - 2) * w->pr * pc + (n + q) * pc;
      whirl_copy_short(a, s + 2 * n, n); /* x_j */
      whirl_copy_short(a + n, s + n, n); /* x_0 */
      whirl_copy_short(a + 3 * n, s + 3 * n, ng);
    }
    whirl_zero_short(a + 2 * n, n);
    const double *s = cond_rows(w, j) + q * wc; /* [x_j | x_{j+1} | g] */
    double *b = Pj + (n + q) * pc;
    whirl_copy_short(b, s, n);
    whirl_zero_short(b + n, n);
    whirl_copy_short(b + 2 * n, s + n, n);
    whirl_copy_short(b + 3 * n, s + 2 * n, ng);
    w->clab[n + q] = w->wlab[j * n + q];
  }
  const int rc = gepp(Pj, pc, 2 * n, 0, n, w->ppiv + (j - 1) * n, w->clab, NULL,
                      w->cpv + (j - 1) * n, NULL);
  if (rc == 2) return WHIRL_EBADFUNC;
  if (rc == 1) return WHIRL_ESINGULAR;
  const size_t at = w->N * w->ni + (j - 1) * n;
  for (size_t q = 0; q < n; ++q) {
    w->prow[at + q] = w->clab[q];
    w->pcol[at + q] = (int)(n * (j * m) + q);
    w->clab[q] = w->clab[n + q]; /* the rows left over go on */
  }
  return 0;
}

/* Step 2 as far as the condensed intervals allow, on the main thread:
 * link j once interval j is done (the links before it done).  It stops
 * for good at an interval that failed (its status is reported in
 * interval order after step 1) or at a link that failed (chain_rc). */
static void chain_advance(cond_ws *w, size_t *next, int *stop, int *chain_rc) {
  const size_t n = w->n;
  while (!*stop && *next < w->N) {
    const size_t j = *next;
    if (!__atomic_load_n(&w->done[j], __ATOMIC_ACQUIRE)) return;
    if (w->frc[j] || w->irc[j]) {
      *stop = 1;
      return;
    }
    if (j == 0) {
      for (size_t q = 0; q < n; ++q) w->clab[q] = w->wlab[q];
    } else if ((*chain_rc = chain_link(w, j)) != 0) {
      *stop = 1;
      return;
    }
    ++*next;
  }
}

/* A pause in a wait for another thread's progress */
#if defined(__x86_64__) || defined(__i386__)
#define WHIRL_SPIN_PAUSE() __builtin_ia32_pause()
#else
#define WHIRL_SPIN_PAUSE() ((void)0)
#endif

/* Thread t's intervals [*lo, *hi) of nth in the loops over intervals:
 * the main thread's first, [0, split), then the other threads' equal
 * parts of the rest, each taken in order. */
static void thread_range(const cond_ws *w, int t, int nth, size_t *lo, size_t *hi) {
  const size_t N = w->N, s = nth > 1 ? w->split : N, nw = (size_t)(nth > 1 ? nth - 1 : 1);
  if (t == 0) {
    *lo = 0;
    *hi = s;
    return;
  }
  const size_t k = (size_t)t - 1;
  *lo = s + (N - s) * k / nw;
  *hi = s + (N - s) * (k + 1) / nw;
}

static double cond_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The main thread's share moved towards the balance of the last loop
 * (monotonic seconds): main_free, when the main thread first waited for
 * another thread's interval (its own and the chain behind them done),
 * main_end when it finished the chain, other_end when the last other
 * thread finished: more intervals for the main thread when it waited,
 * fewer when it finished last by more than a link or two.  By 1/64 of
 * the mesh (at least one interval): the shares then stay put within a
 * few intervals, and with them the blocks in each thread's cache. */
static void cond_balance(cond_ws *w, double main_free, double main_end, double other_end) {
  const size_t N = w->N, step = N / 64 ? N / 64 : 1;
  const double slack = 2e-6;
  if (main_free + slack < other_end && w->split + step < N)
    w->split += step;
  else if (main_end > other_end + slack && w->split > step)
    w->split -= step;
}

/* Steps 1 and 2: the intervals condensed on the governed threads, each
 * its share in order (thread_range); the main thread eliminates the mesh
 * points (step 2, a chain from interval to interval) behind its own
 * intervals, then behind the other threads'.  The
 * statuses are taken in interval order, the model's first, and the
 * determinant's factors are multiplied in the serial order (the
 * intervals', then the links'), so nothing depends on the threads. */
static int condense_and_chain(cond_ws *w, const double *X, const double *p, size_t k,
                              int mode) {
  const size_t N = w->N, n = w->n;
  const int nth = whirl_gov_begin(&w->gov);
  size_t next = 0;
  int stop = 0, chain_rc = 0;
  w->nth_last = nth;
  memset(w->done, 0, N * sizeof *w->done);
  double main_end = 0.0, main_free = 0.0, other_end = 0.0;
  int team = 1; /* the threads the region got (it may get fewer) */
#pragma omp parallel num_threads(nth) if (nth > 1)
  {
    const int t = whirl_thread_num();
    size_t lo, hi;
    thread_range(w, t, whirl_team_size(), &lo, &hi);
    for (size_t i = lo; i < hi; ++i) {
      condense_one(w, X, p, k, mode, i, t);
      if (t == 0) chain_advance(w, &next, &stop, &chain_rc);
    }
    if (t == 0) {
      /* the chain behind the other threads' intervals; free_at: the
       * first wait for one of theirs */
      double free_at = 0.0;
      team = whirl_team_size();
      while (!stop && next < N) {
        const size_t before = next;
        chain_advance(w, &next, &stop, &chain_rc);
        if (next == before) {
          if (team > 1 && free_at == 0.0) free_at = cond_now();
          WHIRL_SPIN_PAUSE();
        }
      }
      if (team > 1) {
        main_end = cond_now();
        main_free = free_at > 0.0 ? free_at : main_end;
      }
    } else {
      const double e = cond_now();
#pragma omp critical(whirl_cond_end)
      if (e > other_end) other_end = e;
    }
  }
  if (team > 1) cond_balance(w, main_free, main_end, other_end);
  whirl_gov_end(&w->gov);
  const cond_ops *ops = w->ops;
  size_t bad = 0;
  while (bad < N && !w->frc[bad]) ++bad;
  if (ops->fill_end) {
    const int rc = ops->fill_end(w, bad, bad < N ? w->frc[bad] : 0);
    if (rc != 0) return rc;
  } else if (bad < N) {
    return w->frc[bad];
  }
  for (size_t i = 0; i < N; ++i) {
    if (w->irc[i] == 2) return WHIRL_EBADFUNC;
    if (w->irc[i] == 1) return singular(w);
    det_times(&w->det_c, &w->idet[i]);
  }
  for (size_t b = 0; b < w->nb; ++b) w->bdone[b] = w->bsrc[b] != NULL;
  if (chain_rc == WHIRL_ESINGULAR) return singular(w);
  if (chain_rc != 0) return chain_rc;
  for (size_t e = 0; e + n < N * n; ++e) det_mul(&w->det_c, w->cpv[e]);
  for (size_t q = 0; q < n; ++q) w->slab[q] = w->clab[q];
  w->npiv_c = N * w->ni + (N - 1) * n;
  return 0;
}

/* The signs of the row order with the final rows in their order before
 * the final elimination (whose swaps factor_border counts), and of the
 * column order: both fixed until the next factor_rows.  The column order
 * depends on the shape alone (the pivots permute rows): its sign is
 * counted once.  The row order's is counted when cond_logdet asks, once a
 * factor_rows: a cycle count over all nx + 1 rows, where a continuation
 * step factors three or four times and asks once (1.5 % of demo fnc's
 * last run on one thread). */
static void order_signs(cond_ws *w) {
  const size_t n = w->n, nx = w->nx, nNm = n * w->N * w->m;
  size_t q = w->npiv_c;
  for (size_t e = 0; e < n; ++e) w->prow[q++] = w->slab[e];
  for (size_t e = 0; e < w->ne; ++e) w->prow[q++] = (int)(nNm + e);
  for (size_t t = 0; t < w->nb; ++t) w->prow[q++] = w->blab[t];
  q = w->npiv_c;
  for (size_t e = 0; e < w->nf; ++e)
    w->pcol[q++] = (int)(e < n ? e : e < 2 * n ? nNm + (e - n) : w->gcol[e - 2 * n]);
  if (!w->sign_col) w->sign_col = perm_sign(w->pcol, nx + 1, w->mark);
  w->sign_c = perm_sign(w->prow, nx + 1, w->mark) * w->sign_col;
}

/* The collocation rows: the system's fill at (X, p) (COND_FILL_*), the
 * condensation of every interval and the elimination of the inner mesh
 * points.  COND_FILL_MONO: F_x only (the global columns 0), for the
 * monodromy. */
static int factor_rows(cond_ws *w, const double *X, const double *p, size_t k,
                       int mode) {
  const int mono = mode == COND_FILL_MONO;
  w->state = 0;
  w->jac_ok = 0;
  w->det_c.mant = 1.0;
  w->det_c.expo = 0;
  w->npiv_c = 0;
  int rc = w->ops->fill_one ? w->ops->fill_begin(w, X, p, k, mode)
                            : w->ops->fill(w, X, p, k, mode);
  if (rc != 0) return rc;
  if ((rc = condense_and_chain(w, X, p, k, mode)) != 0) return rc;
  w->sign_c = 0; /* order_signs, when cond_logdet asks */
  memcpy(w->Xf, X, w->nx * sizeof *w->Xf);
  memcpy(w->pf, p, w->npar * sizeof *w->pf);
  w->jac_ok = mono ? 2 : 1;
  return 0;
}

/* Border row t's entries on the mesh points and globals into Bt (bc),
 * with its interior entries eliminated by each interval (step 1; for the
 * rows of bdone already in the loop of step 1), summed in interval
 * order. */
static void reduce_border_intervals(cond_ws *w, size_t t, const double *r) {
  const size_t n = w->n, m = w->m, N = w->N, ni = w->ni, nm = w->nm,
               ng = w->ng, wc = w->wc;
  double *Bt = w->B + t * w->bc;
  const double *src = w->ops->border(w, t, r, Bt + n * (N + 1));
  const int done = w->bdone[t];
  for (size_t i = 0; i <= N; ++i)
    for (size_t q = 0; q < n; ++q) Bt[n * i + q] = src[n * (i * m) + q];
  for (size_t i = 0; i < N; ++i) {
    if (!done) border_interval(w, t, src, i);
    const double *a = w->W + i * w->wr * wc + (nm + t) * wc;
    for (size_t q = 0; q < n; ++q) {
      Bt[n * i + q] += a[ni + q];
      Bt[n * (i + 1) + q] += a[ni + n + q];
    }
    for (size_t e = 0; e < ng; ++e) Bt[n * (N + 1) + e] += a[ni + 2 * n + e];
  }
}

/* The border rows against the collocation rows of the last factor_rows,
 * then the final dense system. */
static int factor_border(cond_ws *w, const double *r) {
  const size_t n = w->n, N = w->N, ng = w->ng, nb = w->nb, pc = w->pc,
               bc = w->bc, nf = w->nf;
  int rc;
  w->state = 0;
  if (w->jac_ok != 1) return WHIRL_EINVAL;
  w->det = w->det_c;
  /* 1. the interiors */
  for (size_t t = 0; t < nb; ++t) reduce_border_intervals(w, t, r);
  /* 2. the inner mesh points */
  for (size_t j = 1; j < N; ++j) {
    double *Pj = w->P + (j - 1) * w->pr * pc;
    for (size_t t = 0; t < nb; ++t) {
      double *a = Pj + (2 * n + t) * pc, *Bt = w->B + t * bc;
      whirl_copy_short(a, Bt + n * j, n);
      whirl_copy_short(a + n, Bt, n);
      whirl_copy_short(a + 2 * n, Bt + n * (j + 1), n);
      whirl_copy_short(a + 3 * n, Bt + n * (N + 1), ng);
      border_eliminate(Pj, pc, n, a);
      whirl_copy_short(Bt, a + n, n);
      whirl_copy_short(Bt + n * (j + 1), a + 2 * n, n);
      whirl_copy_short(Bt + n * (N + 1), a + 3 * n, ng);
    }
  }
  /* 3. the final system in [x_0 | x_N | g] */
  const double *S = w->P + (N - 2) * w->pr * pc + n * pc; /* [x_0 | x_N | g] at +n */
  double *F = w->F;
  const size_t nNm = n * N * w->m;
  memset(F, 0, nf * nf * sizeof *F);
  for (size_t q = 0; q < n; ++q) {
    whirl_copy_short(F + q * nf, S + q * pc + n, 2 * n + ng);
    w->lab[q] = w->slab[q];
  }
  for (size_t e = 0; e < w->ne; ++e) {
    w->ops->end_row(w, e, F + (n + e) * nf);
    w->lab[n + e] = (int)(nNm + e);
  }
  for (size_t t = 0; t < nb; ++t) {
    double *a = F + (n + w->ne + t) * nf;
    const double *Bt = w->B + t * bc;
    whirl_copy_short(a, Bt, n);
    whirl_copy_short(a + n, Bt + n * N, n);
    whirl_copy_short(a + 2 * n, Bt + n * (N + 1), ng);
    w->lab[n + w->ne + t] = w->blab[t];
  }
  int swaps = 0;
  rc = gepp(F, nf, nf, 0, nf, w->fpiv, w->lab, &w->det, NULL, &swaps);
  if (rc == 2) return WHIRL_EBADFUNC;
  if (rc == 1) return singular(w);
  w->logabs = log(fabs(w->det.mant)) + (double)w->det.expo * log(2.0);
  if (!isfinite(w->logabs)) return WHIRL_EBADFUNC;
  w->sign_f = (w->det.mant < 0.0 ? -1 : 1) * (swaps % 2 ? -1 : 1);
  w->state = 1;
  return 0;
}

int cond_factor(void *ws, const double *X, const double *p, size_t k,
                const double *r) {
  cond_ws *w = ws;
  /* the rows known now: their intervals' part in step 1's loop */
  for (size_t t = 0; t + 1 < w->nb; ++t)
    w->bsrc[t] = w->ops->border_early ? w->ops->border_early(w, t) : NULL;
  w->bsrc[w->nb - 1] = r;
  int rc = factor_rows(w, X, p, k, COND_FILL_FULL);
  for (size_t t = 0; t < w->nb; ++t) w->bsrc[t] = NULL;
  if (rc == 0) rc = factor_border(w, r);
  for (size_t t = 0; t < w->nb; ++t) w->bdone[t] = 0;
  return rc;
}

int cond_factor_F(void *ws, const double *X, const double *p, size_t k,
                  const double *r, double *f) {
  cond_ws *w = ws;
  w->Fout = f;
  const int rc = cond_factor(ws, X, p, k, r);
  w->Fout = NULL;
  return rc;
}

int cond_factor_col(void *ws, const double *X, const double *p,
                    const double *col, const double *r) {
  cond_ws *w = ws;
  memcpy(w->fk, col, w->nx * sizeof *w->fk);
  int rc = factor_rows(w, X, p, 0, COND_FILL_GIVEN);
  return rc != 0 ? rc : factor_border(w, r);
}

/* The same F_x and dF/dp_k with a new border row r (and the system's
 * current border data): only the border rows and the final system are
 * redone. */
int cond_reborder(void *ws, const double *r) { return factor_border(ws, r); }

int cond_factored_at(const cond_ws *w, const double *X, const double *p) {
  return w->jac_ok && memcmp(w->Xf, X, w->nx * sizeof *X) == 0 &&
         memcmp(w->pf, p, w->npar * sizeof *p) == 0;
}

int cond_factor_rows(cond_ws *w, const double *X, const double *p) {
  return factor_rows(w, X, p, 0, COND_FILL_MONO);
}

/* ------------------------------------------------------------ solve */

/* Solve step 1 on interval i: its rows of b transformed by its block's
 * L (into loc, with its border rows' parts); then done[i] set. */
static void forward_interval(cond_ws *w, const double *b, size_t i) {
  const size_t n = w->n, m = w->m, ni = w->ni, nm = w->nm, wr = w->wr;
  double *v = w->loc + i * wr;
  whirl_copy_short(v, b + n * i * m, nm);
  whirl_zero_short(v + nm, w->nb);
  gepp_forward(w->W + i * wr * w->wc, w->wc, nm, w->nb, ni, w->wpiv + i * ni, v);
  __atomic_store_n(&w->done[i], 1, __ATOMIC_RELEASE);
}

/* Solve step 2's link j (1 <= j < NTST): the rows left over and interval
 * j's, transformed by mesh-point block j (into ploc). */
static void forward_link(cond_ws *w, size_t j) {
  const size_t n = w->n, ni = w->ni, nb = w->nb, pr = w->pr;
  double *v = w->ploc + (j - 1) * pr;
  const double *s = j == 1 ? w->loc + ni : w->ploc + (j - 2) * pr + n;
  whirl_copy_short(v, s, n);
  whirl_copy_short(v + n, w->loc + j * w->wr + ni, n);
  for (size_t t = 0; t < nb; ++t) v[2 * n + t] = 0.0;
  gepp_forward(w->P + (j - 1) * pr * w->pc, w->pc, 2 * n, nb, n, w->ppiv + (j - 1) * n, v);
}

/* Solve step 2 as far as the transformed intervals allow (main thread) */
static void forward_advance(cond_ws *w, size_t *next) {
  while (*next < w->N && __atomic_load_n(&w->done[*next], __ATOMIC_ACQUIRE)) {
    if (*next > 0) forward_link(w, *next);
    ++*next;
  }
}

/* The back substitution of interval i's interior from x_i, x_{i+1}, g
 * (thread t's scratch), and x_i into b. */
static void back_interval(cond_ws *w, double *b, size_t i, int t) {
  const size_t n = w->n, m = w->m, ng = w->ng, wr = w->wr;
  const double *xs = w->xs, *g = xs + n * (w->N + 1);
  double *y = w->ysc + (size_t)t * w->ystride;
  whirl_copy_short(y, xs + n * i, 2 * n);
  whirl_copy_short(y + 2 * n, g, ng);
  gepp_back(w->W + i * wr * w->wc, w->wc, w->ni, 2 * n + ng, w->loc + i * wr, y,
            b + n * (i * m + 1));
  whirl_copy_short(b + n * i * m, xs + n * i, n);
}

/* The back substitution of the mesh points x_{N−1} .. x_1 (main thread),
 * each published in w->low once known (release). */
static void back_chain(cond_ws *w) {
  const size_t n = w->n, N = w->N, ng = w->ng, pr = w->pr, pc = w->pc;
  double *xs = w->xs, *g = xs + n * (N + 1), *yp = w->tmp + 2 * w->nf;
  for (size_t j = N - 1; j >= 1; --j) {
    whirl_copy_short(yp, xs, n);
    whirl_copy_short(yp + n, xs + n * (j + 1), n);
    whirl_copy_short(yp + 2 * n, g, ng);
    gepp_back(w->P + (j - 1) * pr * pc, pc, n, 2 * n + ng, w->ploc + (j - 1) * pr, yp,
              xs + n * j);
    __atomic_store_n(&w->low, j, __ATOMIC_RELEASE);
  }
}

/* One right-hand side b (M's rows) into the solution (M's columns).  Steps
 * 1 and 2 as the factorisation's: the intervals on the threads, a few at
 * a time in order, the main thread's chain over the mesh points behind
 * them; the border rows' sums afterwards in the serial order.  The back
 * substitution likewise: the main thread's chain from x_{N−1} down, the
 * intervals' interiors on the threads from the top down behind it.  The
 * same operations in the same order on any number of threads. */
static void solve1(cond_ws *w, double *b) {
  const size_t n = w->n, m = w->m, N = w->N, nm = w->nm, ng = w->ng, nb = w->nb,
               wr = w->wr, pr = w->pr, nf = w->nf;
  double *bb = w->bb, *xs = w->xs, *g = xs + n * (N + 1);
  const int nth = w->nth_last;
  size_t fnext = 0;
  memset(w->done, 0, N * sizeof *w->done);
#pragma omp parallel num_threads(nth) if (nth > 1)
  {
    const int t = whirl_thread_num();
    size_t lo, hi;
    thread_range(w, t, whirl_team_size(), &lo, &hi);
    for (size_t i = lo; i < hi; ++i) {
      forward_interval(w, b, i);
      if (t == 0) forward_advance(w, &fnext);
    }
    if (t == 0)
      while (fnext < N) {
        const size_t before = fnext;
        forward_advance(w, &fnext);
        if (fnext == before) WHIRL_SPIN_PAUSE();
      }
  }
  for (size_t t = 0; t < nb; ++t) bb[t] = b[w->blab[t]];
  for (size_t i = 0; i < N; ++i)
    for (size_t t = 0; t < nb; ++t) bb[t] += w->loc[i * wr + nm + t];
  for (size_t j = 1; j < N; ++j)
    for (size_t t = 0; t < nb; ++t) bb[t] += w->ploc[(j - 1) * pr + 2 * n + t];
  /* 3. */
  double *frp = w->tmp, *zp = frp + nf;
  whirl_copy_short(frp, w->ploc + (N - 2) * pr + n, n);
  whirl_copy_short(frp + n, b + n * N * m, w->ne);
  whirl_copy_short(frp + n + w->ne, bb, nb);
  gepp_forward(w->F, nf, nf, 0, nf, w->fpiv, frp);
  gepp_back(w->F, nf, nf, 0, frp, NULL, zp);
  whirl_copy_short(xs, zp, n);
  whirl_copy_short(xs + n * N, zp + n, n);
  whirl_copy_short(g, zp + 2 * n, ng);
  /* back substitution: the mesh points, and the interiors behind them */
  w->low = N;
#pragma omp parallel num_threads(nth) if (nth > 1)
  {
    const int t = whirl_thread_num();
    size_t lo, hi;
    thread_range(w, t, whirl_team_size(), &lo, &hi);
    if (t == 0) back_chain(w);
    for (size_t i = hi; i-- > lo;) {
      const size_t need = i > 0 ? i : 1;
      while (__atomic_load_n(&w->low, __ATOMIC_ACQUIRE) > need) WHIRL_SPIN_PAUSE();
      back_interval(w, b, i, t);
    }
  }
  whirl_copy_short(b + n * N * m, xs + n * N, n);
  for (size_t e = 0; e < ng; ++e) b[w->gcol[e]] = g[e];
}

/* one(w, column) on each of the nrhs columns of b, after a factor. */
static int solve_columns(cond_ws *w, double *b, size_t nrhs,
                         void (*one)(cond_ws *, double *)) {
  if (w->state != 1) return WHIRL_ESINGULAR;
  for (size_t k = 0; k < nrhs; ++k) one(w, b + k * (w->nx + 1));
  return WHIRL_OK;
}

int cond_solve(void *ws, double *b, size_t nrhs) {
  return solve_columns(ws, b, nrhs, solve1);
}

/* M^T y = c: the adjoint of solve1, its steps in reverse order (steps 6
 * to 0 there).  c is indexed by M's columns (solve1's output), y by its
 * rows (solve1's input); every entry of c is read before y is written.
 * The scratch of solve1 holds the adjoints: loc and ploc those of its
 * transformed right-hand sides, bb of the border rows', xs and g of the
 * mesh points' and globals'. */
static void solve1_t(cond_ws *w, double *b) {
  const size_t n = w->n, m = w->m, N = w->N, ni = w->ni, nm = w->nm,
               ng = w->ng, nb = w->nb, ne = w->ne, wr = w->wr, wc = w->wc,
               pr = w->pr, pc = w->pc, nf = w->nf, nNm = n * N * m;
  double *bb = w->bb, *xs = w->xs, *g = xs + n * (N + 1), *yb = w->tmp;
  memset(w->loc, 0, N * wr * sizeof *w->loc);
  memset(w->ploc, 0, (N - 1) * pr * sizeof *w->ploc);
  /* the outputs' adjoints: the mesh points and the globals */
  for (size_t i = 0; i <= N; ++i) whirl_copy_short(xs + n * i, b + n * i * m, n);
  for (size_t e = 0; e < ng; ++e) g[e] = b[w->gcol[e]];
  /* back substitution of the interiors (in place in c's interior entries) */
  for (size_t i = 0; i < N; ++i) {
    whirl_zero_short(yb, 2 * n + ng);
    gepp_back_t(w->W + i * wr * wc, wc, ni, 2 * n + ng, b + n * (i * m + 1),
                w->loc + i * wr, yb);
    for (size_t q = 0; q < 2 * n; ++q) xs[n * i + q] += yb[q];
    for (size_t e = 0; e < ng; ++e) g[e] += yb[2 * n + e];
  }
  /* back substitution of the mesh points, x_1 first */
  for (size_t j = 1; j < N; ++j) {
    whirl_zero_short(yb, 2 * n + ng);
    gepp_back_t(w->P + (j - 1) * pr * pc, pc, n, 2 * n + ng, xs + n * j,
                w->ploc + (j - 1) * pr, yb);
    for (size_t q = 0; q < n; ++q) {
      xs[q] += yb[q];
      xs[n * (j + 1) + q] += yb[n + q];
    }
    for (size_t e = 0; e < ng; ++e) g[e] += yb[2 * n + e];
  }
  /* 3. the final system: F^T */
  double *zb = w->tmp, *fb = zb + nf;
  whirl_copy_short(zb, xs, n);
  whirl_copy_short(zb + n, xs + n * N, n);
  whirl_copy_short(zb + 2 * n, g, ng);
  whirl_zero_short(fb, nf);
  gepp_back_t(w->F, nf, nf, 0, zb, fb, NULL);
  gepp_forward_t(w->F, nf, nf, 0, nf, w->fpiv, fb);
  double *pl = w->ploc + (N - 2) * pr + n;
  for (size_t q = 0; q < n; ++q) pl[q] += fb[q];
  whirl_copy_short(bb, fb + n + ne, nb);
  /* (fb + n holds the end rows' y until the end) */
  /* 2. the mesh points' forward eliminations, the last first */
  for (size_t j = N - 1; j >= 1; --j) {
    double *v = w->ploc + (j - 1) * pr;
    whirl_copy_short(v + 2 * n, bb, nb);
    gepp_forward_t(w->P + (j - 1) * pr * pc, pc, 2 * n, nb, n, w->ppiv + (j - 1) * n, v);
    double *src = j == 1 ? w->loc + ni : w->ploc + (j - 2) * pr + n;
    double *own = w->loc + j * wr + ni;
    for (size_t q = 0; q < n; ++q) {
      src[q] += v[q];
      own[q] += v[n + q];
    }
  }
  /* 1. the intervals' forward eliminations: y's collocation rows */
  for (size_t i = 0; i < N; ++i) {
    double *v = w->loc + i * wr;
    whirl_copy_short(v + nm, bb, nb);
    gepp_forward_t(w->W + i * wr * wc, wc, nm, nb, ni, w->wpiv + i * ni, v);
    whirl_copy_short(b + n * i * m, v, nm);
  }
  whirl_copy_short(b + nNm, fb + n, ne);
  for (size_t t = 0; t < nb; ++t) b[w->blab[t]] = bb[t];
}

int cond_solve_t(void *ws, double *b, size_t nrhs) {
  return solve_columns(ws, b, nrhs, solve1_t);
}

int cond_logdet(void *ws, double *logabs, int *sign) {
  cond_ws *w = ws;
  if (w->state == 0) return WHIRL_EINVAL;
  if (w->state == 2) {
    *logabs = -INFINITY;
    *sign = 0;
    return WHIRL_OK;
  }
  if (!w->sign_c) order_signs(w);
  *logabs = w->logabs;
  *sign = w->sign_f * w->sign_c;
  return WHIRL_OK;
}

/* ------------------------------------------------------------ monodromy */

/* M = −S_N^{-1} S_0 from the n rows S_0 x_0 + S_N x_N + S_g g left after
 * step 2 of the collocation rows of w (globals fixed). */
int cond_monodromy(cond_ws *w, double *M) {
  const size_t n = w->n, N = w->N, pc = w->pc;
  if (!w->jac_ok) return WHIRL_EINVAL;
  const double *S = w->P + (N - 2) * w->pr * pc + n * pc; /* [x_0 | x_N | g] at +n */
  double *A = w->mblk, *col = A + 2 * n * n, *x = col + n;
  det_acc dt = {1.0, 0};
  /* the block [S_N | S_0] (n x 2n, row-major); elimination of S_N carries
   * S_0 along (whole rows swapped and updated), so only U remains */
  for (size_t q = 0; q < n; ++q) {
    whirl_copy_short(A + q * 2 * n, S + q * pc + 2 * n, n);
    whirl_copy_short(A + q * 2 * n + n, S + q * pc + n, n);
    w->mlab[q] = (int)q;
  }
  int rc = gepp(A, 2 * n, n, 0, n, w->mpiv, w->mlab, &dt, NULL, NULL);
  if (rc != 0) return rc == 2 ? WHIRL_EBADFUNC : WHIRL_ESINGULAR;
  for (size_t j = 0; j < n; ++j) {
    for (size_t q = 0; q < n; ++q) col[q] = A[q * 2 * n + n + j];
    gepp_back(A, 2 * n, n, 0, col, NULL, x);
    for (size_t q = 0; q < n; ++q) M[q + n * j] = -x[q];
  }
  return 0;
}

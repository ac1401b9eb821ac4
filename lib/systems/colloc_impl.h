/* lib/systems/colloc_impl.h — private to lib/systems: the collocation object
 * (colloc.c) shared with its structured linear solver (colloc_cond.c:
 * condensation of parameters, the bordered Newton matrix and the monodromy
 * matrix from the condensed blocks).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_COLLOC_IMPL_H
#define WHIRL_COLLOC_IMPL_H

#include <stddef.h>

#include <whirl/colloc.h>
#include <whirl/system.h>

#include "util/errmsg_impl.h"
#include "util/threads_impl.h"

#define COLLOC_MAXCOL 7

/* A thread's scratch for the model at a Gauss point (sizes n, n, n, n,
 * n·n, n·npar, 2n, npar, n): x and dx/dσ there, f, a second f, f_x, f_p,
 * the differences' work, a parameter copy and dF/dT of the n rows. */
typedef struct colloc_scratch {
  double *xc, *dx, *f, *f2, *J, *Jpar, *work, *pw, *dT;
  double *block; /* all of the above, on cache lines of the thread's own */
} colloc_scratch;

/* The parallel loops over mesh intervals are worth their start (a few
 * microseconds) from about this many state values at Gauss points.  512
 * until 2026-12-07: by their scripts on two threads against one, abcb
 * (its fold loci of orbits on n NTST NCOL = 600) took 0.87 / 0.77 s, ab
 * (560) 0.88 / 0.79, lcbp (800) 0.77 / 0.65, where r3b (1 200 and more)
 * took 0.69 / 0.79 and pla (3 000) gains a third. */
#define COLLOC_PAR_MIN 1024

struct whirl_colloc {
  const whirl_problem *prob;
  whirl_problem shim; /* prob seen through colloc_shim_*, for the multipliers */
  whirl_system sys;
  size_t n, ntst, ncol;
  size_t nnodes; /* ntst*ncol + 1 */
  size_t nx;     /* unknowns = equations */
  size_t nnz;
  int aut;  /* 1: period unknown, phase condition; 0: forced */
  int fpar; /* forcing parameter (forced) or -1 */
  unsigned nu;
  double t0, floquet_rtol;

  double *mesh; /* ntst + 1 */
  double *rot;  /* n: x(1) - x(0) of components that are angles turning by
                   2 pi k over a period (AUTO's rotations, NRTN), else 0 */
  /* Gauss points and weights on [0, 1]; Lagrange basis and its derivative
   * at them, L[c*(ncol+1) + k] = l_k(σ_c), D likewise l_k'(σ_c); dm[k] the
   * weights of the NCOL-th derivative in σ (NCOL^NCOL (−1)^{m−k} C(m, k)). */
  double gs[COLLOC_MAXCOL], gw[COLLOC_MAXCOL];
  double L[COLLOC_MAXCOL * (COLLOC_MAXCOL + 1)];
  double D[COLLOC_MAXCOL * (COLLOC_MAXCOL + 1)];
  double dm[COLLOC_MAXCOL + 1];
  double wint[COLLOC_MAXCOL + 1]; /* int_0^1 l_k: the nodes' norm weights */

  int *Jp, *Ji;  /* compressed-column pattern, nx + 1 and nnz */
  double *Jx;    /* nnz, values for the dense callback */
  double *ref;   /* nnodes*n, node values of the phase reference */
  double *phase; /* nnodes*n, the phase row ∫ <x, x_ref'> as weights */
  double phase0; /* <phase, ref>: 0 for a periodic reference, up to rounding */
  int have_ref;

  /* the model's evaluations at Gauss points: one scratch per thread
   * (scr[0] for the serial entry points) */
  int nthreads;             /* options.threads, resolved: >= 1 */
  whirl_gov gov_F;          /* colloc_F's threads (threads_impl.h) */
  double fill_T;            /* colloc_cond.c: the period of the fill, */
  int fill_fk_loop;         /* and dF/dp_k from f_p in each interval */
  const double *fill_X;     /* and its point, for F's end rows */
  colloc_scratch *scr;      /* nthreads */
  double *r1, *r2;          /* nx, nx */
  double *old_mesh, *old_X; /* ntst + 1, nnodes*n (nthreads copies, the
                               remap's): mesh adaptation */
  size_t *map_idx;  /* the remap's plan: each new node's old interval */
  double *map_L;    /* and its Lagrange values there, nnodes (ncol + 1) */
  double *ref_new;          /* nnodes*n */
  int adapt_every;          /* options.adapt_every (AUTO's IAD) */
  int mesh_jumps;           /* options.mesh_jumps (AUTO's EQDF) */
  int phase_nodes;          /* options.phase_nodes (AUTO's ICPS) */
  double *ref_par;          /* npar: the parameters of the reference ... */
  double ref_T;             /* ... its period */
  int have_ref_par;         /* set by the accept hook */
  int since_adapt;          /* remap calls since the last adaptation */
  size_t adaptations;       /* meshes adapted along branches */

  int floquet;   /* whirl_colloc_floquet: multipliers route */
  void *spec_ws; /* colloc_bsolver workspace for the condensed multipliers */
  void *last_ws; /* the workspace factored last (any owner), or NULL */

  int fq;       /* fixed period: the parameter in T's place, or -1 */
  double Tfix;  /* fixed period: T */
  double *pq;   /* npar: p with p[fq] from X (colloc_par) */
  double *pF;   /* npar: the same for colloc_F alone (called inside the
                   others by differences in p, which would clobber pq) */

  int rhs_fail; /* last recoverable model failure seen by the shim */
  char errmsg[WHIRL_ERRMSG_SIZE]; /* last message (whirl_colloc_errmsg) */
};

/* colloc.c: the period of X at p (the unknown T, or 2π nu/ω). */
double colloc_period_of(const whirl_colloc *c, const double *X,
                        const double *p);

/* colloc.c: the parameters the model sees at X: p itself, or at a fixed
 * period a copy (c->pq) with p[fq] = X's last entry.  Every entry point
 * taking (X, p) passes p through it before calling the model. */
const double *colloc_par(whirl_colloc *c, const double *X, const double *p);

/* colloc.c: the model's f_x at Gauss point g of interval i into s->J, and
 * (autonomous orbits, dT not NULL) dF/dT of the n collocation rows there,
 * dT[n] = −h (f + T τ ∂f/∂t); x and dx/dσ are left in s->xc, s->dx.
 * Returns the model's status. */
int colloc_gauss_jac(whirl_colloc *c, colloc_scratch *s, const double *X,
                     const double *p, double T, size_t i, size_t g,
                     double *dT);

/* colloc.c: F's collocation rows at Gauss point g of interval i (width h,
 * period T) from f there, dx/dσ from s->dx; and F's rows after them, the
 * periodicity and the phase condition: the residual's code, which the
 * condensed fill also runs when it makes F (colloc_cond.c). */
void colloc_residual_rows(const whirl_colloc *c, const colloc_scratch *s, size_t i,
                          size_t g, double h, double T, const double *f, double *F);
void colloc_end_rows(const whirl_colloc *c, const double *X, double *F);

/* colloc.c: threads for the loops over the intervals (1: serial). */
int colloc_threads(const whirl_colloc *c);

/* −h T df/dp_k at Gauss point time t (s->xc, after at_gauss) into fr[n]
 * (hT = h T): the model's jac_p, or a central difference of f in p_k
 * (WHIRL_EBADFUNC if not finite); p as the caller's, a fixed period's free
 * parameter taken from X.  For colloc_Fp and the condensed fill alike, so
 * both give the same column. */
int colloc_fk_rows(const whirl_colloc *c, colloc_scratch *s, const double *X,
                   const double *p, size_t k, double t, double hT, double *fr);

/* colloc_cond.c: the structured bordered solver of the system. */
extern const whirl_bsolver colloc_bsolver;

/* colloc_cond.c: the monodromy matrix M[n*n] (column-major) of the
 * collocation equations linearised at (X, p): the transfer x(1) = M x(0)
 * of the condensed, block-bidiagonal collocation system at fixed T and p
 * (AUTO-07p's Floquet multipliers).  Taken from the last factorisation of
 * the bordered matrix when that was at (X, p), else condensed anew in
 * c->spec_ws. */
int colloc_cond_monodromy(whirl_colloc *c, const double *X, const double *p,
                          double *M);

#endif

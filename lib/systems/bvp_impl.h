/* lib/systems/bvp_impl.h — private to lib/systems: the boundary-value
 * problem object (bvp.c) shared with its structured linear solver
 * (bvp_cond.c: the condensation of parameters of cond_elim.c).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_BVP_IMPL_H
#define WHIRL_BVP_IMPL_H

#include <stddef.h>

#include <whirl/bvp.h>
#include <whirl/system.h>

#include "colloc_basis.h"
#include "util/errmsg_impl.h"
#include "util/threads_impl.h"

/* One thread's scratch at a Gauss point: u, du/dsigma, f, fm, uq (n
 * each), J (n*n), Jpar (n*npar), work (2n), pq (npar), gi, gim (nint),
 * gu, gd (nint*n: the integral conditions' partials in u and u'), and the
 * reference uo, its derivative upo, u' (ud; udq perturbed), n each. */
typedef struct bvp_scratch {
  double *u, *du, *f, *fm, *uq, *J, *Jpar, *work, *pq, *gi, *gim, *gu, *gd, *uo, *upo,
      *ud, *udq;
  double *block; /* all of the above */
} bvp_scratch;

struct whirl_bvp {
  const whirl_problem *prob;
  whirl_system sys;
  size_t n, npar, ntst, ncol;
  size_t nnodes; /* ntst*ncol + 1 */
  size_t ncoll;  /* collocation rows n*ntst*ncol */
  size_t nbc, nint, nfree;
  size_t nx;  /* unknowns = equations */
  size_t nnz;
  size_t *free; /* nfree parameter indices */
  whirl_bvp_bc_fn bc;
  whirl_bvp_ic_fn ic;
  void *data;

  double *mesh; /* ntst + 1 */
  /* Gauss points and weights on [0, 1]; the Lagrange basis and its
   * derivative there, L[g*(ncol+1) + k] = l_k(σ_g), D likewise l_k' */
  double gs[COLLOC_BASIS_MAXCOL], gw[COLLOC_BASIS_MAXCOL];
  double wint[COLLOC_BASIS_MAXCOL + 1]; /* ∫₀¹ of each node's Lagrange
                                           basis polynomial (the norms) */
  double L[COLLOC_BASIS_MAXCOL * (COLLOC_BASIS_MAXCOL + 1)];
  double D[COLLOC_BASIS_MAXCOL * (COLLOC_BASIS_MAXCOL + 1)];

  int *Jp, *Ji; /* compressed-column pattern, nx + 1 and nnz */
  double *Jx;   /* nnz, values for the dense callback */

  /* scratch, in one block (buf): pt (npar), fb, fbm (nbc), cp, cm
   * (nbc + nint); the integral conditions' reference (AUTO's UOLD), node
   * values; icacc the integral rows' terms of every Gauss point (the
   * Jacobian's intervals in parallel, summed in interval order after) */
  double *buf;
  double *pt, *fb, *fbm, *cp, *cm, *ref, *icacc;
  int nthreads;     /* threads of the Jacobian's loop over the intervals */
  whirl_gov gov;    /* how many of them a call runs on (threads_impl.h) */
  whirl_gov gov_F, gov_Fp; /* likewise for the residual's and F_p's loops */
  double *icterm;   /* N NCOL nint: each Gauss point's term of the integral
                       rows of dF/dp_k, summed in order after a parallel
                       loop */
  double *icF;      /* N NCOL nint: likewise, those of F (the residual's
                       loop, or the Jacobian's fill with F) */
  bvp_scratch *scr; /* nthreads; scr[0] the sequential code's */
  /* mesh adaptation (AUTO's IAD): dm the NCOL-th derivative's weights,
   * the old mesh, a copy of a vector and the density's scratch */
  int adapt_every, since_adapt;
  int auto_differences; /* options.auto_differences: AUTO's FUNI, ICNI */
  int udot_direction;   /* options.udot_direction: ic's udot from dref */
  double *dref;         /* the core's direction, node values (n nnodes) */
  size_t adaptations;
  double *nwq, *nwmesh; /* the norm weights (n nnodes) of the mesh nwmesh
                         * (N + 1), kept: a run's PVLS asks at every point */
  int nw_ok;            /* nwq holds nwmesh's weights */
  double dm[COLLOC_BASIS_MAXCOL + 1];
  double *old_mesh, *E, *Q, *Dm;
  double *mapscr;   /* nthreads (n nnodes): the remap's copies */
  double *map_L;    /* the remap's plan: Lagrange values at the new nodes */
  size_t *map_idx;  /* and their intervals on the old mesh */
  char errmsg[WHIRL_ERRMSG_SIZE];
};

/* bvp.c: the threads of the loops over the intervals (1 where the mesh is
 * too small to share). */
int bvp_threads(const whirl_bvp *b);

/* bvp.c: the sparse Jacobian's values Jx (the system's pattern Jp, Ji) at
 * (X, p): the system's Fx_sparse. */
int bvp_Fx_sparse(const double *X, const double *p, double *Jx, void *data);

/* bvp.c, for bvp_cond.c: the Jacobian straight into the condensation's
 * dense blocks (after whirl_bvp_params into b->pt).
 * bvp_fill_block: interval i's collocation rows into its block B (n NCOL
 * rows of wc: [interior | x_i | x_{i+1} | free | p_k], zeroed first) on
 * thread's scratch; the free columns when globals; with fk, dF/dp_k's
 * rows too (central differences, as the system's Fp), into B's last
 * column and fk (indexed as F's rows); the integral rows' terms into
 * b->icacc (and p_k's into b->icterm); with F, F's collocation rows
 * (indexed as F's) and integral terms (b->icF) from the same evaluations.
 * 0, or a status and in *what the callback that failed (NULL: dF/dp_k not
 * finite).
 * bvp_block_sums: after every interval, their integral terms added up, in
 * interval order, into the dense rows ic (row c at ic + c ldic, F's
 * columns), and p_k's into fk_ic[nint] when not NULL.
 * bvp_block_status: a failed bvp_fill_block's status with its message.
 * bvp_fill_bc_rows: the boundary rows into bcr (row s at bcr + s nf:
 * [u(0) | u(1) | free]), the free columns when globals; with fk_bc,
 * d(boundary rows)/dp_k into fk_bc[nbc] (WHIRL_EBADFUNC if not finite).
 * bvp_F_boundary, bvp_F_integrals: F's boundary rows at X (0 or the
 * status, with its message), and its integral rows from the terms in
 * b->icF: the residual's own code (bvp_F), for a fill that makes F. */
int bvp_fill_block(whirl_bvp *b, int thread, const double *X, size_t i, double *B,
                   size_t wc, int globals, double *fk, size_t k, double *F,
                   const char **what);
int bvp_F_boundary(whirl_bvp *b, const double *X, double *F);
void bvp_F_integrals(whirl_bvp *b, double *F);
void bvp_block_sums(whirl_bvp *b, double *ic, size_t ldic, int globals, double *fk_ic);
int bvp_block_status(whirl_bvp *b, int rc, const char *what);
int bvp_fill_bc_rows(whirl_bvp *b, const double *X, double *bcr, size_t nf, int globals,
                     double *fk_bc, size_t k);

/* bvp_cond.c: the structured bordered solver (NTST >= 2). */
extern const whirl_bsolver bvp_bsolver;

#endif

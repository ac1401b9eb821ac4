/* lib/core/cont_impl.h — private state of a continuation (whirl_cont), shared
 * by cont.c (stepping, step control, start and branch switching) and
 * locate.c (localisation of special points by test functions).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_CONT_IMPL_H
#define WHIRL_CONT_IMPL_H

#include <stdio.h>

#include <whirl/cont.h>
#include <whirl/linsol.h>

#include "util/errmsg_impl.h"

/* Everything known about one corrected point: the solution, the unit tangent
 * and the values of the test functions there. */
typedef struct cont_state {
  double *X;       /* X[n+1] = (x, p_icp) */
  double *t;       /* unit tangent t[n+1] (weighted norm) */
  double *sec;     /* the point's stored direction (opt.point_dir; has_sec
                      when it is not the tangent) */
  int has_sec;
  double *p;       /* full parameter vector p[npar] */
  double *re, *im; /* spectrum[nspec] */
  size_t nspec;    /* spectrum entries filled */
  double s;        /* arclength from the start point */
  double psi_lp;   /* t_p: changes sign at a fold */
  double logdet;   /* log|det [F_x F_p; r^T]|, r = predictor direction */
  int sign_det;    /* its sign: changes at a branch point */
  double psi_hb;   /* Re of the complex eigenvalue closest to the axis
                      (multipliers: |mu| - 1 of the complex multiplier
                      closest to the unit circle: a TR test) */
  int has_hb;      /* psi_hb defined (a complex pair exists) */
  double psi_pd;   /* multipliers: mu + 1 of the real negative multiplier
                      nearest to -1 */
  int has_pd;      /* psi_pd defined */
  int n_rn;        /* multipliers: real ones below -1 */
  int n_unstable;  /* eigenvalues with Re > 0, -1 without spectrum */
  int n_cu;        /* complex eigenvalues with Re > 0 (multipliers: complex
                      ones outside the unit circle) */
  double *tau;     /* the system's test functions [ntest] */
  int *ttype;      /* the point types their zeros stand for [ntest] */
  int tests_valid; /* 0 right after a branch switch: no detection yet */
  int type, label;
  int uz;          /* UZ: index of the user value, -1 otherwise */
} cont_state;

struct whirl_cont {
  whirl_system sys;
  whirl_cont_options opt;
  size_t n, N, npar; /* N = n + 1 */
  int sparse;

  whirl_bordered *bd; /* extended matrix [F_x F_p; r^T] (general LU) */
  const whirl_bsolver *bs; /* or the system's structured solver ... */
  void *bws;               /* ... and its workspace */
  double *J;          /* dense F_x[n*n] (dense path) */
  double *Jx;         /* sparse values[nnz] (sparse path) */
  double *fp;         /* F_p[n] */
  double *f;          /* F[n] */
  double *rhs;        /* N */
  double *row;        /* N: border row of the current factorisation */
  double *row2;       /* N: border row wanted (chord Newton) */
  int switch_step;    /* the first step off a branch point: on the
                         hyperplane even with opt.arclength_sphere */
  double *sph;        /* N: 2 (X - X0) / ds, the sphere's row direction
                         (opt.arclength_sphere) */
  int fact_ok;        /* a factorisation chord Newton may use is held */
  int correcting;     /* inside cont_correct (natural_row applies) */
  int arclength_only; /* this step's natural-parameter correction failed:
                         retried on the arclength hyperplane */
  int remapped;       /* the current point was remapped (a new mesh) since
                         it was corrected: not yet a solution of the new
                         representation (recorrect_remapped) */
  double *Xfact;      /* N: the point of the last factorisation ... */
  double *pfact;      /* npar: ... and its parameters (tangent_from_newton
                         asks the spectrum there, where the system's
                         structured solver holds its blocks) */
  double *work;       /* scratch for finite differences */
  size_t wlen;
  whirl_eig *eig;     /* spectrum of F_x when the system has none of its own */

  cont_state cur;     /* last accepted point */
  cont_state trial;   /* point being computed */
  struct cont_event *evs; /* the special points of the current step */
  cont_state *queue;  /* special points and the regular point to emit */
  size_t qlen, qhead, qcap;
  cont_state out;     /* storage behind the point returned to the caller */
  cont_state locbest; /* the localisation's best analysed trial (locate.c) */
  cont_state *autopts; /* opt.loc_epss: each event's point by AUTO's
                          localisation, the next step's start [maxev] */
  size_t nautopts;
  cont_state *loc_next; /* where cont_locate puts that point (NULL: none) */
  int loc_next_ok;      /* ... and whether it did */
  whirl_point pt;

  double *w2;         /* N: weights of the squared components in the
                         arclength norm (opt.x_weight² times the system's
                         norm_weights, opt.p_weight²) */
  double *xw2;        /* n: opt.x_weight², kept for a new representation */
  double *dir;        /* N: predictor direction of the current step */
  double *Xprev;      /* N: previous accepted point (secant predictor) */
  double *Xref;       /* N: a localisation's last trial (its reference) */
  double *ref_p;      /* npar: the parameters given with it */
  int have_prev;
  double *tprev;      /* N: its tangent (curved predictor) ... */
  double hprev;       /* ... and the arclength from it to cur */
  int have_tprev;
  double *Xstart;     /* N: start point, for loop detection */
  double ds;          /* current signed step (> 0 along the tangent) */
  int its;            /* Newton iterations of the last correction */
  int skip_ev[8];     /* opt.auto_steps: the tests zero at the start of */
  size_t skip_k[8];   /* this step (the special point it starts from, */
  double skip_s[8];   /* their ev and k), not tested on it; during */
  size_t nskip;       /* find_events, every zero located (s: where) */
  int first_hidden;   /* opt.hide_first_step: done */
  int pd_rank;        /* the PD test: the pd_rank-th most negative real
                         multiplier (cont_pd_rank_test) */
  int hb_rank;        /* 0: the HB/TR test is psi_hb; k > 0: the k-th
                         largest of the complex spectrum (cont_hb_rank_test)
                         for the crossing being located */
  size_t index;       /* PT of the next point */
  int started, done, stop_reason;
  int singular_start; /* started on a solution where F_x is singular (a
                         fold or a branch point): bp_start_retry armed */
  int label;          /* last label given */
  whirl_cont_stats stats;
  char errmsg[512];
};

/* Correct the point X (in/out, N) onto the curve with the constraint
 * <dir, X - X0>_w = s.  Returns 0, > 0 for a recoverable failure (domain,
 * no convergence), < 0 fatal. */
int cont_correct(whirl_cont *c, const double *X0, const double *dir, double s,
                 double *X);

/* Evaluate the tangent and every test function at st->X, with the border row
 * taken from dir (the predictor direction); st->t is oriented along dir. */
int cont_analyse(whirl_cont *c, cont_state *st, const double *dir);
/* [F_x F_p; r^T] at (X, p) factored, r the weighted dir (0, 2 a model
 * failure, 3 singular, < 0 fatal), and solves with it (trans: its
 * transpose; WHIRL_EINVAL when the structured solver has none). */
int cont_factor_at(whirl_cont *c, const double *X, const double *p, const double *dir);
int cont_solve_ext(whirl_cont *c, double *b, int trans);
/* At a start X0 (solving F, F_x singular) with t a unit null vector of
 * [F_x F_p]: when X0 is a simple branch point, the unit tangent u[N] of
 * the branch nearest t, on t's side (bpstart.c), and 0; > 0 when it is
 * not one (a fold) or its matrix is singular, < 0 on errors. */
int cont_bp_start_tangent(whirl_cont *c, const double *X0, const double *p0, const double *t,
                          double *u);
int cont_tangent(whirl_cont *c, cont_state *st, const double *dir);
int cont_tests(whirl_cont *c, cont_state *st);

/* Weighted inner product of N-vectors: sum of w2[i] a[i] b[i], w2 the
 * squared weights of the components (x_weight, p_weight). */
double cont_dot(const whirl_cont *c, const double *a, const double *b);

/* |A - B|² in the same weighted norm. */
double cont_dist2(const whirl_cont *c, const double *A, const double *B);

/* Copy a state (all arrays). */
void cont_state_copy(const whirl_cont *c, cont_state *dst,
                     const cont_state *src);

/* A special point found in a step: its kind, instance and localisation. */
typedef struct cont_event {
  int ev;
  size_t k;
  cont_state *st;
  cont_state *next; /* opt.loc_epss: AUTO's point, where the branch goes
                       on from (st is the converged point reported) */
  int its; /* Newton iterations of its localisation's last correction */
} cont_event;

/* Event kinds localised by locate.c. */
enum { EV_LP, EV_BP, EV_HB, EV_PD, EV_PMIN, EV_PMAX, EV_UZ, EV_NKIND = EV_UZ,
       EV_SYS = EV_UZ + 1 /* system test function k */ };

/* The quantity the user value uz[k] refers to at state st (locate.c). */
double cont_uz_value(const whirl_cont *c, size_t k, const cont_state *st);

/* Localise the zero of the test function of event kind ev (k: UZ index)
 * between c->cur (s = 0) and the trial point (s = ds) along c->dir; on
 * success fills *out and returns 0; returns > 0 when the zero cannot be
 * bracketed or the corrector fails (the event is then dropped). */
/* The k-th largest real part among the complex eigenvalues of st, or
 * modulus minus 1 among its complex multipliers; NaN when it has fewer
 * than k.  Unlike psi_hb (the one nearest the boundary, which jumps when
 * another pair becomes the nearest), an order statistic of continuous
 * functions is continuous, and it changes sign wherever the count of
 * complex ones beyond the boundary goes through k. */
double cont_hb_rank_test(const whirl_cont *c, const cont_state *st, int k);
/* mu + 1 of the k-th most negative real part of a multiplier (NaN: fewer). */
double cont_pd_rank_test(const cont_state *st, int k);

int cont_locate(whirl_cont *c, int ev, size_t k, const cont_state *b,
                cont_state *out);

/* The unknown whose turning points are the LPs (options.lead, else the
 * continuation parameter X[n]). */
static inline size_t cont_lead(const whirl_cont *c) {
  return c->opt.lead >= 0 ? (size_t)c->opt.lead : c->n;
}

#endif

/* whirl/fold.h — constructor: the fold (limit point) curve of any whirl_system
 * as a new whirl_system, by minimal augmentation (Govaerts 2000, "Numerical
 * methods for bifurcations of dynamical equilibria", ch. 4; Doedel et al.,
 * AUTO-07p manual, ISW = 2).
 *
 * For a base problem F(x, p) = 0 (n equations), a fold in the parameter
 * q = p[par] is a solution where F_x is singular.  With border vectors b, c
 * the bordered matrix  M = [F_x b; c^T 0]  is regular at a simple fold and
 *     M [v; g] = [0; 1],   M^T [w; g] = [0; 1]
 * define g(x, p), which vanishes exactly where F_x is singular, and the right
 * and left null vectors v, w.  The fold system is
 *     F(x, p) = 0,  g(x, p) = 0          in the unknowns (x, p[free[0]])
 * and is continued by the core in a second parameter (its ICP).  Its
 * Jacobian row of g is g_z = -w^T (F_x)_z v, obtained from two base
 * Jacobians (directional difference along v), so the fold system is itself
 * a whirl_system with a Jacobian and nests: a fold of a fold system, a fold
 * of a harmonic-balance system.  The borders follow the null vectors at
 * every accepted point.
 *
 * Codimension-two points are test functions of the fold system
 * (whirl_system.test), detected and localised by the core:
 *   CP  cusp:      w^T F_xx[v, v] = 0 (the fold's quadratic coefficient)
 *   BT  Bogdanov-Takens: w^T v = 0 (zero eigenvalue becomes double; only
 *                  for a base whose spectrum is its eigenvalues)
 *   ZH  zero-Hopf: a complex pair of F_x on the imaginary axis (bialternate
 *                  product over the other eigenvalues; equilibria only)
 *   IS / MG  w^T F_q = 0: q lies in the range of F_x, so the base problem is
 *                  singular in (x, q) as well (G = G_eps = G_Omega = 0 for the
 *                  circular SFD orbits).  The second parameter has an
 *                  extremum along the fold curve: an isolated branch is born
 *                  (IS, the reduced Hessian is definite: a point solution) or
 *                  two branches cross and an isola merges (MG, indefinite).
 * With `cond` set, one of these conditions becomes an extra equation and a
 * second parameter an unknown: the codimension-two curve, continued in a
 * third parameter by the same core.
 *
 * Branch points.  F_x singular and w^T F_q = 0 is also where [F_x F_q]
 * loses rank: a branch point of the base's branches in q (cond BP: the MG
 * equation, the points labelled BP).  Generic BPs need three parameters
 * (free = {q, r}, continued in a third); where a symmetry keeps them in
 * two, `unfold` adds beta instead of r: F + beta b = 0, g = 0, w^T F_q =
 * 0 in (x, q, beta), beta = 0 on the curve (the unfolding of AUTO's BP
 * continuation, F. Dercole's, whose b phi_1^* is this b beta; Govaerts
 * 2000, §4.3).  The row of w^T F_q, with [phi; gamma] = M^{-1} [F_q; 0]:
 *     (w^T F_q)_z = w^T F_qz − w^T (F_x)_z phi,
 * from base Jacobians at q +- h and x +- h phi, so the branch-point curve
 * of a collocation orbit or a BVP keeps the sparse path (AUTO's ISW = 2
 * and 3 at a BP of orbits or of a BVP).
 *
 * The same augmentation holds for any operator A(x, p) whose singularity
 * defines the bifurcation, not only F_x: with `op` set, A is the leading
 * na x na block of F_x plus constant entries (whirl_fold_operator), g
 * comes from [A b; c^T 0] and g_z = -w^T A_z v from the base Jacobians at
 * x +- h (v, 0).  A period doubling of a collocation orbit is such a point:
 * A is the collocation Jacobian on the nodes with the antiperiodic
 * condition x(1) + x(0) = 0, singular exactly when the monodromy has the
 * multiplier -1 (whirl_colloc_pd_operator; the period-doubling locus).
 * Such a curve has no test functions of its own.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_FOLD_H
#define WHIRL_FOLD_H

#include <stddef.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum whirl_fold_cond {
  WHIRL_FOLD_COND_NONE = 0, /* the fold curve itself */
  WHIRL_FOLD_COND_CP = 1,   /* cusp curve */
  WHIRL_FOLD_COND_BT = 2,   /* Bogdanov-Takens curve */
  WHIRL_FOLD_COND_MG = 3,   /* isola-centre / merge curve: w^T F_q = 0 */
  WHIRL_FOLD_COND_BP = 4    /* branch-point curve: w^T F_q = 0, its points BPs */
} whirl_fold_cond;

/* Indices of the test functions in whirl_system.test of a fold system. */
enum {
  WHIRL_FOLD_TEST_CP = 0,
  WHIRL_FOLD_TEST_BT = 1,
  WHIRL_FOLD_TEST_ZH = 2,
  WHIRL_FOLD_TEST_MG = 3,
  WHIRL_FOLD_NTEST = 4
};

/* A = (F_x)[0..na, 0..na] + E, E with ne entries (ei[k], ej[k], ev[k]);
 * E must not depend on (x, p).  The arrays are copied by whirl_fold_alloc. */
typedef struct whirl_fold_operator {
  size_t na;                 /* 1..n */
  size_t ne;
  const size_t *ei, *ej;
  const double *ev;
  int point_type;            /* what the curve's points are (WHIRL_PT_PD) */
  const char *name;          /* the curve's name ("period-doubling curve") */
  /* Optional (0: none): A's block is a collocation orbit's, nstate states
   * at the NTST NCOL + 1 node-major nodes, the n NCOL collocation rows of
   * each interval in turn, then the boundary rows (E's) in u(0) and u(1):
   * the torus locus eliminates it interval by interval (whirl/trloc.h). */
  size_t nstate, ntst, ncol;
} whirl_fold_operator;

typedef struct whirl_fold_options {
  size_t par;     /* q: the parameter in which the point is a fold (the
                     base branch's continuation parameter, e.g. Omega) */
  size_t nfree;   /* parameters appended to the unknowns: 1, or 2 with cond */
  size_t free[2]; /* their indices (default {par}); a fold locus with q held
                     fixed frees another parameter instead */
  int cond;       /* whirl_fold_cond: extra equation (needs nfree == 2) */
  const whirl_fold_operator *op; /* NULL: F_x (a fold); else the operator
                                    whose singularity is followed (no cond) */
  int unfold;     /* with cond BP: the second unknown is no parameter but
                     the unfolding beta of F + beta b = 0 (b the left
                     border), a branch-point curve in two parameters where
                     a symmetry keeps the BPs (AUTO's ISW = 2; without it,
                     ISW = 3, free[1] is a third parameter) */
} whirl_fold_options;

/* Defaults: the fold curve in (par, ICP): nfree 1, free {par}, no cond. */
WHIRL_API void whirl_fold_options_default(whirl_fold_options *o, size_t par);

typedef struct whirl_fold whirl_fold;

/* base is copied (its data stays borrowed: free the fold before the
 * system it is built on, whose structured solver it may use).  NULL on
 * bad options or out of memory, with a message in errbuf. */
WHIRL_API whirl_fold *whirl_fold_alloc(const whirl_system *base,
                                       const whirl_fold_options *o,
                                       char *errbuf, size_t errlen);
WHIRL_API void whirl_fold_free(whirl_fold *f); /* accepts NULL */

/* The fold system: n + nfree unknowns (x, p[free[0]], p[free[1]]), the
 * base's parameters (the freed ones are read from the unknowns). */
WHIRL_API const whirl_system *whirl_fold_system(const whirl_fold *f);
WHIRL_API size_t whirl_fold_size(const whirl_fold *f);

/* Start from a (localised) fold (x, p) of the base: sets the borders to the
 * null vectors of F_x (SVD) and fills Z[n + nfree].  Returns WHIRL_OK, or
 * an error code with the message in whirl_fold_errmsg. */
WHIRL_API int whirl_fold_init(whirl_fold *f, const double *x, const double *p,
                              double *Z);

/* At a point Z of the fold system (p: the other parameters): the null
 * vectors v[n], w[n] (v[na], w[na] with an operator) (normalised c^T v = 1, b^T w = 1 with the current
 * borders), g, and the test values tau[WHIRL_FOLD_NTEST] (any may be NULL). */
WHIRL_API int whirl_fold_vectors(whirl_fold *f, const double *Z,
                                 const double *p, double *v, double *w,
                                 double *g, double *tau);

/* The type of the curve's points: WHIRL_PT_LP, or the operator's. */
WHIRL_API int whirl_fold_point_type(const whirl_fold *f);

/* Copy the base parameter vector with the freed parameters taken from Z. */
WHIRL_API void whirl_fold_params(const whirl_fold *f, const double *Z,
                                 const double *p, double *pfull);

WHIRL_API const char *whirl_fold_errmsg(const whirl_fold *f);

#ifdef __cplusplus
}
#endif
#endif

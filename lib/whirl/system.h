/* whirl/system.h — the algebraic problem F(x, p) = 0 seen by the continuation
 * core.  n equations in n unknowns x, with npar parameters p of which one is
 * free during a continuation.  Equilibria, harmonic balance, collocation, fold
 * and Hopf systems are constructors producing a whirl_system; they nest.
 *
 * Callback contract as in whirl/problem.h: 0 ok, > 0 recoverable (domain),
 * < 0 fatal.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SYSTEM_H
#define WHIRL_SYSTEM_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Optional structured solver for the core's bordered Newton matrix
 *
 *     M = [ F_x(x, p)   dF/dp_k(x, p) ]   order n + 1, k the free parameter,
 *         [        r^T                ]   r[n + 1] the border row
 *
 * (the pseudo-arclength row of the corrector, the predictor direction when
 * the core computes the tangent and the determinant).  A constructor whose
 * Jacobian has more structure than a general sparse LU exploits supplies
 * one, and the core then never assembles M: collocation eliminates the
 * interior unknowns of every mesh interval by small dense LUs (condensation
 * of parameters) and the mesh points by a structured elimination (Doedel,
 * Keller & Kernévez, Int. J. Bif. Chaos 1 (1991) 745; AUTO-07p manual).
 * The factorisation lives in a workspace the core allocates, so one system
 * may serve several continuations.  factor evaluates F_x and dF/dp_k at
 * (x, p) itself.  factor, solve and logdet return WHIRL_OK; factor may also
 * return > 0 for a recoverable model failure (domain), WHIRL_EBADFUNC for a
 * non-finite Jacobian, WHIRL_ESINGULAR for an exactly singular M (logdet is
 * then still usable and reports sign 0, solve is not), or another error. */
typedef struct whirl_bsolver {
  void *(*alloc)(void *data); /* data: the system's; NULL on no memory */
  void (*free)(void *ws);     /* accepts NULL */
  int (*factor)(void *ws, const double *x, const double *p, size_t k,
                const double *r);
  /* M z = b in place, b[(n+1)*nrhs] column-major, last factorisation */
  int (*solve)(void *ws, double *b, size_t nrhs);
  /* log|det M| and its sign (-1, 0, +1), the determinant of M itself (row
   * and column order as above), so its sign changes at branch points
   * exactly as that of a general LU of M */
  int (*logdet)(void *ws, double *logabs, int *sign);
  /* Optional: factor M again with a new border row r but F_x and dF/dp_k
   * of the last factor (for chord Newton: much cheaper than factor when
   * the structure allows).  Same returns as factor. */
  int (*reborder)(void *ws, const double *r);
  /* Optional: factor [F_x col; r^T], the given column col[n] in place of
   * dF/dp_k (F_x at (x, p) as factor's), e.g. a fold system's bordered
   * [F_x b; c^T 0].  Same returns as factor. */
  int (*factor_col)(void *ws, const double *x, const double *p,
                    const double *col, const double *r);
  /* Optional: M^T y = c in place, c[(n+1)*nrhs], with the last
   * factorisation (the left null vector of a fold system). */
  int (*solve_t)(void *ws, double *b, size_t nrhs);
  /* Optional: factor as factor does, and F(x, p) into f[n] from the
   * model evaluations the Jacobian makes, the bytes the system's F gives
   * (AUTO-07p's SETUBV makes the residual with the Jacobian): a Newton
   * iteration with a new Jacobian then evaluates the model once.  Same
   * returns as factor; f is complete when it returns 0. */
  int (*factor_F)(void *ws, const double *x, const double *p, size_t k,
                  const double *r, double *f);
} whirl_bsolver;

typedef struct whirl_system {
  const char *name;
  size_t n;     /* number of equations and of unknowns */
  size_t npar;  /* number of parameters */

  /* f[n] = F(x, p).  Required. */
  int (*F)(const double *x, const double *p, double *f, void *data);

  /* Dense Jacobian J[n*n], column-major, J[i + n*j] = dF_i/dx_j.
   * Optional: NULL -> finite differences (or the sparse callback below). */
  int (*Fx)(const double *x, const double *p, double *J, void *data);

  /* Parameter derivative fk[n] = dF/dp_k.  Optional: NULL -> differences. */
  int (*Fp)(const double *x, const double *p, size_t k, double *fk,
            void *data);

  /* Optional sparse Jacobian: a fixed compressed-column pattern Jp[n+1],
   * Ji[nnz] (row indices, sorted within a column), and a callback filling the
   * values Jx[nnz] in pattern order.  When present the core can use the
   * sparse (UMFPACK) path: symbolic analysis once, numeric factorisation at
   * every Newton step. */
  size_t nnz;
  const int *Jp;
  const int *Ji;
  int (*Fx_sparse)(const double *x, const double *p, double *Jx, void *data);

  /* Optional stability spectrum of the solution (x, p): fills re[m], im[m]
   * with exponents whose positive real part means instability (eigenvalues
   * for an equilibrium, Floquet exponents for a periodic orbit), and sets *m.
   * On entry *m is the capacity (>= nspec).  J is the dense Jacobian at
   * (x, p) when the core has it, else NULL.  Enables HB detection. */
  size_t nspec;
  int (*spectrum)(const double *x, const double *p, const double *J,
                  double *re, double *im, size_t *m, void *data);

  /* What spectrum() returns: WHIRL_SPEC_EIGENVALUES (default, stability
   * means Re < 0; a complex pair crossing the imaginary axis is a Hopf point)
   * or WHIRL_SPEC_MULTIPLIERS (Floquet multipliers of a periodic orbit,
   * stability means |mu| < 1, the trivial multiplier of an autonomous orbit
   * left out; a real multiplier through -1 is a period doubling PD, a complex
   * pair through the unit circle a torus point TR). */
  int spectrum_kind;

  /* Optional: called by the core at the start point and after every
   * accepted continuation point, before the next step, so that a
   * constructor can update references that its equations use (the integral
   * phase condition of collocation, Doedel's AUTO).  Returns 0 or an error. */
  int (*accept)(const double *x, const double *p, void *data);

  /* Optional test functions of the system itself: tau[ntest] at (x, p),
   * whose sign changes the core detects and localises along a branch like
   * its own LP/BP/HB tests.  types[k] receives the point type (a
   * whirl_point_type, e.g. WHIRL_PT_CP) that a zero of tau[k] near (x, p)
   * stands for, or 0 when a sign change there is not a special point (a
   * neutral saddle for the zero-Hopf test).  Fold and Hopf systems use this
   * to label codimension-two points of the problem they were built on
   * (cusp, Bogdanov-Takens, zero-Hopf, isola birth and merge). */
  size_t ntest;
  int (*test)(const double *x, const double *p, double *tau, int *types,
              void *data);

  /* Optional structured solver for the bordered Newton matrix (above);
   * static, borrowed.  Used by the core unless its options say otherwise. */
  const whirl_bsolver *bsolver;

  const char *const *x_names;  /* optional, n names */
  const char *const *p_names;  /* optional, npar names */
  void *data;                  /* borrowed */

  /* Optional change of representation along a branch (mesh adaptation of
   * collocation, AUTO's IAD): called by the core before each new step with
   * the current point v[0] (x[n]) and the other vectors of unknowns it
   * keeps, v[1..nv-1] (tangent and previous point, their x parts).  A
   * system that changes what its unknowns mean (a new mesh) maps all nv
   * vectors in place and returns 1; the core then refactors and reanalyses
   * the current point.  0: nothing changed; < 0: an error. */
  int (*remap)(double *const *v, size_t nv, const double *p, void *data);

  /* Optional: q[n] >= 0, the factors of the unknowns' squared weights in
   * the arclength norm for the system's current representation, which
   * multiply the caller's (whirl_cont_options.x_weight²): collocation gives
   * the quadrature weights of its node values on its mesh, so that a
   * state's part of the norm is its integral over [0, 1], as AUTO-07p
   * measures steps (mesh.f90, RNRMSQ), and 1 for the period and free
   * parameters.  Called by the core at the start and after every remap
   * that changed the representation.  0, or an error. */
  int (*norm_weights)(double *q, void *data);

  /* Optional: the direction vector dir[n + 1] of the coming correction
   * (the unknowns' part, then the continuation parameter's; unit in the
   * arclength norm: the step's secant or tangent, e_n at a start), given
   * by the core at the start of every correction, as AUTO-07p hands its
   * direction vector to the integral conditions as UDOT (AUTO's ICND;
   * whirl_bvp_options.udot_direction).  0, or an error. */
  int (*direction)(const double *dir, void *data);
} whirl_system;

enum { WHIRL_SPEC_EIGENVALUES = 0, WHIRL_SPEC_MULTIPLIERS = 1 };

/* Finite-difference dense Jacobian of a system (central differences).
 * J[n*n] column-major; work[2n] scratch. */
WHIRL_API int whirl_system_fd_jacobian(const whirl_system *sys,
                                       const double *x, const double *p,
                                       double *J, double *work);

/* Finite-difference parameter derivative fk[n] = dF/dp_k; work[n] scratch
 * (p is copied internally, not modified). */
WHIRL_API int whirl_system_fd_param(const whirl_system *sys, const double *x,
                                    const double *p, size_t k, double *fk,
                                    double *work);

/* Evaluate F and check the result is finite: returns the callback status,
 * or WHIRL_EBADFUNC (> 0 is not used here: non-finite is reported as
 * WHIRL_EBADFUNC and treated as recoverable by the core). */
WHIRL_API int whirl_system_eval(const whirl_system *sys, const double *x,
                                const double *p, double *f);

/* Dense Jacobian by the analytic callback (Fx, else Fx_sparse scattered),
 * else finite differences.  work[max(2n, nnz)] (a sparse Jacobian's
 * values go there before they are scattered). */
/* The dense J[n*n] (column-major) of sparse values Jx[nnz] in sys's
 * pattern (Jp, Ji), zeros elsewhere: what a constructor with only a sparse
 * Jacobian gives as its dense Fx. */
WHIRL_API void whirl_system_scatter_dense(const whirl_system *sys, const double *Jx,
                                          double *J);
WHIRL_API int whirl_system_jacobian(const whirl_system *sys, const double *x,
                                    const double *p, double *J, double *work);

/* dF/dp_k by the analytic callback if present, else finite differences.
 * work[n]. */
WHIRL_API int whirl_system_param(const whirl_system *sys, const double *x,
                                 const double *p, size_t k, double *fk,
                                 double *work);

/* max |J_analytic - J_fd| / (1 + |J_analytic|) over the dense (or sparse)
 * analytic Jacobian and, if present, Fp for every parameter. */
WHIRL_API int whirl_system_check_jacobian(const whirl_system *sys,
                                          const double *x, const double *p,
                                          double *max_err);

#ifdef __cplusplus
}
#endif
#endif

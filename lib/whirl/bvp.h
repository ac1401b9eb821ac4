/* whirl/bvp.h — constructor: boundary value problems of an ODE model by
 * orthogonal collocation (AUTO-07p's IPS = 4; de Boor & Swartz 1973;
 * Doedel, AUTO-07p manual ch. 10), as an algebraic problem F(X, p) = 0 for
 * the continuation core.  The sibling of whirl/colloc.h (periodic orbits).
 *
 * The problem, on t ∈ [0, 1]:
 *     u'(t) = f(t, u, p)                     (the model, n = NDIM equations)
 *     b(u(0), u(1), p) = 0                   (NBC boundary conditions)
 *     ∫_0^1 g(u(t), p) dt = 0                (NINT integral conditions)
 * The model's time argument is t itself (no period, no shift).
 *
 * Discretisation: the mesh 0 = τ_0 < ... < τ_NTST = 1 (uniform unless set
 * by whirl_bvp_set_mesh) has NTST intervals, each carrying a polynomial of
 * degree NCOL on NCOL + 1 equally spaced nodes, continuous at the mesh
 * points; the ODE is imposed at the NCOL Gauss–Legendre points of every
 * interval, row-scaled by the interval length h_i as in colloc.h:
 *     sum_k l_k'(σ_c) u_{i,k} − h_i f(τ_{i,c}, u(τ_{i,c}), p~) = 0,
 * and the integrals are the same Gauss quadrature.
 *
 * Parameters.  The free parameters are NFPR = NBC + NINT − NDIM + 1: one is
 * the continuation core's parameter (whirl_cont_options.icp; a parameter of
 * the system, not an unknown), the other nfree = NFPR − 1 = NBC + NINT − n
 * are unknowns of the system, listed in options.free.  p~ denotes the full
 * parameter vector p with p~[free[j]] = X[n·nnodes + j]: f, b and g are
 * always called with p~ (whirl_bvp_params computes it).  The entries of p
 * at the free indices are ignored, so the continuation parameter must not
 * be one of them (its column would vanish).
 *
 * Unknowns X[size], size = n·(NTST·NCOL + 1) + nfree: the values at the
 * NTST·NCOL + 1 nodes, node-major (X[n*j + r] is component r at node j;
 * node j = i·NCOL + k, k < NCOL, sits at τ_i + k h_i / NCOL, the last node
 * at t = 1, so the mesh points are the nodes j = i·NCOL), then the nfree
 * free parameters in the order of options.free.
 * Equations, as many: the n·NTST·NCOL collocation equations (interval by
 * interval, Gauss point by Gauss point, n each), then the NBC boundary
 * conditions, then the NINT integral conditions.
 *
 * Jacobian: the collocation rows analytically from the model's jac_x and
 * jac_p (central differences of f when NULL), the boundary and integral
 * rows by central differences of bc and ic; options.auto_differences
 * takes AUTO-07p's rule with JAC = 0 for the free parameters and ic
 * (forward in p, none in udot).  The system has a compressed-column sparse pattern (rows sorted
 * within a column; usable by UMFPACK on the core's sparse path), a dense
 * callback built from it, and F_p for any parameter.  It has no spectrum
 * (a BVP solution has no stability).  With NTST >= 2 it has a structured
 * solver for the core's bordered matrix (whirl_system bsolver): the
 * condensation of parameters of the periodic collocation (AUTO-07p's
 * solver for IPS = 4), each interval's interior values eliminated, then
 * the mesh points, then a dense system in u(0), u(1), the free parameters
 * and the continuation parameter with the boundary and integral rows;
 * with whirl_cont_options.structured = 0 (or NTST = 1) the core's dense or
 * sparse LU factors it.  Its accept hook keeps the integral conditions'
 * reference.
 *
 * Mesh adaptation (AUTO's IAD): with options.adapt_every = k > 0 the
 * system's remap hook makes a new mesh every k accepted points, which
 * equidistributes AUTO-07p's estimate of |u^(NCOL+1)|^{1/(NCOL+1)}: the
 * jump of the piecewise constant u^(NCOL) to the next interval over the
 * distance of their midpoints (de Boor 1973; Russell & Christiansen 1978;
 * doc/auto-reference.md), the node values of the current point,
 * tangent, previous points and the integral conditions' reference carried
 * over; whirl_bvp_adaptations counts the new meshes.  0: a fixed mesh (as
 * allocated, or set by whirl_bvp_set_mesh).
 *
 * Callback contract (bc, ic and the model), as in whirl/problem.h: return 0
 * on success, > 0 for a recoverable failure (outside the domain: the core
 * shortens its step), < 0 for a fatal error.  Non-finite outputs are
 * treated as recoverable by the core.
 *
 * Ownership: prob and options.free are copied or borrowed as said below;
 * the library never prints or exits; a failure's message stays in the
 * object (whirl_bvp_errmsg) or, for whirl_bvp_alloc, in errbuf.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_BVP_H
#define WHIRL_BVP_H

#include <stddef.h>
#include <whirl/problem.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Boundary conditions fb[nbc] = b(u0, u1, p): u0 = u(0), u1 = u(1), each
 * n values; p the full parameter vector p~ (npar). */
typedef int (*whirl_bvp_bc_fn)(const double *u0, const double *u1,
                               const double *p, double *fb, void *data);
/* Integrands fi[nint] = g(u, uold, udot, upold, p) of the integral
 * conditions at a point t: u = u(t), udot = u'(t) (or the branch's
 * direction: whirl_bvp_options.udot_direction), and uold, upold the
 * reference solution and its derivative there (AUTO's ICND arguments: the
 * reference is the branch's previous point, for phase conditions: the
 * start (whirl_bvp_from_function, whirl_bvp_set_reference), then every
 * point the core accepts; zero before any).  Each n values. */
typedef int (*whirl_bvp_ic_fn)(const double *u, const double *uold,
                               const double *udot, const double *upold,
                               const double *p, double *fi, void *data);

typedef struct whirl_bvp_options {
  size_t ntst;        /* NTST, mesh intervals, 1..WHIRL_COLLOC_MAX_NTST
                         (default 20) */
  size_t ncol;        /* NCOL, collocation points per interval, 2..7
                         (default 4) */
  size_t nbc;         /* NBC, number of boundary conditions (default 0) */
  size_t nint;        /* NINT, number of integral conditions (default 0) */
  whirl_bvp_bc_fn bc; /* required when nbc > 0 */
  whirl_bvp_ic_fn ic; /* required when nint > 0 */
  void *data;         /* passed to bc and ic; borrowed */
  size_t nfree;       /* parameters that are unknowns: must equal
                         nbc + nint − n (AUTO's NFPR − 1; checked) */
  const size_t *free; /* nfree distinct parameter indices < npar; copied
                         by whirl_bvp_alloc (may be NULL when nfree = 0) */
  int adapt_every;    /* IAD: a new mesh every adapt_every accepted points
                         (above); 0 (default): a fixed mesh */
  int threads;        /* threads of the loops over the mesh intervals (the
                         Jacobian's, the residual's, F_p's), as
                         whirl_colloc_options.threads: > 0
                         that many, 0 as many as OpenMP offers, default 1.
                         With more than one the model's rhs and jac_x and
                         ic are called from several threads at once;
                         the Jacobian, F and F_p are the same bytes on
                         any number. */
  int auto_differences; /* 1: the difference quotients of AUTO-07p with
                         JAC = 0 (interfaces.f90, FUNI and ICNI) for the
                         free parameters and the integral conditions:
                         forward in each free parameter p, step
                         1e-7 (1 + |p|), from one evaluation at the point
                         shared by all; central in u; none in udot, which
                         AUTO's ICND gets as data (the branch's direction),
                         not as a function of the unknowns: an ic that
                         reads udot then has no udot terms in its rows.
                         0 (default): central in u, udot and p. */
  int udot_direction; /* 1: ic's udot is the direction of the branch,
                         as AUTO's UDOT (AUTO-07p's ICND: "derivative of
                         UOLD with respect to arclength"): the state part
                         of the core's direction vector of the correction
                         (the step's secant or tangent, unit in the
                         arclength norm; 0 at a start along the
                         parameter), interpolated at t as u; no
                         difference is taken in it.  0 (default): udot =
                         u'(t). */
} whirl_bvp_options;

/* Defaults: NTST 20, NCOL 4, no conditions, no free parameters, fixed
 * mesh, one thread. */
WHIRL_API void whirl_bvp_options_default(whirl_bvp_options *o);

typedef struct whirl_bvp whirl_bvp;

/* prob is borrowed and must outlive the object.  NULL on bad options (the
 * count NBC + NINT = n + nfree, NCOL, NTST, missing callbacks, free indices
 * out of range or repeated, too large for int indices) or no memory, with
 * the message in errbuf[errlen] (errbuf may be NULL). */
WHIRL_API whirl_bvp *whirl_bvp_alloc(const whirl_problem *prob,
                                     const whirl_bvp_options *o, char *errbuf,
                                     size_t errlen);
WHIRL_API void whirl_bvp_free(whirl_bvp *b); /* accepts NULL */

/* The system F(X, p) = 0 (owned by b, valid while b lives). */
WHIRL_API const whirl_system *whirl_bvp_system(const whirl_bvp *b);
/* Unknowns (= equations): n (NTST NCOL + 1) + nfree; 0 for NULL.  The
 * system's F_p(k) is 0 for a free k (p~ takes it from X). */
WHIRL_API size_t whirl_bvp_size(const whirl_bvp *b);

/* pfull[npar] = p with the free parameters taken from X (p~ above); pfull
 * may be p itself. */
WHIRL_API void whirl_bvp_params(const whirl_bvp *b, const double *X,
                                const double *p, double *pfull);

/* Initial guess from a function (AUTO's STPNT(T)): u(t, u, p, d) fills u[n]
 * at t for every node time t ∈ [0, 1] (in increasing order) and may set
 * parameters in p[npar] (in/out, as STPNT's PAR); afterwards X's free
 * entries are p[free[j]].  u returns 0, or a non-zero status that stops the
 * filling and is returned (message in whirl_bvp_errmsg). */
WHIRL_API int whirl_bvp_from_function(whirl_bvp *b,
                                      int (*u)(double t, double *u, double *p,
                                               void *d),
                                      void *d, double *X, double *p);

/* The solution at t ∈ [0, 1]: u[n].  WHIRL_EINVAL outside [0, 1]. */
WHIRL_API int whirl_bvp_eval(const whirl_bvp *b, const double *X, double t,
                             double *u);

/* AUTO's L2-NORM: sqrt(∫_0^1 |u(t)|² dt) by AUTO's quadrature of the node
 * values (each interval's closed Newton-Cotes rule, mesh.f90 RNRMV); NaN
 * for NULL arguments. */
WHIRL_API double whirl_bvp_l2norm(const whirl_bvp *b, const double *X);

/* mx[n]: the maximum over the nodes of each component (AUTO's MAX U(i)). */
WHIRL_API int whirl_bvp_max(const whirl_bvp *b, const double *X, double *mx);

/* AUTO's measures of each component: m1[i] = ∫₀¹ u_i, m2[i] = ∫₀¹ u_i²
 * (5-point Gauss–Legendre on each mesh interval: exact for NCOL <= 4),
 * mn[i] and mx[i] the minimum and maximum over the nodes.  WHIRL_OK or
 * WHIRL_EINVAL. */
WHIRL_API int whirl_bvp_moments(const whirl_bvp *b, const double *X, double *m1,
                                double *m2, double *mn, double *mx);

/* The reference solution of the integral conditions (uold, upold): the
 * node values of X (copied).  The system's accept hook sets it to every
 * point the core accepts, as AUTO's UOLD. */
WHIRL_API int whirl_bvp_set_reference(whirl_bvp *b, const double *X);

/* The meshes adapted so far (adapt_every > 0). */
WHIRL_API size_t whirl_bvp_adaptations(const whirl_bvp *b);

/* Current mesh tau[NTST + 1]. */
WHIRL_API const double *whirl_bvp_mesh(const whirl_bvp *b);
/* Set the mesh tau[NTST + 1], 0 = tau_0 < ... < tau_NTST = 1 (copied); X
 * is not remapped (its node values then sit at the new nodes).
 * WHIRL_EINVAL for a mesh that is not increasing from 0 to 1. */
WHIRL_API int whirl_bvp_set_mesh(whirl_bvp *b, const double *tau);

/* AUTO's ADAPT2 (mesh.f90, NEWMSH) of a restart onto another NTST or NCOL:
 * b's mesh becomes the one of b's NTST intervals that equidistributes the
 * estimate of the (NCOL+1)-th derivative (as the remap hook's) of the
 * solution Xold, node values on nold intervals of degree mold over
 * old_mesh; a solution too flat for the estimate gets the uniform mesh.
 * The caller then samples Xold at the new nodes (whirl_bvp_from_function).
 * WHIRL_EINVAL for a mesh not increasing from 0 to 1 or a non-finite Xold. */
WHIRL_API int whirl_bvp_mesh_from(whirl_bvp *b, size_t nold, size_t mold,
                                  const double *old_mesh, const double *Xold);

/* The message of the last failure of a function given b, with its origin
 * "(bvp.c:N)"; "" if none.  Never NULL. */
WHIRL_API const char *whirl_bvp_errmsg(const whirl_bvp *b);

#ifdef __cplusplus
}
#endif
#endif

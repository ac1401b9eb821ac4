/* whirl/colloc.h — constructor: periodic orbits of an ODE model by
 * orthogonal collocation (de Boor & Swartz 1973; Doedel, AUTO-07p manual
 * ch. 10), as an algebraic problem F(X, p) = 0 for the continuation core.
 *
 * Time is scaled to τ = t/T ∈ [0, 1]; the mesh 0 = τ_0 < ... < τ_NTST = 1
 * has NTST intervals, each carrying a Lagrange polynomial of degree NCOL on
 * NCOL + 1 equally spaced nodes; the ODE x' = T f(t0 + Tτ, x, p) is imposed at
 * the NCOL Gauss–Legendre points of each interval.  Unknowns X: the values at
 * the NTST·NCOL + 1 nodes (n each, node-major: X[n*j + i]), then, for an
 * autonomous model, the period T.  Equations: n·NTST·NCOL collocation
 * equations, n periodicity equations x(1) − x(0) = 0, and for autonomous
 * models the integral phase condition ∫ <x(τ), x_ref'(τ)> dτ = 0 against the
 * last accepted solution (updated through the system's accept hook).
 *
 * Forced (non-autonomous) models: forcing_param >= 0 names the parameter
 * that is the forcing frequency ω, and the period is T = 2π·nu/ω (nu > 1
 * for subharmonic orbits); there is no phase condition and T is not an
 * unknown.
 *
 * The Jacobian is sparse (compressed-column pattern in the system, usable
 * by UMFPACK on the sparse path); a dense callback is also provided.  The
 * system also has a structured solver for the core's bordered Newton matrix
 * (whirl_system bsolver): condensation of parameters interval by interval
 * and a block elimination of the mesh points, as AUTO-07p, which the core
 * uses by default.  The system's spectrum is the Floquet multipliers of the
 * orbit (from the condensed collocation equations by default, or from the
 * variational equations, see whirl_colloc_floquet), so the core reports
 * stability and detects PD and TR; LP comes from the core's fold test.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_COLLOC_H
#define WHIRL_COLLOC_H

#include <stddef.h>
#include <whirl/fold.h>
#include <whirl/problem.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Largest NTST accepted (the run files' limit too); the unknowns and the
 * Jacobian's nonzeros must also fit in int indices. */
#define WHIRL_COLLOC_MAX_NTST 100000

typedef struct whirl_colloc_options {
  size_t ntst;       /* NTST, mesh intervals (default 20, at most
                        WHIRL_COLLOC_MAX_NTST) */
  size_t ncol;       /* NCOL, collocation points per interval, 2..7 (default 4) */
  int forcing_param; /* >= 0: forced model, ω = p[forcing_param];
                        -1 (default): autonomous, T unknown */
  unsigned nu;       /* forced models: period 2π·nu/ω (default 1) */
  double t0;         /* forced models: time of τ = 0 (default 0) */
  double floquet_rtol; /* integrator tolerance for the multipliers (1e-11) */
  int floquet;       /* route to the multipliers (whirl_colloc_floquet):
                        WHIRL_COLLOC_FLOQUET_CONDENSED (default) or
                        WHIRL_COLLOC_FLOQUET_VARIATIONAL */
  int adapt_every;   /* IAD: adapt the mesh to the orbit (whirl_colloc_adapt)
                        every adapt_every continuation steps, the current
                        point, tangent and previous points carried over by
                        the system's remap hook; 0 (default): fixed mesh */
  int mesh_jumps;    /* the density the adapted mesh equidistributes: 0
                        (default) |x^(NCOL)|^{1/(NCOL+1)} of the collocation
                        polynomial; 1: AUTO-07p's |x^(NCOL+1)|^{1/(NCOL+1)}
                        from the jumps of x^(NCOL) between neighbouring
                        intervals, the last to the first (its EQDF), so a
                        run follows AUTO's meshes */
  int phase_nodes;   /* the phase condition of autonomous orbits: 0
                        (default) ∫ <x, x_ref'> by Gauss's rule on each
                        interval, x_ref' the reference polynomial's
                        derivative; 1: AUTO-07p's ∫ <x − x_ref, T f(x_ref)>
                        by the Lagrange integrals' weights at the NCOL + 1
                        nodes (ICPS, STUPBV), the model's f at the
                        reference's nodes (and the eigenfunction's exact
                        derivative at a Hopf start, STHOPF), so a run
                        takes AUTO's phases along a branch */
  int free_param;    /* autonomous orbits at a fixed period (AUTO: IPS 2 with
                        11 not in ICP): >= 0, the period is `period` and the
                        unknown in its place (X's last entry) is this
                        parameter, the second free one beside the core's
                        continuation parameter; -1 (default): T unknown */
  double period;     /* free_param >= 0: the fixed period, > 0 */
  int threads;       /* threads of the loops over the mesh intervals (the
                        residual, the Jacobian's blocks and their
                        condensation): 1 (default) serial; > 1 that many;
                        0 as many as OpenMP offers (OMP_NUM_THREADS, else
                        the processors).  With more than one the model's
                        rhs and Jacobians are called from several threads
                        at once (as AUTO-07p's OpenMP build calls FUNC):
                        they must not share scratch.  Results do not
                        depend on the number of threads. */
} whirl_colloc_options;

/* The Floquet multipliers of the system's spectrum.  CONDENSED: the
 * eigenvalues of the monodromy matrix of the discretised orbit, the product
 * of the interval transfer matrices left by the condensation of the
 * collocation equations (AUTO-07p; Doedel et al. 1991): nearly free, and as
 * accurate as the orbit (superconvergence at the mesh points).
 * VARIATIONAL: integration of the variational equations along the
 * collocation polynomial's start point x(0) at tolerance floquet_rtol
 * (whirl/floquet.h), an independent check.  For an autonomous orbit both
 * leave the trivial multiplier out through the linearised Poincaré map. */
typedef enum whirl_colloc_floquet {
  WHIRL_COLLOC_FLOQUET_CONDENSED = 0,
  WHIRL_COLLOC_FLOQUET_VARIATIONAL = 1
} whirl_colloc_floquet;

WHIRL_API void whirl_colloc_options_default(whirl_colloc_options *o);

typedef struct whirl_colloc whirl_colloc;

/* prob is borrowed and must outlive the object.  NULL on bad options or
 * memory (message in errbuf). */
WHIRL_API whirl_colloc *whirl_colloc_alloc(const whirl_problem *prob,
                                           const whirl_colloc_options *o,
                                           char *errbuf, size_t errlen);
WHIRL_API void whirl_colloc_free(whirl_colloc *c); /* accepts NULL */

WHIRL_API const whirl_system *whirl_colloc_system(const whirl_colloc *c);
WHIRL_API size_t whirl_colloc_size(const whirl_colloc *c); /* unknowns */

/* Initial guess X[size] from m samples of one period, x[k*n + i] at
 * t_k = k T/m, k = 0..m-1 (uniform, periodic, no end point), interpolated
 * periodically (cubic) onto the mesh nodes.  For autonomous models T is
 * stored in X and the phase reference is set from the samples.  Linear in
 * the samples for fixed T, so it also maps perturbations (directions). */
WHIRL_API int whirl_colloc_from_samples(whirl_colloc *c, const double *x,
                                        size_t m, double T, double *X);

/* The orbit at τ ∈ [0, 1] (scaled time): x[n]. */
WHIRL_API int whirl_colloc_eval(const whirl_colloc *c, const double *X,
                                double tau, double *x);

/* Period of the orbit X at parameters p. */
WHIRL_API double whirl_colloc_period(const whirl_colloc *c, const double *X,
                                     const double *p);

/* Adapt the mesh to the orbit X (equidistribute |x^(NCOL)|^{1/(NCOL+1)},
 * Russell & Christiansen 1978, as AUTO's IAD) and re-interpolate X onto
 * the new mesh in place.  The mesh is part of the object, so the caller
 * restarts its continuation from the remapped X. */
WHIRL_API int whirl_colloc_adapt(whirl_colloc *c, double *X);

/* The message of the last failure of a function given c (or, for
 * whirl_colloc_pd_switch, c2), with its origin "(colloc.c:N)"; also of a
 * failed evaluation of the multipliers.  Never NULL. */
WHIRL_API const char *whirl_colloc_errmsg(const whirl_colloc *c);

/* Meshes adapted along branches so far (options.adapt_every). */
WHIRL_API size_t whirl_colloc_adaptations(const whirl_colloc *c);

/* Branch switching at a period doubling: from the orbit X (period T) at a
 * PD point at parameters p, fill the collocation object c2 (same model and
 * options, NTST typically doubled; for forced models nu doubled) with the
 * doubled orbit X2 (the orbit traversed twice, period 2T) and the direction
 * D2[size(c2) + 1] (last entry: the free parameter, 0) along which the
 * period-2 branch leaves: the Floquet eigenvector φ of the multiplier −1
 * carried along the orbit by the variational equations, φ(t + T) = −φ(t).
 * Start the new branch with whirl_cont_start_direction(cont, X2, p, D2).
 *
 * If c2 has NTST2 = 2·NTST and the same NCOL, its mesh is set to c's mesh
 * traversed twice (τ/2, then 1/2 + τ/2) and X2 holds X's node values twice,
 * so X2 solves c2's equations exactly as X solves c's; otherwise X2 is c's
 * piecewise polynomial evaluated at c2's nodes.  The phase reference of c2
 * (autonomous models) is set to X2.  D2 has unit Euclidean norm, zero
 * period (T) entry and zero parameter entry; its sign is arbitrary (both
 * signs give the same period-2 orbit, shifted by T).  The eigenvector is the
 * right singular vector of M + I for the smallest singular value, M the
 * monodromy matrix at tolerance floquet_rtol.  WHIRL_EINVAL for NULL
 * arguments, c2 == c, or a c2 that does not match c (state dimension,
 * number of parameters, autonomous/forced, forcing parameter, t0, and for
 * forced models nu2 = 2 nu); WHIRL_ENOMEM, or the integrator's error (c2's
 * mesh may then have been changed already).
 * The start is a branch point of c2's system (the period-1 orbit traversed
 * twice crosses the period-2 branch there), where the bordered Jacobian is
 * singular: give the continuation a first step ds that leaves its
 * neighbourhood (for Lorenz, ds ≈ 0.02·sqrt(size(c2)) in the unweighted
 * arclength norm); a very small one can make Newton fail down to DSMIN. */
WHIRL_API int whirl_colloc_pd_switch(const whirl_colloc *c, const double *X,
                                     const double *p, whirl_colloc *c2,
                                     double *X2, double *D2);

/* Restart from a stored orbit: set the mesh tau[NTST + 1] (0 = tau_0 <
 * ... < tau_NTST = 1) before whirl_colloc_set_reference with the stored X.
 * WHIRL_EINVAL for a mesh that is not increasing from 0 to 1. */
WHIRL_API int whirl_colloc_set_mesh(whirl_colloc *c, const double *tau);
/* AUTO-07p's start from a solution on another mesh (its ADAPT2): the
 * mesh of c becomes the one that equidistributes AUTO's density (EQDF,
 * periodic: the jumps of the derivative of order mold) of the piecewise
 * polynomial Xold (node values on nold intervals of degree mold over
 * old_mesh[nold + 1], from 0 to 1, NTST * NCOL + 1 rows of n; data rows
 * are mold = 1), and the node part of X is Xold at the new nodes (its
 * last entry, the period, is left).  WHIRL_EINVAL or WHIRL_ENOMEM. */
WHIRL_API int whirl_colloc_adapt_from(whirl_colloc *c, size_t nold, size_t mold,
                                      const double *old_mesh, const double *Xold,
                                      double *X);
/* ADAPT2's interpolation of a second function (AUTO's VPS: the direction
 * of a restart) on c's present mesh: the node part of V is Vold (as Xold
 * of whirl_colloc_adapt_from) at c's nodes; V's other entries are left. */
WHIRL_API int whirl_colloc_interp_from(whirl_colloc *c, size_t nold, size_t mold,
                                       const double *old_mesh, const double *Vold,
                                       double *V);
/* Phase reference of an autonomous orbit (no-op for forced models). */
WHIRL_API int whirl_colloc_set_reference(whirl_colloc *c, const double *X);

/* Start of the periodic branch at a Hopf point x0[n] of the model at p
 * (AUTO's IPS = 2 from an HB label): X[size] the constant orbit x0 with
 * period 2π/ω, D[size + 1] the unit direction x0 + Re(φ e^{2πiτ}) of the
 * bifurcating orbits (φ the eigenvector of ±iω; period and parameter entries
 * 0), the phase reference set to X + D, *omega (may be NULL) = ω, the pair
 * of f_x(x0) closest to the imaginary axis.  Start the continuation with
 * whirl_cont_start_direction(cont, X, p, D).  Autonomous models only;
 * WHIRL_EINVAL when f_x has no complex pair. */
WHIRL_API int whirl_colloc_hopf_start(whirl_colloc *c, const double *x0,
                                      const double *p, double *X, double *D,
                                      double *omega);
/* The same from the pair of f_x(x0) nearest i omega_want (> 0; 0: the
 * pair nearest the imaginary axis): the orbits of one of several centres
 * of a conservative system (AUTO's TY = 'HBk' on a restart, demo r3b's
 * Lyapunov and vertical families from a libration point). */
WHIRL_API int whirl_colloc_hopf_start_at(whirl_colloc *c, const double *x0,
                                         const double *p, double omega_want,
                                         double *X, double *D, double *omega);

/* Rotations (AUTO's NRTN): components that are angles turning by 2 pi k
 * over one period get the periodicity x(1) - x(0) = 2 pi k, k = nint(jump
 * / 2 pi) from the jumps jump[n] (set_rotations) or from the orbit X's
 * x(1) - x(0) (rotations_of; call it after X is set, before continuing).
 * from_samples then reads samples of such an orbit (without the endpoint).
 * The number of rotating components. */
WHIRL_API size_t whirl_colloc_set_rotations(whirl_colloc *c, const double *jump);
WHIRL_API size_t whirl_colloc_rotations_of(whirl_colloc *c, const double *X);
/* The rotations in force, rot[n] (2 pi k, or 0 for a periodic component):
 * what set_rotations of another mesh takes, so an orbit converted to that
 * mesh (whirl_periodic_convert) keeps its turns.  X of rotations_of must be
 * in c's own layout (NTST NCOL + 1 nodes). */
WHIRL_API const double *whirl_colloc_rotations(const whirl_colloc *c);

/* The parameters of the orbit X: p with, at a fixed period (free_param),
 * that parameter's value from X's last entry; pfull may be p. */
WHIRL_API void whirl_colloc_params(const whirl_colloc *c, const double *X,
                                   const double *p, double *pfull);
/* The free parameter in the period's place, or -1 (T unknown or forced). */
WHIRL_API int whirl_colloc_free_param(const whirl_colloc *c);

/* The operator whose singularity is a period doubling, for the
 * period-doubling locus by whirl_fold (op in whirl_fold_options): the
 * collocation Jacobian on the node values (the period column and the
 * phase row left out) with the antiperiodic condition x(1) + x(0) = 0 in
 * place of x(1) − x(0) = 0.  Its null vectors are the solutions of the
 * variational equation with v(1) = −v(0): it is singular exactly when the
 * monodromy has the multiplier −1 (the trivial multiplier 1 of an
 * autonomous orbit does not make it singular).  ei, ej, ev: n entries each
 * (the model's dimension), filled and pointed to by op. */
WHIRL_API void whirl_colloc_pd_operator(const whirl_colloc *c, whirl_fold_operator *op,
                                        size_t *ei, size_t *ej, double *ev);

/* Current mesh: tau[NTST + 1]. */
WHIRL_API const double *whirl_colloc_mesh(const whirl_colloc *c);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/rotor/sfd_dynamics.h — time-domain analysis of the SFD rotor (F_E = 0):
 * the attractors that exist at a speed, with membership tests that let a
 * basin computation stop a trajectory as soon as it has settled, and the
 * initial states the paper uses for its basins (§5.3, Figs. 12–17).
 *
 * Frames.  y + iz = w e^{iΩτ} (sfd.h): a fixed-frame state (y, z, y', z') at
 * time τ maps to the rotating-frame state (u, v, u', v') with
 *   w = (y + iz) e^{−iΩτ},   w' = (y' + iz') e^{−iΩτ} − iΩ w.
 * Circular synchronous orbits are equilibria of the rotating frame and the
 * nonsynchronous (quasiperiodic) response is a limit cycle there.
 *
 * Attractors and their tests.
 *  - Stable circular orbit x* (eq. 15, stability from the rotating-frame
 *    eigenvalues): with A the rotating-frame Jacobian at x* and P the
 *    solution of the Lyapunov equation AᵀP + PA = −I, V(e) = eᵀPe is a
 *    Lyapunov function near x*.  ρ is the largest level for which
 *    dV/dt < 0 on 0 < V ≤ ρ, found on 4096 quasi-random directions × 400
 *    radii, then reduced by the factor safety² (default 0.5² = 0.25).  A
 *    state with V(x − x*) ≤ ρ stays in that set and converges to x*
 *    (Lyapunov; Khalil, Nonlinear Systems, §4.1, §8.2), so one section point
 *    inside is a capture (confirm = 1).  The certificate is sampled, not
 *    interval-verified: that is the one assumption.
 *  - Nonsynchronous (quasiperiodic) response: a reference limit cycle of the
 *    rotating frame is obtained by integrating from a list of starting states
 *    (zero first) until one neither reaches a circular orbit's set nor
 *    touches the housing in search_periods; it is then sampled densely (40
 *    periods, 256 samples per period, checked to be recurrent).  Distances
 *    are measured with every coordinate scaled by its range on the cycle; a
 *    state within qp_tol of the sampled cycle (a polyline) on qp_confirm
 *    consecutive section points counts as captured.  This test is
 *    empirical, not a certificate: it relies on the cycle being attracting
 *    within that distance.
 *  - Contact (ε ≥ 1) is reported by the integrator (WHIRL_BASIN_DOMAIN).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SFD_DYNAMICS_H
#define WHIRL_SFD_DYNAMICS_H

#include <stddef.h>
#include <whirl/basins.h>
#include <whirl/rotor/sfd.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Fixed-frame state x[4] at time t  <->  rotating-frame state xr[4]. */
WHIRL_API void whirl_sfd_to_rotating(double Omega, double t, const double *x,
                                     double *xr);
WHIRL_API void whirl_sfd_to_fixed(double Omega, double t, const double *xr,
                                  double *x);

/* All circular orbits at speed p[OMEGA] from eq. 15: radii eps[] ascending
 * (at most maxn), stable[] (1 if every rotating-frame eigenvalue has
 * Re < 0), max_re[] (largest real part of the eigenvalues; may be NULL).
 * Roots are bracketed on a grid of 4000 values of ε in (0, 1) and refined
 * by bisection and Newton to 1e-14. */
WHIRL_API int whirl_sfd_circular_orbits(const double *p, double *eps,
                                        int *stable, double *max_re,
                                        size_t maxn, size_t *n);

typedef enum whirl_sfd_attractor_kind {
  WHIRL_SFD_CIRCULAR = 0,
  WHIRL_SFD_QUASIPERIODIC = 1
} whirl_sfd_attractor_kind;

typedef struct whirl_sfd_attractor_info {
  whirl_sfd_attractor_kind kind;
  const char *name;  /* "small", "large", "circular", "quasiperiodic" */
  double eps;        /* orbit radius; for the cycle the largest ε */
  double eps_min;    /* smallest ε (= eps for circular) */
  double rate;       /* circular: largest Re μ (< 0) */
  double level;      /* circular: certified level ρ; cycle: tolerance */
} whirl_sfd_attractor_info;

typedef struct whirl_sfd_attractors_options {
  double rtol, atol;       /* integration, defaults 1e-12, 1e-15 */
  double safety;           /* factor on the certified radius, default 0.5 */
  int find_cycle;          /* look for the nonsynchronous response (1) */
  size_t search_periods;   /* per starting state, default 600 */
  double qp_tol;           /* default 0.01 (of each coordinate's range) */
  size_t qp_confirm;       /* default 10 */
  int method;              /* whirl_ode_method, default WHIRL_ODE_DOPRI5 */
} whirl_sfd_attractors_options;

WHIRL_API void whirl_sfd_attractors_options_default(
    whirl_sfd_attractors_options *o);

typedef struct whirl_sfd_attractors whirl_sfd_attractors;

/* Find the attractors at parameters p (F_E must be 0).  On error returns
 * < 0 with a message in errbuf. */
WHIRL_API int whirl_sfd_attractors_find(const double *p,
                                        const whirl_sfd_attractors_options *o,
                                        whirl_sfd_attractors **out,
                                        char *errbuf, size_t errlen);
WHIRL_API void whirl_sfd_attractors_free(whirl_sfd_attractors *a);
WHIRL_API size_t whirl_sfd_attractors_count(const whirl_sfd_attractors *a);
/* The attractors as whirl_basins_compute wants them (valid until free). */
WHIRL_API const whirl_attractor *whirl_sfd_attractors_list(
    const whirl_sfd_attractors *a);
WHIRL_API const whirl_sfd_attractor_info *whirl_sfd_attractors_info(
    const whirl_sfd_attractors *a, size_t i);
/* Rotating-frame samples of the reference cycle (NULL, *m = 0 if none). */
WHIRL_API const double *whirl_sfd_attractors_cycle(
    const whirl_sfd_attractors *a, size_t *m);

/* --- initial states for basins (fixed frame, at τ = 0) ----------------- */

/* Displacements evenly spread in the disc |(y, z)| <= r_max: the points of
 * a square lattice through the origin with spacing h = r_max √(π / n),
 * so about n points.  Writes at most cap points (y, z) to yz[2*cap] (NULL:
 * count only) and returns the count. */
WHIRL_API size_t whirl_sfd_disc_points(size_t n, double r_max, double *yz,
                                       size_t cap);

/* Velocity of the circular orbit through (y, z) at speed Ω, whirling
 * forward with the unbalance: (y', z') = Ω (−z, y). */
WHIRL_API void whirl_sfd_circular_velocity(double Omega, double y, double z,
                                           double *vy, double *vz);

/* Samples of a trajectory (paper Figs. 15a–17): integrate from x0 (NULL:
 * rest at the centre) for skip_periods, then take n states evenly spread in
 * time over span_periods; out[4n].  Returns WHIRL_EDOMAIN (message) if the
 * trajectory touches the housing. */
WHIRL_API int whirl_sfd_trajectory_samples(const double *p, const double *x0,
                                           double skip_periods,
                                           double span_periods, size_t n,
                                           double rtol, double atol,
                                           double *out, char *errbuf,
                                           size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/rotor/sfd.h — the rigid rotor on two short squeeze-film dampers
 * (π-film, paper eqs. 1–17; shared/DESIGN.md), dimensionless.
 *
 * Parameters p[WHIRL_SFD_NPAR] (same order in every SFD problem):
 *   p[0] Omega   dimensionless speed ω/ω_n            (> 0)
 *   p[1] lambda  SFD constant ηR/√(2km) (L/c)^3        (> 0)
 *   p[2] delta   unbalance e_G/c                        (>= 0)
 *   p[3] zeta    external damping ratio                 (>= 0)
 *   p[4] FE      static force (2F_PS − mg)/(m c ω_n²)
 *
 * Fixed frame, x = (y, z, y', z'), time τ:
 *   y'' + 2ζy' + y = δΩ² cos Ωτ + f_y,   z'' + 2ζz' + z = δΩ² sin Ωτ + f_z + F_E
 * Rotating frame (F_E = 0), y + iz = (u + iv) e^{iΩτ}, x = (u, v, u', v'):
 *   w'' + 2iΩw' − Ω²w + 2ζ(w' + iΩw) + w = δΩ² + f(w, w' + iΩw)
 * Circular synchronous orbits are rotating-frame equilibria; their
 * eigenvalues μ give the fixed-frame Floquet multipliers exp(2πμ/Ω).
 * A state with ε = |(y, z)| >= 1 is contact with the housing: callbacks
 * return WHIRL_SFD_CONTACT (> 0, recoverable) and never propagate it.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SFD_H
#define WHIRL_SFD_H

#include <stddef.h>
#include <whirl/problem.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
  WHIRL_SFD_OMEGA = 0,
  WHIRL_SFD_LAMBDA = 1,
  WHIRL_SFD_DELTA = 2,
  WHIRL_SFD_ZETA = 3,
  WHIRL_SFD_FE = 4,
  WHIRL_SFD_NPAR = 5
};

/* Status returned by SFD callbacks when ε >= 1 (journal touches housing). */
#define WHIRL_SFD_CONTACT 1

/* Table 1 of the paper (ζ = 0, F_E = 0, Ω = 1): p[WHIRL_SFD_NPAR]. */
WHIRL_API void whirl_sfd_default_params(double *p);

/* Physical ranges of the parameters.  The paper studies λ in 0.01..1.5,
 * δ in 0.05..0.95, Ω <= 20; the limits leave a wide margin around that and
 * exclude only values where the model is meaningless or the arithmetic
 * overflows (λ = 1e308 makes every force infinite).  |F_E| >= 1 is a static
 * deflection beyond the clearance: the journal rests on the housing. */
#define WHIRL_SFD_OMEGA_MAX 1000.0
#define WHIRL_SFD_LAMBDA_MAX 100.0
#define WHIRL_SFD_DELTA_MAX 10.0
#define WHIRL_SFD_ZETA_MAX 10.0

/* Check a parameter vector: finite, 0 <= Ω <= 1000, 0 < λ <= 100,
 * 0 <= δ <= 10, 0 <= ζ <= 10, |F_E| < 1.  On failure returns WHIRL_EINVAL
 * and writes "lambda must be in (0, 100] (got -1)"-style text to msg[len]. */
WHIRL_API int whirl_sfd_check_params(const double *p, char *msg, size_t len);

/* π-film force of both dampers (dimensionless, eq. 8 times 2/(m c ω_n²)) at
 * position (y, z) and velocity (vy, vz): f[2] = (f_y, f_z).  If J is not
 * NULL, J[2*4] (column-major) receives d f / d(y, z, vy, vz) and dl[2]
 * (if not NULL) d f / d lambda.  Exact at ε = 0 (f = −πλ v).  Returns
 * WHIRL_SFD_CONTACT for ε >= 1, WHIRL_EINVAL for non-finite input. */
WHIRL_API int whirl_sfd_force(double y, double z, double vy, double vz,
                              double lambda, double *f, double *J, double *dl);

/* The two models (static storage, data NULL; parameters come in p). */
WHIRL_API const whirl_problem *whirl_sfd_fixed(void);
WHIRL_API const whirl_problem *whirl_sfd_rotating(void);

/* --- Circular-orbit polynomial (eqs. 15–17): an independent solver. ----
 * For an orbit of radius ε the radial and tangential forces are linear in Ω,
 * F_r = a Ω, F_t = b Ω with a = −4λε²/(1−ε²)², b = −πλε/(1−ε²)^{3/2}, and
 * eq. 15 is the quartic  c4 Ω⁴ + c3 Ω³ + c2 Ω² + c1 Ω + c0 = 0:
 *   c4 = ε² − δ², c3 = 2εa, c2 = ε²(4ζ² − 2) + a² + b² − 4ζεb,
 *   c1 = −2εa, c0 = ε².                                                   */
WHIRL_API int whirl_sfd_circ_coeffs(double eps, double lambda, double delta,
                                    double zeta, double c[5]);

/* G(ε, Ω) of eq. 15 and its partial derivatives (any may be NULL). */
WHIRL_API int whirl_sfd_circ_G(double eps, double Omega, double lambda,
                               double delta, double zeta, double *G,
                               double *G_eps, double *G_Omega);

/* All real roots Ω > 0 of eq. 15 for this ε, ascending: Omega[4], *nroots.
 * Roots come from the companion-matrix eigenvalues (LAPACK) polished by
 * Newton on the quartic. */
WHIRL_API int whirl_sfd_circ_roots(double eps, double lambda, double delta,
                                   double zeta, double *Omega, int *nroots);

/* Phase β of eqs. 16–17 (radians, the angle by which the unbalance leads the
 * journal), for a point of eq. 15. */
WHIRL_API double whirl_sfd_circ_phase(double eps, double Omega, double lambda,
                                      double delta, double zeta);

/* Rotating-frame state x[4] = (u, v, 0, 0) of the circular orbit (ε, Ω):
 * u + iv = ε e^{−iβ}. */
WHIRL_API void whirl_sfd_circ_state(double eps, double Omega, double lambda,
                                    double delta, double zeta, double *x);

/* Fold of eq. 15 in Ω: solve G = ∂G/∂ε = 0 by Newton from (*eps, *Omega)
 * (in/out), to |ΔΩ|, |Δε| < 1e-14 relative.  Returns WHIRL_ENOCONV if it
 * does not converge in 50 iterations or leaves 0 < ε < 1. */
WHIRL_API int whirl_sfd_circ_fold(double *eps, double *Omega, double lambda,
                                  double delta, double zeta);

/* --- The complete synchronous response (all branches of circular orbits in
 * omega_min <= Ω <= omega_max), traced by continuation of the rotating-frame
 * equilibria and seeded from every real root of eq. 15 on an ε grid and on
 * the boundary Ω = omega_max, so isolated branches are found too. */
struct whirl_branch;
struct whirl_cont_stats;

typedef struct whirl_sfd_response_options {
  double omega_min, omega_max; /* defaults 0.01, 20 */
  double ds, ds_max;           /* continuation steps, defaults 0.02, 0.2;
                                  need 0 < ds <= ds_max */
  size_t neps;                 /* ε grid for seeding, default 400, >= 10 */
  int linsol;                  /* whirl_linsol_kind, default dense */
} whirl_sfd_response_options;

WHIRL_API void whirl_sfd_response_options_default(
    whirl_sfd_response_options *o);

typedef struct whirl_sfd_response {
  size_t nbranch;
  struct whirl_branch **branch; /* owned */
  size_t nseeds;                /* seeds from eq. 15 that were examined */
  size_t steps, newton_its, f_evals, jac_evals; /* totals */
} whirl_sfd_response;

/* p: parameter vector (Omega ignored).  On error returns < 0 and writes a
 * message to errbuf.  Free the result with whirl_sfd_response_free. */
WHIRL_API int whirl_sfd_response_compute(const double *p,
                                         const whirl_sfd_response_options *o,
                                         whirl_sfd_response *out, char *errbuf,
                                         size_t errlen);
WHIRL_API void whirl_sfd_response_free(whirl_sfd_response *r);

#ifdef __cplusplus
}
#endif
#endif

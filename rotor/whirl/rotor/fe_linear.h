/* whirl/rotor/fe_linear.h — linear analyses of a finite-element rotor
 * (whirl/rotor/fe.h) with its nonlinear elements left out: damped natural
 * frequencies, log decrements and whirl directions at a speed, the
 * Campbell diagram with the critical speeds, and the linear unbalance
 * response.  doc/rotor-file.md describes the rotor, doc/rotor-validation.md
 * the checks against published results.
 *
 * The eigenvalues s of  (M s² + (C + Ω G) s + K) x = 0  in first-order
 * form  A z = s B z,  A = [0 I; −K −(C+ΩG)],  B = [I 0; 0 M],  z = (x, s x):
 * a small rotor by dense QZ (LAPACK dggevx, balanced, on the inverted
 * pencil B z = λ A z, λ = 1/s, whose errors are relative to the largest |λ|,
 * i.e. the slowest modes are the accurate ones; s = 0 and the infinite s of
 * massless DOFs are dropped), a large one by ARPACK's implicitly restarted
 * Arnoldi on (A − σB)⁻¹B (shift-invert: the eigenvalues nearest the real
 * shift σ; one sparse LU of K + σ(C+ΩG) + σ²M per speed).  A mode is
 * s = −ζω ± iω_d: reported are ω_d > 0, the log decrement δ = −2π Re s/ω_d
 * and the whirl: forward when the orbit (y, z) of the translations turns
 * with the spin (Σ_nodes Im(Y conj Z) > 0 for x ∝ e^{st}), else backward.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_LINEAR_H
#define WHIRL_ROTOR_FE_LINEAR_H

#include <stddef.h>
#include <whirl/rotor/fe.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum whirl_fe_eig_method {
  WHIRL_FE_EIG_AUTO = 0, /* dense up to dense_max DOFs, else ARPACK */
  WHIRL_FE_EIG_DENSE,
  WHIRL_FE_EIG_ARPACK
} whirl_fe_eig_method;

typedef struct whirl_fe_modes_options {
  whirl_fe_eig_method method;
  int dense_max; /* AUTO: dense QZ up to this many DOFs (default 150) */
  double shift;  /* ARPACK: real shift σ, 1/s (default 0: the slowest modes,
                    with σ = −1e-4 (max|K|/max|M|)^½ just left of 0) */
  double tol;    /* ARPACK: relative tolerance of the Ritz values (0: machine) */
} whirl_fe_modes_options;

WHIRL_API void whirl_fe_modes_options_default(whirl_fe_modes_options *o);

typedef struct whirl_fe_mode {
  double omega;   /* damped natural frequency ω_d, rad/s, > 0 */
  double re;      /* real part of the eigenvalue, 1/s */
  double log_dec; /* logarithmic decrement −2π re/ω_d */
  int whirl;      /* +1 forward, −1 backward */
} whirl_fe_mode;

/* The nmodes modes of lowest ω_d > 0 at speed Omega (rad/s), ascending, in
 * modes[nmodes]; *nfound (≤ nmodes) how many there are.  At Omega = 0,
 * where an isotropic rotor's pairs are degenerate, the whirl is the one
 * each mode takes as the rotor starts turning: that at the speed 1e-4 ω_1.  WHIRL_OK, or an error
 * status with the reason in msg (o NULL: defaults). */
WHIRL_API int whirl_fe_modes(const whirl_fe_rotor *r, double Omega,
                             const whirl_fe_modes_options *o, size_t nmodes,
                             whirl_fe_mode *modes, size_t *nfound, char *msg,
                             size_t len);

/* The Campbell diagram: the nmodes lowest modes at each of the nspeed
 * speeds[] (rad/s) into cd[k * nmodes + j] (mode j at speed k; a speed
 * with fewer modes has omega = NaN in the rest). */
WHIRL_API int whirl_fe_campbell(const whirl_fe_rotor *r, const double *speeds,
                                size_t nspeed, const whirl_fe_modes_options *o,
                                size_t nmodes, whirl_fe_mode *cd, char *msg,
                                size_t len);

typedef struct whirl_fe_critical {
  int mode;     /* index of the mode in ascending frequency (0-based) */
  double speed; /* the critical speed, rad/s: ω_d(speed) = speed */
  int whirl;    /* +1 forward, −1 backward, there */
} whirl_fe_critical;

/* The critical speeds in the range of a Campbell diagram (speeds
 * ascending, cd from whirl_fe_campbell): each sign change of ω_j − Ω
 * between neighbouring speeds refined to |ΔΩ| ≤ 1e-10 Ω by the Illinois
 * variant of regula falsi on fresh eigenvalue solves.  Up to maxcrit in
 * crit[], by speed; *ncrit how many. */
WHIRL_API int whirl_fe_critical_speeds(const whirl_fe_rotor *r,
                                       const double *speeds, size_t nspeed,
                                       const whirl_fe_modes_options *o,
                                       size_t nmodes, const whirl_fe_mode *cd,
                                       whirl_fe_critical *crit, size_t maxcrit,
                                       size_t *ncrit, char *msg, size_t len);

/* The linear steady unbalance response at speed Omega > 0: q(t) =
 * Re(Q e^{iΩt}) with
 *   (K − Ω² M + iΩ (C + Ω G)) Q = Ω² (u_c − i u_s),
 * the forcing Ω²(u_c cos Ωt + u_s sin Ωt) of fe.h.  Q = q_re + i q_im,
 * ndof each.  Sparse LU (whirl/linsol.h) of the real 2ndof form. */
WHIRL_API int whirl_fe_unbalance_response(const whirl_fe_rotor *r, double Omega,
                                          double *q_re, double *q_im,
                                          char *msg, size_t len);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/rotor/fe_hbm.h — periodic response of a finite-element rotor
 * (whirl/rotor/fe.h) by harmonic balance, condensed onto the degrees of
 * freedom of its nonlinear elements, as a system F(X, p) = 0 for the
 * continuation core (whirl/cont.h, whirl/fold.h).
 *
 * The response is a truncated Fourier series of the response frequency
 * ω = Ω/ν (ν = 1 synchronous, ν > 1 a subharmonic of order 1/ν):
 *   q(t) = c + Σ_{k=1..H} a_k cos kωt + b_k sin kωt .
 * The linear part is exact per harmonic: D_k(Ω) = K − (kω)² M +
 * i kω (C + Ω G), the static load f0 in harmonic 0 and the unbalance
 * Ω² (u_c − i u_s) in harmonic ν.  The m nonlinear DOFs n (y, z of each
 * element's node and of its pedestal) are kept, the others l eliminated:
 *   Z_k = D_nn − D_nl D_ll⁻¹ D_ln,   g_k = F_n − D_nl D_ll⁻¹ F_l
 * (the Schur complement, by one complex sparse LU of D_ll per harmonic and
 * speed, UMFPACK), and the residual is the dynamic-stiffness form
 *   Z_k q_n,k − g_k − f_nl,k(q_n) = 0 ,   k = 0..H ,
 * f_nl,k the Fourier coefficients of the element forces by AFT (FFTW).
 * Why this form rather than the receptance q − H_k (F + f_nl) with
 * H_k = P D_k⁻¹ Pᵀ: the linear rotor of a damper-supported shaft has its
 * damping in the nonlinear elements, so D_k is (nearly) singular at the
 * critical speeds the response is followed through, and singular at k = 0
 * when the dampers carry the static load alone (no centring spring); H_k
 * is then huge or undefined, while Z_k needs only D_ll, the rotor with its
 * nonlinear DOFs held, to be regular, and stays bounded where the
 * response is resonant.  (Z_k has poles at the resonances of that held
 * rotor, typically far above the dampers' modes.)  The equations of the
 * uncondensed HBM on all DOFs, D_k q_k − F_k − Pᵀ f_nl,k = 0, are the
 * same with b = ndof (options.uncondensed: a check, and the benchmark).
 *
 * Unknowns X (b = m condensed, b = ndof uncondensed; L = 2H + 1 blocks of
 * b: X[j] = c_j, X[b(2k−1) + j] = a_kj, X[b 2k + j] = b_kj), divided by the
 * length scale; residuals divided by the force scale.  The Jacobian is
 * analytic and dense: the linear blocks and, by AFT of the element
 * Jacobians, ∂f_nl/∂q from the Fourier coefficients of ∂f/∂r, ∂f/∂v·(ilω),
 * ∂f/∂a·(ilω)² (the exact derivative of the discrete AFT).  dF/dΩ: the
 * linear part analytic (∂Z = Vᵀ ∂D W, V, W the left and right condensation
 * bases, no further factorisation), the forces by central differences of
 * the AFT alone; dF/d(unbalance) analytic, dF/d(clearance), dF/d(viscosity)
 * by central differences of the AFT.
 *
 * Stability (optional, the system's spectrum): Hill's method on the full
 * linearised system (all DOFs, the AFT Jacobians of the elements inserted
 * at their DOFs), λ² A2 + λ A1 + A0 = 0 in the real Fourier basis,
 * linearised to first order and solved densely (LAPACK dgeev); of the
 * 2 ndof L eigenvalues the 2 ndof with the smallest |Im λ| are the Floquet
 * exponents (Lazarus & Thomas, C. R. Mécanique 338 (2010) 510; Peletan et
 * al., Nonlinear Dyn. 2013), reported as multipliers exp(λ 2π/ω).  For
 * large models the sparse pencil by ARPACK's shift-invert Arnoldi gives the
 * exponents nearest the imaginary axis around 0 (the critical ones).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_HBM_H
#define WHIRL_ROTOR_FE_HBM_H

#include <stddef.h>
#include <whirl/cont.h>
#include <whirl/rotor/fe.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The parameters p of the system. */
enum {
  WHIRL_FE_P_OMEGA = 0,     /* shaft speed Ω, rad/s */
  WHIRL_FE_P_UNBALANCE = 1, /* multiplies u_c, u_s (1: the rotor's) */
  WHIRL_FE_P_CLEARANCE = 2, /* multiplies the radial clearance of every
                               film element (SFDs, journal bearings) */
  WHIRL_FE_P_VISCOSITY = 3, /* multiplies their viscosity */
  WHIRL_FE_NPAR = 4
};

typedef struct whirl_fe_hbm_options {
  size_t harmonics;     /* H (default 5) */
  size_t nsamples;      /* N time samples per period of ω, > 2H (0: the
                           smallest power of two ≥ 2·3H + 1, at least 32) */
  unsigned nu;          /* ν: response frequency Ω/ν (default 1) */
  int uncondensed;      /* 1: all DOFs are unknowns (no condensation) */
  double length_scale;  /* m: X = q / length_scale (0: the smallest film
                           clearance, else 1e-3) */
  double force_scale;   /* N: F = residual / force_scale (0: length_scale
                           × the largest diagonal entry of K) */
  int stability;        /* Hill's multipliers as the system's spectrum:
                           1 dense (all 2 ndof exponents; 2 ndof (2H+1)
                           eigenvalues per point), 2 sparse (ARPACK: every
                           exponent within 1.05 ω/2 of a small shift near
                           0, those in |Im λ| ≤ ω/2 returned), 0 none,
                           3 sparse on a Craig–Bampton reduction (the
                           nonlinear DOFs and the held rotor's modes up to
                           hill_cutoff (H + ½) ω: approximate, fast);
                           −1 (default): dense when 2 ndof (2H+1) ≤ 1200,
                           else 3 when built with ARPACK (2 where the
                           reduction cannot be built), else none */
  size_t hill_nev;      /* the most eigenvalues the sparse Hill method
                           computes at one orbit (default 48); where more
                           lie within 1.05 ω/2 its stability is unknown */
  double hill_cutoff;   /* stability 3: the held rotor's modes kept reach
                           hill_cutoff (H + ½) ω_max (default 3) */
  int interior_lu;      /* the LU of the held rotor in the condensation:
                           0 (default) banded in a reverse Cuthill–McKee
                           ordering while its kl + ku ≤ 64, else UMFPACK;
                           1 banded always, 2 UMFPACK always */
} whirl_fe_hbm_options;

WHIRL_API void whirl_fe_hbm_options_default(whirl_fe_hbm_options *o);

typedef struct whirl_fe_hbm whirl_fe_hbm;

/* r is borrowed and must outlive the object.  NULL on bad options, a rotor
 * without nonlinear elements, or no memory (message in errbuf).  Creates
 * FFTW plans: not to be called concurrently with other FFTW planning. */
WHIRL_API whirl_fe_hbm *whirl_fe_hbm_alloc(const whirl_fe_rotor *r,
                                           const whirl_fe_hbm_options *o,
                                           char *errbuf, size_t errlen);
WHIRL_API void whirl_fe_hbm_free(whirl_fe_hbm *h); /* accepts NULL */

/* The system: n = b (2H + 1) unknowns, WHIRL_FE_NPAR parameters. */
WHIRL_API const whirl_system *whirl_fe_hbm_system(const whirl_fe_hbm *h);
WHIRL_API size_t whirl_fe_hbm_size(const whirl_fe_hbm *h);
/* The nonlinear DOFs (their rotor indices), *m of them. */
WHIRL_API const int *whirl_fe_hbm_nl_dofs(const whirl_fe_hbm *h, int *m);
/* The last failure's message ("" if none). */
WHIRL_API const char *whirl_fe_hbm_errmsg(const whirl_fe_hbm *h);
/* Parameters at their defaults (Ω given, scales 1), p[WHIRL_FE_NPAR]. */
WHIRL_API void whirl_fe_hbm_params(double Omega, double *p);

/* The coefficients of all ndof DOFs, q[ndof (2H + 1)] in metres, same
 * layout, of the solution X at p: q_l,k = D_ll⁻¹ (F_l,k − D_ln q_n,k) per
 * harmonic (condensed), the unknowns themselves (uncondensed). */
WHIRL_API int whirl_fe_hbm_recover(whirl_fe_hbm *h, const double *X,
                                   const double *p, double *q);

/* max over the orbit of √(y² + z²) at a node, from q as recovered (the
 * largest of 16 (2H+1) samples refined by Newton on the derivative). */
WHIRL_API double whirl_fe_hbm_amplitude(const whirl_fe_hbm *h,
                                        const double *q, int node);

/* A start away from rest: X[size] the forward circular orbits y + iz =
 * eps c e^{i(ωt + phase)} of relative eccentricity eps (0 ≤ eps < 1) at
 * every film element (c its clearance), every other unknown 0 — for
 * branches the response from rest does not reach (an isola), seeded from a
 * rigid-rotor solution or a guess and corrected by Newton.  Synchronous
 * responses only (ν = 1); WHIRL_EINVAL otherwise. */
WHIRL_API int whirl_fe_hbm_seed_circular(const whirl_fe_hbm *h, double eps,
                                         double phase, double *X);

/* Hill's Floquet exponents of the solution X at p, by the method of
 * options.stability (dense when 0): dense, the 2 ndof kept eigenvalues;
 * sparse, those within 1.05 ω/2 of a small shift σ = 10⁻³ ω in the strip
 * |Im λ| ≤ ω/2 (WHIRL_EMAXITER when more than hill_nev lie there).  re[],
 * im[] (*m: capacity in, at least hill_nev for sparse; count out), sorted
 * by decreasing real part.  Stable when all re < 0. */
WHIRL_API int whirl_fe_hbm_hill(whirl_fe_hbm *h, const double *X,
                                const double *p, double *re, double *im,
                                size_t *m);

/* ------------------------------------------------- speed response */

typedef struct whirl_fe_hbm_response_options {
  whirl_fe_hbm_options hbm;
  double speed_min, speed_max; /* rad/s (0 0: the rotor's speed range) */
  double unbalance, clearance, viscosity; /* scales (default 1) */
  int node;                  /* amplitude at this node (default 0) */
  double ds, ds_max;         /* steps, rad/s of speed (0: range/200,
                                range/10); the arclength weighs Ω by
                                1/range and the unknowns by 1 */
  size_t nmx;                /* steps (default 2000) */
  /* A seeded branch: when seed_eps > 0 the branch starts at Ω =
   * seed_omega from whirl_fe_hbm_seed_circular(seed_eps, seed_phase)
   * corrected by Newton (the phase giving the smallest residual of 16 when
   * seed_phase is NaN) and is followed towards larger speeds
   * (direction +1, default) or smaller (−1); it ends at the speed range or
   * when it closes on itself (an isola inside the range). */
  double seed_omega, seed_eps, seed_phase;
  int direction;
  /* Or a start X[whirl_fe_hbm_size] at seed_omega (a solution found by
   * discovery), used instead of the circular seed when not NULL. */
  const double *seed_x;
  /* Optional, out: the continuation's counts added up over the branches
   * traced with these options, and the unknowns of the harmonic balance
   * (whirl_fe_hbm_size).  NULL: none. */
  struct whirl_fe_hbm_response_report *report;
} whirl_fe_hbm_response_options;

typedef struct whirl_fe_hbm_response_report {
  whirl_cont_stats cont; /* steps, Newton iterations, ... (summed) */
  size_t unknowns;
} whirl_fe_hbm_response_report;

WHIRL_API void
whirl_fe_hbm_response_options_default(whirl_fe_hbm_response_options *o);

typedef struct whirl_fe_hbm_response_point {
  size_t index;          /* point number along the branch */
  int type;              /* whirl_point_type (LP, BP, PD, TR, EP, ...) */
  int label;
  double Omega;          /* rad/s */
  double amplitude;      /* m, at options.node */
  int stable;            /* 1, 0, −1 unknown */
  const double *X;       /* the unknowns, n of them */
  size_t n;
  int branch;            /* whirl_fe_hbm_discover: 1 the branch from rest,
                            2, 3, ... those found; 0 otherwise */
  int half;              /* whirl_fe_hbm_discover: −1 the half traced
                            towards smaller speeds from where it was found,
                            +1 the other; 0 the branch from rest */
} whirl_fe_hbm_response_point;

/* Called at every point; a non-zero return ends the branch (and is
 * returned). */
typedef int (*whirl_fe_hbm_response_fn)(
    const whirl_fe_hbm_response_point *pt, void *ctx);

/* Continue the periodic response in speed from speed_min to speed_max
 * (start from X = 0 corrected by Newton), calling fn at each point.
 * Returns WHIRL_OK, the callback's value, or an error (message in
 * errbuf). */
WHIRL_API int whirl_fe_hbm_response(const whirl_fe_rotor *r,
                                    const whirl_fe_hbm_response_options *o,
                                    whirl_fe_hbm_response_fn fn, void *ctx,
                                    char *errbuf, size_t errlen);

/* ------------------------------------------------- discovery */

/* Branches the response from rest does not reach (isolas), found without
 * a start on them (doc/discovery.md §FE rotors): after the branch from
 * rest, at each speed of `speeds`, deflated Newton (whirl/deflate.h) on the
 * condensed system from `starts` starts — the linear response (Newton from
 * X = 0), scaled copies of the solutions known there, circular orbits of
 * random eccentricity in (0.05, 0.95) and phase at every film element, and
 * known orbits at a random phase and amplitude — deflated against every
 * crossing of that speed by every branch traced so far.  Each new solution
 * seeds a branch traced towards smaller, then larger speeds. */
typedef struct whirl_fe_discover_options {
  const double *speeds;  /* rad/s, inside the speed range */
  size_t nspeeds;
  size_t starts;         /* per speed (default 40) */
  unsigned long seed;    /* of the random starts (default 1) */
} whirl_fe_discover_options;

WHIRL_API void whirl_fe_discover_options_default(whirl_fe_discover_options *d);

typedef struct whirl_fe_discover_report {
  size_t branches;        /* traced, the one from rest included */
  size_t isolated;        /* found by discovery (not connected to it) */
  size_t starts;          /* starts tried */
  size_t iterations;      /* deflated Newton iterations */
  double search_seconds;  /* wall time of the search (not the tracing) */
} whirl_fe_discover_report;

/* The response (o as for whirl_fe_hbm_response, without a seed), then the
 * discovery; fn is called for every point of every branch, with its branch
 * and half.  WHIRL_OK (report filled, may be NULL), the callback's value,
 * or an error with the message in errbuf. */
WHIRL_API int whirl_fe_hbm_discover(const whirl_fe_rotor *r,
                                    const whirl_fe_hbm_response_options *o,
                                    const whirl_fe_discover_options *d,
                                    whirl_fe_hbm_response_fn fn, void *ctx,
                                    whirl_fe_discover_report *report,
                                    char *errbuf, size_t errlen);

/* ------------------------------------------------- fold loci */
/* (whirl_fe_hbm_fold_locus, whirl_fe_hbm_merge_curve) */

typedef struct whirl_fe_locus_options {
  whirl_fe_hbm_options hbm;  /* as for the response the fold came from
                                (stability is not used: default 0) */
  int param;                 /* the second parameter: WHIRL_FE_P_UNBALANCE
                                (default), _CLEARANCE or _VISCOSITY */
  double pmin, pmax;         /* its range (default 0, 10) */
  double ds, ds_max;         /* steps in the arclength of (x, Ω/omega_scale,
                                param) (0: 0.01, 0.05) */
  size_t nmx;                /* steps (default 500) */
  double omega_scale;        /* rad/s (0: the fold's speed) */
  double pmin2, pmax2;       /* merge curves: the range of the parameter
                                they are followed in (default 0, 10) */
} whirl_fe_locus_options;

WHIRL_API void whirl_fe_locus_options_default(whirl_fe_locus_options *o);

typedef struct whirl_fe_locus_point {
  size_t index;
  int type;        /* whirl_point_type: EP, LP (of the locus), CP, IS, MG */
  double Omega;    /* rad/s */
  double value;    /* the parameter followed */
  double value2;   /* merge curves: the free parameter (NaN on loci) */
  const double *X; /* the unknowns of the fold system: the orbit's, then Ω */
  size_t n;        /* the orbit's unknowns */
} whirl_fe_locus_point;

typedef int (*whirl_fe_locus_fn)(const whirl_fe_locus_point *pt, void *ctx);

/* Follow the fold through the response's fold (X, p) — a point of type LP
 * of whirl_fe_hbm_response, X its unknowns with the same hbm options — in
 * (Ω, param) towards larger (direction +1) or smaller param, within
 * [pmin, pmax] and the rotor's speed range, until it closes on itself.
 * Calls fn at every point (a non-zero return ends the locus).  WHIRL_OK, or
 * an error with its message in err. */
WHIRL_API int whirl_fe_hbm_fold_locus(const whirl_fe_rotor *r,
                                      const whirl_fe_locus_options *o,
                                      const double *X, const double *p,
                                      int direction, whirl_fe_locus_fn fn,
                                      void *ctx, char *err, size_t errlen);

/* The merge curve through a merge point MG of a fold locus (X: the
 * base's unknowns there, p with its speed and o->param): the points where
 * an isolated branch joins another (or is born, IS), with the speed and
 * o->param free, followed in the parameter `along` (another of unbalance,
 * clearance, viscosity) over [pmin2, pmax2] — the boundary of the region
 * of isolas in the plane (along, o->param), Fig. 18 of the paper for a
 * rotor of any shape.  value is `along`, value2 o->param. */
WHIRL_API int whirl_fe_hbm_merge_curve(const whirl_fe_rotor *r,
                                       const whirl_fe_locus_options *o,
                                       int along, const double *X,
                                       const double *p, int direction,
                                       whirl_fe_locus_fn fn, void *ctx,
                                       char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

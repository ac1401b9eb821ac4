/* whirl/rotor/sfd_periodic.h — periodic responses of the SFD rotor that are not
 * rotating-frame equilibria: (1) synchronous orbits in the fixed frame by
 * harmonic balance or collocation, needed when gravity is not fully
 * compensated (F_E != 0, orbits not circular) and, with F_E = 0, as a check
 * of the circular-orbit solver by independent discretisations; (2) the
 * nonsynchronous (quasiperiodic in the fixed frame) response as a periodic
 * orbit of the autonomous rotating-frame system (F_E = 0), continued in Ω.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SFD_PERIODIC_H
#define WHIRL_SFD_PERIODIC_H

#include <stddef.h>
#include <whirl/rotor/sfd.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum whirl_sfd_method {
  WHIRL_SFD_METHOD_CIRCULAR = 0, /* rotating-frame equilibria (F_E = 0) */
  WHIRL_SFD_METHOD_HBM = 1,      /* harmonic balance (AFT) */
  WHIRL_SFD_METHOD_COLLOC = 2    /* orthogonal collocation */
} whirl_sfd_method;

WHIRL_API const char *whirl_sfd_method_name(int method);

typedef struct whirl_sfd_periodic_options {
  int method;          /* HBM (default) or COLLOC */
  size_t harmonics;    /* HBM: N (default 8, the paper's) */
  size_t oversampling; /* HBM: K (default 10, the paper's) */
  size_t ntst, ncol;   /* collocation: NTST (40), NCOL (4) */
  double omega_min, omega_max; /* defaults 0.05, 20 */
  double ds, ds_max;   /* arclength steps, defaults 1e-2 (the paper's), 0.2; for
                          collocation in the orbit's integral norm (AUTO's) */
  size_t nmx;          /* steps per branch half, default 20000 */
  int linsol;          /* whirl_linsol_kind (dense default; collocation
                          always uses the sparse solver) */
  double uz[8];        /* speeds at which to report points (UZ) */
  size_t nuz;
  /* optional progress report after each point of a branch (the points of
   * the branch so far, its speed); NULL: none */
  void (*progress)(size_t points, double omega, void *data);
  void *progress_data;
} whirl_sfd_periodic_options;

WHIRL_API void whirl_sfd_periodic_options_default(
    whirl_sfd_periodic_options *o);

/* One point of a periodic branch. */
typedef struct whirl_sfd_orbit {
  int type, label, stable, n_unstable; /* as whirl_point */
  double Omega;
  double eps_max, eps_min;  /* largest and smallest |(y, z)| on the orbit */
  double phase;             /* synchronous: angle β by which the journal's
                               first harmonic lags the unbalance (eqs. 16-17);
                               nonsync: NAN */
  double a1, b1;            /* first harmonic of y: a1 cos θ + b1 sin θ */
  double max_mult;          /* largest Floquet multiplier modulus */
  double mult_re, mult_im;  /* that multiplier */
  double period;            /* period of the orbit (fixed frame for the
                               synchronous, rotating frame for nonsync) */
  double f2;                /* nonsync: second frequency of the fixed-frame
                               motion, |Ω − ω_r| / Ω; synchronous: NAN */
  double residual;          /* max |F| of the discretised equations */
} whirl_sfd_orbit;

typedef struct whirl_sfd_periodic_branch {
  int id;
  int isola;         /* synchronous: does not reach omega_min */
  int stop_reason;   /* whirl_stop_reason */
  size_t len;
  whirl_sfd_orbit *pts;
} whirl_sfd_periodic_branch;

typedef struct whirl_sfd_periodic {
  int method;
  size_t unknowns;   /* size of the discretised problem */
  size_t nbranch;
  whirl_sfd_periodic_branch *br;
  size_t steps, newton_its;
  double max_residual;
  char note[256];    /* how the branches were seeded (for the header) */
} whirl_sfd_periodic;

WHIRL_API void whirl_sfd_periodic_free(whirl_sfd_periodic *r);

/* Synchronous response in the fixed frame by HBM or collocation.  Seeds:
 * with F_E = 0 every branch of the circular-orbit response (so the isola
 * too); with F_E != 0 the main branch from the static deflection at
 * omega_min, and every isola of the F_E = 0 response carried to the given
 * F_E by continuation in F_E at fixed Ω (the same discretisation).  On error
 * returns < 0 with a message in errbuf. */
WHIRL_API int whirl_sfd_periodic_response(const double *p,
                                          const whirl_sfd_periodic_options *o,
                                          whirl_sfd_periodic *out,
                                          char *errbuf, size_t errlen);

/* The nonsynchronous response (F_E = 0): a periodic orbit of the rotating
 * frame, started from a long time integration at omega_start (the
 * attractor reached from the centre at rest) and continued in Ω in both
 * directions between omega_min and omega_max, through folds of cycles.  The
 * autonomous rotating-frame system makes the fixed-frame motion
 * quasiperiodic with frequencies Ω + k ω_r. */
WHIRL_API int whirl_sfd_nonsync(const double *p, double omega_start,
                                const whirl_sfd_periodic_options *o,
                                whirl_sfd_periodic *out, char *errbuf,
                                size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

/* rotor/fe_hbm_impl.h — internals of the harmonic balance of
 * finite-element rotors (rotor/fe_hbm*.c): the alternating frequency–time
 * evaluation of the nonlinear elements (fe_hbm_aft.c), the linear part per
 * harmonic, condensed onto the nonlinear DOFs or not (fe_hbm_lin.c), the
 * system (fe_hbm.c) and Hill's stability (fe_hbm_hill.c).
 *
 * Layout of a vector of Fourier coefficients over b DOFs ("harmonic
 * major"): L = 2H + 1 blocks of b, block 0 the mean c, block 2k − 1 the
 * cosine a_k, block 2k the sine b_k of harmonic k of the response
 * frequency ω = Ω/ν:  q(t) = c + Σ_k a_k cos kωt + b_k sin kωt.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_HBM_IMPL_H
#define WHIRL_ROTOR_FE_HBM_IMPL_H

#include <complex.h>
#include <fftw3.h>
#include <stddef.h>

#include <whirl/linsol.h>
#include <whirl/problem.h>
#include <whirl/rotor/fe.h>
#include <whirl/rotor/fe_hbm.h>
#include <whirl/system.h>

/* ------------------------------------------------------------------ AFT */

/* The nonlinear DOFs (y, z of each element's node and pedestal, each once,
 * in increasing DOF order) and the forces on them by AFT. */
typedef struct fe_aft {
  int H, N;           /* harmonics, time samples per period (N > 2H) */
  int m;              /* nonlinear DOFs */
  int *dof;           /* dof[m]: their indices in the rotor */
  int nnl;            /* elements */
  whirl_fe_nl *el;    /* own copies (clearance and viscosity scaled) */
  double *clear0, *visc0; /* the rotor's values */
  int (*epos)[4];     /* per element: positions in dof[] of node y, z,
                         pedestal y, z (−1: ground) */
  /* FFTW: displacement, velocity, acceleration coefficients → samples
   * (3m series), forces → coefficients (m), Jacobian samples → their
   * coefficients (12 nnl: Jr, Jv, Ja, 4 entries each) */
  fftw_plan p_q, p_f, p_j;
  double complex *cq, *cf, *cj; /* (N/2 + 1) per series */
  double *tq, *tf, *tj;         /* N per series */
} fe_aft;

int fe_aft_init(fe_aft *a, const whirl_fe_rotor *r, int H, int N, char *err,
                size_t errlen);
void fe_aft_free(fe_aft *a);

/* Set the scales of clearance and viscosity of the film elements. */
void fe_aft_set_scales(fe_aft *a, double clearance, double viscosity);

/* What fe_aft_eval computes besides the force coefficients. */
enum {
  FE_AFT_FORCE = 0,   /* the force coefficients only */
  FE_AFT_JAC = 1,     /* and J = ∂f/∂q (the HBM Jacobian of the forces) */
  FE_AFT_HILL = 2     /* and the three multiplication operators of
                         ∂f/∂r, ∂f/∂v, ∂f/∂a (Hill's method) */
};

/* Force coefficients f[m L] on the nonlinear DOFs at their displacement
 * coefficients q[m L] (SI, layout above), response frequency w, speed
 * Omega.  mode FE_AFT_JAC: J[(mL)²] column-major, J[i + mL j] = ∂f_i/∂q_j.
 * FE_AFT_HILL: J[3 (mL)²], the Galerkin operators of multiplication by
 * ∂f/∂r, ∂f/∂v, ∂f/∂a one after the other.  Returns 0, 1 (recoverable:
 * an element reported contact, WHIRL_EDOMAIN) or < 0. */
int fe_aft_eval(fe_aft *a, const double *q, double w, double Omega, double *f,
                double *J, int mode);

/* -------------------------------------------------------- linear part */

/* A complex banded LU of a sparse n×n matrix in a reverse Cuthill–McKee
 * ordering (fe_band.c): init from the CSC pattern, factor from values on
 * that pattern, solve B (n × nrhs, original order) in place with A or Aᵀ. */
typedef struct fe_band {
  int n, kl, ku, ldab;
  int kv;               /* U's upper bandwidth after the factorisation:
                           ku without row swaps, at most kl + ku */
  int *perm, *pinv;     /* perm[new] = old */
  size_t *pos;          /* band position of each pattern entry */
  int *ipiv;
  double *scale;        /* equilibration, new order */
  double complex *ab;   /* ldab × n, LAPACK's band storage with fill rows */
  double complex *work;
  size_t nwork;
} fe_band;

int fe_band_init(fe_band *b, int n, const int *Ap, const int *Ai);
void fe_band_free(fe_band *b);
int fe_band_factor(fe_band *b, const int *Ap, const double complex *x);
int fe_band_solve(fe_band *b, int transpose, int nrhs, double complex *B);

/* The interior block goes to the banded LU while kl + ku stays at most
 * this (beam rotors: 14–22); wider patterns go to UMFPACK. */
#define FE_BAND_MAX 64

/* A factorisation of the interior block D_ll (fe_hbm_lin.c): banded or
 * UMFPACK's numeric object, on the pattern of an fe_lin. */
typedef struct fe_ilu {
  fe_band band;
  void *numeric;
} fe_ilu;

/* Per harmonic k = 0..H, the complex b×b dynamic stiffness Z_k (condensed:
 * the Schur complement of D_k onto the nonlinear DOFs; else D_k itself),
 * its derivative in Ω, and the forces g per unit unbalance (harmonic ν) and
 * the static load (harmonic 0) reduced the same way, with derivatives. */
/* The speed-dependent results of an earlier update, kept for its speed
 * (fe_lin_update): the fold loci difference the Jacobian at Omega +- h
 * and come back to Omega. */
enum { FE_LIN_SLOTS = 2 };
typedef struct fe_lin_slot {
  double Omega;
  int valid;
  double complex *Z, *dZ, *gu, *dgu;
  double *g0;
} fe_lin_slot;

typedef struct fe_lin {
  const whirl_fe_rotor *r;
  int condensed, H, nu, b, ndof, ni;   /* ni: interior DOFs (condensed) */
  int m;
  const int *nldof;                    /* m nonlinear DOFs (of fe_aft) */
  int *pos;                            /* b-position of each nonlinear DOF */
  double Omega;                        /* cached speed */
  int valid;
  double complex *Z, *dZ;              /* (H+1) b² column-major */
  double complex *gu, *dgu;            /* b (harmonic ν) */
  double *g0;                          /* b (harmonic 0) */
  /* condensed only: union pattern of K, M, C, G; interior sub-pattern */
  int nnz, *Up, *Ui;
  double *Kx, *Mx, *Cx, *Gx;           /* the four on the union pattern */
  int *inv;                            /* DOF → interior index or −1 − nl */
  int *Lp, *Li, *Lmap;                 /* interior pattern, map into union */
  double *Lx, *Lz;                     /* interior values (UMFPACK) */
  double complex *Dv, *dDv;            /* D_k, ∂D_k/∂Ω on the union pattern */
  int nnlq, *nlq, *nlcol;              /* union entries in nonlinear rows,
                                          their columns */
  double complex *Lv;                  /* interior values (band) */
  double complex *rhs;                 /* ni × (2m + 1) right-hand sides */
  int interior_lu;                     /* whirl_fe_hbm_options' */
  int use_band, k0_done;               /* k = 0 does not depend on Ω */
  fe_ilu lu;
  void *symbolic;
  double control[20]; /* UMFPACK_CONTROL (20, checked in fe_hbm_lin.c):
                         no iterative refinement */
  double complex *Xk;                  /* (H+1) ni·m: D_ll⁻¹ D_ln */
  double complex *yk;                  /* (H+1) ni: D_ll⁻¹ F_l */
  double xk_Omega;                     /* the speed of Xk, yk (recover) */
  int xk_valid;
  fe_lin_slot slot[FE_LIN_SLOTS];      /* earlier speeds, latest first */
  double complex *w1, *w2, *w3;        /* work ndof·m */
  double *br, *bz, *xr, *xz;           /* work ni */
  char err[256];
} fe_lin;

int fe_lin_init(fe_lin *l, const whirl_fe_rotor *r, int condensed,
                int interior_lu, int H, int nu, const fe_aft *a);
void fe_lin_free(fe_lin *l);
/* Z, dZ, g at speed Omega (the current speed and FE_LIN_SLOTS earlier
 * ones cached: the same values as computed afresh); WHIRL_OK or an error,
 * message in err */
int fe_lin_update(fe_lin *l, double Omega);
/* Interior factorisations on l's pattern beyond l's own (fe_hbm_shift.c):
 * init (after fe_lin_init), factor from values Dv on the union pattern
 * (l->nnz), solve B (ni × nrhs) in place with D_ll or its transpose. */
int fe_ilu_init(const fe_lin *l, fe_ilu *f);
void fe_ilu_free(fe_ilu *f);
int fe_ilu_factor(fe_lin *l, fe_ilu *f, const double complex *Dv);
int fe_ilu_solve(fe_lin *l, fe_ilu *f, int transpose, int nrhs,
                 double complex *B);

/* All ndof coefficients q[ndof L] from the b-block vector x[b L] (SI),
 * unb the unbalance scale. */
int fe_lin_recover(fe_lin *l, double Omega, double unb, const double *x,
                   double *q);

/* The Hill matrix at a real shift σ condensed onto the nonlinear DOFs
 * (fe_hbm_shift.c): H + 1 interior factorisations at s_k = σ + i kω and
 * the dense real Schur complement S of order m (2H + 1). */
typedef struct fe_shift {
  int H;
  fe_ilu *lu;             /* H + 1 */
  double complex *Dn;     /* (H + 1) nnlq: D(s_k) on the nonlinear rows */
  double complex *X;      /* (H + 1) ni m: D_ll⁻¹ D_ln */
  double complex *T;      /* (H + 1) ni: interior solutions of a solve */
  double *S;              /* (m L)², its LU */
  int *ipiv;
  double complex *Dv;     /* nnz: D(s_k) on the union pattern */
  double *g;              /* m L */
  double complex *Z;      /* m² + 2m work */
} fe_shift;

int fe_shift_init(fe_shift *s, const fe_lin *l);
void fe_shift_free(fe_shift *s);
/* Factor P(σ) at speed Omega, response frequency w, with AFT's three
 * operators J3 (FE_AFT_HILL); message in l->err. */
int fe_shift_factor(fe_shift *s, fe_lin *l, double Omega, double w,
                    double sigma, const double *J3);
/* y[ndof L] := P(σ)⁻¹ y (real harmonic form over all DOFs). */
int fe_shift_solve(fe_shift *s, fe_lin *l, double *y);

/* Hill's stability on a Craig–Bampton reduction of the rotor
 * (fe_hbm_reduce.c): the reduced rotor, its own harmonic balance object
 * (for the sparse Hill method), and where the nonlinear DOFs lie in it. */
typedef struct fe_cb {
  whirl_fe_rotor *r;    /* the reduced rotor (owned) */
  struct whirl_fe_hbm *h; /* on r, stability 2 */
  int m, neta;          /* nonlinear DOFs, interior modes kept */
  int *pos;             /* m: reduced DOF of each of fe_aft's DOFs */
  double wcut, wtop;    /* the cutoff, the highest mode kept (rad/s) */
  double *q;            /* ndof(r) L: an orbit's coefficients on r */
} fe_cb;

/* Build cb for r with the modes of the held interior up to wcut (rad/s);
 * message in err. */
int fe_cb_build(const whirl_fe_rotor *r, const fe_aft *a, double wcut,
                fe_cb *cb, char *err, size_t len);
void fe_cb_free(fe_cb *cb);

/* ----------------------------------------------------------- the object */

struct whirl_fe_hbm {
  const whirl_fe_rotor *r;
  whirl_fe_hbm_options o;
  int H, L, N, b, n;
  fe_aft aft;
  fe_lin lin;
  double Ls, Fs;           /* length and force scales */
  int hill;                /* 0 none, 1 dense, 2 sparse (ARPACK), 3 sparse
                              on the Craig–Bampton reduction */
  fe_cb cb;                /* hill 3: built at the first orbit */
  int cb_unavailable;      /* hill 3: the reduction could not be built */
  whirl_system sys;
  double *q, *f, *fp, *fm, *Jnl; /* work: SI coefficients, forces, m L;
                                    (m L)² (3 (m L)² for Hill) */
  double *qfull;           /* ndof L, for the spectrum */
  double *xsi;             /* b L: the unknowns in metres */
  double *hill_start;      /* 2 ndof L: the sparse Hill method's next
                              Arnoldi start (fe_hbm_hill_sparse.c) */
  int hill_warm;           /* hill_start holds one */
  int hill_nev_cur;        /* the next orbit's first nev (0: not yet) */
  double hill_tol;         /* ARPACK's relative tolerance (0: 1e-12) */
  double *hill_ws;         /* ARPACK's work arrays (fe_hbm_hill_sparse.c) */
  size_t hill_ws_len;
  int *hill_sel;
  size_t hill_sel_len;
  char errmsg[512];
};

/* Hill's method on the full system (fe_hbm_hill.c). */
int fe_hbm_spectrum(const double *X, const double *p, const double *J,
                    double *re, double *im, size_t *m, void *data);
int fe_hill_exponents(whirl_fe_hbm *h, const double *qfull, const double *p,
                      double *re, double *im, size_t *m);
/* The same by ARPACK on the sparse Hill pencil (fe_hbm_hill_sparse.c): the
 * exponents in the strip |Im| ≤ ω/2 among the nev nearest a small shift. */
int fe_hill_sparse(whirl_fe_hbm *h, const double *qfull, const double *p,
                   size_t nev, double *re, double *im, size_t *m);
/* The same on the Craig–Bampton reduction (fe_hbm_reduce.c), from the
 * unknowns X themselves (the nonlinear DOFs' coefficients). */
int fe_hill_reduced(whirl_fe_hbm *h, const double *X, const double *p,
                    double *re, double *im, size_t *m);

#endif

/* whirl/cont.h — pseudo-arclength continuation of F(x, p) = 0 in one
 * parameter (Keller 1977; Doedel, Keller & Kernévez 1991), with a Newton
 * corrector, secant (default) or tangent predictor, adaptive step (AUTO's DS,
 * DSMIN, DSMAX, NMX), and detection and localisation of special points by
 * test functions: folds LP (parameter component of the tangent), branch
 * points BP (sign of det [F_x F_p; t^T]), Hopf points HB (real part of the
 * critical complex pair of the system's spectrum), for Floquet multipliers
 * period doublings PD and tori TR, user values UZ and the system's own test
 * functions.
 *
 * The loop belongs to the caller (GSL style):
 *     char err[256];
 *     whirl_cont *c = whirl_cont_alloc(&sys, &opt, err, sizeof err);
 *     whirl_cont_start(c, x0, p0, +1);
 *     while ((rc = whirl_cont_step(c)) == WHIRL_OK) {
 *       const whirl_point *pt = whirl_cont_point(c); ...
 *     }
 *     if (rc < 0) fprintf(stderr, "%s\n", whirl_cont_errmsg(c));
 * No global state: any number of continuations may run in one process.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_CONT_H
#define WHIRL_CONT_H

#include <stddef.h>
#include <whirl/linsol.h>
#include <whirl/status.h>
#include <whirl/system.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Point types, with AUTO's two-letter names (whirl_point_type_name). */
typedef enum whirl_point_type {
  WHIRL_PT_REGULAR = 0, /* "  " ordinary point */
  WHIRL_PT_EP = 1,      /* "EP" end point of a branch (start, bound, stop) */
  WHIRL_PT_LP = 2,      /* "LP" limit point (fold, saddle-node) */
  WHIRL_PT_BP = 3,      /* "BP" branch point */
  WHIRL_PT_HB = 4,      /* "HB" Hopf point (torus point TR for a rotating-frame
                           equilibrium representing a periodic orbit) */
  WHIRL_PT_UZ = 5,      /* "UZ" user-requested parameter value */
  WHIRL_PT_PD = 6,      /* "PD" period doubling of a cycle (multiplier -1) */
  WHIRL_PT_TR = 7,      /* "TR" torus (Neimark-Sacker) point of a cycle */
  /* codimension-two points, labelled on fold and Hopf curves through the
   * system's own test functions (whirl_system.test) */
  WHIRL_PT_CP = 8,      /* "CP" cusp: the fold's quadratic coefficient is 0 */
  WHIRL_PT_BT = 9,      /* "BT" Bogdanov-Takens: double zero eigenvalue */
  WHIRL_PT_ZH = 10,     /* "ZH" zero-Hopf (fold-Hopf) */
  WHIRL_PT_IS = 11,     /* "IS" isola centre: an isolated branch is born
                           (or shrinks to a point) as the second parameter
                           passes an extremum along the fold curve */
  WHIRL_PT_MG = 12,     /* "MG" merge: an isolated branch joins another
                           branch (two branches cross; extremum of the second
                           parameter along the fold curve) */
  WHIRL_PT_GH = 13,     /* "GH" generalised Hopf (Bautin): the first Lyapunov
                           coefficient is 0 on a Hopf curve */
  /* strong resonances on a Neimark-Sacker curve of a map: the multipliers
   * e^{+-i theta} at theta = 0 (1:1), pi (1:2), 2 pi/3 (1:3), pi/2 (1:4)
   * (Kuznetsov, Elements of Applied Bifurcation Theory, 3rd ed. 2004, §9.5) */
  WHIRL_PT_R1 = 14,     /* "R1" 1:1 resonance */
  WHIRL_PT_R2 = 15,     /* "R2" 1:2 resonance */
  WHIRL_PT_R3 = 16,     /* "R3" 1:3 resonance */
  WHIRL_PT_R4 = 17,     /* "R4" 1:4 resonance */
  WHIRL_PT_NTYPES = 18  /* the number of point types */
} whirl_point_type;

WHIRL_API const char *whirl_point_type_name(int type);

/* Why a branch ended (whirl_cont_stop_reason). */
typedef enum whirl_stop_reason {
  WHIRL_STOP_NONE = 0,
  WHIRL_STOP_PMIN,   /* continuation parameter (or the lead) reached p_min (RL0) */
  WHIRL_STOP_PMAX,   /* continuation parameter (or the lead) reached p_max (RL1) */
  WHIRL_STOP_NMX,    /* NMX steps taken */
  WHIRL_STOP_DOMAIN, /* the model reported a domain error (e.g. contact)
                        that persisted down to DSMIN */
  WHIRL_STOP_NOCONV, /* Newton failed down to DSMIN */
  WHIRL_STOP_LOOP,   /* the branch closed on itself (isola traced whole) */
  WHIRL_STOP_XMAX,   /* |x|_inf exceeded x_max */
  WHIRL_STOP_BP,     /* stop at the first branch point (stop_at_bp) */
  WHIRL_STOP_UZ      /* a user value marked as a stop (uz_stop) */
} whirl_stop_reason;

WHIRL_API const char *whirl_stop_reason_name(int reason);

typedef struct whirl_cont_options {
  size_t icp;          /* ICP: index of the free parameter */
  double ds;           /* DS: initial step (sign ignored, see start) */
  double ds_min;       /* DSMIN */
  double ds_max;       /* DSMAX */
  size_t nmx;          /* NMX: maximum number of steps */
  double p_min, p_max; /* RL0, RL1: bounds of the free parameter, or of
                          the lead unknown X[lead] when lead >= 0 (AUTO's
                          RL0, RL1 bound ICP(1), also on a locus whose
                          ICP(1) is an unknown) */
  double x_max;        /* A1-like bound on |x|_inf (0: none) */
  double p_weight;     /* weight of the parameter in the arclength norm */
  const double *x_weight; /* NULL (1 each), or n weights of the components
                          of x in the arclength norm: |(x, p)|² =
                          sum (x_weight[i] x[i])² + (p_weight p)², as AUTO's
                          THU and THL (0 takes a component out of the
                          step length, e.g. the period: THL = {11: 0});
                          copied by whirl_cont_alloc */
  double newton_tol;   /* EPSU: |dx|_inf <= tol*(1+|x|_inf), |F| <= tol */
  double newton_tol_par; /* EPSL: the continuation parameter's correction
                          |dp| <= tol_par*(1+|p|), each part to its own
                          scale, as AUTO; 0: p with x, to newton_tol and
                          the scale of both */
  size_t newton_par_tail; /* the last newton_par_tail unknowns of x are free
                          parameters (AUTO's PAR(ICP(2..NFPR)) of BVPs, the
                          period of orbits): with newton_tol_par > 0 each is
                          tested as the continuation parameter, to its own
                          scale, and left out of x's; 0: all of x is state */
  int newton_scale_before; /* 1: the state's scale |x|_inf taken before the
                          correction (AUTO's NEWTONBV), 0: after (NEWTONAE) */
  int newton_maxit;    /* ITNW */
  int newton_full;     /* AUTO's NWTN: > 0, a new Jacobian at the first
                          newton_full iterations of a correction only, the
                          last one kept after (chord); 0: at every one */
  int newton_fast;     /* iterations at or below which the step may grow */
  int newton_chord;    /* 0: Newton, a new Jacobian at every iteration;
                          1: chord (modified) Newton: keep the last
                          factorisation, that of the last analysed point or
                          of an earlier iterate, while the corrections
                          contract by chord_theta or better per iteration;
                          a new border row alone is refactored cheaply when
                          the system's structured solver can (reborder) */
  double chord_theta;  /* contraction above which chord Newton refactors */
  double max_angle;    /* max turn of the tangent per step, radians */
  long lead;           /* the lead parameter among the unknowns (AUTO's
                          ICP(1) of a locus whose first listed parameter
                          is an unknown of the system, a fold or Hopf
                          curve's): X[lead] (0 <= lead < n) moves in the
                          direction of sign(dir) at whirl_cont_start (the
                          continuation parameter where its rate is zero to
                          newton_tol), and the LP points are its turning
                          points, as AUTO's (ae.f90: STPRAE, FNLPAE);
                          -1 (default): the continuation parameter */
  int tangent_predictor; /* 0: secant predictor (default), 1: tangent */
  int arclength_sphere; /* 1: a step's corrector keeps the weighted distance
                          of the new point from the last one equal to the
                          step, |X - X0|_w = ds (AUTO-07p's equilibria and
                          maps, ae.f90 SOLVAE), in place of the hyperplane
                          <w dir, X - X0> = ds normal to the direction;
                          the start, branch switches and the localisation
                          of special points keep their hyperplanes */
  int point_dir;       /* what whirl_point.dir holds at a regular point:
                          WHIRL_DIR_TANGENT (0, default) the tangent t;
                          WHIRL_DIR_PREDICTOR the direction its step was
                          predicted along (AUTO's UDOTPS of orbits and
                          BVPs, stored before CONTBV takes the new secant);
                          WHIRL_DIR_SECANT the unit secant of its step
                          (AUTO's UDOT of equilibria, SOLVAE) */
  int tangent_from_newton; /* 0: the tangent and tests of a new point from
                            a fresh Jacobian there (default); 1: from the
                            corrector's last factorisation (at the iterate
                            before the last correction, as AUTO-07p), the
                            tangent refined once by a directional
                            derivative: a Jacobian and a factorisation
                            fewer a step, test functions off by at most
                            newton_tol; located points analysed afresh;
                            2: as 1 without the refinement (AUTO-07p's
                            own direction vector, FNLPBV: the tangent
                            off by O(newton_tol) too; two evaluations of
                            F and a solve fewer a step) */
  double natural_corrector; /* 0 (default): the corrector keeps to the
                            pseudo-arclength hyperplane; s in (0, 1]: where
                            the continuation parameter carries at least the
                            share s of the step direction's weighted length
                            (w_p² d_p² ≥ s |d|²_w), the corrector solves at
                            the predicted parameter instead (natural
                            parameter), the arclength hyperplane elsewhere
                            (near folds): for systems whose evaluation at a
                            new parameter value is costly (a condensation,
                            a factorisation per parameter), one value a
                            step instead of one per Newton iteration */
  int curved_predictor;  /* 1: start the corrector from the second-order
                            predictor X + σ t + σ²/2 κ, κ the change of the
                            unit tangent over the last step per arclength,
                            σ where it meets the constraint hyperplane (the
                            hyperplane itself as chosen above); 0: from
                            X + ds·direction (default) */
  int detect_lp;       /* ILP */
  int detect_bp;       /* ISP (branch points) */
  int detect_hb;       /* ISP (Hopf; needs the system's spectrum); for Floquet
                          multipliers this is the torus point TR */
  int detect_pd;       /* ISP (period doubling; Floquet multipliers only) */
  int stability;       /* 1: the system's spectrum at every point, for its
                          stability and the HB/TR/PD tests (default); 0:
                          none (AUTO's ISP = 0 or 1 on periodic orbits:
                          no Floquet multipliers), stable = -1 */
  int detect_sys;      /* the system's own test functions (codim-2 points
                          on fold and Hopf curves); on by default */
  unsigned sys_skip;   /* point types of the system's tests not reported,
                          a mask of 1u << type (0: none): AUTO's problem
                          classes in run files skip a fold curve's IS and
                          MG, which AUTO reports as the LP they also are */
  int auto_steps;      /* AUTO-07p's step sequence (run files set it):
                          every step yields one point; a step that passes
                          special points ends at the first of them, which
                          starts the next step along its own tangent with
                          the step length unchanged (the points past it
                          are found again from there; AUTO's LCSPBV), and
                          the length then follows AUTO's ADPTDS on the
                          Newton iterations (x2 after 1, x1.5 after 2,
                          x1.1 up to newton_maxit/2, x0.5 at newton_maxit),
                          bounded by ds_max; the first steps take ds as
                          given, even past ds_max (AUTO's RDS = DS: only
                          ADPTDS clips to DSMAX).
                          0 (default): the special points are inserted and
                          the step goes on from the point past them */
  int hide_first_step; /* AUTO-07p's algebraic problems (its CNRLAE): the
                          first step's point is not output nor counted
                          (unless the step passes a special point) and the
                          next step, at the same length, starts from it:
                          the branch's second point is two steps out */
  int start_as_given;  /* whirl_cont_start: the start point is point 1 as
                          given, without Newton, and the tangent is taken
                          there (AUTO-07p's start of an orbit or a
                          boundary-value problem from its data, IRS = 0:
                          CNRLBV lists the data, STDRBV's direction) */
  int stop_at_bp;      /* end the branch at the first BP */
  int detect_loop;     /* stop when the branch returns to its start */
  double loc_tol;      /* localisation tolerance in arclength */
  double loc_epss;     /* > 0 (with auto_steps): the branch goes on after
                          a special point from where AUTO-07p's own
                          localisation ends (LCSPAE, LCSPBV): a secant
                          step from the step's end, then Mueller's method
                          with bracketing, each trial a step from the last
                          one along their secant, until the next step is
                          below loc_epss (1 + sqrt|ds ds_max|) (AUTO's
                          EPSS), at most loc_itmx + 1 trials; the point
                          reported is still the zero to loc_tol.  Where
                          that iteration finds none (AUTO's first step,
                          which tests nothing, or loc_itmx reached),
                          whirl's own localisation alone.  Bounds and the
                          system's own tests: always whirl's.  0
                          (default): on from the zero to loc_tol */
  int loc_itmx;        /* AUTO's ITMX for loc_epss (default 8) */
  double loc_count_epss; /* > 0 (with auto_steps, AUTO's EPSS): the Newton
                          count that sets the step after a located branch
                          point is the trial's where AUTO's localisation would
                          stop, its next secant step below loc_count_epss
                          (1 + sqrt|ds ds_max|); whirl's converged trials
                          go on nearer the point, where beside a branch
                          point Newton needs more iterations (pen's BP 4:
                          4-5 against AUTO's 2, and the next step 0.44
                          where AUTO's is DSMAX 0.5).  0: the last
                          trial's */
  whirl_linsol_kind linsol; /* DENSE, or SPARSE when the system has a pattern */
  int structured;      /* 1: factor the bordered Newton matrix with the
                          system's own structured solver (whirl_system
                          bsolver) when it has one; 0: always the LU of
                          `linsol` (a check, or for comparison) */
  const double *uz;    /* optional user values to output as UZ (AUTO's UZR) */
  size_t nuz;
  /* What uz[k] is a value of: with uz_fun NULL, the continuation parameter;
   * otherwise the quantity uz_fun(k, x, p, uz_ctx) of the point (x, p), p
   * the full parameter vector with the current continuation parameter, e.g.
   * another parameter of a two-parameter system, the period or a state
   * maximum of a periodic orbit.  The UZ point is localised where the
   * quantity equals uz[k], like every other special point.  uz_stop[k] != 0
   * ends the branch there (AUTO's UZSTOP, stop reason WHIRL_STOP_UZ);
   * uz_stop may be NULL. */
  double (*uz_fun)(size_t k, const double *x, const double *p, void *uz_ctx);
  void *uz_ctx;
  const int *uz_stop;
  /* Optional, for a progress display: called by whirl_trace_branch after
   * each point with the points of the branch so far and the point's
   * continuation parameter.  NULL: none. */
  void (*progress)(size_t points, double p, void *progress_ctx);
  void *progress_ctx;
} whirl_cont_options;

/* Defaults: icp 0, ds 1e-2, ds_min 1e-8, ds_max 0.5, nmx 1000, p bounds
 * +-1e30, p_weight 1, x_weight NULL, newton_tol 1e-10, newton_maxit 12, newton_fast 3,
 * Newton (newton_chord 0, chord_theta 0.25 when set),
 * max_angle 0.2 rad, secant predictor, all detections on, loop detection on,
 * loc_tol 1e-12, dense solver, the system's structured solver if any. */
WHIRL_API void whirl_cont_options_default(whirl_cont_options *opt);

typedef struct whirl_cont_stats {
  size_t steps;       /* accepted continuation steps */
  size_t rejected;    /* steps rejected (no convergence, angle, domain) */
  size_t recorrected; /* remapped points corrected on their new
                         representation before a step could be made */
  size_t newton_its;  /* Newton iterations, all purposes */
  size_t f_evals;     /* F evaluations (including finite differences) */
  size_t jac_evals;   /* Jacobian evaluations */
  size_t factorizations;
  size_t eig_evals;   /* spectrum evaluations */
  size_t spectrum_failed; /* of which failed numerically (stability unknown) */
  size_t special;     /* special points localised */
  size_t f_fused;     /* of f_evals: made by a Jacobian's own evaluations
                         (the structured solver's factor_F) */
} whirl_cont_stats;

/* One point of a branch.  All arrays belong to the continuation object and
 * are valid until the next whirl_cont_step / whirl_cont_start / free. */
enum { WHIRL_DIR_TANGENT = 0, WHIRL_DIR_PREDICTOR = 1, WHIRL_DIR_SECANT = 2 };

typedef struct whirl_point {
  size_t index;        /* PT: 0 for the start point */
  int type;            /* whirl_point_type */
  int label;           /* LAB: > 0 for special points, 0 otherwise */
  size_t n, npar;
  const double *x;     /* x[n] */
  const double *p;     /* p[npar] */
  const double *t;     /* unit tangent t[n+1] = (dx, dp_icp), weighted norm */
  const double *dir;   /* unit direction of the branch as the options'
                          point_dir asks (AUTO's stored direction); t at
                          special points and by default */
  double s;            /* arclength from the start point */
  int n_unstable;      /* eigenvalues with Re > 0, -1 if no spectrum */
  int stable;          /* 1 stable, 0 unstable, -1 unknown */
  size_t nspec;
  const double *spec_re, *spec_im; /* spectrum, sorted by decreasing Re */
  double test[3];      /* LP, BP, HB test function values */
  int uz;              /* UZ points: the index k of the user value uz[k]
                          reached; -1 otherwise */
} whirl_point;

typedef struct whirl_cont whirl_cont;

/* sys and opt are copied (sys->data stays borrowed and must outlive c).
 * Returns NULL on out of memory or invalid options; a message is then
 * written to errbuf[errlen] if errbuf is not NULL. */
WHIRL_API whirl_cont *whirl_cont_alloc(const whirl_system *sys,
                                       const whirl_cont_options *opt,
                                       char *errbuf, size_t errlen);
WHIRL_API void whirl_cont_free(whirl_cont *c); /* accepts NULL */

/* Start a branch at (x0, p0): x0 is corrected by Newton with p fixed, then
 * the tangent is oriented so that the free parameter (or the unknown
 * options.lead) moves in the direction of sign(dir) (+1 or -1).  The corrected start point is available from
 * whirl_cont_point as type EP.  Returns WHIRL_OK or an error. */
WHIRL_API int whirl_cont_start(whirl_cont *c, const double *x0,
                               const double *p0, int dir);

/* Start along a given direction t0[n+1] (normalised internally) from an
 * exact solution (x0, p0): used for branch switching.  No correction is done
 * at the start point. */
WHIRL_API int whirl_cont_start_direction(whirl_cont *c, const double *x0,
                                         const double *p0, const double *t0);

/* Branch switching at a branch point bp (from whirl_cont_point of a branch
 * of the same system): computes the second branch direction from the null
 * space of [F_x F_p] at bp, orthogonal to bp->t, and starts along it with
 * the given sign: +1 the side where the parameter grows (AUTO's rule), -1
 * the other; the first point is corrected on the new branch. */
WHIRL_API int whirl_cont_start_switch(whirl_cont *c, const whirl_point *bp,
                                      int dir);

/* The direction whirl_cont_start_switch would start along, into t[n + 1]
 * (unit in the Euclidean norm), without starting: for a caller that
 * orients it by a rule of its own (AUTO's for boundary-value problems)
 * and starts with whirl_cont_start_direction. */
WHIRL_API int whirl_cont_switch_direction(whirl_cont *c, const whirl_point *bp,
                                          int dir, double *t);

/* Take one continuation step.  Returns WHIRL_OK when a new point is
 * available (special points are returned in order before the regular point
 * that follows them), WHIRL_DONE when the branch has ended (see
 * whirl_cont_stop_reason; the last point returned was its EP), or an error
 * < 0 (see whirl_cont_errmsg). */
WHIRL_API int whirl_cont_step(whirl_cont *c);

WHIRL_API const whirl_point *whirl_cont_point(const whirl_cont *c);
/* The point the next step would leave from, on the system's representation
 * as it is now: the last point given, or after a mesh adaptation its values
 * on the new mesh (whirl_cont_point keeps them as they were given, on the
 * old one).  For a branch that ended at DSMIN (WHIRL_STOP_NOCONV), whose
 * last steps may have adapted the mesh: AUTO's MX solution.  Its index is
 * the last point's, its type regular.  The struct is whirl_cont_point's
 * (overwritten), valid until the next call on c; NULL before a start. */
WHIRL_API const whirl_point *whirl_cont_current(whirl_cont *c);
WHIRL_API int whirl_cont_stop_reason(const whirl_cont *c);
WHIRL_API const whirl_cont_stats *whirl_cont_get_stats(const whirl_cont *c);
WHIRL_API void whirl_cont_reset_stats(whirl_cont *c);
/* Message for the last error or stop ("" if none); owned by c. */
WHIRL_API const char *whirl_cont_errmsg(const whirl_cont *c);

/* Newton's method for F(x, p) = 0 with p fixed, from x (in/out).  On return
 * *its holds the iterations used.  Uses the dense Jacobian; tol as
 * whirl_cont_options.newton_tol.  Useful for seeding and for tests. */
WHIRL_API int whirl_newton(const whirl_system *sys, double *x, const double *p,
                           double tol, int maxit, int *its);

#ifdef __cplusplus
}
#endif
#endif

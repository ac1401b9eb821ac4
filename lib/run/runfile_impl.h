/* lib/run/runfile_impl.h — private to lib/run: the parsed settings of a
 * run file as one struct, for the run (run.c, run_model.c, run_basins.c)
 * and the parser's fuzz target.  The public way in is the accessors of
 * whirl/runfile.h.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_RUNFILE_IMPL_H
#define WHIRL_RUNFILE_IMPL_H

#include <whirl/runfile.h>

typedef struct whirl_run_settings {
  char model[WHIRL_RUN_MAXPATH];
  char out[WHIRL_RUN_MAXPATH];  /* "" : default <stem>.out */
  char s[WHIRL_RUN_MAXPATH];    /* restart directory ("" none) */
  char dat[WHIRL_RUN_MAXPATH];  /* IPS 2: the start orbit's data file ("" none) */
  char hb_period[WHIRL_RUN_MAXNAME]; /* IPS 2 from an equilibrium label: take
                                   it as a Hopf point whose orbits have the
                                   period this parameter holds at the label,
                                   from the pair of eigenvalues nearest
                                   2 pi i / period (AUTO's TY = 'HBk'); "" none */
  int ndim;                     /* 0: not given */
  int ips;                      /* WHIRL_IPS_* (default 1) */
  int method;                   /* WHIRL_METHOD_* (default colloc) */
  whirl_run_ref icp[WHIRL_RUN_MAXICP];
  size_t nicp;
  whirl_run_value par[WHIRL_RUN_MAXITEMS];
  size_t npar;
  whirl_run_value u[WHIRL_RUN_MAXITEMS];
  size_t nu;
  int ilp, isp, isw;            /* defaults 1, 2, 1 */
  int irs;                      /* label, or the count with irs_type */
  char irs_type[3];             /* "" or a type name (IRS = HB2) */
  int ntst, ncol, iad;          /* defaults 20, 4, 3 */
  int nhb, oversampling;        /* defaults 8, 4 */
  double ds, dsmin, dsmax;      /* defaults 0.01, 1e-5, 0.1; |DS| is
                                   clipped to [DSMIN, DSMAX] as in AUTO */
  int nmx, npr;                 /* defaults 200, 0 (no regular labels) */
  int iplt;                     /* AUTO's IPLT: the L2-NORM column (0) */
  int nbc, nint;                /* IPS 4: boundary, integral conditions (0) */
  double rl0, rl1, a0, a1;      /* defaults -1e30, 1e30, 0, 1e30 */
  double epsl, epsu, epss;      /* defaults 1e-7, 1e-7, 1e-5 */
  int itnw, jac;                /* defaults 8, 1 */
  int nwtn;                     /* AUTO's NWTN: iterations with a new
                                   Jacobian, then chord (0, default: all) */
  whirl_run_value uzr[WHIRL_RUN_MAXITEMS];
  size_t nuzr;
  whirl_run_value uzstop[WHIRL_RUN_MAXITEMS];
  size_t nuzstop;
  whirl_run_value thl[WHIRL_RUN_MAXITEMS]; /* THL: {parameter or PERIOD: weight} */
  size_t nthl;
  whirl_run_value thu[WHIRL_RUN_MAXITEMS]; /* THU: {state component: weight} */
  size_t nthu;
  whirl_run_value stop[WHIRL_RUN_MAXITEMS]; /* STOP: point type (ref.name)
                                   and count n: end at the n-th of the type */
  size_t nstop;
  char plot[WHIRL_RUN_MAXNAME]; /* y axis of the picture: "" L2-NORM */
  whirl_run_range axes[2];      /* basins: two state components and ranges */
  size_t naxes;
  int grid[2];                  /* basins: points per axis (default 41) */
  int basin_periods;            /* basins: max forcing periods (500) */
  int attractors[WHIRL_RUN_MAXITEMS]; /* basins: labels in S */
  size_t nattractors;
  double basin_tol;             /* basins: capture radius (1e-3) */
  int basin_seeds;              /* basins: atlas seed stride (0: none) */
  int basin_method;             /* basins: whirl_ode_method (DOP853) */
  int threads;                  /* THREADS: the collocation's threads (0:
                                   OpenMP's default, OMP_NUM_THREADS) */
  int mesh_jumps;               /* MESH_RULE = jumps: orbits' meshes by
                                   AUTO's EQDF (0: derivative, whirl's) */
  int eq_sphere;                /* EQ_STEP = sphere: algebraic branches
                                   predict along the secant onto the sphere
                                   of radius DS about the last point, as
                                   AUTO's SOLVAE (0: tangent, whirl's
                                   hyperplane) */
  int auto_differences;         /* DIFFERENCES = auto: BVPs' Jacobian by
                                   AUTO's FUNI and ICNI with JAC = 0
                                   (forward in the free parameters, none in
                                   ICND's UDOT; 0: central, whirl's) */
  int udot_direction;           /* UDOT = direction: a BVP's integral
                                   conditions get the branch's direction as
                                   udot, AUTO's UDOT (0: u'(t)) */
  int mx_label;                 /* MX = label: a branch whose Newton fails
                                   at DSMIN ends in an MX label at its last
                                   point and the run goes on, AUTO's (0:
                                   the run fails, whirl's) */
  int tangent_iterate;          /* TANGENT = iterate: a new point's tangent
                                   is the corrector's last factorisation's
                                   solve as it is, AUTO's direction vector
                                   (0: refined once, whirl's) */
  int locate_auto;              /* LOCATE = auto: special points located by
                                   AUTO's secant and Mueller iteration until
                                   its step is below EPSS (LCSPAE, LCSPBV;
                                   0: to convergence, whirl's) */
  int itmx;                     /* ITMX: that iteration's steps (8) */
  int phase_nodes;              /* PHASE = nodes: orbits' phase condition
                                   as AUTO's, at the nodes with the model's
                                   f (0: gauss, whirl's) */
  int orbit_max_nodes;          /* ORBIT_MAX = nodes: an orbit's MAX U(i) is
                                   AUTO's, the largest node value (0: the
                                   maximum of the collocation polynomial) */
  double discover[WHIRL_RUN_MAXITEMS]; /* discovery: sample values of ICP(1) */
  size_t ndiscover;             /* 0: no discovery */
  whirl_run_range box[WHIRL_RUN_MAXITEMS]; /* discovery: box of random starts */
  size_t nbox;
  int discover_starts;          /* starts per sample value (40) */
  int discover_seed;            /* seed of the random starts (1) */
  double discover_settle;       /* time integration of a start: forcing
                                   periods, or time units (100) */
  whirl_run_value study[WHIRL_RUN_MAXITEMS]; /* parameter study: {name:
                                   [values]}, a grid (first name slowest) */
  size_t nstudy;
  char points[WHIRL_RUN_MAXPATH]; /* parameter study: a TSV of points ("" none) */
} whirl_run_settings;

const whirl_run_settings *whirl_runfile_settings(const whirl_runfile *rf);

#endif

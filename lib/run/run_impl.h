/* lib/run/run_impl.h — a run of a run file (whirl/run.h): its state, shared
 * by the files of the run: run.c builds and continues the branches (and is
 * the API), run_model.c loads models and resolves names, run_table.c
 * writes the branch table and keeps the labelled points, run_basins.c
 * computes basins; labelled solutions are whirl/solution.h's.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_RUN_IMPL_H
#define WHIRL_RUN_IMPL_H

#include <stdio.h>

#include <whirl/basins.h>
#include <whirl/branch.h>
#include <whirl/bvp.h>
#include <whirl/colloc.h>
#include <whirl/cont.h>
#include <whirl/equilibrium.h>
#include <whirl/fold.h>
#include <whirl/hbm.h>
#include <whirl/hopf.h>
#include <whirl/bploc.h>
#include <whirl/trloc.h>
#include <whirl/model.h>
#include <whirl/periodic.h>
#include "runfile_impl.h"
#include <whirl/solution.h>
#include <whirl/run.h>


/* What PLOT (the y axis of the picture) names. */
enum { RUN_PLOT_DEFAULT, RUN_PLOT_PAR, RUN_PLOT_PERIOD, RUN_PLOT_L2,
       RUN_PLOT_STATE };

typedef struct run_basins_job run_basins_job;

struct whirl_run {
  whirl_runfile *rf;
  const whirl_run_settings *s;
  const whirl_model *model;
  void *dl;               /* dlopen handle of a plug-in, or NULL */
  whirl_problem prob;     /* the model's problem (JAC = 0: no Jacobians) */
  size_t n, npar;
  char **pnames, **xnames; /* resolved names (model's or PAR(k)/U(k)) */
  double *par, *u;         /* start parameters and state */
  int icp[WHIRL_RUN_MAXICP]; /* resolved, 0-based; -1 for the period (PAR 11) */
  size_t nicp;
  int period_free;         /* IPS 2: PERIOD (AUTO's 11) listed in ICP */
  char out[4096], rundir[4096];
  char spath[4096];        /* S, resolved (run_path) */
  FILE *log, *table, *sols; /* run.log, branches.tsv, solutions in od */
  int label, branch;
  int stop_seen[WHIRL_RUN_MAXITEMS]; /* points of STOP's item i's type so far */
  int failed;              /* a branch ended in failure (DSMIN reached without
                              convergence, a persisting model domain error):
                              the output is kept, the exit status is 1 */
  int plot_kind, plot_index; /* PLOT resolved: RUN_PLOT_*, parameter or
                               state index */
  int plot_x, plot_y;      /* 1-based columns of the picture's axes */
  char plot_x_name[80], plot_y_name[80];
  int seen_stab[3];         /* rows with STAB -1, 0, 1 */
  int seen_special;
  int *branch_ids;          /* the BR of branches.tsv's rows, each once */
  int *branch_stab;         /* for each: bit k set when it has STAB k - 1 */
  size_t nbranch_ids, capbranch_ids;
  size_t ncols;
  /* the library object (whirl/run.h) */
  whirl_run_io io;
  const whirl_model_registry *registry;
  char file[4096], out_where[4200];
  char **overrides;
  size_t noverrides;
  whirl_run_special *special; /* the labelled points, in order */
  size_t nspecial, capspecial;
  whirl_run_plot plot;
  char errmsg[4600];
  /* branches found (discovery counts the curves, else the branches run) */
  size_t curves, isolated, closed;
  /* parameter study (run_study.c): the grid's axes */
  int in_study;            /* a point of a study: STUDY is not run */
  run_basins_job *bjob;    /* basins: the attractors and the grid */
  size_t study_naxes, study_npoints;
  int study_par[WHIRL_RUN_MAXITEMS];
  size_t study_first[WHIRL_RUN_MAXITEMS], study_nval[WHIRL_RUN_MAXITEMS];
  double *points;          /* POINTS: study_npoints rows of study_naxes values */
};
typedef struct whirl_run run_ctx;

/* "FILE:LINE: message" through io.message (errors about the run file). */
void run_fail(run_ctx *R, whirl_run_key k, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* A message (the first is kept as errmsg), a summary line. */
void run_say(run_ctx *R, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void run_summary(run_ctx *R, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A file of the output through io.open / io.close (0, or -1 said). */
FILE *run_open(run_ctx *R, const char *name);
int run_close(run_ctx *R, FILE *f, const char *name);
double run_now(void); /* monotonic seconds */

/* run_model.c */
/* model, S or OUT's path: relative to the run file's directory, or as it is
 * (absolute, or a command-line override's); 0, or -1 too long (run.c) */
int run_path(const run_ctx *R, whirl_run_key k, const char *value, char *buf, size_t len);
int run_load_model(run_ctx *R);  /* 0 or -1 (message printed) */
int run_resolve(run_ctx *R);     /* names -> indices, PAR, U; 0 or -1 */
int run_par_index(run_ctx *R, const whirl_run_ref *r); /* -1 unknown */
int run_state_index(run_ctx *R, const whirl_run_ref *r);
void run_unload_model(run_ctx *R);

/* The labelled solution of label (or the count-th of type ty if ty[0]) in
 * DIR/solutions, for the model of R (whirl_solution_find). */
int run_solution_find(const run_ctx *R, const char *dir, int label,
                      const char *ty, whirl_solution *out, char *msg, size_t len);

/* run_table.c */
int run_table_header(run_ctx *R, whirl_solution_kind kind, int icp, int q);
/* DAT: m samples xs[m * n] of the data file's orbit, its period *T and
 * (jump not NULL) u_last - u_first, jump[n] (run_dat.c).  0, or -1 (said). */
int run_dat_samples(run_ctx *R, size_t m, double *xs, double *T, double *jump);
/* The same start as AUTO makes it (MESH_RULE = jumps): colloc's mesh from
 * the rows by AUTO's ADAPT2 and X's nodes the rows' interpolant there (the
 * period in *T, not in X).  0, or -1 said. */
int run_dat_adapt(run_ctx *R, whirl_colloc *colloc, double *X, double *T, double *jump);
/* IPS = 4 from the data file DAT, as AUTO's STPNUB: the rows' time on
 * [0, 1], PAR(11) their span (NPAR > 10), the model's stpnt called once
 * (it may set parameters), bvp's mesh by ADAPT2 of the rows as linear
 * pieces and X's node values their interpolant there.  0, or -1 (said). */
int run_dat_bvp(run_ctx *R, whirl_bvp *bvp, double *X);
/* L2-NORM, PERIOD (0 for equilibria) and the state (its MAX over the orbit
 * for periodic orbits, mx[n]) of the solution xb of a problem of this kind */
int run_point_measures(const run_ctx *R, whirl_solution_kind kind, const void *obj,
                       const double *xb, const double *p, double *l2,
                       double *period, double *mx);
/* The periodic orbit of a branch of this kind (WHIRL_SOL_COLLOC, WHIRL_SOL_HBM) as
 * the library's one interface (whirl/periodic.h). */
whirl_periodic run_periodic(whirl_solution_kind kind, const void *obj);
int run_table_row(run_ctx *R, whirl_solution_kind kind, const void *obj, int br, size_t pt,
                  const char *ty, int lab, const double *xb, const double *p,
                  int stable, double *l2out, double *period, double *state);
/* Keep a labelled point (its row of the branch table and its numbers). */
int run_keep_special(run_ctx *R, int br, size_t pt, const char *ty, int lab,
                     const double *p, double period, double l2, const double *state,
                     const char *row);

/* ---- branches (run.c) ---------------------------------------------------- */

/* The points of a traced branch, kept for discovery (run_discover.c). */
typedef struct run_trace {
  size_t n;             /* unknowns of a point */
  size_t npts, cap;
  double *x;            /* npts × n */
  double *q;            /* npts: the continuation parameter */
  int *type;            /* npts: whirl_point_type */
  int br;               /* the BR of its first point */
  int closed;           /* the branch closed on itself */
  /* optional: store the point x at parameters p as out[n] (another
   * discretisation), 0 or -1 */
  int (*convert)(const double *x, const double *p, double *out, void *ctx);
  void *convert_ctx;
} run_trace;
/* Keep the point (x, p): p[icp] is the continuation parameter. */
int run_trace_add(run_trace *t, const double *x, const double *p, int icp, int type, int br);
void run_trace_free(run_trace *t);

typedef struct branch_spec {
  whirl_solution_kind kind;           /* base kind */
  whirl_colloc *colloc;    /* base objects (borrowed) */
  whirl_hbm *hbm;
  whirl_bvp *bvp;
  whirl_fold *fold;        /* locus layers (borrowed), or NULL */
  whirl_hopf *hopf;
  whirl_bploc *bploc;
  whirl_trloc *trloc;
  const whirl_system *sys; /* the system continued */
  size_t nb;               /* unknowns of the base system */
  size_t nnodes;           /* colloc, bvp: the mesh's nodes (node values first) */
  int icp;                 /* core's continuation parameter */
  int q;                   /* loci: the point's own parameter, else -1 */
  double ds_scale;         /* arclength scale of DS (loci of orbits: the
                              square root of their node count) */
  /* start: Newton from (x0, p0); or along dir from exact (x0, p0); or a
   * BP switch from `bp` */
  const double *x0, *p0, *dir;
  /* the label's tangent on the run's unknowns (nb + 1: resampled when the
   * run has another mesh), where one fits the run (the same free
   * parameters), else NULL: what ISW = -1 switches from at a BP */
  const double *tan0;
  const whirl_point *bp;
  int dir_sign;            /* +1 / -1: direction of the parameter at the
                              start; 0: the sign of DS */
  int starting_data;       /* AUTO's first run of a locus of orbits or of
                              a BVP from its LP, PD or BP (ISW = -2 inside
                              AUTO): the start point alone, an EP that the
                              next run restarts from */
  int as_given;            /* AUTO's start of an orbit from data rows:
                              the rows on their mesh are point 1 as they
                              are (whirl_cont_options.start_as_given) */
  long lead;               /* whirl_cont_options.lead: the unknown that
                              moves with DS at the start and whose turning
                              points are LPs (-1: the continued parameter) */
  run_trace *trace;        /* record the points here (or NULL) */
  const whirl_model *model; /* its derived parameters (pvls), or NULL */
  int iterate;             /* maps: fixed points of f^iterate (1: of f) */
} branch_spec;

/* run_bvp.c: the boundary-value problem of the run (IPS = 4) from the
 * model's start or the label so (NULL: none): *bvp, the start *X and a
 * direction *D (malloc'd, the caller frees them), and b's system.  0, -1
 * (failed, said), -2 (bad input, said). */
/* run.c: AUTO's PVLS on a collocation solution Z of sys (orbit or
 * boundary-value problem) with nnodes node values first: the weights of
 * its quadrature from the system's norm weights, par updated.  1 when
 * the model has pvls_solution and it ran, else 0. */
int run_pvls_solution(const whirl_model *m, const whirl_system *sys, const double *Z,
                      size_t nnodes, double *par);

int run_bvp_start(run_ctx *R, const whirl_solution *so, whirl_bvp **bvp, double **X,
                  double **D, branch_spec *b);

/* run_bvp.c: AUTO's orientation of a start direction t[nb + 1] of a
 * boundary-value problem (bvp.f90, STDRBV): the first free parameter in
 * ICP order whose rate is not negligible (> EPSL (1 + |p|)) grows, else
 * the first component of u(1) (> EPSU (1 + |u|)); times the sign of DS. */
void run_bvp_orient(const run_ctx *R, const branch_spec *b, const double *X,
                    const double *p, double *t);

/* Continue branch b: its rows, labels, log and summary.  0, -1, -2. */
int run_branch(run_ctx *R, branch_spec *b);

/* run_discover.c: the start branch b0, then the branches not connected to
 * it (DISCOVER, doc/discovery.md).  0, -1 (failed, said), -2 (bad input). */
int run_discover(run_ctx *R, const branch_spec *b0);

/* run_study.c: the grid of STUDY (at load), the serial study (execute) */
int run_study_resolve(run_ctx *R);
/* run_points.c: the points of POINTS = FILE into R->points: 0, or -1 (said). */
int run_points_load(run_ctx *R, const char *path);
int run_study(run_ctx *R);

/* run_basins.c: the whole grid (execute), or its points by blocks (the
 * rows of whirl/run.h): setup once, then classify, rows, summary */
int run_basins(run_ctx *R);
int run_basins_setup(run_ctx *R);
void run_basins_job_free(run_basins_job *J);
size_t run_basins_points(const run_ctx *R);
size_t run_basins_line(const run_ctx *R);
/* BASIN_SEEDS: the atlas begun (prepare), its rounds, a round's blocks, a
 * block computed, a round entered: 0, or -1 (said). */
int run_basins_atlas_begin(run_ctx *R);
size_t run_basins_rounds(const run_ctx *R);
size_t run_basins_round_blocks(const run_ctx *R, size_t s);
int run_basins_round_compute(run_ctx *R, size_t s, size_t b, void **part, size_t *len);
int run_basins_round_enter(run_ctx *R, size_t s, const void *const *parts, const size_t *lens,
                           size_t n);
int run_basins_classify(run_ctx *R, size_t first, size_t count, int *which,
                        unsigned *periods, whirl_basins_stats *st);
int run_basins_row(const run_ctx *R, size_t q, int which, unsigned periods, char *buf,
                   size_t len);
int run_basins_header(const run_ctx *R, char *buf, size_t len);
void run_basins_summary(run_ctx *R, const int *cls, size_t np);

#endif

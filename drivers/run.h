/* drivers/run.h — `whirl run FILE`: shared state of the run-file driver.
 * cmd_run.c orchestrates; run_model.c loads models and resolves names;
 * run_solution.c reads and writes labelled solutions; run_table.c writes
 * the branch table and the picture; run_basins.c computes basins.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVER_RUN_H
#define WHIRL_DRIVER_RUN_H

#include <stdio.h>

#include <whirl/whirl.h>

#include "outdir.h"

/* What the unknowns of a branch's system are (a solution's KIND). */
typedef enum run_kind {
  RUN_EQ = 0,     /* equilibrium: x = state */
  RUN_COLLOC = 1, /* periodic orbit by collocation: x = node values, T */
  RUN_HBM = 2     /* periodic orbit by harmonic balance */
} run_kind;

/* A labelled solution as stored in OUT/solutions (full precision). */
typedef struct run_solution {
  int label, br, pt;
  char ty[3];
  run_kind kind;
  int icp;          /* the branch's continuation parameter (0-based) */
  int icp2;         /* loci: the second free parameter, else -1 */
  size_t npar, nx;  /* model parameters; unknowns of the base system */
  double *par;      /* npar */
  double *x;        /* nx: base-system unknowns */
  double *tan;      /* nx + 1 or NULL: unit tangent (x, p_icp) */
  int ntst, ncol;   /* colloc */
  double *mesh;     /* colloc: ntst + 1 */
  int nhb;          /* hbm: harmonics */
  int stable;
  size_t nstate;    /* state components: NX (eq), or NX = M nstate + aut
                       for orbits (M nodes or coefficients) */
  int aut;          /* orbits: 1 if the period is the last unknown */
} run_solution;

/* The model a stored solution must fit (0 / NULL / -1: anything). */
typedef struct run_shape {
  const char *model; /* name */
  size_t n, npar;    /* state components, parameters */
  int forced;        /* 1 forced (no period unknown), 0 autonomous */
} run_shape;

/* What PLOT (the y axis of the picture) names. */
enum { RUN_PLOT_DEFAULT, RUN_PLOT_PAR, RUN_PLOT_PERIOD, RUN_PLOT_L2,
       RUN_PLOT_STATE };

typedef struct run_ctx {
  whirl_runfile *rf;
  const whirl_run_settings *s;
  const whirl_model *model;
  void *dl;               /* dlopen handle of a plug-in, or NULL */
  whirl_model_registry *models; /* the registered models (model = NAME) */
  whirl_problem prob;     /* the model's problem (JAC = 0: no Jacobians) */
  size_t n, npar;
  char **pnames, **xnames; /* resolved names (model's or PAR(k)/U(k)) */
  double *par, *u;         /* start parameters and state */
  int icp[4];              /* resolved, 0-based; -1 for the period (PAR 11) */
  size_t nicp;
  char out[4096], rundir[4096];
  cli_outdir od;           /* the output directory, staged (outdir.h) */
  FILE *log, *table, *sols; /* run.log, branches.tsv, solutions in od */
  int label, branch;
  int failed;              /* a branch ended in failure (DSMIN reached without
                              convergence, a persisting model domain error):
                              the output is kept, the exit status is 1 */
  int quiet;
  int plot_kind, plot_index; /* PLOT resolved: RUN_PLOT_*, parameter or
                               state index */
  int plot_x, plot_y;      /* 1-based columns of the picture's axes */
  char plot_x_name[80], plot_y_name[80];
  int seen_stab[3];         /* rows with STAB -1, 0, 1 */
  int seen_special;
  size_t ncols;
} run_ctx;

/* "FILE:LINE: message" to stderr (exit 2 errors about the run file). */
void run_fail(run_ctx *R, whirl_run_key k, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* run_model.c */
int run_load_model(run_ctx *R);  /* 0 or -1 (message printed) */
int run_resolve(run_ctx *R);     /* names -> indices, PAR, U; 0 or -1 */
int run_par_index(run_ctx *R, const whirl_run_ref *r); /* -1 unknown */
int run_state_index(run_ctx *R, const whirl_run_ref *r);
void run_unload_model(run_ctx *R);

/* run_solution.c */
void run_solution_free(run_solution *s);
int run_solution_write(FILE *f, const run_solution *s);
/* Read the solution of label (or the count-th of type ty if ty[0]) from a
 * solutions file f called path, checking every block read up to it (sizes,
 * numbers) and the one found against want; 0, or -1 with a message
 * ("PATH:LINE: ..." or "label 2 of PATH has ...") in msg. */
int run_solution_read(FILE *f, const char *path, const run_shape *want,
                      int label, const char *ty, run_solution *out, char *msg,
                      size_t len);
/* The same from DIR/solutions, for the model of R. */
int run_solution_find(const run_ctx *R, const char *dir, int label,
                      const char *ty, run_solution *out, char *msg, size_t len);

/* run_table.c */
int run_table_header(run_ctx *R, run_kind kind, int icp, int q);
/* L2-NORM, PERIOD (0 for equilibria) and the state (its MAX over the orbit
 * for periodic orbits, mx[n]) of the solution xb of a problem of this kind */
int run_point_measures(const run_ctx *R, run_kind kind, const void *obj,
                       const double *xb, const double *p, double *l2,
                       double *period, double *mx);
/* The periodic orbit of a branch of this kind (RUN_COLLOC, RUN_HBM) as
 * the library's one interface (whirl/periodic.h). */
whirl_periodic run_periodic(run_kind kind, const void *obj);
int run_table_row(run_ctx *R, run_kind kind, const void *obj, int br, size_t pt,
                  const char *ty, int lab, const double *xb, const double *p,
                  int stable, double *l2out, double *period, double *state);
/* The picture's script (diagram.gp, or basins.gp written by run_basins):
 * 0, or -1 with the message printed; *name is the picture to draw. */
int run_write_plot(run_ctx *R, const char **name);

/* run_basins.c */
int run_basins(run_ctx *R);

#endif

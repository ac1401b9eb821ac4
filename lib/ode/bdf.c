/* lib/ode/bdf.c — the BDF method of whirl/ode.h by SUNDIALS CVODE (version
 * 6: Hindmarsh, Brown, Grant, Lee, Serban, Shumaker & Woodward, "SUNDIALS:
 * Suite of nonlinear and differential/algebraic equation solvers", ACM
 * TOMS 31 (2005) 363–396; the CVODE user guide): variable-order,
 * variable-step BDF (orders 1..5, fixed-leading-coefficient form) with
 * Newton iteration on I − γ f_x, solved by CVODE's dense LU (the model's
 * jac_x, or CVODE's difference quotients) or by KLU sparse LU (Davis &
 * Palamadai Natarajan, ACM TOMS 37 (2010) 36) with the pattern of
 * whirl_ode_set_sparse_jacobian; with a mass matrix B
 * (whirl_ode_set_mass_matrix) the Newton systems are B (I − γ f_x) δ = B r,
 * i.e. (B − γ G) δ = B r with the fill's G = B f_x: CVODE's linear-system
 * function builds B − γ G, and a wrapper around KLU multiplies the
 * right-hand side by B.  CVODE runs in one-step mode with a stop
 * time at t_end, so whirl_ode_step keeps its meaning; its dense output is
 * CVodeGetDky.  CVODE's messages go to the object's errmsg, never stderr.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#ifdef HAVE_CONFIG_H
#include "config.h"
#endif
#include <whirl/dynlib.h>
#include <whirl/ode.h>

#include "ode_impl.h"

/* SUNDIALS (CVODE, its vectors, matrices and linear solvers, KLU), opened
 * at the first BDF integration (whirl/dynlib.h) */
#define SUN_FUNCS(X) \
  X(CVode) X(CVodeCreate) X(CVodeFree) X(CVodeGetCurrentStep) X(CVodeGetDky) \
  X(CVodeGetNonlinSolvStats) X(CVodeGetNumErrTestFails) \
  X(CVodeGetNumJacEvals) X(CVodeGetNumLinSolvSetups) \
  X(CVodeGetNumStepSolveFails) X(CVodeGetNumSteps) X(CVodeGetReturnFlagName) \
  X(CVodeInit) X(CVodeReInit) X(CVodeSStolerances) X(CVodeSetErrHandlerFn) \
  X(CVodeSetInitStep) X(CVodeSetJacFn) X(CVodeSetLinSysFn) \
  X(CVodeSetLinearSolver) X(CVodeSetMaxStep) X(CVodeSetMinStep) \
  X(CVodeSetStopTime) X(CVodeSetUserData) X(N_VClone) X(N_VDestroy) \
  X(N_VGetArrayPointer) X(N_VMake_Serial) X(N_VSetArrayPointer) \
  X(SUNContext_Create) X(SUNContext_Free) X(SUNDenseMatrix) \
  X(SUNDenseMatrix_Data) X(SUNLinSolFree) X(SUNLinSolFreeEmpty) \
  X(SUNLinSolInitialize) X(SUNLinSolLastFlag) X(SUNLinSolNewEmpty) \
  X(SUNLinSolSetup) X(SUNLinSolSolve) X(SUNLinSol_Dense) X(SUNLinSol_KLU) \
  X(SUNMatDestroy) X(SUNSparseMatrix) X(SUNSparseMatrix_Data) \
  X(SUNSparseMatrix_IndexPointers) X(SUNSparseMatrix_IndexValues) \
  X(SUNSparseMatrix_NNZ) X(SUNSparseMatrix_Reallocate)
WHIRL_DYNLIB_SUNDIALS(sun, SUN_FUNCS)


struct whirl_bdf {
  SUNContext ctx;
  void *cv;              /* CVODE's memory, NULL before the first reset */
  N_Vector y;            /* CVODE's output: wraps o->xnew */
  N_Vector dky;          /* dense output: wraps the caller's array */
  SUNMatrix A;           /* dense or sparse (CSC) iteration matrix */
  SUNLinearSolver LS;
  int ls_dirty;          /* the Jacobian's kind changed: new solver */
  double dir;            /* direction since the last (re)start, 0: none */
  size_t nnz;            /* sparse pattern (0: dense), sunindextype copy */
  sunindextype *Jp, *Ji;
  whirl_jac_fn fill;
  void *fill_data;
  int jac_status;        /* the Jacobian callback's last status */
  size_t mnnz;           /* mass matrix B (0: none), in J's pattern at */
  int *Mp, *Mi, *Mpos;   /* Mpos[k] (built with the linear solver) */
  double *Mx, *G;        /* B's values; the fill's last values G = B f_x */
  long nst, netf, nncf, nje, nsetups, nni, nnf; /* CVODE's counters */
  double rtol, atol, h_min, h_max; /* the settings CVODE has */
  char msg[WHIRL_ERRMSG_SIZE]; /* CVODE's last error message */
};

/* ------------------------------------------------------------------------
 * Callbacks: CVODE's recoverable (> 0) and unrecoverable (< 0) returns are
 * problem.h's. */

static int rhs_cb(sunrealtype t, N_Vector y, N_Vector f, void *ud) {
  const int r = whirl_ode_eval_(ud, t, sun.N_VGetArrayPointer(y),
                                sun.N_VGetArrayPointer(f));
  return r > 0 ? 1 : r < 0 ? -1 : 0;
}

/* the status of a Jacobian callback, checked for NaN and Inf in J[m] */
static int jac_status(struct whirl_bdf *b, int r, const double *J, size_t m) {
  b->jac_status = r;
  for (size_t i = 0; r == 0 && i < m; ++i)
    if (!isfinite(J[i])) return 1;
  return r > 0 ? 1 : r < 0 ? -1 : 0;
}

/* the model's jac_x: SUNDenseMatrix_Data is column-major like problem.h */
static int jac_dense_cb(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J,
                        void *ud, N_Vector t1, N_Vector t2, N_Vector t3) {
  (void)fy, (void)t1, (void)t2, (void)t3;
  whirl_ode *o = ud;
  double *Jd = sun.SUNDenseMatrix_Data(J);
  const int r = o->prob.jac_x(t, sun.N_VGetArrayPointer(y), o->p, Jd,
                              o->prob.data);
  return jac_status(o->bdf, r, Jd, o->n * o->n);
}

/* the caller's sparse Jacobian: the pattern afresh each time (CVODE may
 * have added the diagonal to the matrix), then the values */
static int jac_sparse_cb(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J,
                         void *ud, N_Vector t1, N_Vector t2, N_Vector t3) {
  (void)fy, (void)t1, (void)t2, (void)t3;
  whirl_ode *o = ud;
  struct whirl_bdf *b = o->bdf;
  if ((size_t)sun.SUNSparseMatrix_NNZ(J) < b->nnz &&
      sun.SUNSparseMatrix_Reallocate(J, (sunindextype)b->nnz) != 0)
    return -1;
  memcpy(sun.SUNSparseMatrix_IndexPointers(J), b->Jp, (o->n + 1) * sizeof *b->Jp);
  memcpy(sun.SUNSparseMatrix_IndexValues(J), b->Ji, b->nnz * sizeof *b->Ji);
  double *v = sun.SUNSparseMatrix_Data(J);
  const int r = b->fill(t, sun.N_VGetArrayPointer(y), o->p, v, b->fill_data);
  return jac_status(b, r, v, b->nnz);
}

/* CVODE's error messages: kept for whirl's message, warnings dropped */
static void err_cb(int code, const char *module, const char *function,
                   char *msg, void *ud) {
  (void)module;
  struct whirl_bdf *b = ud;
  if (code != CV_WARNING)
    snprintf(b->msg, sizeof b->msg, "%s: %s", function, msg);
}

/* ------------------------------------------------------------------------
 * The back end's state */

/* o->bdf with its context and vectors; WHIRL_ENOMEM */
static int bdf_get(whirl_ode *o) {
  if (o->bdf != NULL) return WHIRL_OK;
  char why[256];
  if (sun_bind(why, sizeof why) != WHIRL_OK)
    return ODE_FAIL(o, WHIRL_ENOLIB, "BDF: SUNDIALS: %s", why);
  struct whirl_bdf *b = calloc(1, sizeof *b);
  if (b == NULL || sun.SUNContext_Create(NULL, &b->ctx) != 0) {
    free(b);
    return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory (SUNDIALS context)");
  }
  o->bdf = b;
  b->y = sun.N_VMake_Serial((sunindextype)o->n, o->xnew, b->ctx);
  b->dky = sun.N_VMake_Serial((sunindextype)o->n, o->xs, b->ctx);
  b->ls_dirty = 1;
  if (b->y == NULL || b->dky == NULL)
    return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory (SUNDIALS vectors)");
  return WHIRL_OK;
}

void whirl_bdf_free_(struct whirl_bdf *b) {
  if (b == NULL) return;
  sun.CVodeFree(&b->cv);
  sun.SUNLinSolFree(b->LS);
  sun.SUNMatDestroy(b->A);
  sun.N_VDestroy(b->y);
  sun.N_VDestroy(b->dky);
  free(b->Jp);
  free(b->Ji);
  free(b->Mp); free(b->Mi); free(b->Mx); free(b->Mpos); free(b->G);
  sun.SUNContext_Free(&b->ctx);
  free(b);
}

/* ------------------------------------------------------------------------
 * A mass matrix B: the iteration matrix B − γ G (CVODE's linear-system
 * function; G reused while CVODE says the Jacobian is still good), solved by
 * KLU on B times the right-hand side. */

static int mass_linsys(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix A,
                       sunbooleantype jok, sunbooleantype *jcur,
                       sunrealtype gamma, void *ud, N_Vector t1, N_Vector t2,
                       N_Vector t3) {
  (void)fy, (void)t1, (void)t2, (void)t3;
  whirl_ode *o = ud;
  struct whirl_bdf *b = o->bdf;
  if ((size_t)sun.SUNSparseMatrix_NNZ(A) < b->nnz &&
      sun.SUNSparseMatrix_Reallocate(A, (sunindextype)b->nnz) != 0)
    return -1;
  memcpy(sun.SUNSparseMatrix_IndexPointers(A), b->Jp, (o->n + 1) * sizeof *b->Jp);
  memcpy(sun.SUNSparseMatrix_IndexValues(A), b->Ji, b->nnz * sizeof *b->Ji);
  *jcur = SUNFALSE;
  if (!jok) {
    int r = b->fill(t, sun.N_VGetArrayPointer(y), o->p, b->G, b->fill_data);
    *jcur = SUNTRUE;
    if ((r = jac_status(b, r, b->G, b->nnz)) != 0) return r;
  }
  double *v = sun.SUNSparseMatrix_Data(A);
  for (size_t k = 0; k < b->nnz; ++k) v[k] = -gamma * b->G[k];
  for (size_t k = 0; k < b->mnnz; ++k) v[b->Mpos[k]] += b->Mx[k];
  return 0;
}

typedef struct mass_ls {
  SUNLinearSolver klu;
  N_Vector tmp;
  const struct whirl_bdf *b;
  size_t n;
} mass_ls;

#define MLS(S) ((mass_ls *)(S)->content)

static SUNLinearSolver_Type mls_type(SUNLinearSolver S) {
  (void)S;
  return SUNLINEARSOLVER_DIRECT;
}
static SUNLinearSolver_ID mls_id(SUNLinearSolver S) {
  (void)S;
  return SUNLINEARSOLVER_CUSTOM;
}
static int mls_init(SUNLinearSolver S) { return sun.SUNLinSolInitialize(MLS(S)->klu); }
static int mls_setup(SUNLinearSolver S, SUNMatrix A) { return sun.SUNLinSolSetup(MLS(S)->klu, A); }
static sunindextype mls_lastflag(SUNLinearSolver S) { return sun.SUNLinSolLastFlag(MLS(S)->klu); }

/* x = (B − γG)⁻¹ B r */
static int mls_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector r,
                     sunrealtype tol) {
  const mass_ls *c = MLS(S);
  const struct whirl_bdf *b = c->b;
  const double *rv = sun.N_VGetArrayPointer(r);
  double *w = sun.N_VGetArrayPointer(c->tmp);
  memset(w, 0, c->n * sizeof *w);
  for (size_t j = 0; j < c->n; ++j)
    for (int k = b->Mp[j]; k < b->Mp[j + 1]; ++k) w[b->Mi[k]] += b->Mx[k] * rv[j];
  return sun.SUNLinSolSolve(c->klu, A, x, c->tmp, tol);
}

static int mls_free(SUNLinearSolver S) {
  if (S == NULL) return 0;
  if (S->content != NULL) {
    sun.SUNLinSolFree(MLS(S)->klu);
    sun.N_VDestroy(MLS(S)->tmp);
    free(S->content);
    S->content = NULL;
  }
  sun.SUNLinSolFreeEmpty(S);
  return 0;
}

static SUNLinearSolver mass_solver(struct whirl_bdf *b, SUNMatrix A, size_t n) {
  SUNLinearSolver S = sun.SUNLinSolNewEmpty(b->ctx);
  mass_ls *c = S ? calloc(1, sizeof *c) : NULL;
  if (c == NULL) {
    sun.SUNLinSolFreeEmpty(S);
    return NULL;
  }
  S->content = c;
  S->ops->gettype = mls_type;
  S->ops->getid = mls_id;
  S->ops->initialize = mls_init;
  S->ops->setup = mls_setup;
  S->ops->solve = mls_solve;
  S->ops->lastflag = mls_lastflag;
  S->ops->free = mls_free;
  c->b = b;
  c->n = n;
  c->klu = sun.SUNLinSol_KLU(b->y, A, b->ctx);
  c->tmp = sun.N_VClone(b->y);
  if (c->klu == NULL || c->tmp == NULL) {
    mls_free(S);
    return NULL;
  }
  return S;
}

/* Mpos: where each entry of B sits in J's pattern; −1 when B's pattern is
 * not inside J's. */
static int mass_positions(struct whirl_bdf *b, size_t n) {
  free(b->Mpos);
  free(b->G);
  b->Mpos = malloc((b->mnnz + 1) * sizeof *b->Mpos);
  b->G = malloc((b->nnz + 1) * sizeof *b->G);
  if (b->Mpos == NULL || b->G == NULL) return WHIRL_ENOMEM;
  for (size_t j = 0; j < n; ++j)
    for (int k = b->Mp[j]; k < b->Mp[j + 1]; ++k) {
      b->Mpos[k] = -1;
      for (sunindextype q = b->Jp[j]; q < b->Jp[j + 1]; ++q)
        if (b->Ji[q] == b->Mi[k]) b->Mpos[k] = (int)q;
      if (b->Mpos[k] < 0) return WHIRL_EINVAL;
    }
  return WHIRL_OK;
}

/* A new matrix and linear solver for CVODE: KLU with the sparse pattern,
 * else dense LU with jac_x or difference quotients. */
static int new_linear_solver(whirl_ode *o) {
  struct whirl_bdf *b = o->bdf;
  const sunindextype n = (sunindextype)o->n;
  SUNMatrix A;
  SUNLinearSolver LS;
  if (b->mnnz > 0) {
    const int r = b->nnz > 0 ? mass_positions(b, o->n) : WHIRL_EINVAL;
    if (r != WHIRL_OK)
      return ODE_FAIL(o, r, r == WHIRL_ENOMEM ? "out of memory" :
                      "BDF: the mass matrix needs a sparse Jacobian whose pattern holds its own");
    A = sun.SUNSparseMatrix(n, n, (sunindextype)b->nnz, CSC_MAT, b->ctx);
    LS = A ? mass_solver(b, A, o->n) : NULL;
  } else if (b->nnz > 0) {
    A = sun.SUNSparseMatrix(n, n, (sunindextype)b->nnz, CSC_MAT, b->ctx);
    LS = A ? sun.SUNLinSol_KLU(b->y, A, b->ctx) : NULL;
  } else {
    A = sun.SUNDenseMatrix(n, n, b->ctx);
    LS = A ? sun.SUNLinSol_Dense(b->y, A, b->ctx) : NULL;
  }
  if (LS == NULL || sun.CVodeSetLinearSolver(b->cv, LS, A) != CVLS_SUCCESS) {
    sun.SUNLinSolFree(LS);
    sun.SUNMatDestroy(A);
    return ODE_FAIL(o, WHIRL_ENOMEM, "BDF: no linear solver: %s", b->msg);
  }
  sun.SUNLinSolFree(b->LS); /* the old ones, now detached */
  sun.SUNMatDestroy(b->A);
  b->LS = LS;
  b->A = A;
  CVLsJacFn jac = b->nnz > 0 ? jac_sparse_cb
                  : o->prob.jac_x != NULL ? jac_dense_cb
                                         : NULL;
  if (b->mnnz > 0 ? sun.CVodeSetLinSysFn(b->cv, mass_linsys) != CVLS_SUCCESS
                  : sun.CVodeSetJacFn(b->cv, jac) != CVLS_SUCCESS)
    return ODE_FAIL(o, WHIRL_EINVAL, "BDF: %s", b->msg);
  b->ls_dirty = 0;
  return WHIRL_OK;
}

/* The tolerances (right after a (re)start only: CVodeSStolerances during
 * an integration leaves CVODE 6.4 without its error-weight data) and the
 * step limits, as given to CVODE. */
static int apply_settings(whirl_ode *o) {
  struct whirl_bdf *b = o->bdf;
  if (sun.CVodeSStolerances(b->cv, o->rtol, o->atol) != CV_SUCCESS ||
      sun.CVodeSetMinStep(b->cv, o->h_min) != CV_SUCCESS ||
      sun.CVodeSetMaxStep(b->cv, o->h_max) != CV_SUCCESS)
    return ODE_FAIL(o, WHIRL_EINVAL, "BDF: %s", b->msg);
  b->rtol = o->rtol;
  b->atol = o->atol;
  b->h_min = o->h_min;
  b->h_max = o->h_max;
  return WHIRL_OK;
}

/* CVODE (re)started at (o->t, o->x); its counters start at 0 again. */
static int restart(whirl_ode *o) {
  struct whirl_bdf *b = o->bdf;
  memcpy(o->xnew, o->x, o->n * sizeof *o->x);
  int f;
  if (b->cv == NULL) {
    b->cv = sun.CVodeCreate(CV_BDF, b->ctx);
    if (b->cv == NULL)
      return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory (CVODE)");
    sun.CVodeSetErrHandlerFn(b->cv, err_cb, b);
    f = sun.CVodeInit(b->cv, rhs_cb, o->t, b->y);
    if (f == CV_SUCCESS) f = sun.CVodeSetUserData(b->cv, o);
    b->ls_dirty = 1;
  } else {
    f = sun.CVodeReInit(b->cv, o->t, b->y);
  }
  if (f != CV_SUCCESS)
    return ODE_FAIL(o, f == CV_MEM_FAIL ? WHIRL_ENOMEM : WHIRL_EINVAL,
                    "BDF: %s", b->msg);
  if (b->ls_dirty && (f = new_linear_solver(o)) != WHIRL_OK) return f;
  if (sun.CVodeSetInitStep(b->cv, o->h_init) != CV_SUCCESS)
    return ODE_FAIL(o, WHIRL_EINVAL, "BDF: %s", b->msg);
  b->nst = b->netf = b->nncf = b->nje = b->nsetups = b->nni = b->nnf = 0;
  b->dir = 0.0;
  o->have_step = 0;
  return apply_settings(o);
}

int whirl_bdf_reset_(whirl_ode *o) {
  const int r = bdf_get(o);
  if (r != WHIRL_OK) return r;
  o->bdf->msg[0] = '\0';
  return restart(o);
}

/* ------------------------------------------------------------------------
 * Statistics: CVODE's counters since the last look, added to the object's */

static size_t since(long now, long *last) {
  const long d = now - *last;
  *last = now;
  return d > 0 ? (size_t)d : 0;
}

static void add_stats(whirl_ode *o) {
  struct whirl_bdf *b = o->bdf;
  long nst = 0, netf = 0, nncf = 0, nje = 0, nsetups = 0, nni = 0, nnf = 0;
  sun.CVodeGetNumSteps(b->cv, &nst);
  sun.CVodeGetNumErrTestFails(b->cv, &netf);
  sun.CVodeGetNumStepSolveFails(b->cv, &nncf);
  sun.CVodeGetNumJacEvals(b->cv, &nje);
  sun.CVodeGetNumLinSolvSetups(b->cv, &nsetups);
  sun.CVodeGetNonlinSolvStats(b->cv, &nni, &nnf);
  o->st.steps += since(nst, &b->nst);
  const size_t ef = since(netf, &b->netf), cf = since(nncf, &b->nncf);
  o->st.rejected += ef + cf;
  o->ist.error_fails += ef;
  o->ist.jac_evals += since(nje, &b->nje);
  o->ist.lu_factors += since(nsetups, &b->nsetups);
  o->ist.newton_iters += since(nni, &b->nni);
  o->ist.newton_fails += since(nnf, &b->nnf);
}

/* ------------------------------------------------------------------------
 * A step */

/* whirl's status and message for CVODE's failure flag in a step from t0 */
static int step_failed(whirl_ode *o, int flag, double t0) {
  struct whirl_bdf *b = o->bdf;
  const char *cv = b->msg[0] ? b->msg : sun.CVodeGetReturnFlagName(flag);
  char what[64] = "";
  if (o->last_rhs != 0) whirl_ode_rhs_said_(o, what, sizeof what);
  switch (flag) {
  case CV_RHSFUNC_FAIL:
    return ODE_FAIL(o, WHIRL_EUSER,
                    "right-hand side returned %d (%s) in a BDF step from "
                    "t = %.17g",
                    o->last_rhs, whirl_strerror(o->last_rhs), t0);
  case CV_FIRST_RHSFUNC_ERR:
    return ODE_FAIL(o, WHIRL_ESTEP, "no step possible from t = %.17g: %s there",
                    t0, what);
  case CV_LSETUP_FAIL:
  case CV_LSOLVE_FAIL:
    if (b->jac_status < 0)
      return ODE_FAIL(o, WHIRL_EUSER,
                      "Jacobian returned %d in a BDF step from t = %.17g",
                      b->jac_status, t0);
    return ODE_FAIL(o, b->nnz > 0 ? WHIRL_ESPARSE : WHIRL_ESINGULAR,
                    "BDF linear solver (%s) failed at t = %.17g: %s",
                    b->nnz > 0 ? "KLU" : "dense LU", t0, cv);
  case CV_MEM_FAIL:
    return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory in CVODE");
  case CV_ILL_INPUT:
    return ODE_FAIL(o, WHIRL_EINVAL, "BDF: %s", cv);
  default: /* error or convergence test, repeated recoverable failures */
    return ODE_FAIL(o, WHIRL_ESTEP, "BDF step from t = %.17g failed%s%s: %s",
                    t0, what[0] ? ": " : "", what, cv);
  }
}

int whirl_bdf_step_(whirl_ode *o, double t_end) {
  struct whirl_bdf *b = o->bdf;
  const double dir = t_end > o->t ? 1.0 : -1.0, t0 = o->t;
  int r;
  /* CVODE cannot turn back, nor take new tolerances on the way: restart
   * from the current point; new step limits it takes */
  if (((b->dir != 0.0 && dir != b->dir) || o->rtol != b->rtol ||
       o->atol != b->atol) &&
      (r = restart(o)) != WHIRL_OK)
    return r;
  if ((o->h_min != b->h_min || o->h_max != b->h_max) &&
      (sun.CVodeSetMinStep(b->cv, o->h_min) != CV_SUCCESS ||
       sun.CVodeSetMaxStep(b->cv, o->h_max) != CV_SUCCESS))
    return ODE_FAIL(o, WHIRL_EINVAL, "BDF: %s", b->msg);
  b->h_min = o->h_min;
  b->h_max = o->h_max;
  b->msg[0] = '\0';
  b->jac_status = 0;
  if (sun.CVodeSetStopTime(b->cv, t_end) != CV_SUCCESS)
    return ODE_FAIL(o, WHIRL_EINVAL, "BDF: %s", b->msg);
  sunrealtype tret = t0;
  const int flag = sun.CVode(b->cv, t_end, b->y, &tret, CV_ONE_STEP);
  add_stats(o);
  if (flag < 0) return step_failed(o, flag, t0);
  memcpy(o->x_prev, o->x, o->n * sizeof *o->x);
  memcpy(o->x, o->xnew, o->n * sizeof *o->x);
  o->t_prev = t0;
  o->t = flag == CV_TSTOP_RETURN ? t_end : tret;
  o->have_step = 1;
  b->dir = dir;
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Dense output, next step */

int whirl_bdf_dense_(const whirl_ode *o, double t, double *x) {
  struct whirl_bdf *b = o->bdf;
  sun.N_VSetArrayPointer(x, b->dky);
  if (sun.CVodeGetDky(b->cv, t, 0, b->dky) == CV_SUCCESS) return WHIRL_OK;
  for (size_t i = 0; i < o->n; ++i) x[i] = NAN;
  return WHIRL_EINVAL;
}

double whirl_bdf_h_(const whirl_ode *o) {
  sunrealtype h = 0.0;
  if (!o->have_step || sun.CVodeGetCurrentStep(o->bdf->cv, &h) != CV_SUCCESS)
    return o->h_init;
  return fabs(h);
}

/* ------------------------------------------------------------------------
 * The sparse Jacobian */

/* a compressed-column pattern of an n×n matrix: NULL if good, else why */
static const char *bad_pattern(size_t n, size_t nnz, const int *Jp,
                               const int *Ji) {
  if (Jp == NULL || Ji == NULL || nnz > (size_t)n * n)
    return "need Jp[n+1], Ji[nnz] and nnz <= n*n";
  if (Jp[0] != 0 || (size_t)Jp[n] != nnz) return "need Jp[0] = 0, Jp[n] = nnz";
  for (size_t j = 0; j < n; ++j) {
    if (Jp[j + 1] < Jp[j]) return "Jp is decreasing";
    for (int k = Jp[j]; k < Jp[j + 1]; ++k) {
      if (Ji[k] < 0 || (size_t)Ji[k] >= n) return "a row index is outside [0, n)";
      if (k > Jp[j] && Ji[k] <= Ji[k - 1])
        return "row indices not increasing within a column";
    }
  }
  return NULL;
}

int whirl_ode_set_sparse_jacobian(whirl_ode *o, size_t nnz, const int *Jp,
                                  const int *Ji, whirl_jac_fn fill,
                                  void *data) {
  if (o == NULL) return WHIRL_EINVAL;
  const size_t n = o->n;
  const char *why = NULL;
  if (nnz == 0 ? fill != NULL : fill == NULL)
    why = "fill must be given with nnz > 0 and NULL with nnz = 0";
  else if (nnz > 0)
    why = bad_pattern(n, nnz, Jp, Ji);
  if (why != NULL)
    return ODE_FAIL(o, WHIRL_EINVAL, "sparse Jacobian: %s", why);
  int r = bdf_get(o);
  if (r != WHIRL_OK) return r;
  struct whirl_bdf *b = o->bdf;
  sunindextype *p = nnz ? malloc((n + 1) * sizeof *p) : NULL;
  sunindextype *i = nnz ? malloc(nnz * sizeof *i) : NULL;
  if (nnz > 0 && (p == NULL || i == NULL)) {
    free(p);
    free(i);
    return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory");
  }
  for (size_t j = 0; nnz > 0 && j <= n; ++j) p[j] = Jp[j];
  for (size_t k = 0; k < nnz; ++k) i[k] = Ji[k];
  free(b->Jp);
  free(b->Ji);
  b->Jp = p;
  b->Ji = i;
  b->nnz = nnz;
  b->fill = fill;
  b->fill_data = data;
  b->ls_dirty = 1;
  return WHIRL_OK;
}

int whirl_ode_set_mass_matrix(whirl_ode *o, size_t nnz, const int *Mp,
                              const int *Mi, const double *Mx) {
  if (o == NULL) return WHIRL_EINVAL;
  const size_t n = o->n;
  const char *why = nnz > 0 ? bad_pattern(n, nnz, Mp, Mi) : NULL;
  if (why == NULL && nnz > 0 && Mx == NULL) why = "need the values Mx[nnz]";
  for (size_t k = 0; why == NULL && k < nnz; ++k)
    if (!isfinite(Mx[k])) why = "a value is not finite";
  if (why != NULL) return ODE_FAIL(o, WHIRL_EINVAL, "mass matrix: %s", why);
  int r = bdf_get(o);
  if (r != WHIRL_OK) return r;
  struct whirl_bdf *b = o->bdf;
  int *p = nnz ? malloc((n + 1) * sizeof *p) : NULL, *i = nnz ? malloc(nnz * sizeof *i) : NULL;
  double *x = nnz ? malloc(nnz * sizeof *x) : NULL;
  if (nnz > 0 && (p == NULL || i == NULL || x == NULL)) {
    free(p); free(i); free(x);
    return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory");
  }
  if (nnz > 0) {
    memcpy(p, Mp, (n + 1) * sizeof *p);
    memcpy(i, Mi, nnz * sizeof *i);
    memcpy(x, Mx, nnz * sizeof *x);
  }
  free(b->Mp); free(b->Mi); free(b->Mx);
  b->Mp = p, b->Mi = i, b->Mx = x, b->mnnz = nnz;
  b->ls_dirty = 1;
  return WHIRL_OK;
}

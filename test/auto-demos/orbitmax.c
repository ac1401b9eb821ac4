/* test/auto-demos/orbitmax.c — a converged reference for the MAX U(i)
 * columns of AUTO's b-files, by a route independent of both programs'
 * collocation: the demo's own FUNC (compiled from its equations file) is
 * integrated by SUNDIALS' CVODE (BDF, RelTol 1e-12) over every mesh
 * interval of a labelled orbit of an s-file, from the orbit's value at the
 * interval's left mesh point, and the largest value of each component on
 * the dense output (16 samples an internal step) is the orbit's maximum.
 * Short integrations from each mesh point do not amplify the start's error
 * by the orbit's multipliers.
 *
 *   orbitmax S-FILE            (linked with the demo's compiled .f90)
 *
 * prints, per labelled orbit (NTST > 0), `LAB max_U(1) ... max_U(NDIM)`.
 * AUTO's own MAX is the largest value at its mesh nodes (NTST NCOL + 1 of
 * them), which lies below the orbit's maximum by up to the curvature times
 * the square of half a node spacing; test/auto-demos/run.sh uses this
 * program to say whose MAX is right (doc/auto-files.md).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

/* AUTO's user routines (gfortran's names and calling convention) */
extern void func_(const int *ndim, const double *u, const int *icp,
                  const double *par, const int *ijac, double *f, double *dfdu,
                  double *dfdp);
extern void stpnt_(const int *ndim, double *u, double *par, const double *t);
extern void pvls_(const int *ndim, const double *u, double *par);

/* The utility routines a demo's PVLS or BCND may call: never called here. */
double getp_(void) { return 0; }

extern void dgesv_(const int *n, const int *nrhs, double *a, const int *lda,
                   int *ipiv, double *b, const int *ldb, int *info);

/* AUTO's GE(IAM, N, M1A, A, NRHS, NDX, U, M1F, F, IR, IC, DET): U := A⁻¹ F
 * and DET = det A (brc's and brf's FUNC solve with it), by LAPACK's LU
 * (A and F are overwritten, as AUTO's GE may do). */
void ge_(const int *iam, const int *n, const int *m1a, double *a,
         const int *nrhs, const int *ndx, double *u, const int *m1f, double *f,
         int *ir, int *ic, double *det) {
  (void)iam;
  int info;
  dgesv_(n, nrhs, a, m1a, ir, f, m1f, &info);
  *det = info > 0 ? 0.0 : 1.0;
  for (int i = 0; info == 0 && i < *n; ++i)
    *det *= (ir[i] != i + 1 ? -1.0 : 1.0) * a[i + (size_t)*m1a * i];
  for (int j = 0; j < *nrhs; ++j)
    for (int i = 0; i < *n; ++i) u[i + (size_t)*ndx * j] = f[i + (size_t)*m1f * j];
  (void)ic;
}

enum { MAXPAR = 64 };

typedef struct orbit {
  int ndim, ntpl, ncol, ntst, lab;
  double *t, *u; /* ntpl times, ntpl x ndim values */
  double par[MAXPAR];
} orbit;

typedef struct rhs_ctx {
  const orbit *o;
  double *dfdu, *dfdp;
} rhs_ctx;

static int rhs(double t, N_Vector y, N_Vector ydot, void *data) {
  (void)t;
  rhs_ctx *c = data;
  const int ijac = 0, icp[2] = {1, 11};
  func_(&c->o->ndim, N_VGetArrayPointer(y), icp, c->o->par, &ijac,
        N_VGetArrayPointer(ydot), c->dfdu, c->dfdp);
  double T = c->o->par[10], *f = N_VGetArrayPointer(ydot);
  for (int i = 0; i < c->o->ndim; ++i) f[i] *= T; /* scaled time t in [0, 1] */
  return 0;
}

/* One s-file block: the 16-integer header, then NROWPR lines of numbers
 * (the NTPL rows (t, u), the free parameters, the tangents, then the NPAR
 * parameters last).  Returns 1 for a block read, 0 at the end, -1 on an
 * error. */
static int read_block(FILE *f, orbit *o) {
  int h[16];
  for (int i = 0; i < 16; ++i)
    if (fscanf(f, "%d", &h[i]) != 1) return i == 0 ? 0 : -1;
  int ntpl = h[6], nar = h[7], nrowpr = h[8], npar = h[11];
  o->lab = h[3];
  o->ntst = h[9];
  o->ncol = h[10];
  o->ndim = nar - 1;
  o->ntpl = ntpl;
  if (ntpl < 1 || nar < 2 || npar < 11 || npar > MAXPAR) return -1;
  /* the block's numbers: its NROWPR lines, read as tokens line by line */
  char line[4096];
  size_t cap = 1024, n = 0;
  double *v = malloc(cap * sizeof *v);
  if (!v || !fgets(line, sizeof line, f)) { free(v); return -1; } /* rest of the header line */
  for (int r = 0; r < nrowpr; ++r) {
    if (!fgets(line, sizeof line, f)) { free(v); return -1; }
    for (char *s = line, *e;; s = e) {
      double x = strtod(s, &e);
      if (e == s) break;
      if (n == cap) {
        double *w = realloc(v, 2 * cap * sizeof *w);
        if (!w) { free(v); return -1; }
        v = w;
        cap *= 2;
      }
      v[n++] = x;
    }
  }
  if (n < (size_t)ntpl * nar + (size_t)npar) { free(v); return -1; }
  o->t = malloc((size_t)ntpl * sizeof *o->t);
  o->u = malloc((size_t)ntpl * o->ndim * sizeof *o->u);
  if (!o->t || !o->u) { free(v); return -1; }
  for (int j = 0; j < ntpl; ++j) {
    o->t[j] = v[(size_t)j * nar];
    memcpy(o->u + (size_t)j * o->ndim, v + (size_t)j * nar + 1,
           (size_t)o->ndim * sizeof *o->u);
  }
  memset(o->par, 0, sizeof o->par);
  memcpy(o->par, v + n - npar, (size_t)npar * sizeof *o->par);
  free(v);
  return 1;
}

static void track(const double *y, int n, double *mx) {
  for (int i = 0; i < n; ++i)
    if (y[i] > mx[i]) mx[i] = y[i];
}

/* The largest values of the flow over [t_a, t_b] from ya, into mx. */
static int interval_max(void *cv, N_Vector y, N_Vector dky, const orbit *o,
                        int a, int b, double *mx) {
  int n = o->ndim;
  memcpy(N_VGetArrayPointer(y), o->u + (size_t)a * n, (size_t)n * sizeof(double));
  track(N_VGetArrayPointer(y), n, mx);
  if (CVodeReInit(cv, o->t[a], y) != CV_SUCCESS) return -1;
  CVodeSetStopTime(cv, o->t[b]);
  double tr = o->t[a];
  /* CV_ONE_STEP bypasses CVODE's own step limit: bounded here, so a start
   * whose flow blows up inside the interval (CVODE's steps shrink until
   * t + h = t, vhb's orbits near the homoclinic loop) ends as "no
   * reference" instead of spinning for ever */
  for (long steps = 0; tr < o->t[b]; ++steps) {
    if (steps == 1000000) return -1;
    int st = CVode(cv, o->t[b], y, &tr, CV_ONE_STEP);
    if (st < 0) return -1;
    double h;
    CVodeGetLastStep(cv, &h);
    if (!(fabs(h) > 1e-15 * (fabs(tr) + 1.0))) return -1; /* stalled */
    for (int k = 1; k <= 16; ++k) {
      if (CVodeGetDky(cv, tr - h + h * k / 16.0, 0, dky) != CV_SUCCESS) return -1;
      track(N_VGetArrayPointer(dky), n, mx);
    }
    if (st == CV_TSTOP_RETURN) break;
  }
  return 0;
}

static int orbit_max(SUNContext ctx, const orbit *o, double *mx) {
  int n = o->ndim, rc = 0;
  rhs_ctx c = {o, calloc((size_t)n * n, sizeof(double)),
               calloc((size_t)n * MAXPAR, sizeof(double))};
  N_Vector y = N_VNew_Serial(n, ctx), dky = N_VNew_Serial(n, ctx);
  SUNMatrix A = SUNDenseMatrix(n, n, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  void *cv = CVodeCreate(CV_BDF, ctx);
  for (int i = 0; i < n; ++i) mx[i] = -HUGE_VAL;
  memcpy(N_VGetArrayPointer(y), o->u, (size_t)n * sizeof(double));
  if (!c.dfdu || !c.dfdp || !cv || CVodeInit(cv, rhs, o->t[0], y) != CV_SUCCESS ||
      CVodeSetUserData(cv, &c) != CV_SUCCESS ||
      CVodeSStolerances(cv, 1e-12, 1e-14) != CV_SUCCESS ||
      CVodeSetLinearSolver(cv, LS, A) != CV_SUCCESS ||
      CVodeSetMaxNumSteps(cv, 1000000) != CV_SUCCESS)
    rc = -1;
  for (int j = 0; !rc && j + o->ncol < o->ntpl; j += o->ncol)
    rc = interval_max(cv, y, dky, o, j, j + o->ncol, mx);
  CVodeFree(&cv);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(y);
  N_VDestroy(dky);
  free(c.dfdu);
  free(c.dfdp);
  return rc;
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: orbitmax S-FILE\n");
    return 2;
  }
  FILE *f = fopen(argv[1], "r");
  if (!f) {
    perror(argv[1]);
    return 2;
  }
  SUNContext ctx;
  if (SUNContext_Create(NULL, &ctx)) return 1;
  orbit o;
  int st, bad = 0, inited = 0;
  while ((st = read_block(f, &o)) == 1) {
    if (!inited) { /* a demo's STPNT or PVLS may set up what its FUNC
                      reads (brc's PVLS its differentiation matrix) */
      double u0[512] = {0}, p0[MAXPAR] = {0}, t0 = 0;
      if (o.ndim <= 512) {
        stpnt_(&o.ndim, u0, p0, &t0);
        pvls_(&o.ndim, u0, p0);
      }
      inited = 1;
    }
    if (o.ntst > 0 && o.ncol > 0 && o.ntpl == o.ntst * o.ncol + 1) {
      double mx[512];
      if (o.ndim > 512 || orbit_max(ctx, &o, mx)) {
        fprintf(stderr, "orbitmax: label %d: the integration failed\n", o.lab);
        bad = 1;
      } else {
        printf("%d", o.lab);
        for (int i = 0; i < o.ndim; ++i) printf(" %.10g", mx[i]);
        printf("\n");
      }
    }
    free(o.t);
    free(o.u);
  }
  fclose(f);
  SUNContext_Free(&ctx);
  if (st < 0) {
    fprintf(stderr, "orbitmax: %s: a malformed block\n", argv[1]);
    return 1;
  }
  return bad;
}

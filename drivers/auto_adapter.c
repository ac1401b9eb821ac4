/* drivers/auto_adapter.c — the part of every AUTO-07p plug-in that does not
 * depend on the equations: AUTO's user routines (AUTO-07p manual, ch. 4
 * "User-supplied routines", Fortran, all arguments by reference)
 *   FUNC(NDIM, U, ICP, PAR, IJAC, F, DFDU, DFDP)   the vector field; IJAC 1:
 *        also DFDU(NDIM, NDIM), column-major, as whirl's jac_x
 *   STPNT(NDIM, U, PAR, T)                         the start, T in [0, 1]
 *   BCND, ICND                                     boundary and integral
 *        conditions (IPS = 4), IJAC = 0: whirl differentiates them
 *   PVLS(NDIM, U, PAR)                             output parameters
 * called as whirl's model functions (whirl/model.h), and the two utility
 * routines the users' routines call: GETP (PVLS's solution measures) and
 * GE (a linear solver some FUNCs call: demos brc, brf), written here
 * afresh.  It is whirl's own code, not AUTO's.
 *
 * Built once with whirl (PIC, into libwhirl-auto-adapter.a) and linked into
 * each plug-in `whirl auto` compiles; the plug-in's own C file (written by
 * auto_model.c) holds only what the equations file does not say: NDIM, the
 * parameter count, the names, whirl_model_def.  Compiling the adapter once
 * instead of with every equations file halves the compile of a demo (test/
 * bench/auto_demos_speed.sh; doc/benchmarks.md).  Its symbols that the
 * plug-in's C file uses are hidden: two plug-ins in one process (a demo
 * with c-files of two NDIMs) bind each to its own.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <string.h>

#include <whirl/model.h>


#define HIDDEN __attribute__((visibility("hidden")))

/* the plug-in's C file (auto_model.c writes it) */
extern HIDDEN const int wa_ndim;    /* NDIM */
extern HIDDEN const int wa_npar;    /* whirl's parameters PAR(1..wa_npar) */
extern HIDDEN const int wa_nparx;   /* AUTO's PAR array: max(NPARX 36, npar) */
extern HIDDEN int wa_icp[];         /* [wa_nparx] the run's ICP (set_icp) */
extern HIDDEN double wa_par0[];     /* [wa_npar] STPNT's at T = 0 (init) */
extern HIDDEN double wa_u0[];       /* [wa_ndim] */
extern whirl_model whirl_model_def;

/* the equations file's routines: FUNC and STPNT required, the others
 * optional (a missing one is NULL) */
void func_(const int *, const double *, const int *, const double *, const int *, double *,
           double *, double *);
void stpnt_(const int *, double *, double *, const double *);
void pvls_(const int *, const double *, double *) __attribute__((weak));
void bcnd_(const int *, const double *, const int *, const int *, const double *,
           const double *, double *, const int *, double *) __attribute__((weak));
void icnd_(const int *, const double *, const int *, const int *, const double *,
           const double *, const double *, const double *, double *, const int *,
           double *) __attribute__((weak));

HIDDEN int wa_rhs(double t, const double *x, const double *p, double *f, void *d);
HIDDEN int wa_jac(double t, const double *x, const double *p, double *J, void *d);
HIDDEN int wa_stpnt(double tau, double *u, double *p, void *d);
HIDDEN int wa_pvls(const double *x, double *p, void *d);
HIDDEN int wa_pvls_solution(const double *u, size_t nn, const double *w, double *p, void *d);
HIDDEN int wa_bcnd(size_t nbc, const double *u0, const double *u1, const double *p,
                   double *fb, void *d);
HIDDEN int wa_icnd(size_t nint, const double *u, const double *uo, const double *ud,
                   const double *upo, const double *p, double *fi, void *d);
HIDDEN void wa_set_icp(const int *c, size_t n, const int k[4], void *d);

static int counts[4]; /* NTST, NCOL, NBC, NINT, for GETP */

/* AUTO's GE(IAM, N, M1A, A, NRHS, NDX, U, M1F, F, IR, IC, DET): U = A^-1 F
 * for NRHS columns (A(M1A,N), U(NDX,NRHS), F(M1F,NRHS), column-major) by
 * Gaussian elimination with partial pivoting; DET = det A.  A and F are
 * overwritten, IR and IC unused. */
void ge_(const int *iam, const int *n_, const int *m1a, double *a, const int *nrhs,
         const int *ndx, double *u, const int *m1f, double *f, int *ir, int *ic, double *det) {
  const int n = *n_, la = *m1a, lf = *m1f, lu = *ndx, nr = *nrhs;
  (void)iam, (void)ir, (void)ic;
  *det = 1;
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++)
      if (fabs(a[i + la * k]) > fabs(a[p + la * k])) p = i;
    if (p != k) {
      *det = -*det;
      for (int j = 0; j < n; j++) {
        const double t = a[k + la * j];
        a[k + la * j] = a[p + la * j], a[p + la * j] = t;
      }
      for (int j = 0; j < nr; j++) {
        const double t = f[k + lf * j];
        f[k + lf * j] = f[p + lf * j], f[p + lf * j] = t;
      }
    }
    const double piv = a[k + la * k];
    *det *= piv;
    if (piv == 0) continue;
    for (int i = k + 1; i < n; i++) {
      const double m = a[i + la * k] / piv;
      for (int j = k; j < n; j++) a[i + la * j] -= m * a[k + la * j];
      for (int j = 0; j < nr; j++) f[i + lf * j] -= m * f[k + lf * j];
    }
  }
  for (int j = 0; j < nr; j++)
    for (int i = n - 1; i >= 0; i--) {
      double s = f[i + lf * j];
      for (int k = i + 1; k < n; k++) s -= a[i + la * k] * u[k + lu * j];
      u[i + lu * j] = a[i + la * i] != 0 ? s / a[i + la * i] : 0;
    }
}

/* AUTO's PAR array (wa_nparx entries, zero beyond whirl's) from p */
static void load_par(double *par, const double *p) {
  memset(par, 0, (size_t)wa_nparx * sizeof *par);
  memcpy(par, p, (size_t)wa_npar * sizeof *p);
}

/* The PAR array FUNC, BCND and ICND get: one a thread, kept between calls
 * as AUTO's one PAR of a run is (its entries past whirl's parameters zero
 * at first, then what the user's routines leave there), so that a call
 * copies whirl's wa_npar values alone.  Clearing the whole array at every
 * call was 18 % of demo man's time (a FUNC of three lines, called by its
 * ICND too); a PAR longer than the buffer is the caller's, cleared. */
enum { WA_PAR_KEPT = 256 };
static __thread double kept_par[WA_PAR_KEPT]; /* zero in every new thread */

/* The calling thread's kept_par, its address looked up once: where the
 * copy below is inlined, GCC recomputes a thread-local address at each use
 * (a __tls_get_addr call a pair in a plug-in). */
__attribute__((noinline)) static double *thread_par(void) { return kept_par; }

static double *call_par(double *own, const double *p) {
  if (wa_nparx > WA_PAR_KEPT) {
    load_par(own, p);
    return own;
  }
  /* one double at a time: the caller has just stored the parameter it
   * perturbs, and a 16-byte load across that 8-byte store waits for it
   * to reach the cache (no store forwarding; memcpy's vector loads and a
   * vectorised copy did, 5-8 % of demo fnc's run); volatile keeps the
   * loads scalar and the loop from becoming a memcpy call */
  const volatile double *vp = p;
  double *kp = thread_par();
  for (int i = 0; i < wa_npar; ++i) kp[i] = vp[i];
  return kp;
}

/* The run's ICP, which FUNC, BCND and ICND get as AUTO's do.  PVLS is
 * called once here, before the run, as AUTO calls it after the start: some
 * set up data there that FUNC reads (brc, brf); a boundary-value problem's
 * first PVLS gets its solution instead (pcl's GETP reads it), not this. */
void wa_set_icp(const int *c, size_t n, const int k[4], void *d) {
  static int first = 1;
  (void)d;
  memset(wa_icp, 0, (size_t)wa_nparx * sizeof *wa_icp);
  for (size_t i = 0; i < n && i < (size_t)wa_nparx; i++) wa_icp[i] = c[i];
  memcpy(counts, k, sizeof counts);
  if (first && pvls_ && counts[2] + counts[3] == 0) {
    double par[wa_nparx];
    load_par(par, wa_par0);
    pvls_(&wa_ndim, wa_u0, par);
  }
  first = 0;
}

static int call(const double *x, const double *p, int ijac, double *f, double *dfdu) {
  double own[wa_nparx > WA_PAR_KEPT ? wa_nparx : 1], dfdp[wa_ndim * wa_nparx],
      df[dfdu ? 1 : wa_ndim * wa_ndim];
  func_(&wa_ndim, x, wa_icp, call_par(own, p), &ijac, f, dfdu ? dfdu : df, dfdp);
  return 0;
}

int wa_rhs(double t, const double *x, const double *p, double *f, void *d) {
  (void)t, (void)d;
  return call(x, p, 0, f, NULL);
}

int wa_jac(double t, const double *x, const double *p, double *J, void *d) {
  double f[wa_ndim];
  (void)t, (void)d;
  memset(J, 0, (size_t)(wa_ndim * wa_ndim) * sizeof *J);
  return call(x, p, 1, f, J);
}

int wa_stpnt(double tau, double *u, double *p, void *d) {
  double par[wa_nparx];
  (void)d;
  load_par(par, p);
  stpnt_(&wa_ndim, u, par, &tau);
  memcpy(p, par, (size_t)wa_npar * sizeof *p);
  return 0;
}

/* LAPACK's eigenvalue routine, from the process (whirl links LAPACK); weak:
 * a plug-in loaded where it is not gets no eigenvalues (GETP('EIG') 0) */
void dgeev_(const char *, const char *, const int *, double *, const int *, double *,
            double *, double *, const int *, double *, const int *, double *, const int *,
            int *, size_t, size_t) __attribute__((weak));

/* The equilibrium whose PVLS is running, for GETP('EIG'): its state and
 * whirl's parameters, and its eigenvalues once asked for (eig_state 1; -1
 * when they could not be computed) */
static const double *eig_x, *eig_p;
static double *eig_re, *eig_im;
static int eig_state;

/* The Jacobian at the point by central differences, as AUTO's (step
 * 1e-7 (1 + max |U(i)|), its HMACH), column-major into A[n n]. */
static void eig_jacobian(double *A) {
  const int n = wa_ndim;
  double u[n], fp[n], fm[n], umax = 0;
  memcpy(u, eig_x, (size_t)n * sizeof *u);
  for (int i = 0; i < n; i++) umax = fmax(umax, fabs(u[i]));
  const double ep = 1e-7 * (1 + umax);
  for (int j = 0; j < n; j++) {
    const double uj = u[j];
    u[j] = uj + ep;
    call(u, eig_p, 0, fp, NULL);
    u[j] = uj - ep;
    call(u, eig_p, 0, fm, NULL);
    u[j] = uj;
    for (int i = 0; i < n; i++) A[i + n * j] = (fp[i] - fm[i]) / (2 * ep);
  }
}

/* AUTO's order of the eigenvalues (its STABEQ, AUTO-07p's equilibrium
 * module): by decreasing real part, the last of equal ones first; where a
 * system looks conservative (even n, trace below 1e-7 of the largest
 * entry), eigenvalues within 1e-5 of the imaginary axis among themselves
 * by decreasing |imaginary part|.  PVLS reads them in this order (r3b puts
 * the periods of the purely imaginary ones into PAR(5..7)). */
static void eig_order(const double *A, double *re, double *im) {
  const int n = wa_ndim;
  double tol = 0, trace = 0, amax = 0;
  if (n % 2 == 0) {
    for (int i = 0; i < n; i++) trace += A[i + n * i];
    for (int i = 0; i < n * n; i++) amax = fmax(amax, fabs(A[i]));
    if (fabs(trace) < 1e-7 * amax) tol = 1e-5;
  }
  for (int i = 0; i < n - 1; i++) {
    int loc = i;
    for (int j = i + 1; j < n; j++) {
      if (fabs(re[j]) < tol && fabs(re[loc]) < tol) {
        if (fabs(im[j]) >= fabs(im[loc])) loc = j;
      } else if (re[j] >= re[loc]) {
        loc = j;
      }
    }
    const double tr = re[i], ti = im[i];
    re[i] = re[loc], im[i] = im[loc];
    re[loc] = tr, im[loc] = ti;
  }
}

/* The eigenvalues of the running PVLS's equilibrium, computed once: 0, or
 * -1 where there are none (LAPACK absent or failing, a non-finite
 * Jacobian). */
static int eig_compute(void) {
  if (eig_state) return eig_state > 0 ? 0 : -1;
  const int n = wa_ndim, lw = 8 * n, one = 1;
  double A[n * n], J[n * n], work[lw], vd[1];
  int info = -1;
  eig_state = -1;
  if (!dgeev_) return -1;
  eig_jacobian(A);
  for (int i = 0; i < n * n; i++)
    if (!isfinite(A[i])) return -1;
  memcpy(J, A, sizeof J);
  dgeev_("N", "N", &n, A, &n, eig_re, eig_im, vd, &one, vd, &one, work, &lw, &info, 1, 1);
  if (info != 0) return -1;
  eig_order(J, eig_re, eig_im);
  eig_state = 1;
  return 0;
}

/* PVLS at an equilibrium: the parameters it sets */
int wa_pvls(const double *x, double *p, void *d) {
  double par[wa_nparx], re[wa_ndim], im[wa_ndim];
  (void)d;
  if (!pvls_) return 0;
  load_par(par, p);
  eig_x = x, eig_p = p, eig_re = re, eig_im = im, eig_state = 0;
  pvls_(&wa_ndim, x, par);
  eig_x = eig_p = NULL, eig_re = eig_im = NULL;
  memcpy(p, par, (size_t)wa_npar * sizeof *p);
  return 0;
}

/* the solution PVLS is called on (wa_pvls_solution), for GETP */
static const double *sol_u, *sol_w;
static size_t sol_nn;

/* GETP's measures over the solution (sol_u: node values, sol_w:
 * quadrature weights) of U(ic) */
static double solution_measure(const char *k, int ic) {
  const size_t n = (size_t)wa_ndim;
  const double *v = sol_u + ic - 1;
  if (!strcmp(k, "BV0")) return v[0];
  if (!strcmp(k, "BV1")) return v[n * (sol_nn - 1)];
  const int max = !strcmp(k, "MAX"), min = !strcmp(k, "MIN"), nrm = !strcmp(k, "NRM");
  double s = 0, m = v[0];
  for (size_t j = 0; j < sol_nn; j++) {
    const double x = v[n * j];
    if (max ? x > m : min && x < m) m = x;
    s += sol_w[j] * (nrm ? x * x : x);
  }
  if (max || min) return m;
  if (!strcmp(k, "INT")) return s;
  return nrm ? sqrt(s) : 0.0;
}

/* PVLS's utility GETP(CODE, IC, U), as AUTO's (AUTO-07p manual, ch. 4):
 * at an equilibrium NRM |U(IC)|, INT, MAX, MIN, BV0, BV1 U(IC), and EIG
 * the real (IC odd) or imaginary part (IC even) of eigenvalue (IC + 1) / 2
 * of the Jacobian, in AUTO's order (eig_order); on a
 * solution by collocation NRM the L2 norm and INT the integral of U(IC)
 * over [0, 1], MAX and MIN over the nodes, BV0 and BV1 at t = 0 and 1
 * (EIG there, AUTO's Floquet multipliers, is 0: whirl does not hand them
 * to PVLS); NDIM for NDI; NTST, NCOL, NBC, NINT for NTS, NCO, NBC, NIN;
 * else 0.
 * L is the length of CODE (gfortran's hidden argument). */
double getp_(const char *c, const int *i, const double *u, size_t l) {
  static const char *const cn[4] = {"NTS", "NCO", "NBC", "NIN"};
  char k[4] = {0};
  for (size_t j = 0; j < 3 && j < l; j++)
    k[j] = (char)(c[j] >= 'a' && c[j] <= 'z' ? c[j] - 32 : c[j]);
  const int ic = *i;
  if (!strcmp(k, "NDI") || !strcmp(k, "NDX")) return wa_ndim;
  for (int q = 0; q < 4; q++)
    if (!strcmp(k, cn[q])) return counts[q];
  if (!strcmp(k, "EIG")) {
    if (!eig_x || ic < 1 || ic > 2 * wa_ndim || eig_compute() != 0) return 0.0;
    return ic % 2 ? eig_re[(ic - 1) / 2] : eig_im[ic / 2 - 1];
  }
  if (ic < 1 || ic > wa_ndim) return 0.0;
  if (sol_u) return solution_measure(k, ic);
  if (!strcmp(k, "NRM")) return fabs(u[ic - 1]);
  if (!strcmp(k, "INT") || !strcmp(k, "MAX") || !strcmp(k, "MIN") || !strcmp(k, "BV0") ||
      !strcmp(k, "BV1"))
    return u[ic - 1];
  return 0.0;
}

/* PVLS on a solution by collocation: U is its node values, node-major,
 * which is AUTO's UPS(NDIM*NCOL, NTST+1) in memory */
int wa_pvls_solution(const double *u, size_t nn, const double *w, double *p, void *d) {
  double par[wa_nparx];
  (void)d;
  if (!pvls_) return 0;
  load_par(par, p);
  sol_u = u, sol_w = w, sol_nn = nn;
  pvls_(&wa_ndim, u, par);
  sol_u = sol_w = NULL;
  memcpy(p, par, (size_t)wa_npar * sizeof *p);
  return 0;
}

/* BCND and ICND with IJAC = 0: their DBC, DINT are not written */
int wa_bcnd(size_t nbc, const double *u0, const double *u1, const double *p, double *fb,
            void *d) {
  double own[wa_nparx > WA_PAR_KEPT ? wa_nparx : 1], db[1];
  const int nb = (int)nbc, ijac = 0;
  (void)d;
  if (!bcnd_) return -1;
  bcnd_(&wa_ndim, call_par(own, p), wa_icp, &nb, u0, u1, fb, &ijac, db);
  return 0;
}

int wa_icnd(size_t nint, const double *u, const double *uo, const double *ud,
            const double *upo, const double *p, double *fi, void *d) {
  double own[wa_nparx > WA_PAR_KEPT ? wa_nparx : 1], di[1];
  const int ni = (int)nint, ijac = 0;
  (void)d;
  if (!icnd_) return -1;
  icnd_(&wa_ndim, call_par(own, p), wa_icp, &ni, u, uo, ud, upo, fi, &ijac, di);
  return 0;
}

/* par0 and u0 from STPNT at T = 0, and the period of its orbit, PAR(11) */
__attribute__((constructor)) static void init(void) {
  double par[wa_nparx], t = 0;
  memset(par, 0, sizeof par);
  stpnt_(&wa_ndim, wa_u0, par, &t);
  memcpy(wa_par0, par, (size_t)wa_npar * sizeof *par);
  /* a STPNT that extends a restart (NDIM above the data's: demo pcl) may
   * give NaN here, with no data; a run from STPNT calls it again */
  for (int i = 0; i < wa_ndim; i++)
    if (!isfinite(wa_u0[i])) wa_u0[i] = 0;
  whirl_model_def.period0 = wa_nparx > 10 && par[10] > 0 ? par[10] : 0;
}

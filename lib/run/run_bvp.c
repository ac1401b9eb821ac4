/* lib/run/run_bvp.c — boundary-value problems in a run (AUTO's IPS = 4):
 * the model's BCND and ICND as the conditions of whirl_bvp (whirl/bvp.h),
 * its free parameters from ICP (AUTO's NFPR = NBC + NINT − NDIM + 1: ICP(1)
 * continued, ICP(2) ... ICP(NFPR) unknowns, any further ICP entries shown
 * only), and the start from the model's STPNT(T) at the mesh's nodes or
 * from a labelled solution, on its mesh or resampled onto the run's.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run_impl.h"

static int bc_of_model(const double *u0, const double *u1, const double *p, double *fb,
                       void *data) {
  const run_ctx *R = data;
  return R->model->bcnd((size_t)R->s->nbc, u0, u1, p, fb, R->model->problem.data);
}

static int ic_of_model(const double *u, const double *uold, const double *udot,
                       const double *upold, const double *p, double *fi, void *data) {
  const run_ctx *R = data;
  return R->model->icnd((size_t)R->s->nint, u, uold, udot, upold, p, fi,
                        R->model->problem.data);
}

/* The model's STPNT at t (whirl_bvp_from_function's start). */
static int start_of_model(double t, double *u, double *p, void *d) {
  const run_ctx *R = d;
  return R->model->stpnt(t, u, p, R->model->problem.data);
}

/* A stored solution at t on its own mesh (a restart onto another mesh). */
typedef struct stored_orbit {
  const whirl_bvp *src;
  const double *x;
} stored_orbit;

static int start_of_label(double t, double *u, double *p, void *d) {
  const stored_orbit *o = d;
  (void)p;
  return whirl_bvp_eval(o->src, o->x, t, u);
}

/* The options of the run's problem on a mesh of ntst x ncol; free[] the
 * free parameters (ICP(2) ...).  0, or -2 (said). */
static int bvp_options(run_ctx *R, size_t ntst, size_t ncol, size_t *free,
                       whirl_bvp_options *o) {
  const whirl_run_settings *s = R->s;
  const long nf = (long)s->nbc + (long)s->nint - (long)R->n;
  whirl_bvp_options_default(o);
  if (nf < 0) {
    run_fail(R, WHIRL_RK_NBC, "IPS = 4: NBC + NINT = %d is less than NDIM = %zu "
             "(AUTO: NBC + NINT - NDIM + 1 free parameters, at least the "
             "continued one)", s->nbc + s->nint, R->n);
    return -2;
  }
  if (nf > WHIRL_SOL_MAXFREE) {
    run_fail(R, WHIRL_RK_NBC, "IPS = 4: NBC + NINT - NDIM = %ld free parameters beside "
             "the continued one; whirl has at most %d", nf, WHIRL_SOL_MAXFREE);
    return -2;
  }
  if ((size_t)nf + 1 > R->nicp) {
    run_fail(R, WHIRL_RK_ICP, "ICP: IPS = 4 with NBC = %d, NINT = %d, NDIM = %zu has "
             "NBC + NINT - NDIM + 1 = %ld free parameters; ICP lists %zu", s->nbc,
             s->nint, R->n, nf + 1, R->nicp);
    return -2;
  }
  if ((s->nbc && !R->model->bcnd) || (s->nint && !R->model->icnd)) {
    run_fail(R, s->nbc && !R->model->bcnd ? WHIRL_RK_NBC : WHIRL_RK_NINT,
             "IPS = 4: model '%s' has no %s (NBC = %d, NINT = %d)", R->prob.name,
             s->nbc && !R->model->bcnd ? "boundary conditions (bcnd, AUTO's BCND)"
                                       : "integral conditions (icnd, AUTO's ICND)",
             s->nbc, s->nint);
    return -2;
  }
  for (size_t j = 0; j < (size_t)nf; j++) free[j] = (size_t)R->icp[j + 1];
  o->ntst = ntst;
  o->ncol = ncol;
  o->nbc = (size_t)s->nbc;
  o->nint = (size_t)s->nint;
  o->bc = bc_of_model;
  o->ic = ic_of_model;
  o->data = R;
  o->nfree = (size_t)nf;
  o->free = free;
  o->adapt_every = s->iad; /* AUTO's IAD: a new mesh every IAD steps */
  o->threads = s->threads; /* THREADS: 0, OpenMP's default (as orbits) */
  o->auto_differences = s->auto_differences; /* DIFFERENCES = auto */
  o->udot_direction = s->udot_direction;     /* UDOT = direction */
  return 0;
}

/* The run file's PAR over the parameters STPNT set (as for the other
 * problem classes, run_model.c). */
static void apply_run_file_par(run_ctx *R) {
  for (size_t i = 0; i < R->s->npar; i++)
    R->par[run_par_index(R, &R->s->par[i].ref)] = R->s->par[i].value;
}

/* Does the label so's branch have the run's free parameters, the
 * continued one and the others in the same order?  Its tangent is a
 * direction in (x, those parameters); with another set (c.obv.3 frees
 * PAR(2) where its label's branch had PAR(16)) it is no direction of the
 * new problem, and the branch starts from the new problem's null vector,
 * as AUTO's STPNBV1 decides (NODIR when NFPR or any ICP(i) differs). */
static int same_free_parameters(const whirl_solution *so, int icp,
                                const whirl_bvp_options *o) {
  if (so->icp != icp || (size_t)so->nfree != o->nfree) return 0;
  for (size_t j = 0; j < o->nfree; j++)
    if ((size_t)so->free_par[j] != o->free[j]) return 0;
  return 1;
}

/* A label read with more state components than it had (a restart with a
 * larger NDIM): the new components from the model's stpnt at every node,
 * called with the stored ones and zeros (AUTO-07p io.f90, READBV: "system
 * is extended; call STPNT for extension"; demo pcl adds its Floquet
 * bundle and Lin vectors so), the stored ones and the parameters kept.
 * The values into x[nx] (a copy of so->x).  0 or -1. */
static int extend_state(run_ctx *R, const whirl_solution *so, double *x) {
  memcpy(x, so->x, so->nx * sizeof *x);
  const size_t k = so->nstate_stored, n = R->n, M = (size_t)so->ncol;
  if (!k || !R->model->stpnt) return 0;
  double *u = malloc(n * sizeof *u), *p = malloc(R->npar * sizeof *p);
  int rc = u && p ? 0 : -1;
  for (size_t i = 0; !rc && i < (size_t)so->ntst; i++)
    for (size_t m = 0; m <= M && !rc; m++) {
      if (m == M && i + 1 < (size_t)so->ntst) continue; /* the next interval's first */
      const size_t j = i * M + m;
      const double h = so->mesh[i + 1] - so->mesh[i], t = so->mesh[i] + h * (double)m / (double)M;
      memcpy(u, x + n * j, n * sizeof *u);
      memcpy(p, R->par, R->npar * sizeof *p);
      if (R->model->stpnt(t, u, p, R->prob.data) != 0) rc = -1;
      for (size_t c = k; !rc && c < n; c++) x[n * j + c] = u[c];
    }
  free(u);
  free(p);
  if (rc) run_say(R, "IRS: label %d: the model's stpnt failed extending it to NDIM = %zu",
                  so->label, n);
  return rc;
}

/* The start X from a label so: on its mesh, or resampled from it — and
 * its tangent into D when it has one fitting the run (*tan set): a restart
 * goes on along the branch as AUTO's does, onto another NTST too, and a
 * switch at a BP (ISW = -1) starts from it. */
static int start_on_mesh(run_ctx *R, const whirl_solution *so, const double *x,
                         whirl_bvp *bvp, const whirl_bvp_options *o, double *X, double *D,
                         int tan);

static int start_from_label(run_ctx *R, const whirl_solution *so, whirl_bvp *bvp,
                            const whirl_bvp_options *o, double *X, double *D, int *tan) {
  *tan = so->kind == WHIRL_SOL_BVP && so->tan && same_free_parameters(so, R->icp[0], o);
  const int orbit = so->kind == WHIRL_SOL_COLLOC && (size_t)so->nstate == R->n;
  if (so->kind != WHIRL_SOL_BVP && !orbit) {
    run_fail(R, WHIRL_RK_IRS, "IRS: label %d is %s; IPS = 4 restarts from a "
             "boundary-value solution or a periodic orbit by collocation", so->label,
             so->kind == WHIRL_SOL_EQ ? "an equilibrium" : "an orbit of another kind");
    return -2;
  }
  /* an orbit is a solution on [0, 1] like any other (AUTO's ph1, pcl): its
   * period is AUTO's PAR(11), which the boundary conditions may free */
  if (orbit && so->aut && R->npar >= 11) R->par[10] = so->x[so->nx - 1];
  double *ext = malloc(so->nx * sizeof *ext);
  if (!ext || extend_state(R, so, ext)) {
    free(ext);
    return -1;
  }
  int rc = start_on_mesh(R, so, ext, bvp, o, X, D, *tan);
  free(ext);
  return rc;
}

/* start_from_label's copy or resampling of the node values x (so's,
 * extended).  0 or -1. */
static int start_on_mesh(run_ctx *R, const whirl_solution *so, const double *x,
                         whirl_bvp *bvp, const whirl_bvp_options *o, double *X, double *D,
                         int tan) {
  const size_t nb = whirl_bvp_size(bvp);
  char err[512];
  if ((size_t)so->ntst == o->ntst && (size_t)so->ncol == o->ncol) {
    memcpy(X, x, R->n * (o->ntst * o->ncol + 1) * sizeof *X);
    if (tan) memcpy(D, so->tan, (nb + 1) * sizeof *D);
    whirl_bvp_set_mesh(bvp, so->mesh);
    return 0;
  }
  whirl_bvp_options os = *o;
  os.ntst = (size_t)so->ntst;
  os.ncol = (size_t)so->ncol;
  whirl_bvp *src = whirl_bvp_alloc(&R->prob, &os, err, sizeof err);
  if (!src) {
    run_say(R, "IRS: label %d: %s", so->label, err);
    return -1;
  }
  whirl_bvp_set_mesh(src, so->mesh);
  /* onto the mesh AUTO's ADAPT2 makes from the label (STPNBV): not a
   * uniform one, which loses a boundary layer (spb's c.spb.2 from its
   * epsilon = 1e-3 onto NTST 200: Newton failed at the start) */
  if (whirl_bvp_mesh_from(bvp, (size_t)so->ntst, (size_t)so->ncol, so->mesh, x)) {
    run_say(R, "IRS: label %d onto NTST = %zu: %s", so->label, o->ntst, whirl_bvp_errmsg(bvp));
    whirl_bvp_free(src);
    return -1;
  }
  stored_orbit st = {src, x};
  double *p = malloc(R->npar * sizeof *p);
  int rc = p ? WHIRL_OK : WHIRL_ENOMEM;
  if (!rc) memcpy(p, R->par, R->npar * sizeof *p);
  if (!rc) rc = whirl_bvp_from_function(bvp, start_of_label, &st, X, p);
  if (!rc && tan) { /* the tangent's node part resampled likewise */
    st.x = so->tan;
    rc = whirl_bvp_from_function(bvp, start_of_label, &st, D, p);
    const size_t sn = so->nx - (size_t)so->nfree, dn = nb - o->nfree;
    for (size_t j = 0; !rc && j < o->nfree; j++) D[dn + j] = so->tan[sn + j];
    D[nb] = so->tan[so->nx];
  }
  free(p);
  whirl_bvp_free(src);
  return rc ? -1 : 0;
}

/* AUTO calls PVLS on the restart solution before the first step, and the
 * parameters it sets are the run's start values, free ones included: demo
 * pcl's PVLS puts the Lin gap and vector into eta, Zx, Zy, from which its
 * run 7 closes the gap (UZR eta = 0). */
static void start_pvls(run_ctx *R, whirl_bvp *bvp, const double *X, size_t nnodes) {
  if (run_pvls_solution(R->model, whirl_bvp_system(bvp), X, nnodes, R->par))
    apply_run_file_par(R); /* the run file's PAR still overrides (AUTO) */
}

int run_bvp_start(run_ctx *R, const whirl_solution *so, whirl_bvp **bvp, double **X,
                  double **D, branch_spec *b) {
  const whirl_run_settings *s = R->s;
  char err[512];
  size_t *free_par = malloc((R->nicp + 1) * sizeof *free_par);
  if (!free_par) return -1;
  whirl_bvp_options o;
  int rc = bvp_options(R, (size_t)s->ntst, (size_t)s->ncol, free_par, &o);
  if (!rc && !(*bvp = whirl_bvp_alloc(&R->prob, &o, err, sizeof err))) {
    run_say(R, "boundary-value problem: %s", err);
    rc = -1;
  }
  const size_t nb = *bvp ? whirl_bvp_size(*bvp) : 0;
  if (!rc && (!(*X = calloc(nb + 1, sizeof **X)) || !(*D = calloc(nb + 1, sizeof **D))))
    rc = -1;
  int tan = 0;
  if (!rc && so) {
    rc = start_from_label(R, so, *bvp, &o, *X, *D, &tan);
  } else if (!rc && s->dat[0]) { /* AUTO's STPNUB from a data file */
    if (run_dat_bvp(R, *bvp, *X)) rc = -1;
    apply_run_file_par(R);
  } else if (!rc) {
    if (!R->model->stpnt) {
      run_fail(R, WHIRL_RK_IPS, "IPS = 4 starts from the model's start solution "
               "(stpnt, AUTO's STPNT(T)) or a label (IRS); model '%s' has no stpnt",
               R->prob.name);
      rc = -2;
    } else if (whirl_bvp_from_function(*bvp, start_of_model, R, *X, R->par)) {
      run_say(R, "start: %s", whirl_bvp_errmsg(*bvp));
      rc = -1;
    }
    apply_run_file_par(R);
  }
  if (!rc) {
    const size_t n0 = R->n * ((size_t)s->ntst * (size_t)s->ncol + 1);
    if (so) start_pvls(R, *bvp, *X, n0 / R->n);
    for (size_t j = 0; j < o.nfree; j++) (*X)[n0 + j] = R->par[free_par[j]];
    whirl_bvp_set_reference(*bvp, *X);
    /* along the stored tangent, as for the other classes
     * (run_tangent_start); the sign of DS is applied by the caller.  At a
     * BP (ISW = -1) the switch starts from it, resampled onto the run's
     * mesh (before, the label's own array was read with the run's size:
     * past its end on another NTST, c.lin.2) */
    if (tan) b->tan0 = *D;
    if (tan && s->isw == 1) b->dir = *D;
    b->kind = WHIRL_SOL_BVP;
    b->bvp = *bvp;
    b->sys = whirl_bvp_system(*bvp);
    b->nb = nb;
    b->nnodes = n0 / R->n;
    b->x0 = *X;
    b->p0 = R->par;
    b->ds_scale = 1.0; /* the system's norm weights: AUTO's integral norm */
    if (o.nfree) {
      fprintf(R->log, "boundary-value problem: NBC = %d, NINT = %d, free", s->nbc, s->nint);
      for (size_t j = 0; j < o.nfree; j++) fprintf(R->log, " %s", R->pnames[free_par[j]]);
      fputc('\n', R->log);
    }
  }
  free(free_par);
  return rc;
}

void run_bvp_orient(const run_ctx *R, const branch_spec *b, const double *X,
                    const double *p, double *t) {
  const whirl_run_settings *s = R->s;
  const size_t nb = b->nb, nodes = b->nnodes * R->n; /* the node values */
  const size_t nfree = nb - nodes, last = nodes - R->n; /* free parameters; u(1) */
  double key = 0.0;
  if (fabs(t[nb]) > s->epsl * (1.0 + fabs(p[b->icp]))) key = t[nb];
  for (size_t j = 0; key == 0.0 && j < nfree; j++)
    if (fabs(t[nodes + j]) > s->epsl * (1.0 + fabs(X[nodes + j]))) key = t[nodes + j];
  for (size_t i = 0; key == 0.0 && i < R->n; i++)
    if (fabs(t[last + i]) > s->epsu * (1.0 + fabs(X[last + i]))) key = t[last + i];
  const double sg = (key < 0.0 ? -1.0 : 1.0) * (s->ds < 0 ? -1.0 : 1.0);
  for (size_t i = 0; i <= nb; i++) t[i] *= sg;
}

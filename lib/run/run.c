/* lib/run/run.c — a run of a run file (whirl/run.h): build the problem
 * the run asks for out of the library's constructors, continue it and
 * write the branch table, the labelled solutions and the log:
 *
 *   branches.tsv   branch pt type label, parameters, norms, state, stable (doc/tables.md)
 *   solutions      labelled solutions, full precision, restartable (IRS)
 *   run.log        diagnostics: settings, model, steps, stop reasons
 *
 * Problems (AUTO-07p manual, ch. 10, IPS/ISW):
 *   IPS 1, ISW 1      equilibria from the model's start or a label
 *   IPS 1, ISW -1     branch switching at a BP
 *   IPS 1, ISW 2      fold (LP) or Hopf (HB) locus in two parameters
 *   IPS 2             periodic orbits (METHOD colloc | hbm): from the
 *                     model's start orbit, a settled forced response, an HB
 *                     label (Hopf start) or a periodic label
 *   IPS 2, ISW -1     period doubling (PD) or BP switching
 *   IPS 2, ISW 2      fold of periodic orbits (LP of cycles)
 *   IPS basins        basins of attraction (run_basins.c)
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "run_impl.h"


void run_fail(run_ctx *R, whirl_run_key k, const char *fmt, ...) {
  char where[4200], msg[4600];
  va_list ap;
  va_start(ap, fmt);
  whirl_errmsg_vat(msg, sizeof msg, 0, whirl_runfile_where(R->rf, k, where, sizeof where), fmt, ap);
  va_end(ap);
  run_say(R, "%s", msg);
}

void run_say(run_ctx *R, const char *fmt, ...) {
  char msg[4600];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (!R->errmsg[0]) snprintf(R->errmsg, sizeof R->errmsg, "%s", msg);
  if (R->io.message) R->io.message(msg, R->io.ctx);
}

void run_summary(run_ctx *R, const char *fmt, ...) {
  char line[2048];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(line, sizeof line, fmt, ap);
  va_end(ap);
  if (R->io.summary) R->io.summary(line, R->io.ctx);
}

FILE *run_open(run_ctx *R, const char *name) {
  if (R->io.open) return R->io.open(name, R->io.ctx);
  char p[8300];
  if (mkdir(R->out, 0777) != 0 && errno != EEXIST) {
    run_say(R, "cannot create '%s': %s", R->out, strerror(errno));
    return NULL;
  }
  snprintf(p, sizeof p, "%s/%s", R->out, name);
  FILE *f = fopen(p, "w");
  if (!f) run_say(R, "cannot write %s: %s", p, strerror(errno));
  return f;
}

int run_close(run_ctx *R, FILE *f, const char *name) {
  if (!f) return -1;
  if (R->io.close) return R->io.close(f, name, R->io.ctx);
  int bad = fflush(f) != 0 || ferror(f);
  if (fclose(f) != 0) bad = 1;
  if (bad) run_say(R, "writing %s/%s failed", R->out, name);
  return bad ? -1 : 0;
}

double run_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- one branch --------------------------------------------------------- */


int run_pvls_solution(const whirl_model *m, const whirl_system *sys, const double *Z,
                      size_t nnodes, double *par) {
  const size_t n = m->problem.n;
  if (!m->pvls_solution || !sys->norm_weights || !nnodes) return 0;
  double *q = malloc(sys->n * sizeof *q), *w = malloc(nnodes * sizeof *w);
  int done = 0;
  if (q && w && sys->norm_weights(q, sys->data) == 0) {
    for (size_t j = 0; j < nnodes; j++) w[j] = q[n * j]; /* then the period, free parameters */
    done = m->pvls_solution(Z, nnodes, w, par, m->problem.data) == 0;
  }
  free(q);
  free(w);
  return done;
}

static void base_of(const branch_spec *b, const double *Z, const double *p,
                    double *pfull) {
  if (b->fold)
    whirl_fold_params(b->fold, Z, p, pfull);
  else if (b->hopf)
    whirl_hopf_params(b->hopf, Z, p, pfull);
  else if (b->bploc)
    whirl_bploc_params(b->bploc, Z, p, pfull);
  else if (b->trloc)
    whirl_trloc_params(b->trloc, Z, p, pfull);
  else if (b->kind == WHIRL_SOL_COLLOC)
    whirl_colloc_params(b->colloc, Z, p, pfull); /* a fixed period's parameter */
  else if (b->kind == WHIRL_SOL_BVP)
    whirl_bvp_params(b->bvp, Z, p, pfull); /* the free parameters */
  else
    memcpy(pfull, p, b->sys->npar * sizeof *pfull);
  /* the model's derived parameters (AUTO's PVLS) at an equilibrium, or
   * on a collocation solution (orbit, boundary-value problem) — on a
   * locus too, from its base solution, the locus's first unknowns (AUTO
   * calls PVLS at every point: tfc's PAR(7), PAR(8) = exp(min u1), exp(min
   * u2) along its loci of branch points) */
  if (!b->model) return;
  if (b->kind == WHIRL_SOL_EQ && b->model->pvls)
    b->model->pvls(Z, pfull, b->model->problem.data);
  else if (b->kind == WHIRL_SOL_COLLOC || b->kind == WHIRL_SOL_BVP) {
    const whirl_system *base = b->sys;
    if (b->fold || b->hopf || b->bploc || b->trloc)
      base = b->kind == WHIRL_SOL_COLLOC ? whirl_colloc_system(b->colloc) : whirl_bvp_system(b->bvp);
    run_pvls_solution(b->model, base, Z, b->nnodes, pfull);
  }
}

/* The quantity a UZR/UZSTOP value refers to (whirl_cont_options.uz_fun). */
typedef struct uz_ctx {
  run_ctx *R;
  const branch_spec *b;
  int what[2 * WHIRL_RUN_MAXITEMS]; /* >= 0 parameter, -1 period, -2 - i state i */
  double *pfull, *state;
} uz_ctx;

static double uz_quantity(size_t k, const double *x, const double *p, void *ctx) {
  uz_ctx *u = ctx;
  const branch_spec *b = u->b;
  const int w = u->what[k];
  base_of(b, x, p, u->pfull);
  if (w >= 0) return u->pfull[w];
  if (b->kind == WHIRL_SOL_EQ) return x[-2 - w];
  const void *obj = b->kind == WHIRL_SOL_COLLOC ? (const void *)b->colloc
                    : b->kind == WHIRL_SOL_BVP  ? (const void *)b->bvp
                                                : (const void *)b->hbm;
  if (w == -1) {
    const whirl_periodic po = run_periodic(b->kind, obj);
    return whirl_periodic_period(&po, x, u->pfull);
  }
  double l2, period;
  if (run_point_measures(u->R, b->kind, obj, x, u->pfull, &l2, &period, u->state))
    return NAN;
  return u->state[-2 - w];
}

/* The continuation options of the run file (AUTO's constants) for branch
 * b, with its user points and stops (UZR, UZSTOP) on any quantity: values
 * of a parameter, of the period or of a state component.  0, or -2 (a
 * name that is none of these, said). */
static int branch_options(run_ctx *R, const branch_spec *b, whirl_cont_options *o,
                          double *uz, int *uz_stop, uz_ctx *uc) {
  const whirl_run_settings *s = R->s;
  whirl_cont_options_default(o);
  o->icp = (size_t)b->icp;
  /* AUTO's first steps take DS as given, past DSMAX too (RDS = DS; only
   * ADPTDS clips to DSMAX): ab's c.ab.2 (DS 0.1, DSMAX 0.05) */
  o->ds = fmax(fabs(s->ds), s->dsmin) * b->ds_scale;
  o->ds_min = s->dsmin * b->ds_scale;
  o->ds_max = s->dsmax * b->ds_scale;
  o->nmx = (size_t)s->nmx;
  o->p_min = s->rl0;
  o->p_max = s->rl1;
  /* AUTO's test: the state to EPSU and its own scale, the parameter to
   * EPSL and its own */
  o->newton_tol = s->epsu;
  o->newton_tol_par = s->epsl;
  /* orbits and BVPs (NEWTONBV): the period and the other free parameters
   * (after the node values) to EPSL as parameters, the nodes to EPSU on
   * their largest value before the correction */
  if ((b->kind == WHIRL_SOL_COLLOC || b->kind == WHIRL_SOL_BVP) && !b->fold && !b->hopf &&
      !b->bploc && !b->trloc) {
    o->newton_par_tail = b->nb - b->nnodes * R->n;
    o->newton_scale_before = 1;
  }
  o->newton_maxit = s->itnw;
  /* AUTO's NWTN (0 unless the run file says) for orbits and BVPs; its
   * algebraic corrector (SOLVAE, EQ_STEP = sphere) takes a new Jacobian
   * every iteration */
  o->newton_full = b->kind == WHIRL_SOL_EQ && s->eq_sphere ? 0 : s->nwtn;
  /* the tangent and tests from the corrector's last factorisation, as
   * AUTO: a Jacobian and a factorisation fewer a step; with TANGENT =
   * iterate (whirl auto writes it) not refined, AUTO's direction vector:
   * two evaluations of F and a solve fewer (doc/auto-reference.md) */
  o->tangent_from_newton = s->tangent_iterate ? 2 : 1;
  /* AUTO's step control has no turn limit (ADPTDS counts Newton
   * iterations alone), and neither have run files since 2026-12-06: with
   * the stored secant of orbits and BVPs (whirl_point.dir) the 0.5 rad
   * that obv once needed only parted the step sequences from AUTO's (spb's
   * c.spb.3 halved its step at point 14 where AUTO's goes on, then 2 000
   * points to AUTO's 1 554; chu's c.chu.2 ended at PAR(1) = 11.070 where
   * AUTO's ends at 11.0844; doc/auto-reference.md, the turn limit) */
  o->max_angle = acos(-1.0); /* pi: no turn is rejected */
  /* AUTO's step sequence: a special point starts the next step, and
   * AUTO's algebraic problems (equilibria, maps and their loci) list the
   * point two steps from the start as their second (CNRLAE), unless the
   * start is a switch at a branch point (ISW = -1 stores it) */
  o->auto_steps = 1;
  /* LOCATE = auto: on from where AUTO's localisation to EPSS ends (whirl
   * auto writes converged: doc/auto-reference.md) */
  o->loc_epss = s->locate_auto ? s->epss : 0.0;
  o->loc_itmx = s->itmx;
  o->loc_count_epss = s->epss; /* the step after a located point: AUTO's */
  o->hide_first_step = b->kind == WHIRL_SOL_EQ && !b->bp && s->isw >= 0;
  /* ... and, with EQ_STEP = sphere (whirl auto writes it), algebraic
   * branches predict along the secant of the last two points, as orbits
   * and BVPs (CONTBV), but correct on the sphere of radius DS about the
   * last point (ae.f90's SOLVAE; its UDOT is that secant) where orbits and
   * BVPs keep the hyperplane; else along the tangent onto its hyperplane,
   * whirl's (before 2026-12-06 for AUTO's files too: the points of a
   * branch curved within a step were not AUTO's, auto_steps.sh; for run
   * files the hyperplane stays the default: with the sphere the SFD
   * rotor's discovery, discover_sfd.sh, lost its isola).  Orbits and
   * BVPs store with a point the direction of the step that reached it
   * (UDOTPS); an algebraic restart takes the tangent oriented by the
   * stored direction (STPRAE), so the tangent is stored there. */
  const int sphere = b->kind == WHIRL_SOL_EQ && s->eq_sphere;
  o->tangent_predictor = b->kind == WHIRL_SOL_EQ && !sphere;
  o->arclength_sphere = sphere;
  o->point_dir = b->kind == WHIRL_SOL_EQ ? WHIRL_DIR_TANGENT : WHIRL_DIR_PREDICTOR;
  o->start_as_given = b->as_given;
  o->lead = b->lead;
  o->detect_lp = s->ilp;
  /* ISP as AUTO-07p's CHECKSP (support.f90) reads it.  Equilibria and
   * maps: BP where ISP /= 0; HB and the loci's BT, ZH, GH, CP where ISP is
   * neither 0 nor 3 (a map's TR, its multipliers being its eigenvalues,
   * where ISP /= 0).  Orbits and boundary-value problems: BP where ISP is
   * 2 or 3, PD and TR where it is 2 or 4 (ISP = 1 computes the orbits'
   * multipliers, for the stability, and looks for none of them) */
  const int map = s->ips == WHIRL_IPS_MAP, ae = b->kind == WHIRL_SOL_EQ || map;
  o->detect_bp = ae ? s->isp != 0 : s->isp == 2 || s->isp == 3;
  o->detect_hb = ae ? s->isp != 0 && (s->isp != 3 || map) : s->isp == 2 || s->isp == 4;
  o->detect_pd = ae ? map && s->isp != 0 : s->isp == 2 || s->isp == 4;
  if (ae && !map && (s->isp == 0 || s->isp == 3)) o->detect_sys = 0;
  /* ISP = 0 disables "the computation of Floquet multipliers" (AUTO-07p
   * manual, ISP; with ISP = 1 they are computed), nor then the orbits'
   * stability */
  if (b->kind == WHIRL_SOL_COLLOC && s->isp == 0) o->stability = 0;
  /* AUTO's problem classes label as AUTO: a fold curve's isola centre
   * (IS) or merge (MG), a turning point of the curve in the continued
   * parameter, is AUTO's LP there (abcb's script restarts from that LP);
   * harmonic balance, whirl's own, keeps its IS and MG */
  if (b->kind != WHIRL_SOL_HBM) o->sys_skip = 1u << WHIRL_PT_IS | 1u << WHIRL_PT_MG;
  /* and AUTO's loci of orbits and of BVPs have the test functions of
   * bvp.f90 alone (LP, BP and the multipliers'), no codimension-two ones:
   * the turning point of abcb's fold locus of orbits in its continued
   * parameter is AUTO's LP, where whirl's cusp test labelled CP and the
   * LP at the same point gave way to it */
  if (b->kind == WHIRL_SOL_COLLOC || b->kind == WHIRL_SOL_BVP)
    o->sys_skip |= 1u << WHIRL_PT_CP | 1u << WHIRL_PT_BT | 1u << WHIRL_PT_ZH;
  if (b->starting_data) /* AUTO's bvp.f90: ISW = -2 sets ILP = ISP = 0 */
    o->detect_lp = o->detect_bp = o->detect_hb = o->detect_pd = o->detect_sys = 0;
  /* a sparse Jacobian on KLU from 100 unknowns: the loci of orbits (a
   * few hundred unknowns, no structured solver) take half the time they
   * took on the dense LU (doc/benchmarks.md, the sparse LU) */
  if (b->sys->Jp && b->sys->n > 100) o->linsol = WHIRL_LINSOL_SPARSE;
  /* user points (UZR) and stops (UZSTOP): values of a parameter, of the
   * period (PERIOD, AUTO's PAR(11)) or of a state component (its MAX for
   * periodic orbits), all localised by the core through uz_quantity */
  uc->R = R;
  uc->b = b;
  size_t nuz = 0;
  for (size_t i = 0; i < s->nuzr + s->nuzstop; i++) {
    const int is_stop = i >= s->nuzr;
    const whirl_run_value *u = is_stop ? &s->uzstop[i - s->nuzr] : &s->uzr[i];
    int k = run_par_index(R, &u->ref), xi;
    if (k >= 0) {
      uc->what[nuz] = k;
    } else if ((b->kind == WHIRL_SOL_COLLOC || b->kind == WHIRL_SOL_HBM) &&
               (!strcasecmp(u->ref.name, "PERIOD") ||
                                     u->ref.index == 11)) {
      uc->what[nuz] = -1;
    } else if ((xi = run_state_index(R, &u->ref)) >= 0 && !u->ref.index) {
      uc->what[nuz] = -2 - xi;
    } else {
      run_fail(R, is_stop ? WHIRL_RK_UZSTOP : WHIRL_RK_UZR,
               "%s: '%s' is neither a parameter, PERIOD (periodic orbits) nor "
               "a state component of model '%s'", is_stop ? "UZSTOP" : "UZR",
               u->ref.index ? "(index)" : u->ref.name, R->prob.name);
      return -2;
    }
    /* a value in both UZR and UZSTOP is one point, which stops (before,
     * two labels, the second a step after the first at the same value) */
    size_t j = 0;
    while (j < nuz && !(uc->what[j] == uc->what[nuz] && uz[j] == u->value)) j++;
    if (j < nuz) {
      uz_stop[j] |= is_stop;
      continue;
    }
    uz[nuz] = u->value;
    uz_stop[nuz++] = is_stop;
  }
  o->uz = uz;
  o->uz_stop = uz_stop;
  o->nuz = nuz;
  o->uz_fun = uz_quantity;
  o->uz_ctx = uc;
  return 0;
}

/* THL of parameter k (AUTO's default 1), or -1 when none is given. */
static double thl_of(const whirl_run_settings *s, run_ctx *R, int k) {
  for (size_t i = 0; i < s->nthl; i++)
    if (run_par_index(R, &s->thl[i].ref) == k) return s->thl[i].value;
  return -1;
}

/* A locus's own unknowns after its base's (xw[b->nb] ..): the label's
 * parameter by its THL (default 1), then the angle of a torus locus (1,
 * AUTO's PAR(12)) or a further freed parameter by the THL of the third
 * ICP. */
static void locus_weights(run_ctx *R, const branch_spec *b, double *xw) {
  const whirl_run_settings *s = R->s;
  const size_t N = b->sys->n;
  const double wq = thl_of(s, R, b->q);
  xw[b->nb] = sqrt(wq >= 0 ? wq : 1.0);
  for (size_t i = 0; i < R->nicp && b->nb + 1 < N; i++)
    if (R->icp[i] != b->q && R->icp[i] != b->icp) {
      const double w3 = thl_of(s, R, R->icp[i]);
      xw[b->nb + 1] = sqrt(w3 >= 0 ? w3 : 1.0);
    }
}

/* AUTO's arclength norm (AUTO-07p manual, THL, THU; bvp.f90, RNRMSQP):
 *   |(u, p)|^2 = sum_i THU_i int_0^1 u_i(t)^2 dt + sum_k THL_k p_k^2
 * over the state and every free parameter (the period of an autonomous
 * orbit is PAR(11), the free parameters of a boundary-value problem are
 * among them), weights of the squares, default 1, and THL = {11: 0} for
 * orbits without a THL key (AUTO's main.f90).  Collocation and BVP systems
 * weight their node values by the quadrature of the integral themselves
 * (whirl_system.norm_weights: on the current mesh, so an adapted mesh is
 * measured as AUTO measures it); this adds THU on the state and THL on the
 * continuation parameter, the period and a BVP's free parameters.  (Before,
 * the node values counted 1 each, about NTST NCOL + 1 times the integral,
 * with DS scaled by its square root: a step that mostly changes parameters
 * moved them sqrt(NTST NCOL + 1) times as far as AUTO's, 13 times on kar,
 * whose Newton then failed where its parameter crosses 0.)  Equilibria are
 * measured as AUTO's, and the loci of orbits and BVPs as their base, their
 * own unknowns by THL (locus_weights); the unknowns of loci of equilibria
 * and of harmonic balance keep weight 1.  0, -1 (memory), -2 (bad input, said);
 * *xw is NULL or malloc'd (the caller frees it after whirl_cont_alloc). */
static int branch_weights(run_ctx *R, const branch_spec *b, whirl_cont_options *o,
                          double **xw) {
  const whirl_run_settings *s = R->s;
  *xw = NULL;
  /* a locus of orbits or of a BVP whose system weighs the base's node
   * values (fold, branch-point, period-doubling and torus loci): its
   * base's unknowns as the base's own, then the locus's */
  const int locus = (b->fold || b->trloc) && b->sys->norm_weights;
  const int orbit_base = b->kind == WHIRL_SOL_COLLOC &&
                         (b->sys == whirl_colloc_system(b->colloc) || locus);
  const int bvp_base = b->kind == WHIRL_SOL_BVP && (b->sys == whirl_bvp_system(b->bvp) || locus);
  if (!s->nthl && !s->nthu && !orbit_base && !bvp_base) return 0;
  const int base = (b->kind == WHIRL_SOL_EQ && b->sys->n == R->n) || orbit_base || bvp_base;
  const int orbit = b->kind == WHIRL_SOL_COLLOC, aut = orbit && R->model->forcing_param < 0;
  /* at a fixed period X's last unknown is a parameter: its THL, not PERIOD's */
  const int fq = orbit ? whirl_colloc_free_param(b->colloc) : -1;
  const size_t nfree = bvp_base ? (size_t)(s->nbc + s->nint) - R->n : 0;
  /* AUTO's default without a THL line in an autonomous orbit's run is
   * THL = {11: 0}, the period out of the step (main.f90); a THL given,
   * even empty (THL = {}), leaves it at 1 */
  double wT = aut && fq < 0 && !whirl_runfile_given(R->rf, WHIRL_RK_THL) ? 0.0 : 1.0;
  for (size_t i = 0; i < s->nthl; i++) {
    const whirl_run_value *v = &s->thl[i];
    int k = run_par_index(R, &v->ref);
    if (orbit && (v->ref.index == 11 || !strcasecmp(v->ref.name, "PERIOD"))) {
      if (aut && fq < 0) wT = v->value;
    } else if (k >= 0 && k == fq) {
      wT = v->value;
    } else if (k < 0) {
      char nm[32];
      if (v->ref.index) snprintf(nm, sizeof nm, "PAR(%d)", v->ref.index);
      run_fail(R, WHIRL_RK_THL, "THL: '%s' is not a parameter of model '%s'",
               v->ref.index ? nm : v->ref.name, R->prob.name);
      return -2;
    } else if (k == b->icp && !(v->value >= 0)) {
      run_fail(R, WHIRL_RK_THL, "THL: the continuation parameter's weight must be >= 0");
      return -2;
    }
  }
  /* 0 as AUTO allows (um2: THL = {Period: 0} on ICP(1)): the step is
   * measured on the unknowns alone, which the core then checks are
   * weighted */
  const double wp = thl_of(s, R, b->icp);
  o->p_weight = sqrt(wp >= 0 ? wp : 1.0);
  int weighted = wT != 1.0 || s->nthu || locus; /* any weight other than 1 */
  for (size_t j = 0; j < nfree; j++) weighted |= thl_of(s, R, R->icp[j + 1]) >= 0;
  if (!base || !weighted) return 0;
  const size_t N = b->sys->n; /* b->nb, and a locus's own unknowns after */
  *xw = malloc(N * sizeof **xw);
  if (!*xw) return -1;
  for (size_t i = 0; i < N; i++) (*xw)[i] = 1.0;
  const size_t nodes = b->nb - (size_t)aut - nfree; /* the state's unknowns */
  for (size_t i = 0; i < s->nthu; i++) {
    const int xi = run_state_index(R, &s->thu[i].ref);
    if (xi < 0) {
      char nm[32];
      if (s->thu[i].ref.index) snprintf(nm, sizeof nm, "U(%d)", s->thu[i].ref.index);
      run_fail(R, WHIRL_RK_THU, "THU: '%s' is not a state component of model '%s'",
               s->thu[i].ref.index ? nm : s->thu[i].ref.name, R->prob.name);
      free(*xw), *xw = NULL;
      return -2;
    }
    for (size_t j = (size_t)xi; j < nodes; j += R->n) (*xw)[j] = sqrt(s->thu[i].value);
  }
  if (aut) (*xw)[b->nb - 1] = sqrt(wT);
  for (size_t j = 0; j < nfree; j++) { /* a BVP's free parameters, ICP(2) ... */
    const double w = thl_of(s, R, R->icp[j + 1]);
    (*xw)[nodes + j] = sqrt(w >= 0 ? w : 1.0);
  }
  if (locus) locus_weights(R, b, *xw);
  o->x_weight = *xw;
  for (size_t i = 0; i < N; i++) if ((*xw)[i] > 0) return 0;
  run_fail(R, s->nthu ? WHIRL_RK_THU : WHIRL_RK_THL, "THL, THU: every weight of the "
           "unknowns is 0 (the step length would measure the parameter alone)");
  free(*xw), *xw = NULL;
  return -2;
}

/* A labelled point: its block in the solutions file, and (special points)
 * its line in the log. */
static int write_label(run_ctx *R, const branch_spec *b, const whirl_point *pt,
                       const char *ty, int lab, double *pfull) {
  const whirl_run_settings *s = R->s;
  const int type = pt->type;
  whirl_solution so;
  memset(&so, 0, sizeof so);
  so.label = lab;
  so.br = R->branch;
  so.pt = (int)pt->index;
  snprintf(so.ty, sizeof so.ty, "%s", ty);
  so.kind = b->kind;
  so.iterate = b->iterate;
  so.icp = b->q >= 0 ? b->q : b->icp;
  so.icp2 = b->q >= 0 ? b->icp : -1;
  if (b->fold)
    snprintf(so.locus, sizeof so.locus, "%s",
             whirl_fold_point_type(b->fold) == WHIRL_PT_PD   ? "PD"
             : whirl_fold_point_type(b->fold) == WHIRL_PT_BP ? "BP"
                                                             : "LP");
  else if (b->hopf)
    snprintf(so.locus, sizeof so.locus, "%s", R->s->ips == WHIRL_IPS_MAP ? "TR" : "HB");
  else if (b->bploc)
    snprintf(so.locus, sizeof so.locus, "BP");
  else if (b->trloc)
    snprintf(so.locus, sizeof so.locus, "TR");
  so.npar = R->npar;
  so.nx = b->nb;
  so.par = pfull;
  so.x = (double *)pt->x;
  /* at a fixed period X's last entry is the free parameter (in pfull): the
   * file holds the orbit as every other, with T there, and no tangent (its
   * last entry would be the parameter's) */
  const int fixed_T = b->kind == WHIRL_SOL_COLLOC && !b->fold && !b->hopf && !b->trloc &&
                      whirl_colloc_free_param(b->colloc) >= 0;
  double *xT = NULL;
  if (fixed_T) {
    if (!(xT = malloc(b->nb * sizeof *xT))) return -1;
    memcpy(xT, pt->x, b->nb * sizeof *xT);
    xT[b->nb - 1] = whirl_colloc_period(b->colloc, pt->x, pfull);
    so.x = xT;
  }
  /* the tangent in AUTO's convention: the motion along the branch is DS
   * times it, so it is the motion times the sign of this run's DS, and a
   * restart moves along DS times it (run_tangent_start) */
  double *tan = NULL;
  if (!b->fold && !b->hopf && !b->bploc && !b->trloc && pt->t && !fixed_T) {
    const double sg = (b->dir_sign ? b->dir_sign : s->ds < 0 ? -1 : 1) < 0 ? -1.0 : 1.0;
    if (!(tan = malloc((b->nb + 1) * sizeof *tan))) {
      free(xT);
      return -1;
    }
    /* the point's direction as AUTO stores it (whirl_point.dir): on a
     * branch of orbits or a BVP the one its step was predicted along
     * (UDOTPS, written before CONTBV takes the new secant), so that a
     * restart from the label steps as AUTO's */
    const double *d = pt->dir ? pt->dir : pt->t;
    for (size_t i = 0; i <= b->nb; i++) tan[i] = sg * d[i];
  }
  so.tan = tan;
  so.stable = pt->stable;
  if (b->kind == WHIRL_SOL_COLLOC) {
    so.ncol = s->ncol;
    so.mesh = (double *)whirl_colloc_mesh(b->colloc);
    so.ntst = (int)((b->nb - (R->prob.autonomous ? 1 : 0)) / R->n - 1) / s->ncol;
  }
  if (b->kind == WHIRL_SOL_HBM) so.nhb = s->nhb;
  if (b->kind == WHIRL_SOL_BVP) {
    so.ntst = s->ntst;
    so.ncol = s->ncol;
    so.mesh = (double *)whirl_bvp_mesh(b->bvp);
    so.nfree = (int)(b->nb - R->n * (size_t)(s->ntst * s->ncol + 1));
    for (int j = 0; j < so.nfree && j < WHIRL_SOL_MAXFREE; j++) so.free_par[j] = R->icp[j + 1];
  }
  const int wrc = whirl_solution_write(R->sols, &so);
  free(tan);
  free(xT);
  if (wrc) return -1;
  if (type != WHIRL_PT_REGULAR && type != WHIRL_PT_EP) {
    fprintf(R->log, "  %s  LAB %d  PT %zu  %s = %.10g", ty, lab, pt->index,
            R->pnames[b->icp], pt->p[b->icp]);
    if (b->q >= 0)
      fprintf(R->log, "  %s = %.10g", R->pnames[b->q], pfull[b->q]);
    if (type == WHIRL_PT_HB && pt->nspec)
      for (size_t k = 0; k < pt->nspec; k++)
        if (pt->spec_im[k] > 0) {
          fprintf(R->log, "  omega = %.10g", pt->spec_im[k]);
          break;
        }
    fputc('\n', R->log);
  }
  return 0;
}

/* AUTO's end of a branch whose Newton fails at DSMIN (MX = label): its
 * last point again, one PT on, labelled MX (TY -9 in b. and s. files), as
 * AUTO's STPLBV writes it, and a restart may name it (IRS = 'MX1').  0 or
 * -1 (an output error). */
static int mx_end(run_ctx *R, const branch_spec *b, whirl_cont *c, double *pfull,
                  double *state) {
  const whirl_point *cur = whirl_cont_current(c);
  if (!cur) return -1;
  whirl_point mx = *cur;
  mx.index++;
  mx.type = WHIRL_PT_REGULAR; /* (write_label logs special types itself) */
  const void *obj = b->kind == WHIRL_SOL_COLLOC ? (const void *)b->colloc
                    : b->kind == WHIRL_SOL_HBM  ? (const void *)b->hbm
                    : b->kind == WHIRL_SOL_BVP  ? (const void *)b->bvp
                                                : NULL;
  base_of(b, mx.x, mx.p, pfull);
  double l2 = 0.0, period = 0.0;
  const int lab = ++R->label;
  if (run_table_row(R, b->kind, obj, R->branch, mx.index, "MX", lab, mx.x, pfull,
                    mx.stable, &l2, &period, state) ||
      write_label(R, b, &mx, "MX", lab, pfull))
    return -1;
  fprintf(R->log, "  MX  LAB %d  PT %zu  %s = %.10g: %s\n", lab, mx.index,
          R->pnames[b->icp], mx.p[b->icp], whirl_stop_reason_name(WHIRL_STOP_NOCONV));
  return 0;
}

/* How the branch ended: a failure keeps the points but fails the run
 * (said, R->failed); a normal end is logged.  The branch's status. */
static int branch_end(run_ctx *R, whirl_cont *c, int rc, int stop, size_t npts) {
  const int reason = rc == WHIRL_DONE && !stop ? whirl_cont_stop_reason(c) : 0;
  if (reason == WHIRL_STOP_NOCONV || reason == WHIRL_STOP_DOMAIN) {
    /* the points so far are a result, the end is not: keep them, fail */
    run_say(R, "%s: branch %d failed after point %zu: %s",
              whirl_runfile_name(R->rf), R->branch, npts, whirl_cont_errmsg(c));
    fprintf(R->log, "  failed: %s after %zu points\n", whirl_cont_errmsg(c), npts);
    R->failed = 1;
    rc = 0;
  } else if (rc == WHIRL_DONE || stop) {
    fprintf(R->log, "  ended: %s after %zu points\n",
            stop == 1   ? "L2-NORM left [A0, A1]"
            : stop == 3 ? "a STOP point"
            : stop == 4 ? "no convergence with minimum step size (DSMIN), labelled MX"
            : stop      ? "maximum number of points (NMX)"
                   : whirl_stop_reason_name(whirl_cont_stop_reason(c)),
            npts);
    rc = 0;
  } else if (rc < 0) {
    run_say(R, "%s: branch %d failed: %s",
              whirl_runfile_name(R->rf), R->branch, whirl_cont_errmsg(c));
    fprintf(R->log, "  failed: %s\n", whirl_cont_errmsg(c));
    rc = -1;
  }
  return rc;
}

/* AUTO's run of a locus's starting data (b->starting_data): the start
 * point as a row, then the EP that the next run restarts from, a row and
 * a label of its own at the same point (AUTO's EP ends 5 steps in the null
 * vector's norm that leave the point where it is; a restart's first point
 * is never a label in AUTO's numbering).  0 or -1. */
static int starting_data_rows(run_ctx *R, const branch_spec *b, const void *obj,
                              const whirl_point *pt, double *pfull, double *state) {
  double l2 = 0.0, period = 0.0;
  whirl_point ep = *pt;
  ep.index = pt->index + 1;
  ep.type = WHIRL_PT_EP;
  const int lab = ++R->label;
  if (run_table_row(R, b->kind, obj, R->branch, pt->index, "RG", 0, pt->x, pfull,
                    pt->stable, &l2, &period, state) ||
      run_table_row(R, b->kind, obj, R->branch, ep.index, "EP", lab, ep.x, pfull,
                    ep.stable, &l2, &period, state) ||
      write_label(R, b, &ep, "EP", lab, pfull))
    return -1;
  fprintf(R->log, "  EP  LAB %d  PT %zu: the locus's starting data\n", lab, ep.index);
  return 0;
}

/* The branch's statistics in the log and its summary line. */
static void branch_summary(run_ctx *R, const branch_spec *b, whirl_cont *c,
                           const int *counts, size_t npts, double pmin, double pmax,
                           int mx) {
  const whirl_cont_stats *st = whirl_cont_get_stats(c);
  fprintf(R->log, "  %zu steps, %zu rejected, %zu Newton iterations, %zu "
          "Jacobians, %zu special points\n", st->steps, st->rejected,
          st->newton_its, st->jac_evals, st->special);
  if (st->recorrected)
    fprintf(R->log, "  %zu points corrected on a new mesh before the step from them "
            "converged\n", st->recorrected);
  if (st->spectrum_failed)
    fprintf(R->log, "  stability unknown at %zu points: the spectrum could not "
            "be computed there (STAB -1)\n", st->spectrum_failed);
  {
    char line[1024];
    int len = snprintf(line, sizeof line, "branch %d: %zu points, %s in [%.8g, %.8g]",
                       R->branch, npts, R->pnames[b->icp], pmin, pmax);
    static const int order[] = {WHIRL_PT_LP, WHIRL_PT_BP, WHIRL_PT_HB,
                                WHIRL_PT_PD, WHIRL_PT_TR, WHIRL_PT_UZ,
                                WHIRL_PT_CP, WHIRL_PT_BT, WHIRL_PT_ZH,
                                WHIRL_PT_GH, WHIRL_PT_MG, WHIRL_PT_IS,
                                WHIRL_PT_R1, WHIRL_PT_R2, WHIRL_PT_R3, WHIRL_PT_R4};
    for (size_t i = 0; i < sizeof order / sizeof order[0]; i++)
      if (counts[order[i]] && len > 0 && (size_t)len < sizeof line)
        len += snprintf(line + len, sizeof line - (size_t)len, " %d %s", counts[order[i]],
                        whirl_point_type_name(order[i]));
    if (mx && len > 0 && (size_t)len < sizeof line) /* AUTO's end at DSMIN */
      len += snprintf(line + len, sizeof line - (size_t)len, ", ended in MX");
    run_summary(R, "%s", line);
  }
}

/* The progress of a branch, as io.progress(done, 1000): the larger of the
 * steps over NMX and the parameter's way over [RL0, RL1] (the range
 * covered, over it plus the distance still to the bound the branch heads
 * for); never less than before (*best). */
static void branch_progress(const run_ctx *R, const whirl_cont_options *o, size_t npts,
                            double p, double pmin, double pmax, double *prev, double *best) {
  if (!R->io.progress) return;
  double f = o->nmx ? (double)npts / (double)o->nmx : 0.0;
  if (npts > 1 && fabs(o->p_min) < 1e29 && fabs(o->p_max) < 1e29) {
    const double gap = p >= *prev ? o->p_max - p : p - o->p_min;
    if (pmax - pmin + gap > 0) f = fmax(f, (pmax - pmin) / (pmax - pmin + fmax(gap, 0.0)));
  }
  *prev = p;
  if (f > *best || npts <= 1) *best = npts <= 1 ? f : fmin(f, 1.0);
  R->io.progress((size_t)(1000.0 * *best), 1000, R->io.ctx);
}

/* AUTO's STOP: is this point of type ty the count-th of its type in the
 * run that a STOP item names?  Counts every special point. */
static int at_stop_point(run_ctx *R, const char *ty) {
  const whirl_run_settings *s = R->s;
  int hit = 0;
  for (size_t i = 0; i < s->nstop && i < WHIRL_RUN_MAXITEMS; i++)
    if (!strcmp(s->stop[i].ref.name, ty) && ++R->stop_seen[i] == (int)s->stop[i].value)
      hit = 1;
  return hit;
}

/* ISW = -1 at a BP of a boundary-value problem or of orbits (both
 * bvp.f90's STDRBV in AUTO): the second null vector, oriented as AUTO
 * orients it (run_bvp_orient: ICP(1)'s rate, the other free parameters'
 * (the period), then u(1)'s; not the state at t = 0 first, as equilibria:
 * brc's secondary orbits went to the mirror image of AUTO's). */
static int bvp_switch(run_ctx *R, whirl_cont *c, const branch_spec *b) {
  double *t = malloc((b->nb + 1) * sizeof *t);
  if (!t) return WHIRL_ENOMEM;
  int rc = whirl_cont_switch_direction(c, b->bp, 1, t);
  if (rc == WHIRL_OK) {
    run_bvp_orient(R, b, b->bp->x, b->bp->p, t);
    rc = whirl_cont_start_direction(c, b->bp->x, b->bp->p, t);
  }
  free(t);
  return rc;
}

int run_branch(run_ctx *R, branch_spec *b) {
  const whirl_run_settings *s = R->s;
  whirl_cont_options o;
  double uz[2 * WHIRL_RUN_MAXITEMS];
  int uz_stop[2 * WHIRL_RUN_MAXITEMS];
  uz_ctx uc = {R, b, {0}, NULL, NULL};
  if (branch_options(R, b, &o, uz, uz_stop, &uc)) return -2;
  char err[512];
  double *xw = NULL;
  int rc = branch_weights(R, b, &o, &xw);
  if (rc) return rc;
  whirl_cont *c = whirl_cont_alloc(b->sys, &o, err, sizeof err);
  free(xw);
  if (!c) {
    run_say(R, "%s", err);
    return -1;
  }
  int dir = b->dir_sign ? b->dir_sign : s->ds < 0 ? -1 : 1;
  double *pfull = malloc(R->npar * sizeof *pfull);
  double *state = malloc(R->n * sizeof *state);
  if (!pfull || !state) {
    free(pfull);
    free(state);
    whirl_cont_free(c);
    return -1;
  }
  uc.pfull = pfull; /* scratch shared with the loop below, never in use */
  uc.state = state; /* by both at once */
  if (b->bp && (b->kind == WHIRL_SOL_BVP || b->kind == WHIRL_SOL_COLLOC) && !b->fold &&
      !b->hopf && !b->bploc && !b->trloc)
    rc = bvp_switch(R, c, b);
  else if (b->bp)
    rc = whirl_cont_start_switch(c, b->bp, dir);
  else if (b->dir)
    rc = whirl_cont_start_direction(c, b->x0, b->p0, b->dir);
  else
    rc = whirl_cont_start(c, b->x0, b->p0, dir);
  if (rc != WHIRL_OK) {
    run_say(R, "%s: cannot start the branch: %s",
              whirl_runfile_name(R->rf), whirl_cont_errmsg(c));
    fprintf(R->log, "start failed: %s\n", whirl_cont_errmsg(c));
    whirl_cont_free(c);
    free(pfull);
    free(state);
    return -1;
  }
  R->branch++;
  fprintf(R->log, "branch %d: %s, continuation in %s (%s)\n", R->branch,
          b->sys->name ? b->sys->name : "?", R->pnames[b->icp],
          b->fold ? "fold locus" : b->hopf ? "Hopf locus" : b->bploc ? "branch-point locus"
          : b->trloc ? "torus locus"
                                                                      : "one parameter");
  int counts[WHIRL_PT_NTYPES] = {0};
  int stop = 0;
  size_t npts = 0;
  double pmin = 0.0, pmax = 0.0, pprev = 0.0, done = 0.0;
  for (;;) {
    rc = whirl_cont_step(c);
    if (rc != WHIRL_OK) break;
    const whirl_point *pt = whirl_cont_point(c);
    npts++;
    if (npts == 1 || pt->p[b->icp] < pmin) pmin = pt->p[b->icp];
    if (npts == 1 || pt->p[b->icp] > pmax) pmax = pt->p[b->icp];
    branch_progress(R, &o, npts, pt->p[b->icp], pmin, pmax, &pprev, &done);
    int type = pt->type;
    const char *ty = type ? whirl_point_type_name(type) : "RG";
    base_of(b, pt->x, pt->p, pfull);
    double l2 = 0.0, period = 0.0;
    const void *obj = b->kind == WHIRL_SOL_COLLOC ? (const void *)b->colloc
                      : b->kind == WHIRL_SOL_HBM  ? (const void *)b->hbm
                      : b->kind == WHIRL_SOL_BVP  ? (const void *)b->bvp
                                                  : NULL;
    /* the first point past A0 or A1 ends the branch, an EP as in AUTO
     * (ae.f90 STPLAE: ITP = 9 where AMP leaves [A0, A1]) */
    if (pt->index > 0 && (s->a0 != 0.0 || s->a1 < 1e30) &&
        run_point_measures(R, b->kind, obj, pt->x, pfull, &l2, &period, state) == 0 &&
        (l2 < s->a0 || l2 > s->a1)) {
      stop = 1;
      fprintf(R->log, "  L2-NORM = %g left [A0, A1]: branch ends\n", l2);
      if (type == WHIRL_PT_REGULAR) ty = "EP";
    }
    /* AUTO counts points, the start and the special points included
     * (ae.f90 STPLAE: NTOT, PT = index + 1): the NMX-th ends the branch,
     * an EP, and every NPR-th regular one is labelled */
    if (b->starting_data) { /* the start, then AUTO's EP at the same point */
      rc = starting_data_rows(R, b, obj, pt, pfull, state);
      break;
    }
    const size_t ntot = pt->index + 1;
    if (!stop && ntot >= (size_t)s->nmx) {
      stop = 2;
      if (type == WHIRL_PT_REGULAR) ty = "EP";
    }
    if (!stop && type != WHIRL_PT_REGULAR && at_stop_point(R, ty)) {
      stop = 3;
      fprintf(R->log, "  STOP: the %s ends the branch\n", ty);
    }
    int lab = 0, labelled = type != WHIRL_PT_REGULAR || stop ||
                            (s->npr > 0 && ntot % (size_t)s->npr == 0);
    if (labelled) lab = ++R->label;
    if (type >= 0 && type < WHIRL_PT_NTYPES) counts[type]++;
    if (b->trace && run_trace_add(b->trace, pt->x, pt->p, b->icp, type, R->branch)) {
      rc = -1;
      break;
    }
    if (run_table_row(R, b->kind, obj, R->branch, pt->index, ty, lab, pt->x,
                      pfull, pt->stable, &l2, &period, state)) {
      rc = -1;
      break;
    }
    if (labelled && write_label(R, b, pt, ty, lab, pfull)) {
      rc = -1;
      break;
    }
    if (stop) break;
  }
  if (b->trace && rc == WHIRL_DONE && whirl_cont_stop_reason(c) == WHIRL_STOP_LOOP)
    b->trace->closed = 1;
  if (rc == WHIRL_DONE && !stop && npts > 0 && s->mx_label &&
      whirl_cont_stop_reason(c) == WHIRL_STOP_NOCONV) {
    if (mx_end(R, b, c, pfull, state)) rc = -1;
    else stop = 4;
  }
  rc = branch_end(R, c, rc, stop, npts);
  branch_summary(R, b, c, counts, npts, pmin, pmax, stop == 4);
  whirl_cont_free(c);
  free(pfull);
  free(state);
  return rc;
}

/* ---- building the problem ---------------------------------------------- */

/* Samples of one period of the start orbit: the model's stpnt (autonomous),
 * or a forced response settled by time integration from U. */
static int start_samples(run_ctx *R, size_t m, double *xs, double *T) {
  const whirl_model *md = R->model;
  if (R->s->dat[0]) return run_dat_samples(R, m, xs, T, NULL);
  if (md->forcing_param < 0) {
    if (!md->stpnt || !(md->period0 > 0)) {
      run_fail(R, WHIRL_RK_IPS, "IPS = 2 from the model's start needs a "
               "start orbit: model '%s' has no stpnt/period0 (start from an "
               "HB label instead: S, IRS)", R->prob.name);
      return -1;
    }
    double *ptmp = malloc(R->npar * sizeof *ptmp);
    if (!ptmp) return -1;
    for (size_t k = 0; k < m; k++) {
      memcpy(ptmp, R->par, R->npar * sizeof *ptmp);
      if (md->stpnt((double)k / (double)m, xs + k * R->n, ptmp, R->prob.data)) {
        free(ptmp);
        run_fail(R, WHIRL_RK_MODEL, "model '%s': stpnt failed", R->prob.name);
        return -1;
      }
    }
    free(ptmp);
    *T = md->period0;
    return 0;
  }
  /* forced: integrate 200 periods from U, sample the next one */
  const double w = R->par[md->forcing_param], Tf = 2.0 * WHIRL_PI / w;
  whirl_ode *ode = whirl_ode_alloc(&R->prob, R->par);
  if (!ode) return -1;
  int rc = whirl_ode_set_tolerances(ode, 1e-10, 1e-12);
  if (!rc) rc = whirl_ode_reset(ode, 0.0, R->u);
  if (!rc) rc = whirl_ode_evolve(ode, 200.0 * Tf);
  for (size_t k = 0; !rc && k < m; k++) {
    rc = whirl_ode_evolve(ode, 200.0 * Tf + Tf * (double)k / (double)m);
    if (!rc) memcpy(xs + k * R->n, whirl_ode_x(ode), R->n * sizeof *xs);
  }
  if (rc) {
    run_say(R, "%s: settling the forced response from U by "
              "time integration failed: %s", whirl_runfile_name(R->rf),
              whirl_ode_errmsg(ode));
    whirl_ode_free(ode);
    return -1;
  }
  whirl_ode_free(ode);
  *T = Tf;
  return 0;
}

/* Everything a run may allocate, freed in one place. */
typedef struct run_objects {
  whirl_equilibrium *eq;
  whirl_bvp *bvp;
  whirl_colloc *colloc, *colloc2;
  whirl_hbm *hbm;
  whirl_fold *fold;
  whirl_hopf *hopf;
  whirl_bploc *bploc;
  whirl_trloc *trloc;
  double *X, *D, *Z, *xs;
  whirl_solution sol;
  int have_sol;
} run_objects;

/* The loci before the systems they are built on: a fold system of orbits
 * frees its workspace of the orbit's structured solver (ASan: a read of
 * the freed collocation system, 2026-12-06). */
static void objects_free(run_objects *O) {
  whirl_fold_free(O->fold);
  whirl_hopf_free(O->hopf);
  whirl_bploc_free(O->bploc);
  whirl_trloc_free(O->trloc);
  whirl_equilibrium_free(O->eq);
  whirl_bvp_free(O->bvp);
  whirl_colloc_free(O->colloc);
  whirl_colloc_free(O->colloc2);
  whirl_hbm_free(O->hbm);
  free(O->X);
  free(O->D);
  free(O->Z);
  free(O->xs);
  if (O->have_sol) whirl_solution_free(&O->sol);
}

/* The torus (Neimark-Sacker) locus of orbits from a TR label (AUTO's
 * ISW = 2 at a TR of IPS = 2): whirl_trloc on the orbit's collocation
 * system, its angle from the label's multiplier pair nearest the unit
 * circle (Doedel, Govaerts & Kuznetsov 2003). */
static int torus_locus(run_ctx *R, run_objects *O, branch_spec *b, const whirl_system *base,
                       const double *x, const double *p, int q, int other) {
  whirl_periodic po = whirl_periodic_of_colloc(O->colloc);
  const size_t cap = 2 * R->n + 2;
  double *re = malloc(2 * cap * sizeof *re), theta = -1.0, best = INFINITY;
  size_t m = cap;
  if (!re) return -1;
  int rc = whirl_periodic_multipliers(&po, x, p, re, re + cap, &m);
  for (size_t k = 0; rc == WHIRL_OK && k < m; ++k) {
    const double a = re[k], bi = re[cap + k], r = hypot(a, bi);
    if (bi > 1e-9 * (1.0 + r) && fabs(r - 1.0) < best) best = fabs(r - 1.0), theta = atan2(bi, a);
  }
  free(re);
  if (rc != WHIRL_OK || theta <= 0.0) {
    run_say(R, "torus locus: label %d has no complex multiplier pair (%s)",
            O->sol.label, rc ? whirl_periodic_errmsg(&po) : "all real");
    return -1;
  }
  whirl_fold_operator op;
  size_t *ei = malloc(R->n * sizeof *ei), *ej = malloc(R->n * sizeof *ej);
  double *ev = malloc(R->n * sizeof *ev);
  char err[512] = "";
  if (ei && ej && ev) {
    whirl_colloc_pd_operator(O->colloc, &op, ei, ej, ev);
    /* a third parameter in ICP: free, the angle fixed (AUTO's tor.6) */
    long par2 = -1;
    for (size_t i = 0; par2 < 0 && i < R->nicp; i++)
      if (R->icp[i] != q && R->icp[i] != other) par2 = R->icp[i];
    O->trloc = whirl_trloc_alloc(base, &op, (size_t)q, par2, err, sizeof err);
  }
  free(ei), free(ej), free(ev);
  if (!O->trloc) {
    run_say(R, "torus locus: %s", err[0] ? err : "out of memory");
    return -1;
  }
  O->Z = malloc((whirl_trloc_size(O->trloc) + 1) * sizeof *O->Z);
  if (!O->Z) return -1;
  if (whirl_trloc_init(O->trloc, x, p, theta, O->Z) != WHIRL_OK) {
    run_say(R, "torus locus: %s", whirl_trloc_errmsg(O->trloc));
    return -1;
  }
  fprintf(R->log, "torus locus from label %d: multipliers exp(+-i %.10g), |mu| - 1 = %.2g\n",
          O->sol.label, theta, best);
  b->trloc = O->trloc;
  b->sys = whirl_trloc_system(O->trloc);
  return 0;
}

/* The locus of branch points of orbits or of a BVP (AUTO's ISW = 2 and 3
 * at a BP of IPS = 2 or 4, F. Dercole's BP continuation): whirl_fold's
 * branch-point curve on the collocation system, minimally augmented —
 * ISW = 2 with the unfolding beta (F + beta b, where a symmetry keeps the
 * BPs in two parameters), ISW = 3 with a third parameter, the ICP after
 * the continued one, as AUTO's generic case. */
static int bp_curve(run_ctx *R, run_objects *O, branch_spec *b, const whirl_system *base,
                    const double *x, const double *p, int q, int other) {
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, (size_t)q);
  fo.nfree = 2;
  fo.cond = WHIRL_FOLD_COND_BP;
  fo.unfold = R->s->isw != 3;
  int extra = -1;
  for (size_t i = 0; !fo.unfold && i < R->nicp; i++)
    if (R->icp[i] != q && R->icp[i] != other &&
        !(b->kind == WHIRL_SOL_COLLOC && R->icp[i] == 10)) { /* PAR(11): the period */
      extra = R->icp[i];
      break;
    }
  if (!fo.unfold && extra < 0) {
    run_fail(R, WHIRL_RK_ICP, "ICP: ISW = 3 (a generic branch-point locus) from the BP at "
             "label %d needs '%s' and two more parameters", O->sol.label, R->pnames[q]);
    return -2;
  }
  fo.free[1] = fo.unfold ? (size_t)q : (size_t)extra;
  char err[512];
  O->fold = whirl_fold_alloc(base, &fo, err, sizeof err);
  if (!O->fold) {
    run_say(R, "branch-point locus: %s", err);
    return -1;
  }
  O->Z = malloc((whirl_fold_size(O->fold) + 1) * sizeof *O->Z);
  if (!O->Z) return -1;
  if (whirl_fold_init(O->fold, x, p, O->Z) != WHIRL_OK) {
    run_say(R, "branch-point locus: %s", whirl_fold_errmsg(O->fold));
    return -1;
  }
  fprintf(R->log, "branch-point locus from label %d (%s)\n", O->sol.label,
          fo.unfold ? "with the unfolding beta, ISW = 2" : "generic, ISW = 3");
  b->fold = O->fold;
  b->sys = whirl_fold_system(O->fold);
  return 0;
}

static int locus(run_ctx *R, run_objects *O, branch_spec *b,
                 const whirl_system *base, const double *x, const double *p) {
  const whirl_solution *so = &O->sol;
  int q = so->icp, other = -1;
  for (size_t i = 0; i < R->nicp; i++)
    if (R->icp[i] != q) {
      other = R->icp[i];
      break;
    }
  int has_q = 0;
  for (size_t i = 0; i < R->nicp; i++) has_q |= R->icp[i] == q;
  if (!has_q || other < 0) {
    run_fail(R, WHIRL_RK_ICP, "ICP: a two-parameter continuation from the %s "
             "at label %d needs '%s' (its parameter) and a second parameter",
             so->ty, so->label, R->pnames[q]);
    return -2;
  }
  char err[512];
  b->q = q;
  b->icp = other;
  /* a point of a locus continues that locus; else the label's own type */
  const char *ty = so->icp2 >= 0 && so->locus[0] ? so->locus : so->ty;
  const int pd = !strcmp(ty, "PD") && b->kind == WHIRL_SOL_COLLOC && O->colloc;
  const int map_pd = !strcmp(ty, "PD") && R->s->ips == WHIRL_IPS_MAP;
  if (!strcmp(ty, "LP") || pd || map_pd) {
    whirl_fold_options fo;
    whirl_fold_options_default(&fo, (size_t)q);
    whirl_fold_operator op;
    size_t *ei = NULL, *ej = NULL;
    double *ev = NULL;
    if (pd || map_pd) { /* the operator's constant entries, n of them */
      ei = malloc(R->n * sizeof *ei);
      ej = malloc(R->n * sizeof *ej);
      ev = malloc(R->n * sizeof *ev);
      if (!ei || !ej || !ev) {
        free(ei), free(ej), free(ev);
        return -1;
      }
      fo.op = &op;
    }
    if (pd) /* the period-doubling locus: the antiperiodic operator */
      whirl_colloc_pd_operator(O->colloc, &op, ei, ej, ev);
    else if (map_pd) { /* a map's flip: f_x + I = F_x + 2I singular */
      for (size_t j = 0; j < R->n; ++j) ei[j] = ej[j] = j, ev[j] = 2.0;
      op = (whirl_fold_operator){.na = R->n, .ne = R->n, .ei = ei, .ej = ej, .ev = ev,
                                 .point_type = WHIRL_PT_PD, .name = "flip curve of a map"};
    }
    O->fold = whirl_fold_alloc(base, &fo, err, sizeof err);
    free(ei), free(ej), free(ev);
    if (!O->fold) goto fail_alloc;
    O->Z = malloc((whirl_fold_size(O->fold) + 1) * sizeof *O->Z);
    if (!O->Z) return -1;
    if (whirl_fold_init(O->fold, x, p, O->Z) != WHIRL_OK) {
      run_say(R, "%s locus: %s", pd || map_pd ? "period-doubling" : "fold", whirl_fold_errmsg(O->fold));
      return -1;
    }
    b->fold = O->fold;
    b->sys = whirl_fold_system(O->fold);
  } else if (so->kind == WHIRL_SOL_EQ &&
             (R->s->ips == WHIRL_IPS_MAP ? !strcmp(ty, "TR") : !strcmp(ty, "HB"))) {
    /* a Hopf locus, or a map's Neimark-Sacker locus: the same system */
    O->hopf = R->s->ips == WHIRL_IPS_MAP ? whirl_hopf_alloc_map(base, (size_t)q, err, sizeof err)
                                         : whirl_hopf_alloc(base, (size_t)q, err, sizeof err);
    if (!O->hopf) goto fail_alloc;
    O->Z = malloc((whirl_hopf_size(O->hopf) + 1) * sizeof *O->Z);
    if (!O->Z) return -1;
    if (whirl_hopf_init(O->hopf, x, p, O->Z) != WHIRL_OK) {
      run_say(R, "%s locus: %s", R->s->ips == WHIRL_IPS_MAP ? "Neimark-Sacker" : "Hopf",
              whirl_hopf_errmsg(O->hopf));
      return -1;
    }
    b->hopf = O->hopf;
    b->sys = whirl_hopf_system(O->hopf);
  } else if (so->kind == WHIRL_SOL_EQ && R->s->ips != WHIRL_IPS_MAP && !strcmp(ty, "BP")) {
    /* a locus of branch points: ISW = 2 symmetric, ISW = 3 generic (a
     * third parameter, the ICP after the continued one) */
    const int generic = R->s->isw == 3;
    int extra = -1;
    for (size_t i = 0; generic && i < R->nicp; i++)
      if (R->icp[i] != q && R->icp[i] != other) {
        extra = R->icp[i];
        break;
      }
    if (generic && extra < 0) {
      run_fail(R, WHIRL_RK_ICP, "ICP: ISW = 3 (a generic branch-point locus) from the BP at "
               "label %d needs '%s' and two more parameters", so->label, R->pnames[q]);
      return -2;
    }
    O->bploc = whirl_bploc_alloc(base, (size_t)q, generic, (size_t)(extra < 0 ? 0 : extra),
                                 err, sizeof err);
    if (!O->bploc) goto fail_alloc;
    O->Z = malloc((whirl_bploc_size(O->bploc) + 1) * sizeof *O->Z);
    if (!O->Z) return -1;
    if (whirl_bploc_init(O->bploc, x, p, O->Z) != WHIRL_OK) {
      run_say(R, "branch-point locus: %s", whirl_bploc_errmsg(O->bploc));
      return -1;
    }
    b->bploc = O->bploc;
    b->sys = whirl_bploc_system(O->bploc);
  } else if (!strcmp(ty, "BP") && (b->kind == WHIRL_SOL_COLLOC || b->kind == WHIRL_SOL_BVP)) {
    if (bp_curve(R, O, b, base, x, p, q, other)) return -1;
  } else if (!strcmp(ty, "TR") && b->kind == WHIRL_SOL_COLLOC && O->colloc) {
    if (torus_locus(R, O, b, base, x, p, q, other)) return -1;
  } else {
    run_fail(R, WHIRL_RK_ISW, "ISW = 2 needs an LP or BP (any problem), an HB of "
             "equilibria, a PD or TR of a map, or a PD or TR of periodic orbits by collocation; label %d is "
             "%s%s (loci of %s are not available)",
             so->label, so->ty, so->kind == WHIRL_SOL_EQ ? "" : " of periodic orbits",
             so->ty);
    return -2;
  }
  /* AUTO continues a locus in ICP(1) with the others unknowns, and DS > 0
   * makes ICP(1) grow (ae.f90, STPRAE); whirl continues in `other` with
   * the label's parameter q an unknown: after the base's unknowns in the
   * fold and Hopf systems, after the base's and its null vector's in the
   * branch-point system.  When q is ICP(1), it is the one that grows,
   * and the locus's LPs are its turning points (AUTO's FNLPAE), not the
   * continued parameter's. */
  if (R->icp[0] == q) b->lead = (long)(b->bploc ? 2 * base->n : base->n);
  b->x0 = O->Z;
  b->p0 = p;
  return 0;
fail_alloc:
  run_say(R, "%s", err);
  return -1;
}

/* The branch of equilibria: from the model's start (U) or a label. */
static int start_equilibria(run_ctx *R, run_objects *O, branch_spec *b) {
  const int restart = O->have_sol;
  const whirl_solution *so = &O->sol;
  const double *p0 = R->par;
  if (restart && so->kind != WHIRL_SOL_EQ) {
    run_fail(R, WHIRL_RK_IRS, "IRS = %d is a periodic orbit; IPS = 1 needs "
             "an equilibrium", so->label);
    return -2;
  }
  /* a map's points of period k (a label's own), 2k switching at its PD */
  int k = restart && so->iterate > 1 ? so->iterate : 1;
  if (restart && R->s->isw == -1 && !strcmp(so->ty, "PD")) k *= 2;
  O->eq = R->s->ips == WHIRL_IPS_MAP ? whirl_map_iterate_fixed_points_alloc(&R->prob, k)
                                     : whirl_equilibrium_alloc(&R->prob);
  if (!O->eq) return -1;
  b->iterate = R->s->ips == WHIRL_IPS_MAP ? k : 1;
  b->kind = WHIRL_SOL_EQ;
  b->sys = whirl_equilibrium_system(O->eq);
  b->nb = R->n;
  b->x0 = restart ? so->x : R->u;
  b->p0 = p0;
  /* run_tangent_start: a restart in the label's own parameter moves along
   * DS times its stored tangent (write_label), as AUTO does — the sign of DS
   * is relative to the branch's direction at the label, not to the
   * parameter; and a Newton correction at fixed parameter, the plain
   * start, has a singular F_x at an LP (and would label it again).  The
   * sign of DS is applied in run_continuation. */
  if (restart && R->s->isw == 1 && so->tan && so->icp == b->icp) {
    O->D = malloc((b->nb + 1) * sizeof *O->D);
    if (!O->D) return -1;
    memcpy(O->D, so->tan, (b->nb + 1) * sizeof *O->D);
    b->dir = O->D;
  }
  return 0;
}

/* The stored tangent of so (on src's mesh) onto dst's, D[nb + 1]: its node
 * part by the conversion of orbits (linear), dT/ds and dp/ds as stored.
 * The conversion reads the period from the last entry, which for a tangent
 * may be 0 or negative: 1 there while converting.  0, or -1. */
/* b continues the orbits of collocation c: its system and sizes. */
static void use_colloc(const run_ctx *R, branch_spec *b, whirl_colloc *c) {
  b->colloc = c;
  b->sys = whirl_colloc_system(c);
  b->nb = whirl_colloc_size(c);
  b->nnodes = (b->nb - (R->prob.autonomous ? 1 : 0)) / R->n;
  b->ds_scale = 1.0; /* the system's norm weights: AUTO's integral norm */
}

static int resample_tangent(const whirl_solution *so, const whirl_periodic *src,
                            whirl_periodic *dst, int aut, size_t nb, double *D) {
  double *t = malloc((so->nx + 1) * sizeof *t);
  if (!t) return -1;
  memcpy(t, so->tan, (so->nx + 1) * sizeof *t);
  if (aut) t[so->nx - 1] = 1.0;
  const int rc = whirl_periodic_convert(src, t, so->par, dst, 400, D);
  if (!rc && aut) D[nb - 1] = so->tan[so->nx - 1];
  if (!rc) D[nb] = so->tan[so->nx];
  free(t);
  return rc ? -1 : 0;
}

/* AUTO's restart of an orbit on another mesh (STPNPS's ADAPT2): the mesh
 * of O->colloc equidistributes the stored orbit's jumps (so, restored on
 * O->colloc2), the orbit and its stored tangent (unless no_tangent)
 * interpolated onto it, the period and the tangent's last entries kept. */
static int adapt_restart(run_ctx *R, run_objects *O, branch_spec *b,
                         const whirl_solution *so, int no_tangent) {
  const double *m2 = whirl_colloc_mesh(O->colloc2);
  const size_t nb = b->nb, nt = (size_t)so->ntst, nc = (size_t)so->ncol;
  if (whirl_colloc_adapt_from(O->colloc, nt, nc, m2, so->x, O->X)) {
    run_say(R, "label %d onto NTST = %d, NCOL = %d: %s", so->label, R->s->ntst,
            R->s->ncol, whirl_colloc_errmsg(O->colloc));
    return -1;
  }
  if (R->prob.autonomous) O->X[nb - 1] = so->x[so->nx - 1];
  whirl_colloc_set_reference(O->colloc, O->X);
  if (so->tan && so->icp == b->icp && !no_tangent &&
      whirl_colloc_interp_from(O->colloc, nt, nc, m2, so->tan, O->D) == 0) {
    if (R->prob.autonomous) O->D[nb - 1] = so->tan[so->nx - 1];
    O->D[nb] = so->tan[so->nx];
    b->tan0 = O->D;
    if (R->s->isw == 1) b->dir = O->D;
  }
  fprintf(R->log, "label %d onto NTST = %d, NCOL = %d (AUTO's ADAPT2)\n", so->label,
          R->s->ntst, R->s->ncol);
  return 0;
}

/* AUTO's PD switch onto the run's mesh (STPNPS: PDBLE doubles the orbit and
 * its direction on the stored mesh, ADAPT2 moves both onto NTST, NCOL of
 * the run): the doubled orbit O->X, direction O->D on O->colloc (co's
 * mesh) replaced by their interpolants on the mesh that equidistributes
 * the doubled orbit's jumps (whirl_colloc_adapt_from, _interp_from). */
static int pd_to_run_mesh(run_ctx *R, run_objects *O, branch_spec *b,
                          const whirl_colloc_options *co) {
  whirl_colloc_options c3o = *co;
  char err[512];
  c3o.ntst = (size_t)R->s->ntst;
  c3o.ncol = (size_t)R->s->ncol;
  whirl_colloc *c3 = whirl_colloc_alloc(&R->prob, &c3o, err, sizeof err);
  if (!c3) {
    run_say(R, "collocation: %s", err);
    return -1;
  }
  const size_t nb3 = whirl_colloc_size(c3), nb = b->nb;
  double *X3 = calloc(nb3 + 1, sizeof *X3), *D3 = calloc(nb3 + 1, sizeof *D3);
  const double *mesh = whirl_colloc_mesh(O->colloc);
  int rc = X3 && D3 ? WHIRL_OK : WHIRL_ENOMEM;
  if (!rc) rc = whirl_colloc_adapt_from(c3, co->ntst, co->ncol, mesh, O->X, X3);
  if (!rc) rc = whirl_colloc_interp_from(c3, co->ntst, co->ncol, mesh, O->D, D3);
  if (!rc) whirl_colloc_set_rotations(c3, whirl_colloc_rotations(O->colloc));
  if (rc) {
    run_say(R, "period-doubling switch onto NTST = %d, NCOL = %d: %s", R->s->ntst,
            R->s->ncol, whirl_colloc_errmsg(c3));
    free(X3);
    free(D3);
    whirl_colloc_free(c3);
    return -1;
  }
  if (R->prob.autonomous) { /* the period and its direction */
    X3[nb3 - 1] = O->X[nb - 1];
    D3[nb3 - 1] = O->D[nb - 1];
  }
  D3[nb3] = O->D[nb]; /* the parameter's */
  whirl_colloc_set_reference(c3, X3);
  fprintf(R->log, "period-doubled orbit onto NTST = %d, NCOL = %d (AUTO's ADAPT2)\n",
          R->s->ntst, R->s->ncol);
  free(O->X);
  free(O->D);
  whirl_colloc_free(O->colloc);
  O->X = X3;
  O->D = D3;
  O->colloc = c3;
  use_colloc(R, b, c3);
  b->x0 = O->X;
  b->dir = O->D;
  return 0;
}

/* HB_PERIOD (AUTO's TY = 'HBk', bvp.f90's RSPTBV: PAR(11) = PAR(k)): the
 * frequency 2 pi / period of the orbits that start at equilibrium label so,
 * the period being that parameter's value there (demo r3b's PVLS puts the
 * periods of the centres' imaginary pairs into PAR(5..7)).  0, or -1 said. */
static int hopf_period_omega(run_ctx *R, const whirl_solution *so, const double *p0,
                             double *omega) {
  whirl_run_ref r;
  memset(&r, 0, sizeof r);
  snprintf(r.name, sizeof r.name, "%s", R->s->hb_period);
  const int k = run_par_index(R, &r);
  if (k < 0) {
    run_fail(R, WHIRL_RK_HB_PERIOD, "HB_PERIOD: '%s' is not a parameter of model '%s'",
             R->s->hb_period, R->prob.name);
    return -1;
  }
  const double T = p0[k];
  if (!(T > 0) || !isfinite(T)) {
    run_fail(R, WHIRL_RK_HB_PERIOD, "HB_PERIOD = %s: its value at label %d is %g, "
             "not a period (> 0)", R->s->hb_period, so->label, T);
    return -1;
  }
  *omega = 2 * WHIRL_PI / T;
  return 0;
}

/* Periodic orbits by collocation: from the model's start orbit or a
 * settled forced response, a Hopf point (an HB label, or an equilibrium
 * label with HB_PERIOD), or a periodic label
 * (on its mesh, resampled to another, or doubled at a PD). */
static int start_colloc(run_ctx *R, run_objects *O, branch_spec *b) {
  const whirl_run_settings *s = R->s;
  const int restart = O->have_sol;
  whirl_solution *so = &O->sol;
  int data_mesh = 0; /* the mesh made from the DAT rows (AUTO's ADAPT2) */
  const double *p0 = R->par;
  char err[512];
  whirl_colloc_options co;
  whirl_colloc_options_default(&co);
  co.ntst = (size_t)s->ntst;
  co.ncol = (size_t)s->ncol;
  co.forcing_param = R->model->forcing_param;
  co.adapt_every = s->iad; /* IAD: a new mesh every IAD steps, as AUTO */
  co.mesh_jumps = s->mesh_jumps; /* MESH_RULE = jumps: AUTO's meshes */
  co.phase_nodes = s->phase_nodes; /* PHASE = nodes: AUTO's phase condition */
  co.threads = s->threads;       /* THREADS: 0, OpenMP's default */
  int pd = restart && s->isw == -1 && !strcmp(so->ty, "PD");
  /* AUTO's fixed-period orbits: IPS 2 with two parameters in ICP and not
   * PERIOD (11): the label's period kept, ICP(2) free in its place */
  const int fixed_T = s->isw == 1 && R->prob.autonomous && !R->period_free && R->nicp >= 2;
  if (fixed_T) {
    if (!restart || so->kind != WHIRL_SOL_COLLOC) {
      run_fail(R, WHIRL_RK_ICP, "ICP: orbits at a fixed period (two parameters, "
               "PERIOD not listed) start from a periodic label (IRS), as they keep "
               "its period; add PERIOD to ICP for a free period");
      return -2;
    }
    co.free_param = R->icp[1];
    co.period = so->x[so->nx - 1];
  }
  if (restart && so->kind == WHIRL_SOL_COLLOC && (pd || s->isw == -1)) {
    co.ntst = (size_t)so->ntst; /* switching happens on the stored mesh */
    co.ncol = (size_t)so->ncol;
  }
  O->colloc = whirl_colloc_alloc(&R->prob, &co, err, sizeof err);
  if (!O->colloc) {
    run_say(R, "collocation: %s", err);
    return -1;
  }
  b->kind = WHIRL_SOL_COLLOC;
  use_colloc(R, b, O->colloc);
  O->X = calloc(b->nb + 1, sizeof *O->X);
  O->D = calloc(b->nb + 1, sizeof *O->D);
  if (!O->X || !O->D) return -1;
  b->x0 = O->X;
  b->p0 = p0;
  if (!restart) {
    const size_t m = 200;
    double T;
    O->xs = malloc((m + 1) * R->n * sizeof *O->xs);
    if (!O->xs) return -1;
    if (R->s->dat[0] && s->mesh_jumps) { /* AUTO's ADAPT2 of the rows */
      double *jump = O->xs + m * R->n;
      if (run_dat_adapt(R, O->colloc, O->X, &T, jump)) return -2;
      if (whirl_colloc_set_rotations(O->colloc, jump))
        fprintf(R->log, "rotations: components turning by 2 pi k over a period (AUTO's NRTN)\n");
      if (R->prob.autonomous) O->X[b->nb - 1] = T;
      whirl_colloc_set_reference(O->colloc, O->X);
      data_mesh = 1;
    } else {
      if (R->s->dat[0]) { /* the data's jumps over the period: rotations */
        double *jump = O->xs + m * R->n;
        if (run_dat_samples(R, m, O->xs, &T, jump)) return -2;
        if (whirl_colloc_set_rotations(O->colloc, jump))
          fprintf(R->log, "rotations: components turning by 2 pi k over a period (AUTO's NRTN)\n");
        whirl_colloc_from_samples(O->colloc, O->xs, m, T, O->X);
      } else if (s->mesh_jumps && R->model->forcing_param < 0) {
        /* AUTO's STPNUB: STPNT at the NTST NCOL + 1 equally spaced nodes
         * of the uniform mesh, listed as point 1 as they are (no mesh
         * adapted to them, no Newton at the start: CNRLBV, STDRBV) */
        const size_t mn = co.ntst * co.ncol;
        free(O->xs);
        O->xs = malloc((mn + 1) * R->n * sizeof *O->xs);
        if (!O->xs) return -1;
        if (start_samples(R, mn, O->xs, &T)) return -2;
        whirl_colloc_from_samples(O->colloc, O->xs, mn, T, O->X);
        data_mesh = 1;
      } else {
        if (start_samples(R, m, O->xs, &T)) return -2;
        whirl_colloc_from_samples(O->colloc, O->xs, m, T, O->X);
      }
    }
  } else if (R->s->hb_period[0] && so->kind != WHIRL_SOL_EQ) {
    run_fail(R, WHIRL_RK_HB_PERIOD, "HB_PERIOD starts orbits at an equilibrium "
             "label; label %d is %s of %s", so->label, so->ty,
             so->kind == WHIRL_SOL_COLLOC ? "periodic orbits" : "another kind");
    return -2;
  } else if (so->kind == WHIRL_SOL_EQ) {
    double w_want = 0.0;
    if (R->s->hb_period[0] && hopf_period_omega(R, so, p0, &w_want)) return -2;
    if ((strcmp(so->ty, "HB") && !R->s->hb_period[0]) || !R->prob.autonomous) {
      run_fail(R, WHIRL_RK_IRS, "IPS = 2 from an equilibrium label needs an "
               "HB of an autonomous model (or HB_PERIOD, AUTO's TY = 'HBk'); "
               "label %d is %s", so->label, so->ty);
      return -2;
    }
    double w;
    if (whirl_colloc_hopf_start_at(O->colloc, so->x, p0, w_want, O->X, O->D, &w)) {
      run_say(R, "no complex eigenvalue pair at label %d: "
                "not a Hopf point", so->label);
      return -1;
    }
    fprintf(R->log, "Hopf start at label %d: omega = %.10g, period %.10g\n",
            so->label, w, 2 * WHIRL_PI / w);
    b->dir = O->D;
  } else if (so->kind == WHIRL_SOL_COLLOC) {
    whirl_periodic dst = whirl_periodic_of_colloc(O->colloc);
    if ((size_t)so->ntst == co.ntst && (size_t)so->ncol == co.ncol) {
      memcpy(O->X, so->x, b->nb * sizeof *O->X);
      whirl_periodic_restore(&dst, so->mesh, O->X);
      whirl_colloc_rotations_of(O->colloc, O->X); /* AUTO's SETRTN */
      /* as for equilibria (run_tangent_start): along the stored tangent,
       * which the plain start's Newton at fixed parameter cannot do at an
       * LP of orbits (singular there) */
      if (so->tan && so->icp == b->icp && !pd && !fixed_T) {
        memcpy(O->D, so->tan, (b->nb + 1) * sizeof *O->D); /* O->D: nb + 1 */
        b->tan0 = O->D;
        if (s->isw == 1) b->dir = O->D;
      }
    } else { /* another mesh: resample the stored orbit */
      whirl_colloc_options c0 = co;
      c0.ntst = (size_t)so->ntst;
      c0.ncol = (size_t)so->ncol;
      O->colloc2 = whirl_colloc_alloc(&R->prob, &c0, err, sizeof err);
      if (!O->colloc2) return -1;
      whirl_periodic src = whirl_periodic_of_colloc(O->colloc2);
      whirl_periodic_restore(&src, so->mesh, so->x);
      /* AUTO's SETRTN: the turns read on the stored mesh (its last node
       * is at NTST NCOL of that mesh, not of the new one), in force on the
       * new mesh before the conversion samples the orbit onto it */
      const size_t nrot = whirl_colloc_rotations_of(O->colloc2, so->x);
      whirl_colloc_set_rotations(O->colloc, whirl_colloc_rotations(O->colloc2));
      /* the stored tangent resampled likewise (the map is linear; its last
       * entry dT/ds stays), so the restart goes on along the branch as on
       * the label's own mesh and as AUTO's: before, Newton at fixed
       * parameter and DS's sign in the parameter, the other way round at
       * an LP of orbits.  First, as converting sets the phase reference
       * (then the orbit's); not for turning angles, whose ramp the samples
       * would take for the tangent's */
      if (s->mesh_jumps) { /* AUTO's ADAPT2 (STPNPS) */
        if (adapt_restart(R, O, b, so, pd || fixed_T)) return -1;
      } else {
        if (so->tan && so->icp == b->icp && !pd && !fixed_T && !nrot &&
            resample_tangent(so, &src, &dst, R->prob.autonomous, b->nb, O->D) == 0) {
          b->tan0 = O->D;
          if (s->isw == 1) b->dir = O->D;
        }
        if (whirl_periodic_convert(&src, so->x, so->par, &dst, 400, O->X))
          return -1;
      }
      whirl_colloc_free(O->colloc2);
      O->colloc2 = NULL;
    }
    if (pd) {
      co.ntst *= 2;
      if (co.forcing_param >= 0) co.nu *= 2;
      O->colloc2 = whirl_colloc_alloc(&R->prob, &co, err, sizeof err);
      if (!O->colloc2) return -1;
      double *X2 = calloc(whirl_colloc_size(O->colloc2) + 1, sizeof *X2);
      double *D2 = calloc(whirl_colloc_size(O->colloc2) + 1, sizeof *D2);
      if (!X2 || !D2) {
        free(X2);
        free(D2);
        return -1;
      }
      if (whirl_colloc_pd_switch(O->colloc, O->X, p0, O->colloc2, X2, D2)) {
        free(X2);
        free(D2);
        run_say(R, "period-doubling switch at label %d "
                  "failed", so->label);
        return -1;
      }
      free(O->X);
      free(O->D);
      O->X = X2;
      O->D = D2;
      whirl_colloc *t = O->colloc;
      O->colloc = O->colloc2;
      O->colloc2 = t;
      use_colloc(R, b, O->colloc);
      b->x0 = O->X;
      b->dir = O->D;
      if (s->mesh_jumps && ((size_t)s->ntst != co.ntst || (size_t)s->ncol != co.ncol) &&
          pd_to_run_mesh(R, O, b, &co))
        return -1;
    }
  } else {
    run_fail(R, WHIRL_RK_IRS, "label %d is a harmonic-balance solution; "
             "restart it with METHOD = hbm", so->label);
    return -2;
  }
  if (fixed_T) {
    O->X[b->nb - 1] = p0[R->icp[1]]; /* T's place: the free parameter */
    fprintf(R->log, "fixed period %.10g; %s free in its place\n", co.period,
            R->pnames[R->icp[1]]);
  }
  b->as_given = data_mesh && !b->dir; /* AUTO lists the rows as point 1 (CNRLBV) */
  if (!b->dir && !pd && s->iad > 0 && !restart && !data_mesh)
    whirl_colloc_adapt(O->colloc, O->X);
  return 0;
}

/* Periodic orbits by harmonic balance: from the model's start orbit or a
 * settled forced response, or a harmonic-balance label with the same NHB. */
static int start_hbm(run_ctx *R, run_objects *O, branch_spec *b) {
  const whirl_run_settings *s = R->s;
  const int restart = O->have_sol;
  whirl_solution *so = &O->sol;
  const double *p0 = R->par;
  char err[512];
  whirl_hbm_options ho;
  whirl_hbm_options_default(&ho);
  ho.harmonics = (size_t)s->nhb;
  ho.oversampling = (size_t)s->oversampling;
  ho.forcing_param = R->model->forcing_param;
  if (s->isp != 2 && s->isp != 4) ho.no_spectrum = 1; /* PD, TR: ISP 2 or 4 */
  O->hbm = whirl_hbm_alloc(&R->prob, &ho, err, sizeof err);
  if (!O->hbm) {
    run_say(R, "harmonic balance: %s", err);
    return -1;
  }
  b->kind = WHIRL_SOL_HBM;
  b->hbm = O->hbm;
  b->sys = whirl_hbm_system(O->hbm);
  b->nb = whirl_hbm_size(O->hbm);
  O->X = calloc(b->nb + 1, sizeof *O->X);
  if (!O->X) return -1;
  b->x0 = O->X;
  b->p0 = p0;
  if (!restart) {
    const size_t m = 8 * (2 * (size_t)s->nhb + 1);
    double T;
    O->xs = malloc(m * R->n * sizeof *O->xs);
    if (!O->xs || start_samples(R, m, O->xs, &T)) return O->xs ? -2 : -1;
    whirl_hbm_from_samples(O->hbm, O->xs, m, T, O->X);
    whirl_hbm_set_phase(O->hbm, O->X);
  } else if (so->kind == WHIRL_SOL_HBM && so->nx == b->nb) {
    memcpy(O->X, so->x, b->nb * sizeof *O->X);
  } else {
    run_fail(R, WHIRL_RK_IRS, "label %d is not a harmonic-balance solution "
             "with NHB = %d (it is %s%s)", so->label, s->nhb,
             so->kind == WHIRL_SOL_EQ ? "an equilibrium" : so->kind == WHIRL_SOL_COLLOC ?
             "a collocation orbit" : "a harmonic-balance solution with another NHB",
             "");
    return -2;
  }
  return 0;
}

/* Branch switching at a BP (ISW = -1), and loci from a label (ISW = 2). */
static int switch_or_locus(run_ctx *R, run_objects *O, branch_spec *b) {
  const whirl_run_settings *s = R->s;
  const int restart = O->have_sol;
  whirl_solution *so = &O->sol;
  const double *p0 = R->par;
  /* switching and loci from the labelled point */
  const int map_pd = s->ips == WHIRL_IPS_MAP && !strcmp(so->ty, "PD");
  /* orbits from a Hopf point start so whatever ISW = +-1 says (AUTO's
   * periodic.f90 INIT sets ISW = 1 there: r3b's c.r3b.L1 has ISW = -1) */
  const int hopf_start = s->ips == WHIRL_IPS_PERIODIC && so->kind == WHIRL_SOL_EQ &&
                         (!strcmp(so->ty, "HB") || s->hb_period[0]);
  if (restart && s->isw == -1 && !hopf_start) {
    /* a BP; or a map's PD, a pitchfork of the doubled map (start_equilibria
     * built f^2k), whose branch of period k is the label's own */
    if (!strcmp(so->ty, "BP") || map_pd) {
      /* the label's tangent on this run's unknowns: resampled by the
       * start onto another mesh (tan0), or the stored one where the
       * unknowns are the label's own (equilibria, maps) */
      const double *t0 = b->tan0;
      if (!t0 && b->kind != WHIRL_SOL_BVP && b->kind != WHIRL_SOL_COLLOC && so->tan &&
          so->nx == b->nb)
        t0 = so->tan;
      if (!t0 || so->icp != b->icp) {
        run_fail(R, WHIRL_RK_ISW, "ISW = -1 at the %s of label %d needs its "
                 "tangent, on this run's mesh and free parameters, and the same "
                 "continuation parameter '%s'", so->ty, so->label,
                 R->pnames[so->icp]);
        return -2;
      }
      static whirl_point bp;
      memset(&bp, 0, sizeof bp);
      bp.type = WHIRL_PT_BP;
      bp.n = b->nb;
      bp.npar = R->npar;
      bp.x = b->x0;
      bp.p = p0;
      bp.t = t0;
      bp.stable = -1;
      bp.n_unstable = -1;
      b->bp = &bp;
    } else if (strcmp(so->ty, "PD") || b->kind != WHIRL_SOL_COLLOC) {
      run_fail(R, WHIRL_RK_ISW, "ISW = -1 switches at a BP, or at a PD of a map or "
               "of periodic orbits by collocation; label %d is %s", so->label, so->ty);
      return -2;
    }
  } else if (restart && (s->isw == 2 || s->isw == 3)) {
    int rc = locus(R, O, b, b->sys, b->x0, p0);
    if (rc) return rc;
    /* AUTO starts a locus of orbits or of a BVP at its special point with
     * a run that generates the extended system's starting data (its
     * null vectors: periodic.f90 and toolboxbv.f90 set ISW = -2, bvp.f90
     * then ILP = ISP = 0, NMX = 5: "Generating starting data: Restart at
     * EP label below"), steps in the null vector's norm that leave the
     * point where it is.  whirl's minimally augmented locus needs no such
     * data, but AUTO's scripts and c-files are written for that run
     * (abcb, int, pen), so here it is the start point alone, an EP the
     * next run restarts from */
    if ((b->kind == WHIRL_SOL_COLLOC || b->kind == WHIRL_SOL_BVP) &&
        !(so->icp2 >= 0 && so->locus[0])) {
      b->starting_data = 1;
      fprintf(R->log, "starting data of the locus (AUTO's ISW = -2): the start point, "
              "an EP; restart at it to continue the locus\n");
    }
    b->ds_scale = 1.0;
    /* (a locus whose system weighs the base's node values: AUTO's
     * integral norm, branch_weights) */
    if ((b->kind == WHIRL_SOL_COLLOC || b->kind == WHIRL_SOL_BVP) && !b->sys->norm_weights)
      b->ds_scale = sqrt((double)(s->ntst * s->ncol + 1));
  }
  return 0;
}

/* The branch the run asks for: its system and start, then continued. */
static int run_continuation(run_ctx *R, run_objects *O) {
  const whirl_run_settings *s = R->s;
  branch_spec b;
  memset(&b, 0, sizeof b);
  b.icp = R->icp[0];
  b.q = -1;
  b.lead = -1;
  b.ds_scale = 1.0;
  b.model = R->model;

  if (s->ndiscover && s->ips != WHIRL_IPS_EQUILIBRIA && R->model->forcing_param < 0) {
    run_fail(R, WHIRL_RK_DISCOVER, "DISCOVER finds periodic orbits of forced models; "
             "model '%s' is autonomous (its equilibria: IPS = 1)", R->prob.name);
    return -2;
  }
  const int fixed = s->ips == WHIRL_IPS_EQUILIBRIA || s->ips == WHIRL_IPS_MAP;
  int rc = fixed                                ? start_equilibria(R, O, &b)
           : s->ips == WHIRL_IPS_BVP          ? run_bvp_start(R, O->have_sol ? &O->sol : NULL,
                                                              &O->bvp, &O->X, &O->D, &b)
           : s->method == WHIRL_METHOD_COLLOC ? start_colloc(R, O, &b)
                                              : start_hbm(R, O, &b);
  if (!rc) rc = switch_or_locus(R, O, &b);
  if (rc) return rc;
  if (b.dir && s->ds < 0)
    for (size_t i = 0; i <= b.nb; i++) O->D[i] = -O->D[i];
  if (run_table_header(R, b.kind, b.icp, b.q)) return -1;
  if (s->ndiscover) return run_discover(R, &b);
  rc = run_branch(R, &b);
  R->curves = (size_t)R->branch;
  return rc;
}

/* ---- the run as a library object (whirl/run.h) --------------------------- */

whirl_run *whirl_run_alloc(const whirl_model_registry *models, const whirl_run_io *io) {
  whirl_run *r = calloc(1, sizeof *r);
  if (!r) return NULL;
  r->registry = models;
  if (io) r->io = *io;
  return r;
}

void whirl_run_free(whirl_run *r) {
  if (!r) return;
  if (r->log) fclose(r->log);
  if (r->table) fclose(r->table);
  if (r->sols) fclose(r->sols);
  run_basins_job_free(r->bjob);
  free(r->points);
  run_unload_model(r);
  whirl_runfile_free(r->rf);
  for (size_t i = 0; i < r->nspecial; i++) {
    free((void *)r->special[i].par);
    free((void *)r->special[i].row);
  }
  free(r->special);
  free(r->branch_ids);
  free(r->branch_stab);
  for (size_t i = 0; i < r->noverrides; i++) free(r->overrides[i]);
  free(r->overrides);
  free(r);
}

/* A path of the run (doc/run-files.md, "Paths"): as it is when absolute
 * or given on the command line (relative to the current directory), else
 * relative to the run file's directory — a run file means the same from
 * any directory.  0, or -1 when it does not fit. */
int run_path(const run_ctx *R, whirl_run_key k, const char *value, char *buf, size_t len) {
  int m;
  if (value[0] == '/' || !R->rundir[0] || whirl_runfile_on_command_line(R->rf, k))
    m = snprintf(buf, len, "%s", value);
  else
    m = snprintf(buf, len, "%s%s%s", R->rundir, strcmp(R->rundir, "/") ? "/" : "", value);
  return m < 0 || (size_t)m >= len ? -1 : 0;
}

/* The run file's directory; the output directory (OUT, or the run file's
 * name with .out beside it) and S by run_path.  0, or 2 (said). */
static int set_paths(whirl_run *R, const char *file) {
  const char *slash = strrchr(file, '/');
  if (slash) snprintf(R->rundir, sizeof R->rundir, "%.*s", (int)(slash - file), file);
  if (slash && !R->rundir[0]) snprintf(R->rundir, sizeof R->rundir, "/");
  char def[1024];
  const char *base = slash ? slash + 1 : file;
  const char *dot = strrchr(base, '.');
  int len = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
  snprintf(def, sizeof def, "%.*s.out", len, base);
  if (run_path(R, WHIRL_RK_OUT, R->s->out[0] ? R->s->out : def, R->out, sizeof R->out) ||
      run_path(R, WHIRL_RK_S, R->s->s, R->spath, sizeof R->spath)) {
    run_fail(R, WHIRL_RK_OUT, "OUT or S: the path is too long");
    return 2;
  }
  if (!R->s->s[0]) R->spath[0] = '\0';
  if (whirl_runfile_given(R->rf, WHIRL_RK_OUT))
    whirl_runfile_where(R->rf, WHIRL_RK_OUT, R->out_where, sizeof R->out_where);
  return 0;
}

/* AUTO's c.ab.2 after c.ab.1 with the same output: the run would replace
 * the solutions it restarts from (S).  1 (said) when OUT is S. */
static int replaces_restart(whirl_run *R) {
  struct stat a, b;
  if (!R->spath[0] || stat(R->spath, &a) != 0 || stat(R->out, &b) != 0) return 0;
  if (a.st_dev != b.st_dev || a.st_ino != b.st_ino) return 0;
  run_fail(R, whirl_runfile_given(R->rf, WHIRL_RK_OUT) ? WHIRL_RK_OUT : WHIRL_RK_S,
           "OUT '%s' is S, the run this one restarts from: its output would "
           "replace the solutions it starts from; give another OUT", R->out);
  return 1;
}

int whirl_run_load(whirl_run *R, const char *file, const char *const *overrides,
                   size_t noverrides) {
  if (!R || !file) return WHIRL_EINVAL;
  if (!(R->rf = whirl_runfile_alloc())) return 1;
  snprintf(R->file, sizeof R->file, "%s", file);
  int rc = whirl_runfile_read(R->rf, file);
  R->overrides = calloc(noverrides ? noverrides : 1, sizeof *R->overrides);
  if (!R->overrides) return 1;
  for (size_t i = 0; rc == WHIRL_OK && i < noverrides; i++) {
    R->overrides[R->noverrides++] = strdup(overrides[i]);
    rc = whirl_runfile_override(R->rf, overrides[i]);
  }
  if (rc == WHIRL_OK) rc = whirl_runfile_check(R->rf);
  if (rc != WHIRL_OK) {
    run_say(R, "%s", whirl_runfile_errmsg(R->rf));
    /* a run file that exists but cannot be read is an I/O error (1); a
     * missing one, like any mistake in it, is bad input (2) */
    FILE *probe = rc == WHIRL_EIO ? fopen(file, "r") : NULL;
    if (probe) fclose(probe);
    return rc == WHIRL_EIO && (probe || errno != ENOENT) ? 1 : 2;
  }
  R->s = whirl_runfile_settings(R->rf);
  if (set_paths(R, file) || replaces_restart(R)) return 2;
  return run_load_model(R) || run_resolve(R) || run_study_resolve(R) ? 2 : 0;
}

const char *whirl_run_output(const whirl_run *r) { return r->out; }
const char *whirl_run_output_where(const whirl_run *r) { return r->out_where; }
int whirl_run_failed(const whirl_run *r) { return r->failed; }
size_t whirl_run_nspecial(const whirl_run *r) { return r->nspecial; }
const whirl_run_special *whirl_run_special_point(const whirl_run *r, size_t i) {
  return i < r->nspecial ? &r->special[i] : NULL;
}
const whirl_run_plot *whirl_run_plot_info(const whirl_run *r) {
  whirl_run *w = (whirl_run *)r; /* a view of the fields, made on request */
  w->plot.basins = r->s && r->s->ips == WHIRL_IPS_BASINS;
  if (!w->plot.basins) {
    w->plot.x = r->plot_x;
    w->plot.y = r->plot_y;
    w->plot.stab_col = r->ncols;
    w->plot.x_name = r->plot_x_name;
    w->plot.y_name = r->plot_y_name;
  }
  memcpy(w->plot.seen_stab, r->seen_stab, sizeof w->plot.seen_stab);
  w->plot.seen_special = r->seen_special;
  w->plot.branches = r->branch_ids;
  w->plot.branch_stab = r->branch_stab;
  w->plot.nbranches = r->nbranch_ids;
  return &r->plot;
}
const char *whirl_run_model_name(const whirl_run *r) { return r->prob.name; }
const char *whirl_run_file_name(const whirl_run *r) { return whirl_runfile_name(r->rf); }
const char *whirl_run_errmsg(const whirl_run *r) { return r->errmsg; }

/* The labelled start solution (S, IRS): its parameters under the run
 * file's PAR, and its state for equilibria.  0, or -1 (message said). */
static int restart_solution(whirl_run *R, run_objects *O) {
  char msg[1024];
  /* S resolved like OUT (run_path) */
  if (run_solution_find(R, R->spath, R->s->irs, R->s->irs_type, &O->sol, msg,
                        sizeof msg)) {
    run_fail(R, WHIRL_RK_IRS, "IRS: %s", msg);
    return -1;
  }
  O->have_sol = 1;
  /* the run file's PAR overrides the stored parameters (AUTO); those the
   * solution has not (a restart with a larger NPAR) keep the model's */
  for (size_t k = 0; k < R->npar; k++) {
    if (O->sol.npar_stored && k >= O->sol.npar_stored) O->sol.par[k] = R->par[k];
    R->par[k] = O->sol.par[k];
  }
  for (size_t i = 0; i < R->s->npar; i++)
    R->par[run_par_index(R, &R->s->par[i].ref)] = R->s->par[i].value;
  if (O->sol.kind == WHIRL_SOL_EQ) memcpy(R->u, O->sol.x, R->n * sizeof *R->u);
  return 0;
}

static void write_log_head(whirl_run *R) {
  fprintf(R->log, "whirl %s run %s\n", whirl_version(), R->file);
  for (size_t i = 0; i < R->noverrides; i++)
    fprintf(R->log, "override: %s\n", R->overrides[i]);
  fprintf(R->log, "model: %s (%s), n = %zu, npar = %zu%s\n", R->prob.name,
          R->model->description ? R->model->description : "no description",
          R->n, R->npar, R->dl ? ", plug-in" : ", built-in");
  if (whirl_runfile_ignored(R->rf)[0])
    fprintf(R->log, "ignored AUTO constants: %s\n", whirl_runfile_ignored(R->rf));
  fprintf(R->log, "parameters:");
  for (size_t k = 0; k < R->npar; k++) fprintf(R->log, " %s = %.10g", R->pnames[k], R->par[k]);
  fprintf(R->log, "\n");
  if (R->sols)
    fprintf(R->sols, "# whirl solutions: model %s, npar %zu\n", R->prob.name, R->npar);
}

/* Close the files of the run: 0, or 1 when one was not complete. */
static int close_files(whirl_run *R) {
  int bad = 0;
  if (R->table) bad |= run_close(R, R->table, "branches.tsv");
  if (R->sols) bad |= run_close(R, R->sols, "solutions");
  if (R->log) bad |= run_close(R, R->log, "run.log");
  R->table = R->sols = R->log = NULL;
  return bad ? 1 : 0;
}

int whirl_run_execute(whirl_run *R) {
  if (!R || !R->s) return WHIRL_EINVAL;
  run_objects O;
  memset(&O, 0, sizeof O);
  memset(R->stop_seen, 0, sizeof R->stop_seen);
  int status = 2;
  if ((R->s->irs > 0 || R->s->irs_type[0]) && restart_solution(R, &O)) goto out;
  status = 1;
  const int basins = R->s->ips == WHIRL_IPS_BASINS;
  const int study = R->study_npoints > 0 && !R->in_study;
  R->plot.basins = basins;
  if (!(R->log = run_open(R, "run.log")) ||
      (!basins && !study && (!(R->table = run_open(R, "branches.tsv")) ||
                             !(R->sols = run_open(R, "solutions")))))
    goto out;
  write_log_head(R);
  const double t0 = run_now();
  int rr = study ? run_study(R) : basins ? run_basins(R) : run_continuation(R, &O);
  if (rr) {
    status = rr == -2 ? 2 : 1;
    goto out;
  }
  fprintf(R->log, "wall time %.3f s\n", run_now() - t0);
  status = close_files(R);
out:
  if (status) { /* abandoned: the caller discards what was written */
    if (R->log) fclose(R->log);
    if (R->table) fclose(R->table);
    if (R->sols) fclose(R->sols);
    R->log = R->table = R->sols = NULL;
  }
  objects_free(&O);
  return status;
}

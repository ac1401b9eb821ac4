/* lib/core/cont.c — pseudo-arclength continuation (Keller 1977; Doedel,
 * Keller & Kernévez, Int. J. Bif. Chaos 1 (1991) 493): secant or tangent
 * predictor, Newton corrector on the bordered system
 *     [F_x  F_p] dX = -[F                 ]
 *     [  r^T   ]       [<r, X - X0> - ds ],
 * adaptive step (AUTO's DS/DSMIN/DSMAX/NMX) with a limit on the turn of the
 * tangent, test functions for LP/BP/HB evaluated at every point, and ends at
 * parameter bounds (localised exactly), NMX, closed loops and DSMIN.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

const char *whirl_point_type_name(int type) {
  switch (type) {
  case WHIRL_PT_REGULAR: return "  ";
  case WHIRL_PT_EP: return "EP";
  case WHIRL_PT_LP: return "LP";
  case WHIRL_PT_BP: return "BP";
  case WHIRL_PT_HB: return "HB";
  case WHIRL_PT_UZ: return "UZ";
  case WHIRL_PT_PD: return "PD";
  case WHIRL_PT_TR: return "TR";
  case WHIRL_PT_CP: return "CP";
  case WHIRL_PT_BT: return "BT";
  case WHIRL_PT_ZH: return "ZH";
  case WHIRL_PT_IS: return "IS";
  case WHIRL_PT_MG: return "MG";
  case WHIRL_PT_GH: return "GH";
  case WHIRL_PT_R1: return "R1";
  case WHIRL_PT_R2: return "R2";
  case WHIRL_PT_R3: return "R3";
  case WHIRL_PT_R4: return "R4";
  default: return "??";
  }
}

const char *whirl_stop_reason_name(int reason) {
  switch (reason) {
  case WHIRL_STOP_NONE: return "none";
  case WHIRL_STOP_PMIN: return "parameter reached its lower bound";
  case WHIRL_STOP_PMAX: return "parameter reached its upper bound";
  case WHIRL_STOP_NMX: return "maximum number of steps (NMX)";
  case WHIRL_STOP_DOMAIN: return "model domain error persisted down to DSMIN";
  case WHIRL_STOP_NOCONV: return "no convergence with minimum step size (DSMIN)";
  case WHIRL_STOP_LOOP: return "branch closed on itself";
  case WHIRL_STOP_XMAX: return "solution norm exceeded its bound";
  case WHIRL_STOP_BP: return "branch point (stop_at_bp)";
  case WHIRL_STOP_UZ: return "user stop value reached (UZSTOP)";
  default: return "unknown";
  }
}

void whirl_cont_options_default(whirl_cont_options *o) {
  memset(o, 0, sizeof *o);
  o->icp = 0;
  o->ds = 1e-2;
  o->ds_min = 1e-8;
  o->ds_max = 0.5;
  o->nmx = 1000;
  o->p_min = -1e30;
  o->p_max = 1e30;
  o->x_max = 0.0;
  o->p_weight = 1.0;
  o->newton_tol = 1e-10;
  o->newton_tol_par = 0.0;
  o->newton_maxit = 12;
  o->newton_fast = 3;
  o->newton_chord = 0;
  o->chord_theta = 0.25;
  o->max_angle = 0.2;
  o->lead = -1;
  o->tangent_predictor = 0;
  o->tangent_from_newton = 0;
  o->natural_corrector = 0.0;
  o->detect_lp = o->detect_bp = o->detect_hb = o->detect_pd = 1;
  o->detect_sys = 1;
  o->stability = 1;
  o->stop_at_bp = 0;
  o->detect_loop = 1;
  o->loc_tol = 1e-12;
  o->loc_epss = 0.0;
  o->loc_itmx = 8;
  o->linsol = WHIRL_LINSOL_DENSE;
  o->structured = 1;
  o->uz = NULL;
  o->nuz = 0;
}

double cont_dot(const whirl_cont *c, const double *a, const double *b) {
  double s = 0.0;
  for (size_t i = 0; i < c->N; ++i) s += c->w2[i] * a[i] * b[i];
  return s;
}

double cont_dist2(const whirl_cont *c, const double *A, const double *B) {
  double d2 = 0.0;
  for (size_t i = 0; i < c->N; ++i) {
    const double di = A[i] - B[i];
    d2 += c->w2[i] * di * di;
  }
  return d2;
}

/* The squared weights of the arclength norm: the caller's (AUTO's THU and
 * THL) times the system's own for its representation (the quadrature
 * weights of collocation nodes), which a new mesh changes. */
static int apply_weights(whirl_cont *c) {
  const size_t n = c->n;
  if (c->sys.norm_weights) {
    int rc = c->sys.norm_weights(c->w2, c->sys.data);
    if (rc)
      return WHIRL_FAIL(c, rc < 0 ? rc : WHIRL_EINVAL,
                        "the system's norm weights failed (%d)", rc);
    for (size_t i = 0; i < n; ++i) {
      if (!(c->w2[i] >= 0) || !isfinite(c->w2[i]))
        return WHIRL_FAIL(c, WHIRL_EINVAL, "the system's norm weight of "
                          "unknown %zu is not finite and >= 0", i);
      c->w2[i] *= c->xw2[i];
    }
  } else {
    memcpy(c->w2, c->xw2, n * sizeof *c->w2);
  }
  return WHIRL_OK;
}

static int set_weights(whirl_cont *c, const whirl_cont_options *opt) {
  for (size_t i = 0; i < c->n; ++i)
    c->xw2[i] = opt->x_weight ? opt->x_weight[i] * opt->x_weight[i] : 1.0;
  c->w2[c->n] = opt->p_weight * opt->p_weight;
  return apply_weights(c);
}

static double cont_norm(const whirl_cont *c, const double *a) {
  return sqrt(cont_dot(c, a, a));
}

/* ------------------------------------------------------------ states */

static int state_alloc(whirl_cont *c, cont_state *st) {
  memset(st, 0, sizeof *st);
  st->X = calloc(c->N, sizeof *st->X);
  st->t = calloc(c->N, sizeof *st->t);
  st->sec = calloc(c->N, sizeof *st->sec);
  st->p = calloc(c->npar, sizeof *st->p);
  size_t ns = c->sys.nspec ? c->sys.nspec : 1;
  st->re = calloc(ns, sizeof *st->re);
  st->im = calloc(ns, sizeof *st->im);
  size_t nt = c->sys.test ? c->sys.ntest : 0;
  st->tau = calloc(nt ? nt : 1, sizeof *st->tau);
  st->ttype = calloc(nt ? nt : 1, sizeof *st->ttype);
  return st->X && st->t && st->sec && st->p && st->re && st->im && st->tau && st->ttype
             ? 0
             : -1;
}

static void state_free(cont_state *st) {
  free(st->X);
  free(st->t);
  free(st->sec);
  free(st->p);
  free(st->re);
  free(st->im);
  free(st->tau);
  free(st->ttype);
}

void cont_state_copy(const whirl_cont *c, cont_state *dst,
                     const cont_state *src) {
  double *X = dst->X, *t = dst->t, *sec = dst->sec, *p = dst->p, *re = dst->re, *im = dst->im;
  double *tau = dst->tau;
  int *ttype = dst->ttype;
  *dst = *src;
  dst->tau = tau;
  dst->ttype = ttype;
  if (c->sys.test && c->sys.ntest) {
    memcpy(tau, src->tau, c->sys.ntest * sizeof *tau);
    memcpy(ttype, src->ttype, c->sys.ntest * sizeof *ttype);
  }
  dst->X = X;
  dst->t = t;
  dst->sec = sec;
  dst->p = p;
  dst->re = re;
  dst->im = im;
  memcpy(X, src->X, c->N * sizeof *X);
  memcpy(t, src->t, c->N * sizeof *t);
  if (src->has_sec) memcpy(sec, src->sec, c->N * sizeof *sec);
  memcpy(p, src->p, c->npar * sizeof *p);
  if (c->sys.nspec) {
    memcpy(re, src->re, c->sys.nspec * sizeof *re);
    memcpy(im, src->im, c->sys.nspec * sizeof *im);
  }
}

/* ------------------------------------------------------------ alloc */

/* Finite weights >= 0, and one of them > 0 when the parameter's is 0
 * (AUTO's THL = {ICP(1): 0}): the arclength stays a norm on the tangents. */
static int weights_valid(const double *w, size_t n, double p_weight) {
  int some = p_weight > 0 || !w;
  for (size_t i = 0; w && i < n; ++i) {
    if (!(w[i] >= 0) || !isfinite(w[i])) return 0;
    some |= w[i] > 0;
  }
  return some;
}

whirl_cont *whirl_cont_alloc(const whirl_system *sys,
                             const whirl_cont_options *opt, char *errbuf,
                             size_t errlen) {
  const char *why = NULL;
  if (!sys || !sys->F || sys->n == 0) why = "system has no F or n == 0";
  else if (!opt) why = "no options";
  else if (opt->icp >= sys->npar) why = "ICP is not a parameter index of the system";
  else if (!(opt->ds_min > 0) || !(opt->ds_max >= opt->ds_min) ||
           !(fabs(opt->ds) >= opt->ds_min) ||
           !(opt->auto_steps || fabs(opt->ds) <= opt->ds_max))
    why = opt->auto_steps ? "need 0 < DSMIN <= |DS| and DSMIN <= DSMAX"
                          : "need 0 < DSMIN <= |DS| <= DSMAX";
  else if (!(opt->p_min < opt->p_max)) why = "need RL0 (p_min) < RL1 (p_max)";
  else if (!(opt->newton_tol > 0) || opt->newton_maxit < 1 || !(opt->newton_tol_par >= 0))
    why = "need newton_tol > 0, newton_tol_par >= 0 and newton_maxit >= 1";
  else if (opt->newton_full < 0)
    why = "newton_full: need >= 0 (0: a new Jacobian at every iteration)";
  else if (opt->newton_par_tail >= sys->n)
    why = "newton_par_tail: need fewer free parameters than unknowns";
  else if (!(opt->p_weight >= 0) || !isfinite(opt->p_weight))
    why = "need a finite p_weight >= 0";
  else if (!weights_valid(opt->x_weight, sys->n, opt->p_weight))
    why = "x_weight: need finite weights >= 0, one > 0 when p_weight is 0";
  else if (opt->lead < -1 || opt->lead >= (long)sys->n)
    why = "lead: -1 (the continuation parameter) or an unknown's index < n";
  else if (opt->newton_chord && !(opt->chord_theta > 0 && opt->chord_theta < 1))
    why = "chord Newton needs 0 < chord_theta < 1";
  else if (opt->linsol == WHIRL_LINSOL_SPARSE &&
           (sys->nnz == 0 || !sys->Jp || !sys->Ji || !sys->Fx_sparse))
    why = "sparse solver requested but the system has no sparse Jacobian";
  if (why) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_cont_alloc: %s", why);
    return NULL;
  }
  whirl_cont *c = calloc(1, sizeof *c);
  if (!c) goto nomem;
  c->sys = *sys;
  c->opt = *opt;
  c->n = sys->n;
  c->N = sys->n + 1;
  c->npar = sys->npar;
  c->sparse = opt->linsol == WHIRL_LINSOL_SPARSE;
  if (opt->structured && sys->bsolver) {
    c->bs = sys->bsolver;
    c->bws = c->bs->alloc(sys->data);
    if (!c->bws) goto nomem;
  } else {
    c->bd = whirl_bordered_alloc(c->sparse ? WHIRL_LINSOL_SPARSE : WHIRL_LINSOL_DENSE,
                                 c->n, 1, sys->Jp, sys->Ji);
    if (!c->bd) goto nomem;
  }
  if (c->sparse) {
    c->Jx = calloc(sys->nnz, sizeof *c->Jx);
    if (!c->Jx) goto nomem;
  } else {
    c->J = calloc(c->n * c->n, sizeof *c->J);
    if (!c->J) goto nomem;
  }
  c->wlen = 2 * c->n + sys->nnz + 8;
  c->fp = calloc(c->n, sizeof *c->fp);
  c->f = calloc(c->n, sizeof *c->f);
  c->rhs = calloc(c->N, sizeof *c->rhs);
  c->row = calloc(c->N, sizeof *c->row);
  c->row2 = calloc(c->N, sizeof *c->row2);
  c->sph = calloc(c->N, sizeof *c->sph);
  c->work = calloc(c->wlen, sizeof *c->work);
  c->dir = calloc(c->N, sizeof *c->dir);
  c->w2 = calloc(c->N, sizeof *c->w2);
  c->xw2 = calloc(c->n ? c->n : 1, sizeof *c->xw2);
  c->Xprev = calloc(c->N, sizeof *c->Xprev);
  c->Xref = calloc(c->N, sizeof *c->Xref);
  c->ref_p = calloc(c->npar ? c->npar : 1, sizeof *c->ref_p);
  c->tprev = calloc(c->N, sizeof *c->tprev);
  c->Xstart = calloc(c->N, sizeof *c->Xstart);
  c->Xfact = calloc(c->N, sizeof *c->Xfact);
  c->pfact = calloc(c->npar ? c->npar : 1, sizeof *c->pfact);
  if (!c->fp || !c->f || !c->rhs || !c->row || !c->row2 || !c->sph || !c->work || !c->dir || !c->w2 ||
      !c->xw2 || !c->Xprev || !c->Xref || !c->ref_p || !c->tprev || !c->Xstart || !c->Xfact || !c->pfact)
    goto nomem;
  if (set_weights(c, opt)) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_cont_alloc: %s", c->errmsg);
    c->opt.nuz = 0; /* uz, uz_stop: still the caller's */
    whirl_cont_free(c);
    return NULL;
  }
  c->opt.x_weight = NULL; /* copied: the caller's array need not outlive c */
  /* a step's events: LP, BP, HB, PD, two bounds, the user values and the
   * system's tests; the queue holds their localisations (tail) and what
   * is emitted (head) */
  const size_t maxev = 6 + opt->nuz + (sys->test ? sys->ntest : 0);
  c->evs = calloc(maxev, sizeof *c->evs);
  c->qcap = 2 * (maxev + 2);
  c->queue = calloc(c->qcap, sizeof *c->queue);
  if (!c->queue || !c->evs) goto nomem;
  if (state_alloc(c, &c->cur) || state_alloc(c, &c->trial) ||
      state_alloc(c, &c->out) || state_alloc(c, &c->locbest))
    goto nomem;
  for (size_t i = 0; i < c->qcap; ++i)
    if (state_alloc(c, &c->queue[i])) goto nomem;
  if (opt->loc_epss > 0.0) {
    c->autopts = calloc(maxev, sizeof *c->autopts);
    if (!c->autopts) goto nomem;
    c->nautopts = maxev;
    for (size_t i = 0; i < maxev; ++i)
      if (state_alloc(c, &c->autopts[i])) goto nomem;
  }
  if (opt->nuz) {
    double *uz = malloc(opt->nuz * sizeof *uz);
    if (!uz) goto nomem;
    memcpy(uz, opt->uz, opt->nuz * sizeof *uz);
    c->opt.uz = uz;
    int *stop = calloc(opt->nuz, sizeof *stop);
    if (!stop) goto nomem;
    if (opt->uz_stop) memcpy(stop, opt->uz_stop, opt->nuz * sizeof *stop);
    c->opt.uz_stop = stop;
  }
  return c;
nomem:
  if (c && c->opt.uz == opt->uz) c->opt.uz = NULL; /* not yet owned */
  if (c && c->opt.uz_stop == opt->uz_stop) c->opt.uz_stop = NULL;
  whirl_cont_free(c);
  WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "whirl_cont_alloc: out of memory");
  return NULL;
}

void whirl_cont_free(whirl_cont *c) {
  if (!c) return;
  whirl_bordered_free(c->bd);
  if (c->bs) c->bs->free(c->bws);
  whirl_eig_free(c->eig);
  free(c->J);
  free(c->Jx);
  free(c->fp);
  free(c->f);
  free(c->rhs);
  free(c->row);
  free(c->row2);
  free(c->sph);
  free(c->work);
  free(c->Xfact);
  free(c->pfact);
  free(c->dir);
  free(c->w2);
  free(c->xw2);
  free(c->Xprev);
  free(c->Xref);
  free(c->ref_p);
  free(c->tprev);
  free(c->Xstart);
  state_free(&c->cur);
  state_free(&c->trial);
  state_free(&c->out);
  state_free(&c->locbest);
  if (c->queue)
    for (size_t i = 0; i < c->qcap; ++i) state_free(&c->queue[i]);
  for (size_t i = 0; i < c->nautopts; ++i) state_free(&c->autopts[i]);
  free(c->autopts);
  free(c->queue);
  free(c->evs);
  if (c->opt.nuz) {
    free((double *)c->opt.uz);
    free((int *)c->opt.uz_stop);
  }
  free(c);
}

/* ------------------------------------------------------------ linear algebra */

/* Map a callback status to the corrector's: 0 ok, 2 recoverable (domain or
 * non-finite), < 0 fatal.  (1 is no convergence, 3 a singular matrix.) */
static int classify(whirl_cont *c, int rc, const char *what) {
  if (rc == 0) return 0;
  if (rc > 0 || rc == WHIRL_EBADFUNC) return 2;
  return WHIRL_FAIL(c, WHIRL_EUSER,
                    "%s: callback returned fatal status %d (%s)", what, rc,
                    whirl_strerror(rc));
}

/* F_x (dense or sparse values) and F_p at (x, p). */
static int eval_jac(whirl_cont *c, const double *x, const double *p) {
  int rc;
  if (c->sparse) {
    rc = c->sys.Fx_sparse(x, p, c->Jx, c->sys.data);
    if (rc == 0)
      for (size_t q = 0; q < c->sys.nnz; ++q)
        if (!isfinite(c->Jx[q])) { rc = WHIRL_EBADFUNC; break; }
  } else {
    rc = whirl_system_jacobian(&c->sys, x, p, c->J, c->work);
    if (!c->sys.Fx && !c->sys.Fx_sparse) c->stats.f_evals += 2 * c->n;
  }
  ++c->stats.jac_evals;
  if ((rc = classify(c, rc, "Jacobian")) != 0) return rc;
  rc = whirl_system_param(&c->sys, x, p, c->opt.icp, c->fp, c->work);
  if (!c->sys.Fp) c->stats.f_evals += 2;
  return classify(c, rc, "parameter derivative");
}

static double weighted_len2(const whirl_cont *c, const double *dir) {
  double all = 0.0;
  for (size_t i = 0; i < c->N; ++i) all += c->w2[i] * dir[i] * dir[i];
  return all;
}

/* Natural-parameter correction applies in a step's corrector only, not in
 * the localisation of special points (whose hyperplanes cross folds) nor
 * for a point's tangent, which the arclength row orients (<row, t> = 1:
 * with the natural row its parameter component would keep the direction's
 * sign, the LP test blind); nor with tangent_from_newton, whose tangent
 * comes from the corrector's factorisation. */
static int natural_row(const whirl_cont *c, const double *dir) {
  if (!(c->opt.natural_corrector > 0) || !c->correcting || c->arclength_only ||
      c->opt.tangent_from_newton)
    return 0;
  const double all = weighted_len2(c, dir);
  return all > 0 && c->w2[c->n] * dir[c->n] * dir[c->n] >= c->opt.natural_corrector * all;
}

/* The constraint row of the corrector: the arclength row W dir; dir
 * itself where that vanishes (the start's Newton at fixed parameter,
 * dir = e_N, when the parameter's weight is 0, THL = {ICP(1): 0}, is the
 * constraint p = p0, not a length); or, with opt.natural_corrector where
 * natural_row allows, the hyperplane of constant parameter through the
 * predicted point, (<W dir, dir> / dir_p) e_p: the same constraint value
 * <row, dir> at the predictor, so the predictor and the step are those of
 * the arclength row, and the system is solved at the predicted parameter. */
static void border_row(const whirl_cont *c, const double *dir, double *row) {
  int zero = 1;
  for (size_t i = 0; i < c->N; ++i) {
    row[i] = c->w2[i] * dir[i];
    zero &= row[i] == 0.0;
  }
  if (zero) {
    memcpy(row, dir, c->N * sizeof *row);
  } else if (natural_row(c, dir)) {
    memset(row, 0, c->n * sizeof *row);
    row[c->n] = weighted_len2(c, dir) / dir[c->n];
  }
}

/* Evaluate the Jacobian at (x, p) and factor [F_x F_p; r^T] with r the
 * weighted direction dir: by the system's structured solver, or by the
 * general (dense or sparse) LU of the assembled matrix; with f (a
 * structured solver with factor_F only), F(x, p) into f from the same
 * evaluations.  Returns 0, 2 for a recoverable model failure, 3 for a
 * singular matrix, < 0 fatal. */
static int jac_factor_F(whirl_cont *c, const double *x, const double *p,
                        const double *dir, double *f) {
  border_row(c, dir, c->row);
  int rc;
  c->fact_ok = 0;
  memcpy(c->Xfact, x, c->N * sizeof *c->Xfact);
  memcpy(c->pfact, p, c->npar * sizeof *c->pfact);
  if (c->bs) {
    ++c->stats.jac_evals;
    ++c->stats.factorizations;
    rc = f ? c->bs->factor_F(c->bws, x, p, c->opt.icp, c->row, f)
           : c->bs->factor(c->bws, x, p, c->opt.icp, c->row);
    if (rc == WHIRL_OK) return c->fact_ok = 1, 0;
    if (rc == WHIRL_ESINGULAR) return 3;
    return classify(c, rc, "structured factorisation of the extended Jacobian");
  }
  if ((rc = eval_jac(c, x, p)) != 0) return rc;
  ++c->stats.factorizations;
  rc = whirl_bordered_factor(c->bd, c->sparse ? c->Jx : c->J, c->fp,
                             c->row, &c->row[c->n]);
  if (rc == WHIRL_OK) return c->fact_ok = 1, 0;
  if (rc == WHIRL_ESINGULAR) return 3;
  return WHIRL_FAIL(c, rc, "factorisation of the extended Jacobian: %s",
                    whirl_bordered_errmsg(c->bd));
}

static int jac_factor(whirl_cont *c, const double *x, const double *p,
                      const double *dir) {
  return jac_factor_F(c, x, p, dir, NULL);
}

/* Chord Newton: the held F_x and F_p with the border row row2, when that
 * differs from the row of the factorisation.  Returns as jac_factor, and
 * 4 when the structured solver cannot change its border alone (the caller
 * then factors anew). */
static int reborder(whirl_cont *c) {
  if (memcmp(c->row, c->row2, c->N * sizeof *c->row) == 0) return 0;
  if (c->bs && !c->bs->reborder) return 4;
  memcpy(c->row, c->row2, c->N * sizeof *c->row);
  c->fact_ok = 0;
  int rc;
  ++c->stats.factorizations;
  if (c->bs) {
    rc = c->bs->reborder(c->bws, c->row);
    if (rc == WHIRL_OK) return c->fact_ok = 1, 0;
    if (rc == WHIRL_ESINGULAR) return 3;
    return classify(c, rc, "structured factorisation of the extended Jacobian");
  }
  rc = whirl_bordered_factor(c->bd, c->sparse ? c->Jx : c->J, c->fp, c->row,
                             &c->row[c->n]);
  if (rc == WHIRL_OK) return c->fact_ok = 1, 0;
  if (rc == WHIRL_ESINGULAR) return 3;
  return WHIRL_FAIL(c, rc, "factorisation of the extended Jacobian: %s",
                    whirl_bordered_errmsg(c->bd));
}

/* Solve with the last factorisation, b[N] in place. */
static int ext_solve(whirl_cont *c, double *b, const char *what) {
  int rc = c->bs ? c->bs->solve(c->bws, b, 1)
                 : whirl_bordered_solve(c->bd, b, 1, 0);
  if (rc == WHIRL_OK) return 0;
  return WHIRL_FAIL(c, rc, "%s: %s", what,
                    c->bs ? whirl_strerror(rc) : whirl_bordered_errmsg(c->bd));
}

int cont_factor_at(whirl_cont *c, const double *X, const double *p, const double *dir) {
  return jac_factor(c, X, p, dir);
}

int cont_solve_ext(whirl_cont *c, double *b, int trans) {
  if (!trans) return ext_solve(c, b, "bordered solve");
  if (c->bs && !c->bs->solve_t) return WHIRL_EINVAL; /* no transposed solve */
  const int rc = c->bs ? c->bs->solve_t(c->bws, b, 1) : whirl_bordered_solve(c->bd, b, 1, 1);
  if (rc == WHIRL_OK) return 0;
  return WHIRL_FAIL(c, rc, "transposed bordered solve: %s",
                    c->bs ? whirl_strerror(rc) : whirl_bordered_errmsg(c->bd));
}

/* ------------------------------------------------------------ corrector */

/* F at the iterate (X, p) into c->f, a failure classified as the
 * corrector's. */
static int eval_F(whirl_cont *c, const double *X, const double *p) {
  const int rc = whirl_system_eval(&c->sys, X, p, c->f);
  ++c->stats.f_evals;
  return classify(c, rc, "F");
}

/* After jac_factor_F made F with the Jacobian (status rc): the corrector's
 * status as if F had been evaluated first, as eval_F and then jac_factor
 * would return.  A failed factorisation evaluates F alone, whose failure
 * is then the one reported; F made but not finite is eval_F's failure. */
static int fused_F_status(whirl_cont *c, const double *X, const double *p, int rc) {
  if (rc != 0) {
    const int rf = eval_F(c, X, p);
    return rf != 0 ? rf : rc;
  }
  ++c->stats.f_evals;
  ++c->stats.f_fused;
  for (size_t i = 0; i < c->n; ++i)
    if (!isfinite(c->f[i])) {
      c->fact_ok = 0;
      return classify(c, WHIRL_EBADFUNC, "F");
    }
  return 0;
}

/* Newton's method on the extended system; with chord Newton
 * (opt.newton_chord) the factorisation held from the last analysed point
 * or an earlier iterate is kept while the corrections contract by
 * chord_theta per iteration, and made anew at the current iterate when
 * they do not (AUTO-07p freezes the Jacobian after NWTN iterations in the
 * same spirit).  Its iterations are cheap: F and one solve. */
int cont_correct(whirl_cont *c, const double *X0, const double *dir, double s,
                 double *X) {
  const size_t n = c->n, N = c->N;
  const int chord = c->opt.newton_chord;
  double *p = c->trial.p;
  double prev = INFINITY;
  int fresh = !chord || !c->fact_ok; /* factor at the next iterate */
  int refreshed = 0; /* factorisations made during this correction */
  memcpy(p, c->cur.p, c->npar * sizeof *p);
  /* AUTO's equilibria: the sphere |X - X0|_w = s about the last point,
   * linearised at each iterate (row 2 w (X - X0) / s) */
  const int sphere = c->opt.arclength_sphere && c->correcting && s != 0.0 &&
                     !c->switch_step && !natural_row(c, dir);
  if (chord || c->opt.newton_full > 0) border_row(c, dir, c->row2);
  if (c->sys.direction) {
    const int rc = c->sys.direction(dir, c->sys.data);
    if (rc != 0)
      return WHIRL_FAIL(c, rc < 0 ? rc : WHIRL_EINVAL,
                        "the system's direction callback failed (%d)", rc);
  }
  for (int it = 1; it <= c->opt.newton_maxit; ++it) {
    p[c->opt.icp] = X[n];
    /* AUTO's NWTN: a new Jacobian at the first iterations only */
    if (!chord && (c->opt.newton_full <= 0 || it <= c->opt.newton_full)) fresh = 1;
    /* F from the new Jacobian's own evaluations where the structured
     * solver makes it (factor_F), else evaluated first */
    const int fused = fresh && c->bs && c->bs->factor_F;
    int rc = 0;
    if (!fused && (rc = eval_F(c, X, p)) != 0) return rc;
    if (sphere) {
      for (size_t i = 0; i < N; ++i) c->sph[i] = 2.0 * (X[i] - X0[i]) / s;
      dir = c->sph;
      border_row(c, dir, c->row2);
    }
    if (!fresh && (rc = reborder(c)) == 4) fresh = 1;
    else if (rc != 0) return rc;
    if (fresh) {
      rc = jac_factor_F(c, X, p, dir, fused ? c->f : NULL);
      if (fused) rc = fused_F_status(c, X, p, rc);
      /* singular at a later iterate: Newton has wandered off onto a
       * singular point, a failure to converge, not a singular start */
      if (rc != 0) return rc == 3 && it > 1 ? 1 : rc;
      fresh = 0;
      ++refreshed;
      prev = INFINITY;
    }
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) c->rhs[i] = c->f[i];
    for (size_t i = 0; i < N; ++i) acc += c->row[i] * (X[i] - X0[i]);
    /* the sphere's residual |X - X0|²_w / s − s (its row gives twice it) */
    c->rhs[n] = sphere ? 0.5 * acc - s : acc - s;
    if ((rc = ext_solve(c, c->rhs, "bordered solve")) != 0) return rc;
    ++c->stats.newton_its;
    double dmax = 0.0, xmax = 0.0;
    /* the part to newton_tol: x less its free parameters, or all of X */
    const int by_parts = c->opt.newton_tol_par > 0;
    const size_t nx = by_parts ? n - c->opt.newton_par_tail : N;
    if (c->opt.newton_scale_before) /* AUTO's NEWTONBV: the iterate's scale */
      for (size_t i = 0; i < nx; ++i) {
        const double x = fabs(X[i]);
        if (x > xmax) xmax = x;
      }
    for (size_t i = 0; i < N; ++i) {
      X[i] -= c->rhs[i];
      if (!isfinite(X[i])) return 1;
    }
    /* comparisons, not fmax: a library call per entry at -O2 */
    for (size_t i = 0; i < nx; ++i) {
      const double d = fabs(c->rhs[i]);
      if (d > dmax) dmax = d;
    }
    if (!c->opt.newton_scale_before)
      for (size_t i = 0; i < nx; ++i) {
        const double x = fabs(X[i]);
        if (x > xmax) xmax = x;
      }
    c->its = it; /* iterations used, read by the step control */
    /* the parameters to their own scales (AUTO's EPSL), scaled onto x's test */
    const double tolx = c->opt.newton_tol * (1.0 + xmax);
    for (size_t i = nx; by_parts && i <= n; ++i) {
      const double dp = fabs(c->rhs[i]) / (c->opt.newton_tol_par * (1.0 + fabs(X[i])));
      if (dp * tolx > dmax) dmax = dp * tolx;
    }
    int conv = dmax <= tolx;
    if (!conv && chord && isfinite(prev) && dmax < 0.5 * prev) {
      /* chord Newton converges linearly: the error left after this
       * correction is about θ/(1 − θ) times it, θ = dmax/prev the
       * observed contraction (Deuflhard, Newton Methods for Nonlinear
       * Problems, 2004, §2.1) */
      const double th = dmax / prev;
      conv = th / (1.0 - th) * dmax <= tolx;
    }
    if (conv) {
      p[c->opt.icp] = X[n];
      return 0;
    }
    if (!chord) {
      if (it > 2 && dmax > 2.0 * prev) return 1; /* diverging */
    } else if (dmax > c->opt.chord_theta * prev) {
      /* slow contraction: a new Jacobian at the next iterate; diverging
       * with Jacobians of this correction already: give up */
      if (refreshed >= 2 && dmax > 2.0 * prev) return 1;
      fresh = 1;
    }
    prev = dmax;
  }
  return 1;
}

/* ------------------------------------------------------------ analysis */

/* Stability and Hopf test from eigenvalues: unstable count (Re > 0), complex
 * unstable count and the real part of the complex eigenvalue nearest to the
 * imaginary axis. */
static void eigenvalue_tests(cont_state *st, size_t m) {
  double scale = 1.0;
  for (size_t i = 0; i < m; ++i) scale = fmax(scale, hypot(st->re[i], st->im[i]));
  const double tol = 1e-11 * scale;
  int nu = 0, ncu = 0;
  double best = INFINITY;
  for (size_t i = 0; i < m; ++i) {
    if (st->re[i] > tol) ++nu;
    if (fabs(st->im[i]) > 1e-8 * scale) {
      if (st->re[i] > tol) ++ncu;
      if (fabs(st->re[i]) < fabs(best)) best = st->re[i];
    }
  }
  st->n_unstable = nu;
  st->n_cu = ncu;
  if (isfinite(best)) {
    st->has_hb = 1;
    st->psi_hb = best;
  }
}

/* Stability, PD and TR tests from Floquet multipliers (trivial multiplier
 * already left out by the system): unstable count (|mu| > 1), real
 * multipliers below -1 and mu + 1 of the real negative one nearest to -1
 * (PD), complex ones outside the unit circle and |mu| - 1 of the complex one
 * nearest to it (TR).  Multipliers come from an integration at ~1e-11, so
 * the stability margin is 1e-9. */
static void multiplier_tests(cont_state *st, size_t m) {
  const double tol = 1e-9;
  int nu = 0, ncu = 0, nrn = 0;
  double best_tr = INFINITY, best_pd = INFINITY;
  for (size_t i = 0; i < m; ++i) {
    const double r = hypot(st->re[i], st->im[i]);
    const int cplx = fabs(st->im[i]) > 1e-8 * fmax(1.0, r);
    if (r > 1.0 + tol) ++nu;
    if (cplx) {
      if (r > 1.0 + tol) ++ncu;
      if (fabs(r - 1.0) < fabs(best_tr)) best_tr = r - 1.0;
    } else if (st->re[i] < 0.0) {
      if (st->re[i] < -1.0) ++nrn;
      if (fabs(st->re[i] + 1.0) < fabs(best_pd)) best_pd = st->re[i] + 1.0;
    }
  }
  st->n_unstable = nu;
  st->n_cu = ncu;
  st->n_rn = nrn;
  if (isfinite(best_tr)) st->has_hb = 1, st->psi_hb = best_tr;
  if (isfinite(best_pd)) st->has_pd = 1, st->psi_pd = best_pd;
}

/* The tangent at st (and the determinant of the extended Jacobian, psi_lp)
 * without the spectrum: all that the localisation of an LP or a BP needs at
 * its iterates. */
int cont_tangent(whirl_cont *c, cont_state *st, const double *dir) {
  const size_t n = c->n, N = c->N;
  if (st->p != c->trial.p) memcpy(st->p, c->trial.p, c->npar * sizeof *st->p);
  for (size_t k = 0; k < c->npar; ++k)
    if (k != c->opt.icp) st->p[k] = c->cur.p[k];
  st->p[c->opt.icp] = st->X[n];
  int rc = jac_factor(c, st->X, st->p, dir);
  if (rc != 0) return rc;
  /* tangent: [F_x F_p; r^T] z = e_N, then t = z / |z|_w (Keller). */
  memset(st->t, 0, N * sizeof *st->t);
  st->t[n] = 1.0;
  if ((rc = ext_solve(c, st->t, "tangent solve")) != 0) return rc;
  const double nz = cont_norm(c, st->t);
  if (!(nz > 0) || !isfinite(nz)) return 1;
  for (size_t i = 0; i < N; ++i) st->t[i] /= nz;
  if (c->bs)
    c->bs->logdet(c->bws, &st->logdet, &st->sign_det);
  else
    whirl_bordered_logdet(c->bd, &st->logdet, &st->sign_det);
  st->psi_lp = st->t[cont_lead(c)];
  st->tests_valid = 0;
  return 0;
}

/* One step of iterative refinement of the tangent z at st (solved with
 * the factorisation of the iterate X_k before the last correction, off by
 * O(|X − X_k|)) against the residual at X: its first n rows the
 * directional derivative [F_x F_p] z by a central difference (two
 * evaluations of F instead of a Jacobian and a factorisation), which
 * leaves O(|X − X_k|²) and the difference's truncation error.  zmax and
 * xmax: max |z_i| and max |X_i|.  0, 1 (an evaluation failed: a fresh
 * analysis wanted), < 0 fatal. */
static int refine_tangent(whirl_cont *c, cont_state *st, double *z, double zmax,
                          double xmax) {
  const size_t n = c->n, N = c->N, icp = c->opt.icp;
  double *Xe = c->work, *fm = c->work + N, *r = c->rhs;
  const double eps = cbrt(DBL_EPSILON) * (1.0 + xmax) / zmax;
  int rc = 0;
  for (int side = 0; side < 2; ++side) {
    const double e = side ? -eps : eps;
    for (size_t i = 0; i < N; ++i) Xe[i] = st->X[i] + e * z[i];
    st->p[icp] = Xe[n];
    rc = whirl_system_eval(&c->sys, Xe, st->p, side ? fm : c->f);
    ++c->stats.f_evals;
    if (rc) break;
  }
  st->p[icp] = st->X[n];
  if (rc) return 1; /* not fatal here: the fresh analysis says */
  for (size_t i = 0; i < n; ++i) r[i] = -(c->f[i] - fm[i]) / (2.0 * eps);
  double rz = 0.0;
  for (size_t i = 0; i < N; ++i) rz += c->row[i] * z[i];
  r[n] = 1.0 - rz;
  if ((rc = ext_solve(c, r, "tangent refinement")) != 0) return rc;
  for (size_t i = 0; i < N; ++i) z[i] += r[i];
  return 0;
}

/* The tangent at the corrected point st from the corrector's last
 * factorisation, made at the iterate before the last correction (AUTO-07p
 * takes its direction vector and test functions from that factorisation
 * too, FNLPBV and STDRBV): z0 = A(X_k)⁻¹ e_N, off by O(|X − X_k|) ≤
 * newton_tol, refined once (refine_tangent) unless tangent_from_newton
 * is 2 (AUTO's z0 as it is).  The determinant's sign and log|det| are
 * those of the iterate's factorisation: a zero of a test function within
 * |X − X_k| of X moves by as much, and a located special point is
 * analysed afresh (locate.c).  1 (a fresh analysis wanted) when the
 * factorisation is not the corrector's last. */
static int tangent_from_newton(whirl_cont *c, cont_state *st) {
  const size_t n = c->n, N = c->N;
  if (!c->fact_ok || c->opt.newton_chord) return 1;
  double *z = st->t;
  memset(z, 0, N * sizeof *z);
  z[n] = 1.0;
  int rc = ext_solve(c, z, "tangent solve");
  if (rc) return rc;
  double zmax = 0.0, xmax = 0.0;
  for (size_t i = 0; i < N; ++i) { /* comparisons, not fmax (a call an entry) */
    const double az = fabs(z[i]), ax = fabs(st->X[i]);
    if (az > zmax) zmax = az;
    if (ax > xmax) xmax = ax;
  }
  if (!(zmax > 0) || !isfinite(zmax)) return 1;
  if (c->opt.tangent_from_newton != 2 && (rc = refine_tangent(c, st, z, zmax, xmax)) != 0)
    return rc;
  const double nz = cont_norm(c, z);
  if (!(nz > 0) || !isfinite(nz)) return 1;
  for (size_t i = 0; i < N; ++i) z[i] /= nz;
  if (c->bs)
    c->bs->logdet(c->bws, &st->logdet, &st->sign_det);
  else
    whirl_bordered_logdet(c->bd, &st->logdet, &st->sign_det);
  st->psi_lp = z[cont_lead(c)];
  st->tests_valid = 0;
  return 0;
}

/* The spectrum and the system's test functions at st, whose tangent and
 * determinant are computed: the spectrum at (Xs, ps), the point itself or, with
 * tangent_from_newton, the corrector's last iterate (as AUTO takes its
 * Floquet multipliers from the last Newton iteration's factorisation,
 * which a structured solver reuses), and the system's tests at st. */
static int tests_at(whirl_cont *c, cont_state *st, const double *Xs,
                    const double *ps) {
  int rc;
  st->n_unstable = -1;
  st->n_cu = -1;
  st->has_hb = 0;
  st->psi_hb = 0.0;
  st->has_pd = 0;
  st->psi_pd = 0.0;
  st->n_rn = -1;
  st->nspec = 0;
  if (c->opt.stability && c->sys.spectrum && c->sys.nspec) {
    size_t m = c->sys.nspec;
    rc = c->sys.spectrum(Xs, ps, c->sparse || c->bs ? NULL : c->J, st->re, st->im,
                         &m, c->sys.data);
    ++c->stats.eig_evals;
    if (rc == WHIRL_ESINGULAR || rc == WHIRL_ELAPACK || rc == WHIRL_EMAXITER) {
      /* the stability of this point cannot be computed (e.g. the condensed
       * monodromy matrix of an orbit near a homoclinic one overflows): it
       * stays unknown, and no HB/TR/PD is sought across it; the branch
       * itself is unaffected */
      ++c->stats.spectrum_failed;
    } else {
      if ((rc = classify(c, rc, "spectrum")) != 0) return rc;
      st->nspec = m;
      if (c->sys.spectrum_kind == WHIRL_SPEC_MULTIPLIERS)
        multiplier_tests(st, m);
      else
        eigenvalue_tests(st, m);
    }
  }
  if (c->sys.test && c->sys.ntest) {
    for (size_t k = 0; k < c->sys.ntest; ++k) st->ttype[k] = 0;
    rc = c->sys.test(st->X, st->p, st->tau, st->ttype, c->sys.data);
    if ((rc = classify(c, rc, "test functions")) != 0) return rc;
  }
  st->tests_valid = 1;
  return 0;
}

int cont_tests(whirl_cont *c, cont_state *st) {
  return tests_at(c, st, st->X, st->p);
}

int cont_analyse(whirl_cont *c, cont_state *st, const double *dir) {
  int rc = cont_tangent(c, st, dir);
  return rc ? rc : cont_tests(c, st);
}

/* ------------------------------------------------------------ output */

static void fill_point(whirl_cont *c) {
  cont_state *o = &c->out;
  whirl_point *pt = &c->pt;
  pt->index = c->index++;
  pt->type = o->type;
  pt->label = o->label;
  pt->n = c->n;
  pt->npar = c->npar;
  pt->x = o->X;
  pt->p = o->p;
  pt->t = o->t;
  pt->dir = o->has_sec ? o->sec : o->t;
  pt->s = o->s;
  pt->n_unstable = o->n_unstable;
  pt->stable = o->n_unstable < 0 ? -1 : o->n_unstable == 0;
  pt->nspec = o->nspec;
  pt->spec_re = o->re;
  pt->spec_im = o->im;
  pt->test[0] = o->psi_lp;
  pt->test[1] = o->sign_det;
  pt->test[2] = o->has_hb ? o->psi_hb : NAN;
  pt->uz = o->type == WHIRL_PT_UZ ? o->uz : -1;
}

static void push(whirl_cont *c, const cont_state *st, int type) {
  if (c->qlen >= c->qcap) return; /* cannot happen: qcap bounds events */
  cont_state *q = &c->queue[c->qlen++];
  cont_state_copy(c, q, st);
  q->type = type;
  q->label = type == WHIRL_PT_REGULAR ? 0 : ++c->label;
}

static int pop(whirl_cont *c) {
  if (c->qhead >= c->qlen) {
    c->qhead = c->qlen = 0;
    return 0;
  }
  cont_state_copy(c, &c->out, &c->queue[c->qhead++]);
  if (c->qhead >= c->qlen) c->qhead = c->qlen = 0;
  fill_point(c);
  return 1;
}

/* ------------------------------------------------------------ start */

static void reset_run(whirl_cont *c) {
  c->fact_ok = 0;
  c->qlen = c->qhead = 0;
  c->index = 0;
  c->label = 0;
  c->done = 0;
  c->started = 0;
  c->have_prev = 0;
  c->have_tprev = 0;
  c->switch_step = 0;
  c->singular_start = 0;
  c->nskip = 0;
  c->first_hidden = 0;
  c->stop_reason = WHIRL_STOP_NONE;
  c->errmsg[0] = '\0';
}

/* Tell the system a point was accepted (references such as the phase
 * condition of collocation are updated here). */
static int notify_accept(whirl_cont *c, const cont_state *st) {
  if (!c->sys.accept) return 0;
  int rc = c->sys.accept(st->X, st->p, c->sys.data);
  if (rc != 0)
    return WHIRL_FAIL(c, rc < 0 ? rc : WHIRL_EUSER,
                      "the system's accept callback failed (%d)", rc);
  return 0;
}

static int begin(whirl_cont *c, int tests_valid) {
  int rc = notify_accept(c, &c->cur);
  if (rc) return rc;
  c->cur.s = 0.0;
  c->cur.tests_valid = tests_valid;
  memcpy(c->Xstart, c->cur.X, c->N * sizeof *c->Xstart);
  c->ds = fabs(c->opt.ds);
  c->started = 1;
  push(c, &c->cur, WHIRL_PT_EP);
  return WHIRL_OK;
}

static int check_start(whirl_cont *c, const double *x0, const double *p0) {
  if (!x0 || !p0) return WHIRL_FAIL(c, WHIRL_EINVAL, "start: NULL x0 or p0");
  for (size_t i = 0; i < c->n; ++i)
    if (!isfinite(x0[i]))
      return WHIRL_FAIL(c, WHIRL_EINVAL, "start: x0[%zu] is not finite", i);
  for (size_t k = 0; k < c->npar; ++k)
    if (!isfinite(p0[k]))
      return WHIRL_FAIL(c, WHIRL_EINVAL, "start: p0[%zu] is not finite", k);
  return 0;
}

/* The start x0 solves F already but F_x is singular there, so Newton at
 * the fixed parameter fails: a family along which the parameter does not
 * move (a periodic orbit restarted as a boundary-value problem without a
 * phase condition slides along its phase at a fixed period, AUTO's ph1).
 * As AUTO starts from the null vector of [F_x F_p] (STPNBV's NODIR), the
 * tangent is solved with a generic border instead of the parameter's
 * (Keller 1977: any border not orthogonal to the null vector), then
 * turned by the sign of the run's direction (where that null space is
 * two-dimensional, a branch point, and no step from it converges, the
 * first step turns onto a branch: bp_start_retry).  0 when it worked, else
 * the failure stays the caller's. */
static int start_on_solution(whirl_cont *c, int sign) {
  const size_t n = c->n, N = c->N;
  double *f = c->trial.X; /* scratch: N >= n */
  if (c->sys.F(c->cur.X, c->cur.p, f, c->sys.data) != 0) return -1;
  double r = 0.0, xm = 0.0;
  for (size_t i = 0; i < n; ++i) r = fmax(r, fabs(f[i])), xm = fmax(xm, fabs(c->cur.X[i]));
  if (!(r <= c->opt.newton_tol * (1.0 + xm))) return -1;
  for (size_t i = 0; i < N; ++i) /* fixed, generic: no cancellation with a null vector */
    c->dir[i] = 1.0 + 0.5 * sin(1.0 + 2.7 * (double)i);
  const double nw = cont_norm(c, c->dir);
  if (!(nw > 0)) return -1;
  for (size_t i = 0; i < N; ++i) c->dir[i] /= nw;
  if (notify_accept(c, &c->cur) != 0 || cont_analyse(c, &c->cur, c->dir) != 0) return -1;
  if (sign < 0)
    for (size_t i = 0; i < N; ++i) c->cur.t[i] = -c->cur.t[i];
  memcpy(c->dir, c->cur.t, N * sizeof *c->dir);
  return cont_analyse(c, &c->cur, c->dir) == 0 ? 0 : -1;
}

int whirl_cont_start(whirl_cont *c, const double *x0, const double *p0,
                     int dir) {
  reset_run(c);
  int rc = check_start(c, x0, p0);
  if (rc) return rc;
  const size_t n = c->n, N = c->N;
  memcpy(c->cur.p, p0, c->npar * sizeof *p0);
  memcpy(c->cur.X, x0, n * sizeof *x0);
  c->cur.X[n] = p0[c->opt.icp];
  /* Newton at fixed parameter: the constraint row is e_N. */
  memset(c->dir, 0, N * sizeof *c->dir);
  c->dir[n] = 1.0;
  memcpy(c->trial.X, c->cur.X, N * sizeof *c->trial.X);
  /* the start point is corrected by Newton even when the steps use chord
   * Newton: x0 may be far from the branch (unless start_as_given: AUTO's
   * data, point 0 as they are) */
  const int chord = c->opt.newton_chord;
  c->opt.newton_chord = 0;
  if (c->opt.start_as_given) memcpy(c->trial.p, c->cur.p, c->npar * sizeof *p0);
  rc = c->opt.start_as_given ? 0 : cont_correct(c, c->cur.X, c->dir, 0.0, c->trial.X);
  c->opt.newton_chord = chord;
  if (rc < 0) return rc;
  if (rc > 0 && start_on_solution(c, dir) == 0) { /* x0 solves F, F_x singular */
    c->singular_start = 1;
    return begin(c, 1);
  }
  if (rc == 3)
    return WHIRL_FAIL(c, WHIRL_ESINGULAR,
                      "start: F_x is singular at the start point (a fold or "
                      "branch point?); start elsewhere or give a direction");
  if (rc > 0)
    return WHIRL_FAIL(
        c, WHIRL_ENOCONV,
        "start: Newton did not converge at %s = %g from the given x0%s",
        c->sys.p_names ? c->sys.p_names[c->opt.icp] : "p", p0[c->opt.icp],
        rc == 2 ? " (domain error)" : "");
  memcpy(c->cur.X, c->trial.X, N * sizeof *c->cur.X);
  /* references the equations take from the last accepted point (the phase
   * condition of collocation) must be the start point's before its tangent
   * is computed, or the first step runs along the old reference's phase */
  if ((rc = notify_accept(c, &c->cur)) != 0) return rc;
  rc = cont_analyse(c, &c->cur, c->dir);
  if (rc < 0) return rc;
  if (rc > 0 || fabs(c->cur.t[n]) < 1e-12)
    return WHIRL_FAIL(c, WHIRL_ESINGULAR,
                      "start: F_x is singular at the start point (a fold?); "
                      "start elsewhere or give a direction");
  size_t k = cont_lead(c); /* the coordinate that moves with dir */
  if (fabs(c->cur.t[k]) <= c->opt.newton_tol * (1.0 + fabs(c->cur.X[k]))) k = n;
  if ((dir < 0) == (c->cur.t[k] > 0))
    for (size_t i = 0; i < N; ++i) c->cur.t[i] = -c->cur.t[i];
  /* Re-evaluate the tests with the tangent as border so their signs are
   * consistent with the rows used along the branch. */
  memcpy(c->dir, c->cur.t, N * sizeof *c->dir);
  rc = cont_analyse(c, &c->cur, c->dir);
  if (rc != 0)
    return rc < 0 ? rc
                  : WHIRL_FAIL(c, WHIRL_ESINGULAR,
                               "start: singular extended Jacobian");
  return begin(c, 1);
}

int whirl_cont_start_direction(whirl_cont *c, const double *x0,
                               const double *p0, const double *t0) {
  reset_run(c);
  int rc = check_start(c, x0, p0);
  if (rc) return rc;
  const size_t n = c->n, N = c->N;
  memcpy(c->cur.p, p0, c->npar * sizeof *p0);
  memcpy(c->trial.p, p0, c->npar * sizeof *p0);
  memcpy(c->cur.X, x0, n * sizeof *x0);
  c->cur.X[n] = p0[c->opt.icp];
  double nt = 0.0;
  for (size_t i = 0; i < N; ++i) nt += t0[i] * t0[i];
  if (!(nt > 0) || !isfinite(nt))
    return WHIRL_FAIL(c, WHIRL_EINVAL,
                      "start_direction: zero or non-finite direction");
  for (size_t i = 0; i < N; ++i) c->dir[i] = t0[i];
  const double nw = cont_norm(c, c->dir);
  if (!(nw > 0) || !isfinite(nw))
    return WHIRL_FAIL(c, WHIRL_EINVAL, "start_direction: the direction has no "
                      "length in the arclength's weights");
  for (size_t i = 0; i < N; ++i) c->dir[i] /= nw;
  if ((rc = notify_accept(c, &c->cur)) != 0) return rc; /* as in start */
  rc = cont_analyse(c, &c->cur, c->dir);
  if (rc < 0) return rc;
  /* At a branch point the extended matrix is singular: the direction itself
   * is the tangent to follow. */
  if (rc > 0) {
    memcpy(c->cur.t, c->dir, N * sizeof *c->cur.t);
    c->cur.n_unstable = -1;
  } else {
    memcpy(c->cur.t, c->dir, N * sizeof *c->cur.t);
  }
  return begin(c, 0);
}

int whirl_cont_start_switch(whirl_cont *c, const whirl_point *bp, int dir) {
  double phi[64], *ph = c->N <= 64 ? phi : malloc(c->N * sizeof *ph);
  if (!ph) return WHIRL_FAIL(c, WHIRL_ENOMEM, "start_switch: out of memory");
  int rc = whirl_cont_switch_direction(c, bp, dir, ph);
  if (rc == WHIRL_OK) rc = whirl_cont_start_direction(c, bp->x, bp->p, ph);
  /* the first step off a branch point on the hyperplane normal to the
   * switch direction, whatever the corrector (AUTO's BSW in SOLVAE): the
   * sphere about the branch point also meets the branch left */
  c->switch_step = rc == WHIRL_OK;
  if (ph != phi) free(ph);
  return rc;
}

/* The switch direction ph[N] normalised and oriented: dir = +1 is AUTO's
 * direction (AUTO-07p ae.f90, STPRAE), so that the sign of DS chooses the
 * side and not the solver's sign: of the unit vector, the parameter grows
 * where it moves (its rate above newton_tol relative to 1 + |p|), else (a
 * pitchfork: the new branch leaves at a constant parameter) the first
 * state component that moves so grows. */
static void orient_switch(const whirl_cont *c, const whirl_point *bp, int dir, double *ph) {
  const size_t n = c->n, N = c->N;
  double nph = 0.0;
  for (size_t i = 0; i < N; ++i) nph += ph[i] * ph[i];
  nph = sqrt(nph);
  for (size_t i = 0; i < N; ++i) ph[i] /= nph > 0 ? nph : 1.0;
  const double tol = c->opt.newton_tol;
  double key = 0.0;
  if (fabs(ph[n]) > tol * (1.0 + fabs(bp->p[c->opt.icp]))) key = ph[n];
  for (size_t i = 0; i < n && key == 0.0; ++i)
    if (fabs(ph[i]) > tol * (1.0 + fabs(bp->x[i]))) key = ph[i];
  const double sg = (key < 0.0 ? -1.0 : 1.0) * (dir < 0 ? -1.0 : 1.0);
  for (size_t i = 0; i < N; ++i) ph[i] *= sg;
}

/* A large system's switch direction without the dense SVD (n^3: 1.1 s of
 * demo pcl's BVP of 1 206 unknowns): the null vector of [F_x F_p; t^T]
 * (the tangent as border, weighted as the steps' norm) by two steps of
 * inverse iteration with its LU, the structured or sparse one of the
 * steps, as AUTO's STSDRBV.  At a simple branch point that matrix has
 * the one-dimensional null space of the vector of the null plane
 * orthogonal to t; beside it (the located point) a singular value as
 * small as the distance, so the iterates line up with it.  0, or 1 when
 * the factorisation fails (the caller takes the SVD). */
static int switch_by_inverse_iteration(whirl_cont *c, const whirl_point *bp, double *ph) {
  const size_t n = c->n, N = c->N;
  /* the factorisation's point is (x, p) in one vector of N */
  double *X = malloc(N * sizeof *X);
  if (!X) return 1;
  memcpy(X, bp->x, n * sizeof *X);
  X[n] = bp->p[c->opt.icp];
  const int rc = jac_factor(c, X, bp->p, bp->t);
  free(X);
  if (rc != 0) return 1;
  for (size_t i = 0; i < N; ++i) /* a fixed start with no structure */
    ph[i] = 1.0 + 0.5 * sin(1.7 * (double)i + 0.3);
  for (int k = 0; k < 2; ++k) {
    if (ext_solve(c, ph, "switch direction") != 0) return 1;
    double nph = 0.0;
    for (size_t i = 0; i < N; ++i) nph += ph[i] * ph[i];
    nph = sqrt(nph);
    if (!(nph > 0) || !isfinite(nph)) return 1;
    for (size_t i = 0; i < N; ++i) ph[i] /= nph;
  }
  c->fact_ok = 0; /* the steps factor anew */
  return 0;
}

int whirl_cont_switch_direction(whirl_cont *c, const whirl_point *bp, int dir,
                                double *ph) {
  const size_t n = c->n, N = c->N;
  if (!bp || bp->n != n || bp->npar != c->npar || !bp->t)
    return WHIRL_FAIL(c, WHIRL_EINVAL,
                      "start_switch: point does not belong to this system");
  if (N > 200) { /* the dense SVD below is n^3 */
    memcpy(c->cur.p, bp->p, c->npar * sizeof *bp->p);
    if (switch_by_inverse_iteration(c, bp, ph) == 0) {
      orient_switch(c, bp, dir, ph);
      return WHIRL_OK;
    }
  }
  double *A = malloc(n * N * sizeof *A), *V = malloc(N * 2 * sizeof *V);
  double sv[2];
  int rc = WHIRL_ENOMEM;
  if (!A || !V) goto done;
  memcpy(c->cur.p, bp->p, c->npar * sizeof *bp->p);
  rc = eval_jac(c, bp->x, bp->p);
  if (rc != 0) {
    rc = rc < 0 ? rc
                : WHIRL_FAIL(c, WHIRL_EDOMAIN,
                             "start_switch: cannot evaluate the Jacobian at "
                             "the branch point");
    goto done;
  }
  if (c->sparse) {
    memset(A, 0, n * N * sizeof *A);
    for (size_t j = 0; j < n; ++j)
      for (int q = c->sys.Jp[j]; q < c->sys.Jp[j + 1]; ++q)
        A[(size_t)c->sys.Ji[q] + n * j] = c->Jx[q];
  } else {
    memcpy(A, c->J, n * n * sizeof *A);
  }
  memcpy(A + n * n, c->fp, n * sizeof *A);
  rc = whirl_null_vectors(n, N, A, 2, V, sv);
  if (rc != WHIRL_OK) {
    rc = WHIRL_FAIL(c, rc, "start_switch: SVD of [F_x F_p] failed");
    goto done;
  }
  /* The null space at a simple branch point is spanned by the two right
   * singular vectors v1, v2 of smallest singular value; the new branch's
   * direction is the vector of that plane orthogonal to the known tangent t,
   * (t.v2) v1 - (t.v1) v2 (Keller 1977; AUTO's STSDRBV: the null vector of
   * [F_x F_p; t^T]).  Not v - (v.t) t: where t is not quite in the plane
   * (a restart whose phase condition refers to the point itself, not to
   * the step before) that leaves t's part outside it in the direction:
   * brc's pitchfork of cycles got a parameter rate of 1e-4 where the
   * symmetry-breaking direction has none, and AUTO's orientation by it
   * chose the mirror branch. */
  double tn = 0.0, t1 = 0.0, t2 = 0.0;
  for (size_t i = 0; i < N; ++i) {
    tn += bp->t[i] * bp->t[i];
    t1 += bp->t[i] * V[i];
    t2 += bp->t[i] * V[N + i];
  }
  tn = sqrt(tn);
  if (hypot(t1, t2) > 0.5 * tn) { /* t in the plane, up to an angle of 60 degrees */
    for (size_t i = 0; i < N; ++i) ph[i] = t2 * V[i] - t1 * V[N + i];
  } else { /* t far from the plane: the vector of it least along t */
    double bestn = -1.0;
    for (int k = 0; k < 2; ++k) {
      const double *v = V + N * (size_t)k;
      double vt = 0.0;
      for (size_t i = 0; i < N; ++i) vt += v[i] * bp->t[i] / tn;
      double nn = 0.0;
      for (size_t i = 0; i < N; ++i) {
        double r = v[i] - vt * bp->t[i] / tn;
        nn += r * r;
      }
      if (nn > bestn) {
        bestn = nn;
        for (size_t i = 0; i < N; ++i) ph[i] = v[i] - vt * bp->t[i] / tn;
      }
    }
  }
  orient_switch(c, bp, dir, ph);
  rc = WHIRL_OK;
done:
  free(A);
  free(V);
  return rc;
}

/* ------------------------------------------------------------ step */

static int sgn(double v) { return (v > 0) - (v < 0); }

/* Distance from point P to the segment [A, B] (weighted norm), and the
 * segment parameter of the nearest point. */
static double seg_dist(const whirl_cont *c, const double *P, const double *A,
                       const double *B, double *u_out) {
  double ab = 0, ap = 0;
  for (size_t i = 0; i < c->N; ++i) {
    const double wi = c->w2[i];
    ab += wi * (B[i] - A[i]) * (B[i] - A[i]);
    ap += wi * (P[i] - A[i]) * (B[i] - A[i]);
  }
  double u = ab > 0 ? ap / ab : 0.0;
  if (u_out) *u_out = u;
  u = u < 0 ? 0 : u > 1 ? 1 : u;
  double d = 0;
  for (size_t i = 0; i < c->N; ++i) {
    const double wi = c->w2[i];
    double r = P[i] - (A[i] + u * (B[i] - A[i]));
    d += wi * r * r;
  }
  return sqrt(d);
}


static int finish(whirl_cont *c, int reason) {
  c->done = 1;
  c->stop_reason = reason;
  if (!c->errmsg[0])
    snprintf(c->errmsg, sizeof c->errmsg, "branch ended: %s",
             whirl_stop_reason_name(reason));
  return 0;
}

/* The second-order predictor (opt.curved_predictor): the curve near cur as
 * X(σ) = X + σ t + σ²/2 κ, κ = (t − t_prev) / h the rate of change of the
 * unit tangent over the last step (length h), taken at the σ where it meets
 * the constraint hyperplane <dir, X − X_cur> = ds (one Newton step on the
 * quadratic from σ = ds / <dir, t>).  The corrector then starts O(ds³) from
 * the curve instead of O(ds²). */
static void curved_guess(whirl_cont *c) {
  const size_t N = c->N;
  const double *t = c->cur.t, *tp = c->tprev, h = c->hprev, ds = c->ds;
  double b = cont_dot(c, c->dir, t), a = 0.0;
  if (!(b > 0.1)) return; /* the hyperplane nearly contains the tangent */
  for (size_t i = 0; i < N; ++i) a += c->w2[i] * c->dir[i] * (t[i] - tp[i]);
  a *= 0.5 / h;
  double sg = ds / b;
  const double d = 2.0 * a * sg + b;
  if (d > 0.0) sg -= (a * sg * sg + b * sg - ds) / d;
  if (!(sg > 0.0) || !isfinite(sg)) return;
  const double q = 0.5 * sg * sg / h;
  for (size_t i = 0; i < N; ++i)
    c->trial.X[i] = c->cur.X[i] + sg * t[i] + q * (t[i] - tp[i]);
}

/* The system may change the representation of its unknowns between steps
 * (a new collocation mesh), once every point of the last step has been
 * handed out. */
/* Tests that compare a point's determinant, spectrum or system tests
 * with the next point's: after a change of representation they need the
 * current point analysed anew. */
static int needs_reanalysis(const whirl_cont *c) {
  const whirl_cont_options *o = &c->opt;
  return o->detect_bp || o->detect_hb || o->detect_pd ||
         (o->detect_sys && c->sys.test && c->sys.ntest);
}

static int remap_if_asked(whirl_cont *c) {
  const size_t N = c->N;
  double *v[5] = {c->cur.X, c->cur.t, c->Xstart, c->Xprev, c->tprev};
  size_t nv = c->have_tprev ? 5 : c->have_prev ? 4 : 3;
  int rc = c->sys.remap(v, nv, c->cur.p, c->sys.data);
  if (rc < 0)
    return WHIRL_FAIL(c, rc, "the system's remap callback failed (%d)", rc);
  if (rc != 1) return 0;
  c->fact_ok = 0;
  c->remapped = 1;
  if ((rc = apply_weights(c)) != 0) return rc; /* on the new mesh */
  /* the unit tangents (current and previous) stay unit */
  double *tangents[2] = {c->cur.t, c->have_tprev ? c->tprev : NULL};
  for (int k = 0; k < 2 && tangents[k]; ++k) {
    const double nt = cont_norm(c, tangents[k]);
    if (nt > 0 && isfinite(nt))
      for (size_t i = 0; i < N; ++i) tangents[k][i] /= nt;
  }
  memcpy(c->dir, c->cur.t, N * sizeof *c->dir);
  /* the mapped tangent is the tangent on the new mesh (the map is
   * linear), and the LP test is its parameter's rate; the determinant and
   * the spectrum are analysed there anew only when a test compares them
   * with the next point's (whirl's detection after a mesh change), not
   * for the stability or the LP test alone (a Jacobian and a
   * factorisation a mesh change: spb's c.spb.3 made 518 of them) */
  c->cur.psi_lp = c->cur.t[cont_lead(c)];
  if (!needs_reanalysis(c)) return 0;
  rc = cont_analyse(c, &c->cur, c->dir);
  if (rc < 0) return rc;
  /* ... but the mapped tangent kept where the new one leaves it by more
   * than 25 degrees: solved anew at a branch point (the point a step after
   * a BP starts from, when the mesh changes there) the tangent is any
   * vector of the two-dimensional null space, and the next step went along
   * the other branch (tor's c.tor.2 and pen's doubled rotations: the step
   * from the BP rejected down to 4e-5, then off); elsewhere the two agree
   * to the interpolation error */
  if (cont_dot(c, c->cur.t, c->dir) < 0.9) {
    memcpy(c->cur.t, c->dir, N * sizeof *c->cur.t);
    c->cur.psi_lp = c->cur.t[cont_lead(c)];
  }
  if (rc > 0)
    return WHIRL_FAIL(c, WHIRL_ESINGULAR,
                      "the current point is singular "
                      "after the system's change of representation (remap)");
  return 0;
}

/* The current point after a change of representation (a new mesh) is the
 * old one interpolated, a solution of the new discretisation only to the
 * interpolation error; where that error is large (an orbit near a
 * homoclinic one, whose fast excursion the new mesh moves) the next step's
 * corrector must remove it as well as follow the branch, and fails at every
 * step length down to DSMIN (AUTO-07p has the same weakness: its ADAPT
 * interpolates and steps on).  So when a step after a remap fails, the
 * current point is first corrected on the new representation, on the
 * hyperplane through it normal to the direction (a step of length 0), with
 * twice the corrector's iterations; then the step is retried at the same
 * length.  0: corrected; 1: not (the step is halved as before). */
static int recorrect_remapped(whirl_cont *c) {
  const size_t N = c->N;
  c->remapped = 0;
  memcpy(c->trial.X, c->cur.X, N * sizeof *c->trial.X);
  const int maxit = c->opt.newton_maxit;
  c->opt.newton_maxit = 2 * maxit;
  int rc = cont_correct(c, c->cur.X, c->dir, 0.0, c->trial.X);
  c->opt.newton_maxit = maxit;
  if (rc != 0) return rc < 0 ? rc : 1;
  memcpy(c->cur.X, c->trial.X, N * sizeof *c->cur.X);
  c->cur.p[c->opt.icp] = c->cur.X[c->n];
  ++c->stats.recorrected;
  if (!needs_reanalysis(c)) return 0;
  rc = cont_analyse(c, &c->cur, c->dir); /* the tests at the corrected point */
  return rc < 0 ? rc : rc > 0 ? 1 : 0;
}

/* Did the natural-parameter corrector leave the direction of the step?
 * The secant from the current point to the corrected one turns from the
 * step's direction by about half the tangent's turn along a branch that is
 * a graph over the parameter; more than max_angle, and Newton at the
 * predicted parameter has gone past a fold onto another sheet of the
 * branch (or far along this one): the step is corrected again on the
 * arclength hyperplane. */
static int natural_jumped(const whirl_cont *c) {
  double d2 = 0.0, dd = 0.0;
  for (size_t i = 0; i < c->N; ++i) {
    const double d = c->trial.X[i] - c->cur.X[i];
    d2 += c->w2[i] * d * d;
    dd += c->w2[i] * d * c->dir[i];
  }
  const double len = sqrt(d2 * cont_dot(c, c->dir, c->dir));
  return !(len > 0.0 && dd * (c->ds > 0 ? 1 : -1) >= cos(c->opt.max_angle) * len);
}

/* No step from a start on a singular point converged down to DSMIN: at
 * a branch point the null vector it stepped along is in general no
 * branch's tangent, and Newton wanders between the two branches; once,
 * the step again from DS along the branch nearest it (bpstart.c), with no
 * tests at the point.  0 when it turned, else the branch ends. */
static int bp_start_retry(whirl_cont *c) {
  /* (steps of rounding size may have been taken: still at the start) */
  if (!c->singular_start || !(c->cur.s <= 1e-3 * fabs(c->opt.ds))) return 1;
  c->singular_start = 0;
  double *u = c->trial.t; /* scratch: N */
  if (cont_bp_start_tangent(c, c->cur.X, c->cur.p, c->cur.t, u) != 0) return 1;
  memcpy(c->cur.t, u, c->N * sizeof *u);
  c->cur.tests_valid = 0;
  c->have_prev = 0;
  c->fact_ok = 0;
  c->ds = fabs(c->opt.ds);
  return 0;
}

/* Predict along the secant (or the tangent), correct, analyse; halve the
 * step on a failure or a turn sharper than max_angle (after a remap, first
 * correct the current point on the new representation: recorrect_remapped).
 * 0 with c->trial the new point, WHIRL_DONE at DSMIN (the branch ends
 * there), < 0 fatal. */
static int predict_correct(whirl_cont *c, double *cosang, int *its) {
  const size_t n = c->n, N = c->N;
  const whirl_cont_options *o = &c->opt;
  int last_fail = 1;
  for (;;) {
    if (fabs(c->ds) < o->ds_min && bp_start_retry(c) == 0) continue;
    if (fabs(c->ds) < o->ds_min) {
      const double pv = c->cur.X[n];
      finish(c, last_fail == 2 ? WHIRL_STOP_DOMAIN : WHIRL_STOP_NOCONV);
      snprintf(c->errmsg, sizeof c->errmsg,
               "branch ended at %s = %.10g: %s", c->sys.p_names ? c->sys.p_names[o->icp] : "p",
               pv, whirl_stop_reason_name(c->stop_reason));
      return WHIRL_DONE;
    }
    if (!o->tangent_predictor && c->have_prev) {
      for (size_t i = 0; i < N; ++i) c->dir[i] = c->cur.X[i] - c->Xprev[i];
      double nd = cont_norm(c, c->dir);
      if (!(nd > 0) || !isfinite(nd)) memcpy(c->dir, c->cur.t, N * sizeof *c->dir);
      else
        for (size_t i = 0; i < N; ++i) c->dir[i] /= nd;
    } else {
      memcpy(c->dir, c->cur.t, N * sizeof *c->dir);
    }
    for (size_t i = 0; i < N; ++i) c->trial.X[i] = c->cur.X[i] + c->ds * c->dir[i];
    if (o->curved_predictor && c->have_prev && c->have_tprev && c->hprev > 0.0)
      curved_guess(c);
    c->correcting = 1; /* the step's corrector (not a localisation's) */
    const int natural = natural_row(c, c->dir);
    int rc = cont_correct(c, c->cur.X, c->dir, c->ds, c->trial.X);
    c->correcting = 0;
    if (rc < 0) return rc;
    if (natural && (rc > 0 || natural_jumped(c))) {
      /* at the predicted parameter Newton failed or went far (a fold
       * ahead, another sheet of the branch): the same step on the
       * arclength hyperplane before a shorter one */
      c->arclength_only = 1;
      continue;
    }
    *its = c->its;
    if (rc == 0 && o->tangent_from_newton) {
      rc = tangent_from_newton(c, &c->trial);
      if (rc == 0) rc = tests_at(c, &c->trial, c->Xfact, c->pfact);
      else if (rc > 0) rc = cont_analyse(c, &c->trial, c->dir);
    } else if (rc == 0) {
      rc = cont_analyse(c, &c->trial, c->dir);
    }
    if (rc < 0) return rc;
    if (rc > 0 && c->remapped) {
      if ((rc = recorrect_remapped(c)) < 0) return rc;
      if (rc == 0) continue;
      rc = 1;
    }
    if (rc > 0) {
      last_fail = rc;
      c->ds *= 0.5;
      ++c->stats.rejected;
      continue;
    }
    *cosang = cont_dot(c, c->cur.t, c->trial.t);
    if (*cosang < cos(o->max_angle) && fabs(c->ds) > 4.0 * o->ds_min) {
      c->ds *= 0.5;
      ++c->stats.rejected;
      continue;
    }
    c->trial.s = c->cur.s + sqrt(cont_dist2(c, c->trial.X, c->cur.X));
    c->arclength_only = 0;
    memcpy(c->trial.sec, c->dir, N * sizeof *c->dir);
    return 0;
  }
}

/* ---- special points: one table of what a step can contain -------------- */

/* Has the test function of event kind EV (instance k) a zero between the
 * accepted point a and the new point b? */
typedef int (*crossing_fn)(const whirl_cont *c, size_t k, const cont_state *a,
                           const cont_state *b);

/* A start point where the lead parameter's rate is zero to newton_tol (the
 * start was oriented by the continuation parameter; AUTO's STPRAE takes
 * the next coordinate there) is itself the turning point: a locus started
 * at the vertex of a curve symmetric in its second parameter (demo int's
 * fold curve at PAR(2) = 0) has no LP in its first step. */
static int crosses_lp(const whirl_cont *c, size_t k, const cont_state *a,
                      const cont_state *b) {
  (void)k;
  const size_t l = cont_lead(c);
  if (c->stats.steps == 0 && fabs(a->psi_lp) <= c->opt.newton_tol * (1.0 + fabs(a->X[l])))
    return 0;
  return a->tests_valid && c->opt.detect_lp && sgn(a->psi_lp) * sgn(b->psi_lp) < 0;
}
static int crosses_bp(const whirl_cont *c, size_t k, const cont_state *a,
                      const cont_state *b) {
  (void)k;
  return a->tests_valid && c->opt.detect_bp && a->sign_det * b->sign_det < 0;
}
double cont_hb_rank_test(const whirl_cont *c, const cont_state *st, int k) {
  const int mult = c->sys.spectrum_kind == WHIRL_SPEC_MULTIPLIERS;
  double scale = 1.0, best[64];
  int have = 0;
  if (k < 1 || k > 64) return NAN;
  for (size_t i = 0; i < st->nspec; ++i)
    scale = fmax(scale, hypot(st->re[i], st->im[i]));
  for (size_t i = 0; i < st->nspec; ++i) { /* the k largest, descending */
    const double r = hypot(st->re[i], st->im[i]);
    if (!(fabs(st->im[i]) > 1e-8 * (mult ? fmax(1.0, r) : scale))) continue;
    double v = mult ? r - 1.0 : st->re[i];
    int j = have < k ? have++ : k;
    if (j == k && !(v > best[k - 1])) continue;
    if (j == k) j = k - 1;
    while (j > 0 && best[j - 1] < v) { best[j] = best[j - 1]; --j; }
    best[j] = v;
  }
  return have == k ? best[k - 1] : NAN;
}

/* The count of complex eigenvalues (multipliers) beyond the boundary
 * changed, and the test nearest the boundary changed sign — or, when
 * another pair became the nearest within the step, the order statistic of
 * that count did (cont_hb_rank_test). */
static int crosses_hb(const whirl_cont *c, size_t k, const cont_state *a,
                      const cont_state *b) {
  (void)k;
  if (!(a->tests_valid && c->opt.detect_hb && a->n_cu >= 0 && b->n_cu >= 0 &&
        a->n_cu != b->n_cu && a->has_hb && b->has_hb))
    return 0;
  if (sgn(a->psi_hb) * sgn(b->psi_hb) < 0) return 1;
  const int r = a->n_cu > b->n_cu ? a->n_cu : b->n_cu;
  return sgn(cont_hb_rank_test(c, a, r)) * sgn(cont_hb_rank_test(c, b, r)) < 0;
}
double cont_pd_rank_test(const cont_state *st, int k) {
  double best[64];
  int have = 0;
  if (k < 1 || k > 64) return NAN;
  /* the k most negative real parts, ascending: a complex pair about to
   * meet on the negative axis counts by its real part, so the test stays
   * defined (and continuous) through the meeting that precedes many PDs
   * (demo pen's rotations on IAD = 3 steps) */
  for (size_t i = 0; i < st->nspec; ++i) {
    const double v = st->re[i];
    if (!(v < 0.0)) continue;
    int j = have < k ? have++ : k;
    if (j == k && !(v < best[k - 1])) continue;
    if (j == k) j = k - 1;
    while (j > 0 && best[j - 1] > v) { best[j] = best[j - 1]; --j; }
    best[j] = v;
  }
  return have == k ? best[k - 1] + 1.0 : NAN;
}
/* The count of real multipliers below -1 changed, and the one that passed
 * -1 (the k-th most negative, k the larger count: when it moves far in a
 * step, another negative one can be nearer to -1 than it, lor's PD at rho
 * = 229.4 on big steps) is near -1 at both ends, within a factor 10:
 * multipliers computed wildly wrong on an orbit close to a homoclinic loop
 * of a conservative family (demo vhb: true ones 1 and 1, computed -1e8 and
 * -0.5) jump instead, and are no PD. */
static int near_minus_one(double psi) {
  const double mu = psi - 1.0; /* psi = mu + 1 */
  return mu < -0.1 && mu > -10.0;
}
static int crosses_pd(const whirl_cont *c, size_t k, const cont_state *a,
                      const cont_state *b) {
  (void)k;
  if (!(a->tests_valid && c->opt.detect_pd && a->n_rn >= 0 && b->n_rn >= 0 &&
        a->n_rn != b->n_rn))
    return 0;
  const int r = a->n_rn > b->n_rn ? a->n_rn : b->n_rn;
  const double fa = cont_pd_rank_test(a, r), fb = cont_pd_rank_test(b, r);
  return sgn(fa) * sgn(fb) < 0 && near_minus_one(fa) && near_minus_one(fb);
}
static int crosses_pmin(const whirl_cont *c, size_t k, const cont_state *a,
                        const cont_state *b) {
  (void)k;
  const size_t j = cont_lead(c);
  return b->X[j] < c->opt.p_min && a->X[j] >= c->opt.p_min;
}
static int crosses_pmax(const whirl_cont *c, size_t k, const cont_state *a,
                        const cont_state *b) {
  (void)k;
  const size_t j = cont_lead(c);
  return b->X[j] > c->opt.p_max && a->X[j] <= c->opt.p_max;
}
/* A user value passed between a and b, or met exactly at b (a step of 0.1
 * from 0.5 lands on 1 exactly: that point is the UZ; the step after it,
 * from the zero, is no crossing). */
static int crosses_uz(const whirl_cont *c, size_t k, const cont_state *a,
                      const cont_state *b) {
  const int sa = sgn(cont_uz_value(c, k, a) - c->opt.uz[k]);
  const int sb = sgn(cont_uz_value(c, k, b) - c->opt.uz[k]);
  return sa * sb < 0 || (sb == 0 && sa != 0);
}
static int crosses_sys(const whirl_cont *c, size_t k, const cont_state *a,
                       const cont_state *b) {
  (void)c;
  return a->tests_valid && sgn(a->tau[k]) * sgn(b->tau[k]) < 0;
}

static const struct event_kind {
  int ev;             /* what locate.c localises */
  int type;           /* the point's type (system tests: the state says) */
  crossing_fn crosses;
  int bound;          /* ends the branch; kept at b when not localised */
} event_kinds[] = {
    {EV_LP, WHIRL_PT_LP, crosses_lp, 0},     {EV_BP, WHIRL_PT_BP, crosses_bp, 0},
    {EV_HB, WHIRL_PT_HB, crosses_hb, 0},     {EV_PD, WHIRL_PT_PD, crosses_pd, 0},
    {EV_PMIN, WHIRL_PT_EP, crosses_pmin, 1}, {EV_PMAX, WHIRL_PT_EP, crosses_pmax, 1},
    {EV_UZ, WHIRL_PT_UZ, crosses_uz, 0},     {EV_SYS, 0, crosses_sys, 0}};

/* Instances of an event kind: the user values, the system's tests. */
static size_t instances(const whirl_cont *c, int ev) {
  if (ev == EV_UZ) return c->opt.nuz;
  if (ev == EV_SYS) return c->sys.test && c->opt.detect_sys ? c->sys.ntest : 0;
  return 1;
}

static void add_event(whirl_cont *c, size_t *nev, int ev, size_t k, cont_state *st) {
  c->evs[*nev].ev = ev;
  c->evs[*nev].k = k;
  c->evs[*nev].st = st;
  c->evs[*nev].its = c->its;
  c->evs[*nev].next = NULL;
  ++*nev;
  if (c->nskip < sizeof c->skip_ev / sizeof *c->skip_ev) { /* before any is dropped */
    c->skip_ev[c->nskip] = ev;
    c->skip_k[c->nskip] = k;
    c->skip_s[c->nskip++] = st->s;
  }
}

/* opt.auto_steps: is test (ev, k) zero at this step's start, the special
 * point the step starts from?  Not tested then, as AUTO sets a located
 * test function's value to 0, which no sign change follows (LCSPBV). */
static int skipped(const whirl_cont *c, size_t nskip, int ev, size_t k) {
  for (size_t i = 0; i < nskip; ++i)
    if (c->skip_ev[i] == ev && c->skip_k[i] == k) return 1;
  return 0;
}

/* A fold and a branch point in the same step at the same point: the
 * branch turns at a pitchfork it meets (enz's asymmetric branch at the
 * symmetric one).  The fold test, the parameter component of a tangent
 * that is undetermined there, is noisy near the point; the determinant's
 * zero is not: both are reported at the branch point. */
static void fold_at_branch_point(whirl_cont *c, size_t nev) {
  cont_event *e = c->evs;
  if (nev >= 2 && e[0].ev == EV_LP && e[1].ev == EV_BP &&
      sqrt(cont_dist2(c, e[0].st->X, e[1].st->X)) <= 1e-2 * fabs(c->ds))
    cont_state_copy(c, e[0].st, e[1].st);
}

/* A cusp or a merge found by a system test is also a turning point of the
 * fold curve in the continuation parameter: report it once, with its own
 * name (drop the LP at the same arclength). */
static void drop_lp_at(whirl_cont *c, size_t *nev, const cont_state *q) {
  for (size_t i = 0; i < *nev; ++i)
    if (c->evs[i].ev == EV_LP &&
        fabs(c->evs[i].st->s - q->s) <= 1e-6 * fabs(c->ds) + 1e-12) {
      c->evs[i] = c->evs[--*nev];
      return;
    }
}

/* A codimension-two point of a curve found by a system test (a ZH on a
 * Hopf curve) at a branch point of that curve is reported as the BP alone,
 * as AUTO reports one label a point (its first test to change sign; the
 * others, zero there, change no sign): pp3's Hopf curve through the
 * invariant plane u3 = 0. */
static void drop_sys_at_bp(whirl_cont *c, size_t *nev) {
  for (size_t i = 0; i < *nev;) {
    int at_bp = 0;
    for (size_t j = 0; j < *nev && c->evs[i].ev == EV_SYS; ++j)
      at_bp |= c->evs[j].ev == EV_BP &&
               fabs(c->evs[i].st->s - c->evs[j].st->s) <= 1e-6 * fabs(c->ds) + 1e-12;
    if (at_bp) c->evs[i] = c->evs[--*nev];
    else ++i;
  }
}

/* Localise every zero of a test function between cur and trial into the
 * tail of the queue, listed in c->evs in the order of event_kinds, then
 * ordered by arclength.  Returns their number. */
static size_t find_events(whirl_cont *c) {
  const cont_state *a = &c->cur, *b = &c->trial;
  size_t nev = 0, nslot = 0; /* queue tail slots used by localisations */
  const size_t nskip0 = c->nskip; /* the tests zero at a, then those found */
  for (size_t e = 0; e < sizeof event_kinds / sizeof *event_kinds; ++e) {
    const struct event_kind *K = &event_kinds[e];
    const size_t m = instances(c, K->ev);
    if (K->ev == EV_UZ) fold_at_branch_point(c, nev);
    for (size_t k = 0; k < m; ++k) {
      if (skipped(c, nskip0, K->ev, k) || !K->crosses(c, k, a, b)) continue;
      cont_state *q = &c->queue[c->qcap - 1 - nslot++];
      c->loc_next = c->autopts && nslot <= c->nautopts ? &c->autopts[nslot - 1] : NULL;
      c->loc_next_ok = 0;
      if (cont_locate(c, K->ev, k, b, q) != 0) {
        if (!K->bound) continue;
        cont_state_copy(c, q, b); /* not localised: end at the trial point */
      }
      /* a zero at the start point itself, on the first step: the start (a
       * label of an earlier run, or a point where a test function is zero
       * to rounding, as the trivial branch of an eigenvalue problem in
       * its integral condition's parameter) is no special point of this
       * branch; AUTO labels none there.  "Itself" to 1e-4 of the step: a
       * label of an earlier run is its special point only to that run's
       * localisation (abcb's run 4 restarts at the fold locus's LP, a
       * crossing of two families of orbits, and its first step found
       * that BP of orbits 3.5e-5 of the step from the start; 1e-6 until
       * 2026-12-06) */
      if (!K->bound && c->stats.steps == 0 && fabs(q->s - a->s) <= 1e-4 * fabs(c->ds))
        continue;
      if (K->ev == EV_SYS) {
        const int ty = q->ttype[k];
        if (ty == 0 || (ty > 0 && ty < 32 && (c->opt.sys_skip >> ty & 1u))) continue;
        drop_lp_at(c, &nev, q);
      }
      add_event(c, &nev, K->ev, k, q);
      if (c->loc_next_ok) c->evs[nev - 1].next = c->loc_next;
    }
  }
  c->loc_next = NULL;
  drop_sys_at_bp(c, &nev);
  /* the zeros found in this step, after the ones at a */
  memmove(c->skip_ev, c->skip_ev + nskip0, (c->nskip - nskip0) * sizeof *c->skip_ev);
  memmove(c->skip_k, c->skip_k + nskip0, (c->nskip - nskip0) * sizeof *c->skip_k);
  memmove(c->skip_s, c->skip_s + nskip0, (c->nskip - nskip0) * sizeof *c->skip_s);
  c->nskip -= nskip0;
  /* the localisations moved the work parameter vector: restore it */
  c->trial.p[c->opt.icp] = c->trial.X[c->n];
  for (size_t i = 1; i < nev; ++i) /* insertion sort: stable, a handful */
    for (size_t j = i; j > 0 && c->evs[j].st->s < c->evs[j - 1].st->s; --j) {
      cont_event tmp = c->evs[j];
      c->evs[j] = c->evs[j - 1];
      c->evs[j - 1] = tmp;
    }
  return nev;
}

/* Emit the events in order (the localised states are copied from the
 * queue's tail to its head); 1 when one of them ends the branch. */
static int emit_events(whirl_cont *c, size_t nev) {
  for (size_t i = 0; i < nev; ++i) {
    const cont_event *e = &c->evs[i];
    int type = e->ev == EV_SYS ? e->st->ttype[e->k] : event_kinds[e->ev].type;
    /* a complex pair through the unit circle of the multipliers: torus */
    if (type == WHIRL_PT_HB && c->sys.spectrum_kind == WHIRL_SPEC_MULTIPLIERS)
      type = WHIRL_PT_TR;
    e->st->uz = e->ev == EV_UZ ? (int)e->k : -1;
    push(c, e->st, type);
    ++c->stats.special;
    if (e->ev == EV_UZ && c->opt.uz_stop[e->k]) return finish(c, WHIRL_STOP_UZ), 1;
    if (e->ev == EV_PMAX || e->ev == EV_PMIN)
      return finish(c, e->ev == EV_PMAX ? WHIRL_STOP_PMAX : WHIRL_STOP_PMIN), 1;
    if (e->ev == EV_BP && c->opt.stop_at_bp) {
      c->queue[c->qlen - 1].type = WHIRL_PT_BP;
      return finish(c, WHIRL_STOP_BP), 1;
    }
  }
  return 0;
}

/* opt.auto_steps: the step ends at its first special point (and those at
 * the same place), which becomes the trial point the next step starts
 * from; the later ones are dropped, to be found again from there, and the
 * tests zero at it are not tested on the next step.  Returns the events
 * kept; *its, the Newton iterations of the point's last correction, which
 * AUTO's step control reads (those of its last location step: one when
 * that step is short, as at AUTO's tight EPSS, where the localisation is
 * as exact as whirl's; demos abc, int and ezp agree with AUTO so, not when
 * two are assumed). */
static size_t end_at_first_event(whirl_cont *c, size_t nev, int *its) {
  const double s0 = c->evs[0].st->s, tol = 1e-6 * fabs(c->ds) + 1e-12;
  size_t keep = 1;
  while (keep < nev && fabs(c->evs[keep].st->s - s0) <= tol) ++keep;
  /* not tested next: every zero located there, reported or dropped as
   * coincident (a ZH at a BP: drop_sys_at_bp) */
  size_t m = 0;
  for (size_t i = 0; i < c->nskip; ++i)
    if (fabs(c->skip_s[i] - s0) <= tol) {
      c->skip_ev[m] = c->skip_ev[i];
      c->skip_k[m++] = c->skip_k[i];
    }
  c->nskip = m;
  /* a cusp or a merge is a turning point of the lead parameter too
   * (drop_lp_at): its rate is zero there to rounding, whose sign tests
   * nothing on the next step (the cusp's fold locus mu = -2 x^3 stops
   * without turning: an LP at the CP otherwise, by rounding's sign) */
  const cont_event *e0 = &c->evs[0];
  const int ty0 = e0->ev == EV_SYS ? e0->st->ttype[e0->k] : 0;
  if ((ty0 == WHIRL_PT_CP || ty0 == WHIRL_PT_MG) &&
      c->nskip < sizeof c->skip_ev / sizeof *c->skip_ev) {
    c->skip_ev[c->nskip] = EV_LP;
    c->skip_k[c->nskip++] = 0;
  }
  *its = c->evs[0].its;
  /* the branch goes on from AUTO's point where there is one (opt.loc_epss) */
  cont_state_copy(c, &c->trial, c->evs[0].next ? c->evs[0].next : c->evs[0].st);
  return keep;
}

/* A branch started on a bound and heading out ends where it started. */
static int leaves_its_bound(whirl_cont *c) {
  const whirl_cont_options *o = &c->opt;
  const size_t j = cont_lead(c);
  const double pa = c->cur.X[j], pb = c->trial.X[j];
  if (pb > o->p_max && pa <= o->p_max && pa >= o->p_max - 1e-12 * (1.0 + fabs(o->p_max)))
    return finish(c, WHIRL_STOP_PMAX), 1;
  if (pb < o->p_min && pa >= o->p_min && pa <= o->p_min + 1e-12 * (1.0 + fabs(o->p_min)))
    return finish(c, WHIRL_STOP_PMIN), 1;
  return 0;
}

/* Closed branch: the start point lies on the new segment.  Emits the start
 * point again (so the stored polyline closes) and ends; 1 if so. */
static int closes_loop(whirl_cont *c) {
  const size_t N = c->N;
  const cont_state *a = &c->cur, *b = &c->trial;
  if (!c->opt.detect_loop || c->index <= 3) return 0;
  /* the step's length in the norm of the distance and the arclength (the
   * weights: x_weight, the system's own, p_weight) — unweighted, a BVP's
   * node values made it ~sqrt(nodes) too long and a branch passing its
   * start far away "closed" (spb's c.spb.3) */
  double u;
  const double d = seg_dist(c, c->Xstart, a->X, b->X, &u), dlen = sqrt(cont_dist2(c, a->X, b->X));
  if (!(u >= 0.0 && u <= 1.0 && d < 0.05 * dlen && b->s > 4.0 * dlen)) return 0;
  cont_state *q = &c->queue[c->qcap - 1];
  cont_state_copy(c, q, b);
  memcpy(q->X, c->Xstart, N * sizeof *q->X);
  q->p[c->opt.icp] = c->Xstart[c->n];
  q->s = a->s + u * (b->s - a->s);
  /* the stability of the start point is the one already reported */
  push(c, q, WHIRL_PT_EP);
  finish(c, WHIRL_STOP_LOOP);
  return 1;
}

/* sec = (trial - cur) / |trial - cur|_w; 0 where the step has no length. */
static int secant_of_step(const whirl_cont *c, double *sec) {
  for (size_t i = 0; i < c->N; ++i) sec[i] = c->trial.X[i] - c->cur.X[i];
  const double d = cont_norm(c, sec);
  if (!(d > 0) || !isfinite(d)) return 0;
  for (size_t i = 0; i < c->N; ++i) sec[i] /= d;
  return 1;
}

/* The new point itself: regular, or the end at NMX or past x_max. */
static void emit_step_point(whirl_cont *c) {
  cont_state *b = &c->trial;
  const int is_end = c->stats.steps >= c->opt.nmx;
  double xm = 0.0;
  for (size_t i = 0; i < c->n; ++i) { /* comparisons, not fmax (a call an entry) */
    const double ax = fabs(b->X[i]);
    if (ax > xm) xm = ax;
  }
  const int xmax = c->opt.x_max > 0 && xm > c->opt.x_max;
  /* the point's stored direction (opt.point_dir): the one its step was
   * predicted along (kept in b->sec by predict_correct), or its step's
   * secant */
  b->has_sec = c->opt.point_dir == WHIRL_DIR_PREDICTOR ||
               (c->opt.point_dir == WHIRL_DIR_SECANT && secant_of_step(c, b->sec));
  push(c, b, is_end || xmax ? WHIRL_PT_EP : WHIRL_PT_REGULAR);
  b->has_sec = 0;
  if (is_end) finish(c, WHIRL_STOP_NMX);
  else if (xmax) finish(c, WHIRL_STOP_XMAX);
}

/* AUTO-07p's step factor after a step whose corrector took its
 * iterations of at most itnw (ADPTDS, mesh.f90). */
static double auto_step_factor(int its, int itnw) {
  if (its <= 1) return 2.0;
  if (its == 2) return 1.5;
  if (its <= itnw / 2) return 1.1;
  return its >= itnw ? 0.5 : 1.0;
}

/* Accept the trial point and adapt the step: grow after easy steps,
 * shrink after hard ones (its < 0: keep it). */
static int accept_step(whirl_cont *c, int its, double cosang) {
  const size_t N = c->N;
  const whirl_cont_options *o = &c->opt;
  memcpy(c->Xprev, c->cur.X, N * sizeof *c->Xprev);
  c->have_prev = 1;
  c->switch_step = 0;
  memcpy(c->tprev, c->cur.t, N * sizeof *c->tprev);
  c->hprev = c->trial.s - c->cur.s;
  c->have_tprev = 1;
  cont_state_copy(c, &c->cur, &c->trial);
  int rc = notify_accept(c, &c->cur);
  if (rc) return rc;
  if (its < 0) /* the same step again */
    ;
  else if (o->auto_steps)
    c->ds = fmin(auto_step_factor(its, o->newton_maxit) * fabs(c->ds), o->ds_max);
  else if (its <= o->newton_fast && cosang > cos(0.5 * o->max_angle))
    c->ds = fmin(1.5 * fabs(c->ds), o->ds_max);
  else if (its > o->newton_maxit / 2)
    c->ds = fmax(0.7 * fabs(c->ds), o->ds_min);
  pop(c);
  return WHIRL_OK;
}

/* AUTO's step sequence of algebraic branches (EQ_STEP = sphere) */
static int o_auto_algebraic(const whirl_cont *c) {
  return c->opt.auto_steps && c->opt.arclength_sphere;
}

/* One step: WHIRL_OK with its points queued, STEP_HIDDEN when it queued
 * none (opt.hide_first_step), else a status. */
enum { STEP_HIDDEN = 1000 }; /* not a whirl status */
static int step_once(whirl_cont *c) {
  int rc = c->sys.remap ? remap_if_asked(c) : 0;
  double cosang = 1.0;
  int its = 0;
  if (!rc) rc = predict_correct(c, &cosang, &its);
  c->remapped = 0;
  if (rc) return rc;
  if (leaves_its_bound(c)) return WHIRL_DONE;
  size_t nev = find_events(c);
  const int at_event = c->opt.auto_steps && nev > 0;
  if (!at_event) c->nskip = 0; /* the next step tests everything */
  if (at_event) {
    nev = end_at_first_event(c, nev, &its);
    if (c->stats.steps + 1 >= c->opt.nmx) nev = 0; /* AUTO: the end, an EP */
  }
  if (c->opt.hide_first_step && !c->first_hidden) {
    c->first_hidden = 1;
    if (nev == 0) { /* AUTO's CNRLAE stores its second point only */
      rc = accept_step(c, -1, cosang);
      return rc ? rc : STEP_HIDDEN;
    }
  }
  const int ended = emit_events(c, nev) || closes_loop(c);
  ++c->stats.steps;
  if (!ended && !(at_event && nev)) emit_step_point(c);
  /* AUTO's algebraic branches keep DS after a switch's first step off the
   * branch point (CNRLAE takes it before its loop, without ADPTDS): the
   * step grows or shrinks from the next one on (pp2's branch 2: the
   * switch converged in two iterations, and x1.5 parted the steps) */
  if (c->switch_step && o_auto_algebraic(c)) its = -1;
  /* ... and after a special point other than a UZ (CNRLAE adapts DS at
   * regular points and UZs alone): pp2's BP 4, one iteration, doubled it */
  if (at_event && nev && o_auto_algebraic(c) && c->evs[0].ev != EV_UZ) its = -1;
  rc = accept_step(c, its, cosang);
  /* the next step leaves the special point along its tangent (AUTO's
   * secant of its last two location iterates) */
  if (at_event) c->have_prev = 0;
  return rc;
}

int whirl_cont_step(whirl_cont *c) {
  if (!c->started)
    return WHIRL_FAIL(c, WHIRL_EINVAL,
                      "whirl_cont_step: continuation not started");
  if (pop(c)) return WHIRL_OK;
  if (c->done) return WHIRL_DONE;
  int rc;
  while ((rc = step_once(c)) == STEP_HIDDEN) {
  }
  return rc;
}

const whirl_point *whirl_cont_point(const whirl_cont *c) { return &c->pt; }

const whirl_point *whirl_cont_current(whirl_cont *c) {
  if (!c->started) return NULL;
  const size_t index = c->pt.index;
  cont_state_copy(c, &c->out, &c->cur);
  c->out.type = WHIRL_PT_REGULAR;
  c->out.label = 0;
  c->out.has_sec = 0;
  const size_t next = c->index;
  fill_point(c);
  c->index = next;
  c->pt.index = index;
  return &c->pt;
}
int whirl_cont_stop_reason(const whirl_cont *c) { return c->stop_reason; }
const whirl_cont_stats *whirl_cont_get_stats(const whirl_cont *c) { return &c->stats; }
void whirl_cont_reset_stats(whirl_cont *c) { memset(&c->stats, 0, sizeof c->stats); }
const char *whirl_cont_errmsg(const whirl_cont *c) { return c->errmsg; }

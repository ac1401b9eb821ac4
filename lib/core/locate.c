/* lib/core/locate.c — localisation of special points between two accepted
 * continuation points: the zero of a test function along the same
 * pseudo-arclength parametrisation <r, X - X0> = σ is found by the Illinois
 * variant of regula falsi (Dowell & Jarratt 1971), each trial σ corrected by
 * Newton onto the branch.  Test functions: LP, the parameter component of the
 * unit tangent; BP, det [F_x F_p; r^T]; HB, the real part of the complex
 * eigenvalue nearest the imaginary axis; bounds, p - value; UZ, the user
 * quantity (the parameter by default) - value; the
 * system's own test functions (codimension-two points on fold curves).
 * With opt.loc_epss also AUTO-07p's own localisation (LCSPAE, LCSPBV:
 * secant, then Mueller's steps to EPSS), whose end the branch goes on from.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

double cont_uz_value(const whirl_cont *c, size_t k, const cont_state *st) {
  if (!c->opt.uz_fun) return st->X[c->n];
  st->p[c->opt.icp] = st->X[c->n]; /* p may lag X during a correction */
  return c->opt.uz_fun(k, st->X, st->p, c->opt.uz_ctx);
}

static double psi(const whirl_cont *c, int ev, size_t k, const cont_state *st,
                  double ref_logdet) {
  switch (ev) {
  case EV_LP:
    return st->psi_lp;
  case EV_BP: {
    double e = st->logdet - ref_logdet;
    e = e > 700 ? 700 : e < -700 ? -700 : e;
    return st->sign_det * exp(e);
  }
  case EV_HB:
    if (c->hb_rank > 0) return cont_hb_rank_test(c, st, c->hb_rank);
    return st->has_hb ? st->psi_hb : NAN;
  case EV_PD:
    if (c->pd_rank > 0) return cont_pd_rank_test(st, c->pd_rank);
    return st->has_pd ? st->psi_pd : NAN;
  case EV_PMAX:
    return st->X[cont_lead(c)] - c->opt.p_max;
  case EV_PMIN:
    return st->X[cont_lead(c)] - c->opt.p_min;
  case EV_SYS:
    return st->tau[k];
  default:
    return cont_uz_value(c, k, st) - c->opt.uz[k];
  }
}

/* Value of |psi| below which the zero counts as found. */
static double ftol(const whirl_cont *c, int ev, size_t k, const cont_state *st) {
  switch (ev) {
  case EV_LP:
    return 1e-14;
  case EV_BP:
    /* psi is det relative to its value at the step's start: 1e-8 is
     * within about 1e-8 of a step of the branch point, the parameter to
     * 1e-8 of the step's change.  Nearer, the point's error along the null
     * vector (rounding over the smallest singular value, ~ eps / psi)
     * outgrows its distance: the two balance near sqrt(eps).  Iterating
     * on to a bracket of loc_tol ran Newton into the branch point's
     * shrinking basin, where it fails (enz's pitchfork by a fold: a
     * secant iterate at psi = 3e-15, the next one failing, the point
     * lost; 1e-12 until 2026-12-06) */
    return 1e-8;
  case EV_PD:
    return 1e-12;
  case EV_HB: {
    if (c->sys.spectrum_kind == WHIRL_SPEC_MULTIPLIERS) return 1e-12;
    double sc = 1.0;
    for (size_t i = 0; i < st->nspec; ++i) sc = fmax(sc, hypot(st->re[i], st->im[i]));
    return 1e-13 * sc;
  }
  case EV_PMAX:
    return 1e-14 * (1.0 + fabs(c->opt.p_max));
  case EV_PMIN:
    return 1e-14 * (1.0 + fabs(c->opt.p_min));
  case EV_SYS:
    return 0.0; /* the system's scale is unknown: shrink the bracket */
  default:
    return 1e-14 * (1.0 + fabs(c->opt.uz[k]));
  }
}

/* The cubic Hermite interpolant of the step a → b at pseudo-arclength
 * sigma in [0, ds] (dX/dσ = t / <dir, t> at both ends) into H. */
static void hermite(const whirl_cont *c, const cont_state *a, const cont_state *b,
                    double ds, double sigma, double *H) {
  const double u = sigma / ds, u2 = u * u, u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
  const double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  const double da = cont_dot(c, c->dir, a->t), db = cont_dot(c, c->dir, b->t);
  for (size_t i = 0; i < c->N; ++i)
    H[i] = h00 * a->X[i] + h10 * ds * a->t[i] / da + h01 * b->X[i] + h11 * ds * b->t[i] / db;
}

/* The start of Newton at sigma in the bracket [sa, sb] (states Xa, Xb): the
 * chord, plus for a BP the Hermite interpolant's bend over the bracket,
 * H(σ) − chord of H, O(κ (sb − sa)²).  At a transcritical BP the crossing
 * branch lies within about that bend of the chord, and Newton from the
 * chord alone landed on it as often as not (the logistic map's, 5e-4 off). */
static void trial_start(const whirl_cont *c, const cont_state *a, const cont_state *b,
                        int bend, double ds, double sa, double sb, const double *Xa,
                        const double *Xb, double sigma, double *X, double *H) {
  const size_t N = c->N;
  const double u = (sigma - sa) / (sb - sa);
  for (size_t i = 0; i < N; ++i) X[i] = Xa[i] + u * (Xb[i] - Xa[i]);
  const double da = cont_dot(c, c->dir, a->t), db = cont_dot(c, c->dir, b->t);
  if (!bend || !(fabs(da) > 0.1) || !(fabs(db) > 0.1)) return;
  double *Ha = H + N, *Hb = Ha + N;
  hermite(c, a, b, ds, sigma, H);
  hermite(c, a, b, ds, sa, Ha);
  hermite(c, a, b, ds, sb, Hb);
  for (size_t i = 0; i < N; ++i) X[i] += H[i] - (Ha[i] + u * (Hb[i] - Ha[i]));
}

/* Beside a branch point the other branch crosses the hyperplane of the
 * trial too, a distance of about the square root of the distance to the
 * point away (a pitchfork), and the bordered Jacobian there is nearly
 * singular: Newton from the trial start Xs lands on either, or between
 * them, pushed along the null vector by its rounding over the small
 * singular value.  The start is on the chord of the bracket [Xa, Xb] plus
 * the step's bend, its error on the branch about the curvature times the
 * span squared, i.e. at most the span times its part of the whole step's
 * change (step_span); a solution X further from Xs than that (ten times,
 * plus Newton's tolerance) is off the branch (enz's symmetric pitchfork:
 * s1 - s2 = 1e-5 at |psi| = 5e-8, where the bracket was 1.1e-6 wide;
 * brc's BP of cycles: Newton 1e-4 along the asymmetric null vector from a
 * start 2e-4 wide in a step 6e-2 wide, its MAX U(3) and U(4) 3e-5 apart
 * where the orbit has them equal); then the start itself is the point. */
static void on_the_branch(const whirl_cont *c, const double *Xa, const double *Xb,
                          const double *Xs, double step_span, double *X) {
  double span = 0.0, off = 0.0, size = 0.0;
  for (size_t i = 0; i < c->N; ++i) {
    span = fmax(span, fabs(Xb[i] - Xa[i]));
    off = fmax(off, fabs(X[i] - Xs[i]));
    size = fmax(size, fabs(X[i]));
  }
  const double bend = span * fmin(1.0, 10.0 * span / step_span);
  if (off > bend + c->opt.newton_tol * (1.0 + size))
    memcpy(X, Xs, c->N * sizeof *X);
}

/* The references the equations take from the last point (the phase
 * condition of orbits, the integral conditions' UOLD of BVPs) set to X: each
 * trial of a localisation steps from the last trial, as AUTO-07p's LCSPBV
 * (CONTBV, then STEPBV from the current point), so its phase is the last
 * trial's, not the step start's.  At a located orbit the phase decides its
 * values at the mesh nodes (MAX U(i) over them) and, for rotations, its
 * L2-NORM (pen's doubled rotations: BP 4 shifted by 1e-5 of the period
 * against AUTO's, L2-NORM 10.64230 against 10.64248). */
static int set_reference(whirl_cont *c, const double *X) {
  if (!c->sys.accept) return 0;
  double *p = c->ref_p;
  memcpy(p, c->cur.p, c->npar * sizeof *p);
  p[c->opt.icp] = X[c->n];
  return c->sys.accept(X, p, c->sys.data);
}

/* A trial point's tangent, and its tests unless only the tangent's. */
static int trial_analyse(whirl_cont *c, cont_state *st, int tangent_only) {
  return tangent_only ? cont_tangent(c, st, c->dir) : cont_analyse(c, st, c->dir);
}

/* A branch point located at the share u of the step a = c->cur -> b. */
static void bp_point(whirl_cont *c, const cont_state *b, double u, int its_step,
                     cont_state *out) {
  const cont_state *a = &c->cur;
  /* The next step's length: from the point's Newton count (AUTO's, of
   * its last location step) but not from more than the step's own:
   * beside the branch point Newton converges slowly (pen's doubled
   * rotations: 7 iterations at psi 7e-12, and the next step a fraction
   * of the last) */
  if (c->its > its_step) c->its = its_step;
  /* At the branch point [F_x F_p; r^T] is singular and the tangent solved
   * from it is an arbitrary vector of the two-dimensional null space.  The
   * branch's own tangent is smooth through the point: take it from the
   * regular tangents at both ends of the step, interpolated, so that
   * switching (whirl_cont_start_switch) finds the other branch. */
  for (size_t i = 0; i < c->N; ++i) out->t[i] = (1.0 - u) * a->t[i] + u * b->t[i];
  const double nt = sqrt(cont_dot(c, out->t, out->t));
  if (nt > 0 && isfinite(nt))
    for (size_t i = 0; i < c->N; ++i) out->t[i] /= nt;
  out->psi_lp = out->t[cont_lead(c)];
}

/* Mueller's method with bracketing (Muller, MTAC 10 (1956) 208; AUTO-07p's
 * MUELLER, support.f90): the step from s to the root nearest s of the
 * parabola through (s0, q0), (s1, q1) and (s, q); then (s1, q1) becomes
 * (s, q), and (s0, q0) the old (s1, q1) where q changed sign against it,
 * so that (s0, q0) and (s1, q1) keep bracketing the zero. */
static double mueller_step(double *q0, double *q1, double q, double *s0, double *s1,
                           double s) {
  const double h0 = *s0 - s, h1 = *s1 - s, d = h0 * h1 * (h1 - h0);
  const double a = (h1 * h1 * (*q0 - q) - h0 * h0 * (*q1 - q)) / d;
  const double b = (-h1 * (*q0 - q) + h0 * (*q1 - q)) / d;
  double r = 0.0;
  if (a * a > 4.0 * b * q) r = copysign(sqrt(a * a - 4.0 * b * q), a);
  const double step = -2.0 * q / (a + r);
  if (*q1 * q < 0.0) {
    *q0 = *q1;
    *s0 = *s1;
  }
  *q1 = q;
  *s1 = s;
  return step;
}

/* One trial of AUTO's localisation: the step rds from X (last trial, or the
 * step's end) along dir, the unit secant of the last two trials, corrected
 * on the step's own constraint (the sphere of algebraic branches, else the
 * hyperplane), halved on a failure down to DSMIN as AUTO's STEPAE and
 * STEPBV; then its tests.  0, else no point. */
static int auto_trial(whirl_cont *c, const double *X, const double *dir, double *rds,
                      int p_only, int tangent_only, cont_state *out) {
  int rc;
  for (;;) {
    for (size_t i = 0; i < c->N; ++i) out->X[i] = X[i] + *rds * dir[i];
    c->correcting = c->opt.arclength_sphere; /* the step's own corrector */
    rc = cont_correct(c, X, dir, *rds, out->X);
    c->correcting = 0;
    if (rc <= 0) break;
    *rds *= 0.5;
    if (fabs(*rds) < c->opt.ds_min) break;
  }
  if (rc != 0) return rc;
  /* a trial on the singular point itself (its matrix singular to
   * rounding, AUTO's determinant there ~0): 2 */
  if (!p_only && (rc = trial_analyse(c, out, tangent_only)) > 0) return 2;
  return rc;
}

/* AUTO-07p's localisation of a zero of the UZ or LP test between the step's
 * start a and end b (opt.loc_epss; LCSPAE, LCSPBV): a secant step from b,
 * then Mueller's steps, each from the last trial along the secant of the
 * last two (CONTBV's direction; STEPAE's), until the next step would be
 * below EPSS (1 + sqrt|DS DSMAX|): the last trial is the point, within that
 * step of the zero, as AUTO's own (kar's UZ at PAR(1) = 0 is AUTO's at
 * -8.44948e-3, and the branch goes on from there as AUTO's).  After ITMX + 1
 * trials without, no point: AUTO's "possible special point". */
static int locate_auto(whirl_cont *c, int ev, size_t k, const cont_state *b,
                       double ref, double q0, double q1, cont_state *out) {
  const cont_state *a = &c->cur;
  const size_t N = c->N;
  const double hmach = 1e-7; /* AUTO's nudge past the secant's zero */
  const double tol = c->opt.loc_epss * (1.0 + sqrt(fabs(c->opt.ds * c->opt.ds_max)));
  const int its_step = c->its, p_only = ev == EV_UZ;
  const int tangent_only = ev == EV_LP || ev == EV_BP;
  /* AUTO's test values start at 0 (CNRLAE, CNRLBV), so its first step
   * tests nothing: no sign change from 0 (nor the step before an
   * algebraic branch's second point, opt.hide_first_step) */
  if (c->stats.steps == 0) return 1;
  int singular = 0; /* a point on the branch point itself (auto_trial) */
  if (ev == EV_BP) { /* b's determinant with this step's border row too */
    cont_state_copy(c, out, b);
    const int rc = cont_tangent(c, out, c->dir);
    if (rc < 0) return 1;
    singular = rc > 0;
    if (!singular) q1 = psi(c, ev, k, out, ref);
  }
  const double qend = fmax(fabs(q0), fabs(q1));
  /* a step onto the zero exactly (a UZ of a parameter stepped by a
   * fraction of 1 onto 1: AUTO's steps, 1e-7 longer, pass it): b */
  if (q1 == 0.0 && q0 != 0.0) singular = 1;
  else if (!(q0 * q1 < 0.0)) return 1;
  double s0 = 0.0, s1 = c->ds, dsold = c->ds;
  double rds = (1.0 + hmach) * q1 / (q0 - q1) * (s1 - s0), q = q1;
  cont_state_copy(c, out, b);
  int found = singular || fabs(rds) < tol, stepped = 0;
  if (found) c->its = its_step; /* b itself: its step's Newton count */
  double *prev = found ? NULL : malloc(3 * N * sizeof *prev);
  if (!found && !prev) return 1;
  double *dir = prev ? prev + N : NULL, *dir0 = prev ? prev + 2 * N : NULL;
  if (prev) memcpy(dir0, c->dir, N * sizeof *dir0);
  for (int it = 0; !found && it <= c->opt.loc_itmx; ++it) {
    for (size_t i = 0; i < N; ++i) dir[i] = (out->X[i] - (it ? prev[i] : a->X[i])) / dsold;
    const double nd = sqrt(cont_dot(c, dir, dir));
    if (!(nd > 0.0) || !isfinite(nd)) break;
    for (size_t i = 0; i < N; ++i) dir[i] /= nd;
    memcpy(prev, out->X, N * sizeof *prev);
    memcpy(c->dir, dir, N * sizeof *dir); /* the tangent's orientation */
    int rc = set_reference(c, prev); /* CONTBV's UOLDPS: the last trial */
    if (rc >= 0) rc = auto_trial(c, prev, dir, &rds, p_only, tangent_only, out);
    if (rc == 2 && ev == EV_BP) { /* on the branch point itself */
      found = stepped = singular = 1;
      break;
    }
    if (rc != 0) break;
    stepped = 1;
    q = psi(c, ev, k, out, ref);
    if (!isfinite(q)) break;
    dsold = rds;
    rds = (1.0 + hmach) * mueller_step(&q0, &q1, q, &s0, &s1, s1 + rds);
    found = fabs(rds) < tol;
  }
  if (prev) {
    memcpy(c->dir, dir0, N * sizeof *dir0);
    free(prev);
    if (set_reference(c, a->X) < 0) return 1;
  }
  if (!found) return 1;
  /* a fold's test still as large as at the step's ends: a kink (cont_locate) */
  if (stepped && ev == EV_LP && !(fabs(q) <= 0.1 * qend)) return 1;
  if (stepped && p_only && cont_analyse(c, out, c->dir) != 0) return 1;
  if (stepped && !singular && tangent_only && cont_tests(c, out) != 0) return 1;
  if (ev == EV_BP) {
    const double dab = sqrt(cont_dist2(c, b->X, a->X));
    const double u = dab > 0.0 ? sqrt(cont_dist2(c, out->X, a->X)) / dab : 1.0;
    bp_point(c, b, fmin(u, 1.0), its_step, out);
  }
  out->s = a->s + sqrt(cont_dist2(c, out->X, a->X));
  out->p[c->opt.icp] = out->X[c->n];
  return 0;
}

/* The test's values at the step's ends a = c->cur and b, *fa and *fb (a
 * BP's determinant relative to its value at a with this step's border
 * row, *ref its log; out is scratch); 1 where a's cannot be had. */
static int test_at_ends(whirl_cont *c, int ev, size_t k, const cont_state *b,
                        cont_state *out, double *ref, double *fa, double *fb) {
  const cont_state *a = &c->cur;
  *ref = 0.0;
  if (ev == EV_BP) {
    /* the determinant at the start of the step with this step's border row,
     * so both ends use the same row and the ratio is smooth in σ */
    cont_state_copy(c, out, a);
    if (cont_tangent(c, out, c->dir) != 0) return 1;
    *ref = out->logdet;
    *fa = out->sign_det;
  } else {
    if (ev == EV_PD) /* the multiplier that passed -1 (crosses_pd) */
      c->pd_rank = a->n_rn > b->n_rn ? a->n_rn : b->n_rn;
    if (ev == EV_HB) { /* psi_hb when it changes sign, else the order
                          statistic of the count that changed */
      c->hb_rank = 0;
      if (!(psi(c, ev, k, a, 0.0) * psi(c, ev, k, b, 0.0) < 0.0))
        c->hb_rank = a->n_cu > b->n_cu ? a->n_cu : b->n_cu;
    }
    *fa = psi(c, ev, k, a, 0.0);
  }
  *fb = psi(c, ev, k, b, *ref);
  return 0;
}

static int locate_converged(whirl_cont *c, int ev, size_t k, const cont_state *b,
                            cont_state *out);

/* opt.loc_epss: AUTO's point (locate_auto) into c->loc_next, where the
 * branch goes on from as AUTO's, and the zero to convergence into out, the
 * point reported (AUTO's own where that fails); no point where AUTO's
 * localisation finds none.  Else the zero to convergence alone. */
int cont_locate(whirl_cont *c, int ev, size_t k, const cont_state *b,
                cont_state *out) {
  if (!(c->opt.loc_epss > 0.0) || ev == EV_PMIN || ev == EV_PMAX || ev == EV_SYS)
    return locate_converged(c, ev, k, b, out);
  double ref, fa, fb;
  cont_state *at = c->loc_next ? c->loc_next : out;
  if (test_at_ends(c, ev, k, b, at, &ref, &fa, &fb) != 0) return 1;
  const int rca = locate_auto(c, ev, k, b, ref, fa, fb, at);
  if (at == out && rca == 0) return 0;
  const int its = c->its; /* AUTO's, which the next step's length reads */
  const int rc = locate_converged(c, ev, k, b, out);
  /* where AUTO's iteration finds no point (its first step, or ITMX
   * reached: whirl's tests are not all AUTO's functions, a BP's
   * determinant is of the whole system where AUTO's is of the condensed
   * one), whirl's own, the branch going on from it as before */
  if (rca != 0) return rc;
  /* a branch point the converged localisation rejects (a pole of the
   * determinant, r3b's) is none; another test's zero is AUTO's point
   * where that fails */
  if (rc != 0 && ev == EV_BP) return 1;
  if (rc != 0) cont_state_copy(c, out, at);
  c->loc_next_ok = 1;
  c->its = its;
  return 0;
}

static int locate_trials(whirl_cont *c, int ev, size_t k, const cont_state *b,
                         cont_state *out);

/* The zero to convergence (locate_trials), each trial referred to the last
 * (set_reference), and the references given back to the step's start. */
static int locate_converged(whirl_cont *c, int ev, size_t k, const cont_state *b,
                            cont_state *out) {
  memcpy(c->Xref, b->X, c->N * sizeof *c->Xref); /* the first trial's: b */
  const int rc = locate_trials(c, ev, k, b, out);
  const int rr = set_reference(c, c->cur.X);
  return rr < 0 ? rr : rc;
}

static int locate_trials(whirl_cont *c, int ev, size_t k, const cont_state *b,
                         cont_state *out) {
  const cont_state *a = &c->cur;
  const size_t N = c->N;
  const double ds = c->ds;
  double ref, fa, fb;
  int rc;

  if (test_at_ends(c, ev, k, b, out, &ref, &fa, &fb) != 0) return 1;
  if (ev == EV_UZ && fb == 0.0 && fa != 0.0) { /* the step's end is the point */
    cont_state_copy(c, out, b);
    out->s = a->s + sqrt(cont_dist2(c, out->X, a->X));
    out->p[c->opt.icp] = out->X[c->n];
    return 0;
  }
  if (!(fa * fb < 0.0)) return 1;
  const double fend = fmax(fabs(fa), fabs(fb)); /* the test's size at the step's ends */
  const double fa0 = fa, fb0 = fb;

  double sa = 0.0, sb = ds;
  const double stol = c->opt.loc_tol * fmax(1.0, fabs(ds));
  int found = 0;
  /* the states at the two ends of the bracket: each trial starts from the
   * chord between them, not between a and b, which near a branch point on
   * a sharply turning branch is too far for Newton (enz's pitchfork) */
  double *Xa = malloc(7 * N * sizeof *Xa);
  if (!Xa) return 1;
  double *Xb = Xa + N, *Xbest = Xb + N, *Xs = Xbest + N, *H = Xs + N; /* not before the check */
  double sbest = 0.0, fbest = INFINITY, sout = 0.0;
  double fout = INFINITY; /* |psi| at the point returned */
  int its_best = 0;
  const int its_step = c->its; /* the step's own Newton count */
  memcpy(Xa, a->X, N * sizeof *Xa);
  memcpy(Xb, b->X, N * sizeof *Xb);
  double step_span = 0.0; /* the whole step's change, the bend's scale */
  for (size_t i = 0; i < N; ++i) step_span = fmax(step_span, fabs(Xb[i] - Xa[i]));
  /* the bounds and UZ values need p only: the tangent and the spectrum
   * (a factorisation) are computed at the final point alone */
  const int p_only = ev == EV_PMIN || ev == EV_PMAX || ev == EV_UZ;
  /* an LP's or a BP's test function is the tangent's or the determinant's:
   * the spectrum (the costliest part of a point of a large system: a sparse
   * eigensolver) is computed at the final point alone */
  const int tangent_only = ev == EV_LP || ev == EV_BP;

  /* AUTO's stop (opt.loc_count_epss): the trial after which the next step
   * is below its tolerance, whose Newton count sets the next step.  A
   * branch point's alone: beside it the bordered Jacobian is singular and
   * the trials past AUTO's stop need more iterations; elsewhere the last
   * trial's count is AUTO's (int's steps after its UZs) */
  const double count_tol =
      ev == EV_BP
          ? c->opt.loc_count_epss * (1.0 + sqrt(fabs(c->opt.ds * c->opt.ds_max)))
          : 0.0;
  int its_auto = 0, its_last = 0;
  double s_last = 0.0;

  for (int it = 0; it < 100; ++it) {
    double sigma = (sa * fb - sb * fa) / (fb - fa);
    const double lo = fmin(sa, sb), hi = fmax(sa, sb);
    if (!(sigma > lo && sigma < hi)) sigma = 0.5 * (sa + sb);
    if (it > 0 && !its_auto && fabs(sigma - s_last) < count_tol) its_auto = its_last;
    if ((rc = set_reference(c, c->Xref)) < 0) { /* the last trial's */
      found = 0;
      break;
    }
    /* A trial that lands exactly on a singular point (the secant can hit a
     * branch point to the last bit on linear problems) is moved by a tiny
     * fraction of the bracket and tried again; one that lands merely close
     * to a branch point, where Newton's basin shrinks with the distance
     * (the bordered Jacobian is singular there), is replaced by the
     * bracket's midpoint: a bisection step (brc's BP of cycles). */
    rc = 1;
    const double mid = 0.5 * (sa + sb);
    for (int retry = 0; retry < 4 && rc != 0; ++retry) {
      if (retry == 3) sigma = mid;
      else if (retry) sigma += 1e-7 * (hi - lo) * (retry == 1 ? 1.0 : -2.0);
      trial_start(c, a, b, ev == EV_BP, ds, sa, sb, Xa, Xb, sigma, out->X, H);
      memcpy(Xs, out->X, N * sizeof *Xs);
      rc = cont_correct(c, a->X, c->dir, sigma, out->X);
      if (rc == 0 && ev == EV_BP) on_the_branch(c, Xa, Xb, Xs, step_span, out->X);
      if (rc == 0 && !p_only) rc = trial_analyse(c, out, tangent_only);
      if (rc < 0) break;
      /* the offsets are for a start exactly on a singular point (3); a
       * correction that did not converge is tried at the midpoint at once
       * (abcb's fold loci spent 2 x 7 Newton iterations a trial on them
       * beside a branch point of cycles: runs 3 fw and bw 460 and 674
       * iterations, now 320 and 473); beside a branch point the offsets
       * stay (brc's BP of cycles needs them) */
      if (ev != EV_BP && rc != 0 && rc != 3 && retry < 2) retry = 2;
    }
    if (rc != 0) {
      /* Newton fails very close to a singular point (a branch point, where
       * it converges only linearly): keep the best point found so far when
       * the bracket has already shrunk to a small part of the step */
      if (found && fabs(sb - sa) <= 1e-3 * fabs(ds) && fbest <= 1e-6 && ev == EV_BP) {
        /* a branch point's best trial, already analysed, its determinant
         * within 1e-6 of its size at the step's start: that point.  Beside
         * the branch point the bordered Jacobian is nearly singular and
         * amplifies the residual, so Newton from it fails as well (ext's
         * BP at 7.3769: a trial at psi 9e-10, the next failing and every
         * offset below too, and the point lost) */
        cont_state_copy(c, out, &c->locbest);
        c->its = its_best; /* its Newton iterations set the next step */
        sout = sbest;
        fout = fbest;
        rc = 0;
      } else if (found && fabs(sb - sa) <= 1e-3 * fabs(ds)) {
        /* at the singular point itself the tangent solve may fail too
         * (enz's pitchfork by a fold): then a point a little off it */
        static const double off[] = {0.0, 1e-7, -1e-7, 1e-6, -1e-6, 1e-5, -1e-5};
        rc = 1;
        fout = fbest;
        for (size_t j = 0; rc != 0 && j < sizeof off / sizeof *off; ++j) {
          memcpy(out->X, Xbest, N * sizeof *Xbest);
          sout = sbest + off[j] * fabs(ds);
          rc = cont_correct(c, a->X, c->dir, sout, out->X);
          if (rc == 0 && ev == EV_BP) on_the_branch(c, Xa, Xb, Xbest, step_span, out->X);
          if (rc == 0 && !p_only) rc = trial_analyse(c, out, tangent_only);
          if (rc < 0) break;
        }
      }
      if (rc != 0 && found && ev == EV_BP && fabs(sb - sa) <= 1e-2 * fabs(ds) &&
          fbest <= 1e-2) {
        /* Newton fails still further from a branch point where the other
         * branch crosses at a small angle: the best trial, its determinant
         * within 1e-2 of its size at the step's start, is the point to
         * about 1e-2 of the bracket (abcb's run 4 fw by its script, the
         * fold locus's turning point crossed on the second branch: trials
         * failed from 2.5e-3 of the step, at psi 1.5e-3, and the branch
         * point, which the next run starts from, was lost) */
        cont_state_copy(c, out, &c->locbest);
        c->its = its_best;
        sout = sbest;
        fout = fbest;
        rc = 0;
      }
      if (rc != 0) found = 0;
      break;
    }
    const double f = psi(c, ev, k, out, ref);
    if (!isfinite(f)) {
      found = 0;
      break;
    }
    found = 1;
    sout = sigma;
    fout = fabs(f);
    s_last = sigma;
    its_last = c->its;
    memcpy(c->Xref, out->X, N * sizeof *c->Xref); /* the next trial's reference */
    if (fabs(f) < fbest) {
      fbest = fabs(f);
      sbest = sigma;
      memcpy(Xbest, out->X, N * sizeof *Xbest);
      if (ev == EV_BP) {
        cont_state_copy(c, &c->locbest, out);
        its_best = c->its;
      }
    }
    if (f == 0.0 || fabs(f) <= ftol(c, ev, k, out)) break;
    if (f * fb < 0.0) {
      sa = sb;
      fa = fb;
      memcpy(Xa, Xb, N * sizeof *Xa);
    } else {
      fa *= 0.5; /* Illinois: keep the stale end from stalling the secant */
    }
    sb = sigma;
    fb = f;
    memcpy(Xb, out->X, N * sizeof *Xb);
    if (fabs(sb - sa) <= stol) break;
    /* a branch point to 1e-7 of the step (its parameter to 1e-7 of the
     * step's change): nearer, the bordered Jacobian's smallest singular
     * value falls with the distance and Newton stops converging (pen's
     * doubled rotations: 7 iterations at 5e-5 where EPSU asks 1.5e-6,
     * every trial within 1e-9 of the step failing, and the step after
     * the point went onto the crossing branch) */
    if (ev == EV_BP && fabs(sb - sa) <= 1e-7 * fabs(ds)) break;
  }
  free(Xa);
  if (!found) return 1;
  /* A fold's test, the tangent's lead component, passes zero continuously
   * on a smooth branch; one that is still as large as at the step's ends
   * (a tenth of it) where the bracket has shrunk to nothing jumps: a kink
   * of the branch,
   * not a fold (lcbp's locus where the orbits shrink to u = 0 and its
   * equations' |u| is not smooth: AUTO's Newton fails there, MX).  Not a
   * special point, as AUTO labels none where its localisation finds no
   * zero. */
  if (ev == EV_LP && !(fbest <= 0.1 * fend)) return 1;
  /* The determinant passes through a pole, not a zero, where the system
   * itself is singular (r3b at mu = 0: its mu / r2^3 at the second
   * primary, r2 = 0, where the equilibria's circle meets it).  Near a
   * pole s*, |det| ~ K / |s - s*| is at least its smaller value at the
   * step's ends everywhere between them, so no trial comes below that;
   * near a zero the trials do (a zero 1e-9 of the step from its start,
   * lin's trivial branch, still brings |det| to a quarter of the start's).
   * Not a special point: AUTO's localisation finds no zero there and
   * labels nothing. */
  if (ev == EV_BP && !(fbest < fmin(fabs(fa0), fabs(fb0)))) return 1;
  /* ... nor at the point returned, where the bracket closed on the pole:
   * a smooth part beside the pole can bring a trial on the way below the
   * ends' (r3b's run 1 by AUTO's steps: 0.0044 where b's was 0.0086, the
   * bracket closing on the second primary at mu = 0) */
  if (ev == EV_BP && !(fout < fmin(fabs(fa0), fabs(fb0)))) return 1;
  if (p_only && cont_analyse(c, out, c->dir) != 0) return 1;
  if (tangent_only && cont_tests(c, out) != 0) return 1;
  if (its_auto) c->its = its_auto;
  if (ev == EV_BP) bp_point(c, b, fmin(fmax(sout / ds, 0.0), 1.0), its_step, out);
  out->s = a->s + sqrt(cont_dist2(c, out->X, a->X));
  out->p[c->opt.icp] = out->X[c->n];
  return 0;
}

/* lib/core/locate.c — localisation of special points between two accepted
 * continuation points: the zero of a test function along the same
 * pseudo-arclength parametrisation <r, X - X0> = σ is found by the Illinois
 * variant of regula falsi (Dowell & Jarratt 1971), each trial σ corrected by
 * Newton onto the branch.  Test functions: LP, the parameter component of the
 * unit tangent; BP, det [F_x F_p; r^T]; HB, the real part of the complex
 * eigenvalue nearest the imaginary axis; bounds, p - value; UZ, the user
 * quantity (the parameter by default) - value; the
 * system's own test functions (codimension-two points on fold curves).
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

/* A trial point's tangent, and its tests unless only the tangent's. */
static int trial_analyse(whirl_cont *c, cont_state *st, int tangent_only) {
  return tangent_only ? cont_tangent(c, st, c->dir) : cont_analyse(c, st, c->dir);
}

int cont_locate(whirl_cont *c, int ev, size_t k, const cont_state *b,
                cont_state *out) {
  const cont_state *a = &c->cur;
  const size_t N = c->N;
  const double ds = c->ds;
  double ref = 0.0, fa, fb;
  int rc;

  if (ev == EV_BP) {
    /* the determinant at the start of the step with this step's border row,
     * so both ends use the same row and the ratio is smooth in σ */
    cont_state_copy(c, out, a);
    if (cont_tangent(c, out, c->dir) != 0) return 1;
    ref = out->logdet;
    fa = out->sign_det;
  } else {
    if (ev == EV_PD) /* the multiplier that passed -1 (crosses_pd) */
      c->pd_rank = a->n_rn > b->n_rn ? a->n_rn : b->n_rn;
    if (ev == EV_HB) { /* psi_hb when it changes sign, else the order
                          statistic of the count that changed */
      c->hb_rank = 0;
      if (!(psi(c, ev, k, a, ref) * psi(c, ev, k, b, ref) < 0.0))
        c->hb_rank = a->n_cu > b->n_cu ? a->n_cu : b->n_cu;
    }
    fa = psi(c, ev, k, a, ref);
  }
  fb = psi(c, ev, k, b, ref);
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

  for (int it = 0; it < 100; ++it) {
    double sigma = (sa * fb - sb * fa) / (fb - fa);
    const double lo = fmin(sa, sb), hi = fmax(sa, sb);
    if (!(sigma > lo && sigma < hi)) sigma = 0.5 * (sa + sb);
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
        rc = 0;
      } else if (found && fabs(sb - sa) <= 1e-3 * fabs(ds)) {
        /* at the singular point itself the tangent solve may fail too
         * (enz's pitchfork by a fold): then a point a little off it */
        static const double off[] = {0.0, 1e-7, -1e-7, 1e-6, -1e-6, 1e-5, -1e-5};
        rc = 1;
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
  if (p_only && cont_analyse(c, out, c->dir) != 0) return 1;
  if (tangent_only && cont_tests(c, out) != 0) return 1;
  if (ev == EV_BP) {
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
    const double u = fmin(fmax(sout / ds, 0.0), 1.0);
    for (size_t i = 0; i < N; ++i) out->t[i] = (1.0 - u) * a->t[i] + u * b->t[i];
    const double nt = sqrt(cont_dot(c, out->t, out->t));
    if (nt > 0 && isfinite(nt))
      for (size_t i = 0; i < N; ++i) out->t[i] /= nt;
    out->psi_lp = out->t[cont_lead(c)];
  }
  out->s = a->s + sqrt(cont_dist2(c, out->X, a->X));
  out->p[c->opt.icp] = out->X[c->n];
  return 0;
}

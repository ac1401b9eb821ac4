/* lib/core/branch.c — stored branches: copies of the points a continuation
 * produced, joining of the two halves traced from one seed, the distance of a
 * point to a branch (used to tell whether a seed lies on a branch already
 * traced, the basis of complete diagrams with isolas), and the convenience
 * loops whirl_cont_run and whirl_trace_branch.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/branch.h>

whirl_branch *whirl_branch_alloc(size_t n, size_t npar, size_t nspec,
                                 size_t icp) {
  whirl_branch *b = calloc(1, sizeof *b);
  if (!b) return NULL;
  b->n = n;
  b->npar = npar;
  b->nspec = nspec;
  b->icp = icp;
  return b;
}

static void point_free(whirl_branch_point *q) {
  free(q->x);
  free(q->p);
  free(q->spec_re);
  free(q->spec_im);
}

void whirl_branch_free(whirl_branch *b) {
  if (!b) return;
  for (size_t i = 0; i < b->len; ++i) point_free(&b->pts[i]);
  free(b->pts);
  free(b);
}

static int reserve(whirl_branch *b) {
  if (b->len < b->cap) return 0;
  size_t cap = b->cap ? 2 * b->cap : 64;
  whirl_branch_point *np = realloc(b->pts, cap * sizeof *np);
  if (!np) return -1;
  b->pts = np;
  b->cap = cap;
  return 0;
}

static int copy_point(whirl_branch *b, whirl_branch_point *q, int type,
                      int label, int stable, int n_unstable, size_t index,
                      double s, const double *x, const double *p,
                      const double *re, const double *im, size_t nspec) {
  memset(q, 0, sizeof *q);
  q->type = type;
  q->label = label;
  q->stable = stable;
  q->n_unstable = n_unstable;
  q->index = index;
  q->s = s;
  q->x = malloc(b->n * sizeof *q->x);
  q->p = malloc(b->npar * sizeof *q->p);
  if (b->nspec) {
    q->spec_re = calloc(b->nspec, sizeof *q->spec_re);
    q->spec_im = calloc(b->nspec, sizeof *q->spec_im);
  }
  if (!q->x || !q->p || (b->nspec && (!q->spec_re || !q->spec_im))) {
    point_free(q);
    return -1;
  }
  memcpy(q->x, x, b->n * sizeof *x);
  memcpy(q->p, p, b->npar * sizeof *p);
  size_t m = nspec < b->nspec ? nspec : b->nspec;
  if (m) {
    memcpy(q->spec_re, re, m * sizeof *re);
    memcpy(q->spec_im, im, m * sizeof *im);
  }
  return 0;
}

int whirl_branch_append(whirl_branch *b, const whirl_point *pt) {
  if (pt->n != b->n || pt->npar != b->npar) return WHIRL_EINVAL;
  if (reserve(b)) return WHIRL_ENOMEM;
  if (copy_point(b, &b->pts[b->len], pt->type, pt->label, pt->stable,
                 pt->n_unstable, pt->index, pt->s, pt->x, pt->p, pt->spec_re,
                 pt->spec_im, pt->nspec))
    return WHIRL_ENOMEM;
  ++b->len;
  return WHIRL_OK;
}

void whirl_branch_reverse(whirl_branch *b) {
  if (b->len < 2) return;
  const double stot = b->pts[b->len - 1].s;
  for (size_t i = 0, j = b->len - 1; i < j; ++i, --j) {
    whirl_branch_point t = b->pts[i];
    b->pts[i] = b->pts[j];
    b->pts[j] = t;
  }
  for (size_t i = 0; i < b->len; ++i) {
    b->pts[i].s = stot - b->pts[i].s;
    b->pts[i].index = i;
  }
}

int whirl_branch_join(whirl_branch *dst, const whirl_branch *src) {
  if (src->n != dst->n || src->npar != dst->npar) return WHIRL_EINVAL;
  const double s0 = dst->len ? dst->pts[dst->len - 1].s : 0.0;
  for (size_t i = 1; i < src->len; ++i) {
    const whirl_branch_point *q = &src->pts[i];
    if (reserve(dst)) return WHIRL_ENOMEM;
    if (copy_point(dst, &dst->pts[dst->len], q->type, q->label, q->stable,
                   q->n_unstable, dst->len, s0 + q->s, q->x, q->p, q->spec_re,
                   q->spec_im, src->nspec))
      return WHIRL_ENOMEM;
    ++dst->len;
  }
  return WHIRL_OK;
}

/* The parameter's distance to the parameter interval of segment A-B: a
 * lower bound of the distance to the segment in (x, p_icp). */
static double segment_gap(const whirl_branch_point *A, const whirl_branch_point *B,
                          double p, size_t icp) {
  const double a = A->p[icp], b = B->p[icp];
  const double lo = a < b ? a : b, hi = a < b ? b : a;
  return p < lo ? lo - p : p > hi ? p - hi : 0.0;
}

/* The distance from (x, p) to segment A-B, the parameter weighted by w2 =
 * p_weight^2: the nearest point of the segment by projection, clamped. */
static double segment_distance(const whirl_branch_point *A,
                               const whirl_branch_point *B, size_t n,
                               size_t icp, const double *x, const double *p,
                               double w2) {
  double ab = w2 * (B->p[icp] - A->p[icp]) * (B->p[icp] - A->p[icp]);
  double ap = w2 * (p[icp] - A->p[icp]) * (B->p[icp] - A->p[icp]);
  for (size_t i = 0; i < n; ++i) {
    ab += (B->x[i] - A->x[i]) * (B->x[i] - A->x[i]);
    ap += (x[i] - A->x[i]) * (B->x[i] - A->x[i]);
  }
  double u = ab > 0 ? ap / ab : 0.0;
  u = u < 0 ? 0 : u > 1 ? 1 : u;
  double r = p[icp] - (A->p[icp] + u * (B->p[icp] - A->p[icp]));
  double d = w2 * r * r;
  for (size_t i = 0; i < n; ++i) {
    r = x[i] - (A->x[i] + u * (B->x[i] - A->x[i]));
    d += r * r;
  }
  return sqrt(d);
}

/* The segments of b: len - 1 of them, or the one point of a branch of 1. */
static size_t segment_count(const whirl_branch *b) {
  return b->len <= 1 ? b->len : b->len - 1;
}

double whirl_branch_distance(const whirl_branch *b, const double *x,
                             const double *p, double p_weight, size_t *seg) {
  double best = INFINITY;
  const double w = fabs(p_weight);
  for (size_t k = 0; k < segment_count(b); ++k) {
    const whirl_branch_point *A = &b->pts[k];
    const whirl_branch_point *B = b->len == 1 ? A : &b->pts[k + 1];
    /* a segment whose parameter gap alone cannot beat the best so far is
     * skipped: the same minimum and segment, fewer segments computed */
    if (w * segment_gap(A, B, p[b->icp], b->icp) >= best) continue;
    double d = segment_distance(A, B, b->n, b->icp, x, p, w * w);
    if (d < best) {
      best = d;
      if (seg) *seg = k;
    }
  }
  return best;
}

int whirl_branch_within(const whirl_branch *b, const double *x, const double *p,
                        double p_weight, double tol) {
  const double w = fabs(p_weight);
  for (size_t k = 0; k < segment_count(b); ++k) {
    const whirl_branch_point *A = &b->pts[k];
    const whirl_branch_point *B = b->len == 1 ? A : &b->pts[k + 1];
    if (w * segment_gap(A, B, p[b->icp], b->icp) >= tol) continue;
    if (segment_distance(A, B, b->n, b->icp, x, p, w * w) < tol) return 1;
  }
  return 0;
}

/* whirl_cont_run, telling opt->progress (if any) of each point; *points
 * counts the points of the whole branch. */
static int run_told(whirl_cont *c, whirl_branch *b, const whirl_cont_options *opt,
                    size_t *points) {
  int rc;
  while ((rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    int r = whirl_branch_append(b, pt);
    if (r != WHIRL_OK) return r;
    ++*points;
    if (opt && opt->progress) opt->progress(*points, pt->p[opt->icp], opt->progress_ctx);
  }
  if (rc == WHIRL_DONE) b->stop_reason = whirl_cont_stop_reason(c);
  return rc;
}

int whirl_cont_run(whirl_cont *c, whirl_branch *b) {
  size_t points = 0;
  return run_told(c, b, NULL, &points);
}

static void accumulate(whirl_cont_stats *acc, const whirl_cont_stats *s) {
  if (!acc) return;
  acc->steps += s->steps;
  acc->rejected += s->rejected;
  acc->newton_its += s->newton_its;
  acc->f_evals += s->f_evals;
  acc->jac_evals += s->jac_evals;
  acc->factorizations += s->factorizations;
  acc->eig_evals += s->eig_evals;
  acc->special += s->special;
}

int whirl_trace_branch(const whirl_system *sys, const whirl_cont_options *opt,
                       const double *x0, const double *p0, whirl_branch **out,
                       whirl_cont_stats *stats, char *errbuf, size_t errlen) {
  *out = NULL;
  whirl_cont *c = whirl_cont_alloc(sys, opt, errbuf, errlen);
  if (!c) return WHIRL_EINVAL;
  whirl_branch *half[2] = {NULL, NULL};
  int rc = WHIRL_ENOMEM, reasons[2] = {0, 0};
  size_t points = 0;
  for (int h = 0; h < 2; ++h) {
    half[h] = whirl_branch_alloc(sys->n, sys->npar, sys->nspec, opt->icp);
    if (!half[h]) goto done;
    rc = whirl_cont_start(c, x0, p0, h == 0 ? -1 : +1);
    if (rc == WHIRL_OK) rc = run_told(c, half[h], opt, &points);
    accumulate(stats, whirl_cont_get_stats(c));
    whirl_cont_reset_stats(c);
    if (rc < 0) {
      WHIRL_ERRMSG(errbuf, errlen, rc, "%s", whirl_cont_errmsg(c));
      goto done;
    }
    reasons[h] = whirl_cont_stop_reason(c);
    if (reasons[h] == WHIRL_STOP_LOOP) break; /* isola: traced whole */
  }
  /* half[0] runs from the seed towards smaller p: reverse it so the branch
   * is ordered along the curve, then append half[1] */
  whirl_branch_reverse(half[0]);
  if (half[1] && half[1]->len) {
    /* the seed is interior unless one half ended right at it (a seed on a
     * parameter bound, heading out) */
    if (half[0]->len > 1 && half[1]->len > 1) {
      whirl_branch_point *seed = &half[0]->pts[half[0]->len - 1];
      seed->type = WHIRL_PT_REGULAR;
      seed->label = 0;
    }
    if ((rc = whirl_branch_join(half[0], half[1])) != WHIRL_OK) goto done;
  }
  half[0]->stop_reason = reasons[1] ? reasons[1] : reasons[0];
  /* relabel the special points in order along the branch */
  int lab = 0;
  for (size_t i = 0; i < half[0]->len; ++i) {
    half[0]->pts[i].index = i;
    half[0]->pts[i].label = half[0]->pts[i].type != WHIRL_PT_REGULAR ? ++lab : 0;
  }
  *out = half[0];
  half[0] = NULL;
  rc = WHIRL_OK;
done:
  whirl_branch_free(half[0]);
  whirl_branch_free(half[1]);
  whirl_cont_free(c);
  return rc;
}

/* drivers/label_place.c — a place for each special point's name (see
 * label_place.h): each label in turn takes the cheapest of eight places
 * around its point, the cost counting a collision with a label already
 * placed or with another point (heavily), leaving the axes (heavily), and
 * each curve sample under it (lightly), with a small preference for the
 * places nearer the start of the list (right and above, as before).
 * Greedy, as most plotting programs place labels: n is a few dozen.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "label_place.h"

/* The places tried: offset (characters) and justification. */
static const struct {
  double dx, dy;
  int right;
} place[] = {{1, 0.7, 0},  {1, -0.8, 0},  {-1, 0.7, 1},  {-1, -0.8, 1},
             {1, 1.9, 0},  {-1, 1.9, 1},  {1, -2.0, 0},  {-1, -2.0, 1}};
#define NPLACE (sizeof place / sizeof place[0])

/* The label's box in fractions of the axes: [x0, x1] x [y0, y1]. */
static void box(const lp_label *l, double cu, double cv, double b[4]) {
  const double x = l->u + l->dx * cu, w = (double)l->chars * cu;
  b[0] = l->right ? x - w : x;
  b[1] = l->right ? x : x + w;
  b[2] = l->v + (l->dy - 0.5) * cv;
  b[3] = l->v + (l->dy + 0.5) * cv;
}

static int inside(const double b[4], double u, double v, double pad_u, double pad_v) {
  return u >= b[0] - pad_u && u <= b[1] + pad_u && v >= b[2] - pad_v && v <= b[3] + pad_v;
}

int lp_overlap(const lp_label *a, const lp_label *b, double cu, double cv) {
  double p[4], q[4];
  box(a, cu, cv, p);
  box(b, cu, cv, q);
  return p[0] < q[1] && q[0] < p[1] && p[2] < q[3] && q[2] < p[3];
}

/* The cost of label K of L at its current place (labels before K placed). */
static double cost(const lp_label *l, size_t n, size_t k, double cu, double cv,
                   const double *cu_, const double *cv_, size_t nc) {
  double b[4], c = 0;
  box(&l[k], cu, cv, b);
  if (b[0] < 0 || b[1] > 1 || b[2] < 0 || b[3] > 1) c += 1000;
  for (size_t i = 0; i < k; i++)
    if (lp_overlap(&l[i], &l[k], cu, cv)) c += 1000;
  for (size_t i = 0; i < n; i++) /* the markers: half a character round */
    if (i != k && inside(b, l[i].u, l[i].v, 0.4 * cu, 0.3 * cv)) c += 500;
  for (size_t i = 0; i < nc; i++)
    if (inside(b, cu_[i], cv_[i], 0, 0)) c += 1;
  return c;
}

void lp_place(lp_label *l, size_t n, double cu, double cv, const double *curve_u,
              const double *curve_v, size_t nc) {
  for (size_t k = 0; k < n; k++) {
    size_t best = 0;
    double cbest = 0;
    for (size_t j = 0; j < NPLACE; j++) {
      l[k].dx = place[j].dx, l[k].dy = place[j].dy, l[k].right = place[j].right;
      const double c = cost(l, n, k, cu, cv, curve_u, curve_v, nc) + 0.1 * (double)j;
      if (j == 0 || c < cbest) best = j, cbest = c;
    }
    l[k].dx = place[best].dx, l[k].dy = place[best].dy, l[k].right = place[best].right;
  }
}

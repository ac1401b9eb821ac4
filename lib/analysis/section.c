/* lib/analysis/section.c — character of a Poincaré section
 * (whirl_section_classify, whirl/section.h): fixed point, period-k cycle,
 * invariant curve or irregular set; and of the steady state it samples
 * (whirl_steady_classify), which also tells points still converging or
 * moving away.  Points coincide within tol·size + tol,
 * size the largest distance of a point from the centroid.  The period is the
 * smallest k ≤ max_period with every point P_i within that tolerance of
 * P_(i mod k) (so a slow drift is not taken for a cycle).
 *
 * Otherwise the dimension d comes from how nearest-neighbour distances grow
 * with the number of neighbours, r_k ∝ k^(1/d) (equivalently r ∝ n^(−1/d)
 * with the number n of points: the 8th neighbour among a random quarter of
 * the points is on average the 32nd among all of them): with r_8, r_32 the
 * median distances to the 8th and 32nd nearest neighbours, d = log 4 /
 * log(r_32 / r_8).  Why not the 1st neighbour of all points against every
 * 4th point: (a) the points of a quasi-periodic curve are those of an
 * irrational rotation; by the three-distance theorem their gaps take two or
 * three values whose proportions jump with N, and the median 1st-neighbour
 * distances of N and N/4 such points differ by a factor anywhere from ~1 to
 * ~250 (d from 0.25 to over 100 in tests on ellipses, N = 500 … 8000); the
 * 8th and 32nd neighbours span several gaps and average that out; (b) every
 * 4th point of a section with a 2- or 4-fold structure (a period-doubled
 * torus: two curves visited in turn) lies on half or a quarter of it, which
 * doubles d or worse; the k-neighbour ratio uses all points.  In tests on
 * rotations on ellipses, circles and distorted curves (N = 300 … 20000) d is
 * 1 ± 0.1, for uniform points in a square or disk 1.9 … 2.0, for the Hénon
 * attractor 1.2 … 1.35; near-resonant rotations (points in clusters) give
 * d < 1, still a curve.
 * A cycle longer than max_period (every P_i within tolerance of P_(i mod k),
 * max_period < k ≤ npts/2, found among the returns of P_0) is reported as
 * PERIODIC with period 0, before any dimension is estimated.
 * Nearest neighbours come from a k-d tree, O(N log N).
 *
 * References: P. Grassberger, I. Procaccia, Physica D 9 (1983) 189–208
 * (correlation dimension); R. Badii, A. Politi, J. Stat. Phys. 40 (1985)
 * 725–750 (dimension from nearest-neighbour distances vs the number of
 * points); K. W. Pettis, T. A. Bailey, A. K. Jain, R. C. Dubes, IEEE Trans.
 * PAMI 1 (1979) 25–37 (k-th nearest-neighbour dimension estimate); V. T. Sós,
 * Ann. Univ. Sci. Budapest 1 (1958) 127–134 (three-distance theorem);
 * J. L. Bentley, Commun. ACM 18 (1975) 509–517 (k-d tree).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <whirl/section.h>

/* Minimum number of points for the dimension estimate (the 32nd neighbour
 * must lie well inside the set; reliable from a few hundred points). */
#define SEC_MIN_DIM_PTS 64

/* The dimension compares the distances to the SEC_KNEAR-th and SEC_KFAR-th
 * nearest neighbours (SEC_KFAR = 4 SEC_KNEAR: as for all points against a
 * quarter of them). */
#define SEC_KNEAR 8
#define SEC_KFAR 32

/* k-d tree leaves hold at most this many points. */
#define KD_LEAF 8

/* ------------------------------------------------------------------------
 * k-d tree over a permutation idx[] of n contiguous points, implicit: the node
 * of the range [lo, hi) splits at mid = lo + (hi − lo)/2 along axis[mid]. */

typedef struct kdtree {
  const double *pts; /* pts[i*dim + a] */
  size_t dim;
  size_t *idx;
  size_t *axis;
} kdtree;

static double kd_coord(const kdtree *t, ptrdiff_t i, size_t ax) {
  return t->pts[t->idx[i] * t->dim + ax];
}

/* Hoare's FIND (Wirth's formulation): permute idx[lo, hi) so position k holds
 * the point of rank k along ax, none larger before it, none smaller after. */
static void kd_select(kdtree *t, ptrdiff_t lo, ptrdiff_t hi, ptrdiff_t k,
                      size_t ax) {
  ptrdiff_t l = lo, r = hi - 1;
  while (l < r) {
    const double x = kd_coord(t, k, ax);
    ptrdiff_t i = l, j = r;
    do {
      while (kd_coord(t, i, ax) < x) ++i;
      while (x < kd_coord(t, j, ax)) --j;
      if (i <= j) {
        const size_t s = t->idx[i];
        t->idx[i] = t->idx[j];
        t->idx[j] = s;
        ++i;
        --j;
      }
    } while (i <= j);
    if (j < k) l = i;
    if (k < i) r = j;
  }
}

static void kd_build(kdtree *t, ptrdiff_t lo, ptrdiff_t hi) {
  while (hi - lo > KD_LEAF) {
    size_t ax = 0;
    double best = -1.0;
    for (size_t a = 0; a < t->dim; ++a) { /* axis of largest spread */
      double mn = kd_coord(t, lo, a), mx = mn;
      for (ptrdiff_t i = lo + 1; i < hi; ++i) {
        const double v = kd_coord(t, i, a);
        mn = v < mn ? v : mn;
        mx = v > mx ? v : mx;
      }
      if (mx - mn > best) {
        best = mx - mn;
        ax = a;
      }
    }
    const ptrdiff_t mid = lo + (hi - lo) / 2;
    kd_select(t, lo, hi, mid, ax);
    t->axis[mid] = ax;
    kd_build(t, lo, mid);
    lo = mid + 1; /* the right half by iteration */
  }
}

static double sqdist(const double *a, const double *b, size_t dim) {
  double s = 0.0;
  for (size_t k = 0; k < dim; ++k) {
    const double d = a[k] - b[k];
    s += d * d;
  }
  return s;
}

/* Insert d2 into best[0..SEC_KFAR-1], kept ascending. */
static void knn_insert(double *best, double d2) {
  if (!(d2 < best[SEC_KFAR - 1])) return;
  size_t k = SEC_KFAR - 1;
  while (k > 0 && best[k - 1] > d2) {
    best[k] = best[k - 1];
    --k;
  }
  best[k] = d2;
}

/* Improve best[SEC_KFAR], the smallest squared distances from point self (at
 * q) to the other points of idx[lo, hi). */
static void kd_nearest(const kdtree *t, ptrdiff_t lo, ptrdiff_t hi, size_t self,
                       const double *q, double *best) {
  if (hi - lo <= KD_LEAF) {
    for (ptrdiff_t i = lo; i < hi; ++i)
      if (t->idx[i] != self)
        knn_insert(best, sqdist(q, t->pts + t->idx[i] * t->dim, t->dim));
    return;
  }
  const ptrdiff_t mid = lo + (hi - lo) / 2;
  const size_t ax = t->axis[mid];
  if (t->idx[mid] != self)
    knn_insert(best, sqdist(q, t->pts + t->idx[mid] * t->dim, t->dim));
  const double diff = q[ax] - kd_coord(t, mid, ax);
  if (diff <= 0.0) {
    kd_nearest(t, lo, mid, self, q, best);
    if (diff * diff < best[SEC_KFAR - 1])
      kd_nearest(t, mid + 1, hi, self, q, best);
  } else {
    kd_nearest(t, mid + 1, hi, self, q, best);
    if (diff * diff < best[SEC_KFAR - 1]) kd_nearest(t, lo, mid, self, q, best);
  }
}

static int cmp_double(const void *pa, const void *pb) {
  const double a = *(const double *)pa, b = *(const double *)pb;
  return (a > b) - (a < b);
}

static double median_sorted(double *v, size_t n) {
  qsort(v, n, sizeof *v, cmp_double);
  return 0.5 * (v[(n - 1) / 2] + v[n / 2]);
}

/* Median distances *r_near, *r_far of the n > SEC_KFAR points pts[n*dim] to
 * their SEC_KNEAR-th and SEC_KFAR-th nearest neighbours. */
static int median_knn(const double *pts, size_t n, size_t dim, double *r_near,
                      double *r_far) {
  kdtree t = {pts, dim, malloc(n * sizeof(size_t)), malloc(n * sizeof(size_t))};
  double *dn = malloc(n * sizeof *dn), *df = malloc(n * sizeof *df);
  if (t.idx == NULL || t.axis == NULL || dn == NULL || df == NULL) {
    free(t.idx);
    free(t.axis);
    free(dn);
    free(df);
    return WHIRL_ENOMEM;
  }
  for (size_t i = 0; i < n; ++i) t.idx[i] = i;
  kd_build(&t, 0, (ptrdiff_t)n);
  for (size_t i = 0; i < n; ++i) {
    double best[SEC_KFAR];
    for (size_t k = 0; k < SEC_KFAR; ++k) best[k] = INFINITY;
    kd_nearest(&t, 0, (ptrdiff_t)n, i, pts + i * dim, best);
    dn[i] = sqrt(best[SEC_KNEAR - 1]);
    df[i] = sqrt(best[SEC_KFAR - 1]);
  }
  *r_near = median_sorted(dn, n);
  *r_far = median_sorted(df, n);
  free(t.idx);
  free(t.axis);
  free(dn);
  free(df);
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Classification */

/* Does every point lie within sqrt(eps2) of P_(i mod k)? */
static int has_period(const double *pts, size_t npts, size_t dim, size_t k,
                      double eps2) {
  for (size_t i = k; i < npts; ++i)
    if (sqdist(pts + i * dim, pts + (i % k) * dim, dim) > eps2) return 0;
  return 1;
}

int whirl_section_classify(const double *pts, size_t npts, size_t dim,
                           double tol, size_t max_period,
                           whirl_section_kind *kind, size_t *period,
                           double *dimension) {
  if (pts == NULL || kind == NULL || dim == 0 || npts < 2) return WHIRL_EINVAL;
  if (!(tol >= 0.0) || !isfinite(tol)) return WHIRL_EINVAL;
  if (max_period > npts / 2) return WHIRL_EINVAL;
  if (npts > SIZE_MAX / dim) return WHIRL_EINVAL;
  for (size_t i = 0; i < npts * dim; ++i)
    if (!isfinite(pts[i])) return WHIRL_EINVAL;

  /* size: largest distance from the centroid */
  double *c = calloc(dim, sizeof *c);
  if (c == NULL) return WHIRL_ENOMEM;
  for (size_t i = 0; i < npts; ++i)
    for (size_t a = 0; a < dim; ++a) c[a] += pts[i * dim + a];
  for (size_t a = 0; a < dim; ++a) c[a] /= (double)npts;
  double size2 = 0.0;
  for (size_t i = 0; i < npts; ++i) {
    const double d2 = sqdist(pts + i * dim, c, dim);
    if (d2 > size2) size2 = d2;
  }
  free(c);
  const double eps = tol * sqrt(size2) + tol, eps2 = eps * eps;
  if (!isfinite(eps2)) return WHIRL_EINVAL; /* coordinates near overflow */

  const size_t kmax = max_period > 0 ? max_period : 1;
  for (size_t k = 1; k <= kmax; ++k) {
    if (has_period(pts, npts, dim, k, eps2)) {
      *kind = k == 1 ? WHIRL_SECTION_FIXED : WHIRL_SECTION_PERIODIC;
      if (period) *period = k;
      if (dimension) *dimension = 0.0;
      return WHIRL_OK;
    }
  }

  /* a longer cycle: the first returns of P_0, verified over the record */
  for (size_t k = kmax + 1; k <= npts / 2; ++k) {
    if (sqdist(pts + k * dim, pts, dim) <= eps2 &&
        has_period(pts, npts, dim, k, eps2)) {
      *kind = WHIRL_SECTION_PERIODIC;
      if (period) *period = 0;
      if (dimension) *dimension = 0.0;
      return WHIRL_OK;
    }
  }

  if (npts < SEC_MIN_DIM_PTS) return WHIRL_EINVAL;
  double r_near = 0.0, r_far = 0.0;
  const int st = median_knn(pts, npts, dim, &r_near, &r_far);
  if (st != WHIRL_OK) return st;

  const double ratio = r_near > 0.0 ? r_far / r_near : INFINITY;
  double d;
  if (ratio <= 1.0)
    d = INFINITY; /* no growth at all */
  else
    d = log((double)SEC_KFAR / (double)SEC_KNEAR) / log(ratio);
  *kind = d < 1.5 ? WHIRL_SECTION_CURVE : WHIRL_SECTION_IRREGULAR;
  if (period) *period = 0;
  if (dimension) *dimension = d;
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Steady states */

/* Sums of the distances between successive points over the first (*first)
 * and the last (*last) tenth of the record (the same number of terms). */
static void step_sums(const double *pts, size_t npts, size_t dim,
                      double *first, double *last) {
  const size_t m = npts / 10;
  *first = *last = 0.0;
  for (size_t k = 0; k < m; ++k) {
    *first += sqrt(sqdist(pts + (k + 1) * dim, pts + k * dim, dim));
    *last += sqrt(sqdist(pts + (npts - 1 - k) * dim, pts + (npts - 2 - k) * dim, dim));
  }
}

int whirl_steady_classify(const double *pts, size_t npts, size_t dim,
                          double tol, size_t max_period,
                          whirl_steady_kind *kind, size_t *period,
                          double *dimension) {
  if (pts == NULL || kind == NULL || dim == 0 || !(tol >= 0.0) || !isfinite(tol))
    return WHIRL_EINVAL;
  if (npts > SIZE_MAX / dim) return WHIRL_EINVAL;
  if (period) *period = 0;
  if (dimension) *dimension = NAN;
  for (size_t i = 0; i < npts * dim; ++i)
    if (!isfinite(pts[i])) {
      *kind = WHIRL_STEADY_DIVERGENT;
      return WHIRL_OK;
    }
  if (npts < WHIRL_STEADY_MIN_POINTS) {
    *kind = WHIRL_STEADY_TRANSIENT;
    return WHIRL_OK;
  }
  whirl_section_kind sk;
  size_t per = 0;
  double d = NAN;
  const int st = whirl_section_classify(pts, npts, dim, tol, max_period, &sk, &per, &d);
  if (st != WHIRL_OK) return st;
  if (period) *period = per;
  if (dimension) *dimension = d;
  if (sk == WHIRL_SECTION_FIXED || sk == WHIRL_SECTION_PERIODIC) {
    *kind = sk == WHIRL_SECTION_FIXED ? WHIRL_STEADY_FIXED : WHIRL_STEADY_PERIODIC;
    return WHIRL_OK;
  }
  double first, last;
  step_sums(pts, npts, dim, &first, &last);
  if (last < 1e-3 * first)
    *kind = WHIRL_STEADY_TRANSIENT;
  else if (last > 1e3 * first)
    *kind = WHIRL_STEADY_DIVERGENT;
  else
    *kind = sk == WHIRL_SECTION_CURVE ? WHIRL_STEADY_QUASIPERIODIC : WHIRL_STEADY_IRREGULAR;
  return WHIRL_OK;
}

const char *whirl_steady_kind_name(whirl_steady_kind kind) {
  switch (kind) {
    case WHIRL_STEADY_FIXED: return "fixed";
    case WHIRL_STEADY_PERIODIC: return "periodic";
    case WHIRL_STEADY_QUASIPERIODIC: return "quasiperiodic";
    case WHIRL_STEADY_IRREGULAR: return "irregular";
    case WHIRL_STEADY_TRANSIENT: return "transient";
    case WHIRL_STEADY_DIVERGENT: return "divergent";
  }
  return "?";
}

/* lib/systems/periodic.c — one interface to the discretisations of a
 * periodic orbit (whirl/periodic.h): the adapters for harmonic balance and
 * collocation, and the collocation orbit's maximum and L2 norm.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>

#include <whirl/periodic.h>

#include "colloc_basis.h"
#include "colloc_impl.h"

/* ---- collocation: the maximum and the L2 norm of the orbit -------------- */

static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                             0.5384693101056831, 0.9061798459386640};
static const double gw[5] = {0.2369268850561891, 0.4786286704993665,
                             0.5688888888888889, 0.4786286704993665,
                             0.2369268850561891};

/* Refine the maximum of component i near the sample arg by golden-section
 * search between its neighbouring samples (within one mesh interval,
 * where the polynomial is smooth); the larger of it and best. */
static double refine_max(const whirl_colloc *c, const double *x, size_t i,
                         double arg, double best, double *v) {
  const double *mesh = c->mesh, g = 0.5 * (sqrt(5.0) - 1.0);
  const size_t sub = 8;
  size_t k = 0;
  while (k + 1 < c->ntst && mesh[k + 1] <= arg) k++;
  const double h = (mesh[k + 1] - mesh[k]) / (double)(c->ncol * sub);
  double a = fmax(arg - h, 0.0), b = fmin(arg + h, 1.0);
  double x1 = b - g * (b - a), x2 = a + g * (b - a), f1, f2;
  whirl_colloc_eval(c, x, x1, v), f1 = v[i];
  whirl_colloc_eval(c, x, x2, v), f2 = v[i];
  for (int it = 0; it < 60 && b - a > 1e-15; it++) {
    if (f1 < f2) {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a);
      whirl_colloc_eval(c, x, x2, v), f2 = v[i];
    } else {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a);
      whirl_colloc_eval(c, x, x1, v), f1 = v[i];
    }
  }
  return fmax(best, fmax(f1, f2));
}

/* AUTO prints the maximum over its mesh and collocation nodes, which
 * depends on the mesh: on a spike (ab's u2) two meshes differ in the 4th
 * digit.  Here it is the maximum of the polynomial, to its accuracy
 * (doc/auto-reference.md). */
int whirl_colloc_max(const whirl_colloc *c, const double *x, double *mx) {
  if (!c || !x || !mx) return WHIRL_EINVAL;
  const size_t n = c->n, ntst = c->ntst, ncol = c->ncol, sub = 8, ps = ncol * sub;
  /* the samples sit at the same local positions r/ps of every interval:
   * their Lagrange weights once, not a search of the mesh and a basis
   * evaluation per sample (a tenth of demo pla's run, every point) */
  double *best = malloc((3 * n + ps * (ncol + 1)) * sizeof *best);
  if (!best) return WHIRL_ENOMEM;
  double *arg = best + n, *v = best + 2 * n, *lw = best + 3 * n;
  for (size_t r = 0; r < ps; r++)
    colloc_basis_lagrange_values(ncol, (double)r / (double)ps, lw + r * (ncol + 1));
  for (size_t i = 0; i < n; i++) mx[i] = -HUGE_VAL;
  for (size_t j = 0; j < c->nnodes; j++) /* the nodes */
    for (size_t i = 0; i < n; i++) mx[i] = fmax(mx[i], x[n * j + i]);
  for (size_t i = 0; i < n; i++) best[i] = -HUGE_VAL, arg[i] = 0.0;
  for (size_t k = 0; k < ntst; k++) {
    const double *mesh = c->mesh, *xk = x + n * k * ncol;
    for (size_t r = 0; r < ps; r++) {
      const double *l = lw + r * (ncol + 1);
      for (size_t i = 0; i < n; i++) v[i] = 0.0;
      for (size_t q = 0; q <= ncol; q++)
        for (size_t i = 0; i < n; i++) v[i] += l[q] * xk[n * q + i];
      const double tau = mesh[k] + (mesh[k + 1] - mesh[k]) * (double)r / (double)ps;
      for (size_t i = 0; i < n; i++)
        if (v[i] > best[i]) best[i] = v[i], arg[i] = tau;
    }
  }
  for (size_t i = 0; i < n; i++)
    mx[i] = fmax(mx[i], refine_max(c, x, i, arg[i], best[i], v));
  free(best);
  return WHIRL_OK;
}

double whirl_colloc_l2norm(const whirl_colloc *c, const double *x) {
  const size_t n = c->n;
  double *v = malloc(n * sizeof *v), l2 = 0.0;
  if (!v) return NAN;
  for (size_t k = 0; k < c->ntst; k++) {
    const double a = c->mesh[k], h = c->mesh[k + 1] - c->mesh[k];
    for (int g = 0; g < 5; g++) {
      whirl_colloc_eval(c, x, a + 0.5 * h * (1.0 + gx[g]), v);
      double s = 0.0;
      for (size_t i = 0; i < n; i++) s += v[i] * v[i];
      l2 += 0.5 * h * gw[g] * s;
    }
  }
  free(v);
  return sqrt(l2);
}

/* ∫₀¹ u_i and ∫₀¹ u_i² of each component (5-point Gauss-Legendre on each
 * mesh interval, as whirl_colloc_l2norm) and the minimum and maximum over
 * the NTST*NCOL+1 nodes (AUTO's MIN U(i) and MAX U(i) are taken there). */
int whirl_colloc_moments(const whirl_colloc *c, const double *x, double *m1, double *m2,
                         double *mn, double *mx) {
  const size_t n = c->n;
  double *v = malloc(n * sizeof *v);
  if (!v) return WHIRL_ENOMEM;
  for (size_t i = 0; i < n; i++) m1[i] = m2[i] = 0.0, mn[i] = HUGE_VAL, mx[i] = -HUGE_VAL;
  for (size_t k = 0; k < c->ntst; k++) {
    const double a = c->mesh[k], h = c->mesh[k + 1] - c->mesh[k];
    for (int g = 0; g < 5; g++) {
      whirl_colloc_eval(c, x, a + 0.5 * h * (1.0 + gx[g]), v);
      for (size_t i = 0; i < n; i++) m1[i] += 0.5 * h * gw[g] * v[i], m2[i] += 0.5 * h * gw[g] * v[i] * v[i];
    }
    for (size_t j = 0; j <= c->ncol; j++) {
      whirl_colloc_eval(c, x, a + h * (double)j / (double)c->ncol, v);
      for (size_t i = 0; i < n; i++) mn[i] = fmin(mn[i], v[i]), mx[i] = fmax(mx[i], v[i]);
    }
  }
  free(v);
  return WHIRL_OK;
}

/* ---- the adapters ----------------------------------------------------------- */

/* The multipliers as the object's system computes its stability. */
static int system_multipliers(const whirl_system *S, const double *x,
                              const double *p, double *re, double *im,
                              size_t *m) {
  if (S->spectrum == NULL || *m < S->nspec) return WHIRL_EINVAL;
  return S->spectrum(x, p, NULL, re, im, m, S->data);
}

static size_t hbm_size(const void *o) { return whirl_hbm_size(o); }
static size_t hbm_dim(const void *o) { return whirl_hbm_dim(o); }
static double hbm_period(const void *o, const double *x, const double *p) {
  return whirl_hbm_period(o, x, p);
}
static int hbm_eval(const void *o, const double *x, double tau, double *u) {
  whirl_hbm_eval(o, x, 2.0 * WHIRL_PI * tau, u);
  return WHIRL_OK;
}
static int hbm_from_samples(void *o, const double *u, size_t m, double T,
                            double *x) {
  return whirl_hbm_from_samples(o, u, m, T, x);
}
static size_t hbm_naux(const void *o) { (void)o; return 0; }
static int hbm_save(const void *o, double *aux) { (void)o, (void)aux; return WHIRL_OK; }
static int hbm_restore(void *o, const double *aux, const double *x) {
  (void)o, (void)aux, (void)x;
  return WHIRL_OK;
}
static int hbm_mult(const void *o, const double *x, const double *p,
                    double *re, double *im, size_t *m) {
  return system_multipliers(whirl_hbm_system(o), x, p, re, im, m);
}
static int hbm_max(const void *o, const double *x, double *mx) {
  return whirl_hbm_max(o, x, mx);
}
static double hbm_l2(const void *o, const double *x) { return whirl_hbm_l2norm(o, x); }
static const char *hbm_err(const void *o) { return whirl_hbm_errmsg(o); }

static size_t colloc_size(const void *o) { return whirl_colloc_size(o); }
static size_t colloc_dim(const void *o) { return ((const whirl_colloc *)o)->n; }
static double colloc_period(const void *o, const double *x, const double *p) {
  return whirl_colloc_period(o, x, p);
}
static int colloc_eval(const void *o, const double *x, double tau, double *u) {
  return whirl_colloc_eval(o, x, tau, u);
}
static int colloc_from_samples(void *o, const double *u, size_t m, double T,
                               double *x) {
  return whirl_colloc_from_samples(o, u, m, T, x);
}
static size_t colloc_naux(const void *o) { return ((const whirl_colloc *)o)->ntst + 1; }
static int colloc_save(const void *o, double *aux) {
  const double *mesh = whirl_colloc_mesh(o);
  for (size_t k = 0; k < colloc_naux(o); k++) aux[k] = mesh[k];
  return WHIRL_OK;
}
static int colloc_restore(void *o, const double *aux, const double *x) {
  const int rc = whirl_colloc_set_mesh(o, aux);
  return rc != WHIRL_OK ? rc : whirl_colloc_set_reference(o, x);
}
static int colloc_mult(const void *o, const double *x, const double *p,
                       double *re, double *im, size_t *m) {
  return system_multipliers(whirl_colloc_system(o), x, p, re, im, m);
}
static int colloc_max_op(const void *o, const double *x, double *mx) {
  return whirl_colloc_max(o, x, mx);
}
static double colloc_l2(const void *o, const double *x) { return whirl_colloc_l2norm(o, x); }
static const char *colloc_err(const void *o) { return whirl_colloc_errmsg(o); }

static const whirl_periodic_ops hbm_ops = {
    "hbm", hbm_size, hbm_dim, hbm_period, hbm_eval, hbm_from_samples, hbm_naux,
    hbm_save, hbm_restore, hbm_mult, hbm_max, hbm_l2, hbm_err};
static const whirl_periodic_ops colloc_ops = {
    "colloc", colloc_size, colloc_dim, colloc_period, colloc_eval,
    colloc_from_samples, colloc_naux, colloc_save, colloc_restore, colloc_mult,
    colloc_max_op, colloc_l2, colloc_err};

whirl_periodic whirl_periodic_of_hbm(whirl_hbm *h) {
  return (whirl_periodic){&hbm_ops, h};
}
whirl_periodic whirl_periodic_of_colloc(whirl_colloc *c) {
  return (whirl_periodic){&colloc_ops, c};
}

const char *whirl_periodic_method(const whirl_periodic *po) { return po->ops->method; }
size_t whirl_periodic_size(const whirl_periodic *po) { return po->ops->size(po->obj); }
size_t whirl_periodic_dim(const whirl_periodic *po) { return po->ops->dim(po->obj); }
double whirl_periodic_period(const whirl_periodic *po, const double *x, const double *p) {
  return po->ops->period(po->obj, x, p);
}
int whirl_periodic_eval(const whirl_periodic *po, const double *x, double tau, double *u) {
  return po->ops->eval(po->obj, x, tau, u);
}
int whirl_periodic_from_samples(whirl_periodic *po, const double *u, size_t m,
                                double T, double *x) {
  return po->ops->from_samples(po->obj, u, m, T, x);
}
size_t whirl_periodic_naux(const whirl_periodic *po) { return po->ops->naux(po->obj); }
int whirl_periodic_save(const whirl_periodic *po, double *aux) {
  return po->ops->save(po->obj, aux);
}
int whirl_periodic_restore(whirl_periodic *po, const double *aux, const double *x) {
  return po->ops->restore(po->obj, aux, x);
}
int whirl_periodic_multipliers(const whirl_periodic *po, const double *x,
                               const double *p, double *re, double *im,
                               size_t *m) {
  return po->ops->multipliers(po->obj, x, p, re, im, m);
}
const char *whirl_periodic_errmsg(const whirl_periodic *po) {
  return po->ops->errmsg(po->obj);
}
int whirl_periodic_max(const whirl_periodic *po, const double *x, double *mx) {
  return po->ops->max(po->obj, x, mx);
}
double whirl_periodic_l2norm(const whirl_periodic *po, const double *x) {
  return po->ops->l2norm(po->obj, x);
}

/* ---- built on the ops: harmonics and conversion -------------------------- */

int whirl_periodic_from_harmonics(whirl_periodic *po, const double *c,
                                  size_t nh, double T, double *x) {
  const size_t n = whirl_periodic_dim(po), m0 = 4 * (2 * nh + 1),
               m1 = 4 * whirl_periodic_size(po) / n, m = m0 > m1 ? m0 : m1;
  if (!c || !x || !(T > 0.0)) return WHIRL_EINVAL;
  double *u = malloc(m * n * sizeof *u);
  if (!u) return WHIRL_ENOMEM;
  for (size_t j = 0; j < m; j++)
    for (size_t i = 0; i < n; i++) {
      double v = c[i];
      for (size_t k = 1; k <= nh; k++) {
        const double th = 2.0 * WHIRL_PI * (double)(k * j) / (double)m;
        v += c[n * (2 * k - 1) + i] * cos(th) + c[n * 2 * k + i] * sin(th);
      }
      u[j * n + i] = v;
    }
  const int rc = whirl_periodic_from_samples(po, u, m, T, x);
  free(u);
  return rc;
}

int whirl_periodic_convert(const whirl_periodic *src, const double *xsrc,
                           const double *p, whirl_periodic *dst, size_t m,
                           double *xdst) {
  const size_t n = whirl_periodic_dim(src);
  if (!xsrc || !xdst || whirl_periodic_dim(dst) != n) return WHIRL_EINVAL;
  if (m == 0) {
    const size_t a = whirl_periodic_size(src), b = whirl_periodic_size(dst);
    m = 4 * (a > b ? a : b) / n;
  }
  double *u = malloc(m * n * sizeof *u);
  if (!u) return WHIRL_ENOMEM;
  int rc = WHIRL_OK;
  for (size_t j = 0; j < m && rc == WHIRL_OK; j++)
    rc = whirl_periodic_eval(src, xsrc, (double)j / (double)m, u + j * n);
  if (rc == WHIRL_OK)
    rc = whirl_periodic_from_samples(dst, u, m, whirl_periodic_period(src, xsrc, p), xdst);
  free(u);
  return rc;
}

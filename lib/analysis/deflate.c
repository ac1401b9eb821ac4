/* lib/analysis/deflate.c — deflated Newton (whirl/deflate.h; Farrell,
 * Birkisson & Funke, SIAM J. Sci. Comput. 37 (2015) A2026).
 *
 * One iteration at x: the undeflated step δ = −F_x⁻¹F by one LU, the
 * deflation factor τ = 1/(1 − ∇log M · δ) with
 *
 *   ∇log M · δ = Σ_i −q d_i^(−q−2) (Σ_j w_j² (x_j − r_ij) δ_j) / m_i,
 *   d_i = ‖x − r_i‖_W,  m_i = d_i^(−q) + σ,
 *
 * and the step τδ, shortened to max_step and halved while F leaves the
 * model's domain at the trial point.  Convergence is judged on the
 * undeflated step (the iterate is then a root of F), and the last step is
 * undeflated Newton, so a solution comes out polished.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/deflate.h>
#include <whirl/linsol.h>

struct whirl_deflate {
  const whirl_system *sys;
  whirl_deflate_options o;
  double *w;             /* n weights */
  double *roots;         /* nroots × n */
  size_t nroots, cap;
  whirl_linsol *ls;
  int sparse;
  double *J, *f, *d, *xt, *work, *x0, *xc, *xi;
  whirl_deflate_stats st;
  char err[512];
};

void whirl_deflate_options_default(whirl_deflate_options *o) {
  memset(o, 0, sizeof *o);
  o->power = 2.0;
  o->shift = 1.0;
  o->tol = 1e-10;
  o->maxit = 50;
  o->max_distance = 1e3;
  o->min_distance = 1e-6;
}

static int check_options(const whirl_deflate_options *o, size_t n, char *err,
                         size_t len) {
  if (!(o->power > 0) || !(o->shift >= 0) || !(o->tol > 0) || o->maxit < 1 ||
      !(o->max_step >= 0) || !(o->max_distance > 0) || !(o->min_distance >= 0))
    return WHIRL_ERRMSG(err, len, WHIRL_EINVAL, "deflation: power, tol and "
                        "max_distance must be > 0, shift, max_step and "
                        "min_distance >= 0, maxit >= 1");
  for (size_t i = 0; o->weight && i < n; i++)
    if (!(o->weight[i] > 0) || !isfinite(o->weight[i]))
      return WHIRL_ERRMSG(err, len, WHIRL_EINVAL, "deflation: weight %zu is "
                          "not a positive finite number", i);
  return WHIRL_OK;
}

whirl_deflate *whirl_deflate_alloc(const whirl_system *sys,
                                   const whirl_deflate_options *o, char *err,
                                   size_t len) {
  whirl_deflate_options def;
  if (!o) {
    whirl_deflate_options_default(&def);
    o = &def;
  }
  if (!sys || !sys->F || sys->n == 0) {
    WHIRL_ERRMSG(err, len, WHIRL_EINVAL, "deflation: no system");
    return NULL;
  }
  if (check_options(o, sys->n, err, len)) return NULL;
  const size_t n = sys->n;
  whirl_deflate *d = calloc(1, sizeof *d);
  if (!d) goto nomem;
  d->sys = sys;
  d->o = *o;
  /* sparse (UMFPACK) when the pattern is large, or sparse enough to pay */
  d->sparse = sys->Jp && sys->Ji && sys->Fx_sparse &&
              (n > 400 || (n > 64 && 4 * sys->nnz < n * n));
  d->ls = d->sparse ? whirl_linsol_alloc_sparse(n, sys->Jp, sys->Ji)
                    : whirl_linsol_alloc_dense(n);
  d->J = malloc((d->sparse ? sys->nnz : n * n) * sizeof *d->J);
  d->w = malloc(n * sizeof *d->w);
  d->f = malloc(n * sizeof *d->f);
  d->d = malloc(n * sizeof *d->d);
  d->xt = malloc(n * sizeof *d->xt);
  d->x0 = malloc(n * sizeof *d->x0);
  d->xc = malloc(n * sizeof *d->xc);
  d->xi = malloc(n * sizeof *d->xi);
  d->work = malloc((2 * n + sys->nnz) * sizeof *d->work);
  if (!d->ls || !d->J || !d->w || !d->f || !d->d || !d->xt || !d->x0 || !d->xc || !d->xi ||
      !d->work)
    goto nomem;
  for (size_t i = 0; i < n; i++) d->w[i] = o->weight ? o->weight[i] : 1.0;
  d->o.weight = d->w;
  return d;
nomem:
  whirl_deflate_free(d);
  WHIRL_ERRMSG(err, len, WHIRL_ENOMEM, "deflation: out of memory");
  return NULL;
}

void whirl_deflate_free(whirl_deflate *d) {
  if (!d) return;
  whirl_linsol_free(d->ls);
  free(d->J);
  free(d->w);
  free(d->roots);
  free(d->f);
  free(d->d);
  free(d->xt);
  free(d->x0);
  free(d->xc);
  free(d->xi);
  free(d->work);
  free(d);
}

int whirl_deflate_add(whirl_deflate *d, const double *r) {
  const size_t n = d->sys->n;
  if (d->nroots == d->cap) {
    size_t cap = d->cap ? 2 * d->cap : 8;
    double *nr = realloc(d->roots, cap * n * sizeof *nr);
    if (!nr) return WHIRL_ERRMSG(d->err, sizeof d->err, WHIRL_ENOMEM, "deflation: out of memory");
    d->roots = nr;
    d->cap = cap;
  }
  memcpy(d->roots + d->nroots++ * n, r, n * sizeof *r);
  return WHIRL_OK;
}

void whirl_deflate_clear(whirl_deflate *d) { d->nroots = 0; }
size_t whirl_deflate_count(const whirl_deflate *d) { return d->nroots; }
const double *whirl_deflate_root(const whirl_deflate *d, size_t i) {
  return i < d->nroots ? d->roots + i * d->sys->n : NULL;
}
const whirl_deflate_stats *whirl_deflate_get_stats(const whirl_deflate *d) { return &d->st; }
const char *whirl_deflate_errmsg(const whirl_deflate *d) { return d->err; }

static double wdist(const whirl_deflate *d, const double *a, const double *b) {
  double s = 0.0;
  for (size_t j = 0; j < d->sys->n; j++) {
    const double e = d->w[j] * (a[j] - b[j]);
    s += e * e;
  }
  return sqrt(s);
}

double whirl_deflate_nearest(const whirl_deflate *d, const double *x, size_t *which) {
  double best = INFINITY;
  for (size_t i = 0; i < d->nroots; i++) {
    const double e = wdist(d, x, d->roots + i * d->sys->n);
    if (e < best) {
      best = e;
      if (which) *which = i;
    }
  }
  return best;
}

/* ∇log M · δ at x (the step's deflation term); +inf at a known root. */
static double deflation_slope(const whirl_deflate *d, const double *x, const double *dx) {
  const size_t n = d->sys->n;
  const double q = d->o.power, sigma = d->o.shift;
  double g = 0.0;
  for (size_t i = 0; i < d->nroots; i++) {
    const double *r = d->roots + i * n;
    double dd = 0.0, proj = 0.0;
    for (size_t j = 0; j < n; j++) {
      const double e = x[j] - r[j], w2 = d->w[j] * d->w[j];
      dd += w2 * e * e;
      proj += w2 * e * dx[j];
    }
    if (dd == 0.0) return INFINITY;
    const double dist = sqrt(dd), m = pow(dist, -q) + sigma;
    g += -q * pow(dist, -q - 2.0) * proj / m;
  }
  return g;
}

/* δ = −F_x⁻¹ F at x into d->d (F in d->f): 0, > 0 domain, < 0 fatal. */
static int newton_step(whirl_deflate *d, const double *x, const double *p) {
  const whirl_system *s = d->sys;
  int r = whirl_system_eval(s, x, p, d->f);
  d->st.f_evals++;
  if (r != 0) return r > 0 || r == WHIRL_EBADFUNC ? 1 : r;
  r = d->sparse ? s->Fx_sparse(x, p, d->J, s->data)
                : whirl_system_jacobian(s, x, p, d->J, d->work);
  if (r != 0) return r > 0 || r == WHIRL_EBADFUNC ? 1 : r;
  d->st.factorizations++;
  r = whirl_linsol_factor(d->ls, d->J);
  if (r == WHIRL_ESINGULAR) return 2; /* no step from here */
  if (r != WHIRL_OK)
    return WHIRL_ERRMSG(d->err, sizeof d->err, r, "deflation: %s",
                        whirl_linsol_errmsg(d->ls));
  for (size_t i = 0; i < s->n; i++) d->d[i] = -d->f[i];
  r = whirl_linsol_solve(d->ls, d->d, 1, 0);
  if (r != WHIRL_OK) return r;
  for (size_t i = 0; i < s->n; i++)
    if (!isfinite(d->d[i])) return 2;
  return 0;
}

static double inf_norm(const double *v, size_t n) {
  double m = 0.0;
  for (size_t i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
  return m;
}

/* Take the step τδ from x, halving it while F fails at the trial point.
 * 0, 1 (no admissible step), < 0 fatal. */
static int take_step(whirl_deflate *d, double *x, const double *p, double tau) {
  const size_t n = d->sys->n;
  double s = 0.0;
  for (size_t j = 0; j < n; j++) s += d->w[j] * d->w[j] * d->d[j] * d->d[j];
  const double len = fabs(tau) * sqrt(s);
  if (d->o.max_step > 0 && len > d->o.max_step) tau *= d->o.max_step / len;
  for (int half = 0; half < 12; half++, tau *= 0.5) {
    for (size_t j = 0; j < n; j++) d->xt[j] = x[j] + tau * d->d[j];
    int r = whirl_system_eval(d->sys, d->xt, p, d->f);
    d->st.f_evals++;
    if (r < 0 && r != WHIRL_EBADFUNC) return r;
    if (r == 0) {
      memcpy(x, d->xt, n * sizeof *x);
      return 0;
    }
  }
  return 1;
}

static int iterate(whirl_deflate *d, double *x, const double *p, int *its,
                   int deflate) {
  const size_t n = d->sys->n;
  int it = 0, rc = WHIRL_ENOCONV;
  d->st.solves++;
  memcpy(d->x0, x, n * sizeof *x);
  for (it = 1; it <= d->o.maxit; it++) {
    d->st.iterations++;
    int r = newton_step(d, x, p);
    if (r < 0) { rc = r; break; }
    if (r == 1) { rc = WHIRL_EDOMAIN; break; }
    if (r == 2) break;
    const double fn = inf_norm(d->f, n), dn = inf_norm(d->d, n);
    if (dn <= d->o.tol * (1.0 + inf_norm(x, n)) && fn <= 1e3 * d->o.tol) {
      for (size_t j = 0; j < n; j++) x[j] += d->d[j]; /* polished */
      rc = WHIRL_OK;
      break;
    }
    double tau = 1.0;
    if (deflate && d->nroots) {
      const double g = deflation_slope(d, x, d->d);
      if (!isfinite(g) || fabs(1.0 - g) < 1e-14) break; /* sitting on a root */
      tau = 1.0 / (1.0 - g);
    }
    r = take_step(d, x, p, tau);
    if (r < 0) { rc = r; break; }
    if (r == 1) { rc = WHIRL_EDOMAIN; break; }
    if (wdist(d, x, d->x0) > d->o.max_distance) break; /* ran away */
  }
  if (its) *its = it;
  if (rc == WHIRL_OK && deflate && whirl_deflate_nearest(d, x, NULL) < d->o.min_distance)
    rc = WHIRL_ENOCONV; /* converged onto a known solution after all */
  return rc;
}

int whirl_deflate_solve(whirl_deflate *d, double *x, const double *p, int *its) {
  return iterate(d, x, p, its, 1);
}

int whirl_deflate_polish(whirl_deflate *d, double *x, const double *p, int *its) {
  return iterate(d, x, p, its, 0);
}

int whirl_deflate_add_crossings(whirl_deflate *d, const double *q, const double *x,
                                size_t npts, double s, const double *p) {
  const size_t n = d->sys->n;
  for (size_t k = 0; k + 1 < npts; k++) {
    const double a = q[k], b = q[k + 1];
    if (!((a - s) * (b - s) <= 0.0) || a == b) continue;
    const double th = (s - a) / (b - a);
    for (size_t j = 0; j < n; j++)
      d->xi[j] = d->xc[j] = (1 - th) * x[k * n + j] + th * x[(k + 1) * n + j];
    if (iterate(d, d->xc, p, NULL, 0) != WHIRL_OK) memcpy(d->xc, d->xi, n * sizeof *d->xc);
    if (whirl_deflate_nearest(d, d->xc, NULL) < d->o.min_distance) continue;
    int rc = whirl_deflate_add(d, d->xc);
    if (rc) return rc;
  }
  return WHIRL_OK;
}

double whirl_random_uniform(uint64_t *s) {
  uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (double)(z >> 11) * 0x1.0p-53;
}

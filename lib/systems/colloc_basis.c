/* lib/systems/colloc_basis.c — the piecewise polynomial basis of the
 * collocation constructors (colloc.c, bvp.c): Gauss–Legendre points and
 * weights, the Lagrange basis on equally spaced nodes and its derivative,
 * the evaluation of a piecewise polynomial on a mesh (colloc_basis.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <whirl/status.h>
#include <stdio.h>
#include <stdlib.h>
#include <stddef.h>
#include <string.h>

#include <whirl/problem.h>

#include "colloc_basis.h"
#include "util/threads_impl.h"

/* The Legendre polynomial P_m(z) (into *pm, by the three-term recurrence)
 * and its derivative P_m'(z). */
double colloc_basis_legendre(size_t m, double z, double *pm) {
  double p0 = 1.0, p1 = z;
  for (size_t j = 2; j <= m; ++j) {
    double p2 = ((2.0 * (double)j - 1.0) * z * p1 - ((double)j - 1.0) * p0) / (double)j;
    p0 = p1;
    p1 = p2;
  }
  *pm = p1;
  return (double)m * (z * p1 - p0) / (z * z - 1.0);
}

/* Gauss–Legendre points and weights on [0, 1] by Newton's method on P_m,
 * from the asymptotic guesses cos(π(k + 3/4)/(m + 1/2)); converged to
 * rounding (~1e-16). */
void colloc_basis_gauss_legendre(size_t m, double *s, double *w) {
  for (size_t k = 0; k < m; ++k) {
    double z = cos(WHIRL_PI * ((double)k + 0.75) / ((double)m + 0.5));
    double dp = 1.0, pm;
    for (int it = 0; it < 100; ++it) {
      dp = colloc_basis_legendre(m, z, &pm);
      double dz = pm / dp;
      z -= dz;
      if (fabs(dz) <= 1e-17) break;
    }
    dp = colloc_basis_legendre(m, z, &pm); /* derivative at the converged root, for the weight */
    /* roots come in decreasing z: σ = (1 − z)/2 is increasing */
    s[k] = 0.5 * (1.0 - z);
    w[k] = 1.0 / ((1.0 - z * z) * dp * dp); /* 2/((1−z²)P'²) halved */
  }
}

/* Lagrange basis on the nodes k/m, k = 0..m, at σ: l[k] = l_k(σ) and, if
 * dl is not NULL, dl[k] = l_k'(σ). */
void colloc_basis_lagrange(size_t m, double sigma, double *l, double *dl) {
  for (size_t k = 0; k <= m; ++k) {
    const double sk = (double)k / (double)m;
    double prod = 1.0, der = 0.0;
    for (size_t j = 0; j <= m; ++j) {
      if (j == k) continue;
      const double sj = (double)j / (double)m;
      prod *= (sigma - sj) / (sk - sj);
    }
    l[k] = prod;
    if (!dl) continue;
    for (size_t q = 0; q <= m; ++q) {
      if (q == k) continue;
      const double sq = (double)q / (double)m;
      double term = 1.0 / (sk - sq);
      for (size_t j = 0; j <= m; ++j) {
        if (j == k || j == q) continue;
        const double sj = (double)j / (double)m;
        term *= (sigma - sj) / (sk - sj);
      }
      der += term;
    }
    dl[k] = der;
  }
}

/* The values alone of the Lagrange basis on the nodes k/m at σ, in O(m):
 * l_k(σ) = prod_{j != k} (mσ − j) / ((−1)^{m−k} k! (m − k)!), from prefix
 * and suffix products (the evaluation of orbits for output). */
void colloc_basis_lagrange_values(size_t m, double sigma, double *l) {
  const double u = (double)m * sigma;
  double pre[COLLOC_BASIS_MAXCOL + 2], suf[COLLOC_BASIS_MAXCOL + 2];
  pre[0] = 1.0;
  for (size_t j = 0; j <= m; ++j) pre[j + 1] = pre[j] * (u - (double)j);
  suf[m + 1] = 1.0;
  for (size_t j = m + 1; j-- > 0;) suf[j] = suf[j + 1] * (u - (double)j);
  double fk = 1.0, fmk = 1.0; /* k!, (m − k)! */
  for (size_t j = 2; j <= m; ++j) fmk *= (double)j;
  for (size_t k = 0; k <= m; ++k) {
    const double den = ((m - k) % 2 ? -1.0 : 1.0) * fk * fmk;
    l[k] = pre[k] * suf[k + 1] / den;
    fk *= (double)(k + 1);
    if (k < m) fmk /= (double)(m - k);
  }
}

/* Interval of the mesh tau[0..ntst] containing t ∈ [0, 1] (bisection). */
size_t colloc_basis_find_interval(const double *tau, size_t ntst, double t) {
  size_t lo = 0, hi = ntst;
  while (hi - lo > 1) {
    size_t mid = (lo + hi) / 2;
    if (t >= tau[mid])
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

/* The piecewise polynomial with mesh tau and node values Xn at τ (wrapped
 * periodically into [0, 1]): x[n]. */
void colloc_basis_eval_poly(size_t n, size_t ntst, size_t m, const double *tau,
                            const double *Xn, double t, double *x) {
  if (t < 0.0 || t > 1.0) t -= floor(t);
  const size_t i = colloc_basis_find_interval(tau, ntst, t);
  const double h = tau[i + 1] - tau[i];
  double l[COLLOC_BASIS_MAXCOL + 1];
  colloc_basis_lagrange_values(m, (t - tau[i]) / h, l);
  for (size_t r = 0; r < n; ++r) x[r] = 0.0;
  for (size_t k = 0; k <= m; ++k) {
    const double *xk = Xn + n * (i * m + k);
    for (size_t r = 0; r < n; ++r) x[r] += l[k] * xk[r];
  }
}


void colloc_basis_derivative_weights(size_t m, double *dm) {
  double binom = 1.0, mm = pow((double)m, (double)m);
  for (size_t k = 0; k <= m; ++k) {
    dm[k] = (((m - k) % 2) ? -1.0 : 1.0) * binom * mm;
    binom = binom * (double)(m - k) / (double)(k + 1);
  }
}

/* The new mesh of Nnew intervals equidistributing the density E[N] on
 * old (Q[N + 1] its integral): 1, 0 (E vanishes: the uniform mesh, or old
 * kept when Nnew = N) or -1 - N - k (interval k degenerate). */
static int equidistribute_to(size_t N, const double *old, const double *E, double *Q,
                             size_t Nnew, double *mesh) {
  double Emax = 0.0;
  Q[0] = 0.0;
  for (size_t i = 0; i < N; ++i) {
    Emax = fmax(Emax, E[i]);
    Q[i + 1] = Q[i] + (old[i + 1] - old[i]) * E[i];
  }
  if (!(Emax > 0)) { /* a constant solution: keep the mesh */
    for (size_t k = 0; k <= Nnew; ++k) mesh[k] = Nnew == N ? old[k] : (double)k / (double)Nnew;
    return 0;
  }
  size_t i = 0;
  for (size_t k = 1; k < Nnew; ++k) {
    const double q = Q[N] * (double)k / (double)Nnew;
    while (i < N - 1 && (Q[i + 1] < q || E[i] <= 0.0)) ++i;
    double t = old[i] + (E[i] > 0 ? (q - Q[i]) / E[i] : 0.0);
    t = fmin(fmax(t, old[i]), old[i + 1]);
    mesh[k] = t;
  }
  mesh[0] = 0.0;
  mesh[Nnew] = 1.0;
  for (size_t k = 1; k <= Nnew; ++k)
    if (!(mesh[k] > mesh[k - 1])) {
      if (Nnew == N) memcpy(mesh, old, (N + 1) * sizeof *mesh);
      return -1 - (int)N - (int)k;
    }
  return 1;
}

static int equidistribute(size_t N, const double *old, double *mesh, const double *E,
                          double *Q) {
  return equidistribute_to(N, old, E, Q, N, mesh);
}

/* x_r^(m) on interval i (constant: the m-th derivative of a degree-m
 * polynomial), in t. */
static double mth_derivative(size_t n, size_t m, const double *dm, const double *X,
                             const double *old, size_t i, size_t r) {
  const double h = old[i + 1] - old[i];
  double d = 0.0;
  for (size_t k = 0; k <= m; ++k) d += dm[k] * X[n * (i * m + k) + r];
  return d / pow(h, (double)m);
}

int colloc_basis_new_mesh(size_t n, size_t m, size_t N, const double *dm,
                          const double *X, const double *old, double *mesh,
                          double *E, double *Q) {
  const double pwr = 1.0 / ((double)m + 1.0);
  for (size_t i = 0; i < N; ++i) {
    double e = 0.0;
    for (size_t r = 0; r < n; ++r) e += pow(fabs(mth_derivative(n, m, dm, X, old, i, r)), pwr);
    if (!isfinite(e)) return -1 - (int)i;
    E[i] = e;
  }
  return equidistribute(N, old, mesh, E, Q);
}

/* The density of x^(m+1) from the jumps of the piecewise constant x^(m)
 * (D[n N]): interval i takes the jump to interval i + 1 over the distance
 * of their midpoints, the last interval the jump from the one before it
 * over its own length.  Returns 0 when every |x^(m)| <= 1e-7 (a solution
 * too flat to say where the mesh should go). */
static int jump_density(size_t n, size_t m, size_t N, int periodic, const double *D,
                        const double *old, double *E) {
  const double pwr = 1.0 / ((double)m + 1.0);
  int flat = 1;
  for (size_t i = 0; i < n * N; ++i)
    if (fabs(D[i]) > 1e-7) flat = 0;
  if (flat) return 0;
  for (size_t i = 0; i + 1 < N; ++i) {
    const double mid = 0.5 * (old[i + 2] - old[i]);
    double e = 0.0;
    for (size_t r = 0; r < n; ++r) e += pow(fabs(D[n * (i + 1) + r] - D[n * i + r]) / mid, pwr);
    E[i] = e;
  }
  const size_t last = N - 1, other = periodic ? 0 : last - 1;
  const double hl = periodic ? 0.5 * (old[N] - old[N - 1] + old[1] - old[0])
                             : old[N] - old[N - 1];
  double e = 0.0;
  for (size_t r = 0; r < n; ++r)
    e += pow(fabs(D[n * other + r] - D[n * last + r]) / hl, pwr);
  E[last] = e;
  return 1;
}

int colloc_basis_mesh_from_jumps(size_t n, size_t m, size_t N, int periodic,
                                 const double *dm, const double *X, const double *old,
                                 size_t Nnew, double *mesh, double *E, double *Q,
                                 double *D) {
  for (size_t i = 0; i < N; ++i)
    for (size_t r = 0; r < n; ++r) {
      D[n * i + r] = mth_derivative(n, m, dm, X, old, i, r);
      if (!isfinite(D[n * i + r])) return -1 - (int)i;
    }
  if (N < 2 || !jump_density(n, m, N, periodic, D, old, E)) {
    for (size_t k = 0; k <= Nnew; ++k) mesh[k] = Nnew == N ? old[k] : (double)k / (double)Nnew;
    return 0;
  }
  return equidistribute_to(N, old, E, Q, Nnew, mesh);
}

int colloc_basis_adapt_mesh(size_t n, size_t mold, size_t nold, int periodic, const double *old,
                            const double *Xold, size_t Nnew, double *mesh, char *why,
                            size_t len) {
  if (!old || !Xold || nold < 1 || mold < 1 || mold > COLLOC_BASIS_MAXCOL || old[0] != 0.0 ||
      old[nold] != 1.0) {
    snprintf(why, len, "need a solution on %zu intervals of degree %zu (1 to %d) over a mesh "
             "from 0 to 1", nold, mold, COLLOC_BASIS_MAXCOL);
    return WHIRL_EINVAL;
  }
  for (size_t k = 1; k <= nold; ++k)
    if (!(old[k] > old[k - 1])) {
      snprintf(why, len, "the old mesh is not increasing at point %zu", k);
      return WHIRL_EINVAL;
    }
  double dm[COLLOC_BASIS_MAXCOL + 1];
  colloc_basis_derivative_weights(mold, dm);
  double *w = mesh ? malloc((nold + nold + 1 + n * nold) * sizeof *w) : NULL;
  if (!w) {
    snprintf(why, len, "out of memory");
    return WHIRL_ENOMEM;
  }
  double *E = w, *Q = E + nold, *D = Q + nold + 1;
  const int rc = colloc_basis_mesh_from_jumps(n, mold, nold, periodic, dm, Xold, old, Nnew, mesh,
                                              E, Q, D);
  free(w);
  if (rc >= 0) return 0;
  snprintf(why, len, "the solution is not finite or an interval degenerate");
  return WHIRL_EINVAL;
}

int colloc_basis_new_mesh_jumps(size_t n, size_t m, size_t N, int periodic,
                                const double *dm, const double *X, const double *old,
                                double *mesh, double *E, double *Q, double *D) {
  return colloc_basis_mesh_from_jumps(n, m, N, periodic, dm, X, old, N, mesh, E, Q, D);
}

void colloc_basis_map_nodes(size_t n, size_t m, size_t N, const double *old,
                            const double *mesh, double *copy, double *v) {
  const size_t nnodes = N * m + 1;
  memcpy(copy, v, nnodes * n * sizeof *v);
  for (size_t ii = 0; ii < N; ++ii) {
    const double h = mesh[ii + 1] - mesh[ii];
    for (size_t k = 0; k <= m; ++k) {
      const size_t j = ii * m + k;
      const double t = j == nnodes - 1 ? 1.0 : mesh[ii] + h * (double)k / (double)m;
      colloc_basis_eval_poly(n, N, m, old, copy, t, v + n * j);
    }
  }
}

void colloc_basis_map_plan(size_t m, size_t N, const double *old, const double *mesh,
                           size_t *idx, double *L) {
  const size_t nnodes = N * m + 1;
  for (size_t ii = 0; ii < N; ++ii) {
    const double h = mesh[ii + 1] - mesh[ii];
    for (size_t k = 0; k <= m; ++k) {
      const size_t j = ii * m + k;
      double t = j == nnodes - 1 ? 1.0 : mesh[ii] + h * (double)k / (double)m;
      if (t < 0.0 || t > 1.0) t -= floor(t); /* as colloc_basis_eval_poly */
      const size_t i = colloc_basis_find_interval(old, N, t);
      idx[j] = i;
      colloc_basis_lagrange_values(m, (t - old[i]) / (old[i + 1] - old[i]), L + j * (m + 1));
    }
  }
}

void colloc_basis_map_apply(size_t n, size_t m, size_t N, const size_t *idx,
                            const double *L, double *copy, double *v) {
  const size_t nnodes = N * m + 1;
  memcpy(copy, v, nnodes * n * sizeof *v);
  for (size_t j = 0; j < nnodes; ++j) {
    const double *l = L + j * (m + 1);
    double *x = v + n * j;
    for (size_t r = 0; r < n; ++r) x[r] = 0.0;
    for (size_t k = 0; k <= m; ++k) {
      const double *xk = copy + n * (idx[j] * m + k);
      for (size_t r = 0; r < n; ++r) x[r] += l[k] * xk[r];
    }
  }
}

void colloc_basis_map_many(size_t n, size_t m, size_t N, const size_t *idx,
                           const double *L, double *copies, double *const *v,
                           size_t nv, double *const *w, size_t nw, int nth) {
  const size_t len = (N * m + 1) * n, tot = nv + nw;
  if ((size_t)nth > tot) nth = (int)tot;
#pragma omp parallel for num_threads(nth) schedule(static, 1) if (nth > 1)
  for (size_t k = 0; k < tot; ++k)
    colloc_basis_map_apply(n, m, N, idx, L, copies + (size_t)whirl_thread_num() * len,
                           k < nv ? v[k] : w[k - nv]);
}

void colloc_basis_lagrange_integrals(size_t m, double *W) {
  double gs[COLLOC_BASIS_MAXCOL], gw[COLLOC_BASIS_MAXCOL], l[COLLOC_BASIS_MAXCOL + 1];
  /* W_k = int_0^1 l_k: m Gauss points integrate the degree-m l_k exactly */
  colloc_basis_gauss_legendre(m, gs, gw);
  for (size_t k = 0; k <= m; ++k) W[k] = 0.0;
  for (size_t g = 0; g < m; ++g) {
    colloc_basis_lagrange_values(m, gs[g], l);
    for (size_t k = 0; k <= m; ++k) W[k] += gw[g] * l[k];
  }
}

void colloc_basis_node_weights(size_t n, size_t m, size_t ntst, const double *mesh,
                               double *q) {
  double W[COLLOC_BASIS_MAXCOL + 1];
  colloc_basis_lagrange_integrals(m, W);
  colloc_basis_node_weights_from(n, m, ntst, mesh, W, q);
}

void colloc_basis_node_weights_from(size_t n, size_t m, size_t ntst,
                                    const double *mesh, const double *W,
                                    double *q) {
  for (size_t j = 0; j < n * (ntst * m + 1); ++j) q[j] = 0.0;
  for (size_t i = 0; i < ntst; ++i) {
    const double h = mesh[i + 1] - mesh[i];
    for (size_t k = 0; k <= m; ++k)
      for (size_t r = 0; r < n; ++r) q[n * (i * m + k) + r] += h * W[k];
  }
}

/* lib/systems/hopf.c — constructor: the minimally augmented Hopf system of
 * an equilibrium problem (squared-Jacobian formulation, Govaerts 2000,
 * ch. 4.4) with its Bogdanov-Takens and zero-Hopf tests.  See whirl/hopf.h.
 *
 * The same system follows the Neimark–Sacker points of a map's fixed
 * points (F = f − x): f_x = F_x + I has the multipliers e^{±iθ} when
 * f_x² − 2 cos θ f_x + I = F_x² + κ (F_x + I), κ = 2 (1 − cos θ), is
 * singular with a two-dimensional null space (Govaerts 2000, ch. 10;
 * Kuznetsov 2004, §10.3): only the operator and κ's start differ.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/cont.h>
#include <whirl/hopf.h>
#include <whirl/linsol.h>

#include "util/errmsg_impl.h"

struct whirl_hopf {
  whirl_system base, sys;
  size_t par, n, N, m;  /* N = n + 2 unknowns, m = n + 2 bordered order */
  double *B, *C;        /* borders n x 2, column-major */
  double *Bn, *Cn;      /* n x 2 each: the new borders of an accepted point */
  int gi[2];            /* entries of G (i + 2j) used as equations */
  int map;              /* Neimark–Sacker of a map: F_x^2 + kappa (F_x + I) */
  whirl_linsol *ls;
  whirl_eig *eig;
  double *A, *A2, *M;   /* F_x, F_x^2 + kappa I, bordered */
  double *R;            /* m x 2 right-hand sides / solutions */
  double *pf, *work, *er, *ei;
  char errmsg[WHIRL_ERRMSG_SIZE];
};

void whirl_hopf_params(const whirl_hopf *h, const double *Z, const double *p,
                       double *pfull) {
  if (pfull != p) memcpy(pfull, p, h->base.npar * sizeof *pfull);
  pfull[h->par] = Z[h->n];
}

/* A2 = F_x^2 + kappa I (a map's: F_x^2 + kappa (F_x + I)) from A = F_x. */
static void squared(const whirl_hopf *h, double kappa) {
  const size_t n = h->n;
  for (size_t j = 0; j < n; ++j)
    for (size_t i = 0; i < n; ++i) {
      double s = 0.0;
      for (size_t k = 0; k < n; ++k) s += h->A[i + n * k] * h->A[k + n * j];
      if (h->map) s += kappa * h->A[i + n * j];
      h->A2[i + n * j] = s + (i == j ? kappa : 0.0);
    }
}

/* F_x into h->A, the bordered matrix of F_x^2 + kappa I factorised, and the
 * solutions of M [V; G] = [0; I_2] (trans 0) or M^T (trans 1) in h->R. */
static int solve_G(whirl_hopf *h, const double *x, const double *p,
                   double kappa, int trans) {
  const size_t n = h->n, m = h->m;
  int rc = whirl_system_jacobian(&h->base, x, p, h->A, h->work);
  if (rc != 0) return rc;
  squared(h, kappa);
  memset(h->M, 0, m * m * sizeof *h->M);
  for (size_t j = 0; j < n; ++j) {
    memcpy(h->M + m * j, h->A2 + n * j, n * sizeof *h->M);
    h->M[n + m * j] = h->C[j];
    h->M[n + 1 + m * j] = h->C[j + n];
  }
  for (size_t k = 0; k < 2; ++k) memcpy(h->M + m * (n + k), h->B + n * k, n * sizeof *h->M);
  rc = whirl_linsol_factor(h->ls, h->M);
  if (rc != WHIRL_OK)
    return WHIRL_FAIL(
        h, rc == WHIRL_ESINGULAR ? 1 : rc,
        "Hopf system: bordered matrix of F_x^2 + kappa I is singular");
  memset(h->R, 0, 2 * m * sizeof *h->R);
  h->R[n] = 1.0;
  h->R[m + n + 1] = 1.0;
  rc = whirl_linsol_solve(h->ls, h->R, 2, trans);
  if (rc != WHIRL_OK)
    return WHIRL_FAIL(h, rc, "Hopf system: bordered solve failed");
  return 0;
}

static double G_entry(const whirl_hopf *h, int e) {
  const int i = e % 2, j = e / 2;
  return h->R[h->n + (size_t)i + h->m * (size_t)j];
}

static int hopf_F(const double *Z, const double *p, double *out, void *data) {
  whirl_hopf *h = data;
  const size_t n = h->n;
  whirl_hopf_params(h, Z, p, h->pf);
  int rc = h->base.F(Z, h->pf, out, h->base.data);
  if (rc != 0) return rc;
  if ((rc = solve_G(h, Z, h->pf, Z[n + 1], 0)) != 0) return rc;
  out[n] = G_entry(h, h->gi[0]);
  out[n + 1] = G_entry(h, h->gi[1]);
  return 0;
}

extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a,
                   const int *lda, double *wr, double *wi, double *vl, const int *ldvl,
                   double *vr, const int *ldvr, double *work, const int *lwork, int *info,
                   size_t ljobvl, size_t ljobvr);
extern void dgesv_(const int *n, const int *nrhs, double *a, const int *lda, int *ipiv,
                   double *b, const int *ldb, int *info);

/* Directional derivatives of F at x by central differences (the base's F
 * only): B(u, v) = F_xx[u, v] by polarisation of the second difference,
 * C(u, u, u) = F_xxx[u, u, u] by the five-point third difference.  f1, f2
 * are n-vectors of scratch, y one more. */
static int second_diff(whirl_hopf *h, const double *x, const double *p, const double *u,
                       const double *v, double *out, double *y, double *f1) {
  const size_t n = h->n;
  double sc = 1.0;
  for (size_t i = 0; i < n; ++i) sc = fmax(sc, fabs(x[i]));
  const double e = 1e-4 * sc;
  static const double s1[4] = {1, 1, -1, -1}, s2[4] = {1, -1, 1, -1}, w[4] = {1, -1, -1, 1};
  memset(out, 0, n * sizeof *out);
  for (int k = 0; k < 4; ++k) {
    for (size_t i = 0; i < n; ++i) y[i] = x[i] + e * (s1[k] * u[i] + s2[k] * v[i]);
    int rc = h->base.F(y, p, f1, h->base.data);
    if (rc) return rc;
    for (size_t i = 0; i < n; ++i) out[i] += w[k] * f1[i] / (4 * e * e);
  }
  return 0;
}

/* the five-point third difference at step e, added to out times c */
static int third_step(whirl_hopf *h, const double *x, const double *p, const double *u,
                      double e, double c, double *out, double *y, double *f1) {
  const size_t n = h->n;
  static const double s[4] = {2, 1, -1, -2}, w[4] = {1, -2, 2, -1};
  for (int k = 0; k < 4; ++k) {
    for (size_t i = 0; i < n; ++i) y[i] = x[i] + s[k] * e * u[i];
    int rc = h->base.F(y, p, f1, h->base.data);
    if (rc) return rc;
    for (size_t i = 0; i < n; ++i) out[i] += c * w[k] * f1[i] / (2 * e * e * e);
  }
  return 0;
}

/* ... Richardson-extrapolated from steps 2e and e: O(e^4) */
static int third_diff(whirl_hopf *h, const double *x, const double *p, const double *u,
                      double *out, double *y, double *f1) {
  const size_t n = h->n;
  double sc = 1.0;
  for (size_t i = 0; i < n; ++i) sc = fmax(sc, fabs(x[i]));
  const double e = 1e-3 * sc;
  memset(out, 0, n * sizeof *out);
  int rc = third_step(h, x, p, u, e, 4.0 / 3.0, out, y, f1);
  return rc ? rc : third_step(h, x, p, u, 2 * e, -1.0 / 3.0, out, y, f1);
}

/* Re(p^H v), p = pr + i pi, v = vr + i vi */
static double ph_re(const double *pr, const double *pi, const double *vr, const double *vi,
                    size_t n) {
  double s = 0;
  for (size_t i = 0; i < n; ++i) s += pr[i] * vr[i] + pi[i] * vi[i];
  return s;
}

/* The first Lyapunov coefficient at a Hopf point with F_x = h->A
 * (Kuznetsov, Elements of Applied Bifurcation Theory, 3rd ed., 2004,
 * eq. 3.20 and §10.2.1): with A q = iω q, p^H A = iω p^H, p^H q = 1,
 *   l1 = Re[p^H C(q, q, q̄) − 2 p^H B(q, A⁻¹ B(q, q̄))
 *           + p^H B(q̄, (2iω − A)⁻¹ B(q, q))] / (2ω),
 * B and C by differences of F.  Its sign change along a Hopf curve is
 * the generalised Hopf (Bautin) point GH.  NAN when it cannot be had. */
static double lyapunov1(whirl_hopf *h, const double *x, const double *p, double kappa) {
  const int n = (int)h->n, lw = 8 * n + 16;
  const size_t N = (size_t)n;
  double *buf = malloc((size_t)(6 * n * n + 30 * n + lw) * sizeof *buf);
  int *ipiv = malloc(2 * N * sizeof *ipiv);
  double l1 = NAN;
  if (!buf || !ipiv) goto out;
  double *A = buf, *VL = A + N * N, *VR = VL + N * N, *T = VR + N * N; /* T: 2n x 2n */
  double *wr = T + 4 * N * N, *wi = wr + N, *a = wi + N, *b = a + N, *pr = b + N, *pi = pr + N;
  double *v1 = pi + N, *v2 = v1 + N, *v3 = v2 + N, *g = v3 + N, *y = g + N, *f1 = y + N;
  double *br = f1 + N, *bi = br + N, *rr = bi + 2 * N, *work = rr + 8 * N;
  int info = 0, one = 1, n2 = 2 * n;
  memcpy(A, h->A, N * N * sizeof *A);
  dgeev_("V", "V", &n, A, &n, wr, wi, VL, &n, VR, &n, work, &lw, &info, 1, 1);
  if (info) goto out;
  /* the pair nearest i sqrt(kappa) */
  int k = -1;
  double best = INFINITY, om = sqrt(fmax(kappa, 0.0));
  for (int i = 0; i < n; ++i)
    if (wi[i] > 0 && hypot(wr[i], wi[i] - om) < best) best = hypot(wr[i], wi[i] - om), k = i;
  if (k < 0 || k + 1 >= n) goto out;
  const double w = wi[k];
  for (size_t i = 0; i < N; ++i) { /* q = a + i b; left vector u = pr + i pi */
    a[i] = VR[i + N * k], b[i] = VR[i + N * (k + 1)];
    pr[i] = VL[i + N * k], pi[i] = VL[i + N * (k + 1)];
  }
  /* p^H q = c: p := p / conj(c) so that p^H q = 1 */
  double cr = 0, ci = 0;
  for (size_t i = 0; i < N; ++i)
    cr += pr[i] * a[i] + pi[i] * b[i], ci += pr[i] * b[i] - pi[i] * a[i];
  const double c2 = cr * cr + ci * ci;
  if (!(c2 > 0)) goto out;
  for (size_t i = 0; i < N; ++i) { /* p / conj(c) = p c / |c|^2 */
    const double r = (pr[i] * cr - pi[i] * ci) / c2, m = (pr[i] * ci + pi[i] * cr) / c2;
    pr[i] = r, pi[i] = m;
  }
  double sum_r = 0;
  /* C(q, q, q̄) = C(a,a,a) + C(a,b,b) + i [C(a,a,b) + C(b,b,b)] */
  int rc = 0;
  double *Caaa = v1, *Cbbb = v2, *Cp = v3, *Cm = g;
  rc |= third_diff(h, x, p, a, Caaa, y, f1);
  rc |= third_diff(h, x, p, b, Cbbb, y, f1);
  for (size_t i = 0; i < N; ++i) br[i] = a[i] + b[i], bi[i] = a[i] - b[i];
  rc |= third_diff(h, x, p, br, Cp, y, f1);
  rc |= third_diff(h, x, p, bi, Cm, y, f1);
  if (rc) goto out;
  for (size_t i = 0; i < N; ++i) {
    const double Cabb = (Cp[i] + Cm[i] - 2 * Caaa[i]) / 6, Caab = (Cp[i] - Cm[i] - 2 * Cbbb[i]) / 6;
    rr[i] = Caaa[i] + Cabb; /* real part */
    rr[N + i] = Caab + Cbbb[i]; /* imaginary part */
  }
  sum_r += ph_re(pr, pi, rr, rr + N, N);
  /* B(q, q̄) = B(a,a) + B(b,b), real; A^{-1} of it */
  rc |= second_diff(h, x, p, a, a, v1, y, f1);
  rc |= second_diff(h, x, p, b, b, v2, y, f1);
  if (rc) goto out;
  for (size_t i = 0; i < N; ++i) g[i] = v1[i] + v2[i];
  memcpy(T, h->A, N * N * sizeof *T);
  dgesv_(&n, &one, T, &n, ipiv, g, &n, &info);
  if (info) goto out;
  /* B(q, g) = B(a, g) + i B(b, g) */
  rc |= second_diff(h, x, p, a, g, v1, y, f1);
  rc |= second_diff(h, x, p, b, g, v2, y, f1);
  if (rc) goto out;
  sum_r -= 2 * ph_re(pr, pi, v1, v2, N);
  /* B(q, q) = B(a,a) − B(b,b) + 2i B(a,b); (2iω − A) s = B(q, q) */
  rc |= second_diff(h, x, p, a, a, v1, y, f1);
  rc |= second_diff(h, x, p, b, b, v2, y, f1);
  rc |= second_diff(h, x, p, a, b, v3, y, f1);
  if (rc) goto out;
  for (size_t i = 0; i < N; ++i) rr[i] = v1[i] - v2[i], rr[N + i] = 2 * v3[i];
  memset(T, 0, 4 * N * N * sizeof *T); /* [-A, -2ω I; 2ω I, -A] */
  for (size_t j = 0; j < N; ++j) {
    for (size_t i = 0; i < N; ++i) {
      T[i + 2 * N * j] = -h->A[i + N * j];
      T[N + i + 2 * N * (N + j)] = -h->A[i + N * j];
    }
    T[j + 2 * N * (N + j)] = -2 * w;
    T[N + j + 2 * N * j] = 2 * w;
  }
  dgesv_(&n2, &one, T, &n2, ipiv, rr, &n2, &info);
  if (info) goto out;
  /* B(q̄, s) = B(a, sr) + B(b, si) + i [B(a, si) − B(b, sr)] */
  double *sr = rr, *si = rr + N;
  rc |= second_diff(h, x, p, a, sr, v1, y, f1);
  rc |= second_diff(h, x, p, b, si, v2, y, f1);
  rc |= second_diff(h, x, p, a, si, v3, y, f1);
  rc |= second_diff(h, x, p, b, sr, g, y, f1);
  if (rc) goto out;
  for (size_t i = 0; i < N; ++i) br[i] = v1[i] + v2[i], bi[i] = v3[i] - g[i];
  sum_r += ph_re(pr, pi, br, bi, N);
  l1 = sum_r / (2 * w);
out:
  free(buf);
  free(ipiv);
  return l1;
}

static int hopf_test(const double *Z, const double *p, double *tau, int *types,
                     void *data) {
  whirl_hopf *h = data;
  const size_t n = h->n;
  const double kappa = Z[n + 1];
  whirl_hopf_params(h, Z, p, h->pf);
  int rc = whirl_system_jacobian(&h->base, Z, h->pf, h->A, h->work);
  if (rc != 0) return rc;
  tau[WHIRL_HOPF_TEST_BT] = kappa;
  types[WHIRL_HOPF_TEST_BT] = WHIRL_PT_BT;
  tau[WHIRL_HOPF_TEST_ZH] = 1.0;
  types[WHIRL_HOPF_TEST_ZH] = 0;
  /* l1 only where the curve is a Hopf curve (kappa = omega^2 > 0): NAN
   * (no sign, so no GH sought across) on its neutral-saddle part and where
   * it cannot be had, else the passage through a BT (l1 ~ 1/omega there)
   * or onto the saddle part would read as a sign change */
  tau[WHIRL_HOPF_TEST_GH] = NAN;
  types[WHIRL_HOPF_TEST_GH] = h->map ? 0 : WHIRL_PT_GH;
  if (!h->map && kappa > 0) tau[WHIRL_HOPF_TEST_GH] = lyapunov1(h, Z, h->pf, kappa);
  /* a map's κ → 0 is the 1:1 resonance, not a Bogdanov–Takens point (its
   * zero-Hopf analogue, a multiplier through 1, is not labelled yet); the
   * strong resonances θ = 0, π, 2π/3, π/2 are κ = 0, 4, 3, 2 */
  static const double kres[4] = {0.0, 4.0, 3.0, 2.0};
  for (int r = 0; r < 4; ++r) {
    tau[WHIRL_HOPF_TEST_R1 + r] = h->map ? kappa - kres[r] : 1.0;
    types[WHIRL_HOPF_TEST_R1 + r] = h->map ? WHIRL_PT_R1 + r : 0;
  }
  if (h->map) types[WHIRL_HOPF_TEST_BT] = 0, tau[WHIRL_HOPF_TEST_BT] = 1.0;
  if (n < 3 || h->map) return 0;
  if (whirl_eig_compute(h->eig, h->A, h->er, h->ei) != WHIRL_OK) return 0;
  /* drop the two eigenvalues nearest +-i sqrt(kappa) (or +-sqrt(-kappa)),
   * i.e. the two smallest |l^2 + kappa|; the product of the others changes
   * sign when one of them crosses zero */
  size_t d0 = 0, d1 = 1;
  double r0 = INFINITY, r1 = INFINITY;
  for (size_t i = 0; i < n; ++i) {
    const double re = h->er[i] * h->er[i] - h->ei[i] * h->ei[i] + kappa;
    const double im = 2.0 * h->er[i] * h->ei[i];
    const double r = hypot(re, im);
    if (r < r0) {
      r1 = r0, d1 = d0;
      r0 = r, d0 = i;
    } else if (r < r1) {
      r1 = r, d1 = i;
    }
  }
  double prod = 1.0;
  for (size_t i = 0; i < n; ++i)
    if (i != d0 && i != d1)
      prod *= (h->ei[i] == 0.0 ? h->er[i] : hypot(h->er[i], h->ei[i])) /
              (1.0 + hypot(h->er[i], h->ei[i]));
  /* complex eigenvalues come in pairs whose product |l|^2 > 0: only real ones
   * carry the sign */
  tau[WHIRL_HOPF_TEST_ZH] = prod;
  types[WHIRL_HOPF_TEST_ZH] = WHIRL_PT_ZH;
  return 0;
}

/* Orthonormal pair from the first n rows of the two columns of R. */
static void orthonormal2(const double *R, size_t n, size_t m, double *Q) {
  double a = 0.0;
  for (size_t i = 0; i < n; ++i) a += R[i] * R[i];
  a = sqrt(a);
  for (size_t i = 0; i < n; ++i) Q[i] = R[i] / a;
  double d = 0.0;
  for (size_t i = 0; i < n; ++i) d += Q[i] * R[m + i];
  double b = 0.0;
  for (size_t i = 0; i < n; ++i) {
    Q[n + i] = R[m + i] - d * Q[i];
    b += Q[n + i] * Q[n + i];
  }
  b = sqrt(b);
  for (size_t i = 0; i < n; ++i) Q[n + i] /= b;
}

static int hopf_accept(const double *Z, const double *p, void *data) {
  whirl_hopf *h = data;
  const size_t n = h->n;
  whirl_hopf_params(h, Z, p, h->pf);
  double *Cn = h->Cn, *Bn = h->Bn;
  if (solve_G(h, Z, h->pf, Z[n + 1], 0) != 0) return 0;
  orthonormal2(h->R, n, h->m, Cn);
  if (solve_G(h, Z, h->pf, Z[n + 1], 1) != 0) return 0;
  orthonormal2(h->R, n, h->m, Bn);
  int ok = 1;
  for (size_t i = 0; i < 2 * n; ++i) ok &= isfinite(Cn[i]) && isfinite(Bn[i]);
  if (ok) {
    memcpy(h->C, Cn, 2 * n * sizeof *Cn);
    memcpy(h->B, Bn, 2 * n * sizeof *Bn);
  }
  if (h->base.accept) return h->base.accept(Z, h->pf, h->base.data);
  return 0;
}

whirl_hopf *whirl_hopf_alloc(const whirl_system *base, size_t par, char *errbuf,
                             size_t errlen) {
  const char *why = NULL;
  if (!base || !base->F || base->n < 2) why = "base system needs F and n >= 2";
  else if (par >= base->npar) why = "Hopf parameter is not a parameter of the base system";
  if (why) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_hopf_alloc: %s", why);
    return NULL;
  }
  const size_t n = base->n, m = n + 2;
  whirl_hopf *h = calloc(1, sizeof *h);
  if (!h) goto nomem;
  h->base = *base;
  h->par = par;
  h->n = n;
  h->N = n + 2;
  h->m = m;
  h->gi[0] = 0;
  h->gi[1] = 3;
  h->B = calloc(2 * n, sizeof *h->B);
  h->C = calloc(2 * n, sizeof *h->C);
  h->Bn = calloc(2 * n, sizeof *h->Bn);
  h->Cn = calloc(2 * n, sizeof *h->Cn);
  h->ls = whirl_linsol_alloc_dense(m);
  h->eig = whirl_eig_alloc(n);
  h->A = calloc(n * n, sizeof *h->A);
  h->A2 = calloc(n * n, sizeof *h->A2);
  h->M = calloc(m * m, sizeof *h->M);
  h->R = calloc(2 * m, sizeof *h->R);
  h->pf = calloc(base->npar, sizeof *h->pf);
  h->work = calloc(2 * n + 2 + base->nnz, sizeof *h->work); /* max(2n, nnz) */
  h->er = calloc(n, sizeof *h->er);
  h->ei = calloc(n, sizeof *h->ei);
  if (!h->B || !h->C || !h->Bn || !h->Cn || !h->ls || !h->eig || !h->A || !h->A2 || !h->M ||
      !h->R || !h->pf || !h->work || !h->er || !h->ei)
    goto nomem;
  whirl_system *s = &h->sys;
  s->name = "Hopf curve";
  s->n = h->N;
  s->npar = base->npar;
  s->F = hopf_F;
  s->accept = hopf_accept;
  s->ntest = WHIRL_HOPF_NTEST;
  s->test = hopf_test;
  s->p_names = base->p_names;
  s->data = h;
  return h;
nomem:
  whirl_hopf_free(h);
  WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "whirl_hopf_alloc: out of memory");
  return NULL;
}

whirl_hopf *whirl_hopf_alloc_map(const whirl_system *base, size_t par, char *errbuf,
                                 size_t errlen) {
  whirl_hopf *h = whirl_hopf_alloc(base, par, errbuf, errlen);
  if (!h) return NULL;
  h->map = 1;
  h->sys.name = "Neimark-Sacker curve";
  return h;
}

void whirl_hopf_free(whirl_hopf *h) {
  if (!h) return;
  whirl_linsol_free(h->ls);
  whirl_eig_free(h->eig);
  free(h->B); free(h->C); free(h->Bn); free(h->Cn);
  free(h->A); free(h->A2); free(h->M); free(h->R);
  free(h->pf); free(h->work); free(h->er); free(h->ei);
  free(h);
}

const whirl_system *whirl_hopf_system(const whirl_hopf *h) { return &h->sys; }
size_t whirl_hopf_size(const whirl_hopf *h) { return h->N; }
const char *whirl_hopf_errmsg(const whirl_hopf *h) { return h->errmsg; }

int whirl_hopf_init(whirl_hopf *h, const double *x, const double *p, double *Z) {
  const size_t n = h->n;
  int rc = whirl_system_jacobian(&h->base, x, p, h->A, h->work);
  if (rc != 0)
    return WHIRL_FAIL(h, rc < 0 ? rc : WHIRL_EDOMAIN,
                      "Hopf start: the Jacobian failed (%d)", rc);
  if ((rc = whirl_eig_compute(h->eig, h->A, h->er, h->ei)) != WHIRL_OK)
    return WHIRL_FAIL(h, rc, "Hopf start: eigenvalues failed");
  double best = INFINITY, omega = 0.0, kappa = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!(h->ei[i] > 0)) continue;
    /* a map's multiplier 1 + λ nearest the unit circle: κ = 2 (1 − cos θ) */
    const double dist = h->map ? fabs(hypot(1.0 + h->er[i], h->ei[i]) - 1.0) : fabs(h->er[i]);
    if (dist < best) {
      best = dist, omega = h->ei[i];
      kappa = h->map ? 2.0 * (1.0 - cos(atan2(h->ei[i], 1.0 + h->er[i]))) : omega * omega;
    }
  }
  if (!(omega > 0))
    return WHIRL_FAIL(h, WHIRL_EINVAL, h->map ? "Neimark-Sacker start: f_x has no complex "
                      "pair (not a TR point of the map)" : "Hopf start: F_x has no complex "
                      "pair (not a Hopf point)");
  squared(h, kappa);
  double sv[2];
  if ((rc = whirl_null_vectors(n, n, h->A2, 2, h->C, sv)) != WHIRL_OK)
    return WHIRL_FAIL(h, rc, "Hopf start: SVD failed");
  double *T = h->M; /* scratch n*n <= m*m */
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) T[j + n * i] = h->A2[i + n * j];
  if ((rc = whirl_null_vectors(n, n, T, 2, h->B, sv)) != WHIRL_OK)
    return WHIRL_FAIL(h, rc, "Hopf start: SVD failed");
  memcpy(Z, x, n * sizeof *Z);
  Z[n] = p[h->par];
  Z[n + 1] = kappa;
  /* choose the two entries of G whose derivatives in (p[par], kappa) are
   * best conditioned */
  double d[2][4];
  whirl_hopf_params(h, Z, p, h->pf);
  const double hq = 1e-6 * (1.0 + fabs(Z[n])), hk = 1e-6 * (1.0 + kappa);
  for (int k = 0; k < 2; ++k) {
    double gp[4], gm[4];
    for (int side = 0; side < 2; ++side) {
      const double sg = side ? -1.0 : 1.0;
      whirl_hopf_params(h, Z, p, h->pf);
      if (k == 0) h->pf[h->par] += sg * hq;
      rc = solve_G(h, x, h->pf, kappa + (k == 1 ? sg * hk : 0.0), 0);
      if (rc != 0) {
        char
            why[sizeof h->errmsg]; /* the message is formatted into h->errmsg */
        memcpy(why, h->errmsg, sizeof why);
        return WHIRL_FAIL(h, rc < 0 ? rc : WHIRL_ESINGULAR, "Hopf start: %s",
                          why);
      }
      for (int e = 0; e < 4; ++e) (side ? gm : gp)[e] = G_entry(h, e);
    }
    for (int e = 0; e < 4; ++e) d[k][e] = (gp[e] - gm[e]) / (2.0 * (k ? hk : hq));
  }
  double bestdet = -1.0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      const double det = fabs(d[0][a] * d[1][b] - d[1][a] * d[0][b]);
      if (det > bestdet) bestdet = det, h->gi[0] = a, h->gi[1] = b;
    }
  h->errmsg[0] = 0;
  return WHIRL_OK;
}

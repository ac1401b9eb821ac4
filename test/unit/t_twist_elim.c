/* test/unit/t_twist_elim.c — the structured elimination of a collocation
 * operator with a twisted boundary condition (lib/systems/twist_elim.h)
 * against the operator assembled densely here, by what the elimination
 * promises and not by its own steps:
 *   - det A(θ) / det S(θ) does not depend on θ (the row operations Q are
 *     real and the same for every angle);
 *   - where S(θ) is made singular (B0 chosen so, S being affine in B0), v
 *     from its null vector solves A(θ) v = 0 on every row;
 *   - for any w0, w = Q^T (0; w0) has A(θ)^H w = 0 on every column but
 *     v(0)'s, and S(θ)^H w0 there;
 * on random blocks; and on a mesh of transfers that grow and shrink by
 * 10^85 over the orbit, where the monodromy matrix has no digits left, the
 * decaying null vector to ten digits at every node.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "systems/twist_elim.h"
#include "tap.h"

typedef double complex cplx;

static double rnd(unsigned *s) {
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffff) / 32768.0 - 1.0;
}

/* The dense A(θ) (na × na, column-major) from the blocks as filled (G,
 * copied before twist_factor overwrote them), BN and B0. */
static void assemble(const double *G0, const double *bn, size_t n, size_t N, size_t m,
                     const cplx *b0, cplx *A) {
  const size_t na = n * (N * m + 1), R = n * m;
  memset(A, 0, na * na * sizeof *A);
  for (size_t i = 0; i < N; ++i) {
    const double *G = G0 + i * R * n * (m + 1);
    for (size_t c = 0; c < n * (m + 1); ++c)
      for (size_t r = 0; r < R; ++r) A[(i * R + r) + na * (i * m * n + c)] = G[r + R * c];
  }
  for (size_t k = 0; k < n; ++k)
    for (size_t r = 0; r < n; ++r) {
      A[(N * R + r) + na * k] = b0[r + n * k];
      A[(N * R + r) + na * (N * m * n + k)] = bn[r + n * k];
    }
}

/* log|det| and arg det of a complex matrix by LU with partial pivoting (a
 * copy). */
static cplx det_polar(const cplx *A0, size_t k) {
  cplx *A = malloc(k * k * sizeof *A);
  memcpy(A, A0, k * k * sizeof *A);
  double la = 0.0, ph = 0.0;
  for (size_t j = 0; j < k; ++j) {
    size_t p = j;
    for (size_t i = j + 1; i < k; ++i)
      if (cabs(A[i + k * j]) > cabs(A[p + k * j])) p = i;
    if (p != j) {
      ph += M_PI;
      for (size_t c = 0; c < k; ++c) {
        const cplx s = A[j + k * c];
        A[j + k * c] = A[p + k * c], A[p + k * c] = s;
      }
    }
    const cplx d = A[j + k * j];
    la += log(cabs(d));
    ph += carg(d);
    for (size_t i = j + 1; i < k; ++i) {
      const cplx l = A[i + k * j] / d;
      for (size_t c = j + 1; c < k; ++c) A[i + k * c] -= l * A[j + k * c];
    }
  }
  free(A);
  return la + I * remainder(ph, 2.0 * M_PI);
}

/* Random blocks and BN. */
static void fill(twist_elim *e, size_t n, size_t N, size_t m, unsigned *s) {
  for (size_t i = 0; i < N; ++i) {
    double *G = twist_block(e, i);
    for (size_t q = 0; q < n * m * n * (m + 1); ++q) G[q] = rnd(s);
  }
  for (size_t q = 0; q < n * n; ++q) twist_bn(e)[q] = rnd(s);
}

static void reduce(twist_elim *e, size_t n, const cplx *b0, cplx *S) {
  double *br = malloc(n * n * sizeof *br), *bi = malloc(n * n * sizeof *bi);
  double *sr = malloc(n * n * sizeof *sr), *si = malloc(n * n * sizeof *si);
  for (size_t q = 0; q < n * n; ++q) br[q] = creal(b0[q]), bi[q] = cimag(b0[q]);
  twist_reduce(e, br, bi, sr, si);
  for (size_t q = 0; q < n * n; ++q) S[q] = sr[q] + I * si[q];
  free(br), free(bi), free(sr), free(si);
}

/* x = M^{-1} y for a complex k × k M (a copy), partial pivoting. */
static void csolve(const cplx *M0, size_t k, cplx *x) {
  cplx *M = malloc(k * k * sizeof *M);
  memcpy(M, M0, k * k * sizeof *M);
  for (size_t j = 0; j < k; ++j) {
    size_t p = j;
    for (size_t i = j + 1; i < k; ++i)
      if (cabs(M[i + k * j]) > cabs(M[p + k * j])) p = i;
    for (size_t c = 0; c < k; ++c) {
      const cplx s = M[j + k * c];
      M[j + k * c] = M[p + k * c], M[p + k * c] = s;
    }
    const cplx s = x[j];
    x[j] = x[p], x[p] = s;
    for (size_t i = j + 1; i < k; ++i) {
      const cplx l = M[i + k * j] / M[j + k * j];
      for (size_t c = j; c < k; ++c) M[i + k * c] -= l * M[j + k * c];
      x[i] -= l * x[j];
    }
  }
  for (size_t j = k; j-- > 0;) {
    for (size_t c = j + 1; c < k; ++c) x[j] -= M[j + k * c] * x[c];
    x[j] /= M[j + k * j];
  }
  free(M);
}

/* B0 with S(θ)'s first column zero: S = S0 + Mx B0 (S affine in B0, Mx
 * from S at B0 = 0 and at the unit columns), so B0 = b0 − Mx^{-1} S(b0)
 * e1 e1^T. */
static void make_singular(twist_elim *e, size_t n, cplx *b0) {
  cplx *S = malloc(n * n * sizeof *S), *S0 = malloc(n * n * sizeof *S0);
  cplx *Mx = malloc(n * n * sizeof *Mx), *z = calloc(n * n, sizeof *z), *x = malloc(n * sizeof *x);
  reduce(e, n, z, S0);
  for (size_t k = 0; k < n; ++k) { /* Mx e_k = S(e_k e1^T) e1 − S0 e1 */
    z[k] = 1.0;
    reduce(e, n, z, S);
    for (size_t i = 0; i < n; ++i) Mx[i + n * k] = S[i] - S0[i];
    z[k] = 0.0;
  }
  reduce(e, n, b0, S);
  for (size_t i = 0; i < n; ++i) x[i] = S[i];
  csolve(Mx, n, x);
  for (size_t i = 0; i < n; ++i) b0[i] -= x[i];
  free(S), free(S0), free(Mx), free(z), free(x);
}

static void check(size_t n, size_t N, size_t m, unsigned seed) {
  const size_t na = n * (N * m + 1);
  twist_elim *e = twist_alloc(n, N, m);
  unsigned s = seed;
  fill(e, n, N, m, &s);
  const size_t gsz = N * n * m * n * (m + 1);
  double *G = malloc(gsz * sizeof *G), *bn = malloc(n * n * sizeof *bn);
  memcpy(G, twist_block(e, 0), gsz * sizeof *G);
  memcpy(bn, twist_bn(e), n * n * sizeof *bn);
  const int frc = twist_factor(e);
  cplx *A = malloc(na * na * sizeof *A), *b0 = malloc(n * n * sizeof *b0);
  cplx *S = malloc(n * n * sizeof *S);
  const char *what = "random blocks";
  ok(e && frc == 0, "%s (n %zu, NTST %zu, NCOL %zu): factored", what, n, N, m);
  /* det A(θ) / det S(θ) the same at three angles (random B0's E part) */
  double spread = 0.0;
  cplx ref = 0.0;
  for (size_t q = 0; q < n * n; ++q) b0[q] = rnd(&s);
  for (int a = 0; a < 3; ++a) {
    const double th = 0.4 + 0.9 * a;
    cplx *bt = malloc(n * n * sizeof *bt);
    for (size_t q = 0; q < n * n; ++q) bt[q] = b0[q];
    for (size_t k = 0; k < n; ++k) bt[k + n * k] -= cexp(I * th); /* −e^{iθ} v(0) */
    assemble(G, bn, n, N, m, bt, A);
    reduce(e, n, bt, S);
    const cplx d = det_polar(A, na) - det_polar(S, n);
    if (a == 0) ref = d;
    spread = fmax(spread, cabs(creal(d - ref) + I * remainder(cimag(d - ref), 2 * M_PI)));
    free(bt);
  }
  ok(spread < 1e-10, "%s: log det A(theta) - log det S(theta) the same at three angles "
       "(spread %.1e)", what, spread);
  /* S made singular: A v = 0 from its null vector e1 */
  make_singular(e, n, b0);
  assemble(G, bn, n, N, m, b0, A);
  reduce(e, n, b0, S);
  double *vr = calloc(na, sizeof *vr), *vi = calloc(na, sizeof *vi);
  double v0r[128] = {1.0}, v0i[128] = {0.0};
  twist_right(e, v0r, v0i, vr, vi);
  double res = 0.0, scale = 0.0, vmax = 0.0;
  for (size_t j = 0; j < na; ++j) vmax = fmax(vmax, cabs(vr[j] + I * vi[j]));
  for (size_t i = 0; i < na; ++i) {
    cplx r = 0.0;
    double a = 0.0;
    for (size_t j = 0; j < na; ++j) {
      r += A[i + na * j] * (vr[j] + I * vi[j]);
      a += cabs(A[i + na * j]) * cabs(vr[j] + I * vi[j]);
    }
    res = fmax(res, cabs(r));
    scale = fmax(scale, a);
  }
  ok(res <= 1e-12 * scale, "%s: S(theta) singular, A(theta) v = 0 on every row "
     "(|Av| %.1e, |A||v| %.1e, |v| %.1e)", what, res, scale, vmax);
  /* w = Q^T (0; w0): A^H w zero but on v(0)'s columns, S^H w0 there */
  double w0r[128], w0i[128];
  for (size_t k = 0; k < n; ++k) w0r[k] = rnd(&s), w0i[k] = rnd(&s);
  double *wr = calloc(na, sizeof *wr), *wi = calloc(na, sizeof *wi);
  twist_left(e, w0r, w0i, wr, wi);
  double off = 0.0, at0 = 0.0, wsc = 0.0;
  for (size_t j = 0; j < na; ++j) {
    cplx r = 0.0;
    double a = 0.0;
    for (size_t i = 0; i < na; ++i) {
      r += conj(A[i + na * j]) * (wr[i] + I * wi[i]);
      a += cabs(A[i + na * j]) * cabs(wr[i] + I * wi[i]);
    }
    wsc = fmax(wsc, a);
    if (j >= n) {
      off = fmax(off, cabs(r));
      continue;
    }
    cplx sh = 0.0; /* (S^H w0)_j */
    for (size_t i = 0; i < n; ++i) sh += conj(S[i + n * j]) * (w0r[i] + I * w0i[i]);
    at0 = fmax(at0, cabs(r - sh));
  }
  ok(off <= 1e-12 * wsc && at0 <= 1e-12 * wsc,
     "%s: A(theta)^H Q^T (0; w0) is 0 off v(0) (%.1e) and S^H w0 on it (%.1e), |A||w| %.1e",
     what, off, at0, wsc);
  free(vr), free(vi), free(wr), free(wi), free(A), free(b0), free(S), free(G), free(bn);
  twist_free(e);
}

/* A mesh of N = 100 pure transfers u(i+1) = Φ u(i) (NCOL 1), Φ = D R(0.3),
 * D = diag(e^2, e^-2): multipliers ls and 1/ls per interval (det Φ = 1),
 * so over the orbit 10^±85.  With B0 = −ls^N I and BN = I the decaying
 * solution v_i = ls^i x_s is the null vector of A: S(θ) must be singular
 * along x_s and v must follow ls^i over all those decades, where the
 * monodromy matrix (entries 10^85) leaves none of them. */
static void check_growth(void) {
  const size_t n = 2, N = 100, R = 2;
  twist_elim *e = twist_alloc(n, N, 1);
  const double c = cos(0.3), sn = sin(0.3), a = exp(2.0), b = exp(-2.0);
  const double P[4] = {a * c, b * sn, -a * sn, b * c}; /* Φ column-major */
  for (size_t i = 0; i < N; ++i) {
    double *G = twist_block(e, i); /* [−Φ | I] */
    for (size_t q = 0; q < 4; ++q) G[q] = -P[q];
    G[0 + R * 2] = 1.0, G[1 + R * 2] = 0.0, G[0 + R * 3] = 0.0, G[1 + R * 3] = 1.0;
  }
  double *bn = twist_bn(e);
  bn[0] = 1.0, bn[1] = 0.0, bn[2] = 0.0, bn[3] = 1.0;
  const double tr = P[0] + P[3], ls = 0.5 * (tr - sqrt(tr * tr - 4.0)); /* det Φ = 1 */
  double xs[2] = {-P[2], P[0] - ls}; /* (Φ − ls) x = 0 from its first row */
  const double nx = hypot(xs[0], xs[1]);
  xs[0] /= nx, xs[1] /= nx;
  const double lN = pow(ls, (double)N);
  double b0r[4] = {-lN, 0.0, 0.0, -lN}, b0i[4] = {0}, sr[4], si[4];
  const int frc = twist_factor(e);
  twist_reduce(e, b0r, b0i, sr, si);
  const double sx0 = sr[0] * xs[0] + sr[2] * xs[1], sx1 = sr[1] * xs[0] + sr[3] * xs[1];
  double smax = 0.0;
  for (int q = 0; q < 4; ++q) smax = fmax(smax, fabs(sr[q]));
  ok(frc == 0 && hypot(sx0, sx1) <= 1e-12 * smax, "transfers over 10^+-85: S singular along "
     "the decaying direction (|S x| %.1e, |S| %.1e; the monodromy's entries %.0e)",
     hypot(sx0, sx1), smax, pow(1.0 / ls, (double)N));
  double v0i[2] = {0}, vr[2 * 101], vi[2 * 101];
  twist_right(e, xs, v0i, vr, vi);
  double worst = 0.0;
  for (size_t i = 0; i <= N; ++i) {
    const double li = pow(ls, (double)i);
    for (size_t k = 0; k < n; ++k) worst = fmax(worst, fabs(vr[n * i + k] - li * xs[k]) / li);
  }
  ok(worst < 1e-10, "transfers over 10^+-85: v(i) = ls^i x_s down to %.0e, relative error "
     "%.1e", lN, worst);
  twist_free(e);
}

int main(void) {
  check(3, 5, 4, 7u);
  check(2, 1, 3, 11u);
  check(4, 3, 2, 13u);
  check(70, 2, 2, 19u); /* more states than any fixed buffer: an FE rotor's */
  check_growth();
  ok(twist_alloc(0, 5, 4) == NULL && twist_alloc(3, 0, 4) == NULL, "no states or intervals: NULL");
  return done_testing();
}

/* lib/ode/floquet.c — Floquet multipliers from the monodromy matrix
 * (variational equations, lib/ode/variational.c; paper eq. 24; Seydel,
 * Practical Bifurcation and Stability Analysis, §7.1).  For an autonomous
 * orbit one multiplier is 1 in exact arithmetic.  It is not simply dropped
 * from the eigenvalues of M: when the orbit comes from a truncated
 * discretisation (harmonic balance) the trivial multiplier and a critical
 * one near a fold pair up into a spurious complex pair.  Instead the n − 1
 * nontrivial multipliers are the eigenvalues of the linearised Poincaré map
 * on the section h·(x − x0) = 0, h = f(x0) (Seydel §7.2):
 *   DP = Vᵀ (I − f(x_T) hᵀ / (hᵀ f(x_T))) M V,
 * V an orthonormal basis of h's orthogonal complement.  The distance of M's
 * eigenvalue nearest to 1 from 1 is reported as a check of the orbit.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/floquet.h>
#include <whirl/linsol.h>
#include <whirl/ode.h>

/* Multipliers of the Poincaré map on the section through x0 normal to
 * f(x0): er[n-1], ei[n-1] sorted by decreasing modulus. */
static int poincare_multipliers(const whirl_problem *prob, const double *p,
                                double t0, const double *x0, const double *xT,
                                const double *M, double *er, double *ei) {
  const size_t n = prob->n, k = n - 1;
  double *buf = malloc((4 * n + 3 * n * n) * sizeof *buf);
  whirl_eig *eig = whirl_eig_alloc(k ? k : 1);
  if (!buf || !eig) {
    free(buf);
    whirl_eig_free(eig);
    return WHIRL_ENOMEM;
  }
  double *h = buf, *fT = h + n, *V = fT + n, *A = V + n * n, *B = A + n * n;
  int rc = prob->rhs(t0, x0, p, h, prob->data);
  if (rc == 0) rc = prob->rhs(t0, xT, p, fT, prob->data);
  if (rc > 0) rc = WHIRL_EDOMAIN;
  double hf = 0.0;
  for (size_t i = 0; i < n; ++i) hf += h[i] * fT[i];
  if (rc == 0 && !(fabs(hf) > 0)) rc = WHIRL_ESINGULAR; /* an equilibrium */
  if (rc == 0) {
    double sv[64];
    double *svp = k <= 64 ? sv : malloc(k * sizeof *svp);
    rc = svp ? whirl_null_vectors(1, n, h, k, V, svp) : WHIRL_ENOMEM;
    if (svp != sv) free(svp);
  }
  if (rc == 0) {
    /* A = (I − fT hᵀ / hf) M  (n x n) */
    for (size_t j = 0; j < n; ++j) {
      double hm = 0.0;
      for (size_t i = 0; i < n; ++i) hm += h[i] * M[i + n * j];
      for (size_t i = 0; i < n; ++i) A[i + n * j] = M[i + n * j] - fT[i] * hm / hf;
    }
    /* B = A V (n x k), then DP = Vᵀ B (k x k) stored in A */
    for (size_t j = 0; j < k; ++j)
      for (size_t i = 0; i < n; ++i) {
        double s = 0.0;
        for (size_t l = 0; l < n; ++l) s += A[i + n * l] * V[l + n * j];
        B[i + n * j] = s;
      }
    for (size_t j = 0; j < k; ++j)
      for (size_t i = 0; i < k; ++i) {
        double s = 0.0;
        for (size_t l = 0; l < n; ++l) s += V[l + n * i] * B[l + n * j];
        A[i + k * j] = s;
      }
    rc = k ? whirl_eig_compute(eig, A, er, ei) : WHIRL_OK;
  }
  if (rc == 0)
    for (size_t i = 1; i < k; ++i)
      for (size_t j = i; j > 0 && hypot(er[j], ei[j]) > hypot(er[j - 1], ei[j - 1]); --j) {
        double a = er[j], b = ei[j];
        er[j] = er[j - 1], ei[j] = ei[j - 1];
        er[j - 1] = a, ei[j - 1] = b;
      }
  whirl_eig_free(eig);
  free(buf);
  return rc;
}

/* The farthest from 1 an autonomous orbit's trivial multiplier may be
 * computed for its others to count: a well-resolved orbit's is within
 * ~1e-6 of 1, a coarse mesh's within ~1e-2 (the pairs of test/auto-demos). */
#define TRIVIAL_TOL 0.1

/* Eigenvalues of M sorted by decreasing modulus, and with drop_trivial the
 * Poincaré-map multipliers; shared by both routes to M. */
static int multipliers_of(const whirl_problem *prob, const double *p,
                          double t0, const double *x0, const double *xT,
                          const double *Mm, int drop_trivial, double *er,
                          double *ei, double *re, double *im, size_t *m,
                          double *trivial) {
  const size_t n = prob->n;
  whirl_eig *eig = whirl_eig_alloc(n);
  if (!eig) return WHIRL_ENOMEM;
  int rc = whirl_eig_compute(eig, Mm, er, ei);
  whirl_eig_free(eig);
  if (rc != WHIRL_OK) return rc;
  /* sort by decreasing modulus (insertion sort keeps pairs adjacent) */
  for (size_t i = 1; i < n; ++i)
    for (size_t j = i; j > 0 && hypot(er[j], ei[j]) > hypot(er[j - 1], ei[j - 1]);
         --j) {
      double a = er[j], b = ei[j];
      er[j] = er[j - 1], ei[j] = ei[j - 1];
      er[j - 1] = a, ei[j - 1] = b;
    }
  if (drop_trivial) {
    double best = INFINITY;
    for (size_t i = 0; i < n; ++i) best = fmin(best, hypot(er[i] - 1.0, ei[i]));
    if (trivial) *trivial = best;
    /* An orbit's multiplier 1 (along the flow) computed this far from 1
     * says M is too ill-conditioned for any of its eigenvalues: near a
     * homoclinic loop its entries grow like e^{λT} (demo vhb, T = 30: 1e8,
     * the "multipliers" -14, -92, ... of a conservative family whose true
     * ones are 1 and 1).  Its stability is unknown, not what M says. */
    if (!(best <= TRIVIAL_TOL)) return WHIRL_ESINGULAR;
    rc = poincare_multipliers(prob, p, t0, x0, xT, Mm, er, ei);
    if (rc == WHIRL_ESINGULAR && best < INFINITY) {
      /* f(x0) = 0: a constant orbit (the start of a branch at a Hopf
       * point), with no Poincaré section: the eigenvalue of M nearest to 1
       * is dropped instead (at the Hopf point M has the pair e^{±iωT} = 1) */
      size_t drop = 0;
      for (size_t i = 1; i < n; ++i)
        if (hypot(er[i] - 1.0, ei[i]) < hypot(er[drop] - 1.0, ei[drop])) drop = i;
      for (size_t i = drop; i + 1 < n; ++i) er[i] = er[i + 1], ei[i] = ei[i + 1];
      rc = WHIRL_OK;
    }
    if (rc == WHIRL_OK) {
      for (size_t i = 0; i + 1 < n; ++i) re[i] = er[i], im[i] = ei[i];
      *m = n - 1;
    }
  } else {
    if (trivial) *trivial = NAN;
    for (size_t i = 0; i < n; ++i) re[i] = er[i], im[i] = ei[i];
    *m = n;
  }
  return rc;
}

int whirl_floquet_from_monodromy(const whirl_problem *prob, const double *p,
                                 double t0, const double *x0,
                                 const double *xT, const double *M,
                                 int drop_trivial, double *re, double *im,
                                 size_t *m, double *trivial) {
  if (!prob || !x0 || !xT || !M || !re || !im || !m) return WHIRL_EINVAL;
  const size_t n = prob->n;
  if (*m < (drop_trivial ? n - 1 : n)) return WHIRL_EINVAL;
  double *buf = malloc(2 * n * sizeof *buf);
  if (!buf) return WHIRL_ENOMEM;
  int rc = multipliers_of(prob, p, t0, x0, xT, M, drop_trivial, buf, buf + n,
                          re, im, m, trivial);
  free(buf);
  return rc;
}

int whirl_floquet_multipliers(const whirl_problem *prob, const double *p,
                              double t0, const double *x0, double T,
                              int drop_trivial, double rtol, double atol,
                              double *re, double *im, size_t *m, double *M,
                              double *trivial, char *errbuf, size_t errlen) {
  if (errbuf && errlen) errbuf[0] = '\0';
  if (!prob || !x0 || !re || !im || !m)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "whirl_floquet_multipliers: NULL argument");
  const size_t n = prob->n;
  const size_t want = drop_trivial ? n - 1 : n;
  if (*m < want || !(T > 0) || !isfinite(T))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "whirl_floquet_multipliers: capacity %zu < %zu or "
                        "period %g not positive",
                        *m, want, T);
  if (rtol <= 0) rtol = 1e-11;
  if (atol <= 0) atol = 1e-13;
  double *buf = malloc((n * n + 3 * n) * sizeof *buf);
  if (!buf)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM,
                        "whirl_floquet_multipliers: out of memory (n = %zu)",
                        n);
  double *Mm = buf, *xT = buf + n * n, *er = xT + n, *ei = er + n;
  int rc = whirl_ode_monodromy(prob, p, t0, x0, T, rtol, atol, xT, Mm, NULL,
                               errbuf, errlen);
  if (rc == WHIRL_OK)
    rc = multipliers_of(prob, p, t0, x0, xT, Mm, drop_trivial, er, ei, re, im,
                        m, trivial);
  if (rc == WHIRL_OK) {
    if (M) memcpy(M, Mm, n * n * sizeof *M);
  } else if (errbuf && !errbuf[0]) {
    WHIRL_ERRMSG(errbuf, errlen, rc, "Floquet multipliers: %s",
                 whirl_strerror(rc));
  }
  free(buf);
  return rc;
}

int whirl_floquet_real_eigvec(size_t n, const double *M, double mu, double *v) {
  double *A = malloc(n * n * sizeof *A);
  if (!A) return WHIRL_ENOMEM;
  memcpy(A, M, n * n * sizeof *A);
  for (size_t i = 0; i < n; ++i) A[i + n * i] -= mu;
  double sv;
  int rc = whirl_null_vectors(n, n, A, 1, v, &sv);
  free(A);
  return rc;
}

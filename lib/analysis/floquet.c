/* lib/analysis/floquet.c — Floquet multipliers from the monodromy matrix
 * (variational equations, lib/ode/variational.c; paper eq. 24; Seydel,
 * Practical Bifurcation and Stability Analysis, §7.1).  For an autonomous
 * orbit one multiplier is 1 in exact arithmetic; the one nearest to 1 is left
 * out and its distance to 1 reported as a check of the orbit's accuracy.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/floquet.h>
#include <whirl/linsol.h>
#include <whirl/ode.h>

int whirl_floquet_multipliers(const whirl_problem *prob, const double *p,
                              double t0, const double *x0, double T,
                              int drop_trivial, double rtol, double atol,
                              double *re, double *im, size_t *m, double *M,
                              double *trivial, char *errbuf, size_t errlen) {
  if (errbuf && errlen) errbuf[0] = '\0';
  if (!prob || !x0 || !re || !im || !m) {
    if (errbuf) snprintf(errbuf, errlen, "whirl_floquet_multipliers: NULL argument");
    return WHIRL_EINVAL;
  }
  const size_t n = prob->n;
  const size_t want = drop_trivial ? n - 1 : n;
  if (*m < want || !(T > 0) || !isfinite(T)) {
    if (errbuf)
      snprintf(errbuf, errlen,
               "whirl_floquet_multipliers: capacity %zu < %zu or period %g not "
               "positive",
               *m, want, T);
    return WHIRL_EINVAL;
  }
  if (rtol <= 0) rtol = 1e-11;
  if (atol <= 0) atol = 1e-13;
  double *buf = malloc((n * n + 3 * n) * sizeof *buf);
  whirl_eig *eig = whirl_eig_alloc(n);
  if (!buf || !eig) {
    free(buf);
    whirl_eig_free(eig);
    return WHIRL_ENOMEM;
  }
  double *Mm = buf, *xT = buf + n * n, *er = xT + n, *ei = er + n;
  int rc = whirl_ode_monodromy(prob, p, t0, x0, T, rtol, atol, xT, Mm, NULL,
                               errbuf, errlen);
  if (rc == WHIRL_OK) rc = whirl_eig_compute(eig, Mm, er, ei);
  if (rc == WHIRL_OK) {
    /* sort by decreasing modulus (insertion sort keeps pairs adjacent) */
    for (size_t i = 1; i < n; ++i)
      for (size_t j = i; j > 0 && hypot(er[j], ei[j]) > hypot(er[j - 1], ei[j - 1]);
           --j) {
        double a = er[j], b = ei[j];
        er[j] = er[j - 1], ei[j] = ei[j - 1];
        er[j - 1] = a, ei[j - 1] = b;
      }
    size_t skip = n;
    if (drop_trivial) {
      double best = INFINITY;
      for (size_t i = 0; i < n; ++i) {
        double d = hypot(er[i] - 1.0, ei[i]);
        if (d < best) best = d, skip = i;
      }
      if (trivial) *trivial = best;
    } else if (trivial) {
      *trivial = NAN;
    }
    size_t k = 0;
    for (size_t i = 0; i < n; ++i)
      if (i != skip) re[k] = er[i], im[k] = ei[i], ++k;
    *m = k;
    if (M) memcpy(M, Mm, n * n * sizeof *M);
  } else if (errbuf && !errbuf[0]) {
    snprintf(errbuf, errlen, "Floquet multipliers: %s", whirl_strerror(rc));
  }
  whirl_eig_free(eig);
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

/* lib/ode/variational.c — monodromy matrices by the variational equations
 * (paper eq. 24; e.g. Seydel, Practical Bifurcation and Stability Analysis,
 * 3rd ed., §7.1):  x' = f(t, x, p),  Φ' = f_x(t, x, p) Φ,  Φ(t0) = I,
 * integrated as one system of n + n² states (x, then Φ column-major) by the
 * Dormand–Prince integrator (lib/ode/dopri.c) with its error control on all
 * components; M = Φ(t0 + T).  f_x is the model's jac_x or central
 * differences (whirl_fd_jac_x).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>

typedef struct var_ctx {
  const whirl_problem *prob;
  double *J;    /* n*n */
  double *work; /* 2n, finite differences */
} var_ctx;

/* f and Φ' = J Φ; status of the callbacks.  A non-finite finite-difference
 * Jacobian is handed on as NaN, which the integrator treats as recoverable. */
static int var_rhs(double t, const double *y, const double *p, double *f,
                   void *data) {
  const var_ctx *c = data;
  const whirl_problem *prob = c->prob;
  const size_t n = prob->n;
  int r = prob->rhs(t, y, p, f, prob->data);
  if (r != 0) return r;
  if (prob->jac_x != NULL)
    r = prob->jac_x(t, y, p, c->J, prob->data);
  else
    r = whirl_fd_jac_x(prob, t, y, p, c->J, c->work);
  if (r == WHIRL_EBADFUNC && prob->jac_x == NULL) {
    f[0] = NAN;
    return 0;
  }
  if (r != 0) return r;
  const double *Phi = y + n, *J = c->J;
  double *dPhi = f + n;
  for (size_t j = 0; j < n; ++j) {
    const double *pc = Phi + n * j;
    double *dc = dPhi + n * j;
    for (size_t i = 0; i < n; ++i) dc[i] = 0.0;
    for (size_t k = 0; k < n; ++k) {
      const double pk = pc[k];
      const double *Jk = J + n * k;
      for (size_t i = 0; i < n; ++i) dc[i] += Jk[i] * pk;
    }
  }
  return 0;
}

int whirl_ode_monodromy(const whirl_problem *prob, const double *p, double t0,
                        const double *x0, double T, double rtol, double atol,
                        double *xT, double *M, whirl_ode_stats *stats,
                        char *errbuf, size_t errlen) {
  if (errbuf != NULL && errlen > 0) errbuf[0] = '\0';
  if (stats != NULL) memset(stats, 0, sizeof *stats);
  if (prob == NULL || prob->rhs == NULL || prob->n == 0)
    return WHIRL_ERRMSG(
        errbuf, errlen, WHIRL_EINVAL,
        "whirl_ode_monodromy: problem is NULL, has no rhs or n = 0");
  if (x0 == NULL || M == NULL || (prob->npar > 0 && p == NULL))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "whirl_ode_monodromy: x0, M or p is NULL");
  if (!isfinite(t0) || !isfinite(T))
    return WHIRL_ERRMSG(
        errbuf, errlen, WHIRL_EINVAL,
        "whirl_ode_monodromy: t0 = %g and T = %g must be finite", t0, T);
  const size_t n = prob->n;
  if (n > 4096)
    return WHIRL_ERRMSG(
        errbuf, errlen, WHIRL_EINVAL,
        "whirl_ode_monodromy: n = %zu too large for dense variational "
        "equations",
        n);
  const size_t N = n + n * n;

  var_ctx ctx = {.prob = prob, .J = NULL, .work = NULL};
  whirl_problem var = {.name = "variational equations",
                       .n = N,
                       .npar = prob->npar,
                       .rhs = var_rhs,
                       .autonomous = prob->autonomous,
                       .data = &ctx};
  double *buf = malloc((n * n + 2 * n + N) * sizeof *buf);
  whirl_ode *ode = buf != NULL ? whirl_ode_alloc(&var, p) : NULL;
  int rc;
  if (ode == NULL) {
    rc = WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM,
                      "whirl_ode_monodromy: out of memory (n = %zu)", n);
    goto done;
  }
  ctx.J = buf;
  ctx.work = buf + n * n;
  double *y0 = buf + n * n + 2 * n;
  memcpy(y0, x0, n * sizeof *y0);
  memset(y0 + n, 0, n * n * sizeof *y0);
  for (size_t j = 0; j < n; ++j) y0[n + j * (n + 1)] = 1.0;

  if ((rc = whirl_ode_set_tolerances(ode, rtol, atol)) != WHIRL_OK ||
      (rc = whirl_ode_reset(ode, t0, y0)) != WHIRL_OK ||
      (rc = whirl_ode_evolve(ode, t0 + T)) != WHIRL_OK) {
    WHIRL_ERRMSG(errbuf, errlen, rc, "whirl_ode_monodromy (%s): %s",
                 prob->name != NULL ? prob->name : "model",
                 whirl_ode_errmsg(ode));
  } else {
    const double *y = whirl_ode_x(ode);
    if (xT != NULL) memcpy(xT, y, n * sizeof *xT);
    memcpy(M, y + n, n * n * sizeof *M);
  }
  if (stats != NULL) whirl_ode_get_stats(ode, stats);
done:
  whirl_ode_free(ode);
  free(buf);
  return rc;
}

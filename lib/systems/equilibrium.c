/* lib/systems/equilibrium.c — constructor: equilibria f(x, p) = 0 of an ODE
 * model as an algebraic problem for the continuation core.  The spectrum is
 * the eigenvalues of f_x (LAPACK dgeev), so the core detects Hopf points and
 * reports stability; for non-autonomous models t is fixed at 0.
 *
 * The same object serves the fixed points x = f(x, p) of a map (AUTO's
 * IPS = -1; Kuznetsov, Elements of Applied Bifurcation Theory, 3rd ed.,
 * 2004, ch. 4): F = f − x, F_x = f_x − I, and the spectrum is the
 * eigenvalues of f_x as multipliers, so the core's multiplier tests find
 * the flip (PD, a multiplier −1) and the Neimark–Sacker point (TR, a
 * complex pair on the unit circle) and the fold is its LP.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#include <whirl/equilibrium.h>
#include <whirl/linsol.h>

#include "util/errmsg_impl.h"

struct whirl_equilibrium {
  const whirl_problem *prob;
  whirl_system sys;
  whirl_eig *eig;
  double *J;    /* n*n scratch for the spectrum */
  double *work; /* 2n scratch for finite differences */
  int map;      /* fixed points of the map's map-th iterate x ↦ f^k(x) */
  double *xk, *Jk, *Jt; /* iterates: a point, f_x there, a product (n, n*n each) */
  int *Jp, *Ji; /* full compressed-column pattern, so the sparse path of the
                   core (UMFPACK) can be used and checked against the dense */
  char errmsg[WHIRL_ERRMSG_SIZE]; /* last message (whirl_equilibrium_errmsg) */
};

/* f^k(x) into f (k >= 1 map applications, through eq->xk) */
static int iterate(const whirl_equilibrium *eq, int k, const double *x, const double *p,
                   double *f) {
  const size_t n = eq->prob->n;
  int rc = eq->prob->rhs(0.0, x, p, f, eq->prob->data);
  for (int j = 1; rc == 0 && j < k; ++j) {
    memcpy(eq->xk, f, n * sizeof *f);
    rc = eq->prob->rhs(0.0, eq->xk, p, f, eq->prob->data);
  }
  return rc;
}

static int eq_F(const double *x, const double *p, double *f, void *data) {
  const whirl_equilibrium *eq = data;
  int rc = eq->map ? iterate(eq, eq->map, x, p, f)
                   : eq->prob->rhs(0.0, x, p, f, eq->prob->data);
  if (rc == 0 && eq->map)
    for (size_t i = 0; i < eq->prob->n; ++i) f[i] -= x[i];
  return rc;
}

/* J = f_x, the model's own (or by differences): the Jacobian of the ODE,
 * the map's derivative */
static int model_jac(const whirl_equilibrium *eq, const double *x,
                     const double *p, double *J) {
  if (eq->prob->jac_x) return eq->prob->jac_x(0.0, x, p, J, eq->prob->data);
  return whirl_fd_jac_x(eq->prob, 0.0, x, p, J, eq->work);
}

/* The k-th iterate's derivative by the chain rule: J = f_x(x_{k-1}) ...
 * f_x(x_0), x_{j+1} = f(x_j). */
static int iterate_jac(const whirl_equilibrium *eq, const double *x, const double *p,
                       double *J) {
  const size_t n = eq->prob->n;
  int rc = model_jac(eq, x, p, J);
  double *xj = eq->xk + n; /* xk[n .. 2n): the current iterate */
  if (rc == 0) rc = eq->prob->rhs(0.0, x, p, xj, eq->prob->data);
  for (int j = 1; rc == 0 && j < eq->map; ++j) {
    if ((rc = model_jac(eq, xj, p, eq->Jk)) != 0) break;
    for (size_t c = 0; c < n; ++c) /* Jt = Jk J */
      for (size_t r = 0; r < n; ++r) {
        double s = 0;
        for (size_t l = 0; l < n; ++l) s += eq->Jk[r + n * l] * J[l + n * c];
        eq->Jt[r + n * c] = s;
      }
    memcpy(J, eq->Jt, n * n * sizeof *J);
    if (j + 1 < eq->map) {
      memcpy(eq->xk, xj, n * sizeof *xj);
      rc = eq->prob->rhs(0.0, eq->xk, p, xj, eq->prob->data);
    }
  }
  return rc;
}

static int eq_Fx(const double *x, const double *p, double *J, void *data) {
  const whirl_equilibrium *eq = data;
  int rc = eq->map > 1 ? iterate_jac(eq, x, p, J) : model_jac(eq, x, p, J);
  if (rc == 0 && eq->map)
    for (size_t i = 0; i < eq->prob->n; ++i) J[i + eq->prob->n * i] -= 1.0;
  return rc;
}

/* dF/dp_k: the model's jac_p gives all parameters at once (n*npar); finite
 * differences otherwise (in the core). */
static int eq_Fp(const double *x, const double *p, size_t k, double *fk,
                 void *data) {
  whirl_equilibrium *eq = data;
  const size_t n = eq->prob->n, np = eq->prob->npar;
  double stackbuf[256];
  double *Jp = n * np <= 256 ? stackbuf : malloc(n * np * sizeof *Jp);
  if (!Jp) return WHIRL_FAIL(eq, WHIRL_ENOMEM, "F_p: out of memory");
  int rc = eq->prob->jac_p(0.0, x, p, Jp, eq->prob->data);
  if (rc == 0) memcpy(fk, Jp + n * k, n * sizeof *fk);
  if (Jp != stackbuf) free(Jp);
  return rc;
}

/* Sparse values for the full pattern: column-major order equals the dense
 * layout, so the dense Jacobian is the value array. */
static int eq_Fx_sparse(const double *x, const double *p, double *Jx,
                        void *data) {
  return eq_Fx(x, p, Jx, data);
}

static int eq_spectrum(const double *x, const double *p, const double *J,
                       double *re, double *im, size_t *m, void *data) {
  whirl_equilibrium *eq = data;
  const size_t n = eq->prob->n;
  if (*m < n)
    return WHIRL_FAIL(eq, WHIRL_EINVAL,
                      "spectrum: room for %zu of %zu "
                      "eigenvalues",
                      *m, n);
  if (eq->map) { /* the multipliers: eigenvalues of f_x = F_x + I */
    int rc = J ? (memcpy(eq->J, J, n * n * sizeof *eq->J), 0) : eq_Fx(x, p, eq->J, data);
    if (rc != 0) return rc;
    for (size_t i = 0; i < n; ++i) eq->J[i + n * i] += 1.0;
    J = eq->J;
  } else if (!J) {
    int rc = eq_Fx(x, p, eq->J, data);
    if (rc != 0) return rc;
    J = eq->J;
  }
  int rc = whirl_eig_compute(eq->eig, J, re, im);
  if (rc != WHIRL_OK)
    return WHIRL_FAIL(eq, rc, "eigenvalues of f_x: %s",
                      whirl_eig_errmsg(eq->eig));
  *m = n;
  return 0;
}

whirl_equilibrium *whirl_equilibrium_alloc(const whirl_problem *prob) {
  if (!prob || !prob->rhs || prob->n == 0) return NULL;
  whirl_equilibrium *eq = calloc(1, sizeof *eq);
  if (!eq) return NULL;
  eq->prob = prob;
  eq->eig = whirl_eig_alloc(prob->n);
  eq->J = malloc(prob->n * prob->n * sizeof *eq->J);
  eq->work = malloc(2 * prob->n * sizeof *eq->work);
  eq->Jp = malloc((prob->n + 1) * sizeof *eq->Jp);
  eq->Ji = malloc(prob->n * prob->n * sizeof *eq->Ji);
  if (!eq->eig || !eq->J || !eq->work || !eq->Jp || !eq->Ji) {
    whirl_equilibrium_free(eq);
    return NULL;
  }
  for (size_t j = 0; j <= prob->n; ++j) eq->Jp[j] = (int)(j * prob->n);
  for (size_t q = 0; q < prob->n * prob->n; ++q) eq->Ji[q] = (int)(q % prob->n);
  whirl_system *s = &eq->sys;
  s->name = prob->name;
  s->n = prob->n;
  s->npar = prob->npar;
  s->F = eq_F;
  s->Fx = eq_Fx;
  s->Fp = prob->jac_p ? eq_Fp : NULL;
  s->nnz = prob->n * prob->n;
  s->Jp = eq->Jp;
  s->Ji = eq->Ji;
  s->Fx_sparse = eq_Fx_sparse;
  s->nspec = prob->n;
  s->spectrum = eq_spectrum;
  s->x_names = prob->x_names;
  s->p_names = prob->p_names;
  s->data = eq;
  return eq;
}

whirl_equilibrium *whirl_map_fixed_points_alloc(const whirl_problem *prob) {
  return whirl_map_iterate_fixed_points_alloc(prob, 1);
}

whirl_equilibrium *whirl_map_iterate_fixed_points_alloc(const whirl_problem *prob, int k) {
  if (k < 1) return NULL;
  whirl_equilibrium *eq = whirl_equilibrium_alloc(prob);
  if (!eq) return NULL;
  const size_t n = prob->n;
  eq->map = k;
  eq->sys.spectrum_kind = WHIRL_SPEC_MULTIPLIERS;
  if (k > 1) {
    eq->xk = malloc(2 * n * sizeof *eq->xk);
    eq->Jk = malloc(n * n * sizeof *eq->Jk);
    eq->Jt = malloc(n * n * sizeof *eq->Jt);
    if (!eq->xk || !eq->Jk || !eq->Jt) {
      whirl_equilibrium_free(eq);
      return NULL;
    }
    eq->sys.Fp = NULL; /* d f^k / dp: by the core's differences */
  }
  return eq;
}

void whirl_equilibrium_free(whirl_equilibrium *eq) {
  if (!eq) return;
  whirl_eig_free(eq->eig);
  free(eq->xk);
  free(eq->Jk);
  free(eq->Jt);
  free(eq->J);
  free(eq->work);
  free(eq->Jp);
  free(eq->Ji);
  free(eq);
}

const whirl_system *whirl_equilibrium_system(const whirl_equilibrium *eq) {
  return &eq->sys;
}

const char *whirl_equilibrium_errmsg(const whirl_equilibrium *eq) {
  return eq ? eq->errmsg : "whirl_equilibrium: NULL object";
}

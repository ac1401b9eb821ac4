/* test/unit/t_fe_ode.c — the first-order model of an FE rotor
 * (whirl/rotor/fe_ode.h), each against an independent route:
 *  - the analytic Jacobian (dense) against central differences of the rhs,
 *    with a cubic spring, an SFD on a pedestal and an SFD with fluid
 *    inertia (the implicit added mass);
 *  - the acceleration satisfies the equations of motion of fe.h, written
 *    out here with the element forces at the acceleration itself
 *    (M q'' + (C+ΩG) q' + K q − f0 − Ω²(...) − Σ Pᵀ f_e(r, r', r'') = 0);
 *  - BDF with the sparse (KLU) Jacobian = BDF with the dense one;
 *  - the linear rotor's steady state after its transients decayed (decay
 *    rate from its eigenvalues, whirl_fe_modes) = the complex solve of
 *    whirl_fe_unbalance_response, to 1e-8.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>
#include <whirl/rotor/fe_hbm.h>
#include <whirl/rotor/fe_linear.h>
#include <whirl/rotor/fe_ode.h>

#include "../fe_chain.h"
#include "../tap.h"

static whirl_fe_nl inertia_sfd(int node) {
  whirl_fe_nl e = fe_chain_sfd(node, -1);
  e.kind = WHIRL_FE_SFD_INERTIA;
  e.par.density = 850.0;
  e.par.length = 0.04;
  return e;
}

/* 5 nodes and a pedestal (22 DOF): a cubic spring at 0, fluid inertia at 2,
 * an SFD on the pedestal at 4. */
static whirl_fe_rotor *model5(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 5);
  co.pedestal = 1;
  co.gravity = 9.81;
  co.ks = 3e6;
  co.nnl = 3;
  co.nl[0] = fe_chain_cubic(0, 1e5, 1e13);
  co.nl[1] = inertia_sfd(2);
  co.nl[2] = fe_chain_sfd(4, 0);
  return fe_chain_build(&co);
}

static void random_state(const whirl_fe_rotor *r, double *z) {
  const double c = 2e-4;
  for (int i = 0; i < r->ndof; ++i) {
    const int rot = i < 4 * r->nnode && i % 4 >= 2;
    z[i] = tap_urand(-0.25, 0.25) * (rot ? 1e-3 : c);
    z[r->ndof + i] = tap_urand(-0.25, 0.25) * (rot ? 0.5 : 300 * c);
  }
  z[4 * r->nnode] = z[4 * r->nnode + 1] = 0.0; /* the pedestal: |r| < c */
}

static void test_jacobian(void) {
  whirl_fe_rotor *r = model5();
  char err[256] = "";
  whirl_fe_ode *m = whirl_fe_ode_alloc(r, err, sizeof err);
  const whirl_problem *P = whirl_fe_ode_problem(m);
  const size_t n = P->n;
  double p[WHIRL_FE_NPAR], *z = malloc(n * sizeof *z), *J = malloc(n * n * sizeof *J);
  double *fp = malloc(n * sizeof *fp), *fm = malloc(n * sizeof *fm);
  whirl_fe_hbm_params(350.0, p);
  p[1] = 1.2; p[2] = 1.1; p[3] = 0.9;
  random_state(r, z);
  int rc = P->jac_x(0.3, z, p, J, P->data);
  double worst = 0.0;
  for (size_t j = 0; j < n && rc == 0; ++j) {
    const double h = 1e-6 * (j < (size_t)r->ndof ? 2e-4 : 0.06), zj = z[j];
    z[j] = zj + h; rc |= P->rhs(0.3, z, p, fp, P->data);
    z[j] = zj - h; rc |= P->rhs(0.3, z, p, fm, P->data);
    z[j] = zj;
    double cmax = 0.0, emax = 0.0;
    for (size_t i = 0; i < n; ++i) {
      cmax = fmax(cmax, fabs(J[i + n * j]));
      emax = fmax(emax, fabs(J[i + n * j] - (fp[i] - fm[i]) / (2 * h)));
    }
    worst = fmax(worst, emax / fmax(cmax, 1e-300));
  }
  ok(m && rc == 0 && worst < 1e-6, "dense Jacobian against central "
     "differences, column-wise (%.2e) %s", worst, err);
  free(z); free(J); free(fp); free(fm);
  whirl_fe_ode_free(m);
  fe_chain_free(r);
}

/* y += s A x */
static void csc_mv(const whirl_fe_csc *A, double s, const double *x, double *y) {
  for (int j = 0; j < A->n; ++j)
    for (int k = A->p[j]; k < A->p[j + 1]; ++k) y[A->i[k]] += s * A->x[k] * x[j];
}

static void test_equations(void) {
  whirl_fe_rotor *r = model5();
  whirl_fe_ode *m = whirl_fe_ode_alloc(r, NULL, 0);
  const whirl_problem *P = whirl_fe_ode_problem(m);
  const int nd = r->ndof;
  double p[WHIRL_FE_NPAR], t = 0.01, *z = malloc(2 * nd * sizeof *z);
  double *f = malloc(2 * nd * sizeof *f), *res = calloc(nd, sizeof *res);
  whirl_fe_hbm_params(350.0, p);
  random_state(r, z);
  int rc = P->rhs(t, z, p, f, P->data);
  const double *q = z, *v = z + nd, *a = f + nd, Om = p[0];
  csc_mv(&r->M, 1, a, res);
  csc_mv(&r->C, 1, v, res);
  csc_mv(&r->G, Om, v, res);
  csc_mv(&r->K, 1, q, res);
  double scale = 0.0;
  for (int i = 0; i < nd; ++i) {
    res[i] -= r->f0[i] + Om * Om * (r->unb_c[i] * cos(Om * t) + r->unb_s[i] * sin(Om * t));
    scale = fmax(scale, fabs(r->f0[i]) + fabs(Om * Om * r->unb_c[i]));
  }
  for (int e = 0; e < r->nnl; ++e) {
    const whirl_fe_nl *el = &r->nl[e];
    int d = 4 * el->node, dp = el->pedestal >= 0 ? 4 * r->nnode : -1;
    double rr[2], vv[2], aa[2], fe[2];
    for (int k = 0; k < 2; ++k) {
      rr[k] = q[d + k] - (dp >= 0 ? q[dp + k] : 0);
      vv[k] = v[d + k] - (dp >= 0 ? v[dp + k] : 0);
      aa[k] = a[d + k] - (dp >= 0 ? a[dp + k] : 0);
    }
    rc |= whirl_fe_nl_force(el, rr, vv, aa, Om, fe, NULL, NULL, NULL);
    for (int k = 0; k < 2; ++k) {
      res[d + k] -= fe[k];
      if (dp >= 0) res[dp + k] += fe[k];
      scale = fmax(scale, fabs(fe[k]));
    }
  }
  double worst = 0.0, vmax = 0.0;
  for (int i = 0; i < nd; ++i) {
    worst = fmax(worst, fabs(res[i]));
    vmax = fmax(vmax, fabs(f[i] - v[i]));
  }
  ok(rc == 0 && worst < 1e-10 * scale && vmax == 0.0,
     "the acceleration satisfies M q'' + (C+ΩG) q' + K q = f(t) + Σ Pᵀ f_e(r, "
     "r', r'') with fluid inertia (residual %.2e of %.2e N)", worst, scale);
  free(z); free(f); free(res);
  whirl_fe_ode_free(m);
  fe_chain_free(r);
}

/* BDF over a few periods from a random state, dense or sparse Jacobian */
static int integrate(whirl_fe_ode *m, int sparse, const double *z0, double T,
                     double *zT, whirl_ode_implicit_stats *st) {
  const whirl_problem *P = whirl_fe_ode_problem(m);
  double p[WHIRL_FE_NPAR];
  whirl_fe_hbm_params(350.0, p);
  whirl_ode *ode = whirl_ode_alloc(P, p);
  int rc = whirl_ode_set_method(ode, WHIRL_ODE_BDF);
  rc |= whirl_ode_set_tolerances(ode, 1e-9, 1e-13);
  if (sparse == 1) rc |= whirl_fe_ode_use_sparse(m, ode);
  if (sparse == 2) rc |= whirl_fe_ode_use_mass(m, ode);
  rc |= whirl_ode_reset(ode, 0.0, z0);
  rc |= whirl_ode_evolve(ode, T);
  memcpy(zT, whirl_ode_x(ode), P->n * sizeof *zT);
  whirl_ode_get_implicit_stats(ode, st);
  whirl_ode_free(ode);
  return rc;
}

static void test_sparse(int inertia) {
  whirl_fe_rotor *r = model5();
  if (!inertia) r->nl[1].kind = WHIRL_FE_SFD_SHORT_PI;
  whirl_fe_ode *m = whirl_fe_ode_alloc(r, NULL, 0);
  const size_t n = 2 * (size_t)r->ndof;
  double *z0 = malloc(n * sizeof *z0), *zd = malloc(n * sizeof *zd), *zs = malloc(n * sizeof *zs);
  random_state(r, z0);
  whirl_ode_implicit_stats sd, ss;
  const double T = 4 * 2 * WHIRL_PI / 350.0;
  int rc0 = integrate(m, 0, z0, T, zd, &sd);
  for (int form = 1; form <= 2; ++form) {
    int rc = rc0 | integrate(m, form, z0, T, zs, &ss);
    double d = 0.0, s = 0.0;
    for (size_t i = 0; i < (size_t)r->ndof; ++i) {
      d = fmax(d, fabs(zd[i] - zs[i]));
      s = fmax(s, fabs(zd[i]));
    }
    /* the sparse f_x is the dense one: the same iterates; the mass form
     * solves the same Newton systems (exactly without fluid inertia): the
     * same solution to the integration's accuracy */
    const double tol = form == 1 ? 1e-10 : 1e-6;
    ok(rc == 0 && sd.jac_evals > 0 && ss.jac_evals > 0 && d < tol * s &&
       (form == 1 || inertia || ss.newton_fails <= sd.newton_fails + 2),
       "%s: BDF with %s = with the dense f_x after 4 periods (%.2e of %.2e m; "
       "%zu, %zu Jacobians, %zu, %zu Newton iterations, failures %zu, %zu)",
       inertia ? "fluid inertia" : "no fluid inertia",
       form == 1 ? "the sparse f_x (KLU)" : "the mass matrix on the left (KLU)", d, s,
       sd.jac_evals, ss.jac_evals, sd.newton_iters, ss.newton_iters, sd.newton_fails,
       ss.newton_fails);
  }
  free(z0); free(zd); free(zs);
  whirl_fe_ode_free(m);
  fe_chain_free(r);
}

/* ------------------------------------------------- the linear rotor */

static void test_linear(void) {
  fe_chain_opts co;
  fe_chain_defaults(&co, 5);
  co.cb = 4000.0;
  co.beta = 1e-3;
  co.ks = 2e6;
  whirl_fe_rotor *r = fe_chain_build(&co);
  const int nd = r->ndof;
  const double Om = 300.0;
  whirl_fe_mode md[40];
  size_t nf = 0;
  char err[256] = "";
  int rc = whirl_fe_modes(r, Om, NULL, 40, md, &nf, err, sizeof err);
  double sigma = INFINITY;
  for (size_t k = 0; k < nf; ++k) sigma = fmin(sigma, -md[k].re);
  /* 26 e-foldings, a whole number of periods */
  const double T = 2 * WHIRL_PI / Om, tend = T * ceil(26.0 / sigma / T);
  double *qr = malloc(nd * sizeof *qr), *qi = malloc(nd * sizeof *qi);
  rc |= whirl_fe_unbalance_response(r, Om, qr, qi, err, sizeof err);
  whirl_fe_ode *m = whirl_fe_ode_alloc(r, err, sizeof err);
  const whirl_problem *P = whirl_fe_ode_problem(m);
  double p[WHIRL_FE_NPAR], *z0 = calloc(2 * nd, sizeof *z0);
  whirl_fe_hbm_params(Om, p);
  whirl_ode *ode = whirl_ode_alloc(P, p);
  rc |= whirl_ode_set_method(ode, WHIRL_ODE_BDF);
  rc |= whirl_ode_set_tolerances(ode, 1e-11, 1e-17);
  rc |= whirl_ode_reset(ode, 0.0, z0);
  rc |= whirl_ode_evolve(ode, tend);
  const double *z = whirl_ode_x(ode);
  double dq = 0, qs = 0, dv = 0, vs = 0; /* q(t) = Re(Q e^{iΩt}), t = k T */
  for (int i = 0; i < nd; ++i) {
    dq = fmax(dq, fabs(z[i] - qr[i]));
    dv = fmax(dv, fabs(z[nd + i] + Om * qi[i]));
    qs = fmax(qs, hypot(qr[i], qi[i]));
    vs = fmax(vs, Om * hypot(qr[i], qi[i]));
  }
  ok(rc == 0 && dq < 1e-8 * qs && dv < 1e-8 * vs,
     "linear rotor: BDF after %.0f periods (decay %.3g 1/s) = the unbalance "
     "response, q %.2e, q' %.2e relative %s", tend / T, sigma, dq / qs,
     dv / vs, err);
  whirl_ode_free(ode);
  free(qr); free(qi); free(z0);
  whirl_fe_ode_free(m);
  fe_chain_free(r);
}

int main(void) {
  test_jacobian();
  test_equations();
  test_sparse(0);
  test_sparse(1);
  test_linear();
  return done_testing();
}

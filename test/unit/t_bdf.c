/* test/unit/t_bdf.c — the BDF method of whirl/ode.h (SUNDIALS CVODE,
 * lib/ode/bdf.c) against independent references: the closed form of a
 * linear stiff system x' = A x with eigenvalues −1 and −1e6 (at the end
 * points, on the dense output, backwards, and an event x0 + x1 = 1 at
 * t = ln 2); the Robertson kinetics at t = 40 against Hairer & Wanner's
 * published values (Solving ODEs II, §IV.10; the Bari test set) and its
 * conservation y1 + y2 + y3 = 1; the zeros of cos t found by event location;
 * the SFD rigid rotor (rotor/sfd.c) by BDF against DOPRI5 at tight
 * tolerances after five periods; a stiff chain of masses with the dense
 * LU against the KLU sparse Jacobian and against DOPRI5; a right-hand side
 * returning WHIRL_EDOMAIN (fatal) or a recoverable status outside its
 * domain; and the API: method names, bad sparse patterns, statistics over
 * resets, new parameters, step limits, max steps, switching method.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>
#include <whirl/rotor.h>

#include "../tap.h"

/* ------------------------------------------------------------------------
 * x' = A x, A = V diag(−1, −L) V⁻¹, V = [1 1; 1 −1]; x(0) = (2, 0) gives
 * x(t) = (e^{−t} + e^{−Lt}, e^{−t} − e^{−Lt}).  p[0] = L. */
static int lin_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t, (void)data;
  const double a = 0.5 * (-1.0 - p[0]), b = 0.5 * (-1.0 + p[0]);
  f[0] = a * x[0] + b * x[1];
  f[1] = b * x[0] + a * x[1];
  return 0;
}
static int lin_jac(double t, const double *x, const double *p, double *J,
                   void *data) {
  (void)t, (void)x, (void)data;
  const double a = 0.5 * (-1.0 - p[0]), b = 0.5 * (-1.0 + p[0]);
  J[0] = a, J[1] = b, J[2] = b, J[3] = a;
  return 0;
}
static const whirl_problem lin = {.name = "stiff-linear", .n = 2, .npar = 1,
                                  .rhs = lin_rhs, .jac_x = lin_jac,
                                  .autonomous = 1};
static void lin_exact(double t, double L, double *x) {
  x[0] = exp(-t) + exp(-L * t);
  x[1] = exp(-t) - exp(-L * t);
}

static whirl_ode *bdf_new(const whirl_problem *pr, const double *p,
                          double rtol, double atol) {
  whirl_ode *o = whirl_ode_alloc(pr, p);
  if (o == NULL) return NULL;
  if (whirl_ode_set_method(o, WHIRL_ODE_BDF) != WHIRL_OK ||
      whirl_ode_set_tolerances(o, rtol, atol) != WHIRL_OK) {
    whirl_ode_free(o);
    return NULL;
  }
  return o;
}

static void test_linear(void) {
  const double L = 1e6, x0[2] = {2.0, 0.0};
  double xe[2], xd[2];
  for (int withjac = 1; withjac >= 0; --withjac) {
    whirl_problem pr = lin;
    if (!withjac) pr.jac_x = NULL;
    whirl_ode *o = bdf_new(&pr, &L, 1e-9, 1e-12);
    ok(o && whirl_ode_get_method(o) == WHIRL_ODE_BDF, "BDF integrator");
    whirl_ode_reset(o, 0.0, x0);
    double maxerr = 0.0, maxderr = 0.0;
    const double tout[] = {1e-6, 1e-3, 0.1, 1.0, 5.0, 10.0};
    int rc = WHIRL_OK;
    for (size_t k = 0; k < 6 && rc == WHIRL_OK; ++k) {
      while (rc == WHIRL_OK && whirl_ode_t(o) < tout[k]) {
        rc = whirl_ode_step(o, tout[k]);
        /* the dense output in the middle of each step */
        const double tm = 0.5 * (whirl_ode_t_prev(o) + whirl_ode_t(o));
        if (rc == WHIRL_OK && whirl_ode_dense(o, tm, xd) == WHIRL_OK) {
          lin_exact(tm, L, xe);
          for (int i = 0; i < 2; ++i)
            maxderr = fmax(maxderr, fabs(xd[i] - xe[i]) / (1e-6 + fabs(xe[i])));
        } else if (rc == WHIRL_OK) {
          maxderr = INFINITY;
        }
      }
      lin_exact(tout[k], L, xe);
      const double *x = whirl_ode_x(o);
      for (int i = 0; i < 2; ++i)
        maxerr = fmax(maxerr, fabs(x[i] - xe[i]) / (1e-6 + fabs(xe[i])));
      ok(whirl_ode_t(o) == tout[k], "%s: lands on t = %g exactly",
         withjac ? "jac_x" : "DQ", tout[k]);
    }
    whirl_ode_stats st;
    whirl_ode_implicit_stats is;
    whirl_ode_get_stats(o, &st);
    whirl_ode_get_implicit_stats(o, &is);
    ok(rc == WHIRL_OK, "%s: stiff linear to t = 10 (%s)",
       withjac ? "jac_x" : "DQ", whirl_ode_errmsg(o));
    ok(maxerr < 2e-7, "%s: closed form at the outputs, max rel err %.2e",
       withjac ? "jac_x" : "DQ", maxerr);
    ok(maxderr < 1e-5, "%s: closed form on the dense output, max err %.2e",
       withjac ? "jac_x" : "DQ", maxderr);
    ok(st.steps > 10 && st.steps < 2000,
       "%s: %zu steps (explicit stability would need ~3e6)",
       withjac ? "jac_x" : "DQ", st.steps);
    ok(is.jac_evals > 0 && is.lu_factors >= is.jac_evals &&
           is.newton_iters >= st.steps,
       "%s: %zu Jacobians, %zu LU, %zu Newton iterations, %zu rhs",
       withjac ? "jac_x" : "DQ", is.jac_evals, is.lu_factors,
       is.newton_iters, st.rhs_evals);

    whirl_ode_free(o);
  }
  /* backwards (well posed only without the fast mode: L = 2), from the
   * exact state at t = 2 to t = 0 */
  const double L2 = 2.0;
  whirl_ode *o = bdf_new(&lin, &L2, 1e-10, 1e-13);
  lin_exact(2.0, L2, xe);
  whirl_ode_reset(o, 2.0, xe);
  int rc = whirl_ode_evolve(o, 0.0);
  const double eb = fmax(fabs(whirl_ode_x(o)[0] - x0[0]),
                         fabs(whirl_ode_x(o)[1] - x0[1]));
  ok(rc == WHIRL_OK && whirl_ode_t(o) == 0.0 && eb < 1e-7,
     "backwards from t = 2 to 0: x(0) to %.2e", eb);
  /* and forwards again from there: CVODE restarted in the new direction */
  rc = whirl_ode_evolve(o, 1.0);
  lin_exact(1.0, L2, xe);
  ok(rc == WHIRL_OK && fabs(whirl_ode_x(o)[1] - xe[1]) < 1e-8,
     "then forwards to t = 1: x1 = %.12g (exact %.12g)", whirl_ode_x(o)[1],
     xe[1]);
  whirl_ode_free(o);
  /* DOPRI5 on the same problem: explicit stability limits the step to
   * ~3.3/L, so a budget of 10000 steps is not enough for t = 1 */
  whirl_ode *d = whirl_ode_alloc(&lin, &L);
  whirl_ode_set_tolerances(d, 1e-9, 1e-12);
  whirl_ode_set_max_steps(d, 10000);
  whirl_ode_reset(d, 0.0, x0);
  ok(whirl_ode_evolve(d, 1.0) == WHIRL_EMAXITER,
     "DOPRI5 cannot do it in 10000 steps (stiffness is real)");
  whirl_ode_free(d);
}

/* the event x0 + x1 = 1, i.e. 2 e^{−t} = 1: t = ln 2 */
static double g_sum(double t, const double *x, void *data) {
  (void)t, (void)data;
  return x[0] + x[1] - 1.0;
}

static void test_event_linear(void) {
  const double L = 1e6, x0[2] = {2.0, 0.0};
  whirl_ode *o = bdf_new(&lin, &L, 1e-10, 1e-13);
  whirl_ode_reset(o, 0.0, x0);
  double tev = NAN, xev[2];
  int found = 0, rc = WHIRL_OK;
  while (!found && rc == WHIRL_OK) {
    rc = whirl_ode_step(o, 2.0);
    if (rc == WHIRL_OK)
      found = whirl_ode_find_event(o, g_sum, NULL, -1, 1e-14, &tev, xev);
  }
  ok(found == 1, "BDF: event x0 + x1 = 1 found");
  is_abs(tev, log(2.0), 1e-8, "BDF: event at t = ln 2 (got %.15g)", tev);
  is_abs(xev[0] + xev[1], 1.0, 1e-8, "BDF: state at the event");
  whirl_ode_free(o);
}

/* x'' = −x: zeros of x = cos t at (k + 1/2) π */
static int osc_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t, (void)p, (void)data;
  f[0] = x[1];
  f[1] = -x[0];
  return 0;
}
static const whirl_problem osc = {.name = "oscillator", .n = 2,
                                  .rhs = osc_rhs, .autonomous = 1};
static double g_x0(double t, const double *x, void *data) {
  (void)t, (void)data;
  return x[0];
}

static void test_events_osc(void) {
  const double x0[2] = {1.0, 0.0};
  whirl_ode *o = bdf_new(&osc, NULL, 1e-11, 1e-13);
  whirl_ode_reset(o, 0.0, x0);
  int nev = 0, rc = WHIRL_OK;
  double maxerr = 0.0, tev, xev[2];
  while (rc == WHIRL_OK && whirl_ode_t(o) < 20.0) {
    rc = whirl_ode_step(o, 20.0);
    if (rc == WHIRL_OK && whirl_ode_find_event(o, g_x0, NULL, 0, 0.0, &tev,
                                               xev) == 1) {
      maxerr = fmax(maxerr, fabs(tev - (nev + 0.5) * WHIRL_PI));
      ++nev;
    }
  }
  ok(rc == WHIRL_OK && nev == 6, "BDF: 6 zeros of cos t in [0, 20] (got %d)",
     nev);
  ok(maxerr < 1e-7, "BDF: zeros at (k + 1/2) pi, max err %.2e", maxerr);
  whirl_ode_free(o);
}

/* ------------------------------------------------------------------------
 * Robertson (1966), as in Hairer & Wanner II §IV.10 */
static int rob_rhs(double t, const double *y, const double *p, double *f,
                   void *data) {
  (void)t, (void)p, (void)data;
  f[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
  f[2] = 3e7 * y[1] * y[1];
  f[1] = -f[0] - f[2];
  return 0;
}
static int rob_jac(double t, const double *y, const double *p, double *J,
                   void *data) {
  (void)t, (void)p, (void)data;
  /* column-major J[i + 3 j] = df_i / dy_j */
  J[0] = -0.04, J[3] = 1e4 * y[2], J[6] = 1e4 * y[1];
  J[2] = 0.0, J[5] = 6e7 * y[1], J[8] = 0.0;
  for (int j = 0; j < 3; ++j) J[1 + 3 * j] = -J[3 * j] - J[2 + 3 * j];
  return 0;
}
static const whirl_problem rober = {.name = "robertson", .n = 3,
                                    .rhs = rob_rhs, .jac_x = rob_jac,
                                    .autonomous = 1};

static void test_robertson(void) {
  const double y0[3] = {1.0, 0.0, 0.0};
  /* Hairer & Wanner's reference solution at t = 40 */
  const double ref[3] = {0.7158270687, 9.185534764e-6, 0.2841637457};
  double err;
  whirl_ode *o = bdf_new(&rober, NULL, 1e-10, 1e-16);
  whirl_ode_reset(o, 0.0, y0);
  const int rc = whirl_ode_evolve(o, 40.0);
  const double *y = whirl_ode_x(o);
  ok(rc == WHIRL_OK, "Robertson to t = 40 (%s)", whirl_ode_errmsg(o));
  is_rel(y[0], ref[0], 1e-8, "Robertson y1(40) = %.10f", y[0]);
  is_rel(y[1], ref[1], 1e-7, "Robertson y2(40) = %.10e", y[1]);
  is_rel(y[2], ref[2], 1e-8, "Robertson y3(40) = %.10f", y[2]);
  err = fabs(y[0] + y[1] + y[2] - 1.0);
  ok(err < 1e-12, "Robertson: y1 + y2 + y3 = 1 to %.1e", err);
  whirl_ode_stats st;
  whirl_ode_get_stats(o, &st);
  ok(st.steps < 3000, "Robertson: %zu steps", st.steps);
  whirl_ode_free(o);
}

/* ------------------------------------------------------------------------
 * The SFD rigid rotor, fixed frame: BDF against DOPRI5 */
static void test_sfd(void) {
  double p[WHIRL_SFD_NPAR];
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = 1.5;
  p[WHIRL_SFD_DELTA] = 0.3;
  const double x0[4] = {0.1, -0.05, 0.0, 0.2};
  const double T = 5 * 2 * WHIRL_PI / p[WHIRL_SFD_OMEGA];
  whirl_ode *d = whirl_ode_alloc(whirl_sfd_fixed(), p);
  whirl_ode *b = bdf_new(whirl_sfd_fixed(), p, 1e-11, 1e-14);
  whirl_ode_set_tolerances(d, 1e-13, 1e-15);
  whirl_ode_reset(d, 0.0, x0);
  whirl_ode_reset(b, 0.0, x0);
  const int rd = whirl_ode_evolve(d, T), rb = whirl_ode_evolve(b, T);
  ok(rd == WHIRL_OK && rb == WHIRL_OK, "SFD rotor: 5 periods by both (%s)",
     whirl_ode_errmsg(b));
  double diff = 0.0;
  for (int i = 0; i < 4; ++i)
    diff = fmax(diff, fabs(whirl_ode_x(d)[i] - whirl_ode_x(b)[i]));
  ok(diff < 1e-7, "SFD rotor: BDF = DOPRI5 after 5 periods, max diff %.2e",
     diff);
  ok(fabs(whirl_ode_x(b)[0]) > 1e-3, "SFD rotor: the journal moved (y = %g)",
     whirl_ode_x(b)[0]);
  whirl_ode_free(d);
  whirl_ode_free(b);
}

/* ------------------------------------------------------------------------
 * A chain of NM unit masses between two walls: springs k_j = 10^(6 j/NM),
 * j = 0..NM (1 to 1e6: stiff), Rayleigh damping C = beta K between the
 * masses (the fast modes overdamped, the slow ones hardly damped) and a
 * cubic spring 10 q^3 on each mass: x = (q_1..q_NM, v_1..v_NM),
 *   q' = v,  v' = -K q - beta K v - 10 q^3,  K tridiagonal. */
enum { NM = 12, NC = 2 * NM, NNZ_MAX = 7 * NM };
static const double BETA = 1e-2;
static double kspring(int j) { return pow(10.0, 6.0 * j / NM); }
/* (K u)_i */
static double kmul(const double *u, int i) {
  const double ul = i > 0 ? u[i - 1] : 0.0, ur = i < NM - 1 ? u[i + 1] : 0.0;
  return kspring(i) * (u[i] - ul) + kspring(i + 1) * (u[i] - ur);
}
static int chain_rhs(double t, const double *x, const double *p, double *f,
                     void *data) {
  (void)t, (void)p, (void)data;
  for (int i = 0; i < NM; ++i) {
    f[i] = x[NM + i];
    f[NM + i] = -kmul(x, i) - BETA * kmul(x + NM, i) - 10.0 * pow(x[i], 3);
  }
  return 0;
}
/* column j of -K (rows j-1, j, j+1 that exist), scaled by s, plus d on the
 * diagonal, into v[k..]; the pattern's row indices into ri (offset NM) */
static size_t kcol(int j, double s, double d, double *v, int *ri, size_t k) {
  if (j > 0) {
    if (v) v[k] = s * kspring(j);
    if (ri) ri[k] = NM + j - 1;
    ++k;
  }
  if (v) v[k] = -s * (kspring(j) + kspring(j + 1)) + d;
  if (ri) ri[k] = NM + j;
  ++k;
  if (j < NM - 1) {
    if (v) v[k] = s * kspring(j + 1);
    if (ri) ri[k] = NM + j + 1;
    ++k;
  }
  return k;
}
/* the nonzeros column by column, in the order of the pattern below */
static int chain_fill(double t, const double *x, const double *p, double *v,
                      void *data) {
  (void)t, (void)p;
  size_t k = 0;
  for (int j = 0; j < NM; ++j) /* column of q_j */
    k = kcol(j, 1.0, -30.0 * x[j] * x[j], v, NULL, k);
  for (int j = 0; j < NM; ++j) { /* column of v_j: row j, then -beta K */
    v[k++] = 1.0;
    k = kcol(j, BETA, 0.0, v, NULL, k);
  }
  if (data != NULL) ++*(int *)data;
  return 0;
}
static int chain_Jp[NC + 1], chain_Ji[NNZ_MAX];
static size_t chain_pattern(void) {
  size_t k = 0;
  for (int j = 0; j < NM; ++j) {
    chain_Jp[j] = (int)k;
    k = kcol(j, 1.0, 0.0, NULL, chain_Ji, k);
  }
  for (int j = 0; j < NM; ++j) {
    chain_Jp[NM + j] = (int)k;
    chain_Ji[k++] = j;
    k = kcol(j, 1.0, 0.0, NULL, chain_Ji, k);
  }
  chain_Jp[NC] = (int)k;
  return k;
}
/* the dense jac_x from the same entries (column-major) */
static int chain_jac(double t, const double *x, const double *p, double *J,
                     void *data) {
  (void)data;
  double v[NNZ_MAX];
  chain_fill(t, x, p, v, NULL);
  memset(J, 0, NC * NC * sizeof *J);
  for (int j = 0; j < NC; ++j)
    for (int k = chain_Jp[j]; k < chain_Jp[j + 1]; ++k)
      J[chain_Ji[k] + NC * j] = v[k];
  return 0;
}
static const whirl_problem chain = {.name = "chain", .n = NC,
                                    .rhs = chain_rhs, .jac_x = chain_jac,
                                    .autonomous = 1};

static void test_chain(void) {
  const size_t nnz = chain_pattern();
  double x0[NC] = {0}, jerr = INFINITY;
  for (int i = 0; i < NM; ++i) x0[i] = 0.1 * sin(1.0 + i);
  for (int i = 0; i < NC; ++i) x0[i] += 0.01 * cos(3.0 * i);
  /* the values of the pattern (the dense jac_x is made of them) against
   * central differences of the right-hand side */
  const double nop[1] = {0.0}; /* no parameters */
  const int jrc = whirl_check_jacobian(&chain, 0.0, x0, nop, &jerr);
  ok(jrc == WHIRL_OK && jerr < 1e-6,
     "chain: sparse values = finite differences (err %.1e)", jerr);
  for (int i = 0; i < NC; ++i) x0[i] -= 0.01 * cos(3.0 * i);
  const double tend = 2.0;
  whirl_ode *dn = bdf_new(&chain, NULL, 1e-10, 1e-13);
  whirl_ode *sp = bdf_new(&chain, NULL, 1e-10, 1e-13);
  whirl_ode *ex = whirl_ode_alloc(&chain, NULL);
  int fills = 0;
  ok(whirl_ode_set_sparse_jacobian(sp, nnz, chain_Jp, chain_Ji, chain_fill,
                                   &fills) == WHIRL_OK,
     "chain: sparse pattern (%zu nonzeros) accepted", nnz);
  whirl_ode_set_tolerances(ex, 1e-13, 1e-15);
  whirl_ode_reset(dn, 0.0, x0);
  whirl_ode_reset(sp, 0.0, x0);
  whirl_ode_reset(ex, 0.0, x0);
  const int r1 = whirl_ode_evolve(dn, tend), r2 = whirl_ode_evolve(sp, tend);
  const int r3 = whirl_ode_evolve(ex, tend);
  ok(r1 == WHIRL_OK && r2 == WHIRL_OK && r3 == WHIRL_OK,
     "chain: dense, KLU and DOPRI5 to t = 2 (%s)", whirl_ode_errmsg(sp));
  double dsd = 0.0, dse = 0.0, amp = 0.0;
  for (int i = 0; i < NC; ++i) {
    dsd = fmax(dsd, fabs(whirl_ode_x(dn)[i] - whirl_ode_x(sp)[i]));
    dse = fmax(dse, fabs(whirl_ode_x(ex)[i] - whirl_ode_x(sp)[i]));
    amp = fmax(amp, fabs(whirl_ode_x(ex)[i]));
  }
  /* the same method with another LU: the same solution up to rounding in
   * the Newton iterations, which may move a step-size choice */
  ok(dsd < 1e-8 * amp, "chain: KLU = dense LU, max diff %.2e (scale %.2g)",
     dsd, amp);
  ok(dse < 1e-7 * amp, "chain: KLU = DOPRI5 at 1e-13, max diff %.2e", dse);
  whirl_ode_implicit_stats is, isd;
  whirl_ode_stats ss, sd;
  whirl_ode_get_implicit_stats(sp, &is);
  whirl_ode_get_implicit_stats(dn, &isd);
  whirl_ode_get_stats(sp, &ss);
  whirl_ode_get_stats(dn, &sd);
  ok(fabs((double)ss.steps - (double)sd.steps) < 0.05 * (double)sd.steps,
     "chain: %zu steps with KLU, %zu with dense LU", ss.steps, sd.steps);
  ok(fills > 0 && (size_t)fills == is.jac_evals && is.lu_factors > 0,
     "chain: %d sparse fills = %zu Jacobians, %zu KLU factorisations", fills,
     is.jac_evals, is.lu_factors);
  /* bad patterns */
  int badp[NC + 1];
  memcpy(badp, chain_Jp, sizeof badp);
  badp[NC] = (int)nnz - 1;
  ok(whirl_ode_set_sparse_jacobian(sp, nnz, badp, chain_Ji, chain_fill,
                                   NULL) == WHIRL_EINVAL &&
         strstr(whirl_ode_errmsg(sp), "Jp[n]") != NULL,
     "bad Jp[n] refused: %s", whirl_ode_errmsg(sp));
  int badi[NNZ_MAX];
  memcpy(badi, chain_Ji, sizeof badi);
  badi[1] = NC;
  ok(whirl_ode_set_sparse_jacobian(sp, nnz, chain_Jp, badi, chain_fill,
                                   NULL) == WHIRL_EINVAL,
     "row index out of range refused: %s", whirl_ode_errmsg(sp));
  ok(whirl_ode_set_sparse_jacobian(sp, nnz, chain_Jp, chain_Ji, NULL,
                                   NULL) == WHIRL_EINVAL,
     "pattern without fill refused");
  whirl_ode_free(dn);
  whirl_ode_free(sp);
  whirl_ode_free(ex);
}

/* ------------------------------------------------------------------------
 * Right-hand sides outside their domain: x' = 1 from 0, defined for x < 0.5 */
static int dom_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t, (void)p;
  if (x[0] >= 0.5) return *(const int *)data;
  f[0] = 1.0;
  return 0;
}

static void test_domain(void) {
  const int codes[2] = {WHIRL_EDOMAIN, 1};
  for (int c = 0; c < 2; ++c) {
    whirl_problem pr = {.name = "domain", .n = 1, .rhs = dom_rhs,
                        .data = (void *)&codes[c]};
    whirl_ode *o = bdf_new(&pr, NULL, 1e-8, 1e-10);
    const double x0 = 0.0;
    whirl_ode_reset(o, 0.0, &x0);
    const int rc = whirl_ode_evolve(o, 1.0);
    whirl_ode_stats st;
    whirl_ode_get_stats(o, &st);
    const char *msg = whirl_ode_errmsg(o);
    if (c == 0) {
      ok(rc == WHIRL_EUSER && whirl_ode_last_rhs_status(o) == WHIRL_EDOMAIN,
         "rhs WHIRL_EDOMAIN: stops with WHIRL_EUSER, last rhs status %d",
         whirl_ode_last_rhs_status(o));
      ok(strstr(msg, "returned -9") && strstr(msg, "domain"),
         "  message: %s", msg);
    } else {
      ok(rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(o) == 1,
         "recoverable rhs failure: stops with WHIRL_ESTEP (%d), status %d",
         rc, whirl_ode_last_rhs_status(o));
      ok(strstr(msg, "returned 1") != NULL, "  message: %s", msg);
    }
    /* the last accepted point is on the solution x = t; the recoverable
     * failure is retried up to the edge of the domain, the fatal one not */
    const double t = whirl_ode_t(o);
    ok(t < 0.5 && (c == 0 || t > 0.49) &&
           fabs(whirl_ode_x(o)[0] - t) < 1e-12 && st.rhs_evals < 5000,
       "  stays at the last good point t = %.10g (%zu rhs calls)", t,
       st.rhs_evals);
    whirl_ode_free(o);
  }
}

/* ------------------------------------------------------------------------
 * The rest of the API with BDF */
static void test_api(void) {
  int m = -1;
  ok(whirl_ode_method_parse("bdf", &m) == WHIRL_OK && m == WHIRL_ODE_BDF &&
         whirl_ode_method_parse("dopri5", &m) == WHIRL_OK &&
         m == WHIRL_ODE_DOPRI5 &&
         whirl_ode_method_parse("rk4", &m) == WHIRL_EINVAL &&
         strcmp(whirl_ode_method_name(WHIRL_ODE_BDF), "bdf") == 0 &&
         whirl_ode_method_name(7) == NULL,
     "method names");
  double L = 1e6, x0[2] = {2.0, 0.0}, xe[2];
  whirl_ode *o = whirl_ode_alloc(&lin, &L);
  ok(whirl_ode_get_method(o) == WHIRL_ODE_DOPRI5, "DOPRI5 is the default");
  ok(whirl_ode_set_method(o, 5) == WHIRL_EINVAL, "unknown method refused");
  /* DOPRI5 through the fast transient, then BDF from where it is */
  whirl_ode_set_tolerances(o, 1e-10, 1e-13);
  whirl_ode_reset(o, 0.0, x0);
  int rc = whirl_ode_evolve(o, 2e-5);
  whirl_ode_stats s1, s2;
  whirl_ode_get_stats(o, &s1);
  rc = rc ? rc : whirl_ode_set_method(o, WHIRL_ODE_BDF);
  rc = rc ? rc : whirl_ode_evolve(o, 3.0);
  whirl_ode_get_stats(o, &s2);
  lin_exact(3.0, L, xe);
  ok(rc == WHIRL_OK && fabs(whirl_ode_x(o)[0] - xe[0]) < 1e-7 * xe[0],
     "DOPRI5 then BDF: x(3) = %.12g (exact %.12g)", whirl_ode_x(o)[0], xe[0]);
  ok(s2.steps > s1.steps && s2.rhs_evals > s1.rhs_evals,
     "statistics go on after the switch (%zu then %zu steps)", s1.steps,
     s2.steps);
  /* new parameters at a reset: L = 10, stats kept */
  L = 10.0;
  whirl_ode_set_params(o, &L);
  whirl_ode_reset(o, 0.0, x0);
  rc = whirl_ode_evolve(o, 1.0);
  whirl_ode_stats s3;
  whirl_ode_get_stats(o, &s3);
  lin_exact(1.0, 10.0, xe);
  ok(rc == WHIRL_OK && fabs(whirl_ode_x(o)[1] - xe[1]) < 1e-7 * fabs(xe[1]),
     "new parameters after reset: x1(1) = %.12g (exact %.12g)",
     whirl_ode_x(o)[1], xe[1]);
  ok(s3.steps > s2.steps, "statistics kept over the reset");
  whirl_ode_free(o);
}

/* step limits, t_prev/x_prev, max steps, dense output, new tolerances */
static void test_api_limits(void) {
  double L = 10.0, x0[2] = {2.0, 0.0}, xe[2];
  whirl_ode *o = bdf_new(&lin, &L, 1e-10, 1e-13);
  int rc = WHIRL_OK;
  whirl_ode_set_step_limits(o, 0.0, 0.0, 0.01);
  whirl_ode_reset(o, 0.0, x0);
  int hmax_ok = 1, prev_ok = 1;
  double tlast = 0.0, xlast = x0[0];
  while (rc == WHIRL_OK && whirl_ode_t(o) < 0.5) {
    rc = whirl_ode_step(o, 0.5);
    hmax_ok &= whirl_ode_t(o) - whirl_ode_t_prev(o) <= 0.01 * (1 + 1e-12);
    prev_ok &= whirl_ode_t_prev(o) == tlast && whirl_ode_x_prev(o)[0] == xlast;
    tlast = whirl_ode_t(o);
    xlast = whirl_ode_x(o)[0];
    hmax_ok &= whirl_ode_h(o) <= 0.01 * (1 + 1e-12) && whirl_ode_h(o) > 0;
  }
  ok(rc == WHIRL_OK && hmax_ok, "h_max = 0.01 respected");
  ok(prev_ok, "t_prev, x_prev are the previous step's end");
  /* max steps */
  whirl_ode_set_max_steps(o, 5);
  whirl_ode_reset(o, 0.0, x0);
  rc = whirl_ode_evolve(o, 1.0);
  ok(rc == WHIRL_EMAXITER && strstr(whirl_ode_errmsg(o), "5 steps"),
     "max_steps 5: %s", whirl_ode_errmsg(o));
  /* sampling on the dense output */
  whirl_ode_set_max_steps(o, 0);
  whirl_ode_set_step_limits(o, 0.0, 0.0, 0.0);
  whirl_ode_reset(o, 0.0, x0);
  ok(whirl_ode_dense(o, 0.0, xe) == WHIRL_EINVAL,
     "no dense output before the first step");
  ok(whirl_ode_step(o, 0.0) == WHIRL_DONE, "step to t itself: WHIRL_DONE");
  /* new tolerances half way (CVODE restarts from the current point) */
  whirl_ode_set_tolerances(o, 1e-6, 1e-9);
  rc = whirl_ode_evolve(o, 0.5);
  whirl_ode_set_tolerances(o, 1e-11, 1e-14);
  rc = rc ? rc : whirl_ode_evolve(o, 1.0);
  lin_exact(1.0, L, xe);
  ok(rc == WHIRL_OK && fabs(whirl_ode_x(o)[0] - xe[0]) < 1e-5 * xe[0],
     "tolerances changed half way: x0(1) = %.10g (exact %.10g)",
     whirl_ode_x(o)[0], xe[0]);
  whirl_ode_free(o);
}

/* whirl_ode_sample on BDF's dense output against the closed form */
typedef struct {
  double L, maxerr;
} sample_ctx;
static int sample_check(size_t k, double t, const double *x, void *data) {
  (void)k;
  sample_ctx *c = data;
  double xe[2];
  lin_exact(t, c->L, xe);
  c->maxerr = fmax(c->maxerr, fmax(fabs(x[0] - xe[0]), fabs(x[1] - xe[1])));
  return 0;
}

static void test_sample(void) {
  sample_ctx c = {1e6, 0.0};
  const double x0[2] = {2.0, 0.0};
  whirl_ode *o = bdf_new(&lin, &c.L, 1e-10, 1e-13);
  whirl_ode_reset(o, 0.0, x0);
  const int rc = whirl_ode_sample(o, 0.01, 300, sample_check, &c);
  ok(rc == WHIRL_OK && whirl_ode_t(o) == 3.0 && c.maxerr < 1e-8,
     "sampling 300 points by BDF: max err %.2e", c.maxerr);
  whirl_ode_set_max_steps(o, 3);
  whirl_ode_reset(o, 0.0, x0);
  ok(whirl_ode_sample(o, 0.5, 4, sample_check, &c) == WHIRL_EMAXITER,
     "sampling with 3 steps between samples: %s", whirl_ode_errmsg(o));
  whirl_ode_free(o);
}

/* Jacobians that fail, a right-hand side with NaN, back to dense LU */
static int jac_fatal(double t, const double *x, const double *p, double *J,
                     void *data) {
  (void)t, (void)x, (void)p, (void)J, (void)data;
  return -3;
}
static int rhs_nan(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)t, (void)p, (void)data;
  f[0] = x[0] < 0.5 ? 1.0 : NAN;
  return 0;
}

static void test_failures(void) {
  const double L = 1e6, x0[2] = {2.0, 0.0};
  whirl_problem pr = lin;
  pr.jac_x = jac_fatal;
  whirl_ode *o = bdf_new(&pr, &L, 1e-8, 1e-12);
  whirl_ode_reset(o, 0.0, x0);
  int rc = whirl_ode_evolve(o, 1.0);
  ok(rc == WHIRL_EUSER && strstr(whirl_ode_errmsg(o), "Jacobian returned -3"),
     "a fatal jac_x: %s", whirl_ode_errmsg(o));
  /* a sparse Jacobian replaces it; nnz 0 takes it away again */
  static const int Jp[3] = {0, 2, 4}, Ji[4] = {0, 1, 0, 1};
  ok(whirl_ode_set_sparse_jacobian(o, 4, Jp, Ji, lin_jac, NULL) == WHIRL_OK &&
         whirl_ode_reset(o, 0.0, x0) == WHIRL_OK &&
         whirl_ode_evolve(o, 1.0) == WHIRL_OK,
     "the full 2x2 pattern with KLU instead (%s)", whirl_ode_errmsg(o));
  double xe[2];
  lin_exact(1.0, L, xe);
  ok(fabs(whirl_ode_x(o)[0] - xe[0]) < 1e-6 * xe[0], "  x0(1) = %.10g",
     whirl_ode_x(o)[0]);
  ok(whirl_ode_set_sparse_jacobian(o, 0, NULL, NULL, NULL, NULL) == WHIRL_OK &&
         whirl_ode_reset(o, 0.0, x0) == WHIRL_OK &&
         whirl_ode_evolve(o, 1.0) == WHIRL_EUSER,
     "nnz = 0: back to dense LU with the failing jac_x");
  whirl_ode_free(o);
  whirl_problem pn = {.name = "nan", .n = 1, .rhs = rhs_nan};
  o = bdf_new(&pn, NULL, 1e-8, 1e-10);
  const double y0 = 0.0;
  whirl_ode_reset(o, 0.0, &y0);
  rc = whirl_ode_evolve(o, 1.0);
  ok(rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(o) == WHIRL_EBADFUNC &&
         strstr(whirl_ode_errmsg(o), "NaN"),
     "rhs with NaN: %s", whirl_ode_errmsg(o));
  whirl_ode_free(o);
}

/* ------------------------------------------------------------------------
 * A mass matrix on the left: B x' = A x with B = [2 1; 1 2], A = diag(−1,
 * −3s): the rhs returns B⁻¹ A x, the fill G = A.  Exact: x(t) = V e^{Λt}
 * V⁻¹ x0 from the eigenvalues of B⁻¹A = (1/3)[−2 3s; 1 −6s]. */

static int mass_rhs(double t, const double *x, const double *p, double *f,
                    void *data) {
  (void)t, (void)data;
  const double g0 = -x[0], g1 = -3 * p[0] * x[1];
  f[0] = (2 * g0 - g1) / 3, f[1] = (-g0 + 2 * g1) / 3;
  return 0;
}
static int mass_fill(double t, const double *x, const double *p, double *v,
                     void *data) {
  (void)t, (void)x, (void)data;
  v[0] = -1, v[1] = 0, v[2] = 0, v[3] = -3 * p[0]; /* full 2×2 pattern */
  return 0;
}
static int mass_jac(double t, const double *x, const double *p, double *J,
                    void *data) { /* B⁻¹ A, column-major: for the dense run */
  (void)t, (void)x, (void)data;
  J[0] = -2.0 / 3, J[1] = 1.0 / 3, J[2] = p[0], J[3] = -2 * p[0];
  return 0;
}
static const whirl_problem massp = {.name = "mass", .n = 2, .npar = 1,
                                    .rhs = mass_rhs, .jac_x = mass_jac};

static void mass_exact(double t, double s, const double *x0, double *x) {
  const double a = -2.0 / 3, b = s, c = 1.0 / 3, d = -2 * s; /* B⁻¹A */
  const double tr = a + d, det = a * d - b * c, disc = sqrt(tr * tr / 4 - det);
  const double l1 = tr / 2 + disc, l2 = tr / 2 - disc;
  /* e^{Mt} = (e^{l1 t}(M − l2) − e^{l2 t}(M − l1)) / (l1 − l2) */
  const double e1 = exp(l1 * t), e2 = exp(l2 * t), q = 1 / (l1 - l2);
  const double m00 = q * (e1 * (a - l2) - e2 * (a - l1)), m01 = q * b * (e1 - e2);
  const double m10 = q * c * (e1 - e2), m11 = q * (e1 * (d - l2) - e2 * (d - l1));
  x[0] = m00 * x0[0] + m01 * x0[1];
  x[1] = m10 * x0[0] + m11 * x0[1];
}

static void test_mass(void) {
  static const int Jp[3] = {0, 2, 4}, Ji[4] = {0, 1, 0, 1};
  static const double Bx[4] = {2, 1, 1, 2};
  static const int Dp[3] = {0, 1, 2}, Di[2] = {0, 1};
  const double p[1] = {1e3}, x0[2] = {1, -0.5};
  whirl_ode *ode = whirl_ode_alloc(&massp, p);
  int rc = whirl_ode_set_method(ode, WHIRL_ODE_BDF);
  rc |= whirl_ode_set_tolerances(ode, 1e-10, 1e-14);
  rc |= whirl_ode_set_sparse_jacobian(ode, 4, Jp, Ji, mass_fill, NULL);
  rc |= whirl_ode_set_mass_matrix(ode, 4, Jp, Ji, Bx);
  rc |= whirl_ode_reset(ode, 0.0, x0);
  rc |= whirl_ode_evolve(ode, 2.0);
  double x[2];
  mass_exact(2.0, p[0], x0, x);
  const double *y = whirl_ode_x(ode), e = fmax(fabs(y[0] - x[0]), fabs(y[1] - x[1]));
  const double yy[2] = {y[0], y[1]};
  whirl_ode_implicit_stats is;
  whirl_ode_get_implicit_stats(ode, &is);
  ok(rc == 0 && e < 1e-8 * fabs(x0[0]) && is.newton_fails == 0,
     "mass matrix: B x' = A x, stiffness ratio ~3000, against the matrix "
     "exponential at t = 2 (error %.2e, %zu Newton iterations)", e, is.newton_iters);
  /* B's pattern must lie inside the Jacobian's */
  whirl_ode_set_sparse_jacobian(ode, 2, Dp, Di, mass_fill, NULL);
  ok(whirl_ode_reset(ode, 0.0, x0) == WHIRL_EINVAL &&
     strstr(whirl_ode_errmsg(ode), "mass matrix") != NULL,
     "mass matrix outside the Jacobian's pattern: reset refuses (%s)", whirl_ode_errmsg(ode));
  static const int badi[4] = {1, 0, 0, 1};
  ok(whirl_ode_set_mass_matrix(ode, 4, Jp, badi, Bx) == WHIRL_EINVAL,
     "mass matrix: a bad pattern is refused");
  whirl_ode_free(ode);
  /* the same Newton systems as the dense (I − γ B⁻¹A): the same run */
  whirl_ode *dn = whirl_ode_alloc(&massp, p);
  rc = whirl_ode_set_method(dn, WHIRL_ODE_BDF) | whirl_ode_set_tolerances(dn, 1e-10, 1e-14);
  rc |= whirl_ode_reset(dn, 0.0, x0) | whirl_ode_evolve(dn, 2.0);
  whirl_ode_implicit_stats ds;
  whirl_ode_get_implicit_stats(dn, &ds);
  const double *z = whirl_ode_x(dn), dd = fmax(fabs(z[0] - yy[0]), fabs(z[1] - yy[1]));
  ok(rc == 0 && dd < 1e-11 && ds.newton_iters == is.newton_iters,
     "mass matrix = dense f_x = B^-1 A: the same solution (%.1e) and Newton "
     "iterations (%zu, %zu)", dd, is.newton_iters, ds.newton_iters);
  whirl_ode_free(dn);
}

int main(void) {
  test_mass();
  test_linear();
  test_event_linear();
  test_events_osc();
  test_robertson();
  test_sfd();
  test_chain();
  test_domain();
  test_api();
  test_api_limits();
  test_sample();
  test_failures();
  return done_testing();
}

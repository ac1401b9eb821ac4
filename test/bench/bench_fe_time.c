/* test/bench/bench_fe_time.c — time integration against harmonic balance
 * on a 330-DOF rotor (examples/rotor/compressor.rotor: 82 nodes, 7 disks,
 * 2 short π-film SFDs, a pedestal), per speed:
 *   bdf    CVODE BDF (the mass matrix on the left, KLU:
 *          whirl_fe_ode_use_mass) from rest until the state repeats over a
 *          revolution to `settle` (relative, all q) or `max_periods`: wall
 *          time, revolutions, steps, rhs and Jacobian evaluations, LU
 *          factorisations, and the change over the last revolution (above
 *          `settle`: not settled yet, the time a lower bound);
 *   hbm    one condensed HBM solve at that speed (H = 5): Newton from the
 *          nearest point of the response from rest (whirl_fe_hbm_response,
 *          untimed) on its first crossing of the speed, as a continuation
 *          step would: wall time, iterations;
 * and the ratios bdf/hbm and (per revolution) rev/hbm, the target
 * being HBM ≥ 100× faster per speed;
 * the journal amplitudes of both (they agree when BDF settled).
 * Not a test: run `make bench`.
 * Usage: bench_fe_time [ROTOR [max_periods [settle]]]
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <whirl/cont.h>
#include <whirl/ode.h>
#include <whirl/rotor/fe_hbm.h>
#include <whirl/rotor/fe_ode.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct tres {
  double secs, amp, change;
  size_t periods, steps, rhs, jac, lu;
  int rc;
} tres;

/* from rest until q repeats over a revolution */
static tres integrate(const whirl_fe_rotor *r, double Om, int node, size_t maxp,
                      double settle) {
  tres t = {0};
  whirl_fe_ode *m = whirl_fe_ode_alloc(r, NULL, 0);
  const size_t nd = (size_t)r->ndof;
  double p[WHIRL_FE_NPAR], *z = calloc(2 * nd, sizeof *z), *prev = malloc(nd * sizeof *prev);
  whirl_fe_hbm_params(Om, p);
  whirl_ode *ode = whirl_ode_alloc(whirl_fe_ode_problem(m), p);
  t.rc = whirl_ode_set_method(ode, WHIRL_ODE_BDF) | whirl_ode_set_tolerances(ode, 1e-8, 1e-12);
  t.rc |= whirl_fe_ode_use_mass(m, ode);
  const double t0 = now(), T = 2 * WHIRL_PI / Om;
  t.rc |= whirl_ode_reset(ode, 0.0, z);
  t.change = INFINITY;
  while (!t.rc && t.periods < maxp && t.change > settle) {
    memcpy(prev, whirl_ode_x(ode), nd * sizeof *prev);
    t.rc = whirl_ode_evolve(ode, T * (double)++t.periods);
    double d = 0.0, s = 0.0;
    for (size_t i = 0; i < nd; ++i) {
      d = fmax(d, fabs(whirl_ode_x(ode)[i] - prev[i]));
      s = fmax(s, fabs(prev[i]));
    }
    t.change = d / fmax(s, 1e-300);
  }
  t.secs = now() - t0;
  const int dy = whirl_fe_rotor_dof(r, node, 0);
  for (int k = 0; !t.rc && k < 64; ++k) { /* the amplitude over one more revolution */
    t.rc = whirl_ode_evolve(ode, T * ((double)t.periods + (k + 1) / 64.0));
    t.amp = fmax(t.amp, hypot(whirl_ode_x(ode)[dy], whirl_ode_x(ode)[dy + 1]));
  }
  whirl_ode_stats st;
  whirl_ode_implicit_stats is;
  whirl_ode_get_stats(ode, &st);
  whirl_ode_get_implicit_stats(ode, &is);
  t.steps = st.steps, t.rhs = st.rhs_evals, t.jac = is.jac_evals, t.lu = is.lu_factors;
  whirl_ode_free(ode);
  whirl_fe_ode_free(m);
  free(z); free(prev);
  return t;
}

/* the response's points (speed, unknowns) */
typedef struct trace { double *om, *X; size_t n, cap, nx; } trace;

static int collect(const whirl_fe_hbm_response_point *pt, void *ctx) {
  trace *t = ctx;
  if (t->n == t->cap) {
    t->cap = t->cap ? 2 * t->cap : 512;
    t->om = realloc(t->om, t->cap * sizeof *t->om);
    t->X = realloc(t->X, t->cap * t->nx * sizeof *t->X);
    if (!t->om || !t->X) return WHIRL_ENOMEM;
  }
  t->om[t->n] = pt->Omega;
  memcpy(t->X + t->n++ * t->nx, pt->X, t->nx * sizeof *t->X);
  return 0;
}

/* X = the point nearest Om on the response's first crossing of Om */
static int start_point(const trace *t, double Om, double *X) {
  for (size_t i = 0; i + 1 < t->n; ++i)
    if ((t->om[i] - Om) * (t->om[i + 1] - Om) <= 0) {
      const size_t j = Om - t->om[i] < t->om[i + 1] - Om ? i : i + 1;
      memcpy(X, t->X + j * t->nx, t->nx * sizeof *X);
      return 0;
    }
  return -1;
}

static double hbm_solve(whirl_fe_hbm *h, const whirl_fe_rotor *r, double *X, double Om,
                        int node, int *its, int *rc, double *amp) {
  double p[WHIRL_FE_NPAR], *q = malloc((size_t)r->ndof * 11 * sizeof *q);
  whirl_fe_hbm_params(Om, p);
  const double t0 = now();
  *rc = whirl_newton(whirl_fe_hbm_system(h), X, p, 1e-10, 30, its);
  const double secs = now() - t0;
  *amp = *rc ? NAN : (whirl_fe_hbm_recover(h, X, p, q), whirl_fe_hbm_amplitude(h, q, node));
  free(q);
  return secs;
}

int main(int argc, char **argv) {
  const char *path = argc > 1 ? argv[1] : "examples/rotor/compressor.rotor";
  const size_t maxp = argc > 2 ? (size_t)atol(argv[2]) : 3;
  const double settle = argc > 3 ? atof(argv[3]) : 1e-6;
  char msg[512] = "";
  whirl_fe_rotor *r = whirl_fe_rotor_read(path, msg, sizeof msg, NULL);
  whirl_fe_hbm_options o;
  whirl_fe_hbm_options_default(&o);
  o.harmonics = 5;
  o.stability = 0;
  whirl_fe_hbm *h = r ? whirl_fe_hbm_alloc(r, &o, msg, sizeof msg) : NULL;
  if (!h) {
    fprintf(stderr, "bench_fe_time: %s\n", msg);
    return 1;
  }
  const int node = r->nl[0].node;
  double *X = calloc(whirl_fe_hbm_size(h), sizeof *X);
  const double rpm[] = {2000, 4000, 6000};
  whirl_fe_hbm_response_options ro;
  whirl_fe_hbm_response_options_default(&ro);
  ro.hbm = o;
  ro.node = node;
  ro.speed_min = 200 * WHIRL_PI / 30;
  ro.speed_max = 6500 * WHIRL_PI / 30;
  trace tr = {NULL, NULL, 0, 0, whirl_fe_hbm_size(h)};
  if (whirl_fe_hbm_response(r, &ro, collect, &tr, msg, sizeof msg) != WHIRL_OK)
    fprintf(stderr, "bench_fe_time: the response: %s\n", msg);
  printf("# %s: %d DOF, BDF rtol 1e-8 atol 1e-12 from rest to a change < %g per revolution\n",
         path, r->ndof, settle);
  printf("rpm\tbdf_s\trevs\tsteps\trhs\tjac\tlu\tchange\tbdf_amp_m\thbm_s\tits\thbm_amp_m\tratio\tratio_per_rev\n");
  for (size_t k = 0; k < sizeof rpm / sizeof rpm[0]; ++k) {
    const double Om = rpm[k] * WHIRL_PI / 30;
    int its = 0, hrc = 0;
    double hamp = NAN;
    hrc = start_point(&tr, Om, X);
    const double hs = hrc ? NAN : hbm_solve(h, r, X, Om, node, &its, &hrc, &hamp);
    tres t = integrate(r, Om, node, maxp, settle);
    printf("%.0f\t%.3f\t%zu\t%zu\t%zu\t%zu\t%zu\t%.2e\t%.6e\t%.4f\t%d\t%.6e\t%.0f\t%.0f%s\n",
           rpm[k], t.secs, t.periods, t.steps, t.rhs, t.jac, t.lu, t.change, t.amp, hs, its,
           hamp, t.secs / hs, t.secs / (double)t.periods / hs,
           t.rc || hrc ? "\t(failed)" : "");
    fflush(stdout);
  }
  free(X), free(tr.om), free(tr.X);
  whirl_fe_hbm_free(h);
  whirl_fe_rotor_free(r);
  return 0;
}

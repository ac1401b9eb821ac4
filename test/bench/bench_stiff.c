/* test/bench/bench_stiff.c — DOPRI5 against BDF (CVODE, lib/ode/bdf.c) on
 * the rigid SFD rotor (fixed frame, rotor/sfd.c) as the journal comes close
 * to the housing, where the film force ~ λ/(1 − ε²)^{3/2} makes the
 * equations stiff: Table 1 (far from it), a large unbalance, and a static
 * force F_E pressing the journal towards the housing.  Each run integrates
 * P forcing periods by whirl_ode_step from the case's initial state with
 * the same rtol/atol for both methods; the final state is compared with a
 * DOPRI5 reference at rtol 1e-12, atol 1e-15.  Prints one TSV row per case
 * and method: median wall time over the repeats, steps, rejected steps,
 * rhs evaluations, Jacobians, LU factorisations, max ε, error.
 * Not a test: run `make bench`, record in doc/benchmarks.md.
 * Usage: bench_stiff [repeats [periods [rtol]]]
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <whirl/rotor.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

typedef struct {
  const char *name;
  double omega, delta, fe, z0;
} bench_case;

typedef struct {
  double secs, eps_max, x[4];
  whirl_ode_stats st;
  whirl_ode_implicit_stats ist;
} bench_run;

/* One integration over [0, t_end]; WHIRL_OK or the integrator's status. */
static int run(const double *p, const double *x0, double t_end, int method,
               double rtol, double atol, bench_run *out) {
  whirl_ode *o = whirl_ode_alloc(whirl_sfd_fixed(), p);
  if (o == NULL) return WHIRL_ENOMEM;
  int rc = whirl_ode_set_method(o, method);
  if (rc == WHIRL_OK) rc = whirl_ode_set_tolerances(o, rtol, atol);
  const double t0 = now();
  if (rc == WHIRL_OK) rc = whirl_ode_reset(o, 0.0, x0);
  out->eps_max = 0.0;
  while (rc == WHIRL_OK && whirl_ode_t(o) != t_end) {
    rc = whirl_ode_step(o, t_end);
    const double *x = whirl_ode_x(o);
    out->eps_max = fmax(out->eps_max, hypot(x[0], x[1]));
  }
  out->secs = now() - t0;
  for (int i = 0; i < 4; ++i) out->x[i] = whirl_ode_x(o)[i];
  whirl_ode_get_stats(o, &out->st);
  whirl_ode_get_implicit_stats(o, &out->ist);
  if (rc != WHIRL_OK)
    fprintf(stderr, "bench_stiff: %s\n", whirl_ode_errmsg(o));
  whirl_ode_free(o);
  return rc;
}

/* the case's parameters and initial state */
static void setup(const bench_case *c, double *p, double *x0) {
  whirl_sfd_default_params(p);
  p[WHIRL_SFD_OMEGA] = c->omega;
  p[WHIRL_SFD_DELTA] = c->delta;
  p[WHIRL_SFD_FE] = c->fe;
  x0[0] = 0.0, x0[1] = c->z0, x0[2] = 0.0, x0[3] = 0.0;
}

int main(int argc, char **argv) {
  const int reps = argc > 1 ? atoi(argv[1]) : 5;
  const double periods = argc > 2 ? atof(argv[2]) : 40.0;
  const double rtol = argc > 3 ? atof(argv[3]) : 1e-8, atol = 1e-3 * rtol;
  const bench_case cases[] = {
      {"Table 1 (delta 0.3)", 1.0, 0.3, 0.0, 0.0},
      {"large unbalance (delta 10)", 1.0, 10.0, 0.0, 0.0},
      {"F_E 0.98 (z0 0.98)", 1.0, 0.3, 0.98, 0.98},
      {"F_E 0.995, delta 0.5 (z0 0.99)", 1.0, 0.5, 0.995, 0.99},
  };
  const int methods[2] = {WHIRL_ODE_DOPRI5, WHIRL_ODE_BDF};
  double *t = malloc((size_t)(reps > 0 ? reps : 1) * sizeof *t);
  if (reps < 1 || !(periods > 0) || !(rtol > 0) || t == NULL) {
    fprintf(stderr, "usage: bench_stiff [repeats [periods [rtol]]]\n");
    free(t);
    return 2;
  }
  printf("# %g periods, rtol %g, atol %g; median of %d runs; error: max |x - "
         "x_ref| at the end, x_ref by DOPRI5 at rtol 1e-12, atol 1e-15\n",
         periods, rtol, atol, reps);
  printf("case\tmethod\tms\tsteps\trejected\trhs\tjac\tlu\teps_max\terror\n");
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    double p[WHIRL_SFD_NPAR], x0[4];
    setup(&cases[k], p, x0);
    const double t_end = periods * 2.0 * WHIRL_PI / cases[k].omega;
    bench_run ref, r;
    if (run(p, x0, t_end, WHIRL_ODE_DOPRI5, 1e-12, 1e-15, &ref) != WHIRL_OK)
      continue;
    for (int m = 0; m < 2; ++m) {
      int rc = WHIRL_OK;
      for (int i = 0; i < reps && rc == WHIRL_OK; ++i) {
        rc = run(p, x0, t_end, methods[m], rtol, atol, &r);
        t[i] = r.secs;
      }
      if (rc != WHIRL_OK) continue;
      qsort(t, (size_t)reps, sizeof *t, cmp);
      double err = 0.0;
      for (int i = 0; i < 4; ++i) err = fmax(err, fabs(r.x[i] - ref.x[i]));
      printf("%s\t%s\t%.1f\t%zu\t%zu\t%zu\t%zu\t%zu\t%.6f\t%.1e\n",
             cases[k].name, whirl_ode_method_name(methods[m]),
             1e3 * t[reps / 2], r.st.steps, r.st.rejected, r.st.rhs_evals,
             r.ist.jac_evals, r.ist.lu_factors, r.eps_max, err);
      fflush(stdout);
    }
  }
  free(t);
  return 0;
}

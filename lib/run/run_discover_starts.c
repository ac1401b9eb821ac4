/* lib/run/run_discover_starts.c — the starts of deflated Newton in the
 * discovery step (doc/discovery.md): the model's start or the zero orbit,
 * scaled copies of the known solutions, settled time integrations from
 * random initial states, random states or orbits in the box, and known
 * orbits at a random phase and amplitude.  One generator, splitmix64,
 * seeded per sample value by run_discover.c.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>

#include "run_discover_impl.h"

double disc_urand(disc *D) { return whirl_random_uniform(&D->rng); }

size_t disc_component(const disc *D, size_t j) {
  if (D->b0->kind == WHIRL_SOL_EQ) return j;
  if (D->b0->kind == WHIRL_SOL_HBM) {
    const size_t L = 2 * (size_t)D->R->s->nhb + 1;
    return j / L < D->n ? j / L : D->n - 1;
  }
  return j < D->nb - (D->nb % D->n) ? j % D->n : D->n - 1; /* node-major */
}

/* The period of an orbit at the current sample (forced models). */
static double period(const disc *D) {
  return 2.0 * WHIRL_PI / D->p[D->R->model->forcing_param];
}

/* Time integration from x0 (model state): the end state after `settle`
 * (forcing periods, or time units), or for a periodic problem its next
 * period as the discretised orbit.  0, 1 (the integration failed). */
static int settled(disc *D, const double *x0, double *out) {
  run_ctx *R = D->R;
  const int forced = R->model->forcing_param >= 0;
  const double T = forced ? 2.0 * WHIRL_PI / D->p[R->model->forcing_param] : 1.0;
  const double t1 = R->s->discover_settle * T;
  whirl_ode *ode = whirl_ode_alloc(&R->prob, D->p);
  if (!ode) return 1;
  int rc = whirl_ode_set_tolerances(ode, 1e-8, 1e-10);
  if (!rc) rc = whirl_ode_set_max_steps(ode, 2000000);
  if (!rc) rc = whirl_ode_reset(ode, 0.0, x0);
  if (!rc) rc = whirl_ode_evolve(ode, t1);
  if (!rc && D->b0->kind == WHIRL_SOL_EQ) {
    memcpy(out, whirl_ode_x(ode), D->n * sizeof *out);
  } else if (!rc) {
    const size_t m = D->m;
    for (size_t k = 0; !rc && k < m; k++) {
      rc = whirl_ode_evolve(ode, t1 + T * (double)k / (double)m);
      if (!rc) memcpy(D->xs + k * D->n, whirl_ode_x(ode), D->n * sizeof *D->xs);
    }
    if (!rc) rc = whirl_periodic_from_samples(&D->po, D->xs, m, T, out);
  }
  whirl_ode_free(ode);
  return rc ? 1 : 0;
}

/* A scale of the box for one random start, log-uniform in [1/4, 4]
 * (DISCOVER_BOX given: 1): an isolated branch may lie far from the size of
 * the start branch, which sets the default box. */
static double box_zoom(disc *D) {
  return D->R->s->nbox ? 1.0 : exp(log(4.0) * (2.0 * disc_urand(D) - 1.0));
}

/* A random orbit (or state) in the box: a uniform mean and, for periodic
 * problems, a first harmonic of uniform amplitude up to half the box. */
static int random_start(disc *D, double *out) {
  const size_t n = D->n;
  const double zoom = box_zoom(D);
  for (size_t i = 0; i < n; i++) {
    const double mid = 0.5 * (D->lo[i] + D->hi[i]), half = 0.5 * zoom * (D->hi[i] - D->lo[i]);
    const double lo = mid - half, hi = mid + half;
    D->c[i] = lo + (hi - lo) * disc_urand(D);
    D->c[n + i] = 0.5 * (hi - lo) * (disc_urand(D) - 0.5);
    D->c[2 * n + i] = 0.5 * (hi - lo) * (disc_urand(D) - 0.5);
  }
  if (!D->periodic) {
    memcpy(out, D->c, n * sizeof *out);
    return 0;
  }
  return whirl_periodic_from_harmonics(&D->po, D->c, 1, period(D), out) ? 1 : 0;
}

/* A known orbit at a random phase and a random amplitude (log-uniform in
 * [1/4, 4]): a start whose components are consistent with each other (a
 * velocity the derivative of its displacement), unlike a random orbit.
 * Sampled at the shifted times and taken back (any discretisation). */
static int shifted_start(disc *D, size_t nknown, double *x) {
  size_t pick = (size_t)(disc_urand(D) * (double)nknown);
  if (pick >= nknown) pick = nknown - 1;
  const double *r = whirl_deflate_root(D->d, pick);
  const double a = exp(log(4.0) * (2.0 * disc_urand(D) - 1.0)), shift = disc_urand(D);
  for (size_t k = 0; k < D->m; k++) {
    const double tau = fmod((double)k / (double)D->m + shift, 1.0);
    if (whirl_periodic_eval(&D->po, r, tau, D->xs + k * D->n)) return 1;
    for (size_t i = 0; i < D->n; i++) D->xs[k * D->n + i] *= a;
  }
  return whirl_periodic_from_samples(&D->po, D->xs, D->m, period(D), x) ? 1 : 0;
}

/* The k-th start at the current sample: the model's start (or the zero
 * orbit: Newton's first step from it is the linear response), three scaled
 * copies of each known solution, settled integrations (a quarter of the
 * budget when DISCOVER_SETTLE > 0), then random states — for orbits four in
 * five of them a known orbit at a random phase and amplitude (on the
 * Jeffcott rotor's isola 30 of 30 seeds find it with 40 starts, against 25
 * of 30 with half of them; doc/discovery.md).  0 with the start in
 * x and its kind, 1 when this start is not usable (skipped). */
int disc_start(disc *D, size_t k, size_t nknown, double *x, int *from) {
  static const double scale[3] = {0.5, 1.5, -1.0};
  const int budget = D->R->s->discover_starts;
  const size_t nsettle = D->R->s->discover_settle > 0 ? (size_t)(budget + 3) / 4 : 0;
  if (k == 0) {
    *from = FROM_START;
    if (!D->periodic)
      memcpy(x, D->R->u, D->n * sizeof *x);
    else
      memset(x, 0, D->nb * sizeof *x);
    return 0;
  }
  k--;
  if (k < 3 * nknown) {
    *from = FROM_SCALED;
    const double *r = whirl_deflate_root(D->d, k / 3);
    for (size_t j = 0; j < D->nb; j++) x[j] = scale[k % 3] * r[j];
    return 0;
  }
  k -= 3 * nknown;
  if (k < nsettle) {
    *from = FROM_SETTLED;
    double *x0 = D->c; /* a random initial state in the box */
    const double zoom = box_zoom(D);
    for (size_t i = 0; i < D->n; i++)
      x0[i] = 0.5 * (D->lo[i] + D->hi[i]) + zoom * (D->hi[i] - D->lo[i]) * (disc_urand(D) - 0.5);
    double *st = malloc(D->n * sizeof *st);
    if (!st) return 1;
    memcpy(st, x0, D->n * sizeof *st);
    int rc = settled(D, st, x);
    free(st);
    return rc;
  }
  *from = FROM_RANDOM;
  if (D->periodic && nknown && disc_urand(D) < 0.8) return shifted_start(D, nknown, x);
  return random_start(D, x);
}


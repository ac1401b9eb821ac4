/* start_orbit.c — start data for the AUTO-07p benchmark of the SFD rotor's
 * nonsynchronous response (run_nonsync.py): one period of the stable
 * periodic orbit of the rotating-frame ODE (whirl_sfd_rotating(), state
 * x = (u, v, u', v')) at Table 1 (λ = 0.0503, δ = 0.3, ζ = 0), Ω = 8.7.
 *
 * Integrates from rest (x = 0) for NFORCE = 1500 forcing periods 2π/Ω with
 * whirl's Dormand–Prince 5(4) (rtol 1e-12, atol 1e-15, the paper's), then
 * finds the returns to the section u' = 0 with u at a maximum (u' going
 * from + to −), takes the period T from the last two returns, and writes
 * NSAMP + 1 rows  t  u  v  u'  v'  at t = k T / NSAMP, k = 0..NSAMP, from
 * the last return (t in time units, starting at 0): AUTO's dat format, in
 * which the period is t(last) − t(first), so the closing point
 * x(T) ≈ x(0) is included.  Checks that the orbit has settled (the last
 * returns agree) and closes; exits non-zero with a message otherwise.
 *
 * Build and run (from the source tree, libwhirl built in /tmp/build):
 *   gcc -std=c11 -O2 -I../../../../lib start_orbit.c \
 *       -L/tmp/build/lib/.libs -lwhirl -lm -o start_orbit
 *   LD_LIBRARY_PATH=/tmp/build/lib/.libs ./start_orbit > nonsync.dat
 * Summary (period, returns, closure) on stderr.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <whirl/whirl.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define OMEGA 8.7
#define NFORCE 1500
#define NSAMP 400
#define NRET 64 /* returns kept (ring buffer) */

static double g_du(double t, const double *x, void *data)
{
  (void)t;
  (void)data;
  return x[2]; /* u' */
}

static int die(const char *what, whirl_ode *ode, int status)
{
  fprintf(stderr, "start_orbit: %s failed: %s (%s)\n", what,
          whirl_strerror(status), ode ? whirl_ode_errmsg(ode) : "");
  whirl_ode_free(ode);
  return EXIT_FAILURE;
}

static int print_row(size_t k, double t, const double *x, void *data)
{
  const double *t0 = data;
  (void)k;
  if (printf("%24.16e %24.16e %24.16e %24.16e %24.16e\n", t - *t0, x[0],
             x[1], x[2], x[3]) < 0)
    return -1;
  return 0;
}

int main(void)
{
  const whirl_problem *prob = whirl_sfd_rotating();
  double p[WHIRL_SFD_NPAR], x0[4] = {0.0, 0.0, 0.0, 0.0};
  double tret[NRET], xret[NRET][4], xe[4];
  const double t_end = NFORCE * 2.0 * M_PI / OMEGA;
  size_t nret = 0, i;
  double T, T_prev, dmax, closure, tlast;
  whirl_ode *ode;
  int st;

  whirl_sfd_default_params(p); /* Table 1, ζ = 0, F_E = 0 */
  p[WHIRL_SFD_OMEGA] = OMEGA;
  if (p[WHIRL_SFD_LAMBDA] != 0.0503 || p[WHIRL_SFD_DELTA] != 0.3
      || p[WHIRL_SFD_ZETA] != 0.0) {
    fprintf(stderr, "start_orbit: whirl's default parameters are not "
                    "Table 1 (lambda 0.0503, delta 0.3, zeta 0)\n");
    return EXIT_FAILURE;
  }
  ode = whirl_ode_alloc(prob, p);
  if (!ode) {
    fprintf(stderr, "start_orbit: whirl_ode_alloc failed\n");
    return EXIT_FAILURE;
  }
  if ((st = whirl_ode_set_tolerances(ode, 1e-12, 1e-15)) != WHIRL_OK)
    return die("whirl_ode_set_tolerances", ode, st);
  if ((st = whirl_ode_reset(ode, 0.0, x0)) != WHIRL_OK)
    return die("whirl_ode_reset", ode, st);

  /* integrate, recording the returns to u' = 0 (+ to −: maxima of u) */
  while ((st = whirl_ode_step(ode, t_end)) == WHIRL_OK) {
    double te;
    int ev = whirl_ode_find_event(ode, g_du, NULL, -1, 0.0, &te, xe);
    if (ev < 0)
      return die("whirl_ode_find_event", ode, ev);
    if (ev == 1) {
      tret[nret % NRET] = te;
      for (i = 0; i < 4; i++)
        xret[nret % NRET][i] = xe[i];
      nret++;
    }
  }
  if (st != WHIRL_DONE)
    return die("integration", ode, st);
  if (nret < 12) {
    fprintf(stderr, "start_orbit: only %zu returns to u' = 0 in %d forcing "
                    "periods: no periodic orbit\n", nret, NFORCE);
    whirl_ode_free(ode);
    return EXIT_FAILURE;
  }
  /* settled: the last 10 periods agree and the return points coincide */
  T = tret[(nret - 1) % NRET] - tret[(nret - 2) % NRET];
  T_prev = tret[(nret - 2) % NRET] - tret[(nret - 3) % NRET];
  dmax = 0.0;
  for (i = 2; i <= 10; i++) {
    size_t a = (nret - i) % NRET, b = (nret - i - 1) % NRET;
    double Ti = tret[a] - tret[b], d = fabs(Ti - T);
    size_t j;
    for (j = 0; j < 4; j++)
      d = fmax(d, fabs(xret[a][j] - xret[(nret - 1) % NRET][j]));
    dmax = fmax(dmax, d);
  }
  if (!(dmax < 1e-8)) {
    fprintf(stderr, "start_orbit: not settled after %d forcing periods: the "
                    "last 10 returns differ by %.3g\n", NFORCE, dmax);
    whirl_ode_free(ode);
    return EXIT_FAILURE;
  }

  /* one period from the last return, NSAMP uniform intervals */
  tlast = tret[(nret - 1) % NRET];
  if ((st = whirl_ode_reset(ode, tlast, xret[(nret - 1) % NRET])) != WHIRL_OK)
    return die("whirl_ode_reset", ode, st);
  st = whirl_ode_sample(ode, T / NSAMP, NSAMP, print_row, &tlast);
  if (st != WHIRL_OK)
    return die("sampling one period", ode, st);
  closure = 0.0;
  for (i = 0; i < 4; i++)
    closure = fmax(closure,
                   fabs(whirl_ode_x(ode)[i] - xret[(nret - 1) % NRET][i]));
  if (fflush(stdout) != 0 || ferror(stdout)) {
    fprintf(stderr, "start_orbit: write error\n");
    whirl_ode_free(ode);
    return EXIT_FAILURE;
  }
  fprintf(stderr,
          "start_orbit: Omega = %g, %zu returns to u' = 0 in %d forcing "
          "periods; period T = %.15g (previous %.15g, last 10 returns agree "
          "to %.2g); |x(T) - x(0)| = %.2g; u(0) = %.15g, v(0) = %.15g, "
          "v'(0) = %.15g\n",
          OMEGA, nret, NFORCE, T, T_prev, dmax, closure,
          xret[(nret - 1) % NRET][0], xret[(nret - 1) % NRET][1],
          xret[(nret - 1) % NRET][3]);
  whirl_ode_free(ode);
  if (!(closure < 1e-8)) {
    fprintf(stderr, "start_orbit: the sampled period does not close "
                    "(%.3g)\n", closure);
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

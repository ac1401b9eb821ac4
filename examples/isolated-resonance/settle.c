/* examples/isolated-resonance/settle.c — the time-domain check of a
 * harmonic-balance response of irc.c: integrate the model by DOPRI5
 * (whirl/ode.h, rtol 1e-11) from a state for a number of forcing periods
 * and print where it ends:
 *
 *     settle PERIODS x0 v0 [NAME=VALUE ...]
 *
 * NAME one of the model's parameters (defaults: its par0).  Prints one line
 *     x(nT) v(nT) max_x
 * with T = 2 pi / Omega, n = PERIODS, and max_x the largest x over the
 * period that follows (2000 samples of the dense output, refined by a
 * parabola through the largest sample and its neighbours).  Start from a
 * harmonic-balance orbit's t = 0 state (x(0) = c + sum a_k of its Fourier
 * coefficients): a stable orbit stays, x(nT) = x(0) and max_x = MAX x of
 * branches.tsv; an unstable one drifts away to another response.
 *
 * Build:  make settle   (links irc.c into it; pkg-config --libs whirl)
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/whirl.h>

extern const whirl_model whirl_model_def;

enum { NSAMPLE = 2000 };

typedef struct { double x[NSAMPLE + 1]; } samples;

static int keep(size_t k, double t, const double *x, void *data) {
  (void)t;
  ((samples *)data)->x[k] = x[0];
  return 0;
}

/* The largest sample, refined by the parabola through it and its two
 * neighbours (error O(h^3) for a smooth maximum). */
static double largest(const samples *s) {
  size_t m = 1;
  for (size_t k = 1; k < NSAMPLE; k++)
    if (s->x[k] > s->x[m]) m = k;
  const double a = s->x[m - 1], b = s->x[m], c = s->x[m + 1];
  const double den = a - 2.0 * b + c;
  return den < 0.0 ? b - 0.125 * (c - a) * (c - a) / den : b;
}

static int set_param(const whirl_problem *pr, double *p, const char *arg) {
  const char *eq = strchr(arg, '=');
  for (size_t j = 0; eq != NULL && j < pr->npar; j++)
    if (strlen(pr->p_names[j]) == (size_t)(eq - arg) &&
        strncmp(pr->p_names[j], arg, (size_t)(eq - arg)) == 0) {
      p[j] = atof(eq + 1);
      return 0;
    }
  fprintf(stderr, "settle: '%s' is not NAME=VALUE of a parameter\n", arg);
  return -1;
}

int main(int argc, char **argv) {
  const whirl_model *m = &whirl_model_def;
  const whirl_problem *pr = &m->problem;
  double p[16], x0[2];
  if (argc < 4 || pr->npar > 16 || pr->n != 2) {
    fprintf(stderr, "usage: settle PERIODS x0 v0 [NAME=VALUE ...]\n");
    return 2;
  }
  memcpy(p, m->par0, pr->npar * sizeof *p);
  for (int i = 4; i < argc; i++)
    if (set_param(pr, p, argv[i]) != 0) return 2;
  const double periods = atof(argv[1]);
  const double T = 2.0 * WHIRL_PI / p[m->forcing_param];
  x0[0] = atof(argv[2]);
  x0[1] = atof(argv[3]);
  whirl_ode *ode = whirl_ode_alloc(pr, p);
  samples s;
  int st = ode == NULL ? WHIRL_ENOMEM : whirl_ode_set_tolerances(ode, 1e-11, 1e-13);
  if (st == WHIRL_OK) st = whirl_ode_set_max_steps(ode, 0);
  if (st == WHIRL_OK) st = whirl_ode_reset(ode, 0.0, x0);
  if (st == WHIRL_OK) st = whirl_ode_evolve(ode, periods * T);
  double xT[2] = {0.0, 0.0};
  if (st == WHIRL_OK) memcpy(xT, whirl_ode_x(ode), sizeof xT);
  if (st == WHIRL_OK) st = whirl_ode_sample(ode, T / NSAMPLE, NSAMPLE, keep, &s);
  if (st != WHIRL_OK) {
    fprintf(stderr, "settle: %s\n", ode ? whirl_ode_errmsg(ode) : "out of memory");
    whirl_ode_free(ode);
    return 1;
  }
  printf("%.12g %.12g %.12g\n", xT[0], xT[1], largest(&s));
  whirl_ode_free(ode);
  return 0;
}

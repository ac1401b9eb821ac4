/* examples/isolated-resonance/irc.c — a Duffing oscillator with a
 * nonlinear (amplitude-dependent) damper, the class of single-degree-of-
 * freedom systems with isolated resonance curves of Habib, Cirillo &
 * Kerschen, "Isolated resonances and nonlinear damping", Nonlinear Dyn. 93
 * (2018) 979-994 (doc/isolated-resonance.md):
 *
 *     x'' + (c1 + c3 x^2 + c5 x^4) x' + x + k3 x^3 = F cos(Omega t).
 *
 * With c3 < 0 < c1, c5 the damping first falls, then rises with the
 * amplitude, so the damping force of the first harmonic is not monotone in
 * the amplitude, and for F between its local minimum and maximum the
 * forced response has a closed curve of periodic responses detached from
 * the main resonance peak (doc/isolated-resonance.md §2 gives the closed
 * form by first-harmonic balance).
 *
 * First-order form u = (x, v): x' = v,
 *                               v' = F cos(Omega t) - d(x) v - x - k3 x^3,
 * d(x) = c1 + c3 x^2 + c5 x^4.  Parameters p = (Omega, F, c1, c3, c5, k3);
 * Omega is the forcing frequency (period 2 pi / Omega).
 *
 * Build:  make            (Makefile: pkg-config --cflags --libs whirl)
 * Run:    whirl run irc.whirl    (the isola)
 *         whirl run main.whirl   (the main branch from low frequency)
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>

#include <whirl/whirl.h>

enum { OMEGA, FORCE, C1, C3, C5, K3, NPAR };

static double damping(double x, const double *p) {
  const double x2 = x * x;
  return p[C1] + p[C3] * x2 + p[C5] * x2 * x2;
}

static int rhs(double t, const double *u, const double *p, double *f, void *data) {
  (void)data;
  const double x = u[0], v = u[1];
  f[0] = v;
  f[1] = p[FORCE] * cos(p[OMEGA] * t) - damping(x, p) * v - x - p[K3] * x * x * x;
  return 0;
}

/* Column-major, J[i + n*j] = d f_i / d u_j. */
static int jac_x(double t, const double *u, const double *p, double *J, void *data) {
  (void)t;
  (void)data;
  const double x = u[0], v = u[1];
  const double dd = 2.0 * p[C3] * x + 4.0 * p[C5] * x * x * x; /* d'(x) */
  J[0] = 0.0;
  J[1] = -dd * v - 1.0 - 3.0 * p[K3] * x * x;
  J[2] = 1.0;
  J[3] = -damping(x, p);
  return 0;
}

static int jac_p(double t, const double *u, const double *p, double *J, void *data) {
  (void)data;
  const double x = u[0], v = u[1], x2 = x * x;
  for (int k = 0; k < 2 * NPAR; k++) J[k] = 0.0;
  J[1 + 2 * OMEGA] = -p[FORCE] * t * sin(p[OMEGA] * t);
  J[1 + 2 * FORCE] = cos(p[OMEGA] * t);
  J[1 + 2 * C1] = -v;
  J[1 + 2 * C3] = -x2 * v;
  J[1 + 2 * C5] = -x2 * x2 * v;
  J[1 + 2 * K3] = -x2 * x;
  return 0;
}

/* Refuse parameters whose first-harmonic damping D(a) = c1 + c3 a^2/4 +
 * c5 a^4/8 (the mean of d(x) over a harmonic orbit of amplitude a) can
 * vanish: then the unforced oscillator has limit cycles (self-excitation,
 * not this example's subject).  min D = c1 - c3^2 / (8 c5) for c3 < 0. */
static int check_params(const double *p, char *msg, size_t len) {
  const int bad = p[C1] <= 0.0 || p[C5] < 0.0 ||
                  (p[C3] < 0.0 && p[C3] * p[C3] >= 8.0 * p[C1] * p[C5]);
  if (bad && len > 0) {
    const char *r = "the first-harmonic damping c1 + c3 a^2/4 + c5 a^4/8 must "
                    "stay positive (c1 > 0, c5 >= 0, c3^2 < 8 c1 c5 if c3 < 0)";
    size_t i = 0;
    for (; r[i] != '\0' && i + 1 < len; i++) msg[i] = r[i];
    msg[i] = '\0';
  }
  return bad;
}

static const char *const x_names[] = {"x", "v"};
static const char *const p_names[] = {"Omega", "F", "c1", "c3", "c5", "k3"};
/* doc/isolated-resonance.md §3: the isola exists for 0.04542 < F < 0.06365. */
static const double par0[] = {0.5, 0.055, 0.1, -0.175, 0.05, 0.05};
static const double u0[] = {0.0, 0.0};

const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "irc", .n = 2, .npar = NPAR, .rhs = rhs,
                .jac_x = jac_x, .jac_p = jac_p, .autonomous = 0,
                .x_names = x_names, .p_names = p_names},
    .par0 = par0,
    .u0 = u0,
    .forcing_param = OMEGA,
    .check_params = check_params,
    .description = "Duffing oscillator with a nonlinear damper (isolated resonance)"};

/* examples/ab/ab.c — AUTO-07p's demo 'ab' (the A -> B reaction in a
 * continuous stirred tank, Uppal, Ray & Poore 1974) written against the
 * installed whirl library only: a model struct, the equilibrium constructor
 * and the generic continuation loop.  Prints the special points as TSV.
 *
 *   u1' = -u1 + Da (1 - u1) exp(u2)
 *   u2' = -u2 + Da B (1 - u1) exp(u2) - beta u2      p = (Da, B, beta)
 *
 * Build:  make            (uses pkg-config --cflags --libs whirl)
 * Run:    ./ab [B [beta]] (defaults 17 and 3: AUTO's demo, run 2, from B = 17)
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <whirl/whirl.h>

static int ab_rhs(double t, const double *u, const double *p, double *f, void *data) {
  (void)t;
  (void)data;
  const double e = exp(u[1]);
  f[0] = -u[0] + p[0] * (1.0 - u[0]) * e;
  f[1] = -u[1] + p[0] * p[1] * (1.0 - u[0]) * e - p[2] * u[1];
  return 0;
}

/* column-major J[i + 2 j] = d f_i / d u_j */
static int ab_jac_x(double t, const double *u, const double *p, double *J, void *data) {
  (void)t;
  (void)data;
  const double e = exp(u[1]);
  J[0] = -1.0 - p[0] * e;
  J[1] = -p[0] * p[1] * e;
  J[2] = p[0] * (1.0 - u[0]) * e;
  J[3] = -1.0 + p[0] * p[1] * (1.0 - u[0]) * e - p[2];
  return 0;
}

static int ab_jac_p(double t, const double *u, const double *p, double *J, void *data) {
  (void)t;
  (void)data;
  const double e = exp(u[1]);
  J[0] = (1.0 - u[0]) * e; /* d/dDa */
  J[1] = p[1] * (1.0 - u[0]) * e;
  J[2] = 0.0; /* d/dB */
  J[3] = p[0] * (1.0 - u[0]) * e;
  J[4] = 0.0; /* d/dbeta */
  J[5] = -u[1];
  return 0;
}

static const char *const x_names[] = {"u1", "u2"};
static const char *const p_names[] = {"Da", "B", "beta"};

static const whirl_problem ab = {
    .name = "ab", .n = 2, .npar = 3, .rhs = ab_rhs, .jac_x = ab_jac_x,
    .jac_p = ab_jac_p, .autonomous = 1, .x_names = x_names, .p_names = p_names};

int main(int argc, char **argv) {
  double p[3] = {0.0, 17.0, 3.0}, u[2] = {0.0, 0.0};
  if (argc > 1) p[1] = atof(argv[1]);
  if (argc > 2) p[2] = atof(argv[2]);

  whirl_equilibrium *eq = whirl_equilibrium_alloc(&ab);
  whirl_cont_options opt;
  whirl_cont_options_default(&opt); /* AUTO's c.ab.2: ICP = 1, UZSTOP 0.25 */
  opt.icp = 0;
  opt.ds = 1e-3;
  opt.ds_max = 0.05;
  opt.p_min = 0.0;
  opt.p_max = 0.25;
  char err[256];
  whirl_cont *c = whirl_cont_alloc(whirl_equilibrium_system(eq), &opt, err, sizeof err);
  if (!c) {
    fprintf(stderr, "ab: %s\n", err);
    return 1;
  }
  int rc = whirl_cont_start(c, u, p, +1);
  printf("TY\tLAB\tDa\tL2\tu1\tu2\tomega\n");
  while (rc == WHIRL_OK && (rc = whirl_cont_step(c)) == WHIRL_OK) {
    const whirl_point *pt = whirl_cont_point(c);
    if (pt->type == WHIRL_PT_REGULAR) continue;
    /* AUTO's L2-NORM is the Euclidean norm of the state */
    double l2 = hypot(pt->x[0], pt->x[1]);
    double w = pt->type == WHIRL_PT_HB ? fabs(pt->spec_im[0]) : 0.0;
    printf("%s\t%d\t%.10f\t%.10f\t%.10f\t%.10f\t%.10f\n", whirl_point_type_name(pt->type),
           pt->label, pt->p[0], l2, pt->x[0], pt->x[1], w);
  }
  if (rc < 0) fprintf(stderr, "ab: %s\n", whirl_cont_errmsg(c));
  whirl_cont_free(c);
  whirl_equilibrium_free(eq);
  return rc < 0;
}

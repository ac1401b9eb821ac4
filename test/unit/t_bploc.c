/* test/unit/t_bploc.c — the locus of branch points of equilibria
 * (whirl/bploc.h) on problems with closed-form loci:
 *  - symmetric (ISW = 2): F = x (p1 + p2 - x^2), odd in x; its pitchfork
 *    x = 0, p1 = -p2 for every p2, the unfolding beta staying 0, found
 *    where the generic system (no beta) is singular;
 *  - generic (ISW = 3): F = x^2 - p1^2 + p2 + p3 x, a branch point in p1
 *    where F = (x + p3/2)^2 - p1^2 factorises: x = -p3/2, p1 = 0,
 *    p2 = p3^2/4 along p3;
 *  - AUTO's apbp equations F = (u - p1)(u - p2) + p3: u = p1 = p2, p3 = 0
 *    along p2, both ways (the demo runs it with ISW = 2 and 3).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <whirl/whirl.h>

#include "../tap.h"

static int sym_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * (p[0] + p[1] - x[0] * x[0]);
  return 0;
}
static int sym3_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * (p[0] + p[1] + p[2] - x[0] * x[0]);
  return 0;
}
static int gen_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = x[0] * x[0] - p[0] * p[0] + p[1] + p[2] * x[0];
  return 0;
}
static int apbp_F(const double *x, const double *p, double *f, void *d) {
  (void)d;
  f[0] = (x[0] - p[0]) * (x[0] - p[1]) + p[2];
  return 0;
}

static whirl_system sys_of(int (*F)(const double *, const double *, double *, void *),
                           size_t npar) {
  whirl_system s = {0};
  s.name = "F";
  s.n = 1;
  s.npar = npar;
  s.F = F;
  return s;
}

/* The locus from (x0, p0), in p[icp] over [lo, hi] both ways; the largest
 * deviation of its points from the closed form dev(Z, p). */
static double follow(whirl_bploc *b, const double *x0, double *p0, size_t icp, double lo,
                     double hi, double (*dev)(const double *Z, const double *p),
                     size_t *npts) {
  double Z[4], worst = 0.0;
  *npts = 0;
  if (whirl_bploc_init(b, x0, p0, Z) != WHIRL_OK) {
    printf("# init: %s\n", whirl_bploc_errmsg(b));
    return INFINITY;
  }
  const whirl_system *s = whirl_bploc_system(b);
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.icp = icp;
  o.ds = 0.05;
  o.ds_max = 0.1;
  o.p_min = lo;
  o.p_max = hi;
  for (int dir = -1; dir <= 1; dir += 2) {
    char err[256];
    whirl_cont *c = whirl_cont_alloc(s, &o, err, sizeof err);
    whirl_branch *br = c ? whirl_branch_alloc(s->n, s->npar, s->nspec, icp) : NULL;
    int rc = c && br ? whirl_cont_start(c, Z, p0, dir) : -1;
    if (rc == WHIRL_OK) rc = whirl_cont_run(c, br);
    if (rc < 0) {
      printf("# run: %s\n", c ? whirl_cont_errmsg(c) : err);
      worst = INFINITY;
    }
    for (size_t i = 0; br && i < br->len; ++i) {
      double pf[3];
      whirl_bploc_params(b, br->pts[i].x, br->pts[i].p, pf);
      worst = fmax(worst, dev(br->pts[i].x, pf));
      ++*npts;
    }
    whirl_branch_free(br);
    whirl_cont_free(c);
  }
  return worst;
}

/* Z = (x, psi, p1, beta) */
static double sym_dev(const double *Z, const double *p) {
  return fmax(fabs(Z[0]), fmax(fabs(p[0] + p[1]), fabs(Z[3])));
}
static double gen_dev(const double *Z, const double *p) {
  return fmax(fabs(Z[0] + p[2] / 2), fmax(fabs(p[0]), fabs(p[1] - p[2] * p[2] / 4)));
}
static double apbp_dev(const double *Z, const double *p) {
  return fmax(fabs(Z[0] - p[0]), fmax(fabs(Z[0] - p[1]), fabs(p[2])));
}

int main(void) {
  char err[256] = "";
  size_t n = 0;
  whirl_system sym = sys_of(sym_F, 2), gen = sys_of(gen_F, 3), ap = sys_of(apbp_F, 3);

  whirl_bploc *b = whirl_bploc_alloc(&sym, 0, 0, 0, err, sizeof err);
  double x0 = 0.0, ps[2] = {-0.5, 0.5};
  double d = b ? follow(b, &x0, ps, 1, -2.0, 2.0, sym_dev, &n) : INFINITY;
  ok(d < 1e-10 && n > 20, "symmetric pitchfork x (p1 + p2 - x^2): x = 0, p1 = -p2, beta = 0 "
     "(%zu points, max dev %.2g) %s", n, d, err);
  whirl_bploc_free(b);
  /* without beta (the generic system, with p3 x as the third parameter's
   * term, still odd) the F row vanishes at every symmetric BP: singular */
  whirl_system sym3 = sys_of(sym3_F, 3);
  b = whirl_bploc_alloc(&sym3, 0, 1, 2, err, sizeof err);
  double p3[3] = {-0.5, 0.5, 0.0};
  d = b ? follow(b, &x0, p3, 1, -2.0, 2.0, sym_dev, &n) : 0.0;
  ok(b && !(d < 1e-10 && n > 20), "the symmetric BP without beta (generic system): no locus "
     "(%zu points)", n);
  whirl_bploc_free(b);

  err[0] = 0;
  b = whirl_bploc_alloc(&gen, 0, 1, 1, err, sizeof err);
  double xg = -0.5, pg[3] = {0.0, 0.25, 1.0};
  d = b ? follow(b, &xg, pg, 2, -1.0, 3.0, gen_dev, &n) : INFINITY;
  ok(d < 1e-9 && n > 20, "generic x^2 - p1^2 + p2 + p3 x: x = -p3/2, p1 = 0, p2 = p3^2/4 "
     "(%zu points, max dev %.2g) %s", n, d, err);
  whirl_bploc_free(b);

  for (int generic = 0; generic <= 1; ++generic) {
    err[0] = 0;
    b = whirl_bploc_alloc(&ap, 0, generic, 2, err, sizeof err);
    double xa = 2.0, pa[3] = {2.0, 2.0, 0.0};
    d = b ? follow(b, &xa, pa, 1, -1.0, 5.0, apbp_dev, &n) : INFINITY;
    ok(d < 1e-9 && n > 20, "apbp (u - p1)(u - p2) + p3, %s: u = p1 = p2, p3 = 0 (%zu points, "
       "max dev %.2g) %s", generic ? "generic (ISW = 3)" : "non-generic (ISW = 2)", n, d, err);
    whirl_bploc_free(b);
  }

  ok(whirl_bploc_alloc(&gen, 0, 1, 0, err, sizeof err) == NULL,
     "a generic locus needs a third parameter other than the BP's: %s", err);
  ok(whirl_bploc_alloc(&gen, 5, 0, 0, err, sizeof err) == NULL,
     "the BP's parameter must be one of the base's: %s", err);
  return done_testing();
}

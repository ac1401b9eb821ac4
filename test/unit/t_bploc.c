/* test/unit/t_bploc.c — the locus of branch points of equilibria
 * (whirl/bploc.h) on problems with closed-form loci:
 *  - symmetric (ISW = 2): F = x (p1 + p2 - x^2), odd in x; its pitchfork
 *    x = 0, p1 = -p2 for every p2, the unfolding beta staying 0, found
 *    where the generic system (no beta) is singular;
 *  - generic (ISW = 3): F = x^2 - p1^2 + p2 + p3 x, a branch point in p1
 *    where F = (x + p3/2)^2 - p1^2 factorises: x = -p3/2, p1 = 0,
 *    p2 = p3^2/4 along p3;
 *  - AUTO's apbp equations F = (u - p1)(u - p2) + p3: u = p1 = p2, p3 = 0
 *    along p2, both ways (the demo runs it with ISW = 2 and 3);
 *  - the same three by minimal augmentation (whirl_fold, cond BP: the
 *    branch-point curve of collocation orbits and BVPs), dense on the
 *    scalar equation and sparse on it padded to 121 unknowns with
 *    x_k = k p1 / 100 (a sparse pattern, F_x regular off the first).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/whirl.h>

#include "../tap.h"
#include "bsolver_check.h"

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

/* ---- the branch-point curve by minimal augmentation (whirl_fold) */

static int (*scalar_F)(const double *, const double *, double *, void *);
enum { NPAD = 121 };

/* x[0] the scalar problem, x[k] - k p1 / 100 = 0 for k >= 1 */
static int pad_F(const double *x, const double *p, double *f, void *d) {
  int rc = scalar_F(x, p, f, d);
  for (size_t k = 1; k < NPAD; ++k) f[k] = x[k] - 0.01 * (double)k * p[0];
  return rc;
}
/* dF/dx of the three scalar problems, exact */
static double scalar_dF(const double *x, const double *p) {
  if (scalar_F == sym_F) return p[0] + p[1] - 3.0 * x[0] * x[0];
  if (scalar_F == gen_F) return 2.0 * x[0] + p[2];
  return 2.0 * x[0] - p[0] - p[1]; /* apbp_F */
}
static int pad_Fx_sparse(const double *x, const double *p, double *Jx, void *d) {
  (void)d;
  Jx[0] = scalar_dF(x, p);
  for (size_t k = 1; k < NPAD; ++k) Jx[k] = 1.0;
  return 0;
}
static int pad_Jp[NPAD + 1], pad_Ji[NPAD];

static whirl_system padded(int (*F)(const double *, const double *, double *, void *),
                           size_t npar, int sparse) {
  whirl_system s = sys_of(F, npar);
  if (!sparse) return s;
  scalar_F = F;
  for (int k = 0; k <= NPAD; ++k) pad_Jp[k] = k;
  for (int k = 0; k < NPAD; ++k) pad_Ji[k] = k;
  s.n = NPAD;
  s.F = pad_F;
  s.nnz = NPAD;
  s.Jp = pad_Jp;
  s.Ji = pad_Ji;
  s.Fx_sparse = pad_Fx_sparse;
  return s;
}

/* The curve from x0 (x0[0], the padding's values) at p0, in p[icp] over
 * [lo, hi] both ways; the largest deviation from the closed form (on
 * the scalar x and the parameters, beta in Z[n + 1] with unfold) and
 * the points' types in *types_ok (every labelled point a BP or an end). */
static double follow_fold(const whirl_system *base, const whirl_fold_options *fo,
                          double x00, double *p0, size_t icp, double lo, double hi,
                          double (*dev)(const double *Z, const double *p), size_t *npts) {
  char err[256];
  whirl_fold *f = whirl_fold_alloc(base, fo, err, sizeof err);
  if (!f) {
    printf("# alloc: %s\n", err);
    return INFINITY;
  }
  const size_t n = base->n;
  double x0[NPAD], Z[NPAD + 2], worst = 0.0;
  x0[0] = x00;
  for (size_t k = 1; k < n; ++k) x0[k] = 0.01 * (double)k * p0[0];
  *npts = 0;
  if (whirl_fold_init(f, x0, p0, Z) != WHIRL_OK) {
    printf("# init: %s\n", whirl_fold_errmsg(f));
    whirl_fold_free(f);
    return INFINITY;
  }
  const whirl_system *s = whirl_fold_system(f);
  whirl_cont_options o;
  whirl_cont_options_default(&o);
  o.icp = icp;
  o.ds = 0.05;
  o.ds_max = 0.1;
  o.p_min = lo;
  o.p_max = hi;
  for (int dir = -1; dir <= 1; dir += 2) {
    whirl_cont *c = whirl_cont_alloc(s, &o, err, sizeof err);
    whirl_branch *br = c ? whirl_branch_alloc(s->n, s->npar, s->nspec, icp) : NULL;
    int rc = c && br ? whirl_cont_start(c, Z, p0, dir) : -1;
    if (rc == WHIRL_OK) rc = whirl_cont_run(c, br);
    if (rc < 0) {
      printf("# run: %s\n", c ? whirl_cont_errmsg(c) : err);
      worst = INFINITY;
    }
    for (size_t i = 0; br && i < br->len; ++i) {
      double pf[3], Zs[4];
      whirl_fold_params(f, br->pts[i].x, br->pts[i].p, pf);
      Zs[0] = br->pts[i].x[0];
      Zs[3] = fo->unfold ? br->pts[i].x[n + 1] : 0.0; /* beta, as bploc's Z[3] */
      worst = fmax(worst, dev(Zs, pf));
      for (size_t k = 1; k < n; ++k) /* the padding stays on its solution */
        worst = fmax(worst, fabs(br->pts[i].x[k] - 0.01 * (double)k * pf[0]));
      ++*npts;
    }
    whirl_branch_free(br);
    whirl_cont_free(c);
  }
  whirl_fold_free(f);
  return worst;
}

/* The sparse branch-point curve's Jacobian (the rows of g and w^T F_q
 * worked out from base Jacobians, bp_row) against central differences
 * of its F, off the curve (apbp at x = 0.3, p = (0.2, 0.5, 0.1): neither
 * row vanishes, F_x depends on x, p1 and p2), with beta (column b) and
 * with a third parameter (p2). */
static void test_fold_bp_jacobian(void) {
  whirl_system gen = padded(apbp_F, 3, 1);
  for (int unfold = 0; unfold <= 1; ++unfold) {
    whirl_fold_options fo;
    whirl_fold_options_default(&fo, 0);
    fo.nfree = 2, fo.free[1] = 1, fo.cond = WHIRL_FOLD_COND_BP, fo.unfold = unfold;
    char err[256];
    whirl_fold *f = whirl_fold_alloc(&gen, &fo, err, sizeof err);
    const size_t n = NPAD, N = n + 2;
    double x0[NPAD], Z[NPAD + 2], p[3] = {0.2, 0.5, 0.1}, worst = INFINITY;
    double *Ja = malloc(N * N * sizeof *Ja), *Jd = malloc(N * N * sizeof *Jd),
           *work = malloc((2 * N + NPAD * 3 + 4 * N) * sizeof *work); /* max(2N, nnz) */
    x0[0] = 0.3;
    for (size_t k = 1; k < n; ++k) x0[k] = 0.01 * (double)k * p[0];
    if (f && Ja && Jd && work && whirl_fold_init(f, x0, p, Z) == WHIRL_OK) {
      if (unfold) Z[n + 1] = 0.1;
      const whirl_system *s = whirl_fold_system(f);
      if (whirl_system_jacobian(s, Z, p, Ja, work) == 0 &&
          whirl_system_fd_jacobian(s, Z, p, Jd, work) == 0) {
        worst = 0.0;
        size_t at = 0;
        for (size_t k = 0; k < N * N; ++k)
          if (fabs(Ja[k] - Jd[k]) > worst) worst = fabs(Ja[k] - Jd[k]), at = k;
        if (worst >= 1e-6) printf("# at row %zu column %zu: %.10g against %.10g\n", at % N,
                                  at / N, Ja[at], Jd[at]);
      }
    }
    ok(worst < 1e-6, "whirl_fold BP (sparse) %s: its Jacobian against differences of its F, "
       "max |diff| %.2g", unfold ? "with beta" : "with a third parameter", worst);
    /* its dF/dp_k in each parameter (the rows of g and h worked out,
     * bp_param; a freed one's column 0) against differences of its F */
    double wp = INFINITY, big = 0.0;
    const whirl_system *s = f ? whirl_fold_system(f) : NULL;
    if (s && s->Fp && isfinite(worst)) {
      wp = 0.0;
      for (size_t k = 0; k < 3; ++k)
        if (whirl_system_param(s, Z, p, k, Ja, work) != 0 ||
            whirl_system_fd_param(s, Z, p, k, Jd, work) != 0)
          wp = INFINITY;
        else
          for (size_t i = 0; i < N; ++i)
            wp = fmax(wp, fabs(Ja[i] - Jd[i])), big = fmax(big, fabs(Jd[i]));
    }
    ok(wp < 1e-6 && big > 0.1, "whirl_fold BP (sparse) %s: its dF/dp_k (Fp) against differences "
       "of its F, max |diff| %.2g (entries up to %.2g)", unfold ? "with beta" : "with a third "
       "parameter", wp, big);
    /* its structured solver (the Newton matrix by the factors of [F_x b;
     * c^T 0]) against UMFPACK on the assembled matrix, k the parameter
     * that is not freed */
    if (s) bsolver_check(unfold ? "whirl_fold BP (sparse) with beta" :
                         "whirl_fold BP (sparse) with a third parameter", s, Z, p,
                         unfold ? 1 : 2, 0);
    free(Ja), free(Jd), free(work);
    whirl_fold_free(f);
  }
}

static void test_fold_bp(int sparse) {
  const char *how = sparse ? "sparse, 121 unknowns" : "dense";
  size_t n = 0;
  whirl_fold_options fo;
  whirl_system sym = padded(sym_F, 2, sparse);
  whirl_fold_options_default(&fo, 0);
  fo.nfree = 2, fo.cond = WHIRL_FOLD_COND_BP, fo.unfold = 1;
  double ps[2] = {-0.5, 0.5};
  double d = follow_fold(&sym, &fo, 0.0, ps, 1, -2.0, 2.0, sym_dev, &n);
  ok(d < 1e-9 && n > 20, "whirl_fold BP (%s), symmetric x (p1 + p2 - x^2): x = 0, p1 = -p2, "
     "beta = 0 (%zu points, max dev %.2g)", how, n, d);
  whirl_system gen = padded(gen_F, 3, sparse);
  whirl_fold_options_default(&fo, 0);
  fo.nfree = 2, fo.free[1] = 1, fo.cond = WHIRL_FOLD_COND_BP;
  double pg[3] = {0.0, 0.25, 1.0};
  d = follow_fold(&gen, &fo, -0.5, pg, 2, -1.0, 3.0, gen_dev, &n);
  ok(d < 1e-8 && n > 20, "whirl_fold BP (%s), generic x^2 - p1^2 + p2 + p3 x: x = -p3/2, "
     "p1 = 0, p2 = p3^2/4 (%zu points, max dev %.2g)", how, n, d);
  whirl_system ap = padded(apbp_F, 3, sparse);
  for (int generic = 0; generic <= 1; ++generic) {
    whirl_fold_options_default(&fo, 0);
    fo.nfree = 2, fo.free[1] = 2, fo.cond = WHIRL_FOLD_COND_BP, fo.unfold = !generic;
    double pa[3] = {2.0, 2.0, 0.0};
    d = follow_fold(&ap, &fo, 2.0, pa, 1, -1.0, 5.0, apbp_dev, &n);
    ok(d < 1e-8 && n > 20, "whirl_fold BP (%s), apbp %s: u = p1 = p2, p3 = 0 (%zu points, "
       "max dev %.2g)", how, generic ? "generic" : "non-generic (beta)", n, d);
  }
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

  test_fold_bp(0);
  test_fold_bp(1);
  test_fold_bp_jacobian();
  whirl_fold_options fo;
  whirl_fold_options_default(&fo, 0);
  fo.unfold = 1;
  ok(whirl_fold_alloc(&gen, &fo, err, sizeof err) == NULL && strstr(err, "unfold"),
     "beta without the branch-point condition is refused: %s", err);
  return done_testing();
}

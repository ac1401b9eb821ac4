/* rotor/fe_hbm.c — the harmonic-balance system of a finite-element rotor
 * (whirl/rotor/fe_hbm.h): residual, dense analytic Jacobian, parameter
 * derivatives and the optional Hill spectrum, on the linear part of
 * fe_hbm_lin.c (condensed or not) and the AFT forces of fe_hbm_aft.c.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "config.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"

void whirl_fe_hbm_options_default(whirl_fe_hbm_options *o) {
  memset(o, 0, sizeof *o);
  o->harmonics = 5;
  o->nu = 1;
  o->stability = -1;
  o->hill_nev = 48;
  o->hill_cutoff = 3;
}

void whirl_fe_hbm_params(double Omega, double *p) {
  p[WHIRL_FE_P_OMEGA] = Omega;
  p[WHIRL_FE_P_UNBALANCE] = 1.0;
  p[WHIRL_FE_P_CLEARANCE] = 1.0;
  p[WHIRL_FE_P_VISCOSITY] = 1.0;
}

/* SI coefficients of the nonlinear DOFs from the unknowns. */
static void gather(const whirl_fe_hbm *h, const double *X, double *q) {
  int m = h->aft.m;
  for (int blk = 0; blk < h->L; ++blk)
    for (int j = 0; j < m; ++j)
      q[blk * m + j] = h->Ls * X[blk * h->b + h->lin.pos[j]];
}

/* The linear part at Omega; a singular held rotor (exactly at one of its
 * resonances) is recoverable: the core shortens its step. */
static int lin_at(whirl_fe_hbm *h, double Omega) {
  int rc = fe_lin_update(&h->lin, Omega);
  if (!rc) return 0;
  WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, rc, "%s",
               h->lin.err[0] ? h->lin.err : whirl_strerror(rc));
  return rc == WHIRL_ESINGULAR ? 1 : rc;
}

/* The forces at the parameters p (speed Omega_f for the AFT). */
static int forces(whirl_fe_hbm *h, const double *X, const double *p,
                  double Omega_f, double *f, double *J, int mode) {
  gather(h, X, h->q);
  fe_aft_set_scales(&h->aft, p[WHIRL_FE_P_CLEARANCE], p[WHIRL_FE_P_VISCOSITY]);
  return fe_aft_eval(&h->aft, h->q, Omega_f / h->o.nu, Omega_f, f, J, mode);
}

/* out = Z x (d = 0) or ∂Z/∂Ω x (d = 1) in the real form, per harmonic:
 * [Zr Zi; −Zi Zr] on (a, b). */
static void apply_z(const whirl_fe_hbm *h, const double *x, double *out,
                    int d) {
  int b = h->b;
  const double complex *Zall = d ? h->lin.dZ : h->lin.Z;
  for (int k = 0; k <= h->H; ++k) {
    const double complex *Z = Zall + (size_t)k * b * b;
    for (int i = 0; i < b; ++i) {
      if (k == 0) {
        double s = 0;
        for (int j = 0; j < b; ++j) s += creal(Z[i + (size_t)b * j]) * x[j];
        out[i] = s;
        continue;
      }
      const double *a = x + b * (2 * k - 1), *bs = x + b * 2 * k;
      double sa = 0, sb = 0;
      for (int j = 0; j < b; ++j) {
        double complex z = Z[i + (size_t)b * j];
        sa += creal(z) * a[j] + cimag(z) * bs[j];
        sb += -cimag(z) * a[j] + creal(z) * bs[j];
      }
      out[b * (2 * k - 1) + i] = sa;
      out[b * 2 * k + i] = sb;
    }
  }
}

/* out −= s · (the real form [Re g; −Im g] of a complex load in harmonic k) */
static void sub_load(const whirl_fe_hbm *h, int k, const double complex *g,
                     double s, double *out) {
  for (int i = 0; i < h->b; ++i) {
    out[h->b * (2 * k - 1) + i] -= s * creal(g[i]);
    out[h->b * 2 * k + i] += s * cimag(g[i]);
  }
}

/* out −= s · Pᵀ f (forces on the nonlinear DOFs, m L) */
static void sub_forces(const whirl_fe_hbm *h, const double *f, double s,
                       double *out) {
  int m = h->aft.m;
  for (int blk = 0; blk < h->L; ++blk)
    for (int j = 0; j < m; ++j) out[blk * h->b + h->lin.pos[j]] -= s * f[blk * m + j];
}

static int sys_F(const double *X, const double *p, double *F, void *data) {
  whirl_fe_hbm *h = data;
  double Omega = p[WHIRL_FE_P_OMEGA];
  int rc = lin_at(h, Omega);
  if (rc) return rc;
  if ((rc = forces(h, X, p, Omega, h->f, NULL, FE_AFT_FORCE))) return rc;
  apply_z(h, X, F, 0);
  for (int i = 0; i < h->n; ++i) F[i] *= h->Ls;
  for (int i = 0; i < h->b; ++i) F[i] -= h->lin.g0[i];
  sub_load(h, (int)h->o.nu, h->lin.gu, p[WHIRL_FE_P_UNBALANCE], F);
  sub_forces(h, h->f, 1.0, F);
  for (int i = 0; i < h->n; ++i) F[i] /= h->Fs;
  return 0;
}

static int sys_Fx(const double *X, const double *p, double *J, void *data) {
  whirl_fe_hbm *h = data;
  int rc = lin_at(h, p[WHIRL_FE_P_OMEGA]);
  if (rc) return rc;
  if ((rc = forces(h, X, p, p[WHIRL_FE_P_OMEGA], h->f, h->Jnl, FE_AFT_JAC)))
    return rc;
  size_t n = (size_t)h->n, b = (size_t)h->b;
  double s = h->Ls / h->Fs;
  memset(J, 0, n * n * sizeof *J);
  for (int k = 0; k <= h->H; ++k) {
    const double complex *Z = h->lin.Z + (size_t)k * b * b;
    size_t ra = k == 0 ? 0 : b * (2 * k - 1), rb = b * 2 * k;
    for (size_t j = 0; j < b; ++j)
      for (size_t i = 0; i < b; ++i) {
        double complex z = Z[i + b * j];
        if (k == 0) { J[i + n * j] = s * creal(z); continue; }
        J[ra + i + n * (ra + j)] = s * creal(z);
        J[ra + i + n * (rb + j)] = s * cimag(z);
        J[rb + i + n * (ra + j)] = -s * cimag(z);
        J[rb + i + n * (rb + j)] = s * creal(z);
      }
  }
  int m = h->aft.m;
  size_t ml = (size_t)m * h->L;
  for (size_t c = 0; c < ml; ++c)
    for (size_t r = 0; r < ml; ++r) {
      size_t R = (r / m) * b + h->lin.pos[r % m], C = (c / m) * b + h->lin.pos[c % m];
      J[R + n * C] -= s * h->Jnl[r + ml * c];
    }
  return 0;
}

/* dF/dp of the forces alone by central differences in p[k]. */
static int forces_dp(whirl_fe_hbm *h, const double *X, const double *p,
                     size_t k, double *out) {
  double pp[WHIRL_FE_NPAR];
  memcpy(pp, p, sizeof pp);
  double hstep = cbrt(DBL_EPSILON) * fmax(1.0, fabs(p[k]));
  int ml = h->aft.m * h->L, rc;
  pp[k] = p[k] + hstep;
  if ((rc = forces(h, X, pp, pp[WHIRL_FE_P_OMEGA], h->fp, NULL, FE_AFT_FORCE)))
    return rc;
  pp[k] = p[k] - hstep;
  if ((rc = forces(h, X, pp, pp[WHIRL_FE_P_OMEGA], h->fm, NULL, FE_AFT_FORCE)))
    return rc;
  for (int i = 0; i < ml; ++i) h->fp[i] = (h->fp[i] - h->fm[i]) / (2 * hstep);
  sub_forces(h, h->fp, 1.0, out);
  return 0;
}

static int sys_Fp(const double *X, const double *p, size_t k, double *fk,
                  void *data) {
  whirl_fe_hbm *h = data;
  int rc = lin_at(h, p[WHIRL_FE_P_OMEGA]);
  if (rc) return rc;
  memset(fk, 0, (size_t)h->n * sizeof *fk);
  if (k == WHIRL_FE_P_OMEGA) {
    apply_z(h, X, fk, 1);
    for (int i = 0; i < h->n; ++i) fk[i] *= h->Ls;
    sub_load(h, (int)h->o.nu, h->lin.dgu, p[WHIRL_FE_P_UNBALANCE], fk);
  } else if (k == WHIRL_FE_P_UNBALANCE) {
    sub_load(h, (int)h->o.nu, h->lin.gu, 1.0, fk);
  }
  if (k != WHIRL_FE_P_UNBALANCE && (rc = forces_dp(h, X, p, k, fk))) return rc;
  for (int i = 0; i < h->n; ++i) fk[i] /= h->Fs;
  return 0;
}

/* --------------------------------------------------------------- object */

static double smallest_clearance(const whirl_fe_rotor *r) {
  double c = 0;
  for (int e = 0; e < r->nnl; ++e) {
    double ce = r->nl[e].par.clearance;
    if (r->nl[e].kind != WHIRL_FE_CUBIC && ce > 0 && (c == 0 || ce < c)) c = ce;
  }
  return c > 0 ? c : 1e-3;
}

static double largest_kdiag(const whirl_fe_rotor *r) {
  double k = 0;
  for (int c = 0; c < r->K.n; ++c)
    for (int q = r->K.p[c]; q < r->K.p[c + 1]; ++q)
      if (r->K.i[q] == c) k = fmax(k, fabs(r->K.x[q]));
  return k > 0 ? k : 1.0;
}

static int check_options(const whirl_fe_rotor *r, const whirl_fe_hbm_options *o,
                         int *N, char *err, size_t errlen) {
  if (!r || r->ndof != 4 * r->nnode + 2 * r->npedestal || r->nnl < 1)
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "the rotor needs nonlinear elements and ndof = "
                        "4 nnode + 2 npedestal");
  if (o->stability < -1 || o->stability > 3 ||
      (o->stability >= 2 && o->hill_nev < 1) ||
      ((o->stability == 3 || o->stability == -1) &&
       !(o->hill_cutoff >= 1 && o->hill_cutoff <= 100)))
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "stability %d, hill_nev %zu, hill_cutoff %g: need -1, "
                        "0, 1, 2 or 3, hill_nev >= 1 for 2 and 3, 1 <= "
                        "hill_cutoff <= 100 for 3 and -1", o->stability, o->hill_nev,
                        o->hill_cutoff);
  if (o->harmonics < 1 || o->harmonics > 256 || o->nu < 1 ||
      o->nu > o->harmonics)
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "harmonics %zu, nu %u: need 1 <= nu <= harmonics <= 256",
                        o->harmonics, o->nu);
  int H = (int)o->harmonics;
  *N = (int)o->nsamples;
  if (*N == 0)
    for (*N = 32; *N < 6 * H + 1; *N *= 2) {}
  if (*N <= 2 * H)
    return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL,
                        "nsamples %d: need more than 2 H = %d", *N,
                        2 * H);
  return WHIRL_OK;
}

static void fill_system(whirl_fe_hbm *h) {
  static const char *const pnames[WHIRL_FE_NPAR] = {"Omega", "unbalance",
                                                    "clearance", "viscosity"};
  whirl_system *s = &h->sys;
  memset(s, 0, sizeof *s);
  s->name = h->o.uncondensed ? "fe-hbm-full" : "fe-hbm";
  s->n = (size_t)h->n;
  s->npar = WHIRL_FE_NPAR;
  s->F = sys_F;
  s->Fx = sys_Fx;
  s->Fp = sys_Fp;
  s->p_names = pnames;
  s->data = h;
  size_t hill = 2 * (size_t)h->r->ndof * (size_t)h->L;
  h->hill = h->o.stability;
  if (h->hill < 0) {
#ifdef WHIRL_HAVE_ARPACK
    /* a large rotor: the sparse method on its Craig-Bampton reduction,
     * whose error on the exponents that decide stability is below the
     * Hill truncation's own (doc/fe-hbm.md); the whole rotor's sparse
     * method where the reduction cannot be built (fe_hbm_hill.c) */
    h->hill = hill <= 1200 ? 1 : 3;
#else
    h->hill = hill <= 1200 ? 1 : 0;
#endif
  }
  if (h->hill >= 2 && hill < h->o.hill_nev + 4) h->hill = 1;
  if (h->hill > 0) {
    s->nspec = h->hill == 1 ? 2 * (size_t)h->r->ndof : h->o.hill_nev;
    s->spectrum = fe_hbm_spectrum;
    s->spectrum_kind = WHIRL_SPEC_MULTIPLIERS;
  }
}

whirl_fe_hbm *whirl_fe_hbm_alloc(const whirl_fe_rotor *r,
                                 const whirl_fe_hbm_options *o, char *errbuf,
                                 size_t errlen) {
  whirl_fe_hbm_options def;
  if (!o) { whirl_fe_hbm_options_default(&def); o = &def; }
  int N = 0, rc;
  if (check_options(r, o, &N, errbuf, errlen)) return NULL;
  whirl_fe_hbm *h = calloc(1, sizeof *h);
  if (!h) { WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "out of memory"); return NULL; }
  h->r = r;
  h->o = *o;
  h->H = (int)o->harmonics;
  h->L = 2 * h->H + 1;
  h->N = N;
  if (fe_aft_init(&h->aft, r, h->H, N, errbuf, errlen)) goto fail;
  if ((rc = fe_lin_init(&h->lin, r, !o->uncondensed, o->interior_lu, h->H, (int)o->nu,
                         &h->aft))) {
    WHIRL_ERRMSG(errbuf, errlen, rc, "%s", h->lin.err[0] ? h->lin.err : whirl_strerror(rc));
    goto fail;
  }
  h->b = h->lin.b;
  h->n = h->b * h->L;
  h->Ls = o->length_scale > 0 ? o->length_scale : smallest_clearance(r);
  h->Fs = o->force_scale > 0 ? o->force_scale : h->Ls * largest_kdiag(r);
  size_t ml = (size_t)h->aft.m * h->L;
  h->q = malloc(4 * ml * sizeof *h->q);
  h->Jnl = malloc(3 * ml * ml * sizeof *h->Jnl);
  h->qfull = malloc((size_t)r->ndof * h->L * sizeof *h->qfull);
  h->xsi = malloc((size_t)h->n * sizeof *h->xsi);
  if (!h->q || !h->Jnl || !h->qfull || !h->xsi) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "out of memory");
    goto fail;
  }
  h->f = h->q + ml;
  h->fp = h->f + ml;
  h->fm = h->fp + ml;
  fill_system(h);
  return h;
fail:
  whirl_fe_hbm_free(h);
  return NULL;
}

void whirl_fe_hbm_free(whirl_fe_hbm *h) {
  if (!h) return;
  fe_cb_free(&h->cb);
  fe_lin_free(&h->lin);
  fe_aft_free(&h->aft);
  free(h->q);
  free(h->Jnl);
  free(h->qfull);
  free(h->hill_start);
  free(h->hill_ws);
  free(h->hill_sel);
  free(h->xsi);
  free(h);
}

const whirl_system *whirl_fe_hbm_system(const whirl_fe_hbm *h) { return &h->sys; }
size_t whirl_fe_hbm_size(const whirl_fe_hbm *h) { return (size_t)h->n; }
const char *whirl_fe_hbm_errmsg(const whirl_fe_hbm *h) { return h->errmsg; }

const int *whirl_fe_hbm_nl_dofs(const whirl_fe_hbm *h, int *m) {
  if (m) *m = h->aft.m;
  return h->aft.dof;
}

/* lib/systems/hbm.c — constructor: harmonic balance with the alternating
 * frequency–time scheme (Cameron & Griffin, J. Appl. Mech. 56, 1989; Krack &
 * Gross 2019, ch. 2–3; paper §4.2).  The Fourier coefficients of the state
 * are the unknowns; the nonlinear force is evaluated in the time domain at M
 * equally spaced phases and projected back (trapezoidal rule = exact DFT for
 * trigonometric polynomials up to degree M/2), and so is its Jacobian:
 *   dF_h/dX_h' = Σ_j P_h(θ_j) f_x(t_j, x_j) B_h'(θ_j),
 * with B the basis (1, cos kθ, sin kθ) and P the projection weights.  The
 * derivative x' is exact in the frequency domain: for harmonic k,
 * (a, b)' = k w (b, −a).  Plain sums (O(L M) per component) rather than an
 * FFT: L = 2N + 1 is small for the problems of this field, and the sums keep
 * any M allowed.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/floquet.h>
#include <whirl/hbm.h>

#include "util/errmsg_impl.h"

struct whirl_hbm {
  const whirl_problem *prob;
  whirl_hbm_options o;
  size_t n, N, L, M, ncoef, size;
  int autonomous;       /* w is an unknown */
  double *scale;        /* n */
  int *mask;            /* n*n */
  double *B;            /* basis B[h*M + j] */
  double *P;            /* projection P[h*M + j] */
  double *xs, *fs;      /* M*n samples of x and f */
  double *G;            /* M*n*n Jacobian samples */
  double *Jd;           /* size*size dense Jacobian (sparse values gathered) */
  double *ck, *sk;      /* cos kθ_j, sin kθ_j for k = 0..2N: ck[k*M + j] */
  double *Cg, *Sg;      /* 2N+1: cosine and sine sums of one f_x entry */
  double *coef;         /* n*L unscaled coefficients */
  double *work;         /* 2n finite differences */
  int *Jp, *Ji;         /* compressed-column pattern */
  whirl_system sys;
  char errmsg[WHIRL_ERRMSG_SIZE]; /* last message (whirl_hbm_errmsg) */
};

void whirl_hbm_options_default(whirl_hbm_options *o) {
  memset(o, 0, sizeof *o);
  o->harmonics = 8;
  o->oversampling = 10;
  o->nu = 1;
  o->forcing_param = -1;
  o->floquet_rtol = 1e-11;
}

static double freq(const whirl_hbm *h, const double *X, const double *p) {
  if (h->autonomous) return X[h->ncoef];
  return p[h->o.forcing_param] / (double)h->o.nu;
}

double whirl_hbm_frequency(const whirl_hbm *h, const double *X,
                           const double *p) {
  return freq(h, X, p);
}

double whirl_hbm_period(const whirl_hbm *h, const double *X, const double *p) {
  return 2.0 * WHIRL_PI / freq(h, X, p);
}

/* Unscaled coefficients and the state samples x_j = Σ_h B_h(θ_j) coef_h. */
static void synthesize(whirl_hbm *h, const double *X) {
  const size_t n = h->n, L = h->L, M = h->M;
  for (size_t i = 0; i < n; ++i)
    for (size_t q = 0; q < L; ++q) h->coef[i * L + q] = X[i * L + q] * h->scale[i];
  for (size_t j = 0; j < M; ++j)
    for (size_t i = 0; i < n; ++i) {
      double s = 0.0;
      const double *c = h->coef + i * L;
      for (size_t q = 0; q < L; ++q) s += h->B[q * M + j] * c[q];
      h->xs[j * n + i] = s;
    }
}

static double sample_time(const whirl_hbm *h, size_t j, double w) {
  return h->o.t0 + 2.0 * WHIRL_PI * (double)j / ((double)h->M * w);
}

static int hbm_F(const double *X, const double *p, double *F, void *data) {
  whirl_hbm *h = data;
  const size_t n = h->n, L = h->L, M = h->M;
  const double w = freq(h, X, p);
  if (!(w > 0) || !isfinite(w)) return 1; /* recoverable: step back */
  synthesize(h, X);
  for (size_t j = 0; j < M; ++j) {
    int rc = h->prob->rhs(sample_time(h, j, w), h->xs + j * n, p, h->fs + j * n,
                          h->prob->data);
    if (rc != 0) return rc;
  }
  for (size_t i = 0; i < n; ++i) {
    const double *c = h->coef + i * L;
    double *R = F + i * L;
    for (size_t q = 0; q < L; ++q) {
      double s = 0.0;
      for (size_t j = 0; j < M; ++j) s += h->P[q * M + j] * h->fs[j * n + i];
      R[q] = -s;
    }
    for (size_t k = 1; k <= h->N; ++k) {
      R[2 * k - 1] += (double)k * w * c[2 * k];
      R[2 * k] -= (double)k * w * c[2 * k - 1];
    }
    for (size_t q = 0; q < L; ++q) R[q] /= h->scale[i];
  }
  if (h->autonomous) F[h->ncoef] = X[h->o.phase_component * L + 2];
  return 0;
}

/* Dense Jacobian J[size*size], column-major. */
static int hbm_Fx(const double *X, const double *p, double *J, void *data) {
  whirl_hbm *h = data;
  const size_t n = h->n, L = h->L, M = h->M, S = h->size;
  const double w = freq(h, X, p);
  if (!(w > 0) || !isfinite(w)) return 1;
  synthesize(h, X);
  for (size_t j = 0; j < M; ++j) {
    const double t = sample_time(h, j, w);
    double *Gj = h->G + j * n * n;
    int rc = h->prob->jac_x
                 ? h->prob->jac_x(t, h->xs + j * n, p, Gj, h->prob->data)
                 : whirl_fd_jac_x(h->prob, t, h->xs + j * n, p, Gj, h->work);
    if (rc != 0) return rc;
  }
  memset(J, 0, S * S * sizeof *J);
  /* Block (i, l) = −P diag(g(θ_j)) Bᵀ with g = ∂f_i/∂x_l.  With the sums
   * C_k = (1/M) Σ_j g_j cos kθ_j, S_k = (1/M) Σ_j g_j sin kθ_j (k <= 2N),
   * the product-to-sum identities give every entry exactly:
   *   (1, 1) C_0; (1, cos m) C_m; (1, sin m) S_m; (cos k, 1) 2C_k;
   *   (sin k, 1) 2S_k; (cos k, cos m) C_{k−m} + C_{k+m};
   *   (cos k, sin m) S_{m+k} + S_{m−k}; (sin k, cos m) S_{k+m} + S_{k−m};
   *   (sin k, sin m) C_{k−m} − C_{k+m}, with C_{−j} = C_j, S_{−j} = −S_j:
   * O(N M) per block instead of O(N² M). */
  const size_t N = h->N, K2 = 2 * N + 1;
  for (size_t l = 0; l < n; ++l)
    for (size_t i = 0; i < n; ++i) {
      if (!h->mask[i + n * l]) continue;
      for (size_t k = 0; k < K2; ++k) {
        const double *c = h->ck + k * M, *sn = h->sk + k * M;
        double a = 0.0, b = 0.0;
        for (size_t j = 0; j < M; ++j) {
          const double g = h->G[j * n * n + i + n * l];
          a += g * c[j];
          b += g * sn[j];
        }
        h->Cg[k] = a / (double)M;
        h->Sg[k] = b / (double)M;
      }
      const double *C = h->Cg, *Sv = h->Sg;
      const double sc = -h->scale[l] / h->scale[i];
#define HBM_C(d) (C[(d) < 0 ? -(d) : (d)])
#define HBM_S(d) ((d) < 0 ? -Sv[-(d)] : Sv[(d)])
#define HBM_J(q, q2) J[(l * L + (size_t)(q2)) * S + i * L + (size_t)(q)]
      HBM_J(0, 0) = sc * C[0];
      for (long m = 1; m <= (long)N; ++m) {
        HBM_J(0, 2 * m - 1) = sc * C[m];
        HBM_J(0, 2 * m) = sc * Sv[m];
        HBM_J(2 * m - 1, 0) = sc * 2.0 * C[m];
        HBM_J(2 * m, 0) = sc * 2.0 * Sv[m];
      }
      for (long k = 1; k <= (long)N; ++k)
        for (long m = 1; m <= (long)N; ++m) {
          HBM_J(2 * k - 1, 2 * m - 1) = sc * (HBM_C(k - m) + C[k + m]);
          HBM_J(2 * k - 1, 2 * m) = sc * (Sv[m + k] + HBM_S(m - k));
          HBM_J(2 * k, 2 * m - 1) = sc * (Sv[k + m] + HBM_S(k - m));
          HBM_J(2 * k, 2 * m) = sc * (HBM_C(k - m) - C[k + m]);
        }
#undef HBM_C
#undef HBM_S
#undef HBM_J
    }
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 1; k <= h->N; ++k) {
      const size_t ra = i * L + 2 * k - 1, rb = i * L + 2 * k;
      J[ra + S * rb] += (double)k * w;
      J[rb + S * ra] -= (double)k * w;
    }
  if (h->autonomous) {
    const size_t cw = h->ncoef;
    for (size_t i = 0; i < n; ++i) {
      const double *c = h->coef + i * L;
      for (size_t k = 1; k <= h->N; ++k) {
        J[i * L + 2 * k - 1 + S * cw] = (double)k * c[2 * k] / h->scale[i];
        J[i * L + 2 * k + S * cw] = -(double)k * c[2 * k - 1] / h->scale[i];
      }
    }
    J[h->ncoef + S * (h->o.phase_component * L + 2)] = 1.0;
  }
  return 0;
}

static int hbm_Fx_sparse(const double *X, const double *p, double *Jx,
                         void *data) {
  whirl_hbm *h = data;
  int rc = hbm_Fx(X, p, h->Jd, data);
  if (rc != 0) return rc;
  for (size_t c = 0; c < h->size; ++c)
    for (int q = h->Jp[c]; q < h->Jp[c + 1]; ++q)
      Jx[q] = h->Jd[(size_t)h->Ji[q] + h->size * c];
  return 0;
}

int whirl_hbm_multipliers(const whirl_hbm *h, const double *X, const double *p,
                          double *re, double *im, size_t *m, double *M,
                          char *errbuf, size_t errlen) {
  double x0[64];
  double *x = h->n <= 64 ? x0 : malloc(h->n * sizeof *x);
  if (!x)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM,
                        "hbm multipliers: out of memory");
  whirl_hbm_eval(h, X, 0.0, x);
  int rc = whirl_floquet_multipliers(h->prob, p, h->o.t0, x,
                                     whirl_hbm_period(h, X, p), h->autonomous,
                                     h->o.floquet_rtol, 0.0, re, im, m, M, NULL,
                                     errbuf, errlen);
  if (x != x0) free(x);
  return rc;
}

static int hbm_spectrum(const double *X, const double *p, const double *J,
                        double *re, double *im, size_t *m, void *data) {
  (void)J;
  whirl_hbm *h = data;
  int rc = whirl_hbm_multipliers(h, X, p, re, im, m, NULL, h->errmsg,
                                 sizeof h->errmsg);
  /* a trajectory that leaves the model's domain during the variational
   * integration is recoverable (the step is retried), as the model says */
  return rc;
}

/* Compressed-column pattern from the block mask; the diagonal blocks are
 * always present (the frequency-domain derivative couples a_k and b_k). */
static int build_pattern(whirl_hbm *h) {
  const size_t n = h->n, L = h->L, S = h->size;
  size_t nnz = 0;
  for (size_t l = 0; l < n; ++l) {
    size_t rows = 0;
    for (size_t i = 0; i < n; ++i) rows += h->mask[i + n * l] ? L : 0;
    nnz += rows * L;
  }
  if (h->autonomous) nnz += h->ncoef + 1; /* w column (all rows), phase row */
  h->Jp = malloc((S + 1) * sizeof *h->Jp);
  h->Ji = malloc(nnz * sizeof *h->Ji);
  if (!h->Jp || !h->Ji) return WHIRL_ENOMEM;
  size_t q = 0;
  for (size_t l = 0; l < n; ++l)
    for (size_t q2 = 0; q2 < L; ++q2) {
      const size_t c = l * L + q2;
      h->Jp[c] = (int)q;
      for (size_t i = 0; i < n; ++i)
        if (h->mask[i + n * l])
          for (size_t r = 0; r < L; ++r) h->Ji[q++] = (int)(i * L + r);
      if (h->autonomous && l == h->o.phase_component && q2 == 2)
        h->Ji[q++] = (int)h->ncoef;
    }
  if (h->autonomous) {
    h->Jp[h->ncoef] = (int)q;
    for (size_t r = 0; r < h->ncoef; ++r) h->Ji[q++] = (int)r;
  }
  h->Jp[S] = (int)q;
  h->sys.nnz = q;
  return WHIRL_OK;
}

whirl_hbm *whirl_hbm_alloc(const whirl_problem *prob,
                           const whirl_hbm_options *opt, char *errbuf,
                           size_t errlen) {
  whirl_hbm_options o;
  if (opt) o = *opt;
  else whirl_hbm_options_default(&o);
  if (errbuf && errlen) errbuf[0] = '\0';
#define HBM_BAD(...)                                         \
  do {                                                       \
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, __VA_ARGS__); \
    return NULL;                                             \
  } while (0)
  if (!prob || !prob->rhs || prob->n == 0) HBM_BAD("hbm: model is NULL or has no rhs");
  if (o.harmonics < 1 || o.harmonics > 1000)
    HBM_BAD("hbm: harmonics must be in 1..1000 (got %zu)", o.harmonics);
  if (o.oversampling < 1 || o.oversampling > 1000)
    HBM_BAD("hbm: oversampling must be in 1..1000 (got %zu)", o.oversampling);
  if (o.nu < 1) HBM_BAD("hbm: subharmonic index nu must be >= 1");
  if (o.forcing_param >= (int)prob->npar)
    HBM_BAD("hbm: forcing parameter %d out of range (model has %zu)",
            o.forcing_param, prob->npar);
  if (o.forcing_param < 0 && !prob->autonomous)
    HBM_BAD("hbm: model '%s' is not autonomous: name its forcing-frequency "
            "parameter", prob->name ? prob->name : "?");
  if (o.forcing_param < 0 && o.phase_component >= prob->n)
    HBM_BAD("hbm: phase component %zu out of range (n = %zu)",
            o.phase_component, prob->n);
  if (o.scale)
    for (size_t i = 0; i < prob->n; ++i)
      if (!(o.scale[i] > 0) || !isfinite(o.scale[i]))
        HBM_BAD("hbm: scale[%zu] = %g must be positive", i, o.scale[i]);
#undef HBM_BAD
  if (o.floquet_rtol <= 0) o.floquet_rtol = 1e-11;
  whirl_hbm *h = calloc(1, sizeof *h);
  if (!h) return NULL;
  h->prob = prob;
  h->o = o;
  h->o.scale = NULL;
  h->o.fx_mask = NULL;
  const size_t n = prob->n, N = o.harmonics, L = 2 * N + 1;
  h->n = n, h->N = N, h->L = L, h->M = o.oversampling * L;
  h->autonomous = o.forcing_param < 0;
  h->ncoef = n * L;
  h->size = h->ncoef + (size_t)h->autonomous;
  const size_t M = h->M, S = h->size;
  h->scale = malloc(n * sizeof *h->scale);
  h->mask = malloc(n * n * sizeof *h->mask);
  h->B = malloc(L * M * sizeof *h->B);
  h->P = malloc(L * M * sizeof *h->P);
  h->xs = malloc(M * n * sizeof *h->xs);
  h->fs = malloc(M * n * sizeof *h->fs);
  h->G = malloc(M * n * n * sizeof *h->G);
  h->Jd = malloc(S * S * sizeof *h->Jd);
  h->ck = malloc((2 * N + 1) * M * sizeof *h->ck);
  h->sk = malloc((2 * N + 1) * M * sizeof *h->sk);
  h->Cg = malloc((2 * N + 1) * sizeof *h->Cg);
  h->Sg = malloc((2 * N + 1) * sizeof *h->Sg);
  h->coef = malloc(n * L * sizeof *h->coef);
  h->work = malloc(2 * n * sizeof *h->work);
  if (!h->scale || !h->mask || !h->B || !h->P || !h->xs || !h->fs || !h->G ||
      !h->Jd || !h->coef || !h->work || !h->ck || !h->sk || !h->Cg ||
      !h->Sg) {
    whirl_hbm_free(h);
    return NULL;
  }
  for (size_t i = 0; i < n; ++i) h->scale[i] = opt && opt->scale ? opt->scale[i] : 1.0;
  for (size_t q = 0; q < n * n; ++q)
    h->mask[q] = opt && opt->fx_mask ? opt->fx_mask[q] != 0 : 1;
  for (size_t i = 0; i < n; ++i) h->mask[i + n * i] = 1;
  for (size_t k = 0; k <= 2 * N; ++k)
    for (size_t j = 0; j < M; ++j) {
      /* exact reduction of kj mod M keeps the angles accurate */
      const double th = 2.0 * WHIRL_PI * (double)((k * j) % M) / (double)M;
      h->ck[k * M + j] = cos(th);
      h->sk[k * M + j] = sin(th);
    }
  for (size_t j = 0; j < M; ++j) {
    const double th = 2.0 * WHIRL_PI * (double)j / (double)M;
    h->B[j] = 1.0;
    h->P[j] = 1.0 / (double)M;
    for (size_t k = 1; k <= N; ++k) {
      const double ck = cos((double)k * th), sk = sin((double)k * th);
      h->B[(2 * k - 1) * M + j] = ck;
      h->B[(2 * k) * M + j] = sk;
      h->P[(2 * k - 1) * M + j] = 2.0 * ck / (double)M;
      h->P[(2 * k) * M + j] = 2.0 * sk / (double)M;
    }
  }
  if (build_pattern(h) != WHIRL_OK) {
    whirl_hbm_free(h);
    return NULL;
  }
  whirl_system *s = &h->sys;
  s->name = prob->name;
  s->n = S;
  s->npar = prob->npar;
  s->F = hbm_F;
  s->Fx = hbm_Fx;
  s->Fp = NULL; /* central differences of F in the core */
  s->Jp = h->Jp;
  s->Ji = h->Ji;
  s->Fx_sparse = hbm_Fx_sparse;
  if (!o.no_spectrum) {
    s->nspec = h->autonomous ? n - 1 : n;
    s->spectrum = hbm_spectrum;
    s->spectrum_kind = WHIRL_SPEC_MULTIPLIERS;
  }
  s->p_names = prob->p_names;
  s->data = h;
  return h;
}

void whirl_hbm_free(whirl_hbm *h) {
  if (!h) return;
  free(h->scale);
  free(h->mask);
  free(h->B);
  free(h->P);
  free(h->xs);
  free(h->fs);
  free(h->G);
  free(h->Jd);
  free(h->ck);
  free(h->sk);
  free(h->Cg);
  free(h->Sg);
  free(h->coef);
  free(h->work);
  free(h->Jp);
  free(h->Ji);
  free(h);
}

const whirl_system *whirl_hbm_system(const whirl_hbm *h) { return &h->sys; }
const char *whirl_hbm_errmsg(const whirl_hbm *h) {
  return h ? h->errmsg : "whirl_hbm: NULL object";
}
size_t whirl_hbm_size(const whirl_hbm *h) { return h->size; }
size_t whirl_hbm_dim(const whirl_hbm *h) { return h->n; }

int whirl_hbm_from_samples(whirl_hbm *h, const double *x, size_t m, double T,
                           double *X) {
  const size_t n = h->n, L = h->L, N = h->N;
  if (!x || !X)
    return WHIRL_FAIL(h, WHIRL_EINVAL, "hbm from_samples: NULL samples or X");
  if (m < L)
    return WHIRL_FAIL(h, WHIRL_EINVAL,
                      "hbm from_samples: need m >= 2N + 1 "
                      "= %zu samples (got %zu)",
                      L, m);
  if (h->autonomous && !(T > 0))
    return WHIRL_FAIL(h, WHIRL_EINVAL,
                      "hbm from_samples: an autonomous "
                      "orbit needs a period T > 0 (got %g)",
                      T);
  memset(X, 0, h->size * sizeof *X);
  for (size_t k = 0; k < m; ++k) {
    const double th = 2.0 * WHIRL_PI * (double)k / (double)m;
    for (size_t i = 0; i < n; ++i) {
      const double v = x[k * n + i] / h->scale[i];
      X[i * L] += v / (double)m;
      for (size_t q = 1; q <= N; ++q) {
        X[i * L + 2 * q - 1] += 2.0 * v * cos((double)q * th) / (double)m;
        X[i * L + 2 * q] += 2.0 * v * sin((double)q * th) / (double)m;
      }
    }
  }
  if (h->autonomous) X[h->ncoef] = 2.0 * WHIRL_PI / T;
  return WHIRL_OK;
}

void whirl_hbm_set_phase(const whirl_hbm *h, double *X) {
  if (!h->autonomous) return;
  const size_t L = h->L, j = h->o.phase_component;
  const double phi = atan2(X[j * L + 2], X[j * L + 1]);
  for (size_t i = 0; i < h->n; ++i)
    for (size_t k = 1; k <= h->N; ++k) {
      double *a = X + i * L + 2 * k - 1, *b = a + 1;
      const double c = cos((double)k * phi), s = sin((double)k * phi);
      const double na = *a * c + *b * s, nb = *b * c - *a * s;
      *a = na, *b = nb;
    }
  X[j * L + 2] = 0.0;
}

void whirl_hbm_eval(const whirl_hbm *h, const double *X, double theta,
                    double *x) {
  const size_t L = h->L;
  for (size_t i = 0; i < h->n; ++i) {
    const double *c = X + i * L;
    double s = c[0];
    for (size_t k = 1; k <= h->N; ++k)
      s += c[2 * k - 1] * cos((double)k * theta) + c[2 * k] * sin((double)k * theta);
    x[i] = s * h->scale[i];
  }
}

int whirl_hbm_time_residual(whirl_hbm *h, const double *X, const double *p,
                            size_t K, double *res) {
  const size_t n = h->n, L = h->L, m = (K ? K : 1) * h->M;
  const double w = freq(h, X, p);
  double *buf = malloc(3 * n * sizeof *buf);
  if (!buf)
    return WHIRL_FAIL(h, WHIRL_ENOMEM, "hbm time residual: out of memory");
  double *x = buf, *dx = buf + n, *f = buf + 2 * n, worst = 0.0;
  int rc = 0;
  for (size_t j = 0; j < m && rc == 0; ++j) {
    const double th = 2.0 * WHIRL_PI * (double)j / (double)m;
    whirl_hbm_eval(h, X, th, x);
    for (size_t i = 0; i < n; ++i) {
      const double *c = X + i * L;
      double s = 0.0;
      for (size_t k = 1; k <= h->N; ++k)
        s += (double)k * (-c[2 * k - 1] * sin((double)k * th) +
                          c[2 * k] * cos((double)k * th));
      dx[i] = w * s * h->scale[i];
    }
    rc = h->prob->rhs(h->o.t0 + th / w, x, p, f, h->prob->data);
    for (size_t i = 0; i < n && rc == 0; ++i) worst = fmax(worst, fabs(dx[i] - f[i]));
  }
  free(buf);
  if (rc != 0)
    return WHIRL_FAIL(h, rc, "hbm time residual: the model's rhs returned %d",
                      rc);
  *res = worst;
  return rc;
}

/* ---- measures of the orbit ----------------------------------------------- */

/* Component i of the series at θ and its first two θ-derivatives. */
static void series_derivs(const whirl_hbm *h, const double *c, double th,
                          double *u, double *du, double *ddu) {
  double s = c[0], d1 = 0.0, d2 = 0.0;
  for (size_t k = 1; k <= h->N; ++k) {
    const double kk = (double)k, ck = cos(kk * th), sk = sin(kk * th);
    const double a = c[2 * k - 1], b = c[2 * k];
    s += a * ck + b * sk;
    d1 += kk * (b * ck - a * sk);
    d2 -= kk * kk * (a * ck + b * sk);
  }
  *u = s, *du = d1, *ddu = d2;
}

/* The samples the measures take: 8 per degree of freedom of the series. */
static size_t measure_samples(const whirl_hbm *h) { return 8 * (2 * h->N + 1); }

int whirl_hbm_max(const whirl_hbm *h, const double *X, double *mx) {
  if (!h || !X || !mx) return WHIRL_EINVAL;
  const size_t L = h->L, m = measure_samples(h);
  const double step = 2.0 * WHIRL_PI / (double)m;
  for (size_t i = 0; i < h->n; ++i) {
    const double *c = X + i * L;
    double best = -HUGE_VAL, arg = 0.0, u, du, ddu;
    for (size_t k = 0; k < m; ++k) {
      series_derivs(h, c, step * (double)k, &u, &du, &ddu);
      if (u > best) best = u, arg = step * (double)k;
    }
    /* Newton on u'(θ) = 0 from the best sample: the maximum of the
     * trigonometric polynomial, not of its samples (they fall short by up
     * to (step/2)² |u''| / 2) */
    double th = arg;
    for (int it = 0; it < 30; ++it) {
      series_derivs(h, c, th, &u, &du, &ddu);
      if (!(ddu < 0.0)) break;
      const double d = du / ddu;
      th -= d;
      if (fabs(th - arg) > step) break; /* left the sample's neighbourhood */
      if (fabs(d) < 1e-15) break;
    }
    series_derivs(h, c, th, &u, &du, &ddu);
    if (fabs(th - arg) <= step && u > best) best = u;
    mx[i] = best * h->scale[i];
  }
  return WHIRL_OK;
}

double whirl_hbm_l2norm(const whirl_hbm *h, const double *X) {
  const size_t m = measure_samples(h), n = h->n;
  double l2 = 0.0, *v = malloc(n * sizeof *v);
  if (!v) return NAN;
  for (size_t k = 0; k < m; k++) {
    whirl_hbm_eval(h, X, 2.0 * WHIRL_PI * (double)k / (double)m, v);
    double s = 0.0;
    for (size_t i = 0; i < n; i++) s += v[i] * v[i];
    l2 += s / (double)m;
  }
  free(v);
  return sqrt(l2);
}

/* rotor/jeffcott.c — a Jeffcott (flexible) rotor on two identical short
 * squeeze-film dampers, a model of the rotor module (`model = jeffcott` in
 * run files, whirl_rotor_jeffcott), written against libwhirl's public API
 * only (the damper force is whirl_sfd_force of the rigid-rotor model).  Derivation, scaling and checks:
 * doc/jeffcott-model.md.
 *
 * A disc of mass m_d at mid-span of a massless shaft (stiffness k_s at the
 * disc), two journals of mass m_j at the shaft ends, each in a π-film SFD
 * with a centring (retainer) spring k_r; unbalance at the disc; symmetric,
 * so both journals move together.  With m = m_d + 2 m_j and the rigid-rotor
 * scales (c, ω_n = sqrt(2 k_r / m), τ = ω_n t, λ = ηR/sqrt(2 k_r m) (L/c)^3):
 *
 *   α y_d'' + 2ζ y_d' + (κ/2)(y_d − y_j)            = δ Ω² cos Ωτ
 *   α z_d'' + 2ζ z_d' + (κ/2)(z_d − z_j)            = δ Ω² sin Ωτ
 *   (1−α) y_j'' + y_j − (κ/2)(y_d − y_j)            = f_y(y_j, z_j, y_j', z_j')
 *   (1−α) z_j'' + z_j − (κ/2)(z_d − z_j)            = f_z(...)
 *
 * p = (Omega, lambda, delta, zeta, alpha, kappa):
 *   Omega  ω/ω_n; lambda as whirl_sfd_force; delta = m_d e_d/(m c) (the
 *   whole rotor's mass-centre eccentricity over c, the paper's e_G/c: the
 *   disc's own eccentricity is e_d = delta c / alpha); zeta = b/(2 sqrt(2 k_r
 *   m)) with b an external damper at the DISC; alpha = m_d/m in (0, 1);
 *   kappa = k_s/k_r > 0.
 * Rigid limit κ → ∞: y_d = y_j = y and the sum of the equations is the
 * rigid rotor of whirl_sfd_fixed() (same Ω, λ, δ, ζ, F_E = 0).
 *
 * x = (y_d, z_d, y_j, z_j, y_d', z_d', y_j', z_j'), fixed frame, forced at
 * the frequency p[0].  ε = |(y_j, z_j)| >= 1 (journal on the housing) is
 * WHIRL_SFD_CONTACT (recoverable), as in the rigid-rotor model; alpha outside
 * (0, 1) or kappa <= 0 is JEFFCOTT_PARAM_DOMAIN (recoverable as well, so a
 * continuation in alpha or kappa ends at the edge instead of failing);
 * non-finite t or parameters are WHIRL_EINVAL (fatal).
 *
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>

#include <whirl/model.h>
#include <whirl/rotor.h>

enum { J_OMEGA, J_LAMBDA, J_DELTA, J_ZETA, J_ALPHA, J_KAPPA, J_NPAR };
#define J_N 8

/* Returned for alpha outside (0, 1) or kappa <= 0 (recoverable, > 0). */
#define JEFFCOTT_PARAM_DOMAIN 2

static int jeffcott_check(double t, const double *p) {
  if (!isfinite(t)) return WHIRL_EINVAL;
  for (int k = 0; k < J_NPAR; ++k)
    if (!isfinite(p[k])) return WHIRL_EINVAL;
  if (!(p[J_ALPHA] > 0.0 && p[J_ALPHA] < 1.0) || !(p[J_KAPPA] > 0.0))
    return JEFFCOTT_PARAM_DOMAIN;
  return WHIRL_OK;
}

static int jeffcott_rhs(double t, const double *x, const double *p, double *f,
                        void *data) {
  (void)data;
  int rc = jeffcott_check(t, p);
  if (rc != 0) return rc;
  double fd[2];
  rc = whirl_sfd_force(x[2], x[3], x[6], x[7], p[J_LAMBDA], fd, NULL, NULL);
  if (rc != 0) return rc;
  const double Om = p[J_OMEGA], ze = p[J_ZETA], al = p[J_ALPHA];
  const double hk = 0.5 * p[J_KAPPA], be = 1.0 - al;
  const double u = p[J_DELTA] * Om * Om, ph = Om * t;
  const double sy = hk * (x[0] - x[2]), sz = hk * (x[1] - x[3]); /* shaft */
  f[0] = x[4];
  f[1] = x[5];
  f[2] = x[6];
  f[3] = x[7];
  f[4] = (-2.0 * ze * x[4] - sy + u * cos(ph)) / al;
  f[5] = (-2.0 * ze * x[5] - sz + u * sin(ph)) / al;
  f[6] = (-x[2] + sy + fd[0]) / be;
  f[7] = (-x[3] + sz + fd[1]) / be;
  return WHIRL_OK;
}

/* column-major J[i + 8 j] = d f_i / d x_j */
static int jeffcott_jac_x(double t, const double *x, const double *p,
                          double *J, void *data) {
  (void)data;
  int rc = jeffcott_check(t, p);
  if (rc != 0) return rc;
  double fd[2], Jf[8];
  rc = whirl_sfd_force(x[2], x[3], x[6], x[7], p[J_LAMBDA], fd, Jf, NULL);
  if (rc != 0) return rc;
  const double ze = p[J_ZETA], al = p[J_ALPHA], be = 1.0 - al;
  const double hk = 0.5 * p[J_KAPPA];
  for (int i = 0; i < J_N * J_N; ++i) J[i] = 0.0;
  for (int i = 0; i < 4; ++i) J[i + J_N * (i + 4)] = 1.0;
  for (int c = 0; c < 2; ++c) { /* c = 0: y, c = 1: z */
    const int rd = 4 + c, rj = 6 + c;
    /* disc: (−2ζ v_d − (κ/2)(d − j)) / α */
    J[rd + J_N * c] = -hk / al;
    J[rd + J_N * (2 + c)] = hk / al;
    J[rd + J_N * (4 + c)] = -2.0 * ze / al;
    /* journal: (−j + (κ/2)(d − j) + f(j, v_j)) / (1 − α) */
    J[rj + J_N * c] = hk / be;
    J[rj + J_N * (2 + c)] = (-1.0 - hk) / be;
  }
  /* damper force: d f / d(y_j, z_j, y_j', z_j') = Jf (2 x 4, column-major) */
  static const int col[4] = {2, 3, 6, 7};
  for (int k = 0; k < 4; ++k) {
    J[6 + J_N * col[k]] += Jf[0 + 2 * k] / be;
    J[7 + J_N * col[k]] += Jf[1 + 2 * k] / be;
  }
  return WHIRL_OK;
}

/* column-major J[i + 8 k] = d f_i / d p_k */
static int jeffcott_jac_p(double t, const double *x, const double *p,
                          double *J, void *data) {
  (void)data;
  int rc = jeffcott_check(t, p);
  if (rc != 0) return rc;
  double fd[2], dl[2];
  rc = whirl_sfd_force(x[2], x[3], x[6], x[7], p[J_LAMBDA], fd, NULL, dl);
  if (rc != 0) return rc;
  const double Om = p[J_OMEGA], de = p[J_DELTA], ze = p[J_ZETA];
  const double al = p[J_ALPHA], be = 1.0 - al, hk = 0.5 * p[J_KAPPA];
  const double c = cos(Om * t), s = sin(Om * t), u = de * Om * Om;
  const double dy = x[0] - x[2], dz = x[1] - x[3];
  for (int i = 0; i < J_N * J_NPAR; ++i) J[i] = 0.0;
  /* Ω: d/dΩ of δΩ²(cos Ωτ, sin Ωτ) / α */
  J[4 + J_N * J_OMEGA] = de * Om * (2.0 * c - Om * t * s) / al;
  J[5 + J_N * J_OMEGA] = de * Om * (2.0 * s + Om * t * c) / al;
  J[6 + J_N * J_LAMBDA] = dl[0] / be;
  J[7 + J_N * J_LAMBDA] = dl[1] / be;
  J[4 + J_N * J_DELTA] = Om * Om * c / al;
  J[5 + J_N * J_DELTA] = Om * Om * s / al;
  J[4 + J_N * J_ZETA] = -2.0 * x[4] / al;
  J[5 + J_N * J_ZETA] = -2.0 * x[5] / al;
  /* α: disc rows are A/α, journal rows B/(1 − α) */
  J[4 + J_N * J_ALPHA] = -(-2.0 * ze * x[4] - hk * dy + u * c) / (al * al);
  J[5 + J_N * J_ALPHA] = -(-2.0 * ze * x[5] - hk * dz + u * s) / (al * al);
  J[6 + J_N * J_ALPHA] = (-x[2] + hk * dy + fd[0]) / (be * be);
  J[7 + J_N * J_ALPHA] = (-x[3] + hk * dz + fd[1]) / (be * be);
  /* κ */
  J[4 + J_N * J_KAPPA] = -0.5 * dy / al;
  J[5 + J_N * J_KAPPA] = -0.5 * dz / al;
  J[6 + J_N * J_KAPPA] = 0.5 * dy / be;
  J[7 + J_N * J_KAPPA] = 0.5 * dz / be;
  return WHIRL_OK;
}

static const char *const jeffcott_x_names[J_N] = {"yd",  "zd",  "yj",  "zj",
                                                  "dyd", "dzd", "dyj", "dzj"};
static const char *const jeffcott_p_names[J_NPAR] = {"Omega", "lambda", "delta",
                                                     "zeta",  "alpha",  "kappa"};

/* λ and δ of the paper's Table 1, the disc half the rotor mass, a shaft ten
 * times as stiff as one retainer spring, and a little external damping at
 * the disc (ζ = 0.05): without it the lock-up branch (journal near the
 * housing, disc through its pinned-pinned critical speed √(κ/2α)) has no
 * bound on the disc amplitude (doc/jeffcott-model.md §6). */
static const double jeffcott_par0[J_NPAR] = {1.0, 0.0503, 0.3, 0.05, 0.5, 10.0};
static const double jeffcott_u0[J_N] = {0, 0, 0, 0, 0, 0, 0, 0};
/* displacements in clearances, velocities in clearances per 1/ω_n */
static const double jeffcott_scale[J_N] = {1, 1, 1, 1, 1, 1, 1, 1};

static const whirl_model jeffcott_model = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "jeffcott",
                .n = J_N,
                .npar = J_NPAR,
                .rhs = jeffcott_rhs,
                .jac_x = jeffcott_jac_x,
                .jac_p = jeffcott_jac_p,
                .autonomous = 0,
                .x_names = jeffcott_x_names,
                .p_names = jeffcott_p_names,
                .data = NULL},
    .par0 = jeffcott_par0,
    .u0 = jeffcott_u0,
    .stpnt = NULL,
    .period0 = 0.0,
    .forcing_param = J_OMEGA,
    .scale = jeffcott_scale,
    .description = "Jeffcott rotor (disc on a flexible shaft) on two short "
                   "pi-film squeeze-film dampers, fixed frame, forced"};

const whirl_model *whirl_rotor_jeffcott(void) { return &jeffcott_model; }

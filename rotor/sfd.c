/* rotor/sfd.c — the rigid rotor on two short squeeze-film dampers
 * (paper eqs. 1–14, dimensionless as in eqs. 9–14): the π-film force of
 * eq. 8 in a Cartesian form that is exact at ε = 0, its analytic Jacobians,
 * and the fixed-frame and rotating-frame models with analytic jac_x, jac_p.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>

#include <whirl/rotor/sfd.h>

/* ------------------------------------------------------------------------
 * Parameters.  The check's message is its answer, for the user, so it has
 * no source location (unlike the error messages, whirl/status.h). */

void whirl_sfd_default_params(double *p) {
  if (p == NULL) return;
  p[WHIRL_SFD_OMEGA] = 1.0;
  p[WHIRL_SFD_LAMBDA] = 0.0503; /* Table 1 */
  p[WHIRL_SFD_DELTA] = 0.3;     /* Table 1 */
  p[WHIRL_SFD_ZETA] = 0.0;      /* Fig. 3: no external damping */
  p[WHIRL_SFD_FE] = 0.0;        /* perfectly centred damper (§4.1 (iii)) */
}

static const char *const sfd_p_names[WHIRL_SFD_NPAR] = {"Omega", "lambda",
                                                        "delta", "zeta", "FE"};

static int param_fail(char *msg, size_t len, const char *name, const char *rule,
                      double got) {
  if (msg != NULL && len > 0)
    snprintf(msg, len, "%s must be %s (got %g)", name, rule, got);
  return WHIRL_EINVAL;
}

int whirl_sfd_check_params(const double *p, char *msg, size_t len) {
  if (msg != NULL && len > 0) msg[0] = '\0';
  if (p == NULL) {
    if (msg != NULL && len > 0) snprintf(msg, len, "parameter vector is NULL");
    return WHIRL_EINVAL;
  }
  for (int k = 0; k < WHIRL_SFD_NPAR; ++k)
    if (!isfinite(p[k])) return param_fail(msg, len, sfd_p_names[k], "finite", p[k]);
  /* the rules, with the limits of whirl/rotor/sfd.h in the messages */
  char rule[64];
  snprintf(rule, sizeof rule, "in [0, %g]", WHIRL_SFD_OMEGA_MAX);
  if (!(p[WHIRL_SFD_OMEGA] >= 0.0 && p[WHIRL_SFD_OMEGA] <= WHIRL_SFD_OMEGA_MAX))
    return param_fail(msg, len, "Omega", rule, p[WHIRL_SFD_OMEGA]);
  snprintf(rule, sizeof rule, "in (0, %g]", WHIRL_SFD_LAMBDA_MAX);
  if (!(p[WHIRL_SFD_LAMBDA] > 0.0 && p[WHIRL_SFD_LAMBDA] <= WHIRL_SFD_LAMBDA_MAX))
    return param_fail(msg, len, "lambda", rule, p[WHIRL_SFD_LAMBDA]);
  snprintf(rule, sizeof rule, "in [0, %g]", WHIRL_SFD_DELTA_MAX);
  if (!(p[WHIRL_SFD_DELTA] >= 0.0 && p[WHIRL_SFD_DELTA] <= WHIRL_SFD_DELTA_MAX))
    return param_fail(msg, len, "delta", rule, p[WHIRL_SFD_DELTA]);
  snprintf(rule, sizeof rule, "in [0, %g]", WHIRL_SFD_ZETA_MAX);
  if (!(p[WHIRL_SFD_ZETA] >= 0.0 && p[WHIRL_SFD_ZETA] <= WHIRL_SFD_ZETA_MAX))
    return param_fail(msg, len, "zeta", rule, p[WHIRL_SFD_ZETA]);
  if (!(fabs(p[WHIRL_SFD_FE]) < 1.0))
    return param_fail(msg, len, "FE", "in (-1, 1): a static force |FE| >= 1 "
                      "puts the journal on the housing", p[WHIRL_SFD_FE]);
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * π-film force (eq. 8, both dampers, scaled by 2/(m c ω_n²); DESIGN.md)
 *
 * With r = (y, z), v = (y', z'), ε = |r|, s = 1 − ε², r̂ = r/ε, t̂ = (−ẑ, ŷ),
 * ε' = r̂·v, εγ' = t̂·v and A = (π/2)(1+2ε²)s^{-5/2}, B = 2ε s^{-2},
 * C = (π/2)s^{-3/2}, the force f = f_r r̂ + f_t t̂ of DESIGN.md is
 *   f = −2λ [ A (r̂·v) r̂ + B ((t̂·v) r̂ + (r̂·v) t̂) + C (t̂·v) t̂ ].
 * Since r̂r̂ᵀ + t̂t̂ᵀ = I and A − C = (3π/2) ε² s^{-5/2}, this is
 *   f = −πλ [ s^{-3/2} v + 3 s^{-5/2} (r·v) r + (4/π) ε s^{-2} M(r̂) v ],
 *   M(r̂) = r̂t̂ᵀ + t̂r̂ᵀ = [[−2ŷẑ, ŷ²−ẑ²], [ŷ²−ẑ², 2ŷẑ]],
 * the form computed below.  The first two terms have coefficients that are
 * smooth functions of ε² and give f = (−πλ) v to the last bit at ε = 0.
 * The third (the π-film cross coupling B, from cavitation) depends on the
 * direction r̂ through 2γ and has size 4λε|v|: it is continuous at ε = 0 but
 * NOT differentiable there when v ≠ 0 (f_y = −4λ|y| s^{-2} along r = (y, 0),
 * v = (0, 1)).  At ε = 0 exactly we return its symmetric derivative, zero:
 * the mean of its one-sided derivatives along any line through 0, and what
 * central differences give.  For ε > 0 the Jacobian is the exact derivative
 * (its position part has a direction-dependent O(λ|v|) piece as ε → 0). */

int whirl_sfd_force(double y, double z, double vy, double vz, double lambda,
                    double *f, double *J, double *dl) {
  if (f == NULL) return WHIRL_EINVAL;
  if (!isfinite(y) || !isfinite(z) || !isfinite(vy) || !isfinite(vz) ||
      !isfinite(lambda))
    return WHIRL_EINVAL;
  /* |r| < 1 in the domain (and sqrt is several times cheaper than hypot,
   * which guards against an overflow that cannot happen here) */
  const double eps = sqrt(y * y + z * z);
  if (eps >= 1.0) return WHIRL_SFD_CONTACT;
  /* f = −πλ T with T = s^{-3/2} v + 3 s^{-5/2} (r·v) r + (4/π) ε s^{-2} M(r̂) v,
   * so that at ε = 0 (s = 1) f = (−πλ) v to the last bit. */
  const double e2 = eps * eps;
  const double s = (1.0 - eps) * (1.0 + eps); /* 1 − ε², accurate near ε = 1 */
  const double s1 = 1.0 / s, rs = 1.0 / sqrt(s);
  const double C = s1 * rs;                   /* s^{-3/2} */
  const double K = 3.0 * s1 * s1 * rs;        /* 3 s^{-5/2} */
  const double rv = y * vy + z * vz;          /* r·v = ε ε' */

  /* unit vectors; the cross term vanishes at ε = 0 */
  double yh = 0.0, zh = 0.0, g1 = 0.0, g2 = 0.0, c3 = 0.0, m11 = 0.0, m12 = 0.0;
  if (eps > 0.0) {
    yh = y / eps;
    zh = z / eps;
    m11 = -2.0 * yh * zh;
    m12 = (yh - zh) * (yh + zh);
    g1 = m11 * vy + m12 * vz; /* ĝ = M(r̂) v */
    g2 = m12 * vy - m11 * vz;
    c3 = (4.0 / WHIRL_PI) * eps * s1 * s1; /* (4/π) ε s^{-2} = 2B/π */
  }
  const double T1 = C * vy + K * rv * y + c3 * g1;
  const double T2 = C * vz + K * rv * z + c3 * g2;
  const double k = -WHIRL_PI * lambda;
  f[0] = k * T1;
  f[1] = k * T2;
  if (dl != NULL) {
    dl[0] = -WHIRL_PI * T1;
    dl[1] = -WHIRL_PI * T2;
  }
  if (J == NULL) return WHIRL_OK;

  /* d/dr of C v + K (r·v) r, with dC/dε² = (3/2) s^{-5/2} and
   * dK/dε² = (15/2) s^{-7/2}; dε²/dr = 2 r. */
  const double dC = 1.5 * s1 * s1 * rs;
  const double dK = 7.5 * s1 * s1 * s1 * rs;
  double Ryy = 2.0 * dC * vy * y + 2.0 * dK * rv * y * y + K * (y * vy + rv);
  double Ryz = 2.0 * dC * vy * z + 2.0 * dK * rv * y * z + K * y * vz;
  double Rzy = 2.0 * dC * vz * y + 2.0 * dK * rv * z * y + K * z * vy;
  double Rzz = 2.0 * dC * vz * z + 2.0 * dK * rv * z * z + K * (z * vz + rv);
  /* d/dv of C v + K (r·v) r */
  double Vyy = C + K * y * y, Vyz = K * y * z, Vzy = Vyz, Vzz = C + K * z * z;
  if (eps > 0.0) {
    /* cross term (4/π) φ(ε) ĝ(r), φ = ε s^{-2}, ĝ = M(r̂) v:
     * d/dr = (4/π) s^{-2} [ (4ε²/s − 1) ĝ r̂ᵀ + N ],  N = ∂(M(r) v)/∂r / ε,
     * d/dv = (4/π) ε s^{-2} M(r̂). */
    const double q = (4.0 / WHIRL_PI) * s1 * s1, w = 4.0 * e2 * s1 - 1.0;
    const double n11 = 2.0 * (-zh * vy + yh * vz), n12 = 2.0 * (-yh * vy - zh * vz);
    const double n21 = -n12, n22 = n11;
    Ryy += q * (w * g1 * yh + n11);
    Ryz += q * (w * g1 * zh + n12);
    Rzy += q * (w * g2 * yh + n21);
    Rzz += q * (w * g2 * zh + n22);
    Vyy += c3 * m11;
    Vyz += c3 * m12;
    Vzy += c3 * m12;
    Vzz -= c3 * m11;
  }
  J[0] = k * Ryy; /* column y */
  J[1] = k * Rzy;
  J[2] = k * Ryz; /* column z */
  J[3] = k * Rzz;
  J[4] = k * Vyy; /* column vy */
  J[5] = k * Vzy;
  J[6] = k * Vyz; /* column vz */
  J[7] = k * Vzz;
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Shared parameter check for the callbacks: a non-finite parameter is a
 * caller error (fatal), not a domain excursion. */
static int params_finite(const double *p) {
  for (int k = 0; k < WHIRL_SFD_NPAR; ++k)
    if (!isfinite(p[k])) return 0;
  return 1;
}

/* The fixed-frame callbacks' check: WHIRL_EINVAL (fatal) for a non-finite
 * parameter; WHIRL_SFD_CONTACT for |F_E| >= 1, a static force that presses
 * the journal onto the housing (every state is outside the domain there:
 * recoverable, so that a continuation in F_E ends at |F_E| = 1 and a time
 * integration stops at once instead of crawling along the housing). */
static int fixed_params(const double *p, double t) {
  if (!params_finite(p) || !isfinite(t)) return WHIRL_EINVAL;
  if (!(fabs(p[WHIRL_SFD_FE]) < 1.0)) return WHIRL_SFD_CONTACT;
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Fixed frame, x = (y, z, y', z') (DESIGN.md; paper eq. 1 made dimensionless
 * with eqs. 11–14):
 *   y'' = −2ζy' − y + δΩ² cos Ωτ + f_y
 *   z'' = −2ζz' − z + δΩ² sin Ωτ + f_z + F_E                              */

static int fixed_rhs(double t, const double *x, const double *p, double *f,
                     void *data) {
  (void)data;
  int prc = fixed_params(p, t);
  if (prc != WHIRL_OK) return prc;
  const double Om = p[WHIRL_SFD_OMEGA], de = p[WHIRL_SFD_DELTA];
  const double ze = p[WHIRL_SFD_ZETA];
  double fd[2];
  int rc = whirl_sfd_force(x[0], x[1], x[2], x[3], p[WHIRL_SFD_LAMBDA], fd,
                           NULL, NULL);
  if (rc != 0) return rc;
  const double u = de * Om * Om, ph = Om * t;
  f[0] = x[2];
  f[1] = x[3];
  f[2] = -2.0 * ze * x[2] - x[0] + u * cos(ph) + fd[0];
  f[3] = -2.0 * ze * x[3] - x[1] + u * sin(ph) + fd[1] + p[WHIRL_SFD_FE];
  return WHIRL_OK;
}

static int fixed_jac_x(double t, const double *x, const double *p, double *J,
                       void *data) {
  (void)data;
  int prc = fixed_params(p, t);
  if (prc != WHIRL_OK) return prc;
  double fd[2], Jf[8];
  int rc = whirl_sfd_force(x[0], x[1], x[2], x[3], p[WHIRL_SFD_LAMBDA], fd, Jf,
                           NULL);
  if (rc != 0) return rc;
  const double ze = p[WHIRL_SFD_ZETA];
  for (int i = 0; i < 16; ++i) J[i] = 0.0;
  J[0 + 4 * 2] = 1.0;
  J[1 + 4 * 3] = 1.0;
  for (int j = 0; j < 4; ++j) {
    J[2 + 4 * j] = Jf[0 + 2 * j];
    J[3 + 4 * j] = Jf[1 + 2 * j];
  }
  J[2 + 4 * 0] -= 1.0;
  J[3 + 4 * 1] -= 1.0;
  J[2 + 4 * 2] -= 2.0 * ze;
  J[3 + 4 * 3] -= 2.0 * ze;
  return WHIRL_OK;
}

static int fixed_jac_p(double t, const double *x, const double *p, double *J,
                       void *data) {
  (void)data;
  int prc = fixed_params(p, t);
  if (prc != WHIRL_OK) return prc;
  double fd[2], dl[2];
  int rc = whirl_sfd_force(x[0], x[1], x[2], x[3], p[WHIRL_SFD_LAMBDA], fd,
                           NULL, dl);
  if (rc != 0) return rc;
  const double Om = p[WHIRL_SFD_OMEGA], de = p[WHIRL_SFD_DELTA];
  const double c = cos(Om * t), sn = sin(Om * t);
  for (int i = 0; i < 4 * WHIRL_SFD_NPAR; ++i) J[i] = 0.0;
  /* d/dΩ of δΩ²(cos Ωτ, sin Ωτ) */
  J[2 + 4 * WHIRL_SFD_OMEGA] = de * Om * (2.0 * c - Om * t * sn);
  J[3 + 4 * WHIRL_SFD_OMEGA] = de * Om * (2.0 * sn + Om * t * c);
  J[2 + 4 * WHIRL_SFD_LAMBDA] = dl[0];
  J[3 + 4 * WHIRL_SFD_LAMBDA] = dl[1];
  J[2 + 4 * WHIRL_SFD_DELTA] = Om * Om * c;
  J[3 + 4 * WHIRL_SFD_DELTA] = Om * Om * sn;
  J[2 + 4 * WHIRL_SFD_ZETA] = -2.0 * x[2];
  J[3 + 4 * WHIRL_SFD_ZETA] = -2.0 * x[3];
  J[3 + 4 * WHIRL_SFD_FE] = 1.0;
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Rotating frame, y + iz = w e^{iΩτ}, w = u + iv, x = (u, v, u', v').  The
 * force is rotation-equivariant (f(e^{iθ}r, e^{iθ}v) = e^{iθ} f(r, v)), so
 *   w'' = −2iΩw' + Ω²w − 2ζV − w + δΩ² + f(w, V),   V = w' + iΩw,
 * i.e. with V = (u' − Ωv, v' + Ωu):
 *   u'' =  2Ωv' + Ω²u − 2ζV_u − u + δΩ² + f_1
 *   v'' = −2Ωu' + Ω²v − 2ζV_v − v       + f_2.
 * Only F_E = 0 is allowed: a static force turns into i F_E e^{−iΩτ} here and
 * the frame is no longer autonomous (use the fixed frame). */

static int rot_prepare(double t, const double *x, const double *p, double *V) {
  if (!params_finite(p) || !isfinite(t)) return WHIRL_EINVAL;
  if (p[WHIRL_SFD_FE] != 0.0) return WHIRL_EINVAL;
  const double Om = p[WHIRL_SFD_OMEGA];
  V[0] = x[2] - Om * x[1];
  V[1] = x[3] + Om * x[0];
  return WHIRL_OK;
}

static int rot_rhs(double t, const double *x, const double *p, double *f,
                   void *data) {
  (void)data;
  double V[2], fd[2];
  int rc = rot_prepare(t, x, p, V);
  if (rc != 0) return rc;
  rc = whirl_sfd_force(x[0], x[1], V[0], V[1], p[WHIRL_SFD_LAMBDA], fd, NULL,
                       NULL);
  if (rc != 0) return rc;
  const double Om = p[WHIRL_SFD_OMEGA], ze = p[WHIRL_SFD_ZETA];
  const double O2 = Om * Om;
  f[0] = x[2];
  f[1] = x[3];
  f[2] = 2.0 * Om * x[3] + (O2 - 1.0) * x[0] - 2.0 * ze * V[0] +
         p[WHIRL_SFD_DELTA] * O2 + fd[0];
  f[3] = -2.0 * Om * x[2] + (O2 - 1.0) * x[1] - 2.0 * ze * V[1] + fd[1];
  return WHIRL_OK;
}

static int rot_jac_x(double t, const double *x, const double *p, double *J,
                     void *data) {
  (void)data;
  double V[2], fd[2], Jf[8];
  int rc = rot_prepare(t, x, p, V);
  if (rc != 0) return rc;
  rc = whirl_sfd_force(x[0], x[1], V[0], V[1], p[WHIRL_SFD_LAMBDA], fd, Jf,
                       NULL);
  if (rc != 0) return rc;
  const double Om = p[WHIRL_SFD_OMEGA], ze = p[WHIRL_SFD_ZETA];
  const double O2 = Om * Om;
  for (int i = 0; i < 16; ++i) J[i] = 0.0;
  J[0 + 4 * 2] = 1.0;
  J[1 + 4 * 3] = 1.0;
  /* linear part; dV/d(u, v) = Ω [[0, −1], [1, 0]], dV/d(u', v') = I */
  J[2 + 4 * 0] = O2 - 1.0;
  J[2 + 4 * 1] = 2.0 * ze * Om;
  J[2 + 4 * 2] = -2.0 * ze;
  J[2 + 4 * 3] = 2.0 * Om;
  J[3 + 4 * 0] = -2.0 * ze * Om;
  J[3 + 4 * 1] = O2 - 1.0;
  J[3 + 4 * 2] = -2.0 * Om;
  J[3 + 4 * 3] = -2.0 * ze;
  /* force: df/d(u, v) = J_r + J_v Ω [[0, −1], [1, 0]], df/d(u', v') = J_v */
  for (int i = 0; i < 2; ++i) {
    const double Jvu = Jf[i + 2 * 2], Jvv = Jf[i + 2 * 3];
    J[2 + i + 4 * 0] += Jf[i + 2 * 0] + Om * Jvv;
    J[2 + i + 4 * 1] += Jf[i + 2 * 1] - Om * Jvu;
    J[2 + i + 4 * 2] += Jvu;
    J[2 + i + 4 * 3] += Jvv;
  }
  return WHIRL_OK;
}

static int rot_jac_p(double t, const double *x, const double *p, double *J,
                     void *data) {
  (void)data;
  double V[2], fd[2], Jf[8], dl[2];
  int rc = rot_prepare(t, x, p, V);
  if (rc != 0) return rc;
  rc = whirl_sfd_force(x[0], x[1], V[0], V[1], p[WHIRL_SFD_LAMBDA], fd, Jf, dl);
  if (rc != 0) return rc;
  const double Om = p[WHIRL_SFD_OMEGA], ze = p[WHIRL_SFD_ZETA];
  const double de = p[WHIRL_SFD_DELTA];
  for (int i = 0; i < 4 * WHIRL_SFD_NPAR; ++i) J[i] = 0.0;
  /* d/dΩ, with dV/dΩ = (−v, u) */
  const double dVu = -x[1], dVv = x[0];
  J[2 + 4 * WHIRL_SFD_OMEGA] = 2.0 * x[3] + 2.0 * Om * x[0] - 2.0 * ze * dVu +
                               2.0 * de * Om + Jf[0 + 4] * dVu + Jf[0 + 6] * dVv;
  J[3 + 4 * WHIRL_SFD_OMEGA] = -2.0 * x[2] + 2.0 * Om * x[1] - 2.0 * ze * dVv +
                               Jf[1 + 4] * dVu + Jf[1 + 6] * dVv;
  J[2 + 4 * WHIRL_SFD_LAMBDA] = dl[0];
  J[3 + 4 * WHIRL_SFD_LAMBDA] = dl[1];
  J[2 + 4 * WHIRL_SFD_DELTA] = Om * Om;
  J[2 + 4 * WHIRL_SFD_ZETA] = -2.0 * V[0];
  J[3 + 4 * WHIRL_SFD_ZETA] = -2.0 * V[1];
  /* d/dF_E at F_E = 0 of the (non-autonomous) extension i F_E e^{−iΩτ}:
   * exact, although F_E itself must stay 0 in this frame. */
  J[2 + 4 * WHIRL_SFD_FE] = sin(Om * t);
  J[3 + 4 * WHIRL_SFD_FE] = cos(Om * t);
  return WHIRL_OK;
}

static const char *const sfd_fixed_x_names[4] = {"y", "z", "dy", "dz"};
static const char *const sfd_rot_x_names[4] = {"u", "v", "du", "dv"};

static const whirl_problem sfd_fixed = {
    .name = "sfd_fixed",
    .n = 4,
    .npar = WHIRL_SFD_NPAR,
    .rhs = fixed_rhs,
    .jac_x = fixed_jac_x,
    .jac_p = fixed_jac_p,
    .autonomous = 0,
    .x_names = sfd_fixed_x_names,
    .p_names = sfd_p_names,
    .data = NULL,
};

static const whirl_problem sfd_rotating = {
    .name = "sfd_rotating",
    .n = 4,
    .npar = WHIRL_SFD_NPAR,
    .rhs = rot_rhs,
    .jac_x = rot_jac_x,
    .jac_p = rot_jac_p,
    .autonomous = 1,
    .x_names = sfd_rot_x_names,
    .p_names = sfd_p_names,
    .data = NULL,
};

const whirl_problem *whirl_sfd_fixed(void) { return &sfd_fixed; }
const whirl_problem *whirl_sfd_rotating(void) { return &sfd_rotating; }

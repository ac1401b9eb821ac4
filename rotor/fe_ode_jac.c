/* rotor/fe_ode_jac.c — the analytic Jacobian of the first-order FE rotor
 * (whirl/rotor/fe_ode.h), by implicit differentiation of
 * M_eff(q) q'' = R(t, q, q'):  ∂q''/∂q = M_eff⁻¹ (∂R/∂q + E Jr_S Eᵀ) with
 * Jr the elements' ∂f/∂r at the actual acceleration (it carries ∂(Ja a)/∂r),
 * likewise for q'; dense, and the same values in a sparse pattern.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor/fe_hbm.h> /* WHIRL_FE_P_OMEGA */

#include "fe_ode_impl.h"

/* B = M⁻¹ A, dense nd×nd */
static double *mass_solve(whirl_fe_ode *m, const whirl_fe_csc *A) {
  const size_t nd = (size_t)m->nd;
  double *B = calloc(nd * nd + 1, sizeof *B);
  if (!B) return NULL;
  for (int j = 0; j < A->n; ++j)
    for (int k = A->p[j]; k < A->p[j + 1]; ++k) B[nd * j + A->i[k]] = A->x[k];
  if (whirl_linsol_solve(m->lsM, B, nd, 0) != WHIRL_OK) {
    free(B);
    return NULL;
  }
  return B;
}

static int precompute(whirl_fe_ode *m) {
  if (m->MiK) return 0;
  m->MiC = mass_solve(m, &m->r->C);
  m->MiG = mass_solve(m, &m->r->G);
  m->MiK = m->MiC && m->MiG ? mass_solve(m, &m->r->K) : NULL;
  return m->MiK ? 0 : -1;
}

/* One bottom block Y (leading dimension ld): −(A1 + s A2) + W JS Eᵀ, then
 * M_eff⁻¹ M by Woodbury. */
static int bottom_block(whirl_fe_ode *m, double *Y, size_t ld,
                        const double *A1, const double *A2, double s,
                        const double *JS) {
  const size_t nd = (size_t)m->nd, mm = (size_t)m->m;
  for (size_t j = 0; j < nd; ++j)
    for (size_t i = 0; i < nd; ++i)
      Y[ld * j + i] = -A1[nd * j + i] - (A2 ? s * A2[nd * j + i] : 0.0);
  for (size_t b = 0; b < mm; ++b)
    for (size_t a = 0; a < mm; ++a) {
      const double jab = JS[a + mm * b];
      if (jab == 0.0) continue;
      double *col = Y + ld * m->dof[b];
      for (size_t i = 0; i < nd; ++i) col[i] += m->W[nd * a + i] * jab;
    }
  return fe_ode_woodbury(m, Y, ld, m->nd);
}

int fe_ode_jac_dense(double t, const double *z, const double *p, double *J,
                     void *data) {
  whirl_fe_ode *m = data;
  const size_t nd = (size_t)m->nd, n = 2 * nd;
  int rc = fe_ode_accel(m, t, z, p, 1);
  if (rc) return rc;
  if (precompute(m)) return -1;
  for (size_t j = 0; j < nd; ++j) {
    memset(J + n * j, 0, nd * sizeof *J);            /* ∂q'/∂q = 0 */
    memset(J + n * (nd + j), 0, nd * sizeof *J);     /* ∂q'/∂q' = I */
    J[n * (nd + j) + j] = 1.0;
  }
  if (bottom_block(m, J + nd, n, m->MiK, NULL, 0.0, m->JrS) ||
      bottom_block(m, J + nd + n * nd, n, m->MiC, m->MiG,
                   p[WHIRL_FE_P_OMEGA], m->JvS))
    return -1;
  return 0;
}

/* ---------------------------------------------------------- sparse */

static int sparse_fill(double t, const double *z, const double *p, double *Jx,
                       void *data) {
  whirl_fe_ode *m = data;
  const size_t n = 2 * (size_t)m->nd;
  int rc = fe_ode_jac_dense(t, z, p, m->Jd, m);
  if (rc) return rc;
  for (size_t j = 0; j < n; ++j)
    for (int k = m->Jp[j]; k < m->Jp[j + 1]; ++k) Jx[k] = m->Jd[n * j + m->Ji[k]];
  return 0;
}

/* row i of a bottom block's column j can be non-zero */
static int structural(const whirl_fe_ode *m, size_t i, size_t j, int right,
                      const char *wrow, const char *scol) {
  const size_t nd = (size_t)m->nd;
  if (right ? (m->MiC[nd * j + i] != 0.0 || m->MiG[nd * j + i] != 0.0)
            : m->MiK[nd * j + i] != 0.0)
    return 1;
  return wrow[i] && (scol[j] || m->inertia);
}

static int build_pattern(whirl_fe_ode *m, const char *wrow, const char *scol) {
  const size_t nd = (size_t)m->nd, n = 2 * nd;
  for (int pass = 0; pass < 2; ++pass) {
    size_t nz = 0;
    for (size_t j = 0; j < n; ++j) {
      const int right = j >= nd;
      const size_t jj = right ? j - nd : j;
      if (pass) m->Jp[j] = (int)nz;
      if (right) {
        if (pass) m->Ji[nz] = (int)jj;
        ++nz;
      }
      for (size_t i = 0; i < nd; ++i)
        if (structural(m, i, jj, right, wrow, scol)) {
          if (pass) m->Ji[nz] = (int)(nd + i);
          ++nz;
        }
    }
    if (pass) {
      m->Jp[n] = (int)nz;
      return 0;
    }
    m->nnz = nz;
    m->Ji = malloc((nz + 1) * sizeof *m->Ji);
    m->Jp = malloc((n + 1) * sizeof *m->Jp);
    if (!m->Ji || !m->Jp) return -1;
  }
  return 0;
}

int whirl_fe_ode_use_sparse(whirl_fe_ode *m, whirl_ode *ode) {
  if (!m || !ode) return WHIRL_EINVAL;
  const size_t nd = (size_t)m->nd, n = 2 * nd;
  if (!m->Jp) {
    char *wrow = calloc(nd + 1, 1), *scol = calloc(nd + 1, 1);
    int rc = wrow && scol && !precompute(m) ? 0 : -1;
    for (int a = 0; !rc && a < m->m; ++a) {
      scol[m->dof[a]] = 1;
      for (size_t i = 0; i < nd; ++i) wrow[i] |= m->W[nd * a + i] != 0.0;
    }
    if (!rc) rc = build_pattern(m, wrow, scol);
    free(wrow);
    free(scol);
    if (!rc) m->Jd = malloc(n * n * sizeof *m->Jd);
    if (rc || !m->Jd) {
      free(m->Jp); free(m->Ji);
      m->Jp = m->Ji = NULL;
      return WHIRL_ERRMSG(m->err, sizeof m->err, WHIRL_ENOMEM, "out of memory");
    }
  }
  int rc = whirl_ode_set_sparse_jacobian(ode, m->nnz, m->Jp, m->Ji,
                                         sparse_fill, m);
  if (rc != WHIRL_OK)
    return WHIRL_ERRMSG(m->err, sizeof m->err, rc, "%s", whirl_ode_errmsg(ode));
  return WHIRL_OK;
}

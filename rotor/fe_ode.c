/* rotor/fe_ode.c — a finite-element rotor in first-order form
 * (whirl/rotor/fe_ode.h): the object, the right-hand side and the
 * acceleration with the fluid-inertia elements' added mass on the left
 * (Sherman–Morrison–Woodbury on the factor of M; Golub & Van Loan, Matrix
 * Computations, 4th ed., §2.1.4).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor/fe_hbm.h> /* WHIRL_FE_P_* */

#include "fe_ode_impl.h"

static int is_film(whirl_fe_nl_kind k) {
  return k != WHIRL_FE_RUB && k != WHIRL_FE_CUBIC;
}

static int cmp_int(const void *x, const void *y) {
  int a = *(const int *)x, b = *(const int *)y;
  return (a > b) - (a < b);
}

static int position(const whirl_fe_ode *m, int d) {
  for (int j = 0; j < m->m; ++j)
    if (m->dof[j] == d) return j;
  return -1;
}

/* S: the y, z of each element's node and pedestal, sorted, unique. */
static int collect_dofs(whirl_fe_ode *m) {
  const whirl_fe_rotor *r = m->r;
  m->dof = malloc((4 * (size_t)r->nnl + 1) * sizeof *m->dof);
  m->epos = malloc(((size_t)r->nnl + 1) * sizeof *m->epos);
  if (!m->dof || !m->epos) return WHIRL_ENOMEM;
  int na = 0;
  for (int e = 0; e < r->nnl; ++e)
    for (int k = 0; k < 4; ++k) {
      const whirl_fe_nl *el = &r->nl[e];
      if (k < 2) m->dof[na++] = whirl_fe_rotor_dof(r, el->node, k);
      else if (el->pedestal >= 0)
        m->dof[na++] = whirl_fe_rotor_dof(r, -1 - el->pedestal, k - 2);
    }
  qsort(m->dof, (size_t)na, sizeof *m->dof, cmp_int);
  m->m = 0;
  for (int i = 0; i < na; ++i)
    if (m->m == 0 || m->dof[i] != m->dof[m->m - 1]) m->dof[m->m++] = m->dof[i];
  for (int e = 0; e < r->nnl; ++e)
    for (int k = 0; k < 4; ++k) {
      const whirl_fe_nl *el = &r->nl[e];
      int d = k < 2 ? whirl_fe_rotor_dof(r, el->node, k)
              : el->pedestal >= 0 ? whirl_fe_rotor_dof(r, -1 - el->pedestal, k - 2)
                                  : -1;
      m->epos[e][k] = d >= 0 ? position(m, d) : -1;
    }
  return WHIRL_OK;
}

/* LU of M and W = M⁻¹ E. */
static int factor_mass(whirl_fe_ode *m) {
  const whirl_fe_csc *M = &m->r->M;
  m->lsM = whirl_linsol_alloc_sparse((size_t)m->nd, M->p, M->i);
  if (!m->lsM) return WHIRL_ENOMEM;
  int rc = whirl_linsol_factor(m->lsM, M->x);
  if (rc != WHIRL_OK) return rc;
  for (int j = 0; j < m->m; ++j) m->W[(size_t)m->nd * j + m->dof[j]] = 1.0;
  return m->m ? whirl_linsol_solve(m->lsM, m->W, (size_t)m->m, 0) : WHIRL_OK;
}

static int fe_ode_rhs(double t, const double *z, const double *p, double *f,
                      void *data) {
  whirl_fe_ode *m = data;
  int rc = fe_ode_accel(m, t, z, p, 0);
  if (rc) return rc;
  memcpy(f, z + m->nd, (size_t)m->nd * sizeof *f);
  memcpy(f + m->nd, m->a, (size_t)m->nd * sizeof *f);
  return 0;
}

static int alloc_arrays(whirl_fe_ode *m) {
  size_t nd = (size_t)m->nd, mm = (size_t)m->m, m2 = mm * mm + 1;
  m->W = calloc(nd * mm + 1, sizeof *m->W);
  m->R = malloc(nd * sizeof *m->R);
  m->a = malloc(nd * sizeof *m->a);
  m->JaS = malloc(m2 * sizeof *m->JaS);
  m->JrS = malloc(m2 * sizeof *m->JrS);
  m->JvS = malloc(m2 * sizeof *m->JvS);
  m->X = malloc(m2 * sizeof *m->X);
  m->y = malloc((mm * nd + 1) * sizeof *m->y);
  m->el = malloc(((size_t)m->r->nnl + 1) * sizeof *m->el);
  m->lsX = m->m ? whirl_linsol_alloc_dense(mm) : NULL;
  if (!m->W || !m->R || !m->a || !m->JaS || !m->JrS || !m->JvS || !m->X ||
      !m->y || !m->el || (m->m && !m->lsX))
    return WHIRL_ENOMEM;
  memcpy(m->el, m->r->nl, (size_t)m->r->nnl * sizeof *m->el);
  for (int e = 0; e < m->r->nnl; ++e)
    if (m->el[e].kind == WHIRL_FE_SFD_INERTIA) m->inertia = 1;
  return WHIRL_OK;
}

whirl_fe_ode *whirl_fe_ode_alloc(const whirl_fe_rotor *r, char *errbuf,
                                 size_t errlen) {
  whirl_fe_ode *m = r ? calloc(1, sizeof *m) : NULL;
  if (!m) {
    WHIRL_ERRMSG(errbuf, errlen, r ? WHIRL_ENOMEM : WHIRL_EINVAL,
                 r ? "out of memory" : "no rotor");
    return NULL;
  }
  m->r = r;
  m->nd = r->ndof;
  int rc = collect_dofs(m);
  if (rc == WHIRL_OK) rc = alloc_arrays(m);
  if (rc == WHIRL_OK) {
    rc = factor_mass(m);
    if (rc != WHIRL_OK && rc != WHIRL_ENOMEM) {
      WHIRL_ERRMSG(errbuf, errlen, rc, "the mass matrix: %s",
                   whirl_linsol_errmsg(m->lsM));
      whirl_fe_ode_free(m);
      return NULL;
    }
  }
  if (rc != WHIRL_OK) {
    WHIRL_ERRMSG(errbuf, errlen, rc, "out of memory");
    whirl_fe_ode_free(m);
    return NULL;
  }
  m->prob = (whirl_problem){.name = "fe-rotor", .n = 2 * (size_t)m->nd,
                            .npar = WHIRL_FE_NPAR, .rhs = fe_ode_rhs,
                            .jac_x = fe_ode_jac_dense, .autonomous = 0,
                            .data = m};
  return m;
}

void whirl_fe_ode_free(whirl_fe_ode *m) {
  if (!m) return;
  whirl_linsol_free(m->lsM);
  whirl_linsol_free(m->lsX);
  free(m->dof); free(m->epos); free(m->el); free(m->W); free(m->R);
  free(m->a); free(m->JaS); free(m->JrS); free(m->JvS); free(m->X);
  free(m->y); free(m->MiK); free(m->MiC); free(m->MiG); free(m->Jd);
  free(m->Jp); free(m->Ji); free(m->Gp); free(m->Gi); free(m->Gw);
  free(m);
}

const whirl_problem *whirl_fe_ode_problem(const whirl_fe_ode *m) {
  return m ? &m->prob : NULL;
}

const char *whirl_fe_ode_errmsg(const whirl_fe_ode *m) {
  return m ? m->err : "";
}

/* ------------------------------------------------------------ rhs */

/* y −= A x (compressed columns) */
static void csc_mv_sub(const whirl_fe_csc *A, double s, const double *x,
                       double *y) {
  for (int j = 0; j < A->n; ++j) {
    const double xj = s * x[j];
    if (xj != 0.0)
      for (int k = A->p[j]; k < A->p[j + 1]; ++k) y[A->i[k]] -= A->x[k] * xj;
  }
}

/* R = f0 + s Ω² (u_c cos Ωt + u_s sin Ωt) − K q − (C + Ω G) v */
static void linear_forces(whirl_fe_ode *m, double t, const double *q,
                          const double *v, const double *p) {
  const whirl_fe_rotor *r = m->r;
  const double Om = p[WHIRL_FE_P_OMEGA], s = p[WHIRL_FE_P_UNBALANCE];
  const double fc = s * Om * Om * cos(Om * t), fs = s * Om * Om * sin(Om * t);
  for (int i = 0; i < m->nd; ++i)
    m->R[i] = r->f0[i] + fc * r->unb_c[i] + fs * r->unb_s[i];
  csc_mv_sub(&r->K, 1.0, q, m->R);
  csc_mv_sub(&r->C, 1.0, v, m->R);
  csc_mv_sub(&r->G, Om, v, m->R);
}

static void set_scales(whirl_fe_ode *m, const double *p) {
  for (int e = 0; e < m->r->nnl; ++e)
    if (is_film(m->el[e].kind)) {
      m->el[e].par.clearance =
          m->r->nl[e].par.clearance * p[WHIRL_FE_P_CLEARANCE];
      m->el[e].par.viscosity =
          m->r->nl[e].par.viscosity * p[WHIRL_FE_P_VISCOSITY];
    }
}

/* J_S += Pᵀ J P for a 2×2 element Jacobian J (column-major) */
static void add_block(whirl_fe_ode *m, const int pos[4], const double J[4],
                      double *JS) {
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      if (pos[a] < 0 || pos[b] < 0) continue;
      const double s = (a < 2) == (b < 2) ? 1.0 : -1.0;
      JS[pos[a] + (size_t)m->m * pos[b]] += s * J[a % 2 + 2 * (b % 2)];
    }
}

/* The element forces into R and their assembled Jacobians; acc the
 * acceleration (NULL: zero). */
static int element_forces(whirl_fe_ode *m, const double *q, const double *v,
                          const double *acc, double Om, int with_jac) {
  const size_t m2 = (size_t)m->m * m->m;
  memset(m->JaS, 0, m2 * sizeof *m->JaS);
  if (with_jac) {
    memset(m->JrS, 0, m2 * sizeof *m->JrS);
    memset(m->JvS, 0, m2 * sizeof *m->JvS);
  }
  for (int e = 0; e < m->r->nnl; ++e) {
    const int *pos = m->epos[e];
    double r[2], vr[2], ar[2] = {0, 0}, f[2], Jr[4], Jv[4], Ja[4];
    for (int k = 0; k < 2; ++k) {
      const int d = m->dof[pos[k]], dp = pos[k + 2] >= 0 ? m->dof[pos[k + 2]] : -1;
      r[k] = q[d] - (dp >= 0 ? q[dp] : 0.0) - m->el[e].offset[k];
      vr[k] = v[d] - (dp >= 0 ? v[dp] : 0.0);
      if (acc) ar[k] = acc[d] - (dp >= 0 ? acc[dp] : 0.0);
    }
    const int ine = m->el[e].kind == WHIRL_FE_SFD_INERTIA;
    if (whirl_fe_nl_force(&m->el[e], r, vr, ar, Om, f, with_jac ? Jr : NULL,
                          with_jac ? Jv : NULL, ine ? Ja : NULL) != WHIRL_OK)
      return 1;
    if (acc == NULL)
      for (int k = 0; k < 2; ++k) {
        m->R[m->dof[pos[k]]] += f[k];
        if (pos[k + 2] >= 0) m->R[m->dof[pos[k + 2]]] -= f[k];
      }
    if (ine) add_block(m, pos, Ja, m->JaS);
    if (with_jac) {
      add_block(m, pos, Jr, m->JrS);
      add_block(m, pos, Jv, m->JvS);
    }
  }
  return 0;
}

int fe_ode_woodbury(whirl_fe_ode *m, double *Y, size_t ld, int ncol) {
  if (!m->inertia || m->m == 0 || ncol == 0) return 0;
  const size_t mm = (size_t)m->m, nd = (size_t)m->nd;
  for (int c = 0; c < ncol; ++c) /* y = Ja_S Y_S */
    for (size_t i = 0; i < mm; ++i) {
      double s = 0.0;
      for (size_t j = 0; j < mm; ++j) s += m->JaS[i + mm * j] * Y[ld * c + m->dof[j]];
      m->y[mm * c + i] = s;
    }
  if (whirl_linsol_solve(m->lsX, m->y, (size_t)ncol, 0) != WHIRL_OK) return -1;
  for (int c = 0; c < ncol; ++c) /* Y += W y */
    for (size_t j = 0; j < mm; ++j) {
      const double yj = m->y[mm * c + j];
      for (size_t i = 0; i < nd; ++i) Y[ld * c + i] += m->W[nd * j + i] * yj;
    }
  return 0;
}

/* X = I − Ja_S W_S, factored */
static int factor_x(whirl_fe_ode *m) {
  const size_t mm = (size_t)m->m, nd = (size_t)m->nd;
  for (size_t j = 0; j < mm; ++j)
    for (size_t i = 0; i < mm; ++i) {
      double s = i == j ? 1.0 : 0.0;
      for (size_t k = 0; k < mm; ++k) s -= m->JaS[i + mm * k] * m->W[nd * j + m->dof[k]];
      m->X[i + mm * j] = s;
    }
  return whirl_linsol_factor(m->lsX, m->X) == WHIRL_OK ? 0 : 1;
}

int fe_ode_accel(whirl_fe_ode *m, double t, const double *z, const double *p,
                 int with_jac) {
  const double *q = z, *v = z + m->nd;
  set_scales(m, p);
  linear_forces(m, t, q, v, p);
  int rc = element_forces(m, q, v, NULL, p[WHIRL_FE_P_OMEGA], 0);
  if (rc) return rc;
  memcpy(m->a, m->R, (size_t)m->nd * sizeof *m->a);
  if (whirl_linsol_solve(m->lsM, m->a, 1, 0) != WHIRL_OK) return -1;
  if (m->inertia && m->m) {
    if (factor_x(m)) return 1; /* the added mass cancels the mass */
    if (fe_ode_woodbury(m, m->a, (size_t)m->nd, 1)) return -1;
  }
  if (with_jac) /* Jr, Jv at the actual acceleration (Ja does not depend on it) */
    return element_forces(m, q, v, m->a, p[WHIRL_FE_P_OMEGA], 1);
  return 0;
}

/* rotor/fe_ode_mass.c — the first-order FE rotor for BDF with its mass
 * matrix kept on the left (whirl_ode_set_mass_matrix): B = diag(I, M) and
 * G = B f_x = [0 I; −K + E Jr_S Eᵀ, −(C + Ω G) + E Jv_S Eᵀ], both as sparse
 * as the assembled matrices, so that the Newton systems (B − γ G) δ = B r
 * are banded and KLU factors them in O(ndof) instead of the dense O(ndof³)
 * of f_x = B⁻¹ G.  Exact for rotors without fluid inertia; with it the
 * added mass −E Ja_S Eᵀ is left out of B (a modified Newton iteration; the
 * rhs, hence the solution, stays exact).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor/fe_hbm.h> /* WHIRL_FE_P_OMEGA */

#include "fe_ode_impl.h"

/* position in S of DOF d, or −1 */
static int spos(const whirl_fe_ode *m, int d) {
  for (int a = 0; a < m->m; ++a)
    if (m->dof[a] == d) return a;
  return -1;
}

static void mark_csc(const whirl_fe_csc *A, int j, int off, char *hit) {
  for (int k = A->p[j]; k < A->p[j + 1]; ++k) hit[off + A->i[k]] = 1;
}

/* The pattern of G with B's inside: column j < nd rows {j} ∪ nd + (K ∪ S),
 * column nd + j rows {j} ∪ nd + (C ∪ G ∪ M ∪ S); two passes (count, fill). */
static int mass_pattern(whirl_fe_ode *m) {
  const whirl_fe_rotor *r = m->r;
  const int nd = m->nd, n = 2 * nd;
  char *hit = calloc((size_t)n, 1);
  m->Gp = malloc(((size_t)n + 1) * sizeof *m->Gp);
  if (!hit || !m->Gp) { free(hit); return -1; }
  for (int pass = 0; pass < 2; ++pass) {
    size_t nz = 0;
    for (int c = 0; c < n; ++c) {
      const int j = c % nd, right = c >= nd;
      hit[j] = 1;
      if (right) {
        mark_csc(&r->C, j, nd, hit), mark_csc(&r->G, j, nd, hit), mark_csc(&r->M, j, nd, hit);
      } else {
        mark_csc(&r->K, j, nd, hit);
      }
      if (spos(m, j) >= 0)
        for (int a = 0; a < m->m; ++a) hit[nd + m->dof[a]] = 1;
      if (pass) m->Gp[c] = (int)nz;
      for (int i = 0; i < n; ++i)
        if (hit[i]) {
          if (pass) m->Gi[nz] = i;
          ++nz, hit[i] = 0;
        }
    }
    if (pass) m->Gp[n] = (int)nz;
    else if (!(m->Gi = malloc((nz + 1) * sizeof *m->Gi))) { free(hit); return -1; }
    m->gnnz = nz;
  }
  free(hit);
  return 0;
}

/* one column's values: w (length 2nd, zero on entry) gathered into Jx */
static void gather(whirl_fe_ode *m, int c, double *w, double *Jx) {
  for (int k = m->Gp[c]; k < m->Gp[c + 1]; ++k) {
    Jx[k] = w[m->Gi[k]];
    w[m->Gi[k]] = 0.0;
  }
}

static void scatter_csc(const whirl_fe_csc *A, int j, double s, int off, double *w) {
  for (int k = A->p[j]; k < A->p[j + 1]; ++k) w[off + A->i[k]] += s * A->x[k];
}

static int mass_fill(double t, const double *z, const double *p, double *Jx,
                     void *data) {
  whirl_fe_ode *m = data;
  const whirl_fe_rotor *r = m->r;
  const int nd = m->nd, mm = m->m;
  int rc = fe_ode_accel(m, t, z, p, 1);
  if (rc) return rc;
  double *w = m->Gw; /* 2nd, kept zero between columns */
  for (int c = 0; c < 2 * nd; ++c) {
    const int j = c % nd, right = c >= nd, b = spos(m, j);
    if (right) {
      w[j] = 1.0;
      scatter_csc(&r->C, j, -1.0, nd, w);
      scatter_csc(&r->G, j, -p[WHIRL_FE_P_OMEGA], nd, w);
    } else {
      scatter_csc(&r->K, j, -1.0, nd, w);
    }
    const double *JS = right ? m->JvS : m->JrS;
    for (int a = 0; b >= 0 && a < mm; ++a) w[nd + m->dof[a]] += JS[a + (size_t)mm * b];
    gather(m, c, w, Jx);
  }
  return 0;
}

/* B = diag(I, M) in compressed columns */
static int mass_matrix(const whirl_fe_ode *m, int **Bp, int **Bi, double **Bx) {
  const whirl_fe_csc *M = &m->r->M;
  const int nd = m->nd, nnz = nd + M->p[nd];
  *Bp = malloc((2 * (size_t)nd + 1) * sizeof **Bp);
  *Bi = malloc((size_t)nnz * sizeof **Bi);
  *Bx = malloc((size_t)nnz * sizeof **Bx);
  if (!*Bp || !*Bi || !*Bx) return -1;
  for (int j = 0; j < nd; ++j) (*Bp)[j] = j, (*Bi)[j] = j, (*Bx)[j] = 1.0;
  for (int j = 0; j <= nd; ++j) (*Bp)[nd + j] = nd + M->p[j];
  for (int k = 0; k < M->p[nd]; ++k) (*Bi)[nd + k] = nd + M->i[k], (*Bx)[nd + k] = M->x[k];
  return 0;
}

int whirl_fe_ode_use_mass(whirl_fe_ode *m, whirl_ode *ode) {
  if (!m || !ode) return WHIRL_EINVAL;
  free(m->Gp), free(m->Gi), free(m->Gw);
  m->Gp = m->Gi = NULL;
  m->Gw = calloc(2 * (size_t)m->nd, sizeof *m->Gw);
  int *Bp = NULL, *Bi = NULL;
  double *Bx = NULL;
  int rc = m->Gw && !mass_pattern(m) && !mass_matrix(m, &Bp, &Bi, &Bx) ? WHIRL_OK : WHIRL_ENOMEM;
  if (rc == WHIRL_OK) rc = whirl_ode_set_sparse_jacobian(ode, m->gnnz, m->Gp, m->Gi, mass_fill, m);
  if (rc == WHIRL_OK)
    rc = whirl_ode_set_mass_matrix(ode, (size_t)Bp[2 * m->nd], Bp, Bi, Bx);
  if (rc != WHIRL_OK)
    WHIRL_ERRMSG(m->err, sizeof m->err, rc, "%s",
                 rc == WHIRL_ENOMEM ? "out of memory" : whirl_ode_errmsg(ode));
  free(Bp), free(Bi), free(Bx);
  return rc;
}

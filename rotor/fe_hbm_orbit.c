/* rotor/fe_hbm_orbit.c — the whole orbit of a harmonic-balance solution of
 * a finite-element rotor: the coefficients of every DOF from the condensed
 * unknowns (q_l = D_ll⁻¹ (F_l − D_ln q_n) per harmonic, the same
 * factorisations as the condensation, i.e. q = D_k⁻¹ (F_k + Pᵀ f_nl,k) at a
 * solution without needing D_k regular), and the orbit's amplitude at a
 * node.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"

int whirl_fe_hbm_recover(whirl_fe_hbm *h, const double *X, const double *p,
                         double *q) {
  for (int i = 0; i < h->n; ++i) h->xsi[i] = h->Ls * X[i];
  int rc = fe_lin_recover(&h->lin, p[WHIRL_FE_P_OMEGA],
                          p[WHIRL_FE_P_UNBALANCE], h->xsi, q);
  if (rc)
    WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, rc, "%s",
                 h->lin.err[0] ? h->lin.err : whirl_strerror(rc));
  return rc;
}

/* y, z of the node and their first two θ-derivatives at θ. */
static void node_at(const whirl_fe_hbm *h, const double *q, int node,
                    double th, double v[3][2]) {
  int nd = h->r->ndof;
  for (int c = 0; c < 2; ++c) {
    int d = 4 * node + c;
    v[0][c] = q[d];
    v[1][c] = v[2][c] = 0;
    for (int k = 1; k <= h->H; ++k) {
      double a = q[nd * (2 * k - 1) + d], b = q[nd * 2 * k + d];
      double ck = cos(k * th), sk = sin(k * th);
      v[0][c] += a * ck + b * sk;
      v[1][c] += k * (-a * sk + b * ck);
      v[2][c] += -(double)k * k * (a * ck + b * sk);
    }
  }
}

double whirl_fe_hbm_amplitude(const whirl_fe_hbm *h, const double *q,
                              int node) {
  if (node < 0 || node >= h->r->nnode) return NAN;
  int ns = 16 * h->L;
  double best = -1, bth = 0, v[3][2];
  for (int s = 0; s < ns; ++s) {
    double th = 2 * WHIRL_PI * s / ns;
    node_at(h, q, node, th, v);
    double r2 = v[0][0] * v[0][0] + v[0][1] * v[0][1];
    if (r2 > best) { best = r2; bth = th; }
  }
  for (int it = 0; it < 20; ++it) { /* Newton on d(r²)/dθ = 0 */
    node_at(h, q, node, bth, v);
    double g = v[0][0] * v[1][0] + v[0][1] * v[1][1];
    double dg = v[1][0] * v[1][0] + v[1][1] * v[1][1] + v[0][0] * v[2][0] +
                v[0][1] * v[2][1];
    if (dg >= 0) break; /* not a maximum's neighbourhood */
    double step = -g / dg;
    if (fabs(step) > WHIRL_PI / ns) break;
    double vt[3][2];
    node_at(h, q, node, bth + step, vt);
    double r2 = vt[0][0] * vt[0][0] + vt[0][1] * vt[0][1];
    if (r2 < best) break;
    best = r2;
    bth += step;
    if (fabs(step) < 1e-14) break;
  }
  return sqrt(best);
}

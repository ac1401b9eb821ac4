/* rotor/fe_response.c — the linear steady unbalance response of a
 * finite-element rotor (whirl/rotor/fe_linear.h): q = Re(Q e^{iΩt}) with
 *   (K − Ω²M + iΩD) Q = Ω² (u_c − i u_s),  D = C + ΩG,
 * solved as the real system of twice the size
 *   [K − Ω²M   −ΩD    ] [Re Q]   [ Ω² u_c]
 *   [ΩD        K − Ω²M] [Im Q] = [−Ω² u_s]
 * by one sparse LU (whirl/linsol.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/linsol.h>
#include <whirl/rotor/fe_linear.h>

#include "fe_impl.h"

static void add_block(fe_trip *t, const whirl_fe_rotor *r, const whirl_fe_csc *D, double Om) {
  const int n = r->ndof;
  for (int b = 0; b < 2; ++b) {
    fe_trip_add_csc(t, &r->K, 1, b * n, b * n);
    fe_trip_add_csc(t, &r->M, -Om * Om, b * n, b * n);
  }
  fe_trip_add_csc(t, D, -Om, 0, n);
  fe_trip_add_csc(t, D, Om, n, 0);
}

int whirl_fe_unbalance_response(const whirl_fe_rotor *r, double Omega, double *q_re,
                                double *q_im, char *msg, size_t len) {
  if (!r || !q_re || !q_im || !(Omega >= 0) || !isfinite(Omega)) {
    if (msg && len) snprintf(msg, len, "whirl_fe_unbalance_response: bad arguments");
    return WHIRL_EINVAL;
  }
  const int n = r->ndof;
  whirl_fe_csc D, A;
  if (fe_damping(r, Omega, &D)) return WHIRL_ENOMEM;
  fe_trip t;
  fe_trip_init(&t, 2 * n);
  add_block(&t, r, &D, Omega);
  fe_csc_free(&D);
  if (fe_trip_to_csc(&t, &A)) return WHIRL_ENOMEM;
  double *x = malloc(2 * (size_t)n * sizeof *x);
  whirl_linsol *ls = whirl_linsol_alloc_sparse(2 * (size_t)n, A.p, A.i);
  int rc = x && ls ? whirl_linsol_factor(ls, A.x) : WHIRL_ENOMEM;
  if (!rc) {
    for (int k = 0; k < n; ++k) {
      x[k] = Omega * Omega * r->unb_c[k];
      x[n + k] = -Omega * Omega * r->unb_s[k];
    }
    rc = whirl_linsol_solve(ls, x, 1, 0);
  }
  if (!rc) {
    memcpy(q_re, x, (size_t)n * sizeof *x);
    memcpy(q_im, x + n, (size_t)n * sizeof *x);
  } else if (msg && len)
    snprintf(msg, len, "the unbalance response at %g rad/s: %s", Omega,
             rc == WHIRL_ENOMEM ? "out of memory" : "singular (undamped resonance?)");
  whirl_linsol_free(ls);
  free(x);
  fe_csc_free(&A);
  return rc;
}

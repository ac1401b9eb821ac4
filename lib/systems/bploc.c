/* lib/systems/bploc.c — constructor: the locus of branch points of
 * equilibria (AUTO's ISW = 2 and 3 at a BP).  See whirl/bploc.h for the
 * equations; the core differentiates them by differences (n is small).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/bploc.h>
#include <whirl/linsol.h>

#include "util/errmsg_impl.h"

struct whirl_bploc {
  whirl_system base, sys;
  size_t n, q, extra;
  int generic;
  double *J, *work, *pf, *fp, *fm; /* F_x (n x n), scratch, parameters, F at p_q +- h */
  char errmsg[WHIRL_ERRMSG_SIZE];
};

void whirl_bploc_params(const whirl_bploc *b, const double *Z, const double *p,
                        double *pfull) {
  if (pfull != p) memcpy(pfull, p, b->base.npar * sizeof *pfull);
  pfull[b->q] = Z[2 * b->n];
  if (b->generic) pfull[b->extra] = Z[2 * b->n + 1];
}

/* F + beta psi, F_x^T psi, psi^T F_q (central difference), psi^T psi - 1 */
static int bploc_F(const double *Z, const double *p, double *out, void *data) {
  whirl_bploc *b = data;
  const size_t n = b->n;
  const double *x = Z, *psi = Z + n, beta = b->generic ? 0.0 : Z[2 * n + 1];
  whirl_bploc_params(b, Z, p, b->pf);
  int rc = b->base.F(x, b->pf, out, b->base.data);
  if (rc != 0) return rc;
  for (size_t i = 0; i < n; ++i) out[i] += beta * psi[i];
  if ((rc = whirl_system_jacobian(&b->base, x, b->pf, b->J, b->work)) != 0) return rc;
  for (size_t j = 0; j < n; ++j) {
    double s = 0.0;
    for (size_t i = 0; i < n; ++i) s += b->J[i + n * j] * psi[i];
    out[n + j] = s;
  }
  const double pq = b->pf[b->q], h = 1e-6 * (1.0 + fabs(pq));
  b->pf[b->q] = pq + h;
  if ((rc = b->base.F(x, b->pf, b->fp, b->base.data)) != 0) return rc;
  b->pf[b->q] = pq - h;
  if ((rc = b->base.F(x, b->pf, b->fm, b->base.data)) != 0) return rc;
  b->pf[b->q] = pq;
  double g = 0.0, nn = 0.0;
  for (size_t i = 0; i < n; ++i) {
    g += psi[i] * (b->fp[i] - b->fm[i]) / (2.0 * h);
    nn += psi[i] * psi[i];
  }
  out[2 * n] = g;
  out[2 * n + 1] = nn - 1.0;
  return 0;
}

whirl_bploc *whirl_bploc_alloc(const whirl_system *base, size_t q, int generic, size_t extra,
                               char *errbuf, size_t errlen) {
  const char *why = NULL;
  if (!base || !base->F || base->n < 1) why = "base system needs F and n >= 1";
  else if (q >= base->npar) why = "the branch point's parameter is not a parameter of the base";
  else if (generic && (extra >= base->npar || extra == q))
    why = "a generic branch-point locus needs a third parameter, other than the BP's";
  if (why) {
    WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "whirl_bploc_alloc: %s", why);
    return NULL;
  }
  const size_t n = base->n;
  whirl_bploc *b = calloc(1, sizeof *b);
  if (!b) goto nomem;
  b->base = *base;
  b->n = n, b->q = q, b->extra = extra, b->generic = generic != 0;
  b->J = calloc(n * n, sizeof *b->J);
  b->work = calloc(2 * n + 2 + base->nnz, sizeof *b->work); /* max(2n, nnz) */
  b->pf = calloc(base->npar, sizeof *b->pf);
  b->fp = calloc(n, sizeof *b->fp);
  b->fm = calloc(n, sizeof *b->fm);
  if (!b->J || !b->work || !b->pf || !b->fp || !b->fm) goto nomem;
  whirl_system *s = &b->sys;
  s->name = generic ? "branch-point curve (generic)" : "branch-point curve (symmetric)";
  s->n = 2 * n + 2;
  s->npar = base->npar;
  s->F = bploc_F;
  s->p_names = base->p_names;
  s->data = b;
  return b;
nomem:
  whirl_bploc_free(b);
  WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "whirl_bploc_alloc: out of memory");
  return NULL;
}

void whirl_bploc_free(whirl_bploc *b) {
  if (!b) return;
  free(b->J), free(b->work), free(b->pf), free(b->fp), free(b->fm);
  free(b);
}

const whirl_system *whirl_bploc_system(const whirl_bploc *b) { return &b->sys; }
size_t whirl_bploc_size(const whirl_bploc *b) { return 2 * b->n + 2; }
const char *whirl_bploc_errmsg(const whirl_bploc *b) { return b->errmsg; }

int whirl_bploc_init(whirl_bploc *b, const double *x, const double *p, double *Z) {
  const size_t n = b->n;
  int rc = whirl_system_jacobian(&b->base, x, p, b->J, b->work);
  if (rc != 0)
    return WHIRL_FAIL(b, rc < 0 ? rc : WHIRL_EDOMAIN,
                      "branch-point locus start: the Jacobian failed (%d)", rc);
  double *T = calloc(n * n, sizeof *T), sv = 0.0;
  if (!T) return WHIRL_FAIL(b, WHIRL_ENOMEM, "branch-point locus start: out of memory");
  for (size_t i = 0; i < n; ++i) /* F_x^T: its null vector is psi */
    for (size_t j = 0; j < n; ++j) T[j + n * i] = b->J[i + n * j];
  rc = whirl_null_vectors(n, n, T, 1, Z + n, &sv);
  free(T);
  if (rc != WHIRL_OK) return WHIRL_FAIL(b, rc, "branch-point locus start: SVD failed");
  memcpy(Z, x, n * sizeof *Z);
  Z[2 * n] = p[b->q];
  Z[2 * n + 1] = b->generic ? p[b->extra] : 0.0;
  b->errmsg[0] = 0;
  return WHIRL_OK;
}

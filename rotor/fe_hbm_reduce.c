/* rotor/fe_hbm_reduce.c — Hill's stability of a large rotor on its
 * Craig–Bampton reduction (stability 3, "reduced"): the rotor's DOFs are
 * the m nonlinear DOFs b, kept as they are, and the interior i, replaced by
 *   q_i = Ψ q_b + Φ η,   Ψ = −K_ii⁻¹ K_ib   (static constraint modes),
 * Φ the n_η lowest modes of the interior held at b (K_ii φ = ω² M_ii φ,
 * the symmetric parts), every one up to a cutoff frequency ω_c
 * (Craig & Bampton, AIAA J. 6 (1968) 1313; Géradin & Rixen, Mechanical
 * Vibrations, 3rd ed., Wiley 2015, §6.5).  The reduced rotor has the
 * matrices Tᵀ A T of T = [I 0; Ψ Φ] for A = M, C, G, K, and the nonlinear
 * elements on its b DOFs, unchanged: the same orbit gives the same element
 * Jacobians, and the sparse Hill method (fe_hbm_hill_sparse.c) runs on
 * m + n_η DOFs instead of ndof.
 *
 * Why it is accurate where it matters: the exponents that decide stability
 * are those within ω/2 of 0 in the Hill strip, copies λ − i k ω (|k| ≤ H)
 * of motions at frequencies up to (H + ½) ω.  The constraint modes make
 * the reduction exact at zero frequency and the retained modes at their
 * own; the error of a mode at frequency ω_j falls like (ω_j/ω_c)² and
 * beyond (Géradin & Rixen §6.5), so ω_c = κ (H + ½) ω_max, κ = 3 by
 * default, leaves it small; doc/fe-hbm.md has it measured against the
 * full sparse Hill method.  The congruence keeps M, K symmetric, G skew
 * and C semi-definite, so the reduction adds no energy: a conservative
 * mode stays on the imaginary axis, none turns unstable by the reduction.
 *
 * The reduced rotor lays its DOFs out as a rotor does (4 per node, 2 per
 * pedestal): node j of the reduced rotor carries the j-th nonlinear node's
 * y, z and two modal coordinates, further nodes four modal coordinates
 * each, then the pedestals of the nonlinear elements; n_η is rounded up
 * to fill the slots.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe_hbm_impl.h"
#include "fe_impl.h"

extern void dgetrf_(const int *m, const int *n, double *a, const int *lda,
                    int *ipiv, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs,
                    const double *a, const int *lda, const int *ipiv,
                    double *b, const int *ldb, int *info, size_t ltrans);
extern void dsygvx_(const int *itype, const char *jobz, const char *range,
                    const char *uplo, const int *n, double *a, const int *lda,
                    double *b, const int *ldb, const double *vl,
                    const double *vu, const int *il, const int *iu,
                    const double *abstol, int *m, double *w, double *z,
                    const int *ldz, double *work, const int *lwork, int *iwork,
                    int *ifail, int *info, size_t, size_t, size_t);

/* The most modes of the held rotor computed (dsygvx); the reduced
 * interior is dense, so its condensation's banded LU takes up to 33
 * coordinates (kl + ku ≤ FE_BAND_MAX), UMFPACK more. */
#define CB_MODES_MAX 96
/* Blocks of inertia-relief (Krylov) vectors after the modes */
#ifndef CB_KRYLOV_BLOCKS
#define CB_KRYLOV_BLOCKS 1
#endif

/* The dense column-major copy of the rows/columns rows × cols of A. */
static void dense_block(const whirl_fe_csc *A, const int *inv_r, int nr,
                        const int *inv_c, double *D) {
  for (int c = 0; c < A->n; ++c) {
    int jc = inv_c[c];
    if (jc < 0) continue;
    for (int q = A->p[c]; q < A->p[c + 1]; ++q) {
      int ir = inv_r[A->i[q]];
      if (ir >= 0) D[ir + (size_t)nr * jc] += A->x[q];
    }
  }
}

/* The slot layout: slot[j] = reduced DOF of the j-th basis vector (the m
 * nonlinear DOFs first, in fe_aft's order, then the modes). */
typedef struct cb_layout {
  int nnode, nped, ndof, neta;
  int *node_new;  /* rotor node → reduced node or −1 */
  int *ped_new;   /* rotor pedestal → reduced pedestal or −1 */
  int *slot;      /* m + neta */
} cb_layout;

static int layout_build(const whirl_fe_rotor *r, const fe_aft *a, int want,
                        int max, cb_layout *L) {
  memset(L, 0, sizeof *L);
  L->node_new = malloc((size_t)(r->nnode + 1) * sizeof *L->node_new);
  L->ped_new = malloc((size_t)(r->npedestal + 1) * sizeof *L->ped_new);
  if (!L->node_new || !L->ped_new) return WHIRL_ENOMEM;
  for (int j = 0; j < r->nnode; ++j) L->node_new[j] = -1;
  for (int j = 0; j < r->npedestal; ++j) L->ped_new[j] = -1;
  int nb = 0;
  for (int j = 0; j < a->m; ++j) { /* increasing DOF order: nodes first */
    int d = a->dof[j];
    if (d < 4 * r->nnode) {
      if (L->node_new[d / 4] < 0) L->node_new[d / 4] = nb++;
    } else {
      int p = (d - 4 * r->nnode) / 2;
      if (L->ped_new[p] < 0) L->ped_new[p] = L->nped++;
    }
  }
  int extra = want > 2 * nb ? (want - 2 * nb + 3) / 4 : 0;
  if (2 * nb + 4 * extra > max) extra = (max - 2 * nb) / 4;
  if (extra < 0) return WHIRL_EINVAL; /* too few interior coordinates */
  L->nnode = nb + extra;
  L->neta = 2 * nb + 4 * extra;
  L->ndof = 4 * L->nnode + 2 * L->nped;
  if (L->ndof != a->m + L->neta) return WHIRL_EINVAL; /* a node without y, z */
  L->slot = malloc((size_t)L->ndof * sizeof *L->slot);
  if (!L->slot) return WHIRL_ENOMEM;
  char *used = calloc((size_t)L->ndof, 1);
  if (!used) return WHIRL_ENOMEM;
  for (int j = 0; j < a->m; ++j) {
    int d = a->dof[j], s;
    if (d < 4 * r->nnode) s = 4 * L->node_new[d / 4] + d % 4;
    else s = 4 * L->nnode + 2 * L->ped_new[(d - 4 * r->nnode) / 2] + (d - 4 * r->nnode) % 2;
    L->slot[j] = s;
    used[s] = 1;
  }
  for (int s = 0, j = a->m; s < L->ndof; ++s)
    if (!used[s]) L->slot[j++] = s;
  free(used);
  return WHIRL_OK;
}

static void layout_free(cb_layout *L) {
  free(L->node_new);
  free(L->ped_new);
  free(L->slot);
}

/* The basis T (ndof × nr, columns in slot order): the constraint modes
 * and the fixed-interface modes, from the interior blocks.  neta_max
 * modes are computed, all of them up to wcut kept (at least the layout's
 * minimum); *neta_want the count wanted. */
typedef struct cb_work {
  int nd, ni, m;
  int *inv_i, *inv_b;           /* DOF → interior / boundary index or −1 */
  double *Kii, *Mii, *Kib, *Psi, *Phi, *w;
  double *Klu;                  /* K_ii's LU (LAPACK dgetrf) */
  int *ipiv;
  double *Eta;                  /* ni × neta: the interior coordinates */
} cb_work;

static void work_free(cb_work *w) {
  void *p[] = {w->inv_i, w->inv_b, w->Kii, w->Mii, w->Kib, w->Psi,
               w->Phi, w->w, w->Klu, w->ipiv, w->Eta};
  for (size_t i = 0; i < sizeof p / sizeof *p; ++i) free(p[i]);
}

static int work_init(cb_work *w, const whirl_fe_rotor *r, const fe_aft *a) {
  memset(w, 0, sizeof *w);
  w->nd = r->ndof;
  w->m = a->m;
  w->ni = r->ndof - a->m;
  size_t nd = (size_t)w->nd, ni = (size_t)w->ni, m = (size_t)w->m;
  w->inv_i = malloc(nd * sizeof *w->inv_i);
  w->inv_b = malloc(nd * sizeof *w->inv_b);
  w->Kii = calloc(ni * ni, sizeof *w->Kii);
  w->Mii = calloc(ni * ni, sizeof *w->Mii);
  w->Kib = calloc(ni * m, sizeof *w->Kib);
  w->Psi = malloc(ni * m * sizeof *w->Psi);
  w->w = malloc(ni * sizeof *w->w);
  if (!w->inv_i || !w->inv_b || !w->Kii || !w->Mii || !w->Kib ||
      !w->Psi || !w->w)
    return WHIRL_ENOMEM;
  for (size_t d = 0; d < nd; ++d) w->inv_i[d] = w->inv_b[d] = -1;
  for (int j = 0; j < a->m; ++j) w->inv_b[a->dof[j]] = j;
  for (int d = 0, k = 0; d < w->nd; ++d)
    if (w->inv_b[d] < 0) w->inv_i[d] = k++;
  dense_block(&r->K, w->inv_i, w->ni, w->inv_i, w->Kii);
  dense_block(&r->M, w->inv_i, w->ni, w->inv_i, w->Mii);
  dense_block(&r->K, w->inv_i, w->ni, w->inv_b, w->Kib);
  return WHIRL_OK;
}

/* Ψ = −K_ii⁻¹ K_ib (K_ii as it is: bearings may make it unsymmetric). */
static int constraint_modes(cb_work *w, char *err, size_t len) {
  int ni = w->ni, m = w->m, info = 0;
  size_t n2 = (size_t)ni * ni;
  double *A = w->Klu = malloc(n2 * sizeof *A);
  int *ipiv = w->ipiv = malloc((size_t)(ni ? ni : 1) * sizeof *ipiv);
  if (!A || !ipiv) return WHIRL_ENOMEM;
  memcpy(A, w->Kii, n2 * sizeof *A);
  for (size_t k = 0; k < (size_t)ni * m; ++k) w->Psi[k] = -w->Kib[k];
  dgetrf_(&ni, &ni, A, &ni, ipiv, &info);
  if (info == 0) dgetrs_("N", &ni, &m, A, &ni, ipiv, w->Psi, &ni, &info, 1);
  if (info != 0)
    return WHIRL_ERRMSG(err, len, WHIRL_ESINGULAR,
                        "reduced Hill: the rotor held at its nonlinear DOFs "
                        "is singular (a part free of them): use the sparse "
                        "method");
  return WHIRL_OK;
}

/* The lowest nmax modes of the held interior (symmetric parts of K_ii,
 * M_ii), LAPACK dsygvx; *got of them, ω² ascending in w->w. */
static int interior_modes(cb_work *w, int nmax, int *got, char *err, size_t len) {
  int ni = w->ni, one = 1, lwork = -1, info = 0, il = 1, iu = nmax;
  size_t n2 = (size_t)ni * ni;
  double vl = 0, vu = 0, abstol = 0, q = 0;
  double *Ks = malloc(n2 * sizeof *Ks), *Ms = malloc(n2 * sizeof *Ms);
  int *iwork = malloc(6 * (size_t)ni * sizeof *iwork);
  w->Phi = malloc((size_t)ni * nmax * sizeof *w->Phi);
  if (!Ks || !Ms || !iwork || !w->Phi) { free(Ks); free(Ms); free(iwork); return WHIRL_ENOMEM; }
  for (int c = 0; c < ni; ++c)
    for (int i = 0; i < ni; ++i) {
      Ks[i + (size_t)ni * c] = 0.5 * (w->Kii[i + (size_t)ni * c] + w->Kii[c + (size_t)ni * i]);
      Ms[i + (size_t)ni * c] = 0.5 * (w->Mii[i + (size_t)ni * c] + w->Mii[c + (size_t)ni * i]);
    }
  int *ifail = iwork + 5 * (size_t)ni;
  dsygvx_(&one, "V", "I", "L", &ni, Ks, &ni, Ms, &ni, &vl, &vu, &il, &iu,
          &abstol, got, w->w, w->Phi, &ni, &q, &lwork, iwork, ifail, &info, 1, 1, 1);
  lwork = info == 0 ? (int)q : 8 * ni;
  double *work = malloc((size_t)lwork * sizeof *work);
  if (work)
    dsygvx_(&one, "V", "I", "L", &ni, Ks, &ni, Ms, &ni, &vl, &vu, &il, &iu,
            &abstol, got, w->w, w->Phi, &ni, work, &lwork, iwork, ifail, &info, 1, 1, 1);
  free(work);
  free(Ks);
  free(Ms);
  free(iwork);
  if (!work) return WHIRL_ENOMEM;
  if (info != 0)
    return WHIRL_ERRMSG(err, len, WHIRL_ELAPACK,
                        "reduced Hill: the modes of the rotor held at its "
                        "nonlinear DOFs (LAPACK dsygvx info %d): use the "
                        "sparse method", info);
  return WHIRL_OK;
}

/* y = M_ii x */
static void mult_m(const cb_work *w, const double *x, double *y) {
  size_t ni = (size_t)w->ni;
  memset(y, 0, ni * sizeof *y);
  for (size_t c = 0; c < ni; ++c)
    for (size_t i = 0; i < ni; ++i) y[i] += w->Mii[i + ni * c] * x[c];
}

/* v := v − E (Eᵀ M v) over the first ne columns of E, twice (classical
 * Gram–Schmidt with reorthogonalisation, in the M inner product), then
 * v / |v|_M.  0, or 1 when v lies in their span. */
static int m_orthonormalise(const cb_work *w, const double *E, int ne, double *v,
                            double *Mv) {
  size_t ni = (size_t)w->ni;
  double n0 = 0, n1 = 0;
  mult_m(w, v, Mv);
  for (size_t i = 0; i < ni; ++i) n0 += v[i] * Mv[i];
  for (int pass = 0; pass < 2; ++pass) {
    for (int e = 0; e < ne; ++e) {
      const double *col = E + ni * e;
      double c = 0;
      for (size_t i = 0; i < ni; ++i) c += col[i] * Mv[i];
      for (size_t i = 0; i < ni; ++i) v[i] -= c * col[i];
    }
    mult_m(w, v, Mv);
  }
  for (size_t i = 0; i < ni; ++i) n1 += v[i] * Mv[i];
  if (!(n1 > 1e-20 * n0)) return 1;
  for (size_t i = 0; i < ni; ++i) v[i] /= sqrt(n1);
  return 0;
}

/* The interior coordinates Eta: the nmodes lowest modes, then nblocks
 * blocks of m Krylov vectors (K_ii⁻¹ M_ii)^j Ψ, j = 1..nblocks,
 * M-orthonormalised against all before them: the inertia of the
 * constraint modes, which the truncated modes miss, relieved to the next
 * orders (the error of a motion at frequency s falls from |s/ω_c|² to
 * |s/ω_c|^(2 + 2 nblocks); Craig & Chang's static-complete bases, and the
 * Krylov enrichment of Bampton & Craig's method in Géradin & Rixen §6.5). */
/* The constraint modes that reach the interior (a pedestal held by
 * nonlinear DOFs alone has Ψ = 0: no inertia to relieve), as a list. */
static int moving_constraints(const cb_work *w, int *list) {
  int k = 0;
  for (int j = 0; j < w->m; ++j) {
    const double *c = w->Psi + (size_t)w->ni * j;
    int any = 0;
    for (int i = 0; i < w->ni && !any; ++i) any = c[i] != 0;
    if (any) list[k++] = j;
  }
  return k;
}

static int interior_coordinates(cb_work *w, int nmodes, int nblocks, char *err,
                                size_t len) {
  size_t ni = (size_t)w->ni;
  int *list = malloc((size_t)w->m * sizeof *list);
  if (!list) return WHIRL_ENOMEM;
  int nk = moving_constraints(w, list);
  int ne = nmodes + nblocks * nk, info = 0, one = 1;
  w->Eta = malloc(ni * (size_t)(ne ? ne : 1) * sizeof *w->Eta);
  double *Mv = malloc(ni * sizeof *Mv);
  if (!w->Eta || !Mv) { free(Mv); free(list); return WHIRL_ENOMEM; }
  memcpy(w->Eta, w->Phi, ni * (size_t)nmodes * sizeof *w->Eta);
  for (int b = 0, e = nmodes; b < nblocks; ++b) {
    for (int j = 0; j < nk; ++j, ++e) {
      /* from Ψ's column, then from the previous block's vector */
      const double *from = b == 0 ? w->Psi + ni * (size_t)list[j]
                                  : w->Eta + ni * (size_t)(e - nk);
      double *v = w->Eta + ni * (size_t)e;
      mult_m(w, from, v);
      int ni_ = w->ni;
      dgetrs_("N", &ni_, &one, w->Klu, &ni_, w->ipiv, v, &ni_, &info, 1);
      if (info || m_orthonormalise(w, w->Eta, e, v, Mv)) {
        free(Mv);
        free(list);
        return WHIRL_ERRMSG(err, len, WHIRL_ESINGULAR,
                            "reduced Hill: the inertia-relief vectors are "
                            "dependent: use the sparse method");
      }
    }
  }
  free(Mv);
  free(list);
  return WHIRL_OK;
}

/* T[nd × nr] in slot order. */
static void basis(const cb_work *w, const cb_layout *L, double *T) {
  size_t nd = (size_t)w->nd;
  memset(T, 0, nd * (size_t)L->ndof * sizeof *T);
  for (int j = 0; j < w->m; ++j) {
    double *col = T + nd * L->slot[j];
    for (int d = 0; d < w->nd; ++d) {
      if (w->inv_b[d] == j) col[d] = 1;
      else if (w->inv_i[d] >= 0) col[d] = w->Psi[w->inv_i[d] + (size_t)w->ni * j];
    }
  }
  for (int e = 0; e < L->neta; ++e) {
    double *col = T + nd * L->slot[w->m + e];
    for (int d = 0; d < w->nd; ++d)
      if (w->inv_i[d] >= 0) col[d] = w->Eta[w->inv_i[d] + (size_t)w->ni * e];
  }
}

/* Ar = Tᵀ A T as compressed columns (exact zeros dropped). */
static int project(const whirl_fe_csc *A, const double *T, int nd, int nr,
                   double *AT, whirl_fe_csc *Ar) {
  memset(AT, 0, (size_t)nd * nr * sizeof *AT);
  for (int j = 0; j < nr; ++j) fe_csc_gemv(A, 1.0, T + (size_t)nd * j, AT + (size_t)nd * j);
  fe_trip t;
  fe_trip_init(&t, nr);
  for (int c = 0; c < nr; ++c)
    for (int r = 0; r < nr; ++r) {
      const double *tr = T + (size_t)nd * r, *ac = AT + (size_t)nd * c;
      double s = 0;
      for (int d = 0; d < nd; ++d) s += tr[d] * ac[d];
      if (s != 0) fe_trip_add(&t, r, c, s);
    }
  return fe_trip_to_csc(&t, Ar);
}

/* The reduced rotor: matrices, and the nonlinear elements renumbered. */
static whirl_fe_rotor *reduced_rotor(const whirl_fe_rotor *r, const cb_layout *L,
                                     const double *T) {
  whirl_fe_rotor *rr = calloc(1, sizeof *rr);
  double *AT = malloc((size_t)r->ndof * L->ndof * sizeof *AT);
  if (!rr || !AT) { free(rr); free(AT); return NULL; }
  rr->nnode = L->nnode;
  rr->npedestal = L->nped;
  rr->ndof = L->ndof;
  rr->speed_min = r->speed_min;
  rr->speed_max = r->speed_max;
  rr->omega_ref = r->omega_ref;
  size_t nr = (size_t)L->ndof;
  rr->f0 = calloc(nr, sizeof *rr->f0);
  rr->unb_c = calloc(nr, sizeof *rr->unb_c);
  rr->unb_s = calloc(nr, sizeof *rr->unb_s);
  rr->nl = malloc((size_t)r->nnl * sizeof *rr->nl);
  rr->title = calloc(1, 1);
  int rc = (rr->f0 && rr->unb_c && rr->unb_s && rr->nl && rr->title) ? 0 : WHIRL_ENOMEM;
  const whirl_fe_csc *A[4] = {&r->M, &r->C, &r->G, &r->K};
  whirl_fe_csc *B[4] = {&rr->M, &rr->C, &rr->G, &rr->K};
  for (int k = 0; k < 4 && !rc; ++k) rc = project(A[k], T, r->ndof, L->ndof, AT, B[k]);
  free(AT);
  if (rc) { whirl_fe_rotor_free(rr); return NULL; }
  rr->nnl = r->nnl;
  for (int e = 0; e < r->nnl; ++e) {
    rr->nl[e] = r->nl[e];
    rr->nl[e].node = L->node_new[r->nl[e].node];
    if (r->nl[e].pedestal >= 0) rr->nl[e].pedestal = L->ped_new[r->nl[e].pedestal];
  }
  return rr;
}

/* Interior modes to keep: every one with ω ≤ wcut, at least 4. */
static int modes_wanted(const double *w2, int got, double wcut) {
  int k = 0;
  while (k < got && w2[k] <= wcut * wcut) ++k;
  return k < 4 ? (got < 4 ? got : 4) : k;
}

int fe_cb_build(const whirl_fe_rotor *r, const fe_aft *a, double wcut,
                fe_cb *cb, char *err, size_t len) {
  memset(cb, 0, sizeof *cb);
  cb_work w;
  cb_layout L;
  memset(&L, 0, sizeof L);
  int got = 0, rc = work_init(&w, r, a);
  int nmax = w.ni < CB_MODES_MAX ? w.ni : CB_MODES_MAX;
  if (!rc) rc = constraint_modes(&w, err, len);
  if (!rc) rc = interior_modes(&w, nmax, &got, err, len);
  /* the inertia-relief blocks unless the modes wanted are (nearly) all:
   * then they span the interior, exactly when all are kept */
  int *moving = malloc((size_t)a->m * sizeof *moving);
  if (!rc && !moving) rc = WHIRL_ENOMEM;
  const int nk = rc ? 0 : moving_constraints(&w, moving);
  free(moving);
  const int want = rc ? 0 : modes_wanted(w.w, got, wcut);
  const int nblocks = want + CB_KRYLOV_BLOCKS * nk < got ? CB_KRYLOV_BLOCKS : 0;
  const int nkry = nblocks * nk;
  if (!rc && (rc = layout_build(r, a, want + nkry, got + nkry, &L)) != WHIRL_ENOMEM && rc)
    rc = WHIRL_ERRMSG(err, len, WHIRL_EINVAL,
                      "reduced Hill: the rotor has too few DOFs besides the "
                      "nonlinear ones: use the dense or sparse method");
  if (!rc) rc = interior_coordinates(&w, L.neta - nkry, nblocks, err, len);
  double *T = NULL;
  if (!rc) {
    T = malloc((size_t)r->ndof * L.ndof * sizeof *T);
    if (!T) rc = WHIRL_ENOMEM;
  }
  if (!rc) {
    basis(&w, &L, T);
    cb->r = reduced_rotor(r, &L, T);
    if (!cb->r) rc = WHIRL_ENOMEM;
  }
  if (!rc) {
    cb->m = a->m;
    cb->neta = L.neta;
    cb->wcut = wcut;
    cb->wtop = L.neta > nkry ? sqrt(w.w[L.neta - nkry - 1]) : 0;
    cb->pos = malloc((size_t)a->m * sizeof *cb->pos);
    if (!cb->pos) rc = WHIRL_ENOMEM;
    for (int j = 0; !rc && j < a->m; ++j) cb->pos[j] = L.slot[j];
  }
  if (rc == WHIRL_ENOMEM) WHIRL_ERRMSG(err, len, rc, "reduced Hill: out of memory");
  free(T);
  layout_free(&L);
  work_free(&w);
  if (rc) fe_cb_free(cb);
  return rc;
}

void fe_cb_free(fe_cb *cb) {
  whirl_fe_hbm_free(cb->h);
  whirl_fe_rotor_free(cb->r);
  free(cb->pos);
  free(cb->q);
  memset(cb, 0, sizeof *cb);
}

/* (Re)build h->cb for response frequencies up to w: the cutoff covers the
 * rotor's speed range at once, and 1.5 times the frequency beyond it. */
static int cb_ensure(whirl_fe_hbm *h, double w) {
  const double span = h->o.hill_cutoff * (h->H + 0.5);
  if (h->cb.h && span * w <= h->cb.wcut) return WHIRL_OK;
  double wmax = h->r->speed_max / h->o.nu;
  double wcut = span * (w > wmax ? 1.5 * w : wmax);
  fe_cb_free(&h->cb);
  int rc = fe_cb_build(h->r, &h->aft, wcut, &h->cb, h->errmsg, sizeof h->errmsg);
  if (rc) return rc;
  whirl_fe_hbm_options o = h->o;
  o.stability = 2;
  o.uncondensed = 0;
  o.nsamples = (size_t)h->N;
  o.length_scale = h->Ls;
  o.force_scale = h->Fs;
  char err[256];
  h->cb.h = whirl_fe_hbm_alloc(h->cb.r, &o, err, sizeof err);
  h->cb.q = calloc((size_t)h->cb.r->ndof * h->L, sizeof *h->cb.q);
  if (!h->cb.h || !h->cb.q) {
    rc = h->cb.h ? WHIRL_ENOMEM : WHIRL_EINVAL;
    WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, rc, "reduced Hill: %s",
                 h->cb.h ? "out of memory" : err);
    fe_cb_free(&h->cb);
    return rc;
  }
  /* the Ritz values to 1e-8 relative: three orders below the reduction's
   * own error on the exponents (1e-5 omega, doc/fe-hbm.md), 15 % of the
   * run on compressor.rotor, no stable flag changed */
  h->cb.h->hill_tol = 1e-8;
  if (h->cb.h->hill != 2) {
    fe_cb_free(&h->cb);
    return WHIRL_ERRMSG(h->errmsg, sizeof h->errmsg, WHIRL_EINVAL,
                        "reduced Hill: the reduction is too small for the "
                        "sparse method: use the dense one");
  }
  return WHIRL_OK;
}

int fe_hill_reduced(whirl_fe_hbm *h, const double *X, const double *p,
                    double *re, double *im, size_t *m) {
  double w = p[WHIRL_FE_P_OMEGA] / h->o.nu;
  int rc = cb_ensure(h, w);
  h->cb_unavailable = rc != 0;
  if (rc) return rc;
  fe_cb *cb = &h->cb;
  int ndr = cb->r->ndof;
  for (int blk = 0; blk < h->L; ++blk)
    for (int j = 0; j < cb->m; ++j)
      cb->q[(size_t)blk * ndr + cb->pos[j]] =
          h->Ls * X[(size_t)blk * h->b + h->lin.pos[j]];
  rc = fe_hill_sparse(cb->h, cb->q, p, h->o.hill_nev, re, im, m);
  if (rc) memcpy(h->errmsg, cb->h->errmsg, sizeof h->errmsg);
  return rc;
}

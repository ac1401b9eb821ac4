/* test/fe_chain.h — a synthetic finite-element rotor for the tests and
 * benchmarks of the harmonic balance (issue 16), built by hand into a
 * whirl_fe_rotor (the rotor file reader and the Timoshenko assembly are not
 * used): a uniform steel shaft of Euler–Bernoulli beam elements (the
 * standard 4×4 element per plane, Przemieniecki 1968) with lumped masses,
 * a disk with its gyroscopic coupling and an unbalance, a linear bearing at
 * the first node, a centring spring at the last, Rayleigh damping β K, and
 * nonlinear elements chosen by the caller.  Static inline: one copy per
 * program.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_TEST_FE_CHAIN_H
#define WHIRL_TEST_FE_CHAIN_H

#include <stdlib.h>
#include <string.h>

#include <whirl/rotor/fe.h>

typedef struct fe_chain_opts {
  int nnode;           /* ≥ 2 */
  double length;       /* m */
  double EI, rhoA;     /* N m², kg/m */
  int disk_node;       /* −1: none */
  double disk_m, disk_Id, disk_Ip, me; /* kg, kg m², kg m², unbalance kg m */
  double kb, cb;       /* linear bearing at node 0 */
  double ks;           /* centring spring at the last node (to ground, or
                          to the pedestal) */
  double beta;         /* C = β K + bearing dampers */
  int pedestal;        /* 1: a pedestal under the last node */
  double mp, kp, cp;   /* its mass, spring and damper to ground */
  double gravity;      /* static load −g·mass in y, m/s² */
  int nnl;
  whirl_fe_nl nl[4];
} fe_chain_opts;

static inline void fe_chain_defaults(fe_chain_opts *o, int nnode) {
  memset(o, 0, sizeof *o);
  o->nnode = nnode;
  o->length = 1.0;
  o->EI = 6.44e4;
  o->rhoA = 15.3;
  o->disk_node = nnode / 2;
  o->disk_m = 20.0;
  o->disk_Id = 0.1;
  o->disk_Ip = 0.2;
  o->me = 1e-4;
  o->kb = 1e7;
  o->cb = 200.0;
  o->ks = 5e5;
  o->beta = 2e-5;
  o->mp = 10.0;
  o->kp = 2e7;
  o->cp = 500.0;
}

/* triplets → compressed columns (duplicates summed) */
typedef struct fe_trip { int n, nz, cap; int *i, *j; double *x; } fe_trip;

static inline void fe_trip_add(fe_trip *t, int i, int j, double x) {
  if (x == 0) return;
  if (t->nz == t->cap) {
    t->cap = t->cap ? 2 * t->cap : 256;
    t->i = realloc(t->i, (size_t)t->cap * sizeof *t->i);
    t->j = realloc(t->j, (size_t)t->cap * sizeof *t->j);
    t->x = realloc(t->x, (size_t)t->cap * sizeof *t->x);
  }
  t->i[t->nz] = i; t->j[t->nz] = j; t->x[t->nz++] = x;
}

static inline void fe_trip_csc(fe_trip *t, whirl_fe_csc *A) {
  int n = t->n;
  A->n = n;
  A->p = calloc((size_t)n + 1, sizeof *A->p);
  A->i = malloc((size_t)(t->nz ? t->nz : 1) * sizeof *A->i);
  A->x = malloc((size_t)(t->nz ? t->nz : 1) * sizeof *A->x);
  double *col = calloc((size_t)n, sizeof *col);
  char *hit = calloc((size_t)n, 1);
  int *cnt = calloc((size_t)n + 1, sizeof *cnt);
  for (int q = 0; q < t->nz; ++q) cnt[t->j[q] + 1]++;
  for (int c = 0; c < n; ++c) cnt[c + 1] += cnt[c];
  int *ord = malloc((size_t)(t->nz ? t->nz : 1) * sizeof *ord);
  int *fill = calloc((size_t)n, sizeof *fill);
  for (int q = 0; q < t->nz; ++q) ord[cnt[t->j[q]] + fill[t->j[q]]++] = q;
  int nz = 0;
  for (int c = 0; c < n; ++c) {
    for (int s = cnt[c]; s < cnt[c + 1]; ++s) {
      int q = ord[s];
      col[t->i[q]] += t->x[q];
      hit[t->i[q]] = 1;
    }
    for (int r = 0; r < n; ++r) /* O(n²) but fine up to a few thousand */
      if (hit[r]) { A->i[nz] = r; A->x[nz++] = col[r]; col[r] = 0; hit[r] = 0; }
    A->p[c + 1] = nz;
  }
  free(col); free(hit); free(cnt); free(ord); free(fill);
  free(t->i); free(t->j); free(t->x);
  memset(t, 0, sizeof *t);
}

/* beam element between nodes a and a+1, both planes: (y, θz) and (z, θy) */
static inline void fe_chain_beam(fe_trip *K, fe_trip *M, int a, double l,
                                 double EI, double rhoA) {
  double k[4][4] = {{12, 6 * l, -12, 6 * l},
                    {6 * l, 4 * l * l, -6 * l, 2 * l * l},
                    {-12, -6 * l, 12, -6 * l},
                    {6 * l, 2 * l * l, -6 * l, 4 * l * l}};
  int py[4] = {4 * a + 0, 4 * a + 3, 4 * a + 4, 4 * a + 7};
  int pz[4] = {4 * a + 1, 4 * a + 2, 4 * a + 5, 4 * a + 6};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      fe_trip_add(K, py[i], py[j], EI / (l * l * l) * k[i][j]);
      fe_trip_add(K, pz[i], pz[j], EI / (l * l * l) * k[i][j]);
    }
  for (int s = 0; s < 2; ++s) { /* lumped: half the element mass at each end */
    int nd = a + s;
    for (int c = 0; c < 2; ++c) fe_trip_add(M, 4 * nd + c, 4 * nd + c, 0.5 * rhoA * l);
    for (int c = 2; c < 4; ++c)
      fe_trip_add(M, 4 * nd + c, 4 * nd + c, rhoA * l * l * l / 24.0);
  }
}

static inline void fe_chain_free(whirl_fe_rotor *r) {
  if (!r) return;
  whirl_fe_csc *A[4] = {&r->M, &r->C, &r->G, &r->K};
  for (int s = 0; s < 4; ++s) { free(A[s]->p); free(A[s]->i); free(A[s]->x); }
  free(r->f0); free(r->unb_c); free(r->unb_s); free(r->nl);
  free(r);
}

static inline whirl_fe_rotor *fe_chain_build(const fe_chain_opts *o) {
  whirl_fe_rotor *r = calloc(1, sizeof *r);
  int nn = o->nnode, np = o->pedestal ? 1 : 0, n = 4 * nn + 2 * np;
  r->nnode = nn; r->npedestal = np; r->ndof = n;
  fe_trip K = {n, 0, 0, 0, 0, 0}, M = K, C = K, G = K;
  double l = o->length / (nn - 1);
  for (int a = 0; a + 1 < nn; ++a) fe_chain_beam(&K, &M, a, l, o->EI, o->rhoA);
  int dn = o->disk_node;
  if (dn >= 0) {
    for (int c = 0; c < 2; ++c) fe_trip_add(&M, 4 * dn + c, 4 * dn + c, o->disk_m);
    for (int c = 2; c < 4; ++c) fe_trip_add(&M, 4 * dn + c, 4 * dn + c, o->disk_Id);
    fe_trip_add(&G, 4 * dn + 2, 4 * dn + 3, o->disk_Ip);
    fe_trip_add(&G, 4 * dn + 3, 4 * dn + 2, -o->disk_Ip);
  }
  for (int c = 0; c < 2; ++c) {
    fe_trip_add(&K, c, c, o->kb);
    fe_trip_add(&C, c, c, o->cb);
    int d = 4 * (nn - 1) + c, pd = 4 * nn + c;
    fe_trip_add(&K, d, d, o->ks);
    if (np) {
      fe_trip_add(&K, pd, pd, o->ks + o->kp);
      fe_trip_add(&K, d, pd, -o->ks);
      fe_trip_add(&K, pd, d, -o->ks);
      fe_trip_add(&M, pd, pd, o->mp);
      fe_trip_add(&C, pd, pd, o->cp);
    }
  }
  /* Rayleigh part β K (copy of the K triplets before conversion) */
  for (int q = 0, nz = K.nz; q < nz; ++q)
    fe_trip_add(&C, K.i[q], K.j[q], o->beta * K.x[q]);
  r->f0 = calloc((size_t)n, sizeof *r->f0);
  r->unb_c = calloc((size_t)n, sizeof *r->unb_c);
  r->unb_s = calloc((size_t)n, sizeof *r->unb_s);
  for (int q = 0; q < M.nz; ++q)
    if (M.i[q] == M.j[q] && (M.i[q] >= 4 * nn || M.i[q] % 4 == 0))
      r->f0[M.i[q]] -= o->gravity * M.x[q];
  if (dn >= 0) { r->unb_c[4 * dn] = o->me; r->unb_s[4 * dn + 1] = o->me; }
  fe_trip_csc(&K, &r->K); fe_trip_csc(&M, &r->M);
  fe_trip_csc(&C, &r->C); fe_trip_csc(&G, &r->G);
  r->nnl = o->nnl;
  r->nl = malloc((size_t)(o->nnl ? o->nnl : 1) * sizeof *r->nl);
  memcpy(r->nl, o->nl, (size_t)o->nnl * sizeof *r->nl);
  r->speed_min = 0; r->speed_max = 600;
  r->title = (char *)"chain";
  return r;
}

/* A short π-film SFD at node (pedestal −1: to ground). */
static inline whirl_fe_nl fe_chain_sfd(int node, int pedestal) {
  whirl_fe_nl e;
  memset(&e, 0, sizeof e);
  e.kind = WHIRL_FE_SFD_SHORT_PI;
  e.node = node;
  e.pedestal = pedestal;
  e.par.radius = 0.05;
  e.par.length = 0.02;
  e.par.clearance = 2e-4;
  e.par.viscosity = 0.01;
  return e;
}

static inline whirl_fe_nl fe_chain_cubic(int node, double k1, double k3) {
  whirl_fe_nl e;
  memset(&e, 0, sizeof e);
  e.kind = WHIRL_FE_CUBIC;
  e.node = node;
  e.pedestal = -1;
  e.par.k1 = k1;
  e.par.k3 = k3;
  return e;
}

#endif

/* rotor/fe_assemble.c — the rotor file (fe_file.c) assembled into the
 * sparse M, C, G, K, the static load f0 and the unbalance vectors of
 * whirl/rotor/fe.h.
 *
 * Shaft: the Timoshenko beam element with shear deformation, rotary
 * inertia and gyroscopic terms and consistent mass of Nelson (1980), as in
 * Friswell, Penny, Garvey & Lees, Dynamics of Rotating Machines (2010),
 * §5.4: in each bending plane, DOFs (w1, ψ1, w2,
 * ψ2) with ψ the rotation of the section, φ = 12EI/(κGAL²),
 *   K  = EI/(L³(1+φ)) [12 6L −12 6L; 6L (4+φ)L² −6L (2−φ)L²; ...],
 *   Mt = ρAL/(840(1+φ)²) [m1 m2 m3 −m4; ...] (translational inertia),
 *   Mr = ρI/(30L(1+φ)²) [36 (3−15φ)L ...]   (rotary inertia),
 * and the gyroscopic matrix the rotary one with ρI → ρIp = 2ρI, coupling
 * the planes.  κ is Cowper's (1966) shear coefficient of a hollow circular
 * section, the formula Friswell et al. give in §5.4:
 *   κ = 6(1+ν)(1+α²)² / [(7+6ν)(1+α²)² + (20+12ν)α²],  α = id/od,
 * ν = E/(2G) − 1.
 *
 * Coordinates: the shaft along x, spinning at Ω about +x; node DOFs
 * (y, z, θy, θz), θ rotations about the axes.  The xy plane has w = y,
 * ψ = θz; the xz plane w = z, ψ = −θy.  A disk's equations are then
 *   m y'' = Fy, m z'' = Fz, It θy'' + Ω Ip θz' = My, It θz'' − Ω Ip θy' = Mz
 * (the rate of change of the angular momentum Ip Ω (1, θz, −θy)), so that
 * forward whirl is the motion y + i z ∝ e^{iωt}, ω > 0, as the spin.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe_impl.h"

/* Cowper's shear coefficient of a hollow circular section (see above). */
static double shear_coefficient(double nu, double od, double id) {
  const double a2 = (id / od) * (id / od), b = (1 + a2) * (1 + a2);
  return 6 * (1 + nu) * b / ((7 + 6 * nu) * b + (20 + 12 * nu) * a2);
}

/* The planar matrices of one element, 4x4 row-major in (w1, ψ1, w2, ψ2). */
static void element(double L, double E, double G, double rho, double od, double id, double K[16],
                    double M[16], double Mr[16]) {
  const double A = WHIRL_PI * (od * od - id * id) / 4;
  const double I = WHIRL_PI * (pow(od, 4) - pow(id, 4)) / 64;
  const double kap = shear_coefficient(E / (2 * G) - 1, od, id);
  const double p = 12 * E * I / (kap * G * A * L * L), L2 = L * L;
  const double k = E * I / (L * L2 * (1 + p));
  const double Kp[16] = {12 * k,     6 * L * k,           -12 * k,    6 * L * k,
                         6 * L * k,  (4 + p) * L2 * k,    -6 * L * k, (2 - p) * L2 * k,
                         -12 * k,    -6 * L * k,          12 * k,     -6 * L * k,
                         6 * L * k,  (2 - p) * L2 * k,    -6 * L * k, (4 + p) * L2 * k};
  const double t = rho * A * L / (840 * (1 + p) * (1 + p));
  const double m1 = 312 + 588 * p + 280 * p * p, m2 = (44 + 77 * p + 35 * p * p) * L;
  const double m3 = 108 + 252 * p + 140 * p * p, m4 = (26 + 63 * p + 35 * p * p) * L;
  const double m5 = (8 + 14 * p + 7 * p * p) * L2, m6 = (6 + 14 * p + 7 * p * p) * L2;
  const double Mt[16] = {m1, m2, m3, -m4, m2, m5, m4, -m6, m3, m4, m1, -m2, -m4, -m6, -m2, m5};
  const double r = rho * I / (30 * L * (1 + p) * (1 + p));
  const double r1 = 36, r2 = (3 - 15 * p) * L, r3 = (4 + 5 * p + 10 * p * p) * L2;
  const double r4 = (-1 - 5 * p + 5 * p * p) * L2;
  const double R[16] = {r1, r2, -r1, r2, r2, r3, -r2, r4, -r1, -r2, r1, -r2, r2, r4, -r2, r3};
  for (int q = 0; q < 16; ++q) {
    K[q] = Kp[q];
    Mr[q] = r * R[q];
    M[q] = t * Mt[q] + Mr[q];
  }
}

typedef struct asm_ctx {
  fe_trip M, C, G, K;
} asm_ctx;

/* The element between nodes a and a+1 into M, G, K, and its proportional
 * damping α M_e + β K_e into C. */
static void add_element(asm_ctx *s, const fe_desc *d, const fe_element *e) {
  const fe_material *m = &d->mat[e->material];
  double K[16], M[16], Mr[16];
  element(e->length, m->E, m->G, m->rho, e->od, e->id, K, M, Mr);
  const int a = 4 * e->node, b = a + 4;
  const int g1[4] = {a + 0, a + 3, b + 0, b + 3}; /* (y, θz): w, ψ */
  const int g2[4] = {a + 1, a + 2, b + 1, b + 2}; /* (z, θy): w, −ψ */
  const double s2[4] = {1, -1, 1, -1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const int q = 4 * i + j;
      fe_trip_add(&s->M, g1[i], g1[j], M[q]);
      fe_trip_add(&s->M, g2[i], g2[j], s2[i] * s2[j] * M[q]);
      fe_trip_add(&s->K, g1[i], g1[j], K[q]);
      fe_trip_add(&s->K, g2[i], g2[j], s2[i] * s2[j] * K[q]);
      const double cq = d->damp_alpha * M[q] + d->damp_beta * K[q];
      if (cq != 0) { /* proportional damping of the element (`damping`) */
        fe_trip_add(&s->C, g1[i], g1[j], cq);
        fe_trip_add(&s->C, g2[i], g2[j], s2[i] * s2[j] * cq);
      }
      /* δθy ρIpΩ θz' − δθz ρIpΩ θy' in plane terms: G12 = ρIp R̃, G21 = −ρIp R̃ */
      fe_trip_add(&s->G, g1[i], g2[j], 2 * Mr[q] * s2[j]);
      fe_trip_add(&s->G, g2[i], g1[j], -2 * Mr[q] * s2[i]);
    }
}

/* 2x2 coefficients k[4] (row-major yy yz zy zz) between DOF pairs i (node
 * or pedestal y) and j (−1: ground): + on (i,i), (j,j), − across. */
static void add_pair(fe_trip *T, int i, int j, const double k[4]) {
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      const double v = k[2 * r + c];
      if (v == 0) continue;
      fe_trip_add(T, i + r, i + c, v);
      if (j >= 0) {
        fe_trip_add(T, j + r, j + c, v);
        fe_trip_add(T, i + r, j + c, -v);
        fe_trip_add(T, j + r, i + c, -v);
      }
    }
}

static void add_supports(asm_ctx *s, const fe_desc *d, int nnode) {
  for (size_t k = 0; k < d->ndisk; ++k) {
    const fe_disk *g = &d->disk[k];
    const int n = 4 * g->node;
    fe_trip_add(&s->M, n, n, g->m);
    fe_trip_add(&s->M, n + 1, n + 1, g->m);
    fe_trip_add(&s->M, n + 2, n + 2, g->it);
    fe_trip_add(&s->M, n + 3, n + 3, g->it);
    fe_trip_add(&s->G, n + 2, n + 3, g->ip);
    fe_trip_add(&s->G, n + 3, n + 2, -g->ip);
  }
  for (size_t k = 0; k < d->nbrg; ++k) {
    const fe_bearing *b = &d->brg[k];
    const int j = b->pedestal < 0 ? -1 : 4 * nnode + 2 * b->pedestal;
    add_pair(&s->K, 4 * b->node, j, b->k);
    add_pair(&s->C, 4 * b->node, j, b->c);
  }
  for (size_t k = 0; k < d->nped; ++k) {
    const fe_pedestal *p = &d->ped[k];
    const int j = 4 * nnode + 2 * (int)k;
    fe_trip_add(&s->M, j, j, p->mass);
    fe_trip_add(&s->M, j + 1, j + 1, p->mass);
    add_pair(&s->K, j, -1, p->k);
    add_pair(&s->C, j, -1, p->c);
  }
}

/* f0 = M a (gravity: the consistent load of the shaft elements, the weight
 * of disks and pedestals, exactly M times the uniform acceleration) plus
 * the static loads; the unbalance m e Ω² along (cos(Ωt+β), sin(Ωt+β)). */
static void loads(whirl_fe_rotor *r, const fe_desc *d) {
  double *a = calloc((size_t)r->ndof, sizeof *a);
  if (a) {
    for (int n = 0; n < r->nnode + r->npedestal; ++n) {
      const int j = n < r->nnode ? 4 * n : 4 * r->nnode + 2 * (n - r->nnode);
      a[j] = d->gravity[0];
      a[j + 1] = d->gravity[1];
    }
    fe_csc_gemv(&r->M, 1, a, r->f0);
    free(a);
  }
  for (size_t k = 0; k < d->nload; ++k)
    for (int q = 0; q < 4; ++q) r->f0[4 * d->load[k].node + q] += d->load[k].f[q];
  for (size_t k = 0; k < d->nunb; ++k) {
    const fe_unbalance *u = &d->unb[k];
    const int j = 4 * u->node;
    r->unb_c[j] += u->me * cos(u->phase);
    r->unb_s[j] -= u->me * sin(u->phase);
    r->unb_c[j + 1] += u->me * sin(u->phase);
    r->unb_s[j + 1] += u->me * cos(u->phase);
  }
}

static int assemble(whirl_fe_rotor *r, const fe_desc *d) {
  asm_ctx s;
  fe_trip_init(&s.M, r->ndof);
  fe_trip_init(&s.C, r->ndof);
  fe_trip_init(&s.G, r->ndof);
  fe_trip_init(&s.K, r->ndof);
  for (size_t k = 0; k < d->nel; ++k) add_element(&s, d, &d->el[k]);
  add_supports(&s, d, r->nnode);
  fe_trip *dst[4] = {&s.M, &s.C, &s.G, &s.K};
  for (int k = 0; d->imp && k < 4; ++k) /* the `matrices` line's */
    for (size_t t = 0; t < d->imp[k].nt; ++t)
      fe_trip_add(dst[k], d->imp[k].i[t], d->imp[k].j[t], d->imp[k].x[t]);
  int rc = fe_trip_to_csc(&s.M, &r->M);
  rc |= fe_trip_to_csc(&s.C, &r->C);
  rc |= fe_trip_to_csc(&s.G, &r->G);
  rc |= fe_trip_to_csc(&s.K, &r->K);
  if (rc) return WHIRL_ENOMEM;
  const size_t n = (size_t)r->ndof;
  r->f0 = calloc(n, sizeof *r->f0);
  r->unb_c = calloc(n, sizeof *r->unb_c);
  r->unb_s = calloc(n, sizeof *r->unb_s);
  r->nl = malloc((d->nnl + 1) * sizeof *r->nl);
  r->title = malloc(strlen(d->title) + 1);
  if (!r->f0 || !r->unb_c || !r->unb_s || !r->nl || !r->title) return WHIRL_ENOMEM;
  strcpy(r->title, d->title);
  if (d->nnl) memcpy(r->nl, d->nl, d->nnl * sizeof *r->nl);
  r->nnl = (int)d->nnl;
  loads(r, d);
  return WHIRL_OK;
}

whirl_fe_rotor *whirl_fe_rotor_read(const char *path, char *msg, size_t len, int *status) {
  fe_desc d;
  int st = path ? fe_parse(path, &d, msg, len) : WHIRL_EINVAL;
  whirl_fe_rotor *r = NULL;
  if (st == WHIRL_OK) {
    r = calloc(1, sizeof *r);
    if (r) {
      r->nnode = d.nnode;
      r->npedestal = (int)d.nped;
      r->ndof = 4 * d.nnode + 2 * (int)d.nped;
      r->speed_min = d.speed_min;
      r->speed_max = d.speed_max;
      r->omega_ref = d.omega_ref;
      st = assemble(r, &d);
    } else st = WHIRL_ENOMEM;
    if (st != WHIRL_OK) {
      whirl_fe_rotor_free(r);
      r = NULL;
      if (msg && len) snprintf(msg, len, "%s: out of memory", path);
    }
    fe_desc_free(&d);
  } else if (!path && msg && len) snprintf(msg, len, "no rotor file");
  if (status) *status = st;
  return r;
}

void whirl_fe_rotor_free(whirl_fe_rotor *r) {
  if (!r) return;
  fe_csc_free(&r->M);
  fe_csc_free(&r->C);
  fe_csc_free(&r->G);
  fe_csc_free(&r->K);
  free(r->f0);
  free(r->unb_c);
  free(r->unb_s);
  free(r->nl);
  free(r->title);
  free(r);
}

int whirl_fe_rotor_dof(const whirl_fe_rotor *r, int node, int k) {
  if (!r) return -1;
  if (node >= 0) return node < r->nnode && k >= 0 && k < 4 ? 4 * node + k : -1;
  const int p = -1 - node;
  return p < r->npedestal && k >= 0 && k < 2 ? 4 * r->nnode + 2 * p + k : -1;
}

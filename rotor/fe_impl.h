/* rotor/fe_impl.h — inside the finite-element rotor (not installed): the
 * rotor file as read (fe_file.c), before assembly (fe_assemble.c), and the
 * sparse triplet lists both the assembly and the analyses (fe_modes.c,
 * fe_arpack.c, fe_response.c) build their matrices with (fe_sparse.c).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_IMPL_H
#define WHIRL_ROTOR_FE_IMPL_H

#include <stddef.h>

#include <whirl/problem.h> /* WHIRL_PI */
#include <whirl/rotor/fe.h>

#define FE_NAME 64

typedef struct fe_material {
  char name[FE_NAME];
  double E, G, rho;
  int line;
} fe_material;

/* One shaft element between nodes node and node + 1. */
typedef struct fe_element {
  int node;
  double length, od, id;
  int material;
  int line;
} fe_element;

typedef struct fe_disk {
  int node;
  double m, ip, it; /* mass, polar and transverse (diametral) inertia */
  int line;
} fe_disk;

/* A linear support between a node and the ground or a pedestal: the force
 * on the node is −k r − c r', r = (y, z) relative, k = [kyy kyz; kzy kzz]. */
typedef struct fe_bearing {
  int node;
  char pedestal_name[FE_NAME]; /* "" to ground */
  int pedestal;                /* resolved: −1 ground */
  double k[4], c[4];           /* row-major yy yz zy zz */
  int line;
} fe_bearing;

typedef struct fe_pedestal {
  char name[FE_NAME];
  double mass, k[4], c[4];
  int line;
} fe_pedestal;

typedef struct fe_unbalance {
  int node;
  double me, phase; /* kg·m, rad */
  int line;
} fe_unbalance;

typedef struct fe_load {
  int node;
  double f[4]; /* fy, fz, my, mz */
  int line;
} fe_load;

typedef struct fe_desc {
  char file[512];
  int nlines;
  fe_material *mat;
  size_t nmat, cmat;
  fe_element *el;
  size_t nel, cel;
  fe_disk *disk;
  size_t ndisk, cdisk;
  fe_bearing *brg;
  size_t nbrg, cbrg;
  fe_pedestal *ped;
  size_t nped, cped;
  whirl_fe_nl *nl;
  char (*nl_ped)[FE_NAME]; /* each nonlinear element's pedestal name */
  size_t nnl, cnl;
  fe_unbalance *unb;
  size_t nunb, cunb;
  fe_load *load;
  size_t nload, cload;
  double gravity[2]; /* acceleration (y, z), m/s² */
  int gravity_line, speed_line, reference_line, title_line;
  double speed_min, speed_max, omega_ref;
  char title[256];
  double damp_alpha, damp_beta; /* `damping`: C_e = α M_e + β K_e of the
                                   shaft elements */
  int damping_line;
  int nnode; /* after fe_parse: shaft nodes (and `nodes count`) */
  int nodes_count, nodes_line;
  /* `matrices`: M, C, G, K from Matrix Market files (fe_matrix.c), paths
   * relative to the rotor file's directory; read by fe_parse */
  char mtx[4][1024];
  int mtx_line;
  struct fe_trip *imp; /* 4 triplet lists, or NULL */
} fe_desc;

/* Read PATH into d (zeroed first).  0, or WHIRL_EINVAL / WHIRL_EIO /
 * WHIRL_ENOMEM with "PATH:LINE: ..." in msg. */
int fe_parse(const char *path, fe_desc *d, char *msg, size_t len);
void fe_desc_free(fe_desc *d);

/* ---- Matrix Market files (fe_matrix.c) ---------------------------------- */
struct fe_trip;
int fe_matrix_read(const char *path, int n, struct fe_trip *T, char *msg, size_t len);

/* ---- triplets (i, j, x) summed into compressed columns ---------------- */
typedef struct fe_trip {
  int n;
  size_t nt, cap;
  int *i, *j;
  double *x;
  int failed; /* out of memory in an add */
} fe_trip;

void fe_trip_init(fe_trip *t, int n);
void fe_trip_add(fe_trip *t, int i, int j, double x);
/* a · A added entry by entry, shifted by (r0, c0) */
void fe_trip_add_csc(fe_trip *t, const whirl_fe_csc *A, double a, int r0, int c0);
/* The sum of the triplets as a compressed-column matrix (rows sorted,
 * duplicates summed, every listed position kept even when it sums to 0).
 * 0 or WHIRL_ENOMEM.  The triplets are freed either way. */
int fe_trip_to_csc(fe_trip *t, whirl_fe_csc *A);
void fe_csc_free(whirl_fe_csc *A);
/* y += a · A x */
void fe_csc_gemv(const whirl_fe_csc *A, double a, const double *x, double *y);


/* ---- eigenvalues (fe_modes.c, fe_arpack.c) ----------------------------- */
/* The eigenvalues with Im s > 0 found, with each mode's whirl (+1/−1). */
typedef struct fe_eigs {
  size_t n;
  double *re, *im;
  int *whirl;
} fe_eigs;
int fe_eigs_alloc(fe_eigs *e, size_t n);
void fe_eigs_free(fe_eigs *e);
/* (max|K| / max|M|)^½, the frequency scale of the discretisation */
double fe_omega0(const whirl_fe_rotor *r);
/* |s| < FE_SZERO ω0 is a rigid-body (zero) eigenvalue, dropped */
#define FE_SZERO 1e-6
/* The whirl of the mode x = (vr + i vi)[0..ndof) (fe_modes.c). */
int fe_whirl_of(const whirl_fe_rotor *r, const double *vr, const double *vi);
/* D = C + Ω G as one matrix (pattern union) */
int fe_damping(const whirl_fe_rotor *r, double Omega, whirl_fe_csc *D);
/* All finite eigenvalues, dense QZ (fe_modes.c). */
int fe_eig_dense(const whirl_fe_rotor *r, double Omega, fe_eigs *e, char *msg, size_t len);
/* nev eigenvalues nearest the shift by ARPACK (fe_arpack.c). */
int fe_eig_arpack(const whirl_fe_rotor *r, double Omega, double shift, double tol, size_t nev,
                  fe_eigs *e, char *msg, size_t len);

#endif

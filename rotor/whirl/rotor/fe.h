/* whirl/rotor/fe.h — finite-element rotors: a shaft of Timoshenko beam
 * elements with rigid disks, linear bearings and supports (to ground or
 * through pedestal masses), nonlinear elements at nodes (squeeze-film
 * dampers, journal bearings, rub, cubic springs), unbalances and static
 * loads.  Units are SI throughout; speeds are in rad/s.
 *
 * The equations of motion, q the ndof generalised displacements:
 *
 *   M q'' + (C + Ω G) q' + K q = f0 + Ω² (u_c cos Ωt + u_s sin Ωt)
 *                                   + Σ_e P_eᵀ f_e(r_e, r_e', r_e'', Ω)
 *
 * M, C, G, K are sparse ndof×ndof (compressed columns, the layout of
 * whirl/linsol.h), M the consistent mass of the beam elements plus the
 * disks and pedestals, G the gyroscopic matrix per unit speed
 * (skew-symmetric), f0 gravity and static loads.  Each node has four
 * degrees of freedom, in the order (y, z, θy, θz) at 4·node + 0..3; each
 * pedestal two more (y, z), after all the nodes.  A nonlinear element e
 * acts between the y, z of its node and the ground or a pedestal: its
 * relative displacement r_e = (y_node − y_ped − y_off, z_node − z_ped −
 * z_off) and f_e is the force it exerts on the node (the opposite force on
 * the pedestal).  doc/rotor-file.md describes the file, doc/rotor-forces.md
 * each force with its reference.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_FE_H
#define WHIRL_ROTOR_FE_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------ sparse */

/* An n×n matrix in compressed columns: p[n+1], i[nnz] (rows sorted within
 * a column), x[nnz]. */
typedef struct whirl_fe_csc {
  int n;
  int *p;
  int *i;
  double *x;
} whirl_fe_csc;

/* ------------------------------------------------- nonlinear elements */

typedef enum whirl_fe_nl_kind {
  WHIRL_FE_SFD_SHORT_PI,   /* short SFD, π film (half film, cavitated) */
  WHIRL_FE_SFD_SHORT_2PI,  /* short SFD, 2π film (full film) */
  WHIRL_FE_SFD_LONG,       /* long SFD (sealed ends), π film */
  WHIRL_FE_SFD_INERTIA,    /* short SFD, π film, with fluid inertia */
  WHIRL_FE_JOURNAL_SHORT,  /* short plain journal bearing, Ocvirk, half-Sommerfeld */
  WHIRL_FE_RUB,            /* radial rub: clearance, contact stiffness, friction */
  WHIRL_FE_CUBIC           /* isotropic cubic spring k1 r + k3 |r|² r */
} whirl_fe_nl_kind;

/* The parameters of a nonlinear element, SI.  Which are used depends on
 * the kind (doc/rotor-forces.md); the others are 0. */
typedef struct whirl_fe_nl_params {
  double radius;      /* R: damper or bearing radius, m */
  double length;      /* L: land length, m */
  double clearance;   /* c: radial clearance, m (rub: gap) */
  double viscosity;   /* μ: dynamic viscosity, Pa·s */
  double density;     /* ρ: fluid density, kg/m³ (fluid inertia) */
  double k_contact;   /* rub: contact stiffness, N/m */
  double friction;    /* rub: Coulomb friction coefficient */
  double k1, k3;      /* cubic spring: N/m, N/m³ */
} whirl_fe_nl_params;

typedef struct whirl_fe_nl {
  whirl_fe_nl_kind kind;
  int node;            /* the rotor node it acts on */
  int pedestal;        /* −1: to ground; else the pedestal's index */
  double offset[2];    /* static offset (y, z) of the housing centre, m */
  whirl_fe_nl_params par;
  int line;            /* line of the rotor file, for messages (0: none) */
} whirl_fe_nl;

/* The force f[2] the element exerts on the journal at relative
 * displacement r[2], velocity v[2], acceleration a[2] (used by fluid
 * inertia only), shaft speed Omega (journal bearings only).  Optional
 * Jacobians, column-major 2×2 (J[i + 2j] = ∂f_i/∂r_j), may each be NULL:
 * Jr = ∂f/∂r, Jv = ∂f/∂v, Ja = ∂f/∂a.  Returns WHIRL_OK, or
 * WHIRL_EDOMAIN when the journal reaches the clearance of a film element
 * (|r| ≥ c), with no output written. */
WHIRL_API int whirl_fe_nl_force(const whirl_fe_nl *e, const double r[2],
                                const double v[2], const double a[2],
                                double Omega, double f[2], double Jr[4],
                                double Jv[4], double Ja[4]);

/* The element kind's name in the rotor file ("sfd-short-pi", ...), and
 * back (−1 when unknown). */
WHIRL_API const char *whirl_fe_nl_kind_name(whirl_fe_nl_kind kind);
WHIRL_API int whirl_fe_nl_kind_from_name(const char *name);

/* ------------------------------------------------------- the rotor */

/* An assembled rotor.  Everything is owned by the object; read the
 * members, do not change them (whirl_fe_rotor_free releases all). */
typedef struct whirl_fe_rotor {
  int nnode;            /* shaft nodes, 0..nnode−1 */
  int npedestal;        /* pedestal masses */
  int ndof;             /* 4·nnode + 2·npedestal */
  whirl_fe_csc M, C, G, K;
  double *f0;           /* static load, ndof */
  double *unb_c, *unb_s;/* unbalance load per unit Ω², ndof */
  int nnl;
  whirl_fe_nl *nl;      /* nonlinear elements, nnl */
  double speed_min, speed_max; /* the file's speed range, rad/s (0 0: none) */
  double omega_ref;     /* a reference frequency for nondimensional
                           output, rad/s (rotor file's "reference"; 0: none) */
  char *title;          /* from the file, or "" */
  char errmsg[512];     /* the last message */
} whirl_fe_rotor;

/* Read and assemble a rotor file.  On error returns NULL and writes one
 * message "FILE:LINE: what is wrong" into msg[len] (status in *status,
 * WHIRL_EINVAL for bad input, WHIRL_ENOMEM, WHIRL_EIO); status may be
 * NULL. */
WHIRL_API whirl_fe_rotor *whirl_fe_rotor_read(const char *path, char *msg,
                                              size_t len, int *status);
WHIRL_API void whirl_fe_rotor_free(whirl_fe_rotor *r); /* accepts NULL */

/* The index of DOF k (0..3: y, z, θy, θz) of a node, or of pedestal
 * DOF k (0..1) when node < 0 is −1 − pedestal. */
WHIRL_API int whirl_fe_rotor_dof(const whirl_fe_rotor *r, int node, int k);

#ifdef __cplusplus
}
#endif
#endif

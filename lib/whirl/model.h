/* whirl/model.h — a model as `whirl run` loads it: the vector field (a
 * whirl_problem) plus what a run needs to start, AUTO's STPNT and PVLS in
 * one struct.  Registered models (`model = sfd`, added to a
 * whirl_model_registry by a module such as the rotor module) and plug-ins
 * (`model = ./mymodel.so`) are described the same way.
 *
 * A plug-in is a shared object exporting ONE symbol, `whirl_model_def`, of
 * type `const whirl_model`:
 *
 *     #include <whirl/whirl.h>
 *     static int rhs(double t, const double *u, const double *p, double *f,
 *                    void *data) { ... return 0; }
 *     static const double par0[] = {0.0, 14.0, 2.0};
 *     static const double u0[] = {0.0, 0.0};
 *     const whirl_model whirl_model_def = {
 *       .abi = WHIRL_MODEL_ABI,
 *       .problem = {.name = "ab", .n = 2, .npar = 3, .rhs = rhs,
 *                   .autonomous = 1, .p_names = names},
 *       .par0 = par0, .u0 = u0, .forcing_param = -1};
 *
 * built with
 *     cc -shared -fPIC -o mymodel.so mymodel.c $(pkg-config --cflags --libs whirl)
 *
 * `abi` must be the first member and equal WHIRL_MODEL_ABI of the headers
 * the plug-in was compiled with; whirl refuses a plug-in with another value
 * ("built for model ABI 0, this whirl needs 1: rebuild it") before reading
 * anything else from it.  The ABI number changes whenever this struct or
 * whirl_problem changes layout.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_MODEL_H
#define WHIRL_MODEL_H

#include <stddef.h>
#include <whirl/problem.h>

#ifdef __cplusplus
extern "C" {
#endif

#define WHIRL_MODEL_ABI 6
#define WHIRL_MODEL_SYMBOL "whirl_model_def"

typedef struct whirl_model {
  int abi;               /* WHIRL_MODEL_ABI (first member, checked first) */
  whirl_problem problem; /* the ODE u' = f(t, u, p): callbacks, sizes, names */
  const double *par0;    /* npar default parameter values (required) */
  const double *u0;      /* n components of the default start state: an
                            equilibrium, or for a forced model a point of the
                            stroboscopic section; NULL: zeros (or stpnt) */
  /* Optional, AUTO's STPNT: the start solution at scaled time tau in [0, 1]
   * — for an equilibrium start tau = 0 only; for a periodic start (IPS = 2,
   * IRS = 0) the orbit of period `period0` sampled over one period.  May
   * set parameters in par[npar] (already holding par0).  0 on success. */
  int (*stpnt)(double tau, double *u, double *par, void *data);
  double period0;        /* period of the stpnt orbit (autonomous models) */
  int forcing_param;     /* forced (non-autonomous) models: index of the
                            parameter that is the forcing frequency omega, so
                            the period is 2 pi / p[forcing_param]; -1 for an
                            autonomous model */
  const char *description; /* optional one-line description */
  /* Optional: are the parameter values p[npar] inside the model's domain
   * (physical ranges)?  0, or nonzero with a one-line reason in msg[len].
   * whirl run refuses a run whose parameters fail before computing. */
  int (*check_params)(const double *p, char *msg, size_t len);
  /* Optional (ABI 3): n typical magnitudes of the state components — a
   * displacement's clearance, a velocity at the operating speed — used as
   * the default box ±scale of discovery's random starts (DISCOVER,
   * doc/discovery.md); NULL: the box comes from the start branch. */
  const double *scale;
  /* Optional (ABI 4), AUTO's PVLS: quantities derived from an equilibrium
   * x[n], written into parameters of par[npar] (holding the point's
   * values), which whirl run then shows and UZR/UZSTOP test, at every
   * point of equilibria; the continuation itself never sees them.  0 on
   * success. */
  int (*pvls)(const double *x, double *par, void *data);
  /* Optional (ABI 5), AUTO's BCND and ICND, for boundary-value problems
   * (IPS = 4: u' = f(u, p) on t in [0, 1], the rhs called with t = 0):
   * fb[nbc] = b(u(0), u(1), par), the boundary conditions; fi[nint] the
   * integrands g whose integrals over [0, 1] vanish, at a point of the
   * solution u(t), with the previous solution uold(t) of the branch, u'(t)
   * and uold'(t) there (AUTO's UOLD, UDOT, UPOLD: for phase conditions).
   * nbc and nint are the run's (NBC, NINT).  0 on success, > 0 domain. */
  int (*bcnd)(size_t nbc, const double *u0, const double *u1, const double *par,
              double *fb, void *data);
  int (*icnd)(size_t nint, const double *u, const double *uold, const double *udot,
              const double *upold, const double *par, double *fi, void *data);
  /* Optional (ABI 6), AUTO's PVLS on a solution of periodic orbits or of
   * a boundary-value problem (IPS 2 and 4, by collocation): u[nnodes n]
   * its values at the mesh's nodes (node-major, t from 0 to 1), w[nnodes]
   * the weights of the collocation quadrature (the integral over [0, 1]
   * of a node value), par[npar] as for pvls; AUTO's GETP reads them
   * ('INT', 'NRM', 'MAX', 'MIN', 'BV0', 'BV1').  0 on success. */
  int (*pvls_solution)(const double *u, size_t nnodes, const double *w, double *par,
                       void *data);
  /* Optional (ABI 6): the run's ICP as AUTO numbers it (1-based; 11 the
   * period of orbits) and its NTST, NCOL, NBC, NINT, given before the run
   * calls the model, for user routines that read them (AUTO passes ICP to
   * FUNC, BCND and ICND, and its GETP returns the others: demo ph1's FUNC
   * scales by the period only when ICP is [11, 9], pcl's PVLS asks NBC). */
  void (*set_icp)(const int *icp, size_t nicp, const int counts[4], void *data);
} whirl_model;

/* Check a model description: abi, sizes, required callbacks, parameter
 * defaults finite, names unique and usable in run files.  Returns WHIRL_OK or
 * WHIRL_EINVAL with a one-line reason in msg[len]. */
WHIRL_API int whirl_model_check(const whirl_model *m, char *msg, size_t len);

/* Check parameter values p[npar] against the model's own rules (its
 * check_params; none: every value is accepted, and the callbacks report a
 * bad parameter by their return status).  WHIRL_OK, or WHIRL_EINVAL with
 * the reason in msg[len] ("FE must be in (-1, 1): ... (got 1.5)"). */
WHIRL_API int whirl_model_check_params(const whirl_model *m, const double *p,
                                       char *msg, size_t len);

/* ---- a registry of models, by name (what `model = NAME` finds) ---------- */

typedef struct whirl_model_registry whirl_model_registry;

WHIRL_API whirl_model_registry *whirl_model_registry_alloc(void);
WHIRL_API void whirl_model_registry_free(whirl_model_registry *reg);

/* Add model m under NAME (letters, digits, '_', '-', '.'; not a path).  The
 * struct is copied, the data it points to borrowed.  WHIRL_OK, or
 * WHIRL_EINVAL (m fails whirl_model_check, the name is not usable or
 * taken), WHIRL_ENOMEM, with the reason in msg[len]. */
WHIRL_API int whirl_model_registry_add(whirl_model_registry *reg, const char *name,
                                       const whirl_model *m, char *msg, size_t len);

/* The model registered as NAME, or NULL. */
WHIRL_API const whirl_model *whirl_model_registry_find(const whirl_model_registry *reg,
                                                       const char *name);

/* The registered names, in the order they were added: count and i-th. */
WHIRL_API size_t whirl_model_registry_count(const whirl_model_registry *reg);
WHIRL_API const char *whirl_model_registry_name(const whirl_model_registry *reg,
                                                size_t i);

#ifdef __cplusplus
}
#endif
#endif

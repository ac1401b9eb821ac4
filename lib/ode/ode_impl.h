/* lib/ode/ode_impl.h — private to lib/ode: the integrator object, shared by
 * the DOPRI5 code (dopri.c, which owns the public entry points) and the BDF
 * back end (bdf.c, CVODE), and what sample.c needs beyond the public API.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ODE_IMPL_H
#define WHIRL_ODE_IMPL_H

#include <stddef.h>
#include <whirl/ode.h>

#include "util/errmsg_impl.h"

struct whirl_bdf;    /* CVODE's state, bdf.c */
struct whirl_dop853; /* DOP853's stages and dense output, dop853.c */

struct whirl_ode {
  whirl_problem prob; /* copy; data borrowed */
  size_t n, npar;
  double *p, *p_new; /* active parameters, pending ones (set_params) */
  int p_pending;
  double rtol, atol, h_init, h_min, h_max;
  size_t max_steps;
  int method;            /* whirl_ode_method in force */
  struct whirl_bdf *bdf; /* NULL until BDF or a sparse Jacobian is set */
  struct whirl_dop853 *d8; /* NULL until a DOP853 step */

  int started;       /* reset was called */
  int have_step;     /* a step was accepted since the reset: dense valid */
  int have_f;        /* k[0] = f(t, x) (first same as last) */
  int reject_last;   /* the last attempt was rejected */
  double t, t_prev, h; /* h: |proposed next step|, 0 = automatic */
  double facold;     /* error of the last accepted step (PI controller) */
  double *x, *x_prev, *xs, *xnew, *k[7];
  double *rc; /* dense output: ydiff, bspl, r4, r5 (4n) */
  int last_rhs;
  whirl_ode_stats st;
  whirl_ode_implicit_stats ist;
  char errmsg[WHIRL_ERRMSG_SIZE];
};

/* The step budget of whirl_ode_set_max_steps (0: unlimited). */
size_t whirl_ode_max_steps_(const whirl_ode *o);
/* The object's message buffer, WHIRL_ERRMSG_SIZE chars; ODE_FAIL stores
 * "message (file.c:line)" there and evaluates to code. */
char *whirl_ode_errbuf_(whirl_ode *o);
#define ODE_FAIL(o, code, ...) \
  WHIRL_ERRMSG(whirl_ode_errbuf_(o), WHIRL_ERRMSG_SIZE, (code), __VA_ARGS__)

/* f = f(t, y) with the checks of problem.h (dopri.c): 0, > 0 recoverable
 * (the callback's status or a non-finite output: last_rhs says which),
 * < 0 fatal.  Counts the evaluation. */
int whirl_ode_eval_(whirl_ode *o, double t, const double *y, double *f);
/* "right-hand side returned 1" / "... NaN or Inf": what it said last. */
void whirl_ode_rhs_said_(const whirl_ode *o, char *buf, size_t len);

/* Shared by the explicit methods (dopri.c): 16 ulps of t, the default
 * minimum step; f = f(t, x) at the start (sets have_f; an error message
 * when f cannot be evaluated there); the starting step of HNW I p. 169 for
 * a method of the given order (f0 = f(t, x), f1 scratch). */
double whirl_ode_ulp16_(double t);
int whirl_ode_first_rhs_(whirl_ode *o, double *f);
int whirl_ode_initial_step_(whirl_ode *o, const double *f0, double *f1,
                            int order, double posneg, double span,
                            double hmax, double *hout);

/* An explicit embedded Runge–Kutta pair for the step of dopri.c
 * (whirl_ode_explicit_step_): the order of its starting step, the PI
 * controller's constants (fac = err^expo / facold^beta, the step's factor
 * in [facmin, facmax], safety safe), f(t, x) and a scratch vector for the
 * start, the stages of a step of hh from (t, x) to tn (xnew, the rhs
 * status: 0 or the first nonzero one), its error norm, and the
 * acceptance (advance, dense output, o->h = hnew). */
typedef struct ode_explicit_method {
  int order;
  double expo, beta, safe, facmin, facmax;
  double *(*f0)(whirl_ode *o);
  double *(*scratch)(whirl_ode *o);
  int (*stages)(whirl_ode *o, double t, double hh, double tn);
  double (*error)(const whirl_ode *o, double hh);
  void (*accept)(whirl_ode *o, double t, double tn, double hh, double err,
                 double hnew);
} ode_explicit_method;
int whirl_ode_explicit_step_(whirl_ode *o, const ode_explicit_method *m,
                             double t_end);

/* The DOP853 back end (dop853.c), called by dopri.c's entry points when
 * o->method is WHIRL_ODE_DOP853: one step towards t_end (o->t != t_end,
 * checked); the dense output's stages of the last step (once a step; a
 * status and message if the right-hand side fails there); x(t) on the
 * last step after that (t inside it, checked); free (accepts NULL). */
int whirl_dop853_step_(whirl_ode *o, double t_end);
int whirl_dop853_prepare_dense_(whirl_ode *o);
void whirl_dop853_dense_(const whirl_ode *o, double t, double *out);
void whirl_dop853_free_(struct whirl_dop853 *d);

/* The BDF back end (bdf.c), called by dopri.c's entry points when
 * o->method is WHIRL_ODE_BDF.  reset: (re)start CVODE at o->t, o->x with
 * the object's settings; step: one CVODE step towards t_end (o->t != t_end,
 * checked), updating t, x, t_prev, x_prev, the statistics and errmsg;
 * dense: x(t) on the last step (t inside it, checked); h: |next step|. */
int whirl_bdf_reset_(whirl_ode *o);
int whirl_bdf_step_(whirl_ode *o, double t_end);
int whirl_bdf_dense_(const whirl_ode *o, double t, double *x);
double whirl_bdf_h_(const whirl_ode *o);
void whirl_bdf_free_(struct whirl_bdf *b); /* accepts NULL */

#endif

/* lib/ode/dop853.c — the explicit Runge–Kutta method of order 8 of Dormand
 * & Prince, "High order embedded Runge–Kutta formulae", J. Comput. Appl.
 * Math. 7 (1981) 67–75, in the form of Hairer's DOP853 (Hairer, Nørsett &
 * Wanner, Solving Ordinary Differential Equations I, 2nd ed., 1993, §II.5
 * and §II.10; the coefficients are those of that code): 12 stages, the
 * 8th-order solution, the error estimate that blends its 5th- and
 * 3rd-order embedded estimates ("8(5,3)"), first same as last, and the
 * continuous extension of order 7 with three more stages.
 *
 * At the tolerances the rotor's basins and time responses use (RelTol
 * 1e-12) it takes 5–10 times fewer steps than DOPRI5 and 3–6 times fewer
 * right-hand-side evaluations (doc/sfd-time-domain.md).  The dense output's
 * three stages are computed only when a caller asks for a state inside the
 * last step (whirl_ode_dense, whirl_ode_find_event, whirl_ode_sample), at
 * most once a step.
 *
 * Entry points: called by dopri.c's public functions when o->method is
 * WHIRL_ODE_DOP853 (ode_impl.h).  The error test is the max norm of
 * whirl/ode.h (ode45's), applied to both embedded estimates.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>

#include "ode_impl.h"

/* ------------------------------------------------------------------------
 * Coefficients (Hairer's DOP853).  Stage s (0-based, s = 0..11) is
 * k_s = f(t + C[s] h, x + h Σ_j A[s][j] k_j); stage 12 is f(t + h, x_new)
 * (first same as last); stages 13..15 serve the dense output only. */
enum { NS = 12, NE = 16 };

static const double C[NE] = {
    0.0,
    0.526001519587677318785587544488e-01,
    0.789002279381515978178381316732e-01,
    0.118350341907227396726757197510e+00,
    0.281649658092772603273242802490e+00,
    0.333333333333333333333333333333e+00,
    0.25e+00,
    0.307692307692307692307692307692e+00,
    0.651282051282051282051282051282e+00,
    0.6e+00,
    0.857142857142857142857142857142e+00,
    1.0,
    1.0,
    0.1e+00,
    0.2e+00,
    0.777777777777777777777777777778e+00};

/* A[s][j], j < s; rows 13..15 are the dense output's stages */
static const double A[NE][NE - 1] = {
    {0},
    {5.26001519587677318785587544488e-2},
    {1.97250569845378994544595329183e-2, 5.91751709536136983633785987549e-2},
    {2.95875854768068491816892993775e-2, 0.0,
     8.87627564304205475450678981324e-2},
    {2.41365134159266685502369798665e-1, 0.0,
     -8.84549479328286085344864962717e-1, 9.24834003261792003115737966543e-1},
    {3.7037037037037037037037037037e-2, 0.0, 0.0,
     1.70828608729473871279604482173e-1, 1.25467687566822425016691814123e-1},
    {3.7109375e-2, 0.0, 0.0, 1.70252211019544039314978060272e-1,
     6.02165389804559606850219397283e-2, -1.7578125e-2},
    {3.70920001185047927108779319836e-2, 0.0, 0.0,
     1.70383925712239993810214054705e-1, 1.07262030446373284651809199168e-1,
     -1.53194377486244017527936158236e-2, 8.27378916381402288758473766002e-3},
    {6.24110958716075717114429577812e-1, 0.0, 0.0,
     -3.36089262944694129406857109825e0, -8.68219346841726006818189891453e-1,
     2.75920996994467083049415600797e1, 2.01540675504778934086186788979e1,
     -4.34898841810699588477366255144e1},
    {4.77662536438264365890433908527e-1, 0.0, 0.0,
     -2.48811461997166764192642586468e0, -5.90290826836842996371446475743e-1,
     2.12300514481811942347288949897e1, 1.52792336328824235832596922938e1,
     -3.32882109689848629194453265587e1, -2.03312017085086261358222928593e-2},
    {-9.3714243008598732571704021658e-1, 0.0, 0.0,
     5.18637242884406370830023853209e0, 1.09143734899672957818500254654e0,
     -8.14978701074692612513997267357e0, -1.85200656599969598641566180701e1,
     2.27394870993505042818970056734e1, 2.49360555267965238987089396762e0,
     -3.0467644718982195003823669022e0},
    {2.27331014751653820792359768449e0, 0.0, 0.0,
     -1.05344954667372501984066689879e1, -2.00087205822486249909675718444e0,
     -1.79589318631187989172765950534e1, 2.79488845294199600508499808837e1,
     -2.85899827713502369474065508674e0, -8.87285693353062954433549289258e0,
     1.23605671757943030647266201528e1, 6.43392746015763530355970484046e-1},
    {0}, /* stage 12 = f(t + h, x_new): the weights B */
    {5.61675022830479523392909219681e-2, 0.0, 0.0, 0.0, 0.0, 0.0,
     2.53500210216624811088794765333e-1, -2.46239037470802489917441475441e-1,
     -1.24191423263816360469010140626e-1, 1.5329179827876569731206322685e-1,
     8.20105229563468988491666602057e-3, 7.56789766054569976138603589584e-3,
     -8.298e-3},
    {3.18346481635021405060768473261e-2, 0.0, 0.0, 0.0, 0.0,
     2.83009096723667755288322961402e-2, 5.35419883074385676223797384372e-2,
     -5.49237485713909884646569340306e-2, 0.0, 0.0,
     -1.08347328697249322858509316994e-4, 3.82571090835658412954920192323e-4,
     -3.40465008687404560802977114492e-4, 1.41312443674632500278074618366e-1},
    {-4.28896301583791923408573538692e-1, 0.0, 0.0, 0.0, 0.0,
     -4.69762141536116384314449447206e0, 7.68342119606259904184240953878e0,
     4.06898981839711007970213554331e0, 3.56727187455281109270669543021e-1,
     0.0, 0.0, 0.0, -1.39902416515901462129418009734e-3,
     2.9475147891527723389556272149e0, -9.15095847217987001081870187138e0}};

/* 8th-order weights (of stages 0..11) */
static const double B[NS] = {
    5.42937341165687622380535766363e-2, 0.0, 0.0, 0.0, 0.0,
    4.45031289275240888144113950566e0,  1.89151789931450038304281599044e0,
    -5.8012039600105847814672114227e0,  3.1116436695781989440891606237e-1,
    -1.52160949662516078556178806805e-1, 2.01365400804030348374776537501e-1,
    4.47106157277725905176885569043e-2};
/* 3rd-order estimate: B − (BHH0 k_0 + BHH8 k_8 + BHH11 k_11) */
static const double BHH0 = 0.244094488188976377952755905512e+00,
                    BHH8 = 0.733846688281611857341361741547e+00,
                    BHH11 = 0.220588235294117647058823529412e-01;
/* 5th-order estimate, weights of stages 0..11 */
static const double ER[NS] = {
    0.1312004499419488073250102996e-01, 0.0, 0.0, 0.0, 0.0,
    -0.1225156446376204440720569753e+01, -0.4957589496572501915214079952e+00,
    0.1664377182454986536961530415e+01, -0.3503288487499736816886487290e+00,
    0.3341791187130174790297318841e+00, 0.8192320648511571246570742613e-01,
    -0.2235530786388629525884427845e-01};

/* Dense output: D[r][s], r = 0..3 for the coefficients 5..8 of CONTD8,
 * weights of stages 0..15 (stages 1..4 have none) */
static const double D[4][NE] = {
    {-0.84289382761090128651353491142e+01, 0.0, 0.0, 0.0, 0.0,
     0.56671495351937776962531783590e+00, -0.30689499459498916912797304727e+01,
     0.23846676565120698287728149680e+01, 0.21170345824450282767155149946e+01,
     -0.87139158377797299206789907490e+00, 0.22404374302607882758541771650e+01,
     0.63157877876946881815570249290e+00, -0.88990336451333310820698117400e-01,
     0.18148505520854727256656404962e+02, -0.91946323924783554000451984436e+01,
     -0.44360363875948939664310572000e+01},
    {0.10427508642579134603413151009e+02, 0.0, 0.0, 0.0, 0.0,
     0.24228349177525818288430175319e+03, 0.16520045171727028198505394887e+03,
     -0.37454675472269020279518312152e+03, -0.22113666853125306036270938578e+02,
     0.77334326684722638389603898808e+01, -0.30674084731089398182061213626e+02,
     -0.93321305264302278729567221706e+01, 0.15697238121770843886131091075e+02,
     -0.31139403219565177677282850411e+02, -0.93529243588444783865713862664e+01,
     0.35816841486394083752465898540e+02},
    {0.19985053242002433820987653617e+02, 0.0, 0.0, 0.0, 0.0,
     -0.38703730874935176555105901742e+03, -0.18917813819516756882830838328e+03,
     0.52780815920542364900561016686e+03, -0.11573902539959630126141871134e+02,
     0.68812326946963000169666922661e+01, -0.10006050966910838403183860980e+01,
     0.77771377980534432092869265740e+00, -0.27782057523535084065932004339e+01,
     -0.60196695231264120758267380846e+02, 0.84320405506677161018159903784e+02,
     0.11992291136182789328035130030e+02},
    {-0.25693933462703749003312586129e+02, 0.0, 0.0, 0.0, 0.0,
     -0.15418974869023643374053993627e+03, -0.23152937917604549567536039109e+03,
     0.35763911791061412378285349910e+03, 0.93405324183624310003907691704e+02,
     -0.37458323136451633156875139351e+02, 0.10409964950896230045147246184e+03,
     0.29840293426660503123344363579e+02, -0.43533456590011143754432175058e+02,
     0.96324553959188282948394950600e+02, -0.39177261675615439165231486172e+02,
     -0.14972683625798562581422125276e+03}};

/* step-size control (DOP853's defaults: β = 0, safety 0.9, the factor of
 * the new step in [1/3, 6]) */
static const double SAFE = 0.9, FACMIN = 0.333, FACMAX = 6.0;

/* ------------------------------------------------------------------------
 * State */

struct whirl_dop853 {
  double *k[NE]; /* k[0] = f(t, x) at the current point (FSAL) */
  double *rc;    /* 7n: the dense output's coefficients of the last step */
  double *mem;   /* the block holding k and rc (k[0], k[12] are swapped) */
  int dense_ready;
  double h_last; /* signed length of the last accepted step */
};

/* The DOP853 state of o, allocated on first use.  NULL: out of memory. */
static struct whirl_dop853 *state(whirl_ode *o) {
  if (o->d8 != NULL) return o->d8;
  const size_t n = o->n;
  struct whirl_dop853 *d = calloc(1, sizeof *d);
  double *mem = malloc((NE + 7) * n * sizeof *mem);
  if (d == NULL || mem == NULL) {
    free(d);
    free(mem);
    return NULL;
  }
  for (int s = 0; s < NE; ++s) d->k[s] = mem + (size_t)s * n;
  d->rc = mem + (size_t)NE * n;
  d->mem = mem;
  o->d8 = d;
  return d;
}

void whirl_dop853_free_(struct whirl_dop853 *d) {
  if (d == NULL) return;
  free(d->mem);
  free(d);
}

/* xs = x + h Σ_{j<s} A[s][j] k_j */
static void stage_state(const whirl_ode *o, const struct whirl_dop853 *d,
                        int s, double hh, double *xs) {
  const size_t n = o->n;
  memcpy(xs, o->x, n * sizeof *xs);
  for (int j = 0; j < s; ++j) {
    const double a = A[s][j];
    if (a == 0.0) continue;
    const double ha = hh * a, *kj = d->k[j];
    for (size_t i = 0; i < n; ++i) xs[i] += ha * kj[i];
  }
}

/* The stages 1..11 of a step of hh from (t, x), the 8th-order solution in
 * xnew and f(tn, xnew) in k[12].  The rhs status: 0, or the first nonzero
 * one. */
static int stages(whirl_ode *o, struct whirl_dop853 *d, double t, double hh,
                  double tn) {
  const size_t n = o->n;
  int r;
  for (int s = 1; s < NS; ++s) {
    stage_state(o, d, s, hh, o->xs);
    const double ts = s == NS - 1 ? tn : t + C[s] * hh;
    if ((r = whirl_ode_eval_(o, ts, o->xs, d->k[s])) != 0) return r;
  }
  memcpy(o->xnew, o->x, n * sizeof *o->xnew);
  for (int j = 0; j < NS; ++j) {
    if (B[j] == 0.0) continue;
    const double hb = hh * B[j], *kj = d->k[j];
    for (size_t i = 0; i < n; ++i) o->xnew[i] += hb * kj[i];
  }
  return whirl_ode_eval_(o, tn, o->xnew, d->k[NS]);
}

/* DOP853's error: with e5 and e3 the scaled max norms of the 5th- and
 * 3rd-order estimates, |h| e5² / sqrt(e5² + 0.01 e3²) (HNW I §II.10: the
 * 5th-order estimate, kept from being optimistic by the 3rd). */
static double error_norm(const whirl_ode *o, const struct whirl_dop853 *d,
                         double hh) {
  const double *const x = o->x, *const xn = o->xnew;
  double e5 = 0.0, e3 = 0.0;
  for (size_t i = 0; i < o->n; ++i) {
    double s5 = 0.0, s8 = 0.0;
    for (int j = 0; j < NS; ++j) {
      s5 += ER[j] * d->k[j][i];
      s8 += B[j] * d->k[j][i];
    }
    const double s3 = s8 - BHH0 * d->k[0][i] - BHH8 * d->k[8][i] -
                      BHH11 * d->k[11][i];
    const double sk = fmax(o->atol, o->rtol * fmax(fabs(x[i]), fabs(xn[i])));
    e5 = fmax(e5, fabs(s5) / sk);
    e3 = fmax(e3, fabs(s3) / sk);
  }
  const double den = e5 * e5 + 0.01 * e3 * e3;
  return den > 0.0 ? fabs(hh) * e5 * e5 / sqrt(den) : 0.0;
}

/* Accept the step: advance, k[12] becomes k[0] (the old k[0] is kept in
 * k[12]'s place for the dense output) */
static void accept_step(whirl_ode *o, struct whirl_dop853 *d, double t,
                        double tn, double hh, double err, double hnew) {
  const size_t n = o->n;
  memcpy(o->x_prev, o->x, n * sizeof *o->x);
  memcpy(o->x, o->xnew, n * sizeof *o->x);
  double *tmp = d->k[0];
  d->k[0] = d->k[NS];
  d->k[NS] = tmp;
  d->h_last = hh;
  d->dense_ready = 0;
  o->t_prev = t;
  o->t = tn;
  o->facold = fmax(err, 1e-4);
  o->h = hnew;
  o->reject_last = 0;
  o->have_step = 1;
  ++o->st.steps;
}

/* DOP853 as an explicit method of dopri.c's step */
static double *d8_f0(whirl_ode *o) { return o->d8->k[0]; }
static double *d8_scratch(whirl_ode *o) { return o->d8->k[1]; }
static int d8_stages(whirl_ode *o, double t, double hh, double tn) {
  return stages(o, o->d8, t, hh, tn);
}
static double d8_error(const whirl_ode *o, double hh) { return error_norm(o, o->d8, hh); }
static void d8_accept(whirl_ode *o, double t, double tn, double hh, double err, double hnew) {
  accept_step(o, o->d8, t, tn, hh, err, hnew);
}
static const ode_explicit_method dop853 = {
    8, 1.0 / 8.0, 0.0, SAFE, FACMIN, FACMAX,
    d8_f0, d8_scratch, d8_stages, d8_error, d8_accept};

int whirl_dop853_step_(whirl_ode *o, double t_end) {
  if (state(o) == NULL) return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory");
  return whirl_ode_explicit_step_(o, &dop853, t_end);
}

/* ------------------------------------------------------------------------
 * Dense output (CONTD8) */

/* The three extra stages and the coefficients of the last step.  They
 * start from x_prev with the stages of that step: the step's first stage
 * is in k[12] (swapped on acceptance), f at its end in k[0]. */
int whirl_dop853_prepare_dense_(whirl_ode *o) {
  struct whirl_dop853 *d = o->d8;
  if (d == NULL || !o->have_step) return WHIRL_EINVAL;
  if (d->dense_ready) return WHIRL_OK;
  const size_t n = o->n;
  const double hh = d->h_last, t0 = o->t_prev;
  /* the stages in the order of the tableau: K[0] is the step's first */
  double *K[NE];
  for (int s = 0; s < NE; ++s) K[s] = d->k[s];
  K[0] = d->k[NS];
  K[NS] = d->k[0];
  for (int s = NS + 1; s < NE; ++s) {
    double *xs = o->xs;
    memcpy(xs, o->x_prev, n * sizeof *xs);
    for (int j = 0; j < s; ++j) {
      const double a = A[s][j];
      if (a == 0.0) continue;
      for (size_t i = 0; i < n; ++i) xs[i] += hh * a * K[j][i];
    }
    const int r = whirl_ode_eval_(o, t0 + C[s] * hh, xs, K[s]);
    if (r != 0)
      return ODE_FAIL(o, r < 0 ? WHIRL_EUSER : WHIRL_ESTEP,
                      "dense output of the step from t = %.17g: "
                      "right-hand side returned %d",
                      t0, r);
  }
  double *rc = d->rc;
  for (size_t i = 0; i < n; ++i) {
    const double ydiff = o->x[i] - o->x_prev[i];
    const double bspl = hh * K[0][i] - ydiff;
    rc[i] = ydiff;
    rc[n + i] = bspl;
    rc[2 * n + i] = ydiff - hh * K[NS][i] - bspl;
    for (int q = 0; q < 4; ++q) {
      double s = 0.0;
      for (int j = 0; j < NE; ++j) s += D[q][j] * K[j][i];
      rc[(3 + (size_t)q) * n + i] = hh * s;
    }
  }
  d->dense_ready = 1;
  return WHIRL_OK;
}

/* x(t_prev + θ h), after prepare_dense:
 * x_prev + θ(r0 + θ'(r1 + θ(r2 + θ'(r3 + θ(r4 + θ'(r5 + θ r6)))))), θ' = 1 − θ */
void whirl_dop853_dense_(const whirl_ode *o, double t, double *out) {
  const size_t n = o->n;
  const struct whirl_dop853 *d = o->d8;
  const double th = (t - o->t_prev) / (o->t - o->t_prev), th1 = 1.0 - th;
  const double *r = d->rc;
  for (size_t i = 0; i < n; ++i) {
    double v = r[5 * n + i] + th * r[6 * n + i];
    v = r[4 * n + i] + th1 * v;
    v = r[3 * n + i] + th * v;
    v = r[2 * n + i] + th1 * v;
    v = r[n + i] + th * v;
    v = r[i] + th1 * v;
    out[i] = o->x_prev[i] + th * v;
  }
}

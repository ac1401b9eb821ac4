/* rotor/sfd_dynamics.c — the attractors of the SFD rotor at one speed
 * (circular orbits from eq. 15 with Lyapunov certificates, the
 * nonsynchronous limit cycle of the rotating frame) and the initial states
 * of the paper's basins (§5.3).  See whirl/rotor/sfd_dynamics.h for the method.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/linsol.h>
#include <whirl/rotor/sfd_dynamics.h>

/* ------------------------------------------------------------------ frames */

void whirl_sfd_to_rotating(double Om, double t, const double *x, double *xr) {
  const double c = cos(Om * t), s = sin(Om * t);
  /* w = (y + iz) e^{−iΩt} */
  const double u = c * x[0] + s * x[1], v = -s * x[0] + c * x[1];
  /* w' = (y' + iz') e^{−iΩt} − iΩw */
  const double du = c * x[2] + s * x[3] + Om * v;
  const double dv = -s * x[2] + c * x[3] - Om * u;
  xr[0] = u;
  xr[1] = v;
  xr[2] = du;
  xr[3] = dv;
}

void whirl_sfd_to_fixed(double Om, double t, const double *xr, double *x) {
  const double c = cos(Om * t), s = sin(Om * t);
  /* y + iz = w e^{iΩt},  y' + iz' = (w' + iΩw) e^{iΩt} */
  const double a = xr[2] - Om * xr[1], b = xr[3] + Om * xr[0];
  const double y = c * xr[0] - s * xr[1], z = s * xr[0] + c * xr[1];
  x[2] = c * a - s * b;
  x[3] = s * a + c * b;
  x[0] = y;
  x[1] = z;
}

/* ------------------------------------------------- circular orbits at one Ω */

static double G_at(double eps, const double *p) {
  double G = NAN;
  whirl_sfd_circ_G(eps, p[WHIRL_SFD_OMEGA], p[WHIRL_SFD_LAMBDA],
                   p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA], &G, NULL, NULL);
  return G;
}

static int rot_spectrum(const double *p, const double *xs, double *max_re,
                        double *J) {
  const whirl_problem *rot = whirl_sfd_rotating();
  int rc = rot->jac_x(0.0, xs, p, J, NULL);
  if (rc != 0) return rc > 0 ? WHIRL_EDOMAIN : rc;
  whirl_eig *e = whirl_eig_alloc(4);
  if (!e) return WHIRL_ENOMEM;
  double re[4], im[4];
  rc = whirl_eig_compute(e, J, re, im);
  whirl_eig_free(e);
  if (rc != WHIRL_OK) return rc;
  *max_re = re[0];
  return WHIRL_OK;
}

int whirl_sfd_circular_orbits(const double *p, double *eps, int *stable,
                              double *max_re, size_t maxn, size_t *n) {
  if (!p || !n || (maxn && (!eps || !stable))) return WHIRL_EINVAL;
  char msg[128];
  if (whirl_sfd_check_params(p, msg, sizeof msg) != WHIRL_OK)
    return WHIRL_EINVAL;
  if (p[WHIRL_SFD_FE] != 0.0 || !(p[WHIRL_SFD_OMEGA] > 0)) return WHIRL_EINVAL;
  *n = 0;
  /* Grid: 200 geometric values in [1e-9, 1e-2), then 4000 linear to 1. */
  const int NLOG = 200, NLIN = 4000;
  double e_prev = 1e-9, g_prev = G_at(e_prev, p);
  for (int j = 1; j <= NLOG + NLIN - 1; ++j) {
    double e = j < NLOG ? 1e-9 * pow(1e7, (double)j / NLOG)
                        : 1e-2 + (1.0 - 1e-2) * (double)(j - NLOG) / NLIN;
    double g = G_at(e, p);
    if (isfinite(g) && isfinite(g_prev) && ((g_prev < 0) != (g < 0))) {
      double a = e_prev, b = e, ga = g_prev;
      for (int it = 0; it < 200 && b - a > 1e-15 * b; ++it) {
        double m = 0.5 * (a + b), gm = G_at(m, p);
        if ((gm < 0) == (ga < 0)) {
          a = m;
          ga = gm;
        } else {
          b = m;
        }
      }
      double root = 0.5 * (a + b);
      if (*n < maxn) {
        double xs[4], J[16], mr = NAN;
        whirl_sfd_circ_state(root, p[WHIRL_SFD_OMEGA], p[WHIRL_SFD_LAMBDA],
                             p[WHIRL_SFD_DELTA], p[WHIRL_SFD_ZETA], xs);
        int rc = rot_spectrum(p, xs, &mr, J);
        if (rc != WHIRL_OK) return rc;
        eps[*n] = root;
        stable[*n] = mr < 0;
        if (max_re) max_re[*n] = mr;
      }
      ++*n;
    }
    e_prev = e;
    g_prev = g;
  }
  return WHIRL_OK;
}

/* ------------------------------------------------------ attractor tests */

typedef struct {
  double Om;
  double xs[4];
  double P[16];
  double rho;
} circ_data;

static int circ_test(double t, const double *x, void *data) {
  const circ_data *c = data;
  double xr[4], e[4];
  whirl_sfd_to_rotating(c->Om, t, x, xr);
  for (int i = 0; i < 4; ++i) e[i] = xr[i] - c->xs[i];
  double V = 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) V += e[i] * c->P[i + 4 * j] * e[j];
  return V <= c->rho;
}

typedef struct {
  double Om;
  double *pts; /* m rotating-frame samples, a closed polyline in time order */
  size_t m;
  double lo[4], hi[4];
  double scale[4]; /* 1 / range of each coordinate on the cycle */
  double tol;      /* in scaled coordinates (fraction of each range) */
} cycle_data;

/* Squared distance from q to the segment [a, b] in R^4. */
static double seg_dist2(const double *q, const double *a, const double *b,
                        const double *sc) {
  double ab[4], aq[4], l2 = 0, d = 0;
  for (int i = 0; i < 4; ++i) {
    ab[i] = (b[i] - a[i]) * sc[i];
    aq[i] = (q[i] - a[i]) * sc[i];
    l2 += ab[i] * ab[i];
    d += ab[i] * aq[i];
  }
  double s = l2 > 0 ? d / l2 : 0;
  if (s < 0) s = 0;
  if (s > 1) s = 1;
  double r = 0;
  for (int i = 0; i < 4; ++i) {
    double w = aq[i] - s * ab[i];
    r += w * w;
  }
  return r;
}

static double cycle_dist(const cycle_data *c, const double *xr) {
  double best = INFINITY;
  for (size_t k = 0; k + 1 < c->m; ++k) {
    const double *a = c->pts + 4 * k;
    /* cheap reject on the first coordinate pair */
    double du = (xr[0] - a[0]) * c->scale[0], dv = (xr[1] - a[1]) * c->scale[1];
    if (best < INFINITY && du * du + dv * dv > best + 4 * c->tol * c->tol)
      continue;
    double d = seg_dist2(xr, a, a + 4, c->scale);
    if (d < best) best = d;
  }
  return sqrt(best);
}

static int cycle_test(double t, const double *x, void *data) {
  const cycle_data *c = data;
  double xr[4];
  whirl_sfd_to_rotating(c->Om, t, x, xr);
  for (int i = 0; i < 4; ++i) {
    double m = c->tol / c->scale[i];
    if (xr[i] < c->lo[i] - m || xr[i] > c->hi[i] + m) return 0;
  }
  return cycle_dist(c, xr) <= c->tol;
}

/* ------------------------------------------------------ attractor set */

/* every stable circular orbit the solver can return (16) and the limit
 * cycle: no attractor is ever left out */
#define MAX_CIRC 16
#define MAX_ATT (MAX_CIRC + 1)

struct whirl_sfd_attractors {
  size_t n;
  whirl_attractor att[MAX_ATT];
  whirl_sfd_attractor_info info[MAX_ATT];
  circ_data circ[MAX_ATT];
  cycle_data cycle;
};

void whirl_sfd_attractors_options_default(whirl_sfd_attractors_options *o) {
  if (!o) return;
  o->rtol = 1e-12;
  o->atol = 1e-15;
  o->safety = 0.5;
  o->find_cycle = 1;
  o->search_periods = 600;
  o->qp_tol = 0.01;
  o->qp_confirm = 10;
  o->method = WHIRL_ODE_DOPRI5;
}

/* Lyapunov equation AᵀP + PA = −I by its Kronecker form (16 x 16). */
static int lyapunov(const double *A, double *P) {
  double K[256], b[16];
  memset(K, 0, sizeof K);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      int r = i + 4 * j;
      for (int k = 0; k < 4; ++k) {
        K[r + 16 * (k + 4 * j)] += A[k + 4 * i]; /* (AᵀP)_ij = Σ A_ki P_kj */
        K[r + 16 * (i + 4 * k)] += A[k + 4 * j]; /* (PA)_ij = Σ P_ik A_kj */
      }
      b[r] = (i == j) ? -1.0 : 0.0;
    }
  whirl_linsol *ls = whirl_linsol_alloc_dense(16);
  if (!ls) return WHIRL_ENOMEM;
  int rc = whirl_linsol_factor(ls, K);
  if (rc == WHIRL_OK) rc = whirl_linsol_solve(ls, b, 1, 0);
  whirl_linsol_free(ls);
  if (rc != WHIRL_OK) return rc;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      P[i + 4 * j] = 0.5 * (b[i + 4 * j] + b[j + 4 * i]);
  return WHIRL_OK;
}

static double quad(const double *P, const double *e) {
  double V = 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) V += e[i] * P[i + 4 * j] * e[j];
  return V;
}

/* 1 if dV/dt < 0 at x* + e (and the state is inside the clearance). */
static int decreasing(const double *p, const circ_data *c, const double *e) {
  const whirl_problem *rot = whirl_sfd_rotating();
  double x[4], f[4], Pe[4] = {0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) x[i] = c->xs[i] + e[i];
  if (rot->rhs(0.0, x, p, f, NULL) != 0) return 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) Pe[i] += c->P[i + 4 * j] * e[j];
  double dV = 0;
  for (int i = 0; i < 4; ++i) dV += 2.0 * Pe[i] * f[i];
  return dV < 0;
}

static double gauss(uint64_t *s) {
  /* xorshift64* and Box–Muller: deterministic directions */
  double u[2];
  for (int k = 0; k < 2; ++k) {
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    u[k] = ((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
  }
  if (u[0] < 1e-300) u[0] = 1e-300;
  return sqrt(-2.0 * log(u[0])) * cos(2.0 * WHIRL_PI * u[1]);
}

/* Certified level ρ for the circular attractor c (see the header). */
static double certify(const double *p, const circ_data *c, double s_max,
                      double safety) {
  const int NDIR = 4096, NRAD = 400;
  uint64_t seed = 0x9E3779B97F4A7C15ULL;
  double s_min = s_max;
  for (int k = 0; k < NDIR; ++k) {
    double d[4];
    for (int i = 0; i < 4; ++i) d[i] = gauss(&seed);
    double q = sqrt(quad(c->P, d));
    if (!(q > 0)) continue;
    for (int i = 0; i < 4; ++i) d[i] /= q; /* V(s d) = s² */
    double s_ok = 0;
    for (int j = 1; j <= NRAD; ++j) {
      double s = s_max * j / NRAD, e[4];
      if (s >= s_min) break;
      for (int i = 0; i < 4; ++i) e[i] = s * d[i];
      if (!decreasing(p, c, e)) {
        double a = s_ok, b = s;
        for (int it = 0; it < 30; ++it) {
          double m = 0.5 * (a + b);
          for (int i = 0; i < 4; ++i) e[i] = m * d[i];
          if (decreasing(p, c, e))
            a = m;
          else
            b = m;
        }
        if (a < s_min) s_min = a;
        break;
      }
      s_ok = s;
    }
  }
  return (safety * s_min) * (safety * s_min);
}

static void set_cycle_box(cycle_data *c) {
  for (int i = 0; i < 4; ++i) {
    c->lo[i] = INFINITY;
    c->hi[i] = -INFINITY;
  }
  for (size_t k = 0; k < c->m; ++k)
    for (int i = 0; i < 4; ++i) {
      double v = c->pts[4 * k + i];
      if (v < c->lo[i]) c->lo[i] = v;
      if (v > c->hi[i]) c->hi[i] = v;
    }
  for (int i = 0; i < 4; ++i) {
    double r = c->hi[i] - c->lo[i];
    c->scale[i] = r > 1e-12 ? 1.0 / r : 1e12;
  }
}

typedef struct {
  double Om;
  double *pts;
  size_t m, cap;
} rec_ctx;

static int record_rot(size_t k, double t, const double *x, void *data) {
  (void)k;
  rec_ctx *r = data;
  if (r->m >= r->cap) return 0;
  whirl_sfd_to_rotating(r->Om, t, x, r->pts + 4 * r->m);
  ++r->m;
  return 0;
}

typedef struct {
  const cycle_data *c;
  double worst;
} recur_ctx;

static int check_recur(size_t k, double t, const double *x, void *data) {
  (void)k;
  recur_ctx *r = data;
  double xr[4];
  whirl_sfd_to_rotating(r->c->Om, t, x, xr);
  double d = cycle_dist(r->c, xr);
  if (d > r->worst) r->worst = d;
  return 0;
}

/* Look for the nonsynchronous limit cycle; 1 found, 0 not, < 0 error. */
static int find_cycle(const double *p, whirl_sfd_attractors *a,
                      const whirl_sfd_attractors_options *o, char *errbuf,
                      size_t errlen) {
  const double Om = p[WHIRL_SFD_OMEGA], T = 2.0 * WHIRL_PI / Om;
  const double starts[][2] = {{0, 0},     {0.5, 0},   {0, -0.5}, {0.9, 0},
                              {-0.7, 0.3}, {0.2, 0.2}, {0, 0.95}};
  const size_t nstart = sizeof starts / sizeof starts[0];
  whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
  if (!ode) return WHIRL_ENOMEM;
  int rc = whirl_ode_set_tolerances(ode, o->rtol, o->atol);
  if (rc == WHIRL_OK && o->method != WHIRL_ODE_DOPRI5) rc = whirl_ode_set_method(ode, o->method);
  if (rc != WHIRL_OK) {
    whirl_ode_free(ode);
    WHIRL_ERRMSG(errbuf, errlen, rc, "attractors: bad tolerances %g, %g "
                 "or integration method %d", o->rtol, o->atol, o->method);
    return rc;
  }
  whirl_basins_options bo;
  whirl_basins_options_default(&bo);
  bo.period = T;
  bo.max_periods = o->search_periods;
  bo.rtol = o->rtol;
  bo.atol = o->atol;
  bo.method = o->method;
  int found = 0;
  for (size_t s = 0; s < 2 * nstart && !found; ++s) {
    double x0[4] = {starts[s % nstart][0], starts[s % nstart][1], 0, 0};
    if (s >= nstart)
      whirl_sfd_circular_velocity(Om, x0[0], x0[1], &x0[2], &x0[3]);
    int which;
    unsigned per;
    rc = whirl_basins_classify(ode, x0, a->att, a->n, &bo, &which, &per);
    if (rc != WHIRL_OK) break;
    if (which != WHIRL_BASIN_UNSETTLED) continue;
    /* Sample 40 periods at 256 per period in the rotating frame. */
    const size_t SPP = 256, NPER = 40;
    rec_ctx r = {Om, NULL, 0, SPP * NPER + 1};
    r.pts = malloc(4 * r.cap * sizeof *r.pts);
    if (!r.pts) {
      rc = WHIRL_ENOMEM;
      break;
    }
    rc = whirl_ode_sample(ode, T / SPP, SPP * NPER, record_rot, &r);
    if (rc != WHIRL_OK) {
      free(r.pts);
      if (rc == WHIRL_ESTEP) {
        rc = WHIRL_OK;
        continue;
      }
      break;
    }
    cycle_data *c = &a->cycle;
    c->Om = Om;
    c->pts = r.pts;
    c->m = r.m;
    set_cycle_box(c);
    c->tol = o->qp_tol;
    /* The set must be recurrent: the next 40 section points stay within
     * the tolerance of the sampled cycle. */
    recur_ctx rc2 = {c, 0};
    rc = whirl_ode_sample(ode, T, 40, check_recur, &rc2);
    if (rc != WHIRL_OK || !(rc2.worst <= c->tol)) {
      free(c->pts);
      c->pts = NULL;
      c->m = 0;
      rc = WHIRL_OK;
      continue;
    }
    found = 1;
  }
  whirl_ode_free(ode);
  if (rc != WHIRL_OK)
    return WHIRL_ERRMSG(errbuf, errlen, rc,
                        "attractors: searching the nonsynchronous "
                        "response failed: %s",
                        whirl_strerror(rc));
  return found;
}

int whirl_sfd_attractors_find(const double *p,
                              const whirl_sfd_attractors_options *opt,
                              whirl_sfd_attractors **out, char *errbuf,
                              size_t errlen) {
  char dummy[1];
  if (!errbuf || errlen == 0) {
    errbuf = dummy;
    errlen = sizeof dummy;
  }
  errbuf[0] = '\0';
  if (!p || !out)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "attractors: missing argument");
  *out = NULL;
  whirl_sfd_attractors_options o;
  if (opt)
    o = *opt;
  else
    whirl_sfd_attractors_options_default(&o);
  char tmsg[128];
  if (whirl_basins_check_tolerances(o.rtol, o.atol, tmsg, sizeof tmsg))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "attractors: %s", tmsg);
  if (whirl_sfd_check_params(p, errbuf, errlen) != WHIRL_OK)
    return WHIRL_EINVAL;
  if (p[WHIRL_SFD_FE] != 0.0)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "attractors: need FE = 0 (got %g): with a "
                        "static force the rotating frame is not autonomous",
                        p[4]);
  if (!(p[WHIRL_SFD_OMEGA] > 0))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "attractors: Omega must be > 0 (got %g)", p[0]);
  if (!(o.safety > 0 && o.safety <= 1) || !(o.qp_tol > 0) || o.qp_confirm == 0)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "attractors: need 0 < safety <= 1, qp_tol > 0, "
                        "qp_confirm >= 1");
  whirl_sfd_attractors *a = calloc(1, sizeof *a);
  if (!a) return WHIRL_ENOMEM;

  double eps[MAX_CIRC], mr[MAX_CIRC];
  int stable[MAX_CIRC];
  size_t ncirc = 0;
  int rc = whirl_sfd_circular_orbits(p, eps, stable, mr, MAX_CIRC, &ncirc);
  if (rc != WHIRL_OK) {
    WHIRL_ERRMSG(errbuf, errlen, rc, "attractors: circular orbits: %s",
                 whirl_strerror(rc));
    free(a);
    return rc;
  }
  if (ncirc > MAX_CIRC) ncirc = MAX_CIRC; /* the solver returns at most that */
  const double Om = p[WHIRL_SFD_OMEGA];
  double xall[MAX_CIRC][4];
  for (size_t i = 0; i < ncirc; ++i)
    whirl_sfd_circ_state(eps[i], Om, p[WHIRL_SFD_LAMBDA], p[WHIRL_SFD_DELTA],
                         p[WHIRL_SFD_ZETA], xall[i]);
  size_t nstable = 0;
  for (size_t i = 0; i < ncirc; ++i) nstable += stable[i] != 0;
  size_t seen = 0;
  for (size_t i = 0; i < ncirc && a->n < MAX_ATT - 1; ++i) {
    if (!stable[i]) continue;
    circ_data *c = &a->circ[a->n];
    c->Om = Om;
    memcpy(c->xs, xall[i], sizeof c->xs);
    double J[16];
    const whirl_problem *rot = whirl_sfd_rotating();
    rc = rot->jac_x(0.0, c->xs, p, J, NULL);
    if (rc == 0) rc = lyapunov(J, c->P);
    if (rc != WHIRL_OK) {
      WHIRL_ERRMSG(errbuf, errlen, rc,
                   "attractors: Lyapunov equation at eps = %g "
                   "failed: %s",
                   eps[i], whirl_strerror(rc));
      whirl_sfd_attractors_free(a);
      return rc < 0 ? rc : WHIRL_EDOMAIN;
    }
    /* s_max: V-distance to the nearest other circular orbit (where dV/dt
     * = 0), or far enough to reach the housing. */
    double s_max = 0;
    for (int k = 0; k < 4; ++k) s_max += c->P[k * 5];
    s_max = 4.0 * sqrt(s_max);
    for (size_t k = 0; k < ncirc; ++k) {
      if (k == i) continue;
      double e[4];
      for (int q = 0; q < 4; ++q) e[q] = xall[k][q] - c->xs[q];
      double s = sqrt(quad(c->P, e));
      if (s < s_max) s_max = s;
    }
    c->rho = certify(p, c, s_max, o.safety);
    whirl_sfd_attractor_info *inf = &a->info[a->n];
    inf->kind = WHIRL_SFD_CIRCULAR;
    inf->eps = inf->eps_min = eps[i];
    inf->rate = mr[i];
    inf->level = c->rho;
    inf->name = nstable == 1 ? "circular"
                : seen == 0  ? "small"
                : seen == nstable - 1 ? "large"
                                      : "middle";
    ++seen;
    a->att[a->n].name = inf->name;
    a->att[a->n].test = circ_test;
    a->att[a->n].data = c;
    a->att[a->n].confirm = 1;
    ++a->n;
  }
  if (o.find_cycle) {
    int f = find_cycle(p, a, &o, errbuf, errlen);
    if (f < 0) {
      whirl_sfd_attractors_free(a);
      return f;
    }
    if (f == 1) {
      whirl_sfd_attractor_info *inf = &a->info[a->n];
      inf->kind = WHIRL_SFD_QUASIPERIODIC;
      inf->name = "quasiperiodic";
      double emax = 0, emin = INFINITY;
      for (size_t k = 0; k < a->cycle.m; ++k) {
        double e = hypot(a->cycle.pts[4 * k], a->cycle.pts[4 * k + 1]);
        if (e > emax) emax = e;
        if (e < emin) emin = e;
      }
      inf->eps = emax;
      inf->eps_min = emin;
      inf->rate = NAN;
      inf->level = a->cycle.tol;
      a->att[a->n].name = inf->name;
      a->att[a->n].test = cycle_test;
      a->att[a->n].data = &a->cycle;
      a->att[a->n].confirm = o.qp_confirm;
      ++a->n;
    }
  }
  *out = a;
  return WHIRL_OK;
}

void whirl_sfd_attractors_free(whirl_sfd_attractors *a) {
  if (!a) return;
  free(a->cycle.pts);
  free(a);
}

size_t whirl_sfd_attractors_count(const whirl_sfd_attractors *a) {
  return a ? a->n : 0;
}

const whirl_attractor *whirl_sfd_attractors_list(
    const whirl_sfd_attractors *a) {
  return a ? a->att : NULL;
}

const whirl_sfd_attractor_info *whirl_sfd_attractors_info(
    const whirl_sfd_attractors *a, size_t i) {
  return (a && i < a->n) ? &a->info[i] : NULL;
}

const double *whirl_sfd_attractors_cycle(const whirl_sfd_attractors *a,
                                         size_t *m) {
  if (m) *m = a ? a->cycle.m : 0;
  return a ? a->cycle.pts : NULL;
}

/* ------------------------------------------------------ initial states */

size_t whirl_sfd_disc_points(size_t n, double r_max, double *yz, size_t cap) {
  if (n == 0 || !(r_max > 0) || !isfinite(r_max)) return 0;
  const double h = r_max * sqrt(WHIRL_PI / (double)n);
  const long K = (long)floor(r_max / h);
  size_t count = 0;
  for (long i = -K; i <= K; ++i)
    for (long j = -K; j <= K; ++j) {
      double y = h * (double)j, z = h * (double)i;
      if (y * y + z * z > r_max * r_max) continue;
      if (yz && count < cap) {
        yz[2 * count] = y;
        yz[2 * count + 1] = z;
      }
      ++count;
    }
  return count;
}

void whirl_sfd_circular_velocity(double Omega, double y, double z, double *vy,
                                 double *vz) {
  *vy = -Omega * z;
  *vz = Omega * y;
}

typedef struct {
  double *out;
  size_t n;
} traj_ctx;

static int store_state(size_t k, double t, const double *x, void *data) {
  (void)t;
  traj_ctx *c = data;
  if (k == 0) return 0; /* samples at the end of each interval */
  if (k <= c->n) memcpy(c->out + 4 * (k - 1), x, 4 * sizeof *x);
  return 0;
}

int whirl_sfd_trajectory_samples(const double *p, const double *x0,
                                 double skip_periods, double span_periods,
                                 size_t n, double rtol, double atol,
                                 double *out, char *errbuf, size_t errlen) {
  char dummy[1];
  if (!errbuf || errlen == 0) {
    errbuf = dummy;
    errlen = sizeof dummy;
  }
  errbuf[0] = '\0';
  if (!p || !out || n == 0 || !(skip_periods >= 0) || !(span_periods > 0))
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL,
                        "trajectory samples: bad arguments");
  if (whirl_sfd_check_params(p, errbuf, errlen) != WHIRL_OK)
    return WHIRL_EINVAL;
  const double T = 2.0 * WHIRL_PI / p[WHIRL_SFD_OMEGA];
  const double zero[4] = {0, 0, 0, 0};
  whirl_ode *ode = whirl_ode_alloc(whirl_sfd_fixed(), p);
  if (!ode) return WHIRL_ENOMEM;
  int rc = whirl_ode_set_tolerances(ode, rtol, atol);
  if (rc == WHIRL_OK) rc = whirl_ode_reset(ode, 0.0, x0 ? x0 : zero);
  if (rc == WHIRL_OK) rc = whirl_ode_evolve(ode, skip_periods * T);
  traj_ctx c = {out, n};
  if (rc == WHIRL_OK)
    rc = whirl_ode_sample(ode, span_periods * T / (double)n, n, store_state,
                          &c);
  if (rc != WHIRL_OK) {
    if (rc == WHIRL_ESTEP && whirl_ode_last_rhs_status(ode) > 0) {
      WHIRL_ERRMSG(errbuf, errlen, WHIRL_EDOMAIN,
                   "trajectory samples: the journal touches the "
                   "housing (eps >= 1) at t = %g",
                   whirl_ode_t(ode));
      rc = WHIRL_EDOMAIN;
    } else {
      WHIRL_ERRMSG(errbuf, errlen, rc, "trajectory samples: %s",
                   whirl_ode_errmsg(ode));
    }
  }
  whirl_ode_free(ode);
  return rc;
}

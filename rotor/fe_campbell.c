/* rotor/fe_campbell.c — the Campbell diagram of a finite-element rotor (the
 * damped natural frequencies against speed, whirl_fe_modes at each speed)
 * and its critical speeds, where a mode's frequency meets the 1× line
 * ω_j(Ω) = Ω.  Modes are followed by their rank in ascending frequency,
 * which is a continuous function of Ω even where two modes cross (the
 * ranks swap), so g_j(Ω) = ω_j(Ω) − Ω is continuous and every sign change
 * between neighbouring speeds brackets a root; each is refined by the
 * Illinois variant of regula falsi (Dowell & Jarratt, BIT 11, 1971).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor/fe_linear.h>

int whirl_fe_campbell(const whirl_fe_rotor *r, const double *speeds, size_t nspeed,
                      const whirl_fe_modes_options *o, size_t nmodes, whirl_fe_mode *cd, char *msg,
                      size_t len) {
  for (size_t k = 0; k < nspeed; ++k) {
    size_t nf = 0;
    whirl_fe_mode *row = cd + k * nmodes;
    int rc = whirl_fe_modes(r, speeds[k], o, nmodes, row, &nf, msg, len);
    if (rc) return rc;
    for (size_t j = nf; j < nmodes; ++j) row[j] = (whirl_fe_mode){NAN, NAN, NAN, 0};
  }
  return WHIRL_OK;
}

/* g = ω_j(Ω) − Ω and the whirl there */
static int g_of(const whirl_fe_rotor *r, const whirl_fe_modes_options *o, size_t nmodes, size_t j,
                double Om, whirl_fe_mode *buf, double *g, int *whirl, char *msg, size_t len) {
  size_t nf = 0;
  int rc = whirl_fe_modes(r, Om, o, nmodes, buf, &nf, msg, len);
  if (rc) return rc;
  if (j >= nf) {
    if (msg && len) snprintf(msg, len, "mode %zu lost at speed %g rad/s", j + 1, Om);
    return WHIRL_EDOMAIN;
  }
  *g = buf[j].omega - Om;
  *whirl = buf[j].whirl;
  return WHIRL_OK;
}

/* The root of g_j in [a, b], g(a) ga < 0 < g(b) gb or the other way. */
static int refine(const whirl_fe_rotor *r, const whirl_fe_modes_options *o, size_t nmodes, size_t j,
                  double a, double ga, double b, double gb, whirl_fe_mode *buf, whirl_fe_critical *c,
                  char *msg, size_t len) {
  int side = 0, whirl = 0;
  double x = a;
  for (int it = 0; it < 200; ++it) {
    x = (a * gb - b * ga) / (gb - ga);
    double gx;
    int rc = g_of(r, o, nmodes, j, x, buf, &gx, &whirl, msg, len);
    if (rc) return rc;
    if (gx == 0 || fabs(b - a) <= 1e-10 * fabs(x) || fabs(gx) <= 1e-13 * fabs(x)) break;
    if ((gx > 0) == (gb > 0)) {
      b = x;
      gb = gx;
      if (side == -1) ga /= 2;
      side = -1;
    } else {
      a = x;
      ga = gx;
      if (side == 1) gb /= 2;
      side = 1;
    }
  }
  *c = (whirl_fe_critical){(int)j, x, whirl};
  return WHIRL_OK;
}

static int by_speed(const void *a, const void *b) {
  const whirl_fe_critical *x = a, *y = b;
  return (x->speed > y->speed) - (x->speed < y->speed);
}

int whirl_fe_critical_speeds(const whirl_fe_rotor *r, const double *speeds, size_t nspeed,
                             const whirl_fe_modes_options *o, size_t nmodes,
                             const whirl_fe_mode *cd, whirl_fe_critical *crit, size_t maxcrit,
                             size_t *ncrit, char *msg, size_t len) {
  *ncrit = 0;
  whirl_fe_mode *buf = malloc((nmodes + 1) * sizeof *buf);
  if (!buf) return WHIRL_ENOMEM;
  int rc = WHIRL_OK;
  for (size_t j = 0; j < nmodes && !rc; ++j)
    for (size_t k = 0; k + 1 < nspeed && !rc && *ncrit < maxcrit; ++k) {
      const whirl_fe_mode *p = &cd[k * nmodes + j], *q = &cd[(k + 1) * nmodes + j];
      const double ga = p->omega - speeds[k], gb = q->omega - speeds[k + 1];
      if (!(isfinite(ga) && isfinite(gb))) continue;
      if (ga == 0) crit[(*ncrit)++] = (whirl_fe_critical){(int)j, speeds[k], p->whirl};
      else if ((ga > 0) != (gb > 0) && gb != 0)
        rc = refine(r, o, nmodes, j, speeds[k], ga, speeds[k + 1], gb, buf, &crit[(*ncrit)++], msg, len);
    }
  free(buf);
  if (!rc) qsort(crit, *ncrit, sizeof *crit, by_speed);
  return rc;
}

/* lib/ode/sample.c — uniform sampling of a trajectory on the integrator's
 * dense output (time histories, stroboscopic Poincaré sections with dt = T/m,
 * spectra).  Steps are chosen by error control alone; samples are
 * interpolated, so the sampling rate never changes the computed solution.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdlib.h>

#include <whirl/ode.h>

#include "ode_impl.h"

int whirl_ode_sample(whirl_ode *ode, double dt, size_t nsamples,
                     whirl_sample_fn fn, void *data) {
  if (!ode || !fn || !(dt != 0.0) || !isfinite(dt)) return WHIRL_EINVAL;
  const double t_s = whirl_ode_t(ode);
  const double t_end = t_s + (double)nsamples * dt;
  const double dir = dt > 0 ? 1.0 : -1.0;
  size_t k = 0;
  double *x = NULL;
  int status = WHIRL_OK;

  int r = fn(0, t_s, whirl_ode_x(ode), data);
  if (r != 0) return r;
  if (nsamples == 0) return WHIRL_OK;
  k = 1;
  /* step budget between two samples: a stiff stretch (a journal pressed to
   * the housing) cannot make one interval take hours */
  const size_t budget = whirl_ode_max_steps_(ode);
  size_t since = 0;
  while (k <= nsamples) {
    if (budget > 0 && since >= budget) {
      status = ODE_FAIL(ode, WHIRL_EMAXITER,
                        "%zu steps between two samples (t = %.10g, "
                        "next sample at %.10g)",
                        since, whirl_ode_t(ode), t_s + (double)k * dt);
      break;
    }
    status = whirl_ode_step(ode, t_end);
    ++since;
    if (status == WHIRL_DONE) status = WHIRL_OK;
    if (status != WHIRL_OK) break;
    const double t_now = whirl_ode_t(ode);
    if (dir * ((k == nsamples ? t_end : t_s + (double)k * dt) - t_now) <= 0)
      since = 0; /* this step reaches the next sample */
    for (; k <= nsamples; ++k) {
      double tk = (k == nsamples) ? t_end : t_s + (double)k * dt;
      if (dir * (tk - t_now) > 0) break;
      const double *xk;
      if (k == nsamples || tk == t_now) {
        xk = whirl_ode_x(ode);
      } else {
        if (!x) {
          x = malloc(whirl_ode_size(ode) * sizeof *x);
          if (!x) {
            status = WHIRL_ENOMEM;
            break;
          }
        }
        status = whirl_ode_dense(ode, tk, x);
        if (status != WHIRL_OK) break;
        xk = x;
      }
      r = fn(k, tk, xk, data);
      if (r != 0) {
        free(x);
        return r;
      }
    }
    if (status != WHIRL_OK) break;
  }
  free(x);
  return status;
}

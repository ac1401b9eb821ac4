/* lib/ode/method.c — the choice of the integration method of a whirl_ode
 * object (whirl/ode.h): explicit DOPRI5 (dopri.c), explicit DOP853
 * (dop853.c) or BDF by CVODE (bdf.c),
 * and the methods' names for command lines and run files.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>
#include <string.h>

#include <whirl/ode.h>

#include "ode_impl.h"

static const char *const names[] = {"dopri5", "bdf", "dop853"};
enum { NMETHODS = sizeof names / sizeof names[0] };

const char *whirl_ode_method_name(int method) {
  return method >= 0 && method < NMETHODS ? names[method] : NULL;
}

int whirl_ode_method_parse(const char *s, int *method) {
  if (s == NULL || method == NULL) return WHIRL_EINVAL;
  for (int m = 0; m < NMETHODS; ++m)
    if (strcmp(s, names[m]) == 0) {
      *method = m;
      return WHIRL_OK;
    }
  return WHIRL_EINVAL;
}

int whirl_ode_get_method(const whirl_ode *o) { return o ? o->method : -1; }

int whirl_ode_set_method(whirl_ode *o, int method) {
  if (o == NULL) return WHIRL_EINVAL;
  if (whirl_ode_method_name(method) == NULL)
    return ODE_FAIL(o, WHIRL_EINVAL, "unknown integration method %d", method);
  o->method = method;
  if (!o->started) return WHIRL_OK;
  /* restart from the current point: reset copies x0 into o->x */
  double *x = malloc(o->n * sizeof *x);
  if (x == NULL) return ODE_FAIL(o, WHIRL_ENOMEM, "out of memory");
  memcpy(x, o->x, o->n * sizeof *x);
  const int r = whirl_ode_reset(o, o->t, x);
  free(x);
  return r;
}

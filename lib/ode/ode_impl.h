/* lib/ode/ode_impl.h — private to lib/ode: what sample.c needs from the
 * integrator object beyond the public API.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ODE_IMPL_H
#define WHIRL_ODE_IMPL_H

#include <stddef.h>
#include <whirl/ode.h>

/* The step budget of whirl_ode_set_max_steps (0: unlimited). */
size_t whirl_ode_max_steps_(const whirl_ode *o);
/* Store a message in the object's errmsg and return rc. */
int whirl_ode_fail_(whirl_ode *o, int rc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif

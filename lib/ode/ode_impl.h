/* lib/ode/ode_impl.h — private to lib/ode: what sample.c needs from the
 * integrator object beyond the public API.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ODE_IMPL_H
#define WHIRL_ODE_IMPL_H

#include <stddef.h>
#include <whirl/ode.h>

#include "util/errmsg_impl.h"

/* The step budget of whirl_ode_set_max_steps (0: unlimited). */
size_t whirl_ode_max_steps_(const whirl_ode *o);
/* The object's message buffer, WHIRL_ERRMSG_SIZE chars; ODE_FAIL stores
 * "message (file.c:line)" there and evaluates to code. */
char *whirl_ode_errbuf_(whirl_ode *o);
#define ODE_FAIL(o, code, ...) \
  WHIRL_ERRMSG(whirl_ode_errbuf_(o), WHIRL_ERRMSG_SIZE, (code), __VA_ARGS__)

#endif

/* lib/util/errmsg_impl.h — private to lib/: WHIRL_FAIL, which stores
 * "message (file.c:line)" in an object's `char errmsg[N]` member through
 * whirl_errmsg_set (whirl/status.h) and evaluates to the code:
 *   return WHIRL_FAIL(ls, WHIRL_EINVAL, "nrhs = %zu too large", k);
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ERRMSG_IMPL_H
#define WHIRL_ERRMSG_IMPL_H

#include <whirl/status.h>

/* Size of the errmsg member of the objects that have no reason for another. */
#define WHIRL_ERRMSG_SIZE 256

#define WHIRL_FAIL(obj, code, ...) \
  WHIRL_ERRMSG((obj)->errmsg, sizeof((obj)->errmsg), (code), __VA_ARGS__)

#endif

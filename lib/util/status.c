/* lib/util/status.c — messages for whirl's status codes and the version
 * string.  The list lives in whirl/status.h (X-macro), so the enum and its
 * messages cannot drift apart.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <whirl/status.h>

#include "config.h"

const char *whirl_strerror(int status) {
  switch (status) {
#define WHIRL_X_CASE(name, value, msg) \
  case value:                          \
    return msg;
    WHIRL_STATUS_LIST(WHIRL_X_CASE)
#undef WHIRL_X_CASE
  default:
    return status > 0 ? "user callback reported a recoverable failure"
                      : "user callback reported an error";
  }
}

const char *whirl_version(void) { return PACKAGE_VERSION; }

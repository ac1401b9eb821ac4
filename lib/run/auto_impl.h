/* lib/run/auto_impl.h — internal to lib/run: a message "FILE:LINE: ..." on
 * an AUTO constants object (auto_constants.c), for auto_runfile.c.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_AUTO_IMPL_H
#define WHIRL_AUTO_IMPL_H
#include <whirl/auto_constants.h>

int whirl_auto_constants_fail(whirl_auto_constants *ac, int line, const char *fmt, ...)
    WHIRL_PRINTF_LIKE(3, 4);
#endif

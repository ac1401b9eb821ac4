/* lib/util/errmsg.c — the one formatter of whirl's error messages: the
 * message and its origin " (file.c:line)" (whirl/status.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include <whirl/status.h>

int whirl_errmsg_set(char *buf, size_t len, int code, const char *file,
                     int line, const char *fmt, ...) {
  if (buf == NULL || len == 0) return code;
  va_list ap;
  va_start(ap, fmt);
  const int k = vsnprintf(buf, len, fmt, ap);
  va_end(ap);
  if (k >= 0 && (size_t)k < len && file != NULL) {
    const char *base = strrchr(file, '/');
    snprintf(buf + k, len - (size_t)k, " (%s:%d)", base ? base + 1 : file,
             line);
  }
  return code;
}

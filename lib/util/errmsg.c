/* lib/util/errmsg.c — the formatters of whirl's error messages: an
 * object's message with its origin " (file.c:line)", and bad user input
 * located in the user's terms "WHERE: message" (whirl/status.h).
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

int whirl_errmsg_vat(char *buf, size_t len, int code, const char *where,
                     const char *fmt, va_list ap) {
  if (buf == NULL || len == 0) return code;
  size_t k = 0;
  if (where != NULL && where[0] != '\0') {
    const int w = snprintf(buf, len, "%s: ", where);
    if (w < 0) return code;
    k = (size_t)w < len ? (size_t)w : len - 1;
  }
  vsnprintf(buf + k, len - k, fmt, ap);
  return code;
}

int whirl_errmsg_at(char *buf, size_t len, int code, const char *where,
                    const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  whirl_errmsg_vat(buf, len, code, where, fmt, ap);
  va_end(ap);
  return code;
}

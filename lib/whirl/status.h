/* whirl/status.h — status codes shared by every whirl object.
 * One X-macro list gives the enum and the messages (whirl_strerror), so the two
 * never drift apart.  0 is success, > 0 a warning or a normal end, < 0 an error.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_STATUS_H
#define WHIRL_STATUS_H

#include <stddef.h>
#include <stdarg.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define WHIRL_API
#elif defined(__GNUC__) && __GNUC__ >= 4
#define WHIRL_API __attribute__((visibility("default")))
#else
#define WHIRL_API
#endif

#define WHIRL_STATUS_LIST(X)                                                   \
  X(WHIRL_OK, 0, "success")                                                    \
  X(WHIRL_DONE, 1, "branch finished (see the stop reason)")                   \
  X(WHIRL_EINVAL, -1, "invalid argument")                                      \
  X(WHIRL_ENOMEM, -2, "out of memory")                                         \
  X(WHIRL_ENOCONV, -3, "Newton iteration did not converge")                    \
  X(WHIRL_ESTEP, -4, "step size fell below its minimum")                       \
  X(WHIRL_EUSER, -5, "a user callback reported a fatal error")                 \
  X(WHIRL_ELAPACK, -6, "LAPACK reported an error")                             \
  X(WHIRL_ESPARSE, -7, "the sparse solver (UMFPACK) reported an error")        \
  X(WHIRL_EIO, -8, "input/output error")                                       \
  X(WHIRL_EDOMAIN, -9, "state outside the model's domain")                     \
  X(WHIRL_ESINGULAR, -10, "singular matrix")                                   \
  X(WHIRL_EBADFUNC, -11, "a callback returned NaN or Inf")                     \
  X(WHIRL_EMAXITER, -12, "iteration limit reached")                           \
  X(WHIRL_ENOLIB, -13, "a library whirl needs could not be loaded")

typedef enum whirl_status {
#define WHIRL_X_ENUM(name, value, msg) name = value,
  WHIRL_STATUS_LIST(WHIRL_X_ENUM)
#undef WHIRL_X_ENUM
} whirl_status;

/* Message for a status code; never NULL, static storage. */
WHIRL_API const char *whirl_strerror(int status);

#if defined(__GNUC__)
#define WHIRL_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define WHIRL_PRINTF_LIKE(f, a)
#endif

/* Write the message fmt, ... to buf[len] followed by its origin
 * " (name.c:line)", name the base name of file, as GSL_ERROR does, and
 * return code, so that a failing path is one line:
 *   return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "n = %zu", n);
 * Nothing is written when buf is NULL or len is 0; a message that fills buf
 * is truncated and gets no origin, and so does one with file NULL.  Every whirl
 * object stores its last message this way (whirl_cont_errmsg, whirl_ode_errmsg,
 * ...); front ends may strip the origins before showing a message to a user.  A
 * good place for a debugger breakpoint. */
WHIRL_API int whirl_errmsg_set(char *buf, size_t len, int code,
                               const char *file, int line, const char *fmt, ...)
    WHIRL_PRINTF_LIKE(6, 7);
#define WHIRL_ERRMSG(buf, len, code, ...) \
  whirl_errmsg_set((buf), (len), (code), __FILE__, __LINE__, __VA_ARGS__)

/* Write "WHERE: message" to buf[len] and return code: the message of bad
 * user input, located in the user's terms — "ab.whirl:7", "s.ab:12",
 * "command line (--DS=0)", "rotor.rotor:3" — with no source origin.  WHERE
 * NULL or "" gives the message alone.  Every parser of whirl's files
 * reports through it (run files, labelled solutions, rotor files). */
WHIRL_API int whirl_errmsg_at(char *buf, size_t len, int code,
                              const char *where, const char *fmt, ...)
    WHIRL_PRINTF_LIKE(5, 6);
WHIRL_API int whirl_errmsg_vat(char *buf, size_t len, int code,
                               const char *where, const char *fmt, va_list ap)
    WHIRL_PRINTF_LIKE(5, 0);

/* Version of the library, "MAJOR.MINOR.PATCH"; static storage. */
WHIRL_API const char *whirl_version(void);

#ifdef __cplusplus
}
#endif
#endif

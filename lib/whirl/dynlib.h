/* whirl/dynlib.h — the functions of an optional library (UMFPACK, SUNDIALS,
 * ARPACK, CHOLMOD, FFTW) bound at their first use by dlopen and dlsym,
 * not loaded with every program: a process that never factors a sparse
 * matrix or integrates a stiff problem does not map those libraries and
 * their twenty dependencies (~1.1 ms of every start, doc/benchmarks.md).
 * configure finds each library's soname (what a program linked with it
 * would load); where it cannot, the library is linked as usual and the
 * table below holds the functions themselves.
 *
 * A file using, say, UMFPACK includes config.h first, then this header,
 * and writes
 *
 *   #define UMF_FUNCS(X) X(umfpack_di_symbolic) X(umfpack_di_numeric)
 *   WHIRL_DYNLIB_UMFPACK(umf, UMF_FUNCS)
 *
 * and calls umf.umfpack_di_symbolic(...) after umf_bind(err, len) returned
 * WHIRL_OK (the first call binds, under a lock; later ones only look).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DYNLIB_H
#define WHIRL_DYNLIB_H

#include <pthread.h>
#include <stddef.h>
#include <string.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/* any function pointer; every one has this size and representation on
 * the platforms with dlsym (POSIX) */
typedef void (*whirl_dynfn)(void);

/* Open the libraries SONAMES (':'-separated sonames, e.g.
 * "libumfpack.so.5") and store in fns[i] the address of the function
 * names[i], i < n, the first library defining it winning.  WHIRL_OK, or
 * WHIRL_ENOLIB with the reason (the library, dlerror's words) in err.
 * The libraries stay loaded for the life of the process. */
WHIRL_API int whirl_dynlib_bind(const char *sonames, const char *const *names, size_t n,
                                whirl_dynfn *fns, char *err, size_t errlen);

#define WHIRL_DYN_MEMBER(f) __typeof__(f) *f;
#define WHIRL_DYN_NAME(f) #f,
#define WHIRL_DYN_ADDRESS(f) f,
#define WHIRL_DYN_COUNT(f) +1

/* The table TAB of the functions LIST(X) names, bound from SONAMES, and
 * static int TAB_bind(char *err, size_t len): WHIRL_OK once they are
 * bound, else WHIRL_ENOLIB with the reason in err (len > 0). */
#define WHIRL_DYNLIB(TAB, LIST, SONAMES)                                       \
  static struct TAB##_table { LIST(WHIRL_DYN_MEMBER) } TAB;                    \
  static pthread_once_t TAB##_once = PTHREAD_ONCE_INIT;                       \
  static int TAB##_status;                                                     \
  static char TAB##_reason[256];                                               \
  static void TAB##_open(void) {                                               \
    static const char *const names[] = {LIST(WHIRL_DYN_NAME)};                 \
    whirl_dynfn fns[0 LIST(WHIRL_DYN_COUNT)];                                  \
    _Static_assert(sizeof fns == sizeof TAB, "a table of function pointers");  \
    TAB##_status = whirl_dynlib_bind(SONAMES, names, sizeof names / sizeof *names, \
                                     fns, TAB##_reason, sizeof TAB##_reason);  \
    if (TAB##_status == WHIRL_OK) memcpy(&TAB, fns, sizeof TAB);               \
  }                                                                            \
  static int TAB##_bind(char *err, size_t len) {                               \
    pthread_once(&TAB##_once, TAB##_open);                                     \
    if (TAB##_status != WHIRL_OK && err && len) {                              \
      size_t k = strlen(TAB##_reason);                                         \
      k = k < len ? k : len - 1;                                               \
      memcpy(err, TAB##_reason, k);                                            \
      err[k] = '\0';                                                           \
    }                                                                          \
    return TAB##_status;                                                       \
  }

/* The same table when the library is linked (configure found no soname):
 * the functions' own addresses; TAB_bind always WHIRL_OK. */
#define WHIRL_DYNLIB_LINKED(TAB, LIST)                                          \
  static const struct TAB##_table { LIST(WHIRL_DYN_MEMBER) } TAB = {           \
      LIST(WHIRL_DYN_ADDRESS)};                                                \
  static int TAB##_bind(char *err, size_t len) {                               \
    (void)err, (void)len;                                                      \
    return WHIRL_OK;                                                           \
  }

/* whirl's optional libraries: config.h defines WHIRL_DYNLIB_NAME(T, L) as
 * WHIRL_DYNLIB(T, L, sonames) for those it found the sonames of; the
 * others are linked */
#ifndef WHIRL_DYNLIB_UMFPACK
#define WHIRL_DYNLIB_UMFPACK(T, L) WHIRL_DYNLIB_LINKED(T, L)
#endif
#ifndef WHIRL_DYNLIB_SUNDIALS
#define WHIRL_DYNLIB_SUNDIALS(T, L) WHIRL_DYNLIB_LINKED(T, L)
#endif
#ifndef WHIRL_DYNLIB_ARPACK
#define WHIRL_DYNLIB_ARPACK(T, L) WHIRL_DYNLIB_LINKED(T, L)
#endif
#ifndef WHIRL_DYNLIB_CHOLMOD
#define WHIRL_DYNLIB_CHOLMOD(T, L) WHIRL_DYNLIB_LINKED(T, L)
#endif
#ifndef WHIRL_DYNLIB_FFTW3
#define WHIRL_DYNLIB_FFTW3(T, L) WHIRL_DYNLIB_LINKED(T, L)
#endif

#ifdef __cplusplus
}
#endif
#endif

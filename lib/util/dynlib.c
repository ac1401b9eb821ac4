/* lib/util/dynlib.c — whirl_dynlib_bind: the functions of optional
 * libraries found by dlopen and dlsym at their first use (whirl/dynlib.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <whirl/dynlib.h>

#include <dlfcn.h>
#include <stdio.h>

#include "errmsg_impl.h"

#define MAX_LIBS 16 /* sonames in one list */

/* Open each soname of the ':'-separated list; *n of them. */
static int open_all(const char *sonames, void **handle, size_t *n, char *err,
                    size_t errlen) {
  const char *s = sonames;
  *n = 0;
  if (!*s) return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL, "no library named");
  while (*s) {
    const char *colon = strchr(s, ':');
    const size_t len = colon ? (size_t)(colon - s) : strlen(s);
    char name[256];
    if (len == 0 || len >= sizeof name || *n == MAX_LIBS)
      return WHIRL_ERRMSG(err, errlen, WHIRL_EINVAL, "bad list of libraries '%s'", sonames);
    memcpy(name, s, len);
    name[len] = '\0';
    handle[*n] = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (!handle[*n]) {
      const char *why = dlerror();
      return WHIRL_ERRMSG(err, errlen, WHIRL_ENOLIB, "%s could not be loaded: %s", name,
                          why ? why : "unknown reason");
    }
    ++*n;
    s += len + (colon != NULL);
  }
  return WHIRL_OK;
}

int whirl_dynlib_bind(const char *sonames, const char *const *names, size_t n,
                      whirl_dynfn *fns, char *err, size_t errlen) {
  void *handle[MAX_LIBS];
  size_t nlib = 0;
  if (!sonames || !names || !fns) return WHIRL_EINVAL;
  int rc = open_all(sonames, handle, &nlib, err, errlen);
  if (rc != WHIRL_OK) return rc;
  for (size_t i = 0; i < n; i++) {
    void *sym = NULL;
    for (size_t k = 0; k < nlib && !sym; k++) sym = dlsym(handle[k], names[i]);
    if (!sym)
      return WHIRL_ERRMSG(err, errlen, WHIRL_ENOLIB, "no function %s in %s", names[i],
                          sonames);
    /* POSIX: a function's address returned by dlsym as void * */
    memcpy(&fns[i], &sym, sizeof fns[i]);
  }
  return WHIRL_OK;
}

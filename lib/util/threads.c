/* lib/util/threads.c — see threads_impl.h.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "util/threads_impl.h"

#ifdef _OPENMP
#include <omp.h>
#endif

int whirl_thread_num(void) {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

int whirl_threads_resolve(int threads) {
#ifdef _OPENMP
  int t = threads > 0 ? threads : threads == 0 ? omp_get_max_threads() : 1;
  if (t < 1) t = 1;
  return t > WHIRL_MAX_THREADS ? WHIRL_MAX_THREADS : t;
#else
  (void)threads;
  return 1;
#endif
}

/* lib/util/threads_impl.h — private to libwhirl: OpenMP's thread number and
 * the number of threads an option asks for, with or without OpenMP.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_THREADS_IMPL_H
#define WHIRL_THREADS_IMPL_H

/* The most threads a loop of the library uses (options beyond are cut). */
#define WHIRL_MAX_THREADS 256

/* The calling thread's number in the innermost parallel region (0 outside
 * one, or without OpenMP). */
int whirl_thread_num(void);

/* threads as an option means it: > 0 that many (at most
 * WHIRL_MAX_THREADS), 0 as many as OpenMP offers (OMP_NUM_THREADS, else
 * the processors), < 0 or no OpenMP: 1. */
int whirl_threads_resolve(int threads);

#endif

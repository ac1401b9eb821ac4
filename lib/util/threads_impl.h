/* lib/util/threads_impl.h — private to libwhirl: OpenMP's thread number and
 * the number of threads an option asks for, with or without OpenMP.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_THREADS_IMPL_H
#define WHIRL_THREADS_IMPL_H

#include <stddef.h>

/* The most threads a loop of the library uses (options beyond are cut). */
#define WHIRL_MAX_THREADS 256

/* The calling thread's number in the innermost parallel region (0 outside
 * one, or without OpenMP). */
int whirl_thread_num(void);

/* The number of threads of the innermost parallel region (1 outside one,
 * or without OpenMP): a region may get fewer than it asked for (nested in
 * another, OMP_THREAD_LIMIT, OMP_DYNAMIC). */
int whirl_team_size(void);

/* threads as an option means it: > 0 that many (at most
 * WHIRL_MAX_THREADS), 0 as many as OpenMP offers (OMP_NUM_THREADS, else
 * the processors), < 0 or no OpenMP: 1. */
int whirl_threads_resolve(int threads);

/* Per-thread slices of one array, each starting on a cache line of its
 * own: two threads writing neighbouring slices would otherwise share the
 * line between them and pass it back and forth at every write (false
 * sharing; Intel's optimisation manual, 64-byte lines on x86-64).
 * whirl_thread_stride: len elements of size bytes rounded up to whole
 * lines, in elements (size must divide 64).  whirl_thread_alloc: nth
 * slices of stride elements, zeroed, 64-byte aligned, released by free();
 * NULL when out of memory. */
#define WHIRL_CACHE_LINE 64
size_t whirl_thread_stride(size_t len, size_t size);
void *whirl_thread_alloc(size_t nth, size_t stride, size_t size);

/* A parallel loop's governor: how many of its nmax threads the next call
 * of the loop runs on.  The loops of the library are short (a residual or
 * a Jacobian of a few hundred intervals: 0.03-1 ms) and called hundreds
 * of thousands of times a run; when another process holds a core, a
 * thread descheduled in the middle of one stalls the others at its end:
 * demo pla took 40.8 s on two threads beside one busy core where one
 * thread took 17.1 s (107 s beside AUTO's own OpenMP runs, 14 s idle).
 * So the governor times the calls: after a first span on nmax (0.03 s), a
 * few on one thread and a few on nmax (cut short once slower), and the
 * faster count runs until the next probe, the probes rarer (0.03 s to 2 s
 * apart) while the choice stands.  A call on nmax threads stalled by a
 * scheduler slice (over 1 ms beyond twice a one-thread call) probes at
 * once; stalls in two probes in a row tell every governor of the process
 * to run one thread for 2 s (demo man beside a busy core: 16.5 s, 9.4 s
 * with the note, 8.2 s on one thread).  The loops' results do not depend on
 * their threads (they are written so), so neither do the governor's
 * choices change any value.
 * Usage: n = whirl_gov_begin(&g); the loop on n threads; whirl_gov_end(&g). */
typedef struct whirl_gov {
  int nmax;           /* the threads asked for; 1: no governing */
  int use;            /* the threads of the calls until the next probe */
  int phase;          /* 0 running, 1 probing one thread, 2 probing nmax */
  unsigned left;      /* probe calls left in this phase */
  double span;        /* seconds the choice runs before the next probe */
  double start;       /* this call's start (monotonic seconds) */
  double until;       /* the next probe's time */
  double t1, tn;      /* the probes' times */
  unsigned stalls;    /* the last probes in a row with a stalled call */
  double (*clock)(void); /* monotonic seconds; init sets the system's (a
                          * test sets its own, for times it controls) */
} whirl_gov;

void whirl_gov_init(whirl_gov *g, int nmax);
int whirl_gov_begin(whirl_gov *g);
void whirl_gov_end(whirl_gov *g);

/* The threads g's calls run on now (1 while a core is busy elsewhere),
 * untimed: for a loop too rare to probe (a mesh adaptation's maps), on
 * the count its system's governed loops run. */
int whirl_gov_current(const whirl_gov *g);

#endif

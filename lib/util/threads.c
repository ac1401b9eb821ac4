/* lib/util/threads.c — see threads_impl.h.
 * SPDX-License-Identifier: BSD-3-Clause */
#include "util/threads_impl.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

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

int whirl_team_size(void) {
#ifdef _OPENMP
  return omp_get_num_threads();
#else
  return 1;
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

size_t whirl_thread_stride(size_t len, size_t size) {
  const size_t per = WHIRL_CACHE_LINE / size;
  return (len + per - 1) / per * per + (len ? 0 : per);
}

void *whirl_thread_alloc(size_t nth, size_t stride, size_t size) {
  /* a whole number of lines, as C11's aligned_alloc asks */
  const size_t bytes = (nth ? nth : 1) * (stride ? stride * size : WHIRL_CACHE_LINE);
  void *p = aligned_alloc(WHIRL_CACHE_LINE, bytes);
  if (p) memset(p, 0, bytes);
  return p;
}

/* ------------------------------------------------------------ governor */

/* calls a probe times on each count; the time the choice then runs, at
 * first and at most (doubled while it stands): a probe on two threads
 * costs one scheduler slice (~10 ms) where a core is busy, so the
 * choice runs long enough for that to be small, but the first probe comes
 * early: a run of AUTO's demos is often a tenth of a second, and on two
 * threads where one is faster (demo ab's orbits, NTST 70 of two states:
 * 0.17 s against 0.12 s) a first span of 0.2 s ran all of it on two */
enum { GOV_PROBE = 4 };
static const double gov_span0 = 0.03, gov_span_max = 2.0, gov_stall = 1e-3;

static double gov_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void whirl_gov_init(whirl_gov *g, int nmax) {
  g->nmax = nmax > 1 ? nmax : 1;
  g->use = g->nmax; /* the threads asked for, until the first probe */
  g->phase = 0;
  g->left = 0;
  g->span = gov_span0;
  g->start = 0.0;
  g->until = -1.0; /* the first call sets it */
  g->t1 = g->tn = 0.0;
  g->stalls = 0;
  g->clock = gov_now;
}

/* A core busy elsewhere, as any governor of the process last saw it: a
 * call on nmax threads stalled by a scheduler slice during a probe.  Until
 * busy_until (the governors' clock, in nanoseconds; 0: never seen) every
 * governor runs one thread and holds its probes back: each probe's calls
 * on nmax threads cost a slice, and their threads then spin (OpenMP's
 * wait policy) on the core the others need; a process of four governed
 * loops probed four times as often as one. */
static long long busy_until_ns;

static double busy_until(void) {
  return 1e-9 * (double)__atomic_load_n(&busy_until_ns, __ATOMIC_RELAXED);
}

static void note_busy(double until) {
  __atomic_store_n(&busy_until_ns, (long long)(1e9 * until), __ATOMIC_RELAXED);
}

/* A call on nmax threads of dt seconds stalled: over a scheduler slice's
 * scale (1 ms) beyond twice a call on one thread (the last probe's mean;
 * an idle core wakes in tens of microseconds) */
static int gov_stalled(const whirl_gov *g, double dt) {
  return g->t1 > 0.0 && dt > 2.0 * g->t1 / GOV_PROBE + gov_stall;
}

int whirl_gov_begin(whirl_gov *g) {
  if (g->nmax <= 1) return 1;
  g->start = g->clock();
  const double busy = busy_until();
  if (g->phase == 0 && g->use > 1 && g->start < busy) {
    g->use = 1;
    if (g->until < busy) g->until = busy;
  }
  return g->phase == 1 ? 1 : g->phase == 2 ? g->nmax : g->use;
}

/* the probes done: the faster count runs for the next span, longer when
 * it is the count that ran before */
static void gov_decide(whirl_gov *g, double now) {
  const int use = g->tn < g->t1 ? g->nmax : 1;
  if (use == g->use) g->span = g->span < gov_span_max ? 2.0 * g->span : gov_span_max;
  else g->span = gov_span0;
  g->use = use;
  g->phase = 0;
  g->until = now + g->span;
}

int whirl_gov_current(const whirl_gov *g) {
  if (g->nmax <= 1 || g->clock() < busy_until()) return 1;
  return g->use;
}

/* a stall on nmax threads during a probe: one thread for the longest
 * span, and every governor of the process told */
static void gov_busy(whirl_gov *g, double now) {
  g->use = 1;
  g->phase = 0;
  g->span = gov_span_max;
  g->until = now + gov_span_max;
  note_busy(g->until);
}

void whirl_gov_end(whirl_gov *g) {
  if (g->nmax <= 1) return;
  const double now = g->clock(), dt = now - g->start;
  if (g->phase == 0) {
    const double busy = busy_until();
    if (g->until < 0.0) g->until = now + g->span;
    else if (busy > g->until) g->until = busy; /* no probe while the note lasts */
    /* the probe now: its time, or a call on nmax threads stalled (a core
     * busy since the last probe: the probe says whether it stays busy) */
    if (now >= g->until || (g->use > 1 && gov_stalled(g, dt)))
      g->phase = 1, g->left = GOV_PROBE, g->t1 = g->tn = 0.0;
    return;
  }
  if (g->phase == 1) {
    g->t1 += dt;
    if (--g->left == 0) g->phase = 2, g->left = GOV_PROBE + 1;
    return;
  }
  /* a stall: one thread; the process told when the last probe stalled
   * too (the machine's own noise stalls a call now and then: 1-3 ms in
   * a few of a run's probes on an idle 2-vCPU machine; a busy core
   * stalls 4-11 ms in every probe) */
  if (gov_stalled(g, dt)) {
    if (g->stalls++ > 0) gov_busy(g, now);
    else g->tn = g->t1 + dt, gov_decide(g, now);
    return;
  }
  /* the first call on nmax threads wakes them: not timed, unless it took
   * ten times the whole one-thread probe (a core busy elsewhere: a
   * scheduler slice, 10 ms, where the probe took 0.2 ms), which decides */
  if (g->left == GOV_PROBE + 1) {
    --g->left;
    if (dt > 10.0 * g->t1) g->stalls = 0, g->tn = dt, gov_decide(g, now);
    return;
  }
  g->tn += dt;
  /* nmax threads already slower than the whole one-thread probe: done */
  if (--g->left == 0 || g->tn > g->t1) g->stalls = 0, gov_decide(g, now);
}

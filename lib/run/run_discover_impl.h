/* lib/run/run_discover_impl.h — private to the discovery step of a run
 * (run_discover.c: the search and its bookkeeping; run_discover_starts.c:
 * the starts of deflated Newton).  doc/discovery.md.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_RUN_DISCOVER_IMPL_H
#define WHIRL_RUN_DISCOVER_IMPL_H

#include <stdint.h>

#include <whirl/deflate.h>

#include "run_impl.h"

/* Where a new solution came from. */
enum { FROM_START, FROM_SCALED, FROM_SETTLED, FROM_RANDOM, FROM_FOLD, NFROM };

/* The search.  Its unknowns are those of the search system S: the branch
 * system itself for equilibria and harmonic balance; for collocation a
 * second collocation object on a fixed uniform mesh (sc), since the
 * branch's mesh moves along it (IAD) — traced points are mapped onto it
 * (whirl_periodic_convert), seeds back onto the branch's mesh. */
typedef struct disc {
  run_ctx *R;
  const branch_spec *b0;
  const whirl_system *S;   /* the search system */
  whirl_colloc *sc;        /* collocation: the search object (owned) */
  whirl_periodic po;       /* periodic problems: the search discretisation */
  int periodic;
  size_t n, nb, m;         /* model dimension, unknowns, samples of an orbit */
  double *lo, *hi;         /* the box, per model component */
  double *w;               /* weights of the unknowns */
  whirl_deflate *d;
  run_trace *traces;       /* traces[0] is the start branch */
  int *curve;              /* the curve (branch found) each trace belongs to */
  size_t ntraces, cap, ncurves, nclosed;
  uint64_t rng;
  double *p, *x, *xs, *c, *cv, *cv2;
  size_t starts, found[NFROM];
  double t_trace, t_loci;  /* seconds spent tracing new branches, on loci */
} disc;

/* run_discover_starts.c */
double disc_urand(disc *D);
/* The component of the model that unknown j of the search belongs to
 * (n − 1 for a frequency). */
size_t disc_component(const disc *D, size_t j);
/* The k-th start at the current sample (D->p), nknown the solutions known
 * there (the deflation's first roots): 0 with it in x and its kind, 1 when
 * this start is not usable. */
int disc_start(disc *D, size_t k, size_t nknown, double *x, int *from);

#endif

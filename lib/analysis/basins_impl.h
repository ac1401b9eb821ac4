/* lib/analysis/basins_impl.h — what basins.c and basins_atlas.c share: the
 * classification of one trajectory with an optional atlas lookup and an
 * optional record of its section states.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_BASINS_IMPL_H
#define WHIRL_BASINS_IMPL_H

#include <whirl/basins.h>

/* A growing array of section states: n doubles each, the state and its
 * section phase (0 .. section_phases − 1). */
typedef struct basins_record {
  double *x;
  size_t m, cap, n;
  int oom; /* an allocation failed: the record is incomplete */
} basins_record;

/* Class of the cell of x (at section phase `phase`) in the atlas: an attractor index (>= 0) when
 * the cell and its 2n face neighbours were visited by seed trajectories of
 * that class only, else -1. */
int basins_atlas_lookup(const whirl_basins_atlas *a, const double *x,
                        size_t phase);

/* whirl_basins_classify with an atlas (may be NULL: certificates only) and
 * a record of the section states 0 .. the last (rec may be NULL);
 * *by_atlas = 1 when the atlas gave the class. */
int basins_classify_ex(whirl_ode *ode, const double *x0,
                       const whirl_attractor *att, size_t natt,
                       const whirl_basins_options *o,
                       const whirl_basins_atlas *atlas, basins_record *rec,
                       int *which, unsigned *periods, int *by_atlas);

/* The argument checks of whirl_basins_compute (message in errbuf). */
int basins_check(const whirl_problem *prob, const double *p, size_t npoints,
                 const double *x0, const whirl_attractor *att, size_t natt,
                 const whirl_basins_options *o, char *errbuf, size_t errlen);

/* 1 with the seed's class and periods if point g of the atlas's list is a
 * seed, else 0. */
int basins_atlas_seed(const whirl_basins_atlas *a, size_t g, int *which,
                      unsigned *periods);
size_t basins_atlas_points(const whirl_basins_atlas *a);
size_t basins_atlas_dim(const whirl_basins_atlas *a);

#endif

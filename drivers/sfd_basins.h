/* drivers/sfd_basins.h — what `whirl sfd basins` (cmd_sfd_basins.c) and
 * its studies over points (sfd_basins_study.c) share: the options, the
 * attractors and states of one speed, the table's description.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVER_SFD_BASINS_H
#define WHIRL_DRIVER_SFD_BASINS_H

#include <stdint.h>

#include <whirl/rotor.h>

#include "blocks.h"

#define CMD "sfd basins"

typedef struct sb {
  double p[WHIRL_SFD_NPAR];
  const char *vel;
  const char *method_name;   /* --method */
  int vmode, threads, fixed, noplot, quiet, method;
  size_t npoints, periods, seeds, levels, cells, hits, phases;
  double radius, rtol, atol;
  whirl_sfd_attractors *A;
  size_t na, n;              /* attractors, initial states */
  double *X;                 /* the states, 4 a row (NULL when merging) */
  whirl_basins_options bo;
  whirl_basins_atlas *atlas; /* NULL: none (--seeds 0, --fixed-horizon) */
  size_t per[BLOCKS_MAX_STAGES]; /* seeds a block, each round */
  char header[1024];
  double t_att, t_start;
  blocks_def d;
} sb;

/* The name of class w (an attractor's, contact, unsettled, failed). */
const char *sfd_basins_class(const sb *S, int w);
/* The initial states at S->p (S->n, and S->X unless rows_only): 0 or 1. */
int sfd_basins_states(sb *S, int rows_only);
/* S->bo from the options. */
void sfd_basins_options(sb *S);
/* The identity of the options (a checkpoint's). */
uint64_t sfd_basins_id(const sb *S);

/* --study FILE: basin fractions at each point of FILE (whirl/points.h)
 * into DIR/study.tsv, a row a point, through blocks.c (chunk ci of cn,
 * or the merge of `merge` chunks): the exit status. */
int sfd_basins_study(const sb *S, const char *file, const char *dir, size_t ci, size_t cn,
                     size_t merge, int rank, int nranks);

#endif

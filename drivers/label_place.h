/* drivers/label_place.h — where the names of a picture's special points go
 * so that they overlap neither each other, nor the other points, nor (as
 * far as it can) the curves, nor the frame: a greedy choice among eight
 * places around each point (right, left, above, below), the cheapest
 * first.  Coordinates are fractions of the axes ([0, 1] each way); offsets
 * are in gnuplot's character units, as 'set label ... offset DX,DY' takes.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_LABEL_PLACE_H
#define WHIRL_LABEL_PLACE_H

#include <stddef.h>

typedef struct lp_label {
  double u, v;  /* in: the point, fractions of the axes */
  size_t chars; /* in: the label's length in characters */
  double dx, dy; /* out: the offset, characters */
  int right;    /* out: 1 right-justified (the label left of the point) */
} lp_label;

/* Place the N labels L in turn.  CU, CV: one character's width and height
 * as fractions of the axes.  The NC points (CURVE_U, CURVE_V) sample the
 * curves, to be kept clear where a place without them exists. */
void lp_place(lp_label *l, size_t n, double cu, double cv, const double *curve_u,
              const double *curve_v, size_t nc);

/* 1 when the placed labels A and B overlap (the test's check, and the
 * placement's own). */
int lp_overlap(const lp_label *a, const lp_label *b, double cu, double cv);

#endif

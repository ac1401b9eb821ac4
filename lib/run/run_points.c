/* lib/run/run_points.c — the points of a parameter study from a TSV file
 * (POINTS = file.tsv, doc/parameter-studies.md), read by whirl_points_read
 * (whirl/points.h): every header name must be a parameter of the model,
 * not the continuation parameter, not twice; otherwise "FILE:LINE: what",
 * and the run is bad input.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/points.h>

#include "run_impl.h"

static int check_name(const char *name, size_t col, char *why, size_t len, void *ctx) {
  run_ctx *R = ctx;
  whirl_run_ref ref = {0, ""};
  snprintf(ref.name, sizeof ref.name, "%s", name);
  const int k = run_par_index(R, &ref);
  const char *w = k < 0 ? "is not a parameter of model" : k == R->icp[0]
                  ? "is the continuation parameter (ICP) of model" : NULL;
  for (size_t b = 0; !w && b < col; b++)
    if (R->study_par[b] == k) w = "is named twice for model";
  if (!w) {
    R->study_par[col] = k;
    return 0;
  }
  snprintf(why, len, "%s '%s' (the header names parameters that a study varies)", w,
           R->prob.name);
  return 1;
}

int run_points_load(run_ctx *R, const char *path) {
  whirl_points P;
  char msg[1200];
  const int rc = whirl_points_read(path, WHIRL_RUN_MAXITEMS, check_name, R, &P, msg, sizeof msg);
  if (rc == WHIRL_EIO) run_fail(R, WHIRL_RK_POINTS, "POINTS: %s", msg);
  else if (rc != WHIRL_OK) run_say(R, "%s", msg);
  if (rc != WHIRL_OK) return -1;
  R->study_naxes = P.ncols;
  R->study_npoints = P.nrows;
  R->points = P.v; /* taken over */
  P.v = NULL;
  whirl_points_free(&P);
  return 0;
}

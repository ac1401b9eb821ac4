/* whirl/points.h — a list of parameter sets from a TSV file, for studies
 * over points (doc/parameter-studies.md): a header line of names separated
 * by tabs, then a row of values a point; blank lines and lines starting
 * with '#' are skipped, blanks around a field ignored.  Every row must have
 * a finite number under each name, and there must be a row.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_POINTS_H
#define WHIRL_POINTS_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

#define WHIRL_POINTS_MAXNAME 64

typedef struct whirl_points {
  size_t ncols, nrows;
  char (*names)[WHIRL_POINTS_MAXNAME]; /* ncols header names */
  double *v;                /* nrows × ncols values, row by row */
  size_t header_line;       /* the header's line in the file (1-based) */
} whirl_points;

/* Checks a header name: 0, or nonzero with why[len] ("is not a parameter
 * of model 'x'"), which becomes "FILE:LINE: column K, 'NAME' why". */
typedef int (*whirl_points_name_check)(const char *name, size_t col, char *why, size_t len,
                                       void *ctx);

/* Read `path` (at most maxcols columns; check, may be NULL, called for each
 * header name in order) into *out, which whirl_points_free releases.
 * WHIRL_OK, or WHIRL_EINVAL (the file is not such a list: "FILE:LINE: ..."
 * in msg), WHIRL_EIO (it cannot be read), WHIRL_ENOMEM. */
WHIRL_API int whirl_points_read(const char *path, size_t maxcols, whirl_points_name_check check,
                                void *ctx, whirl_points *out, char *msg, size_t len);
WHIRL_API void whirl_points_free(whirl_points *p);

#ifdef __cplusplus
}
#endif
#endif

/* whirl/runfile.h — run files: AUTO-style constants as `key = value` lines.
 *
 *     # ab-2.whirl
 *     model = ab.so           # a plug-in (path relative to the run file) or
 *                             # a built-in model name (sfd, sfd-rotating)
 *     ICP   = [Da]            # names or 1-based indices
 *     PAR   = {B: 14, beta: 3}
 *     DS    = 0.01            # AUTO names, case-insensitive, or long
 *     step  = 0.01            #   aliases (doc/run-files.md has the table)
 *     UZR   = {Da: [0.1, 0.2]}
 *
 * A value is a number, a word or quoted string, a list `[a, b]` (or items
 * separated by commas/blanks), or a dictionary `{key: value, ...}` whose
 * values are scalars or lists and whose keys differ.  Numbers are decimal
 * (whirl_run_number).  `#` starts a comment outside quotes.  One
 * key per line; a key may appear once in a file; command-line overrides
 * (`--DS=0.02`) replace file values.  Every error names the file and line
 * ("ab.whirl:7: DS: '0,01' is not a number") and the parse stops there.
 *
 * Names of parameters and state components are kept as written: the model
 * is not known here, so the caller resolves them (whirl_runfile_where gives
 * the line to blame).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_RUNFILE_H
#define WHIRL_RUNFILE_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The keys (doc/run-files.md).  Order matters only for the table. */
typedef enum whirl_run_key {
  WHIRL_RK_MODEL, WHIRL_RK_NDIM, WHIRL_RK_IPS, WHIRL_RK_METHOD, WHIRL_RK_ICP,
  WHIRL_RK_PAR, WHIRL_RK_U, WHIRL_RK_ILP, WHIRL_RK_ISP, WHIRL_RK_ISW,
  WHIRL_RK_IRS, WHIRL_RK_S, WHIRL_RK_NTST, WHIRL_RK_NCOL, WHIRL_RK_IAD,
  WHIRL_RK_NHB, WHIRL_RK_OVERSAMPLING, WHIRL_RK_DS, WHIRL_RK_DSMIN,
  WHIRL_RK_DSMAX, WHIRL_RK_NMX, WHIRL_RK_NPR, WHIRL_RK_RL0, WHIRL_RK_RL1,
  WHIRL_RK_A0, WHIRL_RK_A1, WHIRL_RK_EPSL, WHIRL_RK_EPSU, WHIRL_RK_EPSS,
  WHIRL_RK_ITNW, WHIRL_RK_JAC, WHIRL_RK_UZR, WHIRL_RK_UZSTOP, WHIRL_RK_OUT,
  WHIRL_RK_PLOT, WHIRL_RK_BASIN_AXES, WHIRL_RK_BASIN_GRID,
  WHIRL_RK_BASIN_PERIODS, WHIRL_RK_BASIN_ATTRACTORS, WHIRL_RK_BASIN_TOL,
  WHIRL_RK_IGNORED, /* AUTO keys whirl accepts and ignores (ITMX, NWTN, ...) */
  WHIRL_RK_COUNT
} whirl_run_key;

/* Problem types (IPS). */
enum { WHIRL_IPS_EQUILIBRIA = 1, WHIRL_IPS_PERIODIC = 2,
       WHIRL_IPS_BASINS = 11 };
/* Periodic-orbit methods (METHOD). */
enum { WHIRL_METHOD_COLLOC = 0, WHIRL_METHOD_HBM = 1 };

#define WHIRL_RUN_MAXNAME 64
#define WHIRL_RUN_MAXPATH 1024
#define WHIRL_RUN_MAXITEMS 64

/* A reference to a parameter or state component: by 1-based index (index
 * > 0, name empty) or by name (index 0). */
typedef struct whirl_run_ref {
  int index;
  char name[WHIRL_RUN_MAXNAME];
} whirl_run_ref;

typedef struct whirl_run_value {
  whirl_run_ref ref;
  double value;
} whirl_run_value;

typedef struct whirl_run_range {
  whirl_run_ref ref;
  double lo, hi;
} whirl_run_range;

typedef struct whirl_run_settings {
  char model[WHIRL_RUN_MAXPATH];
  char out[WHIRL_RUN_MAXPATH];  /* "" : default <stem>.out */
  char s[WHIRL_RUN_MAXPATH];    /* restart directory ("" none) */
  int ndim;                     /* 0: not given */
  int ips;                      /* WHIRL_IPS_* (default 1) */
  int method;                   /* WHIRL_METHOD_* (default colloc) */
  whirl_run_ref icp[4];
  size_t nicp;
  whirl_run_value par[WHIRL_RUN_MAXITEMS];
  size_t npar;
  whirl_run_value u[WHIRL_RUN_MAXITEMS];
  size_t nu;
  int ilp, isp, isw;            /* defaults 1, 2, 1 */
  int irs;                      /* label, or the count with irs_type */
  char irs_type[3];             /* "" or a type name (IRS = HB2) */
  int ntst, ncol, iad;          /* defaults 20, 4, 3 */
  int nhb, oversampling;        /* defaults 8, 4 */
  double ds, dsmin, dsmax;      /* defaults 0.01, 1e-5, 0.1; |DS| is
                                   clipped to [DSMIN, DSMAX] as in AUTO */
  int nmx, npr;                 /* defaults 200, 0 (no regular labels) */
  double rl0, rl1, a0, a1;      /* defaults -1e30, 1e30, 0, 1e30 */
  double epsl, epsu, epss;      /* defaults 1e-7, 1e-7, 1e-5 */
  int itnw, jac;                /* defaults 8, 1 */
  whirl_run_value uzr[WHIRL_RUN_MAXITEMS];
  size_t nuzr;
  whirl_run_value uzstop[WHIRL_RUN_MAXITEMS];
  size_t nuzstop;
  char plot[WHIRL_RUN_MAXNAME]; /* y axis of the picture: "" L2-NORM */
  whirl_run_range axes[2];      /* basins: two state components and ranges */
  size_t naxes;
  int grid[2];                  /* basins: points per axis (default 41) */
  int basin_periods;            /* basins: max forcing periods (500) */
  int attractors[WHIRL_RUN_MAXITEMS]; /* basins: labels in S */
  size_t nattractors;
  double basin_tol;             /* basins: capture radius (1e-3) */
} whirl_run_settings;

typedef struct whirl_runfile whirl_runfile;

WHIRL_API whirl_runfile *whirl_runfile_alloc(void);
WHIRL_API void whirl_runfile_free(whirl_runfile *rf); /* accepts NULL */

/* Parse text[len] (need not be NUL-terminated) read from the file called
 * `name` (used in messages).  May be called once per object.  Returns
 * WHIRL_OK or WHIRL_EINVAL (message in whirl_runfile_errmsg). */
WHIRL_API int whirl_runfile_parse(whirl_runfile *rf, const char *name,
                                  const char *text, size_t len);

/* Read and parse a file.  WHIRL_EIO when it cannot be read. */
WHIRL_API int whirl_runfile_read(whirl_runfile *rf, const char *path);

/* A command-line override "--KEY=value" (or "KEY=value"), after parsing. */
WHIRL_API int whirl_runfile_override(whirl_runfile *rf, const char *arg);

/* Check that the required keys are present and consistent (model, ICP
 * unless IPS = basins, ...).  Call after the overrides. */
WHIRL_API int whirl_runfile_check(whirl_runfile *rf);

WHIRL_API const whirl_run_settings *whirl_runfile_settings(
    const whirl_runfile *rf);

/* 1 if the key was given (file or command line). */
WHIRL_API int whirl_runfile_given(const whirl_runfile *rf, whirl_run_key k);

/* Where a key was set, for messages: "ab.whirl:7", "command line
 * (--DS=...)" or, for a key that was not given, "ab.whirl".  Returns buf. */
WHIRL_API const char *whirl_runfile_where(const whirl_runfile *rf,
                                          whirl_run_key k, char *buf,
                                          size_t len);

/* The file name as given to parse/read ("" before). */
WHIRL_API const char *whirl_runfile_name(const whirl_runfile *rf);

/* Canonical (AUTO) name of a key, e.g. "DS". */
WHIRL_API const char *whirl_run_key_name(whirl_run_key k);

/* Keys the file set that whirl accepts for AUTO compatibility but ignores,
 * as a comma-separated list ("" if none), for the run's log. */
WHIRL_API const char *whirl_runfile_ignored(const whirl_runfile *rf);

/* A number as run files write it (AUTO's syntax): decimal with an optional
 * sign, point and exponent (0.1, -2, .5, 1e-3, 2.0E+1), nothing else: no
 * blanks, no hexadecimal, no inf or nan.  An underflow (1e-310, 1e-400)
 * gives the nearest double, a denormal or 0.  Returns WHIRL_OK with *x set,
 * WHIRL_EDOMAIN for a number that is not finite (nan, inf, 1e999),
 * WHIRL_EINVAL for anything else.  The other commands read their numeric
 * options with it too. */
WHIRL_API int whirl_run_number(const char *s, double *x);

/* The last error, "FILE:LINE: message" ("" if none); owned by rf. */
WHIRL_API const char *whirl_runfile_errmsg(const whirl_runfile *rf);

#ifdef __cplusplus
}
#endif
#endif

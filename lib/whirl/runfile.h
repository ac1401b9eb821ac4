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
  WHIRL_RK_DISCOVER, WHIRL_RK_DISCOVER_BOX, WHIRL_RK_DISCOVER_STARTS,
  WHIRL_RK_DISCOVER_SEED, WHIRL_RK_DISCOVER_SETTLE, WHIRL_RK_STUDY,
  WHIRL_RK_IPLT, /* AUTO's measure in the L2-NORM column */
  WHIRL_RK_DAT,  /* a start orbit from a data file (AUTO's dat) */
  WHIRL_RK_POINTS, WHIRL_RK_BASIN_SEEDS,
  WHIRL_RK_BASIN_METHOD, /* the integrator of basins (whirl_ode_method) */
  WHIRL_RK_THL, WHIRL_RK_THU, /* AUTO's weights of the arclength norm */
  WHIRL_RK_STOP,    /* end a branch at the n-th point of a type (AUTO's STOP) */
  WHIRL_RK_NBC, WHIRL_RK_NINT, /* IPS 4: boundary and integral conditions */
  WHIRL_RK_ORBIT_MAX, /* MAX of an orbit: the curve's (0) or AUTO's, over nodes (1) */
  WHIRL_RK_MESH_RULE, /* orbits' adapted mesh: whirl's derivative (0) or AUTO's jumps (1) */
  WHIRL_RK_THREADS, /* threads of the collocation (0: OpenMP's default) */
  WHIRL_RK_NWTN,    /* AUTO's NWTN: Newton iterations with a new Jacobian (0: all) */
  WHIRL_RK_IGNORED, /* AUTO keys whirl accepts and ignores (ITMX, NWTN, ...) */
  WHIRL_RK_EQ_STEP, /* algebraic branches' step: the tangent's hyperplane (0) or
                       AUTO's sphere about the last point on the secant (1) */
  WHIRL_RK_DIFFERENCES, /* BVPs' difference quotients: central (0) or AUTO's
                           FUNI and ICNI with JAC = 0 (1) */
  WHIRL_RK_UDOT,        /* BVPs' integral conditions' udot: u'(t) (0) or the
                           branch's direction, AUTO's UDOT (1) */
  WHIRL_RK_HB_PERIOD,   /* IPS 2 from an equilibrium label: a Hopf start with
                           the period this parameter holds (AUTO's TY = 'HBk') */
  WHIRL_RK_TANGENT,     /* a new point's tangent from the corrector's last
                           factorisation: refined once (0) or as it is,
                           AUTO's direction vector (1) */
  WHIRL_RK_MX,          /* a branch whose Newton fails at DSMIN: the run
                           fails (0), or its last point is labelled MX and
                           the run goes on, as AUTO's (1) */
  WHIRL_RK_LOCATE,      /* special points located to convergence (0) or
                           by AUTO's secant and Mueller iteration to its
                           step tolerance EPSS (1) */
  WHIRL_RK_ITMX,        /* AUTO's ITMX: the iterations of that location */
  WHIRL_RK_PHASE,       /* orbits' phase condition: whirl's at the Gauss
                           points (0) or AUTO's at the nodes with the
                           model's f (1) */
  WHIRL_RK_COUNT
} whirl_run_key;

/* Problem types (IPS). */
enum { WHIRL_IPS_MAP = -1, WHIRL_IPS_EQUILIBRIA = 1, WHIRL_IPS_PERIODIC = 2,
       WHIRL_IPS_BVP = 4, WHIRL_IPS_BASINS = 11 };
/* Periodic-orbit methods (METHOD). */
enum { WHIRL_METHOD_COLLOC = 0, WHIRL_METHOD_HBM = 1 };

#define WHIRL_RUN_MAXNAME 64
#define WHIRL_RUN_MAXPATH 1024
#define WHIRL_RUN_MAXITEMS 64
#define WHIRL_RUN_MAXICP 16 /* ICP entries (AUTO demos list up to 11) */

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

/* The value of a key, given or its default (doc/run-files.md).
 * Integer keys — NDIM (0: not given), IPS, METHOD, ILP, ISP, ISW, IRS (the
 * label, or the count with a type), NTST, NCOL, IAD, NHB, OVERSAMPLING,
 * NMX, NPR, ITNW, JAC, NBC, NINT, BASIN_PERIODS, BASIN_SEEDS, BASIN_METHOD (a
 * whirl_ode_method) — through _int; real keys — DS, DSMIN,
 * DSMAX, RL0, RL1, A0, A1, EPSL, EPSU, EPSS, BASIN_TOL — through _real;
 * WHIRL_EINVAL for a key of another type, *v untouched. */
WHIRL_API int whirl_runfile_int(const whirl_runfile *rf, whirl_run_key k,
                                int *v);
WHIRL_API int whirl_runfile_real(const whirl_runfile *rf, whirl_run_key k,
                                 double *v);
/* Text keys — MODEL, OUT ("": the default <stem>.out), S ("": none), PLOT
 * ("": L2-NORM) and IRS's type ("" or a type name, IRS = HB2) — owned by
 * rf; NULL for a key of another type. */
WHIRL_API const char *whirl_runfile_string(const whirl_runfile *rf,
                                           whirl_run_key k);
/* List keys — ICP, PAR, U, UZR, UZSTOP, STOP, BASIN_AXES, BASIN_GRID,
 * BASIN_ATTRACTORS — the number of items (0 for a key of another type),
 * and item i: ICP's parameter in ref (value 0); PAR's, U's, UZR's and
 * UZSTOP's reference and value; STOP's point type in ref.name and its
 * count in value; BASIN_GRID's points per axis and
 * BASIN_ATTRACTORS' labels in value (ref index 0, name "").  WHIRL_EINVAL
 * when i is out of range or k is not a list key. */
WHIRL_API size_t whirl_runfile_count(const whirl_runfile *rf, whirl_run_key k);
WHIRL_API int whirl_runfile_item(const whirl_runfile *rf, whirl_run_key k,
                                 size_t i, whirl_run_value *item);
/* BASIN_AXES' item i: the state component and its range. */
WHIRL_API int whirl_runfile_axis(const whirl_runfile *rf, size_t i,
                                 whirl_run_range *axis);
/* DISCOVER_BOX's item i (whirl_runfile_count gives their number). */
WHIRL_API int whirl_runfile_box(const whirl_runfile *rf, size_t i,
                                whirl_run_range *range);

/* 1 if the key was given (file or command line). */
WHIRL_API int whirl_runfile_given(const whirl_runfile *rf, whirl_run_key k);
/* 1 if the key's value is a command-line override's (whose paths are
 * relative to the current directory, those of the file to the file's). */
WHIRL_API int whirl_runfile_on_command_line(const whirl_runfile *rf, whirl_run_key k);

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

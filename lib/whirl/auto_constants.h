/* whirl/auto_constants.h — AUTO-07p constants files (c.NAME) read as
 * AUTO-07p 0.9.2 reads them (its python/auto/parseC.py), unchanged:
 *
 *     NDIM=   2, IPS =   1, IRS =   0, ILP =   1
 *     ICP =  [2]
 *     THL =  {11: 0.0}, THU =  {}
 *     UZR =  {2: [14.0, 15.0, 16.0, 17.0]}, UZSTOP = {-1: 0.25}
 *     unames = {1: 'u1', 2: 'u2'}, parnames = {1: "Da", 2: "B"}
 *     e = 'ab', dat = 'ab.dat'
 *
 * Several `KEY = value` on a line, separated by commas or blanks; values in
 * Python literal syntax: numbers, strings in either quote, lists, and
 * dictionaries whose values are numbers or lists of numbers, continued over
 * lines while a bracket is open.  A line starting with '#', '!' or '_' is a
 * comment, and so is the rest of a line from a '#' where a key would start.
 * Key names are case-sensitive, as in AUTO.  A later assignment of a key
 * replaces an earlier one; a dictionary naming one index twice collects the
 * values (UZR = {2: 14, 2: 15} is {2: [14, 15]}), as AUTO does.
 *
 * Values are typed by key as AUTO types them: integers for keys starting
 * with I..N (NDIM, IPS, NMX, ...; `NMX = ****` is 10^4, AUTO's shorthand),
 * IRS an integer or a label name (HB2), reals for the others (DS, EPSL,
 * RL0, ...; `DS = '-'` negates the DS given before, -0.01 without one);
 * lists ICP, IREV, IFIXED, IPSI (integers or names), SP and STOP (names);
 * indexed lists THL, THU, UZR, UZSTOP, U, PAR (index or name -> a number or
 * a list of numbers; a negative UZR index means "stop there"), unames and
 * parnames (index -> name); texts e, s, dat, sv, TY.  Numbers may be
 * Fortran-style (1.0D-3, 1.0-100).
 *
 * Old-style numeric constants files (ten lines of numbers) are not read:
 * none of AUTO-07p 0.9.2's demos has one; whirl says so, naming the line.
 * Differences from AUTO, all where AUTO raises a Python exception or
 * silently drops text: an unknown key, a bad number, an unterminated
 * bracket or quote, text after a closing bracket, and a dictionary entry
 * without a value are errors "FILE:LINE: message" (WHIRL_EINVAL; a file
 * that cannot be read: WHIRL_EIO).  Nothing here prints or exits.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_AUTO_CONSTANTS_H
#define WHIRL_AUTO_CONSTANTS_H

#include <stddef.h>
#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_auto_constants whirl_auto_constants;

/* How a key's value is typed (see above). */
typedef enum whirl_auto_kind {
  WHIRL_AC_NONE = 0, /* not an AUTO constant */
  WHIRL_AC_INT,      /* NDIM, IPS, ...; IRS may also be TEXT */
  WHIRL_AC_REAL,     /* DS, EPSL, RL0, ... */
  WHIRL_AC_TEXT,     /* e, s, dat, sv, TY; IRS given as a label name */
  WHIRL_AC_LIST,     /* ICP, IREV, IFIXED, IPSI, SP, STOP */
  WHIRL_AC_INDEXED,  /* THL, THU, UZR, UZSTOP, U, PAR */
  WHIRL_AC_NAMES     /* unames, parnames */
} whirl_auto_kind;

/* An item of a list or indexed key.  `name` is NULL when the index (or
 * list entry) is an integer, in `index`; otherwise index is 0 and name the
 * text ('PERIOD', 'lambda', 'HB1').  For INDEXED keys the values follow:
 * nvalues numbers, `is_list` 1 when written as a list ([14, 15]; also a
 * list of one).  For NAMES, `text` is the name given to the index. */
typedef struct whirl_auto_item {
  int index;
  const char *name;
  const double *values;
  size_t nvalues;
  int is_list;
  const char *text;
} whirl_auto_item;

WHIRL_API whirl_auto_constants *whirl_auto_constants_alloc(void);
WHIRL_API void whirl_auto_constants_free(whirl_auto_constants *ac); /* NULL ok */

/* Parse text[len] read from a file called NAME (for messages).  Once per
 * object.  WHIRL_OK, WHIRL_EINVAL or WHIRL_ENOMEM (message in _errmsg). */
WHIRL_API int whirl_auto_constants_parse(whirl_auto_constants *ac,
                                         const char *name, const char *text,
                                         size_t len);
/* Read and parse the file PATH (named PATH in messages). */
WHIRL_API int whirl_auto_constants_read(whirl_auto_constants *ac,
                                        const char *path);

/* "FILE:LINE: message" of the last error, "" if none. */
WHIRL_API const char *whirl_auto_constants_errmsg(const whirl_auto_constants *ac);
WHIRL_API const char *whirl_auto_constants_name(const whirl_auto_constants *ac);

/* The kind of AUTO constant KEY (case-sensitive), WHIRL_AC_NONE if AUTO
 * has no such key.  For a given key, the kind of its value (IRS: INT or
 * TEXT). */
WHIRL_API whirl_auto_kind whirl_auto_key_kind(const char *key);
WHIRL_API whirl_auto_kind whirl_auto_constants_kind(const whirl_auto_constants *ac,
                                                    const char *key);

/* The line the key was (last) set at, 0 if it was not given. */
WHIRL_API int whirl_auto_constants_line(const whirl_auto_constants *ac,
                                        const char *key);

/* The keys given, in the order of their first assignment. */
WHIRL_API size_t whirl_auto_constants_nkeys(const whirl_auto_constants *ac);
WHIRL_API const char *whirl_auto_constants_key(const whirl_auto_constants *ac,
                                               size_t i);

/* A given key's value: WHIRL_OK, or WHIRL_EINVAL when the key was not
 * given or has another kind (*v untouched).  _text returns NULL then. */
WHIRL_API int whirl_auto_constants_int(const whirl_auto_constants *ac,
                                       const char *key, int *v);
WHIRL_API int whirl_auto_constants_real(const whirl_auto_constants *ac,
                                        const char *key, double *v);
WHIRL_API const char *whirl_auto_constants_text(const whirl_auto_constants *ac,
                                                const char *key);
/* LIST, INDEXED and NAMES keys: the number of items (0 if not given) and
 * item i (its pointers owned by ac). */
WHIRL_API size_t whirl_auto_constants_count(const whirl_auto_constants *ac,
                                            const char *key);
WHIRL_API int whirl_auto_constants_item(const whirl_auto_constants *ac,
                                        const char *key, size_t i,
                                        whirl_auto_item *item);

/* ---- as a whirl run file (doc/auto-files.md) ---------------------------
 * The run file `whirl run` executes for these constants: the keys whirl
 * shares with AUTO copied (NDIM, IPS, ILP, ISP, ISW, NTST, NCOL, IAD, NMX,
 * NPR, RL0, RL1, A0, A1, EPS*, DS*, ITNW, JAC, PAR, U, the AUTO keys whirl
 * accepts and ignores), THL and THU (the arclength weights), indices for names (parnames, unames; PERIOD and
 * PAR(11) of orbits as PERIOD), UZR's negative indices as UZSTOP, IRS with
 * S = opts->restart.  What whirl cannot do yet is refused (IPS other than
 * 1 and 2, dat) with the line of the key; what it does not use (THL
 * beyond NPAR, SP, UZR on PVLS quantities beyond NPAR) is written as a "# note:"
 * comment, so run.log shows it.  *text is malloc'd (the caller frees). */
typedef struct whirl_auto_runfile_opts {
  const char *model;   /* `model = ` (a plug-in path) */
  const char *restart; /* `S = `: the output directory IRS refers to, or NULL */
  const char *label;   /* replaces IRS ("3", "HB1"), or NULL */
  const char *out;     /* `OUT = `: the run's output directory, or NULL */
  size_t npar;         /* the model's parameters PAR(1..npar) */
  const char *dir;     /* where `dat` files are (AUTO's run directory), or
                          NULL: the working directory */
} whirl_auto_runfile_opts;

WHIRL_API int whirl_auto_constants_runfile(whirl_auto_constants *ac,
                                           const whirl_auto_runfile_opts *opts,
                                           char **text);

#ifdef __cplusplus
}
#endif
#endif

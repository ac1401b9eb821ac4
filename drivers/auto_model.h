/* drivers/auto_model.h — an AUTO-07p equations file (NAME.f90, NAME.f) as
 * a whirl plug-in NAME.so: the file, a generated C file of the model's data
 * (auto_model.c in the output) and whirl's adapter of AUTO's routines
 * (drivers/auto_adapter.c, built once into libwhirl-auto-adapter.a),
 * compiled and linked by gfortran (or $FC).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_AUTO_MODEL_H
#define WHIRL_AUTO_MODEL_H
#include <stddef.h>

typedef struct auto_model_info {
  const char *name;            /* the model's name: AUTO's NAME */
  int ndim;                    /* NDIM */
  size_t npar;                 /* PAR(1..npar) are whirl's parameters */
  const char *const *p_names;  /* npar names */
  const char *const *x_names;  /* ndim names */
  const char *file;            /* the plug-in's file stem (FILE.so) and its
                                  adapter's (FILE.c); NULL: NAME.so and
                                  auto_model.c.  c-files of one problem
                                  with another NDIM get a plug-in each */
} auto_model_info;

/* The equations file of demo NAME in DIR (NAME.f90, NAME.f, else NAME.c)
 * into path[len]: 0, or 2 with a message printed (none, or C). */
int auto_model_source(const char *dir, const char *name, char *path, size_t len);

/* Write STAGE/auto_model.c (the model's data and whirl_model_def) and
 * compile it with SOURCE and the adapter archive into STAGE/NAME.so
 * (m->file: STAGE/FILE.c into STAGE/FILE.so).  SOURCE is compiled once
 * into NAME.eq.o for all of them: STAGE's of this invocation, or OUT's of
 * an earlier one where newer than SOURCE.
 * 0, or 2 with a message and the compiler's own lines printed (the
 * equations do not compile, FUNC or STPNT missing), 1 for I/O errors or
 * no adapter archive. */
int auto_model_build(const char *out, const char *stage, const char *source,
                     const auto_model_info *m);

/* Is OUT/NAME.so, built by an earlier invocation, still the plug-in of
 * SOURCE and m: OUT/auto_model.c is the file m gives, and NAME.so is
 * newer than SOURCE, that file and the adapter archive?  1 or 0.  A script of runs
 * (whirl auto --script) calls whirl auto once a run: one compilation. */
int auto_model_current(const char *out, const char *source, const auto_model_info *m);

#endif

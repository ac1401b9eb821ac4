/* whirl/solution.h — labelled solutions, the counterpart of AUTO's s-files:
 * the file `solutions` of a run's output holds one block per label with
 * every digit (%.17g), enough to restart exactly (IRS):
 *
 *   # whirl solutions: model ab, npar 3
 *   LAB 3 TY HB BR 1 PT 27 KIND eq ICP 1 ICP2 0 NX 2 STAB 0
 *   PAR 0.165 14 3
 *   X 0.4059 1.4208
 *   TAN ...            (optional: the branch's unit tangent, NX + 1)
 *   MESH ...           (collocation: NTST + 1 mesh points; NTST, NCOL on LAB)
 *   END
 *
 * Reading checks every block up to the one asked for (counts against NX,
 * NPAR, NTST, NCOL, NHB; finite numbers; a known KIND; END), and the one
 * found against the model it is for, so no caller reads past a vector.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SOLUTION_H
#define WHIRL_SOLUTION_H

#include <stddef.h>
#include <stdio.h>

#include <whirl/status.h>

#ifdef __cplusplus
extern "C" {
#endif

#define WHIRL_SOL_MAXFREE 15 /* bvp: free parameters beside the continued one */

/* What the unknowns of a branch's system are (a solution's KIND). */
typedef enum whirl_solution_kind {
  WHIRL_SOL_EQ = 0,     /* equilibrium: x = state */
  WHIRL_SOL_COLLOC = 1, /* periodic orbit by collocation: x = node values, T */
  WHIRL_SOL_HBM = 2,    /* periodic orbit by harmonic balance */
  WHIRL_SOL_BVP = 3     /* boundary-value problem by collocation (IPS 4):
                           x = node values, then NFREE free parameters */
} whirl_solution_kind;

/* A labelled solution as stored in OUT/solutions (full precision). */
typedef struct whirl_solution {
  int label, br, pt;
  char ty[3];
  whirl_solution_kind kind;
  int icp;          /* the branch's continuation parameter (0-based) */
  int icp2;         /* loci: the second free parameter, else -1 */
  char locus[3];    /* loci: what the curve is made of (LP, PD, HB), else "" */
  size_t npar, nx;  /* model parameters; unknowns of the base system */
  double *par;      /* npar */
  double *x;        /* nx: base-system unknowns */
  double *tan;      /* nx + 1 or NULL: unit tangent (x, p_icp) */
  int ntst, ncol;   /* colloc, bvp */
  double *mesh;     /* colloc, bvp: ntst + 1 */
  int nfree;        /* bvp: free parameters after the node values (their
                       values also in par) */
  int free_par[WHIRL_SOL_MAXFREE]; /* bvp: their indices (0-based) */
  int nhb;          /* hbm: harmonics */
  int stable;
  size_t nstate;    /* state components: NX (eq), or NX = M nstate + aut
                       for orbits (M nodes or coefficients) */
  int aut;          /* orbits: 1 if the period is the last unknown */
  int iterate;      /* maps: the fixed point is of f^iterate (0 or 1: of f) */
  size_t nstate_stored; /* read with pad_state: the components the file had
                           (the others 0), else 0 */
  size_t npar_stored;   /* read for a model with more parameters: the ones
                           the file had (the others 0, for the reader to
                           take from its model: AUTO's NPAR = MAX(NPARR,
                           NPAR)), else 0 */
} whirl_solution;

/* The model a stored solution must fit (0 / NULL / -1: anything). */
typedef struct whirl_solution_shape {
  const char *model; /* name */
  size_t n, npar;    /* state components, parameters */
  int forced;        /* 1 forced (no period unknown), 0 autonomous */
  int pad_state;     /* 1: a collocation solution (orbit, boundary-value
                        problem) with fewer state components is read with
                        the others 0 at every node, as AUTO restarts with a
                        larger NDIM (demo pcl extends its system) */
} whirl_solution_shape;

/* Free the vectors of s and zero it (accepts an empty one). */
WHIRL_API void whirl_solution_free(whirl_solution *s);

/* Write s as one block; 0, or -1 when the stream reports an error. */
WHIRL_API int whirl_solution_write(FILE *f, const whirl_solution *s);

/* Read the solution of label (or the count-th of type ty if ty[0]) from a
 * solutions file f called path, checking every block read up to it (sizes,
 * numbers) and the one found against want; 0, or -1 with a message
 * ("PATH:LINE: ..." or "label 2 of PATH has ...") in msg. */
WHIRL_API int whirl_solution_read(FILE *f, const char *path,
                                  const whirl_solution_shape *want, int label,
                                  const char *ty, whirl_solution *out, char *msg,
                                  size_t len);

/* Every solution of the solutions file f called path, in the file's order,
 * each checked as whirl_solution_read checks it and passed to
 * fn(s, data) (s is freed after the call; fn's non-zero return stops the
 * reading and is returned); 0 at the end of the file, or -1 with the
 * message in msg.  One pass over the file, however many labels. */
WHIRL_API int whirl_solution_each(FILE *f, const char *path,
                                  int (*fn)(const whirl_solution *s, void *data),
                                  void *data, char *msg, size_t len);

/* The same from DIR/solutions. */
WHIRL_API int whirl_solution_find(const char *dir, const whirl_solution_shape *want,
                                  int label, const char *ty, whirl_solution *out,
                                  char *msg, size_t len);

#ifdef __cplusplus
}
#endif
#endif

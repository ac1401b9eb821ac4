/* whirl/auto_files.h — AUTO-07p's output files b.NAME (the branches),
 * s.NAME (the labelled solutions) and d.NAME (diagnostics) written from a
 * whirl run's output directory (branches.tsv, solutions), in the layout
 * AUTO-07p 0.9.2 writes them, so that AUTO's Python tools (parseB, parseS,
 * PyPLAUT) and users' own parsers read them:
 *
 *   b: header lines "   0 ..." (RL0 RL1 A0 A1; constants; the active
 *      parameters; the column names "PT TY LAB PAR(k) L2-NORM U(i)|MAX U(i)
 *      [more ICP, PERIOD]"), then one line a point, Fortran
 *      (I4,I6,I4,I5,nES19.10E3): BR (negative for periodic orbits), PT
 *      (negative where stable), AUTO's type code (0 none, 1 BP, 2 LP, 3 HB,
 *      4 labelled regular point, -4 UZ, 5 LP and 6 BP of orbits, 7 PD, 8 TR,
 *      9 EP, -9 MX, -1 BT, -2 CP, -3 ZH, -32 GH; on a locus 10 k + type,
 *      k the type of the point it started from: whirl_auto_output.itpst),
 *      LAB;
 *   s: per label a header of 16 integers (6I6,I8,I6,I8,7I5): IBR NTOT ITP
 *      LAB NFPR ISW NTPL NAR NROWPR NTST NCOL NPAR 0 NDIM IPS 0, then NTPL
 *      rows (t, u) — the collocation nodes of orbits, t in [0, 1] — the
 *      free parameters' indices (20I5), their tangent (4X,7ES19.10E3), the
 *      state's tangent (NTPL rows), and PAR(1..NPAR), NPAR >= 11 with
 *      PAR(11) the period of orbits;
 *   d: the labelled points as AUTO's terminal shows them (BR PT TY LAB,
 *      ES14.5), a block each; whirl's iteration details stay in run.log.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_AUTO_FILES_H
#define WHIRL_AUTO_FILES_H

#include <stdio.h>
#include <whirl/auto_constants.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_auto_output {
  const char *rundir;            /* the whirl run's output directory */
  const whirl_auto_constants *ac; /* its constants (IPS, ICP, ISW, header) */
  int ndim;
  size_t npar;                   /* the model's parameters PAR(1..npar) */
  const char *const *p_names;    /* column names, or NULL: PAR(k) */
  const char *const *x_names;    /* or NULL: U(i) */
  int label_offset;              /* added to every label written (0: as
                                    whirl numbered them; a merged file of
                                    several runs numbers on, as AUTO's rl) */
  int restarted;                 /* the run started from a label (IRS not
                                    0): its first point is not labelled,
                                    as in AUTO */
  int br;                        /* AUTO's number of the run's first branch
                                    (0: whirl's numbers); later branches
                                    number on */
  int itpst;                     /* AUTO's ITPST: for a run with |ISW| >= 2
                                    from a label, that label's type (its
                                    code, or the code / 10 when >= 10: 2 LP
                                    and 3 HB of equilibria, 5 LP, 6 BP, 7 PD
                                    and 8 TR of orbits), else 0.  A run's
                                    type codes are then 10 itpst + type
                                    (sign of the type), as AUTO writes the
                                    points of a locus: 54, 55, 59 on a fold
                                    locus of orbits; GH on a Hopf locus -32 */
} whirl_auto_output;
/* One label of a run as AUTO numbers it (whirl_auto_labels). */
typedef struct whirl_auto_label {
  int label;                     /* AUTO's: label_offset + its rank */
  int whirl;                     /* whirl's label in the run's solutions */
  int br;                        /* AUTO's branch number */
  int type;                      /* AUTO's type code (b-file column 3) */
  char ty[3];                    /* whirl's type: BP, HB, EP, RG, ... */
} whirl_auto_label;

/* Write b, s and d (any may be NULL), and the number of labels in
 * *nlabels (NULL: not wanted).  WHIRL_OK, WHIRL_EIO (a file that cannot be
 * read or written) or WHIRL_EINVAL (a table whirl did not write), with a
 * message in msg[len]. */
WHIRL_API int whirl_auto_write_files(const whirl_auto_output *o, FILE *b, FILE *s,
                                     FILE *d, int *nlabels, char *msg, size_t len);

/* The labels of the run o->rundir in AUTO's order and numbering (those
 * whirl_auto_write_files writes): the first max in lab[], their number in
 * *n.  WHIRL_OK, WHIRL_EIO or WHIRL_EINVAL with a message in msg[len]. */
WHIRL_API int whirl_auto_labels(const whirl_auto_output *o, whirl_auto_label *lab,
                                size_t max, size_t *n, char *msg, size_t len);
#ifdef __cplusplus
}
#endif
#endif

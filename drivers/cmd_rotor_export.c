/* drivers/cmd_rotor_export.c — `whirl rotor export FILE -o DIR`: the
 * rotor's assembled M, C, G, K as Matrix Market files (M.mtx, C.mtx,
 * G.mtx, K.mtx, whirl's DOF order) and dofs.tsv naming each DOF, as one
 * output transaction: for another code, or to come back through a rotor
 * file's `matrices` line with the nonlinear elements added.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <string.h>

#include "rotor_cli.h"

static const cli_doc export_doc = {
"usage: whirl rotor export FILE [-o DIR]\n"
"\n"
"The rotor's assembled matrices (the nonlinear elements left out) as\n"
"Matrix Market files, in whirl's DOF order: 4 a node (y, z, theta_y,\n"
"theta_z), node by node, then 2 a pedestal (y, z).\n"
"\n"
"options:\n",
"files in DIR: M.mtx C.mtx G.mtx K.mtx (G per unit speed: the equations\n"
"are M q'' + (C + Omega G) q' + K q = f), dofs.tsv 'dof node name'.\n"
"exit status: 0, 1 an output error, 2 bad options or rotor file.\n"};

static void write_dofs(FILE *f, const whirl_fe_rotor *r) {
  static const char *const nm[] = {"y", "z", "theta_y", "theta_z"};
  fprintf(f, "dof\tnode\tname\n");
  for (int d = 0; d < r->ndof; d++) {
    if (d < 4 * r->nnode) fprintf(f, "%d\t%d\t%s\n", d + 1, d / 4, nm[d % 4]);
    else fprintf(f, "%d\tpedestal %d\t%s\n", d + 1, (d - 4 * r->nnode) / 2, nm[(d - 4 * r->nnode) % 2]);
  }
}

int cmd_rotor_export(int argc, char **argv) {
  const char *CMD = "rotor export", *file, *dir = "rotor-matrices";
  int quiet = 0;
  const cli_opt opts[] = {{"-o", CLI_STRING, &dir, "DIR", "output directory (also --out)", NULL},
                          {"--out", CLI_STRING, &dir, "DIR", "output directory", NULL},
                          CLI_OPT_QUIET(quiet)};
  int rc = rotor_parse(CMD, argc, argv, opts, sizeof opts / sizeof opts[0], &export_doc, &file);
  if (rc) return rc == 1 ? 0 : 2;
  whirl_fe_rotor *r = rotor_load(file);
  if (!r) return 2;
  cli_outdir od;
  rc = cli_outdir_check(CMD, NULL, dir);
  if (!rc) rc = cli_outdir_begin(&od, CMD, NULL, dir);
  if (!rc) {
    int bad = 0;
    char name[8], msg[300];
    for (const char *w = "MCGK"; *w && !bad; w++) {
      out_file o;
      snprintf(name, sizeof name, "%c.mtx", *w);
      if ((bad = out_open(&o, &od, name))) break;
      if (whirl_fe_rotor_write_matrix(r, *w, o.fp, msg, sizeof msg)) {
        cli_error(CMD, "%s", msg);
        out_abort(&o);
        bad = 1;
      } else bad = out_commit(&o);
    }
    out_file t;
    if (!bad && !(bad = out_open(&t, &od, "dofs.tsv"))) write_dofs(t.fp, r), bad = out_commit(&t);
    rc = cli_outdir_finish(&od, bad, NULL);
  }
  if (!rc && !quiet)
    fprintf(stderr, "whirl rotor export: M, C, G, K (%d DOFs) in %s\n", r->ndof, dir);
  whirl_fe_rotor_free(r);
  return rc;
}

/* drivers/whirl.c — the whirl command: dispatches subcommands.  Drivers
 * parse options, build library objects, run them and write files; the
 * numerics live in libwhirl.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <string.h>

#include <whirl/whirl.h>

#include "cli.h"

static void usage(FILE *f) {
  fprintf(f,
          "usage: whirl <command> [options]\n"
          "\n"
          "Numerical continuation and bifurcation analysis, first for rigid\n"
          "rotors on squeeze-film dampers.\n"
          "\n"
          "commands:\n"
          "  run FILE       run an AUTO-style run file on any model (built-in or\n"
          "                 a plug-in .so): equilibria, periodic orbits, loci,\n"
          "                 branch switching, basins (doc/run-files.md)\n"
          "  sfd response   every branch of synchronous circular orbits of the\n"
          "                 SFD rotor against speed, with stability, Floquet\n"
          "                 multipliers, folds (LP) and pictures\n"
          "  sfd simulate   one response by time integration: orbit, Poincare\n"
          "                 section, spectrum, class\n"
          "  sfd sweep      up/down speed sweep by time integration (Figs. 3, 11)\n"
          "  sfd basins     basins of attraction at one speed (Figs. 12-17)\n"
          "  sfd onset      onset of the nonsynchronous response from rest\n"
          "  sfd merge      isola-peak merge point (two-parameter continuation)\n"
          "  sfd region     region of (lambda, delta) with an isola (Fig. 18)\n"
          "\n"
          "  whirl <command> --help   options of a command\n"
          "  whirl --version          library version\n");
}

static void sfd_usage(FILE *f) {
  fprintf(f,
          "usage: whirl sfd <command> [options]\n"
          "\n"
          "The rigid rotor on two short squeeze-film dampers (pi-film).\n"
          "commands:\n"
          "  response   all branches of circular orbits, stability, LP points\n"
          "  simulate   one response by time integration\n"
          "  sweep      speed sweep by time integration\n"
          "  basins     basins of attraction\n"
          "  onset      onset of the nonsynchronous response from rest\n"
          "  nonsync    the nonsynchronous response continued as a periodic orbit\n"
          "             of the rotating frame (birth, stability, second frequency)\n"
          "  merge      isola-peak merge point for one lambda\n"
          "  region     region of (lambda, delta) with an isolated branch (Fig. 18)\n");
}

int main(int argc, char **argv) {
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
    usage(stdout);
    return 0;
  }
  if (!strcmp(argv[1], "--version")) {
    printf("whirl %s\n", whirl_version());
    return 0;
  }
  if (!strcmp(argv[1], "run")) return cmd_run(argc - 1, argv + 1);
  if (!strcmp(argv[1], "sfd")) {
    if (argc < 3) {
      sfd_usage(stderr);
      return 2;
    }
    if (!strcmp(argv[2], "--help") || !strcmp(argv[2], "-h")) {
      sfd_usage(stdout);
      return 0;
    }
    if (!strcmp(argv[2], "response")) return cmd_sfd_response(argc - 2, argv + 2);
    if (!strcmp(argv[2], "simulate")) return cmd_sfd_simulate(argc - 2, argv + 2);
    if (!strcmp(argv[2], "sweep")) return cmd_sfd_sweep(argc - 2, argv + 2);
    if (!strcmp(argv[2], "basins")) return cmd_sfd_basins(argc - 2, argv + 2);
    if (!strcmp(argv[2], "onset")) return cmd_sfd_onset(argc - 2, argv + 2);
    if (!strcmp(argv[2], "nonsync")) return cmd_sfd_nonsync(argc - 2, argv + 2);
    if (!strcmp(argv[2], "merge")) return cmd_sfd_merge(argc - 2, argv + 2);
    if (!strcmp(argv[2], "region")) return cmd_sfd_region(argc - 2, argv + 2);
    fprintf(stderr, "whirl sfd: unknown command '%s' (see whirl sfd --help)\n", argv[2]);
    return 2;
  }
  fprintf(stderr, "whirl: unknown command '%s' (see whirl --help)\n", argv[1]);
  return 2;
}

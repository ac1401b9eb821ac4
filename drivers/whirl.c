/* drivers/whirl.c — the whirl command: dispatches subcommands.  Drivers
 * parse options, build library objects, run them and write files; the
 * numerics live in libwhirl.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <string.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <whirl/whirl.h>

#include "cli.h"

/* The sfd commands: the dispatch and both command lists of the help. */
typedef struct sfd_command {
  const char *name;
  int (*run)(int argc, char **argv);
  const char *what;
} sfd_command;
static const sfd_command sfd_commands[] = {
    {"response", cmd_sfd_response,
     "every branch of synchronous circular orbits of the SFD rotor against speed, with "
     "stability, Floquet multipliers, folds (LP) and pictures"},
    {"simulate", cmd_sfd_simulate,
     "one response by time integration: orbit, Poincare section, spectrum, class"},
    {"sweep", cmd_sfd_sweep, "up/down speed sweep by time integration (Figs. 3, 11)"},
    {"basins", cmd_sfd_basins, "basins of attraction at one speed (Figs. 12-17)"},
    {"onset", cmd_sfd_onset, "onset of the nonsynchronous response from rest"},
    {"nonsync", cmd_sfd_nonsync,
     "the nonsynchronous response continued as a periodic orbit of the rotating frame "
     "(birth, stability, second frequency)"},
    {"merge", cmd_sfd_merge, "isola-peak merge point (two-parameter continuation)"},
    {"region", cmd_sfd_region, "region of (lambda, delta) with an isola (Fig. 18)"}};
#define NSFD (sizeof sfd_commands / sizeof sfd_commands[0])

/* The sfd commands as help items, each named PREFIX NAME, text at COL. */
static void list_sfd(FILE *f, const char *prefix, size_t col) {
  char label[64];
  for (size_t k = 0; k < NSFD; ++k) {
    snprintf(label, sizeof label, "%s%s", prefix, sfd_commands[k].name);
    cli_help_item(f, label, sfd_commands[k].what, col);
  }
}

static void usage(FILE *f) {
  fprintf(f,
          "usage: whirl <command> [options]\n"
          "\n"
          "Numerical continuation and bifurcation analysis, first for rigid\n"
          "rotors on squeeze-film dampers.\n"
          "\n"
          "commands:\n");
  cli_help_item(f, "run FILE",
                "run an AUTO-style run file on any model (built-in or a plug-in .so): "
                "equilibria, periodic orbits, loci, branch switching, basins "
                "(doc/run-files.md)", 17);
  cli_help_item(f, "auto DIR [NAME]",
                "run an AUTO-07p problem from its own constants files and "
                "equations (doc/auto-files.md)", 17);
  list_sfd(f, "sfd ", 17);
  cli_rotor_help(f, "rotor ", 17);
  cli_plot_help(f, "plot ", 17);
  fprintf(f,
          "\n"
          "  whirl <command> --help   options of a command\n"
          "  whirl --version          library version\n");
}

static void sfd_usage(FILE *f) {
  fprintf(f,
          "usage: whirl sfd <command> [options]\n"
          "\n"
          "The rigid rotor on two short squeeze-film dampers (pi-film).\n"
          "commands:\n");
  list_sfd(f, "", 13);
  fprintf(f, "\n  whirl sfd <command> --help   options of a command\n");
}

/* Keep freed large blocks in the heap instead of returning each to the
 * kernel (glibc maps blocks over 128 KiB afresh and unmaps them on free):
 * a continuation factorises its Jacobian thousands of times, UMFPACK
 * allocating its work anew each time, and every fresh mapping is paid in
 * page faults (AUTO's demo man, 500 steps of a 1208-unknown BVP: 449 000
 * faults, 21 % of the run, 4.3 s; with the blocks kept 1 100 faults,
 * 3.4 s).  The process's own policy, set by the command, not the library. */
static void keep_freed_blocks(void) {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
#endif
}

int main(int argc, char **argv) {
  keep_freed_blocks();
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
  if (!strcmp(argv[1], "auto")) return cmd_auto(argc - 1, argv + 1);
  if (!strcmp(argv[1], "rotor")) return cmd_rotor(argc - 1, argv + 1);
  if (!strcmp(argv[1], "plot")) return cmd_plot(argc - 1, argv + 1);
  if (!strcmp(argv[1], "sfd")) {
    if (argc < 3) {
      sfd_usage(stderr);
      return 2;
    }
    if (!strcmp(argv[2], "--help") || !strcmp(argv[2], "-h")) {
      sfd_usage(stdout);
      return 0;
    }
    for (size_t k = 0; k < NSFD; ++k)
      if (!strcmp(argv[2], sfd_commands[k].name)) return sfd_commands[k].run(argc - 2, argv + 2);
    fprintf(stderr, "whirl sfd: unknown command '%s' (see whirl sfd --help)\n", argv[2]);
    return 2;
  }
  fprintf(stderr, "whirl: unknown command '%s' (see whirl --help)\n", argv[1]);
  return 2;
}

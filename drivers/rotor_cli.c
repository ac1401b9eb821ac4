/* drivers/rotor_cli.c — what the `whirl rotor` commands share
 * (rotor_cli.h).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <string.h>

#include "rotor_cli.h"

double rotor_unit_factor(const char *cmd, const char *u) {
  if (!strcmp(u, "rpm")) return ROTOR_RPM;
  if (!strcmp(u, "rad/s")) return 1;
  if (!strcmp(u, "hz")) return 2 * WHIRL_PI;
  cli_error(cmd, "--unit must be rpm, rad/s or hz (got '%s')", u);
  return -1;
}

int rotor_parse(const char *cmd, int argc, char **argv, const cli_opt *o,
                size_t no, const cli_doc *doc, const char **file) {
  *file = NULL;
  if (argc >= 2 && argv[1][0] != '-') {
    *file = argv[1];
    argv[1] = argv[0];
    const int r = cli_parse(cmd, argc - 1, argv + 1, o, no, doc);
    argv[1] = (char *)*file;
    return r;
  }
  const int r = cli_parse(cmd, argc, argv, o, no, doc);
  if (r == 0) {
    cli_error(cmd, "the rotor file is missing (see whirl %s --help)", cmd);
    return 2;
  }
  return r;
}

whirl_fe_rotor *rotor_load(const char *file) {
  char msg[600];
  int st = 0;
  whirl_fe_rotor *r = whirl_fe_rotor_read(file, msg, sizeof msg, &st);
  if (!r) cli_error("rotor", "%s", msg);
  return r;
}

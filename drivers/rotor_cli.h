/* drivers/rotor_cli.h — what the `whirl rotor` commands share: the rotor
 * file as the first argument, its loading with the file:line message, and
 * the speed units.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_CLI_H
#define WHIRL_ROTOR_CLI_H

#include <whirl/rotor.h>

#include "cli.h"

#define ROTOR_RPM (WHIRL_PI / 30) /* rad/s per rev/min */

/* The factor to rad/s of a speed unit (rpm, rad/s, hz), or −1 with a
 * message naming --unit. */
double rotor_unit_factor(const char *cmd, const char *unit);

/* cli_parse with the rotor file first: argv[1] is the file unless it is an
 * option (--help).  0 go on (*file set), 1 help shown, 2 bad (message
 * printed; the file missing included). */
int rotor_parse(const char *cmd, int argc, char **argv, const cli_opt *o,
                size_t no, const cli_doc *doc, const char **file);

/* The rotor file read and assembled, or NULL with "whirl rotor:
 * FILE:LINE: ..." printed. */
whirl_fe_rotor *rotor_load(const char *file);

#endif

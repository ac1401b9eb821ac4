/* drivers/run_cmd.h — `whirl run`: the command around the library's run
 * (whirl/run.h): cmd_run.c parses and prints, run_plot.c draws.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_DRIVER_RUN_CMD_H
#define WHIRL_DRIVER_RUN_CMD_H

#include <whirl/run.h>

#include "outdir.h"

/* The picture's script into od (diagram.gp or basins.gp); *name is the
 * picture to draw.  0, or -1 with the message printed. */
int run_write_plot(cli_outdir *od, const whirl_run *r, const char **name);

#endif

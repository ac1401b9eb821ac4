/* drivers/run_plot_impl.h — the parts of whirl run's picture (run_plot.c)
 * kept in their own files.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_RUN_PLOT_IMPL_H
#define WHIRL_RUN_PLOT_IMPL_H

#include <stdio.h>

#include <whirl/whirl.h>

#include "cli.h"

/* The axes' ranges and the names "TY LAB" of the labelled points (EP
 * aside) as 'set label' lines, placed apart from each other, the points
 * and the curves (label_place.c), the curves read back from the stage's
 * branches.tsv.  Without that table, nothing (the points stay marked). */
void run_plot_labels(FILE *f, const cli_outdir *od, const whirl_run *r,
                     const whirl_run_plot *pl);

#endif

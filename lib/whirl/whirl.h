/* whirl/whirl.h — umbrella header for libwhirl.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_WHIRL_H
#define WHIRL_WHIRL_H
#include <whirl/status.h>
#include <whirl/problem.h>
#include <whirl/system.h>
#include <whirl/linsol.h>
#include <whirl/cont.h>
#include <whirl/branch.h>
#include <whirl/equilibrium.h>
#include <whirl/ode.h>
#include <whirl/spectrum.h>
#include <whirl/section.h>
#include <whirl/basins.h>
#include <whirl/deflate.h>
#include <whirl/floquet.h>
#include <whirl/hbm.h>
#include <whirl/colloc.h>
#include <whirl/bvp.h>
#include <whirl/periodic.h>
#include <whirl/fold.h>
#include <whirl/hopf.h>
#include <whirl/bploc.h>
#include <whirl/trloc.h>
#include <whirl/model.h>
#include <whirl/runfile.h>
#include <whirl/solution.h>
#include <whirl/run.h>
#include <whirl/points.h>
#include <whirl/auto_constants.h>
#include <whirl/auto_files.h>
#endif

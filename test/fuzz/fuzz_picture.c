/* test/fuzz/fuzz_picture.c — libFuzzer target for the pictures whirl draws
 * itself: the reader of gnuplot scripts (drivers/gp_parse.c), the layout
 * and drawing (gp_draw.c, raster.c, raster_text.c with FreeType and the
 * configured font) and the PNG encoder (png_write.c).
 *
 * Each input is a script.  gp_parse reads it; when it is one drawn here,
 * the figure is drawn (its size cut to at most 200 x 200, so that an input
 * costs little) into a PNG written to /dev/null.  Besides what ASan/UBSan
 * catch, the target aborts (a finding) when a promise is broken:
 *   - gp_parse returns other than 0 or 1 (it has no memory to run out of
 *     here), or leaves its reason not NUL-terminated or with a line break;
 *   - a parsed figure with no series or an output name that is empty;
 *   - gp_draw_png returns other than 0 or 1.
 * No output, no allocation kept across inputs but the painter (its font
 * and canvas, as in a run of whirl).
 *
 * Build and run: test/fuzz/run.sh [RUNS] picture (doc/fuzzing.md).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gp_draw.h"

#define REQUIRE(cond)              \
  do {                             \
    if (!(cond)) __builtin_trap(); \
  } while (0)

static gp_painter *painter;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  char err[300];
  if (!painter) {
    painter = gp_painter_new(err, sizeof err);
    REQUIRE(painter != NULL); /* the font must be there: no test otherwise */
  }
  char *text = malloc(size + 1);
  if (!text) return 0;
  memcpy(text, data, size);
  text[size] = '\0';
  gp_figure fig;
  memset(err, 'x', sizeof err);
  const int rc = gp_parse(text, &fig, err, sizeof err);
  REQUIRE(rc == 0 || rc == 1);
  REQUIRE(memchr(err, '\0', sizeof err) != NULL && !strchr(err, '\n'));
  if (rc == 0) {
    REQUIRE(fig.nseries > 0 && fig.output[0]);
    if (fig.w > 200) fig.w = 200;
    if (fig.h > 200) fig.h = 200;
    /* data files are looked for where there are none: gnuplot's to draw */
    const int drawn = gp_draw_png(painter, &fig, "/nonexistent", "/dev/null", err, sizeof err);
    REQUIRE(drawn == 0 || drawn == 1);
  }
  gp_figure_free(&fig);
  free(text);
  return 0;
}

/* test/fuzz/fuzz_rotorfile.c — libFuzzer target for the reader of rotor
 * files (rotor/fe_file.c, doc/rotor-file.md): fe_parse on arbitrary bytes.
 *
 * Each input is written to a file fuzz.rotor in a directory of its own
 * (the reader takes a path; `matrices` lines name files relative to it)
 * and parsed.  Besides what ASan/UBSan catch, the target aborts (a
 * finding) when the reader breaks its promise: a failure without one
 * line of printable text "fuzz.rotor:LINE: ..." (LINE a line of the
 * input, or its last + 1), or a success whose description does not hold
 * (a node count below 1, an element, disk, bearing, nonlinear element,
 * unbalance or load off the nodes, a non-finite or negative dimension).
 *
 * Build and run: test/fuzz/run.sh [RUNS] rotorfile  (doc/fuzzing.md).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fe_impl.h"

static char path[4096];

static void setup(void) {
  if (path[0]) return;
  char dir[] = "/tmp/whirl-fuzz-rotor.XXXXXX";
  if (!mkdtemp(dir)) abort();
  snprintf(path, sizeof path, "%s/fuzz.rotor", dir);
}

static int lines_of(const uint8_t *data, size_t size) {
  int n = 1;
  for (size_t i = 0; i < size; i++) n += data[i] == '\n';
  return n;
}

static void check_message(const char *msg, int maxline) {
  const char *colon = strstr(msg, "fuzz.rotor:");
  if (!colon) abort();
  const int line = atoi(colon + strlen("fuzz.rotor:"));
  if (line < 1 || line > maxline + 1) abort();
  for (const char *c = msg; *c; c++)
    if (*c == '\n') abort();
}

static void check_desc(const fe_desc *d) {
  if (d->nnode < 1) abort();
  for (size_t k = 0; k < d->nel; k++)
    if (d->el[k].node < 0 || d->el[k].node + 1 >= d->nnode || !(d->el[k].length > 0) ||
        !(d->el[k].od > d->el[k].id) || !(d->el[k].id >= 0))
      abort();
  for (size_t k = 0; k < d->ndisk; k++)
    if (d->disk[k].node < 0 || d->disk[k].node >= d->nnode || !(d->disk[k].m >= 0)) abort();
  for (size_t k = 0; k < d->nbrg; k++)
    if (d->brg[k].node < 0 || d->brg[k].node >= d->nnode) abort();
  for (size_t k = 0; k < d->nnl; k++)
    if (d->nl[k].node < 0 || d->nl[k].node >= d->nnode) abort();
  for (size_t k = 0; k < d->nunb; k++)
    if (d->unb[k].node < 0 || d->unb[k].node >= d->nnode || !isfinite(d->unb[k].me)) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  setup();
  FILE *f = fopen(path, "wb");
  if (!f) abort();
  if (size && fwrite(data, 1, size, f) != size) abort();
  fclose(f);
  fe_desc d;
  char msg[1024] = "";
  const int rc = fe_parse(path, &d, msg, sizeof msg);
  if (rc == 0) {
    check_desc(&d);
    fe_desc_free(&d);
  } else if (rc == WHIRL_EINVAL) {
    check_message(msg, lines_of(data, size));
  } else if (rc != WHIRL_ENOMEM && rc != WHIRL_EIO) {
    abort();
  }
  return 0;
}

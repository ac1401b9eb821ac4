/* examples/run-api/run_api.c — run a run file through the library, as
 * `whirl run FILE` does, and print its labelled points (their rows of
 * branches.tsv).  Build: make (pkg-config whirl); run: ./run_api ab-1.whirl
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>

#include <whirl/whirl.h>

static void say(const char *line, void *ctx) {
  (void)ctx;
  fprintf(stderr, "run_api: %s\n", line);
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: run_api FILE.whirl\n");
    return 2;
  }
  const whirl_run_io io = {.message = say}; /* files go to the run's OUT */
  whirl_run *r = whirl_run_alloc(NULL, &io); /* plug-in models only */
  int rc = r ? whirl_run_load(r, argv[1], NULL, 0) : 1;
  if (rc == 0) rc = whirl_run_execute(r);
  for (size_t i = 0; rc == 0 && i < whirl_run_nspecial(r); i++)
    printf("%s\n", whirl_run_special_point(r, i)->row);
  whirl_run_free(r);
  return rc;
}

/* test/fuzz/fuzz_runfile.c — libFuzzer target for the run-file parser
 * (lib/run/runfile.c, whirl/runfile.h).
 *
 * Each input is a run file.  It is parsed with whirl_runfile_parse; when
 * that succeeds, up to three command-line overrides derived from the input
 * are applied (its first and last lines as "--LINE", and "--KEY=<second
 * line>" with KEY picked by the first byte), then whirl_runfile_check, and
 * every accessor is called for every key (whirl_runfile_where,
 * whirl_runfile_given, whirl_run_key_name), including out-of-range keys.
 *
 * Besides what ASan/UBSan catch, the target aborts (a finding) when the
 * parser breaks a documented promise:
 *   - an error message that is not one line of printable text, or is not
 *     NUL-terminated inside its buffer;
 *   - a parse error that does not start with "NAME:LINE: " with LINE a line
 *     of the input;
 *   - an override error that does not start with "command line (";
 *   - settings out of their bounds (counts above the array sizes,
 *     unterminated strings, NaN/inf in a real setting).
 * No output, no allocation kept across inputs.
 *
 * Build and run: test/fuzz/run.sh [RUNS]  (doc/fuzzing.md), or by hand
 *   clang -g -O1 -fsanitize=fuzzer,address,undefined -I lib \
 *     test/fuzz/fuzz_runfile.c lib/run/runfile.c -lm -o fuzz_runfile
 *   ./fuzz_runfile -runs=1000000 test/fuzz/corpus
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "runfile_impl.h"

#define NAME "fuzz.whirl"

/* A broken promise: crash loudly so libFuzzer records the input. */
#define REQUIRE(cond)          \
  do {                         \
    if (!(cond)) __builtin_trap(); \
  } while (0)

static int terminated(const char *s, size_t cap) {
  return memchr(s, '\0', cap) != NULL;
}

/* One line, printable ASCII (tabs allowed: an override may contain one),
 * NUL-terminated within the object's buffer (1536 bytes). */
static void check_message(const char *m) {
  REQUIRE(terminated(m, 1536));
  for (const unsigned char *p = (const unsigned char *)m; *p; p++)
    REQUIRE(*p == '\t' || (*p >= 32 && *p != 127));
}

/* "NAME:LINE: ..." with 1 <= LINE <= maxline. */
static void check_file_line(const char *m, long maxline) {
  size_t n = strlen(NAME);
  REQUIRE(!strncmp(m, NAME ":", n + 1));
  char *end;
  long line = strtol(m + n + 1, &end, 10);
  REQUIRE(end != m + n + 1 && end[0] == ':' && end[1] == ' ');
  REQUIRE(line >= 1 && line <= maxline);
}

static void check_settings(const whirl_run_settings *s) {
  REQUIRE(terminated(s->model, sizeof s->model));
  REQUIRE(terminated(s->out, sizeof s->out));
  REQUIRE(terminated(s->s, sizeof s->s));
  REQUIRE(terminated(s->plot, sizeof s->plot));
  REQUIRE(terminated(s->irs_type, sizeof s->irs_type));
  REQUIRE(s->nicp <= WHIRL_RUN_MAXICP && s->npar <= WHIRL_RUN_MAXITEMS &&
          s->nu <= WHIRL_RUN_MAXITEMS && s->nuzr <= WHIRL_RUN_MAXITEMS &&
          s->nuzstop <= WHIRL_RUN_MAXITEMS && s->naxes <= 2 &&
          s->nattractors <= WHIRL_RUN_MAXITEMS);
  for (size_t i = 0; i < s->nicp; i++)
    REQUIRE(terminated(s->icp[i].name, WHIRL_RUN_MAXNAME));
  const double r[] = {s->ds, s->dsmin, s->dsmax, s->rl0, s->rl1, s->a0,
                      s->a1, s->epsl, s->epsu, s->epss, s->basin_tol};
  for (size_t i = 0; i < sizeof r / sizeof r[0]; i++) REQUIRE(isfinite(r[i]));
  for (size_t i = 0; i < s->npar; i++) REQUIRE(isfinite(s->par[i].value));
  for (size_t i = 0; i < s->nu; i++) REQUIRE(isfinite(s->u[i].value));
}

/* A NUL-terminated copy of data[a, b) with "--" in front (unless the text
 * starts with "--" already), cut at 300 bytes; NULL if out of memory. */
static char *override_arg(const uint8_t *data, size_t a, size_t b,
                          const char *key) {
  if (b - a > 300) b = a + 300;
  size_t klen = key ? strlen(key) + 1 : 0;
  char *s = malloc(2 + klen + (b - a) + 1);
  if (!s) return NULL;
  size_t j = 0;
  if (key || b - a < 2 || data[a] != '-' || data[a + 1] != '-') {
    s[j++] = '-';
    s[j++] = '-';
  }
  if (key) {
    memcpy(s + j, key, klen - 1);
    j += klen - 1;
    s[j++] = '=';
  }
  memcpy(s + j, data + a, b - a);
  s[j + (b - a)] = '\0';
  return s;
}

static void apply_override(whirl_runfile *rf, char *arg) {
  if (!arg) return;
  int rc = whirl_runfile_override(rf, arg);
  if (rc != WHIRL_OK) {
    const char *m = whirl_runfile_errmsg(rf);
    check_message(m);
    REQUIRE(!strncmp(m, "command line (", 14));
  }
  free(arg);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  whirl_runfile *rf = whirl_runfile_alloc();
  if (!rf) return 0;
  long nlines = 1;
  for (size_t i = 0; i < size; i++) nlines += data[i] == '\n';

  int rc = whirl_runfile_parse(rf, NAME, (const char *)data, size);
  if (rc != WHIRL_OK) {
    REQUIRE(rc == WHIRL_EINVAL);
    const char *m = whirl_runfile_errmsg(rf);
    check_message(m);
    check_file_line(m, nlines);
    whirl_runfile_free(rf);
    return 0;
  }
  check_settings(whirl_runfile_settings(rf));

  /* overrides: the first line, the last line, and KEY=<second line> */
  size_t e1 = 0;
  while (e1 < size && data[e1] != '\n') e1++;
  size_t s2 = e1 < size ? e1 + 1 : size, e2 = s2;
  while (e2 < size && data[e2] != '\n') e2++;
  size_t last_end = size;
  if (last_end && data[last_end - 1] == '\n') last_end--;
  size_t last = last_end;
  while (last && data[last - 1] != '\n') last--;
  apply_override(rf, override_arg(data, 0, e1, NULL));
  if (last > 0) apply_override(rf, override_arg(data, last, last_end, NULL));
  if (size) {
    whirl_run_key k = (whirl_run_key)(data[0] % WHIRL_RK_COUNT);
    apply_override(rf, override_arg(data, s2, e2, whirl_run_key_name(k)));
  }
  check_settings(whirl_runfile_settings(rf));

  rc = whirl_runfile_check(rf);
  if (rc != WHIRL_OK) {
    const char *m = whirl_runfile_errmsg(rf);
    check_message(m);
    REQUIRE(!strncmp(m, NAME, strlen(NAME)) ||
            !strncmp(m, "command line (", 14));
  }

  char buf[2048];
  for (int k = -1; k <= WHIRL_RK_COUNT; k++) {
    const char *w = whirl_runfile_where(rf, (whirl_run_key)k, buf, sizeof buf);
    REQUIRE(w == buf && terminated(buf, sizeof buf));
    (void)whirl_runfile_given(rf, (whirl_run_key)k);
    REQUIRE(whirl_run_key_name((whirl_run_key)k) != NULL);
  }
  char small[8];
  (void)whirl_runfile_where(rf, WHIRL_RK_DS, small, sizeof small);
  REQUIRE(terminated(small, sizeof small));
  REQUIRE(terminated(whirl_runfile_ignored(rf), 256));
  REQUIRE(!strcmp(whirl_runfile_name(rf), NAME));
  whirl_runfile_free(rf);
  return 0;
}

/* test/fuzz/fuzz_auto_constants.c — libFuzzer target for the reader of
 * AUTO-07p constants files (lib/run/auto_constants.c) and their
 * translation into run files (lib/run/auto_runfile.c),
 * whirl/auto_constants.h.
 *
 * Each input is a constants file.  It is parsed; when that succeeds every
 * accessor is called for every key given (and some that are not), and the
 * file is translated into a run file.  Besides what ASan/UBSan catch, the
 * target aborts (a finding) when a promise breaks:
 *   - an error message that is not one line of printable text starting
 *     "NAME:LINE: " with LINE a line of the input;
 *   - a key given twice in the list of keys, a kind that disagrees with
 *     the accessors, an item with neither an index nor a name where one
 *     must be, NaN or Inf in a value;
 *   - a translation that succeeds without text, or fails without a message.
 * Seeds: test/fuzz/corpus-auto/ (hand-written), or the demos' c-files.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/auto_constants.h>

#define NAME "c.fuzz"
#define REQUIRE(cond)              \
  do {                             \
    if (!(cond)) __builtin_trap(); \
  } while (0)

static void check_message(const char *m, const uint8_t *data, size_t size) {
  size_t lines = 1;
  for (size_t i = 0; i < size; i++) lines += data[i] == '\n';
  REQUIRE(!strncmp(m, NAME ":", strlen(NAME) + 1));
  char *end;
  long line = strtol(m + strlen(NAME) + 1, &end, 10);
  REQUIRE(line >= 1 && (size_t)line <= lines && end[0] == ':' && end[1] == ' ');
  for (const char *p = m; *p; p++) REQUIRE((unsigned char)*p >= 0x20 && *p != 0x7f);
}

static void check_values(const whirl_auto_constants *ac) {
  const size_t n = whirl_auto_constants_nkeys(ac);
  for (size_t i = 0; i < n; i++) {
    const char *k = whirl_auto_constants_key(ac, i);
    REQUIRE(k && whirl_auto_key_kind(k) != WHIRL_AC_NONE);
    for (size_t j = 0; j < i; j++) REQUIRE(strcmp(k, whirl_auto_constants_key(ac, j)));
    const whirl_auto_kind kind = whirl_auto_constants_kind(ac, k);
    int v;
    double x;
    REQUIRE((whirl_auto_constants_int(ac, k, &v) == WHIRL_OK) == (kind == WHIRL_AC_INT));
    REQUIRE((whirl_auto_constants_real(ac, k, &x) == WHIRL_OK) == (kind == WHIRL_AC_REAL));
    if (kind == WHIRL_AC_REAL) REQUIRE(isfinite(x));
    REQUIRE((whirl_auto_constants_text(ac, k) != NULL) == (kind == WHIRL_AC_TEXT));
    REQUIRE(whirl_auto_constants_line(ac, k) >= 1);
    for (size_t j = 0; j < whirl_auto_constants_count(ac, k); j++) {
      whirl_auto_item it;
      REQUIRE(whirl_auto_constants_item(ac, k, j, &it) == WHIRL_OK);
      REQUIRE(!it.name || it.index == 0);
      if (kind == WHIRL_AC_NAMES) REQUIRE(it.text && !it.name);
      for (size_t m = 0; m < it.nvalues; m++) REQUIRE(isfinite(it.values[m]));
    }
    whirl_auto_item it;
    REQUIRE(whirl_auto_constants_item(ac, k, whirl_auto_constants_count(ac, k), &it) != WHIRL_OK);
  }
  REQUIRE(whirl_auto_constants_key(ac, n) == NULL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  whirl_auto_constants *ac = whirl_auto_constants_alloc();
  if (!ac) return 0;
  int rc = whirl_auto_constants_parse(ac, NAME, (const char *)data, size);
  if (rc == WHIRL_EINVAL) check_message(whirl_auto_constants_errmsg(ac), data, size);
  if (rc == WHIRL_OK) {
    check_values(ac);
    const whirl_auto_runfile_opts o = {"m.so", size % 2 ? "r.out" : NULL, NULL, "o.out", size % 40, NULL};
    char *t = NULL;
    rc = whirl_auto_constants_runfile(ac, &o, &t);
    REQUIRE(rc == WHIRL_OK ? t != NULL : t == NULL);
    if (rc == WHIRL_EINVAL) check_message(whirl_auto_constants_errmsg(ac), data, size);
    free(t);
  }
  whirl_auto_constants_free(ac);
  return 0;
}

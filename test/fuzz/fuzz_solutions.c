/* test/fuzz/fuzz_solutions.c — libFuzzer target for the reader of the
 * solutions files that `whirl run` restarts from (S, IRS, BASIN_ATTRACTORS):
 * whirl_solution_read in lib/run/solution.c.
 *
 * Each input is a solutions file called fuzz.sol, read through fmemopen
 * (the reader takes a stream).  It is asked for labels 1, 2 and 3 and for
 * the first HB with no model to fit, for label 2 as the model 'ab' (2
 * states, 3 parameters, autonomous) would ask, and for label 1 as 'ab' with
 * a third state and a forced 'ab' would.
 *
 * Besides what ASan/UBSan catch (a read past a vector, a leak, overflowing
 * arithmetic), the target aborts (a finding) when the reader breaks its
 * promise (whirl/solution.h):
 *   - a solution returned whose sizes do not hold: every vector is read to
 *     its stated end (par[npar], x[nx], tan[nx + 1], mesh[ntst + 1]), every
 *     value is finite, NX = nstate (eq) or (NTST x NCOL + 1 | 2 NHB + 1) x
 *     nstate + aut, the mesh increases from 0 to 1, TY is two printable
 *     characters, the label or type asked for, and the state count,
 *     parameter count and kind of model asked for;
 *   - a solution that does not survive whirl_solution_write and a second
 *     read bit for bit;
 *   - an error message that is empty, not one line of printable text, or
 *     that starts with neither "fuzz.sol:LINE: " (LINE a line of the
 *     input), "fuzz.sol: " and one of "there is no ", "the file is
 *     empty ", "cannot read: ", nor "label N of fuzz.sol ";
 *   - a failed read that leaves anything in the solution.
 *
 * Build and run: test/fuzz/run.sh [RUNS] solutions  (doc/fuzzing.md), or
 *   clang -std=c11 -D_POSIX_C_SOURCE=200809L -g -O1 \
 *     -fsanitize=fuzzer,address,undefined -I lib -I drivers \
 *     test/fuzz/fuzz_solutions.c lib/run/solution.c -lm -o fuzz_solutions
 *   ./fuzz_solutions -runs=100000 test/fuzz/corpus-solutions
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/solution.h>

#define NAME "fuzz.sol"

#define REQUIRE(cond)              \
  do {                             \
    if (!(cond)) __builtin_trap(); \
  } while (0)

static const whirl_solution_shape any = {NULL, 0, 0, -1};
static const whirl_solution_shape ab = {"ab", 2, 3, 0};
static const whirl_solution_shape ab3 = {"ab", 3, 3, 0}; /* a state more */
static const whirl_solution_shape abf = {"ab", 2, 3, 1}; /* forced */

/* Every value of v[n], finite (reading them all lets ASan see the end). */
static void check_vec(const double *v, size_t n) {
  REQUIRE(v != NULL);
  for (size_t i = 0; i < n; i++) REQUIRE(isfinite(v[i]));
}

static void check_solution(const whirl_solution *s, const whirl_solution_shape *want,
                           int label, const char *ty) {
  REQUIRE(s->label >= 1 && s->br >= 1 && s->pt >= 0);
  REQUIRE(strlen(s->ty) == 2 && s->ty[0] > ' ' && s->ty[0] < 127 &&
          s->ty[1] > ' ' && s->ty[1] < 127);
  REQUIRE(ty ? !strcmp(s->ty, ty) : s->label == label);
  REQUIRE(s->npar >= 1 && s->icp >= 0 && (size_t)s->icp < s->npar);
  REQUIRE(s->icp2 >= -1 && s->icp2 < (int)s->npar && s->icp2 != s->icp);
  REQUIRE(s->stable >= -1 && s->stable <= 1 && s->nx >= 1 && s->nstate >= 1);
  check_vec(s->par, s->npar);
  check_vec(s->x, s->nx);
  if (s->tan) check_vec(s->tan, s->nx + 1);
  switch (s->kind) {
    case WHIRL_SOL_EQ:
      REQUIRE(s->nstate == s->nx && !s->mesh);
      break;
    case WHIRL_SOL_COLLOC: {
      REQUIRE(s->ntst >= 2 && s->ncol >= 2 && s->ncol <= 7);
      REQUIRE(s->nx == ((size_t)s->ntst * (size_t)s->ncol + 1) * s->nstate +
                           (size_t)s->aut);
      check_vec(s->mesh, (size_t)s->ntst + 1);
      REQUIRE(s->mesh[0] == 0.0 && s->mesh[s->ntst] == 1.0);
      for (int i = 1; i <= s->ntst; i++) REQUIRE(s->mesh[i] > s->mesh[i - 1]);
      break;
    }
    case WHIRL_SOL_HBM:
      REQUIRE(s->nhb >= 1 && !s->mesh);
      REQUIRE(s->nx == (2 * (size_t)s->nhb + 1) * s->nstate + (size_t)s->aut);
      break;
    default:
      REQUIRE(0);
  }
  if (want->n) {
    REQUIRE(s->nstate == want->n && s->npar == want->npar);
    REQUIRE(s->kind == WHIRL_SOL_EQ || s->aut == !want->forced);
  }
}

static long count_lines(const uint8_t *d, size_t n) {
  long k = 1;
  for (size_t i = 0; i < n; i++) k += d[i] == '\n';
  return k;
}

static void check_message(const char *m, size_t cap, long nlines) {
  REQUIRE(memchr(m, '\0', cap) != NULL && m[0]);
  for (const unsigned char *p = (const unsigned char *)m; *p; p++)
    REQUIRE(*p >= 32 && *p < 127);
  const size_t nl = strlen(NAME);
  if (!strncmp(m, "label ", 6)) {
    char *end;
    REQUIRE(strtol(m + 6, &end, 10) >= 1 && !strncmp(end, " of " NAME " ", nl + 5));
    return;
  }
  REQUIRE(!strncmp(m, NAME ":", nl + 1));
  if (!strncmp(m + nl + 1, " there is no ", 13) ||
      !strncmp(m + nl + 1, " the file is empty ", 19) ||
      !strncmp(m + nl + 1, " cannot read: ", 14))
    return;
  char *end;
  long line = strtol(m + nl + 1, &end, 10);
  REQUIRE(end != m + nl + 1 && end[0] == ':' && end[1] == ' ');
  REQUIRE(line >= 1 && line <= nlines);
}

static int is_empty(const whirl_solution *s) {
  static const whirl_solution zero;
  return !memcmp(s, &zero, sizeof zero);
}

static int same_vec(const double *a, const double *b, size_t n) {
  if (!a || !b) return a == b;
  return !memcmp(a, b, n * sizeof *a);
}

/* Write s, read it back: the same solution, bit for bit. */
static void round_trip(const whirl_solution *s) {
  char *text = NULL;
  size_t len = 0;
  FILE *w = open_memstream(&text, &len);
  if (!w) return;
  fprintf(w, "# whirl solutions: model m, npar %zu\n", s->npar);
  REQUIRE(whirl_solution_write(w, s) == 0);
  if (fclose(w) != 0) {
    free(text);
    return;
  }
  FILE *f = fmemopen(text, len, "r");
  if (f) {
    whirl_solution t;
    char msg[1024];
    REQUIRE(whirl_solution_read(f, NAME, &any, s->label, "", &t, msg, sizeof msg) == 0);
    REQUIRE(t.label == s->label && !strcmp(t.ty, s->ty) && t.br == s->br &&
            t.pt == s->pt && t.kind == s->kind && t.icp == s->icp &&
            t.icp2 == s->icp2 && t.npar == s->npar && t.nx == s->nx &&
            t.ntst == s->ntst && t.ncol == s->ncol && t.nhb == s->nhb &&
            t.stable == s->stable && t.nstate == s->nstate && t.aut == s->aut);
    REQUIRE(same_vec(t.par, s->par, s->npar) && same_vec(t.x, s->x, s->nx) &&
            same_vec(t.tan, s->tan, s->nx + 1) &&
            same_vec(t.mesh, s->mesh, (size_t)s->ntst + 1));
    whirl_solution_free(&t);
    fclose(f);
  }
  free(text);
}

static void ask(const uint8_t *data, size_t size, long nlines,
                const whirl_solution_shape *want, int label, const char *ty) {
  /* fmemopen of 0 bytes fails on some libcs: give it a byte it won't read */
  FILE *f = fmemopen(size ? (void *)data : (void *)"", size ? size : 1, "r");
  if (!f) return;
  if (!size) (void)fgetc(f);
  whirl_solution s;
  char msg[1024];
  memset(msg, 'x', sizeof msg);
  int rc = whirl_solution_read(f, NAME, want, label, ty ? ty : "", &s, msg, sizeof msg);
  fclose(f);
  if (rc == 0) {
    check_solution(&s, want, label, ty);
    round_trip(&s);
    whirl_solution_free(&s);
  } else {
    REQUIRE(rc == -1 && is_empty(&s));
    check_message(msg, sizeof msg, nlines);
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const long nlines = count_lines(data, size);
  for (int label = 1; label <= 3; label++) ask(data, size, nlines, &any, label, NULL);
  ask(data, size, nlines, &any, 1, "HB");
  ask(data, size, nlines, &ab, 2, NULL);
  ask(data, size, nlines, &ab3, 1, NULL);
  ask(data, size, nlines, &abf, 1, NULL);
  return 0;
}

#!/bin/sh
# test/fuzz/run.sh — build the run-file parser's libFuzzer target and run it.
#
#   test/fuzz/run.sh [RUNS]        RUNS inputs (default 1000000)
#
# Environment: CLANG (default clang), FUZZ_JOBS (parallel workers, default 1),
# FUZZ_FLAGS (extra libFuzzer flags, e.g. -max_total_time=600),
# FUZZ_KEEP=1 (keep the work directory).  The checked-in seed corpus
# test/fuzz/corpus/ is copied, not modified; a crashing input is saved under
# test/fuzz/crashes/ (crash-<sha1>, leak-<sha1>, ...).
#
# Exit status: 0 no finding, 1 a finding (crash, leak, timeout, broken
# promise) or a build failure, 77 skipped (no clang with libFuzzer).
# Not part of `make check`: doc/fuzzing.md.
# SPDX-License-Identifier: BSD-3-Clause
set -u
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
runs=${1:-1000000}
CLANG=${CLANG:-clang}
case $runs in
  ''|*[!0-9]*) echo "usage: $0 [RUNS]" >&2; exit 2 ;;
esac

work=$(mktemp -d "${TMPDIR:-/tmp}/whirl-fuzz.XXXXXX") || exit 1
if [ "${FUZZ_KEEP:-0}" = 1 ]; then
  echo "work directory: $work"
else
  trap 'rm -rf "$work"' EXIT
fi

# does this clang have libFuzzer?
if ! command -v "$CLANG" > /dev/null 2>&1; then
  echo "SKIP: $CLANG not found (libFuzzer needs clang)"; exit 77
fi
printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n)\n{ (void)d; (void)n; return 0; }\n' > "$work/probe.c"
if ! "$CLANG" -fsanitize=fuzzer "$work/probe.c" -o "$work/probe" > /dev/null 2>&1; then
  echo "SKIP: $CLANG cannot link -fsanitize=fuzzer (libFuzzer runtime missing)"; exit 77
fi

# runfile.c is self-contained: it needs only the headers (whirl/status.h
# for the status codes), not lib/util/status.c (which needs the generated
# config.h and provides nothing the parser calls).
san=-fsanitize=fuzzer,address,undefined
"$CLANG" -std=c11 -g -O1 $san -fno-sanitize-recover=undefined \
  -I "$top/lib" "$here/fuzz_runfile.c" "$top/lib/run/runfile.c" -lm \
  -o "$work/fuzz_runfile" || { echo "build failed" >&2; exit 1; }

mkdir -p "$work/corpus" "$work/artifacts"
cp "$here"/corpus/* "$work/corpus/"
cd "$work" || exit 1   # with -jobs, libFuzzer writes fuzz-N.log here
start=$(date +%s)
# shellcheck disable=SC2086
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
"$work/fuzz_runfile" -runs="$runs" -dict="$here/runfile.dict" \
  -artifact_prefix="$work/artifacts/" -print_final_stats=1 \
  ${FUZZ_JOBS:+-jobs=$FUZZ_JOBS -workers=$FUZZ_JOBS} ${FUZZ_FLAGS:-} \
  "$work/corpus" > "$work/fuzz.log" 2>&1
rc=$?
end=$(date +%s)
grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)|^Done |^stat::' "$work/fuzz.log"
echo "fuzz_runfile: $runs runs requested, exit $rc, $((end - start)) s wall"
if [ $rc -ne 0 ]; then
  # the report: sanitizer stack, or libFuzzer's "deadly signal" / leak note
  awk '/==[0-9]+==ERROR|runtime error|deadly signal|ERROR: libFuzzer/ { on = 1 }
       /^Shadow bytes around/ { on = 0 }
       on || /^SUMMARY|Test unit written|^artifact_prefix/' "$work/fuzz.log"
  if [ -n "$(ls "$work/artifacts")" ]; then
    mkdir -p "$top/test/fuzz/crashes" && cp "$work/artifacts"/* "$top/test/fuzz/crashes/"
    ls "$top/test/fuzz/crashes"
  fi
  echo "FINDING: the input is saved in $top/test/fuzz/crashes/ (reproduce:" \
    "build as above and run ./fuzz_runfile test/fuzz/crashes/<file>)" >&2
  exit 1
fi
exit 0

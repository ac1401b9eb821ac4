#!/bin/sh
# test/fuzz/run.sh — build the libFuzzer targets and run them, one after
# the other.
#
#   test/fuzz/run.sh [RUNS] [TARGET ...]
#
# RUNS inputs per target (default 1000000); TARGET is one of
#   runfile     the run-file parser (fuzz_runfile.c, lib/run/runfile.c)
#   solutions   the reader of solutions files, what restarts read
#               (fuzz_solutions.c, lib/run/solution.c)
#   rotorfile   the reader of rotor files (fuzz_rotorfile.c, rotor/fe_file.c
#               with the Matrix Market reader, CHOLMOD)
#   auto        AUTO-07p constants files and their run files
#               (fuzz_auto_constants.c, lib/run/auto_constants.c, auto_runfile.c)
#   picture     the gnuplot scripts whirl draws itself, drawn (fuzz_picture.c,
#               drivers/gp_parse.c, gp_draw.c, raster*.c, png_write.c; needs
#               FreeType and DejaVu Sans)
# (default: all).  Each target prints one line
#   fuzz_NAME: RUNS runs requested, exit RC, N s wall
# Environment: CLANG (default clang), FUZZ_JOBS (parallel workers, default 1),
# FUZZ_FLAGS (extra libFuzzer flags, e.g. -max_total_time=600: each target
# stops at RUNS inputs or at that time, whichever comes first), FUZZ_KEEP=1
# (keep the work directory).  The checked-in seed corpora (test/fuzz/corpus/,
# test/fuzz/corpus-solutions/) are copied, not modified; a crashing input is
# saved under test/fuzz/crashes/ (crash-<sha1>, leak-<sha1>, ...).
#
# Exit status: 0 no finding, 1 a finding (crash, leak, timeout, broken
# promise) in any target or a build failure, 2 usage, 77 skipped (no clang
# with libFuzzer).  Not part of `make check`: doc/fuzzing.md.
# CI: FUZZ_FLAGS=-max_total_time=60 sh test/fuzz/run.sh 1000000000
# SPDX-License-Identifier: BSD-3-Clause
set -u
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
all="runfile solutions rotorfile auto picture"
usage() { echo "usage: $0 [RUNS] [TARGET ...]   (targets: $all)" >&2; exit 2; }
runs=1000000
case ${1:-} in
  '') ;;
  *[!0-9]*) ;;
  *) runs=$1; shift ;;
esac
targets=${*:-$all}
for t in $targets; do
  case " $all " in *" $t "*) ;; *) usage ;; esac
done
CLANG=${CLANG:-clang}

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

# Sources of each target: the reader and the message formatters it reports
# through (lib/util/errmsg.c), not lib/util/status.c (which needs the
# generated config.h and provides nothing they call).
sources() {
  case $1 in
    runfile) echo "$here/fuzz_runfile.c $top/lib/run/runfile.c $top/lib/util/errmsg.c" ;;
    solutions) echo "$here/fuzz_solutions.c $top/lib/run/solution.c $top/lib/util/errmsg.c $top/lib/util/fmt_num.c" ;;
    auto) echo "$here/fuzz_auto_constants.c $top/lib/run/auto_constants.c $top/lib/run/auto_runfile.c $top/lib/run/runfile.c $top/lib/util/errmsg.c" ;;
    rotorfile) echo "$here/fuzz_rotorfile.c $top/rotor/fe_file.c $top/rotor/fe_sparse.c $top/rotor/fe_matrix.c $top/lib/run/runfile.c $top/lib/util/errmsg.c -lcholmod" ;;
    picture) d=$top/drivers
      echo "$here/fuzz_picture.c $d/gp_parse.c $d/gp_expr.c $d/gp_data.c $d/gp_axis.c $d/gp_draw.c $d/raster.c $d/raster_draw.c $d/raster_text.c $d/png_write.c -I $d -I $work/picture-config $(pkg-config --cflags --libs freetype2)" ;;
  esac
}
corpus() {
  case $1 in
    runfile) echo "$here/corpus" ;;
    *) echo "$here/corpus-$1" ;;
  esac
}

# The pictures' target takes the font and FreeType as configure would: a
# config.h of its own.  Without them it is skipped (said, and counted as
# passed: there is nothing of it to test).
picture_config() {
  font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
  pkg-config --exists freetype2 2> /dev/null && [ -r "$font" ] || return 1
  mkdir -p "$work/picture-config"
  printf '#define WHIRL_HAVE_FREETYPE 1\n#define WHIRL_FONT "%s"\n' "$font" \
    > "$work/picture-config/config.h"
}

# fuzz NAME: build fuzz_NAME, run it on a copy of its corpus; its exit status
fuzz() {
  name=$1 dir="$work/$1"
  if [ "$name" = picture ] && ! picture_config; then
    echo "fuzz_picture: skipped (no FreeType or no DejaVuSans.ttf), exit 0"
    return 0
  fi
  mkdir -p "$dir/corpus" "$dir/artifacts"
  san=-fsanitize=fuzzer,address,undefined
  # shellcheck disable=SC2046 # the list of sources
  if ! "$CLANG" -std=c11 -D_POSIX_C_SOURCE=200809L -g -O1 $san \
      -fno-sanitize-recover=undefined -I "$top/lib" -I "$top/lib/run" -I "$top/rotor" -I /usr/include/suitesparse \
      $(sources "$name") -lm -o "$dir/fuzz_$name" > "$dir/build.log" 2>&1; then
    cat "$dir/build.log" >&2
    echo "fuzz_$name: build failed, exit 1"
    return 1
  fi
  cp "$(corpus "$name")"/* "$dir/corpus/"
  dict=
  [ -f "$here/$name.dict" ] && dict="-dict=$here/$name.dict"
  start=$(date +%s)
  # with -jobs, libFuzzer writes fuzz-N.log in the current directory
  # shellcheck disable=SC2086
  (cd "$dir" &&
    ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
    UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    "$dir/fuzz_$name" -runs="$runs" $dict -artifact_prefix="$dir/artifacts/" \
      -print_final_stats=1 ${FUZZ_JOBS:+-jobs=$FUZZ_JOBS -workers=$FUZZ_JOBS} \
      ${FUZZ_FLAGS:-} "$dir/corpus" > "$dir/fuzz.log" 2>&1)
  rc=$?
  end=$(date +%s)
  grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)|^Done |^stat::' "$dir/fuzz.log"
  echo "fuzz_$name: $runs runs requested, exit $rc, $((end - start)) s wall"
  [ $rc -eq 0 ] && return 0
  # the report: sanitizer stack, or libFuzzer's "deadly signal" / leak note
  awk '/==[0-9]+==ERROR|runtime error|deadly signal|ERROR: libFuzzer/ { on = 1 }
       /^Shadow bytes around/ { on = 0 }
       on || /^SUMMARY|Test unit written|^artifact_prefix/' "$dir/fuzz.log"
  if [ -n "$(ls "$dir/artifacts")" ]; then
    mkdir -p "$top/test/fuzz/crashes"
    for a in "$dir/artifacts"/*; do cp "$a" "$top/test/fuzz/crashes/$name-$(basename "$a")"; done
    ls "$top/test/fuzz/crashes"
  fi
  echo "FINDING in fuzz_$name: the input is saved in $top/test/fuzz/crashes/$name-* (reproduce:" \
    "build as above and run ./fuzz_$name test/fuzz/crashes/<file>)" >&2
  return 1
}

status=0
for t in $targets; do
  fuzz "$t" || status=1
done
exit $status

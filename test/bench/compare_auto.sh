#!/bin/sh
# test/bench/compare_auto.sh — whirl against AUTO-07p on the same job, both
# timed as whole processes on this machine: the complete Table 1 response
# of the SFD rotor (main branch and isola, LPs localised).
#   whirl:    whirl sfd response --no-plot --quiet, and with its two
#             pictures (response.png, multipliers.png)
#   AUTO-07p: test/bench/auto/sfd/run_auto.sh (cold: compile + 3 runs)
# The machine is shared and its speed drifts, so the three are timed in N
# rounds, one of each a round, and the ratio is taken within each round;
# the medians over the rounds are printed, then AUTO's warm and
# executable-only times and its accuracy (run_auto.sh -n 3).
# Processes are timed by test/bench/bench_wall when built (`make
# test/bench/bench_wall`; it does not start a `date` per measurement).
# usage: test/bench/compare_auto.sh [N]   (from the build directory; needs
# drivers/whirl built and the auto-07p Debian package)
# SPDX-License-Identifier: BSD-3-Clause
set -eu
N=${1:-11}
here=$(cd "$(dirname "$0")" && pwd)
# The binary itself, not libtool's wrapper script drivers/whirl (a shell
# that costs ~15 ms a start): drivers/.libs/whirl with the build's
# libraries, as an installed whirl runs.  WHIRL=/usr/local/bin/whirl times
# an installed one.
if [ -z "${WHIRL:-}" ] && [ -x drivers/.libs/whirl ]; then
  WHIRL=drivers/.libs/whirl
  LD_LIBRARY_PATH=$(pwd)/lib/.libs:$(pwd)/rotor/.libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  export LD_LIBRARY_PATH
fi
WHIRL=${WHIRL:-./drivers/whirl}
[ -x "$WHIRL" ] || { echo "compare_auto.sh: $WHIRL not found (run from the build directory)" >&2; exit 1; }
if [ -z "${BENCH_WALL:-}" ] && [ -x test/bench/bench_wall ]; then BENCH_WALL=$(pwd)/test/bench/bench_wall; fi
export BENCH_WALL=${BENCH_WALL:-}
echo "whirl: $WHIRL; timer: ${BENCH_WALL:-date +%s%N}"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-cmp.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# time_whirl FILE ARGS: one whole run of whirl sfd response, seconds to FILE
time_whirl() {
  f=$1
  shift
  rm -rf "$tmp/out"
  if [ -n "$BENCH_WALL" ]; then
    "$BENCH_WALL" "$f" "$WHIRL" sfd response "$@" --quiet --out "$tmp/out" > /dev/null
  else
    s=$(date +%s%N)
    "$WHIRL" sfd response "$@" --quiet --out "$tmp/out" > /dev/null
    e=$(date +%s%N)
    echo "$s $e" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }' >> "$f"
  fi
}
median() { sort -g | awk '{ a[NR] = $1 } END { printf "%.4g", (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

: > "$tmp/plain"; : > "$tmp/pics"; : > "$tmp/auto"
i=0
while [ $i -lt "$N" ]; do
  time_whirl "$tmp/plain" --no-plot
  time_whirl "$tmp/pics"
  "$here/auto/sfd/run_auto.sh" -n 1 --cold-only | sed -n 's/^cold //p' | tr -d ' ' >> "$tmp/auto"
  i=$((i + 1))
done
# the ratios of each round
paste "$tmp/plain" "$tmp/pics" "$tmp/auto" > "$tmp/rounds"
awk '{ print $3 / $1 }' "$tmp/rounds" > "$tmp/r_plain"
awk '{ print $3 / $2 }' "$tmp/rounds" > "$tmp/r_pics"
echo "$N rounds (whirl without pictures, whirl with them, AUTO-07p cold), medians:"
echo "  whirl sfd response --no-plot:           $(awk '{ print $1 * 1000 }' "$tmp/plain" | median) ms; AUTO cold / it $(median < "$tmp/r_plain")"
echo "  whirl sfd response with its 2 pictures: $(awk '{ print $1 * 1000 }' "$tmp/pics" | median) ms; AUTO cold / it $(median < "$tmp/r_pics")"
echo "  AUTO-07p cold (compile + 3 runs):       $(awk '{ print $1 * 1000 }' "$tmp/auto" | median) ms"
echo "  rounds [ms]: $(awk '{ printf "%.1f/%.1f/%.0f ", $1 * 1000, $2 * 1000, $3 * 1000 }' "$tmp/rounds")"
"$here/auto/sfd/run_auto.sh" -n 3

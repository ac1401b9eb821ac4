#!/bin/sh
# test/bench/compare_auto.sh — whirl against AUTO-07p on the same job, both
# timed as whole processes in one run on this machine: the complete Table 1
# response of the SFD rotor (main branch and isola, LPs localised).
#   whirl:    whirl sfd response --no-plot --quiet   (N runs, median),
#             and with its two pictures (gnuplot)
#   AUTO-07p: test/bench/auto/sfd/run_auto.sh -n N   (cold, warm, exe only)
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
echo "whirl: $WHIRL"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-cmp.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# median wall time in ms of N whole runs of whirl sfd response with ARGS
whirl_median() {
  : > "$tmp/t"
  i=0
  while [ $i -lt "$N" ]; do
    s=$(date +%s%N)
    "$WHIRL" sfd response "$@" --quiet --out "$tmp/out" > /dev/null
    e=$(date +%s%N)
    echo $(( (e - s) / 1000 )) >> "$tmp/t"
    rm -rf "$tmp/out"
    i=$((i + 1))
  done
  sort -n "$tmp/t" | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)] / 1000}'
}
echo "whirl whole process, median of $N: $(whirl_median --no-plot) ms"
echo "whirl whole process with its pictures (response.png, multipliers.png), median of $N: $(whirl_median) ms"
"$here/auto/sfd/run_auto.sh" -n "$N" | tee "$tmp/auto.txt"

#!/bin/sh
# test/bench/busy_core.sh [DEMO [REPEAT]] — whirl's threads beside a core
# that another process keeps busy (a second job, a build): whole-process
# time of `whirl auto` on an AUTO-07p demo (default man: boundary-value
# problems of NTST 100-200, the loops the governor of lib/util/threads.c
# threads) on this build, on BASE's build when given (BASE=/path/to/
# drivers/whirl), and on this build with one thread (OMP_NUM_THREADS=1),
# each REPEAT times (default 3) in turn, first with the machine as it is,
# then beside a busy loop (a shell's `while :`, one core); medians, and
# the user (CPU) seconds, which the threads' spinning shows in.
# SCRIPT=1 runs the demo's own script (`whirl auto DEMO --script`, which
# needs WHIRL_PYTHON: fnc runs only so).
# Each run on a fresh output directory; the demo from
# ../shared/auto-07p/demos unless AUTO_DEMOS is set.  Not a test.
# SPDX-License-Identifier: BSD-3-Clause
set -u
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "${top_srcdir:-$here/../..}" && pwd)
demos=${AUTO_DEMOS:-$top/../shared/auto-07p/demos}
[ -d "$demos" ] && demos=$(cd "$demos" && pwd)
demo=${1:-man}
repeat=${2:-3}
WHIRL=${WHIRL:-${top_builddir:-$top}/drivers/whirl}
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
BASE=${BASE:-}
wargs=; [ -n "${SCRIPT:-}" ] && wargs=--script
case $BASE in /* | "") ;; *) BASE="$(pwd)/$BASE" ;; esac
[ -d "$demos/$demo" ] || { echo "# no AUTO-07p demo $demo in $demos"; exit 0; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-busy.XXXXXX") || exit 1
busy=
stop_busy() { [ -n "$busy" ] && kill "$busy" 2> /dev/null && wait "$busy" 2> /dev/null; busy=; }
trap 'stop_busy; rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
median() { sort -g | awk '{ v[NR] = $1 } END { printf "%.2f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# one run: its wall and user seconds appended to $tmp/NAME.wall, .user
one() {
  name=$1; shift
  rm -rf "$tmp/o"
  # in the scratch directory: an equations file may write there (man's
  # FUNC writes fort.10)
  (cd "$tmp" && /usr/bin/time -f '%e %U' -o "$tmp/t" "$@" auto "$demos/$demo" $wargs --quiet \
    --out="$tmp/o" > /dev/null 2>&1)
  cut -d' ' -f1 "$tmp/t" >> "$tmp/$name.wall"
  cut -d' ' -f2 "$tmp/t" >> "$tmp/$name.user"
}

measure() {
  label=$1
  rm -f "$tmp"/*.wall "$tmp"/*.user
  for r in $(seq 1 "$repeat"); do
    one this "$WHIRL"
    [ -n "$BASE" ] && one base "$BASE"
    one one_thread env OMP_NUM_THREADS=1 "$WHIRL"
  done
  for name in this base one_thread; do
    [ -f "$tmp/$name.wall" ] || continue
    printf '%s\t%s\t%s\t%s\n' "$label" "$name" "$(median < "$tmp/$name.wall")" \
      "$(median < "$tmp/$name.user")"
  done
}

echo "# $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load $(cut -d' ' -f1-3 /proc/loadavg); demo $demo${wargs:+ $wargs}, medians of $repeat"
printf 'machine\tbuild\twall_s\tuser_s\n'
measure idle
# the busy core: an hour at most, should this script be killed unawares
timeout 3600 sh -c 'while :; do :; done' < /dev/null > /dev/null 2>&1 &
busy=$!
measure busy_core
stop_busy

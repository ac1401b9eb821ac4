#!/bin/sh
# test/bench/auto_demos_speed.sh [AUTO_DEMOS_DIR [REPEAT]] — whole-process
# time of each AUTO-07p demo that test/auto-demos/run.sh runs (constants
# files of IPS 1, 2 or 4, or all -1, equations in Fortran): `whirl auto DEMO` (its
# default order of the c-files, no pictures, as AUTO) against AUTO-07p
# itself running the demo's own script NAME.auto (Debian's auto-07p, by
# /usr/bin/python3: its Python, gfortran compiling the demo, then the runs),
# each on a fresh scratch copy, paired back to back, REPEAT times (default
# 3), medians.  Both compile the equations each time (whirl: gfortran into
# a plug-in).  AUTO's script may run more or fewer constants files than
# whirl's default order (test/auto-demos/known-gaps says where): the
# column `runs` gives both.  Prints a table and the totals.  Not a test.
# With BASE=/path/to/another/drivers/whirl the second column is that
# build's `whirl auto` instead of AUTO: two builds paired demo by demo.
# With SCRIPT=1 whirl runs the demo's script as AUTO does (`whirl auto
# DEMO --script`): the same runs on both sides.  With DEFAULT=1 AUTO runs
# whirl's default order of the constants files instead of its script
# (c.NAME.1, c.NAME.2, ... each given the runs before it, as
# test/auto-demos/run.sh's third reference): the same runs on both sides
# again; AUTO gets 60 s a demo there (its default order of pcl runs on for
# minutes), and a demo where AUTO timed out or either side computed no
# point is left out of the totals and listed.
# SPDX-License-Identifier: BSD-3-Clause
set -u
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "${top_srcdir:-$here/../..}" && pwd)
demos=${1:-$top/../shared/auto-07p/demos}
repeat=${2:-3}
WHIRL=${WHIRL:-${top_builddir:-$top}/drivers/whirl}
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
py=${AUTO_07P_PYTHON:-/usr/lib/auto-07p/python}
[ -d "$demos" ] || { echo "# no AUTO-07p demos at $demos"; exit 0; }
BASE=${BASE:-}
SCRIPT=${SCRIPT:-}
DEFAULT=${DEFAULT:-}
wargs=; [ -n "$SCRIPT" ] && wargs=--script
[ -n "$BASE" ] || [ -f "$py/auto/__main__.py" ] || { echo "# no AUTO-07p at $py (Debian package auto-07p)"; exit 0; }
demos=$(cd "$demos" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-autospeed.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }
. "$top/test/auto-demos/default_order.sh" # default_order_script NAME DIR
median() { sort -g | awk '{ v[NR] = $1 } END { printf "%.3f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "# $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load $(cut -d' ' -f1-3 /proc/loadavg)"
if [ -n "$BASE" ]; then printf 'demo\truns_whirl\truns_base\twhirl_s\tbase_s\tratio\n'
else printf 'demo\truns_whirl\truns_auto\twhirl_s\tauto_s\tratio\n'; fi
tw=0 ta=0 faster=0 total=0 left=""
for dir in "$demos"/*/; do
  d=$(basename "$dir")
  [ -f "$dir/$d.f90" ] && [ -f "$dir/$d.auto" ] || continue
  ls "$dir"/c.* > /dev/null 2>&1 || continue
  cls=$(cat "$dir"/c.* | grep -o 'IPS *= *-\{0,1\}[0-9]*' | grep -o -- '-\{0,1\}[0-9]*$' | sort -u | tr '\n' ' ')
  case "$cls" in "1 " | "2 " | "4 " | "1 2 " | "1 4 " | "2 4 " | "1 2 4 " | "-1 ") ;; *) continue ;; esac
  : > "$tmp/w" ; : > "$tmp/a"
  for r in $(seq 1 "$repeat"); do
    rm -rf "$tmp/wd" "$tmp/ad"; mkdir "$tmp/wd" "$tmp/ad"
    # the demo with its sub-directories (fnc's attr and rep), writable
    cp -R "$dir"/. "$tmp/ad"/ 2> /dev/null; chmod -R u+w "$tmp/ad"
    t0=$(now); (cd "$tmp/wd" && timeout 300 "$WHIRL" auto "$dir" $wargs --quiet --out=o > /dev/null 2>&1)
    if [ -n "$BASE" ]; then
      t1=$(now); (cd "$tmp/ad" && timeout 300 "$BASE" auto "$dir" $wargs --quiet --out=o > /dev/null 2>&1)
    elif [ -n "$DEFAULT" ]; then
      default_order_script "$d" "$tmp/ad"
      t1=$(now); (cd "$tmp/ad" && timeout 60 /usr/bin/python3 "$top/test/auto-demos/auto07p.py" "$py/auto/__main__.py" whirl-default.auto > log 2>&1)
      [ $? = 124 ] && echo "$d" > "$tmp/timeout"
    else
      t1=$(now); (cd "$tmp/ad" && timeout 300 /usr/bin/python3 "$top/test/auto-demos/auto07p.py" "$py/auto/__main__.py" "$d.auto" > log 2>&1)
    fi
    t2=$(now)
    echo "$t1 - $t0" | bc -l >> "$tmp/w"; echo "$t2 - $t1" | bc -l >> "$tmp/a"
  done
  nw=$(ls "$tmp/wd/o"/*.whirl "$tmp/wd/o"/runs/*.whirl 2> /dev/null | wc -l)
  # grep -c prints 0 itself when nothing matches (and exits 1): no "|| echo 0"
  if [ -n "$BASE" ]; then na=$(ls "$tmp/ad/o"/*.whirl "$tmp/ad/o"/runs/*.whirl 2> /dev/null | wc -l)
  else na=$(grep -c "^ *BR *PT *TY" "$tmp/ad/log" 2> /dev/null); fi
  [ -n "$na" ] || na=0
  w=$(median < "$tmp/w"); a=$(median < "$tmp/a")
  printf '%s\t%s\t%s\t%s\t%s\t%.1f\n' "$d" "$nw" "$na" "$w" "$a" "$(echo "$a / $w" | bc -l)"
  # whirl's points: none when its first run could not start (fnc: no STPNT)
  pw=$(awk 'substr($0, 1, 4) + 0 != 0' "$tmp/wd/o/b.$d" 2> /dev/null | wc -l)
  if [ -n "$DEFAULT" ] && { [ -f "$tmp/timeout" ] || [ "$pw" = 0 ] || [ "$na" = 0 ]; }; then
    left="$left $d"; rm -f "$tmp/timeout"; continue
  fi
  tw=$(echo "$tw + $w" | bc -l); ta=$(echo "$ta + $a" | bc -l)
  total=$((total + 1))
  [ "$(echo "$w < $a" | bc -l)" = 1 ] && faster=$((faster + 1))
done
other=AUTO; [ -n "$BASE" ] && other=base
[ -n "$left" ] && echo "# left out of the totals (AUTO timed out at 60 s, or a side computed no point):$left"
printf '# total: whirl %.2f s, %s %.2f s, %s / whirl = %.2f; whirl faster on %d of %d demos\n' \
  "$tw" "$other" "$ta" "$other" "$(echo "$ta / $tw" | bc -l)" "$faster" "$total"

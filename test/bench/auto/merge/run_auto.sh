#!/bin/sh
# run_auto.sh — AUTO-07p side of whirl's merge-point comparison
# (doc/auto-merge-benchmark.md): the isola-peak merge point δ* of the SFD
# rotor's circular orbits for λ = 0.05, 0.25, 1 (ζ = 0) and λ = 0.25,
# ζ = 0.05, by an isola run + a fold-curve run per case (run_merge.py).
#
# usage: test/bench/auto/merge/run_auto.sh [-n N] [--keep] [run_merge.py options]
#   -n N     repetitions per timing (default 3; the median is reported)
#   --keep   keep the work directory and print its path
#   other options go to run_merge.py: --method lp|max, --epss X, --dsmax X,
#            --iid0, --tight (see run_merge.py; default: --method lp, AUTO's
#            default tolerances)
# Needs /usr/bin/python3 (not a pyenv python), AUTO-07p (AUTO_DIR, default
# /usr/lib/auto-07p) with gcc and gfortran.  Runs in a fresh temporary
# directory; exits non-zero with a message on any failure.
#
# Timings (wall clock, median of N), for all four cases together and for
# each case alone:
#   cold  run_merge.py run with no sfd.o/sfd.exe: Python + AUTO's Python
#         interface + compile (gcc) and link (gfortran) + the AUTO runs
#   warm  the same with sfd.exe present (AUTO reuses the executable)
#   exe   the same AUTO runs (runs.txt) replayed with ./sfd.exe, constants on
#         stdin and the restart s-file as fort.3, no Python at all
# SPDX-License-Identifier: BSD-3-Clause
set -eu

PY=/usr/bin/python3
N=3
KEEP=
OPTS=
while [ $# -gt 0 ]; do
  case "$1" in
    -n) [ $# -ge 2 ] || { echo "run_auto.sh: -n needs a value" >&2; exit 2; }
        N=$2; shift 2 ;;
    --keep) KEEP=1; shift ;;
    --method|--epss|--dsmax)
        [ $# -ge 2 ] || { echo "run_auto.sh: $1 needs a value" >&2; exit 2; }
        OPTS="$OPTS $1 $2"; shift 2 ;;
    --iid0|--tight) OPTS="$OPTS $1"; shift ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) echo "run_auto.sh: unknown argument: $1" >&2; exit 2 ;;
  esac
done
case "$N" in ''|*[!0-9]*|0) echo "run_auto.sh: -n must be a positive integer" >&2; exit 2 ;; esac

die() { echo "run_auto.sh: error: $*" >&2; exit 1; }

AUTO_DIR=${AUTO_DIR:-/usr/lib/auto-07p}
export AUTO_DIR
[ -x "$PY" ] || die "$PY not found"
[ -d "$AUTO_DIR/python/auto" ] || die "AUTO-07p Python modules not found in $AUTO_DIR/python"
command -v gcc >/dev/null 2>&1 || die "gcc not found (AUTO compiles sfd.c with it)"
command -v gfortran >/dev/null 2>&1 || die "gfortran not found (AUTO links with it)"

SRC=$(cd "$(dirname "$0")" && pwd)
for f in "$SRC/../sfd/sfd.c" "$SRC/../sfd/circ.py" "$SRC/c.merge" "$SRC/run_merge.py"; do
  [ -f "$f" ] || die "missing $f"
done

WORK=$(mktemp -d "${TMPDIR:-/tmp}/whirl-auto-merge.XXXXXX") || die "mktemp failed"
if [ -z "$KEEP" ]; then trap 'rm -rf "$WORK"' EXIT; fi
trap 'exit 1' HUP INT PIPE TERM
cp "$SRC/../sfd/sfd.c" "$SRC/../sfd/circ.py" "$SRC/c.merge" "$SRC/run_merge.py" "$WORK/"
cd "$WORK"

now() { date +%s%N; }
median() { sort -g | awk '{ a[NR] = $1 } END {
  if (NR == 0) exit 1
  if (NR % 2) m = a[(NR + 1) / 2]; else m = (a[NR / 2] + a[NR / 2 + 1]) / 2
  printf "%.4f", m }'; }
elapsed() { echo "$1 $2" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }'; }
clean() { rm -f fort.* b.* s.* d.* c.l* runs.txt auto.log; }

# replay runs.txt with the bare executable (b./s. files of the replay)
replay() {
  while read -r tag rs; do
    rm -f fort.3 fort.7 fort.8 fort.9
    if [ "$rs" != "-" ]; then cp "s.$rs" fort.3; fi
    ./sfd.exe < "c.$tag" > "exe_$tag.out" 2>&1 || die "./sfd.exe < c.$tag failed"
    cp fort.7 "b.$tag"
    cp fort.8 "s.$tag"
  done < runs.txt
}

echo "AUTO-07p $(dpkg-query -W -f='${Version}' auto-07p 2>/dev/null || echo '?') ($AUTO_DIR)," \
     "$(nproc) CPU(s): $(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)"
echo "run_merge.py options:${OPTS:- (none: --method lp, AUTO default tolerances)}; N = $N"
printf '%-7s %4s %5s  %-15s %-10s %8s %8s %8s   %s\n' case runs steps 'delta*' d-whirl cold warm exe \
  'all times [s]: cold | warm | exe'
for CASE in all l0.05 l0.25 l1 l0.25z; do
  if [ "$CASE" = all ]; then SEL=; else SEL="--case $CASE"; fi
  : > t_cold; : > t_warm; : > t_exe
  i=0
  while [ $i -lt "$N" ]; do
    clean; rm -f sfd.o sfd.exe
    t0=$(now)
    # shellcheck disable=SC2086
    "$PY" run_merge.py run $SEL $OPTS > summary.txt 2> err.txt \
      || die "AUTO chain failed ($CASE): $(cat err.txt) (use --keep, see auto.log)"
    t1=$(now); elapsed "$t0" "$t1" >> t_cold
    i=$((i + 1))
  done
  grep -q "^gcc" auto.log || die "cold run did not compile sfd.c (see auto.log)"
  i=0
  while [ $i -lt "$N" ]; do
    clean
    t0=$(now)
    # shellcheck disable=SC2086
    "$PY" run_merge.py run $SEL $OPTS > summary.txt 2> err.txt \
      || die "AUTO chain failed ($CASE): $(cat err.txt)"
    t1=$(now); elapsed "$t0" "$t1" >> t_warm
    i=$((i + 1))
  done
  if grep -q "^gcc" auto.log; then die "warm run recompiled sfd.c"; fi
  [ -x sfd.exe ] || die "sfd.exe missing after the AUTO runs"
  cp summary.txt "summary_$CASE.txt"
  i=0
  while [ $i -lt "$N" ]; do
    t0=$(now)
    replay
    t1=$(now); elapsed "$t0" "$t1" >> t_exe
    i=$((i + 1))
  done
  # shellcheck disable=SC2086
  "$PY" run_merge.py summary $SEL $OPTS > summary_exe.txt 2> err.txt || die "$(cat err.txt)"
  cmp -s summary.txt summary_exe.txt || die "bare sfd.exe replay differs from the AUTO Python runs ($CASE)"
  if [ "$CASE" = all ]; then
    runs=$(awk 'NR > 2 { s += $4 } END { print s }' summary.txt)
    steps=$(awk 'NR > 2 { s += $5 } END { print s }' summary.txt)
    dl=-; dw=-
    "$PY" run_merge.py check $OPTS > check.txt 2> err.txt || die "check failed: $(cat err.txt)"
  else
    set -- $(awk 'NR == 3 { print $4, $5, $6, $9 }' summary.txt)
    runs=$1; steps=$2; dl=$3; dw=$4
  fi
  printf '%-7s %4s %5s  %-15s %-10s %8s %8s %8s   %s| %s| %s\n' "$CASE" "$runs" "$steps" "$dl" "$dw" \
    "$(median < t_cold)" "$(median < t_warm)" "$(median < t_exe)" \
    "$(tr '\n' ' ' < t_cold)" "$(tr '\n' ' ' < t_warm)" "$(tr '\n' ' ' < t_exe)"
done
echo
cat check.txt
if [ -n "$KEEP" ]; then echo "work directory: $WORK"; fi
exit 0

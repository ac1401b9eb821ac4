#!/bin/sh
# run_auto.sh — AUTO-07p side of whirl's speed comparison (doc/auto-sfd-benchmark.md):
# the complete synchronous response of the SFD rotor at Table 1
# (λ = 0.0503, δ = 0.3, ζ = 0) for 0.01 <= Ω <= 20, main branch and isola.
#
# usage: test/bench/auto/sfd/run_auto.sh [-n N] [--tight] [--iid0] [--keep] [--cold-only]
#   -n N     repetitions per timing (default 5; the median is reported)
#   --cold-only  only the cold runs, printed as "cold SECONDS ..." (one
#            round of test/bench/compare_auto.sh)
#   --tight  EPSL = EPSU = 1e-10, EPSS = 1e-8 instead of AUTO's defaults
#            (EPSL = EPSU = 1e-7, EPSS = 1e-5)
#   --iid0   IID = 0: no per-step diagnostics file (AUTO's default IID = 2
#            writes eigenvalues etc. of every step to fort.9)
#   --keep   keep the work directory (b.*, auto.log, ...) and print its path
# BENCH_WALL: test/bench/bench_wall of a build, which times a process
# without starting a `date` for it (else `date +%s%N` around it).
# Needs /usr/bin/python3 (not a pyenv python), AUTO-07p (AUTO_DIR, default
# /usr/lib/auto-07p) with gcc and gfortran.  Runs in a fresh temporary
# directory; exits non-zero with a message on any failure.
#
# Timings (wall clock, median of N):
#   whole, cold  run_sfd.py run with no sfd.o/sfd.exe: Python + AUTO's Python
#                interface + compile (gcc) and link (gfortran) + 3 AUTO runs
#   whole, warm  the same with sfd.exe present (AUTO reuses the executable)
#   exe only     the 3 runs of ./sfd.exe fed their constants on stdin, no
#                Python at all
# SPDX-License-Identifier: BSD-3-Clause
set -eu

PY=/usr/bin/python3
N=5
TIGHT=
IID0=
KEEP=
COLD_ONLY=
while [ $# -gt 0 ]; do
  case "$1" in
    -n) [ $# -ge 2 ] || { echo "run_auto.sh: -n needs a value" >&2; exit 2; }
        N=$2; shift 2 ;;
    --tight) TIGHT=--tight; shift ;;
    --iid0) IID0=--iid0; shift ;;
    --keep) KEEP=1; shift ;;
    --cold-only) COLD_ONLY=1; shift ;;
    -h|--help) sed -n '2,29p' "$0"; exit 0 ;;
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
for f in sfd.c c.sfd circ.py run_sfd.py; do
  [ -f "$SRC/$f" ] || die "missing $SRC/$f"
done

WORK=$(mktemp -d "${TMPDIR:-/tmp}/whirl-auto-sfd.XXXXXX") || die "mktemp failed"
if [ -z "$KEEP" ]; then trap 'rm -rf "$WORK"' EXIT; fi
trap 'exit 1' HUP INT PIPE TERM
cp "$SRC/sfd.c" "$SRC/c.sfd" "$SRC/circ.py" "$SRC/run_sfd.py" "$WORK/"
cd "$WORK"

now() { date +%s%N; }
# timed FILE CMD ARG...: run CMD, append its wall time in seconds to FILE
timed() {
  if [ -n "${BENCH_WALL:-}" ]; then "$BENCH_WALL" "$@"; return; fi
  t_file=$1
  shift
  t0=$(now)
  "$@" || return
  t1=$(now)
  echo "$t0 $t1" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }' >> "$t_file"
}
median() { sort -g | awk '{ a[NR] = $1 } END {
  if (NR == 0) exit 1
  if (NR % 2) m = a[(NR + 1) / 2]; else m = (a[NR / 2] + a[NR / 2 + 1]) / 2
  printf "%.4f", m }'; }
RUNS="main iso_fw iso_bw"

# 1. whole process, cold (compile + link + runs)
: > t_cold
i=0
while [ $i -lt "$N" ]; do
  rm -f sfd.o sfd.exe fort.* b.* auto.log
  timed t_cold "$PY" run_sfd.py run $TIGHT $IID0 > summary.txt 2> err.txt \
    || die "AUTO run failed: $(cat err.txt) (log: $WORK/auto.log; use --keep)"
  i=$((i + 1))
done
grep -q "^gcc" auto.log || die "cold run did not compile sfd.c (see auto.log)"
if [ -n "$COLD_ONLY" ]; then
  echo "cold $(tr '\n' ' ' < t_cold)"
  exit 0
fi
cpu=$(awk '/Total Time/ { s += $3 } END { printf "%.4f", s }' auto.log)

# 2. whole process, warm (AUTO reuses sfd.exe)
: > t_warm
i=0
while [ $i -lt "$N" ]; do
  rm -f fort.* b.* auto.log
  timed t_warm "$PY" run_sfd.py run $TIGHT $IID0 > summary.txt 2> err.txt \
    || die "AUTO run failed: $(cat err.txt)"
  i=$((i + 1))
done
if grep -q "^gcc" auto.log; then die "warm run recompiled sfd.c"; fi

# 3. the executable alone, same constants (c.sfd_<run> from step 1)
[ -x sfd.exe ] || die "sfd.exe missing after the AUTO runs"
: > t_exe
i=0
while [ $i -lt "$N" ]; do
  t0=$(now)
  for r in $RUNS; do
    rm -f fort.7 fort.8 fort.9
    ./sfd.exe < "c.sfd_$r" > "exe_$r.out" 2>&1 || die "./sfd.exe < c.sfd_$r failed"
    cp fort.7 "b.$r"
  done
  t1=$(now)
  echo "$t0 $t1" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }' >> t_exe
  i=$((i + 1))
done
# the bare executable must reproduce the summary of the Python-driven runs
"$PY" run_sfd.py summary > summary_exe.txt 2> err.txt || die "$(cat err.txt)"
cmp -s summary.txt summary_exe.txt || die "bare sfd.exe runs differ from the AUTO Python runs"

echo "AUTO-07p $(dpkg-query -W -f='${Version}' auto-07p 2>/dev/null || echo '?') ($AUTO_DIR)," \
     "$(nproc) CPU(s): $(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)"
echo "tolerances: $([ -n "$TIGHT" ] && echo 'EPSL=EPSU=1e-10 EPSS=1e-8' || echo 'EPSL=EPSU=1e-7 EPSS=1e-5 (AUTO defaults)');" \
     "diagnostics: $([ -n "$IID0" ] && echo 'IID=0' || echo 'IID=2 (AUTO default)')"
echo "wall time, median of $N [s]: whole cold (compile+runs) $(median < t_cold)," \
     "whole warm (exe reused) $(median < t_warm), exe only (3 runs) $(median < t_exe)"
echo "AUTO's own 'Total Time' (CPU, sum of the 3 runs): last cold pass $cpu s," \
     "last warm pass $(awk '/Total Time/ { s += $3 } END { printf "%.4f", s }' auto.log) s"
echo "all times [s]: cold $(tr '\n' ' ' < t_cold)| warm $(tr '\n' ' ' < t_warm)| exe $(tr '\n' ' ' < t_exe)"
cat summary.txt
"$PY" run_sfd.py check $TIGHT > check.txt 2> err.txt || die "check failed: $(cat err.txt)"
sed -n '/^eq. 15/,$p' check.txt
if [ -n "$KEEP" ]; then echo "work directory: $WORK"; fi
exit 0

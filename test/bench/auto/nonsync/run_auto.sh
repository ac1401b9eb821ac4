#!/bin/sh
# run_auto.sh — AUTO-07p side of whirl's speed comparison for the
# nonsynchronous response of the SFD rotor at Table 1 (λ = 0.0503, δ = 0.3,
# ζ = 0): the periodic orbit of the rotating-frame ODE continued in Ω with
# IPS = 2, NTST = 100, NCOL = 4 from the orbit at Ω = 8.7 (nonsync.dat)
# through its fold of cycles up to Ω = 20 on both branches.
#
# usage: test/bench/auto/nonsync/run_auto.sh [-n N] [--tight] [--iid0]
#                                            [--omp1] [--keep]
#   -n N     repetitions per timing (default 5; the median is reported)
#   --tight  EPSL = EPSU = 1e-10, EPSS = 1e-8 instead of AUTO's defaults
#            (EPSL = EPSU = 1e-7, EPSS = 1e-5)
#   --iid0   IID = 0: no per-step diagnostics file (AUTO's default IID = 2
#            writes Floquet multipliers etc. of every step to fort.9)
#   --omp1   OMP_NUM_THREADS=1 (AUTO is built with OpenMP and otherwise
#            uses all cores)
#   --keep   keep the work directory (b.*, auto.log, ...) and print its path
# Needs /usr/bin/python3 (not a pyenv python), AUTO-07p (AUTO_DIR, default
# /usr/lib/auto-07p) with gcc and gfortran.  Runs in a fresh temporary
# directory; exits non-zero with a message on any failure.
#
# Timings (wall clock, median of N):
#   whole, cold  run_nonsync.py run with no nonsync.o/nonsync.exe: Python +
#                AUTO's Python interface + compile (gcc) and link (gfortran)
#                + 2 AUTO runs
#   whole, warm  the same with nonsync.exe present (AUTO reuses it)
#   exe only     the 2 runs of ./nonsync.exe fed their constants on stdin,
#                no Python at all
# The start orbit nonsync.dat is data (made once by start_orbit.c); making
# it is not timed.
# SPDX-License-Identifier: BSD-3-Clause
set -eu

PY=/usr/bin/python3
N=5
TIGHT=
IID0=
OMP1=
KEEP=
while [ $# -gt 0 ]; do
  case "$1" in
    -n) [ $# -ge 2 ] || { echo "run_auto.sh: -n needs a value" >&2; exit 2; }
        N=$2; shift 2 ;;
    --tight) TIGHT=--tight; shift ;;
    --iid0) IID0=--iid0; shift ;;
    --omp1) OMP1=1; shift ;;
    --keep) KEEP=1; shift ;;
    -h|--help) sed -n '2,31p' "$0"; exit 0 ;;
    *) echo "run_auto.sh: unknown argument: $1" >&2; exit 2 ;;
  esac
done
case "$N" in ''|*[!0-9]*|0) echo "run_auto.sh: -n must be a positive integer" >&2; exit 2 ;; esac

die() { echo "run_auto.sh: error: $*" >&2; exit 1; }

AUTO_DIR=${AUTO_DIR:-/usr/lib/auto-07p}
export AUTO_DIR
NCPU=$(nproc --all)  # plain nproc honours OMP_NUM_THREADS
if [ -n "$OMP1" ]; then OMP_NUM_THREADS=1; export OMP_NUM_THREADS; fi
[ -x "$PY" ] || die "$PY not found"
[ -d "$AUTO_DIR/python/auto" ] || die "AUTO-07p Python modules not found in $AUTO_DIR/python"
command -v gcc >/dev/null 2>&1 || die "gcc not found (AUTO compiles nonsync.c with it)"
command -v gfortran >/dev/null 2>&1 || die "gfortran not found (AUTO links with it)"

SRC=$(cd "$(dirname "$0")" && pwd)
for f in nonsync.c c.nonsync nonsync.dat run_nonsync.py ../sfd/circ.py; do
  [ -f "$SRC/$f" ] || die "missing $SRC/$f"
done

WORK=$(mktemp -d "${TMPDIR:-/tmp}/whirl-auto-nonsync.XXXXXX") || die "mktemp failed"
if [ -z "$KEEP" ]; then trap 'rm -rf "$WORK"' EXIT; fi
trap 'exit 1' HUP INT PIPE TERM
cp "$SRC/nonsync.c" "$SRC/c.nonsync" "$SRC/nonsync.dat" "$SRC/run_nonsync.py" \
   "$SRC/../sfd/circ.py" "$WORK/"
cd "$WORK"

now() { date +%s%N; }
median() { sort -g | awk '{ a[NR] = $1 } END {
  if (NR == 0) exit 1
  if (NR % 2) m = a[(NR + 1) / 2]; else m = (a[NR / 2] + a[NR / 2 + 1]) / 2
  printf "%.4f", m }'; }
RUNS="fw bw"

# 1. whole process, cold (compile + link + runs)
: > t_cold
i=0
while [ $i -lt "$N" ]; do
  rm -f nonsync.o nonsync.exe fort.* b.* auto.log
  t0=$(now)
  "$PY" run_nonsync.py run $TIGHT $IID0 > summary.txt 2> err.txt \
    || die "AUTO run failed: $(cat err.txt) (log: $WORK/auto.log; use --keep)"
  t1=$(now)
  echo "$t0 $t1" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }' >> t_cold
  i=$((i + 1))
done
grep -q "^gcc" auto.log || die "cold run did not compile nonsync.c (see auto.log)"
cpu=$(awk '/Total Time/ { s += $3 } END { printf "%.4f", s }' auto.log)

# 2. whole process, warm (AUTO reuses nonsync.exe)
: > t_warm
i=0
while [ $i -lt "$N" ]; do
  rm -f fort.* b.* auto.log
  t0=$(now)
  "$PY" run_nonsync.py run $TIGHT $IID0 > summary.txt 2> err.txt \
    || die "AUTO run failed: $(cat err.txt)"
  t1=$(now)
  echo "$t0 $t1" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }' >> t_warm
  i=$((i + 1))
done
if grep -q "^gcc" auto.log; then die "warm run recompiled nonsync.c"; fi

# 3. the executable alone, same constants (c.nonsync_<run> from step 1);
#    it reads nonsync.dat itself (constant dat)
[ -x nonsync.exe ] || die "nonsync.exe missing after the AUTO runs"
: > t_exe
i=0
while [ $i -lt "$N" ]; do
  t0=$(now)
  for r in $RUNS; do
    rm -f fort.2 fort.7 fort.8 fort.9
    ./nonsync.exe < "c.nonsync_$r" > "exe_$r.out" 2>&1 \
      || die "./nonsync.exe < c.nonsync_$r failed"
    cp fort.7 "b.$r"
  done
  t1=$(now)
  echo "$t0 $t1" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }' >> t_exe
  i=$((i + 1))
done
# the bare executable must reproduce the summary of the Python-driven runs
"$PY" run_nonsync.py summary > summary_exe.txt 2> err.txt || die "$(cat err.txt)"
cmp -s summary.txt summary_exe.txt || die "bare nonsync.exe runs differ from the AUTO Python runs"

echo "AUTO-07p $(dpkg-query -W -f='${Version}' auto-07p 2>/dev/null || echo '?') ($AUTO_DIR)," \
     "$NCPU CPU(s): $(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)," \
     "OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset}"
echo "tolerances: $([ -n "$TIGHT" ] && echo 'EPSL=EPSU=1e-10 EPSS=1e-8' || echo 'EPSL=EPSU=1e-7 EPSS=1e-5 (AUTO defaults)');" \
     "diagnostics: $([ -n "$IID0" ] && echo 'IID=0' || echo 'IID=2 (AUTO default)')"
echo "wall time, median of $N [s]: whole cold (compile+runs) $(median < t_cold)," \
     "whole warm (exe reused) $(median < t_warm), exe only (2 runs) $(median < t_exe)"
echo "AUTO's own 'Total Time' (sum of the 2 runs): last cold pass $cpu s," \
     "last warm pass $(awk '/Total Time/ { s += $3 } END { printf "%.4f", s }' auto.log) s"
echo "all times [s]: cold $(tr '\n' ' ' < t_cold)| warm $(tr '\n' ' ' < t_warm)| exe $(tr '\n' ' ' < t_exe)"
cat summary.txt
"$PY" run_nonsync.py check $TIGHT > check.txt 2> err.txt || die "check failed: $(cat err.txt)"
sed -n '/^fold of cycles/,$p' check.txt
if [ -n "$KEEP" ]; then echo "work directory: $WORK"; fi
exit 0

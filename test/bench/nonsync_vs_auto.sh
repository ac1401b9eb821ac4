#!/bin/sh
# test/bench/nonsync_vs_auto.sh — whirl against AUTO-07p on the same job, both
# timed as whole processes in one run on this machine: the nonsynchronous
# response of the SFD rotor at Table 1 (periodic orbit of the rotating-frame
# ODE from Ω = 8.7 through its fold of cycles up to Ω = 20, both branches).
#   whirl:    whirl sfd nonsync --no-plot --quiet [whirl options]  (N runs,
#             median)
#   AUTO-07p: test/bench/auto/nonsync/run_auto.sh -n N  (cold, warm, exe only;
#             IPS = 2, NTST = 100, NCOL = 4)
# usage: test/bench/nonsync_vs_auto.sh [-n N] [--tight] [--iid0] [--omp1]
#                                      [whirl options ...]
#   -n N      repetitions of each timing (default 5, the median is reported)
#   --tight, --iid0, --omp1   passed to run_auto.sh (AUTO tolerances
#             EPSL = EPSU = 1e-10, EPSS = 1e-8; IID = 0; OMP_NUM_THREADS=1)
#   any other argument goes to whirl, e.g. --method hbm --harmonics 40,
#   --ntst 100 (a "--" ends the options of this script; all after it go to
#   whirl)
# Run from the build directory (WHIRL, default ./drivers/whirl; the
# executable behind libtool's wrapper is timed); needs the auto-07p Debian
# package.  Prints whirl's median, its LP line(s), AUTO's
# report and the ratios AUTO / whirl.
# SPDX-License-Identifier: BSD-3-Clause
set -eu
N=5
AUTO_OPTS=
here=$(cd "$(dirname "$0")" && pwd)
WHIRL=${WHIRL:-./drivers/whirl}
die() { echo "nonsync_vs_auto.sh: error: $*" >&2; exit 1; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-nonsync-cmp.XXXXXX") || die "mktemp failed"
trap 'rm -rf "$tmp"' EXIT
trap 'exit 1' HUP INT PIPE TERM

# whirl options are kept as positional parameters ("$@"), the others removed
nargs=$#
i=0
while [ $i -lt "$nargs" ]; do
  a=$1; shift; i=$((i + 1))
  case "$a" in
    -n) [ $i -lt "$nargs" ] || die "-n needs a value"
        N=$1; shift; i=$((i + 1)) ;;
    --tight|--iid0|--omp1) AUTO_OPTS="$AUTO_OPTS $a" ;;
    --) while [ $i -lt "$nargs" ]; do set -- "$@" "$1"; shift; i=$((i + 1)); done ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    --out|--out=*|--no-plot|--quiet) die "$a is set by this script" ;;
    *) set -- "$@" "$a" ;;
  esac
done
case "$N" in ''|*[!0-9]*|0) die "-n must be a positive integer" ;; esac
[ -x "$WHIRL" ] || die "$WHIRL not found (run from the build directory or set WHIRL)"
# In an uninstalled build ./drivers/whirl is libtool's wrapper script, which
# costs ~20 ms of shell per run: time the executable behind it (with the
# freshly built library first on the search path), as AUTO's "exe only"
# figure times nonsync.exe itself.
WHIRL_LIBPATH=
wdir=$(dirname "$WHIRL")
if [ -x "$wdir/.libs/$(basename "$WHIRL")" ] && [ -d "$wdir/../lib/.libs" ] &&
   grep -q 'libtool' "$WHIRL" 2>/dev/null; then
  WHIRL_LIBPATH=$(cd "$wdir/../lib/.libs" && pwd)
  WHIRL="$wdir/.libs/$(basename "$WHIRL")"
fi

# whirl: N whole-process runs, median wall time
: > "$tmp/t"
i=0
while [ $i -lt "$N" ]; do
  rm -rf "$tmp/out"
  s=$(date +%s%N)
  LD_LIBRARY_PATH="$WHIRL_LIBPATH${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    "$WHIRL" sfd nonsync --no-plot --quiet --out "$tmp/out" "$@" \
    > "$tmp/whirl.out" 2> "$tmp/whirl.err" \
    || die "whirl sfd nonsync $* failed: $(cat "$tmp/whirl.err")"
  e=$(date +%s%N)
  echo "$s $e" | awk '{ printf "%.6f\n", ($2 - $1) / 1e9 }' >> "$tmp/t"
  i=$((i + 1))
done
wmed=$(sort -g "$tmp/t" | awk '{ a[NR] = $1 } END {
  if (NR % 2) m = a[(NR + 1) / 2]; else m = (a[NR / 2] + a[NR / 2 + 1]) / 2
  printf "%.4f", m }')
echo "whirl sfd nonsync --no-plot --quiet $*  ($WHIRL)"
echo "whirl whole process, wall time, median of $N: $wmed s (all: $(tr '\n' ' ' < "$tmp/t"))"
awk '$1 == "LP"' "$tmp/whirl.out" | sed 's/^/whirl: /'
awk '$1 == "LP" { n++ } END { exit n == 0 }' "$tmp/whirl.out" \
  || echo "whirl: (no LP line on stdout)"
echo

# AUTO-07p (run_auto.sh checks its own results and exits non-zero on failure)
# shellcheck disable=SC2086  # AUTO_OPTS is a list of plain words
"$here/auto/nonsync/run_auto.sh" -n "$N" $AUTO_OPTS > "$tmp/auto.txt" \
  || die "run_auto.sh failed"
cat "$tmp/auto.txt"
echo

line=$(grep '^wall time, median of' "$tmp/auto.txt") \
  || die "no timing line in the output of run_auto.sh"
echo "$line" | awk -v w="$wmed" '{
  for (i = 1; i <= NF; i++) {
    if ($i == "(compile+runs)") cold = $(i + 1)
    if ($i == "reused)") warm = $(i + 1)
    if ($i == "runs)") exe = $(i + 1)
  }
  sub(/,$/, "", cold); sub(/,$/, "", warm); sub(/,$/, "", exe)
  if (cold == "" || warm == "" || exe == "" || w <= 0) exit 1
  printf "ratio AUTO / whirl (wall, medians): whole cold %.2f, whole warm %.2f, exe only %.2f\n",
    cold / w, warm / w, exe / w
  printf "  (whirl %s s; AUTO cold %s s, warm %s s, exe only %s s)\n", w, cold, warm, exe
}' || die "could not read AUTO's times: $line"

#!/bin/sh
# test/bench/bench_study.sh — a parameter study (doc/parameter-studies.md)
# of the SFD rotor's isola count over a (lambda, delta) grid, serial and on
# MPI with 2 ranks, paired, REPEAT times (default 3): wall times, the
# speed-up and the parallel efficiency T1 / (2 T2), and the per-point cost
# distribution (for the scaling model of doc/parameter-studies.md).
# Needs a build --with-mpi: WHIRL=path/to/drivers/whirl.  Not a test.
#   sh test/bench/bench_study.sh [REPEAT [GRID_N]]
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_srcdir=${top_srcdir:-.}
WHIRL=${WHIRL:-${top_builddir:-.}/drivers/whirl}
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
case $top_srcdir in /*) ;; *) top_srcdir="$(pwd)/$top_srcdir" ;; esac
repeat=${1:-3}
gn=${2:-6}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-bench.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
lams=$(awk -v n="$gn" 'BEGIN { for (i = 0; i < n; i++) printf "%s%.4g", i ? ", " : "", 0.05 + 0.45 * i / (n - 1) }')
dels=$(awk -v n="$gn" 'BEGIN { for (i = 0; i < n; i++) printf "%s%.4g", i ? ", " : "", 0.15 + 0.5 * i / (n - 1) }')
sed -e '/^ICP/s/.*/ICP    = [Omega]/' -e '/^DISCOVER /s/.*/DISCOVER        = [5, 10, 19]/' \
  "$top_srcdir/examples/discover/sfd-rotating.whirl" > grid.whirl
echo "STUDY = {lambda: [$lams], delta: [$dels]}" >> grid.whirl
now() { date +%s.%N; }
echo "# $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $((gn * gn)) points"
printf 'run\tserial_s\tmpi2_s\tspeedup\tefficiency\n'
for r in $(seq 1 "$repeat"); do
  t0=$(now); "$WHIRL" run grid.whirl --quiet --OUT=s > /dev/null || exit 1
  t1=$(now); mpirun --allow-run-as-root --oversubscribe -n 2 "$WHIRL" run grid.whirl --quiet --OUT=m > /dev/null || exit 1
  t2=$(now)
  cmp -s s/study.tsv m/study.tsv || { echo "the MPI file differs" >&2; exit 1; }
  awk -v a="$(echo "$t1 - $t0" | bc -l)" -v b="$(echo "$t2 - $t1" | bc -l)" -v r="$r" \
    'BEGIN { printf "%d\t%.3f\t%.3f\t%.2f\t%.2f\n", r, a, b, a / b, a / (2 * b) }'
done | tee times.tsv
sort -t '	' -k5 -g times.tsv | awk -F '\t' '{ e[NR] = $5; s[NR] = $4 } END { m = int((NR + 1) / 2); printf "# median speed-up %.2f, parallel efficiency %.2f over %d pairs\n", s[m], e[m], NR }'
# the cost of one point: each alone, serially (the distribution behind the
# scaling model)
head -n 1 s/study.tsv > /dev/null
n=$((gn * gn)); i=0
: > cost.txt
while [ $i -lt "$n" ]; do
  t0=$(now); "$WHIRL" run grid.whirl --quiet --chunk=$((i + 1))/$n --OUT=c > /dev/null; t1=$(now)
  echo "$t1 - $t0" | bc -l >> cost.txt
  rm -rf c.chunk-*
  i=$((i + 1))
done
sort -g cost.txt | awk '{ c[NR] = $1; s += $1 } END { printf "# one point (a whole process): min %.3f s, median %.3f s, max %.3f s, mean %.3f s\n", c[1], c[int((NR + 1) / 2)], c[NR], s / NR }'

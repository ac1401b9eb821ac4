#!/bin/sh
# test/bench/bench_basins_mpi.sh — `whirl sfd basins` (the paper's 8005
# states, the atlas's defaults) in one process against `mpirun -n 2`, one
# thread each, paired back to back, REPEAT times (default 3) a case: wall
# times, speed-up and parallel efficiency T1 / (2 T2); the two basins.tsv
# must be the same bytes (checked every pair).  With WHIRL_BLOCK_TIMES (a
# line a block: stage, block, rank, start, end, bytes) also the ranks'
# utilization (their time in blocks over 2 x the span of the blocks: the
# efficiency on 2 cores of their own, which a shared machine's wall times
# do not show), the blocks' costs and the bytes the ranks exchange (the
# atlas's rounds are broadcast).  Needs a build --with-mpi.  Not a test.
#   sh test/bench/bench_basins_mpi.sh [REPEAT [CASES]]
#   CASES: "1.78:zero 8.5327:circular" (the default: these and 1.715:circular)
#   POINTS=N: about N initial states instead of the paper's 8005
# SPDX-License-Identifier: BSD-3-Clause
set -u
WHIRL=${WHIRL:-${top_builddir:-.}/drivers/whirl}
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
repeat=${1:-3}
cases=${2:-"1.78:zero 1.715:circular 8.5327:circular"}
here=$(cd "$(dirname "$0")" && pwd) # before the cd below: $0 may be relative
pts=${POINTS:+--points $POINTS}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-bench.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
now() { date +%s.%N; }
echo "# $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load $(cut -d' ' -f1-3 /proc/loadavg)"
printf 'omega\tvelocities\trun\tserial_s\tmpi2_s\tspeedup\tefficiency\tutilization\tload\n'
for c in $cases; do
  om=${c%%:*}; vel=${c##*:}
  base="sfd basins --omega $om --velocities $vel $pts --threads 1 --quiet --no-plot"
  for r in $(seq 1 "$repeat"); do
    rm -rf s m
    t0=$(now); WHIRL_BLOCK_TIMES=s.times /usr/bin/time -f '%U %S' -o s.cpu "$WHIRL" $base --out s > /dev/null || exit 1
    t1=$(now); WHIRL_BLOCK_TIMES=m.times mpirun --allow-run-as-root --oversubscribe -x WHIRL_BLOCK_TIMES -n 2 "$WHIRL" $base --out m > /dev/null || exit 1
    t2=$(now)
    cmp -s s/basins.tsv m/basins.tsv || { echo "the MPI basins.tsv differs ($c)" >&2; exit 1; }
    # the ranks' utilization: time in blocks over 2 x the span of the blocks
    u=$(awk -F '\t' 'NR > 1 { b += $5 - $4; if (lo == "" || $4 < lo) lo = $4; if ($5 > hi) hi = $5 } END { printf "%.2f", b / (2 * (hi - lo)) }' m.times)
    cp s.times "s-$om-$vel.times"; cp m.times "m-$om-$vel.times"; cp s.cpu "s-$om-$vel.cpu"
    awk -v a="$(echo "$t1 - $t0" | bc -l)" -v b="$(echo "$t2 - $t1" | bc -l)" -v r="$r" -v om="$om" -v vel="$vel" -v u="$u" -v l="$(cut -d' ' -f1 /proc/loadavg)" \
      'BEGIN { printf "%s\t%s\t%d\t%.2f\t%.2f\t%.2f\t%.2f\t%s\t%s\n", om, vel, r, a, b, a / b, a / (2 * b), u, l }'
  done
done | tee times.tsv
sort -t '	' -k7 -g times.tsv | awk -F '\t' '{ e[NR] = $7 } END { m = int((NR + 1) / 2); printf "# parallel efficiency T1 / (2 T2): median %.2f, min %.2f, max %.2f over %d pairs\n", e[m], e[1], e[NR], NR }'
sort -t '	' -k8 -g times.tsv | awk -F '\t' '{ e[NR] = $8 } END { m = int((NR + 1) / 2); printf "# the ranks'"'"' utilization in blocks: median %.2f, min %.2f, max %.2f\n", e[m], e[1], e[NR] }'
# per case (the last pair): the blocks' CPU seconds (measured a block at a
# time on the ranks), the bytes the ranks exchange (the atlas's rounds
# broadcast, the table's rows sent), and the schedule replayed on cores of
# their own (blocks_model.awk) for 2 and 4 ranks, with the CPU seconds
# outside the blocks (the process's, less its blocks') on every rank
for c in $cases; do
  om=${c%%:*}; vel=${c##*:}
  awk -F '\t' -v c="$om $vel" 'NR > 1 { n[$1]++; s[$1] += $7; if ($7 > mx[$1]) mx[$1] = $7; by[$1] += $6 }
    END { printf "# %s, blocks (CPU):", c; for (k = 0; k in n; k++) printf " stage %d: %d blocks, %.2f s (max %.3f s), %.2f MB;", k, n[k], s[k], mx[k], by[k] / 1e6; printf "\n" }' "m-$om-$vel.times"
  out=$(awk -F '\t' 'NR > 1 { b += $7 } END { printf "%.3f", b }' "s-$om-$vel.times")
  S=$(awk -v b="$out" '{ printf "%.3f", $1 + $2 - b }' "s-$om-$vel.cpu")
  for R in 2 4; do
    printf '# %s %s, model: ' "$om" "$vel"; awk -F '\t' -v R=$R -v S="$S" -f "$here/blocks_model.awk" "m-$om-$vel.times"
  done
done

#!/bin/sh
# test/bench/bench_fe_rotor.sh — the scale benchmark of issue 16: the
# complete unbalance response of examples/rotor/compressor.rotor (330 DOFs,
# 7 impellers, 2 SFDs, a pedestal) from rest to above its second critical
# speed, by `whirl rotor response` (condensed harmonic balance, 5
# harmonics), without stability, with Hill's (sparse, ARPACK) and with
# Hill's on the Craig-Bampton reduction (reduced), each run REPEAT times
# (default 3); prints the median wall times, the points, the special
# points, the steps, Newton iterations, unknowns and spectra, and the
# points whose stable flag the reduced method gives otherwise than the
# sparse one.  Not a test: figures go into
# doc/benchmarks.md with the machine.
#   sh test/bench/bench_fe_rotor.sh [REPEAT]      (from the build tree)
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
WHIRL="$top_builddir/drivers/whirl"
ex="$top_srcdir/examples/rotor/compressor.rotor"
repeat=${1:-3}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-bench.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }
echo "# $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "# $ex: $("$WHIRL" rotor modes "$ex" --modes 1 > /dev/null && echo ok)"
printf 'stability\trun\twall_s\tpoints\tspecial\n'
for stab in off sparse reduced; do
  for r in $(seq 1 "$repeat"); do
    t0=$(now)
    "$WHIRL" rotor response "$ex" --stability "$stab" -o "$tmp/$stab" --no-plot > "$tmp/sp.tsv" 2> "$tmp/err" || exit 1
    t1=$(now)
    pts=$(grep -c . "$tmp/$stab/branches.tsv")
    sp=$(($(wc -l < "$tmp/sp.tsv") - 1))
    printf '%s\t%d\t%.3f\t%d\t%d\n' "$stab" "$r" "$(echo "$t1 - $t0" | bc -l)" "$((pts - 1))" "$sp"
  done
  # steps, Newton iterations, unknowns, spectra of the last run
  sed -n 's/^whirl rotor response: .*: /# '"$stab"': /p' "$tmp/err" >&2
done | tee "$tmp/times.tsv"
for stab in off sparse reduced; do
  awk -F '\t' -v s="$stab" '$1 == s { print $3 }' "$tmp/times.tsv" | sort -g |
    awk -v s="$stab" '{ t[NR] = $1 } END { printf "# median wall time, stability %s: %.3f s over %d runs\n", s, t[int((NR + 1) / 2)], NR }'
done
# the stable flags of the regular points (the located LP's own flag is the
# sign of an exponent equal to 0 to the localisation's tolerance)
paste "$tmp/sparse/branches.tsv" "$tmp/reduced/branches.tsv" | awk -F '\t' '
  NR > 1 && $1 == "-" { n++; if ($7 != $14) d++ }
  END { printf "# stable flags, reduced against sparse: %d of %d regular points differ\n", d, n }'

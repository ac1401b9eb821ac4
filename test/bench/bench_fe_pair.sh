#!/bin/sh
# test/bench/bench_fe_pair.sh — the scale benchmark of issue 16 paired
# against another build: `whirl rotor response` on
# examples/rotor/compressor.rotor by this build and by BASE (the whirl of
# another build tree, e.g. the last release's), alternately, REPEAT times
# each, with stability off and sparse; prints each pair, the median wall
# times and the median of the per-pair ratios (noise on a shared machine
# hits both sides of a pair alike), and whether the special points agree.
# Not a test: figures go into doc/benchmarks.md with the machine.
#   sh test/bench/bench_fe_pair.sh BASE_WHIRL [REPEAT]   (from the build tree)
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
NEW="$top_builddir/drivers/whirl"
BASE=${1:?usage: bench_fe_pair.sh BASE_WHIRL [REPEAT]}
repeat=${2:-5}
ex="$top_srcdir/examples/rotor/compressor.rotor"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-bench.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }
run() { # WHIRL STABILITY OUT -> wall seconds
  t0=$(now)
  "$1" rotor response "$ex" --stability "$2" -o "$3" --no-plot --quiet > "$3.sp" || return 1
  t1=$(now)
  echo "$t1 - $t0" | bc -l
}
echo "# $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
printf 'stability\tpair\tnew_s\tbase_s\tratio\tnew_points\tbase_points\n'
for stab in off sparse; do
  for r in $(seq 1 "$repeat"); do
    tn=$(run "$NEW" "$stab" "$tmp/new") || exit 1
    tb=$(run "$BASE" "$stab" "$tmp/base") || exit 1
    printf '%s\t%d\t%.3f\t%.3f\t%.2f\t%d\t%d\n' "$stab" "$r" "$tn" "$tb" \
      "$(echo "$tb / $tn" | bc -l)" "$(($(grep -c . "$tmp/new/branches.tsv") - 1))" \
      "$(($(grep -c . "$tmp/base/branches.tsv") - 1))"
  done
  # the folds of both, to 1e-8 relative in speed
  paste "$tmp/new.sp" "$tmp/base.sp" | awk -F '\t' -v s="$stab" 'NR > 1 {
      d = ($3 - $10) / $10; if (d < 0) d = -d; if (d > m) m = d; n++ }
    END { printf "# stability %s: %d special points each, largest relative speed difference %.1e\n", s, n, m }' >&2
done | tee "$tmp/t.tsv"
for stab in off sparse; do
  awk -F '\t' -v s="$stab" '$1 == s' "$tmp/t.tsv" > "$tmp/s.tsv"
  med() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
  printf '# stability %s: median new %.3f s, base %.3f s, median ratio base/new %.2f over %d pairs\n' "$stab" \
    "$(cut -f3 "$tmp/s.tsv" | med)" "$(cut -f4 "$tmp/s.tsv" | med)" "$(cut -f5 "$tmp/s.tsv" | med)" "$repeat"
done

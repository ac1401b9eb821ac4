#!/bin/sh
# test/bench/basins_fast.sh — every basin case of the paper (§5.3, Figs.
# 12–17, the 17 cases of basins_paper.sh, 8005 initial states each) with the
# atlas of classified cells (the default of `whirl sfd basins`) against the
# classification without it (--seeds 0: every state integrated until a
# certified capture, which is the fixed 500-period classification: a
# Lyapunov sublevel set is never left, doc/sfd-time-domain.md).  One TSV row
# a case:
#   omega velocities  ref_s  fast_median_s fast_min_s fast_max_s
#   fast_cpu_median_s (user + system: on a shared machine wall time over-
#   states, CPU time / 2 is the wall time on 2 free cores)  max_diff_points (the largest |fast − ref| share of an outcome, in
#   percentage points)  mismatched (states whose class differs)  fast shares
# usage: basins_fast.sh WHIRL OUTDIR [REPEAT (default 3)] [CASES]
#   CASES: a space-separated list like "1.78:zero 8.5327:circular"
#   REFERENCE=DIR: take the reference runs from DIR/OM-VEL/ (not rerun)
set -eu
WHIRL=${1:?usage: basins_fast.sh WHIRL OUTDIR [REPEAT] [CASES]}
OUT=${2:?usage: basins_fast.sh WHIRL OUTDIR [REPEAT] [CASES]}
REPEAT=${3:-3}
CASES=${4:-"1.715:zero 1.78:zero 1.838:zero 7.1:zero 8.0:zero 8.5:zero 8.5327:zero 9.0:zero
1.715:circular 1.78:circular 1.838:circular 7.1:circular 8.0:circular 8.5:circular 8.5327:circular
9.0:circular 9.0:trajectory"}
REFERENCE=${REFERENCE:-}
mkdir -p "$OUT"

wall() { # seconds of the command "$@"; its CPU seconds (user + system) appended to $OUT/cpu
  t0=$(date +%s.%N)
  /usr/bin/time -f '%U %S' -o "$OUT/time.1" "$@" > /dev/null
  t1=$(date +%s.%N)
  awk '{ printf "%.2f\n", $1 + $2 }' "$OUT/time.1" >> "$OUT/cpu"
  awk "BEGIN { printf \"%.2f\", $t1 - $t0 }"
}
median() { sort -g | awk '{ v[NR] = $1 } END { printf "%.2f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# shares of each outcome in a basins.tsv: "name percent" lines
shares() { awk -F'\t' 'NR > 2 { n++; c[$5]++ } END { for (k in c) printf "%s %.4f\n", k, 100 * c[k] / n }' "$1" | sort; }

printf 'omega\tvelocities\tref_s\tfast_median_s\tfast_min_s\tfast_max_s\tfast_cpu_median_s\tmax_diff_points\tmismatched\tfast_shares\n'
for c in $CASES; do
  om=${c%%:*}; vel=${c##*:}
  base="$WHIRL sfd basins --omega $om --velocities $vel --threads 2 --quiet --no-plot"
  if [ -n "$REFERENCE" ]; then
    ref=$REFERENCE/$om-$vel; tref=NA
  else
    ref=$OUT/$om-$vel-ref; rm -rf "$ref"
    tref=$(wall $base --seeds 0 --out "$ref")
  fi
  times=""
  : > "$OUT/cpu"
  for k in $(seq 1 "$REPEAT"); do
    d=$OUT/$om-$vel-fast; rm -rf "$d"
    times="$times $(wall $base --out "$d")"
  done
  stats=$(echo $times | tr ' ' '\n' | sort -g | awk '{ v[NR] = $1 } END {
    m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%.2f\t%.2f\t%.2f", m, v[1], v[NR] }')
  shares "$ref/basins.tsv" > "$OUT/ref.shares"
  shares "$d/basins.tsv" > "$OUT/fast.shares"
  diff=$(join -a 1 -a 2 -e 0 -o 0,1.2,2.2 "$OUT/ref.shares" "$OUT/fast.shares" |
         awk '{ x = $2 - $3; if (x < 0) x = -x; if (x > m) m = x } END { printf "%.3f", m }')
  mism=$(paste "$ref/basins.tsv" "$d/basins.tsv" | awk -F'\t' 'NR > 2 && $5 != $11 { n++ } END { print n + 0 }')
  sh=$(shares "$d/basins.tsv" | awk '{ printf "%s%s %.2f", (NR > 1 ? ", " : ""), $1, $2 }')
  cpu=$(median < "$OUT/cpu")
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$om" "$vel" "$tref" "$stats" "$cpu" "$diff" "$mism" "$sh"
done

#!/bin/sh
# test/bench/basins_paper.sh — every basin case of the paper (§5.3, Figs.
# 12–17) with whirl, at the paper's tolerance and optionally tenfold tighter,
# as one TSV table: omega velocities rtol attractor count percent seconds.
# usage: basins_paper.sh WHIRL OUTDIR [tight]
set -eu
WHIRL=${1:?usage: basins_paper.sh WHIRL OUTDIR [tight]}
OUT=${2:?usage: basins_paper.sh WHIRL OUTDIR [tight]}
TIGHT=${3:-}
mkdir -p "$OUT"
cases="1.715:zero 1.78:zero 1.838:zero 7.1:zero 8.0:zero 8.5:zero 8.5327:zero 9.0:zero
1.715:circular 1.78:circular 1.838:circular 7.1:circular 8.0:circular 8.5:circular 8.5327:circular 9.0:circular
9.0:trajectory"
tols="1e-12:1e-15"
[ -n "$TIGHT" ] && tols="1e-13:1e-16"
printf 'omega\tvelocities\trtol\tattractor\tcount\tpercent\tseconds\n'
for tol in $tols; do
  rtol=${tol%%:*}; atol=${tol##*:}
  for c in $cases; do
    om=${c%%:*}; vel=${c##*:}
    d="$OUT/$om-$vel-$rtol"
    t0=$(date +%s.%N)
    "$WHIRL" sfd basins --omega "$om" --velocities "$vel" --rtol "$rtol" --atol "$atol" \
      --threads 2 --out "$d" --quiet > "$d.tsv"
    t1=$(date +%s.%N)
    secs=$(awk "BEGIN { print $t1 - $t0 }")
    tail -n +2 "$d.tsv" | while IFS="$(printf '\t')" read -r a n pc; do
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%.1f\n' "$om" "$vel" "$rtol" "$a" "$n" "$pc" "$secs"
    done
  done
done

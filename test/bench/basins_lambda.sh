#!/bin/sh
# test/bench/basins_lambda.sh — the basin cases of the nonsynchronous region at
# lambda = 0.05 (the value the paper's time integrations turn out to use,
# doc/sfd-time-domain.md), and the tenfold-tighter-tolerance check on
# 2000-point lattices.  Results in OUTDIR/queue.tsv.
# usage: basins_lambda.sh WHIRL OUTDIR
W=${1:?usage: basins_lambda.sh WHIRL OUTDIR}; OUT=${2:?usage: basins_lambda.sh WHIRL OUTDIR}; mkdir -p "$OUT"
run() { # out lam om vel rtol atol points
  d=$OUT/q-$1; shift
  t0=$(date +%s.%N)
  $W sfd basins --lambda $1 --omega $2 --velocities $3 --rtol $4 --atol $5 --points $6 --threads 2 --out $d --quiet > $d.tsv
  t1=$(date +%s.%N)
  tail -n +2 $d.tsv | while IFS="$(printf '\t')" read -r a n pc; do
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$6" "$a" "$n" "$pc" "$(awk "BEGIN{print $t1-$t0}")"
  done >> $OUT/queue.tsv
}
printf 'lambda\tomega\tvelocities\trtol\tpoints\tattractor\tcount\tpercent\tseconds\n' > $OUT/queue.tsv
for c in 8.5327:zero 8.5327:circular 9.0:zero 9.0:circular 9.0:trajectory; do
  run l05-${c%%:*}-${c##*:} 0.05 ${c%%:*} ${c##*:} 1e-12 1e-15 8000
done
for c in 0.0503:1.78:zero 0.0503:1.78:circular 0.05:8.5327:zero 0.05:9.0:circular; do
  l=${c%%:*}; r=${c#*:}; om=${r%%:*}; vel=${r##*:}
  run t12-$l-$om-$vel $l $om $vel 1e-12 1e-15 2000
  run t13-$l-$om-$vel $l $om $vel 1e-13 1e-16 2000
done
echo done >> $OUT/queue.tsv

#!/bin/sh
# test/regress/region.sh — two-parameter continuation through the user's
# commands:
#  - `whirl sfd merge --lambda 0.25`: the merge value delta* against an
#    independent route, one-parameter continuation of the response
#    (`whirl sfd response`): 1e-5 below delta* there are two folds within
#    0.2 of Omega*, one on each side (the peak's and the isola's tip), 1e-5
#    above it they are gone (the branches have reconnected); its defining
#    equations hold to 1e-10;
#  - `whirl sfd region` and `--zeta 0.05`: every boundary point satisfies
#    the equations of eq. 15 that define it to 1e-10 (relative); the lower
#    curve carries the MG (merge speed reaches W) and CP (region closes)
#    labels; Table 1 (lambda 0.0503, delta 0.3: an isola with its fold at
#    Omega 7.09 < 20, from `whirl sfd response`) lies inside the band, and
#    delta 0.1 (no isola below 20) does not; the picture is written;
#  - bad input: exit 2 with a message, nothing written.
# SPDX-License-Identifier: BSD-3-Clause
set -u
WHIRL="${top_builddir:-.}/drivers/whirl"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-region.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
lt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }

# ---- merge
"$WHIRL" sfd merge --lambda 0.25 --quiet > "$tmp/merge.tsv"
ok $? "whirl sfd merge --lambda 0.25 exits 0"
head -1 "$tmp/merge.tsv" | grep -q "^lambda	zeta	delta	Omega	eps" 
ok $? "merge: header 'lambda zeta delta Omega eps'"
d=$(awk -F'\t' 'NR == 2 { print $3 }' "$tmp/merge.tsv")
W=$(awk -F'\t' 'NR == 2 { print $4 }' "$tmp/merge.tsv")
res=$(awk -F'\t' 'NR == 2 { print $7 }' "$tmp/merge.tsv")
ok $(lt "$res" 1e-10; echo $?) "merge: G = G_eps = G_Omega = 0 to 1e-10 (relative residual $res)"
# folds of the main branch near Omega* just below delta*, none just above
below=$(awk -v d="$d" 'BEGIN { printf "%.12f", d - 1e-5 }')
above=$(awk -v d="$d" 'BEGIN { printf "%.12f", d + 1e-5 }')
nlp() {
  "$WHIRL" sfd response --lambda 0.25 --delta "$1" --no-plot --quiet --out "$tmp/r$1" |
    awk -F'\t' -v W="$W" '$1 == "LP" && $4 < W && W - $4 < 0.2 { lo++ }
      $1 == "LP" && $4 > W && $4 - W < 0.2 { hi++ } END { print lo + hi, lo + 0, hi + 0 }'
}
set -- $(nlp "$below")
nb=$1 nblo=$2 nbhi=$3
set -- $(nlp "$above")
na=$1
ok $(( nb != 2 || nblo != 1 || nbhi != 1 )) "merge: at delta* - 1e-5 there are 2 folds near Omega* = $W, one on each side: the peak's and the isola's ($nb)"
ok $(( na != 0 )) "merge: at delta* + 1e-5 they are gone: the isola has merged ($na)"

# ---- region, both damping cases
for z in 0 0.05; do
  "$WHIRL" sfd region --zeta $z --quiet --out "$tmp/reg$z" > "$tmp/sp$z.tsv"
  ok $? "whirl sfd region --zeta $z exits 0"
  for f in upper lower; do
    head -n 1 "$tmp/reg$z/$f.tsv" | grep -q "^lambda	delta	Omega	eps"
    ok $? "region --zeta $z: $f.tsv has columns lambda delta Omega eps"
    m=$(awk -F'\t' 'NR > 2 { if ($6 + 0 > m) m = $6 + 0; k++ } END { if (k < 20) m = 1; printf "%.2g", m }' "$tmp/reg$z/$f.tsv")
    ok $(lt "$m" 1e-10; echo $?) "region --zeta $z: every $f boundary point satisfies eq. 15 to 1e-10 (max $m)"
  done
  grep -q "^lower	MG" "$tmp/sp$z.tsv"
  ok $? "region --zeta $z: MG on the lower curve (merge speed reaches W)"
  grep -q "^lower	CP" "$tmp/sp$z.tsv"
  ok $? "region --zeta $z: CP on the lower curve (the two folds at W meet)"
  test -s "$tmp/reg$z/region.png"
  ok $? "region --zeta $z: region.png written"
  # Omega at every lower point is W, and lambda covers the range
  ok $(awk -F'\t' 'NR > 2 && ($3 < 19.999999 || $3 > 20.000001) { bad = 1 } END { print bad + 0 }' "$tmp/reg$z/lower.tsv") \
     "region --zeta $z: the lower curve is at Omega = W"
done
# Table 1 inside the band (its isola fold is at 7.09 < 20), delta 0.1 not
"$WHIRL" sfd response --no-plot --quiet --out "$tmp/t1" > "$tmp/t1.tsv"
grep -q "isola" "$tmp/t1/branches.tsv" 2>/dev/null || grep -q "^LP	2" "$tmp/t1.tsv"
ok $? "Table 1 response has an isolated branch (independent route)"
inband() { awk -F'\t' -v l="$1" -v d="$2" 'NR > 1 && NF == 3 { if (p != "" && (pl - l) * ($1 - l) <= 0) { lo = plo + (l - pl) / ($1 - pl) * ($2 - plo); hi = phi + (l - pl) / ($1 - pl) * ($3 - phi); r = (d > lo && d < hi) } pl = $1; plo = $2; phi = $3; p = 1 } NF != 3 { p = "" } END { exit !r }' "$3"; }
inband 0.0503 0.3 "$tmp/reg0/band.tsv"
ok $? "region: Table 1 (lambda 0.0503, delta 0.3) lies in the band"
inband 0.0503 0.1 "$tmp/reg0/band.tsv"
ok $(( $? == 0 )) "region: delta 0.1 at lambda 0.0503 does not"

# ---- bad input
for args in "--lambda -1" "--lambda nan" "--zeta -0.1" "" "--lambda 0.25 --bogus 1"; do
  "$WHIRL" sfd merge $args > "$tmp/bad.out" 2> "$tmp/bad.err"
  rc=$?
  ok $(( rc != 2 || $(wc -l < "$tmp/bad.err") != 1 )) "merge $args: exit 2 with a one-line message ($(cat "$tmp/bad.err"))"
done
for args in "--lambda-min 2 --lambda-max 1" "--zeta nan" "--omega-max 0.5" "--ds-max 0"; do
  "$WHIRL" sfd region $args --out "$tmp/badreg" > /dev/null 2> "$tmp/bad.err"
  rc=$?
  ok $(( rc != 2 || $(wc -l < "$tmp/bad.err") != 1 )) "region $args: exit 2 with a one-line message"
  ok $(test ! -e "$tmp/badreg"; echo $?) "region $args: no output directory"
done

echo "1..$n"
[ "$fails" -eq 0 ]

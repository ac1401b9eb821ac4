#!/bin/sh
# test/regress/discover_sfd.sh — the discovery step (DISCOVER, doc/discovery.md)
# on the paper's rigid rotor in the rotating frame (model = sfd-rotating),
# by the generic route only (deflated Newton and fold loci on whirl run's
# equilibria), against the eq. 15 route of `whirl sfd response` (roots of
# the quartic, a separate code path) and the published values:
#  - Table 1: exactly two branches, the main one and the isola, and the three
#    LPs at Omega = 1.66619771686312, 1.88557959956546, 7.08811962886325
#    (doc/sfd-response.md: eq. 15, 40-digit mpmath, AUTO-07p) to 1e-8;
#  - lambda = 0.25, delta = 0.415: two branches, three LPs equal to eq. 15's;
#  - lambda = 0.25, delta = 0.2: one branch, no isola below Omega = 20;
#  - without DISCOVER the same run finds one branch (the test can fail);
#  - the same seed gives the same files, another seed the same branches;
#  - the paper's own computation (fixed frame, harmonic balance, 8
#    harmonics, 10x oversampling: sfd-fixed-hbm.whirl) finds the isola the
#    paper could only reach from a hand-made start: its fold at eq. 15's
#    7.0881196289 to 1e-8, its upper half stable and lower half unstable at
#    Omega = 10 (paper Fig. 3b), and 300 periods of time integration (whirl
#    sfd simulate, DOPRI5) from the orbit found end on it to 1e-8;
#  - bad input: an empty or inverted box, a budget of 0, a sample value
#    outside [RL0, RL1], orbits of an autonomous model, no sample values: one message with the
#    file and line, exit 2, no output directory.
# SPDX-License-Identifier: BSD-3-Clause
name=discsfd
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/discover"

lps() { awk -F '\t' '$3 == "LP" { printf "%.15g\n", $5 }' "$1/branches.tsv" | sort -g; }
eq15() { awk -F '\t' '$1 == "LP" { printf "%.15g\n", $4 }' "$1/special.tsv" | sort -g; }
close() { # close FILE_A FILE_B TOL: same count, every pair within TOL
  [ "$(wc -l < "$1")" -eq "$(wc -l < "$2")" ] && [ "$(wc -l < "$1")" -gt 0 ] &&
    paste "$1" "$2" | awk -v t="$3" '{ d = $1 - $2; if (d < -t || d > t) bad = 1 } END { exit bad }'
}

cp "$ex"/sfd-rotating*.whirl .
"$WHIRL" run sfd-rotating.whirl > t1.txt 2> t1.err
ok $? "whirl run examples/discover/sfd-rotating.whirl: $(head -c 200 t1.err)"
grep -q "^discovery: 2 branches, 1 of them isolated" t1.txt
ok $? "Table 1: 2 branches, 1 isolated: $(grep "^discovery" t1.txt)"
lps sfd-rotating.out > t1.lp
printf '1.66619771686312\n1.88557959956546\n7.08811962886325\n' > t1.want
close t1.lp t1.want 1e-8
ok $? "Table 1: the three LPs at the published values to 1e-8: $(tr '\n' ' ' < t1.lp)"
"$WHIRL" sfd response --out t1eq > /dev/null 2>&1
eq15 t1eq > t1.eq
close t1.lp t1.eq 1e-8
ok $? "Table 1: the three LPs equal eq. 15's to 1e-8"
# the isola is what discovery found: its branches hold the LP at 7.088 and
# no point of them lies on the main branch's Omega range below 7.08
awk -F '\t' '$3 == "LP" && $5 > 7 { b = $1 } END { exit !(b > 1) }' sfd-rotating.out/branches.tsv
ok $? "Table 1: the isola's fold is on a discovered branch, not the start branch"

"$WHIRL" run sfd-rotating.whirl --DISCOVER_SEED=7 --OUT=seed7 > s7.txt 2>&1
"$WHIRL" run sfd-rotating.whirl --quiet --OUT=again > again.out 2>&1
cmp -s sfd-rotating.out/branches.tsv again/branches.tsv
ok $? "the same seed: the same branches.tsv"
lps seed7 > s7.lp
close t1.lp s7.lp 1e-9 && grep -q "^discovery: 2 branches" s7.txt
ok $? "another seed (7): the same branches and LPs"

sed '/^DISCOVER/d' sfd-rotating.whirl > plain.whirl
"$WHIRL" run plain.whirl --quiet > plain.txt 2>&1
ok $(( $(lps plain.out | wc -l) != 2 )) "without DISCOVER: only the main branch's 2 LPs (the isola is not reached)"

"$WHIRL" run sfd-rotating-fig6.whirl > f6.txt 2> f6.err
ok $? "lambda 0.25, delta 0.415: $(head -c 200 f6.err)"
grep -q "^discovery: 2 branches, 1 of them isolated" f6.txt
ok $? "lambda 0.25, delta 0.415: 2 branches, 1 isolated"
"$WHIRL" sfd response --lambda 0.25 --delta 0.415 --out f6eq > /dev/null 2>&1
lps sfd-rotating-fig6.out > f6.lp
eq15 f6eq > f6.eq
close f6.lp f6.eq 1e-8
ok $? "lambda 0.25, delta 0.415: three LPs equal eq. 15's to 1e-8: $(tr '\n' ' ' < f6.lp)"

"$WHIRL" run sfd-rotating-no-isola.whirl > d2.txt 2> d2.err
ok $? "lambda 0.25, delta 0.2: $(head -c 200 d2.err)"
grep -q "^discovery: 1 branch, 0 of them isolated" d2.txt
ok $? "lambda 0.25, delta 0.2: one branch, no isola below Omega = 20"
"$WHIRL" sfd response --lambda 0.25 --delta 0.2 --out d2eq > d2eq.out 2>&1
grep -q "^whirl sfd response: 1 branch" d2eq.out
ok $? "eq. 15 agrees: one branch ($(head -n 1 d2eq.out | cut -c1-60))"

cp "$ex/sfd-fixed-hbm.whirl" .
"$WHIRL" run sfd-fixed-hbm.whirl > fx.txt 2> fx.err
ok $? "fixed frame, harmonic balance: $(head -c 200 fx.err)"
grep -q "^discovery: 2 branches, 1 of them isolated" fx.txt
ok $? "fixed frame: the main branch and the isola: $(grep '^discovery' fx.txt)"
lps sfd-fixed-hbm.out > fx.lp
close fx.lp t1.want 1e-8
ok $? "fixed frame: the three LPs at eq. 15's values to 1e-8: $(tr '\n' ' ' < fx.lp)"
# at Omega = 10 on the isola (where it was found, and its UZ point): MAX y, STAB
awk -F '\t' '$1 > 1 && ($2 == 0 || $3 == "UZ") { print $12, $16 }' sfd-fixed-hbm.out/branches.tsv | sort -gu > fx.ep
awk 'NR == 1 { lo = $2 } NR == 2 { hi = $2 } END { exit !(NR == 2 && lo == 0 && hi == 1) }' fx.ep
ok $? "fixed frame, Omega = 10: the isola's lower orbit unstable, its upper stable (paper Fig. 3b): $(tr '\n' ' ' < fx.ep)"
# the paper's regions (§5.1, §5.3): at its basin speeds 1.715, 1.78 and
# 1.838 (region B) three orbits, two stable; at 8.5327 (region D) three,
# two stable (the main branch's and the isola's upper half); at 3 (region
# C) one, stable.  Crossings of each speed by the traced branches.
for w in 1.715:3:2 1.78:3:2 1.838:3:2 8.5327:3:2 3:1:1; do
  IFS=: read -r om want wstab <<EOW
$w
EOW
  got=$(awk -F '\t' -v w="$om" 'NR > 1 && $1 == b && ($5 - w) * (p - w) <= 0 && $5 != p { n++; if ($16 == 1) st++ }
    NR > 1 { b = $1; p = $5 } END { printf "%d:%d", n, st }' sfd-fixed-hbm.out/branches.tsv)
  ok $(( $(test "$got" = "$want:$wstab"; echo $?) )) "paper's region at Omega = $om: $want orbits, $wstab stable (got $got)"
done
# the stable orbit's state at t = 0 from its harmonics (4 components of 17)
lab=$(awk -F '\t' '$1 > 1 && $2 == 0 && $16 == 1 { print $4; exit }' sfd-fixed-hbm.out/branches.tsv)
st=$(awk -v lab="$lab" '$1 == "LAB" && $2 == lab { f = 1 } f && $1 == "X" {
  for (i = 0; i < 4; i++) { s = $(2 + 17 * i); for (k = 1; k <= 8; k++) s += $(2 + 17 * i + 2 * k - 1); printf "%.15g ", s }
  exit }' sfd-fixed-hbm.out/solutions)
# shellcheck disable=SC2086
set -- $st
"$WHIRL" sfd simulate --omega 10 --y0 "${1:-0}" --z0 "${2:-0}" --vy0 "${3:-0}" --vz0 "${4:-0}" --periods 300 --out sim > sim.txt 2>&1
tail -n 1 sim/poincare.tsv | awk -v a="${1:-0}" -v b="${2:-0}" -v c="${3:-0}" -v d="${4:-0}" '{
  e = ($3 - a) ^ 2 + ($4 - b) ^ 2 + (($5 - c) / 10) ^ 2 + (($6 - d) / 10) ^ 2; exit !(sqrt(e) < 1e-8) }'
ok $? "time integration (300 periods) from the isola's stable orbit stays on it to 1e-8: $(tail -n 1 sim/poincare.tsv | cut -f3-6)"

bad() { # bad NAME 'LINE' PATTERN
  sed '/^DISCOVER/d' sfd-rotating.whirl > "$1.whirl"
  printf '%s\n' "$2" >> "$1.whirl"
  "$WHIRL" run "$1.whirl" --quiet > "$1.txt" 2> "$1.err"
  rc=$?
  ok $(( rc != 2 )) "$1: exit 2 ($rc)"
  grep -q "$1.whirl:[0-9]*: .*$3" "$1.err" && [ "$(wc -l < "$1.err")" -eq 1 ]
  ok $? "$1: one located message: $(cat "$1.err")"
  [ ! -e "$1.out/branches.tsv" ]
  ok $? "$1: no output written"
}
bad empty-box 'DISCOVER = [5]
DISCOVER_BOX = {u: [1, 1]}' "empty or inverted"
bad inverted-box 'DISCOVER = [5]
DISCOVER_BOX = {u: [1, -1]}' "empty or inverted"
bad budget-0 'DISCOVER = [5]
DISCOVER_STARTS = 0' "DISCOVER_STARTS = 0: must be in"
bad outside 'DISCOVER = [5, 25]' "DISCOVER: 25 is outside \[RL0, RL1\]"
bad no-values 'DISCOVER_STARTS = 10' "discovery needs DISCOVER"
bad nan 'DISCOVER = [nan]' "not a finite number"
sed -e 's/^IPS .*/IPS = 2/' -e '/^DISCOVER/d' sfd-rotating.whirl > colloc.whirl
echo 'DISCOVER = [5]' >> colloc.whirl
"$WHIRL" run colloc.whirl --quiet > colloc.txt 2> colloc.err
ok $(( $? != 2 )) "periodic orbits of an autonomous model refused, exit 2: $(cat colloc.err)"
grep -q "forced models" colloc.err
ok $? "an autonomous model's orbits: the message says why"
tap_end

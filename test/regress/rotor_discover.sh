#!/bin/sh
# test/regress/rotor_discover.sh — `whirl rotor response --discover`: the
# finite-element rotor in the rigid limit (examples/rotor/rigid-limit.rotor,
# the paper's rotor, Table 1) has the rigid rotor's isola, which the
# response from rest does not reach.  Discovery (deflated Newton at two
# speeds, no seed) must find it:
#  - two branches, one isolated; the isola's fold equals that of the branch
#    seeded by hand from the rigid rotor's isola (--seed, the route of
#    rotor_rigid_limit.sh) to 1e-8 and the rigid rotor's (eq. 15) to 1e-4,
#    the main branch's two folds likewise;
#  - without --discover: the two folds of the main branch only;
#  - bad input: a speed outside the range, a budget of 0, --seed with it,
#    a malformed list: one message, exit 2.
# SPDX-License-Identifier: BSD-3-Clause
name=rotdisc
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/rotor/rigid-limit.rotor"
wref=$(awk '$1 == "reference" { sub("omega=", "", $2); print $2 }' "$ex")
speeds=$(awk -v w="$wref" 'BEGIN { printf "%.6f,%.6f", 10 * w, 15 * w }')

"$WHIRL" rotor response "$ex" --harmonics 1 --unit rad/s --discover "$speeds" -o d.d > d.tsv 2> d.err
ok $? "whirl rotor response --discover $speeds: $(grep -v discovery d.err | head -c 200)"
grep -q "discovery: 2 branches, 1 of them isolated" d.err
ok $? "two branches, one isolated: $(grep discovery d.err | cut -c1-120)"
lp() { awk -F '\t' -v b="${2:-}" '$1 == "LP" && (b == "" || $2 == b) { print $5 }' "$1" | sort -g; }
lp d.tsv > d.lp
lp d.tsv 2 > d.iso
ok $(( $(wc -l < d.lp) != 3 || $(wc -l < d.iso) != 1 )) "three folds, one on the discovered branch: $(tr '\n' ' ' < d.lp)"

# the hand-seeded isola (rotor_rigid_limit.sh's route) and eq. 15
"$WHIRL" sfd response --out rigid --quiet > /dev/null 2>&1
seed=$(awk -F '\t' -v w="$wref" '$1 == 2 && $10 == 1 { d = $5 - 10; if (d < 0) d = -d;
  if (best == "" || d < best) { best = d; s = sprintf("%.10g:%s", $5 * w, $6) } } END { print s }' rigid/branches.tsv)
"$WHIRL" rotor response "$ex" --harmonics 1 --unit rad/s --seed "$seed" -o s.d --quiet > s.tsv 2> s.err
ok $? "the isola seeded by hand ($seed): $(head -c 200 s.err)"
lp s.tsv > s.lp
awk -F '\t' '$1 == "LP" { print $4 }' rigid/special.tsv | sort -g > r.lp
rel() { paste "$1" "$2" | awk -v t="$3" '{ d = ($1 - $2) / $2; if (d < 0) d = -d; if (d > t) bad = 1 } END { exit bad || NR != 3 }'; }
rel d.lp s.lp 1e-8
ok $? "the folds equal the hand-seeded run's to 1e-8: $(tr '\n' ' ' < s.lp)"
rel d.lp r.lp 1e-4
ok $? "and the rigid rotor's (eq. 15) to 1e-4: $(tr '\n' ' ' < r.lp)"

"$WHIRL" rotor response "$ex" --harmonics 1 -o p.d --quiet > p.tsv 2> p.err
ok $(( $(lp p.tsv | wc -l) != 2 )) "without --discover: the main branch's two folds only"

bad() { # bad NAME PATTERN ARGS...
  nm=$1 pat=$2
  shift 2
  "$WHIRL" rotor response "$ex" --harmonics 1 -o "$nm.d" --quiet "$@" > "$nm.tsv" 2> "$nm.err"
  rc=$?
  ok $(( rc != 2 )) "$nm: exit 2 ($rc)"
  grep -q "$pat" "$nm.err" && [ "$(wc -l < "$nm.err")" -eq 1 ] && [ ! -e "$nm.d" ]
  ok $? "$nm: one message, nothing written: $(cat "$nm.err")"
}
bad outside "outside the speed range" --unit rad/s --discover 99999
bad budget0 "discover-starts must be >= 1" --discover 50000 --discover-starts 0
bad with-seed "without --seed" --discover 50000 --seed 50000:0.5
bad malformed "wants up to 64 speeds" --discover 5000,abc
bad no-discover "need --discover" --discover-seed 3
tap_end

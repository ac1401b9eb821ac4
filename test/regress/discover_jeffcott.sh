#!/bin/sh
# test/regress/discover_jeffcott.sh — the Jeffcott rotor's lock-up isola
# (doc/jeffcott-model.md §6) found by the discovery step of whirl run with
# harmonic balance (examples/jeffcott/isola.whirl: no start on the isola),
# against the run from the hand-made start that file carried before
# (test/regress/jeffcott-isola-start.whirl: the t = 0 state of the closed-form
# circular orbit of §5):
#  - two branches, one isolated and closed;
#  - the isola's two folds equal those of the hand-started isola to 1e-8;
#  - at Omega = 2.58 it passes through the §5 orbit, eps_j = 0.8879 (closed
#    form, 4 digits), and the main branch through eps_j = 0.499 (§6);
#  - without DISCOVER the run finds the main branch only.
# SPDX-License-Identifier: BSD-3-Clause
name=discjeff
. "${top_srcdir:-.}/test/regress/tap.sh"

cp "$top_srcdir/examples/jeffcott/isola.whirl" "$top_srcdir/test/regress/jeffcott-isola-start.whirl" .
"$WHIRL" run isola.whirl > iso.txt 2> iso.err
ok $? "whirl run examples/jeffcott/isola.whirl: $(head -c 200 iso.err)"
grep -q "^discovery: 2 branches, 1 of them isolated (closed or not connected to the start), 1 closed" iso.txt
ok $? "two branches, the isola closed: $(grep '^discovery' iso.txt)"
"$WHIRL" run jeffcott-isola-start.whirl --quiet > start.txt 2> start.err
ok $? "the hand-started isola: $(head -c 200 start.err)"
lps() { awk -F '\t' -v br="${2:-}" '$3 == "LP" && (br == "" || $1 == br) { printf "%.15g\n", $5 }' "$1/branches.tsv" | sort -g; }
lps isola.out 2 > found.lp
lps jeffcott-isola-start.out > start.lp
[ "$(wc -l < found.lp)" -eq 2 ] && [ "$(wc -l < start.lp)" -eq 2 ] &&
  paste found.lp start.lp | awk '{ d = $1 - $2; if (d < -1e-8 || d > 1e-8) bad = 1 } END { exit bad }'
ok $? "the isola's folds $(tr '\n' ' ' < found.lp)= the hand-started isola's $(tr '\n' ' ' < start.lp)"
# MAX yj (journal orbit radius) is column 15 of branches.tsv
awk -F '\t' '$1 == 2 && $3 == "UZ" { d = $15 - 0.8879; if (d < 0) d = -d; if (d < 1e-4) hit = 1 } END { exit !hit }' isola.out/branches.tsv
ok $? "at Omega = 2.58 the isola passes through the closed-form orbit eps_j = 0.8879"
awk -F '\t' '$1 == 1 && $3 == "UZ" { d = $15 - 0.499; if (d < 0) d = -d; if (d < 1e-3) hit = 1 } END { exit !hit }' isola.out/branches.tsv
ok $? "and the main branch through eps_j = 0.499"
sed '/^DISCOVER/d' isola.whirl > plain.whirl
"$WHIRL" run plain.whirl --quiet > plain.txt 2>&1
ok $(( $(awk -F '\t' '$3 == "LP"' plain.out/branches.tsv | wc -l) != 0 )) "without DISCOVER: no isola (no LP on the main branch in [2, 3.2])"
tap_end

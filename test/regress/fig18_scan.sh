#!/bin/sh
# test/regress/fig18_scan.sh — the paper's Fig. 18 by brute force
# (examples/discover/fig18-scan.whirl: discovery at each point of a 6 x 6
# (lambda, delta) grid) against the region by continuation (whirl sfd
# region: its lower boundary, the isola's birth fold reaching Omega = 20,
# and its upper one, the isola-peak merge point; band.tsv):
#  - below the lower boundary no point has a branch apart from the start
#    branch, and inside the region every point has one (the isola);
#  - above the upper boundary the merged branch leaves the speed window
#    (Omega <= 20) and comes back, so the scan counts a piece apart there
#    too: not a region point, and the count is checked against eq. 15 by
#    study.sh instead — here only reported;
#  - points within 2 % of a boundary (in delta) are not judged.
# SPDX-License-Identifier: BSD-3-Clause
name=fig18
. "${top_srcdir:-.}/test/regress/tap.sh"
cp "$top_srcdir/examples/discover/fig18-scan.whirl" .
"$WHIRL" run fig18-scan.whirl --quiet 2> scan.err
ok $? "whirl run fig18-scan.whirl (36 points): $(head -c 200 scan.err)"
"$WHIRL" sfd region --out region --no-plot --quiet > region.txt 2> region.err
ok $? "whirl sfd region (the boundaries by continuation): $(head -c 200 region.err)"
# each point: the band at the nearest lambda of band.tsv (a log grid of 600)
awk -F '\t' 'NR == FNR { if (FNR > 1) { L[++m] = $1; lo[m] = $2; hi[m] = $3 } next }
  FNR > 1 { b = 1; for (i = 2; i <= m; i++) if ((log(L[i]) - log($2))^2 < (log(L[b]) - log($2))^2) b = i
    w = $3 < lo[b] * 0.98 ? "below" : $3 > hi[b] * 1.02 ? "above" : ($3 > lo[b] * 1.02 && $3 < hi[b] * 0.98) ? "inside" : "edge"
    printf "%s\t%s\t%s\t%s\t%s\t%.4f\t%.4f\n", $2, $3, w, $4, $6, lo[b], hi[b] }' \
  region/band.tsv fig18-scan.out/study.tsv > judged.tsv
nin=$(awk -F '\t' '$3 == "inside"' judged.tsv | wc -l)
nbelow=$(awk -F '\t' '$3 == "below"' judged.tsv | wc -l)
bad_in=$(awk -F '\t' '$3 == "inside" && !($4 == "ok" && $5 >= 1) { printf "(%s, %s) ", $1, $2 }' judged.tsv)
bad_below=$(awk -F '\t' '$3 == "below" && !($4 == "ok" && $5 == 0) { printf "(%s, %s) ", $1, $2 }' judged.tsv)
[ "$nin" -ge 3 ] && [ -z "$bad_in" ]
ok $? "inside the region: an isolated branch at each of the $nin points ${bad_in:+(not at $bad_in)}"
[ "$nbelow" -ge 10 ] && [ -z "$bad_below" ]
ok $? "below the lower boundary: none at each of the $nbelow points ${bad_below:+(one at $bad_below)}"
echo "# above the upper boundary (not judged): $(awk -F '\t' '$3 == "above" { printf "(%s, %s): %s; ", $1, $2, $5 }' judged.tsv)"
echo "# within 2 % of a boundary (not judged): $(awk -F '\t' '$3 == "edge" { printf "(%s, %s) ", $1, $2 }' judged.tsv)"
tap_end

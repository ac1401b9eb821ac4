#!/bin/sh
# test/regress/picture_labels.sh — what a reader of the pictures would
# stumble over, checked in the scripts beside them against the tables:
# sfd response's region letters A-D above the frame (not between B's red
# lines, nor on the upper branch) and apart; multipliers.png's log axis
# clipped (not down to 1e-22) but showing every multiplier from Omega = 1
# on; f2.png's y label saying what f_2 is; history.png of 1000 periods: a
# window of the last 10 periods (gnuplot computes it: 10 T = 20 pi / Omega);
# whirl run's diagram: every special point named "TY LAB", no two names
# overlapping and none leaving the axes (boxes from the script's ranges and
# offsets, at a glyph's size), and no line joining one branch's end to the
# next one's start; the legends outside the axes.
# SPDX-License-Identifier: BSD-3-Clause
name=picture_labels
. "${top_srcdir:-.}/test/regress/tap.sh"
GNUPLOT=${WHIRL_GNUPLOT:-gnuplot}
if ! command -v "$GNUPLOT" > /dev/null 2>&1; then
  echo "1..0 # SKIP gnuplot is not installed"
  exit 0
fi

# ---- sfd response: the region letters and the multipliers' axis
"$WHIRL" sfd response --out resp --quiet > /dev/null 2> resp.err
ok $? "whirl sfd response $(head -c 200 resp.err)"
gp=resp/response.gp
# "set label 'B' at X, graph Y": the four letters, above the frame (Y > 1),
# in order and at least 3 % of the axis (0..20) apart, the LP lines ending
# at the frame (graph 1)
letters=$(sed -n "s/^set label '\([A-D]\)' at \([-0-9.e]*\), graph \([0-9.]*\) .*/\1 \2 \3/p" "$gp")
echo "$letters" | awk 'NF == 3 { n++; if ($3 <= 1) bad = 1; if (n > 1 && $2 - x < 0.03 * 20) bad = 1; x = $2 }
  END { exit !(n == 4 && !bad) }'
ok $? "the region letters A-D above the frame and apart: $(echo $letters)"
grep -q "^set arrow from .*, graph 0 to .*, graph 1 nohead" "$gp" && ! grep -q "^set key .*opaque" "$gp"
ok $? "the LP lines end at the frame, the legend is not drawn over the curves (no opaque key inside)"
# the multipliers: the axis' lower end, against branches.tsv's max_multiplier
lo=$(sed -n 's/^set yrange \[\([-0-9.e]*\):\*\]$/\1/p' resp/multipliers.gp)
min1=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  !/^#/ && NF > 1 && $c["Omega"] >= 1 { m = $c["max_multiplier"] + 0; if (min == "" || m < min) min = m }
  END { print min }' resp/branches.tsv)
awk -v lo="${lo:-0}" -v m="${min1:-0}" 'BEGIN { exit !(lo >= 1e-4 && lo <= 0.1 && lo <= m && m > 0) }' &&
  grep -q '^set logscale y' resp/multipliers.gp && grep -q '^set key outside' resp/multipliers.gp
ok $? "multipliers.png: log axis from ${lo:-none} (>= 1e-4, not 1e-22), below every multiplier from Omega = 1 ($min1), legend outside"

# ---- sfd nonsync: f2.png's label
"$WHIRL" sfd nonsync --omega-max 10 --omega-min 7 --out ns --quiet > /dev/null 2> ns.err
ok $? "whirl sfd nonsync $(head -c 200 ns.err)"
yl=$(grep '^set ylabel' ns/f2.gp)
echo "$yl" | grep -q "second frequency f_2 (in units of {/Symbol W})"
ok $? "f2.png's y label says what is plotted: $yl"

# ---- sfd simulate: history.png's window of the last 10 periods
"$WHIRL" sfd simulate --omega 8.7 --periods 1000 --out sim --quiet > /dev/null 2> sim.err
ok $? "whirl sfd simulate --omega 8.7 --periods 1000 $(head -c 200 sim.err)"
w=$(cd sim && "$GNUPLOT" -e "load 'history.gp'; print t0, t1" 2>&1 | tail -n 1)
# t1: the last time of history.tsv; t1 - t0 = 10 periods of 2 pi / 8.7
last=$(awk -F'\t' 'NR > 1 && !/^#/ && NF > 1 { t = $1 } END { print t }' sim/history.tsv)
echo "$w $last" | awk '{ T = 2 * atan2(0, -1) / 8.7; d = $2 - $1 - 10 * T; e = $2 - $3
  exit !(NF == 3 && d < 1e-9 && d > -1e-9 && e < 1e-6 && e > -1e-6) }' &&
  grep -q "^set xrange \[t0:t1\]$" sim/history.gp && grep -q "^plot 'poincare.tsv' using 2:" sim/history.gp
ok $? "history.png: the whole run once a period, and the window [t0, t1] = [$w] of the last 10 periods (last t $last)"

# ---- whirl run: no line joins the end of one branch to the start of the
# next (they are rows one after the other in branches.tsv).  The discovery
# example traces three branches; its diagram, decoded by draw_check.py, has
# the branches' colour at their points and none on the straight segment
# from the last point of branch 1 to the first of branch 2.
PY=/usr/bin/python3
"$WHIRL" run "$top_srcdir/examples/discover/sfd-rotating.whirl" --out=disc --quiet > /dev/null 2> disc.err
rc=$?
if [ $rc -eq 0 ] && [ -x "$PY" ]; then
  check="$top_srcdir/test/regress/draw_check.py"
  xr=$(sed -n 's/^set xrange \[\(.*\):\(.*\)\]$/\1 \2/p' disc/diagram.gp)
  yr=$(sed -n 's/^set yrange \[\(.*\):\(.*\)\]$/\1 \2/p' disc/diagram.gp)
  awk -F'\t' 'NR > 1 && !/^#/ { if (b != "" && $1 != b) { print x, y; print $5, $10; exit } b = $1; x = $5; y = $10 }' \
    disc/branches.tsv > ends.txt
  awk 'NR == 1 { x0 = $1; y0 = $2 } NR == 2 { for (t = 0.2; t < 0.85; t += 0.15) print x0 + t * ($1 - x0), y0 + t * ($2 - y0) }' \
    ends.txt > gap.txt
  awk -F'\t' 'NR > 1 && !/^#/ && $15 == 1 && NR % 9 == 0 { print $5, $10 }' disc/branches.tsv > on.txt
  # shellcheck disable=SC2086 # the ranges: two numbers each
  gap=$("$PY" "$check" points disc/diagram.png $xr $yr 0 '#1f4e9c' 2 gap.txt)
  # shellcheck disable=SC2086
  on=$("$PY" "$check" points disc/diagram.png $xr $yr 0 '#1f4e9c' 2 on.txt)
  tot=$(echo "$on" | awk '{print $4}') hit=$(echo "$on" | awk '{print $2}')
  [ "$gap" = "found 0 of 5" ] && [ "$tot" -ge 20 ] && [ $((hit * 100)) -ge $((tot * 90)) ]
  ok $? "whirl run's diagram: nothing between branch 1's end and branch 2's start ($gap), the stable points on their curve ($on)"
else
  ok $rc "# SKIP whirl run (exit $rc) or /usr/bin/python3 missing $(head -c 200 disc.err)"
fi

# ---- whirl run: the names of the special points (AUTO's demo ab, a plug-in)
cp "$top_srcdir/examples/auto/ab.c" "$top_srcdir/examples/auto/ab-1.whirl" "$top_srcdir/examples/auto/ab-7.whirl" .
if ! ${CC:-cc} -std=c11 -shared -fPIC -I"$top_srcdir/lib" -I"$top_builddir/lib" -o ab.so ab.c -lm > cc.log 2>&1; then
  ok 0 "# SKIP no C compiler for the plug-in: $(head -c 200 cc.log)"
  tap_end
  exit $?
fi
"$WHIRL" run ab-1.whirl --quiet > /dev/null 2> ab1.err && "$WHIRL" run ab-7.whirl --quiet > /dev/null 2> ab7.err
ok $? "whirl run ab-1.whirl, ab-7.whirl $(cat ab1.err ab7.err | head -c 200)"
gp=ab-7.out/diagram.gp
# every labelled point but EP has its name "TY LAB" in the script
want=$(awk -F'\t' 'NR > 1 && !/^#/ && $3 != "-" && $3 != "EP" { print $3 " " $4 }' ab-7.out/branches.tsv | sort | tr '\n' ';')
got=$(sed -n "s/^set label '\([A-Z][A-Z] [0-9]*\)' at .*/\1/p" "$gp" | sort | tr '\n' ';')
[ -n "$want" ] && [ "$want" = "$got" ]
ok $? "ab-7: every special point named TY LAB ($got)"
# the names' boxes at a glyph's size (8 x 15 of the ~810 x 540 pixel axes),
# from the script's ranges, 'at' and offsets: none overlaps another, none
# leaves the axes
awk -v cu="$(awk 'BEGIN { print 8 / 810 }')" -v cv="$(awk 'BEGIN { print 15 / 540 }')" '
  /^set xrange \[/ { s = $3; gsub(/[\[\]]/, "", s); split(s, r, ":"); x0 = r[1]; x1 = r[2] }
  /^set yrange \[/ { s = $3; gsub(/[\[\]]/, "", s); split(s, r, ":"); y0 = r[1]; y1 = r[2] }
  /^set label / {
    match($0, /'\''[^'\'']*'\''/); t = substr($0, RSTART + 1, RLENGTH - 2)
    s = substr($0, RSTART + RLENGTH); sub(/^ at /, "", s); split(s, a, /[ ,]+/)
    n++; X[n] = a[1]; Y[n] = a[2]; o = a[4]; split(o, d, ","); DX[n] = d[1]; DY[n] = d[2]
    R[n] = ($0 ~ / right /); L[n] = length(t); T[n] = t
  }
  END {
    bad = 0
    for (i = 1; i <= n; i++) {
      u = (X[i] - x0) / (x1 - x0) + DX[i] * cu; v = (Y[i] - y0) / (y1 - y0) + DY[i] * cv
      a0[i] = R[i] ? u - L[i] * cu : u; a1[i] = R[i] ? u : u + L[i] * cu
      b0[i] = v - 0.5 * cv; b1[i] = v + 0.5 * cv
      if (a0[i] < 0 || a1[i] > 1 || b0[i] < 0 || b1[i] > 1) { print "# off the axes: " T[i]; bad = 1 }
      for (j = 1; j < i; j++)
        if (a0[i] < a1[j] && a0[j] < a1[i] && b0[i] < b1[j] && b0[j] < b1[i]) { print "# overlap: " T[i] " " T[j]; bad = 1 }
    }
    exit !(n >= 5 && x1 > x0 && y1 > y0 && !bad)
  }' "$gp" > boxes.txt
rc=$?
cat boxes.txt
ok $rc "ab-7: the names of HB 2 and LP 3 (0.0004 apart in Da), and the others, apart and inside the axes"
grep -q "^set key outside" "$gp"
ok $? "ab-7: the legend outside the axes"
tap_end

#!/bin/sh
# test/regress/draw.sh — the PNGs whirl draws itself (drivers/gp_draw.c),
# checked against the tables they show by an independent decoder
# (test/regress/draw_check.py: CRCs, zlib's Adler-32, the palette; the
# frame found in the pixels): sfd response's response.png (the folds of
# special.tsv green where their (Omega, eps) falls in the frame, stable
# points of branches.tsv blue, the dashed unstable ones near blue, the red
# region lines at the folds' speeds, text above and below the frame) and
# multipliers.png (a log axis: each branch's max |multiplier| on its
# colour), and whirl plot overlay's picture of two responses (automatic
# ranges, each run on its colour; the same check passes on gnuplot's
# picture of the same script), and rotor response's (a data file and
# expressions in using; likewise against gnuplot's).  Drawn with no gnuplot at all, so no
# gnuplot drew them; the
# pictures whirl does not draw (sfd basins), WHIRL_DRAW=gnuplot, and a font
# that cannot be read still come from gnuplot (an RGB PNG, not a palette).
# SPDX-License-Identifier: BSD-3-Clause
name=draw
. "${top_srcdir:-.}/test/regress/tap.sh"
PY=/usr/bin/python3
check="$top_srcdir/test/regress/draw_check.py"
if ! [ -x "$PY" ] || ! "$PY" -c 'import zlib' 2> /dev/null; then
  echo "1..0 # SKIP Debian's python3 with zlib is needed to decode the PNGs"
  exit 0
fi
if ! grep -q '^#define WHIRL_HAVE_FREETYPE 1' "$top_builddir/config.h" ||
   grep -q '^#define WHIRL_FONT ""' "$top_builddir/config.h"; then
  echo "1..0 # SKIP whirl draws no PNG itself (built without FreeType or a font)"
  exit 0
fi

WHIRL_GNUPLOT="$tmp/no/such/gnuplot" "$WHIRL" sfd response --out r > r.stdout 2> r.stderr
rc=$?
info=$("$PY" "$check" info r/response.png 2>&1)
[ $rc -eq 0 ] && [ "$info" = "1100 750 3" ] && ! grep -q "skipped" r.stderr
ok $? "sfd response without gnuplot: exit $rc, response.png '$info' (1100 750, a palette), nothing skipped $(head -c 300 r.stderr)"

# The script's ranges: the picture maps the data through them
xr=$(sed -n 's/^set xrange \[\(.*\):\(.*\)\]$/\1 \2/p' r/response.gp)
yr=$(sed -n 's/^set yrange \[\(.*\):\(.*\)\]$/\1 \2/p' r/response.gp)
[ "$xr" = "0 20" ] && [ "$yr" = "0 1" ]
ok $? "response.gp's ranges: x '$xr', y '$yr'"

# folds: green discs
awk -F'\t' 'NR > 1 && $1 == "LP" {print $4, $5}' r/special.tsv > lp.txt
got=$("$PY" "$check" points r/response.png 0 20 0 1 0 '#2ca02c' 2 lp.txt)
[ "$got" = "found 3 of 3" ]
ok $? "the three folds drawn green where special.tsv puts them: $got"

# stable points (every 5th, away from the folds' green discs, 0.2 in
# Omega and 0.03 in eps): the blue curve
awk -F'\t' 'FNR == NR {split($0, a, " "); lo[NR] = a[1]; le[NR] = a[2]; nl = NR; next}
  FNR > 1 && $1 !~ /^#/ && $10 == 1 && FNR % 5 == 0 {
    for (k = 1; k <= nl; k++)
      if (($5 - lo[k])^2 < 0.04 && ($6 - le[k])^2 < 0.0009) next
    print $5, $6
  }' lp.txt r/branches.tsv > stable.txt
got=$("$PY" "$check" points r/response.png 0 20 0 1 0 '#1f4e9c' 2 stable.txt)
tot=$(echo "$got" | awk '{print $4}') hit=$(echo "$got" | awk '{print $2}')
[ "$tot" -ge 40 ] && [ $((hit * 100)) -ge $((tot * 97)) ]
ok $? "stable points of branches.tsv on the blue curve: $got"

# unstable points: dashed, so within a dash's gap of blue
awk -F'\t' 'NR > 1 && $1 !~ /^#/ && $10 == 0 && NR % 3 == 0 {print $5, $6}' r/branches.tsv > unstable.txt
got=$("$PY" "$check" points r/response.png 0 20 0 1 0 '#1f4e9c' 6 unstable.txt)
tot=$(echo "$got" | awk '{print $4}') hit=$(echo "$got" | awk '{print $2}')
[ "$tot" -ge 20 ] && [ $((hit * 100)) -ge $((tot * 95)) ]
ok $? "unstable points near the dashed blue curve: $got"

# the red region lines: at each fold's speed, at heights no curve crosses
# there (eps 0.04 to 0.24)
awk '{for (k = 1; k <= 6; k++) print $1, k * 0.04}' lp.txt > red.txt
got=$("$PY" "$check" points r/response.png 0 20 0 1 0 '#d62728' 5 red.txt)
[ "$got" = "found 18 of 18" ]
ok $? "the dashed red lines at the folds' speeds: $got"

# text: the title above the frame, the tick labels and x label below it
fr=$("$PY" "$check" frame r/response.png)
set -- $fr
L=$1 R=$2 T=$3 B=$4
above=$("$PY" "$check" dark r/response.png "$L" 0 "$R" "$T")
below=$("$PY" "$check" dark r/response.png "$L" $((B + 3)) "$R" 750)
left=$("$PY" "$check" dark r/response.png 0 "$T" $((L - 2)) "$B")
[ "$above" -gt 200 ] && [ "$below" -gt 200 ] && [ "$left" -gt 200 ] &&
  [ "$L" -gt 40 ] && [ "$R" -lt 900 ] && [ "$T" -gt 40 ] && [ "$B" -lt 720 ]
ok $? "frame $fr (the key to its right); dark text pixels above $above, below $below, left $left"

# multipliers.png: a log axis from 1e-3 to 10 (the script's range, its top
# from the data: the next decade)
awk -F'\t' 'NR > 1 && $1 == 1 && $12 >= 0.001 && NR % 4 == 0 {print $5, $12}' r/branches.tsv > b1.txt
awk -F'\t' 'NR > 1 && $1 == 2 && $12 >= 0.001 && NR % 4 == 0 {print $5, $12}' r/branches.tsv > b2.txt
g1=$("$PY" "$check" points r/multipliers.png 0 20 0.001 10 1 '#9400d3' 2 b1.txt)
g2=$("$PY" "$check" points r/multipliers.png 0 20 0.001 10 1 '#009e73' 2 b2.txt)
t1=$(echo "$g1" | awk '{print $4}') h1=$(echo "$g1" | awk '{print $2}')
t2=$(echo "$g2" | awk '{print $4}') h2=$(echo "$g2" | awk '{print $2}')
[ "$t1" -ge 20 ] && [ "$t2" -ge 20 ] && [ $((h1 * 100)) -ge $((t1 * 95)) ] &&
  [ $((h2 * 100)) -ge $((t2 * 95)) ]
ok $? "multipliers.png on a log axis: branch 1 $g1 (purple), branch 2 $g2 (green)"

# the file is the same when drawn again (nothing depends on the run)
WHIRL_GNUPLOT="$tmp/no/such/gnuplot" "$WHIRL" sfd response --out r2 --quiet > /dev/null 2>&1
cmp -s r/response.png r2/response.png && cmp -s r/multipliers.png r2/multipliers.png
ok $? "drawn twice, byte-identical PNGs"

# whirl plot overlay of two responses (delta 0.1 and 0.3): automatic ranges
# (gnuplot's: x from the data 0.01..20 with a step of 2 to [0:20], y from 0
# to the data's 0.953 with a step of 0.1 to 1), each run's stable points on
# its colour; the same check on gnuplot's picture of the same script below
# says the ranges are gnuplot's
WHIRL_GNUPLOT="$tmp/no/such/gnuplot" "$WHIRL" sfd response --delta 0.1 --out d1 --no-plot --quiet > /dev/null 2>&1
overlay_ok() { # PNG: both runs' stable points (every 7th) on their colours
  awk -F'\t' 'NR > 1 && $1 !~ /^#/ && $10 == 1 && NR % 7 == 0 {print $5, $6}' d1/branches.tsv > s1.txt
  awk -F'\t' 'NR > 1 && $1 !~ /^#/ && $10 == 1 && NR % 7 == 0 && $6 < 0.9 {print $5, $6}' r/branches.tsv > s3.txt
  o1=$("$PY" "$check" points "$1" 0 20 0 1 0 '#1f77b4' 2 s1.txt)
  o3=$("$PY" "$check" points "$1" 0 20 0 1 0 '#d62728' 2 s3.txt)
  t1=$(echo "$o1" | awk '{print $4}') h1=$(echo "$o1" | awk '{print $2}')
  t3=$(echo "$o3" | awk '{print $4}') h3=$(echo "$o3" | awk '{print $2}')
  [ "$t1" -ge 20 ] && [ "$t3" -ge 20 ] && [ $((h1 * 100)) -ge $((t1 * 93)) ] &&
    [ $((h3 * 100)) -ge $((t3 * 93)) ]
}
WHIRL_GNUPLOT="$tmp/no/such/gnuplot" "$WHIRL" plot overlay d1 r --out ov --quiet > /dev/null 2>&1
info=$("$PY" "$check" info ov/overlay.png 2>&1)
[ "$info" = "1100 700 3" ] && overlay_ok ov/overlay.png
ok $? "plot overlay drawn by whirl ($info): delta 0.1 $o1 (blue), delta 0.3 $o3 (red)"

# rotor response (a data file, expressions in using: x the speed in rev/min,
# y 1e3 times the amplitude): automatic ranges by gnuplot's rule (a step of
# 1, 2 or 5 times a power of ten, about 20 / mantissa a decade; the ends
# extended to a step), computed here; the points on the grey line of
# 'stability not computed'
"$WHIRL" rotor response "$top_srcdir/examples/rotor/rigid-limit.rotor" --harmonics 3 \
  --stability off --out rr --quiet > /dev/null 2> rr.err
range() { # column COL (times SCALE) of rr/branches.tsv: lo hi, gnuplot's
  awk -F'\t' -v c="$1" -v k="$2" 'NR > 1 && $1 !~ /^#/ && NF > 1 {
      v = $c * k; if (n++ == 0 || v < lo) lo = v; if (n == 1 || v > hi) hi = v }
    END { r = hi - lo; p = exp(log(10) * int(log(r) / log(10) - (r < 1)))
      x = r / p; s = 20 / x
      t = s > 40 ? 0.05 : s > 20 ? 0.1 : s > 10 ? 0.2 : s > 4 ? 0.5 : s > 2 ? 1 : s > 0.5 ? 2 : int(x + 0.999999)
      t *= p; a = int(lo / t + 1e-9) * t; if (a > lo) a -= t
      b = int(hi / t - 1e-9) * t; if (b < hi) b += t; print a, b }' rr/branches.tsv
}
rx=$(range 4 1) ry=$(range 6 1000)
awk -F'\t' 'NR > 1 && $1 !~ /^#/ && NF > 1 && NR % 3 == 0 { print $4, 1000 * $6 }' rr/branches.tsv > rr.txt
rotor_ok() { # PNG
  # shellcheck disable=SC2086 # the ranges: two numbers each
  got=$("$PY" "$check" points "$1" $rx $ry 0 '#777777' 2 rr.txt)
  tot=$(echo "$got" | awk '{print $4}') hit=$(echo "$got" | awk '{print $2}')
  [ "$tot" -ge 20 ] && [ $((hit * 100)) -ge $((tot * 95)) ]
}
info=$("$PY" "$check" info rr/response.png 2>&1)
[ "$info" = "1100 750 3" ] && rotor_ok rr/response.png
ok $? "rotor response drawn by whirl ($info; x $rx, y $ry): $got $(head -c 200 rr.err)"

GNUPLOT=${WHIRL_GNUPLOT:-gnuplot}
if command -v "$GNUPLOT" > /dev/null 2>&1; then
  (cd rr && rm -f response.png && "$GNUPLOT" response.gp > /dev/null 2>&1)
  info=$("$PY" "$check" info rr/response.png 2>&1)
  [ "$info" = "1100 750 2" ] && rotor_ok rr/response.png
  ok $? "the same script drawn by gnuplot ($info): the same ranges, $got"
  WHIRL_DRAW=gnuplot "$WHIRL" plot overlay d1 r --out ovg --quiet > /dev/null 2>&1
  info=$("$PY" "$check" info ovg/overlay.png 2>&1)
  [ "$info" = "1100 700 2" ] && overlay_ok ovg/overlay.png
  ok $? "the same overlay by gnuplot ($info): the same ranges, delta 0.1 $o1, delta 0.3 $o3"
  WHIRL_DRAW=gnuplot "$WHIRL" sfd response --out g --quiet > /dev/null 2>&1
  info=$("$PY" "$check" info g/response.png 2>&1)
  [ "$info" = "1100 750 2" ]
  ok $? "WHIRL_DRAW=gnuplot: gnuplot's response.png ($info: RGB)"
  WHIRL_FONT="$tmp/no/such.ttf" "$WHIRL" sfd response --out nf --quiet > /dev/null 2> nf.stderr
  rc=$?
  info=$("$PY" "$check" info nf/response.png 2>&1)
  [ $rc -eq 0 ] && [ "$info" = "1100 750 2" ] && ! [ -s nf.stderr ]
  ok $? "a font that cannot be read: gnuplot draws, silently, exit $rc ($info)"
  "$WHIRL" sfd basins --omega 1.78 --points 9 --periods 20 --out b --quiet > /dev/null 2>&1
  info=$("$PY" "$check" info b/basins.png 2>&1)
  [ "$info" != "${info#* * 2}" ] || [ "$info" != "${info#* * 6}" ]
  ok $? "sfd basins (an image plot, not drawn by whirl): gnuplot's basins.png ($info)"
else
  ok 0 "# SKIP gnuplot is not installed (rotor response)"
  ok 0 "# SKIP gnuplot is not installed (overlay)"
  ok 0 "# SKIP gnuplot is not installed (WHIRL_DRAW=gnuplot)"
  ok 0 "# SKIP gnuplot is not installed (font)"
  ok 0 "# SKIP gnuplot is not installed (basins)"
fi
tap_end

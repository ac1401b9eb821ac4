#!/bin/sh
# test/regress/restart_lp.sh — a run restarted at an LP of equilibria
# (IRS = LP1, ISW = 1, the label's own parameter) goes on along the stored
# tangent, as AUTO does, in either direction (the sign of DS), and does not
# label the fold it starts from again.  Before, the start's Newton at fixed
# parameter met the singular F_x of the fold and the run failed.  Model:
# AUTO's cusp demo x' = mu + lambda x - x^3 at lambda = 1, whose folds are
# at mu = +-2/(3 sqrt 3) = +-0.384900179 (closed form).  The sign of DS
# is relative to the first run's (AUTO's convention: the stored tangent
# times DS is the motion): after a first run with DS < 0, DS > 0 goes back.
# AUTO-07p 0.9.2 on its cusp demo (DS = -0.01 to LP1 at mu = -0.3849, then
# LP1 restarted): DS = +0.01 back to the LP at mu = +0.3849 and on to
# mu = -2; DS = -0.01 on to mu = +2 with no LP; neither labels LP1 again.
# SPDX-License-Identifier: BSD-3-Clause
name=restart_lp
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
ex="$top_srcdir/examples/auto"
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o "$tmp/cusp.so" "$ex/cusp.c" -lm
ok $? "cusp plug-in builds"
cp "$ex/cusp-1.whirl" "$tmp/"
(cd "$tmp" && "$WHIRL" run cusp-1.whirl --out=first --quiet > /dev/null 2>&1)
ok $? "first run: the fold LP1 at mu = $(awk '$1 == "LP" { print $8 }' "$tmp/first/run.log")"
fold=0.384900179459750  # 2 / (3 sqrt 3)
for sign in + -; do
  sed -e '/^PAR /d' -e '/^U /d' -e "s/^DS .*/DS = ${sign}0.01/" "$ex/cusp-1.whirl" > "$tmp/restart$sign.whirl"
  printf 'S = first\nIRS = LP1\n' >> "$tmp/restart$sign.whirl"
  (cd "$tmp" && "$WHIRL" run "restart$sign.whirl" --out="r$sign" --quiet > /dev/null 2> "r$sign.err")
  ok $? "restart at LP1 with DS ${sign}0.01: runs ($(head -1 "$tmp/r$sign.err"))"
  lps=$(awk '$1 == "LP" { print $5 ":" $8 }' "$tmp/r$sign/run.log" 2>/dev/null | tr '\n' ' ')
  early=$(awk '$1 == "LP" && $5 <= 2' "$tmp/r$sign/run.log" 2>/dev/null | wc -l)
  [ -f "$tmp/r$sign/run.log" ] && [ "$early" -eq 0 ]
  ok $? "DS ${sign}0.01: the starting fold is not labelled again (LPs at PT:mu ${lps:-none})"
done
# forward: on past the fold, as the first run went (no other fold before
# mu = -2); backward: back along the middle branch to the other fold
[ -z "$(awk '$1 == "LP"' "$tmp/r+/run.log" 2>/dev/null)" ] && grep -q 'UZ .* mu = -2$' "$tmp/r+/run.log"
ok $? "DS +0.01: along the stored tangent, on to mu = -2"
mu=$(awk '$1 == "LP" { print $8; exit }' "$tmp/r-/run.log" 2>/dev/null)
awk -v m="${mu:-0}" -v f="$fold" 'BEGIN { d = m + f; exit !(d < 1e-8 && d > -1e-8) }'
ok $? "DS -0.01: back to the other fold, mu = ${mu:-none} (closed form -$fold)"
# the first run with DS < 0 (to the fold at mu = -fold): AUTO's case
sed -e "s/^DS .*/DS = -0.01/" "$ex/cusp-1.whirl" > "$tmp/neg.whirl"
(cd "$tmp" && "$WHIRL" run neg.whirl --out=neg --quiet > /dev/null 2>&1)
ok $? "first run with DS = -0.01: the fold LP1 at mu = $(awk '$1 == "LP" { print $8 }' "$tmp/neg/run.log")"
for sign in + -; do
  sed -e '/^PAR /d' -e '/^U /d' -e "s/^DS .*/DS = ${sign}0.01/" "$ex/cusp-1.whirl" > "$tmp/rn$sign.whirl"
  printf 'S = neg\nIRS = LP1\n' >> "$tmp/rn$sign.whirl"
  (cd "$tmp" && "$WHIRL" run "rn$sign.whirl" --out="rn$sign" --quiet > /dev/null 2>&1)
done
mu=$(awk '$1 == "LP" { print $8 }' "$tmp/rn+/run.log" 2>/dev/null | tr '\n' ' ')
awk -v m="${mu:-0}" -v f="$fold" 'BEGIN { d = m - f; exit !(d < 1e-8 && d > -1e-8) }' && grep -q 'UZ .* mu = -2$' "$tmp/rn+/run.log"
ok $? "after DS < 0, DS = +0.01 goes back: one LP at mu = ${mu:-none} (AUTO: +0.384900), on to mu = -2 (AUTO too)"
[ -z "$(awk '$1 == "LP"' "$tmp/rn-/run.log" 2>/dev/null)" ] && grep -q 'UZ .* mu = 2$' "$tmp/rn-/run.log"
ok $? "after DS < 0, DS = -0.01 goes on to mu = 2 with no LP (AUTO too)"
tap_end

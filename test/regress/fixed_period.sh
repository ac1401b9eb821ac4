#!/bin/sh
# test/regress/fixed_period.sh — periodic orbits at a fixed period (AUTO's
# IPS = 2 with two parameters in ICP and not PERIOD): the label's period
# kept, ICP(2) free in its place.  Before, ICP(2) was ignored and the period
# left free (whirl auto's c.chu.4 and c.chu.5 continued the wrong family,
# issue 18).  Model: the Hopf normal form with a twist, r' = r (mu - r^2),
# theta' = 1 + b r^2, whose orbits r^2 = mu have the period
# 2 pi / (1 + b mu) (closed form): from the orbit at mu = 0.5, b = 0.5
# (T0 = 2 pi / 1.25), the fixed-period family has b = (1.25 - 1) / mu.
# SPDX-License-Identifier: BSD-3-Clause
name=fixed_period
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o "$tmp/twist.so" "$top_srcdir/test/regress/twist.c" -lm
ok $? "twist plug-in builds"
printf 'model = twist.so\nIPS = 1\nICP = [mu]\nISP = 2\nDS = 0.01\nDSMAX = 0.05\nNMX = 200\nUZSTOP = {mu: [0.5]}\n' > "$tmp/eq.whirl"
printf 'model = twist.so\nIPS = 2\nICP = [mu, PERIOD]\nS = eq.out\nIRS = HB1\nNTST = 20\nDS = 0.01\nDSMAX = 0.1\nNMX = 300\nUZSTOP = {mu: [0.5]}\n' > "$tmp/po.whirl"
(cd "$tmp" && "$WHIRL" run eq.whirl --no-plot --quiet > /dev/null 2>&1 &&
  "$WHIRL" run po.whirl --no-plot --quiet > /dev/null 2> po.err)
ok $? "orbits with a free period from the Hopf point at mu = 0 ($(head -1 "$tmp/po.err"))"
# ISP = 0 disables "the computation of Floquet multipliers" (AUTO-07p
# manual), so the orbits' stability is unknown (before, whirl computed the
# multipliers anyway); with ISP = 1 they are computed (the manual: PD and
# TR are not detected, "however, Floquet multipliers are computed"), and
# the branch is stable, as with ISP = 2
for isp in 0 1; do
  printf 'model = twist.so\nIPS = 2\nICP = [mu, PERIOD]\nS = eq.out\nIRS = HB1\nNTST = 20\nISP = %s\nDS = 0.01\nDSMAX = 0.1\nNMX = 300\nUZSTOP = {mu: [0.5]}\n' "$isp" > "$tmp/po$isp.whirl"
  (cd "$tmp" && "$WHIRL" run "po$isp.whirl" --no-plot --quiet > /dev/null 2> "po$isp.err")
  ok $? "orbits with ISP = $isp ($(head -1 "$tmp/po$isp.err"))"
done
stab() {
  awk -F '\t' -v want="$2" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $3 != "EP" { n++; if ($c["stable"] != want) bad++ }
    END { printf "%d points, %d with stable != %s", n, bad, want; exit !(n > 5 && bad == 0) }' "$tmp/$1/branches.tsv"
}
msg=$(stab po0.out -1)
ok $? "ISP = 0: the orbits' stability unknown, -1 ($msg)"
msg=$(stab po1.out 1)
ok $? "ISP = 1: the same orbits stable ($msg)"
msg=$(stab po.out 1)
ok $? "ISP = 2 (the default): stable ($msg)"
# $1: columns mu, b, period of the UZ at mu = $2 in $1/branches.tsv, then
# b and the period against the closed forms, to 1e-7
uz() {
  awk -F '\t' -v m="$2" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $3 == "UZ" && $c["mu"] + 0 == m { n++; b = $c["b"]; T = $c["period"] }
    END { pi = 4 * atan2(1, 1); eb = 0.25 / m; eT = 2 * pi / 1.25
          printf "b %.10g (closed form %.10g), period %.10g (%.10g)", b, eb, T, eT
          exit !(n == 1 && (b - eb) ^ 2 < 1e-14 && (T - eT) ^ 2 < 1e-14) }' "$tmp/$1/branches.tsv" 2>/dev/null
}
for sign in + -; do
  printf 'model = twist.so\nIPS = 2\nICP = [mu, b]\nS = po.out\nIRS = UZ1\nNTST = 20\nISP = 2\nDS = %s0.01\nDSMAX = 0.05\nNMX = 400\nUZR = {mu: [1, 0.25]}\nUZSTOP = {mu: [1, 0.25]}\n' "$sign" > "$tmp/fx$sign.whirl"
  (cd "$tmp" && "$WHIRL" run "fx$sign.whirl" --no-plot --quiet > /dev/null 2> "fx$sign.err")
  ok $? "fixed period from mu = 0.5, DS ${sign}0.01 ($(head -1 "$tmp/fx$sign.err"))"
  m=1; [ "$sign" = - ] && m=0.25
  msg=$(uz "fx$sign.out" $m)
  ok $? "DS ${sign}0.01: at mu = $m, $msg"
  # the period column constant, every orbit stable (radial multiplier
  # exp(-2 mu T) < 1)
  awk -F '\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    { d = $c["period"] - 8 * atan2(1, 1) / 1.25; if (d * d > 1e-14 || $c["stable"] != 1) bad++; n++ }
    END { exit !(n > 5 && bad == 0) }' "$tmp/fx$sign.out/branches.tsv" 2>/dev/null
  ok $? "DS ${sign}0.01: every point at the fixed period, stable"
done
# the labels hold the orbit as any other: a restart with the period free
# from the fixed-period UZ at mu = 1 (b = 0.25) goes on at b = 0.25
printf 'model = twist.so\nIPS = 2\nICP = [mu, PERIOD]\nS = fx+.out\nIRS = UZ1\nNTST = 20\nDS = -0.01\nDSMAX = 0.05\nNMX = 300\nUZSTOP = {mu: [0.5]}\n' > "$tmp/back.whirl"
(cd "$tmp" && "$WHIRL" run back.whirl --no-plot --quiet > /dev/null 2> back.err)
ok $? "free period again from the fixed-period label ($(head -1 "$tmp/back.err"))"
T=$(awk -F '\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $3 == "UZ" { print $c["period"], $c["b"] }' "$tmp/back.out/branches.tsv" 2>/dev/null)
# b kept at the label's value, 0.25 to the tolerance the label converged to
echo "$T" | awk '{ e = 8 * atan2(1, 1) / (1 + 0.25 * 0.5); exit !(NF == 2 && ($1 - e) ^ 2 < 1e-14 && ($2 - 0.25) ^ 2 < 1e-18) }'
ok $? "at mu = 0.5, b = 0.25: period 2 pi / 1.125 ($T)"
# a fixed period from a Hopf point has no period to keep: said
printf 'model = twist.so\nIPS = 2\nICP = [mu, b]\nS = eq.out\nIRS = HB1\nNTST = 20\nDS = 0.01\nNMX = 10\n' > "$tmp/hb.whirl"
(cd "$tmp" && "$WHIRL" run hb.whirl --no-plot --quiet > /dev/null 2> hb.err)
st=$?
[ "$st" -eq 2 ] && grep -q "fixed period" "$tmp/hb.err"
ok $? "a fixed period from an HB label: exit 2 with a message (exit $st: $(head -1 "$tmp/hb.err"))"
tap_end

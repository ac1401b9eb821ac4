#!/bin/sh
# test/regress/irc_published.sh — the isolated resonance curve (isola) of
# examples/isolated-resonance (a Duffing oscillator with the nonlinear damper
# c1 + c3 x^2 + c5 x^4, the class of Habib, Cirillo & Kerschen, Nonlinear
# Dyn. 93 (2018) 979-994; doc/isolated-resonance.md) by harmonic balance,
# checked against two independent references:
#   (1) the closed form of the first-harmonic balance (doc §2, computed here
#       in awk: the response curve a^2 [(K - W^2)^2 + W^2 D^2] = F^2 solved
#       for W^2, K = 1 + 3/4 k3 a^2, D = c1 + c3 a^2/4 + c5 a^4/8): `whirl run`
#       with NHB = 1 solves exactly these equations, so its folds, its user
#       points and the isola's birth (IS) and merging (MG) on the fold locus
#       in (Omega, F) — at the minimum and the maximum of a D sqrt(K - D^2/4),
#       Habib et al.'s result — must equal the closed form to 1e-8; with
#       NHB = 12 (irc.whirl as shipped) they differ by the higher harmonics,
#       reported and bounded;
#   (2) time integration (DOPRI5 through the library: examples/isolated-
#       resonance/settle.c, built here against the staged install): from the
#       t = 0 state of every labelled response, a stable one stays (state
#       and amplitude to 1e-6 after 300 periods), an unstable one leaves; a
#       perturbed start returns; at F = 0.045, below the closed form's onset,
#       the HBM isola is still there and the integration confirms it.
# And main.whirl, the branch traced from low frequency, has no fold and
# stays below the isola: the isola is not reached from the start branch;
# discover.whirl finds it without a start (harmonic balance and
# collocation), with the folds of the hand-started isola.
# SPDX-License-Identifier: BSD-3-Clause
# shellcheck disable=SC2046,SC2086 # set -- $(...): numbers split into words on purpose
# shellcheck disable=SC2034 # name is read by tap.sh
name=irc
top_builddir=${top_builddir:-.}
case $top_builddir in /*) ;; *) top_builddir="$(pwd)/$top_builddir" ;; esac  # stage.sh, after tap.sh's cd
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
set -- $CC  # CC may carry flags
command -v "$1" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler ($CC)"; exit 77; }
ex="$top_srcdir/examples/isolated-resonance"
diag() { sed 's/^/# /' "$@"; }

# ---- the plug-in (in-tree headers) and the integrator (staged library) -----
cp "$ex/irc.c" "$ex/settle.c" "$ex/irc.whirl" "$ex/main.whirl" "$ex/discover.whirl" . || exit 1
$CC -std=c11 -shared -fPIC ${CFLAGS:-} -I"$top_srcdir/lib" -o irc.so irc.c ${LDFLAGS:-} -lm > cc.log 2>&1
rc=$?
ok $rc "irc.so (examples/isolated-resonance/irc.c) builds as a plug-in"
. "$top_srcdir/test/regress/stage.sh"
$CC -std=c11 ${CFLAGS:-} -I"$incdir" -o settle settle.c irc.c ${LDFLAGS:-} \
  -L"$stage$libdir" -lwhirl -lm >> cc.log 2>&1
rc2=$?
ok $rc2 "settle (examples/isolated-resonance/settle.c) builds against the staged libwhirl"
if [ $rc -ne 0 ] || [ $rc2 -ne 0 ]; then diag cc.log; echo "Bail out! cannot build"; exit 1; fi
settle() { LD_LIBRARY_PATH="$stage$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ./settle "$@"; }
run() { "$WHIRL" run "$@" --quiet 2> run.err || { diag run.err; return 1; }; }

# ---- closed form of the first-harmonic balance (doc §2) ---------------------
# cf WHAT [F] [W]: prints the requested numbers, full precision.
#   ext: aM Gmax am Gmin      (local max and min of G = a D sqrt(K - D^2/4))
#   folds F: wL aL wR aR       (the isola's folds: min W- and max W+)
#   amp F W: the amplitudes a with a^2 [(K - W^2)^2 + W^2 D^2] = F^2
#   peak F: wA aA             (the main branch's top, below aM)
cf() {
  awk -v what="$1" -v F="${2:-0}" -v W="${3:-0}" \
      -v c1=0.1 -v c3=-0.175 -v c5=0.05 -v k3=0.05 '
  function D(a) { return c1 + c3*a*a/4 + c5*a^4/8 }
  function K(a) { return 1 + 0.75*k3*a*a }
  function G(a) { return a*D(a)*sqrt(K(a) - D(a)^2/4) }
  function dG(a) { return (G(a + 1e-6) - G(a - 1e-6)) / 2e-6 }
  function h(a) { return a*a*((K(a) - W*W)^2 + W*W*D(a)^2) - F*F }
  function g(a) { return G(a) - F }
  function bis(f, lo, hi,   m, i, flo) {   # f: 1 dG, 2 h, 3 g
    flo = ev(f, lo)
    for (i = 0; i < 200 && hi - lo > 1e-15; i++) {
      m = (lo + hi) / 2
      if ((ev(f, m) < 0) == (flo < 0)) { lo = m; flo = ev(f, m) } else hi = m
    }
    return (lo + hi) / 2
  }
  function ev(f, a) { return f == 1 ? dG(a) : f == 2 ? h(a) : g(a) }
  function w(a, s,   b, c) {           # W+ (s = 1) or W- (s = -1), or -1
    b = 2*K(a) - D(a)^2; c = K(a)^2 - F*F/(a*a)
    if (b*b - 4*c < 0 || b + s*sqrt(b*b - 4*c) < 0) return -1
    return sqrt((b + s*sqrt(b*b - 4*c)) / 2)
  }
  function gold(lo, hi, s,   r, x1, x2, i) {  # extremum of s*W_s: min of -s*w
    r = (sqrt(5) - 1) / 2
    for (i = 0; i < 200 && hi - lo > 1e-14; i++) {
      x1 = hi - r*(hi - lo); x2 = lo + r*(hi - lo)
      if (-s*w(x1, s) < -s*w(x2, s)) hi = x2; else lo = x1
    }
    return (lo + hi) / 2
  }
  function roots(f, lo, hi, n,   k, a0, a1, c) {  # sign changes on a grid
    c = 0
    for (k = 0; k < n; k++) {
      a0 = lo + (hi - lo)*k/n; a1 = lo + (hi - lo)*(k + 1)/n
      if ((ev(f, a0) < 0) != (ev(f, a1) < 0)) R[++c] = bis(f, a0, a1)
    }
    return c
  }
  BEGIN {
    CONVFMT = OFMT = "%.15g"
    m = roots(1, 0.01, 4, 4000); aM = R[1]; am = R[2]
    if (what == "ext") { printf "%.15g %.15g %.15g %.15g\n", aM, G(aM), am, G(am); exit }
    if (what == "peak") { a = bis(3, 1e-9, aM); printf "%.15g %.15g\n", sqrt(K(a) - D(a)^2/2), a; exit }
    if (what == "amp") { m = roots(2, 1e-6, 4, 40000); for (k = 1; k <= m; k++) printf "%.15g%s", R[k], k < m ? " " : "\n"; exit }
    aB = bis(3, aM, am); aC = bis(3, am, 4)        # the isola: aB <= a <= aC
    aL = gold(aB, aC, -1); aR = gold(aB, aC, 1)
    printf "%.15g %.15g %.15g %.15g\n", w(aL, -1), aL, w(aR, 1), aR
  }'
}
# x(0), v(0) of label LAB in DIR/solutions: c + sum of the cosine coefficients
state0() {
  sed -n "/^LAB $2 /,/^END/p" "$1/solutions" | awk '/^X/ { L = (NF - 1) / 2
    x = $2; for (k = 3; k <= L + 1; k += 2) x += $k
    v = $(L + 2); for (k = L + 3; k <= 2*L + 1; k += 2) v += $k
    printf "%.17g %.17g\n", x, v }'
}
# the rows of type TY in DIR/branches.tsv: LAB Omega F MAXx STAB
rows() { awk -F'\t' -v ty="$2" '$3 == ty { print $4, $5, $6, $13, $15 }' "$1/branches.tsv"; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { e = a - b; if (e < 0) e = -e; exit !(e <= t) }'; }

set -- $(cf ext)
aM=$1 Gmax=$2 am=$3 Gmin=$4
echo "# closed form: G max $Gmax at a = $aM (merging), G min $Gmin at a = $am (birth)"
set -- $(cf folds 0.055)
wL=$1 aL=$2 wR=$3 aR=$4
echo "# closed form, F = 0.055: isola folds W = $wL (a = $aL), W = $wR (a = $aR)"
near "$Gmin" 0.045418 5e-6 && near "$Gmax" 0.063651 5e-6 && near "$wL" 1.03437 5e-5 && near "$wR" 1.07515 5e-5
ok $? "closed form: isola for $Gmin < F < $Gmax, folds at F = 0.055 as doc/isolated-resonance.md states"

# ---- NHB = 1: whirl's first-harmonic balance = the closed form --------------
run irc.whirl --NHB=1 --out=h1.out
ok $? "whirl run irc.whirl --NHB=1 exits 0"
rows h1.out LP > lp1
awk -v wL="$wL" -v aL="$aL" -v wR="$wR" -v aR="$aR" '
  { e1 = $2 - ($2 < 1.055 ? wL : wR); e2 = $4 - ($2 < 1.055 ? aL : aR); e1 = e1 < 0 ? -e1 : e1; e2 = e2 < 0 ? -e2 : e2
    printf "# NHB 1 LP: W = %s (closed form %.12g, error %.1e), MAX x %s (error %.1e)\n", $2, $2 < 1.055 ? wL : wR, e1, $4, e2
    if (e1 > 1e-8 || e2 > 1e-6) bad = 1; n++ } END { exit bad || n != 2 }' lp1
ok $? "NHB = 1: the isola's two folds at the closed form's W (1e-8) and amplitude (1e-6)"
rows h1.out UZ > uz1
bad=0 k=0
while read -r lab W F A S; do
  k=$((k + 1))
  hit=1
  for a in $(cf amp 0.055 "$W"); do near "$A" "$a" 1e-8 && hit=0; done
  [ $hit -eq 0 ] || { bad=1; echo "# UZ $lab W = $W: MAX x $A is none of $(cf amp 0.055 "$W")"; }
done < uz1
[ $bad -eq 0 ] && [ $k -eq 6 ]
ok $? "NHB = 1: the $k user points (W = 1.05, 1.06, 1.07) have the closed form's amplitudes (1e-8)"

printf 'model = ./irc.so\nS = %s\nIRS = LP1\nISW = 2\nIPS = 2\nMETHOD = hbm\nNHB = %s\nICP = [Omega, F]\nDS = -0.002\nDSMAX = 0.005\nNMX = 3000\nRL0 = 0.8\nRL1 = 1.3\n' h1.out 1 > locus1.whirl
run locus1.whirl
ok $? "NHB = 1: the fold locus in (Omega, F) from the isola's first LP runs"
is1=$(rows locus1.out IS) mg1=$(rows locus1.out MG)
echo "# NHB 1 locus: IS $is1; MG $mg1"
set -- $is1 $mg1
[ $# -eq 10 ] && near "$3" "$Gmin" 1e-8 && near "$4" "$am" 1e-5 && near "$8" "$Gmax" 1e-8 && near "$9" "$aM" 1e-5
ok $? "NHB = 1: isola birth (IS) at F = min G, merging (MG) at F = max G (1e-8; amplitudes 1e-5)"

# ---- NHB = 12 (irc.whirl as shipped) ---------------------------------------
run irc.whirl --out=irc.out
ok $? "whirl run irc.whirl exits 0"
grep -q 'branch closed on itself' irc.out/run.log && [ "$(rows irc.out LP | wc -l)" -eq 2 ] && [ "$(rows irc.out TR | wc -l)" -eq 1 ]
ok $? "the isola is a closed loop with 2 LP and 1 TR"
rows irc.out LP > lp12
awk -v wL="$wL" -v wR="$wR" '{ c = $2 < 1.055 ? wL : wR; e = $2 - c; e = e < 0 ? -e : e
  printf "# NHB 12 LP: W = %s, MAX x %s; closed form W %.6f (differs by %.1e)\n", $2, $4, c, e
  if (e > 2e-3) bad = 1 } END { exit bad }' lp12
ok $? "NHB = 12: the folds within 2e-3 of the first-harmonic closed form (higher harmonics)"
sed "s/NHB = 1/NHB = 12/; s/h1.out/irc.out/" locus1.whirl > locus12.whirl
run locus12.whirl
is12=$(rows locus12.out IS) mg12=$(rows locus12.out MG)
echo "# NHB 12 locus: IS $is12; MG $mg12"
set -- $is12 $mg12
[ $# -eq 10 ] && awk -v a="$3" -v b="$Gmin" -v c="$8" -v d="$Gmax" 'BEGIN {
  printf "# NHB 12: birth F = %s (closed form %.6f, %+.2f%%), merging F = %s (%.6f, %+.2f%%)\n", a, b, 100*(a/b - 1), c, d, 100*(c/d - 1)
  exit !(a < b && a > 0.97*b && c < d && c > 0.99*d) }'
ok $? "NHB = 12: birth and merging a little below the closed form (within 3% and 1%)"

# ---- time integration ------------------------------------------------------
rows irc.out UZ > uz12
bad=0 ns=0 nu=0
while read -r lab W F A S; do
  set -- $(state0 irc.out "$lab")
  x0=$1 v0=$2
  if [ "$S" = 1 ]; then
    set -- $(settle 300 "$x0" "$v0" Omega="$W" F="$F")
    ns=$((ns + 1))
    echo "# UZ $lab W = $W stable: HBM x0 $x0 v0 $v0 MAX x $A; DOPRI5 after 300 T: $1 $2 max $3"
    near "$1" "$x0" 1e-6 && near "$2" "$v0" 1e-6 && near "$3" "$A" 1e-6 || bad=1
  else
    set -- $(settle 2000 "$x0" "$v0" Omega="$W" F="$F")
    nu=$((nu + 1))
    echo "# UZ $lab W = $W unstable: MAX x $A; DOPRI5 after 2000 T: max $3"
    near "$3" "$A" 1e-2 && bad=1
  fi
done < uz12
[ $bad -eq 0 ] && [ $ns -ge 3 ] && [ $nu -ge 3 ]
ok $? "DOPRI5 from each HBM user point: the $ns stable ones stay (1e-6), the $nu unstable ones leave"
lab=$(awk '$2 == 1.06 && $5 == 1 { print $1; exit }' uz12)
A=$(awk -v l="$lab" '$1 == l { print $4 }' uz12)
set -- $(state0 irc.out "$lab")
set -- $(settle 2000 "$(awk -v x="$1" 'BEGIN { print 1.03*x }')" "$2" Omega=1.06)
echo "# perturbed start (x0 + 3%) at W = 1.06: max x $3 after 2000 T, HBM $A"
near "$3" "$A" 1e-6
ok $? "the stable isola response attracts: a start 3% off returns to it (1e-6)"

run irc.whirl --ICP="[F]" --PAR="{Omega: 1.0572}" --DS=-0.002 --DSMAX=0.005 --RL0=0.04 --RL1=0.07 --UZR="{F: [0.045]}" --out=f.out
lab=$(rows f.out UZ | awk '$5 == 1 { print $1; exit }')
A=$(rows f.out UZ | awk '$5 == 1 { print $4; exit }')
set -- $(state0 f.out "${lab:-0}")
set -- $(settle 2000 "${1:-0}" "${2:-0}" Omega=1.0572 F=0.045)
echo "# F = 0.045 < closed-form onset $Gmin: HBM isola response MAX x $A, DOPRI5 after 2000 T: max $3"
[ -n "$lab" ] && near "$3" "$A" 1e-6 && awk -v g="$Gmin" 'BEGIN { exit !(g > 0.045) }'
ok $? "F = 0.045, below the closed form's onset: the HBM isola exists and DOPRI5 confirms it (the closed form is first-order)"

# ---- the main branch -------------------------------------------------------
run main.whirl --out=main.out
ok $? "whirl run main.whirl exits 0"
top=$(awk -F'\t' 'NR > 1 && $13 > m { m = $13 } END { print m }' main.out/branches.tsv)
low=$(awk -F'\t' 'NR > 1 && (m == "" || $13 < m) { m = $13 } END { print m }' irc.out/branches.tsv)
echo "# main branch: no LP ($(rows main.out LP | wc -l)), top MAX x $top; the isola's lowest MAX x $low"
[ "$(rows main.out LP | wc -l)" -eq 0 ] && awk -v t="$top" -v l="$low" 'BEGIN { exit !(t < 0.7 && l > 1.3) }'
ok $? "main branch from low frequency: no fold, top below 0.7, the isola above 1.3 — not reached"
set -- $(cf peak 0.055)
wA=$1 aA=$2
run main.whirl --NHB=1 --UZR="{Omega: [$wA]}" --out=main1.out
A=$(rows main1.out UZ | awk '{ print $4 }')
echo "# NHB 1 main branch at the closed-form peak W = $wA: MAX x $A, closed form $aA"
near "${A:-0}" "$aA" 1e-8
ok $? "NHB = 1: the main branch's top has the closed form's amplitude (1e-8)"
A=$(rows main.out UZ | awk '{ print $4 }')
set -- $(settle 2000 0 0 Omega=1.06)
echo "# from rest at W = 1.06: DOPRI5 max x $3 after 2000 T; main branch MAX x $A"
near "$3" "${A:-0}" 1e-6
ok $? "from rest (W = 1.06) the integration settles on the main branch, not on the isola"

# ---- the isola found by the discovery step (discover.whirl: no start on it)
"$WHIRL" run discover.whirl > disc.txt 2> run.err || diag run.err
grep -q "^discovery: 2 branches, 1 of them isolated (closed or not connected to the start), 1 closed" disc.txt
ok $? "discover.whirl: the main branch and one closed isola: $(grep '^discovery' disc.txt)"
awk -F'\t' '$1 == 2 && $3 == "LP" { print $5 }' discover.out/branches.tsv | sort -g > disc.lp
awk -F'\t' '$3 == "LP" { print $5 }' irc.out/branches.tsv | sort -g > hand.lp
[ "$(wc -l < disc.lp)" -eq 2 ] && [ "$(wc -l < hand.lp)" -eq 2 ] &&
  paste disc.lp hand.lp | awk '{ d = $1 - $2; if (d < -1e-8 || d > 1e-8) bad = 1 } END { exit bad }'
ok $? "the discovered isola's folds $(tr '\n' ' ' < disc.lp)= those from the hand-made start $(tr '\n' ' ' < hand.lp)"
# the same discovery by collocation (its own search mesh, deflation against
# orbits mapped onto it): the isola again, its folds those of harmonic
# balance to 1e-7 (two discretisations of the same orbits)
"$WHIRL" run discover.whirl --METHOD=colloc --NTST=40 --OUT=dc.out > dc.txt 2> run.err || diag run.err
grep -q "^discovery: 2 branches, 1 of them isolated (closed or not connected to the start), 1 closed" dc.txt
ok $? "discovery by collocation: the main branch and one closed isola"
awk -F'\t' '$1 == 2 && $3 == "LP" { print $5 }' dc.out/branches.tsv | sort -g > dc.lp
[ "$(wc -l < dc.lp)" -eq 2 ] &&
  paste dc.lp disc.lp | awk '{ d = $1 - $2; if (d < -1e-7 || d > 1e-7) bad = 1 } END { exit bad }'
ok $? "its folds $(tr '\n' ' ' < dc.lp)= harmonic balance's to 1e-7"
tap_end

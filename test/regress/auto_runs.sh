#!/bin/sh
# test/regress/auto_runs.sh — the run semantics `whirl auto` takes from
# AUTO-07p across runs and within one, each checked against AUTO's own
# output (AUTO-07p's log test/hyper.all, or AUTO run on the same files),
# never against whirl's:
#  1. NMX, NPR and IPLT on a fold u' = p - u^2 written here (u from 1
#     through the LP at p = 0 onto u = -sqrt(p)): AUTO-07p 0.9.2 (the Debian
#     package, `run(e='fold', c='fold.1')`) labels PT 1 (EP), 8, 16, 24 (NPR
#     = 8), the LP and PT 30 (EP, NMX = 30): it counts the start and the LP
#     among the points; with IPLT = 1 its second column is U(1) itself,
#     negative past the LP (the L2-NORM would be |u|).
#     dat: a start from a data file, on the Hopf normal form (closed form:
#     r = sqrt(p), period 2 pi), and a missing data file (exit 2).
#     rotations: an angle turning by 2 pi over the orbit (AUTO's NRTN), from
#     a data file, against the closed form (period 2 pi / p).
#  2. Demos of AUTO-07p 0.9.2 (AUTO_07P_DIR, else ../shared/auto-07p beside
#     the source tree; skipped where absent), run from their own c-files,
#     their labels (BR, TY, LAB) against AUTO's log hyper.all:
#     - brc: labels numbered across runs (run 2 from HB 2 labels on from 7,
#       as branch 2), and c.brc.3's IRS = 7 is the BP of run 2; that BP a
#       symmetric cycle as AUTO's, and run 3 on AUTO's side of it;
#     - lrz: MXBF = 10 switches at the BP of run 1 (both sides, branch 2,
#       the side of U(1) > 0 first), c.lrz.2 (IRS = 4) and c.lrz.3 (IRS = 6)
#       start from the HBs on it, their ends labelled 25 and 43 on branches
#       4 and 6 (AUTO's branch number of orbits from an HB is the label);
#     - chu: MXBF = -2, one side a BP; the branch leaving [A0, A1] ends in
#       a labelled EP; c.chu.2 (IRS = 6) starts from the HB on branch 3 and
#       ends in EP 9, no PD near the homoclinic end;
#     - vhb: no PD on the conservative family from the Hopf point (AUTO has
#       none; whirl's multipliers there are wrong by orders of magnitude);
#     - ppp: c.ppp.4 alone (a fresh start with MXBF = 10), all 20 labels
#       against AUTO's own run of it (AUTO-07p 0.9.2, `run(e='ppp',
#       c='ppp.4')`, listed below);
#     - enz: the BP at s0 = 34.2229 just past the LP is found (AUTO's BP 3),
#       on the symmetric branch it lies on, and the branch switched there
#       (MXBF) on AUTO's side (AUTO's LP 7: s1 > s2);
#     - lor: dat = 'lor', the PD near rho = 229.4 and the orbit at the UZ
#       rho = 200 (INTEGRAL U(1) of IPLT = 4 and the period) as AUTO's;
#     - pp3: PVLS's PAR(9) (the L2-NORM through GETP) stops a branch at
#       UZSTOP {9: 1.2}, AUTO's UZ 4;
#     - ffn: IPLT = 9 (2 NDIM + 1): the second column is AUTO's L2-NORM of U(1),
#       at the TR 9.54521E-01 (the whole state's L2-NORM is 1.53);
#     - pen, tor: past a branch point of orbits the branch goes on as
#       AUTO's (c.pen.2's labels 4-6, c.tor.2's LP 9 at -0.832514);
#     - kar (IPS = 4): the L2-NORM of its first points, on the uniform
#       mesh, as AUTO's own run's (AUTO's quadrature of the node values);
#     - spb by its script: a BVP label restarted on a larger NTST (AUTO's
#       ADAPT2 mesh), and its long branch to AUTO's UZSTOP at AUTO's PT;
#     - ab by its script: its last run ends at AUTO's UZ, PERIOD = 1000;
#     - abcb by its script: the fold locus of orbits labels AUTO's LP at
#       its turning point (no CP), and run 4 no BP at its start.
# TAP output.
set -u
: "${top_srcdir:=.}" "${top_builddir:=.}"
WHIRL="$(cd "$top_builddir" && pwd)/drivers/whirl"
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
ok() { n=$((n + 1)); echo "ok $n - $*"; }
nok() { n=$((n + 1)); echo "not ok $n - $*"; fail=1; }
check() { if [ "$1" = 0 ]; then shift; ok "$@"; else shift; nok "$@"; fi; }
skip() { n=$((n + 1)); echo "ok $n - # SKIP $*"; }

# the labelled rows of a b-file, "BR TY LAB" (|BR|, AUTO's type names, RG
# for the NPR labels), one a line
labels() {
  awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 > 0 {
    t = substr($0, 11, 4) + 0; br = substr($0, 1, 4) + 0; if (br < 0) br = -br
    ty = t == 1 || t == 6 ? "BP" : t == 2 || t == 5 ? "LP" : t == 3 ? "HB" : t == 4 ? "RG" : \
         t == -4 ? "UZ" : t == 7 ? "PD" : t == 8 ? "TR" : t == 9 ? "EP" : t == -9 ? "MX" : t
    print br, ty, substr($0, 15, 5) + 0 }' "$1"
}
# AUTO's labelled rows of demo $1 in hyper.all, "BR TY LAB"
hyper_labels() {
  awk -v d="$1" '$0 == "Demo " d " is started" { on = 1; next } $0 == "Demo " d " is done" { on = 0 }
    on && $1 ~ /^[0-9]+$/ && $2 ~ /^[0-9]+$/ && $3 ~ /^[A-Z][A-Z]$/ && $4 ~ /^[0-9]+$/ { print $1, $3, $4 }' "$2"
}
# the point numbers of labels $2..$3 in b-file $1, and in hyper.all ($2 demo)
pts_of() {
  awk -v lo="$2" -v hi="$3" 'substr($0, 1, 4) + 0 != 0 { l = substr($0, 15, 5) + 0; p = substr($0, 5, 6) + 0
    if (p < 0) p = -p; if (l >= lo && l <= hi) printf "%d ", p }' "$1"
}
hyper_pts() {
  awk -v d="$1" -v lo="$3" -v hi="$4" '$0 == "Demo " d " is started" { on = 1; next } $0 == "Demo " d " is done" { on = 0 }
    on && $1 ~ /^[0-9]+$/ && $2 ~ /^[0-9]+$/ && $3 ~ /^[A-Z][A-Z]$/ && $4 >= lo && $4 <= hi { printf "%d ", $2 }' "$2"
}

# ---- 1. the fold: NMX, NPR, IPLT
mkdir "$tmp/fold"
cat > "$tmp/fold/fold.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = PAR(1) - U(1)**2
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1
      U(1) = 1
      END SUBROUTINE STPNT
F
cat > "$tmp/fold/c.fold.1" <<'C'
NDIM=   1, IPS =   1, IRS =   0, ILP =   1
ICP =  [1]
NTST=  20, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 1, NBC= 0, NINT= 0
NMX=   30, NPR=   8, MXBF=  10, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-08
DS  = -0.1, DSMIN= 0.0001, DSMAX=  0.1, IADS=   1
NPAR=   1, THL =  {11: 0.0}, THU =  {}
C
(cd "$tmp" && "$WHIRL" auto fold --quiet > fold.log 2>&1)
check $? "whirl auto fold exits 0"
b="$tmp/fold.out/b.fold"
got=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 > 0 && substr($0, 11, 4) + 0 != 2 {
  pt = substr($0, 5, 6) + 0; if (pt < 0) pt = -pt; printf "%d:%d ", pt, substr($0, 11, 4) + 0 }' "$b" 2>/dev/null)
[ "$got" = "1:9 8:4 16:4 24:4 30:9 " ]
check $? "fold: labels at PT 1 (EP), 8, 16, 24 (NPR) and 30 (EP = NMX) as AUTO's run: $got"
nlp=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 2' "$b" 2>/dev/null | wc -l)
[ "$nlp" -eq 1 ]
check $? "fold: one LP among the 30 points ($nlp)"
grep -q 'PT  TY  LAB    PAR(1) *U(1) *U(1)' "$b" 2>/dev/null
check $? "fold: IPLT = 1 names the second column U(1), as AUTO's b-file"
awk 'substr($0, 1, 4) + 0 != 0 { lp = lp || substr($0, 11, 4) + 0 == 2
    a = substr($0, 39, 19) + 0; u = substr($0, 58, 19) + 0
    if (a != u) bad = 1; if (lp && substr($0, 11, 4) + 0 != 2 && a >= 0) bad = 1 }
  END { exit bad }' "$b" 2>/dev/null
check $? "fold: the second column is U(1) on every row, negative past the LP (not the L2-NORM)"

# ---- dat: the Hopf normal form x' = p x - y - x r^2, y' = x + p y - y r^2
# (orbits r = sqrt(p), period 2 pi) from 41 rows of the circle r = 1 over
# t in [0, 2 pi]: the period is the data's (AUTO's STPNUB), the orbit at the
# user point p = 0.25 has MAX U(1) = 0.5 and period 2 pi
mkdir "$tmp/hnf"
cat > "$tmp/hnf/hnf.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*), R2
      R2 = U(1)**2 + U(2)**2
      F(1) = PAR(1)*U(1) - U(2) - U(1)*R2
      F(2) = U(1) + PAR(1)*U(2) - U(2)*R2
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1
      END SUBROUTINE STPNT
F
awk 'BEGIN { pi = atan2(0, -1); for (k = 0; k <= 40; k++) { t = 2 * pi * k / 40
  printf "%.10E %.10E %.10E\n", t, cos(t), sin(t) } }' | sed 's/E/D/g' > "$tmp/hnf/circle.dat"
cat > "$tmp/hnf/c.hnf.1" <<'C'
dat = 'circle'
NDIM=   2, IPS =   2, IRS =   0, ILP =   1
ICP =  [1, 11]
NTST=  20, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  100, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-08
DS  = -0.05, DSMIN= 0.0001, DSMAX=  0.05, IADS=   1
NPAR=  11, THL =  {11: 0.0}, THU =  {}
UZR = {1: 0.25}, UZSTOP = {1: 0.1}
C
(cd "$tmp" && "$WHIRL" auto hnf --quiet > hnf.log 2>&1)
check $? "dat: whirl auto hnf (a start from the data file circle.dat) exits 0"
uz=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == -4 { printf "%.12g %.12g %.12g\n", substr($0, 20, 19), substr($0, 58, 19), substr($0, 96, 19); exit }' "$tmp/hnf.out/b.hnf" 2>/dev/null)
echo "$uz" | awk '{ pi = atan2(0, -1); exit !($1 != "" && ($1 - 0.25) ^ 2 < 1e-16 && ($2 - 0.5) ^ 2 < 1e-12 && ($3 - 2 * pi) ^ 2 < 1e-12) }'
check $? "dat: at p = 0.25 MAX U(1) = 0.5 and the period 2 pi (closed form): $uz"
grep -q 'start orbit from .*circle.dat: 41 rows over 6.28318530[0-9]*, period 6.28318530' "$tmp/hnf.out/hnf.1.out/run.log"
check $? "dat: the period is the data's t range: $(grep 'start orbit' "$tmp/hnf.out/hnf.1.out/run.log" 2>/dev/null)"
sed 's/circle/nothere/' "$tmp/hnf/c.hnf.1" > "$tmp/hnf/c.hnf.2"
(cd "$tmp" && "$WHIRL" auto hnf --runs=hnf.2 --out=bad.out > bad.log 2>&1)
rc=$?
[ $rc = 2 ] && grep -q "c.hnf.2:1: dat = 'nothere': no data file .*nothere or .*nothere.dat" "$tmp/bad.log" && [ ! -e "$tmp/bad.out" ]
check $? "dat: a missing data file: exit 2 ($rc), the constants file and line, nothing written: $(head -1 "$tmp/bad.log")"
sed -n '1,12p' "$tmp/hnf/circle.dat" > "$tmp/hnf/nan.dat"
echo "1.5D+00 nan 0.5D+00" >> "$tmp/hnf/nan.dat"
sed 's/circle/nan/' "$tmp/hnf/c.hnf.1" > "$tmp/hnf/c.hnf.3"
(cd "$tmp" && "$WHIRL" auto hnf --runs=hnf.3 --out=nan.out > nan.log 2>&1)
rc=$?
[ $rc = 2 ] && grep -q "nan.dat:13: a number is not finite" "$tmp/nan.log"
check $? "dat: a row with NaN: exit 2 ($rc), the data file and line: $(grep -m1 'not finite' "$tmp/nan.log")"

# ---- rotations (AUTO's NRTN): u1' = u2, u2' = p - u2 is 2 pi-periodic in
# the angle u1; its orbits u1 = p t, u2 = p turn u1 by 2 pi in the period
# 2 pi / p.  From a data file over one turn at p = 1 (u1 = t, t in
# [0, 2 pi]): at the user point p = 2 the period is pi and U(2) = 2
mkdir "$tmp/rot"
cat > "$tmp/rot/rot.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = U(2)
      F(2) = PAR(1) - U(2)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1
      END SUBROUTINE STPNT
F
awk 'BEGIN { pi = atan2(0, -1); for (k = 0; k <= 30; k++) { t = 2 * pi * k / 30; printf "%.10e %.10e 1.0\n", t, t } }' > "$tmp/rot/rot.dat"
cat > "$tmp/rot/c.rot.1" <<'C'
dat = 'rot'
NDIM=   2, IPS =   2, IRS =   0, ILP =   1
ICP =  [1, 11]
NTST=  10, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  100, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-08
DS  = 0.05, DSMIN= 0.0001, DSMAX=  0.1, IADS=   1
NPAR=  11, THL =  {11: 0.0}, THU =  {}
UZSTOP = {1: 2.0}
C
(cd "$tmp" && "$WHIRL" auto rot --quiet > rot.log 2>&1)
check $? "rotations: whirl auto rot (an orbit turning the angle u1 by 2 pi) exits 0"
uz=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == -4 { printf "%.12g %.12g %.12g\n", substr($0, 20, 19), substr($0, 77, 19), substr($0, 96, 19); exit }' "$tmp/rot.out/b.rot" 2>/dev/null)
echo "$uz" | awk '{ pi = atan2(0, -1); exit !($1 != "" && ($1 - 2) ^ 2 < 1e-16 && ($2 - 2) ^ 2 < 1e-14 && ($3 - pi) ^ 2 < 1e-14) }'
check $? "rotations: at p = 2 MAX U(2) = 2 and the period pi (closed form): $uz"

# ---- 2. AUTO's demos
auto=${AUTO_07P_DIR:-$top_srcdir/../shared/auto-07p}
hyper="$auto/test/hyper.all"
if [ ! -f "$hyper" ] || [ ! -d "$auto/demos" ]; then
  skip "no AUTO-07p demos at $auto (set AUTO_07P_DIR)"
  echo "1..$n"
  exit $fail
fi
auto=$(cd "$auto" && pwd)
hyper="$auto/test/hyper.all"
demo() { (cd "$tmp" && "$WHIRL" auto "$auto/demos/$1" ${2:+"$2"} --quiet > "$1.log" 2>&1); }

# brc: run 2's labels 7-10 on branch 2, run 3 from label 7 (the BP)
demo brc
w=$(labels "$tmp/brc.out/b.brc" | awk '$3 >= 7 && $3 <= 11' | tr '\n' ';')
a=$(hyper_labels brc "$hyper" | awk '$3 >= 7 && $3 <= 11' | tr '\n' ';')
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "brc: labels 7-11 across runs as AUTO's ($a): $w"
tr11=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 11 { print substr($0, 20, 19) + 0 }' "$tmp/brc.out/b.brc")
awk -v x="${tr11:-0}" 'BEGIN { d = (x - 1.30281) / 1.30281; exit !(d < 1e-5 && d > -1e-5) }'
check $? "brc: c.brc.3 (IRS = 7) starts from the BP: its TR 11 at PAR(5) = $tr11, AUTO 1.30281"
# the BP of the symmetric cycles (U(3) and U(4), U(2) and U(5) alike, as
# AUTO's 3.69249 twice) is a symmetric cycle: Newton beside the branch point
# used to push it 3e-5 along the asymmetric null vector
bp7=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 7 { printf "%.10g %.10g %.10g %.10g\n", substr($0, 96, 19), substr($0, 115, 19), substr($0, 77, 19), substr($0, 134, 19) }' "$tmp/brc.out/b.brc")
echo "$bp7" | awk '{ d = $1 - $2; e = $3 - $4; exit !(NF == 4 && d < 1e-6 && d > -1e-6 && e < 1e-6 && e > -1e-6) }'
check $? "brc: BP 7's MAX U(3), MAX U(4) and MAX U(2), MAX U(5) equal to 1e-6: $bp7"
# ... and run 3 leaves it on AUTO's side of the pitchfork (TR 11: MAX U(2)
# 2.32843, MAX U(5) 2.82494; the mirror image has them swapped)
tr11m=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 11 { print substr($0, 77, 19) + 0, substr($0, 134, 19) + 0 }' "$tmp/brc.out/b.brc")
echo "$tr11m" | awk '{ exit !(NF == 2 && $1 > 2.32842 && $1 < 2.32844 && $2 > 2.82493 && $2 < 2.82495) }'
check $? "brc: run 3 on AUTO's side: TR 11's MAX U(2), MAX U(5) = $tr11m, AUTO 2.32843 2.82494"

# lor: c.lor.3's PD of the doubled orbits (PT 14, rho = 215.966) has
# AUTO's values at the nodes: orbits take their phase along the branch by
# AUTO's phase condition (PHASE = nodes: at the nodes, with the model's f),
# so the meshes the branch adapts are AUTO's too; by whirl's Gauss rule
# the phases drifted apart by 1e-5 of the period, and with them the meshes:
# MAX U(1) 35.9092 and U(3) 297.7295 where AUTO has 35.8658, 297.684
(cd "$tmp" && "$WHIRL" auto "$auto/demos/lor" --quiet --out=lor3.out > lor3.log 2>&1)
pd6=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 6 && substr($0, 11, 4) + 0 == 7 { printf "%.8g %.8g", substr($0, 58, 19), substr($0, 96, 19); exit }' "$tmp/lor3.out/b.lor")
echo "$pd6" | awk '{ d = $1 - 35.8658; e = $2 - 297.684; exit !(NF == 2 && d < 5e-4 && d > -5e-4 && e < 2e-3 && e > -2e-3) }'
check $? "lor: c.lor.3's PD 6 at AUTO's MAX U(1), MAX U(3) (35.8658, 297.684): $pd6"

# kar: its UZ at PAR(1) = 0 is where AUTO's localisation stops at EPSS
# (-8.44948e-3; the test function is steep there, the problem singular at
# PAR(1) = 0), and AUTO's branch goes on from there: its labels 2-5 at PT
# 19 27 70 93.  whirl auto goes on from the zero located to convergence
# (LOCATE = converged: 19 25 61 83); its run file with LOCATE = auto goes on
# from where AUTO's secant and Mueller steps end, and the labels come at
# AUTO's points (the points reported stay converged)
demo kar
(cd "$tmp/kar.out" && "$WHIRL" run kar.1.whirl --LOCATE=auto --OUT=kar.loc --quiet > /dev/null 2>&1)
w=$(awk -F'\t' 'NR > 1 && $4 >= 2 && $4 <= 5 { printf "%d ", $2 + 1 }' "$tmp/kar.out/kar.loc/branches.tsv" 2> /dev/null)
a=$(hyper_pts kar "$hyper" 2 5)
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "kar: LOCATE = auto puts labels 2-5 at AUTO's point numbers ($a): $w"
# pp2 (a constants file of AUTO's new style, ITNW and ISP left to AUTO's
# defaults): branch 2, switched at BP 2 by MXBF, has BP 4, LP 5 and UZ 6 at
# AUTO's PT 21, 25 and 79.  whirl's ITNW = 8 grew the step after three
# Newton iterations where AUTO's ITNW = 5 keeps it, and whirl adapted the
# step after the switch's first step and after BP 4, which AUTO's
# algebraic branches do not (PT 11, 13, 31 before 2026-12-07)
demo pp2
w=$(pts_of "$tmp/pp2.out/b.pp2" 4 6)
a=$(hyper_pts pp2 "$hyper" 4 6)
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "pp2: labels 4-6 at AUTO's point numbers ($a): $w"
# r3b's first run: BPs 2-4 and UZ 5 at AUTO's PT 25 83 141 181.  With
# AUTO's step rules of algebraic branches the steps pass the pole of the
# determinant at mu = 0, x = 1 (the second primary) differently, and a
# trial on the way came below both ends' |det| (0.0044 against 0.0086):
# labelled a BP, one point too many (PT 55), until the point returned had
# to be below them as well
demo r3b r3b
w=$(pts_of "$tmp/r3b.out/b.r3b" 2 5 | awk '{ print $1, $2, $3, $4 }')
a=$(hyper_pts r3b "$hyper" 2 5 | awk '{ print $1, $2, $3, $4 }') # run 1's
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "r3b: labels 2-5 at AUTO's point numbers ($a): $w"

# lrz: MXBF, and IRS = 4, 6 on the switched branch
demo lrz
w=$(labels "$tmp/lrz.out/b.lrz" | awk '$2 != "RG"' | head -9 | tr '\n' ';')
a=$(hyper_labels lrz "$hyper" | tr '\n' ';')
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "lrz: MXBF's branches and the restarts from them labelled as AUTO's ($a): $w"
u4=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 4 { print substr($0, 58, 19) + 0 }' "$tmp/lrz.out/b.lrz")
awk -v x="${u4:-0}" 'BEGIN { d = (x - 7.95602) / 7.95602; exit !(d < 1e-5 && d > -1e-5) }'
check $? "lrz: the side with U(1) > 0 first: U(1) at HB 4 = $u4, AUTO 7.95602"

# chu: MXBF < 0, the EP at A1, IRS = 6
demo chu
w=$(labels "$tmp/chu.out/b.chu" | awk '$3 <= 9' | tr '\n' ';')
a=$(hyper_labels chu "$hyper" | awk '$3 <= 9' | tr '\n' ';')
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "chu: labels 1-9 (one side a BP, the EP at A1, c.chu.2 from HB 6, no PD near the homoclinic end) as AUTO's ($a): $w"

# vhb: no PD on the conservative family (its multipliers are 1, whirl's
# computed ones wild near the homoclinic loop)
demo vhb
npd=$(labels "$tmp/vhb.out/b.vhb" | awk '$2 == "PD"' | wc -l)
apd=$(hyper_labels vhb "$hyper" | awk '$2 == "PD"' | wc -l)
[ "$npd" -eq 0 ] && [ "$apd" -eq 0 ]
check $? "vhb: no PD on the family from the Hopf point, as AUTO ($npd, AUTO $apd)"

# hen: a map (IPS = -1), PD and TR detected with ISP = 1, and STOP =
# ['TR1'] ending the branch at its TR as AUTO's run 1 (without STOP whirl
# went on to a UZ at beta = 3)
demo hen
w=$(labels "$tmp/hen.out/b.hen" | tr '\n' ';')
a=$(hyper_labels hen "$hyper" | head -3 | tr '\n' ';')
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "hen: the map's labels (EP, PD, TR, then STOP) as AUTO's run 1 ($a): $w"

# log: the logistic map's period doublings, ISW = -1 at a PD of a map (the
# doubled map f^2k; what log.auto's loop does): from c.log's PD at mu = 3
# the period-2 points flip at 1 + sqrt 6, the period-4 ones at 3.5440903596
# (closed form and the known cascade; AUTO's PD 6 and 8: 3.44949, 3.54409)
demo log
lw="$tmp/log.out"
sed -e "s|^OUT .*|OUT = 'p2.out'|" -e "s|^ISW .*|ISW = -1|" "$lw/log.whirl" > "$lw/p2.whirl"
printf "IRS = 2\nS = 'log.bif1.out'\n" >> "$lw/p2.whirl"
sed -e "s|^OUT .*|OUT = 'p4.out'|" -e "s|^S = .*|S = 'p2.out'|" "$lw/p2.whirl" > "$lw/p4.whirl"
(cd "$lw" && "$WHIRL" run p2.whirl --quiet && "$WHIRL" run p4.whirl --quiet) > "$tmp/log2.log" 2>&1
pd2=$(awk -F'\t' '$3 == "PD" { print $5; exit }' "$lw/p2.out/branches.tsv" 2>/dev/null)
pd4=$(awk -F'\t' '$3 == "PD" { print $5; exit }' "$lw/p4.out/branches.tsv" 2>/dev/null)
awk -v a="${pd2:-0}" -v b="${pd4:-0}" 'BEGIN { m = 1 + sqrt(6); d = a - m; e = b - 3.5440903596
  exit !(d < 1e-9 && d > -1e-9 && e < 1e-9 && e > -1e-9) }'
check $? "log: PD of the period-2 points at $pd2 (1 + sqrt 6), of the period-4 ones at $pd4 (3.5440903596)"

# ppp: c.ppp.4 alone against AUTO's own run of it
demo ppp --runs=ppp.4
w=$(labels "$tmp/ppp.out/b.ppp" | tr '\n' ';')
a="1 EP 1;1 BP 2;1 EP 3;2 LP 4;2 EP 5;2 BP 6;2 HB 7;2 HB 8;2 BP 9;2 EP 10;3 EP 11;3 EP 12;4 EP 13;4 BP 14;4 BP 15;4 EP 16;5 EP 17;5 EP 18;6 EP 19;6 EP 20;"
[ "$w" = "$a" ]
check $? "ppp: c.ppp.4's 20 labels on 6 branches (MXBF = 10) as AUTO's run of it: $w"

# enz: the BP ten points past the LP (the locator's Newton fails at the
# singular point itself; the point a little off it is taken)
demo enz --runs=enz.1
bp=$(awk 'substr($0, 1, 4) + 0 == 1 && substr($0, 11, 4) + 0 == 1 { print substr($0, 20, 19) + 0, substr($0, 39, 19) + 0; exit }' "$tmp/enz.out/b.enz")
echo "$bp" | awk '{ exit !($1 != "" && (($1 - 34.2229) / 34.2229) ^ 2 < 1e-10 && (($2 - 1.66053) / 1.66053) ^ 2 < 1e-10) }'
check $? "enz: the first BP of run 1 at s0 = 34.2229, L2-NORM 1.66053 as AUTO's BP 3 (hyper.all): $bp"
# ... on the symmetric branch it lies on (s1 = s2: AUTO's 1.17417 both;
# Newton beside the point put whirl's 1e-5 off, onto the other branch), and
# the switched branch (MXBF) on AUTO's side, s1 > s2 (AUTO's LP 7: 25.3727,
# s1 5.88408, s2 0.571738; STPRAE: the first component that moves grows)
got=$(awk 'substr($0, 1, 4) + 0 == 1 && substr($0, 11, 4) + 0 == 1 { b = substr($0, 58, 19) - substr($0, 77, 19); if (b < 0) b = -b }
  substr($0, 1, 4) + 0 == 2 && substr($0, 11, 4) + 0 == 2 && lp == "" { lp = (substr($0, 20, 19) + 0) " " (substr($0, 58, 19) + 0) " " (substr($0, 77, 19) + 0) }
  END { print (b == "" ? 1 : b), lp }' "$tmp/enz.out/b.enz")
echo "$got" | awk '{ exit !($1 < 1e-6 && (($2 - 25.3727) / 25.3727) ^ 2 < 1e-10 && $3 > $4 && (($3 - 5.88408) / 5.88408) ^ 2 < 1e-10) }'
check $? "enz: its BPs on the symmetric branch (|s1 - s2| < 1e-6), branch 2's first LP on AUTO's side (25.3727, s1 5.88408 > s2): $got"

# lor: dat = 'lor' (AUTO's data file of the demo), IPLT = 4 (INTEGRAL U(1))
demo lor --runs=lor.1
uz=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == -4 { printf "%.12g %.12g\n", substr($0, 39, 19), substr($0, 115, 19); exit }' "$tmp/lor.out/b.lor")
echo "$uz" | awk '{ exit !($1 != "" && (($1 + 1.23833) / 1.23833) ^ 2 < 1e-10 && (($2 - 0.516877) / 0.516877) ^ 2 < 1e-10) }'
check $? "lor: from lor.dat, at the UZ rho = 200 INTEGRAL U(1) and PERIOD as AUTO's UZ 3 (-1.23833, 0.516877): $uz"
pd=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 7 { printf "%.12g %.12g %.12g\n", substr($0, 20, 19), substr($0, 39, 19), substr($0, 115, 19); exit }' "$tmp/lor.out/b.lor")
echo "$pd" | awk '{ exit !($1 != "" && (($1 - 229.407) / 229.407) ^ 2 < 1e-10 && (($2 + 1.06862) / 1.06862) ^ 2 < 1e-10 && (($3 - 0.480867) / 0.480867) ^ 2 < 1e-10) }'
check $? "lor: the PD on DSMAX = 25 steps (the multiplier passing -1 moves from -0.98 to -2.0) as AUTO's PD 2 (229.407, -1.06862, 0.480867): $pd"

# pp3: PVLS sets PAR(9) to the L2-NORM of U (GETP('NRM', i, U) = |U(i)|);
# UZSTOP {9: 1.2} ends the first half of MXBF's branch 2 there (AUTO's UZ 4)
demo pp3
uz=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 4 { printf "%d %.12g %.12g\n", substr($0, 11, 4), substr($0, 20, 19), substr($0, 39, 19); exit }' "$tmp/pp3.out/b.pp3")
echo "$uz" | awk '{ exit !($1 == -4 && (($2 - 0.800796) / 0.800796) ^ 2 < 1e-10 && ($3 - 1.2) ^ 2 < 1e-16) }'
check $? "pp3: label 4 is the UZ where PVLS's PAR(9) = L2-NORM = 1.2, at PAR(1) = 0.800796 as AUTO's UZ 4: $uz"

# ffn: IPLT = 9
demo ffn
grep -q 'PT  TY  LAB    amp *L2-NORM x ' "$tmp/ffn.out/b.ffn"
check $? "ffn: IPLT = 9 names the second column 'L2-NORM x' (AUTO's HEADNG with unames {1: 'x'})"
tr=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 8 { print substr($0, 39, 19) + 0; exit }' "$tmp/ffn.out/b.ffn")
awk -v x="${tr:-0}" 'BEGIN { d = (x - 0.954521) / 0.954521; exit !(d < 1e-5 && d > -1e-5) }'
check $? "ffn: L2-NORM U(1) at the TR = $tr, AUTO 9.54521E-01"
# pen and tor: past a branch point of orbits the branch goes on as AUTO's,
# not onto the crossing one (a mesh change at the BP solved its tangent
# anew, any vector of the null plane; the localisation's last Newton count,
# 7 beside the BP, cut the next step to a fraction)
demo pen --runs=pen.1,pen.2
w=$(labels "$tmp/pen.out/b.pen" | awk '$3 >= 4 && $3 <= 6' | tr '\n' ';')
a=$(hyper_labels pen "$hyper" | awk '$3 >= 4 && $3 <= 6' | tr '\n' ';')
[ -n "$a" ] && [ "$w" = "$a" ]
check $? "pen: c.pen.2 (the doubled rotations) labels 4-6 as AUTO's ($a): $w"
# ... its BP 4 is AUTO's orbit in phase too: each trial of a localisation
# refers its phase condition to the last trial, as AUTO's LCSPBV, where
# whirl's all referred to the step's start (the orbit came out 1e-5 of the
# period apart, and the rotations' L2-NORM 10.642297); AUTO at EPSS =
# 1e-10 gives 10.642480232.  And the next step is AUTO's DSMAX, from the
# Newton count of the trial where AUTO's localisation stops (whirl's last
# trial, beside the branch point, took 4-5 iterations to AUTO's 2, and the
# next point was at PAR(3) = 0.29238 for AUTO's 0.28717407)
bp4=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 4 { printf "%.10g\n", substr($0, 39, 19); getline; printf "%.10g\n", substr($0, 20, 19); exit }' "$tmp/pen.out/b.pen" | tr '\n' ' ')
echo "$bp4" | awk '{ d = $1 - 10.642480232; e = $2 - 0.28717407; exit !(NF == 2 && d < 1e-5 && d > -1e-5 && e < 1e-4 && e > -1e-4) }'
check $? "pen: BP 4's L2-NORM (AUTO 10.642480232 at EPSS 1e-10) and the next point's PAR(3) (AUTO 0.28717407): $bp4"
demo tor --runs=tor.1,tor.2
lp9=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 5 && substr($0, 20, 19) + 0 < -0.8 { printf "%.10g", substr($0, 20, 19); exit }' "$tmp/tor.out/b.tor")
awk -v x="${lp9:-0}" 'BEGIN { d = (x + 0.832514) / 0.832514; exit !(d < 1e-6 && d > -1e-6) }'
check $? "tor: c.tor.2 stays on its branch past its BP at -0.587029: AUTO's LP 9 at -0.832514: ${lp9:-none}"
# kar (IPS = 4, NTST 40 uniform until the first mesh adaptation, a
# boundary layer at t = 0): the L2-NORM of its first points as AUTO's, the
# node values by each interval's Newton-Cotes weights (AUTO's RNRMV); a
# Gauss rule of the collocation polynomial gave 4.0997e-3 at PT 2
mkdir "$tmp/kar" && cp "$auto/demos/kar/kar.f90" "$tmp/kar/" &&
  sed 's/NMX= *500, NPR= *500/NMX=   3, NPR=   1/' "$auto/demos/kar/c.kar" > "$tmp/kar/c.kar.1"
(cd "$tmp" && "$WHIRL" auto kar --quiet > kar.log 2>&1)
l2=$(awk 'substr($0, 1, 4) + 0 != 0 && (substr($0, 5, 6) + 0 == 2 || substr($0, 5, 6) + 0 == 3) { printf "%.10g ", substr($0, 39, 19) }' "$tmp/kar.out/b.kar")
echo "$l2" | awk '{ exit !(NF == 2 && (($1 - 4.1417949978e-3) / 4.1417949978e-3) ^ 2 < 1e-12 && (($2 - 1.0384051822e-2) / 1.0384051822e-2) ^ 2 < 1e-12) }'
check $? "kar: PT 2 and 3's L2-NORM as AUTO's (4.1417949978E-003 1.0384051822E-002, AUTO-07p 0.9.2's b.kar): $l2"
# spb by its script (IPS = 4): c.spb.2 restarts the epsilon = 1e-3 label of
# NTST 100 on NTST 200, onto the mesh AUTO's ADAPT2 makes from it (a
# uniform one lost the boundary layer: Newton failed at the start, exit
# 1), and ends in AUTO's EP 19 (PT 15, PAR(1) -1.32815E-01); c.spb.3 then
# runs its NMX (it had stopped "closed on itself" after 565 points: the
# loop test measured the step unweighted against the weighted distance)
(cd "$tmp" && "$WHIRL" auto "$auto/demos/spb" --script --quiet --out=spb.s > spb.s.log 2>&1)
rc=$?
ep=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 5, 6) + 0 == 15 && substr($0, 11, 4) + 0 == 9 { printf "%.10g", substr($0, 20, 19) }' "$tmp/spb.s/b.2" 2>/dev/null)
awk -v x="${ep:-0}" 'BEGIN { d = (x + 0.132815) / 0.132815; exit !(d < 5e-6 && d > -5e-6) }'
check $(( $? + rc )) "spb --script: runs 3-4 run (exit $rc), run 3's EP at PT 15 as AUTO's EP 19 (-1.32815E-01): ${ep:-none}"
# ... and, since the stored direction is AUTO's secant and no turn of a
# step is rejected (2026-12-06), takes AUTO's steps to its UZSTOP at
# PAR(1) = -2.2, AUTO's PT 1554 (AUTO-07p 0.9.2's own run of spb.auto);
# before, a turn of more than 0.5 rad halved its step at point 14 and it
# ran its NMX of 2000 points to PAR(1) = -1.85
last=$(awk 'substr($0, 1, 4) + 0 != 0 { e = substr($0, 5, 6) + 0; t = substr($0, 11, 4) + 0; p = substr($0, 20, 19) + 0 } END { print (e < 0 ? -e : e), t, p }' "$tmp/spb.s/b.2" 2>/dev/null)
echo "$last" | awk '{ exit !($1 >= 1540 && $1 <= 1570 && $2 == -4 && ($3 + 2.2) ^ 2 < 1e-12) }'
check $? "spb --script: c.spb.3 ends at its UZSTOP PAR(1) = -2.2 at AUTO's PT 1554 (PT, type, PAR(1): ${last:-none}; it was an EP at NMX 2000, and 565 before that)"
# ab by its script: its last run (orbits from HB 5 towards the homoclinic
# orbit) ends at its UZSTOP PERIOD = 1000 at AUTO's PAR(1) = 0.110114
# (hyper.all and AUTO's own run: UZ 18 at PT 377, L2-NORM 1.85878).
# Before dF/dp_k of orbits was taken at the Gauss points, the whole
# residual's difference lost its digits at such periods and the run
# ended at NMX = 500 short of it
(cd "$tmp" && "$WHIRL" auto "$auto/demos/ab" --script --quiet --out=ab.s > ab.s.log 2>&1)
rc=$?
last=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 != 0 { t = substr($0, 11, 4) + 0; p = substr($0, 20, 19) + 0; l = substr($0, 39, 19) + 0; T = substr($0, 96, 19) + 0 } END { printf "%d %.10g %.10g %.10g", t, p, l, T }' "$tmp/ab.s/b.ab" 2>/dev/null)
echo "$last" | awk '{ exit !($1 == -4 && $2 - 0.110114 < 1e-6 && 0.110114 - $2 < 1e-6 && $3 - 1.85878 < 1e-5 && 1.85878 - $3 < 1e-5 && $4 - 1000 < 1e-6 && 1000 - $4 < 1e-6) }'
check $(( $? + rc )) "ab --script: the last run ends at AUTO's UZ, PERIOD = 1000 at PAR(1) = 0.110114, L2-NORM 1.85878 (exit $rc; type, PAR(1), L2-NORM, PERIOD: ${last:-none})"
# abcb by its script: its fold locus of orbits (run 3 fw, ICP = [2, 1,
# 11]) turns in PAR(2) at 1.26866, AUTO's LP 30 (type 55: 10 x 5 + 5 on a
# locus from an LP of orbits; AUTO-07p 0.9.2's own run of abcb.auto:
# 1.2686579741), where whirl's cusp test labelled CP
# (AUTO's loci of orbits have bvp.f90's test functions alone); run 4,
# restarted at the bw run's LP where two families of orbits cross, labels
# no BP at its start (AUTO's b.abcb.4.bw has none)
(cd "$tmp" && "$WHIRL" auto "$auto/demos/abcb" --script --quiet --out=abcb.s > abcb.s.log 2>&1)
rc=$?
lp=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 55 { printf "%.10g", substr($0, 20, 19); exit }' "$tmp/abcb.s/b.abcb.3.fw" 2>/dev/null)
cps=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == -52' "$tmp/abcb.s/b.abcb.3.fw" "$tmp/abcb.s/b.abcb.3.bw" 2>/dev/null | wc -l)
awk -v x="${lp:-0}" -v c="$cps" 'BEGIN { d = (x - 1.2686579741) / 1.2686579741; exit !(c == 0 && d < 1e-8 && d > -1e-8) }'
check $(( $? + rc )) "abcb --script: the fold locus of orbits labels AUTO's LP at PAR(2) = 1.2686579741 (exit $rc): ${lp:-none}, $cps CP"
# AUTO's type codes on the loci (io.f90's ITPST, bvp.f90): 10 k + type, k
# the type the locus started from, as AUTO-07p 0.9.2's own run of
# abcb.auto writes them: run 3 (fold locus from LP 5) 54 54 55 54 59, its
# starting data 59; run 5 (branch-point locus from BP 6) 64 ... 69; run 4
# (ISW = 1 from the fold locus's LP) plain 4 and 9; the b-files say
# "Branch type:  5    TY = 'LP '" as AUTO's do
codes() { awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 != 0 { printf "%d ", substr($0, 11, 4) }' "$tmp/abcb.s/b.abcb.$1" 2>/dev/null; }
c3=$(codes 3.fw) c3s=$(codes 3.sw) c5=$(codes 5.fw) c4=$(codes 4.bw)
echo "$c3" | grep -Eq '^(5[459] )+$' && echo "$c3" | grep -q ' 55 ' && [ "$c3s" = "59 " ] &&
  echo "$c5" | grep -Eq '^(6[469] )+$' && echo "$c4" | grep -Eq '^([49] )+$' &&
  grep -q "^   0   Branch type:  5    TY = 'LP '" "$tmp/abcb.s/b.abcb.3.fw" &&
  ! grep -q "Branch type" "$tmp/abcb.s/b.abcb.4.bw"
check $? "abcb --script: AUTO's type codes on the loci of orbits (3 fw: $c3; 3 sw: $c3s; 5 fw: $c5; 4 bw: $c4) and AUTO's 'Branch type' header line"
# ... and its fold locus of orbits adapts the orbits' mesh as it goes (IAD
# = 3, as AUTO's on its loci) and measures its steps by their integral:
# the labels' meshes differ (the locus kept its first mesh before)
meshes=$(grep '^MESH' "$tmp/abcb.s/runs/r4@1.out/solutions" 2>/dev/null | sort -u | wc -l)
labs=$(grep -c '^LAB' "$tmp/abcb.s/runs/r4@1.out/solutions" 2>/dev/null)
[ "${labs:-0}" -ge 3 ] && [ "$meshes" -ge 3 ]
check $? "abcb --script: run 3 fw's fold locus of orbits on adapted meshes ($meshes meshes in its $labs labels)"
bps=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 6' "$tmp/abcb.s/b.abcb.4.bw" 2>/dev/null | wc -l)
[ -s "$tmp/abcb.s/b.abcb.4.bw" ] && [ "$bps" = 0 ]
check $? "abcb --script: run 4 (bw) labels no BP at its start, restarted at the crossing of two families (AUTO none): $bps"
# abcb's run 4 fw from the end of the bw run on the second family through
# that crossing (test/regress/abcb_branch.sol: run 4 bw's EP 6, the run
# that BLAS kernels with AVX-512 gave, where its first step did not
# converge until it turned onto a branch: bpstart.c): the branch point
# of orbits at AUTO's PAR(1) = 0.2199828 (b.abcb.4.fw, its BP 36 on the
# other family, 0.21998281532) is labelled, from which run 5 starts its
# locus.  Newton failed at every trial within 2.5e-3 of the step of it
# (the families cross at a small angle) and the point was lost
bd="$tmp/abcb.s/runs"
if [ -f "$bd/r7@6.whirl" ]; then
  mkdir -p "$bd/bdata.out" && cp "$top_srcdir/test/regress/abcb_branch.sol" "$bd/bdata.out/solutions"
  sed "s/^OUT .*/OUT = 'bfw.out'/; s/^S .*/S = 'bdata.out'/; s/^IRS .*/IRS = 6/" "$bd/r7@6.whirl" > "$bd/bfw.whirl"
  (cd "$bd" && "$WHIRL" run bfw.whirl --quiet --no-plot > bfw.log 2>&1)
  rc=$?
  bp=$(awk -F'\t' '$3 == "BP" { printf "%.10g", $5; exit }' "$bd/bfw.out/branches.tsv" 2>/dev/null)
  awk -v x="${bp:-0}" 'BEGIN { d = x - 0.21998281532; exit !(d < 5e-7 && d > -5e-7) }'
  check $(( $? + rc )) "abcb run 4 fw on the second family: the branch point of orbits at AUTO's PAR(1) = 0.2199828 (exit $rc): ${bp:-none}"
else
  check 1 "abcb run 4 fw on the second family: no run file r7@6.whirl from the script"
fi
# tor by its script: run 6, the torus locus at a fixed angle (ICP = [1, 2,
# 3, 11]), follows the orbits towards the homoclinic end, where AUTO's UZ
# at PERIOD = 3000 is its PT 60.  The locus measures the period by THL (0)
# and its node values by the integral, as AUTO's, and differences F_x on
# the node values' scale: before, the period counted 1 in every step and
# each step moved it by about 1 (NMX at PERIOD 102), and the differences'
# step scaled with the period (at PERIOD 400 Newton converged linearly).
# whirl's steps still shrink before 3000 (AUTO's norm has the eigenfunction
# too, which moves where the orbit hardly does)
(cd "$tmp" && "$WHIRL" auto "$auto/demos/tor" --script --quiet --out=tor.s > tor.s.log 2>&1)
rc=$?
T=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "period") c = i; next } c && $c > m { m = $c } END { printf "%.6g", m }' "$tmp/tor.s/runs/r6@1.out/branches.tsv" 2>/dev/null)
awk -v t="${T:-0}" 'BEGIN { exit !(t > 1000) }'
check $(( $? + rc )) "tor --script: run 6's torus locus follows the orbits past PERIOD 1000 towards AUTO's UZ at 3000 (exit $rc): largest PERIOD ${T:-none}"
# tfc by its script: run 4's BP locus of orbits bw runs towards AUTO's
# homoclinic end (AUTO: 300 points to EP 27 at PAR(6) 9.50030E-03, PERIOD
# 5588) on adapted meshes, measured as its orbits; on its first mesh with
# every node weighed 1 it labelled an LP at PT 68, PAR(6) 0.00968
(cd "$tmp" && "$WHIRL" auto "$auto/demos/tfc" --script --quiet --out=tfc.s > tfc.s.log 2>&1)
bw=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "PAR(6)") c = i; next }
  c { n = $2; if (m == "" || $c < m) m = $c } END { printf "%d %.6g", n, m }' "$tmp/tfc.s/runs/r6@1.out/branches.tsv" 2>/dev/null)
echo "$bw" | awk '{ exit !(NF == 2 && $1 >= 200 && $2 < 0.0096 && $2 > 0.0095) }'
check $? "tfc --script: run 4's BP locus bw runs towards AUTO's end at PAR(6) 9.50030E-03 (last PT, least PAR(6): ${bw:-none})"
echo "1..$n"
exit $fail

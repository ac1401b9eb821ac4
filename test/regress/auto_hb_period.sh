#!/bin/sh
# test/regress/auto_hb_period.sh — AUTO's TY = 'HBk' on a restart of
# periodic orbits (IPS = 2) from an equilibrium label, through `whirl auto`
# (the run file's HB_PERIOD): the label is taken as a Hopf point whose
# orbits have the period PAR(k) at the label, from the eigenvalue pair
# nearest 2 pi i / PAR(k) (AUTO's RSPTBV and STHOPF; demo r3b starts its
# Lyapunov and vertical families so from a libration point, with the
# periods its PVLS computes by GETP('EIG')).  ISW = -1 there starts orbits
# as ISW = 1 (AUTO's periodic INIT).  Until 2026-12-07 whirl refused the
# start ("needs an HB"), and did not label a restart's first point with
# NPR = 1, which AUTO labels (r3b's c.r3b.H1 restarts at IRS = 5, the
# BP at PT 5 of AUTO's L1).  The problem, with closed forms:
#   u1' = u2 + l u1, u2' = -u1 + l u2, u3' = u4 + l u3, u4' = -4 u3 + l u4
# (l = PAR(1)), the equilibrium u = 0 continued in l through 0, where both
# pairs l +- i and l +- 2i are centres; PVLS puts 2 pi / |Im| of the first
# eigenvalue in AUTO's order (the conservative order: 2i first) into
# PAR(2) = pi, of the third into PAR(3) = 2 pi.  From the UZ at l = 0:
#  TY = 'HB3': the orbits u1 + i u2 = a e^{-it}, u3 = u4 = 0 (period 2 pi,
#  l = 0, MAX U(3) = 0); TY = 'HB2': u3, u4 of period pi, u1 = u2 = 0.
# TAP output.
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
name=auto_hb_period
. "${top_srcdir:-.}/test/regress/tap.sh"

for k in 2 3 x; do
  mkdir cen$k
  cat > cen$k/cen$k.f90 <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = U(2) + PAR(1) * U(1)
      F(2) = -U(1) + PAR(1) * U(2)
      F(3) = U(4) + PAR(1) * U(3)
      F(4) = -4 * U(3) + PAR(1) * U(4)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = -0.5D0
      U(1) = 0
      U(2) = 0
      U(3) = 0
      U(4) = 0
      END SUBROUTINE STPNT
      SUBROUTINE PVLS(NDIM,U,PAR)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), GETP, PI, W
      PI = 4 * ATAN(1D0)
      W = ABS(GETP('EIG', 2, U))
      IF (W > 0) PAR(2) = 2 * PI / W
      W = ABS(GETP('EIG', 6, U))
      IF (W > 0) PAR(3) = 2 * PI / W
      END SUBROUTINE PVLS
F
  cat > cen$k/c.cen$k.1 <<C
NDIM = 4, IPS = 1, IRS = 0, ILP = 0, ICP = [1, 2, 3], ISP = 0, ISW = 1
NMX = 100, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS = 0.1, DSMIN = 1e-5, DSMAX = 0.2, NPAR = 11
UZR = {1: 0}, UZSTOP = {1: 0.5}
C
  cat > cen$k/c.cen$k.2 <<C
NDIM = 4, IPS = 2, IRS = 2, ILP = 0, ICP = [1, 11], ISP = 0, ISW = -1
NTST = 20, NCOL = 4, IAD = 3, NMX = 8, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS = 0.1, DSMIN = 1e-5, DSMAX = 0.1, NPAR = 11, THL = {11: 0}
TY = 'HB$k'
C
done
# NPR = 1: AUTO labels every point it counts, the restart's first one too
# (type 4); NPR = 0 leaves it unlabelled (type 0)
sed -i 's/NPR = 0/NPR = 1/' cen3/c.cen3.2

# the b-file's last row, the second run's end (IPS 2 columns: PAR(1),
# L2-NORM, MAX U(1..4), PERIOD): its values from PAR(1)
last_row() {
  awk 'NF > 8 && $1 != 0 { r = $0 } END { n = split(r, v, " "); for (i = 5; i <= n; i++) printf "%s ", v[i]; print "" }' "$1"
}
for k in 2 3; do
  (cd cen$k && "$WHIRL" auto . cen$k --quiet > ../cen$k.log 2>&1)
  ok $? "TY = 'HB$k': whirl auto exit 0 ($(head -c 200 cen$k.log))"
  row=$(last_row cen$k/cen$k.out/b.cen$k)
  if [ $k = 3 ]; then
    echo "$row" | awk '{ pi = 4 * atan2(1, 1); d = $7 - 2 * pi; exit !(NF == 7 && d * d < 1e-16 && $1 * $1 < 1e-16 && $3 > 0.1 && $5 * $5 < 1e-16) }'
    ok $? "TY = 'HB3': orbits of period 2 pi in (u1, u2), l = 0, MAX U(3) = 0 (PAR(1) L2 MAX U(1..4) PERIOD: $row)"
  else
    echo "$row" | awk '{ pi = 4 * atan2(1, 1); d = $7 - pi; exit !(NF == 7 && d * d < 1e-16 && $1 * $1 < 1e-16 && $5 > 0.1 && $3 * $3 < 1e-16) }'
    ok $? "TY = 'HB2': orbits of period pi in (u3, u4), l = 0, MAX U(1) = 0 (PAR(1) L2 MAX U(1..4) PERIOD: $row)"
  fi
done
# the first row of the second run (its PT 1): type and label
first_row() {
  awk 'NF > 8 && $1 != 0 { n++ } NF > 8 && $1 != 0 && $2 == 1 && n > 1 { print $3, $4; exit }' "$1"
}
r3=$(first_row cen3/cen3.out/b.cen3)
r2=$(first_row cen2/cen2.out/b.cen2)
[ "$r3" = "4 4" ] && [ "$r2" = "0 0" ]
ok $? "the Hopf start's PT 1: labelled RG (type 4, label 4) with NPR = 1 as AUTO labels it, unlabelled with NPR = 0 (TY LAB: '$r3', '$r2')"
# whirl's run file (the one `whirl auto` wrote for c.cen3.2) with a bad
# HB_PERIOD: one message, exit 2, no output directory
bad_run() { # $1 the key's new line, $2 the message expected, $3 what
  sed -e "s/^HB_PERIOD .*/$1/" -e "s/^OUT .*/OUT = 'bad.out'/" cen3/cen3.out/cen3.2.whirl > cen3/cen3.out/bad.whirl
  [ -n "${4:-}" ] && sed -i "$4" cen3/cen3.out/bad.whirl
  (cd cen3/cen3.out && "$WHIRL" run bad.whirl --quiet --no-plot > ../../bad.log 2>&1)
  st=$?
  [ "$st" -eq 2 ] && grep -q "$2" bad.log && [ ! -e cen3/cen3.out/bad.out ]
  ok $? "$3: exit 2, '$2', nothing written (exit $st: $(head -c 200 bad.log))"
}
bad_run "HB_PERIOD = nosuch" "HB_PERIOD: 'nosuch' is not a parameter" "HB_PERIOD naming no parameter"
bad_run "HB_PERIOD = PAR(4)" "HB_PERIOD = PAR(4): its value at label 2 is 0, not a period" "HB_PERIOD of a parameter 0 at the label"
bad_run "HB_PERIOD = PAR(3)" "HB_PERIOD starts orbits at an equilibrium label" "HB_PERIOD at a label of orbits" "s/^S .*/S = 'cen3.2.out'/"
# bad input: one message naming the line, exit 2, no run written
sed -i "s/^TY = .*/TY = 'HBx'/" cenx/c.cenx.2
(cd cenx && "$WHIRL" auto . cenx --quiet > ../cenx.log 2>&1)
st=$?
[ "$st" -eq 2 ] && grep -q "c.cenx.2:4: TY = 'HBx'" cenx.log && [ ! -e cenx/cenx.out ]
ok $? "TY = 'HBx': exit 2, the line named, nothing written (exit $st: $(head -c 160 cenx.log))"
tap_end

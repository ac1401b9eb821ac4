#!/bin/sh
# test/regress/auto_isp.sh — AUTO's ISP as AUTO-07p's CHECKSP reads it
# (support.f90: which special points a run looks for), in `whirl auto`,
# on two problems written here with closed forms:
#  1. the Brusselator x' = a - (b + 1) x + x^2 y, y' = b x - x^2 y, a = 1,
#     its equilibrium (a, b/a) continued in b from 1.5: the Hopf point at
#     b = 1 + a^2 = 2 is labelled with ISP = 1 and 2, not with ISP = 0 or
#     3 (CHECKSP: HB, BT, ZH, GH and CP of equilibria where ISP is neither
#     0 nor 3; demo r3b's ISP = 3 runs label no HB in AUTO);
#  2. the boundary-value problem u1' = u2, u2' = -p sin(u1), u1(0) = u1(1)
#     = 0, continued in p along u = 0 from p = 5: its branch point at
#     p = pi^2 (where sin(pi t) bifurcates) is labelled with ISP = 2 and 3,
#     not with ISP = 1 or 4 (CHECKSP: BP of boundary-value problems and
#     orbits where |ISP| >= 2 and |ISP| /= 4);
#  3. x' = mu + lambda x - x^3 (the cusp's normal form): from its LP in mu
#     at lambda = 1, the fold curve lambda = 3 x^2, mu = -2 x^3 in (mu,
#     lambda) towards its cusp at 0: the CP there with ISP = 2, none with
#     ISP = 0 (CHECKSP: the loci's BT, ZH, GH, CP as HB).
# TAP output.
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
name=auto_isp
. "${top_srcdir:-.}/test/regress/tap.sh"

mkdir bru pend
cat > bru/bru.f90 <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = PAR(1) - (PAR(2) + 1) * U(1) + U(1)**2 * U(2)
      F(2) = PAR(2) * U(1) - U(1)**2 * U(2)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1
      PAR(2) = 1.5D0
      U(1) = 1
      U(2) = 1.5D0
      END SUBROUTINE STPNT
F
cat > pend/pend.f90 <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = U(2)
      F(2) = -PAR(1) * SIN(U(1))
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 5
      U(1) = 0
      U(2) = 0
      END SUBROUTINE STPNT
      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), NBC, IJAC
      DOUBLE PRECISION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
      FB(1) = U0(1)
      FB(2) = U1(1)
      END SUBROUTINE BCND
F
for isp in 0 1 2 3; do
  cat > bru/c.bru.$((isp + 1)) <<C
NDIM = 2, IPS = 1, IRS = 0, ILP = 1, ICP = [2], ISP = $isp, ISW = 1
NMX = 100, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-10
DS = 0.02, DSMIN = 1e-5, DSMAX = 0.05, NPAR = 2
UZSTOP = {2: 2.5}
C
  cat > pend/c.pend.$((isp + 1)) <<C
NDIM = 2, IPS = 4, IRS = 0, ILP = 1, ICP = [1], ISP = $((isp + 1)), ISW = 1
NTST = 20, NCOL = 4, IAD = 3, NBC = 2, NINT = 0, JAC = 0
NMX = 100, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-10
DS = 0.2, DSMIN = 1e-5, DSMAX = 0.5, NPAR = 1
UZSTOP = {1: 12}
C
done
mkdir cu
cat > cu/cu.f90 <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = PAR(2) + PAR(1) * U(1) - U(1)**3
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1
      PAR(2) = 0
      U(1) = 0
      END SUBROUTINE STPNT
F
# (ITNW = 8: at EPSL = 1e-10 Newton takes three iterations a step, which
# keep DS at AUTO's default ITNW = 5: AUTO-07p's own run of c.cu.1 then
# ends at NMX with its LP at PT 49, as whirl's, short of the UZSTOP)
cat > cu/c.cu.1 <<'C'
NDIM = 1, IPS = 1, IRS = 0, ILP = 1, ICP = [2], ISP = 2, ISW = 1, ITNW = 8
NMX = 200, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-10
DS = 0.01, DSMIN = 1e-5, DSMAX = 0.1, NPAR = 2
UZSTOP = {2: [-2, 2]}
C
for isp in 0 2; do
  cat > cu/c.cu.$((isp / 2 + 2)) <<C
NDIM = 1, IPS = 1, IRS = 2, ILP = 1, ICP = [2, 1], ISP = $isp, ISW = 2, ITNW = 8
NMX = 100, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-10
DS = -0.01, DSMIN = 1e-5, DSMAX = 0.1, NPAR = 2
C
done
"$WHIRL" auto bru --quiet --out=bru.out > bru.log 2>&1
ok $? "the Brusselator's four runs (exit $?$( [ -s bru.log ] && printf ': %s' "$(tail -1 bru.log)"))"
"$WHIRL" auto pend --quiet --out=pend.out > pend.log 2>&1
ok $? "the BVP's four runs (exit $?$( [ -s pend.log ] && printf ': %s' "$(tail -1 pend.log)"))"
# the points of types $2 (AUTO's type codes, as " 1 6 ") in b-file $1:
# their PAR column
pts() { awk -v t="$2" 'substr($0, 1, 4) + 0 != 0 && index(t, " " (substr($0, 11, 4) + 0) " ") { printf "%.12g ", substr($0, 20, 19) }' "$1" 2> /dev/null; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
for isp in 0 1 2 3; do
  hb=$(pts bru.out/b.bru.$((isp + 1)) " 3 ")
  case $isp in
  1 | 2) set -- $hb; [ $# = 1 ] && near "$1" 2 1e-8; ok $? "ISP = $isp: the HB at b = 1 + a^2 = 2 (${hb:-none})" ;;
  *) [ -z "$hb" ]; ok $? "ISP = $isp: no HB looked for (${hb:-none})" ;;
  esac
done
for isp in 1 2 3 4; do
  bp=$(pts pend.out/b.pend.$isp " 1 6 ")
  case $isp in
  2 | 3) set -- $bp; [ $# = 1 ] && near "$1" 9.86960440109 1e-7; ok $? "ISP = $isp: the BVP's BP at p = pi^2 = 9.8696044011 (${bp:-none})" ;;
  *) [ -z "$bp" ]; ok $? "ISP = $isp: no BP of the BVP looked for (${bp:-none})" ;;
  esac
done
"$WHIRL" auto cu --quiet --out=cu.out > cu.log 2>&1
ok $? "the cusp's LP run and its two fold loci (exit $?$( [ -s cu.log ] && printf ': %s' "$(tail -1 cu.log)"))"
# AUTO's CP on a fold locus of equilibria (ITPST 2): -22 (AUTO-07p's own
# demo cusp writes -22 there, and 24, -24 for its other points)
cp0=$(pts cu.out/b.cu.2 " -22 ") cp2=$(pts cu.out/b.cu.3 " -22 ")
set -- $cp2
[ $# = 1 ] && near "$1" 0 1e-8 && [ -z "$cp0" ]
ok $? "the fold locus's CP at mu = 0 with ISP = 2 (${cp2:-none}), none with ISP = 0 (${cp0:-none})"
# every labelled point of the fold loci as AUTO codes it there (24 every
# NPR steps, 29 at an end, -24 a UZ, -22 the CP), the run before plain (2
# its LP, 9 its ends, -4 its UZ), and AUTO's header line of a locus
loc=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 != 0 { printf "%d ", substr($0, 11, 4) }' cu.out/b.cu.2 cu.out/b.cu.3 2> /dev/null)
lp=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 != 0 { printf "%d ", substr($0, 11, 4) }' cu.out/b.cu.1 2> /dev/null)
echo "$loc" | grep -Eq '^((2[49]|-2[249]) )+$' && echo "$lp" | grep -Eq '^(-?[0-9] )+$' &&
  grep -q "^   0   Branch type:  2    TY = 'LP '" cu.out/b.cu.3
ok $? "the fold loci's codes 10 x 2 + type as AUTO's ($loc), the LP run's plain ($lp), 'Branch type:  2'"
tap_end

#!/bin/sh
# test/regress/auto_stpnt_start.sh — AUTO-07p's start of orbits from the
# equations' STPNT(T) (IPS = 2, IRS = 0) and its Newton test on orbits, in
# `whirl auto`, checked against AUTO-07p itself, never against whirl:
#  a cubic oscillator forced by the oscillator (sn, cs) of demo ffn,
#    x' = y, y' = -c y - x - k x^3 + a sn,
#    sn' = sn + beta cs - sn r2, cs' = cs - beta sn - cs r2 (r2 = sn^2 + cs^2),
#  written here, STPNT the orbit at a = 0 (x = y = 0, sn, cs = sin, cos of
#  2 pi T, period 2 pi / beta); c.osc.1 continues it in a (ICP = [1, 11],
#  THL = {11: 0}) on NTST 10 for 8 steps.
#  The reference rows are AUTO-07p 0.9.2's (the Debian package auto-07p,
#  `run(e='osc', c='osc.1')` on these very files), to 1e-6 relative in
#  every column:
#  - PT 1 is STPNT at the NTST NCOL + 1 equally spaced nodes of the
#    uniform mesh as they are (STPNUB; no mesh adapted to them, no Newton:
#    MAX U(3) = 1 exactly, sin at the node t = 1/4); whirl used to adapt a
#    mesh to the start and correct it, and its PT 2 differed in the 4th
#    digit;
#  - PT 2-9 as AUTO's, the meshes adapted at PT 3 and 6 included: AUTO's
#    NEWTONBV tests the period as a parameter (EPSL, its own scale) and the
#    node values to EPSU on their largest value before the correction;
#    whirl's period counted as a state value (scale 1 + T = 5.19 where
#    AUTO's is 2), so PT 5 converged in 2 iterations where AUTO takes 3,
#    the next step grew by 1.5 instead of 1.1, and PT 6-9 went elsewhere.
# TAP output.
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
name=auto_stpnt_start
. "${top_srcdir:-.}/test/regress/tap.sh"

mkdir "$tmp/osc"
cat > "$tmp/osc/osc.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      DOUBLE PRECISION R
      R = U(3)**2 + U(4)**2
      F(1) = U(2)
      F(2) = -PAR(2)*U(2) - U(1) - PAR(3)*U(1)**3 + PAR(1)*U(3)
      F(3) = U(3) + PAR(4)*U(4) - U(3)*R
      F(4) = U(4) - PAR(4)*U(3) - U(4)*R
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T, PI
      PI = 4.0D0*ATAN(1.0D0)
      PAR(1) = 0.0D0
      PAR(2) = 0.1D0
      PAR(3) = 0.5D0
      PAR(4) = 1.5D0
      PAR(11) = 2.0D0*PI/PAR(4)
      U(1) = 0.0D0
      U(2) = 0.0D0
      U(3) = SIN(2.0D0*PI*T)
      U(4) = COS(2.0D0*PI*T)
      END SUBROUTINE STPNT
      SUBROUTINE BCND
      END SUBROUTINE BCND
      SUBROUTINE ICND
      END SUBROUTINE ICND
      SUBROUTINE FOPT
      END SUBROUTINE FOPT
      SUBROUTINE PVLS
      END SUBROUTINE PVLS
F
cat > "$tmp/osc/c.osc.1" <<'C'
NDIM=   4, IPS =   2, IRS =   0, ILP =   0
ICP =  [1, 11]
NTST=  10, NCOL=   4, IAD =   3, ISP =   2, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=   9, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 0
EPSL= 1e-07, EPSU = 1e-07, EPSS =1e-07
DS  =  0.05, DSMIN=  0.001, DSMAX=  0.2, IADS=   1
NPAR = 11, THL =  {11: 0.0}, THU =  {}
C
(cd "$tmp" && "$WHIRL" auto osc --quiet > osc.log 2>&1)
ok $? "whirl auto osc (orbits from STPNT) exits 0: $(tail -1 "$tmp/osc.log")"

rows_agree() { awk -v b="$1" -f "$top_srcdir/test/regress/auto_rows.awk"; }
rows_agree "$tmp/osc.out/b.osc" > "$tmp/diff1" <<'R'
1 9 0.0000000000 1.0000000000 0.0000000000 0.0000000000 1.0000000000 1.0000000000 4.1887902048
R
rc=$? out=$(head -3 "$tmp/diff1" | tr '\n' ';')
ok $rc "PT 1: STPNT at the uniform mesh's nodes as they are, as AUTO's ${out:+($out)}"
rows_agree "$tmp/osc.out/b.osc" > "$tmp/diff2" <<'R'
2 0 0.0351302743 1.0006325763 0.0278908445 0.0418354181 0.9999998210 0.9999999943 4.1887902087
3 0 0.0877717765 1.0039525949 0.0697710682 0.1046433857 0.9999998210 0.9999999943 4.1887902087
4 0 0.1664454164 1.0142494351 0.1327889127 0.1988076202 0.9972242286 0.9999999828 4.1887902110
5 0 0.2832105793 1.0415526070 0.2283268777 0.3415873418 0.9972286113 0.9999999805 4.1887902110
R
rc=$? out=$(head -3 "$tmp/diff2" | tr '\n' ';')
ok $rc "PT 2-5: the first steps from it, the mesh adapted at PT 3, as AUTO's ${out:+($out)}"
rows_agree "$tmp/osc.out/b.osc" > "$tmp/diff3" <<'R'
6 0 0.4086944479 1.0877842848 0.3357043893 0.5015590798 0.9972472368 0.9999999324 4.1887902110
7 0 0.5382460793 1.1563591072 0.4555329858 0.6795252508 0.9973092043 0.9999994294 4.1887902098
8 0 0.6585079452 1.2445585254 0.5816091539 0.8649733566 0.9974290977 0.9999963133 4.1887902098
9 9 0.7639300170 1.3532596809 0.7163464376 1.0609735556 0.9976586918 0.9999820493 4.1887902098
R
rc=$? out=$(head -3 "$tmp/diff3" | tr '\n' ';')
ok $rc "PT 6-9: PT 5 in 3 Newton iterations (the period tested as a parameter), so the same steps as AUTO's ${out:+($out)}"
tap_end

#!/bin/sh
# test/regress/auto_udot.sh — AUTO's ICND gets UDOT, the direction vector
# of the branch ("derivative of UOLD with respect to arclength", AUTO-07p's
# ICND), not u'(t).  Bratu's problem u'' + lambda e^u = 0, u(0) = u(1) = 0,
# written here with the integral condition PAR(2) = INTEGRAL u UDOT(1)
# (PAR(2) free): with u' in place of UDOT the integral is (u(1)^2 -
# u(0)^2) / 2 = 0, and PAR(2) would be 0 at every point.  Seven steps of
# DS = DSMIN = DSMAX = 0.2 on a fixed mesh (IAD = 0), so both programs take
# the same steps; the reference rows are AUTO-07p 0.9.2's (the Debian
# package auto-07p, `run(e='udt', c='udt')` on these very files, b.udt),
# lambda and PAR(2) to 2e-6 relative at each point.  Then the same with
# AUTO's adapted meshes and adaptive steps, 24 points.  TAP output.
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
name=auto_udot
. "${top_srcdir:-.}/test/regress/tap.sh"

# against REF (AUTO's rows: PT, lambda, PAR(2)), the rows of b-file B with
# PT >= 2, lambda to LTOL and PAR(2) to QTOL relative, every one of AUTO's
# points there: nothing printed when they agree
against_auto() { # REF B LTOL QTOL
  awk '$1 == 1 && $2 >= 2 { print $2, $5, $NF }' "$2" |
    awk -v lt="$3" -v qt="$4" 'function rel(a, b) { d = a - b; if (d < 0) d = -d; if (b < 0) b = -b; return d / b }
      NR == FNR { l[$1] = $2; q[$1] = $3; nref++; next }
      ($1 in l) { seen++; if (rel($2, l[$1]) > lt || rel($3, q[$1]) > qt) printf "PT %s: %s %s against AUTO %s %s; ", $1, $2, $3, l[$1], q[$1] }
      END { if (seen != nref) printf "%d of AUTO %d points", seen, nref }' "$1" -
}

mkdir "$tmp/udt"
cat > "$tmp/udt/udt.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER, INTENT(IN) :: NDIM, ICP(*), IJAC
      DOUBLE PRECISION, INTENT(IN) :: U(NDIM), PAR(*)
      DOUBLE PRECISION, INTENT(OUT) :: F(NDIM)
      DOUBLE PRECISION, INTENT(INOUT) :: DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1)= U(2)
      F(2)=-PAR(1) * EXP(U(1))
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER, INTENT(IN) :: NDIM
      DOUBLE PRECISION, INTENT(INOUT) :: U(NDIM),PAR(*)
      DOUBLE PRECISION, INTENT(IN) :: T
      PAR(1)=0
      PAR(2)=0
      U(1)=0.0
      U(2)=0.0
      END SUBROUTINE STPNT
      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT NONE
      INTEGER, INTENT(IN) :: NDIM, ICP(*), NBC, IJAC
      DOUBLE PRECISION, INTENT(IN) :: PAR(*), U0(NDIM), U1(NDIM)
      DOUBLE PRECISION, INTENT(OUT) :: FB(NBC)
      DOUBLE PRECISION, INTENT(INOUT) :: DBC(NBC,*)
      FB(1)=U0(1)
      FB(2)=U1(1)
      END SUBROUTINE BCND
      SUBROUTINE ICND(NDIM,PAR,ICP,NINT,U,UOLD,UDOT,UPOLD,FI,IJAC,DINT)
      IMPLICIT NONE
      INTEGER, INTENT(IN) :: NDIM, ICP(*), NINT, IJAC
      DOUBLE PRECISION, INTENT(IN) :: PAR(*)
      DOUBLE PRECISION, INTENT(IN) :: U(NDIM), UOLD(NDIM), UDOT(NDIM), UPOLD(NDIM)
      DOUBLE PRECISION, INTENT(OUT) :: FI(NINT)
      DOUBLE PRECISION, INTENT(INOUT) :: DINT(NINT,*)
      FI(1)=U(1)*UDOT(1) - PAR(2)
      END SUBROUTINE ICND
      SUBROUTINE FOPT
      END SUBROUTINE FOPT
      SUBROUTINE PVLS
      END SUBROUTINE PVLS
F
cat > "$tmp/udt/c.udt" <<'C'
NDIM=   2, IPS =   4, IRS =   0, ILP =   0
ICP =  [1, 2]
NTST=  10, NCOL=   4, IAD =   0, ISP =   0, ISW = 1, IPLT= 0, NBC= 2, NINT= 1
NMX=  8, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS =0.0001
DS  =  0.2, DSMIN= 0.2, DSMAX=   0.2, IADS=   1
NPAR = 2, THL =  {}, THU =  {}
C
(cd "$tmp" && "$WHIRL" auto udt --quiet > udt.log 2>&1)
ok $? "whirl auto udt exits 0 $(head -1 "$tmp/udt.log")"
grep -q '^UDOT = direction$' "$tmp/udt.out/udt.whirl"
ok $? "udt.whirl: UDOT = direction (AUTO's ICND)"
# AUTO-07p's b.udt: PT, lambda, PAR(2)
cat > "$tmp/ref" <<'R'
2 1.9110258157E-001 1.5545751559E-003
3 3.8151491739E-001 3.2255047235E-003
4 5.7114389324E-001 5.1190651690E-003
5 7.5988274130E-001 7.2385900860E-003
6 9.4760394442E-001 9.6204893185E-003
7 1.1341541371E+000 1.2308699844E-002
8 1.3193473782E+000 1.5356609941E-002
R
out=$(against_auto "$tmp/ref" "$tmp/udt.out/b.udt" 2e-6 2e-6)
[ -z "$out" ]
ok $? "b.udt: lambda and PAR(2) = INTEGRAL u UDOT(1) at PT 2-8 as AUTO's to 2e-6 (PAR(2) 1.5546e-3 ... 1.5357e-2, not 0) ${out:+($out)}"
# the same with AUTO's adapted meshes (IAD = 3: the direction, the secant
# of the last two points, taken on each new mesh) and adaptive steps (DS
# 0.05 to 0.5): AUTO-07p's 24 points after the start, lambda to 1e-6 and PAR(2)
# to 5e-6 relative (at PT 25, lambda 3.455, they differ by 1.4e-7 and
# 1.3e-6: the integrals by Gauss points, AUTO's by the nodes)
mkdir "$tmp/ud2"
cp "$tmp/udt/udt.f90" "$tmp/ud2/ud2.f90"
sed -e 's/IAD =   0/IAD =   3/' -e 's/NMX=  8/NMX= 25/' -e 's/ILP =   0/ILP =   1/' \
    -e 's/EPSS =0.0001/EPSS = 1e-6/' \
    -e 's/DS  =  0.2, DSMIN= 0.2, DSMAX=   0.2/DS  =  0.05, DSMIN= 0.001, DSMAX=   0.5/' \
    "$tmp/udt/c.udt" > "$tmp/ud2/c.ud2"
(cd "$tmp" && "$WHIRL" auto ud2 --quiet > ud2.log 2>&1)
ok $? "whirl auto ud2 (IAD = 3, adaptive steps) exits 0 $(head -1 "$tmp/ud2.log")"
cat > "$tmp/ref2" <<'R'
2 4.7835368242E-002 3.8338546844E-004
3 1.0040702759E-001 8.1268311667E-004
4 1.5817855619E-001 1.3001908503E-003
5 2.2165539921E-001 1.8535178335E-003
6 2.9138946750E-001 2.4837321585E-003
7 3.6798250545E-001 3.2043165063E-003
8 4.5208931084E-001 4.0318477816E-003
9 5.4442059552E-001 4.9869116566E-003
10 6.4574514005E-001 6.0953547778E-003
11 7.5689069126E-001 7.3900257334E-003
12 8.7874271905E-001 8.9132372981E-003
13 1.0122395930E+000 1.0720314975E-002
14 1.1583617845E+000 1.2884818453E-002
15 1.3181110105E+000 1.5506403101E-002
16 1.4924721317E+000 1.8722959506E-002
17 1.6823447136E+000 2.2729887270E-002
18 1.8884194088E+000 2.7811630705E-002
19 2.1109499201E+000 3.4394924621E-002
20 2.3493183644E+000 4.3141470572E-002
21 2.6011734239E+000 5.5112845575E-002
22 2.8606591217E+000 7.2061950412E-002
23 3.1147725692E+000 9.6895535503E-002
24 3.3195045605E+000 1.3174425217E-001
25 3.4552174004E+000 1.7742851121E-001
R
out=$(against_auto "$tmp/ref2" "$tmp/ud2.out/b.ud2" 1e-6 5e-6)
[ -z "$out" ]
ok $? "b.ud2: AUTO's steps on AUTO's meshes, lambda and PAR(2) at PT 2-25 as AUTO's ${out:+($out)}"
tap_end

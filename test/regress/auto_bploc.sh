#!/bin/sh
# test/regress/auto_bploc.sh — loci of branch points of periodic orbits and
# of boundary-value problems by `whirl auto` (AUTO's ISW = 2 and 3 at a BP
# of IPS = 2 or 4: a run of starting data, then the locus from its EP, as
# AUTO's constants files run them), on equations written here whose loci
# are known in closed form:
#  - circ: u' = -u g(r) + 2 pi J u, g = (r - p1)(r - p2) + p3, r = |u|: the
#    circles r = p1 and r = p2 of period 1 cross at p1 = p2 (p3 = 0), a
#    branch point of orbits in p1; ISW = 2 (the unfolding beta) along p2:
#    p1 = p2, MAX U(1) = p1 (the radius), PERIOD = 1; ISW = 3 with p3 the
#    third parameter: the same, p3 = 0; PVLS's PAR(4) = GETP('MAX', 1, U)
#    the radius p1 along the loci;
#  - tb: u1'' = -p1 p2 u1 - u1^3, u1(0) = u1(1) = 0: the trivial solution
#    branches at p1 p2 = pi^2 (symmetric, u1 -> -u1); ISW = 2 along p2:
#    p1 p2 = pi^2.
# Before 2026-12-06 whirl refused ISW = 2 at a BP of orbits or of a BVP.
# TAP output.
set -u
: "${top_srcdir:=.}" "${top_builddir:=.}"
WHIRL="$(cd "$top_builddir" && pwd)/drivers/whirl"
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
check() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fail=1; fi; }

# constants: $1 NDIM, IPS, IRS, ISW, ICP, NMX, DS, DSMAX, NPAR, NBC
consts() {
  cat <<C
NDIM=   $1, IPS =   $2, IRS =   $3, ILP =   1
ICP =  $5
NTST=  20, NCOL=   4, IAD =   3, ISP =   2, ISW = $4, IPLT= 0, NBC= ${10}, NINT= 0
NMX=   $6, NPR=  100, MXBF=   0, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 0
EPSL= 1e-08, EPSU = 1e-08, EPSS = 1e-06
DS  =  $7, DSMIN= 1e-05, DSMAX=   $8, IADS=   1
NPAR = $9, THL =  {}, THU =  {}
C
}

circ_f90() {
  cat <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      DOUBLE PRECISION R, G, PI
      PI = 4 * ATAN(1.D0)
      R = SQRT(U(1)**2 + U(2)**2)
      G = (R - PAR(1)) * (R - PAR(2)) + PAR(3)
      F(1) = -U(1) * G - 2 * PI * U(2)
      F(2) = -U(2) * G + 2 * PI * U(1)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T, PI
      PI = 4 * ATAN(1.D0)
      PAR(1) = 1
      PAR(2) = 2
      PAR(3) = 0
      PAR(11) = 1
      U(1) = COS(2 * PI * T)
      U(2) = SIN(2 * PI * T)
      END SUBROUTINE STPNT
      SUBROUTINE PVLS(NDIM,U,PAR)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), GETP
      PAR(4) = GETP('MAX', 1, U)
      END SUBROUTINE PVLS
F
}

# the largest deviation over the locus's rows of branches.tsv: awk
# expression $2 in the columns' names h[]
worst() {
  awk -F'\t' -v e="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
    { split(e, t, ";"); for (k in t) { split(t[k], ab, "="); v = $h[ab[1]] - (ab[2] ~ /^[A-Za-z]/ ? $h[ab[2]] : ab[2]);
        if (v < 0) v = -v; if (v > m) m = v } ; rows++ }
    END { printf "%d %.3g\n", rows, m + 0 }' "$1" 2>/dev/null
}

for g in 2 3; do
  d=circ$g
  mkdir "$tmp/$d"
  circ_f90 > "$tmp/$d/$d.f90"
  icp="[1, 2, 11]"; [ $g = 3 ] && icp="[1, 2, 3, 11]"
  consts 2 2 0 1 "[1, 11]" 30 0.05 0.1 11 0 > "$tmp/$d/c.$d.1"
  consts 2 2 2 $g "$icp" 30 0.05 0.1 11 0 > "$tmp/$d/c.$d.2"  # label 2: the BP
  consts 2 2 4 $g "$icp" 20 0.05 0.1 11 0 > "$tmp/$d/c.$d.3"  # label 4: its starting data
  (cd "$tmp" && "$WHIRL" auto $d --quiet > $d.log 2>&1)
  rc=$?
  r=$(worst "$tmp/$d.out/$d.3.out/branches.tsv" "PAR(1)=PAR(2);max_U(1)=PAR(1);period=1;PAR(3)=0")
  echo "$r" | awk -v rc=$rc '{ exit !(rc == 0 && $1 >= 20 && $2 < 1e-8) }'
  check $? "circ, ISW = $g: the locus of the orbits' BP along p2 is p1 = p2, MAX U(1) = p1, PERIOD = 1, p3 = 0 (exit $rc; rows, largest deviation: $r)"
  r=$(worst "$tmp/$d.out/$d.3.out/branches.tsv" "PAR(4)=PAR(1)")
  echo "$r" | awk '{ exit !($1 >= 20 && $2 < 1e-6) }'
  check $? "circ, ISW = $g: PVLS's PAR(4) = GETP('MAX', 1, U) is the radius p1 at every point of the locus, as AUTO calls PVLS there ($r)"
done
grep -q " 0 special points" "$tmp/circ2.out/circ2.3.out/run.log"
check $? "circ: no special point labelled on the locus (a line in (p1, p2))"

mkdir "$tmp/tb"
cat > "$tmp/tb/tb.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = U(2)
      F(2) = -PAR(1) * PAR(2) * U(1) - U(1)**3
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 8
      PAR(2) = 1
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
consts 2 4 0 1 "[1]" 20 0.2 0.5 2 2 > "$tmp/tb/c.tb.1"
consts 2 4 2 2 "[1, 2]" 20 0.05 0.1 2 2 > "$tmp/tb/c.tb.2"
consts 2 4 4 2 "[1, 2]" 20 0.05 0.1 2 2 > "$tmp/tb/c.tb.3"
(cd "$tmp" && "$WHIRL" auto tb --quiet > tb.log 2>&1)
rc=$?
r=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
  { v = $h["PAR(1)"] * $h["PAR(2)"] - 9.869604401089358; if (v < 0) v = -v; if (v > m) m = v; rows++ }
  END { printf "%d %.3g\n", rows, m + 0 }' "$tmp/tb.out/tb.3.out/branches.tsv" 2>/dev/null)
echo "$r" | awk -v rc=$rc '{ exit !(rc == 0 && $1 >= 20 && $2 < 1e-8) }'
check $? "tb (IPS = 4), ISW = 2: the locus of the trivial solution's BP is p1 p2 = pi^2 (exit $rc; rows, largest deviation: $r)"
echo "1..$n"
exit $fail

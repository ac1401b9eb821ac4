#!/bin/sh
# test/regress/auto_getp_eig.sh — AUTO's GETP('EIG', I, U) in a PVLS at
# equilibria, through `whirl auto` (drivers/auto_adapter.c): the real
# (I odd) and imaginary part (I even) of eigenvalue (I + 1) / 2 of the
# Jacobian, in AUTO's order (decreasing real part; in a system that looks
# conservative, the eigenvalues on the imaginary axis by decreasing
# |imaginary part|).  Demo r3b's PVLS reads them so; whirl returned 0
# until 2026-12-07.  Two problems with closed-form eigenvalues:
#  1. u1' = p u1 - 2 u2, u2' = 2 u1 + p u2, u3' = -u3 at u = 0, continued
#     in p = PAR(1): eigenvalues p +- 2i and -1.  At p = -1.5 the first is
#     -1 (imaginary part 0) and the third's real part -1.5; at p = 0.5 the
#     first is 0.5 with imaginary part -2 (LAPACK lists a pair's positive
#     imaginary part first, and AUTO's ordering takes the later of two
#     equal real parts first), the third -1.
#  2. two oscillators u1'' = -a^2 u1, u3'' = -4 u3 (a = PAR(1)): trace 0,
#     eigenvalues +-ia, +-2i; the first by |imaginary part|: 2 at a = 1,
#     3 at a = 3.
# TAP output.
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
name=auto_getp_eig
. "${top_srcdir:-.}/test/regress/tap.sh"

mkdir lin osc
cat > lin/lin.f90 <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = PAR(1) * U(1) - 2 * U(2)
      F(2) = 2 * U(1) + PAR(1) * U(2)
      F(3) = -U(3)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = -2
      U(1) = 0
      U(2) = 0
      U(3) = 0
      END SUBROUTINE STPNT
      SUBROUTINE PVLS(NDIM,U,PAR)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), GETP
      PAR(2) = GETP('EIG', 1, U)
      PAR(3) = GETP('EIG', 2, U)
      PAR(4) = GETP('EIG', 5, U)
      END SUBROUTINE PVLS
F
cat > osc/osc.f90 <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = U(2)
      F(2) = -PAR(1)**2 * U(1)
      F(3) = U(4)
      F(4) = -4 * U(3)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 0.5D0
      U(1) = 0
      U(2) = 0
      U(3) = 0
      U(4) = 0
      END SUBROUTINE STPNT
      SUBROUTINE PVLS(NDIM,U,PAR)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), GETP
      PAR(2) = ABS(GETP('EIG', 2, U))
      END SUBROUTINE PVLS
F
cat > lin/c.lin <<C
NDIM = 3, IPS = 1, IRS = 0, ILP = 0, ICP = [1, 2, 3, 4], ISP = 0, ISW = 1
NMX = 100, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS = 0.1, DSMIN = 1e-5, DSMAX = 0.2, NPAR = 4
UZR = {1: [-1.5, 0.5]}, UZSTOP = {1: 1}
C
cat > osc/c.osc <<C
NDIM = 4, IPS = 1, IRS = 0, ILP = 0, ICP = [1, 2], ISP = 0, ISW = 1
NMX = 100, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS = 0.1, DSMIN = 1e-5, DSMAX = 0.2, NPAR = 2
UZR = {1: [1, 3]}, UZSTOP = {1: 3.5}
C

# the b-file's row of the UZ at PAR(1) = $2 in $1: its columns from PAR(1)
uz_row() {
  awk -v p="$2" '$3 == -4 || $3 == 4 { d = $5 - p; if (d < 0) d = -d; if (d < 1e-9) { $1 = $2 = $3 = $4 = ""; print; exit } }' "$1"
}
# are the values $2.. within $1 of the row's columns (PAR(1), L2-NORM,
# U(1..n), then the ICP parameters): "col=value col=value ..."
near() {
  row=$1 tol=$2; shift 2
  echo "$row" | awk -v tol="$tol" -v want="$*" '{ n = split(want, w, " ")
    for (i = 1; i <= n; i++) { split(w[i], kv, "="); d = $kv[1] - kv[2]; if (d < 0) d = -d; if (d > tol) exit 1 } }'
}

(cd lin && "$WHIRL" auto . lin --quiet > ../lin.log 2>&1)
ok $? "lin: whirl auto exit 0"
r1=$(uz_row lin/lin.out/b.lin -1.5)
r2=$(uz_row lin/lin.out/b.lin 0.5)
# columns: PAR(1) L2-NORM U(1) U(2) U(3) PAR(2) PAR(3) PAR(4)
near "$r1" 1e-7 6=-1 7=0 8=-1.5
ok $? "lin, p = -1.5: eigenvalue 1 is -1 + 0i, eigenvalue 3's real part -1.5 (the row: $r1)"
near "$r2" 1e-7 6=0.5 7=-2 8=-1
ok $? "lin, p = 0.5: eigenvalue 1 is 0.5 - 2i, eigenvalue 3's real part -1 (the row: $r2)"

(cd osc && "$WHIRL" auto . osc --quiet > ../osc.log 2>&1)
ok $? "osc: whirl auto exit 0"
r1=$(uz_row osc/osc.out/b.osc 1)
r2=$(uz_row osc/osc.out/b.osc 3)
# columns: PAR(1) L2-NORM U(1..4) PAR(2)
near "$r1" 1e-6 7=2
ok $? "osc, a = 1: trace 0, the first eigenvalue by |imaginary part| is 2i (the row: $r1)"
near "$r2" 1e-6 7=3
ok $? "osc, a = 3: the first is 3i (the row: $r2)"
tap_end

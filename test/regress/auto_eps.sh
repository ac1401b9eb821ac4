#!/bin/sh
# test/regress/auto_eps.sh — EPSL and EPSU as AUTO-07p reads them: a
# Newton correction has converged when the free parameter's change is
# within EPSL of (1 + |PAR|) and the state's within EPSU of (1 + max |U|),
# each part to its own scale (until 2026-12-05 whirl tested both against
# min(EPSL, EPSU) and the largest of all unknowns, so where the parameter
# outgrew the state a correction stopped an iteration early and the next
# step grew by AUTO's ADPTDS factor for two iterations, not three).
# Checked against AUTO-07p itself, never against whirl: Bratu's problem
# u'' + PAR(1) e^u = 0, u(0) = u(1) = 0, written here, by collocation on
# NTST 5, NCOL 4 with IAD = 3, EPSL = EPSU = 1e-6, from PAR(1) = 0 for 20
# points.  The reference column is PAR(1) of every point of AUTO-07p
# 0.9.2's run of these very files (the Debian package auto-07p,
# `run(e='brt', c='brt')`, fort.7); whirl's points must be AUTO's to 1e-6
# relative, the Newton tolerance.  (With the old test PT 12 was at
# PAR(1) = 1.6038 where AUTO's is 1.42795, and every later point apart.)
# And `whirl auto .` in the problem's directory takes its real name.
# TAP output.
set -u
: "${top_srcdir:=.}" "${top_builddir:=.}"
WHIRL="$(cd "$top_builddir" && pwd)/drivers/whirl"
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/brt"
cat > "$tmp/brt/brt.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), IJAC
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = U(2)
      F(2) = -PAR(1) * EXP(U(1))
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 0
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
cat > "$tmp/brt/c.brt" <<'C'
NDIM=   2, IPS =   4, IRS =   0, ILP =   1
ICP =  [1]
NTST=   5, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 0, NBC= 2, NINT= 0
NMX=   20, NPR=   50, MXBF=  10, IID =   2, ITMX= 8, ITNW= 5, NWTN= 3, JAC= 0
EPSL= 1e-06, EPSU = 1e-06, EPSS =1e-10
DS  =  0.01, DSMIN= 0.001, DSMAX=   1.0, IADS=   1
NPAR = 1, THL =  {}, THU =  {}
C
n=0 fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
(cd "$tmp" && "$WHIRL" auto brt --quiet --out=brt.out > brt.log 2>&1)
ok $? "whirl auto brt exits 0: $(tail -1 "$tmp/brt.log")"
# AUTO-07p's PT and PAR(1)
cat > "$tmp/auto" <<'R'
1 0.0000000000E+000
2 9.5701783284E-003
3 2.3922541752E-002
4 4.5444493081E-002
5 7.7712386656E-002
6 1.2607972053E-001
7 1.9855070231E-001
8 3.0706867309E-001
9 4.6939058968E-001
10 7.1173168225E-001
11 1.0721916454E+000
12 1.4279546776E+000
13 1.7773294083E+000
14 2.1178153290E+000
15 2.4454841053E+000
16 2.7539567082E+000
17 3.0327081398E+000
18 3.2650139302E+000
19 3.4286534336E+000
20 3.5065658449E+000
R
awk 'substr($0, 1, 4) + 0 != 0 { printf "%d %.17g\n", substr($0, 5, 6), substr($0, 20, 19) }' \
  "$tmp/brt.out/b.brt" > "$tmp/whirl" 2> /dev/null
bad=$(awk 'NR == FNR { a[$1] = $2; next }
  { if (!($1 in a)) { print "PT " $1 " missing in the run of whirl"; exit }
    d = a[$1] - $2; if (d < 0) d = -d
    if (d > 1e-6 * (1 + ($2 < 0 ? -$2 : $2))) { print "PT " $1 ": whirl " a[$1] ", AUTO " $2; exit } }' \
  "$tmp/whirl" "$tmp/auto")
ok "$([ -z "$bad" ] && echo 0 || echo 1)" "every one of AUTO's 20 points at AUTO's PAR(1) to 1e-6 relative${bad:+ ($bad)}"
# the problem's name from the directory's real name: `whirl auto .` in it
# (it looked for c.. and c...1)
(cd "$tmp/brt" && "$WHIRL" auto . --quiet --out="$tmp/dot.out" > "$tmp/dot.log" 2>&1)
rc=$?
[ $rc -eq 0 ] && [ -f "$tmp/dot.out/b.brt" ]
ok $? "whirl auto . in the demo's directory runs brt: exit $rc $(head -c 200 "$tmp/dot.log")"
echo "1..$n"
[ "$fails" -eq 0 ]

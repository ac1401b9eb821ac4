#!/bin/sh
# test/regress/auto_steps.sh — `whirl auto` takes AUTO-07p's steps, meshes
# and orbit phase, so its points are AUTO's, point for point; checked
# against AUTO-07p itself, never against whirl:
#  the Brusselator u1' = a - (b + 1) u1 + u1^2 u2, u2' = b u1 - u1^2 u2
#  (a = PAR(2) = 1, b = PAR(1)), written here, run 1 its equilibria from
#  b = 1.5 through the Hopf point b = 1 + a^2 = 2 to the stop at b = 2.2,
#  run 2 the orbits from that HB with user points at b = 2.05 and 2.2.
#  The reference rows are AUTO-07p 0.9.2's (the Debian package auto-07p,
#  `r1 = run(e='bru', c='bru.1'); run(r1('HB1'), c='bru.2')` on these very
#  files, b.bru), to 1e-6 relative in every column:
#  - run 1: AUTO's second point is two steps from the start (its CNRLAE
#    lists no point after the first step): b = 1.52828 at DS = 0.02 along
#    the tangent (1 step: 1.51414); the HB at PT 10, the UZ at PT 13;
#  - run 2: the orbits start in AUTO's phase (its null vector of the Hopf
#    eigenproblem, STHOPF) on AUTO's adapted meshes (EQDF), MAX U(i) over
#    the nodes as AUTO's; a user point ends its step and starts the next
#    at the step that passed it (LCSPBV), the steps grow as AUTO's ADPTDS:
#    PT 2, 3, 17, the UZ at PT 18, then 19, 20, 27 and the UZ at PT 28.
#    (Past PT 28 the two step sequences part: AUTO's last location step
#    there took two Newton iterations, whirl's localisation one.)
#  And the run-file keys `whirl auto` writes for it (MESH_RULE = jumps,
#  ORBIT_MAX = nodes), their input errors, and the curve's maximum (the
#  default) against the nodes'.
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
. "$top_srcdir/test/regress/fmodel.sh" # fmodel: a one-line model's equations file

mkdir "$tmp/bru"
cat > "$tmp/bru/bru.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = PAR(2) - (PAR(1) + 1)*U(1) + U(1)**2*U(2)
      F(2) = PAR(1)*U(1) - U(1)**2*U(2)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1.5D0
      PAR(2) = 1
      U(1) = 1
      U(2) = 1.5D0
      END SUBROUTINE STPNT
F
cat > "$tmp/bru/c.bru.1" <<'C'
NDIM=   2, IPS =   1, IRS =   0, ILP =   1
ICP =  [1]
NTST=  20, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  20, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 5, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS  =  0.02, DSMIN= 0.001, DSMAX=   0.1, IADS=   1
NPAR = 11, THL =  {}, THU =  {}
UZSTOP = {1: 2.2}
C
cat > "$tmp/bru/c.bru.2" <<'C'
NDIM=   2, IPS =   2, IRS =   2, ILP =   1
ICP =  [1, 11]
NTST=  20, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  40, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 5, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS  =  0.02, DSMIN= 0.001, DSMAX=   0.2, IADS=   1
NPAR = 11, THL =  {11: 0.0}, THU =  {}
UZR = {1: [2.05, 2.2]}
C
# c.bru.3: run 2 to its NMX = 20 (the points AUTO's run 2 has there);
# c.bru.4: from its end point (EP) on along the direction stored with it
sed 's/NMX=  40/NMX=  20/' "$tmp/bru/c.bru.2" > "$tmp/bru/c.bru.3"
cat > "$tmp/bru/c.bru.4" <<'C'
NDIM=   2, IPS =   2, IRS =   5, ILP =   1
ICP =  [1, 11]
NTST=  20, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  8, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 5, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS  =  0.2, DSMIN= 0.001, DSMAX=   0.5, IADS=   1
NPAR = 11, THL =  {11: 0.0}, THU =  {}
C
(cd "$tmp" && "$WHIRL" auto bru --runs=bru.1,bru.2@HB1 --quiet > bru.log 2>&1)
check $? "whirl auto bru (equilibria, then the orbits from the HB) exits 0: $(tail -1 "$tmp/bru.log")"

# compare the rows "PT TY v1 v2 ..." of AUTO (stdin) with b-file $1 of whirl
# (|PT|, its type code, the values), every value to 1e-6 relative
rows_agree() { awk -v b="$1" -f "$top_srcdir/test/regress/auto_rows.awk"; }
out=$(rows_agree "$tmp/bru.out/b.bru.1" <<'R'
2 0 1.5282842741 1.8263769661 1.0000000000 1.5282842741
3 0 1.5565685482 1.8501096306 1.0000000000 1.5565685482
9 0 1.9666905223 2.2063253637 1.0000000000 1.9666905223
10 3 1.9999999968 2.2360679746 1.0000000000 1.9999999968
11 0 2.0707106820 2.2995309801 1.0000000000 2.0707106820
13 -4 2.1999999988 2.4166091936 1.0000000000 2.1999999988
R
)
check $? "run 1 (equilibria): the second point two steps out, the HB at PT 10 and the UZ at PT 13, as AUTO's ${out:+($out)}"
out=$(rows_agree "$tmp/bru.out/b.bru.2@HB1" <<'R'
2 0 2.0002000126 2.2363363257 1.0165097130 2.0232038729 6.2832551398
3 0 2.0007996241 2.2371408356 1.0333748480 2.0466059043 6.2834646685
17 0 2.0476024891 2.3001199944 1.3001228483 2.3857595601 6.3006753832
18 -4 2.0500000000 2.3033563864 1.3089999350 2.3961507154 6.3016038419
19 0 2.0618244484 2.3193335872 1.3509404357 2.4450234646 6.3062520502
20 0 2.0745880251 2.3366091066 1.3934944576 2.4938511679 6.3114002674
27 0 2.1831068683 2.4848164918 1.7064760470 2.8290759917 6.3610512528
28 -4 2.1999999995 2.5081124993 1.7513445765 2.8744535975 6.3697905906
R
)
check $? "run 2 (orbits): PT 2-3, 17-20 and 27-28 with their MAX U(1), MAX U(2) and the UZs at PT 18, 28 as AUTO's ${out:+($out)}"

# AUTO stores with a point of orbits the direction its step was predicted
# along (UDOTPS, the secant of the step before: CONTBV runs after STPLBV),
# and a restart steps along it; the tangent at the point (stored before
# 2026-12-06) sent c.bru.4's first step to PAR(1) = 2.149878 and every
# later point off AUTO's.  AUTO-07p's rows: r2 = run(r1('HB1'), c='bru.3');
# run(r2, c='bru.4') on these files.
(cd "$tmp" && "$WHIRL" auto bru --runs=bru.1,bru.3@HB1,bru.4@EP2 --out=restart.out --quiet > restart.log 2>&1)
check $? "whirl auto bru: run 2 to NMX = 20, then on from its end point, exits 0: $(tail -1 "$tmp/restart.log")"
out=$(rows_agree "$tmp/restart.out/b.bru.4@EP2" <<'R'
2 0 2.1507343538 2.4403464808 1.6187369918 2.7381509095 6.3450901871
3 0 2.2393778497 2.5626571882 1.8529622566 2.9771121937 6.3912932850
5 0 2.4330632581 2.8357451462 2.3402498602 3.4405138186 6.5219320965
8 9 2.7387987615 3.2803831771 3.0976535252 4.1314342522 6.8185105593
R
)
check $? "the restart from the end point of orbits steps along AUTO's stored secant: PT 2, 3, 5, 8 as AUTO's ${out:+($out)}"

# a one-dimensional demo NAME: FUNC's F(1) = $2, STPNT's U(1) = 1,
# PAR(1) = 0, and the Fortran $3 after them (BCND)
scalar_demo() {
  mkdir "$tmp/$1"
  cat > "$tmp/$1/$1.f90" <<F
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = $2
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 0
      U(1) = 1
      END SUBROUTINE STPNT
$3
F
}

# No turn limit, as AUTO's ADPTDS: the constant solutions u of u' = 0 with
# u(0)^2 + PAR(1)^2 = 1 (NBC = 1), a circle in (PAR(1), u), continued by
# steps of 0.6 to 0.9, turning its secant by as many radians a step.  Until
# 2026-12-06 run files halved a step that turned more than 0.5 rad (PT 2
# at PAR(1) = 0.3 where AUTO's is at 0.6).  AUTO-07p's rows:
# run(e='cbv', c='cbv.1') on these files.
scalar_demo cbv 0 "      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), NBC, IJAC
      DOUBLE PRECISION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
      FB(1) = U0(1)**2 + PAR(1)**2 - 1
      END SUBROUTINE BCND"
cat > "$tmp/cbv/c.cbv.1" <<'C'
NDIM=   1, IPS =   4, IRS =   0, ILP =   0
ICP =  [1]
NTST=   4, NCOL=   2, IAD =   0, ISP =   0, ISW = 1, IPLT= 0, NBC= 1, NINT= 0
NMX=  12, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 5, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS  =  0.6, DSMIN= 0.001, DSMAX=   0.9, IADS=   1
NPAR = 11, THL =  {}, THU =  {}
C
(cd "$tmp" && "$WHIRL" auto cbv --quiet > cbv.log 2>&1)
check $? "whirl auto cbv (a circle of constant solutions of a BVP, long steps) exits 0: $(tail -1 "$tmp/cbv.log")"
out=$(rows_agree "$tmp/cbv.out/b.cbv.1" <<'R'
2 0 6.0000005001E-001 7.9999996249E-001 7.9999996249E-001
3 0 8.3365591488E-001 5.5228418010E-001 5.5228418010E-001
4 0 9.0888604603E-001 4.1704454838E-001 4.1704454838E-001
9 0 9.4626546508E-001 3.2339089287E-001 -3.2339089287E-001
12 9 7.0739520286E-001 7.0681824182E-001 -7.0681824182E-001
R
)
check $? "steps that turn by 0.6 rad and more are AUTO's, not halved: PT 2-4, 9 and the EP at PT 12 as AUTO's ${out:+($out)}"

# AUTO's algebraic corrector (ae.f90, SOLVAE): the next point at distance
# DS from the last on the secant's prediction, a sphere about it, not the
# tangent's hyperplane: x^2 + PAR(1)^2 = 1 from (1, 0), DS = 0.1, so each
# step turns the branch by 2 asin(DS/2).  Until 2026-12-06 whirl predicted
# along the tangent onto its hyperplane: PT 2 (two steps out) at PAR(1) =
# 0.198997 where AUTO's is at 0.198751, and every later point off AUTO's.
# AUTO-07p's rows: run(e='circ', c='circ.1') on these files.
scalar_demo circ "U(1)**2 + PAR(1)**2 - 1" ""
cat > "$tmp/circ/c.circ.1" <<'C'
NDIM=   1, IPS =   1, IRS =   0, ILP =   0
ICP =  [1]
NTST=  20, NCOL=   4, IAD =   3, ISP =   0, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  12, NPR=  100, MXBF=  10, IID =   2, ITMX= 8, ITNW= 5, NWTN= 3, JAC= 0
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS  =  0.1, DSMIN= 0.001, DSMAX=   0.8, IADS=   1
NPAR = 11, THL =  {}, THU =  {}
C
# c.circ.2: DS = 0.3 past DSMAX = 0.1: AUTO's first steps take DS as
# given (RDS = DS; only ADPTDS clips to DSMAX), whirl clipped it before
# 2026-12-06 (PT 2 at PAR(1) = 0.1987 where AUTO's is at 0.5665)
sed -e 's/NMX=  12/NMX=   8/' -e 's/DS  =  0.1, DSMIN= 0.001, DSMAX=   0.8/DS  =  0.3, DSMIN= 0.001, DSMAX=   0.1/' \
  "$tmp/circ/c.circ.1" > "$tmp/circ/c.circ.2"
(cd "$tmp" && "$WHIRL" auto circ --quiet > circ.log 2>&1)
check $? "whirl auto circ (equilibria on a circle) exits 0: $(tail -1 "$tmp/circ.log")"
out=$(rows_agree "$tmp/circ.out/b.circ.1" <<'R'
2 0 1.9875111396E-001 9.8004999602E-001 9.8004999602E-001
3 0 2.9563978465E-001 9.5529949112E-001 9.5529949112E-001
6 0 5.6484907166E-001 8.2519423547E-001 8.2519423547E-001
9 0 7.8356027678E-001 6.2131577531E-001 6.2131577531E-001
12 9 9.3222039568E-001 3.6189105250E-001 3.6189105250E-001
R
)
check $? "equilibria step as AUTO's (the secant's prediction onto the sphere of radius DS): PT 2, 3, 6, 9 and the EP at PT 12 as AUTO's ${out:+($out)}"
out=$(rows_agree "$tmp/circ.out/b.circ.2" <<'R'
2 0 5.6651712610E-001 8.2404996562E-001 8.2404996562E-001
3 0 6.4598647397E-001 7.6334885567E-001 7.6334885567E-001
5 0 7.1897420566E-001 6.9503675557E-001 6.9503675557E-001
8 9 8.1477496546E-001 5.7977733283E-001 5.7977733283E-001
R
)
check $? "DS past DSMAX: the first two steps at DS, then DSMAX, as AUTO's: PT 2, 3, 5 and the EP at PT 8 ${out:+($out)}"

# AUTO's algebraic step rules and defaults: u' = p u - u^2 + u^3/3 from
# p = -0.5, u = 0, switched by MXBF = -1 at the transcritical BP at p = 0 onto
# u = 3/2 - sqrt(9/4 - 3p) ... whose fold is at p = 3/4, u = 3/2.  The
# constants leave ITNW, ITMX, NWTN, ISP, ILP to AUTO's defaults.  AUTO-07p's
# own run of these files labels the EP at PT 1, the BP at PT 5, the UZ
# (p = 0.9) at PT 10 and the LP at PT 36 (its branch 2 keeps DS = 0.05: four
# and then three Newton iterations a step, ITNW = 5; no ADPTDS after the
# switch's first step nor after the BP).  whirl put the LP at PT 15 before
# 2026-12-07 (its ITNW = 8 grew the step x1.1 after three iterations, and
# it adapted the step after the switch and after special points)
mkdir "$tmp/tc"
fmodel "$tmp/tc/tc.f90" 'F(1) = PAR(1) * U(1) - U(1)**2 + U(1)**3 / 3' -- 'PAR(1) = -0.5' 'U(1) = 0'
cat > "$tmp/tc/c.tc" <<'C'
NDIM = 1, IPS = 1, IRS = 0, ICP = [1], MXBF = -1
NMX = 60, NPR = 0
DS = 0.05, DSMIN = 1e-4, DSMAX = 0.2
UZSTOP = {1: [-1, 0.9]}
C
(cd "$tmp" && "$WHIRL" auto tc --quiet > tc.log 2>&1)
got=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 >= 1 && substr($0, 15, 5) + 0 <= 4 {
  p = substr($0, 5, 6) + 0; printf "%s%d %d", (k++ ? "; " : ""), (p < 0 ? -p : p), substr($0, 11, 4) }' "$tmp/tc.out/b.tc" 2> /dev/null)
[ "$got" = "1 9; 5 1; 10 -4; 36 2" ]
check $? "MXBF's branch as AUTO's algebraic ones (AUTO-07p: 1 9; 5 1; 10 -4; 36 2): $got"
grep -q "^ITNW   = 5  # AUTO's default$" "$tmp/tc.out/tc.whirl" && grep -q "^ITMX   = 9  # AUTO's default$" "$tmp/tc.out/tc.whirl" &&
  grep -q "^NWTN   = 3  # AUTO's default$" "$tmp/tc.out/tc.whirl" && ! grep -q "^MXBF.*default" "$tmp/tc.out/tc.whirl"
check $? "tc.whirl: the keys the constants leave out at AUTO's defaults (ITNW 5, ITMX 9, NWTN 3), the ones they set as set"

# LOCATE = auto: the fold branch p = u^2 from u = -2 down in p, a user
# point at p = 0.7 located to EPSS = 0.05, a step of 0.3 (AUTO's secant step
# and Mueller's: its UZ at 0.698758, 1.2e-3 short) and the branch going on
# from there: AUTO-07p's own run has PT 13 at p = 0.44884369 and the EP 14
# at 0.22311746 (whirl auto, LOCATE = converged: 0.45000373, 0.22411330);
# with LOCATE = auto whirl's are AUTO's, its UZ still reported at 0.7
mkdir "$tmp/fl"
fmodel "$tmp/fl/fl.f90" 'F(1) = PAR(1) - U(1)**2' -- 'PAR(1) = 4' 'U(1) = -2'
cat > "$tmp/fl/c.fl" <<'C'
NDIM = 1, IPS = 1, IRS = 0, ICP = [1], ILP = 0, ISP = 0
NMX = 14, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 0.05, ITNW = 8
DS = -0.3, DSMIN = 1e-4, DSMAX = 0.3
UZR = {1: 0.7}
C
(cd "$tmp" && "$WHIRL" auto fl --quiet > fl.log 2>&1)
grep -q "^LOCATE = converged$" "$tmp/fl.out/fl.whirl"
check $? "fl.whirl: whirl auto writes LOCATE = converged"
(cd "$tmp/fl.out" && "$WHIRL" run fl.whirl --LOCATE=auto --OUT=loc.out --quiet --no-plot > loc.log 2>&1)
rc=$?
got=$(awk -F'\t' 'NR > 1 && $2 >= 11 { printf "%s%d %s %.10g", (k++ ? "; " : ""), $2 + 1, $3, $5 }' "$tmp/fl.out/loc.out/branches.tsv" 2> /dev/null)
echo "$got" | awk -F'; ' '{ split($1, a, " "); split($2, b, " "); split($3, c, " ")
  exit !(NF == 3 && a[1] == 12 && a[2] == "UZ" && a[3] == 0.7 && b[1] == 13 && c[1] == 14 &&
         (b[3] - 0.44884369123) ^ 2 < 1e-14 && (c[3] - 0.22311745681) ^ 2 < 1e-14) }'
check $(( $? + rc )) "LOCATE = auto: the branch goes on from AUTO's point (AUTO-07p: PT 13 at 0.44884369, 14 at 0.22311746), the UZ reported at 0.7 (exit $rc): $got"
# a run file DIR/RUN with KEY's line made "KEY = VALUE" ($3): exit 2, the
# message $4 at the file and line, nothing written
bad_value() {
  sed -e "s/^${3%% *} *= .*\$/$3/" -e 's|^OUT .*$|OUT = bad.out|' "$1/$2" > "$1/bad.whirl"
  (cd "$1" && "$WHIRL" run bad.whirl --quiet --no-plot > bad.log 2>&1)
  rc=$?
  [ $rc = 2 ] && grep -q "bad.whirl:[0-9]*: $4" "$1/bad.log" && [ ! -e "$1/bad.out" ]
  check $? "$3: exit 2 ($rc), the file and line, nothing written: $(head -1 "$1/bad.log")"
}
bad_value "$tmp/fl.out" fl.whirl "LOCATE = nearby" "LOCATE: 'nearby' is neither converged nor auto"
bad_value "$tmp/fl.out" fl.whirl "ITMX = -1" "ITMX = -1: must be in \[0, 1000\]"

# the keys whirl auto writes, and the curve's maximum against the nodes'
w="$tmp/bru.out/bru.2@HB1.whirl"
grep -q '^MESH_RULE = jumps$' "$w" && grep -q '^ORBIT_MAX = nodes$' "$w" && grep -q '^EQ_STEP = sphere$' "$w" &&
  grep -q '^DIFFERENCES = auto$' "$w" && grep -q '^UDOT = direction$' "$w" && grep -q '^TANGENT = iterate$' "$w"
check $? "bru.2@HB1.whirl: MESH_RULE = jumps, ORBIT_MAX = nodes, EQ_STEP = sphere, DIFFERENCES = auto, UDOT = direction and TANGENT = iterate, AUTO's"
sed -e 's/^ORBIT_MAX = nodes$/ORBIT_MAX = curve/' -e 's|^OUT .*$|OUT = curve.out|' "$w" > "$tmp/bru.out/curve.whirl"
(cd "$tmp/bru.out" && "$WHIRL" run curve.whirl --quiet --no-plot > /dev/null 2>&1)
check $? "the same run with ORBIT_MAX = curve exits 0"
paste "$tmp/bru.out/bru.2@HB1.out/branches.tsv" "$tmp/bru.out/curve.out/branches.tsv" 2>/dev/null |
  awk -F'\t' 'NR == 1 { h = NF / 2; for (i = 1; i <= h; i++) if ($i ~ /^max_/) c[i] = 1; next }
    { rows++; for (i in c) { d = $(i + h) - $i; if (d < -1e-12 || d > 1e-3 * (1 + ($i < 0 ? -$i : $i))) bad = 1; if (d > 1e-12) above++ } }
    END { exit !(rows > 30 && !bad && above > 0) }'
check $? "ORBIT_MAX = curve: every orbit's maximum at or above the largest node value, some above it"
for kv in "ORBIT_MAX = sideways:ORBIT_MAX: 'sideways' is neither curve nor nodes" \
          "MESH_RULE = 2:MESH_RULE: '2' is neither derivative nor jumps" \
          "EQ_STEP = ball:EQ_STEP: 'ball' is neither tangent nor sphere" \
          "DIFFERENCES = forward:DIFFERENCES: 'forward' is neither central nor auto" \
          "UDOT = sideways:UDOT: 'sideways' is neither derivative nor direction" \
          "TANGENT = exact:TANGENT: 'exact' is neither refined nor iterate"; do
  bad_value "$tmp/bru.out" bru.2@HB1.whirl "${kv%%:*}" "${kv#*:}"
done
echo "1..$n"
exit $fail

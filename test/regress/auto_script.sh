#!/bin/sh
# test/regress/auto_script.sh — `whirl auto DIR --script`: AUTO's script of
# runs (NAME.auto, Python 2 as AUTO-07p 0.9.2's demos are written) executed
# with AUTO's commands by python/whirl_auto.py, each run a `whirl auto` run.
#  1. The logistic map x -> mu x (1 - x), written here in AUTO's form: the
#     fixed points from mu = 0.5, the period doublings of the cascade by a
#     loop of run(r('PD1'), ISW=-1) as AUTO's log demo does, the parameter
#     read back by name (sol['mu']): mu = 3 and 1 + sqrt(6) exactly, and
#     the period-4 flip at 3.5440903596 (the cascade's third, known to 10
#     digits); run(DS='-') runs the last start again the other way; save,
#     append, relabel and merge write b./s./d. files whose labels run 1, 2,
#     ...; DIR is not written to; a second run into the same OUT works and
#     reuses the plug-in (no compilation).
#  2. Bad input: a command the runner lacks, an error of the script's own,
#     --script with --runs, a missing script: exit 2 with one message naming
#     the script (and its line), no traceback.
#  3. fnc's commands: cd and auto() into a sub-directory's script, loadbd,
#     a run of IPS = 4 from an array with PAR (below).
#  4. AUTO's numbers of labels and branches across a script's runs (the
#     last test, against AUTO-07p's own run).
# TAP output.
set -u
: "${top_srcdir:=.}" "${top_builddir:=.}"
WHIRL="$(cd "$top_builddir" && pwd)/drivers/whirl"
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "1..0 # SKIP no Fortran compiler"; exit 0; }
command -v "${WHIRL_PYTHON:-python3}" >/dev/null 2>&1 || { echo "1..0 # SKIP no python3"; exit 0; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
n=0 fail=0
ok() { n=$((n + 1)); echo "ok $n - $*"; }
nok() { n=$((n + 1)); echo "not ok $n - $*"; fail=1; }
check() { if [ "$1" = 0 ]; then shift; ok "$@"; else shift; nok "$@"; fi; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }

mkdir "$tmp/lg"
cat > "$tmp/lg/lg.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = PAR(1) * U(1) * (1 - U(1))
      IF (IJAC.EQ.0) RETURN
      DFDU(1,1) = PAR(1) * (1 - 2 * U(1))
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 0.5
      U(1) = 0
      END SUBROUTINE STPNT
F
# (ITNW = 8: the map's Newton takes three iterations a step at EPSL = 1e-10,
# which grow the step only where ITNW / 2 >= 3; AUTO's default ITNW = 5
# keeps DS = 0.001, and 400 steps end short of mu = 3)
cat > "$tmp/lg/c.lg" <<'C'
unames = {1: 'x'}, parnames = {1: 'mu'}
NDIM=   1, IPS =  -1, IRS =   0, ILP =   1, ITNW = 8
ICP =  ['mu']
NMX=  400, NPR=    0, MXBF=  -1, ISP = 1, ISW = 1, JAC = 1
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS  =  0.001, DSMIN=  0.0001, DSMAX=   0.02
NPAR = 1
UZSTOP = {'mu': 3.6}
C
cat > "$tmp/lg/lg.auto" <<'A'
# as AUTO-07p 0.9.2's demos: Python 2 prints
print "\n***the fixed points***"
r = run(e='lg', c='lg')
save('lg')
for i in range(3):
    print '%.10f' % r('PD1')['mu']
    r = run(r('PD1'), ISW=-1)
    append('lg')
back = run(DS='-')
print 'runs back %d' % len(back)
ab = relabel(merge(r + back))
save(ab, 'both')
print 'labels %s' % ' '.join(str(s.lab) for s in ab())
A
cp -R "$tmp/lg" "$tmp/lg.orig"
out=$(cd "$tmp" && "$WHIRL" auto lg --script --quiet --out=lg.out 2> err.txt)
rc=$?
check $([ $rc = 0 ] && echo 0 || echo 1) "the script runs (exit $rc$( [ $rc = 0 ] || printf ': %s' "$(head -2 "$tmp/err.txt")"))"
pd=$(printf '%s\n' "$out" | grep -E '^[0-9]+\.[0-9]{10}$' | tr '\n' ' ')
set -- $pd
near "${1:-0}" 3 1e-9; check $? "the first flip at mu = 3 (${1:-none})"
near "${2:-0}" 3.449489742783178 1e-9; check $? "the period-2 flip at 1 + sqrt(6) (${2:-none})"
near "${3:-0}" 3.5440903596 1e-9; check $? "the period-4 flip at 3.5440903596 (${3:-none})"
printf '%s\n' "$out" | grep -q '^runs back [1-9]'; check $? "run(DS='-') runs the last start the other way"
for f in b.lg s.lg d.lg b.both s.both b.runs s.runs; do
  [ -s "$tmp/lg.out/$f" ]; check $? "OUT/$f written"
done
labs=$(printf '%s\n' "$out" | sed -n 's/^labels //p')
want=$(echo "$labs" | awk '{ for (i = 1; i <= NF; i++) s = s (i > 1 ? " " : "") i; print s }')
[ -n "$labs" ] && [ "$labs" = "$want" ]; check $? "relabel numbers 1, 2, ... ($labs)"
blabs=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 != 0 { printf "%d ", substr($0, 15, 5) }' "$tmp/lg.out/b.both")
[ "$blabs" = "$want " ]; check $? "b.both's LAB column as relabelled ($blabs)"
diff -r "$tmp/lg" "$tmp/lg.orig" > /dev/null; check $? "DIR is not written to"
t0=$(stat -c %Y "$tmp/lg.out/runs/lg.so")
sleep 1
out2=$(cd "$tmp" && "$WHIRL" auto lg --script --quiet --out=lg.out 2>&1)
rc=$?
[ $rc = 0 ] && [ "$(printf '%s\n' "$out2" | grep -c '^3\.')" = 3 ]; check $? "a second run into the same OUT (exit $rc)"
[ "$(stat -c %Y "$tmp/lg.out/runs/lg.so")" = "$t0" ]; check $? "the unchanged plug-in is not compiled again"

# the interpreter configure found (sys.executable), not the first python3
# on PATH: a python3 there that fails does not matter (WHIRL_PYTHON unset)
py3=$(sed -n 's/^#define WHIRL_PYTHON3 "\(.*\)"$/\1/p' "$top_builddir/config.h" 2>/dev/null)
if [ -n "$py3" ] && [ -z "${WHIRL_PYTHON:-}" ]; then
  mkdir "$tmp/fakebin"
  printf '#!/bin/sh\necho fake python3 >&2\nexit 7\n' > "$tmp/fakebin/python3"
  chmod +x "$tmp/fakebin/python3"
  out3=$(cd "$tmp" && PATH="$tmp/fakebin:$PATH" "$WHIRL" auto lg --script --quiet --out=lg3.out 2>&1)
  rc=$?
  [ $rc = 0 ] && [ "$(printf '%s\n' "$out3" | grep -c '^3\.')" = 3 ]; check $? "configure's Python 3 ($py3), not a failing python3 first on PATH (exit $rc)"
else
  ok "# SKIP configure found no Python 3, or WHIRL_PYTHON chooses it"
fi

# a restart with a larger NPAR (AUTO: NPAR = MAX(NPARR, NPAR)): PAR(2) as
# the model has it, 0 (STPNT leaves it), beside the label's mu
cat > "$tmp/lg/np.auto" <<'A'
r = run(e='lg', c='lg')
r2 = run(r('UZ1'), ICP=['mu', 2], NMX=5, UZSTOP={})
print('np %s %.10g' % (len(r2()), r2()[-1]['PAR(2)']))
r3 = run(r2()[-1], ICP=['mu'], NMX=3, UZSTOP={})
print('np3 %d' % len(r3()))
A
out=$(cd "$tmp" && "$WHIRL" auto lg --script=lg/np.auto --quiet --out=np.out 2>&1)
printf '%s\n' "$out" | grep -q '^np [1-9][0-9]* 0$'; check $? "a restart with a larger NPAR: the new parameter the model's ($(printf '%s' "$out" | grep '^np ' | tail -1))"
# and back: run 3's constants have NPAR 1, its label (run 2's) stores 2
# parameters: NPAR is the label's (AUTO's MAX(NPARR, NPAR); tfc's run 5
# from run 3's label with PAR(7), PAR(8): "the solutions have 8
# parameters" before 2026-12-06)
printf '%s\n' "$out" | grep -q '^np3 [1-9]'; check $? "a restart from a label with more parameters than NPAR ($(printf '%s' "$out" | grep -E '^np3|solutions have' | tail -1))"
# AUTO's MXBF is 10 where a constants file has none: switching at the BP
# of the fixed points (mu = 1), both ways
sed '/MXBF/s/MXBF= *-1, //' "$tmp/lg/c.lg" > "$tmp/lg/c.lg2"
(cd "$tmp" && "$WHIRL" auto lg lg --runs=lg2 --quiet --out=mx.out > /dev/null 2>&1)
[ -f "$tmp/mx.out/b.lg2.bif1" ] && [ -f "$tmp/mx.out/b.lg2.bif2" ]; check $? "no MXBF in the constants: AUTO's 10, the BP's branch both ways"

# an orbit continued as a boundary-value problem (AUTO's ph1, pcl): the
# lambda-omega system u1' = a u1 - u2 - u1 r^2, u2' = u1 + a u2 - u2 r^2,
# whose orbits are circles of radius sqrt(a) and period 2 pi; its orbit
# at a = 0.25 (IPS = 2) restarts IPS = 4 (periodic boundary conditions,
# AUTO's integral phase condition, the period PAR(11) free), at a = 0.49
# its L2-NORM is the radius 0.7 and PAR(11) is 2 pi (closed forms); its
# PVLS (GETP's NRM, INT, MAX of u1) on both
mkdir "$tmp/lw"
cat > "$tmp/lw/lw.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*), R2, T
      R2 = U(1)**2 + U(2)**2
      T = 1
      IF (PAR(3) .NE. 0) T = PAR(11)
      F(1) = T * (PAR(1) * U(1) - U(2) - U(1) * R2)
      F(2) = T * (U(1) + PAR(1) * U(2) - U(2) * R2)
      IF (NDIM .GE. 3) F(3) = T * (U(3)**2 - 1)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = -0.5
      PAR(3) = 0
      U(1) = 0
      U(2) = 0
      IF (NDIM .GE. 3) U(3) = -1
      END SUBROUTINE STPNT
      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), NBC, IJAC
      DOUBLE PRECISION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
      INTEGER I
      DO I = 1, NBC
        FB(I) = U0(I) - U1(I)
      END DO
      END SUBROUTINE BCND
      SUBROUTINE ICND(NDIM,PAR,ICP,NINT,U,UOLD,UDOT,UPOLD,FI,IJAC,DINT)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), NINT, IJAC
      DOUBLE PRECISION PAR(*), U(NDIM), UOLD(NDIM), UDOT(NDIM), UPOLD(NDIM)
      DOUBLE PRECISION FI(NINT), DINT(NINT,*)
      FI(1) = U(1) * UPOLD(1) + U(2) * UPOLD(2)
      END SUBROUTINE ICND
      SUBROUTINE PVLS(NDIM,U,PAR)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM,*), PAR(*), GETP
      PAR(4) = GETP('NRM', 1, U)
      PAR(5) = GETP('INT', 1, U)
      PAR(6) = GETP('MAX', 1, U)
      IF (NDIM .GE. 3) PAR(7) = GETP('BV0', 3, U)
      END SUBROUTINE PVLS
F
cat > "$tmp/lw/c.lw" <<'C'
NDIM = 2, IPS = 1, IRS = 0, ILP = 1, ICP = [1], NTST = 20, NCOL = 4, IAD = 3
ISP = 1, ISW = 1, NMX = 200, NPR = 0, MXBF = 0, JAC = 0, NPAR = 11
EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8, DS = 0.01, DSMIN = 1e-5, DSMAX = 0.05
UZSTOP = {1: 0.3}
C
cat > "$tmp/lw/lw.auto" <<'A'
r1 = run(e='lw', c='lw')
r2 = run(r1('HB1'), IPS=2, ICP=[1, 11], UZR={1: 0.25})
r3 = run(r2('UZ1'), IPS=4, NBC=2, NINT=1, ICP=[1, 11], PAR={3: 1}, UZR={1: 0.49},
         UZSTOP={1: 0.5})
s = r3('UZ1')
print('bvp %.10f %.10f %.10f' % (s['PAR(1)'], s['L2-NORM'], s['PAR(11)']))
o = r2('UZ1')
print('pvls %.10f %.10f %.10f %.10f %.10f' % (o['PAR(4)'], o['PAR(5)'], o['PAR(6)'], s['PAR(4)'], s['PAR(6)']))
r4 = run(r2('UZ1'), IPS=4, NDIM=3, NBC=3, NINT=1, ICP=[1, 11], PAR={3: 1}, UZR={1: 0.49},
         UZSTOP={1: 0.5})
s = r4('UZ1')
print('ndim3 %.10f %.10f %.10f %.10f' % (s['PAR(1)'], s['PAR(4)'], s['PAR(11)'], s['PAR(7)']))
c7 = run(r1('HB1'), IPS=2, ICP=[1, 11, 2, 3, 4, 5, 6], NMX=4, UZR={})
c6 = run(r1('HB1'), IPS=2, ICP=[1, 11, 2, 3, 4, 5], NMX=4, UZR={})
print('cols7 %s' % '|'.join(c7()[-1].columns))
print('cols6 %s' % '|'.join(c6()[-1].columns))
A
out=$(cd "$tmp" && "$WHIRL" auto lw --script --quiet --out=lw.out 2>&1)
set -- $(printf '%s\n' "$out" | sed -n 's/^bvp //p')
near "${1:-0}" 0.49 1e-9 && near "${2:-0}" 0.7 1e-6 && near "${3:-0}" 6.283185307179586 1e-6
check $? "an orbit restarted as a boundary-value problem: a ${1:-?}, radius ${2:-?} (0.7), PAR(11) ${3:-?} (2 pi)$( [ -n "${1:-}" ] || printf ': %s' "$(printf '%s' "$out" | tail -1)")"
# AUTO's PVLS on solutions, GETP over the orbit (IPS = 2, radius 0.5) and
# the BVP (radius 0.7): NRM of u1 = radius / sqrt 2, INT = 0, MAX = radius
# (over the nodes: to h^2)
set -- $(printf '%s\n' "$out" | sed -n 's/^pvls //p')
near "${1:-0}" 0.3535533906 1e-7 && near "${2:-1}" 0 1e-9 && near "${3:-0}" 0.5 1e-3 &&
  near "${4:-0}" 0.4949747468 1e-7 && near "${5:-0}" 0.7 1e-3
check $? "PVLS on an orbit and a BVP: GETP NRM ${1:-?} ${4:-?}, INT ${2:-?}, MAX ${3:-?} ${5:-?}"
# a restart with a larger NDIM (AUTO-07p's READBV: STPNT fills the new
# components at every node; demo pcl): the orbit extended by
# w' = T (w^2 - 1), whose periodic solutions are w = 1 and w = -1, and
# STPNT's w = -1 picks the second (from w = 0 Newton's matrix is
# singular); u is the same circle (NRM of u1 = 0.7/sqrt 2, period 2 pi)
set -- $(printf '%s\n' "$out" | sed -n 's/^ndim3 //p')
near "${1:-0}" 0.49 1e-9 && near "${2:-0}" 0.4949747468 1e-7 &&
  near "${3:-0}" 6.283185307179586 1e-6 && near "${4:-0}" -1 1e-9
check $? "a boundary-value problem of NDIM 3 from an orbit of NDIM 2, the new component from STPNT: a ${1:-?}, NRM u1 ${2:-?}, PAR(11) ${3:-?}, w ${4:-?} (-1)"

# the same three runs from constants files in the default order (c.lw.1,
# c.lw.2, c.lw.3), the third of NDIM 3: a plug-in of its own NDIM
# (lw.ndim3.so) beside lw.so, and the extended orbit's w = -1 at a = 0.49
mkdir "$tmp/lwd" && cp "$tmp/lw/lw.f90" "$tmp/lwd/lwd.f90" && cp "$tmp/lw/c.lw" "$tmp/lwd/c.lwd.1"
printf '%s\n' "NDIM = 2, IPS = 2, IRS = 'HB1', ICP = [1, 11], NTST = 20, NCOL = 4, IAD = 3" \
  "ISP = 1, ISW = 1, NMX = 200, NPR = 0, MXBF = 0, NPAR = 11" \
  "EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8, DS = 0.01, DSMIN = 1e-5, DSMAX = 0.05" \
  "UZR = {1: 0.25}, UZSTOP = {1: 0.25}" > "$tmp/lwd/c.lwd.2"
printf '%s\n' "NDIM = 3, IPS = 4, IRS = 'UZ1', ICP = [1, 11], NBC = 3, NINT = 1, PAR = {3: 1}" \
  "NTST = 20, NCOL = 4, IAD = 3, ISP = 1, ISW = 1, NMX = 200, NPR = 0, NPAR = 11" \
  "EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8, DS = 0.01, DSMIN = 1e-5, DSMAX = 0.05" \
  "UZR = {1: 0.49}, UZSTOP = {1: 0.5}" > "$tmp/lwd/c.lwd.3"
msg=$(cd "$tmp" && "$WHIRL" auto lwd --quiet --out=lwd.out 2>&1)
rc=$?
w=$(awk '$1 == "LAB" && $4 == "UZ" { u = 1; next } u && $1 == "PAR" { a = $2; w = $8; next }
         u && $1 == "X" { print a, $4; exit }' "$tmp/lwd.out/lwd.3.out/solutions" 2>/dev/null)
set -- $w
[ $rc = 0 ] && [ -f "$tmp/lwd.out/lwd.so" ] && [ -f "$tmp/lwd.out/lwd.ndim3.so" ] &&
  near "${1:-0}" 0.49 1e-9 && near "${2:-0}" -1 1e-9 &&
  grep -q "ndim3" "$tmp/lwd.out/lwd.3.whirl" && ! grep -q "ndim" "$tmp/lwd.out/lwd.2.whirl"
check $? "constants files of NDIM 2 and 3 in the default order: a plug-in for each, the third run's w = ${2:-?} at a = ${1:-?} (exit $rc$( [ $rc = 0 ] || printf ': %s' "$(printf '%s' "$msg" | head -1)"))"

# the b. file's columns as AUTO's (io.f90, WRLINE): U(1..N2) with N2 =
# NDIM, 7 - NICP where both exceed 7, none past 7 parameters
c7=$(printf '%s\n' "$out" | sed -n 's/^cols7 //p'); c6=$(printf '%s\n' "$out" | sed -n 's/^cols6 //p')
[ "$c7" = "PAR(1)|L2-NORM|PERIOD|PAR(2)|PAR(3)|PAR(4)|PAR(5)|PAR(6)" ] &&
  [ "$c6" = "PAR(1)|L2-NORM|MAX U(1)|PERIOD|PAR(2)|PAR(3)|PAR(4)|PAR(5)" ]
check $? "b. columns: 7 ICP, no U ($c7); 6 ICP, one ($c6)"

# 2. bad input
bad_in() { # demo directory, OUT, script text, what the message must name, test name
  d=$1 o=$2
  shift 2
  printf '%s\n' "$1" > "$tmp/$d/bad.auto"
  msg=$(cd "$tmp" && "$WHIRL" auto "$d" --script="$d/bad.auto" --quiet --out="$o" 2>&1 >/dev/null)
  rc=$?
  [ $rc = 2 ] && [ "$(printf '%s\n' "$msg" | grep -c .)" = 1 ] &&
    printf '%s\n' "$msg" | grep -q "$2" && ! printf '%s\n' "$msg" | grep -q Traceback
  check $? "$3 (exit $rc: $msg)"
  rm -f "$tmp/$d/bad.auto"
}
bad() { bad_in lg bad.out "$@"; }
bad "r = run(e='lg', c='lg')
copy('lg', 'x')" "bad.auto:2: the script uses 'copy'" "a command the runner lacks: exit 2, its line"
bad "x = undefined_name + 1" "bad.auto:1: NameError" "the script's own error: exit 2, one line"
rm -rf "$tmp/bad.out"
bad "r = run(e='lg', c='lg'" "bad.auto" "a script that does not compile: exit 2, one line"
[ ! -e "$tmp/bad.out" ]; check $? "a script that does not compile writes nothing (no OUT)"
bad "r = run(e='lg', c='lg.nothere')" "c.lg.nothere" "a missing constants file: exit 2"
bad "r = run(e='lg', c='lg')
r('HB1')" "no HB1" "a label the diagram lacks: exit 2"
# Ctrl-C inside a script (SIGINT after its first run): one line, exit 130,
# the first run's files whole, no temporary file left
printf '%s\n' "import os, signal" "r = run(e='lg', c='lg')" "os.kill(os.getpid(), signal.SIGINT)" \
  "r = run(e='lg', c='lg')" > "$tmp/lg/int.auto"
msg=$(cd "$tmp" && "$WHIRL" auto lg --script=lg/int.auto --quiet --out=int.out 2>&1 >/dev/null)
rc=$?
nb=$(grep -c . "$tmp/int.out/b.runs" 2>/dev/null)
nr=$(cat "$tmp/int.out/runs/b.r1" "$tmp/int.out/runs/b.r1".bif* 2>/dev/null | grep -v '^   0' | grep -c .)
[ $rc = 130 ] && [ "$(printf '%s\n' "$msg" | grep -c .)" = 1 ] &&
  printf '%s' "$msg" | grep -q "int.auto:3: interrupted" && [ -n "$nb" ] &&
  [ "$nb" -gt 0 ] && [ "$nb" = "$nr" ] && [ -z "$(find "$tmp/int.out" -name '*.tmp')" ]
check $? "Ctrl-C in a script: exit $rc, '$msg', b.runs whole ($nb lines, run 1's $nr), no temporary file"
msg=$(cd "$tmp" && "$WHIRL" auto lg --script --runs=lg --out=x.out 2>&1)
[ $? = 2 ] && printf '%s' "$msg" | grep -q "exclude"; check $? "--script with --runs: exit 2"
# 3. a script in AUTO's fnc form: cd into a directory of the demo and
# auto() its own script there (which saves a diagram), loadbd the diagram,
# and a run of the top directory's equations from an array, column-wise
# [[t...], [u...]], with PAR={name: value} (a data start of IPS = 4, as
# AUTO's STPNUB): u' = p u on [0, 1], u(0) = 1, u = exp(p t), L2-NORM
# sqrt((exp(2 p) - 1) / (2 p)); the sub-directory's run goes from p = 0
# (STPNT) to the UZ at p = 0.5, whose t and u columns the top script reads
# (sol['t'], sol['u'], sol.PAR['p']) and starts from at p = 0.5 onto the
# UZ at p = 1
mkdir -p "$tmp/ex/sub"
for d in ex ex/sub; do
  e=$(basename "$d")
  cat > "$tmp/$d/$e.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(NDIM,*)
      F(1) = PAR(1) * U(1)
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 0
      U(1) = 1
      END SUBROUTINE STPNT
      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), NBC, IJAC
      DOUBLE PRECISION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
      FB(1) = U0(1) - 1
      END SUBROUTINE BCND
F
  cat > "$tmp/$d/c.$e" <<'C'
unames = {1: 'u'}, parnames = {1: 'p'}
NDIM = 1, IPS = 4, ICP = ['p'], NBC = 1, NINT = 0
NTST = 10, NCOL = 4, IAD = 0, JAC = 0, ISP = 0, ILP = 0
NMX = 200, NPR = 0, EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS = 0.05, DSMIN = 1e-4, DSMAX = 0.1, NPAR = 1
C
done
echo "UZR = {'p': 0.5}, UZSTOP = {'p': 0.5}" >> "$tmp/ex/sub/c.sub"
echo "UZR = {'p': 1.0}, UZSTOP = {'p': 1.0}" >> "$tmp/ex/c.ex"
printf '%s\n' "r = run(e='sub', c='sub')" "save(r, 'half')" > "$tmp/ex/sub/sub.auto"
cat > "$tmp/ex/ex.auto" <<'A'
cd('sub')
auto('sub.auto')
half = loadbd('half')
cd('..')
sol = half('UZ1')
t, u = sol['t'], sol['u']
print('cols %d %d %.12g %.12g %.12g' % (len(t), len(u), t[-1], u[-1], sol.PAR['p']))
r = run([t, u], e='ex', c='ex', PAR={'p': sol.PAR['p']})
print('data start %.12g %.12g' % (r()[0]['p'], r()[0]['L2-NORM']))
print('uz %.12g %.12g' % (r('UZ1')['p'], r('UZ1')['L2-NORM']))
save(r, 'whole')
import helper
print('helper %.12g' % helper.uz_p('whole'))
A
# a module of the demo's that imports AUTO's commands, as r3b's
# compute_lps.py (from AUTOclui import *), and calls sol.PAR(i)
printf '%s\n' "from AUTOclui import *" "def uz_p(name):" "    return loadbd(name)('UZ1').PAR(1)" > "$tmp/ex/helper.py"
cp -R "$tmp/ex" "$tmp/ex.orig"
out=$(cd "$tmp" && env -u PYTHONDONTWRITEBYTECODE "$WHIRL" auto ex --script --quiet --out=ex.out 2>&1)
rc=$?
check $([ $rc = 0 ] && echo 0 || echo 1) "cd, auto(), loadbd and a run from an array (exit $rc$( [ $rc = 0 ] || printf ': %s' "$(printf '%s' "$out" | tail -2)"))"
set -- $(printf '%s\n' "$out" | sed -n 's/^cols //p')
[ "${1:-0}" = "${2:-1}" ] && [ "${1:-0}" -gt 10 ] && near "${3:-0}" 1 1e-12 &&
  near "${4:-0}" 1.6487212707 2e-9 && near "${5:-0}" 0.5 1e-9
check $? "sol['t'], sol['u'] the columns of the UZ at p = 0.5 (${1:-?} rows, u(1) = ${4:-?} against exp(0.5) = 1.6487212707), sol.PAR['p'] = ${5:-?}"
set -- $(printf '%s\n' "$out" | sed -n 's/^data start //p')
near "${1:-0}" 0.5 1e-12 && near "${2:-0}" 1.3108324944 1e-6
check $? "the run from the array starts at PAR={'p': 0.5}: L2-NORM ${2:-?} against sqrt(e - 1) = 1.3108324944"
set -- $(printf '%s\n' "$out" | sed -n 's/^uz //p')
near "${1:-0}" 1 1e-9 && near "${2:-0}" 1.7873242709 1e-8
check $? "its UZ at p = 1: L2-NORM ${2:-?} against sqrt((e^2 - 1) / 2) = 1.7873242709"
set -- $(printf '%s\n' "$out" | sed -n 's/^helper //p')
near "${1:-0}" 1 1e-9
check $? "a module's 'from AUTOclui import *': loadbd and sol.PAR(1) there (${1:-?})"
[ -s "$tmp/ex.out/sub/b.half" ] && [ -s "$tmp/ex.out/b.whole" ] && [ ! -e "$tmp/ex.out/b.half" ]
check $? "save in the sub-directory writes OUT/sub/b.half, at the top OUT/b.whole"
diff -r "$tmp/ex" "$tmp/ex.orig" > /dev/null; check $? "DIR and its sub-directory are not written to (no __pycache__ of the module it imports)"
bad2() { bad_in ex bad2.out "$@"; }
bad2 "cd('..')" "bad.auto:1: cd('..'): outside" "cd out of the script's directory: exit 2"
bad2 "cd('nothere')" "cd('nothere'): no directory" "cd to a missing directory: exit 2"
bad2 "loadbd('none')" "loadbd('none'): the script saved nothing" "loadbd of a name not saved: exit 2"
printf '%s\n' "cd('sub')" "r = run(e='sub', c='sub')" "r('HB1')" > "$tmp/ex/sub/inner.auto"
bad2 "auto('sub/inner.auto')" "sub/inner.auto:3: .*no HB1" "an error in a script auto() runs names that script and its line"
rm -f "$tmp/ex/sub/inner.auto"
bad2 "run([[0, 1], [1]], e='ex', c='ex')" "all of one length" "an array whose columns differ in length: exit 2"

msg=$(cd "$tmp" && "$WHIRL" auto lg --script=nothere.auto --out=y.out 2>&1)
[ $? = 2 ] && printf '%s' "$msg" | grep -q "nothere.auto"; check $? "a missing script: exit 2"
[ ! -e "$tmp/y.out" ] && [ ! -e "$tmp/x.out" ]; check $? "nothing written on bad arguments"
# AUTO's numbers of a script's runs (io.f90 NEWLAB): a run from a solution
# numbers its labels on from the largest label of the diagram the solution
# was selected from (AUTO's restart file), unless the constants give LAB;
# its branch is that diagram's largest + 1 for a switch (ISW < 0), the
# solution's own otherwise, or the constants' IBR.  The pitchfork
# u' = p u - u^3 from p = -1 (BP at p = 0, UZ at p = 0.5, stop at 1), six
# runs; AUTO-07p's own run of these files wrote in b.all (BR, TY, LAB):
#   1 9 1; 1 1 2; 1 -4 3; 1 -4 4 | 2 -4 5; 2 -4 6 | 1 -4 1 | 9 -4 5 | 2 -4 7
#   | 3 -4 7
# The sixth keeps run 2's ISW = -1 at a UZ, where AUTO continues the branch
# (numbered as a switch): whirl refused it (exit 2) before 2026-12-07.
# (before 2026-12-07 whirl numbered each run from 1 on branch 1).  Runs 3
# and 4 step from p = 0.5 by 0.1 onto p = 1 exactly (AUTO's steps, 1e-7
# longer, pass it): its UZ is labelled (it was missed, an EP at NMX).
mkdir "$tmp/pf"
cat > "$tmp/pf/pf.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = PAR(1) * U(1) - U(1)**3
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = -1
      U(1) = 0
      END SUBROUTINE STPNT
F
cat > "$tmp/pf/c.pf" <<'C'
NDIM = 1, IPS = 1, IRS = 0, ILP = 1, ICP = [1]
NMX = 100, NPR = 0, MXBF = 0, ISP = 1, ISW = 1, JAC = 0
EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-8
DS = 0.05, DSMIN = 1e-4, DSMAX = 0.1
NPAR = 1, UZR = {1: 0.5}, UZSTOP = {1: 1.0}
C
cat > "$tmp/pf/pf.auto" <<'A'
r1 = run(e='pf', c='pf')
r2 = run(r1('BP1'), ISW=-1)
r3 = run(r1('UZ1'), LAB=1)
r4 = run(r1('UZ1'), IBR=9)
r5 = run(r2('UZ1'), ISW=1)
r6 = run(r2('UZ1'))
save(r1 + r2 + r3 + r4 + r5 + r6, 'all')
A
(cd "$tmp" && "$WHIRL" auto pf --script --quiet --out=pf.out > /dev/null 2> pf.err)
st=$?
nums=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 != 0 {
    printf "%s%d %d %d", (k++ ? "; " : ""), substr($0, 1, 4), substr($0, 11, 4), substr($0, 15, 5) }' \
  "$tmp/pf.out/b.all" 2>/dev/null)
[ "$st" = 0 ] && [ "$nums" = "1 9 1; 1 1 2; 1 -4 3; 1 -4 4; 2 -4 5; 2 -4 6; 1 -4 1; 9 -4 5; 2 -4 7; 3 -4 7" ]
check $? "AUTO's label and branch numbers across a script's runs (NEWLAB; exit $st): $nums"
# the same from constants files in whirl auto's default order (no
# script): c.pfd.3 restarts at run 2's UZ (AUTO label 5) with ISW = -1,
# which AUTO continues along that branch (BR 3, its UZ 7 at p = 1, u = 1:
# AUTO-07p's own run of these files, b.all: 1 9 1; 1 1 2; 1 -4 3; 1 -4 4;
# 2 -4 5; 2 -4 6; 3 -4 7); whirl refused it before 2026-12-07 (exit 2:
# "there is no label 5", the restart read as a switch wanting a BP)
mkdir "$tmp/pfd"
cp "$tmp/pf/pf.f90" "$tmp/pfd/pfd.f90"
cp "$tmp/pf/c.pf" "$tmp/pfd/c.pfd.1"
sed -e 's/IRS = 0/IRS = 2/' -e 's/ISW = 1/ISW = -1/' "$tmp/pf/c.pf" > "$tmp/pfd/c.pfd.2"
sed -e 's/IRS = 0/IRS = 5/' -e 's/ISW = 1/ISW = -1/' -e 's/UZR = {1: 0.5}, //' "$tmp/pf/c.pf" > "$tmp/pfd/c.pfd.3"
(cd "$tmp" && "$WHIRL" auto pfd --quiet --out=pfd.out > /dev/null 2> pfd.err)
st=$?
nums=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 != 0 {
    printf "%s%d %d %d", (k++ ? "; " : ""), substr($0, 1, 4), substr($0, 11, 4), substr($0, 15, 5) }' \
  "$tmp/pfd.out/b.pfd" 2>/dev/null)
last=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 == 7 { printf "%.10g %.10g", substr($0, 20, 19), substr($0, 58, 19) }' "$tmp/pfd.out/b.pfd" 2>/dev/null)
set -- $last
[ "$st" = 0 ] && [ "$nums" = "1 9 1; 1 1 2; 1 -4 3; 1 -4 4; 2 -4 5; 2 -4 6; 3 -4 7" ] &&
  near "${1:-0}" 1 1e-9 && near "${2:-0}" 1 1e-9
check $? "the default order: ISW = -1 at a UZ continues the branch as AUTO's (exit $st$( [ -s "$tmp/pfd.err" ] && printf ': %s' "$(head -1 "$tmp/pfd.err")"); $nums; UZ 7 at p, u = ${last:-none})"
# a diagram read back (loadbd) numbers on from the largest label of the
# whole file, as AUTO's parseS does (AUTO-07p's own run: UZ 7 on branch 1;
# from the solution's own run's numbers it would be 5)
cat > "$tmp/pf/ld.auto" <<'A'
r1 = run(e='pf', c='pf')
r2 = run(r1('BP1'), ISW=-1)
save(r1 + r2, 'both')
b = loadbd('both')
r3 = run(b('UZ1'))
save(r3, 'r3')
A
(cd "$tmp" && "$WHIRL" auto pf pf --script=pf/ld.auto --quiet --out=ld.out > /dev/null 2>&1)
nums=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 != 0 {
    printf "%s%d %d %d", (k++ ? "; " : ""), substr($0, 1, 4), substr($0, 11, 4), substr($0, 15, 5) }' \
  "$tmp/ld.out/b.r3" 2>/dev/null)
[ "$nums" = "1 -4 7" ]; check $? "a run from a diagram loadbd read numbers on from the whole file's largest label, as AUTO's: $nums"

echo "1..$n"
exit $fail

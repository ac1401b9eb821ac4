#!/bin/sh
# test/regress/auto_files.sh — `whirl auto` on AUTO-style problem
# directories, and AUTO's b./s./d. files it writes.
#  1. A fold u' = p - u^2 written here (equations and constants in AUTO's
#     form): the branch u = +-sqrt(p) from (1, 1) through the LP at p = 0,
#     with user points at p = 0.25 and a stop at p = 2 (a negative UZR
#     index; AUTO stops at its first crossing), then a second run restarting from label 2.  The b- and s-files
#     are read back by awk here (fixed columns) and checked against the
#     closed form, the stability against the sign of f' = -2u, and run 1's
#     output against being replaced by run 2.
#  2. Bad input: an unknown constant, no equations file, equations that do
#     not compile, STPNT missing: exit 2, the file named, nothing written.
#  3. A branch with a corner, u = |p|: its steps shrink to DSMIN there and
#     the run ends in AUTO's MX label (TY -9) at its last point, which a
#     second run restarts from; MX = fail (whirl's default) fails the run.
#  4. AUTO-07p's demo ab (AUTO_07P_DIR, else ../shared/auto-07p beside the
#     source tree; skipped where absent): the HB of c.ab.2 from label 2
#     against AUTO's own output (test/hyper.all: 1.65042E-01 1.47770E+00
#     4.05955E-01 1.42084E+00), the s-file header of label 1 against the
#     line AUTO writes, the merged b.ab numbering labels on, and, where the
#     Debian package auto-07p is installed, AUTO's parseB/parseS/parseD
#     loading every file.
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

mkdir "$tmp/fold"
cat > "$tmp/fold/fold.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = PAR(1) - U(1)**2
      IF (IJAC.EQ.0) RETURN
      DFDU(1,1) = -2*U(1)
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
ICP =  ['p']
NTST=  20, NCOL=   4, IAD =   3, ISP =   1, ISW = 1, IPLT= 0, NBC= 0, NINT= 0
NMX=  200, NPR=  200, MXBF=  10, IID =   2, ITMX= 8, ITNW= 7, NWTN= 3, JAC= 1
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-08
DS  = -0.05, DSMIN= 0.0001, DSMAX=  0.05, IADS=   1
NPAR=   1, THL =  {11: 0.0}, THU =  {}
UZR = {'p': 0.25, -1: 2.0}
parnames = {1: 'p'}, unames = {1: "u"}
C
cat > "$tmp/fold/c.fold.2" <<'C'
NDIM=   1, IPS =   1, IRS =   2, ILP =   1
ICP =  [1]
NTST=  20, NCOL=   4, IAD =   3, ISP =   1, ISW = 1
NMX=  200, NPR=  200, ITNW= 7, JAC= 1
EPSL= 1e-10, EPSU = 1e-10, EPSS = 1e-08
DS  = 0.05, DSMIN= 0.0001, DSMAX=  0.05
NPAR=   1
UZSTOP = {1: 2.0}
C
(cd "$tmp" && "$WHIRL" auto fold --quiet > auto.out 2> auto.err)
check $? "whirl auto fold: two runs exit 0 $(head -1 "$tmp/auto.err")"
o="$tmp/fold.out"
missing=
for f in fold.so fold.1.whirl fold.1.out/branches.tsv b.fold.1 s.fold.1 d.fold.1 \
         fold.2.out/solutions b.fold.2 s.fold.2 d.fold.2; do
  [ -s "$o/$f" ] || missing="$missing $f"
done
check "$([ -z "$missing" ] && echo 0 || echo 1)" "fold.out: the plug-in, the run files, both outputs and AUTO's files ${missing:+(missing:$missing)}"
# pictures only when asked, as AUTO: none by default, diagram.png with --plot
[ ! -e "$o/fold.1.out/diagram.png" ] && [ ! -e "$o/fold.1.out/diagram.gp" ] && [ ! -e "$o/fold.2.out/diagram.png" ]
check $? "whirl auto draws no picture unless asked (no diagram.png, no diagram.gp)"
if command -v "${WHIRL_GNUPLOT:-gnuplot}" > /dev/null 2>&1; then
  (cd "$tmp" && "$WHIRL" auto fold --plot --out=fold-plot --quiet > /dev/null 2>&1) &&
    [ -s "$tmp/fold-plot/fold.1.out/diagram.png" ] && [ -s "$tmp/fold-plot/fold.2.out/diagram.png" ]
  check $? "whirl auto --plot: each run's diagram.png"
else
  n=$((n + 1)); echo "ok $n # SKIP no gnuplot"
fi

# b-file rows: BR(1-4) PT(5-10) TY(11-14) LAB(15-19), then 19-wide columns
# PAR(1) L2-NORM U(1); the labelled ones, with the closed form u = +-sqrt(p)
awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 > 0 {
  printf "%d %d %d %.17g %.17g %.17g\n", substr($0,5,6), substr($0,11,4), substr($0,15,5), substr($0,20,19), substr($0,39,19), substr($0,58,19) }' \
  "$o/b.fold.1" > "$tmp/lab1"
printf '%s\n' "-1 9 1 1 1 1" "-x -4 2 0.25 0.5 0.5" "x 2 3 0 0 0" "x -4 4 0.25 0.5 -0.5" "x -4 5 2 1.4142135623730951 -1.4142135623730951" > "$tmp/want1"
res=$(awk 'NR == FNR { w[FNR] = $0; nw = FNR; next }
  { split(w[FNR], e, " ");
    if ($2 != e[2] || $3 != e[3]) { print "row " FNR ": type/label " $2 "/" $3 ", want " e[2] "/" e[3]; exit }
    for (i = 4; i <= 6; i++) { d = $i - e[i]; if (d < 0) d = -d; if (d > ($3 == 3 && i > 4 ? 1e-4 : 1e-7)) { print "row " FNR " column " i ": " $i ", want " e[i]; exit } }
    if (e[1] == "-1" && $1 != -1) { print "row 1: PT " $1; exit }
    if ($6 > 1e-3 && $1 > 0) { print "row " FNR ": u > 0 is stable, PT must be negative: " $1; exit }
    if ($6 < -1e-3 && $1 < 0) { print "row " FNR ": u < 0 is unstable, PT must be positive: " $1; exit }
    n++ }
  END { if (!n) print "no rows"; else if (n != nw) print n " labelled rows, want " nw }' "$tmp/want1" "$tmp/lab1")
check "$([ -z "$res" ] && echo 0 || echo 1)" "b.fold.1: EP, UZ p = 1/4, LP p = 0, UZ, stop p = 2 at u = +-sqrt(p), stability in PT's sign ${res}"
grep -q '^   0    PT  TY  LAB    p                  L2-NORM            u' "$o/b.fold.1"
check $? "b.fold.1: the column names from parnames and unames, 19 wide"

# s-file: a 16-integer header a label, then t and u, ICP, the tangent, PAR
# (11 values: 2 lines)
res=$(awk 'NF == 16 && $1 ~ /^[0-9]+$/ { hdr++; lab = $4; ty = $3; nrow = $9; getline; t = $1; u = $2;
           for (k = 1; k < nrow; k++) { getline; if (k == nrow - 2) p = $1 } # PAR: the last 2 lines
           printf "%d %d %.12g %.12g\n", lab, ty, u, p }' "$o/s.fold.1" |
      awk '{ want = ($1 == 1) ? 1 : ($1 == 3 ? 0 : sqrt($4)); if ($1 >= 4) want = -want;
             d = $3 - want; if (d < 0) d = -d; if (d > ($1 == 3 ? 1e-4 : 1e-7)) print "label " $1 ": u " $3 ", want " want; n++ }
           END { if (n != 5) print n " solutions, want 5" }')
check "$([ -z "$res" ] && echo 0 || echo 1)" "s.fold.1: five solutions, u = +-sqrt(PAR(1)) at each ${res}"
head -1 "$o/s.fold.1" | grep -qx '     1     1     9     1     1     1       1     2       6    1    0   11    0    1    1    0'
check $? "s.fold.1: AUTO's header of label 1 (IBR NTOT ITP LAB NFPR ISW NTPL NAR NROWPR NTST NCOL NPAR 0 NDIM IPS 0)"
grep -q "^S      = '[^']*fold.1.out'" "$o/fold.2.whirl" && grep -q '^IRS    = 2$' "$o/fold.2.whirl"
check $? "fold.2.whirl restarts from run 1's output directory"
last=$(awk 'substr($0, 1, 4) + 0 != 0' "$o/b.fold.2" | tail -1)
echo "$last" | awk '{ exit !($3 == -4 && ($5 - 2 < 1e-9 && 2 - $5 < 1e-9) && ($7 - sqrt(2) < 1e-8 && sqrt(2) - $7 < 1e-8)) }'
check $? "b.fold.2: from label 2 up to the stop p = 2, u = sqrt(2) ($last)"
[ "$(grep -c '^LAB' "$o/fold.1.out/solutions")" = 5 ]
check $? "run 2 left run 1's solutions as they were (5 labels)"
for k in b s d; do cat "$o/$k.fold.1" "$o/$k.fold.2" | cmp -s - "$o/$k.fold" || break; done
check $? "b.fold, s.fold, d.fold: run 1's files and run 2's, one after the other ($k)"
grep -q '^# note: THL on PAR(11): not a parameter of the model, ignored' "$o/fold.1.whirl" &&
  ! grep -q '^THL' "$o/fold.1.whirl"
check $? "fold.1.whirl notes THL on PAR(11) of equilibria (no such parameter) and leaves it out"

# bad input: exit 2, FILE:LINE, nothing written
bad() { # DIR, expected message (a grep pattern), what
  rm -rf "$tmp/$1.out"
  (cd "$tmp" && "$WHIRL" auto "$1" --quiet > /dev/null 2> "$1.err"); st=$?
  if [ $st = 2 ] && grep -q -- "$2" "$tmp/$1.err" && [ ! -e "$tmp/$1.out" ] && ! ls -d "$tmp/$1".out.tmp.* >/dev/null 2>&1; then
    ok "$3: exit 2, '$(head -1 "$tmp/$1.err")', nothing written"
  else nok "$3: exit $st, '$(head -1 "$tmp/$1.err")'"; fi
}
mkdir "$tmp/b1" "$tmp/b2" "$tmp/b3" "$tmp/b4"
cp "$tmp/fold/fold.f90" "$tmp/b1/b1.f90"
printf 'NDIM= 1, IPS = 1\nICP = [1]\nDS = 0.1, DSMX = 0.2\n' > "$tmp/b1/c.b1"
bad b1 'b1/c.b1:3: unknown AUTO constant .DSMX.' "an unknown constant"
cp "$tmp/fold/c.fold.1" "$tmp/b2/c.b2"
bad b2 'b2/b2.f90: no equations file' "no equations file"
cp "$tmp/fold/c.fold.1" "$tmp/b3/c.b3"
sed 's/F(1) = PAR(1) - U(1)\*\*2/F(1) = PAR(1) - U(1)**/' "$tmp/fold/fold.f90" > "$tmp/b3/b3.f90"
bad b3 'b3.f90:5' "equations that do not compile (the compiler's FILE:LINE)"
cp "$tmp/fold/c.fold.1" "$tmp/b4/c.b4"
sed '/SUBROUTINE STPNT/,$d' "$tmp/fold/fold.f90" > "$tmp/b4/b4.f90"
bad b4 'stpnt_' "STPNT missing from the equations"
# a later constants file's NDIM out of range: found before any run (each
# NDIM has a plug-in of its own), so run 1 writes nothing either
mkdir "$tmp/b5"
cp "$tmp/fold/fold.f90" "$tmp/b5/b5.f90"
cp "$tmp/fold/c.fold.1" "$tmp/b5/c.b5.1"
printf 'NDIM= -1, IPS = 1\nICP = [1]\n' > "$tmp/b5/c.b5.2"
bad b5 'b5/c.b5.2:1: NDIM = -1: must be >= 1' "a second constants file with NDIM = -1"
# a restart the default order cannot make, beside the demo's script: the
# error, then the script named as the way to run it (exit 2, nothing
# written); without the script, the error alone
mkdir "$tmp/b7"
cp "$tmp/fold/fold.f90" "$tmp/b7/b7.f90"
sed 's/^IRS.*//' "$tmp/fold/c.fold.1" > "$tmp/b7/c.b7"
printf 'IRS = 3\n' >> "$tmp/b7/c.b7"
bad b7 'b7/c.b7:[0-9]*: IRS = 3: no earlier run to restart from' "a restart from no earlier run (no script)"
[ "$(wc -l < "$tmp/b7.err")" = 1 ]
check $? "  and without b7.auto no word of a script ($(wc -l < "$tmp/b7.err") line)"
printf 'run(e="b7", c="b7")\n' > "$tmp/b7/b7.auto"
bad b7 'b7/b7.auto orders the runs of these constants files: .whirl auto b7 b7 --script. runs it' \
  "the same beside its script b7.auto"
# the plug-in links whirl's adapter of AUTO's routines (drivers/
# auto_adapter.c, libwhirl-auto-adapter.a): without it, one message naming
# it, exit 1, nothing written; with it, the plug-in's own C file holds the
# model's data alone (the routines' adapter is not compiled a demo)
mkdir "$tmp/b6"
cp "$tmp/fold/fold.f90" "$tmp/b6/b6.f90"
cp "$tmp/fold/c.fold.1" "$tmp/b6/c.b6"
(cd "$tmp" && WHIRL_AUTO_ADAPTER="$tmp/none/libwhirl-auto-adapter.a" "$WHIRL" auto b6 --quiet \
   > /dev/null 2> b6.err); st=$?
[ $st = 1 ] && [ "$(wc -l < "$tmp/b6.err")" = 1 ] &&
  grep -q "none/libwhirl-auto-adapter.a: No such file or directory" "$tmp/b6.err" &&
  [ ! -e "$tmp/b6.out" ] && ! ls -d "$tmp/b6".out.tmp.* > /dev/null 2>&1
check $? "no adapter archive: exit $st, '$(head -1 "$tmp/b6.err")', nothing written"
(cd "$tmp" && "$WHIRL" auto b6 --quiet > /dev/null 2>&1) &&
  ! grep -q 'func_\|getp_' "$tmp/b6.out/auto_model.c" && grep -q 'wa_ndim = 1,' "$tmp/b6.out/auto_model.c"
check $? "the plug-in's C file is the model's data (NDIM 1), the adapter linked from the archive"

# c-files of two NDIMs (demo pcl's extended systems): a plug-in each, the
# equations compiled once (FC a wrapper that counts its -c calls), and a
# later invocation with a third NDIM links the object the first left in
# the output directory
mkdir "$tmp/nd"
cat > "$tmp/nd/nd.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*), I
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      DO I = 1, NDIM
        F(I) = PAR(1) - U(I)**2
      END DO
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM, I
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1
      DO I = 1, NDIM
        U(I) = 1
      END DO
      END SUBROUTINE STPNT
F
for k in 1 2 3; do
  sed -e "s/^NDIM=   1,/NDIM=   $k,/" -e 's/^NMX=  200/NMX=  20/' -e 's/JAC= 1/JAC= 0/' "$tmp/fold/c.fold.1" > "$tmp/nd/c.nd.$k"
done
mv "$tmp/nd/c.nd.3" "$tmp/nd3"
cat > "$tmp/fc" <<W
#!/bin/sh
case " \$* " in *" -c "*) echo "\$*" >> "$tmp/fc.log" ;; esac
exec "${FC:-gfortran}" "\$@"
W
chmod +x "$tmp/fc"
(cd "$tmp" && FC="$tmp/fc" "$WHIRL" auto nd --quiet > /dev/null 2>&1) &&
  [ "$(grep -c 'nd.f90' "$tmp/fc.log")" = 1 ] && [ -s "$tmp/nd.out/nd.so" ] &&
  [ -s "$tmp/nd.out/nd.ndim2.so" ] && [ -s "$tmp/nd.out/b.nd.2" ] && [ -s "$tmp/nd.out/nd.eq.o" ]
check $? "c-files of NDIM 1 and 2: two plug-ins, the equations compiled once ($(grep -c 'nd.f90' "$tmp/fc.log" 2>/dev/null) -c call)"
mv "$tmp/nd3" "$tmp/nd/c.nd.3"
(cd "$tmp" && FC="$tmp/fc" "$WHIRL" auto nd --runs=nd.3 --quiet > /dev/null 2>&1) &&
  [ "$(grep -c 'nd.f90' "$tmp/fc.log")" = 1 ] && grep -q 'wa_ndim = 3,' "$tmp/nd.out/auto_model.c" &&
  [ -s "$tmp/nd.out/b.nd.3" ]
check $? "a later invocation with NDIM 3: its plug-in from the object in nd.out, no compilation of the equations"
(cd "$tmp" && sleep 1 && touch "$tmp/nd/nd.f90" && FC="$tmp/fc" "$WHIRL" auto nd --runs=nd.3 --quiet > /dev/null 2>&1) &&
  [ "$(grep -c 'nd.f90' "$tmp/fc.log")" = 2 ]
check $? "equations newer than the object: compiled again"
# another demo of the same NAME, its equations older than the object, into
# the same output directory: its own equations compiled, not the object
# of the first (u = +-sqrt(p/2) here: its branch starts at u = 1, p = 2)
mkdir "$tmp/other" "$tmp/other/nd"
sed 's/F(I) = PAR(1) - U(I)\*\*2/F(I) = PAR(1) - 2*U(I)**2/; s/PAR(1) = 1$/PAR(1) = 2/' \
  "$tmp/nd/nd.f90" > "$tmp/other/nd/nd.f90"
cp "$tmp/nd/c.nd.3" "$tmp/other/nd/"
touch -d '2001-01-01' "$tmp/other/nd/nd.f90"
(cd "$tmp" && FC="$tmp/fc" "$WHIRL" auto other/nd --runs=nd.3 --out=nd.out --quiet > /dev/null 2>&1) &&
  [ "$(grep -c 'nd.f90' "$tmp/fc.log")" = 3 ] && grep -q 'other/nd/nd.f90' "$tmp/nd.out/nd.eq.src" &&
  awk '$1 == 1 && ($2 == 1 || $2 == -1) { found = ($5 + 0 > 1.99 && $5 + 0 < 2.01) } END { exit !found }' "$tmp/nd.out/b.nd.3"
check $? "another demo's equations of the same NAME, older than the object: compiled, its own branch (p = 2 at u = 1)"

# A branch with a corner, u = |p| (kink.f90): from p = 1 down, every step
# past the corner fails and the steps shrink to DSMIN.  AUTO ends such a
# branch with an MX label at its last point (TY -9, a solution a restart
# may name; AUTO-07p's own run of these files: PT 11, LAB 2, p =
# 1.06717E-04) and the run goes on; whirl auto's run files ask for that
# (MX = label), a run file without it fails as before.
mkdir "$tmp/kink"
cat > "$tmp/kink/kink.f90" <<'F'
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, IJAC, ICP(*)
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)
      F(1) = U(1) - ABS(PAR(1))
      END SUBROUTINE FUNC
      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1
      U(1) = 1
      END SUBROUTINE STPNT
F
cat > "$tmp/kink/c.kink.1" <<'C'
NDIM = 1, IPS = 1, IRS = 0, ILP = 0, ICP = [1]
NTST = 20, NCOL = 4, IAD = 3, ISP = 0, ISW = 1, IPLT = 0, NBC = 0, NINT = 0
NMX = 100, NPR = 100, MXBF = 0, IID = 2, ITMX = 8, ITNW = 5, NWTN = 3, JAC = 0
EPSL = 1e-8, EPSU = 1e-8, EPSS = 1e-6
DS = -0.1, DSMIN = 1e-4, DSMAX = 0.2, IADS = 1
NPAR = 1, THL = {}, THU = {}
C
sed -e 's/IRS = 0/IRS = 2/' -e 's/DS = -0.1/DS = 0.1/' -e 's/NMX = 100/NMX = 20/' \
  "$tmp/kink/c.kink.1" > "$tmp/kink/c.kink.2"
(cd "$tmp" && "$WHIRL" auto kink --quiet > kink.log 2> kink.err)
st=$?
check $st "whirl auto kink: the branch ending at DSMIN is no failure (exit $st) $(head -1 "$tmp/kink.err")"
# the last two rows of run 1: the last point, then the MX one PT on, label
# 2, the same values; the corner within a few DSMIN
res=$(awk 'substr($0, 1, 4) + 0 != 0 { p2 = p1; p1 = $0 } END {
    split(p2, a, " "); split(p1, b, " ");
    if (b[3] != -9 || b[4] != 2 || b[2] != a[2] + 1) print "types", a[3], b[3], b[4];
    for (i = 5; i <= 7; i++) if (a[i] != b[i]) print "column", i;
    if (!(b[5] + 0 > 0 && b[5] + 0 < 1e-3) || b[7] != b[5]) print "p", b[5], "u", b[7] }' \
  "$tmp/kink.out/b.kink.1" 2>&1)
check "$([ -z "$res" ] && echo 0 || echo 1)" "b.kink.1: the MX row (TY -9, LAB 2) at the last point, PT + 1, by the corner u = p = $(tail -1 "$tmp/kink.out/b.kink.1" | awk '{print $5}') ${res}"
awk 'NR == 1 || ($1 + 0 > 0 && NF == 16) { if ($3 == -9 && $4 == 2) f = 1 } END { exit !f }' "$tmp/kink.out/s.kink.1"
check $? "s.kink.1: the MX solution, label 2 of type -9 (a header AUTO's restarts read)"
grep -q '^MX *= *label' "$tmp/kink.out/kink.1.whirl" && grep -q 'MX  LAB 2' "$tmp/kink.out/kink.1.out/run.log"
check $? "kink.1.whirl asks for MX = label; run.log names the MX label"
last=$(awk 'substr($0, 1, 4) + 0 != 0 { p = $5 } END { print p }' "$tmp/kink.out/b.kink.2")
awk -v p="$last" 'BEGIN { exit !(p + 0 > 1) }'
check $? "c.kink.2 restarts from the MX (IRS = 2) and goes back up the branch (p = $last after NMX)"
(cd "$tmp/kink.out" && "$WHIRL" run kink.1.whirl --MX=fail --OUT=fail.out --quiet --no-plot > ../kinkf.log 2>&1)
st=$?
[ "$st" = 1 ] && grep -q 'no convergence with minimum step size' "$tmp/kinkf.log"
check $? "MX = fail (whirl's default): the same branch fails the run, exit $st: $(head -1 "$tmp/kinkf.log")"
(cd "$tmp/kink.out" && "$WHIRL" run kink.1.whirl --MX=maybe --OUT=bad.out --quiet --no-plot > ../kinkb.log 2>&1)
st=$?
[ "$st" = 2 ] && grep -q "neither fail nor label" "$tmp/kinkb.log" && [ ! -e "$tmp/kink.out/bad.out" ]
check $? "MX = maybe: exit $st, '$(head -1 "$tmp/kinkb.log")', nothing written"
(cd "$tmp/kink.out" && "$WHIRL" run kink.1.whirl --PHASE=sometimes --OUT=badp.out --quiet --no-plot > ../kinkp.log 2>&1)
st=$?
[ "$st" = 2 ] && grep -q "PHASE: 'sometimes' is neither gauss nor nodes" "$tmp/kinkp.log" && [ ! -e "$tmp/kink.out/badp.out" ]
check $? "PHASE = sometimes: exit $st, '$(head -1 "$tmp/kinkp.log")', nothing written"

# AUTO's parseB, parseS and parseD on b., s., d. of the stems $3... in
# directory $1 (output in $2): the same labels in b. and s., each non-empty
auto_parse() {
  dir=$1 out=$2
  shift 2
  (cd "$dir" && python3 - "$py" "$@" > "$out" 2>&1 <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from auto import parseB, parseS, parseD
for stem in sys.argv[2:]:
    b = parseB.parseB("b." + stem)
    s = parseS.parseS("s." + stem)
    parseD.parseD("d." + stem)
    bl = sorted(b.getLabels())
    sl = sorted(x["Label"] for x in s)
    assert bl == sl and bl, (stem, bl, sl)
    print(stem, len(bl), "labels", b.branches[0].coordnames)
PY
  )
}

# AUTO-07p's demo ab
auto=${AUTO_07P_DIR:-$top_srcdir/../shared/auto-07p}
if [ -d "$auto/demos/ab" ]; then
  auto=$(cd "$auto" && pwd)
  (cd "$tmp" && "$WHIRL" auto "$auto/demos/ab" --runs=ab.1,ab.2@2 --quiet > ab.log 2>&1)
  check $? "whirl auto ab --runs=ab.1,ab.2@2 exits 0"
  hb=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 3' "$tmp/ab.out/b.ab.2@2" | head -1)
  echo "$hb" | awk '{ split("1.65042E-01 1.47770E+00 4.05955E-01 1.42084E+00", a, " ");
    for (i = 1; i <= 4; i++) { d = ($(i + 4) - a[i]) / a[i]; if (d < 0) d = -d; if (d > 1e-5) exit 1 } }'
  check $? "b.ab.2@2: the HB agrees with AUTO's (hyper.all) to its 6 digits: $hb"
  head -1 "$tmp/ab.out/s.ab.1" | grep -qx '     1     1     9     1     1     1       1     3       6    1    0   11    0    2    1    0'
  check $? "s.ab.1: label 1's header as AUTO writes it"
  labs=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 15, 5) + 0 > 0 { printf "%d ", substr($0, 15, 5) }' "$tmp/ab.out/b.ab")
  nl=$(grep -c '^LAB' "$tmp/ab.out/ab.1.out/solutions"); n2=$(grep -c '^LAB' "$tmp/ab.out/ab.2@2.out/solutions")
  # AUTO does not label the first point of a restart (run 2's EP at PT 1)
  [ "$labs" = "$(seq -s ' ' 1 $((nl + n2 - 1))) " ]
  check $? "b.ab: both runs, labels numbered on 1..$((nl + n2 - 1)) as AUTO does, the restart's start unlabelled ($labs)"
  py=${AUTO_07P_PYTHON:-/usr/lib/auto-07p/python}
  if [ -f "$py/auto/parseB.py" ] && command -v python3 >/dev/null 2>&1; then
    auto_parse "$tmp/ab.out" "$tmp/py.out" ab.1 ab.2@2 ab
    check $? "AUTO's parseB, parseS, parseD read b., s., d. of both runs and the merged b.ab, s.ab, d.ab: $(tr '\n' ';' < "$tmp/py.out" | cut -c1-160)"
  else
    n=$((n + 1)); echo "ok $n - # SKIP AUTO's Python tools not installed (apt-get install auto-07p)"
  fi
else
  n=$((n + 1)); echo "ok $n - # SKIP no AUTO-07p demos at $auto (set AUTO_07P_DIR)"
fi

# AUTO-07p's demo kar (IPS = 4, NTST 40, IAD = 3): its branch ends at
# DSMIN where PAR(1) = gamma crosses 0 the fourth time, after a mesh
# adaptation in the failing steps; AUTO's own run ends there in MX 8.  The
# MX solution is the last point on the mesh the run now has (the mesh its
# s-file row holds): its L2-NORM is the last row's to the interpolation
# error (the last point's values on the new mesh gave 5.6157 for 5.5588)
if [ -d "$auto/demos/kar" ]; then
  (cd "$tmp" && "$WHIRL" auto "$auto/demos/kar" --quiet > kar.log 2>&1)
  st=$?
  res=$(awk 'substr($0, 1, 4) + 0 != 0 { p2 = p1; p1 = $0 } END {
      split(p2, a, " "); split(p1, b, " "); d = (b[6] - a[6]) / a[6];
      if (d < 0) d = -d;
      if (b[3] != -9 || b[4] != 8 || b[5] != a[5] || !(d < 1e-6)) print a[6], b[3], b[4], b[6] }' \
    "$tmp/kar.out/b.kar.1" 2>&1)
  [ "$st" = 0 ] && [ -z "$res" ]
  check $? "whirl auto kar: exit $st, the branch ends in MX 8 as AUTO's, its L2-NORM the last point's on the new mesh $res"
fi

# AUTO-07p's demo exp: a boundary-value problem (IPS = 4, Bratu)
if [ -d "$auto/demos/exp" ]; then
  py=${AUTO_07P_PYTHON:-/usr/lib/auto-07p/python}
  (cd "$tmp" && "$WHIRL" auto "$auto/demos/exp" --quiet > exp.log 2>&1)
  check $? "whirl auto exp (IPS = 4, both c-files) exits 0: $(tail -1 "$tmp/exp.log")"
  lp=$(awk 'substr($0, 1, 4) + 0 != 0 && substr($0, 11, 4) + 0 == 5' "$tmp/exp.out/b.exp.1" | head -1)
  # AUTO's LP 8 (hyper.all): lambda, INTEGRAL u, MAX v (MAX u is taken
  # over each one's mesh nodes: test/auto-demos/known-gaps)
  echo "$lp" | awk '{ split("3.51383E+00 7.61901E-01 - 4.00000E+00", a, " ");
    for (i = 1; i <= 4; i++) { if (a[i] == "-") continue; d = ($(i + 4) - a[i]) / a[i]; if (d < 0) d = -d; if (d > 1e-5) exit 1 } }'
  check $? "b.exp.1: the fold as AUTO's LP (type 5 of BVPs), lambda, INTEGRAL u, MAX v to its 6 digits: $lp"
  head -1 "$tmp/exp.out/s.exp.1" | awk '{ exit !($7 == 41 && $8 == 3 && $10 == 10 && $11 == 4 && $15 == 4) }'
  check $? "s.exp.1: 41 nodes of (t, u, v) on NTST 10, NCOL 4, IPS 4 in the header: $(head -1 "$tmp/exp.out/s.exp.1")"
  if [ -f "$py/auto/parseB.py" ] && command -v python3 >/dev/null 2>&1; then
    auto_parse "$tmp/exp.out" "$tmp/pye.out" exp.1 exp.2 exp
    check $? "AUTO's parseB, parseS, parseD read exp's b., s., d. (IPS 4): $(tr '\n' ';' < "$tmp/pye.out" | cut -c1-160)"
  else
    n=$((n + 1)); echo "ok $n - # SKIP AUTO's Python tools not installed (apt-get install auto-07p)"
  fi
fi
echo "1..$n"
exit $fail

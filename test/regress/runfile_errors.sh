#!/bin/sh
# test/regress/runfile_errors.sh — malformed run files and command-line
# overrides given to `whirl run`.  For every case of the table below:
#   - the exit status is the expected one (2: a mistake in the run file);
#   - stderr is exactly ONE line, and it matches the case's regex, which
#     names the place: "whirl run: case.whirl:LINE: ..." for a mistake in
#     the file, "whirl run: command line (--KEY=...): ..." for an override;
#   - no output directory (case.out, or OUT) and no temporary directory
#     (*.tmp.*) is left behind, and the directories that existed before (a
#     previous run's output, a foreign directory) are untouched.
# The valid model is AUTO's demo ab (examples/auto/ab.c) built as a plug-in;
# two broken plug-ins (no whirl_model_def, wrong ABI number) are built here
# too, so the script needs a C compiler ($CC, default cc) and skips (77)
# without one.  Positive controls first check that the base run file works.
#
# RUNFILE_ERRORS_MD=FILE: also write the table (mistake, run file, message
# printed) as Markdown rows to FILE (used for doc/run-file-errors.md).
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
WHIRL="$top_builddir/drivers/whirl"
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
case $top_srcdir in /*) ;; *) top_srcdir="$(pwd)/$top_srcdir" ;; esac
CC=${CC:-cc}
md=${RUNFILE_ERRORS_MD:-}

# shellcheck disable=SC2086 # CC may carry flags ("gcc -m64")
set -- $CC
if ! command -v "$1" > /dev/null 2>&1; then
  echo "1..0 # SKIP no C compiler ($CC) to build the test plug-ins"
  exit 77
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-rferr.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
diag() { sed 's/^/# /' "$@"; }

w="$tmp/w"
mkdir -p "$w/sub" || exit 1
cd "$w" || exit 1

# ---- plug-ins -------------------------------------------------------------
$CC -std=c11 -shared -fPIC -I"$top_srcdir/lib" -o ab.so \
  "$top_srcdir/examples/auto/ab.c" -lm > "$tmp/cc.log" 2>&1
rc=$?
ok $rc "ab.so (examples/auto/ab.c) builds as a plug-in"
printf 'int whirl_not_the_model = 1;\n' > nosym.c
$CC -shared -fPIC -o nosym.so nosym.c >> "$tmp/cc.log" 2>&1
rc2=$?
ok $rc2 "nosym.so (no whirl_model_def) builds"
printf '#include <whirl/model.h>\nconst whirl_model whirl_model_def = {.abi = WHIRL_MODEL_ABI + 41};\n' > abi.c
$CC -std=c11 -shared -fPIC -I"$top_srcdir/lib" -o abi.so abi.c >> "$tmp/cc.log" 2>&1
rc3=$?
ok $rc3 "abi.so (model ABI + 41) builds"
if [ $rc -ne 0 ] || [ $rc2 -ne 0 ] || [ $rc3 -ne 0 ]; then
  diag "$tmp/cc.log"
  echo "Bail out! cannot build the test plug-ins with $CC"
  exit 1
fi
cp ab.so sub/ab.so

# ---- positive controls -----------------------------------------------------
# the base of every case: a valid run; its output ab-1.out is the S of the
# restart cases (labels 1 EP, 2 and 3 HB, 4 EP)
printf 'model = ./ab.so\nICP = [Da]\nPAR = {B: 14, beta: 3}\nNMX = 50\n' > ab-1.whirl
"$WHIRL" run ab-1.whirl --quiet > "$tmp/stdout" 2> "$tmp/stderr"
rc=$?
ok $rc "control: a valid run file (model = ./ab.so) runs, exit 0"
[ $rc -eq 0 ] || diag "$tmp/stderr"
[ -f ab-1.out/solutions ] && grep -q '^LAB 2 ' ab-1.out/solutions
ok $? "control: it writes ab-1.out/solutions with label 2"
printf 'model = ab.so\nICP = [Da]\nNMX = 5\n' > sub/bare.whirl
"$WHIRL" run sub/bare.whirl --quiet > "$tmp/stdout" 2> "$tmp/stderr"
rc=$?
ok $rc "control: 'model = ab.so' is relative to the run file (whirl run sub/bare.whirl)"
[ $rc -eq 0 ] || diag "$tmp/stderr"
rm -rf bare.out
cp sub/bare.whirl bare.whirl
"$WHIRL" run bare.whirl --quiet > "$tmp/stdout" 2> "$tmp/stderr"
rc=$?
ok $rc "control: 'model = ab.so' with the run file in the current directory (whirl run bare.whirl)"
[ $rc -eq 0 ] || diag "$tmp/stderr"
rm -rf bare.out bare.whirl
# numbers: a denormal is a number (the nearest double); blanks after '='
# are fine in an override as in the file; PLOT takes a parameter, a state
# component, MAX of one, L2-NORM (the picture's y label says which)
ctl() { # OVERRIDE YLABEL
  rm -rf ctl.out
  "$WHIRL" run ab-1.whirl --quiet "$1" --OUT=ctl.out > "$tmp/stdout" 2> "$tmp/stderr" &&
    grep -q "^set ylabel '$2' " ctl.out/diagram.gp
  rc=$?
  ok $rc "control: whirl run ab-1.whirl $1 runs, exit 0, y axis $2"
  [ $rc -eq 0 ] || diag "$tmp/stderr"
  rm -rf ctl.out
}
ctl --DSMIN=1e-310 L2-NORM
ctl '--NMX= 5' L2-NORM
ctl --PLOT=beta beta
ctl --PLOT=u2 u2
ctl '--PLOT=MAX u1' u1
ctl --PLOT=l2-norm L2-NORM
# a directory that is not a whirl output
mkdir notwhirl.out && echo "not whirl's" > notwhirl.out/keep.txt
: > plain.out

# restarts from solutions that do not fit the model: ab3.so is ab with a
# third state u3' = -u3 (a plug-in that gained a state and kept its name),
# abf.so is ab forced at the frequency beta (periodic orbits have no period
# unknown); po.out holds periodic orbits by collocation (NTST 10, NCOL 4)
# from the HB of ab-1.out; edit-*.s are copies of solutions files with one
# thing changed (sed script)
cat > abx.c <<'EOF_C'
#include <math.h>
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  const double r = p[0] * (1.0 - u[0]) * exp(u[1]);
  (void)d;
  f[0] = -u[0] + r + FORCED * 0.01 * cos(p[2] * t);
  f[1] = -u[1] + p[1] * r - p[2] * u[1];
  if (NSTATE == 3) f[NSTATE - 1] = -u[NSTATE - 1];
  return 0;
}
static const char *const xn[] = {"u1", "u2", "u3"};
static const char *const pn[] = {"Da", "B", "beta"};
static const double par0[] = {0.0, 14.0, 3.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "ab", .n = NSTATE, .npar = 3, .rhs = rhs,
                .autonomous = !FORCED, .x_names = xn, .p_names = pn},
    .par0 = par0, .forcing_param = FORCED ? 2 : -1};
EOF_C
$CC -std=c11 -shared -fPIC -I"$top_srcdir/lib" -DNSTATE=3 -DFORCED=0 -o ab3.so abx.c -lm > "$tmp/cc.log" 2>&1 &&
  $CC -std=c11 -shared -fPIC -I"$top_srcdir/lib" -DNSTATE=2 -DFORCED=1 -o abf.so abx.c -lm >> "$tmp/cc.log" 2>&1
rc=$?
ok $rc "ab3.so (ab with a third state) and abf.so (ab forced) build"
[ $rc -eq 0 ] || diag "$tmp/cc.log"
printf 'model = ./ab.so\nICP = [Da]\nIPS = 2\nS = ab-1.out\nIRS = 2\nNTST = 10\nNMX = 12\nNPR = 5\nOUT = po.out\n' > po.whirl
"$WHIRL" run po.whirl --quiet > "$tmp/stdout" 2> "$tmp/stderr" && grep -q '^LAB 3 .* NX 83 .* NTST 10 NCOL 4$' po.out/solutions
rc=$?
ok $rc "control: periodic orbits from the HB of ab-1.out (po.out, label 3 with NX 83)"
[ $rc -eq 0 ] || diag "$tmp/stderr"
printf 'model = ./ab.so\nICP = [Da]\nIPS = 2\nS = po.out\nIRS = 3\nNTST = 10\nNMX = 3\nOUT = po2.out\n' > po2.whirl
"$WHIRL" run po2.whirl --quiet > "$tmp/stdout" 2> "$tmp/stderr"
rc=$?
ok $rc "control: a restart from label 3 of po.out runs, exit 0"
[ $rc -eq 0 ] || diag "$tmp/stderr"
rm -rf po2.out po.whirl po2.whirl
edit() { # NAME SOURCE SED-SCRIPT: edit-NAME.s/solutions
  mkdir "edit-$1.s" && sed "$3" "$2/solutions" > "edit-$1.s/solutions"
}
L2='/^LAB 2 /,/^END/'   # the block of label 2 (an HB) of ab-1.out
L3='/^LAB 3 /,/^END/'   # the block of label 3 of po.out
edit nx3 ab-1.out "$L2"'{s/ NX 2 / NX 3 /; /^[XT]/s/$/ 0/;}'
edit xshort ab-1.out "$L2"'{/^X /s/ [^ ]*$//;}'
edit tanshort ab-1.out "$L2"'{/^TAN /s/ [^ ]*$//;}'
edit xnan ab-1.out "$L2"'{/^X /s/ [^ ]* / nan /;}'
edit xtext ab-1.out "$L2"'{/^X /s/ [^ ]*$/ 1.5x/;}'
edit par4 ab-1.out '/^LAB 1 /,/^END/{/^PAR /s/$/ 7/;}'
edit npar ab-1.out '1s/npar 3/npar 4/'
edit ty ab-1.out "$L2"'{s/ TY HB / TY HBX /;}'
edit kind ab-1.out "$L2"'{s/ KIND eq / KIND cycle /;}'
edit junk ab-1.out "$L2"'{s/ STAB 1$/ STAB 1 NTST 9/;}'
edit icp ab-1.out "$L2"'{s/ ICP 1 / ICP 7 /;}'
edit mesh ab-1.out "$L2"'{s/^END$/MESH 0 1\nEND/;}'
edit noend ab-1.out '$d'
edit empty ab-1.out 'd'
edit lp ab-1.out "$L2"'{s/ TY HB / TY LP /;}'
edit bp ab-1.out '/^LAB 1 /s/ TY EP / TY BP /'
edit ntst po.out "$L3"'{s/ NTST 10 / NTST 11 /;}'
edit meshshort po.out "$L3"'{/^MESH /s/ [^ ]*$//;}'
edit meshorder po.out "$L3"'{/^MESH /s/ 1$/ 0.99/;}'
edit pd po.out "$L3"'{s/ TY RG / TY PD /;}'
mkdir hbm.s && awk 'NR == 1 { print; print "LAB 1 TY UZ BR 1 PT 0 KIND hbm ICP 1 ICP2 0 NX 35 STAB 1 NHB 8"
  print "PAR 0.16 14 3"; x = "X"; for (i = 0; i < 35; i++) x = x " 0.5"; print x; print "END" }' \
  ab-1.out/solutions > hbm.s/solutions

before=$(ls -d ./*.out ./*.tmp.* 2>/dev/null)

# ---- the table -------------------------------------------------------------
# c STATUS "mistake" 'regex of the one stderr line' 'run file (printf format)' [override ...]
c() {
  want=$1 what=$2 re=$3 text=$4
  shift 4
  # shellcheck disable=SC2059
  printf "$text" > case.whirl
  "$WHIRL" run case.whirl "$@" > "$tmp/stdout" 2> "$tmp/stderr"
  rc=$?
  lines=$(wc -l < "$tmp/stderr" | tr -d ' ')
  chars=$(wc -c < "$tmp/stderr" | tr -d ' ')
  msg=$(head -n 1 "$tmp/stderr")
  ok $(( rc != want )) "$what: exit $rc (want $want)"
  one=1
  [ "$lines" -eq 1 ] && [ "$chars" -gt 0 ] && one=0
  match=1
  [ $one -eq 0 ] && printf '%s\n' "$msg" | grep -Eq -- "$re" && match=0
  ok $(( one || match )) "$what: one line on stderr: $msg"
  if [ $(( one || match )) -ne 0 ]; then
    echo "#   wanted /$re/, got $lines line(s):"
    diag "$tmp/stderr"
  fi
  after=$(ls -d ./*.out ./*.tmp.* 2>/dev/null)
  left=0
  [ "$after" = "$before" ] || left=1
  [ -f notwhirl.out/keep.txt ] && [ -f ab-1.out/solutions ] && [ -f plain.out ] || left=1
  ok $left "$what: no output or temporary directory left"
  if [ $left -ne 0 ]; then
    echo "#   before: $(echo "$before" | tr '\n' ' ')"
    echo "#   after:  $(echo "$after" | tr '\n' ' ')"
  fi
  if [ -n "$md" ]; then
    # Markdown: '|' escaped, lines joined by ⏎, code spans with `` ``
    shown=$(printf '%s' "$text" | sed 's/\\n/ ⏎ /g; s/\\000/\\0/g; s/ ⏎ $//; s/|/\\|/g')
    [ -n "$shown" ] || shown="(empty file)"
    args=""
    [ $# -gt 0 ] && args=" \`$*\`"
    mark=""
    [ $(( rc != want || one || match || left )) -ne 0 ] && mark=" **(test fails)**"
    # shellcheck disable=SC2016 # backquotes are Markdown here
    printf '| %s | `%s`%s | `` %s ``%s |\n' "$(printf '%s' "$what" | sed 's/|/\\|/g')" \
      "$shown" "$args" "$(printf '%s' "$msg" | sed 's/|/\\|/g')" "$mark" >> "$md"
  fi
  # leave nothing for the next case (whatever this one left)
  for d in ./*.out ./*.tmp.*; do
    case " $before " in *"$d"*) ;; *) rm -rf "$d" ;; esac
  done
}
[ -n "$md" ] && : > "$md"

B='model = ./ab.so\nICP = [Da]\n'   # lines 1-2 of most cases
F='^whirl run: case\.whirl'         # the file, in regexes
q="[\"']"                           # a quote in a message

# key names
c 2 "typo in a key" "$F:3: unknown key ${q}DSMX$q \(did you mean DSMAX\?\)$" "$B"'DSMX = 0.1\n'
c 2 "typo in a long alias" "$F:3: unknown key ${q}stpe$q \(did you mean step\?\)$" "$B"'stpe = 0.1\n'
c 2 "unknown key, nothing close" "$F:3: unknown key ${q}frobnicate$q" "$B"'frobnicate = 1\n'
c 2 "blank inside a key" "$F:3: .*not a key name" "$B"'D S = 1\n'
c 2 "non-ASCII byte in a key" "$F:3: .*not a key name" "$B"'D\351 = 1\n'
c 2 "key missing before '='" "$F:3: a key is missing" "$B"'= 5\n'
c 2 "line without '='" "$F:3: expected ${q}key = value$q" "$B"'NMX 100\n'
c 2 "key given twice" "$F:4: DS given twice \(first at line 3\)$" "$B"'DS = 0.01\nDS = 0.02\n'
c 2 "key given twice (name and alias)" "$F:4: DS given twice \(first at line 3\)$" "$B"'DS = 0.01\nstep = 0.02\n'
# values
c 2 "no value after '='" "$F:3: DS: no value" "$B"'DS =\n'
c 2 "text where a number goes" "$F:3: DS: ${q}abc$q is not a finite number$" "$B"'DS = abc\n'
c 2 "text where an integer goes" "$F:3: NMX: ${q}many$q is not an integer$" "$B"'NMX = many\n'
c 2 "fraction where an integer goes" "$F:3: NMX: ${q}2\.5$q is not an integer$" "$B"'NMX = 2.5\n'
c 2 "decimal comma" "$F:3: DS: " "$B"'DS = 0,01\n'
c 2 "NaN value" "$F:3: DS: ${q}nan$q is not a finite number$" "$B"'DS = nan\n'
c 2 "inf value" "$F:3: DSMAX: ${q}inf$q is not a finite number$" "$B"'DSMAX = inf\n'
c 2 "overflowing value" "$F:3: RL1: ${q}1e999$q is not a finite number$" "$B"'RL1 = 1e999\n'
c 2 "NaN in a dictionary" "$F:3: PAR: ${q}nan$q is not a finite number$" "$B"'PAR = {B: nan}\n'
c 2 "DS = 0" "$F:3: DS = 0: must not be 0$" "$B"'DS = 0\n'
c 2 "DSMIN > DSMAX (both given)" "$F:4: DSMIN = 0\.5 exceeds DSMAX = 0\.1$" "$B"'DSMIN = 0.5\nDSMAX = 0.1\n'
c 2 "DSMAX below the default DSMIN" "$F:3: DSMIN = 1e-05 exceeds DSMAX = 1e-06$" "$B"'DSMAX = 1e-6\n'
c 2 "RL0 >= RL1" "$F:4: RL0 = 2 must be below RL1 = 1$" "$B"'RL0 = 2\nRL1 = 1\n'
c 2 "A0 >= A1" "$F:4: A0 = 5 must be below A1 = 1$" "$B"'A0 = 5\nA1 = 1\n'
c 2 "NCOL out of range" "$F:3: NCOL = 8: must be in \[2, 7\]$" "$B"'NCOL = 8\n'
c 2 "NWTN negative" "$F:3: NWTN = -1: must be in \[0, 1000\] \(0: a new Jacobian at every iteration\)$" "$B"'NWTN = -1\n'
c 2 "JAC out of range" "$F:3: JAC = 2: must be 0" "$B"'JAC = 2\n'
c 2 "ISP out of range (5)" "$F:3: ISP = 5: must be 0, 1, 2, 3 or 4" "$B"'ISP = 5\n'
c 2 "ISW out of range" "$F:3: ISW = 4: must be 1" "$B"'ISW = 4\n'
c 2 "IPS = 9 unsupported" "$F:3: IPS = 9 is not supported" "$B"'IPS = 9\n'
c 2 "IPS = 4 with too few conditions" "$F: IPS = 4: NBC \\+ NINT = 0 is less than NDIM = 2" "$B"'IPS = 4\n'
c 2 "unknown METHOD" "$F:3: METHOD: ${q}rk4$q is not a method" "$B"'METHOD = rk4\n'
c 2 "UZR not a dictionary" "$F:3: UZR: expected a dictionary" "$B"'UZR = 0.1\n'
c 2 "JAC = -1 (AUTO has 0 and 1)" "$F:3: JAC = -1: must be 0 \(finite differences\) or 1" "$B"'JAC = -1\n'
c 2 "dictionary key twice (PAR)" "$F:3: PAR: key ${q}B$q given twice$" "$B"'PAR = {B: 14, B: 15}\n'
c 2 "dictionary key twice (UZR)" "$F:3: UZR: key ${q}Da$q given twice$" "$B"'UZR = {Da: 0.1, Da: 0.2}\n'
c 2 "dictionary key twice (THL)" "$F:3: THL: key ${q}11$q given twice$" "$B"'THL = {11: 0, 11: 1}\n'
c 2 "negative arclength weight" "$F:3: THU: weight -1 is negative" "$B"'THU = {1: -1}\n'
c 2 "THL on no parameter" "$F:3: THL: ${q}foo$q is not a parameter of model" "$B"'THL = {foo: 0}\n'
c 2 "THU beyond the state" "$F:3: THU: ${q}U\(7\)$q is not a state component of model" "$B"'THU = {7: 1}\n'
c 2 "THL 0 on the continuation parameter, THU 0 on the state" "$F:4: THL, THU: every weight of the unknowns is 0" "$B"'THL = {Da: 0}\nTHU = {1: 0, 2: 0}\n'
c 2 "one parameter by name and index" "$F:3: PAR: ${q}B$q and ${q}2$q are the same parameter$" "$B"'PAR = {B: 14, 2: 15}\n'
c 2 "one component by name and U(k)" "$F:3: U: ${q}u1$q and ${q}U\(1\)$q are the same state component$" "$B"'U = {u1: 0, U(1): 1}\n'
c 2 "blank in a quoted label" "$F:3: IRS: ${q} 2$q is not a label" "$B""IRS = ' 2'\nS = ab-1.out\n"
c 2 "blank in a type count" "$F:3: IRS: ${q}HB 1$q is not a label" "$B""IRS = 'HB 1'\nS = ab-1.out\n"
c 2 "blank in a quoted range bound" "$F:4: BASIN_AXES: a range bound is not a finite number$" "$B""IPS = basins\nBASIN_AXES = {u1: [' 0', 1], u2: [0, 1]}\nBASIN_ATTRACTORS = [1]\nS = ab-1.out\n"
c 2 "hexadecimal number" "$F:3: DS: ${q}0x1p-3$q is not a finite number$" "$B"'DS = 0x1p-3\n'
c 2 "PLOT naming nothing of the model" "$F:3: PLOT: ${q}MAX xx$q is neither a parameter \(Da, B, beta\), PERIOD, L2-NORM, a state component nor MAX of one \(u1, u2\) of model ${q}ab$q$" "$B"'PLOT = MAX xx\n'
c 2 "PLOT = PERIOD for equilibria" "$F:3: PLOT = PERIOD: only periodic orbits \(IPS = 2\) have a period$" "$B"'PLOT = PERIOD\n'
# syntax
c 2 "unterminated quote (string key)" "$F:3: OUT: unterminated quoted string$" "$B"'OUT = "abc\n'
c 2 "unterminated quote (in a dictionary)" "$F:3: PAR: unterminated quoted string$" "$B""PAR = {B: 'x}\n"
c 2 "unbalanced bracket" "$F:2: ICP: ${q}\]$q missing$" 'model = ./ab.so\nICP = [Da\n'
c 2 "unbalanced brace" "$F:3: PAR: ${q}\}$q missing$" "$B"'PAR = {Da: 1\n'
c 2 "extra closing brace" "$F:3: PAR: unexpected text after the closing bracket$" "$B"'PAR = {Da: 1}}\n'
c 2 "bracket closes a brace" "$F:3: PAR: " "$B"'PAR = {Da: 1]\n'
c 2 "list where one value goes" "$F:3: PAR: ${q}Da$q has a list where one value is expected$" "$B"'PAR = {Da: [1, 2]}\n'
c 2 "NUL byte in the file" "$F:3: NUL byte in the line" "$B"'NMX = 1\000\n'
c 2 "control character (form feed)" "$F:3: control character in the line$" "$B"'DS = 0.01\f\n'
# required keys
c 2 "missing model" "$F:2: end of file without the required key ${q}model$q" 'ICP = [Da]\nDS = 0.01\n'
c 2 "missing ICP" "$F:2: end of file without the required key ${q}ICP$q" 'model = ./ab.so\nNMX = 10\n'
c 2 "empty run file" "$F(:1)?: .*model" ''
# the model
c 2 "unknown built-in model name" "$F:1: model: ${q}nosuch$q is neither a built-in model \(sfd, sfd-rotating, jeffcott\)" 'model = nosuch\nICP = [Da]\n'
c 2 "plug-in path that does not exist" "$F:1: model: cannot open plug-in ${q}(\./)*nosuch\.so$q: No such file" 'model = ./nosuch.so\nICP = [Da]\n'
c 2 "plug-in name that does not exist" "$F:1: model: cannot open plug-in ${q}(\./)*nosuch\.so$q: No such file" 'model = nosuch.so\nICP = [Da]\n'
c 2 "plug-in without the symbol" "$F:1: model: plug-in ${q}(\./)*nosym\.so$q does not export the symbol ${q}whirl_model_def$q" 'model = ./nosym.so\nICP = [Da]\n'
abi=$(sed -n 's/^#define WHIRL_MODEL_ABI \([0-9]*\).*/\1/p' "$top_srcdir/lib/whirl/model.h")
c 2 "plug-in with a wrong ABI number" "$F:1: model: plug-in ${q}(\./)*abi\.so$q was built for model ABI $((abi + 41)), .*needs ABI $abi" 'model = ./abi.so\nICP = [Da]\n'
c 2 "NDIM mismatch" "$F:3: NDIM = 3, but model ${q}ab$q has 2 state components$" "$B"'NDIM = 3\n'
c 2 "ICP naming an unknown parameter" "$F:2: ICP: ${q}Foo$q is not a parameter of model ${q}ab$q \(Da, B, beta\)$" 'model = ./ab.so\nICP = [Foo]\n'
c 2 "ICP index out of range" "$F:2: ICP: ${q}4$q is not a parameter" 'model = ./ab.so\nICP = [4]\n'
c 2 "ICP listing a parameter twice" "$F:2: ICP: parameter ${q}Da$q listed twice$" 'model = ./ab.so\nICP = [Da, Da]\n'
c 2 "PAR with an unknown name" "$F:3: PAR: ${q}Foo$q is not a parameter of model ${q}ab$q" "$B"'PAR = {Foo: 1}\n'
c 2 "PAR with too many values" "$F:3: PAR: ${q}4$q is not a parameter" "$B"'PAR = [1, 2, 3, 4]\n'
c 2 "U with an unknown component" "$F:3: U: ${q}u3$q is not a state component of model ${q}ab$q \(u1, u2\)$" "$B"'U = {u3: 1}\n'
c 2 "IPS = 2 without a start orbit" "$F:3: IPS = 2 from the model's start needs a start orbit" "$B"'IPS = 2\n'
c 2 "UZR on PERIOD for equilibria" "$F:3: UZR: ${q}PERIOD$q is neither a parameter, PERIOD \(periodic orbits\) nor a state component of model ${q}ab$q" "$B"'UZR = {PERIOD: 1}\n'
c 2 "IPS = basins without BASIN_AXES" "$F:[1-9][0-9]*: IPS = basins needs BASIN_AXES" "$B"'IPS = basins\n'
# restarts
c 2 "IRS without S" "$F:3: IRS names a label but S .* is not given$" "$B"'IRS = 2\n'
c 2 "ISW = -1 without IRS" "$F:3: ISW = -1 needs a labelled start point \(IRS\)$" "$B"'ISW = -1\n'
c 2 "S directory missing" "$F:(3|4): IRS: cannot open nodir\.out/solutions: No such file" "$B"'IRS = 2\nS = nodir.out\n'
c 2 "S not a whirl output (a directory)" "$F:(3|4): IRS: cannot open notwhirl\.out/solutions" "$B"'IRS = 2\nS = notwhirl.out\n'
c 2 "S not a whirl output (a file)" "$F:(3|4): IRS: cannot open plain\.out/solutions: Not a directory" "$B"'IRS = 2\nS = plain.out\n'
c 2 "IRS label not present" "$F:3: IRS: ab-1\.out/solutions: there is no label 99$" "$B"'IRS = 99\nS = ab-1.out\n'
c 2 "IRS type count not present" "$F:3: IRS: ab-1\.out/solutions: there is no LP number 1" "$B"'IRS = LP1\nS = ab-1.out\n'
c 2 "ISW = 2 with one ICP" "$F:2: ISW = 2 \(two-parameter continuation\) needs two parameters in ICP$" "$B"'IRS = 2\nS = ab-1.out\nISW = 2\n'
c 2 "ISW = 3 with one ICP" "$F:2: ISW = 3 \(a generic branch point's locus\) needs three parameters in ICP$" "$B"'IRS = 2\nS = ab-1.out\nISW = 3\n'
c 2 "ISW = -1 at an HB label" "$F:5: ISW = -1 switches at a BP" "$B"'IRS = 2\nS = ab-1.out\nISW = -1\n'
# restarts from solutions that do not fit the model (no read past a stored
# vector): every block read is checked for itself, the label found against
# the model
S2='S = ab-1.out\nIRS = 2\n'  # lines 3-4
c 2 "restart: solutions with a state more" "$F:4: IRS: label 2 of edit-nx3\.s/solutions has 3 states \(NX 3\); model ${q}ab$q has 2$" "$B"'S = edit-nx3.s\nIRS = 2\n'
c 2 "restart: X shorter than NX" "$F:4: IRS: edit-xshort\.s/solutions:9: label 2: X has 1 values, NX = 2 expected$" "$B"'S = edit-xshort.s\nIRS = 2\n'
c 2 "restart: TAN shorter than NX + 1" "$F:4: IRS: edit-tanshort\.s/solutions:10: label 2: TAN has 2 values, NX \+ 1 = 3 expected$" "$B"'S = edit-tanshort.s\nIRS = 2\n'
c 2 "restart: NaN in X" "$F:4: IRS: edit-xnan\.s/solutions:9: label 2: X: value 1 is not finite$" "$B"'S = edit-xnan.s\nIRS = 2\n'
c 2 "restart: text in X" "$F:4: IRS: edit-xtext\.s/solutions:9: label 2: X: ${q}1\.5x$q is not a number$" "$B"'S = edit-xtext.s\nIRS = 2\n'
c 2 "restart: PAR longer than npar (an earlier block)" "$F:4: IRS: edit-par4\.s/solutions:3: label 1: PAR has 4 values, npar = 3 expected$" "$B"'S = edit-par4.s\nIRS = 2\n'
c 2 "restart: solutions with another npar" "$F:4: IRS: edit-npar\.s/solutions:1: the solutions have 4 parameters \(npar 4\); model ${q}ab$q has 3$" "$B"'S = edit-npar.s\nIRS = 2\n'
c 2 "restart: TY of three letters" "$F:4: IRS: edit-ty\.s/solutions:7: label 2: TY ${q}HBX$q is not a point type" "$B"'S = edit-ty.s\nIRS = 2\n'
c 2 "restart: unknown KIND" "$F:4: IRS: edit-kind\.s/solutions:7: label 2: unknown KIND ${q}cycle$q" "$B"'S = edit-kind.s\nIRS = 2\n'
c 2 "restart: extra field on the LAB line" "$F:4: IRS: edit-junk\.s/solutions:7: label 2: unexpected ${q}NTST 9$q at the end of the LAB line$" "$B"'S = edit-junk.s\nIRS = 2\n'
c 2 "restart: ICP out of range" "$F:4: IRS: edit-icp\.s/solutions:7: LAB line: ICP must be an integer in \[1, 3\]$" "$B"'S = edit-icp.s\nIRS = 2\n'
c 2 "restart: MESH in an equilibrium" "$F:4: IRS: edit-mesh\.s/solutions:11: label 2: unexpected line ${q}MESH 0 1$q in the block$" "$B"'S = edit-mesh.s\nIRS = 2\n'
c 2 "restart: END missing" "$F:4: IRS: edit-noend\.s/solutions:20: end of file inside the block of label 4 \(END missing\)$" "$B"'S = edit-noend.s\nIRS = 4\n'
c 2 "restart: empty solutions file" "$F:4: IRS: edit-empty\.s/solutions: the file is empty \(not a whirl solutions file\)$" "$B"'S = edit-empty.s\nIRS = 2\n'
c 2 "restart: NX that does not fit NTST, NCOL" "$F:5: IRS: edit-ntst\.s/solutions:[0-9]+: label 3: NX 83 does not fit NTST 11, NCOL 4" "$B"'IPS = 2\nS = edit-ntst.s\nIRS = 3\n'
c 2 "restart: MESH shorter than NTST + 1" "$F:5: IRS: edit-meshshort\.s/solutions:[0-9]+: label 3: MESH has 10 values, NTST \+ 1 = 11 expected$" "$B"'IPS = 2\nS = edit-meshshort.s\nIRS = 3\n'
c 2 "restart: MESH not ending at 1" "$F:5: IRS: edit-meshorder\.s/solutions:[0-9]+: label 3: MESH does not increase from 0 to 1$" "$B"'IPS = 2\nS = edit-meshorder.s\nIRS = 3\n'
A3='model = ./ab3.so\nICP = [Da]\n'
c 2 "restart of a model with a state more: equilibria (IPS = 1)" "$F:4: IRS: label 1 of ab-1\.out/solutions has 2 states \(NX 2\); model ${q}ab$q has 3$" "$A3"'S = ab-1.out\nIRS = 1\n'
c 2 "restart of a model with a state more: Hopf start (IPS = 2)" "$F:4: IRS: label 2 of ab-1\.out/solutions has 2 states \(NX 2\); model ${q}ab$q has 3$" "$A3""$S2"'IPS = 2\n'
c 2 "restart of a model with a state more: Hopf locus (ISW = 2)" "$F:4: IRS: label 2 of ab-1\.out/solutions has 2 states" 'model = ./ab3.so\nICP = [Da, B]\n'"$S2"'ISW = 2\n'
c 2 "restart of a model with a state more: fold locus (ISW = 2)" "$F:4: IRS: label 2 of edit-lp\.s/solutions has 2 states" 'model = ./ab3.so\nICP = [Da, B]\nS = edit-lp.s\nIRS = 2\nISW = 2\n'
c 2 "restart of a model with a state more: BP switch (ISW = -1)" "$F:4: IRS: label 1 of edit-bp\.s/solutions has 2 states" "$A3"'S = edit-bp.s\nIRS = 1\nISW = -1\n'
c 2 "restart of a model with a state more: orbit, same mesh" "$F:4: IRS: label 3 of po\.out/solutions is an orbit of 2 states \(NX 83 = \(NTST 10 x NCOL 4 \+ 1\) x 2 \+ 1\); model ${q}ab$q has 3$" "$A3"'S = po.out\nIRS = 3\nIPS = 2\nNTST = 10\n'
c 2 "restart of a model with a state more: orbit, another mesh" "$F:4: IRS: label 3 of po\.out/solutions is an orbit of 2 states" "$A3"'S = po.out\nIRS = 3\nIPS = 2\nNTST = 20\n'
c 2 "restart of a model with a state more: PD switch (ISW = -1)" "$F:4: IRS: label 3 of edit-pd\.s/solutions is an orbit of 2 states" "$A3"'S = edit-pd.s\nIRS = 3\nIPS = 2\nISW = -1\n'
c 2 "restart of a model with a state more: harmonic balance" "$F:4: IRS: label 1 of hbm\.s/solutions is an orbit of 2 states \(NX 35 = \(2 x NHB 8 \+ 1\) x 2 \+ 1\); model ${q}ab$q has 3$" "$A3"'S = hbm.s\nIRS = 1\nIPS = 2\nMETHOD = hbm\n'
c 2 "restart of a model with a state more: basin attractor" "$F:[0-9]+: BASIN_ATTRACTORS: label 1 of ab-1\.out/solutions has 2 states" "$A3"'S = ab-1.out\nIPS = basins\nBASIN_AXES = {u1: [0, 1], u2: [0, 1]}\nBASIN_ATTRACTORS = [1]\n'
c 2 "restart of a forced model from an autonomous orbit" "$F:4: IRS: label 3 of po\.out/solutions is an orbit of an autonomous model: its period is the last of its NX 83 unknowns; model ${q}ab$q is forced$" 'model = ./abf.so\nICP = [Da]\nS = po.out\nIRS = 3\nIPS = 2\n'
c 2 "OUT is a foreign directory" "$F:3: output directory ${q}notwhirl\.out$q holds an entry whirl did not write \(${q}keep\.txt$q\)" "$B"'OUT = notwhirl.out\n'
# command-line overrides
c 2 "bad override value (--DS=abc)" "^whirl run: command line \(--DS=abc\): DS: ${q}abc$q is not a finite number$" "$B" --DS=abc
c 2 "override with an unknown key" "^whirl run: command line \(--bogus=1\): unknown key ${q}bogus$q" "$B" --bogus=1
c 2 "override key typo" "^whirl run: command line \(--DSMX=0\.1\): unknown key ${q}DSMX$q \(did you mean DSMAX\?\)$" "$B" --DSMX=0.1
c 2 "override without '='" "^whirl run: command line \(--DS\): expected --KEY=value$" "$B" --DS
c 2 "override with a blank for '=' (--NMX 5)" "^whirl run: --NMX needs ${q}=$q: write --NMX=5$" "$B" --NMX 5
c 2 "override with a blank for '=' (--DS -0.01)" "^whirl run: --DS needs ${q}=$q: write --DS=-0.01$" "$B" --DS -0.01
c 2 "override naming an unknown parameter" "^whirl run: command line \(--ICP=\[Foo\]\): ICP: ${q}Foo$q is not a parameter" "$B" '--ICP=[Foo]'
c 2 "override with an unknown model" "^whirl run: command line \(--model=nosuch\): model: " "$B" --model=nosuch
c 2 "override NDIM mismatch" "^whirl run: command line \(--NDIM=3\): NDIM = 3, but" "$B" --NDIM=3
c 2 "override DSMAX below the default DSMIN" "^whirl run: command line \(--DSMAX=1e-6\): DSMIN = 1e-05 exceeds DSMAX = 1e-06$" "$B" --DSMAX=1e-6

# a restart whose OUT is its own S (AUTO's c.ab.2 after c.ab.1 into the same
# directory) would replace the solutions it starts from: refused, S untouched
printf 'model = sfd-rotating\nICP = [Omega]\nPAR = {Omega: 0.5}\nU = {u: 0.1}\nNMX = 30\nDS = 0.05\nDSMAX = 0.2\nOUT = same.out\n' > first.whirl
"$WHIRL" run first.whirl --quiet > /dev/null 2>&1
ok $? "control: a run into same.out"
cp same.out/solutions same.saved
printf 'model = sfd-rotating\nICP = [Omega]\nS = same.out\nIRS = 2\nNMX = 5\nOUT = same.out\n' > again.whirl
"$WHIRL" run again.whirl --quiet > "$tmp/stdout" 2> "$tmp/stderr"
rc=$?
ok $(( rc != 2 )) "OUT = S: exit 2 ($rc)"
grep -q "^whirl run: again.whirl:6: OUT 'same.out' is S, the run this one restarts from" "$tmp/stderr" &&
  cmp -s same.saved same.out/solutions
ok $? "OUT = S: one message at OUT's line, S's solutions untouched: $(cat "$tmp/stderr")"
rm -rf same.out same.saved first.whirl again.whirl

rm -f case.whirl
echo "1..$n"
[ "$fails" -eq 0 ]

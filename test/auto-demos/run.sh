#!/bin/sh
# test/auto-demos/run.sh [AUTO_DEMOS_DIR] — AUTO-07p's demos of the classes
# whirl runs (every constants file IPS 1, 2 or 4, or every one -1 (maps),
# equations in Fortran), each
# run by `whirl auto DEMO` from its own files, unchanged, in the default
# order (c.NAME.1, c.NAME.2, ...; doc/auto-files.md), and every special
# point whirl labels (BP, LP, HB, PD, TR and the loci's BT, CP, ZH, GH)
# looked up in AUTO-07p's own log of the same demo (AUTO_DEMOS_DIR/../test/
# hyper.all, 6 digits): a point agrees when AUTO labels a point of the same
# type whose every printed value (the ICP parameter, L2-NORM, the state or
# its maximum, the other ICP parameters) is within one unit of its 6th
# digit (at least 1e-6: AUTO's 3.00001E-09 of a Hopf point at 0 is 0).
# Prints a table and `N of M demos agree`; known gaps are in
# test/auto-demos/known-gaps.  A point AUTO's runs detect but do not print
# to 6 digits (the localisation stopped at EPSS or ITMX: hyper.all's EPSS
# = 1e-4, or "Possible special point" at 1e-10) agrees with its converged
# value from test/auto-demos/exact.ref (exact.py, independent of whirl),
# counted apart in the summary.  AUTO's demo scripts (NAME.auto) restart
# runs from labels chosen by Python code that whirl auto does not follow,
# so the points AUTO finds beyond whirl's runs are listed, not counted.
# Where AUTO-07p itself is installed (the Debian package auto-07p, driven
# by /usr/bin/python3), AUTO's own run of the demo's script on a scratch
# copy with every EPSS = 1e-10 and ITMX = 40 is a second reference (its 6
# printed digits are converged; hyper.all's are EPSS-limited, often 1e-4;
# ITMX = 8 stops many a localisation at 1e-10 short of it, 'Possible
# special point', so AUTO labels no point there), and AUTO's own
# run of the constants files in whirl's default order (the same runs) a
# third: a point agrees when any of AUTO's runs printed it (REF both, both+
# with the third; AUTO_REF=hyper: hyper.all alone).  That takes minutes (AUTO compiles each demo, some run long at
# EPSS = 1e-10); with hyper.all alone about 30 s.
# Default directory: ../shared/auto-07p/demos beside the source tree; a
# message and exit 0 where it is absent.
set -u
# --script: run each demo by its own script (DEMO.auto, as AUTO's demo
# runner and hyper.all do) with `whirl auto --script` instead of its
# constants files in their default order (known gaps from
# known-gaps.script, else known-gaps); ONLY="ab plp": those demos alone
script=0
[ "${1:-}" = --script ] && { script=1; shift; }
here=$(cd "$(dirname "$0")" && pwd)
top=${top_srcdir:-$here/../..}
top=$(cd "$top" && pwd)
demos=${1:-$top/../shared/auto-07p/demos}
WHIRL=${WHIRL:-${top_builddir:-$top}/drivers/whirl}
[ -d "$demos" ] || { echo "# SKIP: no AUTO-07p demos at $demos"; exit 0; }
demos=$(cd "$demos" && pwd)
hyper="$demos/../test/hyper.all"
[ -f "$hyper" ] || { echo "# SKIP: no reference log $hyper"; exit 0; }
command -v "${FC:-gfortran}" >/dev/null 2>&1 || { echo "# SKIP: no Fortran compiler"; exit 0; }
tmp=$(mktemp -d) || exit 1
# KEEP=1: the scratch directory (each demo's points, matches, logs) is kept and named
trap '[ -n "${KEEP:-}" ] && echo "# kept $tmp" >&2 || rm -rf "$tmp"' EXIT

py=${AUTO_07P_PYTHON:-/usr/lib/auto-07p/python}
# AUTO's interpreter: Debian's, whose numpy AUTO's loadbd needs (a python3
# first on PATH may be another install without it), run through
# auto07p.py (numpy.bool, which numpy 1.24 removed and AUTO 0.9.2 reads)
apy=/usr/bin/python3
[ -x "$apy" ] || apy=python3
tight=0
[ "${AUTO_REF:-}" != hyper ] && [ -f "$py/auto/__main__.py" ] && command -v "$apy" >/dev/null 2>&1 && tight=1
# AUTO's own run of demo $1 at EPSS = 1e-10, ITMX = 40 in a scratch copy: its log,
# framed like hyper.all's, in $tmp/$1.tight (empty when it fails)
auto_tight() {
  rm -rf "$tmp/ref.$1"; mkdir "$tmp/ref.$1"
  # the demo with its sub-directories (fnc's attr and rep: their scripts
  # run there), writable, every constants file at the tight EPSS
  cp -R "$demos/$1"/. "$tmp/ref.$1"/ 2>/dev/null; chmod -R u+w "$tmp/ref.$1"
  for c in $(find "$tmp/ref.$1" -name 'c.*' -type f); do
    sed -e 's/EPSS *= *[-+0-9.eEdD]*/EPSS = 1e-10/' -e 's/ITMX *= *[0-9]*/ITMX = 40/' "$c" > "$c.t" && mv "$c.t" "$c"
  done
  { echo "Demo $1 is started"
    (cd "$tmp/ref.$1" && timeout 300 "$apy" "$here/auto07p.py" "$py/auto/__main__.py" "$1.auto" 2>&1)
    echo "Demo $1 is done"; } > "$tmp/$1.tight"
  grep -q 'PT  TY' "$tmp/$1.tight" || : > "$tmp/$1.tight"
}
# AUTO's own run of demo $1's constants files in whirl's default order
# (c.NAME.1, c.NAME.2, ... or c.NAME alone), each given the runs before it
# as its solutions (IRS: AUTO's numbering of labels across them), in the
# scratch copy auto_tight made (EPSS = 1e-10): the very runs whirl makes,
# where the demo's script makes others (ext's c.ext.2 to NMX, where the
# script stops at PAR(1) = 6); its log in $tmp/$1.default (empty when no
# run printed a point; 60 s at most: pcl's default order runs on past 300 s)
. "$here/default_order.sh"
auto_default() {
  r="$tmp/ref.$1"
  : > "$tmp/$1.default"
  default_order_script "$1" "$r" || return 0
  { echo "Demo $1 is started"
    (cd "$r" && rm -f b.* s.* d.* && timeout 60 "$apy" "$here/auto07p.py" "$py/auto/__main__.py" whirl-default.auto 2>&1)
    echo "Demo $1 is done"; } > "$tmp/$1.default"
  grep -q 'PT  TY' "$tmp/$1.default" || : > "$tmp/$1.default"
}
# the special points of demo $1 in the log $2: TY and values, one a line
auto_points() {
  awk -v d="$1" '$0 == "Demo " d " is started" { on = 1; next }
    $0 == "Demo " d " is done" { on = 0 }
    on && $1 ~ /^-?[0-9]+$/ && $2 ~ /^-?[0-9]+$/ && $3 ~ /^(BP|LP|HB|PD|TR|BT|CP|ZH|GH)$/ {
      s = $3; for (i = 5; i <= NF; i++) s = s " " $i; print s }' "$2"
}
# whirl's points as "LAB TY values" (LAB from columns 15-19)
whirl_points_lab() {
  for b in "$1/b.$2"; do
    [ -f "$b" ] || continue
    awk 'substr($0, 1, 4) + 0 != 0 {
      t = substr($0, 11, 4) + 0
      if (t != -32) t = t >= 0 ? t % 10 : -((-t) % 10) # a locus: 10 k + type (parseB)
      ty = t == 1 || t == 6 ? "BP" : t == 2 || t == 5 ? "LP" : t == 3 ? "HB" : t == 7 ? "PD" : \
           t == 8 ? "TR" : t == -1 ? "BT" : t == -2 ? "CP" : t == -3 ? "ZH" : t == -32 ? "GH" : ""
      if (ty == "") next
      s = (substr($0, 15, 5) + 0) " " ty; for (i = 20; i + 18 <= length($0); i += 19) s = s " " sprintf("%.10g", substr($0, i, 19) + 0)
      print s }' "$b"
  done
}
# whirl's, from the b-file of all runs, b.$2: AUTO's type codes at
# columns 11-14, as "TY values"
whirl_points() { whirl_points_lab "$@" | cut -d' ' -f2-; }
# the value positions of the MAX U(i) columns of the b-file $1, as POS:i
max_mask() {
  awk 'substr($0, 1, 4) + 0 == 0 && index($0, "MAX U(") {
      for (i = 20; i + 18 <= length($0) + 19; i += 19) {
        name = substr($0, i, 19); p = index(name, "MAX U(")
        if (p) { c = substr(name, p + 6); c = substr(c, 1, index(c, ")") - 1); s = s " " ((i - 20) / 19 + 1) ":" c } }
      print s; exit }' "$1"
}
# the converged MAX U(i) of whirl's labelled orbits of demo $1 (orbitmax.c
# linked with the demo's equations), in $tmp/$1.ref; empty when it cannot
maxref_of() {
  : > "$tmp/$1.ref"
  [ $have_cvode = 1 ] || return 0
  mkdir -p "$tmp/om.$1"
  (cd "$tmp/om.$1" && "${FC:-gfortran}" -O2 -c "$demos/$1/$1.f90" -o eq.o > /dev/null 2>&1 &&
   ${CC:-cc} -O2 -o orbitmax "$here/orbitmax.c" eq.o $cvode_libs -llapack -lgfortran -lm > /dev/null 2>&1 &&
   timeout 60 ./orbitmax "$tmp/$1.out/s.$stem" > "$tmp/$1.ref" 2> /dev/null) || : > "$tmp/$1.ref"
}
cvode_libs="-lsundials_cvode -lsundials_nvecserial -lsundials_sunlinsoldense -lsundials_sunmatrixdense"
have_cvode=0
printf '#include <cvode/cvode.h>\nint main(void) { return 0; }\n' > "$tmp/cv.c"
${CC:-cc} -o "$tmp/cv" "$tmp/cv.c" $cvode_libs -llapack > /dev/null 2>&1 && have_cvode=1
# A's lines found in B (same type, every common value within one unit of
# B's 6th digit): the count, and the lines not found (prefixed "- ")
match() {
  awk 'function unit(a,   e, m) { m = a < 0 ? -a : a; if (m < 1e-6) return 1e-6
         e = int(log(m) / log(10) + 100) - 100; if (10 ^ e > m) e--; return 10 ^ (e - 5) }
    NR == FNR { b[++nb] = $0; next }
    { found = 0; na = split($0, x, " ")
      for (k = 1; k <= nb && !found; k++) {
        m = split(b[k], y, " "); if (y[1] != x[1]) continue
        good = 1; for (i = 2; i <= na && i <= m; i++) { d = x[i] - y[i]; if (d < 0) d = -d; if (d > unit(y[i]) * 1.01) good = 0 }
        found = good }
      if (found) n++; else print "- " $0 }
    END { print n + 0 }' "$2" "$1"
}

printf '%-6s %-7s %-6s %-10s %-10s %s\n' DEMO RUNS REF "WHIRL=AUTO" "AUTO-FOUND" NOTE
agree=0 total=0 wpts=0 wok=0 mxw=0 mxa=0 nexact=0 sok=0 stot=0
for dir in "$demos"/*/; do
  d=$(basename "$dir")
  [ -f "$dir/$d.f90" ] || continue
  ls "$dir"/c.* >/dev/null 2>&1 || continue
  cls=$(cat "$dir"/c.* | grep -o 'IPS *= *-\{0,1\}[0-9]*' | grep -o -- '-\{0,1\}[0-9]*$' | sort -u | tr '\n' ' ')
  case "$cls" in "1 " | "2 " | "4 " | "1 2 " | "1 4 " | "2 4 " | "1 2 4 " | "-1 ") ;; *) continue ;; esac
  [ -n "${ONLY:-}" ] && case " $ONLY " in *" $d "*) ;; *) continue ;; esac
  total=$((total + 1))
  if [ $script = 1 ]; then
    (cd "$tmp" && timeout 300 "$WHIRL" auto "$dir" --script --quiet --out="$d.out" > "$d.log" 2>&1)
    rc=$?
    stem=runs
    nrun=$(ls "$tmp/$d.out"/runs/*.whirl 2>/dev/null | wc -l)
  else
    (cd "$tmp" && timeout 300 "$WHIRL" auto "$dir" --quiet --out="$d.out" > "$d.log" 2>&1)
    rc=$?
    stem=$d
    nrun=$(ls "$tmp/$d.out"/*.whirl 2>/dev/null | wc -l)
  fi
  nbad=$(grep -c 'failed (exit' "$tmp/$d.log")
  ref=hyper
  auto_points "$d" "$hyper" > "$tmp/$d.auto"
  if [ $tight = 1 ]; then
    auto_tight "$d"
    [ -s "$tmp/$d.tight" ] && ref=both && auto_points "$d" "$tmp/$d.tight" >> "$tmp/$d.auto"
    # AUTO against itself: the points of its run at EPSS = 1e-10 that
    # hyper.all (the demos' EPSS, often 1e-4) prints to 6 digits too
    if [ -s "$tmp/$d.tight" ]; then
      auto_points "$d" "$tmp/$d.tight" > "$tmp/$d.atight"
      auto_points "$d" "$hyper" > "$tmp/$d.ahyper"
      st=$(wc -l < "$tmp/$d.atight")
      [ "$st" -gt 0 ] && sok=$((sok + $(match "$tmp/$d.atight" "$tmp/$d.ahyper" | tail -1))) && stot=$((stot + st))
    fi
    if [ $script = 0 ]; then
      auto_default "$d"
      [ -s "$tmp/$d.default" ] && ref=$ref+ && auto_points "$d" "$tmp/$d.default" >> "$tmp/$d.auto"
    fi
  fi
  whirl_points "$tmp/$d.out" "$stem" > "$tmp/$d.whirl"
  w=$(wc -l < "$tmp/$d.whirl"); a=$(wc -l < "$tmp/$d.auto")
  match "$tmp/$d.whirl" "$tmp/$d.auto" > "$tmp/$d.m1"; c=$(tail -1 "$tmp/$d.m1")
  # the points AUTO's runs detect but do not print to 6 digits (its
  # localisation stops at EPSS or ITMX): against their converged values
  # (exact.ref, written by exact.py independently of whirl), counted apart
  awk -F'\t' -v d="$d" '$1 == d { print $2 }' "$here/exact.ref" > "$tmp/$d.exact"
  if [ "$c" != "$w" ] && [ -s "$tmp/$d.exact" ]; then
    sed -n 's/^- //p' "$tmp/$d.m1" > "$tmp/$d.rest"
    match "$tmp/$d.rest" "$tmp/$d.exact" > "$tmp/$d.m3"; e=$(tail -1 "$tmp/$d.m3")
    c=$((c + e)); nexact=$((nexact + e))
    { grep '^- ' "$tmp/$d.m3"; echo "$c"; } > "$tmp/$d.m1"
  fi
  match "$tmp/$d.auto" "$tmp/$d.whirl" > "$tmp/$d.m2"; f=$(tail -1 "$tmp/$d.m2")
  note=""
  if [ "$c" != "$w" ]; then
    maxref_of "$d"
    max_mask "$tmp/$d.out/b.$stem" > "$tmp/$d.mask"
    whirl_points_lab "$tmp/$d.out" "$stem" > "$tmp/$d.lab"
    awk -f "$here/maxref.awk" "$tmp/$d.mask" "$tmp/$d.lab" "$tmp/$d.auto" "$tmp/$d.ref" "$tmp/$d.m1" > "$tmp/$d.mx"
    set -- $(tail -1 "$tmp/$d.mx")
    mxw=$((mxw + $2)); mxa=$((mxa + $3))
    [ "$2" -gt 0 ] || [ "$3" -gt 0 ] && note="MAX U(i) alone: $2 nearer the flow than AUTO's, $3 not"
  fi
  [ "$rc" = 0 ] || note="${note:+$note; }exit $rc: $(grep -v '^ ' "$tmp/$d.log" | head -1 | cut -c1-90)"
  gap=
  [ $script = 1 ] && gap=$(awk -F'\t' -v d="$d" '$1 == d { print $2 }' "$here/known-gaps.script" 2>/dev/null | head -1)
  [ -n "$gap" ] || gap=$(awk -F'\t' -v d="$d" '$1 == d { print $2 }' "$here/known-gaps" 2>/dev/null | head -1)
  [ -n "$gap" ] && note="${note:+$note; }known: $gap"
  ok=0
  [ "$rc" = 0 ] && [ "$c" = "$w" ] && { [ "$w" -gt 0 ] || [ "$a" = 0 ]; } && ok=1
  [ $ok = 1 ] && agree=$((agree + 1))
  wpts=$((wpts + w)); wok=$((wok + c))
  printf '%-6s %-7s %-6s %-10s %-10s %s\n' "$d" "$((nrun - nbad))/$nrun" "$ref" "$c/$w" "$f/$a" "$([ $ok = 1 ] && echo agree || echo "${note:-disagree}")"
  [ "$c" = "$w" ] || sed -n '/^- /s/^/         whirl only: /p' "$tmp/$d.m1" | head -4
done
echo "$agree of $total demos agree; $wok of $wpts of whirl's special points are AUTO's to 6 digits"
echo "($nexact of those points by their converged values, test/auto-demos/exact.ref, where AUTO's localisation stops short of them)"
[ "$stot" -gt 0 ] &&
  echo "AUTO against itself: $sok of $stot special points of AUTO's runs at EPSS = 1e-10 are hyper.all's (the demos' own EPSS) to 6 digits"
[ $have_cvode = 1 ] &&
  echo "$((mxw + mxa)) more differ from AUTO's in MAX U(i) alone: the converged maximum (the flow by CVODE) is nearer whirl's in $mxw, AUTO's in $mxa"

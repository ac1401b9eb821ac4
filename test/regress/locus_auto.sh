#!/bin/sh
# test/regress/locus_auto.sh — a fold curve's isola centre (IS) or merge
# (MG), a turning point of the curve in the continued parameter, is
# reported in run files of AUTO's problem classes as AUTO reports it: as
# that parameter's LP when it leads (ICP(1)), as nothing when the other
# one leads.  x' = x^2 + q^2 - r: its folds x = 0, r = q^2, the isola
# centre at q = 0 (circles born at r = 0).  Before, whirl labelled MG there
# in either case (abcb's script restarts from AUTO's LP at such a point).
# (The starting data of a locus of a BVP: test/regress/bvp_run.sh.)
# And RL0, RL1 bound ICP(1) of the locus when it is the fold's own
# parameter, as AUTO's (AUTO-07p itself on this problem, below).
# SPDX-License-Identifier: BSD-3-Clause
name=locus_auto
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
cat > "$tmp/circle.c" <<'C'
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  f[0] = u[0] * u[0] + p[0] * p[0] - p[1];
  return 0;
}
static const char *const xn[] = {"x"};
static const char *const pn[] = {"q", "r"};
static const double par0[] = {0.0, 1.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "circle", .n = 1, .npar = 2, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .forcing_param = -1, .description = "x' = x^2 + q^2 - r"};
C
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o circle.so circle.c -lm
ok $? "circle plug-in builds"
# rows of type $2 in $1/branches.tsv: "col1 col2 ..." of the named columns $3...
rows() {
  d=$1 t=$2; shift 2
  awk -F'\t' -v t="$t" -v cols="$*" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; n = split(cols, c, " "); next }
    $3 == t { s = ""; for (i = 1; i <= n; i++) s = s (i > 1 ? " " : "") $h[c[i]]; print s }' "$d/branches.tsv" 2>/dev/null
}
# the circle's folds through the isola centre q = 0
printf 'model = circle.so\nIPS = 1\nICP = [q]\nU = {x: 0.5}\nPAR = {q: 0.8660254037844386, r: 1}\nDS = 0.01\nDSMAX = 0.05\nNMX = 300\nRL0 = -2\nRL1 = 2\n' > c1.whirl
"$WHIRL" run c1.whirl --no-plot --quiet > /dev/null 2> c1.err
lpc=$(awk -F'\t' 'NR > 1 && $3 == "LP" { print $4; exit }' c1.out/branches.tsv)
for icp in "q, r" "r, q"; do
  printf 'model = circle.so\nIPS = 1\nISW = 2\nS = c1.out\nIRS = %s\nICP = [%s]\nDS = -0.02\nDSMAX = 0.05\nNMX = 200\nRL0 = -3\nRL1 = 3\n' "${lpc:-0}" "$icp" > c2.whirl
  "$WHIRL" run c2.whirl --no-plot --quiet > /dev/null 2> c2.err
  special=$(awk -F'\t' 'NR > 1 && $3 != "-" && $3 != "EP" { printf "%s ", $3 }' c2.out/branches.tsv)
  qmin=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next } NR == 2 || $h["q"] < m { m = $h["q"] } END { print m }' c2.out/branches.tsv)
  lpq=$(rows c2.out LP q r)
  if [ "$icp" = "q, r" ]; then
    [ -z "$special" ] && awk -v q="$qmin" 'BEGIN { exit !(q < -0.5) }'
    ok $? "ICP = [q, r]: q leads through the isola centre q = 0, nothing labelled there ('$special', q down to $qmin)"
  else
    set -- $lpq
    [ "$special" = "LP " ] && awk -v q="${1:-1}" -v r="${2:-1}" 'BEGIN { exit !(q * q < 1e-14 && r * r < 1e-14) }'
    ok $? "ICP = [r, q]: r leads, its turning point at the isola centre is an LP ('$special' at q r = $lpq)"
  fi
done
# RL0 and RL1 bound ICP(1) of a locus, as AUTO's (here q, an unknown of the
# fold system continued in r): AUTO-07p 0.9.2 on this problem (RL1 = 1.5)
# ends its run at the first point past q = 1.5 (PT 34, q = 1.51186, r =
# 2.28571; whirl locates the bound itself); before, whirl bounded r there
printf 'model = circle.so\nIPS = 1\nISW = 2\nS = c1.out\nIRS = %s\nICP = [q, r]\nDS = 0.02\nDSMAX = 0.05\nNMX = 200\nRL0 = -3\nRL1 = 1.5\n' "${lpc:-0}" > c3.whirl
"$WHIRL" run c3.whirl --no-plot --quiet > /dev/null 2> c3.err
end=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next } { e = $h["q"] " " $h["r"] } END { print e }' c3.out/branches.tsv 2>/dev/null)
set -- $end
grep -q "parameter reached its upper bound" c3.out/run.log 2>/dev/null &&
  awk -v q="${1:-0}" -v r="${2:-0}" 'BEGIN { exit !(q - 1.5 < 1e-12 && 1.5 - q < 1e-12 && r > 2.2) }'
ok $? "RL1 = 1.5 bounds ICP(1) = q of the locus, not r: it ends at q r = $end"
"$WHIRL" run c3.whirl --quiet > /dev/null 2> c3p.err
if [ -f c3.out/diagram.gp ]; then
  grep -q "^set xlabel 'q'" c3.out/diagram.gp && grep -q "^set ylabel 'r'" c3.out/diagram.gp
  ok $? "its diagram has ICP(1) = q across and r up, as AUTO's ($(grep -h 'label' c3.out/diagram.gp | tr '\n' ' '))"
else
  ok 0 "# SKIP no diagram.gp (built without gnuplot)"
fi
tap_end

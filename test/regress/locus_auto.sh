#!/bin/sh
# test/regress/locus_auto.sh — what run files of AUTO's problem classes do
# at the start and along a two-parameter curve, as AUTO does.
# 1. A locus of a boundary-value problem (or of orbits) from its special
#    point first generates the starting data (AUTO's ISW = -2: "Generating
#    starting data: Restart at EP label below", its steps leave the point
#    where it is): the run is the start and an EP there; the next run
#    restarts from that EP and follows the curve.  Bratu's problem with the
#    boundary value mu, u'' + lambda e^u = 0, u(0) = u(1) = mu: v = u - mu
#    is Bratu's with lambda e^mu, so the folds are lambda e^mu =
#    3.513830719 (closed form; AUTO's demo int and pen run like this).
# 2. A fold curve's isola centre (IS) or merge (MG), a turning point of the
#    curve in the continued parameter, is reported as AUTO reports it: as
#    that parameter's LP when it leads (ICP(1)), as nothing when the other
#    one leads.  x' = x^2 + q^2 - r: its folds x = 0, r = q^2, the IS at
#    q = 0 (circles born at r = 0).  Before, whirl labelled IS there in
#    either case (abcb's script restarts from AUTO's LP at such a point).
# SPDX-License-Identifier: BSD-3-Clause
name=locus_auto
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
cat > "$tmp/bratu2.c" <<'C'
#include <math.h>
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  f[0] = u[1];
  f[1] = -p[0] * exp(u[0]);
  return 0;
}
static int stpnt(double t, double *u, double *p, void *d) {
  (void)t, (void)p, (void)d;
  u[0] = u[1] = 0.0;
  return 0;
}
static int bcnd(size_t nbc, const double *u0, const double *u1, const double *p,
                double *fb, void *d) {
  (void)nbc, (void)d;
  fb[0] = u0[0] - p[1];
  fb[1] = u1[0] - p[1];
  return 0;
}
static const char *const xn[] = {"u", "v"};
static const char *const pn[] = {"lambda", "mu"};
static const double par0[] = {0.0, 0.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "bratu2", .n = 2, .npar = 2, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .stpnt = stpnt, .forcing_param = -1, .bcnd = bcnd,
    .description = "Bratu's problem with the boundary value mu"};
C
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
for m in bratu2 circle; do
  $CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o $m.so $m.c -lm
  ok $? "$m plug-in builds"
done
# rows of type $2 in $1/branches.tsv: "col1 col2 ..." of the named columns $3...
rows() {
  d=$1 t=$2; shift 2
  awk -F'\t' -v t="$t" -v cols="$*" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; n = split(cols, c, " "); next }
    $3 == t { s = ""; for (i = 1; i <= n; i++) s = s (i > 1 ? " " : "") $h[c[i]]; print s }' "$d/branches.tsv" 2>/dev/null
}
printf 'model = bratu2.so\nIPS = 4\nICP = [lambda]\nNBC = 2\nNTST = 10\nDS = 0.01\nDSMAX = 0.2\nNMX = 60\n' > b1.whirl
"$WHIRL" run b1.whirl --no-plot --quiet > /dev/null 2> b1.err
lp=$(awk -F'\t' 'NR > 1 && $3 == "LP" { print $4; exit }' b1.out/branches.tsv)
ok $? "Bratu's fold at mu = 0 (label ${lp:-none})"
printf 'model = bratu2.so\nIPS = 4\nISW = 2\nS = b1.out\nIRS = %s\nICP = [lambda, mu]\nNBC = 2\nNTST = 10\nDS = 0.05\nDSMAX = 0.2\nNMX = 30\n' "${lp:-0}" > b2.whirl
"$WHIRL" run b2.whirl --no-plot --quiet > /dev/null 2> b2.err
nrow=$(($(wc -l < b2.out/branches.tsv) - 1))
ep=$(rows b2.out EP label lambda mu)
set -- $ep
[ "$nrow" = 2 ] && [ $# = 3 ] && awk -v l="$2" -v m="$3" 'BEGIN { d = l - 3.513830719; exit !(d * d < 1e-12 && m == 0) }'
ok $? "the locus from the fold is AUTO's starting data: the start and an EP there ($nrow rows; EP $ep)"
printf 'model = bratu2.so\nIPS = 4\nISW = 2\nS = b2.out\nIRS = %s\nICP = [lambda, mu]\nNBC = 2\nNTST = 10\nDS = 0.05\nDSMAX = 0.2\nNMX = 30\n' "${1:-0}" > b3.whirl
"$WHIRL" run b3.whirl --no-plot --quiet > /dev/null 2> b3.err
dev=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
  { d = $h["lambda"] * exp($h["mu"]) - 3.513830719125; if (d < 0) d = -d; if (d > m) m = d; k++ }
  END { if (k > 20) printf "%.2g %d\n", m, k }' b3.out/branches.tsv 2>/dev/null)
set -- $dev
[ -n "${1:-}" ] && awk -v d="$1" 'BEGIN { exit !(d < 1e-6) }'
ok $? "restarted at that EP the run follows the folds lambda e^mu = 3.5138307 (max deviation ${1:-?} over ${2:-?} points) ($(head -1 b3.err))"
# 2. the circle's folds through the isola centre q = 0
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
tap_end

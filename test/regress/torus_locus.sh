#!/bin/sh
# test/regress/torus_locus.sh — the torus (Neimark-Sacker) locus of periodic
# orbits in run files (ISW = 2 at a TR of IPS = 2, whirl/trloc.h) against a
# closed form, a model written here:
#   x' = mu x - y - x r^2, y' = x + mu y - y r^2, r^2 = x^2 + y^2,
#   z' = s z - nu w, w' = nu z + s w, s = a + k r^2,
# whose orbit r^2 = mu (born at the Hopf point mu = 0) has the multipliers
# exp(2 pi s) exp(+-2 pi i nu), s = a + k mu: a torus bifurcation where
# a = -k mu (mu = 1.2 at a = -0.6, k = 0.5), at the angle 2 pi nu.  Run 1
# the equilibria to the HB, run 2 the orbits to the TR, run 3 the locus's
# starting data (AUTO's ISW = 2 convention), run 4 the locus in (mu, a):
# a = -k mu at every point; run 5 the locus with the angle fixed and nu
# free (a third ICP, AUTO's tor.6): nu = 0.15 at every point.
# SPDX-License-Identifier: BSD-3-Clause
name=torus_locus
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
cat > tor4.c <<'C'
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  const double r2 = u[0] * u[0] + u[1] * u[1], s = p[1] + p[3] * r2;
  f[0] = p[0] * u[0] - u[1] - u[0] * r2;
  f[1] = u[0] + p[0] * u[1] - u[1] * r2;
  f[2] = s * u[2] - p[2] * u[3];
  f[3] = p[2] * u[2] + s * u[3];
  return 0;
}
static const char *const xn[] = {"x", "y", "z", "w"};
static const char *const pn[] = {"mu", "a", "nu", "k"};
static const double par0[] = {-0.5, -0.6, 0.15, 0.5};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "tor4", .n = 4, .npar = 4, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .forcing_param = -1, .description = "a torus bifurcation at a = -k mu"};
C
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o tor4.so tor4.c -lm
ok $? "tor4 plug-in builds"
# the label of the first point of type $2 in $1/branches.tsv, and a column
label_of() { awk -F'\t' -v t="$2" '$3 == t { print $4; exit }' "$1/branches.tsv" 2>/dev/null; }
col_of() {
  awk -F'\t' -v t="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
    $3 == t { print $h[c]; exit }' "$1/branches.tsv" 2>/dev/null
}
run() { "$WHIRL" run "$1.whirl" --no-plot --quiet > "$1.log" 2>&1; }
printf 'model = tor4.so\nIPS = 1\nICP = [mu]\nU = {x: 0, y: 0, z: 0, w: 0}\nDS = 0.05\nDSMAX = 0.1\nNMX = 100\nRL1 = 1.5\n' > c1.whirl
run c1
hb=$(label_of c1.out HB)
printf 'model = tor4.so\nIPS = 2\nS = c1.out\nIRS = %s\nICP = [mu, PERIOD]\nISP = 2\nNTST = 20\nNCOL = 4\nDS = 0.05\nDSMAX = 0.1\nNMX = 200\nRL1 = 1.5\n' "${hb:-0}" > c2.whirl
run c2
tr=$(label_of c2.out TR) mutr=$(col_of c2.out TR mu)
awk -v m="${mutr:-0}" 'BEGIN { exit !(m - 1.2 < 1e-6 && 1.2 - m < 1e-6) }'
ok $? "the orbits from the HB have their TR at mu = 1.2 = -a/k ($mutr, label ${tr:-none})"
printf 'model = tor4.so\nIPS = 2\nISW = 2\nS = c2.out\nIRS = %s\nICP = [mu, a, PERIOD]\nISP = 0\nNTST = 20\nNCOL = 4\nDS = 0.05\nDSMAX = 0.1\nNMX = 30\n' "${tr:-0}" > c3.whirl
run c3
grep -q "torus locus from label ${tr:-0}: multipliers exp(+-i 0.9424777" c3.out/run.log
ok $? "ISW = 2 at the TR starts the torus locus at the angle 2 pi nu = 0.942478 ($(grep 'torus locus from' c3.out/run.log | cut -c1-90))"
sed -e 's/^S = c2.out/S = c3.out/' -e 's/^IRS = .*/IRS = 1/' c3.whirl > c4.whirl
run c4
awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
  { d = $h["a"] + $h["k"] * $h["mu"]; if (d < 0) d = -d; if (d > m) m = d; n++
    if (n == 1 || $h["mu"] < lo) lo = $h["mu"]; if ($h["mu"] > hi) hi = $h["mu"] }
  END { printf "%d %.3g %.6g %.6g\n", n, m, lo, hi; exit !(n >= 20 && m < 1e-8 && hi - lo > 1) }' c4.out/branches.tsv > c4.sum
ok $? "the torus locus in (mu, a): a = -k mu at every point (points, worst, mu from, to: $(cat c4.sum))"
sed -e 's/^ICP = .*/ICP = [mu, a, nu, PERIOD]/' c4.whirl > c5.whirl
run c5
awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
  { d = $h["a"] + $h["k"] * $h["mu"]; e = $h["nu"] - 0.15; if (d < 0) d = -d; if (e < 0) e = -e
    if (d > m) m = d; if (e > m) m = e; n++ }
  END { printf "%d %.3g\n", n, m; exit !(n >= 20 && m < 1e-8) }' c5.out/branches.tsv > c5.sum
ok $? "the locus at a fixed angle with nu free: nu = 0.15 and a = -k mu at every point (points, worst: $(cat c5.sum)); $(grep -o 'torus curve at a fixed angle' c5.out/run.log)"
# a TR locus needs a TR: from the HB label of the orbits' run, refused
sed -e 's/^IRS = .*/IRS = 1/' c3.whirl > bad.whirl
"$WHIRL" run bad.whirl --no-plot --quiet > bad.log 2>&1
rc=$?
[ $rc = 2 ] && grep -q "ISW = 2 needs" bad.log && [ ! -e bad.out ]
ok $? "ISW = 2 at a label of orbits that is no TR, LP or PD: exit 2 ($rc), nothing written: $(head -1 bad.log | cut -c1-100)"
tap_end

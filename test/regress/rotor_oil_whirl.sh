#!/bin/sh
# test/regress/rotor_oil_whirl.sh — oil whirl of a rigid rotor on two
# short journal bearings (examples/rotor/oil-whirl.rotor): the static
# equilibrium under gravity, followed in speed from 100 rad/s (eps 0.74,
# a start the damped Newton of the response reaches from the centred
# journal) by `whirl rotor response
# --unbalance 0` with Hill's stability, loses stability at a torus point
# TR (the whirl at about half the speed) whose speed equals the closed-form
# threshold of the linearised rotor: per bearing m_b x'' + C x' + K x = 0
# with the short-bearing coefficients K(eps), C(eps)/Omega (Childs 1993;
# San Andres' notes; the same formulas t_fe_forces checks against the
# force's Jacobian) at the Ocvirk eccentricity eps(Omega), unstable when
# m_b > K_eq / nu^2 (Lund 1966: K_eq = (Kxx Cyy + Kyy Cxx - Kxy Cyx -
# Kyx Cxy) / (Cxx + Cyy), nu^2 = ((Kxx - K_eq)(Kyy - K_eq) - Kxy Kyx) /
# (Cxx Cyy - Cxy Cyx)), solved for Omega by bisection here.
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
WHIRL="$top_builddir/drivers/whirl"
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
case $top_srcdir in /*) ;; *) top_srcdir="$(pwd)/$top_srcdir" ;; esac
ex="$top_srcdir/examples/rotor/oil-whirl.rotor"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-oilwhirl.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

want=$(awk 'BEGIN {
  PI = 3.14159265358979323846
  ms = 7810 * PI / 4 * 0.05 ^ 2 * 0.5; m = 100 + ms; mb = m / 2; W = m * 9.81 / 2
  R = 0.025; L = 0.02; c = 50e-6; mu = 0.02
  lo = 800; hi = 2000
  for (it = 0; it < 80; it++) { mid = (lo + hi) / 2; if (mth(mid) > mb) lo = mid; else hi = mid }
  printf "%.10g %.6f", (lo + hi) / 2, eps_of((lo + hi) / 2)
}
function eps_of(Om,   S, a, b, e, k) {
  S = W / (mu * Om * R * L ^ 3 / c ^ 2); a = 0; b = 0.999999
  for (k = 0; k < 100; k++) { e = (a + b) / 2
    if (e * sqrt(PI ^ 2 * (1 - e * e) + 16 * e * e) / (4 * (1 - e * e) ^ 2) > S) b = e; else a = e }
  return (a + b) / 2
}
function mth(Om,   ep, e2, s, h0, A, B, q, Kxx, Kyx, Kxy, Kyy, Cxx, Cxy, Cyy, Keq, nu2) {
  ep = eps_of(Om); e2 = ep * ep; s = 1 - e2
  h0 = 1 / (PI * PI * s + 16 * e2) ^ 1.5; A = W / c * h0; B = W / (c * Om) * h0; q = ep * sqrt(s)
  Kxx = A * 4 * (PI * PI * (2 - e2) + 16 * e2)
  Kyx = -A * PI * (PI * PI * s * (1 + 2 * e2) + 32 * e2 * (1 + e2)) / q
  Kxy = A * PI * (PI * PI * s * s - 16 * e2 * e2) / q
  Kyy = A * 4 * (PI * PI * (1 + 2 * e2) + 32 * e2 * (1 + e2) / s)
  Cxx = B * 2 * PI * sqrt(s) * (PI * PI * (1 + 2 * e2) - 16 * e2) / ep
  Cxy = -B * 8 * (PI * PI * (1 + 2 * e2) - 16 * e2)
  Cyy = B * 2 * PI * (PI * PI * s * s + 48 * e2) / q
  Keq = (Kxx * Cyy + Kyy * Cxx - Kxy * Cxy - Kyx * Cxy) / (Cxx + Cyy)
  nu2 = ((Kxx - Keq) * (Kyy - Keq) - Kxy * Kyx) / (Cxx * Cyy - Cxy * Cxy)
  return Keq / nu2
}')
set -- $want
echo "# closed-form threshold: Omega = $1 rad/s at eps = $2"
"$WHIRL" rotor response "$ex" --unbalance 0 --harmonics 1 -o ow --quiet > ow.tsv 2> ow.err
ok $? "whirl rotor response --unbalance 0: $(head -c 200 ow.err)"
got=$(awk -F '\t' '$1 == "TR" { print $3; exit }' ow.tsv)
echo "# whirl rotor response: TR at Omega = ${got:-none} rad/s"
ok "$(awk -v a="${got:-0}" -v b="$1" 'BEGIN { d = (a - b) / b; exit !(d < 2e-5 && d > -2e-5) }'; echo $?)" \
  "the static equilibrium loses stability (TR) at the closed-form threshold to 2e-5"
awk -F '\t' 'NF > 5 && $2 == 1 { if ($1 == "TR") seen = 1; else if ($1 != "EP" && ($7 == 1) == seen) bad = 1 }
  END { exit bad || !seen }' ow/branches.tsv
ok $? "stable below the threshold, unstable above"

echo "1..$n"
[ "$fails" -eq 0 ]

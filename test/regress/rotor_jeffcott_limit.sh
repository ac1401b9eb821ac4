#!/bin/sh
# test/regress/rotor_jeffcott_limit.sh — the finite-element rotor in the
# Jeffcott limit (examples/rotor/jeffcott-limit.rotor: a massless shaft
# with a disc at mid-span, journals on retainer springs and short pi-film
# SFDs) against the Jeffcott model of the rotor module (model = jeffcott,
# examples/jeffcott/response.whirl, a separate model and code path: the
# generic HBM of whirl run on the model's own equations):
#  - the linear natural frequency (SFDs and damper left out) equals the
#    two-mass closed form to 1e-9;
#  - the four folds of the response equal the Jeffcott model's to 1e-8
#    relative (both 4 harmonics).
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
WHIRL="$top_builddir/drivers/whirl"
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
case $top_srcdir in /*) ;; *) top_srcdir="$(pwd)/$top_srcdir" ;; esac
ex="$top_srcdir/examples/rotor/jeffcott-limit.rotor"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-jefflim.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

# linear: m_d y'' + k_s (y - y_j) = 0, 2 m_j y_j'' + 2 k_r y_j - k_s (y - y_j) = 0
grep -v "^bearing node=1 \|^sfd" "$ex" > linear.rotor
"$WHIRL" rotor modes linear.rotor --speed 0 --modes 2 > modes.tsv 2> modes.err
ok $? "whirl rotor modes (linear part): $(head -c 200 modes.err)"
w=$(awk -F '\t' 'NR == 2 { print $2 }' modes.tsv)
want=$(awk 'BEGIN { md = 142.5; mj = 142.5; ks = 2.5e8; kr = 5e7
  a = md * mj; b = -(md * (kr + ks) + mj * ks); c = ks * kr
  printf "%.12g", sqrt((-b - sqrt(b * b - 4 * a * c)) / (2 * a)) }')
ok "$(awk -v a="$w" -v b="$want" 'BEGIN { d = (a - b) / b; exit !(d < 1e-9 && d > -1e-9) }'; echo $?)" \
  "first natural frequency $w rad/s = closed form $want"

cp "$top_srcdir/examples/jeffcott/response.whirl" .
"$WHIRL" run response.whirl --quiet > run.out 2> run.err
ok $? "whirl run examples/jeffcott/response.whirl: $(head -c 200 run.err)"
awk -F '\t' '$3 == "LP" { print $5 }' response.out/branches.tsv | sort -g > lp.jeffcott
"$WHIRL" rotor response "$ex" --harmonics 4 --stability off -o fe --quiet > fe.tsv 2> fe.err
ok $? "whirl rotor response jeffcott-limit.rotor: $(head -c 200 fe.err)"
awk -F '\t' '$1 == "LP" { print $5 }' fe.tsv | sort -g > lp.fe
echo "# folds, Jeffcott model: $(tr '\n' ' ' < lp.jeffcott)"
echo "# folds, FE rotor:       $(tr '\n' ' ' < lp.fe)"
worst=$(paste lp.fe lp.jeffcott | awk '{ d = ($1 - $2) / $2; if (d < 0) d = -d; if (d > w) w = d } END { if (NR != 4) print 1; else printf "%.3g", w }')
ok "$(awk -v d="$worst" 'BEGIN { exit !(d < 1e-8) }'; echo $?)" "four folds equal the Jeffcott model's to 1e-8 (worst $worst)"

echo "1..$n"
[ "$fails" -eq 0 ]

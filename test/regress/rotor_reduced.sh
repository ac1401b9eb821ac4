#!/bin/sh
# test/regress/rotor_reduced.sh — Hill's method on the Craig-Bampton
# reduction (--stability reduced, rotor/fe_hbm_reduce.c) against the sparse
# method on the whole rotor, on a 330-DOF rotor with a torus point:
# examples/rotor/compressor-journal.rotor (compressor.rotor's shaft on two
# short journal bearings: oil whirl).  The response is the same (the
# harmonic balance does not depend on the stability method); the special
# points are the same in number and type; the TR, located from the
# reduced exponents, within 3e-7 of the sparse method's speed (measured
# 9e-8; 7e-7 with 4 modes and the inertia relief alone, 0.6 without the
# constraint modes); every regular point's stable flag the same.
# SPDX-License-Identifier: BSD-3-Clause
name=rotorred
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/rotor/compressor-journal.rotor"

for s in sparse reduced; do
  "$WHIRL" rotor response "$ex" --stability "$s" -o "$s.d" --no-plot --quiet > "$s.tsv" 2> "$s.err"
  ok $? "whirl rotor response compressor-journal.rotor --stability $s: $(head -c 200 "$s.err")"
done
ok "$(grep -c '^TR' sparse.tsv | awk '{ exit !($1 >= 1) }'; echo $?)" \
  "the sparse method finds the oil whirl's torus point: $(grep '^TR' sparse.tsv | cut -f1,3 | tr '\t\n' '  ')"
ok "$(test "$(cut -f1,2 sparse.tsv)" = "$(cut -f1,2 reduced.tsv)"; echo $?)" \
  "the same special points, in number and type: $(cut -f1 reduced.tsv | tail -n +2 | tr '\n' ' ')"
paste sparse.tsv reduced.tsv | awk -F '\t' 'NR > 1 { d = ($10 - $3) / $3; if (d < 0) d = -d
  if (d > m) m = d } END { printf "%.2e\n", m }' > d.txt
ok "$(awk '{ exit !($1 < 3e-7) }' d.txt; echo $?)" \
  "their speeds within 3e-7 relative ($(cat d.txt))"
paste sparse.d/branches.tsv reduced.d/branches.tsv | awk -F '\t' '
  NR > 1 && $1 == "-" { n++; if ($7 != $14) d++ } END { printf "%d %d\n", d, n }' > f.txt
read -r differ points < f.txt
ok "$(test "$differ" -eq 0 && test "$points" -gt 100; echo $?)" \
  "the stable flags of all $points regular points the same ($differ differ)"
# asked for on a rotor whose reduction is too small for the sparse method:
# the stability's own message, not the core's status alone; nothing written
"$WHIRL" rotor response "$top_srcdir/examples/rotor/rigid-limit.rotor" --harmonics 1 \
  --stability reduced -o small.d --no-plot > small.tsv 2> small.err
rc=$?
[ $rc -ne 0 ] && grep -q "reduction is too small" small.err && [ ! -e small.d ]
ok $? "--stability reduced on rigid-limit.rotor: exit $rc, $(head -c 200 small.err), nothing written"
tap_end

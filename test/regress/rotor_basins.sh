#!/bin/sh
# test/regress/rotor_basins.sh — `whirl rotor basins` on
# examples/rotor/sfd-rigid.rotor at 690 rad/s, between its folds: bad input
# exits 2 with "whirl rotor basins: ..." and writes nothing; the harmonic
# balance finds the two stable orbits (the upper one of larger amplitude);
# on a 3 x 3 grid the corners lie outside the clearance (class -1) and two
# points are checked by an independent route: `whirl rotor simulate` from
# the same start settles on the orbit of the class basins gives (its
# amplitude equals that orbit's to 1e-6).
# SPDX-License-Identifier: BSD-3-Clause
name=rotbas
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/rotor/sfd-rigid.rotor"

bad() {
  prefix=$1; shift
  "$WHIRL" rotor basins "$@" -o out > stdout.txt 2> stderr.txt
  rc=$?
  head -c ${#prefix} stderr.txt | grep -qF "$prefix" && [ $rc -eq 2 ] && [ ! -e out ] && [ ! -s stdout.txt ]
  r=$?
  [ $r -eq 0 ] || echo "#   exit $rc: $(cat stderr.txt)"
  ok $r "$* -> exit 2, '$prefix...'"
}
bad "whirl rotor basins: --speed is required" "$ex"
bad "whirl rotor basins: need 3 <= --grid" "$ex" --speed 690 --grid 2
bad "whirl rotor basins: need 0 < --tol" "$ex" --speed 690 --tol 2
bad "whirl rotor basins: --node 9 is not a node" "$ex" --speed 690 --node 9
bad "whirl rotor basins: the rotor has no nonlinear element" \
  "$top_srcdir/examples/rotor/friswell-5.9.1.rotor" --speed 690

"$WHIRL" rotor basins "$ex" --speed 690 --unit rad/s --grid 3 --quiet -o b > counts.txt
ok $? "a 3 x 3 grid at 690 rad/s: exit 0"
awk -F '\t' 'NR > 1 { a[NR - 1] = $2 } END { exit !(NR == 3 && a[1] > 1.2 * a[2]) }' \
  b/attractors.tsv
ok $? "two stable orbits, the first of larger amplitude ($(cut -f2 b/attractors.tsv | tr '\n' ' '))"
awk -F '\t' 'NF == 4 && NR > 1 && $1 != 0 && $2 != 0 && $3 != -1 { bad = 1 } END { exit bad }' \
  b/basins.tsv
ok $? "the corners of the square lie outside the clearance (class -1)"
[ -s b/basins.png ]
ok $? "basins.png"

# class of the start (Y0, Z0) in basins.tsv, and the amplitude of that orbit
cls() { awk -F '\t' -v y="$1" -v z="$2" 'NF == 4 && $1 == y && $2 == z { print $3 }' b/basins.tsv; }
amp() { awk -F '\t' -v k="$1" 'NR > 1 && $1 == k { print $2 }' b/attractors.tsv; }
for start in "0 0" "0 -9.5e-05"; do
  set -- $start
  k=$(cls "$1" "$2")
  "$WHIRL" rotor simulate "$ex" --speed 690 --unit rad/s --y0 "$1" --z0 "$2" --periods 60 \
    --no-plot --quiet -o "s$k" > sim.txt
  a=$(amp "$k")
  awk -F '\t' -v want="$a" '$1 == "amplitude" { d = $2 - want; if (d < 0) d = -d;
      printf "#   simulate %s, orbit %s\n", $2, want; exit !(want > 0 && d < 1e-6 * want) }' sim.txt
  ok $? "start ($1, $2): class $k, and simulate from there settles on that orbit"
done

tap_end

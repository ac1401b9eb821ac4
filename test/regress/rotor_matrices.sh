#!/bin/sh
# test/regress/rotor_matrices.sh — a rotor's linear part from Matrix Market
# files (the `nodes` and `matrices` lines of a rotor file, read with
# CHOLMOD) against the same rotor assembled from its elements: `whirl rotor
# export` writes M, C, G, K; a rotor file of those matrices alone gives the
# same modes (Friswell 5.9.1 at 0 and 4000 rev/min, every printed digit,
# the skew-symmetric G included); the rigid-limit rotor's matrices with its
# two SFDs added by lines give the same folds; bad matrices lines are
# FILE:LINE, exit 2.
# SPDX-License-Identifier: BSD-3-Clause
name=rotmtx
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/rotor"

"$WHIRL" rotor export "$ex/friswell-5.9.1.rotor" -o fr --quiet 2> err.txt
ok $? "whirl rotor export friswell-5.9.1.rotor: $(head -c 200 err.txt)"
ok "$([ -s fr/M.mtx ] && [ -s fr/G.mtx ] && [ -s fr/K.mtx ] && [ "$(wc -l < fr/dofs.tsv)" -eq 29 ] && echo 0 || echo 1)" \
  "M, C, G, K and the 28 DOFs written"
printf 'title Friswell 5.9.1 from its matrices\nnodes count=7\nmatrices M=M.mtx C=C.mtx G=G.mtx K=K.mtx\n' > fr/from-matrices.rotor
for s in 0 4000; do
  "$WHIRL" rotor modes fr/from-matrices.rotor --speed "$s" > a.tsv 2> err.txt
  "$WHIRL" rotor modes "$ex/friswell-5.9.1.rotor" --speed "$s" > b.tsv
  cmp -s a.tsv b.tsv
  ok $? "modes at $s rev/min from the matrices = from the elements: $(head -c 200 err.txt)"
done

# the nonlinear elements on a matrix rotor: the rigid limit's folds
"$WHIRL" rotor export "$ex/rigid-limit.rotor" -o rl --quiet
{ printf 'nodes count=3\nmatrices M=M.mtx C=C.mtx G=G.mtx K=K.mtx\n'
  grep -E '^(sfd-short-pi|unbalance|speed|reference)' "$ex/rigid-limit.rotor"; } > rl/from-matrices.rotor
"$WHIRL" rotor response rl/from-matrices.rotor --harmonics 1 -o a.d --quiet > a.tsv 2> err.txt
ok $? "whirl rotor response on the matrix rotor with two SFDs: $(head -c 200 err.txt)"
"$WHIRL" rotor response "$ex/rigid-limit.rotor" --harmonics 1 -o b.d --quiet > b.tsv
d=$(paste a.tsv b.tsv | awk -F '\t' 'NR > 1 { e = ($3 - $10) / $10; if (e < 0) e = -e; if (e > w) w = e; k++ }
  END { if (k != 2) print 1; else printf "%.3g", w }')
ok "$(awk -v d="$d" 'BEGIN { exit !(d < 1e-10) }'; echo $?)" "its two folds = the element rotor's (worst $d)"

# bad matrices lines: FILE:LINE, exit 2
bad() {
  printf '%s\n' "$2" > case.rotor
  "$WHIRL" rotor modes case.rotor > out.txt 2> err.txt
  rc=$?
  grep -q "^whirl rotor: case\.rotor:$3: .*$4" err.txt && [ $rc -eq 2 ] && [ ! -s out.txt ]
  ok $? "$1: $(head -c 160 err.txt)"
}
cp fr/M.mtx fr/K.mtx .
bad "a matrix of the wrong size" "$(printf 'nodes count=5\nmatrices M=M.mtx K=K.mtx')" 2 "M: 'M.mtx' is 28 x 28: the rotor has 20 DOFs"
bad "a missing matrix file" "$(printf 'nodes count=7\nmatrices M=nothere.mtx K=K.mtx')" 2 "cannot open 'nothere.mtx'"
bad "not Matrix Market" "$(printf 'nodes count=7\nmatrices M=case.rotor K=K.mtx')" 2 "is not a Matrix Market"
bad "a device, not a file" "$(printf 'nodes count=7\nmatrices M=/dev/zero K=K.mtx')" 2 "'/dev/zero' is not a regular file"
bad "stiffness without mass" "$(printf 'nodes count=7\nmatrices K=K.mtx')" 2 "has no mass"
bad "nodes without matrices" "nodes count=3" 1 "the matrices line is missing"
bad "a key of matrices" "$(printf 'nodes count=7\nmatrices X=K.mtx')" 2 "is not M=FILE"

tap_end

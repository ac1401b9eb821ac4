#!/bin/sh
# test/regress/study.sh — parameter studies (STUDY, doc/parameter-studies.md):
# the isola count of discovery over a (lambda, delta) grid of the SFD rotor
# (Fig. 18 by brute force, small), checked point by point against the
# number of branches eq. 15 gives (whirl sfd response, another route), and
#  - chunks 1/3, 2/3, 3/3 joined by --merge-chunks=3: the single run's file;
#  - a run killed (SIGTERM) mid-way and started again: the same file, and
#    while killed no output directory, only OUT.checkpoint;
#  - the checkpoint of another run (the run file changed): exit 2, the
#    checkpoint kept, nothing written;
#  - MPI (when built --with-mpi and mpirun exists): 2 and 4 ranks give the
#    serial file;
#  - basins (IPS = basins, the Jeffcott rotor's, 11 x 11) through the same
#    blocks: chunks merged, a killed run resumed and MPI give the same
#    basins.tsv as one process;
#  - basins of whirl run with an atlas (BASIN_SEEDS): the certified
#    classes at every point, 2 chunks and 2 ranks the same bytes;
#  - whirl sfd basins (the atlas's rounds broadcast, then the states): 3
#    chunks merged, killed and resumed, the checkpoint of other options
#    refused, a chunk out of range, and 2 and 4 ranks: the one-process
#    basins.tsv and shares;
#  - POINTS = a TSV of points (the grid's, in a file): the grid's
#    study.tsv, serial and on 2 ranks; an empty list, an unknown or
#    repeated name, the continuation parameter, short and long rows, a
#    value that is not a number, POINTS with STUDY: FILE:LINE, exit 2,
#    nothing written;
#  - basin fractions as a study (whirl sfd basins --study points.tsv):
#    each point's counts those of whirl sfd basins at that point alone;
#    chunks merged and 2 ranks give the same study.tsv; an unknown name, no
#    omega: exit 2, nothing written;
#  - bad input: a grid without points, an unknown parameter, the
#    continuation parameter as an axis, a chunk out of range, a missing
#    chunk: one message, exit 2.
# SPDX-License-Identifier: BSD-3-Clause
name=study
. "${top_srcdir:-.}/test/regress/tap.sh"
cb=$top_builddir
case $cb in /*) ;; *) cb="$(cd "$OLDPWD" 2>/dev/null && cd "$top_builddir" && pwd)" ;; esac

sed -e '/^ICP/s/.*/ICP    = [Omega]/' -e '/^DISCOVER /s/.*/DISCOVER        = [5, 10, 19]/' \
  "$top_srcdir/examples/discover/sfd-rotating.whirl" > grid.whirl
echo 'STUDY = {lambda: [0.05, 0.25], delta: [0.2, 0.3, 0.42, 0.6]}' >> grid.whirl
"$WHIRL" run grid.whirl --quiet 2> grid.err
ok $? "whirl run grid.whirl (8 points): $(head -c 200 grid.err)"
cp grid.out/study.tsv serial.tsv
ok $(( $(wc -l < serial.tsv) != 9 )) "study.tsv: a header and 8 rows"
head -n 1 serial.tsv | grep -q "^point	lambda	delta	status	branches	isolated	closed	LP	BP	HB	PD	TR	UZ$"
ok $? "the header names the columns"
# eq. 15's branch count at every point
bad=0
tail -n +2 serial.tsv | while IFS='	' read -r pt l d st br iso rest; do
  want=$("$WHIRL" sfd response --lambda "$l" --delta "$d" --out "eq$pt" --no-plot 2>/dev/null |
    awk -F '\t' '$1 == "EP" { b[$2] = 1 } END { print length(b) }')
  [ "$st" = ok ] && [ "$br" = "$want" ] && [ "$iso" = $((want - 1)) ] || { echo "# point $pt ($l, $d): $br branches, eq. 15 $want"; echo bad >> bad.txt; }
done
ok $([ -s bad.txt ] && echo 1 || echo 0) "every point's branches and isolas equal eq. 15's ($(awk -F '\t' 'NR > 1 { printf "%s,%s:%s ", $2, $3, $6 }' serial.tsv))"

for i in 1 2 3; do "$WHIRL" run grid.whirl --chunk=$i/3 --quiet; done
"$WHIRL" run grid.whirl --merge-chunks=3 --quiet --OUT=grid.out 2> merge.err
ok $? "--merge-chunks=3: $(head -c 200 merge.err)"
cmp -s serial.tsv grid.out/study.tsv
ok $? "chunks 1/3, 2/3, 3/3 merged: the single run's study.tsv"

# killed mid-way, then started again
rm -rf grid.out grid.out.checkpoint
"$WHIRL" run grid.whirl --quiet > /dev/null 2>&1 &
pid=$!
k=0
while [ "$k" -lt 300 ] && [ "$(cat grid.out.checkpoint 2> /dev/null | wc -l)" -lt 3 ]; do sleep 0.05; k=$((k + 1)); done
kill -TERM $pid 2> /dev/null
wait $pid 2> /dev/null
rows=$(($(wc -l < grid.out.checkpoint) - 1))
ok $(( rows < 1 || rows >= 8 )) "killed after $rows of 8 points"
[ ! -e grid.out ]
ok $? "while killed: no output directory (the partial state is only the checkpoint)"
cp grid.out.checkpoint ckpt.saved
cp grid.whirl other.whirl
echo '# another run' >> grid.whirl
"$WHIRL" run grid.whirl --quiet > other.txt 2> other.err
rc=$?
ok $(( rc != 2 )) "the checkpoint of another run (the file changed): exit 2 ($rc)"
grep -q "checkpoint of another run" other.err && cmp -s ckpt.saved grid.out.checkpoint && [ ! -e grid.out ]
ok $? "one message, the checkpoint kept, nothing written: $(cat other.err)"
cp other.whirl grid.whirl
"$WHIRL" run grid.whirl > resume.txt 2> resume.err
ok $? "started again: $(cat resume.txt)"
cmp -s serial.tsv grid.out/study.tsv && [ ! -e grid.out.checkpoint ]
ok $? "the resumed run's study.tsv is the single run's, the checkpoint removed"
grep -q "from the checkpoint" resume.txt && ! grep -q " 0 from the checkpoint" resume.txt
ok $? "it took the finished rows from the checkpoint"

if grep -q "define WHIRL_HAVE_MPI 1" "$cb/config.h" 2> /dev/null && command -v mpirun > /dev/null; then
  for np in 2 4; do
    mpirun --allow-run-as-root --oversubscribe -n $np "$WHIRL" run grid.whirl --quiet --OUT=mpi$np > mpi$np.txt 2>&1
    cmp -s serial.tsv mpi$np/study.tsv
    ok $? "mpirun -n $np: the serial study.tsv ($(head -c 200 mpi$np.txt))"
  done
else
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
fi

# basins (IPS = basins) through the same blocks: the Jeffcott rotor's at
# Omega = 1.59 on an 11 x 11 grid (examples/jeffcott), a grid line a block
cp "$top_srcdir/examples/jeffcott/response.whirl" "$top_srcdir/examples/jeffcott/basins.whirl" .
"$WHIRL" run response.whirl --quiet > /dev/null 2>&1
"$WHIRL" run basins.whirl --BASIN_GRID=11 --OUT=b1 > b1.txt 2> b1.err
ok $? "basins, one process: $(head -c 200 b1.err)"
[ "$(grep -c . b1/basins.tsv)" -eq 122 ] && [ "$(grep -c '^$' b1/basins.tsv)" -eq 11 ] && [ -s b1/basins.png ] &&
  grep -q "attractor LAB 2: .*% of the grid" b1.txt
ok $? "basins.tsv: a header, 121 points, a blank line after each grid line; basins.png; the shares"
# the integrator (BASIN_METHOD): DOP853, the default, and DOPRI5 capture
# every state by the same attractor
"$WHIRL" run basins.whirl --BASIN_GRID=11 --BASIN_METHOD=dopri5 --OUT=b5 --quiet > /dev/null 2>&1
paste b1/basins.tsv b5/basins.tsv | awk -F'\t' 'NR > 1 && $1 != "" { n++; d += $3 != $7 } END { exit !(n == 121 && d == 0) }'
ok $? "basins with BASIN_METHOD = dopri5: the same attractor at all 121 points"
for i in 1 2 3; do "$WHIRL" run basins.whirl --BASIN_GRID=11 --OUT=bc --chunk=$i/3 --quiet; done
"$WHIRL" run basins.whirl --BASIN_GRID=11 --OUT=bc --merge-chunks=3 --quiet
cmp -s b1/basins.tsv bc/basins.tsv && [ -s bc/basins.png ]
ok $? "basins in 3 chunks, merged: the same basins.tsv, and the picture"
"$WHIRL" run basins.whirl --BASIN_GRID=11 --OUT=bk --quiet > /dev/null 2>&1 &
pid=$!
k=0
while [ "$k" -lt 300 ] && [ "$(cat bk.checkpoint 2> /dev/null | wc -l)" -lt 3 ]; do sleep 0.05; k=$((k + 1)); done
kill -TERM $pid 2> /dev/null
wait $pid 2> /dev/null
[ ! -e bk ] && [ -s bk.checkpoint ]
ok $? "basins killed after $(($(wc -l < bk.checkpoint) - 1)) of 11 grid lines: only the checkpoint"
"$WHIRL" run basins.whirl --BASIN_GRID=11 --OUT=bk > bk.txt 2>&1
cmp -s b1/basins.tsv bk/basins.tsv && grep -q "from the checkpoint" bk.txt
ok $? "basins started again: the same basins.tsv ($(tail -n 1 bk.txt))"
if grep -q "define WHIRL_HAVE_MPI 1" "$cb/config.h" 2> /dev/null && command -v mpirun > /dev/null; then
  for np in 2 4; do
    mpirun --allow-run-as-root --oversubscribe -n $np "$WHIRL" run basins.whirl --BASIN_GRID=11 --quiet --OUT=bm$np > bm$np.txt 2>&1
    cmp -s b1/basins.tsv bm$np/basins.tsv
    ok $? "basins, mpirun -n $np: the same basins.tsv"
  done
else
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
fi

# whirl sfd basins (the paper's command) through the same blocks: the atlas's
# rounds as stages every rank takes in, then the states; 400 states at
# Omega = 1.78 (two attractors, both basins large)
sb="sfd basins --omega 1.78 --points 400 --no-plot"
"$WHIRL" $sb --out s1 > s1.txt 2> s1.err
ok $? "sfd basins, one process: $(tail -n 1 s1.err | head -c 200)"
[ "$(wc -l < s1/basins.tsv)" -eq 403 ] && grep -q "^small	" s1.txt && grep -q "^large	" s1.txt && [ ! -e s1.checkpoint ]
ok $? "sfd basins: 401 states, both attractors' shares, no checkpoint left"
for i in 1 2 3; do "$WHIRL" $sb --out sc --chunk $i/3 --quiet > /dev/null; done
"$WHIRL" $sb --out sc --merge-chunks 3 > sc.txt 2> sc.err
cmp -s s1/basins.tsv sc/basins.tsv && cmp -s s1/attractors.tsv sc/attractors.tsv && cmp -s s1.txt sc.txt
ok $? "sfd basins in 3 chunks, merged: the same basins.tsv, attractors.tsv and shares $(head -c 200 sc.err)"
"$WHIRL" $sb --out sk --threads 1 --quiet > /dev/null 2>&1 &
pid=$!
k=0
while [ "$k" -lt 400 ] && [ "$(cat sk.checkpoint 2> /dev/null | grep -a -c "^4	")" -lt 2 ]; do sleep 0.05; k=$((k + 1)); done
kill -TERM $pid 2> /dev/null
wait $pid 2> /dev/null
[ ! -e sk ] && [ -s sk.checkpoint ]
ok $? "sfd basins killed after the atlas and $(grep -a -c "^4	" sk.checkpoint) blocks of states: only the checkpoint"
cp sk.checkpoint sk.saved
"$WHIRL" $sb --out sk --cells 16 --quiet > sko.txt 2> sko.err
rc=$?
[ "$rc" -eq 2 ] && grep -q "checkpoint of another run" sko.err && cmp -s sk.saved sk.checkpoint && [ ! -e sk ]
ok $? "sfd basins, the checkpoint of other options (--cells): exit 2 ($rc), kept, nothing written"
"$WHIRL" $sb --out sk > sk.txt 2> sk.err
cmp -s s1/basins.tsv sk/basins.tsv && cmp -s s1.txt sk.txt && grep -q "from the checkpoint" sk.err && [ ! -e sk.checkpoint ]
ok $? "sfd basins started again: the same basins.tsv ($(tail -n 1 sk.err | sed 's/.*; //'))"
"$WHIRL" $sb --out sx --chunk 4/3 > sx.txt 2> sx.err
rc=$?
[ "$rc" -eq 2 ] && grep -q "need 1 <= I <= N" sx.err && [ ! -e sx.chunk-4-of-3 ] && [ ! -e sx.chunk-4-of-3.checkpoint ]
ok $? "sfd basins --chunk 4/3: exit 2 ($rc), nothing written: $(cat sx.err)"
if grep -q "define WHIRL_HAVE_MPI 1" "$cb/config.h" 2> /dev/null && command -v mpirun > /dev/null; then
  for np in 2 4; do
    mpirun --allow-run-as-root --oversubscribe -n $np "$WHIRL" $sb --threads 1 --out sm$np > sm$np.txt 2> sm$np.err
    cmp -s s1/basins.tsv sm$np/basins.tsv && cmp -s s1.txt sm$np.txt
    ok $? "sfd basins, mpirun -n $np (one thread each): the serial basins.tsv and shares ($(tail -n 1 sm$np.err | head -c 160))"
  done
else
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
fi

# a study over a list of points (POINTS = a TSV with a header of parameter
# names): the grid's points in a file give the grid's study.tsv
printf 'lambda\tdelta\n# the grid above, a row a point\n0.05\t0.2\n0.05\t0.3\n\n0.05\t0.42\n0.05\t0.6\n0.25\t0.2\n0.25\t0.3\n0.25\t0.42\n0.25\t0.6\n' > pts.tsv
sed '/^STUDY/d' grid.whirl > pl.whirl
echo 'POINTS = pts.tsv' >> pl.whirl
"$WHIRL" run pl.whirl --quiet 2> pl.err
cmp -s serial.tsv pl.out/study.tsv
ok $? "POINTS = pts.tsv (the grid's 8 points, a comment, a blank line): the grid's study.tsv $(head -c 200 pl.err)"
if grep -q "define WHIRL_HAVE_MPI 1" "$cb/config.h" 2> /dev/null && command -v mpirun > /dev/null; then
  mpirun --allow-run-as-root --oversubscribe -n 2 "$WHIRL" run pl.whirl --quiet --OUT=plm > plm.txt 2>&1
  cmp -s serial.tsv plm/study.tsv
  ok $? "POINTS, mpirun -n 2: the same study.tsv"
else
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
fi
bad_points() { # NAME PATTERN CONTENT: pts-NAME.tsv with CONTENT refused
  printf "$3" > "pts-$1.tsv"
  "$WHIRL" run pl.whirl --quiet --POINTS="pts-$1.tsv" --OUT="pt-$1" > "pt-$1.txt" 2> "pt-$1.err"
  rc=$?
  [ "$rc" -eq 2 ] && grep -q "$2" "pt-$1.err" && [ "$(wc -l < "pt-$1.err")" -eq 1 ] && [ ! -e "pt-$1" ] && [ ! -e "pt-$1.checkpoint" ]
  ok $? "POINTS $1: exit 2 ($rc), one message, nothing written: $(cat "pt-$1.err")"
}
bad_points empty "pts-empty.tsv:1: no points" 'lambda\tdelta\n'
bad_points unknown "pts-unknown.tsv:1: column 2, 'nope' is not a parameter" 'lambda\tnope\n0.1\t1\n'
bad_points icp "pts-icp.tsv:1: column 1, 'Omega' is the continuation parameter" 'Omega\n1\n'
bad_points twice "pts-twice.tsv:1: column 2, 'lambda' is named twice" 'lambda\tlambda\n0.1\t0.2\n'
bad_points short "pts-short.tsv:4: 1 value where the header names 2" 'lambda\tdelta\n0.1\t0.2\n\n0.1\n'
bad_points long "pts-long.tsv:2: more than 2 values" 'lambda\tdelta\n0.1\t0.2\t0.3\n'
bad_points number "pts-number.tsv:3: column 2 (delta): '0.3x' is not a finite number" 'lambda\tdelta\n0.1\t0.2\n0.1\t0.3x\n'
bad_points nan "pts-nan.tsv:2: column 1 (lambda): 'nan' is not a finite number" 'lambda\tdelta\nnan\t0.2\n'
{ cat pl.whirl; echo 'STUDY = {lambda: [0.1]}'; } > both.whirl
"$WHIRL" run both.whirl --quiet > both.txt 2> both.err
rc=$?
[ "$rc" -eq 2 ] && grep -q "POINTS and STUDY" both.err && [ ! -e both.out ]
ok $? "POINTS and STUDY together: exit 2 ($rc): $(cat both.err)"

# basin fractions as the analysis of a study: whirl sfd basins --study over
# points (omega, delta), each row the counts that whirl sfd basins at that
# point alone prints (another route: the atlas built in rounds of blocks
# there, by whirl_basins_compute itself here)
printf 'omega\tdelta\n1.78\t0.3\n1.715\t0.25\n-1\t0.3\n' > bs.tsv
"$WHIRL" sfd basins --study bs.tsv --points 200 --out bs1 > bs1.txt 2> bs1.err
ok $? "sfd basins --study (3 points, one invalid): $(tail -n 1 bs1.err)"
bad=0
for pt in 0 1; do
  row=$(awk -F '\t' -v p=$pt '$1 == p' bs1/study.tsv)
  om=$(echo "$row" | cut -f2); de=$(echo "$row" | cut -f3)
  "$WHIRL" sfd basins --omega "$om" --delta "$de" --points 200 --no-plot --quiet --out bsp$pt > bsp$pt.txt
  want=$(awk -F '\t' 'NR > 1 { c[$1] = $2 } END { printf "%d %d", c["small"], c["large"] }' bsp$pt.txt)
  got=$(echo "$row" | awk -F '\t' '{ printf "%d %d", $7, $9 }')
  [ "$want" = "$got" ] && [ "$(echo "$row" | cut -f4)" = ok ] || { bad=1; echo "# point $pt: $got, alone $want"; }
done
awk -F '\t' '$1 == 2 && $4 == "invalid"' bs1/study.tsv | grep -q . && grep -q "study point 2: omega must be > 0" bs1.err || bad=1
ok $bad "every point's small and large counts are those of whirl sfd basins at that point; the invalid one said"
for i in 1 2; do "$WHIRL" sfd basins --study bs.tsv --points 200 --out bsc --chunk $i/2 --quiet 2> /dev/null; done
"$WHIRL" sfd basins --study bs.tsv --points 200 --out bsc --merge-chunks 2 --quiet
cmp -s bs1/study.tsv bsc/study.tsv
ok $? "sfd basins --study in 2 chunks, merged: the same study.tsv"
if grep -q "define WHIRL_HAVE_MPI 1" "$cb/config.h" 2> /dev/null && command -v mpirun > /dev/null; then
  mpirun --allow-run-as-root --oversubscribe -n 2 "$WHIRL" sfd basins --study bs.tsv --points 200 --threads 1 --out bsm --quiet > /dev/null 2>&1
  cmp -s bs1/study.tsv bsm/study.tsv
  ok $? "sfd basins --study, mpirun -n 2: the same study.tsv"
else
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
fi
printf 'omega\tclearance\n1.78\t1\n' > bsu.tsv
"$WHIRL" sfd basins --study bsu.tsv --out bsu > bsu.txt 2> bsu.err
rc=$?
[ "$rc" -eq 2 ] && grep -q "bsu.tsv:1: column 2, 'clearance' is not a parameter" bsu.err && [ ! -e bsu ] && [ ! -e bsu.checkpoint ]
ok $? "sfd basins --study, an unknown name: exit 2 ($rc), nothing written: $(cat bsu.err)"
printf 'delta\n0.3\n' > bso.tsv
"$WHIRL" sfd basins --study bso.tsv --out bso > bso.txt 2> bso.err
rc=$?
[ "$rc" -eq 2 ] && grep -q "no omega column, and no --omega" bso.err && [ ! -e bso ]
ok $? "sfd basins --study without omega: exit 2 ($rc): $(cat bso.err)"

# basins of whirl run with the atlas (BASIN_SEEDS = 2: its rounds the
# stages of the blocks), against the certified route (no atlas) point by
# point, and the same bytes on 2 ranks and in 2 chunks
"$WHIRL" run basins.whirl --BASIN_GRID=21 --OUT=ja0 --quiet 2> ja0.err
"$WHIRL" run basins.whirl --BASIN_GRID=21 --BASIN_SEEDS=2 --OUT=ja1 --quiet 2> ja1.err
ok $? "basins with BASIN_SEEDS = 2 (21 x 21): $(head -c 200 ja1.err)"
d=$(paste ja0/basins.tsv ja1/basins.tsv | awk -F '\t' 'NR > 1 && NF > 4 && $3 != $7 { d++ } END { print d + 0 }')
[ "$d" -eq 0 ] && [ "$(grep -c . ja1/basins.tsv)" -eq 442 ]
ok $? "the atlas's classes are the certified route's at every one of the 441 points ($d differ)"
for i in 1 2; do "$WHIRL" run basins.whirl --BASIN_GRID=21 --BASIN_SEEDS=2 --OUT=jac --chunk=$i/2 --quiet; done
"$WHIRL" run basins.whirl --BASIN_GRID=21 --BASIN_SEEDS=2 --OUT=jac --merge-chunks=2 --quiet
cmp -s ja1/basins.tsv jac/basins.tsv
ok $? "basins with the atlas in 2 chunks (each with the whole atlas), merged: the same basins.tsv"
if grep -q "define WHIRL_HAVE_MPI 1" "$cb/config.h" 2> /dev/null && command -v mpirun > /dev/null; then
  mpirun --allow-run-as-root --oversubscribe -n 2 "$WHIRL" run basins.whirl --BASIN_GRID=21 --BASIN_SEEDS=2 --quiet --OUT=jam > /dev/null 2>&1
  cmp -s ja1/basins.tsv jam/basins.tsv
  ok $? "basins with the atlas, mpirun -n 2 (the rounds broadcast): the same basins.tsv"
else
  echo "ok $((n + 1)) # SKIP not built --with-mpi (or no mpirun)"; n=$((n + 1))
fi
"$WHIRL" run basins.whirl --BASIN_SEEDS=-1 --OUT=jan --quiet > jan.txt 2> jan.err
rc=$?
[ "$rc" -eq 2 ] && grep -q "BASIN_SEEDS" jan.err && [ ! -e jan ]
ok $? "BASIN_SEEDS = -1: exit 2 ($rc): $(cat jan.err)"

bad_input() { # NAME PATTERN [ARGS...], the study line last in NAME.whirl
  nm=$1 pat=$2
  shift 2
  "$WHIRL" run "$nm.whirl" --quiet "$@" > "$nm.txt" 2> "$nm.err"
  rc=$?
  ok $(( rc != 2 )) "$nm: exit 2 ($rc)"
  grep -q "$pat" "$nm.err" && [ "$(wc -l < "$nm.err")" -eq 1 ] && [ ! -e "$nm.out" ]
  ok $? "$nm: one message, nothing written: $(cat "$nm.err")"
}
sed '/^STUDY/d' grid.whirl > base.whirl
{ cat base.whirl; echo 'STUDY = {lambda: []}'; } > empty.whirl
bad_input empty "STUDY"
{ cat base.whirl; echo 'STUDY = {nope: [1, 2]}'; } > unknown.whirl
bad_input unknown "'nope' is not a parameter"
{ cat base.whirl; echo 'STUDY = {Omega: [1, 2]}'; } > icp.whirl
bad_input icp "continuation parameter"
cp grid.whirl chunk.whirl
bad_input chunk "need 1 <= I <= N" --chunk=4/3
cp grid.whirl chunk0.whirl
bad_input chunk0 "need 1 <= I <= N" --chunk=0/3
cp grid.whirl missing.whirl
"$WHIRL" run missing.whirl --chunk=1/2 --quiet
bad_input missing "missing.out.chunk-2-of-2/study.tsv" --merge-chunks=2
tap_end

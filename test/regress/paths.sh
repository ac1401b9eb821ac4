#!/bin/sh
# test/regress/paths.sh — the paths of a run file (doc/run-files.md,
# "Paths"): `model`, `S` and `OUT` written in a run file are relative to the
# run file's directory, and so is the default output FILE.out; given on the
# command line (--model=, --S=, --OUT=) they are relative to the current
# directory; absolute paths are taken as they are.  Checked from another
# directory than the run files' (where the old rule — S and OUT relative to
# the current directory — put things elsewhere), from the run files' own
# directory (where both rules agree: the old usage of examples/), and with
# examples/jeffcott run from outside it (basins.whirl's S = response.out).
# SPDX-License-Identifier: BSD-3-Clause
name=paths
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
mkdir -p proj elsewhere abs || exit 1
$CC -std=c11 -shared -fPIC -I"$top_srcdir/lib" -o proj/ab.so "$top_srcdir/examples/auto/ab.c" -lm \
  > cc.log 2>&1
ok $? "ab.so (examples/auto/ab.c) builds as a plug-in"
# labels of first: 1 EP, 2 and 3 HB, 4 EP (runfile_errors.sh's control)
printf 'model = ab.so\nICP = [Da]\nPAR = {B: 14, beta: 3}\nNMX = 50\n' > proj/first.whirl
printf 'model = ab.so\nICP = [Da]\nPAR = {B: 14, beta: 3}\nS = first.out\nIRS = 4\nNMX = 5\n' \
  > proj/second.whirl
printf 'model = ab.so\nICP = [Da]\nPAR = {B: 14, beta: 3}\nS = first.out\nIRS = 4\nNMX = 5\nOUT = results/third\n' \
  > proj/third.whirl
printf 'model = ab.so\nICP = [Da]\nPAR = {B: 14, beta: 3}\nNMX = 5\nOUT = %s/abs/fourth\n' "$tmp" \
  > proj/fourth.whirl

# from another directory
cd elsewhere || exit 1
run() { "$WHIRL" run "$@" --quiet > run.out 2> run.err; }
run ../proj/first.whirl
ok $? "whirl run ../proj/first.whirl: model = ab.so beside the run file $(head -c 200 run.err)"
[ -f ../proj/first.out/solutions ] && [ ! -e first.out ]
ok $? "the default output first.out is beside the run file, not in the current directory"
run ../proj/second.whirl
ok $? "whirl run ../proj/second.whirl: S = first.out beside the run file $(head -c 200 run.err)"
[ -f ../proj/second.out/branches.tsv ] && [ ! -e second.out ] &&
  grep -q '^branch' ../proj/second.out/branches.tsv
ok $? "its output second.out beside the run file"
run ../proj/third.whirl
[ $? -eq 0 ] && [ -f ../proj/results/third/branches.tsv ] && [ ! -e results ]
ok $? "OUT = results/third in the file: proj/results/third $(head -c 200 run.err)"
run ../proj/fourth.whirl
[ $? -eq 0 ] && [ -f ../abs/fourth/branches.tsv ]
ok $? "OUT = an absolute path: as it is $(head -c 200 run.err)"
# the command line's paths are the current directory's
run ../proj/second.whirl --OUT=mine --S=../proj/first.out
[ $? -eq 0 ] && [ -f mine/branches.tsv ] && [ ! -e ../proj/mine ]
ok $? "--OUT=mine --S=../proj/first.out: both relative to the current directory $(head -c 200 run.err)"
cp ../proj/ab.so here.so
run ../proj/first.whirl --model=here.so --OUT=cl
[ $? -eq 0 ] && [ -f cl/branches.tsv ]
ok $? "--model=here.so: relative to the current directory $(head -c 200 run.err)"
run ../proj/second.whirl --S=first.out
[ $? -eq 2 ] && grep -q "first.out" run.err
ok $? "--S=first.out (not in the current directory): exit 2, said: $(head -c 200 run.err)"

# from the run files' directory: what it always did
cd ../proj || exit 1
rm -rf first.out second.out
run first.whirl && run second.whirl
[ $? -eq 0 ] && [ -f first.out/solutions ] && [ -f second.out/branches.tsv ]
ok $? "from the run files' directory: first.out, then second.out from S = first.out"
cd .. || exit 1

# examples/jeffcott from outside: basins.whirl's S = response.out is the
# output of response.whirl beside it
cp -r "$top_srcdir/examples/jeffcott" jeff && chmod -R u+w jeff
run jeff/response.whirl
ok $? "whirl run jeff/response.whirl (from its parent) $(head -c 200 run.err)"
run jeff/basins.whirl --BASIN_GRID=3
[ $? -eq 0 ] && [ -f jeff/basins.out/basins.tsv ] && [ ! -e response.out ] && [ ! -e basins.out ]
ok $? "whirl run jeff/basins.whirl: restarts from jeff/response.out, writes jeff/basins.out $(head -c 200 run.err)"
tap_end

#!/bin/sh
# test/regress/rotor_simulate.sh — `whirl rotor simulate` on
# examples/rotor/sfd-rigid.rotor: bad input is "whirl rotor simulate: ..."
# (or "whirl rotor: FILE...") with exit 2 and nothing written; a start
# beyond the clearance is refused (exit 2); from rest at 690 rad/s the rotor
# settles on a synchronous orbit whose amplitude BDF and DOPRI5 (two
# independent integrators) give alike to 1e-6, with time.tsv of the
# announced size and both pictures.  The orbit against harmonic balance is
# test/unit/t_fe_time_hbm.
# SPDX-License-Identifier: BSD-3-Clause
name=rotsim
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/rotor/sfd-rigid.rotor"

# bad: ARGS... must exit 2 with a message starting with PREFIX, writing nothing
bad() {
  prefix=$1; shift
  "$WHIRL" rotor simulate "$@" -o out > stdout.txt 2> stderr.txt
  rc=$?
  head -c ${#prefix} stderr.txt | grep -qF "$prefix" && [ $rc -eq 2 ] && [ ! -e out ] && [ ! -s stdout.txt ]
  r=$?
  [ $r -eq 0 ] || { echo "#   exit $rc: $(cat stderr.txt)"; }
  ok $r "$* -> exit 2, '$prefix...'"
}
bad "whirl rotor simulate: --speed is required" "$ex"
bad "whirl rotor simulate: --speed must be > 0" "$ex" --speed -3
bad "whirl rotor simulate: --method must be bdf or dopri5" "$ex" --speed 690 --method rk4
bad "whirl rotor simulate: --unit must be" "$ex" --speed 690 --unit furlongs
bad "whirl rotor simulate: --node 9 is not a node" "$ex" --speed 690 --node 9
bad "whirl rotor simulate: need 1 <= --periods" "$ex" --speed 690 --periods 0
bad "whirl rotor simulate: the initial displacement puts a journal" "$ex" --speed 690 --unit rad/s --y0 2e-4
bad "whirl rotor: nofile.rotor: cannot open" nofile.rotor --speed 690
bad "whirl rotor simulate: the rotor file is missing" --speed 690

"$WHIRL" rotor simulate "$ex" --speed 690 --unit rad/s --periods 40 --quiet -o bdf > bdf.txt
rb=$?
"$WHIRL" rotor simulate "$ex" --speed 690 --unit rad/s --periods 40 --method dopri5 --quiet \
  -o dp > dp.txt
rd=$?
ok $((rb + rd)) "BDF and DOPRI5 runs exit 0"
awk -F '\t' 'FNR == NR && $1 == "amplitude" { a = $2 } FNR != NR && $1 == "amplitude" { b = $2 }
  END { d = a - b; if (d < 0) d = -d; printf "#   BDF %s, DOPRI5 %s\n", a, b;
        exit !(a > 5e-5 && a < 1e-4 && d < 1e-6 * a) }' bdf.txt dp.txt
ok $? "the steady amplitude at the journal: BDF = DOPRI5 to 1e-6, inside the clearance"
awk -F '\t' '$1 == "change" { exit !($2 < 1e-9) }' bdf.txt
ok $? "synchronous: the journal's state repeats over the last revolution"
rows=$(wc -l < bdf/time.tsv)
[ "$rows" -eq $((40 * 64 + 2)) ] && [ -s bdf/time.png ] && [ -s bdf/orbit.png ]
ok $? "time.tsv has a header and 40 x 64 + 1 samples ($rows lines), time.png, orbit.png"

tap_end

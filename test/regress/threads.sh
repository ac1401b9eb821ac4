#!/bin/sh
# test/regress/threads.sh — periodic collocation on several threads (run
# files' THREADS, whirl_colloc_options.threads): AUTO-07p's demo lrz, its
# periodic orbits from the Hopf point (examples/auto/lrz-4.whirl) on NTST =
# 60 (720 values at Gauss points, above the size where the loops over the
# intervals go parallel), run with THREADS = 1, 2 and 3: branches.tsv and
# the solutions must be the same bytes (each interval is computed by the
# same arithmetic whichever thread takes it, and the determinant's factors
# are multiplied in interval order).  And THREADS out of range: a file:line
# message, exit 2, nothing written.  TAP output.
set -u
name=threads
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
ex="$top_srcdir/examples/auto"
command -v "$CC" >/dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
cp "$ex"/lrz-1.whirl "$ex"/lrz-2.whirl "$ex"/lrz-4.whirl "$tmp"/
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o "$tmp/lrz.so" "$ex/lrz.c" -lm 2>"$tmp/cc.err"
ok $? "lrz: plug-in builds"
(cd "$tmp" && "$WHIRL" run lrz-1.whirl --quiet && "$WHIRL" run lrz-2.whirl --quiet) >"$tmp/pre.log" 2>&1
ok $? "lrz-1, lrz-2: the equilibria and the Hopf point"
for t in 1 2 3; do
  (cd "$tmp" && "$WHIRL" run lrz-4.whirl --NTST=60 --THREADS=$t --out=t$t --quiet) >"$tmp/t$t.log" 2>&1
  ok $? "lrz-4 on NTST 60 with THREADS = $t exits 0"
done
rows=$(grep -c . "$tmp/t1/branches.tsv" 2>/dev/null || echo 0)
[ "$rows" -gt 30 ]
ok $? "THREADS = 1: the branch has its points ($rows rows)"
for t in 2 3; do
  cmp -s "$tmp/t1/branches.tsv" "$tmp/t$t/branches.tsv" && cmp -s "$tmp/t1/solutions" "$tmp/t$t/solutions"
  ok $? "THREADS = $t: branches.tsv and solutions the same bytes as THREADS = 1"
done
printf 'THREADS = -1\n' >> "$tmp/lrz-4.whirl"
(cd "$tmp" && "$WHIRL" run lrz-4.whirl --out=bad --quiet) >"$tmp/bad.out" 2>"$tmp/bad.err"
rc=$?
[ "$rc" -eq 2 ] && grep -q "lrz-4.whirl:[0-9]*: THREADS" "$tmp/bad.err" && [ ! -e "$tmp/bad" ]
ok $? "THREADS = -1: exit $rc, $(head -1 "$tmp/bad.err"), nothing written"
tap_end

#!/bin/sh
# test/regress/run_api.sh — a user's C program runs a run file through the
# library (whirl/run.h) with exactly the command's results: examples/run-api
# built with its two-line Makefile against the staged install, run on
# AUTO's demo ab (examples/auto/ab-1.whirl and ab-2.whirl, which restarts
# from the first), prints the same labelled rows as `whirl run` writes.
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-api.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

. "$top_srcdir/test/regress/stage.sh"

mkdir "$tmp/api" "$tmp/cmd"
cp "$top_srcdir/examples/run-api/run_api.c" "$top_srcdir/examples/run-api/Makefile" "$tmp/api/"
stage_make "$tmp/api" run_api > "$tmp/build.log" 2>&1
rc=$?
ok $rc "examples/run-api builds with pkg-config whirl against the staged install"
[ $rc -eq 0 ] || sed 's/^/# /' "$tmp/build.log"
lines=$(grep -cv '^ *\(/\*\| \*\|$\)' "$top_srcdir/examples/run-api/run_api.c")
[ "$lines" -le 30 ]
ok $? "the program is $lines lines of code (at most 30)"

# the demo's plug-in, for both (built against the staged headers)
for d in api cmd; do
  cp "$top_srcdir/examples/auto/ab.c" "$top_srcdir/examples/auto/ab-1.whirl" \
     "$top_srcdir/examples/auto/ab-2.whirl" "$tmp/$d/"
  ${CC:-cc} -std=c11 -shared -fPIC ${CFLAGS:-} -I"$incdir" -o "$tmp/$d/ab.so" "$tmp/$d/ab.c" \
    ${LDFLAGS:-} -lm 2>> "$tmp/build.log"
done
for run in ab-1 ab-2; do
  (cd "$tmp/api" && LD_LIBRARY_PATH="$stage$libdir" ./run_api $run.whirl > $run.rows 2> $run.err)
  rc=$?
  ok $rc "run_api $run.whirl exits 0"
  [ $rc -eq 0 ] || sed 's/^/# /' "$tmp/api/$run.err"
  (cd "$tmp/cmd" && LD_LIBRARY_PATH="$stage$libdir" "$whirl" run $run.whirl --quiet) 2> "$tmp/cmd.err"
  ok $? "whirl run $run.whirl exits 0"
  grep -v '^#' "$tmp/cmd/$run.out/branches.tsv" | awk -F'\t' 'NR > 1 && NF > 3 && $3 != "-"' > "$tmp/cmd/$run.rows"
  k=$(wc -l < "$tmp/cmd/$run.rows" | tr -d ' ')
  cmp -s "$tmp/api/$run.rows" "$tmp/cmd/$run.rows" && [ "$k" -ge 2 ]
  ok $? "$run: the program's $k labelled points equal whirl run's rows of branches.tsv"
  cmp -s "$tmp/api/$run.out/solutions" "$tmp/cmd/$run.out/solutions"
  ok $? "$run: and its labelled solutions file is whirl run's"
done
sed 's/^/# /' "$tmp/api/ab-1.rows"

echo "1..$n"
[ $fails -eq 0 ]

#!/bin/sh
# test/regress/failexit.sh — inputs out of range are refused up front (exit 2,
# one message naming the option and the valid range), runs that fail say so
# (exit 1, one line on stderr) and nothing the library or LAPACK prints ever
# reaches stdout.  Every command is bounded by `timeout` so that a regression
# (an endless run) fails the test instead of hanging it.
# SPDX-License-Identifier: BSD-3-Clause
set -u
WHIRL="$(cd "${top_builddir:-.}" && pwd)/drivers/whirl"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-failexit.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

# expect STATUS PATTERN CMD...: the command exits with STATUS within 20 s and
# its stderr matches PATTERN (a grep -E expression) on a single line.
expect() {
  want=$1; pattern=$2; shift 2
  timeout 20 "$WHIRL" "$@" > "$tmp/stdout" 2> "$tmp/stderr"
  rc=$?
  grep -Eq -- "$pattern" "$tmp/stderr"
  found=$?
  msg=$(tail -n 1 "$tmp/stderr")
  ok $(( rc != want || found != 0 )) "exit $rc (want $want): whirl $* : $msg"
}

cd "$tmp" || exit 1

# defect 4: an absurd thread count is refused, not a libgomp crash
expect 2 "threads must be in 0\.\.1024 \(got 100000\)" \
  sfd basins --omega 1.78 --points 20 --threads 100000 --no-plot --quiet --out b1
expect 2 "threads must be in 0\.\.1024 \(got -1\)" \
  sfd basins --omega 1.78 --points 20 --threads -1 --no-plot --quiet --out b1

# defect 8: tolerances so loose that integration crawls are refused
expect 2 "rtol must be in \[1e-13, 0\.001\] \(got 1\)" \
  sfd basins --omega 1.78 --points 20 --rtol 1 --no-plot --quiet --out b2
expect 2 "atol must be in \(0, 0\.001\] \(got 16\)" \
  sfd basins --omega 1.78 --points 20 --atol 16 --no-plot --quiet --out b2
for cmd in "simulate --omega 1.5 --out b3" "sweep --from 1 --to 1.1 --step 0.1 --out b3" \
           "onset --from 1 --to 2"; do
  # shellcheck disable=SC2086
  expect 2 "rtol must be in" sfd $cmd --rtol 0.5
done

echo "1..$n"
[ "$fails" -eq 0 ]

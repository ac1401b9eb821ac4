#!/bin/sh
# test/regress/cli.sh — the whirl command as a user meets it: help texts,
# bad input (a clear one-line message, a non-zero exit, no output written),
# and a full `whirl sfd response` run whose files are checked.
# SPDX-License-Identifier: BSD-3-Clause
set -u
WHIRL="${top_builddir:-.}/drivers/whirl"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-cli.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

for args in "--help" "sfd --help" "sfd response --help"; do
  # shellcheck disable=SC2086
  "$WHIRL" $args > "$tmp/help.txt" 2>&1
  rc=$?
  grep -q "usage" "$tmp/help.txt"
  ok $(( rc != 0 || $? != 0 )) "whirl $args prints usage and exits 0"
done

# bad input: message names the problem, exit status non-zero, nothing written
check_bad() {
  pattern=$1; shift
  out="$tmp/bad-out"
  rm -rf "$out"
  "$WHIRL" sfd response --out "$out" "$@" > "$tmp/stdout" 2> "$tmp/stderr"
  rc=$?
  msg=$(head -n 1 "$tmp/stderr")
  grep -q -- "$pattern" "$tmp/stderr"
  found=$?
  [ ! -e "$out" ]
  clean=$?
  ok $(( rc == 0 || found != 0 || clean != 0 )) "rejects $* : $msg"
}
check_bad "lambda" --lambda 0
check_bad "lambda" --lambda -1
check_bad "delta" --delta -0.2
check_bad "zeta" --zeta -0.5
check_bad "finite" --lambda nan
check_bad "expects a number" --delta abc
check_bad "must be a finite number" --lambda 1e999
check_bad "expects a number" --delta 0x1p-3
check_bad "expects a number" --delta " 0.2"
check_bad "expects a non-negative integer" --ntst " 20"
# a denormal is a number (the nearest double): the run goes on to the next check
check_bad "lambda" --zeta 1e-310 --lambda 0
check_bad "unknown option" --bogus
check_bad "needs a value" --lambda
check_bad "omega-min" --omega-max 0.001
check_bad "ds" --ds 0
"$WHIRL" frobnicate > /dev/null 2> "$tmp/stderr"; rc=$?
grep -q "unknown command" "$tmp/stderr"
ok $(( rc == 0 || $? != 0 )) "unknown command rejected"

# output directory that cannot be created
: > "$tmp/afile"
"$WHIRL" sfd response --no-plot --quiet --out "$tmp/afile/sub" > /dev/null 2> "$tmp/stderr"; rc=$?
grep -q "cannot create output directory" "$tmp/stderr"
ok $(( rc == 0 || $? != 0 )) "unwritable output directory: $(head -n 1 "$tmp/stderr")"

# the main job
out="$tmp/resp"
"$WHIRL" sfd response --out "$out" > "$tmp/special.out" 2> "$tmp/summary"
rc=$?
ok $rc "whirl sfd response (Table 1) exits 0"
head -n 1 "$tmp/special.out" | grep -q "^type	branch	label	Omega	eps"
ok $? "stdout is TSV with type, branch, Omega, eps"
nlp=$(awk -F'\t' '$1 == "LP"' "$tmp/special.out" | wc -l)
ok $(( nlp != 3 )) "stdout lists exactly three LP (got $nlp)"
cmp -s "$tmp/special.out" "$out/special.tsv"
ok $? "special.tsv equals stdout"
hdr=$(grep -v '^#' "$out/branches.tsv" | head -n 1)
miss=0
for col in branch Omega eps phase stable max_multiplier; do
  echo "$hdr" | tr '\t' '\n' | grep -qx "$col" || miss=1
done
ok $miss "branches.tsv has the columns branch Omega eps phase stable max_multiplier"
nbr=$(awk -F'\t' '!/^#/ && NF > 5 && $1 ~ /^[0-9]+$/ {print $1}' "$out/branches.tsv" | sort -u | wc -l)
ok $(( nbr != 2 )) "branches.tsv holds two branches (got $nbr)"
grep -q "2 branches" "$tmp/summary"
ok $? "summary reports the number of branches"
for png in response.png multipliers.png; do
  sig=$(head -c 4 "$out/$png" 2>/dev/null | od -An -c | tr -d ' ')
  [ "$sig" = "211PNG" ]
  ok $? "$png is a PNG"
done
ls -a "$out" | grep -q '\.tmp$'
ok $(( $? == 0 )) "no temporary files left in the output directory"

echo "1..$n"
[ "$fails" -eq 0 ]

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

# the sfd commands: `whirl sfd --help` and `whirl --help` list the same,
# every one of them
sfd_cmds=$("$WHIRL" sfd --help | sed -n 's/^  \([a-z][a-z]*\)   *[a-z].*/\1/p')
top_cmds=$("$WHIRL" --help | sed -n 's/^  sfd \([a-z][a-z]*\)   *[a-z].*/\1/p')
[ "$(echo $sfd_cmds)" = "response simulate sweep basins onset nonsync merge region" ] &&
  [ "$(echo $top_cmds)" = "$(echo $sfd_cmds)" ]
ok $? "whirl --help and whirl sfd --help list the eight sfd commands (got: $(echo $sfd_cmds); $(echo $top_cmds))"

# every sfd command's --help comes from its option table: each option it
# lists is one the command accepts (OPT or OPT=1, then an unknown option,
# so nothing runs), the defaults are the code's (those before the options
# given), and the SFD parameters show Table 1
for c in $sfd_cmds; do
  "$WHIRL" sfd $c --help > "$tmp/help.txt" 2>&1
  rc=$?
  # "  --name ARG  text": ARG an upper-case placeholder; flags have none
  opts=$(sed -n 's/^  \(--[a-z0-9-]*\)\( [A-Z][A-Z]*\)\{0,1\} .*/\1\2/p' "$tmp/help.txt" |
         sed 's/ [A-Z]*$/=1/' | grep -v '^--help$')
  bad=""
  for o in $opts; do
    "$WHIRL" sfd $c "$o" --no-such-option > /dev/null 2> "$tmp/stderr"
    grep -q "unknown option '--no-such-option'" "$tmp/stderr" || bad="$bad $o"
  done
  ok $(( rc != 0 )) "whirl sfd $c --help exits 0"
  [ -n "$opts" ] && [ -z "$bad" ]
  ok $? "whirl sfd $c accepts every option its --help lists ($(echo $opts | wc -w))${bad:+, not:$bad}"
done
"$WHIRL" sfd sweep --periods 7 --lambda 2 --help > "$tmp/help.txt"
grep -q -- "--periods N .*(600)" "$tmp/help.txt" && grep -q -- "--lambda L .*(0.0503)" "$tmp/help.txt"
ok $? "--help after options shows the defaults, not the values given"
miss=""
for c in response simulate sweep basins onset nonsync; do
  "$WHIRL" sfd $c --help > "$tmp/help.txt"
  grep -q -- "--lambda L .*(0.0503)" "$tmp/help.txt" && grep -q -- "--delta D .*(0.3)" "$tmp/help.txt" &&
    grep -q -- "--zeta Z .*(0)" "$tmp/help.txt" || miss="$miss $c"
done
[ -z "$miss" ]
ok $? "--help shows Table 1 (lambda 0.0503, delta 0.3, zeta 0)${miss:+; not in:$miss}"
"$WHIRL" sfd simulate --help | grep -q -- "--steady-from K .*(N/2)" &&
  "$WHIRL" sfd response --help | grep -q -- "--omega-min M .*(0.01; hbm/colloc 0.05)" &&
  "$WHIRL" sfd nonsync --help | grep -q -- "--ntst N .*(35)"
ok $? "--help shows computed defaults (simulate --steady-from, response --omega-min, nonsync --ntst)"

# the SFD parameters are checked alike by every command, before any work
check_param() {
  pattern=$1; shift
  rm -rf "$tmp/p-out"
  (cd "$tmp" && "$WHIRL" "$@" > stdout 2> stderr)
  rc=$?
  grep -q -- "$pattern" "$tmp/stderr"
  found=$?
  [ ! -e "$tmp/p-out" ] && [ ! -e "$tmp/sfd-region" ]
  ok $(( rc != 2 || found != 0 || $? != 0 )) "whirl $* : $(head -n 1 "$tmp/stderr")"
}
check_param "lambda is required" sfd merge
check_param "lambda must be in (0, 100\] (got 500)" sfd merge --lambda 500
check_param "zeta must be in \[0, 10\] (got 11)" sfd merge --lambda 0.25 --zeta 11
check_param "zeta must be in \[0, 10\] (got -1)" sfd region --zeta -1
check_param "lambda must be in (0, 100\] (got 200)" sfd nonsync --lambda 200 --out p-out
check_param "omega is required" sfd basins --out p-out
check_param "FE must be in (-1, 1)" sfd simulate --omega 2 --fe -1 --out p-out
check_param "delta must be in \[0, 10\] (got 11)" sfd onset --from 1 --to 2 --delta 11
check_param "zeta must be in \[0, 10\] (got 12)" sfd sweep --from 1 --to 2 --step 0.5 --zeta 12 --out p-out

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

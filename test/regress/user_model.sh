#!/bin/sh
# test/regress/user_model.sh — the user's path of doc/user-models.md: stage
# `make install` into a temporary DESTDIR, build examples/user-model (the
# Duffing plug-in) with its two-line Makefile through pkg-config, run the
# *installed* `whirl run duffing.whirl`, and check the result:
#   (1) with gamma = 0 (override --PAR=...) the oscillator is linear and its
#       response is harmonic, x = X cos(W t - phi) with amplitude
#       X = F / sqrt((1 - W^2)^2 + (2 zeta W)^2), so L2-NORM = sqrt(∫|u|² dτ)
#       = X sqrt((1 + W^2)/2) at the user point W = 1.2, to 1e-8;
#   (2) with the hardening spring the response bends over: two folds (LP)
#       and three responses at W = 1.2 (UZ), the middle one unstable;
#   (3) the outputs exist: branches.tsv, solutions, run.log, diagram.png.
# CC, CFLAGS and LDFLAGS in the environment (make check exports whirl's
# own) reach the example's make: a sanitized whirl needs them there.
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-um.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
command -v gnuplot >/dev/null 2>&1 || { echo "1..0 # SKIP gnuplot not installed"; exit 0; }

. "$top_srcdir/test/regress/stage.sh"
[ -d "$stage" ]
ok $? "make install DESTDIR=<tmp> stages whirl"

mkdir "$tmp/my"
cp "$top_srcdir/examples/user-model/duffing.c" "$top_srcdir/examples/user-model/Makefile" \
   "$top_srcdir/examples/user-model/duffing.whirl" "$tmp/my/"
stage_make "$tmp/my" > "$tmp/build.log" 2>&1
rc=$?
ok $rc "the plug-in builds with the two-line Makefile through pkg-config"
[ $rc -eq 0 ] || sed 's/^/# /' "$tmp/build.log"

(cd "$tmp/my" && LD_LIBRARY_PATH="$stage$libdir" "$whirl" run duffing.whirl \
   --PAR="{Omega: 0.5, gamma: 0}" --out=linear.out --quiet) 2> "$tmp/err"
ok $? "installed whirl runs the plug-in (gamma = 0)"
awk -F'\t' '$3 == "UZ" { W = $5; z = $6; F = $8; a = F / sqrt((1 - W*W)^2 + (2*z*W)^2) * sqrt((1 + W*W) / 2)
  e = $10 - a; if (e < 0) e = -e; k++; printf "# W = %s: L2-NORM = %s, closed form %.12g, error %.2e\n", W, $10, a, e
  if (e > 1e-8) bad = 1 } END { exit (bad || k != 1) }' "$tmp/my/linear.out/branches.tsv"
ok $? "linear response at the user point: L2-NORM = X sqrt((1 + W^2)/2), X = F / sqrt((1 - W^2)^2 + (2 zeta W)^2), to 1e-8"

(cd "$tmp/my" && LD_LIBRARY_PATH="$stage$libdir" "$whirl" run duffing.whirl --quiet) 2> "$tmp/err"
ok $? "whirl run duffing.whirl exits 0"
for f in branches.tsv solutions run.log diagram.png; do
  [ -s "$tmp/my/duffing.out/$f" ]
  ok $? "duffing.out/$f written"
done
awk -F'\t' '$3 == "LP" { lp++ } $3 == "UZ" { uz++; s = s $NF } END {
  printf "# %d LP, UZ stabilities %s\n", lp, s; exit !(lp == 2 && uz == 3 && s == "101") }' \
  "$tmp/my/duffing.out/branches.tsv"
ok $? "hardening response: 2 folds, 3 responses at W = 1.2 (stable, unstable, stable)"
echo "1..$n"
exit $fails

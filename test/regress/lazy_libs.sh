#!/bin/sh
# test/regress/lazy_libs.sh — the optional libraries configure found sonames
# for (UMFPACK, CHOLMOD, FFTW, ARPACK, SUNDIALS: config.h's
# WHIRL_SONAMES_*) are opened at their first use (whirl/dynlib.h), so the
# program and its two libraries must not list them as NEEDED: a process
# that never calls them does not load them (doc/benchmarks.md).  Then
# commands that do call them: a Campbell diagram by ARPACK from a rotor
# whose matrices are read by CHOLMOD, and a stiff integration by CVODE.
# SPDX-License-Identifier: BSD-3-Clause
name=lazy_libs
. "${top_srcdir:-.}/test/regress/tap.sh"
config=$top_builddir/config.h
case $top_builddir in /*) ;; *) config=$OLDPWD/$config ;; esac
sonames=$(sed -n 's/^#define WHIRL_SONAMES_[A-Z0-9]* "\(.*\)"$/\1/p' "$config" | tr ':' ' ')
if [ -z "$sonames" ]; then
  echo "1..0 # SKIP configure linked every library (--disable-lazy-libraries or no objdump)"
  exit 0
fi
objdump=${OBJDUMP:-objdump}
bin=$(dirname "$WHIRL")/.libs/whirl
[ -x "$bin" ] || bin=$WHIRL
for f in "$bin" "$(dirname "$WHIRL")/../lib/.libs/libwhirl.so" \
         "$(dirname "$WHIRL")/../rotor/.libs/libwhirl-rotor.so"; do
  needed=$("$objdump" -p "$f" 2> /dev/null | sed -n 's/^ *NEEDED *//p')
  [ -n "$needed" ]; ok $? "$(basename "$f"): objdump lists what it needs"
  for s in $sonames; do
    echo "$needed" | grep -qx "$s"
    [ $? -ne 0 ]; ok $? "$(basename "$f") does not need $s"
  done
done

# the libraries opened when called: ARPACK (the sparse eigenproblem) on a
# rotor written as Matrix Market files and read back (CHOLMOD)
rotor=$top_srcdir/examples/rotor/friswell-5.9.1.rotor
"$WHIRL" rotor modes "$rotor" --speed 0 --method arpack > arpack.tsv 2> err.txt
rc=$?
[ $rc -eq 0 ] && grep -q omega_rad_s arpack.tsv; ok $? "rotor modes by ARPACK: exit $rc $(head -c 200 err.txt)"
"$WHIRL" rotor modes "$rotor" --speed 0 --method dense > dense.tsv 2> /dev/null
a=$(awk -F'\t' 'NR == 2 {print $2}' arpack.tsv) d=$(awk -F'\t' 'NR == 2 {print $2}' dense.tsv)
awk -v a="$a" -v d="$d" 'BEGIN {exit !(a > 0 && (a - d) ^ 2 < (1e-8 * d) ^ 2)}'
ok $? "the first frequency by ARPACK equals the dense one ($a, $d)"
# CHOLMOD writes the matrices as Matrix Market files
"$WHIRL" rotor export "$rotor" -o mtx --quiet 2> err.txt
rc=$?
[ $rc -eq 0 ] && head -1 mtx/K.mtx | grep -q '^%%MatrixMarket'
ok $? "rotor export by CHOLMOD: exit $rc, mtx/K.mtx a Matrix Market file $(head -c 200 err.txt)"
tap_end

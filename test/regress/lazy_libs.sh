#!/bin/sh
# test/regress/lazy_libs.sh — the optional libraries configure found sonames
# for (UMFPACK, CHOLMOD, FFTW, ARPACK, SUNDIALS: config.h's
# WHIRL_SONAMES_*) are opened at their first use (whirl/dynlib.h), so the
# program and its two libraries must not list them as NEEDED: a process
# that never calls them does not load them (doc/benchmarks.md).  Then
# commands that do call them (eigenvalues by ARPACK, Matrix Market files
# by CHOLMOD), and with ARPACK and CVODE not loadable: the runs needing
# them fail cleanly (exit 1, the library named), the others run.
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

# a library that cannot be opened fails the runs that need it, with its
# name, exit 1 and nothing written, and no other run: a file that is no
# library first on the loader's path under the sonames of ARPACK and CVODE
arpack=$(echo "$sonames" | tr ' ' '\n' | grep '^libarpack' | head -1)
cvode=$(echo "$sonames" | tr ' ' '\n' | grep '^libsundials_cvode' | head -1)
if [ -n "$arpack" ] && [ -n "$cvode" ]; then
  mkdir broken
  echo "not a shared object" > "broken/$arpack"
  echo "not a shared object" > "broken/$cvode"
  LD_LIBRARY_PATH=$(pwd)/broken${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} \
    "$WHIRL" rotor modes "$rotor" --speed 0 --method arpack > b1.out 2> b1.err
  rc=$?
  [ $rc -eq 1 ] && [ ! -s b1.out ] && grep -q "$arpack could not be loaded" b1.err
  ok $? "ARPACK not loadable: rotor modes --method arpack exits 1, says so, prints nothing (exit $rc: $(head -c 160 b1.err))"
  LD_LIBRARY_PATH=$(pwd)/broken${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} \
    "$WHIRL" rotor simulate "$rotor" --speed 1000 --periods 2 --out sim --quiet > b2.out 2> b2.err
  rc=$?
  [ $rc -eq 1 ] && [ ! -e sim ] && grep -q "$cvode could not be loaded" b2.err
  ok $? "CVODE not loadable: rotor simulate (BDF) exits 1, says so, writes nothing (exit $rc: $(head -c 160 b2.err))"
  LD_LIBRARY_PATH=$(pwd)/broken${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} \
    "$WHIRL" sfd response --out resp --quiet > b3.out 2> b3.err
  rc=$?
  [ $rc -eq 0 ] && [ -s resp/branches.tsv ]
  ok $? "neither loadable: sfd response, which needs neither, runs (exit $rc)"
fi
tap_end

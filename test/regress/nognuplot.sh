#!/bin/sh
# test/regress/nognuplot.sh — whirl without gnuplot (not installed, or
# configured --without-gnuplot: the same path): every command exits as it
# would with its pictures (0 here), says once that the pictures were
# skipped, writes their .gp scripts and no picture, and no summary claims
# one; --no-plot stays silent about pictures.
# SPDX-License-Identifier: BSD-3-Clause
name=nognuplot
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples"
export WHIRL_GNUPLOT="$tmp/no/such/gnuplot"

# check LABEL DIR ARGS...: ARGS run with their output in DIR
check() {
  label=$1 out=$2
  shift 2
  "$@" > "$out.stdout" 2> "$out.stderr"
  rc=$?
  skipped=$(grep -c "pictures skipped" "$out.stderr")
  pics=$(ls "$out" 2> /dev/null | grep -c '\.\(png\|pdf\|svg\)$')
  gps=$(ls "$out" 2> /dev/null | grep -c '\.gp$')
  claims=$(grep -v "pictures skipped" "$out.stderr" "$out.stdout" | grep -c '\.png\|PNG\|the pictures')
  [ $rc -eq 0 ] && [ "$skipped" -eq 1 ] && [ "$pics" -eq 0 ] && [ "$gps" -ge 1 ] && [ "$claims" -eq 0 ]
  ok $? "$label: exit $rc, 'pictures skipped' said $skipped time(s), $gps scripts, $pics pictures, $claims claims of a picture"
}
check "sfd response" resp "$WHIRL" sfd response --out resp
check "sfd simulate" sim "$WHIRL" sfd simulate --omega 1.78 --periods 20 --out sim
check "sfd nonsync" ns "$WHIRL" sfd nonsync --omega-max 10 --omega-min 7 --out ns
check "rotor response" rr "$WHIRL" rotor response "$ex/rotor/rigid-limit.rotor" --harmonics 3 --stability off --out rr
check "whirl run" run "$WHIRL" run "$ex/discover/sfd-rotating.whirl" --out=run

"$WHIRL" sfd response --out np --no-plot > np.stdout 2> np.stderr
rc=$?
[ $rc -eq 0 ] && ! grep -q "pictures skipped" np.stderr
ok $? "sfd response --no-plot: exit $rc, nothing said about pictures"
tap_end

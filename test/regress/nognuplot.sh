#!/bin/sh
# test/regress/nognuplot.sh — whirl without gnuplot (not installed, or
# configured --without-gnuplot: the same path): every command exits as it
# would with its pictures (0 here) and writes their .gp scripts; the PNGs
# whirl draws itself (doc/output-directories.md) are drawn, and the summary
# names them; a command with pictures only gnuplot draws says once that
# they were skipped, writes none and no summary claims one; --no-plot stays
# silent about pictures.
# SPDX-License-Identifier: BSD-3-Clause
name=nognuplot
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples"
export WHIRL_GNUPLOT="$tmp/no/such/gnuplot"

# check LABEL DIR HERE ARGS...: ARGS run with their output in DIR; HERE of
# its pictures are ones whirl draws itself (PNG), the rest need gnuplot
check() {
  label=$1 out=$2 here=$3
  shift 3
  "$@" > "$out.stdout" 2> "$out.stderr"
  rc=$?
  skipped=$(grep -c "pictures skipped" "$out.stderr")
  pics=$(ls "$out" 2> /dev/null | grep -c '\.\(png\|pdf\|svg\)$')
  gps=$(ls "$out" 2> /dev/null | grep -c '\.gp$')
  claims=$(grep -v "pictures skipped" "$out.stderr" "$out.stdout" | grep -c '\.png\|PNG\|the pictures')
  # every picture drawn here: none skipped (and the summary may name
  # them); else skipped, said once, and none claimed
  want_skip=1
  [ "$here" -eq "$gps" ] && want_skip=0
  [ $rc -eq 0 ] && [ "$skipped" -eq $want_skip ] && [ "$pics" -eq "$here" ] &&
    [ "$gps" -ge 1 ] && { [ $want_skip -eq 0 ] || [ "$claims" -eq 0 ]; }
  ok $? "$label: exit $rc, 'pictures skipped' said $skipped time(s), $gps scripts, $pics pictures ($here drawn by whirl itself expected), $claims summary lines naming a picture"
}
check "sfd response" resp 2 "$WHIRL" sfd response --out resp
check "sfd simulate" sim 1 "$WHIRL" sfd simulate --omega 1.78 --periods 20 --out sim
check "sfd nonsync" ns 1 "$WHIRL" sfd nonsync --omega-max 10 --omega-min 7 --out ns
check "rotor response" rr 1 "$WHIRL" rotor response "$ex/rotor/rigid-limit.rotor" --harmonics 3 --stability off --out rr
check "whirl run" run 1 "$WHIRL" run "$ex/discover/sfd-rotating.whirl" --out=run
# WHIRL_DRAW=gnuplot: every picture is gnuplot's, so none is drawn
WHIRL_DRAW=gnuplot check "sfd response, WHIRL_DRAW=gnuplot" resp-gp 0 "$WHIRL" sfd response --out resp-gp

"$WHIRL" sfd response --out np --no-plot > np.stdout 2> np.stderr
rc=$?
[ $rc -eq 0 ] && ! grep -q "pictures skipped" np.stderr
ok $? "sfd response --no-plot: exit $rc, nothing said about pictures"
tap_end

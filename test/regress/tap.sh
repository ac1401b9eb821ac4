# test/regress/tap.sh — sourced by the command-line tests of the rotor
# commands after they set `name` (the temporary directory's stem): makes
# top_builddir, top_srcdir and WHIRL (the command under test) absolute,
# creates the temporary directory tmp (removed on exit) and enters it, and
# defines ok STATUS TEXT (a TAP line; counts n and fails) and tap_end (the
# plan, and the exit status).
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
WHIRL="$top_builddir/drivers/whirl"
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
case $top_srcdir in /*) ;; *) top_srcdir="$(pwd)/$top_srcdir" ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-$name.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
tap_end() {
  echo "1..$n"
  [ "$fails" -eq 0 ]
}

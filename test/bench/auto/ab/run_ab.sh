#!/bin/sh
# run_ab.sh — run AUTO-07p on our equation files for its demos 'ab'
# (stationary runs) and 'cusp', print every labelled point with all the digits
# of AUTO's b-files, and compare with AUTO's published regression log
# (published.txt).  See doc/auto-reference.md.
# usage: test/bench/auto/ab/run_ab.sh [--keep]
# Needs /usr/bin/python3, AUTO-07p (AUTO_DIR, default /usr/lib/auto-07p),
# gcc and gfortran.  Exits non-zero with a message on failure.
# SPDX-License-Identifier: BSD-3-Clause
set -eu
PY=/usr/bin/python3
KEEP=
case "${1:-}" in
  --keep) KEEP=1 ;;
  '') ;;
  *) echo "run_ab.sh: unknown argument: $1" >&2; exit 2 ;;
esac
die() { echo "run_ab.sh: error: $*" >&2; exit 1; }
AUTO_DIR=${AUTO_DIR:-/usr/lib/auto-07p}
export AUTO_DIR
[ -x "$PY" ] || die "$PY not found"
[ -f "$AUTO_DIR/python/auto/__main__.py" ] || die "AUTO-07p not found in $AUTO_DIR"
SRC=$(cd "$(dirname "$0")" && pwd)
WORK=$(mktemp -d "${TMPDIR:-/tmp}/whirl-auto-ab.XXXXXX") || die "mktemp failed"
if [ -z "$KEEP" ]; then trap 'rm -rf "$WORK"' EXIT; fi
trap 'exit 1' HUP INT PIPE TERM
cp "$SRC"/ab.c "$SRC"/c.ab.1 "$SRC"/c.ab.2 "$SRC"/ab.auto \
   "$SRC"/cusp.c "$SRC"/c.cusp "$SRC"/cusp.auto \
   "$SRC"/points.py "$SRC"/published.txt "$WORK/" || die "copy failed"
cd "$WORK"
for demo in ab cusp; do
  "$PY" "$AUTO_DIR/python/auto/__main__.py" "$demo.auto" > "$demo.log" 2>&1 \
    || die "AUTO failed on $demo.auto (log: $WORK/$demo.log; use --keep)"
done
for f in b.start b.ab b.mu b.cusp; do
  [ -s "$f" ] || die "AUTO wrote no $f (see $WORK/*.log; use --keep)"
done
"$PY" points.py list b.start b.ab b.mu b.cusp
"$PY" points.py compare published.txt
if [ -n "$KEEP" ]; then echo "work directory: $WORK"; fi

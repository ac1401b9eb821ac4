#!/bin/sh
# test/regress/diskfull.sh — a full disk at every fill level (issue 14,
# defect 5).  Each command writes its output into a small tmpfs that a
# filler file leaves K pages free, for every K from 0 to what the output
# needs (+2): the run either succeeds with every file byte-identical to a
# run on an ordinary disk, or fails with a message on stderr and a non-zero
# exit, leaving no partial file: whatever it kept (the tables, when only a
# picture did not fit) is complete, and no temporary is left (a command's
# checkpoint, its state to resume from, may stay after a failure).
#
# Needs root for the tmpfs, mounted in a private mount namespace
# (unshare -m) so that it vanishes with the test; skipped otherwise.
# SPDX-License-Identifier: BSD-3-Clause
set -u
if [ -z "${WHIRL_DISKFULL_NS:-}" ]; then
  if [ "$(id -u)" != 0 ] || ! command -v unshare > /dev/null 2>&1 ||
     ! unshare -m --propagation private true 2> /dev/null; then
    echo "1..0 # SKIP needs root and unshare -m for a private tmpfs"
    exit 0
  fi
  WHIRL_DISKFULL_NS=1 exec unshare -m --propagation private sh "$0" "$@"
fi
WHIRL="$(cd "${top_builddir:-.}" && pwd)/drivers/whirl"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-diskfull.XXXXXX")
mnt="$tmp/mnt"
mkdir "$mnt"
trap 'umount "$mnt" 2> /dev/null; rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
diag() { sed 's/^/#   /' "$1"; }
cd "$tmp" || exit 1
PAGE=4096

cp "${top_srcdir:-$OLDPWD}/test/regress/sfd-small.whirl" small.whirl || exit 1
cp "${top_srcdir:-$OLDPWD}/examples/rotor/friswell-5.9.1.rotor" \
   "${top_srcdir:-$OLDPWD}/examples/rotor/rigid-limit.rotor" . || exit 1

# pages the files of DIR take on tmpfs (each file a whole number of pages)
pages_of() {
  total=0
  for f in "$1"/* "$1"/.[!.]*; do
    [ -f "$f" ] || continue
    s=$(stat -c %s "$f")
    total=$(( total + (s + PAGE - 1) / PAGE ))
  done
  echo $total
}

# Is every file of the output OUT identical to the reference REF (run.log:
# complete, as its wall time is not repeatable)?  ALL: every file present.
same_as_ref() {
  out=$1 ref=$2 all=$3
  for f in "$out"/* "$out"/.[!.]*; do
    [ -e "$f" ] || continue
    b=$(basename "$f")
    [ -f "$ref/$b" ] || { echo "#   unexpected file $b"; return 1; }
    if [ "$b" = .whirl-output ]; then # the manifest: the files present
      (cd "$out" && ls -A | grep -vx '\.whirl-output' | sort) > have.txt
      grep -v '^#' "$f" | sort > listed.txt
      cmp -s have.txt listed.txt || { echo "#   the manifest lists other files"; return 1; }
    elif [ "$b" = run.log ]; then
      grep -q "^wall time" "$f" || { echo "#   run.log incomplete"; return 1; }
    else
      cmp -s "$f" "$ref/$b" || { echo "#   $b differs from the reference"; return 1; }
    fi
  done
  [ "$all" = 1 ] || return 0
  for f in "$ref"/* "$ref"/.[!.]*; do
    [ -e "$f" ] || continue
    [ -e "$out/$(basename "$f")" ] || { echo "#   $(basename "$f") missing"; return 1; }
  done
}

run_with_out() { # OUT CMD... : the command with @OUT@ replaced by OUT
  o=$1
  shift
  args=""
  for a in "$@"; do
    a=$(printf '%s' "$a" | sed "s|@OUT@|$o|g")
    args="$args '$(printf '%s' "$a" | sed "s/'/'\\\\''/g")'"
  done
  eval "$args" > /dev/null 2> err.txt
}

check_command() {
  name=$1
  shift
  ref="$tmp/ref-$name"
  run_with_out "$ref" "$@"
  rc=$?
  ok $rc "$name: reference run on an ordinary disk"
  [ $rc -eq 0 ] || { diag err.txt; return; }
  need=$(pages_of "$ref")
  need=$(( need + ${EXTRA:-0} )) # and a checkpoint beside the output while it is written
  size=$(( need + 3 ))
  mount -t tmpfs -o size=$(( size * PAGE )),nr_inodes=64 tmpfs "$mnt" || {
    ok 1 "$name: mount a tmpfs"
    return
  }
  good=0 failed=0 bad=0
  k=0
  while [ $k -le $(( need + 2 )) ]; do
    rm -rf "${mnt:?}"/* "$mnt"/.[!.]* 2> /dev/null
    # the filler leaves k pages free (a failed dd at k = size is fine)
    dd if=/dev/zero of="$mnt/filler" bs=$PAGE count=$(( size - k )) 2> /dev/null
    run_with_out "$mnt/out" "$@"
    rc=$?
    left=$(cd "$mnt" && find . -mindepth 1 ! -name filler ! -path ./out ! -path './out/*')
    why=""
    if [ $rc -eq 0 ]; then
      same_as_ref "$mnt/out" "$ref" 1 > why.txt || why="exit 0 but: $(tr '\n' ' ' < why.txt)"
      [ -z "$left" ] || why="exit 0, left: $left"
    else
      [ -s err.txt ] || why="exit $rc with nothing on stderr"
      # a command's checkpoint (KEEP) is its resume state, not a temporary
      [ -z "${KEEP:-}" ] || [ "$left" != "./$KEEP" ] || left=""
      [ -z "$left" ] || why="exit $rc, left: $left"
      if [ -d "$mnt/out" ]; then
        same_as_ref "$mnt/out" "$ref" 0 > why.txt || why="exit $rc, kept a partial file: $(tr '\n' ' ' < why.txt)"
      fi
    fi
    if [ -n "$why" ]; then
      bad=$((bad + 1))
      echo "# $name, $k pages free: $why"
      sed 's/^/#   stderr: /' err.txt | head -n 3
    elif [ $rc -eq 0 ]; then
      good=$((good + 1))
    else
      failed=$((failed + 1))
      [ $failed -eq 1 ] && msg=$(head -n 1 err.txt)
    fi
    k=$((k + 1))
  done
  umount "$mnt"
  ok $(( bad != 0 || good == 0 || failed == 0 )) "$name: $((need + 3)) fill levels (0..$((need + 2)) pages free, output $need pages): $good complete, $failed failed cleanly, $bad wrong; e.g. ${msg:-}"
}

check_command "sfd response" "$WHIRL" sfd response --out @OUT@ --quiet
# whirl sfd basins keeps out.checkpoint until the output is written (a run
# that fails keeps it, to be resumed: doc/parameter-studies.md)
EXTRA=8 KEEP=out.checkpoint check_command "sfd basins" "$WHIRL" sfd basins --omega 1.78 --points 40 --out @OUT@ --quiet
unset EXTRA KEEP
check_command "sfd nonsync" "$WHIRL" sfd nonsync --out @OUT@ --quiet
check_command "sfd sweep" "$WHIRL" sfd sweep --from 1 --to 1.4 --step 0.1 --out @OUT@ --quiet
check_command "sfd region" "$WHIRL" sfd region --out @OUT@ --quiet
check_command "sfd simulate" "$WHIRL" sfd simulate --omega 3 --periods 8 --samples 16 --out @OUT@ --quiet
check_command "whirl run" "$WHIRL" run small.whirl --OUT=@OUT@ --quiet
check_command "rotor campbell" "$WHIRL" rotor campbell friswell-5.9.1.rotor --speeds 0:4000:5 -o @OUT@ --quiet
check_command "rotor response" "$WHIRL" rotor response rigid-limit.rotor --harmonics 1 --stability off --to 2000 --unit rad/s -o @OUT@ --quiet
check_command "rotor export" "$WHIRL" rotor export friswell-5.9.1.rotor -o @OUT@ --quiet

echo "1..$n"
[ $fails -eq 0 ]

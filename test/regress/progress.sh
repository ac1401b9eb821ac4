#!/bin/sh
# test/regress/progress.sh — the progress line in a real terminal (a tmux
# pane on a private server): `whirl sfd sweep`, `basins`, `simulate`,
# `nonsync` and a long `whirl run` continuation, each run twice into the
# same output directory, once with stdout and stderr redirected to files and
# once with stderr the pane's terminal and stdout a file.  Checked: both
# exit 0; the terminal run's stdout is byte for byte the other's (no
# progress on stdout); the pane got a progress line with an ETA, drawn in
# place (carriage return and clear to the end of the line) and cleared after
# its last update; the non-terminal run wrote no progress; with --quiet the
# pane gets none; and with stdout in the pane too, every row of sfd sweep
# starts its own screen line (no progress glued to it).
# SPDX-License-Identifier: BSD-3-Clause
name=progress
. "${top_srcdir:-.}/test/regress/tap.sh"
if ! command -v tmux > /dev/null 2>&1; then
  echo "1..0 # SKIP tmux is not installed"
  exit 0
fi
sock="whirl-progress-$$"
tm() { tmux -f /dev/null -L "$sock" "$@"; }
trap 'tm kill-server > /dev/null 2>&1; rm -rf "$tmp"' EXIT
esc=$(printf '\033')
cr=$(printf '\r')

# quoted ARGS... as one line of sh
quote() { for a in "$@"; do printf "'%s' " "$(printf '%s' "$a" | sed "s/'/'\\\\''/g")"; done; }

# in_pane NAME REDIRECT ARGS...: whirl ARGS in a new pane of 160 x 20 with
# REDIRECT (e.g. '> NAME.tty.stdout'), the pane's bytes into NAME.raw, its
# exit status into NAME.rc; the pane stays (remain-on-exit) for a capture
in_pane() {
  nm=$1 redir=$2
  shift 2
  rm -f "$nm.go" "$nm.rc" "$nm.raw"
  {
    echo "while [ ! -e '$tmp/$nm.go' ]; do sleep 0.05; done"
    echo "cd '$tmp' && $(quote "$WHIRL" "$@") $redir"
    echo "echo \$? > '$tmp/$nm.rc.tmp' && mv '$tmp/$nm.rc.tmp' '$tmp/$nm.rc'"
  } > "$nm.sh"
  tm new-session -d -s "$nm" -x 160 -y 20 "sh '$tmp/$nm.sh'; sleep 600"
  tm pipe-pane -t "$nm" -o "cat > '$tmp/$nm.raw'"
  # the pane's bytes reach the file only once its cat runs (the shell
  # creates the file then): until then they are lost — under load the first
  # run's progress was (make -j2 check, twice in a day)
  k=0
  while [ ! -e "$nm.raw" ] && [ $k -lt 100 ]; do sleep 0.05; k=$((k + 1)); done
  touch "$nm.go"
  k=0
  while [ ! -e "$nm.rc" ] && [ $k -lt 1200 ]; do sleep 0.1; k=$((k + 1)); done
  sleep 0.3
}

# check NAME ARGS...: the two runs of ARGS and their checks
check() {
  nm=$1
  shift
  "$WHIRL" "$@" > "$nm.plain.stdout" 2> "$nm.plain.stderr"
  prc=$?
  in_pane "$nm" "> '$tmp/$nm.tty.stdout'" "$@"
  trc=$(cat "$nm.rc" 2> /dev/null || echo timeout)
  tm kill-session -t "$nm" > /dev/null 2>&1
  [ $prc -eq 0 ] && [ "$trc" = 0 ]
  ok $? "$nm: whirl $* exits 0 with and without a terminal (got $prc, $trc)"
  cmp -s "$nm.plain.stdout" "$nm.tty.stdout" && [ -s "$nm.tty.stdout" ] &&
    ! grep -q "ETA\|$cr\|$esc" "$nm.tty.stdout"
  ok $? "$nm: stdout with stderr on the terminal = stdout without ($(wc -l < "$nm.tty.stdout") lines)"
  # the progress line: "\r\033[K... ETA <digit>", and after the last one a
  # "\r\033[K" that clears it
  tr "$cr" '\n' < "$nm.raw" > "$nm.lines"
  grep -q "^$esc\[K.*: [0-9]*/[0-9]* ([0-9]*%), ETA [0-9]" "$nm.lines" &&
    awk -v e="$esc" '/ETA/ { last = NR } $0 == e "[K" || index($0, e "[K") == 1 && !/ETA/ { clr = NR }
      END { exit !(last > 0 && clr > last) }' "$nm.lines"
  ok $? "$nm: a progress line with an ETA on the terminal, drawn in place and cleared: $(grep -a 'ETA' "$nm.lines" | tail -n 1 | tr -d "$esc" | head -c 100)"
  ! grep -q "ETA" "$nm.plain.stderr"
  ok $? "$nm: no progress when stderr is not a terminal"
}

# ~2 s (at DS 0.0001 it took 0.55 s on a fast day, close to the 0.5 s
# before the line is drawn, and the check failed)
printf 'model = sfd-rotating\nIPS = 1\nICP = [Omega]\nPAR = {Omega: 0.5}\nU = {u: 0.1}\nNMX = 1000000\nDS = 0.00003\nDSMAX = 0.00003\nRL1 = 8\n' > long.whirl
# long enough for the line to appear (it is drawn after 0.5 s): 0.46 s at
# --step 0.04 --periods 300 on a fast day, and the check failed
check sweep sfd sweep --from 1 --to 3 --step 0.02 --periods 600 --direction up --out sweep.d --no-plot
check basins sfd basins --omega 1.78 --points 250 --out basins.d --no-plot
check simulate sfd simulate --omega 8.7 --periods 3000 --out simulate.d --no-plot
check nonsync sfd nonsync --omega-max 12 --omega-min 4 --ds 0.002 --ds-max 0.002 --out nonsync.d --no-plot
check run run long.whirl --OUT=long.out

# --quiet: no progress on the terminal either
in_pane quiet "> '$tmp/quiet.stdout'" sfd basins --omega 1.78 --points 100 --out quiet.d --no-plot --quiet
[ "$(cat quiet.rc 2> /dev/null)" = 0 ] && ! grep -q "ETA" quiet.raw
ok $? "--quiet: no progress line on the terminal"
tm kill-session -t quiet > /dev/null 2>&1

# stdout on the terminal too: the sweep's rows each on a line of their own
in_pane both "" sfd sweep --from 1 --to 3 --step 0.1 --periods 300 --direction up --out both.d --no-plot
tm capture-pane -p -S - -t both > both.screen 2> /dev/null
rows=$(grep -c "^up " both.screen)
bad=$(grep "up	\|up " both.screen | grep -vc "^up ")
[ "$(cat both.rc 2> /dev/null)" = 0 ] && [ "$rows" -ge 10 ] && [ "$bad" -eq 0 ]
ok $? "stdout and stderr on one terminal: $rows sweep rows, each at the start of its line ($bad not)"
tm kill-session -t both > /dev/null 2>&1
tap_end

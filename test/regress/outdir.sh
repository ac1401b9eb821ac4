#!/bin/sh
# test/regress/outdir.sh — nothing a user owns is lost, nothing is injected,
# nothing is left half-written (issue 14, defects 1, 3, 5, 6 and 9):
#   - replacing an output directory (whirl run and the sfd commands): from
#     inside it, with a trailing slash, through a symbolic link, with the
#     user's own files in it, '.', '..', '/';
#   - file names that would inject gnuplot (and shell) commands;
#   - a gnuplot that exits 0 without writing its picture;
#   - SIGINT and SIGTERM during a run, and the temporaries of a run killed
#     with SIGKILL, removed by the next run;
#   - a rerun with --no-plot keeps no picture of the run before.
# SPDX-License-Identifier: BSD-3-Clause
set -u
WHIRL="$(cd "${top_builddir:-.}" && pwd)/drivers/whirl"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-outdir.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }
diag() { sed 's/^/#   /' "$1"; }
cd "$tmp" || exit 1

# a small run of the built-in rotor: circular orbits, 30 steps in Omega
cp "${top_srcdir:-$OLDPWD}/test/regress/sfd-small.whirl" small.whirl || exit 1
complete_run() { # DIR: a complete whirl run output
  [ -s "$1/branches.tsv" ] && [ -s "$1/solutions" ] && [ -s "$1/run.log" ] &&
    [ -s "$1/diagram.png" ] && grep -q "^wall time" "$1/run.log"
}
no_temps() { # nothing named *.tmp.* or *.old.* below DIR
  [ -z "$(find "$1" -name '*.tmp.*' -o -name '*.old.*' -o -name '.*.tmp')" ]
}

"$WHIRL" run small.whirl --quiet > /dev/null 2> err.txt
rc=$?
complete_run small.out
ok $(( rc != 0 || $? != 0 )) "control: whirl run small.whirl writes small.out/"
[ $rc -eq 0 ] || diag err.txt

# ---- 1. replacing an output directory -------------------------------------
# from inside an earlier output: '.' is refused, the user's files stay
cp small.whirl small.out/notes.whirl
echo "my notes" > small.out/notes.txt
(cd small.out && "$WHIRL" run ../small.whirl --OUT=. --quiet > /dev/null 2> ../err.txt)
rc=$?
[ $rc -eq 2 ] && [ -f small.out/notes.txt ] && [ -f small.out/notes.whirl ] &&
  [ -f small.out/branches.tsv ] && grep -q "'\.' cannot be an output directory" err.txt
ok $? "OUT=. inside an earlier output: refused (exit $rc), every file kept: $(head -n 1 err.txt)"
(cd small.out && "$WHIRL" run ../small.whirl --OUT=../small.out --quiet > /dev/null 2> ../err.txt)
rc=$?
[ $rc -eq 2 ] && [ -f small.out/notes.txt ] && grep -q "working directory" err.txt
ok $? "OUT=../small.out from inside it: refused (exit $rc): $(head -n 1 err.txt)"
for bad in .. / ./ "$tmp/small.out/.."; do
  "$WHIRL" run small.whirl "--OUT=$bad" --quiet > /dev/null 2> err.txt
  rc=$?
  [ $rc -eq 2 ] && [ -f small.whirl ] && [ -f small.out/notes.txt ]
  ok $? "OUT=$bad refused (exit $rc): $(head -n 1 err.txt)"
done

# the user's own files in an earlier output: refused, nothing lost
mkdir small.out/figures && echo plot > small.out/figures/fig.txt
"$WHIRL" run small.whirl --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 2 ] && [ -f small.out/notes.txt ] && [ -f small.out/figures/fig.txt ] &&
  [ -f small.out/branches.tsv ] && grep -q "did not write" err.txt
ok $? "earlier output with analysis files and a folder: refused (exit $rc), all kept: $(head -n 1 err.txt)"
rm -r small.out/notes.txt small.out/notes.whirl small.out/figures

# a trailing slash: the earlier output is replaced whole
"$WHIRL" run small.whirl --OUT=small.out/ --quiet > /dev/null 2> err.txt
rc=$?
complete_run small.out
ok $(( rc != 0 || $? != 0 )) "OUT=small.out/ (trailing slash) replaces the earlier output whole (exit $rc)"
"$WHIRL" run small.whirl --OUT=fresh/ --quiet > /dev/null 2> err.txt
rc=$?
complete_run fresh
ok $(( rc != 0 || $? != 0 )) "OUT=fresh/ on a new directory (exit $rc)"

# a symbolic link to an earlier output: the link is kept, its target replaced
mkdir -p real && "$WHIRL" run small.whirl --OUT=real/a --quiet > /dev/null 2>&1
ln -s real/a link
sed -i 's/^wall time.*/wall time OLD/' real/a/run.log
"$WHIRL" run small.whirl --OUT=link --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ -L link ] && complete_run real/a && ! grep -q OLD real/a/run.log
ok $? "OUT=link (a symlink to an earlier output): link kept, target replaced (exit $rc)"
ln -s nowhere dangling
"$WHIRL" run small.whirl --OUT=dangling --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 2 ] && [ -L dangling ] && grep -q "symbolic link" err.txt
ok $? "OUT=dangling symlink refused (exit $rc): $(head -n 1 err.txt)"
: > afile
"$WHIRL" run small.whirl --OUT=afile --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 2 ] && [ -f afile ] && [ ! -s afile ]
ok $? "OUT naming a file refused (exit $rc): $(head -n 1 err.txt)"
no_temps .
ok $? "no temporary directory or file left by any of these runs"

# the sfd commands: same rule; a rerun with --no-plot keeps no old picture
"$WHIRL" sfd response --out resp --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ -s resp/response.png ] && [ -s resp/special.tsv ]
ok $? "control: sfd response writes resp/ with its pictures (exit $rc)"
"$WHIRL" sfd response --out resp --no-plot --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ ! -e resp/response.png ] && [ ! -e resp/response.gp ] && [ -s resp/branches.tsv ]
ok $? "sfd response --no-plot over an earlier output: no stale picture left (exit $rc)"
echo "keep" > resp/mine.txt
"$WHIRL" sfd response --out resp --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 2 ] && [ -f resp/mine.txt ] && [ -s resp/branches.tsv ]
ok $? "sfd response over a directory with the user's file: refused, kept (exit $rc): $(head -n 1 err.txt)"
mkdir -p old-style && echo "x" > old-style/branches.tsv && echo "y" > old-style/.response.png.tmp
"$WHIRL" sfd response --out old-style --no-plot --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ ! -e old-style/.response.png.tmp ] && [ -s old-style/special.tsv ]
ok $? "an output of an earlier version (no manifest) is recognised and replaced (exit $rc)"
mkdir -p "$tmp/emptydir"
"$WHIRL" sfd simulate --omega 3 --periods 8 --no-plot --out emptydir --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ -s emptydir/history.tsv ]
ok $? "an empty directory is a valid output directory (exit $rc)"

# I/O errors exit 1, bad input 2: a run file that cannot be read, one missing
mkdir -p dir.whirl
"$WHIRL" run dir.whirl > /dev/null 2> err.txt
rc=$?
"$WHIRL" run missing.whirl > /dev/null 2> err2.txt
rc2=$?
[ $rc -eq 1 ] && [ $rc2 -eq 2 ] && [ -s err.txt ] && [ -s err2.txt ]
ok $? "unreadable run file: exit $rc (I/O, want 1); missing run file: exit $rc2 (want 2): $(head -n 1 err.txt)"

# ---- 3. nothing injected through names -------------------------------------
inj="x';system('touch INJECTED');print '.whirl"
cp small.whirl "$inj"
"$WHIRL" run "$inj" --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ ! -e INJECTED ] && [ -s "x';system('touch INJECTED');print '.out/diagram.png" ]
ok $? "a run file named with a quote and system(): no command run, picture drawn (exit $rc)"
nl="y
!touch INJECTED2
.whirl"
cp small.whirl "$nl"
"$WHIRL" run "$nl" --OUT=nl.out --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ ! -e INJECTED2 ] && [ -s nl.out/diagram.png ]
ok $? "a run file named with a newline and !cmd: no command run (exit $rc)"
# parameter names go into axis labels: a plug-in is not needed, the
# title and labels of every script are quoted; check the script itself
grep -q "^set title 'whirl run: x'';system(''touch INJECTED'');print ''.whirl" \
  "x';system('touch INJECTED');print '.out/diagram.gp"
ok $? "the quote is doubled inside the gnuplot string"

# ---- 5. a picture gnuplot could not write is not kept ----------------------
cat > fakegp << 'EOF'
#!/bin/sh
# writes the first bytes of a PNG, as gnuplot does on a full disk, and exits 0
out=$(sed -n "s/^set output '\(.*\)'$/\1/p" "$1" | head -n 1)
printf '\211PNG\r\n\032\n\000\000' > "$out"
exit 0
EOF
chmod +x fakegp
WHIRL_DRAW=gnuplot WHIRL_GNUPLOT="$tmp/fakegp" "$WHIRL" sfd response --out trunc --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 1 ] && [ ! -e trunc/response.png ] && [ -s trunc/special.tsv ] &&
  [ -s trunc/response.gp ] && grep -q "incomplete" err.txt
ok $? "gnuplot exits 0 but writes a truncated PNG: exit $rc, no picture kept, tables kept: $(head -n 1 err.txt)"
WHIRL_DRAW=gnuplot WHIRL_GNUPLOT="$tmp/fakegp" "$WHIRL" run small.whirl --OUT=trunc-run --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 1 ] && [ ! -e trunc-run/diagram.png ] && [ -s trunc-run/branches.tsv ] && grep -q "incomplete" err.txt
ok $? "whirl run likewise: exit $rc, no picture: $(head -n 1 err.txt)"
no_temps .
ok $? "no temporary left after the failed pictures"

# ---- 6. signals, and the temporaries of killed runs ------------------------
# a run that takes seconds; interrupted once its staging directory exists
interrupt() { # SIGNAL DIR CMD...: start, wait for DIR.tmp.PID (or 0.5 s
  sig=$1 dir=$2  # when DIR is -: the basins stage only while writing), signal
  shift 2
  "$@" > /dev/null 2>&1 &
  pid=$!
  k=0
  [ "$dir" = - ] && k=190
  while [ ! -d "$dir.tmp.$pid" ] && [ $k -lt 200 ]; do sleep 0.05; k=$((k + 1)); done
  sleep 0.2
  kill "-$sig" "$pid"
  wait "$pid"
  echo $?
}
rc=$(interrupt INT sweep-int "$WHIRL" sfd sweep --from 0.5 --to 8 --step 0.01 --out sweep-int --quiet)
[ "$rc" -ne 0 ] && [ ! -e sweep-int ] && no_temps .
ok $? "SIGINT during sfd sweep (tables written as it goes): exit $rc, no directory, no temporary left"
rc=$(interrupt TERM - "$WHIRL" sfd basins --omega 1.78 --points 40000 --out bas-term --quiet)
[ "$rc" -ne 0 ] && [ ! -e bas-term ] && no_temps .
ok $? "SIGTERM during sfd basins: exit $rc, nothing left"
"$WHIRL" run small.whirl --quiet > /dev/null 2>&1
cp small.out/branches.tsv before.tsv
rc=$(interrupt INT small.out "$WHIRL" run small.whirl --NMX=100000 --DSMAX=0.0001 --quiet)
[ "$rc" -ne 0 ] && complete_run small.out && cmp -s before.tsv small.out/branches.tsv && no_temps .
ok $? "SIGINT during whirl run over an earlier output: exit $rc, the earlier output intact"

# a run killed with SIGKILL leaves its stage; the next run removes it
sh -c 'exit 0' & dead=$!
wait $dead
mkdir "resp.tmp.$dead" && echo partial > "resp.tmp.$dead/branches.tsv"
mkdir "other.tmp.$$" && echo mine > "other.tmp.$$/keep"  # a live process's, another name
rm -f resp/mine.txt
"$WHIRL" sfd response --out resp --no-plot --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ ! -e "resp.tmp.$dead" ] && [ -f "other.tmp.$$/keep" ]
ok $? "the stage of a killed run (dead PID $dead) is removed by the next run; others are not (exit $rc)"
# killed in the middle of the swap: the previous output is moved back
mv resp "resp.old.$dead"
"$WHIRL" sfd response --out resp --no-plot --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ ! -e "resp.old.$dead" ] && [ -s resp/branches.tsv ]
ok $? "an output left aside by a run killed mid-swap is restored, then replaced (exit $rc)"

echo "1..$n"
[ $fails -eq 0 ]

#!/bin/sh
# test/regress/overlay.sh — `whirl plot overlay`: two `whirl sfd response`
# runs (delta 0.1 and 0.3, as the paper's Fig. 6a draws several delta) on
# one picture, as PNG and PDF: each picture complete (PNG signature and
# IEND chunk, PDF header and %%EOF trailer, checked here independently of
# whirl's own check), its script redrawing it when run as it is, the legend
# a title a run (the differing parameter, or --labels, quoted for gnuplot),
# stable solid and unstable dashed, the folds where special.tsv puts them;
# and bad input (a directory without branches.tsv, a malformed
# branches.tsv, no runs, --out one of the runs) refused with one message,
# exit status 2 and nothing written.
# SPDX-License-Identifier: BSD-3-Clause
name=overlay
. "${top_srcdir:-.}/test/regress/tap.sh"
GNUPLOT=${WHIRL_GNUPLOT:-gnuplot}
if ! command -v "$GNUPLOT" > /dev/null 2>&1; then
  echo "1..0 # SKIP gnuplot is not installed"
  exit 0
fi
png_ok() { # the 8-byte signature, and IEND with its CRC as the last 12 bytes
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] &&
  [ "$(tail -c 12 "$1" | od -An -tx1 | tr -d ' \n')" = 0000000049454e44ae426082 ]
}
pdf_ok() { # %PDF- first, %%EOF the last line
  [ "$(head -c 5 "$1")" = "%PDF-" ] && [ "$(tail -c 32 "$1" | tr -d '\r' | sed '/^$/d' | tail -n 1)" = "%%EOF" ]
}

for d in 0.1 0.3; do
  "$WHIRL" sfd response --delta $d --out "d$d" --no-plot --quiet > /dev/null 2> "d$d.err"
  ok $? "whirl sfd response --delta $d $(head -c 200 "d$d.err")"
done

# the overlay as PNG and as PDF, and its script redrawing it
for fmt in png pdf; do
  "$WHIRL" plot overlay d0.1 d0.3 --out "ov-$fmt" --format $fmt > "ov-$fmt.stdout" 2> "ov-$fmt.stderr"
  rc=$?
  [ $rc -eq 0 ] && "${fmt}_ok" "ov-$fmt/overlay.$fmt" && [ ! -s "ov-$fmt.stdout" ]
  ok $? "plot overlay --format $fmt: a complete overlay.$fmt (exit $rc) $(head -c 200 "ov-$fmt.stderr")"
  rm -f "ov-$fmt/overlay.$fmt"
  (cd "ov-$fmt" && "$GNUPLOT" overlay.gp) > "ov-$fmt.gnuplot" 2>&1
  "${fmt}_ok" "ov-$fmt/overlay.$fmt" && [ ! -s "ov-$fmt.gnuplot" ]
  ok $? "ov-$fmt/overlay.gp redraws overlay.$fmt when run as it is, silently $(head -c 200 "ov-$fmt.gnuplot")"
done
gp=ov-png/overlay.gp

# the legend: one entry a run, named by the parameter that differs
t=$(sed -n "s/^ *NaN with lines lw 2 lc rgb '#[0-9a-f]*' title '\([^']*\)' noenhanced.*/\1/p" "$gp" | tr '\n' ';')
[ "$t" = "delta=0.1;delta=0.3;" ]
ok $? "the legend titles the runs by their delta: $t"
grep -q "^set title 'lambda=0.0503, zeta=0, FE=0' noenhanced$" "$gp"
ok $? "the title names what the runs share: $(grep '^set title' "$gp")"
# each run's colour on its curves and its legend entry; unstable dashed
c1=$(sed -n "s/^plot \$s1 using 1:2 with lines lw 2 lc rgb '\(#[0-9a-f]*\)' notitle.*/\1/p" "$gp")
c2=$(sed -n "s/.*\$s2 using 1:2 with lines lw 2 lc rgb '\(#[0-9a-f]*\)' notitle.*/\1/p" "$gp")
[ -n "$c1" ] && [ -n "$c2" ] && [ "$c1" != "$c2" ] &&
  grep -q "\$u2 using 1:2 with lines lw 2 dt 2 lc rgb '$c2' notitle" "$gp" &&
  grep -q "NaN with lines lw 2 lc rgb '$c1' title 'delta=0.1'" "$gp" &&
  grep -q "NaN with lines lw 2 lc rgb '$c2' title 'delta=0.3'" "$gp" &&
  grep -q "^set key outside" "$gp"
ok $? "a colour a run ($c1, $c2), unstable dashed, the legend in the runs' colours outside the axes"
# the folds drawn are special.tsv's LPs of delta 0.3 (Omega, eps), and delta 0.1 has none
awk -F'\t' '$1 == "LP" { printf "%.8f %.8f\n", $4, $5 }' d0.3/special.tsv | sort > lp.want
awk '/^\$lp2 << EOD$/ { on = 1; next } /^EOD$/ { on = 0 } on { printf "%.8f %.8f\n", $1, $2 }' "$gp" | sort > lp.got
n1=$(awk '/^\$lp1 << EOD$/ { on = 1; next } /^EOD$/ { on = 0 } on' "$gp" | wc -l)
[ "$(wc -l < lp.want)" -eq 3 ] && cmp -s lp.want lp.got && [ "$n1" -eq 0 ]
ok $? "the LP markers: delta 0.3's three folds of special.tsv ($(tr '\n' ';' < lp.got)), none for delta 0.1"
# the stable points drawn are the table's: every stable row of delta 0.1 in $s1
awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  !/^#/ && NF > 1 && $c["stable"] == 1 { printf "%.6e %.6e\n", $c["Omega"], $c["eps"] }' d0.1/branches.tsv | sort -u > s1.want
awk '/^\$s1 << EOD$/ { on = 1; next } /^EOD$/ { on = 0 } on && NF { printf "%.6e %.6e\n", $1, $2 }' "$gp" | sort -u > s1.got
[ "$(wc -l < s1.want)" -gt 100 ] && cmp -s s1.want s1.got
ok $? "delta 0.1's curve: its $(wc -l < s1.want) stable rows of branches.tsv, and only those"

# --labels: the user's titles, quoted for gnuplot (a quote doubled, no way out of the string)
"$WHIRL" plot overlay d0.1 d0.3 --labels "δ = 0.1,it's 0.3" --title "Fig. 6a'
!touch pwned" --out lab --quiet 2> lab.stderr
rc=$?
grep -q "title 'δ = 0.1' noenhanced" lab/overlay.gp && grep -q "title 'it''s 0.3' noenhanced" lab/overlay.gp &&
  ! grep -q '^!' lab/overlay.gp && [ ! -e lab/pwned ] && [ $rc -eq 0 ] && png_ok lab/overlay.png
ok $? "--labels and --title as given, quoted ('it''s 0.3'; a newline cannot start a shell line) $(head -c 200 lab.stderr)"

# bad input: one message, exit 2, nothing written
mkdir empty malformed short
printf 'branch\tpt\ttype\tlabel\tOmega\teps\tstable\n1\t0\t-\t0\t0.5\tnot-a-number\t1\n' > malformed/branches.tsv
printf 'branch\tpt\ttype\tlabel\tOmega\teps\tstable\n1\t0\t-\t0\t0.5\n' > short/branches.tsv
bad() {
  what=$1
  shift
  : > bad.stdout; : > bad.stderr
  before=$(ls)
  "$WHIRL" plot overlay "$@" --out bad.out > bad.stdout 2> bad.stderr
  rc=$?
  after=$(ls)
  [ $rc -eq 2 ] && [ "$(wc -l < bad.stderr)" -eq 1 ] && grep -q "^whirl plot overlay: " bad.stderr &&
    [ ! -s bad.stdout ] && [ ! -e bad.out ] && [ "$before" = "$after" ]
  ok $? "$what: exit 2 ($rc), one message, nothing written: $(cat bad.stderr)"
}
bad "a directory without branches.tsv" d0.1 empty
bad "a malformed branches.tsv (a word for eps)" d0.1 malformed
bad "a row shorter than the header" short d0.3
bad "no runs"
bad "a missing directory" d0.1 no-such-dir
bad "--labels with too few titles" d0.1 d0.3 --labels one
bad "--format gif" d0.1 d0.3 --format gif
"$WHIRL" plot overlay d0.1 d0.3 --out d0.3 > /dev/null 2> same.stderr
[ $? -eq 2 ] && [ -f d0.3/branches.tsv ] && [ ! -e d0.3/overlay.gp ]
ok $? "--out one of the runs: refused, the run kept: $(cat same.stderr)"

# without gnuplot, the PNG whirl draws itself (doc/output-directories.md):
# drawn, a palette PNG, and claimed
WHIRL_GNUPLOT=/nonexistent/gnuplot "$WHIRL" plot overlay d0.1 d0.3 --out here > /dev/null 2> here.stderr
rc=$?
[ $rc -eq 0 ] && [ -s here/overlay.gp ] && ! grep -q 'skipped' here.stderr &&
  grep -q 'overlay.png' here.stderr &&
  [ "$(od -An -tu1 -j25 -N1 here/overlay.png | tr -d ' ')" = 3 ]
ok $? "no gnuplot: exit 0, overlay.png drawn by whirl itself (a palette PNG), claimed: $(tr '\n' ' ' < here.stderr)"
# without gnuplot and with WHIRL_DRAW=gnuplot: the script written, no
# picture claimed, exit 0 as with one
WHIRL_DRAW=gnuplot WHIRL_GNUPLOT=/nonexistent/gnuplot "$WHIRL" plot overlay d0.1 d0.3 --out nogp > /dev/null 2> nogp.stderr
rc=$?
[ $rc -eq 0 ] && [ -s nogp/overlay.gp ] && [ ! -e nogp/overlay.png ] &&
  [ "$(grep -c 'pictures skipped' nogp.stderr)" -eq 1 ] && ! grep -q 'overlay.png' nogp.stderr
ok $? "no gnuplot, WHIRL_DRAW=gnuplot: exit 0, the script kept, the picture said skipped once, not claimed: $(tr '\n' ' ' < nogp.stderr)"
tap_end

#!/bin/sh
# test/regress/pictures.sh — every picture the commands draw, as PNG and as
# PDF (--format): each one complete (PNG: signature and IEND chunk; PDF:
# header and %%EOF trailer, checked here independently of whirl's own
# check), each script beside it redrawing it when run as it is (gnuplot
# NAME.gp in the output directory, the picture removed first), and a bad
# --format refused before any work.  The runs are small versions of the
# examples (the sfd commands, the rotor commands on examples/rotor, whirl
# run on built-in models of examples/).
# SPDX-License-Identifier: BSD-3-Clause
name=pictures
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples"
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

# pictures_ok LABEL FMT OUT RC: every NAME.gp in OUT has its complete
# NAME.FMT, and redraws it when run as it is (the picture removed first)
pictures_ok() {
  label=$1 fmt=$2 out=$3 rc=$4 bad="" np=0
  for gp in "$out"/*.gp; do
    [ -f "$gp" ] || continue
    np=$((np + 1)) pic="${gp%.gp}.$fmt"
    "${fmt}_ok" "$pic" || bad="$bad $(basename "$pic")"
    rm -f "$pic"
    (cd "$out" && "$GNUPLOT" "$(basename "$gp")") > /dev/null 2>&1
    "${fmt}_ok" "$pic" || bad="$bad $(basename "$gp")(redraw)"
  done
  [ "$rc" -eq 0 ] && [ $np -ge 1 ] && [ -z "$bad" ]
  ok $? "$label --format $fmt: $np pictures complete and redrawn by their scripts${bad:+; bad:$bad} $(head -c 200 "$out.stderr")"
}

# check_cmd LABEL DIR-STEM ARGS...: the command with --format png and pdf
check_cmd() {
  label=$1 stem=$2
  shift 2
  for fmt in png pdf; do
    out="$tmp/$stem-$fmt"
    "$WHIRL" "$@" --out "$out" --format "$fmt" --quiet > "$out.stdout" 2> "$out.stderr"
    pictures_ok "$label" "$fmt" "$out" $?
  done
}

check_cmd "sfd response" response sfd response
check_cmd "sfd simulate" simulate sfd simulate --omega 1.78 --periods 40
check_cmd "sfd sweep" sweep sfd sweep --from 1 --to 3 --step 0.5 --periods 60 --record 20 --direction up
check_cmd "sfd basins" basins sfd basins --omega 1.78 --points 25 --periods 60
check_cmd "sfd nonsync" nonsync sfd nonsync --omega-max 10 --omega-min 7
check_cmd "sfd region" region sfd region --lambda-min 0.05 --lambda-max 0.3
rigid="$ex/rotor/rigid-limit.rotor" sfd="$ex/rotor/sfd-rigid.rotor"
check_cmd "rotor campbell" campbell rotor campbell "$ex/rotor/friswell-5.9.1.rotor" --speeds 0:4000:5
check_cmd "rotor response" rresponse rotor response "$rigid" --harmonics 3 --stability off
check_cmd "rotor loci" loci rotor loci "$rigid" --param unbalance --range 0.5:2 --harmonics 1
check_cmd "rotor simulate" rsimulate rotor simulate "$sfd" --speed 690 --unit rad/s --periods 10
check_cmd "rotor basins" rbasins rotor basins "$sfd" --speed 690 --unit rad/s --grid 3 --periods 40
# whirl run takes its options as --KEY=value
check_run() {
  label=$1 stem=$2 file=$3
  for fmt in png pdf; do
    out="$tmp/$stem-$fmt"
    "$WHIRL" run "$file" --out="$out" --format="$fmt" --quiet > "$out.stdout" 2> "$out.stderr"
    pictures_ok "$label" "$fmt" "$out" $?
  done
}
check_run "run (discovery, examples/discover/sfd-rotating.whirl)" disc "$ex/discover/sfd-rotating.whirl"

# One gnuplot process draws all the pictures of a run (its start-up costs
# more than a picture); when that process fails, each picture is drawn
# alone, so a failure is still found and reported per picture.
real_gp=$(command -v "$GNUPLOT")
printf '#!/bin/sh\necho "$#" >> "%s/gp-calls"\nexec "%s" "$@"\n' "$tmp" "$real_gp" > "$tmp/gp-count"
printf '#!/bin/sh\necho "$#" >> "%s/gp-calls2"\n[ $# -gt 1 ] && { echo "batch refused" >&2; exit 1; }\nexec "%s" "$@"\n' "$tmp" "$real_gp" > "$tmp/gp-nobatch"
chmod +x "$tmp/gp-count" "$tmp/gp-nobatch"
# (WHIRL_DRAW=gnuplot: sfd response's PNGs are otherwise drawn by whirl)
WHIRL_DRAW=gnuplot WHIRL_GNUPLOT="$tmp/gp-count" "$WHIRL" sfd response --out "$tmp/batch" --quiet > /dev/null 2>&1
rc=$?
[ $rc -eq 0 ] && [ "$(wc -l < "$tmp/gp-calls")" -eq 1 ] && png_ok "$tmp/batch/response.png" && png_ok "$tmp/batch/multipliers.png"
ok $? "sfd response: both pictures by one gnuplot process ($(wc -l < "$tmp/gp-calls") started)"
WHIRL_DRAW=gnuplot WHIRL_GNUPLOT="$tmp/gp-nobatch" "$WHIRL" sfd response --out "$tmp/batch2" --quiet > /dev/null 2> "$tmp/batch2.err"
rc=$?
[ $rc -eq 0 ] && [ "$(wc -l < "$tmp/gp-calls2")" -eq 3 ] && png_ok "$tmp/batch2/response.png" && png_ok "$tmp/batch2/multipliers.png" && [ ! -s "$tmp/batch2.err" ]
ok $? "sfd response: the batch failing, each picture drawn alone ($(wc -l < "$tmp/gp-calls2") gnuplot runs, exit $rc)"

"$WHIRL" sfd response --out "$tmp/badfmt" --format gif > /dev/null 2> "$tmp/badfmt.err"
rc=$?
[ $rc -eq 2 ] && [ ! -e "$tmp/badfmt" ] && grep -q "png, pdf or svg" "$tmp/badfmt.err"
ok $? "--format gif: exit 2, nothing written: $(cat "$tmp/badfmt.err")"
"$WHIRL" run "$ex/discover/sfd-rotating.whirl" --out="$tmp/badfmt2" --format=eps > /dev/null 2> "$tmp/badfmt2.err"
rc=$?
[ $rc -eq 2 ] && [ ! -e "$tmp/badfmt2" ]
ok $? "whirl run --format=eps: exit 2, nothing written: $(cat "$tmp/badfmt2.err")"
# whirl run --no-plot: the tables, no picture and no script
"$WHIRL" run "$ex/discover/sfd-rotating.whirl" --out="$tmp/noplot" --no-plot > "$tmp/noplot.out" 2>&1
rc=$?
[ $rc -eq 0 ] && [ -s "$tmp/noplot/branches.tsv" ] && [ ! -e "$tmp/noplot/diagram.png" ] &&
  [ ! -e "$tmp/noplot/diagram.gp" ] && ! grep -q "diagram" "$tmp/noplot.out"
ok $? "whirl run --no-plot: branches.tsv, no diagram.png nor diagram.gp, none claimed (exit $rc)"
tap_end

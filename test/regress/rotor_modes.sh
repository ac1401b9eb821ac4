#!/bin/sh
# test/regress/rotor_modes.sh — `whirl rotor modes` and `whirl rotor
# campbell` on examples/rotor/friswell-5.9.1.rotor (Friswell et al. 2010,
# Example 5.9.1; doc/rotor-validation.md): the first six rows at 0 and
# 4000 rev/min equal the published frequencies (rad/s: those ROSS prints
# for this example, to their 8-10 digits; Hz: the book's 4 digits), the
# whirl of each split pair is backward then forward; campbell writes its
# tables and picture, its critical speeds lie on the 1x line (a fresh
# `modes` at each one has that frequency) and its --speed 0 rows are the
# modes table's; `whirl rotor unbalance` on a Jeffcott rotor gives forward
# circular orbits with the phases of a single resonance; the complete
# examples of doc/rotor-file.md read and solve.
# SPDX-License-Identifier: BSD-3-Clause
name=rotmodes
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/rotor/friswell-5.9.1.rotor"

# TSV column COL of rows 2..7 rounded to 2 decimals is the list WANT
rounded() {
  awk -F '\t' -v col="$2" -v want="$3" '
    BEGIN { split(want, w, " ") }
    NR >= 2 && NR <= 7 { k = NR - 1; if (sprintf("%.2f", $col) != w[k]) {
      printf "#   row %d: %s, want %s\n", k, $col, w[k]; bad = 1 } }
    END { exit bad || NR < 7 }' "$1"
}

# compare TSV column COL of rows 2..7 with the list WANT to relative TOL
close() {
  awk -F '\t' -v col="$2" -v want="$3" -v tol="$4" '
    BEGIN { split(want, w, " ") }
    NR >= 2 && NR <= 7 { k = NR - 1; d = ($col - w[k]) / w[k]; if (d < 0) d = -d
      if (d > tol) { printf "#   row %d: %s, want %s\n", k, $col, w[k]; bad = 1 } }
    END { exit bad || NR < 7 }' "$1"
}

"$WHIRL" rotor modes "$ex" --speed 0 > m0.tsv 2> err.txt
ok $? "modes --speed 0 exits 0"
close m0.tsv 2 "86.65811435 86.65811435 274.31285391 274.31285391 716.78631221 716.78631221" 1e-9
ok $? "0 rpm: omega_rad_s = ROSS's printed Example 5.9.1 values"
rounded m0.tsv 3 "13.79 13.79 43.66 43.66 114.08 114.08"
ok $? "0 rpm: freq_hz = 13.79, 43.66, 114.08 Hz (2 decimals)"
"$WHIRL" rotor modes "$ex" --speed 4000 > m4.tsv 2> err.txt
ok $? "modes --speed 4000 exits 0"
close m4.tsv 2 "85.389467 87.7958637 251.78460413 294.71333087 600.17936195 827.07536193" 1e-8
ok $? "4000 rpm: omega_rad_s = ROSS's printed Example 5.9.1 values"
rounded m4.tsv 3 "13.59 13.97 40.07 46.91 95.52 131.63"
ok $? "4000 rpm: freq_hz (2 decimals)"
[ "$(cut -f 5 m4.tsv | sed -n '2,7p' | tr '\n' ' ')" = "backward forward backward forward backward forward " ]
ok $? "4000 rpm: each pair backward, then forward"
if "$WHIRL" rotor modes "$ex" --speed 4000 --method arpack > a4.tsv 2> err.txt; then
  close a4.tsv 2 "85.389467 87.7958637 251.78460413 294.71333087 600.17936195 827.07536193" 1e-8
  ok $? "4000 rpm by ARPACK: the same"
else
  grep -q 'built without ARPACK' err.txt
  ok $? "4000 rpm by ARPACK # SKIP whirl built without ARPACK"
fi
"$WHIRL" rotor modes "$ex" --speed 4000 --unit rpm > u1.tsv && \
  "$WHIRL" rotor modes "$ex" --speed 418.87902047863906 --unit rad/s > u2.tsv
ok $? "--unit rad/s"
paste u1.tsv u2.tsv | awk -F '\t' 'NR > 1 { d = ($2 - $7) / $2; if (d < 0) d = -d; if (d > 1e-12) bad = 1 }
  END { exit bad }'
ok $? "--speed 4000 --unit rpm = --speed 418.879... --unit rad/s"

"$WHIRL" rotor campbell "$ex" -o cb --speeds 0:6000:31 --quiet 2> err.txt
ok $? "campbell exits 0"
[ -s cb/campbell.tsv ] && [ -s cb/critical.tsv ] && [ -s cb/campbell.png ]
ok $? "campbell.tsv, critical.tsv, campbell.png"
[ "$(head -n 1 cb/campbell.tsv)" = "$(printf 'speed_rpm\tspeed_rad_s\tmode\tomega_rad_s\tfreq_hz\tlog_dec\twhirl')" ]
ok $? "campbell.tsv header"
awk -F '\t' 'NR > 1 && $1 == 0 { print $4 }' cb/campbell.tsv > c0.txt
cut -f 2 m0.tsv | sed 1d > m0.txt
cmp -s c0.txt m0.txt
ok $? "campbell at speed 0 = modes --speed 0"
nc=$(sed 1d cb/critical.tsv | wc -l)
[ "$nc" -ge 4 ]
ok $? "at least 4 critical speeds below 6000 rpm ($nc)"
good=1
sed 1d cb/critical.tsv | while IFS="$(printf '\t')" read -r mode rpm rads hz whirl; do
  "$WHIRL" rotor modes "$ex" --speed "$rads" --unit rad/s > c.tsv || exit 1
  awk -F '\t' -v m="$mode" -v s="$rads" -v w="$whirl" 'NR == m + 1 {
    d = ($2 - s) / s; if (d < 0) d = -d; exit !(d < 1e-8 && $5 == w) }' c.tsv || exit 1
done
ok $? "each critical speed: mode's frequency = speed (1e-8), same whirl"

# response: a massless shaft, a disk at mid-span, unbalance at 30 degrees,
# light bearing damping: circular forward orbits, in phase with the
# unbalance below the critical speed (~2770 rpm), opposite above
cat > j.rotor << 'EOF'
material massless E=2e11 G=8e10 rho=0
shaft from=0 to=4 length=0.8 od=0.03 id=0.01 material=massless
disk node=2 mass=12 ip=0.2 it=0.5
bearing node=0 kyy=5e7 kzz=5e7 cyy=2e3 czz=2e3
bearing node=4 kyy=5e7 kzz=5e7 cyy=2e3 czz=2e3
unbalance node=2 me=1e-4 phase-deg=30
EOF
"$WHIRL" rotor unbalance j.rotor --node 2 --speeds 1000:4000:7 > r.tsv 2> err.txt
ok $? "response exits 0"
[ "$(wc -l < r.tsv)" -eq 8 ] && [ "$(head -n 1 r.tsv)" = "$(printf 'speed_rpm\tspeed_rad_s\ty_amp_m\ty_phase_deg\tz_amp_m\tz_phase_deg\tmajor_m\tminor_m\twhirl')" ]
ok $? "response: header and 7 speeds"
awk -F '\t' 'NR > 1 { d = ($7 - $8) / $7; if (d < 0) d = -d; if (d > 1e-9 || $9 != "forward") bad = 1
  p = $4 - $6; if (p < 0) p += 360; p -= 90; if (p < -1e-6 || p > 1e-6) bad = 1 } END { exit bad }' r.tsv
ok $? "response: circular forward orbits, z lagging y by 90 degrees"
awk -F '\t' 'NR == 2 { if ($4 < 29.9 || $4 > 30.1) bad = 1 } NR == 8 { if ($4 > -149.9 || $4 < -150.1) bad = 1 }
  END { exit bad }' r.tsv
ok $? "response: phase 30 degrees below the critical speed, -150 above"
"$WHIRL" rotor unbalance j.rotor --node 5 > r.tsv 2> err.txt
[ $? -eq 2 ] && [ ! -s r.tsv ] && grep -q 'node must be a shaft node, 0..4' err.txt
ok $? "response --node off the shaft: exit 2, nothing printed"

# the complete examples of doc/rotor-file.md read and solve
awk '/^```/ { if (on) { on = 0 } else { on = 1; k++ }; next }
     on { print > ("doc" k ".rotor") }' "$top_srcdir/doc/rotor-file.md"
for f in doc1.rotor doc2.rotor; do
  "$WHIRL" rotor modes "$f" --speed 3000 > d.tsv 2> err.txt && [ "$(wc -l < d.tsv)" -eq 7 ]
  ok $? "doc/rotor-file.md example $f: six modes at 3000 rpm"
done
grep -v '^#' "$top_srcdir/examples/rotor/friswell-5.9.1.rotor" | grep . > ex1.txt
cmp -s doc1.rotor ex1.txt
ok $? "doc/rotor-file.md's first example is examples/rotor/friswell-5.9.1.rotor (without comments)"

# proportional damping (a `damping` line): with alpha alone on a rotor whose
# mass is all in its shaft elements, C = alpha M exactly, so every mode of
# the undamped rotor at rest keeps its shape and gets zeta = alpha/(2 w):
# w_d = w sqrt(1 - zeta^2), log dec = 2 pi zeta / sqrt(1 - zeta^2)
grep -v '^disk' "$ex" > shaft.rotor
{ cat shaft.rotor; echo "damping alpha=20"; } > shaft-damped.rotor
"$WHIRL" rotor modes shaft.rotor --speed 0 > u.tsv && "$WHIRL" rotor modes shaft-damped.rotor --speed 0 > d.tsv
paste u.tsv d.tsv | awk -F '\t' 'NR > 1 { w = $2; z = 20 / (2 * w); wd = w * sqrt(1 - z * z); ld = 2 * 3.14159265358979 * z / sqrt(1 - z * z)
  if (((($7 - wd) / wd) ^ 2) > 1e-16 || ((($9 - ld) / ld) ^ 2) > 1e-10) { bad = 1; print "#   mode " $1 ": " $7 " " $9 ", want " wd " " ld } }
  END { exit bad || NR < 7 }'
ok $? "damping alpha=20: zeta = alpha/(2 omega) in every mode (w_d to 1e-8, log dec to 1e-5 of its 6 digits)"

tap_end

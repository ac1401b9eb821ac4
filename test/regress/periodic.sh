#!/bin/sh
# test/regress/periodic.sh — periodic orbits through the user's commands:
#  - `whirl sfd response --method hbm` and `--method colloc` (fixed-frame
#    periodic orbits) against the default circular-orbit solver (eq. 15
#    seeds, rotating-frame equilibria): the same folds (LP) to 1e-8 and the
#    same eccentricity at the folds;
#  - F_E = -0.1 (orbits not circular): HBM and collocation, two independent
#    discretisations, find the same folds;
#  - `whirl sfd nonsync`: born at a fold of cycles; its second frequency at
#    Omega = 8.7 against the dominant frequency of a long time integration
#    (`whirl sfd simulate`, Hann-windowed DFT) to 1e-4; collocation and
#    harmonic balance agree on the fold;
#  - bad input: exit 2 (or 1 with a message), nothing written.
# SPDX-License-Identifier: BSD-3-Clause
set -u
WHIRL="${top_builddir:-.}/drivers/whirl"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-po.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

# LP speeds (column 4) and eps (column 5) of a special-point table, sorted
lps() { awk -F'\t' '$1 == "LP" { printf "%.15g %.15g\n", $4, $5 }' "$1" | sort -g; }
# largest |difference| of column $3 between two LP lists of equal length
maxdiff() {
  paste -d' ' "$1" "$2" | awk -v c="$3" 'BEGIN { m = -1 }
    NF == 4 { d = $(c) - $(c + 2); if (d < 0) d = -d; if (d > m) m = d }
    END { if (NR == 0) m = 1e9; printf "%.3g\n", m }'
}
lt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }

"$WHIRL" sfd response --no-plot --quiet --out "$tmp/circ" > "$tmp/circ.tsv"
ok $? "whirl sfd response (circular orbits)"
lps "$tmp/circ.tsv" > "$tmp/circ.lp"
for m in hbm colloc; do
  "$WHIRL" sfd response --method $m --no-plot --quiet --out "$tmp/$m" > "$tmp/$m.tsv"
  ok $? "whirl sfd response --method $m"
  lps "$tmp/$m.tsv" > "$tmp/$m.lp"
  ok $(( $(wc -l < "$tmp/$m.lp") != 3 || $(wc -l < "$tmp/circ.lp") != 3 )) \
    "--method $m: three folds, as the circular orbits have"
  d=$(maxdiff "$tmp/circ.lp" "$tmp/$m.lp" 1)
  lt "$d" 1e-8; ok $? "--method $m: fold speeds = circular-orbit folds (max diff $d)"
  tol=1e-10; [ $m = colloc ] && tol=1e-8
  d=$(maxdiff "$tmp/circ.lp" "$tmp/$m.lp" 2)
  lt "$d" $tol; ok $? "--method $m: eps at the folds = circular-orbit eps (max diff $d)"
  grep -m 1 '^#' "$tmp/$m/branches.tsv" | grep -q "method $m"
  ok $? "--method $m: the table header names the method"
done
grep -q "LARGEST eccentricity" "$tmp/hbm/branches.tsv"
ok $? "periodic methods: the header says eps is the largest eccentricity"
r=$(awk -F'\t' '!/^#/ && $17 + 0 > m { m = $17 + 0 } END { printf "%.3g", m }' "$tmp/hbm/branches.tsv")
lt "$r" 1e-11; ok $? "HBM (8 harmonics): largest Galerkin residual on the branches $r"

# F_E != 0: HBM and collocation agree
"$WHIRL" sfd response --fe -0.1 --no-plot --quiet --out "$tmp/feh" > "$tmp/feh.tsv"
ok $? "whirl sfd response --fe -0.1 (HBM)"
"$WHIRL" sfd response --fe -0.1 --method colloc --no-plot --quiet --out "$tmp/fec" > "$tmp/fec.tsv"
ok $? "whirl sfd response --fe -0.1 --method colloc"
lps "$tmp/feh.tsv" > "$tmp/feh.lp"
lps "$tmp/fec.tsv" > "$tmp/fec.lp"
ok $(( $(wc -l < "$tmp/feh.lp") < 3 || $(wc -l < "$tmp/feh.lp") != $(wc -l < "$tmp/fec.lp") )) \
  "F_E = -0.1: HBM and collocation find the same number of folds ($(wc -l < "$tmp/feh.lp"))"
d=$(maxdiff "$tmp/feh.lp" "$tmp/fec.lp" 1)
lt "$d" 1e-7; ok $? "F_E = -0.1: fold speeds, HBM vs collocation (max diff $d)"
d=$(maxdiff "$tmp/feh.lp" "$tmp/fec.lp" 2)
lt "$d" 1e-6; ok $? "F_E = -0.1: largest eccentricity at the folds, HBM vs collocation (max diff $d)"
d=$(maxdiff "$tmp/circ.lp" "$tmp/feh.lp" 1)
lt 1e-4 "$d"; ok $? "F_E = -0.1 moves the folds away from the circular ones ($d)"

# F_E != 0 against a long time integration: the largest eccentricity of
# the orbit at Omega = 3 (HBM and collocation, UZ point) and of the settled
# integrated motion sampled 4096 times per period (sampling error ~1e-8)
"$WHIRL" sfd response --fe -0.1 --uz 3 --omega-max 5 --no-plot --quiet --out "$tmp/u3" > "$tmp/u3.tsv"
eh=$(awk -F'	' '$1 == "UZ" { print $5 }' "$tmp/u3.tsv")
"$WHIRL" sfd response --fe -0.1 --uz 3 --omega-max 5 --method colloc --no-plot --quiet --out "$tmp/u3c" > "$tmp/u3c.tsv"
ec=$(awk -F'	' '$1 == "UZ" { print $5 }' "$tmp/u3c.tsv")
"$WHIRL" sfd simulate --omega 3 --fe -0.1 --periods 400 --samples 4096 --no-plot --quiet --out "$tmp/s3" > /dev/null
et=$(awk -F'	' '!/^#/ && $1 + 0 > 2 * 3.14159265358979 / 3 * 390 && $6 + 0 > m { m = $6 + 0 } END { printf "%.12g", m }' "$tmp/s3/history.tsv")
d=$(awk -v a="$eh" -v b="$ec" -v c="$et" 'BEGIN { d1 = a - b; if (d1 < 0) d1 = -d1; d2 = a - c; if (d2 < 0) d2 = -d2; printf "%.3g %.3g", d1, d2 }')
lt "${d% *}" 1e-9; ok $? "F_E = -0.1, Omega = 3: eps_max HBM $eh vs collocation $ec (diff ${d% *})"
lt "${d#* }" 1e-7; ok $? "F_E = -0.1, Omega = 3: eps_max HBM vs time integration $et (diff ${d#* })"

# the nonsynchronous response
"$WHIRL" sfd nonsync --no-plot --quiet --out "$tmp/ns" > "$tmp/ns.tsv"
ok $? "whirl sfd nonsync"
head -n 1 "$tmp/ns.tsv" | grep -q "^type	branch	label	Omega	f2"
ok $? "nonsync: special-point header has type, branch, label, Omega, f2"
lp=$(awk -F'\t' '$1 == "LP" { print $4 }' "$tmp/ns.tsv" | head -n 1)
lt 8.5 "${lp:-0}" && lt "${lp:-0}" 8.7; ok $? "nonsync: born at a fold of cycles at Omega = $lp"
st=$(awk -F'\t' '$1 == "ST" { print $5, $9 }' "$tmp/ns.tsv")
f2=${st% *}; stab=${st#* }
"$WHIRL" sfd simulate --omega 8.7 --no-plot --quiet --out "$tmp/sim" > "$tmp/sim.tsv"
fs=$(awk -F'\t' '$1 == "1" { print $2 }' "$tmp/sim.tsv")
d=$(awk -v a="$f2" -v b="$fs" 'BEGIN { d = a - b; if (d < 0) d = -d; printf "%.3g", d }')
lt "$d" 1e-4; ok $? "nonsync f2 at 8.7 = $f2, time integration $fs (diff $d)"
ok $(( stab != 1 )) "nonsync: stable at Omega = 8.7 (as the time integration says)"
"$WHIRL" sfd nonsync --method hbm --harmonics 30 --no-plot --quiet --out "$tmp/nsh" > "$tmp/nsh.tsv"
ok $? "whirl sfd nonsync --method hbm --harmonics 30"
lph=$(awk -F'\t' '$1 == "LP" { print $4 }' "$tmp/nsh.tsv" | head -n 1)
d=$(awk -v a="$lp" -v b="$lph" 'BEGIN { d = a - b; if (d < 0) d = -d; printf "%.3g", d }')
lt "$d" 1e-6; ok $? "nonsync fold: collocation $lp vs HBM (30 harmonics) $lph (diff $d)"
# from the other end of the stable branch (the orbit there comes within 3 %
# of the housing: the start is corrected by full Newton)
"$WHIRL" sfd nonsync --omega-start 19 --no-plot --quiet --out "$tmp/ns19" > "$tmp/ns19.tsv"
ok $? "whirl sfd nonsync --omega-start 19"
lp19=$(awk -F'\t' '$1 == "LP" { print $4 }' "$tmp/ns19.tsv" | head -n 1)
d=$(awk -v a="$lp" -v b="${lp19:-0}" 'BEGIN { d = a - b; if (d < 0) d = -d; printf "%.3g", d }')
lt "$d" 1e-6; ok $? "nonsync fold from Omega = 19: $lp19 (diff $d; mesh adapted to the orbit at 19)"

# bad input
check_bad() {
  cmd=$1; want=$2; pattern=$3; shift 3
  out="$tmp/bad-out"
  rm -rf "$out"
  "$WHIRL" sfd "$cmd" --out "$out" "$@" > "$tmp/stdout" 2> "$tmp/stderr"
  rc=$?
  grep -q -- "$pattern" "$tmp/stderr"
  found=$?
  [ ! -e "$out" ]
  clean=$?
  ok $(( rc != want || found != 0 || clean != 0 )) "sfd $cmd $* : exit $rc, $(head -n 1 "$tmp/stderr")"
}
check_bad response 2 "circular, hbm or colloc" --method shooting
check_bad response 2 "needs --fe 0" --method circular --fe 0.1
check_bad response 2 "housing" --fe 1.5
check_bad response 2 "harmonics" --method hbm --harmonics 0
check_bad nonsync 2 "colloc or hbm" --method circular
check_bad nonsync 2 "omega-start" --omega-start 30
check_bad nonsync 1 "circular orbit" --omega-start 3

echo "1..$n"
[ "$fails" -eq 0 ]

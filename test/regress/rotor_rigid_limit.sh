#!/bin/sh
# test/regress/rotor_rigid_limit.sh — the finite-element rotor in the
# rigid limit (examples/rotor/rigid-limit.rotor: a very stiff shaft, the
# disk at mid-span on two short pi-film SFDs with retainer springs,
# Table 1 of the paper) against the rigid rotor of `whirl sfd response`
# (eq. 15, an independent route: circular orbits in the rotating frame):
#  - `whirl rotor response` finds the main branch's two folds and, seeded
#    from the rigid rotor's isolated branch, the isola's fold; all three
#    speeds equal the rigid rotor's to 1e-4 relative, with the same
#    stability on either side (stable below the first fold, unstable
#    between the folds, the isola's lower half unstable);
#  - the difference shrinks tenfold per decade of shaft stiffness
#    (E x 10^3, 10^4, 10^5 of steel's: it is m Omega^2 / k_shaft);
#  - the fold loci in speed x unbalance (whirl rotor loci) merge the
#    isola where the rigid rotor's merge condition does (whirl sfd merge);
#  - the merge curve in (clearance, unbalance), the boundary of the isolas'
#    region (Fig. 18), is the rigid rotor's merge curve delta(lambda);
#  - 1 and 3 harmonics agree (the orbits are circular: one harmonic is
#    exact for the pi film), and 3 harmonics report no TR or PD (the
#    stiff shaft's unresolved modes once made 22).
# SPDX-License-Identifier: BSD-3-Clause
name=rigidlim
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples/rotor/rigid-limit.rotor"

# the rigid rotor: its three folds, and a stable point of the isola
"$WHIRL" sfd response --out rigid --quiet > /dev/null 2>&1
ok $? "whirl sfd response (the rigid rotor)"
awk -F '\t' '$1 == "LP" { print $4 }' rigid/special.tsv | sort -g > lp.rigid
ok "$([ "$(wc -l < lp.rigid)" -eq 3 ] && echo 0 || echo 1)" "the rigid rotor has 3 folds: $(tr '\n' ' ' < lp.rigid)"
# the isola's stable point nearest Omega = 10 (branch 2): speed and eps
seed=$(awk -F '\t' '$1 == 2 && $10 == 1 { d = $5 - 10; if (d < 0) d = -d;
  if (best == "" || d < best) { best = d; s = $5 ":" $6 } } END { print s }' rigid/branches.tsv)
wref=$(awk '$1 == "reference" { sub("omega=", "", $2); print $2 }' "$ex")
seed_rad=$(echo "$seed" | awk -F: -v w="$wref" '{ printf "%.10g:%s", $1 * w, $2 }')
echo "# isola seed from the rigid rotor: Omega_nd:eps = $seed, $seed_rad rad/s"

# response FILE H OUT: the FE rotor's LP speeds (Omega_nd) into OUT
response() {
  "$WHIRL" rotor response "$1" --harmonics "$2" --unit rad/s --seed "$seed_rad" -o "$3.d" --quiet > "$3.tsv" 2> "$3.err"
  rc=$?
  awk -F '\t' '$1 == "LP" { print $5 }' "$3.tsv" | sort -g > "$3"
  return $rc
}
# worst relative difference of two sorted lists of three speeds
worst() { paste "$1" "$2" | awk '{ d = ($1 - $2) / $2; if (d < 0) d = -d; if (d > w) w = d } END { if (NR != 3) print 1; else printf "%.3g", w }'; }

response "$ex" 1 e14
ok $? "whirl rotor response rigid-limit.rotor (1 harmonic): $(head -c 200 e14.err)"
d14=$(worst e14 lp.rigid)
ok "$(awk -v d="$d14" 'BEGIN { exit !(d < 1e-4) }'; echo $?)" "three folds equal the rigid rotor's to 1e-4 (worst $d14): $(tr '\n' ' ' < e14)"

# stability along the main branch: stable before the first fold, unstable
# between the two, stable after (the fold points and the start at rest
# themselves not judged)
awk -F '\t' 'NF > 5 && $2 == 1 { if ($1 == "LP") { lp++; next } if ($1 == "EP") next
  if ((lp == 1) == ($7 == 1)) bad++ } END { exit bad || lp != 2 }' e14.d/branches.tsv
ok $? "main branch: stable, unstable between the folds, stable again"
awk -F '\t' 'NF > 5 && $2 == 2 { if ($1 == "LP") seen = 1; else if (!seen && $7 == 1) bad = 1; else if (seen && $7 != 1 && $1 != "EP") bad = 1 }
  END { exit bad || !seen }' e14.d/branches.tsv
ok $? "isola: unstable from the top of the range down to its fold, stable back up"

response "$ex" 3 h3
ok $? "3 harmonics"
dh=$(worst h3 e14)
ok "$(awk -v d="$dh" 'BEGIN { exit !(d < 1e-8) }'; echo $?)" "3 harmonics = 1 harmonic (circular orbits): $dh"
# the rigid rotor has no torus or period-doubling point here; the stiff
# shaft's unresolved bending modes must not make any (Hill's selection)
ntr=$(awk -F '\t' '$1 == "TR" || $1 == "PD"' h3.tsv | wc -l)
ok "$([ "$ntr" -eq 0 ] && echo 0 || echo 1)" "3 harmonics: no spurious TR or PD ($ntr)"

# the shaft's stiffness: E x 10^3 and 10^4 of steel's
for e in 12 13; do
  sed "s/E=211e14 G=81.2e14/E=211e$e G=81.2e$e/" "$ex" > e$e.rotor
  response e$e.rotor 1 e$e
  ok $? "E = 211e$e: response"
done
d12=$(worst e12 lp.rigid) d13=$(worst e13 lp.rigid)
echo "# worst relative difference to the rigid rotor: E 211e12 $d12, 211e13 $d13, 211e14 $d14"
ok "$(awk -v a="$d12" -v b="$d13" -v c="$d14" 'BEGIN { exit !(a > 5 * b && b > 5 * c) }'; echo $?)" \
  "the difference shrinks about tenfold per decade of stiffness ($d12, $d13, $d14)"

# the fold loci in speed x unbalance: the isola merges with the main
# branch (MG) where the rigid rotor's merge condition G = G_eps = G_Omega = 0
# of eq. 15 says (whirl sfd merge: delta and Omega)
"$WHIRL" sfd merge --lambda 0.0503 --quiet > merge.tsv 2> merge.err
ok $? "whirl sfd merge --lambda 0.0503"
"$WHIRL" rotor loci "$ex" --param unbalance --range 0.05:3 --harmonics 1 -o loci.d --quiet > loci.tsv 2> loci.err
ok $? "whirl rotor loci --param unbalance: $(head -c 200 loci.err)"
res=$(awk -F '\t' 'NR == FNR { if (FNR == 2) { d = $3; w = $4 } next }
  $1 == "MG" && !done { done = 1; dd = 0.3 * $6 / d - 1; dw = $5 / w - 1
    printf "%.3g %.3g %.10g %.10g", (dd < 0 ? -dd : dd), (dw < 0 ? -dw : dw), 0.3 * $6, $5 }
  END { if (!done) print "1 1 none none" }' merge.tsv loci.tsv)
set -- $res
echo "# merge point: FE delta $3 at Omega $4; rigid $(awk -F '\t' 'NR == 2 { print $3, $4 }' merge.tsv)"
ok "$(awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < 1e-5 && b < 1e-4) }'; echo $?)" \
  "the loci's merge point is the rigid rotor's: delta to $1, Omega to $2"

# the merge curve in (clearance, unbalance): a clearance scale s is the
# rigid rotor's lambda / s^3 and delta / s, so its points lie on the rigid
# rotor's merge curve delta(lambda) of whirl sfd merge
"$WHIRL" rotor loci "$ex" --param unbalance --range 0.05:3 --harmonics 1 \
  --merge-along clearance --range2 0.5:2 -o merge.d --quiet > /dev/null 2> merge2.err
ok $? "whirl rotor loci --merge-along clearance: $(head -c 200 merge2.err)"
worst=0 npts=0
for row in $(awk -F '\t' 'NF > 6 && $1 == "-" && (NR % 15) == 0 { print $6 ":" $7 }' merge.d/merge.tsv); do
  s=${row%%:*} u=${row##*:}
  lam=$(awk -v s="$s" 'BEGIN { printf "%.15g", 0.0503 / s ^ 3 }')
  d=$("$WHIRL" sfd merge --lambda "$lam" --quiet | awk -F '\t' 'NR == 2 { print $3 }')
  worst=$(awk -v s="$s" -v u="$u" -v d="$d" -v w="$worst" 'BEGIN { e = 0.3 * u / s / d - 1; if (e < 0) e = -e; printf "%.3g", (e > w ? e : w) }')
  npts=$((npts + 1))
done
echo "# merge curve: $npts points against whirl sfd merge, worst relative delta $worst"
ok "$(awk -v w="$worst" -v k="$npts" 'BEGIN { exit !(k >= 5 && w < 1e-5) }'; echo $?)" \
  "the merge curve in (clearance, unbalance) is the rigid rotor's delta(lambda) to 1e-5 ($npts points, $worst)"

tap_end

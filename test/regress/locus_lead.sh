#!/bin/sh
# test/regress/locus_lead.sh — a locus continued from a label, its first
# listed parameter the label's own (ICP = [PAR(1), PAR(4)] from an HB found
# in PAR(1)): that parameter leads, as AUTO's ICP(1) (ae.f90, STPRAE and
# FNLPAE): DS > 0 makes it grow, and the locus's LPs are its turning points,
# not those of the parameter whirl continues in.  AUTO-07p's demo pp3
# (predator-prey with harvesting; hyper.all, its run "hb"): the Hopf curve
# from the HB at PAR(1) = 0.106415 with PAR(4) free meets the invariant
# plane u3 = 0 at a branch point where u3's eigenvalue -PAR(3) + PAR(5) u2
# is zero, u2 = PAR(3)/PAR(5) = 1/6 (closed form; AUTO: PAR(1) 0.362537,
# PAR(4) 3.34749), and reaches PAR(4) = 4 at the equilibria's other Hopf
# point, PAR(1) = 0.459600 (AUTO's UZ).  Before, the curve went the other
# way (PAR(4) growing, PAR(1) falling), labelled an LP where PAR(4) turned
# and a ZH beside every BP.
# SPDX-License-Identifier: BSD-3-Clause
name=locus_lead
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
cat > "$tmp/pp3.c" <<'C'
#include <math.h>
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  f[0] = u[0] * (1 - u[0]) - p[3] * u[0] * u[1];
  f[1] = -p[1] * u[1] + p[3] * u[0] * u[1] - p[4] * u[1] * u[2] - p[0] * (1 - exp(-p[5] * u[1]));
  f[2] = -p[2] * u[2] + p[4] * u[1] * u[2];
  return 0;
}
static const char *const xn[] = {"u1", "u2", "u3"};
static const char *const pn[] = {"PAR(1)", "PAR(2)", "PAR(3)", "PAR(4)", "PAR(5)", "PAR(6)"};
static const double par0[] = {0.0, 0.25, 0.5, 4.0, 3.0, 5.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "pp3", .n = 3, .npar = 6, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .forcing_param = -1, .description = "AUTO-07p's demo pp3"};
C
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o pp3.so pp3.c -lm
ok $? "pp3 plug-in builds"
# on u3 = 0, u1 = 1 - PAR(4) u2; at u2 = 0.2: u1 = 0.2 and PAR(1) =
# (-0.25 u2 + 4 u1 u2) / (1 - exp(-5 u2)) = 0.11 / (1 - e^-1); towards
# smaller PAR(1) the HB at 0.106415
p1=$(awk 'BEGIN { printf "%.15g", 0.11 / (1 - exp(-1)) }')
printf 'model = pp3.so\nIPS = 1\nICP = [PAR(1)]\nU = {u1: 0.2, u2: 0.2, u3: 0}\nPAR = {PAR(1): %s}\nDS = -0.01\nDSMAX = 0.02\nNMX = 200\nRL0 = 0.05\nEPSL = 1e-8\nEPSU = 1e-8\n' "$p1" > eq.whirl
"$WHIRL" run eq.whirl --no-plot --quiet > /dev/null 2> eq.err
ok $? "equilibria on u3 = 0 to the HB ($(head -1 eq.err))"
hb=$(awk -F'\t' 'NR > 1 && $3 == "HB" { print $4; exit }' eq.out/branches.tsv)
printf 'model = pp3.so\nIPS = 1\nISW = 2\nS = eq.out\nIRS = %s\nICP = [PAR(1), PAR(4)]\nDS = 0.01\nDSMAX = 0.02\nNMX = 300\nEPSL = 1e-8\nEPSU = 1e-8\nUZSTOP = {PAR(4): 4}\n' "${hb:-0}" > hb.whirl
"$WHIRL" run hb.whirl --no-plot --quiet > /dev/null 2> hb.err
ok $? "the Hopf curve from HB label ${hb:-?} in (PAR(1), PAR(4)) ($(head -1 hb.err))"
pts=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
  $3 != "-" && $3 != "EP" { printf "%s %.7f %.6f %.9f;", $3, $h["PAR(1)"], $h["PAR(4)"], $h["u2"] }' hb.out/branches.tsv 2>/dev/null)
echo "$pts" | awk -F';' '{ if (NF != 3) exit 1; split($1, a, " "); split($2, b, " ")
  exit !(a[1] == "BP" && (a[4] - 1/6)^2 < 1e-18 && (a[2] - 0.362537)^2 < 1e-12 &&
         (a[3] - 3.34749)^2 < 1e-10 && b[1] == "UZ" && (b[2] - 0.459600)^2 < 1e-12) }'
ok $? "PAR(1) leads: the BP at u2 = 1/6 (PAR(1) 0.362537, PAR(4) 3.34749 as AUTO's), then PAR(4) = 4 at PAR(1) 0.459600, no LP, no ZH ($pts)"
tap_end

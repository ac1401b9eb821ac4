#!/bin/sh
# test/regress/restart_lp_orbit.sh — a run of periodic orbits restarted at
# an LP of orbits (IRS = LP1, ISW = 1, the label's own parameter) goes on
# along the stored tangent in either direction, as for equilibria
# (restart_lp.sh) and as AUTO does.  Before, the start's Newton at fixed
# parameter met the singular Jacobian of the fold and the run failed
# ("Newton did not converge", issue 18).  Model: the Bautin normal form
# r' = r (mu + 2 r^2 - r^4), theta' = 1, whose orbits r^2 = 1 -+ sqrt(1 + mu)
# (period 2 pi) meet in the LP at mu = -1, r = 1 (closed forms): the inner
# ones unstable, the outer ones stable.
# SPDX-License-Identifier: BSD-3-Clause
name=restart_lp_orbit
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
cat > "$tmp/bautin.c" <<'EOF'
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  const double x = u[0], y = u[1], s = x * x + y * y, g = p[0] + 2 * s - s * s;
  f[0] = g * x - y;
  f[1] = g * y + x;
  return 0;
}
static const char *const xn[] = {"x", "y"};
static const char *const pn[] = {"mu"};
static const double par0[] = {-0.5};
static const double u0[] = {0.0, 0.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "bautin", .n = 2, .npar = 1, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .u0 = u0, .forcing_param = -1,
    .description = "Bautin normal form"};
EOF
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o "$tmp/bautin.so" "$tmp/bautin.c" -lm
ok $? "Bautin plug-in builds"
printf 'model = bautin.so\nIPS = 1\nICP = [mu]\nISP = 2\nDS = 0.01\nDSMAX = 0.05\nNMX = 200\nUZSTOP = {mu: [0.5]}\n' > "$tmp/eq.whirl"
printf 'model = bautin.so\nIPS = 2\nICP = [mu]\nS = eq.out\nIRS = HB1\nILP = 1\nNTST = 20\nDS = -0.01\nDSMAX = 0.1\nNMX = 300\nUZSTOP = {mu: [0.5]}\n' > "$tmp/po.whirl"
(cd "$tmp" && "$WHIRL" run eq.whirl --no-plot --quiet > /dev/null 2>&1 &&
  "$WHIRL" run po.whirl --no-plot --quiet > /dev/null 2>&1)
ok $? "orbits from the Hopf point of the origin (mu = 0)"
lp=$(awk -F '\t' '$3 == "LP" { print $5, $8 }' "$tmp/po.out/branches.tsv" 2>/dev/null)
echo "$lp" | awk '{ exit !(NF == 2 && $1 + 1 < 1e-8 && -1 - $1 < 1e-8 && $2 - 1 < 1e-6 && 1 - $2 < 1e-6) }'
ok $? "the LP of orbits at mu = -1 with max x = 1 ($lp)"
for sign in + -; do
  printf 'model = bautin.so\nIPS = 2\nICP = [mu]\nS = po.out\nIRS = LP1\nILP = 1\nNTST = 20\nDS = %s0.01\nDSMAX = 0.1\nNMX = 300\nUZSTOP = {mu: [-0.5]}\n' "$sign" > "$tmp/re$sign.whirl"
  (cd "$tmp" && "$WHIRL" run "re$sign.whirl" --out="re$sign" --no-plot --quiet > /dev/null 2> "re$sign.err")
  ok $? "restart at the LP of orbits with DS ${sign}0.01 runs ($(head -1 "$tmp/re$sign.err"))"
  nlp=$(awk -F '\t' '$3 == "LP"' "$tmp/re$sign/branches.tsv" 2>/dev/null | wc -l)
  [ -f "$tmp/re$sign/branches.tsv" ] && [ "$nlp" -eq 0 ]
  ok $? "DS ${sign}0.01: the LP it starts from is not labelled again ($nlp LP)"
done
# the two sides at mu = -0.5: r = sqrt(1 -+ sqrt(1/2)).  The stored
# tangent times DS is the motion (AUTO's convention, as restart_lp.sh):
# the first run went with DS < 0, so DS - goes on (onto the outer, stable
# orbits) and DS + goes back (the inner ones)
uz() { awk -F '\t' '$3 == "UZ" { print $8, $10 }' "$tmp/$1/branches.tsv" 2>/dev/null; }
uz re- | awk '{ r = sqrt(1 + sqrt(0.5)); exit !(NF == 2 && ($1 - r) ^ 2 < 1e-12 && $2 == 1) }'
ok $? "DS -0.01: on, to the outer orbit, stable, r = 1.306563 ($(uz re-))"
uz re+ | awk '{ r = sqrt(1 - sqrt(0.5)); exit !(NF == 2 && ($1 - r) ^ 2 < 1e-12 && $2 == 0) }'
ok $? "DS +0.01: back to the inner orbit, unstable, r = 0.541196 ($(uz re+))"
# the same on another mesh (NTST 25, the label's 20): the tangent
# resampled with the orbit.  Before, the restart onto another mesh took
# DS's sign in mu instead, so the two directions came out exchanged
for sign in + -; do
  sed 's/^NTST = 20/NTST = 25/' "$tmp/re$sign.whirl" > "$tmp/m$sign.whirl"
  (cd "$tmp" && "$WHIRL" run "m$sign.whirl" --out="m$sign" --no-plot --quiet > /dev/null 2> "m$sign.err")
  ok $? "NTST 25: restart at the LP with DS ${sign}0.01 runs ($(head -1 "$tmp/m$sign.err"))"
done
uz m- | awk '{ r = sqrt(1 + sqrt(0.5)); exit !(NF == 2 && ($1 - r) ^ 2 < 1e-12 && $2 == 1) }'
ok $? "NTST 25, DS -0.01: on, to the outer orbit, as on the label's mesh ($(uz m-))"
uz m+ | awk '{ r = sqrt(1 - sqrt(0.5)); exit !(NF == 2 && ($1 - r) ^ 2 < 1e-12 && $2 == 0) }'
ok $? "NTST 25, DS +0.01: back to the inner orbit, as on the label's mesh ($(uz m+))"
tap_end

#!/bin/sh
# test/regress/restart_remesh.sh — a periodic label restarted onto another
# mesh (NTST of the run not the label's) keeps the orbit's rotations.
# Before, the rotations (AUTO's SETRTN: x(1) - x(0) = 2 pi k of an angle)
# were read from the stored orbit with the new mesh's node count, past the
# end of the stored array: the run's start then depended on the heap's
# contents (c.chu.4 of AUTO's chu demo converged or not with
# MALLOC_PERTURB_; ASan: heap-buffer-overflow), and a rotating orbit lost
# its rotation.  Model: theta' = w - sin(theta) (and y' = -y), whose rotations for w > 1
# have the period 2 pi / sqrt(w^2 - 1) (closed form), started from a data
# file of one turn (DAT, RK4 here) at w = 2, continued to w = 3 on NTST 10,
# then restarted on NTST 11 (the shortest overrun) and 40.  Those runs
# give w = 1.5 in both UZR and UZSTOP: one UZ there, which ends the run
# (before, two labels at the same w, a step apart).
# SPDX-License-Identifier: BSD-3-Clause
name=restart_remesh
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
cat > "$tmp/adler.c" <<'EOF'
#include <math.h>
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)d;
  f[0] = p[0] - sin(u[0]);
  f[1] = -u[1];
  return 0;
}
static const char *const xn[] = {"theta", "y"};
static const char *const pn[] = {"w"};
static const double par0[] = {2.0};
static const double u0[] = {0.0, 0.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "adler", .n = 2, .npar = 1, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .u0 = u0, .forcing_param = -1,
    .description = "Adler's equation (a rotating phase)"};
EOF
$CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o "$tmp/adler.so" "$tmp/adler.c" -lm
ok $? "Adler plug-in builds"
# one turn at w = 2 by RK4, rows t theta, until theta passes 2 pi
awk 'function f(x) { return 2 - sin(x) }
  BEGIN { h = 1e-3; t = 0; x = 0; printf "%.17g %.17g 0\n", t, x
    while (x < 2 * 3.14159265358979324) {
      k1 = f(x); k2 = f(x + h * k1 / 2); k3 = f(x + h * k2 / 2); k4 = f(x + h * k3)
      x += h * (k1 + 2 * k2 + 2 * k3 + k4) / 6; t += h
      printf "%.17g %.17g 0\n", t, x } }' > "$tmp/adler.dat"
printf "model = adler.so\nIPS = 2\nICP = [w, PERIOD]\nDAT = 'adler.dat'\nNTST = 10\nNCOL = 4\nIAD = 0\nDS = 0.01\nDSMAX = 0.1\nNMX = 200\nUZR = {w: [2.5]}\nUZSTOP = {w: [3]}\n" > "$tmp/turn.whirl"
(cd "$tmp" && "$WHIRL" run turn.whirl --no-plot --quiet > /dev/null 2> turn.err)
ok $? "rotations from the data file, w = 2 to 3 on NTST 10 ($(head -1 "$tmp/turn.err"))"
# the period at the UZ of w = $2 in $1/branches.tsv against 2 pi / sqrt(w^2 - 1),
# to 1e-6 (NTST 11 x NCOL 4 at w = 1.5: 3e-9 relative)
period_ok() {
  awk -F '\t' -v w="$2" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $3 == "UZ" && $c["w"] + 0 == w { n++; T = $c["period"] }
    END { e = 8 * atan2(1, 1) / sqrt(w * w - 1); d = T - e
          printf "period %.10g, closed form %.10g", T, e
          exit !(n == 1 && d * d < 1e-12 * e * e) }' "$tmp/$1/branches.tsv" 2>/dev/null
}
msg=$(period_ok turn.out 2.5)
ok $? "NTST 10: the period at w = 2.5 ($msg)"
for ntst in 11 40; do
  for perturb in 0 85 170; do
    printf "model = adler.so\nIPS = 2\nICP = [w, PERIOD]\nS = turn.out\nIRS = UZ1\nNTST = %s\nNCOL = 4\nIAD = 0\nDS = -0.01\nDSMAX = 0.1\nNMX = 200\nUZR = {w: [1.5]}\nUZSTOP = {w: [1.5]}\n" "$ntst" > "$tmp/re.whirl"
    rm -rf "$tmp/re.out"
    (cd "$tmp" && MALLOC_PERTURB_=$perturb "$WHIRL" run re.whirl --no-plot --quiet > /dev/null 2> re.err)
    ok $? "restart at w = 2.5 on NTST $ntst (MALLOC_PERTURB_ = $perturb) ($(head -1 "$tmp/re.err"))"
  done
  msg=$(period_ok re.out 1.5)
  ok $? "NTST $ntst: the period at w = 1.5 ($msg)"
done
tap_end

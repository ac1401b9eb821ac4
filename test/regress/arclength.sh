#!/bin/sh
# test/regress/arclength.sh — the step length of orbits and boundary-value
# problems measured as AUTO-07p measures it (bvp.f90, RNRMSQP; AUTO-07p
# manual, THL, THU):
#   |(u, p)|^2 = sum_i THU_i int_0^1 u_i^2 dt + sum_k THL_k p_k^2
# over the state and every free parameter, with AUTO's default THL =
# {PERIOD: 0} for periodic orbits when no THL is given (main.f90).  whirl
# sums the M = NTST NCOL + 1 node values (about M times the integral) and
# scales DS by sqrt(M); before, the parameters kept weight 1 there, so a
# step that changed only parameters moved them sqrt(M) times as far as
# AUTO's (kar: 13 times).  Closed forms: branches along which only
# parameters change, at a fixed step (DS = DSMIN = DSMAX).
# SPDX-License-Identifier: BSD-3-Clause
name=arclength
. "${top_srcdir:-.}/test/regress/tap.sh"
CC=${CC:-cc}
command -v "$CC" > /dev/null 2>&1 || { echo "1..0 # SKIP no C compiler"; exit 0; }
# twist.c: r' = r (mu - r^2), theta' = 1 + b r^2, the orbit r^2 = mu has
# the period 2 pi / (1 + b mu); in the scaled time of collocation it does
# not change with b, so a branch in b moves b and the period alone
# u' = 0, u(0) = 0, int (u + p - q) = 0: u = 0 and q = p, a straight line in
# the two free parameters
cat > "$tmp/line.c" <<'EOF'
#include <whirl/model.h>
static int rhs(double t, const double *u, const double *p, double *f, void *d) {
  (void)t, (void)u, (void)p, (void)d;
  f[0] = 0;
  return 0;
}
static int stpnt(double t, double *u, double *p, void *d) {
  (void)t, (void)d;
  u[0] = 0;
  p[0] = p[1] = 0;
  return 0;
}
static int bcnd(size_t nbc, const double *u0, const double *u1, const double *p,
                double *fb, void *d) {
  (void)nbc, (void)u1, (void)p, (void)d;
  fb[0] = u0[0];
  return 0;
}
static int icnd(size_t nint, const double *u, const double *uo, const double *ud,
                const double *upo, const double *p, double *fi, void *d) {
  (void)nint, (void)uo, (void)ud, (void)upo, (void)d;
  fi[0] = u[0] + p[0] - p[1];
  return 0;
}
static const char *const xn[] = {"u"};
static const char *const pn[] = {"p", "q"};
static const double par0[] = {0, 0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "line", .n = 1, .npar = 2, .rhs = rhs, .autonomous = 1,
                .x_names = xn, .p_names = pn},
    .par0 = par0, .stpnt = stpnt, .forcing_param = -1, .bcnd = bcnd, .icnd = icnd,
    .description = "u = 0, q = p"};
EOF
cp "$top_srcdir/test/regress/twist.c" "$tmp/"
for m in twist line; do
  $CC -std=c11 -O2 -shared -fPIC -I"$top_srcdir/lib" -o "$tmp/$m.so" "$tmp/$m.c" -lm
  ok $? "$m plug-in builds"
done
# the last point's value of column $2 in $1/branches.tsv
last() {
  awk -F '\t' -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
    { v = $h[c] } END { print v }' "$tmp/$1/branches.tsv" 2>/dev/null
}
# run NAME.whirl in tmp: a TAP line TEXT with its first message
run_ok() {
  (cd "$tmp" && "$WHIRL" run "$1.whirl" --no-plot --quiet > /dev/null 2> "$1.err")
  ok $? "$2 ($(head -1 "$tmp/$1.err"))"
}
# the orbit r^2 = mu = 0.5 at b = 0.5 (from the Hopf point at mu = 0)
printf 'model = twist.so\nIPS = 1\nICP = [mu]\nISP = 2\nDS = 0.01\nDSMAX = 0.05\nNMX = 200\nUZSTOP = {mu: [0.5]}\n' > "$tmp/eq.whirl"
printf 'model = twist.so\nIPS = 2\nICP = [mu, PERIOD]\nS = eq.out\nIRS = HB1\nNTST = 20\nDS = 0.01\nDSMAX = 0.1\nNMX = 300\nUZSTOP = {mu: [0.5]}\n' > "$tmp/po.whirl"
(cd "$tmp" && "$WHIRL" run eq.whirl --no-plot --quiet > /dev/null 2>&1 &&
  "$WHIRL" run po.whirl --no-plot --quiet > /dev/null 2> po.err)
ok $? "the orbit at mu = 0.5 ($(head -1 "$tmp/po.err"))"
# 10 steps of 0.01 in b (NTST 20, NCOL 4: M = 81; before, 0.09 each)
printf 'model = twist.so\nIPS = 2\nICP = [b, PERIOD]\nS = po.out\nIRS = UZ1\nNTST = 20\nISP = 0\nDS = 0.01\nDSMIN = 0.01\nDSMAX = 0.01\nNMX = 11\n' > "$tmp/b.whirl"
run_ok b "orbits in b, the period free"
b=$(last b.out b)
echo "$b" | awk '{ d = $1 - 0.6; exit !(d * d < 1e-16) }'
ok $? "THL absent (AUTO's PERIOD weight 0): 10 steps of DS = 0.01 move b by 0.1 ($b)"
# with THL = {PERIOD: 1} the period counts: each step is ds^2 = db^2 + dT^2
# along T(b) = 2 pi / (1 + b mu), so b moves less (by the arc length of
# the curve (b, T(b)) of 0.1, to the secant's accuracy)
printf 'THL = {PERIOD: 1}\n' | cat "$tmp/b.whirl" - > "$tmp/bt.whirl"
run_ok bt "orbits in b with THL = {PERIOD: 1}"
bt=$(last bt.out b)
echo "$bt" | awk '{ pi = 4 * atan2(1, 1); mu = 0.5; s = 0; n = 200000; h = ($1 - 0.5) / n
  for (i = 0; i < n; i++) { x = 0.5 + (i + 0.5) * h; d = 2 * pi * mu / (1 + x * mu) ^ 2; s += h * sqrt(1 + d * d) }
  exit !((s - 0.1) ^ 2 < 1e-8) }'
ok $? "THL = {PERIOD: 1}: the arc length of (b, T(b)) over the 10 steps is 0.1 to 1e-4 (b = $bt)"
# a boundary-value problem: p and q free, each step ds^2 = dp^2 + dq^2
printf 'model = line.so\nIPS = 4\nICP = [p, q]\nNBC = 1\nNINT = 1\nNTST = 10\nNCOL = 4\nDS = 0.1\nDSMIN = 0.1\nDSMAX = 0.1\nNMX = 11\n' > "$tmp/line.whirl"
run_ok line "a boundary-value problem moving its free parameters alone"
p=$(last line.out p)
q=$(last line.out q)
echo "$p $q" | awk '{ e = sqrt(0.5); exit !(NF == 2 && ($1 - e) ^ 2 < 1e-16 && ($2 - e) ^ 2 < 1e-16) }'
ok $? "10 steps of DS = 0.1 reach p = q = 1/sqrt 2 (p $p, q $q; before, sqrt(41) times as far)"
# THL on a BVP's free parameter (ICP(2)): THL = {q: 0} takes q out of the
# step (AUTO's c.man.2 does so on PAR(6..9)), so each step moves p by DS
# (before the fix, a THL on ICP(2) alone was ignored: p by DS/sqrt 2)
printf 'THL = {q: 0}\n' | cat "$tmp/line.whirl" - > "$tmp/lineq.whirl"
run_ok lineq "THL = {q: 0} on the BVP's free parameter"
p=$(last lineq.out p)
echo "$p" | awk '{ exit !(($1 - 1) ^ 2 < 1e-16) }'
ok $? "THL = {q: 0}: 10 steps of DS = 0.1 move p by 1 ($p)"
tap_end

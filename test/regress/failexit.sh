#!/bin/sh
# test/regress/failexit.sh — inputs out of range are refused up front (exit 2,
# one message naming the option and the valid range), runs that fail say so
# (exit 1, one line on stderr) and nothing the library or LAPACK prints ever
# reaches stdout.  Every command is bounded by `timeout` so that a regression
# (an endless run) fails the test instead of hanging it; 120 s, not 20: the
# 128-harmonic run takes 3-5 s alone and passed 20 s on a machine running two
# test suites at once.
# SPDX-License-Identifier: BSD-3-Clause
set -u
WHIRL="$(cd "${top_builddir:-.}" && pwd)/drivers/whirl"
SRC="$(cd "${top_srcdir:-.}" && pwd)"
CC=${CC:-cc}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-failexit.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

# expect STATUS PATTERN CMD...: the command exits with STATUS within 20 s and
# its stderr matches PATTERN (a grep -E expression) on a single line, or is
# empty when PATTERN is "".
expect() {
  want=$1; pattern=$2; shift 2
  timeout 120 "$WHIRL" "$@" > "$tmp/stdout" 2> "$tmp/stderr"
  rc=$?
  if [ -n "$pattern" ]; then grep -Eq -- "$pattern" "$tmp/stderr"; else [ ! -s "$tmp/stderr" ]; fi
  found=$?
  msg=$(tail -n 1 "$tmp/stderr")
  # no C source locations ("(cont.c:683)") in what the user reads
  ! grep -Eq '\([A-Za-z0-9_/-]+\.[ch]:[0-9]+\)' "$tmp/stderr"
  clean=$?
  ok $(( rc != want || found != 0 || clean != 0 )) "exit $rc (want $want): whirl $* : $msg"
}

cd "$tmp" || exit 1

# defect 4: an absurd thread count is refused, not a libgomp crash
expect 2 "threads must be in 0\.\.1024 \(got 100000\)" \
  sfd basins --omega 1.78 --points 20 --threads 100000 --no-plot --quiet --out b1
expect 2 "threads must be in 0\.\.1024 \(got -1\)" \
  sfd basins --omega 1.78 --points 20 --threads -1 --no-plot --quiet --out b1

# defect 8: tolerances so loose that integration crawls are refused
expect 2 "rtol must be in \[1e-13, 0\.001\] \(got 1\)" \
  sfd basins --omega 1.78 --points 20 --rtol 1 --no-plot --quiet --out b2
expect 2 "atol must be in \(0, 0\.001\] \(got 16\)" \
  sfd basins --omega 1.78 --points 20 --atol 16 --no-plot --quiet --out b2
for cmd in "simulate --omega 1.5 --out b3" "sweep --from 1 --to 1.1 --step 0.1 --out b3" \
           "onset --from 1 --to 2"; do
  # shellcheck disable=SC2086
  expect 2 "rtol must be in" sfd $cmd --rtol 0.5
done

# defect 7: a branch that ends in failure exits 1 with one line on stderr
# naming the branch, the point and the reason; the points are kept.  Two
# one-state plug-ins, x' = p - x (or p - x - x^3): `domain` reports a domain
# error (recoverable status 1) for p > 0.5, which persists down to DSMIN;
# `badjac` has a Jacobian of the wrong sign, so Newton diverges on the first
# step ("branch 1: 1 points", exit 0 before).
cat > plug.c <<'EOC'
#include <whirl/model.h>
static int rhs(double t, const double *x, const double *p, double *f, void *d) {
  (void)t, (void)d;
  f[0] = p[0] - x[0] - (BADJAC ? x[0] * x[0] * x[0] : 0.0);
  return !BADJAC && p[0] > 0.5;
}
static int jac(double t, const double *x, const double *p, double *J, void *d) {
  (void)t, (void)p, (void)d;
  J[0] = BADJAC ? 1.0 + 3.0 * x[0] * x[0] : -1.0;
  return 0;
}
static const char *const pn[] = {"p"};
static const double par0[] = {0.0};
const whirl_model whirl_model_def = {
    .abi = WHIRL_MODEL_ABI,
    .problem = {.name = "plug", .n = 1, .npar = 1, .rhs = rhs, .jac_x = jac,
                .autonomous = 1, .p_names = pn},
    .par0 = par0, .forcing_param = -1};
EOC
built=0
$CC -std=c11 -shared -fPIC -I"$SRC/lib" -DBADJAC=0 -o domain.so plug.c > cc.log 2>&1 &&
  $CC -std=c11 -shared -fPIC -I"$SRC/lib" -DBADJAC=1 -o badjac.so plug.c >> cc.log 2>&1 && built=1
ok $(( built != 1 )) "the test plug-ins build"
printf 'model = ./domain.so\nICP = [p]\nNMX = 200\nDS = 0.1\nDSMAX = 0.1\nRL1 = 10\n' > domain.whirl
expect 1 "^whirl run: domain\.whirl: branch 1 failed after point [0-9]+: branch ended at p = 0\.[45][0-9]*: model domain error persisted down to DSMIN$" \
  run domain.whirl --quiet
ok $(( $(wc -l < "$tmp/stderr") != 1 )) "one line on stderr"
grep -q "failed: branch ended at p" domain.out/run.log
ok $? "the partial branch is kept, run.log says it failed"
printf 'model = ./badjac.so\nICP = [p]\nNMX = 20\nRL1 = 10\n' > badjac.whirl
expect 1 "^whirl run: badjac\.whirl: branch 1 failed after point 1: branch ended at p = 0: no convergence with minimum step size \(DSMIN\)$" \
  run badjac.whirl --quiet
printf 'model = ./domain.so\nICP = [p]\nNMX = 3\nDS = 0.1\nRL1 = 10\n' > nmx.whirl
expect 0 "" run nmx.whirl --quiet
printf 'model = ./domain.so\nICP = [p]\nNMX = 100\nDS = 0.1\nRL1 = 0.3\n' > rl1.whirl
expect 0 "" run rl1.whirl --quiet

# defect 7, sfd response: unphysical parameters are refused up front (1e308
# made LAPACK print 1200 lines into the results table on stdout, or gave
# "0 branches" and exit 0); a response without any branch, or with a branch
# ending at DSMIN, is a failure
expect 2 "lambda must be in \(0, 100\] \(got 1e\+308\)" sfd response --lambda 1e308 --no-plot --quiet --out r1
ok $(( $(wc -c < "$tmp/stdout") != 0 )) "nothing on stdout ($(wc -l < "$tmp/stdout") lines)"
expect 2 "delta must be in \[0, 10\] \(got 1e\+308\)" sfd response --delta 1e308 --no-plot --quiet --out r1
expect 2 "FE must be in \(-1, 1\)" sfd simulate --omega 1.5 --fe 1.5 --out r1
expect 2 "zeta must be in \[0, 10\]" sfd basins --omega 1.5 --zeta 11 --out r1
expect 1 "^whirl sfd response: no branch of orbits found" sfd response --delta 1e-300 --no-plot --quiet --out r2
expect 1 "^whirl sfd response: branch 1 failed after point [0-9]+ \(Omega = 0\.[0-9]+, eps = 1\): model domain error persisted down to DSMIN$" \
  sfd response --lambda 1e-300 --no-plot --quiet --out r3
[ -s r3/branches.tsv ]
ok $? "the failed response's tables are written"
expect 0 "" sfd response --omega-max 2 --no-plot --quiet --out r4

# defect 8: `whirl run` with the SFD model at |FE| >= 1 is refused up front
# (it crawled along the housing for minutes); a continuation in FE ends at
# the housing as a domain error, at once
printf 'model = sfd\nIPS = 2\nICP = [Omega]\nPAR = {Omega: 1.2, FE: 1.5}\nNMX = 20\n' > fe.whirl
expect 2 "^whirl run: fe\.whirl:4: PAR: model 'sfd_fixed': FE must be in \(-1, 1\)" run fe.whirl --quiet
printf 'model = sfd\nIPS = 2\nICP = [FE]\nPAR = {Omega: 1.2, FE: 0.5}\nNMX = 400\nRL1 = 5\n' > fe2.whirl
expect 1 "branch 1 failed after point [0-9]+: branch ended at FE = 0\.99[0-9]*: model domain error" run fe2.whirl --quiet

# defect 8: sizes are checked first (--ntst 99999999999 busy-looped)
expect 2 "need 2 <= --ntst <= 100000" sfd response --method colloc --ntst 99999999999 --no-plot --out n1
expect 2 "need 2 <= --ntst <= 100000" sfd nonsync --method colloc --ntst 99999999999 --no-plot --out n1

# defect 8: a start at the housing ran for over 15 minutes without output;
# a step budget per forcing period stops it with a message
expect 1 "needed more than 1000000 steps in one forcing period \(period 1, .*the journal is at the housing \(eps = 0\.99999" \
  sfd simulate --omega 1.5 --periods 4 --y0 0.999999 --no-plot --out s1
[ ! -e s1 ]
ok $? "nothing written"
expect 2 "max-steps must be >= 100" sfd simulate --omega 1.5 --max-steps 5 --out s1

# defect 8: --harmonics 128..200 always failed ("invalid argument": the
# seed orbit had 256 samples, fewer than the 2N + 1 coefficients)
expect 0 "" sfd response --method hbm --harmonics 128 --oversampling 2 --omega-max 0.07 --no-plot --quiet --out h1
cnt=$(grep -c '^1	' h1/branches.tsv 2>/dev/null)
[ "${cnt:-0}" -ge 3 ]
ok $? "the 128-harmonic branch has points"

# defect 10: library messages reach the user without source locations
printf 'model = ./domain.so\nICP = [p]\nPAR = {p: 1}\nNMX = 5\n' > start.whirl
expect 1 "^whirl run: start\.whirl: cannot start the branch: start: Newton did not converge at p = 1 from the given x0 \(domain error\)$" \
  run start.whirl --quiet

# defect 10, sfd region: --ds-max below the first step (1e-3) failed with
# an internal message; too small a --ds-max is refused with the range; the
# upper curve was cut at 5001 points (NMX) without a word (at --ds-max
# 0.002 it stopped at lambda = 0.88 of 1.5)
expect 0 "" sfd region --ds-max 1e-4 --lambda-min 0.01 --lambda-max 0.012 --no-plot --quiet --out g1
expect 2 "ds-max must be in \[1e-4, 1\] \(got 5e-05\)" sfd region --ds-max 5e-5 --out g1
expect 0 "" sfd region --ds-max 0.002 --no-plot --quiet --out g2
top=$(awk '!/^#/ && NF > 3 {print $1}' g2/upper.tsv 2>/dev/null | sort -g | tail -n 1)
awk -v t="${top:-0}" 'BEGIN { exit !(t >= 1.4999) }'
ok $? "the upper curve reaches lambda-max 1.5 (got ${top:-nothing})"

# defect 10: a plug-in exporting whirl_model_def as a function was read as
# the struct (an unaligned read of machine code, UBSan's report)
printf '#include <whirl/model.h>\nwhirl_model whirl_model_def(void);\nwhirl_model whirl_model_def(void) { whirl_model m = {0}; return m; }\n' > fn.c
$CC -std=c11 -shared -fPIC -I"$SRC/lib" -o fn.so fn.c >> cc.log 2>&1
printf 'model = ./fn.so\nICP = [p]\n' > fn.whirl
expect 2 "^whirl run: fn\.whirl:1: model: plug-in '\./fn\.so': the symbol 'whirl_model_def' is (a function|not aligned)" run fn.whirl

echo "1..$n"
[ "$fails" -eq 0 ]

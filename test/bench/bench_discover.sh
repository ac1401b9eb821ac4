#!/bin/sh
# test/bench/bench_discover.sh — what the discovery step (DISCOVER,
# doc/discovery.md) costs and how reliably random seeds find every branch:
#  1. cost: examples/discover/sfd-rotating.whirl (equilibria, 4 unknowns)
#     and examples/jeffcott/isola.whirl (harmonic balance, 72 unknowns),
#     each run with and without DISCOVER in pairs, REPEAT times (default 3):
#     median wall times, and from run.log the search, fold-locus and tracing
#     times, starts, deflated Newton iterations and factorisations;
#  2. reliability: the fraction of seeds 1..SEEDS (default 10) whose run
#     finds both branches, for budgets 1, 2, 5, 10, 20, 40 (Jeffcott with
#     ISP = 0: no Floquet multipliers while tracing, for speed).
# Not a test: figures go into doc/discovery.md with the machine.
#   sh test/bench/bench_discover.sh [REPEAT [SEEDS]]   (from the build tree)
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
WHIRL="$top_builddir/drivers/whirl"
case $WHIRL in /*) ;; *) WHIRL="$(pwd)/$WHIRL" ;; esac
case $top_srcdir in /*) ;; *) top_srcdir="$(pwd)/$top_srcdir" ;; esac
repeat=${1:-3}
seeds=${2:-10}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whirl-bench.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
cp "$top_srcdir/examples/discover/sfd-rotating.whirl" sfd.whirl
cp "$top_srcdir/examples/jeffcott/isola.whirl" jeff.whirl
for f in sfd jeff; do sed '/^DISCOVER/d' $f.whirl > $f-plain.whirl; done
now() { date +%s.%N; }
echo "# $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
printf 'case\trun\tplain_s\tdiscover_s\tratio\tsearch_s\tloci_s\ttrace_new_s\tstarts\tnewton_its\tfactorisations\n'
for c in sfd jeff; do
  for r in $(seq 1 "$repeat"); do
    t0=$(now); "$WHIRL" run $c-plain.whirl --quiet --OUT=p > /dev/null || exit 1
    t1=$(now); "$WHIRL" run $c.whirl --quiet --OUT=d > /dev/null || exit 1
    t2=$(now)
    line=$(grep '^discovery: .* s searching' d/run.log)
    echo "$line" | awk -v c=$c -v r=$r -v a="$(echo "$t1 - $t0" | bc -l)" -v b="$(echo "$t2 - $t1" | bc -l)" '{
      for (i = 1; i <= NF; i++) {
        if ($(i + 1) == "starts") st = $i
        if ($(i + 1) == "deflated") it = $i
        if ($(i + 1) == "factorisations,") fa = $i
        if ($(i + 1) == "s" && $(i + 2) == "searching,") se = $i
        if ($(i + 1) == "s" && $(i + 2) == "on") lo = $i
        if ($(i + 1) == "s" && $(i + 2) == "tracing") tr = $i
      }
      printf "%s\t%d\t%.3f\t%.3f\t%.2f\t%s\t%s\t%s\t%s\t%s\t%s\n", c, r, a, b, b / a, se, lo, tr, st, it, fa }'
  done
done | tee times.tsv
for c in sfd jeff; do
  awk -F '\t' -v c=$c '$1 == c { print $5 }' times.tsv | sort -g |
    awk -v c=$c '{ t[NR] = $1 } END { printf "# %s: median (run with DISCOVER) / (run without) = %.2f over %d pairs\n", c, t[int((NR + 1) / 2)], NR }'
  awk -F '\t' -v c=$c '$1 == c { print $6 / $3 }' times.tsv | sort -g |
    awk -v c=$c '{ t[NR] = $1 } END { printf "# %s: median search time / tracing time of the start branch = %.3f\n", c, t[int((NR + 1) / 2)] }'
done
printf 'case\tbudget\tseeds\tfound_all\tfraction\n'
for c in sfd jeff; do
  for b in 1 2 5 10 20 40; do
    hit=0
    for s in $(seq 1 "$seeds"); do
      "$WHIRL" run $c.whirl --ISP=0 --DISCOVER_STARTS=$b --DISCOVER_SEED=$s --OUT=f > f.txt 2>&1
      grep -q '^discovery: 2 branches' f.txt && hit=$((hit + 1))
    done
    printf '%s\t%d\t%d\t%d\t%.2f\n' $c $b "$seeds" $hit "$(echo "$hit / $seeds" | bc -l)"
  done
done

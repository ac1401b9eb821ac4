#!/bin/sh
# test/regress/layers.sh — the library's layers, checked: a file of lib/
# may include headers of its own layer and of the layers below it, never of
# a layer above (util < linalg < core < ode < systems < analysis < run <
# models).  Every public header of lib/whirl/ is given its layer here, so a
# new header must be placed before it can be used.
#
#   test/regress/layers.sh [LIBDIR]     (default: $top_srcdir/lib)
# SPDX-License-Identifier: BSD-3-Clause
set -u
top=${1:-${top_srcdir:-.}}
lib=$top/lib
n=0
fails=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fails=$((fails + 1)); fi; }

rank_of_layer() {
  case $1 in
    util) echo 0 ;; linalg) echo 1 ;; core) echo 2 ;; ode) echo 3 ;;
    systems) echo 4 ;; analysis) echo 5 ;; run) echo 6 ;;
    whirl) echo 7 ;;  # the umbrella header whirl.h
    *) echo "" ;;
  esac
}
# the layer of each public header
layer_of_header() {
  case $1 in
    status.h|points.h|dynlib.h) echo util ;;
    linsol.h) echo linalg ;;
    problem.h|system.h|cont.h|branch.h) echo core ;;
    ode.h|floquet.h) echo ode ;;
    equilibrium.h|hbm.h|colloc.h|fold.h|hopf.h|bploc.h|trloc.h|periodic.h|bvp.h) echo systems ;;
    spectrum.h|section.h|basins.h|deflate.h) echo analysis ;;
    runfile.h|model.h|run.h|solution.h|auto_constants.h|auto_files.h) echo run ;;
    whirl.h) echo whirl ;;
    *) echo "" ;;
  esac
}

# every public header has a layer
unplaced=""
for h in "$lib"/whirl/*.h; do
  b=$(basename "$h")
  [ -n "$(layer_of_header "$b")" ] || unplaced="$unplaced $b"
done
[ -z "$unplaced" ]
ok $? "every public header of lib/whirl has a layer${unplaced:+ (not placed:$unplaced)}"

# no include runs up the layers
bad=""
count=0
for f in "$lib"/*/*.c "$lib"/*/*.h; do
  dir=$(basename "$(dirname "$f")")
  [ "$dir" = whirl ] && dir=$(layer_of_header "$(basename "$f")")
  r=$(rank_of_layer "$dir")
  [ -n "$r" ] || continue
  for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]\([^>"]*\)[>"].*/\1/p' "$f"); do
    case $inc in
      whirl/*) l=$(layer_of_header "${inc#whirl/}") ;;
      ../*/*) l=${inc#../}; l=${l%%/*} ;;
      */*) l=${inc%%/*}; [ -d "$lib/$l" ] || continue ;;
      *) continue ;;  # same directory, or a system header
    esac
    [ -n "$l" ] || continue
    ri=$(rank_of_layer "$l")
    count=$((count + 1))
    if [ "$ri" -gt "$r" ]; then
      bad="$bad ${f#"$lib"/} ($dir) includes $inc ($l);"
    fi
  done
done
[ -z "$bad" ]
ok $? "no file of lib/ includes a header of a layer above its own ($count includes checked)${bad:+:$bad}"

# a header's implementation lives in its layer (whirl/X.h and lib/*/X.c)
misplaced=""
for h in "$lib"/whirl/*.h; do
  b=$(basename "$h" .h)
  want=$(layer_of_header "$b.h")
  for c in "$lib"/*/"$b".c; do
    [ -f "$c" ] || continue
    d=$(basename "$(dirname "$c")")
    [ "$d" = "$want" ] || misplaced="$misplaced ${c#"$lib"/} (header's layer: $want);"
  done
done
[ -z "$misplaced" ]
ok $? "each public header's implementation is in the header's layer${misplaced:+:$misplaced}"

# the rotor module: public headers only
inside=""
nrot=0
for f in "$top"/rotor/*.c "$top"/rotor/whirl/*.h "$top"/rotor/whirl/rotor/*.h; do
  [ -f "$f" ] || continue
  for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*\([<"][^>"]*[>"]\).*/\1/p' "$f"); do
    nrot=$((nrot + 1))
    case $inc in
      \<whirl/rotor/*|\<whirl/rotor.h\>) ;;
      \<whirl/*) h=${inc#<whirl/}; h=${h%>}
        [ -f "$lib/whirl/$h" ] || inside="$inside ${f#"$top"/} includes $inc (no public header);" ;;
      \"*/*|\"../*) inside="$inside ${f#"$top"/} includes $inc;" ;;
      *) ;;
    esac
  done
  grep -q 'lib/\(core\|linalg\|ode\|systems\|analysis\|run\|util\)/' "$f" &&
    grep -n '#.*include.*lib/' "$f" > /dev/null && inside="$inside ${f#"$top"/} names lib/ internals;"
done
[ -z "$inside" ] && [ $nrot -gt 0 ]
ok $? "the rotor module includes libwhirl's public headers only ($nrot includes checked)${inside:+:$inside}"

# the built library exports no model: no symbol of the rotor module
so="${top_builddir:-.}/lib/.libs/libwhirl.so"
if [ -f "$so" ] && command -v nm > /dev/null 2>&1; then
  models=$(nm -D --defined-only "$so" | awk '{print $3}' | grep -i 'sfd\|rotor\|jeffcott')
  [ -z "$models" ]
  ok $? "libwhirl.so exports no model symbol ($(nm -D --defined-only "$so" | grep -c ' T ') functions)${models:+: $(echo $models | head -c 200)}"
fi

echo "1..$n"
[ $fails -eq 0 ]

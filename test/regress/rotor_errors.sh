#!/bin/sh
# test/regress/rotor_errors.sh — malformed rotor files (doc/rotor-file.md)
# given to `whirl rotor modes` and `whirl rotor campbell`.  For every case:
#   - the exit status is 2;
#   - stderr is exactly ONE line, "whirl rotor: case.rotor:LINE: ...",
#     with the line of the mistake and the case's regex;
#   - modes prints nothing on stdout, campbell leaves no output directory
#     and no temporary directory (*.tmp.*) behind.
# A positive control first checks that the base file works.
# SPDX-License-Identifier: BSD-3-Clause
name=roterr
. "${top_srcdir:-.}/test/regress/tap.sh"

base='material steel E=211e9 G=81.2e9 rho=7810
shaft from=0 to=4 length=1 od=0.05 material=steel
disk node=2 mass=10 ip=0.1 it=0.05
bearing node=0 kyy=1e6 kzz=1e6
bearing node=4 kyy=1e6 kzz=1e6'

# ---- positive control ------------------------------------------------------
printf '%s\n' "$base" > good.rotor
"$WHIRL" rotor modes good.rotor --speed 1000 > good.tsv 2> good.err
ok $? "the base file: whirl rotor modes exits 0"
head -n 1 good.tsv | grep -q '^mode	omega_rad_s	freq_hz	log_dec	whirl$'
ok $? "the base file: the header of the modes table"
[ "$(wc -l < good.tsv)" -eq 7 ]
ok $? "the base file: six modes"
"$WHIRL" rotor campbell good.rotor -o good.out --speeds 0:3000:7 --quiet 2> good.err
ok $? "the base file: whirl rotor campbell exits 0"
[ -f good.out/campbell.tsv ] && [ -f good.out/critical.tsv ]
ok $? "the base file: campbell.tsv and critical.tsv written"

# check NAME LINE REGEX: case.rotor is already written
check() {
  name=$1 line=$2 re=$3
  "$WHIRL" rotor modes case.rotor > out.txt 2> err.txt
  rc=$?
  "$WHIRL" rotor campbell case.rotor -o case.out --speeds 0:1000:3 > out2.txt 2> err2.txt
  rc2=$?
  good=1
  [ $rc -eq 2 ] && [ $rc2 -eq 2 ] || good=0
  [ "$(wc -l < err.txt)" -eq 1 ] && [ "$(wc -l < err2.txt)" -eq 1 ] || good=0
  grep -q "^whirl rotor: case\.rotor:$line: .*$re" err.txt || good=0
  cmp -s err.txt err2.txt || good=0
  [ -s out.txt ] && good=0
  [ -e case.out ] && good=0
  for d in case.out.tmp.*; do [ -e "$d" ] && good=0; done
  if [ $good -eq 1 ]; then ok 0 "$name"; else
    ok 1 "$name"
    echo "#   exit $rc / $rc2, stderr:"; sed 's/^/#   /' err.txt err2.txt
  fi
  rm -rf case.out case.out.tmp.*
}

# one extra line (line 6) after the base
extra() {
  printf '%s\n%s\n' "$base" "$4" > case.rotor
  check "$1" "$2" "$3"
}
# a whole file
whole() {
  printf '%s\n' "$4" > case.rotor
  check "$1" "$2" "$3"
}

extra "unknown keyword" 6 "unknown keyword 'spring'" 'spring node=1 k=1e6'
extra "unknown key" 6 "unknown key 'colour' for disk" 'disk node=1 mass=1 colour=red'
extra "bad number" 6 "kyy: '1e6x' is not a number" 'bearing node=1 kyy=1e6x'
extra "not key=value" 6 "'2' is not key=value" 'disk 2 mass=1'
extra "node not an integer" 6 "node must be a node number" 'disk node=1.5 mass=1'
extra "negative length" 6 "length must be > 0" 'shaft from=4 to=5 length=-1 od=0.05 material=steel'
extra "negative diameter" 6 "od must be > 0" 'shaft from=4 to=5 length=1 od=-0.05 material=steel'
extra "negative inner diameter" 6 "id must be >= 0" 'shaft from=4 to=5 length=1 od=0.05 id=-0.01 material=steel'
extra "shaft inner >= outer diameter" 6 "inner diameter id=0.05 must be smaller" \
  'shaft from=4 to=5 length=1 od=0.05 id=0.05 material=steel'
extra "disk inner >= outer diameter" 6 "disk: inner diameter" \
  'disk node=1 width=0.07 od=0.05 id=0.06 material=steel'
extra "shaft to <= from" 6 "to=4 must be greater than from=4" 'shaft from=4 to=4 length=1 od=0.05 material=steel'
extra "node out of range" 6 "disk: node 9 is not on the shaft (nodes 0..4)" 'disk node=9 mass=1'
extra "bearing off the shaft" 6 "bearing: node 5 is not on the shaft" 'bearing node=5 kyy=1'
extra "nonlinear element on a missing node" 6 "sfd-short-pi: node 7 is not on the shaft" \
  'sfd-short-pi node=7 radius=0.05 length=0.02 clearance=1e-4 viscosity=0.01'
extra "material with G > 10 E (Poisson's ratio -1)" 6 "Poisson's ratio -1, outside" \
  'material glass E=1e12 G=1e25 rho=1'
extra "damping without a coefficient" 6 "damping: give alpha=" 'damping'
extra "negative damping" 6 "beta must be >= 0" 'damping beta=-1e-5'
extra "unknown material" 6 "unknown material 'brass'" 'shaft from=4 to=5 length=1 od=0.05 material=brass'
extra "film element with zero clearance" 6 "clearance must be > 0" \
  'sfd-short-pi node=1 radius=0.05 length=0.02 clearance=0 viscosity=0.01'
extra "journal bearing with zero clearance" 6 "clearance must be > 0" \
  'journal-short node=1 radius=0.05 length=0.02 clearance=0 viscosity=0.01'
extra "fluid inertia without density" 6 "sfd-inertia needs density=" \
  'sfd-inertia node=1 radius=0.05 length=0.02 clearance=1e-4 viscosity=0.01'
extra "a key of another kind" 6 "unknown key 'k1' for journal-short" \
  'journal-short node=1 radius=0.05 length=0.02 clearance=1e-4 viscosity=0.01 k1=3'
extra "rub without contact stiffness" 6 "rub needs k-contact=" 'rub node=1 clearance=1e-4'
extra "unknown pedestal" 6 "bearing: unknown pedestal 'P'" 'bearing node=2 kyy=1 pedestal=P'
extra "pedestal without a name" 6 "pedestal needs a name" 'pedestal mass=3'
extra "duplicate material" 6 "material 'steel' defined twice (first at line 1)" 'material steel E=1 G=1 rho=1'
extra "duplicate disk" 6 "a disk at node 2 is already defined (line 3)" 'disk node=2 mass=1'
extra "duplicate shaft element" 6 "between nodes 1 and 2 is defined twice (first at line 2)" \
  'shaft from=1 to=2 length=1 od=0.05 material=steel'
# a shaft over 10^6 nodes with one element given again: found at once (the
# check was quadratic in the elements: libFuzzer's timeout on the first line)
printf '%s\n%s\n%s\n' "$base" 'shaft from=4 to=1000000 length=1 od=0.05 material=steel' \
  'shaft from=500000 to=500001 length=1 od=0.05 material=steel' > case.rotor
timeout 60 "$WHIRL" rotor modes case.rotor > out.txt 2> err.txt
rc=$?
[ $rc -eq 2 ] && grep -q "case\.rotor:7: .*between nodes 500000 and 500001 is defined twice (first at line 6)" err.txt
ok $? "a 10^6-element shaft given twice: exit 2 within 60 s (got $rc): $(head -c 200 err.txt)"
extra "duplicate bearing" 6 "a bearing at node 4 is already defined (line 5)" 'bearing node=4 kyy=1'
extra "duplicate key" 6 "key 'mass' given twice" 'disk node=1 mass=1 mass=2'
extra "disk given both ways" 6 "disk: give either mass= \[ip= it=\] or width= od= \[id=\] material=" \
  'disk node=1 mass=3 width=0.07 od=0.2 material=steel'
extra "elements= not to - from" 6 "elements=3 but from=4 to=6 makes 2 elements" \
  'shaft from=4 to=6 elements=3 length=1 od=0.05 material=steel'
extra "pedestal without mass" 6 "pedestal: mass must be > 0" 'pedestal P mass=0 kyy=1e6'
extra "a second element of one kind at a node" 7 "cubic at node 1 is already defined (line 6)" 'cubic node=1 k1=1 k3=1
cubic node=1 k1=2 k3=2'
extra "bad gravity direction" 6 "direction must be" 'gravity g=9.81 direction=down'
extra "speed range reversed" 6 "to=5 must be greater than from=10" 'speed from=10 to=5 unit=rpm'
extra "bad speed unit" 6 "unit must be rpm, rad/s or hz" 'speed from=0 to=5 unit=rps'
whole "duplicate gravity" 2 "gravity given twice (first at line 1)" "gravity g=9.81 direction=-z
gravity g=9.81 direction=-z
$base"
whole "duplicate title" 2 "title given twice" "title a
title b
$base"
whole "a rotor with no mass" 3 "the rotor has no mass" 'material air E=1e9 G=4e8 rho=0
shaft from=0 to=2 length=1 od=0.05 material=air
bearing node=0 kyy=1e6 kzz=1e6'
whole "a gap in the shaft" 3 "no shaft element between nodes 2 and 3" 'material steel E=211e9 G=81.2e9 rho=7810
shaft from=0 to=2 length=1 od=0.05 material=steel
shaft from=3 to=4 length=1 od=0.05 material=steel'
whole "no shaft" 1 "no shaft" 'material steel E=211e9 G=81.2e9 rho=7810'

# a file that cannot be read: exit 2, one line, nothing written
"$WHIRL" rotor modes missing.rotor > out.txt 2> err.txt
rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q '^whirl rotor: missing.rotor: cannot open' err.txt && [ ! -s out.txt ]
ok $? "a missing rotor file: exit 2, one message"

tap_end

# test/auto-demos/maxref.awk — for the special points of whirl that AUTO
# does not print (run.sh's "whirl only" lines), whether they differ from
# one of AUTO's in the MAX U(i) columns alone, and then whose MAX the
# converged reference (orbitmax.c: the demo's flow integrated by CVODE
# from each mesh point of whirl's orbit) is closer to.
#   awk -f maxref.awk MASK LABELLED AUTO REF WHIRL_ONLY
# MASK: one line, the value positions (1 = the first after TY) of the MAX
# columns, each as POS:COMPONENT; LABELLED: whirl's points as "LAB TY
# values"; AUTO: AUTO's points as "TY values"; REF: "LAB max_U(1) ...";
# WHIRL_ONLY: run.sh's "- TY values" lines.  Prints one line per whirl-only
# point, "max-whirl TY PAR", "max-auto TY PAR" or "other TY PAR", and last
# the counts "MAXREF n_whirl n_auto n_other".
# SPDX-License-Identifier: BSD-3-Clause
function unit(a,   e, m) {
  m = a < 0 ? -a : a
  if (m < 1e-6) return 1e-6
  e = int(log(m) / log(10) + 100) - 100
  if (10 ^ e > m) e--
  return 10 ^ (e - 5)
}
function absd(a) { return a < 0 ? -a : a }
FILENAME == ARGV[1] {
  for (i = 1; i <= NF; i++) { split($i, pc, ":"); ismax[pc[1]] = pc[2] }
  next
}
FILENAME == ARGV[2] { key = $2; for (i = 3; i <= NF; i++) key = key " " $i; lab[key] = $1; next }
FILENAME == ARGV[3] { a[++na] = $0; next }
FILENAME == ARGV[4] { for (i = 2; i <= NF; i++) ref[$1, i - 1] = $i; hasref[$1] = 1; next }
$1 == "-" {
  key = $2; for (i = 3; i <= NF; i++) key = key " " $i
  nw = split(key, w, " ")
  l = (key in lab) ? lab[key] : -1
  best = ""
  for (k = 1; k <= na && best == ""; k++) {
    m = split(a[k], y, " ")
    if (y[1] != w[1]) continue
    good = 1; differ = 0
    for (i = 2; i <= nw && i <= m; i++) {
      d = absd(w[i] - y[i]); if (d <= unit(y[i]) * 1.01) continue
      if ((i - 1) in ismax) differ = 1; else good = 0
    }
    if (good && differ) best = a[k]
  }
  kind = "other"
  if (best != "" && l >= 0 && (l in hasref)) {
    split(best, y, " ")
    kind = "max-whirl"
    for (i = 2; i <= nw; i++) {
      if (!((i - 1) in ismax)) continue
      r = ref[l, ismax[i - 1]]
      if (absd(w[i] - y[i]) > unit(y[i]) * 1.01 && absd(w[i] - r) >= absd(y[i] - r)) kind = "max-auto"
    }
  }
  n[kind]++
  print kind, w[1], w[2], "(label " l ")"
}
END { print "MAXREF", n["max-whirl"] + 0, n["max-auto"] + 0, n["other"] + 0 }

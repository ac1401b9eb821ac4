# test/regress/auto_rows.awk — rows "PT TY v1 v2 ..." of AUTO-07p's own
# b-file (the input) against whirl's b-file b (awk -v b=FILE): the point of
# the same |PT| must have AUTO's type code and every value within 1e-6
# relative of AUTO's (absolute where AUTO's is 0); prints each difference,
# exits 1 if any.  Used by auto_steps.sh, auto_data_start.sh and
# auto_stpnt_start.sh.
# SPDX-License-Identifier: BSD-3-Clause
BEGIN {
  while ((getline l < b) > 0) {
    if (substr(l, 1, 4) + 0 == 0) continue
    m = split(l, w, " "); pt = w[2] < 0 ? -w[2] : w[2]
    ty[pt] = w[3]; nv[pt] = m - 4
    for (i = 5; i <= m; i++) v[pt, i - 4] = w[i]
  }
}
{
  pt = $1
  if (!(pt in ty) || ty[pt] != $2) { print "PT " pt ": type " ty[pt] " where AUTO has " $2; bad = 1; next }
  for (i = 3; i <= NF; i++) {
    a = $i; x = v[pt, i - 2]; d = a == 0 ? x : (x - a) / a; if (d < 0) d = -d
    if (d > 1e-6) { print "PT " pt " column " i - 2 ": " x " where AUTO has " a; bad = 1 }
  }
}
END { exit bad }

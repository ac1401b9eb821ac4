#!/bin/sh
# test/regress/auto_constants.sh — every c.* file of AUTO-07p's demos read
# by whirl (whirl/auto_constants.h, through t_auto_constants --dump) and by
# AUTO-07p's own reader (python/auto/parseC.py of the Debian package
# auto-07p, the independent reference): the same keys with the same
# values, file by file.  Skips where the demos (AUTO_07P_DIR, else
# ../shared/auto-07p beside the source tree) or AUTO's Python are absent.
# TAP output.
set -u
: "${top_srcdir:=.}" "${top_builddir:=.}"
auto=${AUTO_07P_DIR:-$top_srcdir/../shared/auto-07p}
py=${AUTO_07P_PYTHON:-/usr/lib/auto-07p/python}
dump="$top_builddir/test/unit/t_auto_constants"
[ -d "$auto/demos" ] || { echo "1..0 # SKIP no AUTO-07p demos at $auto (set AUTO_07P_DIR)"; exit 0; }
[ -f "$py/auto/parseC.py" ] || { echo "1..0 # SKIP AUTO-07p's Python not at $py (apt-get install auto-07p)"; exit 0; }
command -v python3 >/dev/null 2>&1 || { echo "1..0 # SKIP no python3"; exit 0; }
[ -x "$dump" ] || { echo "1..0 # SKIP $dump not built (make check builds it)"; exit 0; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
ls "$auto"/demos/*/c.* > "$tmp/files"
# AUTO's reading, printed as t_auto_constants --dump prints whirl's
cat > "$tmp/auto.py" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from auto import parseC
kind = {}
def num(x):
    return "%d" % x if isinstance(x, int) else "%.17g" % x
def ref(x):
    return "%d" % x if isinstance(x, int) else "'%s'" % x
def val(k, v):
    if k in ("ICP", "IREV", "IFIXED", "IPSI", "SP", "STOP"):
        if isinstance(v, str): v = [v]       # whirl: a word is a list of one
        return "[" + ", ".join(ref(x) for x in v) + "]"
    if k in ("THL", "THU", "UZR", "UZSTOP", "U", "PAR"):
        return "{" + ", ".join(ref(a) + ": " + (
            "[" + ", ".join("%.17g" % y for y in b) + "]" if isinstance(b, list)
            else "%.17g" % b) for a, b in v) + "}"
    if k in ("unames", "parnames"):
        return "{" + ", ".join("%d: '%s'" % (a, b) for a, b in v) + "}"
    if k in ("e", "s", "dat", "sv", "TY") or isinstance(v, str):
        return "'%s'" % v
    if k[0] in "IJKLMN":
        return "%d" % v
    return "%.17g" % v
for f in sys.stdin.read().split():
    print("== " + f)
    c = parseC.parseC(f)
    for k, v in c.items():
        if k != "new" and v is not None:
            print(k + "\t" + val(k, v))
PY
python3 "$tmp/auto.py" "$py" < "$tmp/files" > "$tmp/auto.out" 2> "$tmp/auto.err" ||
  { echo "1..0 # SKIP AUTO's parseC failed: $(head -1 "$tmp/auto.err")"; exit 0; }
"$dump" --dump $(cat "$tmp/files") > "$tmp/whirl.out"
rc=$?
# one block a file, its lines sorted (the key order differs)
split_blocks() { awk -v d="$2" '/^== /{ f = d "/" (++n); print substr($0, 4) > (d "/names") ; next } { print > f }' "$1"; }
mkdir "$tmp/a" "$tmp/w"
split_blocks "$tmp/auto.out" "$tmp/a"
split_blocks "$tmp/whirl.out" "$tmp/w"
n=0 fail=0 nf=$(wc -l < "$tmp/files")
echo "1..$((nf + 1))"
if [ "$rc" -eq 0 ]; then n=$((n + 1)); echo "ok $n - whirl reads all $nf constants files"
else n=$((n + 1)); echo "not ok $n - whirl failed on some file: $(grep '^error' "$tmp/whirl.out" | head -1)"; fail=1; fi
i=0
while IFS= read -r f; do
  i=$((i + 1)); n=$((n + 1))
  name=${f#"$auto"/demos/}
  sort "$tmp/a/$i" 2>/dev/null > "$tmp/a.s"; sort "$tmp/w/$i" 2>/dev/null > "$tmp/w.s"
  if cmp -s "$tmp/a.s" "$tmp/w.s"; then
    echo "ok $n - $name: $(wc -l < "$tmp/a.s") keys as AUTO reads them"
  else
    echo "not ok $n - $name differs from AUTO's parseC (< AUTO, > whirl):"
    diff "$tmp/a.s" "$tmp/w.s" | grep '^[<>]' | head -6 | sed 's/^/#   /'
    fail=1
  fi
done < "$tmp/files"
exit $fail

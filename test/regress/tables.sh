#!/bin/sh
# test/regress/tables.sh — every TSV whirl writes follows doc/tables.md:
# each command of `whirl` (small runs) and run files of examples/ write
# their tables, and Debian's python3 reads each one with
#   numpy.genfromtxt(f, names=True, comments='#', delimiter='\t', dtype=None)
# and, where pandas is importable, pandas.read_csv(f, sep='\t', comment='#'):
# the names both give must be the header line's, the header the first line,
# the names identifiers without duplicates, the rows as many as the data
# lines, and the header must match that table's row of doc/tables.md (the
# page is parsed here, so a renamed column fails until the page says so).
# One whirl run table is checked against its model's names written out here.
# SPDX-License-Identifier: BSD-3-Clause
name=tables
. "${top_srcdir:-.}/test/regress/tap.sh"
ex="$top_srcdir/examples"
PY=${WHIRL_TEST_PYTHON:-/usr/bin/python3}
if ! "$PY" -c 'import numpy' > /dev/null 2>&1; then
  echo "1..0 # SKIP $PY has no numpy (Debian: apt-get install python3-numpy)"
  exit 0
fi

# the list of tables: COMMAND<TAB>TABLE<TAB>PATH (TABLE as in doc/tables.md)
: > list.tsv
add() { printf '%s\t%s\t%s\n' "$1" "$2" "$3" >> list.tsv; }
# cmd KEY DIR ARGS...: run whirl ARGS with --out DIR, stdout into DIR.stdout;
# every *.tsv of DIR and the stdout go on the list as KEY's (the stdout
# unless doc/tables.md says it is no table: sfd and rotor simulate)
cmd() {
  key=$1 dir=$2
  shift 2
  "$WHIRL" "$@" --out "$dir" --quiet > "$dir.stdout" 2> "$dir.stderr"
  ok $? "whirl $* $(head -c 200 "$dir.stderr")"
  for f in "$dir"/*.tsv; do [ -f "$f" ] && add "$key" "$(basename "$f")" "$f"; done
  case $key in "sfd simulate" | "rotor simulate") ;; *) [ -s "$dir.stdout" ] && add "$key" stdout "$dir.stdout" ;; esac
}
rigid="$ex/rotor/rigid-limit.rotor" sfd="$ex/rotor/sfd-rigid.rotor" f591="$ex/rotor/friswell-5.9.1.rotor"
cmd "sfd response" response sfd response
cmd "sfd response --method hbm" hbm sfd response --method hbm --harmonics 4 --omega-max 3
cmd "sfd simulate" simulate sfd simulate --omega 1.78 --periods 40
cmd "sfd sweep" sweep sfd sweep --from 1 --to 3 --step 0.5 --periods 60 --record 20 --direction up
cmd "sfd basins" basins sfd basins --omega 1.78 --points 25 --periods 60
cmd "sfd nonsync" nonsync sfd nonsync --omega-max 10 --omega-min 7
cmd "sfd region" region sfd region
cmd "rotor campbell" campbell rotor campbell "$f591" --speeds 0:4000:5
cmd "rotor export" export rotor export "$rigid"
rm -f export.stdout; sed -i '/^rotor export	stdout/d' list.tsv
cmd "rotor response" rresponse rotor response "$rigid" --harmonics 3 --stability off
cmd "rotor loci" loci rotor loci "$rigid" --param unbalance --range 0.5:2 --harmonics 1
cmd "rotor loci --merge-along Q" merge rotor loci "$rigid" --param unbalance --range 0.05:3 \
  --harmonics 1 --merge-along clearance --range2 0.5:2
cmd "rotor simulate" rsimulate rotor simulate "$sfd" --speed 690 --unit rad/s --periods 10
cmd "rotor basins" rbasins rotor basins "$sfd" --speed 690 --unit rad/s --grid 3 --periods 40
# the commands with stdout only
"$WHIRL" sfd merge --lambda 0.0503 --quiet > merge.txt
ok $? "whirl sfd merge"
add "sfd merge" stdout merge.txt
"$WHIRL" rotor modes "$f591" > modes.txt
ok $? "whirl rotor modes"
add "rotor modes" stdout modes.txt
"$WHIRL" rotor unbalance "$rigid" --node 0 --speeds 0:4000:5 > unbalance.txt
ok $? "whirl rotor unbalance"
add "rotor unbalance" stdout unbalance.txt
# whirl run on the run files of examples/ (shortened), equilibria, orbits,
# basins and a study
run() {
  dir=$1
  shift
  "$WHIRL" run "$@" --OUT="$dir" --quiet > "$dir.stdout" 2> "$dir.stderr"
  ok $? "whirl run $* $(head -c 200 "$dir.stderr")"
  for f in "$dir"/*.tsv; do [ -f "$f" ] && add "whirl run" "$(basename "$f")" "$f"; done
}
cp "$ex/jeffcott/response.whirl" "$ex/jeffcott/basins.whirl" "$ex/discover/sfd-rotating.whirl" .
run disc sfd-rotating.whirl
run response.out response.whirl --NMX=300
run jbasins basins.whirl --BASIN_GRID=5
run study sfd-rotating.whirl --DISCOVER="[5, 10]" --STUDY="{delta: [0.2, 0.3]}"
run small "$top_srcdir/test/regress/sfd-small.whirl"

"$PY" - "$top_srcdir/doc/tables.md" list.tsv > check.txt 2>&1 << 'EOF'
import re, sys, warnings
import numpy
try:
    import pandas
except ImportError:
    pandas = None
doc, listing = sys.argv[1], sys.argv[2]
ID = r'[A-Za-z][A-Za-z0-9_]*'
# doc/tables.md's names: AUTO's types and '-' for a regular point; the classes
TYPES = {'-', 'ST', 'EP', 'LP', 'BP', 'HB', 'UZ', 'PD', 'TR', 'CP', 'BT', 'ZH', 'IS', 'MG', 'GH'}
CLASSES = {'circular', 'periodic', 'quasiperiodic', 'irregular', 'transient', 'contact'}
# doc/tables.md: | `command` | `table` or stdout | `columns` |
want = {}
for line in open(doc, encoding='utf-8'):
    m = re.match(r'\| `([^`]+)` \| `?([^`|]+?)`? \| `([^`]+)` \|$', line.strip())
    if m:
        want[(m.group(1), m.group(2))] = m.group(3).split()
def pattern(tokens):
    """The header (with a leading space) a doc row allows."""
    out = ''
    for t in tokens:
        if t.startswith('['):
            out += '(?: ' + re.escape(t[1:-1]) + ')?'
        elif t in ('<parameters>', '<states>'):
            out += '(?: ' + ID + ')+'
        elif t.startswith('<'):
            out += ' ' + ID
        else:
            out += ' ' + re.escape(t)
    return '^' + out + '$'
print('# pandas', pandas.__version__ if pandas else 'not installed', '; numpy', numpy.__version__)
bad = 0
seen = set()
for row in open(listing, encoding='utf-8'):
    key, table, path = row.rstrip('\n').split('\t')
    lines = open(path, encoding='utf-8').read().split('\n')
    head = lines[0].split('\t')
    data = [l for l in lines[1:] if l and not l.startswith('#')]
    why = []
    if lines[0].startswith('#'):
        why.append('the first line is a comment')
    if not all(re.fullmatch(ID, n) for n in head):
        why.append('names not identifiers')
    if len(set(head)) != len(head):
        why.append('duplicate names')
    doc_key = (key, table) if (key, table) in want else (key.split(' --')[0], table)
    if doc_key not in want:
        why.append('no row in doc/tables.md')
    elif not re.match(pattern(want[doc_key]), ' ' + ' '.join(head)):
        why.append('not the documented ' + ' '.join(want[doc_key]))
    if any(len(l.split('\t')) != len(head) for l in data):
        why.append('a row with another number of fields')
    if not data:
        why.append('no rows')
    # the same spelling for the same thing in every command: a regular
    # point is '-' (never AUTO's RG, which whirl run wrote), a class one
    # of doc/tables.md's (never 'synchronous', which sfd onset wrote)
    for col, allowed in (('type', TYPES), ('class', CLASSES)):
        if col in head:
            vals = set(l.split('\t')[head.index(col)] for l in data)
            if not vals <= allowed:
                why.append('%s %s not among %s' % (col, sorted(vals - allowed), sorted(allowed)))
    if key == 'whirl run' and table == 'branches.tsv' and '-' not in {
            l.split('\t')[2] for l in data}:
        why.append("no regular point written '-'")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter('error')
            a = numpy.genfromtxt(path, names=True, comments='#', delimiter='\t', dtype=None,
                                 encoding='utf-8')
        if list(a.dtype.names) != head:
            why.append('numpy names %s' % (a.dtype.names,))
        if a.size != len(data):
            why.append('numpy read %d rows of %d' % (a.size, len(data)))
    except Exception as e:
        why.append('numpy: %s' % str(e).replace('\n', ' ')[:200])
    if pandas is not None:
        try:
            d = pandas.read_csv(path, sep='\t', comment='#')
            if list(d.columns) != head or len(d) != len(data):
                why.append('pandas read %s, %d rows' % (list(d.columns), len(d)))
        except Exception as e:
            why.append('pandas: %s' % str(e).replace('\n', ' ')[:200])
    seen.add(doc_key)
    print('%s - %s %s (%s): %d rows%s' % ('not ok' if why else 'ok', key if key.startswith('whirl') else 'whirl ' + key, table, path,
          len(data), ': ' + '; '.join(why) if why else ''))
    bad += bool(why)
missing = sorted(set(want) - seen)
print('%s - every table of doc/tables.md written and checked%s' %
      ('not ok' if missing else 'ok', ': missing %s' % missing if missing else ''))
EOF
rc=$?
ok $rc "python3 ran the checks: $(tail -n 3 check.txt | tr '\n' ' ' | head -c 300)"
while IFS= read -r line; do
  case $line in
    "ok - "*) ok 0 "${line#ok - }" ;;
    "not ok - "*) ok 1 "${line#not ok - }" ;;
    "#"*) echo "$line" ;;
  esac
done < check.txt

# the one run's names in full (examples/discover/sfd-rotating.whirl: the
# sfd-rotating model's PAR and U)
[ "$(head -n 1 disc/branches.tsv)" = "$(printf 'branch\tpt\ttype\tlabel\tOmega\tlambda\tdelta\tzeta\tFE\tl2_norm\tu\tv\tdu\tdv\tstable')" ]
ok $? "whirl run sfd-rotating.whirl: branches.tsv 'branch pt type label Omega lambda delta zeta FE l2_norm u v du dv stable'"
# and a periodic run's: the jeffcott model's, with period and max_
[ "$(head -n 1 response.out/branches.tsv | cut -f 1-12,21)" = "$(printf 'branch\tpt\ttype\tlabel\tOmega\tlambda\tdelta\tzeta\talpha\tkappa\tperiod\tl2_norm\tstable')" ] &&
  [ "$(head -n 1 response.out/branches.tsv | cut -f 13)" = max_yd ]
ok $? "whirl run examples/jeffcott/response.whirl: period, l2_norm, max_yd ... stable"
# sfd onset names the class of the response from rest as sfd sweep does:
# at Omega = 1 both say circular (onset's other classes: nonsynchronous,
# contact)
"$WHIRL" sfd onset --from 1 --to 9.5 --tol 4 --periods 300 --quiet > onset.txt 2> onset.err
ok $? "whirl sfd onset --from 1 --to 9.5 $(head -c 200 onset.err)"
"$WHIRL" sfd sweep --from 1 --to 1.5 --step 0.5 --periods 60 --direction up --no-plot \
  --out sweep1 --quiet > sweep1.txt 2> sweep1.err
c_sweep=$(awk -F'\t' '$2 + 0 == 1 { print $3; exit }' sweep1.txt)
c_onset=$(awk -F'\t' '$1 + 0 == 1 { print $2; exit }' onset.txt)
[ "$c_sweep" = circular ] && [ "$c_onset" = circular ]
ok $? "Omega = 1 from rest: sfd sweep says '$c_sweep', sfd onset '$c_onset' (both circular)"
bad=$(awk -F'\t' 'NR > 1 && $1 != "onset" && $2 != "circular" && $2 != "nonsynchronous" && $2 != "contact"' onset.txt)
[ -z "$bad" ] && grep -q '	nonsynchronous	' onset.txt
ok $? "sfd onset's classes are circular, nonsynchronous, contact: ${bad:-yes}"
tap_end

#!/bin/sh
# test/regress/man.sh — the manual page and the installed guides: whirl(1)
# has a section for every command `whirl --help` lists and every option
# each command's --help lists, renders without a groff warning, and is
# installed where `man whirl` finds it; doc/index.md links every guide of
# doc/, and the install puts each of them under $(docdir).
# SPDX-License-Identifier: BSD-3-Clause
set -u
top_builddir=${top_builddir:-.}
case $top_builddir in /*) ;; *) top_builddir="$(pwd)/$top_builddir" ;; esac
name=man
. "${top_srcdir:-.}/test/regress/tap.sh"
page="$top_builddir/man/whirl.1"

[ -s "$page" ]
ok $? "man/whirl.1 is built"

# the commands, as doc/mkman.sh reads them, and their options
"$WHIRL" --help | awk '/^commands:/ { on = 1; next } on && /^$/ { exit }
  on && /^  [a-z]/ { l = substr($0, 3); if (match(l, /  +/)) l = substr(l, 1, RSTART - 1)
    n = split(l, w, " "); o = ""; for (i = 1; i <= n; i++) if (w[i] !~ /^\[?[A-Z][A-Z0-9_.]*\]?$/) o = o (o ? " " : "") w[i]
    print o }' > "$tmp/commands"
ncmd=$(wc -l < "$tmp/commands")
missing=""
nopt=0
while IFS= read -r cmd; do
  grep -q "^\.SS \"whirl $cmd\"" "$page" || missing="$missing [$cmd]"
  # shellcheck disable=SC2086
  for o in $("$WHIRL" $cmd --help | sed -n 's/^  \(--*[a-zA-Z0-9][-a-zA-Z0-9]*\).*/\1/p'); do
    nopt=$((nopt + 1))
    r=$(printf '%s' "$o" | sed 's/-/\\\\-/g')
    grep -q "^\.B $r\( \|=\|,\|\$\)" "$page" || missing="$missing $cmd:$o"
  done
done < "$tmp/commands"
[ "$ncmd" -ge 17 ] && [ "$nopt" -ge 100 ] && [ -z "$missing" ]
ok $? "whirl(1): all $ncmd commands of whirl --help and their $nopt options${missing:+; missing:$missing}"

if command -v groff > /dev/null 2>&1; then
  groff -man -Tutf8 -ww -z "$page" > "$tmp/groff.err" 2>&1
  [ $? -eq 0 ] && [ ! -s "$tmp/groff.err" ]
  ok $? "groff -man -ww renders whirl.1 without a warning: $(head -c 200 "$tmp/groff.err")"
else
  ok 0 "# SKIP groff is not installed"
fi

# every guide linked from the index, every link of the index a guide
ls "$top_srcdir/doc" | sed -n 's/\.md$//p' | grep -v '^index$' | sort > "$tmp/guides"
sed -n 's/.*(\([a-z0-9-]*\)\.md).*/\1/p' "$top_srcdir/doc/index.md" | sort -u > "$tmp/linked"
unlinked=$(comm -23 "$tmp/guides" "$tmp/linked" | tr '\n' ' ')
dangling=$(comm -13 "$tmp/guides" "$tmp/linked" | tr '\n' ' ')
[ -z "$unlinked" ] && [ -z "$dangling" ] && [ -s "$tmp/linked" ]
ok $? "doc/index.md links each of the $(wc -l < "$tmp/guides") guides${unlinked:+; not linked: $unlinked}${dangling:+; no such guide: $dangling}"

. "$top_srcdir/test/regress/stage.sh"
datarootdir="$prefix/share"
staged_page="$stage$datarootdir/man/man1/whirl.1"
cmp -s "$page" "$staged_page"
ok $? "make install puts whirl.1 in \$(mandir)/man1"
if command -v man > /dev/null 2>&1; then
  MANPATH="$stage$datarootdir/man" MANWIDTH=80 man whirl 2> "$tmp/man.err" | grep -q "whirl rotor response"
  ok $? "man whirl (MANPATH at the staged install) shows the commands $(head -c 200 "$tmp/man.err")"
else
  ok 0 "# SKIP man is not installed"
fi
docdir="$stage$datarootdir/doc/whirl"
absent=""
for g in index $(cat "$tmp/guides"); do [ -s "$docdir/$g.md" ] || absent="$absent $g.md"; done
[ -z "$absent" ] && [ -s "$docdir/README" ]
ok $? "make install puts README, index.md and every guide under \$(docdir)${absent:+; absent:$absent}"
tap_end

# test/auto-demos/default_order.sh — sourced, not run: default_order_script
# NAME DIR writes DIR/whirl-default.auto, an AUTO-07p script that runs demo
# NAME's constants files in whirl auto's default order (c.NAME.1,
# c.NAME.2, ... by number, or c.NAME alone), each given the runs before it
# as its solutions (IRS: AUTO's numbering of labels across them), a run
# that fails said and the next one run.  Returns 1 (and writes nothing)
# when DIR has no constants file of NAME.  Used by test/auto-demos/run.sh
# (AUTO's own run of the default order, its third reference) and by
# test/bench/auto_demos_speed.sh (DEFAULT=1: the same runs on both sides).
# SPDX-License-Identifier: BSD-3-Clause
default_order_script() {
  _files=$(cd "$2" 2>/dev/null && ls c."$1".[0-9]* 2>/dev/null | sort -t. -k3,3n | tr '\n' ' ')
  [ -n "$_files" ] || { [ -f "$2/c.$1" ] && _files="c.$1"; }
  [ -n "$_files" ] || return 1
  { echo "s = None"
    for _f in $_files; do
      echo "try:"
      echo "    r = run(e='$1', c='${_f#c.}') if s is None else run(e='$1', c='${_f#c.}', s=s)"
      echo "    s = r if s is None else s + r"
      echo "except Exception as err:"
      echo "    print('run ${_f#c.} failed: %s' % err)"
    done; } > "$2/whirl-default.auto"
}

"""test/auto-demos/auto07p.py MAIN SCRIPT -- AUTO-07p's command-line
interface (MAIN: Debian auto-07p's /usr/lib/auto-07p/python/auto/__main__.py)
run on SCRIPT, with numpy's alias numpy.bool back where numpy 1.24-1.26
removed it: AUTO 0.9.2's Points.importnumpy reads numpy.bool, so every
loadbd (parseB) of its own output stopped at AttributeError (demo fnc:
"No such file or directory: 'b.attr'" after the traceback), which made
AUTO's own run of such a script no reference.  Nothing else is changed.
SPDX-License-Identifier: BSD-3-Clause
"""
import runpy
import sys

try:
    import numpy
    if not hasattr(numpy, 'bool'):
        numpy.bool = bool
except ImportError:  # AUTO then fails as it would without this file
    pass

if len(sys.argv) < 3:
    sys.stderr.write('usage: auto07p.py AUTO_MAIN SCRIPT\n')
    sys.exit(2)
main = sys.argv[1]
sys.argv = [main] + sys.argv[2:]
runpy.run_path(main, run_name='__main__')

"""whirl_auto -- AUTO-07p's scripts (NAME.auto) run by whirl.

`whirl auto DIR [NAME] --script[=FILE]` runs this module on an AUTO-07p
problem directory: the script (default DIR/NAME.auto) is executed as AUTO's
command-line interface executes it, with AUTO's commands defined here, and
every `run` is one `whirl auto` run of the directory's equations with the
constants the script gives (a constants file, a solution's constants, and
keyword constants on top: AUTO-07p manual, ch. 5 "The AUTO Python CLUI",
commands run, load, save, relabel, merge, cd, auto, loadbd); a run from
an array (column-wise [[t...], [u1...], ...]) starts from it as data.

Each run's constants are written as a constants file of their own into
OUT/stage (beside links to DIR's files; DIR itself is not written to) and
run by `whirl auto OUT/stage E --runs=RUN[@FROM:LABEL] --out=OUT/runs`,
restarting from the run and whirl label of the solution the script names.
The runs' AUTO files (b., s., d.) are read back into bifurcation diagrams
the script handles as AUTO's: bd('HB'), bd('HB1'), bd(6), bd + bd, rl(bd),
save(bd, 'name') writes OUT/b.name, s.name, d.name.  OUT/b.runs and s.runs
hold the points and labelled solutions of every run in the order they ran
(what AUTO's terminal shows).

Scripts of AUTO-07p 0.9.2 are Python 2 (`print "..."`): a line that starts
with `print` and a blank is called as AUTO's console calls it.  Commands
that draw (plot, wait, savefig) draw nothing; commands this runner lacks
stop the script with a message naming them and exit status 2.

This is whirl's own code; no AUTO code is used.
SPDX-License-Identifier: BSD-3-Clause
"""
import ast
import errno
import os
import re
import shutil
import subprocess
import sys
import types


class ScriptError(Exception):
    """Bad input in the script or its files: exit status 2."""


class RunSkipped(Exception):
    """A run that cannot start because the run it starts from failed:
    said, and the script goes on (exit status 1), as AUTO goes on after a
    run that stopped."""


class _Picture:
    """What plot() returns: AUTO's picture, here drawing nothing."""

    def __getattr__(self, name):
        return lambda *a, **k: None


# AUTO's type codes in b. files (doc/auto-files.md), as names
TYPE_NAMES = {1: 'BP', 2: 'LP', 3: 'HB', 4: 'RG', -4: 'UZ', 5: 'LP', 6: 'BP',
              7: 'PD', 8: 'TR', 9: 'EP', -9: 'MX', -1: 'BT', -2: 'CP',
              -3: 'ZH', -32: 'GH', 88: 'TTR'}


def type_name(code):
    """The name of AUTO's type code as AUTO's parseB.type_translation
    gives it: on a locus the code is 10 k + type (54 a regular point of a
    fold locus of orbits, -32 GH), the type its last digit, but for the
    maps' LPD, LTR, PTR and TTR."""
    if code in (28, 78):
        return 'LPD'
    if code in (23, 83):
        return 'LTR'
    if code in (77, 87):
        return 'PTR'
    if code not in (-32, 88):
        code = code % 10 if code >= 0 else -((-code) % 10)
    return TYPE_NAMES.get(code, str(code))


def _relabel_row(row, lab):
    """A b. row (I4,I6,I4,I5,...) with LAB (columns 15-19) set."""
    return row[:14] + '%5d' % lab + row[19:]


class Parameters(dict):
    """PAR(1..NPAR) by index, and by the names parnames gives them."""

    def __init__(self, values, names):
        dict.__init__(self, values)
        self.index = {v: k for k, v in names.items()}

    def __getitem__(self, key):
        if key in self.index:
            key = self.index[key]
        try:
            return dict.__getitem__(self, key)
        except KeyError:
            raise ScriptError('no parameter %r (NPAR = %d)' % (key, len(self)))

    def __call__(self, i):
        """sol.PAR(5): PAR(5), as AUTO's parameters called with an index."""
        return self[i]


class DataStart:
    """A start from an array, as AUTO's run([[t0, ...], [x0, ...], ...]) or
    run([x, y, ...]) for a point: written to OUT/stage as a data file
    (dat) or given as U, with the constants it runs with."""

    def __init__(self, data):
        if not data:
            raise ScriptError('run: an empty array to start from')
        self.e, self.c = None, []
        if all(isinstance(v, (int, float)) for v in data):
            self.point, self.columns = [float(v) for v in data], None
            return
        try:
            cols = [[float(v) for v in col] for col in data]
        except (TypeError, ValueError):
            raise ScriptError('run: an array to start from must be numbers, column-wise '
                              '[[t0, ..., tn], [x0, ..., xn], ...] or a point [x, y, ...]')
        if len(cols) < 2 or len(set(len(c) for c in cols)) != 1 or len(cols[0]) < 2:
            raise ScriptError('run: an array to start from needs the column t and one or '
                              'more state columns, all of one length (two or more)')
        self.point, self.columns = None, cols

    def constants(self, stage, name):
        """The constants that start from this data: U = {...} for a point;
        else dat = NAME, with STAGE/NAME.dat written (rows t, U(1), ...)."""
        if self.point is not None:
            return ['U = %r' % {i + 1: v for i, v in enumerate(self.point)}]
        rows = zip(*self.columns)
        _write_whole(os.path.join(stage, name + '.dat'),
                     ''.join(' '.join('%.17g' % v for v in r) + '\n' for r in rows))
        return ['dat = %r' % name]


class Solution:
    """A labelled point: its b. row, its s. block, the run it came from
    (whirl's run id and label there, for restarts) and its constants."""

    def __init__(self, run_id, wlab, row, block, consts, e, columns=(), runs=None):
        self.run_id, self.wlab, self.runs = run_id, wlab, runs  # runs: its runs/ directory
        self.row, self.block = row, list(block)
        self.c, self.e = list(consts), e
        self.columns = list(columns)  # the b. file's value columns (PAR(1), L2-NORM, ...)
        # the largest label and branch of the solutions of the run it came
        # from, which AUTO's restart file (fort.3) ends with (AUTO's
        # parseS: _mlab, _mbr, and after relabel the number of solutions):
        # a run from it numbers on from them (_numbering); None: not known
        self.numbers = None

    def copy(self):
        c = Solution(self.run_id, self.wlab, self.row, self.block,
                     self.c, self.e, self.columns, self.runs)
        c.numbers = self.numbers
        return c

    @property
    def br(self):
        return abs(int(self.row[0:4]))

    @property
    def itp(self):
        return int(self.row[10:14])

    @property
    def ty(self):
        return type_name(int(self.row[10:14]))

    @property
    def lab(self):
        return int(self.row[14:19])

    def _names(self, key):
        """The dictionary KEY (parnames, unames) of the constants."""
        text = '\n'.join(line.split('#')[0] for line in self.c)
        found = {}
        for m in re.finditer(r'(?<![A-Za-z0-9_])%s\s*=\s*\{' % key, text):
            depth, j = 0, m.end() - 1
            for j in range(m.end() - 1, len(text)):
                depth += {'{': 1, '}': -1}.get(text[j], 0)
                if depth == 0:
                    break
            try:
                found.update(ast.literal_eval(text[m.end() - 1:j + 1]))
            except (ValueError, SyntaxError):
                pass
        return found

    def _ints(self, a, b):
        return int(self.block[0][a:b])

    def _values(self, count):
        """The first COUNT numbers of the s. block after its header (the
        rows t, U(1..NDIM), wrapped at 7 a line as AUTO writes them)."""
        vals = []
        for line in self.block[1:]:
            vals.extend(float(v.replace('D', 'E')) for v in line.split())
            if len(vals) >= count:
                break
        if len(vals) < count:
            raise ScriptError('%r: its s. block is short' % self)
        return vals[:count]

    def _rows(self):
        """The solution's rows [t, U(1), ..., U(NDIM)] (NTPL of them)."""
        if not self.block:
            raise ScriptError('%r has no solution data' % self)
        ntpl, nar = self._ints(36, 44), self._ints(44, 50)
        vals = self._values(ntpl * nar)
        return [vals[k * nar:(k + 1) * nar] for k in range(ntpl)]

    @property
    def PAR(self):
        """PAR(1..NPAR) from the s. block, a dictionary by index that also
        takes the constants' parnames (sol.PAR['mu'], as AUTO's)."""
        if not self.block:
            raise ScriptError('%r has no solution data' % self)
        npar, vals = self._ints(68, 73), []
        for line in reversed(self.block[1:]):
            vals = [float(v.replace('D', 'E')) for v in line.split()] + vals
            if len(vals) >= npar:
                break
        return Parameters({k + 1: v for k, v in enumerate(vals[-npar:])},
                          self._names('parnames'))

    def __getitem__(self, key):
        """sol['mu'] or sol['PAR(1)']: a parameter; sol['x'] or sol['U(1)']:
        the state of an equilibrium (or the orbit's first point)."""
        own = {'LAB': lambda: self.lab, 'TY': lambda: self.ty, 'TY name': lambda: self.ty,
               'BR': lambda: int(self.row[0:4]), 'PT': lambda: abs(int(self.row[4:10]))}
        if key in own:
            return own[key]()
        par = {v: k for k, v in self._names('parnames').items()}
        m = re.fullmatch(r'PAR\((\d+)\)', str(key))
        if key in par or m:
            return self.PAR[par[key] if key in par else int(m.group(1))]
        uns = {v: k for k, v in self._names('unames').items()}
        m = re.fullmatch(r'U\((\d+)\)', str(key))
        if key in uns or m or key == 't':
            # a column of the solution's rows (AUTO's sol['x'], sol['t']);
            # of a point (one row, an equilibrium), its value
            i = 0 if key == 't' else uns[key] if key in uns else int(m.group(1))
            rows = self._rows()
            if not 0 <= i < len(rows[0]):
                raise ScriptError('%r: no state %r (NDIM = %d)' % (self, key, len(rows[0]) - 1))
            col = [r[i] for r in rows]
            return col[0] if len(col) == 1 and key != 't' else col
        if key in self.columns:  # a column of the b. row: 'L2-NORM', 'MAX U(1)'
            k = self.columns.index(key)
            return float(self.row[19 + 19 * k:38 + 19 * k].replace('D', 'E'))
        raise ScriptError('%r: no parameter or state named %r' % (self, key))

    def relabel(self, lab):
        self.row = _relabel_row(self.row, lab)
        if self.block:
            h = self.block[0]
            self.block[0] = h[:18] + '%6d' % lab + h[24:]

    def __repr__(self):
        return 'Solution(%s %d, run %s)' % (self.ty, self.lab, self.run_id)


# AUTO's type codes of the TY constant's names (a restart's type given)
TY_CODES = {'BP': 1, 'LP': 2, 'HB': 3, 'UZ': -4, 'PD': 7, 'TR': 8, 'EP': 9, 'MX': -9}


def _numbering(start, consts):
    """AUTO's numbers of a run from solution START (AUTO-07p io.f90,
    NEWLAB), as constants for the staged constants file: its labels from
    LAB = the largest label of the solutions of the run START came from + 1
    (Solution.numbers; unless the constants give LAB), its first branch IBR
    (unless they give it): one more than their largest branch for a switch
    (ISW < 0, and the run of starting data of a locus of orbits, whose ISW
    AUTO makes -2: periodic.f90), the restart label itself for a locus
    (|ISW| = 2, or ISW = 2 of a BVP) or orbits from a Hopf point (IPS = 2,
    where ISW is then 1), else START's own branch.  None for a fresh start
    (labels from 1, branch 1: whirl's own numbering)."""
    if not isinstance(start, Solution) or start.numbers is None:
        return []

    def const(key, default):
        v = Runner.current(consts, key)
        try:
            return int(float(v.replace('D', 'E').replace('d', 'e'))) if v else default
        except ValueError:
            return default
    mlab, mbr = start.numbers
    ips, isw, itp = const('IPS', 1), const('ISW', 1), start.itp
    ty = Runner.current(consts, 'TY')
    if ty:
        m = re.match(r"['\"]?([A-Za-z]+)", ty)
        itp = TY_CODES.get(m.group(1).upper(), itp) if m else itp
    if ips == 2 and (itp == 3 or abs(itp) // 10 == 3):
        isw = 1  # periodic.f90: a Hopf start
    elif ips == 2 and abs(isw) >= 2 and itp in (5, 6, 7, 8):
        isw = -abs(isw)  # periodic.f90: a locus's run of starting data
    out = []
    if const('LAB', 0) == 0:
        out.append('LAB = %d' % (mlab + 1))
    if const('IBR', 0) == 0:
        if isw < 0:
            br = mbr + 1
        elif (abs(itp) < 10 and abs(isw) == 2) or (ips == 2 and itp == 3) \
                or (ips == 4 and isw == 2 and abs(itp) < 10):
            br = start.lab
        else:
            br = start.br
        out.append('IBR = %d' % br)
    return ['# AUTO\'s numbering of a run from a solution (io.f90 NEWLAB)'] + out


def _loaded(bd):
    """A saved diagram as AUTO's loadbd or load(s=) reads it back: new
    solutions, each with the largest label and branch of the whole file
    (parseS: _mlab, _mbr), which a run from one of them numbers on."""
    bd = BifDiag(b.copy() for b in _as_bd(bd))
    sols = bd()
    numbers = (max([x.lab for x in sols] or [0]), max([x.br for x in sols] or [0]))
    for x in sols:
        x.numbers = numbers
    return bd


def _no_switch(start, consts):
    """ISW < 0 where START is no point to switch at (no BP, no PD; an HB
    of orbits starts them as it is): AUTO continues the branch there, as
    with ISW = 1 (a script's run(r2('UZ1')) after r2 = run(r1('BP1'),
    ISW=-1) keeps r2's ISW = -1; whirl refused it), numbered as a switch
    (_numbering, on the constants as they were)."""
    if not isinstance(start, Solution):
        return []
    isw = Runner.current(consts, 'ISW')
    try:
        if not isw or int(float(isw)) >= 0:
            return []
    except ValueError:
        return []
    ips = Runner.current(consts, 'IPS')
    if start.ty in ('BP', 'PD') or Runner.current(consts, 'TY') or \
            (start.ty == 'HB' and ips and ips.strip() == '2'):
        return []
    return ["# AUTO: ISW < 0 at a %s continues the branch" % start.ty, 'ISW = 1']


def _select(sols, what):
    """AUTO's selection: None all, a label number, 'HB' all of a type,
    'HB1' the first of a type."""
    if what is None:
        return SolutionList(sols)
    if isinstance(what, int):
        for s in sols:
            if s.lab == what:
                return s
        raise ScriptError('there is no solution labelled %d' % what)
    m = re.fullmatch(r'([A-Za-z]+)(\d*)', str(what))
    if not m:
        raise ScriptError('%r is not a label, a type or a type and number' % what)
    ty = m.group(1).upper()
    same = [s for s in sols if s.ty == ty]
    if not m.group(2):
        return SolutionList(same)
    k = int(m.group(2))
    if not 1 <= k <= len(same):
        raise ScriptError('there is no %s%d (%d points of type %s)' % (ty, k, len(same), ty))
    return same[k - 1]


class SolutionList(list):
    def __call__(self, what=None):
        return _select(list(self), what)


class Branch:
    """A branch of a b. file: its header lines and its rows, each row with
    its Solution where it is labelled."""

    def __init__(self, header, rows, run_id=None, runs=None):
        self.header, self.rows = list(header), list(rows)  # rows: (text, Solution|None)
        self.run_id, self.runs = run_id, runs  # whirl's run it came from (its d. file)

    def copy(self):
        return Branch(self.header, [(t, s.copy() if s else None) for t, s in self.rows],
                      self.run_id, self.runs)

    def solutions(self):
        return [s for _, s in self.rows if s is not None]


class BifDiag(list):
    """A bifurcation diagram: a list of branches, called to select
    solutions as AUTO's: bd(), bd(6), bd('HB'), bd('HB1')."""

    def __call__(self, what=None):
        return _select([s for b in self for s in b.solutions()], what)

    def __add__(self, other):
        return BifDiag(list(self) + list(_as_bd(other)))


def _as_bd(x):
    if isinstance(x, BifDiag):
        return x
    if isinstance(x, list) and all(isinstance(b, Branch) for b in x):
        return BifDiag(x)
    raise ScriptError('expected a bifurcation diagram, got %r' % type(x).__name__)


def _write_whole(path, text, keep=False):
    """path replaced by text at once: written to path.tmp and renamed, the
    temporary removed when that fails (a full disk, Ctrl-C).  keep: text
    goes after path's own bytes, copied by the kernel (shutil.copyfile),
    where reading them into Python and joining made a script of long runs
    quadratic (fnc: 19 MB of s.runs rewritten after each of 20 runs)."""
    tmp = path + '.tmp'
    try:
        if keep:
            shutil.copyfile(path, tmp)
        with open(tmp, 'a' if keep else 'w') as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise


# ---- AUTO's files of a run, read back -------------------------------------

def _read_b(path):
    branches, header, rows = [], [], []
    with open(path) as f:
        for line in f:
            line = line.rstrip('\n')
            if line.startswith('   0'):
                if rows:
                    branches.append((header, rows))
                    header, rows = [], []
                header.append(line)
            elif line.strip():
                rows.append(line)
    if rows or header:
        branches.append((header, rows))
    return branches


def _read_s(path):
    """s. blocks by label: the 16-integer header (6I6,I8,I6,I8,7I5) and its
    NROWPR lines."""
    blocks = {}
    if not os.path.exists(path):
        return blocks
    with open(path) as f:
        lines = f.read().split('\n')
    i = 0
    while i < len(lines) and lines[i].strip():
        h = lines[i]
        nrow = int(h[50:58])
        blocks[int(h[18:24])] = lines[i:i + 1 + nrow]
        i += 1 + nrow
    return blocks


def _read_labels(outdir):
    """whirl's label of each point of branches.tsv, in order."""
    labs = []
    with open(os.path.join(outdir, 'branches.tsv')) as f:
        names = None
        for line in f:
            if line.startswith('#'):
                continue
            cols = line.rstrip('\n').split('\t')
            if names is None:
                names = cols
                continue
            labs.append(int(cols[names.index('label')]))
    return labs


class Runner:
    """AUTO's runner: the equations and constants the next run uses."""

    def __init__(self, whirl, srcdir, out, quiet):
        self.whirl, self.quiet = whirl, quiet
        self.top_src, self.top_out = os.path.abspath(srcdir), out
        self.e, self.consts, self.start = None, [], None
        self.last = BifDiag()
        self.count, self.failed = 0, False
        self.saved = {}  # (directory, name): the diagram saved there
        self.all_runs, self.all_sols = [], []  # OUT/b.runs, s.runs (write_runs)
        self.runs_done = {}  # b.runs, s.runs: (lines, bytes) in the file
        self.enter('')

    # -- the directory the script is in (cd) --
    def enter(self, rel):
        """Work in DIR/REL: its files are read from there, its runs and the
        diagrams saved there go to OUT/REL (a stage of links to DIR/REL's
        files, and runs/)."""
        self.rel = rel
        self.srcdir = os.path.join(self.top_src, rel)
        self.out = os.path.join(self.top_out, rel)
        self.stage = os.path.join(self.out, 'stage')
        self.runs = os.path.join(self.out, 'runs')
        os.makedirs(self.stage, exist_ok=True)
        for name in os.listdir(self.srcdir):
            src = os.path.join(self.srcdir, name)
            dst = os.path.join(self.stage, name)
            if os.path.isfile(src) and not os.path.lexists(dst):
                os.symlink(src, dst)

    def cd(self, path):
        """AUTO's cd: a directory of the demo's (DIR itself and those below
        it; a script's runs never leave DIR)."""
        rel = os.path.normpath(os.path.join(self.rel, str(path)))
        rel = '' if rel == '.' else rel
        if rel == '..' or rel.startswith('..' + os.sep) or os.path.isabs(str(path)):
            raise ScriptError('cd(%r): outside the directory the script runs in' % path)
        if not os.path.isdir(os.path.join(self.top_src, rel)):
            raise ScriptError('cd(%r): no directory %s' % (path, os.path.join(self.top_src, rel)))
        self.enter(rel)

    def loadbd(self, name):
        """AUTO's loadbd(NAME): the diagram the script saved as NAME in the
        directory it is in (b.NAME, s.NAME there)."""
        key = (self.rel, str(name))
        if key not in self.saved:
            raise ScriptError('loadbd(%r): the script saved nothing under that name in %s'
                              % (name, self.srcdir))
        return _loaded(self.saved[key])

    # -- constants --
    def read_c(self, name):
        path = os.path.join(self.srcdir, 'c.' + name)
        try:
            with open(path) as f:
                return f.read().split('\n')
        except OSError as e:
            raise ScriptError('c=%r: %s: %s' % (name, path, e.strerror))

    @staticmethod
    def current(consts, key):
        """The last value of KEY in constants text (a later key replaces an
        earlier one), as text; None if absent."""
        pat = re.compile(r'(?<![A-Za-z0-9_])%s\s*=\s*([^,\s]+)' % re.escape(key))
        val = None
        for line in consts:
            for m in pat.finditer(line.split('#')[0]):
                val = m.group(1)
        return val

    def override(self, consts, kw):
        consts = list(consts)
        for key, val in kw.items():
            if key == 'DS' and val in ('-', '+'):
                ds = self.current(consts, 'DS')
                if ds is None:
                    raise ScriptError("DS=%r: the constants have no DS" % val)
                if val == '+':
                    continue
                val = -float(ds.replace('D', 'E').replace('d', 'e'))
            consts.append('%s = %r' % (key, val))
        return consts

    # -- load and run --
    def load(self, data=None, **kw):
        e = kw.pop('e', None)
        c = kw.pop('c', None)
        if 's' in kw:
            s = kw.pop('s')
            if (self.rel, s) not in self.saved:
                raise ScriptError("s=%r: no solutions saved under that name by this script" % s)
            data = _loaded(self.saved[(self.rel, s)])
        if isinstance(data, str):
            e, c = e or data, c or data
            data = None
        if hasattr(data, 'tolist') and not isinstance(data, list):  # a numpy array
            data = data.tolist()
        if isinstance(data, (list, tuple)) and not isinstance(data, (BifDiag, SolutionList)) \
                and not any(isinstance(x, (Branch, Solution)) for x in data):
            data = DataStart(data)
        if isinstance(data, DataStart):  # a fresh start from the array
            data.e = e or self.e
            data.c = self.override(self.read_c(c) if c else self.consts, kw)
            return data
        if data is None:
            if e:
                self.e = e
            if c:
                self.consts = self.read_c(c)
            self.consts = self.override(self.consts, kw)
            return None
        if isinstance(data, list) and not isinstance(data, Solution):
            sols = data() if callable(data) else [s for b in data for s in b.solutions()]
            if 'IRS' in kw:
                sol = _select(list(sols), kw['IRS'])
            elif sols:
                sol = sols[-1]
            elif self.failed:  # an earlier run failed: this one cannot start
                raise RunSkipped('the run it starts from failed')
            else:
                raise ScriptError('the bifurcation diagram has no solutions to start from')
        elif isinstance(data, Solution):
            sol = data
        else:
            raise ScriptError('cannot start from %r' % type(data).__name__)
        sol = sol.copy()
        if e:
            sol.e = e
        if c:
            sol.c = self.read_c(c)
        sol.c = self.override(sol.c, kw)
        return sol

    def run(self, data=None, sv=None, ap=None, **kw):
        """AUTO's run: from data (a solution, a diagram, a name) with its
        constants and kw on top; without data, the runner's last start and
        constants again (run(DS='-') continues the other way), or with c=
        a fresh start from those constants."""
        if data is not None or 's' in kw:
            try:
                sol = self.load(data, **kw)
            except RunSkipped as e:
                sys.stderr.write('whirl auto: run skipped: %s\n' % e)
                self.last = BifDiag()
                return self.last
            self.start = sol
            if sol is not None:
                self.e, self.consts = sol.e or self.e, sol.c
        else:
            if 'c' in kw:
                self.start = None
            self.load(None, **kw)
        if not self.e:
            raise ScriptError('run: no equations (give e=NAME)')
        self.count += 1
        rid = 'r%d' % self.count
        start, consts = self.start, self.consts
        if isinstance(start, DataStart):  # AUTO's run from an array
            consts = consts + start.constants(self.stage, rid)
            start = None
        elif start is not None and start.runs != self.runs:
            raise ScriptError('run: a restart from %r, a run of another directory '
                              '(whirl restarts from the runs of the directory it is in)' % start)
        with open(os.path.join(self.stage, 'c.' + rid), 'w') as f:
            f.write('\n'.join(consts + _numbering(start, consts) + _no_switch(start, consts))
                    + '\n')
        spec = rid if start is None else '%s@%s:%d' % (rid, start.run_id, start.wlab)
        ids = self.whirl_auto(self.e, spec)
        bd = BifDiag()
        for run_id in ids:
            bd.extend(self.read_run(run_id, self.consts, self.e))
        # the run's largest label and branch (its MXBF branches' too: one
        # run of AUTO's), which a run from one of its solutions numbers on
        sols = bd()
        numbers = (max([s.lab for s in sols] or [0]), max([s.br for s in sols] or [0]))
        for s in sols:
            s.numbers = numbers
        self.last = bd
        if sv:
            self.save(bd, sv)
        if ap:
            self.append(bd, ap)
        return bd

    def whirl_auto(self, e, spec):
        cmd = [self.whirl, 'auto', self.stage, e, '--runs=' + spec, '--out=' + self.runs]
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           universal_newlines=True)
        ids = []
        for line in p.stdout.splitlines():
            m = re.fullmatch(r'== (\S+) \(c\.\S+\)', line)
            if m:
                ids.append(m.group(1))
            elif not self.quiet:
                print(line)
        if p.stderr:
            sys.stderr.write(p.stderr)
        if p.returncode:  # said on stderr; the script goes on, as AUTO's
            self.failed = True
        return ids

    def read_run(self, run_id, consts, e):
        bpath = os.path.join(self.runs, 'b.' + run_id)
        if not os.path.exists(bpath):
            return []
        blocks = _read_s(os.path.join(self.runs, 's.' + run_id))
        wlabs = _read_labels(os.path.join(self.runs, run_id + '.out'))
        out, k = [], 0
        for header, rows in _read_b(bpath):
            brows = []
            names = header[-1][19:] if header else ''
            columns = [names[i:i + 19].strip() for i in range(0, len(names), 19)]
            for row in rows:
                wlab = wlabs[k] if k < len(wlabs) else 0
                k += 1
                lab = int(row[14:19])
                sol = None
                if lab and wlab:
                    sol = Solution(run_id, wlab, row, blocks.get(lab, []), consts, e,
                                   columns, self.runs)
                    self.all_sols.extend(sol.block)
                brows.append((row, sol))
                self.all_runs.append(row)
            out.append(Branch(header, brows, run_id, self.runs))
        if k != len(wlabs):
            raise ScriptError('%s: %d points in b.%s, %d in branches.tsv'
                              % (run_id, k, run_id, len(wlabs)))
        self.write_runs()
        return out

    # -- files --
    def write_runs(self):
        """OUT/b.runs and s.runs, whole after every run: each replaced at
        once (a temporary file renamed), never left half written; the
        lines of the runs before copied as the file has them, where it
        has the bytes this runner wrote."""
        for name, lines in (('b.runs', self.all_runs), ('s.runs', self.all_sols)):
            path = os.path.join(self.top_out, name)
            done, size = self.runs_done.get(name, (0, 0))
            try:
                keep = done > 0 and os.path.getsize(path) == size
            except OSError:
                keep = False
            new = lines[done:] if keep else lines
            text = '\n'.join(new) + '\n' if new else ''  # one join, not a line at a time
            _write_whole(path, text, keep)
            self.runs_done[name] = (len(lines), (size if keep else 0) + len(text.encode()))

    def _paths(self, name):
        return [os.path.join(self.out, '%s.%s' % (k, name)) for k in 'bsd']

    def write(self, bd, name, mode):
        bd = _as_bd(bd)
        paths = self._paths(name)
        texts, parts, runs = ['', '', ''], [[], []], []
        for br in bd:
            d = os.path.join(br.runs or self.runs, 'd.%s' % br.run_id)
            if br.run_id and d not in runs:
                runs.append(d)
                try:  # the runs' diagnostics, as AUTO's d. files
                    with open(d) as f:
                        texts[2] += f.read()
                except OSError:
                    pass
            parts[0].extend(br.header)
            for row, sol in br.rows:
                parts[0].append(row)
                if sol is not None and sol.block:
                    parts[1].extend(sol.block)
        for i in (0, 1):  # one join each (a string grown a line at a time is quadratic)
            texts[i] = '\n'.join(parts[i]) + '\n' if parts[i] else ''
        for path, text in zip(paths, texts):
            _write_whole(path, text, mode == 'a' and os.path.exists(path))

    def diagram(self, x):
        """A diagram given as itself or by the name it was saved under."""
        if isinstance(x, str):
            if (self.rel, x) not in self.saved:
                raise ScriptError("%r: nothing saved under that name" % x)
            return self.saved[(self.rel, x)]
        return _as_bd(x)

    def save(self, bd, name=None):
        """save(bd, 'x'), or save('x'): the last run."""
        if name is None:
            bd, name = self.last, bd
        self.write(bd, name, 'w')
        self.saved[(self.rel, name)] = _as_bd(bd)

    def append(self, bd, name=None):
        """append(bd, 'x'), append('a', 'x'), or append('x'): the last run."""
        if name is None:
            bd, name = self.last, bd
        bd = self.diagram(bd)
        self.write(bd, name, 'a')
        self.saved[(self.rel, name)] = self.saved.get((self.rel, name), BifDiag()) + bd

    def in_place(self, f, x):
        """relabel and merge of a saved name rewrite its files."""
        out = f(self.diagram(x))
        if isinstance(x, str):
            self.save(out, x)
        return out


def relabel(bd, start=1):
    """Labels 1, 2, ... in order over all branches (AUTO's relabel)."""
    bd = BifDiag(b.copy() for b in _as_bd(bd))
    lab = start
    for br in bd:
        rows = []
        for row, sol in br.rows:
            if sol is not None:
                sol.relabel(lab)
                row = sol.row
                lab += 1
            rows.append((row, sol))
        br.rows = rows
    # AUTO's relabel: a run from a relabelled solution numbers on from
    # their count (parseS.relabel: _mlab = len)
    for sol in bd():
        sol.numbers = (lab - 1, sol.numbers[1] if sol.numbers else sol.br)
    return bd


def merge(bd):
    """Branches run from one start in both directions as one branch
    (AUTO's merge): the second's points reversed, then the first's."""
    bd = _as_bd(bd)
    out, i = BifDiag(), 0
    while i < len(bd):
        a = bd[i]
        if i + 1 < len(bd) and a.rows and bd[i + 1].rows and \
                a.rows[0][0][19:] == bd[i + 1].rows[0][0][19:]:
            b = bd[i + 1]
            out.append(Branch(a.header, list(reversed(b.rows[1:])) + a.rows, a.run_id, a.runs))
            i += 2
        else:
            out.append(a.copy())
            i += 1
    return out


def _py2_prints(source):
    """AUTO 0.9.2's scripts are Python 2: `print X` becomes print(X), as
    AUTO's console calls a name followed by arguments."""
    out = []
    for line in source.split('\n'):
        m = re.match(r'^(\s*)print(\s+(?![=(])(.*)|\s*)$', line)
        if m:
            arg = (m.group(3) or '').rstrip()
            line = '%sprint(%s)' % (m.group(1), arg)
        out.append(line)
    return '\n'.join(out)


def _unsupported(name):
    def f(*a, **k):
        raise ScriptError("the script uses '%s', which whirl's script runner does not "
                          "have yet (doc/auto-files.md)" % name)
    return f


def namespace(R):
    def nothing(*a, **k):
        return None
    ns = {'__name__': '__main__', 'ScriptError': ScriptError}
    for names, f in ((('run', 'r', 'rn'), R.run), (('load', 'ld'), R.load),
                     (('save', 'sv'), R.save), (('append', 'ap'), R.append),
                     (('relabel', 'rl'), lambda x, *a: R.in_place(relabel, x)),
                     (('merge', 'mb'), lambda x, *a: R.in_place(merge, x)),
                     (('clean', 'cl', 'wait', 'savefig', 'config'), nothing),
                     (('plot', 'pl'), lambda *a, **k: _Picture())):
        for n in names:
            ns[n] = f

    def delete(name):
        for p in R._paths(name):
            if os.path.exists(p):
                os.remove(p)
        R.saved.pop((R.rel, name), None)
    ns['delete'] = ns['dl'] = delete
    ns['cd'] = R.cd
    ns['loadbd'] = R.loadbd

    def auto(script):
        """AUTO's auto(SCRIPT): SCRIPT, in the directory the script is in,
        executed here, in the same namespace (as AUTO's console runs it:
        fnc.auto sets pgm again after its sub-demos' scripts)."""
        path = os.path.join(R.srcdir, str(script))
        try:
            with open(path) as f:
                code = compile(_py2_prints(f.read()), path, 'exec')
        except OSError as e:
            raise ScriptError('auto(%r): %s: %s' % (script, path, e.strerror))
        SCRIPTS.add(path)
        exec(code, ns)
    ns['auto'] = auto
    for n in ('ex', 'bd', 'demo', 'dm', 'copy', 'cp', 'move', 'mv'):
        ns[n] = _unsupported(n)
    return ns


SCRIPTS = set()  # the scripts executed (the main one, those auto() runs)


def _script_line(script):
    """The script and ':LINE' where the exception being handled arose: the
    innermost frame of a script (the main one, or one auto() ran)."""
    where, tb = script, sys.exc_info()[2]
    while tb is not None:
        f = tb.tb_frame.f_code.co_filename
        if f == script or f in SCRIPTS:
            where = '%s:%d' % (f, tb.tb_lineno)
        tb = tb.tb_next
    return where


def main(argv):
    import argparse
    ap = argparse.ArgumentParser(prog='whirl auto --script')
    ap.add_argument('--whirl', required=True)
    ap.add_argument('--dir', required=True)
    ap.add_argument('--out', required=True)
    ap.add_argument('--quiet', action='store_true')
    ap.add_argument('script')
    a = ap.parse_args(argv)
    try:
        with open(a.script) as f:
            source = _py2_prints(f.read())
        code = compile(source, a.script, 'exec')
    except (OSError, SyntaxError) as e:
        sys.stderr.write('whirl auto: %s: %s\n' % (a.script, e))
        return 2
    try:  # OUT, marked as whirl auto's (its check_out), once the script compiles
        os.makedirs(a.out, exist_ok=True)
        with open(os.path.join(a.out, '.whirl-auto'), 'w') as f:
            f.write('written by whirl auto --script\n')
    except OSError as e:
        sys.stderr.write('whirl auto: %s: %s\n' % (a.out, e.strerror))
        return 1
    R = Runner(a.whirl, a.dir, a.out, a.quiet)
    sys.path.insert(0, os.path.abspath(a.dir))
    sys.dont_write_bytecode = True  # a module the script imports: no __pycache__ in DIR
    ns = namespace(R)
    # a module of the demo's that imports AUTO's commands (r3b's
    # compute_lps.py: from AUTOclui import *) gets this runner's
    clui = types.ModuleType('AUTOclui')
    clui.__dict__.update({k: v for k, v in ns.items() if not k.startswith('__')})
    sys.modules['AUTOclui'] = clui
    try:
        exec(code, ns)
    except KeyboardInterrupt:  # Ctrl-C: the runs done so far stay, whole
        sys.stderr.write('whirl auto: %s: interrupted\n' % _script_line(a.script))
        return 130
    except OSError as e:
        if e.errno not in (errno.ENOSPC, errno.EDQUOT, errno.EIO, errno.EROFS):
            what = '%s: %s' % (type(e).__name__, e)  # the script's own
            sys.stderr.write('whirl auto: %s: %s\n' % (_script_line(a.script), what))
            return 2
        sys.stderr.write('whirl auto: %s: %s\n' % (e.filename or a.out, e.strerror))
        return 1  # OUT cannot be written (a full disk): the files there are whole
    except Exception as e:  # bad input, or the script's own error as Python says it
        what = str(e) if isinstance(e, ScriptError) else '%s: %s' % (type(e).__name__, e)
        sys.stderr.write('whirl auto: %s: %s\n' % (_script_line(a.script), what))
        return 2
    return 1 if R.failed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/python3
"""run_nonsync.py — the AUTO-07p side of whirl's speed comparison for the
nonsynchronous response of the SFD rotor (Table 1: λ = 0.0503, δ = 0.3,
ζ = 0): the periodic orbit of the rotating-frame ODE (nonsync.c), continued
in Ω from the start orbit at Ω = 8.7 (nonsync.dat) with IPS = 2, NTST = 100,
NCOL = 4 through its fold of cycles (LP) up to Ω = 20 on both branches.

Two AUTO runs (one executable, nonsync.exe, built from nonsync.c):
  fw   from the orbit at Ω = 8.7, DS > 0: stable branch up to Ω = 20
  bw   from the same orbit, DS < 0: down to the fold of cycles (LP), then
       the unstable branch up to Ω = 20

Commands (run in a directory holding nonsync.c, c.nonsync, nonsync.dat,
circ.py (from ../sfd) and this file):
  prepare [--tight] [--iid0]
                      check the start orbit nonsync.dat against the ODE
                      (6th-order periodic differences of the data vs the
                      right-hand side) and write c.nonsync_fw, c.nonsync_bw
                      (AUTO constants files)
  run [--tight] [--iid0]
                      prepare, then run AUTO-07p through its Python
                      interface (compiles nonsync.c if nonsync.exe is
                      missing or older), keep b.<run>, print the summary
  --tight             EPSL = EPSU = 1e-10, EPSS = 1e-8 (default: AUTO's
                      defaults EPSL = EPSU = 1e-7, EPSS = 1e-5)
  --iid0              IID = 0: no per-step diagnostics (d-file); AUTO's
                      default is IID = 2
  summary             print the summary of the b.<run> files present
  check               summary plus the LP against whirl's fold of cycles
                      (Ω = 8.5900671072, harmonic balance with 60 harmonics
                      and collocation NTST 100, both to ~1e-9); fails if
                      |ΔΩ| > 1e-6
Exit status 0 on success, 1 with a message on stderr on any failure.
Needs /usr/bin/python3 and AUTO-07p (AUTO_DIR, default /usr/lib/auto-07p).
SPDX-License-Identifier: BSD-3-Clause
"""
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(1, os.path.join(HERE, "..", "sfd"))
import circ  # noqa: E402  (rotating-frame right-hand side, plain Python)

LAM, DELTA, ZETA = 0.0503, 0.3, 0.0   # Table 1 of the paper
OM_START = 8.7                         # Ω of the start orbit (nonsync.dat)
OM_END = 20.0                          # both branches end here (UZSTOP)
OM_FOLD_REF = 8.5900671072             # whirl: fold of cycles (HBM, colloc)
DATFILE = "nonsync.dat"
RUNS = ("fw", "bw")
TYPES = {1: "BP", 2: "LP", 3: "HB", 4: "", -4: "UZ", 5: "LP", 6: "BP",
         7: "PD", 8: "TR", 9: "EP", -9: "MX"}


class Failure(Exception):
    pass


def read_dat(path=DATFILE):
    """The start orbit: rows (t, u, v, u', v'); AUTO takes the period as
    t(last) − t(first) and rescales t to [0, 1]."""
    rows = []
    for n, line in enumerate(open(path), 1):
        w = line.split()
        if not w:
            continue
        if len(w) != 5:
            raise Failure("%s line %d: expected 5 columns (t u v u' v'), "
                          "got %d" % (path, n, len(w)))
        rows.append([float(x) for x in w])
    return rows


def check_dat():
    """Check that nonsync.dat is one closed period of the ODE at Ω = 8.7:
    uniform t, x(T) = x(0), and x' from 6th-order periodic central
    differences equal to the right-hand side.  Returns (T, rows, closure,
    relative derivative mismatch)."""
    rows = read_dat()
    if len(rows) < 50:
        raise Failure("%s: only %d rows" % (DATFILE, len(rows)))
    n = len(rows) - 1            # intervals; the last row closes the orbit
    T = rows[-1][0] - rows[0][0]
    h = T / n
    if not T > 0:
        raise Failure("%s: period t(last) - t(first) = %g" % (DATFILE, T))
    for k, r in enumerate(rows):
        if abs(r[0] - rows[0][0] - k * h) > 1e-9 * T:
            raise Failure("%s: t is not uniform at row %d" % (DATFILE, k + 1))
    closure = max(abs(a - b) for a, b in zip(rows[0][1:], rows[-1][1:]))
    if not closure <= 1e-8:
        raise Failure("%s: orbit does not close: |x(T) - x(0)| = %.3g"
                      % (DATFILE, closure))
    xs = [r[1:] for r in rows[:-1]]
    worst, fmax = 0.0, 0.0
    for k in range(n):
        f = circ.rhs(xs[k], OM_START, LAM, DELTA, ZETA)
        xm = [xs[(k + j) % n] for j in (-3, -2, -1, 1, 2, 3)]
        for i in range(4):
            d = (-xm[0][i] + 9 * xm[1][i] - 45 * xm[2][i] + 45 * xm[3][i]
                 - 9 * xm[4][i] + xm[5][i]) / (60 * h)
            worst = max(worst, abs(d - f[i]))
            fmax = max(fmax, abs(f[i]))
    rel = worst / fmax
    # 6th-order differences: 1.2e-6 for the 400 intervals of nonsync.dat
    # (the orbit comes to ε = 0.93, where the film force is steep); the
    # same data at Ω = 8.699 gives 6e-5, at 8.69 6e-4
    if not rel <= 1e-5:
        raise Failure("%s is not an orbit of the ODE at Omega=%g: "
                      "max |dx/dt - f| / max |f| = %.3g"
                      % (DATFILE, OM_START, rel))
    return T, rows, closure, rel


def write_constants(tight, iid0):
    base = open(os.path.join(HERE, "c.nonsync")).read()
    T, rows, closure, rel = check_dat()
    extra = ""
    if tight:
        extra += "EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-08\n"
    if iid0:
        extra += "IID = 0\n"
    for name in RUNS:
        ds = -0.01 if name == "bw" else 0.01
        with open("c.nonsync_" + name, "w") as f:
            f.write(base)
            f.write(extra)
            f.write("# start orbit %s: T = %r, %d intervals, closure %.2e, "
                    "|dx/dt - f|/|f| = %.2e\n"
                    % (DATFILE, T, len(rows) - 1, closure, rel))
            f.write("DS = %r\n" % ds)
    return T, rows, closure, rel


class AutoOutputToLog:
    """Send everything AUTO (and the compilers it starts) prints to a log
    file, at the file-descriptor level, so stdout keeps only the summary."""

    def __init__(self, path):
        self.path = path

    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.log = open(self.path, "a")
        self.saved = (os.dup(1), os.dup(2))
        os.dup2(self.log.fileno(), 1)
        os.dup2(self.log.fileno(), 2)
        return self

    def __exit__(self, *exc):
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(self.saved[0], 1)
        os.dup2(self.saved[1], 2)
        os.close(self.saved[0])
        os.close(self.saved[1])
        self.log.close()
        return False


def run_auto():
    auto_dir = os.environ.get("AUTO_DIR", "/usr/lib/auto-07p")
    sys.path.insert(0, os.path.join(auto_dir, "python"))
    os.environ.setdefault("AUTO_DIR", auto_dir)
    with AutoOutputToLog("auto.log"):
        try:
            from auto import AUTOclui
        except Exception as e:  # pragma: no cover - environment problem
            raise Failure("cannot import AUTO-07p from %s: %s"
                          % (auto_dir, e))
        for name in RUNS:
            for f in ("fort.7", "fort.8", "fort.9"):
                if os.path.exists(f):
                    os.remove(f)
            try:
                AUTOclui.run(e="nonsync", c="nonsync_" + name)
            except Exception as e:
                raise Failure("AUTO run %s failed: %s (see auto.log)"
                              % (name, e))
            if not os.path.exists("fort.7"):
                raise Failure("AUTO run %s wrote no fort.7 (see auto.log)"
                              % name)
            shutil.copyfile("fort.7", "b." + name)


def read_b(path):
    """Labelled points of an AUTO b-file for IPS = 2: (type, PT, Ω, T,
    stable, the Ω string as printed, Ω − 8.59 as printed) per label, and
    the number of the last point.  Columns: BR PT TY LAB Omega L2-NORM
    MAX u .. MAX dv PERIOD dOmega."""
    pts, last = [], 0
    for line in open(path):
        w = line.split()
        if len(w) < 12 or w[0] == "0":
            continue
        try:
            pt, ty, lab = int(w[1]), int(w[2]), int(w[3])
            vals = [float(v.replace("D", "E")) for v in w[4:12]]
        except ValueError:
            continue
        last = max(last, abs(pt))
        if lab != 0:
            om, period = vals[0], vals[6]
            pts.append((TYPES.get(ty, str(ty)), abs(pt), om, period,
                        pt < 0, w[4], w[11]))
    return pts, last


def summary():
    table, steps = [], {}
    for name in RUNS:
        path = "b." + name
        if not os.path.exists(path):
            raise Failure("missing %s (run first)" % path)
        pts, last = read_b(path)
        steps[name] = last - 1   # PT counts the start point as 1
        for p in pts:
            table.append((name,) + p)
    print("AUTO-07p: SFD rotor nonsynchronous response (IPS=2, NTST=100, "
          "NCOL=4), lambda=%g delta=%g zeta=%g, from Omega=%g to %g"
          % (LAM, DELTA, ZETA, OM_START, OM_END))
    print("continuation steps: fw %d, bw %d, total %d"
          % (steps["fw"], steps["bw"], sum(steps.values())))
    print("%-3s %-2s %5s  %-18s %-18s %s" % ("run", "TY", "PT", "Omega",
                                             "period (rot. frame)", "stable"))
    lps, ends, others = [], [], []
    for name, ty, pt, om, period, stable, om_s, dom_s in table:
        print("%-3s %-2s %5d  %-18s %-18.10E %s"
              % (name, ty, pt, om_s, period, "yes" if stable else "no"))
        if ty == "LP":
            lps.append((name, om, om_s, period, dom_s))
        elif ty in ("UZ", "EP", "MX") and pt > 1:
            ends.append((name, ty, om))
        elif ty not in ("EP", "UZ"):
            others.append((name, ty, om))
    # the runs must end on the boundary Ω = 20 (UZSTOP), not elsewhere
    for name, ty, om in ends:
        if ty != "UZ" or abs(om - OM_END) > 1e-6:
            raise Failure("run %s ended with %s at Omega=%g, not at the "
                          "boundary Omega=%g" % (name, ty, om, OM_END))
    if len(ends) != 2:
        raise Failure("expected 2 runs ending at Omega=%g, got %r"
                      % (OM_END, ends))
    if [lp[0] for lp in lps] != ["bw"]:
        raise Failure("expected one LP (fold of cycles) in run bw, AUTO "
                      "found %r" % [(lp[0], lp[1]) for lp in lps])
    for lp in lps:
        print(fold_line(lp)[0])
    if others:
        print("other special points: %s"
              % ", ".join("%s %s at Omega=%.10g" % o for o in others))
    return lps


def fold_line(lp):
    """The LP as AUTO prints it, and Ω = 8.59 + PAR(5) with the digits that
    PAR(5) = Ω − 8.59 (PVLS) adds."""
    name, om, om_s, period, dom_s = lp
    dom = float(dom_s.replace("D", "E"))
    return ("LP (fold of cycles), run %s: Omega = %s (b-file), "
            "8.59 + dOmega = 8.59 + %s = %.15f, period %.10E"
            % (name, om_s, dom_s, 8.59 + dom, period)), 8.59 + dom


def check(lps):
    print("fold of cycles: AUTO LP vs whirl (Omega = %.10f):" % OM_FOLD_REF)
    worst = 0.0
    for lp in lps:
        om = fold_line(lp)[1]
        d = om - OM_FOLD_REF
        print("  run %s: Omega(AUTO) = %.15f, minus %.10f = %.2e"
              % (lp[0], om, OM_FOLD_REF, d))
        worst = max(worst, abs(d))
    if worst > 1e-6:
        raise Failure("AUTO LP differs from whirl's fold by %.3g in Omega"
                      % worst)


def main(argv):
    if len(argv) < 2 or argv[1] not in ("prepare", "run", "summary",
                                         "check"):
        sys.stderr.write(__doc__)
        return 2
    cmd, opts = argv[1], argv[2:]
    bad = [o for o in opts if o not in ("--tight", "--iid0")]
    if bad:
        sys.stderr.write("run_nonsync.py: unknown option %s\n" % bad[0])
        return 2
    tight, iid0 = "--tight" in opts, "--iid0" in opts
    try:
        if cmd in ("prepare", "run"):
            T, rows, closure, rel = write_constants(tight, iid0)
            if cmd == "prepare":
                print("start orbit %s: Omega=%g, period T=%.15g, %d "
                      "intervals, closure %.2e, |dx/dt - f|/|f| = %.2e"
                      % (DATFILE, OM_START, T, len(rows) - 1, closure, rel))
                return 0
            run_auto()
        lps = summary()
        if cmd == "check":
            check(lps)
    except Failure as e:
        sys.stderr.write("run_nonsync.py: error: %s\n" % e)
        return 1
    except (OSError, ValueError, RuntimeError) as e:
        sys.stderr.write("run_nonsync.py: error: %s\n" % e)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

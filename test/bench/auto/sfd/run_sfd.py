#!/usr/bin/python3
"""run_sfd.py — the AUTO-07p side of whirl's speed comparison: the complete
synchronous response of the SFD rotor (Table 1: λ = 0.0503, δ = 0.3, ζ = 0)
for 0.01 <= Ω <= 20, as equilibria of the rotating-frame ODE (sfd.c).

Three AUTO runs (one executable, sfd.exe, built from sfd.c):
  main    from the exact circular orbit at Ω = 0.01, forward to Ω = 20
  iso_fw  from a point of the isola (eq. 15, ε = 0.93), DS > 0, to Ω = 20
  iso_bw  from the same point, DS < 0, through the isola's fold to Ω = 20

Commands (run in a directory holding sfd.c, c.sfd, circ.py, this file):
  prepare [--tight] [--iid0]
                      compute the start points from eq. 15, check them
                      against the ODE residual, write c.sfd_main,
                      c.sfd_iso_fw, c.sfd_iso_bw (AUTO constants files)
  run [--tight] [--iid0]
                      prepare, then run AUTO-07p through its Python
                      interface (compiles sfd.c if sfd.exe is missing or
                      older), keep b.<run>, print the summary
  --tight             EPSL = EPSU = 1e-10, EPSS = 1e-8 (default: AUTO's
                      defaults EPSL = EPSU = 1e-7, EPSS = 1e-5)
  --iid0              IID = 0: no per-step diagnostics (d-file); AUTO's
                      default is IID = 2
  summary             print the summary of the b.<run> files present
  check               summary plus the eq. 15 folds (G = dG/dε = 0) and
                      the differences; fails if |ΔΩ| > 1e-6
Exit status 0 on success, 1 with a message on stderr on any failure.
Needs /usr/bin/python3 and AUTO-07p (AUTO_DIR, default /usr/lib/auto-07p).
SPDX-License-Identifier: BSD-3-Clause
"""
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import circ  # noqa: E402

LAM, DELTA, ZETA = 0.0503, 0.3, 0.0   # Table 1 of the paper
OM_START = 0.01                        # left end of the Ω range
EPS_ISOLA = 0.93                       # radius of the isola start point
RUNS = ("main", "iso_fw", "iso_bw")
TYPES = {1: "BP", 2: "LP", 3: "HB", 4: "", -4: "UZ", 9: "EP", -9: "MX"}


class Failure(Exception):
    pass


def seeds():
    """Start points (Ω, ε, state) of the main branch and the isola."""
    out = {}
    roots = circ.eps_roots(OM_START, LAM, DELTA, ZETA)
    if len(roots) != 1:
        raise Failure("eq. 15 at Omega=%g: expected 1 radius, got %r"
                      % (OM_START, roots))
    out["main"] = (OM_START, roots[0])
    oms = [o for o in circ.omega_roots(EPS_ISOLA, LAM, DELTA, ZETA)
           if 5.0 < o <= 20.0]
    if not oms:
        raise Failure("eq. 15 at eps=%g: no root Omega in (5, 20]"
                      % EPS_ISOLA)
    out["iso"] = (oms[0], EPS_ISOLA)
    res = {}
    for key, (om, eps) in out.items():
        x = circ.state(eps, om, LAM, DELTA, ZETA)
        r = circ.residual(x, om, LAM, DELTA, ZETA)
        # the terms of the ODE are O(Ω² ε): accept rounding-level residuals
        if not r <= 1e-12 * max(1.0, om * om):
            raise Failure("start point %s (Omega=%.17g, eps=%.17g) is not "
                          "an equilibrium: residual %.3g" % (key, om, eps, r))
        res[key] = (om, eps, x, r)
    return res


def write_constants(tight, iid0):
    base = open(os.path.join(HERE, "c.sfd")).read()
    s = seeds()
    extra = ""
    if tight:
        extra += "EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-08\n"
    if iid0:
        extra += "IID = 0\n"
    for name in RUNS:
        om, eps, x, r = s["main" if name == "main" else "iso"]
        ds = -0.01 if name == "iso_bw" else 0.01
        with open("c.sfd_" + name, "w") as f:
            f.write(base)
            f.write(extra)
            f.write("# start point from eq. 15 (ODE residual %.2e)\n" % r)
            f.write("DS = %r\n" % ds)
            f.write("U = {1: %r, 2: %r, 3: 0.0, 4: 0.0}\n" % (x[0], x[1]))
            f.write("PAR = {1: %r, 5: %r}\n" % (om, eps))
    return s


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
                AUTOclui.run(e="sfd", c="sfd_" + name)
            except Exception as e:
                raise Failure("AUTO run %s failed: %s (see auto.log)"
                              % (name, e))
            if not os.path.exists("fort.7"):
                raise Failure("AUTO run %s wrote no fort.7 (see auto.log)"
                              % name)
            shutil.copyfile("fort.7", "b." + name)


def read_b(path):
    """Labelled points of an AUTO b-file: (type, PT, Ω, ε, u, v) per
    label, and the number of the last point."""
    pts, last = [], 0
    for line in open(path):
        w = line.split()
        if len(w) < 11 or w[0] == "0":
            continue
        try:
            br, pt, ty, lab = (int(w[0]), int(w[1]), int(w[2]), int(w[3]))
            vals = [float(v.replace("D", "E")) for v in w[4:11]]
        except ValueError:
            continue
        last = max(last, abs(pt))
        if lab != 0:
            om, _, u, v, _, _, eps = vals
            pts.append((TYPES.get(ty, str(ty)), abs(pt), om, eps, u, v,
                        pt < 0))
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
    print("AUTO-07p: SFD rotor, lambda=%g delta=%g zeta=%g, %g <= Omega <= 20"
          % (LAM, DELTA, ZETA, OM_START))
    print("continuation steps: main %d, iso_fw %d, iso_bw %d, total %d"
          % (steps["main"], steps["iso_fw"], steps["iso_bw"],
             sum(steps.values())))
    print("%-7s %-2s %5s  %-18s %-18s %s" % ("run", "TY", "PT", "Omega",
                                             "eps=sqrt(u^2+v^2)", "stable"))
    lps, ends = [], []
    for name, ty, pt, om, eps, u, v, stable in table:
        e = (u * u + v * v) ** 0.5
        print("%-7s %-2s %5d  %-18.10E %-18.10E %s"
              % (name, ty, pt, om, e, "yes" if stable else "no"))
        if ty == "LP":
            lps.append((om, e))
        if ty in ("UZ", "EP", "MX") and pt > 1:
            ends.append((name, ty, om))
    # the runs must end on the boundary Ω = 20 (UZSTOP), not elsewhere
    for name, ty, om in ends:
        if ty != "UZ" or abs(om - 20.0) > 1e-6:
            raise Failure("run %s ended with %s at Omega=%g, not at the "
                          "boundary Omega=20" % (name, ty, om))
    if len(ends) != 3:
        raise Failure("expected 3 runs ending at Omega=20, got %r" % ends)
    if len(lps) != 3:
        raise Failure("expected 3 LP points, AUTO found %d" % len(lps))
    return lps


def check(lps):
    ref = circ.folds(LAM, DELTA, ZETA, om_min=OM_START, om_max=20.0, n=400)
    ref.sort(key=lambda t: t[1])
    got = sorted(lps)
    if len(ref) != len(got):
        raise Failure("eq. 15 has %d folds, AUTO %d" % (len(ref), len(got)))
    print("eq. 15 folds (G = dG/deps = 0) vs AUTO LP:")
    print("%-18s %-18s %-10s %-10s" % ("Omega (eq. 15)", "eps (eq. 15)",
                                        "dOmega", "deps"))
    worst = 0.0
    for (e, o), (ao, ae) in zip(ref, got):
        print("%-18.13f %-18.13f %-10.2e %-10.2e" % (o, e, ao - o, ae - e))
        worst = max(worst, abs(ao - o))
    if worst > 1e-6:
        raise Failure("AUTO LP differs from eq. 15 fold by %.3g in Omega"
                      % worst)


def main(argv):
    if len(argv) < 2 or argv[1] not in ("prepare", "run", "summary",
                                         "check"):
        sys.stderr.write(__doc__)
        return 2
    cmd, opts = argv[1], argv[2:]
    bad = [o for o in opts if o not in ("--tight", "--iid0")]
    if bad:
        sys.stderr.write("run_sfd.py: unknown option %s\n" % bad[0])
        return 2
    tight, iid0 = "--tight" in opts, "--iid0" in opts
    try:
        if cmd in ("prepare", "run"):
            s = write_constants(tight, iid0)
            if cmd == "prepare":
                for k, (om, eps, x, r) in s.items():
                    print("start %-4s Omega=%.17g eps=%.17g u=%.17g v=%.17g "
                          "residual=%.2e" % (k, om, eps, x[0], x[1], r))
                return 0
            run_auto()
        lps = summary()
        if cmd == "check":
            check(lps)
    except Failure as e:
        sys.stderr.write("run_sfd.py: error: %s\n" % e)
        return 1
    except (OSError, ValueError, RuntimeError) as e:
        sys.stderr.write("run_sfd.py: error: %s\n" % e)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

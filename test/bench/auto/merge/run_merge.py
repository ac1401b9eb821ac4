#!/usr/bin/python3
"""run_merge.py — the AUTO-07p side of whirl's merge-point comparison: the
unbalance δ* at which the isola of the SFD rotor's circular orbits merges
with the resonance peak (doc/auto-merge-benchmark.md), for

    λ = 0.05, 0.25, 1.0 (ζ = 0) and λ = 0.25, ζ = 0.05.

δ* is where the fold curve of the circular orbits in (Ω, δ) has a maximum
of δ (G = ∂G/∂ε = ∂G/∂Ω = 0 in eq. 15).  AUTO-07p has no defining condition
for it.  The chain used here, per case (equation file ../sfd/sfd.c, one
executable sfd.exe for all cases):

  iso    from the largest-radius circular orbit at Ω = 40 (the isola's
         upper branch, eq. 15) at a δ0 < δ*, continue in Ω downwards
         (ICP = [Ω], ILP = 1) and stop at the first LP: the isola's fold
  fold   restart from that LP with ISW = 2 (fold continuation), two free
         parameters, until the δ maximum is passed (see the methods)

Methods (--method):
  lp     (default) fold run with ICP = [δ, Ω]: δ is the principal parameter,
         so AUTO's fold detection (ILP = 1) labels the δ maximum of the fold
         curve as an LP, located by AUTO's own secant iteration; stop there
         (STOP = ['LP1'])
  max    fold run with ICP = [Ω, δ] (Ω principal, as the manual prescribes for
         fold continuation): AUTO labels nothing at the δ maximum; δ* is read
         as the largest δ in the b-file, and also refined by a parabola through
         the three b-file points around it (our post-processing)
  DS > 0 increases the principal parameter, so the fold run starts with
  DS = +0.01 (lp: δ up) or −0.01 (max: Ω down, the isola's left fold moves
  to lower Ω as δ grows); if it misses the maximum anyway (ends at
  δ = δ0 − 0.01 without an LP / an interior maximum), it is repeated with
  the opposite DS, and counted as a run.

Commands (in a directory holding sfd.c, circ.py (both from ../sfd), c.merge
and this file):
  run [--method lp|max] [--tight] [--iid0]
        run the chains through AUTO's Python interface (compiles sfd.c if
        sfd.exe is missing or older); keep b./s./c. files of every run; write
        runs.txt (the runs in order, for a replay with the bare executable);
        print the summary
  summary [--method lp|max]
        print the summary from the b-files present
  check [--method lp|max]
        summary plus the merge point of eq. 15 by Newton (independent of
        whirl and of AUTO) and whirl's values; fails if |Δδ| > 1e-4
  --case NAME[,NAME...]  only these cases (l0.05, l0.25, l1, l0.25z;
           default all four)
  --tight  EPSL = EPSU = 1e-10, EPSS = 1e-8 (default: AUTO's defaults
           EPSL = EPSU = 1e-7, EPSS = 1e-5)
  --iid0   IID = 0 (no per-step diagnostics in the d-file)
  --epss X   EPSS = X only (EPSL, EPSU stay 1e-7): tighter location of the
           LP; --tight fails on the fold curves (Newton stalls above
           EPSL = 1e-10 with JAC = 0, AUTO reports MX)
  --dsmax X  DSMAX = X (default 0.1) in the fold runs (and DS scaled down
           with it, NMX = max(400, 40/X) for max): finer steps on the fold
           curve, i.e. a finer b-file for the max method
Exit status 0 on success, 1 with a message on stderr on any failure.
Needs /usr/bin/python3 and AUTO-07p (AUTO_DIR, default /usr/lib/auto-07p).
SPDX-License-Identifier: BSD-3-Clause
"""
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "sfd"))
import circ  # noqa: E402

# (name, λ, ζ, δ0): δ0 < δ* is the unbalance of the isola start point
CASES = (("l0.05", 0.05, 0.0, 0.30),
         ("l0.25", 0.25, 0.0, 0.40),
         ("l1", 1.0, 0.0, 0.42),
         ("l0.25z", 0.25, 0.05, 0.40))
# whirl's merge points (/tmp/build/drivers/whirl sfd merge --lambda L
# [--zeta Z]): δ*, Ω*, ε*
WHIRL = {"l0.05": (0.330875272605, 3.083631211561, 0.854300282257),
         "l0.25": (0.417043487179, 4.856516730806, 0.719089306000),
         "l1": (0.438010254448, 15.346842474087, 0.667950001321),
         "l0.25z": (0.429278775923, 4.768199109023, 0.710105667510)}
SELECTED = [c[0] for c in CASES]   # --case NAME[,NAME...]
OM_START = 40.0   # the isola start: largest radius of eq. 15 at this Ω
OM_MAX = 50.0
TYPES = {1: "BP", 2: "LP", 3: "HB", 4: "", -4: "UZ", 9: "EP", -9: "MX",
         -22: "CP", -21: "BT", -32: "ZH"}


class Failure(Exception):
    pass


def selected():
    return [c for c in CASES if c[0] in SELECTED]


def point_type(code):
    """Name of an AUTO b-file point type.  On a fold curve (ISW = 2) AUTO
    adds 10·(branch type) to the regular codes: 22 is an LP, 29 an EP,
    -24 a UZ; -22 (CP), -21 (BT), -32 (ZH) are the fold-curve points."""
    if code in TYPES:
        return TYPES[code]
    base = abs(code) % 10
    return TYPES.get(base if code > 0 else -base, str(code))


def read_b(path):
    """Points of an AUTO b-file as dicts (PT, TY, LAB and the named
    columns of the last header)."""
    cols, rows = None, []
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "0":
            if len(w) > 4 and w[1:4] == ["PT", "TY", "LAB"]:
                cols = w[4:]
            continue
        if cols is None or len(w) != 4 + len(cols):
            continue
        r = {"PT": int(w[1]), "TY": point_type(int(w[2])),
             "LAB": int(w[3])}
        for c, v in zip(cols, w[4:]):
            r[c] = float(v.replace("D", "E"))
        rows.append(r)
    return rows


def start(lam, z, dl0):
    """The isola start point: largest ε of eq. 15 at Ω = OM_START."""
    roots = circ.eps_roots(OM_START, lam, dl0, z)
    if len(roots) != 3:
        raise Failure("eq. 15 at Omega=%g, delta=%g: expected 3 radii (main "
                      "branch + isola), got %r" % (OM_START, dl0, roots))
    eps = roots[-1]
    x = circ.state(eps, OM_START, lam, dl0, z)
    r = circ.residual(x, OM_START, lam, dl0, z)
    if not r <= 1e-12 * OM_START ** 2:
        raise Failure("start point (Omega=%g, eps=%.17g) is not an "
                      "equilibrium: residual %.3g" % (OM_START, eps, r))
    return eps, x, r


EPSS = None   # --epss X: override EPSS (the LP location tolerance) only


def constants(extra_lines, tight, iid0):
    s = open(os.path.join(HERE, "c.merge")).read()
    if tight:
        s += "EPSL = 1e-10, EPSU = 1e-10, EPSS = 1e-08\n"
    if EPSS is not None:
        s += "EPSS = %r\n" % EPSS
    if iid0:
        s += "IID = 0\n"
    return s + "".join(l + "\n" for l in extra_lines)


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


def auto_run(clui, tag, text, restart, manifest):
    """One AUTO run from constants c.<tag> (and s.<restart>), outputs kept
    as b./s./d.<tag>; recorded in the manifest for the executable replay."""
    with open("c." + tag, "w") as f:
        f.write(text)
    for f in ("fort.7", "fort.8", "fort.9"):
        if os.path.exists(f):
            os.remove(f)
    try:
        if restart:
            clui.run(e="sfd", c=tag, s=restart)
        else:
            clui.run(e="sfd", c=tag)
    except Exception as e:
        raise Failure("AUTO run %s failed: %s (see auto.log)" % (tag, e))
    if not os.path.exists("fort.7"):
        raise Failure("AUTO run %s wrote no fort.7 (see auto.log)" % tag)
    for k, f in (("b", "fort.7"), ("s", "fort.8"), ("d", "fort.9")):
        if os.path.exists(f):
            shutil.copyfile(f, k + "." + tag)
    manifest.append("%s %s" % (tag, restart or "-"))
    return read_b("b." + tag)


def fold_run(clui, name, method, lp_label, dl0, ds, tight, iid0, dsmax,
             manifest):
    tag = "%s_fold%s" % (name, "p" if ds > 0 else "m")
    icp = ("['delta', 'Omega', 'eps']" if method == "lp"
           else "['Omega', 'delta', 'eps']")
    lines = ["ICP = %s" % icp, "ISW = 2", "IRS = %d" % lp_label,
             "DS = %r" % ds,
             "UZSTOP = {'delta': %r, 'Omega': [0.01, %r]}"
             % (dl0 - 0.01, OM_MAX)]
    lines.append("STOP = ['LP1']" if method == "lp" else "STOP = ['CP1']")
    if method == "max":
        lines.append("NMX = %d" % (400 if dsmax is None else
                                   max(400, int(40 / dsmax))))
    if dsmax is not None:
        lines.append("DSMAX = %r" % dsmax)
        lines.append("DS = %r" % (ds * min(1.0, 10 * dsmax)))
    rows = auto_run(clui, tag, constants(lines, tight, iid0),
                    name + "_iso", manifest)
    return tag, rows


def found(method, rows):
    """The δ maximum of a fold run: the LP row (lp), or the b-file row of
    largest δ if it is interior (max); None if this run missed it."""
    if method == "lp":
        lps = [r for r in rows if r["TY"] == "LP"]
        return lps[0] if lps else None
    i = max(range(len(rows)), key=lambda k: rows[k]["delta"])
    return rows[i] if 0 < i < len(rows) - 1 else None


def run_auto(method, tight, iid0, dsmax):
    auto_dir = os.environ.get("AUTO_DIR", "/usr/lib/auto-07p")
    sys.path.insert(0, os.path.join(auto_dir, "python"))
    os.environ.setdefault("AUTO_DIR", auto_dir)
    manifest = []
    with AutoOutputToLog("auto.log"):
        try:
            from auto import AUTOclui as clui
        except Exception as e:  # pragma: no cover - environment problem
            raise Failure("cannot import AUTO-07p from %s: %s"
                          % (auto_dir, e))
        for name, lam, z, dl0 in selected():
            eps, x, r = start(lam, z, dl0)
            lines = ["ICP = ['Omega', 'eps']", "DS = -0.01",
                     "UZSTOP = {'Omega': [0.01, %r]}" % OM_MAX,
                     "STOP = ['LP1']",
                     "# start point from eq. 15 (ODE residual %.2e)" % r,
                     "U = {1: %r, 2: %r, 3: 0.0, 4: 0.0}" % (x[0], x[1]),
                     "PAR = {1: %r, 2: %r, 3: %r, 4: %r, 5: %r}"
                     % (OM_START, lam, dl0, z, eps)]
            rows = auto_run(clui, name + "_iso",
                            constants(lines, tight, iid0), None, manifest)
            lps = [r for r in rows if r["TY"] == "LP"]
            if not lps:
                raise Failure("%s: the isola run found no LP" % name)
            # DS > 0 increases the principal parameter: δ (lp) goes up,
            # Ω (max) goes up, away from the merge (the isola's left fold
            # moves to lower Ω as δ grows)
            for ds in ((0.01, -0.01) if method == "lp" else (-0.01, 0.01)):
                tag, rows = fold_run(clui, name, method, lps[0]["LAB"], dl0,
                                     ds, tight, iid0, dsmax, manifest)
                if found(method, rows) is not None:
                    break
            else:
                raise Failure("%s: no delta maximum on the fold curve in "
                              "either direction" % name)
    with open("runs.txt", "w") as f:
        f.write("\n".join(manifest) + "\n")


def parabola(rows, i):
    """Vertex of the parabola δ(Ω) through b-file points i−1, i, i+1."""
    (x0, y0), (x1, y1), (x2, y2) = [(rows[k]["Omega"], rows[k]["delta"])
                                    for k in (i - 1, i, i + 1)]
    d01 = (y1 - y0) / (x1 - x0)
    d12 = (y2 - y1) / (x2 - x1)
    a = (d12 - d01) / (x2 - x0)
    # p(x) = y0 + d01 (x - x0) + a (x - x0)(x - x1), p'(xv) = 0
    xv = 0.5 * (x0 + x1) - d01 / (2 * a)
    return y0 + d01 * (xv - x0) + a * (xv - x0) * (xv - x1), xv


def results(method):
    """Per case: (name, λ, ζ, runs, steps, δ, Ω, ε, δ parabola or None)."""
    runs = {}
    if not os.path.exists("runs.txt"):
        raise Failure("missing runs.txt (run first)")
    for line in open("runs.txt"):
        tag = line.split()[0]
        runs.setdefault(tag.split("_")[0], []).append(tag)
    out = []
    for name, lam, z, dl0 in selected():
        tags = runs.get(name)
        if not tags:
            raise Failure("no runs of case %s in runs.txt" % name)
        steps = 0
        for t in tags:
            rows = read_b("b." + t)
            steps += abs(rows[-1]["PT"]) - 1   # PT 1 is the start
        rows = read_b("b." + tags[-1])
        hit = found(method, rows)
        if hit is None:
            raise Failure("%s: last fold run has no delta maximum" % name)
        par = None
        if method == "max":
            i = rows.index(hit)
            par = parabola(rows, i)[0]
        eps = (hit["u"] ** 2 + hit["v"] ** 2) ** 0.5
        out.append((name, lam, z, len(tags), steps, hit["delta"],
                    hit["Omega"], eps, par))
    return out


def merge_ref(eps, om, dl, lam, z):
    """Merge point of eq. 15 by Newton on (G, G_ε, G_Ω) = 0 in (ε, Ω, δ);
    second derivatives in ε, Ω by complex step, δ-derivatives exact."""
    h = 1e-30
    for _ in range(100):
        f = [circ.G(eps, om, lam, dl, z), circ.G_eps(eps, om, lam, dl, z),
             circ.G_Om(eps, om, lam, dl, z)]
        je = [f[1], circ.G_eps(eps + 1j * h, om, lam, dl, z).imag / h,
              circ.G_Om(eps + 1j * h, om, lam, dl, z).imag / h]
        jo = [f[2], circ.G_eps(eps, om + 1j * h, lam, dl, z).imag / h,
              circ.G_Om(eps, om + 1j * h, lam, dl, z).imag / h]
        jd = [-2 * dl * om ** 4, 0.0, -8 * dl * om ** 3]
        m = [[je[k], jo[k], jd[k]] for k in range(3)]
        det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
               - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
               + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
        step = []
        for c in range(3):  # Cramer
            mc = [row[:] for row in m]
            for k in range(3):
                mc[k][c] = f[k]
            step.append((mc[0][0] * (mc[1][1] * mc[2][2] - mc[1][2] * mc[2][1])
                         - mc[0][1] * (mc[1][0] * mc[2][2]
                                       - mc[1][2] * mc[2][0])
                         + mc[0][2] * (mc[1][0] * mc[2][1]
                                       - mc[1][1] * mc[2][0])) / det)
        eps, om, dl = eps - step[0], om - step[1], dl - step[2]
        if max(abs(step[0] / eps), abs(step[1] / om),
               abs(step[2] / dl)) < 1e-14:
            return dl, om, eps
    raise RuntimeError("merge Newton did not converge")


def summary(method, check=False):
    res = results(method)
    print("AUTO-07p: isola-peak merge point, method %s (%s)"
          % (method, "LP of the fold curve, ICP=[delta, Omega]"
             if method == "lp" else
             "largest delta in the b-file, ICP=[Omega, delta]"))
    hdr = "%-7s %-5s %-5s %4s %5s  %-15s %-15s %-15s %-10s" % (
        "case", "lam", "zeta", "runs", "steps", "delta*", "Omega*", "eps*",
        "d-whirl")
    if method == "max":
        hdr += " %-15s %-10s" % ("delta parabola", "d-whirl")
    print(hdr)
    worst = 0.0
    for name, lam, z, nr, st, dl, om, eps, par in res:
        wd = WHIRL[name][0]
        line = "%-7s %-5g %-5g %4d %5d  %-15.11f %-15.11f %-15.11f %-10.2e" % (
            name, lam, z, nr, st, dl, om, eps, dl - wd)
        if par is not None:
            line += " %-15.11f %-10.2e" % (par, par - wd)
        print(line)
        worst = max(worst, abs(dl - wd))
    if not check:
        return
    print("eq. 15 merge point (Newton from AUTO's point) vs whirl and AUTO:")
    print("%-7s %-16s %-16s %-16s %-9s %-9s %-9s %-9s" % (
        "case", "delta (eq. 15)", "Omega (eq. 15)", "eps (eq. 15)",
        "whirl-ref", "AUTO dd", "AUTO dO", "AUTO de"))
    for name, lam, z, nr, st, dl, om, eps, par in res:
        rd, ro, re = merge_ref(eps, om, dl, lam, z)
        print("%-7s %-16.13f %-16.13f %-16.13f %-9.1e %-9.1e %-9.1e %-9.1e"
              % (name, rd, ro, re, WHIRL[name][0] - rd, dl - rd, om - ro,
                 eps - re))
    if worst > 1e-4:
        raise Failure("AUTO's delta* differs from whirl's by %.3g" % worst)


def main(argv):
    global EPSS
    if len(argv) < 2 or argv[1] not in ("run", "summary", "check"):
        sys.stderr.write(__doc__)
        return 2
    cmd, opts = argv[1], argv[2:]
    method, tight, iid0, dsmax = "lp", False, False, None
    i = 0
    while i < len(opts):
        o = opts[i]
        if o == "--method" and i + 1 < len(opts) and \
                opts[i + 1] in ("lp", "max"):
            method = opts[i + 1]
            i += 1
        elif o == "--dsmax" and i + 1 < len(opts):
            dsmax = float(opts[i + 1])
            if not 0 < dsmax <= 0.1:
                sys.stderr.write("run_merge.py: --dsmax must be in (0, 0.1]\n")
                return 2
            i += 1
        elif o == "--case" and i + 1 < len(opts):
            names = opts[i + 1].split(",")
            bad = [n for n in names if n not in [c[0] for c in CASES]]
            if bad:
                sys.stderr.write("run_merge.py: unknown case %s\n" % bad[0])
                return 2
            SELECTED[:] = names
            i += 1
        elif o == "--epss" and i + 1 < len(opts):
            EPSS = float(opts[i + 1])
            i += 1
        elif o == "--tight":
            tight = True
        elif o == "--iid0":
            iid0 = True
        else:
            sys.stderr.write("run_merge.py: bad option %s\n" % o)
            return 2
        i += 1
    try:
        if cmd == "run":
            run_auto(method, tight, iid0, dsmax)
        summary(method, check=(cmd == "check"))
    except Failure as e:
        sys.stderr.write("run_merge.py: error: %s\n" % e)
        return 1
    except (OSError, ValueError, RuntimeError, KeyError) as e:
        sys.stderr.write("run_merge.py: error: %s\n" % e)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

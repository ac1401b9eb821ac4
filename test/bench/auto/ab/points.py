#!/usr/bin/python3
"""points.py — list the labelled points of AUTO-07p b-files with all the
digits AUTO writes, and compare them with published.txt (AUTO-07p's own
regression log, 6 significant digits).

usage: points.py list b.FILE...      print TY, PT, PAR, L2-NORM, U(1), U(2)
       points.py compare published.txt
                                     compare the b-files named in it (in the
                                     current directory) point by point
Exit status 1 with a message on stderr on a mismatch or unreadable file.
SPDX-License-Identifier: BSD-3-Clause
"""
import sys

# AUTO's point types (last digit, signed; as in AUTO's manual)
NAMES = {1: "BP", 2: "LP", 3: "HB", 4: "RG", -4: "UZ", 9: "EP", -9: "MX",
         -1: "BT", -2: "CP", -3: "ZH"}


def type_name(ty):
    t = ty % 10 if ty >= 0 else -((-ty) % 10)
    return NAMES.get(t, str(ty))


def labelled(path):
    """(TY, |PT|, first four numbers) of every labelled point, in order."""
    out = []
    with open(path) as f:
        for line in f:
            w = line.split()
            if len(w) < 8 or w[0] == "0":
                continue
            try:
                pt, ty, lab = int(w[1]), int(w[2]), int(w[3])
                vals = [float(v.replace("D", "E")) for v in w[4:8]]
            except ValueError:
                continue
            if lab != 0:
                out.append((type_name(ty), abs(pt), vals))
    return out


def same6(ours, pub):
    """ours agrees with pub to AUTO's 6 printed digits."""
    if "%.5E" % ours == "%.5E" % pub:
        return True
    return abs(ours - pub) <= 5.01e-6 * abs(pub)


def main(argv):
    if len(argv) >= 3 and argv[1] == "list":
        for path in argv[2:]:
            print("# %s" % path)
            for ty, pt, v in labelled(path):
                print("%-2s %5d " % (ty, pt)
                      + " ".join("%18.10E" % x for x in v))
        return 0
    if len(argv) == 3 and argv[1] == "compare":
        pub = {}
        order = []
        with open(argv[2]) as f:
            for line in f:
                w = line.split()
                if not w or w[0].startswith("#"):
                    continue
                if w[0] not in pub:
                    pub[w[0]] = []
                    order.append(w[0])
                pub[w[0]].append((w[1], int(w[2]), [float(x) for x in w[3:7]]))
        bad = 0
        n = 0
        for path in order:
            ours = labelled(path)
            if len(ours) != len(pub[path]):
                sys.stderr.write("%s: %d labelled points, published %d\n"
                                 % (path, len(ours), len(pub[path])))
                bad += 1
            for (ty, pt, v), (pty, ppt, pv) in zip(ours, pub[path]):
                n += 1
                if ty != pty or pt != ppt or not all(
                        same6(a, b) for a, b in zip(v, pv)):
                    sys.stderr.write("%s: ours %s %d %s, published %s %d %s\n"
                                     % (path, ty, pt, v, pty, ppt, pv))
                    bad += 1
        if bad:
            sys.stderr.write("points.py: %d mismatches\n" % bad)
            return 1
        print("all %d published points reproduced to AUTO's 6 digits" % n)
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except (OSError, ValueError) as e:
        sys.stderr.write("points.py: error: %s\n" % e)
        sys.exit(1)

#!/usr/bin/env python3
"""test/auto-demos/exact.py - converged references for special points of
AUTO-07p's demos that AUTO's own runs do not print to 6 digits: AUTO
detects the point (its test function changes sign) but its localisation
stops short of it (hyper.all's EPSS = 1e-4) or fails to converge at EPSS =
1e-10 (its d-file: "NOTE:Possible special point"), so neither of the logs
test/auto-demos/run.sh compares with holds the point.  Writes
test/auto-demos/exact.ref (run `python3 exact.py > exact.ref`), rows
"demo<TAB>TY v1 v2 ...<TAB>how", the values in the order of the demo's
b-file columns (ICP(1), L2-NORM, the state, the other ICP parameters).

Independent of whirl: each point is reduced by hand to one scalar equation
of the demo's own FUNC (read from its .f90, derivations below and in
doc/auto-reference.md), solved by bisection to the last bit.
"""
import cmath
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "examples", "auto"))
from bisection import bisect  # noqa: E402 (examples/auto/bisection.py)


def eig2(A):
    """The eigenvalues of a real 2x2 matrix, the one of positive imaginary
    part first."""
    tr, det = A[0][0] + A[1][1], A[0][0] * A[1][1] - A[0][1] * A[1][0]
    d = cmath.sqrt(tr * tr / 4 - det)
    l1, l2 = tr / 2 + d, tr / 2 - d
    return (l1, l2) if l1.imag >= l2.imag else (l2, l1)


def null2(A, lam):
    """A vector q with (A - lam I) q = 0 (2x2, lam an eigenvalue)."""
    a, b = A[0][0] - lam, A[0][1]
    return (-b, a) if abs(a) + abs(b) > 0 else (1, 0)


def lyapunov1(A, B, C):
    """The first Lyapunov coefficient of a planar vector field at a Hopf
    point (Kuznetsov, Elements of Applied Bifurcation Theory, 3rd ed.,
    (3.20)): l1 = Re(i g20 g11 + omega g21) / (2 omega^2), with A q = i
    omega q, A^T p = -i omega p, <p, q> = 1, g20 = <p, B(q, q)>, g11 =
    <p, B(q, conj q)>, g21 = <p, C(q, q, conj q)>; B, C the second and
    third derivatives as bilinear and trilinear functions."""
    lam, _ = eig2(A)
    om = lam.imag
    q = null2(A, lam)
    At = [[A[0][0], A[1][0]], [A[0][1], A[1][1]]]
    p = null2(At, lam.conjugate())
    dot = lambda u, v: u[0].conjugate() * v[0] + u[1].conjugate() * v[1]
    s = dot(p, q)
    p = (p[0] / s.conjugate(), p[1] / s.conjugate())
    qb = (q[0].conjugate(), q[1].conjugate())
    g20, g11, g21 = dot(p, B(q, q)), dot(p, B(q, qb)), dot(p, C(q, q, qb))
    return (1j * g20 * g11 + om * g21).real / (2 * om * om)


def row(demo, ty, vals, how):
    return "%s\t%s %s\t%s" % (demo, ty, " ".join("%.10E" % v for v in vals), how)


def fhn_gh():
    """fhn (c.fhn.3, c.fhn.4): the Hopf curve of x' = c (x - x^3/3 + y),
    y' = -(x - a + b y)/c, b = 0.8, in (a, c).  Equilibrium y = x^3/3 - x,
    a = x + b y; Hopf where the trace c (1 - x^2) - b/c = 0, c^2 = b /
    (1 - x^2).  The only nonlinearity is -c x^3/3 in the first equation:
    B(u, v) = (-2 c x u1 v1, 0), C(u, v, w) = (-2 c u1 v1 w1, 0).  GH where
    l1 = 0 (x = 1/2 by this bisection: a = 2/15, c = sqrt(16/15)).
    Columns PAR(1), L2-NORM, U(1), U(2), PAR(3)."""
    b = 0.8

    def at(x):
        c = math.sqrt(b / (1 - x * x))
        A = [[c * (1 - x * x), c], [-1 / c, -b / c]]
        B = lambda u, v: (-2 * c * x * u[0] * v[0], 0)
        C = lambda u, v, w: (-2 * c * u[0] * v[0] * w[0], 0)
        return c, lyapunov1(A, B, C)

    x = bisect(lambda x: at(x)[1], 0.3, 0.7)
    c = at(x)[0]
    y = x ** 3 / 3 - x
    a = x + b * y
    return row("fhn", "GH", [a, math.hypot(x, y), x, y, c],
               "l1 = 0 on the Hopf curve (AUTO's GH test function changes sign between PT 47 "
               "and 48 of c.fhn.4; its localisation stops at ITMX, 'Possible special point')")


def enz_lp():
    """enz (c.enz.2, branch 2 of MXBF): the asymmetric branch of
    F1 = (s0 - s1) + (s2 - s1) - rho R(s1), F2 = (s0 + mu - s2) + (s1 - s2)
    - rho R(s2), R(s) = s/(1 + s + kappa s^2), mu = 0, rho = 100,
    kappa = 1, meets the symmetric branch s1 = s2 = s at its pitchfork,
    where the antisymmetric eigenvalue -3 - rho R'(s) vanishes; s0 = s +
    rho R(s) is there extremal along branch 2 (s0 - s0* ~ (s1 - s2)^2): its
    LP.  Columns PAR(1), L2-NORM, U(1), U(2)."""
    rho, kappa = 100.0, 1.0
    R = lambda s: s / (1 + s + kappa * s * s)
    dR = lambda s: (1 - kappa * s * s) / (1 + s + kappa * s * s) ** 2
    s = bisect(lambda s: -3 - rho * dR(s), 1.5, 20.0)
    s0 = s + rho * R(s)
    return row("enz", "LP", [s0, math.sqrt(2) * s, s, s],
               "the turning point of branch 2 at branch 1's pitchfork, s1 = s2 "
               "(AUTO's LP 9 stops at EPSS with s1, s2 = 4.39458, 4.39436)")


def ppp_bp():
    """ppp (c.ppp.1, branch 2 from BP 2; again in c.ppp.4): the branch
    u3 = 0 of F1 = u1 (1 - u1) - p4 u1 u2, F2 = -p2 u2 + p4 u1 u2 - p5 u2 u3
    - p1 (1 - exp(-p6 u2)), F3 = -p3 u3 + p5 u2 u3, p2..p6 = 0.25, 0.5, 3,
    3, 5 (STPNT), meets the branch u3 != 0 where F3's factor -p3 + p5 u2
    vanishes (a transcritical BP): u2 = p3/p5, u1 = 1 - p4 u2 from F1, p1
    from F2.  Closed form, no iteration.  Columns PAR(1), L2-NORM, U(1),
    U(2), U(3)."""
    p2, p3, p4, p5, p6 = 0.25, 0.5, 3.0, 3.0, 5.0
    u2 = p3 / p5
    u1 = 1 - p4 * u2
    p1 = u2 * (p4 * u1 - p2) / (1 - math.exp(-p6 * u2))
    return row("ppp", "BP", [p1, math.hypot(u1, u2), u1, u2, 0.0],
               "u3 = 0 meets u2 = p3/p5 (hyper.all's BP 6 stops at EPSS = 1e-4, "
               "0.368452; at EPSS = 1e-10 AUTO's run of c.ppp.1 detects it after PT 30 of "
               "branch 2, its localisation at 0.368470 stopping at ITMX, 'Possible special "
               "point')")


def cusp_cp():
    """cusp (cusp.auto's fold locus from LP1, ISW = 2, ICP = [mu, lambda]):
    F = mu + lambda x - x^3.  The fold curve F = F_x = 0 is lambda = 3 x^2,
    mu = -2 x^3; its cusp, where F_xx = -6 x vanishes too, is x = 0, mu =
    lambda = 0.  Closed form.  Columns PAR(2) = mu (ICP(1)), L2-NORM, U(1),
    PAR(1) = lambda."""
    return row("cusp", "CP", [0.0, 0.0, 0.0, 0.0],
               "x = mu = lambda = 0 on the fold curve lambda = 3 x^2, mu = -2 x^3 "
               "(hyper.all's CP 12 stops at EPSS = 1e-4, x = 1.00472e-4, lambda = 3.03e-8)")


print("# test/auto-demos/exact.ref - written by exact.py (see there): converged")
print("# special points that AUTO-07p's own runs detect but do not print to 6 digits.")
print("# demo\tTY values (the b-file's columns)\thow")
print(fhn_gh())
print(enz_lp())
print(ppp_bp())
print(cusp_cp())

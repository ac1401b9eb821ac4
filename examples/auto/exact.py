#!/usr/bin/env python3
"""examples/auto/exact.py - exact values of the special points where AUTO-07p's
published output (examples/auto/*.ref) is further than one unit of its 6th
printed digit from the true point; writes examples/auto/exact.ref, which
test/regress/auto_demos.sh uses in place of AUTO's row.

Independent of whirl: every point is reduced by hand to one scalar equation
(derivations below and in doc/auto-reference.md) solved by bisection to the
last bit, or is a closed form.  Run `python3 exact.py > exact.ref`.

Columns are those of the demo's .ref file: run, TY, AUTO's PT, parameters,
PERIOD ('-' for equilibria, None where the .ref has no PERIOD column),
L2-NORM (the Euclidean norm of the state for an
equilibrium), state.
"""
import math

from bisection import bisect  # beside this file


def row(run, ty, pt, pars, state, period="-"):
    l2 = math.sqrt(sum(v * v for v in state))
    cols = [run, ty, str(pt)] + ["%.10E" % v if isinstance(v, float) else str(v)
                                 for v in pars]
    cols += ([period] if period else []) + ["%.10E" % l2] + ["%.10E" % v for v in state]
    return "\t".join(cols)


out = []

# --- ab: u1' = -u1 + Da (1 - u1) e^u2,  u2' = -u2 + B Da (1 - u1) e^u2 - beta u2.
# On equilibria B f1 - f2 = 0 gives u1 = (1 + beta) u2 / B, and then
# Da(u2) = u1 e^-u2 / (1 - u1).  With r = Da (1 - u1) e^u2 = u1 the trace of
# the Jacobian is  -2 - beta - u1 / (1 - u1) + B u1  (Hopf: trace = 0, the
# determinant being positive there); a user value Da = D solves Da(u2) = D.
def ab_u1(u2, B, beta):
    return (1.0 + beta) * u2 / B


def ab_Da(u2, B, beta):
    u1 = ab_u1(u2, B, beta)
    return u1 * math.exp(-u2) / (1.0 - u1)


def ab_trace(u2, B, beta):
    u1 = ab_u1(u2, B, beta)
    return -2.0 - beta - u1 / (1.0 - u1) + B * u1


def ab_point(run, ty, pt, B, beta, u2):
    u1 = ab_u1(u2, B, beta)
    return row(run, ty, pt, [ab_Da(u2, B, beta), B, beta], [u1, u2])


beta = 3
for run, ty, pt, B, lo, hi in [("ab-6", "HB", 80, 17, 3.7, 4.0),
                               ("ab-7", "HB", 26, 18, 1.2, 1.5),
                               ("ab-7", "HB", 84, 18, 4.0, 4.3)]:
    u2 = bisect(lambda v: ab_trace(v, B, beta), lo, hi)
    out.append(ab_point(run, ty, pt, B, beta, u2))
# ab-6 stops at Da = 0.25 on the upper part of the S-curve (u1 near 0.93)
u2 = bisect(lambda v: ab_Da(v, 17, beta) - 0.25, 3.8, 4.1)
out.append(ab_point("ab-6", "UZ", 82, 17, beta, u2))

# ab-8, ab-9, ab-10 stop at Da = 0.25 on stable periodic orbits (B = 14, 15,
# 16).  AUTO's MAX is the maximum over its mesh and collocation nodes, so on
# the spike of u2 it depends on the mesh; the orbit itself is computed here
# by long time integration (independent of any collocation): classical RK4
# with a fixed step, first a transient from near the equilibrium inside the
# cycle, then Newton on the shooting equations phi_T(u1, c) = (u1, c) for
# (u1, T) with u2 = c fixed (c halfway through the range of u2), with N
# steps of T/N.  PERIOD is T, L2-NORM
# sqrt(1/T int |u|^2 dt) (Simpson), MAX the largest sample refined by the
# parabola through it and its neighbours.
def rk4(f, u1, u2, h, nsteps, samples=None):
    for _ in range(nsteps):
        a1, a2 = f(u1, u2)
        b1, b2 = f(u1 + 0.5 * h * a1, u2 + 0.5 * h * a2)
        c1, c2 = f(u1 + 0.5 * h * b1, u2 + 0.5 * h * b2)
        d1, d2 = f(u1 + h * c1, u2 + h * c2)
        u1 += h / 6.0 * (a1 + 2.0 * b1 + 2.0 * c1 + d1)
        u2 += h / 6.0 * (a2 + 2.0 * b2 + 2.0 * c2 + d2)
        if samples is not None:
            samples.append((u1, u2))
    return u1, u2


def cycle(f, u1, u2, h=1e-3, transient=200000, N=40000):
    """The stable limit cycle of the planar system f reached from (u1, u2):
    (PERIOD, L2-NORM, [MAX u1, MAX u2])."""
    u1, u2 = rk4(f, u1, u2, h, transient)
    # the section u2 = c halfway through the range of u2 on the attractor
    lo2, hi2, y1, y2 = u2, u2, u1, u2
    for _ in range(int(60.0 / h)):
        y1, y2 = rk4(f, y1, y2, h, 1)
        lo2, hi2 = min(lo2, y2), max(hi2, y2)
    assert hi2 - lo2 > 1e-3, "the transient did not end on a cycle"
    c = 0.5 * (lo2 + hi2)
    # the first upward crossing of u2 = c, located by bisection in time
    for _ in range(int(1e7)):
        n1, n2 = rk4(f, u1, u2, h, 1)
        if u2 < c <= n2:
            lo, hi = 0.0, h
            for _ in range(60):
                m = 0.5 * (lo + hi)
                if rk4(f, u1, u2, m, 1)[1] < c:
                    lo = m
                else:
                    hi = m
            x = rk4(f, u1, u2, lo, 1)[0]
            break
        u1, u2 = n1, n2
    # the period: the next upward crossing
    T, y1, y2, t = None, x, c, 0.0
    while T is None:
        n1, n2 = rk4(f, y1, y2, h, 1)
        if t > 0.1 and y2 < c <= n2:
            T = t + h * (c - y2) / (n2 - y2)
        y1, y2, t = n1, n2, t + h
    # Newton on the shooting residual (u1(T) - x, u2(T) - c)
    def res(x, T):
        e1, e2 = rk4(f, x, c, T / N, N)
        return e1 - x, e2 - c
    for _ in range(8):
        r1, r2 = res(x, T)
        dx, dT = 1e-7, 1e-7 * T
        a1, a2 = res(x + dx, T)
        b1, b2 = res(x, T + dT)
        j11, j21 = (a1 - r1) / dx, (a2 - r2) / dx
        j12, j22 = (b1 - r1) / dT, (b2 - r2) / dT
        det = j11 * j22 - j12 * j21
        sx = (r1 * j22 - r2 * j12) / det
        sT = (j11 * r2 - j21 * r1) / det
        x, T = x - sx, T - sT
        if abs(sx) < 1e-13 and abs(sT) < 1e-13 * T:
            break
    samples = [(x, c)]
    rk4(f, x, c, T / N, N, samples)
    # Simpson over the N + 1 samples (N even) for the mean of |u|^2
    w = [1.0 if k in (0, N) else (4.0 if k % 2 else 2.0) for k in range(N + 1)]
    l2 = math.sqrt(sum(wk * (a * a + b * b) for wk, (a, b) in zip(w, samples)) / (3.0 * N))
    mx = []
    for i in (0, 1):
        vals = [s[i] for s in samples[:-1]]
        k = max(range(N), key=lambda q: vals[q])
        ym, y0, yp = vals[k - 1], vals[k], vals[(k + 1) % N]
        den = ym - 2.0 * y0 + yp
        mx.append(y0 - 0.125 * (yp - ym) ** 2 / den if den != 0 else y0)
    return T, l2, mx


def ab_f(Da, B, beta):
    def f(u1, u2):
        r = Da * (1.0 - u1) * math.exp(u2)
        return -u1 + r, -u2 + B * r - beta * u2
    return f


def ab_cycle(Da, B, beta):
    u2e = bisect(lambda v: ab_Da(v, B, beta) - Da, 0.5, B / (1.0 + beta) * (1.0 - 1e-9))
    return cycle(ab_f(Da, B, beta), ab_u1(u2e, B, beta), u2e + 0.01)


for run, pt, B in [("ab-8", 161, 14), ("ab-9", 222, 15), ("ab-10", 309, 16)]:
    T, l2, mx = ab_cycle(0.25, B, beta)
    out.append("\t".join([run, "UZ", str(pt), "%.10E" % 0.25, str(B), str(beta),
                          "%.10E" % T, "%.10E" % l2] + ["%.10E" % v for v in mx]))

# --- cusp: x' = mu + lambda x - x^3 (parameters lambda, mu).
# Folds: lambda = 3 x^2, mu = -2 x^3; at lambda = 1, x = -+1/sqrt(3),
# mu = +-2 / (3 sqrt 3).  The stops mu = -+2 at lambda = 1 solve
# x^3 - x -+ 2 = 0 (one real root each, +-1.52138); on the fold curve
# mu = +-2 is x = -+1, lambda = 3.  The cusp point is (0, 0, 0).
s3 = 1.0 / math.sqrt(3.0)
out.append(row("cusp-1", "LP", 14, [1.0, 2.0 / (3.0 * math.sqrt(3.0))], [-s3], None))
out.append(row("cusp-2", "LP", 14, [1.0, -2.0 / (3.0 * math.sqrt(3.0))], [s3], None))
xr = bisect(lambda x: x ** 3 - x - 2.0, 1.0, 2.0)
out.append(row("cusp-1", "UZ", 47, [1.0, -2.0], [-xr], None))
out.append(row("cusp-2", "UZ", 47, [1.0, 2.0], [xr], None))
out.append(row("cusp-3", "UZ", 34, [3.0, 2.0], [-1.0], None))
out.append(row("cusp-4", "CP", 29, [0.0, 0.0], [0.0], None))
out.append(row("cusp-4", "UZ", 85, [3.0, -2.0], [1.0], None))

# --- enz: s1' = (s0 - s1) + (s2 - s1) - rho R(s1),
#          s2' = (s0 + mu - s2) + (s1 - s2) - rho R(s2),  R(s) = s/(1+s+kappa s^2).
# At mu = 0 the symmetric branch s1 = s2 = s has s0 = s + rho R(s); its
# antisymmetric eigenvalue -3 - rho R'(s) vanishes at the pitchfork, where
# the asymmetric branch turns (AUTO's LP 172 on the branch from the BP).
rho, kappa = 100.0, 1.0


def enz_R(s):
    return s / (1.0 + s + kappa * s * s)


def enz_dR(s):
    d = 1.0 + s + kappa * s * s
    return (1.0 - kappa * s * s) / (d * d)


s = bisect(lambda v: -3.0 - rho * enz_dR(v), 3.0, 6.0)
out.append(row("enz-2", "LP", 172, [s + rho * enz_R(s), 0, 100, 1], [s, s], None))

# --- pp2: fish' = r x (1 - x) - x y - quota (1 - e^(-k x)),
#          sharks' = -y + c x y.  At quota = 0 the shark-free state is (1, 0).
out.append(row("pp2-2", "UZ", 79, [0.0, 3, 5, 3], [1.0, 0.0]))

# pp2-5 stops at quota = 0 on the coexistence branch: fish = 1/c,
# sharks = r (1 - 1/c) - c quota (1 - e^(-k/c)) = 2.
out.append(row("pp2-5", "UZ", 40, [0.0, 3, 5, 3], [1.0 / 3.0, 2.0]))


# pp2-6 stops where the period of the orbits born at the HB reaches 36, a
# stable orbit: quota is found by the secant method on T(quota) = 36, each
# T from the limit cycle reached by integration from the coexistence
# equilibrium (the h and N of the integration resolve the orbit's spike).
def pp2_f(q, r=3.0, k=5.0, c=3.0):
    def f(x, y):
        return r * x * (1.0 - x) - x * y - q * (1.0 - math.exp(-k * x)), -y + c * x * y
    return f


def pp2_cycle(q):
    x = 1.0 / 3.0
    y = 3.0 * (1.0 - x) - 3.0 * q * (1.0 - math.exp(-5.0 / 3.0))
    return cycle(pp2_f(q), x, y + 0.01, h=2e-3, transient=100000, N=120000)


q0, q1 = 0.70793, 0.70795
T0, T1 = pp2_cycle(q0)[0] - 36.0, pp2_cycle(q1)[0] - 36.0
for _ in range(30):
    q2 = q1 - T1 * (q1 - q0) / (T1 - T0)
    q0, T0 = q1, T1
    q1 = q2
    res = pp2_cycle(q1)
    T1 = res[0] - 36.0
    if abs(T1) < 1e-9 or abs(q1 - q0) < 1e-15:
        break
T, l2, mx = res
out.append("\t".join(["pp2-6", "UZ", "26", "%.10E" % q1, "3", "5", "3", "%.10E" % T,
                      "%.10E" % l2] + ["%.10E" % v for v in mx]))

# ab-11 and ab-13 stop at PERIOD = 1000 (UZSTOP), where AUTO prints its
# localised stop at 9.99882E+02 and 9.99998E+02: AUTO's rows with the stop
# value the run asks for (near the homoclinic orbit the other columns hardly
# change with the period: whirl agrees with AUTO's to 6 digits).
out.append("\t".join(["ab-11", "UZ", "116", "1.20102E-01", "17", "3", "1000",
                      "2.07774E+00", "4.77420E-01", "2.02903E+00"]))
out.append("\t".join(["ab-13", "UZ", "67", "1.10829E-01", "18", "3", "1000",
                      "1.75170E+00", "3.80862E-01", "1.71388E+00"]))

print("# run\tTY\tPT\tparameters...\tPERIOD\tL2-NORM\tstate...")
print("# examples/auto/exact.ref - written by exact.py (see there and")
print("# doc/auto-reference.md): exact special points replacing AUTO-07p's")
print("# printed rows that are off by more than one unit of the 6th digit.")
for r in out:
    print(r)

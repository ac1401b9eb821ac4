"""circ.py — circular synchronous orbits of the SFD rotor (paper eqs. 15-17)
and the rotating-frame right-hand side, in plain Python (no numpy), for the
AUTO-07p benchmark of whirl: start points for AUTO, residual checks and
reference folds.

Parameters: lam (λ), dl (δ), z (ζ); Om (Ω); eps (ε, orbit radius / clearance).
SPDX-License-Identifier: BSD-3-Clause
"""
import cmath
import math


def ab(eps, lam):
    """Force coefficients F_r = a Ω, F_t = b Ω of a circular orbit (and
    their ε-derivatives).  Works for complex eps (complex-step)."""
    s = 1 - eps * eps
    a = -4 * lam * eps * eps / (s * s)
    b = -math.pi * lam * eps / s ** 1.5
    da = -8 * lam * eps * (1 + eps * eps) / s ** 3
    db = -math.pi * lam * (1 + 2 * eps * eps) / s ** 2.5
    return a, b, da, db


def coeffs(eps, lam, dl, z):
    """c4..c0 of the quartic in Ω (eq. 15) and their ε-derivatives."""
    a, b, da, db = ab(eps, lam)
    c = [eps * eps - dl * dl,
         2 * eps * a,
         eps * eps * (4 * z * z - 2) + a * a + b * b - 4 * z * eps * b,
         -2 * eps * a,
         eps * eps]
    dc = [2 * eps,
          2 * a + 2 * eps * da,
          2 * eps * (4 * z * z - 2) + 2 * a * da + 2 * b * db
          - 4 * z * (b + eps * db),
          -2 * a - 2 * eps * da,
          2 * eps]
    return c, dc


def polyval(c, x):
    r = 0
    for ci in c:
        r = r * x + ci
    return r


def G(eps, Om, lam, dl, z):
    return polyval(coeffs(eps, lam, dl, z)[0], Om)


def G_eps(eps, Om, lam, dl, z):
    return polyval(coeffs(eps, lam, dl, z)[1], Om)


def G_Om(eps, Om, lam, dl, z):
    c = coeffs(eps, lam, dl, z)[0]
    return polyval([4 * c[0], 3 * c[1], 2 * c[2], c[3]], Om)


def omega_roots(eps, lam, dl, z):
    """All real roots Ω > 0 of eq. 15 for radius eps, ascending
    (Durand-Kerner for the four complex roots, then Newton polish)."""
    c = coeffs(eps, lam, dl, z)[0]
    if c[0] == 0:
        raise ValueError("eps == delta: quartic degenerates")
    m = [ci / c[0] for ci in c]
    rts = [(0.4 + 0.9j) ** k for k in range(4)]
    for _ in range(500):
        new = []
        for i, r in enumerate(rts):
            den = 1
            for j, q in enumerate(rts):
                if j != i:
                    den *= (r - q)
            new.append(r - polyval(m, r) / den)
        done = max(abs(a - b) for a, b in zip(new, rts)) < 1e-15
        rts = new
        if done:
            break
    out = []
    for r in rts:
        if abs(r.imag) > 1e-7 * max(1.0, abs(r)):
            continue
        x = r.real
        for _ in range(20):
            dp = polyval([4 * c[0], 3 * c[1], 2 * c[2], c[3]], x)
            if dp == 0:
                break
            dx = polyval(c, x) / dp
            x -= dx
            if abs(dx) <= 1e-16 * abs(x):
                break
        if x > 0:
            out.append(x)
    return sorted(out)


def phase(eps, Om, lam, dl, z):
    """β of eqs. 16-17: δΩ² cos β = ε − εΩ² − F_r, δΩ² sin β = 2ζεΩ − F_t."""
    a, b, _, _ = ab(eps, lam)
    return math.atan2(2 * z * eps * Om - b * Om, eps - eps * Om * Om - a * Om)


def state(eps, Om, lam, dl, z):
    """Rotating-frame state (u, v, u', v') of the orbit: u + iv = ε e^{−iβ}."""
    beta = phase(eps, Om, lam, dl, z)
    return [eps * math.cos(beta), -eps * math.sin(beta), 0.0, 0.0]


def force(x, y, vx, vy, lam):
    """π-film force of both dampers (DESIGN.md, eq. 8), exact at ε = 0."""
    e = math.hypot(x, y)
    if e >= 1:
        raise ValueError("contact: eps = %g >= 1" % e)
    if e == 0:
        return -math.pi * lam * vx, -math.pi * lam * vy
    rx, ry = x / e, y / e
    tx, ty = -ry, rx
    er = rx * vx + ry * vy          # ε'
    et = tx * vx + ty * vy          # ε γ'
    s = 1 - e * e
    fr = -2 * lam * (0.5 * math.pi * (1 + 2 * e * e) / s ** 2.5 * er
                     + 2 * e / (s * s) * et)
    ft = -2 * lam * (2 * e / (s * s) * er + 0.5 * math.pi / s ** 1.5 * et)
    return fr * rx + ft * tx, fr * ry + ft * ty


def rhs(xs, Om, lam, dl, z):
    """Rotating frame: w'' + 2iΩw' − Ω²w + 2ζ(w' + iΩw) + w = δΩ² + f."""
    u, v, p, q = xs
    fx, fy = force(u, v, p - Om * v, q + Om * u, lam)
    return [p, q,
            2 * Om * q + Om * Om * u - 2 * z * (p - Om * v) - u
            + dl * Om * Om + fx,
            -2 * Om * p + Om * Om * v - 2 * z * (q + Om * u) - v + fy]


def residual(xs, Om, lam, dl, z):
    return max(abs(r) for r in rhs(xs, Om, lam, dl, z))


def eps_roots(Om, lam, dl, z, n=4000, emax=0.9999):
    """All radii 0 < ε < emax of circular orbits at speed Om (eq. 15 in ε),
    by sign changes on a grid (geometric near 0) and bisection."""
    grid = [emax * (k / n) ** 2 for k in range(1, n + 1)]
    out = []
    g0 = G(grid[0], Om, lam, dl, z)
    for e0, e1 in zip(grid, grid[1:]):
        g1 = G(e1, Om, lam, dl, z)
        if g0 == 0:
            out.append(e0)
        elif g0 * g1 < 0:
            lo, hi, glo = e0, e1, g0
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                gm = G(mid, Om, lam, dl, z)
                if gm == 0 or mid in (lo, hi):
                    break
                if glo * gm < 0:
                    hi = mid
                else:
                    lo, glo = mid, gm
            out.append(0.5 * (lo + hi))
        g0 = g1
    return out


def fold(eps, Om, lam, dl, z):
    """Ω-fold of eq. 15: G = ∂G/∂ε = 0, Newton from (eps, Om); second
    derivatives by complex step (exact to rounding).  Converged when the
    Newton step is below 1e-13 relative (the rounding floor of G near the
    isola fold is ~1e-14 relative in Ω)."""
    h = 1e-30
    for _ in range(100):
        g = G(eps, Om, lam, dl, z)
        ge = G_eps(eps, Om, lam, dl, z)
        go = G_Om(eps, Om, lam, dl, z)
        gee = (G_eps(eps + 1j * h, Om, lam, dl, z)).imag / h
        geo = (G_eps(eps, Om + 1j * h, lam, dl, z)).imag / h
        det = ge * geo - go * gee
        de = (g * geo - go * ge) / det
        do = (ge * ge - g * gee) / det
        eps -= de
        Om -= do
        if abs(de) < 1e-13 * abs(eps) and abs(do) < 1e-13 * abs(Om):
            break
    else:
        raise RuntimeError("fold Newton did not converge")
    return eps, Om


def folds(lam, dl, z, om_min=0.01, om_max=20.0, n=400):
    """All Ω-folds of circular orbits in [om_min, om_max]: where the number of
    ε-roots changes along an Ω grid, narrowed by bisection on the root
    count, then refined by fold() from the two merging roots."""
    res = []
    oms = [om_min + (om_max - om_min) * k / n for k in range(n + 1)]
    prev = eps_roots(oms[0], lam, dl, z)
    for o0, o1 in zip(oms, oms[1:]):
        cur = eps_roots(o1, lam, dl, z)
        if len(cur) != len(prev):
            r0, r1 = prev, cur
            for _ in range(40):
                if o1 - o0 < 1e-9 * o1:
                    break
                om = 0.5 * (o0 + o1)
                rm = eps_roots(om, lam, dl, z)
                if len(rm) == len(r0):
                    o0, r0 = om, rm
                else:
                    o1, r1 = om, rm
            more, om = (r1, o1) if len(r1) > len(r0) else (r0, o0)
            i = min(range(len(more) - 1), key=lambda k: more[k + 1] - more[k])
            res.append(fold(0.5 * (more[i] + more[i + 1]), om, lam, dl, z))
        prev = cur
    return res

"""examples/auto/bisection.py - the root finder of the exact values
(examples/auto/exact.py, test/auto-demos/exact.py): bisection of a sign
change to the last bit, independent of whirl."""


def bisect(g, a, b):
    """The zero of g in [a, b] (g(a) g(b) < 0) to the last bit."""
    ga = g(a)
    assert ga * g(b) < 0, (a, b)
    while True:
        m = 0.5 * (a + b)
        if m <= min(a, b) or m >= max(a, b):
            return m
        gm = g(m)
        if gm == 0:
            return m
        if (gm < 0) == (ga < 0):
            a, ga = m, gm
        else:
            b = m

#!/usr/bin/python3
# test/auto-demos/lin_bp.py — an independent check (numpy, not whirl) of
# the BPs of AUTO's demo lin (u'' = -(pi k)^2 u,
# u(0) = u(1) = 0) discretised by orthogonal collocation as AUTO and whirl
# do: NTST = 5 uniform intervals, NCOL = 4 Gauss points, the piecewise
# polynomial given by its values at NCOL + 1 equally spaced nodes per
# interval.  The discrete BPs are the k where the collocation matrix of the
# linear problem is singular; found by secant iteration on its determinant.
# Prints k and the discrete BP; known-gaps (lin) compares.
# SPDX-License-Identifier: BSD-3-Clause
import numpy as np
from numpy.polynomial.legendre import leggauss
ntst, m, n = 5, 4, 2
g, _ = leggauss(m); g = (g + 1) / 2                    # Gauss points on [0, 1]
nodes = np.arange(m + 1) / m
def lag(s):                                            # l_k(s), l_k'(s)
    l = np.ones(m + 1); d = np.zeros(m + 1)
    for k in range(m + 1):
        others = [j for j in range(m + 1) if j != k]
        l[k] = np.prod([(s - nodes[j]) / (nodes[k] - nodes[j]) for j in others])
        d[k] = sum(np.prod([(s - nodes[j]) / (nodes[k] - nodes[j]) for j in others if j != i]) / (nodes[k] - nodes[i]) for i in others)
    return l, d
LD = [lag(s) for s in g]
def A(k):
    N = n * (ntst * m + 1); h = 1.0 / ntst
    M = np.zeros((N, N)); r = 0
    J = np.array([[0, 1], [-(np.pi * k) ** 2, 0]])
    for i in range(ntst):
        for c in range(m):
            l, d = LD[c]
            for q in range(m + 1):
                col = n * (i * m + q)
                M[r:r + n, col:col + n] += d[q] / h * np.eye(n) - l[q] * J
            r += n
    M[r, 0] = 1; M[r + 1, N - n] = 1                   # u1(0) = 0, u1(1) = 0
    return M
def det(k):
    s, ld = np.linalg.slogdet(A(k)); return s * np.exp(ld - 40)
for k0 in (1, 2, 3, 4):
    a, b = k0 - 1e-3, k0 + 1e-3
    fa, fb = det(a), det(b)
    for it in range(60):
        c = b - fb * (b - a) / (fb - fa); a, fa, b, fb = b, fb, c, det(c)
        if abs(b - a) < 1e-15: break
    print(k0, "%.12f" % b)

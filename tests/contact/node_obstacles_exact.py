#!/usr/bin/python3
"""Exact answer of tests/contact/node_obstacles.comm (rational arithmetic).

One node (DX, DY) held by two linear springs (10 N/m along x, 2 N/m along y) and pushed by
F = (5, 5) N towards three unilateral springs (DIS_CHOC) that meet their obstacles after a
gap g along a direction e (rational unit vectors from Pythagorean triples):

    spring  e                 g      k (N/m)
    CHOC1   (-12, 5) / 13     0.5    200
    CHOC2   (-8, -15) / 17    0.1    200
    CHOC3   (-5, 12) / 13     0.2    500

The energy 1/2 u^T diag(10, 2) u - F.u + sum 1/2 k min(g - e.u, 0)^2 is strictly convex;
its minimiser is found by trying each of the 8 contact statuses: the solution of the linear
system of a status is the answer when every spring of the status has gap <= 0 and every
other one gap > 0. Plain full Newton (no line search) from u = 0 cycles on this problem:
all open -> CHOC2 closed -> ... -> back (checked here too, in floating point, as parasol did
before its line search). Prints the answer with 17 significant digits.
"""
from fractions import Fraction as Fr
from itertools import product

A = [[Fr(10), Fr(0)], [Fr(0), Fr(2)]]
F = [Fr(5), Fr(5)]
SPRINGS = [((Fr(-12, 13), Fr(5, 13)), Fr(1, 2), Fr(200)),
           ((Fr(-8, 17), Fr(-15, 17)), Fr(1, 10), Fr(200)),
           ((Fr(-5, 13), Fr(12, 13)), Fr(1, 5), Fr(500))]


def gaps(u):
    return [g - (e[0] * u[0] + e[1] * u[1]) for e, g, k in SPRINGS]


def solve_status(status):
    """u of the quadratic energy with the springs of `status` closed (bilateral)."""
    k = [[A[i][j] for j in range(2)] for i in range(2)]
    b = list(F)
    for closed, (e, g, ks) in zip(status, SPRINGS):
        if not closed:
            continue
        for i in range(2):
            b[i] += ks * g * e[i]
            for j in range(2):
                k[i][j] += ks * e[i] * e[j]
    det = k[0][0] * k[1][1] - k[0][1] * k[1][0]
    return [(b[0] * k[1][1] - b[1] * k[0][1]) / det, (k[0][0] * b[1] - k[1][0] * b[0]) / det]


def exact():
    found = []
    for status in product([False, True], repeat=len(SPRINGS)):
        u = solve_status(status)
        if all((d <= 0) == closed for d, closed in zip(gaps(u), status)):
            found.append((status, u))
    assert len(found) == 1, found
    return found[0]


def plain_newton_cycles(iterations=20):
    """Full Newton from u = 0 without a line search: True when a status comes back."""
    u = [0.0, 0.0]
    seen = []
    for _ in range(iterations):
        status = tuple(d <= 0 for d in gaps([Fr(u[0]), Fr(u[1])]))
        if status in seen:
            return True
        seen.append(status)
        u = [float(x) for x in solve_status(status)]
    return False


if __name__ == "__main__":
    status, u = exact()
    print("status (CHOC1..3 closed):", status)
    print(f"DX = {float(u[0]):.17g}  ({u[0]})")
    print(f"DY = {float(u[1]):.17g}  ({u[1]})")
    print("plain full Newton cycles:", plain_newton_cycles())

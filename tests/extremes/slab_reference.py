#!/usr/bin/python3
"""Independent reference for SSNL130 model B with a *flexible* slab (mpmath, 50 digits).

tools/rigid_bed_exact.py is exact for a rigid plate; it stops being the answer when the slab
is not much stiffer than its bed (E/K below ~1e9 here: the slab's own deflection enters). This
script solves the same finite-element problem as parasol's model B deck, written
independently: an ny x 1 mesh of 4-node plane-strain quadrilaterals (2 x 2 Gauss, unit depth)
of length b and height h, a unilateral spring (DIS_CHOC, stiffness K/ny inside, K/(2 ny) at
the two ends, in X and Y) under every bottom node, the line load FY = -p (b - x)^2 on the
top edge (consistent nodal forces, exact for this cubic integrand), ground fixed. The
contact set is found by the active-set iteration (start all closed; open rows in tension,
close rows that penetrate; repeat until nothing changes). A closed spring carries its
normal (Y) and tangential (X) stiffness; an open one nothing. With DIST_1 = L + delta the
gap of a spring is v - delta (v = DY of the bottom node).

Everything (element matrices, loads, the solve) is computed with mpmath at DIGITS decimal
digits: the reference is the exact discrete answer, whatever the contrast. A double-precision
computation is not: the rounding of the element matrices breaks their exact rigid-body null
space by ~1e-16 of their size, which acts like a spurious support of that strength, and a
slab 1e7..1e15 times stiffer than its bed turns it into an error of ~1e-16 times the
contrast in the answer (measured with a double-precision version of this script and
iterative refinement: 5.7e-6 at PT02 for h = 1e-3, where the exact answer and parasol's
agree in all 13 printed digits; doc/stability.md). Prints DY at PT01 (x = 0) and PT02
(x = b), repr floats.

Usage: slab_reference.py --ny 16 --E 1e6 [--K 1e4 --p 5 --h 0.3 --nu 0.3 --b 2 --delta 0]
"""
import argparse
import sys

import mpmath as mp

# Decimal digits of the computation: the solve loses ~log10(contrast) + 1 of them (up to ~20
# for the extremes cases), and ~17 must be left for a float answer.
DIGITS = 50


def plane_strain_q4(x, y, E, nu):
    """8 x 8 stiffness of a rectangle [x0,x1] x [y0,y1] (2 x 2 Gauss, unit depth)."""
    c = E / ((1 + nu) * (1 - 2 * nu))
    D = mp.matrix([[c * (1 - nu), c * nu, 0], [c * nu, c * (1 - nu), 0],
                   [0, 0, c * (1 - 2 * nu) / 2]])
    xy = mp.matrix([[x[0], y[0]], [x[1], y[0]], [x[1], y[1]], [x[0], y[1]]])
    ke = mp.zeros(8, 8)
    g = 1 / mp.sqrt(3)
    for xi in (-g, g):
        for eta in (-g, g):
            dn = mp.matrix([[-(1 - eta), (1 - eta), (1 + eta), -(1 + eta)],
                            [-(1 - xi), -(1 + xi), (1 + xi), (1 - xi)]]) / 4
            jac = dn * xy
            dxy = mp.inverse(jac) * dn
            B = mp.zeros(3, 8)
            for a in range(4):
                B[0, 2 * a] = dxy[0, a]
                B[1, 2 * a + 1] = dxy[1, a]
                B[2, 2 * a] = dxy[1, a]
                B[2, 2 * a + 1] = dxy[0, a]
            ke += B.T * D * B * mp.det(jac)
    return ke


def solve(ny, E, K, p, h=0.3, nu=0.3, b=2.0, delta=0.0):
    """DY at x = 0 and x = b (bottom nodes, floats) and the number of closed springs.
    The inputs are taken as the decimal numbers a deck would write (repr of the floats)."""
    mp.mp.dps = DIGITS
    E, K, p, h, nu, b, delta = (mp.mpf(repr(float(v))) for v in (E, K, p, h, nu, b, delta))
    xs = [b * i / ny for i in range(ny + 1)]
    bottom = list(range(ny + 1))          # node i at (x_i, 0), node ny + 1 + i at (x_i, h)
    top = [i + ny + 1 for i in bottom]
    n = 4 * (ny + 1)
    Kp = mp.zeros(n, n)
    for i in range(ny):
        nodes = [bottom[i], bottom[i + 1], top[i + 1], top[i]]
        dofs = [d for m in nodes for d in (2 * m, 2 * m + 1)]
        ke = plane_strain_q4(xs[i:i + 2], (0, h), E, nu)
        for r in range(8):
            for c in range(8):
                Kp[dofs[r], dofs[c]] += ke[r, c]
    f = mp.zeros(n, 1)
    g = 1 / mp.sqrt(3)
    for i in range(ny):
        x0, x1 = xs[i], xs[i + 1]
        for s in (-g, g):
            x = (x0 + x1) / 2 + (x1 - x0) / 2 * s
            fy = -p * (b - x) ** 2 * (x1 - x0) / 2
            f[2 * top[i] + 1] += fy * (1 - s) / 2
            f[2 * top[i + 1] + 1] += fy * (1 + s) / 2
    k = [K / ny] * (ny + 1)
    k[0] = k[-1] = K / (2 * ny)
    closed = [True] * (ny + 1)
    for _ in range(4 * (ny + 1)):
        A = Kp.copy()
        rhs = f.copy()
        for i in range(ny + 1):
            if not closed[i]:
                continue
            A[2 * i, 2 * i] += k[i]
            A[2 * i + 1, 2 * i + 1] += k[i]
            rhs[2 * i + 1] += k[i] * delta       # force -k (v - delta) = -k v + k delta
        u = mp.lu_solve(A, rhs)
        v = [u[2 * i + 1] for i in bottom]
        now = [vi - delta <= 0 for vi in v]
        if now == closed:
            return float(v[0]), float(v[ny]), sum(closed)
        closed = now
    raise RuntimeError("active set did not settle")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    ap.add_argument("--ny", type=int, default=16, help="cells along the slab")
    ap.add_argument("--E", type=float, default=2.0e11, help="Young's modulus, Pa")
    ap.add_argument("--K", type=float, default=1.0e4, help="global bed stiffness, N/m")
    ap.add_argument("--p", type=float, default=5.0, help="load scale of P(y) = p (b - y)^2")
    ap.add_argument("--h", type=float, default=0.3, help="slab height, m")
    ap.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio")
    ap.add_argument("--b", type=float, default=2.0, help="slab length, m")
    ap.add_argument("--delta", type=float, default=0.0,
                    help="initial gap of the springs (DIST_1 - L), m")
    o = ap.parse_args(argv)
    v0, vb, nc = solve(o.ny, o.E, o.K, o.p, o.h, o.nu, o.b, o.delta)
    print(f"PT01 {v0!r}\nPT02 {vb!r}\nclosed {nc} of {o.ny + 1}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

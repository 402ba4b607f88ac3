#!/usr/bin/python3
"""Independent reference for SSNL130 model B with a *flexible* slab (numpy, double precision).

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

Only valid where its own solve is well conditioned: the matrix loses about log10(E/K) + 1
digits (LAPACK dgesv, partial pivoting); use it for E/K <= 1e8 and compare the rigid answer
above. Prints DY at PT01 (x = 0) and PT02 (x = b), repr floats.

Usage: slab_reference.py --ny 16 --E 1e6 [--K 1e4 --p 5 --h 0.3 --nu 0.3 --b 2 --delta 0]
"""
import argparse
import sys

import numpy as np


def plane_strain_q4(x, y, E, nu):
    """8 x 8 stiffness of a rectangle [x0,x1] x [y0,y1] (2 x 2 Gauss, unit depth)."""
    c = E / ((1 + nu) * (1 - 2 * nu))
    D = c * np.array([[1 - nu, nu, 0], [nu, 1 - nu, 0], [0, 0, (1 - 2 * nu) / 2]])
    xy = np.array([[x[0], y[0]], [x[1], y[0]], [x[1], y[1]], [x[0], y[1]]])
    ke = np.zeros((8, 8))
    g = 1 / np.sqrt(3)
    for xi in (-g, g):
        for eta in (-g, g):
            dn = 0.25 * np.array([[-(1 - eta), (1 - eta), (1 + eta), -(1 + eta)],
                                  [-(1 - xi), -(1 + xi), (1 + xi), (1 - xi)]])
            jac = dn @ xy
            dxy = np.linalg.solve(jac, dn)
            B = np.zeros((3, 8))
            B[0, 0::2] = dxy[0]
            B[1, 1::2] = dxy[1]
            B[2, 0::2] = dxy[1]
            B[2, 1::2] = dxy[0]
            ke += B.T @ D @ B * np.linalg.det(jac)
    return ke


def solve(ny, E, K, p, h=0.3, nu=0.3, b=2.0, delta=0.0):
    """DY at x = 0 and x = b (bottom nodes) and the number of closed springs."""
    xs = np.linspace(0.0, b, ny + 1)
    bottom = np.arange(ny + 1)            # node i at (x_i, 0), node ny + 1 + i at (x_i, h)
    top = bottom + ny + 1
    n = 2 * 2 * (ny + 1)
    Kp = np.zeros((n, n))
    for i in range(ny):
        nodes = [bottom[i], bottom[i + 1], top[i + 1], top[i]]
        dofs = np.array([[2 * m, 2 * m + 1] for m in nodes]).ravel()
        Kp[np.ix_(dofs, dofs)] += plane_strain_q4(xs[i:i + 2], (0.0, h), E, nu)
    f = np.zeros(n)
    g = 1 / np.sqrt(3)
    for i in range(ny):
        x0, x1 = xs[i], xs[i + 1]
        for s in (-g, g):
            x = 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * s
            fy = -p * (b - x) ** 2 * 0.5 * (x1 - x0)
            f[2 * top[i] + 1] += fy * 0.5 * (1 - s)
            f[2 * top[i + 1] + 1] += fy * 0.5 * (1 + s)
    k = np.full(ny + 1, K / ny)
    k[0] = k[-1] = K / (2 * ny)
    closed = np.ones(ny + 1, dtype=bool)
    for _ in range(4 * (ny + 1)):
        A = Kp.copy()
        rhs = f.copy()
        for i in np.flatnonzero(closed):
            A[2 * i, 2 * i] += k[i]
            A[2 * i + 1, 2 * i + 1] += k[i]
            rhs[2 * i + 1] += k[i] * delta       # force -k (v - delta) = -k v + k delta
        u = np.linalg.solve(A, rhs)
        v = u[1::2][bottom]
        now = v - delta <= 0.0
        if np.array_equal(now, closed):
            return v[0], v[ny], int(closed.sum())
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

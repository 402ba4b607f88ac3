#!/usr/bin/python3
"""Exact discrete answer for a rigid plate on a bed of springs (SSNL130 family).

Rigid plate x in [0, a], y in [0, b] under P(y) = p (b - y)^m (downward for p > 0), on spring
rows y_j = j b / ny, j = 0..ny. RIGI_PARASOL spreads the global stiffness K by area (3D) or
length (2D), so a row carries K/ny inside and K/(2 ny) at the two end rows (the trapezoidal
weights). The plate moves rigidly, z(y) = w + t y relative to the ground. A unilateral
spring row is closed when z_j <= 0 and then pushes up with -k_j z_j; an open row carries
nothing. Bilateral springs (--bilateral) always carry -k_j z_j.

The load decreases along y (m >= 0), so the closed rows form a prefix 0..n. For each
candidate n, from all rows closed downwards, the two equilibrium equations with rows 0..n
closed,
    sum_j k_j (w + t y_j)       = -F,   F = a p b^(m+1) / (m+1),
    sum_j k_j (w + t y_j) y_j   = -M,   M = a p b^(m+2) / ((m+1)(m+2)),
are solved, and the first n whose solution is consistent (z_j <= 0 for j <= n, z_j >= 0
beyond) is kept. All arithmetic is in Fractions, so the result is exact. The ground lift is
added to the displacements afterwards (a rigid shift of everything).

--load nodes: the load Code_Aster (and parasol) apply for a pressure FORMULE on DKT/DKQ
plates: P evaluated at the node rows y_j and interpolated linearly between them (the DKQ
load weights integrate a linear field and its first moment exactly), so F and M are those
of the interpolant (SSNL130 A: F = 855/64 instead of 40/3). The default, --load exact,
integrates P itself (the 2D slice, whose FORCE_CONTOUR is integrated at Gauss points).

Used by the test decks of tests/ (values written into the decks) and by the benchmarks.

Usage: rigid_bed_exact.py [--ny 16] [--a 1 --b 2 --K 1e4 --p 5 --m 2 --lift 0 --bilateral]
                         [--load exact|nodes]
"""
import argparse
import sys
from fractions import Fraction as Fr


class HelpFormatter(argparse.ArgumentDefaultsHelpFormatter,
                    argparse.RawDescriptionHelpFormatter):
    """--help shows each option's default, and the docstring as written."""


class NoEquilibrium(ValueError):
    """No set of closed rows can carry the load (e.g. the load lifts the plate)."""


def load_resultants(a, b, p, m=2):
    """Resultant F of P = p (b - y)^m over the width a, and its moment M about y = 0."""
    return a * p * b ** (m + 1) / (m + 1), a * p * b ** (m + 2) / ((m + 1) * (m + 2))


def nodal_load_resultants(a, b, p, m, ny):
    """F and M of the linear interpolant of P between the node rows y_j = j b / ny: on
    [y_j, y_j+1] (length h) the integral of P is h (P_j + P_j+1) / 2 and that of y P is
    h ((y_j P_j + y_j+1 P_j+1) / 3 + (y_j P_j+1 + y_j+1 P_j) / 6)."""
    h = b / ny
    ys = [h * j for j in range(ny + 1)]
    ps = [p * (b - y) ** m for y in ys]
    F = a * sum(h * (ps[j] + ps[j + 1]) / 2 for j in range(ny))
    M = a * sum(h * ((ys[j] * ps[j] + ys[j + 1] * ps[j + 1]) / 3
                     + (ys[j] * ps[j + 1] + ys[j + 1] * ps[j]) / 6) for j in range(ny))
    return F, M


def solve_rigid_bed(ny, a=1, b=2, K=10000, p=5, m=2, lift=0, bilateral=False, load="exact"):
    """Return dict(pt01, pt03, w, t, n, y0) exactly: the displacement at y = 0 and y = b
    (ground lift included), the relative motion z = w + t y, the last closed row n and the
    zero crossing y0 = -w / t (None for a uniform settlement). load: "exact" (P integrated)
    or "nodes" (P interpolated between the node rows, nodal_load_resultants).

    Errors: ValueError when ny < 1 or load is unknown; NoEquilibrium when no consistent
    contact set exists.
    """
    if ny < 1:
        raise ValueError(f"ny = {ny}: need at least one cell along y")
    a, b, K, p, lift = Fr(a), Fr(b), Fr(K), Fr(p), Fr(lift)
    if load == "exact":
        F, M = load_resultants(a, b, p, m)
    elif load == "nodes":
        F, M = nodal_load_resultants(a, b, p, m, ny)
    else:
        raise ValueError(f"load = {load}: exact or nodes")
    ys = [b * j / ny for j in range(ny + 1)]
    ks = [K / (2 * ny) if j in (0, ny) else K / ny for j in range(ny + 1)]
    candidates = [ny] if bilateral else range(ny, 0, -1)
    for n in candidates:
        s0 = sum(ks[: n + 1])
        s1 = sum(k * y for k, y in zip(ks[: n + 1], ys[: n + 1]))
        s2 = sum(k * y * y for k, y in zip(ks[: n + 1], ys[: n + 1]))
        det = s0 * s2 - s1 * s1
        if det == 0:
            continue
        # [s0 s1; s1 s2] [w; t] = [-F; -M]
        w = (-F * s2 + M * s1) / det
        t = (-M * s0 + F * s1) / det
        z = [w + t * y for y in ys]
        if bilateral or (all(zj <= 0 for zj in z[: n + 1])
                         and all(zj >= 0 for zj in z[n + 1:])):
            y0 = -w / t if t != 0 else None
            return dict(pt01=w + lift, pt03=w + t * b + lift, w=w, t=t, n=n, y0=y0)
    raise NoEquilibrium("no consistent contact set: fewer than two rows can carry the load")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=HelpFormatter)
    ap.add_argument("--ny", type=int, default=16, help="cells along the length (rows - 1)")
    ap.add_argument("--a", default="1", help="plate width in m (exact fraction allowed)")
    ap.add_argument("--b", default="2", help="plate length in m")
    ap.add_argument("--K", default="10000", help="global bed stiffness in N/m")
    ap.add_argument("--p", default="5", help="load scale: P(y) = p (b - y)^m")
    ap.add_argument("--m", type=int, default=2, help="load exponent m")
    ap.add_argument("--lift", default="0", help="rigid ground lift added to the answer")
    ap.add_argument("--bilateral", action="store_true",
                    help="springs that also pull (every row carries)")
    ap.add_argument("--load", choices=["exact", "nodes"], default="exact",
                    help="exact: the pressure integrated exactly; nodes: its values at the "
                    "nodes, interpolated (what Code_Aster integrates for a pressure function "
                    "on plates)")
    o = ap.parse_args(argv)
    try:
        r = solve_rigid_bed(o.ny, Fr(o.a), Fr(o.b), Fr(o.K), Fr(o.p), o.m, Fr(o.lift),
                            o.bilateral, o.load)
    except ValueError as e:
        print(f"rigid_bed_exact: {e}", file=sys.stderr)
        return 1
    for key in ("pt01", "pt03"):
        v = r[key]
        print(f"{key} = {v} = {float(v):.10e}")
    y0 = "none" if r["y0"] is None else f"{float(r['y0']):.10f}"
    print(f"last closed row n = {r['n']}, y0 = {y0}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

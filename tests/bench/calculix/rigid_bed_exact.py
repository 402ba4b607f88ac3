#!/usr/bin/python3
"""Exact discrete answer for a rigid plate on a bed of unilateral springs (SSNL130 family).

Rigid plate x in [0, a], y in [0, b] under P(y) = p (b - y)^2 (downward), on spring rows
y_j = j b / ny, j = 0..ny.  RIGI_PARASOL spreads K by area, so a row carries K/ny inside and
K/(2 ny) at the two ends (the trapezoidal weights).  The plate's vertical motion is
z(y) = w + t y.  A spring row is closed when z_j <= 0 and then pushes up with -k_j z_j; an
open row carries nothing.

The load decreases along y, so the plate sinks at y = 0 and rises towards y = b: the closed
rows form a prefix 0..n.  For each candidate n (from all rows closed downwards) we solve the
two equilibrium equations with rows 0..n closed,
    sum_j k_j (w + t y_j)       = -F,   F = integral a P dy      = a p b^3 / 3,
    sum_j k_j (w + t y_j) y_j   = -M,   M = integral a P y dy    = a p b^4 / 12,
and keep the first n whose solution is consistent (z_j <= 0 for j <= n, z_j >= 0 beyond).
All arithmetic is in Fractions, so the result is exact.

Usage: rigid_bed_exact.py [--ny 16] [--a 1 --b 2 --K 1e4 --p 5]
"""
import argparse
import sys
from fractions import Fraction as Fr


def load_resultants(a, b, p):
    """Resultant F and its moment M about y = 0 of P = p (b - y)^2 over the width a."""
    return a * p * b ** 3 / 3, a * p * b ** 4 / 12


def solve_rigid_bed(ny, a=1, b=2, K=10000, p=5):
    """Return dict(pt01, pt03, w, t, n, y0) exactly: DZ at y = 0 and y = b, the motion
    z = w + t y, the last closed row n and the zero crossing y0 = -w / t.

    Errors: ValueError when ny < 1 or when no consistent contact set exists.
    """
    if ny < 1:
        raise ValueError(f"ny = {ny}: need at least one cell along y")
    a, b, K, p = Fr(a), Fr(b), Fr(K), Fr(p)
    F, M = load_resultants(a, b, p)
    ys = [b * j / ny for j in range(ny + 1)]
    ks = [K / (2 * ny) if j in (0, ny) else K / ny for j in range(ny + 1)]
    for n in range(ny, 0, -1):
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
        if all(zj <= 0 for zj in z[: n + 1]) and all(zj >= 0 for zj in z[n + 1:]):
            y0 = -w / t if t != 0 else None
            return dict(pt01=w, pt03=w + t * b, w=w, t=t, n=n, y0=y0)
    raise ValueError("no consistent contact set: fewer than two rows can carry the load")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ny", type=int, default=16)
    for key, val in (("a", "1"), ("b", "2"), ("K", "1e4"), ("p", "5")):
        ap.add_argument(f"--{key}", default=val)
    o = ap.parse_args(argv)
    r = solve_rigid_bed(o.ny, Fr(o.a), Fr(o.b), Fr(o.K), Fr(o.p))
    print(f"DZ(y=0) = {r['pt01']} = {float(r['pt01']):.10e}")
    print(f"DZ(y=b) = {r['pt03']} = {float(r['pt03']):.10e}")
    print(f"last closed row n = {r['n']}, y0 = {float(r['y0']):.10f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Check a deck written by make_ccx_bed.py by reading its text back (no ccx needed).

For each mesh given (default 4x16 and 3x5) the deck must have:
  * nx*ny S4 shells and one GAPUNI per plate node, from its ground node to the plate node;
  * gap stiffnesses that add up to K (RIGI_PARASOL: weights are area shares), with the
    corner : edge : interior ratio 1 : 2 : 4, and a "force at minus infinity" <= 1e-9 N;
  * nodal loads in -z whose resultant is a p b^3 / 3 and whose moment about the x axis
    through y = 0 is a p b^4 / 12, the exact values of P = p (y - b)^2 (relative 1e-12).
Exit 0 when every check passes, 1 otherwise (each failure printed).
"""
import argparse
import io
import sys
import os

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_ccx_bed  # noqa: E402

A, B, K, P = 1.0, 2.0, 1.0e4, 5.0
REL_TOL = 1.0e-12


def read_blocks(text):
    """List of (keyword line, [data lines]) of an Abaqus-style deck."""
    blocks = []
    for line in text.splitlines():
        if line.startswith("**") or not line.strip():
            continue
        if line.startswith("*"):
            blocks.append((line.upper().replace(" ", ""), []))
        else:
            blocks[-1][1].append([v.strip() for v in line.split(",")])
    return blocks


def check_mesh(nx, ny):
    """Return a list of failure messages for the nx x ny deck."""
    buf = io.StringIO()
    make_ccx_bed.write_deck(buf, nx, ny, **make_ccx_bed.DEFAULTS)
    blocks = read_blocks(buf.getvalue())
    fails = []
    coords, shells, gaps, gapcards, loads = {}, 0, {}, {}, []
    for key, rows in blocks:
        if key.startswith("*NODE,"):
            for r in rows:
                coords[int(r[0])] = tuple(float(v) for v in r[1:4])
        elif key.startswith("*ELEMENT,TYPE=S4,"):
            shells += len(rows)
        elif key.startswith("*ELEMENT,TYPE=GAPUNI"):
            elset = key.split("ELSET=")[1]
            gaps[elset] = [(int(r[1]), int(r[2])) for r in rows]
        elif key.startswith("*GAP,"):
            gapcards[key.split("ELSET=")[1]] = [float(v) if v else 0.0 for v in rows[0]]
        elif key == "*CLOAD":
            loads += [(int(r[0]), int(r[1]), float(r[2])) for r in rows]
    nplate = (nx + 1) * (ny + 1)
    if shells != nx * ny:
        fails.append(f"{shells} S4 shells, expected {nx * ny}")
    ngap = sum(len(v) for v in gaps.values())
    if ngap != nplate:
        fails.append(f"{ngap} gaps, expected one per plate node ({nplate})")
    ktot = 0.0
    for elset, elems in gaps.items():
        card = gapcards.get(elset)
        if card is None:
            fails.append(f"no *GAP card for {elset}")
            continue
        if card[0:4] != [0.0, 0.0, 0.0, 1.0]:
            fails.append(f"{elset}: clearance/direction {card[0:4]}, expected 0, (0, 0, 1)")
        if card[6] > 1.0e-9:
            fails.append(f"{elset}: force at minus infinity {card[6]} N, expected tiny")
        for (n1, n2) in elems:
            g, pl = coords[n1], coords[n2]
            if abs(pl[2]) > 0.0 or abs(g[2] + 0.1) > 1e-15 or g[:2] != pl[:2]:
                fails.append(f"{elset}: gap {n1}->{n2} is not ground (z=-0.1) -> plate")
                break
        ktot += card[5] * len(elems)
    ratios = [gapcards[f"GAP{q}"][5] / gapcards["GAP1"][5] for q in (1, 2, 4)
              if f"GAP{q}" in gapcards]
    if ratios != [1.0, 2.0, 4.0][: len(ratios)]:
        fails.append(f"corner:edge:interior stiffness ratios {ratios}, expected 1:2:4")
    if abs(ktot - K) > REL_TOL * K:
        fails.append(f"total gap stiffness {ktot!r}, expected {K}")
    if any(d != 3 or f > 0.0 for (_, d, f) in loads):
        fails.append("a nodal load is not a downward DZ force")
    force = -sum(f for (_, _, f) in loads)
    moment = -sum(f * coords[n][1] for (n, _, f) in loads)
    f_exact, m_exact = A * P * B ** 3 / 3, A * P * B ** 4 / 12
    if abs(force - f_exact) > REL_TOL * f_exact:
        fails.append(f"load resultant {force!r}, expected {f_exact!r}")
    if abs(moment - m_exact) > REL_TOL * m_exact:
        fails.append(f"load moment {moment!r}, expected {m_exact!r}")
    return [f"{nx}x{ny}: {msg}" for msg in fails]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    ap.add_argument("meshes", nargs="*", default=["4x16", "3x5"],
                    help="meshes NXxNY to write and check")
    o = ap.parse_args(argv)
    meshes = [tuple(int(v) for v in m.split("x")) for m in o.meshes]
    fails = []
    for nx, ny in meshes:
        fails += check_mesh(nx, ny)
    for msg in fails:
        print("FAIL:", msg)
    if not fails:
        print(f"deck checks passed for {', '.join(f'{a}x{b}' for a, b in meshes)}")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

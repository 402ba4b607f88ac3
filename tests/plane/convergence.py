#!/usr/bin/python3
"""Orders of convergence of the plane family on Timoshenko's cantilever (cantilever_plane.comm,
doc/verification.md "Plane elements").

Reads the DEPL tables that cantilever_plane.comm prints (IMPR_RESU, in the order of its
CASES: TRIA3, TRIA6, QUAD4, QUAD8, QUAD9, each on n = 2, 4, 8, 16), regenerates the node
coordinates with make_meshes.py, and measures on each mesh the largest nodal error of the
displacement against the exact solution, relative to the largest exact displacement:
e_n = max_nodes |u_h - u| / max_nodes |u|. The order between meshes n and 2n is
log2(e_n / e_2n). It fails (exit 1) unless the order of the last refinement is at least
MIN_ORDER: 1.8 for the linear cells (O(h^2)), 2.7 for the quadratic ones (O(h^3)).

usage: convergence.py RESU_FILE [--table]   (--table: print the table for doc/verification.md)
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_meshes  # noqa: E402

E, NU, P, L, D = 1000.0, 0.25, 1.0, make_meshes.LENGTH, make_meshes.DEPTH
INERTIA = D ** 3 / 12.0
MIN_ORDER = {"TRIA3": 1.8, "QUAD4": 1.8, "TRIA6": 2.7, "QUAD8": 2.7, "QUAD9": 2.7}


def exact(x, y):
    u = -P * y / (6 * E * INERTIA) * ((6 * L - 3 * x) * x + (2 + NU) * (y * y - D * D / 4))
    v = P / (6 * E * INERTIA) * (3 * NU * y * y * (L - x) + (4 + 5 * NU) * D * D * x / 4
                                 + (3 * L - x) * x * x)
    return u, v


def depl_tables(path):
    """The DEPL tables of the file, in order: {node name: (DX, DY)} each."""
    tables, current = [], None
    with open(path, encoding="ascii") as f:
        for line in f:
            words = line.split()
            if line.startswith(" ---- RESULTAT") and "NOM_CHAM DEPL" in line:
                current = {}
                tables.append(current)
            elif current is not None and words and words[0] == "NOEUD":
                continue
            elif current is not None and len(words) == 3:
                current[words[0]] = (float(words[1]), float(words[2]))
            elif current is not None and not words:
                current = None
    return tables


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    tables = depl_tables(argv[1])
    expected = len(make_meshes.TYPES) * len(make_meshes.CANTILEVER_SIZES)
    if len(tables) != expected:
        print(f"{argv[1]}: {len(tables)} DEPL tables, expected {expected}", file=sys.stderr)
        return 1
    status, rows, k = 0, [], 0
    for ctype in make_meshes.TYPES:
        errors = []
        for n in make_meshes.CANTILEVER_SIZES:
            mesh = make_meshes.cantilever(ctype, n)
            table = tables[k]
            k += 1
            worst, scale = 0.0, 0.0
            for i, (x, y) in enumerate(mesh.nodes, start=1):
                u, v = exact(x, y)
                uh, vh = table[f"N{i}"]
                worst = max(worst, math.hypot(uh - u, vh - v))
                scale = max(scale, math.hypot(u, v))
            errors.append(worst / scale)
        orders = [math.log2(a / b) for a, b in zip(errors, errors[1:])]
        rows.append((ctype, errors, orders))
        if not orders[-1] >= MIN_ORDER[ctype]:
            print(f"{ctype}: order {orders[-1]:.2f} of the last refinement, expected at least "
                  f"{MIN_ORDER[ctype]}", file=sys.stderr)
            status = 1
    for ctype, errors, orders in rows:
        print(f"| {ctype} | " + " | ".join(f"{e:.2e}" for e in errors) + " | "
              + ", ".join(f"{o:.2f}" for o in orders) + " |")
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))

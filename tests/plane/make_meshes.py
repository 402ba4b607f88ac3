#!/usr/bin/python3
"""Meshes (Code_Aster .mail) of the plane-family verification decks (doc/verification.md,
"Plane elements"), one per cell type TRIA3, TRIA6, QUAD4, QUAD8, QUAD9.

  patch_<type>.mail    the distorted patch of MacNeal & Harder (1985) scaled to the unit
                       square (corners N1-N4, interior corners (1/6,1/6) (3/4,1/4)
                       (2/3,2/3) (1/3,2/3)); triangles cut each quadrangle along its 1-3
                       diagonal; the middle nodes of interior sides are moved across the
                       side by up to 4 % of its length (curved sides), QUAD9 centres off
                       the middle. GROUP_MA PATCH; GROUP_NO BORD (every node of the outer
                       boundary), C1..C4 (the interior corners), M1 (the middle node of the
                       side C1-C2, quadratic types).
  cantilever_<type>_<n>.mail  (--cantilever) the beam [0, L] x [-D/2, D/2], L = 4, D = 1,
                       4n x n squares (n = 2, 4, 8, 16), triangles two per square (the
                       diagonal alternating); GROUP_MA BEAM, EXTREM (the edges at x = L);
                       GROUP_NO ENCAST (x = 0), TIP (L, 0).
  thermal_<type>.mail  the cantilever mesh with n = 2 (8 x 2 squares), for thermal_plane.comm
                       (committed, as the patch meshes).
  cantilever.export    (--cantilever) the session of cantilever_plane.comm on those meshes:
                       units 20 + 4 t + k for type t (TRIA3, TRIA6, QUAD4, QUAD8, QUAD9) and
                       mesh k (n = 2, 4, 8, 16).

The patch meshes are committed beside the decks (`--check` compares them); the cantilever
meshes are written at test time into the build tree (`--cantilever --outdir DIR`).

usage: make_meshes.py [--outdir DIR] [--check] [--cantilever]
"""
import argparse
import importlib.util
import math
import os
import sys
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
# the .mail writer and the write-or-check loop of the other verification meshes
_SPEC = importlib.util.spec_from_file_location(
    "verification_meshes", os.path.join(HERE, "..", "verification", "make_meshes.py"))
VERIFICATION = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(VERIFICATION)
TYPES = ("TRIA3", "TRIA6", "QUAD4", "QUAD8", "QUAD9")
CANTILEVER_SIZES = (2, 4, 8, 16)
LENGTH, DEPTH = 4.0, 1.0


class Mesh:
    """Nodes (x, y), cells (type, nodes, group), node groups; in the shape the verification
    meshes' .mail writer takes (dim 2)."""

    def __init__(self, title):
        self.dim, self.title = 2, title
        self.nodes, self.cells, self.node_groups = [], [], {}
        self.middles = {}

    def node(self, x, y):
        self.nodes.append((x, y))
        return len(self.nodes)

    def middle(self, a, b, shift=0.0):
        """The middle node of side a-b (created once), moved across it by shift x length."""
        key = (min(a, b), max(a, b))
        if key not in self.middles:
            (xa, ya), (xb, yb) = self.nodes[a - 1], self.nodes[b - 1]
            tx, ty = xb - xa, yb - ya
            self.middles[key] = self.node((xa + xb) / 2 - shift * ty, (ya + yb) / 2 + shift * tx)
        return self.middles[key]


def corners_of(ctype):
    return 3 if ctype.startswith("TRIA") else 4


def add_cell(mesh, ctype, corners, group, shift_of=lambda a, b: 0.0, centre_shift=(0.0, 0.0)):
    nodes = list(corners)
    if ctype in ("TRIA6", "QUAD8", "QUAD9"):
        nc = len(corners)
        nodes += [mesh.middle(corners[k], corners[(k + 1) % nc],
                              shift_of(corners[k], corners[(k + 1) % nc])) for k in range(nc)]
    if ctype == "QUAD9":
        xs = [mesh.nodes[c - 1] for c in corners]
        nodes.append(mesh.node(sum(p[0] for p in xs) / 4 + centre_shift[0],
                               sum(p[1] for p in xs) / 4 + centre_shift[1]))
    mesh.cells.append((ctype, nodes, group))


def patch(ctype):
    mesh = Mesh(f"Distorted patch on the unit square ({ctype}), MacNeal-Harder 1985")
    points = [(0, 0), (1, 0), (1, 1), (0, 1), (Fraction(1, 6), Fraction(1, 6)),
              (Fraction(3, 4), Fraction(1, 4)), (Fraction(2, 3), Fraction(2, 3)),
              (Fraction(1, 3), Fraction(2, 3))]
    for x, y in points:
        mesh.node(float(x), float(y))
    quads = [(1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8), (5, 6, 7, 8)]

    def shift(a, b):          # interior sides bulge, boundary sides stay straight
        if a <= 4 and b <= 4:
            return 0.0
        return 0.04 * math.sin(7.0 * (a + 3 * b))

    for k, q in enumerate(quads):
        if corners_of(ctype) == 4:
            add_cell(mesh, ctype, q, "PATCH", shift, (0.003 * (k + 1), -0.002 * k))
        else:
            add_cell(mesh, ctype, (q[0], q[1], q[2]), "PATCH", shift)
            add_cell(mesh, ctype, (q[0], q[2], q[3]), "PATCH", shift)
    edge = [i + 1 for i, (x, y) in enumerate(mesh.nodes)
            if min(abs(x), abs(y), abs(x - 1.0), abs(y - 1.0)) < 1e-12]
    mesh.node_groups = {"BORD": edge, "C1": [5], "C2": [6], "C3": [7], "C4": [8]}
    if ctype in ("TRIA6", "QUAD8", "QUAD9"):
        mesh.node_groups["M1"] = [mesh.middles[(5, 6)]]
    return mesh


def cantilever(ctype, n):
    mesh = Mesh(f"Cantilever L={LENGTH} D={DEPTH}, {4 * n} x {n} {ctype}")
    nx, ny = 4 * n, n
    grid = [[mesh.node(LENGTH * i / nx, DEPTH * (j / ny - 0.5)) for i in range(nx + 1)]
            for j in range(ny + 1)]
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]
            if corners_of(ctype) == 4:
                add_cell(mesh, ctype, (a, b, c, d), "BEAM")
            elif (i + j) % 2 == 0:
                add_cell(mesh, ctype, (a, b, c), "BEAM")
                add_cell(mesh, ctype, (a, c, d), "BEAM")
            else:
                add_cell(mesh, ctype, (a, b, d), "BEAM")
                add_cell(mesh, ctype, (b, c, d), "BEAM")
    quadratic = ctype in ("TRIA6", "QUAD8", "QUAD9")
    for j in range(ny):
        a, b = grid[j][nx], grid[j + 1][nx]
        nodes = [a, b] + ([mesh.middles[(min(a, b), max(a, b))]] if quadratic else [])
        mesh.cells.append(("SEG3" if quadratic else "SEG2", nodes, "EXTREM"))
    mesh.node_groups = {
        "ENCAST": [k + 1 for k, (x, y) in enumerate(mesh.nodes) if abs(x) < 1e-12],
        "TIP": [k + 1 for k, (x, y) in enumerate(mesh.nodes)
                if abs(x - LENGTH) < 1e-12 and abs(y) < 1e-12]}
    return mesh


def patch_files():
    files = {f"patch_{t.lower()}.mail": VERIFICATION.to_aster(patch(t)) for t in TYPES}
    for t in TYPES:
        files[f"thermal_{t.lower()}.mail"] = VERIFICATION.to_aster(cantilever(t, 2))
    return files


def cantilever_files():
    files = {}
    lines = ["P time_limit 600\n", "F comm " + os.path.join(HERE, "cantilever_plane.comm")
             + " D 1\n"]
    for t, ctype in enumerate(TYPES):
        for k, n in enumerate(CANTILEVER_SIZES):
            name = f"cantilever_{ctype.lower()}_{n}.mail"
            files[name] = VERIFICATION.to_aster(cantilever(ctype, n))
            lines.append(f"F mail {name} D {20 + 4 * t + k}\n")
    files["cantilever.export"] = "".join(lines)
    return files


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--outdir", default=HERE, help="where to write (default: beside me)")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 if a patch mesh in OUTDIR differs")
    parser.add_argument("--cantilever", action="store_true",
                        help="write the cantilever meshes and their export file instead")
    args = parser.parse_args(argv)
    files = cantilever_files() if args.cantilever else patch_files()
    return VERIFICATION.write_or_check(files, args.outdir, args.check)


if __name__ == "__main__":
    sys.exit(main())

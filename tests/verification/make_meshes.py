#!/usr/bin/python3
"""Generate the meshes (.mail, Code_Aster ASTER format) of parasol's verification decks.

Every mesh is committed beside its deck in tests/verification/, so the tests never need
Python at run time; `make_meshes.py --check` regenerates them in memory and fails when a
committed file differs (CTest `verification.meshes_reproducible`).

Meshes (node names N1.., cell names M1.., in the order written):
  patch_dkq.mail   distorted 5-QUAD4 patch on the unit square in z = 0 (MacNeal & Harder
                   1985, their 0.24 x 0.12 patch scaled to 1 x 1): boundary corners N1 (0,0),
                   N2 (1,0), N3 (1,1), N4 (0,1); interior N5 (1/6,1/6), N6 (3/4,1/4),
                   N7 (2/3,2/3), N8 (1/3,2/3). GROUP_MA PATCH; GROUP_NO BORD (N1-N4),
                   INTER (N5-N8).
  patch_dkt.mail   the same 8 nodes, 10 TRIA3 (each patch quadrilateral cut in two).
  patch_plan.mail  the QUAD4 patch as a 2D mesh (COOR_2D) for D_PLAN / C_PLAN, with the
                   one-node groups PN1 .. PN4 of its corners.
  plate_dkq_N.mail square plate a = 1 in z = 0, N x N QUAD4 (N = 4, 8, 16, 32);
  plate_dkt_N.mail the same grid, each square cut into 2 TRIA3 with the diagonal pointing
                   to the plate centre (N = 8, 16, 32), so the mesh keeps both symmetries.
                   Plate groups: GROUP_MA PLAQUE; GROUP_NO BORD (the 4N edge nodes),
                   CENTRE (a/2, a/2), PT_A (0,0), PT_B (a,0).
  slanted_block.mail 2D trapezoid (0,0) (2,0) (1.5,1) (0,1), its right side slanted: 2 x 2
                   QUAD4 (GROUP_MA BLOC) with the interior node moved to (0.9, 0.45), and
                   its sides as SEG2 running counter-clockwise (outward normals): BAS,
                   DROITE (the slanted one), HAUT, GAUCHE; GROUP_NO CENTRE (the interior
                   node), MDROITE (the middle of DROITE), COIN_A (0,0), COIN_B (2,0).
  list_inst_cutting.mail three 2D nodes N0 (0,0) N1 (1,0) N2 (2,0), SEG2 LIN (N0 N1) in
                   GLIN and CHOC (N1 N2) in GCHOC; GROUP_NO SOL (N0 N2), NOEUD (N1).
  loaded_plate.mail 3D plate [0,2] x [0,1] in z = 0, 4 x 2 cells: QUAD4 on x < 1, TRIA3
                   (each square cut along n1-n3) on x > 1, GROUP_MA PLAQUE; its edges
                   as SEG2: HAUT (y = 1, running from x = 2 to 0), DROITE (x = 2, from
                   y = 0 to 1); GROUP_NO A (0,0), B (2,0), C (1,1) (an isostatic support).
  loaded_block.mail 2D block [0,2] x [0,1] in quadratic cells: QUAD8 on x < 1, two TRIA6
                   on x > 1 (GROUP_MA BLOC); SEG3 sides HAUT (y = 1, from x = 2 to 0:
                   counter-clockwise, outward normal +y) and DROITE (x = 2, from y = 0 to
                   1); GROUP_NO A (0,0), B (2,0).
  cantilever_NXxNY.mail plane-strain cantilever L = 10 x h = 1 (2D), NX x NY QUAD4
                   (20x2, 40x4, 80x8, 160x16): GROUP_MA POUTRE (QUAD4), EXTREM (the NY
                   SEG2 of the tip edge x = L); GROUP_NO ENCAST (x = 0), PTIP (L, h/2),
                   PTIP_B (L, 0).
  glued_plan.mail  2D blocks meeting on x = 1 with non-matching nodes (LIAISON_MAIL):
                   GAUCHE [0,1]^2 in 2 x 2 QUAD4 (inside node at (9/20, 11/20)), DROITE
                   [1,2] x [0,1] in 3 x 4 rectangles cut into TRIA3; SEG2 BORD_D (x = 2),
                   INTERF (DROITE's side on x = 1); GROUP_NO X0 (x = 0), A (0,0), B (2,0),
                   ESCL (DROITE's nodes on x = 1), ESCL_BAS (its lower two), S1 S2 S3
                   (1, 1/4 .. 3/4), M1 (the inside node), M2 (1, 1/2), C (2,1), D (4/3, 1/2).
  glued_plate.mail the same in 3D (z = 0) for plates.

usage: make_meshes.py [--outdir DIR] [--check]
"""
import argparse
import os
import sys
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
PLATE_SIZES_DKQ = (4, 8, 16, 32)
PLATE_SIZES_DKT = (8, 16, 32)
CANTILEVERS = ((20, 2), (40, 4), (80, 8), (160, 16))
CANTILEVER_L, CANTILEVER_H = 10.0, 1.0


class Mesh:
    """Nodes, cells grouped by type (one cell group per list), node groups."""

    def __init__(self, dim, title):
        self.dim, self.title = dim, title
        self.nodes, self.cells, self.node_groups = [], [], {}

    def node(self, *xyz):
        self.nodes.append(tuple(float(v) for v in xyz))
        return len(self.nodes)

    def cell(self, ctype, nodes, group):
        self.cells.append((ctype, list(nodes), group))


def patch(kind, dim):
    """MacNeal-Harder interior positions (0.04,0.02) (0.18,0.03) (0.16,0.08) (0.08,0.08)
    of the 0.24 x 0.12 patch, scaled to the unit square."""
    mesh = Mesh(dim, f"Distorted patch on the unit square ({kind}), MacNeal-Harder 1985")
    corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
    inner = [(Fraction(1, 6), Fraction(1, 6)), (Fraction(3, 4), Fraction(1, 4)),
             (Fraction(2, 3), Fraction(2, 3)), (Fraction(1, 3), Fraction(2, 3))]
    for x, y in corners + inner:
        mesh.node(x, y, 0)
    quads = [(1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8), (5, 6, 7, 8)]
    for q in quads:
        if kind == "QUAD4":
            mesh.cell("QUAD4", q, "PATCH")
        else:
            mesh.cell("TRIA3", (q[0], q[1], q[2]), "PATCH")
            mesh.cell("TRIA3", (q[0], q[2], q[3]), "PATCH")
    mesh.node_groups = {"BORD": [1, 2, 3, 4], "INTER": [5, 6, 7, 8]}
    if dim == 2:
        for k in range(1, 5):
            mesh.node_groups[f"PN{k}"] = [k]
    return mesh


def slanted_block():
    mesh = Mesh(2, "Trapezoid with a slanted side, 2 x 2 QUAD4 (FACE_IMPO DNOR)")
    corners = [(0, 0), (2, 0), (Fraction(3, 2), 1), (0, 1)]

    def point(s, t):
        return tuple((1 - s) * (1 - t) * a + s * (1 - t) * b + s * t * c + (1 - s) * t * d
                     for a, b, c, d in zip(*corners))
    grid = {}
    for j in range(3):
        for i in range(3):
            xy = point(Fraction(i, 2), Fraction(j, 2))
            if (i, j) == (1, 1):
                xy = (Fraction(9, 10), Fraction(9, 20))
            grid[i, j] = mesh.node(*xy)
    for j in range(2):
        for i in range(2):
            mesh.cell("QUAD4", (grid[i, j], grid[i + 1, j], grid[i + 1, j + 1],
                                grid[i, j + 1]), "BLOC")
    sides = {"BAS": [(0, 0), (1, 0), (2, 0)], "DROITE": [(2, 0), (2, 1), (2, 2)],
             "HAUT": [(2, 2), (1, 2), (0, 2)], "GAUCHE": [(0, 2), (0, 1), (0, 0)]}
    for name, path in sides.items():
        for k in range(2):
            mesh.cell("SEG2", (grid[path[k]], grid[path[k + 1]]), name)
    mesh.node_groups = {"CENTRE": [grid[1, 1]], "MDROITE": [grid[2, 1]],
                        "COIN_A": [grid[0, 0]], "COIN_B": [grid[2, 0]]}
    return mesh


def pulled_node():
    mesh = Mesh(2, "A node held by a spring and pulled away from an obstacle "
                "(list_inst_cutting.comm)")
    for x in (0, 1, 2):
        mesh.node(x, 0)
    mesh.cell("SEG2", (1, 2), "GLIN")
    mesh.cell("SEG2", (2, 3), "GCHOC")
    mesh.node_groups = {"SOL": [1, 3], "NOEUD": [2]}
    return mesh


def plate(n, kind, a=1.0):
    mesh = Mesh(3, f"Square plate a={a}, {n} x {n} {kind}")
    grid = [[mesh.node(a * i / n, a * j / n, 0) for i in range(n + 1)] for j in range(n + 1)]
    for j in range(n):
        for i in range(n):
            n1, n2, n3, n4 = grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]
            if kind == "QUAD4":
                mesh.cell("QUAD4", (n1, n2, n3, n4), "PLAQUE")
            elif (i < n // 2) == (j < n // 2):   # diagonal n1-n3 points to the centre
                mesh.cell("TRIA3", (n1, n2, n3), "PLAQUE")
                mesh.cell("TRIA3", (n1, n3, n4), "PLAQUE")
            else:                                # diagonal n2-n4 points to the centre
                mesh.cell("TRIA3", (n1, n2, n4), "PLAQUE")
                mesh.cell("TRIA3", (n2, n3, n4), "PLAQUE")
    edge = [grid[j][i] for j in range(n + 1) for i in range(n + 1)
            if i in (0, n) or j in (0, n)]
    mesh.node_groups = {"BORD": edge, "CENTRE": [grid[n // 2][n // 2]],
                        "PT_A": [grid[0][0]], "PT_B": [grid[0][n]]}
    return mesh


def cantilever(nx, ny, length=CANTILEVER_L, h=CANTILEVER_H):
    mesh = Mesh(2, f"Plane strain cantilever L={length} h={h}, {nx} x {ny} QUAD4")
    grid = [[mesh.node(length * i / nx, h * j / ny) for i in range(nx + 1)]
            for j in range(ny + 1)]
    for j in range(ny):
        for i in range(nx):
            mesh.cell("QUAD4", (grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]),
                      "POUTRE")
    for j in range(ny):
        mesh.cell("SEG2", (grid[j][nx], grid[j + 1][nx]), "EXTREM")
    mesh.node_groups = {"ENCAST": [grid[j][0] for j in range(ny + 1)],
                        "PTIP": [grid[ny // 2][nx]], "PTIP_B": [grid[0][nx]]}
    return mesh


def loaded_plate():
    mesh = Mesh(3, "Plate [0,2] x [0,1], QUAD4 and TRIA3, with its edges (load resultants)")
    grid = [[mesh.node(Fraction(i, 2), Fraction(j, 2), 0) for i in range(5)]
            for j in range(3)]
    for j in range(2):
        for i in range(4):
            n1, n2, n3, n4 = grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]
            if i < 2:
                mesh.cell("QUAD4", (n1, n2, n3, n4), "PLAQUE")
            else:
                mesh.cell("TRIA3", (n1, n2, n3), "PLAQUE")
                mesh.cell("TRIA3", (n1, n3, n4), "PLAQUE")
    for i in range(4, 0, -1):
        mesh.cell("SEG2", (grid[2][i], grid[2][i - 1]), "HAUT")
    for j in range(2):
        mesh.cell("SEG2", (grid[j][4], grid[j + 1][4]), "DROITE")
    mesh.node_groups = {"A": [grid[0][0]], "B": [grid[0][4]], "C": [grid[2][2]]}
    return mesh


def loaded_block():
    mesh = Mesh(2, "Block [0,2] x [0,1] in QUAD8 and TRIA6, SEG3 sides (load resultants)")
    node = {}

    def at(x, y):
        key = (Fraction(x), Fraction(y))
        if key not in node:
            node[key] = mesh.node(*key)
        return node[key]

    def mid(a, b):
        return at((Fraction(a[0]) + Fraction(b[0])) / 2, (Fraction(a[1]) + Fraction(b[1])) / 2)

    def quadratic(ctype, corners, group):
        ends = [at(*c) for c in corners]
        k = len(corners)
        mids = [mid(corners[i], corners[(i + 1) % k]) for i in range(k if k > 2 else 1)]
        mesh.cell(ctype, ends + mids, group)
    quadratic("QUAD8", [(0, 0), (1, 0), (1, 1), (0, 1)], "BLOC")
    quadratic("TRIA6", [(1, 0), (2, 0), (2, 1)], "BLOC")
    quadratic("TRIA6", [(1, 0), (2, 1), (1, 1)], "BLOC")
    quadratic("SEG3", [(2, 1), (1, 1)], "HAUT")
    quadratic("SEG3", [(1, 1), (0, 1)], "HAUT")
    quadratic("SEG3", [(2, 0), (2, 1)], "DROITE")
    mesh.node_groups = {"A": [at(0, 0)], "B": [at(2, 0)]}
    return mesh


def glued_blocks(dim):
    """Two blocks glued by LIAISON_MAIL across x = 1 with non-matching nodes: GAUCHE
    [0,1]^2 in 2 x 2 QUAD4 (its inside node moved off the grid so the quadrangles are
    general), DROITE [1,2] x [0,1] in 3 x 4 rectangles cut into TRIA3. ESCL: DROITE's
    nodes on x = 1 (y = 0, 1/4, 1/2, 3/4, 1: two of them inside GAUCHE's edges, three
    beside its nodes: GAUCHE's nodes on the side are slave nodes' places, so that the
    tie transmits a uniform stress exactly), INTERF its SEG2 there, BORD_D the SEG2 of
    x = 2."""
    title = ("Blocks [0,1]^2 (QUAD4) and [1,2] x [0,1] (TRIA3) meeting on x = 1 with "
             "non-matching nodes (LIAISON_MAIL)")
    mesh = Mesh(dim, title)

    def node(x, y):
        return mesh.node(x, y, 0) if dim == 3 else mesh.node(x, y)
    left = {}
    for j in range(3):
        for i in range(3):
            xy = (Fraction(i, 2), Fraction(j, 2))
            if (i, j) == (1, 1):
                xy = (Fraction(9, 20), Fraction(11, 20))
            left[i, j] = node(*xy)
    for j in range(2):
        for i in range(2):
            mesh.cell("QUAD4", (left[i, j], left[i + 1, j], left[i + 1, j + 1],
                                left[i, j + 1]), "GAUCHE")
    right = {(i, j): node(1 + Fraction(i, 3), Fraction(j, 4))
             for j in range(5) for i in range(4)}
    for j in range(4):
        for i in range(3):
            n1, n2 = right[i, j], right[i + 1, j]
            n3, n4 = right[i + 1, j + 1], right[i, j + 1]
            mesh.cell("TRIA3", (n1, n2, n3), "DROITE")
            mesh.cell("TRIA3", (n1, n3, n4), "DROITE")
    for j in range(4):
        mesh.cell("SEG2", (right[3, j], right[3, j + 1]), "BORD_D")
    for j in range(4, 0, -1):
        mesh.cell("SEG2", (right[0, j], right[0, j - 1]), "INTERF")
    mesh.node_groups = {"X0": [left[0, j] for j in range(3)], "A": [left[0, 0]],
                        "B": [right[3, 0]], "ESCL": [right[0, j] for j in range(5)],
                        "ESCL_BAS": [right[0, 0], right[0, 1]],
                        "S1": [right[0, 1]], "S2": [right[0, 2]], "S3": [right[0, 3]],
                        "M1": [left[1, 1]], "M2": [left[2, 1]], "C": [right[3, 4]],
                        "D": [right[1, 2]]}
    return mesh


def number(x):
    return repr(float(x))


def names(prefix, numbers):
    items = [f"{prefix}{k}" for k in numbers]
    return "".join(" ".join(items[s:s + 8]) + "\n" for s in range(0, len(items), 8))


def to_aster(mesh):
    out = [f"TITRE\n{mesh.title}\nFINSF\n%\nCOOR_{mesh.dim}D\n"]
    for k, xyz in enumerate(mesh.nodes, start=1):
        out.append(f"N{k} " + " ".join(number(v) for v in xyz[:mesh.dim]) + "\n")
    out.append("FINSF\n%\n")
    previous = None
    groups = {}
    for k, (ctype, nodes, group) in enumerate(mesh.cells, start=1):
        if ctype != previous:
            if previous is not None:
                out.append("FINSF\n%\n")
            out.append(f"{ctype}\n")
            previous = ctype
        out.append(f"M{k} " + " ".join(f"N{n}" for n in nodes) + "\n")
        groups.setdefault(group, []).append(k)
    out.append("FINSF\n%\n")
    for name, cells in groups.items():
        out.append(f"GROUP_MA NOM={name}\n" + names("M", cells) + "FINSF\n%\n")
    for name, nodes in mesh.node_groups.items():
        out.append(f"GROUP_NO\n{name}\n" + names("N", nodes) + "FINSF\n%\n")
    out.append("FIN\n")
    return "".join(out)


def all_meshes():
    meshes = {"patch_dkq.mail": patch("QUAD4", 3), "patch_dkt.mail": patch("TRIA3", 3),
              "patch_plan.mail": patch("QUAD4", 2)}
    for n in PLATE_SIZES_DKQ:
        meshes[f"plate_dkq_{n}.mail"] = plate(n, "QUAD4")
    for n in PLATE_SIZES_DKT:
        meshes[f"plate_dkt_{n}.mail"] = plate(n, "TRIA3")
    for nx, ny in CANTILEVERS:
        meshes[f"cantilever_{nx}x{ny}.mail"] = cantilever(nx, ny)
    meshes["slanted_block.mail"] = slanted_block()
    meshes["list_inst_cutting.mail"] = pulled_node()
    meshes["loaded_plate.mail"] = loaded_plate()
    meshes["loaded_block.mail"] = loaded_block()
    meshes["glued_plan.mail"] = glued_blocks(2)
    meshes["glued_plate.mail"] = glued_blocks(3)
    return {name: to_aster(mesh) for name, mesh in meshes.items()}


def write_or_check(files, outdir, check):
    """Writes each {name: text} into outdir, or with check compares instead: 1 if one
    differs (or cannot be read), else 0. Shared with tests/plane/make_meshes.py."""
    status = 0
    for name, text in files.items():
        path = os.path.join(outdir, name)
        if check:
            try:
                with open(path, encoding="ascii", newline="") as f:
                    same = f.read() == text
            except OSError as err:
                print(f"{path}: cannot read: {err}", file=sys.stderr)
                same = False
            if not same:
                print(f"{path}: differs from what {os.path.basename(sys.argv[0])} generates",
                      file=sys.stderr)
                status = 1
        else:
            os.makedirs(outdir, exist_ok=True)
            with open(path, "w", encoding="ascii", newline="\n") as f:
                f.write(text)
    return status


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--outdir", default=HERE, help="where to write (default: beside me)")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 if a file in OUTDIR differs")
    args = parser.parse_args(argv)
    return write_or_check(all_meshes(), args.outdir, args.check)


if __name__ == "__main__":
    sys.exit(main())

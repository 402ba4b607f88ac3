#!/usr/bin/python3
"""Generate meshes of the SSNL130 family (rigid plate on a bed of springs).

Model A (--model a, 3D): an nx x ny QUAD4 plate DALLE in z = 0, x in [0, a], y in [0, b];
one SEG2 spring per plate node from the plate node (node 1) to a ground node at z = -L
(node 2), group RESSORT; the ground nodes carry POI1 cells (GROUP_MA PTRESS) and form the
GROUP_NO PTRESS; GROUP_NO PT01 = (0,0,0), PT02 = (a,0,0), PT03 = (0,b,0), PT04 = (a,b,0);
PCDG is an extra node at the plate centre (a/2, b/2, 0), on no cell, in GROUP_NO PCDG.

Model B (--model b, 2D): an ny x 1 QUAD4 slice DALLE, x in [0, b], y in [0, h];
DALLE_2D = the SEG2 of the bottom edge (y = 0), D0403 = the SEG2 of the top edge (y = h);
RESSORTS = SEG2 springs from a ground node (x, -L) (node 1) to the bottom plate node (x, 0)
(node 2); PTRESS = the ground nodes (GROUP_NO, and POI1 cells GROUP_MA PTRESS);
GROUP_NO PT01 = (0, 0), PT02 = (b, 0).

Numbering: plate nodes row by row (x fastest), then ground nodes in the same order, then
PCDG (model A); node names N1.., cell names M1.. in the order QUAD4, edge SEG2, springs,
POI1. Gmsh files use the same numbers as node and element tags (so the readers' names
N<tag>/M<tag> equal the .mail names); node-only groups (PT01.., PCDG) become physical
groups of extra POI1 elements appended at the end.

Formats: aster (.mail), gmsh41 (Gmsh 4.1 ASCII), gmsh22 (Gmsh 2.2 ASCII).

Examples (the committed meshes):
    make_ssnl130_mesh.py --model a --nx 4 --ny 16 -o decks/ssnl130a.mail
    make_ssnl130_mesh.py --model b --ny 16 -o decks/ssnl130b.mail
    make_ssnl130_mesh.py --model a --nx 4 --ny 16 --format gmsh41 -o tests/mesh/ssnl130a.msh
    make_ssnl130_mesh.py --model a --nx 128 --ny 512 -o /tmp/plate_128x512.mail  # benchmark
"""
import argparse
import sys

CELL_NODES = {"POI1": 1, "SEG2": 2, "TRIA3": 3, "QUAD4": 4}
GMSH_TYPE = {"POI1": 15, "SEG2": 1, "TRIA3": 2, "QUAD4": 3}
GMSH_DIM = {"POI1": 0, "SEG2": 1, "TRIA3": 2, "QUAD4": 2}


class Mesh:
    """Nodes (x, y, z), cells (type, node numbers, group) and node-only groups."""

    def __init__(self, dim, title):
        self.dim, self.title = dim, title
        self.nodes, self.cells, self.node_groups = [], [], {}

    def node(self, x, y, z=0.0):
        self.nodes.append((x, y, z))
        return len(self.nodes)

    def cell(self, ctype, nodes, group):
        self.cells.append((ctype, list(nodes), group))

    def cell_groups(self):
        groups = {}
        for number, (_, _, group) in enumerate(self.cells, start=1):
            groups.setdefault(group, []).append(number)
        return groups


def model_a(a, b, nx, ny, length):
    mesh = Mesh(3, f"SSNL130 model A: {nx} x {ny} plate, a={a} b={b} L={length}")
    plate = [[mesh.node(a * i / nx, b * j / ny) for i in range(nx + 1)] for j in range(ny + 1)]
    ground = [[mesh.node(a * i / nx, b * j / ny, -length) for i in range(nx + 1)]
              for j in range(ny + 1)]
    centre = mesh.node(a / 2, b / 2)
    for j in range(ny):
        for i in range(nx):
            mesh.cell("QUAD4", [plate[j][i], plate[j][i + 1], plate[j + 1][i + 1],
                                plate[j + 1][i]], "DALLE")
    flat_plate = [n for row in plate for n in row]
    flat_ground = [n for row in ground for n in row]
    for p, g in zip(flat_plate, flat_ground):
        mesh.cell("SEG2", [p, g], "RESSORT")
    for g in flat_ground:
        mesh.cell("POI1", [g], "PTRESS")
    mesh.node_groups = {"PTRESS": flat_ground, "PT01": [plate[0][0]], "PT02": [plate[0][nx]],
                        "PT03": [plate[ny][0]], "PT04": [plate[ny][nx]], "PCDG": [centre]}
    return mesh


def model_b(b, h, ny, length):
    mesh = Mesh(2, f"SSNL130 model B: {ny} x 1 slice, b={b} h={h} L={length}")
    bottom = [mesh.node(b * j / ny, 0.0) for j in range(ny + 1)]
    top = [mesh.node(b * j / ny, h) for j in range(ny + 1)]
    ground = [mesh.node(b * j / ny, -length) for j in range(ny + 1)]
    for j in range(ny):
        mesh.cell("QUAD4", [bottom[j], bottom[j + 1], top[j + 1], top[j]], "DALLE")
    for j in range(ny):
        mesh.cell("SEG2", [bottom[j], bottom[j + 1]], "DALLE_2D")
    for j in range(ny):
        mesh.cell("SEG2", [top[j], top[j + 1]], "D0403")
    for g, p in zip(ground, bottom):
        mesh.cell("SEG2", [g, p], "RESSORTS")
    for g in ground:
        mesh.cell("POI1", [g], "PTRESS")
    mesh.node_groups = {"PTRESS": ground, "PT01": [bottom[0]], "PT02": [bottom[ny]]}
    return mesh


def number(x):
    return repr(float(x))


def write_aster(mesh, out):
    out.write(f"TITRE\n{mesh.title}\nFINSF\n%\nCOOR_{mesh.dim}D\n")
    for k, xyz in enumerate(mesh.nodes, start=1):
        out.write(f"N{k} " + " ".join(number(v) for v in xyz[:mesh.dim]) + "\n")
    out.write("FINSF\n%\n")
    previous = None
    for k, (ctype, nodes, _) in enumerate(mesh.cells, start=1):
        if ctype != previous:
            if previous is not None:
                out.write("FINSF\n%\n")
            out.write(f"{ctype}\n")
            previous = ctype
        out.write(f"M{k} " + " ".join(f"N{n}" for n in nodes) + "\n")
    out.write("FINSF\n%\n")
    for name, cells in mesh.cell_groups().items():
        out.write(f"GROUP_MA NOM={name}\n")
        write_names(out, [f"M{c}" for c in cells])
    for name, nodes in mesh.node_groups.items():
        out.write(f"GROUP_NO\n{name}\n")
        write_names(out, [f"N{n}" for n in nodes])
    out.write("FIN\n")


def write_names(out, names):
    for start in range(0, len(names), 8):
        out.write(" ".join(names[start:start + 8]) + "\n")
    out.write("FINSF\n%\n")


def gmsh_cells(mesh):
    """Cells plus one POI1 per node of each node-only group, and physical groups."""
    cells = list(mesh.cells)
    cell_group_names = set(mesh.cell_groups())
    for name, nodes in mesh.node_groups.items():
        if name not in cell_group_names:
            cells.extend(("POI1", [n], name) for n in nodes)
    physical = {}
    for ctype, _, group in cells:
        physical.setdefault(group, (GMSH_DIM[ctype], len(physical) + 1))
    return cells, physical


def write_physical_names(out, physical):
    out.write(f"$PhysicalNames\n{len(physical)}\n")
    for name, (dim, tag) in physical.items():
        out.write(f'{dim} {tag} "{name}"\n')
    out.write("$EndPhysicalNames\n")


def write_gmsh22(mesh, out):
    cells, physical = gmsh_cells(mesh)
    out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
    write_physical_names(out, physical)
    out.write(f"$Nodes\n{len(mesh.nodes)}\n")
    for k, xyz in enumerate(mesh.nodes, start=1):
        out.write(f"{k} " + " ".join(number(v) for v in xyz) + "\n")
    out.write(f"$EndNodes\n$Elements\n{len(cells)}\n")
    for k, (ctype, nodes, group) in enumerate(cells, start=1):
        tag = physical[group][1]
        out.write(f"{k} {GMSH_TYPE[ctype]} 2 {tag} {tag} " + " ".join(map(str, nodes)) + "\n")
    out.write("$EndElements\n")


def write_gmsh41(mesh, out):
    """One entity per physical group (a point entity per POI1, as Gmsh requires one node
    per point entity); all nodes in one block on the first entity of the highest dimension."""
    cells, physical = gmsh_cells(mesh)
    blocks = []   # (dim, entity tag, ctype, [(element tag, nodes)])
    point_tag = 0
    entity_of = {}
    for k, (ctype, nodes, group) in enumerate(cells, start=1):
        dim = GMSH_DIM[ctype]
        if dim == 0:
            point_tag += 1
            blocks.append([0, point_tag, ctype, [(k, nodes)], group])
            continue
        key = (group, ctype)
        if key not in entity_of:
            entity_of[key] = len(blocks)
            same_dim = sum(1 for blk in blocks if blk[0] == dim)
            blocks.append([dim, same_dim + 1, ctype, [], group])
        blocks[entity_of[key]][3].append((k, nodes))
    out.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
    write_physical_names(out, physical)
    counts = [sum(1 for blk in blocks if blk[0] == d) for d in range(4)]
    out.write("$Entities\n" + " ".join(map(str, counts)) + "\n")
    for blk in sorted(blocks, key=lambda blk: (blk[0], blk[1])):
        dim, tag, _, elems, group = blk
        coords = [mesh.nodes[n - 1] for _, ns in elems for n in ns]
        phys = physical[group][1]
        if dim == 0:
            out.write(f"{tag} " + " ".join(number(v) for v in coords[0]) + f" 1 {phys}\n")
        else:
            low = [min(c[i] for c in coords) for i in range(3)]
            high = [max(c[i] for c in coords) for i in range(3)]
            out.write(f"{tag} " + " ".join(number(v) for v in low + high) + f" 1 {phys} 0\n")
    out.write("$EndEntities\n")
    top = max(blocks, key=lambda blk: blk[0])
    n = len(mesh.nodes)
    out.write(f"$Nodes\n1 {n} 1 {n}\n{top[0]} {top[1]} 0 {n}\n")
    out.write("".join(f"{k}\n" for k in range(1, n + 1)))
    for xyz in mesh.nodes:
        out.write(" ".join(number(v) for v in xyz) + "\n")
    out.write("$EndNodes\n")
    out.write(f"$Elements\n{len(blocks)} {len(cells)} 1 {len(cells)}\n")
    for dim, tag, ctype, elems, _ in blocks:
        out.write(f"{dim} {tag} {GMSH_TYPE[ctype]} {len(elems)}\n")
        for k, nodes in elems:
            out.write(f"{k} " + " ".join(map(str, nodes)) + "\n")
    out.write("$EndElements\n")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--model", choices=["a", "b"], default="a",
                        help="a: 3D plate on SEG2 springs; b: 2D slice on 2D springs")
    parser.add_argument("--a", type=float, default=1.0, help="plate width (x), model A")
    parser.add_argument("--b", type=float, default=2.0, help="plate length")
    parser.add_argument("--nx", type=int, default=4, help="cells across the width (model A)")
    parser.add_argument("--ny", type=int, default=16, help="cells along the length")
    parser.add_argument("--L", type=float, default=0.1, help="spring length")
    parser.add_argument("--h", type=float, default=0.3, help="slice thickness (model B)")
    parser.add_argument("--format", choices=["aster", "gmsh41", "gmsh22"], default="aster",
                        help="mesh file format: Code_Aster .mail, or Gmsh .msh 4.1 / 2.2")
    parser.add_argument("-o", "--output", default="-", help="output file ('-': stdout)")
    args = parser.parse_args(argv)
    if args.nx < 1 or args.ny < 1 or min(args.a, args.b, args.L, args.h) <= 0:
        parser.error("sizes and counts must be positive")
    if args.model == "a":
        mesh = model_a(args.a, args.b, args.nx, args.ny, args.L)
    else:
        mesh = model_b(args.b, args.h, args.ny, args.L)
    writer = {"aster": write_aster, "gmsh41": write_gmsh41, "gmsh22": write_gmsh22}[args.format]
    if args.output == "-":
        writer(mesh, sys.stdout)
    else:
        with open(args.output, "w", encoding="ascii", newline="\n") as out:
            writer(mesh, out)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes the small plates the mesh-command tests use (tests/mesh_commands, tests/decks/bad):
an N x N plate of unit QUAD4 in z = 0, its four sides as SEG2 groups, corner node groups.

usage: plate_mesh.py N OUTPUT.mail [--flip-top]

Node (i, j) (0 <= i, j <= N) is N(j*(N+1)+i+1) at (i, j); cell Q(j*N+i+1) has nodes
(i,j) (i+1,j) (i+1,j+1) (i,j+1), counterclockwise. Sides: BAS (y = 0, going +x), DROITE
(x = N, going +y), HAUT (y = N), GAUCHE (x = 0), each SEG2 counterclockwise round the
plate (outward normal by Code_Aster's (dy, -dx)), except HAUT with --flip-top, whose
edges go the other way (inward normal: what ORIE_PEAU must turn round); MILIEU, the SEG2
of the inner line x = N/2 (N even), between two columns of quads. GROUP_MA PLAQUE (the
quads), BORD (the four sides); GROUP_NO A (0, 0), B (N, 0), C (N, N), D (0, N).
"""
import sys


def main(argv):
    n = int(argv[1])
    flip = "--flip-top" in argv
    node = lambda i, j: j * (n + 1) + i + 1
    out = ["TITRE", "plate %d x %d of unit QUAD4 (tests/mesh_commands/plate_mesh.py)" % (n, n),
           "FINSF", "COOR_2D"]
    for j in range(n + 1):
        for i in range(n + 1):
            out.append("N%d %d.0 %d.0" % (node(i, j), i, j))
    out += ["FINSF", "QUAD4"]
    for j in range(n):
        for i in range(n):
            out.append("Q%d N%d N%d N%d N%d" % (j * n + i + 1, node(i, j), node(i + 1, j),
                                               node(i + 1, j + 1), node(i, j + 1)))
    out += ["FINSF", "SEG2"]
    sides = {"BAS": [], "DROITE": [], "HAUT": [], "GAUCHE": []}
    k = 0
    for i in range(n):
        k += 1
        out.append("S%d N%d N%d" % (k, node(i, 0), node(i + 1, 0)))
        sides["BAS"].append(k)
    for j in range(n):
        k += 1
        out.append("S%d N%d N%d" % (k, node(n, j), node(n, j + 1)))
        sides["DROITE"].append(k)
    for i in range(n, 0, -1):
        k += 1
        a, b = node(i, n), node(i - 1, n)
        if flip:
            a, b = b, a
        out.append("S%d N%d N%d" % (k, a, b))
        sides["HAUT"].append(k)
    for j in range(n, 0, -1):
        k += 1
        out.append("S%d N%d N%d" % (k, node(0, j), node(0, j - 1)))
        sides["GAUCHE"].append(k)
    sides["MILIEU"] = []
    nsides = k
    for j in range(n):
        k += 1
        out.append("S%d N%d N%d" % (k, node(n // 2, j), node(n // 2, j + 1)))
        sides["MILIEU"].append(k)
    out.append("FINSF")
    out += ["GROUP_MA NOM=PLAQUE"] + ["Q%d" % c for c in range(1, n * n + 1)] + ["FINSF"]
    for name, cells in sides.items():
        out += ["GROUP_MA NOM=%s" % name] + ["S%d" % c for c in cells] + ["FINSF"]
    out += ["GROUP_MA NOM=BORD"] + ["S%d" % c for c in range(1, nsides + 1)] + ["FINSF"]
    for name, (i, j) in (("A", (0, 0)), ("B", (n, 0)), ("C", (n, n)), ("D", (0, n))):
        out += ["GROUP_NO NOM=%s" % name, "N%d" % node(i, j), "FINSF"]
    out.append("FIN")
    with open(argv[2], "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main(sys.argv))

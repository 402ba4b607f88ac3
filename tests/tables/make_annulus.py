#!/usr/bin/env python3
"""Writes annulus.mail (beside this script): a quarter annulus 1 <= r <= 2, 0 <= theta <= 90
degrees, in QUAD4 cells, nr x nt nodes on a polar grid (COOR_2D), for the POST_RELEVE_T
decks of tests/tables. Node N<i>_<j> sits at r = 1 + (i-1)/(nr-1), theta = 90 (j-1)/(nt-1)
degrees. Groups: RAY (the nodes on theta = 30 degrees, r increasing), ARC (the nodes on
r = 1.5, theta increasing), INNER (r = 1), PLAQUE (every cell).

usage: make_annulus.py [--check]   (--check: exit 1 when annulus.mail differs)
"""
import math
import os
import sys

NR, NT = 5, 7


def text():
    lines = ["TITRE", "Quarter annulus 1 <= r <= 2, 0 <= theta <= 90 degrees (make_annulus.py)",
             "FINSF", "%", "COOR_2D"]
    for i in range(1, NR + 1):
        for j in range(1, NT + 1):
            r = 1.0 + (i - 1) / (NR - 1)
            t = math.radians(90.0 * (j - 1) / (NT - 1))
            lines.append("N%d_%d %s %s" % (i, j, repr(r * math.cos(t)), repr(r * math.sin(t))))
    lines += ["FINSF", "%", "QUAD4"]
    cells = []
    for i in range(1, NR):
        for j in range(1, NT):
            name = "M%d_%d" % (i, j)
            cells.append(name)
            lines.append("%s N%d_%d N%d_%d N%d_%d N%d_%d" % (name, i, j, i + 1, j, i + 1, j + 1,
                                                            i, j + 1))
    lines += ["FINSF", "%", "GROUP_MA NOM=PLAQUE"] + [" ".join(cells)] + ["FINSF", "%"]
    lines += ["GROUP_NO NOM=RAY", " ".join("N%d_3" % i for i in range(1, NR + 1)), "FINSF", "%"]
    lines += ["GROUP_NO NOM=ARC", " ".join("N3_%d" % j for j in range(1, NT + 1)), "FINSF", "%"]
    lines += ["GROUP_NO NOM=INNER", " ".join("N1_%d" % j for j in range(1, NT + 1)), "FINSF",
              "%", "FIN"]
    return "\n".join(lines) + "\n"


def main():
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "annulus.mail")
    if "--check" in sys.argv:
        with open(path) as f:
            if f.read() != text():
                print("annulus.mail differs from what make_annulus.py writes")
                return 1
        return 0
    with open(path, "w") as f:
        f.write(text())
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Quadratic against linear plane cells at equal size (issue 21, "Speed"; doc/performance.md,
"Plane elements: QUAD8 and TRIA6 against QUAD4"): a unit square in D_PLAN meshed with each
cell type so that the system has about the same number of equations (--equations, 1e6 by
default), each assembled and solved by MECA_STATIQUE with SOLVEUR METHODE='MULT_FRONT'.

Meshes (written here as .mail, once per size in WORKDIR):
  QUAD4  n x n squares, (n+1)^2 nodes;
  QUAD8  n x n squares with their side middles, (n+1)(3n+1) nodes;
  QUAD9  as QUAD8 with the centres, (2n+1)^2 nodes;
  TRIA6  n x n squares cut along alternating diagonals into two TRIA6, (2n+1)^2 nodes;
n is chosen for 2 x nodes to come nearest the target. Load: the bottom edge held in DY, the
left edge in DX, the top edge moved by DY = 1e-3: a uniform plane-strain stretch, which
every element type reproduces exactly, so the run also checks its answer (TEST_RESU of DX
at the top right corner against -1e-3 nu / (1 - nu)).

Prints per case the whole run's wall and CPU time (os.wait4), peak RSS, and the wall/CPU
times MECA_STATIQUE writes in the .mess (numbering and the solver's analysis, assembly,
factorization, loads and solves), then each type's ratio to QUAD4 and the share of assembly
in the run (wall/CPU):

  RESULT type=QUAD8 equations=... wall=... cpu=... assembly=... factorization=... ...

usage: bench_quadratic_plane.py PARASOL WORKDIR [--equations N] [--types QUAD4,QUAD8,...]
                                [--repeat R]
Exit status 1 when a case fails or its answer is wrong; the targets (within 2x of QUAD4,
assembly under 20 % of the run) are reported, not enforced (benchmarks measure).
"""
import argparse
import math
import os
import re
import subprocess
import sys
import time

NU = 0.3
STRETCH = 1.0e-3
DECK = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='ASTER')
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA='SQUARE', PHENOMENE='MECANIQUE',
                                      MODELISATION='D_PLAN'))
STEEL = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU={nu!r}))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=STEEL))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_NO='LEFT', DX=0.0),
                                         _F(GROUP_NO='BOTTOM', DY=0.0),
                                         _F(GROUP_NO='TOP', DY={stretch!r})))
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=BC),
                    SOLVEUR=_F(METHODE='MULT_FRONT'))
TEST_RESU(RESU=_F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM='DEPL', GROUP_NO='CORNER',
                  NOM_CMP='DX', REFERENCE='ANALYTIQUE', VALE_REFE={dx!r},
                  VALE_CALC={dx!r}, PRECISION=1.0e-8))
FIN()
"""


def corner_count(cell, n):
    """Nodes of an n x n mesh of `cell`."""
    if cell == "QUAD4":
        return (n + 1) ** 2
    if cell == "QUAD8":
        return (n + 1) * (3 * n + 1)
    return (2 * n + 1) ** 2


def size_for(cell, equations):
    """The n whose 2 x nodes is nearest `equations`."""
    n = max(1, int(math.sqrt(equations / 2.0 / {"QUAD4": 1, "QUAD8": 3}.get(cell, 4))))
    return min(range(max(1, n - 3), n + 4),
               key=lambda m: abs(2 * corner_count(cell, m) - equations))


def write_mesh(cell, n, path):
    """The unit square as n x n cells of `cell` (module doc), Code_Aster .mail."""
    h = 1.0 / n
    quadratic = cell != "QUAD4"
    fine = 2 * n if quadratic else n           # nodes on a fine grid of step h/2 (or h)
    step = 1.0 / fine

    def number(i, j):                           # fine-grid node (i, j) -> its number
        if cell in ("QUAD4", "QUAD9", "TRIA6"):
            return j * (fine + 1) + i + 1
        # QUAD8: even rows hold every fine node, odd rows only the even columns
        full, half = fine + 1, n + 1
        pairs = j // 2
        base = pairs * (full + half)
        if j % 2 == 0:
            return base + i + 1
        return base + full + i // 2 + 1

    out = ["TITRE", "unit square, %d x %d %s (bench_quadratic_plane.py)" % (n, n, cell),
           "FINSF", "COOR_2D"]
    for j in range(fine + 1):
        for i in range(fine + 1):
            if cell == "QUAD8" and j % 2 == 1 and i % 2 == 1:
                continue
            out.append("N%d %.17g %.17g" % (number(i, j), i * step, j * step))
    out += ["FINSF", cell]
    k = 0
    for j in range(n):
        for i in range(n):
            if cell == "QUAD4":
                k += 1
                out.append("M%d N%d N%d N%d N%d" % (k, number(i, j), number(i + 1, j),
                                                     number(i + 1, j + 1), number(i, j + 1)))
                continue
            a, b = 2 * i, 2 * j
            c = [number(a, b), number(a + 2, b), number(a + 2, b + 2), number(a, b + 2)]
            m = [number(a + 1, b), number(a + 2, b + 1), number(a + 1, b + 2),
                 number(a, b + 1)]
            if cell in ("QUAD8", "QUAD9"):
                k += 1
                nodes = c + m + ([number(a + 1, b + 1)] if cell == "QUAD9" else [])
                out.append("M%d " % k + " ".join("N%d" % v for v in nodes))
                continue
            centre = number(a + 1, b + 1)
            if (i + j) % 2 == 0:                # diagonal corner 0 - corner 2
                tris = ((c[0], c[1], c[2], m[0], m[1], centre),
                        (c[0], c[2], c[3], centre, m[2], m[3]))
            else:                               # diagonal corner 1 - corner 3
                tris = ((c[0], c[1], c[3], m[0], centre, m[3]),
                        (c[1], c[2], c[3], m[1], m[2], centre))
            for t in tris:
                k += 1
                out.append("M%d " % k + " ".join("N%d" % v for v in t))
    out += ["FINSF", "GROUP_MA NOM=SQUARE"] + ["M%d" % c for c in range(1, k + 1)] + ["FINSF"]

    def line(name, nodes):
        return ["GROUP_NO NOM=%s" % name] + ["N%d" % v for v in nodes] + ["FINSF"]

    out += line("BOTTOM", [number(i, 0) for i in range(fine + 1)])
    out += line("TOP", [number(i, fine) for i in range(fine + 1)])
    out += line("LEFT", [number(0, j) for j in range(fine + 1)])
    out += line("CORNER", [number(fine, fine)])
    out.append("FIN")
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(path + ".tmp", path)


def run_case(parasol, workdir, cell, n):
    stem = os.path.join(workdir, "square_%s_%d" % (cell.lower(), n))
    if not os.path.exists(stem + ".mail"):
        write_mesh(cell, n, stem + ".mail")
    with open(stem + ".comm", "w") as f:
        f.write(DECK.format(nu=NU, stretch=STRETCH, dx=-STRETCH * NU / (1.0 - NU)))
    start = time.monotonic()
    proc = subprocess.Popen([parasol, "--quiet", "--outdir", workdir, stem + ".comm"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    output = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        sys.stdout.write(output)
        print("FAILED: %s (exit %d; %s.mess)" % (cell, code, stem))
        return None
    mess = open(stem + ".mess").read()
    pair = r"([0-9.]+) / ([0-9.]+)"
    times = re.search(r"MECA_STATIQUE times \(wall / CPU s\): numbering and analysis %s, "
                      r"assembly %s, factorization %s, loads and solves %s"
                      % (pair, pair, pair, pair), mess)
    equations = re.search(r"METHODE MULT_FRONT: (\d+) free equations", mess)
    terms = re.search(r"factorization MULT_FRONT \(ordering (\w+)\): (\d+) terms", mess)
    if not (times and equations and terms):
        print("FAILED: no MECA_STATIQUE times in %s.mess" % stem)
        return None
    t = [float(v) for v in times.groups()]
    return dict(type=cell, n=n, equations=int(equations.group(1)), wall=wall,
                cpu=usage.ru_utime + usage.ru_stime, rss_mb=usage.ru_maxrss / 1024.0,
                analysis=t[0], analysis_cpu=t[1], assembly=t[2], assembly_cpu=t[3],
                factorization=t[4], factorization_cpu=t[5], solves=t[6], solves_cpu=t[7],
                terms=int(terms.group(2)), ordering=terms.group(1))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("parasol")
    parser.add_argument("workdir")
    parser.add_argument("--equations", type=float, default=1.0e6)
    parser.add_argument("--types", default="QUAD4,QUAD8,TRIA6")
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    cells = args.types.split(",")
    best = {}
    for _ in range(args.repeat):
        for cell in cells:
            n = size_for(cell, args.equations)
            r = run_case(args.parasol, args.workdir, cell, n)
            if r is None:
                return 1
            if cell not in best or r["wall"] < best[cell]["wall"]:
                best[cell] = r
    base = best.get("QUAD4")
    for cell in cells:
        r = best[cell]
        line = ("RESULT type=%(type)s n=%(n)d equations=%(equations)d wall=%(wall).2f "
                "cpu=%(cpu).2f rss_mb=%(rss_mb).0f analysis=%(analysis).2f/%(analysis_cpu).2f "
                "assembly=%(assembly).2f/%(assembly_cpu).2f "
                "factorization=%(factorization).2f/%(factorization_cpu).2f "
                "solves=%(solves).2f/%(solves_cpu).2f factor_terms=%(terms)d" % r)
        line += " assembly_share=%.3f/%.3f" % (r["assembly"] / r["wall"],
                                               r["assembly_cpu"] / r["cpu"])
        if base is not None:
            line += " wall_vs_quad4=%.2f cpu_vs_quad4=%.2f" % (r["wall"] / base["wall"],
                                                               r["cpu"] / base["cpu"])
        print(line, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

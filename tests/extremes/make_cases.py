#!/usr/bin/python3
"""Write the "stability at the extremes" decks of tests/extremes/cases (issue 7).

Every case is an SSNL130-family deck written by tools/make_ssnl130_case.py, with its expected
outcome in its first lines (read by run_case.py):
    # mesh: b16.mail            the mesh, in cases/
    # expect-exit: 0|1|2        parasol's exit status
    # expect: REGEX             (exit 1) a regular expression the error line must match
    # why: ...                  one line on why this is the expected outcome
References: the exact rigid-plate answer (tools/rigid_bed_exact.py, shifted by DIST_1 - L
for the gap cases) where the plate is rigid compared with its bed; the flexible-slab
finite-element answer of slab_reference.py (mpmath, exact, independent) where it is not (soft
plate, stiff springs, thin slab). See doc/stability.md for the table and the numerics.

Usage: make_cases.py [--only NAME ...]   (from anywhere; rewrites cases/)
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
GEN = os.path.join(ROOT, "tools", "make_ssnl130_case.py")
OUT = os.path.join(HERE, "cases")
sys.path.insert(0, HERE)
import slab_reference  # noqa: E402

INST1 = r"error: STAT_NON_LINE: INST 1\.0+E\+00: "
NO_EQUILIBRIUM = INST1 + r"no equilibrium: "
NODE = r"at node N[0-9]+ component DR?[XYZ] \(pivot lost [0-9.]+ digits, NPREC = {nprec}\)"
# a pivot at round-off level (>= 12 digits lost): nothing holds the equation
FREE = INST1 + r"singular matrix " + NODE + r", [0-9]+ pivot\(s\) flagged: the equation is free"
# more digits lost than NPREC, fewer than 12: held, but too ill-conditioned for NPREC
ILL = INST1 + r"ill-conditioned matrix " + NODE + r": more than NPREC but fewer than 12"
TIGHT = ["--resi", "1e-10"]


def case(name, args, exit_code=0, expect=None, why="", slab=None):
    """One case. slab: keyword arguments of slab_reference.solve (flexible reference)."""
    return dict(name=name, args=args, exit=exit_code, expect=expect, why=why, slab=slab)


def b_nprec9(name, extra, *rest, **kw):
    args = ["--model", "b", "--nprec", "9"]
    if "--nprec" in extra:
        args = ["--model", "b"]
    return case(name, args + extra, *rest, **kw)


def cases():
    c = []
    # --- stiffness contrast, model B: E with K = 1e4, then K with E = 2e11 ------------------
    for E, tol in (("1e3", "1e-8"), ("1e6", "1e-8"), ("1e9", "1e-8")):
        c.append(b_nprec9(f"b_E{E}", ["--E", E, "--tolerance", tol],
                          why=f"E/K = {float(E) / 1e4:g}: the slab bends; flexible-slab reference",
                          slab=dict(E=float(E))))
    c.append(b_nprec9("b_E2e11", ["--tolerance", "2e-7"],
                      why="nominal (Code_Aster's model B): rigid reference, tolerance 2e-7"))
    c.append(b_nprec9("b_E1e12", ["--E", "1e12", "--tolerance", "1e-7"],
                      why="E/K = 1e8: rigid reference; 8.3 digits lost, within NPREC = 9"))
    c.append(b_nprec9("b_E1e13", ["--E", "1e13", "--tolerance", "1e-8"],
                      why="E/K = 1e9: rigid modes kept apart, 1.4 digits lost (was 9.3: "
                          "stopped at NPREC 9); rigid reference"))
    c.append(b_nprec9("b_E1e18", ["--E", "1e18", "--tolerance", "1e-10"],
                      why="E/K = 1e14: 1.4 digits lost (was 14, a round-off pivot: "
                          "'singular'); rigid reference"))
    for E, tol in (("1e13", "1e-8"), ("1e14", "1e-8")):
        c.append(case(f"b_E{E}_nprec15", ["--model", "b", "--nprec", "15", "--E", E,
                                           "--tolerance", tol] + TIGHT,
                      why="NPREC raised, RESI_GLOB_RELA 1e-10: Newton with incremental forces "
                          "recovers the digits the factor lost"))
    c.append(case("b_E1e15_nprec15", ["--model", "b", "--nprec", "15", "--E", "1e15"] + TIGHT,
                  why="12.4 digits lost (NPREC 15): the pivots stay far above round-off of "
                      "the largest term, so the held slab is not mistaken for a free one; "
                      "the Newton iterations recover the digits"))
    for K, tol in (("1e6", "1e-8"), ("1e8", "1e-8"), ("1e12", "1e-8")):
        c.append(b_nprec9(f"b_K{K}", ["--K", str(int(float(K))), "--tolerance", tol],
                          why="springs stiff against the slab: flexible-slab reference",
                          slab=dict(K=float(K))))
    c.append(b_nprec9("b_K1e2", ["--K", "100", "--tolerance", "1e-8"],
                      why="E/K = 2e9: 1.4 digits lost (was 9.6: stopped at NPREC 9)"))
    c.append(case("b_K1e2_nprec11", ["--model", "b", "--nprec", "11", "--K", "100",
                                     "--tolerance", "1e-8"] + TIGHT,
                  why="NPREC raised, RESI_GLOB_RELA 1e-10: rigid reference to 1e-9"))
    c.append(b_nprec9("b_K1e-4", ["--K", "0.0001", "--tolerance", "1e-10"],
                      why="E/K = 2e15: 1.4 digits lost (was 15, a round-off pivot: "
                          "'singular'); rigid reference"))
    # --- stiffness contrast, model A (4 x 16, NPREC 8) ----------------------------------
    c.append(case("a_nominal", ["--model", "a", "--nprec", "8", "--tolerance", "1e-6"],
                  why="SSNL130 model A, full Newton: rigid reference to 1e-6"))
    c.append(case("a_E2e12", ["--model", "a", "--nprec", "8", "--E", "2e12",
                              "--tolerance", "1e-7"],
                  why="ten times stiffer plate: 1.5 digits lost (was 8.5: stopped at NPREC 8)"))
    c.append(case("a_E2e15", ["--model", "a", "--nprec", "8", "--E", "2e15",
                              "--tolerance", "1e-9"],
                  why="E = 2e15, plate 1e4 times stiffer than SSNL130's: rigid reference"))
    c.append(case("a_K1e-4", ["--model", "a", "--nprec", "8", "--K", "0.0001",
                              "--tolerance", "1e-9"],
                  why="bed 1e8 times softer than SSNL130's: rigid reference"))
    c.append(case("a_E2e12_nprec9", ["--model", "a", "--E", "2e12", "--nprec", "9",
                                     "--tolerance", "1e-7"] + TIGHT,
                  why="same with NPREC = 9 and RESI_GLOB_RELA 1e-10: 1.3e-8"))
    # --- load scale over 20 decades (model B, nominal stiffness) ------------------------
    for p in ("5e-10", "5e-5", "5e5", "5e10"):
        c.append(b_nprec9(f"b_p{p}", ["--p", p, "--tolerance", "2e-7"],
                          why="homogeneous of degree 1 in the load: same contact rows, "
                              "displacements scaled by p/5"))
    c.append(b_nprec9("b_p5e-14", ["--p", "5e-14", "--tolerance", "2e-7"],
                      why="openings of ~3e-17 m, below eps L: the contact status is decided "
                          "on the displacement alone (the eps margin is on the geometry), "
                          "so homogeneity holds"))
    c.append(b_nprec9("b_p5e-200", ["--p", "5e-200", "--tolerance", "2e-7"],
                      why="homogeneity down to 1e-200: openings of ~1e-203 m are still seen"))
    c.append(b_nprec9("b_p5e200", ["--p", "5e200", "--tolerance", "2e-7"],
                      why="homogeneity up to 1e200: no overflow anywhere"))
    # --- thickness, mesh size, time steps -----------------------------------------------
    c.append(b_nprec9("b_h1e-3", ["--h", "1e-3", "--tolerance", "1e-10"] + TIGHT,
                      why="elements 125 times longer than thick, the slab bends: 5.1 digits "
                          "lost (was 9.7: stopped at NPREC 9); exact flexible reference",
                      slab=dict(h=1e-3)))
    c.append(case("b_h1e-3_nprec12", ["--model", "b", "--h", "1e-3", "--nprec", "12",
                                      "--tolerance", "1e-10"] + TIGHT,
                  why="NPREC 12 changes nothing (5.1 digits lost); a double-precision "
                      "reference is 5.7e-6 off here, the exact one (mpmath) is met to 1e-13",
                  slab=dict(h=1e-3)))
    c.append(b_nprec9("b_h10", ["--h", "10", "--tolerance", "2e-8"],
                      why="thick slab, stiffer: 1.7 digits lost (was 10.7: stopped at "
                          "NPREC 9); rigid reference"))
    c.append(case("b_h10_nprec11", ["--model", "b", "--h", "10", "--nprec", "11",
                                    "--tolerance", "1e-7"] + TIGHT,
                  why="NPREC raised, RESI_GLOB_RELA 1e-10: rigid reference"))
    for ny in (64, 128):
        c.append(b_nprec9(f"b_ny{ny}", ["--ny", str(ny), "--tolerance", "2e-7"],
                          why=f"{ny + 1} spring rows: rigid reference of the same discrete bed"))
    c.append(b_nprec9("b_ny512", ["--ny", "512", "--tolerance", "2e-7"],
                      why="513 rows of K/512: 2.9 digits lost (was 9.4: stopped at NPREC 9)"))
    c.append(case("b_ny512_nprec10", ["--model", "b", "--ny", "512", "--nprec", "10",
                                      "--tolerance", "2e-7"],
                  why="NPREC = 10: rigid reference of the 513-row bed"))
    c.append(case("a_ny32", ["--model", "a", "--nprec", "8", "--ny", "32",
                             "--tolerance", "1e-6"],
                  why="model A 4 x 32: 2.5 digits lost (was 8.3: stopped at NPREC 8)"))
    c.append(case("a_ny64_nprec10", ["--model", "a", "--ny", "64", "--nprec", "10",
                                     "--tolerance", "1e-6"] + TIGHT,
                  why="model A 4 x 64 with NPREC = 10: rigid reference"))
    for steps in (10, 100):
        c.append(b_nprec9(f"b_steps{steps}", ["--steps", str(steps), "--tolerance", "2e-7"],
                          why="the answer at t = 1 does not depend on the path (no friction)"))
    # --- initial gaps ---------------------------------------------------------------------
    c.append(b_nprec9("b_gap_plus", ["--dist1-offset", "1e-9", "--shift-by-gap",
                                     "--tolerance", "2e-7"],
                      why="DIST_1 = L + 1e-9: springs start 1e-9 compressed; answer + 1e-9"))
    c.append(b_nprec9("b_gap_minus", ["--dist1-offset=-1e-9", "--shift-by-gap",
                                      "--tolerance", "2e-7"],
                      why="DIST_1 = L - 1e-9: springs start 1e-9 open; answer - 1e-9"))
    c.append(b_nprec9("b_gap_minus_elastic", ["--dist1-offset=-1e-9", "--shift-by-gap",
                                              "--newton", "elastique", "--resi", "1e-10",
                                              "--iter-max", "100", "--tolerance", "2e-7"],
                      why="same, ELASTIQUE (modified Newton); answer - 1e-9"))
    # --- MECA_STATIQUE (bilateral springs): the same solver path --------------------------
    c.append(case("a_bilateral_K1e-4", ["--model", "a", "--bilateral", "--K", "0.0001",
                                        "--tolerance", "1e-9"],
                  why="MECA_STATIQUE, bed 1e8 times softer than SSNL130's (3e5 m of rigid "
                      "motion): was 'singular' (15 digits), now 1.5 digits lost"))
    c.append(b_nprec9("b_bilateral_E2e15_K1e-4", ["--bilateral", "--K", "0.0001", "--E",
                                                  "2e15", "--tolerance", "1e-9"],
                      why="MECA_STATIQUE, E/K = 2e19: the rigid modes kept apart"))
    # --- NPREC judges what is factored: the slab held at its anchors ---------------------
    c.append(b_nprec9("b_nprec1", ["--nprec", "1"], 1, ILL.format(nprec=1),
                      why="the factored matrix (the slab held at its anchors) loses 1.4 "
                          "digits, more than NPREC = 1: still a located stop"))
    # --- no equilibrium, zero load, zero stiffness --------------------------------------
    c.append(b_nprec9("b_lifting_load", ["--p=-5", "--expect-no-equilibrium"], 1,
                      NO_EQUILIBRIUM + r"[0-9]+ of 17 DIS_CHOC springs are open",
                      why="the load pulls the slab off its bed: no equilibrium"))
    c.append(b_nprec9("b_zero_load", ["--p", "0"],
                      why="no load: zero displacement, absolute residual criterion"))
    c.append(b_nprec9("b_K0", ["--K", "0", "--expect-no-equilibrium"], 1, FREE.format(nprec=9),
                      why="springs of zero stiffness: nothing holds the slab"))
    c.append(case("a_K0", ["--model", "a", "--nprec", "8", "--K", "0",
                          "--expect-no-equilibrium"], 1,
                  FREE.format(nprec=8),
                  why="springs of zero stiffness: nothing holds the plate"))
    return c


def option(args, key, default):
    for k, a in enumerate(args):
        if a == key:
            return args[k + 1]
        if a.startswith(key + "="):
            return a.split("=", 1)[1]
    return default


def mesh_name(args):
    model = option(args, "--model", "a")
    ny = option(args, "--ny", "16")
    if model == "a":
        return f"a{option(args, '--nx', '4')}x{ny}.mail"
    h = option(args, "--h", "0.3")
    return f"b{ny}.mail" if h == "0.3" else f"b{ny}_h{h}.mail"


def write(c):
    stem = os.path.join(OUT, c["name"])
    args = list(c["args"])
    if c["slab"]:
        kw = dict(ny=16, E=2.0e11, K=1.0e4, p=5.0)
        kw.update(c["slab"])
        v0, vb, _ = slab_reference.solve(**kw)
        args += [f"--refe-values={v0!r},{vb!r}"]
    # run in cases/ with a relative -o: the deck's "Generated by" line names no local path
    subprocess.run([sys.executable, GEN] + args + ["-o", c["name"]], check=True, cwd=OUT)
    mesh = mesh_name(args)
    os.replace(stem + ".mail", os.path.join(OUT, mesh))
    with open(stem + ".comm", encoding="utf-8") as f:
        deck = f.read()
    head = [f"# mesh: {mesh}", f"# expect-exit: {c['exit']}"]
    if c["expect"]:
        head.append(f"# expect: {c['expect']}")
    head.append(f"# why: {c['why']}")
    if c["slab"]:
        head.append("# reference: flexible slab, tests/extremes/slab_reference.py "
                    + " ".join(f"--{k} {v!r}" for k, v in c["slab"].items()))
    with open(stem + ".comm", "w", encoding="utf-8") as f:
        f.write("\n".join(head) + "\n" + deck)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    ap.add_argument("--only", nargs="*", default=None,
                    help="write only these cases (names as in the CASES table; None: all)")
    o = ap.parse_args(argv)
    os.makedirs(OUT, exist_ok=True)
    for c in cases():
        if o.only is None or c["name"] in o.only:
            write(c)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Write a CalculiX (ccx 2.20) input deck of the SSNL130 plate on a unilateral spring bed.

The model mirrors parasol's SSNL130 model A (doc: ssnl130.md) at any nx x ny mesh:

* plate x in [0, a], y in [0, b], z = 0: nx x ny S4 shells (full integration; S4R, the
  reduced-integration variant, is visibly more flexible), thickness h, steel E, nu;
* one GAPUNI element per plate node, from a fixed ground node at z = -L (element node 1) to
  the plate node (element node 2).  CalculiX's gap condition is d + n.(u2 - u1) >= 0 (open);
  with clearance d = 0 and n = +z the gap closes exactly when the plate node moves down, so
  every spring starts "just closed" as DIS_CHOC with DIST_1 = L does.  The gap stiffness is
  the node's RIGI_PARASOL share of the global stiffness K: node weight = (area the node
  represents) / (plate area), i.e. 1/(4 nx ny) at corners, 2/(4 nx ny) on edges and
  4/(4 nx ny) inside;
* the *GAP "force at minus infinity" (7th entry; ccx default 1e-3 N) is the small tension an
  open gap still carries.  With the default every open gap pulls and the lift at y = b is
  off by percents; GAP_FORCE_INF = 1e-12 N makes open gaps carry nothing that matters;
* pressure P(y) = p (y - b)^2 pushing the plate down, applied as exact consistent nodal
  forces F_i = integral of N_i P over each bilinear cell (P is quadratic in y, so Simpson's
  rule in y is exact; the integrals are done in rational arithmetic).  Their resultant is
  a p b^3 / 3 (40/3 N for the defaults) and their first moments are exact too;
* ccx solves a *STATIC step without NLGEOM as one linear solve unless a material is
  nonlinear, which would ignore the gaps' status.  The steel therefore gets a *PLASTIC yield
  stress (1e30 Pa) that is never reached: ccx then iterates (Newton) on the gap forces;
* in-plane rigid motions (the plate and gaps have no in-plane load or stiffness): DX = DY = 0
  at the corner (0, 0) and DY = 0 at the corner (a, 0).  This is statically determinate in
  the plane (no reaction can arise since no in-plane load exists), so it removes the three
  in-plane rigid modes without changing DZ.  parasol's model uses tangential springs for the
  same purpose; with no in-plane load they carry nothing either.

Output: *NODE PRINT of U for the node set CORNERS (PT01 = (0,0), PT02 = (a,0), PT03 = (0,b),
PT04 = (a,b), in that order) into <job>.dat.  parse_corner_dz() reads it back.

Usage: make_ccx_bed.py [--nx 4] [--ny 16] [-o bed.inp] [--a 1 --b 2 --h 0.3 --E 2e11
       --nu 0.3 --K 1e4 --p 5 --L 0.1]
"""
import argparse
import sys
from fractions import Fraction as Fr

# ccx *GAP 7th entry: tension carried by an open gap at infinite opening (ccx default 1e-3 N).
GAP_FORCE_INF = 1.0e-12
# Yield stress that is never reached: only there to make ccx run its nonlinear iterations.
NEVER_YIELD = 1.0e30
# ccx reads reals with the Fortran format f20.0: longer fields are an input error.
CCX_FIELD_WIDTH = 20

class HelpFormatter(argparse.ArgumentDefaultsHelpFormatter,
                    argparse.RawDescriptionHelpFormatter):
    """--help shows each option's default, and the docstring as written."""


DEFAULTS = dict(a="1", b="2", h="0.3", E="2e11", nu="0.3", K="1e4", p="5", L="0.1")


def plate_node(i, j, nx):
    """Node number of the plate node at column i (x), row j (y); numbering starts at 1."""
    return 1 + i + j * (nx + 1)


def ground_node(i, j, nx, ny):
    """Node number of the ground node under plate node (i, j)."""
    return (nx + 1) * (ny + 1) + plate_node(i, j, nx)


def corner_nodes(nx, ny):
    """PT01..PT04 = (0,0), (a,0), (0,b), (a,b) as plate node numbers."""
    return [plate_node(0, 0, nx), plate_node(nx, 0, nx),
            plate_node(0, ny, nx), plate_node(nx, ny, nx)]


def node_weight_quarters(i, j, nx, ny):
    """Number of cell quarters node (i, j) collects: 1 corner, 2 edge, 4 interior."""
    cx = 1 if i in (0, nx) else 2
    cy = 1 if j in (0, ny) else 2
    return cx * cy


def consistent_pressure_forces(nx, ny, a, b, p):
    """Exact consistent nodal forces (downward magnitudes, Fractions) for P = p (y - b)^2.

    For a cell [x0, x1] x [y0, y1] with bilinear N_i = X_i(x) Y_i(y):
        F_i = (int X_i dx) (int Y_i P dy) = (hx / 2) * int Y_i P dy,
    and Y_i P is a cubic in y, integrated exactly by Simpson's rule.
    Returns a dict plate node number -> force.
    """
    hx, hy = a / nx, b / ny
    pres = lambda y: p * (y - b) ** 2
    forces = {}
    for j in range(ny):
        y0, y1 = j * hy, (j + 1) * hy
        ym = (y0 + y1) / 2
        # Simpson on [y0, y1]: int f = hy/6 (f(y0) + 4 f(ym) + f(y1)); Y_0 = (y1 - y)/hy.
        low = hy / 6 * (pres(y0) + 4 * pres(ym) / 2)
        high = hy / 6 * (4 * pres(ym) / 2 + pres(y1))
        for i in range(nx):
            for (ii, jj, fy) in ((i, j, low), (i + 1, j, low),
                                 (i, j + 1, high), (i + 1, j + 1, high)):
                n = plate_node(ii, jj, nx)
                forces[n] = forces.get(n, Fr(0)) + hx / 2 * fy
    return forces


def ffmt(x):
    """Text of a float that ccx can read: ccx reads each real with format f20.0, so a field
    must fit in 20 characters.  Shortest round-trip text when it fits, else 13 digits."""
    text = repr(float(x))
    return text if len(text) <= CCX_FIELD_WIDTH else f"{float(x):.12e}"


def write_deck(out, nx, ny, a, b, h, E, nu, K, p, L):
    """Write the deck to the open text file `out`.  Numbers are Fractions (or int/str)."""
    a, b, h, E, nu, K, p, L = (Fr(v) for v in (a, b, h, E, nu, K, p, L))
    w = out.write
    w("** SSNL130-like plate on a unilateral spring bed, written by make_ccx_bed.py\n")
    w(f"** nx={nx} ny={ny} a={a} b={b} h={h} E={E} nu={nu} K={K} p={p} L={L}\n")
    w("*NODE, NSET=NPLATE\n")
    for j in range(ny + 1):
        for i in range(nx + 1):
            w(f"{plate_node(i, j, nx)}, {ffmt(a * i / nx)}, {ffmt(b * j / ny)}, 0.0\n")
    w("*NODE, NSET=NGROUND\n")
    for j in range(ny + 1):
        for i in range(nx + 1):
            w(f"{ground_node(i, j, nx, ny)}, {ffmt(a * i / nx)}, {ffmt(b * j / ny)}, "
              f"{ffmt(-L)}\n")
    # Plate: counter-clockwise seen from +z, so the shell normal is +z (irrelevant for the
    # load, which is given as nodal forces, but kept conventional).
    w("*ELEMENT, TYPE=S4, ELSET=PLATE\n")
    e = 0
    for j in range(ny):
        for i in range(nx):
            e += 1
            w(f"{e}, {plate_node(i, j, nx)}, {plate_node(i + 1, j, nx)}, "
              f"{plate_node(i + 1, j + 1, nx)}, {plate_node(i, j + 1, nx)}\n")
    # Gaps, grouped by stiffness class (1, 2 or 4 cell quarters).
    classes = {1: [], 2: [], 4: []}
    for j in range(ny + 1):
        for i in range(nx + 1):
            e += 1
            classes[node_weight_quarters(i, j, nx, ny)].append(
                (e, ground_node(i, j, nx, ny), plate_node(i, j, nx)))
    for q, elems in classes.items():
        if not elems:
            continue
        w(f"*ELEMENT, TYPE=GAPUNI, ELSET=GAP{q}\n")
        for (el, n1, n2) in elems:
            w(f"{el}, {n1}, {n2}\n")
    w("*MATERIAL, NAME=STEEL\n*ELASTIC\n")
    w(f"{ffmt(E)}, {ffmt(nu)}\n")
    w(f"*PLASTIC\n{ffmt(NEVER_YIELD)}, 0.0\n")
    w("*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL\n")
    w(f"{ffmt(h)}\n")
    for q, elems in classes.items():
        if not elems:
            continue
        k = K * q / (4 * nx * ny)
        # clearance, direction (nx, ny, nz), unused, stiffness, force at minus infinity
        w(f"*GAP, ELSET=GAP{q}\n0.0, 0.0, 0.0, 1.0, , {ffmt(k)}, {ffmt(GAP_FORCE_INF)}\n")
    w("*NSET, NSET=CORNERS\n")
    w(", ".join(str(n) for n in corner_nodes(nx, ny)) + "\n")
    w("*BOUNDARY\nNGROUND, 1, 3, 0.0\n")
    # In-plane rigid modes only (see module docstring).
    w(f"*BOUNDARY\n{plate_node(0, 0, nx)}, 1, 2, 0.0\n{plate_node(nx, 0, nx)}, 2, 2, 0.0\n")
    w("*STEP, INC=1000\n*STATIC\n1.0, 1.0\n")
    w("*CLOAD\n")
    forces = consistent_pressure_forces(nx, ny, a, b, p)
    for n in sorted(forces):
        if forces[n] != 0:
            w(f"{n}, 3, {ffmt(-forces[n])}\n")
    w("*NODE PRINT, NSET=CORNERS\nU\n")
    w("*END STEP\n")
    return forces


def parse_corner_dz(dat_path, nx, ny):
    """Return [DZ(PT01), DZ(PT02), DZ(PT03), DZ(PT04)] from the last U block of a ccx .dat.

    Errors: raises ValueError when the file has no displacement block or misses a corner.
    """
    last = {}
    in_block = False
    with open(dat_path, encoding="latin-1") as f:
        for line in f:
            s = line.strip()
            if s.startswith("displacements"):
                in_block, last = True, {}
                continue
            if not in_block or not s:
                continue
            parts = s.split()
            try:
                node = int(parts[0])
                vals = [float(v.replace("D", "E")) for v in parts[1:4]]
            except (ValueError, IndexError):
                in_block = False
                continue
            last[node] = vals
    out = []
    for n in corner_nodes(nx, ny):
        if n not in last:
            raise ValueError(f"{dat_path}: no displacement of corner node {n} "
                             "(did ccx finish the step?)")
        out.append(last[n][2])
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=HelpFormatter)
    ap.add_argument("--nx", type=int, default=4, help="cells across the width")
    ap.add_argument("--ny", type=int, default=16, help="cells along the length")
    for key, val in DEFAULTS.items():
        ap.add_argument(f"--{key}", default=val, help=f"{key} of the SSNL130 case")
    ap.add_argument("-o", "--output", default="-", help="deck file ('-': stdout)")
    o = ap.parse_args(argv)
    if o.nx < 1 or o.ny < 1:
        ap.error("--nx and --ny must be >= 1")
    args = [getattr(o, k) for k in DEFAULTS]
    if o.output == "-":
        forces = write_deck(sys.stdout, o.nx, o.ny, *args)
    else:
        with open(o.output, "w", encoding="ascii") as f:
            forces = write_deck(f, o.nx, o.ny, *args)
    total = sum(forces.values())
    print(f"pressure resultant = {total} = {float(total):.12g} N", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())

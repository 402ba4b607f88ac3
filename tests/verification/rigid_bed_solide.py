#!/usr/bin/env python3
"""The reference of ssnl130a_solide.comm, computed here in rationals.

SSNL130 model A with the plate made rigid (LIAISON_SOLIDE): a rigid plate a = 1 wide,
b = 2 long, on 17 rows of springs y_j = j b/16 (RIGI_PARASOL spreads the global stiffness
K = 1e4 in proportion to area: K/16 per inside row, K/32 per end row), loaded by the
pressure P(y) = 5 (y - 2)^2 as Code_Aster loads a FORMULE pressure on DKT plates: taken at
the nodes and interpolated linearly between them, so each row carries the consistent load
a h/6 (P_{j-1} + 4 P_j + P_{j+1}) (resultant 855/64 N, moment about y = 0 1285/192 N m).
The springs resist compression only: the active set is iterated to its fixed point, in
Fractions, so the answer is exact. The plate's deflection is w(y) = U_A + s y; U_B = w(b).

Usage: rigid_bed_solide.py DECK [SHARED_REF]
  Checks that the constants U_A and U_B of DECK equal the exact values (as Fractions of
  the decimal literals the deck writes). With SHARED_REF (../shared/tools/rigid_bed_ref.py)
  present, also checks that it gives the same values with --load nodes; absent, says the
  cross-check is skipped. Exit 0 when every check holds.
"""
import os
import re
import subprocess
import sys
from fractions import Fraction as Fr


def rigid_bed(a=Fr(1), b=Fr(2), k_total=Fr(10000), p=Fr(5), ny=16):
    h = b / ny
    y = [j * h for j in range(ny + 1)]
    pres = [p * (b - t) ** 2 for t in y]
    k = [k_total / ny / (2 if j in (0, ny) else 1) for j in range(ny + 1)]
    f = []
    for j in range(ny + 1):
        s = (2 if j in (0, ny) else 4) * pres[j]
        s += pres[j - 1] if j > 0 else 0
        s += pres[j + 1] if j < ny else 0
        f.append(a * h / 6 * s)
    force = sum(f)
    moment = sum(fj * yj for fj, yj in zip(f, y))
    active = set(range(ny + 1))
    for _ in range(4 * (ny + 1)):
        # Equilibrium of the springs in contact against the downward load:
        #   sum k_j (u + s y_j) = -F,  sum k_j (u + s y_j) y_j = -M.
        k0 = sum(k[j] for j in active)
        k1 = sum(k[j] * y[j] for j in active)
        k2 = sum(k[j] * y[j] ** 2 for j in active)
        det = k0 * k2 - k1 * k1
        u = (-force * k2 + moment * k1) / det
        s = (-moment * k0 + force * k1) / det
        new = {j for j in range(ny + 1) if u + s * y[j] <= 0}
        if new == active:
            return u, u + s * b, force, moment, max(active)
        active = new
    raise RuntimeError("active set did not settle")


def deck_constant(text, name):
    m = re.search(r"^%s\s*=\s*(-?[0-9.]+)\s*/\s*([0-9.]+)\s*$" % name, text, re.M)
    if not m:
        raise SystemExit("rigid_bed_solide: %s = <num>/<den> not found in the deck" % name)
    return Fr(m.group(1)) / Fr(m.group(2))


def main():
    if len(sys.argv) not in (2, 3):
        raise SystemExit(__doc__)
    u_a, u_b, force, moment, last = rigid_bed()
    print("exact: U_A = %s, U_B = %s, F = %s, M = %s, rows 0..%d in contact"
          % (u_a, u_b, force, moment, last))
    text = open(sys.argv[1], encoding="utf-8").read()
    ok = True
    for name, value in (("U_A", u_a), ("U_B", u_b)):
        got = deck_constant(text, name)
        print("deck:  %s = %s %s" % (name, got, "OK" if got == value else "DIFFERS"))
        ok = ok and got == value
    if len(sys.argv) == 3 and os.path.isfile(sys.argv[2]):
        out = subprocess.run([sys.executable, sys.argv[2], "--load", "nodes"],
                             capture_output=True, text=True, check=True).stdout
        for name, value in (("UA", u_a), ("UB", u_b)):
            m = re.search(r"^%s = (-?\d+)/(\d+)" % name, out, re.M)
            got = Fr(int(m.group(1)), int(m.group(2))) if m else None
            print("shared rigid_bed_ref.py: %s = %s %s"
                  % (name, got, "OK" if got == value else "DIFFERS"))
            ok = ok and got == value
    else:
        print("cross-check with ../shared/tools/rigid_bed_ref.py skipped: not found")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()

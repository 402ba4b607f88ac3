#!/usr/bin/env python3
"""The orders of convergence of tests/fields/navier_plate.comm, measured from its .resu: for
each mesh (LEGENDE 'DKQ NxN') the error of the centre deflection and of EFGE_NOEU MXX
against Navier's series (VALE_REFE), and the order log2(e_h / e_h/2) between successive
meshes. Passes when the last two orders of both are within [1.8, 2.6] (O(h^2)).
Usage: navier_convergence.py RESU_FILE"""
import math
import re
import sys

text = open(sys.argv[1], encoding="utf-8").read()
blocks = re.findall(r" ---- RESULTAT .*\n +\S+ +\d+ +(\S+) +(\S+) +\S+\n.*\n"
                    r" *(?:OK|NOOK) +NON_REGRESSION.*\n"
                    r" *(?:OK|NOOK) +ANALYTIQUE +DKQ (\d+)x\d+ +(\S+) +(\S+)", text)
errors = {}
for field, cmp, n, refe, calc in blocks:
    errors.setdefault((field, cmp), {})[int(n)] = abs(float(calc) - float(refe)) / abs(float(refe))
failures = []
for key in (("DEPL", "DZ"), ("EFGE_NOEU", "MXX")):
    e = errors.get(key, {})
    sizes = sorted(e)
    if sizes != [4, 8, 16, 32]:
        failures.append("%s %s: meshes %s" % (key[0], key[1], sizes))
        continue
    orders = [math.log2(e[a] / e[b]) for a, b in zip(sizes, sizes[1:])]
    print("%s %s: errors %s, orders %s" % (key[0], key[1],
          " ".join("%.3e" % e[s] for s in sizes), " ".join("%.2f" % o for o in orders)))
    if not all(1.8 <= o <= 2.6 for o in orders[-2:]):
        failures.append("%s %s: orders %s, not O(h^2)" % (key[0], key[1], orders))
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)

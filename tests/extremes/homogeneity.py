#!/usr/bin/python3
"""Homogeneity in the load over 20 decades (tests/extremes, doc/stability.md).

usage: homogeneity.py PARASOL WORKDIR

Runs the nominal model B deck (p = 5) and the load-scaled ones (p = 5e-10 .. 5e10, 5e200)
of cases/ and checks that every displacement divided by p/5 equals the nominal one to
RTOL (the printed 13 digits, plus round-off), and that the number of Newton iterations is
the same: the answer is positively homogeneous of degree 1 in the load (ssnl130.md), and
every test and criterion of the computation is relative, so it scales with the load.
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = [("b_E2e11", 5.0), ("b_p5e-10", 5e-10), ("b_p5e-5", 5e-5), ("b_p5e5", 5e5),
         ("b_p5e10", 5e10), ("b_p5e200", 5e200)]
RTOL = 1e-12
VALUE = re.compile(r"DEPL DY (PT0\d): OK ANALYTIQUE \S+ \S+ (\S+) ")


def measure(parasol, work, name):
    deck = os.path.join(HERE, "cases", name + ".comm")
    mesh = os.path.join(HERE, "cases", "b16.mail")
    r = subprocess.run([parasol, "--unit", f"20={mesh}", "--outdir", work, deck],
                       capture_output=True, text=True, timeout=60)
    with open(os.path.join(work, name + ".mess"), encoding="utf-8") as f:
        mess = f.read()
    values = {m[0]: float(m[1]) for m in VALUE.findall(mess)}
    iterations = re.findall(r"converged in (\d+) iteration", mess)
    return r.returncode, values, iterations


def main(argv):
    parasol, work = argv[1], argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []
    base = None
    for name, p in CASES:
        rc, values, its = measure(parasol, work, name)
        if rc != 0 or sorted(values) != ["PT01", "PT02"]:
            failures.append(f"{name}: exit {rc}, values {values}")
            continue
        scaled = {k: v / (p / 5.0) for k, v in values.items()}
        if base is None:
            base = (scaled, its)
        worst = max(abs(scaled[k] / base[0][k] - 1.0) for k in scaled)
        print(f"{name}: u / (p/5) = {scaled}, iterations {its}, relative difference {worst:.1e}")
        if worst > RTOL:
            failures.append(f"{name}: u / (p/5) differs from p = 5 by {worst:.1e} > {RTOL}")
        if its != base[1]:
            failures.append(f"{name}: iterations {its} instead of {base[1]}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

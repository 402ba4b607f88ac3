#!/usr/bin/env python3
"""Model-layer deck tests (LIRE_MAILLAGE .. AFFE_CARA_ELEM), run by CTest.

usage:
  run_model_case.py error PARASOL DECK WORKDIR [--unit 20=PATH]
      The deck's first lines hold `# expect: L:C: error: CMD/KEY:` (checked as
      `DECK.comm:L:C: ...` on stderr; text not starting with a digit is searched as is)
      and `# phrase: ...`; `# mesh: PATH` (relative to the deck) binds unit 20. Passes when parasol exits 1 with both on stderr, no crash.
  run_model_case.py same-tables PARASOL WORKDIR DECK1 MESH1 DECK2 MESH2 EQUATIONS
      Runs both decks (mesh bound to unit 20); their INFO=2 RIGI_PARASOL tables in the
      .mess must be identical and non-empty, and both must report EQUATIONS equations.
  run_model_case.py weights PARASOL WORKDIR DECK MESH EQUATIONS END INTERIOR K
      The RIGI_PARASOL weights must be END (first and last spring) and INTERIOR (the
      others), the stiffnesses K x weight, the sum 1, and the model EQUATIONS equations.
"""
import os
import subprocess
import sys
from fractions import Fraction

CRASH_SIGNS = ("Fortran runtime error", "Backtrace", "ERROR STOP", "Segmentation",
               "double free", "Program received signal")


def run(parasol, deck, workdir, unit=None):
    os.makedirs(workdir, exist_ok=True)
    cmd = [os.path.abspath(parasol), "--outdir", os.path.abspath(workdir)]
    if unit:
        cmd += ["--unit", unit]
    cmd.append(os.path.basename(deck))
    proc = subprocess.run(cmd, cwd=os.path.dirname(os.path.abspath(deck)),
                          capture_output=True, timeout=60)
    return proc.returncode, proc.stderr.decode("utf-8", "replace")


def mess_of(workdir, deck):
    stem = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(workdir, stem + ".mess"), encoding="utf-8") as f:
        return f.read().splitlines()


def table(lines):
    return [l for l in lines if l.startswith("RIGI_PARASOL ")]


def equations(lines):
    found = [l.split()[1] for l in lines if l.strip().startswith("equations ")]
    return int(found[-1]) if found else None


def case_error(argv):
    parasol, deck, workdir = argv[:3]
    unit = argv[argv.index("--unit") + 1] if "--unit" in argv else None
    expect = phrase = None
    with open(deck, encoding="utf-8") as f:
        for line in f.read().splitlines()[:5]:
            if line.startswith("# expect:"):
                expect = line[len("# expect:"):].strip()
            elif line.startswith("# phrase:"):
                phrase = line[len("# phrase:"):].strip()
            elif line.startswith("# mesh:") and unit is None:
                unit = "20=" + os.path.join(os.path.dirname(os.path.abspath(deck)),
                                            line[len("# mesh:"):].strip())
    if expect and expect[0].isdigit():
        expect = os.path.basename(deck) + ":" + expect
    rc, err = run(parasol, deck, workdir, unit)
    problems = []
    if rc != 1:
        problems.append("exit status %d, expected 1" % rc)
    if expect is None or expect not in err:
        problems.append("stderr lacks %r" % expect)
    if phrase and phrase not in err:
        problems.append("stderr lacks the phrase %r" % phrase)
    problems += ["crash sign: " + s for s in CRASH_SIGNS if s in err]
    return problems, err


def case_same_tables(argv):
    parasol, workdir, deck1, mesh1, deck2, mesh2, n_eq = argv[:7]
    problems, tables, err = [], [], ""
    for k, (deck, mesh) in enumerate(((deck1, mesh1), (deck2, mesh2))):
        out = os.path.join(workdir, str(k))
        rc, e = run(parasol, deck, out, "20=" + os.path.abspath(mesh))
        err += e
        if rc != 0:
            problems.append("%s: exit status %d" % (deck, rc))
            continue
        lines = mess_of(out, deck)
        tables.append(table(lines))
        if equations(lines) != int(n_eq):
            problems.append("%s: %s equations, expected %s" % (deck, equations(lines), n_eq))
    if len(tables) == 2:
        if not tables[0]:
            problems.append("no RIGI_PARASOL lines in the .mess")
        if tables[0] != tables[1]:
            diff = [(a, b) for a, b in zip(tables[0], tables[1]) if a != b][:3]
            problems.append("tables differ (%d vs %d lines): %r"
                            % (len(tables[0]), len(tables[1]), diff))
    return problems, err


def case_weights(argv):
    parasol, workdir, deck, mesh, n_eq, end, interior, k_total = argv[:8]
    rc, err = run(parasol, deck, workdir, "20=" + os.path.abspath(mesh))
    if rc != 0:
        return ["exit status %d" % rc], err
    lines = mess_of(workdir, deck)
    problems = []
    if equations(lines) != int(n_eq):
        problems.append("%s equations, expected %s" % (equations(lines), n_eq))
    rows = [l.split() for l in table(lines) if "SUM_OF_WEIGHTS" not in l]
    sums = [l.split() for l in table(lines) if "SUM_OF_WEIGHTS" in l]
    if len(rows) < 3:
        return problems + ["only %d springs in the table" % len(rows)], err
    for i, row in enumerate(rows):
        expected = float(Fraction(end if i in (0, len(rows) - 1) else interior))
        weight = float(row[3])
        if abs(weight - expected) > 1e-12 * expected:
            problems.append("%s: weight %s, expected %r" % (row[1], row[3], expected))
        for k in row[4:]:
            if abs(float(k) - float(k_total) * expected) > 1e-9 * float(k_total) * expected \
                    and float(k) != 0.0:
                problems.append("%s: stiffness %s, expected %r"
                                % (row[1], k, float(k_total) * expected))
    if not sums or abs(float(sums[0][2]) - 1.0) > 1e-12:
        problems.append("sum of weights is not 1: %r" % sums)
    return problems, err


def main(argv):
    mode, rest = argv[1], argv[2:]
    problems, err = {"error": case_error, "same-tables": case_same_tables,
                     "weights": case_weights}[mode](rest)
    if problems:
        print("FAIL: " + "; ".join(problems))
        print("stderr was:\n" + err)
        return 1
    print("ok" + (": " + err.strip() if err.strip() else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

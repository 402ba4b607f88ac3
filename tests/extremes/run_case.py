#!/usr/bin/python3
"""Run one extremes deck and check its stated outcome (tests/extremes, doc/stability.md).

usage: run_case.py PARASOL DECK WORKDIR

The deck's first lines state what it expects (written by make_cases.py):
    # mesh: NAME.mail    # expect-exit: N    # expect: REGEX (exit 1)
The test passes when parasol's exit status is N, nothing crashed, and
  - exit 1: stderr is one error line matching REGEX;
  - exit 2: the .mess has a NOOK ANALYTIQUE line (a limit stated, not hidden);
  - exit 0: stderr is empty, the .mess verdict has no NOOK, and every ANALYTIQUE TEST_RESU
    line agrees with its reference within its own PRECISION, recomputed here from the
    printed values (so an OK can never hide a wrong value).
"""
import os
import re
import subprocess
import sys

CRASH_SIGNS = ("Fortran runtime error", "Backtrace", "ERROR STOP", "Segmentation",
               "Program received signal", "Floating-point exception")
TEST_LINE = re.compile(r"TEST_RESU .*: (OK|NOOK) ANALYTIQUE \S+ (\S+) (\S+) (\S+)% (\S+)%")


def header(deck):
    info = {}
    with open(deck, encoding="utf-8") as f:
        for line in f:
            m = re.match(r"# (mesh|expect-exit|expect|why): (.*)", line.rstrip("\n"))
            if not m:
                break
            info[m.group(1)] = m.group(2)
    return info


def check_values(mess):
    """Problems with the ANALYTIQUE lines of the .mess (recomputed relative errors)."""
    problems, n = [], 0
    for line in mess.splitlines():
        m = TEST_LINE.search(line)
        if not m:
            continue
        n += 1
        verdict, ref, val, tol = m.group(1), float(m.group(2)), float(m.group(3)), \
            float(m.group(5)) / 100
        # printed with 13 significant digits: allow that rounding on top of the tolerance
        err = abs(val - ref)
        ok = err <= tol * abs(ref) + 1e-12 * max(abs(ref), abs(val)) if ref != 0 else \
            err <= tol
        if verdict == "OK" and not ok:
            problems.append("OK printed for a value outside its tolerance: " + line.strip())
        if verdict == "NOOK":
            problems.append(line.strip())
    if n == 0:
        problems.append("no ANALYTIQUE TEST_RESU line in the .mess")
    return problems


def main(argv):
    parasol, deck, workdir = argv[1:4]
    info = header(deck)
    os.makedirs(workdir, exist_ok=True)
    mesh = os.path.join(os.path.dirname(os.path.abspath(deck)), info["mesh"])
    run = subprocess.run([parasol, "--unit", f"20={mesh}", "--outdir", workdir, deck],
                         capture_output=True, text=True, timeout=120)
    out = run.stdout + run.stderr
    failures = []
    if any(sign in out for sign in CRASH_SIGNS):
        failures.append("crash")
    want = int(info["expect-exit"])
    if run.returncode != want:
        failures.append(f"exit status {run.returncode}, expected {want}")
    if want == 1:
        lines = [l for l in run.stderr.splitlines() if l.strip()]
        if len(lines) != 1 or not re.search(info["expect"], lines[0]):
            failures.append(f"error line does not match /{info['expect']}/")
    elif want == 2:
        stem = os.path.splitext(os.path.basename(deck))[0]
        with open(os.path.join(workdir, stem + ".mess"), encoding="utf-8") as f:
            if not any("NOOK" in p for p in check_values(f.read())):
                failures.append("exit 2 without a NOOK line")
    else:
        if run.stderr.strip():
            failures.append("unexpected stderr")
        stem = os.path.splitext(os.path.basename(deck))[0]
        with open(os.path.join(workdir, stem + ".mess"), encoding="utf-8") as f:
            failures += check_values(f.read())
    if failures:
        print(f"{os.path.basename(deck)}: expected: {info.get('why', '')}")
        print(out)
        for f in failures:
            print("FAIL:", f)
        return 1
    print(f"{os.path.basename(deck)}: as expected (exit {want}): {info.get('why', '')}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

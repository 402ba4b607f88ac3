#!/usr/bin/env python3
"""Runs one deck of the table tests and checks what it produced.

usage: run_table_case.py PARASOL DIFF DECK WORKDIR [--ref REF] [--unit N=PATH ...]
                         [--loadtxt UNIT:COLUMNS:EXPECTED] [--same UNIT=REF ...]

The deck must exit 0 (every TEST_TABLE / TEST_RESU line OK); with --ref its .resu must
equal REF (parasol-diff, default tolerances); with --loadtxt the file the deck wrote on
UNIT (<stem>.<UNIT> in WORKDIR) must read with numpy.loadtxt (comments '#') into an array
whose columns COLUMNS (comma separated indices) equal EXPECTED (a Python literal: a list of
rows), exactly; with --same the file the deck wrote on UNIT must equal REF, byte for byte
(files a plotter reads, whose layout is the point).
"""
import argparse
import ast
import os
import shutil
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("parasol")
    parser.add_argument("diff")
    parser.add_argument("deck")
    parser.add_argument("workdir")
    parser.add_argument("--ref")
    parser.add_argument("--unit", action="append", default=[])
    parser.add_argument("--loadtxt", action="append", default=[])
    parser.add_argument("--same", action="append", default=[])
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    cmd = [args.parasol, "--quiet", "--outdir", args.workdir, args.deck]
    for unit in args.unit:
        cmd += ["--unit", unit]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    sys.stdout.write(run.stdout + run.stderr)
    if run.returncode != 0:
        print("FAIL: parasol exited with %d (expected 0)" % run.returncode)
        return 1
    stem = os.path.splitext(os.path.basename(args.deck))[0]
    resu = os.path.join(args.workdir, stem + ".resu")
    if args.ref:
        diff = subprocess.run([args.diff, resu, args.ref], capture_output=True, text=True)
        sys.stdout.write(diff.stdout + diff.stderr)
        if diff.returncode != 0:
            print("FAIL: %s differs from %s" % (resu, args.ref))
            return 1
    for spec in args.loadtxt:
        unit, columns, expected = spec.split(":", 2)
        import numpy
        data = numpy.loadtxt(os.path.join(args.workdir, "%s.%s" % (stem, unit)),
                             comments="#", ndmin=2)
        cols = [int(c) for c in columns.split(",")]
        want = numpy.array(ast.literal_eval(expected), dtype=float)
        got = data[:, cols]
        if got.shape != want.shape or not (got == want).all():
            print("FAIL: unit %s read by numpy.loadtxt:\n%s\nexpected\n%s" % (unit, got, want))
            return 1
        print("unit %s read by numpy.loadtxt: %d rows equal, bit for bit" % (unit, len(got)))
    for spec in args.same:
        unit, ref = spec.split("=", 1)
        path = os.path.join(args.workdir, "%s.%s" % (stem, unit))
        with open(path, "rb") as got, open(ref, "rb") as want:
            if got.read() != want.read():
                print("FAIL: %s differs from %s" % (path, ref))
                subprocess.run(["diff", path, ref])
                return 1
        print("unit %s equals %s" % (unit, os.path.basename(ref)))
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())

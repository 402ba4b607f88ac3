#!/usr/bin/env python3
"""Runs one of Code_Aster's own SSNL130 tests as run_aster does: parasol CASE.export.

usage: run_aster_case.py PARASOL ASTER_DIR CASE EXPECTED_LINES WORKDIR

ASTER_DIR is the folder of Code_Aster's test files (doc/aster-tests.md; CMake cache
variable PARASOL_ASTER_DIR, default: the folder shared/aster beside the source tree). When
ASTER_DIR/ssnl130/CASE.export is absent the test is skipped (exit 77, CTest's
SKIP_RETURN_CODE) with a message. Otherwise parasol runs it in WORKDIR (the files stay
where they are, read-only) and the test asserts that the export ran to the end and
passed, as Code_Aster's test suite requires: exit status 0, every command file evaluated to
its FIN, the listings written, and EXPECTED_LINES TEST_RESU check lines in the .resu, every
one OK (NON_REGRESSION against Code_Aster's VALE_CALC included, issue 11).
"""
import os
import re
import subprocess
import sys

SKIP = 77


def main(argv):
    parasol, aster_dir, case, expected, workdir = argv[1:6]
    export = os.path.join(aster_dir, "ssnl130", case + ".export")
    if not os.path.isfile(export):
        print("skipped: %s not found (Code_Aster's test files are not here; set the CMake "
              "variable PARASOL_ASTER_DIR to their folder)" % export)
        return SKIP
    os.makedirs(workdir, exist_ok=True)
    with open(export) as f:
        n_comm = sum(1 for line in f if re.match(r"\s*F\s+comm\s", line))
    run = subprocess.run([os.path.abspath(parasol), "--outdir", workdir,
                          os.path.abspath(export)], cwd=workdir, capture_output=True,
                         timeout=300)
    err = run.stderr.decode("utf-8", "replace")
    problems = []
    if run.returncode != 0:
        problems.append("exit status %d (1 = stopped on an error, 2 = some TEST_RESU NOOK)"
                        % run.returncode)
    mess = os.path.join(workdir, case + ".mess")
    resu = os.path.join(workdir, case + ".resu")
    ok = nook = 0
    if os.path.exists(mess):
        with open(mess, encoding="utf-8", errors="replace") as f:
            ends = f.read().count("-> end of the deck")
        if ends != n_comm:
            problems.append("%d of %d command files ran to their FIN()" % (ends, n_comm))
    else:
        problems.append("no .mess written")
    if os.path.exists(resu):
        with open(resu) as f:
            for line in f:
                ok += line.startswith(" OK ")
                nook += line.startswith("NOOK ")
        if ok + nook != int(expected):
            problems.append("%d TEST_RESU check lines, expected %s" % (ok + nook, expected))
        if nook:
            problems.append("%d NOOK line(s)" % nook)
    else:
        problems.append("no .resu written")
    summary = "%s: exit %d, %d OK, %d NOOK" % (case, run.returncode, ok, nook)
    if problems:
        print("FAIL " + summary + ": " + "; ".join(problems))
        print("stderr was:\n" + err)
        return 1
    print("ok " + summary)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

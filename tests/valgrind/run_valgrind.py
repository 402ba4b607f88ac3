#!/usr/bin/env python3
"""One parasol run under valgrind's memcheck (CTest valgrind.*, doc/stability.md).

usage: run_valgrind.py PARASOL WORKDIR EXPECTED_EXIT DECK [parasol options...]

Passes when parasol exits with EXPECTED_EXIT (0 for a deck that runs, 1 for an error deck)
and memcheck reports no error: no invalid read or write, no use of uninitialised values, no
definite leak (--errors-for-leak-kinds=definite; the only suppression is ld_so.supp, the
dynamic loader's word-wise strncmp). Exit 77 (skipped) when valgrind is not installed:
scripts/install-deps.sh installs it, and .ci/run runs these tests through scripts/test.sh.
"""
import os
import re
import shutil
import subprocess
import sys

SKIP = 77
VALGRIND_ERROR = 99


def main(argv):
    parasol, workdir, expected, deck = argv[1], argv[2], int(argv[3]), argv[4]
    options = argv[5:]
    valgrind = shutil.which("valgrind")
    if not valgrind:
        print("SKIPPED: valgrind is not installed (scripts/install-deps.sh installs it)")
        return SKIP
    os.makedirs(workdir, exist_ok=True)
    supp = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ld_so.supp")
    cmd = [valgrind, "--tool=memcheck", "--leak-check=full", "--show-leak-kinds=definite",
           "--errors-for-leak-kinds=definite", "--error-exitcode=%d" % VALGRIND_ERROR,
           "--track-origins=yes", "--num-callers=30", "--suppressions=" + supp,
           os.path.abspath(parasol), "--outdir", os.path.abspath(workdir)] + options + \
        [os.path.abspath(deck)]
    run = subprocess.run(cmd, cwd=workdir, capture_output=True, timeout=1800)
    err = run.stderr.decode("utf-8", "replace")
    summary = re.findall(r"==\d+== (ERROR SUMMARY: .*|\s+definitely lost: .*)", err)
    problems = []
    if run.returncode == VALGRIND_ERROR:
        problems.append("memcheck found errors")
    elif run.returncode != expected:
        problems.append("exit status %d, expected %d" % (run.returncode, expected))
    if not any(s.startswith("ERROR SUMMARY: 0 errors") for s in summary):
        problems.append("no clean ERROR SUMMARY")
    if problems:
        print("FAIL %s: %s\n%s" % (os.path.basename(deck), "; ".join(problems), err[-20000:]))
        return 1
    print("ok %s: exit %d, %s" % (os.path.basename(deck), run.returncode,
                                 "; ".join(s.strip() for s in summary)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

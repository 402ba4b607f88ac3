#!/usr/bin/env python3
"""One case of Code_Aster's astest conformance run (doc/aster-tests.md, "The conformance run").

usage: astest_case.py PARASOL ASTER_DIR CASE WORKDIR PASSING_FILE [--timeout S]

Runs `parasol --outdir WORKDIR ASTER_DIR/astest/CASE.export` unchanged, as run_aster runs
a test, and judges it as Code_Aster's test suite does: the case PASSES when parasol exits 0,
every command file of the export ran to its FIN(), and the run counted at least one test
line (TEST_RESU, TEST_TABLE, TEST_FONCTION ...) and every one of them is OK. Otherwise its
first error is the first located `error:` line parasol wrote (or the time limit, or the
first NOOK line).

The verdict against the ratchet tests/astest/passing.txt (PASSING_FILE):
  listed and passing        -> exit 0
  listed and not passing    -> exit 1 (a regression: the suite fails)
  not listed and passing    -> exit 1, saying to add it to passing.txt (so that a case once
                               made to pass is kept passing: the ratchet only moves up)
  not listed, not passing   -> exit 77 (CTest's SKIP_RETURN_CODE: not expected to pass yet),
                               printing the first error
A missing ASTER_DIR/astest is a skip (exit 77) with a message. The judgement is written to
WORKDIR/result.json, which report.py reads to write doc/aster-tests.md.
"""
import json
import os
import re
import subprocess
import sys
import time

SKIP = 77
#: wall-clock limit of one case (s): parasol also applies the export's own `P time_limit`
#: (60 s for most of these cases); this one stops a run that would hang past it.
DEFAULT_TIMEOUT = 300.0


def read_passing(path):
    """The case names of the ratchet file (one per line, # comments)."""
    names = []
    if os.path.isfile(path):
        with open(path) as f:
            for line in f:
                line = line.split("#", 1)[0].strip()
                if line:
                    names.append(line)
    return names


def command_files(export):
    """The number of `F comm` lines of an export file."""
    with open(export, encoding="utf-8", errors="replace") as f:
        return sum(1 for line in f if re.match(r"\s*F\s+comm\s", line))


def first_error_line(stderr, aster_dir):
    """The first located `error:` line of stderr, paths into ASTER_DIR shortened."""
    for line in stderr.splitlines():
        if "error:" in line:
            return shorten(line.strip(), aster_dir)
    return ""


def shorten(text, aster_dir):
    """Drops the folder of Code_Aster's files from paths: `ssls11a.comm:135:22: ...`."""
    for folder in (os.path.join(os.path.abspath(aster_dir), "astest") + os.sep,
                   os.path.abspath(aster_dir) + os.sep):
        text = text.replace(folder, "")
    return text


def category(error):
    """The kind of a first error, for the counts of doc/aster-tests.md: the message without
    its location, its values and its hints (`unknown command DEFI_GROUP`,
    `AFFE_CHAR_MECA/LIAISON_DDL: unknown keyword`, ...)."""
    text = error
    m = re.search(r"error:\s*(.*)", text)
    if m:
        text = m.group(1)
    while True:                                      # hints: (did you mean ...), (valid ...)
        shorter = re.sub(r"\s*\([^()]*\)", "", text)
        if shorter == text:
            break
        text = shorter
    m = re.match(r"([A-Z_0-9]+(?:/[A-Za-z_0-9]+)*): unknown keyword (\S+)", text)
    if m:
        return "%s: unknown keyword %s" % (m.group(1), m.group(2))
    m = re.match(r"([A-Z_0-9]+(?:/[A-Za-z_0-9]+)*): value '([^']*)' is not allowed", text)
    if m:
        return "%s: value %s not allowed" % (m.group(1), m.group(2))
    text = re.sub(r"'[^']*'", "'...'", text)
    text = re.sub(r"\b\d+(\.\d+)?([eE][-+]?\d+)?\b", "N", text)
    return text.strip()[:90]


def run_case(parasol, aster_dir, case, workdir, timeout=DEFAULT_TIMEOUT):
    """Runs one case; returns its judgement as a dict (see the module's doc)."""
    export = os.path.join(aster_dir, "astest", case + ".export")
    os.makedirs(workdir, exist_ok=True)
    result = {"case": case, "passed": False, "exit": None, "ok": 0, "nook": 0,
              "first_error": "", "category": "", "seconds": 0.0}
    for suffix in (".mess", ".resu"):            # never judge an older run's listings
        if os.path.exists(os.path.join(workdir, case + suffix)):
            os.remove(os.path.join(workdir, case + suffix))
    started = time.monotonic()
    try:
        run = subprocess.run([os.path.abspath(parasol), "--quiet", "--outdir", workdir,
                              os.path.abspath(export)], cwd=workdir, capture_output=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        result["seconds"] = round(time.monotonic() - started, 2)
        result["first_error"] = "no end after %g s (the conformance run's time limit)" % timeout
        result["category"] = "time limit of the conformance run"
        return result
    result["seconds"] = round(time.monotonic() - started, 2)
    result["exit"] = run.returncode
    stderr = run.stderr.decode("utf-8", "replace")
    mess = os.path.join(workdir, case + ".mess")
    resu = os.path.join(workdir, case + ".resu")
    ends = 0
    verdict = None
    if os.path.exists(mess):
        with open(mess, encoding="utf-8", errors="replace") as f:
            text = f.read()
        ends = text.count("-> end of the deck")
        m = re.search(r"^verdict: (\d+) OK, (\d+) NOOK", text, re.M)
        if m:
            verdict = (int(m.group(1)), int(m.group(2)))
    first_nook = ""
    if os.path.exists(resu):
        with open(resu, encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith("NOOK") and not first_nook:
                    first_nook = line.strip()
    if verdict:
        result["ok"], result["nook"] = verdict
    error = first_error_line(stderr, aster_dir)
    crashed = "Fortran runtime error" in stderr or "Program received signal" in stderr
    if run.returncode < 0 or run.returncode > 2 or crashed:
        error = "crashed (exit %d): %s" % (run.returncode, stderr.strip()[-300:])
        result["category"] = "crash"
    elif run.returncode == 2:
        error = "NOOK: %d of %d test lines (first: %s)" % (
            result["nook"], result["ok"] + result["nook"], first_nook)
        result["category"] = "test lines NOOK"
    elif run.returncode == 0:
        n_comm = command_files(export)
        if ends != n_comm:
            error = "%d of %d command files ran to their FIN()" % (ends, n_comm)
            result["category"] = "command files not run to FIN"
        elif result["ok"] == 0:
            error = "no test line (TEST_RESU, TEST_TABLE, ...) was checked"
            result["category"] = "no test line"
        elif result["nook"] > 0:
            error = "%d NOOK test line(s) with exit status 0" % result["nook"]
            result["category"] = "test lines NOOK"
        else:
            result["passed"] = True
    elif not error:
        error = "exit status %d without an error line" % run.returncode
    result["first_error"] = error
    return result


def kind_of(result):
    """The kind of a result's first error: a fixed kind (time limit, crash, NOOK ...) or the
    category of its error line."""
    return result.get("category") or category(result.get("first_error", ""))


def main(argv):
    args = argv[1:]
    timeout = DEFAULT_TIMEOUT
    if "--timeout" in args:
        k = args.index("--timeout")
        timeout = float(args[k + 1])
        del args[k:k + 2]
    if len(args) != 5:
        print(__doc__)
        return 2
    parasol, aster_dir, case, workdir, passing_file = args
    export = os.path.join(aster_dir, "astest", case + ".export")
    if not os.path.isfile(export):
        print("skipped: %s not found (Code_Aster's test files are not here; set the CMake "
              "variable PARASOL_ASTER_DIR to their folder)" % export)
        return SKIP
    listed = case in read_passing(passing_file)
    result = run_case(parasol, aster_dir, case, workdir, timeout)
    result["listed"] = listed
    with open(os.path.join(workdir, "result.json"), "w") as f:
        json.dump(result, f, indent=1)
    summary = "%s: exit %s, %d OK, %d NOOK, %.1f s" % (
        case, result["exit"], result["ok"], result["nook"], result["seconds"])
    if result["passed"] and listed:
        print("ok " + summary)
        return 0
    if result["passed"]:
        print("NEW PASS " + summary + ": the case passes and is not in " + passing_file +
              ": add it there (the ratchet keeps it passing)")
        return 1
    if listed:
        print("REGRESSION " + summary + ": listed in " + passing_file + " but " +
              result["first_error"])
        return 1
    print("not passing yet (not in passing.txt): " + summary + ": " + result["first_error"])
    return SKIP


if __name__ == "__main__":
    sys.exit(main(sys.argv))

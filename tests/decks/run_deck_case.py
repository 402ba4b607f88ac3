#!/usr/bin/env python3
"""Runs one deck of the parasol deck corpus and checks the outcome.

usage: run_deck_case.py PARASOL DECK WORKDIR [--check] [--generate KIND]
                        [--expect-exit N] [--expect 'L:C: error: TEXT'] [--phrase TEXT]
       run_deck_case.py PARASOL --missing-deck NAME WORKDIR

A bad deck states what it expects in its first lines:
    # expect: 12:5: error: AFFE_MODELE/AFFE/MODELISATION:
    # phrase: did you mean DKT?
The test passes when parasol exits with status 1 within 1 s, stderr contains
`NAME.comm:12:5: error: AFFE_MODELE/AFFE/MODELISATION:` and the phrase, and no sign of a
crash ("Fortran runtime error", "Backtrace", "ERROR STOP", "Segmentation"). A good deck
(no expect line, or --expect-exit 0) must exit 0 with an empty stderr.
The hostile-input corpus (tests/decks/hostile) adds, in the first ten lines:
    # expect: mesh.msh:17: error: LIRE_MAILLAGE:   (not starting with a digit: taken as is,
                                                     for errors located in a mesh file)
    # mesh: ../../../decks/ssnl130b.mail             (bound to unit 20, relative to the deck)
    # expect-exit: 0                                  (a deck that must run, e.g. a warning)
    # warning: warped beyond                          (a located warning expected on stderr)
    # seconds: 10                                     (a longer limit than 1 s)
--missing-deck: NAME does not exist: exit 1, "cannot open the deck", and no listing at all
(no NAME.mess, NAME.resu or temporary in WORKDIR).
--generate KIND writes the deck first (big or binary inputs are not committed):
empty, binary, long_line (1 MB), deep_parens (10 000 nested parentheses).
"""
import glob
import os
import subprocess
import sys
import time

CRASH_SIGNS = ("Fortran runtime error", "Backtrace", "ERROR STOP", "Segmentation",
               "double free", "Program received signal")


def generate(kind, path):
    if kind == "empty":
        data = b""
    elif kind == "binary":
        data = b"# expect: 3:3: error: \n# phrase: NUL byte\n\x7fE\x00\x01\x02\xff binary\n"
    elif kind == "long_line":
        data = (b"# expect: 3:5: error: \n# phrase: unterminated string\nx = '"
                + b"a" * (1 << 20) + b"\nFIN()\n")
    elif kind == "deep_parens":
        data = (b"# expect: 3:205: error: \n# phrase: nested deeper than 200\nx = "
                + b"(" * 10000 + b"1" + b")" * 10000 + b"\n")
    else:
        raise SystemExit("unknown --generate kind " + kind)
    with open(path, "wb") as f:
        f.write(data)


def expectations(path):
    """The `# key: value` header lines of a deck (first ten lines)."""
    found = {}
    with open(path, "rb") as f:
        head = f.read(4096).decode("utf-8", "replace").splitlines()[:10]
    for line in head:
        for key in ("expect", "phrase", "mesh", "expect-exit", "warning", "seconds"):
            if line.startswith("# %s:" % key):
                found[key] = line[len("# %s:" % key):].strip()
    return found


def missing_deck(parasol, name, workdir):
    """A deck that does not exist: exit 1 with the reason, and no listing written."""
    os.makedirs(workdir, exist_ok=True)
    run = subprocess.run([os.path.abspath(parasol), "--outdir", os.path.abspath(workdir),
                          name], cwd=workdir, capture_output=True, timeout=30)
    err = run.stderr.decode("utf-8", "replace")
    problems = []
    if run.returncode != 1:
        problems.append("exit status %d, expected 1" % run.returncode)
    if "cannot open the deck " + name not in err or "No such file" not in err:
        problems.append("stderr lacks the deck and the system's reason")
    left = [f for f in os.listdir(workdir) if f.startswith(os.path.splitext(name)[0])]
    if left:
        problems.append("files were written for a deck that could not be opened: " +
                        " ".join(left))
    if problems:
        print("FAIL " + name + ": " + "; ".join(problems) + "\nstderr was:\n" + err)
        return 1
    print("ok " + name + ": " + err.strip())
    return 0


def main(argv):
    if argv[2] == "--missing-deck":
        return missing_deck(argv[1], argv[3], argv[4])
    parasol, deck, workdir = argv[1], argv[2], argv[3]
    opts = argv[4:]
    check = "--check" in opts
    expect = phrase = None
    expect_exit = None
    for flag in ("--generate", "--expect", "--phrase", "--expect-exit"):
        if flag in opts:
            value = opts[opts.index(flag) + 1]
            if flag == "--generate":
                os.makedirs(os.path.dirname(os.path.abspath(deck)), exist_ok=True)
                generate(value, deck)
            elif flag == "--expect":
                expect = value
            elif flag == "--phrase":
                phrase = value
            else:
                expect_exit = int(value)
    head = expectations(deck)
    expect = expect or head.get("expect")
    phrase = phrase or head.get("phrase")
    warning = head.get("warning")
    limit = float(head.get("seconds", "1"))
    if expect_exit is None and "expect-exit" in head:
        expect_exit = int(head["expect-exit"])
    if expect_exit is None:
        expect_exit = 1 if expect else 0
    os.makedirs(workdir, exist_ok=True)
    name = os.path.basename(deck)
    stem = os.path.splitext(name)[0]
    old_resu = os.path.join(workdir, stem + ".resu")
    if expect and not check:
        # a failed run must leave an older .resu untouched
        with open(old_resu, "w") as f:
            f.write("OLD RESULT\n")
    cmd = [os.path.abspath(parasol), "--outdir", os.path.abspath(workdir)]
    if check:
        cmd.append("--check")
    if "mesh" in head:
        cmd += ["--unit", "20=" + head["mesh"]]
    cmd.append(name)
    start = time.monotonic()
    run = subprocess.run(cmd, cwd=os.path.dirname(os.path.abspath(deck)),
                         capture_output=True, timeout=30)
    elapsed = time.monotonic() - start
    err = run.stderr.decode("utf-8", "replace")
    problems = []
    if run.returncode != expect_exit:
        problems.append("exit status %d, expected %d" % (run.returncode, expect_exit))
    if elapsed > limit:
        problems.append("took %.2f s (limit %g s)" % (elapsed, limit))
    for sign in CRASH_SIGNS:
        if sign in err:
            problems.append("crash sign on stderr: " + sign)
    if warning and warning not in err:
        problems.append("stderr lacks the warning " + repr(warning))
    if expect:
        prefix = name + ":" + expect if expect[:1].isdigit() else expect
        if prefix not in err:
            problems.append("stderr lacks " + repr(prefix))
        if phrase and phrase not in err:
            problems.append("stderr lacks the phrase " + repr(phrase))
        if not check:
            with open(old_resu) as f:
                if f.read() != "OLD RESULT\n":
                    problems.append("the older .resu was overwritten by a failed run")
            left = glob.glob(os.path.join(workdir, "*.partial"))
            if left:
                problems.append("temporary files were left behind: " + " ".join(left))
            mess = os.path.join(workdir, stem + ".mess")
            if not os.path.exists(mess):
                problems.append("no .mess was committed for the failed run")
            else:
                with open(mess, encoding="utf-8", errors="replace") as f:
                    if prefix not in f.read():
                        problems.append("the .mess lacks the error message")
    elif err.strip() and not (warning and all("warning: " in line
                                              for line in err.strip().splitlines())):
        problems.append("unexpected stderr")
    if problems:
        print("FAIL " + name + ": " + "; ".join(problems))
        print("stderr was:\n" + err)
        return 1
    print("ok " + name + (": " + err.strip() if err.strip() else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

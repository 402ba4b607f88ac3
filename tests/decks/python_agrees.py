#!/usr/bin/env python3
"""The deck language means what Python means: runs a deck of tests/decks/good with CPython
(DEBUT, FIN and _F stubbed: the deck holds no other command) and with parasol, and compares
what they print (the lines starting with '>>': in the .mess for parasol).

usage: python_agrees.py PARASOL DECK WORKDIR

Both must run to the end (every assert of the deck holds in both); the printed lines must be
identical, text of reals included.
"""
import os
import subprocess
import sys


class _F(dict):
    """Code_Aster's _F: a dict of keyword values."""


def python_lines(deck):
    out = []

    def capture(*args, sep=" ", end="\n"):
        out.append(sep.join(str(a) for a in args) + end)

    names = {"DEBUT": lambda **k: None, "FIN": lambda **k: None, "_F": _F,
             "print": capture, "__name__": "__main__"}
    with open(deck, encoding="utf-8") as f:
        exec(compile(f.read(), deck, "exec"), names)
    return [l for l in "".join(out).split("\n") if l.startswith(">>")]


def main(argv):
    parasol, deck, workdir = argv[1:4]
    os.makedirs(workdir, exist_ok=True)
    expected = python_lines(deck)
    run = subprocess.run([parasol, "--quiet", "--outdir", workdir, deck], capture_output=True,
                         text=True, timeout=60)
    if run.returncode != 0:
        print("FAIL: parasol exit %d\n%s" % (run.returncode, run.stderr))
        return 1
    stem = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(workdir, stem + ".mess"), encoding="utf-8") as f:
        got = [l.rstrip("\n") for l in f if l.startswith(">>")]
    if got != expected:
        print("FAIL: printed lines differ\npython:\n  %s\nparasol:\n  %s" % (
            "\n  ".join(expected), "\n  ".join(got)))
        return 1
    print("ok: %d asserts' deck, %d printed lines identical" % (
        open(deck).read().count("assert "), len(got)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

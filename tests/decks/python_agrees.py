#!/usr/bin/env python3
"""The deck language means what Python means: runs a deck of tests/decks/good with CPython
(DEBUT, FIN and _F stubbed: the deck holds no other command) and with parasol, and compares
what they print (the lines starting with '>>': in the .mess for parasol).

usage: python_agrees.py PARASOL DECK WORKDIR

Both must run to the end (every assert of the deck holds in both); the printed lines must be
identical, text of reals included.

A deck that uses Code_Aster's CA.TestCase runs in CPython with a TestCase built as Code_Aster's
(code_aster/Utilities/Tester.py: unittest's asserts, each writing one OK or NOOK line); its OK,
NOOK and summary lines are compared too. With --nook N the deck must end with N NOOK lines
(parasol's exit status 2, its verdict).
"""
import inspect
import os
import re
import subprocess
import sys
import unittest

RESULT_LINE = re.compile(r"^( OK  | NOOK|NOOK |Ran \d+ tests)")


class TestCase(unittest.TestCase):
    """Code_Aster's CA.TestCase as its Tester.py makes it: the asserts never raise, each
    writes ' OK  {method:>16} passed[ : msg]' or 'NOOK {method:>16} failed[ : why] - FILE#LINE'."""

    out = None      # the capture list, set by python_lines
    _depth = 0      # parasol writes one line per assert the deck calls (Tester.py also
                    # writes one for each assert unittest calls inside: see the doc)

    def __init__(self, methodName="runTest", silent=False):
        self._silent = silent
        self._passed = 0
        self._failure = 0
        self._last_ok = True
        super().__init__("runTest")

    @property
    def last_failed(self):
        return not self._last_ok

    def runTest(self):
        pass

    def printSummary(self):
        self.out.append("-" * 70 + "\n")
        count = self._passed + self._failure
        self.out.append("Ran {0} tests, {1} passed, {2} in failure\n".format(
            count, self._passed, self._failure))
        self.out.append("\nNOOK\n\n" if self._failure else "\n OK \n\n")

    def writeResult(self, ok, funcTest, msg, exc=None):
        if self._silent:
            return
        exc = (exc or "").split("\n")[0]
        msg = msg or ""
        frame = inspect.currentframe().f_back.f_back
        here = "%s#%d" % (frame.f_code.co_filename, frame.f_lineno)
        self._last_ok = ok
        if ok:
            self._passed += 1
            line = " OK  {0:>16} passed{1}{2}".format(funcTest, " : " if msg else "", msg)
        else:
            self._failure += 1
            line = "NOOK {0:>16} failed{1}{2} - {3}".format(funcTest, " : " if exc else "",
                                                             exc, here)
        self.out.append(line + "\n")


def _wrap(name):
    method = getattr(unittest.TestCase, name)
    params = list(inspect.signature(method).parameters)[1:]

    def wrapper(self, *args, **kwds):
        if self._depth:         # an assert unittest calls inside another: no line of its own
            return method(self, *args, **kwds)
        args = list(args)
        if "msg" in params and params.index("msg") < len(args):
            kwds["msg"] = args.pop(params.index("msg"))
        self._depth += 1
        try:
            ret = method(self, *args, **kwds)
        except AssertionError as exc:
            self._depth -= 1
            self.writeResult(False, name, kwds.get("msg"), str(exc))
            return None
        self._depth -= 1
        self.writeResult(True, name, kwds.get("msg"))
        return ret
    return wrapper


for _name in ("assertAlmostEqual assertCountEqual assertDictEqual assertEqual assertFalse "
              "assertGreater assertGreaterEqual assertIn assertIs assertIsInstance "
              "assertIsNone assertIsNot assertIsNotNone assertLess assertLessEqual "
              "assertMultiLineEqual assertNotAlmostEqual assertNotEqual assertNotIn "
              "assertNotIsInstance assertSequenceEqual assertTrue assertTupleEqual "
              "assertListEqual").split():
    setattr(TestCase, _name, _wrap(_name))


class CA:
    """from code_aster import CA (run_aster's header): the tester only."""
    TestCase = TestCase


class _F(dict):
    """Code_Aster's _F: a dict of keyword values."""


def python_lines(deck):
    out = []

    def capture(*args, sep=" ", end="\n"):
        out.append(sep.join(str(a) for a in args) + end)

    TestCase.out = out
    names = {"DEBUT": lambda **k: None, "FIN": lambda **k: None, "_F": _F,
             "print": capture, "__name__": "__main__", "CA": CA}
    with open(deck, encoding="utf-8") as f:
        exec(compile(f.read(), deck, "exec"), names)
    return [l for l in "".join(out).split("\n") if compared(l)]


def compared(line):
    return line.startswith(">>") or RESULT_LINE.match(line) is not None


def main(argv):
    parasol, deck, workdir = argv[1:4]
    nook = int(argv[argv.index("--nook") + 1]) if "--nook" in argv else 0
    os.makedirs(workdir, exist_ok=True)
    expected = python_lines(deck)
    if sum(1 for l in expected if l.startswith("NOOK ")) != nook:
        print("FAIL: CPython wrote %d NOOK lines, expected %d" % (
            sum(1 for l in expected if l.startswith("NOOK ")), nook))
        return 1
    run = subprocess.run([parasol, "--quiet", "--outdir", workdir, deck], capture_output=True,
                         text=True, timeout=60)
    if run.returncode != (2 if nook else 0):
        print("FAIL: parasol exit %d\n%s" % (run.returncode, run.stderr))
        return 1
    stem = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(workdir, stem + ".mess"), encoding="utf-8") as f:
        got = [l.rstrip("\n") for l in f if compared(l)]
    if got != expected:
        print("FAIL: printed lines differ\npython:\n  %s\nparasol:\n  %s" % (
            "\n  ".join(expected), "\n  ".join(got)))
        return 1
    print("ok: %d printed and tester lines identical" % len(got))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""parasol's own pFUnit preprocessor, for machines without pFUnit (Debian does not package it).

Turns one pFUnit 4 test suite (`test_x.pf`, module `test_x`) into
  <outdir>/test_x.F90         the module, with each @assert annotation replaced by a call to
                              the matching `funit_assert_*` routine of tests/pfunit/funit.f90,
                              carrying the .pf file name and line, followed by an early return
                              when the test has failed (as pFUnit does);
  <outdir>/test_x_driver.f90  a program that runs every @test between the @before and @after
                              fixtures, reports each result, and exits non-zero on any failure.
Only the subset documented in doc/testing.md (from pfunit.md) is accepted; anything else
is refused with the .pf file and line, so a suite that builds here builds with real pFUnit.

usage: pfunit_preprocess.py SUITE.pf OUTDIR
"""
import os
import re
import sys

ASSERTS = {
    "assertEqual": "funit_assert_equal",
    "assertTrue": "funit_assert_true",
    "assertFalse": "funit_assert_false",
    "assertRelativelyEqual": "funit_assert_relatively_equal",
    "assertLessThan": "funit_assert_less_than",
    "assertLessThanOrEqual": "funit_assert_less_than_or_equal",
    "assertGreaterThan": "funit_assert_greater_than",
    "assertGreaterThanOrEqual": "funit_assert_greater_than_or_equal",
    "assertAll": "funit_assert_all",
    "assertAny": "funit_assert_any",
}
FIXTURES = ("test", "before", "after")
SUB_RE = re.compile(r"^\s*(?:(?:pure|impure|recursive)\s+)*subroutine\s+(\w+)", re.I)
MODULE_RE = re.compile(r"^\s*module\s+(\w+)\s*(?:!.*)?$", re.I)
ANNOT_RE = re.compile(r"^(\s*)@(\w+)\s*(.*)$")


class PfError(Exception):
    pass


def split_call(text, path, lineno):
    """Given '(args) rest', return (args, rest), honouring strings and nesting."""
    if not text.startswith("("):
        raise PfError(f"{path}:{lineno}: expected '(' after the annotation")
    depth, quote = 0, None
    for i, ch in enumerate(text):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth == 0:
                return text[1:i], text[i + 1:]
    raise PfError(f"{path}:{lineno}: the annotation's arguments must close on the same line "
                  "(no continuation lines inside an annotation)")


def translate(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    stem = os.path.splitext(os.path.basename(path))[0]
    base = os.path.basename(path)
    out, tests, fixtures, pending, module = [], [], {}, None, None
    for lineno, line in enumerate(lines, 1):
        if module is None:
            m = MODULE_RE.match(line)
            if m:
                module = m.group(1)
                if module.lower() != stem.lower():
                    raise PfError(f"{path}:{lineno}: module '{module}' must be named after the "
                                  f"file stem '{stem}'")
        if pending:
            m = SUB_RE.match(line)
            if m:
                if pending == "test":
                    tests.append(m.group(1))
                else:
                    fixtures[pending] = m.group(1)
                pending = None
            elif line.strip() and not line.strip().startswith("!"):
                raise PfError(f"{path}:{lineno}: @{pending} must be followed by a subroutine")
        m = ANNOT_RE.match(line)
        if not m:
            out.append(line)
            continue
        indent, name, rest = m.groups()
        if name.lower() in FIXTURES:
            if rest.strip() and not rest.strip().startswith("!"):
                raise PfError(f"{path}:{lineno}: @{name} takes no arguments in this subset "
                              "(@test(...) options and @TestCase are not supported)")
            pending = name.lower()
            out.append(f"{indent}! @{name}")
            continue
        if name not in ASSERTS:
            raise PfError(f"{path}:{lineno}: @{name} is not in the supported pFUnit subset "
                          f"({', '.join('@' + a for a in ASSERTS)}, @test, @before, @after)")
        args, tail = split_call(rest.strip(), path, lineno)
        if tail.strip():
            # pFUnit 4's parser takes an assertion's line whole: anything after the closing
            # parenthesis (even a comment) leaves the line untranslated and breaks the build.
            raise PfError(f"{path}:{lineno}: nothing may follow @{name}(...) on its line, "
                          "not even a comment (real pFUnit rejects it); put the comment above")
        call = (f"{indent}call {ASSERTS[name]}({args}, file='{base}', line={lineno})"
                f"; if (funit_failed()) return{tail}")
        out.append(call)
    if module is None:
        raise PfError(f"{path}: no 'module {stem}' found")
    if pending:
        raise PfError(f"{path}: @{pending} at end of file is not followed by a subroutine")
    if not tests:
        raise PfError(f"{path}: the suite has no @test")
    return module, out, tests, fixtures


def driver(module, tests, fixtures, base):
    names = list(tests) + [fixtures[k] for k in ("before", "after") if k in fixtures]
    d = [f"! Generated by pfunit_preprocess.py from {base}: do not edit.",
         f"program {module}_driver",
         "    use funit, only: funit_start_test, funit_end_test, funit_finish",
         f"    use {module}, only: {', '.join(names)}",
         "    implicit none"]
    for t in tests:
        d.append(f"    call funit_start_test('{module}', '{t}')")
        if "before" in fixtures:
            d.append(f"    call {fixtures['before']}()")
        d.append(f"    call {t}()")
        if "after" in fixtures:
            d.append(f"    call {fixtures['after']}()")
        d.append("    call funit_end_test()")
    d.append(f"    call funit_finish('{module}')")
    d.append(f"end program {module}_driver")
    return d


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    path, outdir = sys.argv[1], sys.argv[2]
    try:
        module, body, tests, fixtures = translate(path)
    except PfError as e:
        sys.exit(f"{e}")
    os.makedirs(outdir, exist_ok=True)
    stem = os.path.splitext(os.path.basename(path))[0]
    base = os.path.basename(path)
    header = f"! Generated by pfunit_preprocess.py from {base}: do not edit."
    write_if_changed(os.path.join(outdir, stem + ".F90"), [header] + body)
    write_if_changed(os.path.join(outdir, stem + "_driver.f90"),
                     driver(module, tests, fixtures, base))


def write_if_changed(path, lines):
    text = "\n".join(lines) + "\n"
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                return
    tmp = path + ".partial"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Runs one verification deck of the mesh commands and checks the groups it makes against
the hand counts in its head (tests/mesh_commands, doc/mesh-commands.md).

usage: run_mesh_case.py PARASOL DECK WORKDIR [--aster-dir DIR]

Header lines of the deck (anywhere before the first command):
    # mesh: plate4.mail                  the mesh on unit 20 (relative to the deck; with
                                         {aster} the Code_Aster folder: skipped without it)
    # unit: 19=strip.mgib                a file on another unit (as mesh:)
    # members: GROUP_NO LOOP = N5 N4 N3  the members of a group made, in order
    # count: GROUP_MA ALL = 36           the number of members of a group made
    # absent: GROUP_MA FACE_UP           a group the deck does not make (empty)
    # line: ORIE_PEAU GROUP_MA BORD (16 cells): 4 turned round   a line of the .mess
    # warning: ... is given twice        a located warning on stderr
The deck must run to exit 0 (every TEST_RESU OK) with nothing on stderr but the warnings it
expects. Groups are read from the .mess, where INFO=2 lists the members of each group made.
Exit 77 (CTest's skip) when the mesh is in a Code_Aster folder that is absent.
"""
import os
import re
import subprocess
import sys

SKIP = 77


def header(deck):
    keys = []
    with open(deck, encoding="utf-8") as f:
        for line in f:
            m = re.match(r"#\s*(mesh|unit|members|count|absent|line|warning):\s*(.*)$",
                         line.rstrip())
            if m:
                keys.append((m.group(1), m.group(2).strip()))
    return keys


def groups_made(mess):
    """{('GROUP_MA', NAME): [members]} from the .mess of a run with INFO=2 (the last group
    of a name made wins: a group destroyed and made again)."""
    made = {}
    lines = mess.splitlines()
    i = 0
    while i < len(lines):
        m = re.match(r"\s+(GROUP_MA|GROUP_NO) (\S+) created: (\d+) (cells|nodes)$", lines[i])
        if m:
            members = []
            j = i + 1
            while j < len(lines) and re.match(r"^      \S", lines[j]):
                members += lines[j].split()
                j += 1
            made[(m.group(1), m.group(2))] = (int(m.group(3)), members)
            i = j
            continue
        i += 1
    return made


def main(argv):
    parasol, deck, work = argv[1], os.path.abspath(argv[2]), argv[3]
    aster = None
    if "--aster-dir" in argv:
        aster = argv[argv.index("--aster-dir") + 1]
    keys = header(deck)
    cmd = [os.path.abspath(parasol), "--outdir", os.path.abspath(work)]
    for key, value in keys:
        if key in ("mesh", "unit"):
            unit = "20"
            if key == "unit":
                unit, value = value.split("=", 1)
            if "{aster}" in value:
                if not aster or not os.path.isdir(aster):
                    print("skipped: Code_Aster's test files (%s) are absent" % aster)
                    return SKIP
                value = value.replace("{aster}", aster)
            else:
                value = os.path.join(os.path.dirname(deck), value)
            if not os.path.exists(value):
                print("skipped: %s is absent" % value)
                return SKIP
            cmd += ["--unit", unit + "=" + value]
    os.makedirs(work, exist_ok=True)
    cmd.append(deck)
    run = subprocess.run(cmd, capture_output=True, timeout=120)
    err = run.stderr.decode("utf-8", "replace")
    stem = os.path.splitext(os.path.basename(deck))[0]
    mess = open(os.path.join(work, stem + ".mess"), encoding="utf-8").read()
    made = groups_made(mess)
    problems = []
    if run.returncode != 0:
        problems.append("exit status %d" % run.returncode)
    expected_warnings = [v for k, v in keys if k == "warning"]
    for line in err.splitlines():
        if not line.strip():
            continue
        if ": warning: " in line and any(w in line for w in expected_warnings):
            continue
        problems.append("unexpected on stderr: " + line)
    for w in expected_warnings:
        if w not in err:
            problems.append("expected warning missing: " + w)
    for key, value in keys:
        if key in ("members", "count", "absent"):
            m = re.match(r"(GROUP_MA|GROUP_NO) (\S+)(?: = (.*))?$", value)
            name = (m.group(1), m.group(2))
            if key == "absent":
                if name in made:
                    problems.append("%s %s was made, it should not be" % name)
                continue
            if name not in made:
                problems.append("%s %s was not made" % name)
                continue
            count, members = made[name]
            if key == "count" and count != int(m.group(3)):
                problems.append("%s %s has %d members, expected %s" % (name + (count, m.group(3))))
            if key == "members" and members != m.group(3).split():
                problems.append("%s %s is %s, expected %s" % (name + (" ".join(members),
                                                                      m.group(3))))
        elif key == "line" and value not in mess:
            problems.append("no line '%s' in the .mess" % value)
    if problems:
        print("FAIL %s:\n  %s\nstderr:\n%s" % (stem, "\n  ".join(problems), err))
        return 1
    print("ok %s: %d groups checked" % (stem, sum(1 for k, _ in keys if k in
                                                  ("members", "count", "absent"))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

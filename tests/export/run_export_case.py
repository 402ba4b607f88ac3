#!/usr/bin/env python3
"""Runs parasol on export files or several command files and checks the outcome.

usage: run_export_case.py PARASOL WORKDIR [--cwd DIR] [--exit N] [--stderr TEXT]
                          [--mess TEXT]... [--resu-lines N] -- PARASOL_ARGS...

--exit N        expected exit status (default 0)
--stderr TEXT   stderr must contain TEXT (a located message: FILE:LINE[:COL]: error: ...)
--mess TEXT     the .mess must contain TEXT (repeatable)
--resu-lines N  the .resu must hold N TEST_RESU check lines (OK or NOOK)
--listings STEM the listings are STEM.mess/.resu in WORKDIR (default: the export file's or
                the first deck's stem)
A failed run (exit 1) must not touch an older .resu, must commit its .mess with the message,
and must show no crash on stderr; every run must end within 60 s.
"""
import os
import subprocess
import sys

CRASH_SIGNS = ("Fortran runtime error", "Backtrace", "ERROR STOP", "Segmentation",
               "double free", "Program received signal")


def main(argv):
    parasol, workdir = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    split = argv.index("--")
    opts, args = argv[3:split], argv[split + 1:]
    expect_exit, stderr_text, mess_texts, resu_lines, cwd = 0, None, [], None, None
    stem = None
    i = 0
    while i < len(opts):
        flag, value = opts[i], opts[i + 1]
        if flag == "--exit":
            expect_exit = int(value)
        elif flag == "--stderr":
            stderr_text = value
        elif flag == "--mess":
            mess_texts.append(value)
        elif flag == "--resu-lines":
            resu_lines = int(value)
        elif flag == "--cwd":
            cwd = value
        elif flag == "--listings":
            stem = value
        else:
            raise SystemExit("unknown option " + flag)
        i += 2
    os.makedirs(workdir, exist_ok=True)
    if stem is None:
        first = next(a for a in args if not a.startswith("-") and "=" not in a)
        stem = os.path.splitext(os.path.basename(first))[0]
    mess = os.path.join(workdir, stem + ".mess")
    resu = os.path.join(workdir, stem + ".resu")
    for path in (mess, resu):
        if os.path.exists(path):
            os.remove(path)
    if expect_exit == 1:
        with open(resu, "w") as f:
            f.write("OLD RESULT\n")
    run = subprocess.run([parasol, "--outdir", workdir] + args, cwd=cwd,
                         capture_output=True, timeout=60)
    err = run.stderr.decode("utf-8", "replace")
    problems = []
    if run.returncode != expect_exit:
        problems.append("exit status %d, expected %d" % (run.returncode, expect_exit))
    for sign in CRASH_SIGNS:
        if sign in err:
            problems.append("crash sign on stderr: " + sign)
    if stderr_text and stderr_text not in err:
        problems.append("stderr lacks " + repr(stderr_text))
    if expect_exit != 1 and err.strip():
        problems.append("unexpected stderr")
    text = ""
    if not os.path.exists(mess):
        problems.append("no .mess written")
    else:
        with open(mess, encoding="utf-8", errors="replace") as f:
            text = f.read()
    for wanted in mess_texts + ([stderr_text] if stderr_text else []):
        if text and wanted not in text:
            problems.append("the .mess lacks " + repr(wanted))
    if expect_exit == 1:
        with open(resu) as f:
            if f.read() != "OLD RESULT\n":
                problems.append("the older .resu was overwritten by a failed run")
    if resu_lines is not None:
        with open(resu) as f:
            n = sum(1 for line in f if line.startswith((" OK ", "NOOK ")))
        if n != resu_lines:
            problems.append("%d TEST_RESU check lines, expected %d" % (n, resu_lines))
    if problems:
        print("FAIL " + " ".join(args) + ": " + "; ".join(problems))
        print("stderr was:\n" + err)
        return 1
    print("ok " + " ".join(args) + (": " + err.strip() if err.strip() else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

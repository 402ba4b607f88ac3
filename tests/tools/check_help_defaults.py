#!/usr/bin/python3
"""Every option of the generators and benchmark scripts shows its default in --help
(argparse's ArgumentDefaultsHelpFormatter, with a help text for each option), and the case
generator's default NPREC is Code_Aster's SSNL130 value, 9, at every size and contrast (the
plate's rigid modes are kept apart: make_ssnl130_case.py default_nprec).

Usage: check_help_defaults.py SOURCE_DIR
"""
import os
import re
import subprocess
import sys

source = sys.argv[1]
SCRIPTS = ["tools/make_ssnl130_case.py", "tools/make_ssnl130_mesh.py", "tools/rigid_bed_exact.py",
           "tests/extremes/make_cases.py", "tests/extremes/measure.py",
           "tests/extremes/slab_reference.py", "tests/bench/calculix/make_ccx_bed.py",
           "tests/bench/calculix/run_ccx_bench.py", "tests/bench/calculix/check_ccx_deck.py",
           "tests/bench/solvers/run_solver_bench.py", "tests/bench/study/run_study.py",
           "tests/bench/stability/run_ladder.py"]
problems = []
for script in SCRIPTS:
    run = subprocess.run([sys.executable, os.path.join(source, script), "--help"],
                         capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        problems.append(f"{script} --help: exit {run.returncode} {run.stderr[-200:]}")
        continue
    section = run.stdout.split("\noptions:\n", 1)[-1]
    # one entry per option: the lines from "  --name" (or "  -x, --name") to the next one
    for entry in re.split(r"\n  (?=-)", "\n" + section)[1:]:
        names = re.findall(r"--[a-z0-9-]+", entry.split("  ")[0])
        if not names or names == ["--help"]:
            continue
        if "(default:" not in " ".join(entry.split()):
            problems.append(f"{script}: {names[-1]} shows no default")

sys.path.insert(0, os.path.join(source, "tools"))
import make_ssnl130_case  # noqa: E402
import argparse  # noqa: E402
for (model, nx, ny, K), wanted in {("a", 4, 16, "10000"): 9, ("a", 64, 256, "10000"): 9,
                                    ("a", 200, 800, "10000"): 9, ("a", 64, 256, "0.0001"): 9,
                                    ("b", 0, 512, "10000"): 9}.items():
    o = argparse.Namespace(model=model, nx=nx, ny=ny, E=2.0e11, h=0.3, K=K)
    got = make_ssnl130_case.default_nprec(o)
    if got != wanted:
        problems.append(f"default NPREC of {model} {nx}x{ny}: {got}, expected {wanted}")

for p in problems:
    print("FAIL:", p)
print(f"check_help_defaults: {len(SCRIPTS)} scripts, {len(problems)} problems")
sys.exit(1 if problems else 0)

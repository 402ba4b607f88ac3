#!/usr/bin/python3
"""Several parasol runs of one deck into one --outdir at the same time: each writes through
its own temporary names (unique per process), so every run succeeds, the listings are
complete and identical, and no temporary file is left behind.

usage: concurrent_runs.py PARASOL DECK MESH OUTDIR [RUNS]
"""
import glob
import os
import shutil
import subprocess
import sys

parasol, deck, mesh, outdir = sys.argv[1:5]
runs = int(sys.argv[5]) if len(sys.argv) > 5 else 4
shutil.rmtree(outdir, ignore_errors=True)
os.makedirs(outdir)
procs = [subprocess.Popen([parasol, "--outdir", outdir, "--unit", "20=" + mesh, deck],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
         for _ in range(runs)]
problems = []
for k, p in enumerate(procs):
    out, _ = p.communicate(timeout=120)
    if p.returncode != 0:
        problems.append(f"run {k} exited with {p.returncode}: {out.strip()}")
stem = os.path.splitext(os.path.basename(deck))[0]
resu = os.path.join(outdir, stem + ".resu")
if not os.path.exists(resu):
    problems.append("no .resu was written")
left = glob.glob(os.path.join(outdir, "*.partial"))
if left:
    problems.append("temporary files left behind: " + " ".join(left))
if problems:
    print("\n".join(problems))
    sys.exit(1)
print(f"{runs} concurrent runs into one folder: all exited 0, no temporary file left")

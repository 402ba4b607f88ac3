#!/usr/bin/env python3
"""Time and memory of each SOLVEUR/METHODE on the SSNL130 family (doc/performance.md,
"Solvers").

For each mesh nx x ny of model A (tools/make_ssnl130_case.py: DKQ plate on DIS_CHOC springs,
full Newton, RESI_GLOB_RELA 1e-6, NPREC 11) and each method (LDLT, MULT_FRONT, MUMPS), runs
parasol once and reports: wall and CPU time and peak RSS of the whole process (os.wait4),
the factorizations of the analysis and their summed time, the factor's stored terms and
memory (from the .mess "factorization" lines), and the largest relative error of DZ at PT01
and PT03 against the exact discrete reference (the deck's TEST_RESU lines). It also prints
the OpenBLAS core in use (openblas_get_corename) and the load average before and after.
Writes a CSV (--csv) and prints a Markdown table.

    /usr/bin/python3 tests/bench/solvers/run_solver_bench.py --parasol build/parasol \
        --meshes 4x16,16x64,32x128,64x256 --csv doc/study/solvers.csv
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
GEN = os.path.join(ROOT, "tools", "make_ssnl130_case.py")
METHODS = ["LDLT", "MULT_FRONT", "MUMPS"]
sys.path.insert(0, os.path.join(ROOT, "tests", "bench", "study"))
from parasol_case import openblas_core  # noqa: E402


def run(cmd, cwd):
    """Whole-process wall, CPU seconds and peak RSS (MB) of cmd."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    code = os.waitstatus_to_exitcode(status)
    return code, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0


def parse_mess(path, resu):
    """Factorizations, their summed time, the largest factor terms and MB, iterations, and
    the largest ANALYTIQUE error of the .resu."""
    text = open(path, encoding="utf-8", errors="replace").read()
    listing = open(resu, encoding="utf-8", errors="replace").read() if os.path.exists(resu) else ""
    rows = re.findall(r"factorization \S+ \(ordering [^)]*\): (\d+) terms, ([0-9.E+-]+) MB, "
                      r"([0-9.]+) s", text)
    iters = re.findall(r"converged in (\d+) iteration", text)
    errs = [abs(float(v)) for v in
            re.findall(r"ANALYTIQUE +\S+ +\S+ +\S+ +([0-9.E+-]+)%", listing)]
    return {"factorizations": len(rows),
            "factor_s": sum(float(r[2]) for r in rows),
            "terms": max((int(r[0]) for r in rows), default=0),
            "factor_mb": max((float(r[1]) for r in rows), default=0.0),
            "iterations": sum(int(i) for i in iters),
            "err": max(errs) / 100.0 if errs else float("nan")}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    ap.add_argument("--parasol", required=True, help="the parasol executable")
    ap.add_argument("--meshes", default="4x16,16x64", help="model A meshes, comma list NXxNY")
    ap.add_argument("--methods", default=",".join(METHODS), help="SOLVEUR METHODEs to time")
    ap.add_argument("--csv", default=None, help="also write the rows to this CSV (None: no)")
    ap.add_argument("--one-thread", action="store_true",
                    help="run parasol with OMP_NUM_THREADS=1 and OPENBLAS_NUM_THREADS=1 (the "
                         "CHOLMOD and MUMPS plug-ins otherwise start OpenMP and OpenBLAS "
                         "threads; by hand only, never in tests or CI)")
    o = ap.parse_args()
    if o.one_thread:
        os.environ["OMP_NUM_THREADS"] = "1"
        os.environ["OPENBLAS_NUM_THREADS"] = "1"
    parasol = os.path.abspath(o.parasol)
    print(f"OpenBLAS core: {openblas_core()}; load average before: {os.getloadavg()}")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for mesh in o.meshes.split(","):
            nx, ny = (int(v) for v in mesh.split("x"))
            for method in o.methods.split(","):
                stem = os.path.join(work, f"a_{nx}x{ny}_{method}")
                subprocess.run([sys.executable, GEN, "--model", "a", "--nx", str(nx), "--ny",
                                str(ny), "--nprec", "11", "--methode", method, "--tolerance",
                                "1e-5", "-o", stem], check=True, stdout=subprocess.DEVNULL)
                deck = stem + ".comm"
                code, wall, cpu, rss = run([parasol, "--outdir", work, deck], work)
                m = parse_mess(stem + ".mess", stem + ".resu")
                row = {"mesh": mesh, "method": method, "exit": code, "wall_s": wall,
                       "cpu_s": cpu, "rss_mb": rss, **m}
                rows.append(row)
                print(f"{mesh} {method}: exit {code}, wall {wall:.3f} s, CPU {cpu:.3f} s, "
                      f"RSS {rss:.0f} MB, {m['factorizations']} factorizations "
                      f"({m['factor_s']:.3f} s), factor {m['terms']} terms / "
                      f"{m['factor_mb']:.1f} MB, err {m['err']:.1e}", flush=True)
    print(f"load average after: {os.getloadavg()}")
    print("\n| mesh | METHODE | wall s | CPU s | RSS MB | factorizations | factor s (sum) "
          "| factor terms | factor MB | err |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['mesh']} | {r['method']} | {r['wall_s']:.3f} | {r['cpu_s']:.3f} | "
              f"{r['rss_mb']:.0f} | {r['factorizations']} | {r['factor_s']:.3f} | "
              f"{r['terms']} | {r['factor_mb']:.1f} | {r['err']:.1e} |")
    if o.csv:
        with open(o.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    return 1 if any(r["exit"] != 0 for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())

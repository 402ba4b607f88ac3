#!/usr/bin/python3
"""The SSNL130 ladder of issue 22: mesh and contrast, every METHODE (doc/stability.md, "Mesh
and contrast ladder").

For each case (model A: nx x ny plates; model B: ny cells; with K the bed's stiffness and E
the plate's) and each METHODE, writes the deck with tools/make_ssnl130_case.py (DIS_CHOC,
full Newton, RESI_GLOB_RELA 1e-6, the generator's NPREC unless --nprec, TEST_RESU against the
exact discrete rigid-plate answer at 1e-6), runs parasol once (single-threaded BLAS and
OpenMP, as by hand) and reports: exit status, the largest relative error of the TEST_RESU
ANALYTIQUE lines (recomputed from the printed values), the digits the factorizations lost
(the .mess's largest loss, or for a run that stopped the pivot its message names) and the
digits the answer holds (the .mess), factorizations and Newton iterations, wall and
CPU seconds and peak RSS (os.wait4), and the first error line. --before PARASOL2 runs a
second executable on the same decks (the "before" columns). --mpi N runs METHODE MUMPS
under `mpirun --oversubscribe -np N` with the executable of --mpi-parasol (an MPI MUMPS
build). --ccx CCX also runs CalculiX on model A's cases (tests/bench/calculix/make_ccx_bed.py:
S4 shells on GAPUNI gaps, the same K and E, exact consistent loads; its error against the
exact rigid-plate answer for that load; "failed" when ccx stops or gives no corners). Writes
a CSV (--csv) and a Markdown table on stdout. Not a test: a measuring tool.

    /usr/bin/python3 tests/bench/stability/run_ladder.py --parasol build/parasol \\
        --model a --meshes 4x16,16x64,32x128 --K 1e4 --methods LDLT,MULT_FRONT,MUMPS
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "bench", "study"))
sys.path.insert(0, os.path.join(ROOT, "tests", "bench", "calculix"))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import parasol_case  # noqa: E402
import make_ccx_bed  # noqa: E402
import rigid_bed_exact  # noqa: E402

GENERATOR = os.path.join(ROOT, "tools", "make_ssnl130_case.py")
ANALYTIQUE = re.compile(r"TEST_RESU .* (OK|NOOK) ANALYTIQUE \S+ (\S+) (\S+) ")
LARGEST = re.compile(r"largest loss ([0-9.]+) digits")
PIVOT_LOST = re.compile(r"pivot lost ([0-9.]+) digits")
HOLDS = re.compile(r"the answer holds ([0-9.]+) significant digits")
TOTAL = re.compile(r"STAT_NON_LINE: (\d+) iteration\(s\), (\d+) factorization\(s\)")
ERROR = re.compile(r"error: (.*)$", re.M)


class HelpFormatter(argparse.ArgumentDefaultsHelpFormatter,
                    argparse.RawDescriptionHelpFormatter):
    """--help shows each option's default, and the docstring as written."""


def generate(base, model, mesh, K, E, methode, nprec, tolerance):
    args = ["--model", model, "--K", K, "--E", E, "--methode", methode,
            "--tolerance", tolerance]
    if model == "a":
        nx, ny = mesh.split("x")
        args += ["--nx", nx, "--ny", ny]
    else:
        args += ["--ny", mesh]
    if nprec:
        args += ["--nprec", nprec]
    subprocess.run([parasol_case.PYTHON, GENERATOR] + args + ["-o", base], check=True,
                   capture_output=True)


def measure(cmd, work, stem, timeout):
    log = os.path.join(work, stem + ".log")
    env = dict(os.environ, **parasol_case.ONE_THREAD)
    try:
        rc, wall, cpu, rss = parasol_case.run_measured(cmd, work, env, log)
    except subprocess.TimeoutExpired:
        return dict(rc="timeout")
    mess_path = os.path.join(work, stem + ".mess")
    mess = open(mess_path, encoding="utf-8", errors="replace").read() \
        if os.path.exists(mess_path) else ""
    errors = []
    for ok, ref, val in ANALYTIQUE.findall(mess):
        ref, val = float(ref), float(val)
        errors.append(abs(val - ref) / abs(ref) if ref != 0.0 else abs(val))
    largest = LARGEST.findall(mess) or PIVOT_LOST.findall(mess)
    holds = HOLDS.findall(mess)
    total = TOTAL.findall(mess)
    err_line = ERROR.findall(open(log, encoding="utf-8", errors="replace").read())
    return dict(rc=rc, wall_s=f"{wall:.2f}", cpu_s=f"{cpu:.2f}", rss_mb=f"{rss:.0f}",
                error=f"{max(errors):.1e}" if errors else "-",
                digits_lost=largest[-1] if largest else "-",
                answer_digits=min(holds, key=float) if holds else "-",
                iterations=total[-1][0] if total else "-",
                factorizations=total[-1][1] if total else "-",
                message=err_line[0][:140] if err_line else "")


def run_ccx(ccx, mesh, K, E, work, timeout):
    """CalculiX on model A nx x ny with bed K and plate E: wall, CPU, RSS and the largest
    relative error of the corners against the exact rigid-plate answer (exact load)."""
    nx, ny = (int(v) for v in mesh.split("x"))
    job = f"ccx_{mesh}_K{K}_E{E}"
    params = dict(make_ccx_bed.DEFAULTS, K=repr(float(K)), E=repr(float(E)))
    with open(os.path.join(work, job + ".inp"), "w", encoding="ascii") as f:
        make_ccx_bed.write_deck(f, nx, ny, **params)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    log = os.path.join(work, job + ".log")
    try:
        rc, wall, cpu, rss = parasol_case.run_measured(
            ["timeout", str(int(timeout)), ccx, "-i", job], work, env, log)
    except subprocess.TimeoutExpired:
        return dict(ccx_error="timeout")
    if rc == 124:
        return dict(ccx_rc=rc, ccx_error=f"timeout ({int(timeout)} s)")
    try:
        dz = make_ccx_bed.parse_corner_dz(os.path.join(work, job + ".dat"), nx, ny)
    except (OSError, ValueError):
        return dict(ccx_rc=rc, ccx_error="failed")
    ref = rigid_bed_exact.solve_rigid_bed(ny, K=params["K"], load="exact")
    errs = [abs(float(dz[i]) - float(ref[k])) / abs(float(ref[k]))
            for i, k in ((0, "pt01"), (2, "pt03"))]
    return dict(ccx_rc=rc, ccx_wall_s=f"{wall:.2f}", ccx_rss_mb=f"{rss:.0f}",
                ccx_error=f"{max(errs):.1e}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 epilog=__doc__.split("\n", 2)[2],
                                 formatter_class=HelpFormatter)
    ap.add_argument("--parasol", required=True, help="the parasol executable")
    ap.add_argument("--before", default=None,
                    help="a second parasol executable run on the same decks (None: none)")
    ap.add_argument("--model", choices=("a", "b"), default="a", help="SSNL130 model")
    ap.add_argument("--meshes", default="4x16,16x64",
                    help="model A: NXxNY list; model B: NY list")
    ap.add_argument("--K", default="1e4", help="bed stiffnesses, comma list (N/m)")
    ap.add_argument("--E", default="2e11", help="plate Young's moduli, comma list (Pa)")
    ap.add_argument("--methods", default="LDLT,MULT_FRONT,MUMPS", help="SOLVEUR METHODEs")
    ap.add_argument("--nprec", default=None,
                    help="SOLVEUR NPREC of every deck (None: the generator's default)")
    ap.add_argument("--tolerance", default="1e-6", help="TEST_RESU PRECISION of the decks")
    ap.add_argument("--mpi", type=int, default=0,
                    help="also run METHODE MUMPS under mpirun with this many processes (0: no)")
    ap.add_argument("--mpi-parasol", default=None,
                    help="the MPI MUMPS build's parasol for --mpi (None: --parasol)")
    ap.add_argument("--ccx", default=None,
                    help="the CalculiX executable: also run it on model A's cases (None: no)")
    ap.add_argument("--timeout", type=float, default=3600.0, help="seconds per run")
    ap.add_argument("--ccx-timeout", type=float, default=600.0,
                    help="seconds per CalculiX run (ccx iterates long on the softest beds)")
    ap.add_argument("--csv", default=None, help="also write the rows to this CSV (None: no)")
    ap.add_argument("--check", action="store_true",
                    help="exit 1 unless every run exits 0 with every error within --tolerance "
                         "and no more digits lost than the deck's NPREC (issue 22)")
    o = ap.parse_args(argv)
    print(f"OpenBLAS core: {parasol_case.openblas_core()}; load average before: "
          f"{os.getloadavg()}", file=sys.stderr)
    rows = []
    runs = [(m, False) for m in o.methods.split(",")]
    if o.mpi:
        runs.append(("MUMPS", True))
        if os.geteuid() == 0:     # Open MPI refuses root unless told (a container's root)
            os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with tempfile.TemporaryDirectory() as work:
        for mesh in o.meshes.split(","):
            for K in o.K.split(","):
                for E in o.E.split(","):
                    for methode, mpi in runs:
                        stem = f"{o.model}_{mesh}_K{K}_E{E}_{methode}{'_mpi' if mpi else ''}"
                        base = os.path.join(work, stem)
                        generate(base, o.model, mesh, K, E, methode, o.nprec, o.tolerance)
                        exe = os.path.abspath(o.mpi_parasol or o.parasol) if mpi else \
                            os.path.abspath(o.parasol)
                        cmd = [exe, "--quiet", "--outdir", work, base + ".comm"]
                        if mpi:
                            cmd = ["mpirun", "--oversubscribe", "-np", str(o.mpi)] + cmd
                        row = dict(model=o.model, mesh=mesh, K=K, E=E,
                                   methode=methode + (f" (mpirun -np {o.mpi})" if mpi else ""))
                        row.update(measure(cmd, work, stem, o.timeout))
                        if o.before:
                            b = measure([os.path.abspath(o.before), "--quiet", "--outdir", work,
                                         base + ".comm"], work, stem, o.timeout)
                            row.update({"before_" + k: v for k, v in b.items()})
                        if o.ccx and o.model == "a" and methode == runs[0][0] and not mpi:
                            row.update(run_ccx(o.ccx, mesh, K, E, work, o.ccx_timeout))
                        rows.append(row)
                        print(" | ".join(str(v) for v in row.values()), file=sys.stderr,
                              flush=True)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    if o.csv:
        with open(o.csv, "w", newline="", encoding="utf-8") as f:
            w = csv.DictWriter(f, fieldnames=keys, restval="")
            w.writeheader()
            w.writerows(rows)
    print("| " + " | ".join(keys) + " |")
    print("|" + "---|" * len(keys))
    for r in rows:
        print("| " + " | ".join(str(r.get(k, "")) for k in keys) + " |")
    if o.check:
        bad = [r for r in rows if not passes(r, float(o.tolerance), o.nprec)]
        for r in bad:
            print(f"FAIL {r['model']} {r['mesh']} K {r['K']} E {r['E']} {r['methode']}: "
                  f"exit {r['rc']}, error {r['error']}, digits lost {r['digits_lost']} "
                  f"{r['message']}")
        return 1 if bad else 0
    return 0


def passes(row, tolerance, nprec):
    """Exit 0, every TEST_RESU within tolerance, digits lost at most NPREC (9 by default)."""
    if row["rc"] != 0 or row["error"] == "-" or float(row["error"]) > tolerance:
        return False
    limit = float(nprec) if nprec else 9.0
    return row["digits_lost"] == "-" or float(row["digits_lost"]) <= limit


if __name__ == "__main__":
    sys.exit(main())

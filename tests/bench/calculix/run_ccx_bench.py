#!/usr/bin/python3
"""Side-by-side benchmark on the SSNL130 plate-on-unilateral-springs problem (issue 7).

For each mesh nx x ny (default ladder 4x16 ... 128x512) this script
  1. writes a CalculiX deck with make_ccx_bed.py (S4 shells + GAPUNI gaps, see there),
  2. runs `ccx` single-threaded (OMP_NUM_THREADS=1) in a temporary directory,
  3. measures the wall time (monotonic clock around the child) and the child's own CPU time
     (user + sys) and peak resident memory from os.wait4's rusage,
  4. reads DZ of the corners PT01..PT04 from the .dat file and compares PT01 (y = 0) and
     PT03 (y = b) with the exact discrete rigid-plate answer for that ny
     (rigid_bed_exact.py, rational arithmetic): err = (dz - exact) / |exact|,
  5. appends one CSV row per run.
With --parasol PATH it will also run parasol on the equivalent generated deck and add its
rows; that half waits for parasol to run decks (see run_parasol_case).

Without --meshes, the ladder stops before the first mesh whose estimated time exceeds
--max-seconds.  The estimate scales the last measured time by the ratio of the team's
reference ccx CPU times (REFERENCE_CPU_S) of the two meshes.

Exit status: 0 all runs done; 1 a run failed (ccx missing output, parse error);
77 ccx not found (CTest SKIP_RETURN_CODE); 3 --parasol given but parasol runs are not
implemented yet.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))  # rigid_bed_exact
import make_ccx_bed  # noqa: E402
import rigid_bed_exact  # noqa: E402

LADDER = [(4, 16), (8, 32), (16, 64), (32, 128), (64, 256), (128, 512)]
# ccx 2.20 CPU seconds measured by the team on a similar machine (8x32 was not measured:
# geometric mean of its neighbours).  Only used to estimate the next run's time.
REFERENCE_CPU_S = {(4, 16): 0.12, (8, 32): 0.51, (16, 64): 2.2, (32, 128): 11.0,
                   (64, 256): 56.0, (128, 512): 315.0}
SKIP_CODE = 77
COLUMNS = ["program", "nx", "ny", "nodes", "equations", "iterations", "wall_s", "cpu_s",
           "maxrss_mb", "dz_pt01", "dz_pt02", "dz_pt03", "dz_pt04", "err_pt01", "err_pt03"]


class BenchError(Exception):
    """A run that did not give usable results (message says which and why)."""


def run_measured(cmd, cwd, env, log_path):
    """Run cmd in cwd with stdout+stderr to log_path.  Return (rc, wall_s, cpu_s, maxrss_mb).

    CPU time and peak RSS are the child's own, from os.wait4 (ru_maxrss is in KiB on Linux).
    """
    with open(log_path, "wb") as log:
        t0 = time.perf_counter()
        proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT)
        _, status, ru = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    return proc.returncode, wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0


def ccx_log_value(log_path, label):
    """The integer printed on the line after `label` in ccx's output, or None."""
    with open(log_path, encoding="latin-1") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines[:-1]):
        if line.strip() == label:
            try:
                return int(lines[i + 1].split()[0])
            except (ValueError, IndexError):
                return None
    return None


def ccx_iterations(log_path):
    """Number of Newton iterations ccx reported."""
    with open(log_path, encoding="latin-1") as f:
        return sum(1 for line in f if line.strip().startswith("iteration "))


def rel_err(value, exact):
    """(value - exact) / |exact|."""
    return (value - float(exact)) / abs(float(exact))


def run_ccx_case(ccx, nx, ny, workdir):
    """Generate, run and parse one CalculiX case; return a CSV row dict.

    Errors: BenchError when ccx fails or its .dat lacks the corner displacements.
    """
    job = f"bed_{nx}x{ny}"
    with open(os.path.join(workdir, job + ".inp"), "w", encoding="ascii") as f:
        make_ccx_bed.write_deck(f, nx, ny, **make_ccx_bed.DEFAULTS)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    log = os.path.join(workdir, job + ".log")
    rc, wall, cpu, rss = run_measured([ccx, "-i", job], workdir, env, log)
    with open(log, encoding="latin-1") as f:
        finished = "Job finished" in f.read()
    if rc != 0 or not finished:
        raise BenchError(f"ccx {nx}x{ny}: exit status {rc}, 'Job finished' "
                         f"{'found' if finished else 'missing'}; see {log}")
    try:
        dz = make_ccx_bed.parse_corner_dz(os.path.join(workdir, job + ".dat"), nx, ny)
    except (OSError, ValueError) as exc:
        raise BenchError(f"ccx {nx}x{ny}: {exc}") from exc
    return finish_row("ccx", nx, ny, 2 * (nx + 1) * (ny + 1),
                      ccx_log_value(log, "number of equations"), ccx_iterations(log),
                      wall, cpu, rss, dz)


def run_parasol_case(parasol, nx, ny, workdir):
    """Run parasol on the deck equivalent to make_ccx_bed.py's for nx x ny; return a row.

    TO BE COMPLETED once parasol runs SSNL130 decks.  What it must do:
      * write a parasol deck (.comm + mesh) of the same model: nx x ny QUAD4 DKT plate,
        RIGI_PARASOL springs (K_T_D_L, VALE = (K, K, K)) on SEG2 from each plate node to a
        ground node L below, DIS_CHOC, the pressure P = p (y - b)^2 as FORCE_COQUE, one time
        step to t = 1 (no ground lift), DZ of PT01..PT04 in the .resu;
      * time it with run_measured([parasol, deck, '--outdir', workdir], ...);
      * parse the four DZ and return finish_row('parasol', nx, ny, nodes, equations,
        iterations, wall, cpu, rss, dz).
    Until then it refuses: no made-up parasol numbers.
    """
    raise NotImplementedError(
        f"parasol side of the benchmark is not implemented yet (parasol={parasol!r}, "
        f"mesh {nx}x{ny}): complete run_parasol_case() in {os.path.abspath(__file__)} "
        "once parasol can run SSNL130 decks")


def finish_row(program, nx, ny, nodes, equations, iterations, wall, cpu, rss, dz):
    """Build the CSV row, with errors of PT01/PT03 against the exact rigid-bed answer."""
    ref = rigid_bed_exact.solve_rigid_bed(ny, *(make_ccx_bed.DEFAULTS[k]
                                                for k in ("a", "b", "K", "p")))
    return dict(program=program, nx=nx, ny=ny, nodes=nodes,
                equations="" if equations is None else equations,
                iterations=iterations, wall_s=f"{wall:.3f}", cpu_s=f"{cpu:.3f}",
                maxrss_mb=f"{rss:.1f}",
                dz_pt01=f"{dz[0]:.6e}", dz_pt02=f"{dz[1]:.6e}",
                dz_pt03=f"{dz[2]:.6e}", dz_pt04=f"{dz[3]:.6e}",
                err_pt01=f"{rel_err(dz[0], ref['pt01']):.2e}",
                err_pt03=f"{rel_err(dz[2], ref['pt03']):.2e}")


def parse_meshes(text):
    """'4x16,16x64' -> [(4, 16), (16, 64)]."""
    out = []
    for item in text.split(","):
        try:
            nx, ny = (int(v) for v in item.lower().split("x"))
        except ValueError:
            raise argparse.ArgumentTypeError(f"bad mesh {item!r}: expected NXxNY, e.g. 4x16")
        if nx < 1 or ny < 1:
            raise argparse.ArgumentTypeError(f"bad mesh {item!r}: sizes must be >= 1")
        out.append((nx, ny))
    return out


def estimate_seconds(mesh, last):
    """Estimated time of `mesh` from the last measured (mesh, seconds), or None if unknown."""
    if mesh not in REFERENCE_CPU_S:
        return None
    if last is None or last[0] not in REFERENCE_CPU_S:
        return REFERENCE_CPU_S[mesh]
    return last[1] * REFERENCE_CPU_S[mesh] / REFERENCE_CPU_S[last[0]]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--meshes", type=parse_meshes,
                    help="comma list NXxNY (e.g. 4x16,16x64); runs exactly these")
    ap.add_argument("--max-seconds", type=float, default=120.0,
                    help="without --meshes: stop before a mesh estimated to take longer "
                         "(default 120)")
    ap.add_argument("--csv", default="ccx_bench.csv", help="output CSV (default %(default)s)")
    ap.add_argument("--ccx", default="ccx", help="CalculiX executable (default: ccx in PATH)")
    ap.add_argument("--parasol", help="parasol executable: also run parasol (not yet done)")
    ap.add_argument("--keep", action="store_true", help="keep the work directories")
    ap.add_argument("--max-err", type=float,
                    help="fail (exit 1) if |err_pt01| or |err_pt03| of a ccx run exceeds this")
    o = ap.parse_args(argv)

    ccx = shutil.which(o.ccx)
    if ccx is None:
        print(f"SKIP: CalculiX executable {o.ccx!r} not found in PATH; install calculix-ccx "
              "or pass --ccx PATH", file=sys.stderr)
        return SKIP_CODE
    meshes = o.meshes if o.meshes else LADDER
    status = 0
    last = None
    with open(o.csv, "w", newline="", encoding="ascii") as fcsv:
        writer = csv.DictWriter(fcsv, fieldnames=COLUMNS)
        writer.writeheader()
        for (nx, ny) in meshes:
            est = estimate_seconds((nx, ny), last)
            if not o.meshes and est is not None and est > o.max_seconds:
                print(f"stop: {nx}x{ny} estimated at {est:.0f} s > --max-seconds "
                      f"{o.max_seconds:g}", file=sys.stderr)
                break
            workdir = tempfile.mkdtemp(prefix=f"ccx_bed_{nx}x{ny}_")
            try:
                row = run_ccx_case(ccx, nx, ny, workdir)
                writer.writerow(row)
                fcsv.flush()
                print(", ".join(f"{k}={row[k]}" for k in COLUMNS))
                last = ((nx, ny), float(row["cpu_s"]))
                if o.max_err is not None and max(abs(float(row["err_pt01"])),
                                                 abs(float(row["err_pt03"]))) > o.max_err:
                    print(f"FAIL: {nx}x{ny} corner error above --max-err {o.max_err:g}",
                          file=sys.stderr)
                    status = 1
                if o.parasol:
                    prow = run_parasol_case(o.parasol, nx, ny, workdir)
                    writer.writerow(prow)
                    fcsv.flush()
            except BenchError as exc:
                print(f"FAIL: {exc}", file=sys.stderr)
                status = 1
                o.keep = True
            except NotImplementedError as exc:
                print(f"NOT DONE: {exc}", file=sys.stderr)
                return 3
            finally:
                if o.keep:
                    print(f"kept {workdir}", file=sys.stderr)
                else:
                    shutil.rmtree(workdir, ignore_errors=True)
    return status


if __name__ == "__main__":
    sys.exit(main())

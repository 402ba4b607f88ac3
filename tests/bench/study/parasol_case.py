#!/usr/bin/python3
"""Run parasol on one generated SSNL130-family deck and measure it (issue 7).

Shared by the speed-accuracy study (run_study.py, this folder) and the side-by-side benchmark
with CalculiX (../calculix/run_ccx_bench.py):

  case_args(...)      the tools/make_ssnl130_case.py options of a case
  generate(...)       writes <base>.comm and <base>.mail with that generator
  run_measured(...)   runs a command; wall time (monotonic clock), the child's CPU time
                      (user + sys) and peak resident memory from os.wait4's rusage
  parse_mess(path)    equations, free equations, profile and bandwidth before/after RENUM,
                      iterations, factorizations, the last RESI_GLOB_RELA, the solver time
                      (sum of the TIME column), the first error line
  parse_resu(path)    VALE_CALC of every TEST_RESU block: {(inst, group, component): value}
  corner_errors(...)  errors of the corners against the exact discrete rigid-plate answer
                      (tools/rigid_bed_exact.py) and against the continuous bed
  run_case(...)       all of the above for one case: one dict (a CSV row)

The SSNL130 load (p = 5, K = 1e4, a = 1, b = 2, m = 2) is the generator's default. The
continuous-bed answer is U_A = -8 p a b^3 / (9 K) = -4/1125 at y = 0 and U_B = -U_A/3 =
4/3375 at y = b (ssnl130.md, "Reference solutions").
"""
import ctypes
import ctypes.util
import os
import re
import subprocess
import sys
import time
from fractions import Fraction as Fr

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
TOOLS = os.path.join(ROOT, "tools")
sys.path.insert(0, TOOLS)
import rigid_bed_exact  # noqa: E402

GENERATOR = os.path.join(TOOLS, "make_ssnl130_case.py")
PYTHON = "/usr/bin/python3"
# Continuous bed (ssnl130.md): y = 0 and y = b corners at INST 1.
U_A_CONTINUOUS = Fr(-4, 1125)
U_B_CONTINUOUS = Fr(4, 3375)
# Corner groups at y = 0 and y = b: model A has two of each, model B one.
CORNERS = {"a": (("PT01", "PT02"), ("PT03", "PT04")), "b": (("PT01",), ("PT02",))}
COMPONENT = {"a": "DZ", "b": "DY"}
# Single-threaded BLAS/OpenMP: one core per run, comparable with ccx's single-thread run.
ONE_THREAD = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}


class CaseError(Exception):
    """A case that could not be generated or whose output could not be read."""


def openblas_core():
    """The OpenBLAS kernel family the library picks on this CPU ('?' if none): what the
    factorizations' dgemm runs (Debian's OpenBLAS 0.3.21 falls back to slower kernels on
    CPUs it does not know)."""
    for name in ("openblas", "openblas.so.0"):
        path = ctypes.util.find_library(name) or "libopenblas.so.0"
        try:
            lib = ctypes.CDLL(path)
            lib.openblas_get_corename.restype = ctypes.c_char_p
            return lib.openblas_get_corename().decode()
        except (OSError, AttributeError):
            continue
    return "?"


def case_args(model="a", nx=4, ny=16, newton="tangente", resi=1e-6, renum="RCMK", nprec=11,
              iter_max=10, methode="LDLT"):
    """Options of tools/make_ssnl130_case.py for one case (one step to INST 1, no lift).

    renum None: the method's default ordering (RCMK for LDLT, METIS for MULT_FRONT, AUTO
    for MUMPS)."""
    args = ["--model", model, "--ny", str(ny), "--newton", newton, "--resi", repr(resi),
            "--methode", methode, "--nprec", str(nprec), "--iter-max", str(iter_max)]
    if renum is not None:
        args += ["--renum", renum]
    if model == "a":
        args += ["--nx", str(nx)]
    return args


def generate(base, args):
    """Write base.comm and base.mail with the project's generator.

    Errors: CaseError when the generator fails (its stderr is in the message).
    """
    proc = subprocess.run([PYTHON, GENERATOR] + args + ["-o", base], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        raise CaseError(f"make_ssnl130_case.py {' '.join(args)}: exit {proc.returncode}: "
                        f"{proc.stderr.strip()}")
    return base + ".comm", base + ".mail"


def run_measured(cmd, cwd, env, log_path):
    """Run cmd in cwd with stdout+stderr to log_path; return (rc, wall_s, cpu_s, maxrss_mb).

    CPU time (user + sys) and peak RSS are the child's own, from os.wait4 (ru_maxrss is in
    KiB on Linux).
    """
    with open(log_path, "wb") as log:
        t0 = time.perf_counter()
        proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT)
        _, status, ru = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - t0
    return os.waitstatus_to_exitcode(status), wall, ru.ru_utime + ru.ru_stime, \
        ru.ru_maxrss / 1024.0


_RE_EQUATIONS = re.compile(r"-> \S+ \(modele\): \d+ elements, (\d+) equations")
_RE_FREE = re.compile(r"(?:RENUM|METHODE) (\w+): (\d+) free equations")
_RE_PROFILE = re.compile(r"profile (\d+) -> (\d+) terms, bandwidth (\d+) -> (\d+)")
_RE_TOTAL = re.compile(r"STAT_NON_LINE: (\d+) iteration\(s\), (\d+) factorization\(s\) "
                       r"in (\d+) step\(s\)")
_RE_ITER = re.compile(r"^\s+(\d+)\s+([0-9.Ee+-]+)\s+([0-9.Ee+-]+)\s+(ELASTIQUE|TANGENTE)\s+"
                      r"(factored|reused|updated)\s+(\d+)\s+(\d+)\s+([0-9.]+)\s*$")
_RE_CONTACT = re.compile(r"contact Newton: (\d+) solve\(s\) with a factor, (\d+) tangent\(s\) "
                         r"through another status's factor, (\d+) correction\(s\) damped")
_RE_ERROR = re.compile(r"error: (.*)$")


def parse_mess(path):
    """What the .mess says about the solve: a dict (missing items are None).

    Keys: equations, free_equations, renum, profile_before, profile_after, band_before,
    band_after, iterations, factorizations, steps, final_resi (RESI_GLOB_RELA of the last
    iteration line), iteration_lines, solve_s (sum of the TIME column; factored_s of the
    rows that factored, reused_s of the others), solves, updated, damped (the "contact
    Newton" line: solves with a factor, tangents through another status's factor, damped
    corrections), error (first line with 'error:'). free_equations and renum come from the
    "RENUM R: N free equations" line (LDLT) or "METHODE M: N free equations" (the others).
    """
    out = dict(equations=None, free_equations=None, renum=None, profile_before=None,
               profile_after=None, band_before=None, band_after=None, iterations=None,
               factorizations=None, steps=None, final_resi=None, iteration_lines=0,
               solve_s=0.0, factored_s=0.0, reused_s=0.0, solves=None, updated=None,
               damped=None, error=None)
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if (m := _RE_EQUATIONS.search(line)):
                out["equations"] = int(m.group(1))
            elif (m := _RE_FREE.search(line)):
                out["free_equations"] = int(m.group(2))
                if line.lstrip().startswith("RENUM"):
                    out["renum"] = m.group(1)
            elif (m := _RE_PROFILE.search(line)):
                (out["profile_before"], out["profile_after"], out["band_before"],
                 out["band_after"]) = (int(g) for g in m.groups())
            elif (m := _RE_TOTAL.search(line)):
                out["iterations"], out["factorizations"], out["steps"] = \
                    (int(g) for g in m.groups())
            elif (m := _RE_ITER.match(line)):
                out["final_resi"] = float(m.group(2))
                out["iteration_lines"] += 1
                out["solve_s"] += float(m.group(8))
                out["factored_s" if m.group(5) == "factored" else "reused_s"] += \
                    float(m.group(8))
            elif (m := _RE_CONTACT.search(line)):
                out["solves"], out["updated"], out["damped"] = (int(g) for g in m.groups())
            elif out["error"] is None and (m := _RE_ERROR.search(line)):
                out["error"] = m.group(1).strip()
    return out


def parse_resu(path):
    """VALE_CALC of each TEST_RESU block of a .resu: {(inst, group, component): value}.

    A block is ' ---- RESULTAT ...' (column titles), a line RESU NUME_ORDRE INST NOM_CHAM
    NOM_CMP GROUP_NO, the REFERENCE titles, then ' OK  ' / 'NOOK' lines whose fifth column
    is VALE_CALC.
    """
    values = {}
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].lstrip().startswith("---- RESULTAT") and i + 3 < len(lines):
            key_tokens = lines[i + 1].split()
            check = lines[i + 3].split()
            if len(key_tokens) >= 6 and len(check) >= 5 and check[0] in ("OK", "NOOK"):
                key = (float(key_tokens[2]), key_tokens[5], key_tokens[4])
                values[key] = float(check[4])
            i += 4
        else:
            i += 1
    return values


def exact_corners(ny, model="a"):
    """Exact discrete corner displacements (y = 0, y = b) at INST 1 for ny cells along y,
    for the load the model applies: model A's pressure is taken at the plate's nodes (as
    Code_Aster does), model B's edge load is integrated exactly."""
    ref = rigid_bed_exact.solve_rigid_bed(ny, load="nodes" if model == "a" else "exact")
    return ref["pt01"], ref["pt03"]


def rel_err(value, exact):
    """(value - exact) / |exact| in floating point."""
    return (value - float(exact)) / abs(float(exact))


def corner_errors(model, ny, values, inst=1.0):
    """Corner values and errors at `inst` from parse_resu's dict.

    Returns dict dz_y0, dz_yb (first corner of each edge), err_disc_y0, err_disc_yb,
    err_cont_y0, err_cont_yb (signed, relative) and err_disc_max, err_cont_max (largest
    |error| over every corner found); None where a corner is missing.
    """
    comp = COMPONENT[model]
    exact = exact_corners(ny, model)
    cont = (U_A_CONTINUOUS, U_B_CONTINUOUS)
    out = dict(dz_y0=None, dz_yb=None, err_disc_y0=None, err_disc_yb=None, err_cont_y0=None,
               err_cont_yb=None, err_disc_max=None, err_cont_max=None)
    disc_all, cont_all = [], []
    for edge, name in enumerate(("y0", "yb")):
        for k, group in enumerate(CORNERS[model][edge]):
            v = values.get((inst, group, comp))
            if v is None:
                continue
            ed, ec = rel_err(v, exact[edge]), rel_err(v, cont[edge])
            disc_all.append(abs(ed))
            cont_all.append(abs(ec))
            if k == 0:
                out[f"dz_{name}"], out[f"err_disc_{name}"], out[f"err_cont_{name}"] = v, ed, ec
    if disc_all:
        out["err_disc_max"], out["err_cont_max"] = max(disc_all), max(cont_all)
    return out


def run_case(parasol, workdir, name, args, repeat=1, repeat_below_s=1.0, model="a", ny=16):
    """Generate, run (one thread) and read one case; return a dict.

    The run is repeated up to `repeat` times while it takes less than repeat_below_s; the
    fastest run's wall/CPU time and its peak RSS are kept (the shared machine adds noise,
    never speed). Status: 'ok' (exit 0, every TEST_RESU OK), 'nook' (exit 2: ran, some
    TEST_RESU outside the generator's 1e-6 tolerance), 'error' (exit 1: stopped, e.g. no
    convergence; the .mess error line is in 'message').

    Errors: CaseError when the deck cannot be generated or parasol leaves no .mess.
    """
    base = os.path.join(workdir, name)
    comm, mail = generate(base, args)
    env = dict(os.environ, **ONE_THREAD)
    cmd = [parasol, "--unit", f"20={mail}", "--outdir", workdir, comm]
    best = None
    for _ in range(max(1, repeat)):
        rc, wall, cpu, rss = run_measured(cmd, workdir, env, base + ".log")
        if best is None or wall < best[1]:
            best = (rc, wall, cpu, rss)
        if wall >= repeat_below_s:
            break
    rc, wall, cpu, rss = best
    mess = base + ".mess"
    if not os.path.exists(mess):
        raise CaseError(f"{name}: parasol exit {rc} and no {mess}; see {base}.log")
    row = dict(rc=rc, wall_s=wall, cpu_s=cpu, maxrss_mb=rss)
    info = parse_mess(mess)
    row.update({k: v for k, v in info.items() if k != "iteration_lines"})
    if row["iterations"] is None and info["iteration_lines"] > 0:
        # Stopped (e.g. ITER_GLOB_MAXI): the iteration lines after the prediction (one step).
        row["iterations"] = info["iteration_lines"] - 1
    resu = base + ".resu"
    values = parse_resu(resu) if os.path.exists(resu) else {}
    row.update(corner_errors(model, ny, values))
    row["status"] = {0: "ok", 2: "nook"}.get(rc, "error")
    row["message"] = info["error"] or ""
    return row

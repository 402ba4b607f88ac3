#!/usr/bin/python3
"""Speed-accuracy study of parasol on the SSNL130 family (issue 7).

From a baseline (model A, 4 x 16 plate, full Newton, RESI_GLOB_RELA = 1e-6, RENUM = RCMK)
one knob is varied at a time:
  mesh    ny = 16, 32, ..., 512 with nx = ny/4 (model A, 3D) and the 2D slice (model B, same
          ny), as far as the time budget allows;
  newton  NEWTON MATRICE = ELASTIQUE (one factorization, modified Newton) vs TANGENTE with
          REAC_ITER = 1;
  resi    RESI_GLOB_RELA = 1e-3 ... 1e-10, for both NEWTON choices;
  renum   RENUM = RCMK, METIS, SANS.
The newton/resi/renum knobs are run on the baseline mesh and on each further --knob-meshes
mesh (default 32x128), where the solve, not the start-up, dominates the time.

Every case is one deck from tools/make_ssnl130_case.py (one load step to INST 1, no ground
lift, SOLVEUR NPREC = --nprec), run single-threaded (OMP_NUM_THREADS = OPENBLAS_NUM_THREADS
= 1). Recorded per run: wall and CPU time, peak RSS, equations, free equations, profile and
bandwidth after RENUM, iterations, factorizations, the last RESI_GLOB_RELA, and the corner
displacements' errors against the exact discrete rigid-plate answer (rigid_bed_exact.py) and
against the continuous bed (U_A = -4/1125, U_B = 4/3375).

Outputs in --outdir (default doc/study): study.csv, summary.md (the tables), and with
matplotlib error_vs_time.png, time_vs_equations.png, iterations_vs_tolerance.png.

The whole study (what doc/speed-accuracy.md reports), from the repository root:
    /usr/bin/python3 tests/bench/study/run_study.py --parasol build/parasol --budget 900
A tiny subset with checks (the CTest bench.study_small):
    /usr/bin/python3 tests/bench/study/run_study.py --small --check --outdir /tmp/study

Exit status: 0 done (and with --check every check passed); 1 a check failed or a case could
not be generated/read; 2 bad options.
"""
import argparse
import csv
import datetime
import math
import os
import platform
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import parasol_case as pc  # noqa: E402

BASELINE = dict(model="a", nx=4, ny=16, newton="tangente", resi=1e-6, renum="RCMK")
LADDER_NY = [16, 32, 64, 128, 256, 512]
RESI_VALUES = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]
RENUMS = ["RCMK", "METIS", "SANS"]
# ITER_GLOB_MAXI: Code_Aster's default 10 for full Newton; the elastic-matrix (modified
# Newton) iterations converge linearly (ratio ~0.6 on SSNL130), SSNL130 itself sets 60;
# 100 leaves room for RESI_GLOB_RELA = 1e-10.
ITER_MAX = {"tangente": 10, "elastique": 100}
# Growth of the run time with the number of equations, to estimate the next mesh of the
# ladder: skyline factorization ~ n b^2 with b ~ sqrt(n) on the plate (3D) and b constant
# on the slice (2D).
TIME_EXPONENT = {"a": 2.0, "b": 1.0}
COLUMNS = ["study", "knob_mesh", "model", "nx", "ny", "newton", "resi", "renum", "nprec",
           "status", "rc", "wall_s", "cpu_s", "maxrss_mb", "equations", "free_equations",
           "profile_after", "band_after", "profile_before", "band_before", "iterations",
           "factorizations", "final_resi", "solve_s", "factored_s", "reused_s", "dz_y0",
           "dz_yb", "err_disc_y0", "err_disc_yb", "err_disc_max", "err_cont_y0", "err_cont_yb",
           "err_cont_max",
           "message"]



class HelpFormatter(argparse.ArgumentDefaultsHelpFormatter,
                    argparse.RawDescriptionHelpFormatter):
    """--help shows each option's default, and the docstring as written."""

def mesh_label(p):
    """'A 4x16' / 'B 16'."""
    return f"A {p['nx']}x{p['ny']}" if p["model"] == "a" else f"B {p['ny']}"


def parse_mesh(text):
    """'32x128' -> (32, 128)."""
    try:
        nx, ny = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"bad mesh {text!r}: expected NXxNY, e.g. 32x128")
    if nx < 1 or ny < 1:
        raise argparse.ArgumentTypeError(f"bad mesh {text!r}: sizes must be >= 1")
    return nx, ny


class Study:
    """Runs cases (each distinct case once), keeps the rows and the time budget."""

    def __init__(self, o, workdir):
        self.o, self.workdir = o, workdir
        self.rows, self.cache, self.spent = [], {}, 0.0

    def case(self, study, knob_mesh, **changes):
        """Run the baseline with `changes` (or reuse an identical case) and keep a row."""
        p = dict(BASELINE, **changes)
        key = tuple(sorted(p.items()))
        if key not in self.cache:
            name = (f"{p['model']}_{p['nx']}x{p['ny']}_{p['newton']}_{p['resi']:.0e}_"
                    f"{p['renum']}").replace("+", "").replace("-", "m")
            args = pc.case_args(p["model"], p["nx"], p["ny"], p["newton"], p["resi"],
                                p["renum"], self.o.nprec, ITER_MAX[p["newton"]])
            r = pc.run_case(self.o.parasol, self.workdir, name, args, repeat=self.o.repeat,
                            repeat_below_s=self.o.repeat_below, model=p["model"], ny=p["ny"])
            self.spent += r["wall_s"]
            self.cache[key] = r
            print(f"{study:6s} {mesh_label(p):11s} {p['newton']:9s} {p['resi']:.0e} "
                  f"{p['renum']:5s} {r['status']:5s} wall {r['wall_s']:8.3f} s  "
                  f"it {r['iterations']} fact {r['factorizations']}  "
                  f"err {fmt(r['err_disc_max'], '.1e')}  {r['message'][:60]}", flush=True)
        row = dict(self.cache[key], study=study, knob_mesh=knob_mesh, nprec=self.o.nprec, **p)
        self.rows.append(row)
        return row

    def skipped(self, study, reason, **changes):
        """A row for a case the budget did not allow."""
        p = dict(BASELINE, **changes)
        self.rows.append(dict(p, study=study, knob_mesh="", nprec=self.o.nprec,
                              status="skipped", message=reason))
        print(f"{study:6s} {mesh_label(p):11s} skipped: {reason}", flush=True)


def run_knobs(st, nx, ny, resi_values, renums):
    """The newton, resi and renum knobs on one mesh of model A."""
    km = f"{nx}x{ny}"
    for newton in ("tangente", "elastique"):
        st.case("newton", km, nx=nx, ny=ny, newton=newton)
    for newton in ("tangente", "elastique"):
        for resi in resi_values:
            st.case("resi", km, nx=nx, ny=ny, newton=newton, resi=resi)
    for renum in renums:
        st.case("renum", km, nx=nx, ny=ny, renum=renum)


def run_ladder(st, model, ladder):
    """Mesh density for one model, stopping before a mesh estimated beyond the budget."""
    last = None
    for ny in ladder:
        nx = max(1, ny // 4)
        changes = dict(model=model, nx=nx if model == "a" else BASELINE["nx"], ny=ny)
        if last is not None:
            growth = (ny / last[0]) ** (2 if model == "a" else 1)
            est = last[1] * growth ** TIME_EXPONENT[model]
            left = st.o.budget - st.spent
            if est > st.o.max_run_seconds or est > left:
                st.skipped("mesh", f"estimated {est:.0f} s > per-run limit "
                           f"{st.o.max_run_seconds:g} s or budget left {left:.0f} s",
                           **changes)
                continue
        row = st.case("mesh", "", **changes)
        last = (ny, max(row["wall_s"], 1e-3))


def fmt(v, spec):
    """Format v, or '' for None."""
    return "" if v is None else format(v, spec)


def write_csv(path, rows):
    """study.csv: one row per (study, case), numbers with enough digits."""
    specs = dict(wall_s=".4f", cpu_s=".4f", maxrss_mb=".1f", final_resi=".3e", solve_s=".3f",
                 factored_s=".3f", reused_s=".3f",
                 dz_y0=".12e", dz_yb=".12e", err_disc_y0=".3e", err_disc_yb=".3e",
                 err_disc_max=".3e", err_cont_y0=".3e", err_cont_yb=".3e",
                 err_cont_max=".3e", resi=".0e")
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: fmt(r.get(k), specs[k]) if k in specs else
                        ("" if r.get(k) is None else r.get(k)) for k in COLUMNS})


INT_COLUMNS = {"nx", "ny", "nprec", "rc", "equations", "free_equations", "profile_after",
               "band_after", "profile_before", "band_before", "iterations", "factorizations"}
TEXT_COLUMNS = {"study", "knob_mesh", "model", "newton", "renum", "status", "message"}


def read_csv(path):
    """Rows of a study.csv back as typed dicts (for --replot)."""
    rows = []
    with open(path, newline="", encoding="utf-8") as f:
        for raw in csv.DictReader(f):
            row = {}
            for k, v in raw.items():
                if k in TEXT_COLUMNS:
                    row[k] = v
                elif v == "":
                    row[k] = None
                else:
                    row[k] = int(v) if k in INT_COLUMNS else float(v)
            rows.append(row)
    return rows


def fit_exponent(points, min_time):
    """Least-squares slope of log(time) against log(n) over points with time >= min_time
    (start-up dominates below); (slope, points used) or (None, 0)."""
    pts = [(math.log(n), math.log(t)) for n, t in points if n and t and t >= min_time]
    if len(pts) < 2:
        return None, len(pts)
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    if sxx == 0:
        return None, len(pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx, len(pts)


def ran(rows, **match):
    """Rows that ran (not skipped) and match every key."""
    return [r for r in rows if r["status"] != "skipped"
            and all(r.get(k) == v for k, v in match.items())]


def mesh_series(rows, model):
    """The mesh study rows of a model that ran to the end (ok or nook), by ny."""
    return sorted([r for r in ran(rows, study="mesh", model=model) if r["status"] != "error"],
                  key=lambda r: r["ny"])


def summary_markdown(rows, o, fits):
    """The tables of summary.md (and of doc/speed-accuracy.md)."""
    out = ["# parasol speed-accuracy study: raw tables", "",
           f"Generated by tests/bench/study/run_study.py on {o.stamp}; host {platform.node()}, "
           f"load average before/after {o.load_before} / {o.load_after}; parasol = "
           f"`{o.parasol}`; NPREC = {o.nprec}; one thread; best of {o.repeat} for runs "
           f"under {o.repeat_below:g} s. err_disc = largest |relative error| of the corners "
           "against the exact discrete answer; err_cont = against the continuous bed "
           "(-4/1125, 4/3375).", ""]
    head = ("| case | status | eqs (free) | profile | wall s | CPU s | RSS MB | iter | fact | "
            "last RESI | err_disc | err_cont |")
    sep = "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"

    def line(r, label):
        return (f"| {label} | {r['status']} | {fmt(r.get('free_equations'), 'd')} | "
                f"{fmt(r.get('profile_after'), 'd')} | {fmt(r.get('wall_s'), '.3f')} | "
                f"{fmt(r.get('cpu_s'), '.3f')} | {fmt(r.get('maxrss_mb'), '.0f')} | "
                f"{fmt(r.get('iterations'), 'd')} | {fmt(r.get('factorizations'), 'd')} | "
                f"{fmt(r.get('final_resi'), '.1e')} | {fmt(r.get('err_disc_max'), '.1e')} | "
                f"{fmt(r.get('err_cont_max'), '.1e')} |")

    out += ["## Mesh density (full Newton, RESI 1e-6, RCMK)", "", head, sep]
    for model in ("a", "b"):
        for r in sorted([r for r in rows if r["study"] == "mesh" and r["model"] == model],
                        key=lambda r: r["ny"]):
            if r["status"] == "skipped":
                out.append(f"| {mesh_label(r)} | skipped: {r['message']} |" + " |" * 10)
            else:
                out.append(line(r, mesh_label(r)))
    for model, (slope, n) in fits.items():
        out.append("")
        expo = "n/a (fewer than two runs)" if slope is None else f"n^{slope:.2f}"
        out.append(f"Model {model.upper()}: wall time ~ {expo} (least squares over the {n} "
                   f"runs of at least {o.fit_min_time:g} s; n = free equations).")
    for study, title, label in (("newton", "NEWTON", lambda r: r["newton"].upper()),
                                ("resi", "RESI_GLOB_RELA", lambda r: f"{r['newton'].upper()} "
                                 f"{r['resi']:.0e}"),
                                ("renum", "RENUM", lambda r: r["renum"])):
        meshes = sorted({r["knob_mesh"] for r in rows if r["study"] == study},
                        key=lambda m: [int(v) for v in m.split("x")])
        for km in meshes:
            out += ["", f"## {title} (model A {km})", "", head, sep]
            out += [line(r, label(r)) for r in rows
                    if r["study"] == study and r["knob_mesh"] == km]
    failed = [r for r in rows if r["status"] == "error"]
    if failed:
        out += ["", "## Runs that stopped", ""]
        seen = set()
        for r in failed:
            k = (mesh_label(r), r["newton"], r["resi"], r["renum"])
            if k not in seen:
                seen.add(k)
                out.append(f"- {k[0]} {k[1]} RESI {k[2]:.0e} {k[3]}: {r['message']}")
    return "\n".join(out) + "\n"


def knob_text(study, r):
    """The value of the knob a study varies, as printed beside its point."""
    if study == "mesh":
        return f"ny={r['ny']}"
    if study == "newton":
        return r["newton"][:4].upper()
    if study == "resi":
        return f"{r['resi']:.0e}"
    return str(r["renum"])


def plot_all(rows, outdir, fits, o):
    """The three PNG plots (matplotlib, Agg). Returns the files written."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    floor = 1e-12  # a zero error is drawn at the plot's floor
    files = []

    # 1. error vs time
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.2))
    styles = {"mesh": "o", "newton": "s", "resi": "^", "renum": "D"}
    for study, marker in styles.items():
        for km in sorted({r["knob_mesh"] for r in ran(rows, study=study)}):
            for model in ("a", "b"):
                pts = [r for r in ran(rows, study=study, knob_mesh=km, model=model)
                       if r.get("err_disc_max") is not None]
                if not pts:
                    continue
                lab = f"{study}" + (f" (A {km})" if km else f" (model {model.upper()})")
                ax1.loglog([r["wall_s"] for r in pts],
                           [max(r["err_disc_max"], floor) for r in pts], marker,
                           label=lab, alpha=0.8, fillstyle="none" if model == "b" else "full")
                # each point names the knob value it was run with (the legend only names
                # the series), so the 8 series can be read point by point
                for r in pts:
                    ax1.annotate(knob_text(study, r), (r["wall_s"], max(r["err_disc_max"], floor)),
                                 fontsize=5.5, xytext=(3, 2), textcoords="offset points",
                                 alpha=0.8)
    ax1.set_xlabel("wall time (s)")
    ax1.set_ylabel("largest corner |error| vs exact discrete answer")
    ax1.set_title("solver error (what RESI/NEWTON/RENUM control); points: knob value")
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=7)
    for model, marker in (("a", "o-"), ("b", "s--")):
        pts = [r for r in mesh_series(rows, model) if r.get("err_cont_max") is not None]
        if pts:
            ax2.loglog([r["wall_s"] for r in pts], [r["err_cont_max"] for r in pts], marker,
                       label=f"model {model.upper()} (mesh ladder)")
            for r in pts:
                ax2.annotate(f"ny={r['ny']}", (r["wall_s"], r["err_cont_max"]), fontsize=7,
                             xytext=(3, 3), textcoords="offset points")
    ax2.set_xlabel("wall time (s)")
    ax2.set_ylabel("largest corner |error| vs continuous bed")
    ax2.set_title("total error (what the mesh controls)")
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=8)
    fig.suptitle(f"parasol on SSNL130, one thread ({o.stamp}, load {o.load_after})",
                 fontsize=10)
    fig.tight_layout()
    files.append(os.path.join(outdir, "error_vs_time.png"))
    fig.savefig(files[-1], dpi=110)
    plt.close(fig)

    # 2. time vs equations
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.2))
    for model, marker in (("a", "o"), ("b", "s")):
        pts = mesh_series(rows, model)
        if not pts:
            continue
        n = [r["free_equations"] for r in pts]
        slope, used = fits[model]
        lab = f"model {model.upper()} wall" + (f", fit n^{slope:.2f} ({used} pts)"
                                               if slope is not None else "")
        ax1.loglog(n, [r["wall_s"] for r in pts], marker + "-", label=lab)
        ax1.loglog(n, [max(r["solve_s"] or 0.0, 1e-3) for r in pts], marker + ":",
                   label=f"model {model.upper()} STAT_NON_LINE iterations (TIME column)",
                   alpha=0.7)
        if slope is not None:
            big = [(x, r["wall_s"]) for x, r in zip(n, pts) if r["wall_s"] >= o.fit_min_time]
            x0, t0 = big[-1]
            xs = [big[0][0], big[-1][0]]
            ax1.loglog(xs, [t0 * (x / x0) ** slope for x in xs], "k--", lw=0.8, alpha=0.6)
        ax2.loglog(n, [r["maxrss_mb"] for r in pts], marker + "-",
                   label=f"model {model.upper()} peak RSS")
        # a run that stopped on an error has no completion time: it is drawn as a vertical
        # line at its size, labelled with how long it ran before stopping
        bad = [r for r in ran(rows, study="mesh", model=model) if r["status"] == "error"]
        for k, r in enumerate(bad):
            for ax in (ax1, ax2):
                ax.axvline(r["free_equations"], color="red", ls=":", lw=1.2,
                           label=(f"model {model.upper()} stopped (error)" if k == 0 else None))
            ax1.annotate(f"stopped after {r['wall_s']:.0f} s", (r["free_equations"], 0.5),
                         xycoords=("data", "axes fraction"), rotation=90, fontsize=7,
                         color="red", xytext=(-9, 0), textcoords="offset points",
                         va="center")
    ax1.set_xlabel("free equations")
    ax1.set_ylabel("time (s)")
    ax1.set_title("time vs problem size (full Newton, RESI 1e-6, RCMK)")
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=7)
    ax2.set_xlabel("free equations")
    ax2.set_ylabel("peak RSS (MB)")
    ax2.set_title("memory vs problem size")
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    files.append(os.path.join(outdir, "time_vs_equations.png"))
    fig.savefig(files[-1], dpi=110)
    plt.close(fig)

    # 3. iterations (and error) vs tolerance
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.2))
    for km in sorted({r["knob_mesh"] for r in ran(rows, study="resi")},
                     key=lambda m: [int(v) for v in m.split("x")]):
        for newton, marker in (("tangente", "o"), ("elastique", "s")):
            pts = sorted(ran(rows, study="resi", knob_mesh=km, newton=newton),
                         key=lambda r: -r["resi"])
            if not pts:
                continue
            lab = f"{newton.upper()} A {km}"
            line, = ax1.semilogx([r["resi"] for r in pts], [r["iterations"] or 0 for r in pts],
                                 marker + "-", label=lab)
            bad = [r for r in pts if r["status"] == "error"]
            if bad:
                ax1.semilogx([r["resi"] for r in bad], [r["iterations"] or 0 for r in bad],
                             "x", color="red", ms=10, label=f"{lab}: stopped, no convergence")
            good = [r for r in pts if r.get("err_disc_max") is not None]
            ax2.loglog([r["resi"] for r in good], [max(r["err_disc_max"], floor)
                                                   for r in good], marker + "-",
                       color=line.get_color(), label=lab)
    for ax in (ax1, ax2):
        ax.invert_xaxis()
        ax.set_xlabel("RESI_GLOB_RELA")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    ax1.set_ylabel("iterations after the prediction")
    ax1.set_title("iterations vs tolerance")
    ax2.set_ylabel("largest corner |error| vs exact discrete answer")
    ax2.set_title("error vs tolerance (converged runs)")
    fig.tight_layout()
    files.append(os.path.join(outdir, "iterations_vs_tolerance.png"))
    fig.savefig(files[-1], dpi=110)
    plt.close(fig)
    return files


def checks(rows):
    """--check: behaviours the study relies on; returns the failures (empty if none)."""
    bad = []
    base = [r for r in rows if r["study"] == "newton" and r["newton"] == "tangente"]
    if not base or base[0]["status"] != "ok":
        bad.append("the baseline (A 4x16, full Newton, RESI 1e-6, RCMK) did not pass its "
                   "TEST_RESU")
    for r in rows:
        if r["status"] == "skipped":
            continue
        if r.get("free_equations") is None or r.get("profile_after") is None:
            bad.append(f"{mesh_label(r)}: free equations/profile not found in the .mess")
        if r["status"] == "ok" and (r.get("err_disc_max") is None
                                    or r["err_disc_max"] > 1e-6):
            bad.append(f"{mesh_label(r)} {r['newton']} {r['resi']:.0e} {r['renum']}: "
                       f"status ok but corner error {r.get('err_disc_max')} > 1e-6")
    el = sorted([r for r in ran(rows, study="resi", newton="elastique")
                 if r.get("err_disc_max") is not None], key=lambda r: -r["resi"])
    if len(el) >= 2 and not el[-1]["err_disc_max"] < el[0]["err_disc_max"]:
        bad.append(f"ELASTIQUE: RESI {el[-1]['resi']:.0e} is not more accurate than "
                   f"{el[0]['resi']:.0e} ({el[-1]['err_disc_max']} vs {el[0]['err_disc_max']})")
    for r in ran(rows, newton="tangente"):
        if r["resi"] >= 1e-6 and r["status"] == "error":
            bad.append(f"{mesh_label(r)} full Newton RESI {r['resi']:.0e} {r['renum']} "
                       f"stopped: {r['message'][:120]}")
    fact = {r["newton"]: r.get("factorizations") for r in ran(rows, study="newton")}
    if fact.get("elastique") != 1:
        bad.append(f"ELASTIQUE should factor once, .mess says {fact.get('elastique')}")
    return bad


def load_average():
    """The 1-minute load average, as text."""
    try:
        return f"{os.getloadavg()[0]:.2f}"
    except OSError:
        return "n/a"


def replot(o):
    """--replot: summary.md and plots from an existing CSV (stamp and load from its summary)."""
    rows = read_csv(o.replot)
    o.stamp, o.load_before, o.load_after = "(from " + o.replot + ")", "n/a", "n/a"
    old = os.path.join(os.path.dirname(os.path.abspath(o.replot)), "summary.md")
    if os.path.exists(old):
        with open(old, encoding="utf-8") as f:
            text = f.read()
        for line in text.splitlines():
            if line.startswith("Generated by"):
                o.stamp = line.split(" on ", 1)[1].split(";", 1)[0]
                loads = line.split("load average before/after ", 1)[1].split(";", 1)[0]
                o.load_before, o.load_after = (v.strip() for v in loads.split("/"))
                o.parasol = line.split("parasol = `", 1)[1].split("`", 1)[0]
                break
    fits = {m: fit_exponent([(r["free_equations"], r["wall_s"]) for r in mesh_series(rows, m)],
                            o.fit_min_time) for m in ("a", "b")}
    os.makedirs(o.outdir, exist_ok=True)
    with open(os.path.join(o.outdir, "summary.md"), "w", encoding="utf-8") as f:
        f.write(summary_markdown(rows, o, fits))
    if not o.no_plots:
        for path in plot_all(rows, o.outdir, fits, o):
            print(f"wrote {path}")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=HelpFormatter)
    ap.add_argument("--parasol", default=os.path.join(pc.ROOT, "build", "parasol"),
                    help="parasol executable (the Release build)")
    ap.add_argument("--outdir", default=os.path.join(pc.ROOT, "doc", "study"),
                    help="CSV, summary and plots")
    ap.add_argument("--budget", type=float, default=900.0,
                    help="seconds of parasol runs for the whole study; the mesh ladder stops "
                         "before a mesh estimated beyond what is left")
    ap.add_argument("--max-run-seconds", type=float, default=300.0,
                    help="skip a mesh whose single run is estimated longer")
    ap.add_argument("--ladder", default=",".join(str(v) for v in LADDER_NY),
                    help="ny values of the mesh study (nx = ny/4 for model A)")
    ap.add_argument("--knob-meshes", default="32x128",
                    help="model A meshes, besides the baseline 4x16, for the newton/resi/"
                         "renum knobs (comma list, '' for none)")
    ap.add_argument("--nprec", type=int, default=11,
                    help="SOLVEUR NPREC (11: the pivots of the 128x512 plate lose ~10.5 digits; "
                         "Code_Aster's SSNL130 uses 9 at 4x16)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs shorter than --repeat-below are run this many times; the fastest "
                         "is kept")
    ap.add_argument("--repeat-below", type=float, default=1.0,
                    help="repeat runs shorter than this many seconds")
    ap.add_argument("--fit-min-time", type=float, default=0.1,
                    help="fit the time exponent over runs of at least this many seconds")
    ap.add_argument("--small", action="store_true",
                    help="tiny subset: ny 16, 32; RESI 1e-3, 1e-6; RCMK, SANS; no knob meshes")
    ap.add_argument("--check", action="store_true", help="exit 1 if a check fails")
    ap.add_argument("--no-plots", action="store_true", help="write the CSV and summary only")
    ap.add_argument("--keep", action="store_true", help="keep the decks and listings")
    ap.add_argument("--replot", metavar="CSV", default=None,
                    help="run nothing: rewrite summary.md and the plots from a study.csv")
    o = ap.parse_args(argv)
    o.parasol = os.path.abspath(o.parasol)
    if o.replot:
        return replot(o)
    if not os.access(o.parasol, os.X_OK):
        print(f"run_study: parasol executable {o.parasol!r} not found; build it (cmake "
              "--build build) or pass --parasol PATH", file=sys.stderr)
        return 2
    try:
        ladder = [int(v) for v in o.ladder.split(",") if v]
        knob_meshes = [parse_mesh(m) for m in o.knob_meshes.split(",") if m]
    except (ValueError, argparse.ArgumentTypeError) as exc:
        print(f"run_study: {exc}", file=sys.stderr)
        return 2
    resi_values, renums = RESI_VALUES, RENUMS
    if o.small:
        ladder, knob_meshes, resi_values, renums = [16, 32], [], [1e-3, 1e-6], ["RCMK", "SANS"]
        o.repeat = 1
    o.stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    o.load_before = load_average()
    os.makedirs(o.outdir, exist_ok=True)
    workdir = tempfile.mkdtemp(prefix="parasol_study_")
    st = Study(o, workdir)
    try:
        for nx, ny in [(BASELINE["nx"], BASELINE["ny"])] + knob_meshes:
            run_knobs(st, nx, ny, resi_values, renums)
        run_ladder(st, "b", ladder)
        run_ladder(st, "a", ladder)
    except pc.CaseError as exc:
        print(f"run_study: {exc}", file=sys.stderr)
        o.keep = True
        return 1
    finally:
        if o.keep:
            print(f"kept {workdir}", file=sys.stderr)
        else:
            shutil.rmtree(workdir, ignore_errors=True)
    o.load_after = load_average()
    fits = {m: fit_exponent([(r["free_equations"], r["wall_s"]) for r in mesh_series(st.rows, m)],
                            o.fit_min_time) for m in ("a", "b")}
    write_csv(os.path.join(o.outdir, "study.csv"), st.rows)
    with open(os.path.join(o.outdir, "summary.md"), "w", encoding="utf-8") as f:
        f.write(summary_markdown(st.rows, o, fits))
    if not o.no_plots:
        for path in plot_all(st.rows, o.outdir, fits, o):
            print(f"wrote {path}")
    print(f"wrote {os.path.join(o.outdir, 'study.csv')} and summary.md "
          f"({len(st.cache)} distinct runs, {st.spent:.1f} s of parasol)")
    if o.check:
        bad = checks(st.rows)
        for msg in bad:
            print(f"CHECK FAILED: {msg}", file=sys.stderr)
        if bad:
            return 1
        print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())

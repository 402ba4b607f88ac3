#!/usr/bin/python3
"""Measure the extremes decks for doc/stability.md: outcome, error, digits lost.

usage: measure.py PARASOL [--only NAME ...] [--markdown] [--bisect]

For every deck of cases/: the exit status and message of the run as written; the worst
relative error of DY/DZ against the deck's reference (recomputed from the printed values of
the .mess ANALYTIQUE lines); the digits the factorizations lost, as the .mess prints them
(`solver M: largest loss X digits`: with rigid modes kept apart, those of the matrix that is
factored and of the coarse matrix); and the digits the answer holds (the .mess line of the
last step: a solve with the final residual). --bisect (the tool as it was before parasol
printed the loss of a factorization that passes) finds the loss by running the deck again
with NPREC = 1..16 instead: the largest loss lies between the largest NPREC that still flags
a pivot and the smallest that does not. "-": no figure (the run stopped before). Not a test:
a measuring tool.
"""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_case  # noqa: E402

LOST = re.compile(r"pivot lost ([0-9.]+) digits")
LARGEST = re.compile(r"largest loss ([0-9.]+) digits")
HOLDS = re.compile(r"the answer holds ([0-9.]+) significant digits")
RIGID = re.compile(r"pivot ([-0-9.E+]+) against a largest diagonal term ([-0-9.E+]+)")


def run(parasol, deck_text, deck_dir, mesh, stem, work):
    path = os.path.join(work, stem + ".comm")
    with open(path, "w", encoding="utf-8") as f:
        f.write(deck_text)
    r = subprocess.run([parasol, "--unit", f"20={os.path.join(deck_dir, mesh)}", "--outdir",
                        work, path], capture_output=True, text=True, timeout=300)
    mess_path = os.path.join(work, stem + ".mess")
    mess = open(mess_path, encoding="utf-8").read() if os.path.exists(mess_path) else ""
    return r.returncode, r.stderr.strip(), mess


def worst_error(mess):
    worst = None
    for line in mess.splitlines():
        m = run_case.TEST_LINE.search(line)
        if m:
            ref, val = float(m.group(2)), float(m.group(3))
            err = abs(val - ref) / abs(ref) if ref != 0 else abs(val)
            worst = err if worst is None else max(worst, err)
    return worst


def flags_pivot(err):
    return bool(LOST.search(err) or RIGID.search(err))


def digits(parasol, text, deck_dir, mesh, stem, work):
    """(figure, low, high): digits lost as printed, and the NPREC bracket."""
    def at(k):
        t = re.sub(r"NPREC=\d+", f"NPREC={k}", text)
        return run(parasol, t, deck_dir, mesh, stem + f"_n{k}", work)[1]
    lo, hi = 0, 17                       # flags at lo (or lo = 0), clean at hi (or 17)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if flags_pivot(at(mid)):
            lo = mid
        else:
            hi = mid
    if lo == 0:
        return "< 1", lo, hi
    e = at(lo)
    m = LOST.search(e)
    if m:
        return m.group(1), lo, hi
    m = RIGID.search(e)
    if m:
        import math
        return f"{math.log10(abs(float(m.group(2)) / float(m.group(1)))):.1f} (rigid)", lo, hi
    return "-", lo, hi


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    ap.add_argument("parasol", help="the parasol executable")
    ap.add_argument("--only", nargs="*", default=None,
                    help="measure only these cases (None: all)")
    ap.add_argument("--markdown", action="store_true", help="rows as a markdown table")
    ap.add_argument("--bisect", action="store_true",
                    help="digits lost by NPREC bisection instead of the .mess figure")
    o = ap.parse_args(argv)
    parasol = os.path.abspath(o.parasol)
    deck_dir = os.path.join(HERE, "cases")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for deck in sorted(glob.glob(os.path.join(deck_dir, "*.comm"))):
            stem = os.path.splitext(os.path.basename(deck))[0]
            if o.only and stem not in o.only:
                continue
            info = run_case.header(deck)
            text = open(deck, encoding="utf-8").read()
            rc, err, mess = run(parasol, text, deck_dir, info["mesh"], stem, work)
            worst = worst_error(mess) if rc != 1 else None
            if o.bisect:
                fig, lo, hi = digits(parasol, text, deck_dir, info["mesh"], stem, work)
                fig = f"{fig} ({lo}-{hi})"
            else:
                m = LARGEST.findall(mess)
                fig = m[-1] if m else "-"
            holds = HOLDS.findall(mess)
            nprec = re.search(r"NPREC=(\d+)", text).group(1)
            msg = err.split("error: ", 1)[-1][:110] if err else ""
            error = "-" if worst is None else ("< 1e-12" if worst < 1e-12 else f"{worst:.1e}")
            rows.append((stem, info.get("why", ""), nprec, fig, holds[-1] if holds else "-",
                         error, rc, msg))
            sep = " | "
            line = sep.join(str(x) for x in rows[-1])
            print(f"| {line} |" if o.markdown else line, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

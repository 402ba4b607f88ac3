#!/usr/bin/env python3
"""A fuzz campaign: fuzz.py over several seeds, one after the other, and the table of
doc/stability.md ("Hostile input", the campaign) from their reports.

usage: campaign.py PARASOL [--compare PARASOL2] [--seeds 101,102,103,104] [--cases 5000]
                   [--jobs 2] [--timeout 60] [--work DIR]
       campaign.py --table REPORT.json...      (the table only, from reports already made)

Each seed S runs `fuzz.py PARASOL --compare PARASOL2 --seed S --cases N --work DIR/wS
--report DIR/seedS.json --quiet`; the table gives, per seed and in total, the cases, the count
of each class (clean, crash, hang, unlocated, nan, temporary, mismatch), the exit statuses and
the time, then the cases per seed input. Exit status 0 when every case of every seed is clean.
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fuzz  # noqa: E402

CLASSES = ("clean", "crash", "hang", "unlocated", "nan", "temporary", "mismatch")


def table(reports):
    lines = ["| seed | cases | " + " | ".join(CLASSES) + " | exit 0 / 1 / 2 | Release agrees |"
             " time |",
             "|---" * (len(CLASSES) + 5) + "|"]
    total = {"cases": 0, "seconds": 0.0, "classes": {}, "exit_statuses": {}, "agree": 0}
    inputs = {}
    for r in reports:
        st = r["exit_statuses"]
        # a clean case records the second build's status only through "mismatch"
        agree = None
        if r.get("compare"):
            agree = r["cases"] - sum(1 for c in r["not_clean"]
                                     if c.get("status_compare") != c["status"])
        lines.append("| %s | %d | %s | %d / %d / %d | %s | %.0f s |" % (
            r["seed"], r["cases"], " | ".join(str(r["classes"].get(c, 0)) for c in CLASSES),
            st.get("0", 0), st.get("1", 0), st.get("2", 0),
            "-" if agree is None else "%d / %d" % (agree, r["cases"]), r["seconds"]))
        total["cases"] += r["cases"]
        total["seconds"] += r["seconds"]
        total["agree"] += agree or 0
        for c, n in r["classes"].items():
            total["classes"][c] = total["classes"].get(c, 0) + n
        for s, n in st.items():
            total["exit_statuses"][s] = total["exit_statuses"].get(s, 0) + n
        for name, n in r["seed_inputs"].items():
            base = name.replace(" (export)", "")
            both = inputs.setdefault(base, [0, 0])
            both[0] += n
            if base != name:
                both[1] += n
    st = total["exit_statuses"]
    lines.append("| **all** | **%d** | %s | %d / %d / %d | %d / %d | %.0f s |" % (
        total["cases"], " | ".join("**%d**" % total["classes"].get(c, 0) for c in CLASSES),
        st.get("0", 0), st.get("1", 0), st.get("2", 0), total["agree"], total["cases"],
        total["seconds"]))
    lines.append("")
    lines.append("Cases per seed input (of which run through an export file with a time "
                 "limit): " + ", ".join("%s %d (%d)" % (k, v[0], v[1])
                                        for k, v in sorted(inputs.items())) + ".")
    clean = total["classes"].get("clean", 0) == total["cases"]
    return "\n".join(lines), clean


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("parasol", nargs="?")
    parser.add_argument("--compare")
    parser.add_argument("--seeds", default="101,102,103,104")
    parser.add_argument("--cases", type=int, default=5000)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--work", default="fuzz-campaign")
    parser.add_argument("--table", nargs="+", metavar="REPORT")
    opts = parser.parse_args(argv)
    if opts.table:
        reports = [json.load(open(p)) for p in opts.table]
    else:
        if not opts.parasol:
            parser.error("PARASOL is needed unless --table is given")
        os.makedirs(opts.work, exist_ok=True)
        reports = []
        for seed in [s for s in opts.seeds.split(",") if s]:
            report = os.path.join(opts.work, "seed%s.json" % seed)
            args = [opts.parasol, "--seed", seed, "--cases", str(opts.cases), "--jobs",
                    str(opts.jobs), "--timeout", str(opts.timeout), "--work",
                    os.path.join(opts.work, "w" + seed), "--report", report, "--keep", "100",
                    "--quiet"]
            if opts.compare:
                args += ["--compare", opts.compare]
            fuzz.main(args)
            reports.append(json.load(open(report)))
    text, clean = table(reports)
    print(text)
    return 0 if clean else 1


if __name__ == "__main__":
    sys.exit(main())

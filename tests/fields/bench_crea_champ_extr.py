#!/usr/bin/env python3
"""CREA_CHAMP OPERATION='EXTR' against the size of the field (issue 19, "Speed": EXTR is
O(n); doc/performance.md, "CALC_CHAMP on the 128 x 512 plate"). For each plate of SSNL130
model A (tools/make_ssnl130_case.py, MULT_FRONT), runs the case with CALC_CHAMP SIGM_ELNO
after the analysis (the base), and the same followed by N extractions of DEPL (a NOEU_DEPL_R
field, 6 components on every node) and N of SIGM_ELNO (an ELNO_SIEF_R field, 6 components
at 4 nodes x 3 sub-points of every plate cell); the CPU time (user + system, os.wait4) of
the second less the first, over 2 N, is the time of one extraction (with the DETRUIRE that
forgets it: a name given again keeps the concept it named). Best of --repeat runs.

  RESULT mesh=128x512 nodes=... cells=... values=... extr_ms=...

With --callgrind the extraction deck runs once under valgrind's callgrind, collecting only
inside CREA_CHAMP: the instructions of one extraction, a figure the machine's load does not
move (the analysis runs ~50 times slower under valgrind: take small plates).

  RESULT mesh=64x256 ... instructions_per_extr=...

usage: bench_crea_champ_extr.py PARASOL WORKDIR [--meshes 64x256,128x512] [--count N]
                                [--repeat R] [--callgrind]
"""
import re
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
BASE = """
RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, CONTRAINTE='SIGM_ELNO')
"""
LOOP = """
for k in range({count}):
    EXD = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=RESU,
                     NOM_CHAM='DEPL', INST=1.0)
    EXS = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='ELNO_SIEF_R', RESULTAT=RESU,
                     NOM_CHAM='SIGM_ELNO', INST=1.0)
    DETRUIRE(NOM=(EXD, EXS))
"""


def cpu_of(parasol, deck, workdir):
    """CPU seconds (user + system) of one run of `deck`."""
    proc = subprocess.Popen([parasol, "--quiet", "--outdir", workdir, deck],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    output = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.stdout.write(output)
        raise SystemExit("FAILED: %s" % deck)
    return usage.ru_utime + usage.ru_stime


def instructions_of(parasol, deck, workdir):
    """Instructions executed inside CREA_CHAMP in one run of `deck` (callgrind)."""
    out = os.path.join(workdir, "callgrind.out")
    proc = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out,
                           "--toggle-collect=__crea_champ_command_MOD_run_crea_champ",
                           parasol, "--quiet", "--outdir", workdir, deck],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    found = re.search(r"Collected : (\d+)", proc.stdout)
    if proc.returncode != 0 or not found:
        sys.stdout.write(proc.stdout[-3000:])
        raise SystemExit("FAILED under callgrind: %s" % deck)
    return int(found.group(1))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("parasol")
    parser.add_argument("workdir")
    parser.add_argument("--meshes", default="64x256,128x512")
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--callgrind", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    for mesh in args.meshes.split(","):
        nx, ny = (int(v) for v in mesh.split("x"))
        stem = os.path.join(args.workdir, "plate_%dx%d" % (nx, ny))
        if not os.path.exists(stem + ".comm"):
            subprocess.run([sys.executable, os.path.join(SOURCE, "tools", "make_ssnl130_case.py"),
                            "--model", "a", "--nx", str(nx), "--ny", str(ny), "--nprec", "12",
                            "--methode", "MULT_FRONT", "-o", stem], check=True,
                           stdout=subprocess.DEVNULL)
        text = open(stem + ".comm").read()
        decks = {}
        for name, extra in (("base", BASE), ("extr", BASE + LOOP.format(count=args.count))):
            deck = "%s_%s.comm" % (stem, name)
            with open(deck, "w") as f:
                f.write(text.replace("FIN()", extra.strip() + "\nFIN()"))
            if not os.path.exists("%s_%s.mail" % (stem, name)):
                os.symlink(os.path.basename(stem + ".mail"), "%s_%s.mail" % (stem, name))
            decks[name] = deck
        nodes = (nx + 1) * (ny + 1)
        cells = nx * ny
        values = nodes * 6 + cells * 4 * 3 * 6
        if args.callgrind:
            count = instructions_of(args.parasol, decks["extr"], args.workdir)
            print("RESULT mesh=%s nodes=%d cells=%d values=%d instructions_per_extr=%d "
                  "per_value=%.2f" % (mesh, nodes, cells, values, count // (2 * args.count),
                                      count / (2.0 * args.count) / values), flush=True)
            continue
        base = min(cpu_of(args.parasol, decks["base"], args.workdir)
                   for _ in range(args.repeat))
        extr = min(cpu_of(args.parasol, decks["extr"], args.workdir)
                   for _ in range(args.repeat))
        print("RESULT mesh=%s nodes=%d cells=%d values=%d base_cpu=%.2f extr_cpu=%.2f "
              "extr_ms=%.3f" % (mesh, nodes, cells, values, base, extr,
                                1000.0 * (extr - base) / (2 * args.count)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

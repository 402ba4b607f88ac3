#!/usr/bin/env python3
"""CALC_CHAMP on the 128 x 512 plate of SSNL130 model A (doc/performance.md, "CALC_CHAMP"):
writes the case with tools/make_ssnl130_case.py (once, in WORKDIR), runs it as written
(the analysis: reading the mesh, the model, STAT_NON_LINE) and again with, after the
analysis, CALC_CHAMP EFGE_NOEU and SIGM_ELNO of the plate, POST_CHAMP of the top face of
SIGM_ELNO and CALC_CHAMP SIGM_NOEU of it; prints the analysis's wall time and the times CALC_CHAMP and
POST_CHAMP report in the .mess, and their share of the analysis:

  RESULT analysis_seconds=A efge_sigm_elno_seconds=B sigm_noeu_seconds=C share=(B+C)/A
         analysis_cpu=D efge_sigm_elno_cpu=E sigm_noeu_cpu=F share_cpu=(E+F)/D

(wall times: the analysis's run and CALC_CHAMP's .mess lines; CPU seconds: CALC_CHAMP's
.mess lines against the rest of the same process, the steadier figure on a shared machine).

usage: bench_calc_champ.py PARASOL WORKDIR [--repeat N] [--nx NX --ny NY]
"""
import argparse
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
EXTRA = """
RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, CONTRAINTE=('EFGE_NOEU', 'SIGM_ELNO'))
TOP = POST_CHAMP(RESULTAT=RESU, EXTR_COQUE=_F(NOM_CHAM='SIGM_ELNO', NUME_COUCHE=1,
                                              NIVE_COUCHE='SUP'))
TOP = CALC_CHAMP(reuse=TOP, RESULTAT=TOP, CONTRAINTE='SIGM_NOEU')
FIN()
"""


def run(parasol, deck, workdir):
    """Wall and CPU (user + system) seconds of one run."""
    start = time.monotonic()
    proc = subprocess.Popen([parasol, "--quiet", "--outdir", workdir, deck],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    output = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    elapsed = time.monotonic() - start
    if os.waitstatus_to_exitcode(status) not in (0, 2):
        sys.stdout.write(output)
        sys.exit(1)
    return elapsed, usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("parasol")
    parser.add_argument("workdir")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--nx", type=int, default=128)
    parser.add_argument("--ny", type=int, default=512)
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    stem = os.path.join(args.workdir, "plate_%dx%d" % (args.nx, args.ny))
    if not os.path.exists(stem + ".comm"):
        subprocess.run([sys.executable, os.path.join(SOURCE, "tools", "make_ssnl130_case.py"),
                        "--model", "a", "--nx", str(args.nx), "--ny", str(args.ny),
                        "--nprec", "12", "--methode", "MULT_FRONT", "-o", stem], check=True,
                       stdout=subprocess.DEVNULL)
    text = open(stem + ".comm").read()
    fields = stem + "_fields.comm"
    with open(fields, "w") as f:
        f.write(text.replace("FIN()", EXTRA.strip() + "\n"))
    os.symlink(os.path.basename(stem + ".mail"), stem + "_fields.mail") \
        if not os.path.exists(stem + "_fields.mail") else None
    best = None
    cpu = None
    for _ in range(args.repeat):
        analysis, analysis_cpu = run(args.parasol, stem + ".comm", args.workdir)
        _, fields_cpu = run(args.parasol, fields, args.workdir)
        mess = open(stem + "_fields.mess").read()
        calc = [float(t) for t in re.findall(r"CALC_CHAMP: .* instant\(s\), ([0-9.]+) s", mess)]
        calc_cpu = [float(t) for t in re.findall(r"CALC_CHAMP: .* s \(CPU ([0-9.]+) s\)",
                                                 mess)]
        if len(calc) != 2 or len(calc_cpu) != 2:
            print("no CALC_CHAMP times in", stem + "_fields.mess")
            return 1
        figures = (analysis, calc[0], calc[1])
        if best is None or figures[1] + figures[2] < best[1] + best[2]:
            best = figures
        # CPU, steadier than wall times on a shared machine: CALC_CHAMP's own (the .mess)
        # against the rest of the same process (the analysis, with POST_CHAMP)
        figures_cpu = (fields_cpu - sum(calc_cpu), calc_cpu[0], calc_cpu[1])
        if cpu is None or sum(figures_cpu[1:]) < sum(cpu[1:]):
            cpu = figures_cpu
    share = (best[1] + best[2]) / best[0]
    print("RESULT analysis_seconds=%.2f efge_sigm_elno_seconds=%.3f sigm_noeu_seconds=%.3f "
          "share=%.3f analysis_cpu=%.2f efge_sigm_elno_cpu=%.3f sigm_noeu_cpu=%.3f "
          "share_cpu=%.3f" % (best[0], best[1], best[2], share, cpu[0], cpu[1], cpu[2],
                              (cpu[1] + cpu[2]) / cpu[0]))
    return 0 if share < 0.10 else 1


if __name__ == "__main__":
    sys.exit(main())

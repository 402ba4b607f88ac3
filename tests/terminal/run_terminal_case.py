#!/usr/bin/python3
"""What parasol prints on the terminal (doc/analysis.md "Progress"; README "Using parasol").

Usage: run_terminal_case.py PARASOL WORKDIR [--bench]

Default checks, on a small SSNL130 case made by tools/make_ssnl130_case.py (3 steps):
 - standard output (a pipe, not a terminal): the STAT_NON_LINE line, one line per step with
   INST, iterations, RESI_GLOB_RELA, springs closed and changed, factorizations and the wall
   time, then the one-line summary (TEST_RESU counts, listings, time); nothing on stderr, no
   carriage return;
 - the Newton table's TIME column: per step its rows add up to at most the step's wall time
   ("wall time of the step" in the .mess), and the steps to at most the run's wall time;
 - --quiet: nothing at all on stdout or stderr, same listings;
 - a deck that cannot be opened: one error line on stderr, `parasol: error: cannot open the
   deck PATH: No such file or directory`, the reason said once, exit 1, no .mess created.
--bench (label bench, a Release build): the 64 x 256 case (--nprec 11) run under a
pseudo-terminal and through a pipe: the first line within 2 s, work under way redrawn with
carriage returns on the terminal and as rate-limited plain lines in the pipe, one line per
step, and the .mess growing while the run goes (its temporary file shows the step's Newton
table before the run ends).
"""
import os
import pty
import re
import select
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MAKE_CASE = os.path.join(HERE, "..", "..", "tools", "make_ssnl130_case.py")
STEP_LINE = re.compile(r"^INST \S+ \(step (\d+)/(\d+)\): \d+ iteration\(s\), "
                       r"RESI_GLOB_RELA \S+, \d+ of \d+ springs closed \(\d+ changed\), "
                       r"\d+ factorization\(s\), [0-9.]+ s$")
SUMMARY = re.compile(r"^parasol: \S+\.comm: (\d+) TEST_RESU OK, 0 NOOK; listings (\S+)\.mess, "
                     r"(\S+)\.resu \([0-9.]+ s\)$")
problems = []


def check(condition, what):
    if not condition:
        problems.append(what)


def make_case(workdir, stem, args):
    os.makedirs(workdir, exist_ok=True)
    out = os.path.join(workdir, stem)
    subprocess.run([sys.executable, MAKE_CASE, *args, "-o", out], check=True,
                   stdout=subprocess.DEVNULL)
    return out + ".comm"


def step_lines(lines, n_steps, label):
    found = [m for m in (STEP_LINE.match(x) for x in lines) if m]
    check([(int(m.group(1)), int(m.group(2))) for m in found] ==
          [(k, n_steps) for k in range(1, n_steps + 1)],
          f"{label}: one line per step expected, got {[m.group(0) for m in found]}")


def time_column(mess_path, run_seconds):
    """TIME rows of each step add up to at most its wall time; steps to the run's."""
    with open(mess_path) as f:
        text = f.read()
    steps = text.split("\n    INST ")[1:]
    check(len(steps) > 0, f"{mess_path}: no step table")
    total = 0.0
    for block in steps:
        rows = re.findall(r"^ +\d+ +\S+ +\S+ +\S+ +(?:factored|reused) +\d+ +\d+ +([0-9.]+)$",
                          block, re.M)
        wall = re.search(r"wall time of the step: ([0-9.]+) s", block)
        check(rows and wall, f"{mess_path}: step without TIME rows or wall time")
        if rows and wall:
            total_rows = sum(float(r) for r in rows)
            # each printed value is rounded to 1 ms
            check(total_rows <= float(wall.group(1)) + 0.0005 * (len(rows) + 1),
                  f"{mess_path}: TIME rows add up to {total_rows} s, more than the step's "
                  f"wall time {wall.group(1)} s")
            total += float(wall.group(1))
    check(total <= run_seconds + 0.01,
          f"{mess_path}: steps take {total} s, more than the run ({run_seconds:.3f} s)")


def default_checks(parasol, workdir):
    deck = make_case(workdir, "progress", ["--model", "a", "--nx", "4", "--ny", "16",
                                           "--lift", "5e-3"])
    os.chdir(workdir)
    t0 = time.monotonic()
    run = subprocess.run([parasol, deck], capture_output=True, text=True, timeout=120)
    seconds = time.monotonic() - t0
    out = run.stdout.splitlines()
    check(run.returncode == 0, f"exit {run.returncode}: {run.stderr}")
    check(run.stderr == "", f"stderr not empty: {run.stderr!r}")
    check("\r" not in run.stdout, "a carriage return in piped output")
    check(bool(out) and out[0].startswith("STAT_NON_LINE: "), f"first line: {out[:1]}")
    step_lines(out, 3, "piped run")
    summary = SUMMARY.match(out[-1]) if out else None
    check(summary is not None, f"last line is not the summary: {out[-1:]}")
    if summary:
        # 4 points x 2 instants x (non-regression + reference)
        check(summary.group(1) == "16", f"summary counts: {out[-1]}")
        check(summary.group(2) == "progress" and summary.group(3) == "progress",
              f"summary listings: {out[-1]}")
    time_column("progress.mess", seconds)

    with open("progress.resu") as f:
        resu = f.read()
    quiet = subprocess.run([parasol, "--quiet", deck], capture_output=True, text=True,
                           timeout=120)
    check(quiet.returncode == 0, f"--quiet: exit {quiet.returncode}")
    check(quiet.stdout == "" and quiet.stderr == "",
          f"--quiet printed {quiet.stdout!r} {quiet.stderr!r}")
    with open("progress.resu") as f:
        check(f.read() == resu, "--quiet: another .resu")

    os.makedirs("missing", exist_ok=True)
    bad = subprocess.run([parasol, "--outdir", "missing", "no_such_deck.comm"],
                         capture_output=True, text=True, timeout=60)
    check(bad.returncode == 1, f"missing deck: exit {bad.returncode}")
    check(bad.stdout == "", f"missing deck: stdout {bad.stdout!r}")
    check(bad.stderr == "parasol: error: cannot open the deck no_such_deck.comm: "
          "No such file or directory\n", f"missing deck: stderr {bad.stderr!r}")
    check(os.listdir("missing") == [], f"missing deck: files written {os.listdir('missing')}")


def read_pty(fd, proc, t0, events, partial_glob):
    """Reads a pseudo-terminal until the process ends; records (seconds, text) chunks and
    whether the .mess temporary file held a Newton row while the run went on."""
    import glob
    buf = b""
    seen_row = None
    while True:
        ready, _, _ = select.select([fd], [], [], 0.2)
        if ready:
            try:
                data = os.read(fd, 4096)
            except OSError:
                data = b""
            if not data and proc.poll() is not None:
                break
            events.append((time.monotonic() - t0, data.decode(errors="replace")))
            buf += data
        elif proc.poll() is not None:
            break
        if seen_row is None:
            for path in glob.glob(partial_glob):
                with open(path, errors="replace") as f:
                    if re.search(r"^ +0 +\S+ +\S+ +\S+ +factored", f.read(), re.M):
                        seen_row = time.monotonic() - t0
    return buf.decode(errors="replace"), seen_row


def bench_checks(parasol, workdir):
    deck = make_case(workdir, "case64", ["--model", "a", "--nx", "64", "--ny", "256",
                                         "--nprec", "11"])
    os.chdir(workdir)
    # a pseudo-terminal: progress redrawn in place
    master, slave = pty.openpty()
    t0 = time.monotonic()
    proc = subprocess.Popen([parasol, deck], stdout=slave, stderr=slave, close_fds=True)
    os.close(slave)
    events = []
    text, row_at = read_pty(master, proc, t0, events, "case64.mess.*.partial")
    proc.wait()
    total = time.monotonic() - t0
    first = events[0][0] if events else None
    print(f"terminal run: {total:.1f} s, first output after {first} s, Newton row in the "
          f".mess temporary file after {row_at} s")
    check(proc.returncode == 0, f"terminal run: exit {proc.returncode}")
    check(first is not None and first <= 2.0, f"terminal run: first output after {first} s")
    check("\r" in text, "terminal run: no progress line redrawn in place")
    lines = [x.split("\r")[-1].strip() for x in text.replace("\r\n", "\n").split("\n")]
    step_lines([x for x in lines if x], 1, "terminal run")
    check(row_at is not None and row_at < total - 0.5,
          f"the .mess showed the Newton table only at {row_at} s of {total:.1f} s")
    # a pipe: plain progress lines
    t0 = time.monotonic()
    proc = subprocess.Popen([parasol, deck], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    first_line = proc.stdout.readline()
    first = time.monotonic() - t0
    rest, err = proc.communicate(timeout=600)
    out = (first_line + rest).splitlines()
    print(f"piped run: first line after {first:.2f} s; {len(out)} lines")
    for line in out:
        print("  | " + line)
    check(proc.returncode == 0, f"piped run: exit {proc.returncode}: {err}")
    check(first <= 2.0, f"piped run: first line after {first:.2f} s")
    check(any(re.search(r"\(\d+\.\d s\)$", x) and "STAT_NON_LINE, INST" in x for x in out),
          "piped run: no plain progress line of the work under way")
    step_lines(out, 1, "piped run")


def main():
    parasol, workdir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    if "--bench" in sys.argv[3:]:
        bench_checks(parasol, workdir)
    else:
        default_checks(parasol, workdir)
    for p in problems:
        print("FAIL:", p)
    print(f"run_terminal_case: {len(problems)} failures")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()

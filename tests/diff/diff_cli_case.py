"""One CLI test case of parasol-diff (tests/diff/CMakeLists.txt registers each as diff.<case>).
Usage: diff_cli_case.py PARASOL_DIFF CASE SOURCE_DIR WORK_DIR
Each case runs parasol-diff on listing pairs of this folder and checks the exit status, the
messages, and that no Fortran runtime error text ever appears."""
import glob
import os
import shutil
import subprocess
import sys
import time

exe, case, src, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
failures = []


def run(*args):
    proc = subprocess.run([exe, *args], capture_output=True, text=True, errors="replace",
                          cwd=work, timeout=60)
    for bad in ("Fortran runtime", "Backtrace", "SIGFPE", "At line"):
        if bad in proc.stdout or bad in proc.stderr:
            failures.append(f"runtime error text {bad!r} in output:\n{proc.stdout}{proc.stderr}")
    return proc


def expect(proc, status, out=(), err=()):
    if proc.returncode != status:
        failures.append(f"exit status {proc.returncode}, expected {status}")
    for text in out:
        if text not in proc.stdout:
            failures.append(f"stdout lacks {text!r}:\n{proc.stdout}")
    for text in err:
        if text not in proc.stderr:
            failures.append(f"stderr lacks {text!r}:\n{proc.stderr}")


def here(name):
    return os.path.join(src, name)


ref = here("reference.resu")
if case == "identical":
    expect(run(ref, ref), 0, out=["parasol-diff: identical within rtol=1.00E-09 atol=1.00E-15"])
elif case == "within_rtol":
    expect(run(here("within_tolerance.resu"), ref), 0, out=["identical within"])
    p = run(here("within_tolerance.resu"), ref, "--rtol", "1e-14", "--atol=0")
    expect(p, 1, out=["4: expected -3.532908704883E-03 got -3.532908704884E-03",
                      "10: expected 1.250000000000E-05 got +1.250000000001E-05",
                      "11: expected 1.000000000000E-17 got 0.0",
                      "parasol-diff: 3 differences in 3 lines"])
elif case == "beyond_rtol":
    p = run(here("beyond_tolerance.resu"), ref)
    expect(p, 1, out=["11: expected 4.400000000000E+02 got 4.400004400000E+02",
                      "parasol-diff: 1 differences in 1 lines"])
elif case == "missing_line":
    p = run(here("missing_line.resu"), ref)
    expect(p, 1, out=["9: expected line 9 of the reference \" N1 ", "(missing line)",
                      "parasol-diff: 1 differences in 1 lines"])
    p = run(ref, here("missing_line.resu"))
    expect(p, 1, out=["9: expected no line got \" N1 ", "(extra line)"])
elif case == "missing_file":
    p = run(here("no_such_file.resu"), ref)
    expect(p, 1, err=["parasol-diff: error: cannot read "])
    if p.stderr.count("\n") != 1:
        failures.append(f"expected one line on stderr, got:\n{p.stderr}")
    expect(run(ref, src), 1, err=["parasol-diff: error: cannot read " + src])
    expect(run(here("binary.resu"), ref), 1, err=["binary file"])
elif case == "usage":
    expect(run(ref), 1, err=["parasol-diff: error: expected two files", "usage:"])
    expect(run(ref, ref, "--rtol", "abc"), 1, err=["--rtol needs a non-negative number"])
    expect(run(ref, ref, "--atol"), 1, err=["--atol needs a value"])
    expect(run(ref, ref, "--bogus"), 1, err=["unknown option \"--bogus\""])
    expect(run("--help"), 0, out=["usage: parasol-diff RESULT REFERENCE"])
elif case == "update":
    target = os.path.join(work, "accepted.resu.ref")
    shutil.copyfile(ref, target)
    result = here("beyond_tolerance.resu")
    expect(run(result, target, "--update"), 0,
           out=["11: expected 4.400000000000E+02 got 4.400004400000E+02", "updated"])
    with open(result) as a, open(target) as b:
        if a.read() != b.read():
            failures.append("--update did not copy RESULT over REFERENCE")
    if glob.glob(target + "*.partial"):
        failures.append("--update left its temporary file")
    expect(run(result, target), 0, out=["identical within"])
elif case == "large_files":
    # 20000 lines of 8 numbers and a 200000-character line; two differences.
    a = os.path.join(work, "large.resu")
    b = os.path.join(work, "large.resu.ref")
    rows = [" N%d " % i + " ".join("%.12E" % (i * 1.37 + k) for k in range(8))
            for i in range(20000)]
    with open(b, "w") as f:
        f.write("\n".join(rows) + "\n" + "x" * 200000 + "\n")
    rows[123] = rows[123].replace("E", "D")
    rows[19000] = rows[19000] + " 1.0"
    with open(a, "w") as f:
        f.write("\n".join(rows) + "\n" + "x" * 200000 + "\n")
    start = time.perf_counter()
    p = run(a, b)
    elapsed = time.perf_counter() - start
    expect(p, 1, out=["19001: expected end of line got 1.0 (token 10)",
                      "parasol-diff: 1 differences in 1 lines"])
    print(f"large_files: 20000 lines x 8 numbers compared in {elapsed:.2f} s")
else:
    failures.append(f"unknown case {case}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)

#!/usr/bin/env python3
"""Faults on the way out (issue 23, doc/stability.md "Faults"), run by CTest.

Every case runs a deck made from decks/ssnl130a.comm (its TEST_RESU and IMPR_RESU RESULTAT)
with outputs added as the KIND asks, first into a roomy folder (the reference files), then
with a fault injected, and checks what a user relies on:
  - exit status 0 with every file complete (equal to the reference; the .mess ends with its
    verdict), or exit status 1 with exactly one line on stderr, naming the file that could
    not be written and the system's reason;
  - no signal, no Fortran runtime error, no backtrace, no HDF5 or MED noise;
  - no file under a final name that is empty or truncated (every file left is either equal
    to the reference or a .mess that ends with its verdict), no `.partial` left behind;
  - a run that fails leaves the older .resu of that name as it was.

usage:
  faults.py dev-full PARASOL SOURCE_DIR WORKDIR KIND
      Each output of KIND in turn is a symbolic link to /dev/full (ENOSPC on the first
      write): exit 1, one line "cannot write PATH: No space left on device", the link left
      in place (not replaced by a file). KIND: listings (.mess, .resu), vtk (.pvd, .vtu),
      gmsh (.msh), med (.rmed), unit (a Gmsh file bound with --unit N=PATH), table
      (IMPR_TABLE to a unit), fonction (IMPR_FONCTION TABLEAU and AGRAF, its two units),
      fields (IMPR_RESU of Gauss-point fields and a CHAM_GD in MED, the CHAM_GD in VTK),
      gibi (PRE_GIBI's .mail).
  faults.py sweep PARASOL SOURCE_DIR WORKDIR KIND FIRST_KB LAST_KB STEP_KB
      The output folder is a tmpfs of FIRST_KB, FIRST_KB + STEP_KB, ... LAST_KB kilobytes
      (mount(8): needs root; skipped with exit 77 and a message otherwise), so that each
      output in turn meets a full disk. KIND: all (MED and VTK, issue 23's sweep) or resu
      (the listings only).
  faults.py ulimit PARASOL SOURCE_DIR WORKDIR KIND FIRST_KB LAST_KB STEP_KB
      The same sweep without root: a file size limit (ulimit -f) instead of a small disk;
      a write past it fails with EFBIG ("File too large").
  faults.py med-flip PARASOL SOURCE_DIR WORKDIR ASTER_DIR
      Issue 23's byte flip: byte 34 789 of Code_Aster's zzzz393a.mmed, 0x00 -> 0x04, made
      HDF5 free a bad pointer under MEDnFamilyGroup (SIGSEGV, no message, .partial files
      left). Read alone (LIRE_MAILLAGE in a deck that does nothing else): exit 1, one line
      "... MED file PATH is damaged: ...", no temporary left; the file unflipped reads.
      Skipped (exit 77) when ASTER_DIR/astest/zzzz393a.mmed is absent.
  faults.py export-lines PARASOL SOURCE_DIR WORKDIR
      Issue 23's three export result lines, each an error located at CASE.export:LINE
      before the run, its .mess kept: a result in a folder that does not exist (the .mess
      then goes to the output folder), a result line naming a folder, the .mess and the
      .resu on one file (the .mess holds the error there).
  faults.py folders PARASOL SOURCE_DIR WORKDIR
      DEFI_FICHIER into REPE_OUT/ (made in the output folder, as Code_Aster's runner makes
      it in its working directory) is written there; MED and IMPR_TABLE into a folder that
      does not exist stop with one line naming the file and the folder.
  faults.py interrupt PARASOL SOURCE_DIR WORKDIR
      SIGINT and SIGTERM during a run (a 32 x 128 plate caught in its first step): the
      listings of an earlier run stay byte for byte, no `.partial` is left, and the process
      ends by the signal.
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import time

SKIP = 77
CRASH_SIGNS = ("Fortran runtime", "Backtrace", "ERROR STOP", "Segmentation", "double free",
               "Program received signal", "HDF5-DIAG", "Erreur", "runtime error")
STEM = "faults"


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def make_deck(source_dir, workdir, kind):
    """decks/ssnl130a.comm with the outputs of KIND before its FIN()."""
    with open(os.path.join(source_dir, "decks", "ssnl130a.comm")) as f:
        text = f.read()
    extra = {
        "listings": "",
        "resu": "",
        "vtk": "IMPR_RESU(FORMAT='VTK', RESU=_F(RESULTAT=RESU))\n",
        "gmsh": "IMPR_RESU(FORMAT='GMSH', RESU=_F(RESULTAT=RESU))\n",
        "med": "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU))\n",
        "unit": "IMPR_RESU(FORMAT='GMSH', UNITE=81, RESU=_F(RESULTAT=RESU))\n",
        "all": "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU))\n"
               "IMPR_RESU(FORMAT='VTK', RESU=_F(RESULTAT=RESU))\n",
        # IMPR_TABLE to an unbound unit (its file STEM.38 in the output folder)
        "table": "TAB_F = CREA_TABLE(LISTE=(_F(PARA='INST', LISTE_R=(0.0, 1.0)),\n"
                 "                          _F(PARA='DX', LISTE_R=(1.5, -2.5))))\n"
                 "IMPR_TABLE(TABLE=TAB_F, UNITE=38)\n",
        # IMPR_FONCTION: TABLEAU to unit 29, AGRAF to units 25 and 26 (values, directives)
        "fonction": "FON_F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 2.0))\n"
                    "IMPR_FONCTION(FORMAT='TABLEAU', UNITE=29, COURBE=_F(FONCTION=FON_F))\n"
                    "IMPR_FONCTION(FORMAT='AGRAF', UNITE=25, UNITE_DIGR=26,\n"
                    "              COURBE=_F(FONCTION=FON_F))\n",
        # IMPR_RESU of fields: element fields at Gauss points in MED (unit 82), a CHAM_GD
        # in MED (83) and in VTK
        "fields": "TEMP_F = CREA_CHAMP(OPERATION='AFFE', TYPE_CHAM='NOEU_TEMP_R', MAILLAGE=MAIL,\n"
                  "                    AFFE=_F(TOUT='OUI', NOM_CMP='TEMP', VALE=20.0))\n"
                  "IMPR_RESU(FORMAT='MED', UNITE=82, RESU=_F(RESULTAT=RESU,\n"
                  "          NOM_CHAM=('SIEF_ELGA', 'VARI_ELGA')))\n"
                  "IMPR_RESU(FORMAT='MED', UNITE=83, RESU=_F(CHAM_GD=TEMP_F))\n"
                  "IMPR_RESU(FORMAT='VTK', RESU=_F(CHAM_GD=TEMP_F))\n",
        # PRE_GIBI: a GIBI file converted to a .mail on unit 21 (its file STEM.21)
        "gibi": "PRE_GIBI(UNITE_GIBI=19, UNITE_MAILLAGE=21)\n",
    }[kind]
    at = text.rindex("FIN()")
    deck = os.path.join(workdir, STEM + ".comm")
    with open(deck, "w") as f:
        f.write(text[:at] + extra + text[at:])
    return deck


def command(parasol, source_dir, deck, outdir, kind):
    cmd = [parasol, "--quiet", "--outdir", outdir,
           "--unit", "20=" + os.path.join(source_dir, "decks", "ssnl130a.mail")]
    if kind in ("med", "all"):
        cmd += ["--unit", "80=" + os.path.join(outdir, STEM + ".rmed")]
    if kind == "unit":
        cmd += ["--unit", "81=" + os.path.join(outdir, "bound.msh")]
    if kind == "gibi":
        cmd += ["--unit", "19=" + os.path.join(source_dir, "tests", "mesh_commands",
                                               "strip.mgib")]
    if kind == "fields":
        cmd += ["--unit", "82=" + os.path.join(outdir, "elga.rmed"),
                "--unit", "83=" + os.path.join(outdir, "cham_gd.rmed")]
    return cmd + [deck]


def run(cmd, preexec=None):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, preexec_fn=preexec)
    return p.returncode, p.stdout, p.stderr


def read(path):
    with open(path, "rb") as f:
        return f.read()


def reference(parasol, source_dir, workdir, kind):
    """Runs the deck into WORKDIR/reference: {file name: bytes}."""
    deck = make_deck(source_dir, workdir, kind)
    out = os.path.join(workdir, "reference")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    rc, _, err = run(command(parasol, source_dir, deck, out, kind))
    if rc != 0:
        fail("the reference run of %s ended with %d: %s" % (kind, rc, err))
    files = {n: read(os.path.join(out, n)) for n in sorted(os.listdir(out))}
    if len(files) < 2:
        fail("the reference run wrote %s" % sorted(files))
    return deck, files


def hdf5_content(data):
    """The datasets and attributes of an HDF5 file (MED), for comparing two files: HDF5
    stores object times, so two complete files of one run differ in bytes."""
    import io
    import h5py
    import numpy
    items = {}
    with h5py.File(io.BytesIO(data), "r") as f:
        def visit(name, obj):
            for k, v in obj.attrs.items():
                items[name + "@" + k] = numpy.asarray(v).tobytes()
            if isinstance(obj, h5py.Dataset):
                items[name] = numpy.asarray(obj[()]).tobytes()
        f.visititems(visit)
        for k, v in f.attrs.items():
            items["@" + k] = numpy.asarray(v).tobytes()
    return items


def same_file(name, data, expected):
    if data == expected:
        return True
    if name.endswith((".rmed", ".med")):
        try:
            return hdf5_content(data) == hdf5_content(expected)
        except (OSError, ValueError):
            return False
    return False


def check_run(label, rc, out, err, outdir, ref, older, forced=None, writing=True):
    """The common checks of one faulty run; returns the file named in the error (or None).
    older: {name: bytes} of files that were there before the run (kept when it fails)."""
    for sign in CRASH_SIGNS:
        if sign in err or sign in out:
            fail("%s: '%s' in the output:\n%s" % (label, sign, err))
    if rc < 0:
        fail("%s: killed by signal %d\n%s" % (label, -rc, err))
    if rc not in (0, 1):
        fail("%s: exit status %d\n%s" % (label, rc, err))
    names = sorted(os.listdir(outdir))
    partial = [n for n in names if n.endswith(".partial")]
    if partial:
        fail("%s: temporary files left: %s" % (label, partial))
    named = None
    if rc == 1:
        lines = [l for l in err.splitlines() if l.strip()]
        if len(lines) != 1:
            fail("%s: %d lines on stderr, not one:\n%s" % (label, len(lines), err))
        m = re.search(r"cannot (?:write|create) (\S+?):", lines[0])
        if writing and not m:
            fail("%s: the error names no file: %s" % (label, lines[0]))
        named = m.group(1) if m else None
        if "TEST_RESU OK" in out or "every TEST_RESU" in out:
            fail("%s: a summary of success on stdout: %s" % (label, out))
    for n in names:
        path = os.path.join(outdir, n)
        if (os.path.islink(path) and n == forced) or os.path.isdir(path):
            continue
        data = read(path)
        if n.endswith(".mess"):
            if not re.search(rb"\nverdict: [^\n]*\n$", data):
                fail("%s: %s is published without its verdict (%d bytes)" % (label, n, len(data)))
            if rc == 0 and not re.search(rb"\nverdict: \d+ OK, 0 NOOK\n$", data):
                fail("%s: %s of a run that ended well lacks its verdict" % (label, n))
            if rc == 1 and b"STOPPED ON AN ERROR" not in data:
                fail("%s: %s of a failed run does not say so" % (label, n))
            continue
        if ref is None:
            continue
        if n not in ref:
            fail("%s: unexpected file %s" % (label, n))
        if not same_file(n, data, ref[n]) and older.get(n) != data:
            fail("%s: %s differs from the reference (%d bytes, reference %d): truncated?"
                 % (label, n, len(data), len(ref[n])))
    if rc == 0 and ref is not None:
        missing = [n for n in ref if n not in names]
        if missing:
            fail("%s: exit 0 but %s missing" % (label, missing))
    else:
        resu = STEM + ".resu"
        if resu in older and resu != forced:
            if resu not in names or read(os.path.join(outdir, resu)) != older[resu]:
                fail("%s: the older %s was not left as it was" % (label, resu))
    return named


# ---- dev-full ----

def outputs_of(kind, ref):
    if kind == "listings":
        return [STEM + ".mess", STEM + ".resu"]
    suffix = {"vtk": (".pvd", ".vtu"), "gmsh": (".msh",), "med": (".rmed",),
              "unit": ("bound.msh",), "table": (".38",), "fonction": (".25", ".26", ".29"),
              "fields": (".rmed", ".pvd", ".vtu"), "gibi": (".21",)}[kind]
    names = [n for n in ref if n.endswith(suffix)]
    if kind == "vtk":     # the .pvd, the first and the last .vtu
        vtu = [n for n in names if n.endswith(".vtu")]
        names = [n for n in names if n.endswith(".pvd")] + [vtu[0], vtu[-1]]
    return names


def dev_full(parasol, source_dir, workdir, kind):
    os.makedirs(workdir, exist_ok=True)
    deck, ref = reference(parasol, source_dir, workdir, kind)
    targets = outputs_of(kind, ref)
    if not targets:
        fail("no output of kind %s in %s" % (kind, sorted(ref)))
    for target in targets:
        out = os.path.join(workdir, "full_" + target.replace(".", "_"))
        shutil.rmtree(out, ignore_errors=True)
        shutil.copytree(os.path.join(workdir, "reference"), out)
        older = {n: read(os.path.join(out, n)) for n in os.listdir(out)}
        os.remove(os.path.join(out, target))
        os.symlink("/dev/full", os.path.join(out, target))
        rc, so, se = run(command(parasol, source_dir, deck, out, kind))
        label = "%s -> /dev/full" % target
        named = check_run(label, rc, so, se, out, ref, older, forced=target)
        if rc != 1:
            fail("%s: exit status %d, not 1" % (label, rc))
        want = "cannot write %s: No space left on device" % os.path.join(out, target)
        if want not in se:
            fail("%s: stderr lacks '%s':\n%s" % (label, want, se))
        if named != os.path.join(out, target):
            fail("%s: the error names %s" % (label, named))
        if os.readlink(os.path.join(out, target)) != "/dev/full":
            fail("%s: the link was replaced" % label)
        print("%s: exit 1, %s" % (label, se.strip()))
    print("dev-full %s: %d outputs, each a located error" % (kind, len(targets)))


# ---- sweeps ----

def sweep(parasol, source_dir, workdir, kind, sizes, how):
    os.makedirs(workdir, exist_ok=True)
    deck, ref = reference(parasol, source_dir, workdir, kind)
    total = sum(len(v) for v in ref.values())
    mnt = os.path.join(workdir, "disk")
    os.makedirs(mnt, exist_ok=True)
    tally = {0: 0, 1: 0}
    named_files = {}
    for kb in sizes:
        if how == "tmpfs":
            subprocess.run(["umount", mnt], capture_output=True)
            p = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=%dk" % kb, "tmpfs", mnt],
                               capture_output=True, text=True)
            if p.returncode != 0:
                fail("mount of a %d KB tmpfs failed: %s" % (kb, p.stderr))
            limit = None
        else:
            shutil.rmtree(mnt, ignore_errors=True)
            os.makedirs(mnt)
            limit = kb * 1024
        # an older .resu of that name, which a failed run must leave as it was
        older = {}
        if kb >= 8:
            with open(os.path.join(mnt, STEM + ".resu"), "wb") as f:
                f.write(b"older listing\n")
            older[STEM + ".resu"] = b"older listing\n"

        def preexec(limit=limit):
            if limit is not None:
                import resource
                resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
        try:
            rc, so, se = run(command(parasol, source_dir, deck, mnt, kind), preexec)
            label = "%s %d KB" % (how, kb)
            named = check_run(label, rc, so, se, mnt, ref, older)
        finally:
            if how == "tmpfs":
                subprocess.run(["umount", mnt], capture_output=True)
        tally[rc] += 1
        if named:
            base = os.path.basename(named)
            key = re.sub(r"_\d+\.vtu$", "_N.vtu", base)
            named_files[key] = named_files.get(key, 0) + 1
        print("%s: exit %d %s" % (label, rc, se.strip()))
    print("%s sweep %s, %d sizes (%d..%d KB; the outputs total %d bytes): exit 0 %d, "
          "exit 1 %d, no signal, no truncated file; files named: %s"
          % (how, kind, len(sizes), sizes[0], sizes[-1], total, tally[0], tally[1],
             ", ".join("%s %d" % kv for kv in sorted(named_files.items()))))


# ---- interrupts ----

def interrupt(parasol, source_dir, workdir):
    """A long run (a 32 x 128 plate in 8 steps, tools/make_ssnl130_case.py) interrupted in
    its first step, once by SIGINT and once by SIGTERM, over the listings of an earlier
    run."""
    os.makedirs(workdir, exist_ok=True)
    tool = os.path.join(source_dir, "tools", "make_ssnl130_case.py")
    stem = os.path.join(workdir, "long")
    p = subprocess.run([sys.executable, tool, "--nx", "32", "--ny", "128", "--steps", "8",
                        "-o", stem], capture_output=True, text=True)
    if p.returncode != 0:
        fail("case generator: %s" % p.stderr)
    for sig in (signal.SIGINT, signal.SIGTERM):
        out = os.path.join(workdir, "interrupt_%d" % sig)
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        older = {"long.mess": b"the .mess of an earlier run\n",
                 "long.resu": b"the .resu of an earlier run\n"}
        for n, data in older.items():
            with open(os.path.join(out, n), "wb") as f:
                f.write(data)
        p = subprocess.Popen([parasol, "--quiet", "--outdir", out, stem + ".comm"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        # wait until the analysis is under way (the temporary .mess, which grows as the run
        # goes, shows the first step), then interrupt it
        temp = os.path.join(out, "long.mess.%d.partial" % p.pid)
        deadline = time.time() + 120
        while time.time() < deadline and p.poll() is None:
            if os.path.exists(temp) and b"(step 1)" in read(temp):
                break
            time.sleep(0.01)
        else:
            p.kill()
            fail("the long run never reached its first step")
        p.send_signal(sig)
        so, se = p.communicate(timeout=60)
        label = "signal %d" % sig
        if p.returncode != -sig:
            fail("%s: exit status %d, not ended by the signal (%s)" % (label, p.returncode, se))
        names = sorted(os.listdir(out))
        now = {n: read(os.path.join(out, n)) for n in names}
        if now != older:
            fail("%s: the folder holds %s, the earlier listings changed or temporaries are "
                 "left" % (label, names))
        print("%s: the process ended by the signal in its first step, the earlier listings "
              "intact, no temporary left" % label)


def med_flip(parasol, workdir, aster_dir):
    source = os.path.join(aster_dir, "astest", "zzzz393a.mmed")
    if not os.path.exists(source):
        print("SKIPPED: %s is absent (Code_Aster's test files, ../shared/aster)" % source)
        return SKIP
    os.makedirs(workdir, exist_ok=True)
    data = bytearray(read(source))
    if data[34789] != 0x00:
        fail("byte 34789 of %s is 0x%02x, not 0x00: another version of the file" %
             (source, data[34789]))
    data[34789] = 0x04
    flipped = os.path.join(workdir, "zzzz393a_flipped.mmed")
    with open(flipped, "wb") as f:
        f.write(data)
    deck = os.path.join(workdir, "read.comm")
    with open(deck, "w") as f:
        f.write("DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\nFIN()\n")
    for mesh, want in ((source, 0), (flipped, 1)):
        out = os.path.join(workdir, "out_%d" % want)
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        rc, so, se = run([parasol, "--quiet", "--outdir", out, "--unit", "20=" + mesh, deck])
        check_run(os.path.basename(mesh), rc, so, se, out, None, {}, writing=False)
        if rc != want:
            fail("%s: exit %d, not %d: %s" % (mesh, rc, want, se))
        if want == 1:
            line = se.strip()
            if "LIRE_MAILLAGE/UNITE: MED file %s is damaged: " % flipped not in line:
                fail("the flipped file's error does not say it is damaged: %s" % line)
            print("flipped: exit 1, " + line)
    print("zzzz393a.mmed reads; with byte 34789 flipped: one line naming it, exit 1")
    return 0


def export_lines(parasol, workdir):
    os.makedirs(workdir, exist_ok=True)
    with open(os.path.join(workdir, "case.comm"), "w") as f:
        f.write("DEBUT()\nFIN()\n")
    cases = [
        ("nodir", "F mess nodir/x.mess R 6\n", 2,
         "F mess nodir/x.mess R 6: the folder nodir does not exist", "out/nodir.mess"),
        ("folder", "F mess kept.mess R 6\nF resu . R 8\n", 3,
         "F resu . R 8: . is a folder", "kept.mess"),
        ("same", "F mess same.txt R 6\nF resu same.txt R 8\n", 3,
         "F resu same.txt R 8: the same file as line 2 (F mess same.txt R 6)", "same.txt"),
    ]
    for name, lines, line, text, mess in cases:
        export = os.path.join(workdir, name + ".export")
        with open(export, "w") as f:
            f.write("F comm case.comm D 1\n" + lines)
        out = os.path.join(workdir, "out")
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        for old in ("kept.mess", "same.txt"):
            if os.path.exists(os.path.join(workdir, old)):
                os.remove(os.path.join(workdir, old))
        p = subprocess.run([parasol, "--quiet", "--outdir", "out", name + ".export"],
                           cwd=workdir, capture_output=True, text=True, timeout=60)
        label = "export %s" % name
        want = "%s.export:%d: error: %s" % (name, line, text)
        lines_err = [l for l in p.stderr.splitlines() if l.strip()]
        if p.returncode != 1 or len(lines_err) != 1 or not lines_err[0].startswith(want):
            fail("%s: exit %d, stderr %r; wanted exit 1 and '%s...'" % (label, p.returncode,
                                                                         p.stderr, want))
        path = os.path.join(workdir, mess)
        if not os.path.exists(path) or want not in open(path).read():
            fail("%s: the error is not in %s" % (label, mess))
        print("%s: %s (in %s too)" % (label, lines_err[0], mess))
    return 0


def folders(parasol, source_dir, workdir):
    """Files of a deck in folders: DEFI_FICHIER into REPE_OUT/ (which Code_Aster's runner
    makes in every working directory) is written there; into a folder that does not exist,
    MED and text outputs stop with one line naming the file and the missing folder."""
    mesh = os.path.join(source_dir, "decks", "ssnl130a.mail")
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    base = ("DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
            "TA = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))\n")
    cases = [
        ("repe_out", "DEFI_FICHIER(UNITE=80, TYPE='BINARY', FICHIER='./REPE_OUT/m.med')\n"
         "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MA))\n"
         "DEFI_FICHIER(UNITE=38, FICHIER='REPE_OUT/t.txt')\n"
         "IMPR_TABLE(TABLE=TA, UNITE=38)\n", 0, ["REPE_OUT/m.med", "REPE_OUT/t.txt"]),
        ("med_nodir", "DEFI_FICHIER(UNITE=80, TYPE='BINARY', FICHIER='NODIR/m.med')\n"
         "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MA))\n", 1,
         "IMPR_RESU: cannot write %s/NODIR/m.med: No such file or directory (its folder "
         "%s/NODIR does not exist)"),
        ("table_nodir", "DEFI_FICHIER(UNITE=38, FICHIER='NODIR/t.txt')\n"
         "IMPR_TABLE(TABLE=TA, UNITE=38)\n", 1,
         "IMPR_TABLE/UNITE: cannot create %s/NODIR/t.txt: No such file or directory"),
    ]
    for name, body, rc_wanted, want in cases:
        deck = os.path.join(workdir, name + ".comm")
        with open(deck, "w") as f:
            f.write(base + body + "FIN()\n")
        out = os.path.join(workdir, name)
        os.makedirs(out)
        rc, so, se = run([parasol, "--quiet", "--outdir", out, "--unit", "20=" + mesh, deck])
        check_run(name, rc, so, se, out, None, {}, writing=False)
        if rc != rc_wanted:
            fail("%s: exit %d, wanted %d: %s" % (name, rc, rc_wanted, se))
        if rc == 0:
            for f in want:
                if not os.path.isfile(os.path.join(out, f)):
                    fail("%s: %s was not written" % (name, f))
            print("%s: exit 0, %s written" % (name, ", ".join(want)))
        else:
            text = want % ((out,) * want.count("%s"))
            if text not in se:
                fail("%s: stderr lacks %r: %r" % (name, text, se))
            print("%s: %s" % (name, se.strip()))
    return 0


def main(argv):
    if len(argv) < 5:
        print(__doc__)
        return 2
    what, parasol, source_dir, workdir = argv[1:5]
    parasol = os.path.abspath(parasol)
    workdir = os.path.abspath(workdir)
    if what == "dev-full":
        dev_full(parasol, source_dir, workdir, argv[5])
    elif what in ("sweep", "ulimit"):
        kind = argv[5]
        first, last, step = (int(a) for a in argv[6:9])
        sizes = list(range(first, last + 1, step))
        if what == "sweep" and os.geteuid() != 0:
            print("SKIPPED: the tmpfs sweep needs root to mount(8) a small file system "
                  "(CI runs as root); faults.ulimit_* sweep without it")
            return SKIP
        sweep(parasol, source_dir, workdir, kind, sizes,
              "tmpfs" if what == "sweep" else "ulimit")
    elif what == "export-lines":
        return export_lines(parasol, workdir)
    elif what == "folders":
        return folders(parasol, source_dir, workdir)
    elif what == "med-flip":
        return med_flip(parasol, workdir, argv[5])
    elif what == "interrupt":
        interrupt(parasol, source_dir, workdir)
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""MED files in and out of parasol (LIRE_MAILLAGE / IMPR_RESU FORMAT='MED'), run by CTest.

usage:
  run_med_case.py fields PARASOL DECK MESH WORKDIR
      Runs DECK (a decks/*.comm reading MESH with FORMAT='ASTER', result RESU) with MED
      output added: every field on unit 80, DEPL on PT01 and PT02 on unit 81, then DEPL and
      REAC_NODA again in two IMPR_RESU on unit 82 (the second adds to the first file), DY on
      the unbound unit 83 (<stem>_RESU.rmed in the output folder). Checks
      the files with h5py (field names RESU____DEPL ..., components, one step per NUME_ORDRE
      with its INST, values equal to the .resu tables of the same run to 1e-12, the profile
      of the GROUP_NO output, one mesh in the file written twice) and with MED's own mdump,
      then runs DECK again reading the MED file it wrote (FORMAT='MED'): same TEST_RESU.
  run_med_case.py bad PARASOL WORKDIR MED_FILE
      Crafts bad MED files from MED_FILE (h5py: versions 2 and 5, counts that lie, an absurd
      space dimension, two meshes, truncations, not HDF5, empty) and reads each with a
      one-command deck: exit 1, the located message at LIRE_MAILLAGE/UNITE (NOM_MED for the
      mesh name), its phrase, and nothing else on stderr (no MED or HDF5 noise, no crash).
  run_med_case.py default-unit PARASOL WORKDIR MED_FILE
      An unbound unit 20 and the default FORMAT (MED): <stem>.mmed beside the deck is read;
      <stem>.med too; both present, or neither, is an error at UNITE naming the paths.
  run_med_case.py aster PARASOL DECK ASTER_DIR MMED WORKDIR
      Runs DECK (a decks/*.comm) with FORMAT='MED' on Code_Aster's own mesh ASTER_DIR/MMED:
      every TEST_RESU OK. Skipped (exit 77) when ASTER_DIR does not exist.
  run_med_case.py aster-mesh PARASOL ASTER_DIR MMED WORKDIR NODES CELLS GROUPS...
      Reads ASTER_DIR/MMED alone: NODES nodes, CELLS cells, each GROUP=SIZE in the .mess.
      Skipped (exit 77) when ASTER_DIR does not exist.
  run_med_case.py import-2x PARASOL ASTER_DIR WORKDIR MMED...
      Code_Aster's meshes ASTER_DIR/MMED written by MED 2.3.6, read through MED's converter
      (MEDimport, in the MED server): exit 0, the .mess says the file was converted, the
      mesh printed (IMPR_RESU FORMAT='RESULTAT') equals that of a copy converted beforehand
      by MED's own medimport tool, and the private temporary folder is gone ($TMPDIR empty).
      A 2.3.6 file that MEDimport cannot convert (its version header made 2.1.0), and a
      $TMPDIR that does not exist, stop at LIRE_MAILLAGE/UNITE with one line, nothing left
      in $TMPDIR. Skipped (exit 77) when ASTER_DIR does not exist.
  run_med_case.py missing-plugin PARASOL DECK MESH WORKDIR WRONG_ABI_SO
      A copy of PARASOL outside the build tree finds no plug-in: a MED deck stops with exit 1
      and the loader's reason, located at LIRE_MAILLAGE/UNITE; a deck reading MESH (.mail)
      without MED still runs (DECK is not used).
      The same with a plug-in file that is not a shared library, and with WRONG_ABI_SO (a
      plug-in of another version) in its place.
  run_med_case.py not-linked PARASOL
      parasol itself does not need the MED, HDF5 or MPI libraries (readelf NEEDED).
  run_med_case.py export PARASOL DECK WORKDIR MED_FILE
      An export file as Code_Aster's: the mesh MED_FILE on `F mmed ... D 20`, the results on
      `F rmed ... R 80`, two command files (DECK with FORMAT='MED' writing DEPL, then a
      POURSUITE file writing REAC_NODA to the same unit): one file with one mesh and both
      fields.
  run_med_case.py installed BUILD_DIR WORKDIR MED_FILE
      cmake --install into a fresh prefix: the plug-in is in <prefix>/lib/parasol and the
      installed parasol reads MED_FILE from an unrelated folder.
"""
import os
import re
import shutil
import subprocess
import sys
import time

CRASH_SIGNS = ("Fortran runtime", "Backtrace", "ERROR STOP", "Segmentation", "double free",
               "Program received signal", "HDF5-DIAG", "../src/", "Erreur")
SKIP = 77


def run(parasol, deck, workdir, units=(), cwd=None):
    os.makedirs(workdir, exist_ok=True)
    cmd = [os.path.abspath(parasol), "--outdir", os.path.abspath(workdir)]
    for u in units:
        cmd += ["--unit", u]
    cmd.append(os.path.abspath(deck))
    proc = subprocess.run(cmd, cwd=cwd or workdir, capture_output=True, timeout=120)
    return proc.returncode, proc.stdout.decode("utf-8", "replace"), \
        proc.stderr.decode("utf-8", "replace")


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def med_deck(deck_text):
    """The deck reading its mesh with FORMAT='MED'."""
    return deck_text.replace("FORMAT='ASTER'", "FORMAT='MED'")


def resu_tables(path):
    """{(field, nume_ordre): (inst, components, {node: [values]})} from IMPR_RESU tables."""
    tables, current = {}, None
    head = re.compile(r" ---- RESULTAT (\S+)\s+NOM_CHAM (\S+)\s+NUME_ORDRE (\d+)\s+INST (\S+)")
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = head.match(line)
            if m:
                current = {"inst": float(m.group(4)), "rows": {}}
                tables[(m.group(2), int(m.group(3)))] = current
                continue
            if current is None:
                continue
            words = line.split()
            if not words:
                current = None
            elif words[0] == "MAILLE":       # an element field's table (cell_tables)
                del tables[[k for k, t in tables.items() if t is current][0]]
                current = None
            elif words[0] == "NOEUD":
                current["cmp"] = words[1:]
            else:   # '-': the node lacks the component
                current["rows"][words[0]] = [None if w == "-" else float(w) for w in words[1:]]
    return tables


def cell_tables(path):
    """{(field, nume_ordre): {'cmp': [...], 'rows': {(cell, point, sub): [values]}}} from the
    IMPR_RESU tables of element fields (MAILLE POINT [SOUS_POINT] components)."""
    tables, current = {}, None
    head = re.compile(r" ---- RESULTAT (\S+)\s+NOM_CHAM (\S+)\s+NUME_ORDRE (\d+)\s+INST (\S+)")
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = head.match(line)
            if m:
                current = {"rows": {}, "sub": False}
                tables[(m.group(2), int(m.group(3)))] = current
                continue
            if current is None:
                continue
            words = line.split()
            if not words:
                current = None
            elif words[0] == "NOEUD":
                current = None        # a node table
            elif words[0] == "MAILLE":
                current["sub"] = words[2] == "SOUS_POINT"
                current["cmp"] = words[3 if current["sub"] else 2:]
            else:
                n = 3 if current["sub"] else 2
                key = (words[0], int(words[1]), int(words[2]) if current["sub"] else 1)
                current["rows"][key] = [None if w == "-" else float(w) for w in words[n:]]
    return {k: t for k, t in tables.items() if "cmp" in t}


def check_cell_fields(f, mesh_name, mesh_step, tables):
    """The element fields of the MED file (SIEF_ELGA, VARI_ELGA) against the .resu tables
    of the same run: each step, each cell type's part (its localisation: Code_Aster's name,
    points x sub-points), each value to 1e-12."""
    import numpy as np
    problems = []
    for fname in ("RESU____SIEF_ELGA", "RESU____VARI_ELGA"):
        if fname not in f["CHA"]:
            continue
        field = f["CHA"][fname]
        symbol = fname[8:]
        ncmp = int(field.attrs["NCO"])
        cmps = field.attrs["NOM"].decode()
        cmps = [cmps[16 * k:16 * k + 16].strip() for k in range(ncmp)]
        orders = sorted(k for (s, k) in tables if s == symbol)
        if not orders or len(field.keys()) != len(orders):
            problems.append("%s: %d steps, %d tables" % (fname, len(field.keys()), len(orders)))
        for k in orders:
            table = tables[(symbol, k)]
            grp = step_group(field, k)
            if grp is None:
                problems.append("%s: no step %d" % (fname, k))
                continue
            checked = 0
            for part in grp.keys():
                if not part.startswith("MAI."):
                    problems.append("%s: values on %s, not on cells" % (fname, part))
                    continue
                cells = [bytes(n).decode().strip() for n in mesh_step["MAI"][part[4:]]["NOM"][:]]
                entity = grp[part]
                profile = entity.attrs["PFL"].decode().strip()
                data = entity[profile]
                n_gauss = int(data.attrs["NGA"])
                loc = data.attrs["GAU"].decode().strip()
                if loc and loc not in f["GAUSS"]:
                    problems.append("%s %s: localisation %s not in the file" % (fname, part, loc))
                if profile == "MED_NO_PROFILE_INTERNAL":
                    on = list(range(len(cells)))
                else:
                    on = [int(i) - 1 for i in f["PROFILS"][profile]["PFL"][:]]
                values = np.asarray(data["CO"][:]).reshape(ncmp, len(on), n_gauss)
                for j, i in enumerate(on):
                    # points x sub-points, the sub-points of each point in turn
                    n_sub = max([s for (c, _, s) in table["rows"] if c == cells[i]] or [1])
                    for g in range(n_gauss):
                        key = (cells[i], g // n_sub + 1, g % n_sub + 1)
                        row = table["rows"].get(key)
                        if row is None:
                            continue
                        for c, name in enumerate(cmps):
                            if name not in table["cmp"]:
                                continue
                            want = row[table["cmp"].index(name)]
                            if want is not None and not close(values[c, j, g], want):
                                problems.append("%s step %d %s %s: MED %r, .resu %r" % (
                                    fname, k, key, name, values[c, j, g], want))
                        checked += 1
            if checked == 0:
                problems.append("%s step %d: no value checked against the .resu" % (fname, k))
    return problems


def close(a, b, rtol=1e-12, atol=1e-15):
    return abs(a - b) <= atol + rtol * abs(b)


def step_group(field, numdt):
    key = "%020d%020d" % (numdt, numdt)
    return field[key] if key in field else None


def case_fields(argv):
    import h5py
    import numpy as np
    parasol, deck, mesh, workdir = argv[:4]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    text = open(deck, encoding="utf-8").read()
    extra = ("IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU))\n"
             "IMPR_RESU(FORMAT='MED', UNITE=81,\n"
             "          RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL', GROUP_NO=('PT01', 'PT02')))\n"
             "IMPR_RESU(FORMAT='MED', UNITE=82, RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL'))\n"
             "IMPR_RESU(FORMAT='MED', UNITE=82, RESU=_F(RESULTAT=RESU, NOM_CHAM='REAC_NODA'))\n"
             "IMPR_RESU(FORMAT='MED', UNITE=83, RESU=_F(RESULTAT=RESU, NOM_CMP='DY'))\n"
             "IMPR_RESU(FORMAT='RESULTAT',\n"
             "          RESU=_F(RESULTAT=RESU, NOM_CHAM=('DEPL', 'FORC_NODA', 'REAC_NODA',\n"
             "                                           'SIEF_ELGA', 'VARI_ELGA')))\n"
             "FIN()")
    assert text.count("FIN()") == 1 and "RESU = " in text, "deck must define RESU and end in FIN()"
    out_deck = os.path.join(workdir, "med_out.comm")
    write(out_deck, text.replace("FIN()", extra))
    all_rmed, pts_rmed, two_rmed = (os.path.join(workdir, n)
                                    for n in ("all.rmed", "pts.rmed", "two.rmed"))
    rc, _, err = run(parasol, out_deck, workdir,
                     ["20=" + os.path.abspath(mesh), "80=" + all_rmed, "81=" + pts_rmed,
                      "82=" + two_rmed])
    problems = []
    if rc != 0:
        return ["writing run: exit %d\n%s" % (rc, err)]
    if err.strip():
        problems.append("stderr not empty: %r" % err[:300])
    tables = resu_tables(os.path.join(workdir, "med_out.resu"))
    nodes = sorted({n for t in tables.values() for n in t["rows"]},
                   key=lambda s: (len(s), s))
    with h5py.File(all_rmed, "r") as f:
        meshes = list(f["ENS_MAA"].keys())
        if len(meshes) != 1:
            problems.append("one mesh expected, found %s" % meshes)
        mesh_name = meshes[0]
        step = f["ENS_MAA"][mesh_name]["-0000000000000000001-0000000000000000001"]
        n_nodes = int(step["NOE"]["COO"].attrs["NBR"])
        names = [bytes(n).decode().strip() for n in step["NOE"]["NOM"][:]]
        fields = sorted(f["CHA"].keys())
        if fields != ["RESU____DEPL", "RESU____FORC_NODA", "RESU____REAC_NODA",
                      "RESU____SIEF_ELGA", "RESU____VARI_ELGA"]:
            problems.append("fields %s" % fields)
        problems += check_cell_fields(f, mesh_name, step, cell_tables(
            os.path.join(workdir, "med_out.resu")))
        for fname in [n for n in fields if not n.endswith("_ELGA")]:
            field = f["CHA"][fname]
            symbol = fname[8:]
            ncmp = int(field.attrs["NCO"])
            cmps = field.attrs["NOM"].decode()
            cmps = [cmps[16 * k:16 * k + 16].strip() for k in range(ncmp)]
            if field.attrs["MAI"].decode() != mesh_name:
                problems.append("%s is on mesh %s" % (fname, field.attrs["MAI"]))
            orders = sorted(k for (s, k) in tables if s == symbol)
            if len(field.keys()) != len(orders):
                problems.append("%s: %d steps, %d instants" % (fname, len(field.keys()),
                                                                len(orders)))
            for k in orders:
                table = tables[(symbol, k)]
                grp = step_group(field, k)
                if grp is None:
                    problems.append("%s: no step %d" % (fname, k))
                    continue
                if grp.attrs["NDT"] != k or grp.attrs["NOR"] != k or \
                        not close(grp.attrs["PDT"], table["inst"]):
                    problems.append("%s step %d: NDT %s NOR %s PDT %s, INST %s" % (
                        fname, k, grp.attrs["NDT"], grp.attrs["NOR"], grp.attrs["PDT"],
                        table["inst"]))
                if table["cmp"] != cmps:
                    problems.append("%s: components %s, table %s" % (fname, cmps, table["cmp"]))
                noe = grp["NOE"]
                profile = noe.attrs["PFL"].decode().strip()
                if profile == "MED_NO_PROFILE_INTERNAL":
                    on = list(range(n_nodes))
                else:   # the nodes that carry a component (ircmpn)
                    on = [int(i) - 1 for i in f["PROFILS"][profile]["PFL"][:]]
                values = np.asarray(noe[profile]["CO"][:]).reshape(ncmp, len(on))
                for i, node in enumerate(names):   # MED stores values by component
                    row = table["rows"].get(node)
                    if i not in on:
                        if row is not None and any(v is not None for v in row):
                            problems.append("%s: node %s has values but is not written" % (
                                fname, node))
                        continue
                    if row is None:
                        problems.append("%s: node %s not in the .resu table" % (fname, node))
                        break
                    j = on.index(i)
                    for c in range(ncmp):
                        if not close(values[c, j], 0.0 if row[c] is None else row[c]):
                            problems.append("%s step %d node %s %s: MED %r, .resu %r" % (
                                fname, k, node, cmps[c], values[c, j], row[c]))
    if not set(nodes) <= set(names) or len(names) != n_nodes:
        problems.append("MED nodes %d (%d names); .resu table nodes not in MED: %s" % (
            n_nodes, len(names), sorted(set(nodes) - set(names))[:5]))
    with h5py.File(pts_rmed, "r") as f:
        profiles = list(f["PROFILS"].keys()) if "PROFILS" in f else []
        if profiles != ["PROFIL_00000001"]:
            problems.append("GROUP_NO output: profiles %s" % profiles)
        else:
            numbers = sorted(int(x) for x in f["PROFILS"]["PROFIL_00000001"]["PFL"][:])
            pt = [names[i - 1] for i in numbers]
            if len(numbers) != 2 or pt != [n for n in names if n in pt]:
                problems.append("profile of PT01, PT02 holds %s" % numbers)
        if list(f["CHA"].keys()) != ["RESU____DEPL"]:
            problems.append("GROUP_NO output: fields %s" % list(f["CHA"].keys()))
    with h5py.File(two_rmed, "r") as f:
        if sorted(f["CHA"].keys()) != ["RESU____DEPL", "RESU____REAC_NODA"]:
            problems.append("two IMPR_RESU on unit 82: fields %s" % list(f["CHA"].keys()))
        if len(f["ENS_MAA"].keys()) != 1:
            problems.append("two IMPR_RESU on unit 82: meshes %s" % list(f["ENS_MAA"].keys()))
    unbound = os.path.join(workdir, "med_out_RESU.rmed")
    if not os.path.isfile(unbound):
        problems.append("unbound unit 83: %s not written" % unbound)
    else:
        with h5py.File(unbound, "r") as f:
            field = f["CHA"]["RESU____DEPL"] if "RESU____DEPL" in f["CHA"] else None
            if sorted(f["CHA"].keys()) != ["RESU____DEPL", "RESU____FORC_NODA",
                                           "RESU____REAC_NODA"] or \
                    field.attrs["NOM"].decode().strip() != "DY":   # NOM_CMP='DY' only
                problems.append("unbound unit 83, NOM_CMP='DY': %s" % list(f["CHA"].keys()))
    dump = subprocess.run(["mdump", all_rmed], input=b"1\n1\n0\n", capture_output=True,
                          timeout=60)
    text_dump = dump.stdout.decode("utf-8", "replace")
    # a second run writes the same contents (not the same bytes: HDF5 stamps times)
    again = os.path.join(workdir, "again")
    rerun = os.path.join(again, "all.rmed")
    rc, _, err = run(parasol, out_deck, again,
                     ["20=" + os.path.abspath(mesh), "80=" + rerun,
                      "81=" + os.path.join(again, "pts.rmed"),
                      "82=" + os.path.join(again, "two.rmed")])
    dump2 = subprocess.run(["mdump", rerun], input=b"1\n1\n0\n", capture_output=True,
                           timeout=60).stdout.decode("utf-8", "replace")
    if rc != 0 or dump2.replace(rerun, all_rmed) != text_dump:
        problems.append("a second run wrote other contents (exit %d)" % rc)
    n_steps = len(re.findall(r"CHAMP \|RESU____DEPL\|", text_dump))
    if dump.returncode != 0 or n_steps != len([k for (s, k) in tables if s == "DEPL"]):
        problems.append("mdump: exit %d, %d DEPL steps listed" % (dump.returncode, n_steps))
    back_deck = os.path.join(workdir, "med_in.comm")
    write(back_deck, med_deck(text))
    rc, _, err = run(parasol, back_deck, os.path.join(workdir, "back"), ["20=" + all_rmed])
    if rc != 0:
        problems.append("reading the written MED back: exit %d\n%s" % (rc, err))
    return problems


BAD_DECK = "DEBUT()\nMAIL = LIRE_MAILLAGE(UNITE=20)\nFIN()\n"
NAMED_DECK = "DEBUT()\nMAIL = LIRE_MAILLAGE(UNITE=20, NOM_MED='NONE')\nFIN()\n"


def craft(good, path, edit):
    import h5py
    shutil.copy(good, path)
    with h5py.File(path, "r+") as f:
        edit(f)


def first_mesh(f):
    name = list(f["ENS_MAA"].keys())[0]
    return name, f["ENS_MAA"][name]["-0000000000000000001-0000000000000000001"]


def set_attr(obj, key, value):
    obj.attrs.modify(key, value)


def case_bad(argv):
    parasol, workdir, good = argv[:3]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    size = os.path.getsize(good)
    data = open(good, "rb").read()

    def cut(n):
        return lambda path: open(path, "wb").write(data[:n])

    def text(path):
        write(path, "COOR_3D\nN1 0 0 0\nFINSF\nFIN\n")

    def empty(path):
        open(path, "wb").close()

    def plain_hdf5(path):
        import h5py
        with h5py.File(path, "w") as f:
            f["x"] = [1.0, 2.0]

    def edited(fn):
        return lambda path: craft(good, path, fn)

    def nodes(f, key, value):
        set_attr(first_mesh(f)[1]["NOE"][key], "NBR", value)

    def cells(f, key, value):
        maille = first_mesh(f)[1]["MAI"]
        set_attr(maille[list(maille.keys())[-1]][key], "NBR", value)

    def group_count(f, value):
        fas = f["FAS"][first_mesh(f)[0]]
        for kind in ("ELEME", "NOEUD"):
            if kind in fas:
                fam = fas[kind][list(fas[kind].keys())[0]]
                set_attr(fam["GRO"], "NBR", value)
                return

    def same_number(f):   # MED refuses to write this; only a crafted file has it
        nodes_fas = f["FAS"][first_mesh(f)[0]]["NOEUD"]
        first = list(nodes_fas.keys())[0]
        f.copy(nodes_fas[first], nodes_fas, name="COPY_OF_" + first)

    def two_meshes(f):
        name = first_mesh(f)[0]
        f.copy(f["ENS_MAA"][name], "ENS_MAA/OTHER")
        f.copy(f["FAS"][name], "FAS/OTHER")

    cases = [
        ("not_hdf5", text, "is not a MED file: it is not even an HDF5 file"),
        ("empty", empty, "is not a MED file"),
        ("hdf5_not_med", plain_hdf5, "is an HDF5 file but not a MED file"),
        ("version_2", edited(lambda f: set_attr(f["INFOS_GENERALES"], "MAJ", 2)),
         "was written by MED 2."),
        ("version_5", edited(lambda f: set_attr(f["INFOS_GENERALES"], "MAJ", 5)),
         "was written by MED 5."),
        ("nodes_fewer", edited(lambda f: nodes(f, "COO", 3)),
         "cannot read the node coordinates"),
        ("nodes_more", edited(lambda f: nodes(f, "COO", 10 ** 6)),
         "cannot read the node coordinates"),
        ("nodes_huge", edited(lambda f: nodes(f, "COO", 2 ** 31 - 1)),
         "nodes, more than this machine can hold"),
        ("nodes_negative", edited(lambda f: nodes(f, "COO", -5)), "cannot count the nodes"),
        ("names_fewer", edited(lambda f: nodes(f, "NOM", 2)), "names for"),
        ("families_more", edited(lambda f: nodes(f, "FAM", 10 ** 5)), "family numbers for"),
        ("cells_fewer", edited(lambda f: cells(f, "NOD", 2)), "cannot read the"),
        ("cells_huge", edited(lambda f: cells(f, "NOD", 2 ** 30)),
         "more than this machine can hold"),
        ("groups_fewer", edited(lambda f: group_count(f, 0)), "family"),
        ("groups_more", edited(lambda f: group_count(f, 10 ** 6)), "groups (at most"),
        ("axes_1000", edited(lambda f: set_attr(f["ENS_MAA"][first_mesh(f)[0]], "ESP", 1000)),
         "coordinate axes (a mesh has 1 to 3)"),
        ("two_meshes", edited(two_meshes), "meshes ("),
        ("family_twice", edited(same_number), "have the same number"),
    ]
    cases += [("truncated_%d" % n, cut(n), "MED file") for n in
              sorted({64, 512, 2048, size // 4, size // 2, 3 * size // 4, size - 1000,
                      size - 1})]
    problems = []
    deck = os.path.join(workdir, "read.comm")
    write(deck, BAD_DECK)
    for name, make, phrase in cases:
        path = os.path.join(workdir, name + ".med")
        make(path)
        rc, out, err = run(parasol, deck, os.path.join(workdir, name), ["20=" + path])
        where = "read.comm:2:22: error: LIRE_MAILLAGE/UNITE: "
        if name == "two_meshes":
            where = "read.comm:2:8: error: LIRE_MAILLAGE/NOM_MED: "
        lines = [l for l in err.splitlines() if l.strip()]
        if rc != 1:
            problems.append("%s: exit %d, expected 1: %s" % (name, rc, err))
        elif len(lines) != 1 or where not in lines[0] or phrase not in lines[0]:
            problems.append("%s: stderr should be one line with %r and %r, got %r" % (
                name, where, phrase, err))
        problems += ["%s: crash sign %r" % (name, s) for s in CRASH_SIGNS if s in err]
    # NOM_MED naming no mesh of the file: located at NOM_MED, the file's meshes listed.
    deck = os.path.join(workdir, "named.comm")
    write(deck, NAMED_DECK)
    rc, _, err = run(parasol, deck, os.path.join(workdir, "named"), ["20=" + good])
    if rc != 1 or "named.comm:2:32: error: LIRE_MAILLAGE/NOM_MED: MED file " not in err or \
            "has no mesh named NONE (it holds: " not in err:
        problems.append("NOM_MED='NONE': exit %d, %r" % (rc, err))
    return problems


def case_default_unit(argv):
    parasol, workdir, good = argv[:3]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    deck = os.path.join(workdir, "study.comm")
    write(deck, "DEBUT()\nMAIL = LIRE_MAILLAGE()\nFIN()\n")
    problems = []
    for ext in (".mmed", ".med"):
        path = os.path.join(workdir, "study" + ext)
        shutil.copy(good, path)
        rc, _, err = run(parasol, deck, workdir)
        mess = open(os.path.join(workdir, "study.mess"), encoding="utf-8").read()
        if rc != 0 or ("MESH " + path) not in mess:
            problems.append("%s beside the deck: exit %d, %r" % (ext, rc, err))
        if ext == ".mmed":
            os.remove(path)
    shutil.copy(good, os.path.join(workdir, "study.mmed"))   # both: which one is meant?
    rc, _, err = run(parasol, deck, workdir)
    if rc != 1 or "study.comm:2:8: error: LIRE_MAILLAGE/UNITE: both " not in err:
        problems.append("both .med and .mmed: exit %d, %r" % (rc, err))
    for ext in (".mmed", ".med"):
        os.remove(os.path.join(workdir, "study" + ext))
    rc, _, err = run(parasol, deck, workdir)
    if rc != 1 or "study.med (or .mmed) for unit 20 does not exist" not in err:
        problems.append("neither: exit %d, %r" % (rc, err))
    return problems


def case_aster(argv):
    parasol, deck, aster_dir, mmed, workdir = argv[:5]
    if not os.path.isdir(aster_dir):
        print("skipped: %s does not exist (Code_Aster's SSNL130 files)" % aster_dir)
        return None
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    med = os.path.join(workdir, os.path.basename(deck))
    write(med, med_deck(open(deck, encoding="utf-8").read()))
    rc, out, err = run(parasol, med, workdir, ["20=" + os.path.join(aster_dir, mmed)])
    if rc != 0:
        return ["exit %d (0 = every TEST_RESU OK)\n%s%s" % (rc, out[-2000:], err)]
    return []


def case_aster_mesh(argv):
    parasol, aster_dir, mmed, workdir, n_nodes, n_cells = argv[:6]
    groups = argv[6:]
    if not os.path.isdir(aster_dir):
        print("skipped: %s does not exist (Code_Aster's SSNL130 files)" % aster_dir)
        return None
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    deck = os.path.join(workdir, "mesh_only.comm")
    write(deck, "DEBUT()\nMAIL = LIRE_MAILLAGE(FORMAT='MED')\nFIN()\n")
    rc, _, err = run(parasol, deck, workdir, ["20=" + os.path.join(aster_dir, mmed)])
    if rc != 0:
        return ["exit %d: %s" % (rc, err)]
    mess = open(os.path.join(workdir, "mesh_only.mess"), encoding="utf-8").read()
    problems = []
    for expected in ["nodes          " + n_nodes, "cells          " + n_cells]:
        if expected not in mess:
            problems.append("the .mess lacks %r" % expected)
    for g in groups:
        name, size = g.split("=")
        if not re.search(r"GROUP_(NO|MA) %s %s (nodes|cells)" % (re.escape(name), size), mess):
            problems.append("the .mess lacks group %s of %s" % (name, size))
    return problems


IMPORT_DECK = ("DEBUT()\nMAIL = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\n"
               "IMPR_RESU(FORMAT='RESULTAT', RESU=_F(MAILLAGE=MAIL))\nFIN()\n")


def case_import_2x(argv):
    parasol, aster_dir, workdir = argv[:3]
    meshes = argv[3:]
    if not os.path.isdir(aster_dir):
        print("skipped: %s does not exist (Code_Aster's meshes of MED 2.3.6)" % aster_dir)
        return None
    import h5py
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    tmp = os.path.join(workdir, "tmp")
    os.makedirs(tmp)
    env = dict(os.environ, TMPDIR=tmp)
    deck = os.path.join(workdir, "import.comm")
    write(deck, IMPORT_DECK)

    def read_mesh(path, out):
        os.makedirs(out, exist_ok=True)
        proc = subprocess.run([os.path.abspath(parasol), "--outdir", out, "--unit",
                               "20=" + path, deck], cwd=out, env=env, capture_output=True,
                              timeout=120)
        return proc.returncode, proc.stderr.decode("utf-8", "replace")

    problems = []
    for mmed in meshes:
        source = os.path.join(aster_dir, "astest", mmed)
        with h5py.File(source, "r") as f:
            version = tuple(int(f["INFOS_GENERALES"].attrs[k]) for k in ("MAJ", "MIN", "REL"))
        if version[0] != 2:
            problems.append("%s is MED %s, not 2.x: the test has no case" % (mmed, version))
            continue
        out = os.path.join(workdir, mmed + ".out")
        rc, err = read_mesh(source, out)
        if rc != 0:
            problems.append("%s: exit %d: %s" % (mmed, rc, err))
            continue
        mess = open(os.path.join(out, "import.mess"), encoding="utf-8").read()
        said = "was written by MED 2.3.6: read from a copy converted to MED 4."
        if said not in mess:
            problems.append("%s: the .mess lacks %r" % (mmed, said))
        if os.listdir(tmp):
            problems.append("%s: left in $TMPDIR: %s" % (mmed, os.listdir(tmp)))
        tool = shutil.which("medimport")
        if tool:
            converted = os.path.join(workdir, mmed + ".converted.med")
            subprocess.run([tool, source, converted], capture_output=True, timeout=120,
                           check=True)
            rc, err = read_mesh(converted, out + ".tool")
            if rc != 0:
                problems.append("%s converted by medimport: exit %d: %s" % (mmed, rc, err))
            elif open(os.path.join(out, "import.resu"), "rb").read() != \
                    open(os.path.join(out + ".tool", "import.resu"), "rb").read():
                problems.append("%s: the mesh read differs from medimport's copy" % mmed)
        else:
            print("note: MED's medimport tool not found: the comparison was skipped")
        # A file MEDimport cannot convert: a 2.3.6 file that says it is 2.1.0 (MEDimport
        # applies the 2.1 to 2.2 conversion to it, fails and exits).
        bad = os.path.join(workdir, mmed + ".v210.med")
        shutil.copy(source, bad)
        os.chmod(bad, 0o644)
        with h5py.File(bad, "r+") as f:
            for k, v in (("MIN", 1), ("REL", 0)):
                f["INFOS_GENERALES"].attrs.modify(k, v)
        rc, err = read_mesh(bad, out + ".bad")
        lines = [l for l in err.splitlines() if l.strip()]
        where = "import.comm:2:36: error: LIRE_MAILLAGE/UNITE: MED file " + bad
        said = "was written by MED 2.1.0, which this parasol cannot read: MED's converter " \
            "(MEDimport) could not convert it"
        if rc != 1 or len(lines) != 1 or where not in lines[0] or said not in lines[0]:
            problems.append("%s made 2.1.0: expected exit 1 and one line %r ... %r, got exit "
                            "%d: %r" % (mmed, where, said, rc, err))
        if os.listdir(tmp):
            problems.append("%s made 2.1.0: left in $TMPDIR: %s" % (mmed, os.listdir(tmp)))
        print("%s: read through MEDimport; as 2.1.0: %s" % (mmed, lines[0] if lines else rc))
        # The fuzzer's case (seed 1202, case 585): one byte of zzzz136d.mmed, 45 661 0x00 ->
        # 0x27, makes MEDimport write its copy without end (9.7 GB in 10 s before its size
        # limit), then crash: exit 1, one line, nothing left, in seconds.
        if mmed == "zzzz136d.mmed":
            looping = os.path.join(workdir, mmed + ".loops.med")
            data = bytearray(open(source, "rb").read())
            data[45661] = 0x27
            with open(looping, "wb") as f:
                f.write(bytes(data))
            started = time.time()
            rc, err = read_mesh(looping, out + ".loops")
            took = time.time() - started
            said = "could not convert it: "
            if rc != 1 or len(err.strip().splitlines()) != 1 or said not in err or \
                    took > 30:
                problems.append("%s byte 45661 0x27: expected exit 1 and one line with %r "
                                "within 30 s, got exit %d after %.1f s: %r" % (
                                    mmed, said, rc, took, err))
            if os.listdir(tmp):
                problems.append("%s byte 45661: left in $TMPDIR: %s" % (mmed, os.listdir(tmp)))
            print("%s byte 45661 0x27: %.1f s, %s" % (mmed, took, err.strip()))
        # The fuzzer's case (seed 2026, case 1449): 110 bytes of zzzz136d.mmed at 59 494
        # duplicated convert into coordinates with a signaling NaN, whose mere test raised
        # IEEE invalid (SIGFPE in the checked build): one line naming the node.
        if mmed == "zzzz136d.mmed":
            snan = os.path.join(workdir, mmed + ".snan.med")
            data = open(source, "rb").read()
            with open(snan, "wb") as f:
                f.write(data[:59494 + 110] + data[59494:59494 + 110] + data[59494 + 110:])
            rc, err = read_mesh(snan, out + ".snan")
            said = "node 96 has a coordinate that is not a finite number"
            if rc != 1 or len(err.strip().splitlines()) != 1 or said not in err:
                problems.append("%s with 110 bytes duplicated at 59494: expected exit 1 and "
                                "one line with %r, got exit %d: %r" % (mmed, said, rc, err))
        # No room for the copy: $TMPDIR a folder that does not exist.
        env["TMPDIR"] = os.path.join(workdir, "no_such_folder")
        rc, err = read_mesh(source, out + ".notmp")
        env["TMPDIR"] = tmp
        said = "could not convert it: cannot make a temporary folder in %s for the " \
            "conversion: No such file or directory" % os.path.join(workdir, "no_such_folder")
        if rc != 1 or len(err.strip().splitlines()) != 1 or said not in err:
            problems.append("%s with no $TMPDIR: expected exit 1 and one line with %r, got "
                            "exit %d: %r" % (mmed, said, rc, err))
    return problems


def case_missing_plugin(argv):
    parasol, deck, mesh, workdir, wrong_abi = argv[:5]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(os.path.join(workdir, "bin"))
    copy = os.path.join(workdir, "bin", "parasol")
    shutil.copy(parasol, copy)
    med = os.path.join(workdir, "med.comm")
    write(med, "DEBUT()\nMAIL = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\nFIN()\n")
    where = "med.comm:2:36: error: LIRE_MAILLAGE/UNITE: FORMAT='MED' needs parasol's MED " \
            "plug-in, which cannot be loaded: "
    plugin_dir = os.path.join(workdir, "lib", "parasol")
    plugin = os.path.join(plugin_dir, "libparasol_med.so")
    problems = []
    for case, make, phrase in [
            ("absent", None, "cannot open shared object file"),
            ("not a library", lambda: write(plugin, "not a shared library\n"),
             "cannot load the shared library"),
            ("another version", lambda: shutil.copy(wrong_abi, plugin),
             "is of version 99, this parasol needs version 2")]:
        if make:
            os.makedirs(plugin_dir, exist_ok=True)
            make()
        rc, _, err = run(copy, med, workdir, ["20=" + os.path.abspath(mesh)])
        expected = where if case != "another version" else \
            "med.comm:2:36: error: LIRE_MAILLAGE/UNITE: the MED plug-in "
        if rc != 1 or expected not in err or phrase not in err or len(err.splitlines()) != 1:
            problems.append("plug-in %s: exit %d, %r" % (case, rc, err))
        problems += ["plug-in %s: crash sign %r" % (case, s) for s in CRASH_SIGNS if s in err]
    ascii_deck = os.path.join(workdir, "ascii.comm")   # no solver either: no plug-in at all
    write(ascii_deck, "DEBUT()\nMAIL = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\nFIN()\n")
    rc, _, err = run(copy, ascii_deck, os.path.join(workdir, "ascii"),
                     ["20=" + os.path.abspath(mesh)])
    if rc != 0:
        problems.append("a deck without MED must run without the plug-in: exit %d %r" % (rc, err))
    return problems


def case_not_linked(argv):
    parasol = argv[0]
    out = subprocess.run(["readelf", "-d", parasol], capture_output=True, check=True)
    needed = re.findall(r"\(NEEDED\)\s+Shared library: \[(.*?)\]", out.stdout.decode())
    bad = [n for n in needed if re.match(r"lib(medC|med|hdf5|mpi|open-rte|open-pal)", n)]
    if not needed:
        return ["readelf found no NEEDED entry in %s" % parasol]
    return ["parasol links %s: MED must stay in the plug-in" % bad] if bad else []


def case_export(argv):
    import h5py
    parasol, deck, workdir, good = argv[:4]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    text = med_deck(open(deck, encoding="utf-8").read())
    write(os.path.join(workdir, "study.comm"), text.replace(
        "FIN()", "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL'))"
        "\nFIN()"))
    write(os.path.join(workdir, "study.com1"),
          "POURSUITE()\nIMPR_RESU(FORMAT='MED', UNITE=80, "
          "RESU=_F(RESULTAT=RESU, NOM_CHAM='REAC_NODA'))\nFIN()\n")
    shutil.copy(good, os.path.join(workdir, "study.mmed"))
    write(os.path.join(workdir, "study.export"),
          "P time_limit 120\nF comm study.comm D 1\nF comm study.com1 D 1\n"
          "F mmed study.mmed D 20\nF rmed out/study.rmed R 80\n")
    os.makedirs(os.path.join(workdir, "out"))
    proc = subprocess.run([os.path.abspath(parasol), "--outdir", os.path.join(workdir, "out"),
                           os.path.join(workdir, "study.export")], cwd=workdir,
                          capture_output=True, timeout=120)
    err = proc.stderr.decode("utf-8", "replace")
    if proc.returncode != 0:
        return ["export run: exit %d %r" % (proc.returncode, err)]
    rmed = os.path.join(workdir, "out", "study.rmed")
    if not os.path.isfile(rmed):
        return ["F rmed ... R 80: %s not written" % rmed]
    with h5py.File(rmed, "r") as f:
        fields = sorted(f["CHA"].keys())
        meshes = list(f["ENS_MAA"].keys())
    problems = []
    if fields != ["RESU____DEPL", "RESU____REAC_NODA"] or len(meshes) != 1:
        problems.append("unit 80 after two command files: fields %s, meshes %s" % (fields,
                                                                                 meshes))
    return problems


def case_installed(argv):
    build, workdir, good = argv[:3]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(os.path.join(workdir, "elsewhere"))
    prefix = os.path.join(workdir, "prefix")
    proc = subprocess.run(["cmake", "--install", build, "--prefix", prefix],
                          capture_output=True, timeout=120)
    if proc.returncode != 0:
        return ["cmake --install: %s" % proc.stderr.decode()]
    plugin = os.path.join(prefix, "lib", "parasol", "libparasol_med.so")
    if not os.path.isfile(plugin):
        return ["%s not installed" % plugin]
    deck = os.path.join(workdir, "elsewhere", "med.comm")
    write(deck, "DEBUT()\nMAIL = LIRE_MAILLAGE()\nFIN()\n")
    rc, _, err = run(os.path.join(prefix, "bin", "parasol"), deck,
                     os.path.join(workdir, "elsewhere"), ["20=" + os.path.abspath(good)])
    return [] if rc == 0 else ["installed parasol on a MED mesh: exit %d %r" % (rc, err)]


CASES = {"fields": case_fields, "bad": case_bad, "default-unit": case_default_unit,
         "aster": case_aster, "aster-mesh": case_aster_mesh, "import-2x": case_import_2x,
         "missing-plugin": case_missing_plugin, "not-linked": case_not_linked,
         "installed": case_installed, "export": case_export}


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in CASES:
        print(__doc__)
        return 2
    problems = CASES[sys.argv[1]](sys.argv[2:])
    if problems is None:
        return SKIP
    for p in problems:
        print("FAIL:", p)
    if not problems:
        print("ok")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

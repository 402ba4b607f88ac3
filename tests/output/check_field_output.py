#!/usr/bin/env python3
"""IMPR_RESU of fields in every format, read back (tests/output/field_output.comm: the DKQ
patch of tests/verification under a uniform moment, two layers, so every value is known):
 - .resu: the node table with IMPR_COOR (the mesh's coordinates), SOUS_TITRE, VALE_MAX and
   VALE_MIN; the element tables (ELNO with 6 sub-points, ELGA, ELNO of a GROUP_MA); the
   CHAM_GD table; the mesh in ASTER format, read back by parasol (LIRE_MAILLAGE);
 - MED with h5py and MED's mdump: every field of the result, the Gauss-point localisations
   (Code_Aster's names, the FPG4 points and weights in Code_Aster's order, the sub-points
   as points), ELGA and ELNO values equal to the .resu tables to 1e-12, ELNO without
   sub-points on MED_NODE_ELEMENT; the CHAM_GD (one step -1, -1); the mesh alone;
 - LIRE_CHAMP: the deck reads the ELGA, ELNO and CHAM_GD fields back and tests them
   (TEST_RESU); a field the file lacks is a located error naming those it has;
 - VTK (meshio): the cell data of an ELNO field with sub-points (the top face's stress on
   every cell) and the node field; Gmsh (gmsh22.py): the $ElementData of EFGE_ELNO MXX.
Usage: check_field_output.py PARASOL SOURCE_DIR WORKDIR"""
import math
import os
import re
import shutil
import subprocess
import sys

import h5py
import meshio
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gmsh22  # noqa: E402

parasol, source, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def close(a, b, rtol=1e-12, atol=1e-9):
    return abs(a - b) <= atol + rtol * abs(b)


E, NU, H = 2.1e11, 0.3, 0.01
KXX, KYY = -1.0e-3, 0.7e-3
TOP = E / (1 - NU ** 2) * H / 2 * (KXX + NU * KYY)            # SIXX, top face
MXX = E * H ** 3 / 12 / (1 - NU ** 2) * (KXX + NU * KYY)
mail = os.path.join(source, "tests", "verification", "patch_dkq.mail")
deck = os.path.join(source, "tests", "output", "field_output.comm")
units = {80: "all.rmed", 81: "cham.rmed", 82: "mesh.rmed"}
cmd = [parasol, "--quiet", "--outdir", work, "--unit", "20=" + mail]
for u, name in units.items():
    cmd += ["--unit", "%d=%s" % (u, os.path.join(work, name))]
run = subprocess.run(cmd + [deck], capture_output=True, text=True, timeout=120)
check(run.returncode == 0 and not run.stderr, "parasol exit %d: %s" % (run.returncode,
                                                                       run.stderr))
coords = {}
with open(mail) as f:
    block = None
    for line in f:
        w = line.split()
        if w and w[0] in ("COOR_3D", "QUAD4", "FINSF"):
            block = w[0]
        elif block == "COOR_3D" and len(w) == 4:
            coords[w[0]] = [float(x) for x in w[1:]]

# ---- .resu
resu = open(os.path.join(work, "field_output.resu")).read()
tables = re.split(r"\n(?= ---- )", resu)


def table(head):
    found = [t for t in tables if t.startswith(head)]
    check(len(found) >= 1, ".resu: no table " + head)
    return found[0].splitlines() if found else []


t = table(" ---- RESULTAT RES  NOM_CHAM EFGE_NOEU  NUME_ORDRE 1")
check(t[1:3] == [" moments at the nodes",
                 " NOEUD    COOR_X                COOR_Y                COOR_Z"
                 "                MXX                   MYY"], ".resu: EFGE_NOEU header %r" % t[:3])
rows = [r.split() for r in t[3:7]]
check([r[0] for r in rows] == ["N5", "N6", "N7", "N8"], ".resu: GROUP_NO INTER rows")
for r in rows:
    check(all(close(float(x), c) for x, c in zip(r[1:4], coords[r[0]])), ".resu: %s coords" % r[0])
    check(close(float(r[4]), MXX), ".resu: %s MXX %s" % (r[0], r[4]))
extremes = [r.split() for r in t if r.startswith(" VALE_")]
check([e[:2] for e in extremes] == [["VALE_MAX", "MXX"], ["VALE_MAX", "MYY"],
                                    ["VALE_MIN", "MXX"], ["VALE_MIN", "MYY"]], ".resu: extremes")
check(all(len(e) == 5 and e[3] == "NOEUD" for e in extremes), ".resu: extremes name a node")


def cell_rows(lines):
    """{(cell, point or node, sub): [values]}"""
    header = lines[1].split()
    sub = "SOUS_POINT" in header
    out = {}
    for line in lines[2:]:
        w = line.split()
        if not w:
            break
        key = (w[0], w[1], int(w[2]) if sub else 1)
        out[key] = [float(x) for x in w[(3 if sub else 2):]]
    return header, out


h, sigm = cell_rows(table(" ---- RESULTAT RES  NOM_CHAM SIGM_ELNO"))
check(h == ["MAILLE", "NOEUD", "SOUS_POINT", "SIXX"] and len(sigm) == 5 * 4 * 6,
      ".resu: SIGM_ELNO %s, %d rows" % (h, len(sigm)))
check(all(close(v[0], TOP) for (c, n, s), v in sigm.items() if s == 6) and
      all(close(v[0], -TOP) for (c, n, s), v in sigm.items() if s == 1), ".resu: SIGM_ELNO faces")
h, sief = cell_rows(table(" ---- RESULTAT RES  NOM_CHAM SIEF_ELGA"))
check(h == ["MAILLE", "POINT", "SOUS_POINT", "SIXX"] and len(sief) == 5 * 4 * 6,
      ".resu: SIEF_ELGA %s, %d rows" % (h, len(sief)))
h, efge = cell_rows(table(" ---- RESULTAT RES  NOM_CHAM EFGE_ELNO"))
check(h[:3] == ["MAILLE", "NOEUD", "NXX"] and len(efge) == 20, ".resu: EFGE_ELNO %s" % h)
t = table(" ---- CHAM_GD TEMP  NOEU_TEMP_R")
check([r.split()[1] for r in t[2:10]] == ["2.000000000000E+01"] * 4 + ["5.000000000000E+01"] * 4,
      ".resu: CHAM_GD TEMP")
check(len(re.findall(r" ---- CHAM_GD TEMP ", resu)) == 1, ".resu: CHAM_GD TEMP printed once")
unit38 = open(os.path.join(work, "field_output.38")).read()
check(unit38.rstrip().splitlines() == t[:10], "UNITE=38: the CHAM_GD TEMP table, as in the .resu")
# the mesh in ASTER format, read back
listing = resu[resu.index("TITRE\n"):resu.index("\nFIN\n") + 5]
back_mail = os.path.join(work, "back.mail")
open(back_mail, "w").write(listing)
back_deck = os.path.join(work, "back.comm")
open(back_deck, "w").write("DEBUT()\nm = LIRE_MAILLAGE(FORMAT='ASTER')\nFIN()\n")
back = subprocess.run([parasol, "--outdir", work, "--unit", "20=" + back_mail, back_deck],
                      capture_output=True, text=True, timeout=60)
mess = open(os.path.join(work, "back.mess")).read() if back.returncode == 0 else ""
check(back.returncode == 0 and "8 nodes" in mess and "5 cells" in mess and "PATCH" in mess
      and "INTER" in mess, "the ASTER listing read back: exit %d %s" % (back.returncode,
                                                                       back.stderr))

# ---- MED
with h5py.File(os.path.join(work, "all.rmed"), "r") as f:
    fields = sorted(f["CHA"].keys())
    check(fields == ["RES_____" + n for n in ("DEPL", "EFGE_ELNO", "EFGE_NOEU", "FORC_NODA",
                                              "REAC_NODA", "SIEF_ELGA", "SIGM_ELGA",
                                              "SIGM_ELNO")], "MED fields %s" % fields)
    mesh = f["ENS_MAA"]["patch_dkq"]["-0000000000000000001-0000000000000000001"]
    cells = [bytes(n).decode().strip() for n in mesh["MAI"]["QU4"]["NOM"][:]]
    conn = np.asarray(mesh["MAI"]["QU4"]["NOD"][:]).reshape(4, -1)   # by node rank
    node_names = [bytes(n).decode().strip() for n in mesh["NOE"]["NOM"][:]]
    loc = f["GAUSS"]["QU4_____FPG4___________6________ASTER_SP"]
    g = 1 / math.sqrt(3)
    pts = np.asarray(loc["GAU"][:]).reshape(2, 24).T        # stored by coordinate
    want = np.repeat(np.array([[-g, -g], [g, -g], [g, g], [-g, g]]), 6, axis=0)
    check(loc.attrs["GEO"] == 204 and np.allclose(pts, want, atol=1e-15) and
          np.allclose(loc["VAL"][:], 1.0), "MED: localisation FPG4 x 6 sub-points")
    check("QU4_____NOEU___________6________ASTER_SP" in f["GAUSS"], "MED: the NOEU localisation")

    def values(name, entity):
        grp = f["CHA"][name]["0000000000000000000100000000000000000001"][entity]
        data = grp["MED_NO_PROFILE_INTERNAL"]
        ncmp = int(f["CHA"][name].attrs["NCO"])
        return data.attrs, np.asarray(data["CO"][:]).reshape(ncmp, int(data.attrs["NBR"]),
                                                              int(data.attrs["NGA"]))
    attrs, v = values("RES_____SIGM_ELNO", "MAI.QU4")
    for j, cell in enumerate(cells):
        for k in range(4):
            node = node_names[conn[k, j] - 1]
            for s in range(6):
                check(close(v[0, j, k * 6 + s], sigm[(cell, node, s + 1)][0]),
                      "MED SIGM_ELNO %s %s %d" % (cell, node, s + 1))
    attrs, v = values("RES_____SIEF_ELGA", "MAI.QU4")
    for j, cell in enumerate(cells):
        for p in range(4):
            for s in range(6):
                check(close(v[0, j, p * 6 + s], sief[(cell, str(p + 1), s + 1)][0]),
                      "MED SIEF_ELGA %s %d %d" % (cell, p + 1, s + 1))
    attrs, v = values("RES_____EFGE_ELNO", "NOE.QU4")      # MED_NODE_ELEMENT
    check(attrs["NGA"] == 4 and np.allclose(v[3], MXX, rtol=1e-12), "MED EFGE_ELNO MXX")
with h5py.File(os.path.join(work, "cham.rmed"), "r") as f:
    step = f["CHA"]["TEMP"]["-0000000000000000001-0000000000000000001"]["NOE"]
    temp = np.asarray(step["MED_NO_PROFILE_INTERNAL"]["CO"][:])
    check(sorted(temp) == [20.0] * 4 + [50.0] * 4, "MED CHAM_GD TEMP %s" % temp)
with h5py.File(os.path.join(work, "mesh.rmed"), "r") as f:
    check("CHA" not in f and list(f["ENS_MAA"].keys()) == ["patch_dkq"], "MED mesh alone")
for name in units.values():
    dump = subprocess.run(["mdump", os.path.join(work, name)], input=b"1\n1\n0\n",
                          capture_output=True, timeout=60)
    text = dump.stdout.decode("utf-8", "replace")
    check(dump.returncode == 0 and "FIN DU DUMP" in text, "mdump %s: exit %d" % (
        name, dump.returncode))
    if name == "all.rmed":
        check("MED_NOEUD_MAILLE de type geometrique MED_QUAD4" in text and
              "|RES_____SIGM_ELNO|" in text, "mdump: the ELNO fields")

# ---- LIRE_CHAMP of a field the file does not have: a located error listing what it has
bad_deck = os.path.join(work, "bad_read.comm")
open(bad_deck, "w").write("DEBUT()\nm = LIRE_MAILLAGE(FORMAT='ASTER')\n"
                          "f = LIRE_CHAMP(MAILLAGE=m, UNITE=80, NOM_MED='RES_____NOPE',\n"
                          "               TYPE_CHAM='NOEU_DEPL_R', NOM_CMP_IDEM='OUI')\nFIN()\n")
bad = subprocess.run([parasol, "--outdir", work, "--unit", "20=" + mail, "--unit",
                      "80=" + os.path.join(work, "all.rmed"), bad_deck], capture_output=True,
                     text=True, timeout=60)
check(bad.returncode == 1 and "bad_read.comm:3:" in bad.stderr and
      "LIRE_CHAMP/NOM_MED: the file has no field RES_____NOPE (it has RES_____DEPL" in bad.stderr
      and "Fortran runtime" not in bad.stderr, "LIRE_CHAMP of a missing field: exit %d %s" % (
          bad.returncode, bad.stderr))

# ---- viewers
vtu = meshio.read(os.path.join(work, "field_output_RES_0001.vtu"))
top = np.concatenate(vtu.cell_data["SIGM_ELNO_SIXX_SP6"])
check(np.allclose(top, TOP, rtol=1e-12), "VTK SIGM_ELNO_SIXX_SP6 %s" % top)
check(np.allclose(vtu.point_data["EFGE_NOEU_MXX"], MXX, rtol=1e-12), "VTK EFGE_NOEU_MXX")
msh = gmsh22.read(os.path.join(work, "field_output_RES.msh"))
blocks = [b for b in msh["element_data"] if b.name.startswith("EFGE_ELNO_MXX")]
check(len(blocks) == 1 and all(close(r[0], MXX) for r in blocks[0].rows.values()),
      "Gmsh EFGE_ELNO_MXX")

for failure in failures:
    print("FAIL:", failure)
print("check_field_output: %d failures" % len(failures))
sys.exit(1 if failures else 0)

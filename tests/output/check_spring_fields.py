"""The springs' element fields of SSNL130 model A as users see them (tests/output/
ssnl130a_spring_fields.comm): parasol runs the deck (every TEST_RESU OK: SIEF_ELGA and
VARI_ELGA of four springs against the rigid-plate reference), then the files IMPR_RESU wrote
are read back:
 - VTK, with meshio: each .vtu holds CellData SIEF_ELGA_N/VY/VZ, VARI_ELGA_V1..V10,
   SPRING_STATUS and GROUP_<group> (and the plates' SIEF_ELGA_SI.._SP1..3); at INST 1 and 2 the status of every spring is its row's
   in the exact solution for the nodal load parasol applies (rows 0..n closed,
   tools/rigid_bed_exact.py, load="nodes"), N = k z for the closed
   ones (k by RIGI_PARASOL's area rule, z of the rigid plate) within 1e-6 of the largest
   force, 0 for the open ones, V1 = z for every spring within 1e-6 of max |z|;
 - Gmsh (gmsh22.py): $ElementData views named with their instant, the groups once (named
   without instant); the same values;
 - the .resu table of SIEF_ELGA N, one line per spring and point.
Usage: check_spring_fields.py PARASOL SOURCE_DIR WORKDIR"""
import os
import re
import subprocess
import sys
from fractions import Fraction as Fr

import meshio
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gmsh22  # noqa: E402

parasol, source, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(source, "tools"))
import rigid_bed_exact  # noqa: E402

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


os.makedirs(work, exist_ok=True)
deck = os.path.join(source, "tests", "output", "ssnl130a_spring_fields.comm")
mail = os.path.join(source, "decks", "ssnl130a.mail")
run = subprocess.run([parasol, "--quiet", "--outdir", work, "--unit", "20=" + mail, deck],
                     capture_output=True, text=True, timeout=300)
check(run.returncode == 0, f"parasol exit {run.returncode}: {run.stderr}")
stem = os.path.join(work, "ssnl130a_spring_fields")

# The mesh: plate nodes N1..N85 on 5 x 17 rows, springs M65..M149 from plate node to ground.
coords, springs = {}, {}
with open(mail) as f:
    block = None
    for line in f:
        words = line.split()
        if not words:
            continue
        if words[0] in ("COOR_3D", "SEG2", "QUAD4", "POI1", "FINSF", "GROUP_MA", "GROUP_NO"):
            block = words[0]
            continue
        if block == "COOR_3D" and len(words) == 4:
            coords[words[0]] = tuple(float(w) for w in words[1:])
        elif block == "SEG2" and len(words) == 3:
            springs[int(words[0][1:])] = (words[1], words[2])
ny, nx, b, a = 16, 4, Fr(2), Fr(1)
ref = rigid_bed_exact.solve_rigid_bed(ny, a=a, b=b, K=10000, p=5, m=2, load="nodes")
k_area = Fr(10000) / (a * b)
cell = (a / nx) * (b / ny)
expected = {}                       # cell number (1-based) -> (closed, N, z)
for number, (plate, ground) in springs.items():
    x, y, _ = coords[plate]
    xf, yf = Fr(x).limit_denominator(1000), Fr(y).limit_denominator(1000)
    share = (Fr(1, 2) if xf in (0, a) else 1) * (Fr(1, 2) if yf in (0, b) else 1)
    z = ref["w"] + ref["t"] * yf
    closed = z <= 0
    expected[number] = (closed, float(k_area * cell * share * z) if closed else 0.0, float(z))
n_force = max(abs(v[1]) for v in expected.values())
n_gap = max(abs(v[2]) for v in expected.values())
check(sum(v[0] for v in expected.values()) == 5 * (ref["n"] + 1), "reference: closed count")


def check_values(label, per_cell):
    """per_cell: name -> {cell number: value}"""
    for number, (closed, force, z) in expected.items():
        status = per_cell["SPRING_STATUS"].get(number)
        check(status == (1 if closed else 2), f"{label}: M{number} status {status}")
        n = per_cell["SIEF_ELGA_N"].get(number)
        check(n is not None and abs(n - force) <= 1e-6 * n_force,
              f"{label}: M{number} N = {n}, exact {force}")
        if "VARI_ELGA_V1" in per_cell:
            gap = per_cell["VARI_ELGA_V1"].get(number)
            check(gap is not None and abs(gap - z) <= 1e-6 * n_gap,
                  f"{label}: M{number} V1 = {gap}, exact {z}")
        v4 = per_cell["VARI_ELGA_V4"].get(number)
        check(v4 == (0.0 if closed else 2.0), f"{label}: M{number} V4 = {v4}")


# VTK: NUME_ORDRE 0..3 = INST 0, 1, 1.5, 2
names = {"SIEF_ELGA_N", "SIEF_ELGA_VY", "SIEF_ELGA_VZ", "SPRING_STATUS", "GROUP_DALLE",
         "GROUP_RESSORT", "GROUP_PTRESS"} | {f"VARI_ELGA_V{k}" for k in range(1, 11)}
for index in (2, 4):
    path = f"{stem}_RESU_{index:04d}.vtu"
    mesh = meshio.read(path)
    # besides, the plates' stresses of SIEF_ELGA at their 3 sub-points (one layer)
    plates = {f"SIEF_ELGA_{c}_SP{s}" for c in ("SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ")
              for s in (1, 2, 3)}
    check(set(mesh.cell_data) == names | plates, f"{path}: cell arrays {sorted(mesh.cell_data)}")
    if not names <= set(mesh.cell_data):
        continue
    flat = {k: np.concatenate(v) for k, v in mesh.cell_data.items()}
    check(len(flat["SIEF_ELGA_N"]) == 234, f"{path}: {len(flat['SIEF_ELGA_N'])} cells")
    per_cell = {k: {n: float(v[n - 1]) for n in expected} for k, v in flat.items()}
    check_values(path, per_cell)
    check(np.array_equal(flat["GROUP_RESSORT"], np.r_[np.zeros(64), np.ones(85), np.zeros(85)]),
          f"{path}: GROUP_RESSORT")
    check(not flat["SPRING_STATUS"][:64].any(), f"{path}: SPRING_STATUS on plate cells")

# Gmsh: DEPL DZ, SIEF_ELGA N, VARI_ELGA V4 (NOM_CMP) at INST 1 and 2; groups once (read with
# gmsh22.py: Debian's meshio cannot read $ElementData in a Gmsh 2.2 file)
msh = gmsh22.read(stem + "_RESU.msh")
views = {b.name: {n: v[0] for n, v in b.rows.items()} for b in msh["element_data"]}
check(set(views) == {"GROUP_DALLE", "GROUP_RESSORT", "GROUP_PTRESS"} |
      {f"{n} (INST {t})" for n in ("SIEF_ELGA_N", "VARI_ELGA_V4", "SPRING_STATUS")
       for t in ("1.0E+00", "2.0E+00")}, f"msh: views {sorted(views)}")
for t in ("1.0E+00", "2.0E+00"):
    per_cell = {n: views.get(f"{n} (INST {t})", {}) for n in
                ("SIEF_ELGA_N", "VARI_ELGA_V4", "SPRING_STATUS")}
    check(all(len(v) == 234 for v in per_cell.values()), f"msh INST {t}: every cell listed")
    check_values(f"msh INST {t}", per_cell)
check(sum(views.get("GROUP_DALLE", {}).values()) == 64, "msh: GROUP_DALLE has 64 cells")
check({b.name for b in msh["node_data"]} == {"DEPL (INST 1.0E+00)", "DEPL (INST 2.0E+00)"},
      f"msh: node views {[b.name for b in msh['node_data']]}")

# .resu: the table of SIEF_ELGA N at INST 1
with open(stem + ".resu") as f:
    resu = f.read()
table = re.search(r" ---- RESULTAT RESU  NOM_CHAM SIEF_ELGA  NUME_ORDRE 1  INST "
                  r"1.000000000000E\+00\n MAILLE +POINT +N\n((?: M\d+ +[12] +\S+\n)+)", resu)
check(table is not None, ".resu: no SIEF_ELGA table")
if table:
    rows = [r.split() for r in table.group(1).splitlines()]
    check(len(rows) == 170, f".resu: {len(rows)} rows, expected 85 springs x 2 points")
    for cell_name, point, value in rows:
        force = expected[int(cell_name[1:])][1]
        check(abs(float(value) - force) <= 1e-6 * n_force, f".resu: {cell_name} {point}")

for f in failures[:40]:
    print("FAIL:", f)
print(f"check_spring_fields: {len(failures)} failures")
sys.exit(1 if failures else 0)

"""Reads the files written by write_result_files with meshio (a real reader) and checks
point counts, cells per type and field values against the formulas of write_result_files.f90.
Usage: check_result_files.py FOLDER"""
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gmsh22  # noqa: E402

folder = sys.argv[1]
NN = 6
TIMES = [0.5, 1.0]
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def expected_depl(t, with_rotation=False):
    """DEPL vector (DX DY DZ) or rotation (0 0 DRZ) of write_result_files.f90."""
    out = np.zeros((NN, 3))
    for i in range(1, NN + 1):
        if with_rotation:
            out[i - 1, 2] = 0.0 if i == 6 else t * (10 * i + 4)
        else:
            for c in range(1, 4):
                out[i - 1, c - 1] = 0.0 if (i == 5 and c == 3) else t * (10 * i + c)
    return out


def expected_reac(t):
    out = np.zeros((NN, 3))
    for i in range(1, NN + 1):
        out[i - 1, 0:2] = [-t * (10 * i + 1), -t * (10 * i + 2)]
    return out


def check_mesh(mesh, label):
    check(mesh.points.shape[0] == NN, f"{label}: {mesh.points.shape[0]} points, expected {NN}")
    expected_points = np.array([[i / 10, 2 * i / 10, 3 * i / 10] for i in range(1, NN + 1)])
    check(np.allclose(mesh.points[:, :3], expected_points, rtol=1e-15, atol=0),
          f"{label}: coordinates differ")
    counts = {}
    for block in mesh.cells:
        counts[block.type] = counts.get(block.type, 0) + len(block.data)
    check(counts == {"quad": 1, "triangle": 1, "line": 1, "vertex": 1},
          f"{label}: cells per type {counts}")
    conn = {block.type: block.data.tolist() for block in mesh.cells}
    check(conn.get("quad") == [[0, 1, 2, 3]] and conn.get("triangle") == [[1, 4, 2]]
          and conn.get("line") == [[3, 5]] and conn.get("vertex") == [[5]],
          f"{label}: connectivity {conn}")


# VTK: the .pvd lists both instants; each .vtu holds the mesh and the fields.
pvd = ET.parse(os.path.join(folder, "tiny.pvd")).getroot()
datasets = pvd.findall("./Collection/DataSet")
check([float(d.get("timestep")) for d in datasets] == TIMES, "pvd: timesteps")
for k, d in enumerate(datasets):
    t = TIMES[k]
    mesh = meshio.read(os.path.join(folder, d.get("file")))
    label = d.get("file")
    check_mesh(mesh, label)
    data = mesh.point_data
    check(set(data) == {"DEPL", "DEPL_DR", "REAC_NODA"}, f"{label}: arrays {sorted(data)}")
    check(np.array_equal(data.get("DEPL"), expected_depl(t)), f"{label}: DEPL values")
    check(np.array_equal(data.get("DEPL_DR"), expected_depl(t, True)), f"{label}: DEPL_DR")
    check(np.array_equal(data.get("REAC_NODA"), expected_reac(t)), f"{label}: REAC_NODA")

# Gmsh: one view per array and instant, named with the instant ("DEPL (INST 1.0E+00)"), read
# block by block with their time and step tags (gmsh22.py: Debian's meshio cannot read a
# file with $ElementData; this one has none, so meshio reads it too).
mesh = meshio.read(os.path.join(folder, "tiny.msh"))
check_mesh(mesh, "tiny.msh")
check(np.array_equal(mesh.point_data.get("DEPL (INST 1.0E+00)"), expected_depl(1.0)),
      "tiny.msh: DEPL (meshio)")
with open(os.path.join(folder, "tiny.msh")) as f:
    head = f.read().split("\n")[0:3]
check(head == ["$MeshFormat", "2.2 0 8", "$EndMeshFormat"], "tiny.msh: header")
blocks = gmsh22.read(os.path.join(folder, "tiny.msh"))["node_data"]
label = {0.5: "5.0E-01", 1.0: "1.0E+00"}
check([(b.name, b.time, b.step, b.components) for b in blocks] ==
      [(f"{nm} (INST {label[t]})", t, s, 3) for s, t in ((1, 0.5), (2, 1.0))
       for nm in ("DEPL", "DEPL_DR", "REAC_NODA")],
      f"tiny.msh: NodeData blocks {[(b.name, b.time, b.step, b.components) for b in blocks]}")
for b in blocks:
    name = b.name.split(" (INST ")[0]
    expected = {"DEPL": expected_depl(b.time), "DEPL_DR": expected_depl(b.time, True),
                "REAC_NODA": expected_reac(b.time)}[name]
    rows = np.array([b.rows[i] for i in range(1, NN + 1)])
    check(np.array_equal(rows, expected), f"tiny.msh: {b.name}")

for f in failures:
    print("FAIL:", f)
print(f"check_result_files: {len(failures)} failures")
sys.exit(1 if failures else 0)

#!/usr/bin/python3
"""Reads back, with meshio (Debian python3-meshio; Gmsh with tests/output/gmsh22.py), the
VTK and Gmsh files that
loads_bilateral.comm writes with IMPR_RESU, and checks them against the deck's exact answer:
171 points (85 plate + 85 ground nodes + PCDG), 64 QUAD4 + 85 SEG2 + 85 POI1 cells, and the
plate's uniform settlement DZ = -2 INST q a b / K under FONC_MULT = 2 INST (INST 1 and 2),
zero at the ground nodes.

usage: check_impr_resu_files.py OUTDIR
"""
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "output"))
import gmsh22  # noqa: E402

U = 5.0 * 1.0 * 2.0 / 1.0e4          # q a b / K
PLATE = range(0, 85)                 # N1..N85 in decks/ssnl130a.mail
GROUND = range(85, 170)


def check_mesh(mesh, where):
    assert mesh.points.shape[0] == 171, f"{where}: {mesh.points.shape[0]} points, expected 171"
    counts = {}
    for block in mesh.cells:
        counts[block.type] = counts.get(block.type, 0) + len(block.data)
    expected = {"quad": 64, "line": 85, "vertex": 85}
    assert counts == expected, f"{where}: cells {counts}, expected {expected}"


def check_depl(depl, inst, where):
    dz = depl[:, 2]
    want = -2.0 * inst * U
    plate = dz[list(PLATE)]
    assert np.allclose(plate, want, rtol=1e-4, atol=0.0), \
        f"{where}: plate DZ in [{plate.min()}, {plate.max()}], expected {want}"
    assert np.all(dz[list(GROUND)] == 0.0), f"{where}: ground nodes moved"


def main():
    out = sys.argv[1]
    stem = os.path.join(out, "loads_bilateral_r_mult")
    # VTK: the .pvd collection lists one .vtu per instant with its time.
    datasets = ET.parse(stem + ".pvd").getroot().iter("DataSet")
    entries = [(float(d.get("timestep")), d.get("file")) for d in datasets]
    assert [t for t, _ in entries] == [1.0, 2.0], f"pvd instants {entries}"
    for inst, name in entries:
        mesh = meshio.read(os.path.join(out, name))
        check_mesh(mesh, name)
        check_depl(mesh.point_data["DEPL"], inst, name)
        assert "REAC_NODA" in mesh.point_data, f"{name}: no REAC_NODA"
    # Gmsh 2.2: one $NodeData block (view) per array and instant, named with the instant;
    # the cell groups as $ElementData (read with gmsh22.py: Debian's meshio 5.0 cannot read
    # $ElementData in a 2.2 file).
    msh = gmsh22.read(stem + ".msh")
    assert msh["nodes"].shape == (171, 3), f"msh: {msh['nodes'].shape} nodes"
    types = [e[1] for e in msh["elements"]]
    assert (types.count(3), types.count(1), types.count(15)) == (64, 85, 85), "msh: cells"
    views = {b.name: b for b in msh["node_data"]}
    for inst, label in ((1.0, "1.0E+00"), (2.0, "2.0E+00")):
        name = f"DEPL (INST {label})"
        assert name in views, f"msh: no {name} node data ({list(views)})"
        depl = np.array([views[name].rows[i] for i in range(1, 172)])
        check_depl(depl, inst, "msh")
    groups = {b.name: b for b in msh["element_data"]}
    assert sum(v[0] for v in groups["GROUP_DALLE"].rows.values()) == 64, "msh: GROUP_DALLE"
    print("IMPR_RESU files read back by meshio: OK")


if __name__ == "__main__":
    main()

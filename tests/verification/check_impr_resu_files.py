#!/usr/bin/python3
"""Reads back, with meshio (Debian python3-meshio), the VTK and Gmsh files that
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
    # Gmsh 2.2: one $NodeData block per instant; meshio keeps the last one of a name.
    mesh = meshio.read(stem + ".msh")
    check_mesh(mesh, "msh")
    assert "DEPL" in mesh.point_data, f"msh: no DEPL node data ({list(mesh.point_data)})"
    check_depl(np.asarray(mesh.point_data["DEPL"]), 2.0, "msh")
    print("IMPR_RESU files read back by meshio: OK")


if __name__ == "__main__":
    main()

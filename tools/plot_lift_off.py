#!/usr/bin/python3
"""Draw the SSNL130 lift-off as parasol's own VTK output shows it (doc/ssnl130a_lift_off.png).

Runs parasol on tests/output/ssnl130a_spring_fields.comm (SSNL130 model A with IMPR_RESU
FORMAT='VTK'), reads the .vtu files it writes with meshio, and draws with matplotlib, at
INST 1 (pressure on, ground at rest) and INST 2 (ground lifted by 5 mm):
 - the plate's cells at their displaced height (DEPL DZ, magnified), coloured by DZ;
 - the springs from each plate node to its ground node, coloured by the SPRING_STATUS cell
   array (closed: in contact, open: lifted off); the legend gives their count and the total
   of their normal forces SIEF_ELGA_N;
 - the lift-off line where the plate's DZ relative to the ground changes sign.
Nothing is computed here but the drawing: every value comes from the .vtu files.

It prints, per instant, what it drew (springs closed and open, their load, the lift-off
line); the `bench.doc_picture_lift_off` test runs it into the build tree and checks those
against the rigid-plate reference for the nodal load parasol applies, as Code_Aster (65
closed springs carry the load's 855/64 N, the lift-off line at y = 1.5115 m).
"""
import argparse
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection, Line3DCollection  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLOSED, OPEN = 1, 2          # SPRING_STATUS (doc/listings.md)


def run_parasol(parasol, work):
    deck = os.path.join(ROOT, "tests", "output", "ssnl130a_spring_fields.comm")
    mail = os.path.join(ROOT, "decks", "ssnl130a.mail")
    subprocess.run([parasol, "--quiet", "--outdir", work, "--unit", "20=" + mail, deck],
                   check=True)
    return os.path.join(work, "ssnl130a_spring_fields_RESU_{:04d}.vtu")


def cell_blocks(mesh):
    """cell type -> (connectivity, {array: values}) with the cell data of each block."""
    out = {}
    for k, block in enumerate(mesh.cells):
        data = {name: values[k] for name, values in mesh.cell_data.items()}
        out[block.type] = (block.data, data)
    return out


def draw(ax, mesh, inst, scale):
    pts = mesh.points
    dz = mesh.point_data["DEPL"][:, 2]
    blocks = cell_blocks(mesh)
    quads, _ = blocks["quad"]
    lines, line_data = blocks["line"]
    z = dz * scale
    polys = [[(pts[i, 0], pts[i, 1], z[i]) for i in q] for q in quads]
    plate_dz = dz[quads].mean(axis=1)
    norm = plt.Normalize(vmin=dz[np.unique(quads)].min(), vmax=dz[np.unique(quads)].max())
    surface = Poly3DCollection(polys, facecolors=plt.cm.viridis(norm(plate_dz)),
                               edgecolors="0.3", linewidths=0.3, alpha=0.75, zorder=1)
    ax.add_collection3d(surface)
    status = line_data["SPRING_STATUS"].astype(int)
    force = line_data["SIEF_ELGA_N"]
    ground_depth = 0.25                  # drawn length of a spring below the plate
    for wanted, colour, label in ((CLOSED, "tab:blue", "closed (in contact)"),
                                  (OPEN, "tab:red", "open (lifted off)")):
        chosen = lines[status == wanted]
        segs = []
        for a, b in chosen:
            top, bottom = (a, b) if pts[a, 2] > pts[b, 2] else (b, a)
            x, y = pts[top, 0], pts[top, 1]
            segs.append([(x, y, z[top]), (x, y, z[bottom] - ground_depth)])
        total = abs(force[status == wanted].sum())
        ax.add_collection3d(Line3DCollection(
            segs, colors=colour, linewidths=1.6,
            label=f"{len(chosen)} {label}, carrying {total:.3f} N"))
    # lift-off line: where the plate's DZ relative to its ground node changes sign
    rows = np.unique(np.round(pts[np.unique(quads), 1], 9))
    gap = {}
    for a, b in lines:
        top, bottom = (a, b) if pts[a, 2] > pts[b, 2] else (b, a)
        gap.setdefault(round(pts[top, 1], 9), []).append(dz[top] - dz[bottom])
    rel = np.array([np.mean(gap[y]) for y in rows])
    crossings = np.nonzero(np.diff(np.sign(rel)) != 0)[0]
    y0 = float("nan")
    if len(crossings):
        k = crossings[0]
        y0 = rows[k] - rel[k] * (rows[k + 1] - rows[k]) / (rel[k + 1] - rel[k])
        x = np.array([pts[:, 0].min(), pts[:, 0].max()])
        zline = np.interp(y0, rows, [np.mean([dz[i] for i in np.unique(quads)
                                              if abs(pts[i, 1] - y) < 1e-9]) for y in rows])
        ax.plot(x, [y0, y0], [zline * scale + 0.02] * 2, color="black", linestyle="--",
                linewidth=2.5, zorder=10, label=f"lift-off line, y = {y0:.3f} m")
    plate_z = z[np.unique(quads)]
    ax.set_xlim(pts[:, 0].min(), pts[:, 0].max())
    ax.set_ylim(pts[:, 1].min(), pts[:, 1].max())
    ax.set_zlim(plate_z.min() - ground_depth - 0.05, plate_z.max() + 0.05)
    print(f"INST {inst:g}: {np.sum(status == CLOSED)} springs closed carrying "
          f"{abs(force[status == CLOSED].sum()):.4f} N, {np.sum(status == OPEN)} open carrying "
          f"{abs(force[status == OPEN].sum()):.4f} N, lift-off line at y = "
          f"{y0:.4f} m")
    ax.set_title(f"INST {inst:g}: DZ x {scale:g}", fontsize=10)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zticks([])
    ax.view_init(elev=22, azim=-60)
    ax.set_box_aspect((1, 2, 0.8))
    ax.legend(loc="upper left", fontsize=7)
    return norm


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    ap.add_argument("--parasol", default=os.path.join(ROOT, "build", "parasol"),
                    help="the parasol executable")
    ap.add_argument("-o", "--output", default=os.path.join(ROOT, "doc", "ssnl130a_lift_off.png"),
                    help="the PNG to write")
    ap.add_argument("--scale", type=float, default=100.0, help="magnification of DZ")
    o = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as work:
        pattern = run_parasol(o.parasol, work)
        # NUME_ORDRE 0, 1, 2, 3 = INST 0, 1, 1.5, 2: files 0002 and 0004
        meshes = [(1.0, meshio.read(pattern.format(2))), (2.0, meshio.read(pattern.format(4)))]
    fig = plt.figure(figsize=(11, 6.2))
    for k, (inst, mesh) in enumerate(meshes):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        norm = draw(ax, mesh, inst, o.scale)
        cbar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="viridis"), ax=ax,
                            shrink=0.55, pad=0.02)
        cbar.set_label("plate DZ (m)")
    fig.suptitle("SSNL130 model A: plate on 85 unilateral springs (DIS_CHOC), parasol's "
                 "VTK output (DEPL, SPRING_STATUS, SIEF_ELGA_N)", fontsize=11)
    fig.tight_layout()
    fig.savefig(o.output, dpi=110)
    print(f"wrote {o.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

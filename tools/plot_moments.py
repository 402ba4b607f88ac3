#!/usr/bin/python3
"""Draw plate bending moments as parasol's own VTK output gives them (doc/plate_moments.png).

Two cases, each run by parasol into a scratch folder, then read back with meshio:
 - SSNL130 model A at INST 1 (tests/output/ssnl130a_spring_fields.comm, the plate on its
   spring bed under the pressure, part of it lifted off), with CALC_CHAMP EFGE_NOEU on the
   plate and IMPR_RESU(FORMAT='VTK') of it added;
 - a clamped square plate (the unit square of tests/verification/plate_dkq_32.mail, 32 x 32
   DKQ, h = 0.01 m, steel) under a uniform pressure of 1 kPa, every DOF of its edge held.
Each case gives two panels, MXX and MYY (N m / m, the nodal means of EFGE_NOEU, Code_Aster's
sign: MXX < 0 where the plate sags under a load along -z), drawn on the plate's quadrangles
split into triangles. Nothing is computed here but the drawing. It prints each panel's range
and, for the clamped plate, the centre and mid-edge moments beside Timoshenko's values for a
clamped square plate with nu = 0.3 (Theory of Plates and Shells, table 35: centre
0.0231 q a^2, middle of an edge -0.0513 q a^2); DKQ on 32 x 32 is expected within a few %.

usage: plot_moments.py --parasol PARASOL [-o doc/plate_moments.png]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SSNL130_TAIL = """
RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, CONTRAINTE='EFGE_NOEU', GROUP_MA='DALLE')
IMPR_RESU(FORMAT='VTK', RESU=_F(RESULTAT=RESU, NOM_CHAM='EFGE_NOEU', INST=1.0))
FIN()
"""

CLAMPED = """DEBUT()
mail = LIRE_MAILLAGE(FORMAT='ASTER')
model = AFFE_MODELE(MAILLAGE=mail,
                    AFFE=_F(GROUP_MA='PLAQUE', PHENOMENE='MECANIQUE', MODELISATION='DKT'))
steel = DEFI_MATERIAU(ELAS=_F(E=2.1e11, NU=0.3))
mater = AFFE_MATERIAU(MAILLAGE=mail, AFFE=_F(TOUT='OUI', MATER=steel))
cara = AFFE_CARA_ELEM(MODELE=model, COQUE=_F(GROUP_MA='PLAQUE', EPAIS=0.01))
load = AFFE_CHAR_MECA(MODELE=model, FORCE_COQUE=_F(GROUP_MA='PLAQUE', PRES=1.0e3),
                      DDL_IMPO=_F(GROUP_NO='BORD', DX=0.0, DY=0.0, DZ=0.0,
                                  DRX=0.0, DRY=0.0, DRZ=0.0))
res = MECA_STATIQUE(MODELE=model, CHAM_MATER=mater, CARA_ELEM=cara, EXCIT=_F(CHARGE=load))
res = CALC_CHAMP(reuse=res, RESULTAT=res, CONTRAINTE='EFGE_NOEU')
IMPR_RESU(FORMAT='VTK', RESU=_F(RESULTAT=res, NOM_CHAM='EFGE_NOEU'))
FIN()
"""


def run_case(parasol, work, stem, text, mail):
    deck = os.path.join(work, stem + ".comm")
    with open(deck, "w") as f:
        f.write(text)
    subprocess.run([parasol, "--quiet", "--outdir", work, "--unit", "20=" + mail, deck],
                   check=True)
    names = sorted(n for n in os.listdir(work) if n.startswith(stem + "_") and n.endswith(".vtu"))
    return meshio.read(os.path.join(work, names[0]))


def plate_triangulation(mesh):
    quads = np.concatenate([block.data for block in mesh.cells if block.type == "quad"])
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    return mtri.Triangulation(mesh.points[:, 0], mesh.points[:, 1], tris)


def panel(fig, ax, tri, values, title):
    levels = np.linspace(values[np.unique(tri.triangles)].min(),
                         values[np.unique(tri.triangles)].max(), 21)
    filled = ax.tricontourf(tri, values, levels=levels, cmap="coolwarm")
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    fig.colorbar(filled, ax=ax, shrink=0.85, label="N m / m")
    used = values[np.unique(tri.triangles)]
    print("%s: %.4g .. %.4g N m/m" % (title, used.min(), used.max()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--parasol", required=True)
    parser.add_argument("-o", "--output", default=os.path.join(ROOT, "doc", "plate_moments.png"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        head = open(os.path.join(ROOT, "tests", "output", "ssnl130a_spring_fields.comm")).read()
        head = head[:head.index("IMPR_RESU(")]
        a = run_case(args.parasol, work, "ssnl130a_moments", head + SSNL130_TAIL,
                     os.path.join(ROOT, "decks", "ssnl130a.mail"))
        c = run_case(args.parasol, work, "clamped_plate", CLAMPED,
                     os.path.join(ROOT, "tests", "verification", "plate_dkq_32.mail"))
    fig, axes = plt.subplots(2, 2, figsize=(11, 9))
    for row, (mesh, name) in enumerate(((a, "SSNL130 model A, INST 1"),
                                        (c, "clamped square plate, 1 kPa"))):
        tri = plate_triangulation(mesh)
        for col, cmp in enumerate(("MXX", "MYY")):
            values = mesh.point_data["EFGE_NOEU_" + cmp][:, 0]
            panel(fig, axes[row, col], tri, values, "%s: EFGE_NOEU %s" % (name, cmp))
    # the clamped plate against Timoshenko's coefficients (q a^2 = 1e3 N m / m here)
    pts = c.points
    mxx = c.point_data["EFGE_NOEU_MXX"][:, 0]
    centre = np.argmin(np.hypot(pts[:, 0] - 0.5, pts[:, 1] - 0.5))
    edge = np.argmin(np.hypot(pts[:, 0] - 0.0, pts[:, 1] - 0.5))
    print("clamped plate: MXX at the centre %.4g (Timoshenko -23.1 in this sign), "
          "at the middle of the edge x = 0 %.4g (Timoshenko +51.3)"
          % (mxx[centre], mxx[edge]))
    fig.suptitle("Plate bending moments from parasol's VTK output (tools/plot_moments.py)")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print("wrote", args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())

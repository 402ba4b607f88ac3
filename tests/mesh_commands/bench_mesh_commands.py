#!/usr/bin/env python3
"""Benchmark of the mesh commands (issue 18 §8; doc/performance.md, "Mesh commands"): every
DEFI_GROUP option, MODI_MAILLAGE operation and CREA_MAILLAGE operation on meshes of about a
million nodes, each timed as the CPU time (user + system) of a parasol run with the command
less that of the same run without it (the mesh read alone), best of --repeat runs.

usage: bench_mesh_commands.py PARASOL [--n 1000] [--line 1000000] [--repeat 3] [--work DIR]
                              [--only NAME,...] [--limit 1.0]

Meshes (written once into WORK): the N x N plate of plate_mesh.py ((N+1)^2 nodes, N^2 QUAD4,
4N boundary SEG2); the same plate tilted out of its plane (z = x/1000: a 3D mesh, for the
options that need one); a straight line of --line SEG2 cells along x, given in a scrambled
order and orientation (for NOEUD_ORDO, SEGM_DROI_ORDO, ORIE_LIGNE). Prints one line per
operation `RESULT mesh_command NAME seconds=S` and exits 1 when one takes more than --limit.
"""
import argparse
import os
import random
import resource
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

HEAD = "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='ASTER')\n"

# name -> (mesh, deck body); every body follows HEAD and precedes FIN().
PLATE, TILTED, LINE = "plate", "tilted", "line"
DG = "MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, "
MM = "MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, "
OPERATIONS = [
    ("crea_group_ma_tout", PLATE, DG + "CREA_GROUP_MA=_F(NOM='ALL', TOUT='OUI'))"),
    ("crea_group_ma_maille", PLATE, DG + "CREA_GROUP_MA=_F(NOM='SOME', MAILLE=('Q1', 'Q500', 'Q999999')))"),
    ("crea_group_ma_slice", PLATE, DG + "CREA_GROUP_MA=_F(NOM='HALF', GROUP_MA='PLAQUE', NUME_INIT=1, NUME_FIN=500000))"),
    ("crea_group_ma_union", PLATE, DG + "CREA_GROUP_MA=_F(NOM='U', UNION=('PLAQUE', 'BORD')))"),
    ("crea_group_ma_intersec", PLATE, DG + "CREA_GROUP_MA=_F(NOM='I', INTERSEC=('PLAQUE', 'PLAQUE')))"),
    ("crea_group_ma_diffe", PLATE, DG + "CREA_GROUP_MA=_F(NOM='D', DIFFE=('PLAQUE', 'BORD')))"),
    ("crea_group_ma_type_maille", PLATE, DG + "CREA_GROUP_MA=_F(NOM='T', TOUT='OUI', TYPE_MAILLE='1D'))"),
    ("crea_group_ma_face_normale_2d", PLATE, DG + "CREA_GROUP_MA=_F(NOM='F', OPTION='FACE_NORMALE', VECT_NORMALE=(0.0, -1.0)))"),
    ("crea_group_ma_face_normale_3d", TILTED, DG + "CREA_GROUP_MA=_F(NOM='F', OPTION='FACE_NORMALE', VECT_NORMALE=(-0.001, 0.0, 1.0)))"),
    ("crea_group_ma_sphere", PLATE, DG + "CREA_GROUP_MA=_F(NOM='S', OPTION='SPHERE', POINT=(500.0, 500.0), RAYON=300.0))"),
    ("crea_group_ma_cylindre", TILTED, DG + "CREA_GROUP_MA=_F(NOM='C', OPTION='CYLINDRE', POINT=(500.0, 500.0, 0.5), RAYON=300.0, VECT_NORMALE=(0.0, 0.0, 1.0)))"),
    ("crea_group_ma_bande", PLATE, DG + "CREA_GROUP_MA=_F(NOM='B', OPTION='BANDE', POINT=(0.0, 500.0), DIST=100.0, VECT_NORMALE=(0.0, 1.0)))"),
    ("crea_group_ma_appui", PLATE, DG + "CREA_GROUP_MA=_F(NOM='P', OPTION='APPUI', GROUP_NO='A', TYPE_APPUI='AU_MOINS_UN'))"),
    ("crea_group_no_tout_group_ma", PLATE, DG + "CREA_GROUP_NO=_F(TOUT_GROUP_MA='OUI'))"),
    ("crea_group_no_group_ma", PLATE, DG + "CREA_GROUP_NO=_F(GROUP_MA='PLAQUE', NOM='NP'))"),
    ("crea_group_no_noeud", PLATE, DG + "CREA_GROUP_NO=_F(NOM='NN', NOEUD=('N1', 'N1000000')))"),
    ("crea_group_no_slice", PLATE, DG + "CREA_GROUP_NO=(_F(GROUP_MA='PLAQUE', NOM='NP'), _F(NOM='NS', GROUP_NO='NP', NUME_INIT=2, NUME_FIN=900000)))"),
    ("crea_group_no_union", PLATE, DG + "CREA_GROUP_NO=(_F(GROUP_MA='PLAQUE', NOM='NP'), _F(NOM='NU', UNION=('NP', 'A'))))"),
    ("crea_group_no_env_sphere", PLATE, DG + "CREA_GROUP_NO=_F(NOM='E', OPTION='ENV_SPHERE', POINT=(500.0, 500.0), RAYON=300.0, PRECISION=0.5))"),
    ("crea_group_no_env_cylindre", TILTED, DG + "CREA_GROUP_NO=_F(NOM='E', OPTION='ENV_CYLINDRE', POINT=(500.0, 500.0, 0.5), RAYON=300.0, PRECISION=0.5, VECT_NORMALE=(0.0, 0.0, 1.0)))"),
    ("crea_group_no_plan", PLATE, DG + "CREA_GROUP_NO=_F(NOM='E', OPTION='PLAN', POINT=(500.0, 0.0), VECT_NORMALE=(1.0, 0.0), PRECISION=0.1))"),
    ("crea_group_no_inclusion", PLATE, DG + "CREA_GROUP_NO=_F(NOM='E', OPTION='INCLUSION', CAS_FIGURE='2D', GROUP_MA='PLAQUE', GROUP_MA_INCL='PLAQUE'))"),
    ("crea_group_no_noeud_ordo", LINE, DG + "CREA_GROUP_NO=_F(NOM='E', OPTION='NOEUD_ORDO', GROUP_MA='LINE', GROUP_NO_ORIG='A'))"),
    ("crea_group_no_segm_droi_ordo", LINE, DG + "CREA_GROUP_NO=_F(NOM='E', OPTION='SEGM_DROI_ORDO', GROUP_NO='ALLN', GROUP_NO_ORIG='A', GROUP_NO_EXTR='B', PRECISION=1.0E-6, CRITERE='RELATIF'))"),
    ("detr_group_ma", PLATE, DG + "DETR_GROUP_MA=_F(NOM=('PLAQUE', 'BORD')))"),
    ("translation", PLATE, MM + "TRANSLATION=(1.0, 2.0))"),
    ("rotation", PLATE, MM + "ROTATION=_F(POIN_1=(0.0, 0.0), ANGLE=30.0))"),
    ("symetrie", PLATE, MM + "SYMETRIE=_F(POINT=(0.0, 0.0), AXE_1=(1.0, 1.0)))"),
    ("echelle", PLATE, MM + "ECHELLE=2.0)"),
    ("modi_base", TILTED, MM + "MODI_BASE=_F(VECT_X=(0.0, 1.0, 0.0), VECT_Y=(0.0, 0.0, 1.0)))"),
    ("orie_peau", PLATE, MM + "ORIE_PEAU=_F(GROUP_MA_PEAU='BORD'))"),
    ("orie_norm_coque", PLATE, MM + "ORIE_NORM_COQUE=_F(GROUP_MA='PLAQUE'))"),
    ("orie_norm_coque_vect", PLATE, MM + "ORIE_NORM_COQUE=_F(GROUP_MA='PLAQUE', VECT_NORM=(0.0, 0.0, -1.0), GROUP_NO='A'))"),
    ("orie_ligne", LINE, MM + "ORIE_LIGNE=_F(GROUP_MA='LINE'))"),
    ("crea_poi1", PLATE, "M2 = CREA_MAILLAGE(MAILLAGE=MA, CREA_POI1=_F(NOM_GROUP_MA='P', TOUT='OUI'))"),
    ("crea_maille", PLATE, "M2 = CREA_MAILLAGE(MAILLAGE=MA, CREA_MAILLE=_F(NOM='C', GROUP_MA='PLAQUE'))"),
    ("quad_tria3", PLATE, "M2 = CREA_MAILLAGE(MAILLAGE=MA, MODI_MAILLE=_F(OPTION='QUAD_TRIA3', TOUT='OUI'))"),
    ("line_quad", PLATE, "M2 = CREA_MAILLAGE(MAILLAGE=MA, LINE_QUAD=_F(TOUT='OUI'))"),
    ("restreint", PLATE, "M2 = CREA_MAILLAGE(MAILLAGE=MA, RESTREINT=_F(GROUP_MA='PLAQUE', TOUT_GROUP_MA='OUI', TOUT_GROUP_NO='OUI'))"),
]
# operations timed against a baseline that already made what they need (key -> its body)
BASES = {
    "quadratic": "M2 = CREA_MAILLAGE(MAILLAGE=MA, LINE_QUAD=_F(TOUT='OUI'))",
    "field": "CH = CREA_CHAMP(TYPE_CHAM='NOEU_DEPL_R', OPERATION='AFFE', MAILLAGE=MA, "
             "AFFE=_F(TOUT='OUI', NOM_CMP=('DX', 'DY'), VALE=(0.5, 0.25)))",
}
BASED = [
    ("quad_line", "quadratic", "M3 = CREA_MAILLAGE(MAILLAGE=M2, QUAD_LINE=_F(TOUT='OUI'))"),
    ("quad8_9", "quadratic", "M3 = CREA_MAILLAGE(MAILLAGE=M2, MODI_MAILLE=_F(OPTION='QUAD8_9', TOUT='OUI'))"),
    ("deforme_depl", "field", MM + "DEFORME=_F(OPTION='TRAN', DEPL=CH))"),
    ("deforme_alea", "field", MM + "DEFORME=_F(OPTION='TRAN', ALEA=1.0E-4))"),
]

def write_line_mesh(path, n, seed=7):
    """n SEG2 along x in scrambled order and orientation; groups LINE (every cell), ALLN
    (every node, scrambled), A and B (the ends)."""
    rng = random.Random(seed)
    order = list(range(n))
    rng.shuffle(order)
    with open(path, "w") as f:
        f.write("TITRE\nline of %d SEG2 (bench_mesh_commands.py)\nFINSF\nCOOR_2D\n" % n)
        f.writelines("N%d %d.0 0.0\n" % (k + 1, k) for k in range(n + 1))
        f.write("FINSF\nSEG2\n")
        for c, k in enumerate(order):
            a, b = k + 1, k + 2
            if rng.random() < 0.5:
                a, b = b, a
            f.write("S%d N%d N%d\n" % (c + 1, a, b))
        f.write("FINSF\nGROUP_MA NOM=LINE\n")
        f.writelines("S%d\n" % (c + 1) for c in range(n))
        nodes = list(range(1, n + 2))
        rng.shuffle(nodes)
        f.write("FINSF\nGROUP_NO NOM=ALLN\n")
        f.writelines("N%d\n" % k for k in nodes)
        f.write("FINSF\nGROUP_NO NOM=A\nN1\nFINSF\nGROUP_NO NOM=B\nN%d\nFINSF\nFIN\n" % (n + 1))


def cpu_of_run(parasol, deck, mesh, work):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run([parasol, "--quiet", "--outdir", work, "--unit", "20=" + mesh, deck],
                         capture_output=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        raise SystemExit("bench_mesh_commands: %s failed:\n%s" % (deck, run.stderr.decode()))
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def best(parasol, work, name, body, mesh, repeat):
    deck = os.path.join(work, name + ".comm")
    with open(deck, "w") as f:
        f.write(HEAD + body + "\nFIN()\n")
    return min(cpu_of_run(parasol, deck, mesh, work) for _ in range(repeat))


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument("parasol")
    ap.add_argument("--n", type=int, default=1000)
    ap.add_argument("--line", type=int, default=1000000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--work", default="bench_mesh_commands_work")
    ap.add_argument("--only", default="")
    ap.add_argument("--limit", type=float, default=1.0)
    a = ap.parse_args(argv[1:])
    os.makedirs(a.work, exist_ok=True)
    parasol = os.path.abspath(a.parasol)
    meshes = {PLATE: os.path.join(a.work, "plate.mail"),
              TILTED: os.path.join(a.work, "tilted.mail"),
              LINE: os.path.join(a.work, "line.mail")}
    import plate_mesh
    if not os.path.exists(meshes[PLATE]):
        plate_mesh.main(["plate_mesh.py", str(a.n), meshes[PLATE]])
    if not os.path.exists(meshes[TILTED]):
        with open(meshes[PLATE]) as f, open(meshes[TILTED], "w") as g:
            section = None
            for line in f:
                word = line.split()
                if word and word[0] in ("COOR_2D", "FINSF"):
                    section = word[0]
                    g.write(line.replace("COOR_2D", "COOR_3D"))
                    continue
                if section == "COOR_2D":
                    x, y = float(word[1]), float(word[2])
                    g.write("%s %s %s %.6f\n" % (word[0], word[1], word[2], x / 1000.0))
                else:
                    g.write(line)
    if not os.path.exists(meshes[LINE]):
        write_line_mesh(meshes[LINE], a.line)
    only = set(a.only.split(",")) if a.only else None
    base = {}
    slow = []
    based = {n: k for n, k, _ in BASED}
    for name, mesh, body in OPERATIONS + [(n, PLATE, b) for n, _, b in BASED]:
        if only and name not in only:
            continue
        key = based.get(name, mesh)
        if key not in base:
            body0 = BASES.get(key, "")
            base[key] = best(parasol, a.work, "base_" + key, body0,
                             meshes[mesh], a.repeat)
            print("RESULT mesh_command base_%s seconds=%.3f" % (key, base[key]), flush=True)
        if name in based:
            body = BASES[based[name]] + "\n" + body
        seconds = best(parasol, a.work, name, body, meshes[mesh], a.repeat) - base[key]
        print("RESULT mesh_command %s seconds=%.3f" % (name, seconds), flush=True)
        if seconds > a.limit:
            slow.append(name)
    if slow:
        print("over %.1f s: %s" % (a.limit, ", ".join(slow)))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

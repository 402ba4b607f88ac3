#!/usr/bin/python3
"""TEST_RESU on the springs' element fields (SIEF_ELGA, VARI_ELGA) that cannot be answered,
and IMPR_RESU of a field not computed, stop with a located message at the keyword
at fault (exit 1, no crash). Each case appends
one TEST_RESU to decks/ssnl130b.comm (model B: 2D_DIS_T springs M49..M65, group RESSORTS).

Usage: spring_field_errors.py PARASOL DECKS_DIR WORKDIR
"""
import os
import subprocess
import sys

parasol, decks, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
with open(os.path.join(decks, "ssnl130b.comm")) as f:
    base = f.read().split("\n")
fin = base.index("FIN()")

# (name, TEST_RESU occurrence text, keyword at fault, phrase)
CASES = [
    ("no_point", "NOM_CHAM='SIEF_ELGA', NOM_CMP='N', MAILLE='M49'", "NOM_CHAM",
     "SIEF_ELGA is read at a Gauss point: give POINT (1 to 2 on cell M49)"),
    ("point_3", "NOM_CHAM='SIEF_ELGA', NOM_CMP='N', MAILLE='M49', POINT=3", "POINT",
     "cell M49: POINT 3 does not exist: the cell has 2 Gauss point(s) (POINT 1 to 2)"),
    ("group_of_17", "NOM_CHAM='VARI_ELGA', NOM_CMP='V4', GROUP_MA='RESSORTS', POINT=1",
     "GROUP_MA", "GROUP_MA RESSORTS holds 17 cells; TEST_RESU needs a group of exactly one"),
    ("slab_cell", "NOM_CHAM='VARI_ELGA', NOM_CMP='V1', MAILLE='M1', POINT=1", "MAILLE",
     "cell M1: the field has no value on the cell"),
    ("vz_in_2d", "NOM_CHAM='SIEF_ELGA', NOM_CMP='VZ', MAILLE='M49', POINT=1", "NOM_CMP",
     "cell M49: the cell has no component VZ in this field (it has N VY)"),
    ("v11", "NOM_CHAM='VARI_ELGA', NOM_CMP='DX', MAILLE='M49', POINT=1", "NOM_CMP",
     "cell M49: the cell has no component DX in this field (it has V1 V2 V3"),
    ("depl_at_cell", "NOM_CHAM='DEPL', NOM_CMP='DY', MAILLE='M49'", "MAILLE",
     "DEPL is a nodal field: give GROUP_NO or NOEUD"),
    ("sief_at_node", "NOM_CHAM='SIEF_ELGA', NOM_CMP='N', NOEUD='N1', POINT=1", "NOEUD",
     "SIEF_ELGA is an element field: give GROUP_MA"),
    ("point_of_depl", "NOM_CHAM='DEPL', NOM_CMP='DY', NOEUD='N1', POINT=1", "POINT",
     "POINT goes with the element fields; DEPL is read at a node"),
    ("impr_resu_med", "IMPR_RESU(FORMAT='MED', RESU=_F(RESULTAT=RESU, NOM_CHAM='SIGM_ELNO'))",
     "NOM_CHAM", "field SIGM_ELNO is not computed in the result"),
]
problems = []
for name, occurrence, key, phrase in CASES:
    line = occurrence if occurrence.startswith("IMPR_RESU") else \
        f"TEST_RESU(RESU=_F(RESULTAT=RESU, INST=1.0, {occurrence}, VALE_CALC=0.0))"
    command = line.split("(")[0]
    deck = os.path.join(work, f"spring_{name}.comm")
    with open(deck, "w") as f:
        f.write("\n".join(base[:fin] + [line] + base[fin:]))
    run = subprocess.run([parasol, "--unit", "20=" + os.path.join(decks, "ssnl130b.mail"),
                          "--outdir", work, deck], capture_output=True, text=True, timeout=60)
    column = line.index(key + "=") + 1 if key + "=" in line else line.index("RESU=_F") + 1
    where = f"spring_{name}.comm:{fin + 1}:{column}: error: {command}/RESU/{key}: "
    if run.returncode != 1 or where not in run.stderr or phrase not in run.stderr \
            or "Fortran runtime" in run.stderr:
        problems.append(f"{name}: exit {run.returncode}, stderr {run.stderr.strip()!r}; "
                        f"expected {where!r} and {phrase!r}")
for p in problems:
    print("FAIL:", p)
print(f"spring_field_errors: {len(CASES) - len(problems)} passed, {len(problems)} failed")
sys.exit(1 if problems else 0)

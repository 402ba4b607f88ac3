#!/usr/bin/env python3
"""Writes the hostile-input corpus (tests/decks/hostile, issue 13) from the SSNL130 decks and
meshes: each example of the issue and each crash the fuzzer found (tests/fuzz), as a deck
(and, for mesh errors, a mesh) whose first lines state the located message it must give
(tests/decks/run_deck_case.py). Run it again when decks/ssnl130a.comm or ssnl130b.comm
change: the locations in the expect lines are computed here.

usage: make_cases.py [OUTPUT_DIR]   (default: this file's folder)
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", "..", ".."))


def read(path):
    with open(os.path.join(TOP, path), encoding="utf-8") as f:
        return f.read()


def body(deck):
    """A deck without its own leading comment block (the case's header replaces it)."""
    lines = deck.split("\n")
    k = 0
    while lines[k].startswith("#") or not lines[k].strip():
        k += 1
    return "\n".join(lines[k:])


class Corpus:
    def __init__(self, out):
        self.out = out

    def write(self, name, text):
        with open(os.path.join(self.out, name), "w", encoding="utf-8") as f:
            f.write(text)

    def mesh_case(self, stem, ext, fmt, mesh, head):
        """A mesh file and a one-command deck reading it (its error is in the mesh)."""
        self.write(stem + "." + ext, mesh)
        self.write(stem + ".comm", head + "DEBUT()\nMAIL = LIRE_MAILLAGE(FORMAT='%s')\nFIN()\n"
                   % fmt)

    def deck_case(self, stem, base, head, edits, mesh="b", at=None):
        """A variant of an SSNL130 deck; `at` = (text of the line, text the column points
        at) replaces @L:@C in the header by the location of that column."""
        text = body(base)
        for old, new in edits:
            if old not in text:
                raise SystemExit("%s: %r is not in the deck" % (stem, old))
            text = text.replace(old, new, 1)
        text = head + "# mesh: ../../../decks/ssnl130%s.mail\n" % mesh + text
        if at:
            needle, column_of = at
            for n, line in enumerate(text.split("\n"), start=1):
                if needle in line and not line.startswith("#"):
                    text = text.replace("@L:@C", "%d:%d" % (n, line.index(column_of) + 1), 1)
                    break
            else:
                raise SystemExit("%s: %r not found" % (stem, needle))
        self.write(stem + ".comm", text)


def line_of(text, exact):
    return text.split("\n").index(exact) + 1


def mesh_cases(c):
    mail_b = read("decks/ssnl130b.mail")
    m = mail_b.replace("N9 1.0 0.0", "N9 1.0E+308 0.0")
    c.mesh_case("mesh_coordinate_1e308", "mail", "ASTER", m,
                "# issue 13: a mesh coordinate 1e308 trapped in the degenerate-cell check (Release: a\n"
                "# wrong \"zero area\"). Coordinates are finite and within 1e30 (number_limits).\n"
                "# expect: mesh_coordinate_1e308.mail:%d: error: LIRE_MAILLAGE: node N9:\n"
                "# phrase: coordinate \"1.0E+308\" is out of range (|x| <= 1.000000000000E+30)\n"
                % line_of(m, "N9 1.0E+308 0.0"))
    m = mail_b.replace("N12 1.375 0.0", "N12 1.375 1e309")
    c.mesh_case("mesh_coordinate_1e309", "mail", "ASTER", m,
                "# issue 13: 1e309 in a mesh trapped in the lexer's read (Release: exit 0 with\n"
                "# Infinity in the .mess); fuzz seed 1 case 2. Read without converting beyond double\n"
                "# precision.\n"
                "# expect: mesh_coordinate_1e309.mail:%d: error: LIRE_MAILLAGE: node N12:\n"
                "# phrase: coordinate \"1e309\" is out of range\n" % line_of(m, "N12 1.375 1e309"))
    m = mail_b.replace("N19 0.125 0.3", "N19 0.125 0.0")
    c.mesh_case("coincident_corners", "mail", "ASTER", m,
                "# issue 13: two coincident nodes in one cell ran to a NOOK with no warning: the\n"
                "# collapsed QUAD4 passes the zero-area test (it is a triangle).\n"
                "# expect: coincident_corners.mail:%d: error: LIRE_MAILLAGE: cell M1:\n"
                "# phrase: its corners N2 and N19 coincide (a QUAD4 needs four distinct corners)\n"
                % line_of(m, "M1 N1 N2 N19 N18"))
    mail_a = read("decks/ssnl130a.mail")
    c.write("warped_dkq.mail", mail_a.replace("N22 0.25 0.5 0.0", "N22 0.25 0.5 0.001"))

    msh = subprocess.run([sys.executable, os.path.join(TOP, "tools", "make_ssnl130_mesh.py"),
                          "--model", "b", "--format", "gmsh41"], check=True,
                         capture_output=True).stdout.decode()
    lines = msh.split("\n")
    ent = lines.index("$Entities") + 1        # 0-based index of the counts line
    x = list(lines)
    x[ent] = "1000000000 3 1 0"
    c.mesh_case("gmsh_entities_count_1e9", "msh", "GMSH", "\n".join(x),
                "# issue 13: a $Entities count of 1e9 allocated and zeroed 24 GB before reading a\n"
                "# byte of it. Counts are checked against the bytes left in the file.\n"
                "# expect: gmsh_entities_count_1e9.msh:%d: error: LIRE_MAILLAGE:\n"
                "# phrase: number of entities of dimension 0 = 1000000000 is more than the\n"
                % (ent + 1))
    pn = lines.index("$PhysicalNames") + 1
    x = list(lines)
    x[pn] = "1000000000"
    c.mesh_case("gmsh_physical_names_count_1e9", "msh", "GMSH", "\n".join(x),
                "# issue 13: a $PhysicalNames count of 1e9 allocated 128 GB (\"Error allocating\");\n"
                "# fuzz seed 1 case 411.\n"
                "# expect: gmsh_physical_names_count_1e9.msh:%d: error: LIRE_MAILLAGE:\n"
                "# phrase: number of physical names = 1000000000 is more than the\n" % (pn + 1))
    x = list(lines)
    x[ent] = "19 -3 1 0"
    c.mesh_case("gmsh_entities_negative_count", "msh", "GMSH", "\n".join(x),
                "# issue 13: a negative entity count corrupted the heap (SIGABRT in Release).\n"
                "# expect: gmsh_entities_negative_count.msh:%d: error: LIRE_MAILLAGE:\n"
                "# phrase: number of entities of dimension 1 = -3 is negative\n" % (ent + 1))
    end = lines.index("$EndEntities")
    x = lines[:end + 1] + lines[ent - 1:end + 1] + lines[end + 1:]
    c.mesh_case("gmsh_second_entities_section", "msh", "GMSH", "\n".join(x),
                "# issue 13: a second $Entities section stopped on the runtime error \"already\n"
                "# allocated\"; fuzz seed 1 case 505. A Gmsh file has one section of each kind.\n"
                "# expect: gmsh_second_entities_section.msh:%d: error: LIRE_MAILLAGE:\n"
                "# phrase: a second $Entities section (the first is at line %d)\n"
                % (end + 2, ent))
    nodes = lines.index("$Nodes") + 1
    head = lines[nodes].split()
    x = list(lines)
    x[nodes] = " ".join([head[0], str(int(head[1]) + 1)] + head[2:])
    c.mesh_case("gmsh41_nodes_total_lies", "msh", "GMSH", "\n".join(x),
                "# issue 13: Gmsh 4.1 $Nodes header totals that disagree with the data were\n"
                "# accepted (exit 0); the 2.2 counts were checked. The header is checked against the\n"
                "# blocks.\n"
                "# expect: gmsh41_nodes_total_lies.msh:%d: error: LIRE_MAILLAGE:\n"
                "# phrase: the $Nodes header says %d nodes, its blocks hold %s\n"
                % (nodes + 1, int(head[1]) + 1, head[1]))
    els = lines.index("$Elements") + 1
    head = lines[els].split()
    x = list(lines)
    x[els] = " ".join(head[:3] + [str(int(head[3]) + 5)])
    c.mesh_case("gmsh41_elements_max_tag_lies", "msh", "GMSH", "\n".join(x),
                "# issue 13: Gmsh 4.1 $Elements header (largest tag) disagreeing with the data.\n"
                "# expect: gmsh41_elements_max_tag_lies.msh:%d: error: LIRE_MAILLAGE:\n"
                "# phrase: the $Elements header says tags 1 to %d, its blocks hold tags 1 to %s\n"
                % (els + 1, int(head[3]) + 5, head[3]))

    msh = subprocess.run([sys.executable, os.path.join(TOP, "tools", "make_ssnl130_mesh.py"),
                          "--model", "a", "--format", "gmsh22"], check=True,
                         capture_output=True).stdout.decode()
    lines = msh.split("\n")
    nodes = lines.index("$Nodes") + 1
    x = list(lines)
    tag, xc, yc, zc = x[nodes + 2].split()
    x[nodes + 2] = " ".join([tag, "1e308", yc, zc])
    c.mesh_case("gmsh22_coordinate_1e308", "msh", "GMSH", "\n".join(x),
                "# fuzz seed 1 case 882: a Gmsh 2.2 node coordinate 1e308 trapped in the\n"
                "# degenerate-cell check. Coordinates are finite and within 1e30, in every format.\n"
                "# expect: gmsh22_coordinate_1e308.msh:%d: error: LIRE_MAILLAGE: node coordinate:\n"
                "# phrase: \"1e308\" is out of range (|x| <= 1.000000000000E+30)\n" % (nodes + 3))
    x = list(lines)
    x[nodes] = "2147483647"
    c.mesh_case("gmsh22_nodes_count_2147483647", "msh", "GMSH", "\n".join(x),
                "# fuzz seed 1 case 1135: a Gmsh 2.2 $Nodes count of 2**31 - 1 allocated 48 GB\n"
                "# (\"Error allocating\"). Counts are checked against the bytes left in the file.\n"
                "# expect: gmsh22_nodes_count_2147483647.msh:%d: error: LIRE_MAILLAGE:\n"
                "# phrase: number of nodes = 2147483647 is more than the\n" % (nodes + 1))


def deck_cases(c):
    deck_a = read("decks/ssnl130a.comm")
    deck_b = read("decks/ssnl130b.comm")
    c.deck_case("material_e_1e308", deck_b,
                "# issue 13: E = 1e308 trapped in the plane-strain elasticity matrix (Release: NaN).\n"
                "# E within Code_Aster's val_min 0 and parasol's 1e100 (moduli: E EPAIS**3 must fit).\n"
                "# expect: @L:@C: error: DEFI_MATERIAU/ELAS/E:\n"
                "# phrase: value 1.000000000000E+308 is out of range (0 <= E <= 1E+100)\n",
                [("E=2.0E+11", "E=1.0E+308")], at=("E=1.0E+308", "1.0E+308"))
    c.deck_case("material_e_denormal", deck_b,
                "# fuzz seed 4 case 1694: E = 1e-320 (a denormal) overflowed in MUMPS's unscaling\n"
                "# (its inverse is beyond the largest real). A modulus other than 0 is at least\n"
                "# 1e-100; the handler then refuses E = 0.\n"
                "# expect: @L:@C: error: DEFI_MATERIAU/ELAS/E:\n"
                "# phrase: value 9.999888671827E-321 is too small: E is 0 or at least 1E-100 in magnitude\n",
                [("E=2.0E+11", "E=1e-320")], at=("E=1e-320", "1e-320"))
    c.deck_case("coque_epais_1e150", deck_a,
                "# issue 13: EPAIS = 1e150 overflowed in EPAIS**3 of the plate's bending stiffness.\n"
                "# expect: @L:@C: error: AFFE_CARA_ELEM/COQUE/EPAIS:\n"
                "# phrase: value 1.000000000000E+150 is out of range (EPAIS <= 1E+30)\n",
                [("EPAIS=0.30", "EPAIS=1.0E+150")], mesh="a",
                at=("EPAIS=1.0E+150", "1.0E+150"))
    c.deck_case("dis_contact_dist_1_1e308", deck_b,
                "# issue 13: DIST_1 = 1e308 overflowed in the DIS_CHOC law (stiffness times gap).\n"
                "# expect: @L:@C: error: DEFI_MATERIAU/DIS_CONTACT/DIST_1:\n"
                "# phrase: value 1.000000000000E+308 is out of range (-1E+30 <= DIST_1 <= 1E+30)\n",
                [("DIST_1=0.1", "DIST_1=1.0E+308")], at=("DIST_1=1.0E+308", "1.0E+308"))
    c.deck_case("ddl_impo_dz_minus_1e308", deck_a,
                "# issue 13: DDL_IMPO DZ = -1e308 trapped in the DIS_CHOC law (Release: NaN,\n"
                "# NON_FINI). A real DDL_IMPO is within 1e30 (validated); a function's value is\n"
                "# checked where it is evaluated (ddl_impo_function_1e308).\n"
                "# expect: @L:@C: error: AFFE_CHAR_MECA/DDL_IMPO/DZ:\n"
                "# phrase: value -1.000000000000E+308 is out of range (-1E+30 <= DZ <= 1E+30)\n",
                [("SOL = AFFE_CHAR_MECA_F(MODELE=MODELE,\n                       "
                  "DDL_IMPO=_F(GROUP_MA='PTRESS', DX=ZERO, DY=ZERO, DZ=DEPZ),)",
                  "SOL = AFFE_CHAR_MECA(MODELE=MODELE,\n                     "
                  "DDL_IMPO=_F(GROUP_MA='PTRESS', DX=0.0, DY=0.0, DZ=-1.0E+308),)")],
                mesh="a", at=("DZ=-1.0E+308", "-1.0E+308"))
    c.deck_case("ddl_impo_function_1e308", deck_b,
                "# issue 13: a DDL_IMPO function worth -1e308 (DEFI_CONSTANTE): checked where the\n"
                "# load is evaluated, located at the DDL_IMPO of the AFFE_CHAR_MECA_F.\n"
                "# expect: @L:@C: error: AFFE_CHAR_MECA_F/DDL_IMPO/DX:\n"
                "# phrase: DX = -1.000000000000E+308 at INST 1.000000000000E+00 is out of range\n",
                [("ZERO = DEFI_CONSTANTE(VALE=0.0)", "ZERO = DEFI_CONSTANTE(VALE=-1.0E+308)")],
                at=("DDL_IMPO=_F(GROUP_NO='PTRESS'", "_F(GROUP_NO='PTRESS'"))
    c.deck_case("defi_fonction_ordinate_1e308", deck_b,
                "# fuzz seed 104 case 1072: a DEFI_FONCTION ordinate of -1e308 overflowed in the\n"
                "# linear interpolation itself ((t - x) (y2 - y1) at INST 2 between -1e308 and 4;\n"
                "# here y2 - y1 between -1e308 and 1e308 at INST 1).\n"
                "# Interpolation terms are formed only when they stay below 2**1000.\n"
                "# expect: @L:@C: error: AFFE_CHAR_MECA_F/DDL_IMPO/DX:\n"
                "# phrase: is beyond 2**1000 (about 1.07E+301) in the linear interpolation\n",
                [("ZERO = DEFI_CONSTANTE(VALE=0.0)",
                  "ZERO = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, -1.0E+308, 2.0, 1.0E+308))")],
                at=("DDL_IMPO=_F(GROUP_NO='PTRESS'", "_F(GROUP_NO='PTRESS'"))
    c.deck_case("test_resu_tole_machine_1e308", deck_b,
                "# issue 13: TOLE_MACHINE = 1e308 overflowed in the TEST_RESU guard (tol * |ref|).\n"
                "# The check divides instead: the deck runs, every TEST_RESU OK.\n"
                "# expect-exit: 0\n"
                "# seconds: 20\n",
                [("TOLE_MACHINE=1.0E-8", "TOLE_MACHINE=1.0E+308")])
    c.deck_case("resi_glob_rela_1e308", deck_a,
                "# fuzz seed 101 case 4685: RESI_GLOB_RELA = 1e308 overflowed in the contact Newton's\n"
                "# zero-gap test (the tolerance times its denominator). Any state converges: the run\n"
                "# ends at its first iterate and the deck's TEST_RESU lines fail (exit 2).\n"
                "# expect-exit: 2\n"
                "# seconds: 20\n",
                [("RESI_GLOB_RELA=1.0E-10", "RESI_GLOB_RELA=1e308")], mesh="a")
    c.deck_case("formula_pow_1e308", deck_b,
                "# issue 13: 10.0**1e308 in a formula overflowed in the ** guard itself.\n"
                "# expect: @L:@C: error: STAT_NON_LINE: FORCE_CONTOUR: FORMULE FORCE: numerical\n"
                "# phrase: overflow in ** (the result exceeds the largest real, about 1.8E+308)\n"
                "# seconds: 20\n",
                [("fy = -5.0*(x - 2.0)**2", "fy = -5.0*(x - 2.0)**2 + 10.0**1e308")],
                at=("10.0**1e308", "**1e308"))
    c.deck_case("formula_t_pow_1e999", deck_b,
                "# issue 13: t**1e999 in a formula: the literal was read to look for x**2\n"
                "# (overflow).\n"
                "# expect: @L:@C: error: FORMULE/VALE:\n"
                "# phrase: number out of range\n",
                [("return (t - 1.0)*5.0E-03", "return (t - 1.0)*5.0E-03 + t**1e999")],
                at=("t**1e999", "1e999"))
    convergence = "CONVERGENCE=_F(RESI_GLOB_RELA=1.0E-10)"
    c.deck_case("iter_glob_maxi_negative", deck_b,
                "# issue 13: ITER_GLOB_MAXI < 0 read out of bounds (garbage in the message).\n"
                "# expect: @L:@C: error: STAT_NON_LINE/CONVERGENCE/ITER_GLOB_MAXI:\n"
                "# phrase: value -3 is out of range (ITER_GLOB_MAXI >= 0)\n",
                [(convergence, convergence[:-1] + ", ITER_GLOB_MAXI=-3)")],
                at=("ITER_GLOB_MAXI=-3", "-3"))
    c.deck_case("iter_glob_maxi_1e9", deck_b,
                "# issue 13: ITER_GLOB_MAXI = 1e9 allocated 40 GB (\"Error allocating\"). What an\n"
                "# analysis records is measured before it is allocated.\n"
                "# expect: @L:@C: error: STAT_NON_LINE/CONVERGENCE/ITER_GLOB_MAXI:\n"
                "# phrase: ITER_GLOB_MAXI = 1000000000: more iterations than can be recorded\n",
                [(convergence, convergence[:-1] + ", ITER_GLOB_MAXI=1000000000)")],
                at=("ITER_GLOB_MAXI=1000000000", "ITER_GLOB_MAXI"))
    c.deck_case("ddl_impo_conflict", deck_b,
                "# issue 13: the same DOF imposed twice with different values silently took the\n"
                "# last; Code_Aster refuses it. Located at the occurrence found second, naming the\n"
                "# first.\n"
                "# expect: @L:@C: error: AFFE_CHAR_MECA/DDL_IMPO/DY: node N35 DY is imposed twice\n"
                "# phrase: with different values at INST 1.000000000000E+00: 1.000000000000E-03 here, 0.000000000000E+00 by the DDL_IMPO at ddl_impo_conflict.comm:\n",
                [("L_INST = DEFI_LIST_REEL",
                  "BLOQ = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(GROUP_NO='PTRESS', "
                  "DY=1.0E-3),)\n\nL_INST = DEFI_LIST_REEL"),
                 ("EXCIT=(_F(CHARGE=CHARGE), _F(CHARGE=SOL),)",
                  "EXCIT=(_F(CHARGE=CHARGE), _F(CHARGE=SOL), _F(CHARGE=BLOQ),)")],
                at=("BLOQ = AFFE_CHAR_MECA", "_F(GROUP_NO='PTRESS', DY=1.0E-3)"))
    c.deck_case("nprec_minus_1_ldlt_singular", deck_b,
                "# issue 13: NPREC = -1 was reported as \"NPREC = 1\". LDLT reads |NPREC|; the\n"
                "# message gives NPREC as written. Springs of zero stiffness: nothing holds the slab.\n"
                "# expect: @L:@C: error: STAT_NON_LINE:\n"
                "# phrase: NPREC = -1, read as 1 by LDLT)\n"
                "# seconds: 20\n",
                [("VALE=(1.0E+04, 1.0E+04)", "VALE=(0.0, 0.0)"),
                 ("SOLVEUR=_F(METHODE='MUMPS', NPREC=9)", "SOLVEUR=_F(METHODE='LDLT', NPREC=-1)")],
                at=("RESU = STAT_NON_LINE", "STAT_NON_LINE"))
    # the warped DKQ: the deck of model A on warped_dkq.mail (its stem), no # mesh: line
    text = ("# issue 13: a warped DKQ gave \"no convergence\" with no word about the warp. Node N22\n"
            "# of SSNL130 A lifted by 1 mm: the model check warns (Code_Aster's measure and 1e-4\n"
            "# threshold, dxqpgl ELEMENTS4_80) with the count and the worst warp, at the cell.\n"
            "# The warped slab then converges (2 iterations in step 1): its cells' rigid motion\n"
            "# is now taken in their mean plane, as the element is built; the 3D rotation of the\n"
            "# lifted corner was a membrane stretch to K, internal forces != K u, and the\n"
            "# Newton diverged. TEST_RESU checks the flat\n"
            "# slab's values: NOOK, exit 2.\n"
            "# expect-exit: 2\n"
            "# warning: warped_dkq.mail:192: warning: AFFE_MODELE: 4 DKQ cell(s) warped beyond 1.00E-04\n"
            "# seconds: 30\n" + body(deck_a))
    c.write("warped_dkq.comm", text)


QUAD8_MAIL = """COOR_2D
N1 0.0 0.0
N2 1.0 0.0
N3 1.0 1.0
N4 0.0 1.0
N5 0.5 %s
N6 1.0 0.5
N7 0.5 1.0
N8 0.0 0.5
FINSF
QUAD8
M1 N1 N2 N3 N4
   N5 N6 N7 N8
FINSF
GROUP_MA NOM=ALL
M1
FINSF
GROUP_NO NOM=LEFT
N1 N4 N8
FINSF
FIN
"""

PLANE_DECK = """DEBUT()
MAIL = LIRE_MAILLAGE(FORMAT='ASTER')
MODEL = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(GROUP_MA='ALL', PHENOMENE='MECANIQUE',
                                           MODELISATION='%s'))
STEEL = DEFI_MATERIAU(ELAS=_F(E=2.0E+11, NU=0.3))
MATER = AFFE_MATERIAU(MAILLAGE=MAIL, AFFE=_F(TOUT='OUI', MATER=STEEL))
BC = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO='LEFT', DX=0.0, DY=0.0),
                    FORCE_NODALE=_F(NOEUD='N3', FX=1.0))
RESU = MECA_STATIQUE(MODELE=MODEL, CHAM_MATER=MATER, EXCIT=_F(CHARGE=BC))
FIN()
"""


def plane_cases(c):
    """Quadratic plane cells (issue 21 section 5): collapsed, folded, on the wrong element."""
    c.mesh_case("tria6_coincident_nodes", "mail", "ASTER",
                "COOR_2D\nN1 0 0\nN2 1 0\nN3 0 1\nN4 0.5 0\nN5 0.5 0.5\nN6 0.5 0.5\n"
                "FINSF\nTRIA6\nM1 N1 N2 N3 N4 N5 N6\nFINSF\nFIN\n",
                "# issue 21: a TRIA6 with two nodes at one place (its side 2-3 middle and side 3-1\n"
                "# middle) is a collapsed cell, refused where it is read.\n"
                "# expect: tria6_coincident_nodes.mail:10: error: LIRE_MAILLAGE: cell M1:\n"
                "# phrase: its nodes N5 and N6 coincide (a TRIA6 needs 6 distinct nodes)\n")
    head = ("# issue 21: a QUAD8 whose lower middle node sits above its upper side folds over\n"
            "# itself (det J changes sign inside): a located error naming the cell, as a folded\n"
            "# QUAD4.\n"
            "# expect: %d:8: error: MECA_STATIQUE: cell M1 (GROUP_MA ALL):\n"
            "# phrase: QUAD8 cell is degenerate: its Jacobian is zero or changes sign\n")
    deck = PLANE_DECK % "D_PLAN"
    line = head.count("\n") + line_of(deck, "RESU = MECA_STATIQUE(MODELE=MODEL, "
                                       "CHAM_MATER=MATER, EXCIT=_F(CHARGE=BC))")
    c.write("quad8_folded.mail", QUAD8_MAIL % "1.6")
    c.write("quad8_folded.comm", head % line + deck)
    head = ("# issue 21: a cell type an element cannot take: DKT has no element on a QUAD8.\n"
            "# expect: %d:%d: error: AFFE_MODELE/AFFE/MODELISATION:\n"
            "# phrase: MODELISATION DKT has no element on cell M1 (GROUP_MA ALL) of type QUAD8 "
            "(it applies to TRIA3, QUAD4)\n")
    deck = PLANE_DECK % "DKT"
    line = head.count("\n") + line_of(deck, "                                           "
                                       "MODELISATION='DKT'))")
    c.write("dkt_on_quad8.mail", QUAD8_MAIL % "0.0")
    c.write("dkt_on_quad8.comm",
            head % (line, len("                                           ") + 1)
            + deck)


def main(argv):
    out = argv[1] if len(argv) > 1 else HERE
    c = Corpus(out)
    mesh_cases(c)
    deck_cases(c)
    plane_cases(c)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

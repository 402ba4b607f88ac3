#!/usr/bin/env python3
"""Seeded mutation fuzzer of parasol's inputs (issue 13, doc/stability.md "Hostile input").

usage: fuzz.py PARASOL [--compare PARASOL2] [--seed S] [--cases N] [--first K] [--jobs J]
               [--timeout T] [--work DIR] [--seeds NAMES] [--keep N] [--report FILE]
               [--show K] [--quiet] [--aster-med DIR]

Makes N cases from the seed inputs below, each from (S, case number) alone: one seed input
(the SSNL130 decks on their .mail, Gmsh 2.2, Gmsh 4.1 and MED meshes, a Code_Aster export
file with its command files and imported module, verification decks with MECA_STATIQUE and
IMPR_RESU files, a deck checked with --check), one of its files, and one to four mutations
(bytes flipped, truncated, deleted or duplicated; lines deleted, duplicated, swapped; numbers
replaced by 0, +-1e308, 1e309, NaN, 2**63, huge and negative counts; keywords and names
swapped; expressions that overflow; Gmsh header counts that lie; sections duplicated; nodes
made coincident or lifted out of their plane; MED files edited at the byte level and, through
h5py, at the content level: values, NBR counts, datasets removed or resized; the mesh
commands DEFI_GROUP, MODI_MAILLAGE, CREA_MAILLAGE on a test plate). Each case runs
in its own folder with a time limit and a 4 GB address-space limit and is classified:

  clean      exit 0 or 2 (TEST_RESU NOOK) with nothing on stderr but located warnings, or
             exit 1 with a located message `FILE:LINE[:COL]: error: ...`
  crash      a signal, another exit status, or a runtime error on stderr (Fortran runtime
             error, backtrace, "Error allocating", double free, ...)
  hang       still running at the time limit
  unlocated  exit 1 without a located error line, or exit 0/2 with an error line
  unnamed    (a Code_Aster MED mesh read alone, --aster-med) exit 1 without exactly one
             line on stderr naming the mesh file
  nan        NaN or Inf in an output (the .mess and .resu, result files, stdout; deck echo
             and quoted input left out)
  temporary  a temporary file (*.partial) left behind
  mismatch   (--compare) the second program (e.g. the Release build) exits differently

--aster-med DIR adds Code_Aster's own MED meshes (every *.mmed below DIR) as seeds read by a
deck that does nothing else (issue 23); --seeds med keeps the seeds with a MED mesh only
(the damaged-MED campaign of doc/stability.md, "Faults"; skipped with exit 77 when DIR is
missing).

--first K starts at case K (to rerun one case: --first K --cases 1 --keep 1 --show 1; the
case folder stays under WORK/cases/K with the command in `command.txt`). Exit status 0 when
every case is clean, 1 otherwise; the report (--report) is JSON with the counts and every
case that is not clean.
"""
import argparse
import concurrent.futures
import json
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutate  # noqa: E402

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CRASH_SIGNS = ("Fortran runtime", "Backtrace", "ERROR STOP", "Segmentation", "double free",
               "Program received signal", "Error allocating", "Floating point exception",
               "free(): ", "malloc(): ", "corrupted", "Aborted", "core dumped",
               "HDF5-DIAG", "Erreur", "At line ")
LOCATED = re.compile(r"^\S+?:\d+(?::\d+)?: error: ", re.M)
ERROR_LINE = re.compile(r"(^|\s)error: ", re.M)
NOT_FINITE = re.compile(r"(?i)(?<![A-Za-z_])(nan|[-+]?inf(inity)?)(?![A-Za-z_0-9])")
# the words parasol's listings print for a value that is not finite (test_resu_command): a
# computed value never should be one; +-INFINI is legitimate only as an ERREUR or TOLE
# percentage (a relative error against a zero reference), followed by %
LISTING_NOT_FINITE = re.compile(r"NON_FINI|[-+]INFINI(?!%)")
ECHO = re.compile(r"^\s*\d+ \| ", re.M)
QUOTES = re.compile(r"\"[^\"\n]*\"|'[^'\n]*'")
# The values a keyword allows, listed or suggested by a validation error (CRITERE: SUP,
# INF).
ALLOWED = re.compile(r"\((allowed: |did you mean )[^)\n]*\)")
ADDRESS_SPACE = 4 << 30
MUTATE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mutate.py")
EXPORT_TIME_LIMIT = 20      # seconds, the P time_limit of the cases run through an export


# ---- seed inputs ------------------------------------------------------------------------------
class Seed:
    """One input set: files copied into the case folder (role -> file name), the command
    arguments, the files that may be mutated (role -> mutation family) and a weight."""

    def __init__(self, name, files, args, targets, weight=1.0, names=None):
        self.name, self.files, self.args = name, files, args
        self.targets, self.weight = targets, weight
        # a file every error of the case must name (a deck that only reads it)
        self.names = names


def run_tool(argv, **kw):
    return subprocess.run(argv, check=True, capture_output=True, **kw)


def make_seeds(parasol, work, wanted, aster_med=None):
    """Writes the seed inputs into WORK/seeds and returns the Seed list. aster_med: a folder
    whose Code_Aster MED meshes (*.mmed, searched below it) become seeds read by a deck that
    does nothing else (issue 23: a damaged MED file is one error line naming it)."""
    seeds_dir = os.path.join(work, "seeds")
    os.makedirs(seeds_dir, exist_ok=True)
    py = sys.executable
    tool = os.path.join(SOURCE, "tools", "make_ssnl130_mesh.py")
    decks = os.path.join(SOURCE, "decks")
    meshes = {}
    for model in ("a", "b"):
        for fmt, ext in (("aster", "mail"), ("gmsh22", "msh"), ("gmsh41", "msh")):
            path = os.path.join(seeds_dir, "%s_%s.%s" % (model, fmt, ext))
            run_tool([py, tool, "--model", model, "--format", fmt, "-o", path])
            meshes[(model, fmt)] = path

    def deck_copy(src, dst, fmt=None):
        text = open(src, encoding="utf-8").read()
        if fmt:
            text = text.replace("FORMAT='ASTER'", "FORMAT='%s'" % fmt)
        with open(os.path.join(seeds_dir, dst), "w", encoding="utf-8") as f:
            f.write(text)
        return os.path.join(seeds_dir, dst)

    seeds = []
    deck_a = os.path.join(decks, "ssnl130a.comm")
    deck_b = os.path.join(decks, "ssnl130b.comm")
    deck_an = os.path.join(decks, "ssnl130a_newton.comm")
    comm_targets = {"case.comm": "deck"}
    seeds.append(Seed("a_mail", {"case.comm": deck_a, "case.mail": meshes[("a", "aster")]},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 1.0))
    seeds.append(Seed("a_newton_mail", {"case.comm": deck_an,
                                        "case.mail": meshes[("a", "aster")]},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 0.5))
    seeds.append(Seed("b_mail", {"case.comm": deck_b, "case.mail": meshes[("b", "aster")]},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 2.0))
    # The iterative methods (krylov_solver): model B with PETSC and its keywords, model A
    # (springs only: the rigid-mode path around the iteration) with GCPC; each with
    # RECH_LINEAIRE (residual_line_search: CORDE, MIXTE and every keyword).
    for name, model, deck, solveur in (
            ("b_iterative", "b", deck_b, "SOLVEUR=_F(METHODE='PETSC', ALGORITHME='FGMRES', "
                          "PRE_COND='LDLT_SP', RESI_RELA=1e-10, NMAX_ITER=50), "
                          "RECH_LINEAIRE=_F(METHODE='CORDE', ITER_LINE_MAXI=3)"),
            ("a_iterative", "a", deck_a, "SOLVEUR=_F(METHODE='GCPC', PRE_COND='LDLT_INC', "
                          "RESI_RELA=1e-9, NMAX_ITER=500, RENUM='RCMK'), "
                          "RECH_LINEAIRE=_F(METHODE='MIXTE', RESI_LINE_RELA=0.05, "
                          "ITER_LINE_MAXI=4, RHO_MIN=0.02, RHO_MAX=5.0, RHO_EXCL=0.01)"),
            # the smoothed-aggregation multigrid (amg_preconditioner) on model A's plate
            ("a_multigrid", "a", deck_a, "SOLVEUR=_F(METHODE='PETSC', PRE_COND='ML', "
                                         "RESI_RELA=1e-9, NMAX_ITER=400)")):
        text = open(deck, encoding="utf-8").read()
        text = re.sub(r"SOLVEUR=_F\([^)]*\)", solveur, text)
        path = os.path.join(seeds_dir, "%s.comm" % name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        seeds.append(Seed(name, {"case.comm": path, "case.mail": meshes[(model, "aster")]},
                          [], dict(comm_targets, **{"case.mail": "mail"}),
                          0.3 if name == "a_multigrid" else 0.5))
    for model, deck in (("a", deck_a), ("b", deck_b)):
        gdeck = deck_copy(deck, "%s_gmsh.comm" % model, "GMSH")
        for fmt in ("gmsh22", "gmsh41"):
            seeds.append(Seed("%s_%s" % (model, fmt),
                              {"case.comm": gdeck, "case.msh": meshes[(model, fmt)]}, [],
                              dict(comm_targets, **{"case.msh": fmt}),
                              1.0 if model == "a" else 1.5))
    # MED: the mesh written by parasol itself (IMPR_RESU FORMAT='MED' of model A and B runs)
    for model, deck in (("a", deck_a), ("b", deck_b)):
        med = os.path.join(seeds_dir, "%s.med" % model)
        if not os.path.exists(med):
            src = open(deck, encoding="utf-8").read()
            src = src.replace("FIN()", "IMPR_RESU(FORMAT='MED', UNITE=80, "
                              "RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL', INST=1.0))\nFIN()")
            wdir = os.path.join(seeds_dir, "med_%s" % model)
            os.makedirs(wdir, exist_ok=True)
            with open(os.path.join(wdir, "w.comm"), "w", encoding="utf-8") as f:
                f.write(src)
            proc = subprocess.run([parasol, "--outdir", wdir, "--unit",
                                   "20=" + meshes[(model, "aster")], "--unit", "80=" + med,
                                   os.path.join(wdir, "w.comm")], capture_output=True)
            if proc.returncode != 0 or not os.path.exists(med):
                print("fuzz: no MED seed (%s): %s" % (model, proc.stderr.decode()[-300:]))
                continue
        mdeck = deck_copy(deck, "%s_med.comm" % model, "MED")
        seeds.append(Seed("%s_med" % model, {"case.comm": mdeck, "case.med": med}, [],
                          dict(comm_targets, **{"case.med": "med"}),
                          1.0 if model == "a" else 1.5))
    # A Code_Aster export file: two command files, an imported module, the mesh on unit 20.
    cases = os.path.join(SOURCE, "tests", "export", "cases")
    export = open(os.path.join(cases, "session.export"), encoding="utf-8").read()
    export = export.replace("../../../decks/ssnl130b.mail", "case.mail")
    with open(os.path.join(seeds_dir, "session.export"), "w", encoding="utf-8") as f:
        f.write(export)
    seeds.append(Seed("export", {"case.export": os.path.join(seeds_dir, "session.export"),
                                 "session.comm": os.path.join(cases, "session.comm"),
                                 "session.com1": os.path.join(cases, "session.com1"),
                                 "slab_loads.py": os.path.join(cases, "slab_loads.py"),
                                 "case.mail": meshes[("b", "aster")]}, [],
                      {"case.export": "export", "session.comm": "deck",
                       "session.com1": "deck", "slab_loads.py": "module"}, 1.5))
    # Verification decks: every load keyword, MECA_STATIQUE, IMPR_RESU VTK and GMSH files;
    # DKQ and plane patch tests; the deck with every command, checked only.
    verif = os.path.join(SOURCE, "tests", "verification")
    seeds.append(Seed("loads", {"case.comm": os.path.join(verif, "loads_bilateral.comm"),
                                "case.mail": meshes[("a", "aster")]}, [],
                      dict(comm_targets, **{"case.mail": "mail"}), 1.0))
    for name in ("patch_dkq", "patch_plan"):
        seeds.append(Seed(name, {"case.comm": os.path.join(verif, name + ".comm"),
                                 "case.mail": os.path.join(verif, name + ".mail")}, [],
                          dict(comm_targets, **{"case.mail": "mail"}), 0.7))
    # The plane family on its five cell types (an export file binding five meshes, curved
    # quadratic cells), their thermal strains (AFFE_VARC) and the discrete elements with
    # rotations and full matrices (issue 21).
    plane = os.path.join(SOURCE, "tests", "plane")
    files = {"case.export": os.path.join(plane, "patch_plane.export"),
             "patch_plane.comm": os.path.join(plane, "patch_plane.comm")}
    for cell in ("tria3", "tria6", "quad4", "quad8", "quad9"):
        files["patch_%s.mail" % cell] = os.path.join(plane, "patch_%s.mail" % cell)
    seeds.append(Seed("plane_patch", files, [],
                      {"case.export": "export", "patch_plane.comm": "deck",
                       "patch_tria6.mail": "mail", "patch_quad8.mail": "mail",
                       "patch_quad9.mail": "mail"}, 1.0))
    files = {"case.export": os.path.join(plane, "thermal_plane.export"),
             "thermal_plane.comm": os.path.join(plane, "thermal_plane.comm")}
    for cell in ("tria3", "tria6", "quad4", "quad8", "quad9"):
        files["thermal_%s.mail" % cell] = os.path.join(plane, "thermal_%s.mail" % cell)
    seeds.append(Seed("plane_thermal", files, [],
                      {"case.export": "export", "thermal_plane.comm": "deck",
                       "thermal_tria6.mail": "mail", "thermal_quad8.mail": "mail"}, 0.6))
    # The shrinkage strains of AFFE_VARC HYDR and SECH (B_ENDOGE, K_DESSIC, EVOL_SECH,
    # HYDR_NOEU) and CALC_CHAMP's EPME_ELGA / EPSP_ELGA on the plane strips.
    files = {"case.export": os.path.join(plane, "shrinkage_plane.export"),
             "shrinkage_plane.comm": os.path.join(plane, "shrinkage_plane.comm")}
    for cell in ("tria3", "tria6", "quad4", "quad8", "quad9"):
        files["thermal_%s.mail" % cell] = os.path.join(plane, "thermal_%s.mail" % cell)
    seeds.append(Seed("plane_shrinkage", files, [],
                      {"case.export": "export", "shrinkage_plane.comm": "deck",
                       "thermal_quad8.mail": "mail"}, 0.5))
    # ELAS_ORTH plane elements in AFFE_CARA_ELEM MASSIF frames (ANGL_REP, ORIG_AXE).
    files = {"case.export": os.path.join(plane, "orthotropic_plane.export"),
             "orthotropic_plane.comm": os.path.join(plane, "orthotropic_plane.comm")}
    for cell in ("tria3", "tria6", "quad4", "quad8", "quad9"):
        files["thermal_%s.mail" % cell] = os.path.join(plane, "thermal_%s.mail" % cell)
    seeds.append(Seed("plane_orthotropic", files, [],
                      {"case.export": "export", "orthotropic_plane.comm": "deck",
                       "thermal_quad4.mail": "mail"}, 0.6))
    # PRES_REP on the plane edges.
    files = {"case.export": os.path.join(plane, "pres_rep_plane.export"),
             "pres_rep_plane.comm": os.path.join(plane, "pres_rep_plane.comm")}
    for cell in ("tria3", "tria6", "quad4", "quad8", "quad9"):
        files["thermal_%s.mail" % cell] = os.path.join(plane, "thermal_%s.mail" % cell)
    seeds.append(Seed("pres_rep_plane", files, [],
                      {"case.export": "export", "pres_rep_plane.comm": "deck",
                       "thermal_tria6.mail": "mail"}, 0.4))
    # PRE_EPSI initial strains: the plane strips (free and held) and the plates.
    pre = os.path.join(SOURCE, "tests", "pre_epsi")
    files = {"case.export": os.path.join(plane, "pre_epsi_plane.export"),
             "pre_epsi_plane.comm": os.path.join(plane, "pre_epsi_plane.comm")}
    for cell in ("tria3", "tria6", "quad4", "quad8", "quad9"):
        files["thermal_%s.mail" % cell] = os.path.join(plane, "thermal_%s.mail" % cell)
    seeds.append(Seed("pre_epsi_plane", files, [],
                      {"case.export": "export", "pre_epsi_plane.comm": "deck",
                       "thermal_quad8.mail": "mail"}, 0.6))
    seeds.append(Seed("pre_epsi_plate",
                      {"case.export": os.path.join(pre, "pre_epsi_plate.export"),
                       "pre_epsi_plate.comm": os.path.join(pre, "pre_epsi_plate.comm"),
                       "pre_epsi_plate.mail": os.path.join(pre, "pre_epsi_plate.mail")}, [],
                      {"case.export": "export", "pre_epsi_plate.comm": "deck",
                       "pre_epsi_plate.mail": "mail"}, 0.6))
    discrete = os.path.join(SOURCE, "tests", "discrete")
    seeds.append(Seed("discrete", {"case.export": os.path.join(discrete, "discrete.export"),
                                   "discrete.comm": os.path.join(discrete, "discrete.comm"),
                                   "discrete_3d.mail": os.path.join(discrete,
                                                                    "discrete_3d.mail"),
                                   "discrete_2d.mail": os.path.join(discrete,
                                                                    "discrete_2d.mail")},
                      [], {"case.export": "export", "discrete.comm": "deck",
                           "discrete_3d.mail": "mail", "discrete_2d.mail": "mail"}, 0.8))
    # SYME='NON': the unsymmetric discretes' correction of the symmetric factor
    seeds.append(Seed("discrete_unsymmetric",
                      {"case.export": os.path.join(discrete, "unsymmetric.export"),
                       "unsymmetric.comm": os.path.join(discrete, "unsymmetric.comm"),
                       "unsymmetric_3d.mail": os.path.join(discrete, "unsymmetric_3d.mail"),
                       "unsymmetric_2d.mail": os.path.join(discrete, "unsymmetric_2d.mail")},
                      [], {"case.export": "export", "unsymmetric.comm": "deck",
                           "unsymmetric_3d.mail": "mail", "unsymmetric_2d.mail": "mail"}, 0.8))
    # Fields: CREA_CHAMP (AFFE, EXTR, ASSE, COMB, EVAL) and TEST_RESU on field concepts.
    fields = os.path.join(SOURCE, "tests", "fields")
    seeds.append(Seed("fields", {"case.comm": os.path.join(fields, "crea_champ.comm"),
                                 "case.mail": os.path.join(verif, "patch_dkq.mail")}, [],
                      dict(comm_targets, **{"case.mail": "mail"}), 0.8))
    seeds.append(Seed("fields_calc", {"case.comm": os.path.join(fields, "plate_moment_dkq.comm"),
                                      "case.mail": os.path.join(verif, "patch_dkq.mail")}, [],
                      dict(comm_targets, **{"case.mail": "mail"}), 0.6))
    seeds.append(Seed("fields_resu", {"case.comm": os.path.join(fields, "crea_resu.comm"),
                                      "case.mail": os.path.join(verif, "patch_dkq.mail")}, [],
                      dict(comm_targets, **{"case.mail": "mail"}), 0.4))
    seeds.append(Seed("fields_frame", {"case.comm": os.path.join(fields, "modi_repere.comm"),
                                       "case.mail": os.path.join(verif, "patch_plan.mail")},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 0.5))
    # CALC_CHAMP ENERGIE: ENEL_* on DKT/DKQ plates, ENEL_* and ETOT_* (a STAT_NON_LINE
    # history) on the plane family's five cell types.
    seeds.append(Seed("fields_energy_plate",
                      {"case.comm": os.path.join(fields, "energy_plate.comm"),
                       "dkt.mail": os.path.join(verif, "patch_dkt.mail"),
                       "dkq.mail": os.path.join(verif, "patch_dkq.mail")},
                      ["--unit", "20=dkt.mail", "--unit", "21=dkq.mail"],
                      dict(comm_targets, **{"dkt.mail": "mail", "dkq.mail": "mail"}), 0.4))
    files = {"case.comm": os.path.join(fields, "energy_patch.comm")}
    args = []
    for unit, cell in enumerate(("tria3", "tria6", "quad4", "quad8", "quad9"), start=20):
        files["patch_%s.mail" % cell] = os.path.join(plane, "patch_%s.mail" % cell)
        args += ["--unit", "%d=patch_%s.mail" % (unit, cell)]
    seeds.append(Seed("fields_energy_plane", files, args,
                      dict(comm_targets, **{"patch_tria6.mail": "mail",
                                            "patch_quad4.mail": "mail"}), 0.4))
    # CREA_CHAMP OPERATION='NORMALE' on the edges of a 12-gon and the faces of a plate patch.
    seeds.append(Seed("fields_normale",
                      {"case.comm": os.path.join(fields, "crea_champ_normale.comm"),
                       "disc.mail": os.path.join(fields, "disc_12.mail"),
                       "dkq.mail": os.path.join(verif, "patch_dkq.mail")},
                      ["--unit", "20=disc.mail", "--unit", "21=dkq.mail"],
                      dict(comm_targets, **{"disc.mail": "mail"}), 0.4))
    # CREA_CHAMP OPERATION='DISC' between locations on the plane family's five cell types.
    files = {"case.comm": os.path.join(fields, "crea_champ_disc.comm")}
    args = []
    for unit, cell in enumerate(("tria3", "tria6", "quad4", "quad8", "quad9"), start=20):
        files["patch_%s.mail" % cell] = os.path.join(plane, "patch_%s.mail" % cell)
        args += ["--unit", "%d=patch_%s.mail" % (unit, cell)]
    seeds.append(Seed("fields_disc", files, args,
                      dict(comm_targets, **{"patch_quad8.mail": "mail"}), 0.4))
    # LIRE_MAILLAGE FORMAT='IDEAS': the universal file mutated.
    seeds.append(Seed("ideas_mesh",
                      {"case.comm": os.path.join(SOURCE, "tests", "mesh", "ideas_plate.comm"),
                       "case.unv": os.path.join(SOURCE, "tests", "mesh", "ideas_plate.unv")},
                      ["--unit", "19=case.unv"], dict(comm_targets, **{"case.unv": "mail"}),
                      0.5))
    # CALC_ERREUR's Zhu-Zienkiewicz estimators on the plane patch.
    seeds.append(Seed("fields_error", {"case.comm": os.path.join(fields, "calc_erreur.comm"),
                                       "case.mail": os.path.join(verif, "patch_plan.mail")},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 0.5))
    # PROJ_CHAMP between two meshes (collocation, VIS_A_VIS, DISTANCE_MAX, MATR_PROJECTION)
    # and CHAMNO_IMPO of the projected field.
    seeds.append(Seed("fields_projection",
                      {"case.comm": os.path.join(fields, "proj_champ.comm"),
                       "case.mail": os.path.join(verif, "patch_plan.mail"),
                       "target.mail": os.path.join(fields, "proj_target.mail")},
                      ["--unit", "20=case.mail", "--unit", "21=target.mail"],
                      dict(comm_targets, **{"case.mail": "mail", "target.mail": "mail"}), 0.5))
    # IMPR_RESU of every kind of field in every format (RESULTAT, MED, VTK, GMSH), and the
    # MED files read back by LIRE_CHAMP (units 80, 81 written and read by the deck itself).
    seeds.append(Seed("fields_output", {"case.comm": os.path.join(SOURCE, "tests", "output",
                                                                  "field_output.comm"),
                                        "case.mail": os.path.join(verif, "patch_dkq.mail")},
                      ["--unit", "20=case.mail", "--unit", "80=all.rmed", "--unit",
                       "81=cham.rmed", "--unit", "82=mesh.rmed"],
                      dict(comm_targets, **{"case.mail": "mail"}), 0.6))
    # Materials as data (every DEFI_MATERIAU behaviour, ELAS three ways).
    seeds.append(Seed("materials", {"case.comm": os.path.join(verif, "materials_as_data.comm"),
                                    "case.mail": os.path.join(verif, "patch_plan.mail")}, [],
                      dict(comm_targets, **{"case.mail": "mail"}), 0.7))
    # Linear relations: LIAISON_DDL / OBLIQUE on the patch, FACE_IMPO DNOR, LIAISON_SOLIDE,
    # LIAISON_MAIL (MASSIF with DNOR and ELIM_MULT, COQUE); LIAISON_PROJ on PROJ_CHAMP's
    # correspondence (IDENTITE on plane solids, EXCENTREMENT on plates); STAT_NON_LINE's
    # follower PRES_REP (EXCIT TYPE_CHARGE='SUIV', functions of XF, YF);
    # the loads' resultants (PESANTEUR, FORCE_ARETE, FORCE_COQUE, FORCE_INTERNE, PRES_REP).
    for name, mesh in (("relations_patch", os.path.join(verif, "patch_plan.mail")),
                       ("face_impo_dnor", os.path.join(verif, "slanted_block.mail")),
                       ("ssnl130a_solide", meshes[("a", "aster")]),
                       ("plate_load_resultants", os.path.join(verif, "loaded_plate.mail")),
                       ("plane_load_resultants", os.path.join(verif, "loaded_block.mail")),
                       ("glued_plan", os.path.join(verif, "glued_plan.mail")),
                       ("glued_plate", os.path.join(verif, "glued_plate.mail")),
                       ("proj_plan", os.path.join(verif, "glued_plan.mail")),
                       ("proj_plate", os.path.join(verif, "proj_plate.mail")),
                       ("follower_pressure", os.path.join(verif, "follower_square.mail"))):
        seeds.append(Seed(name, {"case.comm": os.path.join(verif, name + ".comm"),
                                 "case.mail": mesh}, [],
                          dict(comm_targets, **{"case.mail": "mail"}), 0.7))
    # The deck language's Python: every construct, checked by assert (tests/decks/good).
    seeds.append(Seed("python", {"case.comm": os.path.join(SOURCE, "tests", "decks", "good",
                                                           "python_language.comm")},
                      [], comm_targets, 1.0))
    # Code_Aster's CA.TestCase: every assert, passing and failing.
    seeds.append(Seed("testcase", {"case.comm": os.path.join(SOURCE, "tests", "decks", "python",
                                                             "testcase_asserts.comm")},
                      [], comm_targets, 0.4))
    # Session commands: DEBUT's keywords, DEFI_FICHIER's units, DETRUIRE, CO.
    seeds.append(Seed("session", {"case.comm": os.path.join(SOURCE, "tests", "decks", "good",
                                                            "session_commands.comm")},
                      [], comm_targets, 0.5))
    # User macros: MACRO, SIMP, FACT, rules and UserMacro, calls validated then run.
    seeds.append(Seed("user_macro", {"case.comm": os.path.join(SOURCE, "tests", "decks", "good",
                                                               "user_macro.comm")},
                      [], comm_targets, 0.5))
    # DEFI_LIST_INST and the cutting of a failed step.
    seeds.append(Seed("list_inst", {"case.comm": os.path.join(verif, "list_inst_cutting.comm"),
                                    "case.mail": os.path.join(verif, "list_inst_cutting.mail")},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 0.7))
    # Tables (issue 20): every table command on lists; LIRE_TABLE on mutated table files.
    tables = os.path.join(SOURCE, "tests", "tables")
    seeds.append(Seed("tables", {"case.comm": os.path.join(tables, "table_commands.comm")},
                      [], comm_targets, 1.0))
    seeds.append(Seed("table_files", {"case.comm": os.path.join(tables, "read_tables.comm"),
                                      "case.38": os.path.join(tables, "read_tables.38"),
                                      "case.39": os.path.join(tables, "read_tables.39"),
                                      "case.40": os.path.join(tables, "read_tables.40")},
                      ["--unit", "38=case.38", "--unit", "39=case.39", "--unit", "40=case.40"],
                      dict(comm_targets, **{"case.38": "table", "case.39": "table",
                                            "case.40": "table"}), 1.0))
    # Functions by points: CALC_FONCTION's operations, TEST_FONCTION, IMPR_FONCTION.
    seeds.append(Seed("functions", {"case.comm": os.path.join(tables, "functions.comm")},
                      [], comm_targets, 1.0))
    # DEFI_PRES_EC8: the tank pressure's numbers and the points it is evaluated at.
    seeds.append(Seed("defi_pres_ec8",
                      {"case.comm": os.path.join(SOURCE, "tests", "ec8", "defi_pres_ec8.comm")},
                      [], comm_targets, 0.5))
    seeds.append(Seed("force_coque_fo_ec8",
                      {"case.comm": os.path.join(SOURCE, "tests", "ec8", "ec8_plate_load.comm"),
                       "case.mail": os.path.join(SOURCE, "tests", "verification",
                                                 "loaded_plate.mail")},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 0.5))
    # POST_RELEVE_T on formula fields of the annulus, and on SSNL130's reactions.
    seeds.append(Seed("post_releve", {"case.comm": os.path.join(tables, "post_releve.comm"),
                                      "case.mail": os.path.join(tables, "annulus.mail")},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 1.0))
    seeds.append(Seed("post_releve_ssnl130",
                      {"case.comm": os.path.join(tables, "post_releve_ssnl130.comm"),
                       "case.mail": meshes[("a", "aster")]}, [],
                      dict(comm_targets, **{"case.mail": "mail"}), 0.7))
    # CREA_TABLE on ELGA fields: the points' coordinates on plane cells and plate layers.
    seeds.append(Seed("crea_table_elga",
                      {"case.comm": os.path.join(tables, "crea_table_elga.comm"),
                       "case.20": os.path.join(tables, "elga_plane.mail"),
                       "case.21": os.path.join(tables, "elga_plate.mail")},
                      ["--unit", "20=case.20", "--unit", "21=case.21"],
                      dict(comm_targets, **{"case.20": "mail", "case.21": "mail"}), 0.6))
    # MACR_LIGN_COUPE: cut lines across the four cell types, a patch test's SIGM_ELNO.
    seeds.append(Seed("macr_lign_coupe",
                      {"case.comm": os.path.join(tables, "macr_lign_coupe.comm"),
                       "case.20": os.path.join(tables, "lign_coupe.mail")},
                      ["--unit", "20=case.20"],
                      dict(comm_targets, **{"case.20": "mail"}), 0.6))
    # MACR_LIGN_COUPE's frames (POLAIRE, LOCAL on a node path, CYLINDRIQUE) and quantities
    # (INVARIANT, ELEM_PRINCIPAUX, TRAC_NOR, TRAC_DIR) on the annulus and its turned copy.
    seeds.append(Seed("lign_coupe_frames",
                      {"case.comm": os.path.join(tables, "lign_coupe_frames.comm"),
                       "case.mail": os.path.join(tables, "annulus.mail")},
                      [], dict(comm_targets, **{"case.mail": "mail"}), 0.8))
    # POST_ELEM MASS_INER: a plane rectangle of four cell types, a tilted plate.
    seeds.append(Seed("post_elem",
                      {"case.comm": os.path.join(tables, "post_elem.comm"),
                       "case.20": os.path.join(tables, "lign_coupe.mail"),
                       "case.21": os.path.join(tables, "post_elem_plate.mail")},
                      ["--unit", "20=case.20", "--unit", "21=case.21"],
                      dict(comm_targets, **{"case.20": "mail", "case.21": "mail"}), 0.6))
    # POST_ELEM VOLUMOGRAMME: per-cell ELGA / ELNO values, SEUIL, BORNES, a layered plate.
    seeds.append(Seed("post_elem_volumogramme",
                      {"case.comm": os.path.join(tables, "post_elem_volumogramme.comm"),
                       "case.20": os.path.join(tables, "lign_coupe.mail"),
                       "case.21": os.path.join(tables, "elga_plate.mail")},
                      ["--unit", "20=case.20", "--unit", "21=case.21"],
                      dict(comm_targets, **{"case.20": "mail", "case.21": "mail"}), 0.6))
    seeds.append(Seed("post_elem_energy",
                      {"case.comm": os.path.join(tables, "post_elem_energy.comm"),
                       "case.20": os.path.join(tables, "lign_coupe.mail"),
                       "case.21": os.path.join(tables, "post_elem_plate.mail")},
                      ["--unit", "20=case.20", "--unit", "21=case.21"],
                      dict(comm_targets, **{"case.20": "mail", "case.21": "mail"}), 0.6))
    seeds.append(Seed("post_elem_minmax",
                      {"case.comm": os.path.join(tables, "post_elem_minmax.comm"),
                       "case.20": os.path.join(tables, "lign_coupe.mail")},
                      ["--unit", "20=case.20"], dict(comm_targets, **{"case.20": "mail"}), 0.6))
    # TAB['PARA', ROW], EXTR_TABLE() and the Python tables' columns, rows and filters.
    seeds.append(Seed("table_methods", {"case.comm": os.path.join(tables, "table_methods.comm")},
                      [], comm_targets, 0.8))
    seeds.append(Seed("check_all", {"case.comm": os.path.join(SOURCE, "tests", "decks",
                                                              "check", "all_commands.comm")},
                      ["--check"], comm_targets, 0.5))
    # The mesh commands (DEFI_GROUP, MODI_MAILLAGE, CREA_MAILLAGE) on the test plate: every
    # option of each, their groups used again by later commands.
    mesh_commands = os.path.join(SOURCE, "tests", "mesh_commands")
    for name in ("groups_plate", "modify_plate", "create_plate", "deform_plate"):
        seeds.append(Seed(name, {"case.comm": os.path.join(mesh_commands, name + ".comm"),
                                 "case.mail": os.path.join(mesh_commands, "plate4.mail")}, [],
                          dict(comm_targets, **{"case.mail": "mail"}), 0.7))
    # GIBI meshes (LIRE_MAILLAGE FORMAT='GIBI', PRE_GIBI): the file mutated as text.
    seeds.append(Seed("gibi_strip", {"case.comm": os.path.join(mesh_commands, "gibi_strip.comm"),
                                     "case.mgib": os.path.join(mesh_commands, "strip.mgib")},
                      ["--unit", "19=case.mgib"], dict(comm_targets, **{"case.mgib": "gibi"}),
                      0.7))
    # Gmsh's 1.0 format ($NOD, $ELM): the file mutated as text.
    seeds.append(Seed("gmsh1_strip", {"case.comm": os.path.join(mesh_commands, "gmsh1_strip.comm"),
                                      "case.msh": os.path.join(mesh_commands, "strip1.msh")},
                      ["--unit", "19=case.msh"], dict(comm_targets, **{"case.msh": "gmsh1"}),
                      0.5))
    # I-DEAS universal files (LIRE_MAILLAGE FORMAT='IDEAS'): the file mutated as text.
    seeds.append(Seed("ideas_strip", {"case.comm": os.path.join(mesh_commands, "ideas_strip.comm"),
                                      "case.unv": os.path.join(mesh_commands, "strip.unv")},
                      ["--unit", "19=case.unv"], dict(comm_targets, **{"case.unv": "ideas"}),
                      0.7))
    if aster_med:
        read_deck = os.path.join(seeds_dir, "read_med.comm")
        with open(read_deck, "w", encoding="utf-8") as f:
            f.write("DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\nFIN()\n")
        found = []
        for root, _, names in os.walk(aster_med):
            found += [os.path.join(root, n) for n in names if n.endswith(".mmed")]
        stems = set()
        for path in sorted(found):
            stem = os.path.splitext(os.path.basename(path))[0]
            if stem in stems:
                continue
            stems.add(stem)
            seeds.append(Seed("aster_med_" + stem, {"case.comm": read_deck, "case.med": path},
                              [], {"case.med": "med"}, 0.5, names="case.med"))
        if not stems:
            print("fuzz: no *.mmed under %s" % aster_med)
    if wanted:
        # "med": every seed with a MED mesh
        seeds = [s for s in seeds if s.name in wanted or
                 ("med" in wanted and "case.med" in s.files)]
    return seeds


# ---- cases ------------------------------------------------------------------------------------
def vocabulary(seeds):
    """Keywords and quoted words of every seed text file (for swaps)."""
    words, texts = set(), set()
    for seed in seeds:
        for role, path in seed.files.items():
            if role.endswith((".comm", ".com1", ".mail", ".export", ".py", ".msh")):
                data = open(path, "rb").read()
                words.update(mutate.KEYWORD.findall(data))
                texts.update(m[1:-1] for m in mutate.QUOTED.findall(data))
    return sorted(words), sorted(texts)


GMSH_HEADER = re.compile(rb"^\$(Nodes|Elements|Entities|PhysicalNames)\s*$")
GMSH_BLOCK_START = re.compile(rb"^\$(?!End)\w+\s*$")
GMSH_BLOCK_END = re.compile(rb"^\$End\w+\s*$")
MAIL_BLOCK_START = re.compile(rb"^\s*(COOR_[23]D|POI1|SEG2|TRIA3|QUAD4|GROUP_NO|GROUP_MA)\b")
MAIL_BLOCK_END = re.compile(rb"^\s*FINSF\b")


def mutate_text(rng, data, family, words, texts):
    """One mutation of a text file of the given family; returns (data, description)."""
    ops = [("flip", 2), ("truncate", 1), ("delete", 1), ("duplicate", 1), ("line", 3),
           ("number", 6)]
    if family in ("deck", "module", "export"):
        ops += [("keyword", 3), ("quoted", 2)]
    if family in ("deck", "module"):
        ops += [("expression", 3)]
    if family == "deck":
        ops += [("keyword_number", 8)]
    if family in ("gmsh22", "gmsh41"):
        ops += [("count", 6), ("block", 2)]
    if family == "mail":
        ops += [("geometry", 3), ("block", 2), ("keyword", 1)]
    names = [n for n, _ in ops]
    op = rng.choices(names, weights=[w for _, w in ops])[0]
    if op == "flip":
        return mutate.flip(rng, data)
    if op == "truncate":
        return mutate.truncate(rng, data)
    if op == "delete":
        return mutate.delete_span(rng, data)
    if op == "duplicate":
        return mutate.duplicate_span(rng, data)
    if op == "line":
        return mutate.line_edit(rng, data)
    if op == "number":
        return mutate.number(rng, data)
    if op == "keyword":
        return mutate.keyword(rng, data, words)
    if op == "quoted":
        return mutate.quoted(rng, data, texts)
    if op == "expression":
        return mutate.expression(rng, data)
    if op == "keyword_number":
        return mutate.keyword_number(rng, data)
    if op == "count":
        return mutate.count(rng, data, GMSH_HEADER)
    if op == "geometry":
        return mutate.mail_geometry(rng, data)
    if family == "mail":
        return mutate.block_duplicate(rng, data, MAIL_BLOCK_START, MAIL_BLOCK_END)
    return mutate.block_duplicate(rng, data, GMSH_BLOCK_START, GMSH_BLOCK_END)


def make_case(seeds, words, texts, master, index, folder):
    """Writes case `index` into `folder`; returns (seed, description list)."""
    rng = random.Random("%s/%d" % (master, index))
    seed = rng.choices(seeds, weights=[s.weight for s in seeds])[0]
    os.makedirs(folder, exist_ok=True)
    for role, path in seed.files.items():
        shutil.copyfile(path, os.path.join(folder, role))
    # half of the plain-deck cases run through an export file with a time limit (as
    # run_aster runs them): a legitimately long computation then stops itself, located,
    # and only a true hang (no deadline reached) outlives the fuzzer's timeout
    via_export = ("case.export" not in seed.files and not seed.args
                  and rng.random() < 0.5)
    if via_export:
        lines = ["P time_limit %d" % EXPORT_TIME_LIMIT, "F comm case.comm D 1"]
        for name in seed.files:
            kind = name.rsplit(".", 1)[1]
            if kind in ("mail", "msh", "med"):
                lines.append("F %s %s D 20" % (kind, name))
        with open(os.path.join(folder, "case.export"), "w") as f:
            f.write("\n".join(lines) + "\n")
    role = rng.choice(sorted(seed.targets))
    family = seed.targets[role]
    target = os.path.join(folder, role)
    done = []
    n = rng.choices([1, 2, 3, 4], weights=[60, 25, 10, 5])[0]
    for _ in range(n):
        if family == "med":
            if rng.random() < 0.5:
                # through h5py, in a process of its own: HDF5 may crash on a damaged file
                proc = subprocess.run([sys.executable, MUTATE, "med", target,
                                       str(rng.randrange(2**32))], capture_output=True,
                                      timeout=120)
                if proc.returncode == 0:
                    done.append(proc.stdout.decode("utf-8", "replace").strip())
                    continue
                done.append("h5py refused (exit %d)" % proc.returncode)   # bytes instead
            data = open(target, "rb").read()
            op = rng.choice([mutate.flip, mutate.flip, mutate.truncate, mutate.delete_span,
                             mutate.duplicate_span])
            data, what = op(rng, data)
        else:
            data = open(target, "rb").read()
            data, what = mutate_text(rng, data, family, words, texts)
        with open(target, "wb") as f:
            f.write(data)
        done.append(what)
    return seed, role, done, via_export


# ---- running and classifying ------------------------------------------------------------------
def limit_child():
    resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    os.setsid()


def run_one(parasol, folder, args, timeout):
    out = os.path.join(folder, "out")
    if os.path.isdir(out):
        shutil.rmtree(out)
    os.makedirs(out)
    cmd = [parasol, "--outdir", "out"] + args
    start = time.monotonic()
    proc = subprocess.Popen(cmd, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            preexec_fn=limit_child)
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
        status = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        stdout, stderr = proc.communicate()
        status = None
    return {"status": status, "seconds": round(time.monotonic() - start, 3),
            "stdout": stdout.decode("utf-8", "replace"),
            "stderr": stderr.decode("utf-8", "replace"), "command": " ".join(cmd)}


def input_words(folder):
    """NaN/Inf spellings written in the case's own input files: an error message may quote
    them (`name inf is not defined`, `no node with tag Infinity`) without computing them."""
    words = set()
    for name in os.listdir(folder):
        path = os.path.join(folder, name)
        if os.path.isfile(path) and not name.endswith((".med", ".txt")):
            with open(path, encoding="utf-8", errors="replace") as f:
                words.update(m.group(0).lower().lstrip("+-")
                             for m in NOT_FINITE.finditer(f.read()))
    return words


def scan_not_finite(text, quoted=frozenset()):
    """NaN/Inf tokens in a listing, leaving out echoed deck lines, quoted input, and in
    error and warning lines the spellings that the input itself contains (`quoted`); so
    too, in any line, an all-capitals INF or NAN the input contains (a legend or a name
    copied from the deck: no number is ever written that way)."""
    hits = []
    for line in text.splitlines():
        if ECHO.match(line):
            continue
        line = QUOTES.sub("", line)
        message = "error: " in line or "warning: " in line
        if message:
            line = ALLOWED.sub("", line)
        if LISTING_NOT_FINITE.search(line):
            hits.append(line.strip()[:160])
            continue
        for m in NOT_FINITE.finditer(line):
            if (message or m.group(0).lstrip("+-") in ("INF", "NAN")) and \
                    m.group(0).lower().lstrip("+-") in quoted:
                continue
            hits.append(line.strip()[:160])
            break
    return hits


def scan_outputs(folder):
    """(NaN/Inf findings, temporary files left) in the case folder and its output folder."""
    nan, temps = [], []
    quoted = input_words(folder)
    for root, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(root, name)
            rel = os.path.relpath(path, folder)
            if ".partial" in name or name.endswith(".tmp"):
                temps.append(rel)
            if not rel.startswith("out" + os.sep):
                continue
            if name.endswith((".med", ".rmed")):
                nan += ["%s: %s" % (rel, h) for h in med_not_finite(path)]
                continue
            try:
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read(4 << 20)
            except OSError:
                continue
            nan += ["%s: %s" % (rel, h) for h in scan_not_finite(text, quoted)[:3]]
    return nan, temps


def med_not_finite(path):
    """Datasets of a MED result holding NaN/Inf (h5py in a process of its own)."""
    try:
        import h5py  # noqa: F401
    except ImportError:
        return []
    proc = subprocess.run([sys.executable, MUTATE, "finite", path], capture_output=True,
                          timeout=120)
    lines = proc.stdout.decode("utf-8", "replace").split("\n")
    bad = [line for line in lines if line.strip()]
    if proc.returncode not in (0, 3):
        bad.append("result file checked by h5py: exit %d" % proc.returncode)
    return bad


def classify(result, folder, names=None):
    """The class of a run and its reasons. names: a file the error of exit 1 must name, on
    the one line of stderr (class `unnamed` otherwise)."""
    err, status = result["stderr"], result["status"]
    reasons = []
    if status is None:
        return "hang", ["no exit after %.0f s" % result["seconds"]]
    signs = [s for s in CRASH_SIGNS if s in err or s in result["stdout"]]
    if status < 0 or status not in (0, 1, 2) or signs:
        reasons = ["exit status %d" % status] + ["stderr has %r" % s for s in signs]
        return "crash", reasons
    nan, temps = scan_outputs(folder)
    nan += ["stdout: " + h for h in scan_not_finite(result["stdout"], input_words(folder))[:3]]
    if status == 1 and not LOCATED.search(err):
        return "unlocated", ["exit 1, stderr: " + (err.strip()[:300] or "(empty)")]
    if status in (0, 2) and ERROR_LINE.search(err):
        return "unlocated", ["exit %d with an error on stderr: %s" % (status, err[:300])]
    if names and status == 1:
        lines = [line for line in err.splitlines() if line.strip()]
        if len(lines) != 1 or names not in lines[0]:
            return "unnamed", ["exit 1 without one line naming %s: %s" % (names, err[:300])]
    if nan:
        return "nan", nan[:5]
    if temps:
        return "temporary", temps[:5]
    return "clean", []


def clip(text):
    """The start (the message, the first frames of a backtrace) and the end of stderr."""
    return text if len(text) <= 1500 else text[:1200] + "\n[...]\n" + text[-300:]


def do_case(ctx, index):
    folder = os.path.join(ctx["work"], "cases", str(index))
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    seed, role, what, via_export = make_case(ctx["seeds"], ctx["words"], ctx["texts"],
                                             ctx["seed"], index, folder)
    main = [r for r in seed.files if r.endswith((".comm", ".export"))]
    main = "case.export" if ("case.export" in seed.files or via_export) else main[0]
    args = seed.args + [main]
    result = run_one(ctx["parasol"], folder, args, ctx["timeout"])
    kind, reasons = classify(result, folder, seed.names)
    record = {"case": index, "seed_input": seed.name + (" (export)" if via_export else ""),
              "file": role, "mutations": what,
              "class": kind, "reasons": reasons, "status": result["status"],
              "seconds": result["seconds"], "stderr": clip(result["stderr"])}
    if ctx["compare"]:
        other = run_one(ctx["compare"], folder, args, ctx["timeout"] * 2)
        record["status_compare"] = other["status"]
        other_kind, _ = classify(other, folder, seed.names)
        record["class_compare"] = other_kind
        if kind == "clean" and other["status"] != result["status"]:
            record["class"] = "mismatch"
            record["reasons"] = ["exit %s here, %s with %s" % (result["status"],
                                                              other["status"],
                                                              ctx["compare"])]
            record["stderr_compare"] = clip(other["stderr"])
    with open(os.path.join(folder, "command.txt"), "w") as f:
        f.write("cd %s && %s\n" % (folder, result["command"]))
    if record["class"] == "clean" or ctx["kept"] >= ctx["keep"]:
        shutil.rmtree(folder, ignore_errors=True)
    else:
        ctx["kept"] += 1
    return record


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("parasol")
    parser.add_argument("--compare", help="a second parasol (e.g. Release): same exit status")
    parser.add_argument("--seed", default="1")
    parser.add_argument("--cases", type=int, default=300)
    parser.add_argument("--first", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=30.0)
    parser.add_argument("--work", default="fuzz-work")
    parser.add_argument("--seeds", default="", help="comma-separated seed input names")
    parser.add_argument("--keep", type=int, default=20, help="case folders kept (not clean)")
    parser.add_argument("--report", help="JSON report file")
    parser.add_argument("--show", type=int, default=10, help="cases printed per class")
    parser.add_argument("--quiet", action="store_true")
    parser.add_argument("--aster-med", help="a folder of Code_Aster MED meshes (*.mmed): "
                        "seeds read by a deck that only reads them (--seeds med: MED only)")
    opts = parser.parse_args(argv)
    parasol = os.path.abspath(opts.parasol)
    compare = os.path.abspath(opts.compare) if opts.compare else None
    work = os.path.abspath(opts.work)
    os.makedirs(os.path.join(work, "cases"), exist_ok=True)
    wanted = [w for w in opts.seeds.split(",") if w]
    if opts.aster_med and not os.path.isdir(opts.aster_med):
        print("fuzz: SKIPPED: no folder %s for --aster-med" % opts.aster_med)
        return 77
    seeds = make_seeds(parasol, work, wanted, opts.aster_med)
    words, texts = vocabulary(seeds)
    ctx = {"work": work, "seeds": seeds, "words": words, "texts": texts, "seed": opts.seed,
           "parasol": parasol, "compare": compare, "timeout": opts.timeout,
           "keep": opts.keep, "kept": 0}
    start = time.monotonic()
    records = []
    indexes = range(opts.first, opts.first + opts.cases)
    with concurrent.futures.ThreadPoolExecutor(max_workers=opts.jobs) as pool:
        for record in pool.map(lambda i: do_case(ctx, i), indexes):
            records.append(record)
            if not opts.quiet and record["class"] != "clean":
                print("case %d (%s, %s): %s: %s" % (record["case"], record["seed_input"],
                                                    record["file"], record["class"],
                                                    "; ".join(record["reasons"])[:300]),
                      flush=True)
    elapsed = time.monotonic() - start
    counts = {}
    for r in records:
        counts[r["class"]] = counts.get(r["class"], 0) + 1
    statuses = {}
    for r in records:
        statuses[str(r["status"])] = statuses.get(str(r["status"]), 0) + 1
    by_seed = {}
    for r in records:
        by_seed.setdefault(r["seed_input"], 0)
        by_seed[r["seed_input"]] += 1
    # cases where the MED library died in its own process and parasol reported it (issue 23)
    contained = sum(1 for r in records if "the MED library died" in r["stderr"])
    summary = {"parasol": parasol, "compare": compare, "seed": opts.seed,
               "first": opts.first, "cases": len(records), "seconds": round(elapsed, 1),
               "classes": counts, "exit_statuses": statuses, "seed_inputs": by_seed,
               "med_library_died": contained,
               "not_clean": [r for r in records if r["class"] != "clean"]}
    if opts.report:
        with open(opts.report, "w") as f:
            json.dump(summary, f, indent=1)
    print("fuzz: seed %s, cases %d..%d: %s; exit statuses %s; %.0f s" % (
        opts.seed, opts.first, opts.first + len(records) - 1,
        ", ".join("%s %d" % kv for kv in sorted(counts.items())),
        ", ".join("%s: %d" % kv for kv in sorted(statuses.items())), elapsed))
    if contained:
        print("fuzz: in %d case(s) the MED library died in its own process, reported as "
              "one line" % contained)
    shown = {}
    for r in summary["not_clean"]:
        shown[r["class"]] = shown.get(r["class"], 0) + 1
        if shown[r["class"]] <= opts.show:
            print("  case %d [%s] %s %s: %s\n    mutations: %s\n    stderr: %s" % (
                r["case"], r["class"], r["seed_input"], r["file"], "; ".join(r["reasons"]),
                " | ".join(r["mutations"]), r["stderr"].strip()[-300:]))
    return 0 if counts.get("clean", 0) == len(records) else 1


if __name__ == "__main__":
    sys.exit(main())

# Loads and exact answers of the SSNL130 model B slab (decks/ssnl130b.comm), imported by
# session.comm and session.com1 (tests/export): a module of the deck, as Code_Aster's
# ssnl130a.py is for its test.
"""Rigid-slab references: PT01 and PT02 displacements DY at INST = 1 (doc/verification.md)."""

U_A = -208.0 / 58875.0
U_B = 176.0 / 153075.0
LIFT = 5.0e-03


def Chargement(t, x, y, z):
    fy = -5.0 * (x - 2.0) ** 2
    if t <= 1.0:
        return fy * t
    return fy


def Soulevement(t):
    if t <= 1.0:
        return 0.0
    return (t - 1.0) * LIFT

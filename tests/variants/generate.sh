#!/usr/bin/env bash
# Regenerates the committed variant decks of tests/variants/ (deck + mesh + exact discrete
# references, tools/make_ssnl130_case.py). The tests only run the committed files, so Python
# is needed only to regenerate. Each line: name, then the generator's options.
# Tolerances (relative, on both the NON_REGRESSION and the ANALYTIQUE line): TOL_A for model
# A (issue 6: 1e-6), TOL_B for model B (the slab's own flexibility, doc/verification.md).
# The reference is a rigid plate; the finite-element plate bends by a relative amount that
# grows like K b^4 / (E h^3). Variants that lengthen the slab or move the load towards one
# end (b = 3, m = 1) make it bend more, so they soften the bed (K) to stay in the rigid
# regime the reference describes. With m = 3 the edge load's nodal forces (2-point Gauss on
# each SEG2, exact up to degree 3, here degree 4) are off by O(h^4): 6e-6 at ny = 16,
# 3.5e-7 at 32, 2.4e-8 at 64 (K = 1e2), so model B with m = 3 uses ny = 64. A softer bed (or a finer mesh) makes the stiffness
# ratio plate/springs larger: the pivots lose more digits, so those decks raise NPREC (as a
# Code_Aster user would) above the 9 of SSNL130.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
TOL_A=1e-6
TOL_B=2e-7
# Every deck converges far below the default RESI_GLOB_RELA (1e-6): the test checks the
# answer of the equations, not where a loose criterion happens to stop.
RESI=1e-10
gen() {
    local name=$1; shift
    /usr/bin/python3 "$root/tools/make_ssnl130_case.py" --resi $RESI "$@" -o "$here/decks/$name"
}
mkdir -p "$here/decks"
# Model A (3D DKQ plate + DIS_T springs), full Newton unless said otherwise.
gen a_base          --model a --lift 5e-3 --tolerance $TOL_A
gen a_width_2       --model a --a 2 --tolerance $TOL_A
gen a_length_3      --model a --b 3 --tolerance $TOL_A
gen a_K_1e3         --model a --K 1e3 --nprec 11 --tolerance $TOL_A
gen a_p_50          --model a --p 50 --tolerance $TOL_A
gen a_ny_32         --model a --ny 32 --tolerance $TOL_A
gen a_ny_64         --model a --ny 64 --nprec 11 --tolerance $TOL_A
gen a_nx_8          --model a --nx 8 --tolerance $TOL_A
gen a_m_1           --model a --m 1 --tolerance $TOL_A
gen a_m_3           --model a --m 3 --tolerance $TOL_A
gen a_lift_1e-2     --model a --lift 1e-2 --tolerance $TOL_A
gen a_elastique     --model a --lift 5e-3 --newton elastique --iter-max 60 \
                    --tolerance $TOL_A
gen a_p_5           --model a --tolerance $TOL_A
gen a_p_5e-8        --model a --p 5e-8 --tolerance $TOL_A
gen a_p_5e8         --model a --p 5e8 --tolerance $TOL_A
gen a_lifting_load  --model a --p -5 --expect-no-equilibrium
# RELATION='DIS_CONTACT' (SSNL130 C/D): the springs carry a force only if they start pressed,
# so DIST_1 = L + 1e-9 as in Code_Aster's decks, and the answer moves by that 1e-9.
# ELASTIQUE is true modified Newton there (DIS_CHOC forces tangent corrections).
gen a_dis_contact   --model a --relation DIS_CONTACT --dist1-offset 1e-9 --shift-by-gap \
                    --lift 5e-3 --tolerance $TOL_A
gen a_dis_contact_elastique --model a --relation DIS_CONTACT --dist1-offset 1e-9 \
                    --shift-by-gap --lift 5e-3 --newton elastique --iter-max 60 \
                    --tolerance $TOL_A
# Model B (2D plane-strain slice + 2D_DIS_T springs).
gen b_base          --model b --lift 5e-3 --tolerance $TOL_B
gen b_length_3_K_1e3 --model b --b 3 --K 1e3 --nprec 11 --tolerance $TOL_B
gen b_K_1e3         --model b --K 1e3 --nprec 11 --tolerance $TOL_B
gen b_p_50          --model b --p 50 --tolerance $TOL_B
gen b_ny_32         --model b --ny 32 --tolerance $TOL_B
gen b_ny_64         --model b --ny 64 --tolerance $TOL_B
gen b_m_1_K_1e2     --model b --m 1 --K 1e2 --nprec 12 --tolerance $TOL_B
gen b_m_3_ny_64     --model b --m 3 --ny 64 --tolerance $TOL_B
gen b_lift_1e-2     --model b --lift 1e-2 --tolerance $TOL_B
gen b_elastique     --model b --lift 5e-3 --newton elastique --iter-max 60 \
                    --tolerance $TOL_B
gen b_p_5           --model b --tolerance $TOL_B
gen b_p_5e-8        --model b --p 5e-8 --tolerance $TOL_B
gen b_p_5e8         --model b --p 5e8 --tolerance $TOL_B
gen b_lifting_load  --model b --p -5 --expect-no-equilibrium
gen b_dis_contact   --model b --relation DIS_CONTACT --dist1-offset 1e-9 --shift-by-gap \
                    --lift 5e-3 --tolerance $TOL_B
gen b_dis_contact_elastique --model b --relation DIS_CONTACT --dist1-offset 1e-9 \
                    --shift-by-gap --lift 5e-3 --newton elastique --iter-max 60 \
                    --tolerance $TOL_B

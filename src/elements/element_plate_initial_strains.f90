!> Nodal forces of initial strains on DKT / DKQ plates (thermal strains, PRE_EPSI): the
!> generalized forces N0 = int D eps0(z) dz (membrane) and M0 = int D eps0(z) z dz (bending)
!> at the points of Code_Aster's RIGI family (DKT FPG3, DKQ FPG4), in the cell's local
!> frame (element_plate), give
!>   f = sum_g (Bm^T N0_g + Bb^T M0_g) |det J| w_g,
!> Bm the membrane (CST / bilinear Q4) and Bb the discrete-Kirchhoff curvature operators of
!> the stiffness; the element's equilibrium is K u = f_ext + f. The strain at height z of
!> the plate is e + z k (z along the cell's normal, the right-hand rule on its nodes, from
!> -h/2 at the bottom face INF to +h/2 at the top face SUP), so a temperature rising towards
!> SUP bends the plate towards INF.
!> Through the thickness (plate_layer_points): COQUE_NCOU layers of equal thickness, three
!> points each (INF, MOY, SUP of the layer, Code_Aster's sub-points), Simpson's weights
!> (1, 4, 1)/6 of the layer: exact for a strain quadratic in z.
module element_plate_initial_strains
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use mesh_cell_shapes, only: CELL_TRIA3, CELL_QUAD4
    use element_gauss_families, only: gauss_rule_t, gauss_family, FORMULATION_PLATE
    use element_kirchhoff_bending, only: kirchhoff_bending_b
    use element_plate, only: plate_local_frame, plate_membrane_b
    implicit none
    private

    public :: plate_rigi_rule, plate_layer_points, plate_initial_strain_forces

contains

    !> The RIGI points of a plate cell of nn = 3 (DKT) or 4 (DKQ) nodes.
    subroutine plate_rigi_rule(nn, rule, st)
        integer(i4), intent(in) :: nn
        type(gauss_rule_t), intent(out) :: rule
        type(status_t), intent(out) :: st
        call gauss_family(FORMULATION_PLATE, merge(CELL_TRIA3, CELL_QUAD4, nn == 3), 'RIGI', &
                          rule, st)
    end subroutine plate_rigi_rule

    !> Heights and weights of the sub-points of `layers` equal layers of a plate of
    !> thickness h: z(3 layers), w(3 layers) (sum h), layer by layer from the bottom, INF,
    !> MOY, SUP in each (module header).
    pure subroutine plate_layer_points(h, layers, z, w)
        real(dp), intent(in) :: h
        integer(i4), intent(in) :: layers
        real(dp), intent(out) :: z(:), w(:)
        real(dp) :: hl
        integer(i4) :: l
        hl = h / real(layers, dp)
        do l = 1, layers
            z(3 * l - 2) = -0.5_dp * h + real(l - 1, dp) * hl
            z(3 * l - 1) = z(3 * l - 2) + 0.5_dp * hl
            z(3 * l) = z(3 * l - 2) + hl
            w(3 * l - 2:3 * l) = hl * [1.0_dp, 4.0_dp, 1.0_dp] / 6.0_dp
        end do
    end subroutine plate_layer_points

    !> Global nodal forces (DX .. DRZ per node) of generalized initial-strain forces given at
    !> the RIGI points (module header).
    !>  coords : in, coords(3, nn) node coordinates; nn : in, 3 or 4
    !>  n0, m0 : in, (3, n_rigi) membrane forces and moments (xx, yy, xy) in the local frame
    !>  fe     : out, fe(6 nn)
    !>  st     : out, a degenerate cell
    subroutine plate_initial_strain_forces(coords, nn, n0, m0, fe, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), n0(:, :), m0(:, :)
        real(dp), intent(out) :: fe(6 * nn)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        real(dp) :: rot(3, 3), xy(2, nn), bb(3, 3 * nn), bm(3, 2 * nn), fl(6 * nn)
        real(dp) :: det, detb, wd
        integer(i4) :: g, i
        fe = 0.0_dp
        call plate_local_frame(coords, nn, rot, xy, st)
        if (st%ok()) call plate_rigi_rule(nn, rule, st)
        if (st%failed()) return
        fl = 0.0_dp
        do g = 1, rule%n
            call plate_membrane_b(xy, nn, rule%xi(:, g), bm, det)
            call kirchhoff_bending_b(xy, nn, rule%xi(:, g), bb, detb)
            if (.not. abs(det) > 0.0_dp .or. .not. detb > 0.0_dp) then
                call set_error(st, STATUS_MODEL_ERROR, 'plate cell is degenerate')
                return
            end if
            wd = abs(det) * rule%w(g)
            do i = 1, nn
                fl(6 * i - 5:6 * i - 4) = fl(6 * i - 5:6 * i - 4) + &
                    matmul(n0(:, g), bm(:, 2 * i - 1:2 * i)) * wd
                fl(6 * i - 3:6 * i - 1) = fl(6 * i - 3:6 * i - 1) + &
                    matmul(m0(:, g), bb(:, 3 * i - 2:3 * i)) * wd
            end do
        end do
        do i = 1, 2 * nn       ! the 3-vectors (u; theta) of each node back to the global frame
            fe(3 * i - 2:3 * i) = matmul(transpose(rot), fl(3 * i - 2:3 * i))
        end do
    end subroutine plate_initial_strain_forces

end module element_plate_initial_strains

!> The nodal forces of AFFE_CHAR_MECA(_F) PRE_EPSI, imposed initial strains eps0 (Code_Aster
!> U4.44.01, options CHAR_MECA_EPSI_R / _F): the element's equilibrium is K u = f_ext + f0,
!> so a free body takes exactly the strain eps0 with no stress and a held one carries
!> -D eps0.
!>  - plane cells (D_PLAN, C_PLAN; EPXX, EPYY, EPZZ, EPXY, tensor components in the global
!>    axes): f0 = sum_g B^T sig0 |det J| w_g on the RIGI points, sig0 the stress the cell's
!>    law gives to eps0 (element_plane plane_initial_strain_forces; D_PLAN's eps_zz = 0
!>    makes EPZZ load the plane), as Code_Aster's te0284;
!>  - plates (DKT, DKQ; EXX, EYY, EXY membrane strains and KXX, KYY, KXY curvatures, tensor
!>    components, in the cell's intrinsic frame as Code_Aster's te0035 / dxefgi take them:
!>    x along side 1-2 of a triangle, from the middle of side 4-1 to the middle of side 2-3
!>    of a quadrangle, dxtpgl / dxqpgl): N0 = Dm (EXX, EYY, 2 EXY), M0 = Df (KXX, KYY,
!>    2 KXY) at the RIGI points, Dm and Df the section's membrane and bending rigidities in
!>    that frame (no membrane-bending coupling, as dxefgi), then
!>    f0 = sum_g (Bm^T N0 + Bb^T M0) |det J| w_g (element_plate_initial_strains).
!> A value that is a function (AFFE_CHAR_MECA_F) is evaluated at each RIGI point
!> (X, Y, Z of the point, INST), as dxefgi_fonc; every value is multiplied by the FONC_MULT
!> factor of its EXCIT.
module assembly_pre_epsi
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text
    use mesh_types, only: cell_label, CELL_TYPE_NODES, MAX_CELL_NODES, CELL_TRIA3, CELL_QUAD4
    use mesh_cell_shapes, only: cell_shape
    use model_types, only: is_plate, is_plane_solid
    use model_loads, only: load_item_t, load_value_at, load_locate, LOAD_PRE_EPSI, &
        LOAD_PRE_EPSI_PLATE
    use number_limits, only: product_fits, magnitude_fits, MAX_STRAIN
    use element_gauss_families, only: gauss_rule_t, MAX_GAUSS_POINTS
    use element_plane, only: plane_law_t, plane_rigi_rule, plane_initial_strain_forces
    use element_plate, only: plate_local_frame
    use element_plate_fields, only: plate_user_turn, turn_plate_tensor
    use element_plate_initial_strains, only: plate_rigi_rule, plate_initial_strain_forces
    use model_plate_section, only: plate_section_t
    use assembly_system, only: structure_t, element_equations, MAX_ELEMENT_DOFS
    use assembly_plane_law, only: plane_cell_law
    use assembly_plate_section, only: plate_cell_section
    implicit none
    private

    public :: add_pre_epsi_forces

contains

    !> fext += factor * f0 of PRE_EPSI item `item` on cell c at instant t (module header).
    !>  st : out, a cell of the wrong kind, a value that fails or overflows (located at the
    !>       item's keyword), a degenerate cell or a missing section, naming the cell
    subroutine add_pre_epsi_forces(s, item, c, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: fe(MAX_ELEMENT_DOFS)
        integer(i4) :: eqs(MAX_ELEMENT_DOFS), n, j
        if (item%kind == LOAD_PRE_EPSI .and. .not. is_plane_solid(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, 'PRE_EPSI EPXX, EPYY, EPZZ, EPXY ' // &
                'apply to D_PLAN and C_PLAN cells, not to ' // cell_label(s%mesh, c, &
                item%group))
            return
        else if (item%kind == LOAD_PRE_EPSI_PLATE .and. .not. &
                 is_plate(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, 'PRE_EPSI EXX ... KXY apply to plate ' &
                // '(DKT) cells, not to ' // cell_label(s%mesh, c, item%group))
            return
        end if
        call element_equations(s, c, eqs, n)
        if (item%kind == LOAD_PRE_EPSI) then
            call plane_forces(s, item, c, t, factor, fe(1:n), st)
        else
            call plate_forces(s, item, c, t, factor, fe(1:n), st)
        end if
        if (st%failed()) return
        ! the forces times FONC_MULT are formed only when they fit (number_limits): a strain
        ! within MAX_STRAIN through a stiff law and a huge FONC_MULT can still overflow
        do j = 1, n
            if (eqs(j) <= 0) cycle
            if (.not. (product_fits(factor, fe(j)) .and. magnitude_fits(fext(eqs(j))))) then
                call set_error(st, STATUS_MODEL_ERROR, 'PRE_EPSI on ' // cell_label(s%mesh, &
                    c, item%group) // ': its nodal force ' // to_text(fe(j)) // ' times ' // &
                    to_text(factor) // ' (FONC_MULT) is beyond the range parasol computes ' // &
                    'in (about 1e301)')
                return
            end if
            fext(eqs(j)) = fext(eqs(j)) + factor * fe(j)
        end do
    end subroutine add_pre_epsi_forces

    ! The values of the item's slots 1..ns at the points (x(3, ng)) of a cell, located at
    ! the item on failure; absent slots are zero; each value times `factor` must not
    ! overflow.
    subroutine point_values(item, ns, t, factor, x, ng, v, st)
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: ns, ng
        real(dp), intent(in) :: t, factor, x(3, ng)
        real(dp), intent(out) :: v(ns, ng)
        type(status_t), intent(out) :: st
        integer(i4) :: g, k
        v = 0.0_dp
        do g = 1, ng
            do k = 1, ns
                if (.not. item%values(k)%given) cycle
                call load_value_at(item%values(k), item%kind, k, t, x(:, g), v(k, g), st)
                ! a strain (or curvature) is bounded, alone and times FONC_MULT, before
                ! D eps0 and the nodal forces are formed from it (number_limits MAX_STRAIN)
                if (st%ok() .and. .not. strain_fits(v(k, g), factor)) call set_error(st, &
                    st%code, 'PRE_EPSI: the value ' // to_text(v(k, g)) // ' times ' // &
                    to_text(factor) // ' (FONC_MULT) is beyond the strains parasol takes ' // &
                    '(|value| and |value x FONC_MULT| <= ' // to_text(MAX_STRAIN) // ')')
                call load_locate(item, k, st)
                if (st%failed()) return
            end do
        end do
    end subroutine point_values

    pure logical function strain_fits(value, factor)
        real(dp), intent(in) :: value, factor
        strain_fits = .false.
        if (abs(value) > MAX_STRAIN) return
        if (.not. product_fits(factor, value)) return
        strain_fits = abs(factor * value) <= MAX_STRAIN
    end function strain_fits

    ! Plane cell: eps0 (xx, yy, zz, xy engineering) at the RIGI points, f0 by the law.
    subroutine plane_forces(s, item, c, t, factor, fe, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(out) :: fe(:)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        type(plane_law_t) :: law
        real(dp) :: x(3, MAX_CELL_NODES), xg(3, MAX_GAUSS_POINTS), v(4, MAX_GAUSS_POINTS)
        real(dp) :: n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES), eps0(4, MAX_GAUSS_POINTS)
        integer(i4) :: ctype, nn, g, p0
        fe = 0.0_dp
        ctype = s%mesh%cell_type(c)
        nn = CELL_TYPE_NODES(ctype)
        p0 = s%mesh%cell_ptr(c)
        x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
        call plane_rigi_rule(ctype, rule, st)
        if (st%ok()) call plane_cell_law(s%mesh, s%model, s%materials, s%cara, c, law, st)
        if (st%failed()) then
            call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // st%message)
            return
        end if
        do g = 1, rule%n
            call cell_shape(ctype, rule%xi(1, g), rule%xi(2, g), n(1:nn), dn(:, 1:nn))
            xg(:, g) = matmul(x(:, 1:nn), n(1:nn))
        end do
        call point_values(item, 4, t, factor, xg(:, 1:rule%n), rule%n, v(:, 1:rule%n), st)
        if (st%failed()) return
        eps0(1:3, 1:rule%n) = v(1:3, 1:rule%n)
        eps0(4, 1:rule%n) = 2.0_dp * v(4, 1:rule%n)            ! EPXY: gamma_xy / 2
        call plane_initial_strain_forces(ctype, x(1:2, 1:nn), law, eps0(:, 1:rule%n), fe, st)
        if (st%failed()) call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // &
            st%message)
    end subroutine plane_forces

    ! Plate cell: N0, M0 at the RIGI points in Code_Aster's intrinsic frame, turned to the
    ! element's (plate_local_frame), f0 by element_plate_initial_strains.
    subroutine plate_forces(s, item, c, t, factor, fe, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(out) :: fe(:)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        type(plate_section_t) :: sec
        real(dp) :: x(3, 4), xy(2, 4), rot(3, 3), rot_ca(3, 3), n(4), dn(2, 4)
        real(dp) :: xg(3, MAX_GAUSS_POINTS), v(6, MAX_GAUSS_POINTS)
        real(dp) :: n0(3, MAX_GAUSS_POINTS), m0(3, MAX_GAUSS_POINTS), cs, sn, x_ca(3)
        integer(i4) :: nn, g, p0
        fe = 0.0_dp
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
        call plate_local_frame(x(:, 1:nn), nn, rot, xy(:, 1:nn), st)
        if (st%ok()) call intrinsic_frame(x(:, 1:nn), nn, rot, rot_ca)
        if (st%ok()) call plate_cell_section(s%mesh, s%materials, s%cara, c, rot_ca, sec, st)
        if (st%ok()) call plate_rigi_rule(nn, rule, st)
        ! the intrinsic x axis in the element's frame: x_ca = cs x + sn y
        x_ca = rot_ca(1, :)
        if (st%ok()) call plate_user_turn(rot, x_ca, cs, sn, st)
        if (st%failed()) then
            call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // st%message)
            return
        end if
        do g = 1, rule%n
            call cell_shape(merge(CELL_TRIA3, CELL_QUAD4, nn == 3), rule%xi(1, g), &
                rule%xi(2, g), n(1:nn), dn(:, 1:nn))
            xg(:, g) = matmul(x(:, 1:nn), n(1:nn))
        end do
        call point_values(item, 6, t, factor, xg(:, 1:rule%n), rule%n, v(:, 1:rule%n), st)
        if (st%failed()) return
        do g = 1, rule%n
            ! resultants in the intrinsic frame, then turned back to the element's (the
            ! inverse turn: -sn)
            n0(:, g) = turn_plate_tensor(cs, -sn, matmul(sec%dm, [v(1, g), v(2, g), &
                2.0_dp * v(3, g)]))
            m0(:, g) = turn_plate_tensor(cs, -sn, matmul(sec%df, [v(4, g), v(5, g), &
                2.0_dp * v(6, g)]))
        end do
        call plate_initial_strain_forces(x(:, 1:nn), nn, n0(:, 1:rule%n), m0(:, 1:rule%n), &
            fe, st)
        if (st%failed()) call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // &
            st%message)
    end subroutine plate_forces

    ! Code_Aster's intrinsic frame of a plate cell (rows x, y, normal): the element's for a
    ! triangle (dxtpgl: x along side 1-2); for a quadrangle (dxqpgl) x from the middle of
    ! side 4-1 to the middle of side 2-3, projected on the cell's plane (of normal rot(3, :),
    ! the same side as Code_Aster's).
    pure subroutine intrinsic_frame(x, nn, rot, rot_ca)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: x(3, nn), rot(3, 3)
        real(dp), intent(out) :: rot_ca(3, 3)
        real(dp) :: ex(3)
        rot_ca = rot
        if (nn /= 4) return
        ex = 0.5_dp * (x(:, 2) + x(:, 3)) - 0.5_dp * (x(:, 1) + x(:, 4))
        ex = ex - dot_product(ex, rot(3, :)) * rot(3, :)
        if (.not. norm2(ex) > 0.0_dp) return
        rot_ca(1, :) = ex / norm2(ex)
        rot_ca(2, :) = [rot(3, 2) * rot_ca(1, 3) - rot(3, 3) * rot_ca(1, 2), &
                        rot(3, 3) * rot_ca(1, 1) - rot(3, 1) * rot_ca(1, 3), &
                        rot(3, 1) * rot_ca(1, 2) - rot(3, 2) * rot_ca(1, 1)]
    end subroutine intrinsic_frame

end module assembly_pre_epsi

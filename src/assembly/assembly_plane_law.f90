!> The elastic law of a plane cell (D_PLAN, C_PLAN) in the global axes: what its stiffness
!> (assembly_system), its initial-strain forces (assembly_varc, PRE_EPSI) and its stresses
!> (element_fields) take.
!>  - ELAS: isotropic (element_plane plane_law_isotropic);
!>  - ELAS_FO: isotropic with its E and NU, as the plates take them (model_plate_section
!>    elas_fo_isotropic: functions of no parameter, DEFI_CONSTANTE; a function of the
!>    temperature is a located error, as the law is one per cell);
!>  - ELAS_ORTH: orthotropic in the material frame (L, T, N) that AFFE_CARA_ELEM MASSIF
!>    gives the cell (model_cara_elem: L turned by alpha about Z from global X, N = Z; the
!>    global frame without MASSIF), as Code_Aster's ELAS_ORTH on 2D solids (U4.43.01,
!>    matrHooke3d): the compliance on (L, T, N)
!>        S = [1/E_L, -NU_LT/E_L, -NU_LN/E_L; ., 1/E_T, -NU_TN/E_T; ., ., 1/E_N]
!>    (NU_LT/E_L = NU_TL/E_T), inverted, with the in-plane shear G_LT; turned to (x, y) by
!>    D = T^T D_LTN T, T the engineering-strain rotation; then D_PLAN keeps its in-plane
!>    block and C_PLAN condenses zz out (plane_law_from_d4).
!> E_N, NU_LN and NU_TN are needed (the out-of-plane restraint of D_PLAN, the condensation
!> of C_PLAN); G_LN and G_TN play no part in a plane element.
module assembly_plane_law
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text, real_e13
    use number_limits, only: MIN_MODULUS, MAX_MODULUS, MAX_POISSON
    use mesh_types, only: mesh_t
    use model_types, only: model_t, is_plane_strain
    use model_material, only: material_field_t, material_t, material_of_cell, has_behaviour, &
        behaviour_number
    use model_cara_elem, only: cara_elem_t, material_axis_angle
    use element_plane, only: plane_law_t, plane_law_isotropic, plane_law_from_d4
    use model_plate_section, only: elas_fo_isotropic
    implicit none
    private

    public :: plane_cell_law, orthotropic_plane_d4

    !> The numbers of ELAS_ORTH a plane element reads, in the order of orthotropic_plane_d4.
    character(len=5), parameter :: ORTH_KEYS(7) = ['E_L  ', 'E_T  ', 'E_N  ', 'NU_LT', &
        'NU_LN', 'NU_TN', 'G_LT ']

contains

    !> The plane law of cell c (module header).
    !>  st : out, STATUS_MODEL_ERROR (the caller names the cell): no material, no ELAS nor ELAS_ORTH, a
    !>       number ELAS_ORTH lacks, an orthotropic law that is not positive definite, a
    !>       MASSIF ORIG_AXE frame at the cell's centre
    subroutine plane_cell_law(mesh, model, materials, cara, c, law, st)
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        type(material_field_t), intent(in) :: materials
        type(cara_elem_t), intent(in) :: cara
        integer(i4), intent(in) :: c
        type(plane_law_t), intent(out) :: law
        type(status_t), intent(out) :: st
        real(dp) :: d4(4, 4), alpha, young, nu
        integer(i4) :: m
        m = material_of_cell(materials, c)
        if (m == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'no material (give CHAM_MATER)')
            return
        end if
        associate (mat => materials%materials(m))
            if (mat%has_elas) then
                call plane_law_isotropic(mat%elas%e, mat%elas%nu, &
                    is_plane_strain(model%element(c)), law, st)
            else if (has_behaviour(mat, 'ELAS_ORTH')) then
                call material_axis_angle(mesh, cara, c, alpha, st)
                if (st%ok()) call orthotropic_plane_d4(mat, alpha, d4, st)
                if (st%ok()) call plane_law_from_d4(d4, is_plane_strain(model%element(c)), &
                    law, st)
            else if (has_behaviour(mat, 'ELAS_FO')) then
                call elas_fo_isotropic(mat, young, nu, st)
                if (st%ok()) call plane_law_isotropic(young, nu, &
                    is_plane_strain(model%element(c)), law, st)
            else
                call set_error(st, STATUS_MODEL_ERROR, 'its material has neither ELAS, ' // &
                    'ELAS_FO nor ELAS_ORTH')
            end if
        end associate
    end subroutine plane_cell_law

    !> The 3D stiffness on (xx, yy, zz, xy engineering) of an ELAS_ORTH material whose L
    !> axis is turned by alpha (radians) about Z from global X (module header).
    !>  st : out, STATUS_MODEL_ERROR for a missing number, a modulus <= 0 or a compliance
    !>       that is not positive definite (Code_Aster refuses such a material)
    subroutine orthotropic_plane_d4(mat, alpha, d4, st)
        type(material_t), intent(in) :: mat
        real(dp), intent(in) :: alpha
        real(dp), intent(out) :: d4(4, 4)
        type(status_t), intent(out) :: st
        real(dp) :: v(7), s(3, 3), dl(4, 4), t(4, 4), det, c, sn
        integer(i4) :: k
        logical :: found
        d4 = 0.0_dp
        do k = 1, size(ORTH_KEYS)
            call behaviour_number(mat, 'ELAS_ORTH', trim(ORTH_KEYS(k)), v(k), found)
            if (.not. found) then
                call set_error(st, STATUS_MODEL_ERROR, 'its ELAS_ORTH gives no ' // &
                    trim(ORTH_KEYS(k)) // ', which a plane element needs (E_L, E_T, E_N, ' &
                    // 'NU_LT, NU_LN, NU_TN, G_LT)')
                return
            end if
        end do
        if (.not. (v(1) > 0.0_dp .and. v(2) > 0.0_dp .and. v(3) > 0.0_dp .and. &
                   v(7) > 0.0_dp)) then
            call set_error(st, STATUS_MODEL_ERROR, 'ELAS_ORTH needs E_L, E_T, E_N and ' // &
                'G_LT > 0')
            return
        end if
        ! bounded as ELAS's E (number_limits): the compliance is formed from 1 / E
        if (any(v([1, 2, 3, 7]) < MIN_MODULUS .or. v([1, 2, 3, 7]) > MAX_MODULUS) .or. &
            any(abs(v(4:6)) > MAX_POISSON)) then
            call set_error(st, STATUS_MODEL_ERROR, 'ELAS_ORTH: E_L, E_T, E_N and G_LT ' // &
                'must lie in [' // real_e13(MIN_MODULUS) // ', ' // real_e13(MAX_MODULUS) // &
                '] and |NU_LT|, |NU_LN|, |NU_TN| <= ' // real_e13(MAX_POISSON) // &
                ' (E_L ' // real_e13(v(1)) // ', E_T ' // real_e13(v(2)) // ', E_N ' // &
                real_e13(v(3)) // ', G_LT ' // real_e13(v(7)) // ')')
            return
        end if
        s = reshape([1.0_dp / v(1), -v(4) / v(1), -v(5) / v(1), &
                     -v(4) / v(1), 1.0_dp / v(2), -v(6) / v(2), &
                     -v(5) / v(1), -v(6) / v(2), 1.0_dp / v(3)], [3, 3])
        ! positive definite: the leading minors (Sylvester), relative to the diagonal
        det = s(1, 1) * (s(2, 2) * s(3, 3) - s(2, 3) * s(3, 2)) - s(1, 2) * (s(2, 1) * &
            s(3, 3) - s(2, 3) * s(3, 1)) + s(1, 3) * (s(2, 1) * s(3, 2) - s(2, 2) * s(3, 1))
        if (.not. (s(1, 1) * s(2, 2) - s(1, 2)**2 > 1.0e-12_dp * s(1, 1) * s(2, 2) .and. &
                   det > 1.0e-12_dp * s(1, 1) * s(2, 2) * s(3, 3))) then
            call set_error(st, STATUS_MODEL_ERROR, 'ELAS_ORTH (NU_LT = ' // to_text(v(4)) &
                // ', NU_LN = ' // to_text(v(5)) // ', NU_TN = ' // to_text(v(6)) // &
                ') is not positive definite: no elastic energy for some strain')
            return
        end if
        dl = 0.0_dp
        dl(1:3, 1:3) = inverse3(s, det)
        dl(4, 4) = v(7)
        ! strain on (L, T, N, LT) = t * strain on (x, y, z, xy), engineering shear
        c = cos(alpha)
        sn = sin(alpha)
        t = 0.0_dp
        t(1, :) = [c * c, sn * sn, 0.0_dp, c * sn]
        t(2, :) = [sn * sn, c * c, 0.0_dp, -c * sn]
        t(3, 3) = 1.0_dp
        t(4, :) = [-2.0_dp * c * sn, 2.0_dp * c * sn, 0.0_dp, c * c - sn * sn]
        d4 = matmul(transpose(t), matmul(dl, t))
        d4 = 0.5_dp * (d4 + transpose(d4))
    end subroutine orthotropic_plane_d4

    ! The inverse of a 3x3 matrix of determinant det (/= 0), by its cofactors.
    pure function inverse3(a, det) result(b)
        real(dp), intent(in) :: a(3, 3), det
        real(dp) :: b(3, 3)
        b(1, 1) = a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)
        b(1, 2) = a(1, 3) * a(3, 2) - a(1, 2) * a(3, 3)
        b(1, 3) = a(1, 2) * a(2, 3) - a(1, 3) * a(2, 2)
        b(2, 1) = a(2, 3) * a(3, 1) - a(2, 1) * a(3, 3)
        b(2, 2) = a(1, 1) * a(3, 3) - a(1, 3) * a(3, 1)
        b(2, 3) = a(1, 3) * a(2, 1) - a(1, 1) * a(2, 3)
        b(3, 1) = a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1)
        b(3, 2) = a(1, 2) * a(3, 1) - a(1, 1) * a(3, 2)
        b(3, 3) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
        b = b / det
    end function inverse3

end module assembly_plane_law

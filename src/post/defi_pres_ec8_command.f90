!> DEFI_PRES_EC8: the seismic pressure on the wall of a cylindrical tank (Eurocode 8-4 annex
!> A), a function of X, Y, Z, EP, RHO (functions/ec8_pressure_function), and with EVAL the
!> tables of its parts along a generatrix (LIST_H) or a radius of the bottom (LIST_R_FOND).
!> In the post layer because EVAL makes tables; its numbers are checked by the catalog
!> (catalog_functions).
module defi_pres_ec8_command
    use kinds, only: dp, i4
    use status, only: status_t
    use strings, only: to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use deck_value, only: value_t
    use run_context, only: run_context_t
    use ec8_tank_pressure, only: ec8_tank_t, ec8_parts_t, ec8_pressure_above_bottom
    use ec8_pressure_function, only: ec8_pressure_function_t
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_set_real, TABLE_REAL
    implicit none
    private

    !> The columns of an EVAL table, as Code_Aster's DEFI_PRES_EC8 names them.
    character(len=8), parameter :: EVAL_COLUMNS(11) = [character(len=8) :: 'H', 'R', &
        'THETA', 'PIR', 'PIF', 'PC1', 'PRV', 'PFV', 'PHYDR', 'PSURFLIB', 'PTOT']

    public :: run_defi_pres_ec8

contains

    !> DEFI_PRES_EC8(Z_FOND, RAYON, HAUT_EAU, RHO_EAU, ACCE_SP_H, ACCE_FLEX_H_N, ACCE_FLEX_V,
    !> ACCE_SP_V, ACCE_CONV_H, GRAVITE, PRES_SURF_LIBR, NEWMARK, EVAL) -> formule.
    !>  st : located, an EVAL occurrence (see eval_table)
    subroutine run_defi_pres_ec8(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(ec8_pressure_function_t), allocatable :: f
        character(len=:), allocatable :: newmark
        integer :: i
        allocate (f)
        associate (t => f%tank)
            call cmd%get_real('Z_FOND', t%z_bottom, st)
            if (st%ok()) call cmd%get_real('RAYON', t%radius, st)
            if (st%ok()) call cmd%get_real('HAUT_EAU', t%height, st)
            if (st%ok()) call cmd%get_real('RHO_EAU', t%rho, st)
            if (st%ok()) call cmd%get_real('ACCE_SP_H', t%a_rh, st)
            if (st%ok()) call cmd%get_real('ACCE_FLEX_H_N', t%a_fhn, st)
            if (st%ok()) call cmd%get_real('ACCE_FLEX_V', t%a_fv, st)
            if (st%ok()) call cmd%get_real('ACCE_SP_V', t%a_rv, st)
            if (st%ok()) call cmd%get_real('ACCE_CONV_H', t%a_c1, st)
            if (st%ok()) call cmd%get_real('GRAVITE', t%gravity, st)
            if (st%ok()) call cmd%get_real('PRES_SURF_LIBR', t%p_free, st)
            if (st%ok()) call cmd%get_text('NEWMARK', newmark, st)
            if (st%failed()) return
            t%newmark_sign = merge(-1.0_dp, 1.0_dp, newmark == 'PC-')
        end associate
        do i = 1, cmd%count('EVAL')
            call eval_table(ctx, cmd%occurrence('EVAL', i), i, f%tank, st)
            if (st%failed()) return
        end do
        call move_alloc(f, result)
    end subroutine run_defi_pres_ec8

    !> One EVAL occurrence: the parts of the pressure at the points of LIST_H (heights above
    !> the bottom, at r = RAYON) or of LIST_R_FOND (radii on the bottom), at the angle THETA
    !> (degrees), shell thickness LIST_EPAIS(k) and density RHO, into the table TABLE (columns
    !> EVAL_COLUMNS; above the free surface every part is 0 and PTOT = PRES_SURF_LIBR).
    !>  st : located, LIST_EPAIS not of the list's length (Code_Aster CHARGES7_18), a point
    !>       ec8_pressure_above_bottom refuses
    subroutine eval_table(ctx, occ, number, tank, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        integer, intent(in) :: number
        type(ec8_tank_t), intent(in) :: tank
        type(status_t), intent(out) :: st
        real(dp), parameter :: DEGREE = acos(-1.0_dp) / 180.0_dp
        real(dp), allocatable :: heights(:), radii(:), thickness(:)
        real(dp) :: rho_s, theta, row(size(EVAL_COLUMNS))
        character(len=:), allocatable :: key
        class(concept_t), allocatable :: made
        type(table_t), allocatable :: t
        type(ec8_parts_t) :: parts
        type(value_t) :: target
        integer :: k, c, column
        call occ%get_reals('LIST_EPAIS', thickness, st)
        if (st%ok()) call occ%get_real('RHO', rho_s, st)
        if (st%ok()) call occ%get_real('THETA', theta, st)
        if (st%failed()) return
        if (occ%has('LIST_H')) then
            key = 'LIST_H'
            call occ%get_reals(key, heights, st)
            if (st%failed()) return
            allocate (radii(size(heights)), source=tank%radius)
        else
            key = 'LIST_R_FOND'
            call occ%get_reals(key, radii, st)
            if (st%failed()) return
            allocate (heights(size(radii)), source=0.0_dp)
        end if
        if (size(thickness) /= size(heights)) then
            call occ%error_at('LIST_EPAIS', 'EVAL occurrence ' // to_text(int(number, i4)) // &
                ': LIST_EPAIS has ' // to_text(size(thickness, kind=i4)) // ' value(s), ' // &
                key // ' ' // to_text(size(heights, kind=i4)) // ' (one thickness per point)', st)
            return
        end if
        allocate (t)
        call table_init(t)
        do c = 1, size(EVAL_COLUMNS)
            call table_add_column(t, trim(EVAL_COLUMNS(c)), TABLE_REAL, column, st)
        end do
        call table_add_rows(t, size(heights))
        do k = 1, size(heights)
            call ec8_pressure_above_bottom(tank, radii(k) * cos(theta * DEGREE), &
                radii(k) * sin(theta * DEGREE), heights(k), thickness(k), rho_s, parts, st)
            if (st%failed()) then
                call occ%error_at(key, 'point ' // to_text(int(k, i4)) // ': ' // st%message, st)
                return
            end if
            row = [heights(k), radii(k), theta, parts%pir, parts%pif, parts%pc1, parts%prv, &
                   parts%pfv, parts%phydr, tank%p_free, parts%total]
            do c = 1, size(EVAL_COLUMNS)
                call table_set_real(t, c, k, row(c), st)
            end do
            if (st%failed()) return
        end do
        target = occ%get_value('TABLE')
        call move_alloc(t, made)
        call ctx%produce(target%s, made, st)
    end subroutine eval_table

end module defi_pres_ec8_command

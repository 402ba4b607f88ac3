!> DEFI_PRES_EC8: the seismic pressure on the wall of a cylindrical tank (Eurocode 8-4 annex
!> A), a function of X, Y, Z, EP, RHO (ec8_pressure_function). Its numbers are checked by the
!> catalog (catalog_functions); EVAL, Code_Aster's tables of the pressure's parts along a
!> generatrix or the bottom, is refused (parasol does not build them).
module defi_pres_ec8_command
    use kinds, only: dp
    use status, only: status_t
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use run_context, only: run_context_t
    use ec8_pressure_function, only: ec8_pressure_function_t
    implicit none
    private

    public :: run_defi_pres_ec8

contains

    !> DEFI_PRES_EC8(Z_FOND, RAYON, HAUT_EAU, RHO_EAU, ACCE_SP_H, ACCE_FLEX_H_N, ACCE_FLEX_V,
    !> ACCE_SP_V, ACCE_CONV_H, GRAVITE, PRES_SURF_LIBR, NEWMARK) -> formule.
    !>  st : located, EVAL given (not supported)
    subroutine run_defi_pres_ec8(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(ec8_pressure_function_t), allocatable :: f
        character(len=:), allocatable :: newmark
        if (cmd%count('EVAL') > 0) then
            call cmd%error_at('EVAL', 'EVAL (tables of the parts of the pressure) is not ' // &
                'supported by parasol: evaluate the function itself, fonc(X, Y, Z, EP, RHO)', st)
            return
        end if
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
        call move_alloc(f, result)
        if (ctx%checking) return
    end subroutine run_defi_pres_ec8

end module defi_pres_ec8_command

!> The loads of an analysis: the EXCIT occurrences (a char_meca or char_cine_meca and an
!> optional FONC_MULT) and what they give at an instant: the imposed values and the
!> external forces (MECA_STATIQUE, STAT_NON_LINE).
module analysis_excitation
    use kinds, only: dp, i4
    use status, only: status_t, set_error
    use model_loads, only: load_set_t
    use function_concept, only: function_concept_t, param_binding_t
    use assembly_system, only: structure_t
    use assembly_loads, only: impose_values, add_external_forces
    use assembly_varc, only: add_varc_forces
    implicit none
    private

    !> One EXCIT occurrence: a char_meca's load set and an optional FONC_MULT of INST.
    !> Both pointers refer to concepts owned by the run context (not freed here).
    type, public :: excitation_t
        type(load_set_t), pointer :: load => null()
        class(function_concept_t), pointer :: fonc_mult => null()
    end type excitation_t

    public :: loads_at, recorded_internal_forces

contains

    !> Imposed values into u and external forces at t, over all EXCIT occurrences, and the
    !> forces of the thermal strains of AFFE_VARC (assembly_varc, elem's).
    !>  st : out, function evaluation errors (FONC_MULT included), temperature errors
    subroutine loads_at(s, excit, t, u, fext, st)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        real(dp), intent(in) :: t
        real(dp), intent(inout) :: u(:)
        real(dp), intent(out) :: fext(:)
        type(status_t), intent(out) :: st
        type(param_binding_t) :: binding
        real(dp) :: factor
        integer(i4) :: k
        fext = 0.0_dp
        do k = 1, size(excit)
            factor = 1.0_dp
            if (associated(excit(k)%fonc_mult)) then
                call excit(k)%fonc_mult%bind(['INST'], binding)
                call excit(k)%fonc_mult%evaluate(binding, [t], factor, st)
                if (st%failed()) then
                    call set_error(st, st%code, 'EXCIT/FONC_MULT: ' // st%message)
                    return
                end if
            end if
            call impose_values(s, excit(k)%load, t, factor, u, st)
            if (st%ok()) call add_external_forces(s, excit(k)%load, t, factor, fext, st)
            if (st%failed()) return
        end do
        call add_varc_forces(s, t, fext, st)
    end subroutine loads_at

    !> The nodal internal forces a result records (FORC_NODA) at t: f_int = K u less the
    !> forces of the thermal strains (which loads_at puts into f_ext), i.e. int B^T sigma
    !> with sigma = D (eps - eps_th), as Code_Aster's FORC_NODA. Without AFFE_VARC: f_int.
    !>  st : out, temperature errors (as loads_at)
    subroutine recorded_internal_forces(s, t, fint, forc, st)
        type(structure_t), intent(in) :: s
        real(dp), intent(in) :: t, fint(:)
        real(dp), intent(out) :: forc(:)
        type(status_t), intent(out) :: st
        forc = 0.0_dp
        call add_varc_forces(s, t, forc, st)
        forc = fint - forc
    end subroutine recorded_internal_forces

end module analysis_excitation

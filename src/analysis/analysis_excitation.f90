!> The loads of an analysis: the EXCIT occurrences (a char_meca or char_cine_meca and an
!> optional FONC_MULT) and what they give at an instant: the imposed values and the
!> external forces (MECA_STATIQUE, STAT_NON_LINE). A follower occurrence (STAT_NON_LINE
!> TYPE_CHARGE='SUIV') gives its forces on the current geometry (follower_loads_at), which
!> the Newton loop re-evaluates at every iteration; loads_at leaves them out.
module analysis_excitation
    use kinds, only: dp, i4
    use status, only: status_t, set_error
    use model_loads, only: load_set_t
    use function_concept, only: function_concept_t, param_binding_t
    use assembly_system, only: structure_t
    use assembly_loads, only: impose_values, add_external_forces, add_follower_forces
    use assembly_varc, only: add_varc_forces
    implicit none
    private

    !> One EXCIT occurrence: a char_meca's load set and an optional FONC_MULT of INST.
    !> Both pointers refer to concepts owned by the run context (not freed here).
    type, public :: excitation_t
        type(load_set_t), pointer :: load => null()
        class(function_concept_t), pointer :: fonc_mult => null()
        logical :: follower = .false.        !< TYPE_CHARGE='SUIV'
    end type excitation_t

    public :: loads_at, recorded_internal_forces, follower_loads_at, has_followers

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
        real(dp) :: factor
        integer(i4) :: k
        fext = 0.0_dp
        do k = 1, size(excit)
            call multiplier_at(excit(k), t, factor, st)
            if (st%failed()) return
            call impose_values(s, excit(k)%load, t, factor, u, st)
            if (st%ok() .and. .not. excit(k)%follower) &
                call add_external_forces(s, excit(k)%load, t, factor, fext, st)
            if (st%failed()) return
        end do
        call add_varc_forces(s, t, fext, st)
    end subroutine loads_at

    !> Adds the forces of the follower occurrences at t on the geometry X + u to fext.
    !>  st : out, function evaluation errors (FONC_MULT included), a degenerate current edge
    subroutine follower_loads_at(s, excit, t, u, fext, st)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        real(dp), intent(in) :: t, u(:)
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: factor
        integer(i4) :: k
        do k = 1, size(excit)
            if (.not. excit(k)%follower) cycle
            call multiplier_at(excit(k), t, factor, st)
            if (st%ok()) call add_follower_forces(s, excit(k)%load, t, factor, u, fext, st)
            if (st%failed()) return
        end do
    end subroutine follower_loads_at

    !> Whether an occurrence is a follower load.
    pure logical function has_followers(excit)
        type(excitation_t), intent(in) :: excit(:)
        integer(i4) :: k
        has_followers = .false.
        do k = 1, size(excit)
            if (excit(k)%follower) has_followers = .true.
        end do
    end function has_followers

    ! FONC_MULT at t (1 without it).
    subroutine multiplier_at(e, t, factor, st)
        type(excitation_t), intent(in) :: e
        real(dp), intent(in) :: t
        real(dp), intent(out) :: factor
        type(status_t), intent(out) :: st
        type(param_binding_t) :: binding
        factor = 1.0_dp
        if (.not. associated(e%fonc_mult)) return
        call e%fonc_mult%bind(['INST'], binding)
        call e%fonc_mult%evaluate(binding, [t], factor, st)
        if (st%failed()) call set_error(st, st%code, 'EXCIT/FONC_MULT: ' // st%message)
    end subroutine multiplier_at

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

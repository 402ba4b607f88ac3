!> Globalisation of the contact Newton: the line search on the contact energy along a
!> tangent correction (contact_line_search: with it full Newton cannot cycle), and the
!> verdict "no equilibrium" when the load cannot be carried (doc/analysis.md, "Diagnosis").
module contact_globalisation
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_NO_EQUILIBRIUM
    use strings, only: to_text, real_e13
    use assembly_system, only: structure_t, assembly_map_t, spring_lines, scatter_free
    use element_dis_choc, only: choc_line_t
    use contact_line_search, only: step_choice_t, choose_step, any_crossing
    use analysis_solver, only: pivot_diagnosis_t, PIVOT_REGULAR, PIVOT_FREE
    use analysis_log, only: analysis_log_t, log_add
    use newton_state, only: newton_state_t, step_pivots_t, MATRIX_ELASTIC, MATRIX_NONE, &
        MATRIX_TANGENT
    use contact_status, only: spring_law, spring_group
    use newton_factor, only: factor_status
    use factor_reuse, only: tangent_product
    use two_level_solver, only: from_hat
    implicit none
    private

    !> Consecutive iterations with a free tangent (and a residual that does not decrease)
    !> after which full Newton declares that the load cannot be carried.
    integer(i4), parameter :: FREE_ITERATIONS_MAX = 2
    !> "Does not decrease": the residual stays above this fraction of the previous one.
    real(dp), parameter :: NO_DECREASE_RATIO = 0.999_dp

    public :: line_search, check_no_equilibrium

contains

    !> The step along the tangent correction p (contact_line_search): 1 unless springs
    !> change status on it and the full step fails Armijo's condition on the energy.
    !>  b : in, the residual the correction was solved for (f_ext - f_int, free equations)
    !>  ph : in, the correction, in the solver's hat coordinates (two_level_solver)
    !>  alpha : out, the step; full : out, alpha = 1
    subroutine line_search(s, map, state, b, ph, log, alpha, full, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        real(dp), intent(in) :: b(:), ph(:)
        type(analysis_log_t), intent(inout) :: log
        real(dp), intent(out) :: alpha
        logical, intent(out) :: full
        type(status_t), intent(out) :: st
        type(choc_line_t), allocatable :: lines(:)
        real(dp), allocatable :: q(:), p(:)
        type(step_choice_t) :: choice
        character(len=16) :: buf
        real(dp) :: scale
        alpha = 1.0_dp
        full = .true.
        if (size(map%springs) == 0 .or. .not. state%fac_valid .or. size(ph) == 0) return
        allocate (p(size(ph)))
        call from_hat(state%solver, ph, p)
        ! energies in units of scale^2 (the search does not depend on it): no overflow
        scale = max(maxval(abs(state%u)), maxval(abs(p)))
        if (.not. scale > 0.0_dp) return
        allocate (lines(size(map%springs)))
        call scatter_free(map, p, state%du)
        call spring_lines(s, map, state%u, state%du, scale, lines, st)
        if (st%failed() .or. .not. any_crossing(lines)) return
        ! the curvature p^T K_S p of the tangent at u (element by element, as the residual)
        allocate (q(size(p)))
        call tangent_product(s, map, state, state%closed, ph / scale, q, st)
        if (st%failed()) return
        call choose_step(lines, -dot_product(p / scale, b / scale), dot_product(ph / scale, q), &
            choice)
        if (.not. choice%damped) return
        alpha = choice%alpha
        full = .false.
        state%damped = state%damped + 1
        write (buf, '(f8.6)') alpha
        call log_add(log, '  line search: step ' // trim(adjustl(buf)) // ' of the ' // &
            'correction (' // to_text(choice%n_crossing) // ' springs change status on it; ' &
            // trim(merge('the full step raises the energy           ', &
                          'the full step lowers the energy too little', &
                          choice%energy_full > 0.0_dp)) // ')')
    end subroutine line_search

    !> No equilibrium (the load cannot be carried, the iterate is not converged), declared
    !> when
    !>  - every DIS_CHOC spring is open after an elastic-matrix correction and the residual
    !>    does not decrease, or
    !>  - the tangent was free for FREE_ITERATIONS_MAX consecutive iterations and the last
    !>    one changed no spring status (that contact status is a mechanism the load drives)
    !>    or did not decrease the residual, or
    !>  - (ELASTIQUE) the residual does not decrease, no status changed, and the tangent of
    !>    that status (factored here, only then) is free.
    subroutine check_no_equilibrium(s, map, state, use, iter, changed, piv, resi_maxi, &
                                    previous_maxi, t, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        integer(i4), intent(in) :: use, iter, changed
        type(step_pivots_t), intent(in) :: piv
        real(dp), intent(in) :: resi_maxi, previous_maxi, t
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        logical :: stalled, all_open, stays_free
        type(pivot_diagnosis_t) :: diag
        if (size(state%closed) == 0) return
        stalled = resi_maxi >= NO_DECREASE_RATIO * previous_maxi
        all_open = use == MATRIX_ELASTIC .and. iter >= 1 .and. .not. any(state%closed)
        stays_free = piv%n_free >= FREE_ITERATIONS_MAX .and. (changed == 0 .or. stalled)
        diag%kind = PIVOT_REGULAR
        if (use == MATRIX_ELASTIC .and. iter >= 1 .and. stalled .and. changed == 0 .and. &
            .not. all_open .and. .not. stays_free) then
            ! ELASTIQUE never factors the tangent: a stalled residual with a stable contact
            ! status is no equilibrium if that status leaves the structure free
            state%factored = MATRIX_NONE
            call factor_status(s, map, state, state%u, state%closed, .false., diag, st)
            if (st%failed()) return
            state%factored = MATRIX_TANGENT
            ! free as the elastic matrix is: the structure's own motion, not the springs'
            stays_free = diag%kind == PIVOT_FREE .and. state%elastic_kind /= PIVOT_FREE
        end if
        if (.not. ((all_open .and. stalled) .or. stays_free)) return
        text = 'INST ' // real_e13(t) // ': no equilibrium: ' // &
            to_text(count(.not. state%closed, kind=i4)) // ' of ' // &
            to_text(size(state%closed)) // ' ' // spring_law(s, map) // ' springs are open (' // &
            spring_group(s, map) // ') and the structure is left free'
        if (allocated(piv%free_where)) then
            text = text // ': rigid motion at ' // piv%free_where
        else
            ! ELASTIQUE never factors the tangent: factor it once here to name the motion
            if (diag%kind == PIVOT_REGULAR) then
                state%factored = MATRIX_NONE
                call factor_status(s, map, state, state%u, state%closed, .false., diag, st)
                if (st%ok()) state%factored = MATRIX_TANGENT
            end if
            if (st%failed()) return
            if (diag%kind == PIVOT_FREE) text = text // ': rigid motion at ' // diag%where
        end if
        call set_error(st, STATUS_NO_EQUILIBRIUM, text // '; the residual ' // &
            real_e13(resi_maxi) // ' N no longer decreases')
    end subroutine check_no_equilibrium

end module contact_globalisation

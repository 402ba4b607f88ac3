!> The one factor of STAT_NON_LINE and its pivot rules (doc/analysis.md, "Diagnosis"): the
!> matrix of an iteration is assembled and factored unless the factor already holds its
!> contact status; a free tangent with springs open takes the elastic matrix for that
!> correction; an ill-conditioned tangent is judged if its status converges; any other
!> flagged matrix is reported; with the singularity check off, held equations are judged
!> by the load they carry after the solve.
module newton_factor
    use kinds, only: dp, i4
    use status, only: status_t
    use strings, only: to_text, real_e13
    use sparse_matrix, only: sym_add_element
    use direct_solver, only: solver_options_t, check_disabled
    use assembly_system, only: structure_t, assembly_map_t, assemble_stiffness
    use analysis_solver, only: pivot_diagnosis_t, factor_and_classify, report_pivots, &
        solve_held, accumulate_pivots, modes_support, PIVOT_REGULAR, &
        PIVOT_FREE, PIVOT_ILL_CONDITIONED, PIVOT_UNKNOWN
    use analysis_log, only: analysis_log_t, log_add
    use newton_state, only: newton_state_t, step_pivots_t, MATRIX_NONE, MATRIX_ELASTIC, &
        MATRIX_TANGENT
    use contact_status, only: status_of, factor_holds, status_difference
    use two_level_solver, only: add_block_product
    use progress, only: progress_update
    implicit none
    private

    public :: drop, factor_and_diagnose, factor_status, matrix_for_iteration, solve_correction

contains

    !> Marks matrix `which` as no longer factored (the next use assembles and factors it).
    subroutine drop(state, which)
        type(newton_state_t), intent(inout) :: state
        integer(i4), intent(in) :: which
        if (state%factored == which) state%factored = MATRIX_NONE
        if (which == MATRIX_TANGENT) state%tangent_stale = .true.
    end subroutine drop

    !> Assembles and factors the matrix `use` unless the solver's factor already holds it
    !> (one matrix and one factor per analysis: switching between the elastic and the
    !> tangent matrix refactors); diag is PIVOT_REGULAR when the factor was reused
    !> (state%elastic_kind keeps the class of the elastic matrix). A prediction's tangent is
    !> the one at the start of the step, before the imposed-value increments (Code_Aster
    !> nmprta: zero increment). With DIS_CHOC springs only, a factor is kept with its
    !> contact status and reused for any matrix of that status.
    subroutine factor_and_diagnose(s, map, state, use, prediction, t, log, diag, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        integer(i4), intent(in) :: use
        logical, intent(in) :: prediction
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(pivot_diagnosis_t), intent(out) :: diag
        type(status_t), intent(out) :: st
        state%refactored = .false.
        if (use == state%factored) return
        ! a matrix of the status the factor holds is never factored again (DIS_CHOC only:
        ! its tangent is a function of the status; the elastic matrix = all closed)
        if (state%by_status .and. factor_holds(state, status_of(state, use))) then
            state%factored = use
            if (use == MATRIX_ELASTIC .and. state%elastic_kind == PIVOT_UNKNOWN) &
                state%elastic_kind = state%fac_kind
            return
        end if
        state%factored = MATRIX_NONE
        if (use == MATRIX_TANGENT .and. prediction) then
            call factor_status(s, map, state, state%u_start, status_of(state, use), .false., &
                diag, st, log)
        else
            call factor_status(s, map, state, state%u, status_of(state, use), &
                use == MATRIX_ELASTIC, diag, st, log)
        end if
        if (st%ok() .and. use == MATRIX_ELASTIC) state%elastic_kind = diag%kind
        if (st%failed()) return
        state%factored = use
        ! a free matrix is an error (its message gives its pivot), an overshooting
        ! iterate's tangent that the elastic matrix replaces, or held equations (check
        ! off, named in the .mess): no figure of the matrices the answer was solved with
        if (diag%kind /= PIVOT_FREE) call accumulate_pivots(diag, state%pivots)
        if (diag%kind /= PIVOT_REGULAR .and. .not. check_disabled(state%solver%options)) &
            call log_add(log, '  INST ' // real_e13(t) // ': pivot ' // &
            trim(merge('free           ', 'ill-conditioned', diag%kind == PIVOT_FREE)) // &
            ' at ' // diag%where)
        state%refactored = .true.
        state%factorizations = state%factorizations + 1
    end subroutine factor_and_diagnose

    !> Assembles the matrix of contact status `closed` in place and factors it
    !> (factor_and_classify); the factor's status, class, digits and usability are
    !> recorded. The tangent is assembled at u_asm (springs at their status there, which is
    !> state%closed) and, with DIS_CHOC springs only, the springs whose status in `closed`
    !> differs get their closed matrix added or removed, so a kept tangent of an earlier
    !> status is rebuilt as it was.
    !>  u_asm   : in, the displacements to assemble at (state%u, or state%u_start for a
    !>            prediction)
    !>  elastic : in, the elastic matrix (closed must then be all .true.)
    subroutine factor_status(s, map, state, u_asm, closed, elastic, diag, st, log)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        real(dp), intent(in) :: u_asm(:)
        logical, intent(in) :: closed(:), elastic
        type(pivot_diagnosis_t), intent(out) :: diag
        type(status_t), intent(out) :: st
        type(analysis_log_t), intent(inout), optional :: log
        integer(i4), allocatable :: active(:), signs(:)
        real(dp), allocatable :: ksr(:, :)
        integer(i4) :: k, b, m
        state%fac_valid = .false.
        call progress_update(state%solver%progress, 'assembly of the ' // &
            trim(merge('elastic', 'tangent', elastic)) // ' matrix')
        call assemble_stiffness(s, map, u_asm, elastic, state%matrix, st, state%linear, &
            state%history)
        if (st%failed()) return
        call modes_support(s, map, state%solver, u_asm, elastic, ksr, st, state%history)
        if (st%failed()) return
        if (.not. elastic .and. state%by_status) then
            call status_difference(closed, state%closed, active, signs)
            do k = 1, size(active)
                b = active(k)
                m = state%blocks%sizes(b)
                call sym_add_element(state%matrix, state%blocks%eqs(1:m, b), &
                    real(signs(k), dp) * state%blocks%k(1:m, 1:m, b), st)
                if (st%failed()) return
                ! the same change in K_s R
                if (size(ksr) > 0) call add_block_product(state%solver, &
                    state%blocks%eqs(1:m, b), real(signs(k), dp) * &
                    state%blocks%k(1:m, 1:m, b), ksr)
            end do
        end if
        call factor_and_classify(s, map, state%matrix, state%solver, ksr, diag, st, &
            state%held, log)
        if (st%failed()) return
        state%fac_valid = .true.
        state%fac_closed = closed
        state%fac_kind = diag%kind
        state%fac_usable = diag%kind /= PIVOT_FREE .and. size(state%held%equations) == 0
        state%fac_digits = diag%digits
        state%fac_digits_low = diag%digits
        if (.not. diag%digits_known) state%fac_digits = max(diag%digits, &
            real(diag%nprec, dp))
        state%solves_since_factor = 0.0_dp
        state%last_updated_solves = 0
    end subroutine factor_status

    !> The matrix of one iteration, with the pivot rules of doc/analysis.md:
    !>  - tangent with springs open and a FREE pivot (an overshooting iterate, or no
    !>    equilibrium): this correction uses the elastic matrix (every spring closed,
    !>    regular when the supports exist) and piv%free_now says so; unless the elastic
    !>    matrix is free too: then the free motion is the structure's own (a plate's
    !>    in-plane motion on vertical springs), not the open springs', and the tangent is
    !>    used with its pivot reported like any other. The elastic matrix is the same for the
    !>    whole analysis, so its class is learnt once (state%elastic_kind); with one factor
    !>    per analysis, learning it when it turns out free costs one refactorization of the
    !>    tangent;
    !>  - tangent with springs open and an ILL-CONDITIONED pivot: used; judged at
    !>    convergence (newton_step) if the converged status is the same;
    !>  - otherwise a flagged matrix goes to report_pivots (STATUS_SINGULAR or a warning).
    !> With the singularity check off (METHODE='MUMPS', NPREC < 0) the solver holds the free
    !> pivots and nothing is reported here: a free tangent (held equations) with springs open
    !> follows the first rule all the same, except that when the elastic matrix holds
    !> equations too, the load decides after the solve (solve_correction): the structure's
    !> own free motion is unloaded, the overshoot's is loaded.
    !>  use        : inout, MATRIX_TANGENT may become MATRIX_ELASTIC
    !>  prediction : in, iteration 0: a tangent is assembled at the start of the step
    subroutine matrix_for_iteration(s, map, state, use, prediction, options, t, log, piv, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        integer(i4), intent(inout) :: use
        logical, intent(in) :: prediction
        type(solver_options_t), intent(in) :: options
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(step_pivots_t), intent(inout) :: piv
        type(status_t), intent(out) :: st
        type(pivot_diagnosis_t) :: diag, elastic_diag, again
        logical :: open_springs, tangent_factored, check_off
        call factor_and_diagnose(s, map, state, use, prediction, t, log, diag, st)
        if (st%failed()) return
        open_springs = .not. all(state%closed)
        check_off = check_disabled(options)
        piv%free_now = .false.
        if (diag%kind == PIVOT_FREE .and. use == MATRIX_TANGENT .and. open_springs) then
            tangent_factored = state%refactored
            if (state%elastic_kind == PIVOT_UNKNOWN) then
                call factor_and_diagnose(s, map, state, MATRIX_ELASTIC, prediction, t, log, &
                    elastic_diag, st)
                if (st%failed()) return
                state%refactored = tangent_factored .or. state%refactored
            end if
            if (state%elastic_kind == PIVOT_FREE) then
                if (.not. check_off) call report_pivots(diag, options, t, log, st)
                if (st%failed()) return
                ! the factor may hold the elastic matrix just classified: back to the tangent
                tangent_factored = state%refactored
                call factor_and_diagnose(s, map, state, MATRIX_TANGENT, prediction, t, log, &
                    again, st)
                state%refactored = tangent_factored .or. state%refactored
            else
                call log_add(log, '  tangent matrix free at ' // diag%where // ' with ' // &
                    to_text(count(.not. state%closed, kind=i4)) // ' springs open: ' // &
                    'correction with the elastic matrix')
                call drop(state, MATRIX_TANGENT)
                piv%free_now = .true.
                piv%free_where = diag%where
                use = MATRIX_ELASTIC
                if (state%factored /= MATRIX_ELASTIC) then
                    call factor_and_diagnose(s, map, state, use, prediction, t, log, &
                        elastic_diag, st)
                    if (st%failed()) return
                    state%refactored = tangent_factored .or. state%refactored
                end if
                if (elastic_diag%kind /= PIVOT_REGULAR .and. .not. check_off) &
                    call report_pivots(elastic_diag, options, t, log, st)
            end if
        else if (check_off) then
            ! nothing else is reported: held equations are judged after the solve
        else if (diag%kind == PIVOT_ILL_CONDITIONED .and. use == MATRIX_TANGENT .and. &
                 open_springs) then
            call log_add(log, '  tangent matrix ill-conditioned at ' // diag%where // &
                ' (judged if this contact status converges)')
            piv%ill = diag
            piv%ill_closed = state%closed
        else if (diag%kind /= PIVOT_REGULAR) then
            call report_pivots(diag, options, t, log, st)
        end if
    end subroutine matrix_for_iteration

    !> Solves one correction with the factor (solve_held). With the singularity check off
    !> (METHODE='MUMPS', NPREC < 0) and a tangent kept although it holds equations with
    !> springs open (matrix_for_iteration: the elastic matrix holds equations too, e.g.
    !> SSNL130 A's in-plane plate on vertical springs), the load tells the free motions
    !> apart: the structure's own is unloaded, while a loaded held equation is the
    !> overshooting iterate (or no equilibrium) of the pivot rules, and this correction is
    !> solved again with the elastic matrix, as with the check on (piv%free_now counts it
    !> for check_no_equilibrium). Without that, the overshoot would stop as a loaded free
    !> equation. A loaded held equation of the elastic matrix stops the analysis there.
    !>  use : inout, MATRIX_TANGENT may become MATRIX_ELASTIC
    !>  r   : inout, right-hand side (free equations) in, solution out
    subroutine solve_correction(s, map, state, use, prediction, options, r, t, log, piv, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        integer(i4), intent(inout) :: use
        logical, intent(in) :: prediction
        type(solver_options_t), intent(in) :: options
        real(dp), intent(inout) :: r(:)
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(step_pivots_t), intent(inout) :: piv
        type(status_t), intent(out) :: st
        real(dp), allocatable :: rhs(:)
        character(len=:), allocatable :: loaded_at
        type(pivot_diagnosis_t) :: diag
        logical :: tangent_factored
        if (.not. (check_disabled(options) .and. use == MATRIX_TANGENT .and. &
                   .not. all(state%closed))) then
            call solve_held(s, map, state%matrix, state%solver, state%held, r, t, log, st)
            return
        end if
        rhs = r
        call solve_held(s, map, state%matrix, state%solver, state%held, r, t, log, st, &
            loaded_at)
        if (st%failed() .or. .not. allocated(loaded_at)) return
        call log_add(log, '  tangent matrix free at ' // loaded_at // ' with ' // &
            to_text(count(.not. state%closed, kind=i4)) // ' springs open: correction ' // &
            'with the elastic matrix')
        tangent_factored = state%refactored
        call drop(state, MATRIX_TANGENT)
        piv%free_now = .true.
        piv%free_where = loaded_at
        use = MATRIX_ELASTIC
        call factor_and_diagnose(s, map, state, use, prediction, t, log, diag, st)
        if (st%failed()) return
        state%refactored = tangent_factored .or. state%refactored
        r = rhs
        call solve_held(s, map, state%matrix, state%solver, state%held, r, t, log, st)
    end subroutine solve_correction

end module newton_factor

!> Factor reuse in the contact Newton (doc/analysis.md, "Contact Newton"): the correction of
!> an iteration, a tangent solved through the factor of another contact status by conjugate
!> gradients preconditioned with it (low_rank_update) while that costs fewer solves than a
!> factorization, a tangent solved with its own factor refined the same way, the products
!> with a tangent computed element by element, and the NPREC judgement of a converged
!> status that was only solved through another status's factor.
module factor_reuse
    use kinds, only: dp, i4
    use status, only: status_t
    use strings, only: to_text, real_short
    use direct_solver, only: check_disabled, effective_nprec, DIGITS_ALL_LOST
    use assembly_system, only: structure_t, assembly_map_t, linear_product, body_product, &
        gather_free, scatter_free
    use two_level_solver, only: to_hat, from_hat, hat_body_part, hat_anchors_from, &
        modes_kept_apart
    use low_rank_update, only: pcg_work_t, pcg_begin, pcg_continue, pcg_options_t, &
        pcg_report_t, PCG_CONVERGED, PCG_BREAKDOWN
    use analysis_solver, only: pivot_diagnosis_t, report_pivots, solve_held, real_digits, &
        FREE_PIVOT_DIGITS, PIVOT_REGULAR
    use analysis_log, only: analysis_log_t, log_add
    use newton_state, only: newton_state_t, newton_options_t, step_pivots_t, &
        criterion_tolerance, MATRIX_TANGENT, MATRIX_ELASTIC, BY_REUSED_FACTOR, &
        BY_NEW_FACTOR, BY_UPDATED_FACTOR
    use contact_status, only: status_of, factor_holds, status_difference
    use newton_factor, only: drop, factor_and_diagnose, matrix_for_iteration, solve_correction
    use progress, only: progress_update
    implicit none
    private

    !> A tangent solve (conjugate gradients with a factor) stops when its residual is
    !> below this fraction of the convergence tolerance (RESI_GLOB_RELA times its
    !> denominator, or RESI_GLOB_MAXI): the next Newton residual is then converged if the
    !> contact status is right ...
    real(dp), parameter :: PCG_TOLERANCE_FRACTION = 0.1_dp
    !> ... or, while the status still changed in the last iteration, below this fraction
    !> of the residual it corrects: an inexact Newton step (Eisenstat & Walker, SIAM J. Sci.
    !> Comput. 17, 1996) spends no accuracy on a status that is about to change.
    real(dp), parameter :: PCG_FORCING = 1.0e-2_dp
    !> Solves that refine a direct solve with its own factor, at most (each gains the
    !> digits the factorization kept, ~5 of 16 here; three reach the Newton tolerance).
    integer(i4), parameter :: REFINE_MAX = 10
    !> A tangent solved only through another status's factor is factored at convergence
    !> to judge NPREC when the bound on its digits lost (the factor's digits plus log10 of
    !> the Ritz condition estimate, low_rank_update) is within this margin of NPREC: Ritz
    !> values estimate the extreme eigenvalues from inside.
    real(dp), parameter :: RITZ_DIGITS_MARGIN = 0.5_dp

    public :: correction, tangent_product, judge_converged_tangent

contains

    !> The correction of one iteration: r = K^-1 r for the matrix `use` (module header).
    !> A tangent is solved through the factor of another status when that is allowed and
    !> cheaper (updated_correction), else factored if needed (matrix_for_iteration, with
    !> its pivot rules) and solved with its own factor, refined (refined_correction); the
    !> elastic matrix, a flagged factor, every matrix with the singularity check off and
    !> every matrix of an analysis with DIS_CONTACT springs by a direct solve
    !> (solve_correction).
    !>  prediction : in, iteration 0 (matrix_for_iteration)
    !>  settled : in, solve to the convergence tolerance (no inexact Newton): the last
    !>            iteration changed no spring status, or a status came back
    !>  r       : inout, the residual on the free equations in, the correction out
    !>  mode    : out, BY_REUSED_FACTOR, BY_NEW_FACTOR or BY_UPDATED_FACTOR
    subroutine correction(s, map, state, use, prediction, options, t, settled, log, piv, r, &
                          mode, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        integer(i4), intent(inout) :: use
        logical, intent(in) :: prediction
        type(newton_options_t), intent(in) :: options
        real(dp), intent(in) :: t
        logical, intent(in) :: settled
        type(analysis_log_t), intent(inout) :: log
        type(step_pivots_t), intent(inout) :: piv
        real(dp), intent(inout) :: r(:)
        integer(i4), intent(out) :: mode
        type(status_t), intent(out) :: st
        real(dp) :: target
        logical :: iterative, done
        mode = BY_REUSED_FACTOR
        piv%free_now = .false.          ! an updated solve is no free-tangent correction
        state%iterative_solve = .false.
        ! tangents, and the elastic matrix once its pivots are known regular (an elastic
        ! prediction after a tangent step: it differs from the factored tangent by the open
        ! springs)
        iterative = state%by_status .and. .not. check_disabled(options%factor) .and. &
            (use == MATRIX_TANGENT .or. (use == MATRIX_ELASTIC .and. &
            state%elastic_kind == PIVOT_REGULAR))
        if (iterative) then
            target = pcg_target(options, map, state, r, settled)
            if (.not. factor_holds(state, status_of(state, use))) then
                call updated_correction(s, map, state, status_of(state, use), target, log, &
                    piv, r, done, st)
                if (st%failed()) return
                if (done) then
                    mode = BY_UPDATED_FACTOR
                    state%iterative_solve = .true.
                    return
                end if
            end if
        end if
        call matrix_for_iteration(s, map, state, use, prediction, options%factor, t, log, &
            piv, st)
        if (st%failed()) return
        if (state%refactored) mode = BY_NEW_FACTOR
        call progress_update(options%progress, 'solve')
        if (iterative .and. state%fac_usable .and. factor_holds(state, status_of(state, use))) &
            then
            call refined_correction(s, map, state, status_of(state, use), target, t, log, r, st)
            state%iterative_solve = .true.
        else
            call solve_correction(s, map, state, use, prediction, options%factor, r, t, log, &
                piv, st)
            state%solves = state%solves + 1
        end if
    end subroutine correction

    !> The linear tolerance of a tangent solve: PCG_TOLERANCE_FRACTION of the convergence
    !> tolerance, in newtons, at the current iterate; while the contact status moves, no
    !> less than PCG_FORCING times max|r| (inexact Newton).
    real(dp) function pcg_target(options, map, state, r, settled) result(target)
        type(newton_options_t), intent(in) :: options
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(in) :: state
        real(dp), intent(in) :: r(:)
        logical, intent(in) :: settled
        target = PCG_TOLERANCE_FRACTION * criterion_tolerance(options, map, state)
        if (.not. settled .and. size(r) > 0) target = max(target, PCG_FORCING * maxval(abs(r)))
    end function pcg_target

    !> The matrix of status `closed` (a tangent, or the elastic matrix: all closed) through
    !> the factor of another status
    !> (low_rank_update), when the factor is regular and the solves since it was made,
    !> with this one's expected count (the last one's), stay below a factorization's cost
    !> (a rent-or-buy rule: at most twice the cheaper of the two). Not done (done =
    !> .false., r untouched) when that budget is spent, or CG does not converge within it,
    !> breaks down, or its Ritz values leave fewer than FREE_PIVOT_DIGITS - the factor's
    !> digits: the tangent may be singular, its factorization will tell.
    subroutine updated_correction(s, map, state, closed, target, log, piv, r, done, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        logical, intent(in) :: closed(:)
        real(dp), intent(in) :: target
        type(analysis_log_t), intent(inout) :: log
        type(step_pivots_t), intent(inout) :: piv
        real(dp), intent(inout) :: r(:)
        logical, intent(out) :: done
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: active(:), signs(:)
        real(dp), allocatable :: x(:)
        type(pcg_options_t) :: opts
        type(pcg_report_t) :: rep
        real(dp) :: budget, bound, condition
        character(len=:), allocatable :: why
        done = .false.
        if (.not. (state%fac_valid .and. state%fac_usable)) return
        budget = state%factor_cost - state%solves_since_factor
        if (budget < real(max(1_i4, state%last_updated_solves), dp)) return
        call status_difference(closed, state%fac_closed, active, signs)
        opts%max_iterations = max(1_i4, int(budget, i4))
        opts%tolerance = target
        call tangent_solve(s, map, state, closed, r, opts, x, rep, st)
        if (st%failed()) return
        state%solves = state%solves + rep%iterations
        state%solves_since_factor = state%solves_since_factor + real(rep%iterations, dp)
        state%last_updated_solves = rep%iterations
        ! digits of the Ritz condition estimate (no lower Ritz value above 0: singular)
        condition = DIGITS_ALL_LOST
        if (rep%ritz_min > 0.0_dp .and. rep%ritz_max > 0.0_dp) condition = &
            max(log10(rep%ritz_max) - log10(rep%ritz_min), 0.0_dp)
        bound = state%fac_digits + condition
        why = ''
        if (rep%outcome == PCG_BREAKDOWN) then
            why = 'the tangent is not positive definite'
        else if (rep%outcome /= PCG_CONVERGED) then
            why = 'no convergence in ' // to_text(rep%iterations) // ' solves'
        else if (state%fac_digits_low + condition >= FREE_PIVOT_DIGITS) then
            why = 'it may be singular (' // real_digits(state%fac_digits_low + condition) // &
                ' digits)'
        end if
        if (len(why) > 0) then
            call log_add(log, '  ' // to_text(size(active)) // ' springs differ from the ' // &
                'factored status; updated solve not used: ' // why)
            return
        end if
        r = x
        done = .true.
        state%updated = state%updated + 1
        ! the largest bound seen for this status (short CG runs see fewer Ritz values)
        if (allocated(piv%updated_closed)) then
            if (all(piv%updated_closed .eqv. closed)) bound = max(bound, &
                piv%updated_bound)
        end if
        piv%updated_closed = closed
        piv%updated_bound = bound
        call log_add(log, '  ' // to_text(size(active)) // ' springs differ from the ' // &
            'factored status: ' // to_text(rep%iterations) // ' solves (PCG), residual ' // &
            real_short(rep%residual) // ' N, digits bound ' // real_digits(bound))
    end subroutine updated_correction

    !> q = K_S p on the free equations, K_S the tangent of contact status `closed`: every
    !> cell but the DIS_CHOC springs element by element (linear_product, the arithmetic
    !> of the residual, so CG can reach the tolerance the residual is judged by), plus the
    !> closed matrix of each spring closed in `closed`. With rigid modes kept apart
    !> (two_level_solver) p and q are in its hat coordinates: the plates and plane solids
    !> see only the part of p that deforms them (hat_body_part), the springs all of it
    !> (from_hat), and the anchors get R^T of the springs' forces alone (R^T K_b = 0).
    subroutine tangent_product(s, map, state, closed, p, q, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        logical, intent(in) :: closed(:)
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: q(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: x(:), qs(:)
        if (.not. modes_kept_apart(state%solver)) then
            call scatter_free(map, p, state%du)
            call linear_product(s, map, state%linear, state%du, state%work, st)
            if (st%failed()) return
            call gather_free(map, state%work, q)
            call add_closed_blocks(state, closed, p, q)
            return
        end if
        allocate (x(size(p)), qs(size(p)))
        call from_hat(state%solver, p, x)
        call scatter_free(map, x, state%du)
        call linear_product(s, map, state%linear, state%du, state%work, st, support_only=.true.)
        if (st%failed()) return
        call gather_free(map, state%work, qs)
        call add_closed_blocks(state, closed, x, qs)
        call hat_body_part(state%solver, p, x)
        call scatter_free(map, x, state%du)
        call body_product(s, map, state%linear, state%du, state%work, st)
        if (st%failed()) return
        call gather_free(map, state%work, q)
        q = qs + q
        call to_hat(state%solver, qs, x)
        call hat_anchors_from(state%solver, x, q)
    end subroutine tangent_product

    !> q <- q + the closed matrix of every spring closed in `closed` times p.
    subroutine add_closed_blocks(state, closed, p, q)
        type(newton_state_t), intent(in) :: state
        logical, intent(in) :: closed(:)
        real(dp), intent(in) :: p(:)
        real(dp), intent(inout) :: q(:)
        integer(i4) :: b, i, j, m, ei, ej
        real(dp) :: t
        do b = 1, size(closed, kind=i4)
            if (.not. closed(b)) cycle
            m = state%blocks%sizes(b)
            do i = 1, m
                ei = state%blocks%eqs(i, b)
                if (ei == 0) cycle
                t = 0.0_dp
                do j = 1, m
                    ej = state%blocks%eqs(j, b)
                    if (ej > 0) t = t + state%blocks%k(i, j, b) * p(ej)
                end do
                q(ei) = q(ei) + t
            end do
        end do
    end subroutine add_closed_blocks

    !> K_S x = b by CG preconditioned with the factor (low_rank_update), the products
    !> with K_S by tangent_product: the factor's status may be S (refinement) or another.
    !>  b : in, the right-hand side (original coordinates)
    !>  x : out, the solution in the solver's hat coordinates (two_level_solver)
    subroutine tangent_solve(s, map, state, closed, b, options, x, report, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        logical, intent(in) :: closed(:)
        real(dp), intent(in) :: b(:)
        type(pcg_options_t), intent(in) :: options
        real(dp), allocatable, intent(out) :: x(:)
        type(pcg_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        type(pcg_work_t) :: work
        real(dp), allocatable :: bh(:)
        logical :: more
        allocate (bh(size(b)))
        call to_hat(state%solver, b, bh)
        call pcg_begin(work, state%solver, bh, options, report, more, st)
        do while (more .and. st%ok())
            call tangent_product(s, map, state, closed, work%p, work%q, st)
            if (st%ok()) call pcg_continue(work, state%solver, report, more, st)
        end do
        call move_alloc(work%x, x)
    end subroutine tangent_solve

    !> A matrix of status `closed` (tangent or elastic) solved with its own factor, refined
    !> by CG preconditioned with that factor (at most REFINE_MAX solves, to `target`); a
    !> direct solve if CG breaks down (an indefinite or singular factor).
    !>  r : inout, the residual in, the correction out
    subroutine refined_correction(s, map, state, closed, target, t, log, r, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        logical, intent(in) :: closed(:)
        real(dp), intent(in) :: target, t
        type(analysis_log_t), intent(inout) :: log
        real(dp), intent(inout) :: r(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: x(:)
        type(pcg_options_t) :: opts
        type(pcg_report_t) :: rep
        opts%max_iterations = REFINE_MAX
        opts%tolerance = target
        call tangent_solve(s, map, state, closed, r, opts, x, rep, st)
        if (st%failed()) return
        state%solves = state%solves + rep%iterations
        if (rep%outcome /= PCG_BREAKDOWN) then
            r = x
            return
        end if
        call solve_held(s, map, state%matrix, state%solver, state%held, r, t, log, st)
        state%solves = state%solves + 1
    end subroutine refined_correction

    !> At convergence: an ill-conditioned tangent of the converged contact status is the
    !> model's own (report_pivots). A converged status whose tangent was only solved
    !> through another status's factor is factored here when the bound on its digits lost
    !> (piv%updated_bound + RITZ_DIGITS_MARGIN) passes NPREC, and judged the same way.
    subroutine judge_converged_tangent(s, map, state, options, piv, t, log, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        type(newton_options_t), intent(in) :: options
        type(step_pivots_t), intent(in) :: piv
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        type(pivot_diagnosis_t) :: diag
        integer(i4) :: use
        if (allocated(piv%ill_closed)) then
            if (all(piv%ill_closed .eqv. state%closed)) then
                call report_pivots(piv%ill, options%factor, t, log, st)
                if (st%failed()) return
            end if
        end if
        if (.not. allocated(piv%updated_closed)) return
        if (.not. all(piv%updated_closed .eqv. state%closed)) return
        if (factor_holds(state, state%closed)) return
        if (piv%updated_bound + RITZ_DIGITS_MARGIN <= real(effective_nprec(options%factor), &
            dp)) return
        if (allocated(state%judged_closed)) then
            if (all(state%judged_closed .eqv. state%closed)) then
                ! the same matrix was judged in an earlier step: the same verdict
                if (state%judged%kind /= PIVOT_REGULAR .and. .not. &
                    check_disabled(options%factor)) &
                    call report_pivots(state%judged, options%factor, t, log, st)
                return
            end if
        end if
        call log_add(log, '  the converged status''s tangent was solved through another ' // &
            'status''s factor (digits bound ' // real_digits(piv%updated_bound) // &
            ', NPREC ' // to_text(effective_nprec(options%factor)) // '): factored to judge it')
        state%tangent_closed = state%closed
        state%tangent_stale = .false.
        call drop(state, MATRIX_TANGENT)
        state%tangent_stale = .false.
        use = MATRIX_TANGENT
        call factor_and_diagnose(s, map, state, use, .false., t, log, diag, st)
        if (st%failed()) return
        state%judged_closed = state%closed
        state%judged = diag
        if (diag%kind /= PIVOT_REGULAR .and. .not. check_disabled(options%factor)) &
            call report_pivots(diag, options%factor, t, log, st)
    end subroutine judge_converged_tangent

end module factor_reuse

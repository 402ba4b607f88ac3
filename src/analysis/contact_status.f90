!> Contact statuses of the DIS_CHOC / DIS_CONTACT springs and their changes: the status a
!> matrix holds, the springs by which two statuses differ, the springs that change at zero
!> gap (immaterial to the equilibrium), a status met again in a step (cycling), and the
!> names of springs and their group in messages.
module contact_status
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_NO_CONVERGENCE
    use strings, only: to_text, real_e13, real_short
    use mesh_types, only: cell_name, cell_group_name, cells_of_group, n_cell_groups
    use assembly_system, only: structure_t, assembly_map_t, contact_history_t, is_dis_contact, &
        spring_lines
    use element_dis_choc, only: choc_line_t
    use analysis_log, only: analysis_log_t, log_add
    use newton_state, only: newton_state_t, newton_options_t, MATRIX_TANGENT, criterion_tolerance
    implicit none
    private

    !> Springs named in a list before it is abbreviated.
    integer(i4), parameter :: LIST_NAMES = 6
    !> A spring that changed status in the last iteration while it would carry at most
    !> this fraction of the convergence tolerance (in newtons) when closed sits at zero
    !> gap: its status is immaterial to the equilibrium (the force is nil either way) and
    !> does not keep the iteration from converging (a spring exactly at zero gap otherwise
    !> flips with the round-off of every correction: the linear load P = p (b - y) on a
    !> rigid plate puts the whole row y = b at zero gap).
    real(dp), parameter :: ZERO_GAP_FORCE_FRACTION = 1.0e-2_dp

    public :: status_of, factor_holds, status_difference, changes_at_zero_gap, detect_cycle, &
        changed_names, spring_law, spring_group, warn_unpressed_dis_contact

contains

    !> The contact status of matrix `use`: every spring closed for the elastic matrix (the
    !> closed and the bilateral spring matrices are the same), the tangent's own otherwise.
    pure function status_of(state, use) result(closed)
        type(newton_state_t), intent(in) :: state
        integer(i4), intent(in) :: use
        logical :: closed(size(state%closed))
        closed = .true.
        if (use == MATRIX_TANGENT) closed = state%tangent_closed
    end function status_of

    !> Whether the factor holds the matrix of contact status `closed`.
    pure logical function factor_holds(state, closed)
        type(newton_state_t), intent(in) :: state
        logical, intent(in) :: closed(:)
        factor_holds = state%fac_valid
        if (factor_holds) factor_holds = all(state%fac_closed .eqv. closed)
    end function factor_holds

    !> The springs whose status differs between two contact statuses, with the sign of
    !> their closed matrix in the difference now - before (+1 closed in `now` only).
    pure subroutine status_difference(now, before, active, signs)
        logical, intent(in) :: now(:), before(:)
        integer(i4), allocatable, intent(out) :: active(:), signs(:)
        integer(i4) :: k, n
        n = count(now .neqv. before, kind=i4)
        allocate (active(n), signs(n))
        n = 0
        do k = 1, size(now, kind=i4)
            if (now(k) .eqv. before(k)) cycle
            n = n + 1
            active(n) = k
            signs(n) = merge(1_i4, -1_i4, now(k))
        end do
    end subroutine status_difference

    !> Whether every spring whose status changed since `before` would carry at most
    !> ZERO_GAP_FORCE_FRACTION of the convergence tolerance when closed (at zero gap: its
    !> status does not matter); the .mess says so when it does.
    subroutine changes_at_zero_gap(s, map, state, options, before, log, settled, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        type(newton_options_t), intent(in) :: options
        logical, intent(in) :: before(:)
        type(analysis_log_t), intent(inout) :: log
        logical, intent(out) :: settled
        type(status_t), intent(out) :: st
        type(choc_line_t), allocatable :: lines(:)
        real(dp) :: scale, limit
        integer(i4) :: k
        settled = .false.
        scale = maxval(abs(state%u))
        if (.not. scale > 0.0_dp) scale = 1.0_dp
        allocate (lines(size(map%springs)))
        state%du = 0.0_dp
        call spring_lines(s, map, state%u, state%du, scale, lines, st)
        if (st%failed()) return
        limit = ZERO_GAP_FORCE_FRACTION * criterion_tolerance(options, map, state)
        do k = 1, size(lines, kind=i4)
            if (state%closed(k) .eqv. before(k)) cycle
            ! force * scale > limit, formed on the side that cannot overflow
            if (scale >= 1.0_dp) then
                if (lines(k)%force > limit / scale) return
            else
                if (lines(k)%force * scale > limit) return
            end if
        end do
        settled = .true.
        call log_add(log, '  ' // to_text(count(state%closed .neqv. before, kind=i4)) // &
            ' spring(s) changed status at zero gap (a force below ' // real_short(limit) // &
            ' N either way): ' // changed_names(s, map, before, state%closed))
    end subroutine changes_at_zero_gap

    !> A contact status met again in the step (history(:, k) is the status at the start of
    !> iteration k; `now` the status after iteration iter). After full steps solved to the
    !> convergence tolerance (`tight`), the iterates themselves repeat (a full Newton step
    !> from a status lands on the same point whatever it starts from): that is a cycle,
    !> logged, and for full Newton (REAC_ITER = 1) STATUS_NO_CONVERGENCE naming the
    !> springs; the line search makes it a round-off accident (module header). After a
    !> damped step it is no cycle; after inexact corrections (inexact Newton) neither, but
    !> the next ones are solved tightly (solve_tightly).
    subroutine detect_cycle(s, map, options, history, full, tight, iter, changed, now, t, &
                            log, solve_tightly, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_options_t), intent(in) :: options
        logical, intent(in) :: history(:, 0:), full(0:), tight(0:), now(:)
        integer(i4), intent(in) :: iter, changed
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        logical, intent(inout) :: solve_tightly
        type(status_t), intent(out) :: st
        integer(i4) :: repeat_of
        character(len=:), allocatable :: seen
        repeat_of = cycle_start(history, now)
        if (repeat_of < 0 .or. changed == 0) return
        seen = 'the start of the step'
        if (repeat_of > 0) seen = 'iteration ' // to_text(repeat_of - 1)
        if (.not. all(full(repeat_of:iter))) then
            call log_add(log, '  contact status of iteration ' // to_text(iter) // &
                ' repeats ' // seen // ' after a damped step (lower energy: no cycle)')
            return
        end if
        if (.not. all(tight(repeat_of:iter))) then
            call log_add(log, '  contact status of iteration ' // to_text(iter) // &
                ' repeats ' // seen // ' after inexact corrections: solved to the ' // &
                'convergence tolerance from now on')
            solve_tightly = .true.
            return
        end if
        call log_add(log, '  contact status of iteration ' // to_text(iter) // &
            ' repeats ' // seen // ' (cycling)')
        if (.not. options%matrix_elastic .and. options%reac_iter == 1) then
            call set_error(st, STATUS_NO_CONVERGENCE, 'INST ' // real_e13(t) // &
                ': the contact status cycles (iteration ' // to_text(iter) // &
                ' repeats ' // seen // '); springs ' // &
                'changing: ' // changed_names(s, map, history(:, iter), now))
        end if
    end subroutine detect_cycle

    !> Earliest iteration whose status set equals `now`, except the last one; -1 if none.
    pure integer(i4) function cycle_start(history, now) result(k)
        logical, intent(in) :: history(:, 0:), now(:)
        integer(i4) :: j
        k = -1
        do j = 0, int(ubound(history, 2), i4) - 1
            if (all(history(:, j) .eqv. now)) then
                k = j
                return
            end if
        end do
    end function cycle_start

    !> Names of the springs whose status differs between before and after (optionally only
    !> those that ended closed / open); the list is cut after LIST_NAMES names.
    function changed_names(s, map, before, after, want_closed) result(text)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        logical, intent(in) :: before(:), after(:)
        logical, intent(in), optional :: want_closed
        character(len=:), allocatable :: text
        integer(i4) :: k, n
        n = 0
        text = ''
        do k = 1, size(before)
            if (before(k) .eqv. after(k)) cycle
            if (present(want_closed)) then
                if (after(k) .neqv. want_closed) cycle
            end if
            n = n + 1
            if (n <= LIST_NAMES) then
                if (n > 1) text = text // ' '
                text = text // cell_name(s%mesh, map%springs(k))
            end if
        end do
        if (n > LIST_NAMES) text = text // ' ... (' // to_text(n) // ' in all)'
        if (n == 0) text = 'none'
    end function changed_names

    !> The springs' law for messages: DIS_CHOC, DIS_CONTACT, or "contact" when mixed.
    function spring_law(s, map) result(text)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        character(len=:), allocatable :: text
        integer(i4) :: k, n_contact
        n_contact = 0
        do k = 1, size(map%springs)
            if (is_dis_contact(s, map%springs(k))) n_contact = n_contact + 1
        end do
        text = 'DIS_CHOC'
        if (n_contact == size(map%springs) .and. n_contact > 0) text = 'DIS_CONTACT'
        if (n_contact > 0 .and. n_contact < size(map%springs)) text = 'contact'
    end function spring_law

    !> The cell group made of exactly the contact springs ("group G"), else the first
    !> spring's name ("from cell C").
    function spring_group(s, map) result(text)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        character(len=:), allocatable :: text
        integer(i4), allocatable :: cells(:)
        integer(i4) :: g, k
        logical :: all_in
        do g = 1, n_cell_groups(s%mesh)
            cells = cells_of_group(s%mesh, g)
            if (size(cells) /= size(map%springs)) cycle
            all_in = .true.
            do k = 1, size(map%springs)
                all_in = all_in .and. any(cells == map%springs(k))
            end do
            if (all_in) then
                text = 'group ' // cell_group_name(s%mesh, g)
                return
            end if
        end do
        text = 'from cell ' // cell_name(s%mesh, map%springs(1))
    end function spring_group

    !> A DIS_CONTACT spring that does not start pressed (DIST_1 + DIST_2 <= its length, so
    !> F- = 0 before the first step) never gets a force in a static analysis: Code_Aster's
    !> law only follows a compression it already has (element_dis_contact). parasol computes
    !> the same, and says so once in the .mess, naming the first such spring.
    subroutine warn_unpressed_dis_contact(s, map, history, log)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(contact_history_t), intent(in) :: history
        type(analysis_log_t), intent(inout) :: log
        integer(i4) :: k, n, first
        n = 0
        first = 0
        do k = 1, size(map%springs)
            if (.not. is_dis_contact(s, map%springs(k))) cycle
            if (history%fn0(k) < 0.0_dp) cycle
            n = n + 1
            if (first == 0) first = map%springs(k)
        end do
        if (n == 0) return
        call log_add(log, 'warning: ' // to_text(n) // ' DIS_CONTACT spring(s) (first ' // &
            cell_name(s%mesh, first) // ') do not start pressed (DIST_1 + DIST_2 <= their ' // &
            'length): in a static analysis the DIS_CONTACT law, as Code_Aster integrates it, ' // &
            'never gives them a force; DIS_CHOC, or DIST_1 + DIST_2 above the length, would')
    end subroutine warn_unpressed_dis_contact

end module contact_status

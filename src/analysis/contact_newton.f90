!> STAT_NON_LINE core: quasi-static time stepping with DIS_CHOC / DIS_CONTACT springs (design.md,
!> "STAT_NON_LINE"; Code_Aster U4.51.03 for the NEWTON/CONVERGENCE keywords).
!>
!> Per step (instant t+): imposed values and external forces at t+; then iterations
!> u <- u + K^-1 (f_ext - f_int(u)) on the free equations, iteration 0 being the prediction.
!> K is the "elastic" matrix (every contact spring closed and bilateral) or the tangent at
!> the current spring status; there is one assembled matrix and one factor per analysis, so
!> switching between the two refactors (drop marks the factor stale).
!>   prediction: PREDICTION (default: the MATRICE choice, as Code_Aster); a tangent
!>               prediction, assembled at the start of the step, is rebuilt every REAC_INCR
!>               steps (1), otherwise reused;
!>   corrections: MATRICE = ELASTIQUE: the elastic matrix; TANGENTE: rebuilt every REAC_ITER
!>               iterations (REAC_ITER = 0, the default: the prediction's matrix is kept).
!>   With DIS_CHOC springs every correction and every tangent prediction use the tangent
!>   rebuilt at that point, whatever MATRICE/REAC_ITER/REAC_INCR say (Code_Aster,
!>   MECANONLINE5_5); DIS_CONTACT springs follow NEWTON as given.
!> Convergence: RESI_GLOB_RELA = max|f_ext - f_int| (free equations) / max(max|f_ext|,
!> max|reactions|) <= tolerance (and RESI_GLOB_MAXI = the numerator <= its value if given)
!> and no spring changed status in the last iteration. A zero denominator (no load) switches
!> to the absolute criterion (RESI_GLOB_MAXI, or the RESI_GLOB_RELA value in N), and the
!> .mess says so. Failures: STATUS_NO_CONVERGENCE (ITER_GLOB_MAXI exceeded, or a contact
!> status cycle under full Newton), STATUS_NO_EQUILIBRIUM (the load cannot be carried: the
!> structure stays free with springs open), STATUS_SINGULAR (a free equation in a matrix
!> that should be regular, or ill-conditioning beyond NPREC of the converged contact
!> status); see doc/analysis.md "Diagnosis" and check_no_equilibrium. An intermediate
!> iterate whose tangent is free takes the elastic matrix for its correction. Plate and
!> plane forces are accumulated from the increments (internal_forces_incremental).
!>
!> Tangent corrections (doc/analysis.md, "Contact Newton"), when every contact spring is
!> DIS_CHOC (its tangent is then a function of the contact status): the factor is kept
!> with the contact status it was assembled with, and a matrix of the same status is never
!> factored again. A tangent of another status differs from it by the closed matrices of
!> the springs that changed (low-rank): it is solved by conjugate gradients preconditioned
!> with the factor (low_rank_update) while that costs fewer solves than a factorization
!> (factor_cost_in_solves), and factored otherwise; a tangent solve with its own factor is
!> refined by the same iteration. Every tangent correction is then damped, when a full step
!> would raise the energy, by a line search on the contact energy (contact_line_search):
!> with it full Newton cannot cycle; a status met again after full steps only is still
!> reported as cycling, naming the springs. DIS_CONTACT springs (a tangent that depends on
!> the step's history) keep the plain full Newton: every rebuilt tangent is factored.
!>
!> This module holds the step loop; the rest is split by concern: newton_state (options,
!> state, convergence criteria), contact_status (statuses and their changes), newton_factor
!> (the one factor and its pivot rules), factor_reuse (tangents through another status's
!> factor, PCG, refinement), contact_globalisation (line search, no equilibrium),
!> newton_log (the .mess rows), analysis_solver (the solver as the analyses use it).
module contact_newton
    use kinds, only: dp, i4
    use status, only: status_t, set_error, clear_status, STATUS_NO_CONVERGENCE, &
        STATUS_NO_EQUILIBRIUM
    use strings, only: to_text, real_e13, real_short
    use assembly_system, only: structure_t, assembly_map_t, build_assembly_map, &
        internal_forces_incremental, contact_history_start, contact_history_update, &
        is_dis_contact, spring_matrices, contact_history_t, gather_free, scatter_free, &
        spring_block_width
    use sparse_matrix, only: sym_move
    use solver_factory, only: assembly_renum
    use low_rank_update, only: block_set_init, factor_cost_in_solves
    use assembly_loads, only: mark_imposed
    use analysis_result, only: result_concept_t, result_init, result_store, result_reserve
    use spring_results, only: store_spring_fields
    use analysis_log, only: analysis_log_t, log_add, log_flush
    use analysis_solver, only: open_solver, log_numbering, solver_diagnostics_line, &
        solve_held, answer_digits, real_digits
    use analysis_excitation, only: excitation_t, loads_at, recorded_internal_forces, &
        follower_loads_at, has_followers
    use analysis_relations, only: prepare_relations, relations_at
    use assembly_relations, only: elimination_t
    use newton_state, only: newton_options_t, newton_summary_t, newton_state_t, &
        step_pivots_t, residual_measures, criteria_met, absolute_tol, prediction_is_elastic, &
        DEFAULT_RESI_GLOB_RELA, DEFAULT_ITER_GLOB_MAXI, MATRIX_ELASTIC, &
        MATRIX_TANGENT, BY_UPDATED_FACTOR
    use contact_status, only: changes_at_zero_gap, detect_cycle, changed_names, spring_law, &
        warn_unpressed_dis_contact
    use newton_factor, only: drop
    use factor_reuse, only: correction, judge_converged_tangent
    use contact_globalisation, only: line_search, check_no_equilibrium
    use residual_line_search, only: line_search_options_t, secant_search_t, search_start, &
        search_next, search_trial, search_result
    use newton_log, only: history_text, step_line, seconds_text, iteration_row
    use two_level_solver, only: from_hat, hat_body_part
    use progress, only: wall_seconds, progress_note, progress_update, progress_done, &
        progress_context
    implicit none
    private

    !> The state a failed step is taken back to (DEFI_LIST_INST/ECHEC DECOUPE): the
    !> displacements and forces (the plate/plane forces accumulated by increments
    !> included), the contact statuses and the DIS_CONTACT history. The factor and what it
    !> holds stay as they are: they describe the one matrix, whatever the step.
    type :: step_start_t
        real(dp), allocatable :: u(:), fint(:), fext(:), flin(:), fn(:)
        logical, allocatable :: closed(:)
        type(contact_history_t) :: history
    end type step_start_t

    !> Most steps an analysis may have once failed steps are cut (DEFI_LIST_INST/ECHEC):
    !> SUBD_PAS and SUBD_NIVEAU are the deck's, and nested cuts of failing steps multiply;
    !> beyond this the step is not cut and its error stops the run (issue 13: no count
    !> read from a deck may grow an allocation or a run without bound).
    integer(i4), parameter :: MAX_CUT_STEPS = 100000

    public :: stat_non_line, newton_options_t, newton_summary_t, excitation_t, loads_at, &
        residual_measures, solver_diagnostics_line, DEFAULT_RESI_GLOB_RELA, &
        DEFAULT_ITER_GLOB_MAXI

contains

    !> Runs STAT_NON_LINE.
    !>  s        : in, the structure (s%choc marks the DIS_CHOC cells)
    !>  excit    : in, the EXCIT occurrences
    !>  times    : in, times(1) = INST_INIT, times(2:) the ends of the steps (increasing)
    !>  options  : in, NEWTON/CONVERGENCE/SOLVEUR
    !>  res      : out, evol_noli: NUME_ORDRE 0 = the state at INST_INIT (zero, or u0),
    !>             then each step
    !>  log      : inout, .mess lines (renumbering, Newton table per step)
    !>  summary  : out, iterations and factorizations per step
    !>  st       : out, see the module header; the result holds the converged steps
    !>  u0       : in, optional, the initial displacements (ETAT_INIT), imposed values included
    subroutine stat_non_line(s, excit, times, options, res, log, summary, st, u0)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        real(dp), intent(in) :: times(:)
        type(newton_options_t), intent(in) :: options
        type(result_concept_t), intent(out) :: res
        type(analysis_log_t), intent(inout) :: log
        type(newton_summary_t), intent(out) :: summary
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: u0(:)   !< (n_equations) ETAT_INIT's displacements
        type(assembly_map_t) :: map
        type(newton_state_t) :: state
        logical, allocatable :: imposed(:), rigid(:)
        type(elimination_t) :: elim
        integer(i4) :: k, step, n_eq
        real(dp), allocatable :: targets(:), forc(:)
        character(len=:), allocatable :: text
        integer(i4), allocatable :: levels(:)
        real(dp) :: t_prev
        type(step_start_t) :: saved
        n_eq = s%dofs%n_equations
        call progress_note(options%progress, 'STAT_NON_LINE: ' // to_text(n_eq) // &
            ' equations, ' // to_text(count(s%choc, kind=i4)) // ' DIS_CHOC springs, ' // &
            to_text(size(times, kind=i4) - 1) // ' step(s) from INST ' // &
            real_short(times(1)) // ' to ' // real_short(times(size(times))))
        allocate (imposed(n_eq), source=.false.)
        do k = 1, size(excit)
            call mark_imposed(s, excit(k)%load, imposed, st)
            if (st%failed()) return
        end do
        call prepare_relations(s, excit, imposed, elim, rigid, st)
        if (st%failed()) return
        call build_assembly_map(s, imposed, assembly_renum(options%factor), map, st, elim, &
            rigid)
        if (st%failed()) return
        call log_numbering(map, options%factor, log)
        call sym_move(map%pattern, state%matrix)
        call open_solver(s, map, options%factor, state%matrix, state%solver, log, st)
        if (st%failed()) return
        state%solver%progress => options%progress
        call log_add(log, to_text(size(map%springs)) // ' ' // spring_law(s, map) // ' springs')
        allocate (state%u(n_eq), state%fint(n_eq), state%fext(n_eq), state%flin(n_eq), &
            state%du(n_eq), state%work(n_eq), source=0.0_dp)
        allocate (state%closed(size(map%springs)), state%fn(size(map%springs)), &
            state%fac_closed(size(map%springs)), state%tangent_closed(size(map%springs)))
        state%nprec = options%factor%nprec
        call block_set_init(state%blocks, size(map%springs, kind=i4), &
            spring_block_width(s, map))
        call spring_matrices(s, map, state%blocks%sizes, state%blocks%eqs, state%blocks%k, st)
        if (st%failed()) return
        state%factor_cost = factor_cost_in_solves(state%solver%factor_flops, &
            state%solver%factor_terms, map%n_free)
        call contact_history_start(s, map, state%history, st)
        if (st%failed()) return
        call warn_unpressed_dis_contact(s, map, state%history, log)
        state%forced_tangent = .false.
        state%by_status = .true.
        do k = 1, size(map%springs)
            if (.not. is_dis_contact(s, map%springs(k))) state%forced_tangent = .true.
            if (is_dis_contact(s, map%springs(k))) state%by_status = .false.
        end do
        if (state%forced_tangent .and. (options%matrix_elastic .or. options%reac_iter /= 1)) &
            call log_add(log, 'DIS_CHOC springs: the corrections use the tangent matrix, ' // &
            'rebuilt at every iteration (REAC_ITER = 1), whatever NEWTON/MATRICE and ' // &
            'REAC_ITER say, as Code_Aster does (its message MECANONLINE5_5)')
        ! the state at u = 0: K_lin 0 = 0 exactly, so the incremental form (which builds the
        ! linear cells' cache the steps need anyway) gives internal_forces' values without
        ! rebuilding every plate stiffness (0.2 s at 64 x 256)
        ! ETAT_INIT (Code_Aster's initial state): u = u0, so the same call with du = u0 gives
        ! f_lin = K_lin u0 and the springs' forces and statuses at u0, which then start the
        ! DIS_CONTACT history as the end of a converged step would
        if (present(u0)) then
            state%u = u0
            state%du = u0
        end if
        call internal_forces_incremental(s, map, state%u, state%du, state%flin, state%fint, &
            state%closed, state%fn, st, state%linear, history=state%history)
        if (st%failed()) return
        if (present(u0)) then
            call contact_history_update(s, map, state%u, state%fn, state%history)
            state%du = 0.0_dp
        end if
        call result_init(res, 'evol_noli', s%mesh, s%dofs, int(size(times), i4), map%springs)
        call result_store(res, 0_i4, times(1), state%u, state%fint, 0.0_dp * state%u, &
            state%closed, state%fn)
        call store_spring_fields(s, state%u, res, st)      ! SIEF_ELGA, VARI_ELGA
        if (st%failed()) return
        n_eq = int(size(times), i4) - 1
        call grow_summary(summary, n_eq)
        ! the steps to the instants of the list; a step that fails is cut into shorter ones
        ! when the list says so (DEFI_LIST_INST/ECHEC DECOUPE: cut_failed_step)
        targets = times(2:)
        levels = [(0_i4, k = 1, size(targets))]
        t_prev = times(1)
        k = 1
        step = 0
        do while (k <= size(targets))
            call keep_step_start(state, saved)
            call grow_summary(summary, step + 1 + size(targets, kind=i4) - k)
            call newton_step(s, map, excit, targets(k), step + 1, options, state, log, &
                summary, st)
            if (st%failed()) then
                call cut_failed_step(options, t_prev, k, targets, levels, log, st)
                if (st%failed()) return
                call restore_step_start(saved, state)
                cycle
            end if
            step = step + 1
            call result_reserve(res, step + 1 + size(targets, kind=i4) - k)
            if (.not. allocated(forc)) allocate (forc(size(state%fint)))
            call recorded_internal_forces(s, targets(k), state%fint, forc, st)
            if (st%failed()) return
            call result_store(res, step, targets(k), state%u, forc, &
                reactions(map, state), state%closed, state%fn)
            call store_spring_fields(s, state%u, res, st)
            if (st%failed()) return
            t_prev = targets(k)
            k = k + 1
        end do
        text = state%solver%iteration_summary()       ! GCPC, PETSC: their iterations
        if (len(text) > 0) call log_add(log, text)
    end subroutine stat_non_line

    !> A step to targets(k) from t_prev failed with status st. When the list of instants
    !> cuts failed steps (DEFI_LIST_INST, ECHEC EVENEMENT='ERREUR', ACTION='DECOUPE'), the
    !> failure is a Newton one (no convergence, no equilibrium), the step's level of
    !> subdivision is below SUBD_NIVEAU and its SUBD_PAS parts are at least SUBD_PAS_MINI
    !> (and above round-off), the step is replaced by SUBD_PAS equal steps one level deeper
    !> (Code_Aster nmdecm, nmdecv) and st is cleared; otherwise st is kept, with why the step
    !> could not be cut when cutting was on.
    subroutine cut_failed_step(options, t_prev, k, targets, levels, log, st)
        type(newton_options_t), intent(in) :: options
        real(dp), intent(in) :: t_prev
        integer(i4), intent(in) :: k
        real(dp), allocatable, intent(inout) :: targets(:)
        integer(i4), allocatable, intent(inout) :: levels(:)
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(inout) :: st
        real(dp) :: dt
        integer(i4) :: n, i
        character(len=:), allocatable :: why
        if (.not. options%cutting%enabled) return
        if (st%code /= STATUS_NO_CONVERGENCE .and. st%code /= STATUS_NO_EQUILIBRIUM) return
        n = options%cutting%subd_pas
        dt = (targets(k) - t_prev) / real(n, dp)
        why = ''
        if (levels(k) >= options%cutting%subd_niveau) then
            why = 'SUBD_NIVEAU = ' // to_text(options%cutting%subd_niveau) // ' reached'
        else if (size(targets) + n - 1 > MAX_CUT_STEPS) then
            why = 'the analysis would have more than ' // to_text(MAX_CUT_STEPS) // ' steps'
        else if (dt < options%cutting%subd_pas_mini .or. &
                 .not. dt > epsilon(1.0_dp) * max(abs(targets(k)), abs(t_prev))) then
            why = 'a step of ' // real_e13(dt) // ' would be below SUBD_PAS_MINI = ' // &
                real_e13(options%cutting%subd_pas_mini) // ' or the round-off of INST'
        end if
        if (len(why) > 0) then
            st%message = st%message // ' (DEFI_LIST_INST/ECHEC: the step from INST ' // &
                real_e13(t_prev) // ' could not be cut further: ' // why // ')'
            return
        end if
        call log_add(log, '  step to INST ' // real_e13(targets(k)) // ' failed (' // &
            st%message // '): cut into ' // to_text(n) // ' steps of ' // real_e13(dt) // &
            ' (subdivision level ' // to_text(levels(k) + 1) // ' of SUBD_NIVEAU = ' // &
            to_text(options%cutting%subd_niveau) // ', DEFI_LIST_INST/ECHEC DECOUPE)')
        targets = [targets(1:k - 1), [(t_prev + dt * real(i, dp), i = 1, n - 1)], &
            targets(k:)]
        levels = [levels(1:k - 1), spread(levels(k) + 1, 1, n), levels(k + 1:)]
        call clear_status(st)
    end subroutine cut_failed_step

    !> The state at the start of a step that a failed step is taken back to.
    subroutine keep_step_start(state, saved)
        type(newton_state_t), intent(in) :: state
        type(step_start_t), intent(out) :: saved
        saved%u = state%u
        saved%fint = state%fint
        saved%fext = state%fext
        saved%flin = state%flin
        saved%fn = state%fn
        saved%closed = state%closed
        if (allocated(state%history%fn0)) saved%history = state%history
    end subroutine keep_step_start

    subroutine restore_step_start(saved, state)
        type(step_start_t), intent(in) :: saved
        type(newton_state_t), intent(inout) :: state
        state%u = saved%u
        state%fint = saved%fint
        state%fext = saved%fext
        state%flin = saved%flin
        state%fn = saved%fn
        state%closed = saved%closed
        if (allocated(saved%history%fn0)) state%history = saved%history
    end subroutine restore_step_start

    !> Room for n steps in the summary (kept values kept).
    subroutine grow_summary(summary, n)
        type(newton_summary_t), intent(inout) :: summary
        integer(i4), intent(in) :: n
        if (allocated(summary%inst)) then
            if (size(summary%inst) >= n) return
        end if
        call grow_r(summary%inst)
        call grow_r(summary%resi_rela)
        call grow_r(summary%resi_maxi)
        call grow_i(summary%iterations)
        call grow_i(summary%factorizations)
        call grow_i(summary%solves)
        call grow_i(summary%updated)
        call grow_i(summary%damped)
    contains
        subroutine grow_r(a)
            real(dp), allocatable, intent(inout) :: a(:)
            real(dp), allocatable :: b(:)
            allocate (b(n), source=0.0_dp)
            if (allocated(a)) b(1:size(a)) = a
            call move_alloc(b, a)
        end subroutine grow_r
        subroutine grow_i(a)
            integer(i4), allocatable, intent(inout) :: a(:)
            integer(i4), allocatable :: b(:)
            allocate (b(n), source=0_i4)
            if (allocated(a)) b(1:size(a)) = a
            call move_alloc(b, a)
        end subroutine grow_i
    end subroutine grow_summary

    !> Reactions f_int - f_ext on the imposed equations, 0 elsewhere.
    pure function reactions(map, state) result(reac)
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(in) :: state
        real(dp) :: reac(size(state%u))
        reac = merge(state%fint - state%fext, 0.0_dp, map%constrained)
    end function reactions

    !> One step of STAT_NON_LINE (see the module header).
    subroutine newton_step(s, map, excit, t, step, options, state, log, summary, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(excitation_t), intent(in) :: excit(:)
        real(dp), intent(in) :: t
        integer(i4), intent(in) :: step
        type(newton_options_t), intent(in) :: options
        type(newton_state_t), intent(inout) :: state
        type(analysis_log_t), intent(inout) :: log
        type(newton_summary_t), intent(inout) :: summary
        type(status_t), intent(out) :: st
        logical, allocatable :: start(:), history(:, :), full(:), tight(:)
        real(dp), allocatable :: r(:), b(:), x(:), du_body(:), resi_history(:), fext_fixed(:)
        real(dp) :: resi_rela, resi_maxi, previous_maxi, seconds, t0, step_start, alpha
        integer(i4) :: iter, changed, use, mode
        logical :: zero_load, converged, said_zero, settled, solve_tightly, searchable, searched
        type(step_pivots_t) :: piv
        step_start = wall_seconds()
        call log_add(log, '')
        call log_add(log, 'INST ' // real_e13(t) // ' (step ' // to_text(step) // ')')
        call log_add(log, ' ITER  RESI_GLOB_RELA  RESI_GLOB_MAXI  MATRIX                ' // &
            'CLOSED CHANGED  TIME(s)')
        state%u_start = state%u
        call loads_at(s, excit, t, state%u, state%fext, st)
        if (st%ok()) call relations_at(s, excit, map, t, state%u, st)
        if (st%failed()) return
        state%du = state%u - state%u_start
        ! follower loads (TYPE_CHARGE='SUIV'): on the geometry of the prediction, then of each
        ! iterate (doc/analysis.md "Follower loads")
        if (has_followers(excit)) then
            fext_fixed = state%fext
            call follower_loads_at(s, excit, t, state%u, state%fext, st)
            if (st%failed()) return
        end if
        start = state%closed
        allocate (history(size(state%closed), 0:options%iter_glob_maxi), &
            full(0:options%iter_glob_maxi), tight(0:options%iter_glob_maxi), &
            resi_history(0:options%iter_glob_maxi), r(map%n_free), x(map%n_free), &
            du_body(size(state%u)))
        state%factorizations = 0
        state%solves = 0
        state%updated = 0
        state%damped = 0
        state%force_evaluations = 0
        state%force_seconds = 0.0_dp
        previous_maxi = huge(1.0_dp)
        said_zero = .false.
        converged = .false.
        settled = .false.           ! the last iteration changed no spring status
        solve_tightly = .false.     ! a status came back after inexact corrections
        ! the prediction's correction is a Newton step of the energy (line search) only
        ! without imposed-value increments (with them it solves the linearised problem)
        searchable = .not. maxval(abs(state%du)) > 0.0_dp
        ! Prediction (Code_Aster nmprta/nsassp): the imposed-value increments enter through
        ! the prediction matrix, K du = f_ext(t+) - f_int(t-) - K du_imposed, i.e. the springs
        ! are linearised about the start of the step (doc/analysis.md, "Prediction").
        t0 = wall_seconds()
        call internal_forces_incremental(s, map, state%u, state%du, state%flin, state%fint, &
            state%closed, state%fn, st, state%linear, u_ref=state%u_start, &
            elastic_ref=prediction_is_elastic(options), history=state%history)
        if (st%failed()) return
        call count_forces(state, t0)
        do iter = 0, options%iter_glob_maxi
            call options%deadline%check('STAT_NON_LINE at INST ' // real_e13(t) // &
                                        ', Newton iteration ' // to_text(iter), st)
            if (st%failed()) return
            t0 = wall_seconds()
            call progress_context(options%progress, 'STAT_NON_LINE, INST ' // real_short(t) &
                // ' (step ' // to_text(step) // '/' // to_text(size(summary%inst)) // &
                '), iteration ' // to_text(iter))
            use = choose_matrix(options, iter, step, state)
            call gather_free(map, state%fext - state%fint, r)
            b = r
            tight(iter) = settled .or. solve_tightly
            call correction(s, map, state, use, iter == 0, options, t, tight(iter), log, piv, &
                r, mode, st)
            if (st%failed()) return
            ! a direct solve is no inexact-Newton correction, whatever the status did
            if (mode /= BY_UPDATED_FACTOR .and. .not. state%iterative_solve) tight(iter) = .true.
            if (piv%free_now) then
                piv%n_free = piv%n_free + 1
            else
                piv%n_free = 0
            end if
            alpha = 1.0_dp
            full(iter) = .true.
            ! RECH_LINEAIRE given: Code_Aster's search on the residual replaces parasol's on
            ! the contact energy (doc/analysis.md, "Line search")
            searched = options%line%enabled .and. (iter > 0 .or. searchable)
            if (.not. searched .and. use == MATRIX_TANGENT .and. state%by_status .and. &
                (iter > 0 .or. searchable)) &
                call line_search(s, map, state, b, r, log, alpha, full(iter), st)
            if (st%failed()) return
            call progress_update(options%progress, 'internal forces')
            history(:, iter) = state%closed
            if (searched) then
                call residual_search(s, map, state, options%line, r, x, du_body, log, &
                    full(iter), st)
            else
                call apply_correction(s, map, state, r, alpha, x, du_body, st)
            end if
            if (st%failed()) return
            changed = count(state%closed .neqv. history(:, iter), kind=i4)
            if (allocated(fext_fixed)) then
                state%fext = fext_fixed
                call follower_loads_at(s, excit, t, state%u, state%fext, st)
                if (st%failed()) return
            end if
            call residual_measures(map, state%fint, state%fext, resi_rela, &
                resi_maxi, zero_load)
            resi_history(iter) = resi_maxi
            seconds = wall_seconds() - t0
            call log_add(log, iteration_row(iter, resi_rela, resi_maxi, zero_load, use, &
                mode, count(state%closed, kind=i4), changed, seconds))
            call log_flush(log)             ! the .mess shows each row as it comes
            if (zero_load .and. .not. said_zero) then
                call log_add(log, '  no load and no reaction: RESI_GLOB_RELA is undefined,' &
                    // ' absolute criterion RESI_GLOB_MAXI <= ' // real_e13(absolute_tol( &
                    options)) // ' N used')
                said_zero = .true.
            end if
            converged = criteria_met(options, resi_rela, resi_maxi, zero_load)
            if (converged .and. changed > 0) then
                converged = .false.
                if (state%by_status) call changes_at_zero_gap(s, map, state, options, &
                    history(:, iter), log, converged, st)
                if (st%failed()) return
            end if
            if (converged) exit
            call check_no_equilibrium(s, map, state, use, iter, changed, piv, resi_maxi, &
                previous_maxi, t, st)
            if (st%failed()) return
            previous_maxi = resi_maxi
            settled = changed == 0
            call detect_cycle(s, map, options, history(:, 0:iter), full(0:iter), &
                tight(0:iter), iter, changed, state%closed, t, log, solve_tightly, st)
            if (st%failed()) return
        end do
        if (.not. converged) then
            call set_error(st, STATUS_NO_CONVERGENCE, 'INST ' // real_e13(t) // &
                ': no convergence in ITER_GLOB_MAXI = ' // to_text(options%iter_glob_maxi) // &
                ' iterations; RESI_GLOB_MAXI history: ' // history_text(resi_history) // &
                '; springs still changing: ' // changed_names(s, map, &
                history(:, options%iter_glob_maxi), state%closed))
            return
        end if
        call judge_converged_tangent(s, map, state, options, piv, t, log, st)
        if (st%failed()) return
        call log_answer_digits(s, map, state, t, log, st)
        if (st%failed()) return
        call contact_history_update(s, map, state%u, state%fn, state%history)
        call log_add(log, '  converged in ' // to_text(iter) // ' iteration(s), ' // &
            to_text(state%factorizations) // ' factorization(s); ' // &
            to_text(count(state%closed, kind=i4)) // ' of ' // to_text(size(state%closed)) // &
            ' springs closed')
        call log_add(log, '  solves with a factor: ' // to_text(state%solves) // &
            '; tangents through another status''s factor: ' // to_text(state%updated) // &
            '; corrections damped by the line search: ' // to_text(state%damped))
        call log_add(log, '  internal forces: ' // to_text(state%force_evaluations) // &
            ' evaluation(s), ' // seconds_text(state%force_seconds) // ' s')
        call log_add(log, '  closed in the step: ' // changed_names(s, map, start, &
            state%closed, want_closed=.true.))
        call log_add(log, '  opened in the step: ' // changed_names(s, map, start, &
            state%closed, want_closed=.false.))
        seconds = wall_seconds() - step_start
        call log_add(log, '  wall time of the step: ' // seconds_text(seconds) // ' s')
        call log_flush(log)
        call progress_done(options%progress)
        call progress_note(options%progress, step_line(t, step, size(summary%inst, kind=i4), &
            iter, resi_rela, zero_load, count(state%closed, kind=i4), &
            count(state%closed .neqv. start, kind=i4), size(state%closed, kind=i4), &
            state%factorizations, seconds))
        summary%n_steps = step
        summary%max_digits_lost = state%pivots%max_digits_lost
        if (allocated(state%pivots%digits_at)) summary%digits_at = state%pivots%digits_at
        summary%min_pivot = state%pivots%min_pivot
        summary%max_pivot = state%pivots%max_pivot
        summary%inst(step) = t
        summary%iterations(step) = iter
        summary%factorizations(step) = state%factorizations
        summary%solves(step) = state%solves
        summary%updated(step) = state%updated
        summary%damped(step) = state%damped
        summary%resi_rela(step) = resi_rela
        summary%resi_maxi(step) = resi_maxi
    end subroutine newton_step

    !> u <- u + alpha r and the internal forces there (internal_forces_incremental). The
    !> correction r is in the solver's hat coordinates (two_level_solver): the displacements
    !> move by all of it, the plates and plane solids see only the part that deforms them
    !> (their forces on the rigid modes are zero), so f_lin takes no round-off of the rigid
    !> motion.
    !>  x, du_body : work arrays (n_free, n_equations)
    subroutine apply_correction(s, map, state, r, alpha, x, du_body, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        real(dp), intent(in) :: r(:), alpha
        real(dp), intent(inout) :: x(:), du_body(:)
        type(status_t), intent(out) :: st
        real(dp) :: t0
        call from_hat(state%solver, r, x)
        call scatter_free(map, alpha * x, state%du)
        state%u = state%u + state%du
        call hat_body_part(state%solver, r, x)
        call scatter_free(map, alpha * x, du_body)
        t0 = wall_seconds()
        call internal_forces_incremental(s, map, state%u, state%du, state%flin, state%fint, &
            state%closed, state%fn, st, state%linear, history=state%history, du_body=du_body)
        if (st%ok()) call count_forces(state, t0)
    end subroutine apply_correction

    !> RECH_LINEAIRE (residual_line_search): u moves along the correction p (r in hat
    !> coordinates) to the rho the search chooses, f(rho) = p . (f_int - f_ext) evaluated at
    !> each trial (one evaluation of the internal forces each, the iterate moved by the
    !> difference of rho: the linear forces are exact increments).
    !>  full : out, rho = 1
    subroutine residual_search(s, map, state, opts, r, x, du_body, log, full, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        type(line_search_options_t), intent(in) :: opts
        real(dp), intent(in) :: r(:)
        real(dp), intent(inout) :: x(:), du_body(:)
        type(analysis_log_t), intent(inout) :: log
        logical, intent(out) :: full
        type(status_t), intent(out) :: st
        type(secant_search_t) :: ss
        real(dp), allocatable :: p(:), g(:)
        real(dp) :: at, rho, f0
        logical :: done
        allocate (p(map%n_free), g(map%n_free))
        call from_hat(state%solver, r, p)
        call gather_free(map, state%fint - state%fext, g)
        f0 = dot_product(p, g)
        full = .true.
        if (.not. abs(f0) > 0.0_dp) then
            call apply_correction(s, map, state, r, 1.0_dp, x, du_body, st)
            return
        end if
        call search_start(ss, opts, f0)
        at = 0.0_dp
        do
            rho = search_trial(ss)
            call apply_correction(s, map, state, r, rho - at, x, du_body, st)
            if (st%failed()) return
            at = rho
            call gather_free(map, state%fint - state%fext, g)
            call search_next(ss, opts, dot_product(p, g), done)
            if (done) exit
        end do
        rho = search_result(ss)
        if (abs(rho - at) > 0.0_dp) call apply_correction(s, map, state, r, rho - at, x, du_body, st)
        if (st%failed()) return
        full = .not. abs(rho - 1.0_dp) > 0.0_dp
        if (full) return
        state%damped = state%damped + 1
        call log_add(log, '  line search (RECH_LINEAIRE ' // trim(merge('MIXTE', 'CORDE', &
            opts%mixte)) // '): rho = ' // real_short(rho) // ' after ' // &
            to_text(ss%evaluations) // ' evaluation(s), |f(rho)| / |f(0)| = ' // &
            real_short(ss%f_best / abs(f0)) // trim(merge(' (RESI_LINE_RELA met)    ', &
            ' (ITER_LINE_MAXI reached)', ss%converged)))
    end subroutine residual_search

    !> One more evaluation of the internal forces, started at wall time t0 (the step's count
    !> and time, for the .mess: doc/performance.md measures them).
    subroutine count_forces(state, t0)
        type(newton_state_t), intent(inout) :: state
        real(dp), intent(in) :: t0
        state%force_evaluations = state%force_evaluations + 1
        state%force_seconds = state%force_seconds + (wall_seconds() - t0)
    end subroutine count_forces

    !> The .mess line on the digits the converged answer holds: one solve with the factor
    !> for the final residual (computed from the increments, element by element: without
    !> the contrast's cancellation) estimates the answer's error (answer_digits). Nothing
    !> when no factor is usable (a loaded held equation, check off).
    subroutine log_answer_digits(s, map, state, t, log, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        real(dp), allocatable :: r(:), e(:)
        character(len=:), allocatable :: loaded_at
        if (.not. state%fac_valid .or. map%n_free == 0) return
        allocate (r(map%n_free), e(map%n_free))
        call gather_free(map, state%fext - state%fint, r)
        call solve_held(s, map, state%matrix, state%solver, state%held, r, t, log, st, &
            loaded_at)
        if (st%failed() .or. allocated(loaded_at)) return
        state%solves = state%solves + 1
        call from_hat(state%solver, r, e)
        call log_add(log, '  the answer holds ' // real_digits(answer_digits(e, &
            state%u(map%free_to_eq))) // ' significant digits (correction for the final ' // &
            'residual ' // real_short(maxval(abs(e))) // ' against the largest ' // &
            'displacement ' // real_short(maxval(abs(state%u))) // ')')
    end subroutine log_answer_digits

    !> Which matrix iteration `iter` of step `step` uses; marks a tangent to rebuild by
    !> dropping it (factor_and_diagnose then assembles and factors). With DIS_CHOC springs
    !> (state%forced_tangent) Code_Aster rebuilds the tangent at every correction and every
    !> tangent prediction, whatever MATRICE, REAC_ITER and REAC_INCR say (NonLinear_module:
    !> getMatrTypeCorr turns the correction matrix to TANGENTE, isMatrUpdate forces the
    !> update; message MECANONLINE5_5).
    integer(i4) function choose_matrix(options, iter, step, state) result(use)
        type(newton_options_t), intent(in) :: options
        integer(i4), intent(in) :: iter, step
        type(newton_state_t), intent(inout) :: state
        if (iter == 0) then
            if (prediction_is_elastic(options)) then
                use = MATRIX_ELASTIC
            else
                use = MATRIX_TANGENT
                if (state%forced_tangent) then
                    call drop(state, MATRIX_TANGENT)
                else if (options%reac_incr > 0) then
                    if (mod(step - 1, options%reac_incr) == 0) call drop(state, MATRIX_TANGENT)
                end if
            end if
        else if (state%forced_tangent) then
            use = MATRIX_TANGENT
            call drop(state, MATRIX_TANGENT)
        else if (options%matrix_elastic) then
            use = MATRIX_ELASTIC
        else
            use = state%current
            if (options%reac_iter > 0) then
                if (mod(iter, options%reac_iter) == 0) then
                    use = MATRIX_TANGENT
                    call drop(state, MATRIX_TANGENT)
                end if
            end if
        end if
        if (use == MATRIX_TANGENT .and. state%tangent_stale) then
            state%tangent_closed = state%closed
            state%tangent_stale = .false.
        end if
        state%current = use
    end function choose_matrix

end module contact_newton

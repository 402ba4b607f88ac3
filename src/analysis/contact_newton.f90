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
module contact_newton
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_NO_CONVERGENCE, STATUS_NO_EQUILIBRIUM, &
        STATUS_SINGULAR
    use strings, only: to_text, real_e13, real_short
    use mesh_types, only: cell_name, cell_group_name, cells_of_group, n_cell_groups
    use model_dof_numbering, only: describe_equation
    use model_loads, only: load_set_t
    use function_concept, only: function_concept_t, param_binding_t
    use sparse_matrix, only: sym_matrix_t, sym_diagonal, sym_matvec, sym_move, &
        sym_add_element
    use direct_solver, only: direct_solver_t, solver_options_t, factor_report_t, &
        effective_nprec, check_disabled, DIGITS_ALL_LOST, nprec_text
    use solver_factory, only: create_solver, assembly_renum
    use assembly_system, only: structure_t, assembly_map_t, build_assembly_map, &
        assemble_stiffness, internal_forces_incremental, renumbering_lines, &
        linear_cache_t, contact_history_t, contact_history_start, contact_history_update, &
        is_dis_contact, spring_matrices, spring_lines, linear_product
    use element_dis_choc, only: choc_line_t
    use low_rank_update, only: block_set_t, block_set_init, pcg_work_t, pcg_begin, &
        pcg_continue, factor_cost_in_solves, pcg_options_t, pcg_report_t, PCG_CONVERGED, &
        PCG_BREAKDOWN
    use contact_line_search, only: step_choice_t, choose_step, any_crossing
    use assembly_loads, only: mark_imposed, impose_values, add_external_forces
    use analysis_result, only: result_concept_t, result_init, result_store
    use spring_results, only: store_spring_fields
    use analysis_log, only: analysis_log_t, log_add, log_flush
    use run_deadline, only: deadline_t
    use number_limits, only: is_finite, product_fits, MAX_BINARY_EXPONENT
    use progress, only: progress_t, wall_seconds, progress_note, progress_update, &
        progress_done, progress_context
    implicit none
    private

    !> Code_Aster defaults (U4.51.03): RESI_GLOB_RELA 1e-6, ITER_GLOB_MAXI 10.
    real(dp), parameter, public :: DEFAULT_RESI_GLOB_RELA = 1.0e-6_dp
    integer(i4), parameter, public :: DEFAULT_ITER_GLOB_MAXI = 10
    !> Springs named in a list before it is abbreviated.
    integer(i4), parameter :: LIST_NAMES = 6
    integer(i4), parameter :: MATRIX_NONE = 0, MATRIX_ELASTIC = 1, MATRIX_TANGENT = 2
    !> How an iteration's matrix was solved (the MATRIX column of the Newton table): with
    !> the factor it already had, after a new factorization, or through the factor of
    !> another contact status updated by the springs that differ (low_rank_update).
    integer(i4), parameter :: BY_REUSED_FACTOR = 0, BY_NEW_FACTOR = 1, BY_UPDATED_FACTOR = 2
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
    !> A spring that changed status in the last iteration while it would carry at most
    !> this fraction of the convergence tolerance (in newtons) when closed sits at zero
    !> gap: its status is immaterial to the equilibrium (the force is nil either way) and
    !> does not keep the iteration from converging (a spring exactly at zero gap otherwise
    !> flips with the round-off of every correction: the linear load P = p (b - y) on a
    !> rigid plate puts the whole row y = b at zero gap).
    real(dp), parameter :: ZERO_GAP_FORCE_FRACTION = 1.0e-2_dp
    !> A pivot below this fraction of the largest diagonal term is at the round-off level
    !> of the stiffest terms (~45 machine epsilons): a free rigid motion, even when the
    !> equation's own diagonal is small enough for NPREC not to flag it (e.g. a DX left free
    !> under a plate 1e8 times stiffer than its springs). Not larger: on fine plates the
    !> rotation diagonals (~D/h) are legitimately far below the membrane ones (~E h); the
    !> 128 x 512 SSNL130 plate has regular DRY pivots at 9.3e-13 of the largest term.
    real(dp), parameter :: RIGID_PIVOT_RATIO = 1.0e-14_dp
    !> A pivot that lost at least this many of the ~16 significant digits is at round-off
    !> level: the equation is free (a rigid motion or mechanism), whatever NPREC says. A
    !> pivot that only exceeds NPREC (8 by default, Code_Aster SOLVEUR/NPREC) is an
    !> ill-conditioned but regular matrix: SSNL130's plate ~1e10 N/m on springs ~1e2 N/m
    !> loses ~8-9 digits, which is why Code_Aster's SSNL130 sets NPREC = 9.
    real(dp), parameter :: FREE_PIVOT_DIGITS = 12.0_dp
    !> Pivot classes (classify_pivots).
    integer(i4), parameter :: PIVOT_REGULAR = 0, PIVOT_ILL_CONDITIONED = 1, PIVOT_FREE = 2
    !> Class of a matrix not factored yet (newton_state_t%elastic_kind).
    integer(i4), parameter :: PIVOT_UNKNOWN = -1
    !> Consecutive iterations with a free tangent (and a residual that does not decrease)
    !> after which full Newton declares that the load cannot be carried.
    integer(i4), parameter :: FREE_ITERATIONS_MAX = 2
    !> "Does not decrease": the residual stays above this fraction of the previous one.
    real(dp), parameter :: NO_DECREASE_RATIO = 0.999_dp

    !> A held equation is loaded when the penalty holding it carries more than this fraction
    !> of the largest right-hand-side term: the free motion there is driven, not idle ...
    real(dp), parameter :: HELD_LOAD_RATIO = 1.0e-8_dp
    !> ... and more than the round-off of the product A x, this many times
    !> eps max|a_jj| max|x| (a solve that loses ~9 digits leaves residuals of that order:
    !> model B's idle DX carried 1.9e-7 N against 2.2 N of load).
    real(dp), parameter :: HELD_ROUNDOFF_FACTOR = 1.0e3_dp
    !> Held equations named in the .mess before the list is cut.
    integer(i4), parameter :: LIST_EQUATIONS = 6

    !> Equations held at zero because the singularity check is off (METHODE='MUMPS' with
    !> NPREC < 0, Code_Aster U4.50.01): free equations nothing loads are solved with zero
    !> displacement and named once in the .mess; a loaded one stops the analysis.
    type, public :: held_t
        integer(i4), allocatable :: equations(:)   !< free numbering, of the current factor
        logical :: warned = .false.
    end type held_t

    !> What the factorization of a matrix says about its pivots.
    type :: pivot_diagnosis_t
        integer(i4) :: kind = PIVOT_REGULAR
        character(len=:), allocatable :: where     !< node, component and digits lost
        integer(i4) :: n_flagged = 0
        integer(i4) :: nprec = 8
        !> solver diagnostics of the factorization (style.md: digits lost, pivot range)
        real(dp) :: digits = 0.0_dp                !< largest digits lost
        logical :: digits_known = .true.           !< .false.: MUMPS (no pivot access)
        character(len=:), allocatable :: digits_at !< node and component of that pivot
        real(dp) :: min_pivot = 0.0_dp, max_pivot = 0.0_dp   !< range of |pivot|
    end type pivot_diagnosis_t

    !> NEWTON, CONVERGENCE and SOLVEUR options.
    type, public :: newton_options_t
        logical :: prediction_given = .false.      !< PREDICTION given
        logical :: prediction_elastic = .false.    !< PREDICTION = 'ELASTIQUE'
        logical :: matrix_elastic = .false.        !< MATRICE = 'ELASTIQUE' (default TANGENTE)
        integer(i4) :: reac_iter = 0               !< NEWTON/REAC_ITER
        integer(i4) :: reac_incr = 1               !< NEWTON/REAC_INCR
        logical :: use_rela = .true.               !< RESI_GLOB_RELA criterion active
        real(dp) :: resi_glob_rela = DEFAULT_RESI_GLOB_RELA
        logical :: use_maxi = .false.              !< RESI_GLOB_MAXI given
        real(dp) :: resi_glob_maxi = 0.0_dp
        integer(i4) :: iter_glob_maxi = DEFAULT_ITER_GLOB_MAXI
        type(solver_options_t) :: factor           !< SOLVEUR: METHODE, RENUM, NPREC ...
        type(deadline_t) :: deadline               !< the run's time limit, polled per iteration
        !> the run's reporter: a line per step, the work under way (null: nobody listens)
        class(progress_t), pointer :: progress => null()
    end type newton_options_t

    !> One EXCIT occurrence: a char_meca's load set and an optional FONC_MULT of INST.
    !> Both pointers refer to concepts owned by the run context (not freed here).
    type, public :: excitation_t
        type(load_set_t), pointer :: load => null()
        class(function_concept_t), pointer :: fonc_mult => null()
    end type excitation_t

    !> What each step cost.
    type, public :: newton_summary_t
        integer(i4) :: n_steps = 0
        real(dp), allocatable :: inst(:)
        integer(i4), allocatable :: iterations(:)      !< Newton iterations (excl. prediction)
        integer(i4), allocatable :: factorizations(:)
        integer(i4), allocatable :: solves(:)          !< solves with a factor
        integer(i4), allocatable :: updated(:)         !< tangents through another factor
        integer(i4), allocatable :: damped(:)          !< corrections the line search damped
        real(dp), allocatable :: resi_rela(:), resi_maxi(:)
        !> over every factorization: the largest loss of digits, where, and the |pivot| range
        real(dp) :: max_digits_lost = 0.0_dp
        character(len=:), allocatable :: digits_at
        real(dp) :: min_pivot = huge(1.0_dp), max_pivot = 0.0_dp
    end type newton_summary_t

    !> The analysis state carried from iteration to iteration and step to step.
    type :: newton_state_t
        real(dp), allocatable :: u(:), fint(:), fext(:), fn(:)
        real(dp), allocatable :: flin(:)    !< plate/plane forces, accumulated (K_lin du)
        real(dp), allocatable :: du(:)      !< last increment (imposed and free equations)
        real(dp), allocatable :: work(:)    !< (n_equations) products of the tangent
        type(linear_cache_t) :: linear      !< plate/plane element matrices, built once
        type(contact_history_t) :: history  !< DIS_CONTACT springs at the start of the step
        logical, allocatable :: closed(:)
        type(sym_matrix_t) :: matrix        !< the one assembled matrix, filled in place
        class(direct_solver_t), allocatable :: solver   !< its factor (analysed once)
        integer(i4) :: factored = MATRIX_NONE   !< which matrix the factor holds
        !> pivot class of the elastic matrix, PIVOT_UNKNOWN until it is first factored (the
        !> matrix is the same for the whole analysis: linear cells, every spring closed)
        integer(i4) :: elastic_kind = PIVOT_UNKNOWN
        !> DIS_CHOC springs present: every correction uses the tangent, rebuilt (Code_Aster)
        logical :: forced_tangent = .false.
        real(dp), allocatable :: u_start(:)  !< u at the start of the step (prediction point)
        integer(i4) :: current = MATRIX_NONE
        !> every contact spring is DIS_CHOC: a tangent is a function of the contact status,
        !> and the low-rank solves, the line search and the zero-gap rule apply
        logical :: by_status = .false.
        !> (by_status) the factor and the assembled matrix hold the tangent of status
        !> fac_closed (the elastic matrix = every spring closed); fac_usable: regular, so it
        !> can precondition; fac_kind its pivot class; fac_digits: digits its pivots lost, at
        !> most (MUMPS, which gives no pivots: NPREC) and at least (MUMPS: those reported)
        logical :: fac_valid = .false., fac_usable = .false.
        logical, allocatable :: fac_closed(:)
        integer(i4) :: fac_kind = PIVOT_REGULAR
        real(dp) :: fac_digits = 0.0_dp, fac_digits_low = 0.0_dp
        !> the status of the tangent in use, taken from the current status when the tangent
        !> is rebuilt (drop marks it stale)
        logical, allocatable :: tangent_closed(:)
        logical :: tangent_stale = .true.
        !> the last correction was solved by CG with a factor (updated or refined)
        logical :: iterative_solve = .false.
        type(block_set_t) :: blocks         !< every spring's closed matrix (free equations)
        real(dp) :: factor_cost = 0.0_dp    !< a factorization, in solves
        real(dp) :: solves_since_factor = 0.0_dp   !< through it for another status
        integer(i4) :: last_updated_solves = 0     !< the last such solve's iterations
        !> the last converged status factored to judge NPREC, and what its pivots said
        logical, allocatable :: judged_closed(:)
        type(pivot_diagnosis_t) :: judged
        type(held_t) :: held                !< equations held with the check off
        integer(i4) :: factorizations = 0, solves = 0, updated = 0, damped = 0  !< this step
        logical :: refactored = .false.
        integer(i4) :: nprec = 0            !< SOLVEUR/NPREC
        type(solver_options_t) :: solver_options
        type(newton_summary_t) :: pivots    !< solver diagnostics over the factorizations
    end type newton_state_t

    !> Pivot findings of one step (matrix_for_iteration).
    type :: step_pivots_t
        integer(i4) :: n_free = 0                      !< consecutive free-tangent iterations
        logical :: free_now = .false.
        character(len=:), allocatable :: free_where    !< last free pivot
        type(pivot_diagnosis_t) :: ill                 !< last ill-conditioned tangent ...
        logical, allocatable :: ill_closed(:)          !< ... and its contact status
        !> last tangent solved through another status's factor, and its digits bound
        logical, allocatable :: updated_closed(:)
        real(dp) :: updated_bound = 0.0_dp
    end type step_pivots_t

    public :: stat_non_line, loads_at, residual_measures, factor_and_diagnose_linear, &
        solver_diagnostics_line, open_solver, log_numbering, solve_held

contains

    !> Runs STAT_NON_LINE.
    !>  s        : in, the structure (s%choc marks the DIS_CHOC cells)
    !>  excit    : in, the EXCIT occurrences
    !>  times    : in, times(1) = INST_INIT, times(2:) the ends of the steps (increasing)
    !>  options  : in, NEWTON/CONVERGENCE/SOLVEUR
    !>  res      : out, evol_noli: NUME_ORDRE 0 = zero state at INST_INIT, then each step
    !>  log      : inout, .mess lines (renumbering, Newton table per step)
    !>  summary  : out, iterations and factorizations per step
    !>  st       : out, see the module header; the result holds the converged steps
    subroutine stat_non_line(s, excit, times, options, res, log, summary, st)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        real(dp), intent(in) :: times(:)
        type(newton_options_t), intent(in) :: options
        type(result_concept_t), intent(out) :: res
        type(analysis_log_t), intent(inout) :: log
        type(newton_summary_t), intent(out) :: summary
        type(status_t), intent(out) :: st
        type(assembly_map_t) :: map
        type(newton_state_t) :: state
        logical, allocatable :: imposed(:)
        integer(i4) :: k, step, n_eq
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
        call build_assembly_map(s, imposed, assembly_renum(options%factor), map, st)
        if (st%failed()) return
        call log_numbering(map, options%factor, log)
        call sym_move(map%pattern, state%matrix)
        call open_solver(options%factor, state%matrix, state%solver, log, st)
        if (st%failed()) return
        state%solver%progress => options%progress
        call log_add(log, to_text(size(map%springs)) // ' ' // spring_law(s, map) // ' springs')
        allocate (state%u(n_eq), state%fint(n_eq), state%fext(n_eq), state%flin(n_eq), &
            state%du(n_eq), state%work(n_eq), source=0.0_dp)
        allocate (state%closed(size(map%springs)), state%fn(size(map%springs)), &
            state%fac_closed(size(map%springs)), state%tangent_closed(size(map%springs)))
        state%nprec = options%factor%nprec
        call block_set_init(state%blocks, size(map%springs, kind=i4))
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
        call internal_forces_incremental(s, map, state%u, state%du, state%flin, state%fint, &
            state%closed, state%fn, st, state%linear, history=state%history)
        if (st%failed()) return
        call result_init(res, 'evol_noli', s%mesh, s%dofs, int(size(times), i4), map%springs)
        call result_store(res, 0_i4, times(1), state%u, state%fint, 0.0_dp * state%u, &
            state%closed, state%fn)
        call store_spring_fields(s, state%u, res, st)      ! SIEF_ELGA, VARI_ELGA
        if (st%failed()) return
        n_eq = int(size(times), i4) - 1
        allocate (summary%inst(n_eq), summary%iterations(n_eq), summary%factorizations(n_eq), &
            summary%resi_rela(n_eq), summary%resi_maxi(n_eq), summary%solves(n_eq), &
            summary%updated(n_eq), summary%damped(n_eq))
        do step = 1, int(size(times), i4) - 1
            call newton_step(s, map, excit, times(step + 1), step, options, state, log, &
                summary, st)
            if (st%failed()) return
            call result_store(res, step, times(step + 1), state%u, state%fint, &
                reactions(map, state), state%closed, state%fn)
            call store_spring_fields(s, state%u, res, st)
            if (st%failed()) return
        end do
    end subroutine stat_non_line

    !> Reactions f_int - f_ext on the imposed equations, 0 elsewhere.
    pure function reactions(map, state) result(reac)
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(in) :: state
        real(dp) :: reac(size(state%u))
        reac = merge(state%fint - state%fext, 0.0_dp, map%imposed)
    end function reactions

    !> Imposed values into u and external forces at t, over all EXCIT occurrences.
    !>  st : out, function evaluation errors (FONC_MULT included)
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
    end subroutine loads_at

    !> RESI_GLOB_MAXI = max|f_ext - f_int| over the free equations and RESI_GLOB_RELA =
    !> that / max(max|f_ext|, max|reactions|); zero_load when the denominator is 0 (then
    !> resi_rela is returned as 0 and the caller must use the absolute criterion).
    pure subroutine residual_measures(imposed, fint, fext, resi_rela, resi_maxi, zero_load)
        logical, intent(in) :: imposed(:)
        real(dp), intent(in) :: fint(:), fext(:)
        real(dp), intent(out) :: resi_rela, resi_maxi
        logical, intent(out) :: zero_load
        real(dp) :: denominator
        resi_maxi = maxval(abs(fext - fint), mask=.not. imposed, dim=1)
        if (count(.not. imposed) == 0) resi_maxi = 0.0_dp
        denominator = resi_denominator(imposed, fint, fext)
        zero_load = .not. denominator > 0.0_dp
        resi_rela = 0.0_dp
        if (.not. zero_load) resi_rela = resi_maxi / denominator
    end subroutine residual_measures

    !> The denominator of RESI_GLOB_RELA: max(max|f_ext|, max|reactions|).
    pure real(dp) function resi_denominator(imposed, fint, fext) result(denominator)
        logical, intent(in) :: imposed(:)
        real(dp), intent(in) :: fint(:), fext(:)
        denominator = maxval(abs(fext), dim=1)
        if (any(imposed)) denominator = max(denominator, &
            maxval(abs(fint - fext), mask=imposed, dim=1))
    end function resi_denominator

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
        real(dp), allocatable :: r(:), b(:), resi_history(:)
        real(dp) :: resi_rela, resi_maxi, previous_maxi, seconds, t0, step_start, alpha
        integer(i4) :: iter, changed, use, mode
        logical :: zero_load, converged, said_zero, settled, solve_tightly, searchable
        type(step_pivots_t) :: piv
        step_start = wall_seconds()
        call log_add(log, '')
        call log_add(log, 'INST ' // real_e13(t) // ' (step ' // to_text(step) // ')')
        call log_add(log, ' ITER  RESI_GLOB_RELA  RESI_GLOB_MAXI  MATRIX                ' // &
            'CLOSED CHANGED  TIME(s)')
        state%u_start = state%u
        call loads_at(s, excit, t, state%u, state%fext, st)
        if (st%failed()) return
        state%du = state%u - state%u_start
        start = state%closed
        allocate (history(size(state%closed), 0:options%iter_glob_maxi), &
            full(0:options%iter_glob_maxi), tight(0:options%iter_glob_maxi), &
            resi_history(0:options%iter_glob_maxi), r(map%n_free))
        state%factorizations = 0
        state%solves = 0
        state%updated = 0
        state%damped = 0
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
        call internal_forces_incremental(s, map, state%u, state%du, state%flin, state%fint, &
            state%closed, state%fn, st, state%linear, u_ref=state%u_start, &
            elastic_ref=prediction_is_elastic(options), history=state%history)
        if (st%failed()) return
        do iter = 0, options%iter_glob_maxi
            call options%deadline%check('STAT_NON_LINE at INST ' // real_e13(t) // &
                                        ', Newton iteration ' // to_text(iter), st)
            if (st%failed()) return
            t0 = wall_seconds()
            call progress_context(options%progress, 'STAT_NON_LINE, INST ' // real_short(t) &
                // ' (step ' // to_text(step) // '/' // to_text(size(summary%inst)) // &
                '), iteration ' // to_text(iter))
            use = choose_matrix(options, iter, step, state)
            r = state%fext(map%free_to_eq) - state%fint(map%free_to_eq)
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
            if (use == MATRIX_TANGENT .and. state%by_status .and. (iter > 0 .or. searchable)) &
                call line_search(s, map, state, b, r, log, alpha, full(iter), st)
            if (st%failed()) return
            call progress_update(options%progress, 'internal forces')
            state%du = 0.0_dp
            state%du(map%free_to_eq) = alpha * r
            state%u(map%free_to_eq) = state%u(map%free_to_eq) + state%du(map%free_to_eq)
            history(:, iter) = state%closed
            call internal_forces_incremental(s, map, state%u, state%du, state%flin, &
                state%fint, state%closed, state%fn, st, state%linear, history=state%history)
            if (st%failed()) return
            changed = count(state%closed .neqv. history(:, iter), kind=i4)
            call residual_measures(map%imposed, state%fint, state%fext, resi_rela, &
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
        call contact_history_update(s, map, state%u, state%fn, state%history)
        call log_add(log, '  converged in ' // to_text(iter) // ' iteration(s), ' // &
            to_text(state%factorizations) // ' factorization(s); ' // &
            to_text(count(state%closed, kind=i4)) // ' of ' // to_text(size(state%closed)) // &
            ' springs closed')
        call log_add(log, '  solves with a factor: ' // to_text(state%solves) // &
            '; tangents through another status''s factor: ' // to_text(state%updated) // &
            '; corrections damped by the line search: ' // to_text(state%damped))
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

    !> Absolute tolerance of the zero-load case: RESI_GLOB_MAXI if given, else the
    !> RESI_GLOB_RELA value read in newtons.
    pure real(dp) function absolute_tol(options)
        type(newton_options_t), intent(in) :: options
        absolute_tol = options%resi_glob_rela
        if (options%use_maxi) absolute_tol = options%resi_glob_maxi
    end function absolute_tol

    pure logical function criteria_met(options, resi_rela, resi_maxi, zero_load)
        type(newton_options_t), intent(in) :: options
        real(dp), intent(in) :: resi_rela, resi_maxi
        logical, intent(in) :: zero_load
        if (zero_load) then
            criteria_met = resi_maxi <= absolute_tol(options)
            return
        end if
        criteria_met = .true.
        if (options%use_rela) criteria_met = resi_rela <= options%resi_glob_rela
        if (options%use_maxi) criteria_met = criteria_met .and. &
            resi_maxi <= options%resi_glob_maxi
    end function criteria_met

    !> The prediction's matrix: PREDICTION, or MATRICE when PREDICTION is not given.
    pure logical function prediction_is_elastic(options) result(elastic)
        type(newton_options_t), intent(in) :: options
        elastic = options%matrix_elastic
        if (options%prediction_given) elastic = options%prediction_elastic
    end function prediction_is_elastic

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

    !> The convergence tolerance in newtons at the current iterate: RESI_GLOB_RELA times
    !> its denominator and/or RESI_GLOB_MAXI (the smaller), or the zero-load tolerance.
    real(dp) function criterion_tolerance(options, map, state) result(tolerance)
        type(newton_options_t), intent(in) :: options
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(in) :: state
        real(dp) :: denominator
        denominator = resi_denominator(map%imposed, state%fint, state%fext)
        if (.not. denominator > 0.0_dp) then
            tolerance = absolute_tol(options)
        else
            tolerance = huge(1.0_dp)
            ! RESI_GLOB_RELA may be as large as the deck likes (1e308: any state converges);
            ! the product is formed only when it fits (number_limits), else no bound
            if (options%use_rela) then
                if (product_fits(options%resi_glob_rela, denominator)) &
                    tolerance = options%resi_glob_rela * denominator
            end if
            if (options%use_maxi) tolerance = min(tolerance, options%resi_glob_maxi)
        end if
    end function criterion_tolerance

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
    !> closed matrix of each spring closed in `closed`.
    subroutine tangent_product(s, map, state, closed, p, q, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        logical, intent(in) :: closed(:)
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: q(:)
        type(status_t), intent(out) :: st
        integer(i4) :: b, i, j, m, ei, ej
        real(dp) :: t
        state%du = 0.0_dp
        state%du(map%free_to_eq) = p
        call linear_product(s, map, state%linear, state%du, state%work, st)
        if (st%failed()) return
        q = state%work(map%free_to_eq)
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
    end subroutine tangent_product

    !> K_S x = b by CG preconditioned with the factor (low_rank_update), the products
    !> with K_S by tangent_product: the factor's status may be S (refinement) or another.
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
        logical :: more
        call pcg_begin(work, state%solver, b, options, report, more, st)
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

    !> The step along the tangent correction p (contact_line_search): 1 unless springs
    !> change status on it and the full step fails Armijo's condition on the energy.
    !>  b : in, the residual the correction was solved for (f_ext - f_int, free equations)
    !>  p : in, the correction
    !>  alpha : out, the step; full : out, alpha = 1
    subroutine line_search(s, map, state, b, p, log, alpha, full, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(inout) :: state
        real(dp), intent(in) :: b(:), p(:)
        type(analysis_log_t), intent(inout) :: log
        real(dp), intent(out) :: alpha
        logical, intent(out) :: full
        type(status_t), intent(out) :: st
        type(choc_line_t), allocatable :: lines(:)
        real(dp), allocatable :: q(:)
        type(step_choice_t) :: choice
        character(len=16) :: buf
        real(dp) :: scale
        alpha = 1.0_dp
        full = .true.
        if (size(map%springs) == 0 .or. .not. state%fac_valid .or. size(p) == 0) return
        ! energies in units of scale^2 (the search does not depend on it): no overflow
        scale = max(maxval(abs(state%u)), maxval(abs(p)))
        if (.not. scale > 0.0_dp) return
        allocate (lines(size(map%springs)))
        state%du = 0.0_dp
        state%du(map%free_to_eq) = p
        call spring_lines(s, map, state%u, state%du, scale, lines, st)
        if (st%failed() .or. .not. any_crossing(lines)) return
        ! the curvature p^T K_S p of the tangent at u (element by element, as the residual)
        allocate (q(size(p)))
        call tangent_product(s, map, state, state%closed, p / scale, q, st)
        if (st%failed()) return
        call choose_step(lines, -dot_product(p / scale, b / scale), dot_product(p / scale, q), &
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
        call accumulate_pivots(diag, state%pivots)
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
        integer(i4) :: k, b, m
        state%fac_valid = .false.
        call progress_update(state%solver%progress, 'assembly of the ' // &
            trim(merge('elastic', 'tangent', elastic)) // ' matrix')
        call assemble_stiffness(s, map, u_asm, elastic, state%matrix, st, state%linear, &
            state%history)
        if (st%failed()) return
        if (.not. elastic .and. state%by_status) then
            call status_difference(closed, state%closed, active, signs)
            do k = 1, size(active)
                b = active(k)
                m = state%blocks%sizes(b)
                call sym_add_element(state%matrix, state%blocks%eqs(1:m, b), &
                    real(signs(k), dp) * state%blocks%k(1:m, 1:m, b), st)
                if (st%failed()) return
            end do
        end if
        call factor_and_classify(s, map, state%matrix, state%solver, diag, st, state%held, &
            log)
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

    !> The .mess lines on the numbering: LDLT's renumbering figures (the skyline stores that
    !> envelope), or the method's own ordering.
    subroutine log_numbering(map, options, log)
        type(assembly_map_t), intent(in) :: map
        type(solver_options_t), intent(in) :: options
        type(analysis_log_t), intent(inout) :: log
        character(len=100) :: lines(2)
        if (trim(options%method) == 'LDLT') then
            lines = renumbering_lines(map)
            call log_add(log, lines(1))
            call log_add(log, lines(2))
        else
            call log_add(log, 'METHODE ' // trim(options%method) // ': ' // &
                to_text(map%n_free) // ' free equations, ordered by the solver')
        end if
    end subroutine log_numbering

    !> Creates the solver of SOLVEUR (create_solver) and analyses the pattern once. The
    !> solver never stops on a flagged pivot (the analysis classifies them); with the check
    !> off (check_disabled) it holds the free pivots (FREE_PIVOT_DIGITS, RIGID_PIVOT_RATIO).
    !>  st : out, a RENUM the method lacks, a back-end that cannot load or analyse
    subroutine open_solver(options, matrix, solver, log, st)
        type(solver_options_t), intent(in) :: options
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), allocatable, intent(out) :: solver
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        type(solver_options_t) :: lenient
        character(len=:), allocatable :: text
        lenient = options
        lenient%stop_singular = .false.
        if (check_disabled(options)) then
            lenient%hold_digits = FREE_PIVOT_DIGITS
            lenient%hold_ratio = RIGID_PIVOT_RATIO
        end if
        call create_solver(lenient, solver, st)
        if (st%failed()) return
        call solver%analyse(matrix, st)
        if (st%failed()) return
        text = 'SOLVEUR: METHODE ' // trim(solver%options%method) // ', RENUM ' // &
            trim(solver%options%renum) // ', NPREC ' // to_text(options%nprec)
        if (check_disabled(options)) text = text // ' (singularity check off)'
        text = text // ', factor ' // real_short(real(solver%memory_estimate(), dp) / &
            1.0e6_dp) // ' MB'
        if (solver%factor_flops > 0.0_dp) text = text // ', ' // &
            real_short(solver%factor_flops) // ' flop'
        call log_add(log, text // ' estimated')
    end subroutine open_solver

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

    !> Solves with the factor; with held equations (check off) the penalty that holds each
    !> one must carry (almost) nothing: then the equation is free and unloaded, solved with
    !> zero displacement and named once in the .mess; otherwise a load drives a free
    !> motion and STATUS_SINGULAR names its node and component.
    !>  r : inout, right-hand side (free equations) in, solution out
    !>  loaded_at : out, optional: when given, a loaded held equation is not an error; it is
    !>              named here (node, component, load carried) and r is zeroed; unallocated
    !>              when no held equation is loaded
    subroutine solve_held(s, map, matrix, solver, held, r, t, log, st, loaded_at)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(held_t), intent(inout) :: held
        real(dp), intent(inout) :: r(:)
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        character(len=:), allocatable, intent(out), optional :: loaded_at
        real(dp), allocatable :: rhs(:), ax(:)
        real(dp) :: scale, carried, roundoff
        integer(i4) :: k, eq, worst
        logical :: have_held
        have_held = .false.
        if (allocated(held%equations)) have_held = size(held%equations) > 0
        if (have_held) rhs = r
        call solve_in_range(s, map, matrix, solver, r, t, st)
        if (st%failed() .or. .not. have_held) return
        allocate (ax(size(r)))
        call sym_matvec(matrix, r, ax)
        scale = maxval(abs(rhs))
        roundoff = HELD_ROUNDOFF_FACTOR * epsilon(1.0_dp) * maxval(abs(sym_diagonal(matrix))) &
            * maxval(abs(r))
        worst = 0
        carried = 0.0_dp
        do k = 1, size(held%equations)
            eq = held%equations(k)
            if (abs(rhs(eq) - ax(eq)) > carried) then
                carried = abs(rhs(eq) - ax(eq))
                worst = eq
            end if
        end do
        if (worst > 0 .and. carried > max(HELD_LOAD_RATIO * scale, roundoff) .and. &
            present(loaded_at)) then
            loaded_at = describe_equation(s%dofs, s%mesh, map%free_to_eq(worst)) // &
                ' (held, carrying ' // real_e13(carried) // ' against ' // real_e13(scale) // ')'
            r = 0.0_dp
            return
        else if (worst > 0 .and. carried > max(HELD_LOAD_RATIO * scale, roundoff)) then
            call set_error(st, STATUS_SINGULAR, 'INST ' // real_e13(t) // ': singular ' // &
                'matrix at ' // describe_equation(s%dofs, s%mesh, map%free_to_eq(worst)) // &
                ': the equation is free (SOLVEUR/NPREC < 0 switched the singularity check ' // &
                'off) and loaded (' // real_e13(carried) // ' against ' // real_e13(scale) // &
                '); a support (DDL_IMPO) or a stiffness is missing there')
            r = 0.0_dp
            return
        end if
        if (.not. held%warned) then
            call log_add(log, '  warning (SOLVEUR/NPREC < 0, singularity check off): ' // &
                to_text(size(held%equations)) // ' free equation(s), unloaded, solved ' // &
                'with zero displacement: ' // held_names(s, map, held%equations))
            held%warned = .true.
        end if
    end subroutine solve_held

    !> solver%solve without overflow (issue 13): the right-hand side is scaled by a power of
    !> two to |r| <= 1 (exact: the solution is bit for bit the unscaled one's, scaled), and
    !> the solution is scaled back only when it fits, with the products K u the analysis
    !> forms from it (number_limits): otherwise STATUS_SINGULAR at the largest component,
    !> a load out of all proportion to what holds the structure there.
    subroutine solve_in_range(s, map, matrix, solver, r, t, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        real(dp), intent(inout) :: r(:)
        real(dp), intent(in) :: t
        type(status_t), intent(out) :: st
        integer :: shift
        integer(i4) :: worst
        real(dp) :: largest
        shift = 0
        if (size(r) > 0) then
            if (maxval(abs(r)) > 0.0_dp) shift = exponent(maxval(abs(r)))
        end if
        r = scale(r, -shift)
        call solver%solve(r, st)
        if (st%failed() .or. size(r) == 0) return
        worst = int(maxloc(abs(r), dim=1), i4)
        largest = abs(r(worst))
        if (.not. is_finite(largest)) then
            worst = int(findloc(is_finite(r), .false., dim=1), i4)
        else if (largest > 0.0_dp .and. exponent(largest) + shift + &
                 max(0, exponent(maxval(abs(sym_diagonal(matrix))))) <= MAX_BINARY_EXPONENT) then
            r = scale(r, shift)
            return
        else if (.not. largest > 0.0_dp) then
            return
        end if
        call set_error(st, STATUS_SINGULAR, 'INST ' // real_e13(t) // ': the solution at ' // &
            describe_equation(s%dofs, s%mesh, map%free_to_eq(worst)) // ' is beyond ' // &
            'double precision (about 2**' // to_text(exponent(largest) + shift) // &
            ' times the stiffness): the loads are out of all proportion to what holds the ' // &
            'structure there (a support or a stiffness missing, or loads too large)')
        r = 0.0_dp
    end subroutine solve_in_range

    !> Node and component of the first held equations (cut after LIST_EQUATIONS).
    function held_names(s, map, equations) result(text)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: equations(:)
        character(len=:), allocatable :: text
        integer(i4) :: k
        text = ''
        do k = 1, min(size(equations, kind=i4), LIST_EQUATIONS)
            if (k > 1) text = text // ', '
            text = text // describe_equation(s%dofs, s%mesh, map%free_to_eq(equations(k)))
        end do
        if (size(equations) > LIST_EQUATIONS) text = text // ' ...'
    end function held_names

    !> MECA_STATIQUE: assembles and factors the (linear) stiffness at u; a flagged matrix
    !> is STATUS_SINGULAR or a warning (report_pivots); with the check off (MUMPS, NPREC <
    !> 0) free equations are held instead (solve_held judges them).
    !>  matrix : inout, the pattern in, the assembled matrix out
    !>  solver : inout, analysed (open_solver); factored on return
    !>  held   : out, the held equations
    subroutine factor_and_diagnose_linear(s, map, u, matrix, solver, held, options, log, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:)
        type(sym_matrix_t), intent(inout) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(held_t), intent(out) :: held
        type(solver_options_t), intent(in) :: options
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        type(pivot_diagnosis_t) :: diag
        type(newton_summary_t) :: one
        call assemble_and_factor(s, map, u, .false., matrix, solver, diag, st, held=held, &
            log=log)
        if (st%failed()) return
        call accumulate_pivots(diag, one)
        call log_add(log, solver_diagnostics_line(one, options%nprec, options%method))
        if (diag%kind /= PIVOT_REGULAR .and. .not. check_disabled(options)) &
            call report_pivots(diag, options, 0.0_dp, log, st)
    end subroutine factor_and_diagnose_linear

    !> Assembles the matrix at u (elastic or tangent) in place, factors it without stopping,
    !> and classifies its pivots (classify_pivots).
    !>  diag  : out, PIVOT_REGULAR, PIVOT_ILL_CONDITIONED or PIVOT_FREE, and where
    !>  cache : in, optional, the plate/plane matrices (assemble_stiffness)
    !>  history : in, optional, DIS_CONTACT state at the start of the step
    !>  held  : inout, optional, the equations the factor holds (check off)
    !>  log   : inout, optional, gets the factorization line (method, ordering, size, time)
    subroutine assemble_and_factor(s, map, u, elastic, matrix, solver, diag, st, cache, &
                                   history, held, log)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:)
        logical, intent(in) :: elastic
        type(sym_matrix_t), intent(inout) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(pivot_diagnosis_t), intent(out) :: diag
        type(status_t), intent(out) :: st
        type(linear_cache_t), intent(in), optional :: cache
        type(contact_history_t), intent(in), optional :: history
        type(held_t), intent(inout), optional :: held
        type(analysis_log_t), intent(inout), optional :: log
        call progress_update(solver%progress, 'assembly of the ' // &
            trim(merge('elastic', 'tangent', elastic)) // ' matrix')
        call assemble_stiffness(s, map, u, elastic, matrix, st, cache, history)
        if (st%failed()) return
        call factor_and_classify(s, map, matrix, solver, diag, st, held, log)
    end subroutine assemble_and_factor

    !> Factors the assembled matrix without stopping and classifies its pivots
    !> (classify_pivots); held and log as assemble_and_factor.
    subroutine factor_and_classify(s, map, matrix, solver, diag, st, held, log)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(pivot_diagnosis_t), intent(out) :: diag
        type(status_t), intent(out) :: st
        type(held_t), intent(inout), optional :: held
        type(analysis_log_t), intent(inout), optional :: log
        type(factor_report_t) :: report
        real(dp) :: largest
        real(dp), allocatable :: pivots(:)
        largest = 0.0_dp
        if (matrix%n > 0) largest = maxval(abs(sym_diagonal(matrix)))
        call progress_update(solver%progress, 'factorization (' // &
            trim(solver%options%method) // ')')
        call solver%factor(matrix, report, st)
        if (st%failed()) return
        if (present(log)) call log_add(log, factorization_line(report))
        if (present(held)) held%equations = report%held_equations(1:report%n_held)
        if (report%pivots_known) then
            pivots = report%pivots
        else
            allocate (pivots(0))
        end if
        call classify_pivots(report, pivots, largest, solver%options, diag)
        diag%digits = max(report%max_digits_lost, 0.0_dp)
        diag%digits_known = report%pivots_known
        diag%digits_at = ''
        if (report%max_digits_equation > 0) diag%digits_at = describe_equation(s%dofs, &
            s%mesh, map%free_to_eq(report%max_digits_equation))
        diag%min_pivot = report%min_abs_pivot
        diag%max_pivot = report%max_abs_pivot
        if (diag%kind /= PIVOT_REGULAR) diag%where = describe_equation(s%dofs, s%mesh, &
            map%free_to_eq(diag%n_flagged)) // diag%where
        diag%n_flagged = report%n_flagged
    end subroutine factor_and_classify

    !> One .mess line per factorization: method, ordering, factor size, memory and time.
    function factorization_line(report) result(text)
        type(factor_report_t), intent(in) :: report
        character(len=:), allocatable :: text
        character(len=16) :: buf
        write (buf, '(f0.3)') report%seconds
        if (buf(1:1) == '.') buf = '0' // buf(1:15)
        text = '  factorization ' // report%method // ' (ordering ' // report%ordering // &
            '): ' // to_text(report%factor_entries) // ' terms, ' // &
            real_short(real(report%memory_bytes, dp) / 1.0e6_dp) // ' MB, ' // trim(buf) // ' s'
    end function factorization_line

    !> Classifies a factorization (doc/analysis.md, "Diagnosis"): PIVOT_FREE when a pivot
    !> lost >= FREE_PIVOT_DIGITS digits (zero included) or is below RIGID_PIVOT_RATIO of
    !> the largest diagonal term (round-off level: a free motion); PIVOT_ILL_CONDITIONED
    !> when pivots only exceed NPREC; PIVOT_REGULAR otherwise. On return diag%n_flagged
    !> holds the equation to name (free numbering) and diag%where the pivot text after it.
    !> With the check off (check_disabled) the solver reports only the pivots it held.
    subroutine classify_pivots(report, pivots, largest, options, diag)
        type(factor_report_t), intent(in) :: report
        real(dp), intent(in) :: pivots(:), largest
        type(solver_options_t), intent(in) :: options
        type(pivot_diagnosis_t), intent(inout) :: diag
        integer(i4) :: rigid, eq
        diag%nprec = effective_nprec(options)
        diag%kind = PIVOT_REGULAR
        rigid = 0
        if (size(pivots) > 0) rigid = findloc(abs(pivots) <= RIGID_PIVOT_RATIO * largest, &
            .true., dim=1)
        eq = report%max_digits_equation
        if (report%max_digits_lost >= FREE_PIVOT_DIGITS .and. eq > 0) then
            diag%kind = PIVOT_FREE
        else if (rigid > 0) then
            diag%kind = PIVOT_FREE
            diag%n_flagged = rigid
            diag%where = ' (pivot ' // real_e13(pivots(rigid)) // ' against a largest ' // &
                'diagonal term ' // real_e13(largest) // ')'
            return
        else if (report%n_flagged > 0) then
            diag%kind = PIVOT_ILL_CONDITIONED
            if (.not. report%max_digits_lost > real(diag%nprec, dp)) &
                eq = report%flagged_equations(1)
        else
            return
        end if
        diag%n_flagged = eq
        diag%where = ' (pivot lost ' // real_digits(max(report%max_digits_lost, 0.0_dp)) // &
            ' digits, NPREC = ' // nprec_text(options) // ')'
        if (check_disabled(options)) diag%where = ' (pivot held: NPREC < 0, check off)'
    end subroutine classify_pivots

    !> A flagged matrix that is not an iterate's overshoot: STATUS_SINGULAR (STOP_SINGULIER
    !> = OUI) or a warning line (NON). A free pivot means a missing support or stiffness;
    !> an ill-conditioned one means the model's stiffness contrast exceeds NPREC.
    subroutine report_pivots(diag, options, t, log, st)
        type(pivot_diagnosis_t), intent(in) :: diag
        type(solver_options_t), intent(in) :: options
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        if (diag%kind == PIVOT_FREE) then
            text = 'singular matrix at ' // diag%where // ', ' // to_text(max(diag%n_flagged, &
                1_i4)) // ' pivot(s) flagged: the equation is free (round-off pivot); a ' // &
                'support (DDL_IMPO) or a stiffness is missing there'
        else
            text = 'ill-conditioned matrix at ' // diag%where // ': more than NPREC but ' // &
                'fewer than ' // real_digits(FREE_PIVOT_DIGITS) // ' digits lost, so the ' // &
                'structure is held but its stiffness contrast costs that many digits; ' // &
                'if the contrast is expected raise SOLVEUR/NPREC (Code_Aster''s SSNL130 ' // &
                'uses NPREC = 9)'
            if (options%stop_singular) text = text // ', or set STOP_SINGULIER = ''NON''' &
                // ' to go on with a warning'
        end if
        if (options%stop_singular) then
            call set_error(st, STATUS_SINGULAR, 'INST ' // real_e13(t) // ': ' // text)
        else
            call log_add(log, '  warning (STOP_SINGULIER = NON): ' // text)
        end if
    end subroutine report_pivots

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

    function history_text(values) result(text)
        real(dp), intent(in) :: values(0:)
        character(len=:), allocatable :: text
        integer(i4) :: k
        character(len=12) :: buf
        text = ''
        do k = 0, int(ubound(values, 1), i4)
            write (buf, '(es10.3)') values(k)
            text = text // ' ' // trim(adjustl(buf))
        end do
    end function history_text

    function real_digits(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=8) :: buf
        write (buf, '(f5.1)') x
        text = trim(adjustl(buf))
    end function real_digits

    !> The terminal line of a finished step: INST, iterations, residual, springs closed and
    !> changed in the step, factorizations, wall time.
    function step_line(t, step, n_steps, iterations, resi_rela, zero_load, n_closed, &
                       n_changed, n_springs, factorizations, seconds) result(text)
        real(dp), intent(in) :: t, resi_rela, seconds
        integer(i4), intent(in) :: step, n_steps, iterations, n_closed, n_changed, n_springs, &
            factorizations
        logical, intent(in) :: zero_load
        character(len=:), allocatable :: text
        text = 'INST ' // real_short(t) // ' (step ' // to_text(step) // '/' // &
            to_text(n_steps) // '): ' // to_text(iterations) // ' iteration(s), '
        if (zero_load) then
            text = text // 'no load (absolute criterion)'
        else
            text = text // 'RESI_GLOB_RELA ' // real_short(resi_rela)
        end if
        text = text // ', ' // to_text(n_closed) // ' of ' // to_text(n_springs) // &
            ' springs closed (' // to_text(n_changed) // ' changed), ' // &
            to_text(factorizations) // ' factorization(s), ' // seconds_text(seconds) // ' s'
    end function step_line

    !> Seconds with three decimals (the TIME column's precision).
    function seconds_text(seconds) result(text)
        real(dp), intent(in) :: seconds
        character(len=:), allocatable :: text
        character(len=24) :: buf
        write (buf, '(f0.3)') max(seconds, 0.0_dp)
        text = trim(buf)
        if (text(1:1) == '.') text = '0' // text
    end function seconds_text

    !> One row of the Newton table.
    function iteration_row(iter, resi_rela, resi_maxi, zero_load, use, mode, n_closed, &
                           changed, seconds) result(line)
        integer(i4), intent(in) :: iter, use, mode, n_closed, changed
        real(dp), intent(in) :: resi_rela, resi_maxi, seconds
        logical, intent(in) :: zero_load
        character(len=100) :: line
        character(len=22) :: matrix
        character(len=14) :: rela
        character(len=9), parameter :: modes(0:2) = [character(len=9) :: ' reused', &
            ' factored', ' updated']
        matrix = merge('ELASTIQUE', 'TANGENTE ', use == MATRIX_ELASTIC)
        matrix = trim(matrix) // modes(mode)
        write (rela, '(es14.6)') resi_rela
        if (zero_load) rela = '     undefined'
        write (line, '(i5, 2x, a14, 2x, es14.6, 2x, a22, i6, i8, f9.3)') iter, rela, &
            resi_maxi, matrix, n_closed, changed, seconds
    end function iteration_row

    !> Folds one factorization's diagnostics into the running ones.
    subroutine accumulate_pivots(diag, acc)
        type(pivot_diagnosis_t), intent(in) :: diag
        type(newton_summary_t), intent(inout) :: acc
        if (diag%digits >= acc%max_digits_lost .or. .not. allocated(acc%digits_at)) then
            acc%max_digits_lost = diag%digits
            acc%digits_at = diag%digits_at
        end if
        acc%min_pivot = min(acc%min_pivot, diag%min_pivot)
        acc%max_pivot = max(acc%max_pivot, diag%max_pivot)
    end subroutine accumulate_pivots

    !> The .mess line of solver diagnostics (style.md): the method, the largest loss of
    !> significant digits over the factorizations, where, against NPREC (as given: -1 is
    !> reported as -1, "check off" for MUMPS), and the range of |pivot|.
    function solver_diagnostics_line(acc, nprec, method) result(text)
        type(newton_summary_t), intent(in) :: acc
        integer(i4), intent(in) :: nprec
        character(len=*), intent(in) :: method
        character(len=:), allocatable :: text
        type(solver_options_t) :: opt
        opt%method = method
        opt%nprec = nprec
        text = 'solver ' // trim(method) // ': largest loss ' // &
            real_digits(acc%max_digits_lost) // ' digits'
        if (allocated(acc%digits_at)) then
            if (len(acc%digits_at) > 0) text = text // ' at ' // acc%digits_at
        end if
        text = text // ' (NPREC ' // to_text(nprec)
        if (check_disabled(opt)) then
            text = text // ': check off'
        else if (nprec <= 0) then
            text = text // ', read as ' // to_text(effective_nprec(opt))
        end if
        text = text // '), |pivot| from ' // real_short(acc%min_pivot) // ' to ' // &
            real_short(acc%max_pivot)
    end function solver_diagnostics_line

end module contact_newton

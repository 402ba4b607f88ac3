!> What STAT_NON_LINE's contact Newton carries (contact_newton and the modules it is
!> split into): the NEWTON/CONVERGENCE/SOLVEUR options, the analysis state from iteration to
!> iteration and step to step (displacements and forces, the one assembled matrix and its
!> factor with the contact status it holds), the pivot findings of a step, the summary of
!> what each step cost; and the convergence criteria (RESI_GLOB_RELA, RESI_GLOB_MAXI,
!> Code_Aster U4.51.03).
module newton_state
    use kinds, only: dp, i4
    use sparse_matrix, only: sym_matrix_t
    use direct_solver, only: direct_solver_t, solver_options_t
    use assembly_system, only: assembly_map_t, linear_cache_t, contact_history_t, &
        free_residual_max
    use assembly_relations, only: has_relations
    use low_rank_update, only: block_set_t
    use analysis_solver, only: held_t, pivot_diagnosis_t, pivot_record_t, PIVOT_REGULAR, &
        PIVOT_UNKNOWN
    use run_deadline, only: deadline_t
    use number_limits, only: product_fits
    use progress, only: progress_t
    use time_stepping, only: step_cutting_t
    use residual_line_search, only: line_search_options_t
    implicit none
    private

    !> Code_Aster defaults (U4.51.03): RESI_GLOB_RELA 1e-6, ITER_GLOB_MAXI 10.
    real(dp), parameter, public :: DEFAULT_RESI_GLOB_RELA = 1.0e-6_dp
    integer(i4), parameter, public :: DEFAULT_ITER_GLOB_MAXI = 10
    !> Which matrix an iteration uses.
    integer(i4), parameter, public :: MATRIX_NONE = 0, MATRIX_ELASTIC = 1, MATRIX_TANGENT = 2
    !> How an iteration's matrix was solved (the MATRIX column of the Newton table): with
    !> the factor it already had, after a new factorization, or through the factor of
    !> another contact status updated by the springs that differ (low_rank_update).
    integer(i4), parameter, public :: BY_REUSED_FACTOR = 0, BY_NEW_FACTOR = 1, &
        BY_UPDATED_FACTOR = 2

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
        !> what a step that fails does (DEFI_LIST_INST/ECHEC; off: the analysis stops)
        type(step_cutting_t) :: cutting
        type(solver_options_t) :: factor           !< SOLVEUR: METHODE, RENUM, NPREC ...
        type(line_search_options_t) :: line        !< RECH_LINEAIRE (residual_line_search)
        type(deadline_t) :: deadline               !< the run's time limit, polled per iteration
        !> the run's reporter: a line per step, the work under way (null: nobody listens)
        class(progress_t), pointer :: progress => null()
    end type newton_options_t

    !> What each step cost.
    type, public, extends(pivot_record_t) :: newton_summary_t
        integer(i4) :: n_steps = 0
        real(dp), allocatable :: inst(:)
        integer(i4), allocatable :: iterations(:)      !< Newton iterations (excl. prediction)
        integer(i4), allocatable :: factorizations(:)
        integer(i4), allocatable :: solves(:)          !< solves with a factor
        integer(i4), allocatable :: updated(:)         !< tangents through another factor
        integer(i4), allocatable :: damped(:)          !< corrections the line search damped
        real(dp), allocatable :: resi_rela(:), resi_maxi(:)
    end type newton_summary_t

    !> The analysis state carried from iteration to iteration and step to step.
    type, public :: newton_state_t
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
        !> evaluations of the internal forces in this step, and their wall time (s)
        integer(i4) :: force_evaluations = 0
        real(dp) :: force_seconds = 0.0_dp
        logical :: refactored = .false.
        integer(i4) :: nprec = 0            !< SOLVEUR/NPREC
        type(solver_options_t) :: solver_options
        type(pivot_record_t) :: pivots     !< solver diagnostics over the factorizations
    end type newton_state_t

    !> Pivot findings of one step (matrix_for_iteration).
    type, public :: step_pivots_t
        integer(i4) :: n_free = 0                      !< consecutive free-tangent iterations
        logical :: free_now = .false.
        character(len=:), allocatable :: free_where    !< last free pivot
        type(pivot_diagnosis_t) :: ill                 !< last ill-conditioned tangent ...
        logical, allocatable :: ill_closed(:)          !< ... and its contact status
        !> last tangent solved through another status's factor, and its digits bound
        logical, allocatable :: updated_closed(:)
        real(dp) :: updated_bound = 0.0_dp
    end type step_pivots_t

    public :: residual_measures, resi_denominator, criterion_tolerance, absolute_tol, &
        criteria_met, prediction_is_elastic

contains

    !> RESI_GLOB_MAXI = max|f_ext - f_int| over the free equations (with linear relations
    !> the free equations' residual T^T (f_ext - f_int), the relations' forces on the slaves
    !> taken out: assembly_system free_residual_max) and RESI_GLOB_RELA = that /
    !> max(max|f_ext|, max|reactions|); zero_load when the denominator is 0 (then resi_rela
    !> is returned as 0 and the caller must use the absolute criterion).
    pure subroutine residual_measures(map, fint, fext, resi_rela, resi_maxi, zero_load)
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: fint(:), fext(:)
        real(dp), intent(out) :: resi_rela, resi_maxi
        logical, intent(out) :: zero_load
        real(dp) :: denominator
        if (has_relations(map%elim)) then
            resi_maxi = free_residual_max(map, fint, fext)
        else
            resi_maxi = maxval(abs(fext - fint), mask=.not. map%imposed, dim=1)
            if (count(.not. map%imposed) == 0) resi_maxi = 0.0_dp
        end if
        denominator = resi_denominator(map%constrained, fint, fext)
        zero_load = .not. denominator > 0.0_dp
        resi_rela = 0.0_dp
        if (.not. zero_load) resi_rela = resi_maxi / denominator
    end subroutine residual_measures

    !> The denominator of RESI_GLOB_RELA: max(max|f_ext|, max|reactions|), the reactions
    !> being f_int - f_ext on the constrained equations (imposed, or in a relation).
    pure real(dp) function resi_denominator(constrained, fint, fext) result(denominator)
        logical, intent(in) :: constrained(:)
        real(dp), intent(in) :: fint(:), fext(:)
        denominator = maxval(abs(fext), dim=1)
        if (any(constrained)) denominator = max(denominator, &
            maxval(abs(fint - fext), mask=constrained, dim=1))
    end function resi_denominator

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

    !> The convergence tolerance in newtons at the current iterate: RESI_GLOB_RELA times
    !> its denominator and/or RESI_GLOB_MAXI (the smaller), or the zero-load tolerance.
    real(dp) function criterion_tolerance(options, map, state) result(tolerance)
        type(newton_options_t), intent(in) :: options
        type(assembly_map_t), intent(in) :: map
        type(newton_state_t), intent(in) :: state
        real(dp) :: denominator
        denominator = resi_denominator(map%constrained, state%fint, state%fext)
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

    !> The prediction's matrix: PREDICTION, or MATRICE when PREDICTION is not given.
    pure logical function prediction_is_elastic(options) result(elastic)
        type(newton_options_t), intent(in) :: options
        elastic = options%matrix_elastic
        if (options%prediction_given) elastic = options%prediction_elastic
    end function prediction_is_elastic

end module newton_state

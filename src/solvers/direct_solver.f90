!> One interface for the sparse direct solvers (style.md: FEMPAR's base direct solver, the
!> phases of MUMPS and CHOLMOD): `analyse` a sparsity pattern once (ordering, symbolic
!> factorization, memory estimate), `factor` its values as often as they change, `solve`
!> one or many right-hand sides, and a `factor_report_t` of diagnostics for the .mess and
!> the pivot classification of the analyses. Each back-end extends `direct_solver_t` in its
!> own file and is named as Code_Aster's SOLVEUR/METHODE (U4.50.01): LDLT (parasol's
!> skyline), MULT_FRONT (CHOLMOD supernodal), MUMPS. Callers never see which library runs.
!>
!> The matrix is the assembly's `sym_matrix_t` (upper triangle by columns). Equations are
!> numbered by the caller; diagnostics name equations in that numbering.
!>
!> NPREC (SOLVEUR/NPREC, Code_Aster U4.50.01 §3): LDLT and MULT_FRONT read |NPREC| (0 means
!> the default 8): a pivot that lost more than NPREC digits against its original diagonal
!> is flagged. MUMPS reads NPREC >= 0 as the same test and NPREC < 0 as "no singularity
!> check" (Code_Aster then switches MUMPS's null-pivot detection off).
!>
!> Held pivots: a pivot the caller asks to hold (zero, or below `hold_digits` / `hold_ratio`)
!> is replaced by HOLD_PENALTY times its original diagonal, so its equation comes out ~0
!> instead of Inf/NaN or round-off noise. Each back-end does that in its own way (the
!> skyline in the factorization, CHOLMOD by a penalty and a new factorization, MUMPS by
!> its null-pivot fixation).
module direct_solver
    use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_SINGULAR
    use strings, only: to_text
    use sparse_matrix, only: sym_matrix_t
    use progress, only: progress_t
    implicit none
    private

    !> Code_Aster SOLVEUR/NPREC default: a pivot losing more than 8 digits is singular.
    integer(i4), parameter, public :: NPREC_DEFAULT = 8
    !> Why a pivot was flagged.
    integer(i4), parameter, public :: PIVOT_DIGITS_LOST = 1, PIVOT_ZERO = 2, PIVOT_NEGATIVE = 3
    !> Digits reported for a zero pivot: more than a double holds (-log10(eps) = 15.65).
    real(dp), parameter, public :: DIGITS_ALL_LOST = 16.0_dp
    !> OpenMP threads of the plug-ins' libraries (limit_openmp_threads).
    character(len=*), parameter :: OPENMP_THREAD_LIMIT = '1'
    !> A held pivot becomes this factor times its original diagonal (its unknown ~0).
    real(dp), parameter, public :: HOLD_PENALTY = 1.0e16_dp

    !> How to factor and what counts as singular (SOLVEUR keywords).
    type, public :: solver_options_t
        character(len=16) :: method = 'LDLT'         !< SOLVEUR/METHODE
        character(len=16) :: renum = ''              !< SOLVEUR/RENUM ('' = method default)
        integer(i4) :: nprec = NPREC_DEFAULT         !< SOLVEUR/NPREC, as given
        logical :: stop_singular = .true.            !< SOLVEUR/STOP_SINGULIER = 'OUI'
        logical :: positive_definite = .false.       !< a negative pivot is then flagged
        real(dp) :: hold_digits = 0.0_dp             !< hold pivots losing >= this (0: off)
        real(dp) :: hold_ratio = 0.0_dp              !< hold |pivot| <= this x max|a_jj|
        integer(i4) :: kernel = 0                    !< LDLT: 0 auto, 1 reference, 2 blocked
        !> The iterative methods GCPC and PETSC (krylov_solver; U4.50.01 defaults):
        character(len=16) :: pre_cond = ''            !< PRE_COND ('' = the method's default)
        character(len=16) :: algorithm = ''           !< ALGORITHME (PETSC; GCPC is CG)
        real(dp) :: resi_rela = 1.0e-6_dp             !< RESI_RELA: ||b - A x|| / ||b||
        integer(i4) :: nmax_iter = 0                  !< NMAX_ITER (0: krylov_solver's limit)
    end type solver_options_t

    !> What a factorization saw (the .mess solver lines, the pivot classification).
    type, public :: factor_report_t
        character(len=:), allocatable :: method        !< LDLT, MULT_FRONT, MUMPS
        character(len=:), allocatable :: ordering      !< the fill-reducing ordering used
        integer(i4) :: n_equations = 0
        integer(i8) :: factor_entries = 0_i8           !< stored terms of the factor
        integer(i8) :: memory_bytes = 0_i8             !< memory of the factor (estimate)
        real(dp) :: seconds = 0.0_dp                   !< wall time of the factorization
        integer(i8) :: profile_size = 0_i8             !< LDLT: stored profile
        integer(i4) :: bandwidth = 0                   !< LDLT: largest column height
        real(dp) :: max_digits_lost = 0.0_dp           !< over all pivots
        integer(i4) :: max_digits_equation = 0         !< where it happens (0 if n = 0)
        real(dp) :: min_abs_pivot = 0.0_dp             !< computed pivots, before any
        real(dp) :: max_abs_pivot = 0.0_dp             !< hold
        integer(i4) :: n_negative_pivots = 0           !< = negative eigenvalues (Sylvester)
        logical :: pivots_known = .true.               !< .false.: MUMPS (no pivot access)
        real(dp), allocatable :: pivots(:)             !< (n) computed pivot per equation
        integer(i4) :: n_flagged = 0                   !< flagged pivots, in order found:
        integer(i4), allocatable :: flagged_equations(:)  !< equation numbers
        integer(i4), allocatable :: flagged_reasons(:)    !< PIVOT_DIGITS_LOST/ZERO/NEGATIVE
        real(dp), allocatable :: flagged_digits_lost(:)   !< digits lost at each
        integer(i4) :: n_held = 0                      !< pivots held (HOLD_PENALTY)
        integer(i4), allocatable :: held_equations(:)  !< (n_held)
    end type factor_report_t

    !> A direct solver: analyse once per pattern, factor per values, solve.
    type, abstract, public :: direct_solver_t
        type(solver_options_t) :: options
        logical :: analysed = .false.
        logical :: factored = .false.
        !> From analyse, for callers weighing a new factorization against solves with the
        !> current factor (low_rank_update): stored terms of the factor and the flops of a
        !> factorization (0 when the back-end does not say).
        integer(i8) :: factor_terms = 0_i8
        real(dp) :: factor_flops = 0.0_dp
        !> Where a back-end that can tell how far its factorization is reports it (the
        !> run's reporter, set by the analysis; null: nobody listens)
        class(progress_t), pointer :: progress => null()
    contains
        procedure(analyse_interface), deferred :: analyse
        procedure(factor_interface), deferred :: factor
        procedure(solve_one_interface), deferred :: solve_one
        procedure(solve_many_interface), deferred :: solve_many
        procedure(memory_interface), deferred :: memory_estimate
        procedure :: release => release_nothing
        procedure :: iteration_summary => no_iterations
        generic :: solve => solve_one, solve_many
    end type direct_solver_t

    abstract interface
        !> Symbolic phase on the pattern of a (values not read).
        !>  st : out, the back-end's failure (library missing, out of memory ...)
        subroutine analyse_interface(self, a, st)
            import :: direct_solver_t, sym_matrix_t, status_t
            class(direct_solver_t), intent(inout) :: self
            type(sym_matrix_t), intent(in) :: a
            type(status_t), intent(out) :: st
        end subroutine analyse_interface
        !> Numerical factorization of a (same pattern as analysed); every pivot is tested
        !> (NPREC) and the report filled; held pivots as options say.
        !>  st : out, STATUS_SINGULAR when a pivot is flagged and options%stop_singular
        !>       (the factor is still complete and usable), or the back-end's failure
        subroutine factor_interface(self, a, report, st)
            import :: direct_solver_t, sym_matrix_t, factor_report_t, status_t
            class(direct_solver_t), intent(inout) :: self
            type(sym_matrix_t), intent(in) :: a
            type(factor_report_t), intent(out) :: report
            type(status_t), intent(out) :: st
        end subroutine factor_interface
        !> b <- A^-1 b with the factor.
        subroutine solve_one_interface(self, b, st)
            import :: direct_solver_t, dp, status_t
            class(direct_solver_t), intent(inout) :: self
            real(dp), intent(inout) :: b(:)
            type(status_t), intent(out) :: st
        end subroutine solve_one_interface
        !> b(:, k) <- A^-1 b(:, k) for every column.
        subroutine solve_many_interface(self, b, st)
            import :: direct_solver_t, dp, status_t
            class(direct_solver_t), intent(inout) :: self
            real(dp), intent(inout) :: b(:, :)
            type(status_t), intent(out) :: st
        end subroutine solve_many_interface
        !> Bytes the factor will take (after analyse; 0 before).
        function memory_interface(self) result(bytes)
            import :: direct_solver_t, i8
            class(direct_solver_t), intent(in) :: self
            integer(i8) :: bytes
        end function memory_interface
    end interface

    public :: digits_lost, record_flag, record_hold, singular_message, effective_nprec, &
        nprec_text, &
        check_disabled, start_report, limit_openmp_threads

    interface
        function c_setenv(name, value, overwrite) result(rc) bind(c, name='setenv')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: name(*), value(*)
            integer(c_int), value :: overwrite
            integer(c_int) :: rc
        end function c_setenv
    end interface

contains

    !> Before a back-end plug-in is opened: OpenMP threads limited to OPENMP_THREAD_LIMIT
    !> unless the user set OMP_THREAD_LIMIT (libgomp reads it when it is loaded, i.e. with
    !> the plug-in). Debian's CHOLMOD 3 runs its copy loops on a fixed 4 OpenMP threads
    !> whatever OMP_NUM_THREADS says; on the 2-core machine of doc/performance.md that made
    !> each 32 x 128 factorization 4-20 times slower (90 000 context switches per run). The
    !> heavy work is BLAS 3, threaded by OpenBLAS, which this does not touch.
    subroutine limit_openmp_threads()
        integer(c_int) :: rc
        rc = c_setenv('OMP_THREAD_LIMIT' // c_null_char, OPENMP_THREAD_LIMIT // c_null_char, &
            0_c_int)
    end subroutine limit_openmp_threads

    !> What the iterations of an iterative method did, for the .mess ('' for a direct one).
    function no_iterations(self) result(text)
        class(direct_solver_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = ''
        if (.false.) text = trim(self%options%method)
    end function no_iterations

    !> Frees the back-end's memory (default: nothing to free).
    subroutine release_nothing(self)
        class(direct_solver_t), intent(inout) :: self
        self%analysed = .false.
        self%factored = .false.
    end subroutine release_nothing

    !> NPREC as the method reads it: |NPREC| with 0 -> 8 (LDLT, MULT_FRONT; MUMPS with
    !> NPREC >= 0 too). MUMPS with NPREC < 0: no check (see check_disabled).
    pure integer(i4) function effective_nprec(options)
        type(solver_options_t), intent(in) :: options
        effective_nprec = abs(options%nprec)
        if (effective_nprec == 0) effective_nprec = NPREC_DEFAULT
    end function effective_nprec

    !> NPREC for messages: as the deck wrote it, and how the method reads it when that
    !> differs ("-1, read as 1 by LDLT"): a message must not show a value nobody wrote.
    function nprec_text(options) result(text)
        type(solver_options_t), intent(in) :: options
        character(len=:), allocatable :: text
        text = to_text(options%nprec)
        if (effective_nprec(options) /= options%nprec) text = text // ', read as ' // &
            to_text(effective_nprec(options)) // ' by ' // trim(options%method)
    end function nprec_text

    !> Code_Aster U4.50.01: with METHODE='MUMPS' a negative NPREC switches the singularity
    !> check off; LDLT and MULT_FRONT read |NPREC|.
    pure logical function check_disabled(options)
        type(solver_options_t), intent(in) :: options
        check_disabled = trim(options%method) == 'MUMPS' .and. options%nprec < 0
    end function check_disabled

    !> Empty report of n equations for `method` (flag arrays allocated, empty).
    subroutine start_report(report, method, n)
        type(factor_report_t), intent(out) :: report
        character(len=*), intent(in) :: method
        integer(i4), intent(in) :: n
        report%method = method
        report%ordering = ''
        report%n_equations = n
        allocate (report%flagged_equations(0), report%flagged_reasons(0), &
            report%flagged_digits_lost(0), report%held_equations(0))
    end subroutine start_report

    !> Digits lost by a pivot: log10(|original| / |pivot|); DIGITS_ALL_LOST when the pivot is
    !> zero relative to the original (|pivot| <= eps |original|, or subnormal); 0 when
    !> original = 0 and the pivot is not zero (no reference to lose digits from).
    !>  pivot, original : in, d_i and a_ii
    !>  reference       : in, magnitude used for the zero test when original = 0
    pure real(dp) function digits_lost(pivot, original, reference)
        real(dp), intent(in) :: pivot, original, reference
        real(dp) :: ref
        ref = abs(original)
        if (ref <= 0.0_dp) ref = abs(reference)
        ! Zero: every digit lost, or below the normal range (its reciprocal could overflow).
        if (abs(pivot) <= epsilon(1.0_dp) * ref .or. abs(pivot) < tiny(1.0_dp)) then
            digits_lost = DIGITS_ALL_LOST
        else if (abs(original) > 0.0_dp) then
            digits_lost = log10(abs(original) / abs(pivot))
        else
            digits_lost = 0.0_dp
        end if
    end function digits_lost

    !> Appends a flagged pivot to the report (arrays grow by doubling).
    subroutine record_flag(report, j, reason, lost)
        type(factor_report_t), intent(inout) :: report
        integer(i4), intent(in) :: j, reason
        real(dp), intent(in) :: lost
        integer(i4), allocatable :: ti(:)
        real(dp), allocatable :: tr(:)
        integer(i4) :: m
        m = report%n_flagged
        if (m == size(report%flagged_equations)) then
            allocate (ti(max(8, 2 * m)))
            ti(1:m) = report%flagged_equations(1:m)
            call move_alloc(ti, report%flagged_equations)
            allocate (ti(max(8, 2 * m)))
            ti(1:m) = report%flagged_reasons(1:m)
            call move_alloc(ti, report%flagged_reasons)
            allocate (tr(max(8, 2 * m)))
            tr(1:m) = report%flagged_digits_lost(1:m)
            call move_alloc(tr, report%flagged_digits_lost)
        end if
        m = m + 1
        report%flagged_equations(m) = j
        report%flagged_reasons(m) = reason
        report%flagged_digits_lost(m) = lost
        report%n_flagged = m
    end subroutine record_flag

    !> Appends a held equation to the report.
    subroutine record_hold(report, j)
        type(factor_report_t), intent(inout) :: report
        integer(i4), intent(in) :: j
        integer(i4), allocatable :: ti(:)
        integer(i4) :: m
        m = report%n_held
        if (m == size(report%held_equations)) then
            allocate (ti(max(8, 2 * m)))
            ti(1:m) = report%held_equations(1:m)
            call move_alloc(ti, report%held_equations)
        end if
        m = m + 1
        report%held_equations(m) = j
        report%n_held = m
    end subroutine record_hold

    !> STATUS_SINGULAR for the first flagged pivot (equation numbers: the caller maps them
    !> to nodes and components).
    subroutine singular_message(report, options, st)
        type(factor_report_t), intent(in) :: report
        type(solver_options_t), intent(in) :: options
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        integer(i4) :: j
        character(len=16) :: buf
        j = report%flagged_equations(1)
        select case (report%flagged_reasons(1))
        case (PIVOT_ZERO)
            text = 'matrix is singular: the pivot of equation ' // to_text(j) // &
                   ' is zero (all significant digits lost)'
        case (PIVOT_NEGATIVE)
            text = 'matrix is not positive definite: the pivot of equation ' // to_text(j) &
                   // ' is negative'
        case default
            write (buf, '(f0.1)') report%flagged_digits_lost(1)
            text = 'matrix is singular: the pivot of equation ' // to_text(j) // ' lost ' // &
                   trim(adjustl(buf)) // ' significant digits (more than NPREC = ' // &
                   nprec_text(options) // ')'
        end select
        if (report%n_flagged > 1) then
            text = text // '; ' // to_text(report%n_flagged) // ' equations flagged in all'
        end if
        text = text // ' (a rigid-body motion or mechanism left free? check the boundary ' &
               // 'conditions)'
        call set_error(st, STATUS_SINGULAR, text)
    end subroutine singular_message

end module direct_solver

!> METHODE='MULT_FRONT': CHOLMOD's supernodal Cholesky (SuiteSparse) behind the
!> direct-solver interface. Code_Aster's MULT_FRONT is its own multifrontal LDL^T; parasol
!> runs CHOLMOD's supernodal LL^T, the same family of method (a fill-reducing ordering,
!> dense frontal blocks through BLAS 3) on the same symmetric matrices.
!>
!> CHOLMOD lives in the plug-in libparasol_cholmod.so (plugins/cholmod), opened on the first
!> analyse (dynamic_library): runs that do not ask for MULT_FRONT never load it.
!>
!> Pivots: d_j = L_jj^2 (the LDL^T pivot of the same ordering), tested with NPREC against
!> the original diagonal as LDLT does. LL^T cannot pass a pivot <= 0: CHOLMOD stops there
!> (not positive definite); that equation is flagged as a zero pivot (every digit lost),
!> held (HOLD_PENALTY on its diagonal) and the matrix factored again, so a singular
!> matrix still gives a usable factor, as the skyline does. Pivots the options ask to hold
!> (hold_digits, hold_ratio) are held the same way.
module cholmod_solver
    use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_null_ptr, c_associated, &
        c_int32_t, c_int64_t, c_double, c_f_procpointer
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL, STATUS_IO_ERROR
    use strings, only: to_text
    use dynamic_library, only: dynamic_library_t, open_library, find_symbol
    use install_layout, only: plugin_file_path
    use sparse_matrix, only: sym_matrix_t, sym_diagonal
    use direct_solver, only: direct_solver_t, factor_report_t, effective_nprec, &
        limit_openmp_threads, &
        start_report, digits_lost, record_flag, record_hold, singular_message, &
        PIVOT_DIGITS_LOST, PIVOT_ZERO, PIVOT_NEGATIVE, DIGITS_ALL_LOST, HOLD_PENALTY
    implicit none
    private

    !> The plug-in's file name (in <build>/lib/parasol or <prefix>/lib/parasol).
    character(len=*), parameter, public :: CHOLMOD_PLUGIN = 'libparasol_cholmod.so'
    !> Factorizations one `factor` may take to hold the pivots CHOLMOD cannot pass; a
    !> matrix with more free equations than this is reported as such, not factored.
    integer(i4), parameter :: MAX_HOLD_ROUNDS = 64

    abstract interface
        function create_fn(ordering) result(h) bind(c)
            import :: c_ptr, c_int32_t
            integer(c_int32_t), value :: ordering
            type(c_ptr) :: h
        end function create_fn
        subroutine destroy_fn(h) bind(c)
            import :: c_ptr
            type(c_ptr), value :: h
        end subroutine destroy_fn
        function analyse_fn(h, n, col_ptr, row_index, lnz, flops, info) result(rc) bind(c)
            import :: c_ptr, c_int64_t, c_int32_t, c_double
            type(c_ptr), value :: h
            integer(c_int64_t), value :: n
            integer(c_int64_t), intent(in) :: col_ptr(*)
            integer(c_int32_t), intent(in) :: row_index(*)
            integer(c_int64_t), intent(out) :: lnz
            real(c_double), intent(out) :: flops
            integer(c_int32_t), intent(out) :: info
            integer(c_int32_t) :: rc
        end function analyse_fn
        function factor_fn(h, values, n_hold, hold, penalty, scale, minor, pivots, info) &
            result(rc) bind(c)
            import :: c_ptr, c_int64_t, c_int32_t, c_double
            type(c_ptr), value :: h
            real(c_double), intent(in) :: values(*)
            integer(c_int64_t), value :: n_hold
            integer(c_int64_t), intent(in) :: hold(*)
            real(c_double), value :: penalty, scale
            integer(c_int64_t), intent(out) :: minor
            real(c_double), intent(inout) :: pivots(*)
            integer(c_int32_t), intent(out) :: info
            integer(c_int32_t) :: rc
        end function factor_fn
        function solve_fn(h, nrhs, b, info) result(rc) bind(c)
            import :: c_ptr, c_int64_t, c_int32_t, c_double
            type(c_ptr), value :: h
            integer(c_int64_t), value :: nrhs
            real(c_double), intent(inout) :: b(*)
            integer(c_int32_t), intent(out) :: info
            integer(c_int32_t) :: rc
        end function solve_fn
        function info_fn(h, ordering, in_use, peak) result(rc) bind(c)
            import :: c_ptr, c_int64_t, c_int32_t
            type(c_ptr), value :: h
            integer(c_int32_t), intent(out) :: ordering
            integer(c_int64_t), intent(out) :: in_use, peak
            integer(c_int32_t) :: rc
        end function info_fn
    end interface

    !> The CHOLMOD back-end.
    type, extends(direct_solver_t), public :: cholmod_solver_t
        type(dynamic_library_t) :: library
        type(c_ptr) :: handle = c_null_ptr
        procedure(create_fn), nopass, pointer :: c_create => null()
        procedure(destroy_fn), nopass, pointer :: c_destroy => null()
        procedure(analyse_fn), nopass, pointer :: c_analyse => null()
        procedure(factor_fn), nopass, pointer :: c_factor => null()
        procedure(solve_fn), nopass, pointer :: c_solve => null()
        procedure(info_fn), nopass, pointer :: c_info => null()
        integer(i4) :: n = 0
        integer(i8) :: factor_entries = 0
    contains
        procedure :: analyse => cholmod_analyse
        procedure :: factor => cholmod_factor
        procedure :: solve_one => cholmod_solve_one
        procedure :: solve_many => cholmod_solve_many
        procedure :: memory_estimate => cholmod_memory
        procedure :: release => cholmod_release
        final :: cholmod_final
    end type cholmod_solver_t

contains

    !> Opens the plug-in and takes its entry points (once per solver).
    subroutine load_plugin(self, st)
        class(cholmod_solver_t), intent(inout) :: self
        type(status_t), intent(out) :: st
        type(c_funptr) :: f
        if (associated(self%c_factor)) return
        call limit_openmp_threads()
        call open_library(self%library, plugin_file_path(CHOLMOD_PLUGIN), st)
        if (st%failed()) then
            call set_error(st, STATUS_IO_ERROR, 'METHODE=''MULT_FRONT'' needs its ' // &
                'plug-in: ' // st%message // ' (build parasol with CHOLMOD: apt-get ' // &
                'install libsuitesparse-dev)')
            return
        end if
        call find_symbol(self%library, 'parasol_cholmod_create', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_create)
        call find_symbol(self%library, 'parasol_cholmod_destroy', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_destroy)
        call find_symbol(self%library, 'parasol_cholmod_analyse', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_analyse)
        call find_symbol(self%library, 'parasol_cholmod_solve', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_solve)
        call find_symbol(self%library, 'parasol_cholmod_info', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_info)
        call find_symbol(self%library, 'parasol_cholmod_factor', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_factor)
    end subroutine load_plugin

    !> CHOLMOD's ordering and symbolic factorization of the pattern.
    subroutine cholmod_analyse(self, a, st)
        class(cholmod_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(status_t), intent(out) :: st
        integer(c_int32_t) :: ordering, info, rc
        integer(c_int64_t) :: lnz
        real(c_double) :: flops
        call load_plugin(self, st)
        if (st%failed()) return
        if (c_associated(self%handle)) call self%c_destroy(self%handle)
        select case (trim(self%options%renum))
        case ('AMD', 'MD')
            ordering = 1
        case default
            ordering = 0
        end select
        self%handle = self%c_create(ordering)
        if (.not. c_associated(self%handle)) then
            call set_error(st, STATUS_INTERNAL, 'MULT_FRONT: CHOLMOD could not start ' // &
                '(out of memory)')
            return
        end if
        rc = self%c_analyse(self%handle, int(a%n, c_int64_t), a%col_ptr, a%row_index, lnz, &
            flops, info)
        if (rc /= 0) then
            call set_error(st, STATUS_INTERNAL, 'MULT_FRONT: CHOLMOD analysis failed (' // &
                'code ' // to_text(int(rc, i4)) // ', CHOLMOD status ' // &
                to_text(int(info, i4)) // ')')
            return
        end if
        self%n = a%n
        self%factor_entries = lnz
        self%factor_terms = lnz
        self%factor_flops = flops
        self%analysed = .true.
        self%factored = .false.
    end subroutine cholmod_analyse

    !> Factors a; pivots CHOLMOD cannot pass, and those the options hold, are held and the
    !> matrix factored again (module header).
    subroutine cholmod_factor(self, a, report, st)
        class(cholmod_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(factor_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        real(dp), allocatable :: original(:), pivots(:), first(:)
        integer(c_int64_t), allocatable :: hold(:)
        integer(c_int64_t) :: minor
        integer(c_int32_t) :: info, rc, ord
        integer(c_int64_t) :: in_use, peak
        integer(i4) :: round, j, n_hold
        real(dp) :: scale
        logical :: more
        integer(i8) :: t0, t1, rate
        call start_report(report, 'MULT_FRONT', a%n)
        if (.not. self%analysed .or. a%n /= self%n) then
            call set_error(st, STATUS_INTERNAL, 'MULT_FRONT: factor before analyse, or ' // &
                'another pattern')
            return
        end if
        call system_clock(t0, rate)
        ! allocated first: the reallocating assignment to an unallocated local read its
        ! uninitialised bounds (valgrind, Debug build)
        allocate (original(a%n))
        original = sym_diagonal(a)
        scale = 1.0_dp
        if (a%n > 0) scale = max(maxval(abs(original)), tiny(1.0_dp))
        allocate (pivots(a%n), first(a%n), hold(max(1, a%n)))
        first = huge(1.0_dp)      ! the pivot seen before an equation was held
        n_hold = 0
        do round = 1, MAX_HOLD_ROUNDS
            pivots = 0.0_dp
            rc = self%c_factor(self%handle, a%values, int(n_hold, c_int64_t), hold, &
                HOLD_PENALTY, scale, minor, pivots, info)
            if (rc /= 0) then
                call set_error(st, STATUS_INTERNAL, 'MULT_FRONT: CHOLMOD factorization ' // &
                    'failed (code ' // to_text(int(rc, i4)) // ', CHOLMOD status ' // &
                    to_text(int(info, i4)) // ')')
                return
            end if
            more = .false.
            if (minor > 0) then
                ! LL^T stopped at a pivot <= 0: hold it and factor again
                n_hold = n_hold + 1
                hold(n_hold) = minor
                first(minor) = 0.0_dp
                cycle
            end if
            do j = 1, a%n
                if (first(j) < huge(1.0_dp)) cycle
                if (should_hold(self, pivots(j), original(j), scale)) then
                    n_hold = n_hold + 1
                    hold(n_hold) = j
                    first(j) = pivots(j)
                    more = .true.
                end if
            end do
            if (.not. more) exit
        end do
        if (minor > 0 .or. more) then
            call set_error(st, STATUS_INTERNAL, 'MULT_FRONT: more than ' // &
                to_text(MAX_HOLD_ROUNDS) // ' rounds of held pivots (' // to_text(n_hold) // &
                ' equations held); the matrix is far from regular')
            return
        end if
        ! the report sees the computed pivots (before any hold)
        where (first < huge(1.0_dp)) pivots = first
        call fill_report(self, report, pivots, original, scale)
        do j = 1, n_hold
            call record_hold(report, int(hold(j), i4))
        end do
        self%factored = .true.
        rc = self%c_info(self%handle, ord, in_use, peak)
        report%ordering = ordering_name(ord)
        report%factor_entries = self%factor_entries
        report%memory_bytes = in_use
        call system_clock(t1)
        report%seconds = real(t1 - t0, dp) / real(max(rate, 1_i8), dp)
        if (report%n_flagged > 0 .and. self%options%stop_singular) &
            call singular_message(report, self%options, st)
    end subroutine cholmod_factor

    !> A pivot to hold: zero or negative (LL^T cannot pass it), or as the options say.
    logical function should_hold(self, d, original, scale)
        class(cholmod_solver_t), intent(in) :: self
        real(dp), intent(in) :: d, original, scale
        should_hold = digits_lost(d, original, scale) >= DIGITS_ALL_LOST
        if (self%options%hold_digits > 0.0_dp) should_hold = should_hold .or. &
            digits_lost(d, original, scale) >= self%options%hold_digits
        if (self%options%hold_ratio > 0.0_dp) should_hold = should_hold .or. &
            abs(d) <= self%options%hold_ratio * scale
    end function should_hold

    !> Pivot statistics and NPREC flags, in equation order (as the skyline reports them).
    subroutine fill_report(self, report, pivots, original, scale)
        class(cholmod_solver_t), intent(in) :: self
        type(factor_report_t), intent(inout) :: report
        real(dp), intent(in) :: pivots(:), original(:), scale
        real(dp) :: lost
        integer(i4) :: j, reason, nprec
        nprec = effective_nprec(self%options)
        report%pivots = pivots
        if (size(pivots) > 0) report%min_abs_pivot = huge(1.0_dp)
        do j = 1, size(pivots, kind=i4)
            lost = digits_lost(pivots(j), original(j), scale)
            report%min_abs_pivot = min(report%min_abs_pivot, abs(pivots(j)))
            report%max_abs_pivot = max(report%max_abs_pivot, abs(pivots(j)))
            if (lost > report%max_digits_lost .or. report%max_digits_equation == 0) then
                report%max_digits_lost = lost
                report%max_digits_equation = j
            end if
            reason = 0
            if (lost >= DIGITS_ALL_LOST) then
                reason = PIVOT_ZERO
            else if (pivots(j) < 0.0_dp .and. self%options%positive_definite) then
                reason = PIVOT_NEGATIVE
            else if (lost > real(nprec, dp)) then
                reason = PIVOT_DIGITS_LOST
            end if
            if (reason /= 0) call record_flag(report, j, reason, lost)
        end do
    end subroutine fill_report

    function ordering_name(code) result(name)
        integer(c_int32_t), intent(in) :: code
        character(len=:), allocatable :: name
        select case (code)
        case (0)
            name = 'natural'
        case (2)
            name = 'AMD'
        case (3)
            name = 'METIS'
        case default
            name = 'CHOLMOD ordering ' // to_text(int(code, i4))
        end select
    end function ordering_name

    subroutine cholmod_solve_one(self, b, st)
        class(cholmod_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: st
        real(dp) :: b2(size(b), 1)
        b2(:, 1) = b
        call cholmod_solve_many(self, b2, st)
        if (st%ok()) b = b2(:, 1)
    end subroutine cholmod_solve_one

    subroutine cholmod_solve_many(self, b, st)
        class(cholmod_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: st
        integer(c_int32_t) :: rc, info
        if (.not. self%factored .or. size(b, 1) /= self%n) then
            call set_error(st, STATUS_INTERNAL, 'MULT_FRONT: solve without a factor, or ' // &
                'right-hand sides of size ' // to_text(size(b, 1, kind=i4)) // ' /= ' // &
                to_text(self%n))
            return
        end if
        if (size(b, 2) == 0 .or. self%n == 0) return
        rc = self%c_solve(self%handle, int(size(b, 2), c_int64_t), b, info)
        if (rc /= 0) call set_error(st, STATUS_INTERNAL, 'MULT_FRONT: CHOLMOD solve ' // &
            'failed (CHOLMOD status ' // to_text(int(info, i4)) // ')')
    end subroutine cholmod_solve_many

    !> Bytes of L from the analysis (8 a term, plus its row indices).
    function cholmod_memory(self) result(bytes)
        class(cholmod_solver_t), intent(in) :: self
        integer(i8) :: bytes
        bytes = 8_i8 * self%factor_entries
    end function cholmod_memory

    subroutine cholmod_release(self)
        class(cholmod_solver_t), intent(inout) :: self
        if (c_associated(self%handle) .and. associated(self%c_destroy)) &
            call self%c_destroy(self%handle)
        self%handle = c_null_ptr
        self%analysed = .false.
        self%factored = .false.
    end subroutine cholmod_release

    !> CHOLMOD's memory goes with the solver.
    subroutine cholmod_final(self)
        type(cholmod_solver_t), intent(inout) :: self
        call cholmod_release(self)
    end subroutine cholmod_final

end module cholmod_solver

!> METHODE='MUMPS': the multifrontal solver MUMPS behind the direct-solver interface, in the
!> plug-in libparasol_mumps.so (plugins/mumps), opened on the first analyse: runs that do
!> not ask for MUMPS never load it. The plug-in is built against the sequential MUMPS, or
!> against the MPI MUMPS (CMake option PARASOL_MUMPS_MPI): then `mpirun -np N parasol deck`
!> factors over N processes while process 0 runs parasol (cli starts the workers).
!>
!> Orderings (RENUM -> ICNTL(7), Code_Aster's mapping): AUTO 7, AMD 0, AMF 2, SCOTCH 3,
!> PORD 4, QAMD 6.
!>
!> Singularity (Code_Aster U4.50.01 and its MUMPS driver): NPREC >= 0 switches MUMPS's
!> null-pivot detection on (ICNTL(24) = 1) with the absolute threshold CNTL(3) = -10^-NPREC
!> and the fixation CNTL(5) = 1e20 (a null pivot is held: its unknown comes out ~0).
!> parasol gives MUMPS the matrix scaled to a unit diagonal, S A S with S = |diag A|^-1/2
!> (MUMPS's own scaling off), so that a scaled pivot is d_j / a_jj: the threshold
!> 10^-NPREC is then exactly LDLT's test "more than NPREC digits lost against the original
!> diagonal". MUMPS does not give its pivots one by one (pivots_known = .false.); to tell a
!> free equation (round-off pivot) from an ill-conditioned one, a matrix with null pivots
!> at 10^-NPREC is factored again at 10^-FREE_DIGITS: pivots null there are free (every
!> digit lost, held in the factor kept), the others are reported as having lost NPREC
!> digits (a lower bound) and are not held, as LDLT keeps them. NPREC < 0 switches the
!> check off; parasol then still holds pivots at round-off level (10^-hold_digits) so that
!> a free equation nothing loads is solved with zero displacement (the analysis judges
!> whether it is loaded).
module mumps_solver
    use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_null_ptr, c_associated, &
        c_int32_t, c_int64_t, c_double, c_f_procpointer
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL, STATUS_IO_ERROR, STATUS_SINGULAR
    use number_limits, only: product_fits
    use strings, only: to_text
    use dynamic_library, only: dynamic_library_t, open_library, find_symbol
    use install_layout, only: plugin_file_path
    use parasol_solver_config, only: MUMPS_MPI
    use sparse_matrix, only: sym_matrix_t, sym_diagonal
    use direct_solver, only: direct_solver_t, factor_report_t, effective_nprec, &
        limit_openmp_threads, &
        check_disabled, start_report, record_flag, record_hold, singular_message, &
        PIVOT_ZERO, PIVOT_DIGITS_LOST, DIGITS_ALL_LOST
    implicit none
    private

    !> The plug-in's file name (in <build>/lib/parasol or <prefix>/lib/parasol).
    character(len=*), parameter, public :: MUMPS_PLUGIN = 'libparasol_mumps.so'
    !> CNTL(5), the value null pivots are fixed to (Code_Aster's MUMPS driver).
    real(dp), parameter :: FIXATION = 1.0e20_dp
    !> Digits lost by a free (round-off) pivot, as the analyses classify them
    !> (analysis_solver FREE_PIVOT_DIGITS).
    real(dp), parameter :: FREE_DIGITS = 12.0_dp

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
        function analyse_fn(h, n, col_ptr, row_index, entries, flops, info) result(rc) &
            bind(c)
            import :: c_ptr, c_int64_t, c_int32_t, c_double
            type(c_ptr), value :: h
            integer(c_int64_t), value :: n
            integer(c_int64_t), intent(in) :: col_ptr(*)
            integer(c_int32_t), intent(in) :: row_index(*)
            integer(c_int64_t), intent(out) :: entries
            real(c_double), intent(out) :: flops
            integer(c_int32_t), intent(out) :: info(2)
            integer(c_int32_t) :: rc
        end function analyse_fn
        function factor_fn(h, values, detect, cntl3, fixation, n_null, null_list, n_negative, &
                           entries, megabytes, info) result(rc) bind(c)
            import :: c_ptr, c_int64_t, c_int32_t, c_double
            type(c_ptr), value :: h
            real(c_double), intent(in) :: values(*)
            integer(c_int32_t), value :: detect
            real(c_double), value :: cntl3, fixation
            integer(c_int64_t), intent(out) :: n_null, n_negative, entries, megabytes
            integer(c_int32_t), intent(inout) :: null_list(*)
            integer(c_int32_t), intent(out) :: info(2)
            integer(c_int32_t) :: rc
        end function factor_fn
        function solve_fn(h, nrhs, b, info) result(rc) bind(c)
            import :: c_ptr, c_int64_t, c_int32_t, c_double
            type(c_ptr), value :: h
            integer(c_int64_t), value :: nrhs
            real(c_double), intent(inout) :: b(*)
            integer(c_int32_t), intent(out) :: info(2)
            integer(c_int32_t) :: rc
        end function solve_fn
    end interface

    abstract interface
        function start_fn(rank, size) result(rc) bind(c)
            import :: c_int32_t
            integer(c_int32_t), intent(out) :: rank, size
            integer(c_int32_t) :: rc
        end function start_fn
        subroutine void_fn() bind(c)
        end subroutine void_fn
    end interface

    !> The MPI session of a distributed run (MPI build under mpirun): which process this is.
    type, public :: mumps_session_t
        logical :: active = .false.          !< MPI started by the plug-in
        integer(i4) :: rank = 0, size = 1
        type(dynamic_library_t) :: library
    end type mumps_session_t

    public :: mumps_session_start, mumps_session_stop

    !> The MUMPS back-end.
    type, extends(direct_solver_t), public :: mumps_solver_t
        type(dynamic_library_t) :: library
        type(c_ptr) :: handle = c_null_ptr
        procedure(create_fn), nopass, pointer :: c_create => null()
        procedure(destroy_fn), nopass, pointer :: c_destroy => null()
        procedure(analyse_fn), nopass, pointer :: c_analyse => null()
        procedure(factor_fn), nopass, pointer :: c_factor => null()
        procedure(solve_fn), nopass, pointer :: c_solve => null()
        integer(i4) :: n = 0
        integer(i8) :: factor_entries = 0
        real(dp), allocatable :: scale(:)     !< S, the unit-diagonal scaling (header)
    contains
        procedure :: analyse => mumps_analyse
        procedure :: factor => mumps_factor
        procedure :: solve_one => mumps_solve_one
        procedure :: solve_many => mumps_solve_many
        procedure :: memory_estimate => mumps_memory
        procedure :: release => mumps_release
        final :: mumps_final
    end type mumps_solver_t

contains

    !> Starts the distributed session when this is the MPI build run by mpirun with more
    !> than one process: process 0 goes on and runs the deck (its MUMPS calls are shared
    !> with the others); every other process serves those calls until process 0 stops, then
    !> returns with worker = .true. (it must exit quietly). Otherwise nothing happens.
    !>  st : out, the MPI plug-in cannot be loaded
    subroutine mumps_session_start(session, worker, st)
        type(mumps_session_t), intent(out) :: session
        logical, intent(out) :: worker
        type(status_t), intent(out) :: st
        type(c_funptr) :: f
        procedure(start_fn), pointer :: start
        procedure(void_fn), pointer :: serve
        character(len=16) :: value
        integer :: length, status
        integer(c_int32_t) :: rank, size
        worker = .false.
        if (.not. MUMPS_MPI) return
        ! launched by mpirun (Open MPI sets this in every process it starts)
        call get_environment_variable('OMPI_COMM_WORLD_SIZE', value, length, status)
        if (status /= 0) return
        call limit_openmp_threads()
        call open_library(session%library, plugin_file_path(MUMPS_PLUGIN), st)
        if (st%ok()) call find_symbol(session%library, 'parasol_mumps_start', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, start)
        if (start(rank, size) /= 0) then
            call set_error(st, STATUS_INTERNAL, 'MPI could not start')
            return
        end if
        session%active = .true.
        session%rank = int(rank, i4)
        session%size = int(size, i4)
        if (rank == 0 .or. size <= 1) return
        call find_symbol(session%library, 'parasol_mumps_worker', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, serve)
        call serve()
        worker = .true.
    end subroutine mumps_session_start

    !> Process 0: ends the workers and MPI (nothing outside a distributed session).
    subroutine mumps_session_stop(session)
        type(mumps_session_t), intent(inout) :: session
        type(c_funptr) :: f
        type(status_t) :: st
        procedure(void_fn), pointer :: finish
        if (.not. session%active .or. session%rank /= 0) return
        call find_symbol(session%library, 'parasol_mumps_stop', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, finish)
        call finish()
        session%active = .false.
    end subroutine mumps_session_stop

    !> Opens the plug-in and takes its entry points (once per solver).
    subroutine load_plugin(self, st)
        class(mumps_solver_t), intent(inout) :: self
        type(status_t), intent(out) :: st
        type(c_funptr) :: f
        if (associated(self%c_factor)) return
        call limit_openmp_threads()
        call open_library(self%library, plugin_file_path(MUMPS_PLUGIN), st)
        if (st%failed()) then
            call set_error(st, STATUS_IO_ERROR, 'METHODE=''MUMPS'' needs its plug-in: ' // &
                st%message // ' (build parasol with MUMPS: apt-get install ' // &
                'libmumps-seq-dev; or choose METHODE=''LDLT'')')
            return
        end if
        call find_symbol(self%library, 'parasol_mumps_create', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_create)
        call find_symbol(self%library, 'parasol_mumps_destroy', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_destroy)
        call find_symbol(self%library, 'parasol_mumps_analyse', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_analyse)
        call find_symbol(self%library, 'parasol_mumps_solve', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_solve)
        call find_symbol(self%library, 'parasol_mumps_factor', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, self%c_factor)
    end subroutine load_plugin

    !> ICNTL(7) of a RENUM (Code_Aster's mapping, module header).
    pure integer(c_int32_t) function ordering_code(renum)
        character(len=*), intent(in) :: renum
        select case (renum)
        case ('AMD')
            ordering_code = 0
        case ('AMF')
            ordering_code = 2
        case ('SCOTCH')
            ordering_code = 3
        case ('PORD')
            ordering_code = 4
        case ('QAMD')
            ordering_code = 6
        case default
            ordering_code = 7
        end select
    end function ordering_code

    !> MUMPS analysis (JOB = 1) of the pattern.
    subroutine mumps_analyse(self, a, st)
        class(mumps_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(status_t), intent(out) :: st
        integer(c_int32_t) :: info(2), rc
        integer(c_int64_t) :: entries
        real(c_double) :: flops
        call load_plugin(self, st)
        if (st%failed()) return
        if (c_associated(self%handle)) call self%c_destroy(self%handle)
        self%handle = c_null_ptr
        ! no equation (every one imposed or a slave: zzzz219a): nothing for MUMPS, which
        ! refuses N = 0 (INFOG(1) = -16); the factor and the solves are empty
        if (a%n == 0) then
            self%n = 0
            self%factor_entries = 0
            self%factor_terms = 0
            self%factor_flops = 0.0_dp
            self%analysed = .true.
            self%factored = .false.
            return
        end if
        self%handle = self%c_create(ordering_code(trim(self%options%renum)))
        if (.not. c_associated(self%handle)) then
            call set_error(st, STATUS_INTERNAL, 'MUMPS: the instance could not start')
            return
        end if
        rc = self%c_analyse(self%handle, int(a%n, c_int64_t), a%col_ptr, a%row_index, &
            entries, flops, info)
        if (rc /= 0) then
            call set_error(st, STATUS_INTERNAL, 'MUMPS analysis failed (INFOG(1) = ' // &
                to_text(int(info(1), i4)) // ', INFOG(2) = ' // to_text(int(info(2), i4)) &
                // ')')
            return
        end if
        self%n = a%n
        self%factor_entries = entries
        self%factor_terms = entries
        self%factor_flops = flops
        self%analysed = .true.
        self%factored = .false.
    end subroutine mumps_analyse

    !> MUMPS factorization (JOB = 2) of S A S with the null-pivot rules of the module header.
    subroutine mumps_factor(self, a, report, st)
        class(mumps_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(factor_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        integer(c_int32_t), allocatable :: null_list(:), free_list(:)
        real(dp), allocatable :: scaled(:)
        integer(c_int64_t) :: n_null, n_free
        integer(i4) :: k, nprec
        integer(i8) :: t0, t1, rate
        call start_report(report, 'MUMPS', a%n)
        report%pivots_known = .false.
        report%ordering = trim(self%options%renum)
        if (.not. self%analysed .or. a%n /= self%n) then
            call set_error(st, STATUS_INTERNAL, 'MUMPS: factor before analyse, or another ' &
                // 'pattern')
            return
        end if
        if (a%n == 0) then
            self%factored = .true.
            return
        end if
        call system_clock(t0, rate)
        if (MUMPS_MPI) report%ordering = report%ordering // ', ' // trim(mpi_processes()) // &
            ' MPI process(es)'
        call scale_matrix(self, a, scaled)
        allocate (null_list(max(1, a%n)), free_list(max(1, a%n)))
        nprec = effective_nprec(self%options)
        n_null = 0
        if (check_disabled(self%options)) then
            call factor_once(self, scaled, max(self%options%hold_digits, 0.0_dp), report, &
                free_list, n_free, st)
        else
            call factor_once(self, scaled, real(nprec, dp), report, null_list, n_null, st)
            n_free = 0
            if (st%ok() .and. n_null > 0) call factor_once(self, scaled, FREE_DIGITS, &
                report, free_list, n_free, st)
        end if
        if (st%failed()) return
        do k = 1, int(n_free, i4)
            call record_hold(report, int(free_list(k), i4))
            if (.not. check_disabled(self%options)) &
                call record_flag(report, int(free_list(k), i4), PIVOT_ZERO, DIGITS_ALL_LOST)
            if (report%max_digits_lost < DIGITS_ALL_LOST) then
                report%max_digits_lost = DIGITS_ALL_LOST
                report%max_digits_equation = int(free_list(k), i4)
            end if
        end do
        do k = 1, int(n_null, i4)
            if (any(free_list(1:n_free) == null_list(k))) cycle
            call record_flag(report, int(null_list(k), i4), PIVOT_DIGITS_LOST, real(nprec, dp))
            if (report%max_digits_lost < real(nprec, dp)) then
                report%max_digits_lost = real(nprec, dp)
                report%max_digits_equation = int(null_list(k), i4)
            end if
        end do
        self%factored = .true.
        call system_clock(t1)
        report%seconds = real(t1 - t0, dp) / real(max(rate, 1_i8), dp)
        if (report%n_flagged > 0 .and. self%options%stop_singular) &
            call singular_message(report, self%options, st)
    end subroutine mumps_factor

    !> Number of processes of the MPI run (Open MPI's OMPI_COMM_WORLD_SIZE; 1 without mpirun).
    function mpi_processes() result(text)
        character(len=16) :: text
        integer :: length, status
        call get_environment_variable('OMPI_COMM_WORLD_SIZE', text, length, status)
        if (status /= 0) text = '1'
    end function mpi_processes

    !> S = |diag A|^-1/2 (1 where the diagonal is 0) and the values of S A S.
    subroutine scale_matrix(self, a, scaled)
        class(mumps_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        real(dp), allocatable, intent(out) :: scaled(:)
        integer(i4) :: j
        integer(i8) :: k
        self%scale = abs(sym_diagonal(a))
        where (self%scale > 0.0_dp)
            self%scale = 1.0_dp / sqrt(self%scale)
        elsewhere
            self%scale = 1.0_dp
        end where
        allocate (scaled(size(a%values, kind=i8)))
        do j = 1, a%n
            do k = a%col_ptr(j), a%col_ptr(j + 1) - 1
                scaled(k) = a%values(k) * self%scale(a%row_index(k)) * self%scale(j)
            end do
        end do
    end subroutine scale_matrix

    !> One JOB = 2 with null pivots detected below 10^-digits (digits = 0: no detection).
    subroutine factor_once(self, scaled, digits, report, null_list, n_null, st)
        class(mumps_solver_t), intent(inout) :: self
        real(dp), intent(in) :: scaled(:), digits
        type(factor_report_t), intent(inout) :: report
        integer(c_int32_t), intent(inout) :: null_list(:)
        integer(c_int64_t), intent(out) :: n_null
        type(status_t), intent(out) :: st
        integer(c_int32_t) :: info(2), rc, detect
        integer(c_int64_t) :: n_negative, entries, megabytes
        real(c_double) :: cntl3
        detect = merge(1_c_int32_t, 0_c_int32_t, digits > 0.0_dp)
        cntl3 = -10.0_dp**(-digits)
        rc = self%c_factor(self%handle, scaled, detect, cntl3, FIXATION, n_null, null_list, &
            n_negative, entries, megabytes, info)
        if (rc /= 0) then
            call set_error(st, STATUS_INTERNAL, 'MUMPS factorization failed (INFOG(1) = ' // &
                to_text(int(info(1), i4)) // ', INFOG(2) = ' // to_text(int(info(2), i4)) &
                // ')')
            return
        end if
        report%n_negative_pivots = int(n_negative, i4)
        report%factor_entries = entries
        report%memory_bytes = megabytes * 1000000_i8
    end subroutine factor_once

    subroutine mumps_solve_one(self, b, st)
        class(mumps_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: st
        real(dp) :: b2(size(b), 1)
        b2(:, 1) = b
        call mumps_solve_many(self, b2, st)
        if (st%ok()) b = b2(:, 1)
    end subroutine mumps_solve_one

    subroutine mumps_solve_many(self, b, st)
        class(mumps_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: st
        integer(c_int32_t) :: rc, info(2)
        integer(i4) :: k
        if (.not. self%factored .or. size(b, 1) /= self%n) then
            call set_error(st, STATUS_INTERNAL, 'MUMPS: solve without a factor, or ' // &
                'right-hand sides of size ' // to_text(size(b, 1, kind=i4)) // ' /= ' // &
                to_text(self%n))
            return
        end if
        if (size(b, 2) == 0 .or. self%n == 0) return
        ! (S A S) y = S b, x = S y
        do k = 1, size(b, 2)
            b(:, k) = b(:, k) * self%scale
        end do
        rc = self%c_solve(self%handle, int(size(b, 2), c_int64_t), b, info)
        if (rc /= 0) then
            call set_error(st, STATUS_INTERNAL, 'MUMPS solve failed (INFOG(1) = ' // &
                to_text(int(info(1), i4)) // ')')
            return
        end if
        do k = 1, size(b, 2)
            ! x = S y: S = |a_jj|^-1/2 is large for a small stiffness; a product beyond double
            ! precision is a solution that cannot be represented, not a number to form
            if (.not. all(product_fits(b(:, k), self%scale))) then
                call set_error(st, STATUS_SINGULAR, 'MUMPS: the solution at equation ' // &
                    to_text(int(findloc(product_fits(b(:, k), self%scale), .false., dim=1), &
                    i4)) // ' is beyond double precision: the loads are out of all ' // &
                    'proportion to the stiffness there')
                return
            end if
            b(:, k) = b(:, k) * self%scale
        end do
    end subroutine mumps_solve_many

    !> Entries of the factor estimated by the analysis, 8 bytes each.
    function mumps_memory(self) result(bytes)
        class(mumps_solver_t), intent(in) :: self
        integer(i8) :: bytes
        bytes = 8_i8 * self%factor_entries
    end function mumps_memory

    subroutine mumps_release(self)
        class(mumps_solver_t), intent(inout) :: self
        if (c_associated(self%handle) .and. associated(self%c_destroy)) &
            call self%c_destroy(self%handle)
        self%handle = c_null_ptr
        self%analysed = .false.
        self%factored = .false.
    end subroutine mumps_release

    !> The MUMPS instance goes with the solver.
    subroutine mumps_final(self)
        type(mumps_solver_t), intent(inout) :: self
        call mumps_release(self)
    end subroutine mumps_final

end module mumps_solver

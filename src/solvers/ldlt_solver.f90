!> METHODE='LDLT': parasol's own skyline LDL^T (skyline_solver) behind the direct-solver
!> interface. The profile is the envelope of the pattern in the caller's numbering: the
!> skyline has no ordering of its own, so RENUM (RCMK, METIS, SANS) is applied by the
!> assembly when it numbers the equations (Code_Aster's LDLT renumbers the same way, before
!> the factorization). `analyse` sizes the profile, `factor` scatters the values into it
!> and factors in place.
module ldlt_solver
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL
    use sparse_matrix, only: sym_matrix_t
    use direct_solver, only: direct_solver_t, factor_report_t, effective_nprec
    use skyline_matrix, only: skyline_t, skyline_profile_size
    use skyline_solver, only: skyline_factor, skyline_solve, factor_options_t
    implicit none
    private

    !> The skyline back-end.
    type, extends(direct_solver_t), public :: ldlt_solver_t
        type(skyline_t) :: sky
    contains
        procedure :: analyse => ldlt_analyse
        procedure :: factor => ldlt_factor
        procedure :: solve_one => ldlt_solve_one
        procedure :: solve_many => ldlt_solve_many
        procedure :: memory_estimate => ldlt_memory
        procedure :: release => ldlt_release
    end type ldlt_solver_t

contains

    !> Profile of the pattern: column j reaches up to its first stored row.
    subroutine ldlt_analyse(self, a, st)
        class(ldlt_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(status_t), intent(out) :: st
        integer(i4) :: j
        if (.not. allocated(a%col_ptr)) then
            call set_error(st, STATUS_INTERNAL, 'LDLT: matrix without a pattern')
            return
        end if
        self%sky%n = a%n
        if (allocated(self%sky%diag)) deallocate (self%sky%diag)
        if (allocated(self%sky%values)) deallocate (self%sky%values)
        allocate (self%sky%diag(0:a%n))
        self%sky%diag(0) = 0
        do j = 1, a%n
            if (a%col_ptr(j + 1) <= a%col_ptr(j) .or. &
                a%row_index(max(a%col_ptr(j + 1) - 1, 1_i8)) /= j) then
                call set_error(st, STATUS_INTERNAL, 'LDLT: column without its diagonal')
                return
            end if
            self%sky%diag(j) = self%sky%diag(j - 1) + (j - a%row_index(a%col_ptr(j))) + 1
        end do
        allocate (self%sky%values(self%sky%diag(a%n)))
        self%sky%profile_ready = .true.
        self%sky%factored = .false.
        self%analysed = .true.
        self%factored = .false.
    end subroutine ldlt_analyse

    !> Scatters a into the profile and factors it (skyline_factor, NPREC as options say).
    subroutine ldlt_factor(self, a, report, st)
        class(ldlt_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(factor_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        type(factor_options_t) :: fo
        integer(i4) :: j
        integer(i8) :: k
        integer(i8) :: t0, t1, rate
        if (.not. self%analysed .or. a%n /= self%sky%n) then
            call set_error(st, STATUS_INTERNAL, 'LDLT: factor before analyse, or another ' &
                // 'pattern')
            return
        end if
        call system_clock(t0, rate)
        self%sky%values = 0.0_dp
        do j = 1, a%n
            do k = a%col_ptr(j), a%col_ptr(j + 1) - 1
                self%sky%values(self%sky%diag(j) - (j - a%row_index(k))) = a%values(k)
            end do
        end do
        self%sky%factored = .false.
        fo%nprec = effective_nprec(self%options)
        fo%stop_singular = self%options%stop_singular
        fo%positive_definite = self%options%positive_definite
        fo%method = self%options%kernel
        fo%hold_digits = self%options%hold_digits
        fo%hold_ratio = self%options%hold_ratio
        fo%progress => self%progress
        call skyline_factor(self%sky, report, st, fo)
        self%factored = self%sky%factored
        call system_clock(t1)
        report%seconds = real(t1 - t0, dp) / real(max(rate, 1_i8), dp)
        report%ordering = 'RENUM ' // trim(self%options%renum) // ' of the nodes'
    end subroutine ldlt_factor

    subroutine ldlt_solve_one(self, b, st)
        class(ldlt_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: st
        call skyline_solve(self%sky, b, st)
    end subroutine ldlt_solve_one

    subroutine ldlt_solve_many(self, b, st)
        class(ldlt_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: st
        call skyline_solve(self%sky, b, st)
    end subroutine ldlt_solve_many

    !> The profile, 8 bytes a term (the factor overwrites it).
    function ldlt_memory(self) result(bytes)
        class(ldlt_solver_t), intent(in) :: self
        integer(i8) :: bytes
        bytes = 8_i8 * skyline_profile_size(self%sky)
    end function ldlt_memory

    subroutine ldlt_release(self)
        class(ldlt_solver_t), intent(inout) :: self
        if (allocated(self%sky%diag)) deallocate (self%sky%diag)
        if (allocated(self%sky%values)) deallocate (self%sky%values)
        self%sky%profile_ready = .false.
        self%sky%factored = .false.
        self%analysed = .false.
        self%factored = .false.
    end subroutine ldlt_release

end module ldlt_solver

!> The iterative methods of SOLVEUR (Code_Aster U4.50.01 §3.3-3.4): METHODE='GCPC' (its
!> own preconditioned conjugate gradient) and METHODE='PETSC' (a Krylov method of PETSc's),
!> built here as parasol's own code behind the direct_solver_t interface: `analyse` keeps
!> the pattern, `factor` copies the matrix and builds the preconditioner, `solve` iterates.
!>
!> Algorithms (ALGORITHME; GCPC is always CG):
!>   CG     : preconditioned conjugate gradient (the matrix is symmetric; it must be positive
!>            definite, a breakdown p.Ap <= 0 stops with a message)
!>   FGMRES : flexible GMRES, right preconditioned, restarted every GMRES_RESTART
!>            iterations (PETSc's default restart, 30); PETSC's default ALGORITHME
!> Preconditioners (PRE_COND):
!>   LDLT_INC : incomplete Cholesky with no fill (the pattern of A, NIVE_REMPLISSAGE = 0, the
!>              default of GCPC); on a breakdown it is made on A + shift diag(A) (the
!>              shift in the .mess line)
!>   LDLT_SP  : a complete factorization (MUMPS back-end) of A rounded to single precision,
!>              as Code_Aster's single-precision MUMPS preconditioner (PETSC's default); the
!>              Krylov method then refines on the true A to RESI_RELA
!>   LDLT_DP  : the same factorization of A in double precision
!>   JACOBI   : the inverse of the diagonal;   SANS : none
!>   ML, GAMG : smoothed-aggregation algebraic multigrid, one V-cycle (amg_preconditioner;
!>              both libraries' multigrid is of that family)
!> Others (BOOMER, SOR, HPDDM, BLOC_LAGR, FIELDSPLIT, UTILISATEUR) are refused by the
!> analysis where the deck names them (unsupported_pre_cond): nothing is substituted.
!>
!> Convergence: the true residual ||b - A x||_2 <= RESI_RELA ||b||_2 (default 1e-6), from
!> x = 0, in at most NMAX_ITER iterations (0: max(MIN_ITERATION_LIMIT, number of equations),
!> parasol's reading of "the code chooses"). Not converging is STATUS_NO_CONVERGENCE with
!> the residual reached; the .mess gets the iterations of every solve (iteration_summary).
module krylov_solver
    use, intrinsic :: iso_fortran_env, only: real32
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_NO_CONVERGENCE, STATUS_SINGULAR
    use strings, only: to_text
    use sparse_matrix, only: sym_matrix_t, sym_matvec, sym_nonzeros
    use direct_solver, only: direct_solver_t, factor_report_t, start_report, record_flag, &
        PIVOT_NEGATIVE
    use mumps_solver, only: mumps_solver_t
    use amg_preconditioner, only: amg_t, amg_build, amg_apply, amg_summary
    implicit none
    private

    !> PETSc's default GMRES restart length.
    integer(i4), parameter, public :: GMRES_RESTART = 30
    !> NMAX_ITER = 0: at least this many iterations (and at least the number of equations).
    integer(i4), parameter, public :: MIN_ITERATION_LIMIT = 1000
    !> Code_Aster's defaults (c_solveur.py): PRE_COND of GCPC and of PETSC, ALGORITHME.
    character(len=*), parameter, public :: GCPC_DEFAULT_PRE_COND = 'LDLT_INC', &
        PETSC_DEFAULT_PRE_COND = 'LDLT_SP', PETSC_DEFAULT_ALGORITHM = 'FGMRES'
    !> LDLT_INC: a pivot square below this fraction of its diagonal term is a breakdown (it
    !> would lose more than 8 digits); the factorization then starts again on
    !> A + shift diag(A), the shift from IC_FIRST_SHIFT doubling at most IC_MAX_SHIFTS times.
    real(dp), parameter :: IC_BREAKDOWN_RATIO = 1.0e-8_dp, IC_FIRST_SHIFT = 1.0e-3_dp
    integer(i4), parameter :: IC_MAX_SHIFTS = 40
    !> Code_Aster's RESI_RELA default for GCPC and PETSC.
    real(dp), parameter, public :: KRYLOV_DEFAULT_RESI_RELA = 1.0e-6_dp

    type, extends(direct_solver_t), public :: krylov_solver_t
        type(sym_matrix_t) :: a                          !< the matrix factored last
        real(dp), allocatable :: inv_diag(:)             !< JACOBI
        real(dp), allocatable :: ic(:)                   !< LDLT_INC: L by rows, A's pattern
        type(mumps_solver_t), allocatable :: direct      !< LDLT_SP, LDLT_DP
        type(amg_t) :: amg                               !< ML, GAMG
        real(dp) :: ic_shift = 0.0_dp                    !< LDLT_INC: diagonal shift used
        integer(i8) :: n_solves = 0, total_iterations = 0
        integer(i4) :: max_iterations = 0
        real(dp) :: worst_residual = 0.0_dp              !< largest final relative residual
    contains
        procedure :: analyse => krylov_analyse
        procedure :: factor => krylov_factor
        procedure :: solve_one => krylov_solve_one
        procedure :: solve_many => krylov_solve_many
        procedure :: memory_estimate => krylov_memory
        procedure :: release => krylov_release
        procedure :: iteration_summary => krylov_summary
    end type krylov_solver_t

    public :: pre_cond_allowed, algorithm_allowed

contains

    !> The preconditioners parasol builds for a method (blank-separated).
    pure function pre_cond_allowed(method) result(list)
        character(len=*), intent(in) :: method
        character(len=:), allocatable :: list
        list = 'LDLT_INC LDLT_SP LDLT_DP'
        if (method == 'PETSC') list = list // ' JACOBI ML GAMG SANS'
    end function pre_cond_allowed

    !> The Krylov methods parasol builds for a method (blank-separated).
    pure function algorithm_allowed(method) result(list)
        character(len=*), intent(in) :: method
        character(len=:), allocatable :: list
        list = 'CG'
        if (method == 'PETSC') list = 'CG FGMRES'
    end function algorithm_allowed

    subroutine krylov_analyse(self, a, st)
        class(krylov_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(status_t), intent(out) :: st
        if (len_trim(self%options%pre_cond) == 0) then
            self%options%pre_cond = GCPC_DEFAULT_PRE_COND
            if (trim(self%options%method) == 'PETSC') self%options%pre_cond = PETSC_DEFAULT_PRE_COND
        end if
        if (len_trim(self%options%algorithm) == 0) then
            self%options%algorithm = 'CG'
            if (trim(self%options%method) == 'PETSC') self%options%algorithm = PETSC_DEFAULT_ALGORITHM
        end if
        select case (trim(self%options%pre_cond))
        case ('LDLT_SP', 'LDLT_DP')
            allocate (self%direct)
            self%direct%options = self%options
            self%direct%options%method = 'MUMPS'
            self%direct%options%renum = 'AUTO'
            self%direct%progress => self%progress
            call self%direct%analyse(a, st)
            if (st%failed()) return
        end select
        self%analysed = .true.
        self%factor_terms = sym_nonzeros(a)
    end subroutine krylov_analyse

    !> Copies a and builds the preconditioner. No pivot is judged against NPREC except the
    !> factorization's of LDLT_SP/LDLT_DP (its flags are the report's).
    subroutine krylov_factor(self, a, report, st)
        class(krylov_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(factor_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        type(sym_matrix_t) :: rounded
        real(dp), allocatable :: d(:)
        integer(i4) :: j
        integer(i8) :: k
        self%a = a
        self%factored = .false.
        select case (trim(self%options%pre_cond))
        case ('LDLT_SP', 'LDLT_DP')
            rounded = a
            if (trim(self%options%pre_cond) == 'LDLT_SP') then
                where (abs(rounded%values) < real(huge(1.0_real32), dp)) &
                    rounded%values = real(real(rounded%values, real32), dp)
            end if
            call self%direct%factor(rounded, report, st)
            if (st%failed()) return
            report%method = trim(self%options%method)
        case default
            call start_report(report, trim(self%options%method), a%n)
            report%pivots_known = .false.
            allocate (d(a%n))
            d = 0.0_dp
            do j = 1, a%n
                do k = a%col_ptr(j), a%col_ptr(j + 1) - 1
                    if (a%row_index(k) == j) d(j) = a%values(k)
                end do
            end do
            do j = 1, a%n
                if (.not. d(j) > 0.0_dp) then
                    call record_flag(report, j, PIVOT_NEGATIVE, 0.0_dp)
                    call set_error(st, STATUS_SINGULAR, 'METHODE ' // trim(self%options%method) &
                        // ': the diagonal term of equation ' // to_text(j) // ' is not ' // &
                        'positive: the preconditioned conjugate gradient needs a positive ' // &
                        'definite matrix (a direct METHODE tells where it is singular)')
                    return
                end if
            end do
            select case (trim(self%options%pre_cond))
            case ('JACOBI')
                self%inv_diag = 1.0_dp / d
            case ('LDLT_INC')
                call incomplete_cholesky(self, d, st)
                if (st%failed()) return
            case ('ML', 'GAMG')
                call amg_build(a, self%amg, st)
                if (st%failed()) return
            end select
        end select
        self%factored = .true.
    end subroutine krylov_factor

    !> IC(0): L (lower, stored by rows = the upper triangle's columns of A) with L L^T = A on
    !> A's pattern. Row i: L(i,k) = (a_ik - sum_m L(i,m) L(k,m)) / L(k,k), k < i ascending,
    !> then L(i,i) = sqrt(a_ii - sum_m L(i,m)^2). A breakdown (a square below
    !> IC_BREAKDOWN_RATIO a_ii) starts again on A + shift diag(A), the shift doubling from
    !> IC_FIRST_SHIFT (Manteuffel's shifted incomplete factorization); the shift is reported.
    subroutine incomplete_cholesky(self, d, st)
        class(krylov_solver_t), intent(inout) :: self
        real(dp), intent(in) :: d(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: w(:)
        real(dp) :: s, diag
        integer(i4) :: i, kcol, attempt
        integer(i8) :: p, q
        logical :: broke
        associate (a => self%a)
            allocate (w(a%n))
            self%ic_shift = 0.0_dp
            do attempt = 1, IC_MAX_SHIFTS
                self%ic = a%values
                w = 0.0_dp
                broke = .false.
                rows: do i = 1, a%n
                    diag = 0.0_dp
                    do p = a%col_ptr(i), a%col_ptr(i + 1) - 1
                        kcol = a%row_index(p)
                        if (kcol == i) then
                            diag = a%values(p) * (1.0_dp + self%ic_shift)
                            cycle
                        end if
                        s = 0.0_dp
                        do q = a%col_ptr(kcol), a%col_ptr(kcol + 1) - 2   ! row k, no L(k,k)
                            s = s + self%ic(q) * w(a%row_index(q))
                        end do
                        self%ic(p) = (a%values(p) - s) / self%ic(a%col_ptr(kcol + 1) - 1)
                        w(kcol) = self%ic(p)
                    end do
                    s = diag
                    do p = a%col_ptr(i), a%col_ptr(i + 1) - 2
                        s = s - self%ic(p)**2
                    end do
                    do p = a%col_ptr(i), a%col_ptr(i + 1) - 1
                        w(a%row_index(p)) = 0.0_dp
                    end do
                    if (.not. s > IC_BREAKDOWN_RATIO * d(i)) then
                        broke = .true.
                        exit rows
                    end if
                    self%ic(a%col_ptr(i + 1) - 1) = sqrt(s)
                end do rows
                if (.not. broke) return
                self%ic_shift = max(IC_FIRST_SHIFT, 2.0_dp * self%ic_shift)
            end do
        end associate
        call set_error(st, STATUS_SINGULAR, 'METHODE ' // trim(self%options%method) // &
            ': the incomplete factorization (PRE_COND LDLT_INC) breaks down even on A + ' // &
            real_text(self%ic_shift) // ' diag(A): the matrix is far from positive ' // &
            'definite (choose PRE_COND LDLT_SP, or a direct METHODE that names the equation)')
    end subroutine incomplete_cholesky

    !> z <- M^-1 r for the preconditioner built by factor.
    subroutine apply_preconditioner(self, r, z, st)
        class(krylov_solver_t), intent(inout) :: self
        real(dp), intent(in) :: r(:)
        real(dp), intent(out) :: z(:)
        type(status_t), intent(out) :: st
        integer(i4) :: i
        integer(i8) :: p
        select case (trim(self%options%pre_cond))
        case ('LDLT_SP', 'LDLT_DP')
            z = r
            call self%direct%solve(z, st)
        case ('JACOBI')
            z = self%inv_diag * r
        case ('ML', 'GAMG')
            call amg_apply(self%amg, r, z)
        case ('LDLT_INC')
            associate (a => self%a)
                do i = 1, a%n                                   ! L y = r
                    z(i) = r(i)
                    do p = a%col_ptr(i), a%col_ptr(i + 1) - 2
                        z(i) = z(i) - self%ic(p) * z(a%row_index(p))
                    end do
                    z(i) = z(i) / self%ic(a%col_ptr(i + 1) - 1)
                end do
                do i = a%n, 1, -1                               ! L^T x = y
                    z(i) = z(i) / self%ic(a%col_ptr(i + 1) - 1)
                    do p = a%col_ptr(i), a%col_ptr(i + 1) - 2
                        z(a%row_index(p)) = z(a%row_index(p)) - self%ic(p) * z(i)
                    end do
                end do
            end associate
        case default
            z = r
        end select
    end subroutine apply_preconditioner

    !> b <- A^-1 b by the Krylov method, to RESI_RELA.
    subroutine krylov_solve_one(self, b, st)
        class(krylov_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: x(:)
        real(dp) :: bnorm, rel
        integer(i4) :: iterations, limit
        if (.not. self%factored) then
            call set_error(st, STATUS_SINGULAR, 'METHODE ' // trim(self%options%method) // &
                ': solve before factor')
            return
        end if
        allocate (x(size(b)))
        x = 0.0_dp
        bnorm = norm2(b)
        iterations = 0
        rel = 0.0_dp
        limit = self%options%nmax_iter
        if (limit <= 0) limit = max(MIN_ITERATION_LIMIT, self%a%n)
        if (bnorm > 0.0_dp) then
            if (trim(self%options%algorithm) == 'FGMRES') then
                call fgmres(self, b, x, bnorm, limit, iterations, rel, st)
            else
                call pcg(self, b, x, bnorm, limit, iterations, rel, st)
            end if
        end if
        self%n_solves = self%n_solves + 1
        self%total_iterations = self%total_iterations + iterations
        self%max_iterations = max(self%max_iterations, iterations)
        self%worst_residual = max(self%worst_residual, rel)
        if (st%failed()) return
        if (.not. rel <= self%options%resi_rela) then
            call set_error(st, STATUS_NO_CONVERGENCE, 'METHODE ' // trim(self%options%method) &
                // ' (' // trim(self%options%algorithm) // ', PRE_COND ' // &
                trim(self%options%pre_cond) // ') did not converge in ' // to_text(iterations) &
                // ' iterations: relative residual ' // real_text(rel) // ' > RESI_RELA ' // &
                real_text(self%options%resi_rela) // ' (raise NMAX_ITER, choose another ' // &
                'PRE_COND, or a direct METHODE)')
            return
        end if
        b = x
    end subroutine krylov_solve_one

    !> Preconditioned CG from x = 0; rel: the true relative residual at the end.
    subroutine pcg(self, b, x, bnorm, limit, iterations, rel, st)
        class(krylov_solver_t), intent(inout) :: self
        real(dp), intent(in) :: b(:), bnorm
        real(dp), intent(inout) :: x(:)
        integer(i4), intent(in) :: limit
        integer(i4), intent(out) :: iterations
        real(dp), intent(out) :: rel
        type(status_t), intent(out) :: st
        real(dp), allocatable :: r(:), z(:), p(:), q(:)
        real(dp) :: rz, rz_old, pq, alpha
        r = b
        allocate (z(size(b)), p(size(b)), q(size(b)))
        iterations = 0
        rz = 0.0_dp
        do while (iterations < limit .and. norm2(r) > self%options%resi_rela * bnorm)
            call apply_preconditioner(self, r, z, st)
            if (st%failed()) return
            rz_old = rz
            rz = dot_product(r, z)
            if (iterations == 0) then
                p = z
            else
                p = z + (rz / rz_old) * p
            end if
            call sym_matvec(self%a, p, q)
            pq = dot_product(p, q)
            if (.not. pq > 0.0_dp) then
                call set_error(st, STATUS_SINGULAR, 'METHODE ' // trim(self%options%method) // &
                    ' (CG): p.Ap = ' // real_text(pq) // ' at iteration ' // &
                    to_text(iterations + 1) // ': the matrix is not positive definite (a ' // &
                    'mechanism, or a body held by nothing: a direct METHODE names the node)')
                return
            end if
            alpha = rz / pq
            x = x + alpha * p
            r = r - alpha * q
            iterations = iterations + 1
        end do
        call sym_matvec(self%a, x, q)
        rel = norm2(b - q) / bnorm
    end subroutine pcg

    !> Restarted flexible GMRES, right preconditioned (Saad's FGMRES(m)), from x = 0.
    subroutine fgmres(self, b, x, bnorm, limit, iterations, rel, st)
        class(krylov_solver_t), intent(inout) :: self
        real(dp), intent(in) :: b(:), bnorm
        real(dp), intent(inout) :: x(:)
        integer(i4), intent(in) :: limit
        integer(i4), intent(out) :: iterations
        real(dp), intent(out) :: rel
        type(status_t), intent(out) :: st
        integer(i4), parameter :: m = GMRES_RESTART
        real(dp), allocatable :: v(:, :), z(:, :), r(:)
        real(dp) :: h(m + 1, m), g(m + 1), cs(m), sn(m), y(m), beta, t
        integer(i4) :: j, i, used
        allocate (v(size(b), m + 1), z(size(b), m), r(size(b)))
        iterations = 0
        r = b
        beta = bnorm
        do
            if (beta <= self%options%resi_rela * bnorm .or. iterations >= limit) exit
            v(:, 1) = r / beta
            g = 0.0_dp
            g(1) = beta
            h = 0.0_dp
            used = 0
            do j = 1, m
                call apply_preconditioner(self, v(:, j), z(:, j), st)
                if (st%failed()) return
                call sym_matvec(self%a, z(:, j), v(:, j + 1))
                do i = 1, j                                  ! modified Gram-Schmidt
                    h(i, j) = dot_product(v(:, i), v(:, j + 1))
                    v(:, j + 1) = v(:, j + 1) - h(i, j) * v(:, i)
                end do
                h(j + 1, j) = norm2(v(:, j + 1))
                if (h(j + 1, j) > 0.0_dp) v(:, j + 1) = v(:, j + 1) / h(j + 1, j)
                do i = 1, j - 1                              ! previous rotations
                    t = cs(i) * h(i, j) + sn(i) * h(i + 1, j)
                    h(i + 1, j) = -sn(i) * h(i, j) + cs(i) * h(i + 1, j)
                    h(i, j) = t
                end do
                t = hypot(h(j, j), h(j + 1, j))
                if (.not. t > 0.0_dp) exit
                cs(j) = h(j, j) / t
                sn(j) = h(j + 1, j) / t
                h(j, j) = t
                h(j + 1, j) = 0.0_dp
                g(j + 1) = -sn(j) * g(j)
                g(j) = cs(j) * g(j)
                used = j
                iterations = iterations + 1
                if (abs(g(j + 1)) <= self%options%resi_rela * bnorm .or. &
                    iterations >= limit) exit
            end do
            if (used == 0) exit
            do i = used, 1, -1                               ! H y = g, upper triangular
                y(i) = (g(i) - dot_product(h(i, i + 1:used), y(i + 1:used))) / h(i, i)
            end do
            do i = 1, used
                x = x + y(i) * z(:, i)
            end do
            call sym_matvec(self%a, x, r)
            r = b - r
            beta = norm2(r)
        end do
        call sym_matvec(self%a, x, r)
        rel = norm2(b - r) / bnorm
    end subroutine fgmres

    subroutine krylov_solve_many(self, b, st)
        class(krylov_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: st
        integer :: k
        do k = 1, size(b, 2)
            call self%solve_one(b(:, k), st)
            if (st%failed()) return
        end do
    end subroutine krylov_solve_many

    function krylov_memory(self) result(bytes)
        class(krylov_solver_t), intent(in) :: self
        integer(i8) :: bytes
        bytes = 12_i8 * self%factor_terms
        if (allocated(self%direct)) bytes = bytes + self%direct%memory_estimate()
    end function krylov_memory

    subroutine krylov_release(self)
        class(krylov_solver_t), intent(inout) :: self
        if (allocated(self%direct)) then
            call self%direct%release()
            deallocate (self%direct)
        end if
        if (allocated(self%ic)) deallocate (self%ic)
        if (allocated(self%inv_diag)) deallocate (self%inv_diag)
        if (allocated(self%amg%levels)) deallocate (self%amg%levels)
        self%amg%n_levels = 0
        self%analysed = .false.
        self%factored = .false.
    end subroutine krylov_release

    !> "solver PETSC: FGMRES, PRE_COND LDLT_SP, 12 solve(s), 3 to 5 iterations ..." (.mess).
    function krylov_summary(self) result(text)
        class(krylov_solver_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'solver ' // trim(self%options%method) // ': ' // trim(self%options%algorithm) &
            // ', PRE_COND ' // trim(self%options%pre_cond) // ', ' // to_text(self%n_solves) &
            // ' solve(s), ' // to_text(self%total_iterations) // ' iteration(s) (at most ' // &
            to_text(self%max_iterations) // ' in one), largest relative residual ' // &
            real_text(self%worst_residual) // ' (RESI_RELA ' // &
            real_text(self%options%resi_rela) // ')'
        if (self%ic_shift > 0.0_dp) text = text // '; the incomplete factorization ' // &
            'broke down on A and was made on A + ' // real_text(self%ic_shift) // ' diag(A)'
        if (self%amg%n_levels > 0) text = text // '; multigrid of ' // amg_summary(self%amg)
    end function krylov_summary

    function real_text(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=16) :: buf
        write (buf, '(es10.3)') x
        text = trim(adjustl(buf))
    end function real_text

end module krylov_solver

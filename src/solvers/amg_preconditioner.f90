!> Smoothed-aggregation algebraic multigrid, the preconditioner of SOLVEUR METHODE='PETSC'
!> with PRE_COND='ML' or 'GAMG' (Code_Aster U4.50.01: the multigrid preconditioners of the
!> ML library and of PETSc, both of the smoothed-aggregation family). parasol's own code, on
!> the method of Vaněk, Mandel & Brezina (Computing 56, 1996) with the defaults of ML's
!> guide (Sala et al., ML 5.0 Smoothed Aggregation User's Guide, SAND2006-2649):
!>  - aggregation "uncoupled", threshold 0: every stored off-diagonal term connects; phase
!>    1 makes an aggregate of each node none of whose neighbours is aggregated yet, with
!>    them; phase 2 puts each node left in the aggregate of its strongest neighbour;
!>  - tentative prolongator: the constant on each aggregate, normalised; smoothed by one
!>    damped Jacobi step P = (I - w D^-1 A) P0, w = 4/3 / lambda_max(D^-1 A), lambda_max by
!>    a few power iterations;
!>  - coarse operators A_c = P^T A P until at most COARSE_SIZE unknowns (or MAX_LEVELS, or
!>    an aggregation that no longer coarsens), the coarsest solved by a dense LU (or, beyond
!>    MAX_DENSE_COARSE unknowns, smoothed by symmetric Gauss-Seidel sweeps);
!>  - one V-cycle per application, a symmetric Gauss-Seidel sweep (forward then backward)
!>    before and after the coarse correction: the preconditioner is symmetric.
!> The Krylov method (krylov_solver) converges on the true matrix to RESI_RELA, so the
!> answer is the one any preconditioner gives; what differs from Code_Aster's libraries is
!> the number of iterations (the .mess reports it).
module amg_preconditioner
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_SINGULAR
    use strings, only: to_text
    use sparse_matrix, only: sym_matrix_t
    use dense_lu, only: lu_factor, lu_solve
    implicit none
    private

    !> ML's defaults: "max levels" 10, "coarse: max size" 128, "aggregation: damping
    !> factor" 4/3.
    integer(i4), parameter, public :: MAX_LEVELS = 10
    integer(i4), parameter, public :: COARSE_SIZE = 128
    real(dp), parameter :: DAMPING = 4.0_dp / 3.0_dp
    !> Power iterations for lambda_max(D^-1 A); the estimate is raised by this margin (a
    !> smoothing factor above 2/lambda_max would amplify the highest modes).
    integer(i4), parameter :: POWER_ITERATIONS = 15
    real(dp), parameter :: LAMBDA_MARGIN = 1.05_dp
    !> A level whose aggregation keeps more than this fraction of its unknowns is the last.
    real(dp), parameter :: MIN_COARSENING = 0.9_dp
    !> The coarsest level is solved by a dense LU up to this size; a larger one (the
    !> aggregation stopped coarsening: a matrix with few couplings, e.g. springs alone) is
    !> smoothed by COARSE_SWEEPS symmetric Gauss-Seidel sweeps instead.
    integer(i4), parameter :: MAX_DENSE_COARSE = 2000
    integer(i4), parameter :: COARSE_SWEEPS = 4

    !> A sparse matrix by rows (full, both triangles for the operators).
    type :: csr_t
        integer(i4) :: n_rows = 0, n_cols = 0
        integer(i8), allocatable :: ptr(:)        !< (n_rows + 1)
        integer(i4), allocatable :: col(:)
        real(dp), allocatable :: val(:)
    end type csr_t

    type :: amg_level_t
        type(csr_t) :: a                          !< the operator of this level
        type(csr_t) :: p                          !< prolongation to it from the next level
        real(dp), allocatable :: diag(:)          !< a's diagonal
    end type amg_level_t

    !> The hierarchy (amg_build), applied by amg_apply.
    type, public :: amg_t
        integer(i4) :: n_levels = 0
        type(amg_level_t), allocatable :: levels(:)
        real(dp), allocatable :: coarse_lu(:, :)  !< LU of the coarsest operator
        integer(i4), allocatable :: coarse_pivots(:)
        integer(i8) :: operator_terms = 0         !< stored terms of every level's operator
    end type amg_t

    public :: amg_build, amg_apply, amg_summary

contains

    !> Builds the hierarchy of the symmetric positive definite matrix a.
    !>  st : out, STATUS_SINGULAR when the coarsest operator is singular (a is not
    !>       positive definite: a direct METHODE says where)
    subroutine amg_build(a, amg, st)
        type(sym_matrix_t), intent(in) :: a
        type(amg_t), intent(out) :: amg
        type(status_t), intent(out) :: st
        type(amg_level_t), allocatable :: levels(:)
        integer(i4) :: k, n_coarse, zero_at
        allocate (levels(MAX_LEVELS))
        call full_from_symmetric(a, levels(1)%a)
        k = 1
        do
            levels(k)%diag = diagonal(levels(k)%a)
            amg%operator_terms = amg%operator_terms + size(levels(k)%a%val, kind=i8)
            if (levels(k)%a%n_rows <= COARSE_SIZE .or. k == MAX_LEVELS) exit
            call smoothed_prolongator(levels(k)%a, levels(k)%diag, levels(k)%p, n_coarse)
            if (real(n_coarse, dp) > MIN_COARSENING * real(levels(k)%a%n_rows, dp)) exit
            call galerkin_product(levels(k)%p, levels(k)%a, levels(k + 1)%a)
            k = k + 1
        end do
        amg%n_levels = k
        call move_alloc(levels, amg%levels)
        if (amg%levels(k)%a%n_rows > MAX_DENSE_COARSE) return      ! smoothed (v_cycle)
        associate (c => amg%levels(k)%a)
            allocate (amg%coarse_lu(c%n_rows, c%n_rows), amg%coarse_pivots(c%n_rows))
            call dense_of(c, amg%coarse_lu)
        end associate
        call lu_factor(amg%coarse_lu, amg%coarse_pivots, zero_at)
        if (zero_at /= 0) call set_error(st, STATUS_SINGULAR, 'PRE_COND ML/GAMG: the ' // &
            'coarsest operator of the multigrid (' // to_text(size(amg%coarse_pivots)) // &
            ' unknowns) is singular: the matrix is not positive definite (a direct ' // &
            'METHODE tells where it is singular)')
    end subroutine amg_build

    !> z = M^-1 r: one V-cycle from z = 0.
    subroutine amg_apply(amg, r, z)
        type(amg_t), intent(in) :: amg
        real(dp), intent(in) :: r(:)
        real(dp), intent(out) :: z(:)
        call v_cycle(amg, 1_i4, r, z)
    end subroutine amg_apply

    !> "3 levels (12000, 1400, 160 unknowns), operator complexity 1.32" for the .mess.
    function amg_summary(amg) result(text)
        type(amg_t), intent(in) :: amg
        character(len=:), allocatable :: text
        integer(i4) :: k
        text = to_text(amg%n_levels) // ' level(s) ('
        do k = 1, amg%n_levels
            if (k > 1) text = text // ', '
            text = text // to_text(amg%levels(k)%a%n_rows)
        end do
        text = text // ' unknowns), operator complexity ' // fixed2(real(amg%operator_terms, &
            dp) / real(max(1_i8, size(amg%levels(1)%a%val, kind=i8)), dp))
    contains
        function fixed2(x) result(s)
            real(dp), intent(in) :: x
            character(len=:), allocatable :: s
            character(len=16) :: buf
            write (buf, '(f0.2)') x
            s = trim(buf)
        end function fixed2
    end function amg_summary

    recursive subroutine v_cycle(amg, k, r, z)
        type(amg_t), intent(in) :: amg
        integer(i4), intent(in) :: k
        real(dp), intent(in) :: r(:)
        real(dp), intent(out) :: z(:)
        real(dp), allocatable :: res(:), rc(:), zc(:)
        integer(i4) :: sweep
        if (k == amg%n_levels .and. allocated(amg%coarse_lu)) then
            z = r
            call lu_solve(amg%coarse_lu, amg%coarse_pivots, z)
            return
        else if (k == amg%n_levels) then
            z = 0.0_dp
            do sweep = 1, COARSE_SWEEPS
                call symmetric_sweep(amg%levels(k)%a, amg%levels(k)%diag, r, z)
            end do
            return
        end if
        associate (lv => amg%levels(k))
            z = 0.0_dp
            call symmetric_sweep(lv%a, lv%diag, r, z)
            allocate (res(lv%a%n_rows), rc(lv%p%n_cols), zc(lv%p%n_cols))
            call residual(lv%a, r, z, res)
            call transpose_product(lv%p, res, rc)
            call v_cycle(amg, k + 1_i4, rc, zc)
            call add_product(lv%p, zc, z)
            call symmetric_sweep(lv%a, lv%diag, r, z)
        end associate
    end subroutine v_cycle

    ! One symmetric Gauss-Seidel sweep on a z = r: forward, then backward.
    subroutine symmetric_sweep(a, diag, r, z)
        type(csr_t), intent(in) :: a
        real(dp), intent(in) :: diag(:), r(:)
        real(dp), intent(inout) :: z(:)
        call gauss_seidel(a, diag, r, z, .true.)
        call gauss_seidel(a, diag, r, z, .false.)
    end subroutine symmetric_sweep

    ! One Gauss-Seidel sweep on a z = r, forward or backward.
    subroutine gauss_seidel(a, diag, r, z, forward)
        type(csr_t), intent(in) :: a
        real(dp), intent(in) :: diag(:), r(:)
        real(dp), intent(inout) :: z(:)
        logical, intent(in) :: forward
        integer(i4) :: i, first, last, step
        integer(i8) :: p
        real(dp) :: s
        if (forward) then
            first = 1; last = a%n_rows; step = 1
        else
            first = a%n_rows; last = 1; step = -1
        end if
        do i = first, last, step
            s = r(i)
            do p = a%ptr(i), a%ptr(i + 1) - 1
                if (a%col(p) /= i) s = s - a%val(p) * z(a%col(p))
            end do
            z(i) = s / diag(i)
        end do
    end subroutine gauss_seidel

    ! res = r - A z
    subroutine residual(a, r, z, res)
        type(csr_t), intent(in) :: a
        real(dp), intent(in) :: r(:), z(:)
        real(dp), intent(out) :: res(:)
        call product(a, z, res)
        res = r - res
    end subroutine residual

    ! y = A x
    subroutine product(a, x, y)
        type(csr_t), intent(in) :: a
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: y(:)
        integer(i4) :: i
        integer(i8) :: p
        do i = 1, a%n_rows
            y(i) = 0.0_dp
            do p = a%ptr(i), a%ptr(i + 1) - 1
                y(i) = y(i) + a%val(p) * x(a%col(p))
            end do
        end do
    end subroutine product

    ! y = P^T x
    subroutine transpose_product(p, x, y)
        type(csr_t), intent(in) :: p
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: y(:)
        integer(i4) :: i
        integer(i8) :: q
        y = 0.0_dp
        do i = 1, p%n_rows
            do q = p%ptr(i), p%ptr(i + 1) - 1
                y(p%col(q)) = y(p%col(q)) + p%val(q) * x(i)
            end do
        end do
    end subroutine transpose_product

    ! z <- z + P y
    subroutine add_product(p, y, z)
        type(csr_t), intent(in) :: p
        real(dp), intent(in) :: y(:)
        real(dp), intent(inout) :: z(:)
        integer(i4) :: i
        integer(i8) :: q
        do i = 1, p%n_rows
            do q = p%ptr(i), p%ptr(i + 1) - 1
                z(i) = z(i) + p%val(q) * y(p%col(q))
            end do
        end do
    end subroutine add_product

    ! The full matrix (both triangles) by rows from the upper triangle by columns.
    subroutine full_from_symmetric(a, f)
        type(sym_matrix_t), intent(in) :: a
        type(csr_t), intent(out) :: f
        integer(i4) :: i, j
        integer(i8) :: k
        integer(i8), allocatable :: next(:)
        f%n_rows = a%n
        f%n_cols = a%n
        allocate (f%ptr(a%n + 1), next(a%n))
        next = 0
        do j = 1, a%n
            do k = a%col_ptr(j), a%col_ptr(j + 1) - 1
                i = a%row_index(k)
                next(j) = next(j) + 1                  ! (i, j) in row j as (j, i)
                if (i /= j) next(i) = next(i) + 1      ! (i, j) in row i
            end do
        end do
        f%ptr(1) = 1
        do i = 1, a%n
            f%ptr(i + 1) = f%ptr(i) + next(i)
        end do
        allocate (f%col(f%ptr(a%n + 1) - 1), f%val(f%ptr(a%n + 1) - 1))
        next = f%ptr(1:a%n)
        do j = 1, a%n
            do k = a%col_ptr(j), a%col_ptr(j + 1) - 1
                i = a%row_index(k)
                f%col(next(j)) = i
                f%val(next(j)) = a%values(k)
                next(j) = next(j) + 1
                if (i /= j) then
                    f%col(next(i)) = j
                    f%val(next(i)) = a%values(k)
                    next(i) = next(i) + 1
                end if
            end do
        end do
    end subroutine full_from_symmetric

    function diagonal(a) result(d)
        type(csr_t), intent(in) :: a
        real(dp), allocatable :: d(:)
        integer(i4) :: i
        integer(i8) :: p
        allocate (d(a%n_rows), source=0.0_dp)
        do i = 1, a%n_rows
            do p = a%ptr(i), a%ptr(i + 1) - 1
                if (a%col(p) == i) d(i) = d(i) + a%val(p)
            end do
        end do
    end function diagonal

    subroutine dense_of(a, d)
        type(csr_t), intent(in) :: a
        real(dp), intent(out) :: d(:, :)
        integer(i4) :: i
        integer(i8) :: p
        d = 0.0_dp
        do i = 1, a%n_rows
            do p = a%ptr(i), a%ptr(i + 1) - 1
                d(i, a%col(p)) = d(i, a%col(p)) + a%val(p)
            end do
        end do
    end subroutine dense_of

    ! The aggregates (module header) and P = (I - w D^-1 A) P0.
    subroutine smoothed_prolongator(a, diag, p, n_agg)
        type(csr_t), intent(in) :: a
        real(dp), intent(in) :: diag(:)
        type(csr_t), intent(out) :: p
        integer(i4), intent(out) :: n_agg
        integer(i4), allocatable :: agg(:), size_of(:), marker(:), cols(:)
        real(dp), allocatable :: weight(:), vals(:)
        integer(i4) :: i, j, best, nnz_row
        integer(i8) :: q, total
        real(dp) :: strongest, omega
        logical :: free
        allocate (agg(a%n_rows), source=0_i4)
        n_agg = 0
        do i = 1, a%n_rows                          ! phase 1: whole neighbourhoods
            if (agg(i) /= 0) cycle
            free = .true.
            do q = a%ptr(i), a%ptr(i + 1) - 1
                if (agg(a%col(q)) /= 0) free = .false.
            end do
            if (.not. free) cycle
            n_agg = n_agg + 1
            agg(i) = n_agg
            do q = a%ptr(i), a%ptr(i + 1) - 1
                if (abs(a%val(q)) > 0.0_dp) agg(a%col(q)) = n_agg
            end do
        end do
        do i = 1, a%n_rows                          ! phase 2: the strongest neighbour's
            if (agg(i) > 0) cycle
            best = 0
            strongest = 0.0_dp
            do q = a%ptr(i), a%ptr(i + 1) - 1
                j = a%col(q)
                if (j == i .or. agg(j) <= 0) cycle
                if (abs(a%val(q)) > strongest) then
                    strongest = abs(a%val(q))
                    best = agg(j)
                end if
            end do
            if (best > 0) then
                agg(i) = -best                      ! joined in this phase (not a seed)
            else
                n_agg = n_agg + 1                   ! isolated: an aggregate of its own
                agg(i) = n_agg
            end if
        end do
        agg = abs(agg)
        allocate (size_of(n_agg), source=0_i4)
        do i = 1, a%n_rows
            size_of(agg(i)) = size_of(agg(i)) + 1
        end do
        weight = 1.0_dp / sqrt(real(size_of, dp))
        omega = DAMPING / lambda_max(a, diag)
        ! row i of P: P0(i, agg(i)) - omega / a_ii sum_j a_ij P0(j, agg(j))
        allocate (marker(n_agg), source=0_i4)
        allocate (cols(n_agg), vals(n_agg))
        p%n_rows = a%n_rows
        p%n_cols = n_agg
        allocate (p%ptr(a%n_rows + 1))
        total = 0
        do i = 1, a%n_rows                          ! sizes first
            call row_of_p(i, nnz_row)
            total = total + nnz_row
        end do
        allocate (p%col(total), p%val(total))
        p%ptr(1) = 1
        do i = 1, a%n_rows
            call row_of_p(i, nnz_row)
            p%ptr(i + 1) = p%ptr(i) + nnz_row
            p%col(p%ptr(i):p%ptr(i + 1) - 1) = cols(1:nnz_row)
            p%val(p%ptr(i):p%ptr(i + 1) - 1) = vals(1:nnz_row)
        end do
    contains
        subroutine row_of_p(row, count)
            integer(i4), intent(in) :: row
            integer(i4), intent(out) :: count
            integer(i8) :: qq
            integer(i4) :: c, k
            count = 1
            cols(1) = agg(row)
            vals(1) = weight(agg(row))
            marker(agg(row)) = 1
            do qq = a%ptr(row), a%ptr(row + 1) - 1
                c = agg(a%col(qq))
                if (marker(c) == 0) then
                    count = count + 1
                    marker(c) = count
                    cols(count) = c
                    vals(count) = 0.0_dp
                end if
                vals(marker(c)) = vals(marker(c)) - omega / diag(row) * a%val(qq) * weight(c)
            end do
            do k = 1, count
                marker(cols(k)) = 0
            end do
        end subroutine row_of_p
    end subroutine smoothed_prolongator

    ! lambda_max(D^-1 A) by power iterations (similar to the symmetric D^-1/2 A D^-1/2,
    ! so its eigenvalues are real and positive), from a fixed start (deterministic).
    real(dp) function lambda_max(a, diag) result(lambda)
        type(csr_t), intent(in) :: a
        real(dp), intent(in) :: diag(:)
        real(dp), allocatable :: x(:), y(:)
        integer(i4) :: it, i
        allocate (x(a%n_rows), y(a%n_rows))
        do i = 1, a%n_rows
            x(i) = 1.0_dp + real(mod(i, 7), dp) / 7.0_dp
        end do
        x = x / norm2(x)
        lambda = 1.0_dp
        do it = 1, POWER_ITERATIONS
            call product(a, x, y)
            y = y / diag
            lambda = norm2(y)
            if (.not. lambda > 0.0_dp) then
                lambda = 1.0_dp
                return
            end if
            x = y / lambda
        end do
        lambda = LAMBDA_MARGIN * lambda
    end function lambda_max

    ! c = P^T A P (Gustavson's row-by-row products with a marker array).
    subroutine galerkin_product(p, a, c)
        type(csr_t), intent(in) :: p, a
        type(csr_t), intent(out) :: c
        type(csr_t) :: ap, pt
        call multiply(a, p, ap)
        call transpose_of(p, pt)
        call multiply(pt, ap, c)
    end subroutine galerkin_product

    subroutine transpose_of(a, t)
        type(csr_t), intent(in) :: a
        type(csr_t), intent(out) :: t
        integer(i4) :: i, j
        integer(i8) :: q
        integer(i8), allocatable :: next(:)
        t%n_rows = a%n_cols
        t%n_cols = a%n_rows
        allocate (t%ptr(a%n_cols + 1), next(a%n_cols))
        next = 0
        do q = 1, size(a%col, kind=i8)
            next(a%col(q)) = next(a%col(q)) + 1
        end do
        t%ptr(1) = 1
        do j = 1, a%n_cols
            t%ptr(j + 1) = t%ptr(j) + next(j)
        end do
        allocate (t%col(size(a%col)), t%val(size(a%val)))
        next = t%ptr(1:a%n_cols)
        do i = 1, a%n_rows
            do q = a%ptr(i), a%ptr(i + 1) - 1
                j = a%col(q)
                t%col(next(j)) = i
                t%val(next(j)) = a%val(q)
                next(j) = next(j) + 1
            end do
        end do
    end subroutine transpose_of

    subroutine multiply(a, b, c)
        type(csr_t), intent(in) :: a, b
        type(csr_t), intent(out) :: c
        integer(i4), allocatable :: marker(:), cols(:)
        real(dp), allocatable :: acc(:)
        integer(i4) :: i, k, j, count, pass
        integer(i8) :: q, r, total
        allocate (marker(b%n_cols), source=0_i4)
        allocate (cols(b%n_cols), acc(b%n_cols))
        c%n_rows = a%n_rows
        c%n_cols = b%n_cols
        allocate (c%ptr(a%n_rows + 1))
        c%ptr(1) = 1
        do pass = 1, 2                              ! 1: sizes, 2: values
            total = 0
            do i = 1, a%n_rows
                count = 0
                do q = a%ptr(i), a%ptr(i + 1) - 1
                    k = a%col(q)
                    do r = b%ptr(k), b%ptr(k + 1) - 1
                        j = b%col(r)
                        if (marker(j) == 0) then
                            count = count + 1
                            marker(j) = count
                            cols(count) = j
                            acc(count) = 0.0_dp
                        end if
                        acc(marker(j)) = acc(marker(j)) + a%val(q) * b%val(r)
                    end do
                end do
                if (pass == 1) then
                    c%ptr(i + 1) = c%ptr(i) + count
                else
                    c%col(c%ptr(i):c%ptr(i + 1) - 1) = cols(1:count)
                    c%val(c%ptr(i):c%ptr(i + 1) - 1) = acc(1:count)
                end if
                marker(cols(1:count)) = 0
                total = total + count
            end do
            if (pass == 1) allocate (c%col(total), c%val(total))
        end do
    end subroutine multiply

end module amg_preconditioner

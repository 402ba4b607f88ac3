!> LU factorization with partial pivoting of a small dense general matrix, and solves with
!> it (Golub & Van Loan, Matrix Computations, 4th ed., alg. 3.4.1, column-oriented: the
!> loops run down columns, Fortran's storage order). For the matrices of a few thousand
!> equations at most that parasol factors densely (unsymmetric_correction); parasol does
!> not link LAPACK (blas_library loads BLAS at run time for the skyline only).
module dense_lu
    use kinds, only: dp, i4
    implicit none
    private

    public :: lu_factor, lu_solve

contains

    !> a = P L U in place (L unit lower, below the diagonal; U on and above it).
    !>  pivots : out, (n) row interchanged with row k at step k
    !>  zero_at : out, the first column with no nonzero pivot (0: none; the factor of the
    !>            other columns is still complete)
    pure subroutine lu_factor(a, pivots, zero_at)
        real(dp), intent(inout) :: a(:, :)
        integer(i4), intent(out) :: pivots(:)
        integer(i4), intent(out) :: zero_at
        integer(i4) :: n, k, j, p
        real(dp) :: row(size(a, 2)), pivot
        n = size(a, 1, kind=i4)
        zero_at = 0
        do k = 1, n
            p = k - 1 + int(maxloc(abs(a(k:n, k)), dim=1), i4)
            pivots(k) = p
            if (p /= k) then
                row = a(k, :)
                a(k, :) = a(p, :)
                a(p, :) = row
            end if
            pivot = a(k, k)
            if (.not. abs(pivot) > 0.0_dp) then
                if (zero_at == 0) zero_at = k
                cycle
            end if
            a(k + 1:n, k) = a(k + 1:n, k) / pivot
            do j = k + 1, n
                a(k + 1:n, j) = a(k + 1:n, j) - a(k + 1:n, k) * a(k, j)
            end do
        end do
    end subroutine lu_factor

    !> b <- a^-1 b with the factor of lu_factor (no zero pivot).
    pure subroutine lu_solve(a, pivots, b)
        real(dp), intent(in) :: a(:, :)
        integer(i4), intent(in) :: pivots(:)
        real(dp), intent(inout) :: b(:)
        integer(i4) :: n, k
        real(dp) :: t
        n = size(a, 1, kind=i4)
        do k = 1, n
            if (pivots(k) /= k) then
                t = b(k)
                b(k) = b(pivots(k))
                b(pivots(k)) = t
            end if
        end do
        do k = 1, n               ! L y = P b, by columns
            b(k + 1:n) = b(k + 1:n) - a(k + 1:n, k) * b(k)
        end do
        do k = n, 1, -1           ! U x = y, by columns
            b(k) = b(k) / a(k, k)
            b(1:k - 1) = b(1:k - 1) - a(1:k - 1, k) * b(k)
        end do
    end subroutine lu_solve

end module dense_lu

!> Explicit interfaces to the BLAS and LAPACK routines parasol calls (style.md: one interface
!> module, so argument mistakes fail at compile time). Arguments follow the reference
!> routines (netlib LAPACK 3.x documentation); arrays are assumed-size as there, so callers
!> may pass an array element to start a sub-block (sequence association).
module lapack_interface
    use kinds, only: dp
    implicit none
    private
    public :: ddot, dgemv, dtrsv, dgemm, dsyrk, dtrsm
    public :: dpotrf, dposv, dpbtrf, dpbtrs, dpbsv, dsyev

    interface
        !> BLAS 1: dot product sum x(1+(i-1)incx) * y(1+(i-1)incy).
        pure function ddot(n, x, incx, y, incy)
            import :: dp
            integer, intent(in) :: n, incx, incy
            real(dp), intent(in) :: x(*), y(*)
            real(dp) :: ddot
        end function ddot

        !> BLAS 2: y = alpha op(A) x + beta y, op = 'N' or 'T'.
        pure subroutine dgemv(trans, m, n, alpha, a, lda, x, incx, beta, y, incy)
            import :: dp
            character(len=1), intent(in) :: trans
            integer, intent(in) :: m, n, lda, incx, incy
            real(dp), intent(in) :: alpha, beta, a(lda, *), x(*)
            real(dp), intent(inout) :: y(*)
        end subroutine dgemv

        !> BLAS 2: x = op(A)^-1 x for a triangular A.
        pure subroutine dtrsv(uplo, trans, diag, n, a, lda, x, incx)
            import :: dp
            character(len=1), intent(in) :: uplo, trans, diag
            integer, intent(in) :: n, lda, incx
            real(dp), intent(in) :: a(lda, *)
            real(dp), intent(inout) :: x(*)
        end subroutine dtrsv

        !> BLAS 3: C = alpha op(A) op(B) + beta C.
        pure subroutine dgemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)
            import :: dp
            character(len=1), intent(in) :: transa, transb
            integer, intent(in) :: m, n, k, lda, ldb, ldc
            real(dp), intent(in) :: alpha, beta, a(lda, *), b(ldb, *)
            real(dp), intent(inout) :: c(ldc, *)
        end subroutine dgemm

        !> BLAS 3: C = alpha op(A) op(A)^T + beta C (triangle uplo of C only).
        pure subroutine dsyrk(uplo, trans, n, k, alpha, a, lda, beta, c, ldc)
            import :: dp
            character(len=1), intent(in) :: uplo, trans
            integer, intent(in) :: n, k, lda, ldc
            real(dp), intent(in) :: alpha, beta, a(lda, *)
            real(dp), intent(inout) :: c(ldc, *)
        end subroutine dsyrk

        !> BLAS 3: B = alpha op(A)^-1 B (side 'L') or alpha B op(A)^-1 (side 'R').
        pure subroutine dtrsm(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb)
            import :: dp
            character(len=1), intent(in) :: side, uplo, transa, diag
            integer, intent(in) :: m, n, lda, ldb
            real(dp), intent(in) :: alpha, a(lda, *)
            real(dp), intent(inout) :: b(ldb, *)
        end subroutine dtrsm

        !> LAPACK: Cholesky factorization of a dense SPD matrix; info > 0 = non-positive pivot.
        pure subroutine dpotrf(uplo, n, a, lda, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, lda
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: info
        end subroutine dpotrf

        !> LAPACK: solves A X = B for dense SPD A (Cholesky); A and B are overwritten.
        pure subroutine dposv(uplo, n, nrhs, a, lda, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(inout) :: a(lda, *), b(ldb, *)
            integer, intent(out) :: info
        end subroutine dposv

        !> LAPACK: Cholesky factorization of an SPD band matrix (kd super-diagonals) in
        !> band storage ab(kd+1+i-j, j) = a(i, j) for uplo = 'U'.
        pure subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, kd, ldab
            real(dp), intent(inout) :: ab(ldab, *)
            integer, intent(out) :: info
        end subroutine dpbtrf

        !> LAPACK: solves A X = B with the band Cholesky factor from dpbtrf.
        pure subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, kd, nrhs, ldab, ldb
            real(dp), intent(in) :: ab(ldab, *)
            real(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine dpbtrs

        !> LAPACK: factors and solves an SPD band system (dpbtrf + dpbtrs).
        pure subroutine dpbsv(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, kd, nrhs, ldab, ldb
            real(dp), intent(inout) :: ab(ldab, *), b(ldb, *)
            integer, intent(out) :: info
        end subroutine dpbsv

        !> LAPACK: eigenvalues (and vectors, jobz = 'V') of a dense symmetric matrix.
        pure subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
            import :: dp
            character(len=1), intent(in) :: jobz, uplo
            integer, intent(in) :: n, lda, lwork
            real(dp), intent(inout) :: a(lda, *)
            real(dp), intent(out) :: w(*), work(*)
            integer, intent(out) :: info
        end subroutine dsyev
    end interface

end module lapack_interface

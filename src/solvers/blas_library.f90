!> The BLAS 3 routines of the skyline's blocked kernel (dgemm, dsyrk, dtrsm), taken at run
!> time from the BLAS parasol was configured with (OpenBLAS by default) the first time a
!> factorization needs them. Linking OpenBLAS into parasol cost every process its loading
!> and its thread start (measured: ~6 ms of CPU of a ~18 ms `parasol --check`,
!> doc/performance.md "Start-up"), although only wide skyline profiles use it.
!>
!> The entry points are the Fortran BLAS ones (dgemm_ ...), declared here with bind(C)
!> interfaces that spell out the hidden character lengths of the Fortran calling
!> convention; the type-bound wrappers keep the reference argument lists (netlib BLAS) and
!> pass each array by its first element (sequence association, as BLAS expects).
module blas_library
    use, intrinsic :: iso_c_binding, only: c_funptr, c_char, c_int, c_double, c_size_t, &
        c_f_procpointer
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use dynamic_library, only: dynamic_library_t, open_library, find_symbol
    use parasol_solver_config, only: BLAS_RUNTIME_LIBRARY
    implicit none
    private

    !> Tried when the configured library cannot be opened (Debian's BLAS alternative).
    character(len=*), parameter :: FALLBACK_BLAS = 'libblas.so.3'

    abstract interface
        subroutine dgemm_fn(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc, &
                            la, lb) bind(c)
            import :: c_char, c_int, c_double, c_size_t
            character(kind=c_char), intent(in) :: transa, transb
            integer(c_int), intent(in) :: m, n, k, lda, ldb, ldc
            real(c_double), intent(in) :: alpha, beta, a(lda, *), b(ldb, *)
            real(c_double), intent(inout) :: c(ldc, *)
            integer(c_size_t), value :: la, lb
        end subroutine dgemm_fn
        subroutine dsyrk_fn(uplo, trans, n, k, alpha, a, lda, beta, c, ldc, lu, lt) bind(c)
            import :: c_char, c_int, c_double, c_size_t
            character(kind=c_char), intent(in) :: uplo, trans
            integer(c_int), intent(in) :: n, k, lda, ldc
            real(c_double), intent(in) :: alpha, beta, a(lda, *)
            real(c_double), intent(inout) :: c(ldc, *)
            integer(c_size_t), value :: lu, lt
        end subroutine dsyrk_fn
        subroutine dtrsm_fn(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb, ls, lu, &
                            lt, ld) bind(c)
            import :: c_char, c_int, c_double, c_size_t
            character(kind=c_char), intent(in) :: side, uplo, transa, diag
            integer(c_int), intent(in) :: m, n, lda, ldb
            real(c_double), intent(in) :: alpha, a(lda, *)
            real(c_double), intent(inout) :: b(ldb, *)
            integer(c_size_t), value :: ls, lu, lt, ld
        end subroutine dtrsm_fn
    end interface

    !> The loaded routines (load_blas), called through the wrappers below.
    type, public :: blas_kernels_t
        type(dynamic_library_t) :: library
        procedure(dgemm_fn), nopass, pointer :: c_dgemm => null()
        procedure(dsyrk_fn), nopass, pointer :: c_dsyrk => null()
        procedure(dtrsm_fn), nopass, pointer :: c_dtrsm => null()
    contains
        procedure :: dgemm => blas_dgemm
        procedure :: dsyrk => blas_dsyrk
        procedure :: dtrsm => blas_dtrsm
    end type blas_kernels_t

    public :: load_blas

contains

    !> Opens the BLAS (BLAS_RUNTIME_LIBRARY, else libblas.so.3) and takes dgemm, dsyrk and dtrsm.
    !>  st : out, STATUS_IO_ERROR with the loader's reason when neither library opens or a
    !>       routine is missing
    subroutine load_blas(blas, st)
        type(blas_kernels_t), intent(inout) :: blas
        type(status_t), intent(out) :: st
        type(c_funptr) :: f
        if (associated(blas%c_dtrsm)) return
        call open_library(blas%library, BLAS_RUNTIME_LIBRARY, st)
        if (st%failed()) call open_library(blas%library, FALLBACK_BLAS, st)
        if (st%failed()) then
            call set_error(st, STATUS_IO_ERROR, 'the skyline factorization needs BLAS: ' // &
                st%message // ' (apt-get install libopenblas0 or libblas3)')
            return
        end if
        call find_symbol(blas%library, 'dgemm_', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, blas%c_dgemm)
        call find_symbol(blas%library, 'dsyrk_', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, blas%c_dsyrk)
        call find_symbol(blas%library, 'dtrsm_', f, st)
        if (st%failed()) return
        call c_f_procpointer(f, blas%c_dtrsm)
    end subroutine load_blas

    !> C = alpha op(A) op(B) + beta C (netlib DGEMM).
    subroutine blas_dgemm(self, transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)
        class(blas_kernels_t), intent(in) :: self
        character(len=1), intent(in) :: transa, transb
        integer, intent(in) :: m, n, k, lda, ldb, ldc
        real(dp), intent(in) :: alpha, beta, a(lda, *), b(ldb, *)
        real(dp), intent(inout) :: c(ldc, *)
        call self%c_dgemm(transa, transb, m, n, k, alpha, a(1, 1), lda, b(1, 1), ldb, beta, &
            c(1, 1), ldc, &
            1_c_size_t, 1_c_size_t)
    end subroutine blas_dgemm

    !> C = alpha op(A) op(A)^T + beta C, triangle uplo of C (netlib DSYRK).
    subroutine blas_dsyrk(self, uplo, trans, n, k, alpha, a, lda, beta, c, ldc)
        class(blas_kernels_t), intent(in) :: self
        character(len=1), intent(in) :: uplo, trans
        integer, intent(in) :: n, k, lda, ldc
        real(dp), intent(in) :: alpha, beta, a(lda, *)
        real(dp), intent(inout) :: c(ldc, *)
        call self%c_dsyrk(uplo, trans, n, k, alpha, a(1, 1), lda, beta, c(1, 1), ldc, 1_c_size_t, &
            1_c_size_t)
    end subroutine blas_dsyrk

    !> B = alpha op(A)^-1 B or alpha B op(A)^-1 (netlib DTRSM).
    subroutine blas_dtrsm(self, side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb)
        class(blas_kernels_t), intent(in) :: self
        character(len=1), intent(in) :: side, uplo, transa, diag
        integer, intent(in) :: m, n, lda, ldb
        real(dp), intent(in) :: alpha, a(lda, *)
        real(dp), intent(inout) :: b(ldb, *)
        call self%c_dtrsm(side, uplo, transa, diag, m, n, alpha, a(1, 1), lda, b(1, 1), ldb, &
            1_c_size_t, &
            1_c_size_t, 1_c_size_t, 1_c_size_t)
    end subroutine blas_dtrsm

end module blas_library

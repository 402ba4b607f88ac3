!> LDL^T (Crout) factorization of a symmetric skyline matrix in place, substitution for one
!> or several right-hand sides, and Code_Aster's NPREC singularity detection.
!>
!> Factorization A = U^T D U, U unit upper triangular (U = L^T), by columns (Crout; Bathe,
!> Finite Element Procedures, 8.2.3; FEAP's DATRI). For column j with top t_j:
!>     g_ij = a_ij - sum_{k=max(t_i,t_j)}^{i-1} u_ki g_kj      (i = t_j .. j-1)
!>     u_ij = g_ij / d_i,     d_j = a_jj - sum_{i=t_j}^{j-1} g_ij u_ij
!> The factor overwrites the profile: u_ij above the diagonal, d_j on it.
!> Two kernels compute the same thing: `factor_reference_kernel` (dot products, the textbook
!> form) and `factor_blocked_kernel`, which treats panels of columns as dense blocks so the
!> bulk of the work is BLAS-3 (dgemm, dtrsm); see doc/performance.md.
!>
!> NPREC (Code_Aster SOLVEUR/NPREC, default 8, u4.50.01): the pivot d_i of equation i lost
!>     digits_i = log10(|a_ii| / |d_i|)
!> significant digits relative to the original diagonal a_ii. A pivot is flagged when it
!> loses more than NPREC digits (as Code_Aster's LDLT and MULT_FRONT do, |NPREC| is used and
!> NPREC = 0 means the default 8; only MUMPS reads NPREC < 0 as "no detection"), when it
!> is zero (|d_i| <= eps |a_ii|: every digit lost), or when it is negative and the caller
!> declared the matrix positive definite. With STOP_SINGULIER='OUI' (stop_singular) a flagged
!> pivot is an error STATUS_SINGULAR naming the first flagged equation; the report lists all.
module skyline_solver
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: to_text
    use direct_solver, only: factor_report_t, solver_options_t, NPREC_DEFAULT, &
        PIVOT_DIGITS_LOST, PIVOT_ZERO, PIVOT_NEGATIVE, DIGITS_ALL_LOST, HOLD_PENALTY, &
        digits_lost, record_flag, record_hold, singular_message, start_report
    use skyline_matrix, only: skyline_t, skyline_bandwidth, skyline_profile_size
    use blas_library, only: blas_kernels_t, load_blas
    use progress, only: progress_t
    implicit none
    private

    !> Kernel choice: automatic (blocked for wide profiles), reference, blocked.
    integer(i4), parameter, public :: FACTOR_AUTO = 0, FACTOR_REFERENCE = 1, FACTOR_BLOCKED = 2
    !> Panel width (columns) and row block of the blocked kernel; below this bandwidth the
    !> reference kernel is as fast (measured, doc/performance.md).
    integer(i4), parameter :: PANEL_WIDTH = 64, ROW_BLOCK = 64, BLOCKED_MIN_BANDWIDTH = 64
    !> Columns between two progress reports (a multiple of PANEL_WIDTH; a report costs a
    !> clock reading, next to ~64 x bandwidth^2 operations).
    integer(i4), parameter :: PROGRESS_COLUMNS = 4 * PANEL_WIDTH

    !> How to factor and what counts as singular.
    type, public :: factor_options_t
        integer(i4) :: nprec = NPREC_DEFAULT      !< SOLVEUR/NPREC (|nprec|; 0 -> 8)
        logical :: stop_singular = .true.         !< SOLVEUR/STOP_SINGULIER = 'OUI'
        logical :: positive_definite = .false.    !< a negative pivot is then flagged
        integer(i4) :: method = FACTOR_AUTO       !< FACTOR_AUTO/REFERENCE/BLOCKED
        real(dp) :: hold_digits = 0.0_dp          !< hold pivots losing >= this (0: off)
        real(dp) :: hold_ratio = 0.0_dp           !< hold |pivot| <= this x max|a_jj|
        !> told how far the factorization is, every PROGRESS_COLUMNS columns (null: nobody)
        class(progress_t), pointer :: progress => null()
    end type factor_options_t

    !> Everything the pivot test needs (kept together so kernels stay short).
    type :: pivot_context_t
        type(factor_options_t) :: options
        real(dp) :: scale = 1.0_dp                 !< reference when a_jj = 0
        real(dp), allocatable :: original(:)       !< a_jj before factorization
    end type pivot_context_t

    !> Solve with a factored matrix: b(:) or b(:, :) (several right-hand sides).
    interface skyline_solve
        module procedure skyline_solve_one, skyline_solve_many
    end interface skyline_solve

    public :: skyline_factor, skyline_solve, digits_lost, factor_report_t, NPREC_DEFAULT, &
        PIVOT_DIGITS_LOST, PIVOT_ZERO, PIVOT_NEGATIVE, DIGITS_ALL_LOST

contains

    !> Factors sky in place as U^T D U and tests every pivot (NPREC, module header).
    !>  sky     : inout, assembled matrix; on return its factor (sky%factored = .true.)
    !>  report  : out, pivot statistics and the flagged equations
    !>  st      : out, STATUS_SINGULAR when a pivot is flagged and options%stop_singular
    !>            (message names the first equation; the factor is still complete and usable
    !>            in the sense above), STATUS_INTERNAL if sky has no profile or is factored
    !>  options : in, optional, defaults of factor_options_t (NPREC 8, stop, not SPD, auto)
    subroutine skyline_factor(sky, report, st, options)
        type(skyline_t), intent(inout) :: sky
        type(factor_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        type(factor_options_t), intent(in), optional :: options
        type(pivot_context_t) :: ctx
        type(blas_kernels_t) :: blas
        integer(i4) :: method
        if (.not. sky%profile_ready .or. sky%factored) then
            call set_error(st, STATUS_INTERNAL, 'skyline_factor: matrix has no profile or ' &
                           // 'is already factored')
            return
        end if
        if (present(options)) ctx%options = options
        ! Code_Aster (u4.50.01, LDLT/MULT_FRONT): the absolute value counts, 0 is the default.
        ctx%options%nprec = abs(ctx%options%nprec)
        if (ctx%options%nprec == 0) ctx%options%nprec = NPREC_DEFAULT
        call start_report(report, 'LDLT', sky%n)
        report%profile_size = skyline_profile_size(sky)
        report%bandwidth = skyline_bandwidth(sky)
        report%factor_entries = report%profile_size
        report%memory_bytes = 8_i8 * report%profile_size
        allocate (report%pivots(sky%n))
        if (sky%n == 0) then
            sky%factored = .true.
            return
        end if
        ctx%original = sky%values(sky%diag(1:sky%n))
        ctx%scale = maxval(abs(ctx%original))
        if (ctx%scale <= 0.0_dp) ctx%scale = 1.0_dp
        report%min_abs_pivot = huge(1.0_dp)
        method = ctx%options%method
        if (method == FACTOR_AUTO) then
            method = FACTOR_REFERENCE
            if (report%bandwidth >= BLOCKED_MIN_BANDWIDTH) method = FACTOR_BLOCKED
        end if
        if (method == FACTOR_BLOCKED) then
            call load_blas(blas, st)        ! on first use only (blas_library)
            if (st%failed()) return
            call factor_blocked_kernel(sky%n, sky%diag, sky%values, report%bandwidth, ctx, &
                                       report, blas)
        else
            call factor_reference_kernel(sky%n, sky%diag, sky%values, ctx, report)
        end if
        sky%factored = .true.
        if (report%n_flagged > 0 .and. ctx%options%stop_singular) then
            call singular_message(report, solver_options_t(nprec=ctx%options%nprec), st)
        end if
    end subroutine skyline_factor

    !> Tests pivot d of equation j, records it in the report, and replaces a zero pivot (and
    !> one the options ask to hold) by HOLD_PENALTY x its original diagonal, so the
    !> factorization can go on and the equation's unknown comes out ~0.
    subroutine accept_pivot(j, d, ctx, report)
        integer(i4), intent(in) :: j
        real(dp), intent(inout) :: d
        type(pivot_context_t), intent(in) :: ctx
        type(factor_report_t), intent(inout) :: report
        real(dp) :: lost, ref
        integer(i4) :: reason
        logical :: hold
        lost = digits_lost(d, ctx%original(j), ctx%scale)
        report%pivots(j) = d
        report%min_abs_pivot = min(report%min_abs_pivot, abs(d))
        report%max_abs_pivot = max(report%max_abs_pivot, abs(d))
        if (lost > report%max_digits_lost .or. report%max_digits_equation == 0) then
            report%max_digits_lost = lost
            report%max_digits_equation = j
        end if
        reason = 0
        if (lost >= DIGITS_ALL_LOST) then
            reason = PIVOT_ZERO
        else if (d < 0.0_dp .and. ctx%options%positive_definite) then
            reason = PIVOT_NEGATIVE
        else if (lost > real(ctx%options%nprec, dp)) then
            reason = PIVOT_DIGITS_LOST
        end if
        if (d < 0.0_dp .and. reason /= PIVOT_ZERO) then
            report%n_negative_pivots = report%n_negative_pivots + 1
        end if
        if (reason /= 0) call record_flag(report, j, reason, lost)
        hold = reason == PIVOT_ZERO
        if (ctx%options%hold_digits > 0.0_dp) hold = hold .or. lost >= ctx%options%hold_digits
        if (ctx%options%hold_ratio > 0.0_dp) hold = hold .or. &
            abs(d) <= ctx%options%hold_ratio * ctx%scale
        if (hold) then
            ref = abs(ctx%original(j))
            if (ref <= 0.0_dp) ref = ctx%scale
            d = HOLD_PENALTY * ref
            call record_hold(report, j)
        end if
    end subroutine accept_pivot

    !> Reference kernel: column Crout with dot products (module header formulas).
    !>  n, diag, values : inout skyline arrays (skyline_matrix layout); values become the factor
    subroutine factor_reference_kernel(n, diag, values, ctx, report)
        integer(i4), intent(in) :: n
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(inout) :: values(:)
        type(pivot_context_t), intent(in) :: ctx
        type(factor_report_t), intent(inout) :: report
        integer(i4) :: i, j, k, tj, ti
        integer(i8) :: p0, q0
        real(dp) :: s, g, u, d
        do j = 1, n
            tj = j - int(diag(j) - diag(j - 1), i4) + 1
            p0 = diag(j - 1) + 1 - tj              ! values(p0 + i) = column j, row i
            do i = tj + 1, j - 1
                ti = i - int(diag(i) - diag(i - 1), i4) + 1
                q0 = diag(i - 1) + 1 - ti          ! values(q0 + k) = column i, row k
                s = 0.0_dp
                do k = max(ti, tj), i - 1
                    s = s + values(q0 + k) * values(p0 + k)
                end do
                values(p0 + i) = values(p0 + i) - s
            end do
            s = 0.0_dp
            do i = tj, j - 1
                g = values(p0 + i)
                u = g / values(diag(i))
                s = s + g * u
                values(p0 + i) = u
            end do
            d = values(diag(j)) - s
            call accept_pivot(j, d, ctx, report)
            values(diag(j)) = d
            if (mod(j, PROGRESS_COLUMNS) == 0) call report_progress(ctx, diag, j)
        end do
    end subroutine factor_reference_kernel

    !> Tells the reporter (if any) how far the factorization is: the share of the profile
    !> done after column j.
    subroutine report_progress(ctx, diag, j)
        type(pivot_context_t), intent(in) :: ctx
        integer(i8), intent(in) :: diag(0:)
        integer(i4), intent(in) :: j
        integer(i4) :: n
        if (.not. associated(ctx%options%progress)) return
        n = ubound(diag, 1, kind=i4)
        call ctx%options%progress%update('factorization (LDLT, ' // to_text(n) // &
            ' equations)', real(diag(j), dp) / real(max(diag(n), 1_i8), dp))
    end subroutine report_progress

    !> Blocked kernel: panels of up to PANEL_WIDTH columns j0..j1 are copied to a dense block
    !> P (rows T..j1, T = lowest top of the panel, zeros above each top). Rows T..j0-1 of P
    !> are forward-substituted against the finished columns in row blocks: dgemm with the
    !> block's columns above it (copied to a dense W), then dtrsm with the block's own unit
    !> triangle. The panel's diagonal block gets the update P_JJ -= (D^-1 G)^T G (dgemm) and a
    !> small dense LDL^T with the pivot tests; the panel is then copied back. Same arithmetic
    !> as the reference kernel, reordered (left-looking block Crout).
    subroutine factor_blocked_kernel(n, diag, values, band, ctx, report, blas)
        type(blas_kernels_t), intent(in) :: blas
        integer(i4), intent(in) :: n, band
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(inout) :: values(:)
        type(pivot_context_t), intent(in) :: ctx
        type(factor_report_t), intent(inout) :: report
        real(dp), allocatable :: p(:, :), w(:, :), s(:, :), dk(:)
        integer(i4), allocatable :: top(:)
        integer(i4) :: j, j0, j1, t, ldp, ldw
        allocate (top(n))
        do j = 1, n
            top(j) = j - int(diag(j) - diag(j - 1), i4) + 1
        end do
        ldp = band + PANEL_WIDTH
        ldw = band + ROW_BLOCK
        allocate (p(ldp, PANEL_WIDTH), w(ldw, ROW_BLOCK), s(max(1, band), PANEL_WIDTH), &
                  dk(max(1, band)))
        j0 = 1
        do while (j0 <= n)
            j1 = min(n, j0 + PANEL_WIDTH - 1)
            t = minval(top(j0:j1))
            call load_panel(n, diag, values, top, j0, j1, t, ldp, p)
            call substitute_above_panel(n, diag, values, top, j0, j1, t, ldp, p, ldw, w, blas)
            call factor_panel_diagonal(n, diag, values, j0, j1, t, ldp, p, max(1, band), s, &
                                       dk, ctx, report, blas)
            call store_panel(n, diag, values, top, j0, j1, t, ldp, p)
            if (mod(j1, PROGRESS_COLUMNS) == 0) call report_progress(ctx, diag, j1)
            j0 = j1 + 1
        end do
    end subroutine factor_blocked_kernel

    !> P(1 : j1-t+1, 1 : j1-j0+1) = columns j0..j1, rows t..j1 (zero above each top).
    subroutine load_panel(n, diag, values, top, j0, j1, t, ldp, p)
        integer(i4), intent(in) :: n, top(n), j0, j1, t, ldp
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(in) :: values(:)
        real(dp), intent(inout) :: p(ldp, PANEL_WIDTH)
        integer(i4) :: c, j
        do c = 1, j1 - j0 + 1
            j = j0 + c - 1
            p(1:top(j) - t, c) = 0.0_dp
            p(top(j) - t + 1:j - t + 1, c) = values(diag(j - 1) + 1:diag(j))
            p(j - t + 2:j1 - t + 1, c) = 0.0_dp
        end do
    end subroutine load_panel

    !> Copies the panel back into the profile (rows top(j)..j of each column).
    subroutine store_panel(n, diag, values, top, j0, j1, t, ldp, p)
        integer(i4), intent(in) :: n, top(n), j0, j1, t, ldp
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(inout) :: values(:)
        real(dp), intent(in) :: p(ldp, PANEL_WIDTH)
        integer(i4) :: c, j
        do c = 1, j1 - j0 + 1
            j = j0 + c - 1
            values(diag(j - 1) + 1:diag(j)) = p(top(j) - t + 1:j - t + 1, c)
        end do
    end subroutine store_panel

    !> Rows t..j0-1 of the panel: g_ij = a_ij - sum_k u_ki g_kj with the finished columns,
    !> row block by row block [b0, b1]: rows r0..b0-1 above the block by dgemm, the block's
    !> unit upper triangle by dtrsm (U^T X = B). W holds U(r0..b1, b0..b1), zero-filled.
    subroutine substitute_above_panel(n, diag, values, top, j0, j1, t, ldp, p, ldw, w, blas)
        type(blas_kernels_t), intent(in) :: blas
        integer(i4), intent(in) :: n, top(n), j0, j1, t, ldp, ldw
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(in) :: values(:)
        real(dp), intent(inout) :: p(ldp, PANEL_WIDTH), w(ldw, ROW_BLOCK)
        integer(i4) :: b0, b1, nbr, r0, kr, c, i, wp
        wp = j1 - j0 + 1
        b0 = t
        do while (b0 <= j0 - 1)
            b1 = min(j0 - 1, b0 + ROW_BLOCK - 1)
            nbr = b1 - b0 + 1
            r0 = max(t, minval(top(b0:b1)))
            kr = b0 - r0
            do c = 1, nbr
                i = b0 + c - 1
                ! column i of U, rows max(top(i), r0)..i-1, at W rows (row - r0 + 1)
                w(1:max(top(i), r0) - r0, c) = 0.0_dp
                w(max(top(i), r0) - r0 + 1:i - r0, c) = &
                    values(diag(i) - (i - max(top(i), r0)):diag(i) - 1)
            end do
            if (kr > 0) then
                call blas%dgemm('T', 'N', nbr, wp, kr, -1.0_dp, w, ldw, p(r0 - t + 1, 1), ldp, &
                           1.0_dp, p(b0 - t + 1, 1), ldp)
            end if
            if (nbr > 1) then
                call blas%dtrsm('L', 'U', 'T', 'U', nbr, wp, 1.0_dp, w(kr + 1, 1), ldw, &
                           p(b0 - t + 1, 1), ldp)
            end if
            b0 = b1 + 1
        end do
    end subroutine substitute_above_panel

    !> Diagonal block of the panel: P_JJ -= S^T G with G = P(rows t..j0-1), S = D^-1 G (the
    !> panel's own u_kj, stored back into P), then dense Crout of the block with pivot tests.
    !>  s, dk : work arrays (lds >= j0 - t rows), allocated once by the caller
    subroutine factor_panel_diagonal(n, diag, values, j0, j1, t, ldp, p, lds, s, dk, ctx, &
                                     report, blas)
        type(blas_kernels_t), intent(in) :: blas
        integer(i4), intent(in) :: n, j0, j1, t, ldp, lds
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(in) :: values(:)
        real(dp), intent(inout) :: p(ldp, PANEL_WIDTH), s(lds, PANEL_WIDTH), dk(lds)
        type(pivot_context_t), intent(in) :: ctx
        type(factor_report_t), intent(inout) :: report
        integer(i4) :: na, wp, c, r, q
        real(dp) :: g, u, acc, d
        na = j0 - t
        wp = j1 - j0 + 1
        if (na > 0) then
            dk(1:na) = values(diag(t:j0 - 1))
            if (all(dk(1:na) > 0.0_dp)) then
                ! G^T D^-1 G = H^T H with H = D^-1/2 G: symmetric rank-k update of the upper
                ! triangle only (half the flops of dgemm).
                dk(1:na) = 1.0_dp / sqrt(dk(1:na))
                do c = 1, wp
                    s(1:na, c) = p(1:na, c) * dk(1:na)
                end do
                call blas%dsyrk('U', 'T', wp, na, -1.0_dp, s, lds, 1.0_dp, p(na + 1, 1), ldp)
                do c = 1, wp
                    p(1:na, c) = s(1:na, c) * dk(1:na)
                end do
            else
                dk(1:na) = 1.0_dp / dk(1:na)
                do c = 1, wp
                    s(1:na, c) = p(1:na, c) * dk(1:na)
                end do
                call blas%dgemm('T', 'N', wp, wp, na, -1.0_dp, s, lds, p, ldp, 1.0_dp, &
                           p(na + 1, 1), ldp)
                p(1:na, 1:wp) = s(1:na, 1:wp)
            end if
        end if
        do c = 1, wp
            do r = 2, c - 1
                acc = 0.0_dp
                do q = 1, r - 1
                    acc = acc + p(na + q, r) * p(na + q, c)
                end do
                p(na + r, c) = p(na + r, c) - acc
            end do
            acc = 0.0_dp
            do r = 1, c - 1
                g = p(na + r, c)
                u = g / p(na + r, r)
                acc = acc + g * u
                p(na + r, c) = u
            end do
            d = p(na + c, c) - acc
            call accept_pivot(j0 + c - 1, d, ctx, report)
            p(na + c, c) = d
        end do
    end subroutine factor_panel_diagonal

    !> Solves A x = b with the factor: forward U^T y = b, diagonal z = D^-1 y, back U x = z.
    !>  sky : in, factored by skyline_factor
    !>  b   : inout, size n: right-hand side in, solution out
    !>  st  : out, STATUS_INTERNAL if sky is not factored or sizes differ
    subroutine skyline_solve_one(sky, b, st)
        type(skyline_t), intent(in) :: sky
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: st
        if (.not. sky%factored .or. size(b) /= sky%n) then
            call set_error(st, STATUS_INTERNAL, 'skyline_solve: matrix not factored or ' // &
                           'right-hand side of size ' // to_text(size(b, kind=i4)) // &
                           ' /= ' // to_text(sky%n))
            return
        end if
        call substitute_kernel(sky%n, sky%diag, sky%values, b)
    end subroutine skyline_solve_one

    !> As skyline_solve_one for several right-hand sides b(:, k) (size n x nrhs).
    subroutine skyline_solve_many(sky, b, st)
        type(skyline_t), intent(in) :: sky
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: st
        integer :: k
        if (.not. sky%factored .or. size(b, 1) /= sky%n) then
            call set_error(st, STATUS_INTERNAL, 'skyline_solve: matrix not factored or ' // &
                           'right-hand sides of size ' // to_text(size(b, 1, kind=i4)) // &
                           ' /= ' // to_text(sky%n))
            return
        end if
        do k = 1, size(b, 2)
            call substitute_kernel(sky%n, sky%diag, sky%values, b(:, k))
        end do
    end subroutine skyline_solve_many

    !> Forward, diagonal and back substitution on plain skyline arrays (pivots are never
    !> zero: skyline_factor replaces zero pivots).
    subroutine substitute_kernel(n, diag, values, x)
        integer(i4), intent(in) :: n
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(in) :: values(:)
        real(dp), intent(inout) :: x(n)
        integer(i4) :: j, i, tj
        integer(i8) :: p0
        real(dp) :: s
        do j = 1, n
            tj = j - int(diag(j) - diag(j - 1), i4) + 1
            p0 = diag(j - 1) + 1 - tj
            s = 0.0_dp
            do i = tj, j - 1
                s = s + values(p0 + i) * x(i)
            end do
            x(j) = x(j) - s
        end do
        do j = 1, n
            x(j) = x(j) / values(diag(j))
        end do
        do j = n, 1, -1
            tj = j - int(diag(j) - diag(j - 1), i4) + 1
            p0 = diag(j - 1) + 1 - tj
            do i = tj, j - 1
                x(i) = x(i) - values(p0 + i) * x(j)
            end do
        end do
    end subroutine substitute_kernel

end module skyline_solver

!> A direct solver that keeps the rigid modes of spring-held bodies apart (doc/analysis.md,
!> "Rigid modes"): K u = b with K = K_b + K_s, K_b the bodies' stiffness (its null space
!> holds the rigid modes R, exactly: K_b R = 0) and K_s everything else (springs). A plate
!> 1e8..1e20 times stiffer than its bed makes K's smallest eigenvalues the bed's and its
!> largest the plate's; factoring K then loses as many digits as that contrast. Here the
!> unknowns are changed to u = R a + w, w zero on m anchor equations (one per mode, chosen
!> so that R restricted to them is the identity): in those coordinates
!>
!>     K^ = Q^T K Q = | C  Y^T  |     Q = [R  P],  C = R^T K_s R,  Y = P^T K_s R,
!>                    | Y  K_WW |     K_WW = K with the anchor rows and columns removed,
!>
!> because Q^T K_b R = 0 analytically: the products of the stiff bodies with R are never
!> formed. K_WW is the bodies held at their anchors (plus the springs): its factor has the
!> digits of the bodies' own conditioning, not of the contrast. The coarse matrix
!> S = C - Y^T K_WW^-1 Y (m x m) is factored here; its terms are spring-sized and
!> Y^T K_WW^-1 Y is the small coupling (~ K_s^2 / K_b), so S is formed without the
!> cancellation of the contrast.
!>
!> Vectors in these coordinates ("hat" vectors) have the layout of the free equations: the
!> anchor slots hold a (the displacement of each anchor, R being the identity there), the
!> other slots w. to_hat(b) = Q^T b, from_hat(x^) = Q x^; the solves of this type are
!> solves with K^ (so conjugate gradients preconditioned with it run on K^, and its Ritz
!> values are those of K_F^-1 K_S as before). residual_norm measures a hat residual as the
!> original one (max |Q^-T r^|). Without modes (set_modes not called, or m = 0) it is the
!> inner solver, unchanged.
!>
!> A coarse pivot that loses every digit (a mode nothing holds) is held at a = 0 and
!> reported at its anchor (report%flagged_equations / held_equations): the analysis decides
!> whether that is an error (a body held by nothing), an overshooting iterate, or, with the
!> singularity check off, an unloaded free mode.
module two_level_solver
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: to_text
    use sparse_matrix, only: sym_matrix_t
    use huge_pages, only: advise_huge_pages
    use direct_solver, only: direct_solver_t, factor_report_t, digits_lost, record_flag, &
        record_hold, effective_nprec, check_disabled, DIGITS_ALL_LOST, PIVOT_DIGITS_LOST, &
        PIVOT_ZERO
    implicit none
    private

    !> The inner solver with the rigid modes kept apart (module header).
    type, extends(direct_solver_t), public :: two_level_solver_t
        class(direct_solver_t), allocatable :: inner
        integer(i4) :: n = 0                        !< free equations
        integer(i4) :: m = 0                        !< rigid modes (0: plain inner solver)
        integer(i4), allocatable :: anchors(:)      !< (m) anchor equation of each mode
        real(dp), allocatable :: r(:, :)            !< (n, m) R, the identity on the anchors
        real(dp), allocatable :: y(:, :)            !< (n, m) P^T K_s R (anchor rows 0)
        real(dp), allocatable :: g(:, :)            !< (n, m) K_WW^-1 Y
        real(dp), allocatable :: c(:, :)            !< (m, m) R^T K_s R
        real(dp), allocatable :: l(:, :)            !< (m, m) LDL^T of S: unit L below, D on
                                                    !< the diagonal (held modes: 1, row 0)
        logical, allocatable :: held(:)             !< (m) modes held at a = 0
        real(dp), allocatable :: coarse_pivots(:)   !< (m) D of S's LDL^T, before any hold
        real(dp), allocatable :: coarse_digits(:)   !< (m) digits each lost against S_jj
        logical :: coarse_ready = .false.
    contains
        procedure :: analyse => two_level_analyse
        procedure :: factor => two_level_factor
        procedure :: solve_one => two_level_solve_one
        procedure :: solve_many => two_level_solve_many
        procedure :: memory_estimate => two_level_memory
        procedure :: release => two_level_release
        procedure :: iteration_summary => two_level_iterations
        procedure :: active => two_level_active
    end type two_level_solver_t

    public :: wrap_solver, set_modes, isolate_anchors, set_coarse, to_hat, from_hat, &
        hat_body_part, hat_anchors_from, residual_norm, hat_product, coarse_digits_max, &
        modes_kept_apart, add_block_product

contains

    !> Wraps `inner` (created, not analysed) into a two-level solver without modes: the
    !> wrapper then behaves exactly as the inner solver until set_modes gives it modes.
    !>  inner  : inout, moved into solver
    !>  solver : out
    subroutine wrap_solver(inner, solver)
        class(direct_solver_t), allocatable, intent(inout) :: inner
        class(direct_solver_t), allocatable, intent(out) :: solver
        type(two_level_solver_t), allocatable :: two
        allocate (two)
        two%options = inner%options
        call move_alloc(inner, two%inner)
        call move_alloc(two, solver)
    end subroutine wrap_solver

    !> The rigid modes and their anchors (the analysis finds them: analysis rigid_bodies).
    !>  r       : inout, (n, m) the modes on the free equations, moved into the solver;
    !>            r(anchors(k), :) must be the k-th unit vector (checked)
    !>  anchors : in, (m) distinct free equations
    !>  st      : out, STATUS_INTERNAL if r is not the identity on the anchors
    subroutine set_modes(self, r, anchors, st)
        class(two_level_solver_t), intent(inout) :: self
        real(dp), allocatable, intent(inout) :: r(:, :)
        integer(i4), intent(in) :: anchors(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, j
        self%m = size(anchors, kind=i4)
        self%n = size(r, 1, kind=i4)
        do k = 1, self%m
            do j = 1, self%m
                if (abs(r(anchors(k), j) - merge(1.0_dp, 0.0_dp, j == k)) > 0.0_dp) then
                    call set_error(st, STATUS_INTERNAL, 'two-level solver: the modes are ' // &
                        'not the identity on their anchors')
                    self%m = 0
                    return
                end if
            end do
        end do
        call move_alloc(r, self%r)
        self%anchors = anchors
        ! n x m each (19 MB at 128 x 512): huge pages, filled when first used
        allocate (self%y(self%n, self%m), self%g(self%n, self%m))
        call advise_huge_pages(self%y)
        call advise_huge_pages(self%g)
        allocate (self%c(self%m, self%m), self%l(self%m, self%m), source=0.0_dp)
        allocate (self%held(self%m), source=.false.)
        allocate (self%coarse_pivots(self%m), self%coarse_digits(self%m), source=0.0_dp)
        self%coarse_ready = .false.
    end subroutine set_modes

    !> Whether modes are kept apart (m > 0).
    pure logical function two_level_active(self)
        class(two_level_solver_t), intent(in) :: self
        two_level_active = self%m > 0
    end function two_level_active

    !> Removes the anchor rows and columns from an assembled matrix before it is factored:
    !> their off-diagonal terms are zeroed and the diagonal kept, so the factor is that of
    !> K_WW plus a decoupled pivot per anchor (which loses no digit). Nothing without modes.
    !>  a : inout, the assembled matrix (the pattern the solver analysed)
    subroutine isolate_anchors(self, a)
        class(two_level_solver_t), intent(in) :: self
        type(sym_matrix_t), intent(inout) :: a
        logical, allocatable :: anchor(:)
        integer(i4) :: j
        integer(i8) :: k
        if (self%m == 0) return
        allocate (anchor(a%n), source=.false.)
        anchor(self%anchors) = .true.
        do j = 1, a%n
            do k = a%col_ptr(j), a%col_ptr(j + 1) - 1
                if (a%row_index(k) == j) cycle
                if (anchor(j) .or. anchor(a%row_index(k))) a%values(k) = 0.0_dp
            end do
        end do
        ! an anchor whose diagonal is 0 (an anchor of a mode only the springs see) still
        ! needs a pivot: 1, which decouples it all the same
        do j = 1, self%m
            associate (p => a%col_ptr(self%anchors(j) + 1) - 1)
                if (.not. abs(a%values(p)) > 0.0_dp) a%values(p) = 1.0_dp
            end associate
        end do
    end subroutine isolate_anchors

    !> Symbolic phase: the inner solver's (the pattern is that of K; anchors are isolated
    !> by value, so the pattern does not change).
    subroutine two_level_analyse(self, a, st)
        class(two_level_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(status_t), intent(out) :: st
        self%inner%options = self%options
        self%inner%progress => self%progress
        call self%inner%analyse(a, st)
        self%analysed = self%inner%analysed
        self%factor_terms = self%inner%factor_terms
        self%factor_flops = self%inner%factor_flops
    end subroutine two_level_analyse

    !> Factors a (anchors isolated by isolate_anchors when modes are kept apart); the coarse
    !> matrix is factored by set_coarse, which must follow before a solve.
    subroutine two_level_factor(self, a, report, st)
        class(two_level_solver_t), intent(inout) :: self
        type(sym_matrix_t), intent(in) :: a
        type(factor_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        self%inner%options = self%options
        self%inner%progress => self%progress
        self%coarse_ready = .false.
        call self%inner%factor(a, report, st)
        self%factored = self%inner%factored
    end subroutine two_level_factor

    !> After a factorization: the coarse matrix of the factored matrix from K_s R.
    !>  ksr    : in, (n, m) K_s R on the free equations, K_s the part of the factored matrix
    !>           that is not the bodies' (springs, at the factored contact status)
    !>  report : inout, the factorization's report: each coarse pivot's digits (against
    !>           S_jj) are reported at its anchor; a pivot losing more than NPREC digits is
    !>           flagged there, and one with no digit left (or <= 0) is held (a = 0)
    !>  st     : out, the inner solver's failures
    subroutine set_coarse(self, ksr, report, st)
        class(two_level_solver_t), intent(inout) :: self
        real(dp), intent(in) :: ksr(:, :)
        type(factor_report_t), intent(inout) :: report
        type(status_t), intent(out) :: st
        integer(i4) :: j
        if (self%m == 0) return
        if (size(ksr, 1) /= self%n .or. size(ksr, 2) /= self%m) then
            call set_error(st, STATUS_INTERNAL, 'two-level solver: K_s R of size ' // &
                to_text(size(ksr, 1, kind=i4)) // ' x ' // to_text(size(ksr, 2, kind=i4)))
            return
        end if
        self%y = ksr
        self%y(self%anchors, :) = 0.0_dp
        self%c = matmul(transpose(self%r), ksr)
        self%c = 0.5_dp * (self%c + transpose(self%c))
        self%g = self%y
        call self%inner%solve(self%g, st)
        if (st%failed()) return
        self%g(self%anchors, :) = 0.0_dp
        self%l = self%c - matmul(transpose(self%y), self%g)
        self%l = 0.5_dp * (self%l + transpose(self%l))
        call factor_coarse(self)
        do j = 1, self%m
            call report_coarse_pivot(self, j, report)
        end do
        self%coarse_ready = .true.
    end subroutine set_coarse

    !> LDL^T of the coarse matrix S (in self%l) without pivoting; a pivot at round-off
    !> level of its diagonal (no digit left: a mode nothing holds), or <= 0, is held: its
    !> mode is decoupled and solved with a = 0 (as the back-ends hold free pivots).
    subroutine factor_coarse(self)
        class(two_level_solver_t), intent(inout) :: self
        real(dp) :: s(self%m, self%m), d(self%m), scale
        integer(i4) :: i, j, k
        s = self%l
        scale = 0.0_dp
        do j = 1, self%m
            scale = max(scale, abs(s(j, j)))
        end do
        self%l = 0.0_dp
        self%held = .false.
        do j = 1, self%m
            d(j) = s(j, j)
            do k = 1, j - 1
                d(j) = d(j) - self%l(j, k)**2 * d(k)
            end do
            self%coarse_pivots(j) = d(j)
            self%coarse_digits(j) = digits_lost(d(j), s(j, j), scale)
            if (.not. d(j) > 0.0_dp .or. self%coarse_digits(j) >= DIGITS_ALL_LOST) then
                self%held(j) = .true.
                d(j) = 1.0_dp
                self%l(j, j) = 1.0_dp
                cycle
            end if
            self%l(j, j) = d(j)
            do i = j + 1, self%m
                self%l(i, j) = s(i, j)
                do k = 1, j - 1
                    self%l(i, j) = self%l(i, j) - self%l(i, k) * self%l(j, k) * d(k)
                end do
                self%l(i, j) = self%l(i, j) / d(j)
            end do
        end do
    end subroutine factor_coarse

    !> The coarse pivot j in the factorization's report, at its anchor equation.
    subroutine report_coarse_pivot(self, j, report)
        class(two_level_solver_t), intent(in) :: self
        integer(i4), intent(in) :: j
        type(factor_report_t), intent(inout) :: report
        real(dp) :: lost
        integer(i4) :: eq
        eq = self%anchors(j)
        lost = self%coarse_digits(j)
        if (self%held(j)) lost = DIGITS_ALL_LOST
        if (lost > report%max_digits_lost .or. report%max_digits_equation == 0) then
            report%max_digits_lost = lost
            report%max_digits_equation = eq
        end if
        if (self%held(j)) then
            if (.not. check_disabled(self%options)) call record_flag(report, eq, PIVOT_ZERO, &
                lost)
            if (self%options%hold_digits > 0.0_dp) call record_hold(report, eq)
        else if (lost > real(effective_nprec(self%options), dp) .and. &
                 .not. check_disabled(self%options)) then
            call record_flag(report, eq, PIVOT_DIGITS_LOST, lost)
        end if
    end subroutine report_coarse_pivot

    !> The largest loss of digits of the coarse pivots (0 without modes).
    pure real(dp) function coarse_digits_max(self) result(lost)
        class(two_level_solver_t), intent(in) :: self
        integer(i4) :: j
        lost = 0.0_dp
        do j = 1, self%m
            if (self%held(j)) then
                lost = DIGITS_ALL_LOST
            else
                lost = max(lost, self%coarse_digits(j))
            end if
        end do
    end function coarse_digits_max

    !> b <- K^-1 b in hat coordinates (module header): w = K_WW^-1 (b_W - Y a) with
    !> S a = b_R - Y^T K_WW^-1 b_W.
    subroutine two_level_solve_one(self, b, st)
        class(two_level_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:)
        type(status_t), intent(out) :: st
        real(dp) :: b2(size(b), 1)
        if (self%m == 0) then
            call self%inner%solve(b, st)
            return
        end if
        b2(:, 1) = b
        call two_level_solve_many(self, b2, st)
        b = b2(:, 1)
    end subroutine two_level_solve_one

    subroutine two_level_solve_many(self, b, st)
        class(two_level_solver_t), intent(inout) :: self
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: a(:, :)
        integer(i4) :: k
        if (self%m == 0) then
            call self%inner%solve(b, st)
            return
        end if
        if (.not. self%coarse_ready .or. size(b, 1) /= self%n) then
            call set_error(st, STATUS_INTERNAL, 'two-level solver: solve without a coarse ' &
                // 'factor, or right-hand sides of another size')
            return
        end if
        allocate (a(self%m, size(b, 2)))
        do k = 1, size(b, 2)
            a(:, k) = b(self%anchors, k)
        end do
        b(self%anchors, :) = 0.0_dp
        call self%inner%solve(b, st)
        if (st%failed()) return
        b(self%anchors, :) = 0.0_dp
        do k = 1, size(b, 2)
            a(:, k) = a(:, k) - matmul(b(:, k), self%y)
            call solve_coarse(self, a(:, k))
            b(:, k) = b(:, k) - matmul(self%g, a(:, k))
            b(self%anchors, k) = a(:, k)
        end do
    end subroutine two_level_solve_many

    !> x <- S^-1 x with the coarse LDL^T (held modes: 0).
    pure subroutine solve_coarse(self, x)
        class(two_level_solver_t), intent(in) :: self
        real(dp), intent(inout) :: x(:)
        integer(i4) :: i, k
        where (self%held) x = 0.0_dp
        do i = 1, self%m
            do k = 1, i - 1
                x(i) = x(i) - self%l(i, k) * x(k)
            end do
        end do
        do i = 1, self%m
            x(i) = x(i) / self%l(i, i)
        end do
        do i = self%m, 1, -1
            do k = i + 1, self%m
                x(i) = x(i) - self%l(k, i) * x(k)
            end do
        end do
        where (self%held) x = 0.0_dp
    end subroutine solve_coarse

    !> b^ = Q^T b: b on the non-anchor equations, R^T b on the anchors (a copy of b without
    !> modes).
    subroutine to_hat(self, b, bh)
        class(direct_solver_t), intent(in) :: self
        real(dp), intent(in) :: b(:)
        real(dp), intent(out) :: bh(:)
        bh = b
        select type (self)
        type is (two_level_solver_t)
            if (self%m > 0) bh(self%anchors) = matmul(b, self%r)
        end select
    end subroutine to_hat

    !> x = Q x^ = R a + w (x^ without modes).
    subroutine from_hat(self, xh, x)
        class(direct_solver_t), intent(in) :: self
        real(dp), intent(in) :: xh(:)
        real(dp), intent(out) :: x(:)
        real(dp), allocatable :: a(:)
        x = xh
        select type (self)
        type is (two_level_solver_t)
            if (self%m > 0) then
                a = xh(self%anchors)
                x(self%anchors) = 0.0_dp
                x = x + matmul(self%r, a)
            end if
        end select
    end subroutine from_hat

    !> ksr(eqs, :) <- ksr(eqs, :) + k R(eqs, :): a small block (a spring's matrix, signed)
    !> added to K_s, in K_s R (equations 0: eliminated, skipped). Nothing without modes.
    subroutine add_block_product(self, eqs, k, ksr)
        class(direct_solver_t), intent(in) :: self
        integer(i4), intent(in) :: eqs(:)
        real(dp), intent(in) :: k(:, :)
        real(dp), intent(inout) :: ksr(:, :)
        integer(i4) :: i, j
        select type (self)
        type is (two_level_solver_t)
            if (self%m == 0) return
            do i = 1, size(eqs)
                if (eqs(i) == 0) cycle
                do j = 1, size(eqs)
                    if (eqs(j) > 0) ksr(eqs(i), :) = ksr(eqs(i), :) + k(i, j) * self%r(eqs(j), :)
                end do
            end do
        end select
    end subroutine add_block_product

    !> Whether a solver keeps rigid modes apart (a two-level solver with modes).
    pure logical function modes_kept_apart(self)
        class(direct_solver_t), intent(in) :: self
        modes_kept_apart = .false.
        select type (self)
        type is (two_level_solver_t)
            modes_kept_apart = self%m > 0
        end select
    end function modes_kept_apart

    !> dst <- src on the anchor slots (nothing without modes).
    subroutine hat_anchors_from(self, src, dst)
        class(direct_solver_t), intent(in) :: self
        real(dp), intent(in) :: src(:)
        real(dp), intent(inout) :: dst(:)
        select type (self)
        type is (two_level_solver_t)
            if (self%m > 0) dst(self%anchors) = src(self%anchors)
        end select
    end subroutine hat_anchors_from

    !> w = P x^: the part of x = Q x^ that deforms the bodies (x^ with its anchor slots
    !> zeroed; x^ itself without modes). The bodies' forces are K_b w: K_b R a = 0.
    subroutine hat_body_part(self, xh, w)
        class(direct_solver_t), intent(in) :: self
        real(dp), intent(in) :: xh(:)
        real(dp), intent(out) :: w(:)
        w = xh
        select type (self)
        type is (two_level_solver_t)
            if (self%m > 0) w(self%anchors) = 0.0_dp
        end select
    end subroutine hat_body_part

    !> max |r| of the original residual r = Q^-T r^ for a hat residual r^ (max |r^| without
    !> modes): r = r^ off the anchors, r_A = r^_A - R_W^T r^_W on them.
    real(dp) function residual_norm(self, rh) result(norm)
        class(direct_solver_t), intent(in) :: self
        real(dp), intent(in) :: rh(:)
        real(dp), allocatable :: w(:), ra(:)
        norm = 0.0_dp
        if (size(rh) == 0) return
        select type (self)
        type is (two_level_solver_t)
            if (self%m > 0) then
                w = rh
                w(self%anchors) = 0.0_dp
                ra = rh(self%anchors) - matmul(w, self%r)
                norm = max(maxval(abs(w)), maxval(abs(ra)))
                return
            end if
        end select
        norm = maxval(abs(rh))
    end function residual_norm

    !> y^ = K^ x^ from the matrix the solver factored (anchors isolated) and the coarse
    !> terms: [C a + Y^T w; K_WW w + Y a]. Without modes y = A x.
    !>  a : in, the factored matrix (isolate_anchors applied when modes are kept apart)
    subroutine hat_product(self, a, xh, yh)
        use sparse_matrix, only: sym_matvec
        class(direct_solver_t), intent(in) :: self
        type(sym_matrix_t), intent(in) :: a
        real(dp), intent(in) :: xh(:)
        real(dp), intent(out) :: yh(:)
        real(dp), allocatable :: w(:), c(:)
        call sym_matvec(a, xh, yh)
        select type (self)
        type is (two_level_solver_t)
            if (self%m > 0) then
                c = xh(self%anchors)
                w = xh
                w(self%anchors) = 0.0_dp
                yh = yh + matmul(self%y, c)
                yh(self%anchors) = matmul(self%c, c) + matmul(w, self%y)
            end if
        end select
    end subroutine hat_product

    !> The inner solver's factor plus the modes' vectors (R, Y, G).
    function two_level_memory(self) result(bytes)
        class(two_level_solver_t), intent(in) :: self
        integer(i8) :: bytes
        bytes = self%inner%memory_estimate() + 24_i8 * int(self%n, i8) * int(self%m, i8)
    end function two_level_memory

    subroutine two_level_release(self)
        class(two_level_solver_t), intent(inout) :: self
        if (allocated(self%inner)) call self%inner%release()
        self%analysed = .false.
        self%factored = .false.
        self%coarse_ready = .false.
    end subroutine two_level_release

    !> The inner method's iterations (an iterative METHODE under the rigid-mode path).
    function two_level_iterations(self) result(text)
        class(two_level_solver_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = ''
        if (allocated(self%inner)) text = self%inner%iteration_summary()
    end function two_level_iterations

end module two_level_solver

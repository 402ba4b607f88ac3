!> Solving with a matrix that differs from the factored one by a few small symmetric blocks:
!> A_new = A + sum_b s_b K_b, s_b = +1 (block added) or -1 (block removed), each K_b a dense
!> element matrix on at most MAX_BLOCK equations. This is what a contact status change does
!> to a tangent: a closing spring adds its element matrix, an opening one removes it (one
!> diagonal term per component when its far end is imposed; rank 1 to 3 otherwise).
!>
!> A_new x = b is solved by conjugate gradients preconditioned by the factor of A
!> (`solve_updated`): A^-1 A_new = I + (low rank), so in exact arithmetic CG ends in at most
!> rank + 1 iterations, and far fewer when the update only moves a few eigenvalues (a stiff
!> plate on a soft bed: mostly its rigid motions). With no block (A_new = A) it is iterative
!> refinement of the direct solve, accelerated by CG. The matrix is never refactored here;
!> the caller decides when a new factorization is cheaper (`factor_cost_in_solves`).
!>
!> CG's coefficients also give the Lanczos tridiagonal matrix of A^-1 A_new, whose extreme
!> eigenvalues (Ritz values) estimate the spectrum of A^-1 A_new: a (near) zero one means
!> A_new is singular, and their ratio bounds how many more digits a factorization of A_new
!> would lose than the factorization of A (for a fixed ordering the pivots of A_new are at
!> least lambda_min times those of A, and its diagonal at most lambda_max times A's).
!> References: Golub & Van Loan, Matrix Computations, 4th ed., alg. 11.5.1 (PCG) and
!> sec. 11.3.5 (CG and Lanczos).
!>
!> With a two-level solver (rigid modes kept apart, two_level_solver) CG runs in its hat
!> coordinates: the caller gives Q^T b and hat products, and the residuals are measured as
!> the original ones (residual_norm).
module low_rank_update
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL
    use sparse_matrix, only: sym_matrix_t, sym_matvec
    use direct_solver, only: direct_solver_t
    use two_level_solver, only: residual_norm
    implicit none
    private

    !> Largest block: a 3D SEG2 spring (2 nodes x DX, DY, DZ).
    integer(i4), parameter, public :: MAX_BLOCK = 6
    !> Why solve_updated stopped.
    integer(i4), parameter, public :: PCG_CONVERGED = 0, PCG_MAX_ITERATIONS = 1, &
        PCG_BREAKDOWN = 2
    !> A factorization runs this many times more flops per second than a solve with its
    !> factor: factorizations run BLAS 3 on dense fronts, solves stream the factor once
    !> forward and once backward (memory bound). Measured with CHOLMOD, one thread, on the
    !> SSNL130 plates (doc/performance.md, "Contact Newton"): 32 x 128 refactorization
    !> 0.069 s for 0.87 Gflop (12.6 Gflop/s), solve 5.3 ms for 4 x 3.8 M terms
    !> (2.9 Gflop/s); 64 x 256: 0.52 s for 7.2 Gflop (13.8), solve 27 ms for 4 x 19.4 M
    !> terms (2.9): ratios 4.4 and 4.8.
    real(dp), parameter :: FACTOR_FLOP_RATE_RATIO = 4.5_dp
    !> A factorization never costs fewer solves than this: its fixed costs (the back-end's
    !> copies and workspace, the pivot report) dominate small matrices.
    real(dp), parameter :: MIN_FACTOR_COST_IN_SOLVES = 4.0_dp

    !> The blocks K_b: block b acts on equations eqs(1:size(b), b) (0 = eliminated
    !> equation, skipped) with the dense symmetric matrix k(1:size(b), 1:size(b), b).
    type, public :: block_set_t
        integer(i4) :: n_blocks = 0
        integer(i4), allocatable :: sizes(:)        !< (n_blocks)
        integer(i4), allocatable :: eqs(:, :)       !< (MAX_BLOCK, n_blocks)
        real(dp), allocatable :: k(:, :, :)         !< (MAX_BLOCK, MAX_BLOCK, n_blocks)
    end type block_set_t

    !> What to ask of solve_updated.
    type, public :: pcg_options_t
        integer(i4) :: max_iterations = 50      !< solves with the factor, at most
        real(dp) :: tolerance = 0.0_dp          !< stop when max|b - A_new x| <= this
    end type pcg_options_t

    !> What solve_updated did.
    type, public :: pcg_report_t
        integer(i4) :: outcome = PCG_CONVERGED
        integer(i4) :: iterations = 0           !< = solves with the factor
        real(dp) :: residual = 0.0_dp           !< max|b - A_new x| (CG's recurrence)
        real(dp) :: ritz_min = 1.0_dp           !< extreme eigenvalues of the Lanczos
        real(dp) :: ritz_max = 1.0_dp           !< matrix: estimates of A^-1 A_new's
    end type pcg_report_t

    !> A CG iteration in progress (pcg_begin, pcg_continue): p is the direction whose
    !> product the caller puts in q; x the solution so far (in the caller's scale).
    type, public :: pcg_work_t
        real(dp), allocatable :: x(:), p(:), q(:)
        real(dp), allocatable :: r(:), z(:), alphas(:), betas(:)
        real(dp) :: rz = 0.0_dp, scale = 1.0_dp, tolerance = 0.0_dp
        integer(i4) :: k = 0, kmax = 1
    end type pcg_work_t

    public :: block_set_init, updated_matvec, solve_updated, pcg_begin, pcg_continue, &
        ritz_extremes, factor_cost_in_solves

contains

    !> Allocates n blocks, all empty.
    !>  width : in, optional, the largest block (default MAX_BLOCK; more when linear
    !>          relations put a spring's node on the equations of others: assembly_relations)
    subroutine block_set_init(set, n, width)
        type(block_set_t), intent(out) :: set
        integer(i4), intent(in) :: n
        integer(i4), intent(in), optional :: width
        integer(i4) :: w
        w = MAX_BLOCK
        if (present(width)) w = max(width, MAX_BLOCK)
        set%n_blocks = n
        allocate (set%sizes(n), source=0_i4)
        allocate (set%eqs(w, n), source=0_i4)
        allocate (set%k(w, w, n), source=0.0_dp)
    end subroutine block_set_init

    !> y = (A + sum_k signs(k) K_active(k)) x.
    !>  a      : in, the assembled matrix (upper triangle, sparse_matrix)
    !>  set    : in, the blocks
    !>  active : in, indices of the blocks that differ; signs : in, +1 or -1 each
    pure subroutine updated_matvec(a, set, active, signs, x, y)
        type(sym_matrix_t), intent(in) :: a
        type(block_set_t), intent(in) :: set
        integer(i4), intent(in) :: active(:), signs(:)
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: y(:)
        integer(i4) :: k, b, i, j, m, ei, ej
        real(dp) :: t, s
        call sym_matvec(a, x, y)
        do k = 1, size(active)
            b = active(k)
            s = real(signs(k), dp)
            m = set%sizes(b)
            do i = 1, m
                ei = set%eqs(i, b)
                if (ei == 0) cycle
                t = 0.0_dp
                do j = 1, m
                    ej = set%eqs(j, b)
                    if (ej > 0) t = t + set%k(i, j, b) * x(ej)
                end do
                y(ei) = y(ei) + s * t
            end do
        end do
    end subroutine updated_matvec

    !> Solves (A + sum_k signs(k) K_active(k)) x = b by CG preconditioned with the factor of
    !> A held by `solver` (module header), from x = 0, until max|b - A_new x| <= tolerance
    !> (CG's recurrence residual) or max_iterations solves; the products with A_new are
    !> updated_matvec's (pcg_begin / pcg_continue for products of the caller's own).
    !>  solver : inout, factored with the values of a (its solve is the preconditioner)
    !>  a      : in, the factored matrix
    !>  set, active, signs : in, the update (updated_matvec)
    !>  b      : in, right-hand side; x : out, the solution (the last iterate if not
    !>           converged; 0 after a breakdown)
    !>  report : out, outcome (PCG_CONVERGED, PCG_MAX_ITERATIONS, PCG_BREAKDOWN: a search
    !>           direction with p^T A_new p <= 0, i.e. A_new not positive definite),
    !>           iterations, residual, Ritz values of A^-1 A_new
    !>  st     : out, the solver's failures
    subroutine solve_updated(solver, a, set, active, signs, b, x, options, report, st)
        class(direct_solver_t), intent(inout) :: solver
        type(sym_matrix_t), intent(in) :: a
        type(block_set_t), intent(in) :: set
        integer(i4), intent(in) :: active(:), signs(:)
        real(dp), intent(in) :: b(:)
        real(dp), intent(out) :: x(:)
        type(pcg_options_t), intent(in) :: options
        type(pcg_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        type(pcg_work_t) :: work
        logical :: more
        if (size(x) /= size(b) .or. a%n /= size(b)) then
            call set_error(st, STATUS_INTERNAL, 'solve_updated: sizes differ')
            return
        end if
        call pcg_begin(work, solver, b, options, report, more, st)
        do while (more .and. st%ok())
            call updated_matvec(a, set, active, signs, work%p, work%q)
            call pcg_continue(work, solver, report, more, st)
        end do
        x = work%x
    end subroutine solve_updated

    !> Starts CG preconditioned by the factor held by `solver` on A_new x = b, from x = 0
    !> (reverse communication: the caller owns the products with A_new). CG runs on
    !> b / max|b|, so its dot products are free of overflow whatever the load's scale.
    !>  work   : out, the iteration; on return with more = .true. the caller sets
    !>           work%q = A_new work%p and calls pcg_continue
    !>  report : out, as solve_updated (iterations counts the solves with the factor)
    !>  more   : out, .false. when done already (b small enough, or n = 0)
    subroutine pcg_begin(work, solver, b, options, report, more, st)
        type(pcg_work_t), intent(out) :: work
        class(direct_solver_t), intent(inout) :: solver
        real(dp), intent(in) :: b(:)
        type(pcg_options_t), intent(in) :: options
        type(pcg_report_t), intent(out) :: report
        logical, intent(out) :: more
        type(status_t), intent(out) :: st
        integer(i4) :: n
        n = size(b, kind=i4)
        work%kmax = max(1_i4, options%max_iterations)
        allocate (work%x(n), work%r(n), work%z(n), work%p(n), work%q(n), &
            work%alphas(work%kmax), work%betas(work%kmax))
        work%x = 0.0_dp
        report%residual = residual_norm(solver, b)
        report%iterations = 0
        more = .false.
        if (report%residual <= options%tolerance .or. n == 0) return
        work%scale = report%residual
        work%r = b / work%scale
        work%tolerance = options%tolerance / work%scale
        work%z = work%r
        call solver%solve(work%z, st)
        if (st%failed()) return
        report%iterations = 1
        work%rz = dot(work%r, work%z)
        work%p = work%z
        work%k = 0
        more = .true.
    end subroutine pcg_begin

    !> One CG step after the caller set work%q = A_new work%p (pcg_begin).
    !>  more : out, .true.: set work%q = A_new work%p again and call again; .false.: done
    !>         (report%outcome; the solution is work%x)
    subroutine pcg_continue(work, solver, report, more, st)
        type(pcg_work_t), intent(inout) :: work
        class(direct_solver_t), intent(inout) :: solver
        type(pcg_report_t), intent(inout) :: report
        logical, intent(out) :: more
        type(status_t), intent(out) :: st
        real(dp) :: pq, alpha, rz_new, beta
        integer(i4) :: k
        more = .false.
        work%k = work%k + 1
        k = work%k
        pq = dot(work%p, work%q)
        if (.not. (pq > 0.0_dp .and. work%rz > 0.0_dp)) then
            report%outcome = PCG_BREAKDOWN
            work%x = 0.0_dp
            return
        end if
        alpha = work%rz / pq
        ! A step the reals cannot hold (loads near huge(1.0_dp): the solution overflows)
        ! ends CG as a breakdown: the caller's direct solve then meets and reports it.
        if (.not. step_fits(alpha, work%scale, work%p, work%x)) then
            report%outcome = PCG_BREAKDOWN
            work%x = 0.0_dp
            return
        end if
        work%x = work%x + (alpha * work%scale) * work%p
        work%r = work%r - alpha * work%q
        work%alphas(k) = alpha
        report%residual = residual_norm(solver, work%r) * work%scale
        call ritz_extremes(work%alphas(1:k), work%betas(1:k - 1), report%ritz_min, &
            report%ritz_max)
        if (residual_norm(solver, work%r) <= work%tolerance) then
            report%outcome = PCG_CONVERGED
            return
        end if
        if (k == work%kmax) then
            report%outcome = PCG_MAX_ITERATIONS
            return
        end if
        work%z = work%r
        call solver%solve(work%z, st)
        if (st%failed()) return
        report%iterations = report%iterations + 1
        rz_new = dot(work%r, work%z)
        beta = rz_new / work%rz
        work%betas(k) = beta
        work%rz = rz_new
        work%p = work%z + beta * work%p
        more = .true.
    end subroutine pcg_continue

    !> .true. when x + (alpha scale) p is finite in every entry, formed without overflow.
    pure logical function step_fits(alpha, scale, p, x) result(fits)
        real(dp), intent(in) :: alpha, scale, p(:), x(:)
        real(dp) :: pmax, xmax
        fits = .false.
        pmax = 0.0_dp
        xmax = 0.0_dp
        if (size(p) > 0) pmax = maxval(abs(p))
        if (size(x) > 0) xmax = maxval(abs(x))
        if (xmax > 0.5_dp * huge(alpha)) return
        ! compared in logarithms, which no operand can overflow
        if (abs(alpha) > 0.0_dp .and. scale > 0.0_dp .and. pmax > 0.0_dp) then
            if (log10(abs(alpha)) + log10(scale) + log10(pmax) > &
                log10(0.5_dp * huge(alpha))) return
        end if
        fits = .true.
    end function step_fits

    !> Extreme eigenvalues of the Lanczos matrix of k CG steps with step lengths alphas(1:k)
    !> and direction updates betas(1:k-1) (Golub & Van Loan 11.3.5): diagonal
    !> 1/alpha_j + beta_(j-1)/alpha_(j-1), off-diagonal sqrt(beta_j)/alpha_j. Bisection on
    !> Sturm sequence counts between Gershgorin bounds, to 1e-12 of the largest.
    pure subroutine ritz_extremes(alphas, betas, lmin, lmax)
        real(dp), intent(in) :: alphas(:), betas(:)
        real(dp), intent(out) :: lmin, lmax
        real(dp) :: d(size(alphas)), e2(size(alphas)), lo, hi, radius
        integer(i4) :: j, k
        k = size(alphas, kind=i4)
        lmin = 1.0_dp
        lmax = 1.0_dp
        if (k == 0) return
        d(1) = 1.0_dp / alphas(1)
        do j = 2, k
            d(j) = 1.0_dp / alphas(j) + betas(j - 1) / alphas(j - 1)
        end do
        e2 = 0.0_dp                                         ! off-diagonal squared
        do j = 1, k - 1
            e2(j) = betas(j) / alphas(j)**2
        end do
        lo = huge(1.0_dp)
        hi = -huge(1.0_dp)
        do j = 1, k
            radius = sqrt(e2(j))
            if (j >= 2) radius = radius + sqrt(e2(max(j - 1, 1_i4)))
            lo = min(lo, d(j) - radius)
            hi = max(hi, d(j) + radius)
        end do
        lmin = bisect_eigenvalue(d, e2, 1_i4, lo, hi)
        lmax = bisect_eigenvalue(d, e2, k, lo, hi)
    end subroutine ritz_extremes

    !> The m-th smallest eigenvalue of the symmetric tridiagonal matrix (diagonal d,
    !> squared off-diagonal e2) in [lo, hi], by bisection on Sturm counts.
    pure real(dp) function bisect_eigenvalue(d, e2, m, lo, hi) result(lambda)
        real(dp), intent(in) :: d(:), e2(:), lo, hi
        integer(i4), intent(in) :: m
        real(dp) :: a, b, c, width
        integer(i4) :: it
        a = lo
        b = hi
        width = max(abs(lo), abs(hi), tiny(1.0_dp))
        do it = 1, 200
            c = 0.5_dp * (a + b)
            if (b - a <= 1.0e-12_dp * width) exit
            if (sturm_count(d, e2, c) >= m) then
                b = c
            else
                a = c
            end if
        end do
        lambda = 0.5_dp * (a + b)
    end function bisect_eigenvalue

    !> Number of eigenvalues of the tridiagonal matrix below x (signs of the LDL^T pivots
    !> of T - x I).
    pure integer(i4) function sturm_count(d, e2, x) result(count)
        real(dp), intent(in) :: d(:), e2(:), x
        real(dp) :: q
        integer(i4) :: j
        real(dp) :: floor
        count = 0
        q = 1.0_dp
        do j = 1, size(d, kind=i4)
            q = d(j) - x - e2(max(j - 1, 1_i4)) / q * merge(1.0_dp, 0.0_dp, j > 1)
            ! an exact zero pivot is nudged below zero (LAPACK dstebz does the same)
            floor = epsilon(1.0_dp) * max(abs(d(j)), abs(x), tiny(1.0_dp))
            if (abs(q) < floor) q = -floor
            if (q < 0.0_dp) count = count + 1
        end do
    end function sturm_count

    !> What one factorization of the analysed matrix costs, counted in solves with its
    !> factor: flops / (4 x factor terms) (a solve runs each term once forward, once
    !> backward, a multiply and an add each time) divided by FACTOR_FLOP_RATE_RATIO, and
    !> at least MIN_FACTOR_COST_IN_SOLVES. Deterministic (flop counts, not timings), so two
    !> runs choose alike and give the same listings.
    !>  flops   : in, the factorization's flop count (0 if the back-end gives none: then
    !>            estimated as terms^2 / n, the count of a factor with even columns)
    !>  terms, n: in, stored terms of the factor, equations
    pure real(dp) function factor_cost_in_solves(flops, terms, n) result(cost)
        real(dp), intent(in) :: flops
        integer(i8), intent(in) :: terms
        integer(i4), intent(in) :: n
        real(dp) :: f
        f = flops
        if (.not. f > 0.0_dp .and. n > 0) f = real(terms, dp)**2 / real(n, dp)
        cost = MIN_FACTOR_COST_IN_SOLVES
        if (terms > 0) cost = max(cost, f / (4.0_dp * real(terms, dp)) / &
            FACTOR_FLOP_RATE_RATIO)
    end function factor_cost_in_solves

    pure real(dp) function dot(x, y)
        real(dp), intent(in) :: x(:), y(:)
        integer(i8) :: i
        dot = 0.0_dp
        do i = 1, size(x, kind=i8)
            dot = dot + x(i) * y(i)
        end do
    end function dot

end module low_rank_update

!> Line search of the contact Newton (contact_newton): the step along a Newton correction
!> p, from the energy of the structure along u + alpha p.
!>
!> Unilateral springs make the potential energy
!>   E(u) = 1/2 u^T K_lin u - f_ext^T u + sum over springs of E_s(u),
!>   E_s = 1/2 kn min(d, 0)^2 + [d <= 0] 1/2 r^T K_t r,
!> piecewise quadratic: its gradient is f_int - f_ext and its (generalised) Hessian the
!> tangent of the current contact status. Full Newton is then a semismooth Newton method;
!> with a step that decreases E it cannot cycle (a status reached twice by full steps would
!> give the same iterate twice, with the energy strictly lower the second time), and with
!> exact line searches on a strictly convex piecewise quadratic energy it ends in finitely
!> many steps (Mangasarian, "A finite Newton method for classification", Optim. Methods
!> Softw. 17, 2002; Nocedal & Wright, Numerical Optimization, 2nd ed., sec. 3.1, the Armijo
!> condition).
!>
!> The normal part 1/2 kn min(d, 0)^2 is convex and C^1. The tangential springs of a closed
!> DIS_CHOC (ssnl130.md) are switched on and off with the status: their term is the
!> potential of the closed branch, so E has a jump of 1/2 r^T K_t r where a spring with a
!> tangential relative displacement opens or closes (the law is not the gradient of one
!> energy then). That is the energy chosen here: it is exact on each contact status, it is
!> E of the normal law wherever the tangential displacement of the springs that change is
!> nil (every SSNL130 deck: vertical springs, vertical load), and the search minimises it
!> piece by piece, jumps included.
!>
!> Along p the energy is known exactly from per-spring data (choc_line_t): with g0 = the
!> slope at alpha = 0 (p^T (f_int - f_ext)) and B = p^T K_S p (S the status at u),
!>   E(u + alpha p) - E(u) = alpha g0 + alpha^2 B / 2 + sum over the springs whose status
!>   differs at alpha of +Q_s(alpha) (closed there) or -Q_s(alpha) (opened),
!> Q_s the closed-branch energy of spring s. The full step is kept when no spring changes
!> status on (0, 1] (then E is that quadratic and alpha = 1 is its minimum) or when it
!> satisfies Armijo's condition with ARMIJO_C; otherwise the exact minimiser on (0, 1].
module contact_line_search
    use kinds, only: dp, i4
    use element_dis_choc, only: choc_line_t
    implicit none
    private

    !> Sufficient decrease E(u + p) - E(u) <= ARMIJO_C g0 of a full step (Nocedal & Wright
    !> 3.1: the usual value).
    real(dp), parameter, public :: ARMIJO_C = 1.0e-4_dp

    !> What the line search chose.
    type, public :: step_choice_t
        real(dp) :: alpha = 1.0_dp            !< the step taken
        integer(i4) :: n_crossing = 0         !< springs that change status on (0, 1]
        logical :: damped = .false.           !< alpha < 1
        real(dp) :: energy_full = 0.0_dp      !< E(u + p) - E(u)
        real(dp) :: energy_step = 0.0_dp      !< E(u + alpha p) - E(u)
    end type step_choice_t

    public :: choose_step, line_energy, any_crossing

contains

    !> Chooses the step along p (module header).
    !>  lines : in, each spring along p (spring_lines)
    !>  g0    : in, p^T (f_int - f_ext) at u (< 0 for a descent direction)
    !>  b     : in, p^T K_S p, S = the contact status at u
    !>  choice: out, alpha = 1 unless a spring changes status and the full step fails
    !>          Armijo's condition (or p is no descent direction: then alpha = 1 too)
    pure subroutine choose_step(lines, g0, b, choice)
        type(choc_line_t), intent(in) :: lines(:)
        real(dp), intent(in) :: g0, b
        type(step_choice_t), intent(out) :: choice
        real(dp), allocatable :: at(:)
        integer(i4), allocatable :: order(:), which(:)
        real(dp) :: c(0:2), lo, hi, a, best, best_alpha, value
        integer(i4) :: k, s
        call crossings(lines, at, which)
        choice%n_crossing = size(at, kind=i4)
        if (choice%n_crossing == 0) return
        choice%energy_full = line_energy(lines, g0, b, 1.0_dp)
        choice%energy_step = choice%energy_full
        if (choice%energy_full <= ARMIJO_C * g0 .or. .not. g0 < 0.0_dp) return
        ! exact minimum: sweep the pieces between breakpoints, the quadratic of each kept
        ! as c(0) + c(1) alpha + c(2) alpha^2 / 2
        order = sorted_order(at)
        c = [0.0_dp, g0, b]
        best = 0.0_dp
        best_alpha = 0.0_dp
        lo = 0.0_dp
        do k = 0, size(order, kind=i4)
            hi = 1.0_dp
            if (k < size(order)) hi = at(order(k + 1))
            if (hi > lo .or. k == size(order)) then
                a = piece_minimum(c, lo, hi)
                value = c(0) + a * (c(1) + 0.5_dp * a * c(2))
                if (value < best .and. a > 0.0_dp) then
                    best = value
                    best_alpha = a
                end if
            end if
            if (k == size(order)) exit
            ! past this breakpoint the spring has the other status
            s = which(order(k + 1))
            call add_branch(lines(s), merge(-1.0_dp, 1.0_dp, lines(s)%gap <= 0.0_dp), c)
            lo = hi
        end do
        if (best_alpha > 0.0_dp) then
            choice%alpha = best_alpha
            choice%energy_step = best
            choice%damped = best_alpha < 1.0_dp
        end if
    end subroutine choose_step

    !> Whether some spring changes status on (0, 1] (else the full step is kept).
    pure logical function any_crossing(lines)
        type(choc_line_t), intent(in) :: lines(:)
        integer(i4) :: s
        real(dp) :: a
        any_crossing = .false.
        do s = 1, size(lines, kind=i4)
            call crossing(lines(s), any_crossing, a)
            if (any_crossing) return
        end do
    end function any_crossing

    !> E(u + alpha p) - E(u) from the line data (module header).
    pure real(dp) function line_energy(lines, g0, b, alpha) result(e)
        type(choc_line_t), intent(in) :: lines(:)
        real(dp), intent(in) :: g0, b, alpha
        integer(i4) :: s
        logical :: closed0, closed
        e = alpha * (g0 + 0.5_dp * alpha * b)
        do s = 1, size(lines, kind=i4)
            closed0 = lines(s)%gap <= 0.0_dp
            closed = lines(s)%gap + alpha * lines(s)%slope <= 0.0_dp
            if (closed .eqv. closed0) cycle
            e = e + merge(1.0_dp, -1.0_dp, closed) * closed_energy(lines(s), alpha)
        end do
    end function line_energy

    !> Q_s(alpha): the closed-branch energy of one spring at u + alpha p.
    pure real(dp) function closed_energy(line, alpha) result(q)
        type(choc_line_t), intent(in) :: line
        real(dp), intent(in) :: alpha
        real(dp) :: d
        d = line%gap + alpha * line%slope
        q = 0.5_dp * line%kn * d * d + line%t0 + alpha * (line%t1 + 0.5_dp * alpha * line%t2)
    end function closed_energy

    !> Adds sign * Q_s(alpha) to the piece's coefficients c(0) + c(1) a + c(2) a^2 / 2.
    pure subroutine add_branch(line, sign, c)
        type(choc_line_t), intent(in) :: line
        real(dp), intent(in) :: sign
        real(dp), intent(inout) :: c(0:2)
        c(0) = c(0) + sign * (0.5_dp * line%kn * line%gap**2 + line%t0)
        c(1) = c(1) + sign * (line%kn * line%gap * line%slope + line%t1)
        c(2) = c(2) + sign * (line%kn * line%slope**2 + line%t2)
    end subroutine add_branch

    !> Minimiser of c(0) + c(1) a + c(2) a^2 / 2 on [lo, hi].
    pure real(dp) function piece_minimum(c, lo, hi) result(a)
        real(dp), intent(in) :: c(0:2), lo, hi
        real(dp) :: vlo, vhi
        if (c(2) > 0.0_dp) then
            a = min(max(-c(1) / c(2), lo), hi)
        else
            vlo = lo * (c(1) + 0.5_dp * lo * c(2))
            vhi = hi * (c(1) + 0.5_dp * hi * c(2))
            a = merge(lo, hi, vlo <= vhi)
        end if
    end function piece_minimum

    !> Breakpoints in (0, 1]: where a closed spring (gap <= 0) opens (gap + alpha slope
    !> turns positive) or an open one closes (reaches 0); at(k) for the k-th spring that
    !> changes, which(k) that spring.
    pure subroutine crossings(lines, at, which)
        type(choc_line_t), intent(in) :: lines(:)
        real(dp), allocatable, intent(out) :: at(:)
        integer(i4), allocatable, intent(out) :: which(:)
        integer(i4) :: s, n
        real(dp) :: a
        logical :: changes
        allocate (at(size(lines)), which(size(lines)))
        n = 0
        do s = 1, size(lines, kind=i4)
            call crossing(lines(s), changes, a)
            if (.not. changes) cycle
            n = n + 1
            at(n) = a
            which(n) = s
        end do
        at = at(1:n)
        which = which(1:n)
    end subroutine crossings

    !> Whether a spring changes status on (0, 1], and where (a).
    pure subroutine crossing(line, changes, a)
        type(choc_line_t), intent(in) :: line
        logical, intent(out) :: changes
        real(dp), intent(out) :: a
        changes = .false.
        a = 0.0_dp
        if (line%gap <= 0.0_dp) then
            if (.not. line%gap + line%slope > 0.0_dp) return
            a = -line%gap / line%slope      ! slope > 0 here
        else
            if (.not. line%gap + line%slope <= 0.0_dp) return
            a = -line%gap / line%slope      ! slope < 0 here
        end if
        a = min(max(a, 0.0_dp), 1.0_dp)
        changes = .true.
    end subroutine crossing

    !> Indices that sort x increasingly (merge sort: stable, n log n).
    pure function sorted_order(x) result(order)
        real(dp), intent(in) :: x(:)
        integer(i4), allocatable :: order(:)
        integer(i4), allocatable :: tmp(:)
        integer(i4) :: n, width, lo, mid, hi, i, j, k
        n = size(x, kind=i4)
        allocate (order(n), tmp(n))
        order = [(i, i = 1, n)]
        width = 1
        do while (width < n)
            do lo = 1, n, 2 * width
                mid = min(lo + width - 1, n)
                hi = min(lo + 2 * width - 1, n)
                i = lo
                j = mid + 1
                do k = lo, hi
                    if (i <= mid .and. (j > hi .or. x(order(min(i, n))) <= &
                        x(order(min(j, n))))) then
                        tmp(k) = order(i)
                        i = i + 1
                    else
                        tmp(k) = order(j)
                        j = j + 1
                    end if
                end do
            end do
            order = tmp
            width = 2 * width
        end do
    end function sorted_order

end module contact_line_search

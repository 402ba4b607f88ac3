!> Operations on functions given by points (CALC_FONCTION), as Code_Aster's t_fonction
!> does them (code_aster/Objects/function_py.py), on function_samples_t (LIN LIN
!> interpolation):
!>  - evaluation with the prolongations, an abscissa within 1e-6 of an end (relative to the
!>    end interval) taking the end value (Code_Aster's tolerance against round-off);
!>  - sum and product of two functions on the union of their abscissae, clipped to the
!>    common range where a side is EXCLU (homo_support), the prolongations following;
!>  - derivative (centred slopes weighted by the steps, one-sided at the ends), primitive by
!>    trapezes or Simpson's rule, inverse, absolute value, envelope, integer power.
!> Every value is formed so that it cannot overflow: a product, quotient or sum beyond
!> double precision is an error naming the abscissa, never an Inf.
module function_algebra
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp, i4
    use strings, only: real_e13
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use number_limits, only: product_fits, MAX_BINARY_EXPONENT
    use tabulated_function, only: PROL_EXCLU, PROL_CONSTANT, PROL_LINEAIRE
    use deck_concept, only: concept_t, concept_display_name
    use function_concept, only: function_concept_t
    use function_points, only: function_samples_t, samples_of_function
    use table_sort, only: real_order
    implicit none
    private

    !> Code_Aster's tolerance on the ends of the abscissae (t_fonction.__call__).
    real(dp), parameter :: END_TOLERANCE = 1.0e-6_dp

    public :: function_value_at, samples_value, samples_at, samples_sum, samples_product, samples_scaled, &
        samples_derivative, samples_trapezes, samples_simpson, samples_inverse, &
        samples_abs, samples_envelope, union_abscissae, check_magnitudes

    !> Largest binary exponent of an abscissa or ordinate the operations take: sums of a
    !> few of them stay finite; products and quotients are checked one by one.
    integer, parameter :: MAX_OPERAND_EXPONENT = MAX_BINARY_EXPONENT - 4

contains

    !> The value of function concept `c` at `t` as Code_Aster's Python objects give it
    !> (Function.__call__): a function by points (DEFI_FONCTION, DEFI_CONSTANTE, ...) through
    !> t_fonction (samples_value: the 1e-6 tolerance at the ends of the steps), any other
    !> function (a FORMULE) by its own evaluation.
    subroutine function_value_at(c, t, y, st)
        class(concept_t), intent(in) :: c
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y
        type(status_t), intent(inout) :: st
        type(function_samples_t) :: s
        type(status_t) :: by_points
        y = 0.0_dp
        call samples_of_function(c, s, by_points)
        if (by_points%ok()) then
            call samples_value(s, t, y, st)
            return
        end if
        select type (c)
        class is (function_concept_t)
            call c%call_real([t], y, st)
        class default
            call set_error(st, STATUS_MODEL_ERROR, concept_display_name(c) // ' is not a function')
        end select
    end subroutine function_value_at

    !> f(t) (see the module header).
    !>  st : STATUS_MODEL_ERROR outside an EXCLU end
    subroutine samples_value(f, t, y, st)
        type(function_samples_t), intent(in) :: f
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y
        type(status_t), intent(inout) :: st
        integer :: n, lo, hi, mid
        n = size(f%x)
        y = 0.0_dp
        if (n == 1) then
            y = f%y(1)
            if (abs(t - f%x(1)) <= END_TOLERANCE * abs(f%x(1))) return
            if (t > f%x(1) .and. f%right /= PROL_EXCLU) return
            if (t < f%x(1) .and. f%left /= PROL_EXCLU) return
            call outside(t)
            return
        end if
        if (t <= f%x(1)) then
            if (near(t, f%x(1), f%x(2))) then
                y = f%y(1)
            else if (f%left == PROL_CONSTANT) then
                y = f%y(1)
            else if (f%left == PROL_LINEAIRE) then
                call line(f%x(1), f%x(2), f%y(1), f%y(2), t, y, st)
            else
                call outside(t)
            end if
            return
        end if
        if (t >= f%x(n)) then
            if (near(t, f%x(n), f%x(n - 1))) then
                y = f%y(n)
            else if (f%right == PROL_CONSTANT) then
                y = f%y(n)
            else if (f%right == PROL_LINEAIRE) then
                call line(f%x(n), f%x(n - 1), f%y(n), f%y(n - 1), t, y, st)
            else
                call outside(t)
            end if
            return
        end if
        lo = 1
        hi = n
        do while (hi - lo > 1)
            mid = (lo + hi) / 2
            if (f%x(mid) <= t) then
                lo = mid
            else
                hi = mid
            end if
        end do
        call line(f%x(lo), f%x(hi), f%y(lo), f%y(hi), t, y, st)
    contains
        logical function near(v, end, other)
            real(dp), intent(in) :: v, end, other
            near = abs(v - end) <= END_TOLERANCE * abs(other - end)
        end function near

        subroutine outside(v)
            real(dp), intent(in) :: v
            call set_error(st, STATUS_MODEL_ERROR, 'the function is evaluated at ' // &
                real_e13(v) // ', outside its abscissae [' // real_e13(f%x(1)) // ', ' // &
                real_e13(f%x(n)) // '] where it is EXCLU')
        end subroutine outside
    end subroutine samples_value

    !> y on the line through (xa, ya), (xb, yb) at t, as Code_Aster's interp (LIN LIN):
    !> ya + (yb - ya) * (t - xa) / (xb - xa), the ends within 1e-6 of the step taking the
    !> end value; without overflow.
    subroutine line(xa, xb, ya, yb, t, y, st)
        real(dp), intent(in) :: xa, xb, ya, yb, t
        real(dp), intent(out) :: y
        type(status_t), intent(inout) :: st
        real(dp) :: rise, run
        y = ya
        if (abs(t - xa) < END_TOLERANCE * abs(xb - xa)) return
        y = yb
        if (abs(t - xb) < END_TOLERANCE * abs(xb - xa)) return
        rise = plus(yb, -ya, t, st)
        if (st%ok()) run = plus(t, -xa, t, st)
        if (st%ok()) rise = times(rise, run, t, st)
        if (st%ok()) run = plus(xb, -xa, t, st)
        if (st%ok()) rise = over(rise, run, t, st)
        if (st%ok()) y = plus(ya, rise, t, st)
    end subroutine line

    !> The function at each abscissa of `x` (Code_Aster's evalfonc).
    subroutine samples_at(f, x, g, st)
        type(function_samples_t), intent(in) :: f
        real(dp), intent(in) :: x(:)
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        integer :: k
        g = f
        g%x = x
        deallocate (g%y)
        allocate (g%y(size(x)))
        do k = 1, size(x)
            call samples_value(f, x(k), g%y(k), st)
            if (st%failed()) return
        end do
    end subroutine samples_at

    !> The union of two functions' abscissae (sorted, each once), clipped to the common
    !> range where a side is EXCLU, and the prolongations of the result (homo_support).
    subroutine union_abscissae(a, b, x, left, right)
        type(function_samples_t), intent(in) :: a, b
        real(dp), allocatable, intent(out) :: x(:)
        integer, intent(out) :: left, right
        real(dp) :: low, high
        real(dp), allocatable :: all(:)
        integer, allocatable :: order(:)
        integer :: k, n
        if (b%x(1) > a%x(1)) then
            low = merge(a%x(1), b%x(1), b%left /= PROL_EXCLU)
            left = merge(a%left, b%left, b%left /= PROL_EXCLU)
        else
            low = merge(b%x(1), a%x(1), a%left /= PROL_EXCLU)
            left = merge(b%left, a%left, a%left /= PROL_EXCLU)
        end if
        if (a%x(size(a%x)) > b%x(size(b%x))) then
            high = merge(a%x(size(a%x)), b%x(size(b%x)), b%right /= PROL_EXCLU)
            right = merge(a%right, b%right, b%right /= PROL_EXCLU)
        else
            high = merge(b%x(size(b%x)), a%x(size(a%x)), a%right /= PROL_EXCLU)
            right = merge(b%right, a%right, a%right /= PROL_EXCLU)
        end if
        all = min(max([a%x, b%x], low), high)
        order = real_order(all)
        all = all(order)
        allocate (x(size(all)))
        n = 0
        do k = 1, size(all)
            if (n > 0) then
                if (.not. all(k) > x(n)) cycle
            end if
            n = n + 1
            x(n) = all(k)
        end do
        x = x(1:n)
    end subroutine union_abscissae

    !> a + b on their union (t_fonction.__add__); names and interpolation of `a`.
    subroutine samples_sum(a, b, c, st)
        type(function_samples_t), intent(in) :: a, b
        type(function_samples_t), intent(out) :: c
        type(status_t), intent(inout) :: st
        call combine(a, b, .true., c, st)
    end subroutine samples_sum

    !> a * b on their union (t_fonction.__mul__).
    subroutine samples_product(a, b, c, st)
        type(function_samples_t), intent(in) :: a, b
        type(function_samples_t), intent(out) :: c
        type(status_t), intent(inout) :: st
        call combine(a, b, .false., c, st)
    end subroutine samples_product

    subroutine combine(a, b, add, c, st)
        type(function_samples_t), intent(in) :: a, b
        logical, intent(in) :: add
        type(function_samples_t), intent(out) :: c
        type(status_t), intent(inout) :: st
        type(function_samples_t) :: fa, fb
        real(dp), allocatable :: x(:)
        integer :: left, right, k
        call union_abscissae(a, b, x, left, right)
        call samples_at(a, x, fa, st)
        if (st%ok()) call samples_at(b, x, fb, st)
        if (st%failed()) return
        c = fa
        c%left = left
        c%right = right
        do k = 1, size(x)
            if (add) then
                c%y(k) = plus(fa%y(k), fb%y(k), x(k), st)
            else
                c%y(k) = times(fa%y(k), fb%y(k), x(k), st)
            end if
            if (st%failed()) return
        end do
    end subroutine combine

    !> coef * f.
    subroutine samples_scaled(f, coef, g, st)
        type(function_samples_t), intent(in) :: f
        real(dp), intent(in) :: coef
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        integer :: k
        g = f
        do k = 1, size(f%y)
            g%y(k) = times(coef, f%y(k), f%x(k), st)
            if (st%failed()) return
        end do
    end subroutine samples_scaled

    !> DERIVE: centred slopes weighted by the steps, one-sided at the ends; EXCLU both
    !> sides; NOM_RESU DEPL -> VITE -> ACCE.
    subroutine samples_derivative(f, g, st)
        type(function_samples_t), intent(in) :: f
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: slope(:), step(:)
        real(dp) :: a, b
        integer :: n, k
        n = size(f%x)
        g = f
        g%left = PROL_EXCLU
        g%right = PROL_EXCLU
        if (n < 2) then
            call set_error(st, STATUS_MODEL_ERROR, 'a function of one point has no derivative')
            return
        end if
        allocate (slope(n - 1), step(n - 1))
        do k = 1, n - 1
            step(k) = f%x(k + 1) - f%x(k)
            slope(k) = over(f%y(k + 1) - f%y(k), step(k), f%x(k), st)
            if (st%failed()) return
        end do
        g%y(1) = slope(1)
        g%y(n) = slope(n - 1)
        do k = 2, n - 1
            a = times(slope(k), step(k), f%x(k), st)
            if (st%ok()) b = times(slope(k - 1), step(k - 1), f%x(k), st)
            if (st%ok()) g%y(k) = over(0.5_dp * a + 0.5_dp * b, 0.5_dp * step(k) + &
                                       0.5_dp * step(k - 1), f%x(k), st)
            if (st%failed()) return
        end do
        if (g%result_name(1:min(4, len(g%result_name))) == 'DEPL') then
            g%result_name = 'VITE'
        else if (g%result_name(1:min(4, len(g%result_name))) == 'VITE') then
            g%result_name = 'ACCE'
        end if
    end subroutine samples_derivative

    !> INTEGRE TRAPEZE: the primitive by trapezes from `coef` at the first abscissa.
    subroutine samples_trapezes(f, coef, g, st)
        type(function_samples_t), intent(in) :: f
        real(dp), intent(in) :: coef
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        real(dp) :: area
        integer :: k
        call primitive_names(f, g)
        g%y(1) = coef
        do k = 2, size(f%x)
            area = times(0.5_dp * f%y(k) + 0.5_dp * f%y(k - 1), f%x(k) - f%x(k - 1), &
                         f%x(k), st)
            if (st%ok()) g%y(k) = plus(g%y(k - 1), area, f%x(k), st)
            if (st%failed()) return
        end do
    end subroutine samples_trapezes

    !> INTEGRE SIMPSON: Code_Aster's Simpson primitive on uneven steps (two interleaved
    !> sums, each advancing by a parabola through three points).
    subroutine samples_simpson(f, coef, g, st)
        type(function_samples_t), intent(in) :: f
        real(dp), intent(in) :: coef
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        real(dp) :: sums(2), fa, fm, fb, h1, h2, span, delta, e, ct(3), part, terms(3)
        integer :: k, which
        call primitive_names(f, g)
        g%y(1) = coef
        if (size(f%x) < 2) then
            call set_error(st, STATUS_MODEL_ERROR, 'Simpson''s rule needs two points at ' // &
                'least: the function has one')
            return
        end if
        fm = f%y(1)
        fb = f%y(2)
        h2 = f%x(2) - f%x(1)
        sums(1) = coef
        part = times(fb + fm, 0.5_dp * h2, f%x(2), st)
        if (st%ok()) sums(2) = plus(coef, part, f%x(2), st)
        if (st%failed()) return
        g%y(2) = sums(2)
        which = 1
        do k = 3, size(f%x)
            h1 = h2
            h2 = f%x(k) - f%x(k - 1)
            span = h1 + h2
            fa = fm
            fm = fb
            fb = f%y(k)
            delta = h2 - h1
            if (abs(delta) <= 1.0e-4_dp * abs(h1)) then
                ct = [1.0_dp, 4.0_dp, 1.0_dp]
            else
                e = over(delta, h1, f%x(k), st)        ! (h2 - h1) / h1
                if (st%ok()) ct(2) = over(delta, h2, f%x(k), st)
                if (st%failed()) return
                ! 1 - delta/h1, 2 + delta^2/(h1 h2), 1 + delta/h2
                part = times(e, ct(2), f%x(k), st)
                if (st%failed()) return
                ct = [1.0_dp - e, 2.0_dp + part, 1.0_dp + ct(2)]
            end if
            terms(1) = times(ct(1), fa, f%x(k), st)
            if (st%ok()) terms(2) = times(ct(2), fm, f%x(k), st)
            if (st%ok()) terms(3) = times(ct(3), fb, f%x(k), st)
            if (st%ok()) part = plus(terms(1), terms(2), f%x(k), st)
            if (st%ok()) part = plus(part, terms(3), f%x(k), st)
            if (st%ok()) part = times(span / 6.0_dp, part, f%x(k), st)
            if (st%ok()) sums(which) = plus(sums(which), part, f%x(k), st)
            if (st%failed()) return
            g%y(k) = sums(which)
            which = 3 - which
        end do
    end subroutine samples_simpson

    !> The result of a primitive: EXCLU both sides; NOM_RESU VITE -> DEPL, ACCE -> VITE.
    subroutine primitive_names(f, g)
        type(function_samples_t), intent(in) :: f
        type(function_samples_t), intent(out) :: g
        g = f
        g%left = PROL_EXCLU
        g%right = PROL_EXCLU
        if (g%result_name(1:min(4, len(g%result_name))) == 'VITE') then
            g%result_name = 'DEPL'
        else if (g%result_name(1:min(4, len(g%result_name))) == 'ACCE') then
            g%result_name = 'VITE'
        end if
    end subroutine primitive_names

    !> INVERSE: abscissae and ordinates swapped (reversed when decreasing); NOM_RESU
    !> TOUTRESU; a CONSTANT prolongation becomes EXCLU.
    subroutine samples_inverse(f, g)
        type(function_samples_t), intent(in) :: f
        type(function_samples_t), intent(out) :: g
        integer :: n
        g = f
        n = size(f%x)
        g%x = f%y
        g%y = f%x
        if (n > 1) then
            if (any(g%x(2:) < g%x(:n - 1))) then
                g%x = g%x(n:1:-1)
                g%y = g%y(n:1:-1)
            end if
        end if
        g%result_name = 'TOUTRESU'
        if (g%left == PROL_CONSTANT) g%left = PROL_EXCLU
        if (g%right == PROL_CONSTANT) g%right = PROL_EXCLU
    end subroutine samples_inverse

    !> ABS: |ordinates|; a LINEAIRE prolongation becomes EXCLU.
    subroutine samples_abs(f, g)
        type(function_samples_t), intent(in) :: f
        type(function_samples_t), intent(out) :: g
        g = f
        g%y = abs(f%y)
        if (g%left == PROL_LINEAIRE) g%left = PROL_EXCLU
        if (g%right == PROL_LINEAIRE) g%right = PROL_EXCLU
    end subroutine samples_abs

    !> ENVELOPPE: the largest (SUP) or smallest (INF) value of the functions on the union
    !> of their abscissae; names and prolongations of the first.
    subroutine samples_envelope(fs, upper, g, st)
        type(function_samples_t), intent(in) :: fs(:)
        logical, intent(in) :: upper
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: all(:)
        integer, allocatable :: order(:)
        real(dp) :: v
        integer :: k, j, n
        all = [(fs(k)%x, k=1, size(fs))]
        order = real_order(all)
        all = all(order)
        g = fs(1)
        deallocate (g%x, g%y)
        allocate (g%x(size(all)), g%y(size(all)))
        n = 0
        do k = 1, size(all)
            if (n > 0) then
                if (.not. all(k) > g%x(n)) cycle
            end if
            n = n + 1
            g%x(n) = all(k)
            do j = 1, size(fs)
                call samples_value(fs(j), all(k), v, st)
                if (st%failed()) return
                if (j == 1) then
                    g%y(n) = v
                else if (upper) then
                    g%y(n) = max(g%y(n), v)
                else
                    g%y(n) = min(g%y(n), v)
                end if
            end do
        end do
        g%x = g%x(1:n)
        g%y = g%y(1:n)
    end subroutine samples_envelope

    ! ---- arithmetic that cannot overflow ---------------------------------------------

    !> Refuses a function with an abscissa or ordinate beyond 2**MAX_OPERAND_EXPONENT
    !> (about 6.7E+299), where the operations' sums could overflow.
    subroutine check_magnitudes(f, st)
        type(function_samples_t), intent(in) :: f
        type(status_t), intent(inout) :: st
        integer :: k
        do k = 1, size(f%x)
            if (too_large(f%x(k)) .or. too_large(f%y(k))) then
                call set_error(st, STATUS_MODEL_ERROR, 'the point (' // real_e13(f%x(k)) // &
                    ', ' // real_e13(f%y(k)) // ') is too large for the operations on ' // &
                    'functions (their values stay below 6.7E+299)')
                return
            end if
        end do
    contains
        logical function too_large(v)
            real(dp), intent(in) :: v
            too_large = .false.
            if (abs(v) > 0.0_dp) too_large = exponent(v) > MAX_OPERAND_EXPONENT
        end function too_large
    end subroutine check_magnitudes

    real(dp) function times(a, b, at, st) result(c)
        real(dp), intent(in) :: a, b, at
        type(status_t), intent(inout) :: st
        c = 0.0_dp
        if (.not. product_fits(a, b)) then
            call beyond(at, st)
            return
        end if
        c = a * b
    end function times

    real(dp) function over(a, b, at, st) result(c)
        real(dp), intent(in) :: a, b, at
        type(status_t), intent(inout) :: st
        c = 0.0_dp
        if (.not. abs(b) > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'two abscissae are equal near ' // &
                real_e13(at) // ': the step is zero')
            return
        end if
        if (.not. (ieee_is_finite(a) .and. ieee_is_finite(b))) then
            call beyond(at, st)
            return
        end if
        if (abs(a) > 0.0_dp) then
            if (exponent(a) - exponent(b) + 1 > MAX_BINARY_EXPONENT) then
                call beyond(at, st)
                return
            end if
        end if
        c = a / b
    end function over

    real(dp) function plus(a, b, at, st) result(c)
        real(dp), intent(in) :: a, b, at
        type(status_t), intent(inout) :: st
        c = 0.0_dp
        if (abs(a) > huge(1.0_dp) / 4.0_dp .or. abs(b) > huge(1.0_dp) / 4.0_dp) then
            if (abs(0.5_dp * a + 0.5_dp * b) > huge(1.0_dp) / 2.0_dp) then
                call beyond(at, st)
                return
            end if
        end if
        c = a + b
    end function plus

    subroutine beyond(at, st)
        real(dp), intent(in) :: at
        type(status_t), intent(inout) :: st
        call set_error(st, STATUS_MODEL_ERROR, 'a value at abscissa ' // real_e13(at) // &
            ' is beyond double precision')
    end subroutine beyond

end module function_algebra

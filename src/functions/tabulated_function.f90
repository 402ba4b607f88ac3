!> DEFI_FONCTION: a piecewise-linear function of one parameter (INTERPOL 'LIN','LIN'),
!> with PROL_GAUCHE / PROL_DROITE = EXCLU (error outside the range), CONSTANT (end value)
!> or LINEAIRE (extension of the end segment), as Code_Aster's U4.31.02 describes.
module tabulated_function
    use kinds, only: dp
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use number_limits, only: magnitude_fits, product_fits, MAX_BINARY_EXPONENT
    use deck_concept, only: concept_display_name
    use function_concept, only: function_concept_t, param_binding_t, missing_parameter
    implicit none
    private

    integer, parameter, public :: PROL_EXCLU = 0, PROL_CONSTANT = 1, PROL_LINEAIRE = 2

    type, extends(function_concept_t), public :: tabulated_function_t
        character(len=:), allocatable :: parameter        !< NOM_PARA
        character(len=:), allocatable :: result_name      !< NOM_RESU (default TOUTRESU)
        real(dp), allocatable :: x(:), y(:)               !< strictly increasing x
        integer :: left = PROL_EXCLU, right = PROL_EXCLU
    contains
        procedure :: type_name => tabulated_type_name
        procedure :: parameters => tabulated_parameters
        procedure :: evaluate => tabulated_evaluate
        procedure :: summary => tabulated_summary
    end type tabulated_function_t

    public :: interpolate_table, prolongation_code

contains

    function tabulated_type_name(self) result(name)
        class(tabulated_function_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'fonction'
        if (.false.) name = self%parameter
    end function tabulated_type_name

    function tabulated_parameters(self) result(names)
        class(tabulated_function_t), intent(in) :: self
        type(string_t), allocatable :: names(:)
        allocate (names(1))
        names(1)%s = self%parameter
    end function tabulated_parameters

    subroutine tabulated_evaluate(self, binding, values, y, st)
        class(tabulated_function_t), intent(in) :: self
        type(param_binding_t), intent(in) :: binding
        real(dp), intent(in) :: values(:)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        y = 0.0_dp
        if (binding%slot(1) == 0) then
            call missing_parameter(concept_display_name(self), binding, 1, st)
            return
        end if
        call interpolate_table(self%x, self%y, self%left, self%right, values(binding%slot(1)), &
                               y, st)
        if (st%failed()) st%message = 'function ' // concept_display_name(self) // ': ' // &
            st%message
    end subroutine tabulated_evaluate

    !> Piecewise-linear interpolation in (x, y) at t, with the given prolongations.
    !>  st : out, STATUS_MODEL_ERROR when t is outside an EXCLU end
    subroutine interpolate_table(x, y, left, right, t, value, st)
        real(dp), intent(in) :: x(:), y(:), t
        integer, intent(in) :: left, right
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        integer :: lo, hi, mid, n
        n = size(x)
        value = 0.0_dp
        if (n == 1) then
            value = y(1)
            if ((t < x(1) .and. left == PROL_EXCLU) .or. (t > x(1) .and. right == PROL_EXCLU)) &
                call outside(st, t, x(1), x(1))
            return
        end if
        if (t < x(1)) then
            select case (left)
            case (PROL_EXCLU)
                call outside(st, t, x(1), x(n))
            case (PROL_CONSTANT)
                value = y(1)
            case default
                call linear_through(x(1), y(1), x(2), y(2), t, value, st)
            end select
            return
        end if
        if (t > x(n)) then
            select case (right)
            case (PROL_EXCLU)
                call outside(st, t, x(1), x(n))
            case (PROL_CONSTANT)
                value = y(n)
            case default
                call linear_through(x(n), y(n), x(n - 1), y(n - 1), t, value, st)
            end select
            return
        end if
        lo = 1; hi = n
        do while (hi - lo > 1)                   ! bisection: x(lo) <= t <= x(hi)
            mid = (lo + hi) / 2
            if (x(mid) <= t) then
                lo = mid
            else
                hi = mid
            end if
        end do
        call linear_through(x(lo), y(lo), x(hi), y(hi), t, value, st)
    end subroutine interpolate_table

    !> The line through (xa, ya) and (xb, yb) at t: ya + (t - xa) (yb - ya) / (xb - xa),
    !> formed only when every term stays below 2**MAX_BINARY_EXPONENT (number_limits), so
    !> that ordinates such as -1e308 cannot overflow in the interpolation itself (issue 13);
    !> otherwise an error. When the product (t - xa)(yb - ya) would not fit but the quotient
    !> first does, the quotient is taken first (the last bit may differ, the value not).
    subroutine linear_through(xa, ya, xb, yb, t, value, st)
        real(dp), intent(in) :: xa, ya, xb, yb, t
        real(dp), intent(out) :: value
        type(status_t), intent(inout) :: st
        real(dp) :: dt, dy, dx, q
        value = ya
        if (all(magnitude_fits([xa, ya, xb, yb, t]))) then
            dt = t - xa
            dy = yb - ya
            dx = xb - xa
            if (.not. abs(dx) > 0.0_dp) return
            if (product_fits(dt, dy)) then
                q = dt * dy
                if (exponent(q) - exponent(dx) + 1 <= MAX_BINARY_EXPONENT) then
                    value = ya + q / dx
                    return
                end if
            end if
            if (exponent(dt) - exponent(dx) + 1 <= MAX_BINARY_EXPONENT) then
                q = dt / dx
                if (product_fits(q, dy)) then
                    value = ya + q * dy
                    return
                end if
            end if
        end if
        value = 0.0_dp
        call set_error(st, STATUS_MODEL_ERROR, 'the value at ' // to_text(t) // &
            ' is beyond 2**' // to_text(MAX_BINARY_EXPONENT) // ' (about 1.07E+301) in ' // &
            'the linear interpolation between (' // to_text(xa) // ', ' // to_text(ya) // &
            ') and (' // to_text(xb) // ', ' // to_text(yb) // '): values too large')
    end subroutine linear_through

    subroutine outside(st, t, a, b)
        type(status_t), intent(inout) :: st
        real(dp), intent(in) :: t, a, b
        call set_error(st, STATUS_MODEL_ERROR, 'parameter value ' // to_text(t) // &
            ' is outside the defined range [' // to_text(a) // ', ' // to_text(b) // &
            '] and the prolongation is EXCLU (use PROL_GAUCHE/PROL_DROITE = ''CONSTANT'' ' // &
            'or ''LINEAIRE'')')
    end subroutine outside

    !> PROL_* code of a PROL_GAUCHE/PROL_DROITE text.
    pure integer function prolongation_code(text)
        character(len=*), intent(in) :: text
        select case (text)
        case ('CONSTANT')
            prolongation_code = PROL_CONSTANT
        case ('LINEAIRE')
            prolongation_code = PROL_LINEAIRE
        case default
            prolongation_code = PROL_EXCLU
        end select
    end function prolongation_code

    function tabulated_summary(self) result(text)
        class(tabulated_function_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (fonction): ' // to_text(size(self%x)) // &
            ' points of ' // self%parameter // ' in [' // to_text(self%x(1)) // ', ' // &
            to_text(self%x(size(self%x))) // ']'
    end function tabulated_summary

end module tabulated_function

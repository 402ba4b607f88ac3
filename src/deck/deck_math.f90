!> Checked real arithmetic and the built-in math functions of the deck language, shared by
!> the deck evaluator and the compiled FORMULE evaluator. Every operation checks its operands
!> BEFORE computing, so no IEEE exception is ever raised (the Debug build traps them):
!> errors come back as a code, turned into a located message by the caller.
module deck_math
    use kinds, only: dp
    implicit none
    private

    integer, parameter, public :: MATH_OK = 0, MATH_DOMAIN = 1, MATH_ZERO_DIVISION = 2, &
        MATH_OVERFLOW = 3

    !> Built-in function ids (names in builtin_names).
    integer, parameter, public :: B_ABS = 1, B_MIN = 2, B_MAX = 3, B_SQRT = 4, B_EXP = 5, &
        B_LOG = 6, B_LOG10 = 7, B_SIN = 8, B_COS = 9, B_TAN = 10, B_ASIN = 11, B_ACOS = 12, &
        B_ATAN = 13, B_ATAN2 = 14, B_SINH = 15, B_COSH = 16, B_TANH = 17, B_FLOOR = 18, &
        B_CEIL = 19, B_INT = 20, B_FLOAT = 21, N_BUILTINS = 21
    character(len=5), parameter :: builtin_names(N_BUILTINS) = [character(len=5) :: 'abs', &
        'min', 'max', 'sqrt', 'exp', 'log', 'log10', 'sin', 'cos', 'tan', 'asin', 'acos', &
        'atan', 'atan2', 'sinh', 'cosh', 'tanh', 'floor', 'ceil', 'int', 'float']
    !> Arity of each built-in (-1: one or more arguments).
    integer, parameter :: builtin_arity(N_BUILTINS) = [1, -1, -1, 1, 1, 1, 1, 1, 1, 1, 1, 1, &
        1, 2, 1, 1, 1, 1, 1, 1, 1]

    real(dp), parameter, public :: PI_VALUE = 3.141592653589793238462643383279502884_dp
    real(dp), parameter, public :: E_VALUE = 2.718281828459045235360287471352662498_dp
    !> Largest argument of exp (and half-width for sinh/cosh) that does not overflow.
    real(dp), parameter :: EXP_LIMIT = 709.78_dp

    public :: builtin_name, literal_out_of_range, builtin_id, builtin_arity_of, math_message, &
        checked_binary, checked_call, &
        checked_pow, same_real

contains

    !> True when the decimal literal `text` (e.g. 1.0E+400) is beyond the largest real.
    !> Decided from its digits, before any conversion: converting it would raise an overflow
    !> exception, which the Debug build traps.
    pure logical function literal_out_of_range(text)
        character(len=*), intent(in) :: text
        integer :: i, e, lead, expo, ios
        logical :: seen_point, nonzero
        literal_out_of_range = .false.
        e = scan(text, 'eE')
        expo = 0
        if (e > 0) then
            if (len(text) - e > 6) then
                literal_out_of_range = verify(text(e + 1:), '+-0') > 0 .and. &
                                       index(text(e + 1:), '-') == 0
                if (literal_out_of_range) literal_out_of_range = mantissa_nonzero(text(1:e - 1))
                return
            end if
            read (text(e + 1:), *, iostat=ios) expo
            if (ios /= 0) return
        else
            e = len(text) + 1
        end if
        ! decimal exponent of the leading nonzero digit
        lead = 0; seen_point = .false.; nonzero = .false.
        do i = 1, e - 1
            if (text(i:i) == '.') then
                seen_point = .true.
            else if (.not. nonzero) then
                if (text(i:i) /= '0') then
                    nonzero = .true.
                    if (.not. seen_point) lead = 1
                    if (seen_point) lead = lead - 1
                else if (seen_point) then
                    lead = lead - 1
                end if
            else if (.not. seen_point) then
                lead = lead + 1
            end if
        end do
        if (.not. nonzero) return
        literal_out_of_range = expo + lead - 1 > 308
        if (expo + lead - 1 == 308) literal_out_of_range = leading_digits(text(1:e - 1)) > &
            huge(1.0_dp) * 1.0e-308_dp
    end function literal_out_of_range

    !> The significant digits of a mantissa as d.ddd (a value in [1, 10)).
    pure real(dp) function leading_digits(text)
        character(len=*), intent(in) :: text
        character(len=40) :: digits, number
        integer :: i, n, ios
        digits = ''
        n = 0
        do i = 1, len(text)
            if (text(i:i) == '.') cycle
            if (n == 0 .and. text(i:i) == '0') cycle
            if (n >= 30) exit
            n = n + 1
            digits(n:n) = text(i:i)
        end do
        leading_digits = 0.0_dp
        if (n == 0) return
        number = digits(1:1) // '.' // digits(2:max(2, n)) // '0'
        read (number, *, iostat=ios) leading_digits
    end function leading_digits

    pure logical function mantissa_nonzero(text)
        character(len=*), intent(in) :: text
        mantissa_nonzero = verify(text, '0.') > 0
    end function mantissa_nonzero

    !> Id of a built-in name ('sqrt' or 'math.sqrt'), 0 if none.
    pure integer function builtin_id(name)
        character(len=*), intent(in) :: name
        integer :: k, start
        builtin_id = 0
        start = 1
        if (len(name) > 5) then
            if (name(1:5) == 'math.') start = 6
        end if
        do k = 1, N_BUILTINS
            if (name(start:) == trim(builtin_names(k))) then
                builtin_id = k
                return
            end if
        end do
    end function builtin_id

    !> Name of built-in `id` (e.g. 'sqrt').
    pure function builtin_name(id) result(name)
        integer, intent(in) :: id
        character(len=:), allocatable :: name
        name = trim(builtin_names(id))
    end function builtin_name

    pure integer function builtin_arity_of(id)
        integer, intent(in) :: id
        builtin_arity_of = builtin_arity(id)
    end function builtin_arity_of

    !> Message for a MATH_* code, naming the operation.
    function math_message(code, what) result(text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: what
        character(len=:), allocatable :: text
        select case (code)
        case (MATH_DOMAIN)
            text = 'math domain error in ' // what
        case (MATH_ZERO_DIVISION)
            text = 'division by zero in ' // what
        case (MATH_OVERFLOW)
            text = 'numerical overflow in ' // what // ' (the result exceeds the ' // &
                   'largest real, about 1.8E+308)'
        case default
            text = 'error in ' // what
        end select
    end function math_message

    !> a OP b for real operands, OP in + - * / // % ; code = MATH_*.
    pure subroutine checked_binary(op, a, b, r, code)
        character(len=*), intent(in) :: op
        real(dp), intent(in) :: a, b
        real(dp), intent(out) :: r
        integer, intent(out) :: code
        code = MATH_OK; r = 0.0_dp
        select case (op)
        case ('+', '-')
            block
                real(dp) :: bb
                bb = b
                if (op == '-') bb = -b
                if (abs(a) > 0.5_dp * huge(a) .or. abs(bb) > 0.5_dp * huge(a)) then
                    if (same_real(sign(1.0_dp, a), sign(1.0_dp, bb)) .and. &
                        abs(a) > huge(a) - abs(bb)) then
                        code = MATH_OVERFLOW; return
                    end if
                end if
                r = a + bb
            end block
        case ('*')
            if (abs(b) > 1.0_dp) then
                if (abs(a) > huge(a) / abs(b)) then
                    code = MATH_OVERFLOW; return
                end if
            end if
            r = a * b
        case ('/', '//', '%')
            if (same_real(b, 0.0_dp)) then
                code = MATH_ZERO_DIVISION; return
            end if
            if (abs(b) < 1.0_dp) then
                if (abs(a) > huge(a) * abs(b)) then
                    code = MATH_OVERFLOW; return
                end if
            end if
            r = a / b
            if (op == '//') r = floor_real(r)
            if (op == '%') r = a - floor_real(r) * b   ! Python: the sign of the divisor
        case default
            code = MATH_DOMAIN
        end select
    end subroutine checked_binary

    !> a ** b with Python's rules: 0**negative is a division by zero, a negative base with a
    !> non-integer exponent is a domain error (Python would give a complex number).
    pure subroutine checked_pow(a, b, r, code)
        real(dp), intent(in) :: a, b
        real(dp), intent(out) :: r
        integer, intent(out) :: code
        integer :: n
        real(dp) :: la
        code = MATH_OK; r = 1.0_dp
        if (same_real(b, 0.0_dp)) return
        if (same_real(a, 0.0_dp)) then
            if (b < 0.0_dp) then
                code = MATH_ZERO_DIVISION
            else
                r = 0.0_dp
            end if
            return
        end if
        if (a < 0.0_dp .and. .not. same_real(b, aint(b))) then
            code = MATH_DOMAIN; return
        end if
        ! |a|**b overflows when b * log|a| > log(huge) (EXP_LIMIT, with a margin for the
        ! rounding of the power); the product itself overflows for b = 1e308 (10.0**1e308),
        ! so the test divides instead: log|a| is 0 or at least ~1e-16 in magnitude, and
        ! EXP_LIMIT / |log|a|| is finite
        la = log(abs(a))
        if ((la > 0.0_dp .and. b > 0.0_dp) .or. (la < 0.0_dp .and. b < 0.0_dp)) then
            if (abs(b) > EXP_LIMIT / abs(la)) then
                code = MATH_OVERFLOW; return
            end if
        end if
        if (same_real(b, aint(b)) .and. abs(b) <= 64.0_dp) then
            n = int(b)
            r = a**n                              ! exact for small integer exponents
        else
            r = abs(a)**b
            if (a < 0.0_dp .and. same_real(mod(abs(b), 2.0_dp), 1.0_dp)) r = -r
        end if
    end subroutine checked_pow

    !> Built-in function `id` of real arguments x(1:n); min/max take any n >= 1.
    pure subroutine checked_call(id, x, n, r, code)
        integer, intent(in) :: id, n
        real(dp), intent(in) :: x(*)
        real(dp), intent(out) :: r
        integer, intent(out) :: code
        code = MATH_OK; r = 0.0_dp
        select case (id)
        case (B_ABS)
            r = abs(x(1))
        case (B_MIN)
            r = minval(x(1:n))
        case (B_MAX)
            r = maxval(x(1:n))
        case (B_SQRT)
            if (x(1) < 0.0_dp) then
                code = MATH_DOMAIN
            else
                r = sqrt(x(1))
            end if
        case (B_EXP)
            if (x(1) > EXP_LIMIT) then
                code = MATH_OVERFLOW
            else
                r = exp(x(1))
            end if
        case (B_LOG, B_LOG10)
            if (x(1) <= 0.0_dp) then
                code = MATH_DOMAIN
            else if (id == B_LOG) then
                r = log(x(1))
            else
                r = log10(x(1))
            end if
        case (B_SIN)
            r = sin(x(1))
        case (B_COS)
            r = cos(x(1))
        case (B_TAN)
            r = tan(x(1))
        case (B_ASIN, B_ACOS)
            if (abs(x(1)) > 1.0_dp) then
                code = MATH_DOMAIN
            else if (id == B_ASIN) then
                r = asin(x(1))
            else
                r = acos(x(1))
            end if
        case (B_ATAN)
            r = atan(x(1))
        case (B_ATAN2)
            if (same_real(x(1), 0.0_dp) .and. same_real(x(2), 0.0_dp)) then
                r = 0.0_dp
            else
                r = atan2(x(1), x(2))
            end if
        case (B_SINH, B_COSH)
            if (abs(x(1)) > EXP_LIMIT) then
                code = MATH_OVERFLOW
            else if (id == B_SINH) then
                r = sinh(x(1))
            else
                r = cosh(x(1))
            end if
        case (B_TANH)
            r = tanh(x(1))
        case (B_FLOOR)
            r = floor_real(x(1))
        case (B_CEIL)
            r = -floor_real(-x(1))
        case (B_INT)
            r = aint(x(1))
        case (B_FLOAT)
            r = x(1)
        case default
            code = MATH_DOMAIN
        end select
    end subroutine checked_call

    !> a == b for reals, spelled so that exact comparison is visibly intended.
    elemental logical function same_real(a, b)
        real(dp), intent(in) :: a, b
        same_real = .not. (a < b .or. a > b)
    end function same_real

    !> floor without converting to an integer kind (which could overflow).
    pure real(dp) function floor_real(x)
        real(dp), intent(in) :: x
        floor_real = aint(x)
        if (floor_real > x) floor_real = floor_real - 1.0_dp
    end function floor_real

end module deck_math

!> Text of numbers and strings as Python writes them (doc/deck-language.md, "Text"):
!> repr/str of reals (the shortest text that reads back to the same real), the format
!> specification mini-language of format() and str.format ([[fill]align][sign][#][0]
!> [width][,|_][.precision][type]), and the conversions of the % operator. Digits are
!> correctly rounded, halves to even, as Python's: they come from the processor's
!> formatted output of the exact binary value. Each procedure returns a message instead of
!> a located status; the interpreter locates it.
module deck_format
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    use kinds, only: dp, i8
    use strings, only: to_text, to_upper
    implicit none
    private

    !> Largest precision accepted in a format (Python allows more; no deck needs it).
    integer, parameter, public :: MAX_PRECISION = 400
    !> Largest width accepted in a format.
    integer, parameter, public :: MAX_WIDTH = 10000

    !> A parsed format specification.
    type, public :: format_spec_t
        character :: fill = ' '
        character :: align = ' '      !< < > ^ = or ' ' (default for the type)
        character :: sign = '-'       !< + - or ' '
        logical :: alternate = .false.
        logical :: zero = .false.
        integer :: width = 0
        character :: grouping = ' '   !< , _ or ' '
        integer :: precision = -1     !< -1: not given
        character :: type = ' '
    end type format_spec_t

    public :: real_repr, int_text, string_repr, parse_spec, format_real, format_int, &
        format_text, pad

contains

    ! ---- reals ------------------------------------------------------------------------------

    !> Python's repr(x) (also str(x)): the shortest decimal text that reads back to x;
    !> fixed notation when 1e-4 <= |x| < 1e16 ('0.1', '1.0', '123456.789'), else
    !> scientific ('1e-05', '1.5e+16'); 'inf', '-inf', 'nan'.
    function real_repr(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=:), allocatable :: digits
        integer :: e10
        if (ieee_is_nan(x)) then
            text = 'nan'; return
        end if
        if (abs(x) > huge(x)) then
            text = merge('-inf', 'inf ', x < 0.0_dp)
            text = trim(text); return
        end if
        call shortest_digits(abs(x), digits, e10)
        if (e10 >= -4 .and. e10 < 16) then
            text = fixed_from_digits(digits, e10, 1)
        else
            text = digits(1:1)
            if (len(digits) > 1) text = text // '.' // digits(2:)
            text = text // 'e' // exponent_text(e10)
        end if
        if (sign(1.0_dp, x) < 0.0_dp) text = '-' // text
    end function real_repr

    !> The shortest digits d1 d2 ... (no trailing zeros) and exponent e10 with
    !> x = d1.d2... * 10**e10 that read back to x (x >= 0 and finite).
    subroutine shortest_digits(x, digits, e10)
        real(dp), intent(in) :: x
        character(len=:), allocatable, intent(out) :: digits
        integer, intent(out) :: e10
        character(len=:), allocatable :: mantissa, number
        real(dp) :: y
        integer :: p, ios
        if (x <= 0.0_dp) then
            digits = '0'; e10 = 0; return
        end if
        do p = 1, 17
            call scientific(x, p - 1, mantissa, e10)
            if (.not. fits(mantissa, e10)) cycle
            number = mantissa // 'E' // to_text(int(e10, i8))
            read (number, *, iostat=ios) y
            if (ios == 0 .and. y >= x .and. y <= x) exit
        end do
        digits = ''
        do p = 1, len(mantissa)
            if (mantissa(p:p) /= '.') digits = digits // mantissa(p:p)
        end do
        p = len(digits)
        do while (p > 1 .and. digits(p:p) == '0')
            p = p - 1
        end do
        digits = digits(1:p)
    contains
        !> True when mantissa * 10**e is not beyond the largest real (reading it back must
        !> not overflow).
        logical function fits(m, e)
            character(len=*), intent(in) :: m
            integer, intent(in) :: e
            fits = e < 308
            if (e == 308) fits = llt(m, '1.7976931348623157') .or. m == '1.7976931348623157'
        end function fits
    end subroutine shortest_digits

    !> x >= 0 in scientific notation with `decimals` digits after the point, correctly
    !> rounded: mantissa 'd.ddd' (no point when decimals = 0) and exponent.
    subroutine scientific(x, decimals, mantissa, e10)
        real(dp), intent(in) :: x
        integer, intent(in) :: decimals
        character(len=:), allocatable, intent(out) :: mantissa
        integer, intent(out) :: e10
        character(len=:), allocatable :: buf
        character(len=40) :: fmt
        integer :: epos, ios
        allocate (character(len=decimals + 16) :: buf)
        write (fmt, '(a,i0,a,i0,a)') '(ES', decimals + 16, '.', decimals, 'E4)'
        write (buf, fmt) x
        buf = adjustl(buf)
        epos = index(buf, 'E')
        mantissa = buf(1:epos - 1)
        read (buf(epos + 1:), *, iostat=ios) e10
        if (decimals == 0 .and. index(mantissa, '.') > 0) &
            mantissa = mantissa(1:index(mantissa, '.') - 1)
    end subroutine scientific

    !> x >= 0 in fixed notation with `decimals` digits after the point (no point when 0),
    !> correctly rounded, with its leading zero ('0.50').
    function fixed(x, decimals) result(text)
        real(dp), intent(in) :: x
        integer, intent(in) :: decimals
        character(len=:), allocatable :: text
        character(len=:), allocatable :: buf
        character(len=40) :: fmt
        integer :: w
        w = 330 + decimals
        allocate (character(len=w) :: buf)
        write (fmt, '(a,i0,a,i0,a)') '(F', w, '.', decimals, ')'
        write (buf, fmt) x
        text = trim(adjustl(buf))
        if (text(1:1) == '.') text = '0' // text
        if (decimals == 0 .and. text(len(text):len(text)) == '.') text = text(1:len(text) - 1)
    end function fixed

    !> Fixed notation from significant digits and exponent (x = d1.d2... * 10**e10), at
    !> least min_decimals digits after the point.
    pure function fixed_from_digits(digits, e10, min_decimals) result(text)
        character(len=*), intent(in) :: digits
        integer, intent(in) :: e10, min_decimals
        character(len=:), allocatable :: text
        character(len=:), allocatable :: int_part, frac
        if (e10 >= 0) then
            if (len(digits) > e10 + 1) then
                int_part = digits(1:e10 + 1)
                frac = digits(e10 + 2:)
            else
                int_part = digits // repeat('0', e10 + 1 - len(digits))
                frac = ''
            end if
        else
            int_part = '0'
            frac = repeat('0', -e10 - 1) // digits
        end if
        if (len(frac) < min_decimals) frac = frac // repeat('0', min_decimals - len(frac))
        text = int_part
        if (len(frac) > 0) text = text // '.' // frac
    end function fixed_from_digits

    !> Python's exponent: sign and at least two digits ('+05', '-300').
    pure function exponent_text(e) result(text)
        integer, intent(in) :: e
        character(len=:), allocatable :: text
        character(len=12) :: buf
        write (buf, '(i0)') abs(e)
        text = trim(buf)
        if (len(text) < 2) text = '0' // text
        if (e < 0) then
            text = '-' // text
        else
            text = '+' // text
        end if
    end function exponent_text

    !> format(x, spec) for a real: types e E f F g G % and '' (repr-like, or g with at
    !> least one decimal when a precision is given); sign, alignment, width, grouping.
    !>  message : out, '' or what is wrong (a type that does not apply to reals)
    subroutine format_real(x, spec, text, message)
        real(dp), intent(in) :: x
        type(format_spec_t), intent(in) :: spec
        character(len=:), allocatable, intent(out) :: text
        character(len=:), allocatable, intent(out) :: message
        character(len=:), allocatable :: body, mantissa
        real(dp) :: a
        integer :: p, e10
        character :: t
        message = ''
        text = ''
        t = spec%type
        if (ieee_is_nan(x) .or. abs(x) > huge(x)) then
            body = real_repr(abs(x))
            if (ieee_is_nan(x)) body = 'nan'
            if (index('EFG', t) > 0 .and. t /= ' ') body = to_upper(body)
        else
            a = abs(x)
            p = spec%precision
            select case (t)
            case ('f', 'F', '%')
                if (p < 0) p = 6
                ! Python forms x*100 in floating point: past huge/100 it is inf ('inf%').
                if (t == '%' .and. a > huge(a) / 100.0_dp) then
                    body = 'inf%'
                    call finish_number(body, sign(1.0_dp, x) < 0.0_dp, spec, text)
                    return
                end if
                if (t == '%') a = a * 100.0_dp
                body = fixed(a, p)
                if (spec%alternate .and. p == 0) body = body // '.'
                if (t == '%') body = body // '%'
            case ('e', 'E')
                if (p < 0) p = 6
                call scientific(a, p, mantissa, e10)
                if (spec%alternate .and. p == 0) mantissa = mantissa // '.'
                body = mantissa // 'e' // exponent_text(e10)
                if (t == 'E') body = to_upper(body)
            case ('g', 'G', 'n')
                body = general(a, p, spec%alternate, .false.)
                if (t == 'G') body = to_upper(body)
            case (' ')
                if (p < 0) then
                    body = real_repr(a)
                else
                    body = general(a, p, spec%alternate, .true.)
                end if
            case default
                message = 'format code ''' // t // ''' does not apply to a real'
                return
            end select
        end if
        call finish_number(body, sign(1.0_dp, x) < 0.0_dp .and. .not. ieee_is_nan(x), spec, text)
    end subroutine format_real

    !> Python's 'g': precision p significant digits (6 when not given, 1 for 0); fixed when
    !> -4 <= exponent < p, else scientific; trailing zeros removed unless alternate.
    !> keep_point: the '' type with a precision, whose fixed form keeps one decimal.
    function general(a, precision, alternate, keep_point) result(body)
        real(dp), intent(in) :: a
        integer, intent(in) :: precision
        logical, intent(in) :: alternate, keep_point
        character(len=:), allocatable :: body
        character(len=:), allocatable :: mantissa
        integer :: p, e10
        p = precision
        if (p < 0) p = 6
        if (p == 0) p = 1
        call scientific(a, p - 1, mantissa, e10)
        if (e10 >= -4 .and. e10 < p) then
            body = fixed(a, p - 1 - e10)
            if (.not. alternate) body = strip_zeros(body, keep_point)
        else
            if (.not. alternate) mantissa = strip_zeros(mantissa, .false.)
            body = mantissa // 'e' // exponent_text(e10)
        end if
    end function general

    !> '1.500' -> '1.5', '2.000' -> '2' (or '2.0' with keep_point); no point: unchanged.
    pure function strip_zeros(number, keep_point) result(text)
        character(len=*), intent(in) :: number
        logical, intent(in) :: keep_point
        character(len=:), allocatable :: text
        integer :: k
        text = number
        if (index(number, '.') == 0) then
            if (keep_point) text = number // '.0'
            return
        end if
        k = len(number)
        do while (number(k:k) == '0')
            k = k - 1
        end do
        if (number(k:k) == '.') then
            if (keep_point) then
                k = k + 1
            else
                k = k - 1
            end if
        end if
        text = number(1:k)
    end function strip_zeros

    ! ---- integers ---------------------------------------------------------------------------

    pure function int_text(i) result(text)
        integer(i8), intent(in) :: i
        character(len=:), allocatable :: text
        character(len=24) :: buf
        write (buf, '(i0)') i
        text = trim(buf)
    end function int_text

    !> format(i, spec) for an integer: types d n b o x X c and '' (as d); the real types
    !> format it as a real.
    subroutine format_int(i, spec, text, message)
        integer(i8), intent(in) :: i
        type(format_spec_t), intent(in) :: spec
        character(len=:), allocatable, intent(out) :: text
        character(len=:), allocatable, intent(out) :: message
        character(len=:), allocatable :: body
        integer(i8) :: a
        message = ''
        select case (spec%type)
        case ('e', 'E', 'f', 'F', 'g', 'G', '%')
            call format_real(real(i, dp), spec, text, message)
            return
        case ('d', 'n', ' ')
            if (spec%precision >= 0) then
                message = 'precision not allowed in an integer format'
                return
            end if
            body = int_text(abs(i))
            if (i == -huge(i) - 1) body = '9223372036854775808'
        case ('b', 'o', 'x', 'X')
            a = abs(i)
            body = in_base(a, spec%type)
            if (spec%alternate) body = '0' // spec%type // body
        case ('c')
            if (i < 0 .or. i > 127) then
                message = '%c needs a character code 0..127'
                return
            end if
            text = pad(achar(int(i)), spec, '<')
            return
        case default
            message = 'format code ''' // spec%type // ''' does not apply to an integer'
            return
        end select
        call finish_number(body, i < 0, spec, text)
    end subroutine format_int

    pure function in_base(a, code) result(text)
        integer(i8), intent(in) :: a
        character, intent(in) :: code
        character(len=:), allocatable :: text
        character(len=16), parameter :: DIGITS = '0123456789abcdef'
        integer(i8) :: b, r
        b = 16
        if (code == 'b') b = 2
        if (code == 'o') b = 8
        text = ''
        r = a
        do
            text = DIGITS(int(mod(r, b)) + 1:int(mod(r, b)) + 1) // text
            r = r / b
            if (r == 0) exit
        end do
        if (code == 'X') text = to_upper(text)
    end function in_base

    !> Sign, grouping, zero padding and alignment of a number's digits.
    subroutine finish_number(body, negative, spec, text)
        character(len=*), intent(in) :: body
        logical, intent(in) :: negative
        type(format_spec_t), intent(in) :: spec
        character(len=:), allocatable, intent(out) :: text
        character(len=:), allocatable :: sgn, digits
        type(format_spec_t) :: s
        integer :: fill_count
        digits = body
        if (spec%grouping /= ' ') digits = group_digits(digits, spec%grouping)
        sgn = ''
        if (negative) then
            sgn = '-'
        else if (spec%sign == '+') then
            sgn = '+'
        else if (spec%sign == ' ') then
            sgn = ' '
        end if
        s = spec
        if (s%zero .and. s%align == ' ') then
            s%align = '='; s%fill = '0'
        end if
        if (s%align == '=') then
            fill_count = max(0, s%width - len(sgn) - len(digits))
            text = sgn // repeat(s%fill, fill_count) // digits
        else
            text = pad(sgn // digits, s, '>')
        end if
    end subroutine finish_number

    !> '1234567.5' -> '1,234,567.5' (the integer part only).
    pure function group_digits(body, sep) result(text)
        character(len=*), intent(in) :: body
        character, intent(in) :: sep
        character(len=:), allocatable :: text
        integer :: end_int, k, count
        end_int = scan(body, '.e%') - 1
        if (end_int < 0) end_int = len(body)
        text = body(end_int + 1:)
        count = 0
        do k = end_int, 1, -1
            if (count == 3) then
                text = sep // text
                count = 0
            end if
            text = body(k:k) // text
            count = count + 1
        end do
    end function group_digits

    ! ---- text -------------------------------------------------------------------------------

    !> format(s, spec) for a string: type s or ''; precision cuts it; default alignment left.
    subroutine format_text(s, spec, text, message)
        character(len=*), intent(in) :: s
        type(format_spec_t), intent(in) :: spec
        character(len=:), allocatable, intent(out) :: text
        character(len=:), allocatable, intent(out) :: message
        message = ''
        if (spec%type /= ' ' .and. spec%type /= 's') then
            message = 'format code ''' // spec%type // ''' does not apply to a string'
            return
        end if
        if (spec%sign /= '-' .or. spec%align == '=' .or. spec%grouping /= ' ') then
            message = 'sign, "=" alignment and grouping do not apply to a string'
            return
        end if
        if (spec%precision >= 0 .and. spec%precision < len(s)) then
            text = pad(s(1:spec%precision), spec, '<')
        else
            text = pad(s, spec, '<')
        end if
    end subroutine format_text

    !> text padded to spec%width with spec%fill, aligned by spec%align (default_align when
    !> none is given).
    pure function pad(text, spec, default_align) result(out)
        character(len=*), intent(in) :: text
        type(format_spec_t), intent(in) :: spec
        character, intent(in) :: default_align
        character(len=:), allocatable :: out
        integer :: extra, left
        character :: a
        extra = max(0, spec%width - len(text))
        a = spec%align
        if (a == ' ' .or. a == '=') a = default_align
        select case (a)
        case ('<')
            out = text // repeat(spec%fill, extra)
        case ('^')
            left = extra / 2
            out = repeat(spec%fill, left) // text // repeat(spec%fill, extra - left)
        case default
            out = repeat(spec%fill, extra) // text
        end select
    end function pad

    !> Python's repr of a string: single quotes unless it holds a single quote and no
    !> double quote; backslash, quote, and control characters escaped.
    pure function string_repr(s) result(text)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: text
        character :: q
        integer :: k, c
        q = "'"
        if (index(s, "'") > 0 .and. index(s, '"') == 0) q = '"'
        text = q
        do k = 1, len(s)
            c = iachar(s(k:k))
            if (s(k:k) == q .or. s(k:k) == '\') then
                text = text // '\' // s(k:k)
            else if (c == 10) then
                text = text // '\n'
            else if (c == 9) then
                text = text // '\t'
            else if (c == 13) then
                text = text // '\r'
            else if (c < 32 .or. c == 127) then
                text = text // '\x' // hex_digit(c / 16) // hex_digit(mod(c, 16))
            else
                text = text // s(k:k)
            end if
        end do
        text = text // q
    end function string_repr

    pure function hex_digit(d) result(c)
        integer, intent(in) :: d
        character :: c
        character(len=16), parameter :: DIGITS = '0123456789abcdef'
        c = DIGITS(d + 1:d + 1)
    end function hex_digit

    !> Parses a format specification [[fill]align][sign][#][0][width][,|_][.precision][type].
    !>  message : out, '' or what is wrong in it
    subroutine parse_spec(text, spec, message)
        character(len=*), intent(in) :: text
        type(format_spec_t), intent(out) :: spec
        character(len=:), allocatable, intent(out) :: message
        integer :: k, n, start
        message = ''
        n = len(text); k = 1
        if (n >= 2) then
            if (index('<>^=', text(2:2)) > 0) then
                spec%fill = text(1:1); spec%align = text(2:2); k = 3
            end if
        end if
        if (k == 1 .and. n >= 1) then
            if (index('<>^=', text(1:1)) > 0) then
                spec%align = text(1:1); k = 2
            end if
        end if
        if (k <= n) then
            if (index('+- ', text(k:k)) > 0) then
                spec%sign = text(k:k); k = k + 1
            end if
        end if
        if (k <= n) then
            if (text(k:k) == '#') then
                spec%alternate = .true.; k = k + 1
            end if
        end if
        if (k <= n) then
            if (text(k:k) == '0') then
                spec%zero = .true.; k = k + 1
            end if
        end if
        start = k
        do while (k <= n)
            if (index('0123456789', text(k:k)) == 0) exit
            k = k + 1
        end do
        if (k > start) then
            if (k - start > 5) then
                message = 'format width too large'; return
            end if
            read (text(start:k - 1), *) spec%width
            if (spec%width > MAX_WIDTH) then
                message = 'format width above ' // to_text(MAX_WIDTH); return
            end if
        end if
        if (k <= n) then
            if (text(k:k) == ',' .or. text(k:k) == '_') then
                spec%grouping = text(k:k); k = k + 1
            end if
        end if
        if (k <= n) then
            if (text(k:k) == '.') then
                k = k + 1; start = k
                do while (k <= n)
                    if (index('0123456789', text(k:k)) == 0) exit
                    k = k + 1
                end do
                if (k == start) then
                    message = 'format precision missing after "."'; return
                end if
                if (k - start > 5) then
                    message = 'format precision too large'; return
                end if
                read (text(start:k - 1), *) spec%precision
                if (spec%precision > MAX_PRECISION) then
                    message = 'format precision above ' // to_text(MAX_PRECISION); return
                end if
            end if
        end if
        if (k <= n) then
            spec%type = text(k:k); k = k + 1
            if (index('bcdeEfFgGnosxX%', spec%type) == 0) then
                message = 'unknown format code ''' // spec%type // ''''; return
            end if
        end if
        if (k <= n) message = 'invalid format specifier ''' // text // ''''
    end subroutine parse_spec

end module deck_format

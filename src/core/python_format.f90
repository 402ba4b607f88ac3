!> Numbers spelled as Python spells them, where parasol reproduces text Code_Aster's Python
!> layer writes:
!>  - float_repr: `str(value)` (the filters IMPR_TABLE traces in a table's title): the
!>    shortest decimal that reads back to the same double, in fixed notation for decimal
!>    exponents -4 to 15 ('0.0001', '2.5', '1000000000000000.0') and scientific notation
!>    otherwise ('1e-05', '1.5e+16');
!>  - format_real: printf's '%<width>.<digits>E|F|G' (tables and functions printed with
!>    FORMAT_R, a Fortran format Code_Aster translates with fmtF2PY: E12.5 is %12.5E, one
!>    digit before the point, unlike Fortran's own E12.5).
module python_format
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use kinds, only: dp, i8
    use strings, only: to_upper
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    implicit none
    private

    !> A real format in Python's printf terms: '%<width>.<digits><kind>' after `lead`
    !> blanks (Fortran's nP becomes n blanks, as Code_Aster's fmtF2PY does).
    type, public :: real_format_t
        integer :: lead = 0
        integer :: width = 12
        integer :: digits = 5
        character :: kind = 'E'            !< E, F or G
    end type real_format_t

    !> Code_Aster's default real format of tables and functions (FORMAT_R).
    character(len=*), parameter, public :: DEFAULT_REAL_FORMAT = 'E12.5'

    public :: float_repr, parse_real_format, format_real, format_real_column

contains

    !> repr(x) of a Python float.
    function float_repr(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=40) :: buf
        character(len=16) :: edit
        character(len=:), allocatable :: digits, minus
        real(dp) :: back
        integer :: p, k, e, ios
        if (ieee_is_nan(x)) then
            text = 'nan'
            return
        else if (.not. ieee_is_finite(x)) then
            text = merge('inf ', '-inf', x > 0.0_dp)
            text = trim(text)
            return
        end if
        minus = ''
        if (sign(1.0_dp, x) < 0.0_dp) minus = '-'             ! -0.0 too
        if (.not. abs(x) > 0.0_dp) then
            text = minus // '0.0'
            return
        end if
        ! the fewest significant digits that read back to x
        do p = 1, 17
            write (edit, '(a,i0,a,i0,a)') '(es', p + 10, '.', p - 1, 'e3)'
            write (buf, edit) abs(x)
            read (buf, *, iostat=ios) back
            if (ios == 0 .and. .not. (back < abs(x) .or. back > abs(x))) exit
        end do
        buf = adjustl(buf)
        k = index(buf, 'E')
        read (buf(k + 1:), *) e
        digits = buf(1:1)
        if (k > 3) digits = digits // buf(3:k - 1)
        do while (len(digits) > 1)                   ! drop trailing zeros
            if (digits(len(digits):len(digits)) /= '0') exit
            digits = digits(1:len(digits) - 1)
        end do
        if (e >= -4 .and. e < 16) then
            if (e >= 0) then
                if (len(digits) <= e + 1) then
                    text = digits // repeat('0', e + 1 - len(digits)) // '.0'
                else
                    text = digits(1:e + 1) // '.' // digits(e + 2:)
                end if
            else
                text = '0.' // repeat('0', -e - 1) // digits
            end if
        else
            text = digits(1:1)
            if (len(digits) > 1) text = text // '.' // digits(2:)
            write (buf, '(i0)') abs(e)
            if (abs(e) < 10) buf = '0' // trim(buf)
            text = text // 'e' // merge('+', '-', e >= 0) // trim(buf)
        end if
        text = minus // text
    end function float_repr
    !> Reads a Fortran real format as Code_Aster's fmtF2PY does: an optional `nP` (n
    !> blanks), then E, D, F or G with width.digits (D is E).
    !>  st : STATUS_MODEL_ERROR when the text holds no such edit descriptor
    subroutine parse_real_format(text, fmt, st)
        character(len=*), intent(in) :: text
        type(real_format_t), intent(out) :: fmt
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: t
        integer :: k, p, dot, ios, w, d
        t = to_upper(trim(adjustl(text)))
        fmt%lead = 0
        p = index(t, 'P')
        if (p > 1) then
            read (t(1:p - 1), *, iostat=ios) fmt%lead
            if (ios /= 0 .or. fmt%lead < 0 .or. fmt%lead > 20) fmt%lead = 0
            t = t(p + 1:)
        end if
        k = scan(t, 'EDFG')
        dot = index(t, '.')
        if (k == 0 .or. dot <= k + 1 .or. dot == len(t)) then
            call bad()
            return
        end if
        read (t(k + 1:dot - 1), *, iostat=ios) w
        if (ios == 0) read (t(dot + 1:), *, iostat=ios) d
        if (ios /= 0 .or. verify(t(k + 1:), '0123456789.') /= 0 .or. w < 1 .or. w > 60 .or. &
            d < 0 .or. d > 30) then
            call bad()
            return
        end if
        fmt%width = w
        fmt%digits = d
        fmt%kind = t(k:k)
        if (fmt%kind == 'D') fmt%kind = 'E'
    contains
        subroutine bad()
            call set_error(st, STATUS_MODEL_ERROR, 'FORMAT_R=''' // trim(text) // ''' is ' // &
                'not a real format such as E12.5, 1PE13.6, F10.3 or G14.7 (width 1 to 60, ' // &
                'digits 0 to 30)')
        end subroutine bad
    end subroutine parse_real_format

    !> `x` as Python's '%<width>.<digits><kind>' after `lead` blanks: E with one digit
    !> before the point and an exponent of at least two digits, F fixed, G the shorter
    !> (Python's %G: trailing zeros dropped).
    function format_real(fmt, x) result(text)
        type(real_format_t), intent(in) :: fmt
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        select case (fmt%kind)
        case ('F')
            text = fixed_text(x, fmt%digits)
        case ('G')
            text = general_text(x, max(fmt%digits, 1))
        case default
            text = exponent_text(x, fmt%digits)
        end select
        if (len(text) < fmt%width) text = repeat(' ', fmt%width - len(text)) // text
        text = repeat(' ', fmt%lead) // text
    end function format_real

    !> format_real of every value of `x` (what IMPR_TABLE writes a column with).
    !>  texts   : out, each value's text, left-aligned (at least as long as the longest)
    !>  lengths : out, the length of each text
    subroutine format_real_column(fmt, x, texts, lengths)
        type(real_format_t), intent(in) :: fmt
        real(dp), intent(in) :: x(:)
        character(len=*), intent(out) :: texts(:)
        integer, intent(out) :: lengths(:)
        character(len=:), allocatable :: text
        character(len=32) :: digits
        integer :: i, n, a
        logical :: quick
        do i = 1, size(x)
            quick = .false.
            if (fmt%kind == 'E') quick = quick_exponent(x(i), fmt%digits, digits, n)
            if (quick) then
                a = fmt%lead + max(fmt%width - n, 0)       ! blanks before the digits
                texts(i) = repeat(' ', a) // digits(1:n)
                lengths(i) = a + n
            else
                text = format_real(fmt, x(i))
                texts(i) = text
                lengths(i) = len(text)
            end if
        end do
    end subroutine format_real_column

    !> Python's %.<digits>E of x without the run-time library's formatted write (ten times
    !> faster), for up to 6 digits and exponents within +-290: the mantissa rounded from x
    !> scaled by a power of ten in double precision, whose error is below 1e-7 there, so
    !> that it is the correctly rounded one unless the scaled value lies within 1e-5 of a
    !> rounding boundary (a tie, or a power of ten); then, and outside that range, false
    !> (the caller writes the value the slow way).
    !>  text, n : the text is text(1:n)
    logical function quick_exponent(x, digits, text, n) result(ok)
        real(dp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=*), intent(out) :: text
        integer, intent(out) :: n
        real(dp), parameter :: MARGIN = 1.0e-5_dp
        character(len=*), parameter :: DIGIT_CHARS = '0123456789'
        real(dp) :: a, scaled, low, high, frac
        integer(i8) :: m
        integer :: e, k
        character(len=20) :: mantissa
        ok = .false.
        text = ''
        n = 0
        if (digits < 0 .or. digits > 6 .or. .not. ieee_is_finite(x)) return
        a = abs(x)
        mantissa = repeat('0', digits + 1)
        e = 0
        if (a > 0.0_dp) then
            if (a < 1.0e-290_dp .or. a > 1.0e290_dp) return
            e = floor(log10(a))
            low = 10.0_dp**digits                          ! exact: digits <= 6
            high = 10.0_dp * low
            scaled = scale_by_ten(a, digits - e)
            if (scaled < low) then
                e = e - 1
                scaled = scale_by_ten(a, digits - e)
            else if (scaled >= high) then
                e = e + 1
                scaled = scale_by_ten(a, digits - e)
            end if
            if (abs(scaled - low) < MARGIN .or. abs(scaled - high) < MARGIN) return
            frac = scaled - aint(scaled)
            if (abs(frac - 0.5_dp) < MARGIN) return       ! near a tie
            m = nint(scaled, i8)
            if (real(m, dp) >= high) then                 ! 9.999996 -> 1.00000E+01
                m = m / 10
                e = e + 1
            end if
            do k = digits + 1, 1, -1                      ! the digits + 1 digits of m
                mantissa(k:k) = DIGIT_CHARS(mod(m, 10_i8) + 1:mod(m, 10_i8) + 1)
                m = m / 10
            end do
        end if
        if (sign(1.0_dp, x) < 0.0_dp) call put('-')
        call put(mantissa(1:1))
        if (digits > 0) then
            call put('.')
            call put(mantissa(2:digits + 1))
        end if
        call put('E')
        call put(merge('-', '+', e < 0))
        k = abs(e)
        if (k >= 100) call put(DIGIT_CHARS(k / 100 + 1:k / 100 + 1))
        call put(DIGIT_CHARS(mod(k / 10, 10) + 1:mod(k / 10, 10) + 1))
        call put(DIGIT_CHARS(mod(k, 10) + 1:mod(k, 10) + 1))
        ok = .true.
    contains
        subroutine put(piece)
            character(len=*), intent(in) :: piece
            text(n + 1:n + len(piece)) = piece
            n = n + len(piece)
        end subroutine put
    end function quick_exponent

    !> a 10**k, the power formed as exactly as double precision allows (exact to 10**22).
    pure real(dp) function scale_by_ten(a, k) result(r)
        real(dp), intent(in) :: a
        integer, intent(in) :: k
        if (k >= 0) then
            if (k <= 22) then
                r = a * 10.0_dp**k
            else
                r = (a * 1.0e22_dp) * 10.0_dp**(k - 22)
            end if
        else
            if (-k <= 22) then
                r = a / 10.0_dp**(-k)
            else
                r = (a / 1.0e22_dp) / 10.0_dp**(-k - 22)
            end if
        end if
    end function scale_by_ten


    !> d.ddddE+XX with `digits` decimals (Python %E).
    function exponent_text(x, digits) result(text)
        real(dp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=:), allocatable :: text
        character(len=64) :: buf
        character(len=16) :: edit
        integer :: k
        if (.not. ieee_is_finite(x)) then
            text = non_finite(x)
            return
        end if
        if (digits == 0) then
            write (edit, '(a,i0,a)') '(es', 10, '.0e3)'
        else
            write (edit, '(a,i0,a,i0,a)') '(es', digits + 10, '.', digits, 'e3)'
        end if
        write (buf, edit) x
        text = trim(adjustl(buf))
        ! es.0 writes "1.E+003": Python writes "1E+03"
        k = index(text, '.E')
        if (k > 0) text = text(1:k - 1) // text(k + 1:)
        k = index(text, 'E', back=.true.)
        if (text(k + 2:k + 2) == '0') text = text(1:k + 1) // text(k + 3:)   ! E+003 -> E+03
    end function exponent_text

    !> Fixed notation with `digits` decimals (Python %F).
    function fixed_text(x, digits) result(text)
        real(dp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=:), allocatable :: text
        character(len=400) :: buf
        character(len=16) :: edit
        if (.not. ieee_is_finite(x)) then
            text = non_finite(x)
            return
        end if
        write (edit, '(a,i0,a)') '(f400.', digits, ')'
        write (buf, edit) x
        text = trim(adjustl(buf))
        if (text(1:1) == '.') text = '0' // text                     ! .5 -> 0.5
        if (len(text) > 1) then
            if (text(1:2) == '-.') text = '-0' // text(2:)
        end if
        if (text(len(text):len(text)) == '.') text = text(1:len(text) - 1)   ! digits = 0
    end function fixed_text

    !> Python's %G with `digits` significant digits.
    function general_text(x, digits) result(text)
        real(dp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=:), allocatable :: text
        integer :: k, e, point
        if (.not. ieee_is_finite(x)) then
            text = non_finite(x)
            return
        end if
        text = exponent_text(x, digits - 1)           ! rounded to `digits` digits
        k = index(text, 'E', back=.true.)
        read (text(k + 1:), *) e
        if (e >= -4 .and. e < digits) then
            text = fixed_text(x, digits - 1 - e)
            point = index(text, '.')
            if (point > 0) then
                text = strip_zeros(text)
            end if
        else
            text = strip_zeros(text(1:k - 1)) // text(k:)
        end if
    end function general_text

    !> Drops trailing zeros after a decimal point, and the point when nothing follows.
    pure function strip_zeros(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        integer :: n
        out = text
        if (index(out, '.') == 0) return
        n = len(out)
        do while (n > 0)
            if (out(n:n) /= '0') exit
            n = n - 1
        end do
        if (out(n:n) == '.') n = n - 1
        out = out(1:n)
    end function strip_zeros

    pure function non_finite(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        if (x > 0.0_dp) then
            text = 'INF'
        else if (x < 0.0_dp) then
            text = '-INF'
        else
            text = 'NAN'
        end if
    end function non_finite

end module python_format

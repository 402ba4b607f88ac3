!> Small string utilities shared by every layer.
module strings
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    use kinds, only: dp, i4, i8
    implicit none
    private

    !> A variable-length string, for arrays of names.
    type, public :: string_t
        character(len=:), allocatable :: s
    end type string_t

    !> Text form of a number: integers as `i0`, reals in the listing format (E, 13 digits).
    interface to_text
        module procedure int4_to_text, int8_to_text, real_to_text
    end interface to_text

    public :: to_upper, to_lower, to_text, real_e13, real_short, starts_with, ends_with, &
        join_words

contains

    !> Upper-case copy of ASCII letters (other bytes, e.g. UTF-8, are kept).
    pure function to_upper(text) result(up)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: up
        integer :: i, c
        up = text
        do i = 1, len(text)
            c = iachar(text(i:i))
            if (c >= iachar('a') .and. c <= iachar('z')) up(i:i) = achar(c - 32)
        end do
    end function to_upper

    !> Lower-case copy of ASCII letters.
    pure function to_lower(text) result(low)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: low
        integer :: i, c
        low = text
        do i = 1, len(text)
            c = iachar(text(i:i))
            if (c >= iachar('A') .and. c <= iachar('Z')) low(i:i) = achar(c + 32)
        end do
    end function to_lower

    pure function int4_to_text(value) result(text)
        integer(i4), intent(in) :: value
        character(len=:), allocatable :: text
        character(len=12) :: buf
        write (buf, '(i0)') value
        text = trim(buf)
    end function int4_to_text

    pure function int8_to_text(value) result(text)
        integer(i8), intent(in) :: value
        character(len=:), allocatable :: text
        character(len=21) :: buf
        write (buf, '(i0)') value
        text = trim(buf)
    end function int8_to_text

    pure function real_to_text(value) result(text)
        real(dp), intent(in) :: value
        character(len=:), allocatable :: text
        text = real_e13(value)
    end function real_to_text

    !> A real in the listing format of listings.md: E format with 13 significant digits,
    !> e.g. `-3.532908704883E-03`. Non-finite values are spelled `NaN`, `+Inf`, `-Inf` (a
    !> listing must never contain them; callers check before writing).
    pure function real_e13(value) result(text)
        real(dp), intent(in) :: value
        character(len=:), allocatable :: text
        character(len=32) :: buf
        if (ieee_is_nan(value)) then
            text = 'NaN'
        else if (value > huge(value)) then
            text = '+Inf'
        else if (value < -huge(value)) then
            text = '-Inf'
        else
            write (buf, '(es20.12e3)') value
            text = trim(adjustl(buf))
            text = shorten_exponent(text)
        end if
    end function real_e13

    !> A real with 3 significant digits (tables, ratios), e.g. `3.31E-09`.
    pure function real_short(value) result(text)
        real(dp), intent(in) :: value
        character(len=:), allocatable :: text
        character(len=32) :: buf
        if (ieee_is_nan(value)) then
            text = 'NaN'
        else
            write (buf, '(es10.2e3)') value
            text = shorten_exponent(trim(adjustl(buf)))
        end if
    end function real_short

    !> Drops a leading zero of a three-digit exponent (E-003 -> E-03) unless it is needed.
    pure function shorten_exponent(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        integer :: k
        k = index(text, 'E', back=.true.)
        out = text
        if (k == 0 .or. k + 4 > len(text)) return
        if (text(k + 2:k + 2) == '0') out = text(1:k + 1) // text(k + 3:)
    end function shorten_exponent

    !> True when `text` begins with `prefix`.
    pure logical function starts_with(text, prefix)
        character(len=*), intent(in) :: text, prefix
        starts_with = .false.
        if (len(prefix) > len(text)) return
        starts_with = text(1:len(prefix)) == prefix
    end function starts_with

    !> True when `text` ends with `suffix`.
    pure logical function ends_with(text, suffix)
        character(len=*), intent(in) :: text, suffix
        ends_with = .false.
        if (len(suffix) > len(text)) return
        ends_with = text(len(text) - len(suffix) + 1:) == suffix
    end function ends_with

    !> The words joined by `separator` (e.g. ', ').
    pure function join_words(words, separator) result(text)
        type(string_t), intent(in) :: words(:)
        character(len=*), intent(in) :: separator
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(words)
            if (k > 1) text = text // separator
            text = text // words(k)%s
        end do
    end function join_words

end module strings

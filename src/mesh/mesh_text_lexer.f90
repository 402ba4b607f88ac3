!> Line-aware tokenizer for the text mesh formats (.mail, Gmsh ASCII).
!>
!> The whole file is read at once with stream access into one buffer (no record I/O, no
!> list-directed reads), then scanned by hand: tokens are separated by blanks, tabs, commas
!> and CR (so CRLF files read as LF files); `%` starts a comment to the end of the line when
!> the format allows it. Lines may have any length.
module mesh_text_lexer
    use kinds, only: dp, i4, i8
    use system_error, only: readable_errno, errno_text
    use status, only: status_t, set_error, STATUS_IO_ERROR, STATUS_MESH_ERROR
    implicit none
    private

    !> Scanner state over a file read into memory.
    type, public :: text_lexer_t
        character(len=:), allocatable :: text    !< file contents
        character(len=:), allocatable :: file    !< file name (messages)
        integer(i4) :: pos = 1                   !< next character to scan
        integer(i4) :: line = 1                  !< line of `pos`
        logical :: percent_comments = .true.     !< '%' starts a comment (.mail)
    end type text_lexer_t

    public :: open_lexer, next_token, next_line, at_end, parse_real, parse_integer, bytes_left

contains

    !> Reads `path` into `lex`. Errors: STATUS_IO_ERROR if the file cannot be read.
    subroutine open_lexer(lex, path, st)
        type(text_lexer_t), intent(out) :: lex
        character(len=*), intent(in) :: path
        type(status_t), intent(inout) :: st
        integer :: unit, ios, code
        integer(i8) :: nbytes
        character(len=256) :: msg
        lex%file = path
        ! the system's reason, once (the Fortran message would repeat the path)
        code = readable_errno(path)
        if (code /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot open mesh file ' // path // ': ' // &
                           errno_text(code))
            return
        end if
        open (newunit=unit, file=path, access='stream', form='unformatted', status='old', &
              action='read', iostat=ios)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot open mesh file ' // path)
            return
        end if
        inquire (unit=unit, size=nbytes)
        if (nbytes > int(huge(1_i4), i8)) then
            close (unit)
            call set_error(st, STATUS_MESH_ERROR, 'mesh file ' // path // ' has more than ' // &
                '2**31 - 1 bytes: text meshes are read up to 2 GiB (write it as MED)')
            return
        end if
        allocate (character(len=max(nbytes, 0_i8)) :: lex%text, stat=ios)
        if (ios /= 0) then
            close (unit)
            call set_error(st, STATUS_IO_ERROR, 'mesh file ' // path // ': not enough ' // &
                'memory to read its bytes')
            return
        end if
        if (nbytes > 0) read (unit, iostat=ios, iomsg=msg) lex%text
        close (unit)
        if (ios /= 0) call set_error(st, STATUS_IO_ERROR, 'cannot read mesh file ' // path &
                                     // ': ' // trim(msg))
    end subroutine open_lexer

    !> Bytes not yet scanned: what a count read from the file can still describe (a count
    !> of items of at least k bytes each is at most bytes_left / k).
    integer(i8) function bytes_left(lex)
        type(text_lexer_t), intent(in) :: lex
        bytes_left = max(0_i8, int(len(lex%text), i8) - int(lex%pos, i8) + 1_i8)
    end function bytes_left

    !> True when the whole text has been consumed.
    logical function at_end(lex)
        type(text_lexer_t), intent(in) :: lex
        at_end = lex%pos > len(lex%text)
    end function at_end

    !> Next token on the current line: `first`..`last` in lex%text; first = 0 when the line
    !> (or the text) has no more tokens. Does not move to the next line.
    subroutine next_token(lex, first, last)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: first, last
        integer(i4) :: p, n
        character :: c
        n = len(lex%text)
        p = lex%pos
        first = 0
        last = -1
        do while (p <= n)
            c = lex%text(p:p)
            if (c == ' ' .or. c == ',' .or. c == achar(9) .or. c == achar(13)) then
                p = p + 1
            else if (c == '%' .and. lex%percent_comments) then
                do while (p <= n)
                    if (lex%text(p:p) == achar(10)) exit
                    p = p + 1
                end do
            else
                exit
            end if
        end do
        if (p > n) then
            lex%pos = p
            return
        end if
        if (lex%text(p:p) == achar(10)) then
            lex%pos = p
            return
        end if
        first = p
        do while (p <= n)
            c = lex%text(p:p)
            if (c == ' ' .or. c == ',' .or. c == achar(9) .or. c == achar(13) &
                .or. c == achar(10)) exit
            if (c == '%' .and. lex%percent_comments) exit
            p = p + 1
        end do
        last = p - 1
        lex%pos = p
    end subroutine next_token

    !> Skips what is left of the current line and moves to the start of the next one.
    subroutine next_line(lex)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4) :: k
        if (lex%pos > len(lex%text)) return
        k = index(lex%text(lex%pos:), achar(10))
        if (k == 0) then
            lex%pos = len(lex%text) + 1
        else
            lex%pos = lex%pos + k
            lex%line = lex%line + 1
        end if
    end subroutine next_line

    !> Value of a Fortran or C real literal (`1`, `1.`, `.5`, `1.0D+0`, `-1.5E-3`, `2e4`).
    !> Fast path: up to 18 digits and |exponent| <= 22 use one exact division/multiply by
    !> a power of ten (correctly rounded below 2**53); other forms are read from a short
    !> normalized text (18 significant digits and the decimal exponent) once the decimal
    !> exponent is known to be inside the double range, so no read can overflow (a read of
    !> 1e309 traps in the checked build and gives Infinity in the other).
    !>  token : in, the text;  value : out, the number (0 when not ok)
    !>  ok : out, .false. if `token` is not a number or is out of range
    !>  out_of_range : out, optional, .true. when `token` is a number whose magnitude is
    !>                 1e308 or more (beyond double precision, or at its very edge); numbers
    !>                 below 1e-330 in magnitude read as a signed zero, as strtod gives
    subroutine parse_real(token, value, ok, out_of_range)
        character(len=*), intent(in) :: token
        real(dp), intent(out) :: value
        logical, intent(out) :: ok
        logical, intent(out), optional :: out_of_range
        integer(i8) :: mantissa
        integer(i4) :: p, n, ndigits, kept, scale, expo, esign, ios
        logical :: negative, any_digit
        character :: c
        character(len=48) :: normalized
        real(dp), parameter :: POW10(0:22) = [(10.0_dp**p, p = 0, 22)]
        !> Decimal exponents of the largest and smallest magnitudes read (double precision
        !> holds 1.8e308 down to 4.9e-324; 1e308 and beyond is refused rather than rounded
        !> near the overflow threshold, below 1e-330 is zero).
        integer(i4), parameter :: MAX_DECIMAL_EXPONENT = 307, MIN_DECIMAL_EXPONENT = -330
        value = 0.0_dp
        if (present(out_of_range)) out_of_range = .false.
        n = len(token)
        p = 1
        negative = .false.
        mantissa = 0
        ndigits = 0
        scale = 0
        any_digit = .false.
        ok = .false.
        if (n == 0) return
        if (token(1:1) == '-' .or. token(1:1) == '+') then
            negative = token(1:1) == '-'
            p = 2
        end if
        do while (p <= n)
            c = token(p:p)
            if (c < '0' .or. c > '9') exit
            call add_digit()
            p = p + 1
        end do
        if (p <= n) then
            if (token(p:p) == '.') then
                p = p + 1
                do while (p <= n)
                    c = token(p:p)
                    if (c < '0' .or. c > '9') exit
                    call add_digit()
                    scale = scale - 1
                    p = p + 1
                end do
            end if
        end if
        if (.not. any_digit) return
        expo = 0
        if (p <= n) then
            c = token(p:p)
            if (.not. (c == 'e' .or. c == 'E' .or. c == 'd' .or. c == 'D')) return
            p = p + 1
            esign = 1
            if (p <= n) then
                if (token(p:p) == '-' .or. token(p:p) == '+') then
                    if (token(p:p) == '-') esign = -1
                    p = p + 1
                end if
            end if
            if (p > n) return
            do while (p <= n)
                c = token(p:p)
                if (c < '0' .or. c > '9') return
                if (expo < 100000) expo = 10 * expo + (iachar(c) - 48)
                p = p + 1
            end do
            expo = esign * expo
        end if
        scale = scale + expo
        ok = .true.
        if (mantissa == 0) then
            if (negative) value = -0.0_dp
            return
        end if
        ! the value is mantissa * 10**scale, the mantissa has `kept` digits (the first 18):
        ! 10**(scale + kept - 1) <= |value| < 10**(scale + kept)
        kept = min(ndigits, 18_i4)
        if (scale + kept - 1 > MAX_DECIMAL_EXPONENT) then
            ok = .false.
            if (present(out_of_range)) out_of_range = .true.
            return
        end if
        if (scale + kept - 1 < MIN_DECIMAL_EXPONENT) then
            if (negative) value = -0.0_dp
            return
        end if
        if (ndigits <= 18 .and. abs(scale) <= 22) then
            if (scale >= 0) then
                value = real(mantissa, dp) * POW10(scale)
            else
                value = real(mantissa, dp) / POW10(-scale)
            end if
        else
            write (normalized, '(i0, "e", i0)') mantissa, scale
            read (normalized, '(f48.0)', iostat=ios) value
            ok = ios == 0
        end if
        if (negative) value = -value
    contains
        subroutine add_digit()
            any_digit = .true.
            if (ndigits < 18) then
                mantissa = 10 * mantissa + (iachar(c) - 48)
                if (mantissa > 0) ndigits = ndigits + 1
            else
                scale = scale + 1
                ndigits = ndigits + 1
            end if
        end subroutine add_digit
    end subroutine parse_real

    !> Value of a decimal integer literal with optional sign; ok = .false. otherwise
    !> (including overflow of a 32-bit integer).
    subroutine parse_integer(token, value, ok)
        character(len=*), intent(in) :: token
        integer(i4), intent(out) :: value
        logical, intent(out) :: ok
        integer(i8) :: acc
        integer(i4) :: p, p0
        value = 0
        ok = .false.
        p0 = 1
        if (len(token) == 0) return
        if (token(1:1) == '-' .or. token(1:1) == '+') p0 = 2
        if (p0 > len(token)) return
        acc = 0
        do p = p0, len(token)
            if (token(p:p) < '0' .or. token(p:p) > '9') return
            acc = 10 * acc + (iachar(token(p:p)) - 48)
            if (acc > huge(value)) return
        end do
        value = int(acc, i4)
        if (token(1:1) == '-') value = -value
        ok = .true.
    end subroutine parse_integer

end module mesh_text_lexer

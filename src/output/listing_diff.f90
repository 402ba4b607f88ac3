!> Numeric comparison of two listings (listings.md, "Reference listings and parasol-diff").
!>
!> Both listings are tokenized line by line (tokens are separated by blanks, tabs and other
!> control characters). A token is a number when it reads as [+-]digits[.digits][E|D[+-]digits]
!> optionally followed by `%`; two numbers match when
!>     |a - b| <= atol + rtol * max(|a|, |b|)
!> and both carry the same suffix (`%` or none). Every other token is a word and must be equal
!> character for character. Lines missing from or added to the result are differences; a
!> small look-ahead re-aligns the two listings after such a line so that one missing line does
!> not turn every following line into a difference.
module listing_diff
    use kinds, only: dp, i8
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use strings, only: string_t, real_short
    implicit none
    private

    !> Default relative tolerance of parasol-diff (listings.md): 1e-9, well above the 13
    !> significant digits of the listing format (1e-12) and well below TEST_RESU tolerances.
    real(dp), parameter, public :: DIFF_DEFAULT_RTOL = 1.0e-9_dp
    !> Default absolute tolerance (listings.md): 1e-15, so that round-off around zero
    !> (e.g. 1.0E-17 against 0.0) is not a difference.
    real(dp), parameter, public :: DIFF_DEFAULT_ATOL = 1.0e-15_dp
    !> How many lines ahead the comparison looks to re-align after a missing or extra line.
    integer, parameter :: RESYNC_WINDOW = 20
    !> Largest decimal exponent read as a number; larger values are compared as words so that
    !> reading them can never overflow (the Debug build traps overflow).
    integer, parameter :: MAX_DECIMAL_EXPONENT = 300

    public :: read_text_lines, split_text_lines, next_token, parse_number_token
    public :: numbers_match, compare_listing_lines, compare_listings

contains

    !> Reads a text file into lines (any length; LF or CRLF line ends; a missing final newline
    !> is accepted).
    !>  path  : in, the file
    !>  lines : out, one entry per line, without the line end
    !>  st    : out, STATUS_IO_ERROR "cannot read PATH: why" when the file does not exist, is
    !>          a directory, cannot be read, or is binary (contains a NUL byte)
    subroutine read_text_lines(path, lines, st)
        character(len=*), intent(in) :: path
        type(string_t), allocatable, intent(out) :: lines(:)
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: buffer
        character(len=256) :: msg
        integer :: unit, ios, nul_at
        integer(i8) :: file_size
        logical :: exists
        allocate (lines(0))
        inquire (file=path, exist=exists)
        if (.not. exists) then
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // path // &
                           ': no such file')
            return
        end if
        open (newunit=unit, file=path, access='stream', form='unformatted', action='read', &
              status='old', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // path // ': ' // trim(msg))
            return
        end if
        inquire (unit=unit, size=file_size)
        if (file_size < 0_i8 .or. file_size > int(huge(1), i8)) then
            close (unit, iostat=ios)
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // path // &
                           ': not a regular file, or larger than 2 GiB')
            return
        end if
        allocate (character(len=int(file_size)) :: buffer)
        ios = 0
        if (file_size > 0_i8) read (unit, iostat=ios, iomsg=msg) buffer
        close (unit)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // path // ': ' // trim(msg))
            return
        end if
        nul_at = index(buffer, achar(0))
        if (nul_at > 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // path // &
                           ': binary file (NUL byte), a listing must be text')
            return
        end if
        call split_text_lines(buffer, lines)
    end subroutine read_text_lines

    !> Splits a text at line feeds; a carriage return before a line feed is dropped, a final
    !> line feed does not start an empty line.
    !>  text  : in, the whole text
    !>  lines : out, the lines without their ends
    pure subroutine split_text_lines(text, lines)
        character(len=*), intent(in) :: text
        type(string_t), allocatable, intent(out) :: lines(:)
        character(len=1), parameter :: lf = achar(10), cr = achar(13)
        integer :: n, pos, k, last, line_end
        n = 0
        pos = 1
        do while (pos <= len(text))
            k = index(text(pos:), lf)
            n = n + 1
            if (k == 0) exit
            pos = pos + k
        end do
        allocate (lines(n))
        pos = 1
        do n = 1, size(lines)
            k = index(text(pos:), lf)
            if (k == 0) then
                last = len(text)
            else
                last = pos + k - 2
            end if
            line_end = last
            if (line_end >= pos) then
                if (text(line_end:line_end) == cr) line_end = line_end - 1
            end if
            lines(n)%s = text(pos:line_end)
            pos = last + 2
        end do
    end subroutine split_text_lines

    !> Finds the next token of `line` at or after `pos`.
    !>  line         : in, the text
    !>  pos          : inout, where to start; on return, just after the token
    !>  first, last  : out, bounds of the token; first = 0 when there is none left
    pure subroutine next_token(line, pos, first, last)
        character(len=*), intent(in) :: line
        integer, intent(inout) :: pos
        integer, intent(out) :: first, last
        first = 0
        last = -1
        do while (pos <= len(line))
            if (.not. is_separator(line(pos:pos))) exit
            pos = pos + 1
        end do
        if (pos > len(line)) return
        first = pos
        do while (pos <= len(line))
            if (is_separator(line(pos:pos))) exit
            pos = pos + 1
        end do
        last = pos - 1
    end subroutine next_token

    !> Blanks, tabs and other ASCII control characters separate tokens.
    pure logical function is_separator(c)
        character(len=1), intent(in) :: c
        is_separator = iachar(c) <= 32 .or. iachar(c) == 127
    end function is_separator

    !> Reads a token as a number: [+-]digits[.digits][(E|e|D|d)[+-]digits][%], at least one
    !> digit in the mantissa. `1.0D+00`, `+3`, `.5`, `3.31E-09%` are numbers; `NaN`, `1e`,
    !> `PT01`, `1.0E+400` (beyond MAX_DECIMAL_EXPONENT) are not.
    !>  token      : in, the token
    !>  is_number  : out, true when the token is a number
    !>  value      : out, its value (0 when not a number)
    !>  is_percent : out, true when it ends with `%`
    pure subroutine parse_number_token(token, is_number, value, is_percent)
        character(len=*), intent(in) :: token
        logical, intent(out) :: is_number
        real(dp), intent(out) :: value
        logical, intent(out) :: is_percent
        integer :: n, pos, mantissa_digits, lead_digits, exponent_value, ios
        logical :: in_leading_zeros
        character(len=len(token)) :: copy
        is_number = .false.
        value = 0.0_dp
        n = len(token)
        is_percent = .false.
        if (n > 0) is_percent = token(n:n) == '%'
        if (is_percent) n = n - 1
        pos = 1
        if (pos <= n) then
            if (token(pos:pos) == '+' .or. token(pos:pos) == '-') pos = pos + 1
        end if
        mantissa_digits = 0
        lead_digits = 0       ! integer-part digits after leading zeros: the magnitude
        in_leading_zeros = .true.
        do while (pos <= n)
            if (.not. is_digit(token(pos:pos))) exit
            if (token(pos:pos) /= '0') in_leading_zeros = .false.
            if (.not. in_leading_zeros) lead_digits = lead_digits + 1
            mantissa_digits = mantissa_digits + 1
            pos = pos + 1
        end do
        if (pos <= n) then
            if (token(pos:pos) == '.') then
                pos = pos + 1
                do while (pos <= n)
                    if (.not. is_digit(token(pos:pos))) exit
                    mantissa_digits = mantissa_digits + 1
                    pos = pos + 1
                end do
            end if
        end if
        if (mantissa_digits == 0) return
        exponent_value = 0
        if (pos <= n) then
            if (index('EeDd', token(pos:pos)) == 0) return
            call read_exponent(token(pos + 1:n), exponent_value, ios)
            if (ios /= 0) return
        end if
        if (exponent_value + lead_digits > MAX_DECIMAL_EXPONENT) return
        copy = token(1:n)
        pos = scan(copy, 'Dd')
        if (pos > 0) copy(pos:pos) = 'E'
        read (copy(1:n), *, iostat=ios) value
        if (ios /= 0) then
            value = 0.0_dp
            return
        end if
        is_number = .true.
    end subroutine parse_number_token

    !> Reads [+-]digits (at least one digit) as an exponent, clamped to +-99999.
    pure subroutine read_exponent(text, exponent_value, ios)
        character(len=*), intent(in) :: text
        integer, intent(out) :: exponent_value, ios
        integer :: pos, sign_value
        ios = 1
        exponent_value = 0
        sign_value = 1
        pos = 1
        if (len(text) == 0) return
        if (text(1:1) == '+' .or. text(1:1) == '-') then
            if (text(1:1) == '-') sign_value = -1
            pos = 2
        end if
        if (pos > len(text)) return
        do while (pos <= len(text))
            if (.not. is_digit(text(pos:pos))) return
            if (exponent_value < 99999) &
                exponent_value = 10 * exponent_value + (iachar(text(pos:pos)) - iachar('0'))
            pos = pos + 1
        end do
        exponent_value = sign_value * min(exponent_value, 99999)
        ios = 0
    end subroutine read_exponent

    pure logical function is_digit(c)
        character(len=1), intent(in) :: c
        is_digit = c >= '0' .and. c <= '9'
    end function is_digit

    !> True when |a - b| <= atol + rtol * max(|a|, |b|). Arguments must be finite with
    !> magnitude below 1e300 (parse_number_token guarantees it) and rtol, atol >= 0.
    elemental logical function numbers_match(a, b, rtol, atol)
        real(dp), intent(in) :: a, b, rtol, atol
        real(dp) :: largest, allowed
        largest = max(abs(a), abs(b))
        if (rtol > 1.0_dp) then
            if (largest > huge(1.0_dp) / (4.0_dp * rtol)) then
                numbers_match = .true.      ! the allowed difference exceeds any real
                return
            end if
        end if
        allowed = min(atol, huge(1.0_dp) / 4.0_dp) + rtol * largest
        numbers_match = abs(a - b) <= allowed
    end function numbers_match

    !> Compares one line of the result with one line of the reference, token by token.
    !>  result_line, reference_line : in, the two lines
    !>  rtol, atol  : in, the numeric tolerances (see numbers_match)
    !>  messages    : inout, where the description of each difference is appended
    !>  n_messages  : inout, how many entries of `messages` are used
    !>  label       : in, the `LINE` prefix of the messages (e.g. "12")
    !>  n_found     : out, how many tokens differ (0 when the lines match)
    subroutine compare_listing_lines(result_line, reference_line, rtol, atol, label, &
                                     messages, n_messages, n_found)
        character(len=*), intent(in) :: result_line, reference_line, label
        real(dp), intent(in) :: rtol, atol
        type(string_t), allocatable, intent(inout) :: messages(:)
        integer, intent(inout) :: n_messages
        integer, intent(out) :: n_found
        integer :: pos_res, pos_ref, f_res, l_res, f_ref, l_ref, i_token
        character(len=:), allocatable :: why
        n_found = 0
        pos_res = 1
        pos_ref = 1
        i_token = 0
        do
            call next_token(result_line, pos_res, f_res, l_res)
            call next_token(reference_line, pos_ref, f_ref, l_ref)
            if (f_res == 0 .and. f_ref == 0) exit
            i_token = i_token + 1
            if (f_ref == 0) then
                call append_line(messages, n_messages, label // ': expected end of line got ' &
                                 // result_line(f_res:l_res) // token_suffix(i_token))
            else if (f_res == 0) then
                call append_line(messages, n_messages, label // ': expected ' // &
                                 reference_line(f_ref:l_ref) // ' got end of line' // &
                                 token_suffix(i_token))
            else
                call compare_tokens(result_line(f_res:l_res), reference_line(f_ref:l_ref), &
                                    rtol, atol, why)
                if (len(why) == 0) cycle
                call append_line(messages, n_messages, label // ': expected ' // &
                                 reference_line(f_ref:l_ref) // ' got ' // &
                                 result_line(f_res:l_res) // token_suffix(i_token, why))
            end if
            n_found = n_found + 1
        end do
    end subroutine compare_listing_lines

    !> The " (token N[, why])" tail of a difference message.
    pure function token_suffix(i_token, why) result(text)
        integer, intent(in) :: i_token
        character(len=*), intent(in), optional :: why
        character(len=:), allocatable :: text
        character(len=12) :: buf
        write (buf, '(i0)') i_token
        text = ' (token ' // trim(buf)
        if (present(why)) then
            if (why /= 'word') text = text // ', ' // why
        end if
        text = text // ')'
    end function token_suffix

    !> Compares two tokens: `why` is empty when they match, else says how they differ.
    pure subroutine compare_tokens(result_token, reference_token, rtol, atol, why)
        character(len=*), intent(in) :: result_token, reference_token
        real(dp), intent(in) :: rtol, atol
        character(len=:), allocatable, intent(out) :: why
        logical :: num_res, num_ref, pct_res, pct_ref
        real(dp) :: v_res, v_ref
        why = ''
        if (result_token == reference_token .and. &
            len(result_token) == len(reference_token)) return
        call parse_number_token(result_token, num_res, v_res, pct_res)
        call parse_number_token(reference_token, num_ref, v_ref, pct_ref)
        if (.not. (num_res .and. num_ref)) then
            why = 'word'
        else if (pct_res .neqv. pct_ref) then
            why = 'percent sign differs'
        else if (.not. numbers_match(v_res, v_ref, rtol, atol)) then
            why = '|difference| = ' // real_short(abs(v_res - v_ref)) // ' > ' // &
                  real_short(min(atol, huge(1.0_dp) / 4.0_dp) + rtol * max(abs(v_res), &
                                                                           abs(v_ref)))
        end if
    end subroutine compare_tokens

    !> True when two lines match within the tolerances (no message).
    logical function lines_match(result_line, reference_line, rtol, atol)
        character(len=*), intent(in) :: result_line, reference_line
        real(dp), intent(in) :: rtol, atol
        integer :: pos_res, pos_ref, f_res, l_res, f_ref, l_ref
        character(len=:), allocatable :: why
        lines_match = .false.
        pos_res = 1
        pos_ref = 1
        do
            call next_token(result_line, pos_res, f_res, l_res)
            call next_token(reference_line, pos_ref, f_ref, l_ref)
            if (f_res == 0 .and. f_ref == 0) exit
            if (f_res == 0 .or. f_ref == 0) return
            call compare_tokens(result_line(f_res:l_res), reference_line(f_ref:l_ref), &
                                rtol, atol, why)
            if (len(why) > 0) return
        end do
        lines_match = .true.
    end function lines_match

    !> True when the lines differ in their words or their number of tokens (not only in
    !> numbers): only then is a missing or extra line a likely explanation.
    logical function lines_differ_in_shape(result_line, reference_line)
        character(len=*), intent(in) :: result_line, reference_line
        integer :: pos_res, pos_ref, f_res, l_res, f_ref, l_ref
        logical :: num_res, num_ref, pct
        real(dp) :: v
        lines_differ_in_shape = .true.
        pos_res = 1
        pos_ref = 1
        do
            call next_token(result_line, pos_res, f_res, l_res)
            call next_token(reference_line, pos_ref, f_ref, l_ref)
            if (f_res == 0 .and. f_ref == 0) exit
            if (f_res == 0 .or. f_ref == 0) return
            call parse_number_token(result_line(f_res:l_res), num_res, v, pct)
            call parse_number_token(reference_line(f_ref:l_ref), num_ref, v, pct)
            if (num_res .neqv. num_ref) return
            if (.not. num_res .and. result_line(f_res:l_res) /= reference_line(f_ref:l_ref)) &
                return
        end do
        lines_differ_in_shape = .false.
    end function lines_differ_in_shape

    !> Compares a result listing with its reference.
    !>  result_lines, reference_lines : in, the two listings, one entry per line
    !>  rtol, atol      : in, numeric tolerances (DIFF_DEFAULT_RTOL, DIFF_DEFAULT_ATOL)
    !>  messages        : out, one `LINE: expected … got …` per difference; LINE is the line
    !>                    number in the result (for a missing line: where it is missing, with
    !>                    the reference line number); the reference line is named when it
    !>                    differs from the result line number
    !>  n_differences   : out, number of differences (differing tokens, missing and extra lines)
    !>  n_lines         : out, number of lines with at least one difference
    subroutine compare_listings(result_lines, reference_lines, rtol, atol, messages, &
                                n_differences, n_lines)
        type(string_t), intent(in) :: result_lines(:), reference_lines(:)
        real(dp), intent(in) :: rtol, atol
        type(string_t), allocatable, intent(out) :: messages(:)
        integer, intent(out) :: n_differences, n_lines
        integer :: i, j, n_msg, n_found, k_res, k_ref
        allocate (messages(16))
        n_msg = 0
        n_differences = 0
        n_lines = 0
        i = 1
        j = 1
        do while (i <= size(result_lines) .and. j <= size(reference_lines))
            if (lines_match(result_lines(i)%s, reference_lines(j)%s, rtol, atol)) then
                i = i + 1
                j = j + 1
                cycle
            end if
            k_res = 0
            k_ref = 0
            if (lines_differ_in_shape(result_lines(i)%s, reference_lines(j)%s)) &
                call find_resync(result_lines, reference_lines, i, j, rtol, atol, k_res, k_ref)
            if (k_ref > 0) then
                call report_missing(reference_lines, j, j + k_ref - 1, i, messages, n_msg)
                n_differences = n_differences + k_ref
                n_lines = n_lines + k_ref
                j = j + k_ref
            else if (k_res > 0) then
                call report_extra(result_lines, i, i + k_res - 1, messages, n_msg)
                n_differences = n_differences + k_res
                n_lines = n_lines + k_res
                i = i + k_res
            else
                call compare_listing_lines(result_lines(i)%s, reference_lines(j)%s, rtol, &
                                           atol, line_label(i, j), messages, n_msg, n_found)
                n_differences = n_differences + n_found
                n_lines = n_lines + 1
                i = i + 1
                j = j + 1
            end if
        end do
        if (j <= size(reference_lines)) then
            call report_missing(reference_lines, j, size(reference_lines), i, messages, n_msg)
            n_differences = n_differences + size(reference_lines) - j + 1
            n_lines = n_lines + size(reference_lines) - j + 1
        end if
        if (i <= size(result_lines)) then
            call report_extra(result_lines, i, size(result_lines), messages, n_msg)
            n_differences = n_differences + size(result_lines) - i + 1
            n_lines = n_lines + size(result_lines) - i + 1
        end if
        messages = messages(1:n_msg)
    end subroutine compare_listings

    !> Looks ahead for the nearest re-alignment: result line i matches reference line j+k_ref
    !> (k_ref reference lines missing) or result line i+k_res matches reference line j
    !> (k_res extra lines); the next pair must match too, so blank lines do not mislead.
    subroutine find_resync(result_lines, reference_lines, i, j, rtol, atol, k_res, k_ref)
        type(string_t), intent(in) :: result_lines(:), reference_lines(:)
        integer, intent(in) :: i, j
        real(dp), intent(in) :: rtol, atol
        integer, intent(out) :: k_res, k_ref
        integer :: k
        k_res = 0
        k_ref = 0
        do k = 1, RESYNC_WINDOW
            if (pair_anchors(i, j + k)) then
                k_ref = k
                return
            end if
            if (pair_anchors(i + k, j)) then
                k_res = k
                return
            end if
        end do
    contains
        logical function pair_anchors(ir, jr)
            integer, intent(in) :: ir, jr
            pair_anchors = .false.
            if (ir > size(result_lines) .or. jr > size(reference_lines)) return
            if (.not. lines_match(result_lines(ir)%s, reference_lines(jr)%s, rtol, atol)) &
                return
            if (ir + 1 > size(result_lines) .or. jr + 1 > size(reference_lines)) then
                pair_anchors = ir == size(result_lines) .and. jr == size(reference_lines)
            else
                pair_anchors = lines_match(result_lines(ir + 1)%s, reference_lines(jr + 1)%s, &
                                           rtol, atol)
            end if
        end function pair_anchors
    end subroutine find_resync

    !> `I` or `I (reference line J)`.
    pure function line_label(i, j) result(text)
        integer, intent(in) :: i, j
        character(len=:), allocatable :: text
        character(len=12) :: a, b
        write (a, '(i0)') i
        text = trim(a)
        if (i /= j) then
            write (b, '(i0)') j
            text = text // ' (reference line ' // trim(b) // ')'
        end if
    end function line_label

    !> Messages for reference lines first..last missing from the result before line `at`.
    subroutine report_missing(reference_lines, first, last, at, messages, n_msg)
        type(string_t), intent(in) :: reference_lines(:)
        integer, intent(in) :: first, last, at
        type(string_t), allocatable, intent(inout) :: messages(:)
        integer, intent(inout) :: n_msg
        integer :: j
        character(len=12) :: a, b
        write (a, '(i0)') at
        do j = first, last
            write (b, '(i0)') j
            call append_line(messages, n_msg, trim(a) // ': expected line ' // trim(b) // &
                             ' of the reference "' // reference_lines(j)%s // &
                             '" got no line (missing line)')
        end do
    end subroutine report_missing

    !> Messages for result lines first..last that the reference does not have.
    subroutine report_extra(result_lines, first, last, messages, n_msg)
        type(string_t), intent(in) :: result_lines(:)
        integer, intent(in) :: first, last
        type(string_t), allocatable, intent(inout) :: messages(:)
        integer, intent(inout) :: n_msg
        integer :: i
        character(len=12) :: a
        do i = first, last
            write (a, '(i0)') i
            call append_line(messages, n_msg, trim(a) // ': expected no line got "' // &
                             result_lines(i)%s // '" (extra line)')
        end do
    end subroutine report_extra

    !> Appends `text` to `list(1:n)`, doubling the capacity when needed.
    pure subroutine append_line(list, n, text)
        type(string_t), allocatable, intent(inout) :: list(:)
        integer, intent(inout) :: n
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: bigger(:)
        if (.not. allocated(list)) allocate (list(16))
        if (n >= size(list)) then
            allocate (bigger(2 * size(list) + 1))
            bigger(1:n) = list(1:n)
            call move_alloc(bigger, list)
        end if
        n = n + 1
        list(n)%s = text
    end subroutine append_line

end module listing_diff

!> The deck evaluator (deck_interpreter), the methods of its strings as Python 3 defines
!> them (format, join, split, strip, replace, startswith, find, upper, zfill, ...). Strings
!> are UTF-8: indices count characters; case changes are ASCII's.
submodule(deck_interpreter) deck_interp_strings
    use deck_format, only: format_spec_t, pad
    implicit none

    character(len=*), parameter :: WHITESPACE = ' ' // achar(9) // achar(10) // achar(11) // &
        achar(12) // achar(13)

contains

    ! ---- strings ----------------------------------------------------------------------------

    module procedure str_method
        type(value_t), allocatable :: items(:), parts(:)
        character(len=:), allocatable :: text, chars, what
        integer :: k, n, width, pos
        integer(i8) :: maxsplit
        logical :: found
        type(value_t) :: x
        what = 'str.' // name
        if (name /= 'format' .and. name /= 'join') then
            if (any(args%kind == VK_UNKNOWN)) then
                v%kind = VK_UNKNOWN; return
            end if
        end if
        select case (name)
        case ('format')
            call only_kwargs(ctx, id, what // '()', kwargs, '*', st)
            if (holds_unknown(kwargs) .or. any(args%kind == VK_UNKNOWN)) then
                v%kind = VK_UNKNOWN; return
            end if
            call str_format(ctx, id, s, args, kwargs, text, st)
            if (st%ok()) v = str_value(text)
        case ('join')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            text = ''
            do k = 1, size(items)
                if (items(k)%kind == VK_UNKNOWN) then
                    v%kind = VK_UNKNOWN; return
                end if
                if (items(k)%kind /= VK_STR) then
                    call fail(st, ctx, id, 'str.join(): item ' // to_text(k - 1) // ' is ' // &
                        kind_label(items(k)) // ', not a string (use str(x))'); return
                end if
                if (k > 1) text = text // s
                text = text // items(k)%s
                if (len(text) > MAX_REPEAT) then
                    call fail(st, ctx, id, 'string too long (more than ' // &
                              to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
                end if
            end do
            v = str_value(text)
        case ('upper', 'lower', 'swapcase', 'title', 'capitalize')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            v = str_value(change_case(s, name))
        case ('strip', 'lstrip', 'rstrip')
            call arity(ctx, id, what, args, kwargs, 0, 1, '', st)
            if (st%failed()) return
            chars = WHITESPACE
            if (size(args) == 1) then
                if (args(1)%kind == VK_STR) then
                    chars = args(1)%s
                else if (args(1)%kind /= VK_NONE) then
                    call fail(st, ctx, id, what // '() takes a string of characters'); return
                end if
            end if
            v = str_value(stripped(s, chars, name /= 'rstrip', name /= 'lstrip'))
        case ('split', 'rsplit')
            call arity(ctx, id, what, args, kwargs, 0, 2, 'sep maxsplit', st)
            if (st%failed()) return
            x%kind = VK_NONE
            if (size(args) >= 1) x = args(1)
            call kwarg(kwargs, 'sep', v, found)
            if (found) x = v
            maxsplit = -1
            if (size(args) == 2) maxsplit = args(2)%i
            call kwarg(kwargs, 'maxsplit', v, found)
            if (found) maxsplit = v%i
            if (x%kind /= VK_NONE .and. x%kind /= VK_STR) then
                call fail(st, ctx, id, what // '() sep must be a string or None'); return
            end if
            if (x%kind == VK_STR) then
                if (len(x%s) == 0) then
                    call fail(st, ctx, id, what // '(): empty separator'); return
                end if
                call split_on(s, x%s, maxsplit, name == 'rsplit', parts)
            else
                call split_blanks(s, maxsplit, name == 'rsplit', parts)
            end if
            v = new_list(ctx, parts)
            call check_heap(ctx, id, st)
        case ('splitlines')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            call split_on(s, achar(10), -1_i8, .false., parts)
            do k = 1, size(parts)
                n = len(parts(k)%s)
                if (n > 0) then
                    if (parts(k)%s(n:n) == achar(13)) parts(k) = str_value(parts(k)%s(1:n - 1))
                end if
            end do
            if (size(parts) > 0) then
                if (len(parts(size(parts))%s) == 0) parts = parts(1:size(parts) - 1)
            end if
            v = new_list(ctx, parts)
        case ('partition', 'rpartition')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            if (.not. want_text(ctx, id, args(1), what // '()', st)) return
            if (len(args(1)%s) == 0) then
                call fail(st, ctx, id, what // '(): empty separator'); return
            end if
            pos = index(s, args(1)%s, back=name == 'rpartition')
            if (pos == 0) then
                if (name == 'partition') then
                    v = sequence_value(VK_TUPLE, values_of(str_value(s), str_value(''), str_value('')))
                else
                    v = sequence_value(VK_TUPLE, values_of(str_value(''), str_value(''), str_value(s)))
                end if
            else
                v = sequence_value(VK_TUPLE, values_of(str_value(s(1:pos - 1)), args(1), &
                                   str_value(s(pos + len(args(1)%s):))))
            end if
        case ('replace')
            call arity(ctx, id, what, args, kwargs, 2, 3, '', st)
            if (st%failed()) return
            if (.not. want_text(ctx, id, args(1), what // '()', st)) return
            if (.not. want_text(ctx, id, args(2), what // '()', st)) return
            maxsplit = -1
            if (size(args) == 3) maxsplit = args(3)%i
            call replaced(s, args(1)%s, args(2)%s, maxsplit, text)
            if (len(text) > MAX_REPEAT) then
                call fail(st, ctx, id, 'string too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
            end if
            v = str_value(text)
        case ('startswith', 'endswith')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            if (args(1)%kind == VK_TUPLE) then
                call iterate(ctx, id, args(1), items, st)
            else
                items = args(1:1)
            end if
            found = .false.
            do k = 1, size(items)
                if (.not. want_text(ctx, id, items(k), what // '()', st)) return
                n = len(items(k)%s)
                if (n > len(s)) cycle
                if (name == 'startswith') then
                    if (s(1:n) == items(k)%s) found = .true.
                else
                    if (s(len(s) - n + 1:) == items(k)%s) found = .true.
                end if
            end do
            v = bool_value(found)
        case ('find', 'rfind', 'index', 'rindex', 'count')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            if (.not. want_text(ctx, id, args(1), what // '()', st)) return
            if (name == 'count') then
                v = int_value(int(occurrences(s, args(1)%s), i8)); return
            end if
            pos = index(s, args(1)%s, back=name(1:1) == 'r')
            if (len(args(1)%s) == 0) then
                pos = 1
                if (name(1:1) == 'r') pos = len(s) + 1
            end if
            if (pos == 0) then
                if (name(len(name) - 4:) == 'index') then
                    call fail(st, ctx, id, what // '(): substring ' // &
                              text_of(ctx, args(1), .true.) // ' not found'); return
                end if
                v = int_value(-1_i8)
            else
                v = int_value(int(char_count(s(1:pos - 1)), i8))
            end if
        case ('zfill', 'ljust', 'rjust', 'center')
            if (name == 'zfill') then
                call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            else
                call arity(ctx, id, what, args, kwargs, 1, 2, '', st)
            end if
            if (st%failed()) return
            if (args(1)%kind /= VK_INT .and. args(1)%kind /= VK_BOOL) then
                call fail(st, ctx, id, what // '() takes an integer width'); return
            end if
            width = int(max(0_i8, min(args(1)%i, int(MAX_REPEAT, i8))))
            call justify(s, name, width, args, text)
            if (st%ok()) v = str_value(text)
        case ('isdigit', 'isalpha', 'isspace', 'isupper', 'islower')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            v = bool_value(classified(s, name))
        end select
    contains
        subroutine justify(text0, how, w, a, out)
            character(len=*), intent(in) :: text0, how
            integer, intent(in) :: w
            type(value_t), intent(in) :: a(:)
            character(len=:), allocatable, intent(out) :: out
            type(format_spec_t) :: spec
            integer :: sign_len
            spec%width = w + len(text0) - char_count(text0)
            if (size(a) == 2) then
                if (a(2)%kind /= VK_STR) then
                    call fail(st, ctx, id, what // '() fill must be one character'); return
                end if
                if (len(a(2)%s) /= 1) then
                    call fail(st, ctx, id, what // '() fill must be one (ASCII) character')
                    return
                end if
                spec%fill = a(2)%s
            end if
            select case (how)
            case ('zfill')
                sign_len = 0
                if (len(text0) > 0) then
                    if (text0(1:1) == '-' .or. text0(1:1) == '+') sign_len = 1
                end if
                out = text0(1:sign_len) // repeat('0', max(0, spec%width - len(text0))) // &
                    text0(sign_len + 1:)
            case ('ljust')
                spec%align = '<'; out = pad(text0, spec, '<')
            case ('rjust')
                spec%align = '>'; out = pad(text0, spec, '>')
            case default
                spec%align = '^'; out = pad(text0, spec, '^')
            end select
        end subroutine justify
    end procedure str_method

    !> Characters (UTF-8 code points) of text.
    pure integer function char_count(text)
        character(len=*), intent(in) :: text
        integer :: i
        char_count = 0
        do i = 1, len(text)
            if (iand(iachar(text(i:i)), 192) /= 128) char_count = char_count + 1
        end do
    end function char_count

    pure integer function occurrences(text, sub)
        character(len=*), intent(in) :: text, sub
        integer :: i, p
        occurrences = 0
        if (len(sub) == 0) then
            occurrences = char_count(text) + 1; return
        end if
        i = 1
        do
            p = index(text(i:), sub)
            if (p == 0) exit
            occurrences = occurrences + 1
            i = i + p - 1 + len(sub)
            if (i > len(text)) exit
        end do
    end function occurrences

    pure function change_case(text, how) result(out)
        character(len=*), intent(in) :: text, how
        character(len=len(text)) :: out
        integer :: i
        logical :: start
        out = text
        start = .true.
        do i = 1, len(text)
            select case (how)
            case ('upper')
                out(i:i) = upper(text(i:i))
            case ('lower')
                out(i:i) = lower(text(i:i))
            case ('swapcase')
                if (text(i:i) >= 'a' .and. text(i:i) <= 'z') then
                    out(i:i) = upper(text(i:i))
                else
                    out(i:i) = lower(text(i:i))
                end if
            case ('title')
                if (start) then
                    out(i:i) = upper(text(i:i))
                else
                    out(i:i) = lower(text(i:i))
                end if
                start = .not. is_letter(text(i:i))
            case ('capitalize')
                if (i == 1) then
                    out(i:i) = upper(text(i:i))
                else
                    out(i:i) = lower(text(i:i))
                end if
            end select
        end do
    contains
        pure character function upper(c)
            character, intent(in) :: c
            upper = c
            if (c >= 'a' .and. c <= 'z') upper = achar(iachar(c) - 32)
        end function upper
        pure character function lower(c)
            character, intent(in) :: c
            lower = c
            if (c >= 'A' .and. c <= 'Z') lower = achar(iachar(c) + 32)
        end function lower
    end function change_case

    pure logical function is_letter(c)
        character, intent(in) :: c
        is_letter = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
    end function is_letter

    pure logical function classified(text, how)
        character(len=*), intent(in) :: text, how
        integer :: i
        logical :: cased
        classified = len(text) > 0
        cased = .false.
        do i = 1, len(text)
            select case (how)
            case ('isdigit')
                if (index('0123456789', text(i:i)) == 0) classified = .false.
            case ('isalpha')
                if (.not. is_letter(text(i:i))) classified = .false.
            case ('isspace')
                if (index(WHITESPACE, text(i:i)) == 0) classified = .false.
            case ('isupper')
                if (text(i:i) >= 'a' .and. text(i:i) <= 'z') classified = .false.
                if (text(i:i) >= 'A' .and. text(i:i) <= 'Z') cased = .true.
            case ('islower')
                if (text(i:i) >= 'A' .and. text(i:i) <= 'Z') classified = .false.
                if (text(i:i) >= 'a' .and. text(i:i) <= 'z') cased = .true.
            end select
        end do
        if (how == 'isupper' .or. how == 'islower') classified = classified .and. cased
    end function classified

    pure function stripped(text, chars, left, right) result(out)
        character(len=*), intent(in) :: text, chars
        logical, intent(in) :: left, right
        character(len=:), allocatable :: out
        integer :: i, j
        i = 1; j = len(text)
        if (left) then
            do while (i <= j)
                if (index(chars, text(i:i)) == 0) exit
                i = i + 1
            end do
        end if
        if (right) then
            do while (j >= i)
                if (index(chars, text(j:j)) == 0) exit
                j = j - 1
            end do
        end if
        out = text(i:j)
    end function stripped

    !> text split at each sep (at most maxsplit splits, from the right for rsplit).
    subroutine split_on(text, sep, maxsplit, from_right, parts)
        character(len=*), intent(in) :: text, sep
        integer(i8), intent(in) :: maxsplit
        logical, intent(in) :: from_right
        type(value_t), allocatable, intent(out) :: parts(:)
        integer :: p, stop_at
        integer(i8) :: done
        character(len=:), allocatable :: rest
        allocate (parts(0))
        rest = text
        done = 0
        if (.not. from_right) then
            do
                if (maxsplit >= 0 .and. done >= maxsplit) exit
                p = index(rest, sep)
                if (p == 0) exit
                call append_value(parts, str_value(rest(1:p - 1)))
                rest = rest(p + len(sep):)
                done = done + 1
            end do
            call append_value(parts, str_value(rest))
        else
            stop_at = len(rest)
            do
                if (maxsplit >= 0 .and. done >= maxsplit) exit
                p = index(rest(1:stop_at), sep, back=.true.)
                if (p == 0) exit
                parts = joined(values_of(str_value(rest(p + len(sep):stop_at))), parts)
                stop_at = p - 1
                done = done + 1
            end do
            parts = joined(values_of(str_value(rest(1:stop_at))), parts)
        end if
    end subroutine split_on

    !> text split at runs of blanks, empty strings dropped (str.split()).
    subroutine split_blanks(text, maxsplit, from_right, parts)
        character(len=*), intent(in) :: text
        integer(i8), intent(in) :: maxsplit
        logical, intent(in) :: from_right
        type(value_t), allocatable, intent(out) :: parts(:)
        integer :: i, j, n
        integer(i8) :: done
        allocate (parts(0))
        done = 0
        n = len(text)
        if (.not. from_right) then
            i = 1
            do
                do while (i <= n)
                    if (index(WHITESPACE, text(i:i)) == 0) exit
                    i = i + 1
                end do
                if (i > n) exit
                if (maxsplit >= 0 .and. done >= maxsplit) then
                    j = n
                    do while (j >= i)
                        if (index(WHITESPACE, text(j:j)) == 0) exit
                        j = j - 1
                    end do
                    call append_value(parts, str_value(text(i:j)))
                    exit
                end if
                j = i
                do while (j <= n)
                    if (index(WHITESPACE, text(j:j)) > 0) exit
                    j = j + 1
                end do
                call append_value(parts, str_value(text(i:j - 1)))
                done = done + 1
                i = j
            end do
        else
            j = n
            do
                do while (j >= 1)
                    if (index(WHITESPACE, text(j:j)) == 0) exit
                    j = j - 1
                end do
                if (j < 1) exit
                if (maxsplit >= 0 .and. done >= maxsplit) then
                    i = 1
                    do while (i <= j)
                        if (index(WHITESPACE, text(i:i)) == 0) exit
                        i = i + 1
                    end do
                    parts = joined(values_of(str_value(text(i:j))), parts)
                    exit
                end if
                i = j
                do while (i >= 1)
                    if (index(WHITESPACE, text(i:i)) > 0) exit
                    i = i - 1
                end do
                parts = joined(values_of(str_value(text(i + 1:j))), parts)
                done = done + 1
                j = i
            end do
        end if
    end subroutine split_blanks

    subroutine replaced(text, old, new, count, out)
        character(len=*), intent(in) :: text, old, new
        integer(i8), intent(in) :: count
        character(len=:), allocatable, intent(out) :: out
        integer :: i, p
        integer(i8) :: done
        out = ''
        if (len(old) == 0) then
            out = text; return
        end if
        i = 1; done = 0
        do
            if (count >= 0 .and. done >= count) exit
            p = index(text(i:), old)
            if (p == 0) exit
            out = out // text(i:i + p - 2) // new
            i = i + p - 1 + len(old)
            done = done + 1
            if (i > len(text)) exit
            if (len(out) > MAX_REPEAT) exit
        end do
        if (i <= len(text)) out = out // text(i:)
    end subroutine replaced

end submodule deck_interp_strings

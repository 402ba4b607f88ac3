!> The deck evaluator (deck_interpreter), the methods of its built-in types as Python 3
!> defines them: strings (format, join, split, strip, replace, startswith, find, upper,
!> zfill, ...), lists (append, extend, insert, pop, remove, index, count, sort, reverse,
!> copy, clear), dicts (keys, values, items, get, pop, setdefault, update, copy, clear,
!> popitem), tuples (index, count) and _F (read like a dict); and the % operator of strings.
!> Strings are UTF-8; indices count characters; upper/lower change ASCII letters only.
submodule(deck_interpreter) deck_interp_types
    use deck_format, only: format_spec_t, format_real, format_int, format_text, pad
    implicit none

    character(len=*), parameter :: STR_METHODS = ' capitalize center count endswith find ' // &
        'format index isalpha isdigit islower isspace isupper join ljust lower lstrip ' // &
        'partition replace rfind rindex rjust rpartition rsplit rstrip split splitlines ' // &
        'startswith strip swapcase title upper zfill '
    character(len=*), parameter :: LIST_METHODS = ' append extend insert pop remove index ' // &
        'count reverse sort copy clear '
    character(len=*), parameter :: DICT_METHODS = ' keys values items get pop setdefault ' // &
        'update copy clear popitem '
    character(len=*), parameter :: TUPLE_METHODS = ' index count '
    character(len=*), parameter :: FACTOR_METHODS = ' keys values items get copy '
    character(len=*), parameter :: WHITESPACE = ' ' // achar(9) // achar(10) // achar(11) // &
        achar(12) // achar(13)

contains

    module procedure type_has_method
        select case (kind)
        case (VK_STR)
            type_has_method = index(STR_METHODS, ' ' // name // ' ') > 0
        case (VK_LIST)
            type_has_method = index(LIST_METHODS, ' ' // name // ' ') > 0
        case (VK_DICT)
            type_has_method = index(DICT_METHODS, ' ' // name // ' ') > 0
        case (VK_TUPLE)
            type_has_method = index(TUPLE_METHODS, ' ' // name // ' ') > 0
        case (VK_FACTOR)
            type_has_method = index(FACTOR_METHODS, ' ' // name // ' ') > 0
        case default
            type_has_method = .false.
        end select
    end procedure type_has_method

    module procedure type_method
        character(len=:), allocatable :: methods
        if (.not. type_has_method(obj%kind, name)) then
            select case (obj%kind)
            case (VK_STR)
                methods = STR_METHODS
            case (VK_LIST)
                methods = LIST_METHODS
            case (VK_DICT)
                methods = DICT_METHODS
            case (VK_TUPLE)
                methods = TUPLE_METHODS
            case default
                methods = FACTOR_METHODS
            end select
            call fail(st, ctx, id, kind_label(obj) // ' has no method ' // name // &
                      ' (its methods:' // methods // ')'); return
        end if
        select case (obj%kind)
        case (VK_STR)
            call str_method(ctx, id, obj%s, name, args, kwargs, v, st)
        case (VK_LIST)
            call list_method(ctx, id, obj, name, args, kwargs, v, st, frame)
        case (VK_DICT)
            call dict_method(ctx, id, obj, name, args, kwargs, v, st)
        case (VK_TUPLE)
            call sequence_search(ctx, id, obj, name, args, v, st)
        case (VK_FACTOR)
            call factor_method(ctx, id, obj, name, args, v, st)
        end select
    end procedure type_method

    !> Error unless lo..hi positional arguments and only the keywords `keys`.
    subroutine arity(ctx, id, what, args, kwargs, lo, hi, keys, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id, lo, hi
        character(len=*), intent(in) :: what, keys
        type(value_t), intent(in) :: args(:), kwargs
        type(status_t), intent(inout) :: st
        if (size(args) < lo .or. size(args) > hi) then
            if (lo == hi) then
                call fail(st, ctx, id, what // '() takes ' // to_text(lo) // ' argument(s), ' &
                          // 'got ' // to_text(size(args)))
            else
                call fail(st, ctx, id, what // '() takes ' // to_text(lo) // ' to ' // &
                          to_text(hi) // ' arguments, got ' // to_text(size(args)))
            end if
            return
        end if
        call only_kwargs(ctx, id, what // '()', kwargs, keys, st)
    end subroutine arity

    !> Error unless v is a string (named `what` in the message).
    logical function want_text(ctx, id, v, what, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: v
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        want_text = v%kind == VK_STR
        if (.not. want_text) call fail(st, ctx, id, what // ' takes a string, got ' // &
                                       kind_label(v))
    end function want_text

    ! ---- strings ----------------------------------------------------------------------------

    recursive subroutine str_method(ctx, id, s, name, args, kwargs, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: s, name
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
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
    end subroutine str_method

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

    !> template.format(*args, **kwargs): fields {}, {0}, {name}, with [key] and .attr after
    !> the name, !r !s !a conversions and a format spec (itself with fields inside).
    recursive subroutine str_format(ctx, id, template, args, kwargs, text, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: template
        type(value_t), intent(in) :: args(:), kwargs
        character(len=:), allocatable, intent(out) :: text
        type(status_t), intent(inout) :: st
        integer :: auto
        auto = 0
        call expand(template, text, 0)
    contains
        recursive subroutine expand(t, out, depth)
            character(len=*), intent(in) :: t
            character(len=:), allocatable, intent(out) :: out
            integer, intent(in) :: depth
            integer :: i, j, nest, bang, colon
            character(len=:), allocatable :: field, spec, piece, conv
            type(value_t) :: x
            out = ''
            if (depth > 2) then
                call fail(st, ctx, id, 'str.format(): fields nested too deeply'); return
            end if
            i = 1
            do while (i <= len(t))
                if (t(i:i) == '{') then
                    if (i < len(t)) then
                        if (t(i + 1:i + 1) == '{') then
                            out = out // '{'; i = i + 2; cycle
                        end if
                    end if
                    nest = 0; j = i + 1
                    do while (j <= len(t))
                        if (t(j:j) == '{') nest = nest + 1
                        if (t(j:j) == '}') then
                            if (nest == 0) exit
                            nest = nest - 1
                        end if
                        j = j + 1
                    end do
                    if (j > len(t)) then
                        call fail(st, ctx, id, 'str.format(): "{" without its "}"'); return
                    end if
                    field = t(i + 1:j - 1)
                    colon = index(field, ':')
                    spec = ''
                    if (colon > 0) then
                        spec = field(colon + 1:)
                        field = field(1:colon - 1)
                    end if
                    bang = index(field, '!')
                    conv = ''
                    if (bang > 0) then
                        conv = field(bang + 1:)
                        field = field(1:bang - 1)
                        if (conv /= 'r' .and. conv /= 's' .and. conv /= 'a') then
                            call fail(st, ctx, id, 'str.format(): a conversion is !r, !s or ' &
                                      // '!a'); return
                        end if
                    end if
                    call resolve(field, x)
                    if (st%failed()) return
                    if (conv == 'r' .or. conv == 'a') x = str_value(text_of(ctx, x, .true.))
                    if (conv == 's') x = str_value(text_of(ctx, x, .false.))
                    if (index(spec, '{') > 0) then
                        call expand(spec, piece, depth + 1)
                        if (st%failed()) return
                        spec = piece
                    end if
                    call format_value(ctx, id, x, spec, piece, st)
                    if (st%failed()) return
                    out = out // piece
                    if (len(out) > MAX_REPEAT) then
                        call fail(st, ctx, id, 'string too long (more than ' // &
                                  to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
                    end if
                    i = j + 1
                else if (t(i:i) == '}') then
                    if (i < len(t)) then
                        if (t(i + 1:i + 1) == '}') then
                            out = out // '}'; i = i + 2; cycle
                        end if
                    end if
                    call fail(st, ctx, id, 'str.format(): single "}" (write "}}" for a brace)')
                    return
                else
                    out = out // t(i:i); i = i + 1
                end if
            end do
        end subroutine expand

        !> The value a field name stands for: '' (next positional), N, NAME, then .attr
        !> and [key] accessors.
        recursive subroutine resolve(field, x)
            character(len=*), intent(in) :: field
            type(value_t), intent(out) :: x
            integer :: j, n, ios
            character(len=:), allocatable :: first, rest, key
            integer(i8) :: k
            logical :: found
            type(value_t) :: y
            j = scan(field, '.[')
            if (j == 0) j = len(field) + 1
            first = field(1:j - 1)
            rest = field(j:)
            if (len(first) == 0) then
                auto = auto + 1
                if (auto > size(args)) then
                    call fail(st, ctx, id, 'str.format(): more {} fields than arguments (' // &
                              to_text(size(args)) // ')'); return
                end if
                x = args(auto)
            else if (verify(first, '0123456789') == 0) then
                read (first, *, iostat=ios) n
                if (ios /= 0 .or. n + 1 > size(args)) then
                    call fail(st, ctx, id, 'str.format(): no argument {' // first // '} (' // &
                              to_text(size(args)) // ' given)'); return
                end if
                x = args(n + 1)
            else
                call kwarg(kwargs, first, x, found)
                if (.not. found) then
                    call fail(st, ctx, id, 'str.format(): no keyword argument ' // first)
                    return
                end if
            end if
            do while (len(rest) > 0)
                if (rest(1:1) == '.') then
                    j = scan(rest(2:), '.[')
                    if (j == 0) j = len(rest)
                    key = rest(2:j)
                    rest = rest(j + 1:)
                    y = x
                    call get_attribute(ctx, id, y, key, x, st)
                else
                    j = index(rest, ']')
                    if (j == 0) then
                        call fail(st, ctx, id, 'str.format(): "[" without "]"'); return
                    end if
                    key = rest(2:j - 1)
                    rest = rest(j + 1:)
                    if (len(key) > 0 .and. verify(key, '0123456789') == 0) then
                        read (key, *, iostat=ios) k
                        y = x
                        call get_item(ctx, id, y, int_value(k), x, st)
                    else
                        y = x
                        call get_item(ctx, id, y, str_value(key), x, st)
                    end if
                end if
                if (st%failed()) return
            end do
        end subroutine resolve
    end subroutine str_format

    !> template % arg: Python's printf-style formatting (conversions d i u o x X e E f F g
    !> G c s r a %, flags - + space 0 #, width and precision, %(name)s with a dict).
    module procedure percent_format
        type(value_t), allocatable :: values(:)
        type(value_t) :: x
        type(format_spec_t) :: spec
        character(len=:), allocatable :: piece, message, key
        integer :: i, j, next
        logical :: mapping
        character :: conv
        text = ''
        mapping = arg%kind == VK_DICT .or. arg%kind == VK_FACTOR
        if (arg%kind == VK_TUPLE) then
            call iterate(ctx, id, arg, values, st)
        else
            values = values_of(arg)
        end if
        next = 0
        i = 1
        do while (i <= len(template))
            if (template(i:i) /= '%') then
                j = index(template(i:), '%')
                if (j == 0) then
                    text = text // template(i:); exit
                end if
                text = text // template(i:i + j - 2)
                i = i + j - 1
                cycle
            end if
            i = i + 1
            if (i > len(template)) then
                call fail(st, ctx, id, 'incomplete format: the string ends with "%"'); return
            end if
            spec = format_spec_t()
            key = ''
            if (template(i:i) == '(') then                 ! %(name)s
                j = index(template(i:), ')')
                if (j == 0) then
                    call fail(st, ctx, id, 'incomplete format key: "%(" without ")"'); return
                end if
                key = template(i + 1:i + j - 2)
                i = i + j
            end if
            do while (i <= len(template))                  ! flags
                select case (template(i:i))
                case ('-')
                    spec%align = '<'
                case ('+')
                    spec%sign = '+'
                case (' ')
                    if (spec%sign /= '+') spec%sign = ' '
                case ('0')
                    spec%zero = .true.
                case ('#')
                    spec%alternate = .true.
                case default
                    exit
                end select
                i = i + 1
            end do
            call number_at(spec%width)
            if (i <= len(template)) then
                if (template(i:i) == '.') then
                    i = i + 1
                    spec%precision = 0
                    call number_at(spec%precision)
                end if
            end if
            do while (i <= len(template))                  ! length modifiers: ignored
                if (index('hlL', template(i:i)) == 0) exit
                i = i + 1
            end do
            if (st%failed()) return
            if (i > len(template)) then
                call fail(st, ctx, id, 'incomplete format after "%"'); return
            end if
            conv = template(i:i)
            i = i + 1
            if (conv == '%') then
                text = text // '%'; cycle
            end if
            if (spec%align == '<') spec%zero = .false.
            if (len(key) > 0) then
                if (.not. mapping) then
                    call fail(st, ctx, id, 'format %(' // key // ')' // conv // ' needs a ' // &
                              'dict after %'); return
                end if
                call get_item(ctx, id, arg, str_value(key), x, st)
                if (st%failed()) return
            else
                next = next + 1
                if (next > size(values)) then
                    call fail(st, ctx, id, 'not enough arguments for the format string (' // &
                              to_text(size(values)) // ' given)'); return
                end if
                x = values(next)
            end if
            call convert(x, conv, piece)
            if (st%failed()) return
            text = text // piece
            if (len(text) > MAX_REPEAT) then
                call fail(st, ctx, id, 'string too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
            end if
        end do
        if (.not. mapping .and. next < size(values)) then
            call fail(st, ctx, id, 'not all arguments converted during string formatting (' &
                      // to_text(size(values)) // ' given, ' // to_text(next) // ' used)')
        end if
    contains
        subroutine number_at(n)
            integer, intent(inout) :: n
            integer :: start, ios
            start = i
            if (i <= len(template)) then
                if (template(i:i) == '*') then
                    call fail(st, ctx, id, '"*" widths are not part of the deck language ' // &
                              '(write the number)'); return
                end if
            end if
            do while (i <= len(template))
                if (index('0123456789', template(i:i)) == 0) exit
                i = i + 1
            end do
            if (i == start) return
            if (i - start > 5) then
                call fail(st, ctx, id, 'format width or precision too large'); return
            end if
            read (template(start:i - 1), *, iostat=ios) n
        end subroutine number_at

        subroutine convert(x0, c, out)
            type(value_t), intent(in) :: x0
            character, intent(in) :: c
            character(len=:), allocatable, intent(out) :: out
            type(format_spec_t) :: s2
            character(len=:), allocatable :: digits
            s2 = spec
            out = ''
            select case (c)
            case ('d', 'i', 'u')
                if (.not. is_number(x0)) then
                    call fail(st, ctx, id, '%' // c // ' format: a number is required, not ' // &
                              kind_label(x0)); return
                end if
                s2%type = 'd'; s2%alternate = .false.
                if (x0%kind == VK_REAL) then
                    if (.not. (abs(x0%r) < 9.2e18_dp)) then
                        call fail(st, ctx, id, '%d of a real beyond the integer range'); return
                    end if
                    call int_with_precision(int(x0%r, i8), s2, out)
                else
                    call int_with_precision(x0%i, s2, out)
                end if
            case ('o', 'x', 'X')
                if (x0%kind /= VK_INT .and. x0%kind /= VK_BOOL) then
                    call fail(st, ctx, id, '%' // c // ' format: an integer is required, not ' &
                              // kind_label(x0)); return
                end if
                s2%type = c
                call format_int(x0%i, s2, out, message)
            case ('e', 'E', 'f', 'F', 'g', 'G')
                if (.not. is_number(x0)) then
                    call fail(st, ctx, id, '%' // c // ' format: a number is required, not ' // &
                              kind_label(x0)); return
                end if
                s2%type = c
                call format_real(as_real(x0), s2, out, message)
            case ('c')
                if (x0%kind == VK_STR) then
                    if (len(x0%s) /= 1) then
                        call fail(st, ctx, id, '%c takes one character'); return
                    end if
                    s2%type = ' '; s2%precision = -1
                    call format_text(x0%s, s2, out, message)
                else if (x0%kind == VK_INT) then
                    s2%type = 'c'
                    call format_int(x0%i, s2, out, message)
                else
                    call fail(st, ctx, id, '%c takes an integer or one character'); return
                end if
            case ('s', 'r', 'a')
                digits = text_of(ctx, x0, c /= 's')
                s2%type = ' '; s2%sign = '-'; s2%zero = .false.; s2%alternate = .false.
                call format_text(digits, s2, out, message)
            case default
                call fail(st, ctx, id, 'unsupported format character ''' // c // ''''); return
            end select
            if (allocated(message)) then
                if (len(message) > 0) call fail(st, ctx, id, message)
            end if
        end subroutine convert

        !> %.3d: at least 3 digits.
        subroutine int_with_precision(n, s2, out)
            integer(i8), intent(in) :: n
            type(format_spec_t), intent(in) :: s2
            character(len=:), allocatable, intent(out) :: out
            type(format_spec_t) :: s3
            character(len=:), allocatable :: digits
            s3 = s2
            s3%precision = -1
            if (s2%precision > 0) then
                s3%width = 0; s3%align = ' '; s3%zero = .false.; s3%sign = '-'
                call format_int(abs(n), s3, digits, message)
                if (len(digits) < s2%precision) digits = repeat('0', s2%precision - &
                                                                len(digits)) // digits
                if (n < 0) then
                    digits = '-' // digits
                else if (s2%sign == '+') then
                    digits = '+' // digits
                else if (s2%sign == ' ') then
                    digits = ' ' // digits
                end if
                s3 = s2; s3%precision = -1; s3%zero = .false.
                out = pad(digits, s3, '>')
                message = ''
            else
                call format_int(n, s3, out, message)
            end if
        end subroutine int_with_precision
    end procedure percent_format

    ! ---- lists ------------------------------------------------------------------------------

    recursive subroutine list_method(ctx, id, obj, name, args, kwargs, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t), allocatable :: items(:)
        character(len=:), allocatable :: what
        integer :: n, k
        integer(i8) :: i
        what = 'list.' // name
        v%kind = VK_NONE
        n = ctx%heap%length(obj%i)
        select case (name)
        case ('append')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            call ctx%heap%append(obj%i, args(1))
            call check_heap(ctx, id, st)
        case ('extend')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            if (args(1)%kind == VK_UNKNOWN) return
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            call count_built(ctx, id, int(size(items), i8), st)
            do k = 1, size(items)
                call ctx%heap%append(obj%i, items(k))
            end do
            call check_heap(ctx, id, st)
        case ('insert')
            call arity(ctx, id, what, args, kwargs, 2, 2, '', st)
            if (st%failed()) return
            if (args(1)%kind /= VK_INT .and. args(1)%kind /= VK_BOOL) then
                call fail(st, ctx, id, what // '() takes an integer position'); return
            end if
            i = args(1)%i
            if (i < 0) i = max(0_i8, i + n)
            i = min(i, int(n, i8))
            call ctx%heap%insert(obj%i, int(i) + 1, args(2))
            call check_heap(ctx, id, st)
        case ('pop')
            call arity(ctx, id, what, args, kwargs, 0, 1, '', st)
            if (st%failed()) return
            if (n == 0) then
                call fail(st, ctx, id, 'pop from an empty list'); return
            end if
            i = -1
            if (size(args) == 1) then
                if (args(1)%kind /= VK_INT .and. args(1)%kind /= VK_BOOL) then
                    call fail(st, ctx, id, what // '() takes an integer position'); return
                end if
                i = args(1)%i
            end if
            call get_item(ctx, id, obj, int_value(i), v, st)
            if (st%failed()) return
            if (i < 0) i = i + n
            call ctx%heap%remove_at(obj%i, int(i) + 1)
        case ('remove')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            do k = 1, n
                if (values_equal(ctx, ctx%heap%get(obj%i, k), args(1))) then
                    call ctx%heap%remove_at(obj%i, k)
                    return
                end if
            end do
            call fail(st, ctx, id, what // '(x): x not in the list (x = ' // &
                      text_of(ctx, args(1), .true.) // ')')
        case ('index', 'count')
            call sequence_search(ctx, id, obj, name, args, v, st)
        case ('reverse')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            items = ctx%heap%items_of(obj%i)
            call ctx%heap%set_items(obj%i, items(size(items):1:-1))
        case ('sort')
            call arity(ctx, id, what, args, kwargs, 0, 0, 'key reverse', st)
            if (st%failed()) return
            items = ctx%heap%items_of(obj%i)
            call sort_items(ctx, id, items, kwargs, st, frame)
            if (st%failed()) return
            call ctx%heap%set_items(obj%i, items)
        case ('copy')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            call count_built(ctx, id, int(n, i8), st)
            v = new_list(ctx, ctx%heap%items_of(obj%i))
            call check_heap(ctx, id, st)
        case ('clear')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            call ctx%heap%clear(obj%i)
        end select
    end subroutine list_method

    !> index(x) and count(x) of a list or a tuple.
    recursive subroutine sequence_search(ctx, id, obj, name, args, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: items(:)
        integer :: k, hits
        if (size(args) /= 1) then
            call fail(st, ctx, id, name // '() takes 1 argument, got ' // to_text(size(args)))
            return
        end if
        if (args(1)%kind == VK_UNKNOWN) then
            v = args(1); return
        end if
        call iterate(ctx, id, obj, items, st)
        if (st%failed()) return
        hits = 0
        do k = 1, size(items)
            if (.not. values_equal(ctx, items(k), args(1))) cycle
            if (name == 'index') then
                v = int_value(int(k - 1, i8)); return
            end if
            hits = hits + 1
        end do
        if (name == 'index') then
            call fail(st, ctx, id, text_of(ctx, args(1), .true.) // ' is not in the ' // &
                      merge('list ', 'tuple', obj%kind == VK_LIST)); return
        end if
        v = int_value(int(hits, i8))
    end subroutine sequence_search

    ! ---- dicts ------------------------------------------------------------------------------

    recursive subroutine dict_method(ctx, id, obj, name, args, kwargs, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: keys(:), vals(:), pairs(:), items(:), pair(:)
        type(value_list_t) :: kw
        character(len=:), allocatable :: what
        integer :: k, n
        what = 'dict.' // name
        v%kind = VK_NONE
        n = ctx%heap%length(obj%i)
        select case (name)
        case ('keys', 'values', 'items')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            keys = ctx%heap%keys_of(obj%i)
            vals = ctx%heap%items_of(obj%i)
            if (name == 'keys') then
                v = new_list(ctx, keys)
            else if (name == 'values') then
                v = new_list(ctx, vals)
            else
                allocate (pairs(n))
                do k = 1, n
                    pairs(k) = sequence_value(VK_TUPLE, values_of(keys(k), vals(k)))
                end do
                v = new_list(ctx, pairs)
            end if
            call count_built(ctx, id, int(n, i8), st)
            call check_heap(ctx, id, st)
        case ('get', 'pop', 'setdefault')
            call arity(ctx, id, what, args, kwargs, 1, 2, '', st)
            if (st%failed()) return
            if (args(1)%kind == VK_UNKNOWN) then
                v = args(1); return
            end if
            if (.not. hashable_key(args(1))) return
            k = ctx%heap%dict_find(obj%i, args(1))
            if (k > 0) then
                v = ctx%heap%get(obj%i, k)
                if (name == 'pop') call ctx%heap%dict_delete(obj%i, k)
                return
            end if
            if (size(args) == 2) v = args(2)
            if (name == 'pop' .and. size(args) == 1) then
                call get_item(ctx, id, obj, args(1), v, st)     ! the KeyError message
                return
            end if
            if (name == 'setdefault') then
                call ctx%heap%dict_set(obj%i, args(1), v)
                call check_heap(ctx, id, st)
            end if
        case ('update')
            call arity(ctx, id, what, args, kwargs, 0, 1, '*', st)
            if (st%failed()) return
            if (size(args) == 1) then
                select case (args(1)%kind)
                case (VK_DICT)
                    keys = ctx%heap%keys_of(args(1)%i)
                    vals = ctx%heap%items_of(args(1)%i)
                    do k = 1, size(keys)
                        call ctx%heap%dict_set(obj%i, keys(k), vals(k))
                    end do
                case (VK_FACTOR)
                    kw = unpack_value(args(1))
                    do k = 1, size(kw%items)
                        call ctx%heap%dict_set(obj%i, str_value(kw%keys(k)%s), kw%items(k))
                    end do
                case default
                    call iterate(ctx, id, args(1), items, st)
                    if (st%failed()) return
                    do k = 1, size(items)
                        call iterate(ctx, id, items(k), pair, st)
                        if (st%failed()) return
                        if (size(pair) /= 2) then
                            call fail(st, ctx, id, what // '() takes pairs (KEY, VALUE)'); return
                        end if
                        if (.not. hashable_key(pair(1))) return
                        call ctx%heap%dict_set(obj%i, pair(1), pair(2))
                    end do
                end select
            end if
            if (nitems(kwargs) > 0) then
                kw = unpack_value(kwargs)
                do k = 1, size(kw%items)
                    call ctx%heap%dict_set(obj%i, str_value(kw%keys(k)%s), kw%items(k))
                end do
            end if
            call check_heap(ctx, id, st)
        case ('copy')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            v = ctx%heap%new_dict()
            keys = ctx%heap%keys_of(obj%i)
            vals = ctx%heap%items_of(obj%i)
            do k = 1, size(keys)
                call ctx%heap%dict_set(v%i, keys(k), vals(k))
            end do
            call check_heap(ctx, id, st)
        case ('clear')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            call ctx%heap%clear(obj%i)
        case ('popitem')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            if (n == 0) then
                call fail(st, ctx, id, 'popitem(): the dict is empty'); return
            end if
            v = sequence_value(VK_TUPLE, values_of(ctx%heap%key_at(obj%i, n), ctx%heap%get(obj%i, n)))
            call ctx%heap%dict_delete(obj%i, n)
        end select
    contains
        logical function hashable_key(key)
            use deck_heap, only: hashable
            type(value_t), intent(in) :: key
            hashable_key = hashable(key)
            if (.not. hashable_key) call fail(st, ctx, id, kind_label(key) // &
                ' cannot be a dict key (keys are numbers, strings, tuples of them...)')
        end function hashable_key
    end subroutine dict_method

    !> keys(), values(), items(), get(), copy() of a _F (Code_Aster's _F is a dict).
    recursive subroutine factor_method(ctx, id, obj, name, args, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_list_t) :: list
        type(value_t), allocatable :: out(:)
        integer :: k, n
        list = unpack_value(obj)
        n = nitems(obj)
        select case (name)
        case ('keys', 'values', 'items')
            allocate (out(n))
            do k = 1, n
                if (name == 'keys') out(k) = str_value(list%keys(k)%s)
                if (name == 'values') out(k) = list%items(k)
                if (name == 'items') out(k) = sequence_value(VK_TUPLE, &
                    values_of(str_value(list%keys(k)%s), list%items(k)))
            end do
            v = new_list(ctx, out)
            call check_heap(ctx, id, st)
        case ('get')
            if (size(args) < 1 .or. size(args) > 2) then
                call fail(st, ctx, id, 'get() takes 1 or 2 arguments'); return
            end if
            v%kind = VK_NONE
            if (size(args) == 2) v = args(2)
            if (args(1)%kind /= VK_STR) return
            do k = 1, n
                if (list%keys(k)%s == args(1)%s) v = list%items(k)
            end do
        case ('copy')
            v = ctx%heap%new_dict()
            do k = 1, n
                call ctx%heap%dict_set(v%i, str_value(list%keys(k)%s), list%items(k))
            end do
            call check_heap(ctx, id, st)
        end select
    end subroutine factor_method

end submodule deck_interp_types

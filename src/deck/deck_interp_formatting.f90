!> The deck evaluator (deck_interpreter), the formatting of strings: str.format (fields {},
!> {0}, {name}, [key] and .attr accessors, conversions, nested specs) and the % operator
!> (printf-style conversions, flags, width, precision, %(name)s with a dict), on the format
!> mini-language of deck_format.
submodule(deck_interpreter) deck_interp_formatting
    use deck_format, only: format_spec_t, format_real, format_int, format_text, pad
    implicit none

contains

    !> template.format(*args, **kwargs): fields {}, {0}, {name}, with [key] and .attr after
    !> the name, !r !s !a conversions and a format spec (itself with fields inside).
    module procedure str_format
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
    end procedure str_format

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

end submodule deck_interp_formatting

!> The deck evaluator (deck_interpreter), its built-in functions, as Python 3 defines them
!> for the values of the deck language: len str repr int float bool abs round min max sum
!> sorted reversed enumerate zip range list tuple dict any all map filter isinstance type
!> getattr hasattr divmod pow chr ord format print callable and the exceptions (for raise);
!> round and the math functions in deck_interp_math. Functions Python has and decks must
!> not use (open, eval, exec, input...) are refused by name.
submodule(deck_interpreter) deck_interp_builtins
    use deck_math, only: literal_out_of_range
    implicit none

    !> The built-ins of this submodule (deck_math's math functions come on top).
    character(len=*), parameter :: BUILTINS = ' len str repr int float bool abs round min ' // &
        'max sum sorted reversed enumerate zip range list tuple dict any all map filter ' // &
        'isinstance type getattr hasattr divmod pow chr ord format print callable ' // &
        'Exception ValueError TypeError RuntimeError KeyError IndexError AssertionError ' // &
        'NotImplementedError ZeroDivisionError NameError open eval exec input set ' // &
        'frozenset iter next compile globals locals vars setattr delattr id hash complex ' // &
        'bytes object super CO '

contains

    module procedure is_builtin
        character(len=:), allocatable :: bare
        bare = name
        if (index(name, 'math.') == 1) then
            bare = name(6:)
            is_builtin = index(MATH_EXTRA, ' ' // bare // ' ') > 0
            return
        end if
        is_builtin = index(BUILTINS, ' ' // bare // ' ') > 0 .or. &
            index(MATH_EXTRA, ' ' // bare // ' ') > 0
    end procedure is_builtin

    module procedure call_builtin
        type(value_t), allocatable :: items(:)
        type(value_t) :: x, key
        character(len=:), allocatable :: text
        logical :: found
        integer :: k
        select case (name)
        case ('len')
            call want(1, 1, '')
            if (st%failed()) return
            call length_of(args(1))
        case ('str', 'repr')
            call want(0, 1, '')
            if (st%failed()) return
            if (size(args) == 0) then
                v = str_value('')
            else
                v = str_value(text_of(ctx, args(1), name == 'repr'))
            end if
        case ('int')
            call want(0, 2, '')
            if (st%failed()) return
            call to_int()
        case ('float')
            call want(0, 1, '')
            if (st%failed()) return
            call to_float()
        case ('bool')
            call want(0, 1, '')
            if (st%failed()) return
            v = bool_value(.false.)
            if (size(args) == 1) v = bool_value(is_true(ctx, args(1)))
        case ('abs')
            call want(1, 1, '')
            if (st%failed()) return
            call absolute()
        case ('round')
            call want(1, 2, '')
            if (st%failed()) return
            call round_value(ctx, id, args, v, st)
        case ('min', 'max')
            call extreme()
        case ('sum')
            call want(1, 2, 'start')
            if (st%failed()) return
            call sum_values()
        case ('sorted')
            call want(1, 1, 'key reverse')
            if (st%failed()) return
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            call sort_items(ctx, id, items, kwargs, st, frame)
            if (st%failed()) return
            call built(size(items))
            v = new_list(ctx, items)
        case ('reversed')
            call want(1, 1, '')
            if (st%failed()) return
            if (args(1)%kind == VK_DICT) then
                call fail(st, ctx, id, 'reversed() of a dict: use reversed(list(d))'); return
            end if
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            items = items(size(items):1:-1)
            call built(size(items))
            v = new_list(ctx, items)
        case ('enumerate')
            call want(1, 2, 'start')
            if (st%failed()) return
            call enumerate_items()
        case ('zip')
            call want(0, 1000, '')
            if (st%failed()) return
            call zip_items()
        case ('range')
            call range_value()
        case ('list', 'tuple')
            call want(0, 1, '')
            if (st%failed()) return
            allocate (items(0))
            if (size(args) == 1) call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            call built(size(items))
            if (name == 'list') then
                v = new_list(ctx, items)
            else
                v = sequence_value(VK_TUPLE, items)
            end if
        case ('dict')
            call want(0, 1, '*')
            if (st%failed()) return
            call make_dict()
        case ('any', 'all')
            call want(1, 1, '')
            if (st%failed()) return
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            found = name == 'all'
            do k = 1, size(items)
                if (is_true(ctx, items(k)) .neqv. (name == 'all')) then
                    found = .not. found; exit
                end if
            end do
            v = bool_value(found)
        case ('map', 'filter')
            call want(2, 1000, '')
            if (st%failed()) return
            call map_filter()
        case ('isinstance')
            call want(2, 2, '')
            if (st%failed()) return
            v = bool_value(instance_of(args(1), args(2)))
        case ('type')
            call want(1, 1, '')
            if (st%failed()) return
            v%kind = VK_BUILTIN
            v%s = type_name_of(args(1))
        case ('getattr', 'hasattr')
            call want(2, merge(3, 2, name == 'getattr'), '')
            if (st%failed()) return
            call attribute_of()
        case ('divmod')
            call want(2, 2, '')
            if (st%failed()) return
            call binary(ctx, id, '//', args(1), args(2), x, st)
            if (st%failed()) return
            call binary(ctx, id, '%', args(1), args(2), key, st)
            if (st%failed()) return
            v = sequence_value(VK_TUPLE, values_of(x, key))
        case ('pow')
            call want(2, 2, '')
            if (st%failed()) return
            call binary(ctx, id, '**', args(1), args(2), v, st)
        case ('chr')
            call want(1, 1, '')
            if (st%failed()) return
            if (args(1)%kind /= VK_INT .or. args(1)%i < 0 .or. args(1)%i > 127) then
                call fail(st, ctx, id, 'chr() takes a character code 0..127 (ASCII)'); return
            end if
            v = str_value(achar(int(args(1)%i)))
        case ('ord')
            call want(1, 1, '')
            if (st%failed()) return
            if (args(1)%kind /= VK_STR) then
                call fail(st, ctx, id, 'ord() takes a string of one character'); return
            end if
            if (len(args(1)%s) /= 1) then
                call fail(st, ctx, id, 'ord() takes a string of one (ASCII) character'); return
            end if
            v = int_value(int(iachar(args(1)%s), i8))
        case ('format')
            call want(1, 2, '')
            if (st%failed()) return
            text = ''
            if (size(args) == 2) then
                if (args(2)%kind /= VK_STR) then
                    call fail(st, ctx, id, 'format() takes a format spec string'); return
                end if
                text = args(2)%s
            end if
            call format_value(ctx, id, args(1), text, key%s, st)
            if (st%ok()) v = str_value(key%s)
        case ('print')
            call want(0, 100000, 'sep end file flush')
            if (st%failed()) return
            call print_values()
        case ('CO')
            ! CO('NAME'): the name of a concept a command makes besides its result
            call want(1, 1, '')
            if (st%failed()) return
            if (args(1)%kind /= VK_STR) then
                call fail(st, ctx, id, 'CO() takes the name of the concept to make, a ' // &
                          'string'); return
            end if
            if (.not. identifier(args(1)%s)) then
                call fail(st, ctx, id, 'CO(''' // args(1)%s // '''): a concept name is a ' // &
                          'Python name (letters, digits, _; not starting with a digit)'); return
            end if
            v%kind = VK_CO
            v%s = args(1)%s
            v%line = ctx%ast%nodes(id)%line; v%col = ctx%ast%nodes(id)%col
        case ('Cata.SIMP', 'Cata.FACT', 'Cata.MACRO', 'Cata.UserMacro', 'Cata.EXCLUS', &
              'Cata.UN_PARMI', 'Cata.AU_MOINS_UN', 'Cata.PRESENT_PRESENT', &
              'Cata.PRESENT_ABSENT', 'Cata.ENSEMBLE')
            call cata_builtin(ctx, id, name, args, kwargs, v, st)   ! user macros
        case ('MedUtils.splitMeshAndFieldsFromMedFile')
            call split_med_file(ctx, id, args, kwargs, v, st)   ! deck_interp_medutils
        case ('TestCase')
            call new_testcase(ctx, id, args, kwargs, v, st)     ! CA.TestCase()
        case ('callable')
            call want(1, 1, '')
            if (st%failed()) return
            v = bool_value(any(args(1)%kind == [VK_DEF, VK_BUILTIN, VK_METHOD]) .or. &
                           args(1)%kind == VK_CONCEPT)
        case ('Exception', 'ValueError', 'TypeError', 'RuntimeError', 'KeyError', &
              'IndexError', 'AssertionError', 'NotImplementedError', 'ZeroDivisionError', &
              'NameError')
            text = name
            if (size(args) > 0) text = name // ': ' // text_of(ctx, args(1), .false.)
            v = str_value(text)
        case ('open', 'eval', 'exec', 'input', 'compile', 'globals', 'locals', 'vars', &
              'setattr', 'delattr', 'id', 'hash', 'iter', 'next', 'object', 'super', 'bytes', &
              'complex')
            call fail(st, ctx, id, name // '() is not part of the deck language')
        case ('set', 'frozenset')
            call fail(st, ctx, id, name // '() is not part of the deck language (sets; a ' // &
                      'list or the keys of a dict can stand for one)')
        case default
            call call_math(ctx, id, name, args, kwargs, v, st)
        end select
    contains
        !> Between lo and hi positional arguments; keyword arguments among `keys`
        !> (blank-separated; '*' any).
        subroutine want(lo, hi, keys)
            integer, intent(in) :: lo, hi
            character(len=*), intent(in) :: keys
            if (size(args) < lo .or. size(args) > hi) then
                if (lo == hi) then
                    call fail(st, ctx, id, name // '() takes ' // to_text(lo) // &
                        ' argument(s), got ' // to_text(size(args)))
                else if (hi >= 1000) then
                    call fail(st, ctx, id, name // '() takes at least ' // to_text(lo) // &
                        ' argument(s), got ' // to_text(size(args)))
                else
                    call fail(st, ctx, id, name // '() takes ' // to_text(lo) // ' to ' // &
                        to_text(hi) // ' arguments, got ' // to_text(size(args)))
                end if
                return
            end if
            if (keys /= '*') call only_kwargs(ctx, id, name // '()', kwargs, keys, st)
        end subroutine want

        subroutine built(n)
            integer, intent(in) :: n
            call count_built(ctx, id, int(n, i8), st)
        end subroutine built

        subroutine length_of(x0)
            type(value_t), intent(in) :: x0
            type(value_t), allocatable :: none(:), chars(:)
            select case (x0%kind)
            case (VK_LIST, VK_DICT)
                v = int_value(int(ctx%heap%length(x0%i), i8))
            case (VK_TUPLE, VK_FACTOR)
                v = int_value(int(nitems(x0), i8))
            case (VK_STR)
                call iterate(ctx, id, x0, chars, st)
                v = int_value(int(size(chars), i8))
            case (VK_CONCEPT)
                allocate (none(0))
                call use_attribute(ctx, id, x0, '__len__', .true., none, empty_kwargs(), v, st)
            case default
                call fail(st, ctx, id, 'len() needs a list, a tuple, a dict or a string, got ' &
                          // kind_label(x0))
            end select
        end subroutine length_of

        !> int(x): a real truncated toward zero, a string of digits (in a base).
        subroutine to_int()
            integer(i8) :: base, r, digit
            character(len=:), allocatable :: s
            integer :: j
            logical :: negative
            if (size(args) == 0) then
                v = int_value(0_i8); return
            end if
            select case (args(1)%kind)
            case (VK_INT, VK_BOOL)
                if (size(args) == 2) then
                    call fail(st, ctx, id, 'int() with a base takes a string'); return
                end if
                v = int_value(args(1)%i)
            case (VK_REAL)
                if (size(args) == 2) then
                    call fail(st, ctx, id, 'int() with a base takes a string'); return
                end if
                if (.not. (abs(args(1)%r) < 9.2e18_dp)) then
                    call fail(st, ctx, id, 'int() of ' // text_of(ctx, args(1), .true.) // &
                              ' is beyond the integer range'); return
                end if
                v = int_value(int(args(1)%r, i8))
            case (VK_STR)
                base = 10
                if (size(args) == 2) then
                    if (args(2)%kind /= VK_INT .or. args(2)%i < 2 .or. args(2)%i > 36) then
                        call fail(st, ctx, id, 'int() base must be 2 to 36'); return
                    end if
                    base = args(2)%i
                end if
                s = trim(adjustl(args(1)%s))
                negative = .false.
                if (len(s) > 0) then
                    if (s(1:1) == '-' .or. s(1:1) == '+') then
                        negative = s(1:1) == '-'
                        s = s(2:)
                    end if
                end if
                r = 0
                do j = 1, len(s)
                    digit = index('0123456789abcdefghijklmnopqrstuvwxyz', &
                                  to_lower_char(s(j:j))) - 1
                    if (digit < 0 .or. digit >= base) exit
                    if (real(r, dp) * real(base, dp) + real(digit, dp) > 9.2e18_dp) then
                        call fail(st, ctx, id, 'int(''' // args(1)%s // ''') is beyond ' // &
                                  'the integer range'); return
                    end if
                    r = r * base + digit
                end do
                if (len(s) == 0 .or. j <= len(s)) then
                    call fail(st, ctx, id, 'invalid literal for int() with base ' // &
                        to_text(base) // ': ''' // args(1)%s // ''''); return
                end if
                if (negative) r = -r
                v = int_value(r)
            case default
                call fail(st, ctx, id, 'int() takes a number or a string, got ' // &
                          kind_label(args(1)))
            end select
        end subroutine to_int

        pure logical function identifier(text)
            character(len=*), intent(in) :: text
            identifier = len(text) > 0
            if (.not. identifier) return
            identifier = verify(text, 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ' // &
                '0123456789_') == 0 .and. index('0123456789', text(1:1)) == 0
        end function identifier

        pure function to_lower_char(c) result(l)
            character, intent(in) :: c
            character :: l
            l = c
            if (c >= 'A' .and. c <= 'Z') l = achar(iachar(c) + 32)
        end function to_lower_char

        !> float(x): a number, or a string holding a decimal number (no nan, no inf: the
        !> deck language keeps every value finite).
        subroutine to_float()
            character(len=:), allocatable :: s
            real(dp) :: r
            integer :: ios
            if (size(args) == 0) then
                v = real_value(0.0_dp); return
            end if
            select case (args(1)%kind)
            case (VK_INT, VK_BOOL, VK_REAL)
                v = real_value(as_real(args(1)))
            case (VK_STR)
                s = trim(adjustl(args(1)%s))
                if (.not. decimal_number(s)) then
                    call fail(st, ctx, id, 'could not convert string to float: ''' // &
                              args(1)%s // ''' (a decimal number, e.g. ''2.5E+3'')'); return
                end if
                if (literal_out_of_range(unsigned(s))) then
                    call fail(st, ctx, id, 'float(''' // args(1)%s // ''') is beyond the ' // &
                              'largest real'); return
                end if
                read (s, *, iostat=ios) r
                if (ios /= 0) then
                    call fail(st, ctx, id, 'could not convert string to float: ''' // &
                              args(1)%s // ''''); return
                end if
                v = real_value(r)
            case default
                call fail(st, ctx, id, 'float() takes a number or a string, got ' // &
                          kind_label(args(1)))
            end select
        end subroutine to_float

        pure function unsigned(s) result(u)
            character(len=*), intent(in) :: s
            character(len=:), allocatable :: u
            u = s
            if (len(s) > 0) then
                if (s(1:1) == '-' .or. s(1:1) == '+') u = s(2:)
            end if
        end function unsigned

        !> [+-] digits [. digits] [(e|E) [+-] digits], at least one digit.
        pure logical function decimal_number(s)
            character(len=*), intent(in) :: s
            integer :: j, digits
            decimal_number = .false.
            j = 1; digits = 0
            if (len(s) == 0) return
            if (s(1:1) == '+' .or. s(1:1) == '-') j = 2
            do while (j <= len(s))
                if (index('0123456789', s(j:j)) == 0) exit
                j = j + 1; digits = digits + 1
            end do
            if (j <= len(s)) then
                if (s(j:j) == '.') then
                    j = j + 1
                    do while (j <= len(s))
                        if (index('0123456789', s(j:j)) == 0) exit
                        j = j + 1; digits = digits + 1
                    end do
                end if
            end if
            if (digits == 0) return
            if (j <= len(s)) then
                if (s(j:j) /= 'e' .and. s(j:j) /= 'E') return
                j = j + 1
                if (j <= len(s)) then
                    if (s(j:j) == '+' .or. s(j:j) == '-') j = j + 1
                end if
                digits = 0
                do while (j <= len(s))
                    if (index('0123456789', s(j:j)) == 0) exit
                    j = j + 1; digits = digits + 1
                end do
                if (digits == 0 .or. digits > 6) return
            end if
            decimal_number = j > len(s)
        end function decimal_number

        subroutine absolute()
            select case (args(1)%kind)
            case (VK_INT, VK_BOOL)
                if (args(1)%i == -huge(args(1)%i) - 1) then
                    call fail(st, ctx, id, 'integer overflow in abs()'); return
                end if
                v = int_value(abs(args(1)%i))
            case (VK_REAL)
                v = real_value(abs(args(1)%r))
            case default
                call fail(st, ctx, id, 'abs() takes a number, got ' // kind_label(args(1)))
            end select
        end subroutine absolute

        !> min(...) / max(...): of the arguments, or of one iterable; key= and default=.
        subroutine extreme()
            type(value_t), allocatable :: keys(:)
            type(value_t) :: kf, dflt
            logical :: has_key, has_default
            integer :: best, j, c
            call only_kwargs(ctx, id, name // '()', kwargs, 'key default', st)
            if (st%failed()) return
            call kwarg(kwargs, 'key', kf, has_key)
            call kwarg(kwargs, 'default', dflt, has_default)
            if (has_key) has_key = kf%kind /= VK_NONE
            if (size(args) == 0) then
                call fail(st, ctx, id, name // '() takes at least one argument'); return
            end if
            if (size(args) == 1) then
                call iterate(ctx, id, args(1), items, st)
                if (st%failed()) return
            else
                items = args
            end if
            if (size(items) == 0) then
                if (has_default) then
                    v = dflt; return
                end if
                call fail(st, ctx, id, name // '() of an empty sequence'); return
            end if
            allocate (keys(size(items)))
            do j = 1, size(items)
                if (has_key) then
                    call call_value(ctx, id, kf, values_of(items(j)), empty_kwargs(), keys(j), st, frame)
                    if (st%failed()) return
                else
                    keys(j) = items(j)
                end if
            end do
            best = 1
            do j = 2, size(items)
                call order(ctx, id, keys(j), keys(best), c, st)
                if (st%failed()) return
                if ((name == 'min' .and. c < 0) .or. (name == 'max' .and. c > 0)) best = j
            end do
            v = items(best)
        end subroutine extreme

        subroutine sum_values()
            type(value_t) :: total, s
            integer :: j
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            total = int_value(0_i8)
            call kwarg(kwargs, 'start', s, found)
            if (found) total = s
            if (size(args) == 2) total = args(2)
            if (total%kind == VK_STR) then
                call fail(st, ctx, id, 'sum() cannot add strings: use ''''.join(...)'); return
            end if
            do j = 1, size(items)
                call binary(ctx, id, '+', total, items(j), s, st)
                if (st%failed()) return
                total = s
            end do
            v = total
        end subroutine sum_values

        subroutine enumerate_items()
            type(value_t) :: s
            type(value_t), allocatable :: pairs(:)
            integer(i8) :: start
            integer :: j
            start = 0
            call kwarg(kwargs, 'start', s, found)
            if (size(args) == 2) then
                s = args(2); found = .true.
            end if
            if (found) then
                if (s%kind /= VK_INT) then
                    call fail(st, ctx, id, 'enumerate() start must be an integer'); return
                end if
                start = s%i
            end if
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            allocate (pairs(size(items)))
            do j = 1, size(items)
                pairs(j) = sequence_value(VK_TUPLE, values_of(int_value(start + j - 1), items(j)))
            end do
            call built(size(items))
            v = new_list(ctx, pairs)
        end subroutine enumerate_items

        subroutine zip_items()
            type(value_t), allocatable :: tuples(:), row(:)
            type(value_list_t), allocatable :: columns(:)
            integer :: j, i, n
            allocate (columns(size(args)))
            n = huge(n)
            do i = 1, size(args)
                call iterate(ctx, id, args(i), columns(i)%items, st)
                if (st%failed()) return
                n = min(n, size(columns(i)%items))
            end do
            if (size(args) == 0) n = 0
            allocate (tuples(n), row(size(args)))
            do j = 1, n
                do i = 1, size(args)
                    row(i) = columns(i)%items(j)
                end do
                tuples(j) = sequence_value(VK_TUPLE, row)
            end do
            call built(n * size(args))
            v = new_list(ctx, tuples)
        end subroutine zip_items

        !> range(...) as a value (not the sequence of a for loop, which is counted): the
        !> tuple of its integers, at most MAX_REPEAT.
        subroutine range_value()
            use deck_sequence, only: range_steps
            integer(i8) :: b(3), step, count, j
            character(len=:), allocatable :: message
            type(value_t), allocatable :: ints(:)
            integer :: i
            call want(1, 3, '')
            if (st%failed()) return
            do i = 1, size(args)
                if (args(i)%kind /= VK_INT .and. args(i)%kind /= VK_BOOL) then
                    call fail(st, ctx, id, 'range() takes integers, got ' // &
                              kind_label(args(i)) // ' (use int(...))'); return
                end if
                b(i) = args(i)%i
            end do
            if (size(args) == 1) then
                b(2) = b(1); b(1) = 0
            end if
            step = 1
            if (size(args) == 3) step = b(3)
            call range_steps(b(1), b(2), step, count, message)
            if (len(message) > 0) then
                call fail(st, ctx, id, message); return
            end if
            if (count > MAX_REPEAT) then
                call fail(st, ctx, id, 'range() of more than ' // to_text(int(MAX_REPEAT, i4)) &
                    // ' values as a value (a for loop over range(...) has no such limit)')
                return
            end if
            call built(int(count))
            if (st%failed()) return
            allocate (ints(count))
            do j = 1, count
                ints(j) = int_value(b(1) + (j - 1) * step)
            end do
            v = sequence_value(VK_TUPLE, ints)
        end subroutine range_value

        !> dict(), dict(mapping), dict(iterable of pairs), dict(**kwargs).
        subroutine make_dict()
            type(value_t), allocatable :: pair(:), keys(:)
            type(value_list_t) :: kw
            integer :: j
            v = ctx%heap%new_dict()
            if (size(args) == 1) then
                select case (args(1)%kind)
                case (VK_DICT)
                    keys = ctx%heap%keys_of(args(1)%i)
                    do j = 1, size(keys)
                        call set_item(ctx, id, v, keys(j), ctx%heap%get(args(1)%i, j), st)
                    end do
                case (VK_FACTOR)
                    kw = unpack_value(args(1))
                    do j = 1, size(kw%items)
                        call set_item(ctx, id, v, str_value(kw%keys(j)%s), kw%items(j), st)
                    end do
                case default
                    call iterate(ctx, id, args(1), items, st)
                    if (st%failed()) return
                    do j = 1, size(items)
                        call iterate(ctx, id, items(j), pair, st)
                        if (st%failed()) return
                        if (size(pair) /= 2) then
                            call fail(st, ctx, id, 'dict() takes pairs (KEY, VALUE); item ' // &
                                to_text(j) // ' has ' // to_text(size(pair)) // ' value(s)')
                            return
                        end if
                        call set_item(ctx, id, v, pair(1), pair(2), st)
                        if (st%failed()) return
                    end do
                end select
            end if
            if (nitems(kwargs) > 0) then
                kw = unpack_value(kwargs)
                do j = 1, size(kw%items)
                    call set_item(ctx, id, v, str_value(kw%keys(j)%s), kw%items(j), st)
                end do
            end if
        end subroutine make_dict

        !> map(f, it...) and filter(f, it): lists.
        subroutine map_filter()
            type(value_t), allocatable :: out(:), row(:)
            type(value_list_t), allocatable :: columns(:)
            type(value_t) :: r
            integer :: j, i, n
            allocate (out(0))
            if (name == 'filter') then
                if (size(args) /= 2) then
                    call fail(st, ctx, id, 'filter() takes a function and one iterable'); return
                end if
                call iterate(ctx, id, args(2), items, st)
                if (st%failed()) return
                do j = 1, size(items)
                    if (args(1)%kind == VK_NONE) then
                        r = items(j)
                    else
                        call call_value(ctx, id, args(1), values_of(items(j)), empty_kwargs(), r, st, &
                                        frame)
                        if (st%failed()) return
                    end if
                    if (is_true(ctx, r)) call append_value(out, items(j))
                end do
            else
                allocate (columns(size(args) - 1))
                n = huge(n)
                do i = 2, size(args)
                    call iterate(ctx, id, args(i), columns(i - 1)%items, st)
                    if (st%failed()) return
                    n = min(n, size(columns(i - 1)%items))
                end do
                allocate (row(size(args) - 1))
                do j = 1, n
                    do i = 1, size(row)
                        row(i) = columns(i)%items(j)
                    end do
                    call call_value(ctx, id, args(1), row, empty_kwargs(), r, st, frame)
                    if (st%failed()) return
                    call append_value(out, r)
                end do
            end if
            call built(size(out))
            v = new_list(ctx, out)
        end subroutine map_filter

        !> isinstance(x, T) with T a built-in type (int, float, str, list, tuple, dict,
        !> bool) or a tuple of them.
        recursive logical function instance_of(x0, t) result(yes)
            type(value_t), intent(in) :: x0, t
            type(value_t), allocatable :: ts(:)
            integer :: j
            yes = .false.
            if (t%kind == VK_TUPLE) then
                call iterate(ctx, id, t, ts, st)
                do j = 1, size(ts)
                    if (instance_of(x0, ts(j))) yes = .true.
                end do
                return
            end if
            if (t%kind /= VK_BUILTIN) then
                call fail(st, ctx, id, 'isinstance() takes a built-in type (int, float, str, ' &
                          // 'list, tuple, dict, bool) or a tuple of them'); return
            end if
            yes = type_name_of(x0) == t%s
            if (t%s == 'int' .and. x0%kind == VK_BOOL) yes = .true.
        end function instance_of

        function type_name_of(x0) result(tn)
            type(value_t), intent(in) :: x0
            character(len=:), allocatable :: tn
            select case (x0%kind)
            case (VK_INT)
                tn = 'int'
            case (VK_REAL)
                tn = 'float'
            case (VK_BOOL)
                tn = 'bool'
            case (VK_STR)
                tn = 'str'
            case (VK_LIST)
                tn = 'list'
            case (VK_TUPLE)
                tn = 'tuple'
            case (VK_DICT, VK_FACTOR)
                tn = 'dict'
            case (VK_NONE)
                tn = 'NoneType'
            case (VK_DEF, VK_BUILTIN, VK_METHOD)
                tn = 'function'
            case (VK_CONCEPT)
                tn = x0%s
            case default
                tn = 'object'
            end select
        end function type_name_of

        !> getattr(obj, name[, default]) and hasattr(obj, name).
        subroutine attribute_of()
            type(status_t) :: ast
            if (args(2)%kind /= VK_STR) then
                call fail(st, ctx, id, name // '() takes the attribute name as a string'); return
            end if
            call get_attribute(ctx, id, args(1), args(2)%s, v, ast)
            if (name == 'hasattr') then
                v = bool_value(ast%ok())
            else if (ast%failed()) then
                if (size(args) == 3) then
                    v = args(3)
                else
                    st = ast
                end if
            end if
        end subroutine attribute_of

        !> print(*values, sep=' ', end='\n'): to the .mess, line by line.
        subroutine print_values()
            type(value_t) :: sep, fin, file
            character(len=:), allocatable :: s, e, line
            integer :: j, nl
            s = ' '; e = achar(10)
            call kwarg(kwargs, 'sep', sep, found)
            if (found .and. sep%kind == VK_STR) s = sep%s
            if (found .and. sep%kind /= VK_STR .and. sep%kind /= VK_NONE) then
                call fail(st, ctx, id, 'print() sep must be a string'); return
            end if
            call kwarg(kwargs, 'end', fin, found)
            if (found .and. fin%kind == VK_STR) e = fin%s
            if (found .and. fin%kind /= VK_STR .and. fin%kind /= VK_NONE) then
                call fail(st, ctx, id, 'print() end must be a string'); return
            end if
            call kwarg(kwargs, 'file', file, found)
            if (found .and. file%kind /= VK_NONE) then
                call fail(st, ctx, id, 'print() writes to the .mess: file= is not part of ' // &
                          'the deck language'); return
            end if
            line = ''
            do j = 1, size(args)
                if (j > 1) line = line // s
                line = line // text_of(ctx, args(j), .false.)
            end do
            line = ctx%print_line // line // e
            do
                nl = index(line, achar(10))
                if (nl == 0) exit
                call ctx%write_mess(line(1:nl - 1))
                line = line(nl + 1:)
            end do
            ctx%print_line = line
            v%kind = VK_NONE
        end subroutine print_values

    end procedure call_builtin

    !> Sorts items in place by Python's order (stable merge sort, O(n log n)): of key(item)
    !> with key=, descending with reverse=True (equal keys keep their order, as Python's).
    module procedure sort_items
        type(value_t) :: kf, rev
        type(value_t), allocatable :: keys(:), sorted(:)
        integer, allocatable :: perm(:), work(:)
        logical :: has_key, found, descending
        integer :: j
        call kwarg(kwargs, 'key', kf, has_key)
        if (has_key) has_key = kf%kind /= VK_NONE
        call kwarg(kwargs, 'reverse', rev, found)
        descending = .false.
        if (found) descending = is_true(ctx, rev)
        allocate (keys(size(items)))
        do j = 1, size(items)
            if (has_key) then
                call call_value(ctx, id, kf, values_of(items(j)), empty_kwargs(), keys(j), st, frame)
                if (st%failed()) return
            else
                keys(j) = items(j)
            end if
        end do
        allocate (perm(size(items)), work(size(items)))
        perm = [(j, j = 1, size(items))]
        call merge_sort(1, size(items))
        if (st%failed()) return
        allocate (sorted(size(items)))
        do j = 1, size(items)
            sorted(j) = items(perm(j))
        end do
        items = sorted
    contains
        recursive subroutine merge_sort(lo, hi)
            integer, intent(in) :: lo, hi
            integer :: mid, i, k, l, c
            if (hi <= lo) return
            mid = (lo + hi) / 2
            call merge_sort(lo, mid)
            call merge_sort(mid + 1, hi)
            if (st%failed()) return
            i = lo; k = mid + 1; l = lo
            do while (i <= mid .and. k <= hi)
                call order(ctx, id, keys(perm(k)), keys(perm(i)), c, st)
                if (st%failed()) return
                if (descending) c = -c
                if (c < 0) then                     ! stable: equal keys keep their order
                    work(l) = perm(k); k = k + 1
                else
                    work(l) = perm(i); i = i + 1
                end if
                l = l + 1
            end do
            do while (i <= mid)
                work(l) = perm(i); i = i + 1; l = l + 1
            end do
            do while (k <= hi)
                work(l) = perm(k); k = k + 1; l = l + 1
            end do
            perm(lo:hi) = work(lo:hi)
        end subroutine merge_sort
    end procedure sort_items

end submodule deck_interp_builtins

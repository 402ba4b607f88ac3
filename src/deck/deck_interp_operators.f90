!> The deck evaluator (deck_interpreter), its operators with Python 3's semantics: unary and
!> binary arithmetic on numbers (checked before it is done: no FP trap), strings, tuples,
!> lists and concepts (their special methods), % formatting of strings, and comparisons
!> (chains, in, not in, is, is not).
submodule(deck_interpreter) deck_interp_operators
    use deck_math
    use deck_heap, only: hashable, keys_equal
    use deck_concept, only: placeholder_concept_t
    implicit none

contains

    ! ---- operators --------------------------------------------------------------------------

    module procedure unary
        type(value_t), allocatable :: none(:)
        if (a%kind == VK_UNKNOWN) then
            v = a; return
        end if
        if (a%kind == VK_CONCEPT .and. ctx%ast%nodes(id)%text /= 'not') then
            allocate (none(0))
            call use_attribute(ctx, id, a, merge('__neg__', '__pos__', &
                ctx%ast%nodes(id)%text == '-'), .true., none, empty_kwargs(), v, st)
            return
        end if
        select case (ctx%ast%nodes(id)%text)
        case ('not')
            v = bool_value(.not. is_true(ctx, a))
        case ('-', '+')
            if (.not. is_number(a)) then
                call fail(st, ctx, id, 'unary ' // ctx%ast%nodes(id)%text // &
                          ' needs a number, got ' // kind_label(a)); return
            end if
            if (a%kind == VK_REAL) then
                v = real_value(a%r)
                if (ctx%ast%nodes(id)%text == '-') v%r = -a%r
            else
                if (a%i == -huge(a%i) - 1 .and. ctx%ast%nodes(id)%text == '-') then
                    call fail(st, ctx, id, 'integer overflow in -' // to_text(a%i)); return
                end if
                v = int_value(a%i)
                if (ctx%ast%nodes(id)%text == '-') v%i = -a%i
            end if
        end select
    end procedure unary

    !> a op b with Python 3's semantics on numbers (checked: no FP trap), strings, tuples,
    !> lists and concepts (their special methods); % on a string formats. in_place: the
    !> augmented assignment a op= b, which extends (+) or repeats (*) a list in place.
    module procedure binary
        real(dp) :: r
        integer :: code, k
        integer(i8) :: count
        type(value_t), allocatable :: xa(:), xb(:), all(:)
        character(len=:), allocatable :: text
        logical :: inplace
        inplace = .false.
        if (present(in_place)) inplace = in_place
        if (a%kind == VK_UNKNOWN .or. b%kind == VK_UNKNOWN) then
            v%kind = VK_UNKNOWN; return
        end if
        if (placeholder(a) .or. placeholder(b)) then
            v%kind = VK_UNKNOWN; return          ! check pass: made when the deck runs
        end if
        if (a%kind == VK_CONCEPT .or. b%kind == VK_CONCEPT) then
            ! a - b on concepts (fields, tables): their __sub__, else b's __rsub__
            if (has_method(ctx, a, operator_name(op, .false.))) then
                call use_attribute(ctx, id, a, operator_name(op, .false.), .true., values_of(b), &
                                   empty_kwargs(), v, st); return
            else if (has_method(ctx, b, operator_name(op, .true.))) then
                call use_attribute(ctx, id, b, operator_name(op, .true.), .true., values_of(a), &
                                   empty_kwargs(), v, st); return
            end if
        end if
        if (is_number(a) .and. is_number(b)) then
            if (a%kind /= VK_REAL .and. b%kind /= VK_REAL .and. op /= '/') then
                call int_binary(ctx, id, op, a%i, b%i, v, st)
                return
            end if
            if (op == '**') then
                call checked_pow(as_real(a), as_real(b), r, code)
            else
                call checked_binary(op, as_real(a), as_real(b), r, code)
            end if
            if (code /= MATH_OK) then
                call fail(st, ctx, id, math_message(code, text_of(ctx, a, .true.) // ' ' // op &
                          // ' ' // text_of(ctx, b, .true.))); return
            end if
            v = real_value(r)
            return
        end if
        if (op == '%' .and. a%kind == VK_STR) then
            if (holds_unknown(b)) then
                v%kind = VK_UNKNOWN; return
            end if
            call percent_format(ctx, id, a%s, b, text, st)
            if (st%ok()) v = str_value(text)
            return
        end if
        if (op == '+' .and. a%kind == VK_STR .and. b%kind == VK_STR) then
            if (real(len(a%s), dp) + real(len(b%s), dp) > real(MAX_REPEAT, dp)) then
                call fail(st, ctx, id, 'string too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
            end if
            v = str_value(a%s // b%s); return
        end if
        if (a%kind == VK_LIST .and. inplace .and. (op == '+' .or. op == '*')) then
            ! L += iterable, L *= n: the same list, changed
            if (op == '+') then
                call iterate(ctx, id, b, xb, st)
                if (st%failed()) return
                call count_built(ctx, id, int(size(xb), i8), st)
                if (st%failed()) return
                do k = 1, size(xb)
                    call ctx%heap%append(a%i, xb(k))
                end do
                call check_heap(ctx, id, st)
                v = a
                return
            end if
            if (b%kind == VK_INT .or. b%kind == VK_BOOL) then
                xa = ctx%heap%items_of(a%i)
                call repeated(xa, b%i, all)
                if (st%failed()) return
                call ctx%heap%set_items(a%i, all)
                call check_heap(ctx, id, st)
                v = a
                return
            end if
        end if
        if (op == '+' .and. (a%kind == VK_TUPLE .or. a%kind == VK_LIST) .and. &
            b%kind == a%kind) then
            call iterate(ctx, id, a, xa, st)
            call iterate(ctx, id, b, xb, st)
            if (st%failed()) return
            if (size(xa) + size(xb) > MAX_REPEAT) then
                call fail(st, ctx, id, kind_label(a) // ' too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' items)'); return
            end if
            call count_built(ctx, id, int(size(xa) + size(xb), i8), st)
            if (st%failed()) return
            all = joined(xa, xb)
            call finish_sequence(a%kind, all)
            return
        end if
        if (op == '*' .and. (is_repeatable(a) .and. (b%kind == VK_INT .or. &
            b%kind == VK_BOOL) .or. is_repeatable(b) .and. (a%kind == VK_INT .or. &
            a%kind == VK_BOOL))) then
            if (is_repeatable(a)) then
                call repeat_value(a, b%i)
            else
                call repeat_value(b, a%i)
            end if
            return
        end if
        call fail(st, ctx, id, 'unsupported operand types for ' // op // ': ' // &
                  kind_label(a) // ' and ' // kind_label(b))
    contains
        logical function is_repeatable(x)
            type(value_t), intent(in) :: x
            is_repeatable = x%kind == VK_STR .or. x%kind == VK_TUPLE .or. x%kind == VK_LIST
        end function is_repeatable

        !> items repeated n times (n <= 0: none), within MAX_REPEAT.
        subroutine repeated(items, n, out)
            type(value_t), intent(in) :: items(:)
            integer(i8), intent(in) :: n
            type(value_t), allocatable, intent(out) :: out(:)
            integer :: j, m
            m = int(max(0_i8, min(n, int(MAX_REPEAT, i8) + 1)))
            if (real(size(items), dp) * real(m, dp) > real(MAX_REPEAT, dp)) then
                allocate (out(0))
                call fail(st, ctx, id, 'repetition too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' items)'); return
            end if
            count = int(size(items), i8) * m
            call count_built(ctx, id, count, st)
            allocate (out(size(items) * m))
            do j = 1, m
                out((j - 1) * size(items) + 1:j * size(items)) = items
            end do
        end subroutine repeated

        subroutine repeat_value(x, n)
            type(value_t), intent(in) :: x
            integer(i8), intent(in) :: n
            type(value_t), allocatable :: items(:), out(:)
            integer :: m
            if (x%kind == VK_STR) then
                m = int(max(0_i8, min(n, int(MAX_REPEAT, i8) + 1)))
                if (real(len(x%s), dp) * real(m, dp) > real(MAX_REPEAT, dp)) then
                    call fail(st, ctx, id, 'repetition too long (more than ' // &
                              to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
                end if
                v = str_value(repeat(x%s, m))
                return
            end if
            call iterate(ctx, id, x, items, st)
            if (st%failed()) return
            call repeated(items, n, out)
            if (st%failed()) return
            call finish_sequence(x%kind, out)
        end subroutine repeat_value

        subroutine finish_sequence(kind, items)
            integer, intent(in) :: kind
            type(value_t), intent(in) :: items(:)
            if (kind == VK_LIST) then
                v = new_list(ctx, items)
                call check_heap(ctx, id, st)
            else
                v = sequence_value(VK_TUPLE, items)
            end if
        end subroutine finish_sequence
    end procedure binary

    !> Integer arithmetic with Python's floor division/modulo; overflow is an error.
    subroutine int_binary(ctx, id, op, a, b, v, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: op
        integer(i8), intent(in) :: a, b
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        integer(i8) :: r, q
        integer :: k, code
        real(dp) :: x
        real(dp), parameter :: LIMIT = 9.2e18_dp
        select case (op)
        case ('+', '-', '*')
            if (op == '+') x = real(a, dp) + real(b, dp)
            if (op == '-') x = real(a, dp) - real(b, dp)
            if (op == '*') x = real(a, dp) * real(b, dp)
            if (abs(x) > LIMIT) then
                call fail(st, ctx, id, 'integer overflow in ' // to_text(a) // ' ' // op // &
                          ' ' // to_text(b) // ' (use reals, e.g. 1.0E+20)'); return
            end if
            if (op == '+') r = a + b
            if (op == '-') r = a - b
            if (op == '*') r = a * b
            v = int_value(r)
        case ('//', '%')
            if (b == 0) then
                call fail(st, ctx, id, 'integer division by zero in ' // to_text(a) // ' ' // &
                          op // ' 0'); return
            end if
            if (a == -huge(a) - 1 .and. b == -1) then
                call fail(st, ctx, id, 'integer overflow in ' // to_text(a) // ' ' // op // &
                          ' -1'); return
            end if
            q = a / b
            if (mod(a, b) /= 0 .and. ((a < 0) .neqv. (b < 0))) q = q - 1
            if (op == '//') then
                v = int_value(q)
            else
                v = int_value(a - q * b)
            end if
        case ('**')
            if (b < 0) then
                call checked_pow(real(a, dp), real(b, dp), x, code)
                if (code /= MATH_OK) then
                    call fail(st, ctx, id, math_message(code, to_text(a) // ' ** ' // &
                              to_text(b))); return
                end if
                v = real_value(x); return
            end if
            r = 1
            do k = 1, int(min(b, 64_i8))
                if (abs(real(r, dp) * real(a, dp)) > LIMIT) then
                    call fail(st, ctx, id, 'integer overflow in ' // to_text(a) // ' ** ' // &
                              to_text(b) // ' (use reals)'); return
                end if
                r = r * a
            end do
            if (b > 64 .and. abs(a) > 1) then
                call fail(st, ctx, id, 'integer overflow in ' // to_text(a) // ' ** ' // &
                          to_text(b) // ' (use reals)'); return
            end if
            if (b > 64 .and. a == -1 .and. mod(b, 2_i8) == 1) r = -1
            v = int_value(r)
        case default
            call fail(st, ctx, id, 'unsupported operator ' // op)
        end select
    end subroutine int_binary

    !> a < b <= c ..., in, not in, is, is not: each comparison taken in turn; with concepts
    !> their special methods (tab.NOM == 'START' filters a table).
    module procedure compare_chain
        type(value_t) :: a, b, r
        type(string_t), allocatable :: ops(:)
        integer :: k, i, j
        character(len=:), allocatable :: text
        text = ctx%ast%nodes(id)%text
        allocate (ops(0))
        i = 1
        do while (i <= len(text))
            j = index(text(i:) // ' ', ' ') + i - 1
            call append_string(ops, text(i:j - 1))
            i = j + 1
        end do
        call eval(ctx, ctx%ast%kid(id, 1), a, st, frame)
        if (st%failed()) return
        v = bool_value(.true.)
        do k = 1, size(ops)
            call eval(ctx, ctx%ast%kid(id, k + 1), b, st, frame)
            if (st%failed()) return
            call compare_pair(ctx, id, ops(k)%s, a, b, r, st)
            if (st%failed()) return
            if (size(ops) == 1 .or. r%kind == VK_UNKNOWN) then
                v = r; return
            end if
            if (.not. is_true(ctx, r)) then
                v = bool_value(.false.); return
            end if
            a = b
        end do
    end procedure compare_chain

    !> One comparison a OP b.
    module recursive subroutine compare_pair(ctx, id, op, a, b, r, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: op
        type(value_t), intent(in) :: a, b
        type(value_t), intent(out) :: r
        type(status_t), intent(inout) :: st
        integer :: c
        logical :: found
        if (a%kind == VK_UNKNOWN .or. b%kind == VK_UNKNOWN) then
            r%kind = VK_UNKNOWN; return
        end if
        select case (op)
        case ('in', 'not_in')
            call contains(ctx, id, b, a, found, r, st)
            if (st%failed() .or. r%kind == VK_UNKNOWN) return
            r = bool_value(found .eqv. (op == 'in'))
            return
        case ('is', 'is_not')
            r = bool_value(identical(a, b) .eqv. (op == 'is'))
            return
        end select
        if (placeholder(a) .or. placeholder(b)) then
            r%kind = VK_UNKNOWN; return          ! check pass: made when the deck runs
        end if
        if (a%kind == VK_CONCEPT .or. b%kind == VK_CONCEPT) then
            if (has_method(ctx, a, compare_name(op, .false.))) then
                call use_attribute(ctx, id, a, compare_name(op, .false.), .true., values_of(b), &
                                   empty_kwargs(), r, st); return
            else if (has_method(ctx, b, compare_name(op, .true.))) then
                call use_attribute(ctx, id, b, compare_name(op, .true.), .true., values_of(a), &
                                   empty_kwargs(), r, st); return
            end if
        end if
        select case (op)
        case ('==')
            r = bool_value(values_equal(ctx, a, b))
        case ('!=')
            r = bool_value(.not. values_equal(ctx, a, b))
        case default
            call order(ctx, id, a, b, c, st)
            if (st%failed()) return
            select case (op)
            case ('<')
                r = bool_value(c < 0)
            case ('<=')
                r = bool_value(c <= 0)
            case ('>')
                r = bool_value(c > 0)
            case default
                r = bool_value(c >= 0)
            end select
        end select
    contains
        !> Python's `is`: the same list, dict or concept; None is None; other values (numbers,
        !> strings: immutable, their identity is not something a deck can rely on) by value.
        logical function identical(x, y)
            type(value_t), intent(in) :: x, y
            identical = .false.
            if (x%kind /= y%kind) return
            select case (x%kind)
            case (VK_LIST, VK_DICT)
                identical = x%i == y%i
            case (VK_NONE)
                identical = .true.
            case (VK_CONCEPT)
                identical = associated(x%obj, y%obj)
            case default
                identical = values_equal(ctx, x, y)
            end select
        end function identical
    end subroutine compare_pair

    !> x in container: an equal item of a list or a tuple, a key of a dict or a _F, a
    !> substring of a string, a concept's __contains__.
    recursive subroutine contains(ctx, id, container, x, found, r, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: container, x
        logical, intent(out) :: found
        type(value_t), intent(out) :: r
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: items(:)
        integer :: k
        found = .false.
        select case (container%kind)
        case (VK_LIST, VK_TUPLE, VK_FACTOR)
            call iterate(ctx, id, container, items, st)
            do k = 1, size(items)
                if (values_equal(ctx, items(k), x)) then
                    found = .true.; return
                end if
            end do
        case (VK_DICT)
            if (.not. hashable(x)) then
                call fail(st, ctx, id, kind_label(x) // ' cannot be a dict key'); return
            end if
            found = ctx%heap%dict_find(container%i, x) > 0
        case (VK_STR)
            if (x%kind /= VK_STR) then
                call fail(st, ctx, id, '"in" a string needs a string, got ' // kind_label(x))
                return
            end if
            found = index(container%s, x%s) > 0
        case (VK_CONCEPT)
            call use_attribute(ctx, id, container, '__contains__', .true., values_of(x), &
                               empty_kwargs(), r, st)
            if (st%failed() .or. r%kind == VK_UNKNOWN) return
            found = is_true(ctx, r)
        case default
            call fail(st, ctx, id, '"in" needs a list, a tuple, a dict or a string, got ' // &
                      kind_label(container))
        end select
    end subroutine contains

    !> Python's special name of a binary operator ('+' -> '__add__', reflected '__radd__').
    pure function operator_name(op, reflected) result(name)
        character(len=*), intent(in) :: op
        logical, intent(in) :: reflected
        character(len=:), allocatable :: name
        select case (op)
        case ('+')
            name = 'add'
        case ('-')
            name = 'sub'
        case ('*')
            name = 'mul'
        case ('/')
            name = 'truediv'
        case ('//')
            name = 'floordiv'
        case ('%')
            name = 'mod'
        case ('**')
            name = 'pow'
        case default
            name = 'op'
        end select
        if (reflected) name = 'r' // name
        name = '__' // name // '__'
    end function operator_name

    !> Python's special name of a comparison; reflected: the one the right operand answers
    !> (a < b is b > a).
    pure function compare_name(op, reflected) result(name)
        character(len=*), intent(in) :: op
        logical, intent(in) :: reflected
        character(len=:), allocatable :: name
        character(len=:), allocatable :: o
        o = op
        if (reflected) then
            select case (op)
            case ('<')
                o = '>'
            case ('<=')
                o = '>='
            case ('>')
                o = '<'
            case ('>=')
                o = '<='
            end select
        end if
        select case (o)
        case ('<')
            name = '__lt__'
        case ('<=')
            name = '__le__'
        case ('>')
            name = '__gt__'
        case ('>=')
            name = '__ge__'
        case ('==')
            name = '__eq__'
        case ('!=')
            name = '__ne__'
        case default
            name = '__cmp__'
        end select
    end function compare_name

    !> A check-pass placeholder concept (what a command makes when the deck runs).
    pure logical function placeholder(v)
        type(value_t), intent(in) :: v
        placeholder = .false.
        if (v%kind /= VK_CONCEPT .or. .not. associated(v%obj)) return
        select type (o => v%obj)
        type is (placeholder_concept_t)
            placeholder = .true.
        end select
    end function placeholder

end submodule deck_interp_operators

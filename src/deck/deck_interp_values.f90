!> The deck evaluator (deck_interpreter), what its parts share about values: items of lists,
!> tuples, strings, dicts, _F and concepts (subscripts), walking any iterable, the truth of a
!> value, its text (str and repr, Python's), equality and order.
submodule(deck_interpreter) deck_interp_values
    use deck_format, only: real_repr, int_text, string_repr
    use deck_sequence, only: item_position
    use deck_heap, only: hashable, keys_equal
    use deck_concept, only: concept_display_name
    implicit none

contains

    ! ---- subscripts -------------------------------------------------------------------------

    !> seq[index]: lists, tuples and strings by integer (negative counts from the end),
    !> dicts and _F by key, concepts by their __getitem__.
    module procedure get_item
        type(value_list_t) :: list
        type(value_t), allocatable :: chars(:)
        character(len=:), allocatable :: message
        integer :: k, n
        if (seq%kind == VK_UNKNOWN .or. index%kind == VK_UNKNOWN) then
            v%kind = VK_UNKNOWN; return
        end if
        select case (seq%kind)
        case (VK_LIST, VK_TUPLE, VK_STR)
            if (index%kind /= VK_INT .and. index%kind /= VK_BOOL) then
                call fail(st, ctx, id, 'an index of ' // kind_label(seq) // ' must be an ' // &
                          'integer, got ' // kind_label(index) // ' (use int(...))'); return
            end if
            select case (seq%kind)
            case (VK_LIST)
                n = ctx%heap%length(seq%i)
            case (VK_TUPLE)
                n = nitems(seq)
            case default
                chars = characters(seq%s)
                n = size(chars)
            end select
            call item_position(n, index%i, kind_label(seq), k, message)
            if (len(message) > 0) then
                call fail(st, ctx, id, message); return
            end if
            select case (seq%kind)
            case (VK_LIST)
                v = ctx%heap%get(seq%i, k)
            case (VK_TUPLE)
                v = item(seq, k)
            case default
                v = chars(k)
            end select
        case (VK_DICT)
            if (.not. hashable(index)) then
                call fail(st, ctx, id, kind_label(index) // ' cannot be a dict key (keys ' // &
                          'are numbers, strings, tuples of them...)'); return
            end if
            k = ctx%heap%dict_find(seq%i, index)
            if (k == 0) then
                call fail(st, ctx, id, 'key ' // text_of(ctx, index, .true.) // &
                    ' is not in the dict' // dict_keys_hint(ctx, seq)); return
            end if
            v = ctx%heap%get(seq%i, k)
        case (VK_FACTOR)
            if (index%kind /= VK_STR) then
                call fail(st, ctx, id, 'a _F is read by keyword name, got ' // &
                          kind_label(index)); return
            end if
            list = unpack_value(seq)
            do k = 1, size(list%items)
                if (list%keys(k)%s == index%s) then
                    v = list%items(k); return
                end if
            end do
            call fail(st, ctx, id, 'keyword ' // index%s // ' is not in this _F(...)')
        case (VK_CONCEPT)
            call use_attribute(ctx, id, seq, '__getitem__', .true., values_of(index), empty_kwargs(), &
                               v, st)
        case default
            call fail(st, ctx, id, kind_label(seq) // ' cannot be indexed')
        end select
    end procedure get_item

    !> ' (it has: ...)' for a KeyError message: the dict's first keys.
    function dict_keys_hint(ctx, d) result(text)
        type(run_context_t), intent(in) :: ctx
        type(value_t), intent(in) :: d
        character(len=:), allocatable :: text
        integer :: k, n
        n = ctx%heap%length(d%i)
        if (n == 0) then
            text = ' (the dict is empty)'; return
        end if
        text = ' (its keys: '
        do k = 1, min(n, 8)
            if (k > 1) text = text // ', '
            text = text // text_of(ctx, ctx%heap%key_at(d%i, k), .true.)
        end do
        if (n > 8) text = text // ', ...'
        text = text // ')'
    end function dict_keys_hint

    !> seq[index] = v: a list item, a dict key, a concept's __setitem__.
    module procedure set_item
        type(value_t) :: old
        integer :: k
        type(value_t) :: args(2)
        select case (seq%kind)
        case (VK_UNKNOWN)
        case (VK_LIST)
            call get_item(ctx, id, seq, index, old, st)        ! the index checks
            if (st%failed()) return
            k = int(index%i)
            if (k < 0) k = k + ctx%heap%length(seq%i)
            call ctx%heap%set(seq%i, k + 1, v)
        case (VK_DICT)
            if (index%kind == VK_UNKNOWN) return
            if (.not. hashable(index)) then
                call fail(st, ctx, id, kind_label(index) // ' cannot be a dict key (keys ' // &
                          'are numbers, strings, tuples of them...)'); return
            end if
            call ctx%heap%dict_set(seq%i, index, v)
            call check_heap(ctx, id, st)
        case (VK_CONCEPT)
            args(1) = index; args(2) = v
            call use_attribute(ctx, id, seq, '__setitem__', .true., args, empty_kwargs(), &
                               old, st)
        case (VK_TUPLE, VK_STR, VK_FACTOR)
            call fail(st, ctx, id, kind_label(seq) // ' cannot be changed (build a list [ ' &
                      // '... ] or a dict { ... } to change items)')
        case default
            call fail(st, ctx, id, kind_label(seq) // ' does not support item assignment')
        end select
    end procedure set_item

    !> The characters of a UTF-8 string (code points, not bytes), each a string value.
    module procedure characters
        integer :: i, j, n
        n = 0
        do i = 1, len(s)
            if (iand(iachar(s(i:i)), 192) /= 128) n = n + 1
        end do
        allocate (chars(n))
        n = 0; i = 1
        do while (i <= len(s))
            j = i + 1
            do while (j <= len(s))
                if (iand(iachar(s(j:j)), 192) /= 128) exit
                j = j + 1
            end do
            n = n + 1
            chars(n) = str_value(s(i:j - 1))
            i = j
        end do
    end procedure characters

    !> The items an iterable gives, in order: a list's (as it is now), a tuple's, a
    !> string's characters, a dict's or a _F's keys, a concept's __iter__ result.
    module procedure iterate
        type(value_list_t) :: list
        type(value_t) :: r
        type(value_t), allocatable :: none(:)
        integer :: k
        select case (v%kind)
        case (VK_LIST)
            items = ctx%heap%items_of(v%i)
        case (VK_TUPLE)
            list = unpack_value(v)
            items = list%items
        case (VK_STR)
            items = characters(v%s)
        case (VK_DICT)
            items = ctx%heap%keys_of(v%i)
        case (VK_FACTOR)
            list = unpack_value(v)
            allocate (items(size(list%keys)))
            do k = 1, size(list%keys)
                items(k) = str_value(list%keys(k)%s)
            end do
        case (VK_CONCEPT)
            allocate (none(0))
            call use_attribute(ctx, id, v, '__iter__', .true., none, empty_kwargs(), r, st)
            if (st%failed()) return
            if (r%kind == VK_CONCEPT .or. r%kind == VK_UNKNOWN) then
                allocate (items(0))
                if (r%kind == VK_UNKNOWN) call stop_check(ctx, id)
                if (r%kind == VK_CONCEPT) call fail(st, ctx, id, 'the __iter__ of a ' // &
                    'concept must give a list or a tuple')
                return
            end if
            call iterate(ctx, id, r, items, st)
        case (VK_UNKNOWN)
            allocate (items(0))
            call stop_check(ctx, id)
        case default
            allocate (items(0))
            call fail(st, ctx, id, kind_label(v) // ' cannot be walked (a list, a tuple, a ' &
                      // 'string or a dict can)')
        end select
    end procedure iterate

    ! ---- truth, text, equality, order -------------------------------------------------------

    !> Python's truth of a value (a value known only when the deck runs is false: the
    !> callers stop the check before they ask).
    module procedure is_true
        select case (v%kind)
        case (VK_INT, VK_BOOL)
            is_true = v%i /= 0
        case (VK_REAL)
            is_true = v%r > 0.0_dp .or. v%r < 0.0_dp
        case (VK_STR)
            is_true = len(v%s) > 0
        case (VK_TUPLE, VK_FACTOR)
            is_true = nitems(v) > 0
        case (VK_LIST, VK_DICT)
            is_true = ctx%heap%length(v%i) > 0
        case (VK_NONE, VK_UNKNOWN)
            is_true = .false.
        case default
            is_true = .true.
        end select
    end procedure is_true

    !> Python's str(v) (repr = .false.) or repr(v): reals as their shortest text, strings
    !> quoted by repr, containers with repr of their items; a concept as <type name>.
    module procedure text_of
        type(value_list_t) :: list
        integer :: k, d, n
        d = 0
        if (present(depth)) d = depth
        if (d > MAX_TEXT_DEPTH) then
            text = '...'; return
        end if
        select case (v%kind)
        case (VK_INT)
            text = int_text(v%i)
        case (VK_REAL)
            text = real_repr(v%r)
        case (VK_BOOL)
            text = merge('True ', 'False', v%i /= 0)
            text = trim(text)
        case (VK_STR)
            text = v%s
            if (repr) text = string_repr(v%s)
        case (VK_NONE)
            text = 'None'
        case (VK_TUPLE)
            list = unpack_value(v)
            text = '('
            do k = 1, size(list%items)
                if (k > 1) text = text // ', '
                text = text // text_of(ctx, list%items(k), .true., d + 1)
            end do
            if (size(list%items) == 1) text = text // ','
            text = text // ')'
        case (VK_LIST)
            n = ctx%heap%length(v%i)
            text = '['
            do k = 1, n
                if (k > 1) text = text // ', '
                text = text // text_of(ctx, ctx%heap%get(v%i, k), .true., d + 1)
            end do
            text = text // ']'
        case (VK_DICT)
            n = ctx%heap%length(v%i)
            text = '{'
            do k = 1, n
                if (k > 1) text = text // ', '
                text = text // text_of(ctx, ctx%heap%key_at(v%i, k), .true., d + 1) // &
                    ': ' // text_of(ctx, ctx%heap%get(v%i, k), .true., d + 1)
            end do
            text = text // '}'
        case (VK_FACTOR)
            list = unpack_value(v)
            text = '{'
            do k = 1, size(list%items)
                if (k > 1) text = text // ', '
                text = text // string_repr(list%keys(k)%s) // ': ' // &
                    text_of(ctx, list%items(k), .true., d + 1)
            end do
            text = text // '}'
        case (VK_CONCEPT)
            text = '<' // v%s // '>'
            if (associated(v%obj)) text = '<' // v%obj%type_name() // ' ' // &
                concept_display_name(v%obj) // '>'
        case (VK_DEF)
            text = '<function ' // v%s // '>'
        case (VK_BUILTIN)
            select case (v%s)
            case ('int', 'float', 'str', 'bool', 'list', 'tuple', 'dict', 'set', 'frozenset', &
                  'complex', 'bytes', 'object', 'range', 'type', 'Exception', 'ValueError', &
                  'TypeError', 'RuntimeError', 'KeyError', 'IndexError', 'AssertionError', &
                  'NotImplementedError', 'ZeroDivisionError', 'NameError')
                text = '<class ''' // v%s // '''>'            ! Python's types
            case ('TestCase')
                text = '<class ''code_aster.Utilities.Tester.TestCase''>'
            case default
                text = '<built-in function ' // v%s // '>'
            end select
        case (VK_MODULE)
            text = '<module ''' // v%s // '''>'
        case (VK_METHOD)
            text = '<method ' // v%s // '>'
        case (VK_UNKNOWN)
            text = '<known when the deck runs>'
        case (VK_CO)
            text = "CO('" // v%s // "')"
        case default
            text = '?'
        end select
    end procedure text_of

    !> Python's a == b: numbers by value (1 == 1.0 == True), strings by text, tuples, lists
    !> and dicts item by item, concepts and functions by identity.
    module procedure values_equal
        same = equal_at(a, b, 0)
    contains
        recursive logical function equal_at(x, y, d) result(eq)
            type(value_t), intent(in) :: x, y
            integer, intent(in) :: d
            type(value_list_t) :: lx, ly
            integer :: k, n, j
            eq = .false.
            if (d > MAX_TEXT_DEPTH) return
            if (is_number(x) .and. is_number(y)) then
                eq = keys_equal(x, y); return
            end if
            if (x%kind /= y%kind) return
            select case (x%kind)
            case (VK_STR, VK_NONE, VK_CONCEPT, VK_BUILTIN, VK_MODULE)
                eq = keys_equal(x, y)
                if (x%kind == VK_MODULE) eq = x%s == y%s
            case (VK_DEF)
                eq = x%i == y%i
            case (VK_TUPLE, VK_FACTOR)
                lx = unpack_value(x); ly = unpack_value(y)
                if (size(lx%items) /= size(ly%items)) return
                do k = 1, size(lx%items)
                    if (x%kind == VK_FACTOR) then
                        if (lx%keys(k)%s /= ly%keys(k)%s) return
                    end if
                    if (.not. equal_at(lx%items(k), ly%items(k), d + 1)) return
                end do
                eq = .true.
            case (VK_LIST)
                if (x%i == y%i) then
                    eq = .true.; return
                end if
                n = ctx%heap%length(x%i)
                if (n /= ctx%heap%length(y%i)) return
                do k = 1, n
                    if (.not. equal_at(ctx%heap%get(x%i, k), ctx%heap%get(y%i, k), d + 1)) &
                        return
                end do
                eq = .true.
            case (VK_DICT)
                if (x%i == y%i) then
                    eq = .true.; return
                end if
                n = ctx%heap%length(x%i)
                if (n /= ctx%heap%length(y%i)) return
                do k = 1, n
                    j = ctx%heap%dict_find(y%i, ctx%heap%key_at(x%i, k))
                    if (j == 0) return
                    if (.not. equal_at(ctx%heap%get(x%i, k), ctx%heap%get(y%i, j), d + 1)) &
                        return
                end do
                eq = .true.
            end select
        end function equal_at
    end procedure values_equal

    !> Python's order of a and b (c < 0, 0, > 0): numbers, strings, and tuples or lists
    !> item by item; other pairs are an error.
    module procedure order
        type(value_t), allocatable :: xa(:), xb(:)
        type(value_list_t) :: la, lb
        integer :: k
        c = 0
        if (is_number(a) .and. is_number(b)) then
            if (a%kind /= VK_REAL .and. b%kind /= VK_REAL) then
                if (a%i < b%i) c = -1
                if (a%i > b%i) c = 1
            else
                if (as_real(a) < as_real(b)) c = -1
                if (as_real(a) > as_real(b)) c = 1
            end if
            return
        end if
        if (a%kind == VK_STR .and. b%kind == VK_STR) then
            if (llt(a%s, b%s)) c = -1
            if (lgt(a%s, b%s)) c = 1
            if (c == 0 .and. len(a%s) /= len(b%s)) c = merge(-1, 1, len(a%s) < len(b%s))
            return
        end if
        if ((a%kind == VK_TUPLE .and. b%kind == VK_TUPLE) .or. &
            (a%kind == VK_LIST .and. b%kind == VK_LIST)) then
            if (a%kind == VK_TUPLE) then
                la = unpack_value(a); lb = unpack_value(b)
                xa = la%items; xb = lb%items
            else
                xa = ctx%heap%items_of(a%i); xb = ctx%heap%items_of(b%i)
            end if
            do k = 1, min(size(xa), size(xb))
                if (values_equal(ctx, xa(k), xb(k))) cycle
                call order(ctx, id, xa(k), xb(k), c, st)
                return
            end do
            if (size(xa) < size(xb)) c = -1
            if (size(xa) > size(xb)) c = 1
            return
        end if
        call fail(st, ctx, id, 'cannot order ' // kind_label(a) // ' and ' // kind_label(b))
    end procedure order

end submodule deck_interp_values

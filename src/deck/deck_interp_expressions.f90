!> The deck evaluator (deck_interpreter), its expressions: literals and names, displays of
!> tuples, lists and dicts, comprehensions, f-strings, operators with Python 3's semantics
!> on numbers, strings, tuples, lists and concepts, comparisons (in, is, chains),
!> subscripts and slices, and what the other parts share: the truth of a value, its text
!> (str and repr), equality and order, walking any iterable.
submodule(deck_interpreter) deck_interp_expressions
    use deck_math
    use deck_format, only: real_repr, int_text, string_repr, format_spec_t, parse_spec, &
        format_real, format_int, format_text
    use deck_sequence, only: item_position, slice_positions
    use deck_heap, only: hashable, keys_equal
    use deck_suggest, only: did_you_mean
    use deck_concept, only: concept_display_name
    use run_context, only: SCOPE_SESSION
    implicit none

contains

    !> Evaluates expression node `id` of ctx%ast (public entry, e.g. for tests).
    module procedure eval_expression
        call eval(ctx, id, v, st)
    end procedure eval_expression

    module procedure eval
        type(value_t) :: a, b
        integer :: k, nk, ios
        type(node_t) :: node
        node = ctx%ast%nodes(id)
        select case (node%kind)
        case (N_INT)
            v%kind = VK_INT
            read (node%text, *, iostat=ios) v%i
            if (ios /= 0) call fail(st, ctx, id, 'integer literal too large (at most ' // &
                'about 9.2E+18; write it as a real)')
        case (N_REAL)
            v%kind = VK_REAL
            ios = 0
            if (literal_out_of_range(node%text)) ios = 1
            if (ios == 0) read (node%text, *, iostat=ios) v%r
            if (ios == 0) then
                if (abs(v%r) > huge(v%r)) ios = 1
            end if
            if (ios /= 0) call fail(st, ctx, id, 'real literal out of range (the largest ' // &
                                    'real is about 1.8E+308)')
        case (N_STR)
            v = str_value(node%text)
        case (N_FSTRING)
            call eval_fstring(ctx, id, v, st, frame)
        case (N_NAME)
            call lookup(ctx, id, v, st, frame)
            ! A name's value is located where it is used, not where it was bound, so an
            ! error about it (e.g. a concept of the wrong type) points at the use.
            v%line = node%line; v%col = node%col
        case (N_TUPLE, N_LIST)
            call eval_display(ctx, id, v, st, frame)
        case (N_DICT)
            call eval_dict(ctx, id, v, st, frame)
        case (N_LISTCOMP, N_GENEXP, N_DICTCOMP)
            call eval_comprehension(ctx, id, v, st, frame)
        case (N_LAMBDA)
            call lambda_value(ctx, id, v, st, frame)
        case (N_INDEX)
            call eval(ctx, node%kids(1), a, st, frame)
            if (st%failed()) return
            call eval(ctx, node%kids(2), b, st, frame)
            if (st%failed()) return
            call get_item(ctx, id, a, b, v, st)
        case (N_SLICE)
            call eval_slice(ctx, id, v, st, frame)
        case (N_ATTR)
            call eval(ctx, node%kids(1), a, st, frame)
            if (st%failed()) return
            call get_attribute(ctx, id, a, node%text, v, st)
        case (N_UNARY)
            call eval(ctx, node%kids(1), a, st, frame)
            if (st%failed()) return
            call unary(ctx, id, a, v, st)
        case (N_BINOP)
            call eval(ctx, node%kids(1), a, st, frame)
            if (st%failed()) return
            call eval(ctx, node%kids(2), b, st, frame)
            if (st%failed()) return
            call binary(ctx, id, node%text, a, b, v, st)
        case (N_COMPARE)
            call compare_chain(ctx, id, v, st, frame)
        case (N_AND, N_OR)
            do k = 1, size(node%kids)
                call eval(ctx, node%kids(k), v, st, frame)
                if (st%failed()) return
                if (v%kind == VK_UNKNOWN) exit
                if (is_true(ctx, v) .eqv. (node%kind == N_OR)) exit
            end do
        case (N_IFEXP)
            call eval(ctx, node%kids(2), a, st, frame)
            if (st%failed()) return
            if (a%kind == VK_UNKNOWN) then
                v = a
            else if (is_true(ctx, a)) then
                call eval(ctx, node%kids(1), v, st, frame)
            else
                call eval(ctx, node%kids(3), v, st, frame)
            end if
        case (N_CALL)
            call eval_call(ctx, id, v, st, frame, target)
        case (N_STARRED)
            call fail(st, ctx, id, '*x unpacks inside a call, a list or a tuple only')
        case (N_SLICEITEM)
            call fail(st, ctx, id, 'a slice inside an index, x[a:b, c], is numpy''s: not ' // &
                      'part of the deck language (index one level at a time: x[i][j])')
        case default
            nk = node%kind
            call fail(st, ctx, id, 'unexpected expression (kind ' // to_text(int(nk, i4)) // ')')
        end select
        if (v%line == 0) then
            v%line = node%line; v%col = node%col
        end if
    end procedure eval

    !> (a, b, *c) and [a, b, *c]: a tuple (flat) or a new list of the heap.
    recursive subroutine eval_display(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t), allocatable :: items(:), more(:)
        type(value_t) :: x
        integer :: k, kid, n
        n = ctx%ast%nkids(id)
        allocate (items(n))
        n = 0
        do k = 1, ctx%ast%nkids(id)
            kid = ctx%ast%kid(id, k)
            if (ctx%ast%nodes(kid)%kind == N_STARRED) then
                call eval(ctx, ctx%ast%kid(kid, 1), x, st, frame)
                if (st%failed()) return
                if (x%kind == VK_UNKNOWN) then
                    v = x; return
                end if
                call iterate(ctx, kid, x, more, st)
                if (st%failed()) return
                items = joined(joined(items(1:n), more), items(n + 1:))
                n = n + size(more)
                cycle
            end if
            n = n + 1
            call eval(ctx, kid, items(n), st, frame)
            if (st%failed()) return
        end do
        if (ctx%ast%nodes(id)%kind == N_TUPLE) then
            v = sequence_value(VK_TUPLE, items(1:n))
        else
            v = new_list(ctx, items(1:n))
            call check_heap(ctx, id, st)
        end if
    end subroutine eval_display

    !> {k: v, **d, ...}: a new dict (keys hashable, later keys win).
    recursive subroutine eval_dict(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: key, val
        type(value_t), allocatable :: keys(:)
        integer :: k, knode, j
        v = ctx%heap%new_dict()
        k = 1
        do while (k <= ctx%ast%nkids(id))
            knode = ctx%ast%kid(id, k)
            if (ctx%ast%nodes(knode)%kind == N_DSTAR) then
                call eval(ctx, ctx%ast%kid(knode, 1), val, st, frame)
                if (st%failed()) return
                if (val%kind /= VK_DICT) then
                    call fail(st, ctx, knode, '**x in a dict needs a dict, got ' // &
                              kind_label(val)); return
                end if
                keys = ctx%heap%keys_of(val%i)
                do j = 1, size(keys)
                    call ctx%heap%dict_set(v%i, keys(j), ctx%heap%get(val%i, j))
                end do
            else
                call eval(ctx, knode, key, st, frame)
                if (st%failed()) return
                call eval(ctx, ctx%ast%kid(id, k + 1), val, st, frame)
                if (st%failed()) return
                call set_item(ctx, knode, v, key, val, st)
                if (st%failed()) return
            end if
            k = k + 2
        end do
        call check_heap(ctx, id, st)
    end subroutine eval_dict

    !> lambda PARAMS: EXPR, a function value (VK_DEF on the lambda node) with its defaults.
    recursive subroutine lambda_value(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t), allocatable :: defaults(:)
        integer :: k, p
        allocate (defaults(0))
        do k = 1, ctx%ast%nkids(id) - 1
            p = ctx%ast%kid(id, k)
            if (ctx%ast%nodes(p)%kind /= N_NAME .or. ctx%ast%nkids(p) == 0) cycle
            call append_value(defaults, value_t())
            call eval(ctx, ctx%ast%kid(p, 1), defaults(size(defaults)), st, frame)
            if (st%failed()) return
        end do
        v = function_value(ctx, id, '<lambda>', defaults, frame)
    end subroutine lambda_value

    !> [e for ...], (e for ...) and {k: v for ...}: evaluated in a frame of their own (their
    !> loop variables are theirs, as in Python 3), which sees the names around them. A
    !> generator expression gives a list (what sum, list, tuple, any ... take).
    recursive subroutine eval_comprehension(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(frame_t), target :: local
        integer :: first_clause, nclause
        logical :: is_dict
        is_dict = ctx%ast%nodes(id)%kind == N_DICTCOMP
        first_clause = merge(3, 2, is_dict)
        nclause = ctx%ast%nkids(id) - first_clause + 1
        local%comprehension = .true.
        local%depth = 1
        if (present(frame)) then
            local%enclosing => frame
            local%depth = frame%depth + 1
        end if
        if (local%depth > MAX_CALL_DEPTH) then
            call fail(st, ctx, id, 'comprehensions and def calls nested deeper than ' // &
                      to_text(int(MAX_CALL_DEPTH, i4))); return
        end if
        allocate (local%names(0), local%values(0))
        if (is_dict) then
            v = ctx%heap%new_dict()
        else
            v = new_list(ctx, local%values)
        end if
        ctx%gc_hold = ctx%gc_hold + 1
        call clause(1)
        ctx%gc_hold = ctx%gc_hold - 1
        if (st%failed()) return
        if (ctx%ast%nodes(id)%kind == N_GENEXP) v%line = ctx%ast%nodes(id)%line
    contains
        recursive subroutine clause(c)
            integer, intent(in) :: c
            type(value_t) :: seq, x, key, val
            type(value_t), allocatable :: items(:)
            integer :: node, k, j
            logical :: keep
            node = ctx%ast%kid(id, first_clause + c - 1)
            call eval(ctx, ctx%ast%kid(node, 2), seq, st, local)
            if (st%failed()) return
            if (seq%kind == VK_UNKNOWN) then
                v = seq; return
            end if
            call iterate(ctx, ctx%ast%kid(node, 2), seq, items, st)
            if (st%failed()) return
            do k = 1, size(items)
                call next_iteration(ctx, node, st)
                if (st%failed()) return
                call assign_target(ctx, ctx%ast%kid(node, 1), items(k), st, local)
                if (st%failed()) return
                keep = .true.
                do j = 3, ctx%ast%nkids(node)
                    call eval(ctx, ctx%ast%kid(node, j), x, st, local)
                    if (st%failed()) return
                    if (x%kind == VK_UNKNOWN) then
                        v = x; return
                    end if
                    if (.not. is_true(ctx, x)) then
                        keep = .false.; exit
                    end if
                end do
                if (.not. keep) cycle
                if (c < nclause) then
                    call clause(c + 1)
                    if (st%failed() .or. v%kind == VK_UNKNOWN) return
                    cycle
                end if
                if (is_dict) then
                    call eval(ctx, ctx%ast%kid(id, 1), key, st, local)
                    if (st%failed()) return
                    call eval(ctx, ctx%ast%kid(id, 2), val, st, local)
                    if (st%failed()) return
                    call set_item(ctx, id, v, key, val, st)
                else
                    call eval(ctx, ctx%ast%kid(id, 1), x, st, local)
                    if (st%failed()) return
                    call ctx%heap%append(v%i, x)
                end if
                call check_heap(ctx, id, st)
                if (st%failed()) return
            end do
        end subroutine clause
    end subroutine eval_comprehension

    !> f'...{expr!conv:spec}...': the text of each field formatted by its spec.
    recursive subroutine eval_fstring(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        character(len=:), allocatable :: text, piece, spec_text
        type(value_t) :: x, spec
        integer :: k, part
        text = ''
        do k = 1, ctx%ast%nkids(id)
            part = ctx%ast%kid(id, k)
            if (ctx%ast%nodes(part)%kind == N_STR) then
                text = text // ctx%ast%nodes(part)%text
                cycle
            end if
            call eval(ctx, ctx%ast%kid(part, 1), x, st, frame)
            if (st%failed()) return
            spec_text = ''
            if (ctx%ast%nkids(part) > 1) then
                call eval_fstring(ctx, ctx%ast%kid(part, 2), spec, st, frame)
                if (st%failed()) return
                if (spec%kind == VK_UNKNOWN) x = spec
                if (spec%kind == VK_STR) spec_text = spec%s
            end if
            if (x%kind == VK_UNKNOWN) then
                v = x; return
            end if
            select case (ctx%ast%nodes(part)%text)
            case ('r', 'a')
                x = str_value(text_of(ctx, x, .true.))
            case ('s')
                x = str_value(text_of(ctx, x, .false.))
            end select
            call format_value(ctx, part, x, spec_text, piece, st)
            if (st%failed()) return
            if (len(text) + len(piece) > MAX_REPEAT) then
                call fail(st, ctx, id, 'string too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
            end if
            text = text // piece
        end do
        v = str_value(text)
    end subroutine eval_fstring

    !> format(v, spec): numbers and strings by the format mini-language (deck_format);
    !> other values by their text when the spec is empty.
    module procedure format_value
        type(format_spec_t) :: fs
        character(len=:), allocatable :: message
        text = ''
        if (len(spec) == 0) then
            text = text_of(ctx, v, .false.)
            return
        end if
        call parse_spec(spec, fs, message)
        if (len(message) == 0) then
            select case (v%kind)
            case (VK_INT)
                call format_int(v%i, fs, text, message)
            case (VK_BOOL)
                if (fs%type == ' ') then
                    call format_text(text_of(ctx, v, .false.), fs, text, message)
                else
                    call format_int(v%i, fs, text, message)
                end if
            case (VK_REAL)
                call format_real(v%r, fs, text, message)
            case (VK_STR)
                call format_text(v%s, fs, text, message)
            case default
                message = 'format spec ''' // spec // ''' applies to numbers and strings, ' // &
                    'not to ' // kind_label(v) // ' (format str(x) instead)'
            end select
        end if
        if (len(message) > 0) call fail(st, ctx, id, message)
    end procedure format_value

    ! ---- names ------------------------------------------------------------------------------

    !> Name lookup: the locals of the def (or comprehension, and the frames around it),
    !> the names of the code's namespace (the session's or its module's), the built-ins.
    module procedure lookup
        character(len=:), allocatable :: name
        integer :: k
        type(frame_t), pointer :: f
        name = ctx%ast%nodes(id)%text
        if (present(frame)) then
            f => frame
            do while (associated(f))
                do k = f%n, 1, -1
                    if (f%names(k)%s == name) then
                        v = f%values(k)
                        return
                    end if
                end do
                if (.not. f%comprehension) exit
                f => f%enclosing
            end do
        end if
        k = ctx%find_symbol(name, scope_of(ctx, id))
        if (k > 0) then
            v = ctx%symbols(k)%value
            return
        end if
        select case (name)
        case ('pi', 'math.pi')
            v = real_value(PI_VALUE); return
        case ('math.e')
            v = real_value(E_VALUE); return
        case ('True')
            v = bool_value(.true.); return
        case ('False')
            v = bool_value(.false.); return
        case ('None')
            v%kind = VK_NONE; return
        end select
        if (is_builtin(name) .or. builtin_id(name) > 0) then
            v%kind = VK_BUILTIN; v%s = name
            if (index(name, 'math.') == 1) v%s = name(6:)
            return
        end if
        if (ctx%catalog%find_command(name) > 0 .or. name == '_F') then
            call fail(st, ctx, id, name // ' is a command: call it with (KEYWORD=value, ...)')
            return
        end if
        call undefined_name(ctx, id, name, st)
    end procedure lookup

    !> "name 'X' is not defined", or "used before it is assigned" when a later statement
    !> assigns it, with a suggestion.
    subroutine undefined_name(ctx, id, name, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        integer :: k, s, root, src
        type(string_t), allocatable :: known(:)
        if (len(name) > 5) then
            if (name(1:5) == 'math.') then
                call fail(st, ctx, id, name // ' is not a known math function (known: ' // &
                    'sqrt exp log log10 sin cos tan asin acos atan atan2 sinh cosh tanh ' // &
                    'floor ceil fabs hypot degrees radians, and the constants pi e)')
                return
            end if
        end if
        if (ctx%stashed_name(name) .and. scope_of(ctx, id) == SCOPE_SESSION) then
            call fail(st, ctx, id, 'name ' // name // ' is not defined yet in this file: ' // &
                'it belongs to the session of the earlier command files (continue it with ' // &
                'POURSUITE() before this line)')
            return
        end if
        root = ctx%ast%root
        src = ctx%source_of_file(int(ctx%ast%nodes(id)%file))
        if (src > 0) root = ctx%sources(src)%root
        do k = 1, ctx%ast%nkids(root)
            s = ctx%ast%kid(root, k)
            if ((ctx%ast%nodes(s)%kind == N_ASSIGN .or. ctx%ast%nodes(s)%kind == N_DEF) .and. &
                ctx%ast%nodes(s)%text == name .and. s /= ctx%statement) then
                if (ctx%ast%nodes(s)%line >= ctx%ast%nodes(id)%line) then
                    call fail(st, ctx, id, 'name ' // name // ' is used before it is ' // &
                        'assigned (assigned at line ' // to_text(ctx%ast%nodes(s)%line) // &
                        '; move that statement first)')
                    return
                end if
            end if
        end do
        allocate (known(0))
        do k = 1, ctx%nsymbol
            if (ctx%symbols(k)%scope == scope_of(ctx, id)) &
                call append_string(known, ctx%symbols(k)%name)
        end do
        do k = 1, ctx%catalog%ncmd
            call append_string(known, ctx%catalog%cmds(k)%name)
        end do
        call fail(st, ctx, id, 'name ' // name // ' is not defined' // &
                  did_you_mean(name, known))
    end subroutine undefined_name

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

    !> seq[start:stop:step] of a list (a new list), a tuple or a string.
    recursive subroutine eval_slice(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: seq, b
        type(value_t), allocatable :: items(:), picked(:)
        character(len=:), allocatable :: message, parts, text
        logical :: given(3)
        integer(i8) :: bounds(3)
        integer :: k, j, first, step, count
        call eval(ctx, ctx%ast%kid(id, 1), seq, st, frame)
        if (st%failed()) return
        given = .false.; bounds = 0
        parts = ctx%ast%nodes(id)%text
        j = 1
        do k = 1, 3
            if (parts(k:k) /= '1') cycle
            j = j + 1
            call eval(ctx, ctx%ast%kid(id, j), b, st, frame)
            if (st%failed()) return
            if (b%kind == VK_NONE) cycle
            if (b%kind == VK_UNKNOWN) then
                v = b; return
            end if
            if (b%kind /= VK_INT .and. b%kind /= VK_BOOL) then
                call fail(st, ctx, ctx%ast%kid(id, j), 'slice bounds must be integers, got ' &
                          // kind_label(b) // ' (use int(...))'); return
            end if
            given(k) = .true.; bounds(k) = b%i
        end do
        select case (seq%kind)
        case (VK_UNKNOWN)
            v = seq; return
        case (VK_LIST)
            items = ctx%heap%items_of(seq%i)
        case (VK_TUPLE)
            call iterate(ctx, id, seq, items, st)
        case (VK_STR)
            items = characters(seq%s)
        case default
            call fail(st, ctx, id, kind_label(seq) // ' cannot be sliced (only a list, a ' // &
                      'tuple or a string)'); return
        end select
        call slice_positions(size(items), given, bounds, first, step, count, message)
        if (len(message) > 0) then
            call fail(st, ctx, id, message); return
        end if
        call count_built(ctx, id, int(count, i8), st)
        if (st%failed()) return
        allocate (picked(count))
        do k = 1, count
            picked(k) = items(first + (k - 1) * step)
        end do
        select case (seq%kind)
        case (VK_LIST)
            v = new_list(ctx, picked)
            call check_heap(ctx, id, st)
        case (VK_TUPLE)
            v = sequence_value(VK_TUPLE, picked)
        case default
            text = ''
            do k = 1, count
                text = text // picked(k)%s
            end do
            v = str_value(text)
        end select
    end subroutine eval_slice

    !> The characters of a UTF-8 string (code points, not bytes), each a string value.
    function characters(s) result(chars)
        character(len=*), intent(in) :: s
        type(value_t), allocatable :: chars(:)
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
    end function characters

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
            text = '<built-in function ' // v%s // '>'
        case (VK_MODULE)
            text = '<module ''' // v%s // '''>'
        case (VK_METHOD)
            text = '<method ' // v%s // '>'
        case (VK_UNKNOWN)
            text = '<known when the deck runs>'
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

    ! ---- operators --------------------------------------------------------------------------

    recursive subroutine unary(ctx, id, a, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: a
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
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
    end subroutine unary

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
    recursive subroutine compare_chain(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
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
    end subroutine compare_chain

    !> One comparison a OP b.
    recursive subroutine compare_pair(ctx, id, op, a, b, r, st)
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

end submodule deck_interp_expressions

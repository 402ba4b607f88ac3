!> The deck evaluator (deck_interpreter), its expressions: literals and names, displays of
!> tuples, lists and dicts, comprehensions, lambdas, f-strings and the format specs of
!> values, slices (operators: deck_interp_operators; items, text, equality:
!> deck_interp_values).
submodule(deck_interpreter) deck_interp_expressions
    use deck_math, only: literal_out_of_range, builtin_id, PI_VALUE, E_VALUE
    use deck_format, only: format_spec_t, parse_spec, format_real, format_int, format_text
    use deck_sequence, only: slice_positions
    use deck_suggest, only: did_you_mean
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
        case ('CA', 'code_aster')
            ! run_aster starts a command file with `import code_aster` and
            ! `from code_aster import CA` (run_aster/command_files.py): stand-ins here
            v%kind = VK_MODULE; v%s = 'code_aster'
            if (name == 'CA') v%s = 'code_aster.CA'
            return
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

end submodule deck_interp_expressions

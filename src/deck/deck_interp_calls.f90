!> The deck evaluator (deck_interpreter), its calls: command calls (validated against the
!> catalog, then run by their handler), calls of def functions and lambdas with Python's
!> binding of positional, keyword, *args and **kwargs arguments and defaults, calls of
!> built-ins and of function concepts, attributes and methods (of concepts through the
!> registry of doc/architecture.md "Concept methods", of modules, of strings, lists, dicts
!> and tuples).
submodule(deck_interpreter) deck_interp_calls
    use status, only: add_context, STATUS_NOT_IMPLEMENTED, STATUS_INTERNAL
    use deck_math, only: builtin_id, PI_VALUE, E_VALUE
    use deck_suggest, only: did_you_mean
    use deck_concept, only: concept_t, placeholder_concept_t, concept_display_name
    use deck_command, only: command_t
    use deck_testcase, only: testcase_t
    use deck_validate, only: validate_command
    use run_context, only: method_call_t
    implicit none

contains

    module procedure eval_call
        integer :: callee, icmd
        type(value_t) :: f, obj
        type(value_t), allocatable :: args(:)
        type(value_t) :: kwargs
        character(len=:), allocatable :: name
        callee = ctx%ast%kid(id, 1)
        if (ctx%ast%nodes(callee)%kind == N_NAME) then
            name = ctx%ast%nodes(callee)%text
            if (.not. shadowed(ctx, name, scope_of(ctx, id), frame)) then
                icmd = ctx%catalog%find_command(name)
                if (icmd > 0 .or. name == '_F') then
                    call eval_arguments(ctx, id, args, kwargs, st, frame, repeats=icmd > 0)
                    if (st%failed()) return
                    if (size(args) > 0) then
                        call fail(st, ctx, id, name // ' takes keyword arguments only ' // &
                                  '(KEYWORD=value)'); return
                    end if
                    if (icmd > 0) then
                        call run_command(ctx, icmd, callee, kwargs, v, st, target)
                    else
                        v = kwargs
                        v%kind = VK_FACTOR
                    end if
                    return
                end if
                if (is_command_like(name) .and. .not. is_builtin(name) .and. &
                    builtin_id(name) == 0) then
                    call fail(st, ctx, callee, 'unknown command ' // name // &
                              did_you_mean(name, command_names(ctx)))
                    return
                end if
            end if
        end if
        if (ctx%ast%nodes(callee)%kind == N_ATTR) then
            call eval(ctx, ctx%ast%kid(callee, 1), obj, st, frame)
            if (st%failed()) return
            call eval_arguments(ctx, id, args, kwargs, st, frame)
            if (st%failed()) return
            call call_method(ctx, callee, obj, ctx%ast%nodes(callee)%text, args, kwargs, v, &
                             st, frame)
            return
        end if
        call eval(ctx, callee, f, st, frame)
        if (st%failed()) return
        call eval_arguments(ctx, id, args, kwargs, st, frame)
        if (st%failed()) return
        call call_value(ctx, callee, f, args, kwargs, v, st, frame)
    end procedure eval_call

    !> True when `name` is a local of the running def (or comprehension) or a name of
    !> namespace `scope`.
    logical function shadowed(ctx, name, scope, frame)
        type(run_context_t), intent(in) :: ctx
        character(len=*), intent(in) :: name
        integer, intent(in) :: scope
        type(frame_t), intent(in), optional, target :: frame
        type(frame_t), pointer :: f
        integer :: k
        shadowed = ctx%find_symbol(name, scope) > 0
        if (shadowed .or. .not. present(frame)) return
        f => frame
        do while (associated(f))
            do k = 1, f%n
                if (f%names(k)%s == name) shadowed = .true.
            end do
            if (shadowed .or. .not. f%comprehension) return
            f => f%enclosing
        end do
    end function shadowed

    !> Upper-case names with an underscore or of 4+ letters look like command names.
    pure logical function is_command_like(name)
        character(len=*), intent(in) :: name
        integer :: i
        is_command_like = len(name) >= 4
        do i = 1, len(name)
            if (index('ABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789', name(i:i)) == 0) &
                is_command_like = .false.
        end do
    end function is_command_like

    function command_names(ctx) result(names)
        type(run_context_t), intent(in) :: ctx
        type(string_t), allocatable :: names(:)
        integer :: k
        allocate (names(ctx%catalog%ncmd))
        do k = 1, ctx%catalog%ncmd
            names(k)%s = ctx%catalog%cmds(k)%name
        end do
    end function command_names

    !> Positional arguments (`*seq` unpacked) and keyword arguments (`**dict` unpacked) as a
    !> VK_FACTOR value located at the callee; a keyword given twice is an error (kept when
    !> `repeats`: a command's catalog validation reports it at its keyword).
    recursive subroutine eval_arguments(ctx, id, args, kwargs, st, frame, repeats)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), allocatable, intent(out) :: args(:)
        type(value_t), intent(out) :: kwargs
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        logical, intent(in), optional :: repeats
        type(value_list_t) :: kw
        type(value_t) :: x
        type(value_t), allocatable :: more(:), keys(:)
        integer :: k, a, j
        allocate (args(0), kw%items(0), kw%keys(0), kw%key_line(0), kw%key_col(0))
        do k = 2, ctx%ast%nkids(id)
            a = ctx%ast%kid(id, k)
            select case (ctx%ast%nodes(a)%kind)
            case (N_KWARG)
                call eval(ctx, ctx%ast%kid(a, 1), x, st, frame)
                if (st%failed()) return
                call add_keyword(ctx%ast%nodes(a)%text, x, a)
            case (N_DSTAR)
                call eval(ctx, ctx%ast%kid(a, 1), x, st, frame)
                if (st%failed()) return
                if (x%kind == VK_FACTOR) then               ! a _F is a dict in Code_Aster
                    call add_factor(x)
                    if (st%failed()) return
                    cycle
                end if
                if (x%kind /= VK_DICT) then
                    call fail(st, ctx, a, '**x in a call needs a dict, got ' // kind_label(x))
                    return
                end if
                keys = ctx%heap%keys_of(x%i)
                do j = 1, size(keys)
                    if (keys(j)%kind /= VK_STR) then
                        call fail(st, ctx, a, '**x in a call needs text keys (keyword ' // &
                                  'names), got ' // kind_label(keys(j))); return
                    end if
                    call add_keyword(keys(j)%s, ctx%heap%get(x%i, j), a)
                    if (st%failed()) return
                end do
            case (N_STARRED)
                call eval(ctx, ctx%ast%kid(a, 1), x, st, frame)
                if (st%failed()) return
                call iterate(ctx, a, x, more, st)
                if (st%failed()) return
                args = joined(args, more)
            case default
                call eval(ctx, a, x, st, frame)
                if (st%failed()) return
                call append_value(args, x)
            end select
            if (st%failed()) return
        end do
        kwargs = pack_values(VK_FACTOR, kw)
        kwargs%line = ctx%ast%nodes(ctx%ast%kid(id, 1))%line
        kwargs%col = ctx%ast%nodes(ctx%ast%kid(id, 1))%col
    contains
        subroutine add_keyword(name, value, node)
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: value
            integer, intent(in) :: node
            integer :: i
            do i = 1, size(kw%keys)
                if (present(repeats)) then
                    if (repeats) exit        ! a command: the catalog reports it, located
                end if
                if (kw%keys(i)%s == name) then
                    call fail(st, ctx, node, 'keyword argument ' // name // ' given twice')
                    return
                end if
            end do
            call append_value(kw%items, value)
            call append_string(kw%keys, name)
            kw%key_line = [kw%key_line, int(ctx%ast%nodes(node)%line)]
            kw%key_col = [kw%key_col, int(ctx%ast%nodes(node)%col)]
        end subroutine add_keyword
        !> **occ with a _F: its keywords added.
        subroutine add_factor(occ)
            type(value_t), intent(in) :: occ
            type(value_list_t) :: extra
            integer :: i
            if (nitems(occ) == 0) return
            extra = unpack_value(occ)
            do i = 1, size(extra%items)
                call add_keyword(extra%keys(i)%s, extra%items(i), a)
            end do
        end subroutine add_factor
    end subroutine eval_arguments

    !> Calls a callable value: a built-in, a def or lambda, a function concept (F(0.5)),
    !> a bound method.
    module procedure call_value
        type(value_t) :: receiver
        select case (f%kind)
        case (VK_DEF)
            call call_def(ctx, id, f, args, kwargs, v, st, frame)
            return
        case (VK_UNKNOWN)
            v%kind = VK_UNKNOWN; return
        case (VK_METHOD)
            receiver = item(f, 1)
            call call_method(ctx, id, receiver, f%s, args, kwargs, v, st, frame)
            return
        end select
        if (any(args%kind == VK_UNKNOWN)) then
            v%kind = VK_UNKNOWN; return
        end if
        select case (f%kind)
        case (VK_BUILTIN)
            call call_builtin(ctx, id, f%s, args, kwargs, v, st, frame)
        case (VK_FACTOR)
            if (allocated(f%s)) then
                if (f%s == 'UserMacro') then             ! deck_interp_macros
                    call call_user_macro(ctx, id, f, args, kwargs, v, st, frame)
                    return
                end if
            end if
            call fail(st, ctx, id, kind_label(f) // ' cannot be called')
        case (VK_CONCEPT)
            call call_concept(ctx, id, f, args, kwargs, v, st)
        case (VK_MODULE)
            call fail(st, ctx, id, unavailable(f))
        case default
            call fail(st, ctx, id, kind_label(f) // ' cannot be called')
        end select
    end procedure call_value

    !> What an object of a module parasol does not provide says when it is used.
    function unavailable(m) result(text)
        type(value_t), intent(in) :: m
        character(len=:), allocatable :: text
        integer :: dot
        character(len=:), allocatable :: module
        module = m%s
        dot = index(module, '.')
        if (dot > 0) module = module(1:dot - 1)
        select case (module)
        case ('numpy', 'scipy')
            text = m%s // ': parasol does not provide ' // module // ' (its arrays and ' // &
                'solvers are not part of the deck language; write the values with lists, ' // &
                'loops and math)'
        case ('code_aster')
            text = m%s // ': parasol does not provide Code_Aster''s Python library ' // &
                '(its objects and macros); of it the deck language has the commands and ' // &
                'CA.TestCase'
        case default
            text = m%s // ': parasol does not provide the Python module ' // module
        end select
    end function unavailable

    !> F(x, ...) for a function concept: it evaluates (through concept_t%call_real) with
    !> numbers in NOM_PARA order; other concepts refuse. A placeholder (check pass) gives a
    !> value known when the deck runs.
    subroutine call_concept(ctx, id, f, args, kwargs, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: f
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(status_t) :: cst
        real(dp) :: y
        integer :: k
        class(concept_t), pointer :: ptr
        if (.not. associated(f%obj)) then
            call fail(st, ctx, id, 'this concept cannot be called'); return
        end if
        ptr => f%obj
        select type (ptr)
        type is (placeholder_concept_t)
            ! check pass: a function made when the deck runs gives a value then; a concept
            ! of another type cannot be called, as its handler would say
            select case (ptr%type_name())
            case ('fonction', 'formule', 'fonction_c', 'nappe')
                v%kind = VK_UNKNOWN; return
            end select
            if (ctx%find_method(ptr%type_name(), '__call__', .true.) > 0) then
                v%kind = VK_UNKNOWN; return
            end if
            call fail(st, ctx, id, 'a concept of type ' // ptr%type_name() // &
                      ' cannot be called'); return
        end select
        if (has_method(ctx, f, '__call__')) then
            call use_attribute(ctx, id, f, '__call__', .true., args, kwargs, v, st)
            return
        end if
        if (nitems(kwargs) > 0) then
            call fail(st, ctx, id, 'a function concept takes its parameters in NOM_PARA ' // &
                      'order, without keywords'); return
        end if
        do k = 1, size(args)
            if (.not. is_number(args(k))) then
                call fail(st, ctx, id, 'a function takes numbers, got ' // kind_label(args(k)))
                return
            end if
        end do
        call f%obj%call_real(as_real(args), y, cst)
        if (cst%failed()) then
            call fail(st, ctx, id, cst%message); return
        end if
        v = real_value(y)
    end subroutine call_concept

    !> Calls def (or lambda) function value f, its parameters bound as Python binds them:
    !> positional arguments first, then keyword arguments by name, then the defaults;
    !> extra positional ones go to *args (a tuple), extra keywords to **kwargs (a dict).
    recursive subroutine call_def(ctx, id, f, args, kwargs, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: f
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(frame_t), target :: local
        type(value_list_t) :: kw, captured
        type(value_t) :: defaults, extra_kw
        type(value_t), allocatable :: extra(:), values(:)
        integer :: node, np, k, j, p, star, dstar, nnamed, ndef, first_default, body
        logical, allocatable :: bound(:)
        character(len=:), allocatable :: fname
        type(string_t), allocatable :: names(:)
        node = int(f%i)
        fname = f%s
        np = ctx%ast%nkids(node) - 1
        body = ctx%ast%kid(node, np + 1)
        local%depth = 1
        if (present(frame)) local%depth = frame%depth + 1
        if (local%depth > MAX_CALL_DEPTH) then
            call fail(st, ctx, id, 'def calls nested deeper than ' // &
                      to_text(int(MAX_CALL_DEPTH, i4)) // ' (deep recursion is not supported)')
            return
        end if
        ! parameters: named ones (nnamed, some with defaults), *args, **kwargs
        star = 0; dstar = 0; nnamed = 0
        allocate (names(0))
        do k = 1, np
            p = ctx%ast%kid(node, k)
            select case (ctx%ast%nodes(p)%kind)
            case (N_STARRED)
                star = k
            case (N_DSTAR)
                dstar = k
            case default
                nnamed = nnamed + 1
                call append_string(names, ctx%ast%nodes(p)%text)
            end select
        end do
        allocate (values(nnamed), bound(nnamed))
        bound = .false.
        allocate (extra(0))
        do k = 1, size(args)
            if (k <= nnamed) then
                values(k) = args(k); bound(k) = .true.
            else if (star > 0) then
                call append_value(extra, args(k))
            else
                call fail(st, ctx, id, fname // '() takes ' // to_text(nnamed) // &
                    ' positional argument(s) but ' // to_text(size(args)) // ' were given')
                return
            end if
        end do
        extra_kw = ctx%heap%new_dict()
        kw = unpack_value(kwargs)
        do k = 1, size(kw%keys)
            j = 0
            do p = 1, nnamed
                if (names(p)%s == kw%keys(k)%s) j = p
            end do
            if (j > 0) then
                if (bound(j)) then
                    call fail(st, ctx, id, fname // '() got several values for argument ' // &
                              kw%keys(k)%s); return
                end if
                values(j) = kw%items(k); bound(j) = .true.
            else if (dstar > 0) then
                call ctx%heap%dict_set(extra_kw%i, str_value(kw%keys(k)%s), kw%items(k))
            else
                call fail(st, ctx, id, fname // '() got an unexpected keyword argument ' // &
                    kw%keys(k)%s // did_you_mean(kw%keys(k)%s, names)); return
            end if
        end do
        ! defaults: of the named parameters that have one, in order (function_value)
        defaults = item(f, 1)
        ndef = nitems(defaults)
        first_default = nnamed - ndef + 1
        do k = 1, nnamed
            if (bound(k)) cycle
            if (k >= first_default .and. ndef > 0) then
                values(k) = item(defaults, k - first_default + 1)
            else
                call fail(st, ctx, id, fname // '() is missing its argument ' // names(k)%s)
                return
            end if
        end do
        ! the frame: the names it captured where it was made, then its parameters
        captured = unpack_value(item(f, 2))
        allocate (local%names(0), local%values(0))
        if (allocated(captured%keys)) then
            do k = 1, size(captured%keys)
                call add_local(captured%keys(k)%s, captured%items(k))
            end do
        end if
        do k = 1, nnamed
            call add_local(names(k)%s, values(k))
        end do
        if (star > 0) call add_local(ctx%ast%nodes(ctx%ast%kid(node, star))%text, &
                                     sequence_value(VK_TUPLE, extra))
        if (dstar > 0) call add_local(ctx%ast%nodes(ctx%ast%kid(node, dstar))%text, extra_kw)
        ctx%gc_hold = ctx%gc_hold + 1
        if (ctx%ast%nodes(node)%kind == N_LAMBDA) then
            call eval(ctx, body, v, st, local)
        else
            call exec_block(ctx, body, st, local)
            if (local%returned) then
                v = local%ret
            else
                v%kind = VK_NONE
            end if
        end if
        ctx%gc_hold = ctx%gc_hold - 1
    contains
        subroutine add_local(name, value)
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: value
            integer :: i
            do i = 1, local%n
                if (local%names(i)%s == name) then
                    local%values(i) = value; return
                end if
            end do
            call append_string(local%names, name)
            call append_value(local%values, value)
            local%n = local%n + 1
        end subroutine add_local
    end subroutine call_def

    !> Calls def function `def_node` with positional values `args` (its defaults as written
    !> when it was defined are not known here: every parameter must be given).
    !>  call_id : AST node of the call (for messages);  frame : the caller's frame (depth)
    module procedure call_def_values
        type(value_t) :: f
        f = sequence_value(VK_TUPLE, values_of(sequence_value(VK_TUPLE, args(1:0)), &
                                               pack_values(VK_FACTOR, empty_list())))
        f%kind = VK_DEF
        f%i = def_node
        f%s = ctx%ast%nodes(def_node)%text
        call call_def(ctx, call_id, f, args, empty_kwargs(), v, st, frame)
    contains
        function empty_list() result(list)
            type(value_list_t) :: list
            allocate (list%items(0), list%keys(0), list%key_line(0), list%key_col(0))
        end function empty_list
    end procedure call_def_values

    ! ---- attributes and methods -------------------------------------------------------------

    !> obj.name read as a value: a concept's attribute (registry), a math function or
    !> constant, a bound method of a string, list, dict or tuple (`f = L.append`).
    module procedure get_attribute
        type(value_t), allocatable :: none(:)
        integer :: k
        select case (obj%kind)
        case (VK_UNKNOWN)
            v = obj
        case (VK_CONCEPT)
            allocate (none(0))
            if (is_testcase(obj)) then
                call testcase_method(ctx, id, obj, name, .false., none, empty_kwargs(), v, st)
                return
            end if
            call use_attribute(ctx, id, obj, name, .false., none, empty_kwargs(), v, st)
        case (VK_MODULE)
            if (obj%i > 0) then                               ! a module of the deck
                k = ctx%find_symbol(name, int(obj%i))
                if (k == 0) then
                    call fail(st, ctx, id, 'module ' // obj%s // ' has no name ' // name)
                    return
                end if
                v = ctx%symbols(k)%value
            else if (obj%i < 0) then                          ! math
                select case (name)
                case ('pi')
                    v = real_value(PI_VALUE)
                case ('e')
                    v = real_value(E_VALUE)
                case default
                    if (is_builtin('math.' // name) .or. builtin_id(name) > 0) then
                        v%kind = VK_BUILTIN; v%s = name
                    else
                        call fail(st, ctx, id, 'math.' // name // ' is not a math function ' // &
                            'parasol knows (sqrt exp log log10 sin cos tan asin acos atan ' // &
                            'atan2 sinh cosh tanh floor ceil fabs hypot degrees radians pi e)')
                    end if
                end select
            else if (name == 'TestCase' .and. (obj%s == 'code_aster.CA' .or. &
                     obj%s == 'code_aster.Utilities')) then
                v%kind = VK_BUILTIN; v%s = 'TestCase'      ! CA.TestCase: deck_interp_testcase
            else
                call fail(st, ctx, id, unavailable(str_value(obj%s // '.' // name)))
            end if
        case (VK_STR, VK_LIST, VK_DICT, VK_TUPLE, VK_FACTOR)
            if (.not. type_has_method(obj%kind, name)) then
                call fail(st, ctx, id, kind_label(obj) // ' has no attribute ' // name)
                return
            end if
            v = sequence_value(VK_TUPLE, values_of(obj))
            v%kind = VK_METHOD
            v%s = name
        case default
            call fail(st, ctx, id, kind_label(obj) // ' has no attribute ' // name // &
                      ' in the deck language')
        end select
    end procedure get_attribute

    !> obj.name(args): a concept's method (registry), a math function, a method of a
    !> string, list, dict or tuple.
    module procedure call_method
        type(value_t) :: f
        select case (obj%kind)
        case (VK_UNKNOWN)
            v = obj
        case (VK_CONCEPT)
            if (is_testcase(obj)) then
                call testcase_method(ctx, id, obj, name, .true., args, kwargs, v, st)
                return
            end if
            call use_attribute(ctx, id, obj, name, .true., args, kwargs, v, st)
        case (VK_MODULE)
            call get_attribute(ctx, id, obj, name, f, st)
            if (st%failed()) return
            call call_value(ctx, id, f, args, kwargs, v, st, frame)
        case (VK_STR, VK_LIST, VK_DICT, VK_TUPLE, VK_FACTOR)
            call type_method(ctx, id, obj, name, args, kwargs, v, st, frame)
        case default
            call fail(st, ctx, id, kind_label(obj) // ' has no method ' // name // &
                      ' in the deck language')
        end select
    end procedure call_method

    !> obj.name, obj.name(args...), obj[index], operators and len() on a concept: the
    !> handler registered for its type (ctx%register_method), with flat copies of the
    !> arguments; its result's lists become lists of the deck. In the check pass a
    !> placeholder concept stands for what a command will make: the value is known only
    !> when the deck runs (VK_UNKNOWN).
    !>  id : the AST node the use is located at;  called : obj.name(...) rather than obj.name
    module procedure use_attribute
        type(method_call_t) :: call
        type(status_t) :: hst
        class(concept_t), pointer :: ptr
        type(value_t) :: flat
        integer :: k, j
        character(len=:), allocatable :: what, message
        if (obj%kind == VK_UNKNOWN .or. any(args%kind == VK_UNKNOWN)) then
            v%kind = VK_UNKNOWN; return
        end if
        what = name
        if (called .and. name(1:min(2, len(name))) /= '__') what = name // '()'
        if (obj%kind /= VK_CONCEPT .or. .not. associated(obj%obj)) then
            call fail(st, ctx, id, kind_label(obj) // ' has no attribute ' // name // &
                ' in the deck language'); return
        end if
        ptr => obj%obj
        select type (ptr)
        type is (placeholder_concept_t)
            v%kind = VK_UNKNOWN; return           ! check pass: made when the deck runs
        end select
        k = ctx%find_method(ptr%type_name(), name, called)
        if (k == 0) then
            call fail(st, ctx, id, 'a concept of type ' // ptr%type_name() // ' (' // &
                concept_display_name(ptr) // ') has no ' // method_word(name) // ' ' // what &
                // ' in parasol' // did_you_mean(name, ctx%method_names(ptr%type_name())) // &
                provided(ctx%method_names(ptr%type_name()))); return
        end if
        call%name = name
        call%called = called
        allocate (call%args(size(args)))
        do j = 1, size(args)
            call ctx%heap%flatten(args(j), call%args(j), message)
            if (len(message) > 0) then
                call fail(st, ctx, id, message); return
            end if
        end do
        call ctx%heap%flatten(kwargs, call%kwargs, message)
        if (len(message) > 0) then
            call fail(st, ctx, id, message); return
        end if
        call ctx%methods(k)%run(ctx, ptr, call, flat, hst)
        if (hst%failed()) then
            call fail(st, ctx, id, ptr%type_name() // ' ' // what // ': ' // hst%message)
            return
        end if
        v = ctx%heap%adopt(flat)
        call check_heap(ctx, id, st)
        if (v%line == 0) then
            v%line = ctx%ast%nodes(id)%line; v%col = ctx%ast%nodes(id)%col
        end if
    contains
        pure function method_word(n) result(word)
            character(len=*), intent(in) :: n
            character(len=:), allocatable :: word
            word = 'attribute'
            if (called) word = 'method'
            if (n(1:min(2, len(n))) == '__') word = 'operation'
        end function method_word
        function provided(names) result(text)
            type(string_t), intent(in) :: names(:)
            character(len=:), allocatable :: text
            integer :: j
            text = ' (it has none)'
            if (size(names) == 0) return
            text = ' (it has: '
            do j = 1, size(names)
                if (j > 1) text = text // ', '
                text = text // names(j)%s
            end do
            text = text // ')'
        end function provided
    end procedure use_attribute

    !> True when value v is a CA.TestCase (its methods are the interpreter's).
    logical function is_testcase(v)
        type(value_t), intent(in) :: v
        is_testcase = .false.
        if (.not. associated(v%obj)) return
        select type (o => v%obj)
        type is (testcase_t)
            is_testcase = .true.
        end select
    end function is_testcase

    !> True when value v is a concept (not a placeholder) with a handler for `name`.
    module procedure has_method
        has_method = .false.
        if (v%kind /= VK_CONCEPT .or. .not. associated(v%obj)) return
        has_method = ctx%find_method(v%obj%type_name(), name, .true.) > 0
    end procedure has_method

    ! ---- commands ---------------------------------------------------------------------------

    !> Command `name` of the catalog run from the interpreter itself (a function of
    !> Code_Aster's library that is a command underneath), located at node id.
    module procedure run_catalog_command
        integer :: icmd
        icmd = ctx%catalog%find_command(name)
        if (icmd == 0) then
            call fail(st, ctx, id, 'unknown command ' // name); return
        end if
        call run_command(ctx, icmd, id, kwargs, v, st)
    end procedure run_catalog_command

    !> Validates and runs (or, in the check pass, stands in for) catalog command icmd. Its
    !> keyword values are flat copies (a list given to a command is the list as it is now).
    recursive subroutine run_command(ctx, icmd, name_node, kwargs_in, v, st, target)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: icmd, name_node
        type(value_t), intent(in) :: kwargs_in
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        character(len=*), intent(in), optional :: target
        type(command_t) :: cmd
        class(concept_t), allocatable :: result
        class(concept_t), pointer :: ptr
        type(value_t) :: kwargs
        integer :: h, line, col
        logical :: run_it
        character(len=:), allocatable :: file, message
        line = ctx%ast%nodes(name_node)%line; col = ctx%ast%nodes(name_node)%col
        file = node_file(ctx, name_node)
        if (ctx%finished) then
            call fail(st, ctx, name_node, 'command ' // ctx%catalog%cmds(icmd)%name // &
                      ' after FIN (FIN ends the deck)'); return
        end if
        if (ctx%import_depth > 0) then
            call fail(st, ctx, name_node, 'command ' // ctx%catalog%cmds(icmd)%name // &
                ' while a module is imported (a module gives def functions and values; ' // &
                'call commands in the command file)'); return
        end if
        if (ctx%checking .and. ctx%ncommand >= MAX_CHECKED_COMMANDS) then
            if (.not. ctx%check_stopped) ctx%check_stop_reason = 'the check pass ' // &
                'validated ' // to_text(MAX_CHECKED_COMMANDS) // ' commands, its limit'
            call stop_check(ctx, name_node)
            v%kind = VK_UNKNOWN
            return
        end if
        call ctx%heap%flatten(kwargs_in, kwargs, message)
        if (len(message) > 0) then
            call fail(st, ctx, name_node, ctx%catalog%cmds(icmd)%name // ': ' // message)
            return
        end if
        call ctx%deadline%check(ctx%catalog%cmds(icmd)%name // ' at ' // &
                                node_where(ctx, name_node), st)
        if (st%failed()) then
            call add_context(st, file=file, line=line, column=col); return
        end if
        call ctx%check_listings(ctx%catalog%cmds(icmd)%name // ' at ' // &
                                node_where(ctx, name_node), st)
        if (st%failed()) return
        if (ctx%checking .and. holds_unknown(kwargs)) then
            ! A keyword takes a value known only when the deck runs (a table's cell): the
            ! command is validated then; here it stands in with a placeholder.
            cmd%name = ctx%catalog%cmds(icmd)%name
            cmd%result_type = ctx%catalog%cmds(icmd)%result_type
        else
            call validate_command(ctx%catalog, icmd, kwargs, file, line, col, cmd, st)
            if (st%failed()) return
        end if
        cmd%source = statement_source(ctx)
        h = ctx%find_handler(cmd%name)
        if (h > 0 .and. associated(cmd%reuse)) then
            if (.not. ctx%handlers(h)%reuse) then
                call cmd%error_at('reuse', cmd%name // '(reuse=...), which modifies ' // &
                    concept_display_name(cmd%reuse) // ' in place, is not built yet in ' // &
                    'parasol (leave reuse out and give the result a new name)', st, &
                    STATUS_NOT_IMPLEMENTED)
                return
            end if
        end if
        run_it = h > 0
        if (ctx%checking .and. h > 0) run_it = ctx%handlers(h)%at_check .and. &
            .not. holds_unknown(kwargs)
        ctx%has_plain_result = .false.
        if (allocated(ctx%produced)) deallocate (ctx%produced)
        allocate (ctx%produced(0))
        if (.not. ctx%checking) then
            call echo_statement(ctx, cmd%name, line)
            if (h == 0) then
                call set_error(st, STATUS_NOT_IMPLEMENTED, cmd%name // &
                    ' is not implemented yet', file=file, line=line, column=col)
                return
            end if
        end if
        if (run_it) then
            block
                type(status_t) :: hst
                call ctx%handlers(h)%run(ctx, cmd, result, hst)
                if (hst%failed()) then
                    call add_context(hst, file=file, line=line, column=col, &
                                     command=cmd%name)
                    st = hst
                    return
                end if
            end block
        else if (len(cmd%result_type) > 0 .and. .not. associated(cmd%reuse) .and. &
                 cmd%result_type /= 'entier') then
            allocate (placeholder_concept_t :: result)
            select type (result)
            type is (placeholder_concept_t)
                result%kind_name = cmd%result_type
            end select
        end if
        ctx%ncommand = ctx%ncommand + 1
        if (cmd%name == 'FIN') ctx%finished = .true.
        call bind_outputs(st)
        if (st%failed()) return
        if (cmd%result_type == 'entier') then
            ! a plain value (DEFI_FICHIER's free unit), None when the command gave none;
            ! in the check pass, when the handler does not run, known when the deck runs
            v%kind = VK_NONE
            if (ctx%checking .and. .not. run_it) v%kind = VK_UNKNOWN
            if (ctx%has_plain_result) v = ctx%plain_result
            ctx%has_plain_result = .false.
            return
        end if
        if (.not. allocated(result) .and. associated(cmd%reuse)) then
            ! reuse=X: the command modified X in place; the result is X itself (as in
            ! Code_Aster, where the command's result is the reused object)
            v%kind = VK_CONCEPT
            v%obj => cmd%reuse
            v%s = cmd%reuse%type_name()
            v%line = line; v%col = col
            call ctx%write_mess('    -> ' // cmd%reuse%summary() // ', modified in place (reuse)')
            return
        end if
        if (.not. allocated(result)) then
            if (len(cmd%result_type) > 0) call set_error(st, STATUS_INTERNAL, cmd%name // &
                ' produced no result', file=file, line=line, column=col)
            return
        end if
        result%name = ''
        if (present(target)) result%name = target
        call ctx%own_concept(result, ptr, st)
        if (st%failed()) return
        v%kind = VK_CONCEPT
        v%obj => ptr
        v%s = ptr%type_name()
        v%line = line; v%col = col
        call ctx%write_mess('    -> ' // ptr%summary())
    contains
        !> The CO('NAME') outputs of the command: made by its handler (ctx%produce), or, in
        !> the check pass when it does not run, placeholders of a type known when it runs.
        subroutine bind_outputs(bst)
            type(status_t), intent(inout) :: bst
            class(concept_t), allocatable :: stand_in
            integer :: j
            if (.not. allocated(kwargs%tree)) return
            do j = 1, size(kwargs%tree)
                if (kwargs%tree(j)%kind /= VK_CO) cycle
                if (ctx%checking .and. .not. run_it) then
                    allocate (placeholder_concept_t :: stand_in)
                    select type (stand_in)
                    type is (placeholder_concept_t)
                        stand_in%kind_name = 'unknown'
                    end select
                    call ctx%produce(kwargs%tree(j)%s, stand_in, bst)
                    if (bst%failed()) return
                else if (.not. produced(kwargs%tree(j)%s)) then
                    call set_error(bst, STATUS_INTERNAL, cmd%name // ' did not make the ' // &
                        'concept ' // kwargs%tree(j)%s // ' it was asked for with CO(''' // &
                        kwargs%tree(j)%s // ''')', file=file, line=kwargs%tree(j)%line, &
                        column=kwargs%tree(j)%col)
                    return
                end if
            end do
        end subroutine bind_outputs
        logical function produced(name)
            character(len=*), intent(in) :: name
            integer :: j
            produced = .false.
            do j = 1, size(ctx%produced)
                if (ctx%produced(j)%s == name) produced = .true.
            end do
        end function produced
    end subroutine run_command

    !> Writes the statement being evaluated to the .mess once, with its line numbers.
    subroutine echo_statement(ctx, name, line)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: name
        integer, intent(in) :: line
        integer :: l, first, last
        character(len=8) :: buf
        if (ctx%echoed == ctx%statement) then
            call ctx%write_mess('  -- ' // name // ' (line ' // to_text(int(line, i4)) // ')')
            return
        end if
        ctx%echoed = ctx%statement
        first = ctx%ast%nodes(ctx%statement)%line
        last = max(first, ctx%ast%nodes(ctx%statement)%end_line)
        call ctx%write_mess('')
        call ctx%write_mess('# ---- ' // name // ' (line ' // to_text(int(line, i4)) // ')')
        do l = first, min(last, size(ctx%lines))
            write (buf, '(i6)') l
            call ctx%write_mess(buf(1:6) // ' | ' // ctx%lines(l)%s)
        end do
    end subroutine echo_statement

    function statement_source(ctx) result(text)
        type(run_context_t), intent(in) :: ctx
        character(len=:), allocatable :: text
        integer :: l
        text = ''
        if (ctx%statement == 0) return
        do l = ctx%ast%nodes(ctx%statement)%line, &
               min(ctx%ast%nodes(ctx%statement)%end_line, size(ctx%lines))
            if (len(text) > 0) text = text // achar(10)
            text = text // ctx%lines(l)%s
        end do
    end function statement_source

end submodule deck_interp_calls

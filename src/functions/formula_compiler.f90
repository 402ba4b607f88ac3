!> Compiles a FORMULE VALE expression (and the `def` functions it calls) to bytecode.
!> Names in VALE resolve, in order, to: a NOM_PARA parameter; a deck object bound by an
!> extra FORMULE keyword (Pression=Pression); a deck variable (number, def, function);
!> a built-in (sqrt, math.pi, ...). A `def` body sees its parameters, its locals and the
!> deck variables. Unknown names and syntax errors are reported at their position inside
!> the VALE string in the deck.
module formula_compiler
    use kinds, only: dp, i4
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_ast
    use deck_parser, only: parse_expression
    use deck_value
    use deck_math, only: literal_out_of_range, builtin_id, builtin_arity_of, PI_VALUE, &
        E_VALUE, same_real
    use deck_suggest, only: did_you_mean
    use run_context, only: run_context_t
    use function_concept, only: function_concept_t
    use constant_function, only: constant_function_t
    use formula_program
    implicit none
    private

    !> Local names of the unit being compiled (main: none, parameters are OP_PARAM).
    type :: scope_t
        type(string_t), allocatable :: names(:)
        logical :: is_main = .true.
    end type scope_t

    type :: compiler_t
        type(program_t) :: prog
        type(string_t), allocatable :: params(:)
        type(string_t), allocatable :: bound_names(:)
        type(value_t), allocatable :: bound_values(:)
        integer, allocatable :: def_nodes(:), def_units(:)   !< compiled (or in progress) defs
        logical, allocatable :: def_done(:)
        integer :: depth = 0, max_depth = 0
    end type compiler_t

    public :: compile_formula

contains

    !> Compiles VALE text into prog.
    !>  ctx : inout, the run context (its AST receives the parsed VALE; deck variables and
    !>        def bodies are read from it)
    !>  text : VALE;  line0, col0 : deck position of text(1:1)
    !>  params : NOM_PARA;  bound_names/bound_values : extra FORMULE keywords
    !>  prog : out;  st : out, STATUS_DECK_ERROR located inside the VALE string
    subroutine compile_formula(ctx, text, line0, col0, params, bound_names, bound_values, &
                               prog, st)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: text
        integer, intent(in) :: line0, col0
        type(string_t), intent(in) :: params(:), bound_names(:)
        type(value_t), intent(in) :: bound_values(:)
        type(program_t), intent(out) :: prog
        type(status_t), intent(out) :: st
        type(compiler_t) :: c
        type(scope_t) :: scope
        integer :: expr
        call parse_expression(text, ctx%deck_name, line0, col0, ctx%ast, expr, st)
        if (st%failed()) return
        c%params = params
        c%bound_names = bound_names
        c%bound_values = bound_values
        allocate (c%def_nodes(0), c%def_units(0), c%def_done(0), scope%names(0))
        allocate (c%prog%units(4))
        c%prog%nunit = 1
        c%prog%units(1)%name = 'VALE'
        c%prog%units(1)%nparams = size(params)
        c%prog%file = ctx%deck_name
        call compile_expr(c, ctx, expr, 1, scope, st)
        if (st%failed()) return
        call emit(c, 1, OP_RETURN, ctx%ast%nodes(expr))
        if (c%max_depth > MAX_STACK) then
            call fail(st, ctx, ctx%ast%nodes(expr), 'formula too large (it needs more than ' &
                      // to_text(int(MAX_STACK, i4)) // ' values at once)')
            return
        end if
        prog = c%prog
    end subroutine compile_formula

    recursive subroutine compile_expr(c, ctx, id, u, scope, st)
        type(compiler_t), intent(inout) :: c
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id, u
        type(scope_t), intent(inout) :: scope
        type(status_t), intent(inout) :: st
        integer :: k, jump, n, ios
        integer, allocatable :: ends(:)
        real(dp) :: x
        type(node_t) :: node
        node = ctx%ast%nodes(id)
        select case (node%kind)
        case (N_INT, N_REAL)
            ios = 0
            if (literal_out_of_range(node%text)) ios = 1
            if (ios == 0) read (node%text, *, iostat=ios) x
            if (ios == 0) then
                if (abs(x) > huge(x)) ios = 1
            end if
            if (ios /= 0) then
                call fail(st, ctx, node, 'number out of range'); return
            end if
            call emit(c, u, OP_CONST, node, c%prog%units(u)%constant(x))
        case (N_NAME)
            call compile_name(c, ctx, node, u, scope, st)
        case (N_UNARY)
            call compile_expr(c, ctx, node%kids(1), u, scope, st)
            if (node%text == '-') call emit(c, u, OP_NEG, node)
            if (node%text == 'not') call emit(c, u, OP_NOT, node)
        case (N_BINOP)
            call compile_expr(c, ctx, node%kids(1), u, scope, st)
            if (st%failed()) return
            if (node%text == '**' .and. ctx%ast%nodes(node%kids(2))%kind /= N_NAME) then
                if (is_literal(ctx, node%kids(2), 2.0_dp)) then
                    call emit(c, u, OP_SQUARE, node)
                    return
                end if
            end if
            call compile_expr(c, ctx, node%kids(2), u, scope, st)
            if (st%failed()) return
            call emit(c, u, binary_opcode(node%text), node)
        case (N_COMPARE)
            call compile_compare(c, ctx, id, u, scope, st)
        case (N_AND, N_OR)
            allocate (ends(0))
            do k = 1, size(node%kids)
                call compile_expr(c, ctx, node%kids(k), u, scope, st)
                if (st%failed()) return
                if (k < size(node%kids)) then
                    if (node%kind == N_AND) then
                        call emit(c, u, OP_JUMP_IF_FALSE_OR_POP, node, 0)
                    else
                        call emit(c, u, OP_JUMP_IF_TRUE_OR_POP, node, 0)
                    end if
                    ends = [ends, c%prog%units(u)%ncode]
                end if
            end do
            do k = 1, size(ends)
                c%prog%units(u)%code(ends(k)) = c%prog%units(u)%ncode + 1
            end do
        case (N_IFEXP)
            call compile_expr(c, ctx, node%kids(2), u, scope, st)
            if (st%failed()) return
            call emit(c, u, OP_JUMP_IF_FALSE, node, 0)
            jump = c%prog%units(u)%ncode
            call compile_expr(c, ctx, node%kids(1), u, scope, st)
            if (st%failed()) return
            call emit(c, u, OP_JUMP, node, 0)
            n = c%prog%units(u)%ncode
            c%prog%units(u)%code(jump) = n + 1
            c%depth = c%depth - 1
            call compile_expr(c, ctx, node%kids(3), u, scope, st)
            if (st%failed()) return
            c%prog%units(u)%code(n) = c%prog%units(u)%ncode + 1
        case (N_CALL)
            call compile_call(c, ctx, id, u, scope, st)
        case (N_STR)
            call fail(st, ctx, node, 'a formula computes a real: strings are not allowed')
        case default
            call fail(st, ctx, node, 'this construct is not allowed in a formula (numbers, ' // &
                      'names, operators and function calls only)')
        end select
    end subroutine compile_expr

    !> a < b < c is compiled as (a < b) and (b < c); b is side-effect free.
    recursive subroutine compile_compare(c, ctx, id, u, scope, st)
        type(compiler_t), intent(inout) :: c
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id, u
        type(scope_t), intent(inout) :: scope
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: ops(:)
        integer, allocatable :: ends(:)
        integer :: k, i, j
        character(len=:), allocatable :: text
        text = ctx%ast%nodes(id)%text
        allocate (ops(0), ends(0))
        i = 1
        do while (i <= len(text))
            j = index(text(i:) // ' ', ' ') + i - 1
            call append_string(ops, text(i:j - 1))
            i = j + 1
        end do
        do k = 1, size(ops)
            call compile_expr(c, ctx, ctx%ast%kid(id, k), u, scope, st)
            if (st%failed()) return
            call compile_expr(c, ctx, ctx%ast%kid(id, k + 1), u, scope, st)
            if (st%failed()) return
            call emit(c, u, compare_opcode(ops(k)%s), ctx%ast%nodes(id))
            if (k < size(ops)) then
                call emit(c, u, OP_JUMP_IF_FALSE_OR_POP, ctx%ast%nodes(id), 0)
                ends = [ends, c%prog%units(u)%ncode]
            end if
        end do
        do k = 1, size(ends)
            c%prog%units(u)%code(ends(k)) = c%prog%units(u)%ncode + 1
        end do
    end subroutine compile_compare

    !> A name used as a value.
    recursive subroutine compile_name(c, ctx, node, u, scope, st)
        type(compiler_t), intent(inout) :: c
        type(run_context_t), intent(inout) :: ctx
        type(node_t), intent(in) :: node
        integer, intent(in) :: u
        type(scope_t), intent(inout) :: scope
        type(status_t), intent(inout) :: st
        type(value_t) :: v
        integer :: k
        logical :: found
        if (scope%is_main) then
            do k = 1, size(c%params)
                if (c%params(k)%s == node%text) then
                    call emit(c, u, OP_PARAM, node, k); return
                end if
            end do
        else
            do k = 1, size(scope%names)
                if (scope%names(k)%s == node%text) then
                    call emit(c, u, OP_LOAD, node, k); return
                end if
            end do
        end if
        call resolve_object(c, ctx, node%text, scope%is_main, int(node%file), v, found)
        if (found) then
            if (is_number(v)) then
                call emit(c, u, OP_CONST, node, c%prog%units(u)%constant(as_real(v)))
            else
                call fail(st, ctx, node, node%text // ' is ' // kind_label(v) // &
                          '; a formula can only use it by calling it')
            end if
            return
        end if
        select case (node%text)
        case ('pi', 'math.pi')
            call emit(c, u, OP_CONST, node, c%prog%units(u)%constant(PI_VALUE))
        case ('math.e')
            call emit(c, u, OP_CONST, node, c%prog%units(u)%constant(E_VALUE))
        case default
            call unknown_name(c, ctx, node, scope, st)
        end select
    end subroutine compile_name

    !> A deck object called `name`: bound FORMULE keyword (main unit), else a name of the
    !> namespace of the code's file (the deck's, or the module's of a def imported from it).
    subroutine resolve_object(c, ctx, name, main, file, v, found)
        type(compiler_t), intent(in) :: c
        type(run_context_t), intent(in) :: ctx
        character(len=*), intent(in) :: name
        logical, intent(in) :: main
        integer, intent(in) :: file
        type(value_t), intent(out) :: v
        logical, intent(out) :: found
        integer :: k
        found = .false.
        if (main) then
            do k = 1, size(c%bound_names)
                if (c%bound_names(k)%s == name) then
                    v = c%bound_values(k); found = .true.; return
                end if
            end do
        end if
        k = ctx%find_symbol(name, ctx%scope_of_file(file))
        if (k > 0) then
            v = ctx%symbols(k)%value; found = .true.
        end if
    end subroutine resolve_object

    subroutine unknown_name(c, ctx, node, scope, st)
        type(compiler_t), intent(in) :: c
        type(run_context_t), intent(in) :: ctx
        type(node_t), intent(in) :: node
        type(scope_t), intent(in) :: scope
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: known(:)
        character(len=:), allocatable :: listed
        integer :: k
        allocate (known(0))
        do k = 1, size(c%params)
            call append_string(known, c%params(k)%s)
        end do
        do k = 1, size(c%bound_names)
            call append_string(known, c%bound_names(k)%s)
        end do
        if (.not. scope%is_main) then
            do k = 1, size(scope%names)
                call append_string(known, scope%names(k)%s)
            end do
        end if
        listed = ''
        do k = 1, size(c%params)
            if (k > 1) listed = listed // ', '
            listed = listed // c%params(k)%s
        end do
        call fail(st, ctx, node, 'name ' // node%text // ' is not defined in the formula' // &
            did_you_mean(node%text, known) // ' (NOM_PARA: ' // listed // &
            '; pass other deck objects as keywords, e.g. F=F)')
    end subroutine unknown_name

    !> f(args): built-in, def function, or function concept.
    recursive subroutine compile_call(c, ctx, id, u, scope, st)
        type(compiler_t), intent(inout) :: c
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id, u
        type(scope_t), intent(inout) :: scope
        type(status_t), intent(inout) :: st
        type(node_t) :: callee, node
        type(value_t) :: v
        integer :: k, nargs, b, target
        logical :: found
        node = ctx%ast%nodes(id)
        callee = ctx%ast%nodes(node%kids(1))
        nargs = size(node%kids) - 1
        if (callee%kind /= N_NAME) then
            call fail(st, ctx, callee, 'only named functions can be called in a formula')
            return
        end if
        do k = 2, size(node%kids)
            if (ctx%ast%nodes(node%kids(k))%kind == N_KWARG) then
                call fail(st, ctx, ctx%ast%nodes(node%kids(k)), 'keyword arguments are not ' &
                          // 'allowed in a formula call'); return
            end if
        end do
        call resolve_object(c, ctx, callee%text, scope%is_main, int(callee%file), v, found)
        if (.not. found) then
            b = builtin_id(callee%text)
            if (b == 0) then
                call unknown_name(c, ctx, callee, scope, st); return
            end if
            if (builtin_arity_of(b) > 0 .and. nargs /= builtin_arity_of(b)) then
                call fail(st, ctx, callee, callee%text // '() takes ' // &
                    to_text(int(builtin_arity_of(b), i4)) // ' argument(s), got ' // &
                    to_text(int(nargs, i4))); return
            end if
            if (nargs == 0) then
                call fail(st, ctx, callee, callee%text // '() needs arguments'); return
            end if
            call compile_args()
            if (st%failed()) return
            call emit(c, u, OP_BUILTIN, callee, b, nargs)
            return
        end if
        select case (v%kind)
        case (VK_DEF)
            call compile_def(c, ctx, int(v%i), callee, target, st)
            if (st%failed()) return
            if (nargs /= c%prog%units(target)%nparams) then
                call fail(st, ctx, callee, callee%text // '() takes ' // &
                    to_text(int(c%prog%units(target)%nparams, i4)) // ' argument(s), got ' // &
                    to_text(int(nargs, i4))); return
            end if
            call compile_args()
            if (st%failed()) return
            call emit(c, u, OP_CALL_DEF, callee, target, nargs)
        case (VK_CONCEPT)
            call add_callee(c, ctx, v, callee, nargs, target, st)
            if (st%failed()) return
            call compile_args()
            if (st%failed()) return
            call emit(c, u, OP_CALL_FUNC, callee, target, nargs)
        case default
            call fail(st, ctx, callee, callee%text // ' is ' // kind_label(v) // &
                      ', not a function')
        end select
    contains
        recursive subroutine compile_args()
            integer :: a
            do a = 2, size(node%kids)
                call compile_expr(c, ctx, node%kids(a), u, scope, st)
                if (st%failed()) return
            end do
        end subroutine compile_args
    end subroutine compile_call

    !> Registers a function concept called from the formula (a copy: concepts are immutable).
    subroutine add_callee(c, ctx, v, callee, nargs, index, st)
        type(compiler_t), intent(inout) :: c
        type(run_context_t), intent(in) :: ctx
        type(value_t), intent(in) :: v
        type(node_t), intent(in) :: callee
        integer, intent(in) :: nargs
        integer, intent(out) :: index
        type(status_t), intent(inout) :: st
        type(callee_t), allocatable :: bigger(:)
        type(string_t), allocatable :: names(:)
        character(len=8), allocatable :: dummy(:)
        integer :: k
        index = 0
        if (.not. associated(v%obj)) then
            call fail(st, ctx, callee, callee%text // ' is not a function'); return
        end if
        select type (f => v%obj)
        class is (function_concept_t)
            names = f%parameters()
            if (size(names) /= nargs) then
                select type (f)
                type is (constant_function_t)
                class default
                    call fail(st, ctx, callee, callee%text // '() takes ' // &
                        to_text(int(size(names), i4)) // ' argument(s), got ' // &
                        to_text(int(nargs, i4))); return
                end select
            end if
            if (.not. allocated(c%prog%callees)) allocate (c%prog%callees(2))
            if (c%prog%ncallee == size(c%prog%callees)) then
                allocate (bigger(2 * c%prog%ncallee))
                bigger(1:c%prog%ncallee) = c%prog%callees(1:c%prog%ncallee)
                call move_alloc(bigger, c%prog%callees)
            end if
            c%prog%ncallee = c%prog%ncallee + 1
            index = c%prog%ncallee
            allocate (c%prog%callees(index)%f, source=f)
            allocate (dummy(nargs))
            do k = 1, nargs
                dummy(k) = ''
                if (k <= size(names)) dummy(k) = names(k)%s
            end do
            call c%prog%callees(index)%f%bind(dummy, c%prog%callees(index)%binding)
            c%prog%callees(index)%nargs = nargs
        class default
            call fail(st, ctx, callee, callee%text // ' is a concept of type ' // &
                      v%obj%type_name() // ', not a function')
        end select
    end subroutine add_callee

    !> Compiles def function `def_node` as a unit (once); recursion is refused.
    recursive subroutine compile_def(c, ctx, def_node, callee, unit, st)
        type(compiler_t), intent(inout) :: c
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: def_node
        type(node_t), intent(in) :: callee
        integer, intent(out) :: unit
        type(status_t), intent(inout) :: st
        type(code_unit_t), allocatable :: bigger(:)
        type(scope_t) :: scope
        integer :: k, np, saved_depth, saved_max
        do k = 1, size(c%def_nodes)
            if (c%def_nodes(k) == def_node) then
                unit = c%def_units(k)
                if (.not. c%def_done(k)) call fail(st, ctx, callee, 'recursive def ' // &
                    callee%text // ' cannot be used in a formula')
                return
            end if
        end do
        if (c%prog%nunit == size(c%prog%units)) then
            allocate (bigger(2 * c%prog%nunit))
            bigger(1:c%prog%nunit) = c%prog%units(1:c%prog%nunit)
            call move_alloc(bigger, c%prog%units)
        end if
        c%prog%nunit = c%prog%nunit + 1
        unit = c%prog%nunit
        c%def_nodes = [c%def_nodes, def_node]
        c%def_units = [c%def_units, unit]
        c%def_done = [c%def_done, .false.]
        np = ctx%ast%nkids(def_node) - 1
        c%prog%units(unit)%name = ctx%ast%nodes(def_node)%text
        c%prog%units(unit)%file = node_file(ctx, ctx%ast%nodes(def_node))
        c%prog%units(unit)%nparams = np
        scope%is_main = .false.
        allocate (scope%names(np))
        do k = 1, np
            scope%names(k)%s = ctx%ast%nodes(ctx%ast%kid(def_node, k))%text
        end do
        saved_depth = c%depth; saved_max = c%max_depth
        c%depth = 0
        call compile_block(c, ctx, ctx%ast%kid(def_node, np + 1), unit, scope, st)
        if (st%failed()) return
        call emit(c, unit, OP_NO_RETURN, ctx%ast%nodes(def_node))
        c%prog%units(unit)%nlocals = size(scope%names)
        c%depth = saved_depth; c%max_depth = max(saved_max, c%max_depth)
        c%def_done(size(c%def_done)) = .true.
        do k = 1, size(c%def_nodes)
            if (c%def_nodes(k) == def_node) c%def_done(k) = .true.
        end do
    end subroutine compile_def

    recursive subroutine compile_block(c, ctx, block, u, scope, st)
        type(compiler_t), intent(inout) :: c
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: block, u
        type(scope_t), intent(inout) :: scope
        type(status_t), intent(inout) :: st
        integer :: k, s, slot, jump, jend
        type(node_t) :: node
        do k = 1, ctx%ast%nkids(block)
            s = ctx%ast%kid(block, k)
            node = ctx%ast%nodes(s)
            select case (node%kind)
            case (N_ASSIGN)
                call compile_expr(c, ctx, node%kids(1), u, scope, st)
                if (st%failed()) return
                slot = 0
                do jump = 1, size(scope%names)
                    if (scope%names(jump)%s == node%text) slot = jump
                end do
                if (slot == 0) then
                    call append_string(scope%names, node%text)
                    slot = size(scope%names)
                end if
                call emit(c, u, OP_STORE, node, slot)
            case (N_RETURN)
                call compile_expr(c, ctx, node%kids(1), u, scope, st)
                if (st%failed()) return
                call emit(c, u, OP_RETURN, node)
            case (N_EXPR)
                call compile_expr(c, ctx, node%kids(1), u, scope, st)
                if (st%failed()) return
                call emit(c, u, OP_POP, node)
            case (N_IF)
                call compile_expr(c, ctx, node%kids(1), u, scope, st)
                if (st%failed()) return
                call emit(c, u, OP_JUMP_IF_FALSE, node, 0)
                jump = c%prog%units(u)%ncode
                call compile_block(c, ctx, node%kids(2), u, scope, st)
                if (st%failed()) return
                if (size(node%kids) > 2) then
                    call emit(c, u, OP_JUMP, node, 0)
                    jend = c%prog%units(u)%ncode
                    c%prog%units(u)%code(jump) = jend + 1
                    call compile_block(c, ctx, node%kids(3), u, scope, st)
                    if (st%failed()) return
                    c%prog%units(u)%code(jend) = c%prog%units(u)%ncode + 1
                else
                    c%prog%units(u)%code(jump) = c%prog%units(u)%ncode + 1
                end if
            case (N_BLOCK)
                call compile_block(c, ctx, s, u, scope, st)
                if (st%failed()) return
            case (N_PASS)
            case default
                call fail(st, ctx, node, 'this statement is not allowed in a def used by a ' &
                          // 'formula (assignments, if/elif/else and return only)')
                return
            end select
        end do
    end subroutine compile_block

    !> Emits an instruction and tracks the value stack depth.
    subroutine emit(c, u, op, node, a, b)
        type(compiler_t), intent(inout) :: c
        integer, intent(in) :: u, op
        type(node_t), intent(in) :: node
        integer, intent(in), optional :: a, b
        call c%prog%units(u)%emit(op, node%line, node%col, a, b)
        select case (op)
        case (OP_CONST, OP_PARAM, OP_LOAD)
            c%depth = c%depth + 1
        case (OP_BUILTIN, OP_CALL_DEF, OP_CALL_FUNC)
            c%depth = c%depth - b + 1
        case (OP_NEG, OP_NOT, OP_SQUARE, OP_JUMP, OP_NO_RETURN)
        case default
            c%depth = c%depth - 1
        end select
        c%max_depth = max(c%max_depth, c%depth)
    end subroutine emit

    logical function is_literal(ctx, id, x)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        real(dp), intent(in) :: x
        real(dp) :: y
        integer :: ios
        is_literal = .false.
        if (ctx%ast%nodes(id)%kind /= N_INT .and. ctx%ast%nodes(id)%kind /= N_REAL) return
        ! a literal beyond the largest real (t**1e999) is reported where it is evaluated;
        ! reading it here would raise the overflow the checked build traps
        if (literal_out_of_range(ctx%ast%nodes(id)%text)) return
        read (ctx%ast%nodes(id)%text, *, iostat=ios) y
        if (ios == 0) is_literal = same_real(x, y)
    end function is_literal

    integer function binary_opcode(op)
        character(len=*), intent(in) :: op
        select case (op)
        case ('+')
            binary_opcode = OP_ADD
        case ('-')
            binary_opcode = OP_SUB
        case ('*')
            binary_opcode = OP_MUL
        case ('/')
            binary_opcode = OP_DIV
        case ('//')
            binary_opcode = OP_FLOORDIV
        case ('%')
            binary_opcode = OP_MOD
        case default
            binary_opcode = OP_POW
        end select
    end function binary_opcode

    integer function compare_opcode(op)
        character(len=*), intent(in) :: op
        select case (op)
        case ('<')
            compare_opcode = OP_LT
        case ('<=')
            compare_opcode = OP_LE
        case ('>')
            compare_opcode = OP_GT
        case ('>=')
            compare_opcode = OP_GE
        case ('==')
            compare_opcode = OP_EQ
        case default
            compare_opcode = OP_NE
        end select
    end function compare_opcode

    subroutine fail(st, ctx, node, message)
        type(status_t), intent(inout) :: st
        type(run_context_t), intent(in) :: ctx
        type(node_t), intent(in) :: node
        character(len=*), intent(in) :: message
        if (st%failed()) return
        call set_error(st, STATUS_DECK_ERROR, message, file=node_file(ctx, node), &
                       line=node%line, column=node%col)
    end subroutine fail

    !> The file of a node as named in messages: a def may come from an imported module.
    function node_file(ctx, node) result(file)
        type(run_context_t), intent(in) :: ctx
        type(node_t), intent(in) :: node
        character(len=:), allocatable :: file
        file = ''
        if (node%file >= 1 .and. node%file <= size(ctx%ast%files)) &
            file = ctx%ast%files(node%file)%s
        if (len(file) == 0) file = ctx%deck_name
    end function node_file

end module formula_compiler
